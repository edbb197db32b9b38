"""A new section is its section module and its renderer, nothing else: the holding brake of
docs/adding-a-section.md, written as the document gives it into a copy of the package, shows with
its values in the JSON, the text summary, the calc report's LaTeX, the review's page, the summary
of cases and ``calc compare``.

The brake holds 80 N·m; the typed example's load cycle (tests/conftest.py) peaks at 60 N·m in its
acceleration, so the check |T_2k| <= T_br is made at 60 / 80 = 0.75 and passes; at 40 N·m it is
60 / 40 = 1.5, 50 % over.
"""

import json
import re
import shutil
import subprocess
import sys

import pytest

from ..conftest import PROFILE_TOML, ROOT

DOC = ROOT / "docs" / "adding-a-section.md"
FILES = ("calc/sections/brake.py", "calc/report/brake.py")
BRAKE = 'title = "{title}"\n' + PROFILE_TOML + '\n[brake]\npart = "BR-10"\nholding_torque = "{torque}"\n'

#: Run in the copy: the report's LaTeX blocks (figures left out), the review's page, the summary's row.
OUTPUTS = """
import json, sys
from calc.report import report_of
from calc.report.summary import CSV_COLUMNS, summary_row
from calc.review.view import results_html
from calc.sections import read_case

report = report_of(read_case(sys.argv[1]))
latex = "\\n".join(str(block) for block, _ in report.blocks(figures=lambda: []))
print(json.dumps({"latex": latex, "html": results_html(report, []), "row": summary_row(report, None),
                  "columns": CSV_COLUMNS}))
"""


def example_files() -> dict:
    """The two files of the example, as the document gives them (the code block under each
    file's heading)."""
    text = DOC.read_text(encoding="utf-8")
    blocks = {name: re.search(rf"^### {re.escape(name)}\n\n```python\n(.*?)^```", text, re.S | re.M) for name in FILES}
    return {name: block.group(1) for name, block in blocks.items()}


@pytest.fixture(scope="module")
def package(tmp_path_factory):
    """A copy of the project's package with the brake's two files added, beside the project's
    data; and two cases with a brake, of 80 and of 40 N·m."""
    root = tmp_path_factory.mktemp("project")
    shutil.copytree(ROOT / "calc", root / "calc", ignore=shutil.ignore_patterns("__pycache__"))
    for shared in ("pyproject.toml", "catalogs", "data"):
        (root / shared).symlink_to(ROOT / shared)
    for name, code in example_files().items():
        assert not (root / name).exists()
        (root / name).write_text(code, encoding="utf-8")
    (root / "holds.toml").write_text(BRAKE.format(title="brake that holds", torque="80 N*m"), encoding="utf-8")
    (root / "slips.toml").write_text(BRAKE.format(title="brake that slips", torque="40 N*m"), encoding="utf-8")
    return root


def run(package, *args) -> str:
    proc = subprocess.run([sys.executable, *args], capture_output=True, text=True, cwd=package,
                          env={"PYTHONPATH": str(package)}, check=False)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def test_the_copy_differs_from_the_package_by_the_two_files_only(package):
    copied = {p.relative_to(package).as_posix() for p in (package / "calc").rglob("*.py")}
    original = {p.relative_to(ROOT).as_posix() for p in (ROOT / "calc").rglob("*.py")}
    assert copied - original == set(FILES) and original <= copied


def test_the_brake_is_in_the_json_and_the_text_summary(package):
    r = json.loads(run(package, "-m", "calc", "evaluate", "holds.toml", "--json"))
    check = r["brake"]["check"]
    assert r["brake"]["part"] == "BR-10" and check["criterion"] == "|T_2k| <= T_br"
    assert check["required"] == {"value": 60.0, "unit": "N*m"} and check["rated"] == {"value": 80.0, "unit": "N*m"}
    assert check["utilization"] == pytest.approx(0.75) and check["passes"] is True
    assert r["verdict"] == {"passes": True, "reasons": []}  # the brake is the case's only check
    text = run(package, "-m", "calc", "evaluate", "slips.toml")
    assert "Verdict: FAIL" in text
    assert "Brake BR-10: |T_2k| <= T_br: required 60 N·m > rated 40 N·m, 50 % over" in text
    assert "\nBrake BR-10:\n" in text and "utilization  1.50  FAIL" in text


def test_the_brake_is_in_the_report_the_page_and_the_summary(package):
    out = json.loads(run(package, "-c", OUTPUTS, "holds.toml"))
    latex, html, row = out["latex"], out["html"], out["row"]
    assert "Checks of brake BR-10" in latex and r"\textbf{Brake BR-10}" in latex  # the checks' table, the front page
    inputs = latex[latex.index(r"\section{Inputs}"):]
    assert "brake.holding" in inputs and "80" in inputs
    assert "<h3>Brake BR-10</h3>" in html and "holding torque 80 N·m against 60 N·m: 75 %" in html
    assert "brake BR-10" in html  # among the governing checks
    worst = {"utilization": pytest.approx(0.75), "check": "|T_2k| <= T_br", "section": "brake", "part": "BR-10",
             "passes": True}
    assert row["worst"] == worst
    assert "brake" not in out["columns"]  # it asks for no column of its own


def test_the_brake_is_compared(package):
    text = run(package, "-m", "calc", "compare", "holds.toml", "slips.toml")
    line = next(x for x in text.splitlines() if x.startswith("brake holding torque"))
    assert line.split()[3:] == ["80", "N·m", "40", "N·m", "*"]
    assert next(x for x in text.splitlines() if x.startswith("verdict")).split()[1:] == ["PASS", "FAIL", "*"]
