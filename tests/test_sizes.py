"""Functions and classes of the covered layers stay small enough to read whole: no function over
:data:`MAX_FUNCTION_LINES` lines, no class over :data:`MAX_CLASS_LINES`.

A size counts the lines from ``def``/``class`` to the last one, comments and blank lines included,
docstrings left out: a docstring that documents every argument (tests/test_docstrings.py) is no
reason to split the code it documents. A nested function counts in its parent too. A layer not yet
held whole has its finished modules held one by one (:data:`COVERED_MODULES`)."""

import ast
from pathlib import Path

import pytest

CALC = Path(__file__).resolve().parent.parent / "calc"

#: The layers held to the sizes: every subpackage of calc.
COVERED = ("core", "data", "domain", "figures", "sections", "report", "review")
#: The modules held to the sizes outside the layers (paths under calc): the package and its command line.
COVERED_MODULES = ("__init__.py", "__main__.py")
#: Generated code, not written by hand.
SKIPPED = {"core/formula_numeric.py"}
MAX_FUNCTION_LINES = 80
MAX_CLASS_LINES = 300


def docstring_lines(tree: ast.AST) -> set:
    """The lines that docstrings take in a module.

    Parameters
    ----------
    tree : ast.AST
        The module, parsed.

    Returns
    -------
    set of int
        Their line numbers (1-based).
    """
    lines = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value,
                                                          ast.Constant) and isinstance(first.value.value, str):
                lines |= set(range(first.lineno, first.end_lineno + 1))
    return lines


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
    tree = ast.parse(text)
    documentation = docstring_lines(tree)
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            limit = MAX_CLASS_LINES if isinstance(node, ast.ClassDef) else MAX_FUNCTION_LINES
            lines = len(set(range(node.lineno, node.end_lineno + 1)) - documentation)
            if lines > limit:
                found.append((node.lineno, f"{node.name} ({lines} lines, line {node.lineno})"))
    return [text for _, text in sorted(found)]


FILES = sorted(
    {path for layer in COVERED for path in (CALC / layer).rglob("*.py") if str(path.relative_to(CALC)) not in SKIPPED}
    | {CALC / name for name in COVERED_MODULES}
)


@pytest.mark.parametrize("path", FILES, ids=lambda path: str(path.relative_to(CALC)))
def test_functions_and_classes_are_short(path):
    over = oversized(path.read_text(encoding="utf-8"))
    assert not over, (f"calc/{path.relative_to(CALC)}: over {MAX_FUNCTION_LINES} lines a function "
                      f"or {MAX_CLASS_LINES} a class: {', '.join(over)}")


def test_the_rule_catches_a_long_function():
    body = "".join(f"    x{k} = {k}\n" for k in range(80))
    assert oversized(f"def short():\n    return 1\n\n\ndef long():\n{body}") == ["long (81 lines, line 5)"]
    # A docstring does not count: the def line and 79 lines of code are 80.
    documented = "".join(f"    x{k} = {k}\n" for k in range(79))
    assert oversized(f'def documented():\n    """One\n\n    two.\n    """\n{documented}') == []
