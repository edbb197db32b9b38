"""The one exception type of the package, and how a message shows a list or a value.

Every message is one sentence that names where the bad value came from (file, key, catalog
row and column, or argument), what was expected and what was found, in at most
:data:`MAX_LENGTH` characters: a list inside it names at most :data:`LISTED` items and the count of
the rest (:func:`listing`), and a value as found or a quoted text is shown clipped (:func:`as_found`,
:func:`clipped`).
"""

#: The longest message an error may have [characters].
MAX_LENGTH = 300

#: The most items a list inside a message names; the rest are counted.
LISTED = 10

#: The most characters of a value as found that a message shows.
SHOWN = 60


class CalcError(ValueError):
    """Bad input: a value, unit, file or catalog that the calculation cannot use."""


def listing(items, separator: str = ", ", limit: int = LISTED) -> str:
    """A list as a message names it: its first ``limit`` items, and how many more there are.

    Parameters
    ----------
    items : iterable
        The items, each shown by ``str``.
    separator : str
        Between two items; default ``", "``.
    limit : int
        The most items named; default :data:`LISTED`.

    Returns
    -------
    str
        ``"A, B, C"``, or ``"A, B, C and 497 more"``.

    Examples
    --------
    >>> listing(f"F{k}" for k in range(500))
    'F0, F1, F2, F3, F4, F5, F6, F7, F8, F9 and 490 more'
    >>> listing(["S1", "S5"], " or ")
    'S1 or S5'
    """
    items = [str(x) for x in items]
    named = separator.join(items[:limit])
    return named + (f" and {len(items) - limit} more" if len(items) > limit else "")


def as_found(value, width: int = SHOWN) -> str:
    """A value as found, as a message shows it: its ``repr``, clipped (:func:`clipped`).

    Parameters
    ----------
    value : object
        The value as the file or the caller gave it.
    width : int
        The most characters shown; default :data:`SHOWN`.

    Returns
    -------
    str
        The ``repr``, or its start and how many characters are left out.

    Examples
    --------
    >>> as_found("12 N*m")
    "'12 N*m'"
    >>> as_found("x" * 500)
    "'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx… (446 more characters)"
    """
    return clipped(repr(value), width)


def clipped(text: str, width: int = SHOWN) -> str:
    """A text a message quotes (a source, a reason from a file), clipped to ``width`` characters.

    Parameters
    ----------
    text : str
        The text.
    width : int
        The most characters shown; default :data:`SHOWN`.

    Returns
    -------
    str
        The text, or its start, ``…`` and how many characters are left out.

    Examples
    --------
    >>> clipped("Mayr, Installation and Operational Instructions for ROBA-ES couplings", 40)
    'Mayr, Installation and Operational I… (33 more characters)'
    """
    text = str(text)
    if len(text) <= width:
        return text
    return f"{text[:width - 4]}… ({len(text) - width + 4} more characters)"
