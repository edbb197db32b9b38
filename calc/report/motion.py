"""The motion and the mechanism in the calc report: the mechanism's inputs, the moves, each
formula with its values (the transmission radius, the load's inertia, each move's peak speed and
acceleration, the output torque in each phase), the derived segments and a figure of speed and
torque over the cycle."""

from __future__ import annotations

from ..sections.motion import keys_of
from ..core.units import Q_, sig
from .common import input_row, nothing
from .latex import latex_escape, signed, step_block, symbol_math, table

NAME = "motion"

#: The field of :class:`calc.domain.mechanism.Mechanism` of each of its quantities' keys, where it differs.
FIELDS = {"inertia": "given_inertia", "screw_inertia": "own_inertia", "pinion_inertia": "own_inertia", "pulley_inertia": "own_inertia",
          "pitch_diameter": "diameter", "pulley_diameter": "diameter"}


def _motion(report):
    return None if report.case is None else report.case.motion


def input_rows(report) -> list[list[str]]:
    m = _motion(report)
    if m is None or m.mechanism is None:
        return []
    k = m.mechanism
    quantities = [key.name for key in keys_of(k.type) if key.unit or key.kind == "dimensionless"]
    given = {key: getattr(k, FIELDS.get(key, key)) for key in quantities}
    return [input_row(f"mechanism.{key}", Q_(q)) for key, q in given.items() if q is not None]


def inputs(report) -> list[str]:
    m = _motion(report)
    if m is None:
        return []
    if m.record is not None:
        return [rf"The load cycle is the drive record \texttt{{{latex_escape(m.record)}}} (case key \texttt{{[drive\_record]}}), "
                rf"{len(m.cycle.dt)} intervals between its rows."]
    rows = []
    for k, (move, given) in enumerate(zip(m.moves, m.distances), start=1):
        if move.dwell:
            rows.append([str(k), "dwell", "–", sig(move.time), "–", "–", "–"])
        else:
            rows.append([str(k), "move", latex_escape(f"{given:~P}"), sig(move.time), sig(move.accel_time), sig(move.decel_time),
                         sig(move.jerk_time) if move.jerk_time else "–"])
    kind = "rotary table" if not m.mechanism.linear else m.mechanism.type.replace("-", " and ").replace("ball and screw", "ball screw")
    return [table(
        r"@{}r l r r r r r@{}",
        ["k", "", "Distance", *(f"{symbol_math(t)} [s]" for t in ("t_m", "t_a", "t_d", "t_j"))],
        rows,
        caption=rf"Moves of the load, repeated (case key \texttt{{[[move]]}}; mechanism: {latex_escape(kind)})",
        note="A trapezoid has no jerk time; with one, each speed ramp starts and ends with a ramp of constant jerk (an S-curve).",
    )]


def steps(report) -> list[str]:
    if report.evaluated is None or NAME not in report.evaluated.sections:
        return []
    r = report.evaluated[NAME]
    out = [r"\subsection{Motion and mechanism}"] + [step_block(title, step) for title, step in r.steps]
    rows = [[str(j), g.phase, *(signed(sig(v.value)) for v in (g.duration, g.speed, g.torque))] for j, g in enumerate(r.segments, start=1)]
    out.append(table(
        r"@{}r l r r r@{}",
        ["k", "Phase", f"{symbol_math('t_k')} [s]", f"{symbol_math('n_2k')} [rpm]", f"{symbol_math('T_2k')} [N·m]"],
        rows,
        caption="Segments derived from the sampled cycle, used as the load cycle",
        note=(f"{r.samples} samples per cycle. Mean speed of each segment; its torque gives the segment's cubic mean "
              "(the integral over the samples; in a trapezoid's phase the torque is constant and this is its value). "
              "A pause holds the torque that keeps the load at rest."),
    ))
    return out


def figures(report) -> list:
    m = _motion(report)
    if m is None:
        return []
    from ..figures.motion_plots import motion_figure

    k = m.mechanism
    fig = motion_figure(m.samples, m.cycle.torque, m.segments, to_load=1.0 if k is None else k.to_load(),
                        linear=k is not None and k.linear, rows=("speed", "torque"))
    return [(fig, "Output speed and torque over one cycle, sampled, with the derived segments (dashed).")]


results = checks = candidates = chosen = order_lines = sources = readings = nothing
