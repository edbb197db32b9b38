"""The served design review (``make review``) in a real browser: headless Chromium from the system's
packages, driven by Playwright. Used by the browser test (tests/outputs/test_review_browser.py) and by the
benchmark's ``review_*`` lines.

:func:`served` starts the server on a free port of this machine (``127.0.0.1``), waits for its
first kernel, and stops it after;
:func:`review_in_browser` opens the page as a reviewer would (1366 × 768), waits for the panel,
changes inputs through the number fields and the ratio choice, each found by its key path in the
case file (the label's ``data-key``), and measures each change from the input to the new results
on the page (the results carry a generation count). It keeps a screenshot of the page as first
shown and after the changes. :func:`new_values` gives changes to values not seen before for any
case, from the inputs the page offers for it. The tests' pages are new contexts of one Chromium per
process (:func:`browser_page`, ``fresh=False``); the benchmark's visits each launch a browser of their own.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import urljoin

ROOT = Path(__file__).resolve().parent.parent
CHROMIUM = Path("/usr/bin/chromium")
#: Chromium on a closed network: no background traffic, a fresh profile each run (given apart).
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run"]
SCREEN = {"width": 1366, "height": 768}
RESULTS = ".design-review .dr[data-generation]"
FIGURES = ".design-review .dr-figures svg"  # the load cycle's and the stiffness chain's, hidden where no results


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


#: This process's Playwright driver and its shared Chromium, started at the first page asked for and
#: stopped at exit: a test opens a new context (its own cookies, storage and cache) in one browser, not a
#: browser of its own (a launch costs about a second of CPU).
_SHARED: dict = {}


def playwright_driver():
    """This process's Playwright (sync API), started once: a second ``sync_playwright()`` in a process where
    one runs fails, so every browser of the tests comes from this one.

    Returns
    -------
    playwright.sync_api.Playwright
        The running driver, stopped at exit.
    """
    if "driver" not in _SHARED:
        from playwright.sync_api import sync_playwright

        _SHARED["driver"] = sync_playwright().start()
        atexit.register(_stop_shared)
    return _SHARED["driver"]


def _stop_shared() -> None:
    with contextlib.suppress(Exception):
        if "browser" in _SHARED:
            _SHARED.pop("browser").close()
        _SHARED.pop("driver").stop()


@contextlib.contextmanager
def _context(viewport: dict, fresh: bool):
    """A browser context ``viewport`` wide and high: with ``fresh``, in a Chromium launched for it with a
    fresh profile (what a first visit measures), else a new context of this process's shared Chromium."""
    if fresh:
        with tempfile.TemporaryDirectory() as profile:
            browser = playwright_driver().chromium.launch_persistent_context(
                profile, executable_path=str(CHROMIUM), headless=True, args=CHROMIUM_ARGS, viewport=viewport)
            try:
                yield browser
            finally:
                browser.close()
        return
    if "browser" not in _SHARED:
        _SHARED["browser"] = playwright_driver().chromium.launch(executable_path=str(CHROMIUM), headless=True,
                                                          args=CHROMIUM_ARGS)
    context = _SHARED["browser"].new_context(viewport=viewport)
    try:
        yield context
    finally:
        context.close()


@dataclass
class Server:
    url: str
    started: float  # s from the command to its first kernel launched (the page's notebook not yet run in it)
    process: subprocess.Popen | None = None

    def stop(self) -> None:
        """Stop the server (and its kernels) now, as a dropped connection would leave the page."""
        if self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGTERM)
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                os.killpg(self.process.pid, signal.SIGKILL)
                self.process.wait()


@contextlib.contextmanager
def served(case: Path | None = None, timeout: float = 90.0, reports: Path | None = None,
           idle_seconds: float | None = None):
    """The review page served on a free port of 127.0.0.1, opening ``case`` (by default what
    ``make review`` opens) and linking the reports of the folder ``reports`` (by default
    ``reports/``), once it has launched its first kernel (Voilà's "pool ... is filled", logged when the
    kernel is started and the page's notebook set running in it, not when that has run): a page asked
    for then waits for the notebook's run, as a reviewer's who opens it at once after ``make review``.
    ``idle_seconds``: a closed page's kernel is culled after this long (by default the command's own,
    :data:`calc.review.serve.IDLE_MINUTES`)."""
    port = _free_port()
    chosen = [] if case is None else ["--cases", str(case.parent), "--case", case.name]
    chosen += [] if reports is None else ["--reports", str(reports)]
    chosen += [] if idle_seconds is None else ["--idle-minutes", str(idle_seconds / 60)]
    env = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    start = time.perf_counter()
    server = subprocess.Popen([sys.executable, "-m", "calc.review.serve", "--port", str(port), *chosen], cwd=ROOT,
                              env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                              start_new_session=True)
    log: list[str] = []
    filled = threading.Event()

    def read_log():
        for text in server.stderr:
            log.append(text)
            if "is filled" in text:
                filled.set()

    threading.Thread(target=read_log, daemon=True).start()
    try:
        if not filled.wait(timeout):
            raise RuntimeError("the review server prepared no kernel: " + "".join(log)[-3000:])
        up = Server(f"http://127.0.0.1:{port}/", time.perf_counter() - start, server)
        yield up
    finally:
        Server("", 0.0, server).stop()


@dataclass
class Visit:
    """What a visit measured and saw."""

    ready: float  # s from asking for the page to the panel's results shown
    changes: list = field(default_factory=list)  # (what, s from the input to the new results)
    seen: list = field(default_factory=list)  # (what, the results' text after it)
    shots: list = field(default_factory=list)  # screenshot files
    burst: tuple = ()  # (values typed in a row, updates drawn for them, the results' text after)
    choices: list = field(default_factory=list)  # the case chooser's options as the page shows them
    report: tuple = ()  # the calc report's link as first shown: (address, HTTP status, content type, first bytes)

    @property
    def times(self) -> list[float]:
        return [t for _, t in self.changes]

    @property
    def median(self) -> float:
        return statistics.median(self.times)


def new_values(case: Path, count: int) -> list[tuple[str, str]]:
    """``count`` changes ``(key path, value as typed)`` to the inputs the page offers for ``case``
    (:func:`calc.review.input_specs`), in turn, each to a value not seen before: a few steps up
    from the file's value, inside the input's range (the ratio: the next of the catalog's). Each
    leaves a design that can be evaluated: the page offers the gearbox parts at the file's ratio,
    so a part is forced first, while the ratio is the file's, and given back to the selection
    just before the ratio changes (a forced part of another ratio is an error, not a result)."""
    from calc.sections.case import read_case
    from calc.review import input_specs
    from calc.review.inputs import SELECTION, catalog_ratios, forced_spec

    c = read_case(case)
    specs = input_specs(c, catalog_ratios(c) if c.ratio is not None else [])
    if c.ratio is not None:  # the forced part first, the ratio last
        specs = [forced_spec(c, "gearbox.part"), *(s for s in specs if s.key != "gearbox.ratio"), specs[0]]
    out, forced, ratio_changed, k = [], None, False, 0
    while len(out) < count:
        spec, turn = specs[k % len(specs)], k // len(specs) + 1
        k += 1
        if spec.key == "gearbox.part":
            if ratio_changed:
                continue  # the page offers none of the parts at the new ratio
            others = [o for o in spec.options if o not in (spec.value, SELECTION, forced)]
            forced = others[(turn - 1) % len(others)]
            out.append((spec.key, forced))
            continue
        if spec.options:
            if forced is not None:  # the forced part given back before the ratio changes
                out.append(("gearbox.part", SELECTION))
                forced = None
            others = [o for o in spec.options if o != spec.value]
            if isinstance(spec.value, float):
                others.sort(key=lambda o: abs(o - spec.value))  # the nearest ratios first
            choice = others[(turn - 1) % len(others)]
            ratio_changed = True
            out.append((spec.key, choice if isinstance(choice, str) else f"{choice:g}"))
            continue
        # 2 % further per turn (on the input's step), so each value is new and the design stays possible.
        d = max(spec.step, round(0.02 * turn * abs(spec.value) / spec.step) * spec.step) * turn
        # down from the top; an input that follows another (a decel time its accel time, stepped up
        # just before) steps down, or it would be typed at the value it already shows and change nothing
        up = spec.follows is None and spec.value + d <= spec.high
        v = round(spec.value + d if up else max(spec.value - d, spec.low), 12)
        out.append((spec.key, f"{v:g}"))
    return out[:count]


def row(page, key: str):
    """The control row of the input at the key path ``key``."""
    return page.locator(".dr-row", has=page.locator(f'[data-key="{key}"]')).last


def typed(page, key: str, value: str):
    """Type ``value`` into the field of ``key``, not yet committed; returns the commit: pressing Enter
    (for a choice, choosing the option ``value``), which is where a reviewer's wait for the results
    starts."""
    r = row(page, key)
    if r.locator("select").count():
        return lambda: r.locator("select").select_option(label=value)
    field = r.locator("input[type=text]")
    field.fill(value)
    return lambda: field.press("Enter")


def change(page, key: str, value: str) -> None:
    """Type ``value`` into the field of ``key`` and press Enter (or choose the option ``value``)."""
    typed(page, key, value)()


#: The page's own clock of a change, installed once in a page (:func:`timed_change`): the moment of the commit
#: (the Enter key in a field, or the choice made) and of the first frame drawn once results of a later
#: generation than ``g0`` are in the page, both ``performance.now()`` [ms].
PAGE_CLOCK = """() => {
  if (window.calcClock) return;
  window.calcClock = {g0: Infinity};
  const commit = e => { if ((e.type === 'change' || e.key === 'Enter') && calcClock.commit === undefined)
    calcClock.commit = performance.now(); };
  document.addEventListener('keydown', commit, true);
  document.addEventListener('change', commit, true);
  new MutationObserver(() => {
    const g = Number(document.querySelector('%s')?.dataset.generation);
    if (g > calcClock.g0 && calcClock.results === undefined) {
      calcClock.results = performance.now();
      requestAnimationFrame(() => { calcClock.drawn = performance.now(); });
    }
  }).observe(document.querySelector('.design-review'), {subtree: true, childList: true, attributes: true});
}""" % RESULTS


def timed_change(page, key: str, value: str, timeout: float = 30_000) -> float:
    """Make the change (:func:`typed`, then its commit) and give the seconds from the commit to the first frame
    drawn with its results, on the page's own clock (:data:`PAGE_CLOCK`): what a reviewer waits, without the
    driver's messages to the page and back (some 20 ms)."""
    page.evaluate(PAGE_CLOCK)
    commit = typed(page, key, value)
    page.evaluate("g => { calcClock.g0 = g; delete calcClock.commit; delete calcClock.results; "
                  "delete calcClock.drawn; }", _generation(page))
    commit()
    page.wait_for_function("() => calcClock.drawn !== undefined && calcClock.commit !== undefined", polling="raf",
                           timeout=timeout)
    return page.evaluate("() => calcClock.drawn - calcClock.commit") / 1000


def wait_for_page(page, timeout: float = 60_000) -> None:
    """Until the panel's results are on the page, seen at the frame they are drawn in (Playwright's
    ``wait_for_selector`` looks at intervals that grow to half a second)."""
    page.wait_for_function(f"() => document.querySelector('{RESULTS}') !== null", polling="raf", timeout=timeout)


def wait_for_results(page, after: int, timeout: float = 30_000) -> None:
    """Until the results after generation ``after`` are on the page."""
    page.wait_for_function(f"() => Number(document.querySelector('{RESULTS}')?.dataset.generation) > {after}",
                           polling="raf", timeout=timeout)


@contextlib.contextmanager
def browser_page(viewport: dict = SCREEN):
    """A page ``viewport`` wide and high in a new context (nothing cached, no cookies) of this process's
    shared headless Chromium."""
    with _context(viewport, fresh=False) as browser:
        yield browser.new_page()


def kernel_id(page) -> str | None:
    """The id of the page's kernel (its connection file is ``kernel-<id>.json``), None outside a served page."""
    return page.evaluate("() => { const a = window.jupyterapp, m = a && (a.widgetManager || a._widgetManager);"
                         " const k = m && (m.kernel || m._kernel); return k ? k.id : null; }")


def kernel_memory(page) -> float | None:
    """The resident memory of the page's kernel process [MB] (Linux), None where not found."""
    kernel = kernel_id(page)
    for proc in Path("/proc").iterdir():
        try:
            if proc.name.isdigit() and f"kernel-{kernel}.json".encode() in (proc / "cmdline").read_bytes():
                rss = next(t for t in (proc / "status").read_text().splitlines() if t.startswith("VmRSS:"))
                return int(rss.split()[1]) / 1024
        except (OSError, StopIteration):
            continue
    return None


@dataclass
class FirstLoad:
    """What opening the page once measured, in a browser with nothing cached."""

    ready: float  # s from asking for the page to its results shown
    transfer: int  # bytes the browser received for it (bodies as sent, headers included)
    requests: int  # how many requests it made
    kernel_mb: float | None  # the page's kernel's resident memory [MB]


def first_load(url: str, fresh: bool = True) -> FirstLoad:
    """Open the page once in a fresh browser (nothing cached) and measure it (:class:`FirstLoad`); without
    ``fresh``, in a new context of the shared browser (nothing cached either, the browser already running)."""
    with _context(SCREEN, fresh) as browser:
        page = browser.new_page()
        done: list = []
        page.on("requestfinished", lambda request: done.append(request))
        start = time.perf_counter()
        page.goto(url)
        wait_for_page(page)
        ready = time.perf_counter() - start
        page.wait_for_load_state("networkidle")
        sizes = [r.sizes() for r in done]
        transfer = sum(s["responseBodySize"] + s["responseHeadersSize"] for s in sizes)
        return FirstLoad(ready, transfer, len(sizes), kernel_memory(page))


def _generation(page) -> int:
    return int(page.get_attribute(RESULTS, "data-generation"))


#: What the page shows where a change gives no results: the case cannot be evaluated, or a value refused.
NO_RESULTS = ("cannot be evaluated", "Not applied")


def _check_results(page, what: str, text: str) -> None:
    """Stop with a sentence where the change ``what`` ended in an error on the page (text ``text``) or
    drew no figure: such a change is not "text and figures follow" and must not be timed as one."""
    said = next((t for t in NO_RESULTS if t in text), None)
    if said is not None or not page.locator(f"{FIGURES}:visible").count():
        reason = next((x for x in text.splitlines() if said and said in x), "no figure")[:200]
        raise RuntimeError(f"review: the change {what} ended in no results on the page ({reason}); "
                           "choose a valid value")


def review_in_browser(url: str, shots: Path, changes: list[tuple[str, str]], repeat: int = 1, settle: float = 3.0,
                      burst: tuple[str, list[str]] | None = None, results_each: bool = False,
                      fresh: bool = True) -> Visit:
    """Open the page, wait ``settle`` seconds, then make each change ``(key path, value)`` in turn (a
    number field's value, or the option of a choice), ``repeat`` times over; each is timed from its
    commit to the frame that draws its results (:func:`timed_change`). Then ``burst``, ``(key path,
    values)``: the values typed into that field one after the other without waiting, as a reviewer
    trying values does; counted are the updates the page gets for them until it is still. With
    ``results_each`` (the benchmark's timed changes), a change that ends in an error or without figures
    stops the visit (:func:`_check_results`). With ``fresh`` (the benchmark's) in a browser launched for
    the visit, else in the shared one (:func:`_context`)."""
    shots.mkdir(parents=True, exist_ok=True)
    with _context(SCREEN, fresh) as browser:
        page = browser.new_page()
        start = time.perf_counter()
        page.goto(url)
        wait_for_page(page)
        visit = Visit(ready=time.perf_counter() - start)
        # A reviewer reads the page before the first change; meanwhile the server prepares the
        # next page's kernel, which is not what a change should be timed against.
        page.wait_for_timeout(settle * 1000)
        visit.shots.append(shots / "review-first.png")
        page.screenshot(path=str(visit.shots[-1]))
        visit.seen.append(("first", page.inner_text(RESULTS)))
        visit.choices = page.locator(".design-review select").first.locator("option").all_inner_texts()
        link = page.locator(f"{RESULTS} a", has_text="calc report")
        if link.count():  # asked for as the browser would, from the page's address
            href = link.first.get_attribute("href")
            answer = page.request.get(urljoin(page.url, href))
            visit.report = (href, answer.status, answer.headers.get("content-type"), answer.body()[:5])
        for _ in range(repeat):
            for key, value in changes:
                visit.changes.append((f"{key} = {value}", timed_change(page, key, value)))
                visit.seen.append((f"{key} = {value}", page.inner_text(RESULTS)))
                if results_each:
                    _check_results(page, f"{key} = {value}", visit.seen[-1][1])
                failed = visit.seen[-1][1].startswith("FAIL")
                if failed and not any(p.name == "review-fail.png" for p in visit.shots):
                    visit.shots.append(shots / "review-fail.png")
                    page.screenshot(path=str(visit.shots[-1]))
        if burst:
            key, values = burst
            first = _generation(page)
            # Typed within a few milliseconds: each value committed as Enter or leaving the field does.
            row(page, key).locator("input[type=text]").evaluate(
                "(field, values) => { for (const v of values) { field.value = v;"
                " field.dispatchEvent(new Event('change', {bubbles: true})); } }", values)
            last = None
            while last != _generation(page):  # still for a second
                last = _generation(page)
                page.wait_for_timeout(1000)
            visit.burst = (len(values), last - first, page.inner_text(RESULTS))
        page.wait_for_timeout(300)
        visit.shots.append(shots / "review-changed.png")
        page.screenshot(path=str(visit.shots[-1]))
        visit.shots.append(shots / "review-whole-panel.png")  # on a screen tall enough for all of it
        page.set_viewport_size({"width": SCREEN["width"], "height": 2400})
        page.wait_for_timeout(300)
        page.locator(".design-review").screenshot(path=str(visit.shots[-1]))
        return visit


@dataclass
class Crowd:
    """What several reviewers at once measured and saw."""

    times: list = field(default_factory=list)  # s from each page's input to its new results, every round
    texts: list = field(default_factory=list)  # each page's results after the last round
    memory: float = 0.0  # MB resident per page: the server's kernels over the pages

    @property
    def median(self) -> float:
        return statistics.median(self.times)


def kernels_memory(server: Server) -> float:
    """The resident memory of the server's kernels together [MB]."""
    import psutil

    children = psutil.Process(server.process.pid).children(recursive=True)
    return sum(p.memory_info().rss for p in children if "ipykernel" in " ".join(p.cmdline())) / 2**20


def reviewers_at_once(server: Server, key: str, rounds: list[list[str]], settle: float = 3.0,
                      fresh: bool = True) -> Crowd:
    """One page per value of a round, opened together; in each round every page gets its own value of
    ``key`` at the same time (typed into each page in turn, a few milliseconds apart), and each page
    is timed from its own input until its results follow (all pages watched together). ``fresh``: as in
    :func:`review_in_browser`."""

    crowd = Crowd()
    with _context(SCREEN, fresh) as browser:
        pages = [browser.new_page() for _ in rounds[0]]
        for page in pages:
            page.goto(server.url)
        for page in pages:
            wait_for_page(page, timeout=180_000)
        pages[0].wait_for_timeout(settle * 1000)
        for values in rounds:
            before = [_generation(page) for page in pages]
            started = []
            for page, value in zip(pages, values):
                started.append(time.perf_counter())
                change(page, key, value)
            waiting = set(range(len(pages)))
            deadline = time.perf_counter() + 120
            while waiting and time.perf_counter() < deadline:
                for k in sorted(waiting):
                    if _generation(pages[k]) > before[k]:
                        crowd.times.append(time.perf_counter() - started[k])
                        waiting.discard(k)
            if waiting:
                raise RuntimeError(f"no results within 120 s on pages {sorted(waiting)}")
        for page in pages:
            page.wait_for_function("() => document.querySelector('.design-review .dr-state')?.dataset.state"
                                   " === 'current'", timeout=60_000)
        crowd.texts = [page.inner_text(RESULTS) for page in pages]
        crowd.memory = kernels_memory(server) / len(pages)
        return crowd
