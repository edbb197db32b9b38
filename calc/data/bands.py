"""Factor tables looked up by the band a value falls in: the shock factor (E4), the temperature
factor (E9) and the makers' tables beside them (temperature and start factors of elastomer
couplings).

The source prints both of its tables with open bands (``1000 < Zh < 1500``, ``50°C - 70°C``) that
leave each boundary undefined or in two rows; the errata read both the same way: a band runs from
its lowest value (included) to the next band's (excluded), so the higher factor applies at a
boundary. A maker that prints a factor *at* a value (Mayr: 1.5 at +60 °C, 2 at +90 °C) closes its
bands at the top instead: the factor printed for 60 °C holds up to and at 60 °C. :class:`BandTable`
holds both rules, with the boundary tolerance of :mod:`calc.core.checks`, for the lookup, the plots and
the report's band text.

Every table is data: a CSV file in ``catalogs/factors/`` (or the user's own), read and checked by
:func:`load_factor_table`; :func:`factor_table` finds a table by its role and name.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .catalog import _FLOAT, _HEADER, CATALOG_DIR, Column, _header_unit, display_path, given_path, note_file_read
from ..core.checks import BOUNDARY_RTOL
from ..core.errors import SHOWN, CalcError, as_found, clipped, listing
from ..core.glossary import latex as symbol_latex
from ..core.units import Q_, as_kind, pretty_unit, sig  # noqa: F401 (Q_: the doctests)

#: Which end of its bands a table includes: ``higher``, the higher factor at a boundary (each band
#: includes its lowest value, E4, E9); ``lower``, the lower factor at a boundary (each band includes
#: its highest value, a maker's factor printed at a value).
AT_BOUNDARY = ("higher", "lower")


@dataclass(frozen=True)
class BandTable:
    """A factor for each band of a value, the higher factor at a boundary.

    Parameters
    ----------
    symbol : str
        The looked-up value's symbol, as in the band text (``Z_h``): its name in
        :mod:`calc.core.glossary`, which typesets it for LaTeX.
    lower : tuple of float
        The lowest value of each band in ``unit``, ascending; the first may be ``-inf``.
    values : tuple of float
        The factor of each band.
    unit : str
        The unit of ``lower`` and ``top``.
    kind : str
        The kind a looked-up quantity must have (:func:`calc.core.units.as_kind`).
    source : str
        Where the table comes from.
    top : float
        The highest value the last band covers (included); ``inf`` for an open last band.
    at_boundary : {"higher", "lower"}
        Which factor applies on a boundary between two bands (:data:`AT_BOUNDARY`).

    Notes
    -----
    A value within :data:`calc.core.checks.BOUNDARY_RTOL` below a boundary counts as on it: sums and
    unit conversions carry rounding (a cycle of 2.4000000000000004 s gives 1499.9999999999998
    cycles per hour, which is 1500). A value outside ``lower[0]`` to ``top`` is refused.

    Examples
    --------
    >>> from calc import Q_
    >>> t = BandTable("Z_h", (0, 1000, 1500), (1.0, 1.1, 1.3), "1/h", "per_hour", "an example")
    >>> t.lookup(Q_([999, 1000, 1499.9999999999998, 1e6], "1/h")).tolist()
    [1.0, 1.1, 1.3, 1.3]
    >>> t.text(int(t.band(Q_(1200, "1/h"))))
    '1000 <= Z_h < 1500 1/h'
    """

    symbol: str
    lower: tuple
    values: tuple
    unit: str
    kind: str
    source: str
    top: float = math.inf
    at_boundary: str = "higher"

    def __post_init__(self):
        if self.at_boundary not in AT_BOUNDARY:
            raise CalcError(f"{self.source}: expected at_boundary to be one of {listing(AT_BOUNDARY)}, found "
                            f"{as_found(self.at_boundary)}")
        lower = np.asarray(self.lower, dtype=float)
        if lower.ndim != 1 or len(lower) == 0 or len(self.values) != len(lower):
            raise CalcError(f"{self.source}: expected one factor per band, found {len(self.values)} factors for "
                            f"{len(lower)} bands")
        if not (np.all(np.diff(lower) > 0) and self.top > lower[-1]):
            raise CalcError(f"{self.source}: expected band bounds that rise, found {listing(map(sig, lower))} up to "
                            f"{sig(self.top)}")

    def __len__(self) -> int:
        """The number of bands."""
        return len(self.lower)

    @property
    def bounds(self) -> np.ndarray:
        """The lowest value of each band, as a float array."""
        return np.asarray(self.lower, dtype=float)

    @property
    def factors(self) -> np.ndarray:
        """The factor of each band, as a float array."""
        return np.asarray(self.values, dtype=float)

    def band(self, value, where: str = "value"):
        """Index of the band of each value.

        Parameters
        ----------
        value : pint.Quantity [a unit of kind]
            Scalar or array, of the table's :attr:`kind`.
        where : str
            The argument or key, for error messages; default ``"value"``.

        Returns
        -------
        int or numpy.ndarray of int
            The band of each value.

        Raises
        ------
        CalcError
            Naming ``where``, for a value of another kind or outside the table, ``lower[0]`` to ``top``.
        """
        x = as_kind(value, self.kind, where).m_as(self.unit)
        up, down = x + np.abs(x) * BOUNDARY_RTOL, x - np.abs(x) * BOUNDARY_RTOL
        outside = (up < self.bounds[0]) | (down > self.top)
        if np.any(outside):
            bad = np.asarray(x)[outside] if np.ndim(x) else x
            raise CalcError(f"{where}: expected {self.range_text()} ({clipped(self.source, 2 * SHOWN)}), "
                            f"found {sig(np.ravel(bad)[0])} "
                            f"{pretty_unit(self.unit)}")
        if self.at_boundary == "higher":
            return np.searchsorted(self.bounds, up, side="right") - 1  # just below a boundary is on it
        return np.searchsorted(self.bounds[1:], down, side="left")  # just above a boundary is on it

    def lookup(self, value, where: str = "value"):
        """The factor of each value (scalar or array), the higher one at a boundary.

        Parameters
        ----------
        value : pint.Quantity [a unit of kind]
            Scalar or array, of the table's :attr:`kind`.
        where : str
            The argument or key, for error messages; default ``"value"``.

        Returns
        -------
        float or numpy.ndarray [1]
            The factor of each value's band.
        """
        return self.factors[self.band(value, where)]

    def text(self, k: int, latex: bool = False) -> str:
        r"""Band ``k`` as a reader writes it, ``1500 <= Z_h < 2000 1/h``.

        Parameters
        ----------
        k : int
            The band.
        latex : bool
            For math mode (``\le``, ``\ge``, the symbol by :func:`calc.core.glossary.latex`, the unit as
            text); default False.

        Returns
        -------
        str
            The band's range.
        """
        le, ge = (r"\le", r"\ge") if latex else ("<=", ">=")
        shown = symbol_latex(self.symbol) if latex else self.symbol
        low, last = self.bounds[k], k + 1 == len(self)
        high = self.top if last else self.bounds[k + 1]
        if self.at_boundary == "lower":  # each band holds its highest value
            if k == 0:
                band = f"{shown} {le} {sig(high)}" if math.isinf(low) else f"{sig(low)} {le} {shown} {le} {sig(high)}"
            elif math.isinf(high):
                band = f"{shown} > {sig(low)}"
            else:
                band = f"{sig(low)} < {shown} {le} {sig(high)}"
        elif not last:
            band = f"{shown} < {sig(high)}" if math.isinf(low) else f"{sig(low)} {le} {shown} < {sig(high)}"
        elif math.isinf(high):
            band = f"{shown} {ge} {sig(low)}"
        else:
            band = f"{sig(low)} {le} {shown} {le} {sig(high)}"
        unit = pretty_unit(self.unit)
        return rf"{band}\ \text{{{unit}}}" if latex else f"{band} {unit}"

    def range_text(self) -> str:
        """The values the table covers, ``Z_h >= 0 1/h`` or ``T <= 120 °C``.

        Returns
        -------
        str
            The covered range as a reader writes it.
        """
        low, high = self.bounds[0], self.top
        unit = pretty_unit(self.unit)
        if math.isinf(low):
            return f"{self.symbol} <= {sig(high)} {unit}"
        if math.isinf(high):
            return f"{self.symbol} >= {sig(low)} {unit}"
        return f"{sig(low)} <= {self.symbol} <= {sig(high)} {unit}"


#: The folder of the named factor tables, ``<role>-<name>.csv``.
FACTOR_DIR = CATALOG_DIR / "factors"


@dataclass(frozen=True)
class FactorRole:
    """What a factor table is looked up by: the symbol of the value, its kind, and the table used
    when a case names none (None: the check that needs it is not made without one).

    Parameters
    ----------
    symbol : str
        The looked-up value's symbol (``"Z_h"``).
    kind : str
        Its kind (``"per_hour"``).
    default : str or None
        The table used when a case names none.
    what : str
        What the factor is, in words.
    """

    symbol: str
    kind: str
    default: str | None
    what: str


#: The roles of the factor tables, by the file prefix of their tables in :data:`FACTOR_DIR`.
ROLES = {
    "shock": FactorRole("Z_h", "per_hour", "source", "shock factor f_s against cycles per hour (gearboxes, E4)"),
    "temperature": FactorRole("T", "temperature", "source", "temperature factor of elastomer couplings (E9)"),
    "starts": FactorRole("Z_h", "per_hour", None, "start factor S_z of elastomer couplings against starts per hour"),
}


def table_names(role: str) -> list[str]:
    """The names of the tables of ``role`` shipped in :data:`FACTOR_DIR`.

    Parameters
    ----------
    role : str
        A key of :data:`ROLES` (``"temperature"``).

    Returns
    -------
    list of str
        The names, sorted.

    Examples
    --------
    >>> table_names("temperature")
    ['comintec', 'roba-es', 'source']
    """
    return sorted(p.name[len(role) + 1 : -4] for p in FACTOR_DIR.glob(f"{role}-*.csv"))


def factor_table(role: str, name_or_path: str | None = None, base: Path | None = None,
                 where: str = "factor table") -> BandTable:
    """The factor table of ``role`` by name or by path; the role's default for None.

    Parameters
    ----------
    role : str
        A key of :data:`ROLES`.
    name_or_path : str, optional
        A table's name (``"roba-es"`` is ``catalogs/factors/<role>-roba-es.csv``) or a path to a CSV
        file; None for the role's default.
    base : pathlib.Path, optional
        The case file's folder, which a relative path is read from.
    where : str
        The key, for error messages; default ``"factor table"``.

    Returns
    -------
    BandTable
        The table, read and checked once per run.

    Examples
    --------
    >>> float(factor_table("temperature", "roba-es").lookup(Q_(60, "degC")))
    1.5
    """
    r = ROLES[role]
    name = r.default if name_or_path is None else name_or_path
    if not isinstance(name, str) or not name.strip():
        raise CalcError(f"{where}: expected a table name ({listing(table_names(role))}) or a path to a CSV file, "
                        f"found {as_found(name)}")
    path = given_path(name, base)
    if path is None:
        path = FACTOR_DIR / f"{role}-{name}.csv"
        if not path.is_file():
            raise CalcError(f"{where}: unknown {role}-factor table {as_found(name)}; expected one of "
                            f"{listing(table_names(role))} or a path to a CSV file")
    elif not path.is_file():
        raise CalcError(f"{where}: the factor table {as_found(name)} does not exist (looked for {path})")
    return load_factor_table(path, r.symbol, r.kind)


_COLUMNS = ("from", "to", "factor", "at_boundary", "source")


def load_factor_table(path, symbol: str, kind: str) -> BandTable:
    """Read and check a factor table.

    The file is a CSV file with the columns ``from [unit]``, ``to [unit]`` (the band's ends, in a
    unit of ``kind``), ``factor [1]``, ``at_boundary`` (``higher`` or ``lower``, the same in every
    row, :data:`AT_BOUNDARY`) and ``source``; one row per band, in rising order. The first row's
    ``from`` and the last row's ``to`` may be empty (an open end).

    Parameters
    ----------
    path : pathlib.Path or str
        The CSV file.
    symbol : str
        The looked-up value's symbol, for the band texts.
    kind : str
        The kind of the band's ends.

    Returns
    -------
    BandTable
        The table.

    Raises
    ------
    CalcError
        Naming the file, row and column for a missing column, a unit of the wrong kind, a cell that
        is not a number, a factor at or below zero, bands that do not rise, a gap or overlap between
        bands (a row's ``from`` differs from the row before's ``to``), and factors that fall as the
        value rises.
    """
    path = Path(path)
    try:
        text = path.read_bytes().decode("utf-8-sig")
    except UnicodeDecodeError:
        raise CalcError(f"{path}: expected a UTF-8 CSV file, found bytes that are not UTF-8") from None
    note_file_read(path, "Factor table")
    rows = list(csv.reader(line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")))
    if not rows:
        raise CalcError(f"{path}: expected a header row, found an empty file")
    header = {}
    for i, cell in enumerate(rows[0]):
        m = _HEADER.match(cell)
        if not m:
            raise CalcError(f"{path}: header column {i + 1} {as_found(cell)} is not of the form 'name [unit]'")
        header[m.group(1)] = (i, m.group(2))
    missing = [c for c in _COLUMNS if c not in header]
    if missing:
        raise CalcError(f"{path}: expected the columns {listing(_COLUMNS)}, found no column {as_found(missing[0])}")
    units = {c: _header_unit(path, Column(c, k, c), header[c][1])
             for c, k in (("from", kind), ("to", kind), ("factor", "dimensionless"))}
    if units["from"] != units["to"]:
        raise CalcError(f"{path}, header: expected the columns from and to in one unit, found "
                        f"{as_found(header['from'][1])} "
                        f"and {as_found(header['to'][1])}")
    body = rows[1:]
    if not body:
        raise CalcError(f"{path}: expected one row per band, found none")

    def cell(k: int, column: str) -> str:
        row = body[k]
        i = header[column][0]
        return row[i].strip() if i < len(row) else ""

    def where(k: int, column: str) -> str:
        return f"{path}, row {k + 2}, column {column}"

    def number(k: int, column: str, empty: float | None = None) -> float:
        text = cell(k, column)
        if not text and empty is not None:
            return empty
        if not _FLOAT.match(text):
            raise CalcError(f"{where(k, column)}: expected a number, found {as_found(text)}" if text
                            else f"{where(k, column)}: expected a number, found an empty cell")
        return float(text)

    n = len(body)
    low = [number(k, "from", -math.inf if k == 0 else None) for k in range(n)]
    high = [number(k, "to", math.inf if k == n - 1 else None) for k in range(n)]
    factor = [number(k, "factor") for k in range(n)]
    for k in range(n):
        if not factor[k] > 0:
            raise CalcError(f"{where(k, 'factor')}: expected a factor above zero, found {as_found(cell(k, 'factor'))}")
        if not high[k] > low[k]:
            raise CalcError(f"{where(k, 'to')}: expected a band that rises, to above from, found from "
                            f"{cell(k, 'from') or 'open'} and to {cell(k, 'to') or 'open'}")
        if k and low[k] != high[k - 1]:
            what = "a gap" if low[k] > high[k - 1] else "an overlap"
            raise CalcError(f"{where(k, 'from')}: expected the band to start where the row before ends "
                            f"({cell(k - 1, 'to')}), found {as_found(cell(k, 'from'))}, {what}")
        if k and factor[k] < factor[k - 1]:
            raise CalcError(
                f"{where(k, 'factor')}: expected factors that never fall as {symbol} rises, found {cell(k, 'factor')} "
                f"after {cell(k - 1, 'factor')}"
            )
    rule = cell(0, "at_boundary")
    bad = next((k for k in range(n) if cell(k, "at_boundary") not in AT_BOUNDARY or cell(k, "at_boundary") != rule),
               None)
    if bad is not None:
        found = cell(bad, "at_boundary")
        expected = (f"one of {listing(AT_BOUNDARY)}" if found not in AT_BOUNDARY
                    else f"the same rule in every row ({rule!r} in the first)")
        raise CalcError(f"{where(bad, 'at_boundary')}: expected {expected}, found {as_found(found)}")
    sources = list(dict.fromkeys(cell(k, "source") for k in range(n) if cell(k, "source")))
    if not sources:
        raise CalcError(f"{where(0, 'source')}: expected where the factors come from, found an empty cell")
    shipped = path.parent.resolve() == FACTOR_DIR.resolve()
    shown = "; ".join(sources) if shipped else f"{display_path(path)}: {'; '.join(sources)}"
    return BandTable(symbol, tuple(low), tuple(factor), header["from"][1].strip(), kind, shown, high[-1], rule)
