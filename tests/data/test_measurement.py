"""Measurement files: numpy's reader for short files (no pandas import), pandas' for long ones,
the same floats and the same errors from both."""

import numpy as np
import pytest

from calc import CalcError
from calc.data import measurement
from calc.domain.hysteresis import COLUMNS, read_loop

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



@pytest.mark.parametrize("text", [3, "", "  "])
def test_a_measurement_path_must_be_text(text):
    # TOML `hysteresis = 3` or `hysteresis = ""` names no file.
    with pytest.raises(CalcError) as err:
        measurement.measurement_path(text, None, "accuracy.component[1].hysteresis")
    assert str(err.value) == (
        f"accuracy.component[1].hysteresis: expected the path of a CSV file in quotes, found {text!r}"
    )


@pytest.mark.parametrize(
    "content, message",
    [
        (b"torque [N*m],twist [arcmin]\n0,\xff\n", ": expected a UTF-8 CSV file, found bytes that are not UTF-8"),
        (b"# only a comment\n\n", ": expected a header row such as 'torque [N*m],twist [arcmin]', found none"),
        (b"# a loop\ntorque (N*m),twist [arcmin]\n0,0\n",
         ", row 2: header column 1 'torque (N*m)' is not of the form 'name [unit]'"),
    ],
)
def test_unreadable_files_and_headers_name_the_file(tmp_path, content, message):
    path = tmp_path / "loop.csv"
    path.write_bytes(content)
    with pytest.raises(CalcError) as err:
        read_loop(path)
    assert str(err.value) == f"{path}{message}"


def test_a_folder_is_no_measurement_file(tmp_path):
    with pytest.raises(CalcError) as err:
        read_loop(tmp_path)
    assert str(err.value) == f"{tmp_path}: the measurement file cannot be read (Is a directory)"


def test_recorded_columns_must_be_two_arrays_of_one_length():
    from calc import Q_
    from calc.domain.hysteresis import Loop
    from calc.domain.transmission import Trace

    with pytest.raises(CalcError) as err:
        Loop(Q_([1, 2], "N*m"), Q_([1, 2, 3], "arcmin"), source="rig")
    assert str(err.value) == "rig: expected torque and twist as two arrays of one length, found shapes (2,) and (3,)"
    with pytest.raises(CalcError) as err:
        Trace(Q_([1, 2], "deg"), Q_([[1, 2]], "deg"), source="rig")
    assert str(err.value) == "rig: expected input and output as two arrays of one length, found shapes (2,) and (1, 2)"
