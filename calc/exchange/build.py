"""The IDTA 02021 submodel filled from a case's evaluated results: the project, the motion pattern
at the gearbox output, the mechanism, every chosen part as a main component with its utilizations,
the overall results and the messages. Every number is one the results recorded; nothing is computed
again here (docs/case-format.md, "The exchange with IDTA 02021", maps each result to its path)."""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path

import aas_core3.types as aas

from .. import Q_
from ..report.provenance import PACKAGE
from .elements import collection, entity, file, number, reference, template_reference, text
from .motion_file import motion_csv
from .sizing import sizing_result
from .template import SUBMODEL_SEMANTIC_ID

#: The template's entity for each mechanism type of the case (readings I4).
MECHANISM_ENTITIES = {"rotary": "RotraryTable", "ball-screw": "SpindleDrive", "rack-pinion": "RackDrive",
                      "belt": "BeltDrive"}
#: Where the files of an AASX lie in the package.
FILES = "/aasx/files/"


@dataclass
class Exported:
    """An AAS environment of one sized axis and the files its elements name.

    Parameters
    ----------
    environment : aas_core3.types.Environment
        The shell of the axis and its IDTA 02021 submodel.
    files : dict
        The name each File element gives (``indexing-table.toml``) -> (content type, bytes).
    """

    environment: aas.Environment
    files: dict = field(default_factory=dict)


def numbered(elements: list) -> list:
    """Elements of one kind, numbered ``01``, ``02`` ... where there is more than one (readings I5).

    Parameters
    ----------
    elements : list
        Elements of one template idShort.

    Returns
    -------
    list
        The same elements, their idShorts numbered where there are several.
    """
    if len(elements) > 1:
        for k, e in enumerate(elements, start=1):
            e.id_short = f"{e.id_short}{k:02d}"
    return elements


def export_environment(results, report_pdf: Path | None = None, in_package: bool = False) -> Exported:
    """The AAS environment of a case's evaluated results.

    Parameters
    ----------
    results : calc.sections.evaluation.Results
        The case's results.
    report_pdf : pathlib.Path, optional
        The calc report built of the case, linked as a second sizing file.
    in_package : bool, optional
        Whether the files lie in an AASX (their paths then start with ``/aasx/files/``).

    Returns
    -------
    Exported
        The environment and the files its File elements name.
    """
    case_path = Path(results.case.path)
    case_bytes = case_path.read_bytes()
    digest = hashlib.sha256(case_bytes).hexdigest()
    stem = re.sub(r"[^A-Za-z0-9-]", "-", case_path.stem)
    prefix = FILES if in_package else ""
    files = {case_path.name: ("application/toml", case_bytes)}
    links = [file("SizingProjectInformation.SizingProjectLink", prefix + case_path.name, "application/toml",
                  sha256=digest)]
    if report_pdf is not None:
        pdf = Path(report_pdf).read_bytes()
        files[Path(report_pdf).name] = ("application/pdf", pdf)
        links.append(file("SizingProjectInformation.SizingProjectLink", prefix + Path(report_pdf).name,
                          "application/pdf", sha256=hashlib.sha256(pdf).hexdigest()))
    data = results.to_json(None)
    motion = results.sections.get("motion")
    requirements = [motion_pattern(results.case.title, motion, results.case.output_load,
                                   f"{stem}-motion-pattern.csv", prefix, files),
                    overall_requirements(motion)]
    elements = [
        project_information(results.case.title, case_path.stem, numbered(links)),
        collection("ApplicationRequirements", requirements),
        mechanism(motion, stem),
        sizing_result(results, data),
    ]
    submodel = aas.Submodel(
        f"urn:calc:{stem}:{digest[:16]}:sizing", id_short="PowerDriveTrainSizing", kind=aas.ModellingKind.INSTANCE,
        semantic_id=reference("ExternalReference", "GlobalReference", SUBMODEL_SEMANTIC_ID),
        submodel_elements=[e for e in elements if e is not None])
    shell = aas.AssetAdministrationShell(
        f"urn:calc:{stem}:{digest[:16]}:aas", aas.AssetInformation(aas.AssetKind.INSTANCE,
                                                                   global_asset_id=f"urn:calc:{stem}:axis"),
        id_short="SizedAxis", submodels=[reference("ModelReference", "Submodel", submodel.id)])
    return Exported(aas.Environment([shell], [submodel]), files)


def project_information(title: str, axis: str, links: list) -> aas.SubmodelElementCollection:
    """The project: its name (the case's title), the axis (the case file's name), the case file and
    report with their SHA-256, the tool, the dates.

    Parameters
    ----------
    title : str
        The case's title.
    axis : str
        The case file's stem.
    links : list of aas_core3.types.File
        The sizing files.

    Returns
    -------
    aas_core3.types.SubmodelElementCollection
    """
    p = "SizingProjectInformation."
    now = datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    return collection("SizingProjectInformation", [
        aas.Property(aas.DataTypeDefXSD.STRING, id_short="ClientName",
                     semantic_id=template_reference(p + "ClientName")),  # the case names no client (readings I7)
        text(p + "SizingProjectName", title), text(p + "SizingProjectAxisReference", axis), *links,
        text(p + "SizingToolName", PACKAGE),
        text(p + "DateCreated", now, value_type=aas.DataTypeDefXSD.DATE_TIME),
        text(p + "DateChanged", now, value_type=aas.DataTypeDefXSD.DATE_TIME),
    ])


def motion_pattern(title: str, motion, forces, name: str, prefix: str, files: dict):
    """The motion pattern: one rotative section at the gearbox output, its samples as a CSV file
    (readings I2, I3); None where the case types its cycle as segments.

    Parameters
    ----------
    title : str
        The case's title.
    motion : calc.sections.motion.MotionResult or None
        The motion section's result.
    forces : calc.domain.gearbox.OutputForces or None
        The forces on the gearbox output the case gives.
    name : str
        The CSV file's name.
    prefix : str
        The files' folder in a package ("" beside a JSON file).
    files : dict
        The files written; the CSV is added.

    Returns
    -------
    aas_core3.types.SubmodelElementCollection or None
    """
    if motion is None:
        return None
    s, m = motion.motion.samples, motion.motion
    columns = {"Time": s.t, "AngularPosition": s.position, "AngularVelocity": s.speed,
               "AngularAcceleration": s.acceleration, "AngularJerk": s.jerk, "LoadTorque": m.cycle.torque}
    files[name] = ("text/csv", motion_csv(columns).encode())
    p = "ApplicationRequirements.MotionPattern.MotionPatternSections.RotativeSection"
    units = {"Time": "s", "AngularPosition": "rad", "AngularVelocity": "rad/s", "AngularAcceleration": "rad/s²",
             "AngularJerk": "rad/s³", "LoadTorque": "Nm"}
    meta = [text(f"{p}.MetadataRotativeMotionFile.{k}", u) for k, u in units.items()]
    J_L = motion.to_json().get("J_L")
    section = collection(p, [number(p + ".MomentOfInertiaOfLoad", J_L, "kg*m**2"),
                             *_load_forces(forces, p),
                             collection(p + ".MetadataRotativeMotionFile", meta),
                             file(p + ".MotionSectionFile", prefix + name, "text/csv")])
    return collection("ApplicationRequirements.MotionPattern", [
        text("ApplicationRequirements.MotionPattern.MotionPatternName", title),
        collection("ApplicationRequirements.MotionPattern.MotionPatternSections", [section])])


def _load_forces(forces, p: str) -> list:
    # The output bearing's forces the case gives in [load], as static values of the section.
    names = (("AxialForce", "axial_force", "N"), ("RadialForce", "radial_force", "N"),
             ("LeverArmRadialForce", "lever_arm", "m"), ("LeverArmAxialForce", "axial_radius", "m"))
    return [number(f"{p}.{k}", None if getattr(forces, a, None) is None else Q_(getattr(forces, a)).m_as(u))
            for k, a, u in names]


def overall_requirements(motion):
    """The overall system's requirements the case gives: a brake that holds the load.

    Parameters
    ----------
    motion : calc.sections.motion.MotionResult or None

    Returns
    -------
    aas_core3.types.SubmodelElementCollection or None
    """
    mech = None if motion is None else motion.motion.mechanism
    if mech is None or not mech.holding_brake:
        return None
    return collection("ApplicationRequirements.OverallSystemRequirements",
                      [text("ApplicationRequirements.OverallSystemRequirements.BrakePresent", "true")])


def mechanism(motion, stem: str):
    """The transformation mechanism: the template's entity for the case's type, with the data the
    template has a place for (readings I4).

    Parameters
    ----------
    motion : calc.sections.motion.MotionResult or None
    stem : str
        The case's name, for the entity's asset.

    Returns
    -------
    aas_core3.types.SubmodelElementCollection or None
    """
    mech = None if motion is None else motion.motion.mechanism
    if mech is None:
        return None
    name = MECHANISM_ENTITIES[mech.type]
    p = f"TransformationMechanism.{name}."

    def q(x, unit):
        return None if x is None else Q_(x).m_as(unit)

    own = q(mech.own_inertia, "kg*m**2")
    no_load = q(mech.friction_torque if mech.type == "rotary" else mech.drag_torque, "N*m")
    statements = [number(p + "Efficiency", q(mech.eta, "")), number(p + "InertiaMotorSide", own),
                  number(p + "NoLoadTorque", no_load), number(p + "InclinationAngle", q(mech.incline, "rad"))]
    if name != "RotraryTable":
        statements += [number(p + "FrictionCoefficient", q(mech.friction_coefficient, "")),
                       number(p + "FeedConstant", q(mech.lead, "m"))]
    if name == "RackDrive":
        statements.append(number(p + "DiameterPinion", q(mech.diameter, "m")))
    return collection("TransformationMechanism", [
        entity(p.rstrip("."), statements, global_asset_id=f"urn:calc:{stem}:mechanism")])
