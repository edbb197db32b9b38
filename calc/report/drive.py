"""The servo drive in the outputs: in the calc report its keys among the inputs, the motor's current
and the braking as calculations, its checks, the drives ranked, the braking events, the winding's
temperature as a figure, the chosen drive on the front page and in the order; on the review's page
the drive, its checks and its braking; its chosen part in the comparison of designs."""

from __future__ import annotations

from html import escape

from ..core.units import Q_
from ..domain.drive import I_ph, RANKING
from ..sections.drive import NAME, SECTION
from .common import Renderer, block_doc, candidates_table, checks_table, input_row, page_doc, rejected, result_of
from .latex import itemize, latex_escape, prose, table
from .page import table as html_table, utilization, verdict_cell

#: The keys of ``[drive]`` the inputs table lists where given, as quantities.
KEYS = ("rated_current", "peak_current", "peak_time", "dc_link_voltage", "dc_link_energy", "chopper_voltage")


def _events(r) -> list[list[str]]:
    """Each braking event: phase, start, duration, energy, peak power, what the resistor takes."""
    return [[e.phase or "braking", f"{e.start:.4g} s", f"{e.duration:.4g} s", f"{e.energy:.4g} J",
             f"{e.peak_power:.4g} W", f"{x:.4g} J"]
            for e, x in zip(r.braking.events, r.braking.resistor_energies)]


EVENT_HEADER = ["event", "start", "duration", "energy", "peak power", "to the resistor"]


class DriveRenderer(Renderer):
    """The servo drive."""

    NAME = NAME
    COMPARED_PART = True

    def input_rows(self, report) -> list[list[str]]:
        given = SECTION.inputs(report.case)
        if given is None:
            return []
        rows = [input_row(f"drive.{k}", v) for k, v in given.typed.items()]
        if given.chopper_voltage is not None:
            rows.append(input_row("drive.chopper_voltage", given.chopper_voltage))
        return rows + [input_row(f"drive.brake_resistor.{k}", v) for k, v in given.resistor.items()]

    def steps(self, report) -> list[str]:
        r = self.result(report)
        if r is None or r.current_peak is None:
            return []
        from .latex import step_block

        k_T = Q_(r.motor.k_T, "N*m/A")
        peak = I_ph.step(T_1=Q_(r.current_peak * r.motor.k_T, "N*m"), k_T=k_T)
        b = r.braking
        text = (f"The cycle brakes {len(b.events)} times; the DC link absorbs "
                + ("an unknown energy" if b.dc_link_energy is None else f"{b.dc_link_energy:.4g} J")
                + f" of each ({b.dc_link_from}); {b.energy_per_cycle:.4g} J per cycle are left for a resistor, "
                f"{b.average_power:.4g} W over the cycle; the peak braking power is {b.peak_power:.4g} W.")
        return [r"\subsection{The servo drive}",
                step_block(f"Motor current at the peak torque (k_T: {r.motor.k_T_from})", peak, ""),
                prose(f"RMS current over the cycle: {r.current_rms:.4g} A. " + text)]

    def checks(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        out = [checks_table(r.checks(), f"Drive {r.part}: current, braking and winding")]
        if r.braking.events:
            out.append(table("@{}l r r r r r@{}", EVENT_HEADER, [[latex_escape(c) for c in row] for row in _events(r)],
                             caption="The braking events of the cycle", small=True))
        notes = r.notes + r.selection.notes + r.braking.notes
        return out + [itemize([latex_escape(n) for n in notes])]

    @block_doc("The drives ranked: the utilization of each check, and why the closest rejected ones fail.",
               "list of str", "LaTeX; nothing without a drive.")
    def candidates(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        listed = r.selection.candidates()
        return [r"\subsection*{Drive}", prose(RANKING + "."),
                candidates_table(listed, r.selection.selected,
                                 latex_escape("Utilization of each check of the drive candidates, best first")),
                *rejected(listed)]

    def figures(self, report) -> list:
        r = self.result(report)
        motor = None if r is None else result_of("motor", report)
        w = None if motor is None else motor.thermal
        if w is None:
            return []
        from ..figures.drive_plots import winding_figure

        return [(winding_figure(w, r.motor.part),
                 latex_escape("The winding's temperature over two cycles in the periodic state, against its rise "
                              f"under {w.reference} held (first-order model, T_th of the motor)."))]

    def chosen(self, report) -> list[tuple]:
        r = self.result(report)
        if r is None:
            return []
        return [("Drive", r.selection.selected, f"catalog {r.catalog}" if r.catalog != "typed" else "typed ratings")]

    def order_lines(self, report) -> list[str]:
        r = self.result(report)
        if r is None or r.selection.selected is None or r.catalog == "typed":
            return []
        cat = r.selection.catalog
        row = int(r.selection.order[0])
        return [rf"Drive \textbf{{{latex_escape(r.selection.selected)}}}"
                + latex_escape(f" ({cat.text['maker'][row]})")]

    @page_doc("The drive chosen, its checks and the braking events.", "r", "calc.sections.drive.DriveResult")
    def page(self, r, view) -> str:
        if r is None:
            return ""
        rows = [[escape(k.criterion), escape(str(k.required_value or "n/a")), escape(str(k.rated_value)),
                 utilization(k.utilization), verdict_cell(k.passes)] for k in r.checks()]
        shown = r.selection.candidates(view.shown)
        ranked = [[str(n), escape(c.part), verdict_cell(c.passes), "<br>".join(escape(x) for x in c.reasons)]
                  for n, c in enumerate(shown, start=1)]
        return (f"<h3>Drive {escape(r.selection.selected or 'none passes')}</h3>"
                f"<div class=note>{escape(RANKING)}</div>"
                + html_table(["rank", "part", "verdict", "reasons"], ranked, numeric={0})
                + f"<h4>Checks of {escape(r.part)}</h4>"
                + html_table(["check", "required", "rated", "utilization", "verdict"], rows, numeric={3})
                + "<h4>Braking events</h4>" + html_table(EVENT_HEADER, [[escape(c) for c in x] for x in _events(r)]))

    def compared(self) -> tuple:
        return (("drive resistor power", lambda r: "" if r is None else f"{r.braking.average_power:.4g} W"),)


RENDERER = DriveRenderer()
