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
OUTPUTS = ("report", "review", "exchange", "course", "__main__", "__init__")
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


# -- no import cycle --------------------------------------------------------------------------


def module_name(path: Path) -> str:
    """The dotted name of a file of calc: ``calc/sections/gearbox.py`` -> ``calc.sections.gearbox``,
    ``calc/sections/__init__.py`` -> ``calc.sections``."""
    parts = ("calc", *path.relative_to(CALC).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _is_module(name: str) -> bool:
    relative = Path(*name.split(".")[1:])
    return (CALC / relative).with_suffix(".py").is_file() or (CALC / relative / "__init__.py").is_file()


def imported_modules(path: Path, text: str | None = None) -> set[str]:
    """The calc modules a file imports (at its top or inside a function), by their dotted name:
    an imported name that is a module of its own counts as that module, else the module it is
    taken from."""
    out = set()
    package = module_name(path).split(".") if path.name == "__init__.py" else module_name(path).split(".")[:-1]
    for node in ast.walk(ast.parse(path.read_text() if text is None else text)):
        if isinstance(node, ast.ImportFrom):
            named = (node.module or "").split(".") if node.module else []
            base = named if node.level == 0 else [*package[: len(package) - (node.level - 1)], *named]
            if base[0] != "calc":
                continue
            for alias in node.names:
                whole = ".".join([*base, alias.name])
                out.add(whole if _is_module(whole) else ".".join(base))
        elif isinstance(node, ast.Import):
            out |= {a.name for a in node.names if a.name.startswith("calc.")}
    return out


def import_cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module of an import graph (module ->
    the modules it imports), each sorted, by Tarjan's algorithm."""
    index, low, stack, on_stack, out = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                out.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_no_import_cycle():
    graph = {module_name(p): imported_modules(p) - {module_name(p)} for p in FILES}
    cycles = import_cycles(graph)
    assert not cycles, "modules of calc import each other: " + "; ".join(" <-> ".join(c) for c in cycles)


def test_the_rule_catches_a_made_up_cycle():
    # Two sections importing each other, one at its top and one inside a function; a third
    # importing one of them is not in the cycle.
    sections = CALC / "sections"
    graph = {"calc.sections.gearbox": imported_modules(sections / "gearbox.py", "from . import coupling\n"),
             "calc.sections.coupling": imported_modules(sections / "coupling.py",
                                                        "def f():\n    from .gearbox import NAME\n"),
             "calc.sections.motor": imported_modules(sections / "motor.py", "import calc.sections.gearbox\n")}
    assert import_cycles(graph) == [["calc.sections.coupling", "calc.sections.gearbox"]]
    assert import_cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
