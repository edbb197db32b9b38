"""The servo drive in the design review: the brake resistor's values are inputs, and a change
re-evaluates the drive's braking checks."""

from calc.review.inputs import input_specs, with_inputs
from calc.sections import evaluate, read_case
from calc import Q_

from ..conftest import ROOT


def test_the_brake_resistors_values_are_inputs():
    case = read_case(ROOT / "cases" / "ball-screw-direct.toml")
    specs = {s.key: s for s in input_specs(case)}
    r = specs["drive.brake_resistor.continuous_power"]
    assert r.value == 30 and r.unit == "W" and specs["drive.brake_resistor.resistance"].value == 100
    # The slide gives its resistor 30.66 J per 2 s cycle, 15.33 W on average: a 10 W resistor fails.
    weak = evaluate(with_inputs(case, {"drive.brake_resistor.continuous_power": Q_(10, "W")}))
    avg = weak["drive"].braking.checks[0]
    assert avg.passes is False and avg.utilization == avg.required.m_as("W") / 10
