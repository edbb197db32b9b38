"""What the sections' renderers share.

Every section has one renderer, a :class:`Renderer` in the module of this package named as the
section's module of :mod:`calc.sections` (``RENDERER``): what the calc report, the design review's
page, the summary of several cases and ``calc compare`` show of the section. The report's
blocks are its methods of the :class:`calc.report.Report` (``sources`` and ``readings``
(method), ``input_rows`` (rows of the inputs table) and ``inputs`` (tables after it), ``steps``
(calculations), ``results``, ``checks``, ``candidates``, ``figures`` ((figure, caption) pairs),
``chosen`` ((what, part, detail) rows) and ``order_lines``), the page's its :meth:`Renderer.page`,
and the summary's and the comparison's what it declares. Each has a default that shows nothing.
The sections that read a table of their own (coupling, accuracy) write their method, checks and
inputs the same way (:class:`TableRenderer`). An input row is written from its key's
declaration (:func:`input_row`). The JSON and the text summary are the section's result
record's (:class:`calc.sections.protocol.Result`).
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import ClassVar

from ..domain.gearbox import inertia_ratio
from ..sections import declared
from ..core.units import pretty_unit, sig
from . import symbols
from .latex import breakable, itemize, latex_escape, listed, prose, q, table, util, value_unit, verdict_mark

_METHOD = tomllib.loads((Path(__file__).parent / "errata.toml").read_text(encoding="utf-8"))
#: The sections of the source document each section of a case is computed from.
SOURCE_SECTIONS: dict = _METHOD["sources"]
#: The errata readings by key (E1, ...), each with its ``text`` and the ``section`` it applies to
#: (none: every case), in the order of ``errata.md``.
ERRATA: dict = _METHOD["errata"]


def sources(name: str) -> list[str]:
    """The source's sections a described section is computed from.

    Parameters
    ----------
    name : str
        The section's name (``"coupling"``).

    Returns
    -------
    list of str
        The sections of the source document (``errata.toml``'s ``sources``), empty for none.
    """
    return list(SOURCE_SECTIONS.get(name, ()))


def readings(name: str) -> set[str]:
    """The keys of the errata readings of a section.

    Parameters
    ----------
    name : str
        The section's name.

    Returns
    -------
    set of str
        The readings' keys (``E8``) whose ``section`` is the section.
    """
    return {k for k, e in ERRATA.items() if e.get("section") == name}


#: The columns of an inputs table: symbol, value, unit, description, case key (which may break after a dot
#: or underscore).
INPUT_COLUMNS = r"@{}l r l p{0.36\linewidth} p{0.27\linewidth}@{}"


def case_key(key: str) -> str:
    """A case key in an inputs table: code, breakable.

    Parameters
    ----------
    key : str
        The dotted case key (``coupling.shaft_1``).

    Returns
    -------
    str
        LaTeX.
    """
    return rf"\texttt{{\footnotesize {breakable(key)}}}"


def symbol_latex(name: str) -> str:
    """A symbol's LaTeX by its name in code (:func:`calc.core.glossary.latex`).

    Parameters
    ----------
    name : str
        The symbol's name in code (``T_2max``), or empty for none.

    Returns
    -------
    str
        Its LaTeX; empty for none.
    """
    return symbols.symbol_latex(name) if name else ""


def input_row(path: str, value, derived: bool = False) -> list[str]:
    """A row of the inputs table as the key at ``path`` is declared (:func:`calc.sections.declared`).

    Parameters
    ----------
    path : str
        The dotted case key.
    value : pint.Quantity [the declared unit] or str or list
        A quantity (shown in the unit the declaration shows), or a text as written.
    derived : bool, optional
        The package took the value from the rest of the case (the key is marked).

    Returns
    -------
    list of str
        Symbol, value, unit, description, case key (LaTeX).
    """
    key = declared(path)
    latex = symbol_latex(key.symbol)
    if hasattr(value, "m_as"):
        shown, unit = sig(value.m_as(key.unit)), latex_escape(pretty_unit(key.unit)) or "–"
    else:
        shown, unit = value_unit(listed(value) if isinstance(value, list) else value)
    where = case_key(path) + (r"\textsuperscript{\dag}" if derived else "")
    return [f"${latex}$" if latex else "–", shown, unit, prose(key.description), where]


def result_of(name: str, report):
    """A section's result (:mod:`calc.sections`).

    Parameters
    ----------
    name : str
        The section's name, its key in the results.
    report : calc.report.Report
        The report being built.

    Returns
    -------
    calc.sections.protocol.Result or None
        None where the case has none or cannot be evaluated.
    """
    return report.evaluated.sections.get(name) if report.evaluated is not None else None


def block_doc(summary: str, returns: str, description: str = ""):
    """The numpydoc docstring of a block method of :class:`Renderer` or of a section's renderer: its
    summary, the report it takes and what it returns (every block takes the same report).

    Parameters
    ----------
    summary : str
        What the section gives to the block.
    returns : str
        The type of the block's part.
    description : str, optional
        What the part holds, said under its type.

    Returns
    -------
    callable
        A decorator that sets the method's docstring.
    """
    said = f"    {description}\n" if description else ""

    def document(method):
        method.__doc__ = (f"{summary}\n\nParameters\n----------\nreport : calc.report.Report\n"
                          "    The report being built (its case, and its results where the case could be\n"
                          f"    evaluated).\n\nReturns\n-------\n{returns}\n{said}")
        return method

    return document


def page_doc(summary: str, name: str, kind: str):
    """The numpydoc docstring of a section renderer's part of the review's page (:meth:`Renderer.page`).

    Parameters
    ----------
    summary : str
        What the part shows.
    name : str
        The name the method gives the section's result.
    kind : str
        The result's type.

    Returns
    -------
    callable
        A decorator that sets the method's docstring.
    """
    def document(method):
        method.__doc__ = (f"{summary}\n\nParameters\n----------\n{name} : {kind} or None\n"
                          "    The section's result; None: the case has none.\n"
                          "view : calc.report.page.View\n"
                          "    What the page asks: the candidates to list, the ratio search, a cycle typed by hand.\n"
                          "\nReturns\n-------\nstr\n    HTML.\n")
        return method

    return document


class Renderer:
    """The output side of one section, ``NAME`` (its key in the results): each method gives the
    section's part of one output, empty where it has none.

    ``SUMMARY_COLUMN``: the heading and the width of the summary's column naming the section's
    chosen part (:mod:`calc.report.summary`), None for no column. ``COMPARED_PART``: ``calc
    compare`` and the review's variants name its chosen part and its worst governing utilization
    (of :meth:`calc.sections.protocol.Result.ranked`)."""

    NAME: ClassVar[str]
    SUMMARY_COLUMN: ClassVar[tuple[str, str] | None] = None
    COMPARED_PART: ClassVar[bool] = False

    def result(self, report):
        """The section's result in a report.

        Parameters
        ----------
        report : calc.report.Report
            The report being built.

        Returns
        -------
        calc.sections.protocol.Result or None
            None where the case has none or cannot be evaluated.
        """
        return result_of(self.NAME, report)

    # -- the calc report's blocks (:class:`calc.report.Report`) ---------------------------------

    @block_doc("The source's sections the section is computed from (method).", "list of str")
    def sources(self, report) -> list[str]:
        return []

    @block_doc("The keys of the errata readings that apply (method).", "set of str")
    def readings(self, report) -> set[str]:
        return set()

    @block_doc("Rows of the inputs table (:func:`input_row`).", "list of list of str")
    def input_rows(self, report) -> list[list[str]]:
        return []

    @block_doc("Tables of inputs after the inputs table.", "list of str")
    def inputs(self, report) -> list[str]:
        return []

    @block_doc("The calculations, ``symbol = formula = values = result``.", "list of str")
    def steps(self, report) -> list[str]:
        return []

    @block_doc("What the section gives besides its checks.", "list of str")
    def results(self, report) -> list[str]:
        return []

    @block_doc("The checks of the part chosen (or the closest), or of the section's own values.", "list of str")
    def checks(self, report) -> list[str]:
        return []

    @block_doc("The candidates ranked.", "list of str")
    def candidates(self, report) -> list[str]:
        return []

    @block_doc("(figure, caption) pairs; the caption is LaTeX.", "list")
    def figures(self, report) -> list:
        return []

    @block_doc("(what, part, detail) of the part chosen; part None where none passes.", "list of tuple")
    def chosen(self, report) -> list[tuple]:
        return []

    @block_doc("What to order.", "list of str")
    def order_lines(self, report) -> list[str]:
        return []

    # -- the design review's page and the comparison of designs ----------------------------------

    def page(self, result, view) -> str:
        """The section's part of the review's page, HTML (:mod:`calc.report.page`).

        Parameters
        ----------
        result : calc.sections.protocol.Result or None
            The section's result; None where the case has none.
        view : calc.report.page.View
            What the page asks: the candidates to list, the ratio search, a cycle typed by hand.

        Returns
        -------
        str
        """
        return ""

    def compared(self) -> tuple:
        """Rows of the comparison of designs (``calc compare``) beside the chosen parts.

        Returns
        -------
        tuple
            ``(name, text)`` pairs: the row's name, and a function giving its text of the
            section's result (None where a design has none), in the unit system shown.
        """
        return ()


def checks_table(checks: list, caption: str) -> str:
    """Required, rated, utilization and verdict of each check of one candidate; checks of the other
    operating mode (gearboxes) in grey, for information.

    Parameters
    ----------
    checks : list of calc.core.checks.Check
        The candidate's checks.
    caption : str
        The table's caption, plain text.

    Returns
    -------
    str
        The table, LaTeX.
    """
    modes = any(k.mode for k in checks)
    rows = []
    for k in checks:
        grey = "" if k.governs else r"\color{infogrey}"
        cells = [grey + (prose(k.criterion) if k.criterion else latex_escape(k.name))]
        cells += [grey + latex_escape(k.mode or "")] if modes else []
        note = "" if k.governs else r"{} \footnotesize(for information)"
        cells += [grey + q(k.required_value), grey + q(k.rated_value), grey + util(k.utilization),
                  grey + verdict_mark(k.passes, k.not_made) + note]
        rows.append(cells)
    header = ["Criterion"] + (["Mode"] if modes else []) + ["Required", "Rated", "Utilization", "Verdict"]
    columns = "@{}l " + ("l " if modes else "") + r"r r r >{\raggedright\arraybackslash}p{0.24\linewidth}@{}"
    return table(columns, header, rows, caption=latex_escape(caption), small=True,
                 note="Utilization = required / rated; a check passes at 1.00 or below.")


def requirement_table(checks: list, caption: str) -> str:
    """Checks of a value reached (its required side) against a limit the case requires (its rated
    side): ``value <= required``.

    Parameters
    ----------
    checks : list of calc.core.checks.Check
        The checks.
    caption : str
        The table's caption, plain text.

    Returns
    -------
    str
        The table, LaTeX.
    """
    at_least = lambda k: r"$\geq$ " if k.at_least else ""  # noqa: E731 (a lower bound: a term of it unknown)
    rows = [[prose(k.criterion), at_least(k) + q(k.required_value), q(k.rated_value),
             at_least(k) + util(k.utilization), verdict_mark(k.passes, k.not_made)] for k in checks]
    # The verdict is a paragraph: a check not made gives its reason, which may be long.
    return table(r"@{}p{0.2\linewidth} r r r p{0.3\linewidth}@{}",
                 ["Criterion", "Value", "Required", "Utilization", "Verdict"], rows,
                 caption=latex_escape(caption), note="Utilization = value / required; a check passes at 1.00 or below.")


def candidates_table(candidates: list, selected: str | None, caption: str, inertia: bool = False) -> str:
    """The utilization of each check of each candidate, best first (and its inertia ratio).

    Parameters
    ----------
    candidates : list of calc.core.selection.Candidate
        The candidates, best first.
    selected : str or None
        The chosen part (marked), None for none.
    caption : str
        The table's caption, LaTeX.
    inertia : bool, optional
        Show each candidate's load to motor inertia ratio.

    Returns
    -------
    str
        The table, LaTeX, with a note naming the checks.
    """
    checks = [k for c in candidates for k in c.checks]
    names = list(dict.fromkeys(k.name for k in checks))  # every check any candidate has, in order
    governs = {k.name: k.governs for k in checks}
    criteria = {k.name: k.criterion for k in checks}
    grey = {n: "" if governs[n] else r"\color{infogrey}" for n in names}
    header = ["Part"] + [grey[n] + prose(n) for n in names] + ([r"$\lambda$"] if inertia else []) + ["Verdict"]
    rows = []
    for c in candidates:
        by = {k.name: k for k in c.checks}
        cells = [latex_escape(c.part)]
        cells += [grey[n] + util(by[n].utilization, missing="n/r") if n in by else "–" for n in names]
        if inertia:
            cells.append("–" if c.inertia_ratio is None else f"{c.inertia_ratio:.2f}")
        cells.append(verdict_mark(c.passes) + (r"{} \footnotesize(chosen)" if c.part == selected else ""))
        rows.append(cells)
    cols = "@{}l " + "r " * (len(names) + (1 if inertia else 0)) + "l@{}"
    note = ("Checks: " + "; ".join(prose(criteria[n]) if criteria[n] else latex_escape(n) for n in names)
            + ". n/r: the catalog gives no rating.")
    if inertia:
        note += rf" ${inertia_ratio.latex()}$, load to motor inertia ratio (E6)."
    return table(cols, header, rows, caption=caption, note=note, small=True, narrow=True)


#: Rejected candidates whose reasons a report lists where they are ranked, closest first; the
#: appendix lists all (:func:`rejected_in_full`), as the JSON does.
SHOWN_REJECTIONS = 5


def _rejections(candidates: list) -> list[str]:
    return [rf"\textbf{{{latex_escape(c.part)}}}: {prose('; '.join(c.reasons))}" for c in candidates if c.reasons]


def rejected(candidates: list) -> list[str]:
    """Why the closest rejected candidates fail, one item each, and how many more the appendix lists.

    Parameters
    ----------
    candidates : list of calc.core.selection.Candidate
        The candidates, closest first.

    Returns
    -------
    list of str
        One LaTeX paragraph with the list; nothing when none is rejected.
    """
    items = _rejections(candidates)
    if not items:
        return []
    more = len(items) - SHOWN_REJECTIONS
    tail = [rf"\emph{{and {more} more, each with its reasons in the appendix}}"] if more > 0 else []
    return [r"\paragraph{Why the others are rejected (the closest first).}"
            + itemize(items[:SHOWN_REJECTIONS] + tail)]


def rejected_in_full(name: str, candidates: list) -> list[str]:
    """Every rejected candidate of a section with its reasons, where the report shows only the
    closest (:data:`SHOWN_REJECTIONS`).

    Parameters
    ----------
    name : str
        The section's name.
    candidates : list of calc.core.selection.Candidate
        Its candidates, closest first.

    Returns
    -------
    list of str
        A heading and the list (LaTeX); nothing when the report shows every rejection already.
    """
    items = _rejections(candidates)
    if len(items) <= SHOWN_REJECTIONS:
        return []
    return [rf"\subsection*{{Every rejected {latex_escape(name)} candidate, closest first}}",
            r"{\small" + itemize(items) + "}"]


def raw_section_tables(name: str, raw: dict, derived: dict) -> str:
    """A further section of the case as its inputs, each row as its key is declared: symbol,
    value and unit as written, description, key; its arrays of tables (the members of an accuracy
    chain) as one row each, figures as written.

    Parameters
    ----------
    name : str
        The section's name, its table in the case.
    raw : dict
        The table as written.
    derived : dict
        The inputs the case left out and the package took from the rest of the case, as the case
        would write them.

    Returns
    -------
    str
        The section's heading and tables, LaTeX.
    """
    rows, members = [], []
    for key, v in {**raw, **derived}.items():
        if isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            members += [(key, k, x) for k, x in enumerate(v, start=1)]
            continue
        rows.append(input_row(f"{name}.{key}", v, derived=key in derived))
    out = [rf"\subsection*{{{latex_escape(name.capitalize())}}}"]
    if rows:
        note = (r"\textsuperscript{\dag} Not in the case file: taken from the rest of the case (a coupling between "
                r"motor and gearbox, E8); the calculations show how.") if derived else ""
        out.append(table(INPUT_COLUMNS, ["Symbol", "Value", "Unit", "Description", "Case key"], rows, note=note))
    if members:
        body = []
        for key, k, x in members:
            what = ", ".join(f"{f} = {x[f]}" for f in x if f not in ("name", "side", "part"))
            body.append([rf"\texttt{{\footnotesize {latex_escape(f'{name}.{key}[{k}]')}}}",
                         latex_escape(x.get("name") or x.get("part", "")),
                         latex_escape(x.get("side", "output" if "part" in x else "")), latex_escape(what)])
        out.append(table(r"@{}l l l p{0.42\linewidth}@{}", ["Case key", "Member", "Side", "Figures as written"], body,
                         caption=latex_escape(f"Members of the {name} chain, drive to load")))
    return "\n".join(out)


class TableRenderer(Renderer):
    """The renderer of a section that reads a table of its own (the coupling, the accuracy): its
    method and its inputs as written where the case gives the table, and its checks, of the part
    it chose or against the case's requirements."""

    def described(self, report) -> bool:
        """Whether the case gives the section's own table.

        Parameters
        ----------
        report : calc.report.Report
            The report being built.

        Returns
        -------
        bool
        """
        return report.case.sections.get(self.NAME) is not None

    def derived_inputs(self, report, raw: dict) -> dict:
        """The inputs the table leaves out and the package takes from the rest of the case, as
        the case would write them (by default none).

        Parameters
        ----------
        report : calc.report.Report
            The report being built.
        raw : dict
            The table as written.

        Returns
        -------
        dict
            Key -> text.
        """
        return {}

    def sources(self, report) -> list[str]:
        return sources(self.NAME) if self.described(report) else []

    def readings(self, report) -> set[str]:
        return readings(self.NAME) if self.described(report) else set()

    def inputs(self, report) -> list[str]:
        if not self.described(report):
            return []
        raw = report.case.sections[self.NAME]
        return [raw_section_tables(self.NAME, raw, self.derived_inputs(report, raw))]

    @block_doc("The checks of the best-ranked candidate, or the checks against the case's requirements.",
               "list of str", "The checks' table (LaTeX), none where there is nothing to check.")
    def checks(self, report) -> list[str]:
        r = self.result(report)
        if r is not None and r.ranked() is not None:
            best = r.ranked().best
            return [checks_table(best.checks, f"Checks of {self.NAME} {best.part}")] if best.checks else []
        g = None if r is None else r.governing()
        caption = f"{self.NAME.capitalize()} against the requirements of the case"
        return [] if g is None else [requirement_table(g.checks, caption)]
