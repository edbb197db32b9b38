"""The inputs a reviewer changes: one :class:`InputSpec` per input, and a case with inputs replaced.

An input is named by its key path in the case file (``motor.peak_torque``, ``profile[2].torque``
for the second segment, ``coupling.temperature``, ``mechanism.mass``, ``move[1].time``);
:func:`with_inputs` writes values at key paths into a copy of a case (a mechanism's or a move's
into the tables the motion was derived from, which derive it again). The panel's controls are
built from :func:`input_specs`, so a further input is one more line in :data:`SCALARS` or
:data:`MECHANISM` (or one more rule for a list of tables like ``profile`` or ``move``): its name
in the panel and the range of its slider; its kind, unit and symbol come from the key's
declaration in its section.
"""

from __future__ import annotations

import copy
import dataclasses
import math
import re
from dataclasses import dataclass

import numpy as np

from ..sections.case import Case, Key, Table
from ..domain.profile import Profile
from ..report.symbols import symbol_text
from ..sections import declared
from ..sections import motion as motion_section
from ..core.units import NUMBER, Q_, parse_quantity, pretty_unit

#: Key paths of the inputs that the case keeps as its own fields (the other sections keep their
#: tables raw until evaluated, so their key paths are written into those tables).
CASE_FIELDS = {
    "gearbox.ratio": "ratio",
    "motor.peak_torque": "motor_peak_torque",
    "motor.inertia": "motor_inertia",
    "load.inertia": "load_inertia",
}
_SEGMENT = re.compile(r"profile\[(\d+)\]\.(duration|torque)$")
#: Key paths of the tables a motion is derived from: ``mechanism.mass``, ``move[2].time``.
_MOTION = re.compile(r"(mechanism)\.(\w+)$|(move)\[(\d+)\]\.(\w+)$")


@dataclass(frozen=True)
class InputSpec:
    """One input of the panel: its key path in the case file, what it is, its unit, the range
    and step of its slider and its value in the case. ``options`` makes it a choice (the ratios
    of the catalog) instead of a slider."""

    key: str
    label: str
    unit: str
    low: float
    high: float
    step: float
    value: float
    options: tuple = ()
    exact: float | None = None  # the case's value where the slider's (``value``, on its step) rounds it

    def field_text(self, v: float) -> str:
        """A slider's value as its number field shows it: the case's own value where the slider
        stands at its rounding of it (so a field never shows 15000 for the 14804.4 kg used)."""
        return f"{self.exact:.10g}" if self.exact is not None and v == self.value else f"{v:g}"

    def is_case_value(self, v) -> bool:
        """Whether ``v`` is the case's value: the slider's rounding of it, or the value itself."""
        return v == self.value or (self.exact is not None and v == self.exact)

    @property
    def text(self) -> str:
        """The label with its unit, as the panel shows it: ``motor peak torque T_1B [N·m]``."""
        return f"{self.label} [{pretty_unit(self.unit)}]" if self.unit else self.label


def nice_step(span: float, pixels: int = 200) -> float:
    """A round step (1, 2 or 5 times a power of ten) of about one pixel of a slider ``pixels``
    wide over ``span``, so that a slider's values read as typed.

    >>> nice_step(300.0), nice_step(14.9), nice_step(1.0)
    (2.0, 0.1, 0.005)
    """
    raw = span / pixels
    power = 10.0 ** math.floor(math.log10(raw))
    return next(m * power for m in (1, 2, 5, 10) if m * power >= raw)


def _spec(key, label, unit, value, low, high, options=(), positive=False) -> InputSpec:
    step = nice_step(high - low)
    low = max(low, step) if positive else low  # a segment lasts some time, a mass is some
    on_step = lambda x: round(round(x / step) * step, 12)  # noqa: E731 (no 0.30000000000000004 in a field)
    if options:
        return InputSpec(key, label, unit, on_step(low), on_step(high), step, value, options)
    return InputSpec(key, label, unit, on_step(low), on_step(high), step, on_step(value), options, None if on_step(value) == value else value)


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
)


def input_label(key: Key, name: str) -> str:
    """What the panel calls an input: its name and the key's symbol (``motor peak torque T_1B``)."""
    return f"{name} {symbol_text(key.symbol)}" if key.symbol else name


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
MOVE_TIMES = (("time", "time t"), ("accel_time", "accel time t_a"), ("decel_time", "decel time t_d"), ("jerk_time", "jerk time t_j"))
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
    writes them (an input it leaves out, in the units of the rest of the mechanism)."""
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
        unit, v = ((inch_unit if inch_pound else key.unit), 0.0) if text is None else _as_written(text, key.kind, f"{where}.{key.name}")
        specs.append(_spec(f"mechanism.{key.name}", f"mechanism: {input_label(key, name)}", unit, v, *reach(v), positive=positive))
    for k, move in enumerate(tables["move"], start=1):
        where = f"{case.path}: move[{k}]"
        if "dwell" in move:
            unit, v = _as_written(move["dwell"], "time", f"{where}.dwell")
            specs.append(_spec(f"move[{k}].dwell", f"{k} dwell: time t", unit, v, 0.0, max(3 * v, float(Q_(1, "s").m_as(unit))), positive=True))
            continue
        unit, v = _as_written(move["distance"], case.motion.mechanism.distance_kind, f"{where}.distance")
        specs.append(_spec(f"move[{k}].distance", f"{k} move: distance s", unit, v, *_distance(v)))
        time = parse_quantity(move["time"], "time", f"{where}.time")
        for name, label in MOVE_TIMES:
            if name in move:
                unit, v = _as_written(move[name], "time", f"{where}.{name}")
            else:  # a ramp the file leaves out, at the value reading the file takes: decel as accel, no jerk
                unit, v = _as_written(move["accel_time"], "time", f"{where}.accel_time") if name == "decel_time" else ("s", 0.0)
            # The move's time up to three times; a ramp up to the whole move (beyond half of it the move is impossible).
            high = 3 * v if name == "time" else float(time.m_as(unit))
            specs.append(_spec(f"move[{k}].{name}", f"{k} move: {label}", unit, v, 0.0, high, positive=name != "jerk_time" or v > 0))
    return specs


#: Values a section takes when its file leaves them out (the coupling's temperature, E9).
DEFAULTS = {"coupling.temperature": "20 degC"}


def value_at(case: Case, key: str, unit: str, kind: str):
    """The case's value at ``key`` in ``unit`` (a float; a quantity of ``kind``), or None where the
    case does not give it."""
    if key in CASE_FIELDS:
        q = getattr(case, CASE_FIELDS[key])
        return None if q is None else float(q.m_as(unit))
    section, name = key.split(".", 1)
    table = case.sections.get(section)
    if table is None or (name not in table and key not in DEFAULTS):
        return None
    return float(parse_quantity(table.get(name, DEFAULTS.get(key)), kind, f"{case.path}: {key}").m_as(unit))


def is_inch_pound(unit: str) -> bool:
    """Whether ``unit`` is an inch-pound one (``lbf*in``, ``lb*in**2``, ``in``).

    >>> is_inch_pound("lbf*in"), is_inch_pound("N*m"), is_inch_pound("")
    (True, False, False)
    """
    return bool(unit) and _INCH_POUND.search(unit) is not None


def written_unit(case: Case, key: str) -> str | None:
    """The inch-pound unit the case file writes the value at ``key`` in (``"60 lbf*in"`` → ``lbf*in``),
    or None: the panel then offers it in its SI unit."""
    if key in CASE_FIELDS:
        q = getattr(case, CASE_FIELDS[key])
        unit = None if q is None else f"{q.units:~C}"
    else:
        section, name = key.split(".", 1)
        unit = _unit_of((case.sections.get(section) or {}).get(name))
    return unit if is_inch_pound(unit) else None


def segment_specs(case: Case) -> list[InputSpec]:
    """Each segment's duration and torque (a pause has no torque)."""
    specs, p = [], case.profile
    for k, (phase, t, T) in enumerate(zip(p.phases, p.durations.m_as("s"), p.torques.m_as("N*m")), start=1):
        specs.append(_spec(f"profile[{k}].duration", f"{k} {phase}: duration t", "s", t, 0.0, max(3 * t, 1.0), positive=True))
        if phase != "pause":
            specs.append(_spec(f"profile[{k}].torque", f"{k} {phase}: torque T_2", "N*m", T, *_torque_range(T)))
    return specs


def input_specs(case: Case, ratios=()) -> list[InputSpec]:
    """The inputs of ``case`` the panel offers, in the order it shows them: the ratio (a choice
    among ``ratios``, the catalog's); the mechanism's and the moves' where the case derives its
    load cycle from moves (:func:`motion_specs`), else each segment's duration and torque; then
    :data:`SCALARS` (but the load's inertia where the mechanism gives it)."""
    specs = []
    if case.ratio is not None:
        r = float(case.ratio.m_as(""))
        specs.append(_spec("gearbox.ratio", "gearbox ratio i", "", r, 0, 1, options=tuple(sorted({*ratios, r}))))
    moves = case.motion is not None and bool(case.motion.moves)
    specs += motion_specs(case) if moves else segment_specs(case)
    for path, name, reach in SCALARS:
        key = declared(path)
        unit = written_unit(case, path) or key.unit
        v = value_at(case, path, unit, key.kind)
        if v is not None and not (moves and path == "load.inertia"):  # the mechanism gives J_L
            specs.append(_spec(path, input_label(key, name), unit, v, *reach(v)))
    return specs


def with_inputs(case: Case, values: dict) -> Case:
    """A copy of ``case`` with the quantity ``values[key]`` at each key path (a pause's torque is
    ignored); the raw tables of further sections get the value written as text, so their readers
    check it as if it stood in the file.

    >>> from pathlib import Path
    >>> from calc.sections.case import read_case
    >>> case = read_case(Path(__file__).parents[2] / "cases" / "indexing-table.toml")
    >>> changed = with_inputs(case, {"profile[4].duration": Q_(3, "s"), "coupling.temperature": Q_(60, "degC")})
    >>> changed.profile.durations, changed.sections["coupling"]["temperature"], case.sections["coupling"]["temperature"]
    (<Quantity([0.15 0.2  0.15 3.  ], 'second')>, '60 degree_Celsius', '40 degC')

    The example derives its cycle from its motion; a changed segment makes the cycle a typed one:

    >>> with_inputs(case, {"motor.peak_torque": Q_(13, "N*m")}).motion is case.motion, changed.motion
    (True, None)

    A mechanism's or a move's input goes into the tables the motion was derived from, which derive
    it again as reading the file does (:func:`calc.sections.motion.derive`; eta and μ as bare numbers):

    >>> slower = with_inputs(case, {"move[1].time": Q_(1, "s")})
    >>> slower.motion.tables["move"][0]["time"], round(slower.motion.peak_speed.m_as("rpm"), 2), case.motion.tables["move"][0]["time"]
    ('1 second', 17.65, '0.5 s')
    """
    p = case.profile
    durations, torques = p.durations.m_as("s").copy(), p.torques.m_as("N*m").copy()
    fields, sections = {}, copy.deepcopy(case.sections)
    tables = copy.deepcopy(case.motion.tables) if case.motion is not None else {}
    moved = False
    for key, q in values.items():
        segment, motion = _SEGMENT.match(key), _MOTION.match(key)
        if motion:
            name = motion.group(2) or motion.group(5)
            table = tables["mechanism"] if motion.group(1) else tables["move"][int(motion.group(4)) - 1]
            table[name] = float(q.magnitude) if q.unitless else _text(q)  # eta and μ as the file writes them: bare numbers
            moved = True
        elif segment:
            k, what = int(segment.group(1)) - 1, segment.group(2)
            (durations if what == "duration" else torques)[k] = q.m_as("s" if what == "duration" else "N*m")
        elif key in CASE_FIELDS:
            fields[CASE_FIELDS[key]] = q
        else:
            section, name = key.split(".", 1)
            sections[section][name] = _text(q)
    segments = [
        (phase, Q_(durations[k], "s"), None if phase == "pause" else p.speeds[k], None if phase == "pause" else Q_(torques[k], "N*m"))
        for k, phase in enumerate(p.phases)
    ]
    profile = Profile.from_segments(segments, where=f"{case.path}: profile")
    same = np.allclose(durations, p.durations.m_as("s"), rtol=1e-9) and np.allclose(torques, p.torques.m_as("N*m"), rtol=1e-9)
    # Segments changed by hand are typed: the motion they were derived from no longer holds.
    changed = dataclasses.replace(case, profile=profile, motion=case.motion if same else None, sections=sections, **fields)
    if moved:  # the cycle derived again from the changed tables, as reading the file derives it
        motion_section.apply(changed, motion_section.derive(Table(case.path, "", tables, motion_section.TABLES)))
    return changed


def _text(q) -> str:
    """A quantity as a case file's text, in pint's own unit names, which it reads back."""
    return f"{q.magnitude:.12g} {q.units:D}"


def with_changes(case: Case, ratio=None, durations=None, torques=None, motor_peak_torque=None, motor_inertia=None,
                 load_inertia=None, temperature=None, applied_torque=None) -> Case:
    """A copy of ``case`` with the given inputs replaced (quantities; ``None`` keeps the case's):
    :func:`with_inputs` by name. ``durations`` and ``torques`` are quantity arrays over all segments.

    >>> from pathlib import Path
    >>> from calc.sections.case import read_case
    >>> case = read_case(Path(__file__).parents[2] / "cases" / "indexing-table.toml")
    >>> changed = with_changes(case, ratio=Q_(7, ""))
    >>> changed.ratio, case.ratio
    (<Quantity(7, 'dimensionless')>, <Quantity(10.0, 'dimensionless')>)
    """
    values = {"gearbox.ratio": ratio, "motor.peak_torque": motor_peak_torque, "motor.inertia": motor_inertia,
              "load.inertia": load_inertia, "coupling.temperature": temperature, "accuracy.applied_torque": applied_torque}
    # A further section's input is ignored where the case has no such section.
    values = {k: v for k, v in values.items() if v is not None and (k in CASE_FIELDS or k.split(".")[0] in case.sections)}
    for what, arrays in (("duration", durations), ("torque", torques)):
        if arrays is not None:
            values.update({f"profile[{k}].{what}": q for k, q in enumerate(arrays, start=1)})
    return with_inputs(case, values)
