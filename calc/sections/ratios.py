"""The best ratio of a case (``python -m calc ratios CASE``): the case evaluated at every ratio its
gearbox catalog offers (:mod:`calc.domain.ratios`), the ratio to pick and why. Not a section of the
evaluation: its own command, with the same exit status rules."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .case import Case
from ..data.catalog import display_path
from ..core.errors import CalcError
from ..domain.ratios import RatioSearch, optimal_ratio, search_ratios
from ..core.units import Q_, Value, fmt, pretty_unit, sig
from .gearbox import catalogs, selection_inputs
from .common import Verdict, check_json, json_of, number
from .evaluation import results_of
from .motor import TYPED, motor_side_coupling, output_load, rotor_inertia


#: Not evaluated with the case (its own command, :func:`search`); its place in the report.
ORDER = 70


@dataclass(frozen=True)
class RatioRow:
    """The case at one ratio, with its best gearbox, as the outputs print it.

    Parameters
    ----------
    ratio : float
        The gearbox ratio ``i`` [1].
    part : str
        The best gearbox of the catalog at this ratio.
    passes : bool
        Whether the gearbox and the motor pass at this ratio.
    gearbox_passes : bool
        Whether the gearbox passes.
    utilization : float or None
        The best gearbox's highest governing utilization [1]; None where it has none.
    inertia_ratio : float or None
        The inertia ratio ``λ`` [1]; None where it is not known.
    inertia_within : bool or None
        Whether ``λ`` is within its limit, as the search decides; None where ``λ`` is not known.
    peak_torque_required : Value or None
        The motor's peak torque [N·m]; None where the case has no motor side.
    rms_torque_required : Value or None
        The motor's RMS torque [N·m]; None where the case has no motor side.
    max_speed_required : Value
        The motor's highest speed [rpm].
    checks : list of calc.core.checks.Check
        The motor's checks at this ratio.
    reasons : list of str
        Why the gearbox or the motor fails here.
    pick : bool
        Whether this is the ratio to pick.
    """

    ratio: float
    part: str
    passes: bool
    gearbox_passes: bool
    utilization: float | None
    inertia_ratio: float | None
    inertia_within: bool | None
    peak_torque_required: Value | None
    rms_torque_required: Value | None
    max_speed_required: Value
    checks: list
    reasons: list
    pick: bool


@dataclass(frozen=True)
class OptimalRatio:
    """The inertia-matching ratio ``i_opt = √(J_L / J_in)`` beside the search's pick.

    Parameters
    ----------
    value : float or None
        ``i_opt`` [1]; None where the case lacks an inertia.
    step : calc.core.formula.Step or None
        Its calculation, as computed.
    inertias : str
        Which inertias it counts, or what it lacks.
    pick : float or None
        The search's pick [1], least RMS motor torque.
    """

    value: float | None
    step: object
    inertias: str
    pick: float | None

    def to_json(self) -> dict:
        """``ratios.optimal_ratio``.

        Returns
        -------
        dict
            value, J_L, J_in, which inertias, and the search's pick.
        """
        inputs = {} if self.step is None else {
            "J_L": Value.of(self.step.values["J_L"], "kg*cm**2").to_json(),
            "J_in": Value.of(self.step.values["J_in"], "kg*cm**2").to_json()}
        return {"value": self.value, **inputs, "inertias": self.inertias, "pick": self.pick}

    def line(self) -> str:
        """The ratio in one sentence of the text summary.

        Returns
        -------
        str
        """
        if self.value is None:
            return f"Inertia-matching ratio i_opt = √(J_L / J_in): not computed, {self.inertias}"
        pick = "" if self.pick is None else (f"; the search's pick (least RMS motor torque, friction and process "
                                             f"torque counted) is {self.pick:g}")
        return f"Inertia-matching ratio {self.step} ({self.inertias}){pick}"


def optimal(case: Case, s: RatioSearch, coupling) -> OptimalRatio:
    """The inertia-matching ratio of the case (:data:`calc.domain.ratios.optimal_ratio`): ``J_L`` the
    load at the output, ``J_in`` the rotor with the motor-side coupling's whole inertia and the
    ``J_1`` of the gearbox the search picks (or of the case's ratio's best gearbox without a pick).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with its motor.
    s : calc.domain.ratios.RatioSearch
        The search.
    coupling : calc.sections.coupling.CouplingResult or None
        The coupling section's result.

    Returns
    -------
    OptimalRatio
        The ratio and the inertias it counts.
    """
    pick = None if s.pick is None else float(s.ratios[s.pick])
    if case.load_inertia is None or case.motor_inertia is None:
        return OptimalRatio(None, None, "it needs the load's and the motor's inertia", pick)
    k = s.pick if s.pick is not None else int(np.argmin(np.abs(s.ratios - case.ratio.m_as(""))))
    row = int(s.rows[k])
    J_1 = s.selection.J_1[row]
    J_c, part = motor_side_coupling(coupling)
    terms = [("J_motor", case.motor_inertia)]
    if J_c is not None and not np.isnan(J_c.magnitude):
        terms.append((f"coupling {part}", J_c))
    if not np.isnan(J_1.magnitude):
        terms.append((f"J_1 of {s.parts[k]}", J_1))
    J_in = sum((q for _, q in terms), Q_(0.0, "kg*cm**2"))
    step = optimal_ratio.step(J_L=case.load_inertia, J_in=J_in)
    which = ("J_L the load at the output; J_in = " + " + ".join(f"{name} {fmt(q, 'kg*cm**2')}" for name, q in terms)
             + " at the input")
    return OptimalRatio(float(step.result.m_as("")), step, which, pick)


@dataclass(frozen=True)
class CheckedAt:
    """The gearbox the case's evaluation checks, at its ratio, beside the search's pick: the same
    row where the pick is that ratio, else a sentence that says why the search picks another.

    Parameters
    ----------
    ratio : float
        The case's ratio [1] (its gearbox's).
    part : str
        The gearbox the case is checked with (the gearbox section's first row).
    same : bool
        Whether the search picks that ratio (and so that gearbox).
    said : str
        In one sentence: which gearbox the case is checked with, and where and why the pick differs.
    """

    ratio: float
    part: str
    same: bool
    said: str

    def to_json(self) -> dict:
        """``ratios.checked``.

        Returns
        -------
        dict
            ratio, part, same, said.
        """
        return {"ratio": self.ratio, "part": self.part, "same": self.same, "said": self.said}


def checked_at(s: RatioSearch, part: str, named: bool, fails: tuple = ()) -> CheckedAt | None:
    """The case's own gearbox and ratio against the search's pick, in words.

    Parameters
    ----------
    s : calc.domain.ratios.RatioSearch
        The search, run with ``kept=part``.
    part : str
        The gearbox the case is checked with.
    named : bool
        Whether the case names it (``gearbox.part``) rather than its ratio's ranking choosing it.
    fails : tuple of str, optional
        Why the case's evaluation fails its gearbox or motor (empty where both pass): said where the search
        picks the case's ratio all the same.

    Returns
    -------
    CheckedAt or None
        None where the part is not among the search's rows (a partial row).
    """
    at = np.flatnonzero(s.parts == part)
    if not len(at):
        return None
    k = int(at[0])
    ratio, how = float(s.ratios[k]), "gearbox.part" if named else "chosen at gearbox.ratio"
    head = f"The case is checked at its ratio {ratio:g} with {part} ({how})"
    if s.pick == k:
        failing = "" if not fails else f", though the evaluation fails it there ({fails[0]})"
        return CheckedAt(ratio, part, True, f"{head}: the search picks the same{failing}.")
    if s.pick is None:
        return CheckedAt(ratio, part, False, f"{head}; the search picks no ratio.")
    if not s.feasible[k]:
        reasons = s.gearbox_reasons(k)
        why = f"at {ratio:g} {part} fails ({reasons[0]})" if reasons else \
            f"at {ratio:g} the motor fails ({(s.motor_reasons(k) or ['a check not made'])[0]})"
    elif not s.inertia_within[k] and s.inertia_within[s.pick]:
        why = f"at {ratio:g} λ = {sig(s.inertia_ratio[k], 3)} exceeds {s.inertia_limit:g}"
    elif s.load is not None:
        why = (f"it needs the lower RMS motor torque, {fmt(s.load.rms[s.pick], 'N*m')} against "
               f"{fmt(s.load.rms[k], 'N*m')} at {ratio:g}")
    else:
        why = "the rule puts it first"
    pick = f"{s.ratios[s.pick]:g} ({s.parts[s.pick]})"
    return CheckedAt(ratio, part, False, f"{head}; the search picks ratio {pick}, since {why}: set "
                                         f"[gearbox] ratio = {s.ratios[s.pick]:g} to check that one in full.")


@dataclass
class RatioResult:
    """The ratio search of a case, as the ``ratios`` command writes it.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case, its motor as the search kept it.
    search : calc.domain.ratios.RatioSearch
        Every ratio of the gearbox catalog, evaluated, and the pick.
    notes : list of str
        What the search kept to or left out (the motor kept at every ratio, the case's gearbox at its ratio).
    optimal : OptimalRatio or None, optional
        The inertia-matching ratio beside the pick.
    checked : CheckedAt or None, optional
        The gearbox the case is checked with, at its ratio, against the pick.
    """

    case: Case
    search: RatioSearch
    notes: list
    optimal: OptimalRatio | None = None
    checked: CheckedAt | None = None

    def verdict(self) -> Verdict:
        """True when a ratio can be picked, else False with the reason.

        Returns
        -------
        Verdict
            PASS with a pick, else FAIL with the search's reason.
        """
        s = self.search
        return Verdict(True) if s.pick is not None else Verdict(False, [s.reason])

    @cached_property
    def rows(self) -> list:
        """Each ratio of the catalog (:class:`RatioRow`), in ascending order.

        Returns
        -------
        list of RatioRow
            One row per ratio.
        """
        s = self.search
        load = s.load
        out = []
        for k, ratio in enumerate(s.ratios):
            where = f"ratio {ratio:g}"
            out.append(RatioRow(
                float(ratio), str(s.parts[k]), bool(s.feasible[k]), bool(s.gearbox_passes[k]),
                number(s.utilization[k], f"{where}: utilization"),
                number(s.inertia_ratio[k], f"{where}: inertia_ratio"),
                None if np.isnan(s.inertia_ratio[k]) else bool(s.inertia_within[k]),
                None if load is None else Value.of(load.peak[k], "N*m", f"{where}: peak torque"),
                None if load is None else Value.of(load.rms[k], "N*m", f"{where}: RMS torque"),
                Value.of(s.speed[k], "rpm", f"{where}: speed"), [c.at(k) for c in s.motor],
                s.gearbox_reasons(k) + s.motor_reasons(k), k == s.pick,
            ))
        return out

    def to_json(self) -> dict:
        """The search as ``python -m calc ratios --json`` writes it (``docs/case-format.md``).

        Returns
        -------
        dict
            The case, its catalog's provenance, the mode, the rule, the inertia ratio's limit, each
            ratio's row (quantities as ``{"value", "unit"}``), the pick, notes and verdict.
        """
        s = self.search
        rows = [{
            "ratio": r.ratio, "part": r.part, "passes": r.passes, "gearbox_passes": r.gearbox_passes,
            "utilization": r.utilization,
            "inertia_ratio": r.inertia_ratio, "inertia_ratio_within_limit": r.inertia_within,
            "peak_torque_required": json_of(r.peak_torque_required),
            "rms_torque_required": json_of(r.rms_torque_required),
            "max_speed_required": r.max_speed_required.to_json(),
            "checks": [check_json(c) for c in r.checks], "reasons": r.reasons,
        } for r in self.rows]
        return {
            "title": self.case.title,
            "case": display_path(self.case.path),
            **s.selection.catalog.provenance(),
            "mode": s.selection.mode,
            "rule": s.rule,
            "inertia_ratio_limit": s.inertia_limit,
            "rotor_term": bool(s.load is not None and s.load.rotor_term),
            "ratios": rows,
            "pick": None if s.pick is None else {"ratio": float(s.ratios[s.pick]), "part": str(s.parts[s.pick]),
                                                 "reason": s.reason},
            "reason": s.reason,
            "optimal_ratio": None if self.optimal is None else self.optimal.to_json(),
            "checked": None if self.checked is None else self.checked.to_json(),
            "notes": list(self.notes),
            "verdict": self.verdict().to_json(),
        }

    def summary(self) -> str:
        """The search as ``python -m calc ratios`` prints it: the reason of the pick, the rule and a
        line per ratio with the reasons it fails.

        Returns
        -------
        str
            The text, notes last.
        """
        title = f"{self.case.title}: the ratio"
        lines = [title, "=" * len(title), self.search.reason,
                 *([] if self.checked is None else [self.checked.said]), f"Rule: {self.search.rule}.",
                 *([] if self.optimal is None else [self.optimal.line()]), "",
                 f"{'ratio':>6}  {'gearbox':<14} {'verdict':<7} {'util.':>6} {'λ':>7} {'T_1peak':>10} "
                 f"{'T_1rms':>10} {'n_1':>9}"]

        def val(v):
            return "n/a" if v is None or v.value is None else f"{sig(v.value, 4)} {pretty_unit(v.unit)}"

        for r in self.rows:
            lam = "n/a" if r.inertia_ratio is None else f"{r.inertia_ratio:.2f}"
            util = "n/a" if r.utilization is None else f"{r.utilization:.2f}"
            lines.append(
                f"{r.ratio:>6g}  {r.part:<14} {'PASS' if r.passes else 'FAIL':<7} {util:>6} {lam:>7} "
                f"{val(r.peak_torque_required):>10} {val(r.rms_torque_required):>10} "
                f"{val(r.max_speed_required):>9}{'  <- pick' if r.pick else ''}"
            )
            lines += [f"          {reason}" for reason in r.reasons]
        return "\n".join(lines + [f"Note: {n}" for n in self.notes])


def search(case: Case, evaluated: dict | None = None) -> RatioResult:
    """Every ratio of the case's gearbox catalog, with the motor the case is checked with and its
    motor-side coupling.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    evaluated : dict, optional
        The results of the case's axis and coupling sections where the case was evaluated
        (:attr:`calc.sections.Results.every`); else they are evaluated here.

    Returns
    -------
    RatioResult
        The search, its pick and notes.
    """
    if case.gearbox_catalog is None:
        raise CalcError(f"{case.path}: gearbox: the ratio search needs a [gearbox] table (its catalog gives the "
                        "ratios to try), found none")
    notes = []
    evaluated = results_of(case, ("axis", "gearbox", "coupling", "motor")) if evaluated is None else evaluated
    axis, gearbox = evaluated["axis"], evaluated.get("gearbox")
    if axis.chosen is not None:  # a motor from the catalog: the one the case chooses at its ratio
        notes.append(f"the motor is {axis.chosen}, the motor catalog's choice at the case's ratio "
                     f"{sig(case.ratio.m_as(''))}, kept at every ratio (python -m calc combinations chooses motor "
                     "and gearbox together)")
    case = axis.case
    catalog, hubs = catalogs(case)
    load = output_load(case)
    kept = None
    if gearbox is not None:  # the gearbox the case is checked with: its ratio's row, one gearbox per ratio
        kept = str(gearbox.selection.catalog.parts[gearbox.selection.order[0]])
    if case.gearbox_part is not None:
        notes.append(f"gearbox.part = {case.gearbox_part!r} is kept at its ratio; every other ratio takes its best "
                     "row of the catalog")
    if not load.sampled:
        notes.append(TYPED)
    coupling = evaluated.get("coupling")
    s = search_ratios(
        catalog, case.profile, load, case.motor_rated_torque, case.motor_max_speed,
        lambda J_1: rotor_inertia(case, J_1, coupling),
        hubs=hubs, inertia_limit=case.motor_max_inertia_ratio[0], kept=kept, **selection_inputs(case),
    )
    notes += s.notes
    checked = None if kept is None else checked_at(s, kept, case.gearbox_part is not None, _fails(evaluated))
    return RatioResult(case, s, notes, optimal(case, s, coupling), checked)


def _fails(evaluated: dict) -> tuple:
    """Why the evaluation fails the case's gearbox or motor, one sentence each (a heading ending in a colon
    with its first line)."""
    out = []
    for name in ("gearbox", "motor"):
        result = evaluated.get(name)
        verdict = None if result is None else result.verdict()
        if verdict is not None and verdict.passes is False and verdict.reasons:
            r = verdict.reasons
            out.append(f"{r[0]} {r[1]}" if r[0].endswith(":") and len(r) > 1 else r[0])
    return tuple(out)
