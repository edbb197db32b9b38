"""Shaft and hole tolerances: ISO 286 limit deviations, and bores as an order writes them.

The source's ordering examples give each shaft with its tolerance: metric with an ISO 286
tolerance class (``14 mm k6``), inch with limits (``1.00" +0/-.0005"``, ``.500" +/- .0005"``),
optionally with a keyway (``x 1/8" keyway``). :func:`parse_bore` reads such a text with one
regular expression (nothing is evaluated) and :func:`limit_deviations` gives the limits of an ISO
class from the standard's tables, entered below as data.

No library was used for the tables: the two on the package index that compute ISO 286 limits
cover either hole-basis fits only or sizes from 3 mm with a package layout that does not import;
the standard's tables are short and are tested here against published limits.

Scope of the tables (ISO 286-1:2010): nominal sizes over 0 up to and including 500 mm, in the
main size bands (a size on a band's upper edge belongs to that band: 18 mm is in "over 10 up to
18"); shafts d, e, f, g, h, js (grades IT4 to IT11), k, m, n, p (IT4 to IT11); holes D, E, F, G,
H, JS (IT4 to IT11), K, M, N (IT5 to IT8) and P (IT5 to IT7), the grades where the standard's
rule ``ES = -ei + Δ`` holds. Classes outside it raise :class:`CalcError`.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from ..core.errors import CalcError, listing, as_found
from ..core.units import Q_, as_kind, sig, ureg

#: Upper edge [mm] of each main size band of ISO 286-1 ("over the previous edge up to and
#: including this one"), the rows of the tables below.
SIZE_BANDS_MM = (3, 6, 10, 18, 30, 50, 80, 120, 180, 250, 315, 400, 500)

#: Standard tolerances IT3 to IT11 [µm] per size band (ISO 286-1:2010, standard tolerance
#: grades). IT3 enters only through Δ = IT4 − IT3.
STANDARD_TOLERANCES_UM = {
    3: (2, 2.5, 2.5, 3, 4, 4, 5, 6, 8, 10, 12, 13, 15),
    4: (3, 4, 4, 5, 6, 7, 8, 10, 12, 14, 16, 18, 20),
    5: (4, 5, 6, 8, 9, 11, 13, 15, 18, 20, 23, 25, 27),
    6: (6, 8, 9, 11, 13, 16, 19, 22, 25, 29, 32, 36, 40),
    7: (10, 12, 15, 18, 21, 25, 30, 35, 40, 46, 52, 57, 63),
    8: (14, 18, 22, 27, 33, 39, 46, 54, 63, 72, 81, 89, 97),
    9: (25, 30, 36, 43, 52, 62, 74, 87, 100, 115, 130, 140, 155),
    10: (40, 48, 58, 70, 84, 100, 120, 140, 160, 185, 210, 230, 250),
    11: (60, 75, 90, 110, 130, 160, 190, 220, 250, 290, 320, 360, 400),
}

#: Fundamental deviations of shafts [µm] per size band (ISO 286-1:2010): the upper deviation
#: ``es`` for d to h, the lower deviation ``ei`` for k to p. k's values hold for IT4 to IT7
#: only; its other grades have ``ei = 0``.
SHAFT_DEVIATIONS_UM = {
    "d": (-20, -30, -40, -50, -65, -80, -100, -120, -145, -170, -190, -210, -230),
    "e": (-14, -20, -25, -32, -40, -50, -60, -72, -85, -100, -110, -125, -135),
    "f": (-6, -10, -13, -16, -20, -25, -30, -36, -43, -50, -56, -62, -68),
    "g": (-2, -4, -5, -6, -7, -9, -10, -12, -14, -15, -17, -18, -20),
    "h": (0,) * 13,
    "k": (0, 1, 1, 1, 2, 2, 2, 3, 3, 4, 4, 4, 5),
    "m": (2, 4, 6, 7, 8, 9, 11, 13, 15, 17, 20, 21, 23),
    "n": (4, 8, 10, 12, 15, 17, 20, 23, 27, 31, 34, 37, 40),
    "p": (6, 12, 15, 18, 22, 26, 32, 37, 43, 50, 56, 62, 68),
}
_UPPER_DEVIATION_SHAFTS = "defgh"  # the table gives es; for the others it gives ei
_K_GRADES = range(4, 8)

#: Grades this module covers, per letter (shafts lower case, holes upper case).
GRADES = {
    **{letter: range(4, 12) for letter in (*SHAFT_DEVIATIONS_UM, "js")},
    **{letter.upper(): range(4, 12) for letter in (*_UPPER_DEVIATION_SHAFTS, "js")},
    "K": range(5, 9),
    "M": range(5, 9),
    "N": range(5, 9),
    "P": range(5, 8),
}

#: The standard's one exception in this range: M6 over 250 up to 315 mm has ES = −9 µm
#: (the rule gives −11 µm). Key: (class, index of the size band).
EXCEPTIONS_UM = {("M6", 10): -9}

_CLASS = re.compile(r"^(?P<letter>[A-Za-z]{1,2})(?P<grade>\d{1,2})$")


def _band(size_mm: np.ndarray, where: str) -> np.ndarray:
    if np.any(~(size_mm > 0)) or np.any(size_mm > SIZE_BANDS_MM[-1]):
        bad = size_mm[(~(size_mm > 0)) | (size_mm > SIZE_BANDS_MM[-1])].flat[0]
        raise CalcError(f"{where}: expected a nominal size over 0 up to 500 mm (the ISO 286 tables here), found "
                        f"{sig(bad)} mm")
    return np.searchsorted(SIZE_BANDS_MM, size_mm, side="left")


def _it(grade: int, band: np.ndarray) -> np.ndarray:
    return np.asarray(STANDARD_TOLERANCES_UM[grade], dtype=float)[band]


def _half_it(grade: int, band: np.ndarray) -> np.ndarray:
    """js/JS: ±IT/2; from IT7 on an odd IT is first rounded down to even, so the limits are
    whole micrometres (ISO 286-1, js and JS)."""
    it = _it(grade, band)
    return (it - np.mod(it, 2) if grade >= 7 else it) / 2


def split_class(tolerance_class: str, where: str = "tolerance class") -> tuple[str, int]:
    """``"k6"`` → ``("k", 6)``, checked against the classes this module covers.

    Parameters
    ----------
    tolerance_class : str
        Such as ``"k6"`` or ``"H7"``.
    where : str
        The key, for error messages; default ``"tolerance class"``.

    Returns
    -------
    tuple of (str, int)
        The letter(s) and the grade.

    Examples
    --------
    >>> split_class("k6"), split_class("H7")
    (('k', 6), ('H', 7))
    """
    m = _CLASS.match(tolerance_class.strip()) if isinstance(tolerance_class, str) else None
    if not m:
        raise CalcError(f"{where}: expected an ISO 286 tolerance class such as 'k6' or 'H7', found "
                        f"{as_found(tolerance_class)}")
    letter, grade = m.group("letter"), int(m.group("grade"))
    if letter not in GRADES:
        raise CalcError(
            f"{where}: unknown ISO 286 tolerance class {as_found(tolerance_class)}; known are shafts "
            f"{listing(k for k in GRADES if k.islower())} and holes {listing(k for k in GRADES if not k.islower())}"
        )
    if grade not in GRADES[letter]:
        span = GRADES[letter]
        raise CalcError(
            f"{where}: the tolerance class {as_found(tolerance_class)} has grade IT{grade}; for {letter} the "
            "tables here "
            f"cover IT{span.start} to IT{span.stop - 1}"
        )
    return letter, grade


def limit_deviations(nominal, tolerance_class: str, where: str = "tolerance class"):
    """Lower and upper limit deviation of an ISO 286 tolerance class at a nominal size.

    Shafts (lower-case letter): ``es`` from the table for d to h and ``ei = es − IT``; ``ei``
    from the table for k to p and ``es = ei + IT``; js is ``±IT/2``. Holes (upper case): A to H
    mirror the shafts, ``EI = −es``; K, M, N (to IT8) and P (to IT7) follow
    ``ES = −ei + Δ`` with ``Δ = IT_n − IT_(n−1)`` (0 up to 3 mm); JS is ``±IT/2``.

    Parameters
    ----------
    nominal : pint.Quantity [mm]
        Nominal size, scalar or array, over 0 up to 500 mm.
    tolerance_class : str
        Such as ``"k6"`` (shaft) or ``"H7"`` (hole).
    where : str
        The key, for error messages; default ``"tolerance class"``.

    Returns
    -------
    (Quantity, Quantity) [µm]
        Lower deviation (ei or EI) and upper deviation (es or ES).

    References
    ----------
    ISO 286-1:2010, tables of standard tolerances and fundamental deviations; limits checked
    against ISO 286-2 in ``tests/domain/test_fits.py``.

    Examples
    --------
    The motor shaft of the source's safety-coupling example, 19 mm k6 (over 18 up to 30 mm):

    >>> lower, upper = limit_deviations(Q_(19, "mm"), "k6")
    >>> float(lower.m_as("um")), float(upper.m_as("um"))
    (2.0, 15.0)
    """
    letter, grade = split_class(tolerance_class, where)
    size_mm = np.asarray(as_kind(nominal, "length", where).m_as("mm"), dtype=float)
    band = _band(size_mm, where)
    it = _it(grade, band)
    if letter.lower() == "js":
        half = _half_it(grade, band)
        lower, upper = -half, half
    elif letter.islower():
        dev = np.asarray(SHAFT_DEVIATIONS_UM[letter], dtype=float)[band]
        if letter == "k" and grade not in _K_GRADES:
            dev = np.zeros_like(dev)
        lower, upper = (dev - it, dev) if letter in _UPPER_DEVIATION_SHAFTS else (dev, dev + it)
    elif letter.lower() in _UPPER_DEVIATION_SHAFTS:
        ei = -np.asarray(SHAFT_DEVIATIONS_UM[letter.lower()], dtype=float)[band]
        lower, upper = ei, ei + it
    else:
        delta = np.where(band == 0, 0.0, it - _it(grade - 1, band))
        es = -np.asarray(SHAFT_DEVIATIONS_UM[letter.lower()], dtype=float)[band] + delta
        for (cls, b), value in EXCEPTIONS_UM.items():
            if cls == f"{letter}{grade}":
                es = np.where(band == b, value, es)
        lower, upper = es - it, es
    return Q_(lower, "um"), Q_(upper, "um")


@dataclass(frozen=True)
class Bore:
    """A shaft (or bore) as ordered: nominal size, tolerance, limits and keyway.

    Parameters
    ----------
    text : str
        The order text (``14 mm k6``).
    nominal : pint.Quantity [mm or in]
        The nominal size, in the text's unit.
    tolerance : str or None
        The ISO class (``"k6"``) or the limits as written (``'+0/-.0005"'``); None when the text
        gives none.
    member : str or None
        ``"shaft"`` for a lower-case ISO class, ``"hole"`` for an upper-case one, None for written
        limits.
    lower, upper : pint.Quantity [mm or in] or None
        The limits of size; None without a tolerance.
    keyway : pint.Quantity [mm or in] or None
        The keyway's width; None without one.
    """

    text: str
    nominal: object
    tolerance: str | None
    member: str | None
    lower: object
    upper: object
    keyway: object

    @property
    def unit(self) -> str:
        """The unit the text is written in (``mm``, ``in``), for showing limits the same way."""
        return "in" if self.nominal.units == ureg.inch else f"{self.nominal.units:~}"

    def limits_text(self) -> str:
        """``19.002 / 19.015 mm``: the smallest and largest size, in the text's unit.

        Returns
        -------
        str
            The limits as text.
        """
        if self.lower is None:
            return "no tolerance given"
        digits = 4 if self.unit == "in" else 3
        return f"{self.lower.m_as(self.unit):.{digits}f} / {self.upper.m_as(self.unit):.{digits}f} {self.unit}"


_NUM = r"(?:\d+(?:\.\d*)?|\.\d+)"
_UNIT = r'(?:"|(?!x\b)[A-Za-z]+)'  # "x" is the keyway's "by", never a unit
_DEV = rf"(?:[-+]\s*{_NUM}|0+(?:\.0*)?)"  # a limit deviation: signed, or a bare zero
_BORE = re.compile(
    rf"""^\s*(?P<size>{_NUM})\s*(?P<unit>{_UNIT})
    (?P<tol>
        \s+(?P<cls>[A-Za-z]{{1,2}}\d{{1,2}})(?![\w/])
      | \s*(?:\+\s*/\s*-|±)\s*(?P<sym>{_NUM})\s*(?P<sym_unit>{_UNIT})?
      | \s*(?P<dev1>{_DEV})\s*(?P<dev1_unit>{_UNIT})?\s*/\s*(?P<dev2>{_DEV})\s*(?P<dev2_unit>{_UNIT})?
    )?
    (?:\s*,?\s*(?:x\s+)?(?P<keyway>\d+\s*/\s*\d+|{_NUM})\s*(?P<keyway_unit>{_UNIT})\s+keyway)?
    \s*$""",
    re.VERBOSE,
)

_EXAMPLES = "\"14 mm k6\", '1.00\" +0/-.0005\"' or '.500\" +/- .0005\"', optionally with ', x 1/8\" keyway'"


def _length_unit(text: str, where: str, found: str):
    if text == '"':
        return ureg.inch
    try:
        units = ureg.parse_units(text)
    except Exception:  # pint raises several types for an unknown unit
        raise CalcError(f"{where}: the unit {as_found(text)} in {as_found(found)} is not one the unit registry "
                        "knows") from None
    if not ureg.Quantity(1, units).check("[length]"):
        raise CalcError(f"{where}: expected a length unit such as mm or in, found {as_found(text)} in "
                        f"{as_found(found)}")
    return units


def _number(text: str, where: str, found: str) -> float:
    """A decimal or a fraction (``1/8``) of a bore notation."""
    text = re.sub(r"\s+", "", text)
    try:
        return float(Fraction(text)) if "/" in text else float(text)
    except ZeroDivisionError:
        raise CalcError(
            f"{where}: expected a fraction with a denominator above zero, found {as_found(text)} in {as_found(found)}"
        ) from None


def _spaced(text: str) -> str:
    return re.sub(r"\s+", " ", text.strip())


def _with_unit(number: str, unit: str) -> str:
    number = re.sub(r"\s+", "", number)
    return f"{number}{unit}" if unit == '"' else f"{number} {unit}"


def parse_bore(text, where: str = "bore") -> Bore:
    """Read a shaft as the source's ordering examples write it.

    Accepted: a size with a length unit (``"`` is the inch), then optionally an ISO 286 class
    (``14 mm k6``, ``32 mm H7``), symmetric limits (``.500" +/- .0005"``) or two limits
    (``1.00" +0/-.0005"``; a limit without a unit takes the size's), then optionally a keyway
    (``, x 1/8" keyway``). Read by one regular expression; never evaluated.

    Raises :class:`CalcError` naming ``where`` for a malformed text, an unknown unit or ISO class,
    a size outside the ISO tables, or limits that leave no tolerance.

    Parameters
    ----------
    text : str
        The order text.
    where : str
        The key, for error messages; default ``"bore"``.

    Returns
    -------
    Bore
        The shaft.

    Examples
    --------
    >>> b = parse_bore('1.00" +0/-.0005", x 1/8" keyway')
    >>> b.text, b.limits_text(), f"{b.keyway.m_as('mm'):.3f} mm"
    ('1.00" +0/-.0005", x 1/8" keyway', '0.9995 / 1.0000 in', '3.175 mm')
    >>> parse_bore("14 mm k6").limits_text()
    '14.001 / 14.012 mm'
    """
    if not isinstance(text, str):
        raise CalcError(f"{where}: expected a shaft size with its tolerance as text, such as {_EXAMPLES}, found "
                        f"{as_found(text)}")
    return _parsed_bore(text, where)


@functools.lru_cache(maxsize=512)
def _parsed_bore(text: str, where: str) -> Bore:
    """:func:`parse_bore` of a text, kept (a :class:`Bore` is frozen; a review reads the same shafts
    at every change)."""
    m = _BORE.match(text)
    if not m:
        raise CalcError(f"{where}: expected a shaft size with its tolerance such as {_EXAMPLES}, found "
                        f"{as_found(text)}")
    unit = _length_unit(m.group("unit"), where, text)
    nominal = Q_(float(m.group("size")), unit)
    if not nominal.magnitude > 0:
        raise CalcError(f"{where}: expected a shaft size above zero, found {as_found(text)}")
    size_text = _with_unit(m.group("size"), m.group("unit"))
    tolerance = member = lower = upper = None
    if m.group("cls"):
        tolerance = m.group("cls")
        low_dev, up_dev = limit_deviations(nominal, tolerance, f"{where} ({text!r})")
        member = "shaft" if tolerance[0].islower() else "hole"
        lower, upper = (nominal + low_dev).to(unit), (nominal + up_dev).to(unit)
    elif m.group("tol"):
        tolerance = _spaced(m.group("tol"))
        if m.group("sym"):
            dev = Q_(_number(m.group("sym"), where, text),
                     _length_unit(m.group("sym_unit") or m.group("unit"), where, text))
            devs = (-dev, dev)
        else:
            devs = tuple(
                Q_(_number(m.group(key), where, text),
                   _length_unit(m.group(f"{key}_unit") or m.group("unit"), where, text)) for key in ("dev1", "dev2")
            )
        lower, upper = sorted((nominal + d).to(unit) for d in devs)
        if not upper > lower:
            raise CalcError(f"{where}: the limits in {as_found(text)} leave no tolerance; expected an upper "
                            "limit above the "
                            "lower one")
    keyway = None
    order_text = size_text + (f" {tolerance}" if tolerance else "")
    if m.group("keyway"):
        keyway = Q_(_number(m.group("keyway"), where, text), _length_unit(m.group("keyway_unit"), where, text))
        if not keyway.magnitude > 0:
            raise CalcError(f"{where}: expected a keyway width above zero, found {as_found(text)}")
        order_text += f", x {_with_unit(m.group('keyway'), m.group('keyway_unit'))} keyway"
    return Bore(order_text, nominal, tolerance, member, lower, upper, keyway)
