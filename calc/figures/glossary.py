"""The glossary: the source document's index and symbol tables, and every symbol of the formulas.

The source prints two tables before its formulas: the index (what a subscript means) and the
symbols with their units. :data:`SOURCE_INDEX` and :data:`SOURCE_SYMBOLS` hold them as printed,
with the unit and notation the workbook uses beside them; :func:`symbols_table` lists every symbol
of the formulas defined so far (:data:`calc.core.formula.REGISTRY`) as :mod:`calc.core.glossary`
declares it, so the glossary grows with the formulas and is never typed twice.
"""

from __future__ import annotations

from ..core.formula import REGISTRY
from ..core.glossary import SYMBOLS
from ..core.units import pretty_unit

#: The source's index table: subscript, meaning, and where the workbook uses it.
SOURCE_INDEX = (
    ("1", "input", "n_1, n_1N, n_1max, T_1B, J_1"),
    ("2", "output", "n_2, n_2m, n_2max, T_2, T_2m, T_2N, T_2B, T_2max"),
    ("a", "acceleration", "t_a: an accel segment"),
    ("B", "maximum acceleration", "T_2B (gearbox rating), T_1B (motor peak torque)"),
    ("c", "constant", "t_c: a const segment"),
    ("d", "deceleration", "t_d: a decel segment"),
    ("m", "mean", "n_2m, T_2m"),
    ("max", "maximum", "n_1max, n_2max, T_2max"),
    ("n", "nominal", "written N as makers print it: n_1N, T_2N (E1)"),
    ("p", "pause", "a pause segment"),
)

#: The source's symbol table as printed (symbol, unit, description), then the workbook's notation,
#: its unit and what differs.
SOURCE_SYMBOLS = (
    ("ED", "%", "Duty Cycle", "ED", "%", "t_on / t_cycle (E3)"),
    ("fs", "-", "Shock Factor", "f_s", "–", "table against Z_h, the higher factor at a boundary (E4)"),
    ("i", "-", "Ratio", "i", "–", ""),
    ("J", "kg-cm ²", "Moment of Inertia", "J", "kg·cm²", "kg·cm² in catalogs (E14)"),
    ("n", "RPM", "Speed", "n", "rpm",
     "a speed carries its angle: 300 rpm is 5 revolutions per second, not 31.4 Hz (E15)"),
    ("t", "s", "Time", "t", "s", ""),
    ("T", "Nm", "Torque", "T", "N·m", ""),
    ("Zh", "-", "Number of Cycles", "Z_h", "1/h", "load cycles (moves) per hour, Z_h = 3600 s · z_c / t_cycle (E16)"),
    ("η", "%", "Efficiency", "η", "– (catalog: %)", "a fraction in the formulas; catalogs give it in %"),
)


def source_index_table():
    """The source's index table.

    Returns
    -------
    pandas.DataFrame
        Columns ``index``, ``meaning``, ``used in``.

    Examples
    --------
    >>> source_index_table().iloc[3, :2].tolist()
    ['B', 'maximum acceleration']
    """
    import pandas as pd

    return pd.DataFrame(SOURCE_INDEX, columns=["index", "meaning", "used in"])


def source_symbols_table():
    """The source's symbol table beside the workbook's notation, as a pandas DataFrame.

    Returns
    -------
    pandas.DataFrame
        One row per symbol.

    Examples
    --------
    >>> source_symbols_table().iloc[4, :5].tolist()
    ['n', 'RPM', 'Speed', 'n', 'rpm']
    """
    import pandas as pd

    columns = ["symbol (source)", "unit (source)", "description", "symbol (workbook)", "unit (workbook)", "note"]
    return pd.DataFrame(SOURCE_SYMBOLS, columns=columns)


def symbols_table(formulas=None):
    """Every symbol of ``formulas`` (default: all formulas defined so far), in order of first use,
    once each, as :data:`calc.core.glossary.SYMBOLS` declares it.

    Columns: ``symbol`` (its name in code), ``LaTeX`` (``$...$``), ``description``, ``unit`` (the
    unit it is declared with; ``–`` for a pure number), ``kind`` (what :mod:`calc.core.units` checks
    it for), ``per segment`` (one value per profile segment) and ``formulas`` (the formulas it
    appears in, by the name of their result).

    Parameters
    ----------
    formulas : iterable of Formula, optional
        The formulas whose symbols to list; default all defined so far.

    Returns
    -------
    pandas.DataFrame
        One row per symbol.

    Examples
    --------
    >>> from calc.domain import profile
    >>> t = symbols_table([profile.T_2m])
    >>> t[["symbol", "unit", "kind", "formulas"]].values.tolist()[:2]
    [['T_2m', 'N·m', 'torque', 'T_2m'], ['n_2k', 'rpm', 'speed', 'T_2m']]
    """
    import pandas as pd

    rows: dict[str, dict] = {}
    for f in REGISTRY if formulas is None else formulas:
        for shown in (f.result, *f.inputs):
            s = SYMBOLS.get(shown.name, shown)  # a formula made outside the package may use its own
            row = rows.setdefault(
                s.name,
                {
                    "symbol": s.name,
                    "LaTeX": f"${s.latex}$",
                    "description": s.description,
                    "unit": pretty_unit(s.unit) or "–",
                    "kind": s.kind,
                    "per segment": s.per_segment,
                    "formulas": [],
                },
            )
            if f.name not in row["formulas"]:
                row["formulas"].append(f.name)
    table = pd.DataFrame(list(rows.values()),
                         columns=["symbol", "LaTeX", "description", "unit", "kind", "per segment", "formulas"])
    table["formulas"] = table["formulas"].map(", ".join)
    return table
