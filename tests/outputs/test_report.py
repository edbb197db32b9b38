"""``python -m calc report``: the PDF calc report, its text, escaping, failing cases and batches.

The PDFs are built once per module (each build runs the report notebook and xelatex, about 10 s)
and read back with pdftotext. Expected numbers are the example's, worked by hand in
tests/outputs/test_cli.py: T_2max = 12 N·m · 10 · 1.3 · 0.97 = 151.32 N·m, T_2m = 35.41 N·m.
"""

import re
import subprocess

import pytest

from calc.core.errors import CalcError
from calc.report.publish import output_paths
from calc.report import build_report, latex_escape, prose
from calc.report.common import case_key

from ..conftest import DERIVED_EXAMPLE, EXAMPLE, HEAD_TOML, PROFILE_TOML, ROOT, needs_tools
from ..conftest import REPORT_TITLE as TITLE

needs_tex = needs_tools("xelatex", "pandoc", "pdftotext")


def pdf_text(path) -> str:
    out = subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True, check=True).stdout
    return out


# -- without TeX ------------------------------------------------------------------------------


def test_latex_escape_of_every_special_character():
    assert latex_escape(TITLE) == r"Axis \#3 — 50\% load \& T\_2 \{v2\} \textbackslash{} 100\$"
    assert latex_escape("~^") == r"\textasciitilde{}\textasciicircum{}"
    # TeX would join these into a dash and a quote; they print as typed.
    assert latex_escape("a--b ''c''") == "a-{}-b '{}'c'{}'"
    assert latex_escape("two\nlines") == "two lines"


def test_prose_sets_symbols_in_math_and_escapes_the_rest():
    assert prose("T_2max <= T_2B: 20 % over") == r"$T_{\mathrm{2max}}$ ≤ $T_{\mathrm{2B}}$: 20 \% over"


def test_a_passing_case_names_its_parts(write_case):
    r = build_report(EXAMPLE)
    assert r.verdict.word == "PASS" and r.reasons == []
    assert ("Gearbox", "NPT035-10") in [(w, p) for w, p, _ in r.chosen]
    assert r.summary_line().startswith("PASS  tests/cases/indexing-table-profile.toml: gearbox NPT035-10")
    # Title block: the case file and each catalog with its SHA-256.
    assert [label for label, _, _ in r.files][:2] == ["Case file", "Gearbox catalog"]
    assert all(re.fullmatch(r"[0-9a-f]{64}", digest) for _, _, digest in r.files)


def test_a_failing_case_says_why(write_case):
    # T_1B = 400 N·m: T_2max = 400 · 10 · 1.3 · 0.95 = 4940 N·m, above every T_2B at ratio 10 (at most
    # TP500-10's 4000 N·m, Beckhoff page 'TP500 MF').
    r = build_report(write_case(HEAD_TOML.replace('"12 N*m"', '"400 N*m"') + PROFILE_TOML))
    assert r.verdict.word == "FAIL"
    assert r.reasons[0] == "No gearbox of ratio 10 in catalogs/gearboxes.csv passes the S5 checks:"
    assert any(x.startswith("TP500-10: T_2max <= T_2B: required 4940 N·m > rated 4000 N·m") for x in r.reasons)
    assert r.front_page().count(r"\item") >= 4


def test_a_case_that_cannot_be_evaluated_gives_a_fail_report(write_case):
    r = build_report(write_case(HEAD_TOML.replace("ratio = 10", "ratio = 13") + PROFILE_TOML))
    assert r.verdict.word == "FAIL"
    assert "no gearbox in catalog" in r.reasons[0] and "has ratio 13" in r.reasons[0]
    assert r.front_page()  # still a title page: title, verdict, the case file and its checksum
    assert "motor.peak" in r.inputs()  # the inputs as read, for the reviewer to see what was asked
    assert r.calculations() == r.checks() == r.candidates() == r.order_lines() == ""


def test_output_paths(tmp_path):
    a, b = tmp_path / "a.toml", tmp_path / "x" / "a.toml"
    assert output_paths([a], None) == [tmp_path.__class__("reports/a.pdf")]
    assert output_paths([a], "out/r.pdf")[0].name == "r.pdf"
    with pytest.raises(CalcError, match="expected a folder"):
        output_paths([a, a.with_name("c.toml")], "out/r.pdf")
    with pytest.raises(CalcError, match="would overwrite the report of"):
        output_paths([a, b], "out")


def report_here(capsys, *args):
    """``python -m calc report ARGS`` in this process (so that the errors it builds are seen by
    tests/test_error_sites.py): exit code and standard error."""
    from calc.__main__ import main

    code = main(["report", *map(str, args)])
    return code, capsys.readouterr().err


def test_a_missing_case_file_is_an_error_before_anything_is_built(capsys, tmp_path):
    code, err = report_here(capsys, tmp_path / "nothing.toml", "-o", tmp_path)
    assert code == 2
    assert err.strip() == f"error: {tmp_path / 'nothing.toml'}: the case file does not exist"
    assert list(tmp_path.iterdir()) == []


def test_missing_programs_are_named_with_what_to_install(capsys, monkeypatch, tmp_path):
    monkeypatch.setenv("PATH", str(tmp_path))  # a PATH with neither xelatex nor pandoc on it
    code, err = report_here(capsys, EXAMPLE, "-o", tmp_path / "example.pdf")
    assert code == 2
    assert err.startswith(
        "error: the PDF report needs xelatex (texlive-xetex), pandoc (pandoc), not found on this machine; "
        "on Debian run `make report` as root (it installs them)"
    )
    assert list(tmp_path.iterdir()) == []


# -- the PDFs ---------------------------------------------------------------------------------


@needs_tex
def test_example_pdf_has_title_verdict_parts_and_numbers(report_run):
    _, out, proc = report_run
    text = pdf_text(out / "indexing-table-profile.pdf")
    assert "Rotary indexing table, axis 3" in text
    assert "Verdict: PASS" in text
    assert "NPT035-10" in text
    assert "151.3 N·m" in text  # T_2max = 12 · 10 · 1.3 · 0.97
    assert "35.41 N·m" in text  # T_2m
    # The motor-side coupling's J_load comes from the case (E8): 1500 / 10² + 0.93 = 15.93 kg·cm²,
    # shown as a marked input and as its own calculation step.
    assert re.search(r"15\.93\s+kg·cm²\s+load-side inertia", text)
    assert re.search(r"coupling\.load_\s*inertia\s*†", text)  # a case key may break after an underscore
    assert "Load inertia seen by the coupling, through NPT035-10" in text
    for heading in ("Method and assumptions", "Inputs", "Calculations", "Checks", "Candidates", "Figures", "Order"):
        assert re.search(rf"^\s*\d+\s+{heading}", text, re.M), heading
    assert re.search(r"Case file\s+\S+\s+[0-9a-f]{64}", text)  # each file with its SHA-256 on one row
    pages = int(re.search(r"Page 1 of (\d+)", text).group(1))
    assert pages >= 5
    assert proc.stdout.strip().startswith("PASS  tests/cases/indexing-table-profile.toml: gearbox NPT035-10")


@needs_tex
def test_title_from_the_case_prints_exactly_as_written(report_run):
    _, out, _ = report_run
    text = pdf_text(out / "escape.pdf")
    assert TITLE in text


@needs_tex
def test_failing_case_report_says_fail_and_why(report_run):
    _, out, _ = report_run
    text = pdf_text(out / "failing.pdf")
    assert "Verdict: FAIL" in text
    assert "The design does not pass. Why:" in text
    assert "No gearbox of ratio 10 in catalogs/gearboxes.csv passes the S5 checks" in text
    assert "Nothing to order: no part passes." in text
    text = pdf_text(out / "unreadable.pdf")
    assert "Verdict: FAIL" in text and "The case cannot be evaluated" in text


@needs_tex
def test_batch_builds_one_pdf_each_with_a_progress_bar_and_a_summary(report_run):
    cases, out, proc = report_run
    # Exit status (spec): a case that cannot be read exits 2 (its PDF still says why), before --strict's 1.
    assert proc.returncode == 2, proc.stderr
    assert sorted(p.name for p in out.iterdir()) == [
        "escape.pdf", "failing.pdf", "indexing-table-profile.pdf", "summary.csv", "summary.pdf", "unreadable.pdf",
    ]
    assert "calc reports" in proc.stderr and "4/4" in proc.stderr
    lines = proc.stdout.strip().splitlines()
    assert [line.split()[0] for line in lines[:-1]] == ["PASS", "PASS", "FAIL", "FAIL"]
    assert lines[1].endswith(str(out / "escape.pdf"))


@needs_tex
def test_strict_exits_1_when_a_verdict_is_not_pass(report_run, tmp_path, monkeypatch, capsys):
    # The command line as `python -m calc report`, in this process; the case's PDF is the one report_run
    # built of it (read by test_failing_case_report_says_fail_and_why), so the exit status costs no second build.
    import shutil

    from calc.__main__ import main
    from calc.report import publish

    cases, out, _ = report_run
    monkeypatch.setattr(publish, "render_pdf", lambda report, pdf, jobs=1: shutil.copy(out / "failing.pdf", pdf))
    status = main(["report", str(cases[2]), "--strict", "-o", str(tmp_path / "failing.pdf")])  # no gearbox passes
    shown = capsys.readouterr()
    assert status == 1, shown.err
    assert shown.out.startswith("FAIL  ") and (tmp_path / "failing.pdf").is_file()


def test_inputs_describe_the_load_inertia_of_the_gearbox_section():
    # load.inertia is the gearbox's J_L (load inertia at the output), not the coupling's J_L of the
    # same name (load side with half the coupling).
    text = str(build_report(EXAMPLE).inputs())
    row = next(line for line in text.splitlines() if "load.inertia" in line)
    assert "load inertia at the output" in row and "half the coupling" not in row


def test_shock_factor_band_is_the_one_the_factor_came_from():
    # 0.1 + 0.1 + 0.1 + 2.1 s gives Z_h = 1499.9999999999998 per hour: on the 1500 boundary (E4), f_s = 1.3,
    # so the band printed is 1500 <= Z_h < 2000, not 1000 <= Z_h < 1500.
    from calc import Q_
    from calc.domain.gearbox import shock_factor
    from calc.domain.profile import Z_h
    from calc.report.duty import shock_factor_block

    zh = Z_h(z_c=Q_(1, ""), t_cycle=Q_(0.1 + 0.1 + 0.1 + 2.1, "s"))
    block = shock_factor_block(zh)
    assert float(shock_factor(zh)) == 1.3
    assert r"1500 \le Z_{\mathrm{h}} < 2000" in block and r"f_{\mathrm{s}} = 1.3" in block


def test_a_derived_load_cycle_shows_its_motion_and_mechanism():
    r = build_report(DERIVED_EXAMPLE)
    assert r.verdict.word == "PASS"
    inputs, steps = str(r.inputs()), str(r.calculations())
    # The mechanism's inputs and the moves; the duty's table says the cycle is derived.
    assert case_key("mechanism.friction_torque") in inputs
    assert "Moves of the load, repeated" in inputs and "derived from the motion" in inputs
    # Each formula with its values: ω_2max = 90° / (0.5 − 0.15/2 − 0.15/2) s = 42.86 rpm;
    # α = 4.488 / 0.12 = 37.4 rad/s²;
    # at the peak acceleration T_2 = 0.15 · 37.4 + 3 = 8.61 N·m.
    assert (r"\omega_{\mathrm{2max}} &= \frac{\varphi_{2}}{t_{\mathrm{m}} - \frac{t_{\mathrm{a}}}{2} - "
            r"\frac{t_{\mathrm{d}}}{2}}") in steps
    assert (
        r"&= 42.86\,\mathrm{rpm}" in steps
        and r"&= 37.4\,\mathrm{rad/s^{2}}" in steps
        and r"&= 8.61\,\mathrm{N\,m}" in steps
    )
    assert "Segments derived from the sampled cycle" in steps
    assert steps.index("Motion and mechanism") < steps.index("Duty cycle and operating mode")
    assert any("derived segments" in caption for _, caption in r.figures())


def test_a_linear_axis_shows_its_radius_inertia_and_force():
    r = build_report(ROOT / "cases" / "linear-axis-inch.toml")
    steps = str(r.calculations())
    # r = 1 in / 2π = 4.043 mm; J_L = 60 lb · r² + 2.7 lb·in² = 4.448 + 7.901 = 12.35 kg·cm².
    assert r"r &= \frac{p}{2 \cdot \pi}" in steps and r"&= 4.043\,\mathrm{mm}" in steps
    assert r"&= 12.35\,\mathrm{kg\,cm^{2}}" in steps
    assert r"F &= a \cdot \left(m + m_{\mathrm{c}}\right)" in steps
    # Driven back (d_P = -1) the screw takes its reverse efficiency η' = 2 - 1/0.9 = 0.8889.
    assert (r"T_{2} &= T_{\mathrm{d}} \cdot s_{\mathrm{v}} + F \cdot r \cdot "
            r"\left(\frac{\eta' \cdot \left(1 - d_{\mathrm{P}}\right)}{2} "
            r"+ \frac{1 + d_{\mathrm{P}}}{2 \cdot \eta}\right)") in steps
    assert r"\left(\frac{0.8889 \cdot" in steps


def test_a_derived_load_inertia_is_not_listed_as_a_case_key():
    inputs = str(build_report(DERIVED_EXAMPLE).inputs())
    assert case_key("load.inertia") not in inputs
    assert case_key("mechanism.inertia") in inputs
    assert case_key("load.inertia") in str(build_report(EXAMPLE).inputs())


def test_front_page_lists_every_governing_check_and_what_is_not_checked():
    # The example: the chosen gearbox's, coupling's and motor's checks under each part's name, the
    # accuracy requirement; the bearing's F_2r is not checked, as the catalog gives no F_2R for
    # NPT035-10 (catalogs/gearboxes.csv). The motor is SGMUH-10DA of catalogs/motors.csv
    # (M_max = 6.5 N·m, M_N = 1.59 N·m): its peak, RMS, speeds and inertia ratio.
    page = str(build_report(DERIVED_EXAMPLE).front_page())
    gearbox, motor, accuracy = (page.split(rf"\textbf{{{name}}}")[1].split(r"\end{itemize}")[0]
                                for name in ("Gearbox NPT035-10", "Motor SGMUH-10DA", "Accuracy"))
    assert (r"$F_{\mathrm{2r}}$ ≤ $F_{\mathrm{2R}}$: \notchecked{} {\footnotesize the catalog gives no "
            r"$F_{\mathrm{2R}}$}") in gearbox and r"$d_{\mathrm{hub,max}}$" in gearbox
    assert (
        r"at every sample: 1.006 N·m against 6.5 N·m" in motor
        and r"$T_{\mathrm{1rms}}$ ≤ $M_{\mathrm{N}}$: 0.3199 N·m against 1.59 N·m" in motor
    )
    assert motor.count(r"\item ") == 5
    assert r"positioning accuracy ≤ required: 1.447" in accuracy
    assert r"\textbf{Coupling AKN-18}" in page


def test_title_block_lists_every_data_file_the_results_rest_on():
    # The derived example reads, beside its case and the four catalogs it names, the clamping-hub
    # table (motor.shaft), the source's shock and temperature tables (E4, E9, the defaults) and
    # the generated transmission trace of its chain: each once, with its SHA-256.
    files = {label_path[1]: label_path[0] for label_path in build_report(DERIVED_EXAMPLE).files}
    assert files == {
        "cases/indexing-table.toml": "Case file",
        "catalogs/gearboxes.csv": "Gearbox catalog",
        "catalogs/couplings.csv": "Coupling catalog",
        "catalogs/motors.csv": "Motor catalog",
        "catalogs/drives.csv": "Drive catalog",
        "catalogs/gearbox-hubs.csv": "Catalog",
        "catalogs/factors/shock-source.csv": "Factor table",
        "catalogs/factors/temperature-source.csv": "Factor table",
        "data/transmission-NPT035-10-generated.csv": "Measurement",
    }
    assert all(re.fullmatch(r"[0-9a-f]{64}", digest) for _, _, digest in build_report(DERIVED_EXAMPLE).files)
