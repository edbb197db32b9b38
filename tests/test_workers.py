"""A session run on pytest-xdist's workers (``make test``) is checked as one process's would be: the
error sites built and the tools missing, which each worker records for its own tests, are merged by
the controller (tests/conftest.py) before it makes the checks of the whole session."""

import json

import pytest

from .conftest import ErrorRecord, ToolSkips, merge_record, worker_record
from .error_sites import error_sites
from .test_error_sites import too_long, untriggered


@pytest.fixture
def empty_record(monkeypatch):
    """This process's records emptied for the test, and restored after it."""
    for name, value in {"built": set(), "longest": {}, "whole_folder": False, "reason": "", "merged": 0}.items():
        monkeypatch.setattr(ErrorRecord, name, value)
    monkeypatch.setattr(ToolSkips, "by_tool", {})


def sent(built: list, longest: dict, skips: dict) -> dict:
    """What a worker that built ``built`` sends, as it reaches the controller (a copy, lists for tuples);
    this process's records are left as they were."""
    kept = ErrorRecord.built, ErrorRecord.longest, ErrorRecord.whole_folder, ToolSkips.by_tool
    ErrorRecord.built, ErrorRecord.longest, ErrorRecord.whole_folder = set(built), dict(longest), True
    ToolSkips.by_tool = dict(skips)
    record = json.loads(json.dumps(worker_record()))
    ErrorRecord.built, ErrorRecord.longest, ErrorRecord.whole_folder, ToolSkips.by_tool = kept
    return record


def test_the_sites_two_workers_built_are_checked_together(empty_record):
    # Every site of calc/ built, half on each worker: each half alone leaves sites untriggered, both together none.
    every = [(site.file, site.line) for site in error_sites()]
    halves = every[::2], every[1::2]
    assert all(untriggered(set(half), {}) for half in halves)
    for half in halves:
        merge_record(sent(half, {}, {}))
    assert ErrorRecord.merged == 2 and ErrorRecord.whole_folder and ErrorRecord.built == set(every)
    assert untriggered(ErrorRecord.built, ErrorRecord.longest) == ""


def test_the_longest_message_of_a_site_is_kept_whichever_worker_built_it(empty_record):
    # The first site built on both workers: 20 characters on one, 400 on the other; the length check
    # sees the 400 whichever order the workers end in.
    site = next((site.file, site.line) for site in error_sites())
    for order in ((20, 400), (400, 20)):
        ErrorRecord.longest = {}
        for length in order:
            merge_record(sent([site], {site: "x" * length}, {}))
        assert ErrorRecord.longest == {site: "x" * 400}
        assert "(400 characters)" in too_long(ErrorRecord.built, ErrorRecord.longest)


def test_the_skips_for_want_of_a_tool_are_summed(empty_record):
    merge_record(sent([], {}, {"chromium": 3}))
    merge_record(sent([], {}, {"chromium": 2, "xelatex": 1}))
    assert ToolSkips.by_tool == {"chromium": 5, "xelatex": 1}


def test_a_message_is_measured_as_a_run_in_one_process_builds_it(monkeypatch, tmp_path):
    # A worker's temporary folders lie one level deeper (popen-gw1/): the length check counts the message
    # with the run's folder, as one process would have written it, so both give the same verdict.
    run = tmp_path / "pytest-9"
    monkeypatch.setattr(ErrorRecord, "worker_folder", (f"{run / 'popen-gw1'}/", f"{run}/"))
    message = f"{run / 'popen-gw1' / 'test_x0' / 'case.toml'}: motor.part: no part 'X' in catalog motors.csv"
    assert ErrorRecord.as_in_one_process(message) == f"{run / 'test_x0' / 'case.toml'}: motor.part: no part 'X' in " \
        "catalog motors.csv"
    assert len(ErrorRecord.as_in_one_process(message)) == len(message) - len("popen-gw1/")
