"""What every section of the case layer shares: quantities as the JSON contract writes them, the
verdict of a section, and how many candidates a listing shows.

What a section is, its tables, what it requires, its reading and evaluation and its result
record, is :mod:`calc.sections.protocol`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..core.checks import Check
from ..core.units import Value, number, pretty_unit, sig

#: Candidates listed by default in the JSON and the text summary; ``--all-candidates`` lists all.
SHOWN_CANDIDATES = 20
#: Candidates whose reasons a failing verdict lists, best first.
REASONED_CANDIDATES = 3


def quantity(q, unit: str, key: str = "result") -> dict:
    """A scalar quantity as the contract writes it: ``{"value": 21.3, "unit": "N*m"}``.

    Parameters
    ----------
    q : pint.Quantity [any]
        The quantity; NaN (no value) becomes null.
    unit : str
        The unit it is written in (``"N*m"``).
    key : str, optional
        The result's name, for the error.

    Returns
    -------
    dict
        ``{"value", "unit"}``.

    Raises
    ------
    CalcError
        For an infinite value, naming the result: JSON never holds one.
    """
    return Value.of(q, unit, key).to_json()


def json_of(value: Value | None) -> dict | None:
    """A result's value as the contract writes it.

    Parameters
    ----------
    value : calc.core.units.Value or None
        The result's value.

    Returns
    -------
    dict or None
        ``{"value", "unit"}``; None stays null.
    """
    return None if value is None else value.to_json()


def quantity_text(d: dict | None) -> str:
    """A result quantity as a reader writes it.

    Parameters
    ----------
    d : dict or None
        The quantity as the contract writes it, ``{"value", "unit"}``.

    Returns
    -------
    str
        ``151.3 N·m``; n/a for none (or a null value).
    """
    return "n/a" if d is None or d["value"] is None else f"{sig(d['value'])} {pretty_unit(d['unit'])}".rstrip()


def check_json(check: Check) -> dict:
    """A check as the contract writes it.

    Parameters
    ----------
    check : calc.core.checks.Check
        The check.

    Returns
    -------
    dict
        Its name, mode (where it has one), whether it governs, criterion, required and rated values,
        utilization, whether it passes and, for one not made, why.
    """
    out = {
        "name": check.name,
        "mode": check.mode,
        "governs": check.governs,
        "criterion": check.criterion,
        "required": json_of(check.required_value),
        "rated": check.rated_value.to_json(),
        "utilization": None if check.utilization is None else number(check.utilization, check.name),
        "passes": check.passes,
    }
    if check.mode is None:
        del out["mode"]
    if check.not_made is not None:
        out["not_made"] = check.not_made
    return out


def check_line(check: Check, width: int = 22) -> str:
    """A check as one line of the text summary.

    Parameters
    ----------
    check : calc.core.checks.Check
        The check.
    width : int, optional
        The width its criterion is padded to [characters].

    Returns
    -------
    str
        Criterion, required and rated values, utilization and verdict; one that does not govern is
        marked "for information".
    """
    util = "n/a" if check.utilization is None else f"{check.utilization:.2f}"
    passes = "ok" if check.passes else "FAIL"
    verdict = f"not checked: {check.not_made or 'no rating'}" if check.passes is None else passes
    mark = "" if check.governs else "  (for information)"
    required = "n/a" if check.required is None else str(check.required_value)
    rated = str(check.rated_value)
    return (f"{check.criterion:<{width}} required {required:>12}  rated {rated:>12}  utilization {util:>5}  "
            f"{verdict}{mark}")


def no_candidate_passes(sentence: str, parts, order, reasons) -> list[str]:
    """The reasons of a verdict where no candidate passes.

    Parameters
    ----------
    sentence : str
        The first reason (``No gearbox passes every check:``).
    parts : sequence of str
        The catalog's part names, by row.
    order : sequence of int
        The rows, best first.
    reasons : callable
        ``reasons(row)``: why a row fails, a list of texts.

    Returns
    -------
    list of str
        ``sentence``, then why the best :data:`REASONED_CANDIDATES` fail, one line each.
    """
    return [sentence] + [f"{parts[row]}: {'; '.join(reasons(row))}" for row in order[:REASONED_CANDIDATES]]


def row_json(c) -> dict:
    """What a candidate says of its catalog row, as the contract writes it.

    Parameters
    ----------
    c : calc.core.selection.Candidate
        The candidate.

    Returns
    -------
    dict
        Why it does not pass, and the row's file, maker, family, size, source and doubts (null for none).
    """
    return {"reasons": c.reasons, "catalog": c.catalog, "maker": c.maker or None, "family": c.family, "size": c.size,
            "source": c.source, "unclear": c.unclear or None}


@dataclass(frozen=True)
class Governing:
    """The checks that decide a section's verdict, and whose they are: a candidate's or the
    section's own.

    Parameters
    ----------
    section : str
        The section's name.
    part : str or None
        The candidate's part; None for the section's own checks.
    chosen : bool
        Whether the candidate is chosen; False where none passes and it is only the closest.
    checks : list of calc.core.checks.Check
        The governing checks.
    """

    section: str
    part: str | None
    chosen: bool
    checks: list

    @property
    def not_made(self) -> list[str]:
        """Each check not made, with why: ``gearbox NPS045-10: F_2R: the catalog gives no F_2R``."""
        owner = self.section + (f" {self.part}" if self.part else "")
        return [f"{owner}: {k.name}: {k.not_made or 'not made'}" for k in self.checks if k.passes is None]


def selection_governing(name: str, sel) -> Governing:
    """The governing checks of a selection's best-ranked candidate.

    Parameters
    ----------
    name : str
        The section's name.
    sel : calc.core.selection.Selection
        The selection.

    Returns
    -------
    Governing
        Its best candidate's governing checks, chosen where the selection chose a part.
    """
    best = sel.best
    return Governing(name, best.part, sel.selected is not None, best.governing)


def selection_verdict(sel, what: str, fails: str) -> Verdict:
    """The verdict of a selection.

    Parameters
    ----------
    sel : calc.core.selection.Selection
        The selection.
    what : str
        What it selects, for the reasons (``gearbox``).
    fails : str
        What no candidate passes, for the reasons (``every check``).

    Returns
    -------
    Verdict
        Passes where a part is chosen; not decided where the best row passes every check made but a
        governing check cannot be made (saying which); else no ``what`` passes ``fails``, and why
        the closest fail.
    """
    if sel.selected is not None:
        return Verdict(True)
    best = sel.order[0]
    if sel.passes[best] and sel.not_made:
        return Verdict(None, [f"No {what} can be chosen: {c.reason(best)}" for c in sel.not_made])
    return Verdict(False, no_candidate_passes(f"No {what} passes {fails}:", sel.catalog.parts, sel.order, sel.reasons))


def shown(order, candidates: int | None):
    """The first candidates of a ranking.

    Parameters
    ----------
    order : sequence of int
        The ranking, best first.
    candidates : int or None
        How many to show; None: all.

    Returns
    -------
    sequence of int
        The first ``candidates`` of ``order``.
    """
    return order if candidates is None else order[:candidates]


@dataclass
class Verdict:
    """Whether a section (or the whole case) passes.

    Parameters
    ----------
    passes : bool or None, optional
        True, False, or None when a governing check could not be made.
    reasons : list of str, optional
        Which check fails and by how much, or what is missing.
    """

    passes: bool | None = True
    reasons: list = field(default_factory=list)

    @staticmethod
    def combine(verdicts: list["Verdict"], nothing: str) -> "Verdict":
        """One verdict from several.

        Parameters
        ----------
        verdicts : list of Verdict or None
            The verdicts; None for a section that decides nothing.
        nothing : str
            The reason when no section decides anything.

        Returns
        -------
        Verdict
            False when one fails, else None when one could not be decided, else True; the reasons
            of all.
        """
        deciding = [v for v in verdicts if v is not None]
        if not deciding:
            return Verdict(None, [nothing])
        reasons = [r for v in deciding for r in v.reasons]
        if any(v.passes is False for v in deciding):
            return Verdict(False, reasons)
        if any(v.passes is None for v in deciding):
            return Verdict(None, reasons)
        return Verdict(True, [])

    def to_json(self) -> dict:
        """The verdict as the contract writes it.

        Returns
        -------
        dict
            ``{"passes", "reasons"}``.
        """
        return {"passes": self.passes, "reasons": list(self.reasons)}

    @property
    def word(self) -> str:
        """The verdict in one word: PASS, FAIL or NOT DECIDED."""
        return {True: "PASS", False: "FAIL", None: "NOT DECIDED"}[self.passes]
