"""The design review's state, without its widgets: what the page shows and what a reviewer does to
it, so that each can be tested as plain code (the panel, :mod:`calc.review.panel`, draws it).

:class:`ReviewState` holds the case file chosen and its text, the edits of its moves, the value of
each input and the text of its field, the values refused, undo and redo (:class:`History`), the
unit system and the options of the results. Every change of the case is a key path and a text
(:mod:`calc.review.edit`): the case on the screen is the case file read again with the edits of
the moves and the changed values written in, as it is saved. :meth:`ReviewState.evaluate` gives
the results of the state as it stands (:class:`Screen`), which is where the review reads the
sections' results.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

from ..core.errors import CalcError, as_found
from ..core.units import Q_
from ..domain.mechanism import converted, converted_distance
from ..sections import motion as motion_section
from ..sections.accuracy import NAME as ACCURACY
from ..sections.case import Case, read_case
from ..sections.coupling import NAME as COUPLING
from ..sections.duty import NAME as PROFILE
from ..sections.ratios import search as search_ratios
from .edit import changed_text, edited_case, moves_edits, value_text
from .inputs import (MECHANISM, MOVE_TIMES, SELECTION, TYPED, InputSpec, input_edits, is_inch_pound, option_text,
                     read_typed, review_specs)
from .units import ShownUnits
from .keep import save_path, write_case
from .view import evaluated

#: The attribute of :class:`calc.domain.mechanism.Mechanism` of each of its keys that is named otherwise.
MECHANISM_ATTRIBUTES = {"pitch_diameter": "diameter", "pulley_diameter": "diameter", "screw_inertia": "own_inertia",
                        "pinion_inertia": "own_inertia", "pulley_inertia": "own_inertia"}


class History:
    """What undo and redo step through: the state after each change (:meth:`ReviewState.snapshot`).

    Parameters
    ----------
    first : object
        The state before any change.
    """

    def __init__(self, first):
        self._done, self._undone = [first], []

    def push(self, snapshot) -> None:
        """A change: what was undone is dropped.

        Parameters
        ----------
        snapshot : object
            The state after it; nothing is kept where it is the same as before.

        Returns
        -------
        None
        """
        if snapshot != self._done[-1]:
            self._done.append(snapshot)
            self._undone = []

    def undo(self):
        """Step back over the last change.

        Returns
        -------
        object or None
            The state before it, or None where there is none.
        """
        if len(self._done) < 2:
            return None
        self._undone.append(self._done.pop())
        return self._done[-1]

    def redo(self):
        """Make the change undone last again.

        Returns
        -------
        object or None
            The state after it, or None where none was undone.
        """
        if not self._undone:
            return None
        self._done.append(self._undone.pop())
        return self._done[-1]

    @property
    def can_undo(self) -> bool:
        """Whether there is a change to undo."""
        return len(self._done) > 1

    @property
    def can_redo(self) -> bool:
        """Whether there is a change undone to make again."""
        return bool(self._undone)


@dataclass
class Screen:
    """The results of a review's state as it stood when evaluated (:meth:`ReviewState.evaluate`):
    the changed case and its report, or the input error that keeps it from being made; and the
    state's address then (the moves' edits, each field's text, the changed inputs).

    Parameters
    ----------
    case : calc.sections.case.Case or None
        The changed case; None where the input error keeps it from being made.
    report : calc.report.Report or None
        Its report; None with the input error.
    left_out : list of str
        What had to be left out of the report (a further section the inputs make impossible to
        evaluate, :func:`calc.review.view.evaluated`), one sentence each.
    error : str or None
        The input error, in words.
    ratios : dict, str or None
        The ratio search's JSON, or why it cannot be made; None: not asked for.
    typed_by_hand : bool
        Whether the derived load cycle was typed segment by segment.
    moves : list
        The edits of the moves.
    texts : dict
        Key path -> each field's text.
    changes : dict
        Key path -> (number or part, unit) of each input changed (:meth:`ReviewState.changes`).
    text : str, optional
        The case file as changed, as saved (:meth:`ReviewState.case_text`); None: unchanged.
    file_texts : dict, optional
        Key path -> the changed inputs' texts in the file's units (:meth:`ReviewState.file_texts`); None: the
        fields' texts are those.
    factors : dict, optional
        Key path -> what a value in the file's unit is multiplied by to show it, for each input shown in
        another unit (:meth:`ReviewState.unit_factors`).
    """

    case: Case | None
    report: object
    left_out: list
    error: str | None
    ratios: object
    typed_by_hand: bool
    moves: list
    texts: dict
    changes: dict
    text: str | None = None
    file_texts: dict | None = None
    factors: dict = field(default_factory=dict)

    @property
    def changed_texts(self) -> dict:
        """The texts of the changed inputs in the file's units (the page's address and the variants carry them)."""
        return {key: (self.texts if self.file_texts is None else self.file_texts)[key] for key in self.changes}

    def _section(self, name: str):
        """The result of the section ``name`` (:class:`calc.sections.protocol.Result`), None
        where the case has none or cannot be evaluated."""
        evaluated = None if self.report is None else self.report.evaluated
        return None if evaluated is None else evaluated.sections.get(name)

    def duty(self):
        """The duty values of the load cycle (the load-cycle figure's).

        Returns
        -------
        calc.sections.duty.DutyValues or None
            None where the case cannot be evaluated.
        """
        profile = self._section(PROFILE)
        return None if profile is None else profile.shown

    def chain(self):
        """The accuracy chain's values (the stiffness-chain figure's).

        Returns
        -------
        calc.sections.accuracy.AccuracyValues or None
            None where the case has no accuracy chain, or cannot be evaluated.
        """
        accuracy = self._section(ACCURACY)
        return None if accuracy is None else accuracy.shown

    def idle(self) -> dict:
        """The inputs that have no effect on the design as it stands (a temperature on a coupling
        type without a temperature factor).

        Returns
        -------
        dict
            Key path -> why, in words.
        """
        coupling = self._section(COUPLING)
        if coupling is not None and coupling.inputs.type == "bellows":
            return {"coupling.temperature":
                    "no effect on this design: a metal bellows coupling has no temperature factor (E9)"}
        return {}


def without_folder(text: str, path: Path) -> str:
    """An error without the server's folders: the case file by its name.

    Parameters
    ----------
    text : str
        The error.
    path : pathlib.Path
        The case file.

    Returns
    -------
    str
        The error, each of the file's paths (as given and resolved) its name, its folder left out.

    Examples
    --------
    >>> without_folder("/srv/cases/a.toml: motor.inertia: expected ...", Path("/srv/cases/a.toml"))
    'a.toml: motor.inertia: expected ...'
    """
    for folder in (str(path.resolve()), str(path)):
        text = text.replace(folder, path.name)
    return text.replace(str(path.parent) + "/", "")


class ReviewState(ShownUnits):
    """The review of the case file ``path``: the case, its inputs' values and their history.

    Nothing is read until :meth:`load`. An operation that cannot be made raises
    :class:`calc.core.errors.CalcError` saying why, the state left as it was.

    Parameters
    ----------
    path : str or pathlib.Path
        The case file.

    Attributes
    ----------
    values : dict
        Each input's value by its key path: a slider's number in the input's unit, or a choice.
    texts : dict
        The text each input's field shows, by key path.
    refused : dict
        Key path -> (the text typed and refused, why).
    pinned : set
        The key paths of inputs that follow another while the file leaves them out
        (:attr:`calc.review.inputs.InputSpec.follows`) and that the reviewer set: they no longer follow.
    moves : list
        The edits of the moves, in order (:mod:`calc.review.edit`).
    case : calc.sections.case.Case or None
        The case file read with the moves' edits (what the inputs start from).
    specs : list of calc.review.inputs.InputSpec
        Its inputs.
    units : str
        The unit system of the results shown (``"SI"``, ``"inch-pound"``); ``file_units`` the one
        the case file writes its inputs in.
    all_candidates, ratio_search : bool
        The options of the results: every candidate in the tables, the ratio search.
    history : History
        What undo and redo step through.
    shown : Screen or None
        The results last evaluated.
    """

    def __init__(self, path):
        self.path = Path(path)
        self.file_text: str | None = None
        self.file_units = "SI"
        self._units = "SI"
        self.all_candidates = False
        self.ratio_search = False
        self.moves: list = []
        self.case: Case | None = None
        self.specs: list[InputSpec] = []
        self.values: dict = {}
        self.texts: dict = {}
        self.refused: dict = {}
        self.pinned: set = set()
        self.history = History(self.snapshot())
        self.shown: Screen | None = None

    # -- the case file and its inputs --------------------------------------------------------

    def load(self, path=None) -> None:
        """Read a case file with its own values: no edit, nothing to undo, the results in the unit
        system its inputs are written in.

        Parameters
        ----------
        path : str or pathlib.Path, optional
            The case file; by default the one reviewed.

        Returns
        -------
        None

        Raises
        ------
        calc.core.errors.CalcError
            For a file that cannot be read, the state left on the case file before.
        """
        before = self.path, self.file_text
        self.path = Path(path or self.path)
        try:
            self.file_text = self.path.read_text(encoding="utf-8-sig")  # an editor's byte-order mark is not TOML
        except (OSError, UnicodeDecodeError):
            self.file_text = None  # the reader says why
        try:
            self._build([], {})
        except CalcError:
            self.path, self.file_text = before
            raise
        self.file_units = "inch-pound" if any(is_inch_pound(s.unit) for s in self.specs) else "SI"
        self.units = self.file_units
        self.history = History(self.snapshot())

    def _build(self, moves: list, values: dict, pinned=()) -> None:
        """The inputs of the case file with the ``moves`` edited, at ``values`` (by key path) where
        given, else at the case's, the inputs ``pinned`` set by the reviewer; nothing changes where
        the edited case cannot be read."""
        moves = json.loads(json.dumps(moves))  # as the address and the history write them
        try:
            case = edited_case(self.path, self.file_text, [e for m in moves for e in moves_edits(m)])
            specs = review_specs(case)
        except CalcError as exc:
            raise CalcError(without_folder(str(exc), self.path)) from None
        self.case, self.moves, self.specs, self.refused = case, moves, specs, {}
        self.pinned = {s.key for s in specs if s.follows and s.key in pinned}
        self.values = {s.key: values.get(s.key, s.value) for s in specs}
        self.texts = {s.key: self.field_text(s.key, self.values[s.key]) for s in specs}
        self._follow()

    def _follow(self) -> list:
        """Each input that follows another (the file leaves it out, the reviewer has not set it) at
        that one's value, as reading the changed file takes it; the key paths it changed."""
        moved = []
        for spec in self.specs:
            if spec.follows and spec.key not in self.pinned and spec.follows in self.values:
                v = self.values[spec.follows]
                if self.values[spec.key] != v:
                    self.values[spec.key] = v
                    moved.append(spec.key)
                if spec.key not in self.refused:
                    self.texts[spec.key] = self.field_text(spec.key, v)
        return moved

    def _pin(self, key: str, value) -> None:
        """An input that follows another set by the reviewer: it no longer follows, unless set to
        the value it follows (then it follows again, and the file still leaves it out)."""
        spec = self.spec(key)
        if spec.follows:
            if value == self.values.get(spec.follows):
                self.pinned.discard(key)
            else:
                self.pinned.add(key)

    def following(self, key: str) -> str | None:
        """What an input's value follows, in words, while the file leaves it out.

        Parameters
        ----------
        key : str
            The input's key path.

        Returns
        -------
        str or None
            :attr:`calc.review.inputs.InputSpec.default` where the file leaves the input out and
            it is not changed; None where its value is the file's or the reviewer's.
        """
        spec = self.spec(key)
        if spec.default is None or key in self.changes():
            return None
        return spec.default

    def spec(self, key: str) -> InputSpec:
        """The input of a key path.

        Parameters
        ----------
        key : str
            Its key path (``motor.peak_torque``).

        Returns
        -------
        calc.review.inputs.InputSpec
            The input.
        """
        return next(s for s in self.specs if s.key == key)

    def set_value(self, key: str, value) -> bool:
        """An input set (a slider moved, a choice made).

        Parameters
        ----------
        key : str
            The input's key path.
        value : float or str
            Its value [the input's unit], or a choice.

        Returns
        -------
        bool
            Whether it changed.
        """
        pinned = set(self.pinned)
        self._pin(key, value)
        if self.values[key] == value and pinned == self.pinned:
            return False
        self.values[key] = value
        if key not in self.refused:  # a refused text stays in its field until typed again
            self.texts[key] = self.field_text(key, value)
        self._follow()
        self.history.push(self.snapshot())
        return True

    def type_text(self, key: str, text: str) -> bool:
        """A text typed into an input's field: its value (:func:`calc.review.inputs.read_typed`),
        or refused with why.

        Parameters
        ----------
        key : str
            The input's key path.
        text : str
            The field's text.

        Returns
        -------
        bool
            Whether the results change: a value changed, or a refusal made or taken back.
        """
        if key not in self.refused and text.strip() == self.texts[key]:
            return False  # the field's own text again: nothing typed (a converted value would move by its rounding)
        spec, shown = self.spec(key), self.shown_spec(key)
        try:
            typed = read_typed(text, shown)  # in the unit the field shows
        except CalcError as exc:
            self.refused[key] = (text, str(exc))
            self.texts[key] = text.strip()
            return True
        v = typed if shown is spec else float(Q_(typed, shown.unit).m_as(spec.unit))
        was_refused = self.refused.pop(key, None) is not None
        pinned = set(self.pinned)
        self._pin(key, v)
        changed = self.values[key] != v or pinned != self.pinned
        self.values[key] = v
        self.texts[key] = shown.field_text(typed) if changed else f"{typed:g}"
        self._follow()
        if changed:
            self.history.push(self.snapshot())
        return changed or was_refused

    def follow_values(self, texts: dict) -> None:
        """The inputs at the texts a link gives them.

        Parameters
        ----------
        texts : dict
            Key path -> the field's text, or a choice's option.

        Returns
        -------
        None

        Raises
        ------
        calc.core.errors.CalcError
            For an input the case does not have, or a text it does not take, saying which.
        """
        for key, text in texts.items():
            spec = next((s for s in self.specs if s.key == key), None)
            if spec is None:
                raise CalcError(f"{self.path.name} has no input {key}")
            if spec.options:
                value = next((o for o in spec.options if option_text(o) == text), None)
            else:
                value = read_typed(text, spec)
            if value is None:
                raise CalcError(f"{spec.label}: {as_found(text)} is not one of its choices")
            self.set_value(key, value)

    def changes(self) -> dict:
        """The inputs changed from the case file (with the moves' edits).

        Returns
        -------
        dict
            Key path -> (number [unit] or part, unit).
        """
        out = {}
        for s in self.specs:
            v = self.values[s.key]
            # An input that follows another is changed once set by the reviewer: the file then writes it.
            if (s.key in self.pinned) if s.follows else not s.is_case_value(v):
                out[s.key] = (v, s.unit)
        return out

    def modified(self) -> bool:
        """Whether the screen differs from the case file.

        Returns
        -------
        bool
            True where a value is changed or the moves are edited.
        """
        return bool(self.moves or self.changes())

    def _value_edits(self) -> list:
        """The changed values as edits of the case file (a part left to the selection: its key taken out)."""
        changes = {key: (None if v == SELECTION else v) if isinstance(v, str) else (v, unit)
                   for key, (v, unit) in self.changes().items()}
        return input_edits(self.case, changes)

    def changed_case(self) -> Case:
        """The case file read with the moves' edits and the changed values written in.

        Returns
        -------
        calc.sections.case.Case
            The case; a value left where it started keeps the case's own, not the slider's
            rounding of it (a derived cycle's 7.8269 N·m stays, and stays derived).
        """
        return self._changed()[0]

    def _changed(self) -> tuple:
        """The changed case, and the text it is read from (:meth:`case_text`; None: the file's)."""
        edits = self._value_edits()
        if not (edits or self.moves):
            return self.case, None
        text = changed_text(self.file_text, self.moves, edits, self.path.name)
        return (read_case(self.path, text) if edits else self.case), text

    def case_text(self) -> str:
        """The case file with the moves' edits and the changed values written in, and a first
        comment naming them (:func:`calc.review.edit.changed_text`).

        Returns
        -------
        str
            The TOML text :meth:`save` writes.
        """
        return changed_text(self.file_text, self.moves, self._value_edits(), self.path.name)

    def save(self, name: str) -> Path:
        """Write :meth:`case_text` as a new case file beside the case file, never over a file.

        Parameters
        ----------
        name : str
            The new file's name (:func:`calc.review.keep.save_path`).

        Returns
        -------
        pathlib.Path
            Its path.

        Raises
        ------
        calc.core.errors.CalcError
            For a refused value in a field, a name not taken, or a file not written.
        """
        if self.refused:
            raise CalcError("a refused value is in a field: correct it (or undo) before saving")
        if not self.modified():
            raise CalcError(f"nothing changed: the screen is {self.path.name} as it is; nothing written")
        path = save_path(self.path, name.strip())
        try:
            write_case(path, self.case_text(), self.file_text)
        except CalcError as exc:
            raise CalcError(without_folder(str(exc), self.path)) from None
        return path

    def in_words(self, text: str) -> str:
        """An error as the page says it.

        Parameters
        ----------
        text : str
            The error.

        Returns
        -------
        str
            The text with the input's label where it names its key path, and no folder of the
            server (:func:`without_folder`).
        """
        text = without_folder(text, self.path)
        for spec in sorted(self.specs, key=lambda s: -len(s.key)):
            text = text.replace(f"{spec.key}:", f"{spec.label}:")
        return text

    # -- undo and redo ---------------------------------------------------------------------------

    def snapshot(self) -> tuple:
        """What undo and redo step through.

        Returns
        -------
        tuple
            (the moves' edits as JSON, the inputs' values by key path, the inputs set that follow
            another while the file leaves them out).
        """
        return json.dumps(self.moves), dict(self.values), tuple(sorted(self.pinned))

    def undo(self) -> None:
        """Back to the state before the last change (none: nothing happens).

        Returns
        -------
        None
        """
        self._step(self.history.undo())

    def redo(self) -> None:
        """The change undone last, again (none: nothing happens).

        Returns
        -------
        None
        """
        self._step(self.history.redo())

    def _step(self, snapshot) -> None:
        if snapshot is None:
            return
        moves, values, pinned = snapshot
        if moves != json.dumps(self.moves):
            self._build(json.loads(moves), values, pinned)
            return
        self.pinned = set(pinned)
        for key, v in values.items():
            self.values[key] = v
            if key not in self.refused:
                self.texts[key] = self.field_text(key, v)

    # -- the moves edited: entries added and removed, the mechanism's type changed -----------------

    def entries(self) -> list[str]:
        """The entries of the moves.

        Returns
        -------
        list of str
            Each ``"move"`` or ``"dwell"``, in order; none where the case has no moves.
        """
        motion = self.case.motion if self.case is not None else None
        if motion is None or not motion.moves:
            return []
        return ["dwell" if "dwell" in m else "move" for m in motion.tables["move"]]

    def _entry_texts(self, k: int) -> dict:
        """Entry ``k`` of the moves as a case file writes it, at the inputs' values (a ramp the
        file leaves out only where it was changed)."""
        table = self.case.motion.tables["move"][k - 1]
        names = ("dwell",) if "dwell" in table else ("distance", *(n for n, _ in MOVE_TIMES))
        changed = self.changes()
        return {name: value_text(self.values[key], self.spec(key).unit) for name in names
                if (key := f"move[{k}].{name}") in self.values and (name in table or key in changed)}

    def add_entry(self, after: int, kind: str) -> None:
        """Put a move or a dwell in after an entry of the moves.

        Parameters
        ----------
        after : int
            The entry it follows (counted from 1; 0: before the first).
        kind : str
            ``"move"``: a copy of the move at or before entry ``after``, else the first;
            ``"dwell"``: as long as the last dwell, else 1 s.

        Returns
        -------
        None
        """
        kinds = self.entries()
        if kind == "move":
            before = list(range(after, 0, -1)) + list(range(after + 1, len(kinds) + 1))
            keys = self._entry_texts(next(k for k in before if kinds[k - 1] == "move"))  # a motion has a move
        else:
            dwells = [k for k in range(len(kinds), 0, -1) if kinds[k - 1] == "dwell"]
            keys = self._entry_texts(dwells[0]) if dwells else {"dwell": "1 s"}
        self._edit_moves(["add", after, keys])

    def remove_entry(self, k: int) -> None:
        """Take an entry out of the moves.

        Parameters
        ----------
        k : int
            The entry, counted from 1.

        Returns
        -------
        None
        """
        self._edit_moves(["remove", k])

    def change_mechanism(self, type_: str, size_text: str = "") -> str:
        """A mechanism of another type in place of the case's, its values and the moves'
        distances starting equivalent (:func:`calc.domain.mechanism.converted`).

        Parameters
        ----------
        type_ : str
            The type (:data:`calc.domain.mechanism.TYPES`).
        size_text : str
            A linear type's lead or diameter as typed [:meth:`length_unit`]; a decimal comma is
            read as a point.

        Returns
        -------
        str
            What it did, in words, with what it leaves out.
        """
        try:
            size = None
            if type_ != "rotary":
                t = size_text.strip().replace(",", ".")
                if not TYPED.match(t) or not float(t) > 0:
                    what = "lead" if type_ == "ball-screw" else "diameter"
                    raise CalcError(f"a {type_} needs its {what}: expected a number above zero "
                                    f"(in {self.length_unit()}), found {as_found(size_text.strip())}")
                size = Q_(float(t), self.length_unit())
            edit = mechanism_edit(self.changed_case(), type_, size, self.file_units == "inch-pound")
        except CalcError as exc:
            raise CalcError(self.in_words(str(exc))) from None
        self._edit_moves(edit)
        return edit[3]

    def length_unit(self) -> str:
        """The unit of a mechanism's lead or diameter as its field shows it (the file keeps its own).

        Returns
        -------
        str
            ``"in"`` where the inputs are shown in inch-pound, else ``"mm"``.
        """
        return "in" if self.units == "inch-pound" else "mm"

    def follow_moves(self, moves: list) -> bool:
        """The edits of the moves a link carries: the case file's moves with those edits, at the
        file's values (the link's values follow).

        Parameters
        ----------
        moves : list
            The edits of the moves, in order.

        Returns
        -------
        bool
            Whether they differ from those made (and so were made).
        """
        if json.dumps(moves) == json.dumps(self.moves):
            return False
        self._build(moves, {})
        self.history.push(self.snapshot())
        return True

    def _edit_moves(self, edit: list) -> None:
        """The inputs of the moves with ``edit`` as well, each value carried to its entry's new
        place (an entry removed takes its values with it)."""
        self._build([*self.moves, edit], _moved(self.values, edit), _moved(dict.fromkeys(self.pinned), edit))
        self.history.push(self.snapshot())

    def from_edits(self, key: str) -> str | None:
        """What the edits of the moves made of an input.

        Parameters
        ----------
        key : str
            The input's key path.

        Returns
        -------
        str or None
            An entry added here, or a value set by a change of the mechanism's type, in words;
            None where the value is the file's.
        """
        m = _ENTRY.match(key)
        if m is not None and int(m.group(1)) in added_entries(self.moves):
            return "an entry added here: not in the file"
        set_by_type = key.startswith("mechanism.") or (m is not None and key.endswith(".distance"))
        if set_by_type and any(e[0] == "mechanism" for e in self.moves):
            return "set by the change of the mechanism's type: not in the file"
        return None

    # -- the results ---------------------------------------------------------------------------

    def evaluate(self) -> Screen:
        """The results of the state as it stands: the changed case evaluated whole
        (:func:`calc.review.view.evaluated`), and the ratio search where asked for.

        Returns
        -------
        Screen
            The results, also kept as :attr:`shown`; an input error is its ``error``.
        """
        texts, changes, moves = dict(self.texts), self.changes(), json.loads(json.dumps(self.moves))
        try:
            case, text = self._changed()
        except CalcError as exc:
            self.shown = Screen(None, None, [], self.in_words(str(exc)), None, False, moves, texts, changes)
            return self.shown
        report, left_out = evaluated(case)
        ratios = None
        if self.ratio_search:  # asked for: its own command's result, the case at every ratio
            # The drive and coupling as the whole case evaluated them, not a second time.
            every = report.evaluated.every if report.evaluated is not None and not left_out else None
            try:
                ratios = search_ratios(case, every).to_json()
            except CalcError as exc:
                ratios = self.in_words(str(exc))
        typed = self.case.motion is not None and case.motion is None
        left_out = [self.in_words(x) for x in left_out]
        self.shown = Screen(case, report, left_out, None, ratios, typed, moves, texts, changes, text, self.file_texts(),
                            self.unit_factors())
        return self.shown


def mechanism_edit(case: Case, type_: str, size, inch: bool) -> list:
    """The edit of the moves (:mod:`calc.review.edit`) that puts a mechanism of ``type_`` (of
    lead or diameter ``size``) in place of the case's, its values equivalent at the gearbox output
    and written in inch-pound units where ``inch``, the moves' distances converted.

    Parameters
    ----------
    case : calc.sections.case.Case
        A case whose load cycle is derived from moves.
    type_ : str
        One of :data:`calc.domain.mechanism.TYPES`.
    size : pint.Quantity [mm or in] or None
        A linear type's lead or diameter; None for a rotary type.
    inch : bool
        Whether the case writes inch-pound units.

    Returns
    -------
    list
        ``["mechanism", keys, distances, said]``.
    """
    old = case.motion.mechanism
    new, left = converted(old, type_, size)
    keys = {}
    for key in motion_section.keys_of(type_):
        q = getattr(new, MECHANISM_ATTRIBUTES.get(key.name, key.name), None) if key.name != "type" else type_
        if key.name == "type" or (key.name == "holding_brake" and q):
            keys[key.name] = q
        elif q is not None and key.name in MECHANISM:
            unit = MECHANISM[key.name][1] if inch else key.unit
            v = float(q.m_as(unit or ""))
            # cos 90° is 6e-17 in floating point: a vertical axis' guide carries nothing
            v = 0.0 if abs(v) < 1e-9 else v
            keys[key.name] = v if not unit else value_text(v, unit)
    distances, unit = {}, "deg" if not new.linear else ("in" if inch else "mm")
    for k, given in enumerate(case.motion.distances, start=1):  # None: a dwell
        if given is not None:
            distances[str(k)] = value_text(float(converted_distance(old, new, given).m_as(unit)), unit)
    said = f"mechanism {old.type} -> {type_}"
    said += "" if size is None else f" of {value_text(size.magnitude, f'{size.units:~}')}"
    said += " (equivalent at the gearbox output" + (f"; left out: {'; '.join(left)})" if left else ")")
    return ["mechanism", keys, distances, said]


#: An input of an entry of the moves: ``move[2].time``.
_ENTRY = re.compile(r"^move\[(\d+)\]\.")


def added_entries(moves) -> set:
    """The entries of the moves (counted from 1) that the edits ``moves`` added.

    Parameters
    ----------
    moves : list
        The edits of the moves, in order (:mod:`calc.review.edit`).

    Returns
    -------
    set of int
        Their places after the last edit.

    Examples
    --------
    >>> sorted(added_entries([["add", 2, {"dwell": "1 s"}], ["add", 0, {"dwell": "2 s"}], ["remove", 2]]))
    [1, 3]
    """
    added: list = []  # the added entries' places, kept up to date edit by edit
    for edit in moves:
        added = [p for k in added if (p := _place(k, edit)) is not None]
        added += [edit[1] + 1] if edit[0] == "add" else []
    return set(added)


def _place(k: int, edit) -> int | None:
    """The place of entry ``k`` of the moves after ``edit`` (None: the entry removed)."""
    if edit[0] == "add":
        return k + 1 if k > edit[1] else k
    if edit[0] == "remove":
        return None if k == edit[1] else k - 1 if k > edit[1] else k
    return k


def _moved(values: dict, edit) -> dict:
    """The inputs' ``values`` with each entry's inputs at its place after ``edit``.

    >>> _moved({"move[1].time": 0.5, "move[2].dwell": 1.0, "motor.inertia": 2.0}, ("add", 1, {}))
    {'move[1].time': 0.5, 'move[3].dwell': 1.0, 'motor.inertia': 2.0}
    >>> _moved({"move[1].time": 0.5, "move[2].dwell": 1.0}, ("remove", 1))
    {'move[1].dwell': 1.0}
    """
    if edit[0] == "mechanism":  # it writes the mechanism's values and the distances itself
        return {key: v for key, v in values.items()
                if not key.startswith("mechanism.") and not (_ENTRY.match(key) and key.endswith(".distance"))}
    out = {}
    for key, v in values.items():
        m = _ENTRY.match(key)
        if m is None:
            out[key] = v
            continue
        moved = _place(int(m.group(1)), edit)
        if moved is not None:
            out[f"move[{moved}]." + key[m.end():]] = v
    return out
