"""Reading a design-case file (TOML, ``../shared/spec/case-format.md``).

The file is parsed by the standard library's ``tomllib``; every dimensional value is a string
parsed by :func:`calc.units.parse_quantity` and checked for its kind. Nothing is evaluated. Each
error names the file and the key (``profile[2].duration``).
"""

from __future__ import annotations

import tomllib
import unicodedata
from dataclasses import dataclass, field
from pathlib import Path

from .errors import CalcError
from .profile import Profile
from .units import kind_phrase, parse_quantity


class Table:
    """One table of the case file, read key by key; unknown keys are an error."""

    def __init__(self, path: Path, name: str, data, allowed: tuple[str, ...]):
        self.path, self.name = path, name
        if not isinstance(data, dict):
            raise CalcError(f"{path}: {name}: expected a table of keys, found {type(data).__name__}")
        self.data = data
        for key in data:
            if key not in allowed:
                raise CalcError(f"{path}: {self.key(key)}: unknown key; {name} takes {', '.join(allowed)}")

    def key(self, key: str) -> str:
        return f"{self.name}.{key}" if self.name else key

    def where(self, key: str) -> str:
        return f"{self.path}: {self.key(key)}"

    def has(self, key: str) -> bool:
        return key in self.data

    def quantity(self, key: str, kind: str, required: bool = False, default=None):
        if key not in self.data:
            if required:
                raise CalcError(f"{self.where(key)}: expected a value, found none")
            return default
        return parse_quantity(self.data[key], kind, self.where(key))

    def positive(self, key: str, kind: str, required: bool = False, what: str | None = None):
        """:meth:`quantity`, which must be above zero; ``what`` names it in the error (default:
        its kind)."""
        q = self.quantity(key, kind, required)
        if q is not None and not q.magnitude > 0:
            raise CalcError(f"{self.where(key)}: expected {what or kind_phrase(kind)} above zero, found {self.data[key]!r}")
        return q

    def text(self, key: str, required: bool = False, default=None):
        if key not in self.data:
            if required:
                raise CalcError(f"{self.where(key)}: expected a value, found none")
            return default
        value = self.data[key]
        if not isinstance(value, str):
            raise CalcError(f"{self.where(key)}: expected a text in quotes, found {value!r}")
        return value

    def catalogs(self, key: str, default: str):
        """A catalog key: one name or path, or a list of them ranked together."""
        value = self.data.get(key, default)
        if isinstance(value, list) and value and all(isinstance(v, str) for v in value):
            return value
        if not isinstance(value, str):
            raise CalcError(f"{self.where(key)}: expected a catalog name or path in quotes, or a list of them, found {value!r}")
        return value

    def table(self, key: str, allowed: tuple[str, ...]) -> "Table | None":
        if key not in self.data:
            return None
        return Table(self.path, self.key(key), self.data[key], allowed)

    def tables(self, key: str, allowed: tuple[str, ...]) -> list["Table"]:
        items = self.data.get(key, [])
        if not isinstance(items, list):
            raise CalcError(f"{self.where(key)}: expected an array of tables ([[{self.key(key)}]]), found {type(items).__name__}")
        return [Table(self.path, f"{self.key(key)}[{k}]", item, allowed) for k, item in enumerate(items, start=1)]


@dataclass
class Case:
    """A design case as read from its file: the inputs the sections share, checked, and the raw
    tables of the sections that read their own (``coupling``, ``accuracy``) when evaluated."""

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
    shock_factors: object = None  # the table of f_s (calc.bands.BandTable) of [gearbox]; None: the source's
    emergency_stop_torque: object = None
    gearbox_hubs: str | list | None = None
    motor_shaft: object = None  # Bore of the motor's shaft: picks the gearbox's clamping hub
    output_load: object = None  # calc.gearbox.OutputLoad: forces on the gearbox output
    sections: dict = field(default_factory=dict)  # raw tables of further sections, by name
    motion: object = None  # calc.sections.motion.Motion where the case gives moves or a drive record
    raw: bytes = b""
    # What has been computed from the case, by name (see :func:`once`); a changed copy starts empty.
    computed: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    @property
    def folder(self) -> Path:
        return self.path.parent


def once(case: Case, name: str, compute):
    """``compute()`` the first time ``name`` is asked of this case, the same object after: the
    evaluation, the report and a section that builds on the gearbox share one selection."""
    if name not in case.computed:
        case.computed[name] = compute()
    return case.computed[name]


def read_case(path) -> Case:
    """Read and check a case file; raise :class:`CalcError` naming the file and key on bad input.

    The shared inputs are read here by their sections (:mod:`calc.sections`): the load cycle
    (typed, or derived from the moves and the mechanism or from a drive record), the motor and
    load, the gearbox; the further sections keep their tables for evaluation."""
    from .sections import FURTHER, TOP_KEYS, drive, duty, gearbox, motion

    path = Path(path)
    if path.is_dir():
        raise CalcError(f"{path}: expected a case file, found a directory")
    if not path.is_file():
        raise CalcError(f"{path}: the case file does not exist")
    raw = path.read_bytes()
    try:
        data = tomllib.loads(raw.decode("utf-8-sig"))  # an editor's byte-order mark is not TOML; catalogs accept one too
    except UnicodeDecodeError:
        raise CalcError(f"{path}: expected a UTF-8 TOML file, found bytes that are not UTF-8") from None
    except tomllib.TOMLDecodeError as exc:
        raise CalcError(f"{path}: TOML syntax error: {exc}") from None
    top = Table(path, "", data, TOP_KEYS)
    title = top.text("title", default=path.stem)
    control = next((ch for ch in title if unicodedata.category(ch) == "Cc"), None)
    if control is not None:
        # Refused, not escaped: the title goes to the terminal, the JSON and the LaTeX report, and
        # a control character (an escape sequence, a line break) means nothing in any of them.
        raise CalcError(f"{top.where('title')}: expected one line of printable text, found the control character U+{ord(control):04X}")
    case = Case(path=path, title=title, profile=None, raw=raw)
    derived = motion.derive(top)
    if derived is None:
        case.profile = duty.read(top)
    drive.read(top, case)
    if derived is not None:
        motion.apply(case, derived)  # after [load], whose inertia the mechanism gives instead
    gearbox.read(top, case)
    case.sections = {name: data[name] for name in FURTHER if name in data}
    return case
