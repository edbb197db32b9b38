"""Factor tables looked up by the band a value falls in: the shock factor (E4), the temperature
factor (E9).

The source prints both tables with open bands (``1000 < Zh < 1500``, ``50°C - 70°C``) that leave
each boundary undefined or in two rows; the errata read both the same way: a band runs from its
lowest value (included) to the next band's (excluded), so the higher factor applies at a boundary.
:class:`BandTable` holds that rule once, with the boundary tolerance of :mod:`calc.checks`, for the
lookup, the plots and the report's band text.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .checks import BOUNDARY_RTOL
from .errors import CalcError
from .units import as_kind, pretty_unit, sig


@dataclass(frozen=True)
class BandTable:
    """A factor for each band of a value, the higher factor at a boundary.

    Parameters
    ----------
    symbol : str
        The looked-up value's symbol, as in the band text (``Z_h``); also valid LaTeX.
    lower : tuple of float
        The lowest value of each band in ``unit``, ascending; the first may be ``-inf``.
    values : tuple of float
        The factor of each band.
    unit : str
        The unit of ``lower`` and ``top``.
    kind : str
        The kind a looked-up quantity must have (:func:`calc.units.as_kind`).
    source : str
        Where the table comes from.
    top : float
        The highest value the last band covers (included); ``inf`` for an open last band.

    Notes
    -----
    A value within :data:`calc.checks.BOUNDARY_RTOL` below a boundary counts as on it: sums and
    unit conversions carry rounding (a cycle of 2.4000000000000004 s gives 1499.9999999999998
    cycles per hour, which is 1500). A value outside ``lower[0]`` to ``top`` is refused.

    Examples
    --------
    >>> from calc import Q_
    >>> t = BandTable("Z_h", (0, 1000, 1500), (1.0, 1.1, 1.3), "1/h", "per_hour", "an example")
    >>> t.lookup(Q_([999, 1000, 1499.9999999999998, 1e6], "1/h")).tolist()
    [1.0, 1.1, 1.3, 1.3]
    >>> t.text(int(t.band(Q_(1200, "1/h"))))
    '1000 <= Z_h < 1500 1/h'
    """

    symbol: str
    lower: tuple
    values: tuple
    unit: str
    kind: str
    source: str
    top: float = math.inf

    def __post_init__(self):
        lower = np.asarray(self.lower, dtype=float)
        if lower.ndim != 1 or len(lower) == 0 or len(self.values) != len(lower):
            raise CalcError(f"{self.source}: expected one factor per band, found {len(self.values)} factors for {len(lower)} bands")
        if not (np.all(np.diff(lower) > 0) and self.top > lower[-1]):
            raise CalcError(f"{self.source}: expected band bounds that rise, found {', '.join(map(sig, lower))} up to {sig(self.top)}")

    def __len__(self) -> int:
        """The number of bands."""
        return len(self.lower)

    @property
    def bounds(self) -> np.ndarray:
        """The lowest value of each band, as a float array."""
        return np.asarray(self.lower, dtype=float)

    @property
    def factors(self) -> np.ndarray:
        """The factor of each band, as a float array."""
        return np.asarray(self.values, dtype=float)

    def band(self, value, where: str = "value"):
        """Index of the band of each value (a quantity of :attr:`kind`, scalar or array).

        Raises :class:`CalcError` naming ``where`` for a value of another kind or outside the
        table, ``lower[0]`` to ``top``.
        """
        x = as_kind(value, self.kind, where).m_as(self.unit)
        shifted = x + np.abs(x) * BOUNDARY_RTOL  # just below a boundary is on it
        outside = (shifted < self.bounds[0]) | (x - np.abs(x) * BOUNDARY_RTOL > self.top)
        if np.any(outside):
            bad = np.asarray(x)[outside] if np.ndim(x) else x
            raise CalcError(f"{where}: expected {self.range_text()} ({self.source}), found {sig(np.ravel(bad)[0])} {pretty_unit(self.unit)}")
        return np.searchsorted(self.bounds, shifted, side="right") - 1

    def lookup(self, value, where: str = "value"):
        """The factor of each value (scalar or array), the higher one at a boundary."""
        return self.factors[self.band(value, where)]

    def text(self, k: int, latex: bool = False) -> str:
        """Band ``k`` as a reader writes it, ``1500 <= Z_h < 2000 1/h``; with ``latex``, for math
        mode (``\\le``, ``\\ge``, the unit as text)."""
        le, ge = (r"\le", r"\ge") if latex else ("<=", ">=")
        low, last = self.bounds[k], k + 1 == len(self)
        high = self.top if last else self.bounds[k + 1]
        if not last:
            band = f"{self.symbol} < {sig(high)}" if math.isinf(low) else f"{sig(low)} {le} {self.symbol} < {sig(high)}"
        elif math.isinf(high):
            band = f"{self.symbol} {ge} {sig(low)}"
        else:
            band = f"{sig(low)} {le} {self.symbol} {le} {sig(high)}"
        unit = pretty_unit(self.unit)
        return rf"{band}\ \text{{{unit}}}" if latex else f"{band} {unit}"

    def range_text(self) -> str:
        """The values the table covers, ``Z_h >= 0 1/h`` or ``T <= 120 °C``."""
        low, high = self.bounds[0], self.top
        unit = pretty_unit(self.unit)
        if math.isinf(low):
            return f"{self.symbol} <= {sig(high)} {unit}"
        if math.isinf(high):
            return f"{self.symbol} >= {sig(low)} {unit}"
        return f"{sig(low)} <= {self.symbol} <= {sig(high)} {unit}"
