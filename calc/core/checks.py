"""Checks and their ranking: what every section's checks share.

A :class:`CheckArray` holds, for every candidate at once, the required value, the rated value, the
unit both are shown in, the utilization (required / rated) and the verdict, under the one pass rule
of the package (:func:`within_rating`); :class:`Check` is one of them for one candidate, as results
list it. :func:`rank` orders candidates best first and :func:`selected_part` names the best passing
one.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

from .units import Value, fmt, magnitude_in, sig

#: A value within this relative distance of a boundary (of E3, of E4, or a utilization of 1) counts
#: as on it: sums and unit conversions carry rounding (0.6 s + 0.7 s + 0.2 s = 1.4999999999999998 s,
#: an ED of 1.5 s / 2.5 s would fall just below 60 %).
BOUNDARY_RTOL = 1e-9


def within_rating(utilization):
    """The one pass rule: utilization <= 1, where a utilization within :data:`BOUNDARY_RTOL` above
    1 is 1 (300 rpm · 10 comes back from rad/s as 3000.0000000000005 rpm, which meets 3000 rpm).
    NaN compares false: no rating, no pass.

    Parameters
    ----------
    utilization : float or numpy.ndarray [1]
        Required over rated value.

    Returns
    -------
    bool or numpy.ndarray of bool
        Whether each passes.

    Examples
    --------
    >>> within_rating(np.array([0.5, 1.0 + 1e-12, 1.001, np.nan])).tolist()
    [True, True, False, False]
    """
    return np.asarray(utilization) <= 1.0 + BOUNDARY_RTOL


@dataclass(frozen=True)
class Check:
    """One check of one candidate (or of a section's requirement), as results list it.

    ``passes`` is None when the check could not be made; ``not_made`` then says which input it
    needs. ``governs`` says whether the check decides the verdict (the other mode's checks are
    reported for information, E3).

    Parameters
    ----------
    name : str
        The rated value's symbol (``"T_2B"``).
    criterion : str
        The check as text (``"T_2max <= T_2B"``).
    required : pint.Quantity [unit] or None
        The required value, scalar; None when the check is not made.
    rated : pint.Quantity [unit]
        The rated value, scalar (NaN where the catalog gives none).
    unit : str
        The unit both are shown in.
    utilization : float or None
        Required over rated [1]; None where it cannot be computed.
    passes : bool or None
        The verdict; None when the check could not be made.
    governs : bool
        Whether it decides the verdict; default True.
    mode : str or None
        The operating mode it belongs to (``"S1"``, ``"S5"``), None for both.
    not_made : str or None
        What the check needs that the case does not give.
    at_least : bool
        The required value is a lower bound: a term of it is unknown.
    """

    name: str
    criterion: str
    required: object  # scalar quantity, or None when not made
    rated: object
    unit: str
    utilization: float | None
    passes: bool | None
    governs: bool = True
    mode: str | None = None
    not_made: str | None = None
    at_least: bool = False  # the required value is a lower bound: a term of it is unknown

    @property
    def required_value(self) -> Value | None:
        """The required value as outputs print it; None where the check is not made."""
        return None if self.required is None else Value.of(self.required, self.unit, self.name)

    @property
    def rated_value(self) -> Value:
        """The rated value as outputs print it (no value where the catalog gives none)."""
        return Value.of(self.rated, self.unit, self.name)

    def reason(self) -> str:
        """Why the check does not pass: its excess, or what it needs.

        Returns
        -------
        str
            ``criterion: required … > rated …, N % over``, or ``criterion: not checked, …``.
        """
        if self.not_made is not None:
            return f"{self.criterion}: not checked, {self.not_made}"
        if self.utilization is None:
            return f"{self.criterion}: not checked, the catalog gives no rated value"
        return (
            f"{self.criterion}: required {fmt(self.required, self.unit)} > rated {fmt(self.rated, self.unit)}, "
            f"{sig(100 * (self.utilization - 1), 3)} % over"
        )


def worst_governing(checks) -> Check | None:
    """The worst governing check: of the governing checks made, the one with the highest
    utilization (the first of equals). The one definition of "worst utilization" that the
    candidates' records, the summary of cases and the comparison of designs print.

    Parameters
    ----------
    checks : iterable of Check
        The checks of a candidate or of a section.

    Returns
    -------
    Check or None
        None where no governing check has a utilization.

    Examples
    --------
    >>> from calc.core.units import Q_
    >>> a = Check("T_2B", "T_2max <= T_2B", Q_(5, "N*m"), Q_(10, "N*m"), "N*m", 0.5, True)
    >>> b = Check("T_2N", "T_2m <= T_2N", Q_(8, "N*m"), Q_(10, "N*m"), "N*m", 0.8, True, governs=False)
    >>> worst_governing([a, b]).name
    'T_2B'
    """
    made = [k for k in checks if k.governs and k.utilization is not None]
    return max(made, key=lambda k: k.utilization) if made else None


@dataclass(frozen=True)
class CheckArray:
    """One criterion over all candidates: required and rated values as quantity arrays, and the
    unit both are shown in.

    Parameters
    ----------
    name : str
        The rated value's symbol (``"T_2B"``).
    mode : str or None
        The operating mode it belongs to (``"S1"``, ``"S5"``), None for both.
    text : str
        The check as text (``"T_2max <= T_2B"``).
    required : pint.Quantity [unit] or None
        Required values over the rows; None when the check cannot be made (see ``not_made``).
    rated : pint.Quantity [unit]
        Rated values over the rows (NaN where the catalog gives none).
    unit : str
        The unit both are shown in.
    not_made : str, optional
        What the check needs that the case does not give (keyword only).
    unrated : str, optional
        For a check whose rating a catalog may leave out (a bearing's force): what is missing; a row
        without the rating is then not checked and does not fail. None: such a row fails (keyword
        only).
    """

    name: str
    mode: str
    text: str
    required: object  # quantity array; None when the check cannot be made (see not_made)
    rated: object
    unit: str
    not_made: str | None = field(default=None, kw_only=True)  # what the check needs that the case does not give
    #: For a check whose rating a catalog may leave out (a bearing's force): what is missing, and
    #: a row without the rating is not checked and does not fail; None: such a row fails.
    unrated: str | None = field(default=None, kw_only=True)

    @property
    def made(self) -> bool:
        return self.not_made is None

    @functools.cached_property
    def utilization(self) -> np.ndarray:
        """required / rated; NaN where the catalog gives no rated value or the check is not made."""
        rated = magnitude_in(self.rated, self.unit)
        if not self.made:
            return np.full(np.shape(rated), np.nan)
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.asarray(magnitude_in(self.required, self.unit) / rated, dtype=float)

    @functools.cached_property
    def passes(self) -> np.ndarray:
        """:func:`within_rating` of each row (false where the check is not made); computed once,
        as listing candidates asks it of every row."""
        ok = within_rating(self.utilization)
        return ok | self.unrated_rows if self.made else ok

    @functools.cached_property
    def unrated_rows(self) -> np.ndarray:
        """Rows not checked for want of a rating that may be left out (:attr:`unrated`)."""
        if self.unrated is None:
            return np.zeros(np.shape(self.utilization), bool)
        return np.isnan(magnitude_in(self.rated, self.unit))

    @functools.cached_property
    def ranked_utilization(self) -> np.ndarray:
        """The utilization as ranking counts it: 0 where a row is not checked for want of a
        rating that may be left out (it neither fails nor pushes the row down)."""
        return np.where(self.unrated_rows, 0.0, self.utilization)

    def at(self, row: int, governs: bool = True) -> Check:
        """This check for one row.

        Parameters
        ----------
        row : int
            The row of the catalog.
        governs : bool
            Whether it decides the row's verdict; default True.

        Returns
        -------
        Check
            The row's required and rated value, utilization and verdict.
        """
        u = float(self.utilization[row])
        unrated = self.made and bool(self.unrated_rows[row])
        return Check(
            name=self.name,
            criterion=self.text,
            required=None if not self.made else self.required[row],
            rated=self.rated[row],
            unit=self.unit,
            utilization=None if np.isnan(u) else u,
            passes=None if not self.made or unrated else bool(self.passes[row]),
            governs=governs,
            mode=self.mode,
            not_made=self.unrated if unrated else self.not_made,
        )

    def reason(self, row: int) -> str:
        """Why the row does not pass this check: by how much the required value exceeds the
        rated one, or what the check needs.

        Parameters
        ----------
        row : int
            The row of the catalog.

        Returns
        -------
        str
            The reason as a line of text.
        """
        return self.at(row).reason()


def _significant(values, digits: int = 12) -> np.ndarray:
    """``values`` rounded to ``digits`` significant digits, so that figures which differ only by
    floating-point rounding (the same inputs given in other units) tie, and the tie goes by name."""
    x = np.asarray(values, float)
    scaled = np.isfinite(x) & (x != 0)
    exponent = np.floor(np.log10(np.abs(np.where(scaled, x, 1.0))))
    scale = 10.0 ** (digits - 1 - exponent)
    return np.where(scaled, np.round(x * scale) / scale, x)


def rank(passes, size, worst_utilization, parts, later=None) -> np.ndarray:
    """Indices best first: passing first, and among them the rows not marked ``later`` (an
    illustrative row; a gearbox whose drive train is not shown to clear the excitation) before the
    others, then smallest size and larger margin; failing rows after, closest to passing first (the
    rule of :mod:`calc.domain.gearbox`).

    Parameters
    ----------
    passes : numpy.ndarray of bool
        Each row's verdict.
    size : numpy.ndarray of float
        Each row's size measure (a rated torque's magnitude, smaller first).
    worst_utilization : numpy.ndarray of float [1]
        Each row's highest utilization (NaN ranks last).
    parts : numpy.ndarray of str
        The part names, which break ties.
    later : numpy.ndarray of bool, optional
        Passing rows shown after the other passing ones.

    Returns
    -------
    numpy.ndarray of int
        Row indices, best first.
    """
    passes = np.asarray(passes, bool)
    worst = np.where(np.isnan(worst_utilization), np.inf, _significant(worst_utilization))
    size_key = np.where(passes, _significant(size), 0.0)
    shown_later = np.zeros(len(passes), bool) if later is None else passes & np.asarray(later, bool)
    # The keys in one integer, (group, size, utilization) each as its rank among the distinct values:
    # one sort of integers, a third of the time of a stable sort by each key in turn.
    sizes, size_rank = np.unique(size_key, return_inverse=True)
    worsts, worst_rank = np.unique(worst, return_inverse=True)
    group = (~passes).astype(np.int64) * 2 + shown_later
    key = (group * len(sizes) + size_rank) * len(worsts) + worst_rank
    order = np.argsort(key)
    # Rows tied on every key go by part name, then by row (a sort that is not stable leaves their
    # order open). Names are sorted within the tied runs only: sorting text costs more than the
    # numeric keys, and a catalog has few ties.
    tied = key[order][1:] == key[order][:-1]
    if tied.any():
        run = np.cumsum(np.concatenate(([True], ~tied)))
        at = np.flatnonzero(np.concatenate(([False], tied)) | np.concatenate((tied, [False])))
        rows = order[at]
        order[at] = rows[np.lexsort((rows, np.asarray(parts)[rows].astype(str), run[at]))]
    return order


def selected_part(parts, passes, order) -> str | None:
    """The best-ranked part if it passes, else None.

    Parameters
    ----------
    parts : numpy.ndarray of str
        The part names.
    passes : numpy.ndarray of bool
        Each row's verdict.
    order : numpy.ndarray of int
        Row indices, best first (:func:`rank`).

    Returns
    -------
    str or None
        The chosen part.
    """
    if len(order) and passes[order[0]]:
        return str(parts[order[0]])
    return None
