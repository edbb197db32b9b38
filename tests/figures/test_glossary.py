"""The glossary: the source's index and symbol tables, and the symbols of every formula."""

import calc.domain.gearbox  # noqa: F401  (defines the gearbox formulas)
import calc.domain.profile  # noqa: F401  (defines the duty-cycle and S1 formulas)
from calc.core.formula import REGISTRY
from calc.figures.glossary import source_index_table, source_symbols_table, symbols_table


def test_source_tables_as_printed():
    # The source document's index table has 10 rows, its symbol table 9 (section "Determination of the Duty Cycle").
    index = source_index_table()
    assert index["index"].tolist() == ["1", "2", "a", "B", "c", "d", "m", "max", "n", "p"]
    symbols = source_symbols_table()
    assert symbols["symbol (source)"].tolist() == ["ED", "fs", "i", "J", "n", "t", "T", "Zh", "η"]
    assert symbols["unit (source)"].tolist() == ["%", "-", "-", "kg-cm ²", "RPM", "s", "Nm", "-", "%"]


def test_symbols_table_lists_every_symbol_once():
    table = symbols_table()
    names = {s.name for f in REGISTRY for s in (f.result, *f.inputs)}
    assert set(table.symbol) == names
    assert not table.duplicated(["symbol", "unit", "description"]).any()
    row = table[table.symbol == "i"].iloc[0]
    # The ratio appears in n_1 = n_2 · i, T_2max = T_1B · i · f_s · η and the inertia ratio.
    assert row.unit == "–" and {"n_1", "T_2max", "lambda"} <= set(row.formulas.split(", "))
    assert table[table.symbol == "J_L"].unit.iloc[0] == "kg·cm²"
