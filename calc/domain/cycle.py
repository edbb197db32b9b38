"""The load cycle at the gearbox output as samples in time, in SI floats.

The motion section derives it from the moves and the mechanism (``[[move]]``, ``[mechanism]``);
the motor's side reads it to add the rotor's inertia and to take the RMS torque over the whole
cycle. A hand-typed ``[[profile]]`` has no sampled cycle (its accelerations are not known).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: The phases of the seed's segments, in the order of their codes in a sampled cycle.
PHASES = ("accel", "const", "decel", "pause")
ACCEL, CONST, DECEL, PAUSE = range(4)


@dataclass(frozen=True)
class SampledCycle:
    """One cycle of the load at the gearbox output, one entry per sample (read-only arrays).

    Parameters
    ----------
    dt : numpy.ndarray [s]
        The time each sample stands for (they sum to the cycle time).
    speed : numpy.ndarray [rad/s]
        Signed, forwards positive.
    acceleration : numpy.ndarray [rad/s²]
        Signed, forwards positive.
    torque : numpy.ndarray [N·m]
        The torque the gearbox output gives the mechanism, signed like the speed, and during a
        dwell the torque that holds the load at rest (zero where nothing pulls on it or a brake
        holds it).
    """

    dt: np.ndarray
    speed: np.ndarray
    acceleration: np.ndarray
    torque: np.ndarray

    def __post_init__(self):
        for name in ("dt", "speed", "acceleration", "torque"):
            values = np.array(getattr(self, name), dtype=float)
            values.flags.writeable = False
            object.__setattr__(self, name, values)
        if not len({a.shape for a in (self.dt, self.speed, self.acceleration, self.torque)}) == 1:
            raise ValueError("SampledCycle: dt, speed, acceleration and torque must have one shape")
