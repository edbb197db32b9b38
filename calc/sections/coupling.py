"""The coupling of a case (``[coupling]``): its inputs, given or taken from the rest of the case
(``side = "input"``, E8), the candidates checked and ranked (:mod:`calc.domain.coupling`, E7 to E10)
and the ordering text of the one chosen."""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

from ..domain import coupling as cp
from ..data.bands import factor_table
from .case import Case, Declared, Key, Table
from ..data.catalog import Catalog, load_catalogs
from ..domain.coupling import (
    DEFAULT_SERVICE_FACTOR, SCHEMA, SIDES, TEMPERATURE_FACTORS, TYPES, CouplingSelection, DriveTrain, J_load_at_input,
    check_types, f_e_min, order_lines, select_coupling,
)
from ..core.errors import CalcError, listing, as_found
from ..domain.fits import parse_bore
from ..domain.gearbox import n_1
from ..domain.profile import Z_h
from ..domain.torsion import CouplingSpan, TrainMember, gearbox_at_input, inertia_at_output, load_at_input
from ..core.units import Q_, Value, fmt, sig
from .common import (SHOWN_CANDIDATES, Governing, Verdict, check_json, check_line, json_of, row_json,
                     selection_governing, selection_verdict)
from .protocol import Result, Section

NAME = "coupling"
ORDER = 50
_FROM_CASE = " (with side = \"input\": from the rest of the case)"
TABLES = (Declared(NAME, (
    Key("catalog", "catalog", "the coupling catalog(s): a name in catalogs/ or a path to a CSV file",
        default="couplings"),
    Key("type", "choice", "check only couplings of this type: bellows | elastomer | safety | line-shaft"),
    Key("part", "text", "check this one part instead of ranking the catalog"),
    Key("side", "choice", "where the coupling sits: input (between motor and gearbox) | output"),
    Key("accel_torque", "torque", "acceleration torque of the motor" + _FROM_CASE, "M_a", unit="N*m"),
    Key("drive_inertia", "inertia", "drive-side inertia, without the coupling" + _FROM_CASE, "J_drive",
        unit="kg*cm**2"),
    Key("load_inertia", "inertia", "load-side inertia as the coupling sees it, without the coupling (E8)" + _FROM_CASE,
        "J_load", unit="kg*cm**2"),
    Key("service_factor", "dimensionless", "load (shock) factor (E8)", "S_A", DEFAULT_SERVICE_FACTOR),
    Key("temperature", "temperature", "operating temperature, needed by elastomer couplings (E9)", "vartheta",
        unit="degC"),
    Key("excitation_frequency", "frequency", "excitation frequency of the drive: f_e >= 2 f_er (E7)", "f_er",
        unit="Hz"),
    Key("speed", "speed", "speed of the coupling" + _FROM_CASE, "n", unit="rpm"),
    Key("shaft_1", "bore", "bore 1 with its fit"),
    Key("shaft_2", "bore", "bore 2 with its fit"),
    Key("disengagement_torque", "torque", "disengagement torque of a safety coupling (E10)", "T_A",
        unit="N*m"),
    Key("shaft_distance", "length", "distance between the shafts of a line shaft", "A", unit="mm"),
    Key("temperature_factors", "factor table",
        "the table of the temperature factor K_ϑ (E9): source | roba-es | comintec | a path", default="source"),
    Key("start_factors", "factor table",
        "the table of the start factor S_z: roba-es | a path; the peak-torque check T_S · S_z · K_ϑ <= T_Kmax"),
    Key("starts_per_hour", "per_hour", "starts per hour for the start factor (default: Z_h, load cycles per hour)",
        "Z_h",
        unit="1/hour"),
), "the coupling: its inputs, the candidates checked and ranked, and the order line of the one chosen"),)


@dataclass
class CouplingInputs:
    """The ``[coupling]`` table as read with the case: the candidates (the catalog narrowed to
    the part or type asked for), where the coupling sits, its shafts, each quantity the table
    gives (or its declared default; None where neither) and the factor tables.

    Parameters
    ----------
    table : dict
        The ``[coupling]`` table as written.
    catalog : calc.data.catalog.Catalog
        The candidates: the catalog narrowed to the part or type asked for.
    type : str or None
        The coupling type asked for (:data:`calc.domain.coupling.TYPES`); None: any.
    side : str or None
        Where the coupling sits: ``"input"`` between motor and gearbox, ``"output"`` between
        gearbox and load; None where the table does not say.
    bores : tuple of calc.domain.fits.Bore
        ``shaft_1`` and ``shaft_2`` with their fits.
    given : dict
        Key of :data:`QUANTITIES` to the quantity the table gives (or its declared default; None
        where neither).
    temperature_factors : calc.data.bands.BandTable
        The table of the temperature factor K_ϑ (E9).
    start_factors : calc.data.bands.BandTable or None, optional
        The table of the start factor S_z, where the table names one.
    """

    table: dict
    catalog: Catalog
    type: str | None
    side: str | None
    bores: tuple
    given: dict
    temperature_factors: object
    start_factors: object = None

    def has(self, key: str) -> bool:
        """Whether the table gives a key (a declared default does not count).

        Parameters
        ----------
        key : str
            A key of ``[coupling]`` (``"load_inertia"``).

        Returns
        -------
        bool
            True where the table as written holds it.
        """
        return key in self.table


#: The quantities of ``[coupling]``; with ``side = "input"`` those of :data:`FROM_THE_CASE` the
#: table leaves out come from the rest of the case when evaluated.
QUANTITIES = ("accel_torque", "drive_inertia", "load_inertia", "excitation_frequency", "service_factor", "temperature",
              "speed", "disengagement_torque", "shaft_distance", "starts_per_hour")
FROM_THE_CASE = ("accel_torque", "drive_inertia", "load_inertia", "speed", "starts_per_hour")


@dataclass
class CouplingCase:
    """The ``[coupling]`` section as evaluated: the candidates and the arguments of
    :func:`select_coupling`, with what it takes from the rest of the case.

    Parameters
    ----------
    catalog : calc.data.catalog.Catalog
        The candidates.
    type : str or None
        The coupling type asked for; None: any.
    side : str or None
        Where the coupling sits: ``"input"`` between motor and gearbox, ``"output"`` between
        gearbox and load; None where the table does not say.
    inputs : dict
        The keyword arguments of :func:`select_coupling`: each key of :data:`QUANTITIES` to its
        quantity (None where neither the table nor the case gives it), and the factor tables.
    bores : tuple of calc.domain.fits.Bore
        ``shaft_1`` and ``shaft_2`` with their fits.
    derived : list of str
        What was taken from the rest of the case (``side = "input"``), as sentences.
    missing : dict, optional
        Key to what the case lacks for it (``side = "input"``); its checks are not made.
    drive_train : calc.domain.coupling.DriveTrain or None, optional
        The members around the coupling (:mod:`calc.domain.torsion`); None without the inertias
        of its two sides.
    drive_steps : tuple, optional
        (title, :class:`calc.core.formula.Step`) of each member referred to the coupling's shaft.
    steps : list, optional
        (title, :class:`calc.core.formula.Step`) of each input computed from the rest of the case,
        as computed.
    """

    catalog: Catalog
    type: str | None
    side: str | None
    inputs: dict
    bores: tuple
    derived: list
    missing: dict = field(default_factory=dict)
    drive_train: DriveTrain | None = None
    drive_steps: tuple = ()
    steps: list = field(default_factory=list)


def read_inputs(case: Case) -> CouplingInputs:
    """Read ``[coupling]`` key by key; errors name the file and the key.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case being read, its load cycle, motor and gearbox read.

    Returns
    -------
    CouplingInputs
        The candidates, the side, the shafts, the quantities and the factor tables.
    """
    s = Table(case.path, NAME, case.sections[NAME], TABLES[0].keys)
    catalog, wanted = _candidates(case, s)
    side = s.text("side")
    if side is not None and side not in SIDES:
        raise CalcError(f"{s.where('side')}: expected one of {listing(SIDES)}, found {as_found(side)}")
    derivable = FROM_THE_CASE[:3] if side == "input" else ()  # speed only with a gearbox: not among the keys needed
    for key in ("accel_torque", "drive_inertia", "load_inertia", "excitation_frequency", "shaft_1", "shaft_2"):
        if not s.has(key) and key not in derivable:
            hint = (" (with side = \"input\" it comes from [motor], [load] and the gearbox when they give it)"
                    if side == "input" else "")
            raise CalcError(f"{s.where(key)}: expected a value{hint}, found none")
    bores = tuple(parse_bore(s.data[key], s.where(key)) for key in ("shaft_1", "shaft_2"))
    given = {key: s.quantity(key) for key in QUANTITIES}
    temperature = factor_table("temperature", s.text("temperature_factors"), case.folder,
                               s.where("temperature_factors"))
    starts = None
    if s.has("start_factors"):
        starts = factor_table("starts", s.text("start_factors"), case.folder, s.where("start_factors"))
    return CouplingInputs(s.data, catalog, wanted, side, bores, given, temperature, starts)


def coupling_case(case: Case, given: CouplingInputs, gearbox) -> CouplingCase:
    """The coupling's inputs as given, with what a coupling between motor and gearbox takes from
    the rest of the case, and the drive train around it.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with.
    given : CouplingInputs
        The ``[coupling]`` table as read.
    gearbox : calc.sections.gearbox.GearboxResult or None
        The gearbox section's result; None where the case has no gearbox.

    Returns
    -------
    CouplingCase
        The arguments of :func:`select_coupling`, what was taken from the case and what it lacks,
        and the drive train with the steps that referred its members to the coupling's shaft.
    """
    derived, derived_steps = _from_the_case(case, gearbox) if given.side == "input" else ({}, {})
    if given.start_factors is not None and not given.has("starts_per_hour"):
        # One start from rest per load cycle (move), E16.
        z = Z_h(**case.profile.cycles_per_hour_inputs())
        derived["starts_per_hour"] = (z, "starts_per_hour = Z_h of the load cycle (one start per load cycle, E16) = "
                                         f"{fmt(z, '1/hour')}")
    inputs = {key: given.given[key] if given.has(key) or key not in FROM_THE_CASE else derived.get(key, (None, ""))[0]
              for key in QUANTITIES}
    inputs["temperature_factors"] = given.temperature_factors
    if given.start_factors is not None:
        inputs["start_factors"] = given.start_factors
    notes = [text for key, (q, text) in derived.items() if not given.has(key) and q is not None]
    missing = {key: text for key, (q, text) in derived.items() if not given.has(key) and q is None}
    steps = [step for key, step in derived_steps.items() if not given.has(key)]
    return CouplingCase(given.catalog, given.type, given.side, inputs, given.bores, notes, missing,
                        *_drive_train(case, given.side, inputs, gearbox), steps=steps)


def _candidates(case: Case, s: Table) -> tuple[Catalog, str | None]:
    """The section's coupling catalog narrowed to its ``part`` or ``type``, and the type asked for.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case being read (its folder, where catalogs given as paths are found).
    s : calc.sections.case.Table
        The ``[coupling]`` table.

    Returns
    -------
    tuple
        (:class:`calc.data.catalog.Catalog` of the candidates, the type asked for or None).
    """
    catalog = load_catalogs(s.catalogs("catalog"), case.folder, s.where("catalog"), SCHEMA)
    check_types(catalog)
    wanted = s.text("type")
    if wanted is not None and wanted not in TYPES:
        raise CalcError(f"{s.where('type')}: unknown coupling type {as_found(wanted)}; expected one of "
                        f"{listing(TYPES)}")
    part = s.text("part")
    if part is not None:
        row = catalog.usable_index(part, s.where("part"))
        if wanted is not None and catalog.text["type"][row] != wanted:
            raise CalcError(f"{s.where('part')}: {part} is a {catalog.text['type'][row]} coupling, "
                            f"but coupling.type is {as_found(wanted)}")
        return catalog.rows([row]), wanted
    if wanted is not None:
        mask = catalog.text["type"] == wanted
        if not mask.any():
            raise CalcError(f"{s.where('type')}: the catalog {catalog.shown_name} has no {wanted} coupling")
        catalog = catalog.rows(mask)
    return catalog, wanted


def coupling_span(case: Case) -> CouplingSpan | None:
    """The couplings the case may fit between motor and gearbox, with the motor's and the load's
    inertia and ``2 f_er``: what the gearbox selection bounds each row's drive train with
    (:func:`calc.domain.gearbox.select_gearbox`).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with.

    Returns
    -------
    calc.domain.torsion.CouplingSpan or None
        The candidates' stiffnesses and inertias with the drive's and the load's inertia and
        ``2 f_er``. None where the case has no coupling there, or gives no motor inertia, load
        inertia or excitation frequency, or no candidate has a stiffness and an inertia (a line
        shaft's stiffness needs its length: line shafts are left out).
    """
    given = SECTION.inputs(case)
    if given is None:
        return None
    drive = given.given["drive_inertia"] if given.has("drive_inertia") else case.motor_inertia
    if given.side != "input" or not given.has("excitation_frequency") or drive is None or case.load_inertia is None:
        return None
    catalog, wanted = given.catalog, given.type
    known = (~np.isnan(catalog["C_T"].magnitude) & ~np.isnan(catalog["J"].magnitude)
             & (catalog.text["type"] != "line-shaft"))
    if not known.any():
        return None
    rows = catalog.rows(known)
    which = (str(rows.parts[0]) if given.has("part")
             else f"the {wanted + ' ' if wanted else ''}couplings of {rows.shown_name}")
    two_f_er = f_e_min(f_er=given.given["excitation_frequency"])
    return CouplingSpan(drive, case.load_inertia, rows["C_T"], rows["J"], two_f_er, which)


def _drive_train(case: Case, side: str | None, inputs: dict, gearbox) -> tuple[DriveTrain | None, tuple]:
    """The drive train around the coupling, every member referred to the coupling's shaft
    (:mod:`calc.domain.torsion`), and the steps that referred them there.

    Without a gearbox (a direct drive) the chain is the drive, the coupling and the load as
    the section gives them. With a gearbox, between motor and gearbox (``side = "input"``): the
    motor, the coupling, the gearbox's ``J_1`` and its ``C_t21 / i²``, the load ``J_L / i²``;
    between gearbox and load (``side = "output"``): the motor and ``J_1`` times ``i²``, the
    gearbox's ``C_t21``, the coupling, the load as the section gives it. A member the case does not
    give is named in ``missing`` and left out (the gearbox then counts as rigid), so the chain
    still has the coupling's two sides. Without the inertias of the coupling's two sides (a partial
    case) there is no chain: the resonance checks are then not made (:func:`select_coupling`).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with.
    side : str or None
        Where the coupling sits (``coupling.side``).
    inputs : dict
        The coupling's inputs as evaluated (:attr:`CouplingCase.inputs`).
    gearbox : calc.sections.gearbox.GearboxResult or None
        The gearbox section's result; None where the case has no gearbox.

    Returns
    -------
    tuple
        (:class:`calc.domain.coupling.DriveTrain` or None, (title, :class:`calc.core.formula.Step`)
        of each member referred to the coupling's shaft).
    """
    if inputs["drive_inertia"] is None or inputs["load_inertia"] is None:
        return None, ()
    two_mass = (TrainMember("motor", inputs["drive_inertia"]),), (TrainMember("load", inputs["load_inertia"]),)
    if gearbox is None:
        return DriveTrain(*two_mass), ()
    if side is None:
        side_missing = ("coupling.side (where the coupling sits: input or output of the gearbox)",)
        return DriveTrain(*two_mass, missing=side_missing), ()
    selection = gearbox.selection
    row = selection.order[0]
    part = str(selection.catalog.parts[row])
    i, C_t21, J_1 = selection.catalog["ratio"][row], selection.catalog["C_t21"][row], selection.J_1[row]
    missing = []
    if np.isnan(C_t21.magnitude):
        missing.append(f"the gearbox's torsional stiffness C_t21 ({part}: the catalog leaves it empty)")
    if np.isnan(J_1.magnitude):
        missing.append(f"the gearbox's J_1 ({part}: the catalog gives none for the motor's shaft)")
    end, shaft = ("load", "the gearbox input") if side == "input" else ("motor", "the gearbox output")
    given = {"load": case.load_inertia, "motor": case.motor_inertia}[end]
    if given is None:
        missing.append(f"the {end}'s inertia ({'[load] inertia or [mechanism]' if end == 'load' else 'motor.inertia'})")
    if missing:
        return DriveTrain(*two_mass, missing=tuple(missing), shaft=shaft), ()
    # A gearbox that is not selected stands in for the one the case will get: its modes inform.
    stand_in = (() if selection.selected == part
                else (f"a selected gearbox ({part}, the best-ranked, stands in: none is selected)",))
    if side == "input":
        j_l = load_at_input.step(J_L=given, i=i)
        c_g = gearbox_at_input.step(C_t21=C_t21, i=i)
        steps = (("Load reflected to the gearbox input", j_l), (f"Stiffness of {part} at its input", c_g))
        load = (TrainMember("gearbox", J_1, c_g.result), TrainMember("load", j_l.result))
        train = DriveTrain(two_mass[0], load, stand_in, shaft)
        return train, steps
    j_m = inertia_at_output.step(J_in=given, i=i)
    j_g = inertia_at_output.step(J_in=J_1, i=i)
    steps = (("Motor referred to the gearbox output", j_m), (f"J_1 of {part} referred to its output", j_g))
    drive = (TrainMember("motor", j_m.result), TrainMember("gearbox", j_g.result, C_t21))
    return DriveTrain(drive, two_mass[1], stand_in, shaft), steps


def _from_the_case(case: Case, gearbox) -> tuple[dict, dict]:
    """What a coupling between motor and gearbox can take from the rest of the case.

    ``load_inertia`` is the load reflected to the input plus the gearbox's J_1 (E8), ``speed`` the
    highest input speed ``n_2max · i``, ``accel_torque`` the motor's peak torque and
    ``drive_inertia`` the motor's inertia. A key given in the section is used as given. Where the
    case does not give what ``accel_torque``, ``drive_inertia`` or ``load_inertia`` needs, the key
    holds ``(None, what is missing)``: the checks that need it are not made, naming it (the
    contract's partial cases).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with.
    gearbox : calc.sections.gearbox.GearboxResult or None
        The gearbox section's result; None without one.

    Returns
    -------
    tuple of dict
        By key ``(quantity, sentence)``, and the calculations among them, by key
        ``(title, Step)``.
    """
    out = {
        "accel_torque": (None, "motor.peak_torque (or coupling.accel_torque)"),
        "drive_inertia": (None, "motor.inertia (or coupling.drive_inertia)"),
        "load_inertia": (None, "load.inertia (or the mechanism's) and a gearbox, or coupling.load_inertia"),
    }
    steps = {}
    if case.motor_peak_torque is not None:
        out["accel_torque"] = (case.motor_peak_torque,
                               f"accel_torque M_a = motor.peak_torque = {fmt(case.motor_peak_torque, 'N*m')}")
    if case.motor_inertia is not None:
        out["drive_inertia"] = (case.motor_inertia,
                                f"drive_inertia J_drive = motor.inertia = {fmt(case.motor_inertia, 'kg*cm**2')}")
    if gearbox is None:
        return out, steps
    selection = gearbox.selection
    row = selection.order[0]
    part = str(selection.catalog.parts[row])
    i = selection.catalog["ratio"][row]
    speed = n_1(n_2=case.profile.n_2max, i=i)
    out["speed"] = (speed, f"speed = n_2max · i = {fmt(case.profile.n_2max, 'rpm')} · {sig(i.m_as(''))} = "
                           f"{fmt(speed, 'rpm')}")
    J_1, hub = selection.J_1[row], selection.J_1_hub[row]
    if case.load_inertia is None:
        out["load_inertia"] = (None, "load.inertia (or the mechanism's), or coupling.load_inertia")
    elif np.isnan(J_1.magnitude):
        out["load_inertia"] = (None, f"the gearbox's J_1, which {selection.catalog.catalog_of(row)} does not give "
                                     f"for {part} (or coupling.load_inertia)")
    else:
        step = J_load_at_input.step(J_L=case.load_inertia, i=i, J_1=J_1)
        J = step.result
        which = part if selection.passes[row] else f"{part}, the best-ranked gearbox (none passes)"
        which += "" if np.isnan(hub.magnitude) else f", {fmt(hub, 'mm')} clamping hub"
        steps["load_inertia"] = (f"Load inertia seen by the coupling, through {which}", step)
        out["load_inertia"] = (
            J,
            f"load_inertia J_load = J_L / i² + J_1 = {fmt(case.load_inertia, 'kg*cm**2')} / {sig(i.m_as(''))}² + "
            f"{fmt(J_1, 'kg*cm**2')} ({which}) = {fmt(J, 'kg*cm**2')} (E8)",
        )
    return out, steps


def coupling_selection(cc: CouplingCase, where: str) -> CouplingSelection:
    """The candidates of the coupling as evaluated (:func:`coupling_case`), checked and ranked.

    Parameters
    ----------
    cc : CouplingCase
        The ``[coupling]`` section as evaluated.
    where : str
        The file and table errors name (``case.toml: coupling``).

    Returns
    -------
    calc.domain.coupling.CouplingSelection
        The candidates checked and ranked, with the drive train's modes.
    """
    return select_coupling(cc.catalog, shaft_1=cc.bores[0], shaft_2=cc.bores[1], drive_train=cc.drive_train,
                           where=where, sources=cc.missing, **cc.inputs)


@dataclass(frozen=True)
class Torsion:
    """The drive train's torsional modes (:mod:`calc.domain.torsion`) with the best-ranked coupling:
    its masses and springs referred to ``shaft``, drive to load, the natural frequencies lowest
    first without the rigid-body mode, and the check of the first against 2 f_er.

    Parameters
    ----------
    part : str
        The best-ranked coupling.
    shaft : str
        The shaft the members are referred to (``"the gearbox input"``).
    complete : bool
        Whether the chain holds every member (else some are named in ``missing``).
    missing : list of str
        The members the case does not give, left out.
    masses : list of tuple
        (members, J: :class:`calc.core.units.Value` [kg*cm**2]) of each mass, drive to load.
    springs : list of tuple
        (member, C: :class:`calc.core.units.Value` [N*m/rad]) of each spring, one fewer than the
        masses.
    natural_frequencies : list of calc.core.units.Value
        The natural frequencies [Hz], lowest first, the rigid-body mode left out.
    checks : list of calc.core.checks.Check
        The check of the first natural frequency against 2 f_er.
    """

    part: str
    shaft: str
    complete: bool
    missing: list
    masses: list
    springs: list
    natural_frequencies: list
    checks: list

    def to_json(self) -> dict:
        """The drive train as the JSON contract writes it (``coupling.torsion``).

        Returns
        -------
        dict
            Part, shaft, completeness, the members missing, masses, springs, natural frequencies
            and checks.
        """
        return {
            "part": self.part,
            "shaft": self.shaft,
            "complete": self.complete,
            "missing": list(self.missing),
            "masses": [{"members": name, "J": J.to_json()} for name, J in self.masses],
            "springs": [{"member": name, "C": C.to_json()} for name, C in self.springs],
            "natural_frequencies": [f.to_json() for f in self.natural_frequencies],
            "checks": [check_json(c) for c in self.checks],
        }

    def lines(self) -> list[str]:
        """The chain and its modes as lines of the text summary.

        Returns
        -------
        list of str
            The chain, drive to load; its natural frequencies; the check of the first.
        """
        chain = " | ".join([f"{name} {J}" for name, J in self.masses[:1]]
                           + [f"{spring} {C} | {name} {J}"
                              for (spring, C), (name, J) in zip(self.springs, self.masses[1:])])
        return [
            f"Drive train with {self.part}, at {self.shaft}{'' if self.complete else ' (incomplete)'}: {chain}",
            f"  natural frequencies {', '.join(map(str, self.natural_frequencies))} (rigid-body mode left out)",
            *[f"  {check_line(c, 20)}" for c in self.checks],
        ]


@dataclass(frozen=True)
class BoreResult:
    """A shaft of the coupling as written and as its fit gives it (ISO 286).

    Parameters
    ----------
    key : str
        Its key in ``[coupling]`` (``"shaft_1"``).
    text : str
        As written.
    nominal : calc.core.units.Value
        The nominal diameter [mm].
    tolerance : str or None
        The ISO 286 class (``"k6"``) or the limits as written; None where the text gives none.
    limits : str
        The limits of size as text.
    lower, upper : calc.core.units.Value or None
        The lower and upper limits of size [mm]; None without a tolerance.
    keyway : calc.core.units.Value or None
        The keyway's width [mm]; None without one.
    """

    key: str
    text: str
    nominal: Value
    tolerance: str | None
    limits: str
    lower: Value | None
    upper: Value | None
    keyway: Value | None

    def to_json(self) -> dict:
        """The shaft as the JSON contract writes it (an entry of ``coupling.bores``).

        Returns
        -------
        dict
            Key, text, nominal diameter, tolerance, limits and keyway.
        """
        return {"key": self.key, "text": self.text, "nominal": self.nominal.to_json(), "tolerance": self.tolerance,
                "limits": self.limits, "lower": json_of(self.lower), "upper": json_of(self.upper),
                "keyway": json_of(self.keyway)}


#: How the coupling candidates are ranked (:func:`calc.core.checks.rank`).
RANKING = ("passing first; published rows before illustrative ones; then smallest rated torque T_KN; "
           "then lowest worst utilization")


@dataclass
class CouplingResult(Result):
    """The coupling section as read, its candidates checked and ranked, and the part chosen; the
    figures every output prints are computed once here.

    Parameters
    ----------
    inputs : CouplingCase
        The ``[coupling]`` section as evaluated.
    selection : calc.domain.coupling.CouplingSelection
        Its candidates checked and ranked (:func:`coupling_selection`).
    """

    inputs: CouplingCase
    selection: CouplingSelection
    ranking = RANKING

    @functools.cached_property
    def notes(self) -> list[str]:
        """What the case left to the package, and what it does not give (a shaft's tolerance)."""
        cc = self.inputs
        out = [f"taken from the case: {text}" for text in cc.derived] + list(self.selection.notes)
        return out + [f"coupling.shaft_{k} gives no tolerance; state one when ordering "
                      "(the source asks for shaft sizes and tolerances)"
                      for k, bore in enumerate(cc.bores, start=1) if bore.tolerance is None]

    @functools.cached_property
    def order(self) -> str | None:
        """The order line of the chosen coupling; None where none is chosen."""
        cc, sel = self.inputs, self.selection
        if sel.selected is None:
            return None
        t = sel.row_type(int(sel.order[0]))
        return "; ".join(order_lines(sel.selected, t, cc.bores,
                                     cc.inputs["disengagement_torque"] if t == "safety" else None,
                                     cc.inputs["shaft_distance"] if t == "line-shaft" else None))

    @property
    def M_N(self) -> Value:
        """The nominal torque the coupling must carry [N*m] (E8)."""
        return Value.of(self.selection.M_N, "N*m")

    @property
    def T_op(self) -> Value:
        """The operating torque [N*m]."""
        return Value.of(self.selection.T_op, "N*m")

    @property
    def service_factor(self) -> float:
        """The load (shock) factor S_A [1] (E8)."""
        return float(self.inputs.inputs["service_factor"].m_as(""))

    @property
    def temperature(self) -> Value | None:
        """The operating temperature [degC]; None where the case gives none."""
        t = self.inputs.inputs["temperature"]
        return None if t is None else Value.of(t, "degC")

    @property
    def temperature_factor(self) -> float:
        """K_ϑ of the elastomer couplings (1 where there are none)."""
        sel = self.selection
        elastomer = sel.catalog.text["type"] == "elastomer"
        return float(sel.temperature_factor[elastomer][0]) if elastomer.any() else 1.0

    @property
    def temperature_factors(self) -> str:
        """The source of the table of K_ϑ (E9)."""
        return self.inputs.inputs["temperature_factors"].source

    @property
    def start_factors(self) -> str | None:
        """The source of the table of S_z; None where the case names none."""
        return None if "start_factors" not in self.inputs.inputs else self.inputs.inputs["start_factors"].source

    @property
    def starts_per_hour(self) -> Value | None:
        """The starts per hour the start factor is read at [1/hour]; None without a table of S_z."""
        z = self.inputs.inputs["starts_per_hour"]
        return None if z is None else Value.of(z, "1/hour")

    @property
    def f_e_min(self) -> Value:
        """The lowest natural frequency allowed, 2 f_er [Hz] (E7)."""
        return Value.of(f_e_min(f_er=self.inputs.inputs["excitation_frequency"]), "Hz")

    @property
    def bores(self) -> list[BoreResult]:
        """The coupling's two shafts as written and as their fits give them."""
        def length(q):
            return None if q is None else Value.of(q, "mm")

        return [BoreResult(f"shaft_{k}", b.text, Value.of(b.nominal, "mm"), b.tolerance, b.limits_text(),
                           length(b.lower), length(b.upper), length(b.keyway))
                for k, b in enumerate(self.inputs.bores, start=1)]

    @functools.cached_property
    def torsion(self) -> Torsion | None:
        """The drive train's modes with the best-ranked coupling; None without the drive train."""
        sel = self.selection
        if sel.chain is None:
            return None
        row = int(sel.order[0])
        chain, train = sel.chain, sel.drive_train
        part = str(sel.catalog.parts[row])
        empty = [f"the {name}'s stiffness ({part if name == 'coupling' else name}: the catalog leaves it empty)"
                 for name, C in zip(chain.springs, chain.stiffnesses[row]) if np.isnan(C.magnitude)]
        empty += [f"the inertia of {name} ({part}: the catalog leaves the coupling's J empty)"
                  for name, J in zip(chain.masses, chain.inertias[row]) if np.isnan(J.magnitude)]
        return Torsion(
            part=part, shaft=train.shaft, complete=train.complete and not empty, missing=list(train.missing) + empty,
            masses=[(name, Value.of(chain.inertias[row, k], "kg*cm**2")) for k, name in enumerate(chain.masses)],
            springs=[(name, Value.of(chain.stiffnesses[row, k], "N*m/rad")) for k, name in enumerate(chain.springs)],
            natural_frequencies=[Value.of(f, "Hz") for f in sel.modes[row]],
            checks=[c.at(row) for c in sel.checks if c.name == "f_1"],
        )

    @functools.cached_property
    def torque_steps(self) -> list:
        """(title, Step, what it is compared with) of M_N; of an elastomer best-ranked row also
        M_N · K_ϑ and M_Smax; then 2 f_er. Empty where a check cannot be made (no M_N to show)."""
        x, sel = self.inputs.inputs, self.selection
        if sel.not_made:
            return []
        row = int(sel.order[0])
        part = str(sel.catalog.parts[row])
        m_n = cp.M_N.step(M_a=x["accel_torque"], J_load=x["load_inertia"], J_drive=x["drive_inertia"],
                          S_A=x["service_factor"])
        out = [("Nominal torque of the coupling", m_n, "compared with T_KN")]
        if sel.row_type(row) == "elastomer":
            bands = x["temperature_factors"]
            band = bands.text(int(bands.band(x["temperature"], "coupling.temperature")))
            k_t = Q_(float(sel.temperature_factor[row]), "")
            out.append((f"With the temperature factor ({part})", cp.M_Nt.step(M_N=m_n.result, K_T=k_t),
                        f"the factor of the band {band} ({bands.source})"))
            if sel.M_Smax is not None:
                starts = x["start_factors"]
                s_band = starts.text(int(starts.band(x["starts_per_hour"], "coupling.starts_per_hour")))
                out.append((f"Peak torque with the start and temperature factors ({part})",
                            cp.M_Smax.step(T_S=m_n.result, S_z=Q_(sel.start_factor, ""), K_T=k_t),
                            f"compared with T_Kmax; S_z of the band {s_band} ({starts.source})"))
        return out + [("Lowest natural frequency allowed", cp.f_e_min.step(f_er=x["excitation_frequency"]), "")]

    @functools.cached_property
    def resonance_steps(self) -> list:
        """(title, Step, what it is compared with) of the best-ranked row's two-mass natural
        frequency: J_A, J_L, a line shaft's stiffness, f_e. Empty where f_e has no value."""
        x, sel = self.inputs.inputs, self.selection
        row = int(sel.order[0])
        if sel.not_made or np.isnan(sel.f_e[row].magnitude):
            return []
        cat = sel.catalog
        J = cat["J"][row]
        out = [("Drive side with half the coupling", cp.J_A.step(J_drive=x["drive_inertia"], J_K=J), ""),
               ("Load side with half the coupling", cp.J_L.step(J_load=x["load_inertia"], J_K=J), "")]
        if sel.row_type(row) == "line-shaft" and x["shaft_distance"] is not None:
            z = cp.Z.step(A=x["shaft_distance"], H=cat["H"][row])
            c_t = cp.C_T_line.step(C_B=cat["C_T"][row], Z=z.result, C_tube=cat["C_tube"][row])
            out += [("Tube length", z, ""), ("Stiffness of the line shaft", c_t, "")]
        natural = cp.f_e.step(C_T=sel.C_T[row], J_A=sel.J_A[row], J_L_coupling=sel.J_L[row])
        return out + [("Natural frequency", natural, "compared with 2 f_er")]

    def to_json(self, candidates: int | None = SHOWN_CANDIDATES) -> dict:
        """The ``coupling`` results of the JSON contract.

        Parameters
        ----------
        candidates : int or None
            The most candidates listed, best first (all for None).

        Returns
        -------
        dict
            The catalog's provenance, the torques and factors, the bores, the ranked candidates,
            the part selected, its order line, the drive train and the notes.
        """
        cc, sel = self.inputs, self.selection
        listed = [
            {
                "part": c.part,
                "type": c.type,
                "illustrative": c.illustrative,
                "passes": c.passes,
                "f_e": c.f_e.to_json(),
                "f_1": json_of(c.f_1),
                "C_T": c.C_T.to_json(),
                "temperature_factor": c.temperature_factor,
                "required_torque": c.required_torque.to_json(),
                "peak_torque_required": json_of(c.peak_torque_required),
                "checks": [check_json(k) for k in c.checks],
                **row_json(c),
            }
            for c in sel.candidates(candidates)
        ]
        return {
            **cc.catalog.provenance(),
            "type": cc.type,
            "M_N": self.M_N.to_json(),
            "service_factor": self.service_factor,
            "T_op": self.T_op.to_json(),
            "temperature": json_of(self.temperature),
            "temperature_factor": self.temperature_factor,
            "temperature_factors": self.temperature_factors,
            "start_factors": self.start_factors,
            "starts_per_hour": json_of(self.starts_per_hour),
            "start_factor": sel.start_factor,
            "f_e_min": self.f_e_min.to_json(),
            "bores": [b.to_json() for b in self.bores],
            "ranking": self.ranking,
            "candidate_count": len(sel.order),
            "candidates": listed,
            "selected": sel.selected,
            "order": self.order,
            "torsion": None if self.torsion is None else self.torsion.to_json(),
            "notes": self.notes,
        }

    def summary_lines(self, candidates: int | None = SHOWN_CANDIDATES) -> list[str]:
        """The coupling results as lines of the terminal summary.

        Parameters
        ----------
        candidates : int or None
            The most candidates listed, best first (all for None).

        Returns
        -------
        list of str
            The torques and factors, the bores, each candidate listed with its checks, the part
            selected, the drive train, the order line and the notes.
        """
        cc, sel = self.inputs, self.selection
        table = "E9" if self.temperature_factors == TEMPERATURE_FACTORS.source else self.temperature_factors
        lines = [
            f"Coupling candidates (catalog {cc.catalog.shown_name}{', type ' + cc.type if cc.type else ''}):",
            f"  M_N = {self.M_N} (S_A = {self.service_factor:g}, E8); "
            f"temperature factor {self.temperature_factor:g} ({table}); 2 f_er = {self.f_e_min} (E7)",
        ]
        if sel.start_factor is not None:
            lines.append(f"  start factor S_z = {sel.start_factor:g} at {self.starts_per_hour} ({self.start_factors})")
        lines += [f"  {b.key}: {b.text} ({b.limits})" for b in self.bores]
        several = len(cc.catalog.members) > 1
        listed = sel.candidates(candidates)
        for c in listed:
            verdict = {True: "PASS", False: "FAIL", None: "OPEN"}[c.passes]
            where = f" [{c.catalog}]" if several else ""
            illustrative = ", illustrative" if c.illustrative else ""
            lines.append(f"  {verdict}  {c.part}{where} ({c.type}{illustrative}), f_e = {c.f_e}")
            lines += [f"        {check_line(k, 20)}" for k in c.checks]
            if c.unclear:
                lines.append(f"        doubtful figures: {c.unclear}")
            lines += [f"        rejected: {r}" for r in c.reasons]
        if len(sel.order) > len(listed):
            lines.append(f"  ... {len(sel.order) - len(listed)} more candidates (--all-candidates lists them)")
        lines.append(f"Selected coupling: {sel.selected or self.not_chosen}")
        lines += [] if self.torsion is None else self.torsion.lines()
        if self.order:
            lines.append(f"Order: {self.order}")
        lines += [f"Note: {n}" for n in self.notes]
        return lines

    @property
    def not_chosen(self) -> str:
        """Why no coupling is chosen: a check the case cannot feed, or none passes."""
        sel = self.selection
        if sel.not_made and sel.passes[sel.order[0]]:
            return "none: " + "; ".join(c.reason(int(sel.order[0])) for c in sel.not_made)
        return "none passes"

    def governing(self) -> Governing:
        """The governing checks of the best-ranked coupling.

        Returns
        -------
        calc.sections.common.Governing
            Its governing checks, chosen where a coupling is chosen
            (:func:`calc.sections.common.selection_governing`).
        """
        return selection_governing(NAME, self.selection)

    def ranked(self) -> CouplingSelection:
        """The candidates as ranked.

        Returns
        -------
        calc.domain.coupling.CouplingSelection
            The selection itself.
        """
        return self.selection

    def verdict(self) -> Verdict:
        """The verdict of the coupling selection.

        Returns
        -------
        calc.sections.common.Verdict
            Passes where a coupling is chosen; else why not
            (:func:`calc.sections.common.selection_verdict`).
        """
        return selection_verdict(self.selection, "coupling", "its checks")


class CouplingSection(Section):
    """The coupling: its table read with the case, its candidates checked with what it takes from
    the motor and the gearbox, and ranked."""

    NAME = NAME
    TABLES = TABLES
    REQUIRES = ("axis", "gearbox")

    def read_inputs(self, case: Case) -> CouplingInputs:
        """Read ``[coupling]`` with the case (:func:`read_inputs`).

        Parameters
        ----------
        case : calc.sections.case.Case
            The case being read.

        Returns
        -------
        CouplingInputs
            The table as read.
        """
        return read_inputs(case)

    def evaluate(self, case: Case, earlier) -> CouplingResult:
        """Check and rank the candidates with the motor the case is checked with and the gearbox.

        Parameters
        ----------
        case : calc.sections.case.Case
            The case as read (the axis's case, with its motor, is the one checked).
        earlier : dict
            The results of the sections evaluated before, by name: ``axis`` and, where the case
            has one, ``gearbox``.

        Returns
        -------
        CouplingResult
            The candidates checked and ranked, and the part chosen.
        """
        case = earlier["axis"].case
        cc = coupling_case(case, self.inputs(case), earlier.get("gearbox"))
        return CouplingResult(cc, coupling_selection(cc, f"{case.path}: coupling"))


SECTION = CouplingSection()
