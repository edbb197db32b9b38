"""Angular transmission accuracy from a recorded trace (source, Angular Transmission Accuracy)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.domain.transmission import (Trace, analyze_trace, generate_trace, read_trace, transmission_accuracy,
                                      transmission_error)

from ..conftest import ROOT

SAMPLE = ROOT / "data" / "transmission-NPT035-10-generated.csv"


def test_transmission_error_by_hand():
    # Input at 3600°, ratio 10: the theoretical output is 360°; an actual 360.01° is 0.01° = 36 arcsec ahead.
    e = transmission_error(phi_2=Q_(360.01, "deg"), phi_1=Q_(3600, "deg"), i=Q_(10, ""))
    assert e.m_as("arcsec") == pytest.approx(36.0)
    assert transmission_accuracy(Delta_phi_max=Q_(30, "arcsec"),
                                 Delta_phi_min=Q_(-25, "arcsec")).m_as("arcsec") == pytest.approx(55)


def test_a_pure_once_per_revolution_error_has_twice_its_amplitude_as_range():
    # Output = θ + a·sin θ with a = 20 arcsec over one revolution: range 2a = 40 arcsec (by hand).
    theta = np.linspace(0, 2 * np.pi, 3601)
    a = Q_(20, "arcsec").m_as("rad")
    trace = Trace(Q_(theta * 7, "rad"), Q_(theta + a * np.sin(theta) + 0.3, "rad"), source="hand")
    r = analyze_trace(trace, Q_(7, ""))
    assert r.accuracy.m_as("arcsec") == pytest.approx(40.0, rel=1e-6)
    assert list(r.ranges) == ["forward"] and r.governing == "forward"
    assert str(r.step()) == "phi_TA = 40 arcsec"


def test_each_direction_is_judged_on_its_own():
    # Backward, the output lags by a backlash of 2 arcmin: that is no transmission error.
    theta = np.linspace(0, 2 * np.pi, 2000)
    a = Q_(10, "arcsec").m_as("rad")
    lag = Q_(2, "arcmin").m_as("rad")
    back = theta[::-1]
    inp = np.concatenate([theta, back]) * 5
    out = np.concatenate([theta + a * np.sin(theta), back + a * np.sin(back) - lag])
    r = analyze_trace(Trace(Q_(inp, "rad"), Q_(out, "rad")), Q_(5, ""))
    # mean of the record taken out
    assert r.ranges["forward"].m_as("arcsec") == pytest.approx([-10 + 60, 10 + 60], abs=0.05)
    assert r.accuracy.m_as("arcsec") == pytest.approx(20, abs=0.05)


@settings(max_examples=20, deadline=None)
@given(st.floats(min_value=1, max_value=100), st.floats(min_value=1, max_value=300), st.integers(0, 2**31))
def test_range_grows_with_the_error_and_the_ratio_does_not_matter(i, amplitude, seed):
    r1 = analyze_trace(generate_trace(Q_(i, ""), Q_(amplitude, "arcsec"), seed=seed), Q_(i, "")).accuracy.m_as("arcsec")
    r2 = analyze_trace(generate_trace(Q_(i, ""), Q_(2 * amplitude, "arcsec"), seed=seed),
                       Q_(i, "")).accuracy.m_as("arcsec")
    assert r2 == pytest.approx(2 * r1, rel=1e-6)
    assert 0 < r1 <= 1.75 * amplitude * (1 + 1e-9)  # peaks 1/2 + 1/4 + 1/8 of the amplitude, each way


def test_the_shipped_sample_is_what_its_header_says():
    trace = read_trace(SAMPLE)
    assert trace.comments[0].startswith("GENERATED sample, not a measurement")
    assert trace.comments[1] == (
        'Call: generate_trace(Q_(10, ""), Q_(40, "arcsec"), samples=1000, noise=Q_(1, "arcsec"), seed=7)'
    )
    again = generate_trace(Q_(10, ""), Q_(40, "arcsec"), samples=1000, noise=Q_(1, "arcsec"), seed=7)
    assert trace.input.m_as("deg") == pytest.approx(again.input.m_as("deg"), abs=1e-6)
    assert trace.output.m_as("deg") == pytest.approx(again.output.m_as("deg"), abs=1e-6)
    assert analyze_trace(trace, Q_(10, "")).accuracy.m_as("arcsec") == pytest.approx(62.95, abs=0.01)


def test_less_than_a_revolution_is_an_error():
    theta = np.linspace(0, np.pi, 100)
    with pytest.raises(CalcError,
                       match=r"half: expected a full revolution of the output \(360°\) in at least one direction, "
                             r"found forward 180°"):
        analyze_trace(Trace(Q_(theta * 10, "rad"), Q_(theta, "rad"), source="half"), Q_(10, ""))
    with pytest.raises(CalcError, match="expected a trace of at least 20 samples, found 3"):
        analyze_trace(Trace(Q_([0, 1, 2], "deg"), Q_([0, 1, 2], "deg"), source="short"), Q_(10, ""))
    # E15: a position in a bare number would be read as radians.
    with pytest.raises(CalcError, match="which is a bare number"):
        Trace(Q_([0, 1], ""), Q_([0, 1], "deg"))


def test_trace_file_errors_name_the_row(tmp_path):
    path = tmp_path / "trace.csv"
    path.write_text("input [deg],output [deg]\n0,0\n3.6,x\n")
    with pytest.raises(CalcError, match=r"trace.csv, row 3, column output: expected a number, found 'x'"):
        read_trace(path)


@pytest.mark.parametrize("ratio", [0, -10])
def test_a_ratio_of_zero_or_less_is_an_error(ratio):
    trace = generate_trace(Q_(10, ""), Q_(40, "arcsec"), seed=3)
    with pytest.raises(CalcError) as err:
        analyze_trace(trace, Q_(ratio, ""))
    assert str(err.value) == f"generated trace: ratio: expected a ratio above zero, found {ratio}"
