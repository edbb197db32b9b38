"""The motor's side (calc.domain.motor, calc.sections.motor) and the emergency stop: hand calculations,
laws as hypothesis properties, the section on a typed and on a sampled cycle, and bad input."""

import dataclasses
import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import Q_
from calc.sections.case import read_case
from calc.domain.cycle import ACCEL, CONST, DECEL, PAUSE, SampledCycle
from calc.domain.motor import OutputLoad, _equal_samples, T_1_back, T_1_drive, T_1rms, alpha_1, motor_load, motor_torque
from calc.domain.motion import Samples
from calc.domain.profile import segments
from calc.sections import evaluate
from calc.sections.motion import Motion

from ..conftest import DERIVED_EXAMPLE, EXAMPLE, HEAD_TOML, PROFILE_TOML, run

# A trapezoid move of a rotary load, by hand: J_L = 0.1 kg·m², friction 2 N·m against the motion;
# accelerate at 100 rad/s² for 0.1 s to 10 rad/s, run 0.3 s, brake at -100 rad/s² for 0.1 s, dwell
# 0.5 s on a level axis (no holding torque). T_2 = J_L · α_2 + 2 N·m: 12, 2, -8 and 0 N·m.
PHASES = [  # (duration s, speed rad/s (the phase's mean), acceleration rad/s², T_2 N·m)
    (0.1, 5.0, 100.0, 12.0),
    (0.3, 10.0, 0.0, 2.0),
    (0.1, 5.0, -100.0, -8.0),
    (0.5, 0.0, 0.0, 0.0),
]


def trapezoid(samples_per_phase: int = 10) -> SampledCycle:
    """The trapezoid above, each phase cut into equal samples (the torques are constant within a phase)."""
    d, n, a, T = (np.repeat([p[k] for p in PHASES], samples_per_phase) for k in range(4))
    return SampledCycle(d / samples_per_phase, n, a, T)


def sampled_load(cycle, i, eta, J_motor, J_1):
    return motor_load(
        Q_(cycle.dt, "s"), Q_(cycle.torque, "N*m"), Q_(cycle.speed, "rad/s"), Q_(i, ""), Q_(eta, ""),
        Q_(cycle.acceleration, "rad/s**2"), Q_(J_motor, "kg*m**2"), Q_(J_1, "kg*m**2"),
    )


def test_trapezoid_by_hand():
    # i = 10, η = 0.9, J_motor = J_1 = 1 kg·cm² = 1e-4 kg·m²: α_1 = 10 · 100 = 1000 rad/s², rotor term
    # (1e-4 + 1e-4) · 1000 = 0.2 N·m.
    #   accel (drives): 0.2 + 12 / (10 · 0.9) = 0.2 + 1.33333 = 1.53333 N·m
    #   run (drives):   2 / 9 = 0.22222 N·m
    #   brake (T_2 · ω_2 = -8 · 5 < 0, driven back): -0.2 + (-8) · 0.9 / 10 = -0.92 N·m
    #   dwell: 0
    # peak 1.53333 N·m; RMS = √((1.53333² · 0.1 + 0.22222² · 0.3 + 0.92² · 0.1 + 0 · 0.5) / 1.0)
    #                       = √(0.235111 + 0.014815 + 0.084640) = √0.334566 = 0.578416 N·m
    m = sampled_load(trapezoid(), 10, 0.9, 1e-4, 1e-4)
    assert m.rotor_term
    T = m.T_1.m_as("N*m").reshape(4, 10)
    assert T[:, 0] == pytest.approx([1.533333, 0.222222, -0.92, 0.0], abs=1e-6)
    assert m.peak.m_as("N*m") == pytest.approx(1.533333, abs=1e-6)
    assert m.rms.m_as("N*m") == pytest.approx(0.578416, abs=1e-6)


def test_the_sample_count_does_not_change_the_rms():
    one, many = (sampled_load(trapezoid(k), 10, 0.9, 1e-4, 1e-4) for k in (1, 37))
    assert one.rms.m_as("N*m") == pytest.approx(many.rms.m_as("N*m"), rel=1e-12)


def test_formulas_by_hand():
    # α_1 = 10 · 100 rad/s² = 1000 rad/s²
    assert alpha_1(alpha_2=Q_(100, "rad/s**2"), i=Q_(10, "")).m_as("rad/s**2") == pytest.approx(1000)
    # (1 + 1) kg·cm² · 1000 rad/s² + 12 N·m / (10 · 0.9) = 0.2 + 1.33333 N·m
    args = dict(J_motor=Q_(1, "kg*cm**2"), J_1=Q_(1, "kg*cm**2"), alpha_1=Q_(1000, "rad/s**2"), T_2=Q_(12, "N*m"),
                i=Q_(10, ""), eta=Q_(0.9, ""))
    assert T_1_drive(**args).m_as("N*m") == pytest.approx(1.533333, abs=1e-6)
    # 0.2 + 12 · 0.9 / 10 = 1.28 N·m
    assert T_1_back(**args).m_as("N*m") == pytest.approx(1.28)
    # √((3² · 1 + 4² · 1 + 0² · 2) / 4) = √(25 / 4) = 2.5 N·m
    assert T_1rms(T_1k=Q_([3.0, -4.0, 0.0], "N*m"), t_k=Q_([1.0, 1.0, 2.0], "s")).m_as("N*m") == pytest.approx(2.5)


def test_a_hold_at_rest_drives_and_typed_cycle_leaves_the_rotor_out():
    # The example's cycle (calc.domain.motor.motor_load's docstring): 60 / (10 · 0.97) = 6.1856 N·m; braking
    # -45 · 0.97 / 10 = -4.365 N·m; a holding torque of 5 N·m at rest counts as driving: 5 / 9.7.
    T = motor_torque(Q_([60.0, -45.0, 5.0], "N*m"), Q_([150.0, 150.0, 0.0], "rpm"), Q_(10, ""), Q_(0.97, ""))
    assert T.m_as("N*m") == pytest.approx([6.185567, -4.365, 0.515464], abs=1e-6)


# Torques as a case or catalog can give them: zero, or of magnitude within calc.core.units.SI_SCALE
# (from 1e-12 N·m). Below it the squares of the RMS underflow (1e-159 N·m squared is subnormal),
# which no input reaches.
torques = st.one_of(st.just(0.0), st.floats(1e-12, 1e4), st.floats(-1e4, -1e-12))
ratios = st.floats(1.0, 200.0)
efficiencies = st.floats(0.5, 1.0)


@settings(deadline=None)
@given(T_2=torques, i=ratios, k=st.floats(1.1, 10.0), eta=efficiencies)
def test_load_term_scales_as_one_over_i(T_2, i, k, eta):
    T = [motor_torque(Q_(T_2, "N*m"), Q_(1.0, "rad/s"), Q_(r, ""), Q_(eta, "")).m_as("N*m") for r in (i, k * i)]
    assert T[1] == pytest.approx(T[0] / k, rel=1e-9, abs=1e-12)


@settings(deadline=None)
@given(a=st.floats(-1e4, 1e4, allow_subnormal=False), i=ratios, k=st.floats(1.1, 10.0), J=st.floats(1e-6, 1e-2))
def test_rotor_term_scales_as_i(a, i, k, J):
    def T(r):
        return motor_torque(Q_(0.0, "N*m"), Q_(1.0, "rad/s"), Q_(r, ""), Q_(0.9, ""), Q_(a, "rad/s**2"),
                            Q_(J, "kg*m**2"), Q_(0.0, "kg*m**2"))

    assert T(k * i).m_as("N*m") == pytest.approx(k * T(i).m_as("N*m"), rel=1e-9, abs=1e-12)


@settings(deadline=None)
@given(T_2=torques, i=ratios, eta=st.floats(0.5, 0.999))
def test_driven_back_never_exceeds_driving_in_magnitude(T_2, i, eta):
    args = dict(J_motor=Q_(0, "kg*m**2"), J_1=Q_(0, "kg*m**2"), alpha_1=Q_(0, "rad/s**2"), T_2=Q_(T_2, "N*m"),
                i=Q_(i, ""), eta=Q_(eta, ""))
    assert abs(T_1_back(**args).m_as("N*m")) <= abs(T_1_drive(**args).m_as("N*m"))


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.floats(1e-3, 10.0), torques, st.floats(-300, 300)), min_size=1, max_size=12), ratios,
       efficiencies)
def test_rms_lies_between_zero_and_peak(samples, i, eta):
    t, T, n = (np.array(x) for x in zip(*samples))
    m = motor_load(Q_(t, "s"), Q_(T, "N*m"), Q_(n, "rpm"), Q_(i, ""), Q_(eta, ""))
    rms, peak = m.rms.m_as("N*m"), m.peak.m_as("N*m")
    assert 0 <= rms <= peak * (1 + 1e-12)


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.floats(1e-3, 10.0), st.sampled_from([-20.0, 0.0, 3.5, 12.0]),
                          st.sampled_from([-300.0, 0.0, 150.0]),
                          st.sampled_from([-40.0, 0.0, 25.0])), min_size=1, max_size=30), ratios, efficiencies)
def test_merging_equal_samples_keeps_every_peak_and_rms(samples, i, eta):
    # Values drawn from few choices, so that many samples repeat: merged, the cycle gives the same
    # motor torques in the order each first appears, durations summed.
    t, T, n, a = (np.array(x) for x in zip(*samples))
    out = OutputLoad(Q_(t, "s"), Q_(T, "N*m"), Q_(n, "rpm"), Q_(a, "rad/s**2"), Q_(np.abs(n).max(), "rpm"))
    few = out.distinct()
    assert few.dt.m_as("s").sum() == pytest.approx(t.sum(), rel=1e-12)
    firsts = list(dict.fromkeys(zip(T, n, a)))
    np.testing.assert_allclose(np.column_stack([few.torque.m_as("N*m"), few.speed.m_as("rpm"),
                                                few.alpha_2.m_as("rad/s**2")]),
                               np.array(firsts), rtol=1e-12)
    J = Q_(2.0, "kg*cm**2")
    whole = motor_load(out.dt, out.torque, out.speed, Q_(i, ""), Q_(eta, ""), out.alpha_2, J, J)
    merged = motor_load(few.dt, few.torque, few.speed, Q_(i, ""), Q_(eta, ""), few.alpha_2, J, J)
    assert merged.peak.m_as("N*m") == pytest.approx(whole.peak.m_as("N*m"), rel=1e-12, abs=1e-15)
    assert merged.rms.m_as("N*m") == pytest.approx(whole.rms.m_as("N*m"), rel=1e-9, abs=1e-15)


@settings(max_examples=100, deadline=None)
@given(st.integers(1, 3).flatmap(lambda m: st.lists(
    st.lists(st.sampled_from([0.0, -0.0, 1.0, -2.5, np.inf, np.nan]), min_size=m, max_size=m), max_size=40)))
def test_equal_samples_are_the_groups_numpy_unique_finds(columns):
    # The merge's grouping against numpy's own (np.unique over the columns): the same first
    # samples, each sample in the group of the same first; -0.0 equals 0.0, NaN equals nothing.
    samples = np.array(columns, dtype=float).T.reshape(len(columns[0]) if columns else 1, len(columns))
    first, inverse = _equal_samples(samples)
    if not columns:
        assert first.size == 0 and inverse.size == 0
        return
    _, first_np, inverse_np = np.unique(samples, axis=1, return_index=True, return_inverse=True)
    np.testing.assert_array_equal(np.sort(first), np.sort(first_np))
    np.testing.assert_array_equal(first[inverse], first_np[inverse_np.ravel()])


# --- the section -----------------------------------------------------------------------------------

MOTOR = """
title = "motor axis"
[motor]
peak_torque = "{peak}"
inertia = "1 kg*cm**2"
{extra}
[load]
inertia = "1000 kg*cm**2"
[gearbox]
ratio = 10
part = "NPT035-10"
"""


def motor_case(write_case, peak="12 N*m", extra="", more=""):
    return read_case(write_case(MOTOR.format(peak=peak, extra=extra) + more + PROFILE_TOML))


def test_the_motivating_example_fails_on_the_motors_peak(write_case):
    # 60 N·m at the output through i = 10, η = 0.97 needs 60 / 9.7 = 6.19 N·m at the motor; a motor of
    # 1.2 N·m peak cannot give it. The gearbox alone passes (T_2max = 1.2 · 10 · 1.3 · 0.97 = 15.1 N·m).
    results = evaluate(motor_case(write_case, peak="1.2 N*m"))
    assert results["gearbox"].selection.selected == "NPT035-10"
    m = results.to_json()["motor"]
    assert m["peak_torque_required"]["value"] == pytest.approx(6.185567, abs=1e-6)
    assert m["rotor_term"] is False
    assert any("rotor term" in n and "left out" in n for n in m["notes"])
    peak = next(c for c in m["checks"] if c["name"] == "T_1B")
    assert peak["passes"] is False and peak["utilization"] == pytest.approx(6.185567 / 1.2, rel=1e-6)
    v = results.verdict
    assert v.passes is False and any("T_1peak <= T_1B" in r for r in v.reasons)


def test_rated_torque_and_top_speed_govern_where_given(write_case):
    # RMS of the example's cycle through NPT035-10: 2.647 N·m (calc.domain.motor.motor_load's docstring);
    # top speed 300 rpm · 10 = 3000 rpm.
    case = motor_case(write_case, extra='rated_torque = "2.5 N*m"\nmax_speed = "3000 rpm"')
    m = evaluate(case).to_json()["motor"]
    by = {c["name"]: c for c in m["checks"]}
    assert m["rms_torque_required"]["value"] == pytest.approx(2.64704, abs=1e-5)
    assert by["T_1N"]["passes"] is False and by["T_1N"]["utilization"] == pytest.approx(2.64704 / 2.5, rel=1e-5)
    assert by["n_max"]["passes"] is True and m["max_speed_required"]["value"] == pytest.approx(3000)
    assert evaluate(case).verdict.passes is False
    ok = evaluate(motor_case(write_case, extra='rated_torque = "2.7 N*m"\nmax_speed = "3000 rpm"'))
    assert ok.verdict.passes is True
    slow = evaluate(motor_case(write_case, extra='max_speed = "2500 rpm"'))
    assert slow.verdict.passes is False and any("n_2max · i <= n_max" in r for r in slow.verdict.reasons)


def test_ratings_not_given_are_not_checked_and_say_so(write_case):
    m = evaluate(motor_case(write_case)).to_json()["motor"]
    assert [c["name"] for c in m["checks"]] == ["T_1B"]
    assert any("motor.rated_torque" in n for n in m["notes"]) and any("motor.max_speed" in n for n in m["notes"])


def with_cycle(case, cycle):
    """The case with a sampled cycle at the gearbox output (one segment per phase of the
    trapezoid), as a drive record without a mechanism gives it, its typed segments kept as its
    load cycle: the motor's side reads the samples."""
    k = np.repeat(np.arange(len(PHASES)), len(cycle.dt) // len(PHASES))
    samples = Samples(np.cumsum(cycle.dt) - cycle.dt / 2, cycle.dt, np.cumsum(cycle.speed * cycle.dt), cycle.speed,
                      cycle.acceleration, np.zeros_like(cycle.dt), np.array([ACCEL, CONST, DECEL, PAUSE])[k], k,
                      np.array([p[0] for p in PHASES]))
    motion = Motion(None, [], [], samples, cycle, segments(samples, cycle.torque), case.profile, record="trapezoid.csv")
    return dataclasses.replace(case, motion=motion)


def test_the_section_reads_a_sampled_cycle(write_case):
    # The trapezoid through NPT035-10 (i = 10, η = 0.97, J_1 = 0.93 kg·cm²), J_motor = 1 kg·cm²:
    # rotor term (1 + 0.93) kg·cm² · 1000 rad/s² = 0.193 N·m.
    #   accel: 0.193 + 12 / 9.7 = 0.193 + 1.237113 = 1.430113 N·m
    #   run: 2 / 9.7 = 0.206186 N·m; brake: -0.193 - 8 · 0.97 / 10 = -0.969 N·m; dwell 0
    #   RMS = √(1.430113² · 0.1 + 0.206186² · 0.3 + 0.969² · 0.1) = √(0.204522 + 0.012754 + 0.093896)
    #       = √0.311172 = 0.557828 N·m
    #   top speed 10 rad/s · 10 = 100 rad/s = 954.93 rpm
    case = with_cycle(motor_case(write_case, extra='rated_torque = "0.5 N*m"'), trapezoid())
    m = evaluate(case).to_json()["motor"]
    assert m["rotor_term"] is True
    assert m["J_1"]["value"] == pytest.approx(0.93)
    assert m["peak_torque_required"]["value"] == pytest.approx(1.430113, abs=1e-6)
    assert m["rms_torque_required"]["value"] == pytest.approx(0.557828, abs=1e-6)
    assert m["max_speed_required"]["value"] == pytest.approx(954.9297, abs=1e-4)
    assert not any("left out" in n for n in m["notes"])
    assert evaluate(case).verdict.passes is False  # RMS 0.558 N·m > rated 0.5 N·m


def test_a_sampled_cycle_without_the_motors_inertia_is_not_decided(write_case):
    text = MOTOR.format(peak="12 N*m", extra="").replace('inertia = "1 kg*cm**2"\n', "", 1)
    case = with_cycle(read_case(write_case(text + PROFILE_TOML)), trapezoid())
    r = evaluate(case)
    m = r.to_json()["motor"]
    assert m["peak_torque_required"] is None and m["checks"][0]["passes"] is None
    assert "motor.inertia" in m["checks"][0]["not_made"]
    assert r.verdict.passes is None


def test_a_sampled_cycle_through_a_gearbox_without_j1_is_not_decided(write_case, tmp_path):
    # NPT035-10 with its J_1 left blank (a maker's catalog may lack it): the rotor term cannot be computed.
    from ..conftest import GEARBOXES

    lines = GEARBOXES.read_text().splitlines()
    header = lines[0].split(",")
    row = next(l.split(",") for l in lines[1:] if l.startswith("NPT035-10,"))
    row[header.index("J_1 [kg*cm**2]")] = ""
    (tmp_path / "g.csv").write_text("\n".join([lines[0], ",".join(row)]) + "\n")
    text = MOTOR.format(peak="12 N*m", extra="").replace('part = "NPT035-10"', 'part = "NPT035-10"\ncatalog = "g.csv"')
    r = evaluate(with_cycle(read_case(write_case(text + PROFILE_TOML)), trapezoid()))
    m = r.to_json()["motor"]
    assert m["rms_torque_required"] is None and "J_1" in m["checks"][0]["not_made"]
    assert "NPT035-10" in m["checks"][0]["not_made"]
    assert m["max_speed_required"]["value"] == pytest.approx(954.9297, abs=1e-4)  # the speed needs no inertia


def test_a_motor_side_coupling_turns_with_the_motor():
    # The example: bellows coupling between motor and gearbox (side = "input"); its whole inertia
    # adds to J_1 of NPT035-10 (0.93 kg·cm²).
    case = with_cycle(read_case(EXAMPLE), trapezoid())
    m = evaluate(case).to_json()["motor"]
    J_c = m["J_coupling"]["value"]
    assert J_c > 0 and m["J_1"]["value"] == pytest.approx(0.93 + J_c)
    assert any("motor-side coupling" in n for n in m["notes"])


# --- the emergency stop ----------------------------------------------------------------------------


def test_emergency_stop_default_is_the_motors_peak_through_the_gearbox(write_case):
    # 12 N·m · 10 = 120 N·m (no credit for efficiency) against T_2Not = 480 N·m of NPT035-10: 0.25
    g = evaluate(motor_case(write_case)).to_json()["gearbox"]["candidates"][0]
    stop = next(c for c in g["checks"] if c["name"] == "T_2Not")
    assert stop["required"]["value"] == pytest.approx(120) and stop["utilization"] == pytest.approx(0.25)
    assert stop["governs"] is True


def test_a_given_emergency_stop_torque_governs(write_case):
    case = read_case(write_case(HEAD_TOML + 'emergency_stop_torque = "20000 N*m"\n' + PROFILE_TOML))
    r = evaluate(case)
    # 20000 N·m exceeds every T_2Not at ratio 10 in catalogs/gearboxes.csv (the largest: TP500-10, 15000 N·m)
    assert r["gearbox"].selection.selected is None
    assert any("T_2stop <= T_2Not" in reason for reason in r.verdict.reasons)


def test_a_row_without_t2not_is_not_checked_for_it(write_case, tmp_path):
    from ..conftest import GEARBOXES

    lines = GEARBOXES.read_text().splitlines()
    header = lines[0].split(",")
    k = header.index("T_2Not [N*m]")
    rows = [l.split(",") for l in lines[1:] if l.startswith("NPT035-10,")]
    rows[0][k] = ""
    (tmp_path / "g.csv").write_text("\n".join([lines[0], ",".join(rows[0])]) + "\n")
    case = read_case(write_case(HEAD_TOML + 'catalog = "g.csv"\n' + PROFILE_TOML))
    r = evaluate(case)
    stop = next(c for c in r.to_json()["gearbox"]["candidates"][0]["checks"] if c["name"] == "T_2Not")
    assert stop["passes"] is None and stop["not_made"] == "the catalog gives no T_2Not"
    assert r["gearbox"].selection.selected == "NPT035-10"


# --- bad input -------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "key, value, fragment",
    [
        ("rated_torque", '"0 N*m"', "motor.rated_torque: expected a torque above zero"),
        ("rated_torque", '"-2 N*m"', "motor.rated_torque: expected a torque above zero"),
        ("max_speed", '"0 rpm"', "motor.max_speed: expected a speed above zero"),
        ("max_speed", '"3000 Hz"', "motor.max_speed"),
        ("rated_torque", '"15 N*m"', "motor.rated_torque: expected a continuous torque at most the peak torque"),
    ],
)
def test_bad_motor_ratings_are_one_line_errors(capsys, write_case, key, value, fragment):
    path = write_case(MOTOR.format(peak="12 N*m", extra=f"{key} = {value}") + PROFILE_TOML)
    code, out, err = run(capsys, path)
    assert code == 2 and out == "" and fragment in err and err.count("\n") == 1


def test_a_non_positive_emergency_stop_torque_is_an_error(capsys, write_case):
    code, out, err = run(capsys, write_case(HEAD_TOML + 'emergency_stop_torque = "0 N*m"\n' + PROFILE_TOML))
    assert code == 2 and out == "" and "gearbox.emergency_stop_torque: expected a torque above zero" in err


def test_json_of_the_example_has_the_motor(capsys):
    code, out, _ = run(capsys, EXAMPLE, "--json")
    m = json.loads(out)["motor"]
    assert code == 0
    assert set(m) >= {"peak_torque_required", "rms_torque_required", "max_speed_required", "checks"}



def test_the_report_has_the_motor_and_the_ratio():
    from calc.report import report_of

    typed = report_of(read_case(EXAMPLE))
    text = "\n".join((typed.inputs(), typed.calculations(), typed.checks(), typed.section_results()))
    assert "The motor through the selected gearbox, NPT035-10" in text and "left out" in text
    assert r"T_{\mathrm{1peak}}" in text  # as the criterion T_1peak <= T_1B prints it
    assert r"\subsection*{The ratio}" in text and "lowest RMS motor torque" in text
    captions = [c for _, c in typed.figures()]
    assert any("Motor torque over the cycle" in c for c in captions) and any("against the ratio" in c for c in captions)
    sampled = report_of(with_cycle(read_case(EXAMPLE), trapezoid()))
    # 40 samples: the RMS is shown as its formula and result, not 40 substituted terms
    assert "over the 40 samples" in sampled.calculations()


def test_the_reports_inputs_list_the_motors_ratings_and_the_stop_torque(write_case):
    from calc.report import report_of
    from calc.report.common import case_key

    extra = 'rated_torque = "4.5 N*m"\nmax_speed = "6000 rpm"'
    case = read_case(write_case(MOTOR.format(peak="12 N*m",
                                             extra=extra) + 'emergency_stop_torque = "200 N*m"\n' + PROFILE_TOML))
    inputs = report_of(case).inputs()
    for key in ("motor.rated_torque", "motor.max_speed", "gearbox.emergency_stop_torque"):
        assert case_key(key) in inputs
    assert "T_{\\mathrm{2stop}}" in inputs and "200" in inputs


def test_typed_segments_pick_their_motor_from_the_catalog():
    """The example's derived segments with the dwell shortened are typed (no rotor term); the motor
    is still the catalog's choice, and each phase's torque at the motor is T_2 through the gearbox."""
    from calc.review import with_changes

    typed = with_changes(read_case(DERIVED_EXAMPLE), durations=Q_(np.array([0.15, 0.2, 0.15, 0.25]), "s"))
    result = evaluate(typed)
    motor = result.sections["motor"]
    assert typed.motion is None and result.to_json()["gearbox"]["selected"] == "NPT035-10"
    # by hand, through the chosen NPT035-10 (S1 now: ED = 0.5 / 0.75 = 66.7 %; NPT015-10 would carry the
    # cycle, but no coupling lifts its drive train above 2 f_er), eta = 0.97 and i = 10:
    #   driving:  T_1 = T_2 / (i · eta) = 7.82691 / 9.7 = 0.80690 N·m; 3 / 9.7 = 0.30928 N·m
    #   braking:  T_1 = T_2 · eta / i = 2.34763 · 0.097 = 0.22772 N·m (magnitude)
    peaks = [p.peak_torque for p in motor.phases]
    assert [p.phase for p in motor.phases] == ["accel", "const", "decel", "pause"]
    assert np.allclose(peaks, [0.80690, 0.30928, 0.22772, 0.0], atol=5e-5)
