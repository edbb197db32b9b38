"""The inputs a reviewer changes: one :class:`InputSpec` per input, and a case with inputs replaced.

An input is named by its key path in the case file (``motor.peak_torque``, ``profile[2].torque``
for the second segment, ``coupling.temperature``, ``mechanism.mass``, ``move[1].time``).
:func:`input_edits` writes values at key paths as edits of the case file's text
(:mod:`calc.review.edit`), which the case reader reads again, so a mechanism's or a move's value
derives the motion again as reading the file does; :func:`with_inputs` and :func:`with_changes`
give the case so changed. The panel's controls are built from :func:`input_specs`, so a further
input is one more line in :data:`SCALARS` or :data:`MECHANISM` (or one more rule for a list of
tables like ``profile`` or ``move``): its name in the panel and the range of its slider; its kind,
unit and symbol come from the key's declaration in its section. The values offered are those the
file writes: a value the reader derives or takes from a catalog is not an input.
"""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
from dataclasses import dataclass

import numpy as np

from ..core.errors import CalcError, as_found
from ..core.units import NUMBER, Q_, parse_quantity, pretty_unit
from ..report.page import INCH_POUND, SI_UNIT
from ..report.symbols import symbol_text
from ..sections import OWN_TABLES, axis, declared
from ..sections import motion as motion_section
from ..sections.case import Case, Key
from ..sections.gearbox import catalogs as gearbox_catalogs
from .edit import Edit, edited_case, value_text

#: A segment's input: ``profile[2].torque``.
_SEGMENT = re.compile(r"profile\[(\d+)\]\.(duration|torque)$")


@dataclass(frozen=True)
class InputSpec:
    """One input of the panel: its key path in the case file, what it is, its unit, the range
    and step of its slider and its value in the case.

    Parameters
    ----------
    key : str
        Its key path in the case file (``motor.peak_torque``, ``move[1].time``).
    label : str
        What the panel calls it, with its symbol (``motor peak torque T_1B``).
    unit : str
        Its unit as a case file writes it (``"N*m"``; ``""`` for a bare number or a choice).
    low, high : float
        The ends of its slider [``unit``].
    step : float
        The slider's step [``unit``].
    value : float or str
        Its value in the case [``unit``], on the slider's step; a choice's option.
    options : tuple
        The choices (the ratios of the catalog, the parts to force); a choice instead of a slider
        where given.
    exact : float, optional
        The case's value where the slider's (``value``, on its step) rounds it [``unit``].
    default : str, optional
        Where the file leaves the input out: what its value follows, in words (``follows the
        accel time t_a``); None where the file writes it.
    follows : str, optional
        The key path of the input whose value it takes while the file leaves it out and the
        reviewer has not set it (a move's decel time follows its accel time).
    """

    key: str
    label: str
    unit: str
    low: float
    high: float
    step: float
    value: float
    options: tuple = ()
    exact: float | None = None
    default: str | None = None
    follows: str | None = None

    def shown_text(self, value) -> str:
        """The value as the input's field shows it: a choice by its option's text, a number by
        :meth:`field_text`.

        Parameters
        ----------
        value : float or str
            The value [``unit``], or a choice.

        Returns
        -------
        str
            The field's text.
        """
        return option_text(value) if self.options else self.field_text(value)

    def field_text(self, v: float) -> str:
        """A slider's value as its number field shows it: the case's own value where the slider
        stands at its rounding of it (so a field never shows 15000 for the 14804.4 kg used).

        Parameters
        ----------
        v : float
            The slider's value [``unit``].

        Returns
        -------
        str
            The field's text.

        Examples
        --------
        >>> spec = InputSpec("mechanism.mass", "mechanism: moved mass m", "kg", 0, 20000, 100, 14800, exact=14804.4)
        >>> spec.field_text(14800), spec.field_text(15000)
        ('14804.4', '15000')
        """
        return f"{self.exact:.10g}" if self.exact is not None and v == self.value else f"{v:g}"

    def is_case_value(self, v) -> bool:
        """Whether ``v`` is the case's value: the slider's rounding of it, or the value itself.

        Parameters
        ----------
        v : float or str
            A value of the input [``unit``], or a choice.

        Returns
        -------
        bool
            True for the case's value.
        """
        return v == self.value or (self.exact is not None and v == self.exact)

    def in_unit(self, unit: str) -> InputSpec:
        """The input as its field shows it in another unit of its dimension (:func:`unit_shown`): its
        range, step and value converted; the slider and the state keep the file's unit.

        Parameters
        ----------
        unit : str
            The unit shown.

        Returns
        -------
        InputSpec
            This input where the unit is its own or it is a choice; else a copy in ``unit``.

        Examples
        --------
        >>> spec = InputSpec("mechanism.mass", "mechanism: moved mass m", "kg", 0.5, 100, 0.5, 45.36)
        >>> shown = spec.in_unit("lb")
        >>> shown.unit, round(shown.value, 3), round(shown.high, 2)
        ('lb', 100.002, 220.46)
        """
        if unit == self.unit or self.options:
            return self
        f = unit_factor(self.unit, unit)
        exact = self.value if self.exact is None else self.exact
        return dataclasses.replace(self, unit=unit, low=self.low * f, high=self.high * f, step=self.step * f,
                                   value=self.value * f, exact=exact * f)

    @property
    def text(self) -> str:
        """The label with its unit, as the panel shows it: ``motor peak torque T_1B [N·m]``."""
        return f"{self.label} [{pretty_unit(self.unit)}]" if self.unit else self.label


def option_text(value) -> str:
    """A choice's value as the page shows it: a ratio as ``8``, a part by its name.

    Parameters
    ----------
    value : float or str
        A ratio [-] or a part's name.

    Returns
    -------
    str
        The option's text.
    """
    return value if isinstance(value, str) else f"{value:g}"


def nice_step(span: float, pixels: int = 200) -> float:
    """A round step (1, 2 or 5 times a power of ten) of about one pixel of a slider, so that a
    slider's values read as typed.

    Parameters
    ----------
    span : float
        The slider's range, its high end less its low [the input's unit].
    pixels : int
        The slider's width [px].

    Returns
    -------
    float
        The step [the input's unit], at least ``span / pixels``.

    Examples
    --------
    >>> nice_step(300.0), nice_step(14.9), nice_step(1.0)
    (2.0, 0.1, 0.005)
    """
    raw = span / pixels
    power = 10.0 ** math.floor(math.log10(raw))
    return next(m * power for m in (1, 2, 5, 10) if m * power >= raw)


def _spec(key, label, unit, value, low, high, options=(), positive=False, default=None, follows=None) -> InputSpec:
    step = nice_step(high - low)
    low = max(low, step) if positive else low  # a segment lasts some time, a mass is some
    on_step = lambda x: round(round(x / step) * step, 12)  # noqa: E731 (no 0.30000000000000004 in a field)
    if options:
        return InputSpec(key, label, unit, on_step(low), on_step(high), step, value, options)
    exact = None if on_step(value) == value else value
    return InputSpec(key, label, unit, on_step(low), on_step(high), step, on_step(value), options, exact, default,
                     follows)


def _torque_range(t: float) -> tuple[float, float]:
    """From zero to twice the torque on its own side (a segment's torque keeps its sign), at least ±10."""
    reach = max(2 * abs(t), 10.0)
    return (-reach, 0.0) if t < 0 else (0.0, reach)


def _scaled(v: float) -> tuple[float, float]:
    """A tenth to five times the case's value (inertias, peak torque)."""
    return v / 10, 5 * v


def _temperature(_v: float) -> tuple[float, float]:
    from ..domain.coupling import TEMPERATURE_FACTORS  # the slider ends at the table's top (E9)

    return -20.0, TEMPERATURE_FACTORS.top


#: The single-valued inputs, where the case gives them: key path, what the panel calls it, and the
#: rule of its slider's range; its kind, unit and symbol are the key's declaration
#: (:func:`calc.sections.declared`).
SCALARS = (
    ("motor.peak_torque", "motor peak torque", _scaled),
    ("motor.inertia", "motor inertia", _scaled),
    ("load.inertia", "load inertia", _scaled),
    ("coupling.temperature", "coupling temperature", _temperature),
    ("accuracy.applied_torque", "applied torque", lambda t: (0.0, max(5 * t, 10.0))),
    ("drive.brake_resistor.resistance", "brake resistor", _scaled),
    ("drive.brake_resistor.continuous_power", "brake resistor's continuous power", _scaled),
    ("drive.brake_resistor.peak_power", "brake resistor's peak power", _scaled),
)


def input_label(key: Key, name: str) -> str:
    """What the panel calls an input: its name and the key's symbol.

    Parameters
    ----------
    key : calc.sections.case.Key
        The key's declaration in its section (its symbol).
    name : str
        What the panel calls it (``"motor peak torque"``).

    Returns
    -------
    str
        ``"motor peak torque T_1B"``; the name alone for a key without a symbol. A symbol of two subscripts is
        written as the results write it, ``P_R,peak`` (so that it is typeset, not shown as a key).
    """
    if not key.symbol:
        return name
    base, sep, sub = symbol_text(key.symbol).partition("_")
    return f"{name} {base}{sep}{sub.replace('_', ',')}"


def _signed(v: float, floor: float = 10.0) -> tuple[float, float]:
    """From zero to five times the value on its own side, at least ``floor`` (a force or torque
    that may be left out, so zero)."""
    reach = max(5 * abs(v), floor)
    return (-reach, 0.0) if v < 0 else (0.0, reach)


def _distance(v: float) -> tuple[float, float]:
    """Five times a move's distance either way, so a move can be reversed (zero is refused when the
    moves are read: a pause is a dwell)."""
    return -5 * abs(v), 5 * abs(v)


#: The inputs of a mechanism (its keys, :data:`calc.sections.motion.MECHANISM`): what the panel
#: calls it, its inch-pound unit where the file leaves it out, the rule of its slider's range,
#: and whether it is above zero. The radius and own inertia follow the type (``OWN_KEYS``).
MECHANISM = {
    "inertia": ("load inertia", "lb*in**2", _scaled, True),
    "friction_torque": ("friction torque", "lbf*in", _signed, False),
    "process_torque": ("process torque", "lbf*in", _signed, False),
    "mass": ("moved mass", "lb", _scaled, True),
    "friction_coefficient": ("friction coefficient", "", lambda v: (0.0, max(5 * v, 0.2)), False),
    "incline": ("incline", "deg", lambda _v: (-90.0, 90.0), False),
    "force": ("process force", "lbf", _signed, False),
    "eta": ("efficiency", "", lambda _v: (0.5, 1.0), True),
    "counterweight": ("counterweight", "lb", _signed, False),
    "drag_torque": ("drag torque", "lbf*in", _signed, False),
    "lead": ("screw lead", "in", _scaled, True),
    "pitch_diameter": ("pinion pitch diameter", "in", _scaled, True),
    "pulley_diameter": ("pulley diameter", "in", _scaled, True),
    **{own: (f"{what} inertia", "lb*in**2", _signed, False)
       for own, what in (("screw_inertia", "screw"), ("pinion_inertia", "pinion"), ("pulley_inertia", "pulley"))},
}
#: A move's inputs: its time, and its ramps within it (so a ramp can be made too long for the move).
MOVE_TIMES = (("time", "time t"), ("accel_time", "accel time t_a"), ("decel_time", "decel time t_d"),
              ("jerk_time", "jerk time t_j"))
_INCH_POUND = re.compile(r"\b(in|inch|ft|foot|lb|lbf|pound|pound_force|oz)\b")


def _unit_of(text) -> str:
    """The unit a case file writes a value in (``"1.000 in"`` → ``in``; a bare number: none)."""
    return "" if not isinstance(text, str) else NUMBER.match(text).group(2)


def _as_written(text, kind: str, where: str) -> tuple[str, float]:
    """A case file's value (read as its reader reads it) as its unit and its number in that unit."""
    unit = _unit_of(text)
    return unit, float(parse_quantity(text, kind, where).m_as(unit))


def motion_specs(case: Case) -> list[InputSpec]:
    """The inputs of a case whose load cycle is derived from moves: its mechanism's, then each
    move's distance (either way), time and ramps (accel, decel and jerk time, those the file leaves
    out at the values reading it takes), and each dwell; in the units the file
    writes them (an input it leaves out, in the units of the rest of the mechanism).

    Parameters
    ----------
    case : calc.sections.case.Case
        A case whose motion derives its load cycle from moves.

    Returns
    -------
    list of InputSpec
        The mechanism's inputs (key paths ``mechanism.<key>``), then each entry's of the moves
        (``move[k].<key>``), in the file's order.
    """
    tables = case.motion.tables
    mechanism = tables["mechanism"]
    where = f"{case.path}: mechanism"
    inch_pound = any(is_inch_pound(_unit_of(v)) for k, v in mechanism.items() if k in MECHANISM)
    specs = []
    for key in motion_section.keys_of(mechanism["type"]):
        if key.name not in MECHANISM:
            continue
        name, inch_unit, reach, positive = MECHANISM[key.name]
        text = mechanism.get(key.name)
        if text is None:
            unit, v = (inch_unit if inch_pound else key.unit), 0.0
        else:
            unit, v = _as_written(text, key.kind, f"{where}.{key.name}")
        label = f"mechanism: {input_label(key, name)}"
        default = None if text is not None else "left out of the file: none (0)"
        specs.append(_spec(f"mechanism.{key.name}", label, unit, v, *reach(v), positive=positive, default=default))
    for k, move in enumerate(tables["move"], start=1):
        where = f"{case.path}: move[{k}]"
        if "dwell" in move:
            unit, v = _as_written(move["dwell"], "time", f"{where}.dwell")
            high = max(3 * v, float(Q_(1, "s").m_as(unit)))
            specs.append(_spec(f"move[{k}].dwell", f"{k} dwell: time t", unit, v, 0.0, high, positive=True))
            continue
        unit, v = _as_written(move["distance"], case.motion.mechanism.distance_kind, f"{where}.distance")
        specs.append(_spec(f"move[{k}].distance", f"{k} move: distance s", unit, v, *_distance(v)))
        time = parse_quantity(move["time"], "time", f"{where}.time")
        for name, label in MOVE_TIMES:
            default = follows = None
            if name in move:
                unit, v = _as_written(move[name], "time", f"{where}.{name}")
            # A ramp the file leaves out, at the value reading the file takes: decel as accel, no jerk.
            elif name == "decel_time":
                unit, v = _as_written(move["accel_time"], "time", f"{where}.accel_time")
                default, follows = "left out of the file: follows the accel time t_a", f"move[{k}].accel_time"
            else:
                unit, v = "s", 0.0
                default = "left out of the file: 0 s, no jerk"
            # The move's time up to three times; a ramp up to the whole move (beyond half of it the move is impossible).
            high = 3 * v if name == "time" else float(time.m_as(unit))
            positive = name != "jerk_time" or v > 0
            specs.append(_spec(f"move[{k}].{name}", f"{k} move: {label}", unit, v, 0.0, high, positive=positive,
                               default=default, follows=follows))
    return specs


#: Values a section takes when its file leaves them out (the coupling's temperature, E9).
DEFAULTS = {"coupling.temperature": "20 degC"}


def unit_shown(unit: str, system: str) -> str:
    """The unit an input's field shows in a unit system: its SI or inch-pound counterpart, else its own
    (seconds, degrees, a temperature, a bare number).

    Parameters
    ----------
    unit : str
        The input's unit as the case file writes it.
    system : str
        ``"SI"`` or ``"inch-pound"``.

    Returns
    -------
    str
        The unit shown.

    Examples
    --------
    >>> unit_shown("kg*cm**2", "inch-pound"), unit_shown("lbf*in", "SI"), unit_shown("s", "inch-pound")
    ('lb*in**2', 'N*m', 's')
    """
    return INCH_POUND.get(unit, unit) if system == "inch-pound" else SI_UNIT.get(unit, unit)


def unit_factor(unit: str, shown: str) -> float:
    """What a value in ``unit`` is multiplied by to be in ``shown``: no unit of an input offsets its zero
    (the temperatures an input takes are shown in their own unit in both systems).

    Parameters
    ----------
    unit : str
        The input's unit as the case file writes it.
    shown : str
        The unit its field shows (:func:`unit_shown`).

    Returns
    -------
    float
        The factor [shown / unit].

    Examples
    --------
    >>> round(unit_factor("kg*cm**2", "lb*in**2"), 5)
    0.34172
    """
    return float(Q_(1.0, unit).m_as(shown))


def is_inch_pound(unit: str) -> bool:
    """Whether ``unit`` is an inch-pound one (``lbf*in``, ``lb*in**2``, ``in``).

    Parameters
    ----------
    unit : str
        A unit as a case file writes it, or ``""``.

    Returns
    -------
    bool
        True where it names an inch or pound unit.

    Examples
    --------
    >>> is_inch_pound("lbf*in"), is_inch_pound("N*m"), is_inch_pound("")
    (True, False, False)
    """
    return bool(unit) and _INCH_POUND.search(unit) is not None


def file_tables(case: Case) -> dict:
    """The tables of the case's file as its text writes them (a value the reader derives, takes
    from a catalog or defaults is not there).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read (its file's text).

    Returns
    -------
    dict
        The parsed TOML (tomllib).
    """
    return tomllib.loads(case.raw.decode("utf-8-sig"))


def segment_specs(case: Case) -> list[InputSpec]:
    """Each segment's duration and torque (a pause has no torque).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case (its load cycle, typed or derived).

    Returns
    -------
    list of InputSpec
        ``profile[k].duration`` [s] and, but for a pause, ``profile[k].torque`` [N*m] of each segment.
    """
    specs, p = [], case.profile
    for k, (phase, t, T) in enumerate(zip(p.phases, p.durations.m_as("s"), p.torques.m_as("N*m")), start=1):
        label = f"{k} {phase}: duration t"
        specs.append(_spec(f"profile[{k}].duration", label, "s", t, 0.0, max(3 * t, 1.0), positive=True))
        if phase != "pause":
            specs.append(_spec(f"profile[{k}].torque", f"{k} {phase}: torque T_2", "N*m", T, *_torque_range(T)))
    return specs


def input_specs(case: Case, ratios=()) -> list[InputSpec]:
    """The inputs of ``case`` the panel offers, in the order it shows them: the ratio; the
    mechanism's and the moves' where the case derives its load cycle from moves
    (:func:`motion_specs`), else each segment's duration and torque; then those of
    :data:`SCALARS` the file gives, each in its SI unit or in the inch-pound unit the file writes
    it in.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    ratios : sequence of float
        The ratios offered [-] (the catalog's, :func:`catalog_ratios`), the case's among them.

    Returns
    -------
    list of InputSpec
        The inputs; the ratio a choice, the others sliders.
    """
    specs = []
    if case.ratio is not None:
        r = float(case.ratio.m_as(""))
        specs.append(_spec("gearbox.ratio", "gearbox ratio i", "", r, 0, 1, options=tuple(sorted({*ratios, r}))))
    moves = case.motion is not None and bool(case.motion.moves)
    specs += motion_specs(case) if moves else segment_specs(case)
    tables = file_tables(case)
    for path, name, reach in SCALARS:
        key = declared(path)
        *tables_in, entry = path.split(".")
        table = tables
        for name_in in tables_in:  # a key of an inline table: drive.brake_resistor.resistance
            table = table.get(name_in) if isinstance(table, dict) else None
        given = table.get(entry) if isinstance(table, dict) else None
        text = table.get(entry, DEFAULTS.get(path)) if isinstance(table, dict) else None
        if text is not None:
            unit = _unit_of(text) if is_inch_pound(_unit_of(text)) else key.unit
            v = float(parse_quantity(text, key.kind, f"{case.path}: {path}").m_as(unit))
            default = None if given is not None else f"left out of the file: {text}, the default"
            specs.append(_spec(path, input_label(key, name), unit, v, *reach(v), default=default))
    return specs


#: The gearbox or motor choice that leaves the part to the selection (``part`` not given).
SELECTION = "the selection's"


def catalog_ratios(case: Case) -> list[float]:
    """The ratios of the case's gearbox catalog (the choices of the ratio control).

    Parameters
    ----------
    case : calc.sections.case.Case
        A case with a gearbox.

    Returns
    -------
    list of float
        The distinct ratios [-], ascending.
    """
    return sorted(set(gearbox_catalogs(case)[0]["ratio"].m_as("").tolist()))


def forced_spec(case: Case, key: str) -> InputSpec:
    """The part the reviewer forces at ``key``, checked alone: the gearbox (``gearbox.part``)
    among the catalog's rows at the case's ratio, or the motor (``motor.part``) among the motor
    catalog's rows; the partial rows are never offered; or the selection's.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case (its catalogs, its ratio and the parts it names).
    key : str
        ``"gearbox.part"`` or ``"motor.part"``.

    Returns
    -------
    InputSpec
        A choice; its value the part the case names, else :data:`SELECTION`.
    """
    if key == "gearbox.part":
        catalog, given = gearbox_catalogs(case)[0], case.gearbox_part
        offered = (catalog["ratio"].m_as("") == float(case.ratio.m_as(""))) & ~catalog.partial
    else:
        catalog, given = axis.motor_catalog(case), case.motor_part
        offered = ~catalog.partial
    value = given or SELECTION
    parts = [str(p) for p, shown in zip(catalog.parts, offered) if shown]
    options = tuple(dict.fromkeys([SELECTION, *parts, value]))
    return InputSpec(key, f"{key.split('.')[0]} part forced", "", 0, 0, 0, value, options)


def review_specs(case: Case) -> list[InputSpec]:
    """The panel's inputs of ``case``: :func:`input_specs` (the ratio among the catalog's), then
    the parts to force (:func:`forced_spec`).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.

    Returns
    -------
    list of InputSpec
        The inputs, the gearbox's part (where the case has a gearbox) and the motor's (where it
        has a motor catalog) last.
    """
    ratios = catalog_ratios(case) if case.ratio is not None else []
    return (input_specs(case, ratios) + ([forced_spec(case, "gearbox.part")] if case.ratio is not None else [])
            + ([forced_spec(case, "motor.part")] if case.motor_catalog is not None else []))


#: A number as a reviewer types it: digits with a point or a decimal comma (``0,6``), a sign, an exponent.
TYPED = re.compile(r"^[-+]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][-+]?\d+)?$")


def read_typed(text: str, spec: InputSpec) -> float:
    """The number a reviewer typed into the field of ``spec``: a decimal comma is read as a point;
    not a number, or outside the input's range, is refused with a sentence saying why (never
    clamped).

    Parameters
    ----------
    text : str
        The field's text.
    spec : InputSpec
        The input.

    Returns
    -------
    float
        The value [``spec.unit``]; a text refused raises :class:`calc.core.errors.CalcError`.

    Examples
    --------
    >>> spec = InputSpec("move[1].time", "1 move: time t", "s", 0.05, 1.5, 0.01, 0.5)
    >>> read_typed(" 0,6 ", spec)
    0.6
    >>> read_typed("2", spec)
    Traceback (most recent call last):
    ...
    calc.core.errors.CalcError: 2 s is outside the range of 1 move: time t, 0.05 s to 1.5 s: not applied
    """
    t = text.strip()
    unit = f" {pretty_unit(spec.unit)}" if spec.unit else ""
    if not TYPED.match(t):
        raise CalcError(f"{as_found(t)} is not a number: expected a number such as {spec.value:g} "
                        f"(in{unit or ' no unit'}), "
                        "a decimal point or comma; not applied")
    v = float(t.replace(",", "."))
    if not math.isfinite(v) or not spec.low <= v <= spec.high:
        raise CalcError(f"{t}{unit} is outside the range of {spec.label}, {spec.low:g}{unit} to {spec.high:g}{unit}: "
                        "not applied")
    return v


def input_edits(case: Case, changes: dict) -> list[Edit]:
    """The edits of the case file of ``case`` that write ``changes``: key path -> (number, unit)
    (a bare number where the unit is ""), a part's name, or None (the key taken out). A segment
    changed where the case derives its load cycle (from moves or a drive record) makes it a typed
    one first (:func:`typed_cycle`).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read (its file's text is what is edited).
    changes : dict
        Key path -> (number [unit], unit), a part's name, or None.

    Returns
    -------
    list of calc.review.edit.Edit
        The edits, in the order of ``changes`` (those typing the cycle first).

    Examples
    --------
    >>> from pathlib import Path
    >>> from calc.sections.case import read_case
    >>> case = read_case(Path(__file__).parents[2] / "cases" / "indexing-table.toml")
    >>> changes = {"move[1].time": (0.6, "s"), "gearbox.ratio": (8.0, ""), "gearbox.part": "NPT025-8"}
    >>> for edit in input_edits(case, changes):
    ...     print(edit)
    Edit(key='move[1].time', value='0.6 s', insert=False)
    Edit(key='gearbox.ratio', value=8.0, insert=False)
    Edit(key='gearbox.part', value='NPT025-8', insert=False)
    """
    typed = case.motion is not None and any(_SEGMENT.match(key) for key in changes)
    edits = typed_cycle(case) if typed else []
    for key, change in changes.items():
        if change is not None and not isinstance(change, str):
            number, unit = change
            change = value_text(number, unit) if unit else float(number)
        edits.append(Edit(key, change))
    return edits


def typed_cycle(case: Case) -> list[Edit]:
    """The edits that type the load cycle ``case`` derives: every segment written as a
    ``[[profile]]`` table, the moves, the drive record and the mechanism taken out, and the load's
    inertia the mechanism gave written into ``[load]``.

    Parameters
    ----------
    case : calc.sections.case.Case
        A case whose motion derives its load cycle.

    Returns
    -------
    list of calc.review.edit.Edit
        Durations [s], speeds [rpm] and torques [N*m] as written.
    """
    p, rows = case.profile, []
    for phase, t, n, T in zip(p.phases, p.durations.m_as("s"), p.speeds.m_as("rpm"), p.torques.m_as("N*m")):
        rows.append({"phase": phase, "duration": value_text(t, "s")}
                    | ({} if phase == "pause" else {"speed": value_text(n, "rpm"), "torque": value_text(T, "N*m")}))
    tables = file_tables(case)
    edits = [Edit(name, None) for name in (*motion_section.FORMS, "mechanism") if name in tables]
    edits.append(Edit("profile", rows))
    if case.motion.J_L is not None:
        load = [] if "load" in tables else [Edit("load", {})]
        edits += load + [Edit("load.inertia", value_text(case.motion.J_L.m_as("kg*cm**2"), "kg*cm**2"))]
    return edits


def with_inputs(case: Case, values: dict) -> Case:
    """``case`` read again from its text with the quantity ``values[key]`` written at each key
    path (a part's name as its text, None taking the key or table out; a pause's torque, and a
    segment's value as the case has it, are left out): :func:`input_edits`, so each value is
    checked as if it stood in the file. What ``case`` holds beside its file's text (a value set in
    code, the motor an evaluation chose) is not in the copy: name it in the text (``motor.part``).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    values : dict
        Key path -> a quantity of the key's kind, a part's name (str), or None.

    Returns
    -------
    calc.sections.case.Case
        The changed case; a value the file cannot take raises :class:`calc.core.errors.CalcError`.

    Examples
    --------
    >>> from pathlib import Path
    >>> from calc.sections.case import read_case
    >>> case = read_case(Path(__file__).parents[2] / "cases" / "indexing-table.toml")
    >>> changed = with_inputs(case, {"profile[4].duration": Q_(3, "s"), "coupling.temperature": Q_(60, "degC")})
    >>> changed.profile.durations, changed.sections["coupling"]["temperature"], case.sections["coupling"]["temperature"]
    (<Quantity([0.15 0.2  0.15 3.  ], 'second')>, '60 degree_Celsius', '40 degC')

    The example derives its cycle from its motion; a changed segment makes the cycle a typed one,
    with the load's inertia its mechanism gave:

    >>> changed.motion, changed.load_inertia, case.load_inertia
    (None, <Quantity(1500.0, 'kilogram * centimeter ** 2')>, <Quantity(1500.0, 'kilogram * centimeter ** 2')>)

    A mechanism's or a move's input goes into the tables the motion is derived from, which derive
    it again as reading the file does (:func:`calc.sections.motion.derive`; eta and μ as bare numbers):

    >>> slower = with_inputs(case, {"move[1].time": Q_(1, "s")})
    >>> slower.motion.tables["move"][0]["time"], case.motion.tables["move"][0]["time"]
    ('1 second', '0.5 s')
    >>> round(slower.motion.peak_speed.m_as("rpm"), 2)
    17.65
    """
    p, changes = case.profile, {}
    for key, q in values.items():
        segment = _SEGMENT.match(key)
        if segment:
            k, what = int(segment.group(1)) - 1, segment.group(2)
            was = (p.durations if what == "duration" else p.torques)[k]
            if (what == "torque" and p.phases[k] == "pause") or np.isclose(q.m_as(was.units), was.magnitude, rtol=1e-9):
                continue  # a pause has no torque; a value as the case has it changes nothing
        unit = "" if q is None or isinstance(q, str) or q.unitless else f"{q.units:D}"
        changes[key] = q if q is None or isinstance(q, str) else (float(q.magnitude), unit)
    return edited_case(case.path, case.raw.decode("utf-8-sig"), input_edits(case, changes))


def with_changes(case: Case, ratio=None, durations=None, torques=None, motor_peak_torque=None, motor_inertia=None,
                 load_inertia=None, temperature=None, applied_torque=None) -> Case:
    """A copy of ``case`` with the given inputs replaced (quantities; ``None`` keeps the case's):
    :func:`with_inputs` by name. An input of a section with a table of its own (coupling, accuracy:
    :data:`calc.sections.OWN_TABLES`) the case's file does not have is left out.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    ratio : pint.Quantity [1], optional
        The gearbox ratio i.
    durations : pint.Quantity [s], optional
        Every segment's duration, in order.
    torques : pint.Quantity [N·m], optional
        Every segment's output torque, in order (a pause's is left out).
    motor_peak_torque : pint.Quantity [N·m], optional
        The motor's peak torque T_1B.
    motor_inertia : pint.Quantity [kg·cm²], optional
        The motor's inertia J_motor.
    load_inertia : pint.Quantity [kg·cm²], optional
        The load's inertia J_L.
    temperature : pint.Quantity [degC], optional
        The coupling's temperature.
    applied_torque : pint.Quantity [N·m], optional
        The accuracy chain's applied torque.

    Returns
    -------
    calc.sections.case.Case
        The changed case (:func:`with_inputs`).

    Examples
    --------
    >>> from pathlib import Path
    >>> from calc.sections.case import read_case
    >>> case = read_case(Path(__file__).parents[2] / "cases" / "indexing-table.toml")
    >>> changed = with_changes(case, ratio=Q_(7, ""))
    >>> changed.ratio, case.ratio
    (<Quantity(7.0, 'dimensionless')>, <Quantity(10.0, 'dimensionless')>)
    """
    values = {"gearbox.ratio": ratio, "motor.peak_torque": motor_peak_torque, "motor.inertia": motor_inertia,
              "load.inertia": load_inertia, "coupling.temperature": temperature,
              "accuracy.applied_torque": applied_torque}
    # The input of a section with a table of its own is ignored where the case's file has no such table.
    tables = file_tables(case)
    values = {k: v for k, v in values.items() if v is not None
              and (k.split(".")[0] in tables or k.split(".")[0] not in OWN_TABLES)}
    for what, arrays in (("duration", durations), ("torque", torques)):
        if arrays is not None:
            values.update({f"profile[{k}].{what}": q for k, q in enumerate(arrays, start=1)})
    return with_inputs(case, values)
