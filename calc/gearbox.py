"""Gearbox selection for continuous (S1) and cyclic (S5) operation.

Source: "Selection of Optimum Gearbox for a Continuous Operation (S1)" and "... for a Cycle
Operation (S5)", read with errata E1 to E6. Every row of a catalog at the desired ratio is
evaluated at once (numpy arrays over the rows, no per-row Python loop); each criterion is kept
with its required value, rated value, utilization (required / rated) and verdict.

Ranking rule (:func:`rank`): passing candidates first, and among them rows of published data
before rows marked illustrative (a part is not chosen on illustrative figures while a published
one fits); then the smallest adequate size, measured by the governing torque rating (``T_2B`` in
S5, ``T_2N`` in S1), then the larger margin (lower worst utilization of the governing checks);
failing candidates after, closest to passing first (lowest worst utilization). Ties go by part
name.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .bands import factor_table
from .catalog import Catalog, Column, Rule, Schema, no_less
from .errors import CalcError
from .formula import Formula, Symbol
from .checks import CheckArray, rank, selected_part
from .profile import Profile, T_2m, Z_h, duty, n_2m
from .units import Q_, as_kind, magnitude_in, pretty_unit

#: Columns of a gearbox with a published stiffness curve (strain-wave gears, calc.stiffness.StiffnessCurve):
#: limit torques and slopes; a catalog may leave them out.
CURVE_COLUMNS = (
    Column("T_L1", "torque", "first limit torque of the stiffness curve (T1)", required=False),
    Column("T_L2", "torque", "second limit torque of the stiffness curve (T2)", required=False),
    Column("K_1", "stiffness", "stiffness from 0 to T_L1", required=False),
    Column("K_2", "stiffness", "stiffness from T_L1 to T_L2", required=False),
    Column("K_3", "stiffness", "stiffness above T_L2", required=False),
)

SCHEMA = Schema(
    kind="gearbox",
    columns=(
        Column("ratio", "dimensionless", "ratio i"),
        Column("T_2N", "torque", "nominal output torque"),
        Column("T_2B", "torque", "maximum acceleration output torque"),
        Column("T_2Not", "torque", "emergency-stop output torque", required=False),
        Column("n_1N", "speed", "nominal input speed"),
        Column("n_1max", "speed", "maximum input speed"),
        Column("eta", "dimensionless", "efficiency at full load"),
        Column("backlash", "angle", "torsional backlash", required=False, positive=False),
        Column("C_t21", "stiffness", "torsional stiffness, output", required=False),
        Column("J_1", "inertia", "mass moment of inertia referred to the input", required=False),
    ),
    text_columns=("part", "series", "source"),
    optional_text=("illustrative",),
    rules=(
        Rule("T_2B >= T_2N", no_less("T_2B", "T_2N"), "T_2B"),
        Rule("T_2Not >= T_2B", no_less("T_2Not", "T_2B"), "T_2Not"),
        Rule("n_1max >= n_1N", no_less("n_1max", "n_1N"), "n_1max"),
        Rule("efficiency eta in (0, 1]", lambda v: (v["eta"].m_as("") <= 1.0), "eta"),
        Rule(
            "a stiffness curve in all of T_L1, T_L2, K_1, K_2, K_3 or in none",
            lambda v: np.isin(sum(np.isnan(v[c.name].magnitude).astype(int) for c in CURVE_COLUMNS), (0, len(CURVE_COLUMNS))),
            "K_3",
        ),
        Rule("T_L2 > T_L1", lambda v: ~(v["T_L2"] <= v["T_L1"]), "T_L2"),
    ),
    optional_columns=CURVE_COLUMNS,
)

#: Shock factor f_s against cycles per hour Z_h (errata E4: the higher factor at a boundary), the
#: source's table, ``catalogs/factors/shock-source.csv``; a case may name another
#: (``[gearbox] shock_factors``).
SHOCK_FACTORS = factor_table("shock")

_n_2 = Symbol("n_2", "n_{2}", "speed", "rpm", "output speed")
_i = Symbol("i", "i", "dimensionless", "", "ratio")

n_1 = Formula(
    Symbol("n_1", "n_{1}", "speed", "rpm", "input speed"),
    (_n_2, _i),
    lambda sp, n_2, i: n_2 * i,
    "source, S1 criterion 1 (errata E1: n_2m · i <= n_1N) and S5 criterion 1 (errata E5: n_2max · i <= n_1max)",
)

T_2max = Formula(
    Symbol("T_2max", r"T_{2\,\mathrm{max}}", "torque", "N*m", "maximum output torque"),
    (
        Symbol("T_1B", "T_{1B}", "torque", "N*m", "maximum torque of the motor"),
        _i,
        Symbol("f_s", "f_{s}", "dimensionless", "", "shock factor"),
        Symbol("eta", r"\eta", "dimensionless", "", "efficiency of the gearbox"),
    ),
    lambda sp, T_1B, i, f_s, eta: sp.Mul(T_1B, i, f_s, eta, evaluate=False),  # in the source's order
    "source, S5 calculation 2",
)

inertia_ratio = Formula(
    Symbol("lambda", r"\lambda", "dimensionless", "", "load to motor inertia ratio"),
    (
        Symbol("J_1", "J_{1}", "inertia", "kg*cm**2", "gearbox inertia at the input"),
        Symbol("J_L", "J_{L}", "inertia", "kg*cm**2", "load inertia at the output"),
        _i,
        Symbol("J_motor", r"J_{\mathrm{motor}}", "inertia", "kg*cm**2", "motor inertia"),
    ),
    lambda sp, J_1, J_L, i, J_motor: (J_1 + J_L / i**2) / J_motor,
    "source, S5 criterion 3 (J_motor ≈ J_1 + J_L / i²); errata E6 (reported as a ratio, 1 is ideal)",
)


def shock_factor(cycles_per_hour, table=SHOCK_FACTORS):
    """Shock factor ``f_s`` for ``Z_h`` cycles per hour (errata E4), scalar or array.

    The table is :data:`SHOCK_FACTORS` unless another is given; a value within :data:`calc.checks.BOUNDARY_RTOL` below a
    boundary counts as on it (:class:`calc.bands.BandTable`): a cycle of 0.1 + 0.1 + 0.1 + 2.1 s =
    2.4000000000000004 s gives 1499.9999999999998 cycles per hour, which is 1500. A negative
    ``Z_h`` is refused.

    >>> [float(shock_factor(Q_(z, "1/hour"))) for z in (999, 1000, 1499, 1500, 2000, 3000)]
    [1.0, 1.1, 1.1, 1.3, 1.6, 2.0]
    >>> float(shock_factor(Z_h(t_cycle=Q_(0.1 + 0.1 + 0.1 + 2.1, "s"))))
    1.3
    """
    return table.lookup(cycles_per_hour, "cycles_per_hour")


@dataclass
class Candidate:
    """One gearbox with its checks (:class:`calc.checks.Check`), as listed in results and notebooks."""

    part: str
    ratio: float
    passes: bool | None  # None: every governing check made passes, but one could not be made
    checks: list
    T_2max: object
    inertia_ratio: float | None
    reasons: list
    illustrative: bool


@dataclass
class GearboxSelection:
    """The catalog rows at the desired ratio, checked and ranked.

    Arrays are over the rows of ``catalog`` in catalog order; ``order`` ranks them best first.
    """

    catalog: Catalog
    mode: str
    checks: list
    T_2max: object  # quantity array, or None without the motor's peak torque
    inertia_ratio: object  # float array, or None without the inertias
    passes: np.ndarray  # every governing check that could be made passes
    worst: np.ndarray  # highest utilization of the governing checks (NaN where one has no rating)
    order: np.ndarray

    @property
    def governing(self) -> list:
        return [c for c in self.checks if c.mode == self.mode]

    @property
    def not_made(self) -> list:
        """The governing checks that could not be made (an input is missing)."""
        return [c for c in self.governing if not c.made]

    @property
    def selected(self) -> str | None:
        """Part number of the best passing candidate, or None (also when a governing check
        could not be made)."""
        return None if self.not_made else selected_part(self.catalog.parts, self.passes, self.order)

    def reasons(self, row: int) -> list[str]:
        """Why a row does not pass: each failing governing check with its excess, and each
        governing check that could not be made."""
        return [c.reason(row) for c in self.governing if not c.passes[row]]

    def candidate(self, row: int) -> Candidate:
        """One row as a :class:`Candidate`."""
        lam = None if self.inertia_ratio is None else float(self.inertia_ratio[row])
        passes = bool(self.passes[row])
        return Candidate(
            part=str(self.catalog.parts[row]),
            ratio=float(self.catalog["ratio"][row].m_as("")),
            passes=None if passes and self.not_made else passes,
            checks=[c.at(row, governs=c.mode == self.mode) for c in self.checks],
            T_2max=None if self.T_2max is None else self.T_2max[row],
            inertia_ratio=None if lam is None or np.isnan(lam) else lam,
            reasons=self.reasons(row),
            illustrative=bool(self.catalog.illustrative[row]),
        )

    def candidates(self, limit: int | None = None) -> list[Candidate]:
        """The rows as :class:`Candidate` objects, best first; the first ``limit`` (all for None)."""
        return [self.candidate(row) for row in (self.order if limit is None else self.order[:limit])]


def rows_at_ratio(catalog: Catalog, ratio, where: str = "ratio") -> Catalog:
    """The rows of ``catalog`` whose ratio equals ``ratio`` (to 1 part in 10⁶)."""
    i = as_kind(ratio, "dimensionless", where).m_as("")
    if not i > 0:
        raise CalcError(f"{where}: expected a ratio above zero, found {i:g}")
    mask = np.isclose(catalog["ratio"].m_as(""), i, rtol=1e-6, atol=0)
    if not mask.any():
        ratios = ", ".join(f"{r:g}" for r in sorted(set(catalog["ratio"].m_as("").tolist())))
        raise CalcError(f"{where}: no gearbox in catalog {catalog.path} has ratio {i:g}; its ratios are {ratios}")
    return catalog.rows(mask)


def select_gearbox(
    profile: Profile,
    catalog: Catalog,
    motor_peak_torque=None,
    motor_inertia=None,
    load_inertia=None,
    shock_factors=SHOCK_FACTORS,
) -> GearboxSelection:
    """Check every row of ``catalog`` (already narrowed to the desired ratio, or to one part).

    S1 checks: ``n_2m · i <= n_1N`` (E1), ``T_2m <= T_2N`` (E2). S5 checks: ``n_2max · i <=
    n_1max`` (E5), ``T_2max <= T_2B`` with ``T_2max = T_1B · i · f_s · η`` (E4), which is not made
    without the motor's peak torque ``T_1B`` (it says so; no part is then selected in S5). The
    operating mode of the profile (E3) says which group governs ``passes``; the other group is
    reported for information. The inertia ratio (E6) is given when both inertias are.
    ``shock_factors`` is the table of ``f_s`` (:data:`SHOCK_FACTORS`, the source's, by default).
    """
    d = duty(profile)
    i = catalog["ratio"]
    seg = profile.moving_values()
    checks = [
        CheckArray("n_1N", "S1", "n_2m · i <= n_1N", n_1(n_2=n_2m(n_2k=seg["n_2k"], t_k=seg["t_k"]), i=i), catalog["n_1N"], "rpm"),
        CheckArray("T_2N", "S1", "T_2m <= T_2N", T_2m(**seg) * np.ones(len(catalog)), catalog["T_2N"], "N*m"),
    ]
    checks.append(CheckArray("n_1max", "S5", "n_2max · i <= n_1max", n_1(n_2=profile.n_2max, i=i), catalog["n_1max"], "rpm"))
    t2max = None
    if motor_peak_torque is not None:
        f_s = shock_factor(Z_h(t_cycle=profile.t_cycle), shock_factors)
        t2max = T_2max(T_1B=motor_peak_torque, i=i, f_s=Q_(f_s, ""), eta=catalog["eta"])
        checks.append(CheckArray("T_2B", "S5", "T_2max <= T_2B", t2max, catalog["T_2B"], "N*m"))
    else:
        needs = "T_2max = T_1B · i · f_s · η needs the motor's peak torque T_1B (motor.peak_torque)"
        checks.append(CheckArray("T_2B", "S5", "T_2max <= T_2B", None, catalog["T_2B"], "N*m", not_made=needs))
    lam = None
    if motor_inertia is not None and load_inertia is not None:
        lam = inertia_ratio(J_1=catalog["J_1"], J_L=load_inertia, i=i, J_motor=motor_inertia).m_as("")
    governing = [c for c in checks if c.mode == d.mode]
    passes = np.logical_and.reduce([c.passes for c in governing if c.made])
    worst = np.max([c.utilization for c in governing if c.made], axis=0)
    size = catalog["T_2B" if d.mode == "S5" else "T_2N"].m_as("N*m")
    order = rank(passes, size, worst, catalog.parts, illustrative=catalog.illustrative)
    return GearboxSelection(catalog, d.mode, checks, t2max, lam, passes, worst, order)


def candidates_table(selection: GearboxSelection):
    """Every check of every candidate as a pandas DataFrame, best candidate first.

    Columns: ``rank`` (1 is best), ``part``, ``check`` (the criterion), ``governs`` (the check
    belongs to the governing mode, E3), ``required``, ``rated`` and ``unit`` (rpm or N·m),
    ``utilization`` (required / rated; NaN where the catalog gives no rating) and ``verdict``
    (``pass`` or ``FAIL``). Values are not rounded; round them for display.

    >>> from calc.catalog import load_catalog, resolve
    >>> from calc.profile import Profile
    >>> p = Profile.from_segments([("const", Q_(1, "s"), Q_(240, "rpm"), Q_(40, "N*m")), ("pause", Q_(1, "s"), None, None)])
    >>> rows = rows_at_ratio(load_catalog(resolve("gearboxes", None, "catalog"), SCHEMA), 10)
    >>> t = candidates_table(select_gearbox(p, rows, motor_peak_torque=Q_(12, "N*m")))
    >>> t.loc[t.part == "NPT035-10", ["check", "verdict"]].values.tolist()
    [['n_2m · i <= n_1N', 'FAIL'], ['T_2m <= T_2N', 'pass'], ['n_2max · i <= n_1max', 'pass'], ['T_2max <= T_2B', 'pass']]

    ``T_2max`` = 12 N·m · 10 · 1.3 (Z_h = 1800 1/h) · 0.97 = 151.32 N·m against ``T_2B`` = 220 N·m:

    >>> t.loc[(t.part == "NPT035-10") & t.governs, ["required", "rated", "utilization"]].round(4).values.tolist()
    [[2400.0, 6000.0, 0.4], [151.32, 220.0, 0.6878]]
    """
    import pandas as pd

    order = selection.order
    n = len(order)
    frames = []
    for position, c in enumerate(selection.checks):
        unit = c.unit
        frames.append(
            pd.DataFrame(
                {
                    "rank": np.arange(1, n + 1),
                    "part": selection.catalog.parts[order].astype(str),
                    "check": c.text,
                    "governs": c.mode == selection.mode,
                    "required": c.required[order].m_as(unit) if c.made else np.full(n, np.nan),
                    "rated": c.rated[order].m_as(unit),
                    "unit": pretty_unit(unit),
                    "utilization": c.utilization[order],
                    "verdict": np.where(c.passes[order], "pass", "FAIL") if c.made else "not checked",
                    "_position": position,
                }
            )
        )
    table = pd.concat(frames).sort_values(["rank", "_position"], kind="stable")
    return table.drop(columns="_position").reset_index(drop=True)


def candidates_summary(selection: GearboxSelection):
    """One row per candidate, best first, as a pandas DataFrame: the verdict and why.

    Columns: ``rank``, ``part``, ``verdict`` (``PASS``/``FAIL`` on the governing checks),
    ``worst utilization`` (highest of the governing checks), ``T_2max [N·m]`` (S5, when the motor's
    peak torque is given), ``inertia ratio`` (E6, when both inertias are given), ``illustrative``
    (the catalog row is marked as illustrative) and ``reasons`` (each failed governing check with
    its excess; empty for a pass).
    """
    import pandas as pd

    order = selection.order
    worst = selection.worst[order]
    n = len(order)
    table = pd.DataFrame(
        {
            "rank": np.arange(1, n + 1),
            "part": selection.catalog.parts[order].astype(str),
            "verdict": np.where(selection.passes[order], "PASS", "FAIL"),
            "worst utilization": worst,
            "T_2max [N·m]": np.full(n, np.nan) if selection.T_2max is None else selection.T_2max[order].m_as("N*m"),
            "inertia ratio": np.full(n, np.nan) if selection.inertia_ratio is None else selection.inertia_ratio[order],
            "illustrative": selection.catalog.illustrative[order],
            "reasons": ["; ".join(selection.reasons(row)) for row in order],
        }
    )
    return table
