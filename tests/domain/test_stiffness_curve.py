"""Piecewise torsional stiffness (calc.domain.stiffness.StiffnessCurve): three slopes K1, K2, K3 with limit
torques T1, T2, as strain-wave gear makers publish them; a chain with such a member; the case key
``stiffness_curve``; one-line errors."""

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.domain.accuracy import chain_accuracy
from calc.domain.stiffness import Chain, Component, StiffnessCurve

from ..conftest import HEAD_TOML, PROFILE_TOML, run


def hfuc_32_100(K_3=1.2e5):
    return StiffnessCurve(Q_(29, "N*m"), Q_(108, "N*m"), Q_(6.7e4, "N*m/rad"), Q_(1.1e5, "N*m/rad"), Q_(K_3, "N*m/rad"))


@pytest.mark.parametrize("K_3", [1.2e5, 5e4, 1e6])
def test_hfuc_32_100_at_60_newton_metres(K_3):
    # Harmonic Drive engineering data, HFUC-32-100: T1 = 29 N·m, K1 = 6.7e4 N·m/rad, T2 = 108 N·m,
    # K2 = 1.1e5 N·m/rad; printed: 7.15e-4 rad at 60 N·m. Hand calculation:
    # φ = 29 / 6.7e4 + (60 - 29) / 1.1e5 = 4.328e-4 + 2.818e-4 = 7.147e-4 rad. K3 does not enter below T2.
    phi = hfuc_32_100(K_3).twist(Q_(60, "N*m")).m_as("rad")
    assert phi == pytest.approx(7.15e-4, abs=0.005e-4)
    assert phi == pytest.approx(29 / 6.7e4 + 31 / 1.1e5, rel=1e-12)


def test_each_band_by_hand():
    c = hfuc_32_100()
    # Below T1: 20 / 6.7e4; above T2: 29/6.7e4 + 79/1.1e5 + 42/1.2e5 at 150 N·m.
    assert c.twist(Q_(20, "N*m")).m_as("rad") == pytest.approx(20 / 6.7e4, rel=1e-12)
    assert c.twist(Q_(150, "N*m")).m_as("rad") == pytest.approx(29 / 6.7e4 + 79 / 1.1e5 + 42 / 1.2e5, rel=1e-12)
    assert c.twist(Q_(-60, "N*m")).m_as("rad") == pytest.approx(c.twist(Q_(60, "N*m")).m_as("rad"))
    # The secant at 60 N·m gives the curve's twist; at zero it is K1.
    assert (Q_(60, "N*m") / c.secant(Q_(60, "N*m"))).m_as("rad") == pytest.approx(7.1466e-4, rel=1e-4)
    assert c.secant(Q_(0, "N*m")).m_as("N*m/rad") == pytest.approx(6.7e4)


curves = st.tuples(
    st.floats(1, 100), st.floats(1.01, 10), st.floats(1e3, 1e6), st.floats(1e3, 1e6), st.floats(1e3, 1e6)
).map(lambda v: StiffnessCurve(Q_(v[0], "N*m"), Q_(v[0] * v[1], "N*m"), Q_(v[2], "N*m/rad"), Q_(v[3], "N*m/rad"),
                               Q_(v[4], "N*m/rad")))


@settings(max_examples=200, deadline=None)
@given(curves, st.floats(0, 2000), st.floats(0, 2000))
def test_twist_never_falls_as_torque_rises(curve, a, b):
    lo, hi = sorted((a, b))
    assert curve.twist(Q_(lo, "N*m")).m_as("rad") <= curve.twist(Q_(hi, "N*m")).m_as("rad")


@settings(max_examples=200, deadline=None)
@given(curves)
def test_twist_is_continuous_at_both_limit_torques(curve):
    for limit in (curve.T_1, curve.T_2):
        t = limit.m_as("N*m")
        below, at, above = (curve.twist(Q_(x, "N*m")).m_as("rad") for x in (t * (1 - 1e-12), t, t * (1 + 1e-12)))
        assert below == pytest.approx(at, rel=1e-9) and above == pytest.approx(at, rel=1e-9)


@settings(max_examples=200, deadline=None)
@given(st.floats(1, 100), st.floats(1.01, 10), st.floats(1e3, 1e6), st.floats(0, 2000))
def test_equal_slopes_are_one_slope(t_1, ratio, k, torque):
    curve = StiffnessCurve(Q_(t_1, "N*m"), Q_(t_1 * ratio, "N*m"), Q_(k, "N*m/rad"), Q_(k, "N*m/rad"), Q_(k, "N*m/rad"))
    assert curve.twist(Q_(torque, "N*m")).m_as("rad") == pytest.approx(torque / k, rel=1e-9, abs=1e-15)
    one = Component("one slope", "output", Q_(k, "N*m/rad"), Q_(0, "arcmin"))
    piece = Component("curve", "output", Q_(k, "N*m/rad"), Q_(0, "arcmin"), stiffness_curve=curve)
    a, b = (chain_accuracy(Chain((m,)), Q_(torque, "N*m"), Q_(1e9, "N*m")).lost_motion.m_as("arcmin")
            for m in (one, piece))
    assert b == pytest.approx(a, rel=1e-9, abs=1e-12)


@settings(max_examples=100, deadline=None)
@given(curves, st.floats(0.01, 2000), st.floats(1e3, 1e6), st.floats(1.5, 50))
def test_chain_twist_is_the_sum_of_its_members(curve, torque, coupling, ratio):
    # A motor-side coupling (one slope, reflected through i, E11) and a gear with a curve: the chain's
    # twist at T is the sum of the members' twists at T; the chain's stiffness is the secant |T| / φ.
    t = Q_(torque, "N*m")
    members = (Component("coupling", "input", Q_(coupling, "N*m/rad"), Q_(0, "arcmin")),
               Component("gear", "output", curve.K_1, Q_(1, "arcmin"), stiffness_curve=curve))
    chain = Chain(members, ratio=Q_(ratio, ""))
    phi = torque / (coupling * ratio**2) + curve.twist(t).m_as("rad")
    assert chain.twist(t).m_as("rad").sum() == pytest.approx(phi, rel=1e-9)
    a = chain_accuracy(chain, t, Q_(1e9, "N*m"))  # 3 % of a huge T_N: the backlash form; lost motion is j + φ
    assert a.chain.stiffness.m_as("N*m/rad") == pytest.approx(torque / phi, rel=1e-9)
    assert a.lost_motion.m_as("rad") == pytest.approx(Q_(1, "arcmin").m_as("rad") + phi, rel=1e-9)


def test_a_chain_without_curves_is_itself_at_any_torque():
    chain = Chain((Component("g", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin")),))
    assert chain.at_torque(Q_(20, "N*m")) is chain


def test_steps_show_the_band_formula_and_the_secant():
    steps = hfuc_32_100().steps(Q_(60, "N*m"))
    assert [s.formula.name for s in steps] == ["phi_c2", "C_sec"]
    assert [s.formula.name for s in hfuc_32_100().steps(Q_(0, "N*m"))] == ["phi_c1"]
    assert [s.formula.name for s in hfuc_32_100().steps(Q_(500, "N*m"))] == ["phi_c3", "C_sec"]


@pytest.mark.parametrize(
    "args, message",
    [
        ((29, 29, 6.7e4, 1.1e5, 1.2e5), r"^curve.T2: expected a limit torque above T1 = 29 N·m, found 29 N·m"),
        ((29, 20, 6.7e4, 1.1e5, 1.2e5), r"^curve.T2: expected a limit torque above T1"),
        ((29, 108, 0, 1.1e5, 1.2e5), r"^curve.K1: expected a slope above zero"),
        ((29, 108, 6.7e4, -1.1e5, 1.2e5), r"^curve.K2: expected a slope above zero"),
        ((-29, 108, 6.7e4, 1.1e5, 1.2e5), r"^curve.T1: expected a torque above zero"),
    ],
)
def test_a_bad_curve(args, message):
    t1, t2, k1, k2, k3 = args
    with pytest.raises(CalcError, match=message):
        StiffnessCurve(Q_(t1, "N*m"), Q_(t2, "N*m"), Q_(k1, "N*m/rad"), Q_(k2, "N*m/rad"), Q_(k3, "N*m/rad"),
                       where="curve")


# --- the case key ------------------------------------------------------------------------------

CURVE = (
    'stiffness_curve = {{T1 = "29 N*m", T2 = "{T2}", K1 = "6.7e4 N*m/rad", K2 = "1.1e5 N*m/rad", K3 = "1.2e5 N*m/rad"}}'
)


def gear(applied="60 N*m", curve=None, extra=""):
    curve = curve or CURVE.format(T2="108 N*m")
    return (
        f'[accuracy]\napplied_torque = "{applied}"\nnominal_torque = "178 N*m"\n[[accuracy.component]]\nname = '
        f'"HFUC-32-100"\nside = "output"\nbacklash = "0 arcmin"\n{curve}\n{extra}'
    )


def test_case_with_a_stiffness_curve(capsys, write_case):
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + gear()), "--json")
    assert code == 0, err
    a = json.loads(out)["accuracy"]
    member = a["components"][0]
    assert member["twist_at_applied_torque"]["value"] == pytest.approx(Q_(7.1466e-4, "rad").m_as("arcmin"), rel=1e-4)
    assert member["stiffness_curve"]["K2"] == {"value": 1.1e5,
                                               "unit": "N*m/rad"} and member["stiffness_is_secant"] is True
    assert a["C_total_is_secant"] is True
    assert a["C_total"]["value"] == pytest.approx(Q_(60 / 7.1466e-4, "N*m/rad").m_as("N*m/arcmin"), rel=1e-4)
    assert a["lost_motion"]["value"] == pytest.approx(Q_(7.1466e-4, "rad").m_as("arcmin"), rel=1e-4)
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + gear(), "t.toml"))
    assert "secant |T| / φ at the applied torque" in out


@pytest.mark.parametrize(
    "section, message",
    [
        (gear(curve=CURVE.format(T2="20 N*m")),
         "accuracy.component[1].stiffness_curve.T2: expected a limit torque above T1 = 29 N·m, found 20 N·m"),
        (gear(curve='stiffness_curve = {T1 = "29 N*m", T2 = "108 N*m", K1 = "6.7e4 N*m/rad", K2 = "1.1e5 N*m/rad"}'),
         "accuracy.component[1].stiffness_curve.K3: expected a value, found none"),
        (gear(curve='stiffness_curve = {T1 = "29 N*m", T2 = "108 N*m", K1 = "6.7e4 N*m", K2 = "1.1e5 N*m/rad", K3 = "1 '
                    'N*m/rad"}'), "accuracy.component[1].stiffness_curve.K1: expected a stiffness"),
        (gear(curve='stiffness_curve = {T1 = "29 N*m", T2 = "108 N*m", K1 = "6.7e4 N*m/rad", K2 = "0 N*m/rad", K3 = "1 '
                    'N*m/rad"}'), "accuracy.component[1].stiffness_curve.K2: expected a slope above zero"),
        (gear(curve='stiffness_curve = {T1 = "29 N*m", T3 = "1 N*m"}'),
         "accuracy.component[1].stiffness_curve.T3: unknown key"),
        (gear(extra='stiffness = "1 N*m/arcmin"'),
         "accuracy.component[1].stiffness_curve: the curve gives the member's stiffness; give either stiffness_curve "
         "or stiffness"),
    ],
)
def test_case_errors_name_the_key(capsys, write_case, section, message):
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + section))
    assert code == 2 and out == ""
    assert message in err and err.count("\n") == 1, err


def test_figures_follow_the_curve():
    from calc.figures.accuracy_plots import positioning_rule_figure, stiffness_chain_figure
    from calc.sections.accuracy import chain_values

    curve = hfuc_32_100()
    chain = Chain((Component("HFUC-32-100", "output", curve.K_1, Q_(0, "arcmin"), Q_(1, "arcmin"), Q_(178, "N*m"),
                             stiffness_curve=curve),))
    # The chain's stiffness at each torque is the secant: at 60 N·m, 60 / 7.1466e-4 N·m/rad; at 0, K1.
    c = chain.stiffness_at(Q_([0, 60], "N*m")).m_as("N*m/rad")
    assert c[0] == pytest.approx(6.7e4) and c[1] == pytest.approx(60 / 7.1466e-4, rel=1e-4)
    assert "secant" in positioning_rule_figure(chain, applied_torque=Q_(60, "N*m")).axes[0].get_title()
    assert stiffness_chain_figure(chain_values(chain, Q_(60, "N*m"))).axes[0].get_title()
    plain = Chain((Component("g", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin")),))
    assert plain.stiffness_at(Q_([1, 2], "N*m")) is plain.stiffness


# --- a gearbox catalog with stiffness-curve columns ----------------------------------------------

GEARS = (
    "part,series,ratio [1],T_2N [N*m],T_2B [N*m],T_2Not [N*m],n_1N [rpm],n_1max [rpm],eta [percent],backlash [arcmin],"
    "C_t21 [N*m/arcmin],J_1 [kg*cm**2],T_L1 [N*m],T_L2 [N*m],K_1 [N*m/rad],K_2 [N*m/rad],K_3 [N*m/rad],source\n"
    "SW-32-100,SW,100,100,200,400,2000,4000,80,0.3,,0.2,{curve},"
    '"a test row: the curve is HFUC-32-100\'s, the other figures are made up"\n'
)
HFUC = "29,108,6.7e4,1.1e5,1.2e5"


def gear_catalog(tmp_path, curve=HFUC):
    path = tmp_path / "gears.csv"
    path.write_text(GEARS.format(curve=curve))
    return path


def test_a_catalog_part_with_a_stiffness_curve(capsys, write_case, tmp_path):
    gear_catalog(tmp_path)
    head = HEAD_TOML.replace("ratio = 10", 'ratio = 100\ncatalog = "gears.csv"')
    section = '[accuracy]\napplied_torque = "60 N*m"\n[[accuracy.component]]\npart = "SW-32-100"\n'
    code, out, err = run(capsys, write_case(head + PROFILE_TOML + section), "--json")
    assert code == 0, err
    member = json.loads(out)["accuracy"]["components"][0]
    assert member["stiffness_curve"]["T2"] == {"value": 108.0, "unit": "N*m"}
    assert member["twist_at_applied_torque"]["value"] == pytest.approx(Q_(29 / 6.7e4 + 31 / 1.1e5,
                                                                          "rad").m_as("arcmin"), rel=1e-9)


def test_the_shipped_catalog_loads_without_the_curve_columns():
    from calc.data.catalog import load_catalog, resolve
    from calc.domain.gearbox import SCHEMA

    cat = load_catalog(resolve("gearboxes", None, "catalog"), SCHEMA)
    assert np.isnan(cat["K_1"].magnitude).all()


@pytest.mark.parametrize(
    "curve, message",
    [
        ("29,108,6.7e4,1.1e5,",
         r"row 2 \(SW-32-100\), column K_3: impossible value, expected a stiffness curve in all of T_L1, T_L2, K_1, "
         r"K_2, K_3 or in none"),
        ("108,29,6.7e4,1.1e5,1.2e5", r"row 2 \(SW-32-100\), column T_L2: impossible value, expected T_L2 > T_L1"),
        ("29,108,-6.7e4,1.1e5,1.2e5", r"row 2 \(SW-32-100\), column K_1: expected a value above zero, found -6.7e4"),
    ],
)
def test_a_bad_curve_in_a_catalog(tmp_path, curve, message):
    from calc.data.catalog import load_catalog
    from calc.domain.gearbox import SCHEMA

    with pytest.raises(CalcError, match=message):
        load_catalog(gear_catalog(tmp_path, curve), SCHEMA)


def test_a_curve_column_with_a_wrong_unit(tmp_path):
    from calc.data.catalog import load_catalog
    from calc.domain.gearbox import SCHEMA

    path = gear_catalog(tmp_path)
    path.write_text(path.read_text().replace("K_1 [N*m/rad]", "K_1 [N*m]"))
    with pytest.raises(CalcError, match=r"header, column K_1: expected a unit of stiffness"):
        load_catalog(path, SCHEMA)
