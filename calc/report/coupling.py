"""The coupling in the outputs: in the calc report its inputs (with what a motor-side coupling
takes from the rest of the case), nominal torque and resonance as calculations, its results,
checks, candidates, figures and order line; on the review's page its candidates and the drive
train's modes; its chosen part in the summary's column and in the comparison of designs."""

from __future__ import annotations

from html import escape

from ..core.units import sig
from ..sections.coupling import NAME
from .common import TableRenderer, block_doc, candidates_table, page_doc, rejected
from .latex import breakable, itemize, latex_escape, plain, prose, q, sources_list, step_block, symbol_math, table
from .page import candidates_shown, notes, table as html_table, utilization, value, verdict_cell
from .symbols import html as typeset


def _torsion(r) -> list[str]:
    """The drive train as a chain of masses and springs (calc.domain.torsion): the members referred to
    the coupling's shaft, the chain, and its natural frequencies beside the two-mass f_e."""
    t = r.torsion
    if t is None:
        return []
    out = [rf"\subsection{{Torsional modes of the drive train, with {latex_escape(t.part)}}}",
           prose("The two-mass f_e takes the coupling as the only spring. The drive train has more: it is lumped "
                 f"as a chain, every member referred to {t.shaft}: the motor with half the coupling, the other half "
                 "with the gearbox's J_1, the load J_L / i²; springs: the coupling's C_T and the gearbox's C_t21 / "
                 "i². Its natural frequencies are the roots of the eigenproblem (K − ω² J) φ = 0, the rigid-body "
                 "mode left out.")]
    out += [step_block(title, step) for title, step in r.inputs.drive_steps]
    rows = [[str(k + 1), prose(members), q(J), prose(spring[0]) if spring else "", q(spring[1]) if spring else ""]
            for k, ((members, J), spring) in enumerate(zip(t.masses, [*t.springs, None]))]
    out.append(table(r"@{}r l r l r@{}", ["Mass", "Members", "Inertia", "Spring to the next", "Stiffness"], rows,
                     caption=f"The drive train as masses and springs, referred to {latex_escape(t.shaft)}"))
    out.append(prose("Natural frequencies, lowest first: ") + ", ".join(q(f) for f in t.natural_frequencies) + ".")
    if not t.complete:
        out.append(prose("The chain is incomplete, so its first mode is reported for information: the case does "
                         "not give " + "; ".join(t.missing) + "."))
    return out


def _torsion_table(t) -> str:
    """The drive train as masses and springs with its natural frequencies
    (:class:`calc.sections.coupling.Torsion`), HTML."""
    if t is None:
        return ""
    rows = [[escape(members), value(J), escape(spring[0]) if spring else "", value(spring[1]) if spring else ""]
            for (members, J), spring in zip(t.masses, [*t.springs, None])]
    frequencies = ", ".join(value(f) for f in t.natural_frequencies)
    check = "".join(f"<div class=note>{typeset(c.criterion)}: {value(c.rated_value)}, "
                    f"utilization {utilization(c.utilization)}{'' if c.governs else ' (for information)'}</div>"
                    for c in t.checks)
    missing = ("" if t.complete
               else f"<div class=note>incomplete: the case does not give {escape('; '.join(t.missing))}</div>")
    return (f"<h3>Drive train with {escape(t.part)}, at {escape(t.shaft)}</h3>"
            + html_table(["masses", "inertia", "spring to the next", "stiffness"], rows, numeric={1, 3})
            + f"<div class=note>natural frequencies {frequencies} (rigid-body mode left out)</div>" + check + missing)


class CouplingRenderer(TableRenderer):
    """The coupling: its inputs, steps, results, checks, candidates, figures, chosen part and
    order line in the report, its candidates and drive train on the page, its chosen part in the
    summary and the comparison."""

    NAME = NAME
    SUMMARY_COLUMN = ("Coupling", r"0.08\linewidth")
    COMPARED_PART = True

    def derived_inputs(self, report, raw: dict) -> dict:
        """A motor-side coupling's M_a, J_drive, J_load and speed, where the table leaves them out.

        Parameters
        ----------
        report : calc.report.Report
            The report being built.
        raw : dict
            The coupling's table as written.

        Returns
        -------
        dict
            Key -> the value as the case would write it (``"12.5 N*m"``).
        """
        r = self.result(report)
        if r is None:
            return {}
        units = {"accel_torque": "N*m", "drive_inertia": "kg*cm**2", "load_inertia": "kg*cm**2", "speed": "rpm"}
        x = r.inputs.inputs
        return {k: f"{sig(x[k].m_as(u))} {u}" for k, u in units.items() if k not in raw and x.get(k) is not None}

    @block_doc("The coupling's calculations as the section computed them: the inputs taken from the rest of the "
               "case, M_N with its factors, 2 f_er, the best-ranked row's natural frequency and the drive train's "
               "modes.",
               "list of str", "The calculation steps, LaTeX.")
    def steps(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        out = [r"\subsection{Coupling: nominal torque and resonance}"]
        out += [step_block(title, step) for title, step in r.inputs.steps]
        sel = r.selection
        if sel.not_made:
            # The case lacks what M_N and f_e need (the contract's partial cases): no step to show.
            return out + [prose(f"Not checked: {c.text}, {c.not_made}.") + "\n" for c in sel.not_made]
        out += [step_block(*s) for s in r.torque_steps]
        if r.resonance_steps:
            chosen = "the chosen coupling" if sel.selected else "the closest candidate (none passes)"
            out.append(rf"\subsection{{Natural frequency of {chosen}, {latex_escape(sel.best.part)}}}")
            out += [step_block(*s) for s in r.resonance_steps]
        return out + _torsion(r)

    @block_doc("What the coupling gives besides its checks: M_N, T_op, K_ϑ, f_e,min, the shafts, notes.",
               "list of str", "The results' heading and tables, LaTeX.")
    def results(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        rows = [
            [symbol_math("M_N"), q(r.M_N),
             prose(f"nominal torque of the coupling, S_A = {r.service_factor:g} included (E8)")],
            [symbol_math("T_op"), q(r.T_op), prose("peak torque of normal operation (M_N with S_A = 1)")],
            [symbol_math("K_T"), f"{r.temperature_factor:g}",
             prose("temperature factor (elastomer couplings, E9)"
                   + (f" at {plain(r.temperature)}" if r.temperature else ""))],
            [symbol_math("f_e_min"), q(r.f_e_min), prose("lowest natural frequency allowed, 2 f_er (E7)")],
        ]
        if r.selection.start_factor is not None:
            rows.append([symbol_math("S_z"), f"{r.selection.start_factor:g}",
                         prose(f"start factor at {plain(r.starts_per_hour)} ({r.start_factors})")])
        out = [r"\subsection{Coupling: results}",
               table(r"@{}l r p{0.6\linewidth}@{}", ["Symbol", "Value", "Description"], rows)]
        bores = [[rf"\texttt{{\footnotesize coupling.{latex_escape(b.key)}}}", latex_escape(b.text),
                  latex_escape(b.limits or "–")] for b in r.bores]
        if bores:
            out.append(table(r"@{}l l l@{}", ["Case key", "Shaft as written", "Limits of the shaft (ISO 286)"], bores,
                             caption="Shafts of the coupling"))
        if r.notes:
            out.append(r"\paragraph{Notes.}" + itemize(prose(n) for n in r.notes))
        return out

    @block_doc("Every candidate's utilization of each check, the doubtful figures and sources of the rows, and why "
               "the closest rejected ones fail.",
               "list of str", "LaTeX.")
    def candidates(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        listed = r.selection.candidates()
        doubts = [f"{c.part}: {c.unclear}" for c in listed if c.unclear]
        _, source_list = sources_list(c.source for c in listed if c.source)
        notes = ([r"\noindent Doubtful figures of the rows listed: " + breakable("; ".join(doubts)) + r"\par"]
                 if doubts else [])
        notes += [r"\paragraph{Sources of the rows listed.}" + source_list] if source_list else []
        caption = latex_escape(f"Utilization of each check of the {NAME} candidates, best first")
        return [rf"\subsection*{{{NAME.capitalize()}}}", candidates_table(listed, r.selection.selected, caption),
                *notes, *rejected(listed)]

    def chosen(self, report) -> list[tuple]:
        r = self.result(report)
        return [] if r is None else [(NAME.capitalize(), r.selection.selected,
                                      f"catalog {r.inputs.catalog.shown_name}")]

    def order_lines(self, report) -> list[str]:
        r = self.result(report)
        return [latex_escape(r.order)] if r is not None and r.order else []

    def figures(self, report) -> list:
        r = self.result(report)
        if r is None:
            return []
        from ..figures.coupling_plots import natural_frequency_figure, temperature_factor_figure

        cc, sel = r.inputs, r.selection
        out = [(natural_frequency_figure(sel, r.f_e_min.quantity),
                prose("Natural frequency of each coupling candidate against the lowest allowed, 2 f_er (E7)."))]
        if (sel.catalog.text["type"] == "elastomer").any():
            factors = cc.inputs["temperature_factors"]
            out.append((temperature_factor_figure(cc.inputs["temperature"], factors),
                        prose(f"Temperature factor of elastomer couplings ({factors.source}).")))
        return out

    @page_doc("The coupling candidates, best first, and the drive train's modes.",
              "s", "calc.sections.coupling.CouplingResult")
    def page(self, s, view) -> str:
        if s is None:
            return ""

        def rated(c, name):
            return next((value(k.rated_value) for k in c.checks if k.name == name), "")

        sel = s.selection
        shown, more = candidates_shown(sel, view.shown)
        rows = [
            [str(k), escape(c.part), escape(c.type), verdict_cell(c.passes), value(c.required_torque), rated(c, "T_KN"),
             value(c.f_e), value(c.f_1), utilization(c.worst), "<br>".join(typeset(x) for x in c.reasons)]
            for k, c in enumerate(shown, start=1)
        ]
        header = ["rank", "part", "type", "verdict", typeset("M_N·K_ϑ"), typeset("T_KN"), typeset("f_e"),
                  typeset("f_1"), "worst utilization", "reasons"]
        return (f"<h3>Coupling candidates</h3><div class=note>{typeset(s.ranking)}</div>"
                + html_table(header, rows, numeric={0, 4, 5, 6, 7, 8}, marked=0 if sel.selected else None) + more
                + notes(s.notes) + _torsion_table(s.torsion))


RENDERER = CouplingRenderer()
