"""Dependencies as declared as they are used: every distribution the package, its tests and its
benchmark import (or run as ``python -m NAME``) is declared in pyproject.toml, and environment.txt
pins exactly what is installed, so a clean machine gets the set the tests ran against."""

import ast
import importlib.metadata
import re
import sys
import tomllib

from .conftest import ROOT

PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
#: Modules run as ``python -m NAME`` (a kernel, a server) rather than imported.
RUN_AS_MODULE = re.compile(r"""["']-m["'],\s*["']([A-Za-z_][A-Za-z0-9_]*)["']""")


def normalized(name: str) -> str:
    """A distribution's name as the packaging standards compare them (PEP 503)."""
    return re.sub(r"[-_.]+", "-", name).lower()


def requirement_name(requirement: str) -> str:
    return normalized(re.match(r"[A-Za-z0-9_.-]+", requirement).group(0))


def modules_used(folders) -> dict:
    """Top-level modules outside the standard library that the files import or run, each with a
    file that does."""
    used = {}
    for folder in folders:
        for path in sorted((ROOT / folder).rglob("*.py")):
            text = path.read_text(encoding="utf-8")
            names = set(RUN_AS_MODULE.findall(text))
            for node in ast.walk(ast.parse(text)):
                if isinstance(node, ast.Import):
                    names |= {alias.name.split(".")[0] for alias in node.names}
                elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                    names.add(node.module.split(".")[0])
            # pip comes with every virtual environment (python -m venv), the others are the project's own.
            for name in (
                names - set(sys.stdlib_module_names) - {"calc", "tests", "bench", "review_browser", "__future__", "pip"}
            ):
                used.setdefault(name, path.relative_to(ROOT))
    return used


def undeclared(used: dict, declared: set) -> list[str]:
    distributions = importlib.metadata.packages_distributions()
    missing = []
    for module, where in sorted(used.items()):
        found = {normalized(d) for d in distributions.get(module, [])}
        assert found, f"{where} uses {module}, which no installed distribution provides"
        if not found & declared:
            missing.append(f"{module} ({', '.join(sorted(found))}), used in {where}")
    return missing


def test_what_the_package_uses_is_declared():
    extras = PYPROJECT["optional-dependencies"]
    declared = {requirement_name(r) for r in PYPROJECT["dependencies"]}
    declared |= {requirement_name(r) for name, reqs in extras.items() if name != "test" for r in reqs}
    assert undeclared(modules_used(["calc"]), declared) == []


def test_what_the_tests_and_benchmark_use_is_declared():
    declared = {
        requirement_name(r)
        for reqs in [PYPROJECT["dependencies"], *PYPROJECT["optional-dependencies"].values()]
        for r in reqs
    }
    assert undeclared(modules_used(["tests", "bench"]), declared) == []


def test_environment_txt_pins_exactly_what_is_installed():
    pinned = {}
    for line in (ROOT / "environment.txt").read_text(encoding="utf-8").splitlines():
        line = line.split("#")[0].strip()
        if line:
            name, _, version = line.partition("==")
            assert version, f"environment.txt: expected NAME==VERSION, found {line!r}"
            pinned[normalized(name)] = version
    installed = {
        normalized(d.metadata["Name"]): d.version
        for d in importlib.metadata.distributions()
        if normalized(d.metadata["Name"]) not in {"pip", normalized(PYPROJECT["name"])}
    }
    assert {k: v for k, v in installed.items() if pinned.get(k) != v} == {}, (
        "installed but not pinned (or at another version)"
    )
    assert {k: v for k, v in pinned.items() if installed.get(k) != v} == {}, (
        "pinned but not installed (or at another version)"
    )
