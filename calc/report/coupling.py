"""The coupling in the calc report: its inputs (with what a motor-side coupling takes from the
rest of the case), nominal torque and resonance as calculations, its results, checks,
candidates, figures and order line."""

from __future__ import annotations

import functools

import numpy as np

from ..units import Q_, sig
from . import common
from .common import (
    described, further_candidates, further_checks, further_chosen, further_order_lines, further_readings, further_sources,
    raw_section_tables, results_of,
)
from .latex import itemize, latex_escape, plain, prose, q, step_block, table

NAME = "coupling"

def _derived_inputs(report, raw: dict) -> dict:
    """The inputs that the case left out and the package took from the rest of it (a motor-side
    coupling's M_a, J_drive, J_load, speed), as the case would write them."""
    if report.coupling is None:
        return {}
    units = {"accel_torque": "N*m", "drive_inertia": "kg*cm**2", "load_inertia": "kg*cm**2", "speed": "rpm"}
    x = report.coupling[0].inputs
    return {k: f"{sig(x[k].m_as(u))} {u}" for k, u in units.items() if k not in raw and x.get(k) is not None}


def inputs(report) -> list[str]:
    if not described(NAME, report):
        return []
    raw = report.case.sections[NAME]
    return [raw_section_tables(NAME, raw, _derived_inputs(report, raw))]


def steps(report) -> list[str]:
    if report.coupling is None:
        return []
    from .. import coupling as cp

    cc, sel = report.coupling
    x, cat = cc.inputs, sel.catalog
    row = int(sel.order[0])
    part = latex_escape(str(cat.parts[row]))
    chosen = "the chosen coupling" if sel.selected else "the closest candidate (none passes)"
    out = [r"\subsection{Coupling: nominal torque and resonance}"]
    out += [step_block(title, step) for title, step in cc.steps]  # as the section computed them
    if sel.not_made:
        # The case lacks what M_N and f_e need (the contract's partial cases): no step to show.
        return out + [prose(f"Not checked: {c.text}, {c.not_made}.") + "\n" for c in sel.not_made]
    m_n = cp.M_N.step(M_a=x["accel_torque"], J_load=x["load_inertia"], J_drive=x["drive_inertia"], S_A=x["service_factor"])
    out.append(step_block("Nominal torque of the coupling", m_n, "compared with T_KN"))
    if sel.row_type(row) == "elastomer":
        bands = x["temperature_factors"]
        band = bands.text(int(bands.band(x["temperature"], "coupling.temperature")))
        k_t = Q_(float(sel.temperature_factor[row]), "")
        out.append(step_block(f"With the temperature factor ({part})", cp.M_Nt.step(M_N=m_n.result, K_T=k_t),
                              f"the factor of the band {band} ({bands.source})"))
        if sel.M_Smax is not None:
            starts = x["start_factors"]
            s_band = starts.text(int(starts.band(x["starts_per_hour"], "coupling.starts_per_hour")))
            out.append(step_block(f"Peak torque with the start and temperature factors ({part})",
                                  cp.M_Smax.step(T_S=m_n.result, S_z=Q_(sel.start_factor, ""), K_T=k_t),
                                  f"compared with T_Kmax; S_z of the band {s_band} ({starts.source})"))
    out.append(step_block("Lowest natural frequency allowed", cp.f_e_min.step(f_er=x["excitation_frequency"])))
    if np.isnan(sel.f_e[row].magnitude):
        return out
    out.append(rf"\subsection{{Natural frequency of {chosen}, {part}}}")
    J = cat["J"][row]
    out.append(step_block("Drive side with half the coupling", cp.J_A.step(J_drive=x["drive_inertia"], J_K=J)))
    out.append(step_block("Load side with half the coupling", cp.J_L.step(J_load=x["load_inertia"], J_K=J)))
    if sel.row_type(row) == "line-shaft" and x["shaft_distance"] is not None:
        z = cp.Z.step(A=x["shaft_distance"], H=cat["H"][row])
        out.append(step_block("Tube length", z))
        out.append(step_block("Stiffness of the line shaft", cp.C_T_line.step(C_B=cat["C_T"][row], Z=z.result, C_tube=cat["C_tube"][row])))
    out.append(step_block("Natural frequency", cp.f_e.step(C_T=sel.C_T[row], J_A=sel.J_A[row], J_L=sel.J_L[row]),
                          "compared with 2 f_er"))
    return out + _torsion(report, cc)


def _torsion(report, cc) -> list[str]:
    """The drive train as a chain of masses and springs (calc.torsion): the members referred to
    the coupling's shaft, the chain, and its natural frequencies beside the two-mass f_e."""
    t = (results_of(NAME, report) or {}).get("torsion")
    if not t:
        return []
    out = [rf"\subsection{{Torsional modes of the drive train, with {latex_escape(t['part'])}}}",
           prose("The two-mass f_e takes the coupling as the only spring. The drive train has more: it is lumped as a chain, "
                 f"every member referred to {t['shaft']}: the motor with half the coupling, the other half with the gearbox's J_1, "
                 "the load J_L / i²; springs: the coupling's C_T and the gearbox's C_t21 / i². Its natural frequencies are "
                 "the roots of the eigenproblem (K − ω² J) φ = 0, the rigid-body mode left out.")]
    out += [step_block(title, step) for title, step in cc.drive_steps]
    rows = [[str(k + 1), prose(m["members"]), q(m["J"]), prose(s["member"]) if s else "", q(s["C"]) if s else ""]
            for k, (m, s) in enumerate(zip(t["masses"], [*t["springs"], None]))]
    out.append(table(r"@{}r l r l r@{}", ["Mass", "Members", "Inertia", "Spring to the next", "Stiffness"], rows,
                     caption=f"The drive train as masses and springs, referred to {latex_escape(t['shaft'])}"))
    frequencies = ", ".join(q(f) for f in t["natural_frequencies"])
    out.append(prose("Natural frequencies, lowest first: ") + frequencies + ".")
    if not t["complete"]:
        out.append(prose("The chain is incomplete, so its first mode is reported for information: the case does not give "
                         + "; ".join(t["missing"]) + "."))
    return out


def results(report) -> list[str]:
    """What the coupling gives besides its checks: M_N, T_op, K_ϑ, f_e,min, the shafts, notes."""
    c = results_of(NAME, report)
    if not c:
        return []
    rows = [
        [r"$M_{N}$", q(c["M_N"]), prose(f"nominal torque of the coupling, S_A = {c['service_factor']:g} included (E8)")],
        [r"$T_{\mathrm{op}}$", q(c["T_op"]), prose("peak torque of normal operation (M_N with S_A = 1)")],
        [r"$K_{\vartheta}$", f"{c['temperature_factor']:g}",
         prose("temperature factor (elastomer couplings, E9)" + (f" at {plain(c['temperature'])}" if c.get("temperature") else ""))],
        [r"$f_{e,\mathrm{min}}$", q(c["f_e_min"]), prose("lowest natural frequency allowed, 2 f_er (E7)")],
    ]
    if c.get("start_factor") is not None:
        rows.append([r"$S_{z}$", f"{c['start_factor']:g}", prose(f"start factor at {plain(c['starts_per_hour'])} ({c['start_factors']})")])
    out = [r"\subsection{Coupling: results}", table(r"@{}l r p{0.6\linewidth}@{}", ["Symbol", "Value", "Description"], rows)]
    bores = [[rf"\texttt{{\footnotesize coupling.{latex_escape(b['key'])}}}", latex_escape(b["text"]),
              latex_escape(b.get("limits") or "–")] for b in c.get("bores", [])]
    if bores:
        out.append(table(r"@{}l l l@{}", ["Case key", "Shaft as written", "Limits of the shaft (ISO 286)"], bores,
                         caption="Shafts of the coupling"))
    if c.get("notes"):
        out.append(r"\paragraph{Notes.}" + itemize(prose(n) for n in c["notes"]))
    return out


def figures(report) -> list:
    if report.coupling is None:
        return []
    from ..coupling import f_e_min
    from ..coupling_plots import natural_frequency_figure, temperature_factor_figure

    cc, sel = report.coupling
    out = [(natural_frequency_figure(sel, f_e_min(f_er=cc.inputs["excitation_frequency"])),
            prose("Natural frequency of each coupling candidate against the lowest allowed, 2 f_er (E7)."))]
    if (sel.catalog.text["type"] == "elastomer").any():
        out.append((temperature_factor_figure(cc.inputs["temperature"], cc.inputs["temperature_factors"]),
                    prose(f"Temperature factor of elastomer couplings ({cc.inputs['temperature_factors'].source}).")))
    return out


# The blocks a further section shares with the others, for this section.
sources = functools.partial(further_sources, NAME)
readings = functools.partial(further_readings, NAME)
checks = functools.partial(further_checks, NAME)
candidates = functools.partial(further_candidates, NAME)
chosen = functools.partial(further_chosen, NAME)
order_lines = functools.partial(further_order_lines, NAME)


input_rows = common.nothing
