"""The best ratio: a case evaluated at every ratio a gearbox catalog offers, all at once.

Every row of the catalog is checked in one :func:`calc.domain.gearbox.select_gearbox` (each row at its
own ratio: the formulas run over the rows); the best row of each ratio is the one the ranking of
:mod:`calc.domain.gearbox` puts first among the rows of that ratio, so the one an evaluation of the case
at that ratio would choose, and at the case's own ratio the gearbox its evaluation checks (``kept``:
one gearbox per ratio in every output). The motor torque through each ratio's best gearbox over the whole
cycle is one array (ratios × samples, :func:`calc.domain.motor.motor_load`), and the motor's checks
(:func:`calc.domain.motor.motor_checks`) run over the ratios.

A ratio is **feasible** when its best gearbox passes its governing checks and the motor passes
each of its checks that the case gives a rating for.

Rule for the ratio to pick (:func:`rule`): among the feasible ratios whose load to motor inertia
ratio ``λ = (J_1 + J_L / i²) / J_motor`` (:data:`calc.domain.gearbox.inertia_ratio`, E6, the
gearbox's own inertia counted, and a motor-side coupling's with it, as the motor's check counts it:
one λ, :mod:`calc.domain.dynamics` says what its limit means) is at most the case's limit
(``[motor] max_inertia_ratio``, :data:`calc.domain.gearbox.INERTIA_RATIO_LIMIT` where it gives none),
the one of lowest RMS motor torque (the motor's thermal load, which decides the size of a motor on a cyclic
axis; at a given motor, the lowest RMS utilization); a tie goes to the lower ratio (lower speeds).
If no feasible ratio keeps ``λ`` within the limit, the feasible ratio of lowest ``λ``; where ``λ``
is not known (no inertias), the RMS rule alone. No feasible ratio: no pick.

Beside the pick, the textbook's **inertia-matching ratio** ``i_opt = √(J_L / J_in)``
(:data:`optimal_ratio`): for a load that is inertia alone, the motor torque ``(J_in · i + J_L / i) · α_2``
that accelerates it is least there (``J_in`` the motor's rotor with what turns at its speed, the
coupling and the gearbox's ``J_1``; ``J_L`` the load at the output). With friction and process
torque the ratio of least RMS motor torque, which the search finds, moves from it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.checks import within_rating
from ..core.citation import Source, Validity
from ..core.formula import Formula
from ..data.catalog import Catalog
from .documents import MECHANICS
from .gearbox import GearboxSelection, inertia_ratio, n_1, select_gearbox
from .motor import MotorLoad, OutputLoad, motor_checks, motor_load
from .profile import Profile
from ..core.units import fmt, sig

optimal_ratio = Formula(
    "i_opt",
    ("J_L", "J_in"),
    lambda sp, J_L, J_in: sp.sqrt(J_L / J_in),
    Source(MECHANICS.at(label="inertia matching", says="the motor torque (J_in · i + J_L / i) · α_2 is least where "
                        "d/di = 0: i² = J_L / J_in", validity=Validity("a load that is inertia alone"))),
)


def rule(inertia_limit: float) -> str:
    """The rule for the ratio to pick, in one sentence, with the limit of λ it keeps to.

    Parameters
    ----------
    inertia_limit : float [1]
        The highest load to motor inertia ratio ``λ``.

    Returns
    -------
    str
        The rule, as the outputs print it.
    """
    return (
        "among the feasible ratios (best gearbox and motor pass) whose inertia ratio "
        f"λ = (J_1 + J_L / i²) / J_motor (J_1 with a motor-side coupling's J) is at most {inertia_limit:g} (E6), "
        "the lowest RMS motor torque; a tie to "
        "the lower ratio; if none keeps λ within the limit, the feasible ratio of lowest λ"
    )


@dataclass
class RatioSearch:
    """The best gearbox of each ratio of a catalog, the motor through it, and the ratio to pick.

    Arrays run over :attr:`ratios` (ascending) unless said otherwise.

    Parameters
    ----------
    selection : GearboxSelection
        Every row of the catalog, each at its own ratio.
    ratios : numpy.ndarray [1]
        The distinct ratios.
    rows : numpy.ndarray of int
        The best row of each ratio, an index into the catalog.
    load : MotorLoad or None
        ``T_1`` of shape (ratios, samples); None where the torques cannot be computed.
    speed : pint.Quantity [rpm]
        Highest motor speed ``n_2max · i``.
    motor : list of CheckArray
        Over the ratios, one per motor rating given.
    inertia_ratio : numpy.ndarray [1]
        ``λ`` of each ratio's best row (NaN where not known).
    inertia_limit : float [1]
        The highest ``λ`` the rule keeps to.
    inertia_within : numpy.ndarray of bool
        ``λ`` is known and within :attr:`inertia_limit` (:func:`inertia_within_limit`).
    gearbox_passes : numpy.ndarray of bool
        The best row passes.
    feasible : numpy.ndarray of bool
        The best row and the motor pass.
    utilization : numpy.ndarray [1]
        Highest governing utilization of gearbox and motor.
    pick : int or None
        The ratio picked, an index into ``ratios``.
    reason : str
        Why, in one sentence.
    notes : list of str
        What the motor torques count or lack.
    """

    selection: GearboxSelection  # every row of the catalog, each at its own ratio
    ratios: np.ndarray
    rows: np.ndarray  # the best row of each ratio, an index into the catalog
    load: MotorLoad | None  # T_1 of shape (ratios, samples); None where the torques cannot be computed
    speed: object  # highest motor speed n_2max · i
    motor: list  # CheckArray over the ratios, one per motor rating given
    inertia_ratio: np.ndarray  # λ of each ratio's best row (NaN where not known)
    inertia_limit: float  # the highest λ the rule keeps to
    inertia_within: np.ndarray  # λ known and within the limit
    gearbox_passes: np.ndarray
    feasible: np.ndarray
    utilization: np.ndarray  # highest governing utilization of gearbox and motor
    pick: int | None  # index into ratios
    reason: str
    notes: list  # what the motor torques count or lack

    @property
    def rule(self) -> str:
        """The rule the pick follows (:func:`rule`), with this search's limit of λ."""
        return rule(self.inertia_limit)

    @property
    def parts(self) -> np.ndarray:
        return self.selection.catalog.parts[self.rows]

    def gearbox_reasons(self, k: int) -> list[str]:
        """Why the best gearbox of ratio ``k`` fails (empty when it passes).

        Parameters
        ----------
        k : int
            An index into :attr:`ratios`.

        Returns
        -------
        list of str
            One line per check.
        """
        return self.selection.reasons(int(self.rows[k]))

    def motor_reasons(self, k: int) -> list[str]:
        """Why the motor fails at ratio ``k`` (empty when it passes).

        Parameters
        ----------
        k : int
            An index into :attr:`ratios`.

        Returns
        -------
        list of str
            One line per motor check.
        """
        return [c.reason(k) for c in self.motor if not c.passes[k]]


def best_rows(selection: GearboxSelection) -> tuple[np.ndarray, np.ndarray]:
    """The distinct ratios of the selection's catalog (ascending) and, for each, the row ranked
    first among the rows of that ratio.

    Parameters
    ----------
    selection : GearboxSelection
        Every row of the catalog, checked.

    Returns
    -------
    tuple of numpy.ndarray
        The ratios [1] and the rows (indices into the catalog).
    """
    ratio = selection.catalog["ratio"].m_as("")
    ratios, group = np.unique(ratio, return_inverse=True)
    ranked_groups = group[selection.order]
    _, first = np.unique(ranked_groups, return_index=True)  # first place of each ratio in the ranking
    return ratios, selection.order[first]


def search_ratios(
    catalog: Catalog,
    profile: Profile,
    load: OutputLoad,
    rated_torque=None,
    max_speed=None,
    rotor_inertia=None,
    hubs: Catalog | None = None,
    *,
    inertia_limit: float,
    kept: str | None = None,
    **selection,
) -> RatioSearch:
    """Evaluate the case at every ratio of ``catalog`` (its rankable rows, every ratio).

    ``profile`` gives the duty and the gearbox's checks; ``load`` the cycle at the output for the
    motor's side (a sampled cycle with its accelerations counts the rotor and gearbox inertia;
    typed segments leave the rotor term out). ``rotor_inertia(J_1)``, where given, turns the
    gearboxes' ``J_1`` into what the rotor term counts beside the motor's own: ``(J_1, ...,
    what it lacks or None, notes)`` (a motor-side coupling's inertia added). ``hubs`` and the
    keyword arguments ``selection`` are those of :func:`calc.domain.gearbox.select_gearbox`;
    ``rated_torque`` and ``max_speed`` those of :func:`calc.domain.motor.motor_checks`;
    ``inertia_limit`` the highest λ the pick keeps to (:func:`rule`). ``kept``, the gearbox a case's
    evaluation checks at its ratio, is the best row of its ratio whatever the ranking (a part the case
    names, or the one chosen with the motor), so the search never shows another there. A ratio whose best gearbox
    gives no ``J_1`` has no motor torque on a sampled cycle, and is not feasible (a note says so).

    Parameters
    ----------
    catalog : Catalog
        The gearbox rows, of every ratio.
    profile : Profile
        The load cycle at the output.
    load : OutputLoad
        The cycle at the output for the motor's side.
    rated_torque : pint.Quantity [N·m], optional
        The motor's ``T_1N``.
    max_speed : pint.Quantity [rpm], optional
        The motor's ``n_max``.
    rotor_inertia : callable, optional
        ``rotor_inertia(J_1)`` as above.
    hubs : Catalog, optional
        The clamping hubs.
    inertia_limit : float [1]
        The highest ``λ`` the pick keeps to: the case's ``[motor] max_inertia_ratio``.
    kept : str, optional
        The part the case is checked with at its ratio: the best row of that ratio.
    **selection
        Further arguments of :func:`calc.domain.gearbox.select_gearbox`.

    Returns
    -------
    RatioSearch
        Every ratio and the pick.
    """
    motor_peak_torque, motor_inertia = selection.get("motor_peak_torque"), selection.get("motor_inertia")
    if catalog.partial.any():  # partial rows are never ranked (no copy of a catalog without them)
        catalog = catalog.rows(np.flatnonzero(~catalog.partial))
    sel = select_gearbox(profile, catalog, hubs=hubs, **selection)
    if kept is not None:
        sel.put_first(kept, failing=True)
    ratios, rows = best_rows(sel)
    i, eta = catalog["ratio"][rows], catalog["eta"][rows]
    missing, J_1, notes = None, None, []
    if load.sampled:
        J_1 = sel.J_1[rows]  # for the clamping hub the motor's shaft picks
        if rotor_inertia is not None:
            J_1, _, missing, notes = rotor_inertia(J_1)
        elif motor_inertia is None:
            missing = "the rotor term (J_motor + J_1) · α_1 needs the motor's inertia (motor.inertia)"
        lacking = [str(p) for p, j in zip(catalog.parts[rows], J_1.magnitude) if np.isnan(j)]
        if lacking and missing is None:
            notes = [*notes, f"the catalog gives no J_1 for {', '.join(lacking)}: the motor torque through them is not "
                             "known, so their ratios are not feasible"]
    torques = None
    if missing is None:
        torques = motor_load(load.dt, load.torque, load.speed, i[:, None], eta[:, None], load.alpha_2, motor_inertia,
                             None if J_1 is None else J_1[:, None])
    speed = n_1(n_2=load.n_2max, i=i)
    motor = motor_checks(speed, None if torques is None else torques.peak, None if torques is None else torques.rms,
                         motor_peak_torque, rated_torque, max_speed, not_made=missing)
    gearbox_passes = sel.passes[rows] & (not sel.not_made)
    feasible = gearbox_passes & np.logical_and.reduce([c.passes for c in motor], initial=True)
    # rows without T_2Not and a catalog's missing figures leave NaN: fmax ranks on the others
    utilization = np.fmax.reduce([sel.worst[rows], *[c.utilization for c in motor]], axis=0)
    lam = np.full(len(rows), np.nan) if sel.inertia_ratio is None else sel.inertia_ratio[rows]
    if rotor_inertia is not None and J_1 is not None and sel.inertia_ratio is not None:
        # λ as the motor's check counts it: J_1 with what turns at the motor's speed (a motor-side coupling)
        lam = inertia_ratio(J_1=J_1, J_L=selection["load_inertia"], i=i, J_motor=motor_inertia).m_as("")
    not_made = [c.not_made for c in sel.not_made + motor if c.not_made]
    pick, reason = pick_ratio(ratios, sel.catalog.parts[rows], feasible, lam, torques, not_made, inertia_limit)
    return RatioSearch(sel, ratios, rows, torques, speed, motor, lam, inertia_limit,
                       inertia_within_limit(lam, inertia_limit), gearbox_passes, feasible, utilization, pick, reason,
                       notes)


def inertia_within_limit(inertia_ratio, inertia_limit: float) -> np.ndarray:
    """Whether each ``λ`` is known and within its limit, with the boundary tolerance of the
    checks (:func:`calc.core.checks.within_rating`): the one test of λ against the limit.

    Parameters
    ----------
    inertia_ratio : numpy.ndarray [1]
        ``λ`` of each ratio (NaN where not known).
    inertia_limit : float [1]
        The highest ``λ``.

    Returns
    -------
    numpy.ndarray of bool
        False where ``λ`` is over the limit or not known.

    Examples
    --------
    >>> inertia_within_limit(np.array([5.0, 10.0, 12.0, np.nan]), 10.0).tolist()
    [True, True, False, False]
    """
    lam = np.asarray(inertia_ratio, dtype=float)
    return ~np.isnan(lam) & within_rating(lam / inertia_limit)


def pick_ratio(ratios, parts, feasible, inertia_ratio, torques: MotorLoad | None, not_made: list[str],
               inertia_limit: float) -> tuple[int | None, str]:
    """The ratio to pick by :func:`rule` and why, in one sentence.

    Parameters
    ----------
    ratios : numpy.ndarray [1]
        The distinct ratios, ascending.
    parts : numpy.ndarray of str
        The best part of each.
    feasible : numpy.ndarray of bool
        The best row and the motor pass.
    inertia_ratio : numpy.ndarray [1]
        ``λ`` of each (NaN where not known).
    torques : MotorLoad or None
        The motor torques of each; None where they cannot be computed.
    not_made : list of str
        What is missing, where no ratio is feasible for want of it.
    inertia_limit : float [1]
        The highest ``λ`` the pick keeps to.

    Returns
    -------
    tuple of (int or None, str)
        An index into ``ratios`` (None where none can be picked) and the reason.
    """
    if not feasible.any():
        why = "; ".join(dict.fromkeys(not_made)) if not_made else "at no ratio do the best gearbox and the motor pass"
        return None, f"No ratio can be picked: {why}."
    rms = np.zeros(len(ratios)) if torques is None else torques.rms.m_as("N*m")  # unknown: the ratio decides

    def lowest_rms(k):
        if torques is None:
            return "the lowest ratio (the motor torque is not known)"
        return f"the lowest RMS motor torque, {fmt(torques.rms[k], 'N*m')}"

    known = ~np.isnan(inertia_ratio)
    within = feasible & inertia_within_limit(inertia_ratio, inertia_limit)
    n = int(feasible.sum())
    head = f"{n} of {len(ratios)} ratios are feasible"
    if within.any():
        k = int(np.lexsort((ratios, np.where(within, rms, np.inf)))[0])
        why = (f"{head}, {int(within.sum())} of them with λ <= {inertia_limit:g}; "
               f"of these it needs {lowest_rms(k)}")
        if within.sum() == 1:
            why = f"{head}, and only this one keeps λ <= {inertia_limit:g} (λ = {sig(inertia_ratio[k], 3)})"
    elif (feasible & known).any():
        k = int(np.lexsort((ratios, np.where(feasible & known, inertia_ratio, np.inf)))[0])
        why = f"{head}, none with λ <= {inertia_limit:g}; it has the lowest, λ = {sig(inertia_ratio[k], 3)}"
    else:
        k = int(np.lexsort((ratios, np.where(feasible, rms, np.inf)))[0])
        why = f"{head}; the inertia ratio is not known (motor.inertia and load.inertia), and it needs {lowest_rms(k)}"
    return k, f"Ratio {ratios[k]:g} ({parts[k]}): {why}."
