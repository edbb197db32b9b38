"""Prose that cannot drift: every number a notebook quotes in markdown is one its code prints or
states. In the answers, for each markdown cell each number in its text (outside headings and
links) must appear, at the precision quoted, among the stored outputs or the code literals of the
code cells it introduces (the run of code cells just after it); comments do not count, being
prose themselves. Integers up to 10 are exempt (counts, list items, exponents), and so are the
digits of a part's name (NPT035-10).

In the course's notebooks, whose prose explains a figure or a table above or below it, a number
must appear among the outputs or code literals of any code cell of the notebook; the names of
standards (ISO 286) and of files are not numbers, and the exercises and self-checks pose
hypothetical values (their answers are checked above). A figure quoted from a source, not computed,
is listed in ``QUOTED`` with where it comes from.

Code quotes other notebooks too: a code line whose comment or text names a notebook ("notebook 06's
mean output speed"), and an output line that names one, may state only numbers that notebook prints
or states, so a figure copied from an earlier version of another notebook cannot stay behind."""

import json
import re
from pathlib import Path

import pytest

from .conftest import ROOT

# The notebooks whose prose is checked number by number, beside the code it introduces.
CHECKED = ("notebooks/instructor/99-answers.ipynb",)
# The course's notebooks: each number of their prose is printed or stated somewhere in them.
COURSE = tuple(sorted(str(p.relative_to(ROOT)) for p in (ROOT / "notebooks").glob("*.ipynb")))
# Figures the course quotes from a source rather than computing: (notebook, number): the source.
QUOTED = {
    ("06-s1-selection.ipynb", "6.6"): "ISO 6336-2's life factor for flank pitting, as a torque exponent",
    ("07-s5-selection.ipynb", "3600"): "seconds per hour, in the source's Z_h = 3600 / t_cycle",
    ("13-source-and-errata.ipynb", "3600"): "seconds per hour, in the source's Z_h = 3600 / t_cycle (E16)",
    ("01-motion-and-mechanism.ipynb", "60"): "the inch case file's load, 60 lb (cases/linear-axis-inch.toml)",
    ("01-motion-and-mechanism.ipynb", "200"): "the pinion's travel per revolution, pi · 63.66 mm",
    ("08-couplings.ipynb", "0.012"): "ISO 286-2: k6 over 10 up to 18 mm (calc.domain.fits, tests/domain/test_fits.py)",
    ("08-couplings.ipynb", "0.015"): "ISO 286-2: k6 over 18 up to 30 mm (calc.domain.fits, tests/domain/test_fits.py)",
    ("08-couplings.ipynb", "0.018"): "ISO 286-2: k6 over 30 up to 50 mm (calc.domain.fits, tests/domain/test_fits.py)",
    (
        "10-stiffness-backlash-lost-motion.ipynb",
        "50",
    ): "the band of the loop the stiffness is read in, 50 % to 100 % of T_N (calc.domain.hysteresis)",
    (
        "11-transmission-and-positioning-accuracy.ipynb",
        "31",
    ): "the generated trace's tooth mesh, 31 per input turn (data/transmission-NPT035-10-generated.csv)",
    ("11-transmission-and-positioning-accuracy.ipynb", "310"): "the same mesh per output turn, 31 · 10",
    ("00-index.ipynb", "12"): "how a reader types a quantity, Q_(12, 'N*m'), an example of input",
    ("00-index.ipynb", "106"): "how a reader types a torque in inch-pound units, an example of input",
    ("00-index.ipynb", "300"): "the trap of angles (E15): 300 rpm, an example of input",
}
NAMES = re.compile(r"\b(?:ISO|IEC|DIN)\s[\d-]+|[\w/.-]+\.(?:ipynb|toml|csv|py|png)\b")  # standards and files
POSED = re.compile(r"^## (?:Exercises|Self-check)", re.MULTILINE)  # questions: hypothetical values
NUMBER = re.compile(r"(?<![\w.])(?<!\w-)\d+(?:[ ,]\d{3})*(?:\.\d+)?")
NOTEBOOKS_NAMED = r"\b[Nn]otebooks?\s+\d\d(?:(?:,\s*|\s+(?:and|to|or)\s+)\d\d)*\b"  # "notebooks 01 to 12"
NOT_PROSE = re.compile(
    rf"^#.*$|\]\([^)]*\)|\bE\d+\b|\b\d+[a-z]?\s*·\s|{NOTEBOOKS_NAMED}|^\|\s*\d\d\s*\|", re.MULTILINE
)  # headings, link targets, errata, "02 · ", notebooks named by number, a table's row of a notebook


def text(value) -> str:
    return "".join(value) if isinstance(value, list) else value


def quoted(markdown: str) -> list[str]:
    """The numbers a markdown text quotes, as written (thousands separators dropped)."""
    found = (m.group(0).replace(" ", "").replace(",", "") for m in NUMBER.finditer(NOT_PROSE.sub(" ", markdown)))
    return [n for n in found if "." in n or int(n) > 10]


def stated(cell: dict) -> list[float]:
    """The numbers a code cell prints or displays, and those written in its code (comments left out)."""
    code = "\n".join(line.split("#")[0] for line in text(cell["source"]).splitlines())
    shown = [text(out.get("text", "")) for out in cell.get("outputs", [])]
    shown += [
        text(v) for out in cell.get("outputs", []) for m, v in out.get("data", {}).items() if m.startswith("text/")
    ]
    return [float(m.group(0).replace(" ", "").replace(",", "")) for m in NUMBER.finditer("\n".join([code, *shown]))]


def matches(number: str, values: list[float]) -> bool:
    """Whether ``number`` is one of ``values`` rounded to the decimals it is written with."""
    decimals = len(number.partition(".")[2])
    return any(abs(v - float(number)) <= 0.5 * 10.0**-decimals * (1 + 1e-9) for v in values)


def unfounded(notebook: dict) -> list[str]:
    """Each number of a markdown cell that the code cells it introduces neither print nor state."""
    cells, found = notebook["cells"], []
    for k, cell in enumerate(cells):
        if cell["cell_type"] != "markdown":
            continue
        beside, j = [], k + 1
        while j < len(cells) and cells[j]["cell_type"] == "code":
            beside += stated(cells[j])
            j += 1
        found += [
            f"cell {k}: {n} is quoted but not printed beside it"
            for n in quoted(text(cell["source"]))
            if not matches(n, beside)
        ]
    return found


def unfounded_anywhere(notebook: dict, name: str) -> list[str]:
    """Each number of a course notebook's prose that none of its code cells prints or states."""
    cells = notebook["cells"]
    everywhere = [v for cell in cells if cell["cell_type"] == "code" for v in stated(cell)]
    found = []
    for k, cell in enumerate(cells):
        source = text(cell["source"])
        if cell["cell_type"] != "markdown" or POSED.search(source):
            continue
        found += [f"cell {k}: {n} is quoted but printed nowhere" for n in quoted(NAMES.sub(" ", source))
                  if not matches(n, everywhere) and (name, n) not in QUOTED]
    return found


NAMED = re.compile(r"\bnotebooks?\s+(\d\d)\b")  # a notebook named in a comment, a text or an output
FORMAT = re.compile(r"\{[^{}]*\}")  # an f-string's replacement field: an expression, not a quoted number


def quoted_across(notebook: dict, notebooks: dict) -> list[str]:
    """Each number of a code line or an output line that names another notebook which that notebook
    neither prints nor states.

    ``notebooks`` maps a notebook's number (``"06"``) to the notebook, as read from its JSON."""
    found = []
    for k, cell in enumerate(notebook["cells"]):
        if cell["cell_type"] != "code":
            continue
        shown = [text(out.get("text", "")) for out in cell.get("outputs", [])]
        shown += [text(v) for out in cell.get("outputs", []) for m, v in out.get("data", {}).items()
                  if m == "text/plain"]
        for line in [*text(cell["source"]).splitlines(), *"\n".join(shown).splitlines()]:
            for number in sorted(set(NAMED.findall(line))):
                if number not in notebooks:
                    continue
                there = [v for c in notebooks[number]["cells"] if c["cell_type"] == "code" for v in stated(c)]
                found += [f"cell {k}: {n} is quoted from notebook {number}, which prints it nowhere"
                          for n in quoted(re.sub(NOTEBOOKS_NAMED, " ", FORMAT.sub(" ", line))) if not matches(n, there)]
    return found


@pytest.mark.parametrize("path", COURSE + CHECKED)
def test_every_number_code_quotes_from_another_notebook_is_printed_there(path):
    notebooks = {p.name[:2]: json.loads(p.read_text()) for p in (ROOT / "notebooks").glob("[0-9][0-9]-*.ipynb")}
    problems = quoted_across(json.loads((ROOT / path).read_text()), notebooks)
    assert not problems, problems


def test_the_check_finds_a_figure_code_quotes_from_an_older_notebook():
    printed = [{"text": "n_2m = 30 rpm, f_e = 1069.4 Hz"}]
    there = {"cells": [{"cell_type": "code", "source": "n_2m", "outputs": printed}]}
    code = {"cell_type": "code", "source": 'n_2m = Q_(30, "rpm")  # notebook 06\'s mean output speed',
            "outputs": [{"text": "as read, f_e = 1069.4 Hz (notebook 06)\nat {n:.1f} rpm"}]}
    assert quoted_across({"cells": [code]}, {"06": there}) == []
    code["source"] = 'n_2m = Q_(240, "rpm")  # notebook 06\'s mean output speed'
    code["outputs"][0]["text"] = "as read, f_e = 1316.4 Hz (notebook 06)"
    assert quoted_across({"cells": [code]}, {"06": there}) == [
        "cell 0: 240 is quoted from notebook 06, which prints it nowhere",
        "cell 0: 1316.4 is quoted from notebook 06, which prints it nowhere",
    ]


@pytest.mark.parametrize("path", COURSE)
def test_every_number_the_course_quotes_is_printed(path):
    problems = unfounded_anywhere(json.loads((ROOT / path).read_text()), Path(path).name)
    assert not problems, problems


def test_the_course_check_finds_a_stale_figure():
    code = {
        "cell_type": "code",
        "source": "i = 10",
        "outputs": [
            {"output_type": "stream", "name": "stdout", "text": "C = 20.1 N·m/arcmin, the gearbox 91 % of the twist"}
        ],
    }
    notebook = {
        "cells": [
            code,
            {"cell_type": "markdown", "source": "See ISO 286 and 05-x.ipynb: 91 % of the twist, C = 20.1 N·m/arcmin"},
        ]
    }
    assert unfounded_anywhere(notebook, "05-x.ipynb") == []
    notebook["cells"][1]["source"] = "97 % of the twist, C = 21.35 N·m/arcmin"
    assert unfounded_anywhere(notebook, "05-x.ipynb") == [
        "cell 1: 97 is quoted but printed nowhere",
        "cell 1: 21.35 is quoted but printed nowhere",
    ]
    notebook["cells"][1]["source"] = "## Exercises\n\nTry 97 % and 21.35 N·m/arcmin."
    assert unfounded_anywhere(notebook, "05-x.ipynb") == []


@pytest.mark.parametrize("path", CHECKED)
def test_every_number_quoted_is_printed_beside_it(path):
    problems = unfounded(json.loads((ROOT / path).read_text()))
    assert not problems, problems


def test_the_check_finds_a_number_that_drifted():
    code = {
        "cell_type": "code",
        "source": "x = 2300  # by hand: 2300",
        "outputs": [{"output_type": "stream", "name": "stdout", "text": "n_1N = 2200 rpm, T = 35.41 N·m"}],
    }
    notebook = {
        "cells": [
            {
                "cell_type": "markdown",
                "source": "## 02 · S1\n\nn_1N of 2200 rpm and T_2m = 35.4 N·m; see [E2](02-x.ipynb), 3 checks",
            },
            code,
        ]
    }
    assert unfounded(notebook) == []
    notebook["cells"][0]["source"] = "n_1N of 2300 rpm and T_2m = 35.5 N·m, T = 35.41 N·m"
    assert unfounded(notebook) == ["cell 0: 35.5 is quoted but not printed beside it"]
    code["source"] = "x = 1  # by hand: 2300"
    assert unfounded(notebook) == [
        "cell 0: 2300 is quoted but not printed beside it",
        "cell 0: 35.5 is quoted but not printed beside it",
    ]
