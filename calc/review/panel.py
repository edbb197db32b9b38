"""The design-review panel (ipywidgets): the controls on the left, the results beside them.

The panel is the widgets alone: what a reviewer does goes to the review's state
(:class:`calc.review.state.ReviewState`, the case files offered :class:`calc.review.keep.CaseFiles`,
the variants kept :class:`calc.review.variants.Variants`), and the panel draws what the state
then holds and gives (the HTML of :mod:`calc.review.page`, the figures of :mod:`calc.review.figures`).

Left: the case, chosen among the case files of its folder (no path is typed, so the panel reads no
other file), with buttons back to its values and through the changes; one row per input (its
label with the unit and key path, a slider and a number field, or a choice); the moves' editor
(an entry taken out, a move or a dwell put in, the mechanism's type changed); the options of the
results and the unit system; saving and variants; the load-cycle figure (SVG, drawn by the
browser). Right: the state of the results (current, out of date, connection lost:
:mod:`calc.review.client`), the results as one HTML text (verdict and chosen parts first, then the
governing checks, so they show without scrolling), the stiffness-chain figure and the variants
compared.

A change updates the page once: the results text is replaced whole (it never collapses, so no
stale copy shows), the figures with it. Changes that arrive while one is being drawn are taken
together: a worker thread draws the state's latest values, then looks again.
"""

from __future__ import annotations

import json
import threading
from html import escape
from pathlib import Path
from urllib.parse import quote

from ..core.errors import CalcError
from ..domain.mechanism import TYPES as MECHANISM_TYPES
from ..report.symbols import html as typeset
from .client import STYLE as PAGE_STYLE, state_html
from .figures import load_cycle_svg, stiffness_chain_svg
from .inputs import InputSpec, option_text
from .keep import CaseFiles, Written, free_name
from .page import (SHOWN_CANDIDATES, failed_html, label_html, link_html, message_html, results_text,
                   with_variants)
from .state import ReviewState, without_folder
from .variants import Variants

LABEL_WIDTH = "15.5em"


class DesignReview:
    """The design-review panel of a case file.

    ``controls`` holds each input's value widget by its key path (``motor.peak_torque``); setting
    one's ``value`` (by hand or in code) re-evaluates the case into ``results`` (the text) and the
    figures. ``fields`` holds the number field beside each slider: what is typed there is read by
    :meth:`calc.review.state.ReviewState.type_text` and refused, with its message under the row,
    where it is not a number in the input's range.

    ``state`` is the review's state (:class:`calc.review.state.ReviewState`): the case, the
    changes, undo and redo. :meth:`save` writes the changes as a new case file beside the
    original, :meth:`undo` and :meth:`redo` step through them, and :meth:`keep_variant` pins the
    current design beside the others (the comparison table).

    Parameters
    ----------
    case_path : str or pathlib.Path
        The case file shown first.
    report_link : callable, optional
        ``report_link(path)`` returns the address of a case's report, which the panel links beside
        the verdict.
    cases : str or pathlib.Path, optional
        The folder whose case files can be chosen in the panel; by default the one ``case_path``
        is in.
    reports : str or pathlib.Path, optional
        The folder of the calc reports (:class:`calc.review.keep.CaseFiles`): the case chooser
        shows each case's verdict as its file reads, and the screen's once an input is changed.
    watch : float, optional
        Every this many seconds, the chooser looks at the folder again (:meth:`look_again`), so an
        open page offers the case files saved since (from another page too); None: only at each change.
    """

    def __init__(self, case_path, report_link=None, cases=None, reports=None, watch: float | None = None):
        import ipywidgets as w

        self.files = CaseFiles(case_path, cases, reports, report_link)
        self.state = ReviewState(case_path)
        self.variants = Variants()
        self.rows = InputRows(self._slid, self._typed)
        self._relabelling = False  # the chooser's options being rewritten, not a case chosen
        self.drawing = Drawing(lambda: self.refresh(), self._busy)  # refresh looked up at each drawing
        self.generation = 0  # counts the updates drawn (the page carries it, for tests and timing)
        self._download_text: str | None = None  # the changed case file the download link offers
        _build_widgets(self, w, Path(case_path))
        self.load()
        if watch:
            threading.Thread(target=self._watch, args=(watch,), daemon=True).start()

    def _watch(self, seconds: float) -> None:
        """Look at the folder again every ``seconds``, for as long as the kernel runs."""
        stop = threading.Event()
        while not stop.wait(seconds):
            self.look_again()

    @property
    def controls(self) -> dict:
        """Each input's value widget (a slider, or a choice) by its key path."""
        return self.rows.controls

    @property
    def fields(self) -> dict:
        """The number field beside each slider, by its key path."""
        return self.rows.fields

    def _repr_mimebundle_(self, **kwargs):
        bundle = self.panel._repr_mimebundle_(**kwargs)
        bundle["text/plain"] = f"design review panel of {self.case_file.value.name}"
        return bundle

    # -- what a reviewer does ----------------------------------------------------------------------

    def load(self) -> None:
        """Read the chosen case file and build one control row per input; a file that cannot be
        read is said under the case.

        Returns
        -------
        None
        """
        try:
            self.state.load(self.case_file.value)
        except CalcError as exc:
            self.message.value = failed_html("error", str(exc))
            return
        self.message.value = self._note()
        self.save_name.value = free_name(self.state.path)
        self._show_state()
        self.refresh()

    def _note(self) -> str:
        """What the page says of the reports while any case is shown."""
        return failed_html("no verdicts or reports", self.files.note, whole=True) if self.files.note else ""

    def _slid(self, key: str, value) -> None:
        """A slider moved or a choice made."""
        if self.state.set_value(key, value):
            self.rows.show(self.state)  # and the inputs that follow it
            self.drawing.changed()

    def _typed(self, key: str, text: str) -> None:
        """A value typed into a field: applied, or refused at the field."""
        redraw = self.state.type_text(key, text)
        self.rows.show(self.state)  # and the inputs that follow it
        if redraw:
            self.drawing.changed()

    def _option(self, name: str, value) -> None:
        """An option of the results (all candidates, the ratio search, the unit system) set."""
        if getattr(self.state, name) != value:
            setattr(self.state, name, value)
            if name == "units":  # the fields in that system too
                self.rows.show(self.state)
                self.moves.show_size(self.state)
            if self.state.case is not None:  # else no case file was read: nothing to draw
                self.drawing.changed()

    def undo(self) -> None:
        """Back to the values before the last change.

        Returns
        -------
        None
        """
        self._step(self.state.undo)

    def redo(self) -> None:
        """The change undone last, again.

        Returns
        -------
        None
        """
        self._step(self.state.redo)

    def _step(self, step) -> None:
        step()
        self._show_state()
        self.settled()
        self.refresh()

    def add_entry(self, after: int, kind: str) -> None:
        """Put a move or a dwell in after an entry of the moves
        (:meth:`calc.review.state.ReviewState.add_entry`); why not, under the case.

        Parameters
        ----------
        after : int
            The entry it follows (counted from 1; 0: before the first).
        kind : str
            ``"move"`` or ``"dwell"``.

        Returns
        -------
        None
        """
        self._edit_moves(lambda: self.state.add_entry(after, kind), "not added")

    def remove_entry(self, k: int) -> None:
        """Take an entry out of the moves; why not, under the case.

        Parameters
        ----------
        k : int
            The entry, counted from 1.

        Returns
        -------
        None
        """
        self._edit_moves(lambda: self.state.remove_entry(k), "not removed")

    def change_mechanism(self, type_: str, size_text: str = "") -> None:
        """A mechanism of another type in place of the case's
        (:meth:`calc.review.state.ReviewState.change_mechanism`): what it leaves out is said under
        the moves.

        Parameters
        ----------
        type_ : str
            The type (:data:`calc.domain.mechanism.TYPES`).
        size_text : str
            A linear type's lead or diameter as typed [mm, or in where the case writes inch-pound].

        Returns
        -------
        None
        """
        self._edit_moves(lambda: self.state.change_mechanism(type_, size_text), "type not changed")

    def _edits_asked(self, text: str) -> None:
        """The edits of the moves a link carries (the page's script writes them here)."""
        try:
            moves = json.loads(text) if text else None
        except ValueError:
            return
        if isinstance(moves, list):
            self._edit_moves(lambda: None if self.state.follow_moves(moves) else False, "error")

    def _edit_moves(self, edit, failed: str) -> None:
        """``edit()`` made (what it did in words, None, or False: nothing to do), the panel drawn
        again; or why not, under the case."""
        try:
            said = edit()
            if said is False:
                return
        except CalcError as exc:
            self.message.value = failed_html(failed, str(exc))
            return
        self.message.value = typeset(said) if said else self._note()
        self._show_state()
        self.drawing.changed()

    def save(self, name: str | None = None) -> Path | None:
        """Write the changes as a new case file beside the case file; never over an existing file.
        The new file is offered in the chooser. Says what it did, or why not, under the buttons.

        Parameters
        ----------
        name : str, optional
            The new file's name; by default the save field's.

        Returns
        -------
        pathlib.Path or None
            The new file's path; None where it was not saved.
        """
        try:
            path = self.state.save(name or self.save_name.value)
        except CalcError as exc:
            self.kept.value = failed_html("not saved", str(exc), whole=True)
            return None
        self.files.add(path)
        self._relabel(sorted([*self.case_file.options, (path.name, path)], key=lambda o: o[1]))
        self.kept.value = f"saved as {escape(path.name)} beside {escape(self.state.path.name)} (in the case chooser)"
        self.save_name.value = free_name(self.state.path)
        self._show_written()
        return path

    def report_of_screen(self, wait: bool = False):
        """Build the calc report of the design on the screen: the case file itself while nothing
        is changed, else the changes saved first (:meth:`save`), so the report rests on a file
        that reproduces it. The PDF goes to the reports' folder (the case's folder where none is
        given) and is linked under the buttons once built (``python -m calc report``, some 15 s,
        in a process of its own so the page keeps answering).

        Parameters
        ----------
        wait : bool
            Whether to return only once the report is built.

        Returns
        -------
        threading.Thread or None
            The thread building it; None where the changes could not be saved.
        """
        path = self.state.path if not self.state.modified() else self.save()
        if path is None:
            return None
        pdf = self.files.pdf_folder(path) / f"{path.stem}.pdf"
        try:
            Written(pdf.parent).check_room(pdf.name)
        except CalcError as exc:
            self.kept.value = failed_html("no calc report", str(exc), whole=True)
            return None
        self.kept.value = f"building the calc report of {escape(path.name)} (some 15 s) …"

        def build():
            done = _build_report(path, pdf)
            if done.returncode != 0 or not pdf.is_file():
                why = (done.stderr.strip().splitlines() or [f"exit {done.returncode}"])[-1]
                said = without_folder(why, path)
                self.kept.value = failed_html(f"no calc report of {escape(path.name)}", said, whole=True)
                return
            self.files.reports[path] = pdf
            if path != self.state.path:  # the screen's own report, removable from the page
                Written(pdf.parent).add(pdf.name)
                self._show_written()
            link = link_html(self.files.link(pdf), pdf)
            self.kept.value = f"calc report of {escape(path.name)}, the screen's design: {link}"

        worker = threading.Thread(target=build, daemon=True)
        worker.start()
        if wait:
            worker.join()
        return worker

    def keep_variant(self) -> None:
        """Pin the design on the screen (its name says what changed) beside the variants kept
        before, in the comparison table under the results; why not, under the buttons.

        Returns
        -------
        None
        """
        try:
            self.variants.keep(self.state)
        except CalcError as exc:
            self.kept.value = failed_html("not kept", str(exc), whole=True)
            return
        self._show_variants()
        self.kept.value = f"kept variant {len(self.variants.kept)}"

    def variants_pdf(self) -> Path | None:
        """The variants kept, side by side with their figure, in the unit system shown, as a PDF
        beside the reports (:meth:`calc.review.variants.Variants.pdf`); linked under the buttons.

        Returns
        -------
        pathlib.Path or None
            The PDF's path; None where no variant is kept.
        """
        if not self.variants.kept:
            return None
        try:
            pdf = self.variants.pdf(self.files.pdf_folder(self.state.path), self.state.path.stem, self.state.units)
        except CalcError as exc:
            self.kept.value = failed_html("no PDF", str(exc), whole=True)
            return None
        self.kept.value = f"the variants compared, as a PDF: {link_html(self.files.link(pdf), pdf)}"
        self._show_written()
        return pdf

    def _show_written(self) -> None:
        """The files the page wrote (case files and PDFs, :class:`calc.review.keep.Written`), to remove."""
        folders = dict.fromkeys([self.state.path.parent, self.files.pdf_folder(self.state.path)])
        options = [(f"{folder.name}/{name}", str(folder / name)) for folder in folders
                   for name in Written(folder).names()]
        self.written.options = options
        self.written.value = options[-1][1] if options else None  # the newest
        self.written_box.layout.display = None if options else "none"

    def remove_written(self, path: str | None = None) -> None:
        """Remove a file the page wrote (by default the one chosen); never another file.

        Parameters
        ----------
        path : str, optional
            The file's path, as the chooser of written files gives it.

        Returns
        -------
        None
        """
        path = Path(path or self.written.value or ".")
        try:
            if path == self.state.path:
                raise CalcError(f"{path.name} is the case shown: choose another case first")
            Written(path.parent).remove(path.name)
        except CalcError as exc:
            self.kept.value = failed_html("not removed", str(exc), whole=True)
            return
        self.files.reports = {k: v for k, v in self.files.reports.items() if v != path}
        if any(o[1] == path for o in self.case_file.options):
            self._relabel([o for o in self.case_file.options if o[1] != path])
        self.kept.value = f"removed {escape(path.name)}"
        self.save_name.value = free_name(self.state.path)
        self._show_written()

    def _variants_asked(self, text: str) -> None:
        """The variants a link carries (the page's script writes their states here), each
        evaluated again from its case file; one that no longer reads is left out and said."""
        missed = self.variants.follow(text, self.files)
        if missed is not None:
            self.kept.value = failed_html("not kept from the link", "; ".join(missed), whole=True) if missed else ""
        self._show_variants()

    # -- drawing the state -------------------------------------------------------------------------

    def _show_state(self) -> None:
        """The widgets set to the state: the rows (built again for other inputs), their values,
        the moves' editor, the unit system, undo and redo."""
        if self.rows.build(self.state):
            self.moves.show(self.state)
        self.rows.show(self.state)
        self.units.value = self.state.units  # the state's already: not a change
        self._show_history()

    def refresh(self) -> None:
        """Draw the results of the state (:meth:`calc.review.state.ReviewState.evaluate`): each
        figure, the labels and messages, then the text (last, so that when the text changes on
        the page, everything has), which carries the state it was computed for
        (:func:`calc.review.page.results_text`).

        Returns
        -------
        None
        """
        state = self.state
        screen = state.evaluate()
        if screen.report is not None:
            torque_unit = "lbf*in" if state.units == "inch-pound" else "N*m"
            self.load_cycle.value = load_cycle_svg(screen.case.profile, screen.duty(), torque_unit)
            self.load_cycle.layout.display = None
            chain = screen.chain()
            if chain is not None:
                self.chain.value = stiffness_chain_svg(chain)
            self.chain.layout.display = None if chain is not None else "none"
            self.rows.idle = screen.idle()
            self._chooser_verdict(screen.report.verdict.word, bool(screen.changes or screen.moves))
        else:  # the figures of the last good inputs no longer apply
            self.load_cycle.layout.display = self.chain.layout.display = "none"
        self.rows.show_labels(state, screen.changes)
        self._show_history()
        self._offer_download(screen.text)
        compared = self.variants.comparison(state.units)
        if self.variants.kept and self.variants_html.value != compared:
            self.variants_html.value = compared
        self.generation += 1
        link = self.files.report_address(state.path) if not (screen.changes or screen.moves) else None
        self.results.value = results_text(state, screen, link, self.generation, self.variants)

    def _show_history(self) -> None:
        history = self.state.history
        self.undo_button.disabled, self.redo_button.disabled = not history.can_undo, not history.can_redo

    def _offer_download(self, text: str | None) -> None:
        """The case file as changed (``text``, as *Save as case file* writes it), as a link to download
        under the name in the save field (drawn again when that name changes)."""
        self._download_text = text
        self.download.value = "" if text is None or self.state.refused else (
            f'<a download="{escape(self.save_name.value)}" href="data:application/toml;charset=utf-8,{quote(text)}">'
            "Download the case file</a>")

    def _chooser_verdict(self, word: str, changed: bool) -> None:
        """The chooser's entry of the case shown gives the screen's verdict, not the file's, once
        an input is changed."""
        path = self.state.path
        self.files.look_again(path)  # case files saved since, from another page too
        if path in self.files.labels:
            options = [(self.files.label(path, word, changed) if p == path else self.files.labels[p], p)
                       for p in sorted(self.files.labels)]
            if options != list(self.case_file.options):
                self._relabel(options)

    def look_again(self) -> None:
        """The chooser offers the case files of the folder as they are now
        (:meth:`calc.review.keep.CaseFiles.look_again`), the case shown keeping its label.

        Returns
        -------
        None
        """
        if self.files.look_again(self.state.path):
            shown = dict((p, label) for label, p in self.case_file.options)
            self._relabel([(shown.get(p, self.files.labels[p]), p) for p in sorted(self.files.labels)])

    def _relabel(self, options: list) -> None:
        """New options for the chooser, the case shown staying chosen (and not read again)."""
        self._relabelling = True
        try:
            self.case_file.options = options
            self.case_file.value = self.state.path
        finally:
            self._relabelling = False

    def _show_variants(self) -> None:
        self.variants_html.value = self.variants.comparison(self.state.units)
        self.variants_pdf_button.disabled = not self.variants.kept
        # The results carry the variants' states, for the page's address.
        self.results.value = with_variants(self.results.value, self.variants)

    def _busy(self, busy: bool) -> None:
        """Mark the results out of date while a change is computed (``dr-busy``, the state line)."""
        (self.panel.add_class if busy else self.panel.remove_class)("dr-busy")
        self.status.value = state_html(busy)

    def settled(self) -> "DesignReview":
        """Wait until the changes made so far are drawn (for code that sets controls, then reads).

        Returns
        -------
        DesignReview
            The panel itself.
        """
        self.drawing.settled()
        return self


class Drawing:
    """Drawing in a worker thread: called once a change arrives, and again while more arrived
    meanwhile (taken together, once).

    Parameters
    ----------
    draw : callable
        ``draw()`` draws the state as it then stands.
    busy : callable
        ``busy(True)`` as the first change arrives, ``busy(False)`` once all are drawn.
    """

    def __init__(self, draw, busy):
        self._draw, self._busy = draw, busy
        self._dirty = False
        self._worker: threading.Thread | None = None
        self._lock = threading.Lock()

    def changed(self) -> None:
        """A change: drawn in the worker thread, started where none runs.

        Returns
        -------
        None
        """
        with self._lock:
            self._dirty = True
            if self._worker is not None:
                return
            self._busy(True)
            self._worker = threading.Thread(target=self._work, daemon=True)
            self._worker.start()

    def _work(self) -> None:
        while True:
            with self._lock:  # "nothing left" and "no worker" at once, so no change slips between
                if not self._dirty:
                    self._worker = None
                    self._busy(False)
                    return
                self._dirty = False
            try:
                self._draw()
            except BaseException:  # a fault shows in the log; the next change starts a worker again
                with self._lock:
                    self._worker = None
                    self._busy(False)
                raise

    def settled(self) -> None:
        """Wait until the changes made so far are drawn.

        Returns
        -------
        None
        """
        while True:
            with self._lock:
                worker = self._worker
            if worker is None:
                return
            worker.join()


class InputRows:
    """The panel's row of each input: its label with unit (the whole of it also as tooltip, its
    key path as ``data-key``), a slider and a number field, or a choice, and under it a message
    (a refused value, or that the input has no effect on the design).

    Parameters
    ----------
    on_value : callable
        ``on_value(key, value)``, called when a slider is moved or a choice made; not where the
        rows are set to the state (:meth:`show`).
    on_text : callable
        ``on_text(key, text)``, called when a text is typed into a field; not where the rows are
        set to the state.
    """

    def __init__(self, on_value, on_text):
        import ipywidgets as w
        from ipywidgets.widgets.widget_description import DescriptionStyle
        from ipywidgets.widgets.widget_string import HTMLStyle, TextStyle

        self.box = w.VBox(layout=w.Layout(overflow="hidden"))
        self.controls: dict = {}
        self.fields: dict = {}
        self.labels: dict = {}
        self.messages: dict = {}
        self.idle: dict = {}  # key path -> why the input has no effect on the design shown
        self._specs = None  # the inputs the rows were built for
        self._quiet = False
        self._on_value, self._on_text = on_value, on_text
        # One layout and one style model for the like parts of every row (none of them changes after):
        # a row is six widget models, not thirteen, which the browser builds one by one as the page loads.
        self._shared = {
            "label": w.Layout(width=LABEL_WIDTH, flex="0 0 " + LABEL_WIDTH), "grows": _grows(w),
            "field": w.Layout(width="6.5em", flex="0 0 6.5em"), "full": w.Layout(width="100%"), "plain": w.Layout(),
            "html": HTMLStyle(), "slider": w.SliderStyle(), "text": TextStyle(), "choice": DescriptionStyle(),
        }

    def build(self, state: ReviewState) -> bool:
        """The rows of the state's inputs, built again where they are others.

        Parameters
        ----------
        state : calc.review.state.ReviewState
            The review (its inputs and their values).

        Returns
        -------
        bool
            Whether they were built again.
        """
        if state.specs is self._specs:
            return False
        old = self.box.children
        self.controls, self.fields, self.labels, self.messages = {}, {}, {}, {}
        self.box.children = [self._row(spec, state) for spec in state.specs]
        for row in old:
            _close(row)
        self._specs = state.specs
        return True

    def _row(self, spec: InputSpec, state: ReviewState):
        import ipywidgets as w

        value, shared = state.values[spec.key], self._shared
        label = w.HTML(label_html(spec, False, state.from_edits(spec.key), state.following(spec.key),
                                  state.shown_spec(spec.key)), layout=shared["label"], style=shared["html"])
        label.add_class("dr-label")
        self.labels[spec.key] = label
        self.messages[spec.key] = w.HTML(layout=shared["plain"], style=shared["html"])
        if spec.options:
            control = w.Dropdown(options=[(option_text(r), r) for r in spec.options], value=value, tooltip=spec.text,
                                 layout=shared["grows"], style=shared["choice"])  # the row's width: no choice cut short
            line = w.HBox([label, control], layout=shared["plain"])
        else:
            control = w.FloatSlider(value=value, min=spec.low, max=spec.high, step=spec.step, readout=False,
                                    continuous_update=False, tooltip=spec.text, layout=shared["grows"],
                                    style=shared["slider"])
            field = w.Text(value=state.texts[spec.key], continuous_update=False, tooltip=spec.text,
                           layout=shared["field"], style=shared["text"])
            # The field is read by the state, not by the browser's number input, which clamps to
            # the range and drops a decimal comma without a word.
            field.observe(lambda change, key=spec.key: self._quiet or self._on_text(key, change["new"]), names="value")
            self.fields[spec.key] = field
            line = w.HBox([label, control, field], layout=shared["full"])
        control.observe(lambda change, key=spec.key: self._quiet or self._on_value(key, change["new"]), names="value")
        self.controls[spec.key] = control
        row = w.VBox([line, self.messages[spec.key]], layout=shared["full"])
        row.add_class("dr-row")
        return row

    def show(self, state: ReviewState, keys=None) -> None:
        """The controls and fields at the state's values and texts, refusals marked.

        Parameters
        ----------
        state : calc.review.state.ReviewState
            The review.
        keys : iterable of str, optional
            The key paths of the inputs to set; by default all.

        Returns
        -------
        None
        """
        self._quiet = True
        try:
            for key in self.controls if keys is None else keys:
                if self.controls[key].value != state.values[key]:
                    self.controls[key].value = state.values[key]
                field = self.fields.get(key)
                if field is not None:
                    if field.value.strip() != state.texts[key]:
                        field.value = state.texts[key]
                    shown = state.shown_spec(key)  # its range in the unit the field shows
                    tooltip = f"{shown.text}: {shown.low:.6g} to {shown.high:.6g}"
                    if field.tooltip != tooltip:
                        field.tooltip = tooltip
                    (field.add_class if key in state.refused else field.remove_class)("dr-refused")
                self._show_message(state, key)
        finally:
            self._quiet = False

    def _show_message(self, state: ReviewState, key: str) -> None:
        refused = state.refused.get(key)
        message = message_html(refused and refused[1], self.idle.get(key))
        if self.messages[key].value != message:
            self.messages[key].value = message

    def show_labels(self, state: ReviewState, changes: dict) -> None:
        """Each label marked where its input is changed or made by an edit of the moves, and each
        message.

        Parameters
        ----------
        state : calc.review.state.ReviewState
            The review.
        changes : dict
            The inputs changed, by key path (:meth:`calc.review.state.ReviewState.changes`).

        Returns
        -------
        None
        """
        for spec in state.specs:
            label = label_html(spec, spec.key in changes, state.from_edits(spec.key), state.following(spec.key),
                               state.shown_spec(spec.key))
            if self.labels[spec.key].value != label:  # each value set is a message to the page
                self.labels[spec.key].value = label
            self._show_message(state, spec.key)


class MovesEditor:
    """The moves as a reviewer edits them: an entry taken out, a move or a dwell put in after it,
    the mechanism of another type (its starting values equivalent); and the hidden field through
    which the page's script replays the edits a link carries.

    Parameters
    ----------
    w : module
        ipywidgets.
    p : DesignReview
        The panel, whose :meth:`DesignReview.add_entry`, :meth:`DesignReview.remove_entry` and
        :meth:`DesignReview.change_mechanism` the buttons call.
    """

    def __init__(self, w, p: DesignReview):
        self.entry = w.Dropdown(description="moves", style={"description_width": "3.5em"}, layout=_grows(w),
                                tooltip="an entry of the moves: remove it, or add a move or a dwell after it")
        self.remove_button = _button(w, "remove", "take the chosen entry out of the moves", "5.5em",
                                     lambda: p.remove_entry(self.entry.value))
        add_move = _button(w, "+ move", "a move after the chosen entry (a copy of the move at or before it)", "5.5em",
                           lambda: p.add_entry(self.entry.value, "move"))
        add_dwell = _button(w, "+ dwell", "a dwell after the chosen entry (as long as the last dwell, else 1 s)",
                            "5.5em", lambda: p.add_entry(self.entry.value, "dwell"))
        edits_field = w.Text(continuous_update=False, layout=w.Layout(display="none"))
        edits_field.add_class("dr-edits")
        edits_field.observe(lambda change: p._edits_asked(change["new"]), names="value")
        self.mechanism_type = w.Dropdown(options=list(MECHANISM_TYPES), description="type",
                                         tooltip="the mechanism's type", style={"description_width": "3.5em"},
                                         layout=_grows(w))
        self.mechanism_size = w.Text(placeholder="lead / diameter", layout=w.Layout(width="9em", flex="0 0 9em"),
                                     tooltip="a screw's lead, a pinion's or pulley's diameter (a linear type)")
        why = "the mechanism of the chosen type, starting from values equivalent at the gearbox output"
        change = _button(w, "change type", why, "8em",
                         lambda: p.change_mechanism(self.mechanism_type.value, self.mechanism_size.value))
        row = w.Layout(width="100%")
        self.box = w.VBox([w.HBox([self.entry, self.remove_button, add_move, add_dwell], layout=row),
                           w.HBox([self.mechanism_type, self.mechanism_size, change], layout=row), edits_field],
                          layout=w.Layout(width="100%"))
        self.box.add_class("dr-moves")

    def show(self, state: ReviewState) -> None:
        """The state's moves: the last entry chosen, the mechanism's type and size (none shown
        where the case has no moves).

        Parameters
        ----------
        state : calc.review.state.ReviewState
            The review.

        Returns
        -------
        None
        """
        kinds = state.entries()
        self.box.layout.display = None if kinds else "none"
        self.entry.options = [(f"{k} {kind}", k) for k, kind in enumerate(kinds, start=1)]
        self.entry.value = len(kinds) if kinds else None
        self.remove_button.disabled = len(kinds) < 2
        if kinds:
            self.mechanism_type.value = state.case.motion.mechanism.type
            self.show_size(state)

    def show_size(self, state: ReviewState) -> None:
        """The mechanism's lead or diameter in the unit system the fields show.

        Parameters
        ----------
        state : calc.review.state.ReviewState
            The review.

        Returns
        -------
        None
        """
        if state.case is None or state.case.motion is None:
            return
        mechanism, unit = state.case.motion.mechanism, state.length_unit()
        size = mechanism.lead if mechanism.type == "ball-screw" else mechanism.diameter
        self.mechanism_size.value = "" if size is None else f"{size.m_as(unit):.6g}"
        self.mechanism_size.placeholder = f"lead / diameter [{unit}]"


def _grows(w):
    """The layout of a widget that takes the room its row leaves."""
    return w.Layout(flex="1 1 auto", width="auto")


def _button(w, description: str, tooltip: str, width: str, action, fixed: bool = False, **kwargs):
    """A button ``width`` wide (``fixed``: never narrower) that calls ``action()`` when clicked."""
    layout = w.Layout(width=width, flex=f"0 0 {width}") if fixed else w.Layout(width=width)
    button = w.Button(description=description, tooltip=tooltip, layout=layout, **kwargs)
    button.on_click(lambda _: action())
    return button


def _build_widgets(p: DesignReview, w, path: Path) -> None:
    """Every widget of the panel ``p``, each wired to what it does, laid out."""
    p.message = w.HTML()
    p.moves = MovesEditor(w, p)
    p.case_file = w.Dropdown(options=p.files.options(), value=path, description="case", layout=_grows(w),
                             style={"description_width": "3em"})
    p.case_file.add_class("dr-case")
    p.case_file.observe(lambda _: p._relabelling or p.load(), names="value")
    p.reset = _button(w, "reset", "back to the values of the case file", "4.5em", p.load, fixed=True)
    p.undo_button = _button(w, "undo", "the values before the last change", "4.2em", p.undo, fixed=True, disabled=True)
    p.redo_button = _button(w, "redo", "the change undone last", "4.2em", p.redo, fixed=True, disabled=True)
    top = w.HBox([p.case_file, p.reset, p.undo_button, p.redo_button], layout=w.Layout(width="100%"))
    top.add_class("dr-top")  # its buttons go under the chooser where the column is too narrow, never cut
    p.status = w.HTML(state_html())
    p.results = w.HTML(layout=w.Layout(width="100%"))
    p.load_cycle = w.HTML(layout=w.Layout(width="100%", max_width="560px"))  # SVG, drawn by the browser
    p.chain = w.HTML(layout=w.Layout(width="100%", max_width="640px"))  # SVG, drawn by the browser
    p.load_cycle.add_class("dr-figures")
    p.chain.add_class("dr-figures")
    p.variants_html = w.HTML(layout=w.Layout(width="100%"))
    left = w.VBox([w.HTML(PAGE_STYLE), top, p.message, p.rows.box, p.moves.box, _options(p, w), _keep(p, w),
                   p.load_cycle], layout=w.Layout(flex="0 0 520px", width="520px", padding="0 16px 0 0"))
    right = w.VBox([p.status, p.results, p.chain, p.variants_html],
                   layout=w.Layout(flex="1 1 560px", min_width="560px"))
    # Side by side on a screen; on a narrow one (a notebook beside a file browser) the results go under.
    p.panel = w.HBox([left, right], layout=w.Layout(width="100%", align_items="flex-start", flex_flow="row wrap"))
    p.panel.add_class("design-review")


def _options(p: DesignReview, w):
    """The options of the results: every candidate in the tables, the ratio search, the unit system."""
    p.all_candidates = w.Checkbox(description="all candidates", indent=False, layout=_grows(w),
                                  tooltip=f"list every candidate in the tables, not the best {SHOWN_CANDIDATES}")
    p.ratio_search = w.Checkbox(description="ratio search", indent=False, layout=_grows(w),
                                tooltip="the case at every ratio of the gearbox catalog, and the ratio to pick")
    p.units = w.ToggleButtons(options=["SI", "inch-pound"], tooltip="the unit system of the inputs and the results",
                              style={"button_width": "7.5em"}, layout=w.Layout(width="auto", flex="0 0 auto"))
    for name, widget in (("all_candidates", p.all_candidates), ("ratio_search", p.ratio_search), ("units", p.units)):
        widget.observe(lambda change, name=name: p._option(name, change["new"]), names="value")
    return w.HBox([p.all_candidates, p.ratio_search, p.units])


def _keep(p: DesignReview, w):
    """What is kept: save as a case file beside the original, the same file to download, the
    variants compared, the calc report of the screen."""
    p.save_name = w.Text(placeholder="new-case.toml", tooltip="the new case file's name, in the folder of the case",
                         layout=_grows(w))
    p.save_name.observe(lambda _: p._offer_download(p._download_text), names="value")  # the download's name follows
    save = _button(w, "Save as case file", "write the changed values into a new case file beside this one", "11em",
                   p.save)
    variant = _button(w, "Keep as variant", "pin the design on the screen beside the others", "11em", p.keep_variant)
    report = _button(w, "Calc report of this screen",
                     "save the changed values as a case file (Save as case file) and build its calc report (PDF)",
                     "15em", p.report_of_screen)
    aasx = _button(w, "Save as AASX", "save the changed values as a case file (Save as case file) and its "
                   "IDTA 02021 digital twin beside it (AASX, the case file inside)", "11em", lambda: save_aasx(p))
    p.variants_pdf_button = _button(w, "Variants as PDF",
                                    "the variants kept, side by side with their figure, as a PDF (A4)", "11em",
                                    p.variants_pdf, disabled=True)
    p.download, p.kept = w.HTML(), w.HTML()
    # The page's script hands the variants a link carries to the kernel through this field (hidden).
    p.variants_field = w.Text(continuous_update=False, layout=w.Layout(display="none"))
    p.variants_field.add_class("dr-variants-asked")
    p.variants_field.observe(lambda change: p._variants_asked(change["new"]), names="value")
    p.written = w.Dropdown(description="written", tooltip="a file this page's review wrote: a case file or a PDF",
                           style={"description_width": "4.5em"}, layout=_grows(w))
    remove = _button(w, "remove file", "remove the chosen file written from the review (never another)", "8em",
                     p.remove_written)
    p.written_box = w.HBox([p.written, remove], layout=w.Layout(width="100%", display="none"))
    p.written_box.add_class("dr-written")
    keep = w.VBox([w.HBox([p.save_name, save, aasx], layout=w.Layout(width="100%")),
                   w.HBox([variant, p.variants_pdf_button, report], layout=w.Layout(flex_flow="row wrap")),
                   p.download, p.kept, p.written_box, p.variants_field])
    keep.add_class("dr-keep")
    return keep


def save_aasx(p: DesignReview) -> Path | None:
    """The case on the screen as an IDTA 02021 AASX beside its case file: the changes saved first
    (:meth:`DesignReview.save`), so the AASX carries the file it was built from. Says what it did,
    or why not, under the buttons.

    Parameters
    ----------
    p : DesignReview
        The panel.

    Returns
    -------
    pathlib.Path or None
        The AASX written; None where the changes or the AASX could not be saved.
    """
    from ..exchange.command import export_beside

    path = p.state.path if not p.state.modified() else p.save()
    if path is None:
        return None
    try:
        out = export_beside(path)
    except CalcError as exc:
        p.kept.value = failed_html("no AASX", str(exc), whole=True)
        return None
    if path != p.state.path:  # beside a case file the page saved: written by the page, removable there
        Written(out.parent).add(out.name)
        p._show_written()
    p.kept.value = f"saved {escape(out.name)} beside {escape(path.name)} (IDTA 02021, the case file inside)"
    return out


def _build_report(case: Path, pdf: Path):
    """``python -m calc report case -o pdf`` (the completed process)."""
    import subprocess
    import sys

    command = [sys.executable, "-m", "calc", "report", str(case), "-o", str(pdf)]
    return subprocess.run(command, capture_output=True, text=True)


def _close(widget) -> None:
    for child in getattr(widget, "children", ()):
        _close(child)
    widget.close()
