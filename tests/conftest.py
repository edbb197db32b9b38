"""Shared fixtures: the example case, and writers for case and catalog files in a temporary folder;
and the record of which error messages of the package the tests trigger."""

import fnmatch
import functools
import json
import os
import shutil
import sys
import tempfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "tests" / "cases" / "indexing-table-profile.toml"  # the typed load cycle the tests work by hand
DERIVED_EXAMPLE = ROOT / "cases" / "indexing-table.toml"  # the example: its cycle derived from the motion
GEARBOXES = ROOT / "catalogs" / "gearboxes.csv"
# The example's motor as ratings typed into the case (the motor the tests work by hand), in place of the catalog's
# choice.
TYPED_MOTOR = 'peak_torque = "12 N*m"\ninertia = "4.2 kg*cm**2"\n'


def derived_with_typed_motor() -> str:
    """The example's case file with :data:`TYPED_MOTOR` in place of its motor catalog."""
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8")
    assert text.count('catalog = "motors"\n') == 1, "the example no longer chooses its motor from catalogs/motors.csv"
    return text.replace('catalog = "motors"\n', TYPED_MOTOR)

# The typed example's load cycle, in the case-file format (used to build variants in tests).
PROFILE_TOML = """
[[profile]]
phase = "accel"
duration = "0.2 s"
speed = "150 rpm"
torque = "60 N*m"
[[profile]]
phase = "const"
duration = "0.6 s"
speed = "300 rpm"
torque = "20 N*m"
[[profile]]
phase = "decel"
duration = "0.2 s"
speed = "150 rpm"
torque = "-45 N*m"
[[profile]]
phase = "pause"
duration = "1.0 s"
"""

HEAD_TOML = """
title = "test axis"
[motor]
peak_torque = "12 N*m"
inertia = "4.2 kg*cm**2"
[load]
inertia = "1500 kg*cm**2"
[gearbox]
ratio = 10
"""


def run(capsys, *args):
    """``python -m calc evaluate ARGS`` in this process: exit code, standard output, standard error.
    Results written as JSON are checked against the contract's schema (docs/results.schema.json),
    so every case a test evaluates checks it."""
    from calc.__main__ import main

    code = main(["evaluate", *map(str, args)])
    out, err = capsys.readouterr()
    if code in (0, 1) and "--json" in args:
        check_results(out)
    return code, out, err


def check_results(text: str) -> dict:
    """The results of ``evaluate --json`` read strictly (no NaN or infinity, which JSON lacks)
    and validated against docs/results.schema.json; an error names where it breaks the schema."""

    def refuse(constant):
        raise AssertionError(f"the results hold {constant}, which JSON does not have")

    results = json.loads(text, parse_constant=refuse)
    errors = sorted(results_schema().iter_errors(results), key=lambda e: list(e.absolute_path))
    assert not errors, "; ".join(f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in errors[:5])
    return results


@functools.cache
def results_schema():
    """The validator of docs/results.schema.json (the schema checked first), made on first use: a pytest
    run in a child process that imports this module for its hooks (tests/test_tool_skips.py) imports no
    jsonschema, whose import costs seconds of CPU (calc.report.publish says why)."""
    import jsonschema

    schema = json.loads((ROOT / "docs" / "results.schema.json").read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


@pytest.fixture
def write_case(tmp_path):
    """Write a case file from TOML text; returns its path."""

    def write(text: str, name: str = "case.toml") -> Path:
        path = tmp_path / name
        path.write_text(text)
        return path

    return write


# The cases whose calc reports the tests read: the example, a title of LaTeX's special characters,
# a case no gearbox passes, one that cannot be evaluated.
REPORT_TITLE = r"Axis #3 — 50% load & T_2 {v2} \ 100$"
REPORT_CASES = {
    "escape": f"title = '{REPORT_TITLE}'\n" + HEAD_TOML.replace('title = "test axis"', "") + PROFILE_TOML,
    # 400 N·m · 10 · 1.3 · η (0.95 to 0.97) >= 4940 N·m, above every T_2B at ratio 10 (the largest: TP500-10, 4000 N·m)
    "failing": HEAD_TOML.replace('"12 N*m"', '"400 N*m"') + PROFILE_TOML,
    "unreadable": HEAD_TOML.replace("ratio = 10", "ratio = 13") + PROFILE_TOML,
}


@pytest.fixture(scope="session")
def report_run(tmp_path_factory):
    """The PDFs the tests read, built once per run: ``python -m calc report`` of the example and
    :data:`REPORT_CASES` with ``--summary --strict`` (a PDF build takes seconds; each test file
    building its own made the suite twice as long). The cases, the output folder and the process."""
    import subprocess

    folder = tmp_path_factory.mktemp("reports")
    cases = [EXAMPLE]
    for name, text in REPORT_CASES.items():
        (folder / f"{name}.toml").write_text(text, encoding="utf-8")
        cases.append(folder / f"{name}.toml")
    out = folder / "out"
    proc = subprocess.run(
        [sys.executable, "-m", "calc", "report", *map(str, cases), "--summary", "--strict", "-o", str(out)],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    return cases, out, proc


def sphinx_book(out: Path, lecturer: bool) -> Path:
    """The course's book built as ``make book`` builds it (``-t lecturer``: as ``make lecturer`` does) into
    ``out``, its build time printed; a failed build fails the test with Sphinx's errors."""
    import subprocess
    import time

    start = time.perf_counter()
    tags = ["-t", "lecturer"] if lecturer else []
    run = subprocess.run([sys.executable, "-m", "sphinx", "-q", "-W", "--keep-going", *tags, "-c", "book", ".",
                          str(out)], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    print(f"\n{'lecturer' if lecturer else 'students'}' book: built in {time.perf_counter() - start:.1f} s")
    return out


@pytest.fixture(scope="session")
def students_book(tmp_path_factory):
    """The students' book (``make book``), built once per run: tests/test_book.py opens its pages, and
    tests/test_course.py hands it out with the students' material (a build takes 4 s of CPU)."""
    return sphinx_book(tmp_path_factory.mktemp("students"), lecturer=False)


# --- Which error messages the tests trigger (checked by tests/test_error_sites.py) -------------
#
# Only items under tests/ count: the check must give the same verdict under ``pytest tests`` as
# under the whole suite, and a message needs a test here that asserts its content; a doctest or
# notebook that happens to build the error does not replace it. Only errors built in this process
# count: a test that runs ``python -m calc`` as a subprocess triggers nothing here.

TESTS = Path(__file__).resolve().parent
FINAL = TESTS / "test_error_sites.py"
_OWN_INIT = pytest.StashKey()
_OWN_CACHE = pytest.StashKey()


class ErrorRecord:
    """The (file, line) of each ``CalcError(...)`` built in ``calc/`` while a test under tests/ ran,
    and whether this session selected the whole tests/ folder (if not, ``reason`` says why)."""

    built: set[tuple[str, int]] = set()
    longest: dict[tuple[str, int], str] = {}  # the longest message each site built
    deselected: int = 0
    whole_folder: bool = False
    reason: str = ""
    merged: int = 0  # on the controller: how many workers' records are merged in
    session_checks: set[str] = set()  # on the controller: the checks of the whole session selected, which it makes
    item = None  # the test under tests/ being run, or None
    worker_folder: tuple[str, str] | None = None  # on a worker: its temporary folder, and the run's

    @classmethod
    def as_in_one_process(cls, message: str) -> str:
        """A message as a run in one process would have built it: on a worker, its temporary folder
        named as the run's (10 characters fewer), so that the length check gives the same verdict."""
        return message.replace(*cls.worker_folder) if cls.worker_folder else message


#: Set by .ci/run: a test that needs a tool this machine lacks fails instead of being skipped, so a
#: CI machine without XeLaTeX or Chromium cannot pass by skipping.
REQUIRE_TOOLS = "CALC_REQUIRE_TOOLS"

#: The tools tests need beside Python, each looked up on PATH, and how to get them.
TOOLS = {"xelatex": "make tex", "pandoc": "make tex", "pdftotext": "make tex", "pdftoppm": "make tex",
         "chromium": "make browser"}


def missing_tools(*names: str) -> list[str]:
    """Those of ``names`` (keys of :data:`TOOLS`) that are not on PATH."""
    return [n for n in names if shutil.which(n) is None]


def tools_required() -> bool:
    """Whether a missing tool fails a test (``CALC_REQUIRE_TOOLS=1``, as ``.ci/run`` sets it)."""
    return os.environ.get(REQUIRE_TOOLS) == "1"


def needs_tools(*names: str):
    """The mark of a test that needs these tools: skipped where one is missing, failed instead under
    ``CALC_REQUIRE_TOOLS=1`` (:func:`pytest_runtest_setup`)."""
    unknown = [n for n in names if n not in TOOLS]
    assert not unknown, f"no such tool in TOOLS: {unknown}"
    return pytest.mark.needs_tools(*names)


def has_tool(name: str) -> bool:
    """Whether a tool a part of a test uses is on PATH; under ``CALC_REQUIRE_TOOLS=1`` a missing one
    fails the test."""
    if missing_tools(name) and tools_required():
        pytest.fail(f"{name} is not on PATH ({TOOLS[name]} installs it), and {REQUIRE_TOOLS}=1 refuses the skip",
                    pytrace=False)
    return not missing_tools(name)


class ToolSkips:
    """The tests skipped for want of a tool in this session, by tool."""

    by_tool: dict[str, int] = {}


def pytest_runtest_setup(item):
    names = [n for mark in item.iter_markers("needs_tools") for n in mark.args]
    missing = missing_tools(*names)
    if not missing:
        return
    what = f"needs {', '.join(missing)}, not on PATH ({', '.join(sorted({TOOLS[n] for n in missing}))} installs it)"
    if tools_required():
        pytest.fail(f"{what}; {REQUIRE_TOOLS}=1 refuses the skip", pytrace=False)
    for n in missing:
        ToolSkips.by_tool[n] = ToolSkips.by_tool.get(n, 0) + 1
    pytest.skip(what)


def pytest_terminal_summary(terminalreporter):
    if ToolSkips.by_tool:
        counts = ", ".join(f"{n} {k} tests" for n, k in sorted(ToolSkips.by_tool.items()))
        terminalreporter.write_line(f"skipped for want of a tool: {counts}; .ci/run ({REQUIRE_TOOLS}=1) fails on them",
                                    yellow=True)


def pytest_configure(config):
    # Parsed catalogs (calc.data.parsed) kept for this session only, not in the user's cache.
    if "CALC_CACHE_DIR" not in os.environ:
        config.stash[_OWN_CACHE] = os.environ["CALC_CACHE_DIR"] = tempfile.mkdtemp(prefix="calc-cache-")
    config.addinivalue_line("markers", "needs_tools(*names): the test needs these tools on PATH (TOOLS)")
    from calc.core.errors import CalcError

    if is_worker(config) and config.option.basetemp:
        # A worker's temporary folders are one level below the run's (pytest-xdist's popen-gwN).
        worker = Path(config.option.basetemp).resolve()
        ErrorRecord.worker_folder = (f"{worker}{os.sep}", f"{worker.parent}{os.sep}")
    config.stash[_OWN_INIT] = CalcError.__dict__.get("__init__")
    inherited = CalcError.__init__

    def __init__(self, *args, **kwargs):
        if ErrorRecord.item is not None:
            frame = sys._getframe(1)  # the frame that called CalcError(...)
            path = Path(frame.f_code.co_filename).resolve()
            if path.is_relative_to(ROOT / "calc"):
                site = (path.relative_to(ROOT).as_posix(), frame.f_lineno)
                ErrorRecord.built.add(site)
                message = ErrorRecord.as_in_one_process(str(args[0]) if args else "")
                if len(message) > len(ErrorRecord.longest.get(site, "")):
                    ErrorRecord.longest[site] = message
        inherited(self, *args, **kwargs)

    CalcError.__init__ = __init__


# --- The tests on several processes (pytest-xdist, ``make test``) -----------------------------------
#
# Each worker records its own error sites and tool skips; the controller merges what the workers send
# at their end (``workeroutput``), prints the skips and makes the session checks of
# tests/test_error_sites.py over the whole session's record (:func:`pytest_runtestloop`). A worker
# passes those checks by unrun (:func:`pytest_runtest_protocol`), where they would see only its part.

#: The key of a worker's record in what it sends the controller.
WORKER_RECORD = "calc_session_record"


def is_worker(config) -> bool:
    """Whether this process runs tests for a controller (an xdist worker)."""
    return hasattr(config, "workerinput")


def is_controller(config) -> bool:
    """Whether this process hands the tests to workers (``-n`` above 0) and runs none itself."""
    return config.pluginmanager.has_plugin("dsession")


def worker_record() -> dict:
    """What a worker sends the controller at its end: the error sites built, the longest message of
    each, whether it ran the whole tests/ folder (and if not why), and its skips by tool."""
    longest = sorted([*site, message] for site, message in ErrorRecord.longest.items())
    return {"built": sorted(ErrorRecord.built), "longest": longest,
            "whole_folder": ErrorRecord.whole_folder, "reason": ErrorRecord.reason, "tool_skips": ToolSkips.by_tool}


def merge_record(record: dict) -> None:
    """Add a worker's :func:`worker_record` to this process's :class:`ErrorRecord` and :class:`ToolSkips`.
    Every worker collects the same tests, so the first one's selection stands for all."""
    if not ErrorRecord.merged:
        ErrorRecord.whole_folder, ErrorRecord.reason = record["whole_folder"], record["reason"]
    ErrorRecord.merged += 1
    ErrorRecord.built |= {(file, line) for file, line in record["built"]}
    for file, line, message in record["longest"]:
        if len(message) > len(ErrorRecord.longest.get((file, line), "")):
            ErrorRecord.longest[(file, line)] = message
    for tool, count in record["tool_skips"].items():
        ToolSkips.by_tool[tool] = ToolSkips.by_tool.get(tool, 0) + count


def is_session_check(item) -> bool:
    """Whether the item is a check of tests/test_error_sites.py over the whole session's record."""
    from .test_error_sites import SESSION_CHECKS

    return item.path == FINAL and item.originalname in SESSION_CHECKS


def worker_group(item) -> str | None:
    """The xdist group of an item: a notebook's cells run in order in one kernel (nbval), and the tests
    that share a costly fixture of tests/ (a PDF build, a module's evaluated cases) run on one worker,
    where it is built once; ``None`` for a test that may run on any worker."""
    if item.path.suffix == ".ipynb":
        return item.path.relative_to(ROOT).as_posix()
    info = getattr(item, "_fixtureinfo", None)
    shared = [d for defs in (info.name2fixturedefs.values() if info else ()) for d in defs
              if d.scope != "function" and d.baseid.startswith("tests")]
    session = sorted(d.argname for d in shared if d.scope == "session")
    if session:
        return session[0]
    return item.path.relative_to(ROOT).as_posix() if shared else None


def carry_groups(items) -> None:
    """Put each item's xdist group into the id the controller schedules by. pytest-xdist (3.8) appends
    ``@group`` to an item's ``_nodeid``, which pytest 9 no longer reads (it keeps the id as a ``NodeId``),
    so without this the controller would see no group and split a notebook's cells over the workers."""
    for item in items:
        grouped = getattr(item, "_nodeid", item.nodeid)
        if grouped != item.nodeid:
            from _pytest.nodeid import NodeId  # pytest 9's; where _nodeid is the id (pytest 8), none is needed

            item._id = NodeId.parse(grouped)


#: Files of tests that each take 10 to 60 s without a tool mark: the benchmark, pytest and pip run in a child.
LONG_FILES = {TESTS / name for name in ("test_bench.py", "test_tool_skips.py", "test_package.py", "test_course.py")}


def started_first(item) -> bool:
    """Whether the workers start the item before the others: a test that drives XeLaTeX or Chromium
    (``needs_tools``) or of :data:`LONG_FILES`. The longest first, the short ones fill in at the end,
    so that no worker ends long after the other (``make test`` runs with ``--no-loadscope-reorder``,
    which keeps this order)."""
    return item.path in LONG_FILES or item.get_closest_marker("needs_tools") is not None


def pytest_sessionfinish(session):
    if is_worker(session.config):
        session.config.workeroutput[WORKER_RECORD] = worker_record()


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_node_collection_finished(node, ids):
    # The controller's view of the selection: which checks of the whole session it is to make.
    from .test_error_sites import SESSION_CHECKS

    final = FINAL.relative_to(ROOT).as_posix()
    for nodeid in ids:
        path, _, name = nodeid.partition("::")
        if path == final and name in SESSION_CHECKS:
            ErrorRecord.session_checks.add(name)


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node, error):
    record = getattr(node, "workeroutput", {}).get(WORKER_RECORD)
    if record is not None:
        merge_record(record)


@pytest.hookimpl(wrapper=True)
def pytest_runtestloop(session):
    finished = yield
    if is_controller(session.config):
        from .test_error_sites import SESSION_CHECKS

        for name, check in SESSION_CHECKS.items():
            if name in ErrorRecord.session_checks:
                report_session_check(session, name, check)
    return finished


def report_session_check(session, name: str, check) -> None:
    """Make one of :data:`tests.test_error_sites.SESSION_CHECKS` over the merged record and report it as
    that test's outcome (passed, failed with the check's message, or skipped saying why)."""
    from _pytest.reports import TestReport

    from . import test_error_sites

    path = FINAL.relative_to(ROOT).as_posix()
    nodeid = f"{path}::{name}"
    location = (path, getattr(test_error_sites, name).__code__.co_firstlineno - 1, name)
    if not ErrorRecord.merged:
        outcome, longrepr = "failed", "no worker sent its record of the error sites built (see the workers' errors)"
    elif not ErrorRecord.whole_folder:
        outcome, longrepr = "skipped", (str(FINAL), location[1] + 1, f"Skipped: {whole_folder_needed()}")
    else:
        failure = check(ErrorRecord.built, ErrorRecord.longest)
        outcome, longrepr = ("failed", failure) if failure else ("passed", None)
    hook = session.config.hook
    hook.pytest_runtest_logstart(nodeid=nodeid, location=location)
    hook.pytest_runtest_logreport(report=TestReport(nodeid, location, {name: 1}, outcome, longrepr, "call"))
    hook.pytest_runtest_logfinish(nodeid=nodeid, location=location)


def whole_folder_needed() -> str:
    """Why a session check is not made: it needs the whole tests/ folder."""
    return f"needs the whole tests/ folder: {ErrorRecord.reason}"


def pytest_unconfigure(config):
    if _OWN_CACHE in config.stash:
        shutil.rmtree(config.stash[_OWN_CACHE], ignore_errors=True)
        del os.environ["CALC_CACHE_DIR"]
    from calc.core.errors import CalcError

    if _OWN_INIT not in config.stash:
        return
    if config.stash[_OWN_INIT] is None:
        del CalcError.__init__
    else:
        CalcError.__init__ = config.stash[_OWN_INIT]


def pytest_deselected(items):
    # -k, -m, --deselect and --last-failed all report here.
    ErrorRecord.deselected += len(items)


@pytest.hookimpl(wrapper=True)
def pytest_collection_modifyitems(session, config, items):
    """On a worker, first mark each item's :func:`worker_group` (before xdist reads the marks), then hand
    out the long tests first (:func:`started_first`); last, run the error-site check after every other
    test, whatever the collection order."""
    if is_worker(config):
        for item in items:
            group = worker_group(item)
            if group:
                item.add_marker(pytest.mark.xdist_group(group))
    yield
    if is_worker(config):
        carry_groups(items)
        items.sort(key=lambda item: not started_first(item))  # stable: the same order on every worker
    final = [item for item in items if item.path == FINAL]
    items[:] = [item for item in items if item.path != FINAL] + final


def pytest_collection_finish(session):
    patterns = session.config.getini("python_files")
    files = {p for p in TESTS.rglob("*.py") if any(fnmatch.fnmatch(p.name, pat) for pat in patterns)}
    missing = files - {item.path for item in session.items}
    by_node_id = [arg for arg in session.config.args if "::" in arg]
    if missing:
        ErrorRecord.reason = f"only part of tests/ ran ({len(missing)} of {len(files)} test files not selected)"
    elif by_node_id:
        ErrorRecord.reason = f"tests were selected by node id ({by_node_id[0]})"
    elif ErrorRecord.deselected:
        ErrorRecord.reason = f"{ErrorRecord.deselected} tests were deselected (-k, -m, --deselect or --last-failed)"
    ErrorRecord.whole_folder = not ErrorRecord.reason


@pytest.hookimpl(tryfirst=True)
def pytest_runtest_protocol(item, nextitem):
    if is_worker(item.config) and is_session_check(item):
        return True  # made by the controller over the whole session's record (pytest_runtestloop)
    ErrorRecord.item = item if item.path.is_relative_to(TESTS) else None
    return None


def pytest_runtest_logfinish(nodeid, location):
    ErrorRecord.item = None
