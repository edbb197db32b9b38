"""Dependencies as declared as they are used: every module the package imports comes from a
distribution that pyproject.toml declares (its dependencies or an extra), and environment.txt
pins every distribution of the tested environment (a complete lock: ``make setup`` installs
exactly it)."""

import ast
import importlib.metadata
import re
import sys
import tomllib

from .conftest import ROOT


def normal(name: str) -> str:
    """A distribution's name as packaging compares it (``Jinja2``, ``jupyter_client`` ->
    ``jinja2``, ``jupyter-client``)."""
    return re.sub(r"[-_.]+", "-", name).lower()


def requirement_name(requirement: str) -> str:
    return normal(re.match(r"[A-Za-z0-9][A-Za-z0-9._-]*", requirement.strip()).group(0))


def imported_modules() -> dict[str, str]:
    """Each third-party top-level module ``calc/`` imports, with one file that imports it."""
    out = {}
    for path in sorted((ROOT / "calc").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0:
                names = [node.module]
            else:
                continue
            for name in names:
                top = name.split(".")[0]
                if top not in sys.stdlib_module_names and top != "calc":
                    out.setdefault(top, path.relative_to(ROOT).as_posix())
    return out


def declared() -> set[str]:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    requirements = [*project["dependencies"], *(r for extra in project["optional-dependencies"].values() for r in extra)]
    return {requirement_name(r) for r in requirements}


def test_every_module_the_package_imports_is_declared():
    providers = importlib.metadata.packages_distributions()
    names = declared()
    undeclared = [
        f"{module} (imported by {path}, from {' or '.join(providers.get(module, ['no installed distribution']))})"
        for module, path in imported_modules().items()
        if not any(normal(d) in names for d in providers.get(module, []))
    ]
    assert not undeclared, f"pyproject.toml declares no distribution of: {'; '.join(undeclared)}"


def test_environment_txt_pins_every_installed_distribution():
    pinned = {}
    for line in (ROOT / "environment.txt").read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            name, _, version = line.partition("==")
            pinned[normal(name)] = version.strip()
    installed = {
        normal(d.metadata["Name"]): d.version for d in importlib.metadata.distributions()
        if normal(d.metadata["Name"]) not in {"pip", "drivetrain-calc"}  # the installer and the project itself
    }
    unpinned = sorted(f"{name}=={version}" for name, version in installed.items() if name not in pinned)
    assert not unpinned, f"environment.txt does not pin {', '.join(unpinned)} (installed in the tested environment)"
    wrong = sorted(f"{name}: pinned {pinned[name]}, installed {version}" for name, version in installed.items() if pinned[name] != version)
    assert not wrong, f"environment.txt pins other versions than the tested environment has: {'; '.join(wrong)}"
    assert declared() <= set(pinned), f"environment.txt does not pin {', '.join(sorted(declared() - set(pinned)))}"
