"""The motor's side of a load cycle: the torque the motor gives through the gearbox, its peak and
its RMS over the whole cycle (case format, "The motor's side").

The load cycle at the gearbox output (torque ``T_2``, speed ``ω_2``, acceleration ``α_2``, each
sample or segment with its duration) is carried to the motor through the ratio ``i`` and the
efficiency ``η``:

* driving (power flows from the motor to the load, ``T_2 · ω_2 >= 0``, a hold at rest included):
  ``T_1 = (J_motor + J_1) · α_1 + T_2 / (i · η)``;
* driven back (power flows from the load, ``T_2 · ω_2 < 0``): ``T_1 = (J_motor + J_1) · α_1 +
  T_2 · η / i``, the gearbox's losses then help the motor;

with ``α_1 = i · α_2`` and ``J_1`` the gearbox's inertia at its input (plus a motor-side
coupling's whole inertia). The rotor term needs the accelerations of a sampled cycle
(:class:`calc.domain.cycle.SampledCycle`); over typed segments they are not known and the term is left
out (``alpha_2=None``). The RMS torque weighs every sample by its duration, pauses with the torque
that holds the load (so a pause lowers the RMS of a level axis and keeps the holding torque of an
inclined one).

Every function broadcasts: a gearbox per row (``i``, ``η``, ``J_1`` of shape ``(rows, 1)``)
against the samples of one cycle (shape ``(samples,)``) gives the torques of every row at once.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ..core.checks import CheckArray
from .cycle import SampledCycle
from ..core.citation import Source
from ..core.formula import Formula, segment_sum
from ..core.units import Q_, as_kind
from .documents import CASE_FORMAT, ERRATA, MECHANICS

alpha_1 = Formula(
    "alpha_1",
    ("alpha_2", "i"),
    lambda sp, alpha_2, i: i * alpha_2,
    Source(CASE_FORMAT.at("The motor's side", note="α_1 = i · α_2")),
)

T_1_drive = Formula(
    "T_1_drive",
    ("J_motor", "J_1", "alpha_1", "T_2", "i", "eta"),
    lambda sp, J_motor, J_1, alpha_1, T_2, i, eta: (J_motor + J_1) * alpha_1 + T_2 / (i * eta),
    Source(CASE_FORMAT.at("The motor's side", says="driving, the losses of the gearbox on the motor")),
)

T_1_back = Formula(
    "T_1_back",
    ("J_motor", "J_1", "alpha_1", "T_2", "i", "eta"),
    lambda sp, J_motor, J_1, alpha_1, T_2, i, eta: (J_motor + J_1) * alpha_1 + T_2 * eta / i,
    Source(CASE_FORMAT.at("The motor's side",
                          says="driven back (T_2 · ω_2 < 0), the losses of the gearbox on the load")),
)

T_1rms = Formula(
    "T_1rms",
    ("T_1k", "t_k"),
    lambda sp, T, t: sp.sqrt(segment_sum(T**2 * t) / segment_sum(t)),
    Source(CASE_FORMAT.at("The motor's side", note="RMS over the whole cycle; a pause counts with its holding torque")),
)


P_1 = Formula(
    "P_1",
    ("T_1", "omega_1", "rad"),
    lambda sp, T, w, rad: T * w / rad,
    Source(MECHANICS.at(says="power = torque · angular speed", note=ERRATA.at("E15", label="E15"))),
)

W_regen = Formula(
    "W_regen",
    ("P_back_k", "t_k"),
    lambda sp, P, t: segment_sum(P * t),
    Source(MECHANICS.at(says="the work of the braking samples, before the motor's and the drive's losses")),
)


@dataclass(frozen=True)
class Energy:
    """The motor's power over a cycle (at the shaft: the motor's copper losses and the drive's would
    lower what is given back).

    Parameters
    ----------
    peak_power : float [W]
        Its peak driving power.
    peak_braking_power : float [W]
        Its peak braking power.
    regenerated_per_cycle : float [J]
        The energy given back per cycle.
    """

    peak_power: float
    peak_braking_power: float
    regenerated_per_cycle: float


def energy(dt, speed_1, T_1) -> Energy:
    """:class:`Energy` of the samples of a cycle at the motor: durations [s], speeds [rad/s] and
    torques [N·m] (SI float arrays).

    Parameters
    ----------
    dt : numpy.ndarray [s]
        The duration of each sample.
    speed_1 : numpy.ndarray [rad/s]
        The motor speed of each sample.
    T_1 : numpy.ndarray [N·m]
        The motor torque of each sample.

    Returns
    -------
    Energy
        Peak powers and the energy given back.

    Examples
    --------
    Braking 2 N·m at 300 rad/s for 0.1 s gives back 2 · 300 · 0.1 = 60 J; driving 3 N·m at 300
    rad/s is 900 W:

    >>> e = energy(np.array([0.1, 0.1]), np.array([300.0, 300.0]), np.array([3.0, -2.0]))
    >>> e.peak_power, e.peak_braking_power, round(e.regenerated_per_cycle, 9)
    (900.0, 600.0, 60.0)
    """
    power = P_1.si(T_1=np.asarray(T_1, float), omega_1=np.asarray(speed_1, float))
    back = np.where(power < 0, -power, 0.0)
    return Energy(float(max(power.max(), 0.0)), float(back.max()),
                  float(W_regen.si(P_back_k=back, t_k=np.asarray(dt, float))))


@dataclass(frozen=True)
class Phase:
    """One segment of the cycle at the motor.

    Parameters
    ----------
    phase : str
        Its phase name.
    duration : float [s]
        Its duration.
    speed : float [rad/s]
        Its mean speed.
    rms_torque : float [N·m]
        Its RMS torque.
    peak_torque : float [N·m]
        Its peak torque magnitude.
    """

    phase: str
    duration: float
    speed: float
    rms_torque: float
    peak_torque: float


def phases(segment, names, dt, speed_1, T_1) -> list[Phase]:
    """The cycle at the motor, segment by segment.

    Parameters
    ----------
    segment : numpy.ndarray of int
        Each sample's segment number (contiguous, from 0).
    names : sequence of str
        Each segment's phase.
    dt : numpy.ndarray [s]
        The duration of each sample.
    speed_1 : numpy.ndarray [rad/s]
        The motor speed of each sample.
    T_1 : numpy.ndarray [N·m]
        The motor torque of each sample.

    Returns
    -------
    list of Phase
        One per segment.
    """
    segment, dt, v, T = (np.asarray(x, float) for x in (segment, dt, speed_1, T_1))
    bounds = [*np.searchsorted(segment, np.arange(len(names))), len(segment)]
    out = []
    for name, a, b in zip(names, bounds[:-1], bounds[1:]):  # a few segments: one pass each
        t, torque = dt[a:b], T[a:b]
        duration = float(t.sum())
        out.append(Phase(str(name), duration, float(np.sum(v[a:b] * t) / duration),
                         float(T_1rms.si(T_1k=torque, t_k=t)),
                         float(np.abs(torque).max())))
    return out


def _equal_samples(samples: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The columns of ``samples`` that are equal, as ``np.unique(samples, axis=1, return_index=True,
    return_inverse=True)`` finds them (by value: -0.0 equals 0.0, NaN equals nothing), at a fifth
    of its time (it sorts the columns as records; a stable ``lexsort`` of the rows does the same job).

    Parameters
    ----------
    samples : numpy.ndarray
        One row per quantity, one column per sample (floats, any unit).

    Returns
    -------
    first : numpy.ndarray
        The index of each group's first column.
    inverse : numpy.ndarray
        The group of each column (the position of its first in ``first``).
    """
    order = np.lexsort(samples[::-1])  # stable: the first of each group leads it
    ordered = samples[:, order]
    new = np.ones(samples.shape[1], dtype=bool)
    new[1:] = (ordered[:, 1:] != ordered[:, :-1]).any(axis=0)
    inverse = np.empty(samples.shape[1], dtype=np.intp)
    inverse[order] = np.cumsum(new) - 1
    return order[new], inverse


@dataclass(frozen=True)
class OutputLoad:
    """The load cycle at the gearbox output as the motor's side reads it: an entry per sample (or
    typed segment).

    Parameters
    ----------
    dt : pint.Quantity [s]
        The duration of each entry.
    torque : pint.Quantity [N·m]
        The output torque of each entry.
    speed : pint.Quantity [rad/s]
        The output speed of each entry.
    alpha_2 : pint.Quantity [rad/s²] or None
        The acceleration of each entry where known (None for typed segments: the rotor term is then
        left out).
    n_2max : pint.Quantity [rpm]
        The highest speed.
    """

    dt: object
    torque: object
    speed: object
    alpha_2: object
    n_2max: object

    @property
    def sampled(self) -> bool:
        return self.alpha_2 is not None

    def distinct(self) -> "OutputLoad":
        """The same cycle with its equal samples merged, their durations summed, in the order each
        first appears: every peak, duration-weighted mean and RMS over it is the one over the cycle,
        at a fraction of the cost where the cycle dwells or runs at constant speed. Merged once (the
        pair search and the motor's check both ask).

        Returns
        -------
        OutputLoad
            The merged cycle.
        """
        return self._distinct

    @functools.cached_property
    def _distinct(self) -> "OutputLoad":
        columns = [self.torque.m_as("N*m"), self.speed.m_as("rad/s")]
        columns += [] if self.alpha_2 is None else [self.alpha_2.m_as("rad/s**2")]
        first, inverse = _equal_samples(np.stack(columns))
        order = np.argsort(first, kind="stable")
        dt = np.bincount(inverse, weights=self.dt.m_as("s"), minlength=len(first))[order]
        keep = first[order]
        alpha = None if self.alpha_2 is None else self.alpha_2[keep]
        return OutputLoad(Q_(dt, "s"), self.torque[keep], self.speed[keep], alpha, self.n_2max)

    @classmethod
    def from_cycle(cls, cycle: SampledCycle) -> "OutputLoad":
        """The load of a sampled cycle.

        Parameters
        ----------
        cycle : SampledCycle
            The cycle at the gearbox output.

        Returns
        -------
        OutputLoad
            Its samples, with their accelerations.
        """
        speed = Q_(cycle.speed, "rad/s")
        return cls(Q_(cycle.dt, "s"), Q_(cycle.torque, "N*m"), speed, Q_(cycle.acceleration, "rad/s**2"),
                   abs(speed).max())


@dataclass(frozen=True)
class MotorLoad:
    """The motor torque over a cycle and what the checks need of it.

    Parameters
    ----------
    T_1 : pint.Quantity [N·m]
        The samples on its last axis (rows of gearboxes before it, where given).
    peak : pint.Quantity [N·m]
        The highest ``|T_1|``, without the samples' axis.
    rms : pint.Quantity [N·m]
        ``T_1rms``, without the samples' axis.
    rotor_term : bool
        Whether the rotor and gearbox inertia were counted (a sampled cycle) or left out (typed
        segments).
    """

    T_1: object  # quantity array [N·m]
    peak: object  # highest |T_1|
    rms: object
    rotor_term: bool


def driven_back(torque, speed) -> np.ndarray:
    """Where power flows from the load to the motor: ``T_2 · ω_2 < 0`` (a hold at rest drives).

    Parameters
    ----------
    torque : pint.Quantity [N·m]
        ``T_2`` per sample.
    speed : pint.Quantity [rad/s]
        ``ω_2`` per sample, signed alike.

    Returns
    -------
    numpy.ndarray of bool
        True where driven back.
    """
    return as_kind(torque, "torque", "torque").m_as("N*m") * as_kind(speed, "speed", "speed").m_as("rad/s") < 0


def motor_torque(torque, speed, i, eta, alpha_2=None, J_motor=None, J_1=None):
    """``T_1`` of each sample: :data:`T_1_drive` or, where driven back, :data:`T_1_back`.

    Parameters
    ----------
    torque, speed : pint.Quantity [N·m], [rpm]
        ``T_2`` and ``ω_2`` at the gearbox output, per sample, signed alike (forwards positive).
    i, eta : pint.Quantity [1]
        Ratio and efficiency; arrays of shape ``(rows, 1)`` give one row of torques per gearbox.
    alpha_2 : pint.Quantity [rad/s²], optional
        ``α_2`` per sample; None leaves the rotor term out (typed segments), and then the
        inertias are not needed.
    J_motor, J_1 : pint.Quantity [kg·cm²]
        Needed with ``alpha_2``.

    Returns
    -------
    pint.Quantity [N·m]
        ``T_1`` per sample, broadcast over the rows.

    Examples
    --------
    60 N·m accelerating at 150 rpm through i = 10, η = 0.97: 60 / (10 · 0.97) = 6.186 N·m; braking
    with -45 N·m: -45 · 0.97 / 10 = -4.365 N·m:

    >>> T_1 = motor_torque(Q_([60.0, -45.0], "N*m"), Q_([150.0, 150.0], "rpm"), Q_(10, ""), Q_(0.97, ""))
    >>> T_1.m_as("N*m").round(4).tolist()
    [6.1856, -4.365]
    """
    if alpha_2 is None:
        a_1, J_motor, J_1 = Q_(0.0, "rad/s**2"), Q_(0.0, "kg*m**2"), Q_(0.0, "kg*m**2")
    else:
        a_1 = alpha_1(alpha_2=alpha_2, i=i)
    args = dict(J_motor=J_motor, J_1=J_1, alpha_1=a_1, T_2=torque, i=i, eta=eta)
    drive, back = T_1_drive(**args), T_1_back(**args)
    return Q_(np.where(driven_back(torque, speed), back.m_as("N*m"), drive.m_as("N*m")), "N*m")


def motor_load(dt, torque, speed, i, eta, alpha_2=None, J_motor=None, J_1=None) -> MotorLoad:
    """The motor torque of each sample (:func:`motor_torque`), its peak magnitude and its RMS over
    the whole cycle (:data:`T_1rms`, each sample weighed by its duration ``dt``).

    The example's cycle at i = 10, η = 0.97 (the rotor term left out): T_1 = 6.186, 2.062,
    -4.365, 0 N·m for 0.2, 0.6, 0.2, 1.0 s; RMS = √((6.186² · 0.2 + 2.062² · 0.6 + 4.365² · 0.2) / 2)
    = √(14.014 / 2) = 2.647 N·m.

    Parameters
    ----------
    dt : pint.Quantity [s]
        The duration of each sample.
    torque : pint.Quantity [N·m]
        ``T_2`` per sample.
    speed : pint.Quantity [rad/s]
        ``ω_2`` per sample, signed alike.
    i, eta : pint.Quantity [1]
        Ratio and efficiency, as :func:`motor_torque` takes them.
    alpha_2 : pint.Quantity [rad/s²], optional
        ``α_2`` per sample; None leaves the rotor term out.
    J_motor, J_1 : pint.Quantity [kg·cm²], optional
        Needed with ``alpha_2``.

    Returns
    -------
    MotorLoad
        The torques, their peak and RMS.

    Examples
    --------
    >>> m = motor_load(Q_([0.2, 0.6, 0.2, 1.0], "s"), Q_([60.0, 20.0, -45.0, 0.0], "N*m"),
    ...                Q_([150.0, 300.0, 150.0, 0.0], "rpm"), Q_(10, ""), Q_(0.97, ""))
    >>> round(float(m.peak.m_as("N*m")), 4), round(float(m.rms.m_as("N*m")), 4), m.rotor_term
    (6.1856, 2.647, False)
    """
    T_1 = motor_torque(torque, speed, i, eta, alpha_2, J_motor, J_1)
    rms = T_1rms(T_1k=T_1, t_k=dt)
    return MotorLoad(T_1, abs(T_1).max(axis=-1), rms, alpha_2 is not None)


def motor_checks(speed, peak=None, rms=None, peak_torque=None, rated_torque=None, max_speed=None,
                 not_made: str | None = None) -> list:
    """The motor's checks for the ratings given (a rating left out: no check): peak ``|T_1| <=
    T_1B``, RMS ``T_1rms <= T_1N``, speed ``n_2max · i <= n_max`` (``speed``: the highest motor
    speed). ``not_made`` says what the torques need where they cannot be computed (an inertia
    missing); ``peak`` and ``rms`` are then None. Arrays run over rows of gearboxes, as ``speed``.

    Parameters
    ----------
    speed : pint.Quantity [rpm]
        The highest motor speed ``n_2max · i``.
    peak : pint.Quantity [N·m], optional
        The peak ``|T_1|``.
    rms : pint.Quantity [N·m], optional
        ``T_1rms``.
    peak_torque : pint.Quantity [N·m], optional
        The motor's ``T_1B``.
    rated_torque : pint.Quantity [N·m], optional
        The motor's ``T_1N``.
    max_speed : pint.Quantity [rpm], optional
        The motor's ``n_max``.
    not_made : str, optional
        What the torques need where they cannot be computed.

    Returns
    -------
    list of CheckArray
        One per rating given.
    """
    shape = np.shape(speed.magnitude)
    out = []
    for name, text, required, rated, unit, missing in (
        ("T_1B", "T_1peak <= T_1B", peak, peak_torque, "N*m", not_made),
        ("T_1N", "T_1rms <= T_1N", rms, rated_torque, "N*m", not_made),
        ("n_max", "n_2max · i <= n_max", speed, max_speed, "rpm", None),
    ):
        if rated is not None:
            out.append(CheckArray(name, None, text, None if missing else required, rated * np.ones(shape), unit,
                                  not_made=missing))
    return out
