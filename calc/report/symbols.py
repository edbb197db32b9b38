"""The package's own text in the outputs: symbols as written in code (``T_2B``, ``d_hub,max``,
``K_ϑ``, ``phi_LM``) with their subscripts, ``<=`` and ``>=`` as ≤ and ≥, names written in code
(``positioning_accuracy``) in words, and case keys (``motor.peak_torque``) as code.

Every criterion, reason, note and reading the package emits goes through :func:`tokens` once;
:func:`latex` (the calc report) and :func:`html` (the design review) only render its tokens, so the
two outputs typeset the same symbols the same way. A symbol's LaTeX is the one typesetter's,
:func:`calc.core.glossary.latex`, which the formulas print theirs by: a criterion and a calculation
print a symbol alike.
"""

from __future__ import annotations

import functools
import re
from html import escape

from ..core.glossary import GREEK
from ..core.glossary import latex as glossary_latex
from ..sections import TOP_KEYS

_SPECIAL = {
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
    "^": r"\textasciicircum{}", "_": r"\_", "%": r"\%", "~": r"\textasciitilde{}",
}
_LIGATURE = re.compile(r"(?<=[-`',<>!?])(?=[-`',<>!?])")


def latex_escape(text) -> str:
    r"""Text as LaTeX that prints exactly as written.

    The ten special characters are escaped, line breaks become spaces, and ``{}`` is put between
    characters that TeX would join (``--`` into a dash, ``''`` into a quote).

    Parameters
    ----------
    text : object
        The text (anything else as its ``str``).

    Returns
    -------
    str
        LaTeX.

    Examples
    --------
    >>> print(latex_escape("Axis #3 — 50% load & T_2 {v2} \\ 100$"))
    Axis \#3 — 50\% load \& T\_2 \{v2\} \textbackslash{} 100\$
    >>> print(latex_escape("a--b"))
    a-{}-b
    """
    out = "".join(_SPECIAL.get(c, c) for c in " ".join(str(text).splitlines()))
    return _LIGATURE.sub("{}", out)


_GREEK_NAMES = "|".join(name for name in GREEK if name != "Delta")  # Δ alone is no symbol of the prose
# A case key, ``motor.peak_torque`` or ``coupling.shaft_1``, or a name in the package (code, set as code):
# the case's tables, and the package's own names, calc.domain.gearbox.x.
_TABLES = "|".join(["calc", *(k for k in TOP_KEYS if k != "title")])
_KEY = rf"(?P<key>(?<![\w.])(?:{_TABLES})(?:\[\d+\])?(?:\.[a-z][a-z0-9_]*(?:\[\d+\])?)+)"
# A symbol as written in code: a letter (or a Greek name) and its subscript, ``d_hub,max`` whole.
_SYMBOL = rf"(?P<sym>(?<![\w.])(?P<base>{_GREEK_NAMES}|[^\W\d_])_(?P<sub>[^\W_]+(?:,[^\W_]+)*)(?![\w]))"
# A name written in code, ``positioning_accuracy``: words.
_WORDS = r"(?P<words>(?<![\w.])[a-z]{2,}(?:_[a-z]{2,})+\b)"
# A lone letter or Greek name next to an operator, ``i`` of ``n_2m · i`` and ``J_L / i²`` (not
# a unit after its number, ``0.3 s + 0.3 s``).
_LETTER = rf"(?:{_GREEK_NAMES}|[A-Za-zα-ωϑ])"
_LONE = rf"(?P<lone>(?<![\w.])(?<!\d )(?:(?<=[·/=≤≥+] ){_LETTER}(?=[\s²)]|$)|{_LETTER}(?= [·/=≤≥+] )))"
_TOKEN = re.compile("|".join((_KEY, _SYMBOL, _WORDS, _LONE)))


def tokens(text: str) -> list[tuple[str, ...]]:
    """The text as tokens, each symbol, case key and name in code found once for every output.

    Parameters
    ----------
    text : str
        The package's text (a criterion, reason, note or reading).

    Returns
    -------
    list of tuple
        ``("text", s)``, ``("symbol", base, subscript)`` (subscript empty for a lone letter),
        ``("code", s)``.

    Examples
    --------
    >>> tokens("d_motor <= d_hub,max")
    [('symbol', 'd', 'motor'), ('text', ' ≤ '), ('symbol', 'd', 'hub,max')]
    >>> tokens("n_2m · i <= n_1N")
    [('symbol', 'n', '2m'), ('text', ' · '), ('symbol', 'i', ''), ('text', ' ≤ '), ('symbol', 'n', '1N')]
    >>> tokens("lambda")
    [('symbol', 'lambda', '')]
    >>> tokens("positioning_accuracy <= required, motor.peak_torque")
    [('text', 'positioning accuracy'), ('text', ' ≤ required, '), ('code', 'motor.peak_torque')]
    """
    text = str(text).replace("<=", "≤").replace(">=", "≥")
    if text in GREEK:  # a name that is one Greek letter (a check's, a column's): the letter
        return [("symbol", text, "")]
    out, last = [], 0
    for m in _TOKEN.finditer(text):
        if m.start() > last:
            out.append(("text", text[last:m.start()]))
        if m.group("key"):
            out.append(("code", m.group("key")))
        elif m.group("sym"):
            out.append(("symbol", m.group("base"), m.group("sub")))
        elif m.group("words"):
            out.append(("text", m.group("words").replace("_", " ")))
        else:
            out.append(("symbol", m.group("lone"), ""))
        last = m.end()
    if last < len(text):
        out.append(("text", text[last:]))
    return out


def latex(text: str) -> str:
    r"""The text as LaTeX: escaped, each symbol in math.

    Parameters
    ----------
    text : str
        The package's text.

    Returns
    -------
    str
        LaTeX.

    Examples
    --------
    >>> print(latex("M_N · K_ϑ <= T_KN"))
    $M_{\mathrm{N}}$ · $K_{\vartheta}$ ≤ $T_{\mathrm{KN}}$
    >>> print(latex("d_motor <= d_hub,max, 100%"))
    $d_{\mathrm{motor}}$ ≤ $d_{\mathrm{hub,max}}$, 100\%
    >>> print(latex("T_1rms <= M_N"))
    $T_{\mathrm{1rms}}$ ≤ $M_{\mathrm{N}}$
    """
    out = []
    for kind, *rest in tokens(text):
        if kind == "text":
            out.append(latex_escape(rest[0]))
        elif kind == "code":
            out.append(rf"\texttt{{{latex_escape(rest[0])}}}")
        else:
            out.append(f"${_symbol_latex(*rest)}$")
    return "".join(out)


def _symbol_latex(base: str, sub: str) -> str:
    return glossary_latex(f"{base}_{sub}" if sub else base)


def symbol_latex(name: str) -> str:
    r"""A symbol by its name in code (``T_1N``, ``d_hub,max``, ``vartheta``) as LaTeX math, without
    the dollars: the glossary's (:func:`calc.core.glossary.latex`).

    Parameters
    ----------
    name : str
        The symbol as code writes it.

    Returns
    -------
    str
        LaTeX math.

    Examples
    --------
    >>> print(symbol_latex("T_1N"), symbol_latex("vartheta"), symbol_latex("phi_B"), symbol_latex("t_k"))
    T_{\mathrm{1N}} \vartheta \varphi_{\mathrm{B}} t_{k}
    """
    return glossary_latex(name)


def symbol_text(name: str) -> str:
    """A symbol by its name in code as plain text, its Greek letter written as the letter
    (``vartheta`` as ϑ, ``T_1B`` as is).

    Parameters
    ----------
    name : str
        The symbol as code writes it.

    Returns
    -------
    str
        Plain text.

    Examples
    --------
    >>> symbol_text("vartheta"), symbol_text("T_1B"), symbol_text("mu")
    ('ϑ', 'T_1B', 'μ')
    """
    base, sep, sub = name.partition("_")
    return GREEK[base][1] + sep + sub if base in GREEK else name


def html(text: str) -> str:
    """The text as HTML: escaped, each symbol in italics with its subscript (a case key as written:
    HTML has no underscore to escape).

    Parameters
    ----------
    text : str
        The package's text.

    Returns
    -------
    str
        HTML.

    Examples
    --------
    >>> html("T_2max <= T_2B: required 189.1 N·m > rated 126 N·m")
    '<i>T</i><sub>2max</sub> ≤ <i>T</i><sub>2B</sub>: required 189.1 N·m &gt; rated 126 N·m'
    >>> html("positioning_accuracy 9 arcmin")
    'positioning accuracy 9 arcmin'
    """
    return _html(str(text))


@functools.lru_cache(maxsize=4096)
def _html(text: str) -> str:
    """:func:`html`, kept: the review page typesets the same criteria and reasons at every change."""
    out = []
    for kind, *rest in tokens(text):
        if kind == "text":
            out.append(escape(rest[0]))
        elif kind == "code":
            out.append(escape(rest[0]))  # a case key reads as written
        else:
            base, sub = rest
            letter = GREEK[base][1] if base in GREEK else base
            out.append(f"<i>{escape(letter)}</i>" + (f"<sub>{escape(sub)}</sub>" if sub else ""))
    return "".join(out)
