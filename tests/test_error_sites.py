"""Every place in calc/ that builds the package's error is triggered by a test under tests/.

The sites are read from the current source (tests/error_sites.py); the constructions are
recorded while the other tests run (tests/conftest.py). The check runs last and only when the
whole tests/ folder was selected: a single file or a ``-k`` run cannot trigger every message.
"""

import pytest

from .conftest import ErrorRecord
from .error_sites import error_sites, site_at


def test_every_error_site_is_triggered():
    if not ErrorRecord.whole_folder:
        pytest.skip(f"needs the whole tests/ folder: {ErrorRecord.reason}")
    sites = error_sites()
    unseen = [
        f"{file}:{line}" for file, line in sorted(ErrorRecord.built) if site_at(sites, file, line) is None
    ]
    if unseen:
        pytest.fail(
            "CalcError built where the source scan sees no `CalcError(...)` call (build it by that name): "
            + ", ".join(unseen),
            pytrace=False,
        )
    triggered = {site_at(sites, file, line) for file, line in ErrorRecord.built}
    untested = [site.describe() for site in sites if site not in triggered]
    if untested:
        pytest.fail(
            f"{len(untested)} of {len(sites)} error messages no test under tests/ triggers:\n" + "\n".join(untested),
            pytrace=False,
        )
