"""The motor and the load in the calc report: their rows of the inputs table."""

from __future__ import annotations

from .common import input_row, nothing

NAME = "drive"


def input_rows(report) -> list[list[str]]:
    c = report.case
    given = [("motor.peak_torque", c.motor_peak_torque), ("motor.inertia", c.motor_inertia)]
    if c.motion is None:  # else the mechanism gives J_L (the motion's inputs and steps)
        given.append(("load.inertia", c.load_inertia))
    return [input_row(key, q) for key, q in given if q is not None]


inputs = steps = results = checks = candidates = figures = chosen = order_lines = sources = readings = nothing
