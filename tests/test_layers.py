"""The package's layers point one way: machinery, then the domain modules, then their figures, then
the case layer, then report, review and command line. A module imports (at its top or inside a
function) only modules of its own layer or below."""

import ast
from pathlib import Path

import pytest

CALC = Path(__file__).resolve().parent.parent / "calc"

LAYERS = {
    "machinery": ("errors", "units", "formula", "formula_numeric", "codegen", "checks", "selection", "bands", "catalog", "measurement", "cycle"),
    "domain": ("profile", "motion", "mechanism", "gearbox", "coupling", "fits", "stiffness", "torsion", "hysteresis", "accuracy", "transmission", "inertia", "motor", "motor_ratings", "ratios", "combinations"),
    "figures": ("plots", "combination_plots", "coupling_plots", "accuracy_plots", "motion_plots", "motor_plots", "glossary", "schematic"),
    "case": ("case", "sections"),
    "top": ("report", "review", "publish", "__main__", "__init__", "resources"),
}
RANK = {module: k for k, modules in enumerate(LAYERS.values()) for module in modules}


def top_module(path: Path) -> str:
    """``calc/sections/gearbox.py`` -> ``sections``; ``calc/gearbox.py`` -> ``gearbox``."""
    parts = path.relative_to(CALC).with_suffix("").parts
    return parts[0]


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
                    names |= {rest[0]} if rest else {a.name for a in node.names}
                continue
            base = list(package[: len(package) - (node.level - 1)])
            rest = (node.module or "").split(".") if node.module else []
            full = [*base, *rest]
            names |= {full[0]} if full else {a.name for a in node.names}
        elif isinstance(node, ast.Import):
            names |= {a.name.split(".")[1] for a in node.names if a.name.startswith("calc.")}
    return names


FILES = sorted(p for p in CALC.rglob("*.py"))


def test_every_module_has_a_layer():
    assert {top_module(p) for p in FILES} <= set(RANK), {top_module(p) for p in FILES} - set(RANK)


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(CALC)))
def test_imports_point_down(path):
    own = RANK[top_module(path)]
    upward = sorted(m for m in imported(path) if m in RANK and RANK[m] > own)
    assert not upward, f"{path.relative_to(CALC)} ({list(LAYERS)[own]}) imports {upward} from a layer above"


def test_the_rule_catches_an_upward_import():
    # The case layer importing the report is what the test must refuse (an imported name is seen
    # whether at the top of a module or inside a function).
    assert "report" in imported(CALC / "sections" / "x.py", "def f():\n    from ..report import build_report\n")
    assert "sections" in imported(CALC / "gearbox.py", "from .sections import evaluate\n")
    assert "case" in imported(CALC / "coupling.py", "import calc.case\n")
