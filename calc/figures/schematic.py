"""The drive train as a schematic: motor, coupling, gearbox and load in a row, each member with the
symbols the workbook gives it and the side its indices name (1: the input, 2: the output).

Each notebook opens with it, the members it treats in colour, so a reader sees where on the drive
train the notebook's symbols sit. Built without pyplot, like the other figures (:mod:`calc.figures.plots`).
"""

from __future__ import annotations

import numpy as np

from ..core.errors import CalcError, listing
from ..core.glossary import math as symbol


def _symbols(*names: str) -> str:
    return ", ".join(map(symbol, names))


#: The members, drive to load: (key, name, its symbols). Subscripts follow the source's index table.
MEMBERS = (
    ("motor", "servo motor", (_symbols("J_motor"), _symbols("T_1B", "T_1N"), _symbols("n_1max"))),
    ("coupling", "coupling", (_symbols("C_T", "J_K"), _symbols("M_N", "T_KN"), _symbols("f_e"))),
    ("gearbox", "gearbox", (_symbols("i", "eta", "J_1"), _symbols("T_2N", "T_2B"), _symbols("C_t21", "j_t"))),
    ("load", "load", (_symbols("J_L"), _symbols("T_2", "n_2"), _symbols("phi_2"))),
)
FOCUS_COLOR = "#f6c344"
OTHER_COLOR = "#e8e8e8"


def drive_train_figure(focus: tuple[str, ...] = ()):
    """The drive train motor - coupling - gearbox - load, the members in ``focus`` highlighted.

    Parameters
    ----------
    focus : tuple of str
        Keys of the members a notebook treats: ``motor``, ``coupling``, ``gearbox``, ``load``.

    Returns
    -------
    matplotlib.figure.Figure
        One axes without scales: four boxes joined by shafts, the input side (index 1) and the
        output side (index 2) bracketed beneath.

    Examples
    --------
    >>> fig = drive_train_figure(("gearbox",))
    >>> [t.get_text() for t in fig.axes[0].texts][:2]
    ['servo motor', '$J_{\\\\mathrm{motor}}$']
    >>> drive_train_figure(("brake",))
    Traceback (most recent call last):
    ...
    calc.core.errors.CalcError: focus: expected members among motor, coupling, gearbox, load; found 'brake'
    """
    from matplotlib.figure import Figure
    from matplotlib.patches import FancyBboxPatch

    keys = [key for key, _, _ in MEMBERS]
    unknown = [f for f in focus if f not in keys]
    if unknown:
        raise CalcError(f"focus: expected members among {listing(keys)}; found {listing(repr(f) for f in unknown)}")
    fig = Figure(figsize=(8.0, 2.5), layout="constrained")
    ax = fig.subplots()
    width, gap, height = 1.6, 0.7, 1.5
    for k, (key, name, symbols) in enumerate(MEMBERS):
        x = k * (width + gap)
        ax.add_patch(FancyBboxPatch((x, 0.0), width, height, boxstyle="round,pad=0.02", linewidth=1.2,
                                    facecolor=FOCUS_COLOR if key in focus else OTHER_COLOR, edgecolor="black"))
        ax.text(x + width / 2, height - 0.22, name, ha="center", va="center", fontsize=9, fontweight="bold")
        for j, line in enumerate(symbols):
            ax.text(x + width / 2, height - 0.58 - 0.3 * j, line, ha="center", va="center", fontsize=8)
        if k:  # the shaft from the member before
            ax.plot([x - gap, x], [height / 2, height / 2], color="black", linewidth=3, solid_capstyle="butt")
    # The gearbox splits the train: its input turns with the motor (index 1), its output with the load (index 2).
    split = 2 * (width + gap) + width / 2
    end = 3 * (width + gap) + width
    for left, right, label in ((0.0, split, "input side: index 1 ($n_1$, $T_1$)"),
                               (split, end, "output side: index 2 ($n_2$, $T_2$)")):
        ax.annotate("", (left, -0.25), (right, -0.25), arrowprops={"arrowstyle": "<->", "linewidth": 1})
        ax.text((left + right) / 2, -0.45, label, ha="center", va="top", fontsize=8)
    ax.set_xlim(-0.1, end + 0.1)
    ax.set_ylim(-0.8, height + 0.1)
    ax.set_aspect("equal")
    ax.axis("off")
    return fig


def _gear(center, radius: float, teeth: int, depth: float, internal: bool = False):
    """The outline of a gear as a polygon: ``teeth`` trapezoids of ``depth`` on a pitch circle of
    ``radius``, pointing out (an external gear) or in (the ring's internal teeth)."""
    steps = np.arange(teeth * 4) * (2 * np.pi / (teeth * 4))
    # Each tooth pitch: root, flank up, tip, flank down.
    r = radius + np.tile([-depth / 2, depth / 2, depth / 2, -depth / 2], teeth) * (-1 if internal else 1)
    return np.column_stack([center[0] + r * np.cos(steps), center[1] + r * np.sin(steps)])


def _label(ax, labels) -> None:
    """Each ``(point, place, text)``: the text at ``place``, a thin line to the ``point`` it names."""
    for point, place, text in labels:
        ax.annotate(text, point, place, fontsize=8.5, va="center",
                    arrowprops={"arrowstyle": "-", "linewidth": 0.8, "color": "0.3"})


#: The teeth of the planetary stage drawn: sun, each of the three planets, ring. It can be built:
#: z_ring = z_sun + 2 z_planet; three equally spaced planets need (z_sun + z_ring) / 3 whole
#: (108 / 3 = 36); the planets' tips clear each other (tip diameter 38 modules against a spacing of
#: 27 · sqrt(3) = 46.8); a sun of 18 teeth is not undercut (at least 17 at 20°).
PLANETARY_TEETH = {"sun": 18, "planet": 36, "ring": 90}


def planetary_stage_ratio(teeth: dict = PLANETARY_TEETH) -> float:
    """The ratio of a planetary stage with the ring fixed, the sun driving and the carrier driven.

    .. math:: i = 1 + z_{ring} / z_{sun}

    Parameters
    ----------
    teeth : dict
        The teeth of ``"sun"`` and ``"ring"`` [1].

    Returns
    -------
    float
        i [1].

    Examples
    --------
    >>> planetary_stage_ratio()  # 1 + 90 / 18
    6.0
    """
    return 1 + teeth["ring"] / teeth["sun"]


def planetary_gearbox_figure():
    """A one-stage planetary gearbox seen along its axis, as the catalogs' servo gearboxes are
    built: the sun on the input shaft (index 1), three planets on the carrier, which is the output
    (index 2), and the ring gear fixed in the housing. Drawn to scale with the teeth of
    :data:`PLANETARY_TEETH`, a stage that can be built, of ratio 6. One stage stops near a ratio
    of 10: the sun shrinks towards undercut and the planets grow until their tips touch (at
    i = 10 with three planets, z_planet = 4 z_sun), so catalogs build higher ratios in two stages.

    Returns
    -------
    matplotlib.figure.Figure
        One axes without scales.

    Examples
    --------
    >>> fig = planetary_gearbox_figure()
    >>> sorted(t.get_text().split(":")[0] for t in fig.axes[0].texts if ":" in t.get_text())
    ['carrier (dashed)', 'planets', 'ring gear', 'sun']
    """
    from matplotlib.figure import Figure
    from matplotlib.patches import Circle, Polygon

    fig = Figure(figsize=(7.5, 4.2), layout="constrained")
    ax = fig.subplots()
    z = PLANETARY_TEETH
    half_module = 0.9 / z["ring"]  # the ring's pitch radius 0.9: radius = z · module / 2
    sun, planet, ring = (z[k] * half_module for k in ("sun", "planet", "ring"))
    depth = 2.25 * 2 * half_module  # a tooth's whole depth, 2.25 modules
    ax.add_patch(Circle((0, 0), ring + 0.12, facecolor=OTHER_COLOR, edgecolor="black", linewidth=1.2))
    ax.add_patch(Polygon(_gear((0, 0), ring, z["ring"], depth, internal=True), facecolor="white", edgecolor="black",
                         linewidth=0.8))
    centers = [(sun + planet) * np.array([np.cos(a), np.sin(a)]) for a in np.radians([90, 210, 330])]
    for c in centers:
        ax.add_patch(Polygon(_gear(c, planet, z["planet"], depth), facecolor="#cfe3f5", edgecolor="black",
                             linewidth=0.8))
    # The carrier, a plate behind the planets, drawn over them: its arms join the planets' pins.
    ax.add_patch(Polygon(np.array(centers), closed=True, facecolor="none", edgecolor="#9a6b00", linewidth=2,
                         linestyle="--"))
    for c in centers:
        ax.add_patch(Circle(c, 0.035, facecolor="#9a6b00", edgecolor="black"))
    ax.add_patch(Polygon(_gear((0, 0), sun, z["sun"], depth), facecolor=FOCUS_COLOR, edgecolor="black",
                         linewidth=0.8))
    ax.add_patch(Circle((0, 0), 0.03, facecolor="black"))
    labels = (
        ((0, 0), (1.35, 0.55), f"sun: on the input shaft (index 1: $n_1$, $T_1$), {z['sun']} teeth"),
        (centers[1], (1.35, -0.05), f"planets: roll between sun and ring, {z['planet']} teeth"),
        ((0.5 * (centers[0][0] + centers[2][0]), 0.5 * (centers[0][1] + centers[2][1])), (1.35, -0.45),
         "carrier (dashed): holds the planets, turns the output\n(index 2: $n_2 = n_1 / i$, $T_2$)"),
        ((ring * np.cos(np.radians(40)), ring * np.sin(np.radians(40))), (1.35, 0.95),
         f"ring gear: fixed in the housing, {z['ring']} teeth"),
    )
    _label(ax, labels)
    ax.text(0, -1.2, f"the sun turns $i$ = 1 + {z['ring']} / {z['sun']} = {planetary_stage_ratio(z):g} times while "
            "the carrier turns once", ha="center", fontsize=8.5)
    ax.set_xlim(-1.1, 3.3)
    ax.set_ylim(-1.3, 1.15)
    ax.set_aspect("equal")
    ax.axis("off")
    return fig


def bellows_coupling_figure():
    """A metal bellows coupling in section: a clamping hub on each shaft (the motor's ``D_1``, the
    gearbox input's ``D_2``) joined by a thin metal bellows, stiff in torsion (``C_T``) and soft
    against misalignment between the shafts.

    Returns
    -------
    matplotlib.figure.Figure
        One axes without scales.

    Examples
    --------
    >>> fig = bellows_coupling_figure()
    >>> sorted(t.get_text().split(":")[0] for t in fig.axes[0].texts if ":" in t.get_text())
    ['hub 1', 'hub 2', 'metal bellows']
    """
    from matplotlib.figure import Figure
    from matplotlib.patches import Rectangle

    fig = Figure(figsize=(7.5, 3.0), layout="constrained")
    ax = fig.subplots()
    hub, shaft = 0.9, 0.28  # hub length and shaft radius
    folds, left, right = 7, hub, hub + 1.4
    for x0 in (0.0, right):
        ax.add_patch(Rectangle((x0, -0.6), hub, 1.2, facecolor=OTHER_COLOR, edgecolor="black", linewidth=1.2))
        ax.add_patch(Rectangle((x0 + 0.3, 0.6), 0.18, 0.12, facecolor="0.4", edgecolor="black"))  # the clamping screw
    # The shafts end inside the hubs; the motor's enters from the left, the gearbox's from the right.
    ax.add_patch(Rectangle((-0.9, -shaft), 0.9 + 0.7, 2 * shaft, facecolor=FOCUS_COLOR, edgecolor="black"))
    ax.add_patch(Rectangle((right + hub - 0.7, -shaft * 0.85), 0.7 + 0.9, 1.7 * shaft, facecolor="#cfe3f5",
                           edgecolor="black"))
    x = np.linspace(left, right, 4 * folds + 1)
    wave = 0.48 + 0.1 * np.where(np.arange(len(x)) % 2 == 0, 0.0, 1.0)
    for sign in (1, -1):
        ax.plot(x, sign * wave, color="black", linewidth=1.2)
    labels = (
        ((0.45, 0.62), (-0.9, 1.2), "hub 1: clamps the motor shaft $D_1$"),
        ((right + 0.45, 0.62), (right - 0.2, 1.2), "hub 2: clamps the gearbox shaft $D_2$"),
        (((left + right) / 2, -0.55), ((left + right) / 2 - 1.2, -1.15),
         f"metal bellows: stiff in torsion ({symbol('C_T')}), soft against misalignment;\n"
         "no backlash, no temperature factor (E9)"),
    )
    _label(ax, labels)
    ax.text(-0.9, 0.0, "motor ", ha="right", va="center", fontsize=8.5)
    ax.text(right + hub + 0.9, 0.0, " gearbox", ha="left", va="center", fontsize=8.5)
    ax.set_xlim(-1.6, right + hub + 1.7)
    ax.set_ylim(-1.4, 1.4)
    ax.set_aspect("equal")
    ax.axis("off")
    return fig
