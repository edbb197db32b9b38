"""Checks of catalog candidates, and their ranking: what gearbox and coupling selection share.

A check holds, for every candidate at once, the required value, the rated value, the unit both are
shown in, the utilization (required / rated) and the verdict; :func:`rank` orders candidates best
first and :func:`selected_part` names the best passing one.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from .units import fmt, magnitude_in, sig

#: A value within this relative distance of a boundary (of E3, of E4, or a utilization of 1) counts
#: as on it: sums and unit conversions carry rounding (0.6 s + 0.7 s + 0.2 s = 1.4999999999999998 s,
#: an ED of 1.5 s / 2.5 s would fall just below 60 %).
BOUNDARY_RTOL = 1e-9


@dataclass(frozen=True)
class CheckArray:
    """One criterion over all candidates: required and rated values as quantity arrays, and the
    unit both are shown in."""

    name: str
    mode: str
    text: str
    required: object
    rated: object
    unit: str

    @functools.cached_property
    def utilization(self) -> np.ndarray:
        """required / rated; NaN where the catalog gives no rated value."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.asarray(magnitude_in(self.required, self.unit) / magnitude_in(self.rated, self.unit), dtype=float)

    @property
    def passes(self) -> np.ndarray:
        """utilization <= 1, where a utilization within :data:`BOUNDARY_RTOL` above 1
        is 1: 300 rpm · 10 comes back from rad/s as 3000.0000000000005 rpm, which meets 3000 rpm.
        NaN compares false: no rating, no pass."""
        return self.utilization <= 1.0 + BOUNDARY_RTOL

    def reason(self, row: int) -> str:
        """Why the row fails this check: by how much the required value exceeds the rated one."""
        u = self.utilization[row]
        if np.isnan(u):
            return f"{self.text}: not checked, the catalog gives no rated value"
        return (
            f"{self.text}: required {fmt(self.required[row], self.unit)} > rated {fmt(self.rated[row], self.unit)}, "
            f"{sig(100 * (u - 1), 3)} % over"
        )


def rank(passes, size, worst_utilization, parts, illustrative=None) -> np.ndarray:
    """Indices best first: passing first, published before illustrative rows, then smallest size
    and larger margin; failing rows after, closest to passing first (the rule of :mod:`calc.gearbox`)."""
    passes = np.asarray(passes, bool)
    worst = np.where(np.isnan(worst_utilization), np.inf, worst_utilization)
    size_key = np.where(passes, size, 0.0)
    shown_later = np.zeros(len(passes), bool) if illustrative is None else passes & np.asarray(illustrative, bool)
    keys = (worst, size_key, shown_later, ~passes)
    order = np.lexsort(keys)
    # Rows tied on every key go by part name. Names are sorted within the tied runs only: sorting
    # text costs more than all the numeric keys together, and a catalog has few ties.
    tied = np.logical_and.reduce([k[order][1:] == k[order][:-1] for k in keys])
    if tied.any():
        run = np.cumsum(np.concatenate(([True], ~tied)))
        at = np.flatnonzero(np.concatenate(([False], tied)) | np.concatenate((tied, [False])))
        rows = order[at]
        order[at] = rows[np.lexsort((np.asarray(parts)[rows].astype(str), run[at]))]
    return order


def selected_part(parts, passes, order) -> str | None:
    """The best-ranked part if it passes, else None."""
    if len(order) and passes[order[0]]:
        return str(parts[order[0]])
    return None
