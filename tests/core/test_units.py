"""The unit registry and the guards against pint's angle traps (errata E14, E15)."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from calc import CalcError, Q_, ureg
from calc.core.units import (KINDS, angle_power, as_kind, latex_unit, parse_quantity, pretty_unit,
                             revolutions_per_second, sig)


def test_one_application_registry():
    import pint

    assert pint.get_application_registry().get() is ureg or pint.get_application_registry() is ureg


def test_a_unit_text_is_parsed_once_to_what_pint_parses():
    import pint

    fresh = pint.UnitRegistry()  # pint's own parse, kept nowhere
    parse = ureg._parse_units_as_container
    for text in ("N*m", "kg*cm**2", "N*m/arcmin", "lbf*in", "rev/min"):
        before = parse.cache_info().hits
        first, again = parse(text), parse(text)
        assert again is first and parse.cache_info().hits == before + 1
        if text != "rev/min":  # the alias is the package's own
            assert dict(first) == dict(fresh.parse_units_as_container(text))
    # 1 lbf·in = 0.1129848290276167 N·m (4.4482216152605 N x 0.0254 m), every time it is converted
    assert [Q_(1.0, "lbf*in").m_as("N*m") for _ in range(3)] == [pytest.approx(0.1129848290276167, rel=1e-15)] * 3


@pytest.mark.parametrize(
    "text, kind, unit, value",
    [
        ("300 rpm", "speed", "rpm", 300.0),
        ("1.2 kg*cm**2", "inertia", "kg*m**2", 1.2e-4),  # 1 kg·cm² = 1e-4 kg·m²
        ("1.3 N*m/arcmin", "stiffness", "N*m/rad", 1.3 * 10800 / math.pi),  # E14: 1 N·m/arcmin = 10800/π N·m/rad
        ("60 arcsec", "angle", "arcmin", 1.0),
        ("40 Hz", "frequency", "Hz", 40.0),
        ("1.00 in", "length", "mm", 25.4),
        ("0.2 s", "time", "ms", 200.0),
        ("12 N*m", "torque", "N*m", 12.0),
        ("106.2 lbf*in", "torque", "N*m", 106.2 * 0.1129848290276167),
    ],
)
def test_parse_quantity_converts(text, kind, unit, value):
    assert parse_quantity(text, kind, "k").m_as(unit) == pytest.approx(value, rel=1e-12)


def test_stiffness_conversion_factor_e14():
    # E14: 1 N·m/arcmin = 10800/π ≈ 3437.75 N·m/rad.
    assert Q_(1, "N*m/arcmin").m_as("N*m/rad") == pytest.approx(3437.7467707849396, rel=1e-12)


@pytest.mark.parametrize(
    "text, kind, fragment",
    [
        ("0.24 N*m", "stiffness", "a torque"),  # E15 (a): a torque accepted as a stiffness
        ("3", "angle", "bare number"),  # E15 (a): a bare number read as radians
        (3, "angle", "bare number"),
        ("300 rpm", "frequency", "a speed"),  # E15 (b): rpm silently turned into Hz
        ("5 Hz", "speed", "a frequency"),
        ("12 N", "torque", "a force"),  # a force given for a torque
        ("3 arcmin", "speed", "an angle"),  # an angle given for a speed
        ("12 N*m", "time", "a torque"),
    ],
)
def test_wrong_kind_is_one_clear_error(text, kind, fragment):
    with pytest.raises(CalcError) as err:
        parse_quantity(text, kind, "case.toml: key")
    message = str(err.value)
    assert message.startswith("case.toml: key: expected")
    assert fragment in message
    assert "\n" not in message


@pytest.mark.parametrize("text",
                         ["12 N*mm*", "12 furlongs_per_blip", "N*m", "12 N*m; import os", "__import__('os')", ""])
def test_unparseable_values_are_errors_not_tracebacks(text):
    with pytest.raises(CalcError):
        parse_quantity(text, "torque", "k")


def test_bare_number_only_where_dimensionless():
    assert parse_quantity(10, "dimensionless", "ratio").m_as("") == 10
    with pytest.raises(CalcError, match="bare number"):
        parse_quantity(12, "torque", "motor.peak_torque")


def test_offset_temperature_is_built_not_multiplied():
    # E15: "60 degC" must be a temperature of 60 °C (333.15 K), not 60 × 1 °C.
    q = ureg.Quantity(60.0, ureg.parse_units("degC"))
    assert q.to("K").magnitude == pytest.approx(333.15)


def test_speed_to_rotational_frequency_e15():
    # A shaft at 300 rpm turns 5 times a second; pint alone says 31.4 Hz.
    assert Q_(300, "rpm").to("Hz").magnitude == pytest.approx(10 * math.pi)  # the trap, documented
    assert revolutions_per_second(Q_(300, "rpm")).m_as("Hz") == pytest.approx(5.0)
    with pytest.raises(CalcError):
        revolutions_per_second(Q_(5, "Hz"))


def test_angle_power():
    assert angle_power(ureg.parse_units("rpm")) == 1
    assert angle_power(ureg.parse_units("N*m/arcmin")) == -1
    assert angle_power(ureg.parse_units("N*m")) == 0


def test_as_kind_names_the_argument_for_a_bare_float():
    with pytest.raises(CalcError, match=r"^T_1B: expected a torque as a quantity"):
        as_kind(12.0, "torque", "T_1B")


def test_as_kind_accepts_arrays():
    q = as_kind(Q_(np.array([1.0, 2.0]), "N*m"), "torque", "x")
    assert q.shape == (2,)


@given(st.floats(min_value=1e-3, max_value=1e5, allow_nan=False))
def test_metric_and_inch_inertia_agree(x):
    # 1 lb·in² = 2.9264 kg·cm² (0.45359237 kg × 2.54² cm²).
    lbin2 = parse_quantity(f"{x!r} lb*in**2", "inertia", "k")
    assert lbin2.m_as("kg*cm**2") == pytest.approx(x * 0.45359237 * 2.54**2, rel=1e-12)


def test_formatting():
    assert sig(35.40764860744718) == "35.41"
    assert pretty_unit("kg*cm**2") == "kg·cm²"
    assert latex_unit("N*m/arcmin") == r"\mathrm{N\,m/arcmin}"


_UNITS = {
    "speed": ("rpm", "rad/s", "deg/s", "rev/s"),
    "per_hour": ("1/hour", "1/min", "1/s"),
    "torque": ("N*m", "lbf*in", "kN*m"),
    "dimensionless": ("", "percent"),
    "temperature": ("degC", "K", "degF"),
}


@given(
    kind_and_unit=st.sampled_from([(k, u) for k, units in _UNITS.items() for u in units]),
    x=st.floats(-1e6, 1e6, allow_nan=False),
)
def test_to_si_and_from_si_convert_exactly_as_pint_does(kind_and_unit, x):
    # The cached factor is pint's own, so the numbers are pint's to the last bit (offsets, °C, go through pint).
    from calc.core.units import KINDS, from_si, to_si

    name, unit_text = kind_and_unit
    si = KINDS[name].si_unit
    assert to_si(Q_(x, unit_text), name, "x") == Q_(x, unit_text).m_as(si)
    assert from_si(x, name, unit_text).m_as(unit_text) == Q_(x, si).to(unit_text).magnitude
    array = np.array([x, 2 * x])
    np.testing.assert_array_equal(to_si(Q_(array, unit_text), name, "x"), Q_(array, unit_text).m_as(si))


def test_to_si_checks_the_kind_as_as_kind_does():
    from calc.core.units import to_si

    with pytest.raises(CalcError, match="T: expected a speed such as"):
        to_si(Q_(300, "Hz"), "speed", "T")
    with pytest.raises(CalcError, match="expected a torque as a quantity with a unit"):
        to_si(12.0, "torque", "T")
    assert to_si(10, "dimensionless", "i") == 10.0


@pytest.mark.parametrize(
    "value, shown",
    [
        (True, "True"),  # TOML `peak_torque = true`: a bool is an int to Python, but no torque
        (["12 N*m"], "['12 N*m']"),  # TOML `peak_torque = ["12 N*m"]`
        ({"value": 12}, "{'value': 12}"),  # TOML `peak_torque = {value = 12}`
    ],
)
def test_a_value_that_is_no_text_or_number_is_named(value, shown):
    with pytest.raises(CalcError) as err:
        parse_quantity(value, "torque", "motor.peak_torque")
    assert str(err.value) == f'motor.peak_torque: expected a torque such as "12 N*m", found {shown}'


def test_a_quantity_of_another_registry_is_refused():
    # pint refuses to mix registries deep inside a formula; the message names the argument first.
    import pint

    with pytest.raises(CalcError) as err:
        as_kind(pint.UnitRegistry().Quantity(12, "N*m"), "torque", "T_1B")
    assert str(err.value).startswith("T_1B: the quantity 12 meter * newton was made with another unit registry")
    assert "use calc.ureg or calc.Q_" in str(err.value)


@pytest.mark.parametrize("name", sorted(KINDS))
def test_every_kinds_example_is_an_input_of_that_kind(name):
    # Error messages offer the example ("expected a rate such as ..."): it must itself be accepted.
    k = KINDS[name]
    parse_quantity(k.example.strip('"'), k, f"example of {name}")


def test_quantities_print_their_units_in_the_order_written():
    # Error messages print quantities with "~P": a torque reads N·m as engineers write it, also
    # when it comes out of arithmetic (pint sorts alphabetically by default: "m·N").
    assert f"{Q_(-1, 'N*m'):~P}" == "-1 N·m"
    assert f"{Q_(2, 'N') * Q_(3, 'm'):~P}" == "6 N·m"
    assert f"{Q_(1.3, 'N*m/arcmin'):~P}" == "1.3 N·m/arcmin"


def test_the_unit_cache_belongs_to_this_environment():
    # pint's shared cache (":auto:") records the definition files of the environment that wrote
    # it; a second environment of the same pint then reads those, and breaks once the first is
    # deleted. The package keeps the cache inside its own environment (or none where read-only).
    import sys
    from pathlib import Path

    from calc.core.units import _cache_folder, ureg

    folder = _cache_folder()
    assert folder is None or folder.is_relative_to(Path(sys.prefix))
    assert ureg._diskcache is None or Path(ureg._diskcache.cache_folder) == folder


def test_a_kind_declared_twice_is_refused():
    # A dict built from the declarations kept the last of two "angular_acceleration" kinds silently.
    from calc.core.units import Kind, declared_once

    twice = (Kind("speed", "1/[time]", 1, "rad/s", '"300 rpm"'), Kind("speed", "1/[time]", 1, "rad/s", '"3 rpm"'))
    with pytest.raises(ValueError, match="the kind 'speed' is declared twice"):
        declared_once(twice, "kind")
