"""The package as a user installs it: catalogs, report notebook and template are package data.

Each test builds from a copy of the project's packaging inputs (so no build/ or egg-info lands in
the tree), offline (``--no-index``, ``--no-build-isolation``: the installed setuptools builds) and
without dependencies (``--no-deps``: those of the running interpreter are used). The children run
without PYTHONPATH pointing at this checkout, so they import the installed copy.
"""

import json
import os
import shutil
import site
import subprocess
import sys
from pathlib import Path

import pytest

from calc.sections.case import read_case
from calc.sections import evaluate

from .conftest import DERIVED_EXAMPLE as EXAMPLE, ROOT  # the example case as shipped

PIP = [
    "-m",
    "pip",
    "install",
    "--quiet",
    "--disable-pip-version-check",
    "--no-index",
    "--no-deps",
    "--no-build-isolation",
]


@pytest.fixture
def source(tmp_path):
    """A copy of what the build reads, with a generated report PDF in reports/ (not package data)."""
    src = tmp_path / "src"
    src.mkdir()
    for name in ("pyproject.toml", "README.md", "LICENSE"):
        shutil.copy(ROOT / name, src / name)
    for name in ("calc", "catalogs", "reports", "LICENSES"):
        shutil.copytree(ROOT / name, src / name, ignore=shutil.ignore_patterns("__pycache__", "*.pdf", "*.txt"))
    (src / "reports" / "indexing-table.pdf").write_bytes(b"%PDF-1.5 generated report\n")
    return src


def child_env(**extra) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    return env | extra


def run(args, **kw) -> str:
    done = subprocess.run(args, capture_output=True, text=True, **kw)
    assert done.returncode == 0, done.stderr
    return done.stdout


# Where the installed calc finds its package data, printed by the child as JSON.
WHERE = """
import importlib.resources as r, json, calc
from calc.data.catalog import CATALOG_DIR, PROJECT_DIR, display_path
from calc.report.publish import NOTEBOOK, TEMPLATE_DIRS
from calc.report import git_commit
print(json.dumps({
    "calc": calc.__file__,
    "catalogs": str(r.files("calc.catalogs")),
    "reports": str(r.files("calc.reports")),
    "catalog_dir": str(CATALOG_DIR),
    "project": PROJECT_DIR and str(PROJECT_DIR),
    "shown": display_path(CATALOG_DIR / "gearboxes.csv"),
    "notebook": str(NOTEBOOK),
    "template": TEMPLATE_DIRS[0],
    "commit": git_commit(),
}))
"""


def test_pip_install_runs_the_example_case_from_package_data(source, tmp_path):
    target = tmp_path / "site"
    run([sys.executable, *PIP, "--target", str(target), str(source)], env=child_env())
    installed = target / "calc"
    assert sorted(p.name for p in (installed / "catalogs").glob("*.csv")) == [
        "couplings.csv",
        "drives.csv",
        "gearbox-hubs.csv",
        "gearboxes.csv",
        "motors.csv",
    ]
    assert not list(installed.rglob("*.pdf"))  # generated reports stay out of the package
    # The licences travel with it: MIT for the code, CC BY 4.0 for the catalogs' compilation (LICENSE).
    (info,) = target.glob("drivetrain_calc-*.dist-info")
    assert "License-Expression: MIT AND CC-BY-4.0" in (info / "METADATA").read_text().splitlines()
    assert (info / "licenses" / "LICENSE").is_file() and (info / "licenses" / "LICENSES" / "CC-BY-4.0.md").is_file()

    # The example case and the measurement it names (../data/...) in a folder of their own.
    work = tmp_path / "work"
    (work / "cases").mkdir(parents=True)
    (work / "data").mkdir()
    shutil.copy(EXAMPLE, work / "cases")
    shutil.copy(ROOT / "data" / "transmission-NPT035-10-generated.csv", work / "data")
    env = child_env(PYTHONPATH=str(target))

    where = json.loads(run([sys.executable, "-c", WHERE], cwd=work, env=env))
    assert Path(where["calc"]) == installed / "__init__.py"
    assert Path(where["catalogs"]) == Path(where["catalog_dir"]) == installed / "catalogs"
    assert where["project"] is None and where["shown"] == "catalogs/gearboxes.csv"
    assert Path(where["notebook"]) == installed / "reports" / "calc-report.ipynb"
    assert Path(where["notebook"]).is_file()
    assert (Path(where["template"]) / "calc-report" / "index.tex.j2").is_file()
    assert (Path(where["template"]) / "calc-report" / "conf.json").is_file()
    assert where["commit"] == "none: an installed package, not a git checkout"

    out = run([sys.executable, "-m", "calc", "evaluate", "cases/indexing-table.toml", "--json"], cwd=work, env=env)
    results = json.loads(out)
    # NPT035-10 is the only ratio-10 gearbox that passes T_2B (hand calculation in test_gearbox.py).
    assert results["gearbox"]["selected"] == "NPT035-10"
    assert results["gearbox"]["catalog"] == "catalogs/gearboxes.csv"
    assert results["coupling"]["catalog"] == "catalogs/couplings.csv"
    # The user's files, outside any checkout, show absolute; else the installed copy gives the checkout's results.
    assert results["case"] == str(work.resolve() / "cases" / "indexing-table.toml")
    assert json.loads(out.replace(f"{work.resolve()}/", "")) == json.loads(
        json.dumps(evaluate(read_case(EXAMPLE)).to_json())
    )


def test_editable_install_maps_the_top_level_folders(source, tmp_path):
    # A venv that sees this interpreter's packages (pip, setuptools, the dependencies), not this checkout.
    venv = tmp_path / "venv"
    run([sys.executable, "-m", "venv", "--without-pip", str(venv)])
    python = venv / "bin" / "python"
    venv_site = Path(run([str(python), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"]).strip())
    (venv_site / "dependencies.pth").write_text("\n".join(site.getsitepackages()) + "\n")
    run([str(python), *PIP, "--editable", str(source)], env=child_env())

    where = json.loads(run([str(python), "-c", WHERE], cwd=tmp_path, env=child_env()))
    assert Path(where["calc"]) == source / "calc" / "__init__.py"
    assert Path(where["catalogs"]) == Path(where["catalog_dir"]) == source / "catalogs"
    assert Path(where["reports"]) == source / "reports" == Path(where["notebook"]).parent
    assert where["project"] == str(source) and where["shown"] == "catalogs/gearboxes.csv"
    assert where["commit"] == "not under version control"  # the copy is no git tree
