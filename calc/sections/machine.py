"""A machine of several axes on one DC bus (``python -m calc machine MACHINE.toml``): each axis a
case file evaluated and checked as its own case, placed in the machine's cycle at its start; the
axes' power at the DC bus summed on one time base (braking power another axis takes at the same
moment never reaches a resistor; the DC links' energies add), the net braking energy against the
bus's DC link and brake resistor, and the supply module's continuous and peak power against the
sum (case format, "A machine of several axes"; Schneider Motion Sizer's and Kollmorgen's
multi-axis rule).

Not a section of a case: the machine file is read here and evaluates the cases it names. A case
named by several axes is read and evaluated once.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..core.checks import BOUNDARY_RTOL, Check
from ..core.errors import CalcError
from ..data.catalog import display_path
from ..domain.drive import braking_events, bus_powers, bus_total, passes_all, resistor_energies
from .case import Key, Table, read_case
from .common import Verdict, check_json, check_line, quantity
from .drive import scalar_check
from .evaluation import evaluate
from ..core.units import Q_

#: The keys of a machine file, of each ``[[axis]]``, of ``[dc_bus]`` and its tables.
AXIS_KEYS = (Key("case", "file", "the axis's case file, relative to the machine file"),
             Key("start", "time", "when the axis's cycle starts in the machine's cycle", "t_start", "0 s", "s"))
RESISTOR_KEYS = (Key("resistance", "resistance", "resistance of the bus's brake resistor", "R_br", unit="ohm"),
                 Key("continuous_power", "power", "continuous power the resistor takes", "P_R", unit="W"),
                 Key("peak_power", "power", "peak power the resistor takes", "P_R_peak", unit="W"))
SUPPLY_KEYS = (Key("part", "text", "the supply module as ordered"),
               Key("continuous_power", "power", "continuous DC power of the supply module", "P_N", unit="W"),
               Key("peak_power", "power", "peak DC power of the supply module", "P_max", unit="W"))
BUS_KEYS = (Key("dc_link_energy", "energy", "energy the bus's DC links absorb together (default: the sum of the "
                "axes' drives' E_C, where each is known)", "E_C", unit="J"),
            Key("brake_resistor", "table", "the bus's brake resistor", keys=RESISTOR_KEYS),
            Key("supply", "table", "the supply module: its part and typed ratings", keys=SUPPLY_KEYS))
MACHINE_KEYS = (Key("title", "text", "the machine's title"),
                Key("cycle", "time", "the machine's cycle: each axis's cycle divides it", "t_cycle", unit="s"),
                Key("axis", "tables", "the axes ([[axis]])", keys=AXIS_KEYS),
                Key("dc_bus", "table", "the shared DC bus", keys=BUS_KEYS))


@dataclass(frozen=True)
class Axis:
    """One axis of the machine as read: its case file and start, and the results of its case.

    Parameters
    ----------
    name : str
        ``axis[1]``.
    path : pathlib.Path
        Its case file.
    start : float [s]
        When its cycle starts in the machine's.
    results : calc.sections.evaluation.Results
        The case evaluated.
    """

    name: str
    path: Path
    start: float
    results: object

    @property
    def at_motor(self) -> tuple:
        """Durations [s] and the motor's power [W] of the samples of the axis's cycle."""
        dt, speed, T_1 = self.results.every["motor"]._at_motor
        return dt, T_1 * speed


def read_machine(path) -> tuple:
    """A machine file read, and each axis's case read and evaluated (each distinct file once).

    Parameters
    ----------
    path : str or pathlib.Path
        The machine file.

    Returns
    -------
    tuple
        ``(title, cycle [s], list of Axis, the [dc_bus] table or None)``.

    Raises
    ------
    CalcError
        Naming the file and key: a file that does not read, an axis cycle that does not divide
        the machine's, an axis without the motor's torques.
    """
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8-sig"))
    except (OSError, UnicodeDecodeError) as exc:
        raise CalcError(f"{path}: cannot read the machine file ({type(exc).__name__})") from None
    except tomllib.TOMLDecodeError as exc:
        raise CalcError(f"{path}: TOML syntax error: {exc}") from None
    top = Table(path, "", data, MACHINE_KEYS)
    cycle = float(top.positive("cycle", required=True).m_as("s"))
    tables = top.tables("axis", AXIS_KEYS)
    if not tables:
        raise CalcError(f"{path}: axis: expected one [[axis]] table per axis, found none")
    done, axes = {}, []
    for t in tables:
        name = t.text("case", required=True)
        file = (path.parent / name).resolve()
        if file not in done:
            try:
                done[file] = evaluate(read_case(file))
            except CalcError as exc:
                raise CalcError(f"{t.where('case')}: the axis's case file does not read: {exc}") from None
        results = done[file]
        if results.every.get("motor") is None or results.every["motor"].load is None:
            raise CalcError(f"{t.where('case')}: expected a case whose motor's torques are known, found none in "
                            f"{display_path(file)}")
        t_axis = float(results.case.profile.t_cycle.m_as("s"))
        n = cycle / t_axis
        if abs(n - round(n)) > BOUNDARY_RTOL * n or round(n) < 1:
            raise CalcError(f"{t.where('case')}: the axis's cycle of {t_axis:g} s does not divide the machine's "
                            f"cycle of {cycle:g} s (cycle)")
        start = t.quantity("start")
        axes.append(Axis(t.name, file, 0.0 if start is None else float(start.m_as("s")), results))
    bus = top.table("dc_bus", BUS_KEYS)
    return top.text("title", default=path.stem), cycle, axes, bus


@dataclass
class MachineResult:
    """The machine: its axes' verdicts and the shared DC bus.

    Parameters
    ----------
    title : str
        The machine's title.
    path : pathlib.Path
        The machine file.
    cycle : float [s]
        The machine's cycle.
    axes : list of Axis
        The axes.
    times : numpy.ndarray [s]
        The common time base's edges over one machine cycle.
    total : numpy.ndarray [W]
        The axes' summed DC-bus power over its steps.
    dc_link_energy : float or None [J]
        What the bus's DC links absorb of a net braking event.
    dc_link_from : str
        Where that comes from.
    checks : list of calc.core.checks.Check
        The bus's checks.
    notes : list of str
        What was assumed.
    """

    title: str
    path: Path
    cycle: float
    axes: list
    times: np.ndarray
    total: np.ndarray
    dc_link_energy: float | None
    dc_link_from: str
    checks: list
    notes: list = field(default_factory=list)

    def power_rows(self) -> dict:
        """Each axis's power and their sum over the time base, labelled for a figure.

        Returns
        -------
        tuple
            The steps' edges [s] (every axis's), and a dict: ``axis[1] (case file)`` -> power [W]
            over the steps, and ``sum``.
        """
        times, powers = bus_powers([a.at_motor for a in self.axes], [a.start for a in self.axes], self.cycle)
        rows = {f"{a.name} ({a.path.stem})": p for a, p in zip(self.axes, powers)}
        return times, {**rows, "sum": powers.sum(axis=0)}

    @property
    def dt(self) -> np.ndarray:
        """The time base's steps [s]."""
        return np.diff(self.times)

    @property
    def braking_energy_per_cycle(self) -> float:
        """The energy the axes give back that no other axis takes at the same moment, per machine
        cycle, before any DC link absorbs it [J]."""
        return float((np.maximum(-self.total, 0.0) * self.dt).sum())

    @property
    def resistor_energy_per_cycle(self) -> float:
        """What the net braking events leave for the bus's resistor per cycle [J]."""
        events = braking_events(self.dt, self.total)
        return float(resistor_energies(events, self.dc_link_energy or 0.0).sum())

    def verdict(self) -> Verdict:
        """The machine's verdict: each axis's and the bus's checks.

        Returns
        -------
        calc.sections.common.Verdict
        """
        axes = [Verdict(a.results.verdict.passes, [f"{a.name}: {r}" for r in a.results.verdict.reasons])
                for a in self.axes]
        bus = Verdict(passes_all(self.checks), [f"dc_bus: {k.reason()}" for k in self.checks if k.passes is not True])
        return Verdict.combine(axes + ([bus] if self.checks else []), "nothing is checked")

    def to_json(self) -> dict:
        """The machine's results as the contract writes them.

        Returns
        -------
        dict
            ``title``, ``machine``, ``cycle``, ``verdict``, ``axes``, ``dc_bus``.
        """
        w = self.total

        def q(x, unit):
            return None if x is None else quantity(Q_(x, unit), unit, "dc_bus")
        positive = float((np.maximum(w, 0.0) * self.dt).sum() / self.cycle)
        return {
            "title": self.title, "machine": display_path(self.path), "cycle": q(self.cycle, "s"),
            "verdict": self.verdict().to_json(),
            "axes": [{"axis": a.name, "case": display_path(a.path), "start": q(a.start, "s"),
                      "verdict": a.results.verdict.to_json(),
                      "peak_power": q(float(p.max()), "W"), "braking_power_peak": q(float(max(-p.min(), 0.0)), "W")}
                     for a, p in ((a, a.at_motor[1]) for a in self.axes)],
            "dc_bus": {"peak_power": q(float(w.max()), "W"), "average_power": q(positive, "W"),
                       "braking_energy_per_cycle": q(self.braking_energy_per_cycle, "J"),
                       "dc_link_energy": q(self.dc_link_energy, "J"), "dc_link_energy_from": self.dc_link_from,
                       "resistor_energy_per_cycle": q(self.resistor_energy_per_cycle, "J"),
                       "resistor_average_power": q(self.resistor_energy_per_cycle / self.cycle, "W"),
                       "checks": [check_json(k) for k in self.checks], "notes": list(self.notes)},
        }

    def summary(self) -> str:
        """The machine as a short report for a terminal.

        Returns
        -------
        str
        """
        j = self.to_json()
        v = self.verdict()
        b = j["dc_bus"]
        lines = [self.title, "=" * len(self.title), f"Verdict: {v.word}", *[f"  {r}" for r in v.reasons], "",
                 f"Machine cycle {self.cycle:g} s, {len(self.axes)} axes on one DC bus:"]
        lines += [f"  {a['axis']:<10} {a['case']:<40} start {a['start']['value']:g} s  {x.results.verdict.word}"
                  for a, x in zip(j["axes"], self.axes)]
        lines.append(f"DC bus: peak {b['peak_power']['value']:.4g} W, average {b['average_power']['value']:.4g} W; "
                     f"{b['braking_energy_per_cycle']['value']:.4g} J given back per cycle that no axis takes; "
                     f"{b['resistor_energy_per_cycle']['value']:.4g} J to the resistor "
                     f"({b['resistor_average_power']['value']:.4g} W average)")
        lines += [f"        {check_line(k)}" for k in self.checks]
        return "\n".join(lines + [f"  Note: {n}" for n in self.notes])


def bus_energy(bus, axes: list) -> tuple:
    """What the bus's DC links absorb of a net braking event: ``dc_bus.dc_link_energy``, else the
    sum of the axes' drives' ``E_C`` (the capacitances add), where every axis's is known.

    Parameters
    ----------
    bus : calc.sections.case.Table or None
        ``[dc_bus]``.
    axes : list of Axis
        The axes.

    Returns
    -------
    tuple
        ``(E_C [J] or None, where from)``.
    """
    if bus is not None and bus.has("dc_link_energy"):
        return float(bus.positive("dc_link_energy").m_as("J")), "dc_bus.dc_link_energy"
    drives = [a.results.every.get("drive") for a in axes]
    known = [d.braking.dc_link_energy for d in drives if d is not None]
    if not known or len(known) < len(axes) or any(x is None for x in known):
        return None, "not known: give dc_bus.dc_link_energy, or a drive whose E_C is known on every axis"
    return float(sum(known)), "the sum of the axes' drives' E_C"


def bus_checks(bus, total: np.ndarray, dt: np.ndarray, cycle: float, resistor_energy: float) -> list:
    """The bus's checks: its resistor's average and peak power, the supply's continuous and peak power.

    Parameters
    ----------
    bus : calc.sections.case.Table or None
        ``[dc_bus]``.
    total : numpy.ndarray [W]
        The axes' summed power over the steps.
    dt : numpy.ndarray [s]
        The steps.
    cycle : float [s]
        The machine's cycle.
    resistor_energy : float [J]
        What the resistor takes per cycle.

    Returns
    -------
    list of calc.core.checks.Check
        Those the table's values allow.
    """
    if bus is None:
        return []
    out: list[Check] = []
    r = bus.table("brake_resistor", RESISTOR_KEYS)
    peak_braking = float(max(-total.min(), 0.0))
    if r is not None:
        for key, name, text, required in (("continuous_power", "P_R", "P_R,avg <= P_R", resistor_energy / cycle),
                                          ("peak_power", "P_R,peak", "P_brake,peak <= P_R,peak", peak_braking)):
            rated = r.positive(key)
            out.append(scalar_check(name, text, required, None if rated is None else float(rated.m_as("W")), "W",
                                    None if rated is not None else f"dc_bus.brake_resistor.{key} is not given"))
    s = bus.table("supply", SUPPLY_KEYS)
    if s is not None:
        average = float((np.maximum(total, 0.0) * dt).sum() / cycle)
        for key, name, text, required in (("continuous_power", "P_N", "P_avg <= P_N", average),
                                          ("peak_power", "P_max", "P_peak <= P_max", float(total.max()))):
            rated = s.positive(key)
            out.append(scalar_check(name, text, required, None if rated is None else float(rated.m_as("W")), "W",
                                    None if rated is not None else f"dc_bus.supply.{key} is not given"))
    return out


def machine(path) -> MachineResult:
    """A machine file evaluated: each axis as its own case, the DC bus shared.

    Parameters
    ----------
    path : str or pathlib.Path
        The machine file.

    Returns
    -------
    MachineResult
        The axes, their powers on one time base, and the bus's checks.
    """
    title, cycle, axes, bus = read_machine(path)
    times, total = bus_total([a.at_motor for a in axes], [a.start for a in axes], cycle)
    E_link, src = bus_energy(bus, axes)
    dt = np.diff(times)
    E_R = float(resistor_energies(braking_events(dt, total), E_link or 0.0).sum())
    notes = ["the axes' power at the DC bus is their motors' shaft power: the motors' and drives' losses are not "
             "subtracted"]
    if E_link is None:
        notes.append(f"the DC links' energy is {src}: taken as 0 J, the resistor's energy an upper bound")
    return MachineResult(title, Path(path), cycle, axes, times, total, E_link, src,
                         bus_checks(bus, total, dt, cycle, E_R), notes)
