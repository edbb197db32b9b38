"""The servo drive (calc.domain.drive): the drive catalog as published, the motor current, the
braking energy against the DC link and the resistor, and the winding's first-order model against
its closed form; hand calculations written out, laws as hypothesis properties, bad catalog rows."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import Q_
from calc.core.errors import CalcError
from calc.data.catalog import CATALOG_DIR, load_catalog
from calc.domain.drive import (
    _longest_runs_above,
    E_C, P_R_avg, P_R_peak, SCHEMA, I_ph, braking_events, k_T_derived, longest_run, resistor_energies,
    select_drives, square_cycle_peak, voltage_class, winding_temperature,
)

DRIVES = CATALOG_DIR / "drives.csv"


def test_the_catalog_holds_the_published_rows():
    cat = load_catalog(DRIVES, SCHEMA)
    assert len(cat) == 188  # every published row (SOURCES.md, drives.csv: 188 rows)
    assert int((~cat.partial).sum()) == 42  # "Only the 42 rows with partial = no can be used for a current check"
    row = cat.index("TGZ-S-230-5/15", "test")
    # TG Drives TGZ datasheet: 5 A continuous, 15 A peak for 5 s, 1x230 V AC (DC link 325 V)
    assert cat["I_N"][row].m_as("A") == 5 and cat["I_max"][row].m_as("A") == 15
    assert cat["t_max"][row].m_as("s") == 5 and cat["U_DC"][row].m_as("V") == 325
    row = cat.index("AKD-x00306 (3x230 V AC)", "test")
    # Kollmorgen AKD: 940 µF, 20 Ws stored in the DC link at 230 V
    assert cat["C_DC"][row].m_as("uF") == 940 and cat["E_C"][row].m_as("J") == 20
    assert cat.partial[row]


def test_a_row_with_peak_below_continuous_current_names_file_row_and_column(tmp_path):
    head = DRIVES.read_text(encoding="utf-8").splitlines()[0]
    row = "X-1,Maker,F,230 V AC,325,10,8,5,,,,,,,,,a datasheet"
    path = tmp_path / "drives.csv"
    path.write_text(f"{head}\n{row}\n", encoding="utf-8")
    with pytest.raises(CalcError) as err:
        load_catalog(path, SCHEMA)
    assert str(path) in str(err.value) and "row 2 (X-1)" in str(err.value) and "I_max" in str(err.value)


def test_motor_current_by_hand():
    # SGM7J-02A (Yaskawa Σ-7 manual p. 4-4): k_T = 0.444 N·m/A rms; 1.061 N·m -> 1.061 / 0.444 = 2.3896 A
    assert I_ph(T_1=Q_(1.061, "N*m"), k_T=Q_(0.444, "N*m/A")).m_as("A") == pytest.approx(2.38964, rel=1e-5)
    # AM8031-wCyz (Beckhoff): M_0 = 1.37 N·m, I_0 = 2.95 A -> k_T = 0.4644 N·m/A
    assert k_T_derived(M_0=Q_(1.37, "N*m"), I_0=Q_(2.95, "A")).m_as("N*m/A") == pytest.approx(0.464407, rel=1e-5)


def test_dc_link_energy_and_resistor_power_by_hand():
    # 940 µF from 325 V to 390 V: ½ · 940e-6 · (390² − 325²) = ½ · 940e-6 · 46475 = 21.843 J
    E = E_C(C_DC=Q_(940, "uF"), U_on=Q_(390, "V"), U_DC=Q_(325, "V"))
    assert E.m_as("J") == pytest.approx(21.84325, rel=1e-9)
    # 390 V on 33 Ω: 390² / 33 = 4609.09 W
    assert P_R_peak(U_on=Q_(390, "V"), R_br=Q_(33, "ohm")).m_as("W") == pytest.approx(4609.0909, rel=1e-7)
    assert P_R_avg(E_R=Q_(22, "J"), t_cycle=Q_(2, "s")).m_as("W") == pytest.approx(11.0)


def test_a_stop_whose_energy_exceeds_the_dc_link():
    # A stop from 3000 rpm in 0.1 s of 5 kg·cm² total, the torque ramping the speed down linearly:
    # E = ½ J ω² = ½ · 5e-4 · (314.159)² = 24.674 J, sampled as 100 steps of constant power.
    J, w0, t_d, n = 5e-4, 3000 * 2 * math.pi / 60, 0.1, 100
    dt = np.full(n, t_d / n)
    w = w0 * (1 - (np.arange(n) + 0.5) / n)  # mid-sample speed
    torque = -J * w0 / t_d
    power = np.concatenate(([0.0], torque * w, [0.0]))
    events = braking_events(np.concatenate(([1.2], dt, [0.7])), power)
    assert len(events) == 1
    e = events[0]
    assert e.start == pytest.approx(1.2) and e.duration == pytest.approx(0.1)
    assert e.energy == pytest.approx(0.5 * J * w0**2, rel=1e-9)  # 24.674 J
    # The AKD-x00306's DC link absorbs 20 J: 4.674 J are left for the resistor
    assert resistor_energies(events, 20.0)[0] == pytest.approx(24.674011 - 20.0, rel=1e-6)
    # A DC link of 30 J takes it all
    assert resistor_energies(events, 30.0)[0] == 0.0


def test_a_resistor_too_weak_on_average():
    # Two stops of 60 J per 2 s cycle, DC link 20 J: 2 · (60 − 20) = 80 J per cycle, 40 W average,
    # against a resistor rated 30 W continuous: utilization 40 / 30 = 1.333.
    dt = np.array([0.5, 0.2, 0.8, 0.2, 0.3])
    power = np.array([300.0, -300.0, 100.0, -300.0, 0.0])
    E_R = resistor_energies(braking_events(dt, power), 20.0).sum()
    assert E_R == pytest.approx(80.0)
    avg = P_R_avg(E_R=Q_(E_R, "J"), t_cycle=Q_(dt.sum(), "s")).m_as("W")
    assert avg == pytest.approx(40.0) and avg / 30.0 > 1


def test_the_winding_model_against_its_closed_form_for_a_square_cycle():
    # u = (2 M_0 / M_0)² = 4 for 20 s, then rest for 40 s, T_th = 30 min:
    # θ_max = 4 (1 − e^(−20/1800)) / (1 − e^(−60/1800)) = 4 · 0.01104963 / 0.03278386 = 1.348175
    T_th = 1800.0
    closed = 4 * (1 - math.exp(-20 / T_th)) / (1 - math.exp(-60 / T_th))
    assert square_cycle_peak(4.0, 20.0, 60.0, T_th) == pytest.approx(closed, rel=1e-12)
    assert closed == pytest.approx(1.348175, rel=1e-6)
    t, theta = winding_temperature(np.array([20.0, 40.0]), np.array([4.0, 0.0]), T_th)
    assert theta.max() == pytest.approx(closed, rel=1e-12)
    assert theta[0] == pytest.approx(theta[2], rel=1e-12)  # periodic: the cycle ends where it started
    assert t[-1] == pytest.approx(120.0)  # two cycles


@settings(deadline=None, max_examples=40)
@given(u=st.floats(0.1, 9.0), share=st.floats(0.05, 0.95), t_cycle=st.floats(1.0, 600.0),
       T_th=st.floats(60.0, 7200.0))
def test_the_periodic_peak_lies_between_the_mean_load_and_the_load(u, share, t_cycle, T_th):
    # The square cycle's peak lies above its mean load u · share and below u (the law of a first-order lag).
    peak = square_cycle_peak(u, share * t_cycle, t_cycle, T_th)
    assert u * share * (1 - 1e-9) <= peak <= u * (1 + 1e-9)
    t, theta = winding_temperature(np.array([share * t_cycle, (1 - share) * t_cycle]), np.array([u, 0.0]), T_th)
    assert theta.max() == pytest.approx(peak, rel=1e-9)


def test_longest_run_wraps_round_the_cycle():
    # above at the end (4 s) and the start (1 s) of the cycle: one run of 5 s
    assert longest_run(np.array([1.0, 2.0, 3.0, 4.0]), np.array([True, False, False, True])) == 5.0
    assert longest_run(np.array([1.0, 2.0]), np.array([False, False])) == 0.0
    assert longest_run(np.array([1.0, 2.0]), np.array([True, True])) == 3.0


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.floats(1e-3, 10.0), st.sampled_from([0.0, 1.0, 2.5, 4.0])), min_size=1, max_size=20),
       st.lists(st.sampled_from([0.5, 1.0, 2.5, 3.0, 9.0]), max_size=12))
def test_runs_above_each_rating_are_each_drives_longest_run(samples, ratings):
    # Computed once per distinct rating, then given to every drive of it: each drive's run is
    # longest_run of its own rating, in the catalog's order.
    dt, current = (np.array(x) for x in zip(*samples))
    I_N = np.array(ratings, dtype=float)
    expected = [longest_run(dt, current > x) for x in I_N]
    np.testing.assert_array_equal(_longest_runs_above(dt, current, I_N), np.array(expected, dtype=float))


def test_voltage_classes():
    assert voltage_class(283.0) == voltage_class(325.0) == "200-240 V AC"
    assert voltage_class(565.0) == voltage_class(679.0) == "380-480 V AC"
    assert voltage_class(220.0) is None


def test_drives_ranked_smallest_adequate_first():
    # A motor of the 230 V class drawing 2.4 A peak and about 1 A rms: the smallest adequate drives
    # have I_N = 3 A (Moog G394-030, 3 A / 9 A); 565 V drives are rejected for the voltage class.
    cat = load_catalog(DRIVES, SCHEMA)
    dt = np.array([0.1, 0.4, 0.1, 0.4])
    current = np.array([2.4, 0.2, 1.6, 0.0])
    rms = float(np.sqrt((current**2 * dt).sum() / dt.sum()))
    sel = select_drives(cat, rms, 2.4, dt, current, 283.0)
    assert sel.selected.startswith("G394-030")
    best = sel.candidates(3)
    assert all(c.passes for c in best) and best[0].checks[0].rated.m_as("A") == 3.0
    rejected = sel.candidate(int(np.flatnonzero(sel.catalog.parts == "TGZ-S-400-3/9")[0]))
    assert rejected.passes is False and any("U_DC <= 400 V" in r for r in rejected.reasons)
    # A motor drawing 20 A rms: no 230 V drive carries it; each rejection says why
    sel = select_drives(cat, 20.0, 40.0, dt, current * 16, 283.0)
    assert sel.selected is None
    assert all(c.reasons for c in sel.candidates())
