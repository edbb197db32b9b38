"""Load profile, duty cycle, operating mode (E3), S1 means (E2) and Z_h."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.domain.profile import ED, Profile, T_2m, Z_h, duty, n_2m, operating_mode


def example_profile():
    # The example case's cycle (cases/indexing-table.toml).
    return Profile.from_segments(
        [
            ("accel", Q_(0.2, "s"), Q_(150, "rpm"), Q_(60, "N*m")),
            ("const", Q_(0.6, "s"), Q_(300, "rpm"), Q_(20, "N*m")),
            ("decel", Q_(0.2, "s"), Q_(150, "rpm"), Q_(-45, "N*m")),
            ("pause", Q_(1.0, "s"), None, None),
        ]
    )


def test_duty_of_the_example_by_hand():
    # t_on = 0.2 + 0.6 + 0.2 = 1.0 s; t_cycle = 1.0 + 1.0 = 2.0 s; ED = 1/2 = 50 % < 60 % and t_on < 20 min → S5.
    d = duty(example_profile())
    assert d.t_on.m_as("s") == pytest.approx(1.0)
    assert d.t_cycle.m_as("s") == pytest.approx(2.0)
    assert d.ED.m_as("percent") == pytest.approx(50.0)
    assert d.mode == "S5"


def test_s1_means_of_the_example_by_hand():
    seg = example_profile().moving_values()
    # E2: n_2m = Σ|n|t / Σt over moving segments = (150·0.2 + 300·0.6 + 150·0.2) / 1.0 = 240 rpm.
    assert n_2m(n_2k=seg["n_2k"], t_k=seg["t_k"]).m_as("rpm") == pytest.approx(240.0)
    # E2: T_2m = ∛(Σ|n|t|T|³ / Σ|n|t) with |−45| for the braking segment:
    # numerator = 150·0.2·60³ + 300·0.6·20³ + 150·0.2·45³ = 6 480 000 + 1 440 000 + 2 733 750 = 10 653 750
    # denominator = 240 (rpm·s); 10 653 750 / 240 = 44 390.625; ∛44 390.625 = 35.4076 N·m.
    assert T_2m(**seg).m_as("N*m") == pytest.approx(44390.625 ** (1 / 3), rel=1e-12)
    assert T_2m(**seg).m_as("N*m") == pytest.approx(35.4076, abs=1e-4)


def test_cycles_per_hour():
    # Source: Z_h = 3600 / t_cycle (t in s): 3600 / 2 = 1800 per hour, for one load cycle in the cycle.
    assert Z_h(z_c=Q_(1, ""), t_cycle=Q_(2, "s")).m_as("1/hour") == pytest.approx(1800)
    # E16: two load cycles (moves) in a 3.2 s cycle (the inch example): 2 · 3600 / 3.2 = 2250 per hour.
    assert Z_h(z_c=Q_(2, ""), t_cycle=Q_(3.2, "s")).m_as("1/hour") == pytest.approx(2250)


def _move(t_pause: float) -> list:
    return [("accel", Q_(0.15, "s"), Q_(20, "rpm"), Q_(10, "N*m")),
            ("const", Q_(0.2, "s"), Q_(40, "rpm"), Q_(3, "N*m")),
            ("decel", Q_(0.15, "s"), Q_(20, "rpm"), Q_(-4, "N*m")),
            ("pause", Q_(t_pause, "s"), None, None)]


def test_load_cycles_count_the_moves_e16():
    # E16: a load cycle is acceleration, constant speed, deceleration and pause, as the gearbox makers count it.
    assert Profile.from_segments(_move(1.0)).load_cycles.m == 1
    assert Profile.from_segments(_move(1.0) * 3).load_cycles.m == 3
    # Two moves back to back (the second starts as the first stops) and a triangle move (no constant phase).
    back_to_back = _move(1.0)[:3] + _move(1.0)
    assert Profile.from_segments(back_to_back).load_cycles.m == 2
    assert Profile.from_segments([_move(1.0)[0], _move(1.0)[2]]).load_cycles.m == 1
    # A continuous run (no deceleration) is one load cycle, the cycle itself.
    assert Profile.from_segments([("const", Q_(1, "s"), Q_(100, "rpm"), Q_(5, "N*m"))]).load_cycles.m == 1


@settings(max_examples=30, deadline=None)
@given(k=st.integers(1, 6), t_pause=st.floats(0.05, 10))
def test_one_cycle_of_k_moves_gives_the_z_h_of_one_move_e16(k, t_pause):
    # k copies of a move in one cycle of the file: k load cycles in k times the time, the same Z_h.
    one, many = Profile.from_segments(_move(t_pause)), Profile.from_segments(_move(t_pause) * k)
    assert many.load_cycles.m == k * one.load_cycles.m
    z_one, z_many = Z_h(**one.cycles_per_hour_inputs()), Z_h(**many.cycles_per_hour_inputs())
    assert z_many.m_as("1/hour") == pytest.approx(z_one.m_as("1/hour"), rel=1e-12)


@pytest.mark.parametrize(
    "ed, t_on, mode",
    [
        (59.99, "19.9 min", "S5"),
        (60.0, "1 s", "S1"),  # E3: exactly 60 % is S1
        (50.0, "20 min", "S1"),  # E3: exactly 20 min is S1
        (70.0, "1 s", "S1"),
        (10.0, "25 min", "S1"),
    ],
)
def test_operating_mode_boundaries_e3(ed, t_on, mode):
    from calc.core.units import parse_quantity

    assert operating_mode(Q_(ed, "percent"), parse_quantity(t_on, "time", "t_on")) == mode


@pytest.mark.parametrize(
    "segments, fragment",
    [
        ([], "at least one segment"),
        ([("walk", Q_(1, "s"), Q_(1, "rpm"), Q_(1, "N*m"))], "phase: expected one of accel"),
        ([("const", Q_(0, "s"), Q_(1, "rpm"), Q_(1, "N*m"))], "duration: expected a duration above zero"),
        ([("const", Q_(-1, "s"), Q_(1, "rpm"), Q_(1, "N*m"))], "above zero"),
        ([("const", Q_(1, "s"), Q_(1, "rpm"), Q_(1, "N*m")), ("pause", Q_(1, "s"), Q_(1, "rpm"), None)],
         "a pause takes only a duration"),
        ([("const", Q_(1, "s"), None, Q_(1, "N*m"))], "needs a speed"),
        ([("pause", Q_(1, "s"), None, None)], "only pauses"),
        ([("const", Q_(1, "s"), Q_(1, "Hz"), Q_(1, "N*m"))], "expected a speed"),
    ],
)
def test_bad_profiles(segments, fragment):
    with pytest.raises(CalcError, match=fragment):
        Profile.from_segments(segments, where="case.toml: profile")


segment = st.tuples(
    st.sampled_from(["accel", "const", "decel"]),
    st.floats(0.01, 100),  # s
    st.floats(-6000, 6000, allow_subnormal=False),  # rpm (sign is direction, E2 takes magnitudes)
    st.floats(-500, 500),  # N·m
)


def build(segs, pause=0.0):
    assume(any(n != 0 for _, _, n, _ in segs))  # a cycle whose every speed is zero is refused
    items = [(p, Q_(t, "s"), Q_(n, "rpm"), Q_(T, "N*m")) for p, t, n, T in segs]
    if pause:
        items.append(("pause", Q_(pause, "s"), None, None))
    return Profile.from_segments(items)


@settings(max_examples=150, deadline=None)
@given(st.lists(segment, min_size=1, max_size=8), st.floats(0, 1000))
def test_means_lie_between_smallest_and_largest_segment_value(segs, pause):
    p = build(segs, pause)
    seg = p.moving_values()
    n = abs(seg["n_2k"].m_as("rpm"))
    T = abs(seg["T_2k"].m_as("N*m"))
    mean_n = n_2m(n_2k=seg["n_2k"], t_k=seg["t_k"]).m_as("rpm")
    assert n.min() * (1 - 1e-9) <= mean_n <= n.max() * (1 + 1e-9)
    assume(np.sum(n * seg["t_k"].m_as("s")) > 1e-6)
    mean_T = T_2m(**seg).m_as("N*m")
    moving = n > 0  # segments at standstill carry no weight in the cubic mean
    assert T[moving].min() * (1 - 1e-9) - 1e-9 <= mean_T <= T[moving].max() * (1 + 1e-9) + 1e-9


@settings(max_examples=100, deadline=None)
@given(st.lists(segment, min_size=1, max_size=8), st.floats(0, 1e5))
def test_duty_cycle_is_in_zero_one(segs, pause):
    d = duty(build(segs, pause))
    assert 0 < d.ED.m_as("") <= 1


@settings(max_examples=100, deadline=None)
@given(st.lists(segment, min_size=1, max_size=6), st.floats(0.1, 10))
def test_cubic_mean_is_homogeneous_and_order_free(segs, c):
    seg = build(segs).moving_values()
    assume(np.sum(abs(seg["n_2k"].m_as("rpm")) * seg["t_k"].m_as("s")) > 1e-6)
    base = T_2m(**seg).m_as("N*m")
    scaled = T_2m(n_2k=seg["n_2k"], t_k=seg["t_k"], T_2k=seg["T_2k"] * c).m_as("N*m")
    assert scaled == pytest.approx(c * base, rel=1e-9, abs=1e-9)
    reversed_ = T_2m(n_2k=seg["n_2k"][::-1], t_k=seg["t_k"][::-1], T_2k=seg["T_2k"][::-1]).m_as("N*m")
    assert reversed_ == pytest.approx(base, rel=1e-9, abs=1e-9)


@settings(max_examples=100, deadline=None)
@given(st.lists(segment, min_size=1, max_size=6))
def test_metric_and_inch_inputs_give_the_same_answer(segs):
    seg = build(segs).moving_values()
    assume(np.sum(abs(seg["n_2k"].m_as("rpm")) * seg["t_k"].m_as("s")) > 1e-6)
    imperial = {"n_2k": seg["n_2k"].to("rev/s"), "t_k": seg["t_k"].to("min"), "T_2k": seg["T_2k"].to("lbf*in")}
    assert T_2m(**imperial).m_as("N*m") == pytest.approx(T_2m(**seg).m_as("N*m"), rel=1e-9, abs=1e-9)
    assert n_2m(n_2k=imperial["n_2k"], t_k=imperial["t_k"]).m_as("rpm") == pytest.approx(
        n_2m(n_2k=seg["n_2k"], t_k=seg["t_k"]).m_as("rpm"), rel=1e-9, abs=1e-9
    )


def test_batch_of_profiles_evaluates_at_once():
    # Segment sums run over the last axis, so a batch of P profiles × K segments is one call.
    n = Q_(np.array([[100.0, 200.0], [300.0, 300.0]]), "rpm")
    t = Q_(np.array([[1.0, 1.0], [1.0, 3.0]]), "s")
    assert n_2m(n_2k=n, t_k=t).m_as("rpm") == pytest.approx([150.0, 300.0])


def test_ed_formula():
    assert ED(t_on=Q_(3, "s"), t_cycle=Q_(4, "s")).m_as("percent") == pytest.approx(75)


def test_per_segment_arguments_of_unequal_length_are_named():
    # Two speeds, one duration, three torques: which segment belongs to which cannot be told.
    with pytest.raises(CalcError,
                       match=r"^T_2m: expected one value per segment in each per-segment argument, found lengths n_2k "
                             r"2, t_k 1, T_2k 3$"):
        T_2m(n_2k=Q_([100, 200], "rpm"), t_k=Q_([1.0], "s"), T_2k=Q_([1, 2, 3], "N*m"))
