"""What the review shows of an evaluated case, as one HTML text: the verdict with the chosen parts,
the governing checks, then each section's part as its renderer writes it
(:meth:`calc.report.common.Renderer.page`: the duty values, the candidate tables, the accuracy
of the chain); and designs side by side, each section's rows as its renderer declares them.

Everything is written from the results as the JSON contract has them (every candidate), so the
panel shows what ``python -m calc evaluate --json`` and the report say. Values, tables and
symbols are written as :mod:`calc.report.page` writes them.
"""

from __future__ import annotations

import dataclasses
from html import escape
from pathlib import Path

import numpy as np

from ..sections.case import Case
from ..data.catalog import display_path
from ..report import RENDERERS, Report, report_of
from ..report.page import FAIL_COLOR, PASS_COLOR, SYSTEM, View, table, utilization, value, verdict_cell
from ..report.symbols import html as typeset

STYLE = f"""<style>
.dr {{ font-size: 13px; line-height: 1.35; color: #1a1a1a; }}
.dr h3 {{ font-size: 14px; margin: 12px 0 4px; }}
.dr .decides {{ font-size: 13px; margin: 0 0 6px; }}
.dr .verdict {{ display: flex; align-items: baseline; gap: 12px; flex-wrap: wrap; margin-bottom: 4px; }}
.dr .word {{ font-size: 22px; font-weight: 700; color: #fff; padding: 1px 12px; border-radius: 4px; }}
.dr .pass {{ color: {PASS_COLOR}; font-weight: 600; }} .dr .fail {{ color: {FAIL_COLOR}; font-weight: 600; }}
.dr .open {{ color: #777; }}
.dr .word.pass {{ background: {PASS_COLOR}; color: #fff; }} .dr .word.fail {{ background: {FAIL_COLOR}; color: #fff; }}
.dr .word.open {{ background: #8a6d00; color: #fff; }}
.dr .parts {{ font-size: 15px; }} .dr ul.reasons {{ margin: 2px 0 4px 18px; padding: 0; color: {FAIL_COLOR}; }}
.dr table {{ border-collapse: collapse; margin: 2px 0 6px; }}
.dr th {{ text-align: left; font-weight: 600; border-bottom: 1px solid #999; padding: 2px 8px 2px 0;
  white-space: nowrap; }}
.dr td {{ padding: 2px 8px 2px 0; border-bottom: 1px solid #e4e4e4; vertical-align: top; white-space: nowrap; }}
.dr td.n {{ text-align: right; white-space: nowrap; font-variant-numeric: tabular-nums; }}
.dr td.why {{ color: #555; white-space: normal; }} .dr tr.chosen td {{ background: #eef6ee; }}
.dr .bar {{ display: inline-block; height: 8px; vertical-align: middle; margin-left: 4px; background: #ccc;
  width: 50px; }}
.dr .bar > span {{ display: block; height: 8px; }}
.dr details.notmade {{ display: inline-block; font-size: 13px; color: #6d4c00; }}
.dr details.notmade summary {{ cursor: pointer; }}
.dr details.notmade ul {{ margin: 2px 0 4px 18px; padding: 0; color: #333; }}
.dr .refused {{ background: #fff0f0; border: 1px solid {FAIL_COLOR}; padding: 3px 6px; margin: 2px 0 6px; }}
.dr td.differs {{ background: #fff4d6; font-weight: 600; }}
.dr .values {{ color: #333; }} .dr .values b {{ font-weight: 600; }} .dr .note {{ color: #666; font-size: 12px; }}
.dr .note, .dr .checked-at {{ white-space: normal; overflow-wrap: anywhere; }}
/* the variants' names wrap in their column heads, so that every variant's column is on the screen */
.dr.dr-variants table {{ width: 100%; }}
.dr.dr-variants th {{ white-space: normal; overflow-wrap: anywhere; min-width: 6em; vertical-align: bottom; }}
.dr.dr-variants td:first-child {{ white-space: normal; min-width: 7em; }}
</style>"""


def evaluated(case: Case) -> tuple[Report, list[str]]:
    """The case's report, and what had to be left out of it: when the changed inputs make one
    further section impossible to evaluate (the accuracy chain names a 10:1 gearbox and the ratio
    is now 8), the report of the rest, and that section's reason as one sentence, so the review
    still shows the gearbox and the other sections. The verdict with a section left out is FAIL.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case with the review's inputs.

    Returns
    -------
    tuple
        The report (:class:`calc.report.Report`) and the sentences of what was left out (none where
        the whole case is evaluated, or where leaving out one section does not help: the report's
        error says why). Without the search of every ratio (:attr:`calc.report.Report.ratios`, the PDF's):
        the page runs it where asked for.
    """
    r = report_of(case, ratios=False)
    if r.error is None:
        return r, []
    for name in case.sections:
        rest = report_of(dataclasses.replace(case, sections={k: v for k, v in case.sections.items() if k != name}),
                         ratios=False)
        if rest.error is None:
            why = r.error.replace(str(case.path), display_path(case.path))  # the path as the results write it
            return rest, [f"The {name} section cannot be evaluated with these inputs: {why}"]
    return r, []


def _governing(results) -> str:
    """The governing checks of each chosen part (the closest candidate where none passes), the
    motor's and the accuracy requirements, one row each."""
    rows = []
    for g in results.governing():
        who = g.section + (f" {escape(g.part)}" if g.part else "") + ("" if g.chosen else " (closest)")
        rows += [[who, typeset(k.criterion or k.name), ("≥ " if k.at_least else "") + value(k.required_value),
                  value(k.rated_value), utilization(k.utilization), verdict_cell(k.passes, k.not_made)]
                 for k in g.checks]
    if not rows:
        return ""
    header = ["part", "check", "required", "rated", "utilization", "verdict"]
    return "<h3>Governing checks</h3>" + table(header, rows, numeric={2, 3, 4})


def _deciding_html(results) -> str:
    """Under the verdict, in words: what decides the design, the most utilized governing check of each part
    (:meth:`calc.sections.evaluation.Results.deciding`)."""
    parts = []
    for g, k in results.deciding() if results is not None else []:
        who = g.section + (f" {escape(g.part)}" if g.part else "") + ("" if g.chosen else " (closest)")
        parts.append(f"{who} by {typeset(k.criterion or k.name)} at {100 * k.utilization:.0f} %")
    return f'<div class="decides">What decides the design: {"; ".join(parts)}.</div>' if parts else ""


def _not_made_html(results) -> str:
    """Beside the verdict: how many checks were not made, and (a click away) which and why."""
    missing = results.not_made() if results is not None else []
    if not missing:
        return ""
    items = "".join(f"<li>{typeset(x)}</li>" for x in missing)
    checks = f'{len(missing)} check{"s" if len(missing) > 1 else ""} not made'
    return f'<details class="notmade"><summary>{checks}</summary><ul>{items}</ul></details>'


def results_html(report: Report, left_out: list[str], report_link: str | None = None, typed_by_hand: bool = False,
                 shown: int | None = None, refused: list[str] = (), system: str = "SI", ratios=None) -> str:
    """The review of an evaluated case as one HTML text (see the module's docstring).

    Parameters
    ----------
    report : calc.report.Report
        The case's report (:func:`evaluated`).
    left_out : list of str
        What had to be left out of it, one sentence each: the verdict is then FAIL.
    report_link : str, optional
        The address of the case's report, linked beside the verdict.
    typed_by_hand : bool
        Whether the case's derived load cycle was changed segment by segment.
    shown : int, optional
        The candidates listed in each table, best first; all for None.
    refused : list of str
        The values typed and refused (the results are those of the values before them), each with why.
    system : str
        The unit system of the values shown, "SI" or "inch-pound" (:data:`calc.report.page.INCH_POUND`).
    ratios : dict or str, optional
        The ratio search's JSON, or why it cannot be made, shown after the gearbox; None: not asked for.

    Returns
    -------
    str
        HTML: the page's style, the verdict with the chosen parts, the governing checks and each
        section's part.
    """
    token = SYSTEM.set(system)
    try:
        return _results_html(report, left_out, report_link, typed_by_hand, shown, refused, ratios)
    finally:
        SYSTEM.reset(token)


def _results_html(report, left_out, report_link, typed_by_hand, shown, refused, ratios) -> str:
    word = "FAIL" if left_out else report.verdict.word
    passes = word == "PASS"
    cls = {"PASS": "pass", "FAIL": "fail"}.get(word, "open")  # NOT DECIDED: a check could not be made
    chosen = " · ".join(f"{escape(w)} <b>{escape(p)}</b>" if p else f"{escape(w)} <span class=fail>none passes</span>"
                        for w, p, _ in report.chosen)
    link = f' <a href="{escape(report_link)}" target="_blank">calc report</a>' if report_link else ""
    out = [STYLE, '<div class="dr">',
           f'<div class="verdict"><span class="word {cls}">{word}</span><span class="parts">{chosen}</span>{link}'
           f"{_not_made_html(report.evaluated)}</div>", _deciding_html(report.evaluated)]
    if refused:
        out.append('<div class="refused"><b>Not applied</b> (the results are those of the values before): '
                   + "; ".join(typeset(x) for x in refused) + "</div>")
    reasons = [*left_out, *report.reasons]
    if reasons and not passes:
        out.append('<ul class="reasons">' + "".join(f"<li>{typeset(x)}</li>" for x in reasons) + "</ul>")
    evaluated = report.evaluated
    if evaluated is not None:
        view = View(shown, ratios, typed_by_hand)
        out += [_governing(evaluated), *(r.page(evaluated.sections.get(r.NAME), view) for r in RENDERERS)]
    out.append("</div>")
    return "".join(out)


def _ranked(r: Report, name: str):
    """The catalog a design's section ``name`` ranks (:meth:`calc.sections.protocol.Result.ranked`);
    None where the design has no such section, or the section ranks none (a motor the case types)."""
    s = r.evaluated.sections.get(name) if r.evaluated is not None else None
    return None if s is None else s.ranked()


def _worst(r: Report, name: str) -> float | None:
    """The worst governing utilization of the part a design's section ``name`` chose, in percent;
    None where it has none."""
    sel = _ranked(r, name)
    u = None if sel is None else sel.best.worst
    return None if u is None else 100 * u


#: The renderers of the sections whose chosen part and worst utilization the comparison of
#: designs names (:attr:`calc.report.common.Renderer.COMPARED_PART`), in their order.
COMPARED = tuple(r for r in RENDERERS if r.COMPARED_PART)


def comparison_rows(variants: list[tuple[str, Report]], system: str = "SI") -> list[tuple[str, list[str]]]:
    """The side-by-side comparison of designs: one row per quantity (verdict, the part each
    section of :data:`COMPARED` chose and its worst governing utilization, the checks not made,
    then the rows each section's renderer declares: the duty and accuracy values), one column per
    design, as plain text.

    Parameters
    ----------
    variants : list of tuple
        ``(name, calc.report.Report)`` of each design.
    system : str
        The unit system of the values, "SI" or "inch-pound" (:data:`calc.report.page.INCH_POUND`).

    Returns
    -------
    list of tuple
        ``(row name, [text of each design])``.
    """
    def chosen(r, name):
        sel = _ranked(r, name)
        return "" if sel is None else sel.selected or "none passes"

    def worst(r, name):
        u = _worst(r, name)
        return "" if u is None else f"{u:.0f} %"

    def of(name, text):
        return lambda r: text(r.evaluated.sections.get(name) if r.evaluated is not None else None)

    rows = [("verdict", lambda r: r.verdict.word)]
    for p in COMPARED:
        rows += [(p.NAME, lambda r, n=p.NAME: chosen(r, n)),
                 (f"{p.NAME} worst utilization", lambda r, n=p.NAME: worst(r, n))]
    rows.append(("checks not made", lambda r: str(len(r.evaluated.not_made()) if r.evaluated is not None else 0)))
    rows += [(name, of(p.NAME, text)) for p in RENDERERS for name, text in p.compared()]
    token = SYSTEM.set(system)
    try:
        return [(name, [f(r) for _, r in variants]) for name, f in rows]
    finally:
        SYSTEM.reset(token)


def comparison_html(variants: list[tuple[str, Report]], system: str = "SI") -> str:
    """The variants kept in the review side by side (:func:`comparison_rows`); a value that differs
    from the first variant's is highlighted.

    Parameters
    ----------
    variants : list of tuple
        ``(name, calc.report.Report)`` of each variant.
    system : str
        The unit system of the values, "SI" or "inch-pound" (:data:`calc.report.page.INCH_POUND`).

    Returns
    -------
    str
        HTML: the page's style, the table and the figure of the worst utilizations.
    """
    from .figures import comparison_svg

    rows = comparison_rows(variants, system)

    head = "".join(f"<th>{escape(n)}</th>" for n, _ in variants)
    body = "".join(
        f"<tr><td>{typeset(name)}</td>"
        + "".join(f'<td class="{"differs" if k and v != values[0] else ""}">{escape(v)}</td>'
                  for k, v in enumerate(values)) + "</tr>"
        for name, values in rows
    )
    figure = comparison_svg([str(k) for k in range(1, len(variants) + 1)], worst_utilizations(variants))
    return (f'{STYLE}<div class="dr dr-variants"><h3>Variants compared</h3>'
            f"<table><thead><tr><th></th>{head}</tr></thead><tbody>{body}</tbody></table>"
            f"<div class=note>A value that differs from the first variant's is marked.</div>{figure}</div>")


def worst_utilizations(designs: list[tuple[str, Report]]) -> dict:
    """The worst governing utilization of the part each section of :data:`COMPARED` chose, per
    design.

    Parameters
    ----------
    designs : list of tuple
        ``(name, calc.report.Report)`` of each design.

    Returns
    -------
    dict
        Section name -> each design's utilization [%] (the comparison's rows print them to the
        percent); None where a design has none.
    """
    return {p.NAME: [_worst(r, p.NAME) for _, r in designs] for p in COMPARED}


def comparison_text(names: list[str], rows: list[tuple[str, list[str]]]) -> str:
    """:func:`comparison_rows` as a plain text table, a column per design; a value that differs
    from the first design's is marked ``*``.

    Parameters
    ----------
    names : list of str
        The designs' names, a column each.
    rows : list of tuple
        ``(row name, [text of each design])`` (:func:`comparison_rows`).

    Returns
    -------
    str
        The table, its header ruled, with the mark's key last.

    Examples
    --------
    >>> print(comparison_text(["a", "b"], [("verdict", ["PASS", "FAIL"])]))
             a     b
    -------  ----  ------
    verdict  PASS  FAIL *
    * differs from the first design
    """
    cells = [["", *names]] + [[name, *(v + (" *" if k and v != values[0] else "") for k, v in enumerate(values))]
                              for name, values in rows]
    widths = [max(len(r[j]) for r in cells) for j in range(len(cells[0]))]
    lines = ["  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in cells]
    return "\n".join([lines[0], "  ".join("-" * w for w in widths), *lines[1:], "* differs from the first design"])


def comparison_pdf(names: list[str], rows: list[tuple[str, list[str]]], worst: dict, path,
                   legend: list[str] = (), files: list = ()) -> None:
    """:func:`comparison_rows` as a one-page PDF (A4 landscape): the table, a value that differs
    from the first design's shaded, and a comparison figure of the worst governing utilization of
    each design's gearbox, coupling and motor (matplotlib, no TeX needed).

    Parameters
    ----------
    names : list of str
        The designs' names, a column each.
    rows : list of tuple
        ``(row name, [text of each design])`` (:func:`comparison_rows`).
    worst : dict
        Section name -> each design's worst governing utilization [%], None where it has none
        (:func:`worst_utilizations`).
    path : str or pathlib.Path or file
        Where to write the PDF.
    legend : list of str
        What each design is, where its name is short (the review's variants by number), printed
        under the title.
    files : list of pathlib.Path
        The case files the designs were read from: the title block names each with its SHA-256,
        beside the date, the package's version and commit (:mod:`calc.report.provenance`).

    Returns
    -------
    None
    """
    import textwrap

    from matplotlib.figure import Figure

    from ..core.glossary import SYMBOLS, math
    from ..report.provenance import PACKAGE, build_date, git_commit, sha256

    fig = Figure(figsize=(11.69, 8.27))
    table_ax, bars = fig.add_axes((0.03, 0.36, 0.94, 0.50 if legend else 0.54)), fig.add_axes((0.1, 0.06, 0.85, 0.22))
    table_ax.axis("off")
    fig.text(0.03, 0.965, "Designs compared (shaded: differs from the first design)", fontsize=11, va="top")
    read = "; ".join(f"{Path(f).name} sha256 {sha256(f)[:16]}" for f in dict.fromkeys(files) if Path(f).is_file())
    block = f"{build_date()} · {PACKAGE} · commit {git_commit()}" + (f" · {read}" if read else "")
    fig.text(0.03, 0.94, "\n".join(textwrap.wrap(block, 200)[:2]), fontsize=6.5, va="top", color="#333")
    if legend:
        fig.text(0.03, 0.905, "\n".join(textwrap.wrap("; ".join(legend), 190)[:4]), fontsize=7, va="top")
    cells = [[math(name) if name in SYMBOLS else name, *values] for name, values in rows]
    shown = table_ax.table(cellText=cells, colLabels=["", *names], loc="upper left", cellLoc="left")
    shown.auto_set_font_size(False)
    shown.set_fontsize(8)
    for r, (_, values) in enumerate(rows, start=1):
        for k, v in enumerate(values[1:], start=2):
            if v != values[0]:
                shown[r, k].set_facecolor("#fff0c0")
    x = np.arange(len(names))
    width = 0.8 / len(worst)
    for k, (what, u) in enumerate(worst.items()):
        bars.bar(x + (k - (len(worst) - 1) / 2) * width, [0.0 if v is None else v for v in u], width=width * 0.95,
                 label=what)
    bars.axhline(100, color="#b2222a", linewidth=1)
    bars.set_xticks(x, names, fontsize=8)
    bars.set_ylabel("worst governing utilization [%]", fontsize=8)
    bars.legend(fontsize=8, frameon=False)
    fig.savefig(path, format="pdf")


def compare_cases(paths: list[str], as_json: bool = False, pdf=None) -> str:
    """``python -m calc compare A.toml B.toml ... [--json] [--pdf FILE]``: the designs side by side,
    as the review's *Keep as variant* table has them (:func:`comparison_rows`).

    Parameters
    ----------
    paths : list of str
        The case files, a design each.
    as_json : bool
        JSON instead of text.
    pdf : str or pathlib.Path, optional
        Where to write the comparison as a PDF as well (:func:`comparison_pdf`); None: no PDF.

    Returns
    -------
    str
        The text table (:func:`comparison_text`), or the JSON
        ``{"designs": [file, ...], "rows": [{"name", "values": [...], "differs": [...]}]}``.

    Raises
    ------
    calc.core.errors.CalcError
        A case that cannot be evaluated, with its report's error; a ``pdf`` that exists.
    """
    import json

    from ..sections.case import read_case
    from ..core.errors import CalcError

    if pdf is not None and Path(pdf).exists():
        raise CalcError(f"--pdf {pdf}: the file exists; name a new one (a comparison is never written over a file)")
    designs = [(Path(p).name, report_of(read_case(p))) for p in paths]
    for _, r in designs:
        if r.error is not None:
            raise CalcError(r.error)
    rows = comparison_rows(designs)
    names = [n for n, _ in designs]
    if pdf is not None:
        comparison_pdf(names, rows, worst_utilizations(designs), pdf, files=[Path(p) for p in paths])
    if as_json:
        return json.dumps({"designs": [str(p) for p in paths],
                           "rows": [{"name": name, "values": values,
                                     "differs": [k > 0 and v != values[0] for k, v in enumerate(values)]}
                                    for name, values in rows]}, indent=2, ensure_ascii=False)
    return comparison_text(names, rows)
