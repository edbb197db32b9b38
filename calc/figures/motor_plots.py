"""Figures of the motor's side: the motor torque over the cycle, and the case against the ratio."""

from __future__ import annotations

import numpy as np

from ..domain.motor import MotorLoad, OutputLoad
from ..domain.motor_ratings import MotorSelection, peak_limit
from ..domain.ratios import RatioSearch
from ..core.glossary import latex as symbol_latex
from ..core.glossary import math as symbol


def motor_torque_figure(load: OutputLoad, torques: MotorLoad, row: int = 0, peak_torque=None, rated_torque=None,
                        part: str = ""):
    """The motor torque ``T_1`` over one cycle (each sample or segment held for its duration), its
    RMS, and the motor's peak and rated torque where given.

    Parameters
    ----------
    load : OutputLoad
        The cycle at the gearbox output (its durations place the samples in time).
    torques : MotorLoad
        The motor torques of :func:`calc.domain.motor.motor_load`.
    row : int
        The gearbox whose torques are drawn, where ``torques`` holds several; default 0.
    peak_torque, rated_torque : pint.Quantity [N·m], optional
        ``T_1B`` and ``T_1N``, drawn as limits (both signs for the peak).
    part : str
        The gearbox the torque passes through, for the title; none by default.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.
    """
    from matplotlib.figure import Figure

    dt = np.asarray(load.dt.m_as("s"), float)
    t = np.concatenate(([0.0], np.cumsum(dt)))
    T = np.atleast_2d(torques.T_1.m_as("N*m"))[row]
    fig = Figure(figsize=(7.5, 3.8), layout="constrained")
    ax = fig.subplots()
    # Steps drawn as one line (a stairs patch of thousands of samples costs a second to lay out).
    ax.plot(t, np.append(T, T[-1]), drawstyle="steps-post", color="tab:blue", linewidth=1.6, label="motor torque $T_1$")
    rms = float(np.atleast_1d(torques.rms.m_as("N*m"))[row])
    ax.axhline(rms, color="tab:green", linestyle="-.", linewidth=1.2, label=f"RMS {rms:.3g} N·m")
    if rated_torque is not None:
        ax.axhline(rated_torque.m_as("N*m"), color="tab:orange", linestyle="--", linewidth=1.2,
                   label=f"rated torque {symbol('T_1N')}")
    if peak_torque is not None:
        peak = peak_torque.m_as("N*m")
        ax.axhline(peak, color="tab:red", linestyle="--", linewidth=1.2, label=f"peak torque {symbol('T_1B')} (±)")
        ax.axhline(-peak, color="tab:red", linestyle="--", linewidth=1.2)
    ax.axhline(0, color="black", linewidth=0.6)
    ax.set_xlabel("time in the cycle [s]")
    ax.set_ylabel("motor torque $T_1$ [N·m]")
    rotor = "rotor and gearbox inertia included" if torques.rotor_term else "rotor term left out (typed load cycle)"
    ax.set_title(f"Motor torque over the cycle{' through ' + part if part else ''}; {rotor}", fontsize=10)
    ax.grid(True, color="#dddddd", linewidth=0.6)
    ax.legend(fontsize=8, loc="best")
    return fig


def torque_speed_figure(selection: MotorSelection, row: int):
    """The torque-speed plane of one catalog motor: the cycle's operating points (each sample's
    motor speed and torque magnitude), the motor's peak characteristic at the speeds of the cycle
    and up to its maximum speed, its rated point ``(n_N, M_N)`` and the cycle's RMS torque at its
    mean speed (the S1 check).

    Parameters
    ----------
    selection : calc.domain.motor_ratings.MotorSelection
        The catalog motors checked against the cycle.
    row : int
        The motor's row in ``selection.catalog``.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.
    """
    from matplotlib.figure import Figure

    cat, cycle = selection.catalog, selection.cycle
    to_rpm = 60 / (2 * np.pi)
    n_max = float(cat["n_max"][row].m_as("rad/s"))
    grid = np.linspace(0.0, n_max, 200)
    limit, forms = peak_limit(cat.rows(np.arange(len(cat)) == row), grid, selection.dc_link, selection.curves)
    fig = Figure(figsize=(7.5, 4.2), layout="constrained")
    ax = fig.subplots()
    ax.plot(grid * to_rpm, limit[0], color="tab:red", linewidth=1.6, label=f"peak torque ({forms[0]})")
    ax.plot(np.abs(cycle.speed) * to_rpm, np.abs(cycle.torque[row]), ".", color="tab:blue", markersize=3, alpha=0.5,
            label="operating points $|n_1|, |T_1|$")
    ax.plot([cat["n_N"][row].m_as("rpm")], [cat["M_N"][row].m_as("N*m")], "s", color="tab:orange",
            label=f"rated point $({symbol_latex('n_N')}, {symbol_latex('M_N_motor')})$")
    ax.plot([selection.mean_speed * to_rpm], [cycle.rms[row]], "D", color="tab:green",
            label=f"RMS {cycle.rms[row]:.3g} N·m at the mean speed")
    ax.set_xlim(0, n_max * to_rpm * 1.05)
    ax.set_ylim(0, None)
    ax.set_xlabel("motor speed $n_1$ [rpm]")
    ax.set_ylabel("motor torque $|T_1|$ [N·m]")
    ax.set_title(f"{cat.parts[row]}: the cycle in the torque-speed plane", fontsize=10)
    ax.grid(True, color="#dddddd", linewidth=0.6)
    ax.legend(fontsize=8, loc="best")
    return fig


def ratio_figure(search: RatioSearch, peak_torque=None, rated_torque=None, optimal_ratio=None):
    """The case against the ratio: the motor's peak and RMS torque through each ratio's best
    gearbox (top), the governing utilization and the inertia ratio (bottom); feasible ratios
    shaded, the picked one marked, the inertia-matching ratio dashed where it falls within the
    catalog's ratios.

    Parameters
    ----------
    search : RatioSearch
        The case at every ratio.
    peak_torque : pint.Quantity [N·m], optional
        The motor's ``T_1B``, drawn as a limit.
    rated_torque : pint.Quantity [N·m], optional
        The motor's ``T_1N``, drawn as a limit.
    optimal_ratio : float, optional
        ``i_opt = √(J_L / J_in)`` [1] (:data:`calc.domain.ratios.optimal_ratio`); named in the title,
        drawn where it lies within the catalog's ratios.

    Returns
    -------
    matplotlib.figure.Figure
        Two axes sharing the ratio axis.
    """
    from matplotlib.figure import Figure

    x = search.ratios
    fig = Figure(figsize=(7.5, 6.0), layout="constrained")
    top, bottom = fig.subplots(2, 1, sharex=True)
    for ax in (top, bottom):
        for k in np.flatnonzero(search.feasible):
            ax.axvspan(x[k] - 0.4, x[k] + 0.4, color="#d9f0d3", zorder=0, label="feasible"
                       if k == np.flatnonzero(search.feasible)[0] else None)
        if search.pick is not None:
            ax.axvline(x[search.pick], color="tab:green", linewidth=2, zorder=1, label=f"pick: i = {x[search.pick]:g}")
    if search.load is not None:
        top.plot(x, search.load.peak.m_as("N*m"), "o-", color="tab:red", label="peak $T_1$")
        top.plot(x, search.load.rms.m_as("N*m"), "s-", color="tab:blue", label="RMS $T_1$")
    if peak_torque is not None:
        top.axhline(peak_torque.m_as("N*m"), color="tab:red", linestyle="--", linewidth=1, label=symbol("T_1B"))
    if rated_torque is not None:
        top.axhline(rated_torque.m_as("N*m"), color="tab:blue", linestyle="--", linewidth=1, label=symbol("T_1N"))
    top.set_ylabel("motor torque [N·m]")
    top.legend(fontsize=8, loc="best")
    top.grid(True, color="#dddddd", linewidth=0.6)
    bottom.plot(x, search.utilization, "o-", color="black", label="governing utilization")
    bottom.axhline(1.0, color="black", linestyle="--", linewidth=1)
    handles, labels = bottom.get_legend_handles_labels()
    if not np.all(np.isnan(search.inertia_ratio)):
        lam = bottom.twinx()
        lam.plot(x, search.inertia_ratio, "^:", color="tab:purple", label="inertia ratio λ")
        limit = search.inertia_limit
        lam.axhline(limit, color="tab:purple", linestyle="--", linewidth=1, label=f"λ limit {limit:g}")
        lam.set_ylabel("inertia ratio λ [–]", color="tab:purple")
        more = lam.get_legend_handles_labels()
        handles, labels = handles + more[0], labels + more[1]
    bottom.set_ylabel("utilization [–]")
    bottom.set_xlabel("ratio i")
    bottom.set_xticks(x, [f"{r:g}\n{p}" for r, p in zip(x, search.parts)], fontsize=7)
    bottom.grid(True, color="#dddddd", linewidth=0.6)
    fig.legend(handles, labels, loc="outside lower center", ncols=3, fontsize=8, frameon=False)
    title = "The case at every ratio of the catalog, each with its best gearbox"
    if optimal_ratio is not None:
        title += f"; inertia matching: i_opt = {optimal_ratio:.3g}"
        if x.min() <= optimal_ratio <= x.max():
            for ax in (top, bottom):
                ax.axvline(optimal_ratio, color="tab:gray", linestyle="--", linewidth=1.5)
    top.set_title(title, fontsize=10)
    return fig
