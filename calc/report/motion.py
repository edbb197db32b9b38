"""The motion and the mechanism in the outputs: in the calc report the mechanism's inputs, the
moves, each formula with its values (the transmission radius, the load's inertia, each move's
peak speed and acceleration, the output torque in each phase), the derived segments and a figure
of speed and torque over the cycle; on the review's page the motion's peak values."""

from __future__ import annotations

from html import escape

from ..sections.motion import NAME, keys_of
from ..core.units import Q_, sig
from .common import Renderer, input_row, page_doc
from .latex import latex_escape, signed, step_block, symbol_math, table
from .page import value
from .symbols import html as typeset

#: The field of :class:`calc.domain.mechanism.Mechanism` of each of its quantities' keys, where it differs.
FIELDS = {"inertia": "given_inertia", "screw_inertia": "own_inertia", "pinion_inertia": "own_inertia",
          "pulley_inertia": "own_inertia", "pitch_diameter": "diameter", "pulley_diameter": "diameter"}


def _motion(report):
    return None if report.case is None else report.case.motion


class MotionRenderer(Renderer):
    """The motion: its inputs, steps and figure in the report, its peaks on the page."""

    NAME = NAME

    def input_rows(self, report) -> list[list[str]]:
        m = _motion(report)
        if m is None or m.mechanism is None:
            return []
        k = m.mechanism
        quantities = [key.name for key in keys_of(k.type) if key.unit or key.kind == "dimensionless"]
        given = {key: getattr(k, FIELDS.get(key, key)) for key in quantities}
        return [input_row(f"mechanism.{key}", Q_(q)) for key, q in given.items() if q is not None]

    def inputs(self, report) -> list[str]:
        m = _motion(report)
        if m is None:
            return []
        if m.record is not None:
            return [rf"The load cycle is the drive record \texttt{{{latex_escape(m.record)}}} "
                    rf"(case key \texttt{{[drive\_record]}}), {len(m.cycle.dt)} intervals between its rows."]
        rows = []
        for k, (move, given) in enumerate(zip(m.moves, m.distances), start=1):
            if move.dwell:
                rows.append([str(k), "dwell", "–", sig(move.time), "–", "–", "–"])
            else:
                rows.append([str(k), "move", latex_escape(f"{given:~P}"), sig(move.time), sig(move.accel_time),
                             sig(move.decel_time), sig(move.jerk_time) if move.jerk_time else "–"])
        kind = ("rotary table" if not m.mechanism.linear
                else m.mechanism.type.replace("-", " and ").replace("ball and screw", "ball screw"))
        return [table(
            r"@{}r l r r r r r@{}",
            ["k", "", "Distance", *(f"{symbol_math(t)} [s]" for t in ("t_m", "t_a", "t_d", "t_j"))],
            rows,
            caption=rf"Moves of the load, repeated (case key \texttt{{[[move]]}}; mechanism: {latex_escape(kind)})",
            note="A trapezoid has no jerk time; with one, each speed ramp starts and ends with a ramp of constant jerk "
                 "(an S-curve).",
        )]

    def steps(self, report) -> list[str]:
        if report.evaluated is None or NAME not in report.evaluated.sections:
            return []
        r = report.evaluated[NAME]
        out = [r"\subsection{Motion and mechanism}"] + [step_block(title, step) for title, step in r.steps]
        rows = [[str(j), g.phase, *(signed(sig(v.value)) for v in (g.duration, g.speed, g.torque))]
                for j, g in enumerate(r.segments, start=1)]
        out.append(table(
            r"@{}r l r r r@{}",
            ["k", "Phase", *(f"{symbol_math(symbol)} [{unit}]" for symbol, unit in (("t_k", "s"), ("n_2k", "rpm"),
                                                                                   ("T_2k", "N·m")))],
            rows,
            caption="Segments derived from the sampled cycle, used as the load cycle",
            note=(f"{r.samples} samples per cycle. Mean speed of each segment; its torque gives the segment's cubic "
                  "mean (the integral over the samples; in a trapezoid's phase the torque is constant and this is its "
                  "value). A pause holds the torque that keeps the load at rest."),
        ))
        return out

    def figures(self, report) -> list:
        m = _motion(report)
        if m is None:
            return []
        from ..figures.motion_plots import motion_figure

        k = m.mechanism
        fig = motion_figure(m.samples, m.cycle.torque, m.segments, to_load=1.0 if k is None else k.to_load(),
                            linear=k is not None and k.linear, rows=("speed", "torque"))
        return [(fig, "Output speed and torque over one cycle, sampled, with the derived segments (dashed).")]

    @page_doc("Where the load cycle comes from: the motion's peak values, or that its segments were changed by hand "
              "(then the moves and mechanism no longer derive it).",
              "m", "calc.sections.motion.MotionResult")
    def page(self, m, view) -> str:
        if view.typed_by_hand:
            return ('<div class="values">Load cycle: the segments as changed here (the case derives them from its '
                    'motion; reset to derive them again)</div>')
        if m is None:
            return ""
        parts = [f"{escape(m.mechanism or '')} from its {escape(m.source)}s".strip(),
                 f"peak speed {value(m.peak_speed)}", f"peak acceleration {value(m.peak_acceleration)}",
                 f"{typeset('J_L')} {value(m.J_L)}" if m.J_L is not None else ""]
        return '<div class="values">Motion: ' + " · ".join(p for p in parts if p) + "</div>"


RENDERER = MotionRenderer()
