"""The package's layers point one way: the unit and formula machinery (core), the data read from
files, the domain formulas, their figures, the case layer (sections), then the outputs (report,
review and command line). A module imports (at its top or inside a
function) only modules of its own layer or below."""

import ast
from pathlib import Path

import pytest

CALC = Path(__file__).resolve().parent.parent / "calc"

#: The layers, lowest first: the subpackages of calc (the outputs are the report, the review and
#: the command line).
LAYERS = ("core", "data", "domain", "figures", "sections", "outputs")
OUTPUTS = ("report", "review", "__main__", "__init__")
RANK = {layer: k for k, layer in enumerate(LAYERS)}


def top_module(path: Path) -> str:
    """The layer of a file: ``calc/sections/gearbox.py`` -> ``sections``; ``calc/report/x.py`` -> ``outputs``."""
    first = path.relative_to(CALC).with_suffix("").parts[0]
    return "outputs" if first in OUTPUTS else first


def imported(path: Path, text: str | None = None) -> set[str]:
    """The calc modules a file (its ``text``, read from ``path`` when not given) imports, by their
    top-level name in the package."""
    names = set()
    package = path.relative_to(CALC).parent.parts  # () for calc/, ("sections",) for calc/sections/
    for node in ast.walk(ast.parse(path.read_text() if text is None else text)):
        if isinstance(node, ast.ImportFrom):
            if node.level == 0:
                if node.module and node.module.split(".")[0] == "calc":
                    rest = node.module.split(".")[1:]
                    names |= {_layer(rest[0])} if rest else {_layer(a.name) for a in node.names}
                continue
            base = list(package[: len(package) - (node.level - 1)])
            rest = (node.module or "").split(".") if node.module else []
            full = [*base, *rest]
            names |= {_layer(full[0])} if full else {_layer(a.name) for a in node.names}
        elif isinstance(node, ast.Import):
            names |= {_layer(a.name.split(".")[1]) for a in node.names if a.name.startswith("calc.")}
    return names


def _layer(name: str) -> str:
    return "outputs" if name in OUTPUTS else name


FILES = sorted(p for p in CALC.rglob("*.py"))


def test_every_module_has_a_layer():
    assert {top_module(p) for p in FILES} <= set(RANK), {top_module(p) for p in FILES} - set(RANK)


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(CALC)))
def test_imports_point_down(path):
    own = RANK[top_module(path)]
    upward = sorted(m for m in imported(path) if m in RANK and RANK[m] > own)
    assert not upward, f"{path.relative_to(CALC)} ({LAYERS[own]}) imports {upward} from a layer above"


def test_the_rule_catches_an_upward_import():
    # The case layer importing the report is what the test must refuse (an imported name is seen
    # whether at the top of a module or inside a function).
    assert "outputs" in imported(CALC / "sections" / "x.py", "def f():\n    from ..report import build_report\n")
    assert "sections" in imported(CALC / "domain" / "gearbox.py", "from ..sections import evaluate\n")
    assert "sections" in imported(CALC / "domain" / "coupling.py", "import calc.sections.case\n")
