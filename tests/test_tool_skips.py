"""A test that needs XeLaTeX, pandoc, poppler or Chromium is skipped where the tool is missing on a
local run, and fails under ``CALC_REQUIRE_TOOLS=1``, which ``.ci/run`` sets (tests/conftest.py)."""

import os
import re
import subprocess
import sys

import pytest

from .conftest import REQUIRE_TOOLS, ROOT


def path_without(tmp_path, hidden: str) -> str:
    """A PATH of one folder that links every program of this PATH but ``hidden``."""
    farm = tmp_path / "bin"
    farm.mkdir()
    for folder in os.environ["PATH"].split(os.pathsep):
        if not os.path.isdir(folder):
            continue
        for entry in os.scandir(folder):
            target = farm / entry.name
            if not entry.name.startswith(hidden) and not target.exists() and not target.is_symlink():
                target.symlink_to(entry.path)
    return str(farm)


def run_needing_chromium(tmp_path, path: str, require: bool, workers: int = 0) -> subprocess.CompletedProcess:
    """pytest over two tests marked as needing Chromium, with the tool hooks of tests/conftest.py; on
    ``workers`` processes of pytest-xdist as ``make test`` runs them (0: in this one)."""
    tests = tmp_path / "t"
    tests.mkdir(exist_ok=True)
    (tests / "pytest.ini").write_text("[pytest]\n", encoding="utf-8")
    (tests / "conftest.py").write_text("from tests.conftest import pytest_runtest_setup, pytest_terminal_summary\n"
                                       "from tests.conftest import pytest_sessionfinish, pytest_testnodedown\n"
                                       "from tests.conftest import pytest_configure  # noqa: F401\n", encoding="utf-8")
    (tests / "test_browser.py").write_text("import pytest\n\nfrom tests.conftest import needs_tools\n\n\n"
                                           "@needs_tools('chromium')\n@pytest.mark.parametrize('page', [1, 2])\n"
                                           "def test_in_the_browser(page):\n    pass\n", encoding="utf-8")
    env = {**os.environ, "PATH": path, "PYTHONPATH": str(ROOT), "PYTEST_DISABLE_PLUGIN_AUTOLOAD": "1"}
    env.pop(REQUIRE_TOOLS, None)
    if require:
        env[REQUIRE_TOOLS] = "1"
    parallel = ["-p", "xdist.plugin", "-n", str(workers)] if workers else []
    return subprocess.run([sys.executable, "-m", "pytest", str(tests), "-q", "-p", "no:cacheprovider", *parallel, "-c",
                           str(tests / "pytest.ini")], cwd=tests, env=env, capture_output=True, text=True, timeout=300)


@pytest.fixture(scope="module")
def no_chromium(tmp_path_factory) -> str:
    """This PATH with Chromium hidden."""
    return path_without(tmp_path_factory.mktemp("path"), "chromium")


@pytest.mark.parametrize("workers", [0, 2], ids=["one process", "two workers"])
def test_a_missing_chromium_is_a_skip_locally_and_a_failure_under_ci(tmp_path, no_chromium, workers):
    # With two workers each skip is counted where it happens and summed by the controller (tests/conftest.py).
    path = no_chromium
    local = run_needing_chromium(tmp_path, path, require=False, workers=workers)
    assert local.returncode == 0, local.stdout[-2000:]
    assert "skipped for want of a tool: chromium 2 tests" in local.stdout and "2 skipped" in local.stdout
    ci = run_needing_chromium(tmp_path, path, require=True, workers=workers)
    assert ci.returncode == 1, ci.stdout[-2000:]
    assert "needs chromium, not on PATH (make browser installs it); CALC_REQUIRE_TOOLS=1 refuses the skip" in ci.stdout
    assert "2 errors" in ci.stdout.splitlines()[-1]



def test_the_ci_script_requires_the_tools():
    lines = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    assert f"export {REQUIRE_TOOLS}=1" in lines
    assert lines.index(f"export {REQUIRE_TOOLS}=1") < lines.index("make test")


#: The files that may skip a test by their own call, and why none of them is for want of a tool.
OWN_SKIPS = {"conftest.py": "needs_tools itself", "test_error_sites.py": "a check of the whole tests/ folder, when "
             "only part of it is selected", "test_tool_skips.py": "this test, which names the calls"}


def test_a_tool_is_required_only_through_needs_tools():
    # A test that skips itself where a tool is missing (skipif, pytest.skip, importorskip) would let a CI
    # machine without the tool pass: needs_tools is the one way, which CALC_REQUIRE_TOOLS=1 turns into a failure.
    own = re.compile(r"\bskipif\(|\bpytest\.skip\(|\bimportorskip\(")
    found = [f"{path.relative_to(ROOT)}:{number}" for path in sorted((ROOT / "tests").rglob("*.py"))
             if path.name not in OWN_SKIPS
             for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1) if own.search(line)]
    assert found == [], "a skip of its own (use tests/conftest.py's needs_tools): " + ", ".join(found)
