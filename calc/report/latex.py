"""LaTeX for the calc report: escaping, our own prose with its symbols in math, numbers, and the
tables and calculation steps every section lays out (their skeletons are the Jinja2 templates in
``templates/``, with nbconvert's LaTeX-friendly delimiters ``((* *))``, ``((( )))``, ``((= =))``)."""

from __future__ import annotations

import re
from pathlib import Path

import jinja2
import numpy as np

from ..formula import Step
from ..units import NUMBER, pretty_unit, sig


class Latex(str):
    """A block of LaTeX: Jupyter shows it, nbconvert's LaTeX export passes it into the PDF as is."""

    def _repr_latex_(self):
        return str(self)


_SPECIAL = {
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
    "^": r"\textasciicircum{}", "_": r"\_", "%": r"\%", "~": r"\textasciitilde{}",
}
_LIGATURE = re.compile(r"(?<=[-`',<>!?])(?=[-`',<>!?])")


def latex_escape(text) -> str:
    r"""Text as LaTeX that prints exactly as written.

    The ten special characters are escaped, line breaks become spaces, and ``{}`` is put between
    characters that TeX would join (``--`` into a dash, ``''`` into a quote).

    >>> print(latex_escape("Axis #3 — 50% load & T_2 {v2} \\ 100$"))
    Axis \#3 — 50\% load \& T\_2 \{v2\} \textbackslash{} 100\$
    >>> print(latex_escape("a--b"))
    a-{}-b
    """
    out = "".join(_SPECIAL.get(c, c) for c in " ".join(str(text).splitlines()))
    return _LIGATURE.sub("{}", out)


_SYMBOL = re.compile(r"\b(phi|eta|lambda|[A-Za-z])_([A-Za-z0-9]+(?:,[A-Za-z]+)?)\b")  # d_hub,max whole
_GREEK = {"phi": r"\varphi", "eta": r"\eta", "lambda": r"\lambda"}


def prose(text: str) -> str:
    """Our own running text (readings, assumptions, reasons) as LaTeX: escaped, with each symbol
    written as in code (``n_2m``, ``J_motor``) set in math and ``<=``, ``>=`` as ≤, ≥.

    >>> print(prose("n_2m · i <= n_1N, 100%"))
    $n_{\\mathrm{2m}}$ · i ≤ $n_{\\mathrm{1N}}$, 100\\%
    >>> print(prose("d_motor <= d_hub,max"))
    $d_{\\mathrm{motor}}$ ≤ $d_{\\mathrm{hub,max}}$
    """
    out, last = [], 0
    text = text.replace("<=", "≤").replace(">=", "≥")
    for m in _SYMBOL.finditer(text):
        out += [latex_escape(text[last:m.start()]), rf"${_GREEK.get(m.group(1), m.group(1))}_{{\mathrm{{{m.group(2)}}}}}$"]
        last = m.end()
    return "".join(out) + latex_escape(text[last:])


_TEMPLATES = jinja2.Environment(
    loader=jinja2.FileSystemLoader(Path(__file__).parent / "templates"),
    block_start_string="((*", block_end_string="*))",
    variable_start_string="(((", variable_end_string=")))",
    comment_start_string="((=", comment_end_string="=))",
    trim_blocks=True, autoescape=False, undefined=jinja2.StrictUndefined,
)
_TEMPLATES.filters.update(escape_latex=latex_escape, prose=prose)


def render(template: str, **values) -> str:
    """A template of ``templates/`` filled in; values are LaTeX already (the templates escape
    what they take as text with the ``escape_latex`` and ``prose`` filters)."""
    return _TEMPLATES.get_template(template).render(**values)


def text_math(text: str) -> str:
    """A criterion written in plain text (``n_2m · i <= n_1N``) as LaTeX math."""
    out = re.sub(r"\b([A-Za-z])_([A-Za-z0-9]+)", r"\1_{\\mathrm{\2}}", text)
    return "$" + out.replace("<=", r"\le").replace(">=", r"\ge").replace("·", r"\cdot") + "$"


def signed(text: str) -> str:
    """A number's minus as a minus sign, not a hyphen."""
    return text.replace("-", "−", 1) if text.startswith("-") else text


def plain(d) -> str:
    """A result quantity ``{"value", "unit"}`` as plain text (``151.3 N·m``)."""
    if d is None or d.get("value") is None:
        return "n/a"
    return f"{signed(sig(d['value']))} {pretty_unit(d['unit'])}".rstrip()


def q(d) -> str:
    """A result quantity as LaTeX text."""
    return latex_escape(plain(d))


def num(quantity, unit: str) -> str:
    """A quantity's number in ``unit``."""
    return signed(sig(quantity.m_as(unit)))


def util(u) -> str:
    """A utilization, in bold red above 1."""
    if u is None or (isinstance(u, float) and np.isnan(u)):
        return "no rating"
    text = f"{u:.2f}"
    return rf"\textcolor{{failred}}{{\textbf{{{text}}}}}" if u > 1 else text


def verdict_mark(passes: bool) -> str:
    return r"\pass" if passes else r"\fail"


def listed(value) -> str:
    """A list as ``a, b``; anything else as its text."""
    return ", ".join(map(str, value)) if isinstance(value, (list, tuple)) else str(value)


def itemize(items) -> str:
    """Items (LaTeX already) as a list."""
    return r"\begin{itemize}" + "".join(rf"\item {x}" for x in items) + r"\end{itemize}"


def value_unit(value) -> tuple[str, str]:
    """A value as written in the case, split into number and unit where it is a quantity."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return f"{value:g}", "–"
    m = NUMBER.match(value) if isinstance(value, str) else None
    if m and m.group(2) and re.fullmatch(r"[A-Za-z°][A-Za-z0-9*/()^.-]*", m.group(2)):  # "19 mm k6" stays whole
        return latex_escape(m.group(1)), latex_escape(pretty_unit(m.group(2)))
    return latex_escape(value), "–"


def table(columns: str, header: list[str], rows: list[list[str]], caption: str = "", note: str = "", small: bool = False) -> str:
    """A booktabs longtable: a long one breaks across pages with its header repeated, a short one
    (up to 15 rows) stays on one page. Cells are LaTeX already; the note goes below the table.
    Only captioned tables are numbered (longtable counts every one)."""
    end = r" \\*" if len(rows) <= 15 else r" \\"
    return render(
        "table.tex.j2",
        columns=re.sub(r"(?<!})p\{", r">{\\raggedright\\arraybackslash}p{", columns),  # no stretched words
        head=" & ".join(rf"\textbf{{{h}}}" for h in header) + r" \\",
        body="\n".join(" & ".join(r) + end for r in rows),
        caption=caption, note=note, small=small,
    )


def step_block(title: str, step: Step, note: str = "") -> str:
    """One calculation: a heading, ``symbol = formula = values = result`` aligned on the equals
    signs (scaled down only if wider than the page), and its reference."""
    lhs, expr, values, result = step.parts()
    f = step.formula
    return render("step.tex.j2", title=latex_escape(title), symbol=f.result.latex, lhs=lhs, expr=expr, values=values,
                  result=result, ref=prose(f.reference + (f"; {note}" if note else "")))
