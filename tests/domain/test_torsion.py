"""Torsional modes of the drive train (calc.domain.torsion): the chain lumped from its members, its natural
frequencies against the source's two-mass formula (E7) and a three-mass hand calculation, the laws
of the eigenproblem, and the chain in the coupling selection and the case's results."""

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.data.catalog import load_catalog, resolve
from calc.domain.coupling import SCHEMA, DriveTrain, f_e, select_coupling
from calc.domain.gearbox import SCHEMA as GEARBOX_SCHEMA
from calc.sections import evaluate
from calc.sections.case import read_case
from calc.domain.torsion import (
    TrainMember, gearbox_at_input, inertia_at_output, load_at_input, lumped, natural_frequencies,
)

from ..conftest import DERIVED_EXAMPLE, EXAMPLE as EXAMPLE_CASE

KG_CM2 = "kg*cm**2"


def test_two_masses_give_the_source_formula():
    # The source's two-mass system (E7) is the chain of two masses: AKD-30 (25 000 N·m/rad) between
    # J_A = 4.7 kg·cm² and J_L = 16.43 kg·cm² gives f_e = 1316.35 Hz (tests/domain/test_coupling.py).
    J_A, J_L, C = Q_(4.7, KG_CM2), Q_(16.43, KG_CM2), Q_(25_000, "N*m/rad")
    modes = natural_frequencies(Q_([4.7, 16.43], KG_CM2), Q_([25_000], "N*m/rad"))
    assert modes.m_as("Hz") == pytest.approx([f_e(C_T=C, J_A=J_A, J_L_coupling=J_L).m_as("Hz")], rel=1e-12)
    assert modes.m_as("Hz") == pytest.approx([1316.35], abs=0.01)


def test_three_masses_by_hand():
    # The example axis seen from the gearbox input (cases/indexing-table.toml, AKD-30, NPT035-10):
    #   J_1 = 4.2 + 1/2 = 4.7 kg·cm² (motor and half the coupling),
    #   J_2 = 1/2 + 0.93 = 1.43 kg·cm² (half the coupling and the gearbox's J_1),
    #   J_3 = 1500 / 10² = 15 kg·cm² (the table reflected to the input);
    #   C_1 = 25 000 N·m/rad (AKD-30), C_2 = 22 N·m/arcmin / 10² = 22 · 10800/π / 100 = 756.304 N·m/rad.
    # For three masses, free at both ends, det(K - ω² J) = 0 reduces to ω² (ω⁴ - b ω² + c) = 0 with
    #   b = C_1 (1/J_1 + 1/J_2) + C_2 (1/J_2 + 1/J_3)
    #     = 25 000 · (2127.66 + 6993.01) + 756.304 · (6993.01 + 666.667) = 2.28017e8 + 5.79304e6 = 2.33810e8 1/s²,
    #   c = C_1 C_2 (J_1 + J_2 + J_3) / (J_1 J_2 J_3) = 25 000 · 756.304 · 2.113e-3 / 1.00815e-10 = 3.96288e14 1/s⁴;
    #   ω² = (b ∓ √(b² - 4c)) / 2 = (2.33810e8 ∓ 2.30395e8) / 2 = 1.70738e6 and 2.32102e8 1/s²;
    #   f = √ω² / 2π = 1306.7 / 2π = 207.96 Hz and 15 234.9 / 2π = 2424.71 Hz.
    modes = natural_frequencies(Q_([4.7, 1.43, 15], KG_CM2), Q_([25_000, 22 * 10800 / math.pi / 100], "N*m/rad"))
    assert modes.m_as("Hz") == pytest.approx([207.96, 2424.71], abs=0.01)
    # The same quadratic in closed form, as the gearbox's drive-train bound evaluates it.
    from calc.domain.torsion import first_mode_of_three

    f_1 = first_mode_of_three(J_a=Q_(4.7, KG_CM2), J_b=Q_(1.43, KG_CM2), J_c=Q_(15, KG_CM2),
                              C_ab=Q_(25_000, "N*m/rad"), C_bc=Q_(22, "N*m/arcmin") / 100)
    assert f_1.m_as("Hz") == pytest.approx(207.96, abs=0.01)


def test_reflection_formulas_by_hand():
    # 1500 kg·cm² / 10² = 15 kg·cm²; 22 N·m/arcmin = 75 630.4 N·m/rad, / 10² = 756.304 N·m/rad;
    # 4.2 kg·cm² · 10² = 420 kg·cm².
    assert load_at_input(J_L=Q_(1500, KG_CM2), i=10).m_as(KG_CM2) == pytest.approx(15)
    assert gearbox_at_input(C_t21=Q_(22, "N*m/arcmin"), i=10).m_as("N*m/rad") == pytest.approx(756.304, abs=1e-3)
    assert inertia_at_output(J_in=Q_(4.2, KG_CM2), i=10).m_as(KG_CM2) == pytest.approx(420)


def test_lumping_adds_the_masses_between_springs():
    chain = lumped([
        TrainMember("motor", Q_(4.2, KG_CM2)),
        TrainMember("coupling", Q_(0.5, KG_CM2), Q_(25_000, "N*m/rad"), Q_(0.5, KG_CM2)),
        TrainMember("gearbox", Q_(0.93, KG_CM2), Q_(756.304, "N*m/rad")),
        TrainMember("load", Q_(15, KG_CM2)),
    ])
    assert chain.masses == ("motor + coupling", "coupling + gearbox",
                            "load") and chain.springs == ("coupling", "gearbox")
    assert chain.inertias.m_as(KG_CM2) == pytest.approx([4.7, 1.43, 15])
    assert chain.natural_frequencies().m_as("Hz") == pytest.approx([207.96, 2424.71], abs=0.01)
    # A direct drive has no gearbox spring: its J_1 and the load are one mass.
    rigid = lumped([TrainMember("motor", Q_(4.2, KG_CM2)),
                    TrainMember("coupling", Q_(0.5, KG_CM2), Q_(25_000, "N*m/rad"), Q_(0.5, KG_CM2)),
                    TrainMember("load", Q_(15.93, KG_CM2))])
    assert rigid.masses == ("motor + coupling", "coupling + load")
    assert rigid.natural_frequencies().m_as("Hz") == pytest.approx([1316.35], abs=0.01)


def test_candidates_at_once_and_missing_values():
    # One row per candidate; a row whose catalog leaves a value empty gets NaN, the others their modes.
    J = Q_([[4.7, 16.43], [4.7, np.nan], [5.2, 16.93]], KG_CM2)
    C = Q_([[25_000], [25_000], [np.nan]], "N*m/rad")
    f = natural_frequencies(J, C).m_as("Hz")
    assert f[0, 0] == pytest.approx(1316.35, abs=0.01) and np.isnan(f[1:, 0]).all()


@pytest.mark.parametrize(
    "inertias, stiffnesses, message",
    [
        (Q_([1.0, 2.0], KG_CM2), Q_([1.0, 2.0], "N*m/rad"), "expected one spring fewer than masses"),
        (Q_([1.0], KG_CM2), Q_(np.zeros(0), "N*m/rad"), "a chain needs two masses and a spring"),
        (Q_([1.0, 2.0], KG_CM2), Q_([1.0], "N*m"), "drive train: stiffnesses: expected a stiffness"),
        (Q_([1.0, -2.0], KG_CM2), Q_([1.0], "N*m/rad"), "expected inertias and stiffnesses above zero"),
    ],
)
def test_bad_chains_are_named(inertias, stiffnesses, message):
    with pytest.raises(CalcError, match=message):
        natural_frequencies(inertias, stiffnesses)


def test_a_chain_that_ends_in_a_spring_is_refused():
    with pytest.raises(CalcError, match=r"drive train: the chain ends in a spring \(gearbox\)"):
        lumped([TrainMember("motor", Q_(4.2, KG_CM2)), TrainMember("gearbox", Q_(0.93, KG_CM2), Q_(756, "N*m/rad"))])


positive = st.floats(min_value=0.1, max_value=1e3, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(st.lists(positive, min_size=2, max_size=5), st.data())
def test_a_stiffer_spring_raises_every_mode(inertias, data):
    # K grows by a positive semi-definite matrix, so no root of K φ = ω² J φ falls.
    springs = data.draw(st.lists(positive, min_size=len(inertias) - 1, max_size=len(inertias) - 1))
    k = data.draw(st.integers(0, len(springs) - 1))
    factor = data.draw(st.floats(1.0, 10.0))
    stiffer = list(springs)
    stiffer[k] *= factor
    J = Q_(inertias, KG_CM2)
    before = natural_frequencies(J, Q_(springs, "N*m/rad")).m_as("Hz")
    after = natural_frequencies(J, Q_(stiffer, "N*m/rad")).m_as("Hz")
    assert np.all(after >= before * (1 - 1e-9))


@settings(max_examples=60, deadline=None)
@given(st.lists(positive, min_size=2, max_size=5), st.data(), st.floats(1.5, 100))
def test_reflection_through_a_ratio_keeps_the_modes(inertias, data, i):
    # Every inertia and stiffness divided by i² (the chain seen through a gearbox): the same modes.
    springs = data.draw(st.lists(positive, min_size=len(inertias) - 1, max_size=len(inertias) - 1))
    J, C = Q_(inertias, KG_CM2), Q_(springs, "N*m/arcmin")
    seen = natural_frequencies(
        load_at_input(J_L=J, i=i), gearbox_at_input(C_t21=C, i=i)
    ).m_as("Hz")
    # The eigensolver's error is relative to the highest mode (double precision, squared frequencies):
    # a low mode far below it is held to 1e-9 of the highest.
    expected = natural_frequencies(J, C).m_as("Hz")
    assert seen == pytest.approx(expected, rel=1e-9, abs=1e-9 * expected.max())
    # Only the output side referred to the input (J_L / i², C_t21 / i²) against the input side
    # referred to the output (J · i²): the same train, the same modes.
    J_in, J_out, C_out = Q_(inertias[0], KG_CM2), Q_(inertias[1:], KG_CM2), C
    at_input = natural_frequencies(np.concatenate([[J_in.m_as(KG_CM2)],
                                                   load_at_input(J_L=J_out, i=i).m_as(KG_CM2)]) * Q_(1, KG_CM2),
                                   gearbox_at_input(C_t21=C_out, i=i))
    at_output = natural_frequencies(np.concatenate([[inertia_at_output(J_in=J_in, i=i).m_as(KG_CM2)],
                                                    J_out.m_as(KG_CM2)]) * Q_(1, KG_CM2), C_out)
    assert at_input.m_as("Hz") == pytest.approx(at_output.m_as("Hz"), rel=1e-9, abs=1e-9 * at_output.m_as("Hz").max())


# --- In the coupling selection and the case ----------------------------------------------------

CATALOG = load_catalog(resolve("couplings", None, "catalog"), SCHEMA)
BELLOWS = CATALOG.rows(CATALOG.text["type"] == "bellows")
ARGS = dict(accel_torque=Q_(12, "N*m"), drive_inertia=Q_(4.2, KG_CM2), load_inertia=Q_(15.93, KG_CM2),
            shaft_1="19 mm k6", shaft_2="16 mm h7", speed=Q_(3000, "rpm"))
TRAIN = DriveTrain((TrainMember("motor", Q_(4.2, KG_CM2)),),
                   (TrainMember("gearbox", Q_(0.93, KG_CM2), gearbox_at_input(C_t21=Q_(22, "N*m/arcmin"), i=10)),
                    TrainMember("load", Q_(15, KG_CM2))),
                   shaft="the gearbox input")


def test_the_gearbox_spring_governs_where_the_chain_is_complete():
    # f_er = 150 Hz: 2 f_er = 300 Hz. AKD-30 alone passes f_e = 1316 Hz; in the chain f_1 = 207.96 Hz
    # (test_three_masses_by_hand), 44.3 % short, and no bellows coupling passes.
    s = select_coupling(BELLOWS, excitation_frequency=Q_(150, "Hz"), drive_train=TRAIN, **ARGS)
    row = BELLOWS.index("AKD-30", "part")
    assert s.modes[row].m_as("Hz") == pytest.approx([207.96, 2424.71], abs=0.01)
    assert s.selected is None
    assert "2 f_er <= f_1: required 300 Hz > rated 208 Hz, 44.3 % over" in s.reasons(row)
    # At f_er = 100 Hz (the example's): 200 Hz <= 207.96 Hz, AKD-30 chosen.
    s = select_coupling(BELLOWS, excitation_frequency=Q_(100, "Hz"), drive_train=TRAIN, **ARGS)
    assert s.selected == "AKD-30"
    check = next(c for c in s.checks if c.name == "f_1").at(row)
    assert check.governs and check.passes and check.utilization == pytest.approx(200 / 207.963, rel=1e-5)


def test_an_incomplete_chain_informs_and_names_what_is_missing():
    train = DriveTrain(TRAIN.drive, (TrainMember("load", Q_(15.93, KG_CM2)),),
                       missing=("the gearbox's torsional stiffness C_t21",))
    s = select_coupling(BELLOWS, excitation_frequency=Q_(700, "Hz"), drive_train=train, **ARGS)
    row = BELLOWS.index("AKD-30", "part")
    check = next(c for c in s.checks if c.name == "f_1").at(row)
    # The two-mass chain: f_1 = f_e = 1316 Hz < 1400 Hz; reported, not governing (f_e itself still fails).
    assert check.governs is False and check.passes is False
    assert check.rated.m_as("Hz") == pytest.approx(1316.35, abs=0.01)
    assert not any("f_1" in r for r in s.reasons(row))
    assert any("the case does not give the gearbox's torsional stiffness C_t21" in n for n in s.notes)


def test_the_example_case_results():
    # tests/cases/indexing-table-profile.toml: NPT035-10 (19 mm hub, J_1 = 0.93 kg·cm²), AKD-30,
    # J_L = 1500 kg·cm², f_er = 100 Hz: the chain of test_three_masses_by_hand.
    results = evaluate(read_case(EXAMPLE_CASE)).to_json()
    t = results["coupling"]["torsion"]
    assert t["part"] == "AKD-30" and t["complete"] and t["shaft"] == "the gearbox input"
    assert [m["members"] for m in t["masses"]] == ["motor + coupling", "coupling + gearbox", "load"]
    assert [m["J"]["value"] for m in t["masses"]] == pytest.approx([4.7, 1.43, 15])
    assert [s["C"]["value"] for s in t["springs"]] == pytest.approx([25_000, 756.304], abs=1e-3)
    assert [f["value"] for f in t["natural_frequencies"]] == pytest.approx([207.96, 2424.71], abs=0.01)
    (check,) = t["checks"]
    assert check["name"] == "f_1" and check["governs"] and check["passes"] and check["required"]["value"] == 200


def _torsion(capsys, path):
    from ..conftest import run

    code, out, err = run(capsys, path, "--json")
    assert code in (0, 1), err
    import json

    return json.loads(out)


DIRECT = """
title = "direct drive"
[[profile]]
phase = "accel"
duration = "0.2 s"
speed = "150 rpm"
torque = "6 N*m"
[[profile]]
phase = "pause"
duration = "1 s"
[coupling]
type = "bellows"
part = "AKD-30"
accel_torque = "12 N*m"
drive_inertia = "4.2 kg*cm**2"
load_inertia = "15.93 kg*cm**2"
excitation_frequency = "100 Hz"
shaft_1 = "19 mm k6"
shaft_2 = "16 mm h7"
"""


def test_a_direct_drive_has_no_gearbox_spring(capsys, write_case):
    # No [gearbox]: the chain is the source's two masses, complete, and its one mode is f_e = 1316.35 Hz.
    t = _torsion(capsys, write_case(DIRECT))["coupling"]["torsion"]
    assert t["complete"] and [m["members"] for m in t["masses"]] == ["motor + coupling", "coupling + load"]
    assert [f["value"] for f in t["natural_frequencies"]] == pytest.approx([1316.35], abs=0.01)
    assert t["checks"][0]["governs"] is True


def test_a_coupling_on_the_output_is_referred_there(capsys, write_case):
    # side = "output": the motor and J_1 times i², the gearbox's C_t21 as the catalog gives it, then
    # the coupling and the load as the section gives them. Seen from the input instead (each value
    # / i²) the train has the same modes.
    from ..conftest import HEAD_TOML, PROFILE_TOML

    coupling = DIRECT[DIRECT.index("[coupling]"):].replace('part = "AKD-30"',
                                                           'part = "AKD-300"\nside = "output"').replace(
        '"15.93 kg*cm**2"', '"1500 kg*cm**2"')
    r = _torsion(capsys, write_case(HEAD_TOML + PROFILE_TOML + coupling))
    t = r["coupling"]["torsion"]
    assert t["complete"] and t["shaft"] == "the gearbox output"
    assert [m["members"] for m in t["masses"]] == ["motor + gearbox", "coupling", "coupling + load"]
    gearbox = r["gearbox"]["selected"]
    g = next(c for c in r["gearbox"]["candidates"] if c["part"] == gearbox)
    J_1 = g["J_1"]["value"]
    gearboxes = load_catalog(resolve("gearboxes", None, "catalog"), GEARBOX_SCHEMA)
    C_t21 = gearboxes["C_t21"][gearboxes.index(gearbox, "part")]
    assert [m["J"]["value"] for m in t["masses"]] == pytest.approx([(4.2 + J_1) * 100, 16, 16 + 1500])
    C = [s["C"]["value"] for s in t["springs"]]
    assert C == pytest.approx([C_t21.m_as("N*m/rad"), 280_000])
    seen = natural_frequencies(Q_([4.2 + J_1, 0.16, 15.16], KG_CM2), Q_([C[0] / 100, 280_000 / 100], "N*m/rad"))
    assert [f["value"] for f in t["natural_frequencies"]] == pytest.approx(seen.m_as("Hz").tolist(), rel=1e-9)


def test_a_gearbox_that_is_not_selected_only_informs(capsys, write_case):
    # Without motor.peak_torque no gearbox is selected in S5: the best-ranked stands in, and the
    # chain's first mode is reported for information.
    from ..conftest import HEAD_TOML, PROFILE_TOML

    coupling = DIRECT[DIRECT.index("[coupling]"):].replace('part = "AKD-30"',
                                                           'side = "input"').replace('load_inertia = "15.93 '
                                                                                     'kg*cm**2"\n', "")
    r = _torsion(capsys, write_case(HEAD_TOML.replace('peak_torque = "12 N*m"\n', "") + PROFILE_TOML + coupling))
    t = r["coupling"]["torsion"]
    best = r["gearbox"]["candidates"][0]["part"]
    assert r["gearbox"]["selected"] is None and not t["complete"]
    assert t["missing"] == [f"a selected gearbox ({best}, the best-ranked, stands in: none is selected)"]
    assert t["checks"][0]["governs"] is False
    assert any("the drive train's first mode f_1 is reported for information" in n for n in r["coupling"]["notes"])


def test_an_informing_check_without_a_value_says_why():
    # A catalog row without J: the chain's first mode cannot be computed; reported, not made, with the reason.
    rows = BELLOWS.rows([BELLOWS.index("AKD-30", "part")])
    rows["J"][0] = Q_(np.nan, KG_CM2)
    train = DriveTrain(TRAIN.drive, (TrainMember("load", Q_(15.93, KG_CM2)),), missing=("coupling.side",))
    s = select_coupling(rows, excitation_frequency=Q_(100, "Hz"), drive_train=train, **ARGS)
    check = next(c for c in s.checks if c.name == "f_1").at(0)
    assert check.passes is None and check.governs is False
    assert check.not_made == (
        "the first mode of the drive train needs the coupling's inertia J, which the catalog leaves empty"
    )


def test_the_highest_first_mode_a_coupling_can_give_by_hand():
    # NPT025-10 (C_t21 = 8.5 N·m/arcmin, J_1 = 0.5 kg·cm² for the 19 mm hub, i = 10) behind the
    # example's SGMUH-10DA (1.74 kg·cm²), the table 1500 kg·cm². Of the bellows couplings the light
    # DKN-20-L32 (1500 N·m/rad, 0.025 kg·cm²) gives the highest first mode:
    #   J_1 = 1.74 + 0.0125 = 1.7525, J_2 = 0.0125 + 0.5 = 0.5125, J_3 = 15 kg·cm²;
    #   C_1 = 1500 N·m/rad, C_2 = 8.5 · 10800/π / 10² = 292.208 N·m/rad;
    #   b = C_1 (1/J_1 + 1/J_2) + C_2 (1/J_2 + 1/J_3) = 4.37239e7 1/s², c = C_1 C_2 ΣJ / ΠJ = 5.61704e13 1/s⁴;
    #   ω² = (b - √(b² - 4c)) / 2 = 1.32480e6 1/s², f = √ω² / 2π = 183.19 Hz.
    from calc.domain.coupling import SCHEMA as COUPLING_SCHEMA
    from calc.domain.torsion import CouplingSpan, highest_first_mode

    couplings = load_catalog(resolve("couplings", None, "catalog"), COUPLING_SCHEMA)
    bellows = couplings.rows((couplings.text["type"] == "bellows") & ~np.isnan(couplings["C_T"].magnitude))
    span = CouplingSpan(Q_(1.74, KG_CM2), Q_(1500, KG_CM2), bellows["C_T"], bellows["J"], Q_(200, "Hz"), "bellows")
    J_1, C_t21, i = Q_([0.5, 0.93, 0.5], KG_CM2), Q_([8.5, 22, np.nan], "N*m/arcmin"), Q_([10, 10, 10], "")
    best = highest_first_mode(span, J_1, C_t21, i).m_as("Hz")
    assert best[0] == pytest.approx(183.19, abs=0.01) and np.isnan(best[2])
    # The bound is the highest of the chains with each coupling alone (calc.domain.torsion.lumped).
    each = [lumped([TrainMember("motor", Q_(1.74, KG_CM2)), TrainMember("coupling", J / 2, C, J / 2),
                    TrainMember("gearbox", Q_(0.93, KG_CM2),
                                gearbox_at_input(C_t21=Q_(22, "N*m/arcmin"), i=Q_(10, ""))),
                    TrainMember("load", Q_(15, KG_CM2))]).natural_frequencies().m_as("Hz")[0]
            for C, J in zip(bellows["C_T"], bellows["J"])]
    assert best[1] == pytest.approx(max(each), rel=1e-12)


def test_the_gearbox_ranks_first_the_rows_whose_drive_train_clears_the_excitation():
    # The example with a 3.2 s dwell: f_s = 1.0, T_2max = 6.5 · 10 · 1.0 · 0.97 = 63.05 N·m, which
    # NPT025-10 (T_2B 90 N·m) carries. But its drive train stays at 183.2 Hz with the best bellows
    # coupling (the test above), below 2 f_er = 200 Hz: no coupling could pass. NPT035-10, whose
    # train reaches 265.5 Hz, ranks first; NPT025-10 still passes its own checks, the train check
    # informing (it does not govern), and the coupling section decides the resonance.
    from calc.review.inputs import with_inputs

    case = with_inputs(read_case(DERIVED_EXAMPLE), {"move[2].dwell": Q_(3.2, "s")})
    result = evaluate(case)
    g = result.to_json()["gearbox"]
    train = {c["part"]: next(k for k in c["checks"] if k["name"] == "f_1") for c in g["candidates"]}
    assert [c["part"] for c in g["candidates"]][:2] == ["NPT035-10", "NPT025-10"] and g["selected"] == "NPT035-10"
    assert g["candidates"][1]["passes"] is True
    assert train["NPT025-10"]["rated"]["value"] == pytest.approx(183.19,
                                                                 abs=0.01) and train["NPT025-10"]["passes"] is False
    assert train["NPT025-10"]["governs"] is False and train["NPT025-10"]["mode"] == "drive train"
    assert train["NPT035-10"]["rated"]["value"] == pytest.approx(265.5, abs=0.1)
    assert train["NPT045-10"]["passes"] is None and "C_t21" in train["NPT045-10"]["not_made"]  # no C_t21: ranked after
    assert result.verdict.word == "PASS" and result.to_json()["coupling"]["selected"] == "AKN-18"


def test_the_train_check_needs_a_coupling_between_motor_and_gearbox(write_case):
    # Without [coupling], or with the coupling on the output side, the gearbox has no train check.
    from calc.sections.coupling import coupling_span

    assert coupling_span(read_case(EXAMPLE_CASE)) is not None  # side = "input", f_er, both inertias
    # The measurements' paths absolute: they are found as the case is read.
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8").replace("../data/", f"{DERIVED_EXAMPLE.parents[1] / 'data'}/")
    # An output-side coupling takes nothing from the case: its table gives M_a and both inertias.
    output = ('side = "output"\naccel_torque = "100 N*m"\ndrive_inertia = "1500 kg*cm**2"\n'
              'load_inertia = "1500 kg*cm**2"')
    assert coupling_span(read_case(write_case(text.replace('side = "input"', output)))) is None
    without = read_case(EXAMPLE_CASE)
    assert coupling_span(dataclasses.replace(without,
                                             sections={k: v for k, v in without.sections.items()
                                                       if k != "coupling"})) is None


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(positive, positive), min_size=1, max_size=8), positive, positive, positive, positive,
       st.floats(1.5, 100))
def test_the_highest_first_mode_is_the_best_of_the_chains_one_by_one(couplings, J_motor, J_1, C_t21, J_L, i):
    # Whatever couplings are offered (those another beats on stiffness and inertia left out), the
    # bound is the highest first mode of the chains built with each alone.
    from calc.domain.torsion import CouplingSpan, highest_first_mode

    C = Q_([c for c, _ in couplings], "N*m/arcmin").to("N*m/rad")
    J = Q_([j for _, j in couplings], KG_CM2)
    span = CouplingSpan(Q_(J_motor, KG_CM2), Q_(J_L, KG_CM2), C, J, Q_(200, "Hz"), "drawn")
    best = highest_first_mode(span, Q_([J_1], KG_CM2), Q_([C_t21], "N*m/arcmin"), Q_([i], "")).m_as("Hz")[0]
    modes = np.array([natural_frequencies(Q_([J_motor + j / 2, j / 2 + J_1, J_L / i**2], KG_CM2),
                                          Q_([c, gearbox_at_input(C_t21=Q_(C_t21, "N*m/arcmin"),
                                                                  i=Q_(i, "")).m_as("N*m/rad")], "N*m/rad")).m_as("Hz")
                      for c, j in zip(C.m_as("N*m/rad"), J.m_as(KG_CM2))])
    # to the eigensolver's precision, relative to the highest mode (test_reflection_through_a_ratio_keeps_the_modes)
    assert best == pytest.approx(modes[:, 0].max(), rel=1e-9, abs=1e-9 * modes.max())
