"""The motor's side in the calc report: the motor's ratings among the inputs, the motor torque
through the chosen gearbox as calculations (driving, driven back, RMS), its checks, and the motor
torque over the cycle as a figure."""

from __future__ import annotations

import numpy as np

from ..motor import T_1_back, T_1_drive, T_1rms, alpha_1, driven_back
from ..sections.motor import output_load
from ..units import Q_, latex_unit, sig
from .common import checks_table, input_row, nothing, result_of
from .latex import itemize, latex_escape, prose, step_block

NAME = "motor"

#: The motor's ratings and the stop torque, as the case gives them: the case's field, the key.
RATINGS = (
    ("motor_rated_torque", "motor.rated_torque"), ("motor_max_speed", "motor.max_speed"),
    ("emergency_stop_torque", "gearbox.emergency_stop_torque"),
)
#: Above this many samples the RMS is shown as its formula and result, not every substituted term.
SHOWN_TERMS = 12


def input_rows(report) -> list[list[str]]:
    c = report.case
    return [input_row(key, getattr(c, attr)) for attr, key in RATINGS if getattr(c, attr) is not None]


def steps(report) -> list[str]:
    m = result_of(NAME, report)
    if m is None or m.load is None:
        return []
    out = output_load(report.case)
    T_1 = m.load.T_1[0]
    none = Q_(0.0, "kg*m**2")  # a typed cycle counts no inertia (its α_1 is zero too)
    J_motor = report.case.motor_inertia
    args = dict(i=m.i, eta=m.eta, J_motor=none if J_motor is None else J_motor, J_1=none if m.J_1 is None else m.J_1)
    which = "the selected gearbox" if m.selected else "the best-ranked gearbox (none is selected)"
    blocks = [rf"\subsection{{The motor through {which}, {latex_escape(m.part)}}}"]
    if not m.load.rotor_term:
        blocks.append(prose("The load cycle is typed: its accelerations are not known, so the rotor term (J_motor + J_1) · α_1 is left out."))
    back = driven_back(out.torque, out.speed)
    for title, formula, mask in (("Motor torque at the peak, driving", T_1_drive, ~back), ("Motor torque at the peak, driven back", T_1_back, back)):
        if not mask.any():
            continue
        k = int(np.flatnonzero(mask)[np.argmax(np.abs(T_1.m_as("N*m")[mask]))])
        a_1 = alpha_1(alpha_2=out.alpha_2[k], i=m.i) if out.sampled else Q_(0.0, "rad/s**2")
        if out.sampled:
            blocks.append(step_block(f"{title}: motor acceleration", alpha_1.step(alpha_2=out.alpha_2[k], i=m.i)))
        blocks.append(step_block(title, formula.step(alpha_1=a_1, T_2=out.torque[k], **args),
                                 "driven back: T_2 · ω_2 < 0" if formula is T_1_back else "driving: T_2 · ω_2 >= 0"))
    if len(out.dt) <= SHOWN_TERMS:
        blocks.append(step_block("RMS motor torque over the whole cycle", T_1rms.step(result=m.load.rms[0], T_1k=T_1, t_k=out.dt)))
    else:
        rms = m.load.rms[0]
        blocks.append(rf"\paragraph{{RMS motor torque over the whole cycle.}} ${T_1rms.latex()} = {sig(rms.m_as('N*m'))}\,{latex_unit('N*m')}$"
                      + latex_escape(f" over the {len(out.dt)} samples of the cycle. ") + prose(T_1rms.reference))
    return blocks


def checks(report) -> list[str]:
    m = result_of(NAME, report)
    if m is None:
        return []
    out = [checks_table(m.row_checks, f"The motor through gearbox {m.part}")] if m.row_checks else []
    return out + ([itemize([latex_escape(n) for n in m.notes])] if m.notes else [])


def figures(report) -> list:
    m = result_of(NAME, report)
    if m is None or m.load is None:
        return []
    from ..motor_plots import motor_torque_figure

    c = report.case
    fig = motor_torque_figure(output_load(c), m.load, 0, c.motor_peak_torque, c.motor_rated_torque, m.part)
    return [(fig, latex_escape(f"Motor torque over the cycle through {m.part}, its RMS and the motor's ratings."))]


inputs = results = candidates = chosen = order_lines = sources = readings = nothing
