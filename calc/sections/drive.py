"""The servo drive that feeds the motor (``[drive]``): the drive chosen from a catalog (or named, or
typed) against the motor's current over the cycle and its voltage class, the braking energy of
each braking event against the drive's DC link and its brake resistor, and the winding's
temperature where the motor gives its thermal time constant (:mod:`calc.domain.drive`; case format,
"The servo drive")."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..core.checks import Check
from ..core.errors import CalcError
from ..core.units import Q_, number
from ..data.catalog import Catalog, display_path, load_catalogs
from ..domain.drive import (
    E_C, P_R_avg, P_R_peak, RANKING, SCHEMA, DriveSelection, I_ph, braking_events, k_T_derived,
    passes_all, resistor_energies, select_drives, voltage_class,
)
from .case import Case, Declared, Key, Table
from .common import (SHOWN_CANDIDATES, Governing, Verdict, check_json, check_line, quantity, selection_verdict)
from .protocol import Result, Section

NAME = "drive"
ORDER = 65  # after the motor

RESISTOR_KEYS = (
    Key("resistance", "resistance", "resistance of the brake resistor", "R_br", unit="ohm"),
    Key("continuous_power", "power", "continuous power the resistor takes", "P_R", unit="W"),
    Key("peak_power", "power", "peak power the resistor takes (default: U_on² / R where drive.chopper_voltage "
        "is given)", "P_R_peak", unit="W"),
)
TABLES = (Declared(NAME, (
    Key("catalog", "catalog", "a drive catalog (\"drives\" is catalogs/drives.csv): every drive with published "
        "currents is checked against the motor's current and ranked"),
    Key("part", "text", "check this drive of the catalog alone"),
    Key("rated_current", "current", "continuous output current of a typed drive", "I_N", unit="A"),
    Key("peak_current", "current", "peak output current of a typed drive, at least its rated current", "I_max",
        unit="A"),
    Key("peak_time", "time", "how long a typed drive gives its peak current", "t_max", unit="s"),
    Key("dc_link_voltage", "voltage", "DC-link voltage of a typed drive (with motor.dc_link_voltage: the same; "
        "else the motor's voltage limit takes it)",
        "U_DC", unit="V"),
    Key("dc_link_energy", "energy", "energy a typed drive's DC link absorbs before its chopper switches on",
        "E_C", unit="J"),
    Key("chopper_voltage", "voltage", "switch-on voltage of the brake chopper: E_C from the capacitance, the "
        "resistor's peak power U_on² / R", "U_on", unit="V"),
    Key("brake_resistor", "table", "the brake resistor (default: the drive's internal one)", keys=RESISTOR_KEYS),
), "the servo drive (amplifier) that feeds the motor"),)

#: What the braking energy leaves out.
LOSSES = ("the winding's and the drive's losses are not subtracted (the data give neither for the drive): the "
          "braking energy is an upper bound")
SATURATION = "I = T / k_T: saturation near the peak current not modelled (the peak current is a lower bound)"


@dataclass
class DriveInputs:
    """``[drive]`` as read with the case.

    Parameters
    ----------
    table : dict
        The table as written.
    catalog : str or list of str or None
        The drive catalog; None for a typed drive.
    part : str or None
        The drive named.
    typed : dict
        A typed drive's ratings by key (pint quantities).
    chopper_voltage : pint.Quantity [V] or None
        The brake chopper's switch-on voltage.
    resistor : dict
        ``[drive.brake_resistor]``'s values by key (pint quantities); empty without one.
    where : str
        The file and the table, for errors.
    """

    table: dict
    catalog: object
    part: str | None
    typed: dict
    chopper_voltage: object
    resistor: dict
    where: str


def read_drive(case: Case) -> DriveInputs:
    """``[drive]`` as the case gives it: a catalog (default ``drives``) and a part, or typed ratings.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.

    Returns
    -------
    DriveInputs
        The keys read; every error names the file and the key.
    """
    t = Table(case.path, NAME, case.sections[NAME], TABLES[0].keys)
    typed = {k: t.positive(k) for k in ("rated_current", "peak_current", "peak_time", "dc_link_voltage",
                                        "dc_link_energy") if t.has(k)}
    if typed and (t.has("catalog") or t.has("part")):
        raise CalcError(f"{t.where(next(iter(typed)))}: a catalog drive's ratings come from its row; give either "
                        f"drive.catalog / drive.part or the typed ratings, found both")
    if typed and not {"rated_current", "peak_current"} <= set(typed):
        missing = "rated_current" if "rated_current" not in typed else "peak_current"
        raise CalcError(f"{t.where(next(iter(typed)))}: a typed drive needs drive.rated_current and "
                        f"drive.peak_current, found no drive.{missing}")
    if typed and typed["peak_current"].m_as("A") < typed["rated_current"].m_as("A"):
        raise CalcError(f"{t.where('peak_current')}: expected a peak current at least the rated current "
                        f"{t.data['rated_current']!r}, found {t.data['peak_current']!r}")
    resistor = {}
    r = t.table("brake_resistor", RESISTOR_KEYS)
    if r is not None:
        resistor = {k: r.positive(k) for k in ("resistance", "continuous_power", "peak_power") if r.has(k)}
        if "resistance" not in resistor:
            raise CalcError(f"{r.where('resistance')}: a brake resistor needs its resistance, found none")
    catalog = None if typed else (t.catalogs("catalog") if t.has("catalog") else "drives")
    return DriveInputs(t.data, catalog, t.text("part"), typed, t.positive("chopper_voltage"), resistor,
                       f"{case.path}: drive")


def typed_catalog(case: Case, typed: dict) -> Catalog:
    """A typed drive as a one-row catalog of :data:`calc.domain.drive.SCHEMA`.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case.
    typed : dict
        The typed ratings by key.

    Returns
    -------
    calc.data.catalog.Catalog
        One row, ``typed drive``, NaN where a rating is not typed.
    """
    keys = {"U_DC": ("dc_link_voltage", "V"), "I_N": ("rated_current", "A"), "I_max": ("peak_current", "A"),
            "t_max": ("peak_time", "s"), "E_C": ("dc_link_energy", "J")}
    values = {c.name: Q_(np.full(1, np.nan), "") for c in SCHEMA.columns}
    units = {"C_DC": "uF", "R_int": "ohm", "P_R_int": "W", "R_min": "ohm"}
    for c in SCHEMA.columns:
        key, unit = keys.get(c.name, (None, units.get(c.name)))
        values[c.name] = Q_(np.array([typed[key].m_as(unit) if key in typed else np.nan]), unit)
    return Catalog("typed", case.path, "", SCHEMA, np.array(["typed drive"]), values,
                   {"maker": np.array([""], object), "source": np.array(["the case file"], object)}, np.array([0]))


@dataclass(frozen=True)
class MotorElectrical:
    """What the drive needs of the motor the case is checked with.

    Parameters
    ----------
    part : str
        The motor (``typed motor``).
    k_T : float or None [N·m/A]
        Its torque constant.
    k_T_from : str
        Where ``k_T`` comes from: ``catalog``, ``derived M_0 / I_0``, ``motor.torque_constant``.
    U_DC : float or None [V]
        Its DC-link voltage (its voltage class).
    """

    part: str
    k_T: float | None
    k_T_from: str
    U_DC: float | None


def motor_electrical(case: Case, motor) -> MotorElectrical:
    """The torque constant and DC-link voltage of the motor the case is checked with.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked.
    motor : calc.sections.motor.MotorResult
        The motor section's result.

    Returns
    -------
    MotorElectrical
        From the chosen catalog row (``k_T``, else ``M_0 / I_0``, marked derived) or the typed motor.
    """
    sel = motor.selection
    if sel is None:
        k = case.motor_torque_constant
        U = case.motor_dc_link
        return MotorElectrical("typed motor", None if k is None else float(k.m_as("N*m/A")),
                               "motor.torque_constant", None if U is None else float(U.m_as("V")))
    cat, row = sel.catalog, int(sel.order[0])
    k_T, where = float(cat["k_T"][row].m_as("N*m/A")), "catalog"
    if np.isnan(k_T):
        k_T = float(k_T_derived(M_0=cat["M_0"][row], I_0=cat["I_0"][row]).m_as("N*m/A"))
        where = "derived M_0 / I_0"
    U = float(cat["U_DC"][row].m_as("V"))
    if case.motor_dc_link is not None:
        U = float(case.motor_dc_link.m_as("V"))
    return MotorElectrical(str(cat.parts[row]), None if np.isnan(k_T) else k_T, where, None if np.isnan(U) else U)


@dataclass
class Braking:
    """The braking events of the cycle against the chosen drive's DC link and brake resistor.

    Parameters
    ----------
    events : list of calc.domain.drive.BrakingEvent
        Each braking event.
    dc_link_energy : float or None [J]
        What the DC link absorbs of each event; None where neither ``E_C`` nor ``C_DC`` with
        ``U_on`` is known.
    dc_link_from : str
        Where it comes from.
    resistor_energies : numpy.ndarray [J]
        What each event leaves for the resistor (the DC link taken as zero where unknown).
    t_cycle : float [s]
        The cycle time.
    resistor : dict
        The resistor checked: ``part`` (``drive.brake_resistor`` or the drive's internal one),
        ``resistance`` [Ω], ``continuous_power`` [W], ``peak_power`` [W] (None where unknown).
    checks : list of calc.core.checks.Check
        The braking checks.
    failing : list of str
        A sentence for each failing event.
    notes : list of str
        What was assumed or left out.
    """

    events: list
    dc_link_energy: float | None
    dc_link_from: str
    resistor_energies: np.ndarray
    t_cycle: float
    resistor: dict
    checks: list
    failing: list
    notes: list

    @property
    def energy_per_cycle(self) -> float:
        """What the resistor takes per cycle [J]."""
        return float(self.resistor_energies.sum())

    @property
    def average_power(self) -> float:
        """The resistor's average power over the cycle [W]."""
        return float(P_R_avg.si(E_R=self.energy_per_cycle, t_cycle=self.t_cycle))

    @property
    def peak_power(self) -> float:
        """The highest braking power of the cycle [W]."""
        return max((e.peak_power for e in self.events), default=0.0)

    def to_json(self) -> dict:
        """The braking results as the contract writes them.

        Returns
        -------
        dict
            Events, the DC link's energy, the resistor's energy per cycle, average and peak power, checks.
        """
        def w(x, unit):
            return None if x is None else quantity(Q_(x, unit), unit, "drive.braking")
        return {
            "events": [{"phase": e.phase, "start": w(e.start, "s"), "duration": w(e.duration, "s"),
                        "energy": w(e.energy, "J"), "peak_power": w(e.peak_power, "W"), "resistor_energy": w(r, "J")}
                       for e, r in zip(self.events, self.resistor_energies)],
            "dc_link_energy": w(self.dc_link_energy, "J"), "dc_link_energy_from": self.dc_link_from,
            "resistor_energy_per_cycle": w(self.energy_per_cycle, "J"),
            "resistor_average_power": w(self.average_power, "W"), "peak_power": w(self.peak_power, "W"),
            "resistor": {k: (v if isinstance(v, str) or v is None else number(v)) for k, v in self.resistor.items()},
            "losses_subtracted": [], "checks": [check_json(k) for k in self.checks], "notes": list(self.notes),
        }


def scalar_check(name: str, criterion: str, required, rated, unit: str, not_made: str | None = None) -> Check:
    """One check of two scalars (floats in ``unit``): required within rated.

    Parameters
    ----------
    name : str
        The rated value's symbol.
    criterion : str
        The check as text.
    required : float or None
        The required value; None: not made.
    rated : float or None
        The rated value; None: not made.
    unit : str
        Their unit.
    not_made : str, optional
        Why it is not made.

    Returns
    -------
    calc.core.checks.Check
    """
    if required is None or rated is None or not_made:
        return Check(name, criterion, None, Q_(np.nan if rated is None else rated, unit), unit, None, None,
                     not_made=not_made or "a value is not known")
    u = required / rated if rated > 0 else np.inf
    return Check(name, criterion, Q_(required, unit), Q_(rated, unit), unit, float(u), bool(u <= 1 + 1e-9))


def _value(cat, column: str, row: int, unit: str) -> float | None:
    """A catalog cell as a float in ``unit``; None where empty."""
    x = float(cat[column][row].m_as(unit))
    return None if np.isnan(x) else x


def dc_link_energy(given: DriveInputs, cat, row: int) -> tuple:
    """What the chosen drive's DC link absorbs of a braking event, and where that comes from.

    Parameters
    ----------
    given : DriveInputs
        ``[drive]`` as read.
    cat : calc.data.catalog.Catalog
        The drives.
    row : int
        The chosen drive's row.

    Returns
    -------
    tuple
        ``(E_C [J] or None, where from)``: the published ``E_C``, else ``½ C_DC (U_on² − U_DC²)``
        with ``drive.chopper_voltage``, else None.
    """
    published = _value(cat, "E_C", row, "J")
    if published is not None:
        return published, "E_C of the drive's row" if cat.name != "typed" else "drive.dc_link_energy"
    C, U = _value(cat, "C_DC", row, "F"), _value(cat, "U_DC", row, "V")
    if C is not None and U is not None and given.chopper_voltage is not None:
        U_on = given.chopper_voltage.m_as("V")
        return float(E_C.si(C_DC=C, U_on=U_on, U_DC=U)), "½ C_DC (U_on² − U_DC²) with drive.chopper_voltage"
    return None, "not known: no E_C, and no C_DC with U_DC and drive.chopper_voltage"


def brake_resistor(given: DriveInputs, cat, row: int) -> dict | None:
    """The brake resistor checked: the case's, else the drive's internal one; None without either.

    Parameters
    ----------
    given : DriveInputs
        ``[drive]`` as read.
    cat : calc.data.catalog.Catalog
        The drives.
    row : int
        The chosen drive's row.

    Returns
    -------
    dict or None
        ``part``, ``resistance`` [Ω], ``continuous_power`` [W], ``peak_power`` [W] (None where unknown).
    """
    U_on = None if given.chopper_voltage is None else given.chopper_voltage.m_as("V")
    if given.resistor:
        r = given.resistor
        out = {"part": "drive.brake_resistor", "resistance": r["resistance"].m_as("ohm"),
               "continuous_power": r["continuous_power"].m_as("W") if "continuous_power" in r else None,
               "peak_power": r["peak_power"].m_as("W") if "peak_power" in r else None}
    elif _value(cat, "R_int", row, "ohm") is not None:
        out = {"part": f"the internal resistor of {cat.parts[row]}", "resistance": _value(cat, "R_int", row, "ohm"),
               "continuous_power": _value(cat, "P_R_int", row, "W"), "peak_power": None}
    else:
        return None
    if out["peak_power"] is None and U_on is not None:
        out["peak_power"] = float(P_R_peak.si(U_on=U_on, R_br=out["resistance"]))
    return out


def braking_of(given: DriveInputs, cat, row: int, dt, power, phase_of, t_cycle: float) -> Braking:
    """The cycle's braking events against the chosen drive's DC link and brake resistor.

    Parameters
    ----------
    given : DriveInputs
        ``[drive]`` as read.
    cat : calc.data.catalog.Catalog
        The drives.
    row : int
        The chosen (or closest) drive's row.
    dt : numpy.ndarray [s]
        The duration of each sample.
    power : numpy.ndarray [W]
        The motor power of each sample.
    phase_of : sequence of str
        The phase of each sample.
    t_cycle : float [s]
        The cycle time.

    Returns
    -------
    Braking
        The events, what the DC link and the resistor take, and the checks.
    """
    events = braking_events(dt, power, phase_of)
    E_link, src = dc_link_energy(given, cat, row)
    resistor = brake_resistor(given, cat, row)
    notes = [LOSSES]
    if E_link is None and resistor is not None:
        notes.append("the DC link's energy is not known: taken as 0 J, so the resistor's energy is an upper bound")
    E_R = resistor_energies(events, 0.0 if E_link is None else E_link)
    checks, failing = [], []
    if not events:
        notes.append("the cycle does not brake: nothing reaches the DC link")
    elif resistor is None:
        for e in events:
            what = f"the {e.phase or 'braking'} at {e.start:.4g} s"
            k = scalar_check("E_C", f"E ({what}) <= E_C", e.energy, E_link, "J",
                             None if E_link is not None else f"the DC link's energy is {src}, and no resistor is given")
            checks.append(k)
            if k.passes is False:
                failing.append(f"{what} gives {e.energy:.4g} J; the DC link absorbs {E_link:.4g} J; "
                               f"no resistor is given")
    else:
        average = float(P_R_avg.si(E_R=E_R.sum(), t_cycle=t_cycle))
        peak = max(e.peak_power for e in events)
        checks.append(scalar_check("P_R", "P_R,avg <= P_R", average, resistor["continuous_power"], "W",
                                   None if resistor["continuous_power"] is not None
                                   else "the resistor's continuous power is not known"))
        checks.append(scalar_check("P_R,peak", "P_brake,peak <= P_R,peak", peak, resistor["peak_power"],
                                   "W", None if resistor["peak_power"] is not None else
                                   "the resistor's peak power needs drive.chopper_voltage or its peak_power"))
        R_min = _value(cat, "R_min", row, "ohm")
        if R_min is not None:
            checks.append(scalar_check("R_br", "R_min <= R_br", R_min, resistor["resistance"], "ohm"))
        for e, r in zip(events, E_R):
            if r > 0 and any(k.passes is False for k in checks):
                failing.append(f"the {e.phase or 'braking'} at {e.start:.4g} s gives {e.energy:.4g} J; the DC link "
                               f"absorbs {0.0 if E_link is None else E_link:.4g} J; {r:.4g} J go to "
                               f"{resistor['part']}")
    return Braking(events, E_link, src, E_R, t_cycle, resistor or {}, checks, failing, notes)


@dataclass
class DriveResult(Result):
    """The drive chosen against the motor's current, its braking and the winding's heat.

    Parameters
    ----------
    selection : calc.domain.drive.DriveSelection
        The drives checked and ranked (one row for a named or typed drive).
    motor : MotorElectrical
        What the drive needs of the motor.
    current_rms : float or None [A]
        The motor's RMS phase current over the cycle.
    current_peak : float or None [A]
        Its peak.
    braking : Braking
        The braking events against the chosen (or closest) drive.
    winding : calc.core.checks.Check or None
        ``θ_max <= 1`` where the motor gives its thermal time constant.
    catalog : str or list of str
        The catalog as the outputs name it (``typed`` for typed ratings).
    notes : list of str
        What was assumed or left out.
    """

    selection: DriveSelection
    motor: MotorElectrical
    current_rms: float | None
    current_peak: float | None
    braking: Braking
    winding: Check | None
    catalog: object
    notes: list = field(default_factory=list)

    ranking = RANKING

    @property
    def part(self) -> str:
        """The chosen drive, or the closest where none passes."""
        return self.selection.best.part

    def checks(self) -> list:
        """The chosen (or closest) drive's checks, its braking checks and the winding's.

        Returns
        -------
        list of calc.core.checks.Check
        """
        return self.selection.best.checks + self.braking.checks + ([] if self.winding is None else [self.winding])

    def to_json(self, candidates: int | None = SHOWN_CANDIDATES) -> dict:
        sel, m = self.selection, self.motor
        return {
            "selected": sel.selected, "catalog": self.catalog, "ranking": self.ranking,
            "motor": m.part,
            "torque_constant": (None if m.k_T is None else
                                {**quantity(Q_(m.k_T, "N*m/A"), "N*m/A", "drive.torque_constant"), "from": m.k_T_from,
                                 "derived": m.k_T_from.startswith("derived")}),
            "voltage_class": None if m.U_DC is None else voltage_class(m.U_DC),
            "current_rms": None if self.current_rms is None else quantity(Q_(self.current_rms, "A"), "A"),
            "current_peak": None if self.current_peak is None else quantity(Q_(self.current_peak, "A"), "A"),
            "candidates": [{"part": c.part, "passes": c.passes, "checks": [check_json(k) for k in c.checks],
                            "reasons": c.reasons, "catalog": c.catalog, "maker": c.maker or None,
                            "family": c.family or None} for c in sel.candidates(candidates)],
            "checks": [check_json(k) for k in self.checks()],
            "braking": self.braking.to_json(),
            "notes": list(self.notes) + list(sel.notes),
        }

    def summary_lines(self, candidates: int | None = SHOWN_CANDIDATES) -> list[str]:
        sel, m = self.selection, self.motor
        k_T = "n/a" if m.k_T is None else f"{m.k_T:.4g} N·m/A ({m.k_T_from})"
        rms = "n/a" if self.current_rms is None else f"{self.current_rms:.4g} A"
        peak = "n/a" if self.current_peak is None else f"{self.current_peak:.4g} A"
        lines = [f"Drive {sel.selected or 'none passes'} for motor {m.part} ({len(sel.order)} ranked; k_T {k_T}; "
                 f"I_rms = {rms}, I_peak = {peak}):"]
        for k, c in enumerate(sel.candidates(candidates), start=1):
            verdict = {True: "PASS", False: "FAIL", None: "NOT DECIDED"}[c.passes]
            lines.append(f"  {k:>3}. {c.part:<28} {verdict:<11}" + (f"  {'; '.join(c.reasons)}" if c.reasons else ""))
        b = self.braking
        link = "n/a" if b.dc_link_energy is None else f"{b.dc_link_energy:.4g} J"
        events = f"{len(b.events)} event{'s' if len(b.events) != 1 else ''}"
        lines.append(f"  Braking: {events}, DC link absorbs {link} each; left for a resistor "
                     f"{b.energy_per_cycle:.4g} J per cycle, {b.average_power:.4g} W average, "
                     f"peak braking {b.peak_power:.4g} W")
        lines += [f"    {e.phase or 'braking'} at {e.start:.4g} s for {e.duration:.4g} s: {e.energy:.4g} J"
                  for e in b.events]
        lines.append(f"  Checks of {self.part}" + ("" if sel.selected else " (the closest; none passes)") + ":")
        lines += [f"        {check_line(k)}" for k in self.checks()]
        return lines + [f"  Note: {n}" for n in self.notes + sel.notes + b.notes]

    def verdict(self) -> Verdict:
        """The drive's verdict: its choice, its braking and the winding.

        Returns
        -------
        calc.sections.common.Verdict
        """
        chosen = selection_verdict(self.selection, "drive", f"the current of motor {self.motor.part}")
        rest = self.braking.checks + ([] if self.winding is None else [self.winding])
        passes = passes_all(rest)
        reasons = list(self.braking.failing)
        reasons += [f"Drive {self.part}: {k.reason()}" for k in rest
                    if k.passes is None or (k.passes is False and k.name != "E_C")]
        return Verdict.combine([chosen, Verdict(passes, reasons)], "")

    def governing(self) -> Governing:
        """The chosen (or closest) drive's checks.

        Returns
        -------
        calc.sections.common.Governing
        """
        return Governing(NAME, self.part, self.selection.selected is not None, self.checks())

    def ranked(self) -> DriveSelection:
        """The drives ranked.

        Returns
        -------
        calc.domain.drive.DriveSelection
        """
        return self.selection


class DriveSection(Section):
    """The servo drive: chosen against the motor's current, checked for braking and heat."""

    NAME = NAME
    TABLES = TABLES
    REQUIRES = ("axis", "motor")

    def read_inputs(self, case: Case) -> DriveInputs:
        given = read_drive(case)
        if case.motor_dc_link is None:  # the motor's voltage limit takes the DC link of the drive named
            case.voltage_limit_dc_link = named_dc_link(case, given)
        return given

    def evaluate(self, case: Case, earlier) -> DriveResult:
        given = self.inputs(case)
        motor, checked = earlier.get("motor"), earlier["axis"].case
        if motor is None or motor.load is None:
            return unknown_torques(case, given, motor)
        m = motor_electrical(checked, motor)
        cat = drive_catalog(case, given, m)
        dt, speed, T_1 = motor._at_motor
        no_current = None if m.k_T else (f"the current needs the torque constant of motor {m.part} "
                                         "(motor.torque_constant, or k_T or M_0 and I_0 in its catalog row)")
        I = None if no_current else np.abs(I_ph.si(T_1=T_1, k_T=m.k_T))
        I_rms = None if I is None else float(np.sqrt((I**2 * dt).sum() / dt.sum()))
        I_peak = None if I is None else float(I.max())
        sel = select_drives(cat, I_rms, I_peak, dt, I, m.U_DC, no_current, motor.characteristic_dc_link)
        _resistor_above_minimum(given, sel.catalog)
        segment, names = motor.segments
        phase_of = np.asarray(names, dtype=object)[segment]  # the phase of each sample (thousands of them)
        braking = braking_of(given, sel.catalog, int(sel.order[0]), dt, T_1 * speed, phase_of, float(dt.sum()))
        w = motor.thermal
        winding = None if w is None else scalar_check("theta", "θ_max <= 1 (the winding's rise under "
                                                      f"{w.reference} held)", w.utilization, 1.0, "")
        notes = [SATURATION] if I is not None else []
        if w is None:
            notes.append("the winding's temperature model needs the motor's thermal time constant T_th: "
                         "the RMS rule stands")
        catalog = "typed" if cat.name == "typed" else ([display_path(p) for p, _ in cat.members] if len(cat.members) > 1
                                                        else display_path(cat.path))
        return DriveResult(sel, m, I_rms, I_peak, braking, winding, catalog, notes)


def unknown_torques(case: Case, given: DriveInputs, motor) -> DriveResult:
    """The drive's result where the motor's torques over the cycle are not known (no motor, or one
    whose rotor term lacks an inertia): every check not made, saying why.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    given : DriveInputs
        ``[drive]`` as read.
    motor : calc.sections.motor.MotorResult or None
        The motor section's result; None where the case has no motor.

    Returns
    -------
    DriveResult
        The drives listed, none chosen; the braking not checked.
    """
    why = ("the case gives no motor" if motor is None
           else "; ".join(n for n in motor.notes if "needs" in n) or "the motor's torques are not known")
    reason = f"the drive needs the motor's torques over the cycle: {why}"
    m = MotorElectrical("no motor" if motor is None else "the case's motor", None, "", None)
    cat = drive_catalog(case, given, m)
    sel = select_drives(cat, None, None, np.ones(1), None, None, reason)
    t_cycle = float(case.profile.t_cycle.m_as("s"))
    braking = Braking([], None, "not known", np.zeros(0), t_cycle, {},
                      [scalar_check("E_C", "braking energy against the DC link", None, None, "J", reason)], [], [])
    return DriveResult(sel, m, None, None, braking, None, "typed" if cat.name == "typed" else given.catalog, [reason])


def named_dc_link(case: Case, given: DriveInputs) -> tuple:
    """The DC-link voltage of the drive the case names, which the motor's voltage limit takes
    where ``motor.dc_link_voltage`` is not given.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    given : DriveInputs
        ``[drive]`` as read.

    Returns
    -------
    tuple
        ``(U_DC [pint.Quantity, V], where from)``: the typed ``drive.dc_link_voltage``, or the
        ``U_DC`` of the row of ``drive.part``; ``(None, None)`` where the drive is chosen from a
        catalog, or its DC-link voltage is not given.
    """
    if "dc_link_voltage" in given.typed:
        return given.typed["dc_link_voltage"], "drive.dc_link_voltage"
    if given.typed or given.part is None:
        return None, None
    cat = load_catalogs(given.catalog, case.folder, f"{given.where}.catalog", SCHEMA)
    U = _value(cat, "U_DC", cat.usable_index(given.part, f"{given.where}.part"), "V")
    return (None, None) if U is None else (Q_(U, "V"), f"the U_DC of drive.part {given.part}")


def _resistor_above_minimum(given: DriveInputs, cat) -> None:
    """A resistor the case gives for a drive it names: at least the drive's ``R_min``."""
    R_min = _value(cat, "R_min", 0, "ohm") if given.part is not None else None
    if R_min is not None and given.resistor and given.resistor["resistance"].m_as("ohm") < R_min:
        raise CalcError(f"{given.where}.brake_resistor.resistance: expected at least the R_min of {given.part}, "
                        f"{R_min:g} ohm, found {given.table['brake_resistor']['resistance']!r}")


def drive_catalog(case: Case, given: DriveInputs, m: MotorElectrical):
    """The drives the case offers: its typed drive, its named part alone, or its catalog.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    given : DriveInputs
        ``[drive]`` as read.
    m : MotorElectrical
        The motor.

    Returns
    -------
    calc.data.catalog.Catalog
        Of :data:`calc.domain.drive.SCHEMA`.

    Raises
    ------
    CalcError
        Where a typed or named drive's DC link is of another voltage class than the motor's, or the
        typed DC-link voltage disagrees with motor.dc_link_voltage.
    """
    if given.typed:
        cat = typed_catalog(case, given.typed)
        U = given.typed.get("dc_link_voltage")
        motor_U = case.motor_dc_link
        if U is not None and motor_U is not None and not np.isclose(U.m_as("V"), motor_U.m_as("V")):
            raise CalcError(f"{given.where}.dc_link_voltage: expected the DC link of motor.dc_link_voltage, "
                            f"{motor_U.m_as('V'):g} V, found {given.table['dc_link_voltage']!r}")
        where = f"{given.where}.dc_link_voltage"
    else:
        cat = load_catalogs(given.catalog, case.folder, f"{given.where}.catalog", SCHEMA)
        if given.part is None:
            return cat
        cat = cat.rows(np.array([cat.usable_index(given.part, f"{given.where}.part")]))
        where = f"{given.where}.part"
    U = _value(cat, "U_DC", 0, "V")
    if U is not None and m.U_DC is not None and voltage_class(U) != voltage_class(m.U_DC):
        raise CalcError(f"{where}: a drive of the {voltage_class(U)} class (U_DC = {U:g} V) and motor {m.part} of the "
                        f"{voltage_class(m.U_DC)} class (U_DC = {m.U_DC:g} V) forced together; expected one class")
    return cat


SECTION = DriveSection()
