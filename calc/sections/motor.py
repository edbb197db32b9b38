"""The motor's side of a case (``[motor]``): the motor torque over the load cycle through the
selected (or named) gearbox, with the rotor and gearbox inertia where the cycle is sampled; its
peak, its RMS over the whole cycle and the top speed checked against the motor's peak torque,
rated torque and top speed, each where the case gives it (:mod:`calc.motor`, case format "The
motor's side")."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..case import Case
from ..gearbox import n_1
from ..motor import T_1_back, T_1_drive, T_1rms, MotorLoad, OutputLoad, alpha_1, driven_back, motor_checks, motor_load
from ..units import Q_, fmt
from . import coupling, duty, gearbox
from .common import Governing, Verdict, check_json, check_line, quantity, quantity_text

NAME = "motor"
ORDER = 60

TYPED = (
    "the load cycle is typed ([[profile]]): its accelerations are not known, so the rotor term "
    "(J_motor + J_1) · α_1 is left out and the motor torque is the typed output torque through the gearbox"
)


def output_load(case: Case) -> OutputLoad:
    """The sampled cycle of the motion form where the duty result has one, else the typed segments
    (a pause with zero torque and speed)."""
    cycle = duty.evaluate(case).cycle
    if cycle is None:
        p = case.profile
        return OutputLoad(p.durations, p.torques, p.speeds, None, p.n_2max)
    return OutputLoad.from_cycle(cycle)


def motor_side_coupling(case: Case) -> tuple:
    """A motor-side coupling's whole inertia (it turns with the motor; NaN where its catalog gives
    none) and its part, or ``(None, None)`` without one: the coupling the coupling section chose
    (or its best-ranked)."""
    if not coupling.applies(case):
        return None, None
    cc, sel = coupling.coupling_selection(case)
    if cc.side != "input":
        return None, None
    row = int(sel.order[0])
    part = str(cc.catalog.parts[row])
    return cc.catalog["J"][row], part


def rotor_inertia(case: Case, J_1) -> tuple:
    """What the rotor term of a sampled cycle adds to the motor's inertia, for gearbox rows of
    input inertia ``J_1`` (an array, NaN where the catalog gives none): ``(J_1 with a motor-side
    coupling's whole inertia, that coupling's inertia or None, what the term lacks or None,
    notes)``. The term lacks the motor's inertia where the case gives none, and the coupling's
    where its catalog gives none."""
    J_c, coupling_part = motor_side_coupling(case)
    notes, missing = [], None
    if J_c is not None:
        notes.append(f"the motor-side coupling {coupling_part} turns with the motor: its whole inertia J = {fmt(J_c, 'kg*cm**2')} is added to J_1")
        if np.isnan(J_c.magnitude):
            missing = f"the rotor term needs the inertia J of the motor-side coupling {coupling_part}, which its catalog does not give"
    if case.motor_inertia is None:
        missing = "the rotor term (J_motor + J_1) · α_1 needs the motor's inertia (motor.inertia)"
    return (J_1 if J_c is None else J_1 + J_c), J_c, missing, notes


@dataclass
class MotorResult:
    """The motor torque through one gearbox and the motor's checks."""

    part: str
    selected: bool  # the gearbox is the selection's choice (or the named part); else the best-ranked
    i: object
    eta: object
    J_1: object  # gearbox and motor-side coupling at the input, as counted in the rotor term; None: not counted
    J_coupling: object
    load: MotorLoad | None  # None: the torques need an inertia the case or catalog does not give
    speed: object  # highest motor speed n_2max · i
    # load and speed hold one row (the gearbox): load.T_1 has shape (1, samples)
    checks: list  # CheckArray of one row each
    notes: list
    output: OutputLoad | None = None  # the load cycle at the gearbox output the torques are of
    #: (title, calc.formula.Step, note or None) of the motor torque at the driving and the driven-back
    #: peak and of its RMS, as computed here; the RMS step holds every sample
    steps: list = field(default_factory=list)

    @property
    def row_checks(self) -> list:
        """The motor's checks (:class:`calc.checks.Check`) through the gearbox."""
        return [c.at(0) for c in self.checks]

    def to_json(self, candidates: int | None = None) -> dict:
        load = self.load
        return {
            "gearbox": self.part,
            "gearbox_selected": self.selected,
            "ratio": float(self.i.m_as("")),
            "eta": float(self.eta.m_as("")),
            "J_1": None if self.J_1 is None else quantity(self.J_1, "kg*cm**2", "motor.J_1"),
            "J_coupling": None if self.J_coupling is None else quantity(self.J_coupling, "kg*cm**2", "motor.J_coupling"),
            "rotor_term": bool(load is not None and load.rotor_term),
            "peak_torque_required": None if load is None else quantity(load.peak[0], "N*m", "motor.peak_torque_required"),
            "rms_torque_required": None if load is None else quantity(load.rms[0], "N*m", "motor.rms_torque_required"),
            "max_speed_required": quantity(self.speed[0], "rpm", "motor.max_speed_required"),
            "checks": [check_json(c) for c in self.row_checks],
            "notes": list(self.notes),
        }

    def summary_lines(self, candidates: int | None = None) -> list[str]:
        j = self.to_json()
        which = self.part if self.selected else f"{self.part}, the best-ranked gearbox (none is selected)"
        lines = [
            f"Motor through gearbox {which}: T_1peak = {quantity_text(j['peak_torque_required'])}, "
            f"T_1rms = {quantity_text(j['rms_torque_required'])}, n_2max · i = {quantity_text(j['max_speed_required'])}"
        ]
        lines += [f"        {check_line(c.at(0))}" for c in self.checks]
        return lines + [f"  Note: {n}" for n in self.notes]

    def governing(self) -> Governing | None:
        """The motor's checks; None where the case gives no rating to check."""
        governing = [k for k in self.row_checks if k.governs]
        return Governing(NAME, None, True, governing) if governing else None

    def unchecked(self) -> list[str]:
        """The motor's checks not made for want of a rating, each with why."""
        return [f"{NAME}: {n}" for n in self.notes if " not checked" in n]

    def verdict(self) -> Verdict | None:
        """False where a check fails, None where one cannot be made; no verdict without a rating."""
        if not self.checks:
            return None
        made = [c.at(0) for c in self.checks]
        failing = [f"Motor through gearbox {self.part}: {c.reason()}" for c in made if c.passes is False]
        if failing:
            return Verdict(False, failing)
        open_ = [f"Motor through gearbox {self.part}: {c.reason()}" for c in made if c.passes is None]
        return Verdict(None, open_) if open_ else Verdict(True)


def applies(case: Case) -> bool:
    """With a gearbox (the ratio and efficiency) and any of the motor's figures."""
    given = (case.motor_peak_torque, case.motor_inertia, case.motor_rated_torque, case.motor_max_speed)
    return gearbox.applies(case) and any(q is not None for q in given)


def evaluate(case: Case) -> MotorResult:
    sel = gearbox.gearbox_selection(case)
    row = int(sel.order[0])
    cat = sel.catalog
    part, i, eta = str(cat.parts[row]), cat["ratio"][row], cat["eta"][row]
    one = slice(row, row + 1)  # the checks run over rows of gearboxes: here the one row
    out = output_load(case)
    notes = [] if sel.selected is not None else [f"no gearbox is selected: the motor is checked through {part}, the best-ranked"]
    J_1 = J_c = None
    missing = None
    if out.sampled:
        J_1, J_c, missing, more = rotor_inertia(case, sel.J_1[one])  # for the motor shaft's clamping hub
        notes += more
        if missing is None and np.isnan(J_1[0].magnitude):
            missing = f"the rotor term (J_motor + J_1) · α_1 needs J_1, which the catalog does not give for {part}"
    else:
        notes.append(TYPED)
    load = None if missing else motor_load(
        out.dt, out.torque, out.speed, cat["ratio"][one, None], cat["eta"][one, None], out.alpha_2, case.motor_inertia,
        None if J_1 is None else J_1[:, None],
    )
    speed = n_1(n_2=out.n_2max, i=cat["ratio"][one])
    checks = motor_checks(
        speed, None if load is None else load.peak, None if load is None else load.rms,
        case.motor_peak_torque, case.motor_rated_torque, case.motor_max_speed, not_made=missing,
    )
    for key, what in (("peak_torque", "peak"), ("rated_torque", "RMS"), ("max_speed", "speed")):
        if getattr(case, f"motor_{key}") is None:
            notes.append(f"the motor's {what} is not checked: the case gives no motor.{key}")
    J_1 = None if missing or J_1 is None else J_1[0]
    steps = [] if load is None else motor_steps(out, load, i, eta, case.motor_inertia, J_1)
    return MotorResult(part, sel.selected is not None, i, eta, J_1, J_c, load, speed, checks, notes, out, steps)


def motor_steps(out: OutputLoad, load: MotorLoad, i, eta, J_motor, J_1) -> list:
    """(title, step, note) of the motor torque at the highest driving and driven-back sample (with
    the motor's acceleration there, where the cycle is sampled), and of its RMS over the cycle."""
    none = Q_(0.0, "kg*m**2")  # a typed cycle counts no inertia (its α_1 is zero too)
    args = dict(i=i, eta=eta, J_motor=none if J_motor is None else J_motor, J_1=none if J_1 is None else J_1)
    T_1 = load.T_1[0]
    back = driven_back(out.torque, out.speed)
    steps = []
    for title, formula, mask in (("Motor torque at the peak, driving", T_1_drive, ~back), ("Motor torque at the peak, driven back", T_1_back, back)):
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

