"""The servo drive (amplifier) that feeds the motor: its catalog, the motor's current over the
cycle against the drive's ratings, the braking energy against the DC link and the brake resistor,
and the winding's temperature as a first-order model (case format, "The servo drive").

The published methods, as the makers' sizing chapters state them:

* **Current.** The motor's phase current is ``I = T_1 / k_T`` (``k_T`` per A rms; where the catalog
  gives only ``M_0`` and ``I_0``, ``k_T = M_0 / I_0`` as Beckhoff and Kollmorgen define it). The
  saturation of the iron near the peak current is not modelled: the current there is a lower
  bound. The drive's continuous current ``I_N`` is checked against the cycle's RMS current, its
  peak current ``I_max`` against the cycle's peak, and the longest time the current stays above
  ``I_N`` against the drive's peak time ``t_max``. A drive's DC link must suit the motor: the
  drive's ``U_DC`` lies in the motor's voltage class (:data:`VOLTAGE_CLASSES`).
* **Braking energy.** Each braking event (a run of samples where the motor power is negative) gives
  back the integral of the negative power (Kollmorgen's stop ``E = ½ (J_M + J_L) ω² − 3 I² (R/2)
  t_d − ½ T_F ω t_d`` is its case for a ramp to rest; the winding and drive losses are not
  subtracted, so the energy is an upper bound). The DC link absorbs ``E_C`` (published, or
  ``½ C (U_on² − U_DC²)``) of each event; the rest goes to the brake resistor: its energy per
  cycle over the cycle time against its continuous power, the peak braking power against
  ``U_on² / R`` (or a published peak power), and ``R >= R_min``.
* **Heat.** ``dθ/dt = (u − θ) / T_th`` with ``u = (I / I_0)² = (T_1 / M_0)²``: the winding's rise
  over its rise under ``M_0`` held. With ``u`` constant over each sample the model steps exactly,
  ``θ_k+1 = u_k + (θ_k − u_k) e^(−t_k / T_th)``; the periodic state after many cycles follows in
  closed form from one cycle (:func:`winding_temperature`). For a square cycle (``u_1`` for
  ``t_1``, then rest) its highest value is :data:`theta_max`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..core.checks import BOUNDARY_RTOL, CheckArray
from ..core.citation import Source
from ..core.formula import Formula
from ..core.selection import Selection
from ..core.units import Q_
from ..data.catalog import Column, Rule, Schema, no_less
from .documents import CASE_FORMAT, DRIVE_SIZING

#: The case format's section that states the drive's readings.
DRIVE_SECTION = "The servo drive"

SCHEMA = Schema(
    kind="drive",
    columns=(
        Column("U_DC", "voltage", "DC-link voltage", required=False),
        Column("I_N", "current", "continuous output current"),
        Column("I_max", "current", "peak output current"),
        Column("t_max", "time", "time the peak current may last", required=False),
        Column("C_DC", "capacitance", "DC-link capacitance", required=False),
        Column("E_C", "energy", "energy the DC link absorbs", required=False),
        Column("R_int", "resistance", "internal brake resistor", required=False),
        Column("P_R_int", "power", "continuous power of the internal brake resistor", required=False),
        Column("R_min", "resistance", "smallest external brake resistor", required=False),
    ),
    text_columns=("part", "maker", "source"),
    optional_text=("family", "supply", "overload", "motor_families", "partial"),
    partial="partial",
    rules=(Rule("I_max >= I_N", no_less("I_max", "I_N"), "I_max"),),
)

#: The voltage classes of drives and motors, by DC-link voltage [V]: a drive suits a motor of the
#: same class (the AC supply classes 48 V DC, 100-120 V, 200-240 V and 380-480 V, as sqrt(2) · U_AC).
VOLTAGE_CLASSES = (("48 V DC", 0.0, 60.0), ("100-120 V AC", 120.0, 200.0), ("200-240 V AC", 250.0, 400.0),
                   ("380-480 V AC", 450.0, 800.0))

#: How :func:`select_drives` ranks the catalog's drives.
RANKING = ("passing first; then the smallest adequate drive, the lowest continuous current I_N, ties to the lower "
           "peak current I_max; then lowest worst utilization; partial rows are never ranked")

_SIZING = Source(CASE_FORMAT.at(DRIVE_SECTION, label="a reading (servo drive)"),
                 DRIVE_SIZING.at(says="the makers' sizing chapters"))

I_ph = Formula(
    "I_ph", ("T_1", "k_T"), lambda sp, T, k_T: T / k_T,
    Source(DRIVE_SIZING.at(says="I = T / k_T, saturation near the peak current not modelled"),
           CASE_FORMAT.at(DRIVE_SECTION, label="a reading (servo drive)")),
)

k_T_derived = Formula(
    "k_T_derived", ("M_0", "I_0"), lambda sp, M_0, I_0: M_0 / I_0,
    Source(DRIVE_SIZING.at(says="Beckhoff and Kollmorgen define k_T = M_0 / I_0")),
)

E_C = Formula(
    "E_C", ("C_DC", "U_on", "U_DC"), lambda sp, C, U_on, U_DC: C * (U_on**2 - U_DC**2) / 2,
    Source(DRIVE_SIZING.at(says="the DC link absorbs ½ C (U_on² − U_DC²) before the chopper switches on")),
)

P_R_peak = Formula(
    "P_R_peak", ("U_on", "R_br"), lambda sp, U_on, R: U_on**2 / R,
    Source(DRIVE_SIZING.at(says="the resistor takes U_on² / R at the chopper voltage")),
)

P_R_avg = Formula("P_R_avg", ("E_R", "t_cycle"), lambda sp, E_R, t_cycle: E_R / t_cycle, _SIZING)

u_th = Formula(
    "u_th", ("T_1", "M_0"), lambda sp, T, M_0: (T / M_0) ** 2,
    Source(CASE_FORMAT.at(DRIVE_SECTION, label="a reading (winding temperature)",
                          says="(I / I_0)² = (T_1 / M_0)² with I = T_1 / k_T and k_T = M_0 / I_0")),
)

theta_max = Formula(
    "theta_max", ("u_th", "t_1", "t_cycle", "T_th"),
    lambda sp, u, t_1, t_c, T: u * (1 - sp.exp(-t_1 / T)) / (1 - sp.exp(-t_c / T)),
    Source(CASE_FORMAT.at(DRIVE_SECTION, label="a reading (winding temperature)",
                          says="dθ/dt = (u − θ) / T_th, periodic: the square cycle's highest θ")),
)


def voltage_class(U_DC: float) -> str | None:
    """The voltage class of a DC-link voltage.

    Parameters
    ----------
    U_DC : float [V]
        The DC-link voltage.

    Returns
    -------
    str or None
        The class's name (:data:`VOLTAGE_CLASSES`); None outside every class, or for NaN.

    Examples
    --------
    >>> voltage_class(283.0), voltage_class(565.0), voltage_class(48.0)
    ('200-240 V AC', '380-480 V AC', '48 V DC')
    """
    return next((name for name, low, high in VOLTAGE_CLASSES if low <= U_DC <= high), None)


def class_bounds(U_DC: float) -> tuple[float, float]:
    """The DC-link voltages of a voltage's class.

    Parameters
    ----------
    U_DC : float [V]
        A DC-link voltage inside a class.

    Returns
    -------
    tuple of float [V]
        Its lowest and highest DC-link voltage; NaN, NaN outside every class.
    """
    return next(((low, high) for _, low, high in VOLTAGE_CLASSES if low <= U_DC <= high), (np.nan, np.nan))


def longest_run(dt: np.ndarray, above: np.ndarray) -> float:
    """The longest time a condition holds without a break, the cycle repeated (a run at the end
    goes on into the run at the start of the next cycle).

    Parameters
    ----------
    dt : numpy.ndarray [s]
        The duration of each sample.
    above : numpy.ndarray of bool
        Where the condition holds.

    Returns
    -------
    float [s]
        The longest run; the whole cycle where it always holds.

    Examples
    --------
    >>> longest_run(np.array([1.0, 2.0, 3.0, 4.0]), np.array([True, False, False, True]))
    5.0
    """
    dt, above = np.asarray(dt, float), np.asarray(above, bool)
    if not above.any():  # no run (most drives of a catalog are never exceeded)
        return 0.0
    if above.all():
        return float(dt.sum())
    k = int(np.flatnonzero(~above)[0])  # start after a sample where it does not hold
    d, a = np.roll(dt, -k), np.roll(above, -k)
    run = np.cumsum(np.where(a, d, 0.0))
    reset = np.maximum.accumulate(np.where(a, 0.0, run))
    return float((run - reset).max())


@dataclass
class DriveSelection(Selection):
    """The drives of a catalog checked against the motor's current and voltage class, and ranked.

    Parameters
    ----------
    catalog : calc.data.catalog.Catalog
        The drives, of :data:`SCHEMA` (partial rows left out).
    checks : list of calc.core.checks.CheckArray
        The checks over the rows.
    passes : numpy.ndarray of bool
        Each row's verdict.
    order : numpy.ndarray of int
        The rows, best first.
    notes : list of str
        What was left out or assumed.
    """

    catalog: object
    checks: list
    passes: np.ndarray
    order: np.ndarray
    notes: list = field(default_factory=list)


def drive_checks(cat, I_rms: float | None, I_peak: float | None, t_above, U_motor: float | None,
                 no_current: str | None = None, characteristic: tuple = (None, "not known")) -> list:
    """The checks of every drive of a catalog against the motor's current and voltage class.

    Parameters
    ----------
    cat : calc.data.catalog.Catalog
        The drives, of :data:`SCHEMA`.
    I_rms : float or None [A]
        The motor's RMS current over the cycle; None where it is not known.
    I_peak : float or None [A]
        Its peak current.
    t_above : numpy.ndarray or None [s]
        For each row, the longest time the current stays above the row's ``I_N``.
    U_motor : float or None [V]
        The motor's DC-link voltage (its voltage class); None: the class is not checked.
    no_current : str, optional
        Why the current is not known (the checks of current are then not made).
    characteristic : tuple, optional
        The DC-link voltage the motor's speed-torque characteristic is for [V] (None: not known,
        the check left out) and where it comes from, or why it is not known.

    Returns
    -------
    list of calc.core.checks.CheckArray
        Continuous current, peak current, peak time, the DC-link voltage against the
        characteristic's, and the voltage class's bounds where the motor has one.
    """
    n = len(cat)
    ones = np.ones(n)

    def given(x, unit):
        return None if no_current else Q_(x * ones, unit)
    out = [
        CheckArray("I_N", None, "I_rms <= I_N", given(I_rms, "A"), cat["I_N"], "A", not_made=no_current),
        CheckArray("I_max", None, "I_peak <= I_max", given(I_peak, "A"), cat["I_max"], "A", not_made=no_current),
        CheckArray("t_max", None, "t(I > I_N) <= t_max", None if no_current else Q_(t_above, "s"), cat["t_max"], "s",
                   not_made=no_current, unrated="the catalog gives no peak time t_max"),
    ]
    if characteristic[0] is not None:
        out.append(characteristic_check(cat, characteristic[0]))
    if U_motor is not None:
        low, high = class_bounds(U_motor)
        U = cat["U_DC"].m_as("V")
        cls = voltage_class(U_motor)
        unrated = "the catalog gives no DC-link voltage U_DC"
        out += [CheckArray("U_DC", None, f"U_DC <= {high:g} V ({cls})", Q_(U, "V"),
                           Q_(high * ones, "V"), "V", unrated=unrated),
                CheckArray("U_DC", None, f"{low:g} V <= U_DC ({cls})", Q_(low * ones, "V"),
                           Q_(U, "V"), "V", unrated=unrated)]
    return out


def characteristic_check(cat, U: float):
    """Each drive's DC-link voltage against the one the motor's speed-torque characteristic is
    for: a lower DC link gives the motor less torque at speed than it was checked with.

    Parameters
    ----------
    cat : calc.data.catalog.Catalog
        The drives, of :data:`SCHEMA`.
    U : float [V]
        The DC-link voltage the motor's characteristic is for.

    Returns
    -------
    calc.core.checks.CheckArray
        ``U_DC >= U``; a row without ``U_DC`` is not checked, saying so.
    """
    return CheckArray("U_DC", None, f"U_DC >= {U:g} V (motor's characteristic)", Q_(U * np.ones(len(cat)), "V"),
                      cat["U_DC"], "V", unrated="the catalog gives no DC-link voltage U_DC")


def _longest_runs_above(dt: np.ndarray, I_samples: np.ndarray, I_N: np.ndarray) -> np.ndarray:
    """:func:`longest_run` of the current above each drive's rating, once per distinct rating (a
    catalog's drives share a few ratings).

    Parameters
    ----------
    dt : numpy.ndarray [s]
        The duration of each sample of the cycle.
    I_samples : numpy.ndarray [A]
        The current of each sample.
    I_N : numpy.ndarray [A]
        Each drive's continuous current.

    Returns
    -------
    numpy.ndarray [s]
        Each drive's longest time above its continuous current.
    """
    ratings, each = np.unique(I_N, return_inverse=True)
    return np.array([longest_run(dt, I_samples > x) for x in ratings])[each.ravel()]


def select_drives(cat, I_rms, I_peak, dt, I_samples, U_motor, no_current: str | None = None,
                  characteristic: tuple = (None, "not known")) -> DriveSelection:
    """Every drive of a catalog against the motor's current, ranked as :data:`RANKING` says.

    Parameters
    ----------
    cat : calc.data.catalog.Catalog
        The drives, of :data:`SCHEMA`; its partial rows are left out.
    I_rms : float or None [A]
        The motor's RMS current over the cycle.
    I_peak : float or None [A]
        Its peak current.
    dt : numpy.ndarray [s]
        The duration of each sample of the cycle.
    I_samples : numpy.ndarray or None [A]
        The current of each sample (magnitude).
    U_motor : float or None [V]
        The motor's DC-link voltage; None: the voltage class is not checked.
    no_current : str, optional
        Why the current is not known.
    characteristic : tuple, optional
        The DC-link voltage the motor's characteristic is for [V] (None: not known) and where from.

    Returns
    -------
    DriveSelection
        The rows checked and ranked.
    """
    notes = []
    if cat.partial.any():
        notes.append(f"{int(cat.partial.sum())} partial rows of the drive catalog are never ranked "
                     f"(no continuous or peak current published)")
        cat = cat.rows(~cat.partial)
    I_N = cat["I_N"].m_as("A")
    t_above = None if no_current else _longest_runs_above(dt, I_samples, I_N)
    if U_motor is None:
        notes.append("the voltage class is not checked: the motor's DC-link voltage is not known")
    if characteristic[0] is None:
        notes.append(f"the DC link is not checked against the motor's characteristic, whose DC-link voltage is "
                     f"{characteristic[1]}")
    checks = drive_checks(cat, I_rms, I_peak, t_above, U_motor, no_current, characteristic)
    passes = np.logical_and.reduce([c.passes for c in checks if c.made] or [np.ones(len(cat), bool)])
    if no_current:
        worst = np.full(len(cat), np.nan)
    else:  # the margin of the current's checks
        worst = np.nanmax(np.vstack([c.ranked_utilization for c in checks[:3]]), axis=0)
    worst = np.where(np.isnan(worst), np.inf, worst)
    order = np.lexsort((cat.parts.astype(str), worst, np.where(passes, cat["I_max"].m_as("A"), 0.0),
                        np.where(passes, I_N, 0.0), ~passes))
    return DriveSelection(cat, checks, passes, order, notes)


@dataclass(frozen=True)
class BrakingEvent:
    """A run of samples in which the motor brakes (its power negative).

    Parameters
    ----------
    start : float [s]
        When it starts in the cycle.
    duration : float [s]
        How long it lasts.
    energy : float [J]
        The energy it gives back (the integral of the negative power, no loss subtracted).
    peak_power : float [W]
        Its highest braking power.
    phase : str
        The phase it starts in (``decel``).
    """

    start: float
    duration: float
    energy: float
    peak_power: float
    phase: str = ""


def braking_events(dt, power, phase_names=None) -> list[BrakingEvent]:
    """The braking events of a cycle: each run of samples with negative motor power.

    Parameters
    ----------
    dt : numpy.ndarray [s]
        The duration of each sample.
    power : numpy.ndarray [W]
        The motor power of each sample (negative: braking).
    phase_names : sequence of str, optional
        The phase of each sample.

    Returns
    -------
    list of BrakingEvent
        In the order of the cycle.

    Examples
    --------
    A stop of 0.2 s at 100 W braking, after 1 s of driving:

    >>> e = braking_events(np.array([1.0, 0.1, 0.1, 0.5]), np.array([50.0, -100.0, -100.0, 0.0]))
    >>> [(x.start, round(x.duration, 9), round(x.energy, 9)) for x in e]
    [(1.0, 0.2, 20.0)]
    """
    dt, power = np.asarray(dt, float), np.asarray(power, float)
    back = power < 0
    edges = np.diff(np.concatenate(([0], back.astype(int), [0])))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    t0 = np.concatenate(([0.0], np.cumsum(dt)))
    out = []
    for a, b in zip(starts, ends):
        out.append(BrakingEvent(float(t0[a]), float(t0[b] - t0[a]), float(-(power[a:b] * dt[a:b]).sum()),
                                float(-power[a:b].min()), "" if phase_names is None else str(phase_names[a])))
    return out


def resistor_energies(events: list, E_link: float) -> np.ndarray:
    """What each braking event leaves for the brake resistor once the DC link absorbed its share
    (the link discharges while the axis drives, so each event finds it at ``U_DC``).

    Parameters
    ----------
    events : list of BrakingEvent
        The cycle's braking events.
    E_link : float [J]
        The energy the DC link absorbs.

    Returns
    -------
    numpy.ndarray [J]
        Each event's energy above ``E_link`` (zero where the link takes it all).

    Examples
    --------
    >>> resistor_energies([BrakingEvent(1.2, 0.1, 42.0, 900.0)], 20.0).tolist()
    [22.0]
    """
    return np.maximum(np.array([e.energy for e in events], float) - E_link, 0.0)


def winding_temperature(dt, u, T_th: float, cycles: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """The winding's temperature rise over its rise under ``M_0`` held, in the periodic state
    (after many cycles), at the start and at the end of every sample over ``cycles`` cycles.

    Exact for a thermal load ``u`` constant over each sample: over one cycle ``θ_end = A · θ_0 +
    B`` with ``A = e^(−t_cycle / T_th)``, so the periodic ``θ_0 = B / (1 − A)``.

    Parameters
    ----------
    dt : numpy.ndarray [s]
        The duration of each sample.
    u : numpy.ndarray [1]
        Its thermal load ``(T_1 / M_0)²``.
    T_th : float [s]
        The winding's thermal time constant.
    cycles : int
        How many cycles to give.

    Returns
    -------
    tuple of numpy.ndarray
        Times [s] from the start of the first cycle, and θ [1] at each.

    Examples
    --------
    Held at ``u = 1`` the whole cycle, the winding sits at its rise under ``M_0``:

    >>> t, th = winding_temperature(np.array([1.0]), np.array([1.0]), 600.0)
    >>> [round(float(x), 12) for x in th]
    [1.0, 1.0, 1.0]
    """
    dt, u = np.asarray(dt, float), np.asarray(u, float)
    decay = np.exp(-dt / T_th)
    # θ after each sample from θ_0 = 0, and the decay of θ_0 to it
    theta, rest = [], 1.0
    th = 0.0
    for d, x in zip(decay, u):
        th = x + (th - x) * d
        rest *= d
        theta.append(th)
    theta0 = th / (1.0 - rest)
    one = np.array(theta) + theta0 * np.cumprod(decay)
    values = np.concatenate(([theta0], np.tile(one, cycles)))
    times = np.concatenate(([0.0], np.cumsum(np.tile(dt, cycles))))
    return times, values


def square_cycle_peak(u_1: float, t_1: float, t_cycle: float, T_th: float) -> float:
    """:data:`theta_max` of a square cycle, from its formula.

    Parameters
    ----------
    u_1 : float [1]
        The thermal load while loaded.
    t_1 : float [s]
        The time loaded.
    t_cycle : float [s]
        The cycle time.
    T_th : float [s]
        The thermal time constant.

    Returns
    -------
    float [1]
        The highest θ of the periodic state.

    Examples
    --------
    A short cycle sits near its mean load: u = 4 for a quarter of the cycle gives about 1, by hand
    4 (1 - e^(-1/3600)) / (1 - e^(-4/3600)) = 1.000417:

    >>> round(float(square_cycle_peak(4.0, 1.0, 4.0, 3600.0)), 5)
    1.00042
    """
    return float(theta_max.si(u_th=u_1, t_1=t_1, t_cycle=t_cycle, T_th=T_th))


def passes_all(checks) -> bool | None:
    """The verdict of some checks (:class:`calc.core.checks.Check`): False where one fails, None
    where none fails but one is not made, True otherwise.

    Parameters
    ----------
    checks : iterable of calc.core.checks.Check
        The checks.

    Returns
    -------
    bool or None
    """
    made = [k.passes for k in checks]
    if any(p is False for p in made):
        return False
    return None if any(p is None for p in made) else True



@dataclass(frozen=True)
class Winding:
    """The winding's temperature over the cycle in the periodic state (:func:`winding_temperature`).

    Parameters
    ----------
    times : numpy.ndarray [s]
        Times over two cycles.
    theta : numpy.ndarray [1]
        The rise over the rise under the reference torque held, at each time.
    reference : str
        The reference torque's symbol: ``M_0``, or ``M_N`` where the motor gives no ``M_0``.
    reference_torque : float [N·m]
        Its value.
    T_th : float [s]
        The thermal time constant.
    """

    times: np.ndarray
    theta: np.ndarray
    reference: str
    reference_torque: float
    T_th: float

    @property
    def utilization(self) -> float:
        """θ_max [1]: 1 at the winding's rise under the reference torque held continuously."""
        return float(self.theta.max())


def winding(dt, T_1, reference: str, M_ref: float, T_th: float) -> Winding:
    """The winding's model over a cycle of motor torques.

    Parameters
    ----------
    dt : numpy.ndarray [s]
        The duration of each sample.
    T_1 : numpy.ndarray [N·m]
        The motor torque of each sample.
    reference : str
        ``M_0`` or ``M_N``: which torque ``M_ref`` is.
    M_ref : float [N·m]
        The torque whose continuous hold gives θ = 1.
    T_th : float [s]
        The thermal time constant.

    Returns
    -------
    Winding
        Its temperature over two cycles.

    Examples
    --------
    Twice the standstill torque for a quarter of a cycle short against T_th: about the mean load 1:

    >>> round(winding(np.array([1.0, 3.0]), np.array([2.0, 0.0]), "M_0", 1.0, 3600.0).utilization, 3)
    1.0
    """
    u = u_th.si(T_1=np.asarray(T_1, float), M_0=M_ref)
    times, theta = winding_temperature(dt, u, T_th)
    return Winding(times, theta, reference, float(M_ref), float(T_th))


def bus_powers(samples: list, starts: list, cycle: float) -> tuple[np.ndarray, np.ndarray]:
    """Several axes' power on one time base over the machine's cycle: each axis's cycle repeated
    to fill the machine's, shifted by its start (wrapping round the machine's cycle), every
    sample edge of every axis an edge of the time base.

    Parameters
    ----------
    samples : list of tuple
        Each axis's sample durations [s] and power [W] over its own cycle (numpy arrays).
    starts : list of float [s]
        When each axis's cycle starts in the machine's.
    cycle : float [s]
        The machine's cycle; each axis's cycle divides it.

    Returns
    -------
    tuple of numpy.ndarray
        The time base's edges [s] from 0 to ``cycle``, and each axis's power over its steps [W],
        one row per axis.

    Examples
    --------
    An axis braking 100 W for 1 s of a 2 s cycle and one driving 100 W for its first second,
    started 1 s later: the second takes what the first gives back.

    >>> t, p = bus_powers([(np.array([1.0, 1.0]), np.array([0.0, -100.0])),
    ...                    (np.array([1.0, 1.0]), np.array([100.0, 0.0]))], [0.0, 1.0], 2.0)
    >>> t.tolist(), p.sum(axis=0).tolist()
    ([0.0, 1.0, 2.0], [0.0, 0.0])
    """
    edges = [np.array([0.0, cycle])]
    local = []
    for (dt, _), start in zip(samples, starts):
        dt = np.asarray(dt, float)
        t_axis = float(dt.sum())
        begins = np.concatenate(([0.0], np.cumsum(dt)[:-1]))
        repeats = int(round(cycle / t_axis))
        edges.append((start + (np.arange(repeats)[:, None] * t_axis + begins[None, :]).ravel()) % cycle)
        local.append((begins, t_axis))
    times = np.unique(np.concatenate(edges))
    times = times[np.concatenate(([True], np.diff(times) > BOUNDARY_RTOL * cycle))]  # one edge where two meet
    times[-1] = cycle
    mids = (times[:-1] + times[1:]) / 2
    powers = np.empty((len(samples), len(mids)))
    for k, ((_, p), start, (begins, t_axis)) in enumerate(zip(samples, starts, local)):
        tau = (mids - start) % t_axis
        powers[k] = np.asarray(p, float)[np.searchsorted(begins, tau, side="right") - 1]
    return times, powers


def bus_total(samples: list, starts: list, cycle: float) -> tuple[np.ndarray, np.ndarray]:
    """The sum of several axes' power over the machine's cycle, as :func:`bus_powers` gives it
    summed, from each axis's steps of power alone: the sum at the cycle's start, then each edge's
    change added in time order (edges closer than the checks' tolerance taken as one). Costs the
    sorting of the edges, not a row per axis over every edge.

    Parameters
    ----------
    samples : list of tuple
        Each axis's sample durations [s] and power [W] over its own cycle (numpy arrays).
    starts : list of float [s]
        When each axis's cycle starts in the machine's.
    cycle : float [s]
        The machine's cycle; each axis's cycle divides it.

    Returns
    -------
    tuple of numpy.ndarray
        The edges [s] from 0 to ``cycle``, and the summed power over each step [W].

    Examples
    --------
    >>> t, p = bus_total([(np.array([1.0, 1.0]), np.array([0.0, -100.0])),
    ...                   (np.array([1.0, 1.0]), np.array([100.0, 0.0]))], [0.0, 1.0], 2.0)
    >>> t.tolist(), p.tolist()
    ([0.0, 1.0, 2.0], [0.0, 0.0])
    """
    tol = BOUNDARY_RTOL * cycle
    times, changes, first = [], [], 0.0
    for (dt, p), start in zip(samples, starts):
        dt, p = np.asarray(dt, float), np.asarray(p, float)
        t_axis = float(dt.sum())
        begins = np.concatenate(([0.0], np.cumsum(dt)[:-1]))
        first += p[np.searchsorted(begins, (-start) % t_axis, side="right") - 1]
        repeats = int(round(cycle / t_axis))
        times.append(((start + (np.arange(repeats)[:, None] * t_axis + begins[None, :])) % cycle).ravel())
        changes.append(np.tile(p - np.roll(p, 1), repeats))
    steps = np.round(np.concatenate(times) / tol)
    edge, at = np.unique(steps, return_inverse=True)
    change = np.bincount(at, weights=np.concatenate(changes), minlength=len(edge))
    inside = (edge > 0) & (edge < round(cycle / tol))  # a change at the cycle's start is in ``first``
    edges = np.concatenate(([0.0], edge[inside] * tol, [cycle]))
    return edges, first + np.concatenate(([0.0], np.cumsum(change[inside])))
