"""Load profile, duty cycle and operating mode (source: "Determination of the Duty Cycle").

A profile is any number of segments in time order, each an ``accel``, ``const``, ``decel`` or
``pause`` phase with its duration, mean output speed ``n_2`` and output torque ``T_2``. The moving
segments are every segment but the pauses.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.errors import CalcError, listing, as_found
from ..core.checks import BOUNDARY_RTOL
from .cycle import PAUSE, PHASES
from ..core.citation import Source
from ..core.formula import Formula, segment_sum
from ..core.units import Q_, as_kind
from .documents import ERRATA, SOURCE

#: E3: S5 needs ED below this and an on-time below :data:`S5_MAX_ON_TIME`.
S5_MAX_ED = Q_(60, "percent")
S5_MAX_ON_TIME = Q_(20, "min")

ED = Formula(
    "ED",
    ("t_on", "t_cycle"),
    lambda sp, t_on, t_cycle: t_on / t_cycle,
    Source(SOURCE.at("Determination of the Duty Cycle"), ERRATA.at("E3")),
)

n_2m = Formula(
    "n_2m",
    ("n_2k", "t_k"),
    lambda sp, n, t: segment_sum(sp.Mul(abs(n), t, evaluate=False)) / segment_sum(t),  # the source's order
    Source(SOURCE.at("S1 calculation 1"), ERRATA.at("E2", note="any number of segments, moving time only")),
)

T_2m = Formula(
    "T_2m",
    ("n_2k", "t_k", "T_2k"),
    lambda sp, n, t, T: sp.cbrt(
        segment_sum(sp.Mul(abs(n), t, abs(T) ** 3, evaluate=False)) / segment_sum(sp.Mul(abs(n), t, evaluate=False))
    ),
    Source(SOURCE.at("S1 calculation 2"),
           ERRATA.at("E2", note="speed-weighted cubic mean of magnitudes; the exponent 3 is the rolling-bearing life "
                                "exponent of ISO 281 and the gearbox makers' convention for T_2m, not a gear fatigue "
                                "exponent: gear S-N curves are much steeper, ISO 6336")),
)

Z_h = Formula(
    "Z_h",
    ("z_c", "t_cycle"),
    lambda sp, z_c, t_cycle: z_c / t_cycle,
    Source(SOURCE.at("S5 calculation 1", note="Z_h = 3600 / t_cycle with t_cycle in s, for one load cycle per cycle"),
           ERRATA.at("E16", note="load cycles (moves) per hour: z_c load cycles in the cycle of t_cycle")),
)


@dataclass(frozen=True)
class Profile:
    """The output-side load cycle: one entry per segment, arrays in time order.

    Build one with :meth:`from_segments`.

    Parameters
    ----------
    phases : tuple of str
        The phase of each segment (:data:`PHASES`).
    durations : pint.Quantity [s]
        The duration of each segment.
    speeds : pint.Quantity [rpm]
        The mean output speed of each segment; zero in pauses.
    torques : pint.Quantity [N·m]
        The output torque of each segment; zero in pauses.
    """

    phases: tuple[str, ...]
    durations: object  # Quantity array [s]
    speeds: object  # Quantity array [rpm]
    torques: object  # Quantity array [N*m]

    @classmethod
    def from_segments(cls, segments, where: str = "profile") -> "Profile":
        """Build a profile from ``(phase, duration, speed, torque)`` tuples of quantities.

        A pause takes ``None`` for speed and torque.

        Parameters
        ----------
        segments : sequence of tuple
            ``(phase, duration [s], speed [rpm], torque [N·m])`` of each segment.
        where : str
            The key, for error messages; default ``"profile"``.

        Returns
        -------
        Profile
            The load cycle.

        Raises
        ------
        CalcError
            Naming the segment, for an unknown phase, a duration that is not positive, a pause with a
            speed or a torque, or a moving segment without them.
        """
        segments = list(segments)
        if not segments:
            raise CalcError(f"{where}: expected at least one segment, found none")
        phases, durations, speeds, torques = [], [], [], []
        for k, seg in enumerate(segments, start=1):
            phase, duration, speed, torque = seg
            at = f"{where}[{k}]"
            if phase not in PHASES:
                raise CalcError(f"{at}.phase: expected one of {listing(PHASES)}, found {as_found(phase)}")
            d = as_kind(duration, "time", f"{at}.duration").m_as("s")
            if not d > 0:
                raise CalcError(f"{at}.duration: expected a duration above zero, found {duration:~P}")
            if phase == "pause":
                if speed is not None or torque is not None:
                    raise CalcError(f"{at}: a pause takes only a duration, found a "
                                    f"{'speed' if speed is not None else 'torque'}")
                n, T = 0.0, 0.0
            else:
                if speed is None or torque is None:
                    raise CalcError(f"{at}: a {phase} segment needs a {'speed' if speed is None else 'torque'}, found "
                                    "none")
                n = as_kind(speed, "speed", f"{at}.speed").m_as("rpm")
                T = as_kind(torque, "torque", f"{at}.torque").m_as("N*m")
            phases.append(phase)
            durations.append(d)
            speeds.append(n)
            torques.append(T)
        if not any(p != "pause" for p in phases):
            raise CalcError(f"{where}: expected at least one moving segment (accel, const or decel), found only pauses")
        if not any(n != 0 for n in speeds):
            # n_2m would be 0 and T_2m = 0 / 0: the S1 means weight each torque by its speed.
            raise CalcError(f"{where}: expected a moving segment with a speed other than zero (n_2m weights each "
                            "torque by its speed), found every speed zero")
        return cls(
            tuple(phases),
            Q_(np.array(durations, float), "s"),
            Q_(np.array(speeds, float), "rpm"),
            Q_(np.array(torques, float), "N*m"),
        )

    @property
    def moving(self) -> np.ndarray:
        """Boolean mask of the moving segments (every phase but pause)."""
        return np.array([p != "pause" for p in self.phases])

    @property
    def t_on(self):
        """On-time ``t_a + t_c + t_d``: the total of the moving segments."""
        return self.durations[self.moving].sum()

    @property
    def t_cycle(self):
        """Cycle time: every segment, pauses included (E3); summed as on-time plus pauses, so that
        the duty cycle never rounds above 1."""
        return self.t_on + self.durations[~self.moving].sum()

    @property
    def load_cycles(self):
        """The load cycles (moves) in the cycle ``z_c`` (E16): as the gearbox makers count one,
        acceleration, constant speed, deceleration and pause, each deceleration followed by a pause
        or by the next acceleration (the cycle wraps round) ends one; a cycle with no such end (a
        continuous run) is one load cycle.

        Returns
        -------
        pint.Quantity [dimensionless]
            The count, at least 1.

        Examples
        --------
        >>> move = [("accel", Q_(0.1, "s"), Q_(50, "rpm"), Q_(10, "N*m")),
        ...         ("decel", Q_(0.1, "s"), Q_(50, "rpm"), Q_(-10, "N*m")), ("pause", Q_(1, "s"), None, None)]
        >>> int(Profile.from_segments(move).load_cycles.m), int(Profile.from_segments(move * 2).load_cycles.m)
        (1, 2)
        """
        following = self.phases[1:] + self.phases[:1]
        ends = sum(p == "decel" and q in ("pause", "accel") for p, q in zip(self.phases, following))
        return Q_(float(max(ends, 1)), "")

    def cycles_per_hour_inputs(self) -> dict:
        """The inputs of :data:`Z_h` from this profile: ``z_c`` (:attr:`load_cycles`) and ``t_cycle``.

        Returns
        -------
        dict
            ``z_c`` [dimensionless] and ``t_cycle`` [s].
        """
        return {"z_c": self.load_cycles, "t_cycle": self.t_cycle}

    @property
    def n_2max(self):
        """Highest output speed of the cycle, in magnitude (E5)."""
        return abs(self.speeds).max()

    def moving_values(self) -> dict:
        """The per-segment inputs of the S1 formulas, moving segments only.

        Returns
        -------
        dict
            ``n_2k`` [rpm], ``T_2k`` [N·m] and ``t_k`` [s] as quantity arrays.
        """
        m = self.moving
        return {"n_2k": self.speeds[m], "t_k": self.durations[m], "T_2k": self.torques[m]}

    def to_frame(self):
        """The segments as a pandas DataFrame, units in the column names (for display).

        Returns
        -------
        pandas.DataFrame
            One row per segment.

        Examples
        --------
        >>> p = Profile.from_segments([("const", Q_(1, "s"), Q_(100, "rpm"), Q_(10, "N*m")),
        ...                            ("pause", Q_(1, "s"), None, None)])
        >>> f = p.to_frame()
        >>> list(f.columns)
        ['segment', 'phase', 'duration t [s]', 'mean output speed n_2 [rpm]', 'output torque T_2 [N·m]']
        >>> f["duration t [s]"].tolist(), f["mean output speed n_2 [rpm]"].tolist()
        ([1.0, 1.0], [100.0, 0.0])
        """
        import pandas as pd

        return pd.DataFrame(
            {
                "segment": np.arange(1, len(self.phases) + 1),
                "phase": self.phases,
                "duration t [s]": np.asarray(self.durations.m_as("s"), dtype=float),
                "mean output speed n_2 [rpm]": np.asarray(self.speeds.m_as("rpm"), dtype=float),
                "output torque T_2 [N·m]": np.asarray(self.torques.m_as("N*m"), dtype=float),
            }
        )


def operating_mode(duty_cycle, on_time) -> str:
    """``"S5"`` if and only if ``ED < 60 %`` and ``t_on < 20 min``; every other case ``"S1"`` (E3).

    A value within :data:`BOUNDARY_RTOL` below a boundary counts as on it (rounding of sums).

    Parameters
    ----------
    duty_cycle : pint.Quantity [%]
        ``ED``.
    on_time : pint.Quantity [min]
        ``t_on``.

    Returns
    -------
    str
        ``"S1"`` or ``"S5"``.

    Examples
    --------
    >>> operating_mode(Q_(50, "percent"), Q_(1, "s")), operating_mode(Q_(60, "percent"), Q_(1, "s"))
    ('S5', 'S1')
    >>> operating_mode(Q_((0.6 + 0.7 + 0.2) / 2.5, ""), Q_(1.5, "s"))  # 1.5 s of 2.5 s is 60 %
    'S1'
    """
    ed = as_kind(duty_cycle, "dimensionless", "duty_cycle").m_as("")
    t = as_kind(on_time, "time", "on_time").m_as("s")
    below = 1 - BOUNDARY_RTOL
    return "S5" if (ed < S5_MAX_ED.m_as("") * below and t < S5_MAX_ON_TIME.m_as("s") * below) else "S1"


@dataclass(frozen=True)
class Duty:
    """Duty cycle of a profile: on-time, cycle time, ED and the operating mode (E3).

    Parameters
    ----------
    t_on : pint.Quantity [s]
        The time moving.
    t_cycle : pint.Quantity [s]
        The cycle time.
    ED : pint.Quantity [%]
        The duty cycle.
    mode : str
        ``"S1"`` or ``"S5"``.
    """

    t_on: object
    t_cycle: object
    ED: object
    mode: str


def duty(profile: Profile) -> Duty:
    """Duty cycle and operating mode of a profile.

    Parameters
    ----------
    profile : Profile
        The load cycle.

    Returns
    -------
    Duty
        Its on-time, cycle time, ED and mode.

    Examples
    --------
    >>> p = Profile.from_segments([("const", Q_(1, "s"), Q_(100, "rpm"), Q_(10, "N*m")),
    ...                            ("pause", Q_(1, "s"), None, None)])
    >>> d = duty(p); (float(d.ED.m_as("percent")), d.mode)
    (50.0, 'S5')
    """
    ed = ED(t_on=profile.t_on, t_cycle=profile.t_cycle)
    return Duty(profile.t_on, profile.t_cycle, ed, operating_mode(ed, profile.t_on))


@dataclass(frozen=True)
class Segments:
    """The seed's segments of a sampled cycle (SI floats, :func:`segments`).

    Parameters
    ----------
    phase : numpy.ndarray
        Phase code of each segment (:data:`PHASES`).
    duration : numpy.ndarray [s]
        Its duration.
    speed : numpy.ndarray [rad/s]
        Its mean speed.
    torque : numpy.ndarray [N·m]
        The torque that gives the segment's cubic mean.
    """

    phase: np.ndarray
    duration: np.ndarray
    speed: np.ndarray
    torque: np.ndarray


def segments(s, torque: np.ndarray) -> Segments:
    """The seed's segments (accel, const, decel, pause) of a sampled cycle ``s`` (a
    :class:`calc.domain.motion.Samples`: ``dt``, ``speed``, contiguous ``segment`` numbers, their
    ``durations`` and ``segment_phases``) and its torque per sample.

    For a moving segment k: ``t_k = ∫dt``, ``n_k = ∫n dt / t_k`` and the torque ``T_k`` whose
    ``|n_k|·t_k·|T_k|³`` equals ``∫|n|·|T|³ dt``: :data:`T_2m` over the segment's samples, with the
    sign of ``∫|n|·T³ dt``. So the S1 means of the segments (:data:`n_2m`, :data:`T_2m`) are the
    integrals over the sampled cycle, whether the torque is constant in a phase (a trapezoid:
    exactly its value) or varies (an S-curve). A pause's torque is its mean (the torque that holds
    the load).

    Parameters
    ----------
    s : Samples
        The sampled cycle.
    torque : numpy.ndarray [N·m]
        Its torque per sample.

    Returns
    -------
    Segments
        One entry per segment.

    Examples
    --------
    >>> from calc.domain.motion import Move, sample
    >>> s = sample([Move(1.0, 1.0, 0.5, 0.5)], samples=100)   # a triangle: peak 2 rad/s, ±4 rad/s²
    >>> g = segments(s, 2.0 * s.acceleration)                 # T = J·α with J = 2 kg·m²
    >>> ([PHASES[p] for p in g.phase], g.duration.round(12).tolist(), g.speed.round(12).tolist(),
    ...  g.torque.round(12).tolist())
    (['accel', 'decel'], [0.5, 0.5], [1.0, 1.0], [8.0, -8.0])
    """
    dt, v, T = s.dt, s.speed, np.asarray(torque, dtype=float)
    duration, phase = s.durations, s.segment_phases
    starts = np.searchsorted(s.segment, np.arange(len(duration)))
    ends = np.r_[starts[1:], len(dt)]
    speed = np.add.reduceat(v * dt, starts) / duration
    out = np.add.reduceat(T * dt, starts) / duration  # a pause: the mean torque
    for k in np.flatnonzero(phase != PAUSE):
        at = slice(starts[k], ends[k])
        magnitude = T_2m.si(n_2k=v[at], t_k=dt[at], T_2k=T[at])
        out[k] = np.sign(np.sum(np.abs(v[at]) * dt[at] * T[at] ** 3)) * magnitude
    speed[phase == PAUSE] = 0.0
    return Segments(phase, duration, speed, out)

