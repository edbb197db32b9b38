"""The dynamics section (calc.sections.dynamics) on the example and on variants of it: the same chain
and frequencies as coupling.torsion, λ as the motor's check takes it with its meaning, the stiffness
basis of each spring, the torque reversals, the check at the working point on a K1–K3 curve, and
the three states of a check without its data (a coupling row without C_T)."""

import math

import pytest

from calc.sections import evaluate
from calc.sections.case import read_case

from ..conftest import DERIVED_EXAMPLE


@pytest.fixture(scope="module")
def example():
    return evaluate(read_case(DERIVED_EXAMPLE))


def test_same_chain_and_frequencies_as_coupling_torsion(example):
    d, t = example["dynamics"].to_json(), example["coupling"].torsion.to_json()
    assert [m["J"] for m in d["masses"]] == [m["J"] for m in t["masses"]]
    assert [f["value"] for f in d["natural_frequencies"]] == pytest.approx(
        [f["value"] for f in t["natural_frequencies"]], rel=1e-12)
    assert d["natural_frequencies"][0]["value"] == pytest.approx(265.5, abs=0.05)


def test_anti_resonance_sits_on_the_speed_loop(example):
    d = example["dynamics"].to_json()
    z = [f["value"] for f in d["anti_resonances"]]
    assert z == sorted(z)
    # The motor held: coupling-and-gearbox mass 1.18 kg·cm² hangs on 8000 N·m/rad to the ground and on
    # 756.3 N·m/rad to the table's 15 kg·cm²; the lower root is near the table alone on the gearbox,
    # √(756.3 / 15e-4) / 2π = 113.0 Hz, pulled down by the coupling's compliance to 108.0 Hz.
    assert z[0] == pytest.approx(108.0, abs=0.1)
    f_ar = next(k for k in d["checks"] if k["name"] == "f_ar,1")
    assert f_ar["governs"] is False and f_ar["passes"] is False  # 2 f_er = 200 Hz above it: for information


def test_one_lambda_with_its_meaning(example):
    d = example["dynamics"].to_json()
    lam = d["inertia_ratio"]
    # λ = (J_K + J_1 + J_L / i²) / J_motor = (0.5 + 0.93 + 15) / 1.74 = 9.4425, the motor's check's λ.
    assert lam["value"] == pytest.approx(16.43 / 1.74, rel=1e-9)
    motor = next(k for k in example["motor"].to_json()["checks"] if k["name"] == "lambda")
    assert motor["required"]["value"] == pytest.approx(lam["value"], rel=1e-9)
    assert d["resonance_ratio"] == pytest.approx(math.sqrt(1 + lam["value"]), rel=1e-12)
    assert "√(1 + λ)" in lam["meaning"] and lam["limit"] == 10


def test_stiffness_basis_and_reversals(example):
    d = example["dynamics"].to_json()
    gearbox = next(s for s in d["springs"] if s["name"] == "gearbox")
    assert gearbox["basis"].startswith("C_t21 of NPT035-10")
    assert [gearbox["band"]["from"]["value"], gearbox["band"]["to"]["value"]] == [55.0, 110.0]  # 50 to 100 % of T_2N
    assert gearbox["outside_band"] is True
    f_1 = next(k for k in d["checks"] if k["name"] == "f_1")
    assert f_1["passes"] is True and "outside its band" in f_1["basis"]
    model = next(k for k in d["checks"] if k["name"] == "f_1,model")
    assert model["governs"] is False and model["rated"]["value"] < 200  # the loop model would flip the verdict
    # accelerate +7.83, run +3, brake -2.35, dwell 0: two reversals per cycle, 8 arcmin each.
    assert d["torque_reversals"] == {"per_cycle": 2, "backlash_crossed": {"value": 8.0, "unit": "arcmin"}}


CURVE = '''name = "NPT035-10"
side = "output"
backlash = "8 arcmin"
transmission_accuracy = "63 arcsec"
nominal_torque = "110 N*m"
stiffness_curve = { T1 = "5 N*m", T2 = "50 N*m", K1 = "8 N*m/arcmin", K2 = "15 N*m/arcmin", K3 = "22 N*m/arcmin" }
'''


def test_check_at_the_working_point_on_a_curve(write_case):
    text = DERIVED_EXAMPLE.read_text()
    start = text.index('[[accuracy.component]]\npart = "selected"                        # the gearbox')
    text = text[:start] + "[[accuracy.component]]\n" + CURVE
    r = evaluate(read_case(write_case(text)))["dynamics"].to_json()
    gearbox = next(s for s in r["springs"] if s["name"] == "gearbox")
    # The working torques are 2.348, 3 and 7.827 N·m: the first two on K1 = 8 N·m/arcmin, the last on K2;
    # the softest slope governs, K1, at the input 8 · 3437.75 / 10² = 275.0 N·m/rad.
    assert gearbox["C"]["value"] == pytest.approx(8 * 60 * 180 / math.pi / 100, rel=1e-9)
    assert gearbox["band"]["to"]["value"] == 5.0 and "K1" in gearbox["basis"]
    f_1 = next(k for k in r["checks"] if k["name"] == "f_1")
    assert f_1["governs"] is True and f_1["passes"] is False  # far below 2 f_er at K1
    assert not any(k["name"] == "f_1,model" for k in r["checks"])  # a curve given: no loop model needed


def test_a_coupling_row_without_its_stiffness_is_not_checked(write_case):
    # GS9-98ShA (KTR ROTEX GS, elastomer): the catalog leaves C_T and J empty.
    text = (DERIVED_EXAMPLE.read_text().replace('type = "bellows"', 'part = "GS9-98ShA"')
            .replace('shaft_1 = "19 mm k6"  ', 'shaft_1 = "10 mm k6"  ')
            .replace('shaft_2 = "16 mm h7" ', 'shaft_2 = "10 mm h7" ')
            .replace('kind = "coupling"\npart = "selected"',
                     'name = "GS9"\nside = "input"\nstiffness = "100 N*m/arcmin"\nbacklash = "0 arcmin"'))
    text = text.replace('"../data/', f'"{DERIVED_EXAMPLE.parent.parent / "data"}/')
    results = evaluate(read_case(write_case(text)))
    t = results["coupling"].torsion.to_json()
    assert t["complete"] is False and any("C" in m or "stiffness" in m for m in t["missing"])
    assert t["checks"][0]["passes"] is None and "leaves empty" in t["checks"][0]["not_made"]
    d = results["dynamics"].to_json()
    assert d["complete"] is False and d["natural_frequencies"] == []
    assert d["checks"][0]["passes"] is None and d["checks"][0]["not_made"]


def test_the_ratio_search_names_the_inertia_matching_ratio():
    from calc.sections.ratios import search

    r = search(read_case(DERIVED_EXAMPLE))
    best = r.to_json()["optimal_ratio"]
    # √(1500 / (1.74 + 0.5 + 0.93)) = 21.753; the search picks 10, the least RMS motor torque within λ <= 10.
    assert best["value"] == pytest.approx(math.sqrt(1500 / 3.17), rel=1e-9)
    assert best["J_in"]["value"] == pytest.approx(3.17) and best["pick"] == 10
    assert "coupling AKN-18" in best["inertias"] and "i_opt = 21.75" in r.summary()


def test_the_results_fit_the_schema(capsys, write_case):
    # The example's evaluate --json against docs/results.schema.json, which now describes dynamics and the budget.
    from calc.__main__ import main

    from ..conftest import check_results

    main(["evaluate", str(DERIVED_EXAMPLE), "--json"])
    results = check_results(capsys.readouterr().out)
    assert results["dynamics"]["torque_reversals"]["per_cycle"] == 2
    assert results["accuracy"]["budget"]["contributions"][0]["kind"] == "systematic"
