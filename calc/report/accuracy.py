"""Accuracy in the outputs: in the calc report its inputs, the measured loops and traces and the
chain's accuracy as calculations, its results, checks against the case's requirements, and the
figures (the stiffness chain, hysteresis loops, transmission error, measured positions); on the
review's page and in the comparison of designs the chain's accuracy."""

from __future__ import annotations

from pathlib import Path

from ..sections import gearbox
from ..core.units import Value
from ..domain.accuracy import POSITIONING_CONVENTION
from ..sections.accuracy import NAME, modelled_loop
from .common import TableRenderer, result_of
from .latex import latex_escape, listed, plain, prose, q, step_block, symbol_latex, symbol_math, table
from .page import in_system, table as html_table, value
from .provenance import PROJECT_DIR
from .symbols import html as typeset


def _shown(a, field: str, bound: str = "") -> str:
    """A value of the chain's accuracy (of ``a``, an :class:`calc.sections.accuracy.AccuracyResult`;
    None: none) as the comparison writes it, in the unit system shown; ``≥`` before it where the
    value is a lower bound (``bound``: the field that lists the unknown terms)."""
    if a is None:
        return ""
    v = a.shown
    return ("≥ " if bound and getattr(v, bound) else "") + str(in_system(getattr(v, field)))


class AccuracyRenderer(TableRenderer):
    """The chain's accuracy: its inputs, steps, results, checks and figures in the report, its
    values on the page and in the comparison."""

    NAME = NAME

    def steps(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        spec, a = r.inputs, r.accuracy
        out = []
        for name, (path, analysis) in spec.loops.items():
            out.append(rf"\subsection{{Measured hysteresis loop of {latex_escape(name)}}}")
            out.append(rf"From \texttt{{{latex_escape(path)}}} (E12).")
            out += [step_block(s.formula.result.description.capitalize(), s) for s in analysis.steps()]
        for name, (path, analysis) in spec.traces.items():
            out.append(rf"\subsection{{Measured transmission error of {latex_escape(name)}}}")
            out.append(rf"From \texttt{{{latex_escape(path)}}}.")
            out.append(step_block(analysis.step().formula.result.description.capitalize(), analysis.step()))
        out.append(r"\subsection{Accuracy of the drive train at the output}")
        out.append(prose(f"Applied torque: {a.rule.why}, so the positioning rule of E13 for that range applies, "
                         f"{a.rule.text}."))
        out += [step_block(s.formula.result.description.capitalize(), s) for s in a.steps()]
        out += [step_block(title, step) for title, step in r.arc_steps]
        return out

    def results(self, report) -> list[str]:
        """The chain's stiffness, backlash, transmission accuracy, lost motion, positioning accuracy
        and repeatability, and each member referred to the output.

        Parameters
        ----------
        report : calc.report.Report
            The case's report.

        Returns
        -------
        list of str
            LaTeX: the results' table and the members' table; none without ``[accuracy]``.
        """
        r = self.result(report)
        if r is None:
            return []
        a = r.shown
        rep = "repeatability, an upper bound under torque (E13)" if a.repeatability_is_bound else "repeatability (E13)"
        lower = f"; a lower bound: unknown {'; '.join(a.unknown)}" if a.unknown else ""
        not_known = f"; not known: unknown {'; '.join(a.unknown_chain)}" if a.unknown_chain else ""
        rows = [
            [symbol_math("C_total"), (r"$\leq$ " if a.unknown_chain else "") + q(a.C_total),
             prose("total torsional stiffness at the output (E11)" + ("; an upper bound" if a.unknown_chain else ""))],
            [symbol_math("j_t"), q(a.backlash), prose("torsional backlash at the output")],
            [symbol_math("phi_TA"), q(a.transmission_accuracy),
             prose("angular transmission accuracy, from " + listed(a.transmission_accuracy_from))],
            [symbol_math("phi_LM"), (r"$\geq$ " if a.unknown_chain else "") + q(a.lost_motion),
             prose("total lost motion at the applied torque (E12)" + ("; a lower bound" if a.unknown_chain else ""))],
            [symbol_math("Delta_phi_P"), (r"$\geq$ " if a.unknown else "") + q(a.positioning_accuracy),
             prose(f"positioning accuracy, {a.positioning_rule} (E13)" + lower)],
            ["–", q(a.repeatability), prose(rep + not_known)],
        ]
        rows += [[f"{symbol_math('s')} ({latex_escape(key.replace('_', ' '))})", q(arc),
                  prose(f"as an arc at r = {plain(a.radius)}")] for key, arc in a.arcs.items()]
        comp = [[latex_escape(m.name), latex_escape(m.side), q(m.stiffness_at_output), q(m.backlash_at_output),
                 q(m.transmission_accuracy_at_output), f"{100 * m.share_of_compliance:.1f}",
                 q(m.twist_at_applied_torque)] for m in a.members]
        return [
            r"\subsection{Accuracy: results}",
            prose(f"Positioning accuracy and repeatability are stated as a {POSITIONING_CONVENTION}."),
            table(r"@{}l r p{0.6\linewidth}@{}", ["Symbol", "Value", "Description"], rows),
            table(r"@{}l l r r r r r@{}", ["Member", "Side", *map(symbol_math, ("C", "j_t", "phi_TA")),
                                           rf"$1/{symbol_latex('C')}$ [\%]", f"Twist at {symbol_math('T')}"], comp,
                  small=True,
                  caption=prose(f"Members of the chain referred to the output, at T = {plain(a.applied_torque)}")),
            *_budget_blocks(r),
        ]

    def figures(self, report) -> list:
        """The chain's figures; without measured loops, the chosen gearbox's loop modelled from its
        catalog figures as the accuracy result records it (:attr:`calc.sections.accuracy.AccuracyResult.modelled_loop`;
        for a case without ``[accuracy]``, modelled from the gearbox result the same way).

        Parameters
        ----------
        report : calc.report.Report
            The case's report.

        Returns
        -------
        list of tuple
            ``(matplotlib.figure.Figure, caption)`` of each figure.
        """
        r, g = self.result(report), result_of(gearbox.NAME, report)
        if r is None and g is None:
            return []
        from ..figures.accuracy_plots import (
            budget_figure, hysteresis_figure, positioning_scatter_figure, stiffness_chain_figure,
            transmission_error_figure,
        )
        from ..domain.hysteresis import read_loop

        out = []
        spec = None if r is None else r.inputs
        if spec is not None:
            out.append((stiffness_chain_figure(r.shown),
                        "Stiffness chain referred to the output (E11): each member's share of the twist."))
            out.append((budget_figure(r.budget_json()),
                        prose("Error budget of the positioning accuracy: each contribution (systematic or random), "
                              "the worst case and the root-sum-square.")))
            for name, (path, analysis) in spec.loops.items():
                # a relative display path lies in the checkout (an installed calc shows measurements absolute)
                loop = read_loop(path if Path(path).is_absolute() else PROJECT_DIR / path)
                out.append((hysteresis_figure(loop, analysis),
                            latex_escape(f"Measured hysteresis loop of {name} (E12).")))
        # A case without [accuracy] has no chain's result to hold the gearbox's modelled loop.
        model = modelled_loop(g) if r is None else r.modelled_loop
        if model is not None:
            out.append((hysteresis_figure(model.loop, model.analysis),
                        prose(f"Hysteresis loop of {model.part} modelled from its catalog figures "
                              "(C_t21, backlash, T_2N), not a measurement (E12).")))
        if spec is not None:
            for name, (path, analysis) in spec.traces.items():
                out.append((transmission_error_figure(analysis),
                            latex_escape(f"Transmission error of {name}, from {path}.")))
            if spec.positions is not None:
                out.append((positioning_scatter_figure(spec.positions),
                            "Measured positions: accuracy and repeatability."))
        return out

    def page(self, r, view) -> str:
        """The chain's accuracy on the review's page: its stiffness, lost motion, positioning accuracy
        and repeatability, each bound marked.

        Parameters
        ----------
        r : calc.sections.accuracy.AccuracyResult or None
            The accuracy result; None where the case has none.
        view : calc.report.page.View
            What the page asks (the chain's rows do not depend on it).

        Returns
        -------
        str
            HTML: a heading and the table; empty without a result.
        """
        if r is None:
            return ""
        a = r.shown
        chain = a.unknown_chain  # a member's twist or backlash unknown: bounds
        rows = [
            [typeset("C_total"),
             "total torsional stiffness at the output" + (" (<b>an upper bound</b>)" if chain else ""),
             ("≤ " if chain else "") + value(a.C_total)],
            [typeset("phi_LM"),
             f"lost motion at the applied torque {value(a.applied_torque)}"
             + (" (<b>a lower bound</b>)" if chain else ""),
             ("≥ " if chain else "") + value(a.lost_motion)],
            ["Δ" + typeset("phi_P"), f"positioning accuracy ({typeset(a.positioning_rule)})"
             + (f"; <b>a lower bound</b>: unknown {typeset('; '.join(a.unknown))}" if a.unknown else ""),
             ("≥ " if a.unknown else "") + value(a.positioning_accuracy)],
            ["", "repeatability" + (" (<b>not known</b>: a member's twist or backlash unknown)" if a.unknown_chain
                                    else " (upper bound)" if a.repeatability_is_bound else ""), value(a.repeatability)],
        ]
        b = r.budget_json()
        budget = [[typeset(c["name"]), c["kind"], value(Value(c["value"]["value"], "arcmin")),
                   f"{100 * c['share']:.0f} %"] for c in b["contributions"]]
        budget += [["worst case", "", value(Value(b["worst_case"]["value"], "arcmin")), ""],
                   ["root-sum-square", "", value(Value(b["rss"]["value"], "arcmin")), ""]]
        return ("<h3>Accuracy of the chain</h3>" + html_table(["symbol", "quantity", "value"], rows, numeric={2})
                + f"<h3>Error budget</h3><div class=note>{typeset(b['convention'])}</div>"
                + html_table(["contribution", "kind", "value", "share"], budget, numeric={2, 3}))

    def compared(self) -> tuple:
        return (("positioning accuracy", lambda a: _shown(a, "positioning_accuracy", "unknown")),
                ("lost motion", lambda a: _shown(a, "lost_motion", "unknown_chain")))


def _budget_blocks(r) -> list[str]:
    """The error budget in the report: its steps and its table (LaTeX)."""
    b = r.budget
    rows = [[prose(c.name), c.kind, q(Value.of(c.value, "arcmin")), f"{100 * share:.1f}", prose(c.why)]
            for c, share in zip(b.contributions, b.shares)]
    note = prose(f"Random ones alone (the systematic mapped out): {Value.of(b.rss_random, 'arcmin')}"
                 + (f"; not known: {'; '.join(b.unknown)}" if b.unknown else "") + ".")
    header = ["Contribution", "Kind", "Value", r"Share [\%]", "Why"]
    return [table(r"@{}p{0.2\linewidth} l r r p{0.3\linewidth}@{}", header, rows,
                  caption="Error budget of the positioning accuracy", note=note, small=True),
            step_block("Worst case: every contribution added", b.worst_case),
            step_block("Root-sum-square of the independent contributions", b.rss)]


RENDERER = AccuracyRenderer()
