"""The notebooks as stored: no warning or standard-error output (a reader would take it for a
fault), and no markdown whose asterisks a renderer eats (``N*m`` sets ``m...N`` in italics)."""

import json
import re

import pytest

from .conftest import ROOT

NOTEBOOKS = sorted(
    p for p in ROOT.rglob("*.ipynb") if not {".venv", "build", ".ipynb_checkpoints"} & set(p.relative_to(ROOT).parts)
)
WARNING = re.compile(r"\b\w*Warning\b|^WARNING\b", re.MULTILINE)
# An asterisk between word characters, outside code spans and math: markdown takes it for emphasis.
EATEN = re.compile(r"\w\*\w")
CODE_OR_MATH = re.compile(r"`[^`]*`|\$\$.*?\$\$|\$[^$]*\$", re.DOTALL)


def text(value) -> str:
    return "".join(value) if isinstance(value, list) else value


def problems(notebook: dict) -> list[str]:
    """Each stored stderr or warning output, and each markdown text with an eaten asterisk."""
    found = []
    for k, cell in enumerate(notebook["cells"]):
        markdown = [text(cell["source"])] if cell["cell_type"] == "markdown" else []
        for out in cell.get("outputs", []):
            if out["output_type"] == "stream" and out["name"] == "stderr":
                found.append(f"cell {k}: standard-error output: {text(out['text'])[:200]!r}")
            shown = [text(out.get("text", ""))] + [
                text(v) for m, v in out.get("data", {}).items() if m.startswith("text/")
            ]
            found += [
                f"cell {k}: a warning in the output: {m.group(0)!r}" for s in shown for m in [WARNING.search(s)] if m
            ]
            markdown += [text(out.get("data", {}).get("text/markdown", ""))]
        for s in markdown:
            m = EATEN.search(CODE_OR_MATH.sub("", s))
            if m:
                found.append(f"cell {k}: markdown eats the asterisk of {m.group(0)!r} (write N·m, or `N*m`)")
    return found


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: str(p.relative_to(ROOT)))
def test_no_warning_and_no_eaten_asterisk_is_stored(path):
    assert not problems(json.loads(path.read_text())), problems(json.loads(path.read_text()))


def test_the_check_finds_what_it_looks_for():
    notebook = {"cells": [
        {"cell_type": "markdown", "source": ["Torque 12 N*m at `30 N*m` and $T = 3 N*m$"]},
        {"cell_type": "code", "source": "", "outputs": [
            {"output_type": "stream", "name": "stderr", "text": "x"},
            {"output_type": "stream", "name": "stdout", "text": "foo.py:3: UserWarning: careful"},
            {"output_type": "display_data", "data": {"text/markdown": "> C 22 N*m/arcmin"}},
        ]},
    ]}
    found = problems(notebook)
    assert (
        len(found) == 4
        and "'N*m'" in found[0]
        and "standard-error" in found[1]
        and "UserWarning" in found[2]
        and "'N*m'" in found[3]
    )
    assert problems({"cells": [{"cell_type": "markdown", "source": "a `N*m` b, **bold** and *italic*"}]}) == []
