"""The summary of several design cases (a machine's axes): one row per case with its verdict, the
part chosen by each section whose renderer asks for a column (``SUMMARY_COLUMN``: the gearbox and
the coupling), the worst utilization of every governing check and where it is, and the file of
the case's own calc report; written as CSV and as a LaTeX page for the PDF.

A row is plain data (:func:`summary_row`), so the design review can list the same rows; the PDF
(:func:`summary_latex`) has a title block like a single report's, the table (it breaks across
pages with its header repeated) and the count of each verdict.
"""

from __future__ import annotations

import csv
import os
import re
from pathlib import Path

from ..core.checks import worst_governing
from ..data.catalog import display_path
from ..sections import Verdict
from . import RENDERERS
from .latex import Latex, breakable, latex_escape, prose, render, table, util
from .provenance import PACKAGE

#: The renderers of the sections whose chosen part a row names
#: (:attr:`calc.report.common.Renderer.SUMMARY_COLUMN`), in the order of the columns.
PART_COLUMNS = tuple(r for r in RENDERERS if r.SUMMARY_COLUMN is not None)
#: The columns of the CSV, units in brackets (a utilization is a fraction: 1 is the rating).
CSV_COLUMNS = ("case file", "title", "verdict", *(r.NAME for r in PART_COLUMNS), "worst utilization [1]", "worst check",
               "worst check in", "report", "reason")
#: What a row says where no part of a section passes.
NONE_PASSES = "none passes"
#: File names a relative link in the PDF carries as written (others are shown without a link).
_LINKABLE = re.compile(r"[A-Za-z0-9._+-]+\.pdf")


def worst_check(results) -> dict | None:
    """The worst governing check of the whole case (:func:`calc.core.checks.worst_governing` over
    the governing checks of each section of a :class:`calc.sections.Results`): of the first
    candidate of each section that ranks candidates (the chosen part, or the closest when none
    passes), and of each section's own checks (the motor's, the accuracy against its requirements).

    Parameters
    ----------
    results : calc.sections.Results
        The evaluated case.

    Returns
    -------
    dict or None
        ``{"utilization", "check", "section", "part", "passes"}``: the utilization [1], the criterion
        as the results write it (``T_2max <= T_2B``), the section, the part (None for a section's own
        checks) and the check's verdict; None when no governing check has a utilization.
    """
    worst = [(g, k) for g in results.governing() if (k := worst_governing(g.checks)) is not None]
    if not worst:
        return None
    g, k = max(worst, key=lambda w: w[1].utilization)
    return {"utilization": k.utilization, "check": k.criterion or k.name, "section": g.section, "part": g.part,
            "passes": k.passes}


def summary_row(report, pdf: Path | None) -> dict:
    """One case as plain data: ``case`` (the file as results show it), ``title``, ``verdict``
    (PASS, FAIL or NOT DECIDED) and ``passes`` (True, False or None), ``chosen`` (the part of each
    section of :data:`PART_COLUMNS` the case evaluates; None where none passes), ``worst`` (of
    :func:`worst_check`), ``report`` and ``report_path`` (the calc report's file name and path;
    None when it was not built), ``error`` (why the case cannot be evaluated, or None) and
    ``reason`` (the first reason of a verdict that is not PASS).

    Parameters
    ----------
    report : calc.report.Report
        The case's report.
    pdf : pathlib.Path or None
        Its PDF file; None where it was not built.

    Returns
    -------
    dict
        The row's fields above.
    """
    sections = report.evaluated.sections if report.evaluated is not None else {}
    verdict = report.verdict
    return {
        "case": display_path(report.path),
        "title": report.title,
        "verdict": verdict.word,
        "passes": verdict.passes,
        "chosen": {r.NAME: ranked.selected for r in PART_COLUMNS
                   if r.NAME in sections and (ranked := sections[r.NAME].ranked()) is not None},
        "worst": None if report.evaluated is None else worst_check(report.evaluated),
        "report": None if pdf is None else pdf.name,
        "report_path": None if pdf is None else str(pdf),
        "error": report.error,
        "reason": verdict.reasons[0] if verdict.reasons else None,
    }


def counts(rows: list[dict]) -> dict:
    """How many rows have each verdict, PASS, FAIL, NOT DECIDED (every word, zero counts too).

    Parameters
    ----------
    rows : list of dict
        The cases' rows (:func:`summary_row`).

    Returns
    -------
    dict
        Verdict word -> how many rows have it.

    Examples
    --------
    >>> counts([{"verdict": "PASS"}, {"verdict": "FAIL"}, {"verdict": "PASS"}])
    {'PASS': 2, 'FAIL': 1, 'NOT DECIDED': 0}
    """
    words = [Verdict(p).word for p in (True, False, None)]
    return {w: sum(r["verdict"] == w for r in rows) for w in words}


def counts_text(rows: list[dict]) -> str:
    """The count of each verdict in words.

    Parameters
    ----------
    rows : list of dict
        The cases' rows (:func:`summary_row`).

    Returns
    -------
    str
        ``2 PASS, 1 FAIL, 0 NOT DECIDED``.
    """
    return ", ".join(f"{n} {w}" for w, n in counts(rows).items())


def _chosen_text(row: dict, name: str) -> str:
    if name not in row["chosen"]:
        return ""
    return row["chosen"][name] or NONE_PASSES


def write_csv(rows: list[dict], path: Path) -> None:
    """The rows as CSV: a header of :data:`CSV_COLUMNS`, one line per case; the utilization a
    number, an empty cell where there is none.

    Parameters
    ----------
    rows : list of dict
        The cases' rows (:func:`summary_row`).
    path : pathlib.Path
        The CSV file to write (its folder is made where missing).

    Returns
    -------
    None
    """
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="", encoding="utf-8") as f:
        out = csv.writer(f)
        out.writerow(CSV_COLUMNS)
        for r in rows:
            w = r["worst"] or {}
            out.writerow([r["case"], r["title"], r["verdict"], *(_chosen_text(r, p.NAME) for p in PART_COLUMNS),
                          w.get("utilization", ""),
                          w.get("check", ""), " ".join(x for x in (w.get("section"), w.get("part")) if x),
                          r["report"] or "", r["reason"] or ""])


def _report_link(name: str | None) -> str:
    if name is None:
        return r"\textcolor{failred}{not built}"
    shown = rf"\texttt{{\footnotesize {breakable(name)}}}"
    return rf"\href{{{name}}}{{{shown}}}" if _LINKABLE.fullmatch(name) else shown


def _verdict_cell(row: dict) -> str:
    colour = {True: "passgreen", False: "failred", None: "infogrey"}[row["passes"]]
    words = " ".join(rf"\mbox{{{w}}}" for w in row["verdict"].split())  # NOT DECIDED: two lines, no hyphen
    return rf"\textcolor{{{colour}}}{{\textbf{{{words}}}}}"


def shown_path(path: str, folder: Path) -> str:
    """A path as the summary prints it: relative to the summary's folder where it lies outside
    the project (a summary never prints where on the building machine its files were).

    Parameters
    ----------
    path : str
        The path as the results show it: relative to the project, or absolute outside it.
    folder : pathlib.Path
        The folder the summary is written to.

    Returns
    -------
    str
        ``path`` itself where relative, else from ``folder``.

    Examples
    --------
    >>> shown_path("cases/a.toml", Path("/tmp/out")), shown_path("/tmp/cases/a.toml", Path("/tmp/out"))
    ('cases/a.toml', '../cases/a.toml')
    """
    return os.path.relpath(path, folder) if os.path.isabs(path) else path


def _case_cell(row: dict, folder: Path) -> str:
    out = rf"{latex_escape(row['title'])}\newline\texttt{{\footnotesize {breakable(shown_path(row['case'], folder))}}}"
    worst = row["worst"]
    # the reason, unless the worst check (failing) already says why
    if row["reason"] and (row["error"] or worst is None or worst["passes"] is not False):
        colour = "failred" if row["passes"] is False else "infogrey"
        text = row["reason"]
        if os.path.isabs(row["case"]):
            text = text.replace(row["case"], shown_path(row["case"], folder))
        reason = breakable(text, latex_escape if row["error"] else prose)  # an error quotes the case as written
        out += rf"\newline{{\footnotesize\color{{{colour}}} {reason}}}"
    return out


def _part_cell(row: dict, name: str) -> str:
    text = _chosen_text(row, name)
    if text == NONE_PASSES:
        return rf"\textcolor{{failred}}{{{text}}}"
    return latex_escape(text) if text else "–"


def _worst_cell(row: dict) -> str:
    w = row["worst"]
    if w is None:
        return "–"
    where = " ".join(latex_escape(x) for x in (w["section"], w["part"]) if x)
    check = prose(w["check"])
    return rf"{util(w['utilization'])}\newline{{\footnotesize {where}: {check}}}"


def summary_latex(rows: list[dict], files_read: list, built: str, commit: str, folder: Path) -> Latex:
    """The summary PDF's content: heading, the count of each verdict, the table of cases and the
    title block (each case file and catalog read, with its SHA-256; build date, package, commit).

    Parameters
    ----------
    rows : list of dict
        The cases' rows (:func:`summary_row`).
    files_read : list
        The files each row's report rests on (:attr:`calc.report.Report.files`): for each report,
        its ``(label, path, sha256)`` triples.
    built : str
        When the summary is built, as its title block writes it.
    commit : str
        The commit of the package it is built with.
    folder : pathlib.Path
        Where the summary is written (paths outside the project are shown from there).

    Returns
    -------
    calc.report.latex.Latex
        The LaTeX of the summary's page.
    """
    # Rows of several lines set apart.
    body = [[(r"\addlinespace[5pt]" if k else "") + _case_cell(r, folder), _verdict_cell(r),
             *(_part_cell(r, p.NAME) for p in PART_COLUMNS), _worst_cell(r), _report_link(r["report"])]
            for k, r in enumerate(rows)]
    parts = "".join(f"p{{{p.SUMMARY_COLUMN[1]}}} " for p in PART_COLUMNS)
    cases = table(
        rf"@{{}} p{{0.29\linewidth}} p{{0.1\linewidth}} {parts}p{{0.16\linewidth}} p{{0.12\linewidth}}@{{}}",
        ["Case", "Verdict", *(p.SUMMARY_COLUMN[0] for p in PART_COLUMNS), "Worst utilization", "Report"], body,
        small=True,
        note="Worst utilization: the highest required / rated of every governing check of the chosen parts (of the "
             "closest candidate where none passes) and of the requirements of the case; above 1.00 the check fails. "
             "Each report's file name links to it, in the folder of this summary.",
    )
    files = {}  # path text -> (label, sha256): each file once, in the order read
    for each in files_read:
        for label, path, digest in each:
            files.setdefault(path, (label, digest))
    block = []
    for path, (label, digest) in files.items():
        block += [[latex_escape(label), rf"\texttt{{{breakable(shown_path(path, folder))}}}"],
                  ["SHA-256", rf"\texttt{{\footnotesize {digest}}}"]]
    block += [["Built", latex_escape(built)], ["Package", latex_escape(PACKAGE)],
              ["Commit", rf"\texttt{{\footnotesize {latex_escape(commit)}}}"]]
    n = counts(rows)
    errors = sum(r["error"] is not None for r in rows)
    return Latex(render(
        "summary.tex.j2", n_cases=len(rows), counts=counts_text(rows),
        colour="failred" if n["FAIL"] else ("infogrey" if n["NOT DECIDED"] else "passgreen"),
        errors=errors, cases=cases, title_block=table(r"@{}l p{0.78\linewidth}@{}", ["Item", "Value"], block),
    ))
