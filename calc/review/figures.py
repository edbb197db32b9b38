"""The review's live figures, drawn by the browser: SVG texts of the load cycle's steps and of the
stiffness chain's shares.

The calc report and the notebooks draw them with matplotlib (:func:`calc.figures.plots.load_cycle_figure`,
:func:`calc.figures.accuracy_plots.stiffness_chain_figure`); the review redraws them on changes (the load
cycle on every change of a move, the mechanism or a segment; the chain on a change of ratio, part
or applied torque), and rendering such a figure to a PNG takes 0.2 to 0.4 s, most of a change's
time. Here the kernel writes SVG (some 2 KB, under a millisecond) and the browser draws it: the
same data (each segment's mean output speed and torque against time, the pauses shaded, ED and the
mode in the title; each member's share of the twist, its twist and stiffness at the output, from
the results, prepared once for both drawings), without the report figures' finer annotations.
"""

from __future__ import annotations

import math
from html import escape

import numpy as np

from ..core.units import pretty_unit

WIDTH, HEIGHT = 540, 300
LEFT, RIGHT, TOP, GAP, BOTTOM = 58, 10, 26, 22, 30
PANEL = (HEIGHT - TOP - GAP - BOTTOM) / 2


def nice_ticks(low: float, high: float, count: int = 4) -> list[float]:
    """Round tick values (1, 2 or 5 times a power of ten apart) covering ``low`` to ``high``.

    Parameters
    ----------
    low, high : float
        The range to cover [the axis' unit].
    count : int
        About how many steps the ticks take.

    Returns
    -------
    list of float
        The ticks, ascending, the first at or below ``low`` and the last at or above ``high``.

    Examples
    --------
    >>> nice_ticks(0, 300), nice_ticks(-45, 60)
    ([0.0, 100.0, 200.0, 300.0], [-50.0, 0.0, 50.0, 100.0])
    """
    span = (high - low) or abs(high) or 1.0
    raw = span / count
    power = 10.0 ** math.floor(math.log10(raw))
    step = next(m * power for m in (1, 2, 5, 10) if m * power >= raw)
    first = math.floor(low / step) * step
    return [round(first + k * step, 12) for k in range(int(math.ceil((high - first) / step - 1e-9)) + 1)]


def _svg(cls: str, height: float, label: str, body: list[str]) -> str:
    """A figure of the page: ``body`` in an SVG of the page's width and font, named ``label``."""
    return (f'<svg class="{cls}" xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {WIDTH} {height}" width="100%" '
            f'style="max-width:{WIDTH}px;font:11px sans-serif" role="img" aria-label="{escape(label)}">'
            + "".join(body) + "</svg>")


def _grid(ticks, y, stroke=lambda v: "#e2e2e2") -> list[str]:
    """A line across the plot and its value at each tick; ``y`` gives a value's height."""
    return [part for v in ticks for part in (
        f'<line x1="{LEFT}" x2="{WIDTH - RIGHT}" y1="{y(v):.1f}" y2="{y(v):.1f}" stroke="{stroke(v)}"/>',
        f'<text x="{LEFT - 4}" y="{y(v) + 4:.1f}" text-anchor="end">{v:g}</text>')]


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
    out += _grid(ticks, y, lambda v: "#999" if v == 0 else "#e2e2e2")
    points = " ".join(f"{x(t):.1f},{y(v):.1f}" for a, b, v in zip(edges[:-1], edges[1:], values) for t in (a, b))
    out.append(f'<polyline points="{points}" fill="none" stroke="#1f5fbf" stroke-width="2"/>')
    out.append(f'<text x="12" y="{top + PANEL / 2:.1f}" transform="rotate(-90 12 {top + PANEL / 2:.1f})" '
               f'text-anchor="middle">{escape(label)}</text>')
    return out


def load_cycle_svg(profile, duty=None, torque_unit: str = "N*m") -> str:
    """The load cycle ``profile`` as an SVG text: mean output speed [rpm] above, output torque
    below (in ``torque_unit``), against time; pauses shaded.

    Parameters
    ----------
    profile : calc.domain.profile.Profile
        The load cycle.
    duty : calc.sections.duty.DutyValues, optional
        The load cycle's values: the title's ED, cycle time and mode.
    torque_unit : str
        The unit of the torque's axis (``"N*m"``, ``"lbf*in"``).

    Returns
    -------
    str
        The SVG (class ``dr-load-cycle``).

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.domain.profile import Profile
    >>> p = Profile.from_segments([("const", Q_(1, "s"), Q_(100, "rpm"), Q_(10, "N*m")),
    ...                            ("pause", Q_(1, "s"), None, None)])
    >>> svg = load_cycle_svg(p)
    >>> svg.count("<polyline"), 'points="58.0,' in svg
    (2, True)
    """
    edges = np.concatenate([[0.0], np.cumsum(profile.durations.m_as("s"))])
    speeds = np.nan_to_num(profile.speeds.m_as("rpm"))
    torques = np.nan_to_num(profile.torques.m_as(torque_unit))
    moving = profile.moving
    title = "Load cycle (each segment at its mean speed)"
    if duty is not None:
        title = (f"Load cycle: ED = {duty.ED.quantity.m_as('percent'):.3g} %, "
                 f"cycle {duty.t_cycle.quantity.m_as('s'):.3g} s, mode {duty.mode}")
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
    return _svg("dr-load-cycle", HEIGHT, title, body)


def stiffness_chain_svg(accuracy) -> str:
    """Each member's share of the chain's twist at the output, as horizontal bars labelled with its
    twist and stiffness at the output: the bars and labels of
    :func:`calc.figures.accuracy_plots.stiffness_chain_figure` (both from
    :func:`calc.figures.accuracy_plots.stiffness_chain_bars`), drawn by the browser.

    Parameters
    ----------
    accuracy : calc.sections.accuracy.AccuracyValues
        The chain's accuracy (E11): its members, applied torque and total stiffness.

    Returns
    -------
    str
        The SVG (class ``dr-chain``).

    Examples
    --------
    >>> from calc.sections.case import read_case
    >>> from calc.data.catalog import CATALOG_DIR
    >>> from calc.sections import evaluate
    >>> a = evaluate(read_case(CATALOG_DIR.parent / "cases" / "indexing-table.toml")).sections["accuracy"].shown
    >>> svg = stiffness_chain_svg(a)
    >>> svg.count("<rect"), [m.name for m in a.members]
    (2, ['AKN-18', 'NPT035-10'])
    """
    from ..figures.accuracy_plots import SIDE_COLORS, stiffness_chain_bars  # the report figure's colours and data

    data = stiffness_chain_bars(accuracy)
    row, left, top = 30, 130, 24
    height = top + row * len(data.bars) + 34
    scale = (WIDTH - left - 10) / 110  # 0 to 110 %
    title = data.title("C_total", ratio=False)
    body = [f'<text x="0" y="14" font-weight="600">{escape(title)}</text>']
    for share in range(0, 101, 20):
        x = left + scale * share
        body.append(f'<line x1="{x:.1f}" x2="{x:.1f}" y1="{top}" y2="{height - 30}" stroke="#e2e2e2"/>')
        body.append(f'<text x="{x:.1f}" y="{height - 18}" text-anchor="middle">{share}</text>')
    for k, b in enumerate(data.bars):
        y, end = top + row * k + 5, left + scale * b.share
        body += [f'<rect x="{left}" y="{y}" width="{scale * b.share:.1f}" height="{row - 10}" '
                 f'fill="{SIDE_COLORS.get(b.side, "#888")}"/>',
                 f'<text x="{left - 6}" y="{y + 9}" text-anchor="end">{escape(b.name)}</text>',
                 f'<text x="{left - 6}" y="{y + 20}" text-anchor="end" fill="#666">({escape(b.side)} side)</text>',
                 # beside a short bar, inside a long one (so it stays in the figure)
                 f'<text x="{end + 4:.1f}" y="{y + 14}">{escape(b.label)}</text>' if b.share < 50 else
                 f'<text x="{end - 4:.1f}" y="{y + 14}" text-anchor="end" '
                 f'fill="#fff">{escape(b.label)}</text>']
    body.append(f'<text x="{left}" y="{height - 4}">'
                "share of the twist at the output [%]; input side purple, output side blue</text>")
    return _svg("dr-chain", height, title, body)


#: A part's colour in the comparison of variants.
PART_COLORS = {"gearbox": "#1f5fbf", "coupling": "#7b3fa0", "motor": "#2e7d32"}


def comparison_svg(names: list[str], worst: dict) -> str:
    """The variants' worst governing utilization of each part as grouped bars, one group per
    variant, with the limit of 100 % in red and a value over it written in red.

    Parameters
    ----------
    names : list of str
        The variants' names, one group of bars each.
    worst : dict
        Part -> its worst governing utilization [%] in each variant, None where it has none
        (:func:`calc.review.view.worst_utilizations`).

    Returns
    -------
    str
        The SVG (class ``dr-compared``).

    Examples
    --------
    >>> worst = {"gearbox": [32.0, 120.0], "coupling": [67.0, None], "motor": [94.0, 94.0]}
    >>> svg = comparison_svg(["1", "2"], worst)
    >>> svg.count("<rect"), svg.count('fill="#b2222a">120 %')  # five bars (no coupling in 2) and three keys; one over
    (8, 1)
    """
    parts = list(worst)
    known = [v for u in worst.values() for v in u if v is not None]
    ticks = nice_ticks(0.0, max([100.0, *known]))
    height, bottom, top = 210, 40, 34
    plot = height - bottom - top
    scale = plot / ticks[-1]
    step = (WIDTH - LEFT - RIGHT) / max(len(names), 1)
    bar = step * 0.8 / len(parts)
    body = ['<text x="0" y="14" font-weight="600">Worst governing utilization of each variant\'s parts [%]</text>']
    body += _grid(ticks, lambda t: height - bottom - scale * t, lambda t: "#b2222a" if t == 100 else "#e2e2e2")
    for k, name in enumerate(names):
        x0 = LEFT + step * k + step * 0.1
        for j, part in enumerate(parts):
            v = worst[part][k]
            if v is None:
                continue
            x, h = x0 + bar * j, scale * v
            over = ' fill="#b2222a"' if v > 100 else ""
            body += [f'<rect x="{x:.1f}" y="{height - bottom - h:.1f}" width="{bar * 0.9:.1f}" height="{h:.1f}" '
                     f'fill="{PART_COLORS.get(part, "#888")}"/>',
                     f'<text x="{x + bar * 0.45:.1f}" y="{height - bottom - h - 3:.1f}" text-anchor="middle" '
                     f'font-size="9"{over}>{v:.0f} %</text>']
        body.append(f'<text x="{x0 + step * 0.4:.1f}" y="{height - bottom + 14}" text-anchor="middle">'
                    f'variant {escape(name)}</text>')
    # the key
    body += [f'<rect x="{LEFT + 90 * j}" y="{height - 14}" width="10" height="10" fill="{PART_COLORS.get(p, "#888")}"/>'
             f'<text x="{LEFT + 90 * j + 14}" y="{height - 5}">{escape(p)}</text>' for j, p in enumerate(parts)]
    return _svg("dr-compared", height, "worst utilization of each variant", body)


def ratio_search_svg(found: dict) -> str:
    """The ratio search as bars: each ratio's RMS motor torque through its best gearbox, green
    where the ratio is feasible and keeps λ within its limit (as the search records it), light
    green where it is feasible with λ over it, grey where it is not feasible; the pick outlined; λ
    above each bar. The data of
    :func:`calc.figures.motor_plots.ratio_figure`, drawn by the browser.

    Parameters
    ----------
    found : dict
        The ratio search's JSON (:func:`calc.sections.ratios.search`, ``to_json()``): its ratios
        (each with λ and whether it is within the limit), the inertia ratio's limit and the pick.

    Returns
    -------
    str
        The SVG (class ``dr-ratios``).

    Examples
    --------
    >>> from calc.sections.case import read_case
    >>> from calc.data.catalog import CATALOG_DIR
    >>> from calc.sections.ratios import search
    >>> svg = ratio_search_svg(search(read_case(CATALOG_DIR.parent / "cases" / "indexing-table.toml")).to_json())
    >>> svg.count("<rect"), svg.count('stroke-width="2.5"')  # six ratios, the pick outlined
    (6, 1)
    """
    rows, limit = found["ratios"], found["inertia_ratio_limit"]
    pick = None if found["pick"] is None else found["pick"]["ratio"]
    rms = [r["rms_torque_required"]["value"] if r["rms_torque_required"] else None for r in rows]
    unit = next((r["rms_torque_required"]["unit"] for r in rows if r["rms_torque_required"]), "N*m")
    known = [v for v in rms if v is not None]
    top_value = max(known) if known else 1.0
    ticks = nice_ticks(0.0, top_value)
    height, bottom, top = 220, 40, 34
    plot = height - bottom - top
    scale = plot / ticks[-1] if ticks[-1] > 0 else 1.0
    step = (WIDTH - LEFT - RIGHT) / max(len(rows), 1)
    title = f"RMS motor torque at each ratio, its best gearbox; λ above (limit {limit:g})"
    body = [f'<text x="0" y="14" font-weight="600">{escape(title)}</text>']
    body += _grid(ticks, lambda t: height - bottom - scale * t)
    middle = height - bottom - plot / 2
    body.append(f'<text x="12" y="{middle:.0f}" transform="rotate(-90 12 {middle:.0f})" '
                f'text-anchor="middle">{escape(pretty_unit(unit))}</text>')
    for k, (r, v) in enumerate(zip(rows, rms)):
        x = LEFT + step * k + step * 0.2
        lam = r["inertia_ratio"]
        within = r["inertia_ratio_within_limit"] is True
        fill = "#2e7d32" if r["passes"] and within else ("#a5d6a7" if r["passes"] else "#bdbdbd")
        h = 0.0 if v is None else scale * v
        outline = ' stroke="#000" stroke-width="2.5"' if r["ratio"] == pick else ""
        over = "" if within else ' fill="#b2222a"'  # λ over its limit, in red
        lam_text = "–" if lam is None else f"{lam:.3g}"
        mid = x + step * 0.3
        body += [f'<rect x="{x:.1f}" y="{height - bottom - h:.1f}" width="{step * 0.6:.1f}" height="{h:.1f}" '
                 f'fill="{fill}"{outline}/>',
                 f'<text x="{mid:.1f}" y="{height - bottom + 14}" text-anchor="middle">{r["ratio"]:g}</text>',
                 f'<text x="{mid:.1f}" y="{height - bottom + 27}" text-anchor="middle" fill="#666">'
                 f'{escape(r["part"])}</text>',
                 f'<text x="{mid:.1f}" y="{height - bottom - h - 4:.1f}" text-anchor="middle"{over}>'
                 f'λ {lam_text}</text>']
    return _svg("dr-ratios", height, title, body)
