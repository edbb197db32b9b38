"""What the served review's kernel does at its start and at each change, and what it leaves out: the
page answers within a tenth of a second only while each change does no more than the page shows
(bench/bench.py measures the times; these tests hold the work down)."""

import subprocess
import sys

import ipywidgets
import pytest

import calc.report
from calc.review import DesignReview

from ..conftest import DERIVED_EXAMPLE as EXAMPLE  # the example as make review serves it


def test_the_pages_kernel_imports_no_typesetting_plotting_or_table_library():
    # The page's notebook (calc/review/design-review.ipynb) imports the panel and draws the example: Jinja2
    # (the report's LaTeX), sympy, pandas, matplotlib and python-control are the PDF's and the notebooks'.
    code = ("import sys; from calc.review import DesignReview; DesignReview(sys.argv[1]).settled(); "
            "print(sorted(m for m in ('jinja2', 'sympy', 'pandas', 'matplotlib', 'control', 'scipy.signal') "
            "if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code, str(EXAMPLE)], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_a_change_runs_the_ratio_search_only_where_the_page_shows_it(monkeypatch):
    # The report's search of every ratio is the PDF's; the page shows the search where asked for and runs it then.
    searched = []
    real = calc.report.ratio_search
    monkeypatch.setattr(calc.report, "ratio_search", lambda *a: searched.append(1) or real(*a))
    p = DesignReview(EXAMPLE).settled()
    p._typed("mechanism.inertia", "1600")
    p.settled()
    assert searched == [] and p.state.shown.report.ratios is None and "Gearbox <b>" in p.results.value
    p._option("ratio_search", True)
    p.settled()
    assert searched == [] and "<h3>Ratio search</h3>" in p.results.value  # the page's own search, shown
    assert calc.report.report_of(p.state.shown.case).ratios is not None and searched == [1]  # the PDF's, kept


def test_the_input_rows_share_their_layouts_and_styles():
    # A row is its label, message, control and field, and the two boxes that hold them: six models, the
    # layouts and styles of every row shared (the browser builds each model one by one as the page loads).
    p = DesignReview(EXAMPLE).settled()
    rows = p.rows.box.children
    assert len(rows) >= 10
    layouts, styles, widgets = set(), set(), 0
    for row in rows:
        line, message = row.children
        for widget in (row, line, message, *line.children):
            widgets += 1
            layouts.add(widget.layout.model_id)
            style = getattr(widget, "style", None)
            if style is not None:
                styles.add(style.model_id)
    assert widgets >= 5 * len(rows) and len(layouts) <= 5 and len(styles) <= 4
    # shared, they still hold what each kind of part sets
    label = rows[0].children[0].children[0]
    assert label.layout.width and label.layout.flex and isinstance(label, ipywidgets.HTML)


@pytest.mark.parametrize("key, value", [("mechanism.inertia", "1650"), ("drive.brake_resistor.resistance", "110")])
def test_a_change_gives_the_results_a_page_built_for_its_values_gives(key, value):
    # Whatever a change leaves out or reuses, its results are those of a page opened on the changed values.
    p = DesignReview(EXAMPLE).settled()
    p._typed(key, value)
    p.settled()
    fresh = DesignReview(EXAMPLE).settled()
    fresh.state.follow_values({key: value})
    fresh.refresh()

    def body(html: str) -> str:  # from the verdict on (the head above it says when it was computed)
        return html[html.index('<div class="verdict">'):]

    assert body(p.results.value) == body(fresh.results.value)
