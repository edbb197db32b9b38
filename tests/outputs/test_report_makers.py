"""The calc report shows the makers' checks: the case's factor tables, the peak torque of an
elastomer coupling against T_Kmax, a member's stiffness curve and the accuracy as arcs at a radius."""

from calc.report import build_report
from calc.report.common import case_key

from ..conftest import HEAD_TOML, PROFILE_TOML

CASE = """
[coupling]
type = "elastomer"
accel_torque = "2 N*m"
drive_inertia = "1.5 kg*cm**2"
load_inertia = "30 kg*cm**2"
temperature = "60 degC"
temperature_factors = "roba-es"
start_factors = "roba-es"
starts_per_hour = "150 1/hour"
excitation_frequency = "40 Hz"
shaft_1 = "14 mm k6"
shaft_2 = "12 mm h7"

[accuracy]
applied_torque = "60 N*m"
nominal_torque = "178 N*m"
radius = "200 mm"
required_positioning_accuracy = "0.5 mm"
[[accuracy.component]]
name = "HFUC-32-100"
backlash = "0 arcmin"
side = "output"
stiffness_curve = {T1 = "29 N*m", T2 = "108 N*m", K1 = "6.7e4 N*m/rad", K2 = "1.1e5 N*m/rad", K3 = "1.2e5 N*m/rad"}
"""


def test_report_blocks_show_the_makers_checks(write_case, tmp_path):
    (tmp_path / "shock.csv").write_text(
        "from [1/h],to [1/h],factor [1],at_boundary,source\n0,,1.5,higher,a test table\n"
    )
    head = HEAD_TOML.replace("ratio = 10", 'ratio = 10\nshock_factors = "shock.csv"')
    report = build_report(write_case(head + PROFILE_TOML + CASE))
    assert report.error is None, report.error
    steps = str(report.calculations())
    assert r"f_{\mathrm{s}} = 1.5" in steps and "a test table" in steps
    assert "Peak torque with the start and temperature factors" in steps and "Mayr" in steps
    assert "30 < $T$ ≤ 60 °C" in steps  # the ROBA-ES band of 60 °C
    assert "Positioning accuracy as an arc at the radius" in steps and "given as an arc" in steps
    assert "stiffness curve" in steps  # the band formula of the curve and its secant
    results = str(report.section_results())
    assert r"$S_{\mathrm{z}}$" in results and "as an arc at $r$ = 200 mm" in results
    inputs = str(report.inputs())
    assert case_key("accuracy.radius") in inputs and case_key("coupling.start_factors") in inputs
