"""Boundaries of E3 and E4 hold for cycles whose durations add up with rounding."""

import pytest

from calc import Q_
from calc.domain.gearbox import shock_factor
from calc.domain.profile import Profile, Z_h, duty


def _cycle(moving, pause):
    segments = [("const", Q_(t, "s"), Q_(100, "rpm"), Q_(10, "N*m")) for t in moving]
    return Profile.from_segments(segments + [("pause", Q_(pause, "s"), None, None)])


def test_ed_of_exactly_60_percent_is_s1_after_rounded_sums():
    # 0.6 + 0.7 + 0.2 s = 1.5 s of a 2.5 s cycle: ED = 60 % exactly, S1 by E3.
    # In floating point the on-time sums to 1.4999999999999998 s (ED 59.999999999999986 %).
    p = _cycle([0.6, 0.7, 0.2], 1.0)
    assert duty(p).mode == "S1"


def test_on_time_of_exactly_20_min_is_s1_after_rounded_sums():
    # 1024.1 + 0.1 + 175.8 s = 1200 s = 20 min at ED 50 %: S1 by E3.
    # In floating point the on-time sums to 1199.9999999999998 s.
    p = _cycle([1024.1, 0.1, 175.8], 1200.0)
    assert duty(p).mode == "S1"


@pytest.mark.parametrize(
    "moving, pause, fs",
    [
        ([0.1, 0.1, 0.1], 2.1, 1.3),  # t_cycle 2.4 s → Z_h = 1500 exactly → 1.3 (E4); sums to 2.4000000000000004 s
        ([0.6, 0.7, 0.2], 2.1, 1.1),  # t_cycle 3.6 s → Z_h = 1000 → 1.1
        ([0.1, 0.2], 1.5, 1.6),  # t_cycle 1.8 s → Z_h = 2000 → 1.6
    ],
)
def test_shock_factor_boundary_after_rounded_sums(moving, pause, fs):
    p = _cycle(moving, pause)
    assert shock_factor(Z_h(**p.cycles_per_hour_inputs())) == fs


def test_just_below_a_boundary_stays_below():
    # A real difference (one part in a million) is not rounded away.
    assert shock_factor(Q_(1500 * (1 - 1e-6), "1/hour")) == 1.1
    p = _cycle([1.5 * (1 - 1e-6)], 1.0 + 1.5e-6)
    assert duty(p).mode == "S5"
