"""Functions and classes of the covered layers stay small enough to read whole: no function over
:data:`MAX_FUNCTION_LINES` lines, no class over :data:`MAX_CLASS_LINES` (from ``def``/``class`` to
the last line, docstring and comments included; a nested function counts in its parent too)."""

import ast
from pathlib import Path

import pytest

CALC = Path(__file__).resolve().parent.parent / "calc"

#: The layers held to the sizes (the subpackages of calc); the others join as they are split.
COVERED = ("core", "data", "domain", "figures")
#: Generated code, not written by hand.
SKIPPED = {"core/formula_numeric.py"}
MAX_FUNCTION_LINES = 80
MAX_CLASS_LINES = 300


def oversized(text: str) -> list:
    """The functions and classes of a module's source over their limits.

    Parameters
    ----------
    text : str
        The module's source.

    Returns
    -------
    list of str
        ``name (N lines, line L)`` for each, in source order.
    """
    found = []
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            limit = MAX_CLASS_LINES if isinstance(node, ast.ClassDef) else MAX_FUNCTION_LINES
            lines = node.end_lineno - node.lineno + 1
            if lines > limit:
                found.append((node.lineno, f"{node.name} ({lines} lines, line {node.lineno})"))
    return [text for _, text in sorted(found)]


FILES = sorted(
    path for layer in COVERED for path in (CALC / layer).rglob("*.py")
    if str(path.relative_to(CALC)) not in SKIPPED
)


@pytest.mark.parametrize("path", FILES, ids=lambda path: str(path.relative_to(CALC)))
def test_functions_and_classes_are_short(path):
    over = oversized(path.read_text(encoding="utf-8"))
    assert not over, (f"calc/{path.relative_to(CALC)}: over {MAX_FUNCTION_LINES} lines a function "
                      f"or {MAX_CLASS_LINES} a class: {', '.join(over)}")


def test_the_rule_catches_a_long_function():
    body = "".join(f"    x{k} = {k}\n" for k in range(80))
    assert oversized(f"def short():\n    return 1\n\n\ndef long():\n{body}") == ["long (81 lines, line 5)"]
