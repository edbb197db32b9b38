"""The design-review panel (ipywidgets): the controls on the left, the results beside them.

Left: the case, chosen among the case files of its folder (no path is typed, so the panel reads no
other file), with a button back to its values, one row per input (:func:`calc.review.inputs.input_specs`: the label with its unit, a
slider, a number field for an exact value, linked in the browser), and the load-cycle figure.
Right: the results as one HTML text (:func:`calc.review.view.results_html`: verdict and chosen
parts first, then the governing checks, so they show without scrolling) and the stiffness-chain
figure.

A change updates the page once: the results text is replaced whole (it never collapses, so no
stale copy shows), and a figure only when what it draws changed (each figure's PNG is kept by its
inputs). Changes that arrive while one is being drawn are taken together: a worker thread draws the
controls' latest values, then looks again.
"""

from __future__ import annotations

import io
import threading
from html import escape
from pathlib import Path

from ..case import Case, read_case
from ..errors import CalcError
from ..publish import summary_rows
from ..units import Q_, pretty_unit
from .inputs import InputSpec, input_specs, with_inputs
from .view import FAIL_COLOR, evaluated, results_html, typeset

LABEL_WIDTH = "15.5em"
FIGURE_DPI = 72  # the PNG's pixels at the width the column shows it
FIGURES_KEPT = 32
SHOWN_CANDIDATES = 6  # rows of each candidate table, best first, unless all are asked for


def _png(figure) -> bytes:
    out = io.BytesIO()
    figure.savefig(out, format="png", dpi=FIGURE_DPI)
    return out.getvalue()


def _ratios(case: Case) -> list[float]:
    """The ratios of the case's gearbox catalog (the choices of the ratio control)."""
    from ..catalog import load_catalog, resolve
    from ..gearbox import SCHEMA

    catalog = load_catalog(resolve(case.gearbox_catalog, case.folder, "gearbox.catalog"), SCHEMA)
    return sorted(set(catalog["ratio"].m_as("").tolist()))


class DesignReview:
    """The design-review panel of the case file ``case_path``; any case file of the folder
    ``cases`` (by default the one it is in) can be chosen in the panel.

    ``controls`` holds each input's value widget by its key path (``motor.peak_torque``); setting
    one's ``value`` (by hand or in code) re-evaluates the case into ``results`` (the text) and the
    figures. ``report_link(path)``, where given, returns the address of a case's report,
    which the panel links beside the verdict.

    ``reports``, where given, is the folder of the calc reports (``python -m calc report
    cases/*.toml --summary -o reports/``): the case chooser shows each case's verdict as its file
    reads (:func:`calc.publish.summary_rows`), and the link is shown only where the case's report
    was built, ``report_link`` then getting the report's path.
    """

    def __init__(self, case_path, report_link=None, cases=None, reports=None):
        import ipywidgets as w

        path = Path(case_path)
        choices = sorted({*Path(cases or path.parent).glob("*.toml"), path})
        self.message = w.HTML()
        self.reports_folder, self.reports, labels = reports, {}, {p: p.name for p in choices}
        self._note = ""  # what the page says of the reports while any case is shown
        if reports is not None:
            try:
                rows = summary_rows(choices, str(reports))
            except CalcError as exc:
                self._note = f'<span style="color:{FAIL_COLOR}">no verdicts or reports: {typeset(str(exc))}</span>'
                rows = []
            for p, row in zip(choices, rows):
                labels[p] = f"{p.name} · {row['verdict']}"
                self.reports[p] = Path(row["report_path"])
        self.case_file = w.Dropdown(options=[(labels[p], p) for p in choices], value=path, description="case",
                                    style={"description_width": "3em"}, layout=w.Layout(flex="1 1 auto", width="auto"))
        self.case_file.observe(lambda _: self.load(), names="value")
        self.reset = w.Button(description="reset", tooltip="back to the values of the case file", layout=w.Layout(width="6.5em"))
        self.reset.on_click(lambda _: self.load())
        self.report_link = report_link
        self.all_candidates = w.Checkbox(description="all candidates", indent=False,
                                         tooltip=f"list every candidate in the tables, not the best {SHOWN_CANDIDATES}")
        self.controls_box = w.VBox(layout=w.Layout(overflow="hidden"))
        self.results = w.HTML(layout=w.Layout(width="100%"))
        self.load_cycle = w.Image(format="png", layout=w.Layout(width="100%", max_width="560px"))
        self.chain = w.Image(format="png", layout=w.Layout(width="100%", max_width="640px"))
        top = w.HBox([self.case_file, self.reset], layout=w.Layout(width="100%"))
        self.all_candidates.observe(self._changed, names="value")
        left = w.VBox([top, self.message, self.controls_box, self.all_candidates, self.load_cycle],
                      layout=w.Layout(flex="0 0 520px", width="520px", padding="0 16px 0 0"))
        right = w.VBox([self.results, self.chain], layout=w.Layout(flex="1 1 560px", min_width="560px"))
        # Side by side on a screen; on a narrow one (a notebook beside a file browser) the results go under.
        self.panel = w.HBox([left, right], layout=w.Layout(width="100%", align_items="flex-start", flex_flow="row wrap"))
        self.panel.add_class("design-review")
        self.controls: dict = {}
        self.specs: list[InputSpec] = []
        self.case: Case | None = None
        self._figures: dict = {}  # (figure, its inputs) -> PNG
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
            case = read_case(self.case_file.value)
            ratios = _ratios(case) if case.ratio is not None else []
        except CalcError as exc:
            self.message.value = f'<b style="color:{FAIL_COLOR}">error</b>: {typeset(str(exc))}'
            return
        self.case, self.message.value = case, self._note
        self.specs = input_specs(case, ratios)
        self.controls = {}
        old = self.controls_box.children
        self.controls_box.children = [self._row(spec) for spec in self.specs]
        for row in old:
            for widget in row.children:
                widget.close()
            row.close()
        for control in self.controls.values():
            control.observe(self._changed, names="value")
        self.refresh()

    def _row(self, spec: InputSpec):
        """One input: its label with unit (the whole of it also as tooltip), a slider and a number
        field linked in the browser (so a typed value moves the slider, and only the slider's
        value reaches the kernel), or a choice."""
        import ipywidgets as w

        label = w.HTML(f'<span title="{escape(spec.text)}">{typeset(spec.label)}{" [" + pretty_unit(spec.unit) + "]" if spec.unit else ""}</span>',
                       layout=w.Layout(width=LABEL_WIDTH, flex="0 0 " + LABEL_WIDTH))
        if spec.options:
            control = w.Dropdown(options=[(f"{r:g}", r) for r in spec.options], value=spec.value, tooltip=spec.text,
                                 layout=w.Layout(width="8em"))
            self.controls[spec.key] = control
            return w.HBox([label, control])
        slider = w.FloatSlider(value=spec.value, min=spec.low, max=spec.high, step=spec.step, readout=False,
                               continuous_update=False, tooltip=spec.text, layout=w.Layout(flex="1 1 auto", width="auto"))
        field = w.BoundedFloatText(value=spec.value, min=spec.low, max=spec.high, step=spec.step, tooltip=spec.text,
                                   layout=w.Layout(width="6.5em", flex="0 0 6.5em"))
        w.jslink((slider, "value"), (field, "value"))
        self.controls[spec.key] = slider
        return w.HBox([label, slider, field], layout=w.Layout(width="100%"))

    # -- the results ---------------------------------------------------------------------------

    def changed_case(self) -> Case:
        """The loaded case with the values of the controls that were moved (one left where it
        started keeps the case's own value, not the control's rounding of it: a derived cycle's
        7.8269 N·m stays, and stays derived)."""
        moved = {s.key: self.controls[s.key].value for s in self.specs}
        return with_inputs(self.case, {s.key: Q_(v, s.unit) for s in self.specs if (v := moved[s.key]) != s.value})

    def _draw(self):
        """The results text and the changed case (None where the inputs cannot make one)."""
        try:
            case = self.changed_case()
        except CalcError as exc:
            return f'<div class="dr"><b style="color:{FAIL_COLOR}">input error</b>: {typeset(str(exc))}</div>', None
        report, left_out = evaluated(case)
        link = self._report_address(case.path)
        typed = self.case.motion is not None and case.motion is None
        shown = None if self.all_candidates.value else SHOWN_CANDIDATES
        return results_html(report, left_out, link, typed_by_hand=typed, shown=shown), (case, report)

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
        text (last, so that when the text changes on the page, everything has)."""
        text, drawn = self._draw()
        if drawn is not None:
            case, report = drawn
            p = case.profile
            key = (p.durations.m_as("s").tobytes(), p.speeds.m_as("rpm").tobytes(), p.torques.m_as("N*m").tobytes())
            self.load_cycle.value = self._figure("load cycle", key, lambda: _load_cycle(case))
            if report.accuracy is not None:
                spec, _ = report.accuracy
                key = (repr(spec.chain), float(spec.applied_torque.m_as("N*m")))
                self.chain.value = self._figure("chain", key, lambda: _chain(spec))
            self.chain.layout.display = None if report.accuracy is not None else "none"
        self.generation += 1
        self.results.value = text.replace('<div class="dr">', f'<div class="dr" data-generation="{self.generation}">', 1)

    def _figure(self, name, key, draw) -> bytes:
        """A figure's PNG, drawn once for its inputs (the last :data:`FIGURES_KEPT` are kept, so
        moving back and forth draws nothing)."""
        if (name, key) not in self._figures:
            if len(self._figures) >= FIGURES_KEPT:
                del self._figures[next(iter(self._figures))]
            self._figures[(name, key)] = _png(draw())
        return self._figures[(name, key)]

    def _changed(self, _change) -> None:
        """A control moved: draw in the worker thread; what moves meanwhile is drawn after, once."""
        with self._lock:
            self._dirty = True
            if self._worker is not None:
                return
            self._worker = threading.Thread(target=self._work, daemon=True)
            self._worker.start()

    def _work(self) -> None:
        while True:
            with self._lock:  # "nothing left" and "no worker" at once, so no change slips between
                if not self._dirty:
                    self._worker = None
                    return
                self._dirty = False
            try:
                self.refresh()
            except BaseException:  # a fault shows in the log; the next change starts a worker again
                with self._lock:
                    self._worker = None
                raise

    def settled(self) -> "DesignReview":
        """Wait until the changes made so far are drawn (for code that sets controls, then reads)."""
        while True:
            with self._lock:
                worker = self._worker
            if worker is None:
                return self
            worker.join()


def _load_cycle(case: Case):
    from ..plots import load_cycle_figure

    return load_cycle_figure(case.profile)


def _chain(spec):
    from ..accuracy_plots import stiffness_chain_figure

    return stiffness_chain_figure(spec.chain, spec.applied_torque)

