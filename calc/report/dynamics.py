"""The drive train's dynamics in the outputs: in the calc report the two-mass model's steps, the
chain with the stiffness each spring stands on, its modes and anti-resonances, λ and what its limit
means, the torque reversals, the checks with their basis and the frequency response; on the review's
page the same in short with the response drawn as SVG; in the comparison the first mode and the
lowest anti-resonance."""

from __future__ import annotations

from html import escape

import numpy as np

from ..core.units import Value, sig
from ..sections.dynamics import NAME
from .common import Renderer, checks_table
from .latex import latex_escape, prose, q, step_block, table
from .page import notes, table as html_table, value
from .symbols import html as typeset

#: The page's response drawing: width and height in pixels.
SVG_SIZE = (560, 180)


def _band(s) -> str:
    return "any torque" if s.band is None else f"{s.band[0]} to {s.band[1]}"


def response_svg(r) -> str:
    """The frequency response as an inline SVG polyline (dB over log frequency), resonances red,
    anti-resonances blue dashed, the speed loop's f_er green dotted: cheap enough to redraw on every
    change of the page.

    Parameters
    ----------
    r : calc.sections.dynamics.DynamicsResult
        The dynamics with modes.

    Returns
    -------
    str
        SVG markup; empty without modes.
    """
    resp = r.response
    if resp is None:
        return ""
    w, h = SVG_SIZE
    lf = np.log10(resp.frequency.m_as("Hz"))
    db = 20 * np.log10(resp.magnitude)
    lo, hi = float(db.min()), float(db.max())

    def x(v):
        return 40 + (w - 50) * (v - lf[0]) / (lf[-1] - lf[0])

    def y(v):
        return 10 + (h - 30) * (hi - v) / (hi - lo)

    points = " ".join(f"{x(a):.1f},{y(b):.1f}" for a, b in zip(lf, db))
    k = next((k for k in r.checks if k.name == "f_1" and k.required is not None), None)
    f_er = "" if k is None else (
        f'<line x1="{x(np.log10(k.required.m_as("Hz") / 2)):.1f}" x2="{x(np.log10(k.required.m_as("Hz") / 2)):.1f}" '
        f'y1="10" y2="{h - 20}" stroke="#5a9e3a" stroke-width="2" stroke-dasharray="1 3"><title>f_er '
        f'{sig(k.required.m_as("Hz") / 2, 4)} Hz</title></line>')
    marks = "".join(
        f'<line x1="{x(np.log10(f)):.1f}" x2="{x(np.log10(f)):.1f}" y1="10" y2="{h - 20}" stroke="{color}"'
        f'{dash}><title>{title} {sig(f, 4)} Hz</title></line>'
        for fs, color, dash, title in ((r.modes.natural_frequencies, "#b2222a", "", "resonance"),
                                       (r.modes.anti_resonances, "#1f5fa8", ' stroke-dasharray="4 3"',
                                        "anti-resonance"))
        for f in fs.m_as("Hz"))
    return (f'<svg class=dynamics width="{w}" height="{h}" role="img" aria-label="frequency response">'
            f'<polyline fill="none" stroke="black" points="{points}"/>{marks}{f_er}'
            f'<text x="40" y="{h - 4}" font-size="10">{sig(10 ** lf[0], 3)} Hz</text>'
            f'<text x="{w - 60}" y="{h - 4}" font-size="10">{sig(10 ** lf[-1], 3)} Hz</text>'
            f'<text x="2" y="12" font-size="10">{sig(hi, 3)} dB</text></svg>')


class DynamicsRenderer(Renderer):
    """The drive train's dynamics."""

    NAME = NAME

    def steps(self, report) -> list[str]:
        r = self.result(report)
        if r is None or r.two_mass is None:
            return []
        return [r"\subsection*{The drive train's dynamics: the two-mass model}"] + [
            step_block(title, step) for title, step in r.two_mass.steps]

    def results(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        if r.modes is None:
            return [r"\subsection*{The drive train's dynamics}", prose(f"No modes: {r.reason}.")]
        t, m = r.train, r.modes
        mass_rows = [[latex_escape(name), q(Value.of(J, "kg*cm**2"))] for name, J in zip(t.masses, t.inertias)]
        spring_rows = [[latex_escape(f"{s.name} {s.part}"), q(s.C),
                        prose(s.basis + ("; the working torques lie outside it" if s.outside else "")),
                        latex_escape(_band(s))] for s in r.springs]
        mode_rows = [[str(k + 1), q(Value.of(f, "Hz")), q(Value.of(z, "Hz")),
                      latex_escape(", ".join(f"{v:+.3f}" for v in m.shapes[k]))]
                     for k, (f, z) in enumerate(zip(m.natural_frequencies, m.anti_resonances))]
        tm = r.two_mass
        lam = (f"λ = J_Lm / J_motor = {tm.J_Lm} / {tm.J_motor} = {tm.inertia_ratio:.4g}: the two-mass model's "
               f"f_r / f_ar = {tm.ratio:.4g} = √(1 + λ). Limit λ <= {r.inertia_limit[0]:g} "
               f"({r.inertia_limit[1]}): {r.lam_meaning}. The chain's own ratio f_1 / f_ar,1 is "
               f"{float(m.natural_frequencies[0] / m.anti_resonances[0]):.4g}: its soft spring has the coupling "
               "and the gearbox input on the motor's side.")
        reversals = f"Torque reversals per cycle at the gearbox: {r.reversals}." + (
            "" if r.backlash is None or not r.reversals else
            f" At each the chain crosses the backlash {r.backlash} with no stiffness.")
        return [
            r"\subsection*{The drive train's dynamics}",
            table(r"@{}l r@{}", ["Mass", "Inertia"], mass_rows, caption=latex_escape(f"Masses at {t.shaft}")),
            table(r"@{}p{0.16\linewidth} r p{0.4\linewidth} p{0.14\linewidth}@{}", ["Spring", "C", "Basis", "Holds at"],
                  spring_rows,
                  caption="The springs and the stiffness each stands on", small=True),
            table(r"@{}r r r l@{}", ["Mode", "Natural frequency", "Anti-resonance", "Mode shape (drive to load)"],
                  mode_rows, caption="Natural frequencies, anti-resonances (motor held) and mode shapes"),
            prose(lam), prose(reversals),
        ]

    def checks(self, report) -> list[str]:
        r = self.result(report)
        if r is None:
            return []
        said = [prose(f"{k.criterion}: {r.bases[k.name]}.") for k in r.checks if k.name in r.bases]
        return [checks_table(r.checks, "Checks of the drive train's dynamics"), *said,
                *[prose(f"Note: {n}.") for n in r.notes]]

    def figures(self, report) -> list:
        r = self.result(report)
        if r is None or r.response is None:
            return []
        from ..figures.dynamics_plots import frequency_response_figure

        k = next((k for k in r.checks if k.name == "f_1" and k.required is not None), None)
        f_er = None if k is None else k.required / 2
        return [(frequency_response_figure(r.response, r.modes.natural_frequencies, r.modes.anti_resonances, f_er),
                 prose("Frequency response of the motor's speed to the motor's torque: resonances (solid), "
                       "anti-resonances with the motor held (dashed), the speed loop's f_er and 2 f_er."))]

    def page(self, r, view) -> str:
        """The dynamics on the review's page: modes, springs, λ, checks and the response as SVG.

        Parameters
        ----------
        r : calc.sections.dynamics.DynamicsResult or None
            The result; None where the case has no drive train.
        view : object
            How the page is viewed (unused: the dynamics list no candidates).

        Returns
        -------
        str
            HTML.
        """
        if r is None:
            return ""
        if r.modes is None:
            return f"<h3>Drive-train dynamics</h3><div class=note>no modes: {escape(r.reason)}</div>"
        m, tm = r.modes, r.two_mass
        rows = [[str(k + 1), value(Value.of(f, "Hz")), value(Value.of(z, "Hz"))]
                for k, (f, z) in enumerate(zip(m.natural_frequencies, m.anti_resonances))]
        springs = "".join(
            f"<div class=note>{escape(f'{s.name} {s.part}')}: C = {value(s.C)}, {typeset(s.basis)}"
            + ("" if s.band is None else f"; holds at {value(s.band[0])} to {value(s.band[1])}")
            + ("; <b>the working torques lie outside it</b>" if s.outside else "") + "</div>" for s in r.springs)
        checks = "".join(f"<div class=note>{typeset(k.criterion)}: {value(k.rated_value)}"
                         f"{'' if k.utilization is None else f', utilization {k.utilization:.2f}'}"
                         f"{'' if k.governs else ' (for information)'}</div>" for k in r.checks)
        return ("<h3>Drive-train dynamics</h3>"
                + html_table(["mode", "natural frequency", "anti-resonance (motor held)"], rows, numeric={1, 2})
                + springs
                + f"<div class=note>{typeset(f'λ = {tm.inertia_ratio:.4g}: f_r / f_ar = {tm.ratio:.4g} = √(1 + λ)')}"
                + f"; {typeset(r.lam_meaning)}</div>" + checks + notes(r.notes) + response_svg(r))

    def compared(self) -> tuple:
        def first(r):
            return "" if r is None or r.modes is None else f"{sig(r.modes.natural_frequencies[0].m_as('Hz'), 4)} Hz"

        def anti(r):
            return "" if r is None or r.modes is None else f"{sig(r.modes.anti_resonances[0].m_as('Hz'), 4)} Hz"

        return (("first mode f_1", first), ("lowest anti-resonance", anti))


RENDERER = DynamicsRenderer()
