"""LaTeX for the calc report: escaping, our own prose with its symbols in math, numbers, and the
tables and calculation steps every section lays out (their skeletons are the Jinja2 templates in
``templates/``, with nbconvert's LaTeX-friendly delimiters ``((* *))``, ``((( )))``, ``((= =))``).
"""

from __future__ import annotations

import functools
import re
from pathlib import Path

import numpy as np

from ..core.checks import within_rating
from ..core.formula import Step
from ..core.units import NUMBER, Value, pretty_unit, sig
from .symbols import latex as prose
from ..core.glossary import math as symbol_math  # noqa: F401 (the report's sections take it from here)
# symbol_latex: the report's sections take it from here
from .symbols import latex_escape, symbol_latex  # noqa: F401


class Latex(str):
    """A block of LaTeX: Jupyter shows it, nbconvert's LaTeX export passes it into the PDF as is."""

    def _repr_latex_(self):
        return str(self)


@functools.lru_cache(maxsize=1)
def _templates():
    """The templates' environment, made at the first LaTeX asked for: the review's page, which asks
    for none, does without importing Jinja2."""
    import jinja2

    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(Path(__file__).parent / "templates"),
        block_start_string="((*", block_end_string="*))",
        variable_start_string="(((", variable_end_string=")))",
        comment_start_string="((=", comment_end_string="=))",
        trim_blocks=True, autoescape=False, undefined=jinja2.StrictUndefined,
    )
    env.filters.update(escape_latex=latex_escape, prose=prose)
    return env


def render(template: str, **values) -> str:
    """A template of ``templates/`` filled in.

    Parameters
    ----------
    template : str
        The template's file name (``"table.tex.j2"``).
    **values
        The template's variables, LaTeX already (the templates escape what they take as text with
        the ``escape_latex`` and ``prose`` filters).

    Returns
    -------
    str
        LaTeX.
    """
    return _templates().get_template(template).render(**values)


def signed(text: str) -> str:
    """A number's minus as a minus sign, not a hyphen.

    Parameters
    ----------
    text : str
        A number as text.

    Returns
    -------
    str
        The text, a leading hyphen written ``−``.
    """
    return text.replace("-", "−", 1) if text.startswith("-") else text


def plain(v: Value | None) -> str:
    """A result value as plain text (``151.3 N·m``, a minus sign where negative).

    Parameters
    ----------
    v : calc.core.units.Value or None
        The value.

    Returns
    -------
    str
        Its significant figures and unit; ``n/a`` for none.
    """
    if v is None or v.value is None:
        return "n/a"
    return f"{signed(sig(v.value))} {pretty_unit(v.unit)}".rstrip()


def q(d) -> str:
    """A result quantity as LaTeX text.

    Parameters
    ----------
    d : calc.core.units.Value or None
        The value.

    Returns
    -------
    str
        :func:`plain`, escaped.
    """
    return latex_escape(plain(d))


def num(quantity, unit: str) -> str:
    """A quantity's number in ``unit``.

    Parameters
    ----------
    quantity : pint.Quantity [any]
        The quantity.
    unit : str
        The unit to show it in, of its dimension.

    Returns
    -------
    str
        Its significant figures, a minus sign where negative.
    """
    return signed(sig(quantity.m_as(unit)))


def util(u, missing: str = "no rating") -> str:
    """A utilization, in bold red where it fails the one pass rule (:func:`calc.core.checks.within_rating`).

    Parameters
    ----------
    u : float or None
        The utilization [1]; None or NaN for none.
    missing : str, optional
        What to show where there is none (a table of many columns says it shorter).

    Returns
    -------
    str
        LaTeX, two decimals.
    """
    if u is None or (isinstance(u, float) and np.isnan(u)):
        return missing
    text = f"{u:.2f}"
    return text if within_rating(u) else rf"\textcolor{{failred}}{{\textbf{{{text}}}}}"


def verdict_mark(passes: bool | None, not_made: str | None = None) -> str:
    """PASS or FAIL; a check not made as not checked, with its reason.

    Parameters
    ----------
    passes : bool or None
        The verdict; None for a check not made.
    not_made : str, optional
        Why the check is not made.

    Returns
    -------
    str
        LaTeX (the template's ``\\pass``, ``\\fail`` or ``\\notchecked``).
    """
    if passes is None:
        return r"\notchecked" + (rf"{{}} {{\footnotesize {prose(not_made)}}}" if not_made else "")
    return r"\pass" if passes else r"\fail"


def listed(value) -> str:
    """A list as ``a, b``; anything else as its text.

    Parameters
    ----------
    value : object
        A list, a tuple or anything else.

    Returns
    -------
    str
        The text.
    """
    return ", ".join(map(str, value)) if isinstance(value, (list, tuple)) else str(value)


def breakable(text: str, escape=latex_escape) -> str:
    """Text as LaTeX that may break after a slash, an underscore or an ampersand (paths,
    addresses and case keys in narrow columns and notes).

    Parameters
    ----------
    text : str
        The text.
    escape : callable, optional
        How it becomes LaTeX (default :func:`latex_escape`).

    Returns
    -------
    str
        LaTeX.
    """
    out = escape(text)
    for c in ("/", r"\&", r"\_"):
        out = out.replace(c, c + r"\allowbreak{}")
    return out


def stacked(*lines: str) -> str:
    """Lines set one above the other in one table cell (a column's symbol over its unit).

    Parameters
    ----------
    *lines : str
        The lines, LaTeX.

    Returns
    -------
    str
        A one-column tabular.
    """
    # \relax: a line may start with [
    return r"\begin{tabular}[b]{@{}c@{}}" + r" \\ \relax ".join(lines) + r"\end{tabular}"


def sources_list(sources) -> tuple[dict, str]:
    """Each source once, numbered in the order given.

    Parameters
    ----------
    sources : iterable of str
        The sources, repeated or not.

    Returns
    -------
    tuple
        The number of each source (dict), and the list as LaTeX (empty for none).
    """
    numbers = {s: k for k, s in enumerate(dict.fromkeys(sources), start=1)}
    items = "".join(rf"\item[{{[{k}]}}] {breakable(s)}" for s, k in numbers.items())
    listing = r"{\footnotesize\begin{description}\setlength{\itemsep}{0pt}" + items + r"\end{description}}"
    return numbers, listing if numbers else ""


def itemize(items) -> str:
    """Items as a list.

    Parameters
    ----------
    items : iterable of str
        The items, LaTeX already.

    Returns
    -------
    str
        An itemize environment.
    """
    return r"\begin{itemize}" + "".join(rf"\item {x}" for x in items) + r"\end{itemize}"


def value_unit(value) -> tuple[str, str]:
    """A value as written in the case, split into number and unit where it is a quantity.

    Parameters
    ----------
    value : str or int or float
        The value as written.

    Returns
    -------
    tuple of str
        (number, unit) as LaTeX; the unit ``–`` where there is none.
    """
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return f"{value:g}", "–"
    m = NUMBER.match(value) if isinstance(value, str) else None
    if m and m.group(2) and re.fullmatch(r"[A-Za-z°][A-Za-z0-9*/()^.-]*", m.group(2)):  # "19 mm k6" stays whole
        return latex_escape(m.group(1)), latex_escape(pretty_unit(m.group(2)))
    return latex_escape(value), "–"


def table(columns: str, header: list[str], rows: list[list[str]], caption: str = "", note: str = "",
          small: bool = False, narrow: bool = False) -> str:
    """A booktabs longtable: a long one breaks across pages with its header repeated, a short one
    (up to 15 rows) stays on one page.

    Parameters
    ----------
    columns : str
        The column specification (a ``p{...}`` column is set ragged right).
    header : list of str
        The columns' headings, LaTeX (set in bold).
    rows : list of list of str
        The cells, LaTeX already.
    caption : str, optional
        The caption, LaTeX; only captioned tables are numbered (longtable counts every one).
    note : str, optional
        A note below the table, LaTeX.
    small : bool, optional
        Set it in a smaller type.
    narrow : bool, optional
        Less space between columns (tables of many columns, to fit the text width).

    Returns
    -------
    str
        LaTeX.
    """
    end = r" \\*" if len(rows) <= 15 else r" \\"
    return render(
        "table.tex.j2",
        columns=re.sub(r"(?<!})p\{", r">{\\raggedright\\arraybackslash}p{", columns),  # no stretched words
        head=" & ".join(rf"\textbf{{{h}}}" for h in header) + r" \\",
        body="\n".join(" & ".join(r) + end for r in rows),
        caption=caption, note=note, small=small, narrow=narrow,
    )


def step_block(title: str, step: Step, note: str = "") -> str:
    """One calculation: a heading, ``symbol = formula = values = result`` aligned on the equals
    signs (scaled down only if wider than the page), and its reference.

    Parameters
    ----------
    title : str
        The heading, plain text.
    step : calc.core.formula.Step
        The formula with its values and result.
    note : str, optional
        Said after the formula's reference, prose.

    Returns
    -------
    str
        LaTeX.
    """
    lhs, expr, values, result = step.parts()
    f = step.formula
    return render("step.tex.j2", title=latex_escape(title), symbol=f.result.latex, lhs=lhs, expr=expr,
                  values=values, result=result, ref=prose(f.reference + (f"; {note}" if note else "")))
