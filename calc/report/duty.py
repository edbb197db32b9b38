"""The load cycle in the calc report: its table, the duty cycle, the S1 means and the S5 values
with the shock factor, and the figures of the cycle and of the shock factor."""

from __future__ import annotations

import dataclasses

from ..domain.gearbox import SHOCK_FACTORS
from ..sections import duty as sections_duty
from ..core.units import sig
from .common import nothing
from .latex import latex_escape, num, render, step_block, symbol_latex, symbol_math, table

NAME = "duty"


def shock_factor_block(zh, table=SHOCK_FACTORS) -> str:
    """The shock factor of ``Z_h`` (a quantity) with its band, the one calc.domain.gearbox.shock_factor
    chooses from ``table`` (E4, with its boundary tolerance; the case's ``[gearbox] shock_factors``)."""
    k = int(table.band(zh, "Z_h"))
    return render(
        "shock-factor.tex.j2", fs=f"{table.factors[k]:g}", band=table.text(k, latex=True),
        zh=sig(zh.m_as(table.unit)), source=latex_escape(table.source),
        f_s=symbol_latex("f_s"), Z_h=symbol_latex("Z_h"),
    )


def inputs(report) -> list[str]:
    p = report.case.profile
    rows = []
    for k, (phase, t, n, T) in enumerate(zip(p.phases, p.durations, p.speeds, p.torques), start=1):
        moving = phase != "pause"
        rows.append([str(k), phase, num(t, "s"), num(n, "rpm") if moving else "–", num(T, "N*m") if moving else "–"])
    return [table(
        r"@{}r l r r r@{}",
        ["k", "Phase", f"{symbol_math('t_k')} [s]", f"{symbol_math('n_2k')} [rpm]", f"{symbol_math('T_2k')} [N·m]"],
        rows,
        caption="Load cycle at the gearbox output (case key \\texttt{[[profile]]})" if report.case.motion is None
        else "Load cycle at the gearbox output, derived from the motion (below)",
        note="Speeds are the mean output speed of each segment; a negative torque brakes.",
    )]


def _result(report):
    return report.evaluated[sections_duty.NAME]


def steps(report) -> list[str]:
    d = _result(report)
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


def figures(report) -> list:
    from ..figures.plots import load_cycle_figure, shock_factor_figure

    if report.evaluated is None:
        return []
    d = _result(report)
    shown = dataclasses.replace(d.shock_factors, source=report.relative(d.fs_table, str))  # the case's table, its path as the case names it
    return [
        (load_cycle_figure(d.profile), "Load cycle at the gearbox output, with ED and the operating mode (E3)."),
        (shock_factor_figure(d.Zh, shown), latex_escape(f"Shock factor against cycles per hour ({shown.source}); the case's point marked (E4).")),
    ]


input_rows = results = checks = candidates = chosen = order_lines = sources = readings = nothing
