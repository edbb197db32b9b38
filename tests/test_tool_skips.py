"""A test that needs XeLaTeX, pandoc, poppler or Chromium is skipped where the tool is missing on a
local run, and fails under ``CALC_REQUIRE_TOOLS=1``, which ``.ci/run`` sets (tests/conftest.py)."""

import os
import subprocess
import sys

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


def run_needing_chromium(tmp_path, path: str, require: bool) -> subprocess.CompletedProcess:
    """pytest over one test marked as needing Chromium, with the tool hooks of tests/conftest.py."""
    tests = tmp_path / "t"
    tests.mkdir(exist_ok=True)
    (tests / "pytest.ini").write_text("[pytest]\n", encoding="utf-8")
    (tests / "conftest.py").write_text("from tests.conftest import pytest_runtest_setup, pytest_terminal_summary\n"
                                       "from tests.conftest import pytest_configure  # noqa: F401\n", encoding="utf-8")
    (tests / "test_browser.py").write_text("from tests.conftest import needs_tools\n\n\n"
                                           "@needs_tools('chromium')\ndef test_in_the_browser():\n    pass\n",
                                           encoding="utf-8")
    env = {**os.environ, "PATH": path, "PYTHONPATH": str(ROOT), "PYTEST_DISABLE_PLUGIN_AUTOLOAD": "1"}
    env.pop(REQUIRE_TOOLS, None)
    if require:
        env[REQUIRE_TOOLS] = "1"
    return subprocess.run([sys.executable, "-m", "pytest", str(tests), "-q", "-p", "no:cacheprovider", "-c",
                           str(tests / "pytest.ini")], cwd=tests, env=env, capture_output=True, text=True, timeout=300)


def test_a_missing_chromium_is_a_skip_locally_and_a_failure_under_ci(tmp_path):
    path = path_without(tmp_path, "chromium")
    local = run_needing_chromium(tmp_path, path, require=False)
    assert local.returncode == 0, local.stdout[-2000:]
    assert "skipped for want of a tool: chromium 1 tests" in local.stdout and "1 skipped" in local.stdout
    ci = run_needing_chromium(tmp_path, path, require=True)
    assert ci.returncode == 1, ci.stdout[-2000:]
    assert "needs chromium, not on PATH (make browser installs it); CALC_REQUIRE_TOOLS=1 refuses the skip" in ci.stdout
    assert "1 error" in ci.stdout.splitlines()[-1]



def test_the_ci_script_requires_the_tools():
    lines = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    assert f"export {REQUIRE_TOOLS}=1" in lines
    assert lines.index(f"export {REQUIRE_TOOLS}=1") < lines.index("make test")
