"""The motion pattern's time series as IDTA 02021 writes it: a CSV file, ``;`` between columns, a
header of ``idShort [unit]``, then one row per sample with ``.`` as the decimal point (the template's
section 2.2.2). The workbook writes a rotative section at the gearbox output (readings I3)."""

from __future__ import annotations

import io

import numpy as np

from ..core.errors import CalcError

#: The columns written, each the idShort of the template's MetadataRotativeMotionFile and its unit.
ROTATIVE_COLUMNS = (("Time", "s"), ("AngularPosition", "rad"), ("AngularVelocity", "rad/s"),
                    ("AngularAcceleration", "rad/s²"), ("AngularJerk", "rad/s³"), ("LoadTorque", "Nm"))
#: The columns a case needs of a rotative section: the time and the speed.
NEEDED = ("Time", "AngularVelocity")
#: The most rows read: a cycle sampled far more finely than any evaluation needs is refused before
#: it fills the memory.
MAX_ROWS = 200_000
#: The most bytes read of one motion file (about 100 bytes a row).
MAX_BYTES = MAX_ROWS * 120


def motion_csv(columns: dict) -> str:
    """The CSV text of a rotative motion section.

    Parameters
    ----------
    columns : dict
        idShort of :data:`ROTATIVE_COLUMNS` -> numpy.ndarray in that column's unit, all of one length.

    Returns
    -------
    str
        Header and rows, ``;``-separated, each number with 12 significant digits.
    """
    names = [n for n, _ in ROTATIVE_COLUMNS if n in columns]
    units = dict(ROTATIVE_COLUMNS)
    table = np.column_stack([np.asarray(columns[n], dtype=float) for n in names])
    out = io.StringIO()
    out.write(";".join(f"{n} [{units[n]}]" for n in names) + "\n")
    np.savetxt(out, table, fmt="%.12g", delimiter=";")
    return out.getvalue()


def read_motion_csv(data: bytes, where: str) -> dict:
    """The columns of a rotative motion section's CSV file.

    Parameters
    ----------
    data : bytes
        The file's content.
    where : str
        The file as the error names it (the package and the element's path).

    Returns
    -------
    dict
        idShort -> numpy.ndarray in the unit of :data:`ROTATIVE_COLUMNS` (the columns it has).

    Raises
    ------
    CalcError
        For a file too large, not UTF-8, a header that is not ``idShort [unit]`` with the template's
        unit, a column the case needs missing, a cell that is not a number, or times not increasing.
    """
    if len(data) > MAX_BYTES:
        raise CalcError(f"{where}: expected a motion pattern of at most {MAX_ROWS} rows, found a file of "
                        f"{len(data)} bytes")
    try:
        lines = data.decode("utf-8-sig").splitlines()
    except UnicodeDecodeError:
        raise CalcError(f"{where}: expected a UTF-8 CSV file, found bytes that are not UTF-8") from None
    if len(lines) - 1 > MAX_ROWS:
        raise CalcError(f"{where}: expected a motion pattern of at most {MAX_ROWS} rows, found {len(lines) - 1}")
    units = dict(ROTATIVE_COLUMNS)
    header = [h.strip() for h in lines[0].split(";")] if lines else []
    names = []
    for h in header:
        name, _, unit = h.partition(" [")
        if name not in units or unit != units[name] + "]":
            raise CalcError(f"{where}: expected a header of the template's 'idShort [unit]' (Time [s], "
                            f"AngularVelocity [rad/s] ...), found '{h[:40]}'")
        names.append(name)
    missing = [n for n in NEEDED if n not in names]
    if missing:
        raise CalcError(f"{where}: expected the columns {' and '.join(NEEDED)}, found no {missing[0]}")
    rows = [line.split(";") for line in lines[1:] if line.strip()]
    short = next((k for k, row in enumerate(rows, start=2) if len(row) != len(names)), None)
    if len(rows) < 2 or short is not None:
        raise CalcError(f"{where}: expected at least two rows of {len(names)} cells each, found "
                        f"{f'row {short} with another count' if short else f'{len(rows)} rows'}")
    try:
        table = np.array([[float(c) for c in row] for row in rows], dtype=float)
    except ValueError:
        raise CalcError(f"{where}: expected numbers with '.' as the decimal point, found a cell that is not "
                        f"one") from None
    if not np.isfinite(table).all():
        raise CalcError(f"{where}: expected finite numbers, found a cell that is not")
    if np.any(np.diff(table[:, names.index("Time")]) <= 0):
        raise CalcError(f"{where}: expected the column Time [s] to increase from row to row, found it does not")
    return {n: table[:, k] for k, n in enumerate(names)}
