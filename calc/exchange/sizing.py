"""The sizing result of the IDTA 02021 submodel from a case's results JSON: the overall system, a
main component for each chosen part (motor, gearbox, coupling, and the servo drive where the
evaluation has one), the messages and the text statement. Each utilization is a check's as the
results recorded it, in percent (docs/case-format.md, "The exchange with IDTA 02021")."""

from __future__ import annotations

from pathlib import Path

import aas_core3.types as aas

from ..report.provenance import PACKAGE

from .elements import collection, entity, number, template_reference, text, words

_MC = "SizingResult.MainComponent."
#: The component type of each section's part (the template's example "Motor"; readings I10).
COMPONENT_TYPES = {"motor": "Motor", "gearbox": "Gearbox", "coupling": "Coupling", "drive": "DriveController"}
#: Per section: the checks whose utilization the component's torque, speed and thermal utilization
#: are, first found first (readings I8).
CHECKS = {
    "motor": {"torque": ("peak",), "speed": ("n_max",), "thermal": ("RMS",)},
    "gearbox": {"torque": ("T_2B", "T_2N"), "speed": ("n_1max",), "thermal": ("n_1N",)},
    "coupling": {"torque": ("T_KN",), "speed": ("n_max",), "thermal": ()},
    "drive": {"torque": (), "speed": (), "thermal": ()},
}


def find_check(checks: list, names: tuple):
    """The first of a part's checks (as JSON) by name, governing ones first.

    Parameters
    ----------
    checks : list of dict
        The checks as the results JSON writes them.
    names : tuple of str
        The names looked for, in order.

    Returns
    -------
    dict or None
    """
    for name in names:
        found = [k for k in checks if k["name"] == name]
        found.sort(key=lambda k: not k.get("governs"))
        if found:
            return found[0]
    return None


def percent(check) -> float | None:
    """A check's utilization in percent; None for a check not made or not found.

    Parameters
    ----------
    check : dict or None

    Returns
    -------
    float or None
    """
    if check is None or check.get("utilization") is None:
        return None
    return 100 * check["utilization"]


def chosen(section: dict) -> dict:
    """The chosen candidate of a section's results JSON (the section itself for typed ratings).

    Parameters
    ----------
    section : dict

    Returns
    -------
    dict
    """
    part = section.get("selected")
    return next((c for c in section.get("candidates", []) if c.get("part") == part), section)


def component(name: str, section: dict) -> aas.Entity | None:
    """A main component from a section's results JSON.

    Parameters
    ----------
    name : str
        The section: ``motor``, ``gearbox``, ``coupling`` or ``drive``.
    section : dict
        Its results JSON.

    Returns
    -------
    aas_core3.types.Entity or None
        None where the section chose no part.
    """
    part = section.get("selected")
    if not part:
        return None
    row = chosen(section)
    checks = row.get("checks") or section.get("checks") or []
    rules = CHECKS[name]
    torque, speed = find_check(checks, rules["torque"]), find_check(checks, rules["speed"])
    thermal = percent(find_check(checks, rules["thermal"]))
    extra = []
    if name == "motor":
        if (section.get("thermal") or {}).get("utilization") is not None:
            thermal = 100 * section["thermal"]["utilization"]
        lam = find_check(checks, ("lambda",))
        extra = [number(_MC + "RmsOfMotorTorque", section.get("rms_torque_required"), "N*m"),
                 number(_MC + "MassInertiaRatio", None if lam is None else lam["required"]["value"]),
                 number(_MC + "MaxRegenerativePowerDcLink",
                        (section.get("energy") or {}).get("peak_braking_power"), "W")]
    if name == "drive":
        extra = drive_values(section)
    family = row.get("family")
    statements = [
        text(_MC + "MainComponentType", COMPONENT_TYPES[name]),
        # the catalog row's maker where its catalog has the column (motors, drives), else no value (readings I9)
        aas.Property(aas.DataTypeDefXSD.STRING, id_short="ManufacturerName",
                     semantic_id=template_reference(_MC + "ManufacturerName"), value=row.get("maker") or None),
        text(_MC + "ManufacturerArticleNumber", part),
        words(_MC + "ManufacturerProductDesignation", family) if family else None,
        text(_MC + "ManufacturerOrderCode", section.get("order") or part),
        number(_MC + "MaxTorqueUtilizationPercentage", percent(torque)),
        number(_MC + "MaxTorqueUtilization", None if torque is None else torque["required"], "N*m"),
        number(_MC + "MaxRotationSpeedUtilizationPercentage", percent(speed)),
        number(_MC + "MaxRotationSpeedUtilization", None if speed is None else speed["required"], "rpm"),
        number(_MC + "MaxThermalUtilizationPercentage", thermal),
        *extra,
    ]
    return entity("SizingResult.MainComponent", statements)


def drive_values(section: dict) -> list:
    """The servo drive's currents and braking powers (the contract of ``drive``: ``current_peak``,
    ``checks``, ``braking.peak_power``, ``braking.resistor_average_power``).

    Parameters
    ----------
    section : dict
        The drive's results JSON.

    Returns
    -------
    list
        Elements or None.
    """
    current = [k for k in section.get("checks", [])
               if (k.get("required") or {}).get("unit") in ("A", "ampere") and k.get("utilization") is not None]
    braking = section.get("braking") or {}
    return [
        number(_MC + "MaxCurrentUtilizationPercentage",
               max((100 * k["utilization"] for k in current), default=None)),
        number(_MC + "MaxCurrentUtilization", section.get("current_peak"), "A"),
        number(_MC + "MaxRegenerativePowerDcLink", braking.get("peak_power"), "W"),
        number(_MC + "AverageRegenerativePowerDcLink", braking.get("resistor_average_power"), "W"),
    ]


def messages(results, data: dict) -> list:
    """The verdict's reasons (errors), every check not made (warnings) and every section's notes
    (information).

    Parameters
    ----------
    results : calc.sections.evaluation.Results
    data : dict
        Its JSON.

    Returns
    -------
    list of aas_core3.types.SubmodelElementCollection
    """
    p = "SizingResult.Messages.Message"
    said = ([("Error", r) for r in results.verdict.reasons] + [("Warning", r) for r in results.not_made()]
            + [("Information", n) for s in data.values() if isinstance(s, dict) for n in s.get("notes") or []
               if isinstance(n, str)])
    out = [collection(p, [text(p + ".CriticalityOfMessage", level), words(p + ".MessageText", said_text)])
           for level, said_text in said]
    if len(out) > 1:
        for k, m in enumerate(out, start=1):
            m.id_short = f"Message{k:02d}"
    return out


def sizing_result(results, data: dict) -> aas.SubmodelElementCollection:
    """The sizing result: the overall system, the main components, the messages, the statement.

    Parameters
    ----------
    results : calc.sections.evaluation.Results
    data : dict
        Its JSON (``results.to_json(None)``).

    Returns
    -------
    aas_core3.types.SubmodelElementCollection
    """
    parts = [c for name in COMPONENT_TYPES if isinstance(data.get(name), dict)
             if (c := component(name, data[name])) is not None]
    if len(parts) > 1:
        for k, c in enumerate(parts, start=1):
            c.id_short = f"MainComponent{k:02d}"
    lam = find_check((data.get("motor") or {}).get("checks") or [], ("lambda",))
    overall = entity("SizingResult.OverallSystem", [
        number("SizingResult.OverallSystem.MassInertiaRatio", None if lam is None else lam["required"]["value"])])
    statement = (f"Sized by {PACKAGE} from the case file {Path(results.case.path).name}; verdict "
                 f"{results.verdict.word}. Each utilization is a check's, in percent; each check not made is a "
                 f"warning.")
    return collection("SizingResult", [
        overall, *parts,
        aas.SubmodelElementCollection(id_short="Messages", semantic_id=template_reference("SizingResult.Messages"),
                                      value=messages(results, data) or None),
        words("SizingResult.TextStatement", statement)])
