"""The report prints what the evaluation computed, on the example and on two one-line variants of
it: ``motor.shaft = "24 mm k6"`` (the 24 mm clamping hub of NPT035-10, J_1 = 1.7 kg·cm² instead of
the 19 mm hub's 0.93, catalogs/gearbox-hubs.csv) and ``[gearbox] shock_factors`` naming a table of
one band, f_s = 1.5 (the source's table gives 1.6 at the example's Z_h = 2400 /h).

Each number of a step is compared with the same number in the JSON; each criterion, reason and
note the package emits is typeset the same in LaTeX and HTML; a check not made says so in text,
LaTeX and HTML; and no table of the PDF is wider than the text (xelatex's overfull boxes)."""

import re
import shutil

import pytest

from calc.report import publish
from calc.report import build_report
from calc.report.symbols import html, latex
from calc.review.view import results_html
from calc.core.units import sig

from ..conftest import DERIVED_EXAMPLE, ROOT, needs_tools

needs_tex = needs_tools("xelatex", "pandoc", "pdftotext")

SHOCK_TABLE = (
    "from [1/h],to [1/h],factor [1],at_boundary,source\n0,,1.5,higher,a table of one band for every cycle rate\n"
)


@pytest.fixture(scope="module")
def cases(tmp_path_factory):
    """The example and its two variants, each in a folder laid out like the project (the example
    names its measurement as ../data/...)."""
    root = tmp_path_factory.mktemp("variants")
    (root / "cases").mkdir()
    shutil.copytree(ROOT / "data", root / "data")
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8")
    shaft = text.replace('shaft = "19 mm k6" ', 'shaft = "24 mm k6" ', 1)
    shock = text.replace('catalog = "gearboxes"\n', 'catalog = "gearboxes"\nshock_factors = "shock-1.5.csv"\n', 1)
    assert shaft != text and shock != text
    (root / "cases" / "shaft-24.toml").write_text(shaft, encoding="utf-8")
    (root / "cases" / "shock-1.5.toml").write_text(shock, encoding="utf-8")
    (root / "cases" / "shock-1.5.csv").write_text(SHOCK_TABLE, encoding="utf-8")
    return {
        "example": DERIVED_EXAMPLE,
        "shaft-24": root / "cases" / "shaft-24.toml",
        "shock-1.5": root / "cases" / "shock-1.5.toml",
    }


@pytest.fixture(scope="module")
def reports(cases):
    built = {name: build_report(path) for name, path in cases.items()}
    for name, r in built.items():
        assert r.error is None, (name, r.error)
    return built


STEP = re.compile(
    r"\\calcstep\{(?P<title>[^}]*)\}(?:(?!\\calcstep).)*?\\begin\{aligned\}(?P<body>.*?)\\end\{aligned\}", re.S
)


def steps_of(report) -> dict:
    """Each calculation step of the report by its title: its sides as LaTeX (symbol, formula, values, result)."""
    return {
        m["title"]: [side.strip() for side in m["body"].split("&=")] for m in STEP.finditer(str(report.calculations()))
    }


def json_of(report) -> dict:
    """The results of the report's case as ``evaluate --json --all-candidates`` writes them."""
    return report.evaluated.to_json(candidates=None)


def number(d: dict, unit_factor: float = 1.0) -> str:
    """A JSON quantity's number as a step prints it."""
    return sig(d["value"] * unit_factor).replace("-", "−", 1)


@pytest.mark.parametrize("name", ["example", "shaft-24", "shock-1.5"])
def test_every_number_of_the_duty_and_coupling_steps_is_the_json_number(reports, name):
    r = reports[name]
    j, steps = json_of(r), steps_of(r)
    # The duty: ED in %, n_2m in rpm, T_2m in N·m, Z_h in 1/h, as the JSON writes them.
    for title, value in (("Duty cycle", j["duty"]["ED"]), ("Mean output speed", j["continuous"]["n2m"]),
                         ("Cubic mean output torque", j["continuous"]["T2m"]),
                         ("Load cycles per hour", j["cyclic"]["Zh"])):
        assert steps[title][-1].startswith(number(value)), (title, steps[title][-1], value)
    shock = re.search(r"f_\{\\mathrm\{s\}\} = ([\d.]+)", str(r.calculations()))
    assert float(shock.group(1)) == j["cyclic"]["fs"]
    # The coupling sees J_L / i² + J_1 with the J_1 of the hub the gearbox selection chose.
    gearbox = j["gearbox"]["candidates"][0]
    load = next(v for t, v in steps.items() if t.startswith("Load inertia seen by the coupling"))
    assert rf"+ {number(gearbox['J_1'])}\," in load[2], load[2]
    assert load[3].startswith(number({"value": 1500 / 10**2 + gearbox["J_1"]["value"]}))  # J_L = 1500 kg·cm², i = 10
    assert steps["Nominal torque of the coupling"][-1].startswith(number(j["coupling"]["M_N"]))


@pytest.mark.parametrize("name", ["example", "shaft-24", "shock-1.5"])
def test_every_gearbox_step_is_the_required_value_of_its_check_in_the_json(reports, name):
    r = reports[name]
    g, steps = json_of(r)["gearbox"], steps_of(r)
    checks = {k["name"]: k for k in g["candidates"][0]["checks"]}
    for title, check in (
        ("Input speed at the mean output speed (S1)", "n_1N"),
        ("Input speed at the highest output speed (S5)", "n_1max"),
        ("Maximum output torque", "T_2B"),
        ("Tilting moment on the output bearing", "M_2K"),
    ):
        assert steps[title][-1].startswith(number(checks[check]["required"])), (
            title,
            steps[title][-1],
            checks[check]["required"],
        )
    assert steps["Load to motor inertia ratio"][-1] == sig(g["candidates"][0]["inertia_ratio"])
    # The shock factor of T_2max is the case's: 1.5 in the variant, 1.6 (the source's, Z_h = 2400 /h) otherwise.
    assert rf"\cdot {json_of(r)['cyclic']['fs']:g} \cdot" in steps["Maximum output torque"][2]


def test_the_24_mm_hub_is_the_j1_of_every_step(reports):
    # catalogs/gearbox-hubs.csv: NPT035-10's 24 mm hub has J_1 = 1.7 kg·cm²; 1500 / 10² + 1.7 = 16.7.
    load = next(
        v for t, v in steps_of(reports["shaft-24"]).items() if t.startswith("Load inertia seen by the coupling")
    )
    assert r"+ 1.7\," in load[2] and load[3].startswith("16.7")
    assert "24 mm clamping hub" in next(t for t in steps_of(reports["shaft-24"]) if t.startswith("Load inertia seen"))


@pytest.mark.parametrize("name, fs", [("example", 1.6), ("shock-1.5", 1.5)])
def test_the_shock_factor_figure_plots_the_case_table(reports, name, fs):
    r = reports[name]
    assert json_of(r)["cyclic"]["fs"] == fs
    figure = next(f for f, caption in r.figures() if caption.startswith("Shock factor"))
    point = next(line for line in figure.axes[0].lines if line.get_gid() == "case")
    assert float(point.get_ydata()[0]) == fs
    bands = next(line for line in figure.axes[0].lines if line.get_gid() == "included")
    assert list(bands.get_ydata()) == ([1.5] if name == "shock-1.5" else [1.0, 1.1, 1.3, 1.6, 2.0])


def emitted_texts(results: dict) -> list[str]:
    """Every criterion, reason, not-made reason, note and ranking the package writes into the JSON."""
    out = list(results["verdict"]["reasons"])
    for section in results.values():
        if not isinstance(section, dict):
            continue
        out += [section.get("ranking") or ""] + list(section.get("notes") or [])
        for c in [section, *section.get("candidates", [])]:
            out += list(c.get("reasons") or []) if c is not section else []
            for k in c.get("checks") or []:
                out += [k["criterion"], k.get("not_made") or ""]
    return [t for t in out if t]


LATEX_SYMBOL = re.compile(r"\$(\\?\w+)_\{(?:\\mathrm\{([^}]*)\}|([^}]*))\}\$|\$(\\?\w+)\$")
HTML_SYMBOL = re.compile(r"<i>([^<]*)</i>(?:<sub>([^<]*)</sub>)?")
GREEK = {r"\varphi": "φ", r"\eta": "η", r"\lambda": "λ", r"\vartheta": "ϑ"}


def test_every_criterion_and_reason_typesets_the_same_in_latex_and_html(reports):
    texts = sorted({t for r in reports.values() for t in emitted_texts(json_of(r))})
    assert len(texts) > 50 and any("d_hub,max" in t for t in texts) and any("K_ϑ" in t for t in texts)
    for text in texts:
        tex, page = latex(text), html(text)
        in_latex = [(GREEK.get(m[0] or m[3], m[0] or m[3]), GREEK.get(m[1] or m[2], m[1] or m[2]))
                    for m in LATEX_SYMBOL.findall(tex)]
        in_html = [(m[0], m[1]) for m in HTML_SYMBOL.findall(page)]
        assert in_latex == in_html, (text, tex, page)
        prose = re.sub(r"\\texttt\{[^}]*\}", "", tex)  # a case key is code, and code keeps its underscore
        assert r"\_" not in prose and "_" not in re.sub(r"\$[^$]*\$", "", prose), (text, tex)
        assert not re.search(r"\$[^$]*\$,\w", tex), (text, tex)  # no subscript part left outside its symbol (d_hub,max)


def test_a_check_not_made_prints_as_not_checked_in_text_latex_and_html(reports):
    # NPT035-10 (catalogs/gearboxes.csv) has no F_2R: the check F_2r <= F_2R is not made.
    r = reports["example"]
    check = next(k for k in json_of(r)["gearbox"]["candidates"][0]["checks"] if k["name"] == "F_2R")
    assert check["passes"] is None and check["not_made"] == "the catalog gives no F_2R"
    assert "F_2r <= F_2R" in r.evaluated.summary() and "not checked: the catalog gives no F_2R" in r.evaluated.summary()
    row = next(line for line in str(r.checks()).splitlines() if line.startswith(r"$F_{\mathrm{2r}}$"))
    assert r"\notchecked" in row and r"\fail" not in row and r"the catalog gives no $F_{\mathrm{2R}}$" in row
    assert r"\notchecked" in str(r.front_page())
    assert "not checked: the catalog gives no <i>F</i><sub>2R</sub>" in results_html(r, [])


def test_a_rejection_list_shows_the_closest_few_and_the_appendix_all(reports):
    r = reports["example"]
    rejected = [c for c in json_of(r)["coupling"]["candidates"] if c.get("reasons")]
    assert len(rejected) > 5  # catalogs/couplings.csv: most rows fail AKD-30's case
    candidates = str(r.candidates())
    assert f"and {len(rejected) - 5} more, each with its reasons in the appendix" in candidates
    appendix = str(r.appendix())
    assert all(rf"\textbf{{{c['part']}}}" in appendix for c in rejected)


@pytest.fixture(scope="module")
def notebooks(reports):
    """Each case's report notebook (:func:`calc.report.publish.report_notebook`), its figures made once
    for every PDF built from it (the exporter typesets a copy)."""
    return {name: publish.report_notebook(r) for name, r in reports.items()}


def built_pdf(notebook, pdf, kept=None) -> tuple[str, int]:
    """Write the PDF of a report notebook as :func:`calc.report.publish.render_pdf` does, with the pass
    files ``kept`` (:func:`calc.report.publish.kept_passes`, None: none): xelatex's log of the last pass,
    and how many passes xelatex made."""
    exporter = publish.exporter(kept)
    passes = []
    run = exporter.run_command
    exporter.run_command = lambda *args, **kwargs: passes.append(1) or run(*args, **kwargs)
    body, _ = exporter.from_notebook_node(notebook, resources={"metadata": {"name": pdf.stem}})
    pdf.write_bytes(body)
    return exporter.latex_log, len(passes)


@pytest.fixture(scope="module")
def pdfs(notebooks, tmp_path_factory):
    """Each case's PDF, xelatex's log of its last pass and the number of passes. The example keeps the
    files of its last pass (``kept``, the stem :func:`test_a_report_built_again_takes_one_pass_and_typesets_the_same`
    builds again from); the variants keep none."""
    folder = tmp_path_factory.mktemp("pdfs")
    kept = folder / "kept" / "pass-example"
    return {name: (folder / f"{name}.pdf", *built_pdf(notebook, folder / f"{name}.pdf",
                                                        kept if name == "example" else None))
            for name, notebook in notebooks.items()}


@needs_tex
@pytest.mark.parametrize("name", ["example", "shaft-24", "shock-1.5"])
def test_no_table_is_wider_than_the_text(pdfs, name):
    _, log, _ = pdfs[name]
    overfull = re.findall(r"Overfull \\hbox \(([\d.]+)pt too wide\) (in alignment|in paragraph)[^\n]*", log)
    assert not [o for o in overfull if float(o[0]) > 1.0], overfull


@needs_tex
@pytest.mark.parametrize("name", ["shaft-24", "shock-1.5"])
def test_the_pdf_prints_no_absolute_path(pdfs, cases, name):
    import subprocess

    pdf, _, _ = pdfs[name]
    text = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
    assert str(cases[name].parent.parent) not in text
    assert f"{name}.toml" in text and "../data/transmission-NPT035-10-generated.csv" in text


def test_a_number_of_parallel_builds_below_one_is_refused(capsys):
    from calc.__main__ import main

    assert main(["report", str(DERIVED_EXAMPLE), "-j", "0"]) == 2
    assert capsys.readouterr().err.strip() == "error: -j 0: expected a number of parallel builds of 1 or more"


def test_the_report_notebook_shows_the_blocks_the_pdf_typesets(reports):
    # reports/calc-report.ipynb, run as a user runs it in JupyterLab (a kernel, the example case):
    # its LaTeX outputs and figure captions are the blocks calc.report.publish typesets, in order.
    import nbformat
    from nbclient import NotebookClient

    from calc.report import Latex

    notebook = nbformat.read(publish.NOTEBOOK, as_version=4)
    NotebookClient(
        notebook, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(publish.NOTEBOOK.parent)}}
    ).execute()
    shown = [
        (o["data"].get("text/latex"), o.get("metadata", {}).get("caption"))
        for c in notebook.cells
        for o in c.get("outputs", [])
        if o["output_type"] == "display_data"
    ]
    blocks = [(str(b), None) if isinstance(b, Latex) else (None, m["caption"]) for b, m in reports["example"].blocks()]
    built = re.compile(r"\d{4}-\d\d-\d\d \d\d:\d\d UTC")  # the build date, to the minute
    assert [(built.sub("", t or ""), c) for t, c in shown] == [(built.sub("", t or ""), c) for t, c in blocks]


@needs_tex
@pytest.mark.parametrize("name", ["example", "shaft-24", "shock-1.5"])
def test_the_signature_lines_are_on_the_front_page(pdfs, name):
    # The front page is what a reviewer signs: the verdict, the governing checks, the title block
    # with every file's SHA-256 and the signature lines below them, on one page.
    import subprocess

    pdf, _, _ = pdfs[name]
    first = subprocess.run(
        ["pdftotext", "-f", "1", "-l", "1", str(pdf), "-"], capture_output=True, text=True, check=True
    ).stdout
    assert "Title block" in first and "Approved by" in first
    assert "generated.csv" in first  # the last file listed (the path breaks in its column)


@needs_tex
def test_the_compiled_preamble_typesets_what_xelatex_alone_does(notebooks, pdfs, monkeypatch, tmp_path):
    import subprocess

    def text(path):
        return subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True, check=True).stdout

    pdf, log, _ = pdfs["example"]
    # The format drops the kernel's preloaded Latin Modern fonts (calc.report.publish.compiled_preamble):
    # a glyph set in one of them would be lost, and xelatex would say so.
    assert "preloaded format=report-" in log.splitlines()[0] and "Missing character" not in log
    monkeypatch.setattr(publish, "compiled_preamble", lambda tex: None)
    alone_log, _ = built_pdf(notebooks["example"], tmp_path / "alone.pdf")
    assert "preloaded format=xelatex" in alone_log.splitlines()[0]
    assert text(tmp_path / "alone.pdf") == text(pdf)


def test_a_preamble_without_its_end_mark_is_not_compiled(tmp_path):
    tex = tmp_path / "plain.tex"
    tex.write_text("\\documentclass{article}\n\\begin{document}x\\end{document}\n", encoding="utf-8")
    assert publish.compiled_preamble(tex) is None


@needs_tex
def test_a_preamble_that_cannot_be_compiled_is_tried_once(tmp_path, monkeypatch):
    import subprocess

    tex = tmp_path / "broken.tex"
    # A class no TeX has: xelatex cannot make the format, and says so in a marker beside it.
    tex.write_text(f"\\documentclass{{no-such-class}}\n{publish.END_OF_DUMP}\n\\begin{{document}}x\\end{{document}}\n",
                   encoding="utf-8")
    assert publish.compiled_preamble(tex) is None
    real = subprocess.run

    def no_xelatex(command, *args, **kwargs):
        assert command[0] != "xelatex", "a failed preamble is compiled again"
        return real(command, *args, **kwargs)

    monkeypatch.setattr(subprocess, "run", no_xelatex)
    assert publish.compiled_preamble(tex) is None


@needs_tex
def test_a_report_built_again_takes_one_pass_and_typesets_the_same(notebooks, pdfs, tmp_path):
    import subprocess

    def text(pdf):
        out = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
        return re.sub(r"Built .*UTC", "", out)

    # The example's first build (pdfs) kept the files of its last pass, from none.
    pdf, _, first = pdfs["example"]
    kept = pdf.parent / "kept" / "pass-example"
    assert first == 2 and kept.with_name("pass-example.aux").is_file()  # page X of Y: the second pass
    _, again = built_pdf(notebooks["example"], tmp_path / "example.pdf", kept)
    assert again == 1 and text(tmp_path / "example.pdf") == text(pdf)
    # The files kept from another report: its labels and last page have moved, xelatex says so and passes again,
    # and typesets what a build from no kept files (pdfs) does.
    _, other = built_pdf(notebooks["shaft-24"], tmp_path / "shaft-24.pdf", kept)
    assert other == 2 and text(tmp_path / "shaft-24.pdf") == text(pdfs["shaft-24"][0])


def test_kept_pass_files_unused_for_a_month_are_removed(tmp_path):
    import os
    import time

    old, recent = tmp_path / "pass-old.aux", tmp_path / "pass-recent.aux"
    for path in (old, recent, tmp_path / "report-x.fmt"):
        path.write_text("x", encoding="utf-8")
    month_ago = time.time() - publish.PASS_FILES_KEPT - 60
    os.utime(old, (month_ago, month_ago))
    os.utime(tmp_path / "report-x.fmt", (month_ago, month_ago))  # a compiled preamble is not a pass file
    publish._forget_old_passes(tmp_path)
    assert not old.exists() and recent.exists() and (tmp_path / "report-x.fmt").exists()


def test_a_figures_labels_are_parsed_once_and_its_pdf_is_matplotlibs(reports):
    """The report's figures share one mathtext parser (a label was parsed by each of the three
    renderers that save a PDF): the same bytes as matplotlib's own savefig, with fewer parses."""
    import base64
    import io

    from matplotlib.mathtext import MathTextParser
    from matplotlib.text import Text

    from calc.report import RENDERERS

    def undated(pdf: bytes) -> bytes:
        return re.sub(rb"/CreationDate \(.*?\)", b"", pdf)

    def misses(save) -> int:
        before = MathTextParser._parse_cached.cache_info().misses
        save()
        return MathTextParser._parse_cached.cache_info().misses - before

    figures = [figure for r in RENDERERS if r.NAME == "motor" for figure, _ in r.figures(reports["example"])]
    assert figures
    for figure in figures:
        own = io.BytesIO()
        own_parses = misses(lambda: figure.savefig(own, format="pdf"))
        shared = []
        shared_parses = misses(lambda: shared.append(publish.figure_pdf(figure)))
        assert undated(base64.b64decode(shared[0])) == undated(own.getvalue())
        labels = len({(t.get_text(), t.get_fontsize()) for t in figure.findobj(Text) if "$" in t.get_text()})
        assert labels and own_parses >= 2 * labels  # each renderer its own parse
        assert shared_parses <= labels  # once, or not at all where parsed for an earlier figure
