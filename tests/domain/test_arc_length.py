"""Accuracy as a length at a radius (``[accuracy] radius``): arc = r · φ, requirements given as a
length, and the error of a length without a radius."""

import json
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import Q_
from calc.domain.accuracy import angle_of_arc, arc_length

from ..conftest import HEAD_TOML, PROFILE_TOML, run

CHAIN = """
[accuracy]
applied_torque = "20 N*m"
{extra}
[[accuracy.component]]
name = "EPL-W-064 10:1"
side = "output"
stiffness = "1.3 N*m/arcmin"
backlash = "3 arcmin"
transmission_accuracy = "60 arcsec"
nominal_torque = "40 N*m"
"""


def test_arc_by_hand():
    # 1 arcmin = π / 10800 rad; at r = 200 mm: s = 200 · π / 10800 = 0.058178 mm.
    s = arc_length(r=Q_(200, "mm"), phi=Q_(1, "arcmin"))
    assert s.m_as("mm") == pytest.approx(200 * math.pi / 10800, rel=1e-12)
    phi = angle_of_arc(s=Q_(0.05, "mm"), r=Q_(200, "mm"))
    assert phi.m_as("arcmin") == pytest.approx(0.05 / 200 * 10800 / math.pi, rel=1e-12)


@settings(max_examples=200, deadline=None)
@given(st.floats(1e-3, 1e4), st.floats(1e-3, 1e3), st.floats(0.1, 100))
def test_arc_scales_linearly_with_radius(r, phi, k):
    one = arc_length(r=Q_(r, "mm"), phi=Q_(phi, "arcmin")).m_as("mm")
    assert arc_length(r=Q_(k * r, "mm"), phi=Q_(phi, "arcmin")).m_as("mm") == pytest.approx(k * one, rel=1e-12)
    assert angle_of_arc(s=Q_(one, "mm"), r=Q_(r, "mm")).m_as("arcmin") == pytest.approx(phi, rel=1e-12)
    # Inch and metric radii agree.
    assert arc_length(r=Q_(r / 25.4, "in"), phi=Q_(phi, "arcmin")).m_as("mm") == pytest.approx(one, rel=1e-12)


def evaluate(capsys, write_case, extra, name="case.toml"):
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + CHAIN.format(extra=extra), name), "--json")
    return code, out, err


def test_results_give_angles_and_arcs(capsys, write_case):
    code, out, err = evaluate(capsys, write_case, 'radius = "200 mm"\nrequired_positioning_accuracy = "1 mm"')
    assert code == 0, err
    a = json.loads(out)["accuracy"]
    assert a["radius"] == {"value": 200.0, "unit": "mm"}
    for key in ("backlash", "lost_motion", "positioning_accuracy", "repeatability"):
        assert a[f"{key}_arc"]["value"] == pytest.approx(200 * a[key]["value"] * math.pi / 10800, rel=1e-12)
    check = a["checks"][0]
    # 1 mm at 200 mm is 1/200 rad = 17.189 arcmin; positioning accuracy 1 + 20 / 1.3 = 16.385 arcmin passes.
    assert check["required"]["value"] == pytest.approx(10800 / math.pi / 200, rel=1e-12)
    assert check["required_arc"]["value"] == pytest.approx(1.0, rel=1e-12) and check["passes"] is True
    extra = 'radius = "200 mm"\nrequired_positioning_accuracy = "1 mm"'
    code, text, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + CHAIN.format(extra=extra), "t.toml"))
    assert "As arcs s = r · φ at r = 200 mm" in text and "(as arcs:" in text


def test_a_length_requirement_fails_like_its_angle(capsys, write_case):
    # 0.5 mm at 200 mm = 8.594 arcmin < 16.385 arcmin: fails, as "8.594 arcmin" would.
    code, out, err = evaluate(capsys, write_case, 'radius = "200 mm"\nrequired_positioning_accuracy = "0.5 mm"')
    by_length = json.loads(out)
    code, out, err = evaluate(capsys, write_case,
                              f'required_positioning_accuracy = "{0.5 / 200 * 10800 / math.pi!r} arcmin"', "b.toml")
    by_angle = json.loads(out)
    assert by_length["verdict"]["passes"] is False
    utilization = by_angle["accuracy"]["checks"][0]["utilization"]
    assert by_length["accuracy"]["checks"][0]["utilization"] == pytest.approx(utilization, rel=1e-12)


@pytest.mark.parametrize(
    "extra, message",
    [
        ('required_positioning_accuracy = "0.05 mm"',
         "accuracy.required_positioning_accuracy: a requirement given as a length ('0.05 mm') is an arc at a radius; "
         "give accuracy.radius as well"),
        ('radius = "0 mm"', "accuracy.radius: expected a radius above zero"),
        ('radius = "5 arcmin"', "accuracy.radius: expected a length"),
        ('radius = "200 mm"\nrequired_repeatability = "-1 mm"',
         "accuracy.required_repeatability: expected a length above zero"),
    ],
)
def test_errors_name_the_key(capsys, write_case, extra, message):
    code, out, err = evaluate(capsys, write_case, extra)
    assert code == 2 and out == "" and message in err and err.count("\n") == 1, err


def test_the_report_prints_the_arc_steps_of_the_evaluation(write_case):
    from calc.report import build_report
    from calc.core.units import sig

    extra = 'radius = "200 mm"\nrequired_positioning_accuracy = "1 mm"'
    path = write_case(HEAD_TOML + PROFILE_TOML + CHAIN.format(extra=extra), "r.toml")
    report = build_report(path)
    a = report.evaluated["accuracy"].shown
    calculations = str(report.calculations())
    # s = r · φ of the positioning accuracy, and the required 1 mm as an angle: 1/200 rad = 17.19 arcmin.
    assert "Positioning accuracy as an arc at the radius" in calculations
    assert sig(a.arcs["positioning_accuracy"].value) in calculations
    assert "Required positioning accuracy given as an arc" in calculations
    assert sig(10800 / math.pi / 200) in calculations
