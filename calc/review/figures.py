"""The review's live load-cycle figure, drawn by the browser: an SVG text of the cycle's steps.

The calc report and the notebooks draw the load cycle with matplotlib
(:func:`calc.plots.load_cycle_figure`); the review redraws it on every change of a move, the
mechanism or a segment, and rendering that figure to a PNG takes 0.2 to 0.4 s, most of a change's
time. Here the kernel writes the steps as SVG (some 2 KB, under a millisecond) and the browser
draws them: the same data (each segment's mean output speed and torque against time, the pauses
shaded, ED and the mode in the title), without the report figure's annotations.
"""

from __future__ import annotations

import math
from html import escape

import numpy as np

from ..units import Q_, pretty_unit

WIDTH, HEIGHT = 540, 300
LEFT, RIGHT, TOP, GAP, BOTTOM = 58, 10, 26, 22, 30
PANEL = (HEIGHT - TOP - GAP - BOTTOM) / 2


def nice_ticks(low: float, high: float, count: int = 4) -> list[float]:
    """Round tick values (1, 2 or 5 times a power of ten apart) covering ``low`` to ``high``.

    >>> nice_ticks(0, 300), nice_ticks(-45, 60)
    ([0.0, 100.0, 200.0, 300.0], [-50.0, 0.0, 50.0, 100.0])
    """
    span = (high - low) or abs(high) or 1.0
    raw = span / count
    power = 10.0 ** math.floor(math.log10(raw))
    step = next(m * power for m in (1, 2, 5, 10) if m * power >= raw)
    first = math.floor(low / step) * step
    return [round(first + k * step, 12) for k in range(int(math.ceil((high - first) / step - 1e-9)) + 1)]


def _panel(edges, values, top: float, label: str, moving) -> list[str]:
    """One panel: its axis, ticks, the pauses shaded and the step line."""
    ticks = nice_ticks(min(0.0, float(np.min(values))), max(0.0, float(np.max(values))))
    lo, hi = ticks[0], ticks[-1]
    span_x = edges[-1] or 1.0

    def x(t):
        return LEFT + (WIDTH - LEFT - RIGHT) * t / span_x

    def y(v):
        return top + PANEL * (hi - v) / ((hi - lo) or 1.0)

    out = [f'<rect x="{x(a):.1f}" y="{top:.1f}" width="{x(b) - x(a):.1f}" height="{PANEL:.1f}" fill="#eeeeee"/>'
           for a, b, m in zip(edges[:-1], edges[1:], moving) if not m]
    for v in ticks:
        out.append(f'<line x1="{LEFT}" x2="{WIDTH - RIGHT}" y1="{y(v):.1f}" y2="{y(v):.1f}" stroke="{"#999" if v == 0 else "#e2e2e2"}"/>')
        out.append(f'<text x="{LEFT - 4}" y="{y(v) + 4:.1f}" text-anchor="end">{v:g}</text>')
    points = " ".join(f"{x(t):.1f},{y(v):.1f}" for a, b, v in zip(edges[:-1], edges[1:], values) for t in (a, b))
    out.append(f'<polyline points="{points}" fill="none" stroke="#1f5fbf" stroke-width="2"/>')
    out.append(f'<text x="12" y="{top + PANEL / 2:.1f}" transform="rotate(-90 12 {top + PANEL / 2:.1f})" text-anchor="middle">{escape(label)}</text>')
    return out


def load_cycle_svg(profile, duty: dict | None = None, torque_unit: str = "N*m") -> str:
    """The load cycle ``profile`` as an SVG text: mean output speed [rpm] above, output torque
    below (in ``torque_unit``), against time; pauses shaded; ``duty`` (the results' ``duty``
    section) gives the title's ED, cycle time and mode.

    >>> from calc import Q_
    >>> from calc.profile import Profile
    >>> p = Profile.from_segments([("const", Q_(1, "s"), Q_(100, "rpm"), Q_(10, "N*m")), ("pause", Q_(1, "s"), None, None)])
    >>> svg = load_cycle_svg(p)
    >>> svg.count("<polyline"), 'points="58.0,' in svg
    (2, True)
    """
    edges = np.concatenate([[0.0], np.cumsum(profile.durations.m_as("s"))])
    speeds = np.nan_to_num(profile.speeds.m_as("rpm"))
    torques = np.nan_to_num(profile.torques.m_as(torque_unit))
    moving = profile.moving
    title = "Load cycle (each segment at its mean speed)"
    if duty:
        title = (f"Load cycle: ED = {Q_(duty['ED']['value'], duty['ED']['unit']).m_as('percent'):.3g} %, "
                 f"cycle {duty['t_cycle']['value']:.3g} s, mode {duty['mode']}")
    body = [f'<text x="{LEFT}" y="16" font-weight="600">{escape(title)}</text>']
    body += _panel(edges, speeds, TOP, "n₂ [rpm]", moving)
    body += _panel(edges, torques, TOP + PANEL + GAP, f"T₂ [{pretty_unit(torque_unit)}]", moving)
    bottom = TOP + 2 * PANEL + GAP
    span_x = edges[-1] or 1.0
    for t in nice_ticks(0.0, float(edges[-1]), 6):
        if t <= span_x + 1e-9:
            px = LEFT + (WIDTH - LEFT - RIGHT) * t / span_x
            body.append(f'<text x="{px:.1f}" y="{bottom + 14:.1f}" text-anchor="middle">{t:g}</text>')
    body.append(f'<text x="{WIDTH - RIGHT}" y="{bottom + 27:.1f}" text-anchor="end">time t [s]; pauses shaded</text>')
    return (f'<svg class="dr-load-cycle" xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {WIDTH} {HEIGHT}" width="100%" '
            f'style="max-width:{WIDTH}px;font:11px sans-serif" role="img" aria-label="{escape(title)}">' + "".join(body) + "</svg>")
