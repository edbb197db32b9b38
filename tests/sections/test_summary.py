"""``python -m calc report CASES --summary``: one row per case in summary.csv and summary.pdf.

The cases: the example (PASS), the example's axis with a 30 N·m motor (FAIL: T_2max = 30 N·m · 10 ·
1.3 · 0.97 = 378.3 N·m, above every T_2B at ratio 10, at most 220 N·m, as in tests/outputs/test_report.py),
the same at ratio 13 (no gearbox of the catalog has it: the case cannot be evaluated) and without
the motor's peak torque (NOT DECIDED: T_2max <= T_2B cannot be checked). Each row is checked
against the results of ``python -m calc evaluate --json`` of its case.
"""

import csv
import json
import re
import subprocess
import zlib

import pytest

from calc.data.catalog import display_path
from calc.report.publish import render_summary, summary_rows
from calc.report import build_report
from calc import Q_
from calc.core.checks import Check
from calc.report.summary import CSV_COLUMNS, worst_check, write_csv
from calc.sections.common import Governing

from ..conftest import EXAMPLE, HEAD_TOML, PROFILE_TOML, REPORT_CASES, run
from ..outputs.test_report import needs_tex, pdf_text, report_here

FAILING, UNREADABLE = REPORT_CASES["failing"], REPORT_CASES["unreadable"]
NOT_DECIDED = HEAD_TOML.replace('peak_torque = "12 N*m"\n', "") + PROFILE_TOML
LONG_TITLE = "Gantry Z axis with counterweight, left-hand portal of the second press line, " * 3


def write_cases(folder, **texts):
    """Case files named by the keywords; their paths in that order."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, text in texts.items():
        (folder / f"{name}.toml").write_text(text, encoding="utf-8")
        paths.append(folder / f"{name}.toml")
    return paths


def expected_worst(results: dict):
    """The worst governing utilization written out from the JSON, with its criterion and where it
    is: the first candidate's checks of gearbox and coupling (chosen, or closest when none passes)
    and accuracy's own checks."""
    found = []
    for name in ("gearbox", "coupling", "accuracy"):
        s = results.get(name)
        if s is None:
            continue
        checks = s["candidates"][0]["checks"] if s.get("candidates") else s.get("checks", [])
        where = f"{name} {s['candidates'][0]['part']}" if s.get("candidates") else name
        found += [(k["utilization"], k["criterion"], where) for k in checks
                  if k.get("governs", True) and k["utilization"] is not None]
    return max(found) if found else None


def evaluated(capsys, case):
    """``python -m calc evaluate CASE --json``: its results, or its error line."""
    code, out, err = run(capsys, case, "--json")
    return (json.loads(out), None) if code == 0 else (None, err.strip().removeprefix("error: "))


def read_csv(path):
    with path.open(newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def check_row_against_json(capsys, row: dict, case):
    """A CSV row (text cells) says what ``evaluate --json`` of its case says."""
    results, error = evaluated(capsys, case)
    assert row["case file"] == (results["case"] if results else display_path(case))
    if results is None:
        assert row["verdict"] == "FAIL"
        assert row["reason"] == f"The case cannot be evaluated: {error}"
        assert row["gearbox"] == row["coupling"] == row["worst utilization [1]"] == ""
        return
    assert row["title"] == results["title"]
    assert row["verdict"] == {True: "PASS", False: "FAIL", None: "NOT DECIDED"}[results["verdict"]["passes"]]
    assert row["reason"] == (results["verdict"]["reasons"][0] if results["verdict"]["reasons"] else "")
    for name in ("gearbox", "coupling"):
        if name in results:
            assert row[name] == (results[name]["selected"] or "none passes")
        else:
            assert row[name] == ""
    utilization, criterion, where = expected_worst(results)
    assert float(row["worst utilization [1]"]) == utilization  # a fraction, written in full
    assert row["worst check"] == criterion
    assert row["worst check in"] == where


# -- without TeX ------------------------------------------------------------------------------


def test_worst_check_takes_governing_checks_with_a_utilization():
    # Hand-built governing checks: a check not made has no utilization; accuracy's own checks
    # count; the closest gearbox counts where none is chosen.
    def check(name, criterion, utilization):
        return Check(name, criterion, Q_(1.0, "N*m"), Q_(1.0, "N*m"), "N*m", utilization,
                     utilization is not None and utilization <= 1)

    class Evaluated:
        def __init__(self, *governing):
            self.governing = lambda: list(governing)

    gearbox = Governing("gearbox", "A", False, [check("T_2B", "T_2max <= T_2B", 0.5)])
    motor = Governing("motor", None, True, [check("rms", "rms <= rated", None)])
    accuracy = Governing("accuracy", None, True,
                         [check("positioning_accuracy", "positioning_accuracy <= required", 0.7)])
    assert worst_check(Evaluated(gearbox, motor, accuracy)) == {
        "utilization": 0.7, "check": "positioning_accuracy <= required", "section": "accuracy", "part": None,
        "passes": True}
    lower = Governing("accuracy", None, True, [check("positioning_accuracy", "positioning_accuracy <= required", 0.3)])
    assert worst_check(Evaluated(gearbox, motor, lower)) == {
        "utilization": 0.5, "check": "T_2max <= T_2B", "section": "gearbox", "part": "A", "passes": True}
    assert worst_check(Evaluated()) is None
    assert worst_check(Evaluated(motor)) is None


def test_summary_rows_are_plain_data_one_per_case(capsys, tmp_path):
    cases = write_cases(tmp_path, failing=FAILING, unreadable=UNREADABLE, undecided=NOT_DECIDED)
    rows = summary_rows([EXAMPLE, *cases], str(tmp_path / "out"))
    assert [r["verdict"] for r in rows] == ["PASS", "FAIL", "FAIL", "NOT DECIDED"]
    example, failing, unreadable, undecided = rows
    # The example: NPT035-10 and AKD-30; its worst check is the drive train's first mode against
    # 2 f_er, 200 Hz / 207.96 Hz = 0.962 (tests/domain/test_torsion.py), above T_2max / T_2B = 151.32 / 220 = 0.688.
    assert example["chosen"] == {"gearbox": "NPT035-10", "coupling": "AKD-30"}
    assert example["worst"]["check"] == "2 f_er <= f_1" and example["worst"]["part"] == "AKD-30"
    assert example["worst"]["utilization"] == pytest.approx(200 / 207.963, rel=1e-5)
    assert example["report"] == "indexing-table-profile.pdf"
    assert example["report_path"] == str(tmp_path / "out" / "indexing-table-profile.pdf")
    assert example["error"] is None and example["reason"] is None
    # Failing: no gearbox passes; its worst check is over 1 (4940 / 4000 = 1.235 for TP500-10, η 0.95).
    assert failing["chosen"] == {"gearbox": None} and failing["worst"]["utilization"] > 1
    assert unreadable["error"].endswith("has ratio 13; its ratios are 3, 4, 5, 7, 8, 10")
    assert unreadable["reason"] == f"The case cannot be evaluated: {unreadable['error']}"
    assert unreadable["chosen"] == {} and unreadable["worst"] is None
    assert undecided["passes"] is None and "motor.peak_torque" in undecided["reason"]
    json.dumps(rows)  # plain data
    # The same rows as `evaluate --json` says, through the CSV.
    write_csv(rows, tmp_path / "summary.csv")
    lines = read_csv(tmp_path / "summary.csv")
    assert tuple(lines[0]) == CSV_COLUMNS
    for row, case in zip(lines, [EXAMPLE, *cases]):
        check_row_against_json(capsys, row, case)


def test_summary_needs_a_folder(capsys, tmp_path):
    code, err = report_here(capsys, EXAMPLE, "--summary", "-o", tmp_path / "all.pdf")
    assert code == 2
    assert err.strip() == (f"error: -o {tmp_path / 'all.pdf'}: with --summary, expected a folder for the reports "
                           "and summary.pdf, found a file name")
    assert list(tmp_path.iterdir()) == []


def test_a_case_named_summary_would_lose_its_report(capsys, tmp_path):
    (case,) = write_cases(tmp_path / "cases", summary=FAILING)
    code, err = report_here(capsys, EXAMPLE, case, "--summary", "-o", tmp_path / "out")
    assert code == 2
    assert err.strip() == (f"error: {case}: its report {tmp_path / 'out' / 'summary.pdf'} would be overwritten "
                           "by the summary; rename the case file")
    assert not (tmp_path / "out").exists()


# -- the PDFs ---------------------------------------------------------------------------------


def links(pdf) -> list[str]:
    """The files a PDF's links open (GoToR actions), from its (compressed) object streams."""
    data = pdf.read_bytes()
    out = []
    for m in re.finditer(rb"stream\r?\n(.*?)endstream", data, re.S):
        try:
            text = zlib.decompress(m.group(1))
        except zlib.error:
            continue
        out += [f.decode() for f in re.findall(rb"/S\s*/GoToR\s*/F\s*\(([^)]*)\)", text)]
    return out


@needs_tex
def test_summary_of_four_cases(capsys, report_run):
    cases, out, proc = report_run
    # A case that cannot be read exits 2 (spec, "Exit status"); every report and the summary are written.
    assert proc.returncode == 2, proc.stderr
    assert proc.stdout.strip().splitlines()[-1] == (f"2 PASS, 2 FAIL, 0 NOT DECIDED  ->  {out / 'summary.pdf'}  "
                                                    f"{out / 'summary.csv'}")
    rows = read_csv(out / "summary.csv")
    assert [r["report"] for r in rows] == ["indexing-table-profile.pdf", "escape.pdf", "failing.pdf", "unreadable.pdf"]
    for row, case in zip(rows, cases):
        check_row_against_json(capsys, row, case)

    text = pdf_text(out / "summary.pdf")
    assert "Design review summary" in text and "2 PASS, 2 FAIL, 0 NOT DECIDED" in text
    assert "1 of the FAIL: the case cannot be evaluated" in text
    flat = " ".join(text.split())
    for title, verdict in (("Rotary indexing table, axis 3", "PASS"), ("test axis", "FAIL")):
        assert re.search(rf"{re.escape(title)}\s+{verdict}", text), title
    assert re.search(r"Rotary indexing table, axis 3\s+PASS\s+NPT035-10\s+AKD-30\s+0\.96", text)
    # 400 · 10 · 1.3 · 0.95 = 4940 N·m / 4000 (TP500-10, the closest)
    assert re.search(r"test axis\s+FAIL\s+none\s+–\s+1\.24", text)
    assert "has ratio 13" in flat
    # Title block: each data file the cases rest on (case files, catalogs, tables, measurements)
    # once, with its SHA-256.
    files = {(path, digest) for case in cases for _, path, digest in build_report(case).files}
    assert all(digest in text for _, digest in files)
    assert text.count("catalogs/gearboxes.csv\n") >= 1
    assert len(re.findall(r"SHA-256\s+[0-9a-f]{64}", text)) == len(files)
    # Each report's file name links to it, relative to the summary.
    assert set(links(out / "summary.pdf")) == {"indexing-table-profile.pdf", "escape.pdf", "failing.pdf",
                                               "unreadable.pdf"}


@needs_tex
def test_many_rows_break_across_pages_with_the_header_repeated(tmp_path):
    # 40 cases, one with a title over three lines; no case reports are built, only the summary.
    texts = {f"axis-{k:02d}": (FAILING if k % 3 else HEAD_TOML + PROFILE_TOML).replace('"test axis"', f'"axis {k}"')
             for k in range(40)}
    texts["axis-07"] = texts["axis-07"].replace('"axis 7"', json.dumps(LONG_TITLE))
    cases = write_cases(tmp_path / "cases", **texts)
    rows = summary_rows(cases, str(tmp_path))
    pdf, table = render_summary(rows, [build_report(c).files for c in cases], tmp_path)
    pages = pdf_text(pdf).split("\f")
    with_rows = [p for p in pages if re.search(r"^\s*axis \d+\s+(PASS|FAIL)", p, re.M)]
    assert len(with_rows) >= 2
    assert all(re.search(r"Case\s+Verdict\s+Gearbox\s+Coupling\s+Worst", p) for p in with_rows)
    flat = " ".join(pdf_text(pdf).split())
    assert all(f"axis {k} " in flat for k in range(40) if k != 7)
    # The long title wraps inside its column (A4, 2 cm margins: the case column is the first 0.29 of 17 cm).
    first_column = subprocess.run(["pdftotext", "-x", "50", "-y", "0", "-W", "150", "-H", "842", str(pdf), "-"],
                                  capture_output=True, text=True, check=True).stdout
    assert LONG_TITLE.strip() in " ".join(first_column.split())
    assert "14 PASS, 26 FAIL, 0 NOT DECIDED" in flat
    assert len(read_csv(table)) == 40
    # The cases lie outside the project: the summary shows them from its own folder, never where
    # on this machine they are.
    assert str(tmp_path) not in pdf_text(pdf) and "cases/axis-00.toml" in "".join(pdf_text(pdf).split())
