"""The served design review shared by the browser tests of both files (test_review_browser.py,
test_review_signoff_browser.py) that open the derived example's page and write nothing."""

import contextlib

import pytest

from ..conftest import DERIVED_EXAMPLE, is_worker


def tiny_pdf(path):
    """A one-page PDF (matplotlib's, in milliseconds) standing for a calc report: building a real
    one runs the report notebook and xelatex (11 s on this machine, and only where TeX is
    installed), which the report tests cover; here only its serving is tested.

    Parameters
    ----------
    path : pathlib.Path
        Where it is written.

    Returns
    -------
    None
    """
    from matplotlib.figure import Figure

    Figure(figsize=(1, 1)).savefig(path, format="pdf")


class SharedServer:
    """The review page of ``case`` served (``bench.review_browser.served``) for the tests that ask for the fixture
    ``fixture``, linking the reports of ``reports``: started when a test first asks for its address, and stopped
    once no test still to run here asks for it (:func:`pytest_runtest_teardown`; left running, its kernel waiting for
    a page would be culled and started again every minute while other tests run), started again should one ask.

    Parameters
    ----------
    case : pathlib.Path
        The case file the page opens.
    reports : pathlib.Path
        The reports' folder the page links.
    fixture : str
        The name of the fixture that gives it.
    """

    def __init__(self, case, reports, fixture):
        self.case, self.reports, self.fixture = case, reports, fixture
        self._running = None  # (the served context's exit stack, its Server) while it runs

    def _server(self):
        if self._running is None:
            from bench.review_browser import served

            stack = contextlib.ExitStack()
            self._running = (stack, stack.enter_context(served(self.case, reports=self.reports)))
        return self._running[1]

    @property
    def url(self) -> str:
        """The page's address, the server started if it is not running."""
        return self._server().url

    @property
    def started(self) -> float:
        """How long the server took to launch its first kernel [s]."""
        return self._server().started

    def stop(self) -> None:
        """Stop the server and its kernels, if running.

        Returns
        -------
        None
        """
        if self._running is not None:
            stack, self._running = self._running[0], None
            stack.close()


#: The shared servers of the run, by the name of their fixture, while their fixture is set up.
SHARED: dict[str, SharedServer] = {}


@contextlib.contextmanager
def shared_server(case, reports, fixture: str):
    """A :class:`SharedServer`, for a fixture named ``fixture`` to yield; stopped at the fixture's end.

    Parameters
    ----------
    case : pathlib.Path
        The case file the page opens.
    reports : pathlib.Path
        The reports' folder the page links.
    fixture : str
        The fixture's name.

    Returns
    -------
    contextlib.AbstractContextManager
        Giving the :class:`SharedServer`.
    """
    SHARED[fixture] = SharedServer(case, reports, fixture)
    try:
        yield SHARED[fixture]
    finally:
        SHARED.pop(fixture).stop()


@pytest.fixture(scope="session")
def derived_server(tmp_path_factory):
    """The derived example's page (cases/, as ``make review`` serves it) for the tests that open it and write
    nothing (each page its own kernel): a server and its first kernel started once for them, not once per test;
    each page takes the kernel waiting for it, and the server prepares the next. Session-wide, its tests run on one
    worker, one after the other (tests/conftest.py's ``worker_group``). Its reports' folder (``.reports``) holds a
    stand-in for the example's calc report (:func:`tiny_pdf`), which the page links."""
    reports = tmp_path_factory.mktemp("reports")
    tiny_pdf(reports / "indexing-table.pdf")
    with shared_server(DERIVED_EXAMPLE, reports, "derived_server") as server:
        yield server


#: In a run in one process, the position of the last test that asks for each shared fixture, and of each test (by
#: its id), found once: not by a scan of the tests for every test.
_LAST_ASKING: dict[str, int] = {}
_POSITION: dict[int, int] = {}


def _asked_for_later(item, nextitem, fixture: str) -> bool:
    """Whether a test still to run in this process asks for ``fixture``: in a run in one process, any test after
    ``item``; on a worker (pytest-xdist), the next one, all it knows (a group's tests are handed it in a row)."""
    if is_worker(item.config):
        return nextitem is not None and fixture in getattr(nextitem, "fixturenames", ())
    items = item.session.items
    if fixture not in _LAST_ASKING:
        asking = [k for k, later in enumerate(items) if fixture in getattr(later, "fixturenames", ())]
        _LAST_ASKING[fixture] = max(asking, default=-1)
    if not _POSITION:
        _POSITION.update((id(later), k) for k, later in enumerate(items))
    return _POSITION[id(item)] < _LAST_ASKING[fixture]


@pytest.hookimpl(trylast=True)
def pytest_runtest_teardown(item, nextitem):
    for name, server in SHARED.items():
        if not _asked_for_later(item, nextitem, name):
            server.stop()
