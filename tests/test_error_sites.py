"""Every place in calc/ that builds the package's error is triggered by a test under tests/.

The sites are read from the current source (tests/error_sites.py); the constructions are
recorded while the other tests run (tests/conftest.py). The check runs last and only when the
whole tests/ folder was selected: a single file or a ``-k`` run cannot trigger every message.
"""

import textwrap

import pytest

from .conftest import ErrorRecord
from .error_sites import error_sites, site_at

#: Sites that no input reaches, by file, function and message start (so that moved lines keep
#: them): they report a failure of the report machinery itself. A case that cannot be evaluated
#: gives a report saying FAIL and why, and every text set in TeX is escaped, so only a fault in
#: the package (an exception other than CalcError while the report is built) or in the TeX installation
#: gets here.
NOT_FROM_INPUT = {
    ("calc/report/publish.py", "render_pdf", "{display_path(report.path)}: xelatex could not typeset the report"),
    ("calc/report/publish.py", "render_summary", "{pdf}: xelatex could not typeset the summary"),
    # The export is verified before it is written: a failure is a defect of calc.exchange.build, which
    # tests/outputs/test_exchange.py holds to zero errors on every shipped case.
    ("calc/exchange/package.py", "verified_json", "the AAS export does not pass the meta-model's verification"),
    # A backstop of the results: inputs are held to calc.core.units.SI_SCALE, within which no formula overflows.
    ("calc/core/units.py", "number", "{key}: the calculation overflows"),
}


def _is(site, entry) -> bool:
    file, function, start = entry
    return site.file == file and site.function == function and site.message.startswith(start)


def test_every_error_site_is_triggered():
    if not ErrorRecord.whole_folder:
        pytest.skip(f"needs the whole tests/ folder: {ErrorRecord.reason}")
    sites = error_sites()
    unseen = [f"{file}:{line}" for file, line in sorted(ErrorRecord.built) if site_at(sites, file, line) is None]
    if unseen:
        pytest.fail(
            "CalcError built where the source scan sees no `CalcError(...)` call (build it by that name): "
            + ", ".join(unseen),
            pytrace=False,
        )
    stale = [entry for entry in NOT_FROM_INPUT if not any(_is(site, entry) for site in sites)]
    if stale:
        pytest.fail(f"NOT_FROM_INPUT names sites that no longer exist: {stale}", pytrace=False)
    triggered = {site_at(sites, file, line) for file, line in ErrorRecord.built}
    exempt = {site for site in sites for entry in NOT_FROM_INPUT if _is(site, entry)}
    untested = [site.describe() for site in sites if site not in triggered | exempt]
    if untested:
        pytest.fail(
            f"{len(untested)} of {len(sites)} error messages no test under tests/ triggers:\n" + "\n".join(untested),
            pytrace=False,
        )


def test_the_scan_finds_every_construction(tmp_path):
    # Raised at once, over several lines, returned to a caller, kept in a variable, by module attribute.
    package = tmp_path / "calc"
    package.mkdir()
    (package / "m.py").write_text(
        textwrap.dedent(
            '''
            from . import errors
            from .errors import CalcError

            def check(x):
                if x < 0:
                    raise CalcError(f"x: expected zero or more, found {x}")
                if x > 9:
                    raise CalcError(
                        "x: expected at most 9, "
                        f"found {x}"
                    )

            class Reader:
                def error(self, key):
                    return CalcError(f"{key}: unknown key")

            def other():
                exc = errors.CalcError("plain")
                raise exc
            '''
        )
    )
    sites = error_sites(package, root=tmp_path)
    assert [(s.line, s.end_line, s.function, s.message) for s in sites] == [
        (7, 7, "check", "x: expected zero or more, found {x}"),
        (9, 12, "check", "x: expected at most 9, found {x}"),
        (16, 16, "Reader.error", "{key}: unknown key"),
        (19, 19, "other", "plain"),
    ]
    # A line inside the multi-line message belongs to its call.
    assert site_at(sites, "calc/m.py", 11) == sites[1]
    assert site_at(sites, "calc/m.py", 13) is None
    assert sites[1].describe() == "calc/m.py:9 (check): x: expected at most 9, found {x}"
