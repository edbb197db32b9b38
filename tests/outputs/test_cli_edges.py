"""Edges a user meets at the command line: a byte-order mark, a folder given as the case, control
characters in the title, a measured record out of time order, and a reader that closes the pipe.
Each input error is one line on standard error naming the file and key, exit code 2, nothing on
standard output."""

import csv
import json
import os
import subprocess
import sys

import pytest

from ..conftest import DERIVED_EXAMPLE, EXAMPLE, HEAD_TOML, PROFILE_TOML, ROOT, run


def one_line_error(capsys, path, *fragments):
    code, out, err = run(capsys, path, "--json")
    assert (code, out) == (2, "")
    assert err.count("\n") == 1 and err.startswith("error: ")
    for fragment in fragments:
        assert fragment in err, err
    return err


def test_a_case_file_with_a_byte_order_mark_is_read(capsys, tmp_path):
    # Editors on Windows write UTF-8 with a BOM (EF BB BF); the same case without it gives the same results.
    text = HEAD_TOML + PROFILE_TOML
    plain, marked = tmp_path / "plain.toml", tmp_path / "marked.toml"
    plain.write_text(text, encoding="utf-8")
    marked.write_text(text, encoding="utf-8-sig")
    assert marked.read_bytes()[:3] == b"\xef\xbb\xbf"
    code, out, err = run(capsys, marked, "--json")
    assert (code, err) == (0, "")
    assert out.replace("marked.toml", "plain.toml").replace("marked", "plain") == run(capsys, plain, "--json")[1]


def test_a_folder_given_as_the_case(capsys, tmp_path):
    one_line_error(capsys, tmp_path, f"{tmp_path}: expected a case file, found a directory")


@pytest.mark.parametrize(
    "title, code_point", [("axis \\u001b[31m3", "U+001B"), ("axis\\n3", "U+000A"), ("axis \\u009b3", "U+009B")]
)
def test_control_characters_in_the_title_are_refused(capsys, write_case, title, code_point):
    # An escape sequence (ESC [31m turns a terminal red), a line break, a C1 control (CSI): none reaches the terminal.
    path = write_case(HEAD_TOML.replace('title = "test axis"', f'title = "{title}"') + PROFILE_TOML)
    err = one_line_error(
        capsys, path, f"{path}: title: expected one line of printable text, found the control character {code_point}"
    )
    assert "\x1b" not in err and "\x9b" not in err


LOOP = ROOT / "data" / "hysteresis-NPT035-10-generated.csv"
TRACE = ROOT / "data" / "transmission-NPT035-10-generated.csv"


def with_time_column(source, target, swap=None):
    """The record of ``source`` with a column ``time [ms]`` (0, 10, 20 ... ms), the data rows ``swap``
    exchanged with their times."""
    lines = source.read_text(encoding="utf-8").splitlines()
    header = next(k for k, line in enumerate(lines) if not line.startswith("#"))
    rows = [f"{row},{10 * k}" for k, row in enumerate(lines[header + 1:])]
    if swap:
        a, b = swap
        rows[a], rows[b] = rows[b], rows[a]
    target.write_text("\n".join(lines[:header] + [lines[header] + ",time [ms]"] + rows) + "\n", encoding="utf-8")
    return target


def accuracy_case(write_case, key, record, extra=""):
    return write_case(HEAD_TOML + PROFILE_TOML + f"""
[accuracy]
applied_torque = "20 N*m"
[[accuracy.component]]
name = "gearbox on the rig"
side = "output"
nominal_torque = "110 N*m"
{key} = "{record.name}"
{extra}""")


def test_a_loop_in_time_order_is_read(capsys, write_case, tmp_path):
    # The sample loop with increasing times gives the sample's figures: backlash 8 arcmin, its generator's, to 1 %.
    record = with_time_column(LOOP, tmp_path / "loop.csv")
    code, out, err = run(capsys, accuracy_case(write_case, "hysteresis", record), "--json")
    assert (code, err) == (0, "")
    loop = json.loads(out)["accuracy"]["components"][0]["measured_loop"]
    assert loop["backlash"]["value"] == pytest.approx(8, rel=0.01)


def test_a_loop_shuffled_in_time_names_the_file_row_and_column(capsys, write_case, tmp_path):
    # Data rows 100 and 400 exchanged (counting from 0): the times run 990, 4000, 1010 ms, so data row 101 is
    # the first that does not increase. Five comment lines and the header come first: it is line 7 + 101 = 108.
    record = with_time_column(LOOP, tmp_path / "loop.csv", swap=(100, 400))
    one_line_error(capsys, accuracy_case(write_case, "hysteresis", record),
                   f"{record}, row 108, column time: expected times that increase", "found 1010 ms after 4000 ms")


def test_a_trace_shuffled_in_time_names_the_file_row_and_column(capsys, write_case, tmp_path):
    # The transmission trace is read the same way. Data rows 5 and 6 exchanged: 60 ms, then 50 ms in data
    # row 6; three comment lines and the header come first: line 5 + 6 = 11.
    record = with_time_column(TRACE, tmp_path / "trace.csv", swap=(5, 6))
    one_line_error(
        capsys,
        accuracy_case(write_case, "transmission_trace", record, 'stiffness = "22 N*m/arcmin"\nbacklash = "8 arcmin"'),
        f"{record}, row 11, column time: expected times that increase",
        "found 50 ms after 60 ms",
    )


def test_evaluate_into_a_pipe_closed_early_exits_quietly():
    # `python -m calc evaluate case.toml | head -1`: the reader is gone before anything is written.
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    for args in ([], ["--json"]):
        proc = subprocess.Popen([sys.executable, "-m", "calc", "evaluate", str(EXAMPLE), *args],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd=ROOT)
        proc.stdout.close()
        err = proc.stderr.read().decode()
        proc.stderr.close()
        assert proc.wait() == 1 and err == ""


@pytest.mark.parametrize(
    "cells, message",
    [
        ({"C_t21 [N*m/arcmin]": "1e-320"}, "column C_t21: expected a magnitude between 1e-12 and 1e+12 in SI units"),
        (
            {"T_2N [N*m]": "1e-308", "T_2B [N*m]": "1e-308"},
            "column T_2N: expected a magnitude between 1e-12 and 1e+12 in SI units",
        ),
    ],
)
def test_a_hostile_catalog_gives_one_line_on_standard_error(tmp_path, cells, message):
    # The example's chosen row with numbers a float holds but a calculation cannot: before the
    # loader held cells to SI_SCALE, numpy's overflow and divide-by-zero warnings (7 to 9 lines)
    # reached standard error ahead of an error that named a result, not the cell.
    rows = list(csv.reader((ROOT / "catalogs" / "gearboxes.csv").open(encoding="utf-8")))
    header = rows[0]
    chosen = next(k for k, row in enumerate(rows) if row[0] == "NPT035-10")
    for column, value in cells.items():
        rows[chosen][header.index(column)] = value
    folder = tmp_path / "cases"
    folder.mkdir()
    (tmp_path / "data").symlink_to(ROOT / "data")
    with (folder / "hostile.csv").open("w", encoding="utf-8", newline="") as f:
        csv.writer(f, lineterminator="\n").writerows(rows)
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8")
    assert text.count('catalog = "gearboxes"\n') == 1
    case = folder / "case.toml"
    case.write_text(text.replace('catalog = "gearboxes"\n', 'catalog = "hostile.csv"\n'), encoding="utf-8")
    done = subprocess.run(
        [sys.executable, "-m", "calc", "evaluate", str(case), "--json"], capture_output=True, text=True, cwd=ROOT
    )
    assert (done.returncode, done.stdout) == (2, "")
    assert done.stderr.count("\n") == 1, done.stderr
    assert (
        done.stderr.startswith(f"error: {folder / 'hostile.csv'}, row {chosen + 1} (NPT035-10), ")
        and message in done.stderr
    )
