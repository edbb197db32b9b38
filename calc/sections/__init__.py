"""The case layer: a design case's sections read, evaluated and written the same way.

Every section is a module of this package with the same shape (:mod:`calc.sections.common`):
``ORDER`` (its place in the results and the report), ``TABLES`` (the tables of the case file it
reads, each key declared once: :class:`calc.sections.case.Declared`), and where it has results ``NAME``,
``applies(case)`` and ``evaluate(case)`` returning a result with ``to_json``, ``summary_lines``
and ``verdict``. The modules are found here, so a new section is its module alone:
:data:`MODULES`, :data:`SECTIONS`, :data:`FURTHER` and :data:`TOP_KEYS` follow from them.
:func:`evaluate` evaluates what the case gives, and :class:`Results` holds the one verdict of the
case (``docs/case-format.md``, "One verdict"), which the JSON, the text summary, the report and
the design review all print.
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass

import numpy as np

from .case import Case, key_names
from ..data.catalog import display_path
from .common import SHOWN_CANDIDATES, Verdict  # noqa: F401 (SHOWN_CANDIDATES: the command line)


def _modules() -> tuple:
    """The section modules of this package (those with an ``ORDER``), in their order."""
    found = [importlib.import_module(f"{__name__}.{m.name}") for m in pkgutil.iter_modules(__path__)]
    return tuple(sorted((m for m in found if hasattr(m, "ORDER")), key=lambda m: m.ORDER))


#: Every section module, in the order of the results and the report.
MODULES = _modules()
#: The evaluated sections, in the order of the results.
SECTIONS = tuple(m for m in MODULES if hasattr(m, "evaluate"))
#: Every table a case file may have, as its section declares it.
DECLARED = tuple(t for m in MODULES for t in getattr(m, "TABLES", ()))
#: Tables of sections that read their own when evaluated (the case keeps them raw until then).
FURTHER = tuple(t.name for m in MODULES if getattr(m, "FURTHER", False) for t in m.TABLES)
#: The keys a case file may have at its top level.
TOP_KEYS = ("title", *key_names(DECLARED))


def declared(path: str):
    """The declaration (:class:`calc.sections.case.Key`) of a key path of a case file (``motor.inertia``,
    ``profile[2].torque``, ``accuracy.component[1].stiffness_curve.K1``); a table's own path gives
    its :class:`calc.sections.case.Declared`."""
    names = [part.split("[")[0] for part in path.split(".")]
    out = next(t for t in DECLARED if t.name == names[0])
    for name in names[1:]:
        out = next(k for k in out.keys if k.name == name)
    return out


NOTHING_CHECKED = "Nothing is checked: the case names no gearbox ratio or part, no coupling and no accuracy requirement."


@dataclass
class Results:
    """Every result the case's inputs allow, by section, and the verdict of the case."""

    case: Case
    sections: dict  # section name -> its result

    @property
    def verdict(self) -> Verdict:
        return Verdict.combine([r.verdict() for r in self.sections.values()], NOTHING_CHECKED)

    def governing(self) -> list:
        """The governing checks of each section that has checks (:class:`calc.sections.common.Governing`)."""
        return [g for r in self.sections.values() if hasattr(r, "governing") and (g := r.governing()) is not None]

    def not_made(self) -> list[str]:
        """Every governing check not made, each with why; and the motor's checks left out for want
        of a rating."""
        return [x for g in self.governing() for x in g.not_made] + [
            x for r in self.sections.values() if hasattr(r, "unchecked") for x in r.unchecked()]

    def __getitem__(self, name: str):
        return self.sections[name]

    def to_json(self, candidates: int | None = SHOWN_CANDIDATES) -> dict:
        """The results as the JSON contract writes them; ``candidates`` bounds each candidate list
        (all for None)."""
        out = {"title": self.case.title, "case": display_path(self.case.path), "verdict": self.verdict.to_json()}
        for name, result in self.sections.items():
            written = result.to_json(candidates)
            out.update(written if getattr(result, "AT_TOP", False) else {name: written})
        return out

    def summary(self, candidates: int | None = SHOWN_CANDIDATES) -> str:
        """The results as a short report for a terminal: the verdict first, then each section."""
        title = self.case.title
        v = self.verdict
        lines = [title, "=" * len(title), f"Verdict: {v.word}", *[f"  {r}" for r in v.reasons]]
        for result in self.sections.values():
            lines += ["", *result.summary_lines(candidates)]
        return "\n".join(lines)


def evaluate(case: Case) -> Results:
    """Evaluate every section the case gives; numpy's floating-point warnings are not printed
    (what overflows gives inf or NaN, which the results report: :func:`calc.sections.common.number`)."""
    from .motor import with_chosen_motor

    with np.errstate(all="ignore"):
        case = with_chosen_motor(case)
        return Results(case, {m.NAME: m.evaluate(case) for m in SECTIONS if m.applies(case)})

