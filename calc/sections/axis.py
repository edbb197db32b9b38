"""The motor and the load of a case (``[motor]``, ``[load]``): inputs that the gearbox, coupling
and motor sections share, and the motor the case is checked with: its typed ratings, the part it
names, or the motor its catalog chooses (:func:`chosen_motor`). The section writes no output of
its own; the sections after it read the case with that motor (:class:`AxisResult`)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from .case import Case, Declared, Key, Table
from . import evaluation, pairs
from .protocol import Section
from ..core.errors import CalcError, listing, as_found
from ..domain.fits import parse_bore
from ..data.measurement import measurement_path
from ..domain.gearbox import INERTIA_RATIO_LIMIT, OutputForces
from ..domain.motor_ratings import ELECTRICAL
from .motor_catalog import motor_catalog, motor_ratings

NAME = "axis"
ORDER = 10
MOTOR = Declared("motor", (
    Key("peak_torque", "torque", "maximum torque of the motor (S5)", "T_1B", unit="N*m"),
    Key("inertia", "inertia", "motor inertia (the inertia ratio, the rotor term)", "J_motor", unit="kg*cm**2"),
    Key("rated_torque", "torque", "continuous torque of the motor, at most its peak: the RMS check", "T_1N",
        unit="N*m"),
    Key("max_speed", "speed", "highest speed of the motor", "n_max", unit="rpm"),
    Key("shaft", "bore",
        "the motor's shaft as ordered (\"19 mm k6\"): picks the gearbox's clamping hub and so its J_1"),
    Key("catalog", "catalog", "a motor catalog (\"motors\" is catalogs/motors.csv): every motor in it is checked "
        "against the cycle and ranked"),
    Key("part", "text", "check this motor of the catalog (its ratings and inertia then hold for every section) "
        "instead of typed ratings"),
    Key("max_inertia_ratio", "dimensionless", "highest load-to-motor inertia ratio λ a catalog motor may have",
        "lambda_max", INERTIA_RATIO_LIMIT),
    Key("dc_link_voltage", "voltage", "DC-link voltage of the drive: with a catalog's electrical data, the voltage "
        "limit (without it: the drive the case names)", "U_DC", unit="V"),
    Key("curves", "file", "the catalog motors' peak and S1 curves read from the makers' charts: part, curve, "
        "speed [unit], torque [unit], source"),
    Key("torque_constant", "torque_constant", "torque constant of a typed motor, per A rms: its current I = T / k_T "
        "for the servo drive (a catalog motor takes its row's, or M_0 / I_0)", "k_T", unit="N*m/A"),
    Key("thermal_time_constant", "time", "thermal time constant of a typed motor's winding: the winding's "
        "temperature model (a catalog motor takes its row's)", "T_th", unit="min"),
), "the motor driving the gearbox")
LOAD = Declared("load", (
    Key("inertia", "inertia", "load inertia at the output of the gearbox (left out where a [mechanism] gives it)",
        "J_L", unit="kg*cm**2"),
    Key("axial_force", "force", "axial force on the gearbox output", "F_2a", unit="N"),
    Key("radial_force", "force", "radial force on the gearbox output, with its lever_arm", "F_2r", unit="N"),
    Key("lever_arm", "length", "distance of the radial force from the output flange", "x_2", unit="mm"),
    Key("axial_force_radius", "length", "distance of the axial force from the axis", "y_2", unit="mm"),
), "the load at the gearbox output")
TABLES = (MOTOR, LOAD)


def read(top: Table, case: Case) -> None:
    """Read ``[motor]`` and ``[load]`` into the case; each value above zero, the motor's rated
    (continuous) torque no higher than its peak torque (a distance of the
    forces on the output may be zero). ``motor.shaft`` is the motor's shaft as ordered
    (``"19 mm k6"``), which picks the gearbox's clamping hub; the forces on the gearbox output
    (``load.axial_force``, ``radial_force``, its ``lever_arm`` from the output flange, and
    ``axial_force_radius``, the axial force's distance from the axis) are checked against the
    output bearing's ratings.

    Parameters
    ----------
    top : calc.sections.case.Table
        The case file's top-level table.
    case : calc.sections.case.Case
        The case being read; its motor and load fields are written.

    Returns
    -------
    None
    """
    motor = top.table(MOTOR.name, MOTOR.keys)
    if motor and (motor.has("catalog") or motor.has("part")):
        read_catalog_motor(motor, case)
    elif motor:
        for key in ("max_inertia_ratio", "dc_link_voltage", "curves"):
            if motor.has(key):
                raise CalcError(f"{motor.where(key)}: a key of a catalog motor; "
                                f"give motor.catalog (or motor.part with it) as well")
        case.motor_peak_torque = motor.positive("peak_torque")
        case.motor_inertia = motor.positive("inertia")
        case.motor_rated_torque = motor.positive("rated_torque")
        case.motor_max_speed = motor.positive("max_speed")
        case.motor_torque_constant = motor.positive("torque_constant")
        case.motor_thermal_time_constant = motor.positive("thermal_time_constant")
        peak, rated = case.motor_peak_torque, case.motor_rated_torque
        if peak is not None and rated is not None and rated.m_as("N*m") > peak.m_as("N*m"):
            raise CalcError(
                f"{motor.where('rated_torque')}: expected a continuous torque at most the peak torque "
                f"motor.peak_torque = {as_found(motor.data['peak_torque'])} (a motor's peak is above its "
                "continuous rating), "
                f"found {as_found(motor.data['rated_torque'])}"
            )
        if motor.has("shaft"):
            case.motor_shaft = parse_bore(motor.data["shaft"], motor.where("shaft"))
    load = top.table(LOAD.name, LOAD.keys)
    if load:
        case.load_inertia = load.positive("inertia")
        forces = OutputForces(
            axial_force=load.positive("axial_force", what="an axial force"),
            radial_force=load.positive("radial_force", what="a radial force"),
            lever_arm=_distance(load, "lever_arm"),
            axial_radius=_distance(load, "axial_force_radius"),
        )
        if forces.lever_arm is not None and forces.radial_force is None:
            raise CalcError(f"{load.where('lever_arm')}: a lever arm is the distance of load.radial_force "
                            f"from the output flange, but no radial_force is given")
        if forces.radial_force is not None and forces.lever_arm is None:
            raise CalcError(f"{load.where('radial_force')}: the tilting moment needs the force's lever arm "
                            f"from the output flange, load.lever_arm, found none")
        if forces.axial_radius is not None and forces.axial_force is None:
            raise CalcError(f"{load.where('axial_force_radius')}: the distance of load.axial_force from the axis, "
                            f"but no axial_force is given")
        case.output_load = forces if forces.given else None


def read_catalog_motor(motor: Table, case: Case) -> None:
    """A motor from a catalog: ``part`` names one (its ratings and inertia become the case's, so
    every section checks with them), else every motor of ``catalog`` is ranked by the motor
    section; typed ratings beside a catalog are an error (they would disagree with its rows).

    Parameters
    ----------
    motor : calc.sections.case.Table
        The case's ``[motor]``.
    case : calc.sections.case.Case
        The case being read; its motor fields are written.

    Returns
    -------
    None
    """
    typed = [k for k in ("peak_torque", "inertia", "rated_torque", "max_speed", "torque_constant",
                         "thermal_time_constant") if motor.has(k)]
    if typed:
        raise CalcError(f"{motor.where(typed[0])}: a catalog motor's ratings come from its catalog row; "
                        f"give either motor.catalog / motor.part or the typed ratings, found both")
    case.motor_catalog = motor.catalogs("catalog") if motor.has("catalog") else "motors"
    case.motor_part = motor.text("part")
    ratio = motor.positive("max_inertia_ratio", what="an inertia ratio")
    where = "motor.max_inertia_ratio" if motor.has("max_inertia_ratio") else "the default"
    case.motor_max_inertia_ratio = (float(ratio.m_as("")), where)
    case.motor_dc_link = motor.positive("dc_link_voltage")
    if case.motor_dc_link is not None:  # else the drive the case names may give it (calc.sections.drive)
        case.voltage_limit_dc_link = (case.motor_dc_link, "motor.dc_link_voltage")
    if motor.has("curves"):
        case.motor_curves = measurement_path(motor.data["curves"], case.folder, motor.where("curves"))
    if motor.has("shaft"):
        case.motor_shaft = parse_bore(motor.data["shaft"], motor.where("shaft"))
    if case.motor_part is not None:
        cat = motor_catalog(case)
        row = cat.usable_index(case.motor_part, motor.where("part"))
        for field, value in motor_ratings(cat, row).items():
            setattr(case, field, value)
        missing = [c for c in ELECTRICAL if np.isnan(cat[c][row].magnitude)]
        if case.motor_dc_link is not None and missing:
            raise CalcError(f"{motor.where('dc_link_voltage')}: the voltage limit needs the electrical data of "
                            f"{case.motor_part}, but {cat.catalog_of(row)} (row {cat.lines[row]}) "
                            f"gives no {listing(missing)}")


def _distance(load: Table, key: str):
    """A distance of a force on the output: zero or more."""
    q = load.quantity(key)
    if q is not None and not q.magnitude >= 0:
        raise CalcError(f"{load.where(key)}: expected a distance of zero or more, found {as_found(load.data[key])}")
    return q


@dataclass(frozen=True)
class AxisResult:
    """The case with the ratings and inertia of the motor it is checked with, and the motor and
    gearbox where the catalog chose them.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case with that motor's ratings and inertia.
    chosen : str, optional
        The motor the catalog chose; None where the case names or types its motor.
    gearbox : str, optional
        The gearbox chosen with it (the gearbox section puts it first where it passes); None for a
        direct drive, or where the case names or types its motor.
    evaluated : dict
        The results of the sections after this one that confirmed the pair (the gearbox, the
        coupling and the motor evaluated with it), by section name; empty where none did.
    """

    case: Case
    chosen: str | None = None
    gearbox: str | None = None
    evaluated: dict = field(default_factory=dict, repr=False, compare=False)


def chosen_motor(case: Case) -> AxisResult:
    """The motor and the gearbox a case with a motor catalog (``[motor] catalog`` without a
    ``part``) is checked with: the first pair of the motor x gearbox search of its rows
    (:func:`calc.sections.pairs.case_pairs`, in the order of :data:`calc.domain.combinations.RULE`:
    the smallest adequate motor, for it the gearbox the gearbox ranking puts first) that the full
    evaluation confirms (:func:`confirmed`: the coupling chosen with that motor counted), or the pair
    closest to passing where none is confirmed; the case itself where it names its motor or types it.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.

    Returns
    -------
    AxisResult
        The case with the chosen motor's ratings and inertia, that motor and its gearbox, and the
        results that confirmed them.
    """
    if case.motor_catalog is None or case.motor_part is not None:
        return AxisResult(case)
    cat = motor_catalog(case)
    tried = {}

    def with_pair(motor: str, gearbox: str | None) -> AxisResult:
        row = cat.index(motor, f"{case.path}: motor.catalog")
        return AxisResult(dataclasses.replace(case, **motor_ratings(cat, row)), motor, gearbox)

    def confirm(motor: str, gearbox: str | None) -> bool:
        axis = with_pair(motor, gearbox)
        tried[motor, gearbox] = axis
        return confirmed(axis)

    found = pairs.case_pairs(case, confirm)
    if found.chosen is None:  # no motor or no gearbox row to pair: the motor section says so
        return AxisResult(case)
    g, m = found.chosen
    gearbox = None if case.ratio is None and case.gearbox_part is None else str(found.gearbox_parts[g])
    pair = (str(found.motor_parts[m]), gearbox)
    return tried[pair] if pair in tried else with_pair(*pair)  # the results evaluated with it are kept


def confirmed(axis: AxisResult) -> bool:
    """Whether a pair of the search passes evaluated in full: the gearbox, the coupling and the motor
    evaluated with that motor and gearbox (:func:`calc.sections.evaluation.results_of`), the motor's
    checks (λ with the coupling chosen with it among them) passed and the gearbox passing with it.
    The results are kept in ``axis.evaluated``: the evaluation takes them as they are.

    Parameters
    ----------
    axis : AxisResult
        The case with the pair's motor, the motor and the gearbox (None: a direct drive).

    Returns
    -------
    bool
        True where the motor and the gearbox pass.
    """
    results = evaluation.results_of(axis.case, ("motor",), given={NAME: axis})
    axis.evaluated.update((k, v) for k, v in results.items() if k != NAME)
    motor, gearbox = results.get("motor"), results.get("gearbox")
    if motor is None or motor.selection is None:
        return False
    if axis.gearbox is not None and (gearbox is None or not _passes(gearbox.selection, axis.gearbox)):
        return False
    return _passes(motor.selection, axis.chosen)


def _passes(selection, part: str) -> bool:
    """Whether a selection's row of that part passes its checks."""
    rows = np.flatnonzero(np.asarray(selection.catalog.parts) == part)
    return bool(len(rows) and selection.passes[rows[0]])


class DriveSection(Section):
    """The motor and the load: read into the case's fields; evaluated, the motor the case is
    checked with."""

    NAME = NAME
    TABLES = TABLES
    SHOWN = False

    def read(self, top: Table, case: Case) -> None:
        read(top, case)

    def applies(self, case: Case) -> bool:
        return True

    def evaluate(self, case: Case, earlier) -> AxisResult:
        return chosen_motor(case)

    def checked(self, case: Case, result: AxisResult) -> Case:
        return result.case

    def evaluated_with(self, result: AxisResult) -> dict:
        return dict(result.evaluated)


SECTION = DriveSection()
