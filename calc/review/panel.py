"""The design-review panel (ipywidgets): the controls on the left, the results beside them.

Left: the case, chosen among the case files of its folder (no path is typed, so the panel reads no
other file), with buttons back to its values and through the changes, one row per input
(the entries of the moves added and removed, the mechanism's type changed: :meth:`DesignReview.add_entry`,
:meth:`DesignReview.change_mechanism`, each an edit of the file's text the rows are built from)
(:func:`calc.review.inputs.input_specs`: the label with its unit and key path, a slider and a number
field read by :func:`read_typed`), the unit system, saving and variants, and the load-cycle
figure (SVG, drawn by the browser). Right: the state of the results
(current, out of date, connection lost: :mod:`calc.review.client`), the results as one HTML text
(:func:`calc.review.view.results_html`: verdict and chosen parts first, then the governing checks,
so they show without scrolling), the stiffness-chain figure and the variants compared.

A change updates the page once: the results text is replaced whole (it never collapses, so no
stale copy shows), the figures with it (SVG, :mod:`calc.review.figures`). Changes that arrive while one is being drawn are taken together: a worker thread draws
the controls' latest values, then looks again.
"""

from __future__ import annotations

import dataclasses
import json
import math
import re
import threading
from html import escape
from pathlib import Path
from urllib.parse import quote

from ..sections.case import Case, read_case
from ..core.errors import CalcError
from ..domain.mechanism import TYPES as MECHANISM_TYPES, converted, converted_distance
from ..report.publish import summary_rows
from ..sections import drive
from ..sections import motion as motion_section
from ..sections.gearbox import catalogs as gearbox_catalogs
from ..sections.ratios import search as search_ratios
from ..core.units import Q_, pretty_unit
from .client import STYLE as PAGE_STYLE, state_html
from .figures import load_cycle_svg, stiffness_chain_svg
from .inputs import MECHANISM, MOVE_TIMES, InputSpec, input_specs, is_inch_pound, with_inputs
from .keep import changed_text, edit_text, free_name, save_path, value_text, with_moves_edited
from .view import FAIL_COLOR, comparison_html, comparison_pdf, comparison_rows, evaluated, results_html, typeset, worst_utilizations

LABEL_WIDTH = "15.5em"
SHOWN_CANDIDATES = 6  # rows of each candidate table, best first, unless all are asked for


def _ratios(case: Case) -> list[float]:
    """The ratios of the case's gearbox catalog (the choices of the ratio control)."""
    return sorted(set(gearbox_catalogs(case)[0]["ratio"].m_as("").tolist()))


#: The gearbox choice that leaves the part to the selection (``[gearbox] part`` not given).
SELECTION = "the selection's"


def forced_part_spec(case: Case) -> InputSpec:
    """The gearbox part the reviewer forces (``[gearbox] part``, checked alone): a choice among
    the catalog's rows at the case's ratio (not the partial ones), or the selection's."""
    catalog = gearbox_catalogs(case)[0]
    ratio = float(case.ratio.m_as(""))
    parts = [str(p) for p, r, partial in zip(catalog.parts, catalog["ratio"].m_as(""), catalog.partial) if r == ratio and not partial]
    value = case.gearbox_part or SELECTION
    return InputSpec("gearbox.part", "gearbox part forced", "", 0, 0, 0, value, tuple(dict.fromkeys([SELECTION, *parts, value])))


def forced_motor_spec(case: Case) -> InputSpec:
    """The motor the reviewer forces (``[motor] part``, checked alone): a choice among the motor
    catalog's rows (not the partial ones), or the catalog's choice."""
    catalog = drive.motor_catalog(case)
    parts = [str(p) for p, partial in zip(catalog.parts, catalog.partial) if not partial]
    value = case.motor_part or SELECTION
    return InputSpec("motor.part", "motor part forced", "", 0, 0, 0, value, tuple(dict.fromkeys([SELECTION, *parts, value])))


#: A number as a reviewer types it: digits with a point or a decimal comma (``0,6``), a sign, an exponent.
_TYPED = re.compile(r"^[-+]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][-+]?\d+)?$")


def read_typed(text: str, spec: InputSpec) -> float:
    """The number a reviewer typed into the field of ``spec``: a decimal comma is read as a point;
    not a number, or outside the input's range, is refused with a sentence saying why (never
    clamped). A choice's text is one of its options.

    >>> from calc.review.inputs import InputSpec
    >>> spec = InputSpec("move[1].time", "1 move: time t", "s", 0.05, 1.5, 0.01, 0.5)
    >>> read_typed(" 0,6 ", spec)
    0.6
    >>> read_typed("2", spec)
    Traceback (most recent call last):
    ...
    calc.core.errors.CalcError: 2 s is outside the range of 1 move: time t, 0.05 s to 1.5 s: not applied
    """
    t = text.strip()
    unit = f" {pretty_unit(spec.unit)}" if spec.unit else ""
    if not _TYPED.match(t):
        raise CalcError(f"{t!r} is not a number: expected a number such as {spec.value:g} (in{unit or ' no unit'}), a decimal point or comma; not applied")
    v = float(t.replace(",", "."))
    if not math.isfinite(v) or not spec.low <= v <= spec.high:
        raise CalcError(f"{t}{unit} is outside the range of {spec.label}, {spec.low:g}{unit} to {spec.high:g}{unit}: not applied")
    return v


class DesignReview:
    """The design-review panel of the case file ``case_path``; any case file of the folder
    ``cases`` (by default the one it is in) can be chosen in the panel.

    ``controls`` holds each input's value widget by its key path (``motor.peak_torque``); setting
    one's ``value`` (by hand or in code) re-evaluates the case into ``results`` (the text) and the
    figures. ``fields`` holds the number field beside each slider: what is typed there is read by
    :func:`read_typed` and refused, with its message under the row, where it is not a number in the
    input's range. ``report_link(path)``, where given, returns the address of a case's report,
    which the panel links beside the verdict.

    ``reports``, where given, is the folder of the calc reports (``python -m calc report
    cases/*.toml --summary -o reports/``): the case chooser shows each case's verdict as its file
    reads (:func:`calc.report.publish.summary_rows`), and the link is shown only where the case's report
    was built, ``report_link`` then getting the report's path. The chooser's entry of the case
    shown gives the screen's verdict once an input is changed.

    The reviewer's changes are kept: :meth:`save` writes them as a new case file beside the
    original (:mod:`calc.review.keep`), :meth:`undo` and :meth:`redo` step through them, and
    :meth:`keep_variant` pins the current design beside the others (the comparison table).
    """

    def __init__(self, case_path, report_link=None, cases=None, reports=None):
        import ipywidgets as w

        path = Path(case_path)
        choices = sorted({*Path(cases or path.parent).glob("*.toml"), path})
        self.message = w.HTML()
        self.reports_folder, self.reports, self.labels = reports, {}, {p: p.name for p in choices}
        self._note = ""  # what the page says of the reports while any case is shown
        if reports is not None:
            try:
                rows = summary_rows(choices, str(reports))
            except CalcError as exc:
                self._note = f'<span style="color:{FAIL_COLOR}">no verdicts or reports: {typeset(str(exc))}</span>'
                rows = []
            for p, row in zip(choices, rows):
                self.labels[p] = f"{p.name} · {row['verdict']}"
                self.reports[p] = Path(row["report_path"])
        self.case_file = w.Dropdown(options=[(self.labels[p], p) for p in choices], value=path, description="case",
                                    style={"description_width": "3em"}, layout=w.Layout(flex="1 1 auto", width="auto"))
        self.case_file.add_class("dr-case")
        self._relabelling = False  # the chooser's options being rewritten, not a case chosen
        self.case_file.observe(lambda _: self._relabelling or self.load(), names="value")
        self.reset = w.Button(description="reset", tooltip="back to the values of the case file", layout=w.Layout(width="4.5em", flex="0 0 4.5em"))
        self.reset.on_click(lambda _: self.load())
        self.undo_button = w.Button(description="undo", tooltip="the values before the last change", layout=w.Layout(width="4.2em", flex="0 0 4.2em"), disabled=True)
        self.redo_button = w.Button(description="redo", tooltip="the change undone last", layout=w.Layout(width="4.2em", flex="0 0 4.2em"), disabled=True)
        self.undo_button.on_click(lambda _: self.undo())
        self.redo_button.on_click(lambda _: self.redo())
        self.report_link = report_link
        self.all_candidates = w.Checkbox(description="all candidates", indent=False, layout=w.Layout(width="auto", flex="1 1 auto"),
                                         tooltip=f"list every candidate in the tables, not the best {SHOWN_CANDIDATES}")
        self.controls_box = w.VBox(layout=w.Layout(overflow="hidden"))
        self.state = w.HTML(state_html())
        self.results = w.HTML(layout=w.Layout(width="100%"))
        self.load_cycle = w.HTML(layout=w.Layout(width="100%", max_width="560px"))  # SVG, drawn by the browser
        self.chain = w.HTML(layout=w.Layout(width="100%", max_width="640px"))  # SVG, drawn by the browser
        self.load_cycle.add_class("dr-figures")
        self.chain.add_class("dr-figures")
        # Kept: save as a case file beside the original, the same file to download, variants compared.
        self.save_name = w.Text(placeholder="new-case.toml", tooltip="the new case file's name, in the folder of the case",
                                layout=w.Layout(flex="1 1 auto", width="auto"))
        self.save_button = w.Button(description="Save as case file", tooltip="write the changed values into a new case file beside this one",
                                    layout=w.Layout(width="11em"))
        self.save_button.on_click(lambda _: self.save())
        self.variant_button = w.Button(description="Keep as variant", tooltip="pin the design on the screen beside the others",
                                       layout=w.Layout(width="11em"))
        self.variant_button.on_click(lambda _: self.keep_variant())
        self.report_button = w.Button(description="Calc report of this screen", layout=w.Layout(width="15em"),
                                      tooltip="save the changed values as a case file (Save as case file) and build its calc report (PDF)")
        self.report_button.on_click(lambda _: self.report_of_screen())
        self.variants_pdf_button = w.Button(description="Variants as PDF", layout=w.Layout(width="11em"), disabled=True,
                                            tooltip="the variants kept, side by side with their figure, as a PDF (A4)")
        self.variants_pdf_button.on_click(lambda _: self.variants_pdf())
        self.download = w.HTML()
        self.kept = w.HTML()
        self.variants_html = w.HTML(layout=w.Layout(width="100%"))
        self.variants: list = []  # (name, Report) pinned by keep_variant
        self.variant_states: list = []  # each variant's moves' edits and changed values as shown (for the page's address)
        self._variants_asked_for: list = []  # the variants' states a link asked for
        # The page's script hands the variants a link carries to the kernel through this field (hidden).
        self.variants_field = w.Text(continuous_update=False, layout=w.Layout(display="none"))
        self.variants_field.add_class("dr-variants-asked")
        self.variants_field.observe(lambda change: self._variants_asked(change["new"]), names="value")
        keep = w.VBox([w.HBox([self.save_name, self.save_button], layout=w.Layout(width="100%")),
                       w.HBox([self.variant_button, self.variants_pdf_button, self.report_button], layout=w.Layout(flex_flow="row wrap")),
                       self.download, self.kept, self.variants_field])
        keep.add_class("dr-keep")
        top = w.HBox([self.case_file, self.reset, self.undo_button, self.redo_button], layout=w.Layout(width="100%"))
        self.all_candidates.observe(self._changed, names="value")
        self.ratio_search = w.Checkbox(description="ratio search", indent=False, layout=w.Layout(width="auto", flex="1 1 auto"),
                                       tooltip="the case at every ratio of the gearbox catalog, and the ratio to pick")
        self.ratio_search.observe(self._changed, names="value")
        self.units = w.ToggleButtons(options=["SI", "inch-pound"], tooltip="the unit system of the results",
                                     style={"button_width": "7.5em"}, layout=w.Layout(width="auto", flex="0 0 auto"))
        self.units.observe(self._changed, names="value")
        # The moves as a reviewer edits them: an entry taken out, a move or a dwell put in after it.
        self.entry = w.Dropdown(description="moves", tooltip="an entry of the moves: remove it, or add a move or a dwell after it", style={"description_width": "3.5em"},
                                layout=w.Layout(width="auto", flex="1 1 auto"))
        self.remove_button = w.Button(description="remove", tooltip="take the chosen entry out of the moves", layout=w.Layout(width="5.5em"))
        self.add_move_button = w.Button(description="+ move", tooltip="a move after the chosen entry (a copy of the move at or before it)",
                                        layout=w.Layout(width="5.5em"))
        self.add_dwell_button = w.Button(description="+ dwell", tooltip="a dwell after the chosen entry (as long as the last dwell, else 1 s)",
                                         layout=w.Layout(width="5.5em"))
        self.remove_button.on_click(lambda _: self.remove_entry(self.entry.value))
        self.add_move_button.on_click(lambda _: self.add_entry(self.entry.value, "move"))
        self.add_dwell_button.on_click(lambda _: self.add_entry(self.entry.value, "dwell"))
        # The page's script replays the edits a link carries through this field (hidden).
        self.edits_field = w.Text(continuous_update=False, layout=w.Layout(display="none"))
        self.edits_field.add_class("dr-edits")
        self.edits_field.observe(lambda change: self._edits_asked(change["new"]), names="value")
        # The mechanism of another type, its starting values equivalent (calc.domain.mechanism.converted).
        self.mechanism_type = w.Dropdown(options=list(MECHANISM_TYPES), description="type", tooltip="the mechanism's type",
                                         style={"description_width": "3.5em"}, layout=w.Layout(width="auto", flex="1 1 auto"))
        self.mechanism_size = w.Text(placeholder="lead / diameter", tooltip="a screw's lead, a pinion's or pulley's diameter (a linear type)",
                                     layout=w.Layout(width="9em", flex="0 0 9em"))
        self.mechanism_button = w.Button(description="change type", layout=w.Layout(width="8em"),
                                         tooltip="the mechanism of the chosen type, starting from values equivalent at the gearbox output")
        self.mechanism_button.on_click(lambda _: self.change_mechanism(self.mechanism_type.value, self.mechanism_size.value))
        self.moves_editor = w.VBox([w.HBox([self.entry, self.remove_button, self.add_move_button, self.add_dwell_button], layout=w.Layout(width="100%")),
                                    w.HBox([self.mechanism_type, self.mechanism_size, self.mechanism_button], layout=w.Layout(width="100%")),
                                    self.edits_field], layout=w.Layout(width="100%"))
        self.moves_editor.add_class("dr-moves")
        left = w.VBox([w.HTML(PAGE_STYLE), top, self.message, self.controls_box, self.moves_editor,
                       w.HBox([self.all_candidates, self.ratio_search, self.units]), keep, self.load_cycle],
                      layout=w.Layout(flex="0 0 520px", width="520px", padding="0 16px 0 0"))
        right = w.VBox([self.state, self.results, self.chain, self.variants_html], layout=w.Layout(flex="1 1 560px", min_width="560px"))
        # Side by side on a screen; on a narrow one (a notebook beside a file browser) the results go under.
        self.panel = w.HBox([left, right], layout=w.Layout(width="100%", align_items="flex-start", flex_flow="row wrap"))
        self.panel.add_class("design-review")
        self.controls: dict = {}
        self.fields: dict = {}
        self._messages: dict = {}  # key path -> the HTML under its row (a refusal, or that it has no effect)
        self._labels: dict = {}  # key path -> its label
        self.refused: dict = {}  # key path -> the refused text, with why
        self.specs: list[InputSpec] = []
        self.case: Case | None = None  # the case the controls start from: the file's, with the moves' edits
        self.file_text: str | None = None
        self.file_units = "SI"  # the unit system the case file writes its inputs in
        self.edits: list = []  # the edits of the moves (calc.review.keep.with_moves_edited), in order
        self._added: set = set()  # the entries of the moves added by them
        self.shown: tuple | None = None  # (case, report) of the results on the screen
        self._history: list[tuple] = []  # (edits of the moves, the controls' values) after each change, for undo and redo
        self._undone: list[tuple] = []
        self._stepping = False
        self._dirty = False
        self._worker: threading.Thread | None = None
        self._lock = threading.Lock()
        self.generation = 0  # counts the updates drawn (the page carries it, for tests and timing)
        self.load()

    def _repr_mimebundle_(self, **kwargs):
        bundle = self.panel._repr_mimebundle_(**kwargs)
        bundle["text/plain"] = f"design review panel of {self.case_file.value.name}"
        return bundle

    # -- the controls ------------------------------------------------------------------------

    def load(self) -> None:
        """Read the chosen case file and build one control row per input."""
        try:
            self.file_text = self.case_file.value.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            self.file_text = None  # the reader says why
        if self._build([], {}):
            # The results in the units the case file writes: inch-pound where its inputs are.
            self.file_units = "inch-pound" if self._writes_inch_pound() else "SI"
            self.units.unobserve(self._changed, names="value")
            self.units.value = self.file_units
            self.units.observe(self._changed, names="value")
            self._history, self._undone = [self._state()], []
            self.save_name.value = free_name(self.case.path)
            self.refresh()

    def _build(self, edits: list, values: dict, failed: str = "error") -> bool:
        """Build one control row per input of the case file with the moves' ``edits``, the controls
        at ``values`` (by key path) where given, else at the case's; False, and the reason in the
        message, where the edited case cannot be read."""
        path = self.case_file.value
        try:
            case = _edited_case(path, self.file_text, edits)  # no text: the file as it is, or why it cannot be read
            ratios = _ratios(case) if case.ratio is not None else []
        except CalcError as exc:
            self.message.value = f'<b style="color:{FAIL_COLOR}">{failed}</b>: {typeset(_without_folder(str(exc), path))}'
            return False
        self.case, self.edits, self.message.value = case, list(edits), self._note
        self.specs = _specs_of(case, ratios)
        self._added = _added_entries(edits)
        self.controls, self.fields, self._messages, self._labels, self.refused = {}, {}, {}, {}, {}
        old = self.controls_box.children
        self.controls_box.children = [self._row(spec, values.get(spec.key, spec.value)) for spec in self.specs]
        for row in old:
            _close(row)
        for control in self.controls.values():
            control.observe(self._changed, names="value")
        entries = case.motion.tables["move"] if case.motion is not None and case.motion.moves else []
        self.moves_editor.layout.display = None if entries else "none"
        self.entry.options = [(f"{k} {'dwell' if 'dwell' in m else 'move'}", k) for k, m in enumerate(entries, start=1)]
        self.entry.value = len(entries) if entries else None
        self.remove_button.disabled = len(entries) < 2
        if entries:
            self.mechanism_type.value = case.motion.mechanism.type
            unit = self._length_unit()
            size = case.motion.mechanism.lead if case.motion.mechanism.type == "ball-screw" else case.motion.mechanism.diameter
            self.mechanism_size.value = "" if size is None else f"{size.m_as(unit):.6g}"
            self.mechanism_size.placeholder = f"lead / diameter [{unit}]"
        return True

    def _writes_inch_pound(self) -> bool:
        """Whether the case file writes its inputs in inch-pound units."""
        return any(is_inch_pound(s.unit) for s in self.specs)

    def _length_unit(self) -> str:
        """The unit of a mechanism's lead or diameter: inch where the case writes inch-pound."""
        return "in" if self._writes_inch_pound() else "mm"

    def _row(self, spec: InputSpec, value):
        """One input: its label with unit (the whole of it also as tooltip, its key path as
        ``data-key``), a slider and a number field, or a choice; under it, where there is one, a
        message (a refused value, or that the input has no effect on the design)."""
        import ipywidgets as w

        label = w.HTML(self._label_html(spec, changed=False, added=self._from_edits(spec.key)), layout=w.Layout(width=LABEL_WIDTH, flex="0 0 " + LABEL_WIDTH))
        label.add_class("dr-label")
        self._labels[spec.key] = label
        message = w.HTML()
        self._messages[spec.key] = message
        if spec.options:
            control = w.Dropdown(options=[(_text_of(r), r) for r in spec.options], value=value, tooltip=spec.text,
                                 layout=w.Layout(width="auto", flex="1 1 auto"))  # the row's width: no choice cut short
            self.controls[spec.key] = control
            line = w.HBox([label, control])
        else:
            slider = w.FloatSlider(value=value, min=spec.low, max=spec.high, step=spec.step, readout=False,
                                   continuous_update=False, tooltip=spec.text, layout=w.Layout(flex="1 1 auto", width="auto"))
            field = w.Text(value=spec.field_text(value), continuous_update=False, tooltip=f"{spec.text}: {spec.low:g} to {spec.high:g}",
                           layout=w.Layout(width="6.5em", flex="0 0 6.5em"))
            # The field is read here, not by the browser's number input, which clamps to the range
            # and drops a decimal comma without a word.
            field.observe(lambda change, spec=spec: self._typed(spec, change["new"]), names="value")
            slider.observe(lambda change, key=spec.key: self._slid(key, change["new"]), names="value")
            self.controls[spec.key], self.fields[spec.key] = slider, field
            line = w.HBox([label, slider, field], layout=w.Layout(width="100%"))
        row = w.VBox([line, message], layout=w.Layout(width="100%"))
        row.add_class("dr-row")
        return row

    @staticmethod
    def _label_html(spec: InputSpec, changed: bool, added: str | None = None) -> str:
        unit = " [" + pretty_unit(spec.unit) + "]" if spec.unit else ""
        was = (f" ({added})" if added
               else f" (changed; the file: {spec.field_text(spec.value) if not spec.options else _text_of(spec.value)}{' ' + pretty_unit(spec.unit) if spec.unit else ''})" if changed else "")
        return (f'<span title="{escape(spec.text + was)}" data-key="{escape(spec.key)}"{" class=dr-changed" if changed or added else ""}>'
                f"{typeset(spec.label)}{unit}</span>")

    def _typed(self, spec: InputSpec, text: str) -> None:
        """A value typed into a field: applied through its slider, or refused at the field."""
        field = self.fields[spec.key]
        try:
            v = read_typed(text, spec)
        except CalcError as exc:
            self.refused[spec.key] = (text, str(exc))
            field.add_class("dr-refused")
            self._show_message(spec.key)
            self._changed(None)  # the results say that a value was refused
            return
        was_refused = self.refused.pop(spec.key, None) is not None
        field.remove_class("dr-refused")
        self._show_message(spec.key)
        if f"{v:g}" != text.strip():
            field.value = f"{v:g}"  # a decimal comma shown as the point it was read as
        if self.controls[spec.key].value != v:
            self.controls[spec.key].value = v
        elif was_refused:
            self._changed(None)

    def _slid(self, key: str, v: float) -> None:
        field = self.fields[key]
        text = self._spec(key).field_text(v)
        if key not in self.refused and field.value.strip() != text:
            field.value = text

    def _show_message(self, key: str, idle: str = "") -> None:
        if key in self.refused:
            self._messages[key].value = f'<div class="dr-message">{typeset(self.refused[key][1])}</div>'
        elif idle:
            self._messages[key].value = f'<div class="dr-idle">{typeset(idle)}</div>'
        else:
            self._messages[key].value = ""

    def _values(self) -> dict:
        return {s.key: self.controls[s.key].value for s in self.specs}

    def _state(self) -> tuple:
        """What undo and redo step through: the moves' edits and the controls' values."""
        return json.dumps(self.edits), self._values()

    def changes(self) -> dict:
        """The inputs changed from the case file (with the moves' edits): key path -> (number, unit)."""
        return {s.key: (v, s.unit) for s in self.specs if not s.is_case_value(v := self.controls[s.key].value)}

    def modified(self) -> bool:
        """Whether the screen differs from the case file: a value changed, or the moves edited."""
        return bool(self.edits or self.changes())

    def _from_edits(self, key: str) -> str | None:
        """What the edits of the moves made of the input ``key``, or None: an entry added here,
        or a value set by a change of the mechanism's type."""
        m = _ENTRY.match(key)
        if m is not None and int(m.group(1)) in self._added:
            return "an entry added here: not in the file"
        if any(e[0] == "mechanism" for e in self.edits) and (key.startswith("mechanism.") or (m is not None and key.endswith(".distance"))):
            return "set by the change of the mechanism's type: not in the file"
        return None

    # -- the moves edited: entries added and removed ---------------------------------------------------

    def _entry_texts(self, k: int) -> dict:
        """Entry ``k`` of the moves as a case file writes it, at the controls' values (a ramp the
        file leaves out only where it was changed)."""
        table = self.case.motion.tables["move"][k - 1]
        names = ("dwell",) if "dwell" in table else ("distance", *(n for n, _ in MOVE_TIMES))
        out, changed = {}, self.changes()
        for name in names:
            key = f"move[{k}].{name}"
            if key in self.controls and (name in table or key in changed):
                out[name] = value_text(self.controls[key].value, self._spec(key).unit)
        return out

    def add_entry(self, after: int, kind: str) -> None:
        """Put a move (a copy of the move at or before entry ``after``, else the first) or a dwell
        (as long as the last dwell, else 1 s) in after entry ``after``."""
        entries = self.case.motion.tables["move"]
        is_move = lambda k: "dwell" not in entries[k - 1]  # noqa: E731
        before = list(range(after, 0, -1)) + list(range(after + 1, len(entries) + 1))
        if kind == "move":
            source = next(k for k in before if is_move(k))  # a motion has a move
            keys = self._entry_texts(source)
        else:
            dwells = [k for k in range(len(entries), 0, -1) if not is_move(k)]
            keys = self._entry_texts(dwells[0]) if dwells else {"dwell": "1 s"}
        self._edit_moves(("add", after, keys))

    def remove_entry(self, k: int) -> None:
        """Take entry ``k`` out of the moves."""
        self._edit_moves(("remove", k))

    def _edit_moves(self, edit) -> None:
        """Rebuild the controls for the moves with ``edit`` as well, each value carried to its
        entry's new place (an entry removed takes its values with it)."""
        values = _moved(self._values(), edit)
        if self._build([*self.edits, edit], values, failed="not added" if edit[0] == "add" else "not removed"):
            self._changed(None)

    def change_mechanism(self, type_: str, size_text: str = "") -> None:
        """The mechanism of ``type_`` in place of the case's (of lead or diameter ``size_text`` in
        the case's length unit, for a linear type), its values and the moves' distances starting
        equivalent (:func:`calc.domain.mechanism.converted`): what it leaves out is said under the moves."""
        try:
            case = self.changed_case()
            old = case.motion.mechanism
            size = None
            if type_ != "rotary":
                t = size_text.strip().replace(",", ".")
                if not _TYPED.match(t) or not float(t) > 0:
                    raise CalcError(f"a {type_} needs its {'lead' if type_ == 'ball-screw' else 'diameter'}: expected a number above zero "
                                    f"(in {self._length_unit()}), found {size_text.strip()!r}")
                size = Q_(float(t), self._length_unit())
            new, left = converted(old, type_, size)
        except CalcError as exc:
            self.message.value = f'<b style="color:{FAIL_COLOR}">type not changed</b>: {typeset(self._in_words(str(exc)))}'
            return
        inch = self._writes_inch_pound()
        keys = {}
        for key in motion_section.keys_of(type_):
            attribute = MECHANISM_ATTRIBUTES.get(key.name, key.name)
            q = getattr(new, attribute, None) if key.name != "type" else type_
            if key.name == "type" or (key.name == "holding_brake" and q):
                keys[key.name] = q
            elif q is not None and key.name in MECHANISM:
                unit = MECHANISM[key.name][1] if inch else key.unit
                v = float(q.m_as(unit or ""))
                v = 0.0 if abs(v) < 1e-9 else v  # cos 90° is 6e-17 in floating point: a vertical axis' guide carries nothing
                keys[key.name] = v if not unit else value_text(v, unit)
        distances, unit = {}, "deg" if not new.linear else ("in" if inch else "mm")
        for k, given in enumerate(case.motion.distances, start=1):  # None: a dwell
            if given is not None:
                distances[k] = value_text(float(converted_distance(old, new, given).m_as(unit)), unit)
        said = f"mechanism {old.type} -> {type_}" + (f" of {value_text(size.magnitude, self._length_unit())}" if size is not None else "")
        said += " (equivalent at the gearbox output" + (f"; left out: {'; '.join(left)})" if left else ")")
        edit = ("mechanism", keys, distances, said)
        if self._build([*self.edits, edit], _moved(self._values(), edit), failed="type not changed"):
            self.message.value = typeset(said)
            self._changed(None)

    def _edits_asked(self, text: str) -> None:
        """The edits of the moves a link carries (the page's script writes them here): the
        case file's moves with those edits, at the file's values (the link's values follow)."""
        if not text:
            return
        try:
            edits = [tuple(e) for e in json.loads(text)]
        except (ValueError, TypeError):
            return
        if edits != self.edits and self._build(edits, {}):
            self._changed(None)

    def _shown_texts(self) -> dict:
        """Each control's text as the page shows it (the results' stamp, compared in the browser)."""
        return {s.key: (self.fields[s.key].value.strip() if s.key in self.fields else _text_of(self.controls[s.key].value)) for s in self.specs}

    # -- the results ---------------------------------------------------------------------------

    def changed_case(self) -> Case:
        """The loaded case with the values of the controls that were moved (one left where it
        started keeps the case's own value, not the control's rounding of it: a derived cycle's
        7.8269 N·m stays, and stays derived)."""
        return _with_changes(self.case, self.changes())

    def _draw(self):
        """The results text and the changed case (None where the inputs cannot make one)."""
        try:
            case = self.changed_case()
        except CalcError as exc:
            return f'<div class="dr"><b style="color:{FAIL_COLOR}">input error</b>: {typeset(self._in_words(str(exc)))}</div>', None
        report, left_out = evaluated(case)
        left_out = [self._in_words(x) for x in left_out]
        link = self._report_address(case.path) if not self.modified() else None  # the file's report, while the screen is the file
        typed = self.case.motion is not None and case.motion is None
        shown = None if self.all_candidates.value else SHOWN_CANDIDATES
        refused = [f"{self._spec(k).label}: {why}" for k, (_, why) in self.refused.items()]
        ratios = None
        if self.ratio_search.value:  # asked for: its own command's result, the case at every ratio
            try:
                ratios = search_ratios(case).to_json()
            except CalcError as exc:
                ratios = self._in_words(str(exc))
        return (results_html(report, left_out, link, typed_by_hand=typed, shown=shown, refused=refused, system=self.units.value,
                             ratios=ratios), (case, report))

    def _spec(self, key: str) -> InputSpec:
        return next(s for s in self.specs if s.key == key)

    def _in_words(self, text: str) -> str:
        """An error as the page says it: the control's label where the text names its key path,
        and no folder of the server."""
        text = _without_folder(text, self.case.path)
        for spec in sorted(self.specs, key=lambda s: -len(s.key)):
            text = text.replace(f"{spec.key}:", f"{spec.label}:")
        return text

    def _report_address(self, path: Path) -> str | None:
        """The address of the report of the case file ``path``: given the reports' folder, only
        where the report was built."""
        if self.report_link is None:
            return None
        if self.reports_folder is None:
            return self.report_link(path)
        pdf = self.reports.get(path)
        return self.report_link(pdf) if pdf is not None and pdf.is_file() else None

    def refresh(self) -> None:
        """Draw the results of the controls' values: each figure whose inputs changed, then the
        text (last, so that when the text changes on the page, everything has). The text carries
        the field texts it was computed for (``data-inputs``), and the changed ones
        (``data-changed``), which the page's script compares with the fields."""
        stamp = self._shown_texts()
        text, drawn = self._draw()
        self.shown = drawn
        changes = self.changes()
        self._shown_state = (json.loads(json.dumps(self.edits)), {k: stamp[k] for k in changes}, changes)
        if drawn is not None:
            case, report = drawn
            torque_unit = "lbf*in" if self.units.value == "inch-pound" else "N*m"
            sections = {} if report.evaluated is None else report.evaluated.sections  # None: the case cannot be evaluated
            self.load_cycle.value = load_cycle_svg(case.profile, sections["profile"].shown if sections else None, torque_unit)
            self.load_cycle.layout.display = None
            accuracy = sections.get("accuracy")
            if accuracy is not None:
                self.chain.value = stiffness_chain_svg(accuracy.shown)
            self.chain.layout.display = None if accuracy is not None else "none"
            self._idle_inputs(report)
            self._chooser_verdict(report, changes)
        else:  # the figures of the last good inputs no longer apply
            self.load_cycle.layout.display = self.chain.layout.display = "none"
        for spec in self.specs:
            label = self._label_html(spec, spec.key in changes, self._from_edits(spec.key))
            if self._labels[spec.key].value != label:  # each value set is a message to the page
                self._labels[spec.key].value = label
        self._keep_history()
        self._offer_download(changes)
        if self.variants:  # in the unit system shown
            compared = comparison_html(self.variants, self.units.value)
            if self.variants_html.value != compared:
                self.variants_html.value = compared
        self.generation += 1
        attributes = (f'data-generation="{self.generation}" data-case="{escape(self.case.path.name)}" '
                      f'data-inputs="{escape(json.dumps(stamp))}" data-edits="{escape(json.dumps(self.edits))}" '
                      f'data-units="{escape(self.units.value)}" data-file-units="{escape(self.file_units)}" '
                      f'{self._variants_attribute()} '
                      f'data-changed="{escape(json.dumps({k: stamp[k] for k in changes}))}"')
        self.results.value = text.replace('<div class="dr">', f'<div class="dr" {attributes}>', 1)

    def _idle_inputs(self, report) -> None:
        """An input that has no effect on the design as it stands says so under its row (a
        temperature on a coupling type without a temperature factor)."""
        if "coupling.temperature" not in self._messages or report.evaluated is None:
            return
        c = report.evaluated.sections.get("coupling")
        idle = ""
        if c is not None and c.inputs.type == "bellows":
            idle = "no effect on this design: a metal bellows coupling has no temperature factor (E9)"
        self._show_message("coupling.temperature", idle)

    def _chooser_verdict(self, report, changes: dict) -> None:
        """The chooser's entry of the case shown gives the screen's verdict, not the file's, once
        an input is changed."""
        path = self.case.path
        if path not in self.labels:
            return
        changed = bool(changes or self.edits)
        word = report.verdict.word if not changed else f"{report.verdict.word} (changed here)"
        label = f"{path.name} · {word}" if (changed or " · " in self.labels[path]) else self.labels[path]
        options = [(label if p == path else self.labels[p], p) for _, p in self.case_file.options]
        if options != list(self.case_file.options):
            self._relabel(options)

    def _relabel(self, options: list) -> None:
        """New options for the chooser, the case shown staying chosen (and not read again)."""
        self._relabelling = True
        try:
            self.case_file.options = options
            self.case_file.value = self.case.path
        finally:
            self._relabelling = False

    def _changed(self, _change) -> None:
        """A control moved: the results marked out of date at once, and drawn in the worker
        thread; what moves meanwhile is drawn after, once."""
        with self._lock:
            self._dirty = True
            if self._worker is not None:
                return
            self._busy(True)
            self._worker = threading.Thread(target=self._work, daemon=True)
            self._worker.start()

    def _busy(self, busy: bool) -> None:
        """Mark the results out of date while a change is computed (``dr-busy``, the state line)."""
        (self.panel.add_class if busy else self.panel.remove_class)("dr-busy")
        self.state.value = state_html(busy)

    def _work(self) -> None:
        while True:
            with self._lock:  # "nothing left" and "no worker" at once, so no change slips between
                if not self._dirty:
                    self._worker = None
                    self._busy(False)
                    return
                self._dirty = False
            try:
                self.refresh()
            except BaseException:  # a fault shows in the log; the next change starts a worker again
                with self._lock:
                    self._worker = None
                    self._busy(False)
                raise

    def settled(self) -> "DesignReview":
        """Wait until the changes made so far are drawn (for code that sets controls, then reads)."""
        while True:
            with self._lock:
                worker = self._worker
            if worker is None:
                return self
            worker.join()

    # -- kept: undo, save, download, variants ------------------------------------------------------

    def _keep_history(self) -> None:
        state = self._state()
        if not self._stepping and state != self._history[-1]:
            self._history.append(state)
            self._undone = []
        self.undo_button.disabled, self.redo_button.disabled = len(self._history) < 2, not self._undone

    def _step_to(self, state: tuple) -> None:
        edits, values = state
        self._stepping = True
        try:
            if edits != json.dumps(self.edits):
                self._build([tuple(e) for e in json.loads(edits)], values)
            for key, v in values.items():
                self.controls[key].value = v
            self.settled()
            self.refresh()
        finally:
            self._stepping = False

    def undo(self) -> None:
        """Back to the values before the last change."""
        if len(self._history) > 1:
            self._undone.append(self._history.pop())
            self._step_to(self._history[-1])

    def redo(self) -> None:
        """The change undone last, again."""
        if self._undone:
            self._history.append(self._undone.pop())
            self._step_to(self._history[-1])

    def case_text(self) -> str:
        """The case file with the changed values written in (:func:`calc.review.keep.changed_text`)."""
        path = self.case.path
        changes = {k: ((None, u) if v == SELECTION else (v, u)) for k, (v, u) in self.changes().items()}
        return changed_text(_edited_text(path, self.file_text, self.edits), changes, path.name, self.edits)

    def save(self, name: str | None = None) -> Path | None:
        """Write the changed values as the new case file ``name`` (by default the save field's)
        beside the case file; never over an existing file. The new file is offered in the chooser.
        Says what it did, or why not, under the buttons; returns the new file's path."""
        try:
            if self.refused:
                raise CalcError("a refused value is in a field: correct it (or undo) before saving")
            path = save_path(self.case.path, (name or self.save_name.value).strip())
            path.write_text(self.case_text(), encoding="utf-8")
        except (CalcError, OSError) as exc:
            self.kept.value = f'<span style="color:{FAIL_COLOR}">not saved: {typeset(_without_folder(str(exc), self.case.path))}</span>'
            return None
        self.labels[path] = path.name
        self._relabel(sorted([*self.case_file.options, (path.name, path)], key=lambda o: o[1]))
        self.kept.value = f"saved as {escape(path.name)} beside {escape(self.case.path.name)} (in the case chooser)"
        self.save_name.value = free_name(self.case.path)
        return path

    def _offer_download(self, changes: dict) -> None:
        """The same file as *Save as case file* writes, as a link to download."""
        if not (changes or self.edits) or self.refused:
            self.download.value = ""
            return
        try:
            text = self.case_text()
        except CalcError:
            self.download.value = ""
            return
        self.download.value = (f'<a download="{escape(self.save_name.value)}" href="data:application/toml;charset=utf-8,{quote(text)}">'
                               "Download the case file</a>")

    def report_of_screen(self, wait: bool = False):
        """Build the calc report of the design on the screen: the case file itself while nothing
        is changed, else the changed values saved first (:meth:`save`), so the report rests on a
        file that reproduces it. The PDF goes to the reports' folder (the case's folder where none
        is given) and is linked under the buttons once built (``python -m calc report``, some 15 s,
        in a process of its own so the page keeps answering). Returns the thread building it."""
        path = self.case.path if not self.modified() else self.save()
        if path is None:
            return None
        folder = Path(self.reports_folder) if self.reports_folder else path.parent
        pdf = folder / f"{path.stem}.pdf"
        self.kept.value = f"building the calc report of {escape(path.name)} (some 15 s) …"

        def build():
            done = _build_report(path, pdf)
            if done.returncode != 0 or not pdf.is_file():
                why = (done.stderr.strip().splitlines() or [f"exit {done.returncode}"])[-1]
                self.kept.value = f'<span style="color:{FAIL_COLOR}">no calc report of {escape(path.name)}: {typeset(_without_folder(why, path))}</span>'
                return
            self.reports[path] = pdf
            address = self.report_link(pdf) if self.report_link is not None else None
            link = f'<a href="{escape(address)}" target="_blank">{escape(pdf.name)}</a>' if address else escape(str(pdf))
            self.kept.value = f"calc report of {escape(path.name)}, the screen's design: {link}"

        worker = threading.Thread(target=build, daemon=True)
        worker.start()
        if wait:
            worker.join()
        return worker

    def keep_variant(self) -> None:
        """Pin the design on the screen (its name says what changed) beside the variants kept
        before, in the comparison table under the results."""
        if self.shown is None:
            self.kept.value = f'<span style="color:{FAIL_COLOR}">not kept: the inputs give no design (an input error)</span>'
            return
        _, report = self.shown
        edits, texts, changes = self._shown_state
        name = _variant_name(len(self.variants) + 1, self.case.path.name, self.specs, changes, edits)
        self.variants.append((name, report))
        self.variant_states.append({"case": self.case.path.name, "edits": edits, "values": texts})
        self._show_variants()
        self.kept.value = f"kept variant {len(self.variants)}"

    def _show_variants(self) -> None:
        self.variants_html.value = comparison_html(self.variants, self.units.value) if self.variants else ""
        self.variants_pdf_button.disabled = not self.variants
        # The results carry the variants' states, for the page's address.
        self.results.value = re.sub(r'data-variants="[^"]*" data-variants-asked="[^"]*"', self._variants_attribute(), self.results.value, count=1)

    def variants_pdf(self) -> Path | None:
        """The variants kept, side by side with their figure (:func:`calc.review.view.comparison_pdf`,
        in the unit system shown), as ``<case>-variants-N.pdf`` in the reports' folder (the case's
        folder where none is given), never over a file; linked under the buttons."""
        if not self.variants:
            return None
        folder = Path(self.reports_folder) if self.reports_folder else self.case.path.parent
        n = 1
        while (pdf := folder / f"{self.case.path.stem}-variants-{n}.pdf").exists():
            n += 1
        rows = comparison_rows(self.variants, self.units.value)
        comparison_pdf([f"variant {k}" for k in range(1, len(self.variants) + 1)], rows, worst_utilizations(self.variants), pdf,
                       legend=[name for name, _ in self.variants])
        address = self.report_link(pdf) if self.report_link is not None else None
        link = f'<a href="{escape(address)}" target="_blank">{escape(pdf.name)}</a>' if address else escape(str(pdf))
        self.kept.value = f"the variants compared, as a PDF: {link}"
        return pdf

    def _variants_attribute(self) -> str:
        """The variants' states, and those a link asked for (which the page's script waits for)."""
        return (f'data-variants="{escape(json.dumps(self.variant_states))}" '
                f'data-variants-asked="{escape(json.dumps(self._variants_asked_for))}"')

    def _variants_asked(self, text: str) -> None:
        """The variants a link carries (the page's script writes their states here: the moves'
        edits and the changed values as the fields showed them), each evaluated again from the
        case file; one that no longer reads is left out and said."""
        try:
            states = json.loads(text) if text else []
            states = [{"case": str(st["case"]), "edits": [list(e) for e in st["edits"]], "values": dict(st["values"])} for st in states]
        except (ValueError, TypeError, KeyError, AttributeError):
            return
        self._variants_asked_for = states
        if states == self.variant_states:
            self._show_variants()
            return
        variants, kept, missed = [], [], []
        for k, state in enumerate(states, start=1):
            try:
                variants.append(self._variant_of(len(variants) + 1, state))
                kept.append(state)
            except CalcError as exc:
                missed.append(f"variant {k}: {self._in_words(str(exc))}")
        self.variants, self.variant_states = variants, kept
        self.kept.value = f'<span style="color:{FAIL_COLOR}">not kept from the link: {typeset("; ".join(missed))}</span>' if missed else ""
        self._show_variants()

    def _variant_of(self, number: int, state: dict) -> tuple:
        """(name, report) of a variant's state, from its case file (one of the chooser's) as :meth:`load` reads it."""
        path = next((p for p in self.labels if p.name == state["case"]), None)
        if path is None:
            raise CalcError(f"no case file {state['case']!r} among the cases")
        edits = [tuple(e) for e in state["edits"]]
        case = _edited_case(path, path.read_text(encoding="utf-8"), edits)
        specs = {spec.key: spec for spec in _specs_of(case, _ratios(case) if case.ratio is not None else [])}
        changes = {}
        for key, text in state["values"].items():
            spec = specs.get(key)
            if spec is None:
                raise CalcError(f"{path.name} has no input {key}")
            value = next((o for o in spec.options if _text_of(o) == text), None) if spec.options else read_typed(text, spec)
            if value is None:
                raise CalcError(f"{spec.label}: {text!r} is not one of its choices")
            if not spec.is_case_value(value):
                changes[key] = (value, spec.unit)
        report, _ = evaluated(_with_changes(case, dict(changes)))
        return _variant_name(number, path.name, specs.values(), changes, edits), report


def _edited_text(path: Path, text: str | None, edits) -> str | None:
    """The text ``text`` of the case file ``path`` with the moves' ``edits`` (none: the text)."""
    return with_moves_edited(text, edits, path.name) if edits else text


def _edited_case(path: Path, text: str | None, edits) -> Case:
    """The case file ``path`` of the text ``text`` (None: as the file reads) with the moves' ``edits``."""
    return read_case(path, _edited_text(path, text, edits))


def _specs_of(case: Case, ratios) -> list[InputSpec]:
    """The panel's inputs of ``case``: :func:`calc.review.inputs.input_specs`, and the parts to force."""
    return (input_specs(case, ratios) + ([forced_part_spec(case)] if case.ratio is not None else [])
            + ([forced_motor_spec(case)] if case.motor_catalog is not None else []))


def _with_changes(case: Case, changes: dict) -> Case:
    """``case`` with the inputs ``changes`` (key path -> (number or part, unit)) written in; a part
    forced is checked alone (the file's part, where it names one, is the unchanged value)."""
    changes = dict(changes)
    forced = changes.pop("gearbox.part", (None, ""))[0]
    motor = changes.pop("motor.part", (None, ""))[0]
    case = with_inputs(case, {key: Q_(v, unit) for key, (v, unit) in changes.items()})
    if forced is not None:
        case = dataclasses.replace(case, gearbox_part=None if forced == SELECTION else forced)
    if motor is not None:
        case = drive.with_motor_part(case, None if motor == SELECTION else motor, f"{case.path}: motor.part")
    return case


def _variant_name(number: int, file: str, specs, changes: dict, edits) -> str:
    """A variant's name: its number, the case file, and what was changed in it."""
    labels = {spec.key: spec.label for spec in specs}
    said = "; ".join([edit_text(e) for e in edits]
                     + [f"{labels[k]} {v if isinstance(v, str) else value_text(v, pretty_unit(u))}" for k, (v, u) in changes.items()])
    return f"{number}: {file}" + (f" with {said}" if said else " as written")


#: The attribute of :class:`calc.domain.mechanism.Mechanism` of each of its keys that is named otherwise.
MECHANISM_ATTRIBUTES = {"pitch_diameter": "diameter", "pulley_diameter": "diameter",
                        "screw_inertia": "own_inertia", "pinion_inertia": "own_inertia", "pulley_inertia": "own_inertia"}

#: An input of an entry of the moves: ``move[2].time``.
_ENTRY = re.compile(r"^move\[(\d+)\]\.")


def _place(k: int, edit) -> int | None:
    """The place of entry ``k`` of the moves after ``edit`` (None: the entry removed)."""
    if edit[0] == "add":
        return k + 1 if k > edit[1] else k
    if edit[0] == "remove":
        return None if k == edit[1] else k - 1 if k > edit[1] else k
    return k


def _added_entries(edits) -> set:
    """The entries of the moves (counted from 1, after ``edits``) that the edits added."""
    added: list = []  # the added entries' places, kept up to date edit by edit
    for edit in edits:
        added = [p for k in added if (p := _place(k, edit)) is not None] + ([edit[1] + 1] if edit[0] == "add" else [])
    return set(added)


def _moved(values: dict, edit) -> dict:
    """The controls' ``values`` with each entry's inputs at its place after ``edit``.

    >>> _moved({"move[1].time": 0.5, "move[2].dwell": 1.0, "motor.inertia": 2.0}, ("add", 1, {}))
    {'move[1].time': 0.5, 'move[3].dwell': 1.0, 'motor.inertia': 2.0}
    >>> _moved({"move[1].time": 0.5, "move[2].dwell": 1.0}, ("remove", 1))
    {'move[1].dwell': 1.0}
    """
    if edit[0] == "mechanism":  # it writes the mechanism's values and the distances itself
        return {key: v for key, v in values.items() if not key.startswith("mechanism.") and not (_ENTRY.match(key) and key.endswith(".distance"))}
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


def _text_of(value) -> str:
    """A choice's value as the page shows it: a ratio as ``8``, a part by its name."""
    return value if isinstance(value, str) else f"{value:g}"


def _build_report(case: Path, pdf: Path):
    """``python -m calc report case -o pdf`` (the completed process)."""
    import subprocess
    import sys

    return subprocess.run([sys.executable, "-m", "calc", "report", str(case), "-o", str(pdf)], capture_output=True, text=True)


def _without_folder(text: str, path: Path) -> str:
    """An error without the server's folders: the case file by its name."""
    return text.replace(str(path.resolve()), path.name).replace(str(path), path.name).replace(str(path.parent) + "/", "")


def _close(widget) -> None:
    for child in getattr(widget, "children", ()):
        _close(child)
    widget.close()



