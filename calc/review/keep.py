"""A reviewer's changes kept as a case file: the original file with only the changed values
rewritten, its comments and layout kept (tomlkit), and a comment at the top naming what changed.

A change is a key path (:mod:`calc.review.inputs`) and the value as the panel's field shows it, in
the input's unit. The file is written beside the original, in the same folder, under a new name;
an existing file is never overwritten.
"""

from __future__ import annotations

import re
from pathlib import Path

from ..core.errors import CalcError

#: A key path into the file: ``motor.peak_torque``, ``move[2].time``, ``profile[1].duration``.
_KEY = re.compile(r"^(\w+)(?:\[(\d+)\])?\.(\w+)$")
#: A new case file's name: letters, digits, ``-``, ``_`` and ``.``, ending in ``.toml``.
_NAME = re.compile(r"^[\w][\w.-]*\.toml$")


def value_text(number: float, unit: str) -> str:
    """A number in ``unit`` as the case file writes it: ``"1.5 s"``; a bare number without a unit.

    >>> value_text(1.5, "s"), value_text(0.9, "")
    ('1.5 s', '0.9')
    """
    return f"{number:.12g} {unit}" if unit else f"{number:.12g}"


def _trailing(table) -> list:
    """The comments and blank lines at the end of a table (those before the next one), taken off it."""
    body, out = table.value.body, []
    while body and body[-1][0] is None:
        out.insert(0, body.pop()[1])
    return out


def with_moves_edited(original: str, edits, source: str) -> str:
    """The TOML text ``original`` with its ``[[move]]`` entries edited in order: ``("add", k,
    keys)`` puts a new entry of ``keys`` (its texts, as a case file writes them) after entry ``k``
    (0: before the first), ``("remove", k)`` takes entry ``k`` out (counted from 1);
    ``("mechanism", keys, distances, said)`` makes ``[mechanism]`` the table of ``keys`` (its
    comments kept where its keys stay) and writes ``distances[k]`` (entry k, as text) as the moves'
    distances. The other tables, comments and layout are kept; the comments after the last entry
    stay after it.

    >>> text = '[[move]]\\ndistance = "90 deg"\\ntime = "0.5 s"\\n[[move]]\\ndwell = "1 s"\\n\\n# the coupling\\n[coupling]\\n'
    >>> print(with_moves_edited(text, [("add", 2, {"dwell": "0.5 s"}), ("remove", 2)], "a.toml"))
    [[move]]
    distance = "90 deg"
    time = "0.5 s"
    [[move]]
    dwell = "0.5 s"
    <BLANKLINE>
    # the coupling
    [coupling]
    <BLANKLINE>
    """
    import tomlkit

    doc = tomlkit.parse(original)
    moves = doc.get("move")
    if not isinstance(moves, tomlkit.items.AoT):
        raise CalcError(f"{source}: the case gives no [[move]] tables to add to or remove from")
    for edit in edits:
        if edit[0] == "mechanism":
            _mechanism_edited(doc, moves, edit[1], edit[2])
            continue
        k = edit[1]
        if not 0 <= k <= len(moves) or (edit[0] == "remove" and k == 0):
            raise CalcError(f"{source}: move entry {k}: the case has {len(moves)} [[move]] tables")
        if edit[0] == "add":
            table = tomlkit.table()
            for key, text in edit[2].items():
                table[key] = text
            if k == len(moves):  # after the last: what followed it follows the new one
                for item in _trailing(moves[-1]):
                    table.value.append(None, item)
            moves.insert(k, table)
        elif len(moves) == 1:
            raise CalcError(f"{source}: move entry 1 is the only one: a motion needs at least one move")
        else:
            trail = _trailing(moves[k - 1]) if k == len(moves) else []
            del moves[k - 1]
            for item in trail:
                moves[-1].value.append(None, item)
    return tomlkit.dumps(doc)


def _mechanism_edited(doc, moves, keys: dict, distances: dict) -> None:
    """``[mechanism]`` as the table of ``keys``, and the moves' ``distances`` (by entry, from 1)."""
    table = doc["mechanism"]
    for key in [k for k in table if k not in keys]:
        del table[key]
    for key, value in keys.items():
        table[key] = value
    for k, text in distances.items():
        moves[int(k) - 1]["distance"] = text


def edit_text(edit) -> str:
    """An edit of the moves (:func:`with_moves_edited`) in words.

    >>> edit_text(("add", 2, {"dwell": "0.5 s"})), edit_text(("remove", 1))
    ('dwell 0.5 s added as entry 3', 'entry 1 of the moves removed')
    """
    if edit[0] == "remove":
        return f"entry {edit[1]} of the moves removed"
    if edit[0] == "mechanism":
        return edit[3]
    keys = edit[2]
    what = f"dwell {keys['dwell']}" if "dwell" in keys else f"move {keys.get('distance')} in {keys.get('time')}"
    return f"{what} added as entry {edit[1] + 1}"


def changed_text(original: str, changes: dict, source: str, edits=()) -> str:
    """The TOML text ``original`` with each ``changes[key] = (number, unit)`` written at its key
    path (a key the file leaves out is added to its table; a text, a part's name, is written as
    it is, and None removes the key), and a first comment naming the changes and the file
    ``source`` they were made to (after the ``edits`` of the moves the text already carries,
    :func:`with_moves_edited`).

    >>> text = '# axis\\n[motor]\\npeak_torque = "12 N*m"  # T_1B\\n'
    >>> print(changed_text(text, {"motor.peak_torque": (16.0, "N*m")}, "a.toml"))
    # Changed in the design review from a.toml: motor.peak_torque 12 N*m -> 16 N*m
    # axis
    [motor]
    peak_torque = "16 N*m"  # T_1B
    <BLANKLINE>
    """
    import tomlkit

    doc = tomlkit.parse(original)
    said = [edit_text(e) for e in edits]
    for key, (number, unit) in changes.items():
        m = _KEY.match(key)
        if m is None:
            raise CalcError(f"{key}: not a key path of a case file")
        section, index, name = m.group(1), m.group(2), m.group(3)
        if section not in doc:
            raise CalcError(f"{source}: {key}: the file has no [{section}] table to write it in")
        table = doc[section]
        if index is not None:
            items = table
            if int(index) > len(items):
                raise CalcError(f"{source}: {key}: the file has {len(items)} [[{section}]] tables")
            table = items[int(index) - 1]
        before = table.get(name)
        if isinstance(number, str) or number is None:  # a part named (None: the selection's, the key removed)
            if number is None:
                table.pop(name, None)
            else:
                table[name] = number
            said.append(f"{key} {'(not given)' if before is None else _plain(before)} -> {'(the selection)' if number is None else number}")
            continue
        if isinstance(before, bool) or (not unit and isinstance(before, (int, float))) or (before is None and not unit):
            new = int(number) if float(number).is_integer() and isinstance(before, int) else float(number)
        else:
            new = value_text(number, unit)
        table[name] = new
        said.append(f"{key} {'(not given)' if before is None else _plain(before)} -> {_plain(new)}")
    head = f"# Changed in the design review from {source}: " + "; ".join(said) + "\n"
    return head + tomlkit.dumps(doc)


def _plain(value) -> str:
    return str(value.unwrap() if hasattr(value, "unwrap") else value)


def save_path(original: Path, name: str) -> Path:
    """The new case file ``name`` beside ``original``: a plain file name (no folder), ending in
    ``.toml``, of a file that does not exist yet."""
    if not _NAME.match(name) or name in (".", ".."):
        raise CalcError(f"save as {name!r}: expected a file name such as {original.stem}-variant.toml (letters, digits, - _ .), no folder")
    path = original.parent / name
    if path.exists():
        raise CalcError(f"save as {name}: the file exists in {original.parent.name}/; choose another name (a case file is never overwritten here)")
    return path


def free_name(original: Path) -> str:
    """The first free name ``<stem>-variant-N.toml`` beside ``original``."""
    n = 1
    while (original.parent / f"{original.stem}-variant-{n}.toml").exists():
        n += 1
    return f"{original.stem}-variant-{n}.toml"
