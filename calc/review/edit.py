"""Every edit of a case, one way: a key path and the value as the case file writes it, applied to
the parsed TOML (tomlkit, so comments and layout are kept) and read again by the case reader
(:func:`calc.sections.case.read_case`). The case on the screen is so the file it is saved as.

A key path names a value (``motor.peak_torque``, ``move[2].time``), an entry of an array of
tables (``move[3]``) or a table (``mechanism``, ``profile``). A value is a text (``"16 N*m"``, a
part's name), a bare number (a ratio, an efficiency), a dict (the keys of a table or entry), a list
of dicts (an array of tables) or None (the key, entry or table taken out).

The reviewer's edits of the moves are kept as the page's address carries them (:func:`moves_edits`
writes each as key paths): ``("add", k, keys)`` a new entry after entry ``k`` (0: before the
first), ``("remove", k)`` entry ``k`` taken out (counted from 1), ``("mechanism", keys, distances,
said)`` the mechanism of another type, with the moves' distances by entry.
"""

from __future__ import annotations

import functools
import pickle
import re
from dataclasses import dataclass
from pathlib import Path

from ..core.errors import CalcError
from ..sections.case import Case, read_case

#: One part of a key path: a name, with the entry of an array of tables where given (``move[2]``).
_PART = re.compile(r"^(\w+)(?:\[(\d+)\])?$")


@dataclass(frozen=True)
class Edit:
    """One edit of a case file: ``value`` written at the key path ``key`` (see the module's
    docstring).

    Parameters
    ----------
    key : str
        The key path: a value's (``motor.peak_torque``), an entry's (``move[3]``) or a table's.
    value : str, float, dict, list of dict or None
        The value as the file writes it: a text (``"16 N*m"``), a bare number, the keys of a table
        or entry, the entries of an array of tables; None takes the key, entry or table out.
    insert : bool
        Put a new entry in at the place ``key`` names (``move[3]``: before the third, or after the
        last where the array has two), the later ones moving up.
    """

    key: str
    value: object
    insert: bool = False


def value_text(number: float, unit: str) -> str:
    """A number in ``unit`` as the case file writes it: ``"1.5 s"``; a bare number without a unit.

    Parameters
    ----------
    number : float
        The value [``unit``].
    unit : str
        Its unit as a case file writes it (``"N*m"``), or ``""``.

    Returns
    -------
    str
        The text, twelve significant digits.

    Examples
    --------
    >>> value_text(1.5, "s"), value_text(0.9, "")
    ('1.5 s', '0.9')
    """
    return f"{number:.12g} {unit}" if unit else f"{number:.12g}"


def edited_text(text: str, edits, source: str) -> str:
    """The TOML text ``text`` with each of ``edits`` applied in order; the other tables, comments
    and layout are kept; the comment beside a value written over is marked as said of the file's
    value, which the change may contradict.

    Parameters
    ----------
    text : str
        A case file's text.
    edits : iterable of Edit
        The edits, in order.
    source : str
        The file's name, for an error.

    Returns
    -------
    str
        The edited text. An edit that cannot be made raises :class:`calc.core.errors.CalcError`
        naming the file and the key path.

    Examples
    --------
    >>> text = '[motor]\\npeak_torque = "12 N*m"  # T_1B\\n[[move]]\\ndwell = "1 s"\\n'
    >>> edits = [Edit("motor.peak_torque", "16 N*m"), Edit("move[2]", {"dwell": "0.5 s"}, insert=True)]
    >>> print(edited_text(text, edits, "a.toml"))
    [motor]
    peak_torque = "16 N*m"  # (said of the file's value 12 N*m) T_1B
    [[move]]
    dwell = "1 s"
    [[move]]
    dwell = "0.5 s"
    <BLANKLINE>
    """
    import tomlkit

    doc = _document(text)
    for edit in edits:
        _apply(doc, edit, source)
    return tomlkit.dumps(doc)


def edited_case(path: Path, text: str | None, edits) -> Case:
    """The case file read again by the case reader with ``edits`` written into its text.

    Parameters
    ----------
    path : pathlib.Path
        The case file (its folder finds the files it names).
    text : str or None
        Its text; None: as the file reads (then with no edit).
    edits : iterable of Edit
        The edits (:func:`edited_text`).

    Returns
    -------
    calc.sections.case.Case
        The case; a text that cannot be read, or edits that do not read, raise
        :class:`calc.core.errors.CalcError` saying why.
    """
    return read_case(path, edited_text(text, edits, path.name) if edits and text is not None else text)


def _apply(doc, edit: Edit, source: str):
    """Apply ``edit`` to the tomlkit document ``doc``; returns the value it replaced (None: none)."""
    parts = [_PART.match(p) for p in edit.key.split(".")]
    scalar = not isinstance(edit.value, (dict, list)) and edit.value is not None
    if not all(parts) or (scalar and len(parts) < 2):
        raise CalcError(f"{edit.key}: not a key path of a case file")
    table = doc
    for m in parts[:-1]:
        table = _entry(table, m.group(1), m.group(2), edit.key, source)
    name, index = parts[-1].group(1), parts[-1].group(2)
    if index is not None:
        return _edit_entry(table, name, int(index), edit, source)
    before = table.get(name)
    if edit.value is None:
        table.pop(name, None)
    elif isinstance(edit.value, dict):
        _set_keys(table, name, edit.value)
    elif isinstance(edit.value, list):
        table[name] = _array_of_tables(edit.value)
    else:
        table[name] = _as_written(edit.value, before)
        _mark_comment(table[name], before)
    return before


def _mark_comment(item, before) -> None:
    """The comment beside a value written over the file's: marked as said of the file's value,
    which the change may contradict (``# T_1B, 12 N*m`` beside 16 N*m)."""
    trivia = getattr(item, "trivia", None)
    if before is None or trivia is None or not trivia.comment or _plain(before) == _plain(item):
        return
    said = trivia.comment.lstrip("#").strip()
    if not said.startswith("(said of the file's value"):
        trivia.comment = f"# (said of the file's value {comment_text(_plain(before))}) {said}"


#: Characters that end a line or do not print: never written into a comment (a newline there would be TOML).
_UNPRINTED = re.compile(r"[\x00-\x1f\x7f-\x9f\u2028\u2029]")


def comment_text(text: str, limit: int = 300) -> str:
    """A text as one line of a TOML comment: each line break or unprinted character a space, and
    cut at ``limit`` characters, so that no text, a link's among them, becomes TOML.

    Parameters
    ----------
    text : str
        The text (a link's words, a value as the file wrote it).
    limit : int
        The most characters kept; default 300.

    Returns
    -------
    str
        One line.

    Examples
    --------
    >>> comment_text('rotary\\n[drive_record]\\nfile = "/etc/x"')
    'rotary [drive_record] file = "/etc/x"'
    """
    one = _UNPRINTED.sub(" ", str(text))
    return one if len(one) <= limit else one[: limit - 1] + "…"


def _entry(table, name: str, index, key: str, source: str):
    """The table ``name`` of ``table``, or its entry ``index`` (from 1) where it is an array of tables."""
    import tomlkit

    if name not in table:
        raise CalcError(f"{source}: {key}: the file has no [{name}] table to write it in")
    item = table[name]
    if index is None:
        return item
    if not isinstance(item, tomlkit.items.AoT):
        raise CalcError(f"{source}: {key}: the file has no [[{name}]] tables")
    if not 1 <= int(index) <= len(item):
        raise CalcError(f"{source}: {key}: the file has {len(item)} [[{name}]] tables")
    return item[int(index) - 1]


def _as_written(value, before):
    """``value`` as the file writes it: a bare number stays an integer where the file's was one
    (a ratio of 10 becomes 8, not 8.0), and a text where the file quoted it."""
    if isinstance(value, float) and isinstance(before, str):
        return value_text(value, "")
    if isinstance(value, float) and isinstance(before, int) and not isinstance(before, bool) and value.is_integer():
        return int(value)
    return value


def _set_keys(table, name: str, keys: dict) -> None:
    """``table[name]`` as the table of ``keys``: the keys it no longer has taken out, those it
    keeps in their places (with their comments), new ones after them."""
    import tomlkit

    if name not in table:
        table[name] = tomlkit.table()
    _fill(table[name], keys)


def _fill(table, keys: dict) -> None:
    for key in [k for k in table if k not in keys]:
        del table[key]
    for key, value in keys.items():
        table[key] = value


def _array_of_tables(rows: list):
    import tomlkit

    aot = tomlkit.aot()
    for row in rows:
        entry = tomlkit.table()
        _fill(entry, row)
        aot.append(entry)
    return aot


def _trailing(table) -> list:
    """The comments and blank lines at the end of a table (those before the next one), taken off it."""
    body, out = table.value.body, []
    while body and body[-1][0] is None:
        out.insert(0, body.pop()[1])
    return out


def _edit_entry(table, name: str, k: int, edit: Edit, source: str):
    """An entry of the array of tables ``table[name]`` put in, replaced or taken out; the comments
    after the last entry stay after the last."""
    import tomlkit

    entries = table.get(name)
    if not isinstance(entries, tomlkit.items.AoT):
        raise CalcError(f"{source}: {edit.key}: the file has no [[{name}]] tables to add to or remove from")
    if not 1 <= k <= len(entries) + (1 if edit.insert else 0):
        raise CalcError(f"{source}: {edit.key}: the file has {len(entries)} [[{name}]] tables")
    if edit.insert:
        entry = tomlkit.table()
        _fill(entry, edit.value)
        if k == len(entries) + 1:  # after the last: what followed it follows the new one
            for item in _trailing(entries[-1]):
                entry.value.append(None, item)
        entries.insert(k - 1, entry)
        return None
    before = entries[k - 1]
    if edit.value is not None:
        _fill(before, edit.value)
        return before
    if len(entries) == 1:
        raise CalcError(f"{source}: {edit.key} is the only [[{name}]] table: it cannot be taken out")
    trail = _trailing(before) if k == len(entries) else []
    del entries[k - 1]
    for item in trail:
        entries[-1].value.append(None, item)
    return before


def moves_edits(edit) -> list[Edit]:
    """An edit of the moves (see the module's docstring) as key-path edits.

    Parameters
    ----------
    edit : sequence
        ``("add", k, keys)``, ``("remove", k)`` or ``("mechanism", keys, distances, said)``.

    Returns
    -------
    list of Edit
        The edits of the case file, in order: an entry put in or taken out, or the mechanism's
        table and each move's distance.

    Examples
    --------
    >>> moves_edits(("add", 2, {"dwell": "1 s"})), moves_edits(("remove", 1))
    ([Edit(key='move[3]', value={'dwell': '1 s'}, insert=True)], [Edit(key='move[1]', value=None, insert=False)])
    """
    if edit[0] == "add":
        return [Edit(f"move[{edit[1] + 1}]", dict(edit[2]), insert=True)]
    if edit[0] == "remove":
        return [Edit(f"move[{edit[1]}]", None)]
    return [Edit("mechanism", dict(edit[1]))] + [Edit(f"move[{k}].distance", text) for k, text in edit[2].items()]


def edit_text(edit) -> str:
    """An edit of the moves in words.

    Parameters
    ----------
    edit : sequence
        An edit of the moves (:func:`moves_edits`).

    Returns
    -------
    str
        What it did, as the changed file's first comment and the variant's name say it.

    Examples
    --------
    >>> edit_text(("add", 2, {"dwell": "0.5 s"})), edit_text(("remove", 1))
    ('dwell 0.5 s added as entry 3', 'entry 1 of the moves removed')
    """
    if edit[0] == "remove":
        return f"entry {edit[1]} of the moves removed"
    if edit[0] == "mechanism":
        return comment_text(edit[3])
    keys = edit[2]
    what = f"dwell {keys['dwell']}" if "dwell" in keys else f"move {keys.get('distance')} in {keys.get('time')}"
    return f"{what} added as entry {edit[1] + 1}"


@functools.lru_cache(maxsize=8)
def _parsed(text: str) -> bytes:
    """The TOML text parsed by tomlkit, kept as its pickle (this process's own bytes, never a file's:
    :func:`_document` gives copies)."""
    import tomlkit

    return pickle.dumps(tomlkit.parse(text), pickle.HIGHEST_PROTOCOL)


def _document(text: str):
    """A tomlkit document of ``text`` to edit: a copy of the one parsed (a review's every change edits
    the same file's text; unpickling its document takes a twentieth of parsing it again, a third of
    ``copy.deepcopy``)."""
    return pickle.loads(_parsed(text))


def changed_text(original: str, moves, edits, source: str) -> str:
    """The TOML text ``original`` with the edits of the ``moves`` and then ``edits`` applied, and a
    first comment naming them and the file they were made to: each edit of the moves in words
    (:func:`edit_text`), each value as it was and as it is.

    Parameters
    ----------
    original : str
        The case file's text.
    moves : list
        The edits of the moves (:func:`moves_edits`), in order.
    edits : list of Edit
        The edits of values after them.
    source : str
        The case file's name.

    Returns
    -------
    str
        The text a changed case is read from and saved as.

    Examples
    --------
    >>> text = '# axis\\n[motor]\\npeak_torque = "12 N*m"  # T_1B\\n'
    >>> print(changed_text(text, [], [Edit("motor.peak_torque", "16 N*m")], "a.toml"))
    # Changed in the design review from a.toml: motor.peak_torque 12 N*m -> 16 N*m
    # axis
    [motor]
    peak_torque = "16 N*m"  # (said of the file's value 12 N*m) T_1B
    <BLANKLINE>
    """
    import tomlkit

    doc = _document(original)
    said = [edit_text(e) for e in moves]
    for edit in [e for m in moves for e in moves_edits(m)]:
        _apply(doc, edit, source)
    for edit in edits:
        before = _apply(doc, edit, source)
        if isinstance(edit.value, list):
            said.append(f"{edit.key} written as {len(edit.value)} tables")
        elif edit.value is None and "." not in edit.key:
            said.append(f"[{edit.key}] taken out")
        elif not isinstance(edit.value, dict):
            now = "(not given)" if edit.value is None else _plain(_as_written(edit.value, before))
            said.append(f"{edit.key} {'(not given)' if before is None else _plain(before)} -> {now}")
    header = comment_text(f"Changed in the design review from {source}: " + "; ".join(said), 4000)
    return f"# {header}\n" + tomlkit.dumps(doc)


def _plain(value) -> str:
    return str(value.unwrap() if hasattr(value, "unwrap") else value)
