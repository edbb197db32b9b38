"""A design case evaluated: the results of ``python -m calc evaluate`` (``spec/case-format.md``).

:func:`evaluate` returns plain data ready for JSON: every quantity as ``{"value", "unit"}``,
ratios and factors as numbers, verdicts as booleans. :func:`summary` prints the same for a reader.
Each section of the case is evaluated by the function listed in :data:`SECTIONS`.
"""

from __future__ import annotations

import importlib
import math

import numpy as np

from .case import Case, once
from .catalog import display_path, load_catalog, resolve
from .errors import CalcError
from .gearbox import SCHEMA as GEARBOX_SCHEMA
from .gearbox import GearboxSelection, rows_at_ratio, select_gearbox, shock_factor
from .profile import T_2m, Z_h, duty, n_2m
from .units import magnitude_in, pretty_unit, sig


#: Further sections of a case, by name: the module that evaluates it. Each such module has
#: ``section_results(case) -> dict`` and ``summary_lines(section: dict) -> list[str]``.
SECTIONS = {"coupling": "calc.coupling", "accuracy": "calc.accuracy"}


def quantity(q, unit: str) -> dict:
    """A scalar quantity as the contract writes it: ``{"value": 21.3, "unit": "N*m"}``."""
    return {"value": number(magnitude_in(q, unit)), "unit": unit}


def number(x):
    """A float for JSON; NaN (no value) becomes null."""
    x = float(x)
    return None if math.isnan(x) else x


def gearbox_selection(case: Case) -> GearboxSelection:
    """The gearbox catalog of the case, narrowed to its ratio (or named part), checked and ranked;
    computed once per case."""
    return once(case, "gearbox", lambda: _select_gearbox(case))


def _select_gearbox(case: Case) -> GearboxSelection:
    where = f"{case.path}: gearbox"
    catalog = load_catalog(resolve(case.gearbox_catalog, case.folder, f"{where}.catalog"), GEARBOX_SCHEMA)
    if case.gearbox_part is not None:
        row = catalog.index(case.gearbox_part, f"{where}.part")
        rows = catalog.rows([row])
        part_ratio = rows["ratio"][0].m_as("")
        if case.ratio is not None and not np.isclose(part_ratio, case.ratio.m_as(""), rtol=1e-6):
            raise CalcError(
                f"{where}.part: {case.gearbox_part} has ratio {part_ratio:g}, but gearbox.ratio is {case.ratio.m_as(''):g}"
            )
    else:
        rows = rows_at_ratio(catalog, case.ratio, f"{where}.ratio")
    d = duty(case.profile)
    if d.mode == "S5" and case.motor_peak_torque is None:
        raise CalcError(
            f"{case.path}: motor.peak_torque: the cycle is S5 (ED {sig(d.ED.m_as('percent'), 3)} %), "
            "whose check T_2max <= T_2B needs the motor's peak torque T_1B, found none"
        )
    return select_gearbox(case.profile, rows, case.motor_peak_torque, case.motor_inertia, case.load_inertia)


def _gearbox_results(selection: GearboxSelection) -> dict:
    candidates = []
    for c in selection.candidates():
        candidates.append(
            {
                "part": c.part,
                "ratio": c.ratio,
                "passes": c.passes,
                "illustrative": c.illustrative,
                "checks": [
                    {
                        "name": k["name"],
                        "mode": k["mode"],
                        "governs": k["governs"],
                        "criterion": k["text"],
                        "required": quantity(k["required"], k["unit"]),
                        "rated": quantity(k["rated"], k["unit"]),
                        "utilization": number(k["utilization"]),
                        "passes": k["passes"],
                    }
                    for k in c.checks
                ],
                "inertia_ratio": c.inertia_ratio,
                "T2max": None if c.T_2max is None else quantity(c.T_2max, "N*m"),
                "reasons": c.reasons,
            }
        )
    return {
        "catalog": display_path(selection.catalog.path),
        "catalog_sha256": selection.catalog.sha256,
        "mode": selection.mode,
        "ranking": "passing first; published rows before illustrative ones; then smallest governing torque rating (T_2B in S5, T_2N in S1); then lowest worst utilization",
        "candidates": candidates,
        "selected": selection.selected,
    }


def evaluate(case: Case) -> dict:
    """Every result the case's inputs allow, as plain data (the JSON contract)."""
    p = case.profile
    d = duty(p)
    seg = p.moving_values()
    zh = Z_h(t_cycle=p.t_cycle)
    out = {
        "title": case.title,
        "case": display_path(case.path),
        "duty": {
            "t_on": quantity(d.t_on, "s"),
            "t_cycle": quantity(d.t_cycle, "s"),
            "ED": quantity(d.ED, "percent"),
            "mode": d.mode,
        },
        "continuous": {
            "n2m": quantity(n_2m(n_2k=seg["n_2k"], t_k=seg["t_k"]), "rpm"),
            "T2m": quantity(T_2m(**seg), "N*m"),
            "governs": d.mode == "S1",
        },
        "cyclic": {
            "Zh": quantity(zh, "1/hour"),
            "fs": float(shock_factor(zh)),
            "n2max": quantity(p.n_2max, "rpm"),
            "governs": d.mode == "S5",
        },
    }
    if case.ratio is not None or case.gearbox_part is not None:
        selection = gearbox_selection(case)
        out["gearbox"] = _gearbox_results(selection)
        if selection.T_2max is not None:
            row = selection.order[0]
            out["cyclic"]["T2max"] = quantity(selection.T_2max[row], "N*m")
            out["cyclic"]["T2max_part"] = str(selection.catalog.parts[row])
    for name, module in SECTIONS.items():
        if name in case.sections:
            out[name] = importlib.import_module(module).section_results(case)
    return out


def quantity_text(d: dict | None) -> str:
    """A result quantity ``{"value", "unit"}`` as a reader writes it (``151.3 N·m``); n/a for none."""
    return "n/a" if d is None or d["value"] is None else f"{sig(d['value'])} {pretty_unit(d['unit'])}".rstrip()


def summary(results: dict) -> str:
    """The results as a short report for a terminal."""
    d, s1, s5 = results["duty"], results["continuous"], results["cyclic"]
    lines = [
        results["title"],
        "=" * len(results["title"]),
        f"Duty cycle: t_on = {quantity_text(d['t_on'])}, t_cycle = {quantity_text(d['t_cycle'])}, ED = {quantity_text(d['ED'])} -> mode {d['mode']} (E3)",
        f"S1{' (governs)' if s1['governs'] else ''}: n_2m = {quantity_text(s1['n2m'])}, T_2m = {quantity_text(s1['T2m'])}",
        f"S5{' (governs)' if s5['governs'] else ''}: Z_h = {quantity_text(s5['Zh'])}, f_s = {s5['fs']:g}, n_2max = {quantity_text(s5['n2max'])}"
        + (f", T_2max = {quantity_text(s5['T2max'])} ({s5['T2max_part']})" if "T2max" in s5 else ""),
    ]
    g = results.get("gearbox")
    if g:
        lines += ["", f"Gearbox candidates ({g['mode']} governs; catalog {g['catalog']}):"]
        for c in g["candidates"]:
            verdict = "PASS" if c["passes"] else "FAIL"
            lam = "" if c["inertia_ratio"] is None else f", inertia ratio {c['inertia_ratio']:.2f}"
            lines.append(f"  {verdict}  {c['part']}{' (illustrative)' if c['illustrative'] else ''}{lam}")
            for k in c["checks"]:
                util = "n/a" if k["utilization"] is None else f"{k['utilization']:.2f}"
                mark = "" if k["governs"] else "  (for information)"
                lines.append(
                    f"        {k['criterion']:<22} required {quantity_text(k['required']):>12}  rated {quantity_text(k['rated']):>12}  "
                    f"utilization {util:>5}  {'ok' if k['passes'] else 'FAIL'}{mark}"
                )
            for r in c["reasons"]:
                lines.append(f"        rejected: {r}")
        lines.append(f"Selected gearbox: {g['selected'] or 'none passes'}")
    for name, module in SECTIONS.items():
        if name in results:
            lines += ["", *importlib.import_module(module).summary_lines(results[name])]
    return "\n".join(lines)
