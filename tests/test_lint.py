"""The code passes ruff as pyproject.toml configures it (``[tool.ruff]``): pyflakes (unused imports
and names, undefined names) everywhere, and lines of at most 120 characters outside the folders
pyproject still lists as exceptions."""

import subprocess
import sys

from .conftest import ROOT

#: What ruff checks, from the project's top level.
CHECKED = ("calc", "tests", "bench", "book")


def test_ruff_finds_nothing():
    run = subprocess.run([sys.executable, "-m", "ruff", "check", "--no-cache", *CHECKED],
                         cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, f"ruff check {' '.join(CHECKED)}:\n{run.stdout}{run.stderr}"
