"""``python -m calc evaluate`` with a ``[coupling]`` section: the contract, and one-line errors."""

import json
import subprocess
import sys

import pytest


from ..conftest import EXAMPLE, HEAD_TOML, PROFILE_TOML, run

COUPLING_TOML = """
[coupling]
type = "bellows"
accel_torque = "12 N*m"
drive_inertia = "4.2 kg*cm**2"
load_inertia = "15.93 kg*cm**2"
excitation_frequency = "150 Hz"
speed = "3000 rpm"
shaft_1 = "19 mm k6"
shaft_2 = "16 mm h7"
"""


def case_with(write_case, coupling: str):
    return write_case(HEAD_TOML + PROFILE_TOML + coupling)


def test_example_gets_a_coupling_with_its_order_line():
    proc = subprocess.run(
        [sys.executable, "-m", "calc", "evaluate", str(EXAMPLE), "--json"], capture_output=True, text=True
    )
    assert proc.returncode == 0, proc.stderr
    c = json.loads(proc.stdout)["coupling"]
    assert set(c) >= {"M_N", "temperature_factor", "candidates", "selected", "order"}
    # Hand calculation (tests/domain/test_coupling.py): M_N = 12 · 15.93 / 20.13 · 2.5 = 23.7407 N·m.
    assert c["M_N"] == {"value": pytest.approx(23.7407, abs=1e-4), "unit": "N*m"}
    assert c["temperature_factor"] == 1.0  # a metal bellows coupling gets no factor (E9)
    assert c["selected"] == "AKD-30"
    assert c["order"] == "Standard coupling AKD-30; D1 = 19 mm k6; D2 = 16 mm h7"
    first = c["candidates"][0]
    assert first["part"] == "AKD-30" and first["passes"] is True
    assert first["f_e"] == {"value": pytest.approx(1316.35, abs=0.01), "unit": "Hz"}
    assert set(first["checks"][0]) >= {"name", "required", "rated", "utilization", "passes"}
    assert [k["name"] for k in first["checks"]] == [
        "T_KN",
        "f_e",
        "f_1",
        "n_max",
        "d_1min",
        "d_1max",
        "d_2min",
        "d_2max",
    ]
    assert c["bores"][0]["lower"] == {"value": pytest.approx(19.002), "unit": "mm"}


def test_summary_shows_the_coupling(capsys):
    code, out, err = run(capsys, EXAMPLE)
    assert code == 0 and err == ""
    assert "Selected coupling: AKD-30" in out
    assert "Order: Standard coupling AKD-30; D1 = 19 mm k6; D2 = 16 mm h7" in out
    assert "rejected: M_N · K_ϑ <= T_KN: required 23.74 N·m > rated 22 N·m, 7.91 % over" in out


def test_the_spec_example_section_is_accepted(capsys, write_case):
    # The [coupling] table of docs/case-format.md, as written there.
    spec = """
[coupling]
catalog = "couplings"
type = "elastomer"
accel_torque = "12 N*m"
drive_inertia = "1.5 kg*cm**2"
load_inertia = "30 kg*cm**2"
service_factor = 2.5
temperature = "60 degC"
excitation_frequency = "40 Hz"
shaft_1 = "14 mm k6"
shaft_2 = "1.000 in"
"""
    code, out, err = run(capsys, case_with(write_case, spec), "--json")
    assert code == 0, err
    c = json.loads(out)["coupling"]
    # E9: 60 °C lies in 50 <= T < 70, factor 1.3. M_N = 12 · 30 / 31.5 · 2.5 = 28.571 N·m.
    assert c["temperature_factor"] == 1.3
    assert c["M_N"]["value"] == pytest.approx(28.5714, abs=1e-4)
    assert c["candidates"][0]["required_torque"]["value"] == pytest.approx(28.5714 * 1.3, abs=1e-3)
    assert c["selected"] is None and c["order"] is None
    assert any("shaft_2 gives no tolerance" in n for n in c["notes"])


def test_safety_coupling_order_carries_its_disengagement_torque(capsys, write_case):
    text = COUPLING_TOML.replace('"bellows"', '"safety"') + 'disengagement_torque = "25 N*m"\n'
    code, out, err = run(capsys, case_with(write_case, text), "--json")
    c = json.loads(out)["coupling"]
    assert c["selected"] == "SKB-30"
    assert c["order"] == "Safety coupling SKB-30; D1 = 19 mm k6; D2 = 16 mm h7; T_A (disengagement torque) = 25 N·m"


def test_a_named_part_is_checked_alone(capsys, write_case):
    text = COUPLING_TOML.replace('type = "bellows"', 'part = "AKD-18"')
    c = json.loads(run(capsys, case_with(write_case, text), "--json")[1])["coupling"]
    assert [k["part"] for k in c["candidates"]] == ["AKD-18"] and c["selected"] is None


def test_a_bore_outside_every_hub_is_a_failing_check(capsys, write_case):
    code, out, err = run(capsys, case_with(write_case, COUPLING_TOML.replace('"19 mm k6"', '"90 mm k6"')), "--json")
    assert code == 0
    c = json.loads(out)["coupling"]
    assert c["selected"] is None
    akd30 = next(k for k in c["candidates"] if k["part"] == "AKD-30")
    assert akd30["reasons"] == ["D_1 <= d_1max: required 90 mm > rated 30 mm, 200 % over"]


@pytest.mark.parametrize(
    "old, new, fragment",
    [
        ('"4.2 kg*cm**2"\nload', '"-4.2 kg*cm**2"\nload', "coupling.drive_inertia: expected an inertia above zero"),
        ('"15.93 kg*cm**2"', '"0 kg*cm**2"', "coupling.load_inertia: expected an inertia above zero"),
        ('"15.93 kg*cm**2"', '"15.93 kg"', "coupling.load_inertia: expected an inertia such as"),
        ('"150 Hz"', '"150 Hz"\ntemperature = "60 C"', "coupling.temperature: expected a temperature such as"),
        (
            '"bellows"',
            '"rubber"',
            "coupling.type: unknown coupling type 'rubber'; expected one of bellows, elastomer, safety, line-shaft",
        ),
        ('"19 mm k6"', '"14 mm q99"', "coupling.shaft_1 ('14 mm q99'): unknown ISO 286 tolerance class 'q99'"),
        ('"19 mm k6"', '"14 mm k"', "coupling.shaft_1: expected a shaft size with its tolerance such as"),
        (
            '"150 Hz"',
            '"150 Hz"\ndisengagement_torque = "25 N*m"',
            "coupling.disengagement_torque: a disengagement torque T_A (E10) is for safety couplings only",
        ),
        (
            '"bellows"',
            '"safety"',
            "coupling.disengagement_torque: safety couplings need a disengagement torque T_A (E10), found none",
        ),
        (
            '"bellows"',
            '"line-shaft"',
            "coupling.shaft_distance: line-shaft couplings need a distance between shafts, found none",
        ),
        (
            'type = "bellows"',
            'type = "line-shaft"\nshaft_distance = "120 mm"',
            "coupling.shaft_distance: 120 mm is shorter than the two hubs of every line shaft",
        ),
        (
            '"150 Hz"',
            '"150 Hz"\nshaft_distance = "915 mm"',
            "coupling.shaft_distance: a distance between shafts is for line-shaft couplings only",
        ),
        ('"150 Hz"', '"3000 rpm"', "coupling.excitation_frequency: expected a frequency such as"),
        ('excitation_frequency = "150 Hz"\n', "", "coupling.excitation_frequency: expected a value, found none"),
        ('shaft_2 = "16 mm h7"\n', "", "coupling.shaft_2: expected a value, found none"),
        (
            'type = "bellows"',
            'type = "bellows"\nservice_factor = 0.5',
            "coupling.service_factor: expected a load factor S_A of 1 or more (E8), found 0.5",
        ),
        ('type = "bellows"', 'type = "bellows"\ncolour = "red"', "coupling.colour: unknown key"),
        ('type = "bellows"', 'part = "XK-1"', "coupling.part: no part 'XK-1' in catalog"),
        (
            'type = "bellows"',
            'type = "bellows"\npart = "SKB-30"',
            "coupling.part: SKB-30 is a safety coupling, but coupling.type is 'bellows'",
        ),
        (
            'type = "bellows"',
            'type = "bellows"\ncatalog = "nosuch"',
            "coupling.catalog: the catalog 'nosuch' does not exist",
        ),
        (
            'type = "bellows"',
            'type = "elastomer"',
            "coupling.temperature: elastomer couplings need the operating temperature",
        ),
    ],
)
def test_bad_coupling_input_gives_one_line_naming_file_and_key(capsys, write_case, old, new, fragment):
    assert old in COUPLING_TOML
    path = case_with(write_case, COUPLING_TOML.replace(old, new, 1))
    code, out, err = run(capsys, path, "--json")
    assert code != 0
    assert out == ""
    assert err.count("\n") == 1 and err.startswith("error: ")
    assert str(path) in err
    assert fragment in err


def test_a_bad_coupling_catalog_names_file_row_and_column(capsys, write_case, tmp_path):
    from calc.data.catalog import resolve

    good = resolve("couplings", None, "catalog").read_text()
    (tmp_path / "my.csv").write_text(good.replace("AKD-30,AKD,30,bellows,36,", "AKD-30,AKD,30,bellows,3x6,"))
    path = case_with(write_case, COUPLING_TOML.replace('type = "bellows"', 'type = "bellows"\ncatalog = "my.csv"'))
    code, out, err = run(capsys, path, "--json")
    assert code != 0 and out == ""
    assert f"{tmp_path / 'my.csv'}, row 3 (AKD-30), column T_KN: expected a number, found '3x6'" in err


def test_a_type_the_catalog_lacks_names_the_catalog(capsys, write_case, tmp_path):
    # A catalog of the header and the safety rows only: no bellows coupling to choose from.
    from calc.data.catalog import resolve

    lines = resolve("couplings", None, "catalog").read_text().splitlines()
    (tmp_path / "safety.csv").write_text("\n".join([lines[0], *(l for l in lines[1:] if ",safety," in l)]) + "\n")
    path = case_with(write_case, COUPLING_TOML.replace('type = "bellows"', 'type = "bellows"\ncatalog = "safety.csv"'))
    code, out, err = run(capsys, path, "--json")
    assert code == 2 and out == ""
    assert f"coupling.type: the catalog {tmp_path / 'safety.csv'} has no bellows coupling" in err


# f_er = 100 Hz, as the example: with the gearbox's spring in the chain, its first mode is 208 Hz
# (tests/domain/test_torsion.py), so 2 f_er may be at most that.
INPUT_SIDE = """
[coupling]
type = "bellows"
side = "input"
excitation_frequency = "100 Hz"
shaft_1 = "19 mm k6"
shaft_2 = "16 mm h7"
"""


def test_a_motor_side_coupling_takes_its_inputs_from_the_case(capsys, write_case):
    derived = json.loads(run(capsys, case_with(write_case, INPUT_SIDE), "--json")[1])
    explicit = json.loads(run(capsys, case_with(write_case, COUPLING_TOML), "--json")[1])
    # By hand (E8): J_load = J_L / i² + J_1 = 1500 / 10² + 0.93 (NPT035-10, selected) = 15.93 kg·cm²;
    # M_a = motor.peak_torque = 12 N·m; J_drive = motor.inertia = 4.2 kg·cm²; speed = 300 rpm · 10 = 3000 rpm.
    # COUPLING_TOML states the same four values by hand, so every result agrees.
    c, e = derived["coupling"], explicit["coupling"]
    assert c["M_N"]["value"] == pytest.approx(e["M_N"]["value"], rel=1e-12)
    assert c["M_N"]["value"] == pytest.approx(12 * 15.93 / (15.93 + 4.2) * 2.5, rel=1e-12)
    f_e = {k["part"]: k["f_e"]["value"] for k in e["candidates"]}
    assert [k["f_e"]["value"] for k in c["candidates"]] == pytest.approx(
        [f_e[k["part"]] for k in c["candidates"]], rel=1e-12
    )
    # The ranking may differ: only the derived case places the gearbox in the chain (side = "input"),
    # where its first mode governs; without a side it is reported for information.
    assert c["torsion"]["complete"] and not e["torsion"]["complete"]
    assert e["torsion"]["missing"] == ["coupling.side (where the coupling sits: input or output of the gearbox)"]
    assert c["selected"] == e["selected"] == "AKD-30"
    assert c["order"] == e["order"]
    assert any("J_load = J_L / i² + J_1" in n and "15.93 kg·cm²" in n and "NPT035-10" in n for n in c["notes"])


def test_the_derived_load_inertia_follows_the_ratio(capsys, write_case):
    text = HEAD_TOML.replace("ratio = 10", "ratio = 8") + PROFILE_TOML + INPUT_SIDE
    r = json.loads(run(capsys, write_case(text), "--json")[1])
    selected = r["gearbox"]["selected"]
    # catalogs/gearboxes.csv, J_1 for the smallest clamping hub (Beckhoff pages 'TP010 MF', 'NPT035 MF').
    J_1 = {"TP010-8": 0.48, "NPT035-8": 1.0}[selected]
    # E8 by hand: J_load = 1500 / 8² + J_1; M_N = 12 · J_load / (J_load + 4.2) · 2.5.
    J_load = 1500 / 64 + J_1
    assert r["coupling"]["M_N"]["value"] == pytest.approx(12 * J_load / (J_load + 4.2) * 2.5, rel=1e-12)
    assert any(f"{J_load:.4g} kg·cm²" in n for n in r["coupling"]["notes"])


def test_keys_given_are_used_as_given(capsys, write_case):
    text = INPUT_SIDE.replace('side = "input"', 'side = "input"\nload_inertia = "30 kg*cm**2"')
    r = json.loads(run(capsys, case_with(write_case, text), "--json")[1])
    # M_N = 12 · 30 / (30 + 4.2) · 2.5 (the given J_load, not the derived 15.93).
    assert r["coupling"]["M_N"]["value"] == pytest.approx(12 * 30 / 34.2 * 2.5, rel=1e-12)
    assert not any("load_inertia" in n for n in r["coupling"]["notes"])


@pytest.mark.parametrize(
    "text, fragment",
    [
        (
            HEAD_TOML + PROFILE_TOML + INPUT_SIDE.replace('"input"', '"motor"'),
            "coupling.side: expected one of input, output, found 'motor'",
        ),
        (
            HEAD_TOML + PROFILE_TOML + INPUT_SIDE.replace('excitation_frequency = "100 Hz"\n', ""),
            "coupling.excitation_frequency: expected a value (with side = \"input\" it comes from [motor], [load] "
            "and the gearbox when they give it), found none",
        ),
    ],
)
def test_bad_side(capsys, write_case, text, fragment):
    path = write_case(text)
    code, out, err = run(capsys, path, "--json")
    assert code != 0 and out == "" and fragment in err and str(path) in err


def test_an_input_side_coupling_without_the_load_inertia(capsys, write_case):
    # A partial case (the contract): no [load] inertia, so J_load = J_L / i² + J_1 cannot be
    # formed. The torque and resonance checks, which need it, are not made and name it; the speed
    # and bore checks are made; no coupling is chosen and the verdict is not decided.
    path = write_case(HEAD_TOML.replace('[load]\ninertia = "1500 kg*cm**2"\n', "") + PROFILE_TOML + INPUT_SIDE)
    r = json.loads(run(capsys, path, "--json")[1])
    checks = {k["name"]: k for k in r["coupling"]["candidates"][0]["checks"]}
    for name in ("T_KN", "f_e"):
        assert checks[name]["passes"] is None
        assert checks[name]["not_made"] == "needs load.inertia (or the mechanism's), or coupling.load_inertia"
    assert checks["n_max"]["passes"] is True and checks["d_1max"]["passes"] is True
    assert r["coupling"]["selected"] is None and r["verdict"]["passes"] is None
