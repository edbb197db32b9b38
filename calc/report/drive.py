"""The motor and the load in the calc report: their rows of the inputs table."""

from __future__ import annotations

from .common import gearbox_symbols, input_row, nothing

NAME = "drive"


def input_rows(report) -> list[list[str]]:
    c, sym = report.case, gearbox_symbols()
    given = [("T_1B", c.motor_peak_torque, "motor.peak_torque"), ("J_motor", c.motor_inertia, "motor.inertia")]
    if c.motion is None:  # else the mechanism gives J_L (the motion's inputs and steps)
        given.append(("J_L", c.load_inertia, "load.inertia"))
    return [input_row(sym[name], q, key) for name, q, key in given if q is not None]


inputs = steps = results = checks = candidates = figures = chosen = order_lines = sources = readings = nothing
