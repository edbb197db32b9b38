"""The load cycle in the outputs: in the calc report its table, the duty cycle, the S1 means and
the S5 values with the shock factor, and the figures of the cycle and of the shock factor; on the
review's page the duty values in one line; in the comparison of designs the mode, ED, T_2max and
T_2m."""

from __future__ import annotations

import dataclasses
from html import escape

from ..domain.gearbox import SHOCK_FACTORS
from ..sections import duty as sections_duty
from ..core.units import sig
from .common import Renderer
from .latex import latex_escape, num, render, step_block, symbol_latex, symbol_math, table
from .page import in_system, value
from .symbols import html as typeset


def shock_factor_block(zh, table=SHOCK_FACTORS) -> str:
    """The shock factor of ``Z_h`` with its band, the one :func:`calc.domain.gearbox.shock_factor`
    chooses from ``table`` (E4, with its boundary tolerance).

    Parameters
    ----------
    zh : pint.Quantity [1/h]
        The cycles per hour ``Z_h``.
    table : calc.data.bands.BandTable
        The shock factors by band of ``Z_h``: the case's ``[gearbox] shock_factors``, else the
        package's.

    Returns
    -------
    str
        LaTeX: the factor, its band and the table's source.
    """
    k = int(table.band(zh, "Z_h"))
    return render(
        "shock-factor.tex.j2", fs=f"{table.factors[k]:g}", band=table.text(k, latex=True),
        zh=sig(zh.m_as(table.unit)), source=latex_escape(table.source),
        f_s=symbol_latex("f_s"), Z_h=symbol_latex("Z_h"),
    )


def _shown(result, field: str) -> str:
    """A duty value of ``result`` (None: none) as the comparison writes it, in the unit system shown."""
    v = None if result is None else getattr(result.shown, field)
    return "" if v is None else str(in_system(v))


class DutyRenderer(Renderer):
    """The load cycle: its table, steps and figures in the report, its values on the page and in
    the comparison."""

    NAME = sections_duty.NAME

    def inputs(self, report) -> list[str]:
        p = report.case.profile
        rows = []
        for k, (phase, t, n, T) in enumerate(zip(p.phases, p.durations, p.speeds, p.torques), start=1):
            moving = phase != "pause"
            rows.append([str(k), phase, num(t, "s"), num(n, "rpm") if moving else "–",
                         num(T, "N*m") if moving else "–"])
        return [table(
            r"@{}r l r r r@{}",
            ["k", "Phase", *(f"{symbol_math(symbol)} [{unit}]" for symbol, unit in (("t_k", "s"), ("n_2k", "rpm"),
                                                                                   ("T_2k", "N·m")))],
            rows,
            caption="Load cycle at the gearbox output (case key \\texttt{[[profile]]})" if report.case.motion is None
            else "Load cycle at the gearbox output, derived from the motion (below)",
            note="Speeds are the mean output speed of each segment; a negative torque brakes.",
        )]

    def steps(self, report) -> list[str]:
        d = self.result(report)
        (t_ed, ed), (t_n, n2m), (t_t, t2m), (t_z, zh) = d.steps
        return [
            r"\subsection{Duty cycle and operating mode}",
            step_block(t_ed, ed, f"operating mode {d.duty.mode} (E3)"),
            r"\subsection{Continuous operation (S1)}",
            step_block(t_n, n2m),
            step_block(t_t, t2m),
            r"\subsection{Cycle operation (S5)}",
            step_block(t_z, zh),
            shock_factor_block(zh.result, d.shock_factors),
        ]

    def figures(self, report) -> list:
        from ..figures.plots import load_cycle_figure, shock_factor_figure

        if report.evaluated is None:
            return []
        d = self.result(report)
        # The case's table, its path as the case names it.
        shown = dataclasses.replace(d.shock_factors, source=report.relative(d.fs_table, str))
        return [
            (load_cycle_figure(d.profile), "Load cycle at the gearbox output, with ED and the operating mode (E3)."),
            (shock_factor_figure(d.Zh, shown, f_s=d.fs),
             latex_escape(f"Shock factor against cycles per hour ({shown.source}); the case's point marked (E4).")),
        ]

    def page(self, d, view) -> str:
        """The duty values in one line of the review's page: mode, ED, the S5 and S1 values.

        Parameters
        ----------
        d : calc.sections.duty.DutyResult
            The duty result.
        view : calc.report.page.View
            What the page asks (the line does not depend on it).

        Returns
        -------
        str
            HTML: one ``div``.
        """
        v = d.shown
        parts = [f"<b>{escape(v.mode)}</b>", f"ED {value(v.ED)}", f"cycle {value(v.t_cycle)}",
                 f"{typeset('Z_h')} {value(v.Z_h)}", f"{typeset('f_s')} {sig(v.f_s)}",
                 f"{typeset('n_2max')} {value(v.n_2max)}",
                 f"{typeset('T_2max')} {value(v.T_2max)}" + (f" (with {typeset('eta')} {sig(v.T_2max_eta)})"
                                                            if v.T_2max_eta is not None else "")
                 if v.T_2max is not None else "",
                 f"{typeset('n_2m')} {value(v.n_2m)}", f"{typeset('T_2m')} {value(v.T_2m)}"]
        return '<div class="values">Duty: ' + " · ".join(p for p in parts if p) + "</div>"

    def compared(self) -> tuple:
        return (("mode", lambda d: "" if d is None else d.shown.mode),
                ("ED", lambda d: _shown(d, "ED")),
                ("T_2max", lambda d: _shown(d, "T_2max")),
                ("T_2m", lambda d: _shown(d, "T_2m")))


RENDERER = DutyRenderer()
