"""Regenerate ``notebooks/figures/12-design-review.png``, the picture notebook 12 shows of its
panel (a static page, the book among them, cannot run the live panel): the served design review
of the example as a reviewer first sees it, in headless Chromium.

Run ``.venv/bin/python book/panel_screenshot.py`` after a change to the panel's look.
"""

import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from bench.review_browser import review_in_browser, served  # noqa: E402

TARGET = ROOT / "notebooks" / "figures" / "12-design-review.png"

if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as shots, served(ROOT / "cases" / "indexing-table.toml") as server:
        visit = review_in_browser(server.url, Path(shots), [])
        TARGET.parent.mkdir(exist_ok=True)
        shutil.copy(visit.shots[0], TARGET)
    print(f"{TARGET.relative_to(ROOT)}: the panel as first shown")
