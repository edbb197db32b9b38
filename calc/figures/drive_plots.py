"""Figures of the servo drive: the winding's temperature over two cycles, the motor's power with
the braking events, and the DC-bus power of a machine's axes and their sum."""

from __future__ import annotations

import numpy as np

from ..domain.drive import Winding


def winding_figure(w: Winding, title: str = ""):
    """The winding's temperature rise over two cycles in the periodic state, against its limit 1
    (the rise under the reference torque held continuously).

    Parameters
    ----------
    w : calc.domain.drive.Winding
        The winding's model as the motor section computed it.
    title : str
        The motor, for the title; none by default.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.
    """
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.5, 3.4), layout="constrained")
    ax = fig.subplots()
    ax.plot(w.times, w.theta, color="tab:red", linewidth=1.6, label="winding θ (periodic state)")
    ax.axhline(1.0, color="black", linestyle="--", linewidth=1.0, label=f"θ = 1: {w.reference} held")
    ax.set_xlabel("time over two cycles [s]")
    ax.set_ylabel("θ [1]")
    ax.set_ylim(0, max(1.1, 1.1 * float(w.theta.max())))
    ax.set_title(f"Winding temperature{' of ' + title if title else ''}: θ_max = {w.utilization:.3g}, "
                 f"T_th = {w.T_th / 60:.3g} min", fontsize=10)
    ax.grid(True, color="#dddddd", linewidth=0.6)
    ax.legend(fontsize=8, loc="lower right")
    return fig


def power_figure(times, powers: dict, title: str):
    """Powers over one cycle, each held over its step (a motor's; a machine's axes and their sum).

    Parameters
    ----------
    times : numpy.ndarray [s]
        The step edges, one more than each power's values.
    powers : dict
        Label -> the power of each step [W] (negative: braking).
    title : str
        The figure's title.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.
    """
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.5, 3.6), layout="constrained")
    ax = fig.subplots()
    for label, p in powers.items():
        p = np.asarray(p, float)
        ax.plot(times, np.append(p, p[-1]), drawstyle="steps-post", linewidth=1.8 if label == "sum" else 1.0,
                color="black" if label == "sum" else None, label=label)
    ax.axhline(0, color="black", linewidth=0.6)
    ax.set_xlabel("time in the cycle [s]")
    ax.set_ylabel("power at the DC bus [W]; negative: braking")
    ax.set_title(title, fontsize=10)
    ax.grid(True, color="#dddddd", linewidth=0.6)
    ax.legend(fontsize=8, loc="best")
    return fig


def machine_pdf(summary: str, times, powers: dict, path) -> None:
    """A machine's PDF: its summary as text on the first page, the DC bus's power on the second.

    Parameters
    ----------
    summary : str
        The machine's text summary.
    times : numpy.ndarray [s]
        The time base's edges.
    powers : dict
        Each axis's power and their sum [W] over the steps.
    path : str or pathlib.Path
        The PDF file.

    Returns
    -------
    None
    """
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.figure import Figure

    text = Figure(figsize=(8.27, 11.69))
    text.text(0.05, 0.97, summary, family="monospace", fontsize=6.5, va="top", wrap=True)
    with PdfPages(path) as pdf:
        pdf.savefig(text)
        pdf.savefig(power_figure(times, powers, "Power of each axis at the shared DC bus and their sum "
                                                "(negative: braking)"))
