"""The served design review (``make review``) in a real browser, as a reviewer uses it.

Headless Chromium (Debian's package, installed by ``make browser``) opens the page at 1366 × 768,
changes the ratio and a torque through the page's own controls, and the verdict and the values
of the tables follow; values typed in a row end on the last one. The times are printed (page ready, each change until the results follow),
not asserted: a shared machine makes a timed assertion flaky. The screenshots are kept in
``build/screenshots/``.

On the derived example, a move's time and the mechanism's inertia are changed, an impossible ramp
shows its input error, and the calc report linked beside the verdict answers as a PDF.
"""

import pytest

from bench.review_browser import CHROMIUM, review_in_browser, served
from calc.review import serve

from .conftest import DERIVED_EXAMPLE, EXAMPLE, ROOT

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


def print_times(server, visit):
    """The measured figures of a visit (printed, not asserted: a shared machine's times vary)."""
    print(f"\nserver ready: {server.started:.2f} s; page ready: {visit.ready:.2f} s")
    for what, t in visit.changes:
        print(f"  {what}: {t:.3f} s")
    print(f"per change: median {visit.median:.3f} s, maximum {max(visit.times):.3f} s (budget 0.3 s median)")


def test_a_reviewer_changes_the_ratio_and_a_torque_and_the_results_follow():
    with served(EXAMPLE) as server:
        visit = review_in_browser(server.url, SHOTS, CHANGES, burst=(CHANGES[2][0], ["13", "14", "15", "16", "17"]))
    print_times(server, visit)
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


#: On the derived example (cases/indexing-table.toml): the index in 1.0 s instead of 0.5 s lowers
#: the peak speed (42.86 to 17.65 rpm) and the starts per hour (Z_h 2400 to 1800 /h: f_s 1.6 to 1.3,
#: so T_2max = 12 · 10 · 1.3 · 0.97 = 151.3 N·m instead of 186.2 N·m, test_review.py); a ramp of
#: 0.3 s in 0.5 s is impossible (an input error), 0.15 s again recovers.
MOVE_CHANGES = [
    ("1 move: time t [s]", "1"),
    ("1 move: time t [s]", "0.5"),
    ("mechanism: load inertia J_L [kg·cm²]", "3000"),
    ("mechanism: load inertia J_L [kg·cm²]", "1500"),
    ("1 move: accel time t_a [s]", "0.3"),
    ("1 move: accel time t_a [s]", "0.15"),
]


def tiny_pdf(path):
    """A one-page PDF (matplotlib's, in milliseconds) standing for a calc report: building a real
    one runs the report notebook and xelatex (11 s on this machine, and only where TeX is installed), which the report tests
    cover; here only its serving is tested."""
    from matplotlib.figure import Figure

    Figure(figsize=(1, 1)).savefig(path, format="pdf")


def test_a_reviewer_changes_a_move_and_opens_the_calc_report(tmp_path):
    tiny_pdf(tmp_path / "indexing-table.pdf")
    with served(DERIVED_EXAMPLE, reports=tmp_path) as server:
        visit = review_in_browser(server.url, SHOTS / "derived", MOVE_CHANGES)
    print_times(server, visit)
    print(f"calc report: {visit.report}")
    seen = dict(visit.seen)
    first = seen["first"]
    assert first.startswith("PASS") and "186.2 N·m" in first and "42.86 rpm" in first
    slower = seen["1 move: time t [s] = 1"]
    assert slower.startswith("PASS") and "151.3 N·m" in slower and "17.65 rpm" in slower and "186.2 N·m" not in slower
    assert seen["1 move: time t [s] = 0.5"] == first
    assert "3000 kg·cm²" in seen["mechanism: load inertia J_L [kg·cm²] = 3000"] and seen["mechanism: load inertia J_L [kg·cm²] = 1500"] == first
    impossible = seen["1 move: accel time t_a [s] = 0.3"]
    assert impossible.startswith("input error") and "found 0.3 s + 0.3 s > 0.5 s" in impossible and "Governing checks" not in impossible
    assert seen["1 move: accel time t_a [s] = 0.15"] == first
    # The chooser gives each case's verdict; the built report is linked, and served as a PDF.
    assert [c.replace("\xa0", " ") for c in visit.choices] == ["indexing-table.toml · PASS", "linear-axis-inch.toml · PASS"]
    href, status, content_type, head = visit.report
    assert href == serve.report_address(tmp_path / "indexing-table.pdf", tmp_path)
    assert status == 200 and content_type == "application/pdf" and head == b"%PDF-"
