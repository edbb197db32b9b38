"""The motor's side in the calc report: the motor's ratings among the inputs, the motor torque
through the chosen gearbox as calculations (driving, driven back, RMS), its checks, and the motor
torque over the cycle as a figure."""

from __future__ import annotations

from ..motor import T_1rms
from ..units import latex_unit, sig
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
    which = "the selected gearbox" if m.selected else "the best-ranked gearbox (none is selected)"
    blocks = [rf"\subsection{{The motor through {which}, {latex_escape(m.part)}}}"]
    if not m.load.rotor_term:
        blocks.append(prose("The load cycle is typed: its accelerations are not known, so the rotor term (J_motor + J_1) · α_1 is left out."))
    for title, step, note in m.steps:
        samples = len(m.output.dt)
        if step.formula is T_1rms and samples > SHOWN_TERMS:  # the formula and its result, not every term
            blocks.append(rf"\paragraph{{{title}.}} ${T_1rms.latex()} = {sig(step.result.m_as('N*m'))}\,{latex_unit('N*m')}$"
                          + latex_escape(f" over the {samples} samples of the cycle. ") + prose(T_1rms.reference))
        else:
            blocks.append(step_block(title, step, note or ""))
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
    fig = motor_torque_figure(m.output, m.load, 0, c.motor_peak_torque, c.motor_rated_torque, m.part)
    return [(fig, latex_escape(f"Motor torque over the cycle through {m.part}, its RMS and the motor's ratings."))]


inputs = results = candidates = chosen = order_lines = sources = readings = nothing
