"""Every motor of a case's motor catalog with every gearbox of its gearbox catalog, at every ratio
(``python -m calc combinations CASE``): the feasible pairs and the one to pick by
:data:`calc.domain.combinations.RULE`, from the cycle's moments (:mod:`calc.domain.combinations`: exact,
with no pass over the samples per pair). Not a section of the evaluation: its own command, with the same
exit status rules.

What a pair must pass: the gearbox's own governing checks at its ratio (all of
:func:`calc.domain.gearbox.select_gearbox` but those that need the motor), its ``T_2B`` against the
motor's peak through it (E4, in S5), the motor's peak torque ``M_max``, its RMS torque ``M_N``, its
top speed and the inertia ratio (E6; ``[motor] max_inertia_ratio``). The motor's peak is screened
against ``M_max`` at every speed: the speed-torque characteristic (:mod:`calc.domain.motor_ratings`)
and the emergency stop are checked when the case is evaluated with the pair it picks.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .case import Case
from ..data.catalog import display_path
from ..domain.combinations import RULE, CycleMoments, search
from ..core.errors import CalcError
from ..domain.gearbox import T_2max, select_gearbox, shock_factor
from ..domain.profile import Z_h
from ..core.units import sig
from . import axis
from .common import Verdict
from .gearbox import catalogs, selection_inputs
from .motor import output_load


@dataclass(frozen=True)
class Pick:
    """The pair picked, as the outputs print it.

    Parameters
    ----------
    motor : str
        The motor's part.
    gearbox : str
        The gearbox's part.
    ratio : float
        The gearbox's ratio [1].
    peak_torque : float
        The motor's peak torque over the cycle [N*m], at the motor.
    rms_torque : float
        The motor's RMS torque over the cycle [N*m].
    utilization : float
        The pair's highest utilization [1].
    """

    motor: str
    gearbox: str
    ratio: float
    peak_torque: float
    rms_torque: float
    utilization: float


@dataclass
class PairSearch:
    """The pairs of a case: the gearbox rows (all ratios, no partial row) and the motors (no
    partial row), their arrays (gearbox rows × motors) and the pick.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    gearbox_parts : numpy.ndarray
        The gearbox rows' parts.
    ratios : numpy.ndarray
        The gearbox rows' ratios [1].
    motor_parts : numpy.ndarray
        The motors' parts.
    motor_rated : numpy.ndarray
        The motors' rated torque M_N [N*m]: their order in the figure.
    result : calc.domain.combinations.Combinations
        The pairs' arrays (gearbox rows × motors) and the pick.
    notes : list of str
        What the search leaves out or counts with none.
    """

    case: Case
    gearbox_parts: np.ndarray
    ratios: np.ndarray
    motor_parts: np.ndarray
    motor_rated: np.ndarray
    result: object
    notes: list

    @cached_property
    def pick(self) -> Pick | None:
        """The pair picked by :data:`calc.domain.combinations.RULE`; None where no pair is feasible."""
        r = self.result
        if r.pick is None:
            return None
        g, m = r.pick
        return Pick(str(self.motor_parts[m]), str(self.gearbox_parts[g]), float(self.ratios[g]), float(r.peak[g, m]),
                    float(r.rms[g, m]), float(r.utilization[g, m]))

    @property
    def feasible_count(self) -> int:
        """How many pairs pass."""
        return int(self.result.feasible.sum())

    def verdict(self) -> Verdict:
        """Whether the search finds a pair.

        Returns
        -------
        calc.sections.common.Verdict
            Passes where a pair is picked; else fails, saying how many pairs were checked.
        """
        if self.pick is not None:
            return Verdict(True)
        return Verdict(False, [f"No motor of the catalog works with any gearbox of the catalog at any ratio "
                               f"({self.result.feasible.size} pairs checked)"])

    def to_json(self) -> dict:
        """The search as ``python -m calc combinations --json`` writes it.

        Returns
        -------
        dict
            The title, the case file, the rule, the counts of pairs, gearboxes and motors, the ratios,
            the pick, the notes and the verdict.
        """
        p = self.pick
        return {
            "title": self.case.title,
            "case": display_path(self.case.path),
            "rule": RULE,
            "pairs": int(self.result.feasible.size),
            "feasible": self.feasible_count,
            "gearboxes": int(len(self.gearbox_parts)),
            "motors": int(len(self.motor_parts)),
            "ratios": sorted({float(r) for r in self.ratios}),
            "pick": None if p is None else {
                "motor": p.motor, "gearbox": p.gearbox, "ratio": p.ratio,
                "peak_torque": {"value": p.peak_torque, "unit": "N*m"},
                "rms_torque": {"value": p.rms_torque, "unit": "N*m"}, "utilization": p.utilization,
            },
            "notes": list(self.notes),
            "verdict": self.verdict().to_json(),
        }

    def summary(self) -> str:
        """The search as ``python -m calc combinations`` prints it.

        Returns
        -------
        str
            A title, the counts, the rule, the pick (and how to check it in full) or why there is
            none, and the notes.
        """
        title = f"{self.case.title}: motor x gearbox x ratio"
        lines = [title, "=" * len(title),
                 f"{self.result.feasible.size} pairs ({len(self.motor_parts)} motors x {len(self.gearbox_parts)} "
                 f"gearbox rows at {len(set(self.ratios.tolist()))} ratios), {self.feasible_count} feasible.",
                 f"Rule: {RULE}."]
        p = self.pick
        if p is None:
            lines.append(self.verdict().reasons[0])
        else:
            lines.append(f"Pick: motor {p.motor} with gearbox {p.gearbox} (i = {p.ratio:g}): "
                         f"motor peak {sig(p.peak_torque)} N·m, "
                         f"RMS {sig(p.rms_torque)} N·m, highest utilization {p.utilization:.2f}.")
            lines.append(f"Check it in full: [motor] part = \"{p.motor}\", [gearbox] part = \"{p.gearbox}\", "
                         f"then python -m calc evaluate.")
        return "\n".join(lines + [f"Note: {n}" for n in self.notes])

    def figure(self):
        """The motors (smallest rated torque first) against the ratios.

        Returns
        -------
        matplotlib.figure.Figure
            :func:`calc.figures.combination_plots.combinations_figure` of the pairs, the pick marked.
        """
        from ..figures.combination_plots import combinations_figure

        order = np.argsort(self.motor_rated, kind="stable")
        r = self.result
        pick = None if r.pick is None else (r.pick[0], int(np.flatnonzero(order == r.pick[1])[0]))
        return combinations_figure(r.utilization[:, order], r.feasible[:, order], sorted(set(self.ratios.tolist())),
                                   [str(p) for p in self.motor_parts[order]], pick, ratio_of_rows=self.ratios)


def search_pairs(case: Case) -> PairSearch:
    """Every (gearbox row, motor) pair of the case's catalogs against its cycle.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read, with a motor catalog and a gearbox table.

    Returns
    -------
    PairSearch
        The pairs and the pick.

    Raises
    ------
    CalcError
        Where the case has no motor catalog or no gearbox table.
    """
    if case.motor_catalog is None:
        raise CalcError(f"{case.path}: motor.catalog: the search of motors and gearboxes needs a motor catalog "
                        f"([motor] catalog = \"motors\"), found none")
    if case.gearbox_catalog is None:
        raise CalcError(f"{case.path}: gearbox: the search of motors and gearboxes needs a [gearbox] table "
                        f"(its catalog gives the gearboxes), found none")
    gear, hubs = catalogs(case)
    gear = gear.rows(~gear.partial)
    # Per pair, not per case: the motor's peak and rotor (the drive train's bound needs the rotor; the
    # case is evaluated with the pair it picks, where the coupling checks the train).
    inputs = {**selection_inputs(case), "motor_peak_torque": None, "motor_inertia": None, "coupling_span": None}
    sel = select_gearbox(case.profile, gear, hubs=hubs, **inputs)
    f_s = float(shock_factor(Z_h(**case.profile.cycles_per_hour_inputs()), inputs["shock_factors"]))
    i, eta = gear["ratio"].m_as(""), gear["eta"].m_as("")
    # T_2max <= T_2B (E4): the highest motor peak each row takes, in S5 (T_2max is T_1B times the rest)
    if sel.mode == "S5":
        peak_limit = gear["T_2B"].m_as("N*m") / T_2max.si(T_1B=1.0, i=i, f_s=f_s, eta=eta)
    else:
        peak_limit = np.full(len(gear), np.inf)
    J_L = case.load_inertia
    motors = axis.motor_catalog(case)
    motors = motors.rows(~motors.partial)
    out = output_load(case)
    alpha = np.zeros(len(out.dt)) if out.alpha_2 is None else out.alpha_2.m_as("rad/s**2")
    moments = CycleMoments.of(out.dt.m_as("s"), out.torque.m_as("N*m"), out.speed.m_as("rad/s"), alpha)
    J_1 = np.nan_to_num(sel.J_1.m_as("kg*m**2"))
    typed = "the load cycle is typed: its accelerations are not known, so the rotor term is left out"
    notes = [] if out.sampled else [typed]
    if np.isnan(sel.J_1.magnitude).any():
        notes.append("a gearbox row without J_1 is counted with none")
    if J_L is None:
        notes.append("the case gives no load inertia: the inertia ratio is counted with none")
    if case.sections.get("coupling", {}).get("side") == "input":
        notes.append("the motor-side coupling's inertia is not counted here (evaluate counts it)")
    result = search(
        moments, float(out.n_2max.m_as("rad/s")),
        {"i": i, "eta": eta, "J_1": J_1, "passes": sel.passes.astype(float), "peak_limit": peak_limit,
         "size": gear["T_2B" if sel.mode == "S5" else "T_2N"].m_as("N*m"),
         "J_L": 0.0 if J_L is None else float(J_L.m_as("kg*m**2"))},
        {"J": motors["J"].m_as("kg*m**2"), "rated_torque": motors["M_N"].m_as("N*m"),
         "peak_torque": motors["M_max"].m_as("N*m"), "max_speed": motors["n_max"].m_as("rad/s")},
        inertia_limit=case.motor_max_inertia_ratio[0],
    )
    return PairSearch(case, gear.parts, i, motors.parts, motors["M_N"].m_as("N*m"), result, notes + sel.notes)
