"""The workbook's benchmark: one line per measurement, ``name: value unit``, all from one run.

Run it with ``make bench`` (or ``.venv/bin/python bench/bench.py``). Each figure that has a target
is followed by it, ``[target <= 2 x: met]``. What is measured:

* ``rank_100k``: the gearbox selection of the example case (``cases/indexing-table.toml``) over a
  synthetic catalog of 100,000 rows at its ratio, through the public API
  (:func:`calc.domain.gearbox.rows_at_ratio`, :func:`calc.domain.gearbox.select_gearbox`: quantities in,
  quantities out). Beside it ``rank_numpy_100k``, the same computation in raw numpy on float
  arrays (the floor), and ``loop_100k``, the per-row loop with pint scalar quantities that a
  scalar library leads to, run on a slice and scaled. The three must give the same ranking; the
  run stops if they do not.
* ``ratios_100k``: the best ratio of the example's typed form (``tests/cases/indexing-table-profile.toml``:
  segments, so the floor and the API both leave the rotor term out) over a synthetic catalog of 100,000 rows at
  six ratios, through the public API (:func:`calc.domain.ratios.search_ratios`: one selection over every
  row, the best row of each ratio, the motor through each over the cycle, the pick), with the
  motor's rated torque and top speed set so that every check is made. Beside it
  ``ratios_numpy_100k``, the same in raw numpy, and ``ratios_loop_100k``, the per-row pint loop (a
  whole evaluation per row), run on a slice and scaled. The three must pick the same rows; the run
  stops if they do not.
* ``sweep``: a design space of ratio × cycle time × motor peak torque (10^5 points) evaluated with
  the package's Formula objects broadcast over arrays, beside the same in raw numpy; ``sweep_1M``
  the same with 10^6 points, where the fixed cost of each call weighs ten times less.
* ``catalog_load_100k``: reading and validating that catalog's CSV file, the first
  :func:`calc.data.catalog.load_catalog` of it in the run (a later one is served from what was read;
  no target; not part of ``rank_100k``).
* ``evaluate_100k_filled`` and ``evaluate_100k_blank``: ``python -m calc evaluate --json`` of a
  copy of the example case whose ``gearbox.catalog`` is a synthetic catalog of 100,000 rows at its
  ratio (the shipped rows at that ratio among them, as the accuracy chain names one), in the
  shipped catalog's columns with the optional ones (family, size, forces, ...) filled or left
  blank, end to end in a fresh process; ``_vs_shipped`` its time over that of the example with
  the shipped catalog, and ``_memory`` its peak resident memory.
* ``hysteresis_1M``: the analysis of a measured hysteresis loop of 10^6 samples.
* ``motion_1M``: deriving a load cycle of 10^6 samples from its moves and mechanism (a quarter-turn
  trapezoid index and a dwell of a rotary table: :func:`calc.domain.motion.sample`, the mechanism's torque,
  :func:`calc.domain.motion.segments`), beside ``motion_numpy_1M``, the same cycle on a uniform grid in raw
  numpy (the floor), and ``motion_loop_1M``, the obvious loop over the samples with Python floats,
  run on a slice and scaled. The three must give the same segments; the run stops if they do not.
* ``combinations``: every motor with every gearbox row at every ratio (:data:`COMBINATIONS`: 200
  synthetic motors × 100 series × 16 ratios over a 20,000-sample cycle) checked and one pair picked
  through :func:`calc.domain.combinations.search` (the motor torque's peak and RMS from the cycle's
  moments), beside ``combinations_numpy``, the same in raw numpy with a pass over the samples for
  each gearbox row and every motor, and ``combinations_loop``, :func:`calc.domain.motor.motor_load` per
  pair, run on ten pairs and scaled. The three must agree on the torques and the pick; the run
  stops if they do not.
* ``import_calc``, ``evaluate_cli``, ``report``: cold runs of a fresh interpreter (median of 5 for
  the first two), beside ``import_numpy``. ``import_calc`` is ``from calc import ureg``: the package
  with its unit registry, which a bare ``import calc`` builds only when first asked for. ``report``
  builds the example's PDF as a first build does (a changed case, a new PDF): the files a last pass
  kept (:func:`calc.report.publish.kept_passes`) removed before each run, so each takes two xelatex
  passes (the compiled preamble stays, as it does for any user after the first report).
  ``report_rebuilt``, no target: the same PDF built again from its kept pass, one xelatex pass where
  its labels have not moved.
* ``notebooks``: the nbval run of every notebook, ``pytest notebooks``.
* ``report_20_cases``: ``python -m calc report`` of 20 cases (the project's shipped cases in turn) with ``--summary``,
  as many at a time as the machine has cores.
* ``review_page_ready``, ``review_change_median``, ``review_change_max``: the served design review
  (``make review``) in headless Chromium (bench/review_browser.py): from asking for the page to
  the panel's results shown (asked for as soon as the server has launched its first kernel, Voilà's
  "pool is filled": the page's notebook still runs in it), and each of
  :data:`REVIEW_CHANGES` changes to values not seen before (each input the page offers for the
  example, found by its key path, in turn), typed into the page's number fields or chosen, each timed
  on the page's own clock (:func:`review_browser.timed_change`) from its commit (Enter pressed, or the
  option chosen: the typing before it is the reviewer's) to the first frame drawn with the results
  (text and figures), without the driver's messages to the page and back; every value is new, so
  each figure whose inputs change is drawn, and each leaves a design that is evaluated (a gearbox part
  forced only while the ratio is the file's): a change that ends in an error or without figures stops
  the run.
  ``review_start``: from starting the server (``python -m calc.review.serve``, as ``make review``
  does) to its first kernel launched, plus ``review_page_ready``: a reviewer's wait from the command
  to a verdict (their browser already open). Each of these, and ``report``, is measured in
  :data:`PAGE_RUNS` runs: the line gives the median, which the target judges, with the minimum
  and maximum.
* ``review_5_reviewers_median``, ``review_5_reviewers_memory``: five pages of the served review at
  once, each with its own kernel, each changing the index time to its own values at the same
  moment, three rounds (bench/review_browser.py, ``reviewers_at_once``): the median time from a
  page's input to its new results, and the kernels' resident memory per page.
* ``review_page_transfer``, ``review_kernel_memory``: the page opened once more in a fresh browser
  (nothing cached, :func:`review_browser.first_load`): the bytes it receives (bodies as sent and
  headers; target 2 MB: 5.2 MB uncompressed), and its kernel's resident memory (target 220 MB; the
  frequency response the page draws no longer imports python-control and SciPy, some 90 MB).

In-process timings are the best of several repeats (the least disturbed by the other work of a
shared machine); ratios are taken between figures of this one run.

``--quick`` runs every measurement at a tiny size, once, to prove the script works (the test
suite does so); its figures mean nothing. It leaves out the notebook run, the report, the page's
second load (transfer and kernel memory) and the reviewers at once, which the test suite covers
itself (the last two through the same functions, tests/outputs/test_review_signoff_browser.py and
test_review_browser.py), and visits the page with a few changes in one browser (not one launched
for each visit).
"""

from __future__ import annotations

import argparse
import csv
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from review_browser import (  # beside this file
    CHROMIUM, first_load, new_values, review_in_browser, reviewers_at_once, served,
)

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "cases" / "indexing-table.toml"
TYPED_EXAMPLE = ROOT / "tests" / "cases" / "indexing-table-profile.toml"  # its cycle typed: the ratio floor's form
JUDGED = True  # figures are held against the targets (not with --quick)


@dataclass(frozen=True)
class Size:
    rows: int  # synthetic catalog rows
    loop_rows: int  # rows the per-row pint loop runs on (then scaled to ``rows``)
    sweep: tuple[int, int, int]  # ratios × cycle times × peak torques
    sweep_large: tuple[int, int, int]  # the same, ten times the points
    samples: int  # samples of a hysteresis loop and of a motion cycle
    repeats: int  # in-process repeats (best of)
    runs: int  # subprocess runs (median of)
    judged: bool  # whether the figures are held against the targets


FULL = Size(rows=100_000, loop_rows=2_000, sweep=(40, 50, 50), sweep_large=(100, 100, 100), samples=1_000_000,
            repeats=15, runs=5, judged=True)
QUICK = Size(rows=300, loop_rows=30, sweep=(4, 5, 5), sweep_large=(5, 5, 8), samples=2_000, repeats=1, runs=1,
             judged=False)


def timed(fn) -> tuple[float, object]:
    """The wall time of one call of ``fn``, in seconds, and its result."""
    t0 = time.perf_counter()
    result = fn()
    return time.perf_counter() - t0, result


def best_of_pair(fn, floor, repeats: int) -> tuple[float, object, float, object]:
    """The shortest of ``repeats`` timed calls of a computation and of its floor, run in turn so
    that both meet the same load of a shared machine, and their last results. One untimed call
    of each comes first: first-call costs belong to the cold-start figures."""
    times, floor_times = [], []
    result, floor_result = fn(), floor()
    for _ in range(repeats):
        t0 = time.perf_counter()
        result = fn()
        t1 = time.perf_counter()
        floor_result = floor()
        times.append(t1 - t0)
        floor_times.append(time.perf_counter() - t1)
    return min(times), result, min(floor_times), floor_result


def median_run(command: list[str], runs: int) -> float:
    """The median wall time of ``runs`` fresh processes of ``command``, in seconds."""
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        subprocess.run(command, cwd=ROOT, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


#: Run in a fresh interpreter: runs the command given as its arguments once and prints the wall
#: time and the peak resident memory of that one child (the wrapper has no other child).
_MEASURED_CHILD = """
import resource, subprocess, sys, time
t0 = time.perf_counter()
subprocess.run(sys.argv[1:], check=True, stdout=subprocess.DEVNULL)
print(time.perf_counter() - t0, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
"""


def measured_run(command: list[str]) -> tuple[float, float]:
    """The wall time (s) and peak resident memory (MB) of one fresh process of ``command``."""
    done = subprocess.run([sys.executable, "-c", _MEASURED_CHILD, *command], cwd=ROOT, check=True, capture_output=True,
                          text=True)
    seconds, max_rss_kib = done.stdout.split()  # Linux reports ru_maxrss in KiB
    return float(seconds), int(max_rss_kib) / 1024


def line(name: str, value: float | None, unit: str, target: tuple[str, float] | None = None, note: str = "",
         failed: bool = False) -> str:
    """``name: value unit`` with the target and whether it is met, or ``n/a`` and why. With
    ``--quick`` no target is given (:data:`JUDGED`). A run that ``failed`` misses its target, however
    quick it was."""
    if value is None:
        return f"{name}: n/a ({note})"
    text = f"{name}: {value:.3g} {unit}" if unit == "x" else f"{name}: {value:.4g} {unit}"
    if note:
        text += f" ({note})"
    if target is not None and JUDGED:
        op, bound = target
        met = not failed and (value <= bound if op == "<=" else value >= bound)
        text += f"  [target {op} {bound:g} {unit}: {'met' if met else 'MISSED'}]"
    return text


#: Why a line of ``--quick`` has no figure.
QUICK_LEFT_OUT = "left out in --quick"


def unmeasured(why: str, *named: tuple[str, str]) -> list[str]:
    """The lines ``(name, unit)`` with no figure, each saying ``why``.

    Parameters
    ----------
    why : str
        Why they were not measured.
    *named : tuple of str
        Each line's name and unit.

    Returns
    -------
    list of str
        The lines, as :func:`line` prints them.
    """
    return [line(name, None, unit, note=why) for name, unit in named]


# --- rank: a synthetic catalog -------------------------------------------------------------------

HEADER = (
    "part,series,ratio [1],T_2N [N*m],T_2B [N*m],T_2Not [N*m],n_1N [rpm],n_1max [rpm],eta [percent],"
    "backlash [arcmin],C_t21 [N*m/arcmin],J_1 [kg*cm**2],illustrative,source"
)


def write_synthetic_catalog(path: Path, rows: int, ratio, seed: int = 1) -> None:
    """A gearbox catalog of ``rows`` made-up rows, all at ``ratio`` (or, for a sequence of ratios,
    each in turn), in the units makers print (whole rpm, so some rows sit exactly on a speed
    check's boundary, as real ones do)."""
    ratios = np.resize(np.atleast_1d(np.asarray(ratio, float)), rows)
    rng = np.random.default_rng(seed)
    t_2n = rng.uniform(10, 2000, rows).round(1)
    t_2b = (t_2n * rng.uniform(1.5, 2.2, rows)).round(1)
    t_2not = (t_2b * 1.5).round(1)
    n_1n = rng.uniform(1500, 5000, rows).round(0)
    n_1max = (n_1n * rng.uniform(1.2, 2.5, rows)).round(0)
    eta = rng.uniform(90, 98, rows).round(1)
    backlash = rng.uniform(1, 10, rows).round(1)
    c_t21 = rng.uniform(5, 500, rows).round(1)
    j_1 = rng.uniform(0.1, 50, rows).round(2)
    illustrative = np.where(rng.uniform(size=rows) < 0.3, "yes", "no")
    with open(path, "w", encoding="utf-8") as f:
        f.write(HEADER + "\n")
        for k in range(rows):
            f.write(
                f"SYN{k:06d}-{ratios[k]:g},SYN,{ratios[k]:g},{t_2n[k]},{t_2b[k]},{t_2not[k]},{n_1n[k]},{n_1max[k]},"
                f"{eta[k]},"
                f"{backlash[k]},{c_t21[k]},{j_1[k]},{illustrative[k]},synthetic\n"
            )


def rank_api(catalog, case):
    """The public API: quantities in, a ranked :class:`calc.domain.gearbox.GearboxSelection` out."""
    from calc.domain.gearbox import rows_at_ratio, select_gearbox

    rows = rows_at_ratio(catalog, case.ratio)
    return select_gearbox(case.profile, rows, case.motor_peak_torque, case.motor_inertia, case.load_inertia)


@dataclass
class Floats:
    """The inputs of the selection as plain SI floats, prepared outside the timed region."""

    ratio: np.ndarray
    T_2N: np.ndarray
    T_2B: np.ndarray
    T_2Not: np.ndarray
    n_1N: np.ndarray  # rad/s
    n_1max: np.ndarray
    eta: np.ndarray  # fraction
    J_1: np.ndarray  # kg·m²
    parts: np.ndarray  # str
    illustrative: np.ndarray  # bool
    i: float
    t: np.ndarray  # segment durations, s
    n: np.ndarray  # segment speeds, rad/s
    T: np.ndarray  # segment torques, N·m
    moving: np.ndarray
    T_1B: float
    J_motor: float
    J_L: float


def floats(catalog, case) -> Floats:
    p = case.profile
    return Floats(
        ratio=catalog["ratio"].m_as(""),
        T_2N=catalog["T_2N"].m_as("N*m"),
        T_2B=catalog["T_2B"].m_as("N*m"),
        T_2Not=catalog["T_2Not"].m_as("N*m"),
        n_1N=catalog["n_1N"].m_as("rad/s"),
        n_1max=catalog["n_1max"].m_as("rad/s"),
        eta=catalog["eta"].m_as(""),
        J_1=catalog["J_1"].m_as("kg*m**2"),
        parts=catalog.parts.astype(str),
        illustrative=np.array([str(m).lower() == "yes" for m in catalog.text["illustrative"]]),
        i=case.ratio.m_as(""),
        t=p.durations.m_as("s"),
        n=p.speeds.m_as("rad/s"),
        T=p.torques.m_as("N*m"),
        moving=p.moving,
        T_1B=case.motor_peak_torque.m_as("N*m"),
        J_motor=case.motor_inertia.m_as("kg*m**2"),
        J_L=case.load_inertia.m_as("kg*m**2"),
    )


def rank_numpy(f: Floats):
    """The floor: the same selection on float arrays (duty, n_2m, T_2m, Z_h, f_s, T_2max, the four
    checks and the emergency stop, the inertia ratio, passes, ranking by lexsort: passing first,
    published before illustrative rows, smallest size, lowest worst utilization, part name).
    Returns the order, passes, T_2max and the ranking keys (size, worst utilization)."""
    rows = np.isclose(f.ratio, f.i, rtol=1e-6, atol=0)
    return select_numpy(f, rows)


def select_numpy(f: Floats, rows):
    """:func:`rank_numpy` over the rows ``rows`` (a mask or index), each at its own ratio."""
    from calc.core.checks import BOUNDARY_RTOL, rank
    from calc.domain.gearbox import SHOCK_FACTORS

    i, t_2n, t_2b, t_2not, n_1n, n_1max, eta, j_1, parts, illustrative = (
        a[rows] for a in (f.ratio, f.T_2N, f.T_2B, f.T_2Not, f.n_1N, f.n_1max, f.eta, f.J_1, f.parts, f.illustrative)
    )
    t, n, T = f.t[f.moving], f.n[f.moving], f.T[f.moving]
    t_on, t_cycle = t.sum(), f.t.sum()
    s5 = t_on / t_cycle < 0.6 * (1 - BOUNDARY_RTOL) and t_on < 1200.0 * (1 - BOUNDARY_RTOL)
    w = np.abs(n) * t
    n_2m = w.sum() / t.sum()
    t_2m = np.cbrt((w * np.abs(T) ** 3).sum() / w.sum())
    z_h = 3600.0 / t_cycle
    f_s = SHOCK_FACTORS.factors[np.searchsorted(SHOCK_FACTORS.bounds, z_h * (1 + BOUNDARY_RTOL), side="right") - 1]
    t_2max = f.T_1B * eta * f_s * i
    u = (n_2m * i / n_1n, t_2m / t_2n, np.abs(n).max() * i / n_1max, t_2max / t_2b)
    _ = (j_1 + f.J_L / i**2) / f.J_motor  # inertia ratio, as the API gives it
    u_stop = f.T_1B * i / t_2not  # the emergency stop, in both modes; not checked without T_2Not
    governing = u[2:] if s5 else u[:2]
    passes = (np.logical_and.reduce([g <= 1.0 + BOUNDARY_RTOL for g in governing])
              & ((u_stop <= 1.0 + BOUNDARY_RTOL) | np.isnan(t_2not)))
    worst = np.fmax(np.max(governing, axis=0), u_stop)
    worst = np.where(np.isnan(worst), np.inf, worst)
    size = np.where(passes, t_2b if s5 else t_2n, 0.0)
    order = rank(passes, size, worst, parts, illustrative)  # the ranking is numpy on floats already
    return order, passes, t_2max, (size, worst)


def same_ranking(order, floor_order, keys) -> bool:
    """Whether two rankings agree, up to rows whose keys tie to rounding (a utilization computed
    through rpm and through rad/s may differ in its last bit, and the part name then decides)."""
    differ = order != floor_order
    size, worst = keys
    a, b = order[differ], floor_order[differ]
    return bool(np.all(size[a] == size[b]) and np.allclose(worst[a], worst[b], rtol=1e-12, atol=0))


def rank_loop(catalog, case, rows: int):
    """The per-row loop a scalar library leads to: pint scalar quantities, one row at a time.
    Returns the ranking of the first ``rows`` rows."""
    return np.array([key[-1] for key in loop_keys(catalog, case, rows)])


def loop_keys(catalog, case, rows: int) -> list:
    """:func:`rank_loop`'s ranking keys ``(fails, illustrative, size, worst, part, row)`` of the
    first ``rows`` rows (those at the case's ratio; every row where the case has none), sorted."""
    from calc import Q_
    from calc.core.checks import BOUNDARY_RTOL

    p = case.profile
    segments = [(p.durations[k], p.speeds[k], p.torques[k]) for k in range(len(p.phases)) if p.phases[k] != "pause"]
    t_on = sum((t for t, _, _ in segments), Q_(0, "s"))
    t_cycle = sum((p.durations[k] for k in range(len(p.phases))), Q_(0, "s"))
    s5 = (t_on / t_cycle).to("") < 0.6 * (1 - BOUNDARY_RTOL) and t_on < Q_(20, "min") * (1 - BOUNDARY_RTOL)
    weight = sum((abs(n) * t for t, n, _ in segments), Q_(0, "rpm*s"))
    n_2m = weight / t_on
    t_2m = (sum((abs(n) * t * abs(T) ** 3 for t, n, T in segments), Q_(0, "rpm*s*N**3*m**3")) / weight) ** (1 / 3)
    z_h = (1 / t_cycle).to("1/hour").magnitude * (1 + BOUNDARY_RTOL)
    f_s = 2.0 if z_h >= 3000 else 1.6 if z_h >= 2000 else 1.3 if z_h >= 1500 else 1.1 if z_h >= 1000 else 1.0
    n_2max = max(abs(n) for _, n, _ in segments)
    T_1B, J_motor, J_L = case.motor_peak_torque, case.motor_inertia, case.load_inertia
    ratio, t_2n, t_2b, t_2not, n_1n, n_1max, eta, j_1 = (
        catalog[c] for c in ("ratio", "T_2N", "T_2B", "T_2Not", "n_1N", "n_1max", "eta", "J_1")
    )
    keys = []
    for k in range(rows):
        i = ratio[k]
        if case.ratio is not None and abs(i.m_as("") - case.ratio.m_as("")) > 1e-6 * case.ratio.m_as(""):
            continue
        t_2max = T_1B * i * f_s * eta[k]
        u = [
            (n_2m * i / n_1n[k]).m_as(""),
            (t_2m / t_2n[k]).m_as(""),
            (n_2max * i / n_1max[k]).m_as(""),
            (t_2max / t_2b[k]).m_as(""),
        ]
        _ = ((j_1[k] + J_L / i**2) / J_motor).m_as("")
        u_stop = (T_1B * i / t_2not[k]).m_as("")
        governing = u[2:] if s5 else u[:2]
        passes = (all(x <= 1.0 + BOUNDARY_RTOL for x in governing)
                  and (np.isnan(u_stop) or u_stop <= 1.0 + BOUNDARY_RTOL))
        size = (t_2b[k] if s5 else t_2n[k]).m_as("N*m") if passes else 0.0
        later = passes and str(catalog.text["illustrative"][k]).lower() == "yes"
        worst = max(governing) if np.isnan(u_stop) else max(*governing, u_stop)
        keys.append((not passes, later, size, worst, str(catalog.parts[k]), k))
    return sorted(keys)


def measure_rank(size: Size, workdir: Path) -> list[str]:
    from calc.sections import evaluate
    from calc.sections.case import read_case
    from calc.data.catalog import load_catalog
    from calc.domain.gearbox import SCHEMA

    case = evaluate(read_case(EXAMPLE), "axis").case  # the motor the evaluation chooses from the motor catalog
    path = workdir / "synthetic-gearboxes.csv"
    write_synthetic_catalog(path, size.rows, case.ratio.m_as(""))
    load_time, catalog = timed(lambda: load_catalog(path, SCHEMA))
    f = floats(catalog, case)

    api_time, selection, floor_time, (order, passes, t_2max, keys) = best_of_pair(
        lambda: rank_api(catalog, case), lambda: rank_numpy(f), size.repeats
    )
    if not (np.array_equal(selection.passes, passes) and same_ranking(selection.order, order, keys)):
        raise RuntimeError("rank: the public API and the raw numpy floor rank the synthetic catalog differently")
    if not np.allclose(selection.T_2max.m_as("N*m"), t_2max, rtol=1e-12):
        raise RuntimeError("rank: the public API and the raw numpy floor give different T_2max")

    loop_rows = min(size.loop_rows, size.rows)
    loop_time, loop_order = timed(lambda: rank_loop(catalog, case, loop_rows))
    columns = ("ratio", "T_2N", "T_2B", "T_2Not", "n_1N", "n_1max", "eta", "J_1", "parts", "illustrative")
    sub = Floats(**{**f.__dict__, **{k: getattr(f, k)[:loop_rows] for k in columns}})
    sub_order, _, _, sub_keys = rank_numpy(sub)
    if not same_ranking(loop_order, sub_order, sub_keys):
        raise RuntimeError("rank: the per-row pint loop ranks the slice differently from the floor")
    loop_scaled = loop_time * size.rows / loop_rows

    return [
        line("catalog_load_100k", load_time, "s", note=f"{size.rows} rows read and validated; not part of rank"),
        line("rank_100k", api_time, "s",
             note=f"{size.rows} rows, rows_at_ratio + select_gearbox, quantities in and out"),
        line("rank_numpy_100k", floor_time, "s", note="the same on float arrays"),
        line("loop_100k", loop_scaled, "s",
             note=f"pint scalars row by row: {loop_rows} rows timed, scaled to {size.rows}"),
        line("rank_vs_numpy", api_time / floor_time, "x", ("<=", 2)),
        line("loop_vs_rank", loop_scaled / api_time, "x", (">=", 100)),
    ]


#: The ratios of the synthetic catalog of the ratio search, and the motor ratings it checks
#: besides the example's peak torque (so that every check of the motor is made).
SEARCH_RATIOS = (3, 4, 5, 7, 8, 10)
SEARCH_T_1N, SEARCH_N_MAX = 4.0, 6000.0  # N·m, rpm


def ratios_api(catalog, case, load):
    """The public API: quantities in, a :class:`calc.domain.ratios.RatioSearch` out."""
    from calc import Q_
    from calc.domain.gearbox import INERTIA_RATIO_LIMIT
    from calc.domain.ratios import search_ratios

    return search_ratios(catalog, case.profile, load, Q_(SEARCH_T_1N, "N*m"), Q_(SEARCH_N_MAX, "rpm"),
                         inertia_limit=INERTIA_RATIO_LIMIT, motor_peak_torque=case.motor_peak_torque,
                         motor_inertia=case.motor_inertia, load_inertia=case.load_inertia)


def ratios_numpy(f: Floats):
    """The floor: every row's gearbox checks and ranking (:func:`select_numpy`), the first row of
    each ratio in the ranking, the motor torque through each (typed segments: driving
    ``T_2 / (i η)``, driven back ``T_2 η / i``), its peak, RMS and speed checks, the inertia
    ratio and the pick (lowest RMS among feasible ratios with λ <= 10). Returns the best row of
    each ratio and the pick."""
    from calc.core.checks import BOUNDARY_RTOL
    from calc.domain.gearbox import INERTIA_RATIO_LIMIT

    order, passes, _, _ = select_numpy(f, slice(None))
    ratios, group = np.unique(f.ratio, return_inverse=True)
    _, first = np.unique(group[order], return_index=True)
    rows = order[first]
    i, eta = f.ratio[rows][:, None], f.eta[rows][:, None]
    T_1 = np.where(f.T * f.n < 0, f.T * eta / i, f.T / (i * eta))
    peak = np.abs(T_1).max(axis=1)
    rms = np.sqrt((T_1**2 * f.t).sum(axis=1) / f.t.sum())
    speed = np.abs(f.n).max() * i[:, 0] * 30 / np.pi  # rpm

    def ok(u):
        return u <= 1.0 + BOUNDARY_RTOL

    feasible = passes[rows] & ok(peak / f.T_1B) & ok(rms / SEARCH_T_1N) & ok(speed / SEARCH_N_MAX)
    lam = (f.J_1[rows] + f.J_L / i[:, 0] ** 2) / f.J_motor
    within = feasible & ok(lam / INERTIA_RATIO_LIMIT)
    pick = int(np.lexsort((ratios, np.where(within, rms, np.inf)))[0]) if within.any() else None
    return rows, pick


def ratios_loop(catalog, case, rows: int):
    """The per-row loop: every row checked with pint scalars (:func:`rank_loop`), the first row of
    each ratio, the motor torque of each segment through it with pint scalars, the pick. Returns
    the best row of each ratio (ascending) and the pick, over the first ``rows`` rows."""
    import dataclasses

    from calc import Q_
    from calc.core.checks import BOUNDARY_RTOL
    from calc.domain.gearbox import INERTIA_RATIO_LIMIT

    best, fails = {}, {}
    for key in loop_keys(catalog, dataclasses.replace(case, ratio=None), rows):
        k = key[-1]
        fails[k] = key[0]
        best.setdefault(float(catalog["ratio"][k].m_as("")), k)
    p = case.profile
    keyed = []
    for r in sorted(best):
        k = best[r]
        i, eta = catalog["ratio"][k], catalog["eta"][k]
        torques = [T * eta / i if (T * n).magnitude < 0 else T / (i * eta) for T, n in zip(p.torques, p.speeds)]
        peak = max(abs(T) for T in torques)
        rms = (sum((T**2 * t for T, t in zip(torques, p.durations)), Q_(0, "N**2*m**2*s")) / p.t_cycle) ** 0.5
        speed = p.n_2max * i
        lam = ((catalog["J_1"][k] + case.load_inertia / i**2) / case.motor_inertia).m_as("")
        ok = not fails[k] and all(
            x <= 1.0 + BOUNDARY_RTOL
            for x in ((peak / case.motor_peak_torque).m_as(""), (rms / Q_(SEARCH_T_1N, "N*m")).m_as(""),
                      (speed / Q_(SEARCH_N_MAX, "rpm")).m_as(""))
        )
        if ok and lam <= INERTIA_RATIO_LIMIT * (1 + BOUNDARY_RTOL):
            keyed.append((rms.m_as("N*m"), r))
    ratios = sorted(best)
    pick = ratios.index(min(keyed)[1]) if keyed else None
    return np.array([best[r] for r in ratios]), pick


def measure_ratios(size: Size, workdir: Path) -> list[str]:
    from calc.sections.case import read_case
    from calc.data.catalog import load_catalog
    from calc.domain.gearbox import SCHEMA
    from calc.sections.motor import output_load

    case = read_case(TYPED_EXAMPLE)  # typed segments: the floor leaves the rotor term out, as the API then does
    path = workdir / "synthetic-ratios.csv"
    write_synthetic_catalog(path, size.rows, SEARCH_RATIOS, seed=2)
    catalog = load_catalog(path, SCHEMA)
    load = output_load(case)
    f = floats(catalog, case)
    api_time, search, floor_time, (rows, pick) = best_of_pair(lambda: ratios_api(catalog, case, load),
                                                              lambda: ratios_numpy(f), size.repeats)
    if not (np.array_equal(search.rows, rows) and search.pick == pick):
        raise RuntimeError("ratios: the public API and the raw numpy floor pick different rows")
    loop_rows = min(size.loop_rows, size.rows)
    loop_time, (loop_best, loop_pick) = timed(lambda: ratios_loop(catalog, case, loop_rows))
    columns = ("ratio", "T_2N", "T_2B", "T_2Not", "n_1N", "n_1max", "eta", "J_1", "parts", "illustrative")
    sub = Floats(**{**f.__dict__, **{k: getattr(f, k)[:loop_rows] for k in columns}})
    if not (np.array_equal(loop_best, ratios_numpy(sub)[0]) and loop_pick == ratios_numpy(sub)[1]):
        raise RuntimeError("ratios: the per-row pint loop picks differently from the floor")
    loop_scaled = loop_time * size.rows / loop_rows
    return [
        line("ratios_100k", api_time, "s", note=f"{size.rows} rows at {len(SEARCH_RATIOS)} ratios, "
             "search_ratios: best gearbox and motor per ratio, the pick"),
        line("ratios_numpy_100k", floor_time, "s", note="the same on float arrays"),
        line("ratios_loop_100k", loop_scaled, "s",
             note=f"pint scalars row by row: {loop_rows} rows timed, scaled to {size.rows}"),
        line("ratios_vs_numpy", api_time / floor_time, "x", ("<=", 2)),
        line("loop_vs_ratios", loop_scaled / api_time, "x", (">=", 100)),
    ]


#: The optional columns of the shipped gearbox catalog that the large catalog fills (``filled``) or
#: leaves blank (``blank``), with a made-up value of row ``k`` for the filled kind: a catalog that
#: leaves them blank must cost no more than one that fills them.
OPTIONAL_CELLS = {
    "family": lambda k: f"SYN{k % 40}",
    "size": lambda k: f"{k % 25 * 5 + 40:03d}",
    "stages [1]": lambda k: str(1 + k % 2),
    "J_1_hub [mm]": lambda k: "14",
    "F_2A [N]": lambda k: str(2000 + k % 900),
    "F_2R [N]": lambda k: str(1500 + k % 700),
    "M_2K [N*m]": lambda k: str(100 + k % 300),
    "m [kg]": lambda k: "1.2",
    "unclear": lambda k: "the rated speed is read from a chart" if k % 97 == 0 else "",
}


def write_large_case(workdir: Path, rows: int, optional: str) -> Path:
    """A copy of the example case whose ``gearbox.catalog`` is a synthetic catalog of ``rows`` rows
    at its ratio, in the shipped catalog's columns, with the :data:`OPTIONAL_CELLS` ``"blank"`` or
    ``"filled"``: the shipped rows at that ratio (the accuracy chain names one of them) and made-up
    rows whose ratings vary, so the ranking has work to do. The folder links the project's
    ``data`` so that the case's measurement paths hold."""
    from calc.sections.case import read_case

    ratio = read_case(EXAMPLE).ratio.m_as("")
    folder = workdir / f"large-{optional}" / "cases"
    folder.mkdir(parents=True)
    (folder.parent / "data").symlink_to(ROOT / "data")
    with open(ROOT / "catalogs" / "gearboxes.csv", encoding="utf-8", newline="") as f:
        header, *shipped = csv.reader(f)
    names = HEADER.split(",")
    if not set(names) | set(OPTIONAL_CELLS) <= set(header):
        raise RuntimeError("evaluate_100k: catalogs/gearboxes.csv no longer has the synthetic catalog's columns")
    # The shipped rows at the ratio; partial rows (never ranked) left out.
    partial = header.index("partial") if "partial" in header else None
    shipped = [row for row in shipped
               if float(row[header.index("ratio [1]")]) == ratio and (partial is None or not row[partial])]
    synthetic = workdir / f"synthetic-{optional}.csv"
    write_synthetic_catalog(synthetic, rows - len(shipped), ratio)
    catalog = folder / "gearboxes-large.csv"
    with open(synthetic, encoding="utf-8", newline="") as f, open(catalog, "w", encoding="utf-8", newline="") as out:
        made, *made_rows = csv.reader(f)
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(header)
        for k, row in enumerate(made_rows):
            cells = dict(zip(made, row))
            writer.writerow([
                cells[name] if name in cells
                else OPTIONAL_CELLS[name](k) if optional == "filled" and name in OPTIONAL_CELLS else ""
                for name in header
            ])
        writer.writerows(shipped)
    text = EXAMPLE.read_text(encoding="utf-8")
    if text.count('catalog = "gearboxes"\n') != 1 or text.count('family = "NPT"\n') != 1:
        raise RuntimeError(f"evaluate_100k: {EXAMPLE} no longer names its gearbox catalog and family as this "
                           "benchmark expects")
    case = folder / EXAMPLE.name
    # every row of the large catalog is checked: the family the example keeps to is dropped
    case.write_text(text.replace('catalog = "gearboxes"\n', f'catalog = "{catalog.name}"\n')
                    .replace('family = "NPT"\n', ""), encoding="utf-8")
    return case


def measure_evaluate_large(size: Size, workdir: Path) -> list[str]:
    py = sys.executable
    shipped = [measured_run([py, "-m", "calc", "evaluate", str(EXAMPLE.relative_to(ROOT)), "--json"])
               for _ in range(size.runs)]
    shipped_time = statistics.median(t for t, _ in shipped)
    out = []
    for optional in ("filled", "blank"):
        case = write_large_case(workdir, size.rows, optional)
        large = [measured_run([py, "-m", "calc", "evaluate", str(case), "--json"]) for _ in range(size.runs)]
        large_time = statistics.median(t for t, _ in large)
        name = f"evaluate_100k_{optional}"
        out += [
            line(name, large_time, "s",
                 note=f"python -m calc evaluate --json, {size.rows} catalog rows at the example's ratio, "
                 f"optional columns {optional}, median of {size.runs}; shipped catalog {shipped_time:.3g} s"),
            line(f"{name}_vs_shipped", large_time / shipped_time, "x", ("<=", 2)),
            line(f"{name}_memory", max(m for _, m in large), "MB", ("<=", 500),
                 note="peak resident memory of the process"),
        ]
    return out


# --- sweep: a design space ------------------------------------------------------------------------

#: The gearbox and load cycle swept: the example's cycle shape with the pause varied.
SWEEP_GEARBOX = {"T_2B": 400.0, "n_1max": 6000.0, "eta": 0.97}  # N·m, rpm, fraction
SWEEP_T_ON, SWEEP_N_2MAX = 1.0, 300.0  # s, rpm


def sweep_grid(shape):
    n_i, n_t, n_T = shape
    return (
        np.linspace(3, 100, n_i)[:, None, None],  # ratio
        np.linspace(1.1, 10, n_t)[None, :, None],  # cycle time, s
        np.linspace(2, 50, n_T)[None, None, :],  # motor peak torque, N·m
    )


def sweep_inputs(grid) -> dict:
    """The sweep's inputs as quantities, built outside the timed region (as the floor's floats are)."""
    from calc import Q_

    return {
        "i": Q_(grid[0], ""),
        "t_cycle": Q_(grid[1], "s"),
        "T_1B": Q_(grid[2], "N*m"),
        "t_on": Q_(SWEEP_T_ON, "s"),
        "n_2max": Q_(SWEEP_N_2MAX, "rpm"),
        "eta": Q_(SWEEP_GEARBOX["eta"], ""),
        "T_2B": Q_(SWEEP_GEARBOX["T_2B"], "N*m"),
        "n_1max": Q_(SWEEP_GEARBOX["n_1max"], "rpm"),
        "ED_max": Q_(60, "percent"),
    }


def sweep_api(q: dict):
    """Every point of the grid through the Formula objects (quantities in, quantities out):
    duty cycle, cycles per hour, shock factor, T_2max, peak input speed, the two S5 utilizations."""
    from calc import Q_
    from calc.core.checks import CheckArray
    from calc.domain.gearbox import T_2max, n_1, shock_factor
    from calc.domain.profile import ED, Z_h

    ed = ED(t_on=q["t_on"], t_cycle=q["t_cycle"])
    f_s = shock_factor(Z_h(z_c=Q_(1, ""), t_cycle=q["t_cycle"]))  # one move per cycle (E16)
    t_2max = T_2max(T_1B=q["T_1B"], i=q["i"], f_s=Q_(f_s, ""), eta=q["eta"])
    n_1max = n_1(n_2=q["n_2max"], i=q["i"])
    torque = CheckArray("T_2B", "S5", "T_2max <= T_2B", t_2max, q["T_2B"], "N*m")
    speed = CheckArray("n_1max", "S5", "n_2max · i <= n_1max", n_1max, q["n_1max"], "rpm")
    return (ed < q["ED_max"]) & (torque.utilization <= 1.0) & (speed.utilization <= 1.0), t_2max


def sweep_numpy(grid):
    """The same on float arrays."""
    from calc.domain.gearbox import SHOCK_FACTORS
    from calc.core.checks import BOUNDARY_RTOL

    ratio, t_cycle, T_1B = grid
    ed = SWEEP_T_ON / t_cycle
    z_h = 3600.0 / t_cycle * (1 + BOUNDARY_RTOL)
    f_s = SHOCK_FACTORS.factors[np.searchsorted(SHOCK_FACTORS.bounds, z_h, side="right") - 1]
    t_2max = T_1B * SWEEP_GEARBOX["eta"] * f_s * ratio  # in the formula's order: one product over the whole grid
    u_torque = t_2max / SWEEP_GEARBOX["T_2B"]
    u_speed = SWEEP_N_2MAX * ratio / SWEEP_GEARBOX["n_1max"]
    return (ed < 0.6) & (u_torque <= 1.0) & (u_speed <= 1.0), t_2max


def measure_sweep(size: Size) -> list[str]:
    out = []
    for shape, name in ((size.sweep, "sweep"), (size.sweep_large, "sweep_1M")):
        grid = sweep_grid(shape)
        inputs = sweep_inputs(grid)
        api_time, (passes, t_2max), floor_time, (passes_np, t_2max_np) = best_of_pair(
            lambda: sweep_api(inputs), lambda: sweep_numpy(grid), size.repeats
        )
        if not (np.array_equal(passes, passes_np) and np.allclose(t_2max.m_as("N*m"), t_2max_np, rtol=1e-12)):
            raise RuntimeError(f"{name}: the Formula objects and the raw numpy floor disagree")
        points = int(np.prod(shape))
        out += [
            line(name, api_time, "s", note=f"{points} points, Formula objects over arrays"),
            line(f"{name}_numpy", floor_time, "s", note="the same on float arrays"),
            line(f"{name}_vs_numpy", api_time / floor_time, "x", ("<=", 2) if name == "sweep" else None),
        ]
    return out


# --- hysteresis, cold starts, notebooks, report ----------------------------------------------------


def measure_hysteresis(size: Size) -> list[str]:
    """:func:`calc.domain.hysteresis.analyze_loop` on a loop drawn by the model of a catalog gearbox,
    unevenly sampled, with noise on torque and twist (as a rig records it)."""
    from calc import Q_
    from calc.domain.hysteresis import analyze_loop, model_for_part

    model = model_for_part("NPT035-10")
    loop = model.loop(size.samples, noise_torque=Q_(0.05, "N*m"), noise_twist=Q_(0.02, "arcmin"), seed=1)
    analyze_loop(loop, model.nominal_torque)  # first-call costs belong to the cold-start figures
    elapsed, _ = timed(lambda: analyze_loop(loop, model.nominal_torque))
    return [line("hysteresis_1M", elapsed, "s", ("<=", 0.5), note=f"analyze_loop, {size.samples} samples")]


#: The bench's motion: a table of 0.15 kg·m² against 3 N·m of friction turns a quarter turn in
#: 0.5 s with ramps of 0.15 s, then dwells 1.0 s.
MOTION = dict(J=0.15, T_f=3.0, distance=np.pi / 2, time=0.5, ramp=0.15, dwell=1.0)


def motion_api(samples: int):
    from calc import Q_
    from calc.domain.mechanism import Mechanism
    from calc.domain.motion import Move, sample
    from calc.domain.profile import segments

    m = MOTION
    table = Mechanism("rotary", inertia=Q_(m["J"], "kg*m**2"), friction_torque=Q_(m["T_f"], "N*m"),
                      process_torque=Q_(0, "N*m"))
    s = sample([Move(m["distance"], m["time"], m["ramp"], m["ramp"]), Move(0.0, m["dwell"])], samples)
    g = segments(s, table.torque(s.speed, s.acceleration))
    return g.duration, g.speed, g.torque


def motion_numpy(samples: int):
    """The same cycle in raw numpy: midpoints of a uniform grid, each phase by its time window."""
    m = MOTION
    cycle = m["time"] + m["dwell"]
    w = m["distance"] / (m["time"] - m["ramp"])
    a = w / m["ramp"]
    dt = cycle / samples
    t = (np.arange(samples) + 0.5) * dt
    bounds = np.array([m["ramp"], m["time"] - m["ramp"], m["time"]])
    phase = np.searchsorted(bounds, t, side="right")
    speed = np.select([phase == 0, phase == 1, phase == 2], [a * t, np.full_like(t, w), w - a * (t - bounds[1])], 0.0)
    acc = np.select([phase == 0, phase == 2], [a, -a], 0.0)
    torque = m["J"] * acc + m["T_f"] * np.sign(speed)
    duration = np.bincount(phase, minlength=4) * dt
    mean = np.bincount(phase, weights=speed, minlength=4) * dt / duration
    weight = np.abs(speed)
    cubic = np.bincount(phase, weights=weight * np.abs(torque) ** 3, minlength=4)
    base = np.bincount(phase, weights=weight, minlength=4)
    T = np.zeros(4)
    T[:3] = np.sign(np.bincount(phase, weights=weight * torque**3, minlength=4)[:3]) * np.cbrt(cubic[:3] / base[:3])
    return duration, mean, T


def motion_loop(samples: int, rows: int):
    """The obvious loop: each sample's speed, acceleration and torque with Python floats, the
    segment sums accumulated as it goes; ``rows`` of the ``samples`` (a uniform grid) timed."""
    m = MOTION
    cycle = m["time"] + m["dwell"]
    w = m["distance"] / (m["time"] - m["ramp"])
    a = w / m["ramp"]
    dt = cycle / samples
    sums = [[0.0, 0.0, 0.0, 0.0, 0.0] for _ in range(4)]  # time, speed·dt, |n|·|T|³·dt, |n|·dt, |n|·T³·dt
    for k in range(rows):
        t = (k + 0.5) * dt
        if t < m["ramp"]:
            p, v, acc = 0, a * t, a
        elif t < m["time"] - m["ramp"]:
            p, v, acc = 1, w, 0.0
        elif t < m["time"]:
            p, v, acc = 2, w - a * (t - (m["time"] - m["ramp"])), -a
        else:
            p, v, acc = 3, 0.0, 0.0
        torque = m["J"] * acc + (m["T_f"] if v > 0 else 0.0)
        row = sums[p]
        row[0] += dt
        row[1] += v * dt
        row[2] += abs(v) * abs(torque) ** 3 * dt
        row[3] += abs(v) * dt
        row[4] += abs(v) * torque**3 * dt
    return sums


def measure_motion(size: Size) -> list[str]:
    api_time, (duration, speed, torque), floor_time, (f_duration, f_speed, f_torque) = best_of_pair(
        lambda: motion_api(size.samples), lambda: motion_numpy(size.samples), size.repeats
    )
    # The package samples each piece on its own grid and the floor on one grid over the cycle; a
    # trapezoid's segment means are exact on both (a sample or two at each corner of the floor's grid
    # straddle two phases, so its durations are within a sample of the true ones).
    rtol = 20 / size.samples
    if not (np.allclose(torque, f_torque, rtol=rtol, atol=1e-9) and np.allclose(speed, f_speed, rtol=rtol, atol=1e-9)
            and np.allclose(duration, f_duration, atol=2 * (MOTION["time"] + MOTION["dwell"]) / size.samples)):
        raise RuntimeError("motion: the package and the raw numpy floor give different segments")
    rows = max(1, size.samples // 20)
    loop_time, _ = timed(lambda: motion_loop(size.samples, rows))
    loop_scaled = loop_time * size.samples / rows
    return [
        line("motion_1M", api_time, "s", ("<=", 0.5),
             note=f"{size.samples} samples: sample, the mechanism's torque, segments"),
        line("motion_numpy_1M", floor_time, "s", note="the same cycle on a uniform grid in raw numpy"),
        line("motion_loop_1M", loop_scaled, "s",
             note=f"Python floats sample by sample: {rows} samples timed, scaled to {size.samples}"),
        line("motion_vs_numpy", api_time / floor_time, "x", ("<=", 3)),
        line("motion_loop_vs_motion", loop_scaled / api_time, "x", (">=", 3)),
    ]


# --- every motor with every gearbox at every ratio ------------------------------------------------

#: Motors, gearbox series and ratios of the combination search, and the samples of its cycle.
COMBINATIONS = dict(motors=200, gearboxes=100, ratios=(3, 4, 5, 7, 8, 10, 12, 15, 16, 20, 25, 28, 35, 40, 50, 70),
                    samples=20_000)


def combination_inputs(motors: int, gearboxes: int, ratios, samples: int, seed: int = 3):
    """A sampled cycle at the output (the motion benchmark's index of a rotary table, its load
    ten times lighter), ``gearboxes`` series each at every ratio and ``motors`` motors with
    ratings that grow with their size, as float arrays in SI units."""
    from calc import Q_
    from calc.domain.mechanism import Mechanism
    from calc.domain.motion import Move, sample

    m = MOTION
    table = Mechanism("rotary", inertia=Q_(m["J"] / 10, "kg*m**2"), friction_torque=Q_(m["T_f"] / 10, "N*m"),
                      process_torque=Q_(0, "N*m"))
    s = sample([Move(m["distance"], m["time"], m["ramp"], m["ramp"]), Move(0.0, m["dwell"])], samples)
    torque = np.asarray(table.torque(s.speed, s.acceleration), float)  # N·m, SI floats
    cycle = (s.dt, torque, s.speed, s.acceleration)
    rng = np.random.default_rng(seed)
    i = np.tile(np.asarray(ratios, float), gearboxes)
    series = np.repeat(rng.uniform(5.0, 500.0, gearboxes), len(ratios))  # the T_2B of each series
    eta = np.where(i > 10, 0.94, 0.97)
    gear = {"i": i, "eta": eta, "J_1": np.repeat(rng.uniform(1e-5, 5e-4, gearboxes), len(ratios)) / i ** 0.5,
            "passes": rng.random(len(i)) > 0.1, "peak_limit": series / (i * 1.6 * eta), "rank": series,
            "J_L": m["J"] / 10}
    rated = np.geomspace(0.1, 40.0, motors)
    motor = {"J": 1.5e-5 * rated ** 1.3, "rated_torque": rated, "peak_torque": 3.2 * rated,
             "max_speed": np.full(motors, 6000 * np.pi / 30) / (1 + rated / 40)}
    return cycle, float(np.abs(s.speed).max()), gear, motor


def combinations_numpy(cycle, top_speed, gear, motor):
    """The same search in raw numpy: each gearbox row's motor torque over every sample for every
    motor at once (motors × samples), its peak and RMS, and the same checks and rule."""
    from calc.domain.gearbox import INERTIA_RATIO_LIMIT

    dt, T, w, a = cycle
    back = T * w < 0
    peak = np.empty((len(gear["i"]), len(motor["J"])))
    rms = np.empty_like(peak)
    for g, (i, eta, J_1) in enumerate(zip(gear["i"], gear["eta"], gear["J_1"])):
        T_1 = (motor["J"][:, None] + J_1) * i * a + np.where(back, T * eta / i, T / (i * eta))
        peak[g] = np.abs(T_1).max(axis=1)
        rms[g] = np.sqrt((T_1 * T_1) @ dt / dt.sum())
    i = gear["i"][:, None]
    lam = (gear["J_1"][:, None] + gear["J_L"] / i**2) / motor["J"]
    u = (peak / motor["peak_torque"], rms / motor["rated_torque"], top_speed * i / motor["max_speed"],
         motor["peak_torque"] / gear["peak_limit"][:, None], lam / INERTIA_RATIO_LIMIT)
    feasible = gear["passes"][:, None] & np.logical_and.reduce([x <= 1 + 1e-9 for x in u])
    rows, cols = np.nonzero(feasible)
    keys = (gear["i"][rows], rms[rows, cols] / motor["rated_torque"][cols], gear["rank"][rows], motor["J"][cols],
            motor["rated_torque"][cols])
    best = np.lexsort(keys)[0]
    return (int(rows[best]), int(cols[best])), peak, rms


def combinations_loop(cycle, gear, motor, pairs):
    """The per-combination loop: :func:`calc.domain.motor.motor_load` (quantities, a pass over the samples)
    for each (gearbox row, motor) pair given."""
    from calc import Q_
    from calc.domain.motor import motor_load

    dt, T, w, a = (Q_(cycle[0], "s"), Q_(cycle[1], "N*m"), Q_(cycle[2], "rad/s"), Q_(cycle[3], "rad/s**2"))
    out = []
    for g, m in pairs:
        load = motor_load(dt, T, w, Q_(gear["i"][g], ""), Q_(gear["eta"][g], ""), a, Q_(motor["J"][m], "kg*m**2"),
                          Q_(gear["J_1"][g], "kg*m**2"))
        out.append((float(load.peak.m_as("N*m")), float(load.rms.m_as("N*m"))))
    return out


def measure_combinations(size: Size) -> list[str]:
    from calc.domain.combinations import CycleMoments, search
    from calc.domain.gearbox import INERTIA_RATIO_LIMIT

    c = COMBINATIONS if size.judged else dict(motors=20, gearboxes=5, ratios=(5, 10), samples=2_000)
    cycle, top, gear, motor = combination_inputs(c["motors"], c["gearboxes"], c["ratios"], c["samples"])
    pairs = len(gear["i"]) * len(motor["J"])
    api_time, found = min((timed(lambda: search(CycleMoments.of(*cycle), (top, 0.0), gear, motor, INERTIA_RATIO_LIMIT))
                           for _ in range(max(1, size.repeats // 3))), key=lambda x: x[0])
    floor_time, (floor_pick, floor_peak, floor_rms) = timed(lambda: combinations_numpy(cycle, top, gear, motor))
    same = np.allclose(found.peak, floor_peak, rtol=1e-9) and np.allclose(found.rms, floor_rms, rtol=1e-9)
    if found.pick != floor_pick or not same:
        raise RuntimeError("combinations: the moments and the raw numpy floor give different torques or picks")
    rng = np.random.default_rng(5)
    sample = [found.pick,
              *zip(rng.integers(0, len(gear["i"]), 9).tolist(), rng.integers(0, len(motor["J"]), 9).tolist())]
    loop_time, loop = timed(lambda: combinations_loop(cycle, gear, motor, sample))
    if not np.allclose(loop, [(found.peak[g, m], found.rms[g, m]) for g, m in sample], rtol=1e-9):
        raise RuntimeError("combinations: the per-combination loop gives other torques than the moments")
    loop_scaled = loop_time * pairs / len(sample)
    what = (f"{len(motor['J'])} motors x {c['gearboxes']} gearboxes x {len(c['ratios'])} ratios "
            f"over {c['samples']} samples")
    return [
        line("combinations", api_time, "s", ("<=", 1),
             note=f"{what}: the cycle's moments, every pair's peak, RMS and checks, the pick"),
        line("combinations_numpy", floor_time, "s",
             note="raw numpy: each gearbox row's motor torque over every sample for every motor"),
        line("combinations_loop", loop_scaled, "s",
             note=f"calc.domain.motor.motor_load per pair: {len(sample)} pairs timed, scaled to {pairs}"),
        line("combinations_numpy_vs_ours", floor_time / api_time, "x",
             note="the three agree on the pick and on the torques"),
        line("combinations_loop_vs_ours", loop_scaled / api_time, "x"),
    ]


#: The axes of the machine benchmark: the two shipped cases in turn on one DC bus (their cycles, 2 s and
#: 1.5 s, divide the machine's 6 s).
MACHINE_AXES, MACHINE_AXES_QUICK = 50, 4


def measure_machine(size: Size, workdir: Path) -> list[str]:
    from calc.sections import evaluate, read_case
    from calc.sections.machine import machine

    axes = MACHINE_AXES if size.judged else MACHINE_AXES_QUICK
    shipped = [ROOT / "cases" / "ball-screw-direct.toml", EXAMPLE]
    files = [shipped[k % 2] for k in range(axes)]
    text = 'title = "bench machine"\ncycle = "6 s"\n' + "".join(
        f'[[axis]]\ncase = "{f}"\nstart = "{0.1 * k:.1f} s"\n' for k, f in enumerate(files))
    path = workdir / "machine.toml"
    path.write_text(text + '[dc_bus.brake_resistor]\nresistance = "50 ohm"\ncontinuous_power = "200 W"\n',
                    encoding="utf-8")
    one_by_one, _ = timed(lambda: [evaluate(read_case(f)) for f in files])
    together, result = timed(lambda: machine(path))
    return [
        line(f"machine_{MACHINE_AXES}_axes", together, "s", ("<=", 3),
             note=f"calc.sections.machine.machine: {axes} axes of 2 case files on one DC bus, "
                  f"{len(result.times) - 1} steps of the common time base"),
        line(f"cases_{MACHINE_AXES}_one_by_one", one_by_one, "s",
             note=f"the same {axes} case files read and evaluated one by one"),
    ]


def measure_cold(size: Size) -> list[str]:
    py = sys.executable
    numpy_time = median_run([py, "-c", "import numpy"], size.runs)
    # With its unit registry, which ``import calc`` alone leaves until first asked for (calc/__init__.py).
    calc_time = median_run([py, "-c", "from calc import ureg"], size.runs)
    cli_time = median_run([py, "-m", "calc", "evaluate", str(EXAMPLE.relative_to(ROOT))], size.runs)
    runs = f"median of {size.runs}"
    return [
        line("import_numpy", numpy_time, "s", note=runs),
        line("import_calc", calc_time, "s", ("<=", 0.5), note=f"from calc import ureg, {runs}"),
        line("evaluate_cli", cli_time, "s", ("<=", 1.0),
             note=f"python -m calc evaluate {EXAMPLE.relative_to(ROOT)}, {runs}"),
    ]


def measure_notebooks(size: Size, quick: bool) -> list[str]:
    notebooks = sorted((ROOT / "notebooks").glob("*.ipynb"))
    if quick:
        return unmeasured(QUICK_LEFT_OUT, ("notebooks", "s"))
    if not notebooks:
        return [line("notebooks", None, "s", note="no notebooks yet")]
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "pytest", "notebooks", "-q"], cwd=ROOT, capture_output=True, text=True)
    elapsed = time.perf_counter() - t0
    verdict = "passed" if done.returncode == 0 else f"FAILED, pytest exit {done.returncode}"
    return [line("notebooks", elapsed, "s", ("<=", 60), note=f"pytest notebooks, {len(notebooks)} notebooks, {verdict}",
                 failed=done.returncode != 0)]


def measure_report(size: Size, quick: bool, workdir: Path) -> list[str]:
    if quick:
        return unmeasured(QUICK_LEFT_OUT, ("report", "s"), ("report_rebuilt", "s"), ("report_20_cases", "s"))
    from calc.report.publish import PASS_FILES, kept_passes

    pdf = workdir / "indexing-table.pdf"
    command = [sys.executable, "-m", "calc", "report", str(EXAMPLE.relative_to(ROOT)), "-o", str(pdf)]
    kept = kept_passes(pdf)

    def forget_kept_pass() -> None:
        for suffix in PASS_FILES if kept is not None else ():
            kept.with_name(kept.name + suffix).unlink(missing_ok=True)

    times, failed = {"cold": [], "rebuilt": []}, None
    for kind in times:  # cold: each run as a first build of a changed case; rebuilt: the same PDF again
        for _ in range(PAGE_RUNS):
            if kind == "cold":
                forget_kept_pass()
            t0 = time.perf_counter()
            done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
            times[kind].append(time.perf_counter() - t0)
            if done.returncode != 0 or not pdf.is_file():
                failed = f"FAILED, exit {done.returncode}: {done.stderr.strip().splitlines()[-1:]}"
                break
        if failed:
            break
    forget_kept_pass()
    if failed:
        out = [line(name, None, "s", note=failed) for name in ("report", "report_rebuilt")]
    else:
        about = f"python -m calc report {EXAMPLE.relative_to(ROOT)}, a {pdf.stat().st_size // 1024} KiB PDF"
        out = [line("report", statistics.median(times["cold"]), "s", ("<=", 4),
                    note=f"{about}, no earlier pass of it kept (two xelatex passes); {spread(times['cold'])}"),
               line("report_rebuilt", statistics.median(times["rebuilt"]), "s",
                    note=f"the same PDF built again from its last pass (one xelatex pass); {spread(times['rebuilt'])}")]
    # 20 cases, the project's shipped cases in turn, laid out as the project is (a case names ../data/...).
    (workdir / "cases20").mkdir()
    shutil.copytree(ROOT / "data", workdir / "data", dirs_exist_ok=True)
    shipped = sorted((ROOT / "cases").glob("*.toml"))
    for k in range(20):
        shutil.copy(shipped[k % len(shipped)], workdir / "cases20" / f"axis-{k + 1:02d}.toml")
    cases = sorted(str(p) for p in (workdir / "cases20").glob("*.toml"))
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "calc", "report", *cases, "--summary", "-o",
                           str(workdir / "reports20")], cwd=ROOT, capture_output=True, text=True)
    elapsed = time.perf_counter() - t0
    if done.returncode != 0:
        return out + [line("report_20_cases", None, "s",
                           note=f"FAILED, exit {done.returncode}: {done.stderr.strip().splitlines()[-1:]}")]
    return out + [line("report_20_cases", elapsed, "s", ("<=", 60),
                       note=f"python -m calc report of 20 cases --summary, {os.cpu_count()} at a time")]


#: The changes the review benchmark makes on the example ``make review`` opens: each input the page
#: offers, in turn, to a value not seen before (:func:`review_browser.new_values`), so each figure
#: whose inputs change is drawn; at the quick size a few, to prove the browser part works.
REVIEW_CHANGES, REVIEW_CHANGES_QUICK = 20, 3


#: Runs of each page and report measurement, whose median meets the target (min and max printed).
PAGE_RUNS = 3

#: Reviewers at once on the served page (``review_5_reviewers``), and the rounds of changes they make.
CROWD, CROWD_ROUNDS = 5, 3


def settle(quick: bool) -> float:
    """How long a page is read before its first timed change [s]: the server starts the next page's
    kernel ``FILL_DELAY`` after a page takes one (:mod:`calc.review.serve`), and its start (about a
    second) is over before the changes are timed; at the quick size, a second.

    Parameters
    ----------
    quick : bool
        The quick size (``--quick``).

    Returns
    -------
    float
        The time [s].
    """
    from calc.review.serve import FILL_DELAY

    return 1.0 if quick else FILL_DELAY + 1.0


def spread(values: list[float], unit: str = "s") -> str:
    """``median of 3: min 0.1, max 0.2 s`` of several runs' figures."""
    if len(values) == 1:
        return "one run"
    return f"median of {len(values)}: min {min(values):.3g}, max {max(values):.3g} {unit}"


def measure_review(quick: bool, workdir: Path) -> list[str]:
    if not CHROMIUM.exists():  # the lines in the order a run prints them
        return unmeasured(f"no Chromium at {CHROMIUM}: make browser", *(
            (name, "s") for name in ("review_start", "review_page_ready", "review_change_median", "review_change_max")),
            ("review_page_transfer", "MB"), ("review_kernel_memory", "MB"), (f"review_{CROWD}_reviewers_median", "s"),
            (f"review_{CROWD}_reviewers_memory", "MB"))
    changes = new_values(EXAMPLE, REVIEW_CHANGES_QUICK if quick else REVIEW_CHANGES)
    runs, first = [], None
    for _ in range(1 if quick else PAGE_RUNS):
        with served() as server:
            runs.append((server.started, review_in_browser(server.url, workdir / "screenshots", changes,
                                                           settle=settle(quick), results_each=True,
                                                           fresh=not quick)))
            if len(runs) == 1 and not quick:
                first = first_load(server.url)  # a second reviewer, nothing cached
    start = [started + visit.ready for started, visit in runs]
    ready = [visit.ready for _, visit in runs]
    median = [visit.median for _, visit in runs]
    worst = [max(visit.times) for _, visit in runs]
    slowest = max((c for _, visit in runs for c in visit.changes), key=lambda c: c[1])[0]
    note = f"{len(runs[0][1].times)} changes to new values in headless Chromium, each ending in results"
    med = statistics.median
    return [
        line("review_start", med(start), "s", ("<=", 2.5),
             note=f"the server's first kernel launched, then the page; {spread(start)}"),
        line("review_page_ready", med(ready), "s", ("<=", 2.5), note=spread(ready)),
        line("review_change_median", med(median), "s", ("<=", 0.1), note=f"{note}; {spread(median)}"),
        line("review_change_max", med(worst), "s", ("<=", 0.2), note=f"slowest {slowest}; {spread(worst)}"),
        *measure_first(first),
        *measure_crowd(quick),
    ]


def measure_first(first) -> list[str]:
    """The page's second load, in a fresh browser (:func:`review_browser.first_load`): what it transfers, and
    its kernel's memory; None: left out (``--quick``)."""
    if first is None:
        return unmeasured(QUICK_LEFT_OUT, ("review_page_transfer", "MB"), ("review_kernel_memory", "MB"))
    memory = first.kernel_mb
    return [
        line("review_page_transfer", first.transfer / 1e6, "MB", ("<=", 2),
             note=f"{first.requests} requests, nothing cached, responses compressed"),
        line("review_kernel_memory", memory, "MB", ("<=", 220),
             note="resident memory of a page's kernel" if memory is not None else "its kernel not found (Linux only)"),
    ]


def measure_crowd(quick: bool) -> list[str]:
    """:data:`CROWD` reviewers at once, each page changing the index time to its own values."""
    if quick:
        return unmeasured(QUICK_LEFT_OUT, (f"review_{CROWD}_reviewers_median", "s"),
                          (f"review_{CROWD}_reviewers_memory", "MB"))
    rounds = [[f"{0.6 + 0.05 * (r * CROWD + k):g}" for k in range(CROWD)] for r in range(CROWD_ROUNDS)]
    with served() as server:
        crowd = reviewers_at_once(server, "move[1].time", rounds, settle=settle(False))
    note = f"{CROWD} pages at once, {len(rounds)} rounds of changes"
    return [
        line(f"review_{CROWD}_reviewers_median", crowd.median, "s", ("<=", 0.5),
             note=f"{note}; slowest {max(crowd.times):.3g} s"),
        line(f"review_{CROWD}_reviewers_memory", crowd.memory, "MB", note="resident memory of the kernels per page"),
    ]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="tiny sizes, one repeat: proves the script works")
    args = parser.parse_args(argv)
    size = QUICK if args.quick else FULL
    global JUDGED
    JUDGED = size.judged
    with tempfile.TemporaryDirectory() as tmp:
        for measure in (
            lambda: measure_rank(size, Path(tmp)),
            lambda: measure_ratios(size, Path(tmp)),
            lambda: measure_evaluate_large(size, Path(tmp)),
            lambda: measure_sweep(size),
            lambda: measure_hysteresis(size),
            lambda: measure_motion(size),
            lambda: measure_combinations(size),
            lambda: measure_machine(size, Path(tmp)),
            lambda: measure_cold(size),
            lambda: measure_notebooks(size, args.quick),
            lambda: measure_report(size, args.quick, Path(tmp)),
            lambda: measure_review(args.quick, Path(tmp)),
        ):
            for text in measure():
                print(text, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
