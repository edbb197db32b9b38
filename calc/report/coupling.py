"""The coupling in the calc report: its inputs (with what a motor-side coupling takes from the
rest of the case), nominal torque and resonance as calculations, its results, checks,
candidates, figures and order line."""

from __future__ import annotations

import functools

from ..core.units import sig
from . import common
from .common import (
    candidates_table, described, further_checks, further_readings, further_sources, raw_section_tables, rejected, result_of,
)
from .latex import breakable, itemize, latex_escape, plain, prose, q, sources_list, step_block, symbol_math, table

NAME = "coupling"

def _derived_inputs(report, raw: dict) -> dict:
    """The inputs that the case left out and the package took from the rest of it (a motor-side
    coupling's M_a, J_drive, J_load, speed), as the case would write them."""
    r = result_of(NAME, report)
    if r is None:
        return {}
    units = {"accel_torque": "N*m", "drive_inertia": "kg*cm**2", "load_inertia": "kg*cm**2", "speed": "rpm"}
    x = r.inputs.inputs
    return {k: f"{sig(x[k].m_as(u))} {u}" for k, u in units.items() if k not in raw and x.get(k) is not None}


def inputs(report) -> list[str]:
    if not described(NAME, report):
        return []
    raw = report.case.sections[NAME]
    return [raw_section_tables(NAME, raw, _derived_inputs(report, raw))]


def steps(report) -> list[str]:
    """The coupling's calculations as the section computed them: the inputs taken from the rest
    of the case, M_N with its factors, 2 f_er, the best-ranked row's natural frequency and the
    drive train's modes."""
    r = result_of(NAME, report)
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


def _torsion(r) -> list[str]:
    """The drive train as a chain of masses and springs (calc.domain.torsion): the members referred to
    the coupling's shaft, the chain, and its natural frequencies beside the two-mass f_e."""
    t = r.torsion
    if t is None:
        return []
    out = [rf"\subsection{{Torsional modes of the drive train, with {latex_escape(t.part)}}}",
           prose("The two-mass f_e takes the coupling as the only spring. The drive train has more: it is lumped as a chain, "
                 f"every member referred to {t.shaft}: the motor with half the coupling, the other half with the gearbox's J_1, "
                 "the load J_L / i²; springs: the coupling's C_T and the gearbox's C_t21 / i². Its natural frequencies are "
                 "the roots of the eigenproblem (K − ω² J) φ = 0, the rigid-body mode left out.")]
    out += [step_block(title, step) for title, step in r.inputs.drive_steps]
    rows = [[str(k + 1), prose(members), q(J), prose(spring[0]) if spring else "", q(spring[1]) if spring else ""]
            for k, ((members, J), spring) in enumerate(zip(t.masses, [*t.springs, None]))]
    out.append(table(r"@{}r l r l r@{}", ["Mass", "Members", "Inertia", "Spring to the next", "Stiffness"], rows,
                     caption=f"The drive train as masses and springs, referred to {latex_escape(t.shaft)}"))
    out.append(prose("Natural frequencies, lowest first: ") + ", ".join(q(f) for f in t.natural_frequencies) + ".")
    if not t.complete:
        out.append(prose("The chain is incomplete, so its first mode is reported for information: the case does not give "
                         + "; ".join(t.missing) + "."))
    return out


def results(report) -> list[str]:
    """What the coupling gives besides its checks: M_N, T_op, K_ϑ, f_e,min, the shafts, notes."""
    r = result_of(NAME, report)
    if r is None:
        return []
    rows = [
        [symbol_math("M_N"), q(r.M_N),
         prose(f"nominal torque of the coupling, S_A = {r.service_factor:g} included (E8)")],
        [symbol_math("T_op"), q(r.T_op), prose("peak torque of normal operation (M_N with S_A = 1)")],
        [symbol_math("K_T"), f"{r.temperature_factor:g}",
         prose("temperature factor (elastomer couplings, E9)" + (f" at {plain(r.temperature)}" if r.temperature else ""))],
        [symbol_math("f_e_min"), q(r.f_e_min), prose("lowest natural frequency allowed, 2 f_er (E7)")],
    ]
    if r.selection.start_factor is not None:
        rows.append([symbol_math("S_z"), f"{r.selection.start_factor:g}",
                     prose(f"start factor at {plain(r.starts_per_hour)} ({r.start_factors})")])
    out = [r"\subsection{Coupling: results}", table(r"@{}l r p{0.6\linewidth}@{}", ["Symbol", "Value", "Description"], rows)]
    bores = [[rf"\texttt{{\footnotesize coupling.{latex_escape(b.key)}}}", latex_escape(b.text), latex_escape(b.limits or "–")] for b in r.bores]
    if bores:
        out.append(table(r"@{}l l l@{}", ["Case key", "Shaft as written", "Limits of the shaft (ISO 286)"], bores,
                         caption="Shafts of the coupling"))
    if r.notes:
        out.append(r"\paragraph{Notes.}" + itemize(prose(n) for n in r.notes))
    return out


def candidates(report) -> list[str]:
    """Every candidate's utilization of each check, the doubtful figures and sources of the rows,
    and why the closest rejected ones fail."""
    r = result_of(NAME, report)
    if r is None:
        return []
    listed = r.selection.candidates()
    doubts = [f"{c.part}: {c.unclear}" for c in listed if c.unclear]
    _, source_list = sources_list(c.source for c in listed if c.source)
    notes = ([r"\noindent Doubtful figures of the rows listed: " + breakable("; ".join(doubts)) + r"\par"] if doubts else []) + (
        [r"\paragraph{Sources of the rows listed.}" + source_list] if source_list else [])
    return [rf"\subsection*{{{NAME.capitalize()}}}",
            candidates_table(listed, r.selection.selected, latex_escape(f"Utilization of each check of the {NAME} candidates, best first")),
            *notes, *rejected(listed)]


def chosen(report) -> list[tuple]:
    r = result_of(NAME, report)
    return [] if r is None else [(NAME.capitalize(), r.selection.selected, f"catalog {r.inputs.catalog.shown_name}")]


def order_lines(report) -> list[str]:
    r = result_of(NAME, report)
    return [latex_escape(r.order)] if r is not None and r.order else []


def figures(report) -> list:
    r = result_of(NAME, report)
    if r is None:
        return []
    from ..figures.coupling_plots import natural_frequency_figure, temperature_factor_figure

    cc, sel = r.inputs, r.selection
    out = [(natural_frequency_figure(sel, r.f_e_min.quantity),
            prose("Natural frequency of each coupling candidate against the lowest allowed, 2 f_er (E7)."))]
    if (sel.catalog.text["type"] == "elastomer").any():
        out.append((temperature_factor_figure(cc.inputs["temperature"], cc.inputs["temperature_factors"]),
                    prose(f"Temperature factor of elastomer couplings ({cc.inputs['temperature_factors'].source}).")))
    return out


# The blocks a further section shares with the others, for this section.
sources = functools.partial(further_sources, NAME)
readings = functools.partial(further_readings, NAME)
checks = functools.partial(further_checks, NAME)


input_rows = common.nothing
