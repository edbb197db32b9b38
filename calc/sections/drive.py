"""The motor and the load of a case (``[motor]``, ``[load]``): inputs that the gearbox, coupling
and accuracy sections share. They have no results of their own."""

from __future__ import annotations

from ..case import Case, Table
from ..errors import CalcError

MOTOR_KEYS = ("peak_torque", "inertia", "rated_torque", "max_speed")
LOAD_KEYS = ("inertia",)


def read(top: Table, case: Case) -> None:
    """Read ``[motor]`` and ``[load]`` into the case; each value above zero, and the motor's rated
    (continuous) torque no higher than its peak torque."""
    motor = top.table("motor", MOTOR_KEYS)
    if motor:
        case.motor_peak_torque = motor.positive("peak_torque", "torque")
        case.motor_inertia = motor.positive("inertia", "inertia")
        case.motor_rated_torque = motor.positive("rated_torque", "torque")
        case.motor_max_speed = motor.positive("max_speed", "speed")
        peak, rated = case.motor_peak_torque, case.motor_rated_torque
        if peak is not None and rated is not None and rated.m_as("N*m") > peak.m_as("N*m"):
            raise CalcError(
                f"{motor.where('rated_torque')}: expected a continuous torque at most the peak torque "
                f"motor.peak_torque = {motor.data['peak_torque']!r} (a motor's peak is above its continuous rating), "
                f"found {motor.data['rated_torque']!r}"
            )
    load = top.table("load", LOAD_KEYS)
    if load:
        case.load_inertia = load.positive("inertia", "inertia")
