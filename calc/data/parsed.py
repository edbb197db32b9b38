"""Parsed catalogs kept on disk between runs, keyed by the file's content: a large catalog (a
maker's whole range, 10^5 rows) is read and validated once, and every later run that reads the
same bytes against the same schema with the same reader loads the arrays instead.

Only a catalog that loaded without an error is kept, so a bad cell gives the same one-sentence
error on every run. The folder is ``$CALC_CACHE_DIR`` (``off`` keeps nothing), else
``$XDG_CACHE_HOME/calc``, else ``~/.cache/calc``, and holds the :data:`KEPT` last; a file there is
arrays only (``numpy.load`` without pickles), and one that cannot be read is read again from the
catalog.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path

import numpy as np

#: Files at least this large are kept parsed [bytes]: a small catalog parses faster than it loads.
SMALLEST = 1_000_000

#: The most parsed catalogs kept; the least recently written go first.
KEPT = 16

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


def cache_key(raw: bytes, schema) -> str:
    """The name a parsed catalog is kept under: the file's bytes, the schema's columns and rules,
    and the reader's source.

    Parameters
    ----------
    raw : bytes
        The catalog file's content.
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
    h = hashlib.sha256(raw)
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
        and ``header_units``; text arrays of Python strings, as the reader makes them.
    """
    folder = cache_folder()
    if folder is None or not (folder / f"{key}.npz").is_file():
        return None
    try:
        with np.load(folder / f"{key}.npz", allow_pickle=False) as kept:
            meta = json.loads(str(kept["meta"]))
            text = {name: kept[f"text:{name}"].astype(object)[kept[f"code:{name}"]] for name in meta["text"]}
            values = {name: (kept[f"value:{name}"], unit) for name, unit in meta["units"].items()}
            return {"parts": kept["parts"].astype(object), "lines": kept["lines"], "values": values, "text": text,
                    "header_units": meta["header_units"]}
    except (OSError, ValueError, KeyError):  # a damaged or foreign file: read the catalog again
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
    meta = {"text": list(text), "units": {name: unit for name, (_, unit) in values.items()},
            "header_units": header_units}
    arrays = {"meta": np.array(json.dumps(meta)), "parts": np.asarray(parts, dtype=str), "lines": np.asarray(lines)}
    arrays |= {f"value:{name}": np.asarray(m, float) for name, (m, _) in values.items()}
    for name, v in text.items():  # each distinct text once: a source or family repeats over the rows
        codes: dict = {}
        arrays[f"code:{name}"] = np.fromiter((codes.setdefault(x, len(codes)) for x in v), dtype=np.int64, count=len(v))
        arrays[f"text:{name}"] = np.array(list(codes), dtype=str)
    try:
        folder.mkdir(parents=True, exist_ok=True)
        partial = folder / f"{key}.{os.getpid()}.tmp.npz"
        np.savez(partial, **arrays)
        partial.replace(folder / f"{key}.npz")
        kept = sorted(folder.glob("*.npz"), key=lambda f: f.stat().st_mtime_ns)
        for old in kept[:-KEPT]:
            old.unlink(missing_ok=True)
    except OSError:  # a read-only home: every run reads the catalog
        return
