"""Every motor of a case's motor catalog with every gearbox of its gearbox catalog, at every ratio
(``python -m calc combinations CASE``): the feasible pairs and the one to pick by
:data:`calc.domain.combinations.RULE`, from the cycle's moments (:mod:`calc.domain.combinations`: exact,
with no pass over the samples per pair). Not a section of the evaluation: its own command, with the same
exit status rules.

The evaluation of a case with a motor catalog takes its motor and gearbox from the same search
(:func:`case_pairs`: the rows at the case's ratio, or its named part, or a direct drive) by the same
rule (:mod:`calc.sections.axis`).

What a pair must pass: the gearbox's own governing checks at its ratio (all of
:func:`calc.domain.gearbox.select_gearbox` but those that need the motor), its ``T_2B`` (E4, in S5) and
``T_2Not`` (the emergency stop ``T_1B · i``) against the motor's peak through it, the motor's peak
torque at every sample's speed (its speed-torque characteristic, :mod:`calc.domain.motor_ratings`),
its RMS torque against ``M_N``, its rated and top speed, and the inertia ratio (E6;
``[motor] max_inertia_ratio``), with a motor-side coupling's inertia turning with the motor (the
lightest candidate's where the case names none). The peak is screened against ``M_max`` for every
pair and checked against the characteristic for the motors in the rule's order until one passes.
The evaluation then confirms the pair in full (:func:`calc.sections.axis.confirmed`: the coupling
chosen with its motor counted), taking the next in the rule's order where it is refused.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .case import Case
from ..data.catalog import display_path
from ..core.checks import within_rating
from ..domain.combinations import RULE, CycleMoments, search
from ..core.errors import CalcError
from ..domain.gearbox import T_2max, T_2stop, rows_at_ratio, select_gearbox, shock_factor
from ..domain.motor import motor_torque
from ..domain.motor_ratings import peak_limit, read_curves
from ..domain.profile import Z_h, n_2m
from ..core.units import Q_, sig
from . import coupling
from .common import Verdict
from .gearbox import catalogs, selection_inputs
from .motor import output_load
from .motor_catalog import motor_catalog, motor_ratings


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
    def chosen(self) -> tuple[int, int] | None:
        """The pair the evaluation takes: the pick, else the pair closest to passing (its checks then
        fail where the case is evaluated); None where there is no pair at all.

        Returns
        -------
        tuple of int or None
            ``(gearbox row, motor)``, rows of :attr:`gearbox_parts` and :attr:`motor_parts`.
        """
        return self.result.pick if self.result.pick is not None else self.result.closest

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
    """Every (gearbox row, motor) pair of the case's catalogs, at every ratio of the gearbox catalog,
    against its cycle (``python -m calc combinations``).

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
    return _search(case, gear.rows(~gear.partial), hubs)


def case_pairs(case: Case, confirm=None) -> PairSearch:
    """The pairs the case's evaluation chooses from: every motor of its catalog with every gearbox row
    at its ratio (or its named part), or driving the load directly where it has no gearbox.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read, with a motor catalog.
    confirm : callable, optional
        ``confirm(motor part, gearbox part or None)`` -> bool: whether the pair passes evaluated in
        full; the pairs that pass the screen are confirmed in the rule's order, and the first
        confirmed is the pick (:func:`calc.domain.combinations.search`). None: none is asked.

    Returns
    -------
    PairSearch
        The pick, and the pairs of the motors screened up to it, in the rule's order (for a direct
        drive, one gearbox row: none, ``i = 1``).
    """
    if case.ratio is None and case.gearbox_part is None:
        return _search(case, None, None, first=True, confirm=confirm)
    return _search(case, case_rows(case), case.gearbox_hubs, first=True, confirm=confirm)


def _search(case: Case, gear, hubs, first: bool = False, confirm=None) -> PairSearch:
    """The pairs of the motor catalog with the rows ``gear`` (None: a direct drive) by
    :func:`calc.domain.combinations.search`, each motor's pairs examined in full in the rule's order
    until one passes (with ``first``, the motors after it are not screened either) and, with
    ``confirm`` (:func:`case_pairs`), is confirmed."""
    motors = motor_catalog(case)
    motors = motors.rows(~motors.partial)
    out = output_load(case)
    few = out.distinct()  # the same sums and envelopes over each distinct sample once
    alpha = np.zeros(len(few.dt)) if few.alpha_2 is None else few.alpha_2.m_as("rad/s**2")
    moments = CycleMoments.of(few.dt.m_as("s"), few.torque.m_as("N*m"), few.speed.m_as("rad/s"), alpha)
    J_c, notes = _coupling_inertia(case)
    notes = ([] if out.sampled else ["the load cycle is typed: its accelerations are not known, "
                                     "so the rotor term is left out"]) + notes
    if gear is None:
        rows = {"i": [1.0], "eta": [1.0], "J_1": [J_c], "passes": [1.0], "peak_limit": [np.inf], "rank": [0.0]}
        parts, more = np.array(["none (direct drive)"]), []
    else:
        rows, more = _gear_rows(case, gear, hubs, J_c)
        parts = gear.parts
    J_L = case.load_inertia
    if J_L is None:
        notes.append("the case gives no load inertia: the inertia ratio is counted with none")
    motor_rows = {"J": motors["J"].m_as("kg*m**2"), "rated_torque": motors["M_N"].m_as("N*m"),
                  "peak_torque": motors["M_max"].m_as("N*m"), "max_speed": motors["n_max"].m_as("rad/s")}
    if case.motor_curves is None:  # an S1 curve lets a motor run past n_N (calc.domain.motor_ratings)
        motor_rows["rated_speed"] = motors["n_N"].m_as("rad/s")
    w = np.abs(few.speed.m_as("rad/s"))
    speeds = (float(out.n_2max.m_as("rad/s")), float(n_2m.si(n_2k=w, t_k=few.dt.m_as("s"))))
    rows["J_L"] = 0.0 if J_L is None else float(J_L.m_as("kg*m**2"))
    asked = None if confirm is None else (
        lambda g, m: confirm(str(motors.parts[m]), None if gear is None else str(parts[g])))
    result = search(moments, speeds, rows, motor_rows, case.motor_max_inertia_ratio[0],
                    examine=_examine(case, few, motors, rows, gear, hubs), first=first, confirm=asked)
    shown = slice(None) if result.motors is None else result.motors
    return PairSearch(case, parts, np.asarray(rows["i"], float), motors.parts[shown], motors["M_N"].m_as("N*m")[shown],
                      result, notes + more)


def case_rows(case: Case):
    """The case's gearbox rows the evaluation chooses from: its named part, or the rows at its ratio
    (no partial row).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read, with a gearbox table.

    Returns
    -------
    calc.data.catalog.Catalog
        Those rows.
    """
    where = f"{case.path}: gearbox"
    catalog, _ = catalogs(case)
    if case.gearbox_part is not None:
        return catalog.rows([catalog.usable_index(case.gearbox_part, f"{where}.part")])
    return rows_at_ratio(catalog, case.ratio, f"{where}.ratio")  # its partial rows left out already


def _gear_rows(case: Case, gear, hubs, J_c: float) -> tuple[dict, list]:
    """The arrays of :func:`calc.domain.combinations.search` over the gearbox rows, and the notes."""
    # Per pair, not per case: the motor's peak and rotor.
    inputs = {**selection_inputs(case), "motor_peak_torque": None, "motor_inertia": None, "coupling_span": None}
    sel = select_gearbox(case.profile, gear, hubs=hubs, **inputs)
    f_s = float(shock_factor(Z_h(**case.profile.cycles_per_hour_inputs()), inputs["shock_factors"]))
    i, eta = gear["ratio"].m_as(""), gear["eta"].m_as("")
    # T_2max <= T_2B (E4): the highest motor peak each row takes, in S5 (T_2max is T_1B times the rest)
    peak_limit = np.full(len(gear), np.inf)
    if sel.mode == "S5":
        peak_limit = gear["T_2B"].m_as("N*m") / T_2max.si(T_1B=1.0, i=i, f_s=f_s, eta=eta)
    if case.emergency_stop_torque is None:  # T_2stop = T_1B · i <= T_2Not where the row gives it
        with np.errstate(invalid="ignore"):
            peak_limit = np.fmin(peak_limit, gear["T_2Not"].m_as("N*m") / T_2stop.si(T_1B=1.0, i=i))
    rank = np.full(len(gear), float(len(gear)))
    rank[sel.order] = np.arange(len(sel.order))
    notes = ["a gearbox row without J_1 is counted with none"] if np.isnan(sel.J_1.magnitude).any() else []
    J_1 = np.nan_to_num(sel.J_1.m_as("kg*m**2")) + J_c
    return {"i": i, "eta": eta, "J_1": J_1, "passes": sel.passes.astype(float), "peak_limit": peak_limit,
            "rank": rank}, notes + sel.notes


def _coupling_inertia(case: Case) -> tuple[float, list]:
    """What a motor-side coupling adds to each pair's ``J_1`` [kg·m²]: the named part's whole inertia,
    else the lightest candidate's (the one chosen turns with the motor when the case is evaluated)."""
    given = coupling.SECTION.inputs(case)
    if given is None or given.side != "input":
        return 0.0, []
    J = given.catalog["J"].m_as("kg*m**2")[~given.catalog.partial]
    if np.isnan(J).all():
        return 0.0, ["the motor-side coupling's catalog gives no inertia: the pairs count none"]
    J_c = float(np.nanmin(J))
    which = "its" if given.has("part") else "the lightest candidate's"
    return J_c, [f"the motor-side coupling turns with the motor: {which} inertia "
                 f"{sig(J_c * 1e4)} kg·cm² is added to J_1"]


def _examine(case: Case, few, motors, rows: dict, gear, hubs):
    """``examine(motor, rows)`` of :func:`calc.domain.combinations.search`: the highest motor torque
    over the peak torque the motor gives at each sample's speed
    (:func:`calc.domain.motor_ratings.peak_limit`, with the case's DC link and curves), and the
    gearbox rows checked and ranked with that motor as the gearbox section checks them."""
    curves = None if case.motor_curves is None else read_curves(case.motor_curves, motor_catalog(case).parts)
    i, eta, J_1 = (np.asarray(rows[k], float) for k in ("i", "eta", "J_1"))
    w = np.abs(few.speed.m_as("rad/s"))

    def peak_share(m: int, at: np.ndarray) -> np.ndarray:
        """The highest motor torque over the peak torque at its speed, for motor m through rows at."""
        one = motors.rows([m])
        T_1 = motor_torque(few.torque, few.speed, Q_(i[at, None], ""), Q_(eta[at, None], ""), few.alpha_2,
                           one["J"][0], Q_(J_1[at, None], "kg*m**2")).m_as("N*m")
        T_1 = np.broadcast_to(T_1, (len(at), len(w)))
        limit, _ = peak_limit(one, (w[None, :] * i[at, None]).ravel(), case.voltage_limit_dc_link[0], curves)
        with np.errstate(invalid="ignore", divide="ignore"):
            u = np.abs(T_1) / limit.reshape(len(at), len(w))
        return np.where(np.isnan(u), np.inf, u).max(axis=1, initial=0.0)

    def examine(m: int, at: np.ndarray) -> tuple:
        if gear is None:
            return peak_share(m, at), np.ones(len(at), bool), None
        trial = dataclasses.replace(case, **motor_ratings(motors, m))
        sel = select_gearbox(trial.profile, gear.rows(at), hubs=hubs, **selection_inputs(trial))
        rank = np.empty(len(at))
        rank[sel.order] = np.arange(len(sel.order))
        u = np.full(len(at), np.nan)  # the rows in the gearbox ranking's order, until one passes
        order = sel.order[sel.passes[sel.order]]
        for start in range(0, len(order), BATCH):
            batch = order[start:start + BATCH]
            u[batch] = peak_share(m, at[batch])
            if within_rating(u[batch]).any():
                break
        return u, sel.passes, rank

    return examine


#: Gearbox rows checked against a motor's characteristic at once, in the ranking's order.
BATCH = 64
