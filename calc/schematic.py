"""The drive train as a schematic: motor, coupling, gearbox and load in a row, each member with the
symbols the workbook gives it and the side its indices name (1: the input, 2: the output).

Each notebook opens with it, the members it treats in colour, so a reader sees where on the drive
train the notebook's symbols sit. Built without pyplot, like the other figures (:mod:`calc.plots`).
"""

from __future__ import annotations

from .errors import CalcError

#: The members, drive to load: (key, name, its symbols). Subscripts follow the source's index table.
MEMBERS = (
    ("motor", "servo motor", ("$J_{motor}$", "$T_{1B}$, $T_{1N}$", "$n_{1max}$")),
    ("coupling", "coupling", ("$C_T$, $J_K$", "$M_N$, $T_{KN}$", "$f_e$")),
    ("gearbox", "gearbox", ("$i$, $\\eta$, $J_1$", "$T_{2N}$, $T_{2B}$", "$C_{t21}$, $j_t$")),
    ("load", "load", ("$J_L$", "$T_2$, $n_2$", "$\\varphi_2$")),
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
    ['servo motor', '$J_{motor}$']
    >>> drive_train_figure(("brake",))
    Traceback (most recent call last):
    ...
    calc.errors.CalcError: focus: expected members among motor, coupling, gearbox, load; found 'brake'
    """
    from matplotlib.figure import Figure
    from matplotlib.patches import FancyBboxPatch

    keys = [key for key, _, _ in MEMBERS]
    unknown = [f for f in focus if f not in keys]
    if unknown:
        raise CalcError(f"focus: expected members among {', '.join(keys)}; found {', '.join(repr(f) for f in unknown)}")
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
    for left, right, label in ((0.0, split, "input side: index 1 ($n_1$, $T_1$)"), (split, end, "output side: index 2 ($n_2$, $T_2$)")):
        ax.annotate("", (left, -0.25), (right, -0.25), arrowprops={"arrowstyle": "<->", "linewidth": 1})
        ax.text((left + right) / 2, -0.45, label, ha="center", va="top", fontsize=8)
    ax.set_xlim(-0.1, end + 0.1)
    ax.set_ylim(-0.8, height + 0.1)
    ax.set_aspect("equal")
    ax.axis("off")
    return fig
