"""The motor's side of a case (``[motor]``): the motor torque over the load cycle through the
selected (or named) gearbox, with the rotor and gearbox inertia where the cycle is sampled; its
peak, its RMS over the whole cycle and the top speed checked against the motor's peak torque,
rated torque and top speed, each where the case gives it (:mod:`calc.domain.motor`, case format
"The motor's side")."""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from .case import Case
from ..data.catalog import display_path
from ..domain.gearbox import inertia_ratio, n_1
from ..domain.cycle import PHASES
from ..domain.motor import (
    T_1_back, T_1_drive, T_1rms, Energy, MotorLoad, OutputLoad, alpha_1, driven_back, energy, motor_checks, motor_load,
    motor_torque, phases,
)
from ..domain.motor_ratings import RANKING, Cycle, MotorSelection, read_curves, select_motors
from ..core.units import Q_, fmt, number
from ..domain.drive import Winding, winding
from .motor_catalog import motor_catalog
from .common import (Governing, Verdict, check_json, check_line, quantity, quantity_text, row_json, selection_governing,
                     selection_verdict)
from .protocol import Result, Section

NAME = "motor"
ORDER = 60

#: The winding's model as the results name it.
THERMAL_MODEL = ("first order: dθ/dt = ((T_1 / M_0)² − θ) / T_th, the cycle repeated until periodic; θ = 1 at the "
                 "winding's rise under M_0 held (M_N where the motor gives no M_0)")

TYPED = (
    "the load cycle is typed ([[profile]]): its accelerations are not known, so the rotor term "
    "(J_motor + J_1) · α_1 is left out and the motor torque is the typed output torque through the gearbox"
)


def output_load(case: Case) -> OutputLoad:
    """The load cycle at the gearbox output as the motor's side reads it.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.

    Returns
    -------
    calc.domain.motor.OutputLoad
        The sampled cycle of the motion form where the case derives its load cycle, else the
        typed segments (a pause with zero torque and speed).
    """
    if case.motion is None:
        p = case.profile
        return OutputLoad(p.durations, p.torques, p.speeds, None, p.n_2max)
    return case.motion.output_load


def motor_side_coupling(coupling) -> tuple:
    """A motor-side coupling's whole inertia (it turns with the motor; NaN where its catalog gives
    none) and its part, or ``(None, None)`` without one: the coupling the ``coupling`` result
    (None: the case has none) chose, or its best-ranked.

    Parameters
    ----------
    coupling : calc.sections.coupling.CouplingResult or None
        The coupling section's result; None where the case has no coupling.

    Returns
    -------
    tuple
        The coupling's inertia J [kg·m², a pint.Quantity] and its part, or ``(None, None)``.
    """
    if coupling is None:
        return None, None
    cc, sel = coupling.inputs, coupling.selection
    if cc.side != "input":
        return None, None
    row = int(sel.order[0])
    part = str(cc.catalog.parts[row])
    return cc.catalog["J"][row], part


def rotor_inertia(case: Case, J_1, coupling, catalog_rotors: bool = False) -> tuple:
    """What the rotor term of a sampled cycle adds to the motor's inertia, for gearbox rows of
    input inertia ``J_1`` (an array, NaN where the catalog gives none), with the ``coupling``
    result (None: none): ``(J_1 with a motor-side coupling's whole inertia, that coupling's
    inertia or None, what the term lacks or None, notes)``. The term lacks the motor's inertia
    where the case gives none (and ``catalog_rotors`` is not set: each catalog motor brings its
    own), and the coupling's where its catalog gives none.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with.
    J_1 : pint.Quantity [kg*m**2]
        Input inertia of each gearbox row (NaN where the catalog gives none).
    coupling : calc.sections.coupling.CouplingResult or None
        The coupling section's result; None where the case has no coupling.
    catalog_rotors : bool
        Each catalog motor brings its own rotor (the case's motor inertia is not needed).

    Returns
    -------
    tuple
        ``(J_1 with the coupling [kg·m²], the coupling's J [kg·m²] or None, what the term lacks
        or None, notes)``.
    """
    J_c, coupling_part = motor_side_coupling(coupling)
    notes, missing = [], None
    if J_c is not None:
        notes.append(f"the motor-side coupling {coupling_part} turns with the motor: "
                     f"its whole inertia J = {fmt(J_c, 'kg*cm**2')} is added to J_1")
        if np.isnan(J_c.magnitude):
            missing = (f"the rotor term needs the inertia J of the motor-side coupling {coupling_part}, "
                       f"which its catalog does not give")
    if case.motor_inertia is None and not catalog_rotors:
        missing = "the rotor term (J_motor + J_1) · α_1 needs the motor's inertia (motor.inertia)"
    return (J_1 if J_c is None else J_1 + J_c), J_c, missing, notes


#: Where a typed motor's characteristic comes from: no voltage.
TYPED_CHARACTERISTIC = "not known: a typed motor's ratings name no DC-link voltage"


@dataclass
class MotorResult(Result):
    """The motor torque through one gearbox and the motor's checks. ``load`` and ``speed`` hold one
    row (the gearbox): ``load.T_1`` has shape (1, samples).

    Parameters
    ----------
    part : str or None
        The gearbox; None for a direct drive.
    selected : bool
        Whether the gearbox is the selection's choice (or the named part); else the best-ranked.
    i : pint.Quantity [1]
        The gearbox's ratio (1 for a direct drive).
    eta : pint.Quantity [1]
        Its efficiency.
    J_1 : pint.Quantity [kg*m**2] or None
        Gearbox and motor-side coupling at the input, as counted in the rotor term; None: not
        counted.
    J_coupling : pint.Quantity [kg*m**2] or None
        The motor-side coupling's whole inertia; None without one.
    load : calc.domain.motor.MotorLoad or None
        The motor's torques; None: they need an inertia the case or catalog does not give.
    speed : pint.Quantity [rpm]
        The highest motor speed n_2max · i, one row.
    checks : list of calc.core.checks.CheckArray
        The typed ratings' checks, of one row each.
    notes : list of str
        What was left out or assumed.
    output : calc.domain.motor.OutputLoad, optional
        The load cycle at the gearbox output the torques are of.
    J_motor : pint.Quantity [kg*m**2], optional
        The rotor's inertia the torques count (None: none).
    selection : calc.domain.motor_ratings.MotorSelection, optional
        The catalog motors ranked (``[motor] catalog`` or ``part``).
    segments : tuple, optional
        Each sample's segment number and each segment's phase name (the motion's segments, or
        the typed ones).
    thermal_rating : tuple, optional
        The winding's reference torque's symbol (``M_0``, or ``M_N``), its value [N·m] and the
        thermal time constant [s], where the motor gives ``T_th``: the winding's model is made.
    characteristic_dc_link : tuple, optional
        The DC-link voltage the checked motor's speed-torque characteristic is for [V] (None where
        not known) and where it comes from (:func:`characteristic_dc_link`).
    """

    part: str | None
    selected: bool
    i: object
    eta: object
    J_1: object
    J_coupling: object
    load: MotorLoad | None
    speed: object
    checks: list
    notes: list
    output: OutputLoad | None = None
    J_motor: object = None
    selection: MotorSelection | None = None
    segments: tuple | None = None
    thermal_rating: tuple | None = None
    characteristic_dc_link: tuple = (None, TYPED_CHARACTERISTIC)

    @property
    def row_checks(self) -> list:
        """The motor's checks (:class:`calc.core.checks.Check`) through the gearbox: the typed
        ratings', or the best-ranked catalog motor's."""
        if self.selection is not None:
            return self.selection.best.checks
        return [c.at(0) for c in self.checks]

    ranking = RANKING

    @functools.cached_property
    def phases(self) -> list:
        """The cycle at the motor, segment by segment (:class:`calc.domain.motor.Phase`), for the
        motor whose torques ``load`` holds; computed on first use."""
        if self.load is None or self.segments is None:
            return []
        return phases(*self.segments, *self._at_motor)

    @functools.cached_property
    def energy(self) -> Energy | None:
        """Its power and the energy it gives back per cycle (:func:`calc.domain.motor.energy`)."""
        return None if self.load is None else energy(*self._at_motor)

    @functools.cached_property
    def thermal(self) -> Winding | None:
        """The winding's first-order model over the cycle (:func:`calc.domain.drive.winding`), where
        the motor gives its thermal time constant and the torques are known; else None."""
        if self.thermal_rating is None or self.load is None:
            return None
        dt, _, T_1 = self._at_motor
        return winding(dt, T_1, *self.thermal_rating)

    @property
    def _at_motor(self) -> tuple:
        """Durations [s], motor speeds [rad/s] and motor torques [N·m] of the samples."""
        out = self.output
        return out.dt.m_as("s"), (out.speed * self.i).m_as("rad/s"), self.load.T_1[0].m_as("N*m")

    @functools.cached_property
    def steps(self) -> list:
        """(title, calc.core.formula.Step, note or None) of the motor torque at the driving and the
        driven-back peak and of its RMS (:func:`motor_steps`), computed here on first use."""
        if self.load is None:
            return []
        return motor_steps(self.output, self.load, self.i, self.eta, self.J_motor, self.J_1)

    @property
    def through(self) -> str:
        """What the motor drives: ``gearbox NPT035-10`` or ``the load directly`` (a direct drive)."""
        return "the load directly" if self.part is None else f"gearbox {self.part}"

    def to_json(self, candidates: int | None = None) -> dict:
        load = self.load
        out = {
            "gearbox": self.part,
            "gearbox_selected": self.selected,
            "ratio": float(self.i.m_as("")),
            "eta": float(self.eta.m_as("")),
            "J_1": None if self.J_1 is None else quantity(self.J_1, "kg*cm**2", "motor.J_1"),
            "J_coupling": (None if self.J_coupling is None
                           else quantity(self.J_coupling, "kg*cm**2", "motor.J_coupling")),
            "rotor_term": bool(load is not None and load.rotor_term),
            "peak_torque_required": (None if load is None
                                     else quantity(load.peak[0], "N*m", "motor.peak_torque_required")),
            "rms_torque_required": None if load is None else quantity(load.rms[0], "N*m", "motor.rms_torque_required"),
            "max_speed_required": quantity(self.speed[0], "rpm", "motor.max_speed_required"),
            "characteristic_dc_link": {
                "value": (None if self.characteristic_dc_link[0] is None
                          else quantity(Q_(self.characteristic_dc_link[0], "V"), "V", "motor.characteristic_dc_link")),
                "from": self.characteristic_dc_link[1]},
            "checks": [check_json(c) for c in self.row_checks],
            "notes": list(self.notes),
            "phases": [{"phase": p.phase, "duration": quantity(Q_(p.duration, "s"), "s"),
                        "speed": quantity(Q_(p.speed, "rad/s"), "rpm"),
                        "rms_torque": quantity(Q_(p.rms_torque, "N*m"), "N*m"),
                        "peak_torque": quantity(Q_(p.peak_torque, "N*m"), "N*m")}
                       for p in self.phases],
        }
        if self.energy is not None:
            e = self.energy
            out["energy"] = {"regenerated_per_cycle": quantity(Q_(e.regenerated_per_cycle, "J"), "J", "motor.energy"),
                             "peak_power": quantity(Q_(e.peak_power, "W"), "W", "motor.peak_power"),
                             "peak_braking_power": quantity(Q_(e.peak_braking_power, "W"), "W",
                                                            "motor.peak_braking_power")}
        w = self.thermal
        if w is not None:
            out["thermal"] = {"model": THERMAL_MODEL, "utilization": number(w.utilization),
                              "reference": w.reference,
                              "reference_torque": quantity(Q_(w.reference_torque, "N*m"), "N*m", "motor.thermal"),
                              "thermal_time_constant": quantity(Q_(w.T_th, "s"), "min", "motor.thermal")}
        sel = self.selection
        if sel is not None:
            one = len(sel.catalog.members) == 1
            out.update({
                "catalog": display_path(sel.catalog.path) if one else [display_path(p) for p, _ in sel.catalog.members],
                "selected": sel.selected,
                "ranking": self.ranking,
                "mean_speed": quantity(Q_(sel.mean_speed, "rad/s"), "rpm", "motor.mean_speed"),
                "max_inertia_ratio": {"value": sel.inertia_limit, "from": sel.inertia_limit_from},
                "dc_link_voltage": (None if sel.dc_link is None
                                    else quantity(sel.dc_link, "V", "motor.dc_link_voltage")),
                "candidates": [{"part": c.part, "passes": c.passes, "characteristic": c.form,
                                "rated_torque": c.rated_torque.to_json(),
                                "rotor_inertia": c.rotor_inertia.to_json(), "inertia_ratio": c.inertia_ratio,
                                "checks": [check_json(k) for k in c.checks], **row_json(c)}
                               for c in sel.candidates(candidates)],
            })
        return out

    def summary_lines(self, candidates: int | None = None) -> list[str]:
        j = self.to_json()
        best_ranked = f"{self.through}, the best-ranked gearbox (none is selected)"
        which = self.through if self.selected or self.part is None else best_ranked
        n_1max = "n_2max" if self.part is None else "n_2max · i"
        lines = [
            f"Motor through {which}: T_1peak = {quantity_text(j['peak_torque_required'])}, "
            f"T_1rms = {quantity_text(j['rms_torque_required'])}, {n_1max} = {quantity_text(j['max_speed_required'])}"
        ]
        if self.energy is not None:
            e = self.energy
            lines.append(f"  Power at the motor: peak {Q_(e.peak_power, 'W'):.4g~P} driving, "
                         f"{Q_(e.peak_braking_power, 'W'):.4g~P} braking; "
                         f"{Q_(e.regenerated_per_cycle, 'J'):.4g~P} given back per cycle")
        w = self.thermal
        if w is not None:
            lines.append(f"  Winding (first-order model, T_th = {Q_(w.T_th, 's').to('min'):.4g~P}): "
                         f"θ_max = {w.utilization:.3g} of its rise under {w.reference} held")
        sel = self.selection
        if sel is None:
            lines += [f"        {check_line(c.at(0))}" for c in self.checks]
        else:
            shown = sel.candidates(candidates)
            lines.append(f"  Motor {sel.selected or 'none passes'} from {sel.catalog.shown_name} "
                         f"({len(sel.order)} ranked; "
                         f"mean speed {quantity_text(j['mean_speed'])}, "
                         f"λ <= {sel.inertia_limit:g} from {sel.inertia_limit_from}):")
            for k, c in enumerate(shown, start=1):
                verdict = {True: "PASS", False: "FAIL", None: "NOT DECIDED"}[c.passes]
                worst = "n/a" if c.worst is None else f"{c.worst:.2f}"
                lines.append(f"  {k:>3}. {c.part:<28} {verdict:<11} worst {worst:>5}  M_N {c.rated_torque}  "
                             f"J {c.rotor_inertia}  ({c.form})"
                             + (f"  {'; '.join(c.reasons)}" if c.reasons else ""))
            lines.append(f"  Checks of {sel.best.part}" + ("" if sel.selected else " (the closest; none passes)") + ":")
            lines += [f"        {check_line(k)}" for k in self.row_checks]
            U = j["characteristic_dc_link"]
            lines.append(f"  Its characteristic is for U_DC = {quantity_text(U['value'])} ({U['from']})")
        return lines + [f"  Note: {n}" for n in self.notes]

    def governing(self) -> Governing | None:
        """The motor's checks.

        Returns
        -------
        calc.sections.common.Governing or None
            The best-ranked catalog motor's, or the typed ratings' governing checks; None where
            the case gives no rating to check.
        """
        if self.selection is not None:
            return selection_governing(NAME, self.selection)
        governing = [k for k in self.row_checks if k.governs]
        return Governing(NAME, None, True, governing) if governing else None

    def unchecked(self) -> list[str]:
        """The motor's checks not made for want of a rating.

        Returns
        -------
        list of str
            Each with why.
        """
        return [f"{NAME}: {n}" for n in self.notes if " not checked" in n]

    def ranked(self) -> MotorSelection | None:
        """The catalog motors ranked.

        Returns
        -------
        calc.domain.motor_ratings.MotorSelection or None
            The ranking; None for a motor the case types.
        """
        return self.selection

    def verdict(self) -> Verdict | None:
        """The motor's verdict.

        Returns
        -------
        calc.sections.common.Verdict or None
            False where a check fails, None where one cannot be made; no verdict without a rating.
        """
        if self.selection is not None:
            return selection_verdict(self.selection, "motor", f"the cycle through {self.through}")
        if not self.checks:
            return None
        made = [c.at(0) for c in self.checks]
        failing = [f"Motor through {self.through}: {c.reason()}" for c in made if c.passes is False]
        if failing:
            return Verdict(False, failing)
        open_ = [f"Motor through {self.through}: {c.reason()}" for c in made if c.passes is None]
        return Verdict(None, open_) if open_ else Verdict(True)


@dataclass(frozen=True)
class Transmission:
    """What is between the motor and the load's cycle: the gearbox row the motor drives through
    (its part, ratio, efficiency and input inertia as a one-row array), or nothing (a direct
    drive: ratio and efficiency 1, no J_1).

    Parameters
    ----------
    part : str or None
        The gearbox row; None for a direct drive.
    selected : bool
        Whether it is the selection's choice; else the best-ranked.
    i : pint.Quantity [1]
        Its ratio.
    eta : pint.Quantity [1]
        Its efficiency.
    J_1 : pint.Quantity [kg*m**2]
        Its input inertia, a one-row array (zero for a direct drive).
    notes : list of str
        What the motor's checks should say of it.
    """

    part: str | None
    selected: bool
    i: object
    eta: object
    J_1: object
    notes: list


def transmission(gearbox) -> Transmission:
    """What the motor drives through.

    Parameters
    ----------
    gearbox : calc.sections.gearbox.GearboxResult or None
        The gearbox section's result; None where the case has no gearbox (a direct drive).

    Returns
    -------
    Transmission
        The best-ranked row of the gearbox, or a direct drive (ratio and efficiency 1, no J_1).
    """
    if gearbox is None:
        return Transmission(None, True, Q_(1.0, ""), Q_(1.0, ""), Q_(np.zeros(1), "kg*m**2"), [])
    sel = gearbox.selection
    row = int(sel.order[0])
    cat = sel.catalog
    best = f"no gearbox is selected: the motor is checked through {cat.parts[row]}, the best-ranked"
    notes = [] if sel.selected is not None else [best]
    return Transmission(str(cat.parts[row]), sel.selected is not None, cat["ratio"][row], cat["eta"][row],
                        sel.J_1[row:row + 1], notes)


class MotorSection(Section):
    """The motor's side: the motor torque through the gearbox the case is checked with (or
    directly), with a motor-side coupling's inertia, checked against the motor's ratings or
    every motor of its catalog."""

    NAME = NAME
    REQUIRES = ("axis", "gearbox", "coupling")

    def applies(self, case: Case) -> bool:
        """With a catalog motor, or any of the motor's figures; through the gearbox, or directly.

        Parameters
        ----------
        case : calc.sections.case.Case
            The case as read.

        Returns
        -------
        bool
            True where the case gives a motor catalog or a motor figure.
        """
        given = (case.motor_peak_torque, case.motor_inertia, case.motor_rated_torque, case.motor_max_speed,
                 case.motor_catalog)
        return any(q is not None for q in given)

    def evaluate(self, case: Case, earlier) -> MotorResult:
        axis = earlier["axis"]
        return motor_result(axis.case, transmission(earlier.get("gearbox")), earlier.get("coupling"), axis.chosen)


SECTION = MotorSection()


def motor_result(case: Case, t: Transmission, coupling, chosen: str | None = None) -> MotorResult:
    """The motor's torques through a transmission and its checks.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with.
    t : Transmission
        What the motor drives through.
    coupling : calc.sections.coupling.CouplingResult or None
        The coupling section's result; None where the case has no coupling.
    chosen : str, optional
        The catalog motor chosen with the gearbox (:class:`calc.sections.axis.AxisResult`): ranked
        first, failing or not (the case is checked with its ratings).

    Returns
    -------
    MotorResult
        The motor's torques, checks and notes (the catalog motors ranked where the case has a
        motor catalog).
    """
    out = output_load(case)
    notes = list(t.notes)
    J_1 = J_c = None
    missing = None
    if out.sampled:
        # J_1 for the motor shaft's clamping hub
        J_1, J_c, missing, more = rotor_inertia(case, t.J_1, coupling, catalog_rotors=case.motor_catalog is not None)
        notes += more
        if missing is None and np.isnan(J_1[0].magnitude):
            missing = (f"the rotor term (J_motor + J_1) · α_1 needs J_1, which the catalog does not give "
                       f"for {t.part}")
    else:
        notes.append(TYPED)
    speed = n_1(n_2=out.n_2max, i=t.i * np.ones(1))
    J_1 = None if missing or J_1 is None else J_1[0]
    if case.motor_catalog is not None:
        return _catalog_motor(case, t, out, J_1, J_c, missing, speed, notes, chosen)
    load = None if missing else motor_load(out.dt, out.torque, out.speed, t.i, t.eta, out.alpha_2, case.motor_inertia,
                                           J_1)
    if load is not None:
        load = MotorLoad(load.T_1[None, :], load.peak[None], load.rms[None], load.rotor_term)  # one row: the gearbox
    checks = motor_checks(
        speed, None if load is None else load.peak, None if load is None else load.rms,
        case.motor_peak_torque, case.motor_rated_torque, case.motor_max_speed, not_made=missing,
    )
    for key, what in (("peak_torque", "peak"), ("rated_torque", "RMS"), ("max_speed", "speed")):
        if getattr(case, f"motor_{key}") is None:
            notes.append(f"the motor's {what} is not checked: the case gives no motor.{key}")
    thermal = None
    if case.motor_thermal_time_constant is not None and case.motor_rated_torque is not None:
        thermal = ("M_N", case.motor_rated_torque.m_as("N*m"), case.motor_thermal_time_constant.m_as("s"))
    return MotorResult(t.part, t.selected, t.i, t.eta, J_1, J_c, load, speed, checks, notes, output=out,
                       J_motor=case.motor_inertia, segments=segments_of(case), thermal_rating=thermal)


def _catalog_motor(case: Case, t: Transmission, out: OutputLoad, J_1, J_c, missing, speed, notes,
                   chosen: str | None) -> MotorResult:
    """Every motor of the case's catalog (or its part alone) against the cycle through ``t``."""
    cat = motor_catalog(case)
    if case.motor_part is not None:
        cat = cat.rows(cat.parts == case.motor_part)
    elif cat.partial.any():  # never ranked: not computed either
        notes.append(f"{int(cat.partial.sum())} partial rows of the motor catalog are never ranked "
                     f"(no rated or peak torque published)")
        cat = cat.rows(~cat.partial)
    J = cat["J"]
    if missing is not None:  # J_1 or the coupling's inertia unknown: the rotor term counts what is known
        notes.append(missing)
    J_1q = Q_(0.0, "kg*m**2") if J_1 is None else J_1
    few = out.distinct()  # every motor against each distinct sample once
    T_1 = motor_torque(few.torque, few.speed, t.i, t.eta, few.alpha_2, J[:, None], J_1q)
    T_1 = Q_(np.broadcast_to(T_1.m_as("N*m"), (len(cat), len(few.dt))), "N*m")
    rms = T_1rms(T_1k=T_1, t_k=few.dt)
    J_L = case.load_inertia
    lam = None if J_L is None else inertia_ratio(J_1=J_1q, J_L=J_L, i=t.i, J_motor=J).m_as("")
    no_ratio = "the inertia ratio needs the load's inertia (load.inertia or a [mechanism])"
    cycle = Cycle(T_1.m_as("N*m"), (few.speed * t.i).m_as("rad/s"), few.dt.m_as("s"), rms.m_as("N*m"), lam,
                  None if J_L is not None else no_ratio)
    limit, where = case.motor_max_inertia_ratio
    curves = None if case.motor_curves is None else read_curves(case.motor_curves, motor_catalog(case).parts)
    sel = select_motors(cat, cycle, case.voltage_limit_dc_link[0], curves, limit, where,
                        float(case.profile.t_cycle.m_as("s")))
    if chosen is not None:  # the motor the case is checked with is the one every output names
        sel.put_first(chosen, failing=True)
    best = int(sel.order[0])
    # Every sample, in time.
    T_best = motor_torque(out.torque, out.speed, t.i, t.eta, out.alpha_2, J[best:best + 1, None], J_1q)
    # One row, the chosen motor's, with or without a rotor term.
    T_best = Q_(np.atleast_2d(T_best.m_as("N*m")), "N*m")
    load = MotorLoad(T_best, np.abs(T_1[best:best + 1]).max(axis=-1), rms[best:best + 1], out.sampled)
    return MotorResult(t.part, t.selected, t.i, t.eta, J_1, J_c, load, speed, [], notes + sel.notes, output=out,
                       J_motor=J[best], selection=sel, segments=segments_of(case),
                       thermal_rating=thermal_rating(cat, best),
                       characteristic_dc_link=characteristic_dc_link(case, sel))


def characteristic_dc_link(case: Case, sel: MotorSelection) -> tuple:
    """The DC-link voltage the checked motor's speed-torque characteristic is for, and where it
    comes from: the case's (``motor.dc_link_voltage``, or the drive the case names) where its
    voltage limit is computed, else the ``U_DC`` its catalog row's ratings or curves are given for.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    sel : calc.domain.motor_ratings.MotorSelection
        The motors ranked, the checked one first.

    Returns
    -------
    tuple
        ``(U [V] or None, where from)``.
    """
    row = int(sel.order[0])
    part, form = str(sel.catalog.parts[row]), sel.forms[row]
    if form == "voltage limit":
        U, where = case.voltage_limit_dc_link
        return float(U.m_as("V")), f"{where}, the voltage limit of {part}"
    what = "ratings" if form == "ratings" else "digitised curves"
    rated = float(sel.catalog["U_DC"][row].m_as("V"))
    if np.isnan(rated):
        return None, f"not known: the {what} of {part}, whose catalog row gives no U_DC"
    return rated, f"the U_DC of {part}'s catalog row, for its {what}"


def thermal_rating(cat, row: int) -> tuple | None:
    """What the winding's model needs of a catalog motor: ``(M_0 or M_N, its torque [N·m], T_th [s])``.

    Parameters
    ----------
    cat : calc.data.catalog.Catalog
        A motor catalog.
    row : int
        The motor's row.

    Returns
    -------
    tuple or None
        None where the row gives no thermal time constant.
    """
    T_th = float(cat["T_th"][row].m_as("s"))
    if np.isnan(T_th):
        return None
    M_0 = float(cat["M_0"][row].m_as("N*m"))
    return ("M_N", float(cat["M_N"][row].m_as("N*m")), T_th) if np.isnan(M_0) else ("M_0", M_0, T_th)


def segments_of(case: Case) -> tuple:
    """Each sample's segment number and each segment's phase name.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.

    Returns
    -------
    tuple
        (segment number of each sample, phase name of each segment): the motion's segments, or
        the typed segments one sample each.
    """
    if case.motion is not None:
        s = case.motion.samples
        return s.segment, [PHASES[p] for p in s.segment_phases]
    return np.arange(len(case.profile.phases)), list(case.profile.phases)


def motor_steps(out: OutputLoad, load: MotorLoad, i, eta, J_motor, J_1) -> list:
    """The steps of the motor torque at the highest driving and driven-back sample (with the
    motor's acceleration there, where the cycle is sampled), and of its RMS over the cycle.

    Parameters
    ----------
    out : calc.domain.motor.OutputLoad
        The load cycle at the gearbox output.
    load : calc.domain.motor.MotorLoad
        The motor's torques, one row.
    i : pint.Quantity [1]
        The gearbox's ratio.
    eta : pint.Quantity [1]
        Its efficiency.
    J_motor : pint.Quantity [kg*m**2] or None
        The rotor's inertia counted; None: none.
    J_1 : pint.Quantity [kg*m**2] or None
        The gearbox's (and motor-side coupling's) input inertia counted; None: none.

    Returns
    -------
    list of tuple
        (title, :class:`calc.core.formula.Step`, note or None) of each.
    """
    none = Q_(0.0, "kg*m**2")  # a typed cycle counts no inertia (its α_1 is zero too)
    args = dict(i=i, eta=eta, J_motor=none if J_motor is None else J_motor, J_1=none if J_1 is None else J_1)
    T_1 = load.T_1[0]
    back = driven_back(out.torque, out.speed)
    steps = []
    peaks = (("Motor torque at the peak, driving", T_1_drive, ~back),
             ("Motor torque at the peak, driven back", T_1_back, back))
    for title, formula, mask in peaks:
        if not mask.any():
            continue
        k = int(np.flatnonzero(mask)[np.argmax(np.abs(T_1.m_as("N*m")[mask]))])
        a_1 = Q_(0.0, "rad/s**2")
        if out.sampled:
            a = alpha_1.step(alpha_2=out.alpha_2[k], i=i)
            steps.append((f"{title}: motor acceleration", a, None))
            a_1 = a.result
        steps.append((title, formula.step(alpha_1=a_1, T_2=out.torque[k], **args),
                      "driven back: T_2 · ω_2 < 0" if formula is T_1_back else "driving: T_2 · ω_2 >= 0"))
    steps.append(("RMS motor torque over the whole cycle", T_1rms.step(result=load.rms[0], T_1k=T_1, t_k=out.dt), None))
    return steps

