"""The motor chosen from a catalog (calc.domain.motor_ratings, [motor] catalog / part): the catalog as
published, the speed-torque characteristic by hand, the ranking, a direct drive, and bad input."""

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import Q_
from calc.data.catalog import CATALOG_DIR, load_catalog
from calc.domain.motor_ratings import SCHEMA, T_V, Cycle, peak_limit, select_motors

from ..conftest import DERIVED_EXAMPLE, check_results

MOTORS = CATALOG_DIR / "motors.csv"

DIRECT_DRIVE = """
title = "Direct-drive ball screw"
[motor]
catalog = "motors"
{motor}
[mechanism]
type = "ball-screw"
mass = "40 kg"
lead = "10 mm"
screw_inertia = "1.2 kg*cm**2"
eta = 0.9
friction_coefficient = 0.05
[[move]]
distance = "300 mm"
time = "0.6 s"
accel_time = "0.1 s"
[[move]]
dwell = "0.4 s"
[[move]]
distance = "-300 mm"
time = "0.6 s"
accel_time = "0.1 s"
[[move]]
dwell = "0.4 s"
"""


def catalog():
    return load_catalog(MOTORS, SCHEMA)


def one(part):
    cat = catalog()
    return cat.rows(cat.parts == part)


def rpm(n):
    return Q_(n, "rpm").m_as("rad/s")


def test_the_catalog_keeps_every_published_row_and_ranks_the_complete_ones():
    cat = catalog()
    # ../shared/reference/published/motors.csv: 184 motors; the Beckhoff rows publish M_0 only.
    assert len(cat) == 184 and int(cat.partial.sum()) == 109
    row = cat.index("AM8031-wCyz (230 V AC)", "test")
    assert cat.partial[row] and "no rated torque M_N" in cat.text["partial"][row]
    assert cat["M_max"][cat.index("SGM7J-02A", "test")].m_as("N*m") == 2.23


def test_the_ratings_reading_past_the_knee_by_hand():
    # SGM7J-02A: M_max 2.23 N·m up to n_N 3000 rpm, then straight to M_N 0.637 N·m at n_max 6000 rpm.
    # At 4500 rpm, halfway: 2.23 - (2.23 - 0.637) · 1500 / 3000 = 1.4335 N·m; at 2000 rpm the full 2.23.
    limit, forms = peak_limit(one("SGM7J-02A"), np.array([rpm(2000), rpm(4500), rpm(6000)]))
    assert limit[0] == pytest.approx([2.23, 1.4335, 0.637], rel=1e-12) and forms == ["ratings"]


def test_the_voltage_limit_by_hand():
    # 1FT7044-AK7 (Siemens 1FT7 configuration manual): k_E 57 V/krpm, k_T 0.88 N·m/A, R_ph 0.61 Ω,
    # L_ph 4.2 mH, 6 poles; a 600 V DC link. At 6000 rpm: E = 57 · 6 / √3 = 197.45 V, U = 600 / √6
    # = 244.95 V, X = 3 · 628.32 rad/s · 4.2 mH = 7.917 Ω;
    # I = (√(U² (R² + X²) − X² E²) − R E) / (R² + X²) = (√(60000 · 63.05 − 62.68 · 38987) − 120.4) / 63.05
    #   = 16.44 A; T_V = 0.88 · 16.44 = 14.47 N·m, of which an operating point may use 90 %: 13.02 N·m.
    R, X, E, U = 0.61, 3 * rpm(6000) * 4.2e-3, 57 * 6 / math.sqrt(3), 600 / math.sqrt(6)
    by_hand = 0.88 * (math.sqrt(U**2 * (R**2 + X**2) - X**2 * E**2) - R * E) / (R**2 + X**2)
    assert by_hand == pytest.approx(14.47, abs=0.01)
    T = T_V(U_DC=Q_(600, "V"), k_E=Q_(57, "V/krpm"), k_T=Q_(0.88, "N*m/A"), R_ph=Q_(0.61, "ohm"), L_ph=Q_(4.2, "mH"),
            poles=Q_(6, ""), n=Q_(6000, "rpm"))
    assert T.m_as("N*m") == pytest.approx(by_hand, rel=1e-12)
    limit, forms = peak_limit(one("1FT7044-AK7"), np.array([rpm(6000), rpm(0)]), Q_(600, "V"))
    # At standstill the voltage allows more than M_max 23 N·m: M_max holds.
    assert limit[0] == pytest.approx([0.9 * by_hand, 23.0], rel=1e-9) and forms == ["voltage limit"]


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(0, 10000), min_size=2, max_size=30),
       st.sampled_from(["SGM7J-02A", "HC52", "1FT7044-AK7", "SGMUH-10DA"]),
       st.sampled_from([None, 400.0, 600.0]))
def test_the_peak_characteristic_never_rises_with_speed(speeds, part, volts):
    n = np.sort(np.array([rpm(s) for s in speeds]))
    limit, _ = peak_limit(one(part), n, None if volts is None else Q_(volts, "V"))
    assert np.all(np.diff(limit[0]) <= 1e-9)


def toy_cycle(rows, torque=1.0, J_L=2.0):
    """A cycle of two samples at 1000 rpm for ``rows`` motors: torque, then a hold of zero."""
    T = np.tile([torque, 0.0], (rows, 1))
    return Cycle(T, np.array([rpm(1000), 0.0]), np.array([1.0, 1.0]), np.full(rows, torque / math.sqrt(2)), None)


@settings(max_examples=25, deadline=None)
@given(st.floats(0.05, 20.0))
def test_a_motor_that_passes_a_cycle_passes_it_at_lower_torque(torque):
    cat = catalog()
    complete = cat.rows(~cat.partial)
    strong = select_motors(complete, toy_cycle(len(complete), torque))
    weak = select_motors(complete, toy_cycle(len(complete), torque / 2))
    assert np.all(weak.passes >= strong.passes)


def test_the_smallest_adequate_motor_is_the_lowest_rated_torque_then_the_lower_inertia(tmp_path):
    header = MOTORS.read_text(encoding="utf-8").splitlines()[0]
    cols = header.split(",")
    rows = [  # part, M_N, M_max, J: A is too weak for a 2.5 N·m peak; B and C share M_N, C has the lower J
        ("A", 1.0, 2.0, 0.5), ("B", 2.0, 6.0, 2.0), ("C", 2.0, 6.0, 1.0), ("D", 5.0, 15.0, 0.2),
    ]
    lines = [header]
    for part, M_N, M_max, J in rows:
        cell = {"part": part, "maker": "test", "M_N [N*m]": M_N, "M_max [N*m]": M_max, "n_N [rpm]": 3000,
                "n_max [rpm]": 6000,
                "J [kg*cm**2]": J, "illustrative": "yes", "source": "a test row"}
        lines.append(",".join(str(cell.get(c, "")) for c in cols))
    path = tmp_path / "toy.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    cat = load_catalog(path, SCHEMA)
    # 2.5 N·m for 1 s, then 1 s at rest: RMS 2.5 / √2 = 1.77 N·m, within B's and C's M_N of 2 N·m.
    sel = select_motors(cat, toy_cycle(4, torque=2.5))
    assert [c.part for c in sel.candidates()] == ["C", "B", "D", "A"] and sel.selected == "C"
    assert sel.candidates()[-1].reasons == ["|T_1| <= T_peak(n_1) at every sample: required 2.5 N·m > rated 2 N·m, 25 "
                                            "% over",
                                            "T_1rms <= M_N: required 1.768 N·m > rated 1 N·m, 76.8 % over"]


def test_a_direct_drive_is_sized_by_hand(write_case, capsys):
    from calc.__main__ import main

    path = write_case(DIRECT_DRIVE.format(motor=""), "dd.toml")
    assert main(["evaluate", str(path), "--json"]) == 0
    r = check_results(capsys.readouterr().out)
    m = r["motor"]
    assert m["gearbox"] is None and m["ratio"] == 1.0 and m["selected"] == "SGM7J-02A"
    # The screw: r = 10 mm / 2π = 1.5915 mm; J_L = 40 kg · r² + 1.2 kg·cm² = 1.0132 + 1.2 = 2.2132 kg·cm².
    # SGM7J-02A's rotor 0.263 kg·cm²: λ = 2.2132 / 0.263 = 8.415 (no gearbox: no J_1, i = 1).
    best = m["candidates"][0]
    assert best["inertia_ratio"] == pytest.approx(2.2132 / 0.263, rel=1e-3)
    # Its top speed 0.3 m in 0.6 s with 0.1 s ramps: v = 0.3 / 0.5 = 0.6 m/s = 3600 rpm at 10 mm per turn,
    # past n_N 3000 rpm: the peak limit there is 2.23 − 1.593 · 600 / 3000 = 1.9114 N·m, and M_max
    # 2.23 N·m at n_N and below; the worst sample lies between.
    assert m["max_speed_required"]["value"] == pytest.approx(3600, rel=1e-9)
    peak = next(k for k in best["checks"] if k["name"] == "peak")
    assert 1.9114 <= peak["rated"]["value"] <= 2.23 and peak["passes"] is True
    assert r["verdict"]["passes"] is True


def test_the_chosen_motor_is_what_the_gearbox_checks_with(write_case, capsys):
    from calc.__main__ import main
    from calc.sections.case import read_case
    from calc.sections import evaluate

    text = DERIVED_EXAMPLE.read_text(encoding="utf-8")
    text = text.replace('peak_torque = "12 N*m"', 'catalog = "motors"').replace('inertia = "4.2 kg*cm**2"', "")
    path = write_case(text.replace('"../data/', f'"{DERIVED_EXAMPLE.parent.parent / "data"}/'), "c.toml")
    results = evaluate(read_case(path))
    sel = results["motor"].selection
    cat = sel.catalog
    row = cat.index(sel.selected, "test")
    # The gearbox's S5 check takes T_1B = M_max of the chosen motor, its inertia ratio the rotor's J.
    assert results.case.motor_peak_torque.m_as("N*m") == cat["M_max"][row].m_as("N*m")
    assert results.case.motor_inertia.m_as("kg*cm**2") == cat["J"][row].m_as("kg*cm**2")
    assert main(["evaluate", str(path), "--json"]) in (0, 1)
    assert check_results(capsys.readouterr().out)["motor"]["selected"] == sel.selected


@pytest.mark.parametrize("motor, message", [
    ('peak_torque = "12 N*m"',
     "motor.peak_torque: a catalog motor's ratings come from its catalog row; give either motor.catalog / motor.part "
     "or the typed ratings, found both"),
    ('part = "SGM7J-99Z"', "motor.part: no part 'SGM7J-99Z' in catalog catalogs/motors.csv; it has SGM7J-A5A"),
    ('part = "AM8031-wCyz (230 V AC)"', "motor.part: AM8031-wCyz (230 V AC) is a partial row of catalogs/motors.csv"),
    ('part = "SGM7J-02A"\ndc_link_voltage = "300 V"',
     "motor.dc_link_voltage: the voltage limit needs the electrical data of SGM7J-02A, but catalogs/motors.csv (row 5) "
     "gives no k_E, R_ph, L_ph, poles"),
    ('max_inertia_ratio = 0', "motor.max_inertia_ratio: expected an inertia ratio above zero, found 0"),
])
def test_bad_motor_input_gets_one_sentence(write_case, capsys, motor, message):
    from calc.__main__ import main

    path = write_case(DIRECT_DRIVE.format(motor=motor), "bad.toml")
    assert main(["evaluate", str(path)]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_a_catalog_key_without_a_catalog_is_refused(write_case, capsys):
    from calc.__main__ import main

    path = write_case('title = "t"\n[motor]\npeak_torque = "12 N*m"\nmax_inertia_ratio = 5\n[[profile]]\nphase = '
                      '"const"\nduration = "1 s"\n'
                      'speed = "100 rpm"\ntorque = "10 N*m"\n', "t.toml")
    assert main(["evaluate", str(path)]) == 2
    assert ("motor.max_inertia_ratio: a key of a catalog motor; give motor.catalog (or motor.part with it) as well"
            in capsys.readouterr().err)


def test_a_motor_row_with_peak_below_rated_is_refused(tmp_path):
    from calc.core.errors import CalcError

    lines = MOTORS.read_text(encoding="utf-8").splitlines()
    bad = lines[1].replace(",0.159,3000,0.557,", ",0.159,3000,0.1,")  # SGM7J-A5A: M_max 0.1 < M_N 0.159
    path = tmp_path / "bad.csv"
    path.write_text("\n".join([lines[0], bad]) + "\n", encoding="utf-8")
    with pytest.raises(CalcError, match=r"row 2 \(SGM7J-A5A\), column M_max: .*M_max >= M_N"):
        load_catalog(path, SCHEMA)


def test_the_json_names_the_fixed_keys(write_case, capsys):
    from calc.__main__ import main

    path = write_case(DIRECT_DRIVE.format(motor="max_inertia_ratio = 5"), "dd.toml")
    main(["evaluate", str(path), "--json"])
    m = json.loads(capsys.readouterr().out)["motor"]
    assert {"selected", "candidates", "mean_speed", "peak_torque_required", "rms_torque_required", "max_speed_required",
            "checks"} <= set(m)
    assert m["max_inertia_ratio"] == {"value": 5.0, "from": "motor.max_inertia_ratio"}
    # A limit of 5: SGM7J-02A's λ of 8.4 fails it; the smallest motor with a rotor of J_L / 5 or more passes.
    assert m["selected"] != "SGM7J-02A" and all(c["inertia_ratio"] <= 5 for c in m["candidates"] if c["passes"])


def test_a_direct_drive_takes_the_smallest_adequate_motor_of_the_search(write_case):
    from calc.sections.case import read_case
    from calc.sections import evaluate
    from calc.sections.pairs import case_pairs

    # No gearbox: one row of the search, i = 1; the motor it picks is the one the motor section names.
    case = read_case(write_case(DIRECT_DRIVE.format(motor=""), "dd.toml"))
    found = case_pairs(case)
    assert found.ratios.tolist() == [1.0] and found.pick is not None
    results = evaluate(case)
    assert results["motor"].selection.selected == found.pick.motor and results.every["axis"].gearbox is None


def test_the_shipped_direct_drive_chooses_its_motor_with_every_check_made():
    from calc.sections.case import read_case
    from calc.sections import evaluate

    results = evaluate(read_case(DERIVED_EXAMPLE.parent / "ball-screw-direct.toml"))
    m = results["motor"]
    assert m.part is None and m.selection.selected == "SGM7J-02A" and results.verdict.passes is True
    assert all(k.passes is True for k in m.row_checks) and {k.name
                                                            for k in m.row_checks} == {"peak", "RMS", "n_N", "n_max",
                                                                                       "lambda"}


CURVES = """part,curve,speed [rpm],torque [N*m],source
SGM7J-02A,peak,0,2.23,a test chart
SGM7J-02A,peak,3000,2.23,a test chart
SGM7J-02A,peak,6000,1.0,a test chart
SGM7J-02A,S1,0,0.637,a test chart
SGM7J-02A,S1,6000,0.5,a test chart
"""


def test_a_motor_with_its_curves_is_checked_on_them_by_hand(write_case, capsys):
    from calc.__main__ import main

    write_case(CURVES, "curves.csv")
    path = write_case(DIRECT_DRIVE.format(motor='part = "SGM7J-02A"\ncurves = "curves.csv"'), "dd.toml")
    assert main(["evaluate", str(path), "--json"]) == 0
    m = check_results(capsys.readouterr().out)["motor"]
    c = m["candidates"][0]
    assert c["part"] == "SGM7J-02A" and c["characteristic"] == "curves"
    checks = {k["name"]: k for k in c["checks"]}
    # The S1 curve at the mean speed of 1800 rpm: 0.637 − (0.637 − 0.5) · 1800 / 6000 = 0.5959 N·m,
    # and the rated speed is no limit of a motor held to its S1 curve.
    assert checks["RMS"]["rated"]["value"] == pytest.approx(0.5959, rel=1e-9) and "n_N" not in checks
    # The peak curve at the top speed of 3600 rpm: 2.23 − 1.23 · 600 / 3000 = 1.984 N·m; the worst
    # sample is at or below that speed, where the curve allows between 1.984 and 2.23 N·m.
    assert 1.984 - 1e-9 <= checks["peak"]["rated"]["value"] <= 2.23


@pytest.mark.parametrize("rows, message", [
    ("SGM7J-99Z,peak,0,2,a chart", "row 2, column part: 'SGM7J-99Z' is no part of the motor catalog"),
    ("SGM7J-02A,peak,3000,2,a chart\nSGM7J-02A,peak,1000,2,a chart",
     "row 3, column speed: expected a speed above the curve's one before (1000)"),
    ("SGM7J-02A,peak,0,-1,a chart", "row 2, column torque: expected a number of zero or more, found '-1'"),
    ("SGM7J-02A,intermittent,0,2,a chart", "row 2, column curve: expected one of peak, S1, found 'intermittent'"),
])
def test_a_bad_curves_file_gets_one_sentence(write_case, capsys, rows, message):
    from calc.__main__ import main

    write_case("part,curve,speed [rpm],torque [N*m],source\n" + rows + "\n", "curves.csv")
    path = write_case(DIRECT_DRIVE.format(motor='curves = "curves.csv"'), "dd.toml")
    assert main(["evaluate", str(path)]) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("content, message", [
    (b"", "expected a header and rows of part, curve, speed [unit], torque [unit], source, found an empty file"),
    (b"part,curve,speed [rpm],source\n", "header: expected a column 'torque', found part, curve, speed, source"),
    (b"part,curve,speed [rpm],torque [N*m],source\nSGM7J-02A,peak,0,2,\n",
     "row 2, column source: expected the chart the points are read from"),
    (b"part,curve,speed [rpm],torque [N*m],source\nSGM7J-02A,peak,0,2,\xff\n",
     "cannot read the curves file (UnicodeDecodeError)"),
])
def test_a_curves_file_that_cannot_be_read_is_named(write_case, tmp_path, capsys, content, message):
    from calc.__main__ import main

    (tmp_path / "curves.csv").write_bytes(content)
    path = write_case(DIRECT_DRIVE.format(motor='curves = "curves.csv"'), "dd.toml")
    assert main(["evaluate", str(path)]) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1
