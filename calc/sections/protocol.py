"""What a section of a case is: the one protocol every section of :mod:`calc.sections` implements.

A section module holds one :class:`Section` (``SECTION``) and its result record (a
:class:`Result`). The section declares its ``NAME`` (its key in the results), its ``TABLES`` (the
tables of a case file it reads, each key declared once: :class:`calc.sections.case.Declared`), the
earlier sections it ``REQUIRES`` (whose results its evaluation reads), how it reads its tables when
the case is read (:meth:`Section.read`: a bad key is an error then, naming the file and the key),
whether it ``applies`` to a case and how it evaluates it (:meth:`Section.evaluate`). Its module's
``ORDER`` is its place in the results and in every output; the evaluation follows ``REQUIRES``
(:mod:`calc.sections.evaluation`). Where an output has nothing to say of a section the methods
say so by their defaults: no governing checks (None), nothing left unchecked, no catalog ranked.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import ClassVar

from .common import SHOWN_CANDIDATES, Governing, Verdict


class Result(ABC):
    """The result record of a section: what the JSON, the text summary and the verdict read.
    ``AT_TOP``: the JSON writes the record's objects at its top level, not under the section's name."""

    AT_TOP: ClassVar[bool] = False

    @abstractmethod
    def to_json(self, candidates: int | None = SHOWN_CANDIDATES) -> dict:
        """The record as the JSON contract writes it.

        Parameters
        ----------
        candidates : int or None
            The most candidates each list holds, best first (all for None).

        Returns
        -------
        dict
        """

    @abstractmethod
    def summary_lines(self, candidates: int | None = SHOWN_CANDIDATES) -> list[str]:
        """The record as lines of the text summary.

        Parameters
        ----------
        candidates : int or None
            The most candidates each list holds, best first (all for None).

        Returns
        -------
        list of str
        """

    @abstractmethod
    def verdict(self) -> Verdict | None:
        """Whether the section passes.

        Returns
        -------
        calc.sections.common.Verdict or None
            None where the section checks nothing.
        """

    def governing(self) -> Governing | None:
        """The checks that decide the verdict.

        Returns
        -------
        calc.sections.common.Governing or None
            None where the section has none.
        """
        return None

    def unchecked(self) -> list[str]:
        """Checks left out for want of an input (beside the governing checks not made).

        Returns
        -------
        list of str
            Each with why.
        """
        return []

    def ranked(self):
        """The catalog ranked and the part chosen. The outputs name its chosen part and worst
        utilization, and a record that ranks says how in its ``ranking`` (a sentence).

        Returns
        -------
        calc.core.selection.Selection or None
            None where the section ranks none.
        """
        return None


class Section(ABC):
    """A section of a case: its tables, what it requires, how it reads and evaluates a case.

    ``SHOWN`` False: the section's result is read by the sections after it but written by no
    output (the motor a case is checked with)."""

    NAME: ClassVar[str]
    TABLES: ClassVar[tuple] = ()
    REQUIRES: ClassVar[tuple[str, ...]] = ()
    SHOWN: ClassVar[bool] = True

    @property
    def keeps_table(self) -> bool:
        """Whether a case keeps the section's own table (the one of its ``TABLES`` named as it is)
        as written, in ``case.sections``, and its typed inputs in ``case.inputs``: the section
        reads it as :meth:`read` does here, not overriding it.

        Returns
        -------
        bool
        """
        return type(self).read is Section.read and any(t.name == self.NAME for t in self.TABLES)

    def read(self, top, case) -> None:
        """Read the section's own table (the one of its ``TABLES`` named as it is) into the case
        as it is read: its typed inputs (:meth:`read_inputs`) in ``case.inputs`` and the table as
        written in ``case.sections``. A section whose inputs the other sections share writes them
        into the case's fields instead (it overrides this).

        Parameters
        ----------
        top : calc.sections.case.Table
            The case file's top-level table.
        case : calc.sections.case.Case
            The case being read, the sections before this one read into it.

        Returns
        -------
        None
        """
        if self.keeps_table and top.has(self.NAME):
            case.sections[self.NAME] = top.data[self.NAME]
            case.inputs[self.NAME] = self.read_inputs(case)

    def read_inputs(self, case):
        """The typed inputs of the section's own table as ``case.sections`` holds it; every error
        names the file and the key.

        Parameters
        ----------
        case : calc.sections.case.Case
            The case as read.

        Returns
        -------
        object or None
            An object that keeps the table it was read from (``table``); None for a section that
            reads no table of its own.
        """
        return None

    def inputs(self, case):
        """The typed inputs of the section's own table as the case holds it: those read with the
        case, or read again from a copy of the case whose table was changed (the design review's
        inputs, a variant in a notebook).

        Parameters
        ----------
        case : calc.sections.case.Case
            The case, or a changed copy of it.

        Returns
        -------
        object or None
            As :meth:`read_inputs`; None where the case has no such table.
        """
        table = case.sections.get(self.NAME)
        read = case.inputs.get(self.NAME)
        if read is not None and read.table is table:
            return read
        return None if table is None else self.read_inputs(case)

    def applies(self, case) -> bool:
        """Whether the case gives what the section evaluates: by default, its own table.

        Parameters
        ----------
        case : calc.sections.case.Case
            The case as read.

        Returns
        -------
        bool
        """
        return self.NAME in case.sections

    def checked(self, case, result):
        """The case as the outputs show it checked, once the section gave its result: by default
        the case itself (the drive section gives it the ratings of the motor chosen).

        Parameters
        ----------
        case : calc.sections.case.Case
            The case as checked so far.
        result : object
            The section's result.

        Returns
        -------
        calc.sections.case.Case
        """
        return case

    def evaluated_with(self, result) -> dict:
        """Results of sections after this one that its evaluation already made for the case as
        checked: the evaluation takes them instead of evaluating those sections again (the drive's
        choice of a motor from a catalog evaluates the gearbox, the coupling and the motor with it).
        By default none.

        Parameters
        ----------
        result : object
            The section's result.

        Returns
        -------
        dict
            Results by section name.
        """
        return {}

    @abstractmethod
    def evaluate(self, case, earlier) -> Result:
        """The section's result for a case, reading the results of the sections it requires.

        Parameters
        ----------
        case : calc.sections.case.Case
            The case as read (the drive section's result holds it with the motor it is checked with).
        earlier : calc.sections.evaluation.Earlier
            The results of the sections it requires.

        Returns
        -------
        Result or object
            A :class:`Result` where the section is shown.
        """
