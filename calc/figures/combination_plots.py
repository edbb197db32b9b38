"""The figure of a motor × gearbox × ratio search (:mod:`calc.domain.combinations`): which motor works
at which ratio, and how hard, at a glance."""

from __future__ import annotations

import numpy as np

#: Colours: a feasible pair's utilization runs from green (much margin) to red (at a rating).
FEASIBLE_MAP = "RdYlGn_r"
INFEASIBLE = "#d9d9d9"
PICK = "#222222"


def combinations_figure(utilization, feasible, ratios, motor_names, pick=None, ratio_of_rows=None):
    """A grid of motors (rows, smallest first) against ratios (columns): each cell the lowest
    utilization of the feasible gearboxes of that ratio with that motor (the highest of its
    checks; green is margin, red is at a rating), grey where no gearbox of that ratio works with it; the pick
    marked with a star.

    ``utilization`` and ``feasible`` are (gearbox rows × motors) (:class:`calc.domain.combinations.Combinations`),
    ``ratio_of_rows`` the ratio of each gearbox row, ``ratios`` the columns (ascending),
    ``motor_names`` the rows, ``pick`` the (gearbox row, motor) picked.

    Parameters
    ----------
    utilization : numpy.ndarray [1]
        Gearbox rows × motors.
    feasible : numpy.ndarray of bool
        Gearbox rows × motors.
    ratios : numpy.ndarray [1]
        The columns, ascending.
    motor_names : sequence of str
        The rows.
    pick : tuple of int, optional
        The ``(gearbox row, motor)`` picked.
    ratio_of_rows : numpy.ndarray [1], optional
        The ratio of each gearbox row.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.

    Examples
    --------
    >>> import numpy as np
    >>> u = np.array([[0.5, 0.9], [1.2, 0.4]])
    >>> fig = combinations_figure(u, u <= 1, [5.0, 10.0], ["A", "B"], (0, 0), ratio_of_rows=np.array([5.0, 10.0]))
    >>> [t.get_text() for t in fig.axes[0].get_xticklabels()]
    ['5', '10']
    """
    from matplotlib.figure import Figure

    utilization, feasible = np.asarray(utilization, float), np.asarray(feasible, bool)
    ratios = np.asarray(ratios, float)
    column = np.searchsorted(ratios, np.asarray(ratio_of_rows, float))
    best = np.full((len(motor_names), len(ratios)), np.nan)
    # the lowest feasible utilization of each (motor, ratio): a minimum over the rows of each ratio
    masked = np.where(feasible, utilization, np.inf)
    for k in range(len(ratios)):
        rows = column == k
        if rows.any():
            low = masked[rows].min(axis=0)
            best[:, k] = np.where(np.isfinite(low), low, np.nan)
    height = min(12.0, 1.6 + 0.14 * len(motor_names))
    fig = Figure(figsize=(7.5, height), layout="constrained")
    ax = fig.subplots()
    ax.set_facecolor(INFEASIBLE)
    image = ax.imshow(best, aspect="auto", cmap=FEASIBLE_MAP, vmin=0.0, vmax=1.0, interpolation="nearest",
                      origin="lower")
    fig.colorbar(image, ax=ax, label="lowest utilization of a working gearbox (1 = at a rating)")
    ax.set_xticks(range(len(ratios)), [f"{r:g}" for r in ratios])
    step = max(1, len(motor_names) // 40)  # at most some 40 names on the axis
    ax.set_yticks(range(0, len(motor_names), step), [str(n) for n in motor_names][::step], fontsize=7)
    ax.set_xlabel("gearbox ratio i")
    ax.set_ylabel("motor (smallest first)")
    if pick is not None:
        row, motor = pick
        ax.plot([column[row]], [motor], marker="*", markersize=14, color=PICK, markeredgecolor="white",
                linestyle="none",
                label="the pick")
        ax.legend(loc="upper left", fontsize=8, framealpha=0.9)
    ax.set_title("Which motor works at which ratio (grey: none of that ratio's gearboxes)", fontsize=10, loc="left")
    return fig
