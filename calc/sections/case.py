"""Reading a design-case file (TOML, ``docs/case-format.md``).

The file is parsed by the standard library's ``tomllib``; every dimensional value is a string
parsed by :func:`calc.core.units.parse_quantity` and checked for its kind. Nothing is evaluated. Each
error names the file and the key (``profile[2].duration``).

Each section declares the tables and keys it reads once (:class:`Key`, :class:`Declared`); the
reader (:class:`Table`) takes a key's kind and default from there, and the report's inputs, the
design review's inputs and the format document (checked by the tests) follow the same declaration.
Each section reads its tables when the case is read (:meth:`calc.sections.protocol.Section.read`),
so a bad key is an error here, before anything is evaluated.
"""

from __future__ import annotations

import tomllib
import unicodedata
from dataclasses import dataclass, field
from pathlib import Path

from ..core.errors import CalcError, listing, as_found
from ..domain.gearbox import INERTIA_RATIO_LIMIT
from ..domain.profile import Profile
from ..core.units import kind_phrase, parse_quantity
from .evaluation import sections


@dataclass(frozen=True)
class Key:
    """One key of a case file's table, declared once by the section that reads it.

    Parameters
    ----------
    name : str
        The key as a case file writes it (``peak_torque``).
    kind : str
        A quantity kind of :mod:`calc.core.units` (``"torque"``) or one of :data:`OTHER_KINDS`.
    description : str
        What it is, for the report, the design review and the format document.
    symbol : str, optional
        The source document's symbol in code form (``"T_1B"``) where the key has one.
    default : object, optional
        The value as a case file would write it, which the reader takes when the key is left out
        (None: none, or one the description states because it comes from the rest of the case).
    unit : str, optional
        The unit the report and the design review show it in.
    only : tuple of str, optional
        The types of a typed table (a mechanism's) the key belongs to; empty for every type.
    keys : tuple of Key, optional
        The keys of an inline table or of each table of an array.
    """

    name: str
    kind: str
    description: str
    symbol: str = ""
    default: object = None
    unit: str = ""
    only: tuple = ()
    keys: tuple = ()


#: Kinds of keys that are not quantities: what a case file writes for them.
OTHER_KINDS = {
    "text": "a text in quotes",
    "choice": "one of the texts the description lists",
    "catalog": "a catalog name or path, or a list of them ranked together",
    "factor table": "a factor table's name (catalogs/factors) or a path to a CSV file",
    "file": "a path to a CSV file, relative to the case file",
    "bore": "a shaft with its fit, metric (ISO 286) or inch",
    "flag": "true or false",
    "table": "an inline table of the keys below",
    "tables": "an array of tables ([[...]]) of the keys below",
    "angle or length": "an angle, or with accuracy.radius a length at that radius",
    "distance": "an angle (a rotary mechanism) or a length (a linear one)",
}


@dataclass(frozen=True)
class Declared:
    """A top-level table of a case file as a section declares it.

    Parameters
    ----------
    name : str
        Its name (``motor``).
    keys : tuple of Key
        Its keys.
    description : str
        What it holds.
    array : bool, optional
        Whether it is an array of tables (``[[profile]]``).
    """

    name: str
    keys: tuple
    description: str
    array: bool = False

    def key(self, name: str) -> Key:
        """One of its keys.

        Parameters
        ----------
        name : str
            The key's name.

        Returns
        -------
        Key
            Its declaration.
        """
        return next(k for k in self.keys if k.name == name)


def key_names(keys) -> tuple[str, ...]:
    """The names of declared keys or tables.

    Parameters
    ----------
    keys : iterable of Key, Declared or str
        The declarations; plain names pass through.

    Returns
    -------
    tuple of str
        Their names, in order.
    """
    return tuple(k if isinstance(k, str) else k.name for k in keys)


class Table:
    """One table of the case file, read key by key as its section declares them (:class:`Key`:
    the kind and default of each); unknown keys are an error.

    Parameters
    ----------
    path : pathlib.Path
        The case file, for the errors.
    name : str
        The table's key path (``profile[2]``); empty for the file's top level.
    data : dict
        The table as TOML reads it; anything else is an error.
    allowed : tuple of Key, Declared or str
        The keys it may have.
    """

    def __init__(self, path: Path, name: str, data, allowed: tuple):
        self.path, self.name = path, name
        if not isinstance(data, dict):
            raise CalcError(f"{path}: {name}: expected a table of keys, found {type(data).__name__}")
        self.data = data
        self.declared = {k.name: k for k in allowed if isinstance(k, Key)}
        allowed = key_names(allowed)
        for key in data:
            if key not in allowed:
                raise CalcError(f"{path}: {self.key(key)}: unknown key; {name} takes {listing(allowed)}")

    def key(self, key: str) -> str:
        """A key's path from the file's top level.

        Parameters
        ----------
        key : str
            A key of the table.

        Returns
        -------
        str
            ``profile[2].duration``.
        """
        return f"{self.name}.{key}" if self.name else key

    def where(self, key: str) -> str:
        """Where a key is, as an error names it.

        Parameters
        ----------
        key : str
            A key of the table.

        Returns
        -------
        str
            The file and the key's path.
        """
        return f"{self.path}: {self.key(key)}"

    def has(self, key: str) -> bool:
        """Whether the table gives a key.

        Parameters
        ----------
        key : str
            A key of the table.

        Returns
        -------
        bool
            True where the case file writes it.
        """
        return key in self.data

    def kind(self, key: str) -> str:
        """The declared kind of a key.

        Parameters
        ----------
        key : str
            A declared key of the table.

        Returns
        -------
        str
            Its kind (:attr:`Key.kind`).
        """
        return self.declared[key].kind

    def _absent(self, key: str, required: bool):
        """What a key left out reads as: an error when required, else its declared default."""
        if required:
            raise CalcError(f"{self.where(key)}: expected a value, found none")
        return self.declared[key].default if key in self.declared else None

    def quantity(self, key: str, kind: str | None = None, required: bool = False):
        """The quantity at a key.

        Parameters
        ----------
        key : str
            A key of the table.
        kind : str, optional
            Its kind; None: its declared kind.
        required : bool, optional
            Whether leaving it out is an error.

        Returns
        -------
        pint.Quantity [the kind's unit] or None
            The quantity; its declared default, parsed, where the table leaves it out (None
            without one).
        """
        kind = kind or self.kind(key)
        value = self.data[key] if key in self.data else self._absent(key, required)
        return None if value is None else parse_quantity(value, kind, self.where(key))

    def positive(self, key: str, kind: str | None = None, required: bool = False, what: str | None = None):
        """The quantity at a key (:meth:`quantity`), which must be above zero.

        Parameters
        ----------
        key : str
            A key of the table.
        kind : str, optional
            Its kind; None: its declared kind.
        required : bool, optional
            Whether leaving it out is an error.
        what : str, optional
            What it is, for the error; None: its kind.

        Returns
        -------
        pint.Quantity [the kind's unit] or None
            The quantity, or its declared default (None without one).
        """
        kind = kind or self.kind(key)
        q = self.quantity(key, kind, required)
        if q is not None and not q.magnitude > 0:
            raise CalcError(f"{self.where(key)}: expected {what or kind_phrase(kind)} above zero, "
                            f"found {as_found(self.data[key])}")
        return q

    def text(self, key: str, required: bool = False, default=None):
        """The text at a key.

        Parameters
        ----------
        key : str
            A key of the table.
        required : bool, optional
            Whether leaving it out is an error.
        default : str, optional
            What it reads as where the table leaves it out (one that comes from the rest of the
            case); None: its declared default.

        Returns
        -------
        str or None
            The text, or the default.
        """
        if key not in self.data:
            declared = self._absent(key, required)
            return declared if default is None else default
        value = self.data[key]
        if not isinstance(value, str):
            raise CalcError(f"{self.where(key)}: expected a text in quotes, found {as_found(value)}")
        return value

    def _one_or_more(self, key: str, value, what: str):
        """``value`` where it is a text or a non-empty list of texts; else an error naming ``what``."""
        if isinstance(value, str) or (isinstance(value, list) and value and all(isinstance(v, str) for v in value)):
            return value
        raise CalcError(f"{self.where(key)}: expected {what} in quotes, or a list of them, found {as_found(value)}")

    def texts(self, key: str) -> tuple:
        """A text or a list of texts at a key.

        Parameters
        ----------
        key : str
            A key of the table.

        Returns
        -------
        tuple of str
            The texts; empty where the table leaves it out.
        """
        if key not in self.data:
            return ()
        value = self._one_or_more(key, self.data[key], "a text")
        return (value,) if isinstance(value, str) else tuple(value)

    def catalogs(self, key: str):
        """A catalog key.

        Parameters
        ----------
        key : str
            A key of the table.

        Returns
        -------
        str or list of str
            One name or path, or a list of them ranked together; its declared default where the
            table leaves it out.
        """
        value = self.data[key] if key in self.data else self._absent(key, False)
        return self._one_or_more(key, value, "a catalog name or path")

    def table(self, key: str, allowed: tuple) -> "Table | None":
        """An inline table at a key.

        Parameters
        ----------
        key : str
            A key of the table.
        allowed : tuple of Key or str
            The keys it may have.

        Returns
        -------
        Table or None
            The table; None where it is left out.
        """
        if key not in self.data:
            return None
        return Table(self.path, self.key(key), self.data[key], allowed)

    def tables(self, key: str, allowed: tuple) -> list["Table"]:
        """An array of tables at a key.

        Parameters
        ----------
        key : str
            A key of the table.
        allowed : tuple of Key or str
            The keys each may have.

        Returns
        -------
        list of Table
            The tables, named from 1 (``profile[1]``); empty where it is left out.
        """
        items = self.data.get(key, [])
        if not isinstance(items, list):
            raise CalcError(f"{self.where(key)}: expected an array of tables ([[{self.key(key)}]]), "
                            f"found {type(items).__name__}")
        return [Table(self.path, f"{self.key(key)}[{k}]", item, allowed) for k, item in enumerate(items, start=1)]


@dataclass
class Case:
    """A design case as read from its file: the inputs the sections share, checked, and for each
    section that reads a table of its own (``coupling``, ``accuracy``) its typed inputs
    (``inputs``) and its table as written (``sections``).

    Parameters
    ----------
    path : pathlib.Path
        The case file.
    title : str
        The case's title (default: the file's name without its suffix).
    profile : calc.domain.profile.Profile
        The load cycle at the gearbox output.
    motor_peak_torque : pint.Quantity [N*m], optional
        ``[motor] peak_torque``, T_1B (or the catalog motor's maximum torque).
    motor_inertia : pint.Quantity [kg*m**2], optional
        ``[motor] inertia``, the rotor's.
    motor_rated_torque : pint.Quantity [N*m], optional
        ``[motor] rated_torque``, the continuous torque.
    motor_max_speed : pint.Quantity [rpm], optional
        ``[motor] max_speed``.
    load_inertia : pint.Quantity [kg*m**2], optional
        ``[load] inertia``, J_L at the gearbox output.
    ratio : pint.Quantity [1], optional
        ``[gearbox] ratio``, i.
    gearbox_catalog : str or list of str, optional
        ``[gearbox] catalog``: one name or path, or several ranked together.
    gearbox_part : str, optional
        ``[gearbox] part``.
    gearbox_family : tuple of str, optional
        ``[gearbox] family``: only rows of these families are checked (all where empty).
    shock_factors : calc.data.bands.BandTable, optional
        The table of f_s of ``[gearbox]``; None: the source's.
    emergency_stop_torque : pint.Quantity [N*m], optional
        ``[gearbox] emergency_stop_torque``.
    gearbox_hubs : calc.data.catalog.Catalog, optional
        The table of clamping hubs of ``[gearbox]``.
    motor_shaft : calc.domain.fits.Bore, optional
        The motor's shaft: picks the gearbox's clamping hub.
    motor_catalog : str or list of str, optional
        ``[motor] catalog``: the motor chosen from it (or its part).
    motor_part : str, optional
        ``[motor] part``.
    motor_max_inertia_ratio : tuple, optional
        The limit of λ [1] and where it comes from (a key path, or "the default").
    motor_dc_link : pint.Quantity [V], optional
        ``[motor] dc_link_voltage``, U_DC.
    voltage_limit_dc_link : tuple, optional
        The DC-link voltage the motors' voltage limit takes [V] and where it comes from (a key path,
        or the row of the drive the case names); ``(None, None)`` where the case gives none.
    motor_curves : pathlib.Path, optional
        The motors' curves file.
    motor_torque_constant : pint.Quantity [N*m/A], optional
        A typed motor's torque constant.
    motor_thermal_time_constant : pint.Quantity [s], optional
        A typed motor's thermal time constant.
    output_load : calc.domain.gearbox.OutputForces, optional
        The forces on the gearbox output.
    sections : dict, optional
        The tables of the sections that read their own, as written, by name.
    inputs : dict, optional
        Those sections' typed inputs, by name (:meth:`calc.sections.protocol.Section.inputs`).
    motion : calc.sections.motion.Motion, optional
        Where the case gives moves or a drive record.
    raw : bytes, optional
        The file's bytes as read.
    """

    path: Path
    title: str
    profile: Profile
    motor_peak_torque: object = None
    motor_inertia: object = None
    motor_rated_torque: object = None
    motor_max_speed: object = None
    load_inertia: object = None
    ratio: object = None
    gearbox_catalog: str | list | None = None
    gearbox_part: str | None = None
    gearbox_family: tuple = ()
    shock_factors: object = None
    emergency_stop_torque: object = None
    gearbox_hubs: object = None
    motor_shaft: object = None
    motor_catalog: str | list | None = None
    motor_part: str | None = None
    motor_max_inertia_ratio: tuple = (INERTIA_RATIO_LIMIT, "the default")
    motor_dc_link: object = None
    voltage_limit_dc_link: tuple = (None, None)
    motor_curves: object = None
    motor_torque_constant: object = None
    motor_thermal_time_constant: object = None
    output_load: object = None
    sections: dict = field(default_factory=dict)
    inputs: dict = field(default_factory=dict)
    motion: object = None
    raw: bytes = b""

    @property
    def folder(self) -> Path:
        """The folder of the case file, where its own files are found."""
        return self.path.parent


def declared_tables() -> tuple:
    """Every table a case file may have, as its section declares it, in the order of the sections.

    Returns
    -------
    tuple of Declared
        Each section's :attr:`calc.sections.protocol.Section.TABLES`.
    """
    return tuple(t for s in sections() for t in s.TABLES)


def top_keys() -> tuple:
    """The keys a case file may have at its top level.

    Returns
    -------
    tuple of str
        ``title`` and the name of every declared table.
    """
    return ("title", *key_names(declared_tables()))


def read_case(path, text: str | None = None) -> Case:
    """Read and check a case file.

    Each section reads its tables in turn, in the order of the sections (:mod:`calc.sections`):
    the motor and load, the load cycle (derived from the moves and the mechanism or from a drive
    record, else typed), the gearbox, then the sections that read a table of their own.

    Parameters
    ----------
    path : str or pathlib.Path
        The case file.
    text : str, optional
        The file's text, where it is read from memory (a case edited in memory, its files found
        beside ``path`` as the file's would be).

    Returns
    -------
    Case
        The case, each section's tables read into it.

    Raises
    ------
    CalcError
        On bad input, naming the file and the key.
    """
    path = Path(path)
    if text is not None:
        raw = text.encode("utf-8")
    elif path.is_dir():
        raise CalcError(f"{path}: expected a case file, found a directory")
    elif not path.is_file():
        raise CalcError(f"{path}: the case file does not exist")
    else:
        raw = path.read_bytes()
    try:
        # An editor's byte-order mark is not TOML; catalogs accept one too.
        data = tomllib.loads(raw.decode("utf-8-sig"))
    except UnicodeDecodeError:
        raise CalcError(f"{path}: expected a UTF-8 TOML file, found bytes that are not UTF-8") from None
    except tomllib.TOMLDecodeError as exc:
        raise CalcError(f"{path}: TOML syntax error: {exc}") from None
    top = Table(path, "", data, top_keys())
    title = top.text("title", default=path.stem)
    control = next((ch for ch in title if unicodedata.category(ch) == "Cc"), None)
    if control is not None:
        # Refused, not escaped: the title goes to the terminal, the JSON and the LaTeX report, and
        # a control character (an escape sequence, a line break) means nothing in any of them.
        raise CalcError(f"{top.where('title')}: expected one line of printable text, "
                        f"found the control character U+{ord(control):04X}")
    case = Case(path=path, title=title, profile=None, raw=raw)
    for s in sections():
        s.read(top, case)
    return case
