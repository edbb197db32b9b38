"""The gearbox in the calc report: its inputs, the checks of the chosen gearbox (or the closest
candidate) as calculations and as a table, the candidates with their catalog ratings, the
utilization figure and the order line."""

from __future__ import annotations

import numpy as np

from ..core.units import sig
from . import common
from .common import candidates_table, checks_table, input_row, nothing, rejected, result_of
from .latex import breakable, latex_escape, num, sources_list, stacked, step_block, symbol_math, table

NAME = "gearbox"


def sources(report) -> list[str]:
    return common.sources(NAME)


def readings(report) -> set[str]:
    """Every gearbox reading; the inertia match (E6) only where the report gives the ratio."""
    out = common.readings(NAME)
    r = result_of(NAME, report)
    return out if r is not None and r.selection.inertia_ratio is not None else out - {"E6"}


def input_rows(report) -> list[list[str]]:
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
        given = (("axial_force", load.axial_force), ("radial_force", load.radial_force), ("lever_arm", load.lever_arm),
                 ("axial_force_radius", load.axial_radius))
        rows += [input_row(f"load.{key}", q) for key, q in given if q is not None]
    return rows


def steps(report) -> list[str]:
    """The best-ranked row's checks as the gearbox section computed them."""
    r = result_of(NAME, report)
    if r is None:
        return []
    sel = r.selection
    chosen = "the chosen gearbox" if sel.selected else "the closest candidate (none passes)"
    out = [rf"\subsection{{Checks of {chosen}, {latex_escape(str(sel.catalog.parts[int(sel.order[0])]))}}}"]
    return out + [step_block(title, step, note) for title, step, note in r.steps]


def checks(report) -> list[str]:
    r = result_of(NAME, report)
    if r is None:
        return []
    best = r.selection.best
    return [checks_table(best.checks, f"Checks of gearbox {best.part}" + (" (chosen)" if r.selection.selected else " (the closest candidate; none passes)"))]


def candidates(report) -> list[str]:
    """Every candidate at the ratio: its catalog ratings, and the utilization of each check."""
    r = result_of(NAME, report)
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
            latex_escape(f"{family[r]} {size[r]}".strip()) + (rf" {{\scriptsize {latex_escape(cat.catalog_of(r))}}}" if several else ""),
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
        note = "".join(rf"$^{{\dagger{k}}}$ doubtful figures of {breakable(d)}. " for k, d in enumerate(doubts, start=1)) + note
    if illustrative:
        note = r"$^{*}$ illustrative row: not a maker's own figures. " + note
    return [
        table(
            r"@{}l l r r r r r r r r@{}",
            ["Part", "Family, size", *(stacked(symbol_math(symbol), f"[{unit}]") for symbol, unit in (
                ("T_2N", "N·m"), ("T_2B", "N·m"), ("n_1N", "rpm"), ("n_1max", "rpm"), ("eta", r"\%"), ("J_1", "kg·cm²"),
                ("d_hub", "mm"))),
             "Src."],
            rows, caption=latex_escape(f"Catalog ratings of the candidates ({cat.shown_name}), best first"), note=note, small=True, narrow=True,
        ),
        r"\paragraph{Sources of the rows.}" + source_list,
        candidates_table(listed, sel.selected, f"Utilization of each check (required / rated), {sel.mode} governs; "
                                                "checks in grey are for information", inertia=True),
        *rejected(listed),
    ]


def figures(report) -> list:
    r = result_of(NAME, report)
    if r is None:
        return []
    from ..figures.plots import comparison_figure, utilization_figure

    return [
        (utilization_figure(r.selection), "Utilization of the governing checks of each candidate, best first."),
        (comparison_figure(r.selection), "The makers compared: the highest governing utilization of each candidate, "
                                              "coloured by family (and catalog, where several are ranked together)."),
    ]


def chosen(report) -> list[tuple]:
    r = result_of(NAME, report)
    if r is None:
        return []
    sel = r.selection
    return [("Gearbox", sel.selected, f"ratio {sel.best.ratio:g}, {sel.mode} checks, catalog {sel.catalog.shown_name}")]


def order_lines(report) -> list[str]:
    r = result_of(NAME, report)
    if r is None or r.selection.selected is None:
        return []
    sel = r.selection
    row = int(sel.order[0])
    return [rf"Gearbox \textbf{{{latex_escape(sel.selected)}}}, ratio $i = {sig(sel.best.ratio)}$"
            rf" (series {latex_escape(str(sel.catalog.text['series'][row]))})"]


inputs = results = nothing
