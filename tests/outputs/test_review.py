"""The design review: changed copies of a case, the inputs' specs, what the panel shows, and the
panel that re-evaluates them (the served page in a browser: test_review_browser.py).

Expected numbers are worked by hand from the example case (cases/indexing-table.toml):
T_2max = T_1B · i · f_s · η, with f_s = 1.3 at Z_h = 1800 /h and η = 0.97 (NPT035-10).
"""

import dataclasses
import re

import numpy as np
import pytest

from calc import Q_
from calc.sections.case import read_case
from calc.sections import evaluate as evaluate_case
from calc.review import DesignReview, evaluated, input_specs, results_html, with_changes, with_inputs
from calc.review.inputs import nice_step

from ..conftest import DERIVED_EXAMPLE, EXAMPLE, has_tool


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


def test_key_paths_reach_the_case_as_the_named_arguments_do(case):
    by_path = with_inputs(case, {"gearbox.ratio": Q_(8, ""), "profile[4].duration": Q_(3, "s"),
                                 "accuracy.applied_torque": Q_(16, "N*m")})
    by_name = with_changes(case, ratio=Q_(8, ""), durations=Q_(np.array([0.2, 0.6, 0.2, 3.0]), "s"),
                           applied_torque=Q_(16, "N*m"))
    assert by_path.ratio == by_name.ratio == Q_(8, "")
    assert by_path.sections == by_name.sections
    torque = with_inputs(case, {"accuracy.applied_torque": Q_(16, "N*m")})  # written as text, read back by the section
    assert evaluate(torque)["accuracy"]["applied_torque"]["value"] == pytest.approx(16)
    assert np.array_equal(by_path.profile.durations.m_as("s"), by_name.profile.durations.m_as("s"))


def test_input_specs_of_the_example(case):
    specs = {s.key: s for s in input_specs(case, ratios=(5.0, 10.0))}
    assert list(specs) == ["gearbox.ratio", "profile[1].duration", "profile[1].torque", "profile[2].duration",
                           "profile[2].torque", "profile[3].duration", "profile[3].torque", "profile[4].duration",
                           "motor.peak_torque", "motor.inertia", "load.inertia", "coupling.temperature",
                           "accuracy.applied_torque"]
    assert specs["gearbox.ratio"].options == (5.0, 10.0)
    assert specs["motor.peak_torque"].text == "motor peak torque T_1B [N·m]"
    assert specs["load.inertia"].text == "load inertia J_L [kg·cm²]"
    assert specs["coupling.temperature"].text == "coupling temperature ϑ [°C]"
    # The decel torque -45 N·m keeps its sign: -90 to 0 N·m over some 200 pixels, in steps of 0.5 N·m.
    t3 = specs["profile[3].torque"]
    assert (t3.low, t3.high, t3.step, t3.value) == (-90.0, 0.0, 0.5, -45.0)
    # Every value sits on its step, and every range holds its value; a duration never reaches zero.
    for s in specs.values():
        if not s.options:
            assert s.low <= s.value <= s.high and s.value == round(round(s.value / s.step) * s.step, 12)
    assert all(specs[f"profile[{k}].duration"].low > 0 for k in range(1, 5))


@pytest.mark.parametrize("span, step", [(300.0, 2.0), (1.0, 0.005), (7350.0, 50.0), (90.0, 0.5), (140.0, 1.0)])
def test_steps_are_round_and_about_a_pixel(span, step):
    assert nice_step(span) == step
    assert span / 200 <= step < 2.5 * span / 200


def test_results_html_of_the_example(case):
    text = results_html(*evaluated(case))
    assert '<span class="word pass">PASS</span>' in text
    assert "Gearbox <b>NPT035-10</b> · Coupling <b>AKD-30</b>" in text
    # Governing checks typeset as in the figures, no code spelling left.
    assert "<i>T</i><sub>2max</sub> ≤ <i>T</i><sub>2B</sub>" in text and "<i>K</i><sub>ϑ</sub>" in text
    assert "T_2B" not in text and "C_total" not in text and "N*m" not in text
    assert re.search(r"\b(?:NaN|nan)\b", text) is None  # a number, not the "nan" of "resonance"
    # Full reasons with the rated value and the excess (TP010-10: T_2max 151.3 N·m against T_2B 126 N·m).
    assert "rated 126 N·m, 20.1 % over" in text
    # No index column: the first column of each candidate table is the rank.
    assert text.count("<thead><tr><th>rank</th>") == 2
    assert "True" not in text and "False" not in text
    # A check the catalog cannot decide says so, not FAIL (NPT035-10's row gives no F_2R).
    assert '<span class="open">not checked: the catalog gives no <i>F</i><sub>2R</sub></span>' in text
    assert "<sub>hub,max</sub>" in text
    # The motor's peak torque governs too: the typed cycle through NPT035-10 (i = 10, η = 0.97) needs
    # 60 N·m / (10 · 0.97) = 6.186 N·m at the motor (no rotor term), against T_1B = 12 N·m.
    assert '<td class="">motor</td>' in text and "6.186 N·m" in text


def test_a_failing_accuracy_requirement_gives_its_numbers(case):
    # T = 2 N·m is below 3 % of T_N... the 3 % rule: 2 N·m < 0.03 · 110 N·m = 3.3 N·m, so the
    # positioning accuracy is the lost motion (E13): 9.049 arcmin against the required 5 arcmin.
    text = results_html(*evaluated(with_changes(case, applied_torque=Q_(2, "N*m"))))
    assert '<span class="word fail">FAIL</span>' in text
    assert "positioning accuracy 9.049 arcmin &gt; required 5 arcmin, 81 % over" in text


def test_a_case_that_checks_nothing_says_so(write_case):
    from tests.conftest import PROFILE_TOML

    from calc.sections.case import read_case as read

    report, left_out = evaluated(read(write_case(PROFILE_TOML)))
    text = results_html(report, left_out)
    assert '<span class="word open">NOT DECIDED</span>' in text and "Nothing is checked" in text
    assert "Governing checks" not in text and "Gearbox candidates" not in text
    panel = DesignReview(write_case(PROFILE_TOML, "only-a-cycle.toml"))  # its controls: the cycle's alone
    cycle = {f"profile[{k}].{w}" for k in (1, 2, 3) for w in ("duration", "torque")} | {"profile[4].duration"}
    assert set(panel.controls) == cycle
    assert "NOT DECIDED" in panel.results.value


def test_panel_controls_re_evaluate_the_case():
    review = DesignReview(EXAMPLE)
    assert {"gearbox.ratio", "profile[1].duration", "profile[1].torque", "motor.peak_torque", "motor.inertia",
            "load.inertia", "coupling.temperature", "accuracy.applied_torque"} <= set(review.controls)
    first = review.generation
    assert "PASS" in review.results.value and review.load_cycle.value.startswith('<svg class="dr-load-cycle"')
    cycle, chain = review.load_cycle.value, review.chain.value
    # The example's chain by hand (test_the_accuracy_chain_follows_a_change_of_ratio): AKD-30 727.2 and
    # NPT035-10 22 N·m/arcmin at the output, so shares 1/727.2 : 1/22 = 2.94 % : 97.1 %.
    assert chain.startswith('<svg class="dr-chain"') and "2.94 %: " in chain and "97.1 %: " in chain
    review.controls["coupling.temperature"].value = 60.0
    review.settled()
    assert review.generation == first + 1  # one update per change
    # a bellows coupling has no temperature factor
    assert (review.load_cycle.value, review.chain.value) == (cycle, chain)
    review.controls["profile[2].torque"].value = 21.0
    review.settled()
    assert review.load_cycle.value != cycle and review.chain.value == chain  # the load cycle only
    review.controls["motor.peak_torque"].value = 30.0
    review.settled()
    # T_2max = 30 · 10 · 1.3 · 0.97 = 378.3 N·m, above NPT035-10's T_2B of 220 N·m: NPS045-10 (400 N·m)
    # is chosen; the coupling follows the motor's torque (AKN-60: of the two 75 N·m sizes, AKD-60 and
    # AKN-60, the drive train's first mode is higher with AKN-60, 228.4 Hz against 227.8 Hz, so its
    # worst utilization, 2 f_er / f_1 = 200 / 228.4, is the lower), and with both the accuracy chain.
    assert "Gearbox <b>NPS045-10</b> · Coupling <b>AKN-60</b>" in review.results.value
    assert "378.3 N·m" in review.results.value
    assert "NPS045-10" in review.chain.value and "NPT035-10" not in review.chain.value
    review.reset.click()  # back to the case file's values
    assert review.controls["motor.peak_torque"].value == 12.0
    assert "PASS" in review.results.value and review.chain.value == chain


def test_changes_that_arrive_while_drawing_are_drawn_once_together():
    import threading

    review = DesignReview(EXAMPLE)
    first, drawing, draw = review.generation, threading.Event(), review.refresh
    review.refresh = lambda: drawing.wait(10) and draw()  # the first drawing lasts until all values are set
    for t in (13.0, 14.0, 15.0, 16.0, 17.0):
        review.controls["motor.peak_torque"].value = t
    drawing.set()
    review.settled()
    # Five values, at most two drawings: the one under way (which may already read a later value),
    # then what came meanwhile, at once.
    assert first + 1 <= review.generation <= first + 2
    assert "</i><sub>2max</sub> 214.4 N·m" in review.results.value  # 17 N·m · 10 · 1.3 · 0.97, the last value


def test_a_case_that_cannot_be_evaluated_says_why_instead_of_raising(case):
    text = results_html(*evaluated(with_changes(case, ratio=Q_(13, ""))))
    assert "FAIL" in text and "has ratio 13" in text
    bad = DesignReview(EXAMPLE.parent / "missing.toml")
    assert "the case file does not exist" in bad.message.value


def test_the_panel_offers_the_case_files_of_its_folder_only(tmp_path):
    import shutil

    for name in ("a.toml", "b.toml"):
        shutil.copy(EXAMPLE, tmp_path / name)
    (tmp_path / "notes.txt").write_text("not a case")
    review = DesignReview(tmp_path / "a.toml")
    assert [label for label, _ in review.case_file.options] == ["a.toml", "b.toml"]
    review.case_file.value = tmp_path / "b.toml"
    assert review.state.case.path == tmp_path / "b.toml"


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
    text = results_html(*evaluated(with_changes(case, ratio=Q_(8, ""))))
    # TP010-8's transmission accuracy is not known (the catalog gives none): 0.365 arcmin is a lower
    # bound, so the required 5 arcmin is not decided, and the page says which part and figure.
    assert a["positioning_accuracy_is_lower_bound"] and a["unknown"] == [
        "TP010-8: its transmission accuracy (the trace of NPT035-10 does not apply to it, and the case gives no "
        "transmission_accuracy)"]
    assert a["checks"][0]["passes"] is None and r["verdict"]["passes"] is None
    assert '<span class="word open">NOT DECIDED</span>' in text
    assert "Gearbox <b>TP010-8</b>" in text and "≥ 0.365 arcmin" in text
    # Beside the verdict, the checks not made: TP010-8's F_2R (no rating), the positioning accuracy,
    # the motor's RMS and speed (the case gives no ratings).
    assert "<b>a lower bound</b>: unknown TP010-8: its transmission accuracy" in text and "4 checks not made" in text


def test_a_section_that_no_longer_fits_is_left_out_not_everything(write_case):
    # A chain that names NPT035-10 (a 10:1 part) no longer fits the drive train at ratio 8.
    # The review still shows the gearbox and the coupling, and says FAIL with the reason.
    text = EXAMPLE.read_text()
    start = text.index("[[accuracy.component]]")
    named = text[:start] + '[[accuracy.component]]\npart = "NPT035-10"\n'
    report, left_out = evaluated(with_changes(read_case(write_case(named)), ratio=Q_(8, "")))
    shown = results_html(report, left_out)
    assert "FAIL" in shown and "The accuracy section cannot be evaluated with these inputs" in shown
    assert "NPT035-10" in shown
    # catalogs/gearboxes.csv, the complete rows at ratio 8 (the SP+ rows are partial, never ranked).
    assert {c.part for c in report.evaluated["gearbox"].selection.candidates()} == {f"{s}-8" for s in (
        "TP004", "TP010", "TP050", "TP300", "TP500", "NPT005", "NPT015", "NPT025", "NPT035", "NPT045", "NPS015",
        "NPS045")}
    assert "Coupling candidates" in shown and "Accuracy of the chain" not in shown


def test_slider_labels_read_as_written():
    panel = DesignReview(EXAMPLE)
    described = [s.text for s in panel.state.specs]
    assert "load inertia J_L [kg·cm²]" in described
    assert not any("··" in d or "**" in d or "*" in d for d in described)
    assert all(c.tooltip for c in panel.controls.values())  # no empty ("null") tooltip


def test_a_report_link_is_shown_beside_the_verdict():
    panel = DesignReview(EXAMPLE, report_link=lambda path: f"reports/{path.stem}.pdf")
    assert '<a href="reports/indexing-table-profile.pdf"' in panel.results.value


def test_the_server_starts_voila_without_the_unit_registry_or_the_panel():
    # python -m calc.review.serve replaces itself with Voila: what it imports first, a reviewer waits for (pint's
    # registry and the panel were 0.2 s). The package's names still come when asked for.
    import subprocess
    import sys

    probe = ("import sys, calc.review.serve; print(sorted(m for m in ('pint', 'ipywidgets', 'numpy', 'calc.core.units',"
             " 'calc.review.panel') if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"
    import calc
    import calc.review
    from calc.core.units import ureg

    assert calc.ureg is ureg and calc.review.DesignReview is DesignReview
    for package, name in ((calc, "Q"), (calc.review, "Panel")):
        with pytest.raises(AttributeError, match=f"has no attribute '{name}'"):
            getattr(package, name)


def test_the_served_page_offers_the_panel_alone_and_culls_idle_kernels(capsys):
    from calc.review import serve

    argv = serve.command(8866)
    # Voilà's own main, one slow import kept out of the server (the browser tests run it).
    assert argv[argv.index("-c") + 1] == serve.LAUNCH and serve.LAUNCH.endswith("from voila.app import main; main()")
    assert "'compress_response': True" in serve.LAUNCH  # every response compressed
    assert str(serve.PAGE) in argv and serve.PAGE.is_file()
    assert "--Voila.ip=127.0.0.1" in argv and "--strip_sources=True" in argv and "--preheat_kernel=True" in argv
    # The waiting kernel's successor starts 3 s after a page takes it, not during that page's drawing.
    assert "--VoilaKernelManager.fill_delay=3" in argv and "--pool_size=1" in argv
    # Culled within a minute of the page closing: idle 45 s, looked at every 15 s.
    assert "--MappingKernelManager.cull_idle_timeout=45" in argv and "--MappingKernelManager.cull_interval=15" in argv
    assert "--MappingKernelManager.cull_connected=False" in argv
    # The page loads the widgets' scripts and no other JupyterLab extension of the environment.
    assert f"--VoilaConfiguration.extension_allowlist={list(serve.PAGE_EXTENSIONS)!r}" in argv
    # Checked by hand in a browser with idle_seconds=6: two pages opened and closed, their two
    # kernels culled some 8 s later, the waiting kernel kept.
    assert "--MappingKernelManager.cull_idle_timeout=6" in serve.command(8866, idle_seconds=6)
    assert serve.environment(EXAMPLE)[serve.CASE_VARIABLE] == str(EXAMPLE.resolve())
    assert serve.main(["--cases", str(EXAMPLE.parent), "--case", "missing.toml"]) == 2
    assert "missing.toml: the case file does not exist" in capsys.readouterr().err


def test_make_review_culls_within_a_minute_and_idle_minutes_sets_the_timeout(monkeypatch):
    # What `python -m calc.review.serve` runs (its exec caught): by default a closed page's kernel is culled
    # after 45 s, looked at every 15 s, so within 60 s; the browser test serves with --idle-minutes 5/60 (5 s).
    from calc.review import serve

    ran = []
    monkeypatch.setattr(serve.os, "execve", lambda path, argv, env: ran.append(argv))
    serve.main(["--cases", str(EXAMPLE.parent), "--case", EXAMPLE.name, "--port", "0"])
    serve.main(["--cases", str(EXAMPLE.parent), "--case", EXAMPLE.name, "--port", "0", "--idle-minutes", str(5 / 60)])
    timeouts = [[int(a.split("=")[1]) for a in argv if a.startswith(("--MappingKernelManager.cull_idle_timeout=",
                                                                        "--MappingKernelManager.cull_interval="))]
                for argv in ran]
    assert timeouts == [[45, 15], [5, 5]] and sum(timeouts[0]) <= 60


def test_a_derived_cycle_offers_its_mechanism_and_moves_not_its_segments():
    panel = DesignReview(DERIVED_EXAMPLE)
    specs = {s.key: s for s in panel.state.specs}
    assert list(specs) == ["gearbox.ratio", "mechanism.inertia", "mechanism.friction_torque",
                           "mechanism.process_torque", "move[1].distance", "move[1].time", "move[1].accel_time",
                           "move[1].decel_time", "move[1].jerk_time", "move[2].dwell", "coupling.temperature",
                           "accuracy.applied_torque", "drive.brake_resistor.resistance",
                           "drive.brake_resistor.continuous_power", "drive.brake_resistor.peak_power", "gearbox.part",
                           "motor.part"]
    # The decel time the file leaves out is offered at the value reading the file takes: the accel time.
    assert (specs["move[1].decel_time"].unit, specs["move[1].decel_time"].value) == ("s", 0.15)
    # In the file's units: the index of 90 deg, the table's 1500 kg·cm²; the friction 3 N·m, the
    # process torque left out (0 N·m, its default).
    assert (specs["move[1].distance"].unit, specs["move[1].distance"].value) == ("deg", 90.0)
    assert specs["mechanism.inertia"].text == "mechanism: load inertia J_L [kg·cm²]"
    assert specs["mechanism.inertia"].value == 1500.0
    assert (specs["mechanism.process_torque"].low, specs["mechanism.process_torque"].value) == (0.0, 0.0)
    # A ramp reaches up to the whole move (0.5 s), so a reviewer can make the move impossible.
    assert specs["move[1].accel_time"].high == 0.5 and specs["move[1].jerk_time"].high == 0.5
    assert all(s.low > 0 for k, s in specs.items() if k.startswith("move[") and not k.endswith("distance"))
    assert "Motion: rotary from its moves · peak speed 42.86 rpm" in panel.results.value
    assert panel.state.changed_case().motion is panel.state.case.motion  # no control moved: the case as read


def test_the_inch_pound_example_offers_its_inputs_in_its_units():
    from tests.conftest import ROOT

    specs = {s.key: s for s in input_specs(read_case(ROOT / "cases" / "linear-axis-inch.toml"))}
    assert {k: (specs[k].unit, specs[k].value) for k in ("mechanism.mass", "mechanism.lead", "mechanism.screw_inertia",
                                                         "mechanism.eta", "mechanism.incline", "move[3].distance")} == {
        "mechanism.mass": ("lb", 60.0), "mechanism.lead": ("in", 1.0), "mechanism.screw_inertia": ("lb*in**2", 2.7),
        "mechanism.eta": ("", 0.9), "mechanism.incline": ("deg", 90.0), "move[3].distance": ("in", 10.0)}
    # The process force the file leaves out comes in the mechanism's units too.
    assert specs["mechanism.force"].text == "mechanism: process force F_p [lbf]"
    # Either way, so a move can be reversed.
    distance = specs["move[1].distance"]
    assert (distance.low, distance.high, distance.value) == (-50.0, 50.0, -10.0)
    assert "load.inertia" not in specs  # the mechanism gives J_L
    assert specs["mechanism.eta"].low == 0.5 and specs["mechanism.eta"].high == 1.0


def test_a_heavier_load_is_derived_again_as_reading_the_file_derives_it(write_case):
    from tests.conftest import ROOT

    case = read_case(ROOT / "cases" / "linear-axis-inch.toml")
    changed = with_inputs(case, {"mechanism.mass": Q_(80, "lb"), "mechanism.eta": Q_(0.8, "")})
    # J_L = m·r² + J_M with r = p / 2π = 1 in / 2π = 0.159155 in: 80 lb · 0.0253303 in² + 2.7 lb·in²
    # = 4.72642 lb·in² (13.8314 kg·cm²); the file's 60 lb gave 4.21982 lb·in².
    assert changed.load_inertia.m_as("lb*in**2") == pytest.approx(4.72642, rel=1e-5)
    assert case.load_inertia.m_as("lb*in**2") == pytest.approx(4.21982, rel=1e-5)
    assert changed.motion.tables["mechanism"]["eta"] == 0.8 and case.motion.tables["mechanism"]["mass"] == "60 lb"
    # The same as a file that says so.
    text = ((ROOT / "cases" / "linear-axis-inch.toml").read_text().replace('mass = "60 lb"', 'mass = "80 lb"')
            .replace("eta = 0.90", "eta = 0.8"))
    assert evaluate(changed) == evaluate(dataclasses.replace(read_case(write_case(text)), path=case.path))


TRAPEZOID = """title = "a quarter turn, trapezoid"
[gearbox]
ratio = 10
[mechanism]
type = "rotary"
inertia = "1500 kg*cm**2"
[[move]]
distance = "90 deg"
time = "0.5 s"
accel_time = "0.15 s"
[[move]]
dwell = "1.0 s"
"""


def test_move_times_set_the_accelerating_torque(write_case):
    # A trapezoid of φ = π/2 rad in t with ramps t_a: α_2 = φ / (t_a·(t − t_a)), T = J_L·α_2 (no friction).
    # t = 0.5 s, t_a = 0.15 s: α_2 = 1.570796 / (0.15 · 0.35) = 29.9199 rad/s², T = 0.15 kg·m² · α_2 = 4.48799 N·m.
    case = read_case(write_case(TRAPEZOID))
    assert case.profile.torques[0].m_as("N*m") == pytest.approx(4.48799, rel=1e-5)
    # t = 1.0 s: α_2 = 1.570796 / (0.15 · 0.85) = 12.3200 rad/s², T = 1.84800 N·m.
    longer = with_inputs(case, {"move[1].time": Q_(1.0, "s")})
    assert longer.profile.torques[0].m_as("N*m") == pytest.approx(1.84800, rel=1e-5)
    # Every time doubled (t = 1.0 s, t_a = 0.3 s): α_2 = φ / (4·t_a·(t − t_a)), a quarter: T = 1.12200 N·m.
    slower = with_inputs(case, {"move[1].time": Q_(1.0, "s"), "move[1].accel_time": Q_(0.3, "s")})
    assert slower.profile.torques[0].m_as("N*m") == pytest.approx(4.48799 / 4, rel=1e-5)
    # Every result follows: ED = 1.0 s / 2.0 s = 50 % (it was 0.5 / 1.5 = 33.3 %), peak speed
    # ω = φ / (t − t_a) = 1.570796 / 0.7 = 2.24399 rad/s = 21.4286 rpm.
    r = evaluate(slower)
    assert r["duty"]["ED"]["value"] == pytest.approx(50.0)
    assert evaluate(case)["duty"]["ED"]["value"] == pytest.approx(100 / 3)
    assert r["motion"]["peak_speed"]["value"] == pytest.approx(21.4286, rel=1e-5)
    assert r["motion"]["segments"][0]["torque"]["value"] == pytest.approx(1.12200, rel=1e-5)


def test_an_impossible_move_shows_the_input_error_and_the_panel_recovers():
    panel = DesignReview(DERIVED_EXAMPLE)
    first = panel.results.value
    panel.controls["move[1].accel_time"].value = 0.3  # 0.3 s + 0.3 s > 0.5 s
    panel.settled()
    assert "input error</b>: " in panel.results.value and "Governing checks" not in panel.results.value
    # The control by its label, the case file by its name (no folder of the server), no figure.
    assert ("1 move: accel time <i>t</i><sub>a</sub>: expected acceleration and deceleration times that fit in the "
            "move") in panel.results.value
    assert "move[1]" not in panel.results.value.split("data-changed")[1].split(">", 1)[1]
    assert str(DERIVED_EXAMPLE.parent) not in panel.results.value
    assert panel.load_cycle.layout.display == "none" and panel.chain.layout.display == "none"
    assert "found 0.3 s + 0.3 s &gt; 0.5 s" in panel.results.value
    panel.controls["move[1].accel_time"].value = 0.15
    panel.settled()
    again = panel.results.value.replace(f'data-generation="{panel.generation}"', "")
    assert again == first.replace('data-generation="1"', "")
    panel.controls["move[1].jerk_time"].value = 0.1  # over half of 0.15 s
    panel.settled()
    assert ("1 move: jerk time <i>t</i><sub>j</sub>: expected a jerk time of at most half the acceleration and the "
            "deceleration time (0.075 s)") in panel.results.value
    panel.controls["move[1].jerk_time"].value = 0.03
    panel.settled()
    assert "PASS" in panel.results.value and "peak speed 42.86 rpm" in panel.results.value


def test_a_recorded_cycle_keeps_its_segments_and_becomes_typed_when_one_is_moved(write_case, tmp_path):
    (tmp_path / "rec.csv").write_text("time [s],speed [rad/s]\n0,0\n1,2\n2,2\n3,0\n")
    path = write_case(TRAPEZOID.split("[[move]]")[0] + '[drive_record]\nfile = "rec.csv"\n')
    panel = DesignReview(path)
    assert "profile[1].torque" in panel.controls and not any(k.startswith("move[") for k in panel.controls)
    panel.controls["profile[1].torque"].value = 9.0
    panel.settled()
    assert panel.state.changed_case().motion is None
    assert "Load cycle: the segments as changed here" in panel.results.value


def test_the_tables_list_the_best_candidates_unless_all_are_asked_for():
    import re

    panel = DesignReview(EXAMPLE)
    notes = re.findall(r"6 of (\d+) candidates shown", panel.results.value)
    assert len(notes) == 2 and all(int(n) > 6 for n in notes)  # the gearbox and the coupling table
    assert panel.results.value.count('<td class="n">7</td>') == 0  # no rank 7
    panel.all_candidates.value = True
    panel.settled()
    assert "candidates shown" not in panel.results.value
    assert panel.results.value.count("<tr><td") + panel.results.value.count("<tr class=chosen><td") > 2 * 7


def test_the_chooser_gives_each_verdict_and_links_a_built_report(tmp_path):
    from calc.review import serve

    panel = DesignReview(DERIVED_EXAMPLE, reports=tmp_path, report_link=lambda pdf: serve.report_address(pdf, tmp_path))
    assert [label for label, _ in panel.case_file.options] == [
        "ball-screw-direct.toml · PASS", "indexing-table.toml · PASS", "linear-axis-inch.toml · PASS"]
    assert "calc report" not in panel.results.value  # not built yet
    (tmp_path / "indexing-table.pdf").write_bytes(b"%PDF-1.4\n")
    panel.reset.click()
    address = "voila/files/" + (tmp_path / "indexing-table.pdf").relative_to(serve.served_root(tmp_path)).as_posix()
    assert f'<a href="{address}" target="_blank">calc report</a>' in panel.results.value


def test_a_case_named_like_the_summary_says_so_in_the_chooser(tmp_path):
    import shutil

    shutil.copy(EXAMPLE, tmp_path / "summary.toml")
    panel = DesignReview(tmp_path / "summary.toml", reports=tmp_path / "reports", report_link=str)
    assert "would be overwritten by the summary" in panel.message.value and "PASS" in panel.results.value


def test_the_server_serves_the_folder_of_page_and_reports_and_only_the_reports_pdfs(tmp_path):
    import re

    from calc.review import serve
    from tests.conftest import ROOT

    # As make review runs it: the project is served, the PDFs directly in reports/ only.
    reports = ROOT / "reports"
    assert serve.served_root(reports) == ROOT
    patterns = serve.allowed(reports)
    allowed = lambda path: any(re.fullmatch(p, path, re.IGNORECASE) for p in patterns)  # noqa: E731 (as Voilà matches)
    assert allowed("reports/indexing-table.pdf")
    assert not allowed("reports/calc-report.ipynb") and not allowed("reports/x/y.pdf")
    assert not allowed("cases/indexing-table.toml") and not allowed("indexing-table.pdf")
    assert serve.report_address(reports / "axis 3.pdf", reports) == "voila/files/reports/axis%203.pdf"
    argv = serve.command(8866, reports=reports)
    assert f"--Voila.root_dir={ROOT}" in argv and f"--VoilaConfiguration.file_allowlist={patterns!r}" in argv
    # A folder that holds the page: its PDFs are served from the top of it.
    assert serve.allowed(ROOT / "calc") == [r"[^/]+\.pdf"]
    assert serve.environment(EXAMPLE, tmp_path)[serve.REPORTS_VARIABLE] == str(tmp_path.resolve())


# -- never silently changed, kept, compared ------------------------------------------------------


def test_a_typed_value_is_read_with_a_decimal_comma_and_refused_outside_its_range_never_clamped():
    panel = DesignReview(DERIVED_EXAMPLE)
    first = panel.generation
    panel.fields["move[2].dwell"].value = "0,6"  # a decimal comma: 0.6 s, not 6 s
    panel.settled()
    assert panel.controls["move[2].dwell"].value == 0.6 and panel.fields["move[2].dwell"].value == "0.6"
    assert panel.generation > first and not panel.state.refused
    for typed, why in (("1e9", "outside the range"), ("-40", "outside the range"), ("abc", "is not a number"),
                       ("0", "outside the range")):
        panel.fields["mechanism.inertia"].value = typed
        panel.settled()
        assert panel.controls["mechanism.inertia"].value == 1500.0  # kept, not clamped
        assert why in panel.rows.messages["mechanism.inertia"].value
        assert "dr-refused" in panel.fields["mechanism.inertia"]._dom_classes
        assert "Not applied" in panel.results.value and "load inertia" in panel.results.value
    panel.fields["mechanism.inertia"].value = "1600"
    panel.settled()
    assert not panel.state.refused and panel.rows.messages["mechanism.inertia"].value == ""
    assert "Not applied" not in panel.results.value
    # The results carry the field texts they were computed for, and the changed ones.
    assert '&quot;mechanism.inertia&quot;: &quot;1600&quot;' in panel.results.value


def test_the_saved_case_file_reproduces_the_screen_and_keeps_the_comments(tmp_path):
    import shutil

    for p in (DERIVED_EXAMPLE, DERIVED_EXAMPLE.parent / "linear-axis-inch.toml"):
        shutil.copy(p, tmp_path / p.name)
    (tmp_path / "data").mkdir()
    for p in (DERIVED_EXAMPLE.parent.parent / "data").glob("*.csv"):
        shutil.copy(p, tmp_path / "data" / p.name)
    original = tmp_path / DERIVED_EXAMPLE.name
    text = original.read_text().replace("../data/", "data/")
    original.write_text(text)
    panel = DesignReview(original)
    panel.controls["move[1].time"].value = 0.6
    panel.controls["mechanism.inertia"].value = 1600.0
    panel.controls["coupling.temperature"].value = 60.0
    panel.settled()
    assert panel.save("indexing-table.toml") is None and "exists" in panel.kept.value  # never over a file
    assert panel.save("../elsewhere.toml") is None and "no folder" in panel.kept.value  # only in the cases' folder
    saved = panel.save("axis-3-slower.toml")
    assert saved == tmp_path / "axis-3-slower.toml" and original.read_text() == text
    written = saved.read_text()
    assert written.startswith("# Changed in the design review from indexing-table.toml: "
                              "mechanism.inertia 1500 kg*cm**2 -> 1600 kg*cm**2; "
                              "move[1].time 0.5 s -> 0.6 s; coupling.temperature 40 degC -> 60 degC\n")
    # Only the changed values rewritten: every comment and every other line as it was, a comment beside a changed
    # value marked as said of the file's.
    assert written.count("\n") == text.count("\n") + 1 and "# T_f, against the motion while the table turns" in written
    assert ('inertia = "1600 kg*cm**2"      # (said of the file\'s value 1500 kg*cm**2) J_L at the gearbox output'
            in written)
    # The file re-evaluates to the screen's results.
    assert evaluate(read_case(saved))["verdict"] == evaluate(panel.state.shown.case)["verdict"]
    assert evaluate(read_case(saved))["cyclic"] == evaluate(panel.state.shown.case)["cyclic"]
    assert saved in [p for _, p in panel.case_file.options]
    assert 'download="indexing-table-variant-1.toml"' in panel.download.value
    panel.save_name.value = "axis-3-reviewed.toml"  # the download's name follows the save field at once
    assert 'download="axis-3-reviewed.toml"' in panel.download.value


def test_undo_and_redo_step_through_the_changes():
    panel = DesignReview(EXAMPLE)
    def shown():  # the results without their generation count
        return panel.results.value.replace(f'data-generation="{panel.generation}"', "")

    first = shown()
    panel.controls["motor.peak_torque"].value = 30.0
    panel.settled()
    panel.controls["gearbox.ratio"].value = 8.0
    panel.settled()
    assert not panel.undo_button.disabled and panel.redo_button.disabled
    panel.undo()
    assert panel.controls["gearbox.ratio"].value == 10.0 and panel.controls["motor.peak_torque"].value == 30.0
    panel.undo()
    assert panel.state.changes() == {} and shown() == first and panel.undo_button.disabled
    panel.redo()
    assert panel.state.changes() == {"motor.peak_torque": (30.0, "N*m")} and "NPS045-10" in panel.results.value
    assert "dr-changed" in panel.rows.labels["motor.peak_torque"].value
    assert "dr-changed" not in panel.rows.labels["gearbox.ratio"].value


def test_variants_are_compared_side_by_side_and_by_the_command_line(tmp_path):
    import json

    panel = DesignReview(EXAMPLE)
    panel.keep_variant()
    panel.controls["motor.peak_torque"].value = 30.0
    panel.settled()
    panel.keep_variant()
    table = panel.variants_html.value
    # 30 N·m · 10 · 1.3 · 0.97 = 378.3 N·m: NPS045-10 instead of NPT035-10, marked as a difference.
    assert "Variants compared" in table
    assert '<td class="differs">NPS045-10</td>' in table and '<td class="">NPT035-10</td>' in table
    assert '<td class="differs">378.3 N·m</td>' in table and "with motor peak torque" in table
    # The comparison figure: each variant's worst governing utilization per part; the first's
    # gearbox is NPT035-10's T_2max / T_2B = 151.3 / 220 = 69 %.
    figure = table[table.index('<svg class="dr-compared"'):]
    assert '<td class="">69 %</td>' in table and ">69 %</text>" in figure and "variant 2" in figure
    panel.units.value = "inch-pound"  # the comparison follows the unit system shown: 378.3 N·m = 3348 lbf·in
    panel.settled()
    assert '<td class="differs">3348 lbf·in</td>' in panel.variants_html.value
    # The variants' states go with the results (the page's address); a second panel given them
    # (as the page's script gives a link's) shows the same comparison.
    again = DesignReview(EXAMPLE)
    again.units.value = "inch-pound"
    again.settled()
    again.variants_field.value = json.dumps(panel.variants.states)
    assert again.variants_html.value == panel.variants_html.value
    assert [n for n, _ in again.variants.kept] == [n for n, _ in panel.variants.kept]
    import subprocess
    import sys

    stronger = tmp_path / "stronger.toml"
    stronger.write_text(EXAMPLE.read_text().replace('peak_torque = "12 N*m"', 'peak_torque = "30 N*m"')
                        .replace('"../../data/', f'"{EXAMPLE.parent.parent.parent}/data/'))
    done = subprocess.run([sys.executable, "-m", "calc", "compare", str(EXAMPLE), str(stronger), "--json"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    rows = {r["name"]: r for r in json.loads(done.stdout)["rows"]}
    assert rows["gearbox"]["values"] == ["NPT035-10", "NPS045-10"] and rows["gearbox"]["differs"] == [False, True]
    assert rows["T_2max"]["values"][1] == "378.3 N·m" and rows["mode"]["differs"] == [False, False]
    pdf = tmp_path / "compared.pdf"
    text = subprocess.run([sys.executable, "-m", "calc", "compare", str(EXAMPLE), str(stronger), "--pdf", str(pdf)],
                          capture_output=True, text=True).stdout
    assert "NPS045-10 *" in text and text.splitlines()[-1] == "* differs from the first design"
    assert pdf.read_bytes()[:5] == b"%PDF-"

    if has_tool("pdftotext"):
        printed = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True, text=True).stdout
        assert "NPS045-10" in printed and "378.3 N·m" in printed and "worst governing utilization" in printed


def test_a_temperature_on_a_bellows_coupling_says_it_has_no_effect():
    panel = DesignReview(EXAMPLE)
    said = panel.rows.messages["coupling.temperature"].value
    assert "no effect on this design: a metal bellows coupling has no temperature factor" in said


def test_the_chooser_gives_the_screens_verdict_once_changed():
    panel = DesignReview(EXAMPLE)
    panel.controls["accuracy.applied_torque"].value = 2.0  # 9.049 arcmin > 5 (FAIL, E13)
    panel.settled()
    assert panel.case_file.label == f"{EXAMPLE.name} · FAIL (changed here)"


def test_what_cannot_be_saved_says_why():
    from calc.core.errors import CalcError
    from calc.review.edit import Edit, changed_text

    text = '[motor]\npeak_torque = "12 N*m"\n[[move]]\ndwell = "1 s"\n'
    with pytest.raises(CalcError, match=r"^motor: not a key path of a case file$"):
        changed_text(text, [], [Edit("motor", "1 s")], "a.toml")
    with pytest.raises(CalcError, match=r"^a.toml: move\[2\].dwell: the file has 1 \[\[move\]\] tables$"):
        changed_text(text, [], [Edit("move[2].dwell", "1 s")], "a.toml")
    # A segment written where the file has none (a derived cycle is typed first: calc.review.inputs.typed_cycle).
    with pytest.raises(CalcError,
                       match=r"^a.toml: profile\[1\].torque: the file has no \[profile\] table to write it in$"):
        changed_text(text, [], [Edit("profile[1].torque", "9 N*m")], "a.toml")
    panel = DesignReview(EXAMPLE)
    panel.fields["motor.peak_torque"].value = "abc"
    panel.settled()
    assert panel.save("anything.toml") is None and "a refused value is in a field" in panel.kept.value
    assert not (EXAMPLE.parent / "anything.toml").exists()


def test_the_report_of_the_screen_rests_on_the_saved_variant(tmp_path, monkeypatch):
    import calc.review.panel

    built = []

    def build(case, pdf):  # the report's own tests build real PDFs; here only what is built, and the link
        import subprocess

        built.append((case, pdf, case.read_text()))
        pdf.write_bytes(b"%PDF-")
        return subprocess.CompletedProcess([], 0, "", "")

    monkeypatch.setattr(calc.review.panel, "_build_report", build)
    case = tmp_path / "axis.toml"
    case.write_text(EXAMPLE.read_text().replace('"../../data/', f'"{EXAMPLE.parent.parent.parent}/data/'))
    reports = tmp_path / "reports"
    reports.mkdir()
    panel = DesignReview(case, reports=reports, report_link=lambda pdf: f"voila/files/{pdf.name}")
    panel.report_of_screen(wait=True)  # nothing changed: the case file's own report
    assert built[-1][:2] == (case, reports / "axis.pdf") and 'href="voila/files/axis.pdf"' in panel.kept.value
    panel.controls["motor.peak_torque"].value = 16.0
    panel.settled()
    panel.report_of_screen(wait=True)
    saved, pdf, text = built[-1]
    assert saved == tmp_path / "axis-variant-1.toml" and pdf == reports / "axis-variant-1.pdf"
    assert 'peak_torque = "16 N*m"' in text and "the screen's design" in panel.kept.value


def test_the_inch_case_shows_inputs_and_results_in_inch_pound_and_switches_to_si():
    from tests.conftest import ROOT

    panel = DesignReview(ROOT / "cases" / "linear-axis-inch.toml")
    # The inputs as the file writes them (60 lb, not 27.2 kg rounded from 27.216 kg).
    assert panel.fields["mechanism.mass"].value == "60" and panel.state.spec("mechanism.mass").unit == "lb"
    assert panel.units.value == "inch-pound"
    inch = panel.results.value
    assert "lbf·in" in inch and "N·m</td>" not in inch
    panel.units.value = "SI"
    panel.settled()
    si = panel.results.value
    assert "N·m" in si and "lbf·in" not in si
    # T_2max in both: 1 lbf·in = 0.112985 N·m.
    import re

    t_si = float(re.search(r"<sub>2max</sub> ([\d.]+) N·m", si).group(1))
    t_in = float(re.search(r"<sub>2max</sub> ([\d.]+) lbf·in", inch).group(1))
    assert t_in * 0.112985 == pytest.approx(t_si, rel=2e-3)
    # The fields switch too: 60 lb = 60 · 0.45359237 kg = 27.2155 kg, its label in kg; 30 kg typed there is
    # 30 / 0.45359237 = 66.1387 lb, which the file keeps in lb.
    assert panel.fields["mechanism.mass"].value == "27.2155" and "[kg]" in panel.rows.labels["mechanism.mass"].value
    assert " [kg]: " in panel.fields["mechanism.mass"].tooltip  # its range too
    panel.fields["mechanism.mass"].value = "30"
    panel.settled()
    saved = panel.state.case_text()
    assert 'mass = "66.13867' in saved and saved.split('mass = "66.1', 1)[1].split("\n")[0].endswith(' lb"')
    # A changed inch value is saved as the file writes it.
    panel.units.value = "inch-pound"
    panel.settled()
    assert panel.fields["mechanism.mass"].value == "66.1387"
    panel.fields["mechanism.mass"].value = "70"
    panel.settled()
    assert 'mass = "70 lb"' in panel.state.case_text()


def test_the_load_cycle_figure_draws_the_segments_steps():
    from calc.review.figures import HEIGHT, LEFT, RIGHT, WIDTH, load_cycle_svg

    case = read_case(EXAMPLE)  # 0.2 s, 0.6 s, 0.2 s, then a pause of 1 s: edges at 0, 0.2, 0.8, 1.0, 2.0 s
    svg = load_cycle_svg(case.profile, evaluate_case(case)["profile"].shown)
    scale = (WIDTH - LEFT - RIGHT) / 2.0
    speed = svg.split('<polyline points="')[1].split('"')[0].split()
    assert [float(p.split(",")[0]) for p in speed] == pytest.approx(
        [LEFT + scale * t for t in (0, 0.2, 0.2, 0.8, 0.8, 1.0, 1.0, 2.0)], abs=0.06)
    assert "Load cycle: ED = 50 %, cycle 2 s, mode S5" in svg
    assert svg.count('fill="#eeeeee"') == 2  # the pause, in both panels
    assert f'viewBox="0 0 {WIDTH} {HEIGHT}"' in svg and len(svg) < 8000


def test_a_forced_gearbox_part_is_checked_alone_and_saved_by_name():
    panel = DesignReview(EXAMPLE)
    assert panel.controls["gearbox.part"].value == "the selection's"
    assert "TP010-10" in panel.state.spec("gearbox.part").options
    assert "NPS035-10" not in panel.state.spec("gearbox.part").options  # a partial row is never checked
    panel.controls["gearbox.part"].value = "TP010-10"
    panel.settled()
    # TP010-10 alone: T_2B = 126 N·m (catalogs/gearboxes.csv) against T_2max = 151.3 N·m: it fails, by 20.1 %.
    assert '<span class="word fail">FAIL</span>' in panel.results.value and "gearbox TP010-10" in panel.results.value
    assert "required 151.3 N·m &gt; rated 126 N·m, 20.1 % over" in panel.results.value
    assert 'part = "TP010-10"' in panel.state.case_text()
    assert "gearbox.part (not given) -> TP010-10" in panel.state.case_text()
    panel.controls["gearbox.part"].value = "the selection's"
    panel.settled()
    assert "PASS" in panel.results.value and panel.state.changes() == {}


def test_each_candidate_row_can_force_its_part():
    # The gearbox and motor tables mark each row with the control it sets and the part (the served
    # page's script sets it on a click; tests/outputs/test_review_browser.py clicks one).
    panel = DesignReview(DERIVED_EXAMPLE)
    html = panel.results.value
    assert 'data-force="gearbox.part" data-part="NPT025-10"' in html
    assert 'data-force="motor.part" data-part="SGMUH-10DA"' in html
    assert 'data-force="coupling' not in html  # no control forces a coupling


def test_a_move_is_reversed_and_a_ramp_the_file_leaves_out_is_set():
    panel = DesignReview(DERIVED_EXAMPLE)
    first = evaluate(panel.state.changed_case())
    panel.fields["move[1].distance"].value = "-90"  # the index the other way
    panel.settled()
    back = evaluate(panel.state.shown.case)
    # The same index backwards: the same peak speed, the torques mirrored (so the S5 values hold).
    assert back["motion"]["peak_speed"] == first["motion"]["peak_speed"]
    assert back["cyclic"]["T2max"] == first["cyclic"]["T2max"]
    assert back["motion"]["segments"][0]["torque"]["value"] < 0 < first["motion"]["segments"][0]["torque"]["value"]
    panel.fields["move[1].decel_time"].value = "0.2"  # not in the file: written into the move
    panel.settled()
    assert panel.state.shown.case.motion.tables["move"][0]["decel_time"] == "0.2 s"
    assert 'decel_time = "0.2 s"' in panel.state.case_text()


def test_compare_of_a_case_that_cannot_be_evaluated_names_it(tmp_path):
    # python -m calc compare stops at a case the package cannot evaluate, with its one-line error.
    from calc import CalcError
    from calc.review.view import compare_cases

    bad = tmp_path / "bad.toml"
    bad.write_text(EXAMPLE.read_text(encoding="utf-8").replace('catalog = "gearboxes"', 'catalog = "nosuch"', 1),
                   encoding="utf-8")
    with pytest.raises(CalcError, match="gearbox.catalog: the catalog 'nosuch' does not exist"):
        compare_cases([str(EXAMPLE), str(bad)])


def test_compare_never_writes_over_a_pdf(tmp_path):
    # python -m calc compare --pdf refuses a file that exists, and leaves it as it was.
    from calc import CalcError
    from calc.review.view import compare_cases

    pdf = tmp_path / "kept.pdf"
    pdf.write_bytes(b"%PDF- a report signed off")
    with pytest.raises(CalcError, match=r"^--pdf .*kept.pdf: the file exists; name a new one"):
        compare_cases([str(EXAMPLE), str(EXAMPLE)], pdf=pdf)
    assert pdf.read_bytes() == b"%PDF- a report signed off"


def test_a_forced_catalog_motor_is_checked_alone_and_saved_by_name():
    from ..conftest import ROOT

    panel = DesignReview(ROOT / "cases" / "ball-screw-direct.toml")
    spec = panel.state.spec("motor.part")
    assert panel.controls["motor.part"].value == "the selection's" and "SGM7J-04A" in spec.options
    assert "AM8031-wCyz (230 V AC)" not in spec.options  # a partial row is never checked
    assert "Motor <b>SGM7J-02A</b>" in panel.results.value
    panel.controls["motor.part"].value = "SGM7J-04A"
    panel.settled()
    # SGM7J-04A alone: the catalog's next size up (M_N 1.27 N·m, J 0.486 kg·cm²): λ = 2.213 / 0.486 = 4.55.
    assert "Motor <b>SGM7J-04A</b>" in panel.results.value
    assert "PASS" in panel.results.value and ">4.55<" in panel.results.value
    assert 'part = "SGM7J-04A"' in panel.state.case_text()
    assert "motor.part (not given) -> SGM7J-04A" in panel.state.case_text()
    panel.controls["motor.part"].value = "the selection's"
    panel.settled()
    assert "Motor <b>SGM7J-02A</b>" in panel.results.value and panel.state.changes() == {}


def test_moves_added_and_removed_follow_and_are_kept(tmp_path):
    """Entries of the moves added and removed in the panel. The example's cycle is one move of
    0.5 s and a dwell of 1 s: ED = 0.5 / 1.5 = 33.3 %. A dwell added after the dwell (as long as
    the last one, 1 s): ED = 0.5 / 2.5 = 20 %. A move added after the first (a copy of it, 90 deg in
    0.5 s) and turned back: ED = 1.0 / 3.0 = 33.3 % and the table ends where it started. The saved
    file has the edited moves, its comments, and re-evaluates to the screen."""
    case = tmp_path / "axis.toml"
    case.write_text(DERIVED_EXAMPLE.read_text().replace('"../data/', f'"{DERIVED_EXAMPLE.parents[1]}/data/'))
    panel = DesignReview(case).settled()
    ed = lambda: panel.state.shown.report.evaluated.sections["profile"].shown.ED.value  # noqa: E731
    assert ed() == pytest.approx(100 / 3) and [label for label, _ in panel.moves.entry.options] == ["1 move", "2 dwell"]
    panel.add_entry(2, "dwell")
    panel.settled()
    assert ed() == pytest.approx(20.0)
    assert [label for label, _ in panel.moves.entry.options] == ["1 move", "2 dwell", "3 dwell"]
    assert "dr-changed" in panel.rows.labels["move[3].dwell"].value
    assert "dr-changed" not in panel.rows.labels["move[2].dwell"].value
    panel.add_entry(1, "move")
    panel.settled()
    panel.controls["move[2].distance"].value = -90.0
    panel.settled()
    assert [label for label, _ in panel.moves.entry.options] == ["1 move", "2 move", "3 dwell", "4 dwell"]
    assert ed() == pytest.approx(100 / 3)
    back = {"distance": "-90 deg", "time": "0.5 s", "accel_time": "0.15 s", "jerk_time": "0.03 s"}
    assert panel.state.shown.case.motion.tables["move"][1] == back
    panel.remove_entry(4)
    panel.settled()
    assert ed() == pytest.approx(1.0 / 2.0 * 100)
    shown = panel.state.shown.report.evaluated.to_json()
    saved = panel.save("axis-back-and-forth.toml")
    text = saved.read_text()
    assert text.startswith("# Changed in the design review from axis.toml: dwell 1 s added as entry 3; "
                           "move 90 deg in 0.5 s added as entry 2; entry 4 of the moves removed; "
                           "move[2].distance 90 deg -> -90 deg\n")
    assert "# One index: 90 deg in 0.5 s" in text and text.count("\n[[move]]\n") == 3
    again = evaluate_case(read_case(saved)).to_json()
    assert again["verdict"] == shown["verdict"] and again["gearbox"]["selected"] == shown["gearbox"]["selected"]
    assert again["duty"] == shown["duty"]
    # Undo steps back through the edits too: the move turned forwards again, then the move taken out.
    panel.undo()
    assert [label for label, _ in panel.moves.entry.options] == ["1 move", "2 move", "3 dwell", "4 dwell"]
    panel.undo()
    assert panel.controls["move[2].distance"].value == 90.0
    panel.undo()
    assert [label for label, _ in panel.moves.entry.options] == ["1 move", "2 dwell", "3 dwell"]
    # The only move cannot be removed: the panel says why and keeps the moves.
    panel.load()
    panel.remove_entry(1)
    assert panel.message.value.endswith(
        "not removed</b>: axis.toml: move: expected at least one move with a distance, found only dwells")
    assert [label for label, _ in panel.moves.entry.options] == ["1 move", "2 dwell"]


def test_the_results_are_marked_out_of_date_while_a_change_is_computed():
    """The kernel marks the results out of date as a change arrives and current once they are
    drawn: in JupyterLab (notebook 12), where the page's script does not run, that is the mark."""
    import threading

    panel = DesignReview(EXAMPLE)
    assert "dr-busy" not in panel.panel._dom_classes and 'data-state="current"' in panel.status.value
    drawing, go_on = threading.Event(), threading.Event()
    refresh = panel.refresh

    def held():  # the computation held until the marks are read
        drawing.set()
        go_on.wait(10)
        refresh()

    panel.refresh = held
    panel.controls["motor.peak_torque"].value = 16.0
    assert drawing.wait(10)
    assert "dr-busy" in panel.panel._dom_classes and 'data-state="stale"' in panel.status.value
    assert "Out of date: computing" in panel.status.value
    go_on.set()
    panel.settled()
    assert "dr-busy" not in panel.panel._dom_classes and 'data-state="current"' in panel.status.value
    assert "201.8 N·m" in panel.results.value  # 16 · 10 · 1.3 · 0.97


def test_the_mechanism_changes_type_from_equivalent_values(tmp_path):
    """*change type* puts a mechanism of another type in, its values equivalent at the gearbox
    output (calc.domain.mechanism.converted). The example's table as a ball screw of 20 mm lead: the moved
    mass 0.15 kg·m² / (0.02 m / 2π)² = 14 804.4 kg, the friction as drag torque 3 N·m, the quarter
    turn as 0.25 · 20 mm = 5 mm: the output torques are the table's; back to a table, its values
    again. The saved file reads and gives the screen's results."""
    case = tmp_path / "axis.toml"
    case.write_text(DERIVED_EXAMPLE.read_text().replace('"../data/', f'"{DERIVED_EXAMPLE.parents[1]}/data/'))
    panel = DesignReview(case).settled()
    before = panel.state.shown.case.profile
    panel.change_mechanism("ball-screw", "20")
    panel.settled()
    screw = panel.state.shown.case
    mechanism = screw.motion.tables["mechanism"]
    assert mechanism["type"] == "ball-screw" and mechanism["lead"] == "20 mm" and mechanism["drag_torque"] == "3 N*m"
    assert float(mechanism["mass"].split()[0]) == pytest.approx(0.15 / (0.02 / (2 * np.pi)) ** 2, rel=1e-9)
    assert screw.motion.tables["move"][0]["distance"] == "5 mm"
    np.testing.assert_allclose(screw.profile.torques.m_as("N*m"), before.torques.m_as("N*m"), rtol=1e-9)
    np.testing.assert_allclose(screw.profile.durations.m_as("s"), before.durations.m_as("s"), rtol=1e-12)
    assert "set by the change of the mechanism" in panel.rows.labels["mechanism.mass"].value
    # The field shows the mass used, not the slider's step (500 kg over its range): 14804.4066, not 15000.
    assert panel.fields["mechanism.mass"].value == "14804.4066" and panel.controls["mechanism.mass"].value == 15000
    assert "mechanism.mass" not in panel.state.changes()
    saved = panel.save("axis-screw.toml")
    assert saved.read_text().startswith(
        "# Changed in the design review from axis.toml: mechanism rotary -> ball-screw of 20 mm")
    assert evaluate_case(read_case(saved)).to_json()["verdict"] == (
        panel.state.shown.report.evaluated.to_json()["verdict"])
    panel.change_mechanism("rotary")
    panel.settled()
    table = panel.state.shown.case.motion.tables["mechanism"]
    assert table == {"type": "rotary", "inertia": "1500 kg*cm**2", "friction_torque": "3 N*m",
                     "process_torque": "0 N*m"}
    panel.change_mechanism("belt", "0")
    assert ("type not changed</b>: a belt needs its diameter: expected a number above zero (in mm), "
            "found &#x27;0&#x27;") in panel.message.value


def test_a_linear_axis_becomes_a_table_with_the_torques_the_drive_gives():
    """The direct ball screw (40 kg, lead 10 mm, screw 1.2 kg·cm², η 0.9, μ 0.05, drag 0.05 N·m) as a
    table, by hand with r = 10 mm / 2π = 1.59155 mm: J_L = 40 · r² / 0.9 + 1.2 = 2.32579 kg·cm²,
    T_f = 0.05 · 40 · 9.80665 · r / 0.9 + 0.05 = 0.084684 N·m; a move of s mm turns s / r rad."""
    from pathlib import Path

    panel = DesignReview(Path(DERIVED_EXAMPLE).parent / "ball-screw-direct.toml").settled()
    before = panel.state.shown.case.motion
    panel.change_mechanism("rotary")
    panel.settled()
    table = panel.state.shown.case.motion.tables["mechanism"]
    assert float(table["inertia"].split()[0]) == pytest.approx(2.32579, abs=5e-6)
    assert float(table["friction_torque"].split()[0]) == pytest.approx(0.084684, abs=5e-7)
    r = 10 / (2 * np.pi)
    s = float(before.tables["move"][0]["distance"].split()[0])
    turned = float(panel.state.shown.case.motion.tables["move"][0]["distance"].split()[0])
    assert turned == pytest.approx(np.degrees(s / r), rel=1e-9)


ONE_MOVE = '[[move]]\ndistance = "90 deg"\ntime = "1 s"\n'


@pytest.mark.parametrize("text, edits, message", [
    ('[motor]\npeak_torque = "1 N*m"\n', [("remove", 1)],
     "a.toml: move[1]: the file has no [[move]] tables to add to or remove from"),
    (ONE_MOVE, [("add", 3, {"dwell": "1 s"})], "a.toml: move[4]: the file has 1 [[move]] tables"),
    (ONE_MOVE, [("remove", 0)], "a.toml: move[0]: the file has 1 [[move]] tables"),
    (ONE_MOVE, [("remove", 1)], "a.toml: move[1] is the only [[move]] table: it cannot be taken out"),
])
def test_an_edit_of_the_moves_that_cannot_be_made_says_why(text, edits, message):
    from calc.core.errors import CalcError
    from calc.review.edit import edited_text, moves_edits

    with pytest.raises(CalcError) as err:
        edited_text(text, [e for edit in edits for e in moves_edits(edit)], "a.toml")
    assert str(err.value) == message


def test_a_link_variant_that_no_longer_reads_is_left_out_saying_why():
    import json

    panel = DesignReview(DERIVED_EXAMPLE).settled()
    panel.variants_field.value = json.dumps([
        {"case": "gone.toml", "edits": [], "values": {}},
        {"case": DERIVED_EXAMPLE.name, "edits": [], "values": {"move[9].time": "1"}},
        {"case": DERIVED_EXAMPLE.name, "edits": [], "values": {"gearbox.ratio": "11"}},
        {"case": DERIVED_EXAMPLE.name, "edits": [], "values": {"move[1].time": "0.6"}},
    ])
    said = panel.kept.value
    assert "variant 1: no case file &#x27;gone.toml&#x27; among the cases" in said
    assert f"variant 2: {DERIVED_EXAMPLE.name} has no input move[9].time" in said
    assert "variant 3: gearbox ratio i: &#x27;11&#x27; is not one of its choices" in said
    assert [name for name, _ in panel.variants.kept] == ["1: indexing-table.toml with 1 move: time t 0.6 s"]


def test_the_variants_as_a_pdf(tmp_path):
    """*Variants as PDF* writes the comparison with its figure beside the case (no reports'
    folder given), never over a file, the variants named in full under the title."""
    import subprocess

    case = tmp_path / "axis.toml"
    case.write_text(EXAMPLE.read_text().replace('"../../data/', f'"{EXAMPLE.parents[2]}/data/'))
    panel = DesignReview(case).settled()
    assert panel.variants_pdf_button.disabled and panel.variants_pdf() is None
    panel.keep_variant()
    panel.controls["motor.peak_torque"].value = 30.0
    panel.settled()
    panel.keep_variant()
    assert not panel.variants_pdf_button.disabled
    first, second = panel.variants_pdf(), panel.variants_pdf()
    assert (first.name, second.name) == ("axis-variants-1.pdf", "axis-variants-2.pdf")
    assert first.read_bytes()[:5] == b"%PDF-" and "the variants compared, as a PDF" in panel.kept.value
    if has_tool("pdftotext"):
        text = subprocess.run(["pdftotext", "-layout", str(first), "-"], capture_output=True, text=True).stdout
        assert "variant 1" in text and "variant 2" in text and "378.3 N·m" in text and "NPS045-10" in text
        assert "2: axis.toml with motor peak torque" in text and "worst governing utilization" in text


def test_the_page_and_the_report_draw_the_same_stiffness_chain():
    # Both drawings take their bars and labels from the example's accuracy record (stiffness_chain_bars).
    import re

    from calc.figures.accuracy_plots import stiffness_chain_figure
    from calc.review.figures import WIDTH, stiffness_chain_svg

    shown = evaluate_case(read_case(DERIVED_EXAMPLE))["accuracy"].shown
    ax = stiffness_chain_figure(shown).axes[0]
    svg = stiffness_chain_svg(shown)
    bars = [float(w) for w in re.findall(r'<rect x="130" y="\d+" width="([\d.]+)"', svg)]
    scale = (WIDTH - 130 - 10) / 110  # the SVG's 110 % across its plot
    assert [b.get_width() for b in ax.patches] == pytest.approx([w / scale for w in bars], abs=0.1 / scale)
    labels = [t.get_text() for t in ax.texts]
    # AKN-18 232.7 and NPT035-10 22 N·m/arcmin at the output: shares 1/232.7 : 1/22 = 8.64 % : 91.4 %, and
    # 8 N·m twists them by 8 / 232.7 = 0.0344 and 8 / 22 = 0.364 arcmin.
    assert labels == ["8.64 %: 0.0344 arcmin, C = 232.7 N·m/arcmin", "91.4 %: 0.364 arcmin, C = 22 N·m/arcmin"]
    assert all(f">{label}</text>" in svg for label in labels)
    assert "C_total = 20.1 N·m/arcmin, twist 0.398 arcmin" in svg and "= 20.1 N·m/arcmin, twist 0.398" in ax.get_title()


def test_the_frequency_response_is_redrawn_on_a_change():
    # The dynamics' part of the page: modes, springs, λ and the response as SVG, drawn again from the
    # changed case's results (another ratio, another gearbox and load at its input: another curve).
    case = read_case(DERIVED_EXAMPLE)
    before = results_html(*evaluated(case))
    after = results_html(*evaluated(with_changes(case, ratio=Q_(8, ""))))
    assert "<h3>Drive-train dynamics</h3>" in before and "anti-resonance (motor held)" in before
    curve = [re.search(r'<svg class=dynamics.*?</svg>', t, re.DOTALL).group(0) for t in (before, after)]
    assert curve[0] != curve[1] and "resonance 265.5 Hz" in curve[0]


def test_a_saved_file_with_tables_its_original_has_not_is_removed_and_not_saved(tmp_path):
    # Save only changes values, moves and the cycle: a file that reads as a case but gains a table
    # (here every table of the example, against an empty original) is removed, and the save is refused.
    from calc.core.errors import CalcError
    from calc.review.keep import write_case

    target = tmp_path / "gained-tables.toml"
    with pytest.raises(CalcError, match=r"^not saved: gained-tables.toml read back has tables the file has not: "):
        write_case(target, EXAMPLE.read_text(encoding="utf-8"), "")
    assert not target.exists()


def test_the_case_shown_is_never_removed_from_the_page(tmp_path):
    import shutil

    (tmp_path / "cases").mkdir()
    shown = tmp_path / "cases" / "indexing-table.toml"
    shutil.copy(EXAMPLE, shown)
    shutil.copytree(EXAMPLE.parent.parent / "data", tmp_path / "data")
    panel = DesignReview(shown)
    panel.remove_written(str(shown))
    assert "not removed" in panel.kept.value and "is the case shown: choose another case first" in panel.kept.value
    assert shown.exists()
