"""A servo motor against its ratings: the motor catalog, the speed-torque characteristic, and a
load cycle at the motor checked against every catalog motor at once.

The characteristic takes one of three forms, the first the data allow (each a reading, as the
errata are; ``docs/case-format.md``, "The motor chosen from a catalog"):

* **Curves** digitised from the maker's chart (a curves file, :func:`read_curves`: per part its
  ``peak`` and ``S1`` curves as points of speed and torque): straight between the points, no torque
  beyond the last; the RMS is then checked against the S1 curve at the cycle's mean speed.
* **Voltage limit**, where the catalog gives the electrical data (``k_T``, ``k_E``, ``R_ph``,
  ``L_ph``, ``poles``) and the case the drive's DC-link voltage ``U_DC``: a permanent-magnet
  synchronous motor under field-oriented control without field weakening (``i_d = 0``), in steady
  state, per phase ``(R·I + E)² + (X·I)² <= U²`` with the back-EMF ``E = k_E·n / √3`` (``k_E``
  read as the line-to-line RMS voltage per speed), the reactance ``X = p·ω·L`` (``p = poles / 2``
  pole pairs), the highest phase voltage ``U = U_DC / √6`` a space-vector modulated inverter gives
  (line-to-line amplitude ``U_DC``) and the current ``I = T / k_T`` (``k_T`` per A rms). Solved
  for the current, the torque the voltage allows is :data:`T_V`; an operating point keeps 10 %
  clear of it (``|T| <= 0.9·T_V``, the clearance of the makers' guides) and within ``M_max``.
* **Ratings** alone, as the makers' selection guides (Siemens configuration manuals; Yaskawa,
  Omron and Mitsubishi selection guides) check a motor without its curves: the maximum torque
  ``M_max`` up to the rated speed ``n_N``, above it a straight line down to the rated torque
  ``M_N`` at the maximum speed ``n_max`` (:data:`T_peak_line`). Below the makers' drawn
  intermittent zone for a motor rated near its voltage limit (the Yaskawa and Mitsubishi tables:
  the zone falls from about ``n_N`` and ends above ``M_N``), but above it for a motor whose rated
  speed lies past the knee of its voltage limit: 1FT7044-AK7's voltage limit on a 600 V DC link
  allows about 13 N·m at its rated 6000 rpm where this reading allows its ``M_max`` of 23 N·m
  (notebook 04). Give the DC link where the catalog has the electrical data.

The checks of a cycle (motor torque ``T_1`` and speed ``n_1`` per sample, durations ``t_k``): every
sample under the peak characteristic at its speed; the RMS torque within the rated torque,
``T_1rms <= M_N``, with the cycle's mean speed ``<= n_N`` (with an S1 curve: within the curve at
the mean speed); the top speed
``<= n_max``; the load-to-motor inertia ratio within a limit. The RMS holds only while the cycle is
short against the motor's thermal time constant ``T_th``: a cycle longer than a tenth of ``T_th``
gets a note (the winding's temperature then swings within the cycle by a share of its rise of the
order of ``t_cycle / T_th``).
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..data.catalog import _FLOAT, _HEADER, Catalog, Column, Rule, Schema, _header_unit, no_less, note_file_read
from ..core.errors import CalcError, listing, as_found
from ..core.checks import CheckArray
from ..core.citation import Source
from ..core.formula import Formula
from .documents import CASE_FORMAT
from .gearbox import INERTIA_RATIO_LIMIT
from .profile import n_2m
from ..core.selection import Candidate, Selection
from ..core.units import Q_, Value

#: The clearance an operating point keeps from the voltage limit.
VOLTAGE_CLEARANCE = 0.9
#: A cycle longer than this share of the thermal time constant gets a note (the RMS method assumes it short).
THERMAL_SHARE = 0.1
#: How :func:`select_motors` ranks the catalog's motors.
RANKING = ("passing first; then the smallest adequate motor, the lowest rated torque M_N, ties to the lower rotor "
           "inertia; "
           "then lowest worst utilization; partial rows are never ranked")

SCHEMA = Schema(
    kind="motor",
    columns=(
        Column("U_DC", "voltage", "DC-link voltage the ratings are given for", required=False),
        Column("M_0", "torque", "standstill torque", required=False),
        Column("M_N", "torque", "rated (continuous) torque"),
        Column("n_N", "speed", "rated speed"),
        Column("M_max", "torque", "maximum torque"),
        Column("n_max", "speed", "maximum speed"),
        Column("J", "inertia", "rotor inertia"),
        Column("J_brake", "inertia", "rotor inertia with the holding brake", required=False),
        Column("k_T", "torque_constant", "torque constant, per A rms", required=False),
        Column("k_E", "voltage_constant", "voltage constant, line-to-line RMS", required=False),
        Column("R_ph", "resistance", "phase resistance", required=False),
        Column("L_ph", "inductance", "phase inductance", required=False),
        Column("I_0", "current", "standstill current", required=False),
        Column("I_max", "current", "maximum current", required=False),
        Column("poles", "dimensionless", "number of poles", required=False),
        Column("T_th", "time", "thermal time constant", required=False),
        Column("m", "mass", "mass", required=False),
        Column("shaft_d", "length", "shaft diameter", required=False, may_be_absent=True),
        Column("F_R", "force", "permissible radial force on the shaft", required=False, may_be_absent=True),
    ),
    text_columns=("part", "maker", "source"),
    optional_text=("family", "size", "partial", "unclear", "illustrative"),
    partial="partial",
    rules=(
        Rule("M_max >= M_N", no_less("M_max", "M_N"), "M_max"),
        Rule("n_max >= n_N", no_less("n_max", "n_N"), "n_max"),
    ),
)

#: The columns the voltage limit needs besides the case's DC-link voltage.
ELECTRICAL = ("k_T", "k_E", "R_ph", "L_ph", "poles")

#: The case format's section that states the readings of a catalog motor's characteristic.
RATINGS_SECTION = "The motor chosen from a catalog"

T_peak_line = Formula(
    "T_peak_line",
    ("M_max", "M_N_motor", "n", "n_N", "n_max"),
    lambda sp, M_max, M_N, n, n_N, n_max: M_max - (M_max - M_N) * (n - n_N) / (n_max - n_N),
    Source(CASE_FORMAT.at(RATINGS_SECTION, label="a reading (motor ratings)",
                          says="M_max up to n_N, then straight down to M_N at n_max")),
)

T_V = Formula(
    "T_V",
    ("U_DC", "k_E", "k_T", "R_ph", "L_ph", "poles", "n", "rad"),
    lambda sp, U_DC, k_E, k_T, R, L, poles, n, rad: k_T * (
        sp.sqrt((U_DC**2 / 6) * (R**2 + (poles / 2 * n * L / rad) ** 2)
                - (poles / 2 * n * L / rad) ** 2 * (k_E * n / sp.sqrt(3)) ** 2)
        - R * k_E * n / sp.sqrt(3)
    ) / (R**2 + (poles / 2 * n * L / rad) ** 2),
    Source(CASE_FORMAT.at(RATINGS_SECTION, label="a reading (motor voltage limit)",
                          says="(R·I + E)² + (X·I)² = (U_DC/√6)², E = k_E·n/√3, X = p·ω·L, I = T/k_T")),
)


#: The curves a curves file may give per part.
CURVES = ("peak", "S1")
CURVE_COLUMNS = (Column("speed", "speed", "motor speed", positive=False),
                 Column("torque", "torque", "torque on the curve", positive=False))


@dataclass(frozen=True)
class Curves:
    """Speed-torque curves digitised from the makers' charts.

    Parameters
    ----------
    points : dict
        Per ``(part, curve)``, the points as ``(speeds [rad/s], torques [N·m])`` float arrays, speed
        ascending.
    path : pathlib.Path
        The file they come from.
    """

    points: dict
    path: Path

    def of(self, part: str, curve: str):
        """One curve of one motor.

        Parameters
        ----------
        part : str
            The motor's part.
        curve : str
            ``"peak"`` or ``"S1"``.

        Returns
        -------
        tuple of numpy.ndarray or None
            Its speeds [rad/s] and torques [N·m]; None where the file has no such curve.
        """
        return self.points.get((part, curve))


def read_curves(path: Path, parts) -> Curves:
    """A curves file: the columns ``part``, ``curve`` (``peak`` or ``S1``), ``speed`` and ``torque``
    with their units in brackets, and ``source``; a curve's rows in ascending speed.

    Parameters
    ----------
    path : pathlib.Path
        The CSV file.
    parts : numpy.ndarray of str
        The catalog's parts, which the file's must be among.

    Returns
    -------
    Curves
        The curves by part and curve.

    Raises
    ------
    CalcError
        Naming the file, row and column: an unknown part, an unknown curve, a speed not above the
        one before, a negative or malformed number, a missing source.
    """
    try:
        text = path.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise CalcError(f"{path}: cannot read the curves file ({type(exc).__name__})") from None
    rows = list(csv.reader(text.splitlines()))
    if not rows:
        raise CalcError(f"{path}: expected a header and rows of part, curve, speed [unit], torque [unit], source, "
                        "found an empty file")
    header = {}
    for cell in rows[0]:
        m = _HEADER.match(cell)
        if m:
            header[m.group(1)] = (len(header), m.group(2))
    for name in ("part", "curve", "source", "speed", "torque"):
        if name not in header:
            raise CalcError(f"{path}, header: expected a column {as_found(name)}, found {listing(header) or 'none'}")
    factor = {c.name: Q_(1.0, _header_unit(path, c, header[c.name][1])).m_as("rad/s" if c.name == "speed" else "N*m")
              for c in CURVE_COLUMNS}
    known = set(str(p) for p in parts)
    points: dict = {}
    for line, row in enumerate(rows[1:], start=2):
        if not any(cell.strip() for cell in row):
            continue
        cell = {name: (row[k].strip() if k < len(row) else "") for name, (k, _) in header.items()}
        where = f"{path}, row {line}"
        if cell["part"] not in known:
            raise CalcError(f"{where}, column part: {as_found(cell['part'])} is no part of the motor catalog")
        if cell["curve"] not in CURVES:
            raise CalcError(f"{where}, column curve: expected one of {listing(CURVES)}, found "
                            f"{as_found(cell['curve'])}")
        if not cell["source"]:
            raise CalcError(f"{where}, column source: expected the chart the points are read from, found an empty cell")
        values = []
        for name in ("speed", "torque"):
            if not _FLOAT.match(cell[name]) or float(cell[name]) < 0:
                raise CalcError(f"{where}, column {name}: expected a number of zero or more, found "
                                f"{as_found(cell[name])}")
            values.append(float(cell[name]) * factor[name])
        speeds, torques = points.setdefault((cell["part"], cell["curve"]), ([], []))
        if speeds and not values[0] > speeds[-1]:
            raise CalcError(f"{where}, column speed: expected a speed above the curve's one before ({cell['speed']}), "
                            "the points in ascending speed")
        speeds.append(values[0])
        torques.append(values[1])
    note_file_read(path, "Motor curves")
    return Curves({key: (np.array(n), np.array(t)) for key, (n, t) in points.items()}, path)


@dataclass(frozen=True)
class Cycle:
    """A load cycle at the motor, per sample, with the RMS torque and inertia ratio of each motor.

    Parameters
    ----------
    torque : numpy.ndarray [N·m]
        The motor torque of each motor (rows × samples).
    speed : numpy.ndarray [rad/s]
        The motor speed of each sample.
    dt : numpy.ndarray [s]
        The duration of each sample.
    rms : numpy.ndarray [N·m]
        The RMS torque of each motor.
    inertia_ratio : numpy.ndarray [1] or None
        The load-to-motor inertia ratio of each; None where it cannot be had.
    inertia_ratio_missing : str, optional
        What the inertia ratio misses.
    """

    torque: np.ndarray
    speed: np.ndarray
    dt: np.ndarray
    rms: np.ndarray
    inertia_ratio: np.ndarray | None
    inertia_ratio_missing: str | None = None


def peak_limit(cat: Catalog, speed: np.ndarray, dc_link=None, curves: Curves | None = None) -> tuple[np.ndarray, list]:
    """The peak torque of each catalog row at each speed, and the form each row's came from (see the
    module).

    Parameters
    ----------
    cat : Catalog
        The motor rows.
    speed : numpy.ndarray [rad/s]
        The speeds (magnitudes).
    dc_link : pint.Quantity [V], optional
        The drive's DC-link voltage.
    curves : Curves, optional
        The digitised curves.

    Returns
    -------
    tuple
        ``(limit, forms)``: the peak torque [N·m], rows × speeds, and per row ``"ratings"``,
        ``"voltage limit"`` or ``"curves"``.
    """
    n = np.abs(np.asarray(speed, float))[None, :]
    M_max = cat["M_max"].m_as("N*m")[:, None]
    M_N = cat["M_N"].m_as("N*m")[:, None]
    n_N = cat["n_N"].m_as("rad/s")[:, None]
    n_max = cat["n_max"].m_as("rad/s")[:, None]
    with np.errstate(invalid="ignore", divide="ignore"):
        line = T_peak_line.si(M_max=M_max, M_N_motor=M_N, n=n, n_N=n_N, n_max=n_max)
    limit = np.where((n <= n_N) | (n_max <= n_N), M_max, line)
    forms = ["ratings"] * len(cat)
    if dc_link is not None:
        electrical = np.logical_and.reduce([~np.isnan(cat[c].magnitude) for c in ELECTRICAL])
        if electrical.any():
            rows = np.flatnonzero(electrical)
            with np.errstate(invalid="ignore"):
                volts = T_V.si(U_DC=float(dc_link.m_as("V")), k_E=cat["k_E"].m_as("V*s/rad")[rows, None],
                               k_T=cat["k_T"].m_as("N*m/A")[rows, None],
                               R_ph=cat["R_ph"].m_as("ohm")[rows, None], L_ph=cat["L_ph"].m_as("H")[rows, None],
                               poles=cat["poles"].m_as("")[rows, None], n=n)
            volts = np.where(np.isnan(volts), 0.0, np.maximum(volts, 0.0))  # no current left: no torque
            limit[rows] = np.minimum(limit[rows], VOLTAGE_CLEARANCE * volts)
            for r in rows:
                forms[r] = "voltage limit"
    if curves is not None:
        for r, part in enumerate(cat.parts):
            points = curves.of(str(part), "peak")
            if points is not None:
                limit[r] = np.interp(n[0], *points, right=0.0)
                forms[r] = "curves"
    return limit, forms


def s1_limit(cat: Catalog, speed: float, curves: Curves | None) -> np.ndarray:
    """Each row's continuous torque at ``speed`` on its S1 curve; NaN without one.

    Parameters
    ----------
    cat : Catalog
        The motor rows.
    speed : float [rad/s]
        The speed.
    curves : Curves or None
        The digitised curves.

    Returns
    -------
    numpy.ndarray [N·m]
        One per row.
    """
    out = np.full(len(cat), np.nan)
    for r, part in enumerate(cat.parts):
        points = None if curves is None else curves.of(str(part), "S1")
        if points is not None:
            out[r] = np.interp(abs(speed), *points, right=0.0)
    return out


@dataclass(kw_only=True)
class MotorCandidate(Candidate):
    """A catalog motor with its checks, its ratings and the form of its characteristic (the fields of
    :class:`calc.core.selection.Candidate`, and these).

    Parameters
    ----------
    rated_torque : Value [N·m]
        Its rated torque ``T_1N``.
    rotor_inertia : Value [kg·cm²]
        Its rotor's inertia.
    form : str
        Where its peak torque comes from: ``"ratings"``, ``"voltage limit"`` or ``"curves"``.
    inertia_ratio : float or None
        The load-to-motor inertia ratio [1]; None where it cannot be had.
    """

    rated_torque: Value
    rotor_inertia: Value
    form: str
    inertia_ratio: float | None


@dataclass
class MotorSelection(Selection):
    """The catalog motors checked against a cycle and ranked. Arrays run over the rows of ``catalog``.

    Parameters
    ----------
    catalog : Catalog
        The rows checked.
    cycle : Cycle
        The cycle at the motor.
    limit : numpy.ndarray [N·m]
        Peak torque of each row at each sample's speed.
    forms : list of str
        Per row: ``"ratings"``, ``"voltage limit"`` or ``"curves"``.
    dc_link : pint.Quantity [V] or None
        The drive's DC-link voltage; None where the case gives none.
    s1 : numpy.ndarray [N·m]
        Each row's continuous torque on its S1 curve at the mean speed (NaN without one).
    curves : Curves or None
        The curves file the case names, None without one.
    mean_speed : float [rad/s]
        The cycle's mean speed.
    inertia_limit : float [1]
        The highest inertia ratio allowed.
    inertia_limit_from : str
        Where that limit comes from.
    checks : list of CheckArray
        Every check.
    passes : numpy.ndarray of bool
        Every check made passes.
    worst : numpy.ndarray [1]
        Highest utilization of each row.
    order : numpy.ndarray of int
        The rows, best first.
    notes : list of str
        What the outputs say besides the checks.
    """

    catalog: Catalog
    cycle: Cycle
    limit: np.ndarray  # peak torque of each row at each sample's speed (N·m)
    forms: list  # per row: "ratings", "voltage limit" or "curves"
    dc_link: object  # the drive's DC-link voltage (a quantity), None where the case gives none
    s1: np.ndarray  # per row: its S1 curve at the mean speed (N·m), NaN without one
    curves: Curves | None  # the curves file the case names, None without one
    mean_speed: float  # rad/s
    inertia_limit: float
    inertia_limit_from: str
    checks: list
    passes: np.ndarray
    worst: np.ndarray
    order: np.ndarray
    notes: list

    candidate_type = MotorCandidate

    def applies(self, check, row: int) -> bool:
        """A row with an S1 curve is held to it at the mean speed, not to its rated speed.

        Parameters
        ----------
        check : CheckArray
            One of the selection's checks.
        row : int
            The row of the catalog.

        Returns
        -------
        bool
            True where the check is made for the row.
        """
        return check.name != "n_N" or np.isnan(self.s1[row])

    def row_fields(self, row: int) -> dict:
        lam = None if self.cycle.inertia_ratio is None else float(self.cycle.inertia_ratio[row])
        return dict(rated_torque=Value.of(self.catalog["M_N"][row], "N*m"),
                    rotor_inertia=Value.of(self.catalog["J"][row], "kg*cm**2"),
                    form=self.forms[row], inertia_ratio=lam)


def select_motors(cat: Catalog, cycle: Cycle, dc_link=None, curves: Curves | None = None,
                  inertia_limit: float = INERTIA_RATIO_LIMIT,
                  inertia_limit_from: str = "the default", t_cycle: float | None = None) -> MotorSelection:
    """Every row of ``cat`` (no partial row) against the cycle at the motor (:class:`Cycle`), its
    checks (module docstring) and the ranking (:data:`RANKING`); failing rows after the passing
    ones, closest to passing first.

    Parameters
    ----------
    cat : Catalog
        The motor rows.
    cycle : Cycle
        The cycle at the motor.
    dc_link : pint.Quantity [V], optional
        The drive's DC-link voltage.
    curves : Curves, optional
        The digitised curves.
    inertia_limit : float [1]
        The highest inertia ratio allowed; default :data:`INERTIA_RATIO_LIMIT`.
    inertia_limit_from : str
        Where that limit comes from; default ``"the default"``.
    t_cycle : float [s], optional
        The cycle time, against the motors' thermal time constants.

    Returns
    -------
    MotorSelection
        The rows checked and ranked.
    """
    rows = len(cat)
    limit, forms = peak_limit(cat, cycle.speed, dc_link, curves)
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.abs(cycle.torque) / limit
    ratio = np.where(np.isnan(ratio), np.inf, ratio)  # a torque where no torque is available
    k = np.argmax(ratio, axis=1)
    at = np.arange(rows)
    worst_torque = np.abs(cycle.torque[at, k])
    worst_limit = limit[at, k]
    n_mean = float(n_2m.si(n_2k=cycle.speed, t_k=cycle.dt))  # the mean over every sample, pauses included
    s1 = s1_limit(cat, n_mean, curves)
    on_curve = ~np.isnan(s1)
    top = float(np.max(np.abs(cycle.speed)))
    ones = np.ones(rows)
    checks = [
        CheckArray("peak", None, "|T_1| <= T_peak(n_1) at every sample", Q_(worst_torque, "N*m"),
                   Q_(worst_limit, "N*m"), "N*m"),
        CheckArray("RMS", None, "T_1rms <= M_N" if not on_curve.any()
                   else "T_1rms <= T_S1(n_1mean), M_N without an S1 curve", Q_(cycle.rms, "N*m"),
                   Q_(np.where(on_curve, s1, cat["M_N"].m_as("N*m")), "N*m"), "N*m"),
        CheckArray("n_N", None, "n_1mean <= n_N", Q_(n_mean * ones, "rad/s"), cat["n_N"], "rpm"),
        CheckArray("n_max", None, "n_1max <= n_max", Q_(top * ones, "rad/s"), cat["n_max"], "rpm"),
    ]
    if cycle.inertia_ratio is not None or cycle.inertia_ratio_missing is not None:
        checks.append(CheckArray("lambda", None, "λ <= λ_max", None if cycle.inertia_ratio is None
                                 else Q_(cycle.inertia_ratio, ""),
                                 Q_(inertia_limit * ones, ""), "", not_made=cycle.inertia_ratio_missing))
    passes = np.logical_and.reduce([c.passes | (on_curve if c.name == "n_N" else False) for c in checks if c.made])
    passes &= ~cat.partial
    worst = np.max([np.where(on_curve & (c.name == "n_N"), 0.0,
                             np.where(np.isnan(c.utilization), np.inf if c.made else 0.0, c.utilization))
                    for c in checks], axis=0)
    worst = np.where(cat.partial, np.inf, worst)
    keys = (worst, np.where(passes, cat["J"].m_as("kg*m**2"), 0.0), np.where(passes, cat["M_N"].m_as("N*m"), 0.0),
            ~passes)
    order = np.lexsort(keys)
    order = order[~cat.partial[order]]
    notes = []
    th = cat["T_th"].m_as("s")
    if t_cycle is not None:
        long = [str(cat.parts[r]) for r in order[:3] if not np.isnan(th[r]) and t_cycle > THERMAL_SHARE * th[r]]
        if long:
            notes.append(f"the cycle ({t_cycle:g} s) is not short against the thermal time constant of "
                         f"{', '.join(long)}: "
                         "the RMS torque understates the winding's peak temperature")
    return MotorSelection(cat, cycle, limit, forms, dc_link, s1, curves, n_mean, inertia_limit, inertia_limit_from,
                          checks, passes, worst, order, notes)
