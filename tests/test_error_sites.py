"""Every place in calc/ that builds the package's error is triggered by a test under tests/.

The sites are read from the current source (tests/error_sites.py); the constructions are
recorded while the other tests run (tests/conftest.py). The check runs last and only when the
whole tests/ folder was selected: a single file or a ``-k`` run cannot trigger every message.
"""

import textwrap

import pytest

from calc.core.errors import LISTED, MAX_LENGTH, CalcError, listing

from .conftest import DERIVED_EXAMPLE, ROOT, ErrorRecord, whole_folder_needed
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


def untriggered(built: set, longest: dict) -> str:
    """The failure of the error-site check over a session's record (the (file, line) of every
    ``CalcError`` built, and the longest message of each), or "" where every site is triggered."""
    sites = error_sites()
    unseen = [f"{file}:{line}" for file, line in sorted(built) if site_at(sites, file, line) is None]
    if unseen:
        return ("CalcError built where the source scan sees no `CalcError(...)` call (build it by that name): "
                + ", ".join(unseen))
    stale = [entry for entry in NOT_FROM_INPUT if not any(_is(site, entry) for site in sites)]
    if stale:
        return f"NOT_FROM_INPUT names sites that no longer exist: {stale}"
    triggered = {site_at(sites, file, line) for file, line in built}
    exempt = {site for site in sites for entry in NOT_FROM_INPUT if _is(site, entry)}
    untested = [site.describe() for site in sites if site not in triggered | exempt]
    if untested:
        return f"{len(untested)} of {len(sites)} error messages no test under tests/ triggers:\n" + "\n".join(untested)
    return ""


def too_long(built: set, longest: dict) -> str:
    """The failure of the length check: every message the session made the package build, at its
    longest, has at most MAX_LENGTH characters (the temporary folders of the tests' files included);
    "" where it holds."""
    sites = error_sites()
    exempt = {site for site in sites for entry in NOT_FROM_INPUT if _is(site, entry)}
    long = [f"{file}:{line} ({len(message)} characters): {message[:120]}…"
            for (file, line), message in sorted(longest.items())
            if len(message) > MAX_LENGTH and site_at(sites, file, line) not in exempt]
    if long:
        return f"{len(long)} error messages are longer than {MAX_LENGTH} characters:\n" + "\n".join(long)
    return ""


#: The checks over the whole session's record, by the test that makes them. Under pytest-xdist the
#: workers leave these tests out and the controller makes them over the merged record (tests/conftest.py).
SESSION_CHECKS = {"test_every_error_site_is_triggered": untriggered, "test_every_error_is_one_short_sentence": too_long}


def _session_check(name: str) -> None:
    if not ErrorRecord.whole_folder:
        pytest.skip(whole_folder_needed())
    failure = SESSION_CHECKS[name](ErrorRecord.built, ErrorRecord.longest)
    if failure:
        pytest.fail(failure, pytrace=False)


def test_every_error_site_is_triggered():
    _session_check("test_every_error_site_is_triggered")


def test_every_error_is_one_short_sentence():
    _session_check("test_every_error_is_one_short_sentence")


def test_a_list_in_an_error_names_ten_items_and_counts_the_rest(tmp_path_factory):
    from calc.sections.case import read_case
    from calc.sections import evaluate

    # The message holds the paths of the case and the catalog: both in a folder of a short name, so that the
    # message's length does not hang on the test's name or on pytest-xdist's folder of each worker.
    tmp_path = tmp_path_factory.mktemp("many")
    # A gearbox catalog of 500 families (one row each, the shipped NPT035-10's figures), and a case
    # that keeps to a family it lacks: the message names ten families and the count of the other 490.
    shipped = (ROOT / "catalogs" / "gearboxes.csv").read_text(encoding="utf-8").splitlines()
    header, row = shipped[0], next(line for line in shipped if line.startswith("NPT035-10,"))
    family = header.split(",").index("family")
    rows = []
    for k in range(500):
        cells = row.split(",")
        cells[0], cells[family] = f"G{k:03d}-10", f"F{k:03d}"
        rows.append(",".join(cells))
    (tmp_path / "many.csv").write_text("\n".join([header, *rows]) + "\n", encoding="utf-8")
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8").replace('"../data/', f'"{ROOT / "data"}/')
    text = text.replace('catalog = "gearboxes"', f'catalog = "{tmp_path / "many.csv"}"').replace(
        'family = "NPT"', 'family = "XYZ"')
    (tmp_path / "many.toml").write_text(text, encoding="utf-8")
    with pytest.raises(CalcError) as raised:
        evaluate(read_case(tmp_path / "many.toml"))
    message = str(raised.value)
    assert "has no gearbox of family 'XYZ'; its families are F000, F001, F002" in message
    assert message.endswith(f"F009 and {500 - LISTED} more") and len(message) <= MAX_LENGTH


def test_a_value_as_found_is_shown_clipped(write_case):
    from calc.sections.case import read_case

    # A ratio typed as 5,000 characters of text: the message shows its start and counts the rest.
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8").replace("\nratio = 10\n", f'\nratio = "{"1" * 5000}"\n')
    with pytest.raises(CalcError, match=r"gearbox\.ratio: .*'1111.*… \(4946 more characters\)") as raised:
        read_case(write_case(text, "long.toml"))
    assert len(str(raised.value)) <= MAX_LENGTH


def test_a_list_of_ten_or_fewer_is_named_whole():
    assert listing(["a", "b"]) == "a, b" and listing([]) == ""
    assert listing(range(LISTED)) == ", ".join(map(str, range(LISTED)))
    assert listing(range(LISTED + 1)) == ", ".join(map(str, range(LISTED))) + " and 1 more"
    assert listing(["x", "y", "z"], " -> ", limit=2) == "x -> y and 1 more"


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
