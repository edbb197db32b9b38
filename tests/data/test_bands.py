"""Factor tables by band (calc.data.bands): the shock factor (E4) and the temperature factor (E9) share
one lookup, one boundary tolerance and one band text."""

import math

import numpy as np
import pytest

from calc import CalcError, Q_
from calc.data.bands import BandTable
from calc.core.checks import BOUNDARY_RTOL
from calc.domain.coupling import TEMPERATURE_FACTORS, temperature_factor
from calc.domain.gearbox import SHOCK_FACTORS, shock_factor

# Each boundary of each table, with the factors below and at it (E4 and E9: the higher at a boundary).
BOUNDARIES = [
    (SHOCK_FACTORS, "1/h", 1000, 1.0, 1.1),
    (SHOCK_FACTORS, "1/h", 1500, 1.1, 1.3),
    (SHOCK_FACTORS, "1/h", 2000, 1.3, 1.6),
    (SHOCK_FACTORS, "1/h", 3000, 1.6, 2.0),
    (TEMPERATURE_FACTORS, "degC", 50, 1.0, 1.3),
    (TEMPERATURE_FACTORS, "degC", 70, 1.3, 1.6),
    (TEMPERATURE_FACTORS, "degC", 90, 1.6, 1.8),
    (TEMPERATURE_FACTORS, "degC", 110, 1.8, 2.0),
]


@pytest.mark.parametrize("table, unit, boundary, below, at", BOUNDARIES)
def test_both_tables_apply_the_same_boundary_tolerance(table, unit, boundary, below, at):
    # A tenth of BOUNDARY_RTOL below a boundary is rounding, so on it; a millionth below is below it.
    on = Q_(boundary * (1 - BOUNDARY_RTOL / 10), unit)
    under = Q_(boundary * (1 - 1e-6), unit)
    assert table.lookup(on).tolist() == at and table.lookup(under).tolist() == below


def test_the_public_functions_are_the_tables():
    # shock_factor and temperature_factor are the tables' lookups: the same factors over a sweep.
    z = Q_(np.linspace(0, 5000, 501), "1/h")
    t = Q_(np.linspace(-40, 120, 321), "degC")
    np.testing.assert_array_equal(shock_factor(z), SHOCK_FACTORS.lookup(z))
    np.testing.assert_array_equal(temperature_factor(t), TEMPERATURE_FACTORS.lookup(t))


def test_lookup_is_vectorized_and_band_gives_the_index():
    # 500, 1000, 1800, 2999, 3000 per hour fall in bands 0, 1, 2, 3, 4 (E4).
    z = Q_([500, 1000, 1800, 2999, 3000], "1/hour")
    assert SHOCK_FACTORS.band(z).tolist() == [0, 1, 2, 3, 4]
    assert SHOCK_FACTORS.lookup(z).tolist() == [1.0, 1.1, 1.3, 1.6, 2.0]
    assert int(TEMPERATURE_FACTORS.band(Q_(95, "degC"))) == 3


def test_band_text():
    # The E4 and E9 readings, band by band, as the report and the plots print them.
    assert [SHOCK_FACTORS.text(k) for k in range(5)] == [
        "0 <= Z_h < 1000 1/h", "1000 <= Z_h < 1500 1/h", "1500 <= Z_h < 2000 1/h", "2000 <= Z_h < 3000 1/h",
        "Z_h >= 3000 1/h",
    ]
    assert [TEMPERATURE_FACTORS.text(k) for k in range(5)] == [
        "T < 50 °C", "50 <= T < 70 °C", "70 <= T < 90 °C", "90 <= T < 110 °C", "110 <= T <= 120 °C",
    ]
    # The symbol as calc.core.glossary typesets it.
    assert SHOCK_FACTORS.text(2, latex=True) == r"1500 \le Z_{\mathrm{h}} < 2000\ \text{1/h}"


def test_values_outside_the_table_name_the_argument():
    with pytest.raises(CalcError, match=r"^cycles_per_hour: expected Z_h >= 0 1/h .*, found -5 1/h$"):
        shock_factor(Q_(-5, "1/hour"))
    with pytest.raises(CalcError, match=r"^temperature: expected T <= 120 °C .*, found 130 °C$"):
        TEMPERATURE_FACTORS.band(Q_([20, 130], "degC"), "temperature")
    with pytest.raises(CalcError, match="cycles_per_hour"):
        shock_factor(Q_(3, "s"))


def test_a_table_must_rise_and_have_a_factor_per_band():
    with pytest.raises(CalcError, match="one factor per band"):
        BandTable("x", (0, 1), (1.0,), "1/h", "per_hour", "a table")
    with pytest.raises(CalcError, match="bounds that rise"):
        BandTable("x", (0, 2, 1), (1.0, 1.1, 1.2), "1/h", "per_hour", "a table")
    with pytest.raises(CalcError, match="bounds that rise"):
        BandTable("T", (-math.inf, 50.0), (1.0, 1.3), "degC", "temperature", "a table", top=40.0)
