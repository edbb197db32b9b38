"""What the review shows of an evaluated case, as one HTML text: the verdict with the chosen parts,
the governing checks, the duty values, the candidate tables and the accuracy of the chain.

Everything is written from the results as the JSON contract has them (every candidate), so the
panel shows what ``python -m calc evaluate --json`` and the report say. Symbols are typeset as in
the figures (``T_2B`` as T₂B with a subscript, ``<=`` as ≤), units as a reader writes them
(``N·m``), blanks where a value is not given; a table has no index column.
"""

from __future__ import annotations

import contextvars
import dataclasses
from html import escape

import numpy as np

from ..sections.case import Case
from ..data.catalog import display_path
from ..report import Report, report_of
from ..report.symbols import html as typeset
from ..core.checks import within_rating
from ..core.units import Q_, Value, sig
from .figures import ratio_search_svg

PASS_COLOR, FAIL_COLOR = "#1b7837", "#b2222a"
STYLE = f"""<style>
.dr {{ font-size: 13px; line-height: 1.35; color: #1a1a1a; }}
.dr h3 {{ font-size: 14px; margin: 12px 0 4px; }}
.dr .verdict {{ display: flex; align-items: baseline; gap: 12px; flex-wrap: wrap; margin-bottom: 4px; }}
.dr .word {{ font-size: 22px; font-weight: 700; color: #fff; padding: 1px 12px; border-radius: 4px; }}
.dr .pass {{ color: {PASS_COLOR}; font-weight: 600; }} .dr .fail {{ color: {FAIL_COLOR}; font-weight: 600; }}
.dr .open {{ color: #777; }}
.dr .word.pass {{ background: {PASS_COLOR}; color: #fff; }} .dr .word.fail {{ background: {FAIL_COLOR}; color: #fff; }}
.dr .word.open {{ background: #8a6d00; color: #fff; }}
.dr .parts {{ font-size: 15px; }} .dr ul.reasons {{ margin: 2px 0 4px 18px; padding: 0; color: {FAIL_COLOR}; }}
.dr table {{ border-collapse: collapse; margin: 2px 0 6px; }}
.dr th {{ text-align: left; font-weight: 600; border-bottom: 1px solid #999; padding: 2px 8px 2px 0; white-space: nowrap; }}
.dr td {{ padding: 2px 8px 2px 0; border-bottom: 1px solid #e4e4e4; vertical-align: top; white-space: nowrap; }}
.dr td.n {{ text-align: right; white-space: nowrap; font-variant-numeric: tabular-nums; }}
.dr td.why {{ color: #555; white-space: normal; }} .dr tr.chosen td {{ background: #eef6ee; }}
.dr .bar {{ display: inline-block; height: 8px; vertical-align: middle; margin-left: 4px; background: #ccc; width: 50px; }}
.dr .bar > span {{ display: block; height: 8px; }}
.dr details.notmade {{ display: inline-block; font-size: 13px; color: #6d4c00; }} .dr details.notmade summary {{ cursor: pointer; }}
.dr details.notmade ul {{ margin: 2px 0 4px 18px; padding: 0; color: #333; }}
.dr .refused {{ background: #fff0f0; border: 1px solid {FAIL_COLOR}; padding: 3px 6px; margin: 2px 0 6px; }}
.dr td.differs {{ background: #fff4d6; font-weight: 600; }}
.dr .values {{ color: #333; }} .dr .values b {{ font-weight: 600; }} .dr .note {{ color: #666; font-size: 12px; }}
</style>"""


def evaluated(case: Case) -> tuple[Report, list[str]]:
    """The case's report, and what had to be left out of it: when the changed inputs make one
    further section impossible to evaluate (the accuracy chain names a 10:1 gearbox and the ratio
    is now 8), the report of the rest, and that section's reason as one sentence, so the review
    still shows the gearbox and the other sections. The verdict with a section left out is FAIL."""
    r = report_of(case)
    if r.error is None:
        return r, []
    for name in case.sections:
        rest = report_of(dataclasses.replace(case, sections={k: v for k, v in case.sections.items() if k != name}))
        if rest.error is None:
            why = r.error.replace(str(case.path), display_path(case.path))  # the path as the results write it
            return rest, [f"The {name} section cannot be evaluated with these inputs: {why}"]
    return r, []


#: The unit system the results are shown in: "SI" as the results write them, or "inch-pound".
SYSTEM = contextvars.ContextVar("system", default="SI")
#: A result's SI unit and its inch-pound counterpart (the units a US maker's sheet writes).
INCH_POUND = {"N*m": "lbf*in", "N": "lbf", "mm": "in", "m": "in", "kg*cm**2": "lb*in**2", "kg*m**2": "lb*in**2", "kg": "lb",
              "N*m/arcmin": "lbf*in/arcmin", "N*m/rad": "lbf*in/rad", "m/s": "in/s", "mm/s": "in/s", "m/s**2": "in/s**2"}


def in_system(v: Value | None) -> Value | None:
    """A result value in the unit system shown (:data:`SYSTEM`).

    >>> token = SYSTEM.set("inch-pound")
    >>> shown = in_system(Value(6.779, "N*m"))
    >>> shown.unit, round(shown.value, 2)
    ('lbf*in', 60.0)
    >>> SYSTEM.reset(token)
    """
    if v is None or v.value is None or SYSTEM.get() == "SI" or v.unit not in INCH_POUND:
        return v
    unit = INCH_POUND[v.unit]
    return Value(float(Q_(v.value, v.unit).m_as(unit)), unit)


def _q(v: Value | None) -> str:
    """A result value as text, in the unit system shown; blank where not given."""
    return "" if v is None or v.value is None else escape(str(in_system(v)).replace(" 1/hour", " /h"))


def _verdict_cell(passes, not_made: str | None = None) -> str:
    """PASS or FAIL; a check that could not be made (``passes`` None) says why, in grey."""
    if passes is None:
        return f'<span class="open">not checked{": " + typeset(not_made) if not_made else ""}</span>'
    return '<span class="pass">PASS</span>' if passes else '<span class="fail">FAIL</span>'


def _utilization(u) -> str:
    """A utilization in per cent with a bar (red over 100 %); blank where there is none."""
    if u is None:
        return ""
    width = max(0.0, min(u, 1.0)) * 100
    color = PASS_COLOR if within_rating(u) else FAIL_COLOR
    return f'{100 * u:.0f} %<span class="bar"><span style="width:{width:.0f}%;background:{color}"></span></span>'


#: Under a table whose rows force their part (:func:`_table`'s ``force``).
FORCING = "on the served page, a click on a row forces that part"


def _table(header: list[str], rows: list[list[str]], numeric: set[int] = frozenset(), marked: int | None = None,
           force: tuple[str, list[str]] | None = None) -> str:
    """An HTML table; with ``force`` (a control's key and each row's part) a click on a row forces
    that part (the page's script sets the control, :mod:`calc.review.client`)."""
    head = "".join(f"<th>{h}</th>" for h in header)

    def forcing(k: int) -> str:
        if force is None:
            return ""
        key, parts = force
        return f' data-force="{escape(key)}" data-part="{escape(parts[k])}" title="click to force {escape(parts[k])}"'

    body = "".join(
        f'<tr{" class=chosen" if k == marked else ""}{forcing(k)}>'
        + "".join(f'<td class="{"n" if j in numeric else ("why" if h in ("reasons", "verdict") else "")}">{c}</td>' for j, (h, c) in enumerate(zip(header, row)))
        + "</tr>"
        for k, row in enumerate(rows)
    )
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _governing(results) -> str:
    """The governing checks of each chosen part (the closest candidate where none passes), the
    motor's and the accuracy requirements, one row each."""
    rows = []
    for g in results.governing():
        who = g.section + (f" {escape(g.part)}" if g.part else "") + ("" if g.chosen else " (closest)")
        rows += [[who, typeset(k.criterion or k.name), ("≥ " if k.at_least else "") + _q(k.required_value), _q(k.rated_value),
                  _utilization(k.utilization), _verdict_cell(k.passes, k.not_made)] for k in g.checks]
    if not rows:
        return ""
    return "<h3>Governing checks</h3>" + _table(["part", "check", "required", "rated", "utilization", "verdict"], rows, numeric={2, 3, 4})


def _duty(d) -> str:
    """The duty values (:class:`calc.sections.duty.DutyValues`) in one line: mode, ED, the S5 and S1 values."""
    parts = [f"<b>{escape(d.mode)}</b>", f"ED {_q(d.ED)}", f"cycle {_q(d.t_cycle)}",
             f"{typeset('Z_h')} {_q(d.Z_h)}", f"{typeset('f_s')} {sig(d.f_s)}", f"{typeset('n_2max')} {_q(d.n_2max)}",
             f"{typeset('T_2max')} {_q(d.T_2max)}" if d.T_2max is not None else "",
             f"{typeset('n_2m')} {_q(d.n_2m)}", f"{typeset('T_2m')} {_q(d.T_2m)}"]
    return '<div class="values">Duty: ' + " · ".join(p for p in parts if p) + "</div>"


def _motion(m, typed_by_hand: bool) -> str:
    """Where the load cycle comes from: the motion's peak values (a
    :class:`calc.sections.motion.MotionResult`, None without one), or that its segments were
    changed by hand (then the moves and mechanism no longer derive it)."""
    if typed_by_hand:
        return '<div class="values">Load cycle: the segments as changed here (the case derives them from its motion; reset to derive them again)</div>'
    if m is None:
        return ""
    parts = [f"{escape(m.mechanism or '')} from its {escape(m.source)}s".strip(), f"peak speed {_q(m.peak_speed)}",
             f"peak acceleration {_q(m.peak_acceleration)}", f"{typeset('J_L')} {_q(m.J_L)}" if m.J_L is not None else ""]
    return '<div class="values">Motion: ' + " · ".join(p for p in parts if p) + "</div>"


def _shown(sel, shown: int | None) -> tuple[list, str]:
    """The first ``shown`` candidates of a selection, best first (all for None; only those are
    made into records), and a note of how many are left out."""
    listed, total = sel.candidates(shown), len(sel.order)
    if len(listed) == total:
        return listed, ""
    return listed, f"<div class=note>{len(listed)} of {total} candidates shown; tick <i>all candidates</i> for the rest.</div>"


def _gearbox_table(g, shown: int | None) -> str:
    """The gearbox candidates (a :class:`calc.sections.gearbox.GearboxResult`), best first."""
    sel = g.selection
    listed, more = _shown(sel, shown)
    rows = [
        [str(k), escape(c.part), _verdict_cell(c.passes), _utilization(c.worst), _q(c.T_2max),
         "" if c.inertia_ratio is None else sig(c.inertia_ratio, 3), "illustrative" if c.illustrative else "",
         "<br>".join(typeset(x) for x in c.reasons)]
        for k, c in enumerate(listed, start=1)
    ]
    header = ["rank", "part", "verdict", "worst utilization", typeset("T_2max"), "inertia ratio λ", "data", "reasons"]
    return (f"<h3>Gearbox candidates</h3><div class=note>{typeset(g.ranking)}; {FORCING}</div>"
            + _table(header, rows, numeric={0, 3, 4, 5}, marked=0 if sel.selected else None, force=("gearbox.part", [c.part for c in listed]))
            + more)


def _coupling_table(s, shown: int | None) -> str:
    """The coupling candidates (a :class:`calc.sections.coupling.CouplingResult`), best first, and
    the drive train's modes."""
    def rated(c, name):
        return next((_q(k.rated_value) for k in c.checks if k.name == name), "")

    sel = s.selection
    listed, more = _shown(sel, shown)
    rows = [
        [str(k), escape(c.part), escape(c.type), _verdict_cell(c.passes), _q(c.required_torque), rated(c, "T_KN"),
         _q(c.f_e), _q(c.f_1), _utilization(c.worst), "<br>".join(typeset(x) for x in c.reasons)]
        for k, c in enumerate(listed, start=1)
    ]
    header = ["rank", "part", "type", "verdict", typeset("M_N·K_ϑ"), typeset("T_KN"), typeset("f_e"), typeset("f_1"), "worst utilization", "reasons"]
    notes = "".join(f"<div class=note>{typeset(n)}</div>" for n in s.notes)
    return (f"<h3>Coupling candidates</h3><div class=note>{typeset(s.ranking)}</div>"
            + _table(header, rows, numeric={0, 4, 5, 6, 7, 8}, marked=0 if sel.selected else None) + more + notes
            + _torsion_table(s.torsion))


def _motor_table(m, shown: int | None) -> str:
    """The catalog motors (a :class:`calc.sections.motor.MotorResult` with its selection), best first."""
    sel = m.selection
    listed, more = _shown(sel, shown)
    rows = [
        [str(k), escape(c.part), _verdict_cell(c.passes), _utilization(c.worst), _q(c.rated_torque), _q(c.rotor_inertia),
         "" if c.inertia_ratio is None else sig(c.inertia_ratio, 3), escape(c.form), "<br>".join(typeset(x) for x in c.reasons)]
        for k, c in enumerate(listed, start=1)
    ]
    header = ["rank", "part", "verdict", "worst utilization", typeset("M_N"), typeset("J_motor"), "inertia ratio λ", "peak characteristic", "reasons"]
    return (f"<h3>Motor candidates, through {escape(m.through)}</h3><div class=note>{typeset(m.ranking)}; {FORCING}</div>"
            + _table(header, rows, numeric={0, 3, 4, 5, 6}, marked=0 if sel.selected else None, force=("motor.part", [c.part for c in listed]))
            + more)


def _torsion_table(t) -> str:
    """The drive train as masses and springs with its natural frequencies (:class:`calc.sections.coupling.Torsion`)."""
    if t is None:
        return ""
    rows = [[escape(members), _q(J), escape(spring[0]) if spring else "", _q(spring[1]) if spring else ""]
            for (members, J), spring in zip(t.masses, [*t.springs, None])]
    frequencies = ", ".join(_q(f) for f in t.natural_frequencies)
    check = "".join(f"<div class=note>{typeset(c.criterion)}: {_q(c.rated_value)}, utilization {_utilization(c.utilization)}"
                    f"{'' if c.governs else ' (for information)'}</div>" for c in t.checks)
    missing = "" if t.complete else f"<div class=note>incomplete: the case does not give {escape('; '.join(t.missing))}</div>"
    return (f"<h3>Drive train with {escape(t.part)}, at {escape(t.shaft)}</h3>"
            + _table(["masses", "inertia", "spring to the next", "stiffness"], rows, numeric={1, 3})
            + f"<div class=note>natural frequencies {frequencies} (rigid-body mode left out)</div>" + check + missing)


def _accuracy_table(a) -> str:
    """The chain's accuracy (:class:`calc.sections.accuracy.AccuracyValues`)."""
    rows = [
        [typeset("C_total"), "total torsional stiffness at the output" + (" (<b>an upper bound</b>)" if a.unknown_chain else ""),
         ("≤ " if a.unknown_chain else "") + _q(a.C_total)],
        [typeset("phi_LM"), f"lost motion at the applied torque {_q(a.applied_torque)}" + (" (<b>a lower bound</b>)" if a.unknown_chain else ""),
         ("≥ " if a.unknown_chain else "") + _q(a.lost_motion)],
        ["Δ" + typeset("phi_P"), f"positioning accuracy ({typeset(a.positioning_rule)})"
         + (f"; <b>a lower bound</b>: unknown {typeset('; '.join(a.unknown))}" if a.unknown else ""),
         ("≥ " if a.unknown else "") + _q(a.positioning_accuracy)],
        ["", "repeatability" + (" (<b>not known</b>: a member's twist or backlash unknown)" if a.unknown_chain
                                else " (upper bound)" if a.repeatability_is_bound else ""), _q(a.repeatability)],
    ]
    return "<h3>Accuracy of the chain</h3>" + _table(["symbol", "quantity", "value"], rows, numeric={2})


def _ratio_block(found) -> str:
    """The ratio search (its JSON, :func:`calc.sections.ratios.search`), or why it cannot be made
    (a sentence): each ratio's best gearbox, whether it is feasible, λ and the motor's torques, the
    pick and why, and the bars of :func:`calc.review.figures.ratio_search_svg`."""
    if isinstance(found, str):
        return f"<h3>Ratio search</h3><div class=note>{typeset(found)}</div>"

    def value(v):
        return "" if v is None else _q(Value(v["value"], v["unit"]))

    pick = None if found["pick"] is None else found["pick"]["ratio"]
    rows = [
        [sig(r["ratio"]), escape(r["part"]), _verdict_cell(r["passes"]), _utilization(r["utilization"]),
         "" if r["inertia_ratio"] is None else sig(r["inertia_ratio"], 3), value(r["peak_torque_required"]),
         value(r["rms_torque_required"]), value(r["max_speed_required"]), "pick" if r["ratio"] == pick else ""]
        for r in found["ratios"]
    ]
    header = ["ratio i", "best gearbox", "feasible", "utilization", "inertia ratio λ", typeset("T_1peak"), typeset("T_1rms"), typeset("n_1max"), ""]
    marked = next((k for k, r in enumerate(found["ratios"]) if r["ratio"] == pick), None)
    notes = "".join(f"<div class=note>{typeset(n)}</div>" for n in found["notes"])
    return (f"<h3>Ratio search</h3><div class=note>{typeset(found['rule'])}</div><div><b>{typeset(found['reason'])}</b></div>"
            + _table(header, rows, numeric={0, 3, 4, 5, 6, 7}, marked=marked) + notes + ratio_search_svg(found))


def _not_made_html(results) -> str:
    """Beside the verdict: how many checks were not made, and (a click away) which and why."""
    missing = results.not_made() if results is not None else []
    if not missing:
        return ""
    items = "".join(f"<li>{typeset(x)}</li>" for x in missing)
    return f'<details class="notmade"><summary>{len(missing)} check{"s" if len(missing) > 1 else ""} not made</summary><ul>{items}</ul></details>'


def results_html(report: Report, left_out: list[str], report_link: str | None = None, typed_by_hand: bool = False,
                 shown: int | None = None, refused: list[str] = (), system: str = "SI", ratios=None) -> str:
    """The review of an evaluated case as one HTML text (see the module's docstring);
    ``report_link``, where given, is the address of the case's report, linked beside the verdict;
    ``typed_by_hand``: the case's derived load cycle was changed segment by segment; ``shown``:
    the candidates listed in each table, best first (all for None); ``refused``: the values typed
    and refused (the results are those of the values before them), each with why; ``system``:
    the unit system of the values shown, "SI" or "inch-pound" (:data:`INCH_POUND`); ``ratios``: the
    ratio search's JSON, or why it cannot be made, shown after the gearbox (None: not asked for)."""
    token = SYSTEM.set(system)
    try:
        return _results_html(report, left_out, report_link, typed_by_hand, shown, refused, ratios)
    finally:
        SYSTEM.reset(token)


def _results_html(report, left_out, report_link, typed_by_hand, shown, refused, ratios) -> str:
    word = "FAIL" if left_out else report.verdict.word
    passes = word == "PASS"
    cls = {"PASS": "pass", "FAIL": "fail"}.get(word, "open")  # NOT DECIDED: a check could not be made
    chosen = " · ".join(f"{escape(w)} <b>{escape(p)}</b>" if p else f"{escape(w)} <span class=fail>none passes</span>" for w, p, _ in report.chosen)
    link = f' <a href="{escape(report_link)}" target="_blank">calc report</a>' if report_link else ""
    out = [STYLE, '<div class="dr">', f'<div class="verdict"><span class="word {cls}">{word}</span><span class="parts">{chosen}</span>{link}'
           f"{_not_made_html(report.evaluated)}</div>"]
    if refused:
        out.append('<div class="refused"><b>Not applied</b> (the results are those of the values before): '
                   + "; ".join(typeset(x) for x in refused) + "</div>")
    reasons = [*left_out, *report.reasons]
    if reasons and not passes:
        out.append('<ul class="reasons">' + "".join(f"<li>{typeset(x)}</li>" for x in reasons) + "</ul>")
    evaluated = report.evaluated
    if evaluated is not None:
        out += [_governing(evaluated), _motion(evaluated.sections.get("motion"), typed_by_hand), _duty(evaluated["profile"].shown)]
        if "gearbox" in evaluated.sections:
            out.append(_gearbox_table(evaluated["gearbox"], shown))
        if ratios is not None:
            out.append(_ratio_block(ratios))
        if "coupling" in evaluated.sections:
            out.append(_coupling_table(evaluated["coupling"], shown))
        if "motor" in evaluated.sections and evaluated["motor"].selection is not None:
            out.append(_motor_table(evaluated["motor"], shown))
        if "accuracy" in evaluated.sections:
            out.append(_accuracy_table(evaluated["accuracy"].shown))
    out.append("</div>")
    return "".join(out)


def _section(r: Report, name: str):
    return r.evaluated.sections.get(name) if r.evaluated is not None else None


def _worst(r: Report, part: str) -> float | None:
    """The worst governing utilization of a design's ``part`` in percent; None where it has none
    (a motor the case types has no selection: its checks stand alone)."""
    s = _section(r, part)
    u = None if s is None or s.selection is None else s.selection.best.worst
    return None if u is None else 100 * u


def comparison_rows(variants: list[tuple[str, Report]], system: str = "SI") -> list[tuple[str, list[str]]]:
    """The side-by-side comparison of designs, ``(name, report)``: one row per quantity (verdict,
    chosen parts, the worst governing utilization of each, the checks not made, the duty and
    accuracy values), one column per design, as plain text in the unit system ``system``."""
    def chosen(r, name):
        s = _section(r, name)
        return "" if s is None or s.selection is None else s.selection.selected or "none passes"

    def worst(r, name):
        u = _worst(r, name)
        return "" if u is None else f"{u:.0f} %"

    def shown(r, name, field):
        s = _section(r, name)
        v = None if s is None else getattr(s.shown, field)
        return "" if v is None else str(in_system(v))

    def bound(r, field="unknown"):
        s = _section(r, "accuracy")
        return "≥ " if s is not None and getattr(s.shown, field) else ""

    rows = [
        ("verdict", lambda r: r.verdict.word),
        ("gearbox", lambda r: chosen(r, "gearbox")),
        ("gearbox worst utilization", lambda r: worst(r, "gearbox")),
        ("coupling", lambda r: chosen(r, "coupling")),
        ("coupling worst utilization", lambda r: worst(r, "coupling")),
        ("motor", lambda r: chosen(r, "motor")),
        ("motor worst utilization", lambda r: worst(r, "motor")),
        ("checks not made", lambda r: str(len(r.evaluated.not_made()) if r.evaluated is not None else 0)),
        ("mode", lambda r: "" if _section(r, "profile") is None else _section(r, "profile").shown.mode),
        ("ED", lambda r: shown(r, "profile", "ED")),
        ("T_2max", lambda r: shown(r, "profile", "T_2max")),
        ("T_2m", lambda r: shown(r, "profile", "T_2m")),
        ("positioning accuracy", lambda r: bound(r) + shown(r, "accuracy", "positioning_accuracy")),
        ("lost motion", lambda r: bound(r, "unknown_chain") + shown(r, "accuracy", "lost_motion")),
    ]
    token = SYSTEM.set(system)
    try:
        return [(name, [f(r) for _, r in variants]) for name, f in rows]
    finally:
        SYSTEM.reset(token)


def comparison_html(variants: list[tuple[str, Report]], system: str = "SI") -> str:
    """The variants kept in the review side by side (:func:`comparison_rows`), in the unit system
    ``system``; a value that differs from the first variant's is highlighted."""
    from .figures import comparison_svg

    rows = comparison_rows(variants, system)

    head = "".join(f"<th>{escape(n)}</th>" for n, _ in variants)
    body = "".join(
        f"<tr><td>{typeset(name)}</td>" + "".join(f'<td class="{"differs" if k and v != values[0] else ""}">{escape(v)}</td>' for k, v in enumerate(values)) + "</tr>"
        for name, values in rows
    )
    figure = comparison_svg([str(k) for k in range(1, len(variants) + 1)], worst_utilizations(variants))
    return (f'{STYLE}<div class="dr dr-variants"><h3>Variants compared</h3><table><thead><tr><th></th>{head}</tr></thead>'
            f"<tbody>{body}</tbody></table><div class=note>A value that differs from the first variant's is marked.</div>{figure}</div>")


#: The parts whose worst governing utilization the comparison figures draw.
COMPARED_PARTS = ("gearbox", "coupling", "motor")


def worst_utilizations(designs: list[tuple[str, Report]]) -> dict:
    """Each part's worst governing utilization per design, ``(name, report)``, in percent (the
    comparison's rows print them to the percent); None where a design has none."""
    return {part: [_worst(r, part) for _, r in designs] for part in COMPARED_PARTS}


def comparison_text(names: list[str], rows: list[tuple[str, list[str]]]) -> str:
    """:func:`comparison_rows` as a plain text table, a column per design; a value that differs
    from the first design's is marked ``*``."""
    cells = [["", *names]] + [[name, *(v + (" *" if k and v != values[0] else "") for k, v in enumerate(values))] for name, values in rows]
    widths = [max(len(r[j]) for r in cells) for j in range(len(cells[0]))]
    lines = ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in cells]
    return "\n".join([lines[0], "  ".join("-" * w for w in widths), *lines[1:], "* differs from the first design"])


def comparison_pdf(names: list[str], rows: list[tuple[str, list[str]]], worst: dict, path, legend: list[str] = ()) -> None:
    """:func:`comparison_rows` as a one-page PDF (A4 landscape): the table, a value that differs
    from the first design's shaded, and a comparison figure of the worst governing utilization of
    each design's gearbox, coupling and motor (``worst``, :func:`worst_utilizations`; matplotlib, no
    TeX needed). ``legend``: what each
    design is, where its name is short (the review's variants by number), printed under the title."""
    import textwrap

    from matplotlib.figure import Figure

    fig = Figure(figsize=(11.69, 8.27))
    table_ax, bars = fig.add_axes((0.03, 0.36, 0.94, 0.52 if legend else 0.58)), fig.add_axes((0.1, 0.06, 0.85, 0.22))
    table_ax.axis("off")
    fig.text(0.03, 0.965, "Designs compared (shaded: differs from the first design)", fontsize=11, va="top")
    if legend:
        fig.text(0.03, 0.935, "\n".join(textwrap.wrap("; ".join(legend), 190)[:4]), fontsize=7, va="top")
    cells = [[name.replace("_", " "), *values] for name, values in rows]
    shown = table_ax.table(cellText=cells, colLabels=["", *names], loc="upper left", cellLoc="left")
    shown.auto_set_font_size(False)
    shown.set_fontsize(8)
    for r, (_, values) in enumerate(rows, start=1):
        for k, v in enumerate(values[1:], start=2):
            if v != values[0]:
                shown[r, k].set_facecolor("#fff0c0")
    x = np.arange(len(names))
    width = 0.8 / len(COMPARED_PARTS)
    for k, (what, u) in enumerate(worst.items()):
        bars.bar(x + (k - (len(COMPARED_PARTS) - 1) / 2) * width, [0.0 if v is None else v for v in u], width=width * 0.95, label=what)
    bars.axhline(100, color="#b2222a", linewidth=1)
    bars.set_xticks(x, names, fontsize=8)
    bars.set_ylabel("worst governing utilization [%]", fontsize=8)
    bars.legend(fontsize=8, frameon=False)
    fig.savefig(path, format="pdf")


def compare_cases(paths: list[str], as_json: bool = False, pdf=None) -> str:
    """``python -m calc compare A.toml B.toml ... [--json] [--pdf FILE]``: the designs side by side,
    as the review's *Keep as variant* table has them (:func:`comparison_rows`), as text or as JSON
    (``{"designs": [file, ...], "rows": [{"name", "values": [...], "differs": [...]}]}``); with
    ``pdf``, also written there as a PDF (:func:`comparison_pdf`)."""
    import json
    from pathlib import Path

    from ..sections.case import read_case
    from ..core.errors import CalcError

    designs = [(Path(p).name, report_of(read_case(p))) for p in paths]
    for _, r in designs:
        if r.error is not None:
            raise CalcError(r.error)
    rows = comparison_rows(designs)
    names = [n for n, _ in designs]
    if pdf is not None:
        comparison_pdf(names, rows, worst_utilizations(designs), pdf)
    if as_json:
        return json.dumps({"designs": [str(p) for p in paths],
                           "rows": [{"name": name, "values": values, "differs": [k > 0 and v != values[0] for k, v in enumerate(values)]}
                                    for name, values in rows]}, indent=2, ensure_ascii=False)
    return comparison_text(names, rows)
