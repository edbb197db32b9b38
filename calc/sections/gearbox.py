"""The gearbox of a case (``[gearbox]``): the catalog rows at the desired ratio (or the named part)
checked for the duty of the load cycle and ranked (:mod:`calc.gearbox`, E1 to E6)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..bands import factor_table
from ..case import Case, Table, once
from ..catalog import display_path, load_catalog, resolve
from ..errors import CalcError
from ..gearbox import SCHEMA, GearboxSelection, rows_at_ratio, select_gearbox
from .common import SHOWN_CANDIDATES, Verdict, check_json, check_line, no_candidate_passes, quantity

NAME = "gearbox"
KEYS = ("ratio", "catalog", "part", "shock_factors")
RANKING = (
    "passing first; published rows before illustrative ones; then smallest governing torque rating "
    "(T_2B in S5, T_2N in S1); then lowest worst utilization"
)


def read(top: Table, case: Case) -> None:
    """Read ``[gearbox]`` into the case: the ratio (above zero; needed unless a part is named),
    the catalog and the part."""
    gearbox = top.table("gearbox", KEYS)
    if not gearbox:
        return
    case.ratio = gearbox.positive("ratio", "dimensionless", required=not gearbox.has("part"), what="a ratio")
    case.gearbox_catalog = gearbox.text("catalog", default="gearboxes")
    case.gearbox_part = gearbox.text("part")
    case.shock_factors = factor_table("shock", gearbox.text("shock_factors"), case.folder, gearbox.where("shock_factors"))


def applies(case: Case) -> bool:
    return case.ratio is not None or case.gearbox_part is not None


def gearbox_selection(case: Case) -> GearboxSelection:
    """The gearbox catalog of the case, narrowed to its ratio (or named part), checked and ranked;
    computed once per case."""
    return once(case, "gearbox", lambda: _select(case))


def _select(case: Case) -> GearboxSelection:
    where = f"{case.path}: gearbox"
    catalog = load_catalog(resolve(case.gearbox_catalog, case.folder, f"{where}.catalog"), SCHEMA)
    if case.gearbox_part is not None:
        rows = catalog.rows([catalog.index(case.gearbox_part, f"{where}.part")])
        part_ratio = rows["ratio"][0].m_as("")
        if case.ratio is not None and not np.isclose(part_ratio, case.ratio.m_as(""), rtol=1e-6):
            raise CalcError(
                f"{where}.part: {case.gearbox_part} has ratio {part_ratio:g}, but gearbox.ratio is {case.ratio.m_as(''):g}"
            )
    else:
        rows = rows_at_ratio(catalog, case.ratio, f"{where}.ratio")
    return select_gearbox(case.profile, rows, case.motor_peak_torque, case.motor_inertia, case.load_inertia, case.shock_factors)


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
                }
            )
        return {
            "catalog": display_path(s.catalog.path),
            "catalog_sha256": s.catalog.sha256,
            "mode": s.mode,
            "ranking": RANKING,
            "candidate_count": len(s.order),
            "candidates": listed,
            "selected": s.selected,
        }

    def summary_lines(self, candidates: int | None = SHOWN_CANDIDATES) -> list[str]:
        s = self.selection
        lines = [f"Gearbox candidates ({s.mode} governs; catalog {display_path(s.catalog.path)}):"]
        for c in s.candidates(candidates):
            verdict = {True: "PASS", False: "FAIL", None: "OPEN"}[c.passes]
            lam = "" if c.inertia_ratio is None else f", inertia ratio {c.inertia_ratio:.2f}"
            lines.append(f"  {verdict}  {c.part}{' (illustrative)' if c.illustrative else ''}{lam}")
            lines += [f"        {check_line(k)}" for k in c.checks]
            lines += [f"        rejected: {r}" for r in c.reasons]
        if candidates is not None and len(s.order) > candidates:
            lines.append(f"  ... {len(s.order) - candidates} more candidates (--all-candidates lists them)")
        lines.append(f"Selected gearbox: {s.selected or ('none: ' + s.not_made[0].not_made if s.not_made else 'none passes')}")
        return lines

    def verdict(self) -> Verdict:
        s = self.selection
        if s.selected is not None:
            return Verdict(True)
        best = s.order[0]
        ratios = ", ".join(sorted({f"{r:g}" for r in s.catalog["ratio"].m_as("")}))
        what = f"gearbox of ratio {ratios} in {display_path(s.catalog.path)}"
        if s.passes[best] and s.not_made:
            return Verdict(None, [f"No {what} can be chosen: {c.reason(best)}" for c in s.not_made])
        return Verdict(False, no_candidate_passes(f"No {what} passes the {s.mode} checks:", s.catalog.parts, s.order, s.reasons))


def evaluate(case: Case) -> GearboxResult:
    return GearboxResult(gearbox_selection(case))
