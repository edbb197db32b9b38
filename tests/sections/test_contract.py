"""The second round of the contract (docs/case-format.md, "What every run promises"): one verdict,
partial cases, exit status, finite numbers, bounded candidate lists and ``part = "selected"``.

Numbers are worked by hand from the example's load cycle (tests/conftest.py): ED 50 % (S5), Z_h =
1800 /h so f_s = 1.3 (E4); NPT035-10 has T_2B = 220 N·m, eta = 0.97, n_1max = 6000 rpm.
"""

import csv
import json

import pytest

from ..conftest import EXAMPLE, HEAD_TOML, PROFILE_TOML, ROOT, derived_with_typed_motor, run

COUPLING_TOML = """
[coupling]
type = "bellows"
side = "input"
service_factor = 2.5
excitation_frequency = "100 Hz"
shaft_1 = "19 mm k6"
shaft_2 = "16 mm h7"
"""


def results(capsys, path, *options):
    code, out, err = run(capsys, path, "--json", *options)
    assert code == 0, err
    return json.loads(out)


def test_a_passing_case_has_a_true_verdict(capsys):
    r = results(capsys, EXAMPLE)
    assert r["verdict"] == {"passes": True, "reasons": []}


def test_a_failing_case_says_which_check_and_by_how_much(capsys, write_case):
    # T_1B = 400 N·m: T_2max = 400 · 10 · 1.3 · 0.95 = 4940 N·m > T_2B = 4000 N·m of TP500-10, the
    # largest at i = 10 (η 0.95, Beckhoff page 'TP500 MF'): 23.5 % over, the closest to passing.
    r = results(capsys, write_case(HEAD_TOML.replace('"12 N*m"', '"400 N*m"') + PROFILE_TOML))
    assert r["verdict"]["passes"] is False
    assert r["verdict"]["reasons"][0] == "No gearbox of ratio 10 in catalogs/gearboxes.csv passes the S5 checks:"
    assert r["verdict"]["reasons"][1] == "TP500-10: T_2max <= T_2B: required 4940 N·m > rated 4000 N·m, 23.5 % over"


def test_s5_without_peak_torque_evaluates_every_section(capsys, write_case):
    # Partial case: no motor.peak_torque. Duty, S1, S5 values, candidates, coupling and accuracy still come;
    # the check T_2max <= T_2B is not made, nothing is selected and the verdict is null, naming the key.
    accuracy = ('\n[accuracy]\napplied_torque = "8 N*m"\nnominal_torque = "100 N*m"\n[[accuracy.component]]\n'
                'name = "shaft"\nside = "output"\nstiffness = "20 N*m/arcmin"\nbacklash = "1 arcmin"\n')
    case = write_case(HEAD_TOML.replace('peak_torque = "12 N*m"\n', "") + PROFILE_TOML
                      + COUPLING_TOML.replace("[coupling]", '[coupling]\naccel_torque = "12 N*m"') + accuracy)
    r = results(capsys, case)
    assert r["duty"]["mode"] == "S5" and r["cyclic"]["fs"] == 1.3
    assert r["gearbox"]["selected"] is None
    best = r["gearbox"]["candidates"][0]
    t2b = next(k for k in best["checks"] if k["name"] == "T_2B")
    assert t2b["passes"] is None and t2b["required"] is None and "motor.peak_torque" in t2b["not_made"]
    # Every row passes the checks made. Those whose drive train some bellows coupling lifts above
    # 2 f_er = 200 Hz (f_1,max) rank first, the smallest T_2B of them first: TP010-10 (126 N·m), where
    # NPT005-10 (13 N·m) would leave the train at 47 Hz. n_2max · i = 300 · 10 = 3000 rpm against
    # TP010-10's n_1max of 7500 rpm is made without T_1B: 0.4.
    assert best["part"] == "TP010-10" and best["passes"] is None
    assert next(k for k in best["checks"] if k["name"] == "n_1max")["utilization"] == pytest.approx(0.4)
    assert next(k for k in best["checks"] if k["name"] == "f_1")["passes"] is True
    assert r["coupling"]["selected"] == "AKD-30" and r["accuracy"]["C_total"]["value"] == pytest.approx(20)
    assert r["verdict"]["passes"] is None
    assert any("motor.peak_torque" in reason for reason in r["verdict"]["reasons"])
    code, out, _ = run(capsys, case)
    assert code == 0 and "Verdict: NOT DECIDED" in out


def test_an_input_side_coupling_without_the_motors_peak_torque(capsys, write_case):
    # The same partial case with the coupling taking M_a from [motor] (side = "input"), as the
    # contract's example says: the coupling's torque check T_KN is not made, naming
    # motor.peak_torque; its resonance, speed and bore checks are made; no coupling is chosen.
    case = write_case(HEAD_TOML.replace('peak_torque = "12 N*m"\n', "") + PROFILE_TOML + COUPLING_TOML)
    r = results(capsys, case)
    c = r["coupling"]
    assert c["selected"] is None and c["M_N"]["value"] is None
    best = c["candidates"][0]
    checks = {k["name"]: k for k in best["checks"]}
    assert checks["T_KN"]["passes"] is None and checks["T_KN"]["required"] is None
    assert checks["T_KN"]["not_made"] == "needs motor.peak_torque (or coupling.accel_torque)"
    # f_e is made: J_load = 1500 / 10² + J_1 of the best-ranked gearbox, J_drive = motor.inertia.
    assert checks["f_e"]["passes"] is True and checks["n_max"]["passes"] is True
    assert best["passes"] is None and "T_KN" in " ".join(best["reasons"])
    assert r["verdict"]["passes"] is None
    assert ("No coupling can be chosen: M_N · K_ϑ <= T_KN: not checked, needs motor.peak_torque "
            "(or coupling.accel_torque)") in r["verdict"]["reasons"]
    code, out, _ = run(capsys, case)
    assert code == 0 and "Selected coupling: none: M_N · K_ϑ <= T_KN: not checked, needs motor.peak_torque" in out


def test_the_motor_and_coupling_without_the_gearboxs_J_1(capsys, write_case, tmp_path):
    # The derived example through a catalog that leaves every J_1 empty (and no motor.shaft, so no
    # clamping-hub table gives one): the motor's torques need J_1 in the rotor term, the input-side
    # coupling needs it in J_load = J_L / i² + J_1. Their checks are not made, naming J_1 and the
    # part; the motor's speed check (n_2max · i = 42.86 · 10 = 428.6 rpm) is still made.
    rows = list(csv.reader((ROOT / "catalogs" / "gearboxes.csv").open(encoding="utf-8")))
    j_1, partial = rows[0].index("J_1 [kg*cm**2]"), rows[0].index("partial")
    for row in rows[1:]:
        if not row[partial]:
            row[j_1] = ""
    (tmp_path / "data").symlink_to(ROOT / "data")
    folder = tmp_path / "cases"
    folder.mkdir()
    with (folder / "no-j1.csv").open("w", encoding="utf-8", newline="") as f:
        csv.writer(f, lineterminator="\n").writerows(rows)
    text = derived_with_typed_motor().replace('catalog = "gearboxes"\n', 'catalog = "no-j1.csv"\n')
    text = text.replace('shaft = "19 mm k6" ', 'max_speed = "6000 rpm" ').replace(
        'peak_torque = "12 N*m"', 'peak_torque = "12 N*m"\nrated_torque = "4 N*m"')
    case = write_case(text, "cases/no-j1.toml")
    r = results(capsys, case)
    motor = {k["name"]: k for k in r["motor"]["checks"]}
    for name in ("T_1B", "T_1N"):
        assert motor[name]["passes"] is None and motor[name]["required"] is None
        assert motor[name]["not_made"] == ("the rotor term (J_motor + J_1) · α_1 needs J_1, "
                                           "which the catalog does not give for NPT035-10")
    assert motor["n_max"]["passes"] is True and motor["n_max"]["required"]["value"] == pytest.approx(428.57, abs=0.01)
    assert r["motor"]["peak_torque_required"] is None
    f_e = next(k for k in r["coupling"]["candidates"][0]["checks"] if k["name"] == "f_e")
    assert f_e["passes"] is None
    assert "the gearbox's J_1, which" in f_e["not_made"] and "for NPT035-10" in f_e["not_made"]
    assert r["gearbox"]["selected"] == "NPT035-10" and r["accuracy"]["positioning_accuracy"]["value"] is not None
    assert r["verdict"]["passes"] is None


def test_a_chain_that_follows_a_selection_choosing_no_part(capsys, write_case, tmp_path):
    # The derived example without motor.peak_torque: neither the gearbox (T_2max needs T_1B) nor
    # the coupling (M_N needs M_a) can be chosen, so the accuracy chain, whose members follow both
    # selections, is of parts that stand in. Its values are given for information; the
    # requirement is not decided and says why; the verdict is null.
    (tmp_path / "data").symlink_to(ROOT / "data")  # the example's measurement paths hold
    (tmp_path / "cases").mkdir()
    text = derived_with_typed_motor().replace('peak_torque = "12 N*m"', "")
    r = results(capsys, write_case(text, "cases/example-without-peak.toml"))
    a = r["accuracy"]
    assert a["positioning_accuracy"]["value"] > 0 and [c["side"] for c in a["components"]] == ["input", "output"]
    best_gearbox, best_coupling = r["gearbox"]["candidates"][0]["part"], r["coupling"]["candidates"][0]["part"]
    (check,) = a["checks"]
    assert check["passes"] is None and check["utilization"] is None
    assert f"the gearbox selection chooses no part ({best_gearbox}, its best-ranked, stands in)" in check["not_made"]
    assert f"the coupling selection chooses no part ({best_coupling}, its best-ranked, stands in)" in check["not_made"]
    assert a["passes"] is None and r["verdict"]["passes"] is None
    assert any(reason.startswith("The accuracy requirement is not decided: positioning_accuracy")
               for reason in r["verdict"]["reasons"])


def test_exit_status(capsys, write_case):
    failing = write_case(HEAD_TOML.replace('"12 N*m"', '"400 N*m"') + PROFILE_TOML, "failing.toml")
    open_ = write_case(HEAD_TOML.replace('peak_torque = "12 N*m"\n', "") + PROFILE_TOML, "open.toml")
    bad = write_case(HEAD_TOML.replace("ratio = 10", "ratio = 13") + PROFILE_TOML, "bad.toml")
    assert run(capsys, EXAMPLE, "--strict")[0] == 0
    assert run(capsys, failing)[0] == 0  # results were produced
    assert run(capsys, failing, "--strict")[0] == 1
    assert run(capsys, open_, "--strict")[0] == 1  # a verdict that is not true
    code, out, err = run(capsys, bad, "--strict")
    assert code == 2 and out == "" and err.count("\n") == 1


@pytest.mark.parametrize(
    "edit, key",
    [
        (('"1500 kg*cm**2"', '"1e999 kg*cm**2"'), "load.inertia: expected a finite number"),
        (('"12 N*m"', '"inf N*m"'), "motor.peak_torque: expected a number followed by a unit"),
        (('torque = "60 N*m"', 'torque = "1e103 N*m"'),
         "profile[1].torque: expected a magnitude between 1e-12 and 1e+12"),
        (('duration = "0.2 s"', 'duration = "1e-308 s"'),
         "profile[1].duration: expected a magnitude between 1e-12 and 1e+12"),
        (("ratio = 10", "ratio = inf"), "gearbox.ratio: expected a finite number"),
        (("ratio = 10", "ratio = nan"), "gearbox.ratio: expected a finite number"),
    ],
)
def test_numbers_are_finite(capsys, write_case, edit, key):
    code, out, err = run(capsys, write_case((HEAD_TOML + PROFILE_TOML).replace(*edit, 1)))
    assert code == 2 and out == "" and key in err and err.count("\n") == 1


def test_service_factor_inf_names_its_key(capsys, write_case):
    case = write_case(HEAD_TOML + PROFILE_TOML + COUPLING_TOML.replace("service_factor = 2.5", "service_factor = inf"))
    code, out, err = run(capsys, case)
    assert code == 2 and out == "" and "coupling.service_factor: expected a finite number" in err


def test_every_speed_zero_is_an_input_error(capsys, write_case):
    # n_2m = 0 and T_2m = 0 / 0: refused, naming the profile, and no numpy warning on stderr.
    case = write_case(HEAD_TOML + PROFILE_TOML.replace('"150 rpm"', '"0 rpm"').replace('"300 rpm"', '"0 rpm"'))
    code, out, err = run(capsys, case)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "profile: expected a moving segment with a speed other than zero" in err


@pytest.fixture
def big_catalog(tmp_path):
    """The shipped gearbox catalog with 40 more rows at ratio 10 (sizes above NPT035-10's)."""
    from ..conftest import GEARBOXES

    lines = GEARBOXES.read_text().splitlines()
    row = next(line for line in lines if line.startswith("NPT035-10,"))
    extra = [row.replace("NPT035-10,", f"BIG{k:02d}-10,").replace(",220,", f",{230 + k},", 1) for k in range(40)]
    path = tmp_path / "big.csv"
    path.write_text("\n".join([*lines, *extra]) + "\n")
    return path


def test_candidate_lists_are_bounded(capsys, write_case, big_catalog):
    # 12 complete shipped rows + 40 at ratio 10: the best 20 are listed with the count; --all-candidates lists all 52.
    case = write_case(HEAD_TOML.replace("ratio = 10", f'ratio = 10\ncatalog = "{big_catalog}"') + PROFILE_TOML)
    r = results(capsys, case)
    assert r["gearbox"]["candidate_count"] == 52 and len(r["gearbox"]["candidates"]) == 20
    assert len(results(capsys, case, "--all-candidates")["gearbox"]["candidates"]) == 52
    code, out, _ = run(capsys, case)
    assert "... 32 more candidates (--all-candidates lists them)" in out


SELECTED_CHAIN = """
[accuracy]
applied_torque = "8 N*m"
[[accuracy.component]]
kind = "coupling"
part = "selected"
[[accuracy.component]]
part = "selected"
"""


def test_chain_follows_the_selection(capsys, write_case):
    # Ratio 10: NPT035-10 (C_t21 = 22 N·m/arcmin, backlash 8 arcmin) and the motor-side AKD-30
    # (C_T = 25000 N·m/rad = 7.272 N·m/arcmin, referred to the output · i² = 727.2 N·m/arcmin, E11).
    # C_total = 1 / (1/727.2 + 1/22) = 21.354 N·m/arcmin.
    head = HEAD_TOML + PROFILE_TOML + COUPLING_TOML
    r = results(capsys, write_case(head + SELECTED_CHAIN))
    names = [c["name"] for c in r["accuracy"]["components"]]
    assert names == ["AKD-30", "NPT035-10"]
    assert [c["side"] for c in r["accuracy"]["components"]] == ["input", "output"]
    assert r["accuracy"]["C_total"]["value"] == pytest.approx(
        1 / (1 / (25000 * 3.141592653589793 / 10800 * 100) + 1 / 22), rel=1e-4)
    # Ratio 8: the gearbox selection moves (NPT035-8: 22 N·m/arcmin, 8 arcmin, ratio 8) and the
    # chain follows it: the coupling is referred through i² = 64, C = 7.272 · 64 = 465.4 N·m/arcmin.
    r8 = results(capsys, write_case((head + SELECTED_CHAIN).replace("ratio = 10", "ratio = 8"), "eight.toml"))
    assert r8["gearbox"]["selected"] == r8["accuracy"]["components"][1]["name"]
    assert r8["accuracy"]["ratio"] == 8
    assert r8["accuracy"]["components"][0]["stiffness_at_output"]["value"] == pytest.approx(
        25000 * 3.141592653589793 / 10800 * 64, rel=1e-4)


@pytest.mark.parametrize(
    "chain, fragment",
    [
        (SELECTED_CHAIN.replace('kind = "coupling"\n', 'kind = "motor"\n'),
         "accuracy.component[1].kind: expected one of gearbox, coupling, found 'motor'"),
        (SELECTED_CHAIN.replace('kind = "coupling"\npart = "selected"\n',
                                'kind = "coupling"\nname = "x"\nside = "input"\n'
                                'stiffness = "1 N*m/arcmin"\nbacklash = "0 arcmin"\n'),
         "accuracy.component[1].kind: kind says which catalog a part comes from; give part as well"),
        (SELECTED_CHAIN + 'catalog = "gearboxes"\n',
         "accuracy.component[2].catalog: part = \"selected\" takes the gearbox selection's catalog"),
    ],
)
def test_selected_part_errors(capsys, write_case, chain, fragment):
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + COUPLING_TOML + chain))
    assert code == 2 and out == "" and fragment in err


TRACE = 'transmission_trace = "{trace}"\n'


@pytest.mark.parametrize(
    "chain, fragment",
    [
        (SELECTED_CHAIN + TRACE,
         "accuracy.component[2].transmission_trace: a measurement belongs to the part it was made on, "
         "but part = \"selected\" follows the selection; name that part with measured_part"),
        (SELECTED_CHAIN + 'measured_part = "NPT035-10"\n',
         "accuracy.component[2].measured_part: measured_part names the part a measurement was made on; "
         "give hysteresis or transmission_trace as well"),
        (SELECTED_CHAIN.replace('[[accuracy.component]]\npart = "selected"\n',
                                '[[accuracy.component]]\npart = "NPT035-10"\n')
         + TRACE + 'measured_part = "NPT035-10"\n',
         "accuracy.component[2].measured_part: measured_part names the part a measurement was made on when "
         "part = \"selected\"; found part = 'NPT035-10', whose measurements are its own"),
    ],
)
def test_measured_part_errors(capsys, write_case, chain, fragment):
    trace = ROOT / "data" / "transmission-NPT035-10-generated.csv"
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + COUPLING_TOML + chain.format(trace=trace)))
    assert code == 2 and out == "" and fragment in err and err.count("\n") == 1


def test_a_measurement_applies_while_the_selection_chooses_its_part(capsys, write_case):
    # The generated trace of NPT035-10 gives 62.9456 arcsec (tests/outputs/test_accuracy_cli.py); it is
    # used at ratio 10, where the selection chooses NPT035-10, and left out at ratio 8 (NPT035-8).
    trace = ROOT / "data" / "transmission-NPT035-10-generated.csv"
    chain = SELECTED_CHAIN + TRACE.format(trace=trace) + 'measured_part = "NPT035-10"\n'
    head = HEAD_TOML + PROFILE_TOML + COUPLING_TOML
    at_10 = results(capsys, write_case(head + chain))["accuracy"]
    assert at_10["transmission_accuracy"]["value"] == pytest.approx(62.9456, abs=1e-4)
    assert "measured_trace" in at_10["components"][1]
    at_8 = results(capsys, write_case((head + chain).replace("ratio = 10", "ratio = 8"), "eight.toml"))["accuracy"]
    gearbox = at_8["components"][1]
    assert "measured_trace" not in gearbox and at_8["transmission_accuracy"]["value"] == 0
    assert gearbox["source"].endswith(
        f"the transmission_trace of NPT035-10 not used: the selection chose {gearbox['name']}")


def test_selected_needs_the_section_it_follows(capsys, write_case):
    code, _, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + SELECTED_CHAIN))
    assert code == 2 and ("accuracy.component[1].part: part = \"selected\" with kind = \"coupling\" follows the "
                          "coupling selection, but the case has no [coupling]") in err
    no_gearbox = (HEAD_TOML.replace("[gearbox]\nratio = 10\n", "") + PROFILE_TOML
                  + SELECTED_CHAIN.split("[[accuracy.component]]\nkind")[0]
                  + '[[accuracy.component]]\npart = "selected"\n')
    code, _, err = run(capsys, write_case(no_gearbox, "nogear.toml"))
    assert code == 2 and "follows the gearbox selection, but the case names no gearbox ratio or part" in err


@pytest.mark.parametrize(
    "chain, fragment",
    [
        (SELECTED_CHAIN.replace('part = "selected"\n', 'part = "selected"\ncatalog = "couplings"\n', 1),
         "accuracy.component[1].catalog: part = \"selected\" takes the coupling selection's catalog; give no catalog"),
        (SELECTED_CHAIN.replace('part = "selected"\n', 'part = "AX2090-EC05"\nside = "input"\n', 1),
         "(AX2090-EC05): the twist of a coupling of type elastomer is not one catalog stiffness; "
         "give its stiffness and backlash"),
        (SELECTED_CHAIN.replace('part = "selected"\n', 'part = "selected"\nside = "output"\n', 1),
         "accuracy.component[1].side: the coupling selection's coupling sits on the input side (coupling.side), "
         "found 'output'"),
    ],
)
def test_coupling_part_errors(capsys, write_case, chain, fragment):
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + COUPLING_TOML + chain))
    assert code == 2 and out == "" and fragment in err and err.count("\n") == 1


def test_a_coupling_part_without_stiffness(capsys, write_case, tmp_path):
    from ..conftest import ROOT

    text = (ROOT / "catalogs" / "couplings.csv").read_text().replace("AKD-30,AKD,30,bellows,36,,25000,",
                                                                     "AKD-30,AKD,30,bellows,36,,,")
    (tmp_path / "mine.csv").write_text(text)
    chain = SELECTED_CHAIN.replace('part = "selected"\n', 'part = "AKD-30"\nside = "input"\ncatalog = "mine.csv"\n', 1)
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + COUPLING_TOML + chain))
    assert code == 2 and out == "" and "(AKD-30), column C_T: expected a value, found an empty cell" in err
