"""Gearbox selection: shock factor (E4), T_2max, checks (E1, E5), inertia ratio (E6), ranking."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.data.catalog import load_catalog
from calc.core.checks import rank
from calc.domain.gearbox import SCHEMA, T_2max, inertia_ratio, n_1, rows_at_ratio, select_gearbox, shock_factor
from calc.domain.profile import Profile
from calc.core.units import Value

from ..conftest import GEARBOXES
from .test_profile import example_profile


@pytest.fixture(scope="module")
def catalog():
    return load_catalog(GEARBOXES, SCHEMA)


@pytest.mark.parametrize(
    "zh, fs",
    [(0, 1.0), (999.9, 1.0), (1000, 1.1), (1499, 1.1), (1500, 1.3), (1999, 1.3), (2000, 1.6), (2999, 1.6), (3000, 2.0),
     (10000, 2.0)],
)
def test_shock_factor_table_with_e4_boundaries(zh, fs):
    # E4: the higher factor applies at each boundary 1000, 1500, 2000, 3000.
    assert shock_factor(Q_(zh, "1/hour")) == fs


@given(st.lists(st.floats(0, 1e5), min_size=2, max_size=20))
def test_shock_factor_never_falls_as_cycles_rise(zs):
    zs = np.sort(np.array(zs))
    fs = shock_factor(Q_(zs, "1/hour"))
    assert np.all(np.diff(fs) >= 0)


def test_example_s5_selection_by_hand(catalog):
    rows = rows_at_ratio(catalog, Q_(10, ""))
    sel = select_gearbox(example_profile(), rows, Q_(12, "N*m"), Q_(4.2, "kg*cm**2"), Q_(1500, "kg*cm**2"))
    assert sel.mode == "S5"
    # Hand calculation: Z_h = 3600/2 = 1800 → f_s = 1.3 (E4); T_2max = 12 · 10 · 1.3 · 0.97 = 151.32 N·m.
    # Against T_2B (catalogs/gearboxes.csv, Beckhoff pages of each row's source): NPT035-10 220 → 0.688
    # (pass), TP010-10 126 → 1.201 (fail). Passing rows by T_2B: NPT035 220; NPS045 and NPT045 400 (tied
    # also on the worst utilization, 3000/4000 rpm = 0.75: by name); TP050 648; TP300 2280; TP500 4000
    # (T_2max 148.2 N·m at η 0.95). Failing, closest first: TP010 1.20; NPT025 151.32/90 = 1.68; TP004
    # /42 = 3.60; NPS015, NPT015 /35 = 4.32; NPT005 /13 = 11.6. Partial rows (SP+, NPS035) are not ranked.
    by_part = {c.part: c for c in sel.candidates()}
    t2b = {c.name: c for c in by_part["NPT035-10"].checks}["T_2B"]
    assert t2b.required.m_as("N*m") == pytest.approx(151.32)
    assert t2b.utilization == pytest.approx(151.32 / 220)
    assert [c.part for c in sel.candidates()] == [
        "NPT035-10", "NPS045-10", "NPT045-10", "TP050-10", "TP300-10", "TP500-10",
        "TP010-10", "NPT025-10", "TP004-10", "NPS015-10", "NPT015-10", "NPT005-10",
    ]
    assert {c.part for c in sel.candidates() if c.best_of_family} == {"NPT035-10", "NPS045-10", "TP050-10"}
    assert sel.selected == "NPT035-10"
    assert by_part["TP010-10"].reasons == ["T_2max <= T_2B: required 151.3 N·m > rated 126 N·m, 20.1 % over"]
    # E5: n_2max · i = 300 · 10 = 3000 rpm against n_1max 6000 → 0.5.
    n1max = {c.name: c for c in by_part["NPT035-10"].checks}["n_1max"]
    assert n1max.utilization == pytest.approx(0.5)
    # E1 (information in S5): n_2m · i = 240 · 10 = 2400 rpm > n_1N 2300 of NPT045-10 → fails but does not govern.
    n1n = {c.name: c for c in by_part["NPT045-10"].checks}["n_1N"]
    assert n1n.passes is False and n1n.governs is False and by_part["NPT045-10"].passes
    # E6: λ = (J_1 + J_L/i²)/J_motor = (0.93 + 1500/100)/4.2 = 3.7929, J_1 of the 19 mm hub.
    assert by_part["NPT035-10"].inertia_ratio == pytest.approx((0.93 + 15) / 4.2)
    assert by_part["NPT035-10"].J_1_hub == Value(19.0, "mm") and by_part["NPT035-10"].J_1 == Value(0.93, "kg*cm**2")
    # A row without J_1 has no ratio rather than a wrong one.
    no_j1 = rows.rows([rows.index("NPT035-10", "part")])
    no_j1.values = dict(no_j1.values, J_1=Q_([np.nan], "kg*cm**2"))
    assert select_gearbox(example_profile(), no_j1, Q_(12, "N*m"), Q_(4.2, "kg*cm**2"),
                          Q_(1500, "kg*cm**2")).candidates()[0].inertia_ratio is None


def s1_profile():
    # The example's motion with a 0.2 s pause: ED = 1.0/1.2 = 83 % → S1 (E3).
    return Profile.from_segments(
        [
            ("accel", Q_(0.2, "s"), Q_(150, "rpm"), Q_(60, "N*m")),
            ("const", Q_(0.6, "s"), Q_(300, "rpm"), Q_(20, "N*m")),
            ("decel", Q_(0.2, "s"), Q_(150, "rpm"), Q_(-45, "N*m")),
            ("pause", Q_(0.2, "s"), None, None),
        ]
    )


def test_s1_selection_by_hand(catalog):
    rows = rows_at_ratio(catalog, Q_(10, ""))
    sel = select_gearbox(s1_profile(), rows)
    assert sel.mode == "S1"
    assert sel.T_2max is None
    # E1: n_2m · i = 240 · 10 = 2400 rpm; E2: T_2m = 35.41 N·m. Rows at i = 10 (T_2N, n_1N):
    # NPT025 45, 3900 → 0.787, 0.615 pass; TP010 81, 3100 → 0.437, 0.774 pass; NPT035 110, 3000 →
    # 0.32, 0.8 pass; TP050 331, 2500 → 0.96 pass. Failing, closest first: NPT045 2300 rpm → 1.043;
    # NPS045 2000 → 1.2; TP004 27 N·m → 1.311; TP300 1700 rpm → 1.412; TP500 1500 → 1.6; NPS015 and
    # NPT015 19 N·m → 1.864 (by name); NPT005 6 N·m → 5.90. The smallest adequate T_2N is NPT025-10.
    assert [c.part for c in sel.candidates()] == [
        "NPT025-10", "TP010-10", "NPT035-10", "TP050-10",
        "NPT045-10", "NPS045-10", "TP004-10", "TP300-10", "TP500-10", "NPS015-10", "NPT015-10", "NPT005-10",
    ]
    assert sel.selected == "NPT025-10"
    rejected = sel.candidates()[4]
    assert not rejected.passes
    assert rejected.reasons == ["n_2m · i <= n_1N: required 2400 rpm > rated 2300 rpm, 4.35 % over"]
    assert rejected.unclear.startswith("n_1max/eta/L_PA/m/backlash")  # the row's doubt goes with it


def test_s5_without_peak_torque_ranks_but_selects_none(catalog):
    # Partial case (spec, second round): T_2max <= T_2B cannot be made without T_1B; the other S5
    # check n_2max · i <= n_1max is made (300 rpm · 10 = 3000 rpm against 6000 rpm for NPT035-10).
    sel = select_gearbox(example_profile(), rows_at_ratio(catalog, Q_(10, "")))
    assert sel.selected is None and [c.name for c in sel.not_made] == ["T_2B"]
    best = sel.candidates(1)[0]
    t2b = {c.name: c for c in best.checks}["T_2B"]
    assert t2b.passes is None and t2b.required is None and "motor.peak_torque" in t2b.not_made
    assert best.passes is None  # every check made passes; one could not be made
    assert {c.name: c for c in best.checks}["n_1max"].passes is True


def test_ratio_not_in_catalog(catalog):
    with pytest.raises(CalcError, match=r"no gearbox in catalog .* has ratio 9; its ratios are 3, 4, 5, 7, 8, 10"):
        rows_at_ratio(catalog, Q_(9, ""))
    with pytest.raises(CalcError, match="above zero"):
        rows_at_ratio(catalog, Q_(0, ""))


def test_formulas_by_hand():
    assert n_1(n_2=Q_(300, "rpm"), i=Q_(10, "")).m_as("rpm") == pytest.approx(3000)
    assert T_2max(T_1B=Q_(4, "N*m"), i=Q_(5, ""), f_s=Q_(2, ""), eta=Q_(0.9, "")).m_as("N*m") == pytest.approx(36)
    lam = inertia_ratio(J_1=Q_(1, "kg*cm**2"), J_L=Q_(400, "kg*cm**2"), i=Q_(10, ""), J_motor=Q_(2.5, "kg*cm**2"))
    assert lam.m_as("") == pytest.approx((1 + 4) / 2.5)


@settings(max_examples=60, deadline=None)
@given(st.floats(0.5, 50), st.floats(1.5, 100))
def test_inertia_ratio_reflects_with_i_squared(J_L, i):
    a = inertia_ratio(J_1=Q_(0, "kg*cm**2") + Q_(1e-12, "kg*cm**2"), J_L=Q_(J_L, "kg*cm**2"), i=Q_(i, ""),
                      J_motor=Q_(1, "kg*cm**2"))
    b = inertia_ratio(J_1=Q_(1e-12, "kg*cm**2"), J_L=Q_(J_L, "kg*cm**2"), i=Q_(2 * i, ""), J_motor=Q_(1, "kg*cm**2"))
    assert a.m_as("") == pytest.approx(4 * b.m_as(""), rel=1e-6)


def test_vectorized_selection_equals_part_by_part(catalog):
    # Checking all rows at once and checking each part alone must agree, row for row.
    rows = rows_at_ratio(catalog, Q_(10, ""))
    together = {c.part: c for c in select_gearbox(example_profile(), rows, Q_(12, "N*m")).candidates()}
    for k in range(len(rows)):
        alone = select_gearbox(example_profile(), rows.rows([k]), Q_(12, "N*m")).candidates()[0]
        assert alone.passes == together[alone.part].passes
        assert [c.utilization
                for c in alone.checks] == pytest.approx([c.utilization for c in together[alone.part].checks])


def test_rank_puts_published_rows_before_illustrative_ones():
    passes = np.array([True, True, False])
    size = np.array([50.0, 80.0, 10.0])
    worst = np.array([0.5, 0.5, 1.2])
    parts = np.array(["small-illustrative", "large-published", "failing"], dtype=object)
    order = rank(passes, size, worst, parts, later=np.array([True, False, True]))
    assert list(order) == [1, 0, 2]


def test_rank_rule():
    passes = np.array([False, True, True, False])
    size = np.array([50.0, 200.0, 100.0, 80.0])
    worst = np.array([1.5, 0.5, 0.9, 1.1])
    parts = np.array(["a", "b", "c", "d"], dtype=object)
    # Passing first, smallest size first (c before b); failing closest-to-passing first (d before a).
    assert list(rank(passes, size, worst, parts)) == [2, 1, 3, 0]


@settings(max_examples=200, deadline=None)
@given(
    rows=st.lists(
        st.tuples(st.booleans(), st.sampled_from([10.0, 20.0, 0.0, -0.0, np.inf, np.nan]),
                  st.sampled_from([0.5, 0.9, 1.2, 0.0, -0.0, np.inf, np.nan]), st.booleans(), st.integers(0, 40)),
        min_size=1,
        max_size=60,
    ),
)
def test_rank_breaks_ties_by_part_name_then_row_as_a_full_stable_sort_does(rows):
    # Few distinct keys, so most rows tie and the part name decides, then the row where a name repeats
    # (catalogs ranked together); names are sorted only within the tied runs, which must give the
    # order of a full stable sort with the name as its last key.
    passes, size, worst, illustrative, name = (np.array(c) for c in zip(*rows))
    parts = np.array([f"P{k:03d}" for k in name], dtype=object)
    passes, illustrative = passes.astype(bool), illustrative.astype(bool)
    full = np.lexsort((parts.astype(str), np.where(np.isnan(worst), np.inf, worst), np.where(passes, size, 0.0),
                       passes & illustrative, ~passes))
    assert list(rank(passes, size, worst, parts, later=illustrative)) == list(full)


def test_a_required_speed_equal_to_the_rating_passes(catalog):
    # n_2max · i = 300 rpm · 10 = 3000 rpm against n_1max = 3000 rpm: utilization 1, a pass, although
    # the product comes back from rad/s as 3000.0000000000005 rpm.
    rows = rows_at_ratio(catalog, Q_(10, ""))
    row = rows.rows([0])
    row.values["n_1max"] = Q_(np.array([3000.0]), "rpm")
    check = next(c for c in select_gearbox(example_profile(), row, Q_(12, "N*m")).checks if c.name == "n_1max")
    assert check.required[0].m_as("rpm") == pytest.approx(3000)
    assert check.passes[0]


@pytest.mark.parametrize("zh, shown", [(-1, "-1 1/h"), ([100, -1], "-1 1/h")])
def test_negative_cycles_per_hour_are_an_error(zh, shown):
    # A cycle count per hour is zero or more; below zero the table of E4 has no row.
    with pytest.raises(CalcError) as err:
        shock_factor(Q_(zh, "1/hour"))
    assert str(err.value) == (
        "cycles_per_hour: expected Z_h >= 0 1/h (the source's shock-factor table, S5 calculation 1, read with errata "
        f"E4), found {shown}"
    )
