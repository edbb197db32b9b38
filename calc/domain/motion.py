"""Motion laws of the load: moves by distance and time, trapezoids, triangles, S-curves and dwells.

A cycle is a list of :class:`Move` s, repeated. A move covers its distance in its time: it
accelerates for ``accel_time``, runs at its peak speed, and decelerates for ``decel_time``
(a trapezoid; a triangle where the two fill the move). With a ``jerk_time``, each acceleration
phase starts and ends with a ramp of constant jerk that long (an S-curve). A dwell stands still.

The law is written once, at the gearbox output (angles): the mechanism (:mod:`calc.domain.mechanism`)
turns a load's distance into the output's angle first, and its travel is proportional to that
angle, so the load's law is the same law scaled.

Formulas (a reading, ``docs/case-format.md``, "Motion and mechanism")::

    ω_2max = φ_2 / (t_m - (t_a + t_d) / 2)          peak speed of a trapezoid
    α_2max = ω_2max / (t_r - t_j)                    peak acceleration of a ramp of t_r (t_a or t_d)

Sampling (:func:`sample`): each piece of the law (a jerk ramp, a constant acceleration, a constant
speed, a dwell) gets its own share of the samples, at the midpoints of equal steps. The midpoint
rule integrates a polynomial of degree one exactly, so over a trapezoid (speed linear, torque
constant in each phase) every segment mean of :func:`segments` is exact to rounding; over an
S-curve (the integrand ``|n|·|T|³`` a polynomial of degree five in a jerk ramp) the relative error
falls with the square of the samples per piece, below 10⁻⁶ at the default :data:`SAMPLES`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .cycle import ACCEL, CONST, DECEL, PAUSE, PHASES  # noqa: F401 (PHASES: the doctests)
from ..core.citation import Source
from ..core.formula import Formula
from .documents import motion_reading

#: Samples of one cycle by default; each piece of the law gets at least :data:`MIN_PER_PIECE`.
SAMPLES = 20_000
MIN_PER_PIECE = 200


omega_2max = Formula(
    "omega_2max",
    ("phi_2", "t_m", "t_a", "t_d"),
    lambda sp, phi, t, ta, td: phi / (t - (ta + td) / 2),
    Source(motion_reading("the distance is the area of the trapezoid of speed; an S-curve's symmetric ramps keep it")),
)

alpha_2max = Formula(
    "alpha_2max",
    ("omega_2max", "t_r", "t_j"),
    lambda sp, w, tr, tj: w / (tr - tj),
    Source(motion_reading("a ramp of t_r with jerk ramps of t_j at both ends gains ω at α·(t_r − t_j)")),
)


@dataclass(frozen=True)
class Move:
    """One move of the cycle at the gearbox output, in SI floats; a dwell has ``distance`` 0 and only
    its ``time``. The case layer checks the times before it builds one.

    Parameters
    ----------
    distance : float [rad]
        Signed.
    time : float [s]
        The move's duration.
    accel_time : float [s]
        Its acceleration ramp; default 0.
    decel_time : float [s]
        Its deceleration ramp; default 0.
    jerk_time : float [s]
        Each corner's time of constant jerk; default 0.
    """

    distance: float
    time: float
    accel_time: float = 0.0
    decel_time: float = 0.0
    jerk_time: float = 0.0

    @property
    def dwell(self) -> bool:
        return self.distance == 0

    @property
    def const_time(self) -> float:
        return self.time - self.accel_time - self.decel_time

    @property
    def peak_speed(self) -> float:
        """ω_2max [rad/s], signed (:data:`omega_2max`)."""
        if self.dwell:
            return 0.0
        return float(omega_2max.si(phi_2=self.distance, t_m=self.time, t_a=self.accel_time, t_d=self.decel_time))

    def peak_accelerations(self) -> tuple[float, float]:
        """α_2max of the acceleration and of the deceleration ramp, signed: the deceleration's is against
        the speed (:data:`alpha_2max`).

        Returns
        -------
        tuple of float [rad/s²]
            The two peaks.
        """
        if self.dwell:
            return 0.0, 0.0
        w = self.peak_speed
        return (
            float(alpha_2max.si(omega_2max=w, t_r=self.accel_time, t_j=self.jerk_time)),
            -float(alpha_2max.si(omega_2max=w, t_r=self.decel_time, t_j=self.jerk_time)),
        )

    def pieces(self):
        """Each piece of constant jerk, in order; zero-length pieces left out.

        Returns
        -------
        list of tuple
            ``(duration [s], acceleration at its start [rad/s²], jerk [rad/s³], phase)``.
        """
        if self.dwell:
            return [(self.time, 0.0, 0.0, PAUSE)]
        a_up, a_down = self.peak_accelerations()
        tj = self.jerk_time
        out = []
        for ramp, a, phase in ((self.accel_time, a_up, ACCEL), (None, 0.0, CONST), (self.decel_time, a_down, DECEL)):
            if ramp is None:
                out.append((self.const_time, 0.0, 0.0, CONST))
            elif tj > 0:
                out += [(tj, 0.0, a / tj, phase), (ramp - 2 * tj, a, 0.0, phase), (tj, a, -a / tj, phase)]
            else:
                out.append((ramp, a, 0.0, phase))
        return [p for p in out if p[0] > 0]


@dataclass(frozen=True)
class Samples:
    """One cycle sampled at the midpoints of equal steps of each piece (SI floats).

    Parameters
    ----------
    t : numpy.ndarray [s]
        The time of each sample.
    dt : numpy.ndarray [s]
        The time each sample stands for.
    position : numpy.ndarray [rad]
        Output position.
    speed : numpy.ndarray [rad/s]
        Output speed.
    acceleration : numpy.ndarray [rad/s²]
        Output acceleration.
    jerk : numpy.ndarray [rad/s³]
        Output jerk.
    phase : numpy.ndarray
        The phase code of each sample (:data:`PHASES`).
    segment : numpy.ndarray of int
        The index of the phase of a move each sample belongs to, in time order.
    durations : numpy.ndarray [s]
        Of each segment: the sum of its pieces' durations, not of the ``dt``.
    """

    t: np.ndarray
    dt: np.ndarray
    position: np.ndarray
    speed: np.ndarray
    acceleration: np.ndarray
    jerk: np.ndarray
    phase: np.ndarray
    segment: np.ndarray
    durations: np.ndarray  # of each segment [s]: the sum of its pieces' durations, not of the dt

    @property
    def segment_phases(self) -> np.ndarray:
        """The phase code of each segment."""
        first = np.flatnonzero(np.r_[True, np.diff(self.segment) != 0])
        return self.phase[first]


def sample(moves: list[Move], samples: int = SAMPLES) -> Samples:
    """Sample one cycle of ``moves``: each piece of constant jerk gets a share of ``samples`` in
    proportion to its duration, at least :data:`MIN_PER_PIECE`.

    Speed and position at a piece's start are carried from the end of the one before (the
    acceleration steps at a trapezoid's corners); inside a piece, ``x(τ) = x_0 + v_0 τ + a_0 τ²/2 + j τ³/6``.

    Parameters
    ----------
    moves : list of Move
        The cycle's moves and dwells, in order.
    samples : int
        About how many samples in all; default :data:`SAMPLES`.

    Returns
    -------
    Samples
        The sampled cycle.

    Examples
    --------
    >>> s = sample([Move(np.pi / 2, 1.0, 0.25, 0.25), Move(0.0, 1.0)], samples=1000)
    >>> round(float(s.position.max()), 6), round(float((s.speed * s.dt).sum()), 12) == round(np.pi / 2, 12)
    (1.570796, True)
    >>> PHASES[s.segment_phases[0]], len(s.segment_phases)
    ('accel', 4)
    """
    rows = []  # duration, jerk, phase, segment, start acceleration, speed, position, per piece
    segment, x = -1, 0.0
    for move in moves:
        last_phase, v = None, 0.0  # a move starts at rest exactly (no rounding carried over)
        for h, a, j, phase in move.pieces():
            if phase != last_phase:
                segment += 1
                last_phase = phase
            rows.append((h, j, phase, segment, a, v, x))
            v, x = v + a * h + j * h**2 / 2, x + v * h + a * h**2 / 2 + j * h**3 / 6
    duration, jerk, phase, seg, a0, v0, x0 = (np.array(c) for c in zip(*rows))
    duration, jerk = duration.astype(float), jerk.astype(float)
    total = duration.sum()
    counts = np.maximum(MIN_PER_PIECE, np.ceil(samples * duration / total)).astype(np.int64)
    step = duration / counts
    start = np.cumsum(counts) - counts
    each = lambda values: np.repeat(values, counts)  # noqa: E731 (a piece's value on each of its samples)
    dt = each(step)
    tau = (np.arange(counts.sum()) - each(start) + 0.5) * dt
    j, a, v, x = each(jerk), each(a0), each(v0), each(x0)
    # Horner's form: products, no powers (a power of an array costs several times a product).
    return Samples(
        t=each(np.cumsum(duration) - duration) + tau,
        dt=dt,
        position=x + tau * (v + tau * (a / 2 + tau * (j / 6))),
        speed=v + tau * (a + tau * (j / 2)),
        acceleration=a + j * tau,
        jerk=j,
        phase=each(phase),
        segment=each(seg),
        durations=np.bincount(seg, weights=duration),
    )


#: A recorded interval stands still where its speed is at most :data:`REST_SHARE` of the record's
#: highest speed, and is a ramp (accel or decel) where its acceleration is above :data:`RAMP_SHARE`
#: of the record's highest. A drive's speed signal carries noise, which must not cut a constant run
#: into pieces: a run of one phase shorter than :data:`MIN_RUN_SHARE` of the cycle joins the run
#: before it (the first, the one after).
REST_SHARE = 0.01
RAMP_SHARE = 0.1
MIN_RUN_SHARE = 0.02


def record_samples(time: np.ndarray, speed: np.ndarray) -> Samples:
    """A cycle recorded by a drive (times [s], increasing; speeds [rad/s] at the gearbox output)
    as samples: one per interval between two rows, with the mean of its two speeds and the slope
    between them; each interval a pause, ramp or constant run by :data:`REST_SHARE` and
    :data:`RAMP_SHARE`, an acceleration where the speed's magnitude grows; a segment per run of
    one phase (:data:`MIN_RUN_SHARE`).

    Parameters
    ----------
    time : numpy.ndarray [s]
        The recorded times, increasing.
    speed : numpy.ndarray [rad/s]
        The speeds at the gearbox output.

    Returns
    -------
    Samples
        One sample per interval.

    Examples
    --------
    >>> s = record_samples(np.array([0.0, 1.0, 2.0, 3.0, 4.0]), np.array([0.0, 2.0, 2.0, 0.0, 0.0]))
    >>> [PHASES[p] for p in s.phase], s.segment.tolist(), s.speed.tolist(), s.acceleration.tolist()
    (['accel', 'const', 'decel', 'pause'], [0, 1, 2, 3], [1.0, 2.0, 1.0, 0.0], [2.0, 0.0, -2.0, 0.0])
    """
    dt = np.diff(time)
    v = (speed[1:] + speed[:-1]) / 2
    acceleration = np.diff(speed) / dt
    rest = np.abs(v) <= REST_SHARE * np.abs(speed).max()
    ramp = np.abs(acceleration) > RAMP_SHARE * np.abs(acceleration).max()
    phase = np.where(rest, PAUSE, np.where(ramp, np.where(acceleration * v > 0, ACCEL, DECEL), CONST))
    phase = _join_short_runs(phase, dt, MIN_RUN_SHARE * (time[-1] - time[0]))
    mid = (time[1:] + time[:-1]) / 2
    segment = np.r_[0, np.cumsum(phase[1:] != phase[:-1])]
    return Samples(
        t=mid,
        dt=dt,
        position=np.cumsum(speed[:-1] * dt + acceleration * dt**2 / 2),
        speed=v,
        acceleration=acceleration,
        jerk=np.gradient(acceleration, mid) if len(mid) > 1 else np.zeros(1),
        phase=phase,
        segment=segment,
        durations=np.bincount(segment, weights=dt),
    )


def _join_short_runs(phase: np.ndarray, dt: np.ndarray, shortest: float) -> np.ndarray:
    """``phase`` with each run shorter than ``shortest`` [s] given the phase of the run before
    it (the first run, of the run after); runs are few, so a loop over them."""
    starts = np.flatnonzero(np.r_[True, phase[1:] != phase[:-1]])
    ends = np.r_[starts[1:], len(phase)]
    lengths = np.add.reduceat(dt, starts)
    out = phase.copy()
    for k, (a, b, length) in enumerate(zip(starts, ends, lengths)):
        if length < shortest and len(starts) > 1:
            out[a:b] = out[a - 1] if k > 0 else phase[ends[0]]
    return out
