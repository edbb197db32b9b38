"""The calc report of a design case: what it holds, collected once and laid out in LaTeX.

:func:`build_report` reads and evaluates a case and collects what a reviewer reads, in the order
they read it (efficalc's order): the verdict and the chosen parts; the title block (the case file
and each catalog with its SHA-256, the build date, the package version, the commit:
:mod:`.provenance`); method and assumptions (the source's sections and the errata readings that
apply, ``errata.toml``); the inputs; each calculation as ``symbol = formula = substituted values =
result`` from the :class:`calc.core.formula.Formula` objects; the checks; the candidate tables; the
figures; the order lines. Each part is a :class:`Latex` block: the report notebook
(``reports/calc-report.ipynb``) displays it and nbconvert passes it unchanged into the PDF
(:mod:`calc.report.publish`).

Each section of a case has its renderer, in the module of the same name as the section's module
(:data:`RENDERERS`, in the sections' order; the shape in :class:`.common.Renderer`): what the
report, the design review's page, the summary of several cases and ``calc compare`` show of it. A
block of the report is its frame with each section's part in turn. The LaTeX helpers are in
:mod:`.latex`, the skeletons of the blocks in ``templates/``.

Text from a case file or a catalog goes through :func:`latex_escape`, so it prints as written. A
case that fails its checks, or cannot be evaluated at all, still gives a report: its verdict is
FAIL and it says why.
"""

from __future__ import annotations

import functools
import importlib
import os
from dataclasses import dataclass, field
from pathlib import Path

from ..sections.case import Case, read_case
from ..data.catalog import display_path, recording_files_read
from ..exchange import aasx_beside
from ..core.errors import CalcError
from ..sections import Results, Verdict, evaluate, places
from ..sections.ratios import search as ratio_search
from ..sections.gearbox import NAME as GEARBOX
from .common import ERRATA, INPUT_COLUMNS, rejected_in_full
from .latex import Latex, breakable, latex_escape, prose, q, render, table, util, verdict_mark
from .provenance import PACKAGE, build_date, git_commit, sha256

__all__ = ["RENDERERS", "Latex", "Report", "build_report", "latex_escape", "prose", "report_of"]


def _renderers() -> tuple:
    """The renderer of each module of :mod:`calc.sections` with a place in the outputs
    (:func:`calc.sections.places`), in their order: ``RENDERER`` of this package's module of the
    same name.
    """
    names = [m.__name__.rpartition(".")[2] for m in places()]
    return tuple(importlib.import_module(f"{__name__}.{name}").RENDERER for name in names)


#: The renderer of each section (and of the ratio search), in the order of the outputs.
RENDERERS = _renderers()

#: What every report assumes.
ASSUMPTIONS = (
    "The load cycle is given at the gearbox output: each segment's mean output speed and output torque, "
    "pauses by their duration.",
    "Ratings are the catalog's published figures (each row names its source); rows marked illustrative are not "
    "a maker's own figures and are never chosen without a look at the maker's data.",
    "The operating mode decides which checks govern the verdict; the checks of the other mode are reported "
    "for information only.",
)


def _parts(block: str, report) -> list:
    """Every section's part of a block (its renderer's method of that name), in the order of
    :data:`RENDERERS`.
    """
    return [x for r in RENDERERS for x in getattr(r, block)(report)]


@dataclass
class Report:
    """Everything a calc report holds, collected from one case file.

    Attributes
    ----------
    path : pathlib.Path
        The case file.
    title : str
        The case's title (the file's stem until the case is read).
    built : str
        The build date (empty for a report of a case already read, :func:`report_of`).
    commit : str
        The package's commit (:func:`.provenance.git_commit`; empty as ``built``).
    case : Case or None
        The case as evaluated (with a motor from a catalog, its ratings and inertia are the chosen
        motor's); None where it could not be read.
    evaluated : Results or None
        Its results; None where it could not be evaluated.
    ratios : RatioResult or None
        The case at every ratio of its gearbox catalog; None without a gearbox section.
    error : str or None
        Why the case could not be evaluated.
    files : list of tuple
        (label, path text, SHA-256) of the case file and each file its results rest on.
    """

    path: Path
    title: str
    built: str
    commit: str
    case: Case | None = None
    evaluated: Results | None = None
    ratios: object = None  # RatioResult: the case at every ratio of its gearbox catalog
    error: str | None = None  # why the case could not be evaluated
    files: list = field(default_factory=list)  # (label, path text, sha256)

    # -- the verdict -------------------------------------------------------------------------

    @property
    def chosen(self) -> list[tuple[str, str, str]]:
        """(what, part, detail) of each chosen part; part is None where none passes."""
        return _parts("chosen", self) if self.evaluated is not None else []

    @property
    def verdict(self) -> Verdict:
        """The case's one verdict (:mod:`calc.sections`); FAIL with the reason for a case that
        cannot be evaluated."""
        if self.error is not None:
            return Verdict(False, [f"The case cannot be evaluated: {self.error}"])
        return self.evaluated.verdict

    @property
    def reasons(self) -> list[str]:
        """Why the case does not pass, one plain sentence each (empty when it passes)."""
        return self.verdict.reasons

    @property
    def passes(self) -> bool:
        """Whether the verdict is PASS."""
        return self.verdict.passes is True

    def summary_line(self) -> str:
        """One line for a terminal: verdict, case, chosen parts or the first reason.

        Returns
        -------
        str
            ``PASS  cases/x.toml: gearbox NPT035-10, ...``, or the first two reasons where it fails.
        """
        if self.passes:
            what = ", ".join(f"{w.lower()} {p}" for w, p, _ in self.chosen)
        else:
            what = " ".join(self.reasons[:2])
        return f"{self.verdict.word}  {display_path(self.path)}: {what}"

    def relative(self, text: str, escape=latex_escape) -> str:
        """Text with the absolute path of the case file's folder (and of the folder above it, where
        a case names ``../data/...``) written as the case writes it, relative to its folder: a report
        never prints where on the building machine its files were.

        Parameters
        ----------
        text : str
            LaTeX or plain text.
        escape : callable, optional
            How the text writes a path: :func:`latex_escape` for LaTeX (the default), ``str`` for
            plain text.

        Returns
        -------
        str
            The text, the folders written relative.
        """
        folder = self.path.resolve().parent
        for base, shown in ((folder, ""), (folder.parent, "../")):
            text = text.replace(escape(f"{base}/"), shown)
        return text

    # -- the blocks, in the order of the report ------------------------------------------------

    def front_page(self) -> Latex:
        """Title, verdict with its reasons, chosen parts, title block and signature lines.

        Returns
        -------
        Latex
            The front page.
        """
        render_reason = latex_escape if self.error else prose  # an error message quotes the case file as written
        chosen = ""
        if self.chosen:
            rows = [[w, latex_escape(p) if p else r"\textcolor{failred}{none passes}", latex_escape(d)]
                    for w, p, d in self.chosen]
            # Small, under the table's own heading: the signature lines stay on the front page.
            chosen = table(r"@{}l l p{0.6\linewidth}@{}", ["Part", "Chosen", "Basis"], rows, small=True)
        # One row per file, its SHA-256 beside it: the signature lines stay on the front page.
        def digest(text: str) -> str:
            return rf"\texttt{{\tiny {text}}}"

        files = self.files or [("Case file", display_path(self.path), None)]
        rows = [[latex_escape(label), rf"\texttt{{\footnotesize {breakable(path)}}}",
                 digest(sha) if sha else "unreadable"]
                for label, path, sha in files]
        commit = rf"\texttt{{\footnotesize {latex_escape(self.commit)}}}"
        rows += [["Built", rf"\multicolumn{{2}}{{l}}{{{latex_escape(f'{self.built} by {PACKAGE}')}}}", None],
                 ["Commit", rf"\multicolumn{{2}}{{p{{0.7\linewidth}}}}{{{commit}}}", None]]
        rows = [[c for c in row if c is not None] for row in rows]
        return Latex(render(
            "front-page.tex.j2", title=self.title, case=display_path(self.path), word=self.verdict.word,
            passes=self.passes, governing=self._governing_lines(), chosen=chosen,
            reasons=[rf"\item {render_reason(r)}" for r in self.reasons],
            title_block=table(r"@{}l p{0.39\linewidth} l@{}", ["Item", "File", "SHA-256"], rows, small=True,
                              narrow=True),
        ))

    def _governing_lines(self) -> str:
        """The governing checks of each chosen part, and of each section's own checks (the motor's,
        the accuracy's requirements), one line each with its utilization, or why it is not made.
        """
        groups = []
        for g in self.evaluated.governing() if self.evaluated is not None else []:
            if g.part is not None and not g.chosen or not g.checks:
                continue
            lines = []
            for k in g.checks:
                crit = prose(k.criterion or k.name)
                if k.passes is None:
                    lines.append(rf"{crit}: {verdict_mark(None, k.not_made or 'no rating')}")
                else:
                    lines.append(rf"{crit}: {q(k.required_value)} against {q(k.rated_value)}, "
                                 rf"$u$ = {util(k.utilization)}")
            owner = latex_escape(g.section.capitalize() + (f" {g.part}" if g.part else ""))
            groups.append(rf"\par\textbf{{{owner}}}\nopagebreak\begin{{itemize}}"
                          r"\setlength{\itemsep}{0pt}\setlength{\parskip}{0pt}"
                          + "".join(rf"\item {x}" for x in lines) + r"\end{itemize}")
        # Compact, in two columns under each part's name: the signature lines stay on the front page.
        # No column break between a part's name and its first check (a list invites one where it begins).
        return (r" {\footnotesize ($u$: utilization, the required over the rated value)}"
                r"{\footnotesize\raggedright\setlength{\multicolsep}{2pt}\csname @beginparpenalty\endcsname=10000"
                r"\begin{multicols}{2}"
                + "".join(groups) + r"\end{multicols}}") if groups else ""

    def method(self) -> Latex:
        """The source's sections, the errata readings that apply, and the assumptions.

        Returns
        -------
        Latex
            The method block (empty where the case could not be read).
        """
        if self.case is None:
            return Latex("")
        applied = set(_parts("readings", self))
        rankings = [f"Ranking of the {name} candidates: {r.ranking}." for name, r in self._ranked()]
        return Latex(render(
            "method.tex.j2", sources=_parts("sources", self),
            readings=[(k, e["text"]) for k, e in ERRATA.items() if "section" not in e or k in applied],
            assumptions=[*ASSUMPTIONS, *rankings],
        ))

    def inputs(self) -> Latex:
        """The inputs as tables: symbol, value, unit, description (and where in the case file).

        Returns
        -------
        Latex
            The inputs block (empty where the case could not be read).
        """
        if self.case is None:
            return Latex("")
        out = [r"\section{Inputs}"]
        rows = _parts("input_rows", self)
        if rows:
            out.append(table(INPUT_COLUMNS, ["Symbol", "Value", "Unit", "Description", "Case key"], rows))
        return Latex("\n".join(out + _parts("inputs", self)))

    def calculations(self) -> Latex:
        """Every formula used, as ``symbol = formula = values = result`` with its reference.

        Returns
        -------
        Latex
            The calculations block (empty where the case could not be evaluated).
        """
        if self.evaluated is None:
            return Latex("")
        return Latex("\n".join([r"\section{Calculations}", *_parts("steps", self)]))

    def checks(self) -> Latex:
        """The checks of each chosen part (or the closest candidate) with required, rated,
        utilization and verdict.

        Returns
        -------
        Latex
            The checks block (empty where there is none).
        """
        out = _parts("checks", self) if self.evaluated is not None else []
        return Latex("\n".join([r"\section{Checks}", *out]) if out else "")

    def candidates(self) -> Latex:
        """Every candidate: its catalog ratings, and the utilization of each check.

        Returns
        -------
        Latex
            The candidates block (empty where there is none).
        """
        out = _parts("candidates", self) if self.evaluated is not None else []
        return Latex("\n".join([r"\section{Candidates}", *out]) if out else "")

    def section_results(self) -> Latex:
        """What the coupling and accuracy sections and the ratio search give besides the checks.

        Returns
        -------
        Latex
            The further results block (empty where there is none).
        """
        out = _parts("results", self) if self.evaluated is not None else []
        return Latex("\n".join([r"\section{Further results}", *out]) if out else "")

    def figures(self) -> list:
        """The figures: the load cycle, the shock factor, the utilizations, each section's.

        Returns
        -------
        list of tuple
            (figure, caption) pairs; the caption is LaTeX, for the output's ``caption`` metadata that
            our LaTeX template reads. Empty where the case could not be read.
        """
        return _parts("figures", self) if self.case is not None else []

    def figures_heading(self) -> Latex:
        """The heading of the figures, on a page of its own.

        Returns
        -------
        Latex
            ``\\clearpage\\section{Figures}`` (empty where the case could not be read).
        """
        return Latex(r"\clearpage\section{Figures}") if self.case is not None else Latex("")  # figures start a page

    def order_lines(self) -> Latex:
        """What to order: one line per chosen part.

        Returns
        -------
        Latex
            The order lines (empty where the case could not be evaluated).
        """
        if self.evaluated is None:
            return Latex("")
        return Latex(render("order.tex.j2", lines=_parts("order_lines", self)))

    def appendix(self) -> Latex:
        """Every rejected candidate with its reasons, where the candidates' pages show only the closest.

        Returns
        -------
        Latex
            The appendix (empty where no candidate was rejected).
        """
        out = [x for name, r in self._ranked() for x in rejected_in_full(name, r.ranked().candidates())]
        return Latex("\n".join([r"\clearpage\appendix\section{Rejected candidates}", *out]) if out else "")

    def _ranked(self) -> list:
        """(name, result) of each section that ranks a catalog (:meth:`calc.sections.protocol.Result.ranked`)."""
        sections = self.evaluated.sections if self.evaluated is not None else {}
        return [(name, r) for name, r in sections.items() if r.ranked() is not None]

    def blocks(self, figures=None) -> list[tuple[object, dict]]:
        """The whole report in a reviewer's order.

        The report notebook displays them; the PDF is built from them in this process
        (:mod:`calc.report.publish`), so both give the same content.

        Parameters
        ----------
        figures : callable, optional
            A function giving the (figure, caption) pairs of :meth:`figures` made elsewhere, called
            once the text is set (the PDF makes them meanwhile, as vector PDF); default
            :meth:`figures`.

        Returns
        -------
        list of tuple
            (what is shown, its display metadata) pairs: LaTeX blocks, and each figure with its
            caption.
        """
        text = (self.front_page, self.method, self.inputs, self.calculations, self.section_results, self.checks,
                self.candidates, self.figures_heading)
        out = [(Latex(self.relative(b())), {}) for b in text]
        out += [(figure, {"caption": self.relative(caption)}) for figure, caption in (figures or self.figures)()]
        return out + [(Latex(self.relative(b())), {}) for b in (self.order_lines, self.appendix)]


def report_path(p, folder: Path) -> str:
    """A file's path as a report shows it: :func:`display_path`, but a file outside the project
    relative to the case's ``folder``: the report names no folder of the machine it was built on.

    Parameters
    ----------
    p : str or pathlib.Path
        The file.
    folder : pathlib.Path
        The case file's folder.

    Returns
    -------
    str
        The path as shown.
    """
    text = display_path(p)
    return os.path.relpath(p, folder) if os.path.isabs(text) else text


def build_report(case_path) -> Report:
    """Read and evaluate a case and collect its report.

    Parameters
    ----------
    case_path : str or pathlib.Path
        The design-case TOML file.

    Returns
    -------
    Report
        Its report, with the digest of every file its results rest on; a case that cannot be read or
        evaluated gives a report whose verdict is FAIL with the reason (never an exception for bad
        input).
    """
    path = Path(case_path)
    report = Report(path=path, title=path.stem, built=build_date(), commit=git_commit())
    shown = functools.partial(report_path, folder=path.parent)

    if path.is_file():
        report.files.append(("Case file", shown(path), sha256(path)))
    if aasx_beside(path).is_file():  # the case's IDTA 02021 export, where one was written beside it
        report.files.append(("IDTA 02021 export", shown(aasx_beside(path)), sha256(aasx_beside(path))))
    with recording_files_read() as read:
        try:
            case = read_case(path)
        except CalcError as exc:
            report.error = str(exc)
            return report
        report = report_of(case, report)
    # Every other data file the results rest on (hub and factor tables, measurements), once each.
    listed = {p for _, p, _ in report.files}
    report.files += [(what, shown(p), digest) for p, (what, digest) in read.items() if shown(p) not in listed]
    return report


def report_of(case: Case, report: Report | None = None, ratios: bool = True) -> Report:
    """Evaluate a case already read (the design review passes changed copies) into a report.

    Parameters
    ----------
    case : Case
        The case, read.
    report : Report, optional
        The report to fill (a new one, without build date and commit, when not given).
    ratios : bool
        Whether to search every ratio of the gearbox catalog (:attr:`Report.ratios`, which only the
        PDF shows); the review's page, which shows the search where asked for and runs it then,
        leaves it out.

    Returns
    -------
    Report
        The report, with the case's results and the digest of each ranked catalog; with the reason
        where the case cannot be evaluated.
    """
    if report is None:
        report = Report(path=case.path, title=case.title, built="", commit="")
    report.case, report.title = case, case.title
    try:
        evaluated = evaluate(case)
        searched = ratio_search(evaluated.case, evaluated.every) if ratios and GEARBOX in evaluated.sections else None
    except CalcError as exc:
        report.error = str(exc)
        return report
    # The case as evaluated: with a motor from a catalog, its ratings and inertia are the chosen motor's.
    report.case, report.evaluated, report.ratios = evaluated.case, evaluated, searched
    for name, r in report._ranked():
        report.files += [(f"{name.capitalize()} catalog", report_path(path, case.folder), sha)
                         for path, sha in r.ranked().catalog.members]
    return report
