"""Figures of a motion: position, speed, acceleration and torque against time over one cycle, at the
gearbox output and at the load, with the seed's segments drawn over the samples.

Built without pyplot, like :mod:`calc.figures.plots` (deterministic, labelled for a printed page).
"""

from __future__ import annotations

import numpy as np

from ..domain.cycle import PAUSE
from ..domain.motion import Samples
from ..domain.profile import Segments
from ..core.glossary import math as symbol
from .plots import ON_COLOR, PAUSE_COLOR, SPEED_COLOR, TORQUE_COLOR

POSITION_COLOR = "#444444"
ACCELERATION_COLOR = "#5a9e3a"

#: How the load's travel is shown: per linear or rotary load, its unit and the factor from SI.
LOAD_UNITS = {True: ("mm", 1e3, "mm/s", 1e3, "m/s²", 1.0),
              False: ("deg", 180 / np.pi, "rpm", 30 / np.pi, "rad/s²", 1.0)}


def motion_figure(samples: Samples, torque: np.ndarray, segments: Segments | None = None, to_load: float = 1.0,
                  linear: bool = False, title: str = "",
                  rows: tuple[str, ...] = ("position", "speed", "acceleration", "torque")):
    """The sampled cycle against time: each of ``rows`` on its own axes, the gearbox output on the
    left scale and, for ``position``, ``speed`` and ``acceleration``, the load on the right
    (``to_load``: the load's travel per radian of the output, m or rad, SI); moving phases
    shaded blue, pauses grey; ``segments`` drawn as steps over the speed and torque (each
    segment's mean speed and the torque of its cubic mean).

    Parameters
    ----------
    samples : calc.domain.motion.Samples
        One cycle at the gearbox output (SI).
    torque : numpy.ndarray [N·m]
        The output torque of each sample.
    segments : calc.domain.motion.Segments, optional
        The seed's segments of the cycle.
    to_load : float [m/rad or 1]
        The load's travel per radian of the output (r of the mechanism, 1 for a table).
    linear : bool
        Whether the load moves along a line (its scale in mm, mm/s, m/s²).
    title : str
        The figure's title; none by default.
    rows : tuple of str
        The axes, top to bottom: ``position``, ``speed``, ``acceleration``, ``torque``.

    Returns
    -------
    matplotlib.figure.Figure
        One axes per row, sharing the time axis.

    Examples
    --------
    >>> from calc.domain.motion import Move, sample
    >>> from calc.domain.profile import segments
    >>> s = sample([Move(1.0, 1.0, 0.25, 0.25), Move(0.0, 0.5)], samples=200)
    >>> fig = motion_figure(s, 2 * s.acceleration, segments(s, 2 * s.acceleration))
    >>> [ax.get_ylabel() for ax in fig.axes[:2]]
    ['output angle $\\\\varphi_2$ [deg]', 'output speed $n_2$ [rpm]']
    >>> [ax.get_ylabel() for ax in fig.axes[2:4]]
    ['output acceleration $\\\\alpha_2$ [rad/s²]', 'output torque $T_2$ [N·m]']
    """
    from matplotlib.figure import Figure

    t = samples.t
    edges = np.concatenate([[0.0], np.cumsum(samples.durations)])
    phases = samples.segment_phases
    load_unit = LOAD_UNITS[linear]
    names = (("travel $s$", "speed $v$", "acceleration $a$") if linear
             else (f"angle {symbol('phi_L')}", f"speed {symbol('n_L')}", f"acceleration {symbol('alpha_L')}"))
    spec = {
        "position": (samples.position * 180 / np.pi, POSITION_COLOR, r"output angle $\varphi_2$ [deg]",
                     (np.pi / 180 * to_load * load_unit[1], f"load {names[0]} [{load_unit[0]}]")),
        "speed": (samples.speed * 30 / np.pi, SPEED_COLOR, "output speed $n_2$ [rpm]",
                  (np.pi / 30 * to_load * load_unit[3], f"load {names[1]} [{load_unit[2]}]")),
        "acceleration": (samples.acceleration, ACCELERATION_COLOR, r"output acceleration $\alpha_2$ [rad/s²]",
                         (to_load * load_unit[5], f"load {names[2]} [{load_unit[4]}]")),
        "torque": (torque, TORQUE_COLOR, "output torque $T_2$ [N·m]", None),
    }
    fig = Figure(figsize=(8.0, 2.0 + 1.7 * len(rows)), layout="constrained")
    axes = np.atleast_1d(fig.subplots(len(rows), 1, sharex=True))
    for ax, row in zip(axes, rows):
        values, color, label, load = spec[row]
        for k in range(len(phases)):
            ax.axvspan(edges[k], edges[k + 1], color=PAUSE_COLOR if phases[k] == PAUSE else ON_COLOR, linewidth=0,
                       zorder=0)
        ax.axhline(0.0, color="black", linewidth=0.8, zorder=1)
        ax.plot(t, values, color=color, linewidth=1.8, zorder=3)
        ax.set_ylabel(label)
        ax.grid(True, color="white", linewidth=0.8)
        if segments is not None and row in ("speed", "torque"):
            stairs = segments.speed * 30 / np.pi if row == "speed" else segments.torque
            ax.stairs(stairs, edges, baseline=None, color="black", linewidth=1.2, linestyle="--", zorder=4,
                      label="segment: mean speed" if row == "speed" else "segment: torque of the cubic mean")
            ax.legend(loc="upper right", fontsize=8, framealpha=0.9)
        if load is not None:
            factor, load_label = load
            side = ax.secondary_yaxis("right", functions=(lambda x, f=factor: x * f, lambda y, f=factor: y / f))
            side.set_ylabel(load_label)
    axes[-1].set_xlabel("time $t$ [s]")
    axes[-1].set_xlim(edges[0], edges[-1])
    if title:
        fig.suptitle(title)
    return fig
