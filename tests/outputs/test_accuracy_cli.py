"""``python -m calc evaluate`` with an ``[accuracy]`` section: the contract, and one-line errors."""

import json
import subprocess
import sys

import numpy as np
import pytest

from calc import Q_
from calc.domain.hysteresis import Loop, LoopModel, write_loop

from ..conftest import EXAMPLE, HEAD_TOML, PROFILE_TOML, ROOT, run

SOURCE_EXAMPLE = """
[accuracy]
applied_torque = "20 N*m"
[[accuracy.component]]
name = "EKM-15 coupling"
side = "{side}"
stiffness = "0.24 N*m/arcmin"
backlash = "0 arcmin"
[[accuracy.component]]
name = "EPL-W-064 10:1"
side = "output"
stiffness = "1.3 N*m/arcmin"
backlash = "3 arcmin"
transmission_accuracy = "60 arcsec"
nominal_torque = "40 N*m"
"""


def results(capsys, path):
    code, out, err = run(capsys, path, "--json")
    assert code == 0, err
    return json.loads(out)["accuracy"]


def case_with(write_case, accuracy: str, head: str = HEAD_TOML):
    return write_case(head + PROFILE_TOML + accuracy)


def test_example_shows_its_chain_lost_motion_and_positioning_accuracy():
    proc = subprocess.run(
        [sys.executable, "-m", "calc", "evaluate", str(EXAMPLE), "--json"], capture_output=True, text=True
    )
    assert proc.returncode == 0, proc.stderr
    a = json.loads(proc.stdout)["accuracy"]
    assert set(a) >= {"C_total", "lost_motion", "positioning_accuracy", "repeatability", "components"}
    # Both members follow the selections (part = "selected"): AKD-30 and NPT035-10 at ratio 10.
    assert [(c["name"], c["side"]) for c in a["components"]] == [("AKD-30", "input"), ("NPT035-10", "output")]
    coupling, gearbox = a["components"]
    assert set(coupling) >= {"name", "side", "stiffness_at_output", "backlash_at_output"}
    # By hand: AKD-30's 25 000 N·m/rad is 7.27221 N·m/arcmin at the motor, × 10² = 727.221 at the output (E11);
    # with NPT035-10's 22 N·m/arcmin: 1 / (1/727.221 + 1/22) = 21.3540 N·m/arcmin.
    assert coupling["stiffness_at_output"] == {"value": pytest.approx(727.221, abs=1e-3), "unit": "N*m/arcmin"}
    assert gearbox["stiffness_at_output"] == {"value": pytest.approx(22.0), "unit": "N*m/arcmin"}
    assert gearbox["backlash_at_output"] == {"value": pytest.approx(8.0), "unit": "arcmin"}
    assert a["C_total"] == {"value": pytest.approx(21.3540, abs=1e-4), "unit": "N*m/arcmin"}
    # Lost motion at 8 N·m: 8 + 8 / 21.3540 = 8.37464 arcmin (E12).
    assert a["lost_motion"] == {"value": pytest.approx(8.37464, abs=1e-5), "unit": "arcmin"}
    # 8 N·m > 3 % of 110 N·m: ATA (62.9456 arcsec of the generated trace = 1.04909 arcmin) + 0.37464 (E13).
    assert a["transmission_accuracy"] == {"value": pytest.approx(62.9456, abs=1e-4), "unit": "arcsec"}
    assert a["positioning_accuracy"] == {"value": pytest.approx(1.42373, abs=1e-5), "unit": "arcmin"}
    # Repeatability under torque: the tighter of the lost motion (E13) and the positioning accuracy, both full
    # widths (calc.domain.accuracy.POSITIONING_CONVENTION): min(8.37464, 1.42373) = 1.42373 arcmin.
    assert a["repeatability"]["value"] == pytest.approx(1.42373, abs=1e-5) and a["repeatability_is_bound"] is True
    assert a["repeatability_basis"].startswith("the positioning accuracy, a full width")
    # The budget: ATA 1.04909 arcmin (systematic) and the twist 0.37464 arcmin (random); worst case their sum,
    # the positioning accuracy; RSS √(1.04909² + 0.37464²) = 1.11398 arcmin.
    b = a["budget"]
    assert [(c["kind"], c["value"]["value"]) for c in b["contributions"]] == [
        ("systematic", pytest.approx(1.04909, abs=1e-5)), ("random", pytest.approx(0.37464, abs=1e-5))]
    assert b["worst_case"]["value"] == pytest.approx(a["positioning_accuracy"]["value"], rel=1e-12)
    assert b["rss"]["value"] == pytest.approx(1.11398, abs=1e-5)
    assert sum(c["share"] for c in b["contributions"]) == pytest.approx(1.0)
    assert a["nominal_torque_from"] == "NPT035-10" and a["passes"] is True
    assert gearbox["measured_trace"]["file"] == "data/transmission-NPT035-10-generated.csv"


def test_summary_shows_the_chain(capsys):
    code, out, err = run(capsys, EXAMPLE)
    assert code == 0 and err == ""
    assert "Accuracy at the output (applied torque 8 N·m, ratio 10; E11 to E13):" in out
    assert "C_total = 21.35 N·m/arcmin; backlash = 8 arcmin" in out
    assert "Lost motion = j_t + |T| / C = 8.375 arcmin (E12)" in out
    assert "Repeatability <= 1.424 arcmin (the positioning accuracy, a full width, tighter than the lost motion" in out
    assert "worst case 1.424 arcmin; root-sum-square 1.114 arcmin" in out


@pytest.mark.parametrize("side, c_total", [("output", 0.202597), ("input", 1.233196)])
def test_source_example_as_a_case(capsys, write_case, side, c_total):
    # Source, Torsional Stiffness: 0.20 N·m/arcmin; E11: about 1.23 N·m/arcmin with the coupling at the motor.
    a = results(capsys, case_with(write_case, SOURCE_EXAMPLE.format(side=side)))
    assert a["C_total"]["value"] == pytest.approx(c_total, rel=1e-5)
    assert a["positioning_rule"] == "|T| > 3 % of T_N: phi_TA + |T| / C"


def test_component_from_a_catalog_part(capsys, write_case):
    a = results(
        capsys,
        case_with(write_case, '[accuracy]\napplied_torque = "0 N*m"\n[[accuracy.component]]\npart = "TP010-10"\n'),
    )
    (c,) = a["components"]
    assert c["name"] == "TP010-10" and c["side"] == "output" and c["source"] == "catalogs/gearboxes.csv row 11"
    assert c["stiffness_at_output"]["value"] == pytest.approx(23) and c["backlash_at_output"]["value"] == pytest.approx(
        3
    )
    assert a["nominal_torque"]["value"] == pytest.approx(81)
    # At rest: positioning accuracy = ATA (none given) + backlash; repeatability = backlash (E13).
    assert a["positioning_accuracy"]["value"] == pytest.approx(3) and a["repeatability_is_bound"] is False
    assert a["transmission_accuracy_from"] == []


def test_component_from_a_measured_loop_and_a_positioning_record(capsys, write_case, tmp_path):
    loop = ROOT / "data" / "hysteresis-NPT035-10-generated.csv"
    (tmp_path / "positions.csv").write_text("target [deg],actual [deg]\n0,0.01\n0,0.03\n90,90.02\n90,90.02\n")
    text = f"""
[accuracy]
applied_torque = "20 N*m"
positions = "positions.csv"
required_repeatability = "2 arcmin"
[[accuracy.component]]
name = "gearbox on the rig"
side = "output"
hysteresis = "{loop}"
nominal_torque = "110 N*m"
"""
    a = results(capsys, case_with(write_case, text))
    (c,) = a["components"]
    m = c["measured_loop"]
    assert m["stiffness_positive"]["value"] == pytest.approx(22, rel=0.01)
    assert m["backlash"]["value"] == pytest.approx(8, rel=0.01)
    assert c["stiffness_at_output"]["value"] == pytest.approx(
        min(m["stiffness_positive"]["value"], m["stiffness_negative"]["value"])
    )
    assert a["measured_positioning"]["accuracy"] == {"value": pytest.approx(1.8), "unit": "arcmin"}
    assert a["measured_positioning"]["repeatability"] == {"value": pytest.approx(1.2), "unit": "arcmin"}
    assert a["checks"][0]["name"] == "repeatability" and a["passes"] is False  # bound 8 + 20/22 > 2 arcmin


BAD_LOOP_ROWS = {
    "too_few": "0,0\n80,3\n-80,-3\n",
    "one_way": "\n".join(f"{t:.6g},{t / 22:.6g}" for t in np.linspace(0, 110, 200)),
    "cells": "0,0\n10,0.5\n20,about 1\n",
}


def component(**keys):
    lines = "\n".join(f"{k} = {v}" for k, v in keys.items())
    return f'[accuracy]\napplied_torque = "20 N*m"\n[[accuracy.component]]\n{lines}\n'


GOOD = dict(
    name='"gearbox"', side='"output"', stiffness='"22 N*m/arcmin"', backlash='"8 arcmin"', nominal_torque='"110 N*m"'
)


@pytest.mark.parametrize(
    "accuracy, fragment",
    [
        (
            component(**GOOD | dict(stiffness='"0 N*m/arcmin"')),
            "accuracy.component[1].stiffness: expected a stiffness above zero",
        ),
        (
            component(**GOOD | dict(stiffness='"-1.3 N*m/arcmin"')),
            "accuracy.component[1].stiffness: expected a stiffness above zero",
        ),
        # E15: pint would take a torque for a stiffness, and a bare number for an angle in radians.
        (
            component(**GOOD | dict(stiffness='"0.24 N*m"')),
            "accuracy.component[1].stiffness: expected a stiffness such as \"1.3 N*m/arcmin\", found '0.24 N*m', "
            "which is a torque (its unit must carry the angle, errata E15)",
        ),
        (
            component(**GOOD | dict(backlash='"3"')),
            "accuracy.component[1].backlash: expected an angle such as \"3 arcmin\", found '3', which is a bare "
            "number (its unit must carry the angle, errata E15)",
        ),
        (
            component(**GOOD | dict(backlash="3")),
            "accuracy.component[1].backlash: expected an angle with its unit such as \"3 arcmin\", "
            "found the bare number 3",
        ),
        (
            component(**GOOD | dict(transmission_accuracy='"60 N*m"')),
            "accuracy.component[1].transmission_accuracy: expected an angle",
        ),
        (
            component(**GOOD | dict(transmission_accuracy='"60"')),
            "which is a bare number (its unit must carry the angle, errata E15)",
        ),
        (
            component(**GOOD | dict(backlash='"-1 arcmin"')),
            "accuracy.component[1].backlash: expected an angle of zero or more",
        ),
        (
            component(**GOOD | dict(transmission_accuracy='"-1 arcmin"')),
            "accuracy.component[1].transmission_accuracy: expected an angle of zero or more, found '-1 arcmin'",
        ),
        (
            component(**GOOD | dict(side='"motor"')),
            "accuracy.component[1].side: expected input or output, found 'motor'",
        ),
        (component(**GOOD | dict(stifness='"22 N*m/arcmin"')), "accuracy.component[1].stifness: unknown key"),
        (
            component(**{k: v for k, v in GOOD.items() if k != "stiffness"}),
            "accuracy.component[1].stiffness: expected a stiffness",
        ),
        (
            component(**{k: v for k, v in GOOD.items() if k != "backlash"}),
            "accuracy.component[1].backlash: expected an angle",
        ),
        (
            component(**{k: v for k, v in GOOD.items() if k != "side"}),
            "accuracy.component[1].side: expected a value, found none",
        ),
        (
            component(**GOOD).replace('applied_torque = "20 N*m"\n', ""),
            "accuracy.applied_torque: expected a value, found none",
        ),
        ('[accuracy]\napplied_torque = "20 N*m"\n', "accuracy.component: expected one [[accuracy.component]] table"),
        ('[accuracy]\napplied_torque = "20 N*m"\ntolerance = "1 arcmin"\n', "accuracy.tolerance: unknown key"),
        (
            component(**GOOD | dict(nominal_torque='"0 N*m"')),
            "accuracy.component[1].nominal_torque: expected a torque above zero",
        ),
        (
            component(**{k: v for k, v in GOOD.items() if k != "nominal_torque"}),
            "accuracy.nominal_torque: the 3 % rule of positioning accuracy (E13) needs the nominal torque",
        ),
        (
            component(**GOOD).replace('"20 N*m"', '"20 N*m"\nrequired_positioning_accuracy = "5 N*m"'),
            "accuracy.required_positioning_accuracy: expected an angle",
        ),
        (
            component(**GOOD) + "[[accuracy.component]]\n" + "\n".join(f"{k} = {v}" for k, v in GOOD.items()),
            "accuracy.component[2].name: the name 'gearbox' is already used",
        ),
        (
            component(part='"TP010-10"', stiffness='"22 N*m/arcmin"'),
            "accuracy.component[1].stiffness: the part 'TP010-10' gives its stiffness from the catalog",
        ),
        (
            component(part='"TP010-10"', side='"input"'),
            "accuracy.component[1].side: a gearbox's catalog figures are referred to its output",
        ),
        (component(part='"TP999-10"'), "accuracy.component[1].part: no part 'TP999-10' in catalog"),
        (
            component(part='"TP010-5"'),
            "accuracy.component[1].part: TP010-5 has ratio 5, but the case's gearbox ratio is 10",
        ),
        (
            component(**GOOD | dict(catalog='"gearboxes"')),
            "accuracy.component[1].catalog: a catalog is read only for a part",
        ),
        (
            component(name='"rig"', side='"output"', hysteresis='"loop.csv"'),
            "accuracy.component[1].nominal_torque: a measured loop is analysed at 50 % to 100 % and ±3 % of the "
            "nominal torque",
        ),
        (
            component(name='"rig"', side='"output"', nominal_torque='"110 N*m"', hysteresis='"missing.csv"'),
            "accuracy.component[1].hysteresis: the measurement file 'missing.csv' does not exist",
        ),
        (
            component(name='"rig"', side='"output"', nominal_torque='"110 N*m"', hysteresis='"too_few.csv"'),
            "too_few.csv: expected a loop of at least 20 samples, found 3",
        ),
        (
            component(name='"rig"', side='"output"', nominal_torque='"110 N*m"', hysteresis='"one_way.csv"'),
            "one_way.csv: the loop is loaded in one direction only",
        ),
        (
            component(name='"rig"', side='"output"', nominal_torque='"250 N*m"', hysteresis='"../loop.csv"'),
            "between 50 % and 100 % of the nominal torque (125 to 250 N·m), found 0",
        ),
        (
            component(name='"rig"', side='"output"', nominal_torque='"110 N*m"', hysteresis='"cells.csv"'),
            "cells.csv, row 4, column twist: expected a number, found 'about 1'",
        ),
        (
            component(**GOOD | dict(hysteresis='"../loop.csv"')),
            "accuracy.component[1].stiffness: the measured loop gives the stiffness",
        ),
        (
            component(**GOOD | dict(transmission_trace='"../trace.csv"')),
            "trace.csv: expected a full revolution of the output (360°) in at least one direction",
        ),
        (
            component(**GOOD | dict(transmission_trace='"../trace.csv"', transmission_accuracy='"1 arcmin"')),
            "give either transmission_trace or transmission_accuracy",
        ),
    ],
)
def test_bad_accuracy_input_is_one_line_naming_file_and_key(capsys, write_case, tmp_path, accuracy, fragment):
    folder = tmp_path / "cases"
    folder.mkdir()
    for name, body in BAD_LOOP_ROWS.items():
        (folder / f"{name}.csv").write_text(f"torque [N*m],twist [arcmin]\n{body}\n")
    # A loop to only 110 N·m, and a trace over half a revolution, one folder up.
    t = Q_(np.concatenate([np.linspace(0, 110, 300), np.linspace(110, -110, 600), np.linspace(-110, 110, 600)]), "N*m")
    model = LoopModel(Q_(22, "N*m/arcmin"), Q_(8, "arcmin"), Q_(110, "N*m"))
    write_loop(tmp_path / "loop.csv", Loop(t, model.twist(t)), ("test loop",))
    theta = np.linspace(0, 180, 200)
    (tmp_path / "trace.csv").write_text("input [deg],output [deg]\n" + "\n".join(f"{10 * a},{a}" for a in theta) + "\n")
    path = folder / "case.toml"
    path.write_text(HEAD_TOML + PROFILE_TOML + accuracy)
    code, out, err = run(capsys, path)
    assert code == 2 and out == ""
    assert err.startswith("error: ") and err.count("\n") == 1
    assert fragment in err
    assert "case.toml" in err or ".csv" in err


def test_input_side_needs_the_gearbox_ratio(capsys, write_case):
    head = 'title = "no gearbox"\n[motor]\npeak_torque = "12 N*m"\n'
    code, out, err = run(capsys, case_with(write_case, SOURCE_EXAMPLE.format(side="input"), head=head))
    assert code == 2 and out == ""
    assert (
        "accuracy.component[1].side: an input-side component is referred to the output through the gearbox ratio "
        "(E11), but the case gives no gearbox.ratio"
        in err
    )


@pytest.mark.parametrize("column, edit", [("C_t21", "7500,97,3,,0.4,"), ("backlash", "7500,97,,23,0.4,")])
def test_a_part_without_its_catalog_figure_names_row_and_column(capsys, write_case, tmp_path, column, edit):
    # TP010-10 (row 11 of the shipped catalog) with its stiffness or backlash cell left empty.
    (tmp_path / "gaps.csv").write_text(
        (ROOT / "catalogs" / "gearboxes.csv").read_text().replace("7500,97,3,23,0.4,", edit)
    )
    code, out, err = run(capsys, case_with(write_case, component(part='"TP010-10"', catalog='"gaps.csv"')))
    assert code == 2 and out == ""
    assert (
        f"accuracy.component[1].part: {tmp_path / 'gaps.csv'}, row 11 (TP010-10), column {column}: "
        "expected a value, found an empty cell"
        in err
    )


def test_a_trace_needs_the_gearbox_ratio(capsys, write_case, tmp_path):
    # The trace's input position is divided by the ratio (φ_2 - φ_1 / i); a case without a gearbox gives none.
    head = 'title = "no gearbox"\n[motor]\npeak_torque = "12 N*m"\n'
    (tmp_path / "trace.csv").write_text("input [deg],output [deg]\n0,0\n")
    accuracy = component(**GOOD | dict(transmission_trace='"trace.csv"'))
    code, out, err = run(capsys, case_with(write_case, accuracy, head=head))
    assert code == 2 and out == ""
    assert (
        "accuracy.component[1].transmission_trace: the transmission error is reckoned through the gearbox ratio, "
        "but the case gives no gearbox.ratio" in err
    )


def _forced(write_case, required="5 arcmin"):
    """The shipped example with NPT045-10 forced: catalogs/gearboxes.csv row 50 leaves its C_t21 empty (cut
    off in the source, its comment says); backlash 8 arcmin, T_2N 350 N·m."""
    trace = ROOT / "data" / "transmission-NPT035-10-generated.csv"
    text = (
        (ROOT / "cases" / "indexing-table.toml")
        .read_text()
        .replace('family = "NPT"', 'family = "NPT"\npart = "NPT045-10"')
        .replace("../data/transmission-NPT035-10-generated.csv", str(trace))
        .replace('required_positioning_accuracy = "5 arcmin"', f'required_positioning_accuracy = "{required}"')
    )
    return write_case(text)


def test_a_selected_gearbox_without_its_stiffness_gives_bounds_not_numbers(capsys, write_case):
    # The chain is reckoned with NPT045-10 rigid, so by hand (8 N·m <= 3 % of 350 N·m = 10.5 N·m:
    # the backlash form, E13) the positioning accuracy is at least 0 + 8 = 8 arcmin, over the
    # required 5: a lower bound already over the limit fails. C_total is the coupling's alone (an
    # upper bound) and the lost motion 8 + 8 / C_total at least.
    code, out, err = run(capsys, _forced(write_case), "--json")
    assert code == 0, err
    r = json.loads(out)
    a = r["accuracy"]
    coupling, gearbox = a["components"]
    assert gearbox["name"] == "NPT045-10" and gearbox["stiffness_at_output"]["value"] is None
    assert gearbox["twist_at_applied_torque"]["value"] is None and gearbox["share_of_compliance"] == 0
    assert a["C_total"]["value"] == pytest.approx(coupling["stiffness_at_output"]["value"], rel=1e-12)
    assert a["lost_motion"]["value"] == pytest.approx(8 + 8 / a["C_total"]["value"], rel=1e-12)
    assert a["positioning_accuracy"]["value"] == pytest.approx(8.0, rel=1e-12)
    assert a["C_total_is_upper_bound"] and a["lost_motion_is_lower_bound"] and a["repeatability_is_lower_bound"]
    assert (
        a["unknown"][0]
        == "NPT045-10: its torsional stiffness C_t21 (empty in catalogs/gearboxes.csv row 50; reckoned rigid)"
    )
    check = a["checks"][0]
    assert check["passes"] is False and check["value_is_lower_bound"] and check["utilization"] == pytest.approx(1.6)
    assert r["verdict"]["passes"] is False
    assert (
        "positioning_accuracy >= 8 arcmin > required 5 arcmin, at least 60 % over (a lower bound: unknown NPT045-10"
        in r["verdict"]["reasons"][0]
    )


def test_a_lower_bound_within_the_limit_decides_nothing(capsys, write_case):
    # Required 10 arcmin: at least 8 arcmin may or may not be within it.
    code, out, err = run(capsys, _forced(write_case, "10 arcmin"))
    assert code == 0, err
    assert "Verdict: NOT DECIDED" in out
    assert "Positioning accuracy (|T| <= 3 % of T_N: phi_TA + j_t, T_N = 350 N·m (NPT045-10)) >= 8 arcmin (E13)" in out
    assert "C_total <= " in out and "Lost motion = j_t + |T| / C >= 8.0" in out
    assert (
        "not made: the positioning accuracy is a lower bound: unknown NPT045-10: its torsional stiffness C_t21" in out
    )
