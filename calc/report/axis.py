"""The motor and the load in the outputs: their rows of the calc report's inputs table."""

from __future__ import annotations

from ..sections.axis import SECTION
from .common import Renderer, input_row


class AxisRenderer(Renderer):
    """The motor's peak torque and inertia, and the load's inertia where no mechanism gives it."""

    NAME = SECTION.NAME

    def input_rows(self, report) -> list[list[str]]:
        c = report.case
        given = [("motor.peak_torque", c.motor_peak_torque), ("motor.inertia", c.motor_inertia)]
        if c.motion is None:  # else the mechanism gives J_L (the motion's inputs and steps)
            given.append(("load.inertia", c.load_inertia))
        return [input_row(key, q) for key, q in given if q is not None]


RENDERER = AxisRenderer()
