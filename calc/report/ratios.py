"""The best ratio in the outputs: in the calc report the case at every ratio of its gearbox
catalog as a table, the ratio a reviewer should pick and why (the rule of :mod:`calc.domain.ratios`),
and the figure; on the review's page the same, where the reviewer asks for it (after the gearbox's
candidates: :meth:`RatiosRenderer.page_block`). Not a section of the evaluation: the report and
the page run the search (:func:`calc.sections.ratios.search`)."""

from __future__ import annotations

from html import escape

from ..core.units import Value, sig
from ..data.catalog import display_path
from .common import Renderer
from .latex import latex_escape, prose, q, symbol_latex, symbol_math, table, util, verdict_mark
from .page import notes, table as html_table, utilization, value, verdict_cell
from .symbols import html as typeset


class RatiosRenderer(Renderer):
    """The ratio search: its table and figure in the report, and on the page where asked for."""

    NAME = "ratios"

    def results(self, report) -> list[str]:
        r = report.ratios
        if r is None:
            return []
        rows = [[f"{x.ratio:g}", latex_escape(x.part), util(x.utilization),
                 "–" if x.inertia_ratio is None else f"{x.inertia_ratio:.2f}",
                 "–" if x.peak_torque_required is None else q(x.peak_torque_required),
                 "–" if x.rms_torque_required is None else q(x.rms_torque_required), q(x.max_speed_required),
                 verdict_mark(x.passes) + (r"{} \footnotesize(pick)" if x.pick else "")] for x in r.rows]
        return [
            r"\subsection*{The ratio}",
            prose(r.search.reason),
            *([] if r.checked is None else [prose(r.checked.said)]),
            *([] if r.optimal is None else [prose(r.optimal.line() + ".")]),
            table(r"@{}r l r r r r r l@{}",
                  [symbol_math("i"), "Best gearbox", "Utilization", *map(symbol_math, ("lambda", "T_1peak", "T_1rms")),
                   rf"${symbol_latex('n_2max')} \cdot i$", "Verdict"], rows,
                  caption=latex_escape(f"The case at every ratio of {display_path(r.search.selection.catalog.path)}, "
                                       "each with its best gearbox"),
                  note=prose(f"Rule: {r.search.rule}.")),
        ]

    def figures(self, report) -> list:
        r = report.ratios
        if r is None:
            return []
        from ..figures.motor_plots import ratio_figure

        c = report.case
        i_opt = None if r.optimal is None else r.optimal.value
        return [(ratio_figure(r.search, c.motor_peak_torque, c.motor_rated_torque, i_opt),
                 prose("The case against the ratio: motor torques, governing utilization and inertia ratio; "
                       "feasible ratios shaded; the inertia-matching ratio i_opt named (dashed where the catalog "
                       "reaches it)."))]

    def page_block(self, found) -> str:
        """The ratio search on the review's page: each ratio's best gearbox, whether it is feasible, λ
        and the motor's torques, the pick and why, and the bars of
        :func:`calc.review.figures.ratio_search_svg`.

        Parameters
        ----------
        found : dict or str
            The ratio search's JSON (:func:`calc.sections.ratios.search`), or why it cannot be made
            (a sentence).

        Returns
        -------
        str
            HTML.
        """
        from ..review.figures import ratio_search_svg

        if isinstance(found, str):
            return f"<h3>Ratio search</h3><div class=note>{typeset(found)}</div>"

        def given(v):
            return "" if v is None else value(Value(v["value"], v["unit"]))

        pick = None if found["pick"] is None else found["pick"]["ratio"]
        rows = [
            [sig(r["ratio"]), escape(r["part"]), verdict_cell(r["passes"]), utilization(r["utilization"]),
             "" if r["inertia_ratio"] is None else sig(r["inertia_ratio"], 3), given(r["peak_torque_required"]),
             given(r["rms_torque_required"]), given(r["max_speed_required"]), "pick" if r["ratio"] == pick else ""]
            for r in found["ratios"]
        ]
        header = ["ratio i", "best gearbox", "feasible", "utilization", "inertia ratio λ", typeset("T_1peak"),
                  typeset("T_1rms"), typeset("n_1max"), ""]
        marked = next((k for k, r in enumerate(found["ratios"]) if r["ratio"] == pick), None)
        best = found.get("optimal_ratio")
        matching = ""
        if best and best["value"] is not None:
            said = f"inertia matching: i_opt = √(J_L / J_in) = {sig(best['value'], 4)} ({best['inertias']})"
            matching = f"<div class=note>{typeset(said)}; the pick minimizes the RMS motor torque</div>"
        checked = found.get("checked")
        said = "" if checked is None else f"<div class=checked-at>{typeset(checked['said'])}</div>"
        return (f"<h3>Ratio search</h3><div class=note>{typeset(found['rule'])}</div>"
                f"<div><b>{typeset(found['reason'])}</b></div>" + said + matching
                + html_table(header, rows, numeric={0, 3, 4, 5, 6, 7}, marked=marked) + notes(found["notes"])
                + ratio_search_svg(found))


RENDERER = RatiosRenderer()
