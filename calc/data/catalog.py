"""Technical-data catalogs: CSV files with the unit in each column header, and one loader.

A catalog file has a header row such as ``part,series,ratio [1],T_2N [N*m],...,source``. Each
numeric column's unit is read from its header (any unit of the right kind: a maker's table in
lbf·in loads as well as one in N·m), each cell is parsed as a plain number (never evaluated) and
every problem is reported with the file, the row (its line number in the file) and the column.
"""

from __future__ import annotations

import contextlib
import contextvars
import csv
import dataclasses
import functools
import hashlib
import importlib.resources
import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from ..core.errors import CalcError, as_found, clipped, listing
from .parsed import SMALLEST, cache_key, keep_parsed, load_parsed
from ..core.units import Q_, SI_SCALE, describe_units, kind, pretty_unit, ureg


def _project_dir() -> Path | None:
    root = Path(__file__).resolve().parents[2]
    return root if (root / "pyproject.toml").is_file() and (root / "catalogs" / "__init__.py").is_file() else None


#: The project checkout calc is imported from (the folder of ``pyproject.toml``, ``calc/`` and
#: ``catalogs/``), or None for an installed calc.
PROJECT_DIR = _project_dir()


def package_folder(name: str) -> Path:
    """The folder of the package data ``calc.<name>`` (``catalogs``, ``reports``).

    An installed calc finds it with importlib.resources: the wheel holds the project's top-level
    ``<name>/`` as ``calc/<name>/`` (``package-dir`` in pyproject.toml). A calc imported from a
    checkout, installed editable or not, reads that checkout's own ``<name>/``: the tree that runs
    is the tree being edited, even when another tree's editable install is on the path.

    Parameters
    ----------
    name : str
        The data's folder name.

    Returns
    -------
    pathlib.Path
        The folder.
    """
    if PROJECT_DIR is not None:
        return PROJECT_DIR / name
    return Path(importlib.resources.files(f"calc.{name}")).resolve()


CATALOG_DIR = package_folder("catalogs")

_HEADER = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\[(.*)\])?\s*$")
_FLOAT = re.compile(r"^[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")


@dataclass(frozen=True)
class Column:
    """A numeric column: its name, kind, whether every row needs a value, and its lower bound.

    Parameters
    ----------
    name : str
        The column's name in the header (``"T_2N"``).
    kind : str
        The kind of its header unit.
    description : str
        What it holds, for error messages.
    required : bool
        Every row needs a value; default True.
    positive : bool
        Values must be above zero; default True.
    may_be_absent : bool
        A file without the column loads, every cell empty (a maker's table that lacks it); default
        False.
    """

    name: str
    kind: str
    description: str
    required: bool = True
    positive: bool = True
    may_be_absent: bool = False  # a file without the column loads, every cell empty (a maker's table that lacks it)


@dataclass(frozen=True)
class Rule:
    """A relation between columns that every row must satisfy, e.g. ``T_2B >= T_2N``.

    Parameters
    ----------
    text : str
        The relation as the error message states it.
    holds : callable
        ``(values: dict of quantity arrays) -> bool array``; NaN cells hold vacuously.
    column : str
        The column named in the error.
    """

    text: str
    holds: Callable  # (values: dict[str, Quantity array]) -> bool array; NaN cells hold vacuously
    column: str  # the column named in the error


@dataclass(frozen=True)
class Schema:
    """What a catalog of one kind of part must hold.

    Parameters
    ----------
    kind : str
        The kind of part (``"gearbox"``).
    columns : tuple of Column
        The numeric columns.
    text_columns : tuple of str
        The text columns every file has; default ``("part", "source")``.
    optional_text : tuple of str
        Text columns a file may have.
    rules : tuple of Rule
        Relations every row must satisfy.
    partial : str, optional
        The text column whose non-empty cell marks a row as partial, giving the reason: a partial
        row may leave required cells empty, and is kept for reference but never checked or chosen.
    """

    kind: str
    columns: tuple[Column, ...]
    text_columns: tuple[str, ...] = ("part", "source")
    optional_text: tuple[str, ...] = ()
    rules: tuple[Rule, ...] = ()
    #: The text column whose non-empty cell marks a row as partial, giving the reason: a partial
    #: row may leave required cells empty, and is kept for reference but never checked or chosen.
    partial: str | None = None


@dataclass
class Catalog:
    """A validated catalog: parts, numeric columns as quantity arrays (NaN where a cell is empty).

    Parameters
    ----------
    name : str
        The file's stem (``"gearboxes"``).
    path : pathlib.Path
        The file.
    sha256 : str
        The file's SHA-256.
    schema : Schema
        What it was checked against.
    parts : numpy.ndarray of str
        The part of each row.
    values : dict
        Each numeric column by name, a quantity array in the file's unit.
    text : dict
        Each text column by name, an object array.
    lines : numpy.ndarray of int
        The line number of each row in the file.
    header_units : dict
        Each numeric column's unit as the file writes it.
    members : tuple
        The files the rows come from, as ``(path, sha256)``: one file, or several ranked together
        (:func:`combine`).
    member : numpy.ndarray of int
        Each row's index into ``members``.
    """

    name: str
    path: Path
    sha256: str
    schema: Schema
    parts: np.ndarray
    values: dict = field(default_factory=dict)
    text: dict = field(default_factory=dict)
    lines: np.ndarray = None  # line number of each row in the file
    header_units: dict = field(default_factory=dict)  # each numeric column's unit as the file writes it
    #: The files the rows come from, as (path, sha256), and each row's index into them: one file,
    #: or several ranked together (:func:`combine`).
    members: tuple = ()
    member: np.ndarray = None
    #: The cuts of :meth:`kept_rows` by key; a copy of the catalog (``dataclasses.replace``) starts without.
    _kept: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def __post_init__(self):
        if not self.members:
            self.members = ((self.path, self.sha256),)
        if self.member is None:
            self.member = np.zeros(len(self.parts), int)

    def __len__(self):
        return len(self.parts)

    @property
    def shown_name(self) -> str:
        """The catalog as results name it: its file, or its files joined by " + "."""
        return " + ".join(display_path(path) for path, _ in self.members)

    def provenance(self) -> dict:
        """Where the rows come from, as every result's JSON names it: the catalog's shown name, its
        SHA-256 (the first file's) and each file with its SHA-256.

        Returns
        -------
        dict
            ``catalog``, ``catalog_sha256`` and ``catalogs`` (a list of ``{catalog, sha256}``).
        """
        return {
            "catalog": self.shown_name,
            "catalog_sha256": self.sha256,
            "catalogs": [{"catalog": display_path(path), "sha256": sha} for path, sha in self.members],
        }

    def catalog_of(self, row: int) -> str:
        """The file of one row, as results name it.

        Parameters
        ----------
        row : int
            The row.

        Returns
        -------
        str
            Its file as :func:`display_path` shows it.
        """
        return display_path(self.members[self.member[row]][0])

    def text_or_blank(self, column: str) -> np.ndarray:
        """A text column's cells, blank where the file has no such column.

        Parameters
        ----------
        column : str
            The column's name.

        Returns
        -------
        numpy.ndarray of str
            One cell per row.
        """
        return self.text[column] if column in self.text else self._blank

    # Each of these is worked out once over the whole catalog and carried to the catalogs of its
    # rows (:meth:`rows`): callers index them per candidate, and a per-candidate pass over 10^5
    # rows made writing the results quadratic in the catalog.
    @functools.cached_property
    def _blank(self) -> np.ndarray:
        return _read_only(np.full(len(self), "", dtype=object))

    @functools.cached_property
    def family(self) -> np.ndarray:
        """Each row's family (``TP+``), or its series where the file gives no family."""
        family = self.text_or_blank("family")
        return _read_only(np.where(family == "", self.text_or_blank("series"), family))

    @functools.cached_property
    def partial(self) -> np.ndarray:
        """True for a partial row (:attr:`Schema.partial`): kept, never checked or chosen."""
        return _read_only(self.text_or_blank(self.schema.partial) != "" if self.schema.partial
                          else np.zeros(len(self), bool))

    @functools.cached_property
    def illustrative(self) -> np.ndarray:
        """True for rows whose ``illustrative`` column says yes (figures not a maker's own); read
        once per catalog and carried to the catalogs of its rows."""
        marks = self.text.get("illustrative")
        if marks is None:
            return np.zeros(len(self), bool)
        out = np.zeros(len(self), bool)
        for mark in set(marks.tolist()):  # each distinct spelling once, not each row
            if str(mark).strip().lower() == "yes":
                out |= marks == mark
        return out

    def __getitem__(self, column: str):
        return self.values[column]

    def rows(self, mask) -> "Catalog":
        """A catalog of some of the rows.

        Parameters
        ----------
        mask : numpy.ndarray of bool or of int
            The rows to keep: true where kept, or their indices.

        Returns
        -------
        Catalog
            The rows, with every per-row array cut alike.
        """
        out = Catalog(
            self.name, self.path, self.sha256, self.schema, self.parts[mask],
            {k: v[mask] for k, v in self.values.items()}, {k: v[mask] for k, v in self.text.items()},
            self.lines[mask], self.header_units, self.members, self.member[mask],
        )
        for name in ("illustrative", "family", "partial"):
            setattr(out, name, getattr(self, name)[mask])
        return out

    def kept_rows(self, key, mask) -> "Catalog":
        """:meth:`rows`, cut once and kept under ``key``: the rows at a case's ratio are asked for by the pair
        search and the gearbox section alike, and a cut of 10^5 rows copies every column.

        Parameters
        ----------
        key : hashable
            What decides ``mask`` (``("ratio", 10.0)``): the same key, the same rows.
        mask : numpy.ndarray of bool or of int
            The rows, as :meth:`rows` takes them.

        Returns
        -------
        Catalog
            The rows, the same catalog for the same key, its arrays read-only (every caller shares them);
            the catalog itself where ``mask`` keeps every row (nothing to copy).
        """
        mask = np.asarray(mask)
        if mask.dtype == bool and len(mask) == len(self) and mask.all():
            return self
        cut = self._kept.get(key)
        if cut is None:
            if len(self._kept) >= KEPT_CUTS:
                del self._kept[next(iter(self._kept))]  # the oldest
            cut = self._kept[key] = self.rows(mask)
            for a in (cut.parts, cut.lines, cut.member, *cut.text.values(), *(q.magnitude for q in cut.values.values()),
                      cut.illustrative, cut.family, cut.partial):
                _read_only(a)
        return cut

    @functools.cached_property
    def row_of_part(self) -> dict:
        """Each part's row: its last, where a part repeats (catalogs ranked together)."""
        return dict(zip(self.parts.tolist(), range(len(self))))

    def index(self, part: str, where: str) -> int:
        """The row of a part.

        Parameters
        ----------
        part : str
            The part's name.
        where : str
            The key that names it, for the error message.

        Returns
        -------
        int
            Its first row.

        Raises
        ------
        CalcError
            For a part the catalog does not hold, naming a few that it does.
        """
        hits = np.flatnonzero(self.parts == part)
        if not len(hits):
            raise CalcError(f"{where}: no part {as_found(part)} in catalog {self.shown_name}; it has "
                            f"{listing(self.parts, limit=6)}")
        return int(hits[0])

    def usable_index(self, part: str, where: str) -> int:
        """:meth:`index` of a part that may be checked: a partial row is an input error.

        Parameters
        ----------
        part : str
            The part's name.
        where : str
            The key that names it, for the error message.

        Returns
        -------
        int
            Its row.
        """
        row = self.index(part, where)
        if self.partial[row]:
            reason = self.text[self.schema.partial][row]
            raise CalcError(
                f"{where}: {part} is a partial row of {self.catalog_of(row)} (row {self.lines[row]}), never "
                f"checked: {clipped(reason, 100)}"
            )
        return row

    def to_frame(self):
        """The catalog as a pandas DataFrame, units in the column names (for display).

        Returns
        -------
        pandas.DataFrame
            One row per part.
        """
        import pandas as pd

        data = {"part": self.parts}
        for c in self.schema.columns:
            data[f"{c.name} [{pretty_unit(self.header_units[c.name])}]"] = self.values[c.name].magnitude
        data.update({k: v for k, v in self.text.items() if k != "part"})
        return pd.DataFrame(data)


#: The most cuts a catalog keeps (:meth:`Catalog.kept_rows`): a ratio search cuts one per ratio.
KEPT_CUTS = 8


def _read_only(a: np.ndarray) -> np.ndarray:
    """``a``, which no caller may change: it is shared by every caller of the catalog."""
    a.flags.writeable = False
    return a


def display_path(path: Path) -> str:
    """A path as shown in results, the same on every machine: a packaged catalog as
    ``catalogs/NAME.csv`` (installed or not), any other file relative to the project checkout when
    inside it, else absolute.

    Parameters
    ----------
    path : pathlib.Path
        The file.

    Returns
    -------
    str
        The path as results show it.

    Examples
    --------
    >>> display_path(CATALOG_DIR / "gearboxes.csv")
    'catalogs/gearboxes.csv'
    """
    return _shown_path(os.path.abspath(path))


@functools.lru_cache(maxsize=1024)
def _shown_path(absolute: str) -> str:
    """:func:`display_path` of an absolute path: resolved once (each path component is looked up on
    disk, and a review's every change shows the same few paths)."""
    path = Path(absolute).resolve()
    for base, shown in ((CATALOG_DIR, Path("catalogs")), (PROJECT_DIR, Path())):
        if base is not None and path.is_relative_to(base):
            return str(shown / path.relative_to(base))
    return str(path)


def given_path(name_or_path: str, base: Path | None) -> Path | None:
    """The file a case names by path, or None where it names a file the package ships.

    Parameters
    ----------
    name_or_path : str
        A name, or a path (with a ``/`` or ending in ``.csv``).
    base : pathlib.Path or None
        The case file's folder, which a relative path is read from.

    Returns
    -------
    pathlib.Path or None
        The path.
    """
    if "/" not in name_or_path and not name_or_path.endswith(".csv"):
        return None
    path = Path(name_or_path)
    return base / path if not path.is_absolute() and base is not None else path


def resolve(name_or_path: str, base: Path | None, where: str) -> Path:
    """A catalog by name (``"gearboxes"`` → ``catalogs/gearboxes.csv``) or by path.

    Parameters
    ----------
    name_or_path : str
        The name or path.
    base : pathlib.Path or None
        The case file's folder, which a relative path is read from.
    where : str
        The key, for error messages.

    Returns
    -------
    pathlib.Path
        The file, which exists.
    """
    if not isinstance(name_or_path, str) or not name_or_path.strip():
        raise CalcError(f"{where}: expected a catalog name or a path to a CSV file, found {as_found(name_or_path)}")
    path = given_path(name_or_path, base) or CATALOG_DIR / f"{name_or_path}.csv"
    if not path.is_file():
        raise CalcError(f"{where}: the catalog {as_found(name_or_path)} does not exist (looked for {path})")
    return path


#: Each catalog read so far in this run, by resolved path and schema: the file's (size, mtime_ns,
#: inode) when read, and the catalog. The gearbox selection and the accuracy chain's part lookups
#: of one evaluation share one read; a file changed since (or replaced, as editors save) is read again.
_LOADED: dict = {}


#: Where a caller records the data files read (:func:`recording_files_read`); None: nobody does.
_FILES_READ: contextvars.ContextVar = contextvars.ContextVar("files_read", default=None)


@contextlib.contextmanager
def recording_files_read():
    """Within it, every data file the package reads (catalogs, factor tables, measurements) is
    recorded, once, as ``path -> (what it is, SHA-256)``: the provenance a report lists.

    Yields
    ------
    dict
        The record, filled as files are read.
    """
    files = {}
    token = _FILES_READ.set(files)
    try:
        yield files
    finally:
        _FILES_READ.reset(token)


def note_file_read(path: Path, what: str, digest: str | None = None) -> None:
    """Record ``path`` as read (:func:`recording_files_read`).

    Parameters
    ----------
    path : pathlib.Path
        The file.
    what : str
        What it is (``"catalog"``).
    digest : str, optional
        Its SHA-256 where the reader has it, else it is computed, only while something records.

    Returns
    -------
    None
    """
    files = _FILES_READ.get()
    if files is not None and path.resolve() not in files:
        files[path.resolve()] = (what, digest or hashlib.sha256(path.read_bytes()).hexdigest())


def load_catalog(path: Path, schema: Schema) -> Catalog:
    """Read and validate a catalog file against ``schema``, once per run.

    Parameters
    ----------
    path : pathlib.Path
        The CSV file.
    schema : Schema
        What it must hold.

    Returns
    -------
    Catalog
        The catalog, its arrays read-only.

    Raises
    ------
    CalcError
        Naming the file, row and column for: a missing column, a header unit of the wrong kind, an
        empty required cell, a non-numeric or non-finite cell, a value at or below zero where it
        must be positive, a duplicate part, or a row that breaks one of the schema's rules.

    Notes
    -----
    A later call for the same file (by resolved path) and schema returns the catalog already read,
    unless the file's size or modification time has changed or another file has taken its place;
    its arrays are read-only, as every caller shares them.
    """
    path = Path(path)
    stat = path.stat()
    key, stamp = (path.resolve(), schema), (stat.st_size, stat.st_mtime_ns, stat.st_ino)
    known = _LOADED.get(key)
    if known is None or known[0] != stamp:
        known = _LOADED[key] = (stamp, _read_catalog(path, schema))
    catalog = known[1]
    note_file_read(path, "Catalog", catalog.sha256)
    # The same file asked for by another spelling of its path is named as asked.
    if catalog.path == path:
        return catalog
    return dataclasses.replace(catalog, name=path.stem, path=path, members=((path, catalog.sha256),))


def load_catalogs(names, base: Path | None, where: str, schema: Schema) -> Catalog:
    """The catalog of a case's ``catalog`` key: one name or path (:func:`resolve`), or a list of
    them whose rows are ranked together (:func:`combine`), each row keeping the file it comes from.

    Parameters
    ----------
    names : str or list of str
        The key's value.
    base : pathlib.Path or None
        The case file's folder, which a relative path is read from.
    where : str
        The key, for error messages.
    schema : Schema
        What each file must hold.

    Returns
    -------
    Catalog
        One catalog of all the rows.
    """
    if isinstance(names, str):
        return load_catalog(resolve(names, base, where), schema)
    if not isinstance(names, list) or not names:
        raise CalcError(f"{where}: expected a catalog name, a path to a CSV file or a list of them, found "
                        f"{as_found(names)}")
    paths = [resolve(name, base, f"{where}[{k}]") for k, name in enumerate(names, start=1)]
    return combine([load_catalog(path, schema) for path in paths], where)


def combine(catalogs: list, where: str) -> Catalog:
    """The rows of several catalogs of one schema as one catalog, in the units of the first.

    Each row keeps the file it comes from (:attr:`Catalog.member`). The same part in two files is
    an error naming both rows: a candidate's name must say which row it is.

    Parameters
    ----------
    catalogs : list of Catalog
        The catalogs, of one schema.
    where : str
        The key, for error messages.

    Returns
    -------
    Catalog
        Their rows in order.
    """
    if len(catalogs) == 1:
        return catalogs[0]
    first = catalogs[0]
    seen = {}
    for k, cat in enumerate(catalogs):
        for part, line in zip(cat.parts.tolist(), cat.lines.tolist()):
            if part in seen and seen[part][0] != k:
                other, other_line = seen[part]
                raise CalcError(
                    f"{where}: the part {as_found(part)} stands in {display_path(catalogs[other].path)} (row "
                    f"{other_line}) and "
                    "in "
                    f"{display_path(cat.path)} (row {line}); rename one, as candidates are named by part"
                )
            seen.setdefault(part, (k, line))
    texts = sorted({name for cat in catalogs for name in cat.text})
    out = Catalog(
        name=" + ".join(cat.name for cat in catalogs),
        path=first.path,
        sha256=first.sha256,
        schema=first.schema,
        parts=np.concatenate([cat.parts for cat in catalogs]),
        values={
            c.name: Q_(np.concatenate([cat[c.name].m_as(first[c.name].units) for cat in catalogs]), first[c.name].units)
            for c in first.schema.columns
        },
        text={name: np.concatenate([cat.text_or_blank(name) for cat in catalogs]) for name in texts},
        lines=np.concatenate([cat.lines for cat in catalogs]),
        header_units=first.header_units,
        members=tuple(member for cat in catalogs for member in cat.members),
        member=np.concatenate([np.full(len(cat), k) for k, cat in enumerate(catalogs)]),
    )
    out.illustrative = np.concatenate([cat.illustrative for cat in catalogs])
    return out


def _read_catalog(path: Path, schema: Schema) -> Catalog:
    """Read and validate a catalog file, column by column over all rows at once; see
    :func:`load_catalog`."""
    raw = path.read_bytes()
    digest = hashlib.sha256(raw).hexdigest()
    key = cache_key(digest, schema) if len(raw) >= SMALLEST else None
    kept = None if key is None else load_parsed(key)
    if kept is not None:
        return _catalog(path, digest, schema, kept["parts"], kept["lines"],
                        {name: Q_(m, unit) for name, (m, unit) in kept["values"].items()}, kept["text"],
                        kept["header_units"])
    reader, width, columns, units = _header(path, raw, schema)
    cells, lines, misfit = _rows(path, reader, width)

    def column(name):
        return cells[columns[name][0]::width]

    texts = {name: list(map(str.strip, column(name))) for name in (*schema.text_columns, *schema.optional_text)
             if name in columns}
    numbers = {c.name: _numbers(column(c.name) if c.name in columns else [""] * len(lines)) for c in schema.columns}
    problem = _first_problem(path, schema, lines, texts, numbers, {name: _si(u) for name, u in units.items()})
    if problem:
        raise CalcError(problem)
    if misfit is not None:
        raise CalcError(f"{path}, row {misfit[0]}: expected {width} cells as in the header, found {misfit[1]}")

    parts = np.array(texts["part"], dtype=object)
    _no_repeated_part(path, parts, lines)
    values = {c.name: Q_(numbers[c.name].values, units[c.name]) for c in schema.columns}
    for rule in schema.rules:
        with np.errstate(invalid="ignore"):
            ok = np.asarray(rule.holds(values), dtype=bool)
        if not ok.all():
            j = int(np.flatnonzero(~ok)[0])
            raise CalcError(f"{path}, row {lines[j]} ({parts[j]}), column {rule.column}: impossible value, expected "
                            f"{rule.text}")
    text_arrays = {k: np.array(v, dtype=object) for k, v in texts.items()}
    header_units = {c.name: columns[c.name][1].strip() if c.name in columns else str(units[c.name])
                    for c in schema.columns}
    if key is not None:  # read without an error: kept for the next run (calc.data.parsed)
        keep_parsed(key, parts, lines, {n: (q.magnitude, str(q.units)) for n, q in values.items()}, text_arrays,
                    header_units)
    return _catalog(path, digest, schema, parts, lines, values, text_arrays, header_units)


def _catalog(path: Path, digest: str, schema: Schema, parts, lines, values: dict, text: dict,
             header_units: dict) -> Catalog:
    """The catalog of a file's rows as read (or as kept, :mod:`calc.data.parsed`), its arrays read-only."""
    for a in (parts, lines, *text.values(), *(q.magnitude for q in values.values())):
        a.flags.writeable = False  # shared by every caller of the run (load_catalog)
    return Catalog(name=path.stem, path=path, sha256=digest, schema=schema, parts=parts,
                   values=values, text=text, lines=lines, header_units=header_units)


def _header(path: Path, raw: bytes, schema: Schema):
    """The CSV reader past the header of a catalog file's bytes, the header's width, its columns
    (name -> (index, unit text)) and the unit of each column of ``schema``, all checked."""
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise CalcError(f"{path}: expected a UTF-8 CSV file, found bytes that are not UTF-8") from None
    reader = csv.reader(text.splitlines())
    try:
        header = next(reader)
    except StopIteration:
        raise CalcError(f"{path}: expected a header row, found an empty file") from None
    columns = {}  # name -> (index, unit text)
    for i, cell in enumerate(header):
        m = _HEADER.match(cell)
        if not m:
            raise CalcError(f"{path}: header column {i + 1} {as_found(cell)} is not of the form 'name [unit]'")
        if m.group(1) in columns:
            raise CalcError(f"{path}: the column {as_found(m.group(1))} appears twice in the header")
        columns[m.group(1)] = (i, m.group(2))
    for name in schema.text_columns:
        if name not in columns:
            raise CalcError(f"{path}: expected a column {as_found(name)}, found columns {listing(columns)}")
    units = {}
    for c in schema.columns:
        if c.name not in columns and c.may_be_absent:
            units[c.name] = ureg.parse_units(kind(c.kind).si_unit or "dimensionless")
            continue
        if c.name not in columns:
            raise CalcError(
                f"{path}: expected a column '{c.name} [unit]' ({c.description}), found columns {listing(columns)}"
            )
        unit_text = columns[c.name][1]
        units[c.name] = _header_unit(path, c, unit_text)
    return reader, len(header), columns, units


def _rows(path: Path, reader, width: int):
    """The cells of all data rows in one flat list, their line numbers, and the first row whose
    length differs from the header's (``(line, length)``, or None).

    The list stops at that row; it is reported after any problem in the rows before it, as a
    reader going row by row would. Each row's list is dropped at once: 10^5 row lists kept alive
    would make the garbage collector walk them again and again.
    """
    cells, lines, misfit = [], [], None
    for line, row in enumerate(reader, start=2):
        if not "".join(row).strip():
            continue  # a blank row
        if len(row) != width:
            misfit = (line, len(row))
            break
        cells.extend(row)
        lines.append(line)
    if not lines and misfit is None:
        raise CalcError(f"{path}: expected at least one row of data, found none")
    return cells, np.array(lines, dtype=int), misfit


def _no_repeated_part(path: Path, parts: np.ndarray, lines: np.ndarray) -> None:
    """Raises for the first row whose part already stands in an earlier row."""
    # np.unique gives each part's first row; a row whose part first stands earlier repeats it.
    _, first, inverse = np.unique(parts.astype(str), return_index=True, return_inverse=True)
    first = first[inverse.ravel()]
    repeats = np.flatnonzero(first != np.arange(len(parts)))
    if len(repeats):
        j = repeats[0]
        raise CalcError(f"{path}, row {lines[j]}, column part: the part {as_found(parts[j])} already stands in row "
                        f"{lines[first[j]]}")


@dataclass(frozen=True)
class _Numbers:
    """A numeric column parsed: its cells as written, values (NaN where empty or not a number)
    and which cells are empty or not numbers."""

    cells: list
    values: np.ndarray
    empty: np.ndarray
    malformed: np.ndarray

    def bad(self, c: Column, si_factor: float) -> np.ndarray:
        """Where a cell fails column ``c``: empty though required, or given but not a finite
        number in range (NaN, the mark of a malformed cell, is neither), or out of
        :data:`calc.core.units.SI_SCALE` once in SI units (``si_factor``: the header unit's), where
        the calculations would overflow or lose the value to underflow."""
        ok = np.isfinite(self.values) & (self.values > 0 if c.positive else self.values >= 0)
        low, high = SI_SCALE
        with np.errstate(over="ignore", invalid="ignore"):
            si = np.abs(self.values * si_factor)
        ok &= (si == 0) | ((si >= low) & (si <= high))
        return np.where(self.empty, c.required, ~ok)

    def problem(self, j: int, c: Column, si_factor: float, si_unit, where: str) -> str:
        """What is wrong with cell ``j``, one that :meth:`bad` marks."""
        cell = self.cells[j].strip()
        if self.empty[j]:
            return f"{where}: expected a number, found an empty cell"
        if self.malformed[j]:
            return f"{where}: expected a number, found {cell!r}"
        if not math.isfinite(self.values[j]):
            return f"{where}: expected a finite number, found {cell!r}"
        if c.positive and not self.values[j] > 0:
            return f"{where}: expected a value above zero, found {cell}"
        if not self.values[j] >= 0:
            return f"{where}: expected a value of zero or more, found {cell}"
        low, high = SI_SCALE
        return (f"{where}: expected a magnitude between {low:g} and {high:g} in SI units ({si_unit:~P}), "
                f"found {cell}, which is {abs(self.values[j] * si_factor):.3g}")


def _numbers(cells: list) -> _Numbers:
    """Parse a column of cells as written. Each distinct spelling is stripped, held against
    :data:`_FLOAT` and parsed once (a catalog repeats its values, and a lookup costs less than a
    parse), so ``inf``, ``nan``, ``1_000`` or hex, which ``float`` would take, are malformed."""
    spellings = dict.fromkeys(cells)  # the distinct spellings, each with its index below
    stripped = [spelling.strip() for spelling in spellings]
    parsed = np.array([float(cell) if cell and _FLOAT.match(cell) else math.nan for cell in stripped], float)
    blank = np.array([not cell for cell in stripped], bool)
    if len(spellings) == 1:  # a blank or constant column (a maker's table that leaves one out): no lookups
        at = np.zeros(len(cells), np.intp)
    else:
        index = dict(zip(spellings, range(len(spellings))))
        at = np.fromiter(map(index.__getitem__, cells), np.intp, len(cells))
    values, empty = parsed[at], blank[at]
    # A number's spelling never parses to NaN: NaN marks the empty and the malformed cells.
    return _Numbers(cells, values, empty, np.isnan(values) & ~empty)


def _first_problem(path: Path, schema: Schema, lines, texts: dict, numbers: dict, si: dict) -> str | None:
    """The message of the first bad cell a reader meets going row by row and, in a row, column by
    column (the text columns, then the numeric ones in the schema's order), or None. Each
    column's bad cells are found over the whole column at once; ``si`` gives each numeric
    column's factor to SI and its SI unit (:func:`_si`)."""
    firsts = []  # (row index, column order, column name) of each column's first bad cell
    for order, name in enumerate(texts):
        if name in schema.text_columns and "" in texts[name]:
            firsts.append((texts[name].index(""), order, name))
    partial = np.array(texts[schema.partial], dtype=object) != "" if schema.partial in texts else False
    for order, c in enumerate(schema.columns, start=len(texts)):
        bad = numbers[c.name].bad(c, si[c.name][0])
        if c.required:
            bad &= ~(partial & numbers[c.name].empty)  # a partial row may leave a required cell empty
        if bad.any():
            firsts.append((int(np.argmax(bad)), order, c.name))
    if not firsts:
        return None
    j, _, name = min(firsts)
    if name in texts:
        return f"{path}, row {lines[j]}, column {name}: expected a value, found an empty cell"
    c = next(c for c in schema.columns if c.name == name)
    return numbers[name].problem(j, c, *si[name], f"{path}, row {lines[j]} ({texts['part'][j]}), column {name}")


def _si(units) -> tuple[float, object]:
    """The factor that takes a column's unit to SI, and the SI unit."""
    base = ureg.Quantity(1.0, units).to_base_units()
    return float(base.magnitude), base.units


def _header_unit(path: Path, c: Column, unit_text):
    where = f"{path}, header, column {c.name}"
    k = kind(c.kind)
    if unit_text is None:
        raise CalcError(f"{where}: expected a unit in brackets such as '{c.name} [{k.si_unit or 1}]', found none")
    text = unit_text.strip()
    try:
        units = ureg.parse_units(text) if text not in ("", "1", "-") else ureg.dimensionless
    except Exception as exc:  # pint raises several types for unknown or malformed units
        raise CalcError(
            f"{where}: the unit {as_found(text)} is not one the unit registry knows ({type(exc).__name__})"
        ) from None
    if not k.accepts(units):
        raise CalcError(f"{where}: expected a unit of {k.name} such as {k.example}, found {as_found(text)}, which is "
                        f"{describe_units(units)}")
    return units


def no_less(a: str, b: str) -> Callable:
    """Rule helper: column ``a`` is at least column ``b`` where both are given.

    Parameters
    ----------
    a, b : str
        The columns' names.

    Returns
    -------
    callable
        The test of a :class:`Rule`.
    """

    def holds(v):
        x, y = v[a].magnitude, v[b].m_as(v[a].units)
        return np.isnan(x) | np.isnan(y) | (x >= y)

    return holds
