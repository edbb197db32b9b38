"""The variants a reviewer keeps: each design pinned with its name (what was changed in it), its
report and its state (the case file, the moves' edits and the changed values as the fields showed
them), compared side by side (:func:`calc.review.view.comparison_html`, as a PDF
:func:`calc.review.view.comparison_pdf`). The page's address carries the states, so that a link
gives the same variants, each evaluated again from its case file.
"""

from __future__ import annotations

import json
from pathlib import Path

from ..core.errors import CalcError, as_found
from ..core.units import pretty_unit
from .edit import edit_text, value_text
from .keep import CaseFiles, Written
from .state import ReviewState
from .view import comparison_html, comparison_pdf, comparison_rows, worst_utilizations


def variant_name(number: int, file: str, specs, changes: dict, moves) -> str:
    """A variant's name: its number, the case file, and what was changed in it.

    Parameters
    ----------
    number : int
        The variant's number, from 1.
    file : str
        The case file's name.
    specs : iterable of calc.review.inputs.InputSpec
        The inputs (their labels name the changes).
    changes : dict
        Key path -> (number [unit] or part, unit).
    moves : list
        The edits of the moves.

    Returns
    -------
    str
        ``"<number>: <file> with <changes>"``, or ``"... as written"`` where nothing was changed.

    Examples
    --------
    >>> from calc.review.inputs import InputSpec
    >>> specs = [InputSpec("move[1].time", "1 move: time t", "s", 0.05, 1.5, 0.01, 0.5)]
    >>> variant_name(2, "a.toml", specs, {"move[1].time": (0.6, "s")}, [("remove", 2)])
    '2: a.toml with entry 2 of the moves removed; 1 move: time t 0.6 s'
    """
    labels = {spec.key: spec.label for spec in specs}
    said = "; ".join([edit_text(e) for e in moves]
                     + [f"{labels[k]} {v if isinstance(v, str) else value_text(v, pretty_unit(u))}"
                        for k, (v, u) in changes.items()])
    return f"{number}: {file}" + (f" with {said}" if said else " as written")


class Variants:
    """The variants kept, none at first.

    Attributes
    ----------
    kept : list of tuple
        (name, report) of each variant (:class:`calc.report.Report`).
    states : list of dict
        Each one's state as the page's address writes it: its case file, the moves' edits and the
        changed values' field texts.
    asked : list of dict
        The states a link asked for.
    """

    def __init__(self):
        self.kept: list = []
        self.states: list = []
        self.asked: list = []

    def keep(self, state: ReviewState) -> None:
        """Pin the design the state last evaluated (:attr:`ReviewState.shown`) after the others.

        Parameters
        ----------
        state : calc.review.state.ReviewState
            The review, evaluated.

        Returns
        -------
        None

        Raises
        ------
        calc.core.errors.CalcError
            Where the state's inputs give no design (an input error).
        """
        shown = state.shown
        if shown is None or shown.report is None:
            raise CalcError("the inputs give no design (an input error)")
        name = variant_name(len(self.kept) + 1, state.path.name, state.specs, shown.changes, shown.moves)
        self.kept.append((name, shown.report))
        self.states.append({"case": state.path.name, "edits": shown.moves, "values": shown.changed_texts})

    def follow(self, text: str, files: CaseFiles) -> list[str] | None:
        """The variants of the states a link carries, each evaluated again from its case file;
        one that no longer reads is left out.

        Parameters
        ----------
        text : str
            The states' JSON, as the page's address writes them (:attr:`states`).
        files : calc.review.keep.CaseFiles
            The case files offered (a state's case file is one of them).

        Returns
        -------
        list of str or None
            Why each variant left out was, one sentence each; None where the text gives no states,
            or those kept.
        """
        try:
            states = json.loads(text) if text else []
            states = [{"case": str(st["case"]), "edits": [list(e) for e in st["edits"]], "values": dict(st["values"])}
                      for st in states]
        except (ValueError, TypeError, KeyError, AttributeError):
            return None
        self.asked = states
        if states == self.states:
            return None
        kept, missed = [], []
        for k, st in enumerate(states, start=1):
            try:
                kept.append((self._variant(len(kept) + 1, st, files), st))
            except CalcError as exc:
                missed.append(f"variant {k}: {exc}")
        self.kept, self.states = [v for v, _ in kept], [st for _, st in kept]
        return missed

    @staticmethod
    def _variant(number: int, st: dict, files: CaseFiles) -> tuple:
        """(name, report) of a variant's state ``st``, from its case file as the review reads it."""
        path = files.named(st["case"])
        if path is None:
            raise CalcError(f"no case file {as_found(st['case'])} among the cases")
        state = ReviewState(path)
        state.load()
        try:
            state.follow_moves(st["edits"])
            state.follow_values(st["values"])
        except CalcError as exc:
            raise CalcError(state.in_words(str(exc))) from None
        shown = state.evaluate()
        if shown.report is None:
            raise CalcError(shown.error)
        return variant_name(number, path.name, state.specs, shown.changes, shown.moves), shown.report

    def comparison(self, units: str) -> str:
        """The variants side by side (:func:`calc.review.view.comparison_html`).

        Parameters
        ----------
        units : str
            The unit system, ``"SI"`` or ``"inch-pound"``.

        Returns
        -------
        str
            HTML; empty where none is kept.
        """
        return comparison_html(self.kept, units) if self.kept else ""

    def pdf(self, folder: Path, stem: str, units: str) -> Path:
        """The variants side by side with their figure, as a PDF never written over a file
        (:func:`calc.review.view.comparison_pdf`).

        Parameters
        ----------
        folder : pathlib.Path
            Where it goes.
        stem : str
            Its name's start: ``<stem>-variants-N.pdf``, N the first free from 1.
        units : str
            The unit system, ``"SI"`` or ``"inch-pound"``.

        Returns
        -------
        pathlib.Path
            The PDF's path; where the page has written its most files there
            (:class:`calc.review.keep.Written`), :class:`calc.core.errors.CalcError`.
        """
        n = 1
        while (pdf := folder / f"{stem}-variants-{n}.pdf").exists():
            n += 1
        written = Written(folder)
        written.check_room(pdf.name)
        rows = comparison_rows(self.kept, units)
        comparison_pdf([f"variant {k}" for k in range(1, len(self.kept) + 1)], rows, worst_utilizations(self.kept), pdf,
                       legend=[name for name, _ in self.kept], files=[r.path for _, r in self.kept])
        written.add(pdf.name)
        return pdf
