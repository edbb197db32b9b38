"""Lost motion, positioning accuracy and repeatability (source, Lost Motion and Accuracy and
Repeatability; errata E11 to E13), and a measured positioning record."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.domain.accuracy import (
    analyze_positions,
    chain_accuracy,
    lost_motion,
    positioning_rule,
    positioning_accuracy,
    positioning_accuracy_high,
    positioning_accuracy_low,
    read_positions,
    repeatability,
)
from calc.domain.stiffness import Chain, Component

GEARBOX = Component("EPL-W-064 10:1", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin"), Q_(60, "arcsec"), Q_(40, "N*m"))
COUPLING = Component("EKM-15", "output", Q_(0.24, "N*m/arcmin"), Q_(0, "arcmin"))


def test_total_lost_motion_is_the_texts_formula():
    # Source, Lost Motion: Backlash + Applied Torque / Torsional Stiffness. 3 arcmin + 13 N·m / 1.3 N·m/arcmin = 13
    # arcmin.
    assert lost_motion(j_t=Q_(3, "arcmin"), T=Q_(13, "N*m"),
                       C=Q_(1.3, "N*m/arcmin")).m_as("arcmin") == pytest.approx(13.0)
    # The twist under a torque of either sign counts as its magnitude.
    assert lost_motion(j_t=Q_(3, "arcmin"), T=Q_(-13, "N*m"),
                       C=Q_(1.3, "N*m/arcmin")).m_as("arcmin") == pytest.approx(13.0)
    assert lost_motion.latex() == r"\varphi_{\mathrm{LM}} = j_{\mathrm{t}} + \frac{\left|{T}\right|}{C}"


def test_summed_over_components_it_is_the_chains():
    # Source: "Total lost motion can be calculated for each component and summed".
    chain = Chain((COUPLING, GEARBOX))
    t = Q_(20, "N*m")
    each = [lost_motion(j_t=c.backlash, T=t, C=c.stiffness).m_as("arcmin") for c in chain.components]
    assert sum(each) == pytest.approx(chain_accuracy(chain, t).lost_motion.m_as("arcmin"))
    # By hand: 0 + 3 + 20 / 0.202597 = 101.717 arcmin.
    assert sum(each) == pytest.approx(101.717, abs=1e-3)


def test_three_percent_rule_as_written():
    # E13, with T_N = 40 N·m: 3 % is 1.2 N·m. ATA 1 arcmin, backlash 3 arcmin, C 1.3 N·m/arcmin.
    args = dict(nominal_torque=Q_(40, "N*m"), transmission_accuracy=Q_(60, "arcsec"), backlash=Q_(3, "arcmin"),
                stiffness=Q_(1.3, "N*m/arcmin"))
    assert positioning_accuracy(Q_(1.2, "N*m"), **args).m_as("arcmin") == pytest.approx(1 + 3)  # at 3 %: ATA + backlash
    # above: ATA + T/C
    assert positioning_accuracy(Q_(1.3, "N*m"), **args).m_as("arcmin") == pytest.approx(1 + 1.3 / 1.3)
    assert positioning_accuracy(Q_(-26, "N*m"), **args).m_as("arcmin") == pytest.approx(1 + 20)
    batch = positioning_accuracy(Q_(np.array([0, 1.2, 2.6]), "N*m"), **args).m_as("arcmin")
    assert batch == pytest.approx([4, 4, 3])
    assert positioning_accuracy_low.latex() == r"\Delta\varphi_{\mathrm{P}} = j_{\mathrm{t}} + \varphi_{\mathrm{TA}}"
    high = r"\Delta\varphi_{\mathrm{P}} = \varphi_{\mathrm{TA}} + \frac{\left|{T}\right|}{C}"
    assert positioning_accuracy_high.latex() == high


@given(st.floats(min_value=0, max_value=0.03), st.floats(min_value=1, max_value=1e4))
def test_low_torque_is_at_most_three_percent(share, t_n):
    assert positioning_rule(Q_(share * t_n * (1 - 1e-12), "N*m"), Q_(t_n, "N*m")).low_torque
    assert not positioning_rule(Q_(0.0301 * t_n, "N*m"), Q_(t_n, "N*m")).low_torque


def test_the_rule_says_which_form_and_why():
    # E13 with T_N = 110 N·m: 3 % is 3.3 N·m. 3.3 N·m is on the line (the backlash form), 3.4 N·m above it;
    # 0.03 * 110 = 3.3000000000000003 in floats, and 3.3 N·m in mN·m back in N·m is within BOUNDARY_RTOL of it.
    t_n = Q_(110, "N*m")
    at = positioning_rule(Q_(3.3, "N*m"), t_n)
    assert at.low_torque and at.text == "|T| <= 3 % of T_N: phi_TA + j_t"
    assert at.why == "|T| = 3.3 N·m <= 3 % of T_N = 3.3 N·m"
    assert positioning_rule(Q_(3300, "mN*m"), t_n).low_torque
    above = positioning_rule(Q_(-3.4, "N*m"), t_n)
    assert not above.low_torque and above.text == "|T| > 3 % of T_N: phi_TA + |T| / C"
    assert above.why == "|T| = 3.4 N·m > 3 % of T_N = 3.3 N·m"
    # The step is the formula of the form that applies: 1 + 3 arcmin at 3.3 N·m, 1 + 3.4 / 1.7 = 3 arcmin at 3.4 N·m.
    args = (Q_(1, "arcmin"), Q_(3, "arcmin"), Q_(1.7, "N*m/arcmin"))
    assert at.step(*args).formula is positioning_accuracy_low and at.accuracy(*args).m_as("arcmin") == pytest.approx(4)
    assert above.step(*args).formula is positioning_accuracy_high
    assert above.accuracy(*args).m_as("arcmin") == pytest.approx(3)
    with pytest.raises(CalcError, match="nominal_torque: expected a torque above zero"):
        positioning_rule(Q_(1, "N*m"), Q_(0, "N*m"))


def test_repeatability_is_the_backlash_at_rest_and_bounded_by_lost_motion_under_torque():
    v, bound = repeatability(Q_(0, "N*m"), Q_(3, "arcmin"), Q_(1.3, "N*m/arcmin"))
    assert v.m_as("arcmin") == pytest.approx(3) and not bound
    v, bound = repeatability(Q_(13, "N*m"), Q_(3, "arcmin"), Q_(1.3, "N*m/arcmin"))
    assert v.m_as("arcmin") == pytest.approx(13) and bound


@given(st.floats(min_value=0, max_value=500), st.floats(min_value=0, max_value=10, allow_subnormal=False),
       st.floats(min_value=0.1, max_value=100))
def test_lost_motion_grows_with_torque_and_never_falls_below_the_backlash(t, j, c):
    a = lost_motion(j_t=Q_(j, "arcmin"), T=Q_(t, "N*m"), C=Q_(c, "N*m/arcmin")).m_as("arcmin")
    b = lost_motion(j_t=Q_(j, "arcmin"), T=Q_(t + 1, "N*m"), C=Q_(c, "N*m/arcmin")).m_as("arcmin")
    assert a >= j * (1 - 1e-12) and a < b  # (unit conversions round in the last digit)


def test_chain_accuracy_of_the_contract_example():
    # docs/case-format.md: EKM-15 and EPL-W-064 on the output side, 20 N·m; T_N 40 N·m from the gearbox.
    a = chain_accuracy(Chain((COUPLING, GEARBOX)), Q_(20, "N*m"))
    assert a.chain.stiffness.m_as("N*m/arcmin") == pytest.approx(0.202597, rel=1e-5)
    assert a.nominal_torque.m_as("N*m") == 40 and not a.low_torque
    # 1 arcmin + 20 / 0.202597 = 99.717 arcmin; repeatability at most the lost motion, 101.717 arcmin.
    assert a.positioning_accuracy.m_as("arcmin") == pytest.approx(99.717, abs=1e-3)
    assert a.repeatability.m_as("arcmin") == pytest.approx(101.717, abs=1e-3) and a.repeatability_is_bound
    assert [s.formula.name for s in a.steps()] == ["C_total", "phi_LM", "Delta_phi_P_high"]
    at_rest = chain_accuracy(Chain((COUPLING, GEARBOX)), Q_(0, "N*m"))
    assert at_rest.positioning_accuracy.m_as("arcmin") == pytest.approx(4)
    assert at_rest.repeatability.m_as("arcmin") == pytest.approx(3)


def test_chain_without_a_nominal_torque():
    chain = Chain((COUPLING,))
    assert chain_accuracy(chain, Q_(0, "N*m")).low_torque
    with pytest.raises(CalcError,
                       match=r"nominal_torque: the 3 % rule of positioning accuracy \(E13\) needs the nominal torque"):
        chain_accuracy(chain, Q_(5, "N*m"))
    assert not chain_accuracy(chain, Q_(5, "N*m"), nominal_torque=Q_(100, "N*m")).low_torque
    with pytest.raises(CalcError, match=r"^nominal_torque: expected a torque above zero, found 0 "):
        chain_accuracy(chain, Q_(5, "N*m"), nominal_torque=Q_(0, "N*m"))


def test_measured_positions_by_hand():
    # Two targets, three approaches each. Errors (arcmin): 0°: +0.6, +1.2, +0.9; 90°: -0.3, +0.3, +1.5.
    target = Q_([0, 0, 0, 90, 90, 90], "deg")
    actual = target + Q_([0.6, 1.2, 0.9, -0.3, 0.3, 1.5], "arcmin")
    r = analyze_positions(target, actual)
    assert r.accuracy.m_as("arcmin") == pytest.approx(1.5)  # the largest |error|
    assert r.repeatability.m_as("arcmin") == pytest.approx(1.8)  # 90°: 1.5 - (-0.3)
    assert r.targets == 2
    with pytest.raises(CalcError, match="expected each target approached at least twice, found target 90° once"):
        analyze_positions(Q_([0, 0, 90], "deg"), Q_([0, 0, 90], "deg"))
    # Three targets and two actual positions: checked before the error formula broadcasts them.
    with pytest.raises(CalcError) as err:
        analyze_positions(Q_([0, 0, 90], "deg"), Q_([0, 0], "deg"), source="positions.csv")
    assert str(err.value) == (
        "positions.csv: expected target and actual as two arrays of one length, found shapes (3,) and (2,)"
    )


def test_positions_file(tmp_path):
    path = tmp_path / "positions.csv"
    path.write_text("# indexing table, 3 approaches to each station\ntarget [deg],actual "
                    "[deg]\n0,0.01\n0,0.02\n0,0.015\n90,90.01\n90,89.99\n90,90\n")
    r = read_positions(path)
    assert r.accuracy.m_as("arcmin") == pytest.approx(1.2) and r.repeatability.m_as("arcmin") == pytest.approx(1.2)
    path.write_text("target [deg],actual [1]\n0,0\n")
    with pytest.raises(CalcError, match="column actual: expected a unit of angle"):
        read_positions(path)


@settings(max_examples=30, deadline=None)
@given(st.floats(0.5, 100), st.floats(0, 20), st.floats(0, 300), st.floats(-100, 100))
def test_error_budget_adds_up_to_the_positioning_accuracy(stiffness, backlash, ta_arcsec, torque):
    from calc.domain.accuracy import error_budget

    g = Component("g", "output", Q_(stiffness, "N*m/arcmin"), Q_(backlash, "arcmin"), Q_(ta_arcsec, "arcsec"),
                  Q_(110, "N*m"))
    a = chain_accuracy(Chain((g,)), Q_(torque, "N*m"))
    b = error_budget(a)
    # The worst case is the positioning accuracy (E13), the RSS never more, the shares sum to one.
    pa = a.positioning_accuracy.m_as("arcmin")
    assert b.worst_case.result.m_as("arcmin") == pytest.approx(pa, rel=1e-9, abs=1e-12)
    assert b.rss.result.m_as("arcmin") <= b.worst_case.result.m_as("arcmin") * (1 + 1e-12) + 1e-12
    assert [c.kind for c in b.contributions] == ["systematic", "random"]
    # Repeatability: never above the lost motion, nor above the positioning accuracy under torque.
    r = a.repeatability_bound.m_as("arcmin")
    assert r <= a.lost_motion.m_as("arcmin") * (1 + 1e-12)
    if torque != 0:
        assert r <= a.positioning_accuracy.m_as("arcmin") * (1 + 1e-12) + 1e-12
