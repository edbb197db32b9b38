"""What the sections' parts of the design review's page share: values, utilizations, verdicts and
tables as HTML, in the unit system the page shows.

Symbols are typeset as in the figures (``T_2B`` as T₂B with a subscript, ``<=`` as ≤:
:func:`calc.report.symbols.html`), units as a reader writes them (``N·m``), blanks where a value is
not given; a table has no index column. Each section's renderer (:class:`calc.report.common.Renderer`)
writes its part of the page with these; :mod:`calc.review.view` lays the page out.
"""

from __future__ import annotations

import contextvars
from dataclasses import dataclass
from html import escape

from ..core.checks import within_rating
from ..core.units import Q_, Value
from .symbols import html as typeset

PASS_COLOR, FAIL_COLOR = "#1b7837", "#b2222a"

#: The unit system the results are shown in: "SI" as the results write them, or "inch-pound".
SYSTEM = contextvars.ContextVar("system", default="SI")
#: A result's SI unit and its inch-pound counterpart (the units a US maker's sheet writes).
INCH_POUND = {"N*m": "lbf*in", "N": "lbf", "mm": "in", "m": "in", "kg*cm**2": "lb*in**2", "kg*m**2": "lb*in**2",
              "kg": "lb", "N*m/arcmin": "lbf*in/arcmin", "N*m/rad": "lbf*in/rad", "mm/s": "in/s", "m/s": "in/s",
              "m/s**2": "in/s**2"}
#: The other way: the SI unit of each inch-pound one, the first that :data:`INCH_POUND` lists for it (what the
#: review's fields of an inch-pound case show in SI).
SI_UNIT = {ip: si for si, ip in reversed(INCH_POUND.items())}
#: Under a table whose rows force their part (:func:`table`'s ``force``).
FORCING = "on the served page, a click on a row forces that part"


@dataclass(frozen=True)
class View:
    """What the page asks of the sections' parts.

    Attributes
    ----------
    shown : int or None
        The candidates listed in each table, best first (all for None).
    ratios : dict or str or None
        The ratio search's JSON or why it cannot be made (None: not asked for).
    typed_by_hand : bool
        The case's derived load cycle was changed segment by segment.
    """

    shown: int | None = None
    ratios: object = None
    typed_by_hand: bool = False


def in_system(v: Value | None) -> Value | None:
    """A result value in the unit system shown (:data:`SYSTEM`).

    Parameters
    ----------
    v : calc.core.units.Value or None
        A result value [its unit].

    Returns
    -------
    calc.core.units.Value or None
        The value in the unit of the system shown [SI, or inch-pound: :data:`INCH_POUND`].

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


def value(v: Value | None) -> str:
    """A result value as HTML text, in the unit system shown.

    Parameters
    ----------
    v : calc.core.units.Value or None
        A result value [its unit].

    Returns
    -------
    str
        ``151.3 N·m``; blank where not given.
    """
    return "" if v is None or v.value is None else escape(str(in_system(v)).replace(" 1/hour", " /h"))


def verdict_cell(passes, not_made: str | None = None) -> str:
    """PASS or FAIL, coloured; a check that could not be made says why, in grey.

    Parameters
    ----------
    passes : bool or None
        Whether the check passes; None where it could not be made.
    not_made : str, optional
        Why it could not be made.

    Returns
    -------
    str
    """
    if passes is None:
        return f'<span class="open">not checked{": " + typeset(not_made) if not_made else ""}</span>'
    return '<span class="pass">PASS</span>' if passes else '<span class="fail">FAIL</span>'


def utilization(u) -> str:
    """A utilization in per cent with a bar (red over 100 %).

    Parameters
    ----------
    u : float or None
        Required over rated [1]; None where there is none.

    Returns
    -------
    str
        Blank where there is none.
    """
    if u is None:
        return ""
    width = max(0.0, min(u, 1.0)) * 100
    color = PASS_COLOR if within_rating(u) else FAIL_COLOR
    return f'{100 * u:.0f} %<span class="bar"><span style="width:{width:.0f}%;background:{color}"></span></span>'


def table(header: list[str], rows: list[list[str]], numeric: set[int] = frozenset(), marked: int | None = None,
          force: tuple[str, list[str]] | None = None) -> str:
    """An HTML table; a click on a row may force its part (the page's script sets the control,
    :mod:`calc.review.client`).

    Parameters
    ----------
    header : list of str
        The columns' headings (HTML).
    rows : list of list of str
        The cells (HTML).
    numeric : set of int
        The columns set right-aligned as numbers.
    marked : int, optional
        The row shaded as chosen.
    force : tuple, optional
        A control's key and each row's part: a click on a row forces that part.

    Returns
    -------
    str
    """
    head = "".join(f"<th>{h}</th>" for h in header)

    def forcing(k: int) -> str:
        if force is None:
            return ""
        key, parts = force
        return f' data-force="{escape(key)}" data-part="{escape(parts[k])}" title="click to force {escape(parts[k])}"'

    def cell_class(j: int, h: str) -> str:
        return "n" if j in numeric else ("why" if h in ("reasons", "verdict") else "")

    body = "".join(
        f'<tr{" class=chosen" if k == marked else ""}{forcing(k)}>'
        + "".join(f'<td class="{cell_class(j, h)}">{c}</td>' for j, (h, c) in enumerate(zip(header, row)))
        + "</tr>"
        for k, row in enumerate(rows)
    )
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def candidates_shown(sel, shown: int | None) -> tuple[list, str]:
    """The first candidates of a selection, best first, and a note of how many are left out.

    Parameters
    ----------
    sel : calc.core.selection.Selection
        A catalog ranked.
    shown : int or None
        How many (all for None; only those are made into records).

    Returns
    -------
    tuple
        The candidates (:class:`calc.core.selection.Candidate`) and the note (HTML, empty where none is left out).
    """
    out, total = sel.candidates(shown), len(sel.order)
    if len(out) == total:
        return out, ""
    return out, (f"<div class=note>{len(out)} of {total} candidates shown; tick <i>all candidates</i> "
                 "for the rest.</div>")


def notes(texts) -> str:
    """Notes under a table, one line each.

    Parameters
    ----------
    texts : iterable of str
        The notes, symbols as the results write them.

    Returns
    -------
    str
    """
    return "".join(f"<div class=note>{typeset(n)}</div>" for n in texts)
