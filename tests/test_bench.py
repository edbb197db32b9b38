"""The benchmark (bench/bench.py) runs, at a tiny size, and prints every line; no time is asserted."""

import importlib.util
import subprocess
import sys

from tests.conftest import ROOT

#: Every line ``make bench`` prints, by name (bench/bench.py says what each measures).
LINES = (
    "catalog_load_100k", "rank_100k", "rank_numpy_100k", "loop_100k", "rank_vs_numpy", "loop_vs_rank",
    "ratios_100k", "ratios_numpy_100k", "ratios_loop_100k", "ratios_vs_numpy", "loop_vs_ratios",
    "evaluate_100k_filled", "evaluate_100k_filled_vs_shipped", "evaluate_100k_filled_memory",
    "evaluate_100k_blank", "evaluate_100k_blank_vs_shipped", "evaluate_100k_blank_memory",
    "sweep", "sweep_numpy", "sweep_vs_numpy", "sweep_1M", "sweep_1M_numpy", "sweep_1M_vs_numpy", "hysteresis_1M",
    "motion_1M", "motion_numpy_1M", "motion_loop_1M", "motion_vs_numpy", "motion_loop_vs_motion",
    "combinations", "combinations_numpy", "combinations_loop", "combinations_numpy_vs_ours",
    "combinations_loop_vs_ours", "machine_50_axes", "cases_50_one_by_one",
    "import_numpy", "import_calc", "evaluate_cli", "notebooks", "report", "report_rebuilt", "report_20_cases",
    "review_start", "review_page_ready", "review_change_median", "review_change_max",
    "review_page_transfer", "review_kernel_memory", "review_5_reviewers_median", "review_5_reviewers_memory",
)


def test_benchmark_runs_at_a_tiny_size_and_prints_every_line():
    # The run itself checks that the API, the raw numpy floor and the per-row loop agree.
    done = subprocess.run([sys.executable, "bench/bench.py", "--quick"], cwd=ROOT, capture_output=True, text=True)
    print(done.stdout)
    assert done.returncode == 0, done.stderr
    names = [text.split(":")[0] for text in done.stdout.splitlines()]
    assert names == list(LINES)
    for text in done.stdout.splitlines():
        name, rest = text.split(": ", 1)
        assert rest.split()[0] == "n/a" or float(rest.split()[0]) >= 0, text


def test_every_timed_page_change_ends_in_results():
    # The bench times each change until "text and figures follow": each must leave a design that is
    # evaluated, never one that cannot be (a forced gearbox part of another ratio than the one chosen).
    from bench.review_browser import new_values
    from calc.review.state import ReviewState

    example = ROOT / "cases" / "indexing-table.toml"
    changes = new_values(example, 20)
    state = ReviewState(example)
    state.load()
    assert len(changes) == 20 and len(set(changes)) == 20
    assert {"gearbox.part", "gearbox.ratio"} <= {key for key, _ in changes}
    for key, value in changes:
        if key in ("gearbox.part", "gearbox.ratio"):  # a choice
            assert state.set_value(key, float(value) if key == "gearbox.ratio" else value), (key, value)
        else:
            assert state.type_text(key, value), (key, value)
        shown = state.evaluate()
        assert shown.error is None and shown.report is not None and not shown.left_out, (key, value, shown.left_out)
        assert shown.report.evaluated is not None and not state.refused, (key, value)


def test_a_failed_run_misses_its_target_however_quick(monkeypatch):
    # The script as `make bench` runs it: its folder on the path, for its sibling review_browser.
    monkeypatch.syspath_prepend(str(ROOT / "bench"))
    spec = importlib.util.spec_from_file_location("bench_script", ROOT / "bench" / "bench.py")
    bench = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, "bench_script", bench)  # its dataclasses look their module up
    spec.loader.exec_module(bench)
    assert bench.line("notebooks", 30.0, "s", ("<=", 60), note="passed").endswith("[target <= 60 s: met]")
    missed = bench.line("notebooks", 30.0, "s", ("<=", 60), note="FAILED, pytest exit 1", failed=True)
    assert missed.endswith("[target <= 60 s: MISSED]")
    assert bench.line("notebooks", 61.0, "s", ("<=", 60)).endswith("MISSED]")
