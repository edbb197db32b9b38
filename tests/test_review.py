"""The design review: changed copies of a case, and the panel that re-evaluates them.

Expected numbers are worked by hand from the example case (cases/indexing-table.toml):
T_2max = T_1B · i · f_s · η, with f_s = 1.3 at Z_h = 1800 /h and η = 0.97 (NPT035-10).
"""

import numpy as np
import pytest

from calc import Q_
from calc.case import read_case
from calc.sections import evaluate as evaluate_case
from calc.review import DesignReview, review_items, with_changes

from .conftest import EXAMPLE


def evaluate(case) -> dict:
    """The results of ``case`` as the JSON contract writes them."""
    return evaluate_case(case).to_json()


@pytest.fixture(scope="module")
def case():
    return read_case(EXAMPLE)


def test_no_change_is_the_same_case(case):
    assert evaluate(with_changes(case)) == evaluate(case)


def test_a_stronger_motor_fails_every_gearbox(case):
    # 400 N·m · 10 · 1.3 · 0.95 = 4940 N·m, above every T_2B at ratio 10 (at most TP500-10's 4000 N·m).
    r = evaluate(with_changes(case, motor_peak_torque=Q_(400, "N*m")))
    assert r["cyclic"]["T2max"]["value"] == pytest.approx(4940)
    assert r["gearbox"]["selected"] is None
    assert case.motor_peak_torque == Q_(12, "N*m")  # the case itself is untouched


def test_cycle_timing_sets_the_duty_cycle(case):
    # Pause 1 s -> 3 s: ED = 1 s / 4 s = 25 %, Z_h = 3600 / 4 = 900 /h, so f_s = 1.0 (E4).
    durations = Q_(np.array([0.2, 0.6, 0.2, 3.0]), "s")
    r = evaluate(with_changes(case, durations=durations))
    assert r["duty"]["ED"]["value"] == pytest.approx(25.0)
    assert r["cyclic"]["fs"] == 1.0


def test_torques_set_the_cubic_mean(case):
    # Every torque doubled: T_2m doubles (the cubic mean is homogeneous of degree 1).
    r0 = evaluate(case)
    r = evaluate(with_changes(case, torques=2 * case.profile.torques))
    assert r["continuous"]["T2m"]["value"] == pytest.approx(2 * r0["continuous"]["T2m"]["value"])


def test_temperature_and_applied_torque_reach_their_sections(case):
    r = evaluate(with_changes(case, temperature=Q_(95, "degC"), applied_torque=Q_(16, "N*m")))
    assert r["coupling"]["temperature"]["value"] == pytest.approx(95)
    assert r["accuracy"]["applied_torque"]["value"] == pytest.approx(16)
    # Lost motion j_t + T / C grows by the extra 8 N·m over the chain's stiffness.
    r0 = evaluate(case)
    extra = 8 / r0["accuracy"]["C_total"]["value"]
    assert r["accuracy"]["lost_motion"]["value"] == pytest.approx(r0["accuracy"]["lost_motion"]["value"] + extra)


def test_panel_controls_re_evaluate_the_case():
    review = DesignReview(EXAMPLE)
    assert {"ratio", "t_1", "T_1", "T_1B", "J_motor", "J_L", "temperature", "applied_torque"} <= set(review.controls)
    assert "PASS" in review.items()[0].data
    # The slider's top, 5 · 12 = 60 N·m: T_2max = 60 · 10 · 1.3 · 0.97 = 756.6 N·m exceeds T_2B of
    # NPT035-10 (220), NPS045-10 and NPT045-10 (400) and TP050-10 (648); TP300-10 (η 0.95: 741 N·m
    # against 2280 N·m) is the smallest adequate gearbox.
    review.controls["T_1B"].value = 60.0
    assert "gearbox TP300-10" in review.items()[0].data
    assert "gearbox TP300-10" in review.output.outputs[0]["data"]["text/html"]  # the panel's output follows the control


def test_a_case_that_cannot_be_evaluated_says_why_instead_of_raising(case):
    items = review_items(with_changes(case, ratio=Q_(13, "")))
    assert "FAIL" in items[0].data and "has ratio 13" in items[0].data
    bad = DesignReview(EXAMPLE.parent / "missing.toml")
    assert "the case file does not exist" in bad.message.value


def test_review_items_of_the_example(case):
    kinds = [type(x).__name__ for x in review_items(case)]
    assert kinds == ["HTML", "Figure", "HTML", "DataFrame", "HTML", "DataFrame", "HTML", "DataFrame", "Figure"]


def test_the_accuracy_chain_follows_a_change_of_ratio(case):
    # The example's chain takes the selections' parts, so at ratio 8 it is AKD-30 and TP010-8
    # (catalogs/gearboxes.csv: C_t21 = 23 N·m/arcmin, backlash 3 arcmin, T_2N = 80 N·m). By hand:
    # AKD-30's 25 000 N·m/rad = 7.27221 N·m/arcmin × 8² = 465.421 at the output (E11);
    # C_total = 1 / (1/465.421 + 1/23) = 21.9170 N·m/arcmin; lost motion at 8 N·m = 3 + 8/21.9170
    # = 3.36501 arcmin (E12); 8 N·m > 3 % of 80 N·m and the trace of NPT035-10 no longer applies,
    # so the positioning accuracy is 0 + 8/21.9170 = 0.36501 arcmin (E13).
    r = evaluate(with_changes(case, ratio=Q_(8, "")))
    a = r["accuracy"]
    assert [c["name"] for c in a["components"]] == ["AKD-30", "TP010-8"]
    assert a["C_total"]["value"] == pytest.approx(21.9170, abs=1e-4)
    assert a["lost_motion"]["value"] == pytest.approx(3.36501, abs=1e-5)
    assert a["positioning_accuracy"]["value"] == pytest.approx(0.36501, abs=1e-5)
    assert "the transmission_trace of NPT035-10 not used: the selection chose TP010-8" in a["components"][1]["source"]
    assert "measured_trace" not in a["components"][1]
    items = review_items(with_changes(case, ratio=Q_(8, "")))
    assert "PASS" in items[0].data and "TP010-8" in items[0].data


def test_a_section_that_no_longer_fits_is_left_out_not_everything(write_case):
    # A chain that names NPT035-10 (a 10:1 part) no longer fits the drive train at ratio 8.
    # The review still shows the gearbox and the coupling, and says FAIL with the reason.
    import pandas as pd

    text = EXAMPLE.read_text()
    start = text.index("[[accuracy.component]]")
    named = text[:start] + '[[accuracy.component]]\npart = "NPT035-10"\n'
    items = review_items(with_changes(read_case(write_case(named)), ratio=Q_(8, "")))
    verdict = items[0].data
    assert "FAIL" in verdict and "The accuracy section cannot be evaluated with these inputs" in verdict
    assert "NPT035-10" in verdict
    tables = [x for x in items if isinstance(x, pd.DataFrame)]
    gearbox = tables[0]
    # catalogs/gearboxes.csv, the complete rows at ratio 8 (the SP+ rows are partial, never ranked).
    assert set(gearbox["part"]) == {f"{s}-8" for s in ("TP004", "TP010", "TP050", "TP300", "TP500", "NPT005", "NPT015", "NPT025",
                                                         "NPT035", "NPT045", "NPS015", "NPS045")}
    assert len(tables) == 2  # gearbox and coupling candidates; no accuracy table


def test_slider_units_read_as_written():
    panel = DesignReview(EXAMPLE)
    described = [c.description for c in panel.controls.values()]
    assert any(d.endswith("[kg·cm²]") for d in described)
    assert not any("··" in d or "**" in d for d in described)
