"""One typesetter for every output: the calc report's prose (criteria, reasons, notes) prints a
symbol as the formulas print it in the calculations (calc.core.glossary), so ``T_1B`` is one
``T_{\\mathrm{1B}}`` on every page."""

import pytest

from calc.core.glossary import SYMBOLS
from calc.report.symbols import latex, tokens


def prose_names():
    """The declared names the prose reads as one symbol (a name such as ``J_L_linear`` is code, not
    prose)."""
    return sorted(n for n in SYMBOLS if len(tokens(n)) == 1 and tokens(n)[0][0] == "symbol")


def test_the_prose_reads_most_names_as_symbols():
    assert len(prose_names()) > 80 and {"T_1B", "T_2max", "J_motor", "n_2k", "lambda", "phi_TA"} <= set(prose_names())


@pytest.mark.parametrize("name", prose_names())
def test_a_criterion_prints_a_symbol_as_its_formula_does(name):
    assert latex(name) == f"${SYMBOLS[name].latex}$"


def test_the_example_of_the_two_typesetters():
    # The PDF printed T_{1B} in its calculations and T_{\mathrm{1B}} in its criteria.
    from calc.domain.gearbox import T_2stop

    assert T_2stop.latex() == r"T_{\mathrm{2stop}} = T_{\mathrm{1B}} \cdot i"
    assert latex("T_2stop <= T_2Not") == r"$T_{\mathrm{2stop}}$ ≤ $T_{\mathrm{2Not}}$"
