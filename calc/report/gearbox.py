"""The gearbox in the outputs: in the calc report its inputs, the checks of the chosen gearbox (or
the closest candidate) as calculations and as a table, the candidates with their catalog ratings,
the utilization figure and the order line; on the review's page the candidates, with the ratio
search after them where it is asked for (:meth:`calc.report.ratios.RatiosRenderer.page_block`);
its chosen part in the summary's column and in the comparison of designs."""

from __future__ import annotations

import numpy as np

from html import escape

from ..core.units import sig
from ..sections import gearbox as sections_gearbox
from . import common
from .common import Renderer, block_doc, result_of, candidates_table, checks_table, input_row, page_doc, rejected
from .latex import breakable, latex_escape, num, prose, sources_list, stacked, step_block, symbol_math, table
from .page import FORCING, candidates_shown, table as html_table, utilization, value, verdict_cell
from .ratios import RENDERER as RATIOS
from .symbols import html as typeset


class GearboxRenderer(Renderer):
    """The gearbox: its inputs, steps, checks, candidates, figures, chosen part and order line in
    the report, its candidates on the page, its chosen part in the summary and the comparison."""

    NAME = sections_gearbox.NAME
    SUMMARY_COLUMN = ("Gearbox", r"0.11\linewidth")
    COMPARED_PART = True

    def sources(self, report) -> list[str]:
        return common.sources(self.NAME)

    @block_doc("Every gearbox reading; the inertia match (E6) only where the report gives the ratio.",
               "set of str", "The readings' keys.")
    def readings(self, report) -> set[str]:
        out = common.readings(self.NAME)
        r = self.result(report)
        return out if r is not None and r.selection.inertia_ratio is not None else out - {"E6"}

    def input_rows(self, report) -> list[list[str]]:
        c = report.case
        rows = [input_row("gearbox.ratio", c.ratio)] if c.ratio is not None else []
        if c.gearbox_part:
            rows.append(input_row("gearbox.part", c.gearbox_part))
        if c.gearbox_catalog and (c.ratio is not None or c.gearbox_part):
            rows.append(input_row("gearbox.catalog", c.gearbox_catalog))
        if c.gearbox_family:
            rows.append(input_row("gearbox.family", " or ".join(c.gearbox_family)))
        if c.motor_shaft is not None:
            rows.append(input_row("motor.shaft", c.motor_shaft.text))
        load = c.output_load
        if load is not None:
            given = (("axial_force", load.axial_force), ("radial_force", load.radial_force),
                     ("lever_arm", load.lever_arm), ("axial_force_radius", load.axial_radius))
            rows += [input_row(f"load.{key}", q) for key, q in given if q is not None]
        return rows

    @block_doc("The best-ranked row's checks as the gearbox section computed them.",
               "list of str", "The calculation steps, LaTeX.")
    def steps(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        sel = r.selection
        chosen = "the chosen gearbox" if sel.selected else "the closest candidate (none passes)"
        out = [rf"\subsection{{Checks of {chosen}, {latex_escape(str(sel.catalog.parts[int(sel.order[0])]))}}}"]
        out += [step_block(title, step, note) for title, step, note in r.steps]
        return out + _one_lambda(report, r.steps)

    def checks(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        best = r.selection.best
        which = " (chosen)" if r.selection.selected else " (the closest candidate; none passes)"
        return [checks_table(best.checks, f"Checks of gearbox {best.part}{which}")]

    @block_doc("Every candidate at the ratio: its catalog ratings, and the utilization of each check.",
               "list of str", "LaTeX.")
    def candidates(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        sel = r.selection
        cat = sel.catalog
        illustrative = False
        doubts = []
        several = len(cat.members) > 1
        family, size, unclear = cat.family, cat.text_or_blank("size"), cat.text_or_blank("unclear")
        best = sel.best_of_family
        listed = sel.candidates()
        numbers, source_list = sources_list(str(cat.text["source"][r]) for r in sel.order)
        rows = []
        for r in sel.order:
            illustrative |= bool(cat.illustrative[r])
            mark = r"$^{*}$" if cat.illustrative[r] else ""
            if unclear[r]:
                doubts.append(f"{cat.parts[r]}: {unclear[r]}")
                mark += rf"$^{{\dagger{len(doubts)}}}$"
            j1, hub = sel.J_1[r], sel.J_1_hub[r]
            rows.append([
                latex_escape(str(cat.parts[r])) + mark + (r" $\star$" if best[r] else ""),
                latex_escape(f"{family[r]} {size[r]}".strip())
                + (rf" {{\scriptsize {latex_escape(cat.catalog_of(r))}}}" if several else ""),
                num(cat["T_2N"][r], "N*m"), num(cat["T_2B"][r], "N*m"),
                num(cat["n_1N"][r], "rpm"), num(cat["n_1max"][r], "rpm"),
                num(cat["eta"][r], "percent"),
                "–" if np.isnan(j1.magnitude) else num(j1, "kg*cm**2"),
                "–" if np.isnan(hub.magnitude) else sig(hub.m_as("mm")),
                f"[{numbers[str(cat.text['source'][r])]}]",
            ])
        note = (rf"$\star$ smallest adequate size of its family. {symbol_math('J_1')} for the clamping hub of bore "
                f"{symbol_math('d_hub')}. Sources by number below.")
        if doubts:
            note = "".join(rf"$^{{\dagger{k}}}$ doubtful figures of {breakable(d)}. "
                           for k, d in enumerate(doubts, start=1)) + note
        if illustrative:
            note = r"$^{*}$ illustrative row: not a maker's own figures. " + note
        return [
            table(
                r"@{}l l r r r r r r r r@{}",
                ["Part", "Family, size", *(stacked(symbol_math(symbol), f"[{unit}]") for symbol, unit in (
                    ("T_2N", "N·m"), ("T_2B", "N·m"), ("n_1N", "rpm"), ("n_1max", "rpm"), ("eta", r"\%"),
                    ("J_1", "kg·cm²"), ("d_hub", "mm"))), "Src."],
                rows, caption=latex_escape(f"Catalog ratings of the candidates ({cat.shown_name}), best first"),
                note=note, small=True, narrow=True,
            ),
            r"\paragraph{Sources of the rows.}" + source_list,
            candidates_table(listed, sel.selected, f"Utilization of each check (required / rated), {sel.mode} governs; "
                                                    "checks in grey are for information", inertia=True),
            *rejected(listed),
        ]

    def figures(self, report) -> list:
        r = self.result(report)
        if r is None:
            return []
        from ..figures.plots import comparison_figure, utilization_figure

        return [
            (utilization_figure(r.selection), "Utilization of the governing checks of each candidate, best first."),
            (comparison_figure(r.selection), "The makers compared: the highest governing utilization of each "
                                             "candidate, coloured by family (and catalog, where several are ranked "
                                             "together)."),
        ]

    def chosen(self, report) -> list[tuple]:
        r = self.result(report)
        if r is None:
            return []
        sel = r.selection
        return [("Gearbox", sel.selected,
                 f"ratio {sel.best.ratio:g}, {sel.mode} checks, catalog {sel.catalog.shown_name}")]

    def order_lines(self, report) -> list[str]:
        r = self.result(report)
        if r is None or r.selection.selected is None:
            return []
        sel = r.selection
        row = int(sel.order[0])
        return [rf"Gearbox \textbf{{{latex_escape(sel.selected)}}}, ratio $i = {sig(sel.best.ratio)}$"
                rf" (series {latex_escape(str(sel.catalog.text['series'][row]))})"]

    @page_doc("The gearbox candidates, best first, then the ratio search where it is asked for.",
              "g", "calc.sections.gearbox.GearboxResult")
    def page(self, g, view) -> str:
        search = "" if view.ratios is None else RATIOS.page_block(view.ratios)
        if g is None:
            return search
        sel = g.selection
        shown, more = candidates_shown(sel, view.shown)
        rows = [
            [str(k), escape(c.part), verdict_cell(c.passes), utilization(c.worst), value(c.T_2max),
             "" if c.inertia_ratio is None else sig(c.inertia_ratio, 3), "illustrative" if c.illustrative else "",
             "<br>".join(typeset(x) for x in c.reasons)]
            for k, c in enumerate(shown, start=1)
        ]
        lam = "inertia ratio λ" if g.inertia_note is None else "λ, J_1 alone"
        header = ["rank", "part", "verdict", "worst utilization", typeset("T_2max"), typeset(lam), "data", "reasons"]
        said = "" if g.inertia_note is None else f"<div class=note>{typeset(g.inertia_note)}</div>"
        return (f"<h3>Gearbox candidates</h3><div class=note>{typeset(g.ranking)}; {FORCING}</div>"
                + html_table(header, rows, numeric={0, 3, 4, 5}, marked=0 if sel.selected else None,
                             force=("gearbox.part", [c.part for c in shown]))
                + said + more + search)


def _one_lambda(report, steps) -> list[str]:
    """Where the gearbox's λ leaves out a motor-side coupling (chosen after the gearbox), the one λ
    the motor's check and the dynamics take, with its terms (LaTeX prose); else nothing."""
    dynamics = result_of("dynamics", report)
    lam = next((step.result.m_as("") for _, step, _ in steps if step.formula.name == "lambda"), None)
    if dynamics is None or dynamics.two_mass is None or lam is None:
        return []
    tm = dynamics.two_mass
    if abs(tm.inertia_ratio - float(lam)) <= 1e-9 * tm.inertia_ratio:
        return []
    return [prose(f"This λ leaves out the motor-side coupling, chosen after the gearbox. The one λ the motor's check "
                  f"and the drive train's dynamics take counts it: λ = J_Lm / J_motor = {tm.J_Lm} / {tm.J_motor} = "
                  f"{tm.inertia_ratio:.4g}.")]


RENDERER = GearboxRenderer()
