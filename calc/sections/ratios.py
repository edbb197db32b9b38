"""The best ratio of a case (``python -m calc ratios CASE``): the case evaluated at every ratio its
gearbox catalog offers (:mod:`calc.ratios`), the ratio to pick and why. Not a section of the
evaluation: its own command, with the same exit status rules."""

from __future__ import annotations

from dataclasses import dataclass

from ..case import Case, once
from ..catalog import display_path
from ..errors import CalcError
from ..ratios import INERTIA_RATIO_LIMIT, RULE, RatioSearch, search_ratios
from ..units import sig
from .gearbox import catalogs, selection_inputs
from .common import Verdict, check_json, number, quantity
from .motor import TYPED, output_load, rotor_inertia


#: Not evaluated with the case (its own command, :func:`search`); its place in the report.
ORDER = 70


@dataclass
class RatioResult:
    """The ratio search of a case, as the ``ratios`` command writes it."""

    case: Case
    search: RatioSearch
    notes: list

    def verdict(self) -> Verdict:
        """True when a ratio can be picked, else False with the reason."""
        s = self.search
        return Verdict(True) if s.pick is not None else Verdict(False, [s.reason])

    def to_json(self) -> dict:
        s = self.search
        load = s.load
        rows = []
        for k, ratio in enumerate(s.ratios):
            rows.append({
                "ratio": float(ratio),
                "part": str(s.parts[k]),
                "passes": bool(s.feasible[k]),
                "gearbox_passes": bool(s.gearbox_passes[k]),
                "utilization": number(s.utilization[k], f"ratio {ratio:g}: utilization"),
                "inertia_ratio": number(s.inertia_ratio[k], f"ratio {ratio:g}: inertia_ratio"),
                "peak_torque_required": None if load is None else quantity(load.peak[k], "N*m", f"ratio {ratio:g}: peak torque"),
                "rms_torque_required": None if load is None else quantity(load.rms[k], "N*m", f"ratio {ratio:g}: RMS torque"),
                "max_speed_required": quantity(s.speed[k], "rpm", f"ratio {ratio:g}: speed"),
                "checks": [check_json(c.at(k)) for c in s.motor],
                "reasons": s.gearbox_reasons(k) + s.motor_reasons(k),
            })
        cat = s.selection.catalog
        return {
            "title": self.case.title,
            "case": display_path(self.case.path),
            "catalog": display_path(cat.path),
            "catalog_sha256": cat.sha256,
            "mode": s.selection.mode,
            "rule": RULE,
            "inertia_ratio_limit": INERTIA_RATIO_LIMIT,
            "rotor_term": bool(load is not None and load.rotor_term),
            "ratios": rows,
            "pick": None if s.pick is None else {"ratio": float(s.ratios[s.pick]), "part": str(s.parts[s.pick]), "reason": s.reason},
            "reason": s.reason,
            "notes": list(self.notes),
            "verdict": self.verdict().to_json(),
        }

    def summary(self) -> str:
        j = self.to_json()
        title = f"{self.case.title}: the ratio"
        lines = [title, "=" * len(title), j["reason"], f"Rule: {RULE}.", "",
                 f"{'ratio':>6}  {'gearbox':<14} {'verdict':<7} {'util.':>6} {'λ':>7} {'T_1peak':>10} {'T_1rms':>10} {'n_1':>9}"]
        for r in j["ratios"]:
            def val(d, unit):
                return "n/a" if d is None or d["value"] is None else f"{sig(d['value'], 4)} {unit}"

            lam = "n/a" if r["inertia_ratio"] is None else f"{r['inertia_ratio']:.2f}"
            util = "n/a" if r["utilization"] is None else f"{r['utilization']:.2f}"
            mark = "  <- pick" if j["pick"] and j["pick"]["ratio"] == r["ratio"] else ""
            lines.append(
                f"{r['ratio']:>6g}  {r['part']:<14} {'PASS' if r['passes'] else 'FAIL':<7} {util:>6} {lam:>7} "
                f"{val(r['peak_torque_required'], 'N·m'):>10} {val(r['rms_torque_required'], 'N·m'):>10} {val(r['max_speed_required'], 'rpm'):>9}{mark}"
            )
            lines += [f"          {reason}" for reason in r["reasons"]]
        return "\n".join(lines + [f"Note: {n}" for n in j["notes"]])


def search(case: Case) -> RatioResult:
    """Every ratio of the case's gearbox catalog; computed once per case."""
    return once(case, "ratios", lambda: _search(case))


def _search(case: Case) -> RatioResult:
    if case.gearbox_catalog is None:
        raise CalcError(f"{case.path}: gearbox: the ratio search needs a [gearbox] table (its catalog gives the ratios to try), found none")
    catalog, hubs = catalogs(case)
    load = output_load(case)
    notes = []
    if case.gearbox_part is not None:
        notes.append(f"gearbox.part = {case.gearbox_part!r} is not kept to: every row of the catalog is tried")
    if not load.sampled:
        notes.append(TYPED)
    s = search_ratios(
        catalog, case.profile, load, case.motor_rated_torque, case.motor_max_speed, lambda J_1: rotor_inertia(case, J_1),
        hubs=hubs, **selection_inputs(case),
    )
    notes += s.notes
    return RatioResult(case, s, notes)
