"""The key reference of the case format, written from the sections' declarations
(:func:`calc.sections.case.declared_tables`): ``docs/case-format.md`` holds it between two markers, and a test
checks that it is what the declarations give, so the document cannot drift from the readers.

After declaring a key, ``python -c "from calc.sections.reference import reference; print(reference())"``
prints the reference to paste there.
"""

from __future__ import annotations

from .case import OTHER_KINDS, Declared, Key, declared_tables
from ..core.units import KINDS, pretty_unit

BEGIN = "<!-- key reference: written by calc.sections.reference.reference() -->"
END = "<!-- end of the key reference -->"


def _kind(key: Key) -> str:
    """The kind of a key with an example of how a case file writes it."""
    if key.kind == "dimensionless":
        return "bare number"
    if key.kind in KINDS:
        return f"{key.kind.replace('_', ' ')} (`{KINDS[key.kind].example}`)"
    return key.kind


def _default(key: Key) -> str:
    if key.default is None:
        return ""
    if isinstance(key.default, bool):
        return f"`{str(key.default).lower()}`"
    # A float as a case writes it: 10, not 10.0.
    return f"`{key.default:g}`" if isinstance(key.default, float) else f"`{key.default}`"


def _cell(text: str) -> str:
    """Text in a Markdown table's cell (a bar would end the cell)."""
    return text.replace("|", "\\|")


def _table(heading: str, description: str, keys: tuple) -> list[str]:
    out = [f"### `{heading}`", "", _cell(description[0].upper() + description[1:]) + ".", "",
           "| key | kind | symbol | default | unit shown | description |", "|---|---|---|---|---|---|"]
    for k in keys:
        only = f" ({', '.join(k.only)} only)" if k.only else ""
        out.append(f"| `{k.name}` | {_kind(k)} | {f'`{k.symbol}`' if k.symbol else ''} | {_default(k)} | "
                   f"{pretty_unit(k.unit) if k.unit else ''} | {_cell(k.description)}{only} |")
    out.append("")
    for k in keys:
        if k.keys:
            path = f"{heading.strip('[]')}.{k.name}"
            out += _table(f"[[{path}]]" if k.kind == "tables" else path, k.description, k.keys)
    return out


def reference(tables: tuple[Declared, ...] | None = None) -> str:
    """The key reference in Markdown: the kinds that are not quantities, then one table per
    declared table of a case file.

    Parameters
    ----------
    tables : tuple of calc.sections.case.Declared, optional
        The declared tables to write; None: every section's, in their order
        (:func:`calc.sections.case.declared_tables`).

    Returns
    -------
    str
        The reference, between the markers :data:`BEGIN` and :data:`END`.
    """
    tables = declared_tables() if tables is None else tables
    out = [BEGIN, "", "| kind | a case file writes |", "|---|---|"]
    out += [f"| {name} | {what} |" for name, what in OTHER_KINDS.items()]
    out.append("")
    for t in tables:
        out += _table(f"[[{t.name}]]" if t.array else f"[{t.name}]", t.description, t.keys)
    return "\n".join(out + [END])
