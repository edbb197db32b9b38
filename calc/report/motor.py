"""The motor's side in the calc report: the motor's ratings among the inputs, the motor torque
through the chosen gearbox as calculations (driving, driven back, RMS), its checks, and the motor
torque over the cycle as a figure."""

from __future__ import annotations

from ..domain.motor import T_1rms
from ..core.units import latex_unit, sig
from .common import candidates_table, checks_table, input_row, nothing, rejected, result_of
from .latex import itemize, latex_escape, prose, q, step_block, symbol_math, table

NAME = "motor"

#: The motor's ratings and the stop torque, as the case gives them: the case's field, the key.
RATINGS = (
    ("motor_rated_torque", "motor.rated_torque"), ("motor_max_speed", "motor.max_speed"),
    ("emergency_stop_torque", "gearbox.emergency_stop_torque"),
)
#: Above this many samples the RMS is shown as its formula and result, not every substituted term.
SHOWN_TERMS = 12
#: The catalog motors whose ratings the report lists, best first.
SHOWN_ROWS = 12


def input_rows(report) -> list[list[str]]:
    c = report.case
    return [input_row(key, getattr(c, attr)) for attr, key in RATINGS if getattr(c, attr) is not None]


def steps(report) -> list[str]:
    m = result_of(NAME, report)
    if m is None or m.load is None:
        return []
    if m.part is None:
        heading = "The motor, driving the load directly"
    else:
        which = "the selected gearbox" if m.selected else "the best-ranked gearbox (none is selected)"
        heading = f"The motor through {which}, {m.part}"
    if m.selection is not None:
        heading += f": {m.selection.best.part}" + ("" if m.selection.selected else " (the closest; none passes)")
    blocks = [rf"\subsection{{{latex_escape(heading)}}}"]
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
    motor = "The motor" if m.selection is None else f"Motor {m.selection.best.part}"
    out = [checks_table(m.row_checks, f"{motor} through {m.through}")] if m.row_checks else []
    return out + ([itemize([latex_escape(n) for n in m.notes])] if m.notes else [])


def candidates(report) -> list[str]:
    """The catalog motors: each one's ratings and characteristic, the utilization of each check,
    and why the closest rejected ones fail."""
    m = result_of(NAME, report)
    if m is None or m.selection is None:
        return []
    sel = m.selection
    listed = sel.candidates()
    rows = [[latex_escape(c.part), q(c.rated_torque), q(c.rotor_inertia), "–" if c.inertia_ratio is None else f"{c.inertia_ratio:.2f}",
             latex_escape(c.form)] for c in listed[:SHOWN_ROWS]]
    more = f"; {len(listed) - SHOWN_ROWS} more in the candidates' utilization below" if len(listed) > SHOWN_ROWS else ""
    return [r"\subsection*{Motor}",
            table(r"@{}l r r r l@{}",
                  ["Part", *map(symbol_math, ("M_N_motor", "J_motor", "lambda")), "Peak characteristic"], rows,
                  caption=latex_escape(f"The motors of {sel.catalog.shown_name}, best first ({sel.inertia_limit:g} is the limit of λ, "
                                       f"from {sel.inertia_limit_from}){more}"), small=True),
            candidates_table(listed, sel.selected, latex_escape("Utilization of each check of the motor candidates, best first")),
            *rejected(listed)]


def chosen(report) -> list[tuple]:
    m = result_of(NAME, report)
    if m is None or m.selection is None:
        return []
    return [("Motor", m.selection.selected, f"catalog {m.selection.catalog.shown_name}")]


def figures(report) -> list:
    m = result_of(NAME, report)
    if m is None or m.load is None:
        return []
    from ..figures.motor_plots import motor_torque_figure

    c = report.case
    out = [(motor_torque_figure(m.output, m.load, 0, c.motor_peak_torque, c.motor_rated_torque, m.part or ""),
            latex_escape(f"Motor torque over the cycle through {m.through}, its RMS and the motor's ratings."))]
    if m.selection is not None:
        from ..figures.motor_plots import torque_speed_figure

        best = int(m.selection.order[0])
        out.append((torque_speed_figure(m.selection, best),
                    latex_escape(f"The cycle's operating points under the peak characteristic of {m.selection.catalog.parts[best]}, "
                                 "its rated point and the RMS torque at the mean speed.")))
    return out


def order_lines(report) -> list[str]:
    m = result_of(NAME, report)
    if m is None or m.selection is None or m.selection.selected is None:
        return []
    sel = m.selection
    row = int(sel.order[0])
    family = str(sel.catalog.family[row])
    return [rf"Motor \textbf{{{latex_escape(sel.selected)}}}" + latex_escape(f" ({sel.catalog.text['maker'][row]}" + (f", {family}" if family else "") + ")")]


inputs = results = sources = readings = nothing
