"""The motor and the load of a case (``[motor]``, ``[load]``): inputs that the gearbox, coupling
and accuracy sections share. They have no results of their own."""

from __future__ import annotations

from ..case import Case, Table

MOTOR_KEYS = ("peak_torque", "inertia")
LOAD_KEYS = ("inertia",)


def read(top: Table, case: Case) -> None:
    """Read ``[motor]`` and ``[load]`` into the case; each value above zero."""
    motor = top.table("motor", MOTOR_KEYS)
    if motor:
        case.motor_peak_torque = motor.positive("peak_torque", "torque")
        case.motor_inertia = motor.positive("inertia", "inertia")
    load = top.table("load", LOAD_KEYS)
    if load:
        case.load_inertia = load.positive("inertia", "inertia")
