"""Measurement files: numpy's reader for short files (no pandas import), pandas' for long ones,
the same floats and the same errors from both."""

import numpy as np
import pytest

from calc import CalcError, measurement
from calc.hysteresis import COLUMNS, read_loop

BAD = [
    ("0,0\n1,abc\n", "row 4, column twist: expected a number, found 'abc'"),
    ("0,0\n,1\n", "row 4, column torque: expected a number, found an empty cell"),
    ("0,0\n\n1,1\n", "row 4, column torque: expected a number, found an empty cell"),
    ("0,0\n1\n", "row 4, column twist: expected a number, found an empty cell"),
    ("0,0\n1,1,2\n", "rows must have the header's 2 cells (row 4 has 3)"),
    ("0,0\n1,inf\n", "row 4, column twist: expected a number, found 'inf'"),
]


def _write(tmp_path, body):
    path = tmp_path / "loop.csv"
    path.write_text("# a loop\ntorque [N*m],twist [arcmin]\n" + body)
    return path


@pytest.mark.parametrize("reader_from", [measurement.PANDAS_FROM, 0])
@pytest.mark.parametrize("body, fragment", BAD)
def test_both_readers_name_the_same_bad_cell(tmp_path, monkeypatch, reader_from, body, fragment):
    monkeypatch.setattr(measurement, "PANDAS_FROM", reader_from)
    with pytest.raises(CalcError, match=fragment.replace("(", r"\(").replace(")", r"\)")):
        read_loop(_write(tmp_path, body))


def test_both_readers_give_the_same_floats(tmp_path, monkeypatch):
    rng = np.random.default_rng(3)
    rows = "\n".join(f"{a:.9g},{b:.17g}" for a, b in rng.normal(0, 50, (2000, 2))) + '\n"1.5", 2\n'
    path = _write(tmp_path, rows)
    numpy_read = measurement.read_measurement(path, COLUMNS)
    monkeypatch.setattr(measurement, "PANDAS_FROM", 0)
    pandas_read = measurement.read_measurement(path, COLUMNS)
    for c in COLUMNS:
        np.testing.assert_array_equal(numpy_read[c.name].magnitude, pandas_read[c.name].magnitude)
    assert numpy_read["torque"][-1].m_as("N*m") == 1.5

