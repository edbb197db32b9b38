"""Measured data as a test rig records it: a CSV file of numeric columns, units in the header.

A measurement file opens with any number of comment lines (``#`` ...) that say where the data
come from, then a header row such as ``torque [N*m],twist [arcmin]``, then one row per sample.
Each column's unit is read from its header and checked for its kind (errata E15: a twist column
in ``[1]`` or a torque column in ``[N*m/arcmin]`` is refused). Every problem is reported with the
file, the row (its line number in the file) and the column. Further columns (a channel the
calculation does not use) are allowed and left out; a ``time [unit]`` column, if there is one,
must increase from row to row (:data:`TIME`).

A clean table is read by a C parser: numpy's (``np.loadtxt``) for a file up to
:data:`PANDAS_FROM` characters, pandas' (three times faster, a million rows in a seventh of a
second) for a larger one, where it repays its import (a quarter of a second, which evaluating a
case with a short record does not pay). Both round each number correctly, so they give the same
floats. A file that is not a clean table is read again cell by cell, to name the first bad row
and column.
"""

from __future__ import annotations

import io
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .catalog import _HEADER, Column, _header_unit, note_file_read
from ..core.errors import CalcError, as_found, listing
from ..core.units import Q_, as_kind

_COMMENT = "#"

#: An optional column of sample times. Where a record has one, the times must increase: a loop's
#: loading direction and a trace's travel are read from the order of the rows, and a record sorted
#: or merged out of time order would be analysed wrongly without a word.
TIME = Column("time", "time", "time of the sample")


@dataclass(frozen=True)
class Measurement:
    """The columns of a measurement file as quantity arrays, with its comment lines.

    Parameters
    ----------
    path : pathlib.Path
        The file.
    columns : dict
        Each column by name, a quantity array in the file's unit.
    comments : tuple of str
        The file's comment lines, without their ``#``.
    """

    path: Path
    columns: dict
    comments: tuple[str, ...]

    def __getitem__(self, name: str):
        return self.columns[name]


def measurement_path(text, base: Path | None, where: str) -> Path:
    """The file a case names (relative to the case file's folder); an error if it is missing.

    Parameters
    ----------
    text : str
        The path as the case writes it.
    base : pathlib.Path or None
        The case file's folder.
    where : str
        The key, for error messages.

    Returns
    -------
    pathlib.Path
        The file.
    """
    if not isinstance(text, str) or not text.strip():
        raise CalcError(f"{where}: expected the path of a CSV file in quotes, found {as_found(text)}")
    path = Path(text)
    if not path.is_absolute() and base is not None:
        path = base / path
    if not path.is_file():
        looked = str(path.resolve())
        looked = looked if len(looked) <= 60 else "…" + looked[-59:]  # the file's end says most
        raise CalcError(f"{where}: the measurement file {as_found(text)} does not exist (looked for {looked})")
    return path


def read_measurement(path, columns: tuple[Column, ...], optional: tuple[Column, ...] = ()) -> Measurement:
    """Read a measurement file and check it against ``columns`` and those of ``optional`` that its
    header has.

    Cells may hold any sign (a twist, an error).

    Parameters
    ----------
    path : pathlib.Path or str
        The CSV file.
    columns : tuple of Column
        The columns it must have (name, kind, description).
    optional : tuple of Column
        Columns it may have.

    Returns
    -------
    Measurement
        Its columns and comment lines.

    Raises
    ------
    CalcError
        Naming the file, row and column for: a missing column, a header unit of the wrong kind, an
        empty or non-numeric cell, a value that is not finite, or a row with too few cells.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise CalcError(f"{path}: expected a UTF-8 CSV file, found bytes that are not UTF-8") from None
    except OSError as exc:
        raise CalcError(f"{path}: the measurement file cannot be read ({exc.strerror})") from None
    note_file_read(path, "Measurement")
    comments, header_line, header_end = [], None, 0
    for line_number, line in enumerate(text.splitlines(keepends=True), start=1):
        header_end += len(line)
        if line.lstrip().startswith(_COMMENT):
            comments.append(line.strip().lstrip(_COMMENT).strip())
        elif line.strip():
            header_line = line_number
            header = line
            break
    if header_line is None:
        raise CalcError(f"{path}: expected a header row such as 'torque [N*m],twist [arcmin]', found none")
    names = {}
    for i, cell in enumerate(header.strip().split(",")):
        m = _HEADER.match(cell)
        if not m:
            raise CalcError(f"{path}, row {header_line}: header column {i + 1} {as_found(cell)} is not of the "
                            "form 'name "
                            "[unit]'")
        names[m.group(1)] = (i, m.group(2))
    columns = (*columns, *(c for c in optional if c.name in names))
    if TIME.name in names and all(c.name != TIME.name for c in columns):
        columns = (*columns, TIME)
    units = {}
    for c in columns:
        if c.name not in names:
            raise CalcError(
                f"{path}, row {header_line}: expected a column '{c.name} [unit]' ({c.description}), found columns "
                f"{listing(names)}"
            )
        units[c.name] = _header_unit(path, c, names[c.name][1])

    body = text[header_end:].rstrip()
    if not body:
        raise CalcError(f"{path}: expected rows of data after the header (row {header_line}), found none")
    table = _table(body, len(names))
    if table is None:
        table = _table_cell_by_cell(body, names, columns, path, header_line + 1)
    if TIME.name in names:
        _check_time_order(table[:, names[TIME.name][0]], units[TIME.name], path, header_line + 1)
    out = {c.name: Q_(table[:, names[c.name][0]], units[c.name]) for c in columns}
    return Measurement(path=path, columns=out, comments=tuple(comments))


def _check_time_order(time: np.ndarray, unit: str, path: Path, first_row: int) -> None:
    """Raise :class:`CalcError` naming the first row whose time does not increase."""
    back = np.flatnonzero(np.diff(time) <= 0)
    if back.size:
        j = int(back[0]) + 1
        raise CalcError(
            f"{path}, row {first_row + j}, column {TIME.name}: expected times that increase (the rows in the order "
            "measured), "
            f"found {time[j]:g} {unit} after {time[j - 1]:g} {unit}"
        )


#: Above this many characters of data, pandas reads the table.
PANDAS_FROM = 16_000_000


def _table(body: str, width: int) -> np.ndarray | None:
    """The rows as a (rows × width) array of finite floats, or None if the body is not such a
    clean table (a blank line, a row of another width, a cell that is empty, not a number or not
    finite)."""
    if _BLANK_LINE.search(body):
        return None
    try:
        if len(body) > PANDAS_FROM:
            import pandas as pd

            table = pd.read_csv(io.StringIO(body), header=None, dtype=float, na_filter=False, engine="c").to_numpy()
        else:
            table = np.loadtxt(io.StringIO(body), delimiter=",", dtype=float, ndmin=2, comments=None, quotechar='"')
    except ValueError:  # pandas' ParserError is one too
        return None
    return table if table.shape[1] == width and np.isfinite(table).all() else None


_BLANK_LINE = re.compile(r"^[ \t\r]*$", re.MULTILINE)


def _table_cell_by_cell(body: str, names: dict, columns, path: Path, first_row: int) -> np.ndarray:
    """The rows read cell by cell, or the error naming the first bad row and column: a row with
    more cells than the header, then per column the first empty, non-numeric or infinite cell.
    Cells missing at the end of a short row are empty; columns the calculation does not use may
    hold anything."""
    rows = [line.split(",") for line in body.split("\n")]
    for j, cells in enumerate(rows):
        if len(cells) > len(names):
            raise CalcError(f"{path}: rows must have the header's {len(names)} cells (row {first_row + j} has "
                            f"{len(cells)})")
    table = np.full((len(rows), len(names)), np.nan)
    for c in columns:
        i = names[c.name][0]
        for j, cells in enumerate(rows):
            cell = cells[i].strip().strip('"') if i < len(cells) else ""
            try:
                value = float(cell)
            except ValueError:
                value = math.nan
            if not math.isfinite(value):
                found = repr(cell) if cell.strip() else "an empty cell"
                raise CalcError(f"{path}, row {first_row + j}, column {c.name}: expected a number, found {found}")
            table[j, i] = value
    return table


def write_measurement(path, columns: dict, units: dict, comments: tuple[str, ...], digits: int = 6) -> None:
    """Write quantity arrays as a measurement file: comment lines, a header with units, rows.

    Parameters
    ----------
    path : pathlib.Path or str
        The file to write.
    columns : dict
        Each column by name, a quantity array.
    units : dict
        Each column by name, the unit it is written in.
    comments : tuple of str
        The comment lines.
    digits : int
        Significant figures of each cell; default 6.

    Returns
    -------
    None
    """
    path = Path(path)
    arrays = [np.asarray(q.m_as(units[name]), dtype=float) for name, q in columns.items()]
    header = "\n".join([*(f"# {c}".rstrip() for c in comments),
                        ",".join(f"{name} [{units[name]}]" for name in columns)])
    np.savetxt(path, np.column_stack(arrays), fmt=f"%.{digits}g", delimiter=",", header=header, comments="",
               encoding="utf-8")


def travel_direction(values: np.ndarray) -> np.ndarray:
    """+1 where a recorded signal rises, -1 where it falls, for each sample (0 where it holds).

    The sign of the mean of the next ``k`` samples minus the mean of the previous ``k``
    (``k = max(2, n // 500)``): noise shrinks as ``1/√k`` while the trend grows as ``k``. A run of
    fewer than ``k`` samples between two runs of the other sign is noise, and takes their sign.

    Parameters
    ----------
    values : numpy.ndarray
        The samples in the order recorded (magnitudes, any unit).

    Returns
    -------
    numpy.ndarray of int
        The direction of each sample.
    """
    n = len(values)
    k = max(2, n // 500)
    c = np.concatenate(([0.0], np.cumsum(values)))
    idx = np.arange(n)
    ahead_end, behind_start = np.minimum(idx + 1 + k, n), np.maximum(idx - k, 0)
    ahead = (c[ahead_end] - c[np.minimum(idx + 1, n)]) / np.maximum(ahead_end - idx - 1, 1)
    behind = (c[idx] - c[behind_start]) / np.maximum(idx - behind_start, 1)
    ahead = np.where(idx + 1 < n, ahead, values)
    behind = np.where(idx > 0, behind, values)
    direction = np.sign(ahead - behind).astype(int)
    starts = np.flatnonzero(np.concatenate(([True], direction[1:] != direction[:-1])))
    lengths = np.diff(np.concatenate((starts, [n])))
    labels = direction[starts]
    inner = np.arange(1, len(starts) - 1)
    flip = inner[(lengths[inner] < k) & (labels[inner - 1] == labels[inner + 1])]
    labels[flip] = labels[flip - 1]
    return np.repeat(labels, lengths)


def check_pair(source: str, first: tuple, second: tuple) -> None:
    """Check two recorded columns: their kinds, and that they are two 1-D arrays of one length.

    Parameters
    ----------
    source : str
        Where they come from, for error messages.
    first, second : tuple
        Each ``(name, quantity array, kind)``.

    Returns
    -------
    None

    Raises
    ------
    CalcError
        Naming ``source``.
    """
    (name_a, a, kind_a), (name_b, b, kind_b) = first, second
    a = as_kind(a, kind_a, f"{source}: {name_a}").magnitude
    b = as_kind(b, kind_b, f"{source}: {name_b}").magnitude
    if np.ndim(a) != 1 or np.shape(a) != np.shape(b):
        raise CalcError(
            f"{source}: expected {name_a} and {name_b} as two arrays of one length, found shapes {np.shape(a)} and "
            f"{np.shape(b)}"
        )
