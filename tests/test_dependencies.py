"""What the package imports is declared in pyproject.toml, and environment.txt pins all of it and
everything that needs: a module imported but not declared works only by luck of what else was
installed, and an unpinned dependency changes under the tests from one set-up to the next."""

import ast
import importlib.metadata as metadata
import sys
import tomllib

from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

from .conftest import ROOT


def imported_distributions() -> dict:
    """Each distribution whose modules calc/ imports, with a file that imports it."""
    by_module = metadata.packages_distributions()
    out = {}
    for path in sorted((ROOT / "calc").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0:
                names = [node.module]
            else:
                continue
            for top in (name.split(".")[0] for name in names):
                if top in sys.stdlib_module_names or top == "calc":
                    continue
                for dist in by_module.get(top, [top]):
                    out.setdefault(canonicalize_name(dist), path.relative_to(ROOT).as_posix())
    return out


def declared() -> set:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    requirements = project["dependencies"] + [r for extra in project["optional-dependencies"].values() for r in extra]
    return {canonicalize_name(Requirement(r).name) for r in requirements}


def pinned() -> dict:
    lines = (ROOT / "environment.txt").read_text(encoding="utf-8").splitlines()
    return {canonicalize_name(line.split("==")[0]): line for line in lines if "==" in line}


def test_every_module_the_package_imports_is_declared():
    undeclared = {dist: where for dist, where in imported_distributions().items() if dist not in declared()}
    assert not undeclared, f"imported but not declared in pyproject.toml: {undeclared}"


def test_the_lock_holds_every_declared_dependency_and_what_each_needs():
    lock = pinned()
    assert declared() <= set(lock), f"declared but not pinned in environment.txt: {declared() - set(lock)}"
    unpinned = set()
    for name in lock:
        for text in metadata.distribution(name).requires or []:
            requirement = Requirement(text)
            if requirement.marker is not None and not requirement.marker.evaluate({"extra": ""}):
                continue  # an extra of that distribution, or another platform's
            if canonicalize_name(requirement.name) not in lock:
                unpinned.add(f"{requirement.name} (needed by {name})")
    assert not unpinned, f"installed but not pinned in environment.txt: {sorted(unpinned)}"
