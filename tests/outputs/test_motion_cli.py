"""``python -m calc evaluate`` with the motion form (``[mechanism]``, ``[[move]]``,
``[drive_record]``): the results it adds, and one line naming the key for each bad input (exit 2,
nothing on standard output)."""

import json

import pytest

from ..conftest import PROFILE_TOML, run

HEAD = """
title = "motion axis"
[gearbox]
ratio = 10
"""

TABLE = """
[mechanism]
type = "rotary"
inertia = "1500 kg*cm**2"
friction_torque = "2 N*m"
"""

SCREW = """
[mechanism]
type = "ball-screw"
mass = "50 kg"
lead = "20 mm"
eta = 0.9
"""

MOVE = """
[[move]]
distance = "{distance}"
time = "0.5 s"
accel_time = "0.1 s"
[[move]]
dwell = "0.5 s"
"""


def evaluated(capsys, write_case, text):
    code, out, err = run(capsys, write_case(text), "--json")
    assert code == 0, err
    return json.loads(out)


def test_a_table_indexing_a_quarter_turn_by_hand(capsys, write_case):
    r = evaluated(capsys, write_case, HEAD + TABLE + MOVE.format(distance="90 deg"))
    m = r["motion"]
    # By hand: ω_2max = (π/2 rad) / (0.5 s − 0.1 s) = 3.92699 rad/s = 37.5 rpm; α = 3.92699 / 0.1 = 39.2699 rad/s².
    assert m["peak_speed"] == {"value": pytest.approx(37.5, rel=1e-12), "unit": "rpm"}
    assert m["peak_acceleration"] == {"value": pytest.approx(39.2699082, rel=1e-8), "unit": "rad/s**2"}
    assert m["J_L"] == {"value": pytest.approx(1500.0), "unit": "kg*cm**2"}
    # T_2 = J_L·α + T_f: 0.15 kg·m² · 39.2699 + 2 = 7.89049 N·m; const 2 N·m; decel −5.89049 + 2 = −3.89049 N·m.
    phases = [(s["phase"], s["duration"]["value"], s["speed"]["value"], s["torque"]["value"]) for s in m["segments"]]
    expected = [
        ("accel", 0.1, 18.75, 7.890486225),
        ("const", 0.3, 37.5, 2.0),
        ("decel", 0.1, 18.75, -3.890486225),
        ("pause", 0.5, 0.0, 0.0),
    ]
    for got, want in zip(phases, expected, strict=True):
        assert got[0] == want[0]
        assert got[1:] == pytest.approx(want[1:], rel=1e-9, abs=1e-12)
    # The duty section uses them as typed: ED = 0.5 / 1.0 = 50 %,
    # n_2m = (18.75·0.1 + 37.5·0.3 + 18.75·0.1) / 0.5 = 30 rpm.
    assert r["duty"]["ED"]["value"] == pytest.approx(50.0)
    assert r["continuous"]["n2m"]["value"] == pytest.approx(30.0, rel=1e-12)
    # T_2m = ∛((18.75·0.1·7.890486³ + 37.5·0.3·2³ + 18.75·0.1·3.890486³) / 15)
    #      = ∛((921.11 + 90 + 110.41) / 15) = ∛74.768 = 4.21281 N·m
    assert r["continuous"]["T2m"]["value"] == pytest.approx(4.21281, abs=1e-5)


def test_the_load_inertia_comes_from_the_mechanism(capsys, write_case):
    r = evaluated(
        capsys,
        write_case,
        HEAD + SCREW + MOVE.format(distance="100 mm") + '[motor]\ninertia = "4.2 kg*cm**2"\npeak_torque = "12 N*m"\n',
    )
    # By hand: r = 20 mm / 2π = 3.18310 mm; J_L = 50 kg · (3.18310 mm)² = 5.06606 kg·cm².
    assert r["motion"]["J_L"]["value"] == pytest.approx(5.06606, abs=1e-5)
    ratio = r["gearbox"]["candidates"][0]["inertia_ratio"]
    assert ratio is not None


def test_the_duty_result_carries_the_sampled_cycle_only_in_the_motion_form(write_case):
    from calc.sections.case import read_case
    from calc.sections import evaluate

    motion = evaluate(read_case(write_case(HEAD + TABLE + MOVE.format(distance="90 deg"))))
    cycle = motion["profile"].cycle
    assert cycle is not None and cycle.dt.sum() == pytest.approx(1.0, rel=1e-12)
    assert cycle.torque.max() == pytest.approx(7.890486, rel=1e-6)
    typed = evaluate(read_case(write_case(HEAD + PROFILE_TOML, "typed.toml")))
    assert typed["profile"].cycle is None and "motion" not in typed.to_json()


def test_a_drive_record_is_cut_into_the_seeds_segments(capsys, write_case, tmp_path):
    (tmp_path / "rec.csv").write_text(
        "# generated: a triangle of 0.2 s to 300 rpm and back, 0.2 s at rest\n"
        "time [s],speed [rpm],torque [N*m]\n0,0,10\n0.1,150,10\n0.2,300,10\n0.3,150,-10\n0.4,0,-10\n0.5,0,0\n0.6,0,0\n"
    )
    r = evaluated(capsys, write_case, HEAD + '[drive_record]\nfile = "rec.csv"\n')
    m = r["motion"]
    # By hand, one sample per interval between rows, its speed and torque the means of its two rows:
    # accelerating 75 and 225 rpm at 10 N·m; braking 225 rpm at (10 − 10)/2 = 0 and 75 rpm at −10 N·m;
    # at rest (−10 + 0)/2 = −5 and 0 N·m. Braking: T = −∛((225·0.1·0³ + 75·0.1·10³) / (150·0.2)) = −∛250 = −6.2996 N·m;
    # the pause holds the mean, −2.5 N·m.
    assert [s["phase"] for s in m["segments"]] == ["accel", "decel", "pause"]
    assert [s["duration"]["value"] for s in m["segments"]] == pytest.approx([0.2, 0.2, 0.2])
    assert [s["speed"]["value"] for s in m["segments"]] == pytest.approx([150.0, 150.0, 0.0])
    assert [s["torque"]["value"] for s in m["segments"]] == pytest.approx([10.0, -(250 ** (1 / 3)), -2.5])
    assert m["J_L"] is None and m["source"] == "drive_record"
    assert m["peak_speed"]["value"] == pytest.approx(225.0)  # the highest interval mean


def test_a_drive_record_without_torque_takes_the_mechanisms(capsys, write_case, tmp_path):
    (tmp_path / "rec.csv").write_text("time [s],speed [rad/s]\n0,0\n1,2\n2,2\n3,0\n")
    r = evaluated(capsys, write_case, HEAD + TABLE + '[drive_record]\nfile = "rec.csv"\n')
    # By hand: accel 2 rad/s²: T = 0.15 · 2 + 2 = 2.3 N·m; const 2 N·m; decel −0.3 + 2 = 1.7 N·m.
    assert [s["torque"]["value"] for s in r["motion"]["segments"]] == pytest.approx([2.3, 2.0, 1.7])


ERRORS = [
    (
        HEAD + '[mechanism]\ntype = "crank"\ninertia = "1 kg*m**2"\n' + MOVE.format(distance="90 deg"),
        "mechanism.type",
        "crank",
    ),
    (
        HEAD + TABLE + 'lead = "20 mm"\n' + MOVE.format(distance="90 deg"),
        "mechanism.lead",
        "a key of a ball-screw mechanism",
    ),
    (
        HEAD + SCREW + 'inertia = "1 kg*m**2"\n' + MOVE.format(distance="1 mm"),
        "mechanism.inertia",
        "a key of a rotary mechanism",
    ),
    (HEAD + TABLE + 'colour = "red"\n' + MOVE.format(distance="90 deg"), "mechanism.colour", "unknown key"),
    (HEAD + TABLE + "holding_brake = 1\n" + MOVE.format(distance="90 deg"), "mechanism.holding_brake", "true or false"),
    (
        HEAD + TABLE + '[[move]]\ndistance = "90 deg"\ntime = "0.5 s"\naccel_time = "0.3 s"\n',
        "move[1].accel_time",
        "fit in the move",
    ),
    (
        HEAD + TABLE + '[[move]]\ndistance = "90 deg"\ntime = "0.5 s"\naccel_time = "0.2 s"\ndecel_time = "0.31 s"\n',
        "move[1].accel_time",
        "0.2 s + 0.31 s > 0.5 s",
    ),
    (
        HEAD + TABLE + '[[move]]\ndistance = "90 deg"\ntime = "0.5 s"\naccel_time = "0.1 s"\njerk_time = "0.06 s"\n',
        "move[1].jerk_time",
        "at most half",
    ),
    (
        HEAD + TABLE + MOVE.format(distance="100 mm"),
        "move[1].distance",
        "a rotary mechanism moves its load by an angle",
    ),
    (
        HEAD + SCREW + MOVE.format(distance="90 deg"),
        "move[1].distance",
        "a ball-screw mechanism moves its load by a length",
    ),
    (HEAD + SCREW + MOVE.format(distance="2 s"), "move[1].distance", "which is a time"),
    (HEAD + TABLE + MOVE.format(distance="0 deg"), "move[1].distance", "other than zero"),
    (
        HEAD + TABLE + '[[move]]\ndistance = "90 deg"\ntime = "0 s"\naccel_time = "0.1 s"\n',
        "move[1].time",
        "above zero",
    ),
    (
        HEAD + TABLE + '[[move]]\ndistance = "90 deg"\ntime = "0.5 s"\naccel_time = "-0.1 s"\n',
        "move[1].accel_time",
        "above zero",
    ),
    (
        HEAD
        + TABLE
        + '[[move]]\ndwell = "-1 s"\n[[move]]\ndistance = "90 deg"\ntime = "0.5 s"\naccel_time = "0.1 s"\n',
        "move[1].dwell",
        "above zero",
    ),
    (
        HEAD + SCREW.replace('lead = "20 mm"', 'lead = "0 mm"') + MOVE.format(distance="1 mm"),
        "mechanism.lead",
        "above zero",
    ),
    (
        HEAD + SCREW.replace("mass = \"50 kg\"", "mass = \"-5 kg\"") + MOVE.format(distance="1 mm"),
        "mechanism.mass",
        "above zero",
    ),
    (
        HEAD + SCREW.replace("eta = 0.9", "eta = 0") + MOVE.format(distance="1 mm"),
        "mechanism.eta",
        "an efficiency above zero",
    ),
    (HEAD + SCREW.replace("eta = 0.9", "eta = 1.2") + MOVE.format(distance="1 mm"), "mechanism.eta", "at most 1"),
    (
        HEAD
        + SCREW.replace('type = "ball-screw"', 'type = "belt"').replace('lead = "20 mm"', 'pulley_diameter = "-60 mm"')
        + MOVE.format(distance="1 mm"),
        "mechanism.pulley_diameter",
        "above zero",
    ),
    (
        HEAD
        + SCREW.replace('type = "ball-screw"', 'type = "rack-pinion"').replace(
            'lead = "20 mm"', 'pitch_diameter = "0 mm"'
        )
        + MOVE.format(distance="1 mm"),
        "mechanism.pitch_diameter",
        "above zero",
    ),
    (
        HEAD + SCREW + "friction_coefficient = -0.1\n" + MOVE.format(distance="1 mm"),
        "mechanism.friction_coefficient",
        "zero or more",
    ),
    (
        HEAD + TABLE + 'friction_torque = "-1 N*m"\n'.replace("friction", "process") + MOVE.format(distance="90 deg"),
        "mechanism.process_torque",
        "zero or more",
    ),
    (
        HEAD + TABLE + '[[move]]\ndistance = "90 deg"\ndwell = "0.5 s"\n',
        "move[1].distance",
        "a dwell takes only its time",
    ),
    (HEAD + TABLE + '[[move]]\ntime = "0.5 s"\n', "move[1].distance", "found neither"),
    (HEAD + TABLE + '[[move]]\ndwell = "0.5 s"\n', "move", "only dwells"),
    ("move = []\n" + HEAD + TABLE, "move", "found none"),
    (HEAD + PROFILE_TOML + TABLE + MOVE.format(distance="90 deg"), "move", "given as profile already"),
    (
        HEAD + TABLE + MOVE.format(distance="90 deg") + '[drive_record]\nfile = "rec.csv"\n',
        "drive_record",
        "given as move already",
    ),
    (HEAD + MOVE.format(distance="90 deg"), "move", "need the mechanism"),
    (HEAD + TABLE + PROFILE_TOML, "mechanism", "found [[profile]]"),
    (HEAD + TABLE, "mechanism", "found neither"),
    (
        HEAD + '[load]\ninertia = "1 kg*m**2"\n' + TABLE + MOVE.format(distance="90 deg"),
        "load.inertia",
        "the mechanism gives",
    ),
]


@pytest.mark.parametrize("text, key, fragment", ERRORS, ids=[f"{k}-{f}" for _, k, f in ERRORS])
def test_bad_motion_input_is_one_line_naming_the_key(capsys, write_case, text, key, fragment):
    path = write_case(text)
    code, out, err = run(capsys, path, "--json")
    assert code == 2 and out == ""
    line = err.strip()
    assert "\n" not in line
    assert f"{path}: {key}" in line and fragment in line, line


RECORDS = [
    ("time [s],speed [rpm]\n0,0\n0.1,100\n0.1,0\n", "", "expected times that increase"),
    ("time [s],torque [N*m]\n0,0\n0.1,1\n", "", "expected a column 'speed [unit]'"),
    ("speed [rpm]\n0\n100\n", TABLE, "expected a column 'time [unit]'"),
    ("time [s],speed [rpm]\n0,0\n", TABLE, "at least two rows"),
    ("time [s],speed [rpm]\n0,0\n1,10\n", "", "drive_record.file: the record has no torque column"),
    ("time [s],speed [m/s]\n0,0\n1,10\n", TABLE, "expected a unit of speed"),
]


@pytest.mark.parametrize("csv, mechanism, fragment", RECORDS, ids=[f for _, _, f in RECORDS])
def test_a_bad_drive_record_is_one_line(capsys, write_case, tmp_path, csv, mechanism, fragment):
    (tmp_path / "rec.csv").write_text(csv)
    code, out, err = run(capsys, write_case(HEAD + mechanism + '[drive_record]\nfile = "rec.csv"\n'), "--json")
    assert code == 2 and out == ""
    assert "\n" not in err.strip() and fragment in err, err


def test_one_cycle_of_two_moves_gives_the_verdict_of_two_cycles_of_one_e16(capsys, tmp_path):
    # The example's motion written twice in one cycle (index, 1 s, index, 1 s) is physically the example: E16 counts
    # load cycles (moves) per hour, so Z_h = 2 · 3600 / 3 s = 3600 / 1.5 s = 2400 /h either way (f_s 1.6, E4), and
    # T_2max, the gearbox and the verdict do not change.
    from ..conftest import DERIVED_EXAMPLE

    text = DERIVED_EXAMPLE.read_text()
    moves = '[[move]]\ndistance = "90 deg"\ntime = "0.5 s"\naccel_time = "0.15 s"\njerk_time = "0.03 s"\n' \
            '[[move]]\ndwell = "1.0 s"\n'
    assert moves in text
    twice = tmp_path / "indexing-table-twice.toml"
    # Beside the example, its measurement files are found where the example finds them.
    twice.write_text(text.replace(moves, moves + moves).replace('"../data/', f'"{DERIVED_EXAMPLE.parent.parent}/data/'))
    (code1, out1, _), (code2, out2, err2) = run(capsys, DERIVED_EXAMPLE, "--json"), run(capsys, twice, "--json")
    assert code1 == code2 == 0, err2
    one, two = json.loads(out1), json.loads(out2)
    assert one["duty"]["t_cycle"]["value"] == pytest.approx(1.5) and two["duty"]["t_cycle"]["value"] == pytest.approx(3)
    assert one["cyclic"]["Zh"]["value"] == pytest.approx(2400) and two["cyclic"]["Zh"]["value"] == pytest.approx(2400)
    assert two["cyclic"]["fs"] == one["cyclic"]["fs"] == 1.6
    for key in ("T2max", "n2max"):
        assert two["cyclic"][key]["value"] == pytest.approx(one["cyclic"][key]["value"], rel=1e-12), key
    assert two["gearbox"]["selected"] == one["gearbox"]["selected"] == "NPT035-10"
    assert two["verdict"] == one["verdict"]
