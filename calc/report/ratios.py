"""The best ratio in the calc report: the case at every ratio of its gearbox catalog as a table,
the ratio a reviewer should pick and why (the rule of :mod:`calc.domain.ratios`), and the figure."""

from __future__ import annotations

from ..data.catalog import display_path
from .latex import latex_escape, prose, q, symbol_latex, symbol_math, table, util, verdict_mark
from .common import nothing

NAME = "ratios"


def results(report) -> list[str]:
    r = report.ratios
    if r is None:
        return []
    rows = [[f"{x.ratio:g}", latex_escape(x.part), util(x.utilization), "–" if x.inertia_ratio is None else f"{x.inertia_ratio:.2f}",
             "–" if x.peak_torque_required is None else q(x.peak_torque_required),
             "–" if x.rms_torque_required is None else q(x.rms_torque_required), q(x.max_speed_required),
             verdict_mark(x.passes) + (r"{} \footnotesize(pick)" if x.pick else "")] for x in r.rows]
    return [
        r"\subsection*{The ratio}",
        prose(r.search.reason),
        table(r"@{}r l r r r r r l@{}",
              [symbol_math("i"), "Best gearbox", "Utilization", *map(symbol_math, ("lambda", "T_1peak", "T_1rms")),
               rf"${symbol_latex('n_2max')} \cdot i$", "Verdict"], rows,
              caption=latex_escape(f"The case at every ratio of {display_path(r.search.selection.catalog.path)}, each with its best gearbox"),
              note=prose(f"Rule: {r.search.rule}.")),
    ]


def figures(report) -> list:
    r = report.ratios
    if r is None:
        return []
    from ..figures.motor_plots import ratio_figure

    c = report.case
    return [(ratio_figure(r.search, c.motor_peak_torque, c.motor_rated_torque),
             "The case against the ratio: motor torques, governing utilization and inertia ratio; feasible ratios shaded.")]


input_rows = inputs = steps = checks = candidates = chosen = order_lines = sources = readings = nothing
