"""The load cycle derived instead of typed (``docs/case-format.md``, "Motion and mechanism"):
the moves of the load (``[[move]]``) through its mechanism (``[mechanism]``), or a time series a
drive recorded (``[drive_record]``), sampled at the gearbox output
(:class:`calc.domain.cycle.SampledCycle`) and cut into the seed's segments, which the duty section
uses as if they were typed."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from .case import Case, Declared, Key, Table, key_names
from ..data.catalog import Column
from ..domain.cycle import PHASES, SampledCycle
from ..core.errors import CalcError, listing, as_found
from ..data.measurement import measurement_path, read_measurement
from ..domain.inertia import FORMULAS, SHAPES, Body
from ..domain.mechanism import TYPES, Mechanism, phi_2
from ..domain.motion import Move, Samples, alpha_2max, omega_2max, record_samples, sample
from ..domain.motor import OutputLoad
from ..domain.profile import Profile, segments
from ..core.units import Q_, Value, kind_phrase, parse_quantity
from .common import json_of
from .protocol import Result, Section

NAME = "motion"
ORDER = 20
#: Per linear type: the key of its radius (a lead or a diameter) and of its own inertia.
OWN_KEYS = {"ball-screw": ("lead", "screw_inertia"), "rack-pinion": ("pitch_diameter", "pinion_inertia"),
            "belt": ("pulley_diameter", "pulley_inertia")}
_LINEAR = tuple(OWN_KEYS)
#: The keys of a body of the load ([[mechanism.body]], :class:`calc.domain.inertia.Body`): the dimension
#: each key gives, by its formula name.
BODY_KEYS = (
    Key("shape", "choice", "cylinder | hollow-cylinder | plate"),
    Key("diameter", "length", "outer diameter (a cylinder)", "D", unit="mm"),
    Key("inner_diameter", "length", "inner diameter (a hollow cylinder)", "d_i", unit="mm"),
    Key("length", "length", "length along the axis of rotation (a plate's thickness)", "L", unit="mm"),
    Key("width", "length", "side of a plate across the axis", "a", unit="mm"),
    Key("depth", "length", "other side of a plate across the axis", "b", unit="mm"),
    Key("mass", "mass", "mass of the body (or its density)", "m", unit="kg"),
    Key("density", "density", "density of its material (or its mass)", "rho", unit="kg/m**3"),
    Key("offset", "length", "distance of its own axis from the axis of rotation (the parallel-axis term)", "e",
        "0 mm", "mm"),
)
BODY_DIMENSIONS = {"diameter": "D", "inner_diameter": "d_i", "length": "L", "width": "a", "depth": "b"}
MECHANISM = Declared("mechanism", (
    Key("type", "choice", "rotary | ball-screw | rack-pinion | belt; the type says which keys below it takes"),
    Key("holding_brake", "flag", "a brake holds the load in the dwells (no torque there)", default=False),
    Key("inertia", "inertia", "inertia of the load at the gearbox output (with bodies: besides them)", "J_L",
        unit="kg*cm**2", only=("rotary",)),
    Key("body", "tables", "bodies of the load whose inertia the geometry gives, added to inertia ([[mechanism.body]])",
        only=("rotary",), keys=BODY_KEYS),
    Key("friction_torque", "torque", "friction torque of the table, against the motion while it moves", "T_f",
        "0 N*m", "N*m", ("rotary",)),
    Key("process_torque", "torque", "process torque, against the motion while it moves", "T_p", "0 N*m", "N*m",
        ("rotary",)),
    Key("mass", "mass", "moved mass", "m", unit="kg", only=_LINEAR),
    Key("friction_coefficient", "dimensionless", "friction coefficient of the guide", "mu", 0, only=_LINEAR),
    Key("incline", "angle", "incline of the axis (90°: vertical, up is forwards)", "theta", "0 deg", "deg", _LINEAR),
    Key("force", "force", "process force, against the motion while it moves", "F_p", "0 N", "N", _LINEAR),
    Key("eta", "dimensionless", "efficiency of the mechanism, above 0 and at most 1", "eta", only=_LINEAR),
    Key("counterweight", "mass", "counterweight on a rope over the same lead or radius, travelling the other way: "
        "its mass accelerates with the load, its weight pulls against the load's", "m_c", "0 kg", "kg", _LINEAR),
    Key("drag_torque", "torque", "drag torque at the screw, pinion or pulley shaft (preload, seals), against the "
        "motion while it moves, outside the efficiency", "T_d", "0 N*m", "N*m", _LINEAR),
    Key("reverse_efficiency", "dimensionless", "efficiency of the screw driven back by the load, above 0 and at "
        "most 1 (default: 2 − 1/eta, at most 0 for eta at most 0.5: self-locking)", "eta_reverse",
        only=("ball-screw",)),
    Key("lead", "length", "lead of the screw: travel per revolution", "p", unit="mm", only=("ball-screw",)),
    Key("screw_inertia", "inertia", "own inertia of the screw", "J_M", "0 kg*m**2", "kg*cm**2", ("ball-screw",)),
    Key("pitch_diameter", "length", "pitch diameter of the pinion", "d", unit="mm", only=("rack-pinion",)),
    Key("pinion_inertia", "inertia", "own inertia of the pinion", "J_M", "0 kg*m**2", "kg*cm**2", ("rack-pinion",)),
    Key("pulley_diameter", "length", "diameter of the pulley", "d", unit="mm", only=("belt",)),
    Key("pulley_inertia", "inertia", "own inertia of the pulley", "J_M", "0 kg*m**2", "kg*cm**2", ("belt",)),
), "the mechanism between the load and the gearbox output")
MOVE = Declared("move", (
    Key("distance", "distance", "distance of the move; negative: back", "phi_2"),
    Key("time", "time", "time of the move", "t_m", unit="s"),
    Key("accel_time", "time", "acceleration time (a trapezoid; accel + decel = time is a triangle)", "t_a", unit="s"),
    Key("decel_time", "time", "deceleration time (default: accel_time)", "t_d", unit="s"),
    Key("jerk_time", "time", "an S-curve: each ramp starts and ends with constant jerk this long, at most half a ramp",
        "t_j", unit="s"),
    Key("dwell", "time", "a pause of this time, instead of a move (takes no other key)", unit="s"),
), "the moves of the load in order, one table each; the cycle repeats after the last", array=True)
RECORD = Declared("drive_record", (
    Key("file", "file",
        "a drive's record: columns time [s], speed [rpm] and optionally torque [N*m] (else the mechanism's)"),
), "a time series a drive recorded, instead of the moves")
#: The tables of a case that give its motion; each is also a key at the case file's top level.
TABLES = (MECHANISM, MOVE, RECORD)
#: The ways to give the load cycle; a case gives exactly one.
FORMS = ("profile", "move", "drive_record")
RECORD_COLUMNS = (Column("time", "time", "time of the sample"), Column("speed", "speed", "output speed"))
RECORD_TORQUE = Column("torque", "torque", "output torque")


def keys_of(type_: str) -> tuple[Key, ...]:
    """The keys a mechanism of one type takes.

    Parameters
    ----------
    type_ : str
        The mechanism's type (:data:`calc.domain.mechanism.TYPES`).

    Returns
    -------
    tuple of Key
        Those of every type and those of this one, in declared order.
    """
    return tuple(k for k in MECHANISM.keys if not k.only or type_ in k.only)


@dataclass
class Motion:
    """The motion form of a case: the mechanism and its moves, or a drive record, sampled at the
    gearbox output and cut into the seed's segments.

    Parameters
    ----------
    mechanism : calc.domain.mechanism.Mechanism or None
        The mechanism; None for a drive record with its torque.
    moves : list of calc.domain.motion.Move
        The moves at the gearbox output; empty for a drive record.
    distances : list
        Per move: the distance as the case gives it (None for a dwell).
    samples : calc.domain.motion.Samples
        The samples at the gearbox output.
    cycle : calc.domain.cycle.SampledCycle
        The sampled cycle at the gearbox output.
    segments : calc.domain.motion.Segments
        The seed's segments.
    profile : calc.domain.profile.Profile
        Those segments as the profile the other sections use.
    record : str, optional
        The drive record's file as the case names it.
    tables : dict, optional
        The raw tables it was derived from, by name (mechanism, move, drive_record).
    """

    mechanism: Mechanism | None
    moves: list
    distances: list
    samples: Samples
    cycle: SampledCycle
    segments: object
    profile: Profile
    record: str | None = None
    tables: dict = field(default_factory=dict)

    @cached_property
    def output_load(self) -> OutputLoad:
        """The cycle as the motor's side reads it (:meth:`calc.domain.motor.OutputLoad.from_cycle`), made
        once: the pair search and the motor's check of an evaluation both read it."""
        return OutputLoad.from_cycle(self.cycle)

    @property
    def J_L(self):
        """The load's inertia at the gearbox output the mechanism gives; None without a mechanism."""
        return None if self.mechanism is None else self.mechanism.load_inertia

    @property
    def peak_speed(self):
        """The highest output speed in magnitude: the moves' ω_2max, or the record's highest."""
        if self.moves:
            return Q_(max(abs(m.peak_speed) for m in self.moves), "rad/s").to("rpm")
        return Q_(float(np.abs(self.cycle.speed).max()), "rad/s").to("rpm")

    @property
    def peak_acceleration(self):
        """The highest output acceleration in magnitude: the moves' α_2max, or the record's."""
        if self.moves:
            return Q_(max(abs(a) for m in self.moves for a in m.peak_accelerations()), "rad/s**2")
        return Q_(float(np.abs(self.cycle.acceleration).max()), "rad/s**2")


def nonnegative(table: Table, key: str):
    """A quantity (:meth:`calc.sections.case.Table.quantity`), which must not be below zero.

    Parameters
    ----------
    table : calc.sections.case.Table
        The table.
    key : str
        A key of it with a declared default.

    Returns
    -------
    pint.Quantity [the key's kind]
        The quantity, or its default.
    """
    q = table.quantity(key)
    if q.magnitude < 0:
        raise CalcError(f"{table.where(key)}: expected {kind_phrase(table.kind(key))} of zero or more, "
                        f"found {as_found(table.data[key])}")
    return q


def read_mechanism(top: Table) -> Mechanism | None:
    """``[mechanism]``, checked: its type, then only the keys of that type.

    Parameters
    ----------
    top : calc.sections.case.Table
        The case file's top-level table.

    Returns
    -------
    calc.domain.mechanism.Mechanism or None
        The mechanism; None where the case gives none.
    """
    raw = top.data.get("mechanism")
    if raw is None:
        return None
    any_keys = tuple(raw) if isinstance(raw, dict) else ()
    type_ = Table(top.path, MECHANISM.name, raw, any_keys).text("type", required=True)
    if type_ not in TYPES:
        raise CalcError(f"{top.path}: mechanism.type: expected one of {listing(TYPES)}, found {as_found(type_)}")
    allowed = keys_of(type_)
    names = key_names(allowed)
    for key in raw:
        owner = next((t for t in TYPES if key in key_names(keys_of(t))), None)
        if key not in names and owner is not None:
            raise CalcError(f"{top.path}: mechanism.{key}: a key of a {owner} mechanism; "
                            f"a {type_} mechanism takes {listing(names)}")
    t = Table(top.path, MECHANISM.name, raw, allowed)
    brake = t.data.get("holding_brake", MECHANISM.key("holding_brake").default)
    if not isinstance(brake, bool):
        raise CalcError(f"{t.where('holding_brake')}: expected true or false, found {as_found(brake)}")
    if type_ == "rotary":
        bodies = tuple(read_body(b) for b in t.tables("body", BODY_KEYS))
        given = t.positive("inertia", required=not bodies)
        inertia = sum((b.inertia for b in bodies), Q_(0.0, "kg*cm**2") if given is None else given.to("kg*cm**2"))
        return Mechanism(
            type_, holding_brake=brake, inertia=inertia, bodies=bodies, given_inertia=given,
            friction_torque=nonnegative(t, "friction_torque"), process_torque=nonnegative(t, "process_torque"),
        )
    eta = t.positive("eta", required=True, what="an efficiency")
    if eta.m_as("") > 1:
        raise CalcError(f"{t.where('eta')}: expected an efficiency of at most 1, found {as_found(t.data['eta'])}")
    reverse = t.positive("reverse_efficiency", what="an efficiency") if type_ == "ball-screw" else None
    if reverse is not None and reverse.m_as("") > 1:
        raise CalcError(f"{t.where('reverse_efficiency')}: expected an efficiency of at most 1, "
                        f"found {as_found(t.data['reverse_efficiency'])}")
    radius_key, own_key = OWN_KEYS[type_]
    size = t.positive(radius_key, required=True)
    return Mechanism(
        type_, holding_brake=brake, mass=t.positive("mass", required=True),
        friction_coefficient=nonnegative(t, "friction_coefficient"),
        incline=t.quantity("incline"), force=t.quantity("force"), eta=eta, reverse_efficiency=reverse,
        own_inertia=nonnegative(t, own_key),
        counterweight=nonnegative(t, "counterweight"), drag_torque=nonnegative(t, "drag_torque"),
        **({"lead": size} if type_ == "ball-screw" else {"diameter": size}),
    )


def read_body(t: Table) -> Body:
    """One ``[[mechanism.body]]``: its shape, the dimensions the shape takes (others refused), its
    mass or its density (one of them), and its offset.

    Parameters
    ----------
    t : calc.sections.case.Table
        The body's table.

    Returns
    -------
    calc.domain.inertia.Body
        The body.
    """
    shape = t.text("shape", required=True)
    if shape not in SHAPES:
        raise CalcError(f"{t.where('shape')}: expected one of {listing(SHAPES)}, found {as_found(shape)}")
    needed = FORMULAS[shape][2]
    dimensions = {}
    for key, name in BODY_DIMENSIONS.items():
        if name in needed:
            dimensions[name] = t.positive(key, required=True)
        elif t.has(key):
            takes = listing(k for k, n in BODY_DIMENSIONS.items() if n in needed)
            raise CalcError(f"{t.where(key)}: a {shape} takes {takes}, not {key}")
    if shape == "hollow-cylinder" and not dimensions["d_i"] < dimensions["D"]:
        raise CalcError(f"{t.where('inner_diameter')}: expected an inner diameter below the outer "
                        f"{as_found(t.data['diameter'])}, found {as_found(t.data['inner_diameter'])}")
    if t.has("mass") == t.has("density"):
        raise CalcError(f"{t.where('mass')}: give the body's mass or its material's density, one of them, "
                        f"found {'both' if t.has('mass') else 'neither'}")
    return Body(shape, dimensions, mass=t.positive("mass"), density=t.positive("density"),
                offset=nonnegative(t, "offset"))


def read_move(t: Table, mechanism: Mechanism):
    """One ``[[move]]``: a dwell, or a distance in a time with its ramps.

    Parameters
    ----------
    t : calc.sections.case.Table
        The move's table.
    mechanism : calc.domain.mechanism.Mechanism
        The mechanism that carries the load: the distance's kind and its way to the output.

    Returns
    -------
    tuple
        The :class:`calc.domain.motion.Move` at the gearbox output and the distance as given
        (None for a dwell).
    """
    if t.has("dwell"):
        other = next((k for k in t.data if k != "dwell"), None)
        if other is not None:
            raise CalcError(f"{t.where(other)}: a dwell takes only its time (dwell), found {other} beside it")
        return Move(0.0, t.positive("dwell").m_as("s")), None
    if not t.has("distance"):
        raise CalcError(f"{t.where('distance')}: expected a distance (a move) or a dwell, found neither")
    distance_kind = mechanism.distance_kind
    try:
        distance = parse_quantity(t.data["distance"], distance_kind, t.where("distance"))
    except CalcError as exc:
        how = f"a {mechanism.type} mechanism moves its load by {kind_phrase(distance_kind)}"
        raise CalcError(f"{exc} ({how})") from None
    if distance.magnitude == 0:
        raise CalcError(f"{t.where('distance')}: expected a distance other than zero (a pause is a dwell), "
                        f"found {as_found(t.data['distance'])}")
    time = t.positive("time", required=True).m_as("s")
    accel = t.positive("accel_time", required=True).m_as("s")
    decel = t.positive("decel_time")
    decel = accel if decel is None else decel.m_as("s")
    if accel + decel > time * (1 + 1e-12):
        raise CalcError(
            f"{t.where('accel_time')}: expected acceleration and deceleration times that fit in the move "
            f"(accel_time + decel_time <= time), found {accel:g} s + {decel:g} s > {time:g} s"
        )
    jerk = t.positive("jerk_time")
    jerk = 0.0 if jerk is None else jerk.m_as("s")
    if jerk > min(accel, decel) / 2 * (1 + 1e-12):
        raise CalcError(
            f"{t.where('jerk_time')}: expected a jerk time of at most half the acceleration and the deceleration "
            f"time ({min(accel, decel) / 2:g} s), found {jerk:g} s"
        )
    phi = mechanism.to_output(distance).m_as("rad")
    return Move(phi, time, accel, decel, jerk), distance


def derive(top: Table) -> Motion | None:
    """The motion form of a case from its raw top-level tables: the mechanism and its moves, or a
    drive record. A case file is read through here, and so is every edit of a case's text (the
    design review's, :mod:`calc.review.edit`), read again by the same reader.

    Parameters
    ----------
    top : calc.sections.case.Table
        The case file's top-level table, as the file reads.

    Returns
    -------
    Motion or None
        The motion; None where the case types its load cycle.

    Raises
    ------
    CalcError
        On bad input, naming the key.
    """
    forms = [f for f in FORMS if top.has(f)]
    if len(forms) > 1:
        raise CalcError(f"{top.path}: {forms[1]}: the load cycle is given as {forms[0]} already; "
                        f"give one of [[profile]], [[move]] or [drive_record]")
    mechanism = read_mechanism(top)
    if not forms or forms == ["profile"]:
        if mechanism is not None:
            raise CalcError(f"{top.path}: mechanism: a mechanism needs the moves of its load ([[move]]) "
                            f"or a [drive_record], found {'[[profile]]' if forms else 'neither'}")
        return None
    if mechanism is not None and isinstance(top.data.get("load"), dict) and "inertia" in top.data["load"]:
        raise CalcError(f"{top.path}: load.inertia: the mechanism gives the load's inertia J_L; "
                        f"leave load.inertia out")
    motion = read_moves(top, mechanism) if forms == ["move"] else read_record(top, mechanism)
    motion.tables = {name: top.data[name] for name in key_names(TABLES) if name in top.data}
    return motion


def apply(case: Case, motion: Motion) -> None:
    """Give a case its derived motion: its load cycle (the seed's segments) and, where the
    mechanism gives it, the load's inertia J_L (which the file then leaves out of ``[load]``).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case being read; its motion, profile and load inertia are written.
    motion : Motion
        The derived motion (:func:`derive`).

    Returns
    -------
    None
    """
    case.motion, case.profile = motion, motion.profile
    if motion.J_L is not None:
        case.load_inertia = motion.J_L


def read_moves(top: Table, mechanism: Mechanism | None) -> Motion:
    """The motion of the ``[[move]]`` tables through the mechanism.

    Parameters
    ----------
    top : calc.sections.case.Table
        The case file's top-level table.
    mechanism : calc.domain.mechanism.Mechanism or None
        The mechanism; None is an error (moves need one).

    Returns
    -------
    Motion
        The moves sampled, the torque the mechanism gives.
    """
    where = f"{top.path}: move"
    if mechanism is None:
        raise CalcError(f"{where}: moves need the mechanism that carries the load ([mechanism] with its type), "
                        f"found none")
    read_rows = [read_move(t, mechanism) for t in top.tables(MOVE.name, MOVE.keys)]
    if not read_rows:
        raise CalcError(f"{where}: expected one [[move]] table per move, found none")
    moves = [m for m, _ in read_rows]
    if all(m.dwell for m in moves):
        raise CalcError(f"{where}: expected at least one move with a distance, found only dwells")
    s = sample(moves)
    return _motion(mechanism, moves, [d for _, d in read_rows], s, mechanism.torque(s.speed, s.acceleration), where)


def read_record(top: Table, mechanism: Mechanism | None) -> Motion:
    """The motion of a ``[drive_record]``: its samples, with its torque or the mechanism's.

    Parameters
    ----------
    top : calc.sections.case.Table
        The case file's top-level table.
    mechanism : calc.domain.mechanism.Mechanism or None
        The mechanism; needed where the record has no torque column.

    Returns
    -------
    Motion
        The record sampled, its torque the mean of each pair of rows (else the mechanism's).
    """
    t = top.table(RECORD.name, RECORD.keys)
    path = measurement_path(t.data.get("file"), top.path.parent, t.where("file"))
    m = read_measurement(path, RECORD_COLUMNS, optional=(RECORD_TORQUE,))
    time, speed = m["time"].m_as("s"), m["speed"].m_as("rad/s")
    if len(time) < 2:
        raise CalcError(f"{path}: expected at least two rows (a record of a cycle), found one")
    torque = m.columns.get("torque")
    if torque is None and mechanism is None:
        raise CalcError(f"{t.where('file')}: the record has no torque column, so the torque comes from a [mechanism], "
                        f"found none")
    s = record_samples(time, speed)
    if torque is None:
        out = mechanism.torque(s.speed, s.acceleration)
    else:
        T = torque.m_as("N*m")
        out = (T[1:] + T[:-1]) / 2
    motion = _motion(mechanism, [], [], s, out, t.where("file"))
    motion.record = t.data["file"]
    return motion


def _motion(mechanism, moves, distances, s: Samples, torque: np.ndarray, where: str) -> Motion:
    g = segments(s, torque)
    rows = [
        (PHASES[p], Q_(t, "s"), None if PHASES[p] == "pause" else Q_(n, "rad/s"),
         None if PHASES[p] == "pause" else Q_(T, "N*m"))
        for p, t, n, T in zip(g.phase, g.duration, g.speed, g.torque)
    ]
    profile = Profile.from_segments(rows, where=where)
    cycle = SampledCycle(s.dt, s.speed, s.acceleration, torque)
    return Motion(mechanism, moves, distances, s, cycle, g, profile)


@dataclass(frozen=True)
class Segment:
    """A derived segment of the load cycle as the outputs print it.

    Parameters
    ----------
    phase : str
        accel, const, decel or pause.
    duration : calc.core.units.Value
        Its duration [s].
    speed : calc.core.units.Value
        Its mean output speed [rpm].
    torque : calc.core.units.Value
        Its output torque [N*m].
    """

    phase: str
    duration: Value
    speed: Value
    torque: Value


@dataclass(frozen=True)
class MotionResult(Result):
    """The derived segments, the peaks and the load's inertia at the output, and the steps that
    derived them (the transmission radius, the load's inertia, each move's distance, peak speed
    and acceleration, and the output torque of each of its phases).

    Parameters
    ----------
    motion : Motion
        The case's motion form.
    segments : list of Segment
        The derived segments.
    peak_speed : calc.core.units.Value
        The highest output speed [rpm].
    peak_acceleration : calc.core.units.Value
        The highest output acceleration [rad/s**2].
    J_L : calc.core.units.Value or None
        The load's inertia at the output [kg*cm**2], where the mechanism gives it.
    mechanism : str or None
        The mechanism's type; None for a drive record with its torque.
    source : str
        "move" or "drive_record".
    samples : int
        How many samples the cycle has.
    """

    motion: Motion
    segments: list
    peak_speed: Value
    peak_acceleration: Value
    J_L: Value | None
    mechanism: str | None
    source: str
    samples: int

    def to_json(self, candidates: int | None = None) -> dict:
        return {
            "segments": [{"phase": g.phase, "duration": g.duration.to_json(), "speed": g.speed.to_json(),
                          "torque": g.torque.to_json()} for g in self.segments],
            "peak_speed": self.peak_speed.to_json(),
            "peak_acceleration": self.peak_acceleration.to_json(),
            "J_L": json_of(self.J_L),
            "mechanism": self.mechanism,
            "source": self.source,
            "samples": self.samples,
        }

    def summary_lines(self, candidates: int | None = None) -> list[str]:
        source = "the drive record" if self.source == "drive_record" else "the moves"
        head = f"Motion ({self.mechanism or 'recorded torque'}, from {source}): "
        head += f"peak speed {self.peak_speed}, peak acceleration {self.peak_acceleration}"
        if self.J_L is not None:
            head += f", J_L = {self.J_L}"
        lines = [head]
        mech = self.motion.mechanism
        if mech is not None and mech.self_locking:
            lines.append(f"  the screw is self-locking (η' = {mech.reverse.m_as(''):.4g} ≤ 0): the load cannot drive "
                         "it back; the motor drives it where the load would, and it holds the load at rest")
        for k, g in enumerate(self.segments, start=1):
            lines.append(f"  {k:>2} {g.phase:<6} {str(g.duration):>10}  {str(g.speed):>12}  {str(g.torque):>12}")
        return lines

    def verdict(self):
        """The motion has no checks of its own.

        Returns
        -------
        None
        """
        return None

    @cached_property
    def steps(self) -> list:
        """(title, calc.core.formula.Step) of how the moves give the output's motion and torque,
        computed here on first use (the review's changes need none of them)."""
        return motion_steps(self.motion)


def motion_steps(m: Motion) -> list:
    """How the moves give the output's speed, acceleration and torque.

    Parameters
    ----------
    m : Motion
        The case's motion form.

    Returns
    -------
    list of tuple
        (title, :class:`calc.core.formula.Step`): the transmission radius and the load's inertia
        (a linear mechanism), each body's inertia, and per move its distance at the output, peak
        speed, acceleration and deceleration and the output torque of each of its phases.
    """
    k = m.mechanism
    out = []
    if k is not None and k.linear:
        out += [("Transmission radius", k.radius_step()),
                ("Load inertia at the gearbox output", k.load_inertia_step())]
        if k.reverse_step() is not None:
            out.append(("Reverse efficiency of the screw", k.reverse_step()))
    for n, body in enumerate(() if k is None else k.bodies, start=1):
        out += [(f"Body {n} ({body.shape}): {step.formula.result.description}", step) for step in body.steps()]
    for n, (move, given) in enumerate(zip(m.moves, m.distances), start=1):
        if move.dwell:
            continue
        phi = k.to_output(given)
        if k.linear:
            out.append((f"Move {n}: distance at the output", phi_2.step(result=phi, s=given, r=k.radius)))
        times = {"t_m": Q_(move.time, "s"), "t_a": Q_(move.accel_time, "s"), "t_d": Q_(move.decel_time, "s")}
        w = omega_2max.step(phi_2=phi, **times)
        out.append((f"Move {n}: peak output speed", w))
        accel = alpha_2max.step(omega_2max=w.result, t_r=times["t_a"], t_j=Q_(move.jerk_time, "s"))
        out.append((f"Move {n}: peak output acceleration", accel))
        decel = accel
        if move.decel_time != move.accel_time:
            decel = alpha_2max.step(omega_2max=w.result, t_r=times["t_d"], t_j=Q_(move.jerk_time, "s"))
            out.append((f"Move {n}: peak output deceleration", decel))
        phases = (("acceleration", accel.result), ("constant speed", Q_(0.0, "rad/s**2")),
                  ("deceleration", -decel.result))
        for phase, a in phases:
            out += [(f"Move {n}, {phase}: {step.formula.result.description}", step) for step in k.steps(w.result, a)]
    return out


class MotionSection(Section):
    """The load cycle derived from the moves and the mechanism, or from a drive record."""

    NAME = NAME
    TABLES = TABLES

    def read(self, top: Table, case: Case) -> None:
        """Derive the load cycle where the case gives moves or a drive record (after ``[load]``,
        whose inertia the mechanism gives instead).

        Parameters
        ----------
        top : calc.sections.case.Table
            The case file's top-level table.
        case : calc.sections.case.Case
            The case being read.

        Returns
        -------
        None
        """
        derived = derive(top)
        if derived is not None:
            apply(case, derived)

    def applies(self, case: Case) -> bool:
        return case.motion is not None

    def evaluate(self, case: Case, earlier) -> MotionResult:
        return motion_result(case.motion)


SECTION = MotionSection()


def motion_result(m: Motion) -> MotionResult:
    """The derived segments and peaks of a motion as the outputs print them.

    Parameters
    ----------
    m : Motion
        The case's motion form.

    Returns
    -------
    MotionResult
        Its segments, peaks, load inertia, mechanism, source and number of samples.
    """
    g = m.segments
    segments = [Segment(PHASES[p], Value.of(Q_(t, "s"), "s", "motion.segments.duration"),
                        Value.of(Q_(n, "rad/s"), "rpm", "motion.segments.speed"),
                        Value.of(Q_(T, "N*m"), "N*m", "motion.segments.torque"))
                for p, t, n, T in zip(g.phase, g.duration, g.speed, g.torque)]
    return MotionResult(
        m, segments, Value.of(m.peak_speed, "rpm", "motion.peak_speed"),
        Value.of(m.peak_acceleration, "rad/s**2", "motion.peak_acceleration"),
        None if m.J_L is None else Value.of(m.J_L, "kg*cm**2", "motion.J_L"),
        None if m.mechanism is None else m.mechanism.type,
        "drive_record" if m.record is not None else "move", int(len(m.cycle.dt)))
