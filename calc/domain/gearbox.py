"""Gearbox selection for continuous (S1) and cyclic (S5) operation.

Source: "Selection of Optimum Gearbox for a Continuous Operation (S1)" and "... for a Cycle
Operation (S5)", read with errata E1 to E6. Every row of a catalog at the desired ratio is
evaluated at once (numpy arrays over the rows, no per-row Python loop); each criterion is kept
with its required value, rated value, utilization (required / rated) and verdict.

The emergency stop (``T_2Not``, the catalog's emergency-stop rating) is checked in both modes:
the torque of an emergency stop does not depend on the duty. Where a row gives no ``T_2Not`` it is
not checked for it (and says so); where the case gives neither the stop torque nor the motor's
peak torque, the check is not made and is reported for information only.

Ranking rule (:func:`rank`): passing candidates first, and among them rows of published data
before rows marked illustrative (a part is not chosen on illustrative figures while a published
one fits); then the smallest adequate size, measured by the governing torque rating (``T_2B`` in
S5, ``T_2N`` in S1), then the larger margin (lower worst utilization of the governing checks);
failing candidates after, closest to passing first (lowest worst utilization). Ties go by part
name. Partial rows of a catalog (its ``partial`` column) are never ranked; the ranking runs across
families and marks the smallest adequate size of each (:attr:`GearboxSelection.best_of_family`).
The output bearing's checks (:func:`bearing_checks`) and the clamping hub's govern in both modes.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ..data.bands import factor_table
from ..data.catalog import Catalog, Column, Rule, Schema, no_less
from ..core.errors import CalcError, listing
from ..core.formula import Formula
from ..core import selection
from ..core.checks import CheckArray, rank
from ..core.citation import Source
from .documents import CASE_FORMAT, ERRATA, SOURCE, WITTENSTEIN
from .profile import Profile, T_2m, Z_h, duty, n_2m
from .torsion import CouplingSpan, highest_first_mode
from ..core.selection import Selection
from ..core.units import Q_, Value, as_kind, pretty_unit

#: The columns of a gearbox's stiffness curve, all five or none in a row (calc.domain.stiffness.StiffnessCurve).
CURVE_COLUMNS = ("T_L1", "T_L2", "K_1", "K_2", "K_3")

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
        *(
            Column(name, kind_name, description, required=False, may_be_absent=True)
            for name, kind_name, description in (
                ("J_1_hub", "length", "bore of the clamping hub that J_1 is for"),
                ("F_2A", "force", "maximum axial force on the output"),
                ("F_2R", "force", "maximum radial (lateral) force on the output"),
                ("M_2K", "torque", "maximum tilting moment on the output bearing"),
                ("z_2", "length", "distance from the output flange to the bearing's centre (tilting moment)"),
                ("stages", "dimensionless", "number of gear stages"),
                ("backlash_reduced", "angle", "torsional backlash, reduced-backlash version"),
                ("T_2a", "torque", "maximum output torque"),
                ("T_012", "torque", "no-load torque"),
                ("C_2K", "stiffness", "tilting rigidity of the output"),
                ("m", "mass", "mass"),
                # A stiffness curve (strain-wave gears, calc.domain.stiffness.StiffnessCurve): limit torques and slopes.
                ("T_L1", "torque", "first limit torque of the stiffness curve (T1)"),
                ("T_L2", "torque", "second limit torque of the stiffness curve (T2)"),
                ("K_1", "stiffness", "stiffness from 0 to T_L1"),
                ("K_2", "stiffness", "stiffness from T_L1 to T_L2"),
                ("K_3", "stiffness", "stiffness above T_L2"),
            )
        ),
    ),
    text_columns=("part", "series", "source"),
    optional_text=("illustrative", "family", "size", "partial", "unclear"),
    partial="partial",
    rules=(
        Rule("T_2B >= T_2N", no_less("T_2B", "T_2N"), "T_2B"),
        Rule("T_2Not >= T_2B", no_less("T_2Not", "T_2B"), "T_2Not"),
        Rule("n_1max >= n_1N", no_less("n_1max", "n_1N"), "n_1max"),
        Rule("efficiency eta in (0, 1]", lambda v: (v["eta"].m_as("") <= 1.0), "eta"),
        Rule(
            "a stiffness curve in all of T_L1, T_L2, K_1, K_2, K_3 or in none",
            lambda v: np.isin(sum(np.isnan(v[name].magnitude).astype(int) for name in CURVE_COLUMNS),
                              (0, len(CURVE_COLUMNS))),
            "K_3",
        ),
        Rule("T_L2 > T_L1", lambda v: ~(v["T_L2"] <= v["T_L1"]), "T_L2"),
    ),
)

#: Clamping hubs of the gearboxes: one row per gearbox and hub bore, with the gearbox's J_1 for it.
HUB_SCHEMA = Schema(
    kind="gearbox clamping hub",
    columns=(
        Column("d_hub", "length", "bore of the clamping hub"),
        Column("J_1", "inertia", "mass moment of inertia referred to the input, with this hub"),
    ),
    text_columns=("part", "gearbox", "source"),
)

#: Shock factor f_s against cycles per hour Z_h (errata E4: the higher factor at a boundary), the
#: source's table, ``catalogs/factors/shock-source.csv``; a case may name another
#: (``[gearbox] shock_factors``).
SHOCK_FACTORS = factor_table("shock")

n_1 = Formula(
    "n_1",
    ("n_2", "i"),
    lambda sp, n_2, i: n_2 * i,
    Source(SOURCE.at("S1 criterion 1", note=ERRATA.at("E1", says="n_2m · i <= n_1N")),
           SOURCE.at("S5 criterion 1", label="S5 criterion 1", note=ERRATA.at("E5", says="n_2max · i <= n_1max")),
           joined=" and "),
)

T_2max = Formula(
    "T_2max",
    ("T_1B", "i", "f_s", "eta"),
    lambda sp, T_1B, i, f_s, eta: sp.Mul(T_1B, i, f_s, eta, evaluate=False),  # in the source's order
    Source(SOURCE.at("S5 calculation 2"),
           SOURCE.at("S5 calculation 2", label="read as written",
                     says="η credited, as for a peak the motor drives through the gearbox",
                     note="a braking peak, the load driving back, reaches the output as T_1B · i / η, higher by 1/η²")),
)

T_2stop = Formula(
    "T_2stop",
    ("T_1B", "i"),
    lambda sp, T_1B, i: T_1B * i,
    Source(CASE_FORMAT.at("Emergency stop", says="the motor's peak through the gearbox, no credit for efficiency",
                          note="η = 1")),
)

inertia_ratio = Formula(
    "lambda",
    ("J_1", "J_L", "i", "J_motor"),
    lambda sp, J_1, J_L, i, J_motor: (J_1 + J_L / i**2) / J_motor,
    Source(SOURCE.at("S5 criterion 3", note="J_motor ≈ J_1 + J_L / i²"),
           ERRATA.at("E6", note="reported as a ratio, 1 is ideal")),
)

#: E6: servo practice keeps the load to motor inertia ratio λ below roughly 5 to 10; the upper end is
#: the limit where a case gives none (``[motor] max_inertia_ratio``).
INERTIA_RATIO_LIMIT = 10.0


M_2k = Formula(
    "M_2k",
    ("F_2a", "y_2", "F_2r", "x_2", "z_2"),
    lambda sp, F_2a, y_2, F_2r, x_2, z_2: sp.Add(F_2a * y_2, F_2r * sp.Add(x_2, z_2, evaluate=False), evaluate=False),
    Source(WITTENSTEIN.at("output bearing", says="M_2k = F_2a · y_2 + F_2r · (x_2 + z_2), read as documented in "
                                                 "calc.domain.gearbox.bearing_checks",
                          note="z_2 is not in the published data reached; 0 where the catalog gives none")),
)


@dataclass(frozen=True)
class OutputForces:
    """External forces on the gearbox output (``[load]``): each None where the case gives none.

    Parameters
    ----------
    axial_force : pint.Quantity [N], optional
        ``F_2a``.
    radial_force : pint.Quantity [N], optional
        ``F_2r``.
    lever_arm : pint.Quantity [mm], optional
        ``x_2``, from the output flange to the radial force.
    axial_radius : pint.Quantity [mm], optional
        ``y_2``, from the axis to the axial force's line of action.
    """

    axial_force: object = None  # F_2a
    radial_force: object = None  # F_2r
    lever_arm: object = None  # x_2, from the output flange to the radial force
    axial_radius: object = None  # y_2, from the axis to the axial force's line of action

    @property
    def given(self) -> bool:
        return self.axial_force is not None or self.radial_force is not None


def bearing_checks(load: OutputForces, catalog: Catalog) -> list:
    """The output bearing's checks against the catalog's ratings, every row at once.

    ``F_2a <= F_2A`` (axial), ``F_2r <= F_2R`` (radial) and ``M_2k <= M_2K`` (tilting moment,
    :data:`M_2k`), each made when the case gives its force; a row whose catalog gives no rating
    is not checked ("the catalog gives no F_2R") and does not fail. They govern in both modes.

    Parameters
    ----------
    load : OutputForces
        The forces the case gives.
    catalog : Catalog
        Rows of :data:`SCHEMA`.

    Returns
    -------
    list of CheckArray
        One check per force given, over the rows.

    Notes
    -----
    The tilting moment is read as WITTENSTEIN's alpha catalogues write it, ``M_2k = F_2a · y_2 +
    F_2r · (x_2 + z_2)``: the radial force acts at its lever arm ``x_2`` from the output flange
    plus the distance ``z_2`` from the flange to the bearing's centre, and an axial force acting
    off the axis (at ``y_2``) adds its own moment. The published data reached gives no ``z_2``
    (``SOURCES.md``), so where the catalog's ``z_2`` column is empty the moment is taken at the
    flange (``z_2 = 0``), which understates it by ``F_2r · z_2``: the check then says so. The
    forces are static maxima of the cycle; no bearing life is computed (no dynamic load rating
    is published).

    >>> from calc.data.catalog import load_catalog, resolve
    >>> rows = load_catalog(resolve("gearboxes", None, "catalog"), SCHEMA)
    >>> rows = rows.rows([rows.index("NPT035-10", "part")])
    >>> [c.at(0).criterion for c in bearing_checks(OutputForces(Q_(1000, "N"), Q_(500, "N"), Q_(50, "mm")), rows)]
    ['F_2a <= F_2A', 'F_2r <= F_2R', 'M_2k <= M_2K']
    """
    n = len(catalog)
    checks = []
    zero = Q_(0.0, "mm")
    if load.axial_force is not None:
        checks.append(CheckArray("F_2A", None, "F_2a <= F_2A", load.axial_force * np.ones(n), catalog["F_2A"], "N",
                                 unrated="the catalog gives no F_2A"))
    if load.radial_force is not None:
        checks.append(CheckArray("F_2R", None, "F_2r <= F_2R", load.radial_force * np.ones(n), catalog["F_2R"], "N",
                                 unrated="the catalog gives no F_2R"))
    if load.given:
        z_2 = catalog["z_2"]
        moment = M_2k(
            F_2a=load.axial_force if load.axial_force is not None else Q_(0.0, "N"),
            y_2=load.axial_radius if load.axial_radius is not None else zero,
            F_2r=load.radial_force if load.radial_force is not None else Q_(0.0, "N"),
            x_2=load.lever_arm if load.lever_arm is not None else zero,
            z_2=Q_(np.nan_to_num(z_2.m_as("mm")), "mm"),
        ) * np.ones(n)
        checks.append(CheckArray("M_2K", None, "M_2k <= M_2K", moment, catalog["M_2K"], "N*m",
                                 unrated="the catalog gives no M_2K"))
    return checks


def clamping_hubs(catalog: Catalog, hubs: Catalog | None, motor_shaft=None):
    """J_1 of each row for its clamping hub, the hub's bore, and the largest hub bore listed.

    Without ``motor_shaft`` a row's J_1 is the catalog's (for the hub in its ``J_1_hub`` column,
    the smallest listed in the shipped data). With it, the smallest hub of ``hubs`` whose bore
    takes the shaft (``d_hub >= d``) gives J_1; a row with hubs listed but none that fits has no
    J_1 (the hub check fails); a row with no hubs listed keeps the catalog's J_1.

    Parameters
    ----------
    catalog : Catalog
        Rows of :data:`SCHEMA`.
    hubs : Catalog or None
        Rows of :data:`HUB_SCHEMA`, the clamping hubs of each gearbox.
    motor_shaft : pint.Quantity [mm], optional
        The motor's shaft diameter ``d``.

    Returns
    -------
    tuple of numpy.ndarray
        ``(J_1 [kg·cm²], d_hub [mm], d_hub_max [mm])``, float arrays over the rows.

    Examples
    --------
    >>> from calc.data.catalog import load_catalog, resolve
    >>> cat = load_catalog(resolve("gearboxes", None, "catalog"), SCHEMA)
    >>> hubs = load_catalog(resolve("gearbox-hubs", None, "catalog"), HUB_SCHEMA)
    >>> row = cat.rows([cat.index("TP010-10", "part")])
    >>> [a.tolist() for a in clamping_hubs(row, hubs, Q_(16, "mm"))]
    [[0.57], [19.0], [24.0]]
    """
    J_1 = catalog["J_1"].m_as("kg*cm**2").copy()
    d_hub = catalog["J_1_hub"].m_as("mm").copy()
    d_max = np.full(len(catalog), np.nan)
    if hubs is None:
        return J_1, d_hub, d_max
    shaft = None if motor_shaft is None else as_kind(motor_shaft, "length", "motor.shaft").m_as("mm")
    row_of = catalog.row_of_part
    best = np.full(len(catalog), np.inf)
    best_J = np.full(len(catalog), np.nan)
    for gearbox, d, j in zip(hubs.text["gearbox"].tolist(), hubs["d_hub"].m_as("mm").tolist(),
                             hubs["J_1"].m_as("kg*cm**2").tolist()):
        k = row_of.get(gearbox)
        if k is None:
            continue
        d_max[k] = d if np.isnan(d_max[k]) else max(d_max[k], d)
        if shaft is not None and shaft <= d < best[k]:
            best[k], best_J[k] = d, j
    if shaft is not None:
        listed = ~np.isnan(d_max)
        J_1[listed], d_hub[listed] = best_J[listed], np.where(np.isinf(best), np.nan, best)[listed]
    return J_1, d_hub, d_max


def shock_factor(cycles_per_hour, table=SHOCK_FACTORS):
    """Shock factor ``f_s`` for ``Z_h`` cycles per hour (errata E4), scalar or array.

    A value within :data:`calc.core.checks.BOUNDARY_RTOL` below a boundary counts as on it
    (:class:`calc.data.bands.BandTable`): a cycle of 0.1 + 0.1 + 0.1 + 2.1 s =
    2.4000000000000004 s gives 1499.9999999999998 cycles per hour, which is 1500. A negative
    ``Z_h`` is refused.

    Parameters
    ----------
    cycles_per_hour : pint.Quantity [1/h]
        ``Z_h``, scalar or array.
    table : BandTable
        ``f_s`` against ``Z_h``; default :data:`SHOCK_FACTORS`.

    Returns
    -------
    float or numpy.ndarray [1]
        ``f_s``.

    Examples
    --------
    >>> [float(shock_factor(Q_(z, "1/hour"))) for z in (999, 1000, 1499, 1500, 2000, 3000)]
    [1.0, 1.1, 1.1, 1.3, 1.6, 2.0]
    >>> float(shock_factor(Z_h(z_c=Q_(1, ""), t_cycle=Q_(0.1 + 0.1 + 0.1 + 2.1, "s"))))
    1.3
    """
    return table.lookup(cycles_per_hour, "cycles_per_hour")


@dataclass(kw_only=True)
class Candidate(selection.Candidate):
    """One gearbox with its checks, as every output lists it (the fields of
    :class:`calc.core.selection.Candidate`, and these).

    Parameters
    ----------
    ratio : float
        Its ratio ``i`` [1].
    T_2max : Value [N·m], optional
        The peak output torque; None without the motor's peak torque.
    inertia_ratio : float, optional
        ``λ`` (E6) [1]; None without the inertias.
    J_1 : Value [kg·cm²], optional
        Its input inertia for the clamping hub of ``J_1_hub`` (no value where unknown).
    J_1_hub : Value [mm], optional
        The hub bore ``J_1`` is for.
    best_of_family : bool
        The best-ranked passing candidate of its family.
    """

    ratio: float
    T_2max: Value | None = None  # None without the motor's peak torque
    inertia_ratio: float | None = None
    J_1: Value | None = None  # for the clamping hub of J_1_hub (no value where unknown)
    J_1_hub: Value | None = None
    best_of_family: bool = False  # the best-ranked passing candidate of its family


@dataclass
class GearboxSelection(Selection):
    """The catalog rows at the desired ratio, checked and ranked.

    Arrays are over the rows of ``catalog`` in catalog order; ``order`` ranks them best first.

    Parameters
    ----------
    catalog : Catalog
        The rows checked.
    mode : str
        The profile's operating mode, ``"S1"`` or ``"S5"`` (E3).
    checks : list of CheckArray
        Every check, governing or not.
    T_2max : pint.Quantity [N·m] or None
        The peak output torque per row; None without the motor's peak torque.
    inertia_ratio : numpy.ndarray or None
        ``λ`` per row [1]; None without the inertias.
    passes : numpy.ndarray of bool
        Every governing check that could be made passes.
    worst : numpy.ndarray [1]
        Highest utilization of the governing checks (NaN where one has no rating).
    order : numpy.ndarray of int
        The rows, best first.
    J_1 : pint.Quantity [kg·cm²], optional
        Each row's J_1 for its clamping hub (:func:`clamping_hubs`).
    J_1_hub : pint.Quantity [mm], optional
        The hub bore J_1 is for (NaN where unknown).
    notes : list of str, optional
        What the outputs say besides the checks.
    """

    catalog: Catalog
    mode: str
    checks: list
    T_2max: object  # quantity array, or None without the motor's peak torque
    inertia_ratio: object  # float array, or None without the inertias
    passes: np.ndarray  # every governing check that could be made passes
    worst: np.ndarray  # highest utilization of the governing checks (NaN where one has no rating)
    order: np.ndarray
    J_1: object = None  # quantity array: each row's J_1 for its clamping hub (clamping_hubs)
    J_1_hub: object = None  # quantity array: the hub bore J_1 is for (NaN where unknown)
    notes: list = None

    candidate_type = Candidate

    def governs(self, check: CheckArray) -> bool:
        """Whether a check decides the verdict (:func:`governs`).

        Parameters
        ----------
        check : CheckArray
            One of the selection's checks.

        Returns
        -------
        bool
            True for a governing check in the selection's mode.
        """
        return governs(check, self.mode)

    @functools.cached_property
    def best_of_family(self) -> np.ndarray:
        """True for the best-ranked passing row of each family: the smallest adequate size of
        that family, by the ranking rule."""
        out = np.zeros(len(self.catalog), bool)
        passing = self.order[self.passes[self.order]]
        # Each family's first row in rank order: a dict built from the last row back keeps the first.
        first = dict(zip(self.catalog.family[passing[::-1]].tolist(), passing[::-1].tolist()))
        out[list(first.values())] = True
        return out

    def row_fields(self, row: int) -> dict:
        lam = None if self.inertia_ratio is None else float(self.inertia_ratio[row])
        part = str(self.catalog.parts[row])
        return dict(
            ratio=float(self.catalog["ratio"][row].m_as("")),
            T_2max=None if self.T_2max is None else Value.of(self.T_2max[row], "N*m", f"gearbox {part}: T2max"),
            inertia_ratio=None if lam is None or np.isnan(lam) else lam,
            J_1=Value.of(self.J_1[row], "kg*cm**2", f"gearbox {part}: J_1"),
            J_1_hub=Value.of(self.J_1_hub[row], "mm", f"gearbox {part}: J_1_hub"),
            best_of_family=bool(self.best_of_family[row]),
        )


#: The mode of the drive train's check (``2 f_er <= f_1,max``): for information and the ranking, in
#: either operating mode.
TRAIN = "drive train"


def governs(check: CheckArray, mode: str) -> bool:
    """Whether a gearbox check decides the verdict in operating mode ``mode`` (E3): a check of that
    mode does; a check of no mode (the emergency stop, the output bearing, the clamping hub) does
    in both, once it can be made.

    Parameters
    ----------
    check : CheckArray
        The check.
    mode : str
        ``"S1"`` or ``"S5"``.

    Returns
    -------
    bool
        True for a governing check.
    """
    return check.mode == mode if check.mode is not None else check.made


#: Two ratios are the same to this relative tolerance: a catalog's 10 is the case's 10.000001.
RATIO_RTOL = 1e-6


def same_ratio(a, b):
    """Whether ratios are the same (to :data:`RATIO_RTOL`), element-wise over arrays.

    Parameters
    ----------
    a, b : float or numpy.ndarray [1]
        The ratios.

    Returns
    -------
    bool or numpy.ndarray of bool
        True where they are the same.

    Examples
    --------
    >>> bool(same_ratio(10.0, 10.000001)), bool(same_ratio(10.0, 10.1))
    (True, False)
    """
    return np.isclose(a, b, rtol=RATIO_RTOL, atol=0)


def rows_at_ratio(catalog: Catalog, ratio, where: str = "ratio") -> Catalog:
    """The rows of ``catalog`` whose ratio equals ``ratio`` (:func:`same_ratio`).

    Parameters
    ----------
    catalog : Catalog
        Rows of :data:`SCHEMA`.
    ratio : float or pint.Quantity [1]
        The ratio ``i``.
    where : str
        The key, for error messages; default ``"ratio"``.

    Returns
    -------
    Catalog
        The rows at that ratio, partial rows left out.

    Raises
    ------
    CalcError
        Where no usable row has the ratio, naming the catalog's ratios.
    """
    i = as_kind(ratio, "dimensionless", where).m_as("")
    if not i > 0:
        raise CalcError(f"{where}: expected a ratio above zero, found {i:g}")
    at_ratio = same_ratio(catalog["ratio"].m_as(""), i)
    mask = at_ratio & ~catalog.partial
    if not mask.any():
        usable = catalog["ratio"].m_as("")[~catalog.partial]
        ratios = listing(f"{r:g}" for r in sorted(set(usable.tolist())))
        partial = (f" (only partial rows, never checked: {listing(catalog.parts[at_ratio], limit=6)})" if at_ratio.any()
                   else "")
        raise CalcError(f"{where}: no gearbox in catalog {catalog.shown_name} has ratio {i:g}{partial}; its ratios are "
                        f"{ratios}")
    return catalog.kept_rows(("ratio", i), mask)


def select_gearbox(
    profile: Profile,
    catalog: Catalog,
    motor_peak_torque=None,
    motor_inertia=None,
    load_inertia=None,
    emergency_stop_torque=None,
    output_load: OutputForces | None = None,
    hubs: Catalog | None = None,
    motor_shaft=None,
    shock_factors=SHOCK_FACTORS,
    coupling_span: CouplingSpan | None = None,
) -> GearboxSelection:
    """Check every row of ``catalog`` (already narrowed to the desired ratio, or to one part).

    S1 checks: ``n_2m · i <= n_1N`` (E1), ``T_2m <= T_2N`` (E2). S5 checks: ``n_2max · i <=
    n_1max`` (E5), ``T_2max <= T_2B`` with ``T_2max = T_1B · i · f_s · η`` (E4), which is not made
    without the motor's peak torque ``T_1B`` (it says so; no part is then selected in S5).
    ``T_2max`` is read as the source writes it, a reading like the errata's: the efficiency is
    credited, as for a peak the motor drives through the gearbox; a braking peak, with the load
    driving back through the gearbox, reaches the output as ``T_1B · i / η``, higher by ``1/η²``
    (6.3 % at η = 0.97). The
    operating mode of the profile (E3) says which group governs ``passes``; the other group is
    reported for information. In both modes the emergency-stop torque (``emergency_stop_torque``,
    default ``T_2stop = T_1B · i``) is checked against the catalog's ``T_2Not`` where a row gives
    one. The inertia ratio (E6) is given when both inertias are, with each
    row's J_1 for its clamping hub (:func:`clamping_hubs`: the smallest of ``hubs`` that takes
    ``motor_shaft``, checked ``d <= d_hub,max``). The output bearing's checks
    (:func:`bearing_checks`) are made when ``output_load`` gives a force; they and the hub check
    govern in both modes. ``shock_factors`` is the table of ``f_s`` (:data:`SHOCK_FACTORS`, the
    source's, by default). With ``coupling_span`` (the couplings a case may fit between motor and
    gearbox) each row's drive train is checked, for information, for the highest first mode any of
    those couplings gives it, ``2 f_er <= f_1,max`` (:func:`calc.domain.torsion.highest_first_mode`). The
    gearbox is the train's soft spring: the ranking puts the passing rows this check shows to clear
    the excitation before the others (a row it fails, or cannot check for want of ``C_t21``), as it
    puts published rows before illustrative ones; the resonance itself is decided by the coupling
    that is chosen (:func:`calc.domain.coupling.select_coupling`), not here.

    Parameters
    ----------
    profile : Profile
        The load cycle at the gearbox output.
    catalog : Catalog
        Rows of :data:`SCHEMA`, at the desired ratio or one part.
    motor_peak_torque : pint.Quantity [N·m], optional
        ``T_1B``; without it ``T_2max`` is not checked.
    motor_inertia : pint.Quantity [kg·cm²], optional
        The motor's inertia, for the inertia ratio.
    load_inertia : pint.Quantity [kg·cm²], optional
        The load's inertia at the output, for the inertia ratio.
    emergency_stop_torque : pint.Quantity [N·m], optional
        ``T_2stop``; default ``T_1B · i``.
    output_load : OutputForces, optional
        The forces on the output bearing.
    hubs : Catalog, optional
        Rows of :data:`HUB_SCHEMA`.
    motor_shaft : pint.Quantity [mm], optional
        The motor's shaft diameter.
    shock_factors : BandTable
        ``f_s`` against ``Z_h``; default :data:`SHOCK_FACTORS`.
    coupling_span : CouplingSpan, optional
        The couplings a case may fit between motor and gearbox.

    Returns
    -------
    GearboxSelection
        The rows checked and ranked.
    """
    d = duty(profile)
    i = catalog["ratio"]
    checks, t2max = _duty_checks(profile, catalog, motor_peak_torque, shock_factors)
    checks.append(_emergency_stop_check(catalog, emergency_stop_torque, motor_peak_torque))
    notes = []
    if output_load is not None and output_load.given:
        checks += bearing_checks(output_load, catalog)
        if output_load.radial_force is not None and np.isnan(catalog["z_2"].magnitude).any():
            notes.append(
                "M_2k = F_2a · y_2 + F_2r · (x_2 + z_2) is taken at the output flange (z_2 = 0) where the catalog "
                "gives no "
                "z_2, which understates it by F_2r · z_2"
            )
    J_1, d_hub, d_max = clamping_hubs(catalog, hubs, motor_shaft)
    later = catalog.illustrative
    if coupling_span is not None:
        f_1 = highest_first_mode(coupling_span, Q_(J_1, "kg*cm**2"), catalog["C_t21"], i)
        train = CheckArray("f_1", TRAIN, "2 f_er <= f_1,max", coupling_span.f_min * np.ones(len(catalog)), f_1, "Hz",
                           unrated="the catalog gives no C_t21, or no J_1 for the motor's shaft")
        checks.append(train)
        later = later | ~(train.passes & ~train.unrated_rows)
        notes.append(f"f_1,max is the drive train's first mode with the one of {coupling_span.couplings} that gives it "
                     "the highest; "
                     "passing gearboxes whose f_1,max clears 2 f_er rank first; the coupling section checks the "
                     "coupling it chooses")
    if motor_shaft is not None:
        shaft = as_kind(motor_shaft, "length", "motor.shaft")
        checks.append(
            CheckArray("d_hub", None, "d_motor <= d_hub,max", shaft * np.ones(len(catalog)), Q_(d_max, "mm"), "mm",
                       unrated="the hub table lists no clamping hub of this gearbox")
        )
    lam = None
    if motor_inertia is not None and load_inertia is not None:
        lam = inertia_ratio(J_1=Q_(J_1, "kg*cm**2"), J_L=load_inertia, i=i, J_motor=motor_inertia).m_as("")
    governing = [c for c in checks if governs(c, d.mode)]
    passes = np.logical_and.reduce([c.passes for c in governing if c.made])
    # fmax: a row that a check cannot rate (no T_2Not, no bearing rating) is ranked on its others
    worst = np.fmax.reduce([c.ranked_utilization for c in governing if c.made], axis=0)
    size = catalog["T_2B" if d.mode == "S5" else "T_2N"].m_as("N*m")
    order = rank(passes, size, worst, catalog.parts, later=later)
    return GearboxSelection(
        catalog, d.mode, checks, t2max, lam, passes, worst, order, Q_(J_1, "kg*cm**2"), Q_(d_hub, "mm"), notes
    )


def _duty_checks(profile: Profile, catalog: Catalog, motor_peak_torque, shock_factors):
    """The S1 checks (E1, E2) and the S5 checks (E5, E4) of every row, and ``T_2max`` per row (None
    without the motor's peak torque, when the check of ``T_2B`` is not made)."""
    i = catalog["ratio"]
    seg = profile.moving_values()
    checks = [
        CheckArray("n_1N", "S1", "n_2m · i <= n_1N", n_1(n_2=n_2m(n_2k=seg["n_2k"], t_k=seg["t_k"]), i=i),
                   catalog["n_1N"], "rpm"),
        CheckArray("T_2N", "S1", "T_2m <= T_2N", T_2m(**seg) * np.ones(len(catalog)), catalog["T_2N"], "N*m"),
    ]
    checks.append(CheckArray("n_1max", "S5", "n_2max · i <= n_1max", n_1(n_2=profile.n_2max, i=i), catalog["n_1max"],
                             "rpm"))
    t2max = None
    if motor_peak_torque is not None:
        f_s = shock_factor(Z_h(**profile.cycles_per_hour_inputs()), shock_factors)
        t2max = T_2max(T_1B=motor_peak_torque, i=i, f_s=Q_(f_s, ""), eta=catalog["eta"])
        checks.append(CheckArray("T_2B", "S5", "T_2max <= T_2B", t2max, catalog["T_2B"], "N*m"))
    else:
        needs = "T_2max = T_1B · i · f_s · η needs the motor's peak torque T_1B (motor.peak_torque)"
        checks.append(CheckArray("T_2B", "S5", "T_2max <= T_2B", None, catalog["T_2B"], "N*m", not_made=needs))
    return checks, t2max


def _emergency_stop_check(catalog: Catalog, emergency_stop_torque, motor_peak_torque) -> CheckArray:
    """``T_2stop <= T_2Not`` for every row: the case's emergency-stop torque, else ``T_1B · i``; not
    made without either."""
    stop = "T_2stop <= T_2Not"
    unrated = "the catalog gives no T_2Not"
    if emergency_stop_torque is not None:
        required = as_kind(emergency_stop_torque, "torque", "emergency_stop_torque") * np.ones(len(catalog))
        return CheckArray("T_2Not", None, stop, required, catalog["T_2Not"], "N*m", unrated=unrated)
    if motor_peak_torque is not None:
        required = T_2stop(T_1B=motor_peak_torque, i=catalog["ratio"])
        return CheckArray("T_2Not", None, stop, required, catalog["T_2Not"], "N*m", unrated=unrated)
    needs = ("the emergency-stop torque needs gearbox.emergency_stop_torque or the motor's peak torque "
             "(motor.peak_torque)")
    return CheckArray("T_2Not", None, stop, None, catalog["T_2Not"], "N*m", not_made=needs, unrated=unrated)


def candidates_table(selection: GearboxSelection):
    """Every check of every candidate as a pandas DataFrame, best candidate first.

    Columns: ``rank`` (1 is best), ``part``, ``check`` (the criterion), ``governs`` (the check
    belongs to the governing mode, E3), ``required``, ``rated`` and ``unit`` (rpm or N·m),
    ``utilization`` (required / rated; NaN where the catalog gives no rating) and ``verdict``
    (``pass``, ``FAIL``, or ``not checked`` where a check is not made or the row has no rating it
    may lack, such as ``T_2Not``). Values are not rounded; round them for display.

    Parameters
    ----------
    selection : GearboxSelection
        The checked rows.

    Returns
    -------
    pandas.DataFrame
        One row per check of each candidate.

    Examples
    --------
    >>> from calc.data.catalog import load_catalog, resolve
    >>> from calc.domain.profile import Profile
    >>> p = Profile.from_segments([("const", Q_(1, "s"), Q_(240, "rpm"), Q_(40, "N*m")),
    ...                            ("pause", Q_(1, "s"), None, None)])
    >>> rows = rows_at_ratio(load_catalog(resolve("gearboxes", None, "catalog"), SCHEMA), 10)
    >>> t = candidates_table(select_gearbox(p, rows, motor_peak_torque=Q_(12, "N*m")))
    >>> verdicts = t.loc[t.part == "NPT035-10", ["check", "verdict"]].values.tolist()  # n_1N 3000 rpm at i = 10
    >>> verdicts[:3]
    [['n_2m · i <= n_1N', 'pass'], ['T_2m <= T_2N', 'pass'], ['n_2max · i <= n_1max', 'pass']]
    >>> verdicts[3:]
    [['T_2max <= T_2B', 'pass'], ['T_2stop <= T_2Not', 'pass']]

    ``T_2max`` = 12 N·m · 10 · 1.3 (Z_h = 1800 1/h) · 0.97 = 151.32 N·m against ``T_2B`` = 220 N·m;
    the emergency stop ``T_2stop`` = 12 N·m · 10 = 120 N·m against ``T_2Not`` = 480 N·m:

    >>> t.loc[(t.part == "NPT035-10") & t.governs, ["required", "rated", "utilization"]].round(4).values.tolist()
    [[2400.0, 6000.0, 0.4], [151.32, 220.0, 0.6878], [120.0, 480.0, 0.25]]
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
                    "governs": selection.governs(c),
                    "required": c.required[order].m_as(unit) if c.made else np.full(n, np.nan),
                    "rated": c.rated[order].m_as(unit),
                    "unit": pretty_unit(unit),
                    "utilization": c.utilization[order],
                    "verdict": np.where(c.unrated_rows[order], "not checked", np.where(c.passes[order], "pass", "FAIL"))
                    if c.made else "not checked",
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
    (the catalog row is marked as illustrative), ``reasons`` (each failed governing check with
    its excess; empty for a pass), then ``catalog`` (the file of the row), ``family``, ``size``,
    ``best of family`` (the smallest adequate size of its family), ``J_1 [kg·cm²]`` and ``hub [mm]``
    (the clamping hub J_1 is for), ``doubtful`` (the row's doubtful figures) and ``source``.

    Parameters
    ----------
    selection : GearboxSelection
        The checked rows.

    Returns
    -------
    pandas.DataFrame
        One row per candidate.
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
            "catalog": [selection.catalog.catalog_of(row) for row in order],
            "family": selection.catalog.family[order].astype(str),
            "size": selection.catalog.text_or_blank("size")[order].astype(str),
            "best of family": selection.best_of_family[order],
            "J_1 [kg·cm²]": selection.J_1[order].m_as("kg*cm**2"),
            "hub [mm]": selection.J_1_hub[order].m_as("mm"),
            "doubtful": selection.catalog.text_or_blank("unclear")[order].astype(str),
            "source": selection.catalog.text_or_blank("source")[order].astype(str),
        }
    )
    return table
