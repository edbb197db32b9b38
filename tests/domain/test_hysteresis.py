"""Hysteresis loops: the model, the analysis of a measured loop (errata E12), reading loop files."""

import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.domain.hysteresis import (
    Loop,
    LoopModel,
    analyze_loop,
    backlash_from_loop,
    lost_motion_from_loop,
    model_for_part,
    read_loop,
    stiffness_from_slope,
)

from ..conftest import ROOT

SAMPLE = ROOT / "data" / "hysteresis-NPT035-10-generated.csv"
TP010 = LoopModel(Q_(23, "N*m/arcmin"), Q_(3, "arcmin"), Q_(81, "N*m"))


def test_source_definitions_by_hand():
    # Source, "Torsional Stiffness": applied torque / deflection: 40.5 N·m over 1.761 arcmin is 23 N·m/arcmin.
    slope = stiffness_from_slope(Delta_T=Q_(40.5, "N*m"), Delta_phi_twist=Q_(1.76087, "arcmin"))
    assert slope.m_as("N*m/arcmin") == pytest.approx(23.0, rel=1e-5)
    # Source, "Backlash" and "Lost Motion": maximum minus minimum deflection.
    assert backlash_from_loop(phi_max_0=Q_(1.5, "arcmin"),
                              phi_min_0=Q_(-1.5, "arcmin")).m_as("arcmin") == pytest.approx(3.0)
    assert lost_motion_from_loop(phi_max_3=Q_(1.77, "arcmin"),
                                 phi_min_3=Q_(-1.77, "arcmin")).m_as("arcmin") == pytest.approx(3.54)


def test_model_is_built_on_the_catalog_figures():
    m = model_for_part("TP010-10")  # catalogs/gearboxes.csv: C_t21 23 N·m/arcmin, backlash 3 arcmin, T_2N 81 N·m
    assert (m.stiffness.m_as("N*m/arcmin"), m.backlash.m_as("arcmin"), m.nominal_torque.m_as("N*m")) == (23, 3, 81)
    # The middle curve is odd, and the width at 0 N·m is 2 e(T_f) = the backlash by construction.
    t = Q_(np.linspace(-81, 81, 41), "N*m")
    e = m.middle_curve(t).m_as("arcmin")
    assert e == pytest.approx(-e[::-1])
    assert 2 * m.middle_curve(Q_(0.02 * 81, "N*m")).m_as("arcmin") == pytest.approx(3.0)
    # Lost motion of the model: 2 e(0.03 T_N + T_f); above the backlash by the band's twist (E12).
    assert m.lost_motion.m_as("arcmin") == pytest.approx(2 * m.middle_curve(Q_(0.05 * 81, "N*m")).m_as("arcmin"))
    assert 3.0 < m.lost_motion.m_as("arcmin") < 3.0 + 2 * (0.05 * 81 / 23) * 2


def test_noise_free_loop_analyses_back_to_the_catalog_figures():
    a = analyze_loop(TP010.loop(4000, uneven=False), Q_(81, "N*m"))
    assert a.stiffness_positive.m_as("N*m/arcmin") == pytest.approx(23, rel=1e-4)
    assert a.stiffness_negative.m_as("N*m/arcmin") == pytest.approx(23, rel=1e-4)
    assert a.backlash.m_as("arcmin") == pytest.approx(3, rel=2e-3)
    assert a.lost_motion.m_as("arcmin") == pytest.approx(TP010.lost_motion.m_as("arcmin"), rel=2e-3)
    assert [str(s) for s in a.steps()] == [
        "C_t = 23 N·m/arcmin", "C_t = 23 N·m/arcmin", "j_t = 2.999 arcmin", "phi_LM3 = 3.538 arcmin",
    ]


@settings(max_examples=25, deadline=None)
@given(
    twist_at_nominal=st.floats(min_value=0.8, max_value=8.0),  # T_N / C [arcmin], a gearbox's wind-up
    nominal=st.floats(min_value=5.0, max_value=3000.0),  # T_N [N·m]
    backlash_over_twist=st.floats(min_value=0.3, max_value=4.0),
    seed=st.integers(min_value=0, max_value=2**31),
)
def test_noisy_uneven_loop_is_analysed_back_to_its_parameters(twist_at_nominal, nominal, backlash_over_twist, seed):
    stiffness = nominal / twist_at_nominal
    backlash = backlash_over_twist * twist_at_nominal
    model = LoopModel(Q_(stiffness, "N*m/arcmin"), Q_(backlash, "arcmin"), Q_(nominal, "N*m"))
    # A rig's noise: 0.1 % of T_N on the torque, 0.5 % of the wind-up at T_N on the twist.
    loop = model.loop(3000, noise_torque=Q_(0.001 * nominal, "N*m"), noise_twist=Q_(0.005 * twist_at_nominal, "arcmin"),
                      seed=seed)
    a = analyze_loop(loop, Q_(nominal, "N*m"))
    for c in (a.stiffness_positive, a.stiffness_negative):
        assert c.m_as("N*m/arcmin") == pytest.approx(stiffness, rel=0.03)
    tolerance = 0.03 * twist_at_nominal  # 3 % of the wind-up at nominal torque
    assert a.backlash.m_as("arcmin") == pytest.approx(backlash, abs=tolerance)
    assert a.lost_motion.m_as("arcmin") == pytest.approx(model.lost_motion.m_as("arcmin"), abs=tolerance)


def test_a_recording_that_starts_and_ends_unloaded():
    # The source's procedure as a rig may record it: 0 -> +T_N -> 0 -> -T_N -> 0. The unloaded start
    # lies inside the loop and must not count; the last ramp ends at 0 N·m.
    t = np.concatenate([np.linspace(0, 81, 500), np.linspace(81, -81, 1000)[1:], np.linspace(-81, 0, 500)[1:]])
    loop = Loop(Q_(t, "N*m"), TP010.twist(Q_(t, "N*m")), source="rig")
    a = analyze_loop(loop, Q_(81, "N*m"))
    assert a.backlash.m_as("arcmin") == pytest.approx(3, rel=0.01)
    assert a.stiffness.m_as("N*m/arcmin") == pytest.approx(23, rel=1e-3)


def test_the_shipped_sample_is_what_its_header_says():
    loop = read_loop(SAMPLE)
    assert loop.comments[0].startswith("GENERATED sample, not a measurement")
    call = 'model_for_part("NPT035-10").loop(2000, noise_torque=Q_(0.1, "N*m"), noise_twist=Q_(0.02, "arcmin"), seed=7)'
    assert loop.comments[1] == f"Call: {call}"
    again = model_for_part("NPT035-10").loop(2000, noise_torque=Q_(0.1, "N*m"), noise_twist=Q_(0.02, "arcmin"), seed=7)
    assert loop.torque.m_as("N*m") == pytest.approx(again.torque.m_as("N*m"), abs=1e-5, rel=1e-5)
    assert loop.twist.m_as("arcmin") == pytest.approx(again.twist.m_as("arcmin"), abs=1e-5, rel=1e-5)
    a = analyze_loop(loop, Q_(110, "N*m"))  # NPT035-10: C_t21 22 N·m/arcmin, backlash 8 arcmin
    assert a.stiffness.m_as("N*m/arcmin") == pytest.approx(22, rel=0.01)
    assert a.backlash.m_as("arcmin") == pytest.approx(8, rel=0.01)


def test_a_million_samples_are_analysed_fast():
    loop = TP010.loop(10**6, noise_torque=Q_(0.08, "N*m"), noise_twist=Q_(0.02, "arcmin"), seed=1)
    start = time.perf_counter()
    a = analyze_loop(loop, Q_(81, "N*m"))
    elapsed = time.perf_counter() - start
    assert a.stiffness.m_as("N*m/arcmin") == pytest.approx(23, rel=0.002)
    assert a.backlash.m_as("arcmin") == pytest.approx(3, rel=0.01)
    # The target is 0.5 s; the bound leaves room for a busy shared machine.
    assert elapsed < 2.0


def write(tmp_path, body, header="torque [N*m],twist [arcmin]", name="loop.csv"):
    path = tmp_path / name
    path.write_text(f"# a measured loop\n{header}\n{body}")
    return path


def rows(t, phi):
    return "\n".join(f"{a:.6g},{b:.6g}" for a, b in zip(t, phi)) + "\n"


def test_loop_file_in_other_units(tmp_path):
    loop = TP010.loop(800, uneven=False)
    t, phi = loop.torque.m_as("lbf*in"), loop.twist.m_as("deg")
    a = analyze_loop(read_loop(write(tmp_path, rows(t, phi), header="torque [lbf*in],twist [deg]")), Q_(81, "N*m"))
    assert a.stiffness.m_as("N*m/arcmin") == pytest.approx(23, rel=1e-3)


def test_bad_loops_are_one_clear_error(tmp_path):
    t = np.linspace(0, 81, 100)
    one_way = read_loop(write(tmp_path, rows(t, t / 23)))
    with pytest.raises(CalcError,
                       match=r"loop.csv: the loop is loaded in one direction only \(torque from 0 to 81 N·m\)"):
        analyze_loop(one_way, Q_(81, "N*m"))
    with pytest.raises(CalcError, match="expected a loop of at least 20 samples, found 5"):
        analyze_loop(Loop(Q_(np.array([0, 80, -80, 80, 0.0]), "N*m"), Q_(np.zeros(5), "arcmin"), source="short"),
                     Q_(81, "N*m"))
    # Loaded only to 40 % of the nominal torque: no points in the 50 % to 100 % band.
    low = TP010.loop(1000)
    with pytest.raises(CalcError,
                       match=r"expected at least 3 samples loading in the positive direction between 50 % and 100 % of "
                             r"the nominal torque \(100 to 200 N·m\), found 0"):
        analyze_loop(low, Q_(200, "N*m"))
    with pytest.raises(CalcError, match="nominal torque: expected a torque"):
        analyze_loop(low, Q_(81, "N*m/arcmin"))
    # Loaded up and down once, never back: 0 N·m is passed only while the torque falls.
    t = np.concatenate([np.linspace(0, 81, 400), np.linspace(81, -81, 800)[1:]])
    half = Loop(Q_(t, "N*m"), TP010.twist(Q_(t, "N*m")), source="half loop")
    with pytest.raises(CalcError, match="half loop: expected the loop to pass 0 N·m in both directions, found 1 pass$"):
        analyze_loop(half, Q_(81, "N*m"))


@pytest.mark.parametrize(
    "body, header, fragment",
    [
        ("0,0\n1,abc\n", None, "loop.csv, row 4, column twist: expected a number, found 'abc'"),
        ("0,0\n,1\n", None, "loop.csv, row 4, column torque: expected a number, found an empty cell"),
        ("0,0\n\n1,1\n", None, "loop.csv, row 4, column torque: expected a number, found an empty cell"),
        ("0,0\n1,1,2\n", None, "rows must have the header's 2 cells (row 4 has 3)"),
        ("0,0\n", "torque [N*m],twist [1]",
         "column twist: expected a unit of angle such as \"3 arcmin\", found '1', which is a bare number"),
        ("0,0\n", "torque [N*m/arcmin],twist [arcmin]", "column torque: expected a unit of torque"),
        ("0,0\n", "torque [N*m],angle [arcmin]", "row 2: expected a column 'twist [unit]'"),
        ("", None, "expected rows of data after the header (row 2), found none"),
    ],
)
def test_bad_loop_files_name_file_row_and_column(tmp_path, body, header, fragment):
    path = write(tmp_path, body, header=header or "torque [N*m],twist [arcmin]")
    with pytest.raises(CalcError) as err:
        read_loop(path)
    assert fragment in str(err.value)
    assert str(path) in str(err.value)


@pytest.mark.parametrize(
    "kwargs, fragment",
    [
        (dict(stiffness=Q_(0, "N*m/arcmin")), "stiffness: expected a stiffness above zero"),
        (dict(stiffness=Q_(23, "N*m")), "which is a torque (its unit must carry the angle, errata E15)"),
        (dict(backlash=Q_(3, "")), "which is a bare number (its unit must carry the angle, errata E15)"),
        (dict(backlash=Q_(0.1, "arcmin")), "more than the backlash"),
        (dict(backlash=Q_(3, "arcmin"), friction=0.0), "needs friction above zero"),
        (dict(backlash=Q_(-1, "arcmin")), "loop model: backlash: expected an angle of zero or more, found -1 arcmin"),
        (dict(nominal_torque=Q_(0, "N*m")), "loop model: nominal_torque: expected a torque above zero, found 0 "),
        (dict(friction=1.0), "loop model: friction: expected a share from 0 to below 1, found 1.0"),
        (dict(soft_share=-0.1), "loop model: soft_share: expected a share from 0 to below 1, found -0.1"),
        (dict(soft_width=0.3), "loop model: soft_width: expected a share above 0 and below 0.25, found 0.3"),
        (dict(gap_width=0.0), "loop model: gap_width: expected a share above 0 and below 0.25, found 0.0"),
    ],
)
def test_bad_models_are_one_clear_error(kwargs, fragment):
    args = dict(stiffness=Q_(23, "N*m/arcmin"), backlash=Q_(3, "arcmin"), nominal_torque=Q_(81, "N*m")) | kwargs
    with pytest.raises(CalcError) as err:
        LoopModel(**args)
    assert fragment in str(err.value)


def test_a_backlash_free_part_without_friction():
    m = LoopModel(Q_(50, "N*m/arcmin"), Q_(0, "arcmin"), Q_(100, "N*m"), friction=0.0)
    a = analyze_loop(m.loop(2000, uneven=False), Q_(100, "N*m"))
    assert a.backlash.m_as("arcmin") == pytest.approx(0, abs=1e-3)
    assert a.stiffness.m_as("N*m/arcmin") == pytest.approx(50, rel=1e-3)


@pytest.mark.parametrize("samples", [1, 2.5, "100"])
def test_a_loop_needs_a_whole_number_of_samples(samples):
    with pytest.raises(CalcError) as err:
        TP010.loop(samples)
    assert str(err.value) == f"loop model: samples: expected a whole number of 2 or more, found {samples!r}"


def test_bad_recordings_and_nominal_torques_are_one_clear_error():
    loop = TP010.loop(1000, uneven=False)
    with pytest.raises(CalcError, match="^generated loop: nominal torque: expected a torque above zero, found 0 "):
        analyze_loop(loop, Q_(0, "N*m"))
    # One sample lost by the rig (NaN): the least-squares lines would all be NaN.
    twist = loop.twist.m_as("arcmin").copy()
    twist[5] = np.nan
    with pytest.raises(CalcError) as err:
        analyze_loop(Loop(loop.torque, Q_(twist, "arcmin"), source="rig.csv"), Q_(81, "N*m"))
    assert str(err.value) == "rig.csv: expected finite torque and twist samples, found NaN or infinity"
    # The twist recorded with the wrong sign: it falls as the torque rises, no stiffness is positive.
    with pytest.raises(CalcError) as err:
        analyze_loop(Loop(loop.torque, -loop.twist, source="rig.csv"), Q_(81, "N*m"))
    assert str(err.value) == (
        "rig.csv: the twist does not rise with the torque between 50 % and 100 % of the nominal torque in the positive "
        "direction"
    )


@pytest.mark.parametrize("column, edit", [("C_t21", "7500,97,3,,0.4,"), ("backlash", "7500,97,,23,0.4,")])
def test_a_part_without_catalog_figures_has_no_loop_model(tmp_path, column, edit):
    # TP010-10 (row 11 of the shipped catalog) with its stiffness or backlash cell left empty.
    path = tmp_path / "gearboxes.csv"
    path.write_text((ROOT / "catalogs" / "gearboxes.csv").read_text().replace("7500,97,3,23,0.4,", edit))
    with pytest.raises(CalcError) as err:
        model_for_part("TP010-10", catalog=str(path))
    assert str(err.value) == (
        f"{path}, row 11 (TP010-10), column {column}: expected a value for the loop model, found an empty cell"
    )
