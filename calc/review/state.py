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
from dataclasses import dataclass
from pathlib import Path

from ..core.errors import CalcError
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
from .keep import save_path
from .view import evaluated

#: The attribute of :class:`calc.domain.mechanism.Mechanism` of each of its keys that is named otherwise.
MECHANISM_ATTRIBUTES = {"pitch_diameter": "diameter", "pulley_diameter": "diameter", "screw_inertia": "own_inertia",
                        "pinion_inertia": "own_inertia", "pulley_inertia": "own_inertia"}


class History:
    """What undo and redo step through: the state after each change (:meth:`ReviewState.snapshot`)."""

    def __init__(self, first):
        self._done, self._undone = [first], []

    def push(self, snapshot) -> None:
        """A change: ``snapshot`` after it (none where it is the same as before); what was undone is dropped."""
        if snapshot != self._done[-1]:
            self._done.append(snapshot)
            self._undone = []

    def undo(self):
        """The state before the last change, or None where there is none."""
        if len(self._done) < 2:
            return None
        self._undone.append(self._done.pop())
        return self._done[-1]

    def redo(self):
        """The state after the change undone last, or None where none was undone."""
        if not self._undone:
            return None
        self._done.append(self._undone.pop())
        return self._done[-1]

    @property
    def can_undo(self) -> bool:
        return len(self._done) > 1

    @property
    def can_redo(self) -> bool:
        return bool(self._undone)


@dataclass
class Screen:
    """The results of a review's state as it stood when evaluated (:meth:`ReviewState.evaluate`):
    the changed case and its report, or the input error that keeps it from being made; and the
    state's address then (the moves' edits, each field's text, the changed inputs)."""

    case: Case | None
    report: object  # calc.report.Report
    left_out: list
    error: str | None  # the input error, in words
    ratios: object  # the ratio search's JSON, or why it cannot be made; None: not asked for
    typed_by_hand: bool  # the derived load cycle typed segment by segment
    moves: list
    texts: dict
    changes: dict
    text: str | None = None  # the case file as changed, as saved (:meth:`ReviewState.case_text`); None: unchanged

    @property
    def changed_texts(self) -> dict:
        """The field texts of the changed inputs (the page's address carries them)."""
        return {key: self.texts[key] for key in self.changes}

    def _section(self, name: str):
        """The result of the section ``name`` (:class:`calc.sections.protocol.Result`), None
        where the case has none or cannot be evaluated."""
        evaluated = None if self.report is None else self.report.evaluated
        return None if evaluated is None else evaluated.sections.get(name)

    def duty(self):
        """The duty values of the load cycle (the load-cycle figure's), None where the case cannot be evaluated."""
        profile = self._section(PROFILE)
        return None if profile is None else profile.shown

    def chain(self):
        """The accuracy chain's values (the stiffness-chain figure's), None where the case has none."""
        accuracy = self._section(ACCURACY)
        return None if accuracy is None else accuracy.shown

    def idle(self) -> dict:
        """The inputs that have no effect on the design as it stands, each with why (a temperature
        on a coupling type without a temperature factor)."""
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

    Examples
    --------
    >>> without_folder("/srv/cases/a.toml: motor.inertia: expected ...", Path("/srv/cases/a.toml"))
    'a.toml: motor.inertia: expected ...'
    """
    for folder in (str(path.resolve()), str(path)):
        text = text.replace(folder, path.name)
    return text.replace(str(path.parent) + "/", "")


class ReviewState:
    """The review of the case file ``path``: the case, its inputs' values and their history.

    ``values`` holds each input's value by its key path (a slider's number in the input's unit, or
    a choice); ``texts`` the text its field shows; ``refused`` each text typed and refused, with
    why. ``moves`` are the edits of the moves in order (:mod:`calc.review.edit`), ``case`` the case
    file read with them (what the inputs start from). An operation that cannot be made raises
    :class:`calc.core.errors.CalcError` saying why, the state left as it was.
    """

    def __init__(self, path):
        self.path = Path(path)
        self.file_text: str | None = None
        self.file_units = "SI"  # the unit system the case file writes its inputs in
        self.units = "SI"  # the unit system of the results shown
        self.all_candidates = False
        self.ratio_search = False
        self.moves: list = []
        self.case: Case | None = None
        self.specs: list[InputSpec] = []
        self.values: dict = {}
        self.texts: dict = {}
        self.refused: dict = {}  # key path -> (the text refused, why)
        self.history = History(self.snapshot())
        self.shown: Screen | None = None  # the results last evaluated

    # -- the case file and its inputs --------------------------------------------------------

    def load(self, path=None) -> None:
        """Read the case file ``path`` (by default the one reviewed) with its own values: no edit,
        nothing to undo, the results in the unit system its inputs are written in."""
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

    def _build(self, moves: list, values: dict) -> None:
        """The inputs of the case file with the ``moves`` edited, at ``values`` (by key path) where
        given, else at the case's; nothing changes where the edited case cannot be read."""
        moves = json.loads(json.dumps(moves))  # as the address and the history write them
        try:
            case = edited_case(self.path, self.file_text, [e for m in moves for e in moves_edits(m)])
            specs = review_specs(case)
        except CalcError as exc:
            raise CalcError(without_folder(str(exc), self.path)) from None
        self.case, self.moves, self.specs, self.refused = case, moves, specs, {}
        self.values = {s.key: values.get(s.key, s.value) for s in specs}
        self.texts = {s.key: _field_text(s, self.values[s.key]) for s in specs}

    def spec(self, key: str) -> InputSpec:
        return next(s for s in self.specs if s.key == key)

    def set_value(self, key: str, value) -> bool:
        """The input ``key`` set to ``value`` (a slider moved, a choice made); whether it changed."""
        if self.values[key] == value:
            return False
        self.values[key] = value
        if key not in self.refused:  # a refused text stays in its field until typed again
            self.texts[key] = _field_text(self.spec(key), value)
        self.history.push(self.snapshot())
        return True

    def type_text(self, key: str, text: str) -> bool:
        """A text typed into the field of ``key``: its value (:func:`calc.review.inputs.read_typed`),
        or refused with why. Whether the results change: a value changed, or a refusal made or
        taken back."""
        spec = self.spec(key)
        try:
            v = read_typed(text, spec)
        except CalcError as exc:
            self.refused[key] = (text, str(exc))
            self.texts[key] = text.strip()
            return True
        was_refused = self.refused.pop(key, None) is not None
        changed = self.values[key] != v
        self.values[key] = v
        self.texts[key] = spec.field_text(v) if changed else f"{v:g}"
        if changed:
            self.history.push(self.snapshot())
        return changed or was_refused

    def follow_values(self, texts: dict) -> None:
        """The inputs at the ``texts`` a link gives them (key path -> the field's text, a choice's
        option): an input the case does not have, or a text it does not take, says which."""
        for key, text in texts.items():
            spec = next((s for s in self.specs if s.key == key), None)
            if spec is None:
                raise CalcError(f"{self.path.name} has no input {key}")
            if spec.options:
                value = next((o for o in spec.options if option_text(o) == text), None)
            else:
                value = read_typed(text, spec)
            if value is None:
                raise CalcError(f"{spec.label}: {text!r} is not one of its choices")
            self.set_value(key, value)

    def changes(self) -> dict:
        """The inputs changed from the case file (with the moves' edits): key path -> (number or part, unit)."""
        return {s.key: (v, s.unit) for s in self.specs if not s.is_case_value(v := self.values[s.key])}

    def modified(self) -> bool:
        """Whether the screen differs from the case file: a value changed, or the moves edited."""
        return bool(self.moves or self.changes())

    def _value_edits(self) -> list:
        """The changed values as edits of the case file (a part left to the selection: its key taken out)."""
        changes = {key: (None if v == SELECTION else v) if isinstance(v, str) else (v, unit)
                   for key, (v, unit) in self.changes().items()}
        return input_edits(self.case, changes)

    def changed_case(self) -> Case:
        """The case file read with the moves' edits and the changed values written in (a value
        left where it started keeps the case's own, not the slider's rounding of it: a derived
        cycle's 7.8269 N·m stays, and stays derived)."""
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
        comment naming them (:func:`calc.review.edit.changed_text`): what :meth:`save` writes."""
        return changed_text(self.file_text, self.moves, self._value_edits(), self.path.name)

    def save(self, name: str) -> Path:
        """Write :meth:`case_text` as the new case file ``name`` beside the case file (never over
        a file); its path."""
        if self.refused:
            raise CalcError("a refused value is in a field: correct it (or undo) before saving")
        path = save_path(self.path, name.strip())
        try:
            path.write_text(self.case_text(), encoding="utf-8")
        except OSError as exc:
            raise CalcError(without_folder(str(exc), self.path)) from None
        return path

    def in_words(self, text: str) -> str:
        """An error as the page says it: the input's label where the text names its key path, and
        no folder of the server."""
        text = without_folder(text, self.path)
        for spec in sorted(self.specs, key=lambda s: -len(s.key)):
            text = text.replace(f"{spec.key}:", f"{spec.label}:")
        return text

    # -- undo and redo ---------------------------------------------------------------------------

    def snapshot(self) -> tuple:
        """What undo and redo step through: the moves' edits and the inputs' values."""
        return json.dumps(self.moves), dict(self.values)

    def undo(self) -> None:
        """Back to the state before the last change."""
        self._step(self.history.undo())

    def redo(self) -> None:
        """The change undone last, again."""
        self._step(self.history.redo())

    def _step(self, snapshot) -> None:
        if snapshot is None:
            return
        moves, values = snapshot
        if moves != json.dumps(self.moves):
            self._build(json.loads(moves), values)
            return
        for key, v in values.items():
            self.values[key] = v
            if key not in self.refused:
                self.texts[key] = _field_text(self.spec(key), v)

    # -- the moves edited: entries added and removed, the mechanism's type changed -----------------

    def entries(self) -> list[str]:
        """The entries of the moves, each ``"move"`` or ``"dwell"`` (none where the case has no moves)."""
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
        """Put a move (a copy of the move at or before entry ``after``, else the first) or a dwell
        (as long as the last dwell, else 1 s) in after entry ``after``."""
        kinds = self.entries()
        if kind == "move":
            before = list(range(after, 0, -1)) + list(range(after + 1, len(kinds) + 1))
            keys = self._entry_texts(next(k for k in before if kinds[k - 1] == "move"))  # a motion has a move
        else:
            dwells = [k for k in range(len(kinds), 0, -1) if kinds[k - 1] == "dwell"]
            keys = self._entry_texts(dwells[0]) if dwells else {"dwell": "1 s"}
        self._edit_moves(["add", after, keys])

    def remove_entry(self, k: int) -> None:
        """Take entry ``k`` out of the moves."""
        self._edit_moves(["remove", k])

    def change_mechanism(self, type_: str, size_text: str = "") -> str:
        """The mechanism of ``type_`` in place of the case's (of lead or diameter ``size_text`` in
        :meth:`length_unit`, for a linear type), its values and the moves' distances starting
        equivalent (:func:`calc.domain.mechanism.converted`); what it did, in words (with what it
        leaves out)."""
        try:
            size = None
            if type_ != "rotary":
                t = size_text.strip().replace(",", ".")
                if not TYPED.match(t) or not float(t) > 0:
                    what = "lead" if type_ == "ball-screw" else "diameter"
                    raise CalcError(f"a {type_} needs its {what}: expected a number above zero "
                                    f"(in {self.length_unit()}), found {size_text.strip()!r}")
                size = Q_(float(t), self.length_unit())
            edit = mechanism_edit(self.changed_case(), type_, size, self.length_unit() == "in")
        except CalcError as exc:
            raise CalcError(self.in_words(str(exc))) from None
        self._edit_moves(edit)
        return edit[3]

    def length_unit(self) -> str:
        """The unit of a mechanism's lead or diameter: inch where the case writes inch-pound."""
        return "in" if self.file_units == "inch-pound" else "mm"

    def follow_moves(self, moves: list) -> bool:
        """The edits of the moves a link carries: the case file's moves with those edits, at the
        file's values (the link's values follow); whether they differ from those made."""
        if json.dumps(moves) == json.dumps(self.moves):
            return False
        self._build(moves, {})
        self.history.push(self.snapshot())
        return True

    def _edit_moves(self, edit: list) -> None:
        """The inputs of the moves with ``edit`` as well, each value carried to its entry's new
        place (an entry removed takes its values with it)."""
        self._build([*self.moves, edit], _moved(self.values, edit))
        self.history.push(self.snapshot())

    def from_edits(self, key: str) -> str | None:
        """What the edits of the moves made of the input ``key``, or None: an entry added here,
        or a value set by a change of the mechanism's type."""
        m = _ENTRY.match(key)
        if m is not None and int(m.group(1)) in added_entries(self.moves):
            return "an entry added here: not in the file"
        set_by_type = key.startswith("mechanism.") or (m is not None and key.endswith(".distance"))
        if set_by_type and any(e[0] == "mechanism" for e in self.moves):
            return "set by the change of the mechanism's type: not in the file"
        return None

    # -- the results ---------------------------------------------------------------------------

    def evaluate(self) -> Screen:
        """The results of the state as it stands (kept as :attr:`shown`): the changed case
        evaluated whole (:func:`calc.review.view.evaluated`), and the ratio search where asked for."""
        texts, changes, moves = dict(self.texts), self.changes(), json.loads(json.dumps(self.moves))
        try:
            case, text = self._changed()
        except CalcError as exc:
            self.shown = Screen(None, None, [], self.in_words(str(exc)), None, False, moves, texts, changes)
            return self.shown
        report, left_out = evaluated(case)
        ratios = None
        if self.ratio_search:  # asked for: its own command's result, the case at every ratio
            try:
                ratios = search_ratios(case).to_json()
            except CalcError as exc:
                ratios = self.in_words(str(exc))
        typed = self.case.motion is not None and case.motion is None
        left_out = [self.in_words(x) for x in left_out]
        self.shown = Screen(case, report, left_out, None, ratios, typed, moves, texts, changes, text)
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
    size : Quantity or None
        A linear type's lead or diameter [mm or in].
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


def _field_text(spec: InputSpec, value) -> str:
    """An input's value as its field shows it (a choice: its option's text)."""
    return option_text(value) if spec.options else spec.field_text(value)


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
