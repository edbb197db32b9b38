"""The motor's side in the outputs: in the calc report the motor's ratings among the inputs, the
motor torque through the chosen gearbox as calculations (driving, driven back, RMS), its checks,
and the motor torque over the cycle as a figure; on the review's page the catalog motors ranked;
its chosen part in the comparison of designs."""

from __future__ import annotations

from html import escape

from ..domain.motor import T_1rms
from ..core.units import latex_unit, sig
from ..sections.motor import NAME
from .common import Renderer, block_doc, candidates_table, checks_table, input_row, page_doc, rejected
from .latex import itemize, latex_escape, prose, q, step_block, symbol_math, table
from .page import FORCING, candidates_shown, table as html_table, utilization, value, verdict_cell
from .symbols import html as typeset

#: The motor's ratings and the stop torque, as the case gives them: the case's field, the key.
RATINGS = (
    ("motor_rated_torque", "motor.rated_torque"), ("motor_max_speed", "motor.max_speed"),
    ("emergency_stop_torque", "gearbox.emergency_stop_torque"),
)
#: Above this many samples the RMS is shown as its formula and result, not every substituted term.
SHOWN_TERMS = 12
#: The catalog motors whose ratings the report lists, best first.
SHOWN_ROWS = 12


class MotorRenderer(Renderer):
    """The motor's side: its ratings, steps, checks, catalog motors, chosen part, figures and
    order line in the report, its catalog motors on the page, its chosen part in the comparison."""

    NAME = NAME
    COMPARED_PART = True

    def input_rows(self, report) -> list[list[str]]:
        c = report.case
        return [input_row(key, getattr(c, attr)) for attr, key in RATINGS if getattr(c, attr) is not None]

    def steps(self, report) -> list[str]:
        m = self.result(report)
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
            blocks.append(prose("The load cycle is typed: its accelerations are not known, so the rotor term "
                                "(J_motor + J_1) · α_1 is left out."))
        for title, step, note in m.steps:
            samples = len(m.output.dt)
            if step.formula is T_1rms and samples > SHOWN_TERMS:  # the formula and its result, not every term
                rms = rf"${T_1rms.latex()} = {sig(step.result.m_as('N*m'))}\,{latex_unit('N*m')}$"
                over = latex_escape(f" over the {samples} samples of the cycle. ")
                blocks.append(rf"\paragraph{{{title}.}} {rms}" + over + prose(T_1rms.reference))
            else:
                blocks.append(step_block(title, step, note or ""))
        return blocks

    def checks(self, report) -> list[str]:
        m = self.result(report)
        if m is None:
            return []
        motor = "The motor" if m.selection is None else f"Motor {m.selection.best.part}"
        out = [checks_table(m.row_checks, f"{motor} through {m.through}")] if m.row_checks else []
        return out + ([itemize([latex_escape(n) for n in m.notes])] if m.notes else [])

    @block_doc("The catalog motors: each one's ratings and characteristic, the utilization of each check, and why "
               "the closest rejected ones fail.",
               "list of str", "LaTeX; nothing for a motor the case types, or none.")
    def candidates(self, report) -> list[str]:
        m = self.result(report)
        if m is None or m.selection is None:
            return []
        sel = m.selection
        listed = sel.candidates()
        rows = [[latex_escape(c.part), q(c.rated_torque), q(c.rotor_inertia),
                 "–" if c.inertia_ratio is None else f"{c.inertia_ratio:.2f}", latex_escape(c.form)]
                for c in listed[:SHOWN_ROWS]]
        left = len(listed) - SHOWN_ROWS
        more = f"; {left} more in the candidates' utilization below" if left > 0 else ""
        caption = (f"The motors of {sel.catalog.shown_name}, best first ({sel.inertia_limit:g} is the limit of λ, "
                   f"from {sel.inertia_limit_from}){more}")
        header = ["Part", *map(symbol_math, ("M_N_motor", "J_motor", "lambda")), "Peak characteristic"]
        return [r"\subsection*{Motor}",
                table(r"@{}l r r r l@{}", header, rows, caption=latex_escape(caption), small=True),
                candidates_table(listed, sel.selected,
                                 latex_escape("Utilization of each check of the motor candidates, best first")),
                *rejected(listed)]

    def chosen(self, report) -> list[tuple]:
        m = self.result(report)
        if m is None or m.selection is None:
            return []
        return [("Motor", m.selection.selected, f"catalog {m.selection.catalog.shown_name}")]

    def figures(self, report) -> list:
        m = self.result(report)
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
                        latex_escape(f"The cycle's operating points under the peak characteristic of "
                                     f"{m.selection.catalog.parts[best]}, its rated point and the RMS torque "
                                     "at the mean speed.")))
        return out

    def order_lines(self, report) -> list[str]:
        m = self.result(report)
        if m is None or m.selection is None or m.selection.selected is None:
            return []
        sel = m.selection
        row = int(sel.order[0])
        family = str(sel.catalog.family[row])
        maker = f" ({sel.catalog.text['maker'][row]}" + (f", {family}" if family else "") + ")"
        return [rf"Motor \textbf{{{latex_escape(sel.selected)}}}" + latex_escape(maker)]

    @page_doc("The catalog motors, best first; nothing for a motor the case types, or none.",
              "m", "calc.sections.motor.MotorResult")
    def page(self, m, view) -> str:
        if m is None or m.selection is None:
            return ""
        sel = m.selection
        shown, more = candidates_shown(sel, view.shown)
        rows = [
            [str(k), escape(c.part), verdict_cell(c.passes), utilization(c.worst), value(c.rated_torque),
             value(c.rotor_inertia), "" if c.inertia_ratio is None else sig(c.inertia_ratio, 3), escape(c.form),
             "<br>".join(typeset(x) for x in c.reasons)]
            for k, c in enumerate(shown, start=1)
        ]
        header = ["rank", "part", "verdict", "worst utilization", typeset("M_N"), typeset("J_motor"), "inertia ratio λ",
                  "peak characteristic", "reasons"]
        return (f"<h3>Motor candidates, through {escape(m.through)}</h3>"
                f"<div class=note>{typeset(m.ranking)}; {FORCING}</div>"
                + html_table(header, rows, numeric={0, 3, 4, 5, 6}, marked=0 if sel.selected else None,
                             force=("motor.part", [c.part for c in shown]))
                + more)


RENDERER = MotorRenderer()
