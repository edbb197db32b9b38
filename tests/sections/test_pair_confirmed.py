"""The pair the search picks is confirmed by the full evaluation (calc.sections.axis.confirmed): the
coupling chosen with its motor counts in λ, a pair refused gives way to the next in the rule's order,
and the motor every output names is the motor the case is checked with."""

import dataclasses

import pytest
from hypothesis import given, settings, strategies as st

from calc import Q_
from calc.review.inputs import with_inputs
from calc.sections import evaluate
from calc.sections.axis import AxisResult, confirmed
from calc.sections.case import read_case
from calc.sections.motor_catalog import motor_catalog, motor_ratings

from ..conftest import DERIVED_EXAMPLE


@pytest.fixture(scope="module")
def example():
    return read_case(DERIVED_EXAMPLE)


def with_table_inertia(case, J_table: float):
    """The example with the table's inertia [kg·cm²] as the review sets it."""
    return with_inputs(case, {"mechanism.inertia": Q_(J_table, "kg*cm**2")})


def by_hand(J_K: float, J_1: float, J_L: float, i: float, J_motor: float) -> float:
    """λ = (J_K + J_1 + J_L / i²) / J_motor, every inertia in kg·cm² (E6, the coupling on the motor
    shaft turning with it)."""
    return (J_K + J_1 + J_L / i ** 2) / J_motor


def test_at_1590_the_smallest_motor_is_confirmed_and_passes(example):
    r = evaluate(with_table_inertia(example, 1590))
    motor, dynamics = r["motor"], r["dynamics"]
    assert r.every["axis"].chosen == motor.selection.selected == "SGMUH-10DA"
    assert r["coupling"].selection.selected == "AKN-18"
    # AKN-18's J_K = 0.5, NPT035-10's J_1 = 0.93, i = 10, SGMUH-10DA's rotor 1.74 kg·cm²:
    # (0.5 + 0.93 + 15.9) / 1.74 = 17.33 / 1.74 = 9.960 <= 10.
    lam = by_hand(0.5, 0.93, 1590, 10, 1.74)
    assert lam == pytest.approx(9.95977, rel=1e-5)
    assert r.case.motor_inertia.m_as("kg*cm**2") == pytest.approx(1.74)
    assert dynamics.two_mass.inertia_ratio == pytest.approx(lam, rel=1e-9)
    assert motor.selection.candidates(1)[0].inertia_ratio == pytest.approx(lam, rel=1e-9)
    assert r.verdict.passes is True


def test_at_1600_the_pair_with_the_coupling_over_lambda_is_refused_and_the_next_taken(example):
    case = with_table_inertia(example, 1600)
    cat = motor_catalog(case)
    refused = AxisResult(dataclasses.replace(case, **motor_ratings(cat, cat.index("SGMUH-10DA", "test"))),
                         "SGMUH-10DA", "NPT035-10")
    # The screen counts the lightest candidate coupling; evaluated in full, SGMUH-10DA takes AKN-18 and
    # (0.5 + 0.93 + 16) / 1.74 = 17.43 / 1.74 = 10.017 > 10: its λ check fails, so the pair is refused.
    assert confirmed(refused) is False
    trial = refused.evaluated
    assert trial["coupling"].selection.selected == "AKN-18"
    first = trial["motor"].selection.candidates(1)[0]
    assert (first.part, first.passes) == ("SGMUH-10DA", False)
    assert first.inertia_ratio == pytest.approx(by_hand(0.5, 0.93, 1600, 10, 1.74), rel=1e-9)
    assert first.inertia_ratio == pytest.approx(10.01724, rel=1e-5)
    r = evaluate(case)
    # The next motor in the rule's order is HC53 (rotor 6.6 kg·cm²): it is the motor checked and named.
    assert r.every["axis"].chosen == r["motor"].selection.selected == "HC53"
    assert r.case.motor_inertia.m_as("kg*cm**2") == pytest.approx(6.6)
    # With HC53 no coupling passes (AKD-30 stands in, J_K = 1.0): λ = (1.0 + 0.93 + 16) / 6.6 = 2.717,
    # and the chain's first mode falls under 2 f_er: the case fails, as it did before the pair search.
    assert r["coupling"].selection.catalog.parts[r["coupling"].selection.order[0]] == "AKD-30"
    assert r["dynamics"].two_mass.inertia_ratio == pytest.approx(by_hand(1.0, 0.93, 1600, 10, 6.6), rel=1e-9)
    assert r.verdict.passes is False


@settings(max_examples=8, deadline=None)
@given(J_table=st.floats(200.0, 4000.0))
def test_every_output_names_the_motor_the_case_is_checked_with(example, J_table):
    r = evaluate(with_table_inertia(example, J_table))
    axis, sel = r.every["axis"], r["motor"].selection
    best = sel.candidates(1)[0]
    # The motor section ranks the case's motor first; it is the one selected unless it fails.
    assert best.part == axis.chosen
    assert sel.selected in (axis.chosen, None)
    assert (sel.selected is not None) == bool(best.passes)
    row = sel.catalog.index(axis.chosen, "test")
    assert r.case.motor_inertia.m_as("kg*cm**2") == pytest.approx(sel.catalog["J"][row].m_as("kg*cm**2"))
    assert r.case.motor_peak_torque == sel.catalog["M_max"][row]
    limit = r.case.motor_max_inertia_ratio[0]
    if r.verdict.passes:
        # A PASS never has a failing λ: neither the motor's check nor the dynamics' two-mass λ.
        assert best.inertia_ratio <= limit
        assert r["dynamics"].two_mass.inertia_ratio <= limit
        assert r["dynamics"].two_mass.inertia_ratio == pytest.approx(best.inertia_ratio, rel=1e-9)
