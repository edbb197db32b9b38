"""Figures of the gearbox selection: the load cycle, the shock-factor table and the utilizations.

Each function returns a :class:`matplotlib.figure.Figure` built without pyplot, so no global
figure state is left behind: a notebook shows it (after ``%matplotlib inline``), a report saves it
with ``fig.savefig``. matplotlib is imported inside each function, so ``import calc`` stays light.
Figures are deterministic (fixed sizes, colours and text) and labelled for a printed page: axes
with symbol and unit, a title, a legend.
"""

from __future__ import annotations

import textwrap

import numpy as np

from ..core.errors import CalcError
from ..core.glossary import math as symbol
from ..domain.gearbox import SHOCK_FACTORS, GearboxSelection, shock_factor
from ..domain.profile import S5_MAX_ED, S5_MAX_ON_TIME, Duty, Profile
from ..domain.profile import duty as profile_duty
from ..core.units import as_kind, fmt, sig

SPEED_COLOR = "#1f5fa8"
TORQUE_COLOR = "#b2222a"
ON_COLOR = "#d7e6f5"
PAUSE_COLOR = "#e4e4e4"
CASE_COLOR = "#d95f02"
PASS_COLOR = "#4c9a3f"
FAIL_COLOR = "#c0392b"
#: Where the utilization figure's axis ends: far-failing rows would flatten the rest.
UTILIZATION_AXIS_END = 2.0

#: A segment narrower than this share of the cycle gets no value or phase label (they would overlap).
_LABEL_MIN_SHARE = 0.06


def load_cycle_figure(profile: Profile, duty: Duty | None = None):
    """Output speed and output torque against time over one cycle, on-time and pauses shaded.

    The profile gives each segment's *mean* output speed, so each segment is drawn as a step at
    the value the profile holds: an acceleration from 0 to 300 rpm appears at its mean, 150 rpm,
    not as a ramp (the figure says so). Torques keep their sign. The title gives ED, the on-time,
    the cycle time and the operating mode (errata E3).

    Parameters
    ----------
    profile : Profile
        The load cycle.
    duty : Duty, optional
        Its duty cycle; computed with :func:`calc.domain.profile.duty` when not given.

    Returns
    -------
    matplotlib.figure.Figure
        Two axes sharing time: speed [rpm] above, torque [N·m] below.

    Examples
    --------
    >>> from calc import Q_
    >>> p = Profile.from_segments([("const", Q_(1, "s"), Q_(100, "rpm"), Q_(10, "N*m")),
    ...                            ("pause", Q_(1, "s"), None, None)])
    >>> [ax.get_ylabel() for ax in load_cycle_figure(p).axes]
    ['mean output speed $n_2$ [rpm]', 'output torque $T_2$ [N·m]']
    """
    from matplotlib.figure import Figure
    from matplotlib.patches import Patch
    from matplotlib.transforms import blended_transform_factory

    d = profile_duty(profile) if duty is None else duty
    edges = np.concatenate([[0.0], np.cumsum(profile.durations.m_as("s"))])
    cycle = edges[-1]
    moving = profile.moving
    speeds = profile.speeds.m_as("rpm")
    torques = profile.torques.m_as("N*m")

    fig = Figure(figsize=(8.0, 6.2), layout="constrained")
    ax_n, ax_T = fig.subplots(2, 1, sharex=True)
    series = (
        (ax_n, speeds, SPEED_COLOR, "mean output speed $n_2$ [rpm]", "rpm"),
        (ax_T, torques, TORQUE_COLOR, "output torque $T_2$ [N·m]", "N·m"),
    )
    steps = []
    for ax, values, color, ylabel, unit in series:
        for k in range(len(values)):
            ax.axvspan(edges[k], edges[k + 1], color=ON_COLOR if moving[k] else PAUSE_COLOR, linewidth=0, zorder=0)
        ax.axhline(0.0, color="black", linewidth=0.8, zorder=1)
        steps.append(ax.stairs(values, edges, baseline=None, color=color, linewidth=2.2, zorder=3, label=ylabel))
        ax.set_ylabel(ylabel)
        low, high = min(0.0, values.min()), max(0.0, values.max())
        pad = 0.18 * (high - low) if high > low else 1.0
        ax.set_ylim(low - pad, high + pad)
        ax.grid(True, axis="y", color="white", linewidth=0.8, zorder=0)
        for k in np.flatnonzero(moving & (np.diff(edges) >= _LABEL_MIN_SHARE * cycle)):
            v = values[k]
            ax.annotate(
                f"{sig(v, 3)} {unit}", ((edges[k] + edges[k + 1]) / 2, v), xytext=(0, 5 if v >= 0 else -5),
                textcoords="offset points", ha="center", va="bottom" if v >= 0 else "top", fontsize=8, color=color,
            )
    top = blended_transform_factory(ax_n.transData, ax_n.transAxes)
    for k in np.flatnonzero(np.diff(edges) >= _LABEL_MIN_SHARE * cycle):
        ax_n.text((edges[k] + edges[k + 1]) / 2, 1.02, profile.phases[k], transform=top, ha="center", va="bottom",
                  fontsize=8)
    ax_T.set_xlabel("time $t$ [s]")
    ax_T.set_xlim(0.0, cycle)

    ed, t_on, t_cycle = d.ED.m_as("percent"), d.t_on, d.t_cycle
    fig.suptitle(
        f"Load cycle: ED = {sig(ed, 3)} % (on-time {fmt(t_on, 's')} of a {fmt(t_cycle, 's')} cycle), mode {d.mode}\n"
        f"E3: S5 if and only if ED < {sig(S5_MAX_ED.m_as('percent'))} % and on-time < "
        f"{sig(S5_MAX_ON_TIME.m_as('min'))} min, "
        "otherwise S1",
        fontsize=10,
    )
    ax_n.set_title("speed: each segment at its mean, as the profile gives it (accel and decel are not drawn as ramps)",
                   fontsize=8, pad=16)
    handles = [
        *steps,
        Patch(color=ON_COLOR, label=f"on-time (moving), {fmt(t_on, 's')}"),
        Patch(color=PAUSE_COLOR, label=f"pause, {fmt(t_cycle - t_on, 's')}"),
    ]
    fig.legend(handles=handles, loc="outside lower center", ncols=4, fontsize=8, frameon=False)
    return fig


def shock_factor_figure(cycles_per_hour=None, table=SHOCK_FACTORS, f_s: float | None = None):
    """A shock-factor table (errata E4) as a step plot against ``Z_h``, the case's point marked.

    Each band of ``table`` (the source's, :data:`calc.domain.gearbox.SHOCK_FACTORS`, unless the case names
    another with ``[gearbox] shock_factors``) is a horizontal line from its lowest ``Z_h`` to the
    next band's; a filled marker shows the band a boundary belongs to, an open one the band it is
    excluded from, by the table's own rule (:attr:`calc.data.bands.BandTable.at_boundary`): the
    higher factor at a boundary, as E4 reads the source's table, or the lower one.

    Parameters
    ----------
    cycles_per_hour : pint.Quantity [1/h], optional
        The case's ``Z_h``; marked with its factor.
    table : calc.data.bands.BandTable
        The table the case's ``f_s`` is read from.
    f_s : float [1], optional
        The case's ``f_s`` as its evaluation recorded it (:attr:`calc.sections.duty.DutyResult.fs`);
        read from ``table`` at ``cycles_per_hour`` (:func:`calc.domain.gearbox.shock_factor`) where
        not given.

    Returns
    -------
    matplotlib.figure.Figure
        One axes; the case's point is the line with gid ``"case"``.

    Examples
    --------
    >>> from calc import Q_
    >>> case = next(l for l in shock_factor_figure(Q_(1800, "1/hour")).axes[0].lines if l.get_gid() == "case")
    >>> float(case.get_xdata()[0]), float(case.get_ydata()[0])
    (1800.0, 1.3)
    """
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    bounds, factors = table.bounds, table.factors
    z_case = None
    if cycles_per_hour is not None:
        z = as_kind(cycles_per_hour, "per_hour", "cycles_per_hour").m_as("1/hour")
        if np.ndim(z) != 0:
            raise CalcError(f"cycles_per_hour: expected one number of cycles per hour, found {np.size(z)} of them")
        z_case = float(z)
        f_case = float(shock_factor(cycles_per_hour, table) if f_s is None else f_s)
    # a table of one band: 0 to 1000 /h shown
    span = bounds[-1] - bounds[-2] if len(bounds) > 1 else max(bounds[-1], 1000.0)
    x_end = bounds[-1] + span
    if z_case is not None and z_case > 0.9 * x_end:
        x_end = 1.15 * z_case

    fig = Figure(figsize=(7.5, 5.2), layout="constrained")
    ax = fig.subplots()
    right = np.append(bounds[1:], x_end)
    ax.hlines(factors, bounds, right, color=SPEED_COLOR, linewidth=2.5, zorder=2)
    ax.vlines(bounds[1:], factors[:-1], factors[1:], color=SPEED_COLOR, linewidth=0.8, linestyles=":", zorder=1)
    higher = table.at_boundary == "higher"
    # A boundary belongs to the band it starts (higher factor) or to the band it ends (lower factor).
    kept, left = (factors, factors[:-1]) if higher else (np.append(factors[:1], factors[:-1]), factors[1:])
    ax.plot(bounds, kept, "o", color=SPEED_COLOR, markersize=7, zorder=3, gid="included")
    ax.plot(bounds[1:], left, "o", markerfacecolor="white", markeredgecolor=SPEED_COLOR, markersize=7, zorder=3,
            gid="excluded")
    ax.annotate("", (x_end, factors[-1]), xytext=(x_end - 0.06 * x_end, factors[-1]),
                arrowprops=dict(arrowstyle="->", color=SPEED_COLOR, linewidth=2.5))
    for lo, hi, f in zip(bounds, right, factors):
        ax.text((lo + hi) / 2, f + 0.03, f"{symbol('f_s')} = {f:.1f}", ha="center", va="bottom", fontsize=9)

    handles = [
        Line2D([], [], marker="o", color=SPEED_COLOR, linestyle="none", label="boundary included in the band"),
        Line2D([], [], marker="o", markerfacecolor="white", markeredgecolor=SPEED_COLOR, linestyle="none",
               label="boundary excluded (the higher factor applies, E4)" if higher
               else "boundary excluded (the lower factor applies, as the table reads)"),
    ]
    if z_case is not None:
        ax.vlines(z_case, 0.0, f_case, color=CASE_COLOR, linewidth=1, linestyles="--", zorder=2)
        ax.hlines(f_case, 0.0, z_case, color=CASE_COLOR, linewidth=1, linestyles="--", zorder=2)
        label = f"this case: {symbol('Z_h')} = {sig(z_case)} 1/h, {symbol('f_s')} = {f_case:g}"
        ax.plot([z_case], [f_case], marker="*", markersize=16, color=CASE_COLOR, markeredgecolor="black",
                linestyle="none", zorder=4, gid="case", label=label)
        handles.append(ax.lines[-1])

    ax.set_xlim(-0.02 * x_end, x_end)
    ax.set_ylim(0.9, factors[-1] + 0.2)
    ax.set_xticks(bounds)
    ax.set_yticks(factors)
    ax.grid(True, color="#dddddd", linewidth=0.6, zorder=0)
    ax.set_xlabel(f"load cycles per hour {symbol('Z_h')} = 3600 s · {symbol('z_c')} / {symbol('t_cycle')} [1/h]")
    ax.set_ylabel(f"shock factor {symbol('f_s')} [–]")
    ax.set_title(textwrap.fill(f"Shock factor against cycles per hour: {table.source}", 90) + "\n"
                 f"makers rate {symbol('T_2B')} for up to 1000 cycles per hour; {symbol('f_s')} covers more",
                 fontsize=10)
    fig.legend(handles=handles, loc="outside lower center", ncols=1, fontsize=8, frameon=False)
    return fig


def utilization_figure(selection: GearboxSelection, limit: int = 12):
    """Each candidate's governing-check utilizations (required / rated), best first, read at a glance.

    One row per candidate: its bar is its highest governing utilization, green where the candidate
    passes and red where it fails (the verdict of its checks, not a second reading of the numbers),
    labelled with the value and the check that decides it; a dot for each of its other governing
    checks. The dashed line at 1 is the limit. The axis stops at 2: a bar beyond it is cut and its
    label gives the value. A check whose rated value the catalog leaves empty has no dot and is
    named after "no rating".

    Parameters
    ----------
    selection : GearboxSelection
        The checked and ranked catalog rows.
    limit : int
        Draw at most this many candidates, best first (the title says how many there are).

    Returns
    -------
    matplotlib.figure.Figure
        One axes, one row per candidate, the best at the top.
    """
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    candidates = selection.candidates(limit)
    total = len(selection.order)
    fig = Figure(figsize=(10.0, 0.38 * len(candidates) + 1.9), layout="constrained")
    ax = fig.subplots()
    for row, c in enumerate(candidates):
        governing = [k for k in c.checks if k.governs]
        u = np.array([k.utilization for k in governing], dtype=float)
        rated = ~np.isnan(u)
        worst = int(np.nanargmax(u)) if rated.any() else None
        value = u[worst] if worst is not None else 0.0
        ax.barh(row, min(value, UTILIZATION_AXIS_END), 0.62, color=PASS_COLOR if c.passes else FAIL_COLOR, zorder=2)
        others = np.array([v for j, v in enumerate(u) if j != worst and rated[j]])
        ax.plot(np.minimum(others, UTILIZATION_AXIS_END), np.full(len(others), row), "o", color="#333333",
                markersize=3.5, zorder=3)
        label = "" if worst is None else f"{value:.2f}  {governing[worst].criterion}"
        unrated = [k.criterion for k, r in zip(governing, rated) if not r]
        label += ("; " if label else "") + ("no rating: " + ", ".join(unrated) if unrated else "")
        ax.text(min(value, UTILIZATION_AXIS_END) + 0.03, row, label, va="center", fontsize=8, zorder=4)
    ax.axvline(1.0, color="black", linestyle="--", linewidth=1.2, zorder=3)
    marks = [" (selected)" if c.part == selection.selected else "" for c in candidates]
    ax.set_yticks(range(len(candidates)),
                  [f"{c.part}  {'PASS' if c.passes else 'FAIL'}{m}" + ("  illustrative" if c.illustrative else "")
                                            for c, m in zip(candidates, marks)], fontsize=8)
    ax.set_ylim(len(candidates) - 0.5, -0.5)  # the best at the top
    # Room on the right for the labels; the ticks stop at the axis end.
    ax.set_xlim(0.0, UTILIZATION_AXIS_END + 2.0)
    ax.set_xticks(np.arange(0.0, UTILIZATION_AXIS_END + 0.01, 0.25))
    ax.set_xlabel("utilization = required / rated [–]")
    shown = (f"best {len(candidates)} of {total}" if total > len(candidates)
             else f"{total} candidate{'s' if total != 1 else ''}")
    ax.set_title(f"Utilization of the governing {selection.mode} checks, {shown}\n"
                 f"bar: the highest, with the check that decides it (cut at {UTILIZATION_AXIS_END:g}); dots: the "
                 "others", fontsize=10)
    ax.grid(True, axis="x", color="#dddddd", linewidth=0.6, zorder=0)
    handles = [Patch(color=PASS_COLOR, label="passes"), Patch(color=FAIL_COLOR, label="fails"),
               Line2D([], [], marker="o", linestyle="none", color="#333333", markersize=3.5,
                      label="other governing checks"),
               Line2D([], [], color="black", linestyle="--", label="limit: utilization 1")]
    fig.legend(handles=handles, loc="outside lower center", ncols=4, fontsize=8, frameon=False)
    return fig


#: Colours of the families (or catalogs) in :func:`comparison_figure`, in order of first appearance.
FAMILY_COLORS = ("#1f5fa8", "#e08a1e", "#5a9e3a", "#8e5ba8", "#c0392b", "#7f7f7f", "#17becf", "#bcbd22")


def comparison_figure(selection: GearboxSelection, limit: int = 24):
    """The makers compared: each candidate's governing utilization (the highest of its governing
    checks, the ranking's margin), best first, one bar per candidate coloured by its family; with
    several catalogs the colour is the catalog and family (``my-maker.csv · MK``).

    A failing candidate's bar is hatched (its worst check above the dashed line at 1); the axis
    stops at 3, a label gives each value. The smallest adequate size of each family is marked with
    a star. A candidate whose governing check has no rating has no bar ("no rating").

    Parameters
    ----------
    selection : GearboxSelection
        The checked and ranked catalog rows (of one catalog or several).
    limit : int
        Draw at most this many candidates, best first.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.data.catalog import load_catalog, resolve
    >>> from calc.domain.gearbox import SCHEMA, rows_at_ratio, select_gearbox
    >>> from calc.domain.profile import Profile
    >>> p = Profile.from_segments([("const", Q_(1, "s"), Q_(240, "rpm"), Q_(40, "N*m")),
    ...                            ("pause", Q_(1, "s"), None, None)])
    >>> rows = rows_at_ratio(load_catalog(resolve("gearboxes", None, "catalog"), SCHEMA), 10)
    >>> fig = comparison_figure(select_gearbox(p, rows, motor_peak_torque=Q_(12, "N*m")))
    >>> sorted(t.get_text() for t in fig.legends[0].get_texts())[:3]
    ['NPS', 'NPT', 'TP+']
    """
    from matplotlib.figure import Figure
    from matplotlib.patches import Patch

    cat = selection.catalog
    order = selection.order[:limit]
    several = len(cat.members) > 1
    groups = [f"{cat.catalog_of(r)} · {cat.family[r]}" if several else str(cat.family[r]) for r in order]
    colors = {g: FAMILY_COLORS[k % len(FAMILY_COLORS)] for k, g in enumerate(dict.fromkeys(groups))}
    worst = np.asarray(selection.worst[order], dtype=float)
    best = selection.best_of_family[order]
    x = np.arange(len(order))
    fig = Figure(figsize=(max(6.5, 0.55 * len(order) + 2.5), 4.8), layout="constrained")
    ax = fig.subplots()
    bars = ax.bar(x, np.nan_to_num(worst, nan=0.0), 0.7, color=[colors[g] for g in groups], zorder=2)
    for bar, passes in zip(bars, selection.passes[order]):
        if not passes:
            bar.set_hatch("///")
            bar.set_edgecolor("black")
    ax.bar_label(bars, labels=["no rating" if np.isnan(v) else f"{v:.2f}" + (" ★" if b else "")
                               for v, b in zip(worst, best)],
                 fontsize=7, padding=2, rotation=90)
    ax.axhline(1.0, color="black", linestyle="--", linewidth=1.2, zorder=3)
    ax.set_xticks(x, [str(cat.parts[r]) for r in order], fontsize=7, rotation=90)
    # Far-failing rows would flatten the rest: the axis stops at 3, their labels give the value.
    ax.set_ylim(0.0, 1.3 * min(3.0, max(1.0, np.nanmax(worst, initial=0.0))))
    ax.set_ylabel(f"governing utilization ({selection.mode}) [–]")
    ax.set_xlabel("candidate, best first")
    total = len(selection.order)
    shown = f"best {len(order)} of {total}" if total > len(order) else f"{total} candidates"
    ax.set_title(f"Makers compared: highest governing utilization of each candidate, {shown}\n"
                 "(★ smallest adequate size of its family; hatched: over the limit)", fontsize=10)
    ax.grid(True, axis="y", color="#dddddd", linewidth=0.6, zorder=0)
    fig.legend(handles=[Patch(color=c, label=g) for g, c in colors.items()], loc="outside right upper", fontsize=8,
               frameon=False)
    return fig
