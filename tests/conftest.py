"""Shared fixtures: the example case, and writers for case and catalog files in a temporary folder."""

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "cases" / "indexing-table.toml"
GEARBOXES = ROOT / "catalogs" / "gearboxes.csv"

# The example's load cycle, in the case-file format (used to build variants in tests).
PROFILE_TOML = """
[[profile]]
phase = "accel"
duration = "0.2 s"
speed = "150 rpm"
torque = "60 N*m"
[[profile]]
phase = "const"
duration = "0.6 s"
speed = "300 rpm"
torque = "20 N*m"
[[profile]]
phase = "decel"
duration = "0.2 s"
speed = "150 rpm"
torque = "-45 N*m"
[[profile]]
phase = "pause"
duration = "1.0 s"
"""

HEAD_TOML = """
title = "test axis"
[motor]
peak_torque = "12 N*m"
inertia = "4.2 kg*cm**2"
[load]
inertia = "1500 kg*cm**2"
[gearbox]
ratio = 10
"""


def run(capsys, *args):
    """``python -m calc evaluate ARGS`` in this process: exit code, standard output, standard error."""
    from calc.__main__ import main

    code = main(["evaluate", *map(str, args)])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def write_case(tmp_path):
    """Write a case file from TOML text; returns its path."""

    def write(text: str, name: str = "case.toml") -> Path:
        path = tmp_path / name
        path.write_text(text)
        return path

    return write
