"""The live design review: a case re-evaluated whole as its inputs change.

:func:`with_changes` copies a case with some inputs replaced (the ratio, each segment's duration
and torque, the motor's peak torque, the inertias, the coupling's temperature, the applied torque
of the accuracy chain); :func:`review_items` evaluates a case and returns what a reviewer looks at
(the verdict, the load cycle, the candidate tables with their verdicts, the accuracy of the
chain); :class:`DesignReview` is the ipywidgets panel of notebook 07: one control per input, and
every change re-evaluates the whole case (:func:`calc.report.report_of`). ipywidgets, pandas and
matplotlib are imported inside, so ``import calc`` stays light.
"""

from __future__ import annotations

import copy
import dataclasses
from pathlib import Path

import numpy as np

from .case import Case, read_case
from .errors import CalcError
from .profile import Profile
from .units import Q_, parse_quantity, pretty_unit, sig


def with_changes(
    case: Case,
    ratio=None,
    durations=None,
    torques=None,
    motor_peak_torque=None,
    motor_inertia=None,
    load_inertia=None,
    temperature=None,
    applied_torque=None,
) -> Case:
    """A copy of ``case`` with the given inputs replaced (quantities; ``None`` keeps the case's).

    ``durations`` and ``torques`` are quantity arrays over all segments (a pause's torque is
    ignored). The coupling's ``temperature`` and the accuracy chain's ``applied_torque`` are
    written into copies of those sections as their readers expect them, so they are checked
    as if they stood in the file.

    >>> case = read_case(Path(__file__).parent.parent / "cases" / "indexing-table.toml")
    >>> changed = with_changes(case, motor_peak_torque=Q_(30, "N*m"))
    >>> changed.motor_peak_torque, case.motor_peak_torque
    (<Quantity(30, 'newton * meter')>, <Quantity(12.0, 'newton * meter')>)

    The example derives its cycle from its motion; a changed segment makes the cycle a typed one:

    >>> with_changes(case).motion is case.motion, with_changes(case, durations=2 * case.profile.durations).motion
    (True, None)
    """
    p = case.profile
    durations = p.durations if durations is None else durations
    torques = p.torques if torques is None else torques
    segments = [
        (phase, durations[k], None if phase == "pause" else p.speeds[k], None if phase == "pause" else torques[k])
        for k, phase in enumerate(p.phases)
    ]
    sections = copy.deepcopy(case.sections)
    if temperature is not None and "coupling" in sections:
        sections["coupling"]["temperature"] = f"{temperature.m_as('degC'):.12g} degC"
    if applied_torque is not None and "accuracy" in sections:
        sections["accuracy"]["applied_torque"] = f"{applied_torque.m_as('N*m'):.12g} N*m"
    given = dict(ratio=ratio, motor_peak_torque=motor_peak_torque, motor_inertia=motor_inertia, load_inertia=load_inertia)
    same = np.allclose(durations.m_as("s"), p.durations.m_as("s"), rtol=1e-9) and np.allclose(torques.m_as("N*m"), p.torques.m_as("N*m"), rtol=1e-9)
    return dataclasses.replace(
        case,
        profile=Profile.from_segments(segments, where=f"{case.path}: profile"),
        motion=case.motion if same else None,  # changed segments are typed: the derived motion no longer holds
        sections=sections,
        **{k: v for k, v in given.items() if v is not None},
    )


def review_items(case: Case) -> list:
    """What the review shows for ``case``, in order: the verdict (HTML), the load-cycle figure,
    the gearbox and coupling candidate tables (DataFrames, rounded), the accuracy of the chain
    (a table and the stiffness-chain figure). An input that cannot be evaluated gives the one
    sentence that says why, as the verdict."""
    from html import escape

    from IPython.display import HTML

    from .plots import load_cycle_figure

    r, left_out = _report_of_what_evaluates(case)
    color = "#1b7837" if r.passes and not left_out else "#b2222a"
    if r.passes and not left_out:
        why = "; ".join(f"{w.lower()} {p}" for w, p, _ in r.chosen)
    else:
        why = "<br>".join(escape(x) for x in [*left_out, *r.reasons])
    verdict = "FAIL" if left_out else r.verdict.word
    passes = r.passes and not left_out
    items = [HTML(f'<p><b style="color:{color}">{verdict}</b>: {why if passes else ""}</p>'
                  + ("" if passes else f"<p>{why}</p>"))]
    items.append(load_cycle_figure(case.profile))
    if r.selection is not None:
        from .gearbox import candidates_summary

        items += [HTML("<b>Gearbox candidates</b>"), candidates_summary(r.selection).round(3)]
    if r.coupling is not None:
        from .coupling import candidates_frame

        items += [HTML("<b>Coupling candidates</b>"), candidates_frame(r.coupling[1]).round(3)]
    if r.accuracy is not None:
        import pandas as pd

        from .accuracy_plots import stiffness_chain_figure

        spec, a = r.accuracy
        rows = [
            ("C_total", "total torsional stiffness at the output", a.chain.stiffness, "N*m/arcmin"),
            ("phi_LM", "lost motion at the applied torque", a.lost_motion, "arcmin"),
            ("Delta_phi_P", "positioning accuracy", a.positioning_accuracy, "arcmin"),
            ("repeatability", "repeatability" + (" (upper bound)" if a.repeatability_is_bound else ""), a.repeatability, "arcmin"),
        ]
        frame = pd.DataFrame([(s, d, sig(q.m_as(u)), u) for s, d, q, u in rows], columns=["symbol", "quantity", "value", "unit"])
        items += [HTML("<b>Accuracy of the chain</b>"), frame, stiffness_chain_figure(spec.chain, spec.applied_torque)]
    return items


def _report_of_what_evaluates(case: Case):
    """The case's report, and what had to be left out of it: when the changed inputs make one
    further section impossible to evaluate (the accuracy chain names a 10:1 gearbox and the ratio
    is now 8), the report of the rest, and that section's reason as one sentence, so the review
    still shows the gearbox and the other sections. The verdict with a section left out is FAIL."""
    from .report import report_of

    r = report_of(case)
    if r.error is None:
        return r, []
    for name in case.sections:
        rest = report_of(dataclasses.replace(case, sections={k: v for k, v in case.sections.items() if k != name}))
        if rest.error is None:
            return rest, [f"The {name} section cannot be evaluated with these inputs: {r.error}"]
    return r, []


class DesignReview:
    """The design-review panel: load a case file, change its inputs, see the whole case again.

    ``controls`` holds the input widgets by name; setting one's ``value`` (by hand or in code)
    re-evaluates the case into the panel's output. :meth:`items` is what the panel shows.
    """

    def __init__(self, case_path):
        import ipywidgets as w

        self.path = w.Text(value=str(case_path), description="case file", layout=w.Layout(width="60%"))
        load = w.Button(description="Load")
        load.on_click(lambda _: self.load())
        self.message = w.HTML()
        self.controls_box = w.VBox()
        self.output = w.Output()
        self.panel = w.VBox([w.HBox([self.path, load]), self.message, self.controls_box, self.output])
        self.controls: dict = {}
        self.case: Case | None = None
        self.load()

    def _repr_mimebundle_(self, **kwargs):
        bundle = self.panel._repr_mimebundle_(**kwargs)
        bundle["text/plain"] = f"design review panel of {Path(self.path.value).name}"
        return bundle

    def load(self) -> None:
        """Read the case file named in the panel and build one control per input."""
        import ipywidgets as w

        try:
            case = read_case(self.path.value)
        except CalcError as exc:
            self.message.value = f"<b>error</b>: {exc}"
            return
        self.case, self.message.value = case, ""
        p = case.profile

        def slider(label, value, low, high, step, unit):
            return w.FloatSlider(value=value, min=low, max=high, step=step, description=f"{label} [{unit}]",
                                 continuous_update=False, readout_format=".3g", style={"description_width": "14em"},
                                 layout=w.Layout(width="38em"))

        c: dict = {}
        if case.ratio is not None:
            from .catalog import load_catalog, resolve
            from .gearbox import SCHEMA

            catalog = load_catalog(resolve(case.gearbox_catalog, case.folder, "gearbox.catalog"), SCHEMA)
            ratios = sorted(set(catalog["ratio"].m_as("").tolist()))
            c["ratio"] = w.Dropdown(options=[(f"{r:g}", r) for r in ratios], value=case.ratio.m_as(""), description="ratio i",
                                    style={"description_width": "14em"})
        for k, (phase, t, T) in enumerate(zip(p.phases, p.durations.m_as("s"), p.torques.m_as("N*m")), start=1):
            c[f"t_{k}"] = slider(f"segment {k} ({phase}): duration", t, 0.01, max(3 * t, 1.0), 0.01, "s")
            if phase != "pause":
                span = max(3 * abs(T), 10.0)
                c[f"T_{k}"] = slider(f"segment {k} ({phase}): torque", T, -span, span, 0.5, "N·m")
        for key, label, q, unit in (("T_1B", "motor peak torque T_1B", case.motor_peak_torque, "N*m"),
                                    ("J_motor", "motor inertia J_motor", case.motor_inertia, "kg*cm**2"),
                                    ("J_L", "load inertia J_L", case.load_inertia, "kg*cm**2")):
            if q is not None:
                v = q.m_as(unit)
                c[key] = slider(label, v, v / 10, 5 * v, v / 100, pretty_unit(unit))
        coupling = case.sections.get("coupling")
        if coupling is not None:
            t = parse_quantity(coupling.get("temperature", "20 degC"), "temperature", "coupling.temperature").m_as("degC")
            from .coupling import TEMPERATURE_FACTORS  # the slider ends at the table's top (E9)

            c["temperature"] = slider("coupling temperature", t, -20.0, TEMPERATURE_FACTORS.top, 1.0, "°C")
        accuracy = case.sections.get("accuracy")
        if accuracy is not None and "applied_torque" in accuracy:
            t = parse_quantity(accuracy["applied_torque"], "torque", "accuracy.applied_torque").m_as("N*m")
            c["applied_torque"] = slider("applied torque T (accuracy)", t, 0.0, max(5 * t, 10.0), 0.1, "N·m")
        for control in c.values():
            control.observe(lambda _: self.update(), names="value")
        self.controls = c
        self.controls_box.children = tuple(c.values())
        self.update()

    def changed_case(self) -> Case:
        """The loaded case with the controls' values."""
        c, p = self.controls, self.case.profile
        n = len(p.phases)
        value = lambda key, unit: Q_(c[key].value, unit) if key in c else None  # noqa: E731
        torques = np.array([c[f"T_{k}"].value if f"T_{k}" in c else 0.0 for k in range(1, n + 1)])
        return with_changes(
            self.case,
            ratio=value("ratio", ""),
            durations=Q_(np.array([c[f"t_{k}"].value for k in range(1, n + 1)]), "s"),
            torques=Q_(torques, "N*m"),
            motor_peak_torque=value("T_1B", "N*m"),
            motor_inertia=value("J_motor", "kg*cm**2"),
            load_inertia=value("J_L", "kg*cm**2"),
            temperature=Q_(c["temperature"].value, "degC") if "temperature" in c else None,
            applied_torque=value("applied_torque", "N*m"),
        )

    def items(self) -> list:
        """What the panel shows for the controls' values (see :func:`review_items`)."""
        try:
            return review_items(self.changed_case())
        except CalcError as exc:
            from IPython.display import HTML

            return [HTML(f'<p><b style="color:#b2222a">FAIL</b>: {exc}</p>')]

    def update(self) -> None:
        """Re-evaluate the case into the panel's output.

        The output widget's state is set from the kernel (not by capturing displays in a
        front end), so it holds the same outputs with or without one.
        """
        items = self.items()
        self.output.outputs = ()
        for item in items:
            self.output.append_display_data(item)
