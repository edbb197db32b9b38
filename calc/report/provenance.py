"""Where a calc report comes from, for its title block: the build date, the package version, the
commit the package was built from, and the SHA-256 of each file read."""

from __future__ import annotations

import hashlib
import subprocess
from datetime import datetime, timezone
from pathlib import Path

from .. import __version__
from ..data.catalog import PROJECT_DIR

#: The package as the title block names it.
PACKAGE = f"calc {__version__}"


def build_date() -> str:
    """Now, in UTC, to the minute.

    Returns
    -------
    str
        ``2025-01-31 14:05 UTC``.
    """
    return datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC")


def sha256(path: Path) -> str:
    """The SHA-256 of a file read.

    Parameters
    ----------
    path : pathlib.Path or str
        The file.

    Returns
    -------
    str
        Its digest, hexadecimal.
    """
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def git_commit(folder: Path | None = PROJECT_DIR) -> str:
    """The commit the package was built from, marked when calc/ or catalogs/ differ from it.

    Parameters
    ----------
    folder : pathlib.Path or None, optional
        The project's top folder (default :data:`calc.data.catalog.PROJECT_DIR`); None for an
        installed calc, which has no git tree.

    Returns
    -------
    str
        The commit's hash, or why there is none: a checkout that is not the top of its own git tree
        (an unpacked source archive inside another repository) is not under version control, as the
        enclosing repository's commit would name the wrong source.
    """
    if folder is None:
        return "none: an installed package, not a git checkout"
    try:
        head = subprocess.run(["git", "-C", str(folder), "rev-parse", "--show-toplevel", "HEAD"],
                              capture_output=True, text=True, check=True)
        dirty = subprocess.run(
            ["git", "-C", str(folder), "status", "--porcelain", "--untracked-files=no", "--", "calc", "catalogs"],
            capture_output=True, text=True, check=True,
        )
    except (OSError, subprocess.CalledProcessError):
        return "not under version control"
    top, commit = head.stdout.splitlines()
    if Path(top).resolve() != Path(folder).resolve():
        return "not under version control"
    return commit + (" (with uncommitted changes in calc/ or catalogs/)" if dirty.stdout.strip() else "")
