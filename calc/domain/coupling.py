"""Couplings and safety couplings: sizing torque, temperature factor, resonance, selection, order.

Source: "Sizing and Selecting for Couplings and Safety Couplings", read with errata E7 to E10,
E14 and E15. The coupling sees the acceleration torque ``M_a`` of the motor split by the inertias
on its two sides; the load factor ``S_A`` (E8) gives its nominal torque ``M_N``, and an
elastomer coupling's torque is further multiplied by a temperature factor (E9). The coupling is
the spring of a two-mass system whose natural frequency ``f_e`` must be at least twice the
excitation frequency of the drive (E7). That system leaves out every other spring of the drive
train: given the members around the coupling (:class:`DriveTrain`), the first mode ``f_1`` of the
whole chain (:mod:`calc.domain.torsion`) is checked against the same ``2 f_er``. A line shaft's
stiffness comes from its two bellows and its tube at the case's shaft distance; a safety
coupling's disengagement torque ``T_A`` must lie in the size's adjustable range and above the peak
torque of normal operation (E10).

Every row of a catalog (or of the requested type) is checked at once, as numpy arrays over the
rows. The case's inertias are those of the machine without the coupling: each candidate's own
inertia is added, half to each side (E7).

Ranking rule: passing candidates first, published rows before illustrative ones (as for
gearboxes); among them the smallest adequate size, measured by the rated torque ``T_KN``, then the
larger margin (lower worst utilization); failing candidates after, closest to passing first. Ties
go by part name (:func:`calc.core.checks.rank`).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ..data.bands import factor_table
from ..data.catalog import Catalog, Column, Rule, Schema, load_catalog, no_less, resolve  # noqa: F401 (load_catalog, resolve: the doctests)
from ..core.errors import CalcError, listing, as_found
from .fits import Bore, parse_bore
from ..core.formula import Formula
from ..core.glossary import symbol
from ..core import selection
from ..core.checks import CheckArray, rank, within_rating
from ..core.citation import Source, Validity
from .documents import ERRATA, KTR_ROTEX, MAYR_ROBA_ES, RW_EK, RW_ZA, SOURCE
from .torsion import MassSpringChain, TrainMember, lumped
from ..core.selection import Selection
from ..core.units import Q_, Value, as_kind, fmt, sig

TYPES = ("bellows", "elastomer", "safety", "line-shaft")

#: How the source's ordering examples head each kind of coupling.
ORDER_TITLES = {
    "bellows": "Standard coupling",
    "elastomer": "Standard coupling",
    "safety": "Safety coupling",
    "line-shaft": "Drive shaft coupling",
}

#: S_A when the case gives none (errata E8: servo drives on machine tools 2 to 3).
DEFAULT_SERVICE_FACTOR = 2.5

#: Temperature factor of elastomer couplings (source, Sizing 3; errata E9: the higher factor at a
#: boundary), ``catalogs/factors/temperature-source.csv``. The source's last band, "> 110 °C", is
#: open; it means something only while the elastomer holds, and thermoplastic polyurethane inserts
#: of servo couplings are rated up to +120 °C (98 Sh A inserts to +100 °C), so the table ends
#: there. A maker's table (``temperature-roba-es.csv``, ``temperature-comintec.csv``, or the
#: user's own) can be passed to :func:`temperature_factor` instead (``[coupling]
#: temperature_factors``).
TEMPERATURE_FACTORS = factor_table("temperature")

SCHEMA = Schema(
    kind="coupling",
    columns=(
        Column("T_KN", "torque", "rated torque (a safety coupling may give only its T_A range)", required=False),
        Column("T_Kmax", "torque", "maximum torque", required=False),
        Column("C_T", "stiffness", "torsional stiffness (of the two bellows for a line shaft)", required=False),
        Column("C_tube", "stiffness_length", "tube stiffness per unit length (line shafts)", required=False),
        Column("J", "inertia", "inertia of the whole coupling", required=False),
        Column("n_max", "speed", "maximum speed", required=False),
        Column("d_1min", "length", "smallest bore of hub 1", required=False),
        Column("d_1max", "length", "largest bore of hub 1", required=False),
        Column("d_2min", "length", "smallest bore of hub 2", required=False),
        Column("d_2max", "length", "largest bore of hub 2", required=False),
        Column("T_Amin", "torque", "smallest disengagement torque (safety couplings)", required=False),
        Column("T_Amax", "torque", "largest disengagement torque (safety couplings)", required=False),
        Column("H", "length", "hub length (line shafts)", required=False),
        Column("A_max", "length", "longest distance between shafts (line shafts)", required=False),
        *(
            Column(name, kind_name, description, required=False, may_be_absent=True)
            for name, kind_name, description in (
                ("L", "length", "overall length"),
                ("C_r", "linear_stiffness", "radial spring rate"),
                ("C_a", "linear_stiffness", "axial spring rate"),
                ("dK_a", "length", "permissible axial misalignment"),
                ("dK_r", "length", "permissible radial misalignment"),
                ("dK_w", "angle", "permissible angular misalignment"),
                ("m", "mass", "mass"),
                ("screw_torque", "torque", "tightening torque of the clamping screw"),
            )
        ),
    ),
    text_columns=("part", "series", "size", "type", "source"),
    optional_text=("illustrative", "insert", "J_basis", "clamp_screw", "unclear"),
    rules=(
        Rule("T_Kmax >= T_KN", no_less("T_Kmax", "T_KN"), "T_Kmax"),
        Rule("d_1max >= d_1min", no_less("d_1max", "d_1min"), "d_1max"),
        Rule("d_2max >= d_2min", no_less("d_2max", "d_2min"), "d_2max"),
        Rule("T_Amax >= T_Amin", no_less("T_Amax", "T_Amin"), "T_Amax"),
        Rule("A_max > 2 H", lambda v: np.isnan(v["A_max"].magnitude) | (v["A_max"] > 2 * v["H"]), "A_max"),
    ),
)

#: Columns a row of each type must fill. A safety coupling may give only the range of its
#: disengagement torque T_A (Mayr's EAS-compact tables give no separate rated torque): the torque
#: it passes is then bounded by T_A, which E10 checks.
_TYPE_NEEDS = {
    "bellows": ("T_KN",), "elastomer": ("T_KN",), "safety": ("T_Amin", "T_Amax"),
    "line-shaft": ("T_KN", "C_T", "C_tube", "H"),
}

M_N = Formula(
    "M_N",
    ("M_a", "J_load", "J_drive", "S_A"),
    lambda sp, M_a, J_load, J_drive, S_A: sp.Mul(  # in the source's order
        M_a, J_load / sp.Add(J_load, J_drive, evaluate=False), S_A, evaluate=False
    ),
    Source(SOURCE.at("Couplings, Sizing 1"),
           ERRATA.at("E8", note="the factor 2.5 is the load factor S_A, default 2.5")),
)

J_load_at_input = Formula(
    "J_load",
    ("J_L", "i", "J_1"),
    lambda sp, J_L, i, J_1: sp.Add(J_L / i**2, J_1, evaluate=False),  # in the order of E8
    Source(ERRATA.at("E8", note="a coupling between motor and gearbox sees the load reflected to the input plus the "
                                "gearbox's J_1")),
)

M_Nt = Formula(
    "M_Nt",
    ("M_N", "K_T"),
    lambda sp, M_N, K_T: M_N * K_T,
    Source(SOURCE.at("Couplings, Sizing 3", note="multiply M_N by the temperature factor"),
           ERRATA.at("E9", validity=Validity("elastomer couplings only"))),
)


M_Smax = Formula(
    "M_Smax",
    ("T_S", "S_z", "K_T"),
    lambda sp, T_S, S_z, K_T: sp.Mul(T_S, S_z, K_T, evaluate=False),
    Source(KTR_ROTEX.at(says="T_Kmax >= T_S · S_t · S_z", note="the catalogue page itself was not reached"),
           RW_EK.at(note="T_Kmax dictated by the peak torque T_S, with the start factor S_Z and the temperature factor "
                         "S_υ"),
           MAYR_ROBA_ES.at("p. 26", note="S_z, S_δ"),
           SOURCE.at("Couplings, Sizing 1", label="T_S read as the source's M_N",
                     note="a drive-side shock: M_a · J_load / (J_load + J_drive) · S_A")),
)


def _with_half_coupling(result: str, side: str) -> Formula:
    return Formula(
        result,
        (side, "J_K"),
        lambda sp, J, J_K: J + J_K / 2,
        Source(SOURCE.at("Couplings", note="J_mot, J_moch: inertia + 1/2 coupling inertia"), ERRATA.at("E7")),
    )


J_A = _with_half_coupling("J_A", "J_drive")
J_L = _with_half_coupling("J_L_coupling", "J_load")

f_e = Formula(
    "f_e",
    ("C_T", "rad", "J_A", "J_L_coupling"),
    lambda sp, C_T, rad, J_A, J_L: sp.sqrt(C_T * rad * (J_A + J_L) / (J_A * J_L)) / (2 * sp.pi),
    Source(SOURCE.at("Couplings, Sizing 2", note="garbled there"),
           ERRATA.at("E7", validity=Validity("two-mass system, coupling as the spring"))),
)

f_e_min = Formula(
    "f_e_min",
    ("f_er",),
    lambda sp, f_er: 2 * f_er,
    Source(SOURCE.at("Couplings", note="f_coupling >= 2 f_drive"), ERRATA.at("E7")),
)

Z = Formula(
    "Z",
    ("A", "H"),
    lambda sp, A, H: A - 2 * H,
    Source(RW_ZA.at(says="tube length Z = A - 2 H")),
)

C_T_line = Formula(
    "C_T",
    ("C_B", "Z", "C_tube"),
    lambda sp, C_B, Z, C_tube: 1 / (1 / C_B + Z / C_tube),
    Source(RW_ZA.at(says="the bellows and the tube of length Z in series")),
)

phi = Formula(
    symbol("phi").shown_in("deg"),
    ("T", "C_T"),
    lambda sp, T, C_T: T / C_T,
    Source(RW_ZA.at("worked example", note="angle of twist under torque")),
)


def start_factor(starts_per_hour, table, where: str = "starts_per_hour"):
    """Start factor ``S_z`` of an elastomer coupling for a number of starts per hour, from a
    maker's table (:func:`calc.data.bands.factor_table` ``("starts", name)``), scalar or array.

    Parameters
    ----------
    starts_per_hour : pint.Quantity [1/h]
        Starts per hour, scalar or array.
    table : BandTable
        ``S_z`` against starts per hour.
    where : str
        The key, for error messages; default ``"starts_per_hour"``.

    Returns
    -------
    float or numpy.ndarray [1]
        ``S_z``.

    Examples
    --------
    Mayr ROBA-ES (B.9.6.EN p. 26): 0-100 starts per hour 1, 101-200 1.2, 201-400 1.4, 401-800
    1.6, 801-1000 1.8:

    >>> from calc.data.bands import factor_table
    >>> mayr = factor_table("starts", "roba-es")
    >>> [float(start_factor(Q_(z, "1/hour"), mayr)) for z in (100, 101, 200, 400, 800, 1000)]
    [1.0, 1.2, 1.2, 1.4, 1.6, 1.8]
    """
    return table.lookup(as_kind(starts_per_hour, "per_hour", where), where)


def temperature_factor(temperature, table=TEMPERATURE_FACTORS, where: str = "temperature"):
    """Temperature factor of an elastomer coupling (errata E9), scalar or array.

    Parameters
    ----------
    temperature : pint.Quantity [°C]
        Operating temperature (``Q_(60, "degC")``; a temperature difference is refused).
    table : calc.data.bands.BandTable
        The factor by temperature band, the higher factor at a boundary. Default: the source's
        table, :data:`TEMPERATURE_FACTORS`.
    where : str
        The key, for error messages; default ``"temperature"``.

    Returns
    -------
    float or numpy.ndarray [1]
        The factor ``K_ϑ`` that multiplies ``M_N``.

    Notes
    -----
    A temperature below absolute zero is an input error, and so is one above the table's range:
    the source's table ends at 120 °C, the highest temperature servo elastomer inserts
    (thermoplastic polyurethane) are rated for; its last band, "> 110 °C", has no meaning beyond
    the elastomer's range, where no elastomer coupling is sized by a factor (E9).

    Examples
    --------
    >>> [float(temperature_factor(Q_(t, "degC"))) for t in (49.9, 50, 69.9, 70, 90, 110, 120)]
    [1.0, 1.3, 1.3, 1.6, 1.8, 2.0, 2.0]
    """
    t = as_kind(temperature, "temperature", where)
    if any(name.startswith("delta_") for name in t.units._units):
        raise CalcError(f"{where}: expected a temperature such as \"60 degC\", found {t:~P}, which is a temperature "
                        "difference")
    kelvin = np.asarray(t.m_as("K"))
    if np.any(kelvin < 0):
        raise CalcError(f"{where}: expected a temperature above absolute zero (-273.15 °C), found "
                        f"{sig(kelvin[kelvin < 0][0] - 273.15)} °C")
    return table.lookup(t, where)


@dataclass(frozen=True)
class CouplingCheck(CheckArray):
    """A :class:`calc.core.checks.CheckArray` that may apply to some rows only (a safety coupling's
    T_A range), and says why it cannot be made where a value is missing.

    Parameters
    ----------
    applies : numpy.ndarray of bool, optional
        The rows it applies to; None: every row.
    missing : str or numpy.ndarray of str
        Why a row without a rated value is not checked; one text, or one per row.
    lower_bound : bool
        ``least <= value``: the rated side is the value checked; default False.
    optional : bool
        A row without a rating is reported as not checked, and passes; default False.
    informs : bool
        Reported for information: it decides nothing (a drive train the case gives in part);
        default False.
    """

    applies: object = None  # bool array over the rows; None: every row
    missing: object = "the catalog gives no rated value"  # text, or one text per row
    lower_bound: bool = False  # "least <= value": the rated side is the value checked
    optional: bool = False  # a row without a rating is reported as not checked, and passes
    informs: bool = False  # reported for information: it decides nothing (a drive train the case gives in part)

    @property
    def passes(self) -> np.ndarray:
        if self.informs:
            return np.ones(np.shape(self.utilization), bool)
        ok = super().passes
        if self.optional:
            ok = ok | np.isnan(self.utilization)
        return ok if self.applies is None else ok | ~self.applies

    def applies_to(self, row: int) -> bool:
        """Whether the check applies to a row.

        Parameters
        ----------
        row : int
            The row of the catalog.

        Returns
        -------
        bool
            True where it is made for the row.
        """
        return True if self.applies is None else bool(self.applies[row])

    def at(self, row: int, governs: bool = True):
        """This check for one row; a row it cannot be made for (no rated value) is not made and
        says why, and an optional check's then decides nothing.

        Parameters
        ----------
        row : int
            The row of the catalog.
        governs : bool
            Whether it decides the row's verdict; default True.

        Returns
        -------
        Check
            The row's check.
        """
        check = super().at(row, governs and not self.informs)
        if self.informs:
            # The verdict it would give, shown though it decides nothing; none where it cannot be made.
            made = check.utilization is not None
            missing = self.missing if isinstance(self.missing, str) else self.missing[row]
            return dataclasses.replace(check, passes=bool(within_rating(self.utilization[row])) if made else None,
                                       not_made=None if made else missing)
        if check.utilization is None and self.made and check.not_made is None:
            # A row without the value checked (a C_T the catalog leaves empty): not made, with why.
            missing = self.missing if isinstance(self.missing, str) else self.missing[row]
            return dataclasses.replace(check, passes=None, governs=check.governs and not self.optional,
                                       not_made=missing)
        return check

    def reason(self, row: int) -> str:
        """Why the row fails this check: the excess, the shortfall, or what is missing.

        Parameters
        ----------
        row : int
            The row of the catalog.

        Returns
        -------
        str
            The reason as a line of text.
        """
        if not self.made:
            return f"{self.text}: not checked, {self.not_made}"
        u = self.utilization[row]
        if np.isnan(u):
            missing = self.missing if isinstance(self.missing, str) else self.missing[row]
            return f"{self.text}: not checked, {missing}"
        if self.lower_bound:
            return (
                f"{self.text}: {fmt(self.rated[row], self.unit)} is below the least "
                f"{fmt(self.required[row], self.unit)}, "
                f"{sig(100 * (1 - 1 / u), 3)} % short"
            )
        return super().reason(row)


@dataclass(frozen=True)
class DriveTrain:
    """The drive train around the coupling (:mod:`calc.domain.torsion`), every member referred to the
    coupling's shaft.

    Parameters
    ----------
    drive : tuple of TrainMember
        The members before the coupling, drive to load.
    load : tuple of TrainMember
        The members after it, drive to load.
    missing : tuple of str
        The members the case does not give; the chain is then incomplete, and the check of its
        first mode is reported for information only.
    shaft : str
        Which shaft the members are referred to; default ``"the coupling's shaft"``.
    """

    drive: tuple
    load: tuple
    missing: tuple = ()
    shaft: str = "the coupling's shaft"

    @property
    def complete(self) -> bool:
        return not self.missing


@dataclass(kw_only=True)
class CouplingCandidate(selection.Candidate):
    """One coupling with its checks and key figures, as every output lists it (the fields of
    :class:`calc.core.selection.Candidate`, and these).

    Parameters
    ----------
    type : str
        One of :data:`TYPES`.
    f_e : Value [Hz]
        The two-mass natural frequency (no value where the catalog lacks C_T or J).
    f_1 : Value [Hz] or None
        The drive train's first mode; None without the drive train.
    C_T : Value [N·m/rad]
        Its torsional stiffness.
    temperature_factor : float
        ``K_ϑ`` [1].
    required_torque : Value [N·m]
        ``M_N · K_ϑ``.
    peak_torque_required : Value [N·m] or None
        ``M_Smax``; None without the start factor.
    """

    type: str
    f_e: Value  # the two-mass natural frequency (no value where the catalog lacks C_T or J)
    f_1: Value | None  # the drive train's first mode; None without the drive train
    C_T: Value
    temperature_factor: float
    required_torque: Value  # M_N · K_ϑ
    peak_torque_required: Value | None  # M_Smax; None without the start factor


@dataclass
class CouplingSelection(Selection):
    """The candidate couplings, checked and ranked. Arrays run over the rows of ``catalog``.

    Parameters
    ----------
    catalog : Catalog
        The rows checked.
    M_N : pint.Quantity [N·m]
        Scalar, before the temperature factor.
    T_op : pint.Quantity [N·m]
        Peak torque of normal operation, ``M_N`` with ``S_A = 1``.
    temperature_factor : numpy.ndarray [1]
        ``K_ϑ`` per row (1 for all but elastomer couplings).
    M_Nt : pint.Quantity [N·m]
        Required torque per row.
    start_factor : float or None
        ``S_z`` at the case's starts per hour; None without a start-factor table.
    M_Smax : pint.Quantity [N·m] or None
        Peak torque with ``S_z`` and ``K_ϑ`` per row (elastomer couplings); None without ``S_z``.
    C_T : pint.Quantity [N·m/rad]
        Torsional stiffness per row (a line shaft's at the case's shaft distance).
    J_A : pint.Quantity [kg·cm²]
        Drive-side inertia per row, with half the coupling (E7).
    J_L : pint.Quantity [kg·cm²]
        Load-side inertia per row, with half the coupling (E7).
    f_e : pint.Quantity [Hz]
        Two-mass natural frequency per row.
    checks : list of CouplingCheck
        Every check.
    passes : numpy.ndarray of bool
        Every check made passes.
    worst : numpy.ndarray [1]
        Highest utilization of the checks that apply (inf where one cannot be made).
    order : numpy.ndarray of int
        The rows, best first.
    notes : list of str
        What is not checked, and why.
    drive_train : DriveTrain, optional
        The members around the coupling, as the case gives them.
    chain : MassSpringChain, optional
        The drive train lumped, its arrays over the rows (None without ``drive_train``).
    modes : pint.Quantity [Hz], optional
        Its natural frequencies per row, lowest first (rows × modes).
    """

    catalog: Catalog
    M_N: object  # scalar quantity, before the temperature factor
    T_op: object  # peak torque of normal operation, M_N with S_A = 1
    temperature_factor: np.ndarray  # per row (1 for all but elastomer couplings)
    M_Nt: object  # required torque per row
    start_factor: float | None  # S_z at the case's starts per hour; None without a start-factor table
    M_Smax: object  # peak torque with S_z and K_ϑ per row (elastomer couplings); None without S_z
    C_T: object  # torsional stiffness per row (a line shaft's at the case's shaft distance)
    J_A: object
    J_L: object
    f_e: object
    checks: list
    passes: np.ndarray
    worst: np.ndarray  # highest utilization of the checks that apply (inf where one cannot be made)
    order: np.ndarray
    notes: list
    drive_train: "DriveTrain | None" = None  # the members around the coupling, as the case gives them
    chain: MassSpringChain | None = None  # the drive train lumped, its arrays over the rows (None without drive_train)
    modes: object = None  # its natural frequencies per row, lowest first (quantity, rows × modes)

    candidate_type = CouplingCandidate

    def applies(self, check, row: int) -> bool:
        return check.applies_to(row)

    def row_fields(self, row: int) -> dict:
        return dict(
            type=self.row_type(row),
            f_e=Value.of(self.f_e[row], "Hz"),
            f_1=None if self.modes is None else Value.of(self.modes[row, 0], "Hz"),
            C_T=Value.of(self.C_T[row], "N*m/rad"),
            temperature_factor=float(self.temperature_factor[row]),
            required_torque=Value.of(self.M_Nt[row], "N*m"),
            peak_torque_required=None if self.M_Smax is None else Value.of(self.M_Smax[row], "N*m"),
        )

    def row_type(self, row: int) -> str:
        """The type of a row.

        Parameters
        ----------
        row : int
            The row of the catalog.

        Returns
        -------
        str
            One of :data:`TYPES`.
        """
        return str(self.catalog.text["type"][row])


def candidates_frame(selection: CouplingSelection):
    """One row per candidate, best first, as a pandas DataFrame: verdict, the key figures and why.

    Columns: ``rank``, ``part``, ``type``, ``verdict`` (PASS/FAIL), ``M_N·K_ϑ [N·m]``,
    ``T_KN [N·m]``, ``f_e [Hz]`` (NaN where the catalog lacks C_T or J), ``worst utilization``
    and ``reasons`` (each failed check; empty for a pass). Values are not rounded.

    Parameters
    ----------
    selection : CouplingSelection
        The checked rows.

    Returns
    -------
    pandas.DataFrame
        One row per candidate.
    """
    import pandas as pd

    order = selection.order
    return pd.DataFrame(
        {
            "rank": np.arange(1, len(order) + 1),
            "part": selection.catalog.parts[order].astype(str),
            "type": selection.catalog.text["type"][order].astype(str),
            "verdict": np.where(selection.passes[order], "PASS", "FAIL"),
            "M_N·K_ϑ [N·m]": selection.M_Nt[order].m_as("N*m"),
            "T_KN [N·m]": selection.catalog["T_KN"][order].m_as("N*m"),
            "f_e [Hz]": selection.f_e[order].m_as("Hz"),
            "worst utilization": selection.worst[order],
            "reasons": ["; ".join(selection.reasons(row)) for row in order],
        }
    )


def _positive(q, where: str, what: str, unit: str):
    if q is not None and not np.all(q.magnitude > 0):
        raise CalcError(f"{where}: expected {what} above zero, found {fmt(q, unit)}")


def _as_bore(value, where: str) -> Bore:
    return value if isinstance(value, Bore) else parse_bore(value, where)


def select_coupling(
    catalog: Catalog,
    accel_torque,
    drive_inertia,
    load_inertia,
    excitation_frequency,
    shaft_1,
    shaft_2,
    service_factor=DEFAULT_SERVICE_FACTOR,
    temperature=None,
    speed=None,
    disengagement_torque=None,
    shaft_distance=None,
    temperature_factors=TEMPERATURE_FACTORS,
    start_factors=None,
    starts_per_hour=None,
    drive_train: "DriveTrain | None" = None,
    where: str = "coupling",
    sources: dict | None = None,
) -> CouplingSelection:
    """Check every coupling of ``catalog`` (already narrowed to a type or a part) and rank them.

    Checks, each with required, rated, utilization and verdict:

    * torque: ``M_N · K_ϑ <= T_KN``, ``K_ϑ`` the temperature factor for elastomer couplings
      (E9), 1 for the others; ``M_N = M_a · J_load / (J_load + J_drive) · S_A`` (E8);
    * resonance: ``2 f_er <= f_e`` (E7), ``J_A`` and ``J_L`` each with half the coupling;
    * with ``drive_train``, the first mode of the whole chain: ``2 f_er <= f_1``
      (:mod:`calc.domain.torsion`), which sees the gearbox's spring the two-mass ``f_e`` leaves out;
    * speed: ``n <= n_max`` (when ``speed`` is given);
    * bores: ``d_min <= D <= d_max`` for each hub, on the nominal diameter;
    * safety couplings: ``T_Amin <= T_A <= T_Amax`` and ``T_op <= T_A``, ``T_op`` the peak torque
      of normal operation, ``M_N`` with ``S_A = 1`` (E10);
    * line shafts: ``2 H <= A <= A_max``; ``C_T`` from the bellows and the tube of length
      ``A - 2 H``;
    * elastomer couplings, with a start-factor table: the peak torque ``T_S · S_z · K_ϑ <=
      T_Kmax`` as KTR, R+W and Mayr size them, ``T_S`` the source's ``M_N`` (a drive-side shock
      with ``S_A``), ``S_z`` the start factor at ``starts_per_hour``; a row without ``T_Kmax`` is
      reported as not checked.

    Parameters
    ----------
    catalog : Catalog
        Rows of :data:`SCHEMA`.
    accel_torque : pint.Quantity [N·m] or None
        ``M_a``, acceleration torque of the motor.
    drive_inertia, load_inertia : pint.Quantity [kg·cm²] or None
        ``J_drive`` and ``J_load`` without the coupling (with a coupling between motor and
        gearbox, ``J_load`` is ``J_L / i² + J_1``, E8).

        Any of these three may be None (the contract's partial cases): the checks that need it
        (the torque checks ``T_KN``, ``T_Kmax``, ``T_op <= T_A`` need all three, the resonance
        check the two inertias) are not made, naming the missing value as ``sources`` gives it
        (by key; default ``<where>.<key>``), and no coupling is chosen; the others are made.
    excitation_frequency : pint.Quantity [Hz]
        ``f_er`` of the drive (E7).
    shaft_1, shaft_2 : Bore or str
        The shafts as ordered (``"19 mm k6"``, see :func:`calc.domain.fits.parse_bore`).
    service_factor : float or pint.Quantity [1]
        ``S_A`` (E8), 1 or more; default 2.5.
    temperature : pint.Quantity [°C], optional
        Operating temperature; needed when elastomer couplings are among the candidates.
    speed : pint.Quantity [rpm], optional
        Highest speed of the coupling.
    disengagement_torque : pint.Quantity [N·m], optional
        ``T_A``; only, and always, for safety couplings.
    shaft_distance : pint.Quantity [mm], optional
        ``A``; only, and always, for line shafts.
    temperature_factors : calc.data.bands.BandTable
        ``K_ϑ`` against temperature; default the source's table (E9).
    start_factors : calc.data.bands.BandTable, optional
        ``S_z`` against starts per hour (a maker's table); with it the ``T_Kmax`` check is made.
    starts_per_hour : pint.Quantity [1/h], optional
        Starts per hour; needed with ``start_factors``.
    drive_train : DriveTrain, optional
        The members around the coupling. With it, each candidate is put in the chain (half its
        inertia on each end of its spring, as for ``f_e``) and the chain's first mode is checked,
        ``2 f_er <= f_1`` (:mod:`calc.domain.torsion`): governing where the chain is complete, for
        information where the case leaves a member out.
    where : str
        Prefix of error messages (the case file and section).
    sources : dict, optional
        The key that gives each of the acceleration torque and the two inertias, by argument name,
        for the message of a check not made.

    Returns
    -------
    CouplingSelection
        The candidates checked and ranked.

    Examples
    --------
    The example case: motor 12 N·m, 4.2 kg·cm²; load 1500 kg·cm² through i = 10 plus the
    gearbox's 0.93 kg·cm² gives J_load = 15.93 kg·cm² (E8):

    >>> cat = load_catalog(resolve("couplings", None, "catalog"), SCHEMA)
    >>> bellows = cat.rows(cat.text["type"] == "bellows")
    >>> s = select_coupling(bellows, Q_(12, "N*m"), Q_(4.2, "kg*cm**2"), Q_(15.93, "kg*cm**2"),
    ...                     Q_(150, "Hz"), "19 mm k6", "16 mm h7", speed=Q_(3000, "rpm"))
    >>> fmt(s.M_N, "N*m"), s.selected, fmt(s.f_e[cat.index("AKD-30", "part")], "Hz")
    ('23.74 N·m', 'AKD-30', '1316 Hz')
    """
    if not len(catalog):
        raise CalcError(f"{where}: no coupling to check, the catalog has no rows")
    check_types(catalog)
    types = catalog.text["type"]
    kinds = _Kinds(types == "elastomer", types == "safety", types == "line-shaft")
    case = _checked_case(catalog, kinds, dict(accel_torque=accel_torque, drive_inertia=drive_inertia,
                                              load_inertia=load_inertia), excitation_frequency, shaft_1, shaft_2,
                         service_factor, speed, disengagement_torque, shaft_distance, where, sources or {})
    K_T, S_z = _load_factors(kinds.elastomer, temperature, temperature_factors, start_factors, starts_per_hour, where)

    m_n = M_N(M_a=case.M_a, J_load=case.J_load, J_drive=case.J_drive, S_A=case.S_A)
    t_op = M_N(M_a=case.M_a, J_load=case.J_load, J_drive=case.J_drive, S_A=Q_(1.0, ""))
    m_nt = M_Nt(M_N=m_n, K_T=Q_(K_T, ""))
    j_a, j_l, c_t, fe, chain, modes = _two_masses_and_chain(catalog, case, kinds.line_shaft, drive_train, where)
    notes = []
    checks, m_smax = _operating_checks(catalog, case, kinds, c_t, fe, modes, drive_train, (m_n, m_nt, K_T, S_z), notes)
    checks += _fit_checks(catalog, case, kinds, t_op)
    passes, worst, order = _verdicts(catalog, checks)
    return CouplingSelection(catalog, m_n, t_op, K_T, m_nt, S_z, m_smax, c_t, j_a, j_l, fe, checks, passes, worst,
                             order, notes,
                             drive_train, chain, modes)


class _Kinds(NamedTuple):
    """Which rows are of the types with checks of their own (bool arrays over the rows)."""

    elastomer: np.ndarray
    safety: np.ndarray
    line_shaft: np.ndarray


@dataclass(frozen=True)
class _Case:
    """The case's values for the coupling, checked and in their kinds; a torque or inertia the case
    leaves out is NaN, and ``no_torque``/``no_inertia`` say which checks that stops (None: none)."""

    M_a: object
    J_drive: object
    J_load: object
    f_er: object
    S_A: object
    bore_1: Bore
    bore_2: Bore
    speed: object
    T_A: object
    A: object
    no_torque: str | None
    no_inertia: str | None


def _checked_case(catalog, kinds, given, excitation_frequency, shaft_1, shaft_2, service_factor, speed,
                  disengagement_torque, shaft_distance, where, sources) -> _Case:
    """The arguments of :func:`select_coupling` checked, in the order it names them (``given``: the
    acceleration torque and the two inertias, each possibly None)."""
    types = catalog.text["type"]
    accel_torque, drive_inertia, load_inertia = given["accel_torque"], given["drive_inertia"], given["load_inertia"]
    absent = [sources.get(key, f"{where}.{key}") for key, value in given.items() if value is None]
    absent_inertia = [sources.get(key, f"{where}.{key}") for key in ("drive_inertia", "load_inertia")
                      if given[key] is None]
    no_torque = "needs " + " and ".join(absent) if absent else None
    no_inertia = "needs " + " and ".join(absent_inertia) if absent_inertia else None
    M_a = Q_(math.nan, "N*m") if accel_torque is None else as_kind(accel_torque, "torque", f"{where}.accel_torque")
    J_drive = (Q_(math.nan, "kg*m**2") if drive_inertia is None
               else as_kind(drive_inertia, "inertia", f"{where}.drive_inertia"))
    J_load = (Q_(math.nan, "kg*m**2") if load_inertia is None
              else as_kind(load_inertia, "inertia", f"{where}.load_inertia"))
    f_er = as_kind(excitation_frequency, "frequency", f"{where}.excitation_frequency")
    S_A = as_kind(service_factor, "dimensionless", f"{where}.service_factor")
    _positive(None if accel_torque is None else M_a, f"{where}.accel_torque", "a torque", "N*m")
    _positive(None if drive_inertia is None else J_drive, f"{where}.drive_inertia", "an inertia", "kg*cm**2")
    _positive(None if load_inertia is None else J_load, f"{where}.load_inertia", "an inertia", "kg*cm**2")
    _positive(f_er, f"{where}.excitation_frequency", "a frequency", "Hz")
    if not S_A.m_as("") >= 1:
        raise CalcError(
            f"{where}.service_factor: expected a load factor S_A of 1 or more (E8), found {sig(S_A.m_as(''))}"
        )
    bore_1, bore_2 = _as_bore(shaft_1, f"{where}.shaft_1"), _as_bore(shaft_2, f"{where}.shaft_2")
    if speed is not None:
        speed = as_kind(speed, "speed", f"{where}.speed")
        _positive(speed, f"{where}.speed", "a speed", "rpm")
    T_A = (None if disengagement_torque is None
           else as_kind(disengagement_torque, "torque", f"{where}.disengagement_torque"))
    A = None if shaft_distance is None else as_kind(shaft_distance, "length", f"{where}.shaft_distance")
    _positive(T_A, f"{where}.disengagement_torque", "a torque", "N*m")
    _positive(A, f"{where}.shaft_distance", "a distance", "mm")
    _only_for(T_A, kinds.safety, types, "safety", f"{where}.disengagement_torque", "a disengagement torque T_A (E10)")
    _only_for(A, kinds.line_shaft, types, "line-shaft", f"{where}.shaft_distance", "a distance between shafts")
    if A is not None:
        two_hubs = 2 * catalog["H"][kinds.line_shaft]
        if not np.any(A >= two_hubs):
            raise CalcError(
                f"{where}.shaft_distance: {fmt(A, 'mm')} is shorter than the two hubs of every line shaft "
                f"(2 H = {listing(fmt(h, 'mm') for h in two_hubs)}); expected A >= 2 H"
            )
    return _Case(M_a, J_drive, J_load, f_er, S_A, bore_1, bore_2, speed, T_A, A, no_torque, no_inertia)


def _load_factors(is_el, temperature, temperature_factors, start_factors, starts_per_hour, where: str):
    """``K_ϑ`` per row (1 for all but elastomer couplings, E9) and ``S_z`` at the case's starts per
    hour (None without a start-factor table)."""
    K_T = np.ones(len(is_el))
    if is_el.any():
        if temperature is None:
            raise CalcError(
                f"{where}.temperature: elastomer couplings need the operating temperature for their factor (E9), "
                "found none; give it, or a type that is not elastomer"
            )
        K_T = np.where(is_el, temperature_factor(temperature, temperature_factors, where=f"{where}.temperature"), 1.0)
    elif temperature is not None:
        # Checked, though no candidate uses it.
        temperature_factor(temperature, temperature_factors, where=f"{where}.temperature")
    S_z = None
    if start_factors is not None:
        if starts_per_hour is None:
            raise CalcError(
                f"{where}.starts_per_hour: the start-factor table needs the number of starts per hour, found none"
            )
        S_z = float(start_factor(starts_per_hour, start_factors, f"{where}.starts_per_hour"))
    elif starts_per_hour is not None:
        raise CalcError(
            f"{where}.starts_per_hour: starts per hour are read against a start-factor table; "
            "give coupling.start_factors as well"
        )
    return K_T, S_z


def _two_masses_and_chain(catalog: Catalog, case: _Case, is_line, drive_train, where: str):
    """Per row: ``J_A``, ``J_L``, the stiffness ``C_T`` (a line shaft's at the case's distance), the
    two-mass ``f_e``, and with ``drive_train`` its chain and natural frequencies (else None)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        j_a = J_A(J_drive=case.J_drive, J_K=catalog["J"])
        j_l = J_L(J_load=case.J_load, J_K=catalog["J"])
        # A line shaft's catalog C_T is its bellows alone; its own stiffness needs the tube's length.
        c_line = np.full(len(catalog), np.nan)
        if case.A is not None:
            fits_in = case.A >= 2 * catalog["H"]
            line = C_T_line(C_B=catalog["C_T"], Z=Z(A=case.A, H=catalog["H"]), C_tube=catalog["C_tube"])
            c_line = np.where(fits_in, line.m_as("N*m/rad"), np.nan)
        c_t = Q_(np.where(is_line, c_line, catalog["C_T"].m_as("N*m/rad")), "N*m/rad")
        fe = f_e(C_T=c_t, J_A=j_a, J_L_coupling=j_l)
        chain = modes = None
        if drive_train is not None:
            # Half the coupling on each end of its spring, as J_A and J_L take it (E7).
            half = catalog["J"] / 2
            coupling = TrainMember("coupling", half, c_t, half)
            chain = lumped((*drive_train.drive, coupling, *drive_train.load), f"{where}: drive train")
            modes = chain.natural_frequencies()
    return j_a, j_l, c_t, fe, chain, modes


def _over_rows(q, n: int):
    """A scalar quantity repeated over ``n`` rows."""
    return q * np.ones(n)


def _operating_checks(catalog, case: _Case, kinds: _Kinds, c_t, fe, modes, drive_train, torques, notes: list):
    """The checks of the coupling in operation: rated torque, resonance (two-mass and, with the
    drive train, its first mode), peak torque with a start-factor table, speed. ``torques`` is
    ``(M_N, M_N·K_ϑ, K_ϑ, S_z)``; what is not checked is added to ``notes``. Returns the checks and
    the peak torque ``M_Smax`` per row (None without ``S_z``)."""
    n = len(catalog)
    m_n, m_nt, K_T, S_z = torques
    no_c, no_j = np.isnan(c_t.magnitude), np.isnan(catalog["J"].magnitude)
    empty = np.where(no_c & no_j, "torsional stiffness C_T and inertia J",
                     np.where(no_c, "torsional stiffness C_T", "inertia J"))

    def needs(what: str):
        return np.where(
            kinds.line_shaft & (case.A is None),
            "a line shaft's stiffness needs coupling.shaft_distance",
            np.char.add(np.char.add(f"{what} needs the coupling's ", empty.astype(str)),
                        ", which the catalog leaves empty"),
        )

    f_min = _over_rows(f_e_min(f_er=case.f_er), n)
    rated = ~(kinds.safety & np.isnan(catalog["T_KN"].magnitude))
    checks = [
        CouplingCheck("T_KN", "coupling", "M_N · K_ϑ <= T_KN", m_nt, catalog["T_KN"], "N*m", rated,
                      not_made=case.no_torque),
        CouplingCheck("f_e", "coupling", "2 f_er <= f_e", f_min, fe, "Hz", None, needs("f_e"),
                      not_made=case.no_inertia),
    ]
    if modes is not None:
        checks.append(
            CouplingCheck("f_1", "coupling", "2 f_er <= f_1", f_min, modes[:, 0], "Hz", None,
                          needs("the first mode of the drive train"), informs=not drive_train.complete,
                          not_made=case.no_inertia)
        )
        if not drive_train.complete:
            notes.append(
                "the drive train's first mode f_1 is reported for information: the case does not give "
                + ", ".join(drive_train.missing)
            )
    m_smax = None
    if S_z is not None:
        m_smax = M_Smax(T_S=m_n, S_z=Q_(S_z, ""), K_T=Q_(K_T, ""))
        checks.append(
            CouplingCheck(
                "T_Kmax", "coupling", "T_S · S_z · K_ϑ <= T_Kmax", m_smax, catalog["T_Kmax"], "N*m", kinds.elastomer,
                "the catalog gives no maximum torque T_Kmax", optional=True, not_made=case.no_torque,
            )
        )
    elif kinds.elastomer.any():
        notes.append("coupling.start_factors not given: the peak-torque check T_S · S_z · K_ϑ <= T_Kmax "
                     "of elastomer couplings is not made")
    if case.speed is not None:
        checks.append(CouplingCheck("n_max", "coupling", "n <= n_max", _over_rows(case.speed, n), catalog["n_max"],
                                    "rpm",
                                    None, "the catalog gives no maximum speed"))
    else:
        notes.append("coupling.speed not given: the speed check n <= n_max is not made")
    return checks, m_smax


def _fit_checks(catalog, case: _Case, kinds: _Kinds, t_op) -> list:
    """The checks of how the coupling fits the machine: each hub's bore range, a safety coupling's
    ``T_A`` range and ``T_op <= T_A`` (E10), a line shaft's distance."""
    n = len(catalog)
    checks = []
    for k, bore in ((1, case.bore_1), (2, case.bore_2)):
        missing = f"the catalog gives no bore range for hub {k}"
        D = _over_rows(bore.nominal, n)
        checks += [
            CouplingCheck(f"d_{k}min", "coupling", f"d_{k}min <= D_{k}", catalog[f"d_{k}min"], D, "mm", None, missing,
                          True),
            CouplingCheck(f"d_{k}max", "coupling", f"D_{k} <= d_{k}max", D, catalog[f"d_{k}max"], "mm", None, missing),
        ]
    if kinds.safety.any():
        t_a = Q_(np.full(n, np.nan), "N*m") if case.T_A is None else _over_rows(case.T_A, n)
        missing = "needs coupling.disengagement_torque (E10)"
        checks += [
            CouplingCheck("T_Amin", "coupling", "T_Amin <= T_A", catalog["T_Amin"], t_a, "N*m", kinds.safety, missing,
                          True),
            CouplingCheck("T_Amax", "coupling", "T_A <= T_Amax", t_a, catalog["T_Amax"], "N*m", kinds.safety, missing),
            CouplingCheck("T_A", "coupling", "T_op <= T_A", _over_rows(t_op, n), t_a, "N*m", kinds.safety, missing,
                          not_made=case.no_torque),
        ]
    if kinds.line_shaft.any():
        a = Q_(np.full(n, np.nan), "mm") if case.A is None else _over_rows(case.A, n)
        missing = ("needs coupling.shaft_distance" if case.A is None
                   else "the catalog gives no longest shaft distance A_max")
        checks += [
            CouplingCheck("A_min", "coupling", "2 H <= A", 2 * catalog["H"], a, "mm", kinds.line_shaft,
                          "needs coupling.shaft_distance", True),
            CouplingCheck("A_max", "coupling", "A <= A_max", a, catalog["A_max"], "mm", kinds.line_shaft, missing),
        ]
    return checks


def _verdicts(catalog: Catalog, checks: list):
    """Per row: whether it passes every check made, its worst utilization, and the ranking."""
    made = [c for c in checks if c.made]  # a check the case cannot feed decides no row (CouplingSelection.not_made)
    passes = np.logical_and.reduce([c.passes for c in made])
    # A row an optional check cannot be made for counts as unburdened by it (it decides nothing there).
    utilizations = np.array(
        [np.where(c.applies if c.applies is not None else True,
                  np.nan_to_num(c.utilization, nan=0.0) if c.optional else c.utilization, 0.0)
         for c in made if not c.informs]
    )
    worst = np.max(np.where(np.isnan(utilizations), np.inf, utilizations), axis=0)
    size = catalog["T_KN"].m_as("N*m")
    # a safety coupling rated by its T_A range alone
    size = np.where(np.isnan(size), catalog["T_Amax"].m_as("N*m"), size)
    order = rank(passes, size, worst, catalog.parts, later=catalog.illustrative)
    return passes, worst, order


def _only_for(value, rows_of_type, types, type_name: str, where: str, what: str) -> None:
    """``value`` (T_A or A) is for couplings of one type: given, every candidate must be of that
    type; not given, a catalog of that type alone cannot be checked."""
    if value is not None and not rows_of_type.all():
        others = sorted(set(types[~rows_of_type]))
        raise CalcError(
            f"{where}: {what} is for {type_name} couplings only, but the candidates include {listing(others)} "
            "couplings; "
            f"set type = \"{type_name}\" or remove the key"
        )
    if value is None and rows_of_type.all():
        raise CalcError(f"{where}: {type_name} couplings need {what}, found none")


def order_lines(part: str, coupling_type: str, bores, disengagement_torque=None, shaft_distance=None) -> list[str]:
    """The order text of a coupling, line by line, as the source's ordering examples write it.

    Series and size, each shaft with its fit or limits and keyway (``D1 = 14 mm k6``), the
    disengagement torque ``T_A`` for a safety coupling (E10), the distance between shafts for a
    line shaft.

    Parameters
    ----------
    part : str
        The coupling's part (series and size).
    coupling_type : str
        One of :data:`TYPES`.
    bores : list of Bore
        The shafts, hub 1 first.
    disengagement_torque : pint.Quantity [N·m], optional
        ``T_A``, for a safety coupling only.
    shaft_distance : pint.Quantity [mm], optional
        The distance between shafts, for a line shaft only (written in the unit given).

    Returns
    -------
    list of str
        The order's lines.

    Examples
    --------
    >>> from calc.domain.fits import parse_bore
    >>> order_lines("SKB-30", "safety", [parse_bore("19 mm k6")], disengagement_torque=Q_(25, "N*m"))
    ['Safety coupling SKB-30', 'D1 = 19 mm k6', 'T_A (disengagement torque) = 25 N·m']
    """
    if coupling_type not in TYPES:
        raise CalcError(f"coupling type: expected one of {listing(TYPES)}, found {as_found(coupling_type)}")
    if (disengagement_torque is not None) != (coupling_type == "safety"):
        raise CalcError(f"{part}: a disengagement torque T_A is given for safety couplings, and only for them (E10)")
    if (shaft_distance is not None) != (coupling_type == "line-shaft"):
        raise CalcError(f"{part}: the distance between shafts is given for line shafts, and only for them")
    lines = [f"{ORDER_TITLES[coupling_type]} {part}"]
    lines += [f"D{k} = {bore.text}" for k, bore in enumerate(bores, start=1)]
    if disengagement_torque is not None:
        lines.append("T_A (disengagement torque) = "
                     f"{fmt(as_kind(disengagement_torque, 'torque', f'{part}: T_A'), 'N*m')}")
    if shaft_distance is not None:
        distance = as_kind(shaft_distance, "length", f"{part}: distance between shafts")
        lines.append(f"Distance between shafts = {sig(distance.magnitude)} {distance.units:~}")  # in the unit given
    return lines


#: Where the coupling sits: ``input``, between motor and gearbox; ``output``, between gearbox and load.
SIDES = ("input", "output")


def check_types(catalog: Catalog) -> None:
    """Each row's type is known and the row fills the columns its type needs.

    Parameters
    ----------
    catalog : Catalog
        Rows of :data:`SCHEMA`.

    Returns
    -------
    None

    Raises
    ------
    CalcError
        Naming the file, row and column.
    """
    types = catalog.text["type"]

    def where(j):
        return f"{catalog.path}, row {catalog.lines[j]} ({catalog.parts[j]})"

    unknown = np.flatnonzero(~np.isin(types, TYPES))
    if len(unknown):
        j = unknown[0]
        raise CalcError(f"{where(j)}, column type: expected one of {listing(TYPES)}, found {as_found(types[j])}")
    for t, columns in _TYPE_NEEDS.items():
        for column in columns:
            empty = np.flatnonzero((types == t) & np.isnan(catalog[column].magnitude))
            if len(empty):
                raise CalcError(f"{where(empty[0])}, column {column}: a {t} coupling needs a value, found an empty "
                                "cell")
