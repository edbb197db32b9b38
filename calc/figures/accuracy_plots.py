"""Figures of drive-train accuracy: the hysteresis loop, the stiffness chain, the transmission error
and the accuracy/repeatability targets.

The source's figures of these (the hysteresis curves, the measurement of angular transmission
accuracy, the three targets) were lost; these draw them from data. Like :mod:`calc.figures.plots`, each
function returns a :class:`matplotlib.figure.Figure` built without pyplot, imports matplotlib
inside, and is deterministic (fixed sizes and colours; random pictures take a seed).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..domain.accuracy import PositioningScatter, low_torque_limit, lost_motion, positioning_accuracy
from ..core.checks import BOUNDARY_RTOL
from ..core.glossary import latex as symbol_latex
from ..core.glossary import math as symbol
from ..domain.hysteresis import LOW_TORQUE_SHARE, STIFFNESS_BAND, Loop, LoopAnalysis
from ..domain.stiffness import Chain
from ..domain.transmission import TransmissionAnalysis
from ..core.units import Q_, as_kind, fmt, sig

LOOP_COLOR = "#1f5fa8"
FIT_COLOR = "#b2222a"
BAND_COLOR = "#d7e6f5"
LOW_BAND_COLOR = "#fbe3c6"
MARK_COLOR = "#d95f02"
SIDE_COLORS = {"input": "#8e5ba8", "output": "#1f5fa8"}
DIRECTION_COLORS = {"forward": "#1f5fa8", "backward": "#5a9e3a"}

#: The source's three target pictures: (title, offset of the mean, spread), in units of the ring spacing.
TARGETS = (
    ("Poor positioning accuracy,\npoor repeatability", (1.6, 1.1), 0.9),
    ("Poor positioning accuracy,\ngood repeatability", (1.9, -1.2), 0.18),
    ("Good positioning accuracy,\ngood repeatability", (0.05, 0.05), 0.18),
)


def _double_arrow(ax, x, y0, y1, text, color, side="right", fontsize=8):
    ax.annotate("", (x, y1), (x, y0), arrowprops=dict(arrowstyle="<->", color=color, lw=1.4, shrinkA=0, shrinkB=0))
    ax.annotate(
        text, (x, 0.5 * (y0 + y1)), xytext=(6 if side == "right" else -6, 0), textcoords="offset points",
        ha="left" if side == "right" else "right", va="center", fontsize=fontsize, color=color,
    )


def hysteresis_figure(loop: Loop, analysis: LoopAnalysis):
    """The loop, whole and in detail around zero, with what E12 reads from it.

    Left: the whole loop with the 50 % to 100 % bands shaded and the fitted stiffness lines.
    Right: the detail of ±3 % of the nominal torque (the source's second figure), with the
    backlash (width at 0 N·m) and the lost motion (width over the ±3 % band) marked.

    Parameters
    ----------
    loop : Loop
        The measured or modelled loop.
    analysis : LoopAnalysis
        What :func:`calc.domain.hysteresis.analyze_loop` reads from it.

    Returns
    -------
    matplotlib.figure.Figure
        Two axes: the whole loop and the detail around zero.

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.domain.hysteresis import LoopModel, analyze_loop
    >>> loop = LoopModel(Q_(23, "N*m/arcmin"), Q_(3, "arcmin"), Q_(81, "N*m")).loop(800)
    >>> [ax.get_xlabel() for ax in hysteresis_figure(loop, analyze_loop(loop, Q_(81, "N*m"))).axes]
    ['torque at the output $T$ [N·m]', 'torque at the output $T$ [N·m]']
    """
    from matplotlib.figure import Figure
    from matplotlib.patches import Patch

    t = loop.torque.m_as("N*m")
    phi = loop.twist.m_as("arcmin")
    t_n = analysis.nominal_torque.m_as("N*m")
    edge = LOW_TORQUE_SHARE * t_n
    lo, hi = (x * t_n for x in STIFFNESS_BAND)
    zero = analysis.backlash_range.m_as("arcmin")
    band = analysis.lost_motion_range.m_as("arcmin")

    fig = Figure(figsize=(10.0, 5.0), layout="constrained")
    ax, detail = fig.subplots(1, 2, gridspec_kw={"width_ratios": (1.25, 1)})
    for a in (ax, detail):
        a.axvspan(-edge, edge, color=LOW_BAND_COLOR, linewidth=0, zorder=0)
        a.axhline(0, color="black", linewidth=0.6, zorder=1)
        a.axvline(0, color="black", linewidth=0.6, zorder=1)
        a.set_xlabel("torque at the output $T$ [N·m]")
        a.grid(True, color="#dddddd", linewidth=0.6, zorder=0)
    for a, b in ((lo, hi), (-hi, -lo)):
        ax.axvspan(a, b, color=BAND_COLOR, linewidth=0, zorder=0)
    ax.plot(t, phi, color=LOOP_COLOR, linewidth=0.9, zorder=2)
    for fit, sign, stiff in ((analysis.fit_positive, 1, analysis.stiffness_positive),
                             (analysis.fit_negative, -1, analysis.stiffness_negative)):
        ft, fp = fit.torque.m_as("N*m"), fit.twist.m_as("arcmin")
        ax.plot(ft, fp, color=FIT_COLOR, linewidth=2.4, zorder=3)
        ax.annotate(
            f"{symbol('C_t')} = {fmt(stiff, 'N*m/arcmin', 4)}\n({fit.samples} loading samples)", (ft.mean(), fp.mean()),
            xytext=(0, -22 * sign),
            textcoords="offset points", ha="center", va="top" if sign > 0 else "bottom", fontsize=8, color=FIT_COLOR,
        )
    ax.set_ylabel("twist at the output $\\varphi$ [arcmin]")
    ax.set_xlim(-1.08 * t_n, 1.08 * t_n)
    ax.set_title(f"Hysteresis loop to ±{fmt(analysis.nominal_torque, 'N*m')} (nominal torque {symbol('T_N')})",
                 fontsize=9)

    near = np.abs(t) <= 2.5 * edge
    detail.plot(t[near], phi[near], ".", color=LOOP_COLOR, markersize=2.5, zorder=2)
    detail.plot(t, phi, color=LOOP_COLOR, linewidth=0.6, alpha=0.6, zorder=2)
    detail.set_xlim(-2.5 * edge, 2.5 * edge)
    pad = 0.25 * (band[1] - band[0])
    detail.set_ylim(band[0] - pad, band[1] + pad)
    for y in band:
        detail.hlines(y, -edge, edge, color=MARK_COLOR, linewidth=0.9, linestyles="--", zorder=3)
    for y in zero:
        detail.plot([0], [y], "o", color=FIT_COLOR, markersize=5, zorder=4)
    _double_arrow(detail, 0.0, zero[0], zero[1], f"backlash {symbol('j_t')}\n= {fmt(analysis.backlash, 'arcmin', 3)}",
                  FIT_COLOR, side="left")
    _double_arrow(detail, edge, band[0], band[1],
                  f"lost motion\n(±3 % {symbol('T_N')})\n= {fmt(analysis.lost_motion, 'arcmin', 3)}", MARK_COLOR)
    detail.set_title("Detail of ±3 % of nominal torque", fontsize=9)

    fig.suptitle(f"Torsional stiffness, backlash and lost motion from a hysteresis loop (E12) - {analysis.source}",
                 fontsize=10)
    fig.legend(
        handles=[
            Patch(color=BAND_COLOR, label=f"50 % to 100 % of {symbol('T_N')}: stiffness is the slope here"),
            Patch(color=LOW_BAND_COLOR, label=f"±3 % of {symbol('T_N')}: lost motion is the width here"),
        ],
        loc="outside lower center", ncols=2, fontsize=8, frameon=False,
    )
    return fig


@dataclass(frozen=True)
class ChainBar:
    """One member's bar of the stiffness chain.

    Parameters
    ----------
    name : str
        The member's name.
    side : str
        ``input`` or ``output`` side of the gearbox.
    share : float
        Its share of the chain's twist at the output [%].
    label : str
        What the bar says: share, twist and stiffness at the output, or that its stiffness is unknown.
    """

    name: str
    side: str
    share: float
    label: str


@dataclass(frozen=True)
class ChainBars:
    """The stiffness-chain figure's data, as the PDF's figure and the review's SVG both draw it.

    Parameters
    ----------
    torque : str
        The applied torque at the output, with its unit.
    relation : str
        ``≤`` where a member's stiffness is unknown (reckoned rigid: the chain's is an upper bound), else ``=``.
    stiffness : str
        ``C_total`` at the output, with its unit.
    twist : str
        The chain's twist at the applied torque [arcmin], without its unit.
    ratio : str or None
        The gearbox ratio the input side is referred through; None without one.
    bars : tuple of ChainBar
        The members, drive to load.
    """

    torque: str
    relation: str
    stiffness: str
    twist: str
    ratio: str | None
    bars: tuple

    def title(self, c_total: str, ratio: bool = True) -> str:
        """The figure's title.

        Parameters
        ----------
        c_total : str
            The symbol of the chain's stiffness as the drawing writes it (mathtext or plain).
        ratio : bool
            Whether to say how the input side is referred to the output.

        Returns
        -------
        str
            ``Stiffness chain at …: C_total = …, twist … arcmin (E11…)``.
        """
        referred = f", input side × i² with i = {self.ratio}" if ratio and self.ratio is not None else ""
        return (f"Stiffness chain at {self.torque}: {c_total} {self.relation} {self.stiffness}, "
                f"twist {self.twist} arcmin (E11{referred})")


def stiffness_chain_bars(accuracy) -> ChainBars:
    """The stiffness-chain figure's data from the chain's recorded values (E11): each member's share
    of the compliance ``1/C`` (every member carries the same torque, so its share of the twist), its
    twist and its stiffness referred to the output.

    Parameters
    ----------
    accuracy : calc.sections.accuracy.AccuracyValues or calc.sections.accuracy.ChainValues
        The chain's values as recorded: ``applied_torque`` [N·m], ``ratio``, ``C_total``
        [N·m/arcmin] and the ``members`` with their ``share_of_compliance``,
        ``twist_at_applied_torque`` [arcmin] and ``stiffness_at_output`` [N·m/arcmin] (no value
        where unknown).

    Returns
    -------
    ChainBars
        The bars, their labels and the title's values.

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.domain.stiffness import Chain, Component
    >>> from calc.sections.accuracy import chain_values
    >>> c = Chain((Component("coupling", "output", Q_(0.24, "N*m/arcmin"), Q_(0, "arcmin")),
    ...            Component("gearbox", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin"))))
    >>> [b.label for b in stiffness_chain_bars(chain_values(c, Q_(20, "N*m"))).bars]
    ['84.4 %: 83.3 arcmin, C = 0.24 N·m/arcmin', '15.6 %: 15.4 arcmin, C = 1.3 N·m/arcmin']
    """
    members = accuracy.members
    twist = np.array([m.twist_at_applied_torque.quantity.m_as("arcmin") for m in members])
    bars = tuple(
        ChainBar(m.name, m.side, 100 * m.share_of_compliance,
                 f"{sig(100 * m.share_of_compliance, 3)} %: {sig(t, 3)} arcmin, C = {m.stiffness_at_output}"
                 if m.stiffness_at_output.value is not None else "C unknown: reckoned rigid, so the twist is more")
        for m, t in zip(members, twist))
    unknown = any(m.stiffness_at_output.value is None for m in members)
    return ChainBars(str(accuracy.applied_torque), "≤" if unknown else "=", str(accuracy.C_total),
                     sig(np.nansum(twist), 3), None if accuracy.ratio is None else sig(accuracy.ratio), bars)


def stiffness_chain_figure(accuracy):
    """Each member's share of the twist at the output, as horizontal bars (E11), drawn from
    :func:`stiffness_chain_bars`: each bar labelled with its twist under the applied torque and its
    stiffness referred to the output.

    Parameters
    ----------
    accuracy : calc.sections.accuracy.AccuracyValues or calc.sections.accuracy.ChainValues
        The chain's values as recorded (a case's :attr:`calc.sections.accuracy.AccuracyResult.shown`,
        or :func:`calc.sections.accuracy.chain_values` of a chain).

    Returns
    -------
    matplotlib.figure.Figure
        One axes of horizontal bars.

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.domain.stiffness import Chain, Component
    >>> from calc.sections.accuracy import chain_values
    >>> gearbox = Chain((Component("gearbox", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin")),))
    >>> ax = stiffness_chain_figure(chain_values(gearbox, Q_(20, "N*m"))).axes[0]
    >>> ax.get_xlabel(), [t.get_text() for t in ax.texts]
    ('share of the twist at the output [%]', ['100 %: 15.4 arcmin, C = 1.3 N·m/arcmin'])
    """
    from matplotlib.figure import Figure
    from matplotlib.patches import Patch

    data = stiffness_chain_bars(accuracy)
    bars = data.bars
    y = np.arange(len(bars))[::-1]
    fig = Figure(figsize=(8.0, 1.6 + 0.55 * len(bars)), layout="constrained")
    ax = fig.subplots()
    ax.barh(y, [b.share for b in bars], color=[SIDE_COLORS[b.side] for b in bars], height=0.6, zorder=2)
    for b, at in zip(bars, y):
        ax.annotate(b.label, (b.share, at), xytext=(4, 0), textcoords="offset points", va="center", fontsize=8)
    ax.set_yticks(y, [f"{b.name}\n({b.side} side)" for b in bars], fontsize=8)
    ax.set_xlim(0, 160)
    ax.set_xticks(np.arange(0, 101, 20))
    ax.set_xlabel("share of the twist at the output [%]")
    ax.grid(True, axis="x", color="#dddddd", linewidth=0.6, zorder=0)
    ax.set_title(data.title(symbol("C_total")), fontsize=9)
    fig.legend(handles=[Patch(color=v, label=f"{k} side of the gearbox") for k, v in SIDE_COLORS.items()],
               loc="outside lower center", ncols=2, fontsize=8, frameon=False)
    return fig


def transmission_error_figure(analysis: TransmissionAnalysis):
    r"""Transmission error against the output position over one revolution, each direction, with
    the range that is the angular transmission accuracy.

    Parameters
    ----------
    analysis : TransmissionAnalysis
        The trace's error and ranges.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.domain.transmission import analyze_trace, generate_trace
    >>> a = analyze_trace(generate_trace(Q_(10, ""), Q_(40, "arcsec")), Q_(10, ""))
    >>> transmission_error_figure(a).axes[0].get_ylabel()
    'transmission error $\\Delta\\varphi_2$ [arcsec]'
    """
    from matplotlib.figure import Figure

    out = analysis.output.m_as("deg")
    err = analysis.error.m_as("arcsec")
    fig = Figure(figsize=(9.0, 4.4), layout="constrained")
    ax = fig.subplots()
    start = out.min()
    for sign, name in ((1, "forward"), (-1, "backward")):
        mask = analysis.direction == sign
        if name not in analysis.ranges:
            continue
        lo, hi = analysis.ranges[name].m_as("arcsec")
        ax.plot(out[mask] - start, err[mask], color=DIRECTION_COLORS[name], linewidth=0.9,
                label=f"{name}: range {sig(hi - lo, 3)} arcsec")
    lo, hi = analysis.ranges[analysis.governing].m_as("arcsec")
    ax.axhspan(lo, hi, color=BAND_COLOR, zorder=0, linewidth=0)
    for v in (lo, hi):
        ax.axhline(v, color=FIT_COLOR, linewidth=0.9, linestyle="--")
    _double_arrow(ax, 368.0, lo, hi, f"{symbol('phi_TA')} = {fmt(analysis.accuracy, 'arcsec', 3)}", FIT_COLOR)
    ax.set_xlim(0, 450)
    ax.set_xticks(np.arange(0, 361, 45))
    ax.set_xlabel("output position from the start of the record [°]")
    ax.set_ylabel("transmission error $\\Delta\\varphi_2$ [arcsec]")
    ax.grid(True, color="#dddddd", linewidth=0.6)
    fig.legend(loc="outside lower center", ncols=2, fontsize=8, frameon=False)
    ax.set_title(
        "Angular transmission accuracy: range of $\\varphi_2 - \\varphi_1 / i$ over one output revolution, "
        f"without load ({analysis.governing} governs)",
        fontsize=9,
    )
    return fig


def target_points(offset, spread: float, count: int = 12, seed: int = 0) -> np.ndarray:
    """Seeded hits around a target.

    Parameters
    ----------
    offset : sequence of float
        The mean ``(x, y)`` of the hits.
    spread : float
        The standard deviation of each coordinate.
    count : int
        How many points; default 12.
    seed : int
        Seed of the random generator; default 0.

    Returns
    -------
    numpy.ndarray
        ``count`` rows of ``(x, y)``.
    """
    rng = np.random.default_rng(seed)
    return np.asarray(offset, float) + rng.normal(0.0, spread, (count, 2))


def accuracy_targets_figure(seed: int = 0):
    """The source's three target pictures, drawn from seeded data.

    Accuracy is how close the actual positions (✦) come to the required one (●); repeatability
    is how close they come to each other. Poor/poor: scattered and off; poor/good: tight but
    off; good/good: tight and on.

    Parameters
    ----------
    seed : int
        Seed of the hits; default 0.

    Returns
    -------
    matplotlib.figure.Figure
        Three axes, one per target.

    Examples
    --------
    >>> [a.get_title().splitlines()[0] for a in accuracy_targets_figure().axes]
    ['Poor positioning accuracy,', 'Poor positioning accuracy,', 'Good positioning accuracy,']
    """
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    fig = Figure(figsize=(10.0, 3.9), layout="constrained")
    axes = fig.subplots(1, 3)
    for k, (ax, (title, offset, spread)) in enumerate(zip(axes, TARGETS)):
        for r, shade in zip((4, 3, 2, 1), ("#f2f2f2", "#e2e2e2", "#d0d0d0", "#bdbdbd")):
            ax.add_patch(_circle(r, shade))
        pts = target_points(offset, spread, seed=seed + k)
        ax.plot([0], [0], "o", color="black", markersize=6, markeredgecolor="white", zorder=5)
        ax.plot(pts[:, 0], pts[:, 1], "*", color=MARK_COLOR, markersize=9, markeredgecolor="white", markeredgewidth=0.4,
                zorder=4)
        ax.set_xlim(-4.3, 4.3)
        ax.set_ylim(-4.3, 4.3)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(title, fontsize=9)
    fig.legend(
        handles=[
            Line2D([], [], marker="o", color="black", linestyle="", label="required position"),
            Line2D([], [], marker="*", color=MARK_COLOR, linestyle="", markersize=10, label="actual position"),
        ],
        loc="outside lower center", ncols=2, fontsize=8, frameon=False,
    )
    fig.suptitle(f"Accuracy and repeatability (seeded data, seed {seed})", fontsize=10)
    return fig


def _circle(radius, color):
    from matplotlib.patches import Circle

    return Circle((0, 0), radius, facecolor=color, edgecolor="white", linewidth=1.0, zorder=1)


def positioning_scatter_figure(scatter: PositioningScatter):
    r"""A measured positioning record: each approach's error at its target, with the measured
    accuracy (largest error) and repeatability (largest spread at one target) marked.

    Parameters
    ----------
    scatter : PositioningScatter
        The measured record.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.domain.accuracy import analyze_positions
    >>> s = analyze_positions(Q_([0, 0, 90, 90], "deg"), Q_([0.01, 0.02, 90.01, 90.03], "deg"))
    >>> positioning_scatter_figure(s).axes[0].get_ylabel()
    'positioning error $\\Delta\\varphi$ [arcmin]'
    """
    from matplotlib.figure import Figure

    target = scatter.target.m_as("deg")
    err = scatter.error.m_as("arcmin")
    keys, g = np.unique(target, return_inverse=True)
    fig = Figure(figsize=(8.0, 4.2), layout="constrained")
    ax = fig.subplots()
    a = scatter.accuracy.m_as("arcmin")
    ax.axhspan(-a, a, color=BAND_COLOR, linewidth=0, zorder=0,
               label=f"accuracy: largest |error| {fmt(scatter.accuracy, 'arcmin', 3)}")
    ax.axhline(0, color="black", linewidth=0.8)
    ax.plot(g, err, "*", color=MARK_COLOR, markersize=8, zorder=3, label="actual - target, each approach")
    low = np.full(len(keys), np.inf)
    high = np.full(len(keys), -np.inf)
    np.minimum.at(low, g, err)
    np.maximum.at(high, g, err)
    worst = int(np.argmax(high - low))
    ax.vlines(np.arange(len(keys)), low, high, color=FIT_COLOR, linewidth=1.2, zorder=2)
    ax.annotate(
        f"repeatability {fmt(scatter.repeatability, 'arcmin', 3)}", (worst, high[worst]), xytext=(6, 6),
        textcoords="offset points", fontsize=8, color=FIT_COLOR,
    )
    ax.set_xticks(np.arange(len(keys)), [f"{sig(k)}°" for k in keys], fontsize=8)
    ax.set_xlabel("target position")
    ax.set_ylabel("positioning error $\\Delta\\varphi$ [arcmin]")
    ax.grid(True, axis="y", color="#dddddd", linewidth=0.6)
    ax.set_ylim(min(-1.2 * a, 1.2 * err.min()), max(1.2 * a, 1.2 * err.max()))
    fig.legend(loc="outside lower center", ncols=2, fontsize=8, frameon=False)
    ax.set_title(f"Measured positioning: {len(err)} approaches to {scatter.targets} targets - {scatter.source}",
                 fontsize=9)
    return fig


def positioning_rule_figure(chain: Chain, nominal_torque=None, applied_torque=None):
    """Positioning accuracy by the 3 % rule and the repeatability bound against the applied torque.

    Up to 3 % of the nominal torque the backlash counts (``φ_TA + j_t``); above, the twist does
    (``φ_TA + |T| / C``), as the source writes it (E13), so the curve jumps at 3 %. Repeatability is
    the backlash at rest and at most the lost motion ``j_t + |T| / C`` under torque.

    Parameters
    ----------
    chain : Chain
        The members, drive to load.
    nominal_torque : pint.Quantity [N·m], optional
        ``T_N``; default the chain's.
    applied_torque : pint.Quantity [N·m], optional
        The case's torque, marked on the curves.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.domain.stiffness import Component
    >>> c = Chain((Component("gearbox", "output", Q_(22, "N*m/arcmin"), Q_(8, "arcmin"), Q_(63, "arcsec"),
    ...                      Q_(110, "N*m")),))
    >>> positioning_rule_figure(c, applied_torque=Q_(8, "N*m")).axes[0].get_xlabel()
    'applied torque at the output $|T|$ [N·m]'
    """
    from matplotlib.figure import Figure

    t_n = chain.nominal_torque if nominal_torque is None else as_kind(nominal_torque, "torque", "nominal_torque")
    edge = low_torque_limit(t_n).m_as("N*m")
    past = np.nextafter(edge * (1 + BOUNDARY_RTOL), np.inf)  # the first torque the rule puts above 3 %
    torque = np.union1d(np.linspace(0.0, t_n.m_as("N*m"), 400), [edge, past])
    stiffness = chain.stiffness_at(Q_(torque, "N*m"))  # the secant at each torque where a member gives a curve
    args = dict(transmission_accuracy=chain.transmission_accuracy, backlash=chain.backlash, stiffness=stiffness)
    acc = positioning_accuracy(Q_(torque, "N*m"), t_n, **args).m_as("arcmin")
    bound = lost_motion(j_t=chain.backlash, T=Q_(torque, "N*m"), C=stiffness).m_as("arcmin")
    fig = Figure(figsize=(8.0, 4.4), layout="constrained")
    ax = fig.subplots()
    low = f"|T| <= 3 % of {symbol('T_N')} ({sig(edge, 3)} N·m): ${symbol_latex('phi_TA')} + {symbol_latex('j_t')}$"
    ax.axvspan(0, edge, color=LOW_BAND_COLOR, linewidth=0, zorder=0, label=low)
    ax.plot(torque, acc, color=FIT_COLOR, linewidth=2.0, label="positioning accuracy (E13)")
    ax.plot(torque, bound, color=LOOP_COLOR, linewidth=1.4, linestyle="--",
            label=f"repeatability at most: lost motion ${symbol_latex('j_t')} + |T|/C$")
    if applied_torque is not None:
        t = abs(as_kind(applied_torque, "torque", "applied_torque").m_as("N*m"))
        a = positioning_accuracy(Q_(t, "N*m"), t_n,
                                 **{**args, "stiffness": chain.stiffness_at(Q_(t, "N*m"))}).m_as("arcmin")
        ax.plot([t], [a], "o", color=MARK_COLOR, zorder=4, label=f"the case: {sig(t, 3)} N·m -> {sig(a, 3)} arcmin")
    ax.set_xlim(0, t_n.m_as("N*m"))
    ax.set_ylim(0, None)
    ax.set_xlabel("applied torque at the output $|T|$ [N·m]")
    ax.set_ylabel("angle at the output [arcmin]")
    ax.grid(True, color="#dddddd", linewidth=0.6)
    fig.legend(loc="outside lower center", ncols=2, fontsize=8, frameon=False)
    ax.set_title(
        "Positioning accuracy and repeatability against torque (E13)\n"
        f"{symbol('phi_TA')} = {fmt(chain.transmission_accuracy, 'arcmin', 3)}, "
        f"{symbol('j_t')} = {fmt(chain.backlash, 'arcmin', 3)}, "
        + ("C: the secant of the stiffness curves at each torque" if chain.has_curves
           else f"C = {fmt(chain.stiffness, 'N*m/arcmin', 4)}")
        + f", {symbol('T_N')} = {fmt(t_n, 'N*m')}",
        fontsize=9,
    )
    return fig


def budget_figure(budget: dict):
    """The error budget as horizontal bars: each contribution (systematic dark, random light), then
    the worst case and the root-sum-square.

    Parameters
    ----------
    budget : dict
        ``accuracy.budget`` as the results write it (:meth:`calc.sections.accuracy.AccuracyResult.budget_json`).

    Returns
    -------
    matplotlib.figure.Figure
        One axes.

    Examples
    --------
    >>> b = {"contributions": [{"name": "φ_TA", "kind": "systematic", "value": {"value": 1.0}},
    ...                        {"name": "twist", "kind": "random", "value": {"value": 0.4}}],
    ...      "worst_case": {"value": 1.4}, "rss": {"value": 1.077}, "convention": "full width"}
    >>> [round(float(p.get_width()), 3) for p in budget_figure(b).axes[0].patches]
    [1.0, 0.4, 1.4, 1.077]
    """
    from matplotlib.figure import Figure

    parts = budget["contributions"]
    labels = [f"{c['name']} ({c['kind']})" for c in parts] + ["worst case", "root-sum-square"]
    widths = [c["value"]["value"] for c in parts] + [budget["worst_case"]["value"], budget["rss"]["value"]]
    colors = ["#1f5fa8" if c["kind"] == "systematic" else "#9ecae1" for c in parts] + ["#444444", "#888888"]
    fig = Figure(figsize=(7.0, 0.5 + 0.45 * len(widths)), layout="constrained")
    ax = fig.add_subplot()
    y = np.arange(len(widths))[::-1]
    ax.barh(y, widths, color=colors)
    for k, w in zip(y, widths):
        ax.annotate(f"{w:.3g} arcmin", (w, k), xytext=(3, 0), textcoords="offset points", va="center", fontsize=8)
    ax.set_yticks(y, labels, fontsize=8)
    ax.set_xlabel(f"arcmin ({budget['convention'].split(':')[0]})")
    ax.set_xlim(0, 1.25 * max(widths))
    return fig
