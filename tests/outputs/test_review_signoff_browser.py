"""What a reviewer who signs a design off relies on, in a real browser (headless Chromium, as
test_review_browser.py): each test reproduces one way the page could show a reviewer something other
than what was computed, and holds that it no longer does.

Numbers are worked by hand from the example (cases/indexing-table.toml): one index of 90 deg in 0.5 s
(ramps 0.15 s), a dwell of 1 s; the catalog's motor SGMUH-10DA (T_1B 6.5 N·m) through NPT035-10
(i = 10, η = 0.97), Z_h = 3600 / 1.5 = 2400 /h, f_s = 1.6 (E4), T_2max = 6.5 · 10 · 1.6 · 0.97 = 100.9 N·m.
"""

import pytest

from bench.review_browser import CHROMIUM, browser_page, change, row, served, wait_for_results

from ..conftest import DERIVED_EXAMPLE, ROOT

RESULTS = ".design-review .dr[data-generation]"
SHOTS = ROOT / "build" / "screenshots" / "sign-off"

pytestmark = pytest.mark.skipif(not CHROMIUM.exists(), reason=f"no Chromium at {CHROMIUM} (make browser installs it)")


def _copy(tmp_path, name="axis.toml"):
    """The example in a folder of its own (a saved file lands there)."""
    path = tmp_path / name
    path.write_text(DERIVED_EXAMPLE.read_text().replace('"../data/', f'"{ROOT}/data/'))
    return path


def _current(page) -> None:
    page.wait_for_function("() => document.querySelector('.design-review .dr-state').dataset.state === 'current'",
                           timeout=60_000)


def _changed(page, key: str, value: str) -> str:
    """Type a value, wait for the results drawn after it, and give them."""
    g = int(page.get_attribute(RESULTS, "data-generation"))
    change(page, key, value)
    wait_for_results(page, g)
    _current(page)
    return page.inner_text(RESULTS)


def _field(page, key: str) -> str:
    return row(page, key).locator("input[type=text]").input_value()


def test_a_field_the_file_leaves_out_shows_the_value_computed(tmp_path):
    # Finding 1: the example leaves the decel time out, so it follows the accel time. Accel 0.3 s in
    # a move of 0.7 s: the field shows 0.3 s, and the peak speed is 0.25 rev / (0.7 − 0.3) s = 37.5 rpm
    # (the 0.15 s the field used to show would give 31.58 rpm).
    SHOTS.mkdir(parents=True, exist_ok=True)
    with served(_copy(tmp_path)) as server, browser_page() as page:
        page.goto(server.url)
        page.wait_for_selector(RESULTS, timeout=60_000)
        follows = row(page, "move[1].decel_time").locator(".dr-follows")
        assert follows.inner_text() == "left out of the file: follows the accel time ta"  # t_a typeset
        _changed(page, "move[1].time", "0.7")
        shown = _changed(page, "move[1].accel_time", "0.3")
        page.wait_for_function("() => document.querySelector('.dr-row [data-key=\"move[1].decel_time\"]')"
                               "?.closest('.dr-row').querySelector('input[type=text]').value === '0.3'")
        assert _field(page, "move[1].decel_time") == "0.3"
        assert "37.5 rpm" in shown and "31.58 rpm" not in shown
        row(page, "move[1].decel_time").scroll_into_view_if_needed()
        page.screenshot(path=str(SHOTS / "decel-follows-accel.png"))
        # Typed by the reviewer, it no longer follows: 0.15 s is computed and written.
        shown = _changed(page, "move[1].decel_time", "0.15")
        assert "31.58 rpm" in shown
        assert row(page, "move[1].decel_time").locator(".dr-follows").count() == 0
        assert row(page, "move[1].decel_time").locator(".dr-changed").count() == 1


def test_the_same_motion_written_twice_gives_the_same_verdict_in_the_page(tmp_path):
    # Finding 2 (E16): a copy of the move and of the dwell (index, 1 s, index, 1 s) is the example's motion
    # twice: Z_h = 2 · 3600 / 3 s = 2400 /h, as before, so f_s 1.6 and T_2max 100.9 N·m stay, and the verdict.
    with served(_copy(tmp_path)) as server, browser_page() as page:
        page.goto(server.url)
        page.wait_for_selector(RESULTS, timeout=60_000)
        first = page.inner_text(RESULTS)
        assert first.startswith("PASS") and "100.9 N·m" in first and "2400" in first
        for after, kind in (("2 dwell", "move"), ("3 move", "dwell")):
            g = int(page.get_attribute(RESULTS, "data-generation"))
            page.locator(".design-review .dr-moves select").first.select_option(label=after)
            page.locator(".design-review .dr-moves button", has_text=f"+ {kind}").click()
            wait_for_results(page, g)
            _current(page)
        twice = page.inner_text(RESULTS)
        assert "cycle 3 s" in twice
        assert twice.startswith("PASS") and "100.9 N·m" in twice and "2400" in twice and "Gearbox NPT035-10" in twice
        assert "69.36 N·m" not in twice and "1200" not in twice
        page.screenshot(path=str(SHOTS / "motion-twice.png"))
