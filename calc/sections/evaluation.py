"""How a case is evaluated: the sections found, put in the order of what each requires, and
evaluated in turn, each with the results of the sections it requires.

The sections are the modules of :mod:`calc.sections` that hold a ``SECTION``
(:class:`calc.sections.protocol.Section`), found here: a new section is its module alone. Their
modules' ``ORDER`` is their place in the results and the outputs (:func:`sections`); the
evaluation runs in the topological order of their ``REQUIRES`` (:func:`evaluation_order`), so a
section's evaluation reads the results it requires (:class:`Earlier`) and nothing else. The ratio
search and the search of motor and gearbox pairs evaluate variants of a case the same way
(:func:`results_of`).
"""

from __future__ import annotations

import functools
import importlib
import pkgutil
from dataclasses import dataclass, field

import numpy as np

from ..core.errors import CalcError, listing, as_found
from ..data.catalog import display_path
from .common import SHOWN_CANDIDATES, Verdict
from .protocol import Section


@functools.cache
def places() -> tuple:
    """Every module of :mod:`calc.sections` with a place in the outputs, in their order.

    Returns
    -------
    tuple of module
        The modules with an ``ORDER`` (the sections, and the ratio search, which the report
        shows), sorted by it.
    """
    package = importlib.import_module(__package__)
    found = [importlib.import_module(f"{__package__}.{m.name}") for m in pkgutil.iter_modules(package.__path__)]
    return tuple(sorted((m for m in found if hasattr(m, "ORDER")), key=lambda m: m.ORDER))


@functools.cache
def sections() -> tuple:
    """Every section, in the order of the results.

    Returns
    -------
    tuple of calc.sections.protocol.Section
        The ``SECTION`` of each module of :func:`places` that has one.
    """
    return tuple(m.SECTION for m in places() if isinstance(getattr(m, "SECTION", None), Section))


def section(name: str):
    """The section of that name.

    Parameters
    ----------
    name : str
        Its key in the results (``"gearbox"``).

    Returns
    -------
    calc.sections.protocol.Section
    """
    return next(s for s in sections() if s.NAME == name)


@functools.cache
def evaluation_order() -> tuple:
    """Every section after those it requires.

    Returns
    -------
    tuple of calc.sections.protocol.Section
        :func:`requirement_order` of :func:`sections`.
    """
    return requirement_order(sections())


def requirement_order(found: tuple) -> tuple:
    """The sections in an order where each comes after those it requires, otherwise in their given
    order (Kahn's algorithm, the earliest ready first).

    Parameters
    ----------
    found : tuple
        Sections (each with ``NAME`` and ``REQUIRES``), in the order of the results.

    Returns
    -------
    tuple
        The same sections in the order of evaluation.

    Raises
    ------
    CalcError
        Where a requirement names no section, or sections require each other in a cycle (named).
    """
    names = {s.NAME for s in found}
    for s in found:
        unknown = [r for r in s.REQUIRES if r not in names]
        if unknown:
            raise CalcError(f"section {s.NAME} requires {as_found(unknown[0])}, which is no section; "
                            f"the sections are {listing(sorted(names))}")
    done, out = set(), []
    while len(out) < len(found):
        ready = next((s for s in found if s.NAME not in done and set(s.REQUIRES) <= done), None)
        if ready is None:
            cycle = _cycle([s for s in found if s.NAME not in done])
            raise CalcError(f"the sections require each other in a cycle: {listing(cycle, ' -> ')}")
        done.add(ready.NAME)
        out.append(ready)
    return tuple(out)


def _cycle(left: list) -> list[str]:
    """A cycle among sections none of which is ready: follow a requirement still open until a
    section comes back."""
    requires = {s.NAME: [r for r in s.REQUIRES if r in {x.NAME for x in left}] for s in left}
    path = [left[0].NAME]
    while path.count(path[-1]) < 2:
        path.append(requires[path[-1]][0])
    return path[path.index(path[-1]):]


class Earlier:
    """The results a section's evaluation reads: those of the sections it requires, by name
    (``earlier["gearbox"]``; :meth:`get` gives None where that section does not apply to the
    case). Asking for a section not required is an error: a section declares what it reads.

    Parameters
    ----------
    section : calc.sections.protocol.Section
        The section evaluated.
    results : dict
        The results evaluated so far, by section name.
    """

    def __init__(self, section, results: dict):
        self._section, self._results = section, results

    def _required(self, name: str) -> None:
        if name not in self._section.REQUIRES:
            raise LookupError(f"section {self._section.NAME} reads the results of {name} but does not require it")

    def __getitem__(self, name: str):
        self._required(name)
        return self._results[name]

    def get(self, name: str):
        """The result of a required section, or None where it does not apply to the case.

        Parameters
        ----------
        name : str
            The section's name; one it does not require is an error.

        Returns
        -------
        calc.sections.protocol.Result or None
            Its result.
        """
        self._required(name)
        return self._results.get(name)


def results_of(case, names: tuple = (), given: dict | None = None) -> dict:
    """The results of some sections of a case and of those they require, where each applies.

    numpy's floating-point warnings are not printed (what overflows gives inf or NaN, which the
    results report: :func:`calc.sections.common.number`).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    names : tuple of str
        The sections wanted (every section for none).
    given : dict, optional
        Results taken as they are instead of evaluated, by section name (a variant of the case
        with its motor fixed).

    Returns
    -------
    dict
        Each result evaluated or given, by section name, in the order of evaluation.
    """
    wanted = _wanted(case, names or tuple(s.NAME for s in sections()))
    results = dict(given or {})
    with np.errstate(all="ignore"):
        for s in evaluation_order():
            if s.NAME in wanted and s.NAME not in results:
                results[s.NAME] = s.evaluate(case, Earlier(s, results))
                for name, made in s.evaluated_with(results[s.NAME]).items():
                    if name in wanted:
                        results.setdefault(name, made)
    return results


def _wanted(case, names: tuple) -> set:
    """The sections ``names`` that apply to ``case``, and those their evaluation requires."""
    out, todo = set(), list(names)
    while todo:
        s = section(todo.pop())
        if s.NAME not in out and s.applies(case):
            out.add(s.NAME)
            todo += s.REQUIRES
    return out


NOTHING_CHECKED = ("Nothing is checked: the case names no gearbox ratio or part, no coupling and no accuracy "
                   "requirement.")


@dataclass
class Results:
    """Every result the case's inputs allow, by section, and the verdict of the case.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked (:meth:`calc.sections.protocol.Section.checked`: with the motor it is
        checked with).
    sections : dict
        Section name -> its result (:class:`calc.sections.protocol.Result`), in the order of the
        results.
    every : dict, optional
        Every section's result evaluated, shown or not, by name.
    """

    case: object
    sections: dict
    every: dict = field(default_factory=dict, repr=False)

    @functools.cached_property
    def verdict(self) -> Verdict:
        """The one verdict of the case, from its sections' (:meth:`calc.sections.common.Verdict.combine`);
        combined once (the results do not change after the evaluation, and every output asks for it)."""
        return Verdict.combine([r.verdict() for r in self.sections.values()], NOTHING_CHECKED)

    def governing(self) -> list:
        """The governing checks of each section that has checks.

        Returns
        -------
        list of calc.sections.common.Governing
            In the order of the results.
        """
        return [g for r in self.sections.values() if (g := r.governing()) is not None]

    def deciding(self) -> list:
        """What decides the design: the most utilized governing check of each part, most utilized first.

        Returns
        -------
        list of tuple
            ``(governing, check)``: the :class:`calc.sections.common.Governing` and its check of the
            highest utilization (checks not made left out; a part without a made check left out).
        """
        out = []
        for g in self.governing():
            made = [k for k in g.checks if k.utilization is not None]
            if made:
                out.append((g, max(made, key=lambda k: k.utilization)))
        return sorted(out, key=lambda gk: -gk[1].utilization)

    def not_made(self) -> list[str]:
        """Every governing check not made, and every check left out for want of an input (the
        motor's without a rating).

        Returns
        -------
        list of str
            Each with why, ``gearbox NPS045-10: F_2R: the catalog gives no F_2R``.
        """
        return ([x for g in self.governing() for x in g.not_made]
                + [x for r in self.sections.values() for x in r.unchecked()])

    def __getitem__(self, name: str):
        return self.sections[name]

    def to_json(self, candidates: int | None = SHOWN_CANDIDATES) -> dict:
        """The results as the JSON contract writes them.

        Parameters
        ----------
        candidates : int or None
            The most candidates each list holds, best first (all for None).

        Returns
        -------
        dict
            Title, case file, verdict, then each section's results under its name (or at the top,
            where its record says so).
        """
        out = {"title": self.case.title, "case": display_path(self.case.path), "verdict": self.verdict.to_json()}
        for name, result in self.sections.items():
            written = result.to_json(candidates)
            out.update(written if result.AT_TOP else {name: written})
        return out

    def summary(self, candidates: int | None = SHOWN_CANDIDATES) -> str:
        """The results as a short report for a terminal: the verdict first, then each section.

        Parameters
        ----------
        candidates : int or None
            The most candidates each list shows, best first (all for None).

        Returns
        -------
        str
        """
        title = self.case.title
        v = self.verdict
        lines = [title, "=" * len(title), f"Verdict: {v.word}", *[f"  {r}" for r in v.reasons]]
        for result in self.sections.values():
            lines += ["", *result.summary_lines(candidates)]
        return "\n".join(lines)


def evaluate(case, *names: str) -> Results:
    """Evaluate some sections of a case (every section for none) with what they require, where
    each applies.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    *names : str
        The sections wanted (``"gearbox"``).

    Returns
    -------
    Results
        The shown sections' results in their order, the case as checked (with the motor it is
        checked with) and every result evaluated.
    """
    results = results_of(case, names)
    for s in evaluation_order():
        if s.NAME in results:
            case = s.checked(case, results[s.NAME])
    return Results(case, {s.NAME: results[s.NAME] for s in sections() if s.SHOWN and s.NAME in results}, results)
