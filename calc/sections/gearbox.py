"""The gearbox of a case (``[gearbox]``): the catalog rows at the desired ratio (or the named part)
checked for the duty of the load cycle and ranked (:mod:`calc.gearbox`, E1 to E6)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..bands import factor_table
from ..case import Case, Declared, Key, Table, once
from ..catalog import display_path, load_catalogs
from ..errors import CalcError
from ..gearbox import HUB_SCHEMA, SCHEMA, SHOCK_FACTORS, GearboxSelection, rows_at_ratio, select_gearbox
from ..units import fmt
from .common import SHOWN_CANDIDATES, Verdict, check_json, check_line, no_candidate_passes, quantity

NAME = "gearbox"
ORDER = 40
TABLES = (Declared(NAME, (
    Key("ratio", "dimensionless", "ratio of the gearbox, as desired (needed unless a part is named)", "i"),
    Key("catalog", "catalog", "the gearbox catalog(s): a name in catalogs/ or a path to a CSV file", default="gearboxes"),
    Key("part", "text", "check this one part instead of ranking the catalog (never a partial row)"),
    Key("hubs", "catalog", "the table of clamping hubs (J_1 per hub), picked by motor.shaft", default="gearbox-hubs"),
    Key("emergency_stop_torque", "torque", "torque of an emergency stop against the catalog's T_2Not (default T_1B · i)", "T_2stop", unit="N*m"),
    Key("shock_factors", "factor table", "the table of the shock factor f_s (E4): source, or a path to a CSV file", default="source"),
), "the gearbox: the rows at the desired ratio (or the named part) checked for the duty and ranked"),)
RANKING = (
    "passing first; published rows before illustrative ones; then smallest governing torque rating "
    "(T_2B in S5, T_2N in S1); then lowest worst utilization (the emergency stop's included where the row gives T_2Not); "
    "partial rows are never ranked"
)


def read(top: Table, case: Case) -> None:
    """Read ``[gearbox]`` into the case: the ratio (above zero; needed unless a part is named),
    the catalog and the part."""
    gearbox = top.table(NAME, TABLES[0].keys)
    if not gearbox:
        return
    case.ratio = gearbox.positive("ratio", required=not gearbox.has("part"), what="a ratio")
    case.gearbox_catalog = gearbox.catalogs("catalog")
    case.gearbox_hubs = gearbox.catalogs("hubs")
    case.gearbox_part = gearbox.text("part")
    case.emergency_stop_torque = gearbox.positive("emergency_stop_torque")
    case.shock_factors = factor_table("shock", gearbox.text("shock_factors"), case.folder, gearbox.where("shock_factors"))


def applies(case: Case) -> bool:
    return case.ratio is not None or case.gearbox_part is not None


def gearbox_selection(case: Case) -> GearboxSelection:
    """The gearbox catalog of the case, narrowed to its ratio (or named part), checked and ranked;
    computed once per case."""
    return once(case, "gearbox", lambda: _select(case))


def catalogs(case: Case) -> tuple:
    """The case's gearbox catalog (its rows together, when it names several) and hub table."""
    where = f"{case.path}: gearbox"
    return (load_catalogs(case.gearbox_catalog, case.folder, f"{where}.catalog", SCHEMA),
            load_catalogs(case.gearbox_hubs, case.folder, f"{where}.hubs", HUB_SCHEMA))


def selection_inputs(case: Case) -> dict:
    """What :func:`calc.gearbox.select_gearbox` takes from the case beside the profile and rows."""
    return dict(
        motor_peak_torque=case.motor_peak_torque, motor_inertia=case.motor_inertia, load_inertia=case.load_inertia,
        emergency_stop_torque=case.emergency_stop_torque, output_load=case.output_load,
        motor_shaft=None if case.motor_shaft is None else case.motor_shaft.nominal,
        shock_factors=SHOCK_FACTORS if case.shock_factors is None else case.shock_factors,
    )


def _select(case: Case) -> GearboxSelection:
    where = f"{case.path}: gearbox"
    catalog, hubs = catalogs(case)
    if case.gearbox_part is not None:
        rows = catalog.rows([catalog.usable_index(case.gearbox_part, f"{where}.part")])
        part_ratio = rows["ratio"][0].m_as("")
        if case.ratio is not None and not np.isclose(part_ratio, case.ratio.m_as(""), rtol=1e-6):
            raise CalcError(
                f"{where}.part: {case.gearbox_part} has ratio {part_ratio:g}, but gearbox.ratio is {case.ratio.m_as(''):g}"
            )
    else:
        rows = rows_at_ratio(catalog, case.ratio, f"{where}.ratio")
    return select_gearbox(case.profile, rows, hubs=hubs, **selection_inputs(case))


@dataclass
class GearboxResult:
    """The ranked gearbox candidates of a case and the part chosen."""

    selection: GearboxSelection

    def to_json(self, candidates: int | None = SHOWN_CANDIDATES) -> dict:
        s = self.selection
        listed = []
        for c in s.candidates(candidates):
            listed.append(
                {
                    "part": c.part,
                    "ratio": c.ratio,
                    "passes": c.passes,
                    "illustrative": c.illustrative,
                    "checks": [check_json(k) for k in c.checks],
                    "inertia_ratio": c.inertia_ratio,
                    "T2max": None if c.T_2max is None else quantity(c.T_2max, "N*m", f"gearbox {c.part}: T2max"),
                    "reasons": c.reasons,
                    "catalog": c.catalog,
                    "family": c.family,
                    "size": c.size,
                    "source": c.source,
                    "unclear": c.unclear or None,
                    "best_of_family": c.best_of_family,
                    "J_1": None if c.J_1 is None else quantity(c.J_1, "kg*cm**2", f"gearbox {c.part}: J_1"),
                    "J_1_hub": None if c.J_1_hub is None else quantity(c.J_1_hub, "mm", f"gearbox {c.part}: J_1_hub"),
                }
            )
        return {
            "catalog": s.catalog.shown_name,
            "catalog_sha256": s.catalog.sha256,
            "catalogs": [{"catalog": display_path(path), "sha256": sha} for path, sha in s.catalog.members],
            "mode": s.mode,
            "ranking": RANKING,
            "candidate_count": len(s.order),
            "candidates": listed,
            "selected": s.selected,
            "best_of_family": {str(s.catalog.family[row]): str(s.catalog.parts[row]) for row in s.order[s.best_of_family[s.order]]},
            "notes": list(s.notes or []),
        }

    def summary_lines(self, candidates: int | None = SHOWN_CANDIDATES) -> list[str]:
        s = self.selection
        lines = [f"Gearbox candidates ({s.mode} governs; catalog {s.catalog.shown_name}):"]
        several = len(s.catalog.members) > 1
        for c in s.candidates(candidates):
            verdict = {True: "PASS", False: "FAIL", None: "OPEN"}[c.passes]
            lam = "" if c.inertia_ratio is None else f", inertia ratio {c.inertia_ratio:.2f}"
            hub = "" if c.J_1 is None or np.isnan(c.J_1.magnitude) else f", J_1 {fmt(c.J_1, 'kg*cm**2')}" + (
                "" if np.isnan(c.J_1_hub.magnitude) else f" ({fmt(c.J_1_hub, 'mm')} hub)"
            )
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
        lines.append(f"Selected gearbox: {s.selected or ('none: ' + s.not_made[0].not_made if s.not_made else 'none passes')}")
        return lines

    def verdict(self) -> Verdict:
        s = self.selection
        if s.selected is not None:
            return Verdict(True)
        best = s.order[0]
        ratios = ", ".join(sorted({f"{r:g}" for r in s.catalog["ratio"].m_as("")}))
        what = f"gearbox of ratio {ratios} in {s.catalog.shown_name}"
        if s.passes[best] and s.not_made:
            return Verdict(None, [f"No {what} can be chosen: {c.reason(best)}" for c in s.not_made])
        return Verdict(False, no_candidate_passes(f"No {what} passes the {s.mode} checks:", s.catalog.parts, s.order, s.reasons))


def evaluate(case: Case) -> GearboxResult:
    return GearboxResult(gearbox_selection(case))
