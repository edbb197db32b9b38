"""A catalog's rows checked and ranked: what the gearbox and coupling selections share.

A selection holds, over the rows of its ``catalog`` in catalog order, its checks
(:class:`calc.core.checks.CheckArray`), whether each row passes, each row's worst utilization and the
ranking ``order`` (:func:`calc.core.checks.rank`), and its notes. :class:`Selection` names the chosen
part, says why a row fails and lists the rows, best first, as :class:`Candidate` records, which
the JSON, the text summary, the calc report and the design review all print. A selection type says
which of its checks govern (:meth:`Selection.governs`), which apply to a row
(:meth:`Selection.applies`) and what else a row's record holds (:meth:`Selection.row_fields`).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from .checks import selected_part, worst_governing


@dataclass(kw_only=True)
class Candidate:
    """One catalog row with its checks (:class:`calc.core.checks.Check`), as every output lists it.

    Parameters
    ----------
    part : str
        The row's part name.
    passes : bool or None
        Its verdict; None where every governing check made passes but one could not be made.
    checks : list of Check
        Its checks.
    reasons : list of str
        Why the row does not pass: each failing check, each check not made.
    illustrative : bool
        An illustrative row (not from a maker's published table).
    catalog : str
        The file of the row.
    family : str
        The row's family (series).
    size : str
        The row's size.
    source : str
        Where its figures come from.
    unclear : str
        The row's doubtful figures, as its catalog says.
    maker : str
        The row's maker, where its catalog has the column (motors, drives); blank otherwise.
    """

    part: str
    passes: bool | None  # None: every governing check made passes, but one could not be made
    checks: list
    reasons: list  # why the row does not pass: each failing check, each check not made
    illustrative: bool
    catalog: str = ""  # the file of the row
    family: str = ""
    size: str = ""
    source: str = ""
    unclear: str = ""  # the row's doubtful figures, as its catalog says
    maker: str = ""

    @property
    def governing(self) -> list:
        """The checks that decide the row's verdict."""
        return [k for k in self.checks if k.governs]

    @property
    def worst(self) -> float | None:
        """The worst governing utilization (:func:`calc.core.checks.worst_governing`); None where none has one."""
        worst = worst_governing(self.checks)
        return None if worst is None else worst.utilization


class Selection:
    """The methods a checked and ranked catalog shares; its fields are the selection type's
    (``catalog``, ``checks``, ``passes``, ``order``, ``notes``)."""

    #: The record of one row; a selection type may extend it.
    candidate_type = Candidate

    def governs(self, check) -> bool:
        """Whether a check decides the verdict; all do, unless the selection type says otherwise.

        Parameters
        ----------
        check : CheckArray
            One of the selection's checks.

        Returns
        -------
        bool
            True for a governing check.
        """
        return True

    def applies(self, check, row: int) -> bool:
        """Whether a check applies to a row; all do, unless the selection type says otherwise.

        Parameters
        ----------
        check : CheckArray
            One of the selection's checks.
        row : int
            The row of the catalog.

        Returns
        -------
        bool
            True where the check is made for the row.
        """
        return True

    @property
    def governing(self) -> list:
        return [c for c in self.checks if self.governs(c)]

    @property
    def not_made(self) -> list:
        """The governing checks the case gives too little for: no row can be chosen."""
        return [c for c in self.governing if not c.made]

    @property
    def selected(self) -> str | None:
        """Part of the best passing row, or None (also when a governing check could not be made)."""
        return None if self.not_made else selected_part(self.catalog.parts, self.passes, self.order)

    def put_first(self, part: str, failing: bool = False) -> None:
        """Rank ``part`` first where it passes, or with ``failing`` whether or not it passes (the
        pair a case's motor and gearbox are chosen together by); else leave the ranking as it is.

        Parameters
        ----------
        part : str
            A part of the selection's catalog.
        failing : bool
            Put it first even where it fails (the motor a case is checked with); default False.

        Returns
        -------
        None
        """
        rows = np.flatnonzero(np.asarray(self.catalog.parts) == part)
        if len(rows) and (failing or self.passes[rows[0]]):
            self.order = np.concatenate((rows[:1], self.order[self.order != rows[0]]))

    def decided(self, row: int) -> bool | None:
        """Whether a row passes: None where every check made passes but one could not be made.

        Parameters
        ----------
        row : int
            The row of the catalog.

        Returns
        -------
        bool or None
            The row's verdict.
        """
        passes = bool(self.passes[row])
        return None if passes and self.not_made else passes

    def reasons(self, row: int) -> list[str]:
        """Why a row does not pass: each governing check it fails, with the excess, and each that
        could not be made.

        Parameters
        ----------
        row : int
            The row of the catalog.

        Returns
        -------
        list of str
            One line per check (empty for a pass).
        """
        return [c.reason(row) for c in self.governing if self.applies(c, row) and (not c.made or not c.passes[row])]

    def row_fields(self, row: int) -> dict:
        """What the selection type's record of a row holds besides :class:`Candidate`'s fields.

        Parameters
        ----------
        row : int
            The row of the catalog.

        Returns
        -------
        dict
            Field name to value (none here).
        """
        return {}

    def _texts(self) -> tuple:
        cat = self.catalog
        return (cat.family, cat.text_or_blank("size"), cat.text_or_blank("source"), cat.text_or_blank("unclear"),
                cat.text_or_blank("maker"))

    def candidate(self, row: int, texts: tuple | None = None) -> Candidate:
        """One row as its record.

        Parameters
        ----------
        row : int
            The row of the catalog.
        texts : tuple, optional
            The family, size, source, doubt and maker columns, when at hand (read from the catalog otherwise).

        Returns
        -------
        Candidate
            Of the selection type's :attr:`candidate_type`.
        """
        family, size, source, unclear, maker = texts or self._texts()
        return self.candidate_type(
            part=str(self.catalog.parts[row]),
            passes=self.decided(row),
            checks=[c.at(row, governs=self.governs(c)) for c in self.checks if self.applies(c, row)],
            reasons=self.reasons(row),
            illustrative=bool(self.catalog.illustrative[row]),
            catalog=self.catalog.catalog_of(row),
            family=str(family[row]),
            size=str(size[row]),
            source=str(source[row]),
            unclear=str(unclear[row]),
            maker=str(maker[row]),
            **self.row_fields(row),
        )

    def candidates(self, limit: int | None = None) -> list[Candidate]:
        """The rows as records, best first.

        Parameters
        ----------
        limit : int, optional
            How many to give; all for None.

        Returns
        -------
        list of Candidate
            The first ``limit`` rows in ranking order.
        """
        texts = self._texts()
        return [self.candidate(row, texts) for row in (self.order if limit is None else self.order[:limit])]

    @functools.cached_property
    def best(self) -> Candidate:
        """The best-ranked row: the chosen part, or the closest where none passes."""
        return self.candidate(int(self.order[0]))

    @property
    def chosen(self) -> Candidate | None:
        """The chosen row; None where none is chosen."""
        return self.best if self.selected is not None else None
