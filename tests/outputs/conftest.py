"""The served design review shared by the browser tests of both files (test_review_browser.py,
test_review_signoff_browser.py) that open the derived example's page and write nothing."""

import pytest

from ..conftest import DERIVED_EXAMPLE


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


@pytest.fixture(scope="session")
def derived_server(tmp_path_factory):
    """The derived example's page (cases/, as ``make review`` serves it) for the tests that open it and write
    nothing (each page its own kernel): a server and its first kernel started once, not once per test; each page
    takes the kernel waiting for it, and the server prepares the next. Session-wide, its tests run on one worker
    (tests/conftest.py's ``worker_group``). Its reports' folder (``server.reports``) holds a stand-in for the
    example's calc report (:func:`tiny_pdf`), which the page links."""
    from bench.review_browser import served

    reports = tmp_path_factory.mktemp("reports")
    tiny_pdf(reports / "indexing-table.pdf")
    with served(DERIVED_EXAMPLE, reports=reports) as server:
        yield server
