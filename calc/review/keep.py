"""A reviewer's changes kept as a case file: the original file with only the changed values
rewritten, its comments and layout kept (tomlkit), and a comment at the top naming what changed.

A change is a key path (:mod:`calc.review.inputs`) and the value as the panel's field shows it, in
the input's unit. The file is written beside the original, in the same folder, under a new name;
an existing file is never overwritten.
"""

from __future__ import annotations

import re
from pathlib import Path

from ..errors import CalcError

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


def changed_text(original: str, changes: dict, source: str) -> str:
    """The TOML text ``original`` with each ``changes[key] = (number, unit)`` written at its key
    path (a key the file leaves out is added to its table; a text, a part's name, is written as
    it is, and None removes the key), and a first comment naming the changes and the file
    ``source`` they were made to.

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
    said = []
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
