"""Springs in series referred to the output shaft (source, Torsional Stiffness; errata E11, E15)."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.domain.stiffness import (
    Chain,
    Component,
    angle_at_output,
    series_stiffness,
    stiffness_at_output,
    torque_at_output,
)

NM_ARCMIN = "N*m/arcmin"
stiff = st.floats(min_value=0.01, max_value=1e4)
ratios = st.floats(min_value=1.0, max_value=200.0)


def part(name, c, side="output", backlash=0.0, **more):
    return Component(name, side, Q_(c, NM_ARCMIN), Q_(backlash, "arcmin"), **more)


def test_source_example_on_the_output_side():
    # Source, "Torsional Stiffness": EPL-W-064 10:1 C = 1.3 N·m/arcmin, EKM-15 C = 0.24 N·m/arcmin,
    # 1/C_total = 1/1.3 + 1/0.24 -> 0.20 N·m/arcmin. By hand: 1 / (0.769231 + 4.166667) = 0.202597.
    chain = Chain((part("EKM-15", 0.24), part("EPL-W-064 10:1", 1.3)))
    assert chain.stiffness.m_as(NM_ARCMIN) == pytest.approx(0.202597, rel=1e-5)
    assert round(float(chain.stiffness.m_as(NM_ARCMIN)), 2) == 0.20


def test_source_example_with_the_coupling_on_the_motor_side():
    # E11: at the motor, the coupling is seen from the output as 0.24 · 10² = 24 N·m/arcmin;
    # 1 / (1/24 + 1/1.3) = 1 / (0.041667 + 0.769231) = 1.233196 N·m/arcmin ("about 1.23").
    chain = Chain((part("EKM-15", 0.24, side="input"), part("EPL-W-064 10:1", 1.3)), ratio=Q_(10, ""))
    assert chain.stiffness_at_output.m_as(NM_ARCMIN) == pytest.approx([24.0, 1.3])
    assert chain.stiffness.m_as(NM_ARCMIN) == pytest.approx(1.233196, rel=1e-5)


def test_series_formula_is_the_sources():
    assert series_stiffness.latex() == r"C_{\mathrm{total}} = \frac{1}{\sum_{k} \frac{1}{C_{k}}}"
    step = series_stiffness.step(C_k=Q_([1.3, 0.24], NM_ARCMIN))
    assert str(step) == "C_total = 0.2026 N·m/arcmin"


def test_reflection_through_the_ratio_by_hand():
    # A 2 arcmin backlash at the motor behind i = 8 is 0.25 arcmin at the output; 500 N·m/rad is 32 000 N·m/rad.
    assert angle_at_output(phi_1=Q_(2, "arcmin"), i=Q_(8, "")).m_as("arcmin") == pytest.approx(0.25)
    assert stiffness_at_output(C_1=Q_(500, "N*m/rad"), i=Q_(8, "")).m_as("N*m/rad") == pytest.approx(32000)
    assert torque_at_output(T_1=Q_(36, "N*m"), i=Q_(10, "")).m_as("N*m") == pytest.approx(360)
    chain = Chain((part("coupling", 0.5, side="input", backlash=2.0), part("gearbox", 20, backlash=3.0)),
                  ratio=Q_(8, ""))
    assert chain.backlash_at_output.m_as("arcmin") == pytest.approx([0.25, 3.0])
    assert chain.backlash.m_as("arcmin") == pytest.approx(3.25)


def test_shares_and_twist():
    chain = Chain((part("EKM-15", 0.24), part("EPL-W-064 10:1", 1.3)))
    # Compliances 4.16667 and 0.76923 arcmin/(N·m): shares 0.84416 and 0.15584; at 20 N·m, 83.33 and 15.38 arcmin.
    assert chain.compliance_shares == pytest.approx([0.84416, 0.15584], abs=1e-5)
    assert chain.twist(Q_(20, "N*m")).m_as("arcmin") == pytest.approx([83.3333, 15.3846], abs=1e-4)
    assert chain.twist(Q_(-20, "N*m")).m_as("arcmin").sum() == pytest.approx(20 / chain.stiffness.m_as(NM_ARCMIN))


def test_transmission_accuracy_and_nominal_torque_of_the_chain():
    gearbox = part("gearbox", 20, transmission_accuracy=Q_(60, "arcsec"), nominal_torque=Q_(81, "N*m"))
    motor_side = part("belt", 5, side="input", transmission_accuracy=Q_(100, "arcsec"), nominal_torque=Q_(5, "N*m"))
    chain = Chain((motor_side, part("coupling", 50), gearbox), ratio=Q_(10, ""))
    # 100 arcsec / 10 + 60 arcsec; the belt limits the output to 5 · 10 = 50 N·m < 81 N·m.
    assert chain.transmission_accuracy.m_as("arcsec") == pytest.approx(70)
    assert chain.transmission_accuracy_from == ["belt", "gearbox"]
    assert chain.nominal_torque.m_as("N*m") == pytest.approx(50)
    assert chain.nominal_torque_from == "belt"
    assert Chain((part("coupling", 50),)).nominal_torque is None


@given(st.lists(stiff, min_size=1, max_size=8))
def test_total_is_below_the_weakest_member(cs):
    chain = Chain(tuple(part(f"c{k}", c) for k, c in enumerate(cs)))
    total = chain.stiffness.m_as(NM_ARCMIN)
    assert total <= min(cs) * (1 + 1e-12)
    if len(cs) > 1:
        assert total < min(cs)
    assert chain.compliance_shares.sum() == pytest.approx(1.0)


@given(st.lists(stiff, min_size=1, max_size=6), stiff, st.sampled_from(["input", "output"]), ratios)
def test_adding_a_component_never_stiffens(cs, extra, side, i):
    chain = Chain(tuple(part(f"c{k}", c) for k, c in enumerate(cs)), ratio=Q_(i, ""))
    longer = chain.with_component(part("extra", extra, side=side))
    assert longer.stiffness.m_as(NM_ARCMIN) < chain.stiffness.m_as(NM_ARCMIN)


@given(stiff, ratios, st.floats(min_value=1.1, max_value=10))
def test_reflection_scales_with_the_square_of_the_ratio(c, i, k):
    a = stiffness_at_output(C_1=Q_(c, NM_ARCMIN), i=Q_(i, "")).m_as(NM_ARCMIN)
    b = stiffness_at_output(C_1=Q_(c, NM_ARCMIN), i=Q_(k * i, "")).m_as(NM_ARCMIN)
    assert b / a == pytest.approx(k**2)
    j = angle_at_output(phi_1=Q_(c, "arcmin"), i=Q_(i, "")).m_as("arcmin")
    assert j * i == pytest.approx(c)


@given(st.lists(stiff, min_size=1, max_size=5))
def test_same_answer_in_inch_pound_units(cs):
    metric = Chain(tuple(part(f"c{k}", c) for k, c in enumerate(cs))).stiffness
    inch = Chain(tuple(Component(f"c{k}", "output", Q_(c, NM_ARCMIN).to("lbf*in/deg"), Q_(0, "deg"))
                       for k, c in enumerate(cs))).stiffness
    assert inch.m_as(NM_ARCMIN) == pytest.approx(metric.m_as(NM_ARCMIN))


def test_series_evaluates_a_batch_of_chains_at_once():
    batch = series_stiffness(C_k=Q_(np.array([[0.24, 1.3], [24.0, 1.3]]), NM_ARCMIN)).m_as(NM_ARCMIN)
    assert batch == pytest.approx([0.202597, 1.233196], rel=1e-5)


@pytest.mark.parametrize(
    "make, fragment",
    [
        (lambda: Component("c", "output", Q_(0, NM_ARCMIN), Q_(0, "arcmin")),
         "expected a stiffness above zero, found 0"),
        (lambda: Component("c", "output", Q_(-1, NM_ARCMIN), Q_(0, "arcmin")), "above zero, found -1"),
        # E15: a torque is no stiffness, though pint would convert it (off by 3437.75).
        (lambda: Component("c", "output", Q_(0.24, "N*m"), Q_(0, "arcmin")),
         "which is a torque (its unit must carry the angle, errata E15)"),
        # E15: a bare number is no angle, though pint would read it as radians.
        (lambda: Component("c", "output", Q_(1, NM_ARCMIN), Q_(3, "")),
         "which is a bare number (its unit must carry the angle, errata E15)"),
        (lambda: Component("c", "output", Q_(1, NM_ARCMIN), 3), "expected an angle as a quantity"),
        (lambda: Component("c", "output", Q_(1, NM_ARCMIN), Q_(-1, "arcmin")),
         "backlash: expected an angle of zero or more"),
        (lambda: Component("c", "motor", Q_(1, NM_ARCMIN), Q_(0, "arcmin")),
         "side: expected input or output, found 'motor'"),
        (lambda: Component("c", "output", Q_(1, NM_ARCMIN), None), "backlash: expected an angle"),
        (lambda: Component("c", "output", Q_(1, NM_ARCMIN), Q_(0, "arcmin"), nominal_torque=Q_(0, "N*m")),
         "component 'c': nominal_torque: expected a torque above zero, found 0 "),
        (lambda: Chain(()), "expected at least one component"),
        (lambda: Chain((part("c", 1, side="input"),)), "sits on the input side"),
        (lambda: Chain((part("c", 1),), ratio=Q_(0, "")), "expected a ratio above zero"),
    ],
)
def test_bad_components_are_one_clear_error(make, fragment):
    with pytest.raises(CalcError, match="component|chain") as err:
        make()
    assert fragment in str(err.value)
    assert "\n" not in str(err.value)
