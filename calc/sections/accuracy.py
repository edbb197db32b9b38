"""The accuracy of a case's drive chain (``[accuracy]``): its components given, taken from a catalog
part (the gearbox or coupling selection's choice with ``part = "selected"``) or measured, the
stiffness, lost motion, positioning accuracy and repeatability at the output (:mod:`calc.domain.accuracy`,
E11 to E13), and the required values checked."""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass, field

import numpy as np

from ..domain.accuracy import (POSITIONING_CONVENTION, Budget, ChainAccuracy, PositioningScatter, angle_of_arc,
                               arc_length, chain_accuracy, error_budget, read_positions)
from .case import Case, Declared, Key, Table
from ..data.catalog import display_path, load_catalog, load_catalogs, resolve
from ..core.checks import CheckArray
from ..core.errors import CalcError, listing, as_found
from ..core.units import Q_, Value, as_kind, fmt, parse_quantity, sig
from ..data.measurement import measurement_path
from ..domain.stiffness import SIDES, Chain, Component, StiffnessCurve
from ..domain.coupling import SCHEMA as COUPLING_SCHEMA
from ..domain.gearbox import SCHEMA as GEARBOX_SCHEMA, same_ratio
from ..domain.hysteresis import analyze_loop, model_for_row
from .common import Governing, Verdict, json_of, number, quantity
from .protocol import Result, Section

NAME = "accuracy"
ORDER = 80
#: The keys of a component's ``stiffness_curve``: limit torques and slopes
#: (:class:`calc.domain.stiffness.StiffnessCurve`).
CURVE_KEYS = (
    Key("T1", "torque", "the torque up to which K1 holds", "T_L1", unit="N*m"),
    Key("T2", "torque", "the torque up to which K2 holds", "T_L2", unit="N*m"),
    Key("K1", "stiffness", "slope up to T1", "K_1", unit="N*m/rad"),
    Key("K2", "stiffness", "slope from T1 to T2", "K_2", unit="N*m/rad"),
    Key("K3", "stiffness", "slope above T2", "K_3", unit="N*m/rad"),
)
COMPONENT_KEYS = (
    Key("name", "text", "name of the member (default: its part)"),
    Key("side", "choice", "input | output of the gearbox; input is referred to the output through the ratio (E11)",
        default="output"),
    Key("kind", "choice", "which catalog a part comes from: gearbox | coupling (a bellows or safety coupling)",
        default="gearbox"),
    Key("stiffness", "stiffness", "torsional stiffness at the output, always with its angle unit (\"1.3 N*m/arcmin\")",
        "C", unit="N*m/arcmin"),
    Key("backlash", "angle", "backlash (\"0 arcmin\" for none)", "phi_B", unit="arcmin"),
    Key("transmission_accuracy", "angle", "transmission accuracy", unit="arcsec"),
    Key("nominal_torque", "torque", "nominal torque of the member (a measured loop is analysed at it, E12)", "T_N",
        unit="N*m"),
    Key("part", "text", "a catalog part whose figures the member takes; \"selected\": the selection's choice"),
    Key("catalog", "catalog", "the catalog of the part (default: gearbox.catalog, or couplings)"),
    Key("hysteresis", "file", "a measured hysteresis loop: torque [N*m], twist [arcmin]"),
    Key("transmission_trace", "file", "a position trace over one output revolution"),
    Key("measured_part", "text", "with part = \"selected\": the part the measurements were made on"),
    Key("stiffness_curve", "table", "the stiffness as a curve of three slopes instead of one", keys=CURVE_KEYS),
)
TABLES = (Declared(NAME, (
    Key("applied_torque", "torque", "applied torque at the output, for lost motion and positioning accuracy", "T",
        unit="N*m"),
    Key("nominal_torque", "torque", "nominal torque for the 3 % rule (E13; default: the chain's)", "T_N", unit="N*m"),
    Key("component", "tables", "the members of the chain, drive to load ([[accuracy.component]])", keys=COMPONENT_KEYS),
    Key("positions", "file", "measured positions: the scatter of repeated moves"),
    Key("required_positioning_accuracy", "angle or length", "positioning accuracy required: a check", unit="arcmin"),
    Key("required_repeatability", "angle or length", "repeatability required: a check", unit="arcmin"),
    Key("radius", "length", "radius at which angles are also given as arcs s = r · φ (a pinion, a table's edge)", "r",
        unit="mm"),
), "the accuracy of the drive chain at the output"),)
#: What the text summary says after C_total where a member gives a stiffness curve.
SECANT = " (secant |T| / φ at the applied torque: a member gives a stiffness curve)"
#: The keys of a component that read a measurement of one physical part.
MEASUREMENTS = ("hysteresis", "transmission_trace")


@dataclass
class ComponentInputs:
    """One ``[[accuracy.component]]`` as read with the case: its own figures, checked key by key;
    a catalog part, the selection it follows and its measurements are taken when evaluated.

    Parameters
    ----------
    table : calc.sections.case.Table
        The component's keys, for what is checked against the rest of the case.
    part : str or None
        A catalog part, ``"selected"`` for the selection's choice; None where the case gives the figures.
    kind : str
        The catalog the part comes from: ``gearbox`` or ``coupling``.
    name : str or None
        The member's name; None: the part's.
    side : str
        ``input`` or ``output`` side of the gearbox.
    stiffness : pint.Quantity [N·m/arcmin] or None
        The torsional stiffness given (a curve's first slope where it gives a curve).
    curve : calc.domain.stiffness.StiffnessCurve or None
        The stiffness as a curve of three slopes.
    backlash : pint.Quantity [arcmin] or None
        The backlash given.
    accuracy : pint.Quantity [arcsec] or None
        The transmission accuracy given.
    nominal : pint.Quantity [N·m] or None
        The member's nominal torque given.
    hysteresis : str or None
        A measured loop's file as the case names it (found and read when evaluated).
    trace : str or None
        A transmission trace's file as the case names it (found and read when evaluated).
    """

    table: Table
    part: str | None
    kind: str
    name: str | None
    side: str
    stiffness: object
    curve: StiffnessCurve | None
    backlash: object
    accuracy: object
    nominal: object
    hysteresis: str | None = None
    trace: str | None = None


@dataclass
class AccuracyInputs:
    """The ``[accuracy]`` table as read with the case.

    Parameters
    ----------
    table : dict
        The table as written.
    applied_torque : pint.Quantity [N·m]
        The torque at the output.
    nominal_torque : pint.Quantity [N·m] or None
        The nominal torque for the 3 % rule (E13); None: the chain's.
    components : list of ComponentInputs
        The members, drive to load.
    positions : str or None
        The measured positions' file as the case names it.
    radius : pint.Quantity [mm] or None
        The radius at which angles are also given as arcs.
    required : dict
        ``"positioning_accuracy"`` | ``"repeatability"`` -> the required angle [arcmin].
    required_arcs : dict
        A requirement given as a length [mm], by the same names.
    """

    table: dict
    applied_torque: object
    nominal_torque: object
    components: list
    positions: str | None
    radius: object
    required: dict
    required_arcs: dict


@dataclass
class AccuracyCase:
    """The ``[accuracy]`` section as evaluated: its chain of the parts the case is checked with,
    with what its measurements gave.

    Parameters
    ----------
    chain : calc.domain.stiffness.Chain
        The members, drive to load.
    applied_torque : pint.Quantity [N·m]
        The torque at the output.
    nominal_torque : pint.Quantity [N·m] or None
        Given in the section; None: the chain's.
    loops : dict
        Component name -> (file, :class:`calc.domain.hysteresis.LoopAnalysis`) of its measured loop.
    traces : dict
        Component name -> (file, :class:`calc.domain.transmission.TransmissionAnalysis`) of its trace.
    positions : calc.domain.accuracy.PositioningScatter or None
        The measured positions.
    required : dict
        ``"positioning_accuracy"`` | ``"repeatability"`` -> the required angle [arcmin].
    radius : pint.Quantity [mm] or None
        ``r``: the results also give each angle as the arc ``r · φ`` at it.
    required_arcs : dict
        A requirement given as a length [mm], by name.
    unknown : list of str
        The terms of the positioning accuracy not known for the chosen parts, each naming the part
        and the missing figure: the accuracy reckoned without them is a lower bound.
    unknown_chain : list of str
        Of those, the members' twist or backlash unknown (a followed selection's row leaves its
        C_t21 or backlash empty): the member is reckoned rigid and free of backlash, so the lost
        motion and repeatability are lower bounds as well, and the chain's stiffness an upper one.
    unchosen : list of str
        The components whose followed selection chooses no part (its best-ranked stands in), as
        sentences: no requirement can be decided on a chain of parts that will not be ordered.
    """

    chain: Chain
    applied_torque: object
    nominal_torque: object = None
    loops: dict = field(default_factory=dict)
    traces: dict = field(default_factory=dict)
    positions: PositioningScatter | None = None
    required: dict = field(default_factory=dict)
    radius: object = None
    required_arcs: dict = field(default_factory=dict)
    unknown: list = field(default_factory=list)
    unknown_chain: list = field(default_factory=list)
    unchosen: list = field(default_factory=list)

    def evaluate(self) -> ChainAccuracy:
        """The chain's accuracy at the applied torque (E11 to E13, :func:`calc.domain.accuracy.chain_accuracy`).

        Returns
        -------
        calc.domain.accuracy.ChainAccuracy
            Lost motion, positioning accuracy and repeatability.
        """
        return chain_accuracy(self.chain, self.applied_torque, self.nominal_torque)


def read_inputs(case: Case) -> AccuracyInputs:
    """Read the case's ``[accuracy]`` table; every error names the file and the key.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case being read.

    Returns
    -------
    AccuracyInputs
    """
    sec = Table(case.path, NAME, case.sections[NAME], TABLES[0].keys)
    applied = sec.quantity("applied_torque", required=True)
    nominal = _positive(sec, "nominal_torque", "torque")
    tables = sec.tables("component", COMPONENT_KEYS)
    if not tables:
        raise CalcError(f"{sec.where('component')}: expected one [[accuracy.component]] table per member of the chain, "
                        "drive to load, found none")
    components = [read_component(t) for t in tables]
    out = AccuracyInputs(sec.data, applied, nominal, components, sec.data.get("positions"),
                         sec.positive("radius", what="a radius"), {}, {})
    for key in ("required_positioning_accuracy", "required_repeatability"):
        q = _requirement(sec, key, out)
        if q is not None:
            out.required[key.removeprefix("required_")] = q
    return out


def accuracy_case(case: Case, given: AccuracyInputs, gearbox, coupling) -> AccuracyCase:
    """The chain of the case's components, each taking its figures from the case, a catalog part,
    the gearbox or coupling section's choice or its measurements.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    given : AccuracyInputs
        The ``[accuracy]`` table as read.
    gearbox : calc.sections.gearbox.GearboxResult or None
        The gearbox section's result; None where the case has no gearbox.
    coupling : calc.sections.coupling.CouplingResult or None
        The coupling section's result; None where the case has no coupling.

    Returns
    -------
    AccuracyCase
    """
    ratio = _case_ratio(case)
    out = AccuracyCase(chain=None, applied_torque=given.applied_torque, nominal_torque=given.nominal_torque,
                       radius=given.radius, required=given.required, required_arcs=given.required_arcs)
    components = [_component(case, c, ratio, out, gearbox, coupling) for c in given.components]
    tables = [c.table for c in given.components]
    names = [c.name for c in components]
    for k, name in enumerate(names):
        if name in names[:k]:
            first = tables[names.index(name)].key("name")
            raise CalcError(f"{tables[k].where('name')}: the name {as_found(name)} is already used by {first}")
    input_side = [t for t, c in zip(tables, components) if c.side == "input"]
    if input_side and ratio is None:
        raise CalcError(
            f"{input_side[0].where('side')}: an input-side component is referred to the output through the gearbox "
            "ratio (E11), but the case gives no gearbox.ratio"
        )
    out.chain = Chain(tuple(components), ratio)
    if given.positions is not None:
        sec = Table(case.path, NAME, given.table, TABLES[0].keys)
        out.positions = read_positions(measurement_path(given.positions, case.folder, sec.where("positions")))
    return out


def _requirement(sec: Table, key: str, out: AccuracyInputs):
    """A required value: an angle, or with ``accuracy.radius`` a length at that radius (the arc a
    machine builder states a tolerance as), turned into the angle ``s / r``."""
    if not sec.has(key) or _is_angle(sec.data[key]):
        return _positive(sec, key, "angle")
    arc = sec.positive(key, "length", what="a length")
    if out.radius is None:
        raise CalcError(f"{sec.where(key)}: a requirement given as a length ({as_found(sec.data[key])}) is an "
                        "arc at a radius; "
                        "give accuracy.radius as well")
    out.required_arcs[key.removeprefix("required_")] = arc
    return angle_of_arc(s=arc, r=out.radius)


def _is_angle(text) -> bool:
    """Whether a value reads as anything but a length (an angle, or an error the angle reading names)."""
    try:
        parse_quantity(text, "length", "")
    except CalcError:
        return True
    return False


def _positive(sec: Table, key: str, kind: str):
    q = sec.quantity(key, kind)
    if q is not None and not q.magnitude > 0:
        raise CalcError(f"{sec.where(key)}: expected {'an' if kind == 'angle' else 'a'} {kind} above zero, found "
                        f"{as_found(sec.data[key])}")
    return q


def _nonnegative_angle(t: Table, key: str):
    q = t.quantity(key, "angle")
    if q is not None and not q.magnitude >= 0:
        raise CalcError(f"{t.where(key)}: expected an angle of zero or more, found {as_found(t.data[key])}")
    return q


def _case_ratio(case: Case):
    """The gearbox ratio the chain is referred through: ``gearbox.ratio``, else the named part's."""
    if case.ratio is not None:
        return case.ratio
    if case.gearbox_part is not None:
        rows, row = _catalog_row(case, case.gearbox_catalog or "gearboxes", case.gearbox_part, f"{case.path}: gearbox")
        return rows["ratio"][row]
    return None


#: The catalogs a component's ``part`` comes from (``kind``), and the value that follows the
#: selection of the case instead of naming a part.
PART_KINDS = ("gearbox", "coupling")
SELECTED = "selected"


def _catalog_row(case: Case, catalog, part: str, where: str):
    """The gearbox catalog (one file or several, as ``gearbox.catalog``) and the row of ``part``;
    a partial row is an input error."""
    rows = load_catalogs(catalog, case.folder, f"{where}.catalog", GEARBOX_SCHEMA)
    return rows, rows.usable_index(part, f"{where}.part")


def _chosen_row(selection, what: str) -> tuple[int, str, str | None]:
    """The row a ``part = "selected"`` follows, its source text, and None; where the selection
    chooses none, its best-ranked candidate stands in, and the third value says so (the
    requirements are then not decided, :func:`not_known`)."""
    row = int(selection.order[0])
    part = str(selection.catalog.parts[row])
    if selection.selected is not None:
        return row, f"the {what} selection's choice {part}", None
    return (row, f"{part}, the best-ranked {what} (none is chosen)",
            f"the {what} selection chooses no part ({part}, its best-ranked, stands in)")


def _doubt(rows, row: int) -> str:
    """The row's doubtful figures as its catalog marks them (``unclear``), for the source text."""
    doubt = rows.text_or_blank("unclear")[row]
    return f" (doubtful figures: {doubt})" if doubt else ""


def _gearbox_part(case: Case, t: Table, part: str, gearbox):
    """The catalog, row and source text of a gearbox component's ``part`` (``gearbox``: the gearbox
    result a ``part = "selected"`` follows, None without one); a row's doubtful figures go with it."""
    if part != SELECTED:
        catalog = t.text("catalog", default=case.gearbox_catalog or "gearboxes")
        rows, row = _catalog_row(case, catalog, part, t.where("").rstrip("."))
        return rows, row, f"{rows.catalog_of(row)} row {rows.lines[row]}{_doubt(rows, row)}", None
    if gearbox is None:
        raise CalcError(f"{t.where('part')}: part = \"selected\" follows the gearbox selection, but the case names no "
                        "gearbox ratio or part")
    row, chosen, stand_in = _chosen_row(gearbox.selection, "gearbox")
    rows = gearbox.selection.catalog
    return rows, row, f"{chosen}, {rows.catalog_of(row)} row {rows.lines[row]}{_doubt(rows, row)}", stand_in


def _coupling_part(case: Case, t: Table, part: str, coupling):
    """Part name, stiffness, side and source text of a coupling component's ``part`` (``coupling``:
    the coupling result a ``part = "selected"`` follows, None without one): a bellows or safety
    coupling of the catalog (torsionally stiff and free of backlash by design)."""
    if part == SELECTED:
        if coupling is None:
            raise CalcError(f"{t.where('part')}: part = \"selected\" with kind = \"coupling\" follows the coupling "
                            "selection, but the case has no [coupling]")
        row, chosen, stand_in = _chosen_row(coupling.selection, "coupling")
        rows, side = coupling.selection.catalog, coupling.inputs.side or "output"
    else:
        path = resolve(t.text("catalog", default="couplings"), case.folder, t.where("catalog"))
        rows = load_catalog(path, COUPLING_SCHEMA)
        row = rows.index(part, t.where("part"))
        chosen, side, stand_in = str(rows.parts[row]), None, None
    name, kind_of = str(rows.parts[row]), str(rows.text["type"][row])
    where = f"{t.where('part')}: {rows.path}, row {rows.lines[row]} ({name})"
    if kind_of not in ("bellows", "safety"):
        raise CalcError(f"{where}: the twist of a coupling of type {kind_of} is not one catalog stiffness; give its "
                        "stiffness and backlash instead of a part")
    stiffness = rows["C_T"][row]
    if np.isnan(stiffness.magnitude):
        raise CalcError(f"{where}, column C_T: expected a value, found an empty cell")
    return name, stiffness, side, f"{chosen}, {rows.catalog_of(row)} row {rows.lines[row]}", stand_in


def _check_measured_part(t: Table, part: str | None) -> None:
    """A measurement belongs to the part it was made on: with ``part = "selected"`` it needs
    ``measured_part``, which is given only then and only with a measurement."""
    measured = [key for key in MEASUREMENTS if t.has(key)]
    measured_on = t.text("measured_part")
    if measured_on is not None and part != SELECTED:
        raise CalcError(f"{t.where('measured_part')}: measured_part names the part a measurement was made on when part "
                        "= \"selected\"; found "
                        f"{'no part' if part is None else f'part = {as_found(part)}, whose measurements are its own'}")
    if measured_on is not None and not measured:
        raise CalcError(f"{t.where('measured_part')}: measured_part names the part a measurement was made on; give "
                        "hysteresis or transmission_trace as well")
    if part == SELECTED and measured and measured_on is None:
        raise CalcError(f"{t.where(measured[0])}: a measurement belongs to the part it was made on, but part = "
                        "\"selected\" follows the selection; name that part with measured_part")


def _measured_part_chosen(t: Table, chosen_part: str | None, sources: list) -> bool:
    """Whether the component's measurements apply: while the selection chooses the part they were
    made on (``sources`` is told when it does not)."""
    measured_on = t.text("measured_part")
    if measured_on is None or measured_on == chosen_part:
        return True
    measured = [key for key in MEASUREMENTS if t.has(key)]
    sources.append(f"the {' and '.join(measured)} of {measured_on} not used: the selection chose {chosen_part}")
    return False


def read_component(t: Table) -> ComponentInputs:
    """One ``[[accuracy.component]]`` as the case gives it: its keys checked, each against the others.

    Parameters
    ----------
    t : calc.sections.case.Table
        The component's table.

    Returns
    -------
    ComponentInputs
    """
    part = t.text("part")
    kind = t.text("kind")
    if kind not in PART_KINDS:
        raise CalcError(f"{t.where('kind')}: expected one of {listing(PART_KINDS)}, found {as_found(kind)}")
    if t.has("kind") and part is None:
        raise CalcError(f"{t.where('kind')}: kind says which catalog a part comes from; give part as well")
    name = t.text("name", required=part is None)
    side = t.text("side", required=part is None)
    if side not in SIDES:
        raise CalcError(f"{t.where('side')}: expected input or output, found {as_found(side)}")
    stiffness, curve = _positive(t, "stiffness", "stiffness"), None
    if t.has("stiffness_curve"):
        for key in ("stiffness", "part", "hysteresis"):
            if t.has(key):
                raise CalcError(f"{t.where('stiffness_curve')}: the curve gives the member's stiffness; give either "
                                f"stiffness_curve or {key}")
        c = t.table("stiffness_curve", CURVE_KEYS)
        curve = StiffnessCurve(*(c.quantity(key.name, required=True) for key in CURVE_KEYS),
                               where=f"{c.path}: {c.name}")
        stiffness = curve.K_1
    backlash, accuracy = _nonnegative_angle(t, "backlash"), _nonnegative_angle(t, "transmission_accuracy")
    nominal = _positive(t, "nominal_torque", "torque")
    if part is not None:
        for key in ("stiffness", "backlash", "nominal_torque"):
            if t.has(key):
                raise CalcError(f"{t.where(key)}: the part {as_found(part)} gives its {key} from the catalog; "
                                "give either part "
                                f"or {key}")
        if kind == "gearbox" and side != "output":
            raise CalcError(f"{t.where('side')}: a gearbox's catalog figures are referred to its output, so the part "
                            f"{as_found(part)} sits on the output side, found {as_found(side)}")
        if part == SELECTED and t.has("catalog"):
            raise CalcError(f"{t.where('catalog')}: part = \"selected\" takes the {kind} selection's catalog; "
                            "give no catalog")
    elif t.has("catalog"):
        raise CalcError(f"{t.where('catalog')}: a catalog is read only for a part; give part as well")
    _check_measured_part(t, part)
    for key in ("stiffness", "backlash") if t.has("hysteresis") else ():
        if t.has(key):
            raise CalcError(f"{t.where(key)}: the measured loop gives the {key}; give either hysteresis or {key}")
    return ComponentInputs(t, part, kind, name, side, stiffness, curve, backlash, accuracy, nominal,
                           *(t.data.get(key) for key in MEASUREMENTS))


@dataclass
class Figures:
    """A member's figures as they are taken in turn: given, from a catalog part, measured.

    Parameters
    ----------
    name : str
        The member's name.
    side : str
        ``input`` or ``output`` side of the gearbox.
    stiffness : pint.Quantity [N·m/arcmin] or None
        Its torsional stiffness.
    curve : calc.domain.stiffness.StiffnessCurve or None
        Its stiffness as a curve.
    backlash : pint.Quantity [arcmin] or None
        Its backlash.
    accuracy : pint.Quantity [arcsec] or None
        Its transmission accuracy.
    nominal : pint.Quantity [N·m] or None
        Its nominal torque.
    ratio : pint.Quantity [1] or None
        The ratio its measured trace is reckoned through: its gearbox part's, else the case's.
    chosen : str or None
        The catalog part it is, once a selection is followed.
    sources : list of str
        Where its figures come from, in turn.
    """

    name: str
    side: str
    stiffness: object
    curve: StiffnessCurve | None
    backlash: object
    accuracy: object
    nominal: object
    ratio: object
    chosen: str | None
    sources: list


def _component(case: Case, c: ComponentInputs, ratio, out: AccuracyCase, gearbox, coupling) -> Component:
    """One member of the chain: from its keys, a catalog part (or the ``gearbox`` or ``coupling``
    result's choice), or measurements; what is unknown of it is told to ``out``."""
    f = Figures(c.name if c.name is not None else c.part, c.side, c.stiffness, c.curve, c.backlash, c.accuracy,
                c.nominal, ratio, c.part, [])
    if c.part is not None:
        if c.kind == "coupling":
            stand_in = _coupling_figures(case, c, f, coupling)
        else:
            stand_in = _gearbox_figures(case, c, f, ratio, out, gearbox)
        if stand_in is not None:
            out.unchosen.append(stand_in)
    _measured_figures(case, c, f, out)
    t = c.table
    if f.stiffness is None:
        raise CalcError(f"{t.where('stiffness')}: expected a stiffness such as \"1.3 N*m/arcmin\" (or a part, or a "
                        "measured hysteresis loop), found none")
    if f.backlash is None:
        raise CalcError(f"{t.where('backlash')}: expected an angle such as \"3 arcmin\" (\"0 arcmin\" for none), "
                        "found none")
    return Component(f.name, f.side, f.stiffness, f.backlash, f.accuracy, f.nominal,
                     source="; ".join(f.sources) or "case", stiffness_curve=f.curve)


def _coupling_figures(case: Case, c: ComponentInputs, f: Figures, coupling) -> str | None:
    """A coupling part's stiffness and side (its backlash none); returns why the part only stands
    in for one not chosen, or None."""
    t = c.table
    chosen, f.stiffness, coupling_side, source, stand_in = _coupling_part(case, t, c.part, coupling)
    if coupling_side is not None and t.has("side") and f.side != coupling_side:
        raise CalcError(f"{t.where('side')}: the coupling selection's coupling sits on the {coupling_side} side "
                        f"(coupling.side), found {as_found(f.side)}")
    f.side = coupling_side or f.side
    f.backlash = Q_(0.0, "arcmin")
    f.chosen = chosen
    f.name = chosen if f.name == SELECTED else f.name
    f.sources.append(source)
    return stand_in


def _gearbox_figures(case: Case, c: ComponentInputs, f: Figures, ratio, out: AccuracyCase, gearbox) -> str | None:
    """A gearbox part's stiffness (or its curve), backlash and nominal torque from its catalog row;
    a figure the row of a followed selection leaves empty is reckoned without and told to ``out``.
    Returns why the part only stands in for one not chosen, or None."""
    t = c.table
    rows, row, source, stand_in = _gearbox_part(case, t, c.part, gearbox)
    f.chosen = str(rows.parts[row])
    if f.name == SELECTED:
        f.name = f.chosen
    f.ratio = rows["ratio"][row]
    if ratio is not None and not same_ratio(f.ratio.m_as(""), ratio.m_as("")):
        raise CalcError(f"{t.where('part')}: {rows.parts[row]} has ratio {f.ratio.m_as(''):g}, but the case's gearbox "
                        f"ratio is {ratio.m_as(''):g}")
    f.stiffness, f.backlash, f.nominal = rows["C_t21"][row], rows["backlash"][row], rows["T_2N"][row]
    if not np.isnan(rows["K_1"][row].magnitude):  # the catalog gives the gear's stiffness curve
        f.curve = StiffnessCurve(*(rows[name][row] for name in ("T_L1", "T_L2", "K_1", "K_2", "K_3")))
        f.stiffness = f.curve.K_1
    empty = [column for column, q in (("C_t21", f.stiffness), ("backlash", f.backlash)) if np.isnan(q.magnitude)]
    if empty and c.part != SELECTED:  # a part named here: its figures are asked for
        raise CalcError(f"{t.where('part')}: {rows.path}, row {rows.lines[row]} ({rows.parts[row]}), "
                        f"column {empty[0]}: expected a value, found an empty cell")
    if empty:  # the selection's part: the chain is reckoned without the figure, and says so
        figures = " and ".join({"C_t21": "torsional stiffness C_t21", "backlash": "backlash"}[e] for e in empty)
        reckoned = " and ".join({"C_t21": "rigid", "backlash": "free of backlash"}[e] for e in empty)
        unknown = (f"{f.chosen}: its {figures} (empty in {rows.catalog_of(row)} row {rows.lines[row]}; "
                   f"reckoned {reckoned})")
        out.unknown.append(unknown)
        out.unknown_chain.append(unknown)
        f.stiffness = Q_(np.inf, "N*m/arcmin") if "C_t21" in empty else f.stiffness
        f.backlash = Q_(0.0, "arcmin") if "backlash" in empty else f.backlash
    f.sources.append(source)
    return stand_in


def _measured_figures(case: Case, c: ComponentInputs, f: Figures, out: AccuracyCase) -> None:
    """The stiffness and backlash of a measured loop (E12) and the transmission accuracy of a
    trace, where the measurements apply to the part chosen (else the accuracy they gave is
    unknown, where the case gives none)."""
    t = c.table
    applies = _measured_part_chosen(t, f.chosen, f.sources)
    if not applies and c.trace is not None and f.accuracy is None:
        # The trace was the transmission accuracy; the part chosen instead has none given, which is
        # not the same as none at all.
        out.unknown.append(f"{f.chosen}: its transmission accuracy (the trace of {t.text('measured_part')} does not "
                           "apply to it, and the case gives no transmission_accuracy)")
    if applies and c.hysteresis is not None:
        from ..domain.hysteresis import analyze_loop, read_loop

        if f.nominal is None:
            raise CalcError(f"{t.where('nominal_torque')}: a measured loop is analysed at 50 % to 100 % and ±3 % of "
                            "the nominal torque (E12), found none")
        path = measurement_path(c.hysteresis, case.folder, t.where("hysteresis"))
        analysis = analyze_loop(read_loop(path), f.nominal)
        f.stiffness, f.backlash = analysis.stiffness, analysis.backlash
        out.loops[f.name] = (display_path(path), analysis)
        f.sources.append(f"measured loop {display_path(path)}")
    if applies and c.trace is not None:
        from ..domain.transmission import analyze_trace, read_trace

        if f.accuracy is not None:
            raise CalcError(f"{t.where('transmission_accuracy')}: the trace gives the transmission accuracy; give "
                            "either transmission_trace or transmission_accuracy")
        if f.ratio is None:
            raise CalcError(f"{t.where('transmission_trace')}: the transmission error is reckoned through the gearbox "
                            "ratio, but the case gives no gearbox.ratio")
        path = measurement_path(c.trace, case.folder, t.where("transmission_trace"))
        analysis = analyze_trace(read_trace(path), f.ratio)
        f.accuracy = analysis.accuracy
        out.traces[f.name] = (display_path(path), analysis)
        f.sources.append(f"trace {display_path(path)}")


def _chain_accuracy(case: Case, spec: AccuracyCase) -> ChainAccuracy:
    """The accuracy of the evaluated chain ``spec``; an error of the chain names the case's table."""
    try:
        return spec.evaluate()
    except CalcError as exc:
        raise CalcError(f"{case.path}: accuracy.{exc}") from None


def _unknown_terms(spec: AccuracyCase, name: str) -> list:
    """The unknown terms that leave ``name`` (positioning_accuracy, repeatability, lost_motion)
    below what the chain reaches: every one for the positioning accuracy, a member's twist or
    backlash for the others."""
    if name == "positioning_accuracy":
        return spec.unknown
    return spec.unknown_chain if name in ("repeatability", "lost_motion") else []


def relation(spec: AccuracyCase, name: str) -> str:
    """How a value relates to what the chain reaches.

    Parameters
    ----------
    spec : AccuracyCase
        The section as evaluated.
    name : str
        The value: ``positioning_accuracy``, ``repeatability`` or ``lost_motion``.

    Returns
    -------
    str
        ``>=`` for a value that is a lower bound (a term of it unknown for the chosen parts), else ``=``.
    """
    return ">=" if _unknown_terms(spec, name) else "="


def not_known(spec: AccuracyCase, name: str) -> str | None:
    """Why the check of ``name`` cannot be made.

    Parameters
    ----------
    spec : AccuracyCase
        The section as evaluated.
    name : str
        The checked value: ``positioning_accuracy`` or ``repeatability``.

    Returns
    -------
    str or None
        The reasons: a followed selection chooses no part (the chain is of a part that stands in),
        or the value is a lower bound (a term of it is unknown for the chosen parts); None where
        the check can be made.
    """
    reasons = list(spec.unchosen)
    if _unknown_terms(spec, name):
        reasons.append(f"the {name.replace('_', ' ')} is a lower bound: unknown "
                       + "; ".join(_unknown_terms(spec, name)))
    return "; ".join(reasons) or None


def requirement_checks(spec: AccuracyCase, a: ChainAccuracy) -> list[CheckArray]:
    """The chain's positioning accuracy and repeatability against the values the case requires,
    under the package's one pass rule.

    Parameters
    ----------
    spec : AccuracyCase
        The section as evaluated, with the required values.
    a : calc.domain.accuracy.ChainAccuracy
        The chain's accuracy.

    Returns
    -------
    list of calc.core.checks.CheckArray
        One check per required value [arcmin], the chain's value as the required side.
    """
    # A term of the positioning accuracy unknown: it bounds nothing, the repeatability keeps the lost motion.
    values = {"positioning_accuracy": a.positioning_accuracy,
              "repeatability": a.repeatability if spec.unknown else a.repeatability_bound}
    return [
        CheckArray(name, "", f"{name} <= required", values[name].reshape(1), limit.reshape(1), "arcmin")
        for name, limit in spec.required.items()
    ]


@dataclass(frozen=True)
class MeasuredLoop:
    """A member's measured hysteresis loop as analysed (E12).

    Parameters
    ----------
    file : str
        The loop's file as the results show it.
    stiffness_positive, stiffness_negative : Value
        The stiffness fitted each way [N·m/arcmin].
    backlash : Value
        The width at zero torque [arcmin].
    lost_motion : Value
        The width over ±3 % of the nominal torque [arcmin].
    """

    file: str
    stiffness_positive: Value
    stiffness_negative: Value
    backlash: Value
    lost_motion: Value


#: Where a modelled loop's figures come from, as the outputs say it.
MODEL_FROM = ("the chosen gearbox's catalog row (C_t21, backlash, T_2N) and the shape factors of the loop model "
              "(calc.domain.hysteresis.LoopModel), not a measurement (E12)")
#: Samples of a modelled loop, as drawn and analysed.
MODEL_SAMPLES = 800


@dataclass(frozen=True)
class ModelledLoop:
    """The hysteresis loop of the chosen gearbox (the best-ranked row) modelled from its catalog
    figures, and the loop as analysed like a measurement (E12): what the outputs print and draw
    where the chain names no measured loop.

    Parameters
    ----------
    part : str
        The gearbox's part.
    catalog : str
        The file of its row.
    model : calc.domain.hysteresis.LoopModel
        The model: ``C_t21`` [N·m/arcmin], backlash [arcmin], ``T_2N`` [N·m] and the shape factors.
    loop : calc.domain.hysteresis.Loop
        The modelled loop, torque [N·m] against twist [arcmin].
    analysis : calc.domain.hysteresis.LoopAnalysis
        The loop as analysed at ``T_2N``: stiffness each way [N·m/arcmin], backlash and lost motion [arcmin].
    """

    part: str
    catalog: str
    model: object
    loop: object
    analysis: object

    def to_json(self) -> dict:
        """The modelled loop as the results write it (``accuracy.modelled_loop``).

        Returns
        -------
        dict
            ``part``, ``catalog``, ``from``, the model's ``C_t21``, ``backlash_catalog``, ``T_2N`` and
            ``shape`` factors, and the analysed ``stiffness_positive``, ``stiffness_negative``,
            ``backlash`` and ``lost_motion``, each quantity as ``{"value", "unit"}``.
        """
        m, a, where = self.model, self.analysis, f"accuracy.modelled_loop ({self.part})"
        shape = {k: getattr(m, k) for k in ("soft_share", "soft_width", "friction", "gap_width")}
        return {
            "part": self.part, "catalog": self.catalog, "from": MODEL_FROM,
            "C_t21": quantity(m.stiffness, "N*m/arcmin", where),
            "backlash_catalog": quantity(m.backlash, "arcmin", where),
            "T_2N": quantity(m.nominal_torque, "N*m", where), "shape": shape,
            "stiffness_positive": quantity(a.stiffness_positive, "N*m/arcmin", where),
            "stiffness_negative": quantity(a.stiffness_negative, "N*m/arcmin", where),
            "backlash": quantity(a.backlash, "arcmin", where), "lost_motion": quantity(a.lost_motion, "arcmin", where),
        }

    def summary_line(self) -> str:
        """The modelled loop in one line of the text summary.

        Returns
        -------
        str
            Its part, where its figures come from and its analysed stiffness, backlash and lost motion.
        """
        a = self.analysis
        return (f"  Modelled loop of {self.part} (from its catalog row, not a measurement): "
                f"C = {fmt(a.stiffness_positive, 'N*m/arcmin')} / {fmt(a.stiffness_negative, 'N*m/arcmin')} "
                f"(+ / -), backlash {fmt(a.backlash, 'arcmin')}, lost motion ±3 % {fmt(a.lost_motion, 'arcmin')}")


def modelled_loop(gearbox) -> ModelledLoop | None:
    """The hysteresis loop of a gearbox section's best-ranked row, modelled from its catalog figures
    and analysed at its ``T_2N`` (E12).

    Parameters
    ----------
    gearbox : calc.sections.gearbox.GearboxResult or None
        The gearbox section's result.

    Returns
    -------
    ModelledLoop or None
        None without a gearbox, or where the row gives no ``C_t21`` or backlash.
    """
    if gearbox is None:
        return None
    cat, row = gearbox.selection.catalog, int(gearbox.selection.order[0])
    if np.isnan(cat["C_t21"][row].magnitude) or np.isnan(cat["backlash"][row].magnitude):
        return None
    model = model_for_row(cat, row)
    loop = model.loop(MODEL_SAMPLES)
    return ModelledLoop(str(cat.parts[row]), cat.catalog_of(row), model, loop, analyze_loop(loop, model.nominal_torque))


@dataclass(frozen=True)
class MeasuredTrace:
    """A member's measured transmission error over one output revolution.

    Parameters
    ----------
    file : str
        The trace's file as the results show it.
    transmission_accuracy : Value
        The range of the error [arcsec].
    direction : str
        The direction that governs.
    """

    file: str
    transmission_accuracy: Value
    direction: str


@dataclass(frozen=True)
class MeasuredPositioning:
    """The scatter of repeated moves to targets, measured at the output.

    Parameters
    ----------
    file : str
        The positions' file as the results show it.
    targets : int
        How many target positions.
    approaches : int
        How many moves in all.
    accuracy : Value
        The positioning accuracy measured [arcmin].
    repeatability : Value
        The repeatability measured [arcmin].
    """

    file: str
    targets: int
    approaches: int
    accuracy: Value
    repeatability: Value


@dataclass(frozen=True)
class Member:
    """A member of the chain referred to the output, as the outputs print it.

    Parameters
    ----------
    name : str
        The member's name.
    side : str
        ``input`` or ``output`` side of the gearbox.
    source : str
        Where its figures come from.
    stiffness_at_output : Value
        Its stiffness at the output [N·m/arcmin] (the secant ``|T| / φ(T)`` at the applied torque
        where it has a curve); no value where unknown.
    backlash_at_output : Value
        Its backlash at the output [arcmin].
    transmission_accuracy_at_output : Value or None
        Its transmission accuracy at the output [arcsec]; None where it gives none.
    share_of_compliance : float
        Its share of the chain's compliance ``1/C`` [1], so of the twist.
    twist_at_applied_torque : Value
        Its twist at the applied torque [arcmin]; no value where its stiffness is unknown.
    stiffness_curve : dict or None
        ``T1``, ``T2`` [N·m], ``K1``, ``K2``, ``K3`` [N·m/rad] as Values, where it has a curve.
    measured_loop : MeasuredLoop or None
        Its measured loop as analysed.
    measured_trace : MeasuredTrace or None
        Its measured trace as analysed.
    """

    name: str
    side: str
    source: str
    stiffness_at_output: Value
    backlash_at_output: Value
    transmission_accuracy_at_output: Value | None
    share_of_compliance: float
    twist_at_applied_torque: Value
    stiffness_curve: dict | None = None
    measured_loop: MeasuredLoop | None = None
    measured_trace: MeasuredTrace | None = None


@dataclass(frozen=True)
class AccuracyValues:
    """The chain's accuracy at the output as the outputs print it (:attr:`AccuracyResult.shown`).

    Parameters
    ----------
    applied_torque : Value
        The torque at the output [N·m].
    ratio : float or None
        The gearbox ratio the input side is referred through; None without one.
    nominal_torque : Value or None
        The nominal torque of the 3 % rule [N·m]; None where there is none.
    nominal_torque_from : str or None
        Where it comes from.
    C_total : Value
        The chain's stiffness at the output [N·m/arcmin].
    C_total_is_secant : bool
        Whether it is the secant at the applied torque (a member gives a stiffness curve).
    backlash : Value
        The chain's backlash at the output [arcmin].
    transmission_accuracy : Value
        The chain's transmission accuracy at the output [arcsec].
    transmission_accuracy_from : list of str
        The members that give one.
    lost_motion : Value
        The lost motion at the applied torque [arcmin] (E12).
    positioning_rule : str
        The rule of E13 that applied.
    positioning_accuracy : Value
        The positioning accuracy [arcmin] (E13).
    unknown : list of str
        The terms unknown for the chosen parts: the positioning accuracy is a lower bound.
    unknown_chain : list of str
        A member's twist or backlash unknown: the lost motion and the repeatability are lower
        bounds, ``C_total`` an upper one.
    repeatability : Value
        The repeatability [arcmin] (E13).
    repeatability_is_bound : bool
        Whether it is bounded by the lost motion under torque.
    members : list of Member
        The members, drive to load.
    radius : Value or None
        The radius of the arcs [mm]; None without one.
    arcs : dict
        ``backlash``, ``lost_motion``, ``positioning_accuracy``, ``repeatability`` as arcs at the radius [mm].
    check_arcs : dict
        Per check: (the chain's value, the required value) as arcs at the radius [mm].
    positioning : MeasuredPositioning or None
        The measured positions.
    """

    applied_torque: Value
    ratio: float | None
    nominal_torque: Value | None
    nominal_torque_from: str | None
    C_total: Value
    C_total_is_secant: bool
    backlash: Value
    transmission_accuracy: Value
    transmission_accuracy_from: list
    lost_motion: Value
    positioning_rule: str
    positioning_accuracy: Value
    unknown: list
    unknown_chain: list
    repeatability: Value
    repeatability_is_bound: bool
    members: list
    radius: Value | None
    arcs: dict
    check_arcs: dict
    positioning: MeasuredPositioning | None


@dataclass(frozen=True)
class ChainValues:
    """The chain referred to the output as the outputs print it: what the stiffness-chain figures draw
    (:func:`calc.figures.accuracy_plots.stiffness_chain_bars`).

    Parameters
    ----------
    applied_torque : Value
        The torque at the output [N·m].
    ratio : float or None
        The gearbox ratio the input side is referred through; None without one.
    C_total : Value
        The chain's stiffness at the output [N·m/arcmin]; no value where every member's is unknown.
    members : list of Member
        The members, drive to load.
    """

    applied_torque: Value
    ratio: float | None
    C_total: Value
    members: list


def chain_values(chain: Chain, applied_torque, loops: dict | None = None, traces: dict | None = None) -> ChainValues:
    """The chain's members referred to the output at ``applied_torque`` (E11), as the accuracy result
    records them; a member of unknown stiffness (infinite: reckoned rigid) has no stiffness or twist.

    Parameters
    ----------
    chain : calc.domain.stiffness.Chain
        The members, drive to load; a member with a stiffness curve stands in with its secant at the torque.
    applied_torque : pint.Quantity [N·m]
        The torque at the output.
    loops : dict, optional
        Member name -> (file, :class:`calc.domain.hysteresis.LoopAnalysis`) of its measured loop.
    traces : dict, optional
        Member name -> (file, :class:`calc.domain.transmission.TransmissionAnalysis`) of its measured trace.

    Returns
    -------
    ChainValues
        Applied torque, ratio, ``C_total`` and the members.

    Examples
    --------
    >>> from calc.domain.stiffness import Component
    >>> c = Chain((Component("coupling", "output", Q_(0.24, "N*m/arcmin"), Q_(0, "arcmin")),
    ...            Component("gearbox", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin"))))
    >>> v = chain_values(c, Q_(20, "N*m"))
    >>> str(v.C_total), [str(m.twist_at_applied_torque) for m in v.members]
    ('0.2026 N·m/arcmin', ['83.33 arcmin', '15.38 arcmin'])
    """
    c = chain.at_torque(as_kind(applied_torque, "torque", "applied_torque"))
    twist = c.twist(applied_torque)
    members = [_member(c, k, share, twist[k], loops or {}, traces or {}) for k, share in enumerate(c.compliance_shares)]
    return ChainValues(Value.of(applied_torque, "N*m"), None if c.ratio is None else number(c.ratio.m_as("")),
                       _known(c.stiffness, "N*m/arcmin", np.isinf(c.stiffness.magnitude)), members)


def _member(c: Chain, k: int, share: float, twist, loops: dict, traces: dict) -> Member:
    """Member ``k`` of the chain ``c`` at the output, with its measured loop and trace as analysed."""
    comp = c.components[k]
    ta = c.transmission_accuracy_at_output[k]
    curve = loop = trace = None
    if comp.stiffness_curve is not None:
        sc = comp.stiffness_curve
        curve = {"T1": Value.of(sc.T_1, "N*m"), "T2": Value.of(sc.T_2, "N*m"),
                 **{key: Value.of(getattr(sc, f"K_{key[1]}"), "N*m/rad") for key in ("K1", "K2", "K3")}}
    if comp.name in loops:
        path, m = loops[comp.name]
        loop = MeasuredLoop(path, Value.of(m.stiffness_positive, "N*m/arcmin"),
                            Value.of(m.stiffness_negative, "N*m/arcmin"), Value.of(m.backlash, "arcmin"),
                            Value.of(m.lost_motion, "arcmin"))
    if comp.name in traces:
        path, t = traces[comp.name]
        trace = MeasuredTrace(path, Value.of(t.accuracy, "arcsec"), t.governing)
    rigid = np.isinf(comp.stiffness.magnitude)  # its stiffness unknown (reckoned rigid): no stiffness, no twist to show
    return Member(comp.name, comp.side, comp.source, _known(c.stiffness_at_output[k], "N*m/arcmin", rigid),
                  Value.of(c.backlash_at_output[k], "arcmin"),
                  None if np.isnan(ta.magnitude) else Value.of(ta, "arcsec"), number(share),
                  _known(twist, "arcmin", rigid), curve, loop, trace)


def _known(q, unit: str, unknown: bool) -> Value:
    """A value, or no value (``n/a``, JSON null) where a term of it is unknown."""
    return Value(None, unit) if unknown else Value.of(q, unit)


def accuracy_values(spec: AccuracyCase, a: ChainAccuracy) -> AccuracyValues:
    """The values of the chain's accuracy in the units every output shows them in.

    Parameters
    ----------
    spec : AccuracyCase
        The section as evaluated.
    a : calc.domain.accuracy.ChainAccuracy
        The chain's accuracy.

    Returns
    -------
    AccuracyValues
        The values, the members' (:func:`chain_values`) among them.
    """
    c = a.chain
    chain = chain_values(c, a.applied_torque, spec.loops, spec.traces)
    repeatability = a.repeatability if spec.unknown else a.repeatability_bound
    arcs, check_arcs = {}, {}
    if spec.radius is not None:
        r = spec.radius
        for key in ("backlash", "lost_motion", "positioning_accuracy", "repeatability"):
            angle = {"backlash": c.backlash, "repeatability": repeatability}.get(key, getattr(a, key, None))
            arcs[key] = Value.of(arc_length(r=r, phi=angle), "mm", f"accuracy.{key}_arc")
        for k in (k.at(0) for k in requirement_checks(spec, a)):
            check_arcs[k.name] = (Value.of(arc_length(r=r, phi=k.required), "mm", f"accuracy.{k.name}"),
                                  Value.of(arc_length(r=r, phi=k.rated), "mm", f"accuracy.required_{k.name}"))
    p = spec.positions
    positioning = None if p is None else MeasuredPositioning(
        display_path(p.source), p.targets, len(p.error.magnitude), Value.of(p.accuracy, "arcmin"),
        Value.of(p.repeatability, "arcmin"))
    return AccuracyValues(
        applied_torque=chain.applied_torque, ratio=chain.ratio,
        nominal_torque=None if a.nominal_torque is None else Value.of(a.nominal_torque, "N*m"),
        nominal_torque_from="accuracy.nominal_torque" if spec.nominal_torque is not None else c.nominal_torque_from,
        C_total=chain.C_total, C_total_is_secant=c.has_curves, backlash=Value.of(c.backlash, "arcmin"),
        transmission_accuracy=Value.of(c.transmission_accuracy, "arcsec"),
        transmission_accuracy_from=c.transmission_accuracy_from, lost_motion=Value.of(a.lost_motion, "arcmin"),
        positioning_rule=a.rule.text, positioning_accuracy=Value.of(a.positioning_accuracy, "arcmin"),
        unknown=list(spec.unknown), unknown_chain=list(spec.unknown_chain),
        repeatability=Value.of(repeatability, "arcmin"), repeatability_is_bound=a.repeatability_is_bound,
        members=chain.members, radius=None if spec.radius is None else Value.of(spec.radius, "mm"), arcs=arcs,
        check_arcs=check_arcs,
        positioning=positioning,
    )


def _member_json(m: Member) -> dict:
    out = {"name": m.name, "side": m.side, "source": m.source, "stiffness_at_output": m.stiffness_at_output.to_json(),
           "backlash_at_output": m.backlash_at_output.to_json(),
           "transmission_accuracy_at_output": json_of(m.transmission_accuracy_at_output),
           "share_of_compliance": m.share_of_compliance, "twist_at_applied_torque": m.twist_at_applied_torque.to_json()}
    if m.stiffness_curve is not None:
        out["stiffness_curve"] = {key: v.to_json() for key, v in m.stiffness_curve.items()}
        out["stiffness_is_secant"] = True  # stiffness_at_output: |T| / φ(T) at the applied torque
    if m.measured_loop is not None:
        out["measured_loop"] = dataclasses.asdict(m.measured_loop)
    if m.measured_trace is not None:
        out["measured_trace"] = dataclasses.asdict(m.measured_trace)
    return out


@dataclass
class AccuracyResult(Result):
    """The chain as read, its accuracy at the output, and the required values checked.

    Parameters
    ----------
    inputs : AccuracyCase
        The section as evaluated.
    accuracy : calc.domain.accuracy.ChainAccuracy
        The chain's accuracy.
    modelled_loop : ModelledLoop or None
        The chosen gearbox's loop modelled from its catalog figures; None where the chain names a
        measured loop.
    """

    inputs: AccuracyCase
    accuracy: ChainAccuracy
    modelled_loop: ModelledLoop | None = None

    @functools.cached_property
    def shown(self) -> AccuracyValues:
        return accuracy_values(self.inputs, self.accuracy)

    @functools.cached_property
    def budget(self) -> Budget:
        """The positioning accuracy's error budget (:func:`calc.domain.accuracy.error_budget`)."""
        return error_budget(self.accuracy)

    @property
    def repeatability_basis(self) -> str:
        """What the repeatability stated rests on, in words."""
        a = self.accuracy
        if not a.repeatability_is_bound:
            return "the backlash at T = 0"
        if self.shown.repeatability.value < a.repeatability.m_as("arcmin"):
            return (f"the positioning accuracy, a full width, tighter than the lost motion "
                    f"{fmt(a.repeatability, 'arcmin')}")
        return "bounded by the lost motion under torque"

    def budget_json(self) -> dict:
        """``accuracy.budget``: the contributions with their kind and share, worst case and RSS.

        Returns
        -------
        dict
            convention, worst_case, rss, rss_random, contributions (name, kind, value, share, why), unknown.
        """
        b = self.budget
        return {
            "convention": POSITIONING_CONVENTION,
            "worst_case": Value.of(b.worst_case.result, "arcmin").to_json(),
            "rss": Value.of(b.rss.result, "arcmin").to_json(),
            "rss_random": Value.of(b.rss_random, "arcmin").to_json(),
            "contributions": [{"name": c.name, "kind": c.kind, "value": Value.of(c.value, "arcmin").to_json(),
                               "share": share, "why": c.why} for c, share in zip(b.contributions, b.shares)],
            "unknown": list(b.unknown),
        }

    def budget_lines(self) -> list[str]:
        """The error budget as lines of the text summary.

        Returns
        -------
        list of str
        """
        b = self.budget
        lines = [f"  Error budget of the positioning accuracy ({POSITIONING_CONVENTION}):"]
        lines += [f"    {c.name:<24} {c.kind:<10} {fmt(c.value, 'arcmin'):>14}  {100 * share:5.1f} %"
                  for c, share in zip(b.contributions, b.shares)]
        lines.append(f"    worst case {fmt(b.worst_case.result, 'arcmin')}; root-sum-square "
                     f"{fmt(b.rss.result, 'arcmin')}; the random ones alone (the systematic mapped out) "
                     f"{fmt(b.rss_random, 'arcmin')}")
        return lines + [f"    not known: {u}" for u in b.unknown]

    @functools.cached_property
    def arc_steps(self) -> list:
        """(title, step) of the positioning accuracy as an arc at the case's radius, and of each
        required value the case gives as an arc, as an angle; none without a radius."""
        spec, a = self.inputs, self.accuracy
        if spec.radius is None:
            return []
        at_radius = arc_length.step(r=spec.radius, phi=a.positioning_accuracy)
        return [("Positioning accuracy as an arc at the radius", at_radius)] + [
            (f"Required {name.replace('_', ' ')} given as an arc", angle_of_arc.step(s=arc, r=spec.radius))
            for name, arc in spec.required_arcs.items()]

    def to_json(self, candidates: int | None = None) -> dict:
        """The ``accuracy`` section of the results (``docs/case-format.md``): ``C_total`` referred to
        the output, ``lost_motion``, ``positioning_accuracy``, ``repeatability`` and the
        ``components`` with their ``stiffness_at_output`` and ``backlash_at_output``, each quantity as
        ``{"value", "unit"}``; measured loops, traces and positioning records where the case names them.

        Parameters
        ----------
        candidates : int or None
            Unused: the chain lists no candidates.

        Returns
        -------
        dict
            The section's record, its checks where the case gives requirements.

        Examples
        --------
        >>> from calc.sections import evaluate, read_case
        >>> from calc.data.catalog import CATALOG_DIR
        >>> r = evaluate(read_case(CATALOG_DIR.parent / "cases" / "indexing-table.toml"))["accuracy"].to_json()
        >>> round(r["C_total"]["value"], 2), r["C_total"]["unit"], [c["side"] for c in r["components"]]
        (20.1, 'N*m/arcmin', ['input', 'output'])
        """
        v = self.shown
        out = {
            "applied_torque": v.applied_torque.to_json(), "ratio": v.ratio, "nominal_torque": json_of(v.nominal_torque),
            "nominal_torque_from": v.nominal_torque_from, "C_total": v.C_total.to_json(),
            "C_total_is_secant": v.C_total_is_secant,
            "backlash": v.backlash.to_json(), "transmission_accuracy": v.transmission_accuracy.to_json(),
            "transmission_accuracy_from": v.transmission_accuracy_from, "lost_motion": v.lost_motion.to_json(),
            "positioning_rule": v.positioning_rule, "positioning_accuracy": v.positioning_accuracy.to_json(),
            # A term unknown for the chosen parts: the value above is a lower bound, and says which.
            "positioning_accuracy_is_lower_bound": bool(v.unknown), "unknown": v.unknown,
            # A member's twist or backlash unknown (reckoned rigid, free of backlash): bounds too.
            "lost_motion_is_lower_bound": bool(v.unknown_chain), "repeatability_is_lower_bound": bool(v.unknown_chain),
            "C_total_is_upper_bound": bool(v.unknown_chain),
            "repeatability": v.repeatability.to_json(), "repeatability_is_bound": v.repeatability_is_bound,
            "repeatability_basis": self.repeatability_basis,
            "positioning_convention": POSITIONING_CONVENTION,
            "budget": self.budget_json(),
            "components": [_member_json(m) for m in v.members],
        }
        if v.radius is not None:
            out["radius"] = v.radius.to_json()
            out.update({f"{key}_arc": arc.to_json() for key, arc in v.arcs.items()})
        if v.positioning is not None:
            out["measured_positioning"] = dataclasses.asdict(v.positioning)
        if self.modelled_loop is not None:
            out["modelled_loop"] = self.modelled_loop.to_json()
        g = self.governing()
        if g is not None:
            # An accuracy check lists the chain's value and the limit the case requires of it.
            out["checks"] = [self._check_json(k) for k in g.checks]
            out["passes"] = self.verdict().passes
        return out

    def _check_json(self, k) -> dict:
        out = {"name": k.name, "criterion": k.criterion, "value": quantity(k.required, k.unit, f"accuracy.{k.name}"),
               "required": quantity(k.rated, k.unit, f"accuracy.required_{k.name}"),
               "utilization": None if k.utilization is None else number(k.utilization, f"accuracy.{k.name}"),
               "passes": k.passes}
        if k.not_made is not None:
            out["not_made"] = k.not_made
        if k.at_least and k.passes is False:
            out["value_is_lower_bound"] = True  # a term unknown, and the bound already over the limit
        out["governs"] = True
        if k.name in self.shown.check_arcs:
            value_arc, required_arc = self.shown.check_arcs[k.name]
            out.update(value_arc=value_arc.to_json(), required_arc=required_arc.to_json())
        return out

    def summary_lines(self, candidates: int | None = None) -> list[str]:
        """The accuracy results as lines of the terminal report: the chain table, then C_total, lost
        motion, positioning accuracy with the rule that applied, and repeatability, each with its
        errata entry; measurements and checks after.

        Parameters
        ----------
        candidates : int or None
            Unused: the chain lists no candidates.

        Returns
        -------
        list of str
            The lines.
        """
        v = self.shown
        ratio = "" if v.ratio is None else f", ratio {v.ratio:g}"
        lines = [f"Accuracy at the output (applied torque {v.applied_torque}{ratio}; E11 to E13):"]
        width = max(len("component"), *(len(m.name) for m in v.members))
        lines.append(f"  {'component':<{width}}  side    {'stiffness at output':>20}  {'share of twist':>14}  "
                     f"{'backlash at output':>18}  source")
        for m in v.members:
            lines.append(
                f"  {m.name:<{width}}  {m.side:<6}  {str(m.stiffness_at_output):>20}  "
                f"{100 * m.share_of_compliance:>12.1f} %"
                f"  {str(m.backlash_at_output):>18}  {m.source}"
            )
        ta_from = ", ".join(v.transmission_accuracy_from) or "no component gives one"
        t_n = "" if v.nominal_torque is None else f", T_N = {v.nominal_torque} ({v.nominal_torque_from})"
        lines += [
            f"  C_total {'<=' if v.unknown_chain else '='} {v.C_total}{SECANT if v.C_total_is_secant else ''}; "
            f"backlash {'>=' if v.unknown_chain else '='} {v.backlash}; transmission accuracy = "
            f"{v.transmission_accuracy} ({ta_from})",
            f"  Lost motion = j_t + |T| / C {relation(self.inputs, 'lost_motion')} {v.lost_motion} (E12)",
            f"  Positioning accuracy ({v.positioning_rule}{t_n}) {relation(self.inputs, 'positioning_accuracy')} "
            f"{v.positioning_accuracy} (E13)"
            + (f"; a lower bound: unknown {'; '.join(v.unknown)}" if v.unknown else ""),
            f"  Repeatability {'<=' if v.repeatability_is_bound else '='} {v.repeatability} "
            f"({self.repeatability_basis}, E13)"
            + (f"; not known: unknown {'; '.join(v.unknown_chain)}" if v.unknown_chain else ""),
        ]
        if v.radius is not None:
            a = v.arcs
            lines.append(
                f"  As arcs s = r · φ at r = {v.radius}: backlash {a['backlash']}, lost motion {a['lost_motion']}, "
                f"positioning accuracy {a['positioning_accuracy']}, repeatability {a['repeatability']}"
            )
        for m in v.members:
            if m.measured_loop is not None:
                loop = m.measured_loop
                lines.append(
                    f"  Measured loop of {m.name} ({loop.file}): C = {loop.stiffness_positive} / "
                    f"{loop.stiffness_negative} (+ / -), backlash {loop.backlash}, lost motion ±3 % {loop.lost_motion}"
                )
            if m.measured_trace is not None:
                t = m.measured_trace
                lines.append(f"  Measured trace of {m.name} ({t.file}): transmission accuracy "
                             f"{t.transmission_accuracy} ({t.direction})")
        if self.modelled_loop is not None:
            lines.append(self.modelled_loop.summary_line())
        lines += self.budget_lines()
        if v.positioning is not None:
            p = v.positioning
            lines.append(
                f"  Measured positioning ({p.file}, {p.approaches} approaches to {p.targets} targets): "
                f"accuracy {p.accuracy}, repeatability {p.repeatability}"
            )
        g = self.governing()
        for k in [] if g is None else g.checks:
            value, limit = k.required_value, k.rated_value
            if k.passes is None:
                lines.append(f"  {k.name:<22} {relation(self.inputs, k.name)} {value} required <= {limit}  not made: "
                             f"{k.not_made}")
                continue
            arcs = v.check_arcs.get(k.name)
            lines.append(
                f"  {k.name:<22} {('>= ' if k.at_least else '') + str(value):>12} required <= {str(limit):>12}  "
                f"utilization {'>= ' if k.at_least else ''}{k.utilization:.2f}  {'ok' if k.passes else 'FAIL'}"
                + (f"  (as arcs: {arcs[0]} <= {arcs[1]})" if arcs else "")
            )
        return lines

    def governing(self) -> Governing | None:
        """The checks against the case's requirements (the chain's value as the required side, the
        case's limit as the rated one); a value that is a lower bound decides nothing.

        Returns
        -------
        calc.sections.common.Governing or None
            The checks; None without requirements.
        """
        checks = []
        for k in (c.at(0) for c in requirement_checks(self.inputs, self.accuracy)):
            why = not_known(self.inputs, k.name)
            if why is not None and k.passes is False and not self.inputs.unchosen:
                checks.append(dataclasses.replace(k, at_least=True))  # a lower bound already over the limit: it fails
            else:
                checks.append(k if why is None else dataclasses.replace(k, passes=None, utilization=None,
                                                                        not_made=why, at_least=True))
        return Governing(NAME, None, True, checks) if checks else None

    def verdict(self) -> Verdict | None:
        """The required values govern; a chain without requirements decides nothing.

        Returns
        -------
        calc.sections.common.Verdict or None
            Failing and undecided requirements with their reasons; None without requirements.
        """
        g = self.governing()
        if g is None:
            return None
        open_ = [k for k in g.checks if k.passes is None]
        failing = [k for k in g.checks if k.passes is False]
        reasons = [
            f"The accuracy requirement is not met: {k.name} {'>= ' if k.at_least else ''}{fmt(k.required, k.unit)} > "
            f"required {fmt(k.rated, k.unit)}, "
            f"{'at least ' if k.at_least else ''}{sig(100 * (k.utilization - 1), 3)} % over"
            + (f" (a lower bound: unknown {'; '.join(_unknown_terms(self.inputs, k.name))})" if k.at_least else "")
            for k in failing
        ] + [
            f"The accuracy requirement is not decided: {k.name} {relation(self.inputs, k.name)} "
            f"{fmt(k.required, k.unit)}, {k.not_made}"
            for k in open_
        ]
        return Verdict(False if failing else (None if open_ else True), reasons)


class AccuracySection(Section):
    """The accuracy of the drive chain: its table read with the case, its members taken from the
    parts the gearbox and coupling sections choose where it follows them."""

    NAME = NAME
    TABLES = TABLES
    REQUIRES = ("gearbox", "coupling")

    def read_inputs(self, case: Case) -> AccuracyInputs:
        return read_inputs(case)

    def evaluate(self, case: Case, earlier) -> AccuracyResult:
        gearbox = earlier.get("gearbox")
        spec = accuracy_case(case, self.inputs(case), gearbox, earlier.get("coupling"))
        return AccuracyResult(spec, _chain_accuracy(case, spec), None if spec.loops else modelled_loop(gearbox))


SECTION = AccuracySection()
