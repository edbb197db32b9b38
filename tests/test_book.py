"""The course as a static website (``make book``): built from a clean checkout's notebooks as
stored, with Sphinx warnings as errors, then every page opened in headless Chromium from the files
alone: it loads, asks for nothing on the network and nothing missing, its images show, its local
links reach a page of the book, MathJax (shipped in the build) typesets its math with no error,
and the self-checks open to their feedback; no page is wider than the window. In the lecturer's book,
the pages whose content is the students' are opened in the students' book, and their links (their
navigation lists the lecturer's pages) are read from the file. The build time and the page count are
printed."""

import contextlib
import re
import tempfile
from pathlib import Path
from urllib.parse import unquote, urlparse

import pytest

from bench.review_browser import CHROMIUM, CHROMIUM_ARGS, playwright_driver

from .conftest import ROOT, needs_tools, sphinx_book

pytestmark = needs_tools("chromium")

RAW_TEX = re.compile(r"\$\\?[A-Za-z][^$\n]*\$")  # $T_{2m}$ or $\\mathrm{ED}$ left as typed
NOTEBOOKS = sorted(p.stem for p in (ROOT / "notebooks").glob("*.ipynb"))


@pytest.fixture(scope="module", params=["students", "lecturer"])
def book(request, students_book, tmp_path_factory):
    """The students' book (make book, make student; shared with tests/test_course.py) or the lecturer's
    (make lecturer: ``-t lecturer``)."""
    out = students_book if request.param == "students" else sphinx_book(tmp_path_factory.mktemp("lecturer"), True)
    pages = sorted(out.glob("notebooks/*.html")) + [out / "book" / "index.html"]
    pages += sorted(out.glob("book/course/*.html"))  # the course frame, the primer, the licence
    pages += sorted(out.glob("notebooks/instructor/*.html")) + sorted(out.glob("book/lecturer*.html"))
    print(f"\n{request.param}' book: {len(pages)} pages")
    return out, pages


def test_every_students_notebook_is_a_page_and_the_lecturers_only_in_the_lecturers_book(book):
    out, pages = book
    assert sorted(p.stem for p in pages if p.parent.name == "notebooks") == NOTEBOOKS
    lecturers = {p.relative_to(out).as_posix() for p in pages} & {
        "notebooks/instructor/99-answers.html", "book/lecturer.html", "book/lecturer-grading.html"}
    if out.name.startswith("students"):
        assert not list(out.rglob("*99-answers*")) and not list(out.rglob("*lecturer*"))
    else:
        assert len(lecturers) == 3
    assert {p.stem for p in pages if p.parent.name == "course"} == {"frame", "primer", "licence"}
    front = (out / "book" / "index.html").read_text()
    assert all(f"{name}.html" in front for name in NOTEBOOKS)  # the table of contents links each
    assert 'url=book/index.html' in (out / "index.html").read_text()  # the address make book names leads there
    # Every figure says what it shows to a reader who cannot see it (the cells' mystnb alt text), not its file name.
    for page in pages:
        for img in re.findall(r"<img\b[^>]*>", page.read_text()):
            alt = re.search(r'\balt="([^"]*)"', img)
            assert alt and len(alt.group(1).split()) >= 8 and not alt.group(1).endswith(".png"), (page.name, img[:200])


def article(page: Path) -> str:
    """A page's content: its main column, without the navigation, which lists the lecturer's pages in their book."""
    text = page.read_text(encoding="utf-8")
    return text[text.index('<div class="body" role="main">'):text.index('<div class="sphinxsidebar"')]


def missing_links(page: Path) -> list[str]:
    """The links of a page's file to files of the book that do not exist."""
    targets = (unquote(href.split("#")[0].split("?")[0]) for href in re.findall(r'href="([^"]*)"', page.read_text()))
    return [t for t in targets if t and ":" not in t and not (page.parent / t).exists()]


def test_every_page_loads_offline_with_its_images_links_math_and_self_checks(book, students_book):
    out, pages = book
    problems = []
    if out != students_book:
        # A lecturer's page with the students' page's content (all but the lecturer's own three) is opened in the
        # students' book: here only its navigation differs, and its links are read from the file.
        same = [p for p in pages if (students_book / p.relative_to(out)).exists()
                and article(p) == article(students_book / p.relative_to(out))]
        problems += [f"{p.relative_to(out)}: link to {t} leads nowhere" for p in same for t in missing_links(p)]
        pages = [p for p in pages if p not in same]
        assert {p.relative_to(out).as_posix() for p in pages} >= {
            "notebooks/instructor/99-answers.html", "book/lecturer.html", "book/lecturer-grading.html"}
    with contextlib.nullcontext(playwright_driver()) as pw, tempfile.TemporaryDirectory() as profile:
        browser = pw.chromium.launch_persistent_context(
            profile, executable_path=str(CHROMIUM), headless=True, args=CHROMIUM_ARGS
        )
        try:
            page = browser.new_page()
            asked, failed, typeset = [], [], 0
            page.on("request", lambda r: asked.append(r.url))
            page.on("requestfailed", lambda r: failed.append(r.url))
            for path in pages:
                name = path.relative_to(out)
                asked.clear(), failed.clear()
                page.goto(path.as_uri(), wait_until="load")
                if page.locator("script[src*='mathjax']").count():  # Sphinx adds MathJax to the pages with math
                    page.wait_for_function(
                        "() => window.MathJax && MathJax.startup && MathJax.startup.promise", timeout=30_000
                    )
                    page.evaluate("() => MathJax.startup.promise")
                    typeset += page.evaluate("() => document.querySelectorAll('mjx-container').length")
                problems += [f"{name}: asks the network for {u}" for u in asked if not u.startswith("file:")]
                problems += [f"{name}: {u} is missing" for u in failed]
                broken = page.evaluate(
                    "() => [...document.images].filter(i => !i.complete || i.naturalWidth === 0).map(i => i.src)"
                )
                problems += [f"{name}: image {u} does not show" for u in broken]
                # A wide output (a catalog's table, a long formula) scrolls in its own box (book/_static/custom.css).
                width, window = page.evaluate("() => [document.documentElement.scrollWidth, window.innerWidth]")
                problems += [f"{name}: the page is {width} px wide in a {window} px window"] if width > window else []
                for href in page.evaluate("() => [...document.querySelectorAll('a[href]')].map(a => a.href)"):
                    target = urlparse(href)
                    if target.scheme == "file" and not Path(unquote(target.path)).exists():
                        problems += [f"{name}: link to {href} leads nowhere"]
                errors = page.evaluate(
                    "() => [...document.querySelectorAll('mjx-merror')]"
                    ".map(e => e.getAttribute('data-mjx-error') || e.textContent)"
                )
                problems += [f"{name}: math error {e!r}" for e in errors]
                prose = page.evaluate(
                    "() => { const b = document.body.cloneNode(true); "
                    "b.querySelectorAll('pre, code, script').forEach(e => e.remove()); return b.textContent; }"
                )
                raw = RAW_TEX.findall(prose)  # code shows its $...$ as written
                problems += [f"{name}: shows raw TeX {raw[:3]}"] if raw else []
                left = page.evaluate(
                    "() => [...document.querySelectorAll('.math')]"
                    ".filter(m => !m.querySelector('mjx-container')).length"
                )
                problems += [f"{name}: {left} formulas left untypeset"] if left else []
                if path.parent.name == "notebooks" and "Self-check" in page.inner_text("body"):
                    answer = page.locator("details").first
                    answer.locator("summary").click()
                    if not answer.evaluate("d => d.open") or not answer.inner_text().split("\n", 1)[-1].strip():
                        problems.append(f"{name}: a self-check's answer does not open to its feedback")
        finally:
            browser.close()
    assert not problems, problems
    assert typeset > (300 if out == students_book else 50)  # every page's formulas (the glossary's); the answers'

