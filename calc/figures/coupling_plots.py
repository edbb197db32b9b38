"""Figures of the coupling sizing: inertia split, temperature factor, natural frequencies, bores.

Each function returns a :class:`matplotlib.figure.Figure` built without pyplot (no global figure
state); matplotlib is imported inside each function, so ``import calc`` stays light. Figures are
deterministic: fixed sizes, colours and text.
"""

from __future__ import annotations

import math

import numpy as np

from ..domain.coupling import TEMPERATURE_FACTORS, CouplingSelection, temperature_factor
from ..core.glossary import math as symbol
from ..core.units import as_kind, fmt, sig

DRIVE_COLOR = "#1f5fa8"
LOAD_COLOR = "#e08a1e"
PASS_COLOR = "#5a9e3a"
FAIL_COLOR = "#b2222a"
CASE_COLOR = "#d95f02"
MISSING_COLOR = "#bbbbbb"


def inertia_split_figure(accel_torque, drive_inertia, load_inertia, M_N):
    """The inertias on the two sides of the coupling as one stacked bar, with ``M_N``.

    The coupling passes on the share ``J_load / (J_load + J_drive)`` of the motor's acceleration
    torque ``M_a`` (source, Sizing 1); ``M_N`` multiplies that by ``S_A`` (E8).

    Parameters
    ----------
    accel_torque : pint.Quantity [N·m]
        ``M_a``, the motor's acceleration torque.
    drive_inertia : pint.Quantity [kg·cm²]
        ``J_drive``, without the coupling.
    load_inertia : pint.Quantity [kg·cm²]
        ``J_load``, without the coupling.
    M_N : pint.Quantity [N·m]
        The coupling's nominal torque.

    Returns
    -------
    matplotlib.figure.Figure
        One axes: the drive side and the load side as two segments of one bar.

    Examples
    --------
    >>> from calc import Q_
    >>> fig = inertia_split_figure(Q_(12, "N*m"), Q_(4.2, "kg*cm**2"), Q_(15.93, "kg*cm**2"), Q_(23.74, "N*m"))
    >>> [round(float(p.get_width()), 2) for p in fig.axes[0].patches]
    [4.2, 15.93]
    """
    from matplotlib.figure import Figure

    j_d = as_kind(drive_inertia, "inertia", "drive_inertia").m_as("kg*cm**2")
    j_l = as_kind(load_inertia, "inertia", "load_inertia").m_as("kg*cm**2")
    share = j_l / (j_l + j_d)
    fig = Figure(figsize=(8.0, 2.4), layout="constrained")
    ax = fig.subplots()
    ax.barh([0], [j_d], color=DRIVE_COLOR, label=f"drive side {symbol('J_drive')} = {sig(j_d)} kg·cm²")
    ax.barh([0], [j_l], left=[j_d], color=LOAD_COLOR, label=f"load side {symbol('J_load')} = {sig(j_l)} kg·cm²")
    ax.text(j_d / 2, 0, f"{sig(100 * (1 - share), 3)} %", ha="center", va="center", color="white", fontsize=9)
    ax.text(j_d + j_l / 2, 0, f"{sig(100 * share, 3)} %", ha="center", va="center", color="white", fontsize=9)
    ax.set_yticks([])
    ax.set_xlabel("inertia [kg·cm²]")
    ax.set_xlim(0, j_d + j_l)
    ax.set_title(
        f"The coupling passes on {sig(100 * share, 3)} % of M_a = {fmt(accel_torque, 'N*m')} to the load; "
        f"with S_A: M_N = {fmt(M_N, 'N*m')}",
        fontsize=10,
    )
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.45), ncols=2, fontsize=8, frameon=False)
    return fig


def temperature_factor_figure(temperature=None, table=TEMPERATURE_FACTORS):
    """The elastomer temperature-factor table (E9) as steps, the case's temperature marked.

    Each band is a line from its lowest temperature (filled marker: the boundary belongs to this
    band, the higher factor) to the next band's (open marker); the last band ends at the table's
    top (filled), above which no elastomer coupling is sized.

    Parameters
    ----------
    temperature : pint.Quantity [°C], optional
        The case's temperature.
    table : BandTable
        ``K_ϑ`` against temperature; default the source's.

    Returns
    -------
    matplotlib.figure.Figure
        One axes; the case's point is the line with gid ``"case"``.

    Examples
    --------
    >>> from calc import Q_
    >>> fig = temperature_factor_figure(Q_(60, "degC"))
    >>> case = next(l for l in fig.axes[0].lines if l.get_gid() == "case")
    >>> float(case.get_xdata()[0]), float(case.get_ydata()[0])
    (60.0, 1.3)
    """
    from matplotlib.figure import Figure

    bounds, factors = table.bounds, table.factors
    finite = bounds[np.isfinite(bounds)]
    low = finite.min() - 30.0
    high = table.top + 10.0 if math.isfinite(table.top) else finite.max() + 30.0
    fig = Figure(figsize=(7.0, 3.6), layout="constrained")
    ax = fig.subplots()
    edges = [max(b, low) for b in bounds] + [min(table.top, high)]
    higher = table.at_boundary == "higher"  # a band holds its lowest value (E9), else its highest (a maker's table)
    for k, f in enumerate(factors):
        last = k + 1 == len(factors)
        ax.plot([edges[k], edges[k + 1]], [f, f], color=DRIVE_COLOR, linewidth=2.2)
        if math.isfinite(bounds[k]):
            ax.plot([edges[k]], [f], "o", markerfacecolor=None if higher or k == 0 else "white", color=DRIVE_COLOR,
                    markersize=5)
        if not last or math.isfinite(table.top):  # the table's top is in its last band; above it, no factor
            ax.plot([edges[k + 1]], [f], "o", markerfacecolor=None if last or not higher else "white",
                    color=DRIVE_COLOR, markersize=5)
    if temperature is not None:
        t = as_kind(temperature, "temperature", "temperature").m_as("degC")
        k_t = float(temperature_factor(temperature, table))
        ax.plot([t], [k_t], "D", color=CASE_COLOR, markersize=8, gid="case", label=f"case: {sig(t)} °C → K_ϑ = {k_t:g}")
        ax.legend(loc="upper left", fontsize=8)
    ax.set_xlim(low, high)
    ax.set_xlabel("operating temperature [°C]")
    ax.set_ylabel(f"temperature factor {symbol('K_T')}")
    rule = "E9: the higher factor at a boundary" if higher else "the factor printed at a temperature holds up to it"
    ax.set_title(f"Elastomer couplings: M_N is multiplied by K_ϑ ({rule})", fontsize=10)
    ax.grid(True, alpha=0.3)
    return fig


def natural_frequency_figure(selection: CouplingSelection, f_e_min):
    """The natural frequency ``f_e`` of each candidate against the required ``2 f_er`` (E7).

    Candidates in ranked order; a bar is green where ``f_e >= 2 f_er``, red where not, and a grey
    stub marked "n/a" where the catalog leaves ``C_T`` or ``J`` empty. Where the selection has the
    drive train (:mod:`calc.domain.torsion`), a black diamond marks each candidate's first mode ``f_1``.

    Parameters
    ----------
    selection : CouplingSelection
        The checked candidates.
    f_e_min : pint.Quantity [Hz]
        ``2 f_er``.

    Returns
    -------
    matplotlib.figure.Figure
        One axes of bars.

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.data.catalog import load_catalog, resolve
    >>> from calc.domain.coupling import SCHEMA, select_coupling
    >>> cat = load_catalog(resolve("couplings", None, "catalog"), SCHEMA)
    >>> s = select_coupling(cat.rows(cat.text["type"] == "bellows"), Q_(12, "N*m"), Q_(4.2, "kg*cm**2"),
    ...                     Q_(15.93, "kg*cm**2"), Q_(150, "Hz"), "19 mm k6", "16 mm h7")
    >>> [t.get_text() for t in natural_frequency_figure(s, Q_(300, "Hz")).axes[0].get_yticklabels()][:2]
    ['AKD-30', 'AKN-30']
    """
    from matplotlib.figure import Figure

    order = selection.order
    parts = selection.catalog.parts[order].astype(str)
    fe = selection.f_e[order].m_as("Hz")
    need = as_kind(f_e_min, "frequency", "f_e_min").m_as("Hz")
    fig = Figure(figsize=(7.5, 0.45 * len(parts) + 1.4), layout="constrained")
    ax = fig.subplots()
    y = np.arange(len(parts))[::-1]
    known = ~np.isnan(fe)
    colors = np.where(fe >= need, PASS_COLOR, FAIL_COLOR)
    ax.barh(y[known], fe[known], color=colors[known])
    top = np.nanmax(np.append(fe, need)) * 1.15
    for yy in y[~known]:
        ax.barh([yy], [top * 0.02], color=MISSING_COLOR)
        ax.text(top * 0.03, yy, "n/a (catalog gives no C_T or J)", va="center", fontsize=8, color="dimgray")
    ax.axvline(need, color=CASE_COLOR, linewidth=2, label=f"2 f_er = {sig(need)} Hz")
    title = "Each candidate as the spring of the two-mass system: f_e >= 2 f_er (E7)"
    if selection.modes is not None:
        # The drive train's first mode, where the case gives the chain (calc.domain.torsion).
        f_1 = selection.modes[order, 0].m_as("Hz")
        ax.plot(f_1, y, "D", color="black", markersize=5, label="first mode of the drive train $f_1$")
        title += "\nand in the drive train (the gearbox's spring too): f_1 >= 2 f_er"
    ax.set_yticks(y, parts)
    ax.set_xlim(0, top)
    ax.set_xlabel(f"natural frequency {symbol('f_e')} [Hz]")
    ax.set_title(title, fontsize=10)
    ax.legend(loc="lower right", fontsize=8)
    return fig


def bore_ranges_figure(selection: CouplingSelection, bores):
    """Each candidate's bore range per hub, with the two shafts' diameters.

    Hub 1 above hub 2 for each candidate, in ranked order; a missing range is left out and
    labelled "n/a".

    Parameters
    ----------
    selection : CouplingSelection
        The checked candidates.
    bores : sequence of Bore
        The two shafts.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.data.catalog import load_catalog, resolve
    >>> from calc.domain.coupling import SCHEMA, select_coupling
    >>> from calc.domain.fits import parse_bore
    >>> cat = load_catalog(resolve("couplings", None, "catalog"), SCHEMA)
    >>> b = [parse_bore("19 mm k6"), parse_bore("16 mm h7")]
    >>> s = select_coupling(cat.rows(cat.text["type"] == "bellows"), Q_(12, "N*m"), Q_(4.2, "kg*cm**2"),
    ...                     Q_(15.93, "kg*cm**2"), Q_(150, "Hz"), *b)
    >>> len(bore_ranges_figure(s, b).axes[0].patches)  # 26 bellows rows, two hubs each
    52
    """
    from matplotlib.figure import Figure

    order = selection.order
    parts = selection.catalog.parts[order].astype(str)
    fig = Figure(figsize=(7.5, 0.6 * len(parts) + 1.4), layout="constrained")
    ax = fig.subplots()
    base = np.arange(len(parts))[::-1] * 1.0
    colors = (DRIVE_COLOR, LOAD_COLOR)
    for hub, (bore, color, offset) in enumerate(zip(bores, colors, (0.18, -0.18)), start=1):
        lo = selection.catalog[f"d_{hub}min"][order].m_as("mm")
        hi = selection.catalog[f"d_{hub}max"][order].m_as("mm")
        known = ~(np.isnan(lo) | np.isnan(hi))
        ax.barh(base[known] + offset, (hi - lo)[known], left=lo[known], height=0.3, color=color, alpha=0.55,
                label=f"hub {hub} bore range")
        d = bore.nominal.m_as("mm")
        ax.axvline(d, color=color, linewidth=2, label=f"D{hub} = {bore.text}")
        for yy in (base + offset)[~known]:
            ax.text(d, yy, " n/a", va="center", fontsize=7, color="dimgray")
    ax.set_yticks(base, parts)
    ax.set_xlim(left=0)
    ax.set_xlabel("bore diameter [mm]")
    ax.set_title("Shaft diameters against each hub's bore range", fontsize=10)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.18), ncols=2, fontsize=8, frameon=False)
    return fig
