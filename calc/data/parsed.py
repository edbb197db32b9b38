"""Parsed catalogs kept on disk between runs, keyed by the file's content: a large catalog (a
maker's whole range, 10^5 rows) is read and validated once, and every later run that reads the
same bytes against the same schema with the same reader loads the arrays instead.

Only a catalog that loaded without an error is kept, so a bad cell gives the same one-sentence
error on every run. The folder is ``$CALC_CACHE_DIR`` (``off`` keeps nothing), else
``$XDG_CACHE_HOME/calc``, else ``~/.cache/calc``, and holds the :data:`KEPT` last, each a folder of
numpy's ``.npy`` files (arrays only, loaded without pickles and mapped from the file, not copied:
an archive's members were read and checksummed whole, 37 ms of a 40 ms load for 10^5 rows) and its
``meta.json``; one that cannot be read is read again from the catalog.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
from pathlib import Path

import numpy as np

#: Files at least this large are kept parsed [bytes]: a small catalog parses faster than it loads.
SMALLEST = 1_000_000

#: The most parsed catalogs kept; the least recently written go first.
KEPT = 16

#: What this module writes in the folder: a key's folder, one being written, an archive of an earlier form.
_KEPT_NAME = re.compile(r"[0-9a-f]{64}(\.\d+\.tmp)?(\.npz)?")

#: The reader's own source: a change to how a catalog is read makes every kept file stale.
_READER = hashlib.sha256(b"".join(p.read_bytes() for p in sorted(Path(__file__).parent.glob("*.py")))).hexdigest()


def cache_folder() -> Path | None:
    """Where parsed catalogs are kept; None where ``CALC_CACHE_DIR=off``.

    Returns
    -------
    pathlib.Path or None
        The folder (made when first written).
    """
    given = os.environ.get("CALC_CACHE_DIR")
    if given == "off":
        return None
    if given:
        return Path(given)
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "calc"


def cache_key(digest: str, schema) -> str:
    """The name a parsed catalog is kept under: the file's content (its SHA-256), the schema's columns
    and rules, and the reader's source.

    Parameters
    ----------
    digest : str
        The catalog file's SHA-256 in hex.
    schema : calc.data.catalog.Schema
        What it was read against.

    Returns
    -------
    str
        A SHA-256 in hex.
    """
    shape = repr((schema.kind, [(c.name, c.kind, c.required, c.positive, c.may_be_absent) for c in schema.columns],
                  schema.text_columns, schema.optional_text, [(r.text, r.column) for r in schema.rules],
                  schema.partial))
    h = hashlib.sha256(digest.encode())
    h.update(shape.encode())
    h.update(_READER.encode())
    return h.hexdigest()


def load_parsed(key: str) -> dict | None:
    """The arrays kept under ``key``, or None where there are none (or they cannot be read).

    Parameters
    ----------
    key : str
        :func:`cache_key`.

    Returns
    -------
    dict or None
        ``parts``, ``lines``, ``values`` (column -> (magnitudes, unit)), ``text`` (column -> array)
        and ``header_units``; text arrays of Python strings, as the reader makes them; the numbers
        read-only, mapped from the kept files.
    """
    folder = cache_folder()
    if folder is None or not (folder / key / "meta.json").is_file():
        return None
    kept = folder / key

    def array(name: str) -> np.ndarray:
        return np.asarray(np.load(kept / f"{name}.npy", mmap_mode="r", allow_pickle=False))

    try:
        meta = json.loads((kept / "meta.json").read_text())
        text = {name: array(f"text-{k}").astype(object)[array(f"code-{k}")] for k, name in enumerate(meta["text"])}
        values = {name: (array(f"value-{k}"), unit) for k, (name, unit) in enumerate(meta["units"])}
        return {"parts": array("parts").astype(object), "lines": array("lines"), "values": values, "text": text,
                "header_units": meta["header_units"]}
    except (OSError, ValueError, KeyError, TypeError, IndexError):  # damaged or foreign: read the catalog again,
        shutil.rmtree(kept, ignore_errors=True)  # and keep it afresh
        return None


def keep_parsed(key: str, parts, lines, values: dict, text: dict, header_units: dict) -> None:
    """Keep a catalog's arrays under ``key`` (written whole or not at all; nothing where the folder
    cannot be written).

    Parameters
    ----------
    key : str
        :func:`cache_key`.
    parts, lines : numpy.ndarray
        The parts and each row's line in the file.
    values : dict
        Column -> (magnitudes, unit text).
    text : dict
        Column -> array of strings.
    header_units : dict
        Column -> unit as the file writes it.

    Returns
    -------
    None
    """
    folder = cache_folder()
    if folder is None:
        return
    # Files are named by position, not by column: a column's name is the schema's, not a file name.
    meta = {"text": list(text), "units": [[name, unit] for name, (_, unit) in values.items()],
            "header_units": header_units}
    arrays = {"parts": np.asarray(parts, dtype=str), "lines": np.asarray(lines)}
    arrays |= {f"value-{k}": np.asarray(m, float) for k, (m, _) in enumerate(values.values())}
    for k, v in enumerate(text.values()):  # each distinct text once: a source or family repeats over the rows
        codes: dict = {}
        arrays[f"code-{k}"] = np.fromiter((codes.setdefault(x, len(codes)) for x in v), dtype=np.int32, count=len(v))
        arrays[f"text-{k}"] = np.array(list(codes), dtype=str)
    partial = folder / f"{key}.{os.getpid()}.tmp"
    try:
        partial.mkdir(parents=True)
        for name, a in arrays.items():
            np.save(partial / f"{name}.npy", a, allow_pickle=False)
        (partial / "meta.json").write_text(json.dumps(meta))  # last: a folder without it is never read
        partial.rename(folder / key)
        # The oldest go, in this form or an earlier one (an archive); nothing else in the folder is touched.
        entries = sorted((f for f in folder.iterdir() if _KEPT_NAME.fullmatch(f.name)),
                         key=lambda f: f.stat().st_mtime_ns)
        for old in entries[:-KEPT]:
            shutil.rmtree(old, ignore_errors=True) if old.is_dir() else old.unlink(missing_ok=True)
    except OSError:  # a read-only home, another run kept the same catalog first, or removed an entry meanwhile
        shutil.rmtree(partial, ignore_errors=True)
