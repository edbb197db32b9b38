"""The gearbox of a case (``[gearbox]``): the catalog rows at the desired ratio (or the named part)
checked for the duty of the load cycle and ranked (:mod:`calc.domain.gearbox`, E1 to E6)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..data.bands import factor_table
from .case import Case, Declared, Key, Table
from ..data.catalog import load_catalogs
from ..core.errors import CalcError, listing, as_found
from ..domain.gearbox import (
    HUB_SCHEMA, SCHEMA, SHOCK_FACTORS, GearboxSelection, M_2k, T_2max, inertia_ratio, n_1, rows_at_ratio, same_ratio,
    select_gearbox, shock_factor,
)
from ..domain.profile import Z_h, n_2m
from ..core.units import Q_, sig
from . import coupling
from .common import (SHOWN_CANDIDATES, Governing, Verdict, check_json, check_line, json_of, row_json,
                     selection_governing, selection_verdict)
from .protocol import Result, Section

NAME = "gearbox"
ORDER = 40
TABLES = (Declared(NAME, (
    Key("ratio", "dimensionless", "ratio of the gearbox, as desired (needed unless a part is named)", "i"),
    Key("catalog", "catalog", "the gearbox catalog(s): a name in catalogs/ or a path to a CSV file",
        default="gearboxes"),
    Key("part", "text", "check this one part instead of ranking the catalog (never a partial row)"),
    Key("family", "text",
        "check only gearboxes of this family (the catalog's family column: \"NPT\"), or of these (a list)"),
    Key("hubs", "catalog", "the table of clamping hubs (J_1 per hub), picked by motor.shaft", default="gearbox-hubs"),
    Key("emergency_stop_torque", "torque",
        "torque of an emergency stop against the catalog's T_2Not (default T_1B · i)", "T_2stop", unit="N*m"),
    Key("shock_factors", "factor table", "the table of the shock factor f_s (E4): source, or a path to a CSV file",
        default="source"),
), "the gearbox: the rows at the desired ratio (or the named part) checked for the duty and ranked"),)
RANKING = (
    "passing first; published rows before illustrative ones, and where the case fits a coupling between motor and "
    "gearbox, rows whose drive train some coupling lifts above 2 f_er (f_1,max) before those it does not; "
    "then smallest governing torque rating (T_2B in S5, T_2N in S1); then lowest worst utilization "
    "(the emergency stop's included where the row gives T_2Not); partial rows are never ranked"
)


def read(top: Table, case: Case) -> None:
    """Read ``[gearbox]`` into the case: the ratio (above zero; needed unless a part is named),
    the catalog and the part; the tables of shock factors and of clamping hubs it names.

    Parameters
    ----------
    top : calc.sections.case.Table
        The case file's top-level table.
    case : calc.sections.case.Case
        The case being read; its gearbox fields are written.

    Returns
    -------
    None
    """
    gearbox = top.table(NAME, TABLES[0].keys)
    if not gearbox:
        return
    case.ratio = gearbox.positive("ratio", required=not gearbox.has("part"), what="a ratio")
    case.gearbox_catalog = gearbox.catalogs("catalog")
    case.gearbox_hubs = gearbox.catalogs("hubs")
    case.gearbox_part = gearbox.text("part")
    case.gearbox_family = gearbox.texts("family")
    case.emergency_stop_torque = gearbox.positive("emergency_stop_torque")
    case.shock_factors = factor_table("shock", gearbox.text("shock_factors"), case.folder,
                                      gearbox.where("shock_factors"))
    case.gearbox_hubs = load_catalogs(case.gearbox_hubs, case.folder, gearbox.where("hubs"), HUB_SCHEMA)


def catalogs(case: Case) -> tuple:
    """The case's gearbox catalog and hub table.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.

    Returns
    -------
    tuple of calc.data.catalog.Catalog
        The catalog (its rows together, when it names several; only those of its families where
        it names some) and the table of clamping hubs read with the case.
    """
    where = f"{case.path}: gearbox"
    catalog = load_catalogs(case.gearbox_catalog, case.folder, f"{where}.catalog", SCHEMA)
    if case.gearbox_family:
        unknown = [f for f in case.gearbox_family if not (catalog.family == f).any()]
        if unknown:
            known = listing(sorted(set(catalog.family.tolist())))
            raise CalcError(f"{where}.family: the catalog {catalog.shown_name} has no gearbox of family "
                            f"{as_found(unknown[0])}; its families are {known}")
        if case.gearbox_part is not None:
            family = catalog.family[catalog.index(case.gearbox_part, f"{where}.part")]
            if family not in case.gearbox_family:
                families = listing(map(repr, case.gearbox_family), " or ")
                raise CalcError(f"{where}.part: {case.gearbox_part} is of family {as_found(family)}, "
                                f"but gearbox.family is {families}")
        named = tuple(case.gearbox_family)
        catalog = catalog.kept_rows(("family", named), np.isin(catalog.family, named))
    return catalog, case.gearbox_hubs


def selection_inputs(case: Case) -> dict:
    """What :func:`calc.domain.gearbox.select_gearbox` takes from the case beside the profile and rows.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with.

    Returns
    -------
    dict
        Its keyword arguments: the motor's peak torque and inertia, the load's inertia, the
        emergency stop's torque, the forces on the output, the motor shaft's nominal diameter,
        the table of shock factors and the coupling's span.
    """
    return dict(
        motor_peak_torque=case.motor_peak_torque, motor_inertia=case.motor_inertia, load_inertia=case.load_inertia,
        emergency_stop_torque=case.emergency_stop_torque, output_load=case.output_load,
        motor_shaft=None if case.motor_shaft is None else case.motor_shaft.nominal,
        shock_factors=SHOCK_FACTORS if case.shock_factors is None else case.shock_factors,
        coupling_span=coupling.coupling_span(case),
    )


def gearbox_selection(case: Case) -> GearboxSelection:
    """The gearbox catalog of the case, narrowed to its ratio (or named part), checked and ranked.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with
        (:class:`calc.sections.axis.AxisResult`).

    Returns
    -------
    calc.domain.gearbox.GearboxSelection
        The rows checked and ranked, with a note naming the families where the case keeps to some.
    """
    where = f"{case.path}: gearbox"
    catalog, hubs = catalogs(case)
    if case.gearbox_part is not None:
        rows = catalog.rows([catalog.usable_index(case.gearbox_part, f"{where}.part")])
        part_ratio = rows["ratio"][0].m_as("")
        if case.ratio is not None and not same_ratio(part_ratio, case.ratio.m_as("")):
            raise CalcError(
                f"{where}.part: {case.gearbox_part} has ratio {part_ratio:g}, "
                f"but gearbox.ratio is {case.ratio.m_as(''):g}"
            )
    else:
        rows = rows_at_ratio(catalog, case.ratio, f"{where}.ratio")
    selection = select_gearbox(case.profile, rows, hubs=hubs, **selection_inputs(case))
    if case.gearbox_family:
        families = " or ".join(case.gearbox_family)
        selection.notes.append(f"only gearboxes of family {families} are checked (gearbox.family)")
    return selection


@dataclass
class GearboxResult(Result):
    """The ranked gearbox candidates of a case and the part chosen, with the calculations of the
    best-ranked row's checks as steps.

    Parameters
    ----------
    selection : calc.domain.gearbox.GearboxSelection
        The rows checked and ranked.
    steps : list, optional
        (title, :class:`calc.core.formula.Step`, what it is compared with) of the best-ranked
        row's checks (:func:`check_steps`).
    inertia_note : str, optional
        Where the case fits a coupling between motor and gearbox: that the candidates' λ counts their
        ``J_1`` without it, which the motor's check counts (one λ, said where another is shown).
    """

    selection: GearboxSelection
    steps: list = field(default_factory=list)
    inertia_note: str | None = None
    ranking = RANKING

    def to_json(self, candidates: int | None = SHOWN_CANDIDATES) -> dict:
        s = self.selection
        listed = [
            {
                "part": c.part,
                "ratio": c.ratio,
                "passes": c.passes,
                "illustrative": c.illustrative,
                "checks": [check_json(k) for k in c.checks],
                "inertia_ratio": c.inertia_ratio,
                "T2max": json_of(c.T_2max),
                **row_json(c),
                "best_of_family": c.best_of_family,
                "J_1": json_of(c.J_1),
                "J_1_hub": json_of(c.J_1_hub),
            }
            for c in s.candidates(candidates)
        ]
        return {
            **s.catalog.provenance(),
            "mode": s.mode,
            "ranking": self.ranking,
            "candidate_count": len(s.order),
            "candidates": listed,
            "selected": s.selected,
            "best_of_family": {str(s.catalog.family[row]): str(s.catalog.parts[row])
                               for row in s.order[s.best_of_family[s.order]]},
            "notes": list(s.notes or []),
        }

    def summary_lines(self, candidates: int | None = SHOWN_CANDIDATES) -> list[str]:
        s = self.selection
        lines = [f"Gearbox candidates ({s.mode} governs; catalog {s.catalog.shown_name}):"]
        several = len(s.catalog.members) > 1
        for c in s.candidates(candidates):
            verdict = {True: "PASS", False: "FAIL", None: "OPEN"}[c.passes]
            lam = "" if c.inertia_ratio is None else f", inertia ratio {c.inertia_ratio:.2f}"
            hub_size = "" if c.J_1_hub.value is None else f" ({c.J_1_hub} hub)"
            hub = "" if c.J_1.value is None else f", J_1 {c.J_1}" + hub_size
            best = f", smallest adequate {c.family}" if c.best_of_family else ""
            where = f" [{c.catalog}]" if several else ""
            lines.append(f"  {verdict}  {c.part}{where}{' (illustrative)' if c.illustrative else ''}{best}{lam}{hub}")
            lines += [f"        {check_line(k)}" for k in c.checks]
            if c.unclear:
                lines.append(f"        doubtful figures: {c.unclear}")
            lines += [f"        rejected: {r}" for r in c.reasons]
        if candidates is not None and len(s.order) > candidates:
            lines.append(f"  ... {len(s.order) - candidates} more candidates (--all-candidates lists them)")
        lines += [f"  note: {note}" for note in s.notes or []]
        none = "none: " + s.not_made[0].not_made if s.not_made else "none passes"
        lines.append(f"Selected gearbox: {s.selected or none}")
        return lines

    def governing(self) -> Governing:
        return selection_governing(NAME, self.selection)

    def ranked(self) -> GearboxSelection:
        return self.selection

    def verdict(self) -> Verdict:
        s = self.selection
        # Distinct first: a catalog may have 10^5 rows.
        ratios = ", ".join(sorted({f"{r:g}" for r in np.unique(s.catalog["ratio"].m_as(""))}))
        return selection_verdict(s, f"gearbox of ratio {ratios} in {s.catalog.shown_name}", f"the {s.mode} checks")


def check_steps(case: Case, sel: GearboxSelection) -> list:
    """The calculations of the best-ranked row's checks: the input speeds, T_2max with the case's
    shock factor, the inertia ratio with the J_1 of the row's clamping hub and the tilting moment
    of the output bearing.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with.
    sel : calc.domain.gearbox.GearboxSelection
        Its gearbox rows, ranked.

    Returns
    -------
    list of tuple
        (title, :class:`calc.core.formula.Step`, what it is compared with) of each.
    """
    p = case.profile
    row = int(sel.order[0])
    cat = sel.catalog
    i = cat["ratio"][row]
    table = SHOCK_FACTORS if case.shock_factors is None else case.shock_factors
    seg = p.moving_values()
    n_2 = n_2m(n_2k=seg["n_2k"], t_k=seg["t_k"])
    out = [("Input speed at the mean output speed (S1)", n_1.step(n_2=n_2, i=i), "compared with n_1N"),
           ("Input speed at the highest output speed (S5)", n_1.step(n_2=p.n_2max, i=i), "compared with n_1max")]
    if case.motor_peak_torque is not None:
        f_s = Q_(float(shock_factor(Z_h(**p.cycles_per_hour_inputs()), table)), "")
        step = T_2max.step(T_1B=case.motor_peak_torque, i=i, f_s=f_s, eta=cat["eta"][row])
        out.append(("Maximum output torque", step, "compared with T_2B"))
    if sel.inertia_ratio is not None and not np.isnan(sel.J_1[row].magnitude):
        hub = sel.J_1_hub[row]
        hub_size = "" if np.isnan(hub.magnitude) else f"; J_1 for the {sig(hub.m_as('mm'))} mm clamping hub"
        which = "errata E6" + hub_size
        step = inertia_ratio.step(J_1=sel.J_1[row], J_L=case.load_inertia, i=i, J_motor=case.motor_inertia)
        out.append(("Load to motor inertia ratio", step, which))
    load = case.output_load
    if load is not None:
        zero, z_2 = Q_(0.0, "mm"), cat["z_2"][row]
        out.append(("Tilting moment on the output bearing", M_2k.step(
            F_2a=load.axial_force if load.axial_force is not None else Q_(0.0, "N"),
            y_2=load.axial_radius if load.axial_radius is not None else zero,
            F_2r=load.radial_force if load.radial_force is not None else Q_(0.0, "N"),
            x_2=load.lever_arm if load.lever_arm is not None else zero,
            z_2=zero if np.isnan(z_2.magnitude) else z_2,
        ), "compared with M_2K; WITTENSTEIN's form" + ("; z_2 = 0, the catalog gives none" if np.isnan(z_2.magnitude)
                                                        else "")))
    return out


class GearboxSection(Section):
    """The gearbox: the catalog's rows at the ratio (or the named part), checked with the motor
    the case is checked with, and ranked."""

    NAME = NAME
    TABLES = TABLES
    REQUIRES = ("axis",)

    def read(self, top: Table, case: Case) -> None:
        read(top, case)

    def applies(self, case: Case) -> bool:
        return case.ratio is not None or case.gearbox_part is not None

    def evaluate(self, case: Case, earlier) -> GearboxResult:
        axis = earlier["axis"]
        case = axis.case
        selection = gearbox_selection(case)
        if axis.gearbox is not None:  # chosen with the motor (calc.sections.axis)
            selection.put_first(axis.gearbox)
        given = coupling.SECTION.inputs(case)
        note = None
        if selection.inertia_ratio is not None and given is not None and given.side == "input":
            note = ("λ of the candidates counts each gearbox's J_1 alone: the coupling between motor and gearbox is "
                    "chosen after the gearbox; the motor's check, the ratio search and the dynamics count its J too")
        return GearboxResult(selection, check_steps(case, selection), note)


SECTION = GearboxSection()
