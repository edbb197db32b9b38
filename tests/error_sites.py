"""The places in ``calc/`` that build the package's error, read from the current source.

A site is every call ``CalcError(...)`` in ``calc/**/*.py``, whatever happens to the object
afterwards (raised at once, returned to a caller that raises it, kept in a variable). Building
the error is what the package cannot do without a message, so every construction is a
message that needs a test. A site is named by its file (relative to the repository) and the
line where the call starts; the runtime record is matched to a site by the line range of its
call, so a message written over several lines counts as one site.
"""

import ast
import functools
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "calc"
ERROR = "CalcError"


@dataclass(frozen=True)
class Site:
    """One ``CalcError(...)`` call: where it is and how its message starts."""

    file: str  # relative to the repository, with forward slashes
    line: int  # first line of the call
    end_line: int  # last line of the call
    function: str  # qualified name of the enclosing function, or "<module>"
    message: str  # the message's source text, placeholders shown as {expression}

    def describe(self, width: int = 70) -> str:
        """``calc/x.py:123 (function): the message's start``."""
        text = self.message if len(self.message) <= width else self.message[: width - 1] + "…"
        return f"{self.file}:{self.line} ({self.function}): {text}"


def _is_error(func: ast.expr) -> bool:
    """``CalcError`` or ``something.CalcError``."""
    return (isinstance(func, ast.Name) and func.id == ERROR) or (
        isinstance(func, ast.Attribute) and func.attr == ERROR
    )


def _message_text(call: ast.Call) -> str:
    """The first argument as a reader sees it: literal text, and ``{expr}`` for each placeholder."""
    if not call.args:
        return "(no message)"
    node = call.args[0]
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        parts = []
        for value in node.values:
            if isinstance(value, ast.Constant):
                parts.append(str(value.value))
            else:
                parts.append("{" + ast.unparse(value.value) + "}")
        return "".join(parts)
    return ast.unparse(node)


class _Finder(ast.NodeVisitor):
    def __init__(self, file: str):
        self.file = file
        self.scope: list[str] = []
        self.sites: list[Site] = []

    def _enter(self, node):
        self.scope.append(node.name)
        self.generic_visit(node)
        self.scope.pop()

    visit_FunctionDef = visit_AsyncFunctionDef = visit_ClassDef = _enter

    def visit_Call(self, node: ast.Call):
        if _is_error(node.func):
            self.sites.append(
                Site(
                    self.file,
                    node.lineno,
                    node.end_lineno,
                    ".".join(self.scope) or "<module>",
                    " ".join(_message_text(node).split()),
                )
            )
        self.generic_visit(node)


def error_sites(package: Path = PACKAGE, root: Path = ROOT) -> list[Site]:
    """Every ``CalcError(...)`` call under ``package``, in file and line order, files named
    relative to ``root``. The package's own are read once a session (calc/ does not change while it
    runs, and a scan takes seconds); any other folder each time it is asked for."""
    if (package, root) == (PACKAGE, ROOT):
        return list(_package_sites())
    return _scan(package, root)


@functools.cache
def _package_sites() -> tuple[Site, ...]:
    return tuple(_scan(PACKAGE, ROOT))


def _scan(package: Path, root: Path) -> list[Site]:
    sites = []
    for path in sorted(package.rglob("*.py")):
        finder = _Finder(path.relative_to(root).as_posix())
        finder.visit(ast.parse(path.read_text(encoding="utf-8"), filename=str(path)))
        sites.extend(finder.sites)
    return sites


def site_at(sites: list[Site], file: str, line: int) -> Site | None:
    """The innermost site of ``file`` whose call spans ``line`` (a message may run over lines)."""
    spanning = [s for s in sites if s.file == file and s.line <= line <= s.end_line]
    return min(spanning, key=lambda s: s.end_line - s.line, default=None)
