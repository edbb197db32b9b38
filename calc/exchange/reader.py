"""A case file from an IDTA 02021 submodel (the workbook's or another tool's): the motion pattern's
rotative section as a drive record at the gearbox output, the load's inertia and the output's forces
where given, the chosen motor and gearbox as parts of the shipped catalogs, the drive where it is a
usable part of the shipped drive catalog; every other value of the submodel listed at the file's
head as one the case cannot use; what the case needs and the submodel lacks an error naming it."""

from __future__ import annotations

import json
from dataclasses import dataclass

import aas_core3.types as aas
import numpy as np

from .. import Q_
from ..core.errors import CalcError
from ..data.catalog import load_catalogs
from ..domain.drive import SCHEMA as DRIVE_SCHEMA
from .motion_file import read_motion_csv
from .package import Opened
from .template import SUBMODEL_SEMANTIC_ID, base_id_short

_SECTIONS = "ApplicationRequirements.MotionPattern.MotionPatternSections"
#: The main components a case takes, by type: the table and its catalog.
PARTS = {"Motor": ("motor", "motors"), "Gearbox": ("gearbox", "gearboxes"), "DriveController": ("drive", "drives")}


@dataclass
class Imported:
    """A case file's text and its drive record's CSV text.

    Parameters
    ----------
    case : str
        The TOML text.
    record : str
        The drive record's CSV text (time [s], speed [rpm], torque [N*m] where given).
    """

    case: str
    record: str


def sizing_submodel(opened: Opened) -> aas.Submodel:
    """The IDTA 02021 submodel of an AAS file, found by its semanticId.

    Parameters
    ----------
    opened : calc.exchange.package.Opened

    Returns
    -------
    aas_core3.types.Submodel

    Raises
    ------
    CalcError
        Where the file has none.
    """
    for sm in opened.environment.submodels or []:
        if sm.semantic_id is not None and any(k.value == SUBMODEL_SEMANTIC_ID for k in sm.semantic_id.keys):
            return sm
    raise CalcError(f"{opened.path}: expected a submodel with semanticId {SUBMODEL_SEMANTIC_ID} (IDTA 02021), "
                    f"found none")


def flatten(elements, prefix: str = "") -> dict:
    """Every element of a submodel by its idShort path, numbers kept (``SizingResult.MainComponent01``).

    Parameters
    ----------
    elements : iterable of aas_core3.types.SubmodelElement
    prefix : str, optional

    Returns
    -------
    dict
        Path -> element.
    """
    out = {}
    for e in elements or []:
        path = prefix + (e.id_short or "")
        out[path] = e
        if isinstance(e, aas.SubmodelElementCollection):
            out.update(flatten(e.value, path + "."))
        elif isinstance(e, aas.Entity):
            out.update(flatten(e.statements, path + "."))
        elif isinstance(e, aas.SubmodelElementList):
            out.update(flatten(e.value, path + "."))
    return out


def value_of(element, where: str):
    """A property's value as a number, or its text.

    Parameters
    ----------
    element : aas_core3.types.SubmodelElement or None
    where : str
        The element's path, as the error names it.

    Returns
    -------
    float, str or None

    Raises
    ------
    CalcError
        For a number of the template that is not one.
    """
    if element is None or not isinstance(element, aas.Property) or element.value is None:
        return None
    if element.value_type in (aas.DataTypeDefXSD.STRING,):
        return element.value
    try:
        x = float(element.value)
    except ValueError:
        raise CalcError(f"{where}: expected a number, found {element.value[:40]!r}") from None
    if not np.isfinite(x):
        raise CalcError(f"{where}: expected a finite number, found {element.value[:40]!r}")
    return x


def import_case(opened: Opened, record_name: str) -> Imported:
    """The case file of an AAS file's IDTA 02021 submodel.

    Parameters
    ----------
    opened : calc.exchange.package.Opened
    record_name : str
        The drive record's file name, as the case names it.

    Returns
    -------
    Imported

    Raises
    ------
    CalcError
        Where the submodel lacks what the case needs (a rotative section with its time series) or a
        value is of the wrong type.
    """
    sm = sizing_submodel(opened)
    where = f"{opened.path}: submodel {sm.id_short}"
    flat = flatten(sm.submodel_elements)
    used: set[str] = set()
    sections = [p for p in flat if p.rsplit(".", 1)[0] == _SECTIONS]
    rotative = [p for p in sections if base_id_short(p.rsplit(".", 1)[1]) == "RotativeSection"]
    if len(rotative) != 1:
        found = ", ".join(p.rsplit(".", 1)[1] for p in sections) or "none"
        raise CalcError(f"{where}: the case needs one {_SECTIONS}.RotativeSection (a time series at the gearbox "
                        f"output), found {found}")
    sec = rotative[0]
    file_el = flat.get(sec + ".MotionSectionFile")
    if not isinstance(file_el, aas.File) or not file_el.value:
        raise CalcError(f"{where}: the case needs {sec}.MotionSectionFile, a file with the time series; found none")
    columns = read_motion_csv(opened.read(file_el.value, f"{sec}.MotionSectionFile"),
                              f"{opened.path.name}: {sec}.MotionSectionFile")
    used |= {sec + ".MotionSectionFile"} | {p for p in flat if p.startswith(sec + ".MetadataRotativeMotionFile.")}
    record = _record(columns)

    def number(path):
        used.add(path)
        return value_of(flat.get(path), f"{where}: {path}")

    title = number("SizingProjectInformation.SizingProjectName") or opened.path.stem
    lines = [f"title = {json.dumps(str(title))}", ""]
    inertia = number(sec + ".MomentOfInertiaOfLoad")
    if inertia is None and "LoadTorque" not in columns:
        raise CalcError(f"{where}: the case needs {sec}.MomentOfInertiaOfLoad or a LoadTorque column, found "
                        f"neither")
    lines += _parts(flat, used, where)
    forces = [(k, number(f"{sec}.{name}"), u) for k, name, u in
              (("axial_force", "AxialForce", "N"), ("radial_force", "RadialForce", "N"),
               ("lever_arm", "LeverArmRadialForce", "m"), ("axial_force_radius", "LeverArmAxialForce", "m"))]
    if any(v is not None for _, v, _ in forces):
        lines += ["[load]", *[f'{k} = "{v!r} {u}"' for k, v, u in forces if v is not None], ""]
    if inertia is not None:
        lines += ["[mechanism]", 'type = "rotary"', f'inertia = "{inertia!r} kg*m**2"', ""]
    lines += ["[drive_record]", f"file = {json.dumps(record_name)}", ""]
    head = _head(opened, flat, used)
    return Imported("\n".join(head + lines), record)


def _record(columns: dict) -> str:
    names = ["time [s]", "speed [rpm]"] + (["torque [N*m]"] if "LoadTorque" in columns else [])
    speed = Q_(columns["AngularVelocity"], "rad/s").m_as("rpm")
    table = [columns["Time"], speed] + ([columns["LoadTorque"]] if "LoadTorque" in columns else [])
    rows = "\n".join(",".join(f"{x:.12g}" for x in row) for row in np.column_stack(table))
    return ",".join(names) + "\n" + rows + "\n"


def _parts(flat: dict, used: set, where: str) -> list[str]:
    lines = []
    for path, e in flat.items():
        if path.count(".") != 1 or base_id_short(path.split(".")[1]) != "MainComponent":
            continue
        kind = value_of(flat.get(path + ".MainComponentType"), f"{where}: {path}.MainComponentType")
        part = value_of(flat.get(path + ".ManufacturerArticleNumber"), f"{where}: {path}.ManufacturerArticleNumber")
        if kind in PARTS and part:
            table, catalog = PARTS[kind]
            if table == "drive" and not drive_in_catalog(str(part)):
                continue  # another tool's drive: listed at the file's head
            lines += [f"[{table}]", f'catalog = "{catalog}"', f"part = {json.dumps(str(part))}"]
            if table == "drive":
                lines += ["# The submodel has no place for a brake resistor: add [drive.brake_resistor] where there is",
                          "# one (without it, each braking event is checked against the DC link's energy)."]
            lines.append("")
            used |= {path, path + ".MainComponentType", path + ".ManufacturerArticleNumber"}
    return lines


def drive_in_catalog(part: str) -> bool:
    """Whether a drive is a part of the shipped drive catalog that a case can name: a row with
    both currents published (a partial row is never chosen).

    Parameters
    ----------
    part : str
        The DriveController's ``ManufacturerArticleNumber``.

    Returns
    -------
    bool
        True where ``[drive] catalog = "drives"`` with this ``part`` names a usable row.
    """
    catalog = load_catalogs("drives", None, "drive.catalog", DRIVE_SCHEMA)
    rows = np.flatnonzero(catalog.parts == part)
    return bool(rows.size) and not catalog.partial[rows[0]]


def _head(opened: Opened, flat: dict, used: set) -> list[str]:
    unused = [p for p, e in flat.items() if p not in used and _has_value(e)]
    head = [f"# Read from {opened.path.name}, an IDTA 02021 submodel, by python -m calc import.",
            "# The motion pattern is a drive record at the gearbox output; the load's inertia a rotary mechanism",
            "# there. The submodel's values the case cannot use:"]
    head += [f"#   {p} = {_shown(flat[p])}" for p in unused] or ["#   none"]
    return head + [""]


def _has_value(e) -> bool:
    return isinstance(e, (aas.Property, aas.File, aas.MultiLanguageProperty, aas.Range)) and bool(
        getattr(e, "value", None) or getattr(e, "min", None) or getattr(e, "max", None))


def _shown(e) -> str:
    if isinstance(e, aas.MultiLanguageProperty):
        text = e.value[0].text
    elif isinstance(e, aas.Range):
        text = f"{e.min} .. {e.max}"
    else:
        text = e.value
    return " ".join(str(text).split())[:100]
