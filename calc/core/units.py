"""The package's one unit registry, and the checks that guard its traps.

pint treats angles as dimensionless (errata E15). So a torque converts silently to a torsional
stiffness (``"0.24 N*m"`` to N·m/arcmin), a bare number converts to an angle (read as radians) and
``"300 rpm"`` converts to 31.4 Hz. Every input therefore declares a :class:`Kind`: its
dimensionality *and* the power of angle its unit must carry, and :func:`as_kind` checks both.
"""

from __future__ import annotations

import functools
import math
import os
import re
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pint

from .errors import CalcError, as_found


def _cache_folder():
    """Where pint keeps its parsed unit definitions: in this Python environment, so that the
    cache goes with it. A cache shared by every environment (pint's ":auto:", the user's cache
    folder) records the definition files of the environment that wrote it, and breaks every other
    once that one is deleted. None (no cache) where the environment is not writable."""
    folder = Path(sys.prefix) / "pint-cache"
    return folder if os.access(folder if folder.exists() else sys.prefix, os.W_OK) else None


ureg = pint.UnitRegistry(cache_folder=_cache_folder())
ureg.define("@alias revolution = rev")  # "rev/s" and "rev/min" as speed units engineers write
ureg.formatter.default_format = "~P"
ureg.formatter.default_sort_func = None  # units in the order written: "N·m", not pint's alphabetical "m·N"
pint.set_application_registry(ureg)
Q_ = ureg.Quantity
# pint keeps a parsed unit text only where the text is one unit's name: "N*m" or "kg*cm**2" is parsed
# again at every conversion (a fifth of a design review's change). The registry's units are fixed
# once defined above, so each text's parse is kept (the same container pint would give).
ureg._parse_units_as_container = functools.lru_cache(maxsize=4096)(ureg._parse_units_as_container)


@functools.cache
def unit(text: str) -> pint.Unit:
    """The registry's unit for one of the package's unit strings (``"N*m"``), parsed once.

    Parameters
    ----------
    text : str
        A unit as the package writes it (``"kg*cm**2"``).

    Returns
    -------
    pint.Unit
        The unit of the package's one registry.
    """
    return ureg.Unit(text)

#: A number and the unit text after it, as case files and catalogs write a quantity.
NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


@dataclass(frozen=True)
class Kind:
    """What an input must be: a dimensionality, the power of angle its unit carries, a unit to
    compute in (coherent SI, angles in radians) and an example for error messages.

    Parameters
    ----------
    name : str
        The kind's name (``"torque"``), as the checks name it.
    dimensionality : str
        Its pint dimensionality (``"[mass] * [length] ** 2 / [time] ** 2"``).
    angle : int
        The power of angle its unit carries (1 for a speed in rpm, -1 for a stiffness per arcmin).
    si_unit : str
        The unit to compute in: coherent SI, angles in radians (empty for a bare number).
    example : str
        A value of the kind for error messages (``"12 N*m"``).
    """

    name: str
    dimensionality: str
    angle: int
    si_unit: str
    example: str

    def accepts(self, units) -> bool:
        """Whether a unit measures this kind: the same dimensionality and power of angle.

        Parameters
        ----------
        units : pint.Unit or str
            The unit to check.

        Returns
        -------
        bool
            True when a quantity in ``units`` is of this kind.
        """
        return _signature(_container(units)) == _signature(_container(self.si_unit))


def _container(units):
    """pint's hashable container of a unit: the cache key of the checks and conversions below.
    (A quantity's ``.units`` builds a new Unit object at every access; ``._units`` is the container.)"""
    if isinstance(units, str):
        return unit(units)._units
    return getattr(units, "_units", units)


@functools.lru_cache(maxsize=512)
def _signature(units) -> tuple:
    """Dimensionality and angle power of a unit (cached: a unit is checked once per process)."""
    return ureg.Quantity(1, units).dimensionality, angle_power(units)


def angle_power(units) -> float:
    """The power of angle a unit carries, read from its root units (rpm → 1, N·m/arcmin → −1).

    Not rounded: the square root of a stiffness over an inertia carries rad^-1/2, which is no
    frequency (E15).

    Parameters
    ----------
    units : pint.Unit or str
        The unit.

    Returns
    -------
    float
        The exponent of the radian in the unit's root units [1].
    """
    _, root = ureg.get_root_units(units)
    return float(root._units.get("radian", 0))


def declared_once(items: tuple, what: str) -> dict:
    """Declarations by their ``name``; a name given twice raises (a dict would keep the last silently).

    Parameters
    ----------
    items : tuple
        Objects with a ``name``.
    what : str
        What they are, for the message (``"kind"``).

    Returns
    -------
    dict
        Each item by its name, in the order given.
    """
    out = {}
    for item in items:
        if item.name in out:
            raise ValueError(f"calc.core: the {what} {item.name!r} is declared twice")
        out[item.name] = item
    return out


#: Every kind by its name, each declared once.
KINDS: dict[str, Kind] = declared_once((
    Kind("time", "[time]", 0, "s", '"0.2 s"'),
    Kind("speed", "1/[time]", 1, "rad/s", '"300 rpm"'),
    Kind("angular_acceleration", "1/[time]**2", 1, "rad/s**2", '"60 rad/s**2"'),
    Kind("frequency", "1/[time]", 0, "Hz", '"40 Hz"'),
    Kind("torque", "[mass]*[length]**2/[time]**2", 0, "N*m", '"12 N*m"'),
    Kind("inertia", "[mass]*[length]**2", 0, "kg*m**2", '"1.2 kg*cm**2"'),
    Kind("stiffness", "[mass]*[length]**2/[time]**2", -1, "N*m/rad", '"1.3 N*m/arcmin"'),
    Kind("angle", "", 1, "rad", '"3 arcmin"'),
    Kind("length", "[length]", 0, "m", '"14 mm"'),
    Kind("dimensionless", "", 0, "", "10"),
    Kind("per_hour", "1/[time]", 0, "1/s", '"1800 1/hour"'),
    Kind("temperature", "[temperature]", 0, "K", '"60 degC"'),
    Kind("stiffness_length", "[mass]*[length]**3/[time]**2", -1, "N*m**2/rad", '"20230 N*m**2/rad"'),
    Kind("mass", "[mass]", 0, "kg", '"50 kg"'),
    Kind("force", "[mass]*[length]/[time]**2", 0, "N", '"100 N"'),
    Kind("linear_speed", "[length]/[time]", 0, "m/s", '"0.5 m/s"'),
    Kind("linear_acceleration", "[length]/[time]**2", 0, "m/s**2", '"9.80665 m/s**2"'),
    Kind("linear_stiffness", "[mass]/[time]**2", 0, "N/m", '"200 N/mm"'),
    Kind("density", "[mass]/[length]**3", 0, "kg/m**3", '"7850 kg/m**3"'),
    Kind("power", "[mass]*[length]**2/[time]**3", 0, "W", '"400 W"'),
    Kind("energy", "[mass]*[length]**2/[time]**2", 0, "J", '"60 J"'),
    Kind("voltage", "[mass]*[length]**2/[time]**3/[current]", 0, "V", '"565 V"'),
    Kind("current", "[current]", 0, "A", '"5.7 A"'),
    Kind("resistance", "[mass]*[length]**2/[time]**3/[current]**2", 0, "ohm", '"0.61 ohm"'),
    Kind("capacitance", "[current]**2*[time]**4/[mass]/[length]**2", 0, "F", '"940 uF"'),
    Kind("inductance", "[mass]*[length]**2/[time]**2/[current]**2", 0, "H", '"4.2 mH"'),
    Kind("torque_constant", "[mass]*[length]**2/[time]**2/[current]", 0, "N*m/A", '"0.88 N*m/A"'),
    Kind("voltage_constant", "[mass]*[length]**2/[time]**2/[current]", -1, "V*s/rad", '"57 V/krpm"'),
), "kind")


def kind(name: str | Kind) -> Kind:
    """The kind of a name (``"torque"``), or the kind itself.

    Parameters
    ----------
    name : str or Kind
        A kind's name, or a kind.

    Returns
    -------
    Kind
        The package's kind of that name.
    """
    return name if isinstance(name, Kind) else KINDS[name]


def describe_units(units) -> str:
    """Name what a unit measures, for error messages ("a torque", "a bare number", ...).

    Parameters
    ----------
    units : pint.Unit or str
        The unit.

    Returns
    -------
    str
        The kind it measures with its article, or its dimensionality where no kind has it.
    """
    if units == ureg.dimensionless or str(units) == "":
        return "a bare number"
    for k in KINDS.values():
        if k.name not in ("dimensionless", "per_hour") and k.accepts(units):
            return f"{_article(k.name)} {k.name}"
    return f"a quantity of dimension {ureg.Quantity(1, units).dimensionality} with angle power {angle_power(units)}"


def _article(word: str) -> str:
    return "an" if word[0] in "aeiou" else "a"


def kind_phrase(expected: str | Kind) -> str:
    """A kind as a phrase of an error message: ``"a torque"``, ``"an inertia"``.

    Parameters
    ----------
    expected : str or Kind
        The kind, or its name.

    Returns
    -------
    str
        Its name with the article.
    """
    name = kind(expected).name
    return f"{_article(name)} {name}"


#: Largest and smallest (non-zero) magnitude in SI units that an input may have. Every quantity of
#: a drive train lies orders of magnitude inside (a torque of 10⁶ N·m, an inertia of 10⁻⁷ kg·m², an
#: angle of 10⁻⁶ rad); outside, a formula could overflow (a torque of 10¹⁰³ N·m cubed, 3600 s / 10⁻³⁰⁸ s)
#: far from the key that caused it, so the key is named here instead.
SI_SCALE = (1e-12, 1e12)


def _in_scale(quantity: pint.Quantity, where: str, found) -> pint.Quantity:
    """``quantity`` if its magnitude is finite and within :data:`SI_SCALE` in SI units (or zero)."""
    low, high = SI_SCALE
    value = quantity.magnitude
    si = abs(quantity.to_base_units().magnitude) if math.isfinite(value) else math.inf
    if not math.isfinite(si):
        raise CalcError(f"{where}: expected a finite number, found {as_found(found)}")
    if si != 0 and not low <= si <= high:
        raise CalcError(
            f"{where}: expected a magnitude between {low:g} and {high:g} in SI units "
            f"({quantity.to_base_units().units:~P}), "
            f"found {as_found(found)}, which is {si:.3g}"
        )
    return quantity


def parse_quantity(text, expected: str | Kind, where: str) -> pint.Quantity:
    """Parse a case-file or catalog value such as ``"12 N*m"`` and check its kind.

    The number and the unit are split by a regular expression and the unit is parsed by the
    registry's own unit parser; nothing is evaluated as code. Offset units (``"60 degC"``) are
    built as a quantity of that temperature, not multiplied.

    Parameters
    ----------
    text : str or number
        The value as written (a bare number only for a dimensionless kind).
    expected : str or Kind
        The kind it must be.
    where : str
        The file and key, for error messages.

    Returns
    -------
    pint.Quantity [the unit written]
        The value in the unit it was written in.

    Raises
    ------
    CalcError
        For text that is no number with a unit, an unknown unit or a unit of another kind, naming
        ``where``.
    """
    k = kind(expected)
    if isinstance(text, bool):
        raise CalcError(f"{where}: expected {_article(k.name)} {k.name} such as {k.example}, found {as_found(text)}")
    if isinstance(text, (int, float)):
        if k.name == "dimensionless":
            return _in_scale(ureg.Quantity(float(text), ""), where, text)
        raise CalcError(
            f"{where}: expected {_article(k.name)} {k.name} with its unit such as {k.example}, found the bare number "
            f"{as_found(text)}"
        )
    if not isinstance(text, str):
        raise CalcError(f"{where}: expected {_article(k.name)} {k.name} such as {k.example}, found {as_found(text)}")
    match = NUMBER.match(text)
    if not match:
        raise CalcError(f"{where}: expected a number followed by a unit such as {k.example}, found {as_found(text)}")
    number, unit_text = match.groups()
    try:
        units = ureg.parse_units(unit_text) if unit_text else ureg.dimensionless
    except Exception as exc:  # pint's parser raises many types for malformed text, AssertionError among them
        raise CalcError(f"{where}: the unit {as_found(unit_text)} in {as_found(text)} is not one the unit "
                        "registry knows "
                        f"({type(exc).__name__})") from None
    quantity = ureg.Quantity(float(number), units)
    return _in_scale(as_kind(quantity, k, where, found=text), where, text)


def as_kind(value, expected: str | Kind, where: str, found: str | None = None) -> pint.Quantity:
    """Check that ``value`` is a quantity of the expected kind; return it unchanged.

    A bare number is accepted only for dimensionless kinds; anything else raises
    :class:`CalcError` naming ``where``.

    Parameters
    ----------
    value : pint.Quantity [any unit] or number
        The value to check.
    expected : str or Kind
        The kind it must be.
    where : str
        The argument or key, for error messages.
    found : str, optional
        What the message says was found, in place of the value itself.

    Returns
    -------
    pint.Quantity [the unit given]
        ``value`` (a bare number as a dimensionless quantity).
    """
    k = kind(expected)
    if not isinstance(value, pint.Quantity):
        bare = isinstance(value, (int, float, np.ndarray, np.number)) and not isinstance(value, bool)
        if k.name == "dimensionless" and bare:
            return ureg.Quantity(np.asarray(value, dtype=float) if isinstance(value, np.ndarray) else float(value), "")
        raise CalcError(
            f"{where}: expected {_article(k.name)} {k.name} as a quantity with a unit such as {k.example}, found "
            f"{type(value).__name__} {as_found(value)}"
        )
    if value._REGISTRY is not ureg:
        raise CalcError(f"{where}: the quantity {value} was made with another unit registry; use calc.ureg or calc.Q_")
    if not k.accepts(value._units):
        shown = found if found is not None else f"{value:~P}"
        what = describe_units(value.units)
        hint = ""
        same_dimension = value.dimensionality == ureg.Quantity(1, k.si_unit).dimensionality
        if k.angle and angle_power(value.units) != k.angle and same_dimension:
            hint = " (its unit must carry the angle, errata E15)"
        raise CalcError(f"{where}: expected {_article(k.name)} {k.name} such as {k.example}, found "
                        f"{as_found(shown)}, which is "
                        f"{what}{hint}")
    return value


def to_si(value, expected: str | Kind, where: str):
    """Magnitude of a checked quantity in the kind's coherent SI unit (float or array).

    The check of :func:`as_kind` and pint's conversion (the magnitude times pint's factor), with
    the factor looked up once per unit.

    Parameters
    ----------
    value : pint.Quantity [any unit]
        The quantity, scalar or array.
    expected : str or Kind
        The kind it must be.
    where : str
        The argument or key, for error messages.

    Returns
    -------
    float or numpy.ndarray [the kind's SI unit]
        Its magnitude in the kind's SI unit (radians for angles).

    Examples
    --------
    >>> to_si(Q_(300, "rpm"), "speed", "n"), to_si(Q_(2, "kg*m**2"), "inertia", "J")
    (31.41592653589793, 2)
    """
    k = kind(expected)
    if not (isinstance(value, pint.Quantity) and value._REGISTRY is ureg and k.accepts(value._units)):
        value = as_kind(value, k, where)  # the error, or a bare number where the kind is dimensionless
    return magnitude_in(value, k.si_unit)


def magnitude_in(q: pint.Quantity, unit_text: str):
    """``q.m_as(unit_text)`` with pint's conversion factor looked up once per pair of units.

    Parameters
    ----------
    q : pint.Quantity [any unit]
        The quantity, scalar or array.
    unit_text : str
        The unit wanted (``"rev/s"``).

    Returns
    -------
    float or numpy.ndarray [unit_text]
        Its magnitude in ``unit_text``.

    Examples
    --------
    >>> magnitude_in(Q_(3000, "rpm"), "rev/s")
    50.0
    """
    factor = _factor(q._units, _container(unit_text))
    if factor is None:
        return q.m_as(unit_text)  # an offset unit (degC)
    return q.magnitude if factor == 1.0 else q.magnitude * factor


def from_si(magnitude, expected: str | Kind, unit_text: str) -> pint.Quantity:
    """A magnitude in the kind's SI unit as a quantity in ``unit_text``, converted as pint does.

    Parameters
    ----------
    magnitude : float or numpy.ndarray [the kind's SI unit]
        The value in the kind's SI unit.
    expected : str or Kind
        Its kind.
    unit_text : str
        The unit wanted.

    Returns
    -------
    pint.Quantity [unit_text]
        The value in ``unit_text``.

    Examples
    --------
    >>> from_si(31.41592653589793, "speed", "rpm")
    <Quantity(300.0, 'revolutions_per_minute')>
    """
    si, shown = unit(kind(expected).si_unit), unit(unit_text)
    factor = _factor(si._units, shown._units)
    if factor is None:
        return ureg.Quantity(magnitude, si).to(shown)
    return ureg.Quantity(magnitude if factor == 1.0 else magnitude * factor, shown)


@functools.lru_cache(maxsize=1024)
def _factor(src, dst) -> float | None:
    """pint's factor from unit ``src`` to unit ``dst`` (containers); None where the conversion has
    an offset (°C)."""
    if src == dst:
        return 1.0
    if ureg.Quantity(0.0, src).m_as(dst) != 0.0:
        return None
    return ureg.Quantity(1.0, src).m_as(dst)


def revolutions_per_second(speed) -> pint.Quantity:
    """Rotational frequency of a shaft: ``n / 60 s`` per revolution (errata E15).

    pint would turn 300 rpm into 31.4 Hz (it treats Hz as rad/s); a shaft at 300 rpm turns
    five times a second.

    Parameters
    ----------
    speed : pint.Quantity [rpm]
        The shaft's speed.

    Returns
    -------
    pint.Quantity [Hz]
        Revolutions per second.

    Examples
    --------
    >>> revolutions_per_second(Q_(300, "rpm"))
    <Quantity(5.0, 'hertz')>
    """
    n = as_kind(speed, "speed", "speed")
    return ureg.Quantity(n.m_as("rpm") / 60.0, "Hz")


def fmt(q, unit: str, digits: int = 4) -> str:
    """Format a scalar quantity in ``unit`` with ``digits`` significant figures (``21.33 N·m``).

    Parameters
    ----------
    q : pint.Quantity [any unit]
        A scalar quantity.
    unit : str
        The unit to show it in (``"N*m"``).
    digits : int
        Significant figures; default 4.

    Returns
    -------
    str
        The number (:func:`sig`) and the unit as a reader writes it (:func:`pretty_unit`).
    """
    return f"{sig(q.m_as(unit), digits)} {pretty_unit(unit)}".rstrip()


def sig(x: float, digits: int = 4) -> str:
    """A number to ``digits`` significant figures, trailing zeros dropped (``0.2``, ``35.41``).

    Parameters
    ----------
    x : float
        The number.
    digits : int
        Significant figures; default 4.

    Returns
    -------
    str
        The number as text (in exponent form where it is very small or large).

    Examples
    --------
    >>> sig(35.40764), sig(0.2), sig(2400.0), sig(1.5e-7)
    ('35.41', '0.2', '2400', '1.500e-07')
    """
    x = float(x)
    if x == 0 or not math.isfinite(x):
        return f"{x:g}"
    if 1e-4 <= abs(x) < 1e9:
        decimals = max(digits - 1 - int(math.floor(math.log10(abs(x)))), 0)
        text = f"{round(x, decimals):.{decimals}f}"
        return text.rstrip("0").rstrip(".") if "." in text else text
    return f"{x:.{digits - 1}e}"


_PRETTY = {"**2": "²", "**3": "³", "**-1": "⁻¹", "*": "·", "percent": "%", "degC": "°C", "deg": "°"}


def pretty_unit(unit: str) -> str:
    """Our own unit strings as a reader writes them: ``kg*cm**2`` → ``kg·cm²``.

    Parameters
    ----------
    unit : str
        A unit as the package writes it.

    Returns
    -------
    str
        The unit with middle dots and superscripts.
    """
    out = unit
    for a, b in _PRETTY.items():
        out = out.replace(a, b)
    return out


def latex_unit(unit: str) -> str:
    r"""Our own unit strings in LaTeX: ``N*m/arcmin`` → ``\mathrm{N\,m/arcmin}``.

    Parameters
    ----------
    unit : str
        A unit as the package writes it.

    Returns
    -------
    str
        The unit as LaTeX math.
    """
    if not unit:
        return ""
    body = unit.replace("percent", r"\%").replace("degC", r"^{\circ}C")
    body = re.sub(r"\*\*(-?\d+)", r"^{\1}", body).replace("*", r"\,")
    return r"\mathrm{" + body + "}"


def number(x, key: str = "result") -> float | None:
    """A result as a plain float; NaN (no value) becomes None, infinity is an error naming the
    result (no output holds one).

    Parameters
    ----------
    x : float
        The result's magnitude.
    key : str
        The result's name, for the error message; default ``"result"``.

    Returns
    -------
    float or None
        ``x``, or None for NaN.
    """
    x = float(x)
    if math.isnan(x):
        return None
    if math.isinf(x):
        raise CalcError(f"{key}: the calculation overflows (found {x}); check the inputs it comes from for values out "
                        "of scale")
    return x


@dataclass(frozen=True)
class Value:
    """A scalar result as every output prints it: its magnitude in the unit it is shown in, None
    where there is no value. The results hold these; the JSON writes ``{"value", "unit"}``.

    Parameters
    ----------
    value : float or None
        The magnitude in ``unit``; None where there is no value.
    unit : str
        The unit it is shown in, as the package writes it (``"N*m"``).
    """

    value: float | None
    unit: str

    @classmethod
    def of(cls, q, unit_text: str, key: str = "result") -> "Value":
        """A scalar quantity in ``unit_text`` (NaN: no value; infinity: an error naming ``key``).

        Parameters
        ----------
        q : pint.Quantity [any unit]
            A scalar quantity.
        unit_text : str
            The unit to show it in.
        key : str
            The result's name, for the error message; default ``"result"``.

        Returns
        -------
        Value
            Its magnitude in ``unit_text``.
        """
        return cls(number(magnitude_in(q, unit_text), key), unit_text)

    def to_json(self) -> dict:
        """The value as the JSON output writes it.

        Returns
        -------
        dict
            ``{"value": float or None, "unit": str}``.
        """
        return {"value": self.value, "unit": self.unit}

    @property
    def quantity(self) -> pint.Quantity:
        """The value as a quantity (NaN for no value), for a figure that plots it."""
        return Q_(math.nan if self.value is None else self.value, self.unit)

    def __str__(self) -> str:
        """As a reader writes it: ``151.3 N·m``; n/a for no value."""
        return "n/a" if self.value is None else f"{sig(self.value)} {pretty_unit(self.unit)}".rstrip()
