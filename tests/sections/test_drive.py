"""The servo drive section ([drive]): a direct-drive case and the indexing-table example size their
drive; a typed cycle worked by hand (the motor current, a stop whose energy exceeds the DC link, a
resistor too weak on average, the winding against its closed form for a square cycle); bad input
named in one sentence."""

import json
import math

import numpy as np
import pytest

from calc.core.errors import CalcError
from calc.domain.motor_ratings import peak_limit
from calc.sections import evaluate, read_case

from ..conftest import DERIVED_EXAMPLE, ROOT, run

DIRECT = ROOT / "cases" / "ball-screw-direct.toml"
#: The direct-drive example without its own [drive] table.
DIRECT_TEXT = DIRECT.read_text().split("\n# The servo drive")[0]
RESISTOR = '\n[drive.brake_resistor]\nresistance = "100 ohm"\ncontinuous_power = "30 W"\npeak_power = "1.5 kW"\n'

# A typed cycle driven directly (ratio and efficiency 1, no rotor term): the motor torque is the
# typed torque and the motor speed the segment's mean speed.
TYPED = """
title = "typed axis with its drive"
[motor]
peak_torque = "10 N*m"
rated_torque = "2 N*m"
torque_constant = "0.5 N*m/A"
thermal_time_constant = "30 min"
[[profile]]
phase = "accel"
duration = "0.1 s"
speed = "1500 rpm"
torque = "4 N*m"
[[profile]]
phase = "const"
duration = "0.3 s"
speed = "3000 rpm"
torque = "0.5 N*m"
[[profile]]
phase = "decel"
duration = "0.1 s"
speed = "1500 rpm"
torque = "-4 N*m"
[[profile]]
phase = "pause"
duration = "0.5 s"
[drive]
rated_current = "5 A"
peak_current = "10 A"
peak_time = "1 s"
dc_link_voltage = "325 V"
dc_link_energy = "20 J"
"""


def drive_json(capsys, path) -> dict:
    code, out, _ = run(capsys, path, "--json")
    assert code == 0
    return json.loads(out)


def every_check_made_or_named(checks) -> None:
    for k in checks:
        assert k["passes"] is not None or k["not_made"], k


def test_the_direct_drive_case_sizes_its_drive(capsys, write_case):
    path = write_case(DIRECT_TEXT + '\n[drive]\ncatalog = "drives"\n' + RESISTOR)
    d = drive_json(capsys, path)["drive"]
    # SGM7J-02A (k_T 0.444 N·m/A, 200 V class): 1.061 N·m peak / 0.444 = 2.39 A; the smallest 230 V drive
    # with published currents is Moog G394-030 (3 A continuous, 9 A peak)
    assert d["motor"] == "SGM7J-02A" and d["torque_constant"] == {"value": 0.444, "unit": "N*m/A", "from": "catalog",
                                                                  "derived": False}
    assert d["current_peak"]["value"] == pytest.approx(1.0606 / 0.444, rel=2e-3)
    assert d["selected"].startswith("G394-030")
    assert d["voltage_class"] == "200-240 V AC"
    every_check_made_or_named(d["checks"])
    assert all(c["reasons"] for c in d["candidates"] if c["passes"] is False)
    b = d["braking"]
    assert len(b["events"]) == 2 and b["losses_subtracted"] == []
    # two stops of 15.33 J each (the screw driven back through η' = 2 − 1/0.9), the DC link not known (taken as 0 J):
    # 30.66 J per 2 s cycle = 15.33 W
    assert b["resistor_energy_per_cycle"]["value"] == pytest.approx(30.66, rel=1e-3)
    assert b["resistor_average_power"]["value"] == pytest.approx(30.66 / 2, rel=1e-3)


def test_the_example_sizes_its_drive_or_names_why(capsys):
    # cases/indexing-table.toml carries [drive] catalog = "drives" and the resistor of RESISTOR.
    assert RESISTOR in DERIVED_EXAMPLE.read_text()
    d = drive_json(capsys, DERIVED_EXAMPLE)["drive"]
    # SGMUH-10DA is a 400 V-class motor (565 V): the smallest 400 V drive, KEBA SA54.0075 (2.5 A, 7.5 A)
    assert d["selected"] == "SA54.0075" and d["voltage_class"] == "380-480 V AC"
    assert d["candidates"][0]["maker"] == "KEBA"
    every_check_made_or_named(d["checks"])
    # One stop a cycle; its energy, the DC link not known (0 J), goes to the resistor over the 1.5 s cycle.
    (event,) = d["braking"]["events"]
    # at most the train's kinetic energy at the top speed, ½ J ω² with J = 1.74 (rotor) + 0.5 (AKN-18)
    # + 0.93 (J_1) + 1500 / 10² (table) = 18.17 kg·cm² and ω = 428.6 rpm = 44.88 rad/s: 1.830 J; the
    # table's friction and the gearbox take the rest.
    assert 0 < event["energy"]["value"] < 0.5 * 18.17e-4 * (428.57 * 2 * math.pi / 60) ** 2
    b = d["braking"]
    assert b["resistor_energy_per_cycle"]["value"] == pytest.approx(event["energy"]["value"], rel=1e-12)
    assert b["resistor_average_power"]["value"] == pytest.approx(event["energy"]["value"] / 1.5, rel=1e-12)


def test_a_typed_stop_whose_energy_exceeds_the_dc_link(write_case):
    results = evaluate(read_case(write_case(TYPED)))
    d = results["drive"].to_json()
    # I = |T| / k_T = 8, 1, 8, 0 A; I_rms = sqrt((64·0.1 + 1·0.3 + 64·0.1) / 1.0) = sqrt(13.1) = 3.6194 A
    assert d["current_rms"]["value"] == pytest.approx(math.sqrt(13.1), rel=1e-12)
    assert d["current_peak"]["value"] == pytest.approx(8.0)
    # the decel gives back 4 N·m · 1500 rpm · 2π/60 · 0.1 s = 62.832 J from 0.4 s; the DC link absorbs 20 J
    (event,) = d["braking"]["events"]
    assert event["start"]["value"] == pytest.approx(0.4) and event["duration"]["value"] == pytest.approx(0.1)
    assert event["energy"]["value"] == pytest.approx(4 * 1500 * 2 * math.pi / 60 * 0.1, rel=1e-12)
    assert d["braking"]["dc_link_energy"]["value"] == 20.0
    v = results.verdict
    assert v.passes is False
    assert "the decel at 0.4 s gives 62.83 J; the DC link absorbs 20 J; no resistor is given" in v.reasons


def test_a_resistor_too_weak_on_average(write_case):
    text = TYPED + '\nchopper_voltage = "390 V"\n[drive.brake_resistor]\nresistance = "100 ohm"\n' \
                   'continuous_power = "30 W"\n'
    d = evaluate(read_case(write_case(text)))["drive"].to_json()
    # (62.832 − 20) J per 1 s cycle = 42.83 W against 30 W; the peak 628.3 W against 390² / 100 = 1521 W
    b = d["braking"]
    assert b["resistor_average_power"]["value"] == pytest.approx(4 * 50 * math.pi * 0.1 - 20, rel=1e-12)
    avg, peak = b["checks"]
    assert avg["passes"] is False and avg["utilization"] == pytest.approx((20 * math.pi - 20) / 30, rel=1e-12)
    assert peak["passes"] is True and peak["rated"]["value"] == pytest.approx(390**2 / 100)


def test_the_winding_against_its_closed_form_for_a_square_cycle(write_case):
    # 4 N·m (twice M_N = 2 N·m: u = 4) for 60 s, then 240 s at rest, T_th = 1 min. The RMS rule passes,
    # sqrt(16 · 60 / 300) = 1.789 N·m <= 2 N·m, but the cycle is long against T_th:
    # θ_max = 4 (1 − e^(−60/60)) / (1 − e^(−300/60)) = 4 · 0.632121 / 0.993262 = 2.545635
    text = (TYPED.split("[[profile]]")[0].replace('"30 min"', '"1 min"')
            + '[[profile]]\nphase = "const"\nduration = "60 s"\nspeed = "100 rpm"\ntorque = "4 N*m"\n'
            '[[profile]]\nphase = "pause"\nduration = "240 s"\n'
            + "[drive]" + TYPED.split("[drive]")[1].replace('"1 s"', '"100 s"'))
    results = evaluate(read_case(write_case(text)))
    thermal = results["motor"].to_json()["thermal"]
    closed = 4 * (1 - math.exp(-1)) / (1 - math.exp(-5))
    assert closed == pytest.approx(2.545635, rel=1e-6)
    assert thermal["utilization"] == pytest.approx(closed, rel=1e-12) and thermal["reference"] == "M_N"
    assert results["motor"].verdict().passes is True  # the RMS rule
    assert results.verdict.passes is False
    assert results.verdict.reasons == [f"Drive typed drive: θ_max <= 1 (the winding's rise under M_N held): "
                                       f"required {closed:.4g} > rated 1, {100 * (closed - 1):.3g} % over"]


@pytest.mark.parametrize("extra, fragment", [
    ('\n[drive]\ncatalog = "drives"\nrated_current = "5 A"\n', "drive.rated_current: a catalog drive's ratings"),
    ('\n[drive]\nrated_current = "5 A"\n', "a typed drive needs drive.rated_current and drive.peak_current, "
                                           "found no drive.peak_current"),
    ('\n[drive]\nrated_current = "5 A"\npeak_current = "4 A"\n', "drive.peak_current: expected a peak current at "
                                                                 "least the rated current '5 A', found '4 A'"),
    ('\n[drive]\n[drive.brake_resistor]\ncontinuous_power = "5 W"\n', "drive.brake_resistor.resistance: a brake "
                                                                       "resistor needs its resistance"),
])
def test_bad_drive_tables_are_one_sentence(write_case, extra, fragment):
    path = write_case(DIRECT_TEXT + extra)
    with pytest.raises(CalcError) as err:
        read_case(path)
    assert str(path) in str(err.value) and fragment in str(err.value)
    assert len(str(err.value)) <= 300


def test_a_drive_and_a_motor_of_different_voltage_classes_forced_together(write_case):
    path = write_case(DIRECT_TEXT + '\n[drive]\npart = "TGZ-S-400-3/9"\n')
    with pytest.raises(CalcError, match=r"drive.part: a drive of the 380-480 V AC class \(U_DC = 565 V\) and motor "
                                        r"SGM7J-02A of the 200-240 V AC class \(U_DC = 283 V\) forced together"):
        evaluate(read_case(path))


def test_typed_dc_link_voltages_must_agree(write_case):
    text = DIRECT_TEXT.replace("max_inertia_ratio = 10", 'max_inertia_ratio = 10\ndc_link_voltage = "283 V"')
    path = write_case(text + '\n[drive]\nrated_current = "5 A"\npeak_current = "9 A"\ndc_link_voltage = "325 V"\n')
    with pytest.raises(CalcError, match=r"drive.dc_link_voltage: expected the DC link of motor.dc_link_voltage, "
                                        r"283 V, found '325 V'"):
        evaluate(read_case(path))


def test_a_drive_without_the_motors_torques_makes_no_check(write_case):
    path = write_case(TYPED.replace("[motor]", "[gearbox]\nratio = 5\n[motor_removed]", 1).split("[motor_removed]")[0]
                      + "[[profile]]" + TYPED.split("[[profile]]", 1)[1])
    results = evaluate(read_case(path))
    d = results["drive"].to_json()
    assert d["selected"] is None and d["current_rms"] is None
    assert all(k["passes"] is None and "the drive needs the motor's torques over the cycle: the case gives no motor"
               in k["not_made"] for k in d["checks"])
    assert results["drive"].verdict().passes is None


def test_a_named_resistor_below_the_drives_minimum(write_case, tmp_path):
    head = (ROOT / "catalogs" / "drives.csv").read_text(encoding="utf-8").splitlines()[0]
    (tmp_path / "mine.csv").write_text(f"{head}\nD-1,Maker,F,230 V AC,325,5,15,5,,,,,,40,,,a datasheet\n",
                                       encoding="utf-8")
    path = write_case(DIRECT_TEXT + '\n[drive]\ncatalog = "mine.csv"\npart = "D-1"\n' + RESISTOR.replace(
        '"100 ohm"', '"33 ohm"'))
    with pytest.raises(CalcError, match=r"drive.brake_resistor.resistance: expected at least the R_min of D-1, "
                                        r"40 ohm, found '33 ohm'"):
        evaluate(read_case(path))


def test_a_catalog_drive_with_its_capacitance_and_internal_resistor(write_case, tmp_path):
    # A drive row with its DC link's capacitance and an internal resistor (as Kollmorgen's AKD rows give
    # them): 940 µF from 325 V to the chopper's 390 V absorb ½ · 940e-6 · (390² − 325²) = 21.84 J, more
    # than each of the slide's stops (15.4 J): nothing reaches the internal 33 Ω, 50 W resistor, whose peak
    # at the chopper voltage is 390² / 33 = 4609 W.
    head = (ROOT / "catalogs" / "drives.csv").read_text(encoding="utf-8").splitlines()[0]
    (tmp_path / "mine.csv").write_text(f"{head}\nD-2,Maker,F,230 V AC,325,5,15,5,,940,,33,50,,,,a datasheet\n",
                                       encoding="utf-8")
    path = write_case(DIRECT_TEXT + '\n[drive]\ncatalog = "mine.csv"\nchopper_voltage = "390 V"\n')
    b = evaluate(read_case(path))["drive"].to_json()["braking"]
    assert b["dc_link_energy"]["value"] == pytest.approx(0.5 * 940e-6 * (390**2 - 325**2), rel=1e-12)
    assert b["dc_link_energy_from"].startswith("½ C_DC (U_on² − U_DC²)")
    assert b["resistor_energy_per_cycle"]["value"] == 0.0
    assert b["resistor"]["part"] == "the internal resistor of D-2"
    avg, peak = b["checks"]
    assert avg["passes"] is True and peak["rated"]["value"] == pytest.approx(390**2 / 33, rel=1e-12)


# -- the drive's DC link and the motor's voltage limit ------------------------------------------

#: 1FT7044-AK7 (k_E 57 V/krpm, k_T 0.88 N·m/A, R_ph 0.61 Ω, L_ph 4.2 mH, 6 poles; its row gives no
#: U_DC) driving a constant speed directly, with a typed drive of the DC link given.
ON_A_DRIVE = """
title = "1FT7044-AK7 on its drive"
[motor]
part = "1FT7044-AK7"
{motor}
[[profile]]
phase = "const"
duration = "1 s"
speed = "{speed}"
torque = "1 N*m"
[drive]
{drive}
"""
TYPED_DRIVE = 'rated_current = "10 A"\npeak_current = "30 A"\ndc_link_voltage = "{U}"'


def test_a_typed_drive_lowers_the_motors_voltage_limit(write_case):
    # The voltage limit (case format, "The motor chosen from a catalog") on a 540 V DC link at 6000 rpm:
    # E = 57 · 6 / √3 = 197.45 V, U = 540 / √6 = 220.45 V (U² = 48 600 V²), X = 3 · 628.32 rad/s · 4.2 mH
    # = 7.917 Ω, R² + X² = 63.05 Ω²; I = (√(48 600 · 63.05 − 62.68 · 38 987) − 0.61 · 197.45) / 63.05
    # = (√620 500 − 120.4) / 63.05 = 10.58 A, T_V = 0.88 · 10.58 = 9.31 N·m, 90 % of it 8.38 N·m
    # (on the 600 V the motor's test takes, 13.02 N·m).
    R, X, E, U = 0.61, 3 * 6000 * 2 * math.pi / 60 * 4.2e-3, 57 * 6 / math.sqrt(3), 540 / math.sqrt(6)
    by_hand = 0.9 * 0.88 * (math.sqrt(U**2 * (R**2 + X**2) - X**2 * E**2) - R * E) / (R**2 + X**2)
    assert by_hand == pytest.approx(8.38, abs=0.01)
    path = write_case(ON_A_DRIVE.format(motor="", speed="6000 rpm", drive=TYPED_DRIVE.format(U="540 V")))
    results = evaluate(read_case(path))
    m = results["motor"].to_json()
    assert m["characteristic_dc_link"] == {"value": {"value": 540.0, "unit": "V"},
                                           "from": "drive.dc_link_voltage, the voltage limit of 1FT7044-AK7"}
    peak = next(k for k in m["checks"] if k["name"] == "peak")
    assert peak["rated"]["value"] == pytest.approx(by_hand, rel=1e-9)
    # The speed at which no current is left: T_V = 0 where U_DC / √6 = E = k_E · n / √3, so
    # n_0 = U_DC / (√2 · k_E): 540 / (√2 · 57) krpm = 6699 rpm (7443 rpm on 600 V): it scales with U_DC.
    sel = results["motor"].selection
    n_0 = 540 / (math.sqrt(2) * 57) * 1000
    assert n_0 == pytest.approx(6699, abs=1)
    limit, forms = peak_limit(sel.catalog, np.array([n_0 * 0.999, n_0 * 1.001]) * 2 * math.pi / 60, sel.dc_link)
    assert forms == ["voltage limit"] and limit[0][0] > 0 and limit[0][1] == 0
    d = results["drive"].to_json()
    U_DC = next(k for k in d["checks"] if k["criterion"] == "U_DC >= 540 V (motor's characteristic)")
    assert U_DC["passes"] is True and U_DC["utilization"] == 1.0


def test_a_named_drive_gives_the_motor_its_dc_link(write_case):
    # Moog G394-030 (3x230 V AC): U_DC 325 V; at 3000 rpm E = 98.73 V, below U = 325 / √6 = 132.68 V.
    path = write_case(ON_A_DRIVE.format(motor="", speed="3000 rpm", drive='part = "G394-030 (3x230 V AC)"'))
    results = evaluate(read_case(path))
    assert results["motor"].selection.dc_link.m_as("V") == 325.0
    assert results["motor"].characteristic_dc_link == (325.0, "the U_DC of drive.part G394-030 (3x230 V AC), "
                                                              "the voltage limit of 1FT7044-AK7")


def test_a_drive_below_the_motors_dc_link_never_passes(write_case):
    # The motor checked on 600 V (motor.dc_link_voltage); KEBA SA54.0075 has 565 V: 600 / 565 = 1.062.
    path = write_case(ON_A_DRIVE.format(motor='dc_link_voltage = "600 V"', speed="3000 rpm",
                                        drive='part = "SA54.0075"'))
    results = evaluate(read_case(path))
    assert results["motor"].characteristic_dc_link == (600.0, "motor.dc_link_voltage, the voltage limit of 1FT7044-AK7")
    k = next(k for k in results["drive"].checks() if k.criterion == "U_DC >= 600 V (motor's characteristic)")
    assert k.passes is False and k.utilization == pytest.approx(600 / 565, rel=1e-12)
    assert results["drive"].verdict().passes is False
    # Chosen from the catalog: no published drive with both currents has a DC link of 600 V or more (565 V
    # at most), so none passes, and a row without U_DC is not checked (it fails the class check anyway).
    path = write_case(ON_A_DRIVE.format(motor='dc_link_voltage = "600 V"', speed="3000 rpm",
                                        drive='catalog = "drives"'))
    d = evaluate(read_case(path))["drive"]
    assert d.selection.selected is None and d.verdict().passes is False
    k = next(c for c in d.selection.checks if c.text == "U_DC >= 600 V (motor's characteristic)")
    assert not (k.passes & ~k.unrated_rows).any() and k.utilization[~k.unrated_rows].min() == pytest.approx(600 / 565)
    assert k.unrated_rows.sum() == np.isnan(d.selection.catalog["U_DC"].m_as("V")).sum() > 0


def test_the_example_checks_its_drive_at_the_motors_rated_dc_link():
    # SGMUH-10DA's row gives U_DC 565 V (its ratings are for it); KEBA SA54.0075 has 565 V: 100 %.
    m = evaluate(read_case(DERIVED_EXAMPLE))
    assert m["motor"].characteristic_dc_link == (565.0, "the U_DC of SGMUH-10DA's catalog row, for its ratings")
    assert ("  Its characteristic is for U_DC = 565 V (the U_DC of SGMUH-10DA's catalog row, for its ratings)"
            in m["motor"].summary_lines())
    k = next(k for k in m["drive"].checks() if k.criterion == "U_DC >= 565 V (motor's characteristic)")
    assert k.passes is True and k.utilization == 1.0


def test_a_typed_motor_leaves_the_check_out_and_says_why(write_case):
    d = evaluate(read_case(write_case(TYPED)))["drive"]
    assert not any("characteristic" in k.criterion for k in d.checks())
    assert ("the DC link is not checked against the motor's characteristic, whose DC-link voltage is not known: "
            "a typed motor's ratings name no DC-link voltage") in d.selection.notes
