"""Prose that cannot drift: every number an answer quotes in markdown is one its code prints or
states. For each markdown cell of a checked notebook, each number in its text (outside headings
and links) must appear, at the precision quoted, among the stored outputs or the code literals of
the code cells it introduces (the run of code cells just after it); comments do not count, being
prose themselves. Integers up to 10 are exempt (counts, list items, exponents), and so are the
digits of a part's name (NPT035-10)."""

import json
import re

import pytest

from .conftest import ROOT

# The notebooks whose prose is checked number by number.
CHECKED = ("notebooks/instructor/99-answers.ipynb",)
NUMBER = re.compile(r"(?<![\w.])(?<!\w-)\d+(?:[ ,]\d{3})*(?:\.\d+)?")
NOT_PROSE = re.compile(r"^#.*$|\]\([^)]*\)|\bE\d+\b|\b\d+[a-z]?\s*·\s", re.MULTILINE)  # headings, link targets, errata, "02 · "


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
    shown += [text(v) for out in cell.get("outputs", []) for m, v in out.get("data", {}).items() if m.startswith("text/")]
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
        found += [f"cell {k}: {n} is quoted but not printed beside it" for n in quoted(text(cell["source"])) if not matches(n, beside)]
    return found


@pytest.mark.parametrize("path", CHECKED)
def test_every_number_quoted_is_printed_beside_it(path):
    problems = unfounded(json.loads((ROOT / path).read_text()))
    assert not problems, problems


def test_the_check_finds_a_number_that_drifted():
    code = {"cell_type": "code", "source": "x = 2300  # by hand: 2300", "outputs": [{"output_type": "stream", "name": "stdout", "text": "n_1N = 2200 rpm, T = 35.41 N·m"}]}
    notebook = {"cells": [{"cell_type": "markdown", "source": "## 02 · S1\n\nn_1N of 2200 rpm and T_2m = 35.4 N·m; see [E2](02-x.ipynb), 3 checks"}, code]}
    assert unfounded(notebook) == []
    notebook["cells"][0]["source"] = "n_1N of 2300 rpm and T_2m = 35.5 N·m, T = 35.41 N·m"
    assert unfounded(notebook) == ["cell 0: 35.5 is quoted but not printed beside it"]
    code["source"] = "x = 1  # by hand: 2300"
    assert unfounded(notebook) == ["cell 0: 2300 is quoted but not printed beside it", "cell 0: 35.5 is quoted but not printed beside it"]
