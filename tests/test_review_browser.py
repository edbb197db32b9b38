"""The served design review (``make review``) in a real browser, as a reviewer uses it.

Headless Chromium (Debian's package, installed by ``make browser``) opens the page at 1366 × 768,
changes the ratio and a torque through the page's own controls, and the verdict and the values
of the tables follow; values typed in a row end on the last one. The times are printed (page ready, each change until the results follow),
not asserted: a shared machine makes a timed assertion flaky. The screenshots are kept in
``build/screenshots/``.
"""

import pytest

from bench.review_browser import CHROMIUM, review_in_browser, served

from .conftest import EXAMPLE, ROOT

SHOTS = ROOT / "build" / "screenshots"
#: (label as the page shows it, value), on the typed example whose numbers test_review.py works by
#: hand: the ratio to 8 (TP010-8 chosen, and the accuracy chain follows it: positioning accuracy
#: 0.365 arcmin) and back to 10; the motor's peak torque to 30 N·m (T_2max = 30 · 10 · 1.3 · 0.97 =
#: 378.3 N·m, above NPT035-10's T_2B of 220 N·m: NPS045-10) and back to 12 N·m; the applied torque
#: to 2 N·m, below 3 % of T_N = 3.3 N·m, so the backlash counts in full: 9.049 arcmin against the
#: required 5 (FAIL, E13) and back; then a segment's torque.
CHANGES = [
    ("gearbox ratio i", "8"),
    ("gearbox ratio i", "10"),
    ("motor peak torque T_1B [N·m]", "30"),
    ("motor peak torque T_1B [N·m]", "12"),
    ("applied torque T [N·m]", "2"),
    ("applied torque T [N·m]", "8"),
    ("1 accel: torque T_2 [N·m]", "70"),
    ("1 accel: torque T_2 [N·m]", "60"),
]

pytestmark = pytest.mark.skipif(not CHROMIUM.exists(), reason=f"no Chromium at {CHROMIUM} (make browser installs it)")


def test_a_reviewer_changes_the_ratio_and_a_torque_and_the_results_follow():
    with served(EXAMPLE) as server:
        visit = review_in_browser(server.url, SHOTS, CHANGES, burst=(CHANGES[2][0], ["13", "14", "15", "16", "17"]))
    print(f"\nserver ready: {server.started:.2f} s; page ready: {visit.ready:.2f} s")
    for what, t in visit.changes:
        print(f"  {what}: {t:.3f} s")
    print(f"per change: median {visit.median:.3f} s, maximum {max(visit.times):.3f} s (budget 0.3 s median)")
    typed, drawn, after = visit.burst
    print(f"{typed} values typed in a row: {drawn} updates drawn")
    print("screenshots: " + ", ".join(str(p.relative_to(ROOT)) for p in visit.shots))
    seen = dict(visit.seen)
    first = seen["first"]
    assert first.startswith("PASS") and "NPT035-10" in first and "Governing checks" in first
    at_8 = seen["gearbox ratio i = 8"]
    assert at_8.startswith("PASS") and "Gearbox TP010-8" in at_8 and "0.365 arcmin" in at_8 and "0.365 arcmin" not in first
    assert seen["gearbox ratio i = 10"] == first
    strong = seen["motor peak torque T_1B [N·m] = 30"]
    assert strong.startswith("PASS") and "Gearbox NPS045-10" in strong and "378.3 N·m" in strong and "151.3 N·m" not in strong
    assert seen["motor peak torque T_1B [N·m] = 12"] == first
    loose = seen["applied torque T [N·m] = 2"]
    assert loose.startswith("FAIL") and "9.049 arcmin > required 5 arcmin" in loose
    assert seen["applied torque T [N·m] = 8"] == first
    # A larger accelerating torque raises the cubic mean T_2m (the S1 value), 35.41 N·m in the example.
    assert "35.41 N·m" in first and "35.41 N·m" not in seen["1 accel: torque T_2 [N·m] = 70"]
    assert all(p.stat().st_size > 10_000 for p in visit.shots)
    # Values typed in a row: the page ends on the last (17 N·m · 10 · 1.3 · 0.97 = 214.4 N·m), drawn
    # at most once each (changes that arrive while one is drawn are drawn together).
    assert 1 <= drawn <= typed and "214.4 N·m" in after
