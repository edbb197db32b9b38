"""Coupling sizing (E7 to E10): M_N, temperature factor, natural frequency, line shafts, safety
couplings, the vectorized selection and the order line."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.data.bands import BandTable
from calc.data.catalog import load_catalog, resolve
from calc.domain.coupling import (
    SCHEMA,
    C_T_line,
    J_A,
    J_L,
    M_N,
    Z,
    f_e,
    order_lines,
    phi,
    select_coupling,
    temperature_factor,
)
from calc.domain.fits import parse_bore
from calc.core.citation import Document, Source
from calc.core.formula import REGISTRY, Formula
from calc.core.glossary import Symbol, symbol

CATALOG = load_catalog(resolve("couplings", None, "catalog"), SCHEMA)


def of_type(name):
    return CATALOG.rows(CATALOG.text["type"] == name)


# The example case (cases/indexing-table.toml): a coupling between the servo motor and the gearbox.
EXAMPLE = dict(
    accel_torque=Q_(12, "N*m"),
    drive_inertia=Q_(4.2, "kg*cm**2"),
    load_inertia=Q_(15.93, "kg*cm**2"),
    excitation_frequency=Q_(150, "Hz"),
    shaft_1="19 mm k6",
    shaft_2="16 mm h7",
    speed=Q_(3000, "rpm"),
)


# --- M_N (source, Sizing 1; E8) -------------------------------------------------------------


def test_nominal_torque_by_hand():
    # Hand calculation: J_load = 1500 kg·cm² / 10² + 0.93 kg·cm² = 15.93 kg·cm² (E8: the load
    # reflected to the motor side plus the gearbox's J_1); J_drive = 4.2 kg·cm².
    # M_N = 12 N·m · 15.93 / (15.93 + 4.2) · 2.5 = 12 · 0.791356 · 2.5 = 23.7407 N·m.
    m = M_N(M_a=Q_(12, "N*m"), J_load=Q_(15.93, "kg*cm**2"), J_drive=Q_(4.2, "kg*cm**2"), S_A=2.5)
    assert m.m_as("N*m") == pytest.approx(23.7407, abs=1e-4)


def test_service_factor_defaults_to_two_and_a_half():
    # E8: S_A is a parameter with default 2.5.
    s = select_coupling(of_type("bellows"), **EXAMPLE)
    assert s.M_N.m_as("N*m") == pytest.approx(23.7407, abs=1e-4)
    assert select_coupling(of_type("bellows"), service_factor=1,
                           **EXAMPLE).M_N.m_as("N*m") == pytest.approx(23.7407 / 2.5, abs=1e-4)


@given(
    m_a=st.floats(0.1, 1000), j_load=st.floats(1e-3, 1e4), j_drive=st.floats(1e-3, 1e4), s_a=st.floats(1, 4)
)
def test_nominal_torque_lies_between_zero_and_the_shock_loaded_motor_torque(m_a, j_load, j_drive, s_a):
    m = M_N(M_a=Q_(m_a, "N*m"), J_load=Q_(j_load, "kg*cm**2"), J_drive=Q_(j_drive, "kg*cm**2"), S_A=s_a).m_as("N*m")
    assert 0 < m <= m_a * s_a * (1 + 1e-12)


# --- Temperature factor (source, Sizing 3; E9) ------------------------------------------------


@pytest.mark.parametrize(
    "celsius, factor",
    [(-20, 1.0), (49.99, 1.0), (50, 1.3), (69.99, 1.3), (70, 1.6), (89.99, 1.6), (90, 1.8), (109.99, 1.8), (110, 2.0),
     (120, 2.0)],
)
def test_temperature_factor_takes_the_higher_factor_at_a_boundary(celsius, factor):
    # E9: T < 50 °C → 1.0; 50 <= T < 70 → 1.3; 70 <= T < 90 → 1.6; 90 <= T < 110 → 1.8; T >= 110 → 2.0,
    # up to the table's top, 120 °C.
    assert float(temperature_factor(Q_(celsius, "degC"))) == factor


def test_temperature_in_other_units():
    # 122 °F = 50 °C and 343.15 K = 70 °C: each on a boundary.
    assert float(temperature_factor(Q_(122, "degF"))) == 1.3
    assert float(temperature_factor(Q_(343.15, "K"))) == 1.6


def test_another_makers_table_is_data():
    # E9: one elastomer maker publishes 1.0 up to 30 °C, 1.5 at 60, 2.0 at 90, 2.5 at 110 °C.
    table = BandTable("T", (-math.inf, 30.0, 60.0, 90.0), (1.0, 1.5, 2.0, 2.5), "degC", "temperature", "another maker",
                      top=110.0)
    assert [float(temperature_factor(Q_(t, "degC"), table)) for t in (20, 30, 60, 95)] == [1.0, 1.5, 2.0, 2.5]


@pytest.mark.parametrize("temperature", [Q_(-300, "degC"), Q_(-1, "K"), Q_(-500, "degF")])
def test_temperature_below_absolute_zero_is_an_input_error(temperature):
    # -300 °C, -1 K and -500 °F (-295.9 °C) all lie below 0 K = -273.15 °C: no factor, an error naming the key.
    with pytest.raises(CalcError, match=r"^coupling.temperature: expected a temperature above absolute zero"):
        temperature_factor(temperature, where="coupling.temperature")


@pytest.mark.parametrize("temperature",
                         [Q_(121, "degC"), Q_(1000, "degC"), Q_(400, "K"), Q_(Q_(120.5, "degC").m_as("degF"), "degF")])
def test_temperature_above_the_tables_range_is_an_input_error(temperature):
    # The source's last band, "> 110 °C", ends at 120 °C, the highest rating of servo elastomer inserts
    # (thermoplastic polyurethane): 121 °C, 1000 °C, 400 K = 126.85 °C and 120.5 °C in °F lie above it.
    with pytest.raises(CalcError, match=r"^temperature: expected T <= 120 °C \(the source's temperature-factor table"):
        temperature_factor(temperature)


def test_the_tables_top_belongs_to_it():
    # 120 °C is the top of the last band (included); 393.15 K is 120 °C, 248 °F is 120.00000000000006 °C,
    # within the boundary tolerance.
    assert [float(temperature_factor(t)) for t in (Q_(120, "degC"), Q_(393.15, "K"), Q_(248, "degF"))] == [2.0] * 3


def test_temperature_must_be_a_temperature():
    with pytest.raises(CalcError, match="temperature: expected a temperature"):
        temperature_factor(Q_(60, "coulomb"))
    with pytest.raises(CalcError, match="temperature difference"):
        temperature_factor(Q_(60, "delta_degC"))


def test_only_elastomer_couplings_get_the_factor():
    both = CATALOG.rows(np.isin(CATALOG.text["type"], ["bellows", "elastomer"]))
    s = select_coupling(both, temperature=Q_(60, "degC"), **EXAMPLE)
    elastomer = both.text["type"] == "elastomer"
    assert set(s.temperature_factor[elastomer]) == {1.3} and set(s.temperature_factor[~elastomer]) == {1.0}
    assert s.M_Nt[elastomer][0].m_as("N*m") == pytest.approx(23.7407 * 1.3, abs=1e-3)


# --- Natural frequency (source, Sizing 2; E7, E15) -------------------------------------------


def test_natural_frequency_by_hand():
    # AKD-30 (C_T = 25 000 N·m/rad, J = 1 kg·cm²) between the example's motor and load:
    # J_A = 4.2 + 0.5 = 4.7 kg·cm² = 4.7e-4 kg·m²; J_L = 15.93 + 0.5 = 16.43e-4 kg·m².
    # (J_A + J_L) / (J_A · J_L) = 21.13e-4 / 7.7221e-7 = 2736.30 1/(kg·m²);
    # ω = √(25 000 · 2736.30) = 8270.9 rad/s; f_e = ω / 2π = 1316.35 Hz.
    j_a = J_A(J_drive=Q_(4.2, "kg*cm**2"), J_K=Q_(1, "kg*cm**2"))
    j_l = J_L(J_load=Q_(15.93, "kg*cm**2"), J_K=Q_(1, "kg*cm**2"))
    assert j_a.m_as("kg*cm**2") == pytest.approx(4.7) and j_l.m_as("kg*cm**2") == pytest.approx(16.43)
    assert f_e(C_T=Q_(25_000, "N*m/rad"), J_A=j_a, J_L_coupling=j_l).m_as("Hz") == pytest.approx(1316.35, abs=0.01)


def test_natural_frequency_takes_a_stiffness_per_arcmin():
    # The source's EKM-15: 0.24 N·m/arcmin = 0.24 · 10800/π = 825.06 N·m/rad (E14). With
    # J_A = J_L = 1 kg·cm²: f_e = √(825.06 · 2 / 1e-4) / 2π = √(1.65012e7) / 2π = 646.5 Hz.
    j = Q_(1, "kg*cm**2")
    assert f_e(C_T=Q_(0.24, "N*m/arcmin"), J_A=j, J_L_coupling=j).m_as("Hz") == pytest.approx(646.5, abs=0.1)
    with pytest.raises(CalcError, match="argument 'C_T': expected a stiffness"):
        f_e(C_T=Q_(0.24, "N*m"), J_A=j, J_L_coupling=j)  # a torque is no stiffness (E15)


def test_radian_is_a_constant_of_the_formula():
    assert symbol("rad").value == "1 rad"
    with pytest.raises(CalcError, match="unknown argument 'rad'"):
        f_e(C_T=Q_(1, "N*m/rad"), J_A=Q_(1, "kg*m**2"), J_L_coupling=Q_(1, "kg*m**2"), rad=Q_(1, "rad"))
    assert r"\mathrm{rad}" in f_e.latex()
    step = f_e.step(C_T=Q_(25_000, "N*m/rad"), J_A=Q_(4.7, "kg*cm**2"), J_L_coupling=Q_(16.43, "kg*cm**2"))
    assert r"1\,\mathrm{rad}" in step.latex() and str(step) == "f_e = 1316 Hz"


def test_without_the_radian_the_angle_check_fails():
    # The strict check of E15 is not weakened: the same expression without the radian leaves
    # rad^-1/2 in a frequency and is refused.
    wrong = Formula(
        Symbol("f", "f", "frequency", "Hz", "frequency"),
        (Symbol("C", "C", "stiffness", "N*m/rad", "stiffness"), Symbol("J", "J", "inertia", "kg*m**2", "inertia")),
        lambda sp, C, J: sp.sqrt(C / J) / (2 * sp.pi),
        Source(Document("tests", "the package's tests", "drivetrain-calc").at()),
    )
    try:
        with pytest.raises(CalcError, match="expected frequency"):
            wrong.check_dimensions()
    finally:
        REGISTRY.remove(wrong)
    f_e.check_dimensions()


@given(c=st.floats(1e2, 1e7), j_a=st.floats(0.01, 1e4), j_l=st.floats(0.01, 1e4), more=st.floats(1.001, 100))
def test_natural_frequency_falls_as_either_inertia_grows(c, j_a, j_l, more):
    def fe(a, b):
        return f_e(C_T=Q_(c, "N*m/rad"), J_A=Q_(a, "kg*cm**2"), J_L_coupling=Q_(b, "kg*cm**2")).m_as("Hz")

    base = fe(j_a, j_l)
    assert fe(j_a * more, j_l) < base and fe(j_a, j_l * more) < base


@given(c=st.floats(1e2, 1e7), j=st.floats(0.01, 1e4))
def test_a_very_heavy_load_leaves_the_single_mass_frequency(c, j):
    # J_L → ∞: f_e → √(C_T / J_A) / 2π, the drive side on a spring to a fixed wall.
    single = math.sqrt(c / (j * 1e-4)) / (2 * math.pi)
    far = f_e(C_T=Q_(c, "N*m/rad"), J_A=Q_(j, "kg*cm**2"), J_L_coupling=Q_(j * 1e9, "kg*cm**2"))
    assert far.m_as("Hz") == pytest.approx(single, rel=1e-6)


@given(
    m_a=st.floats(0.5, 200), j_drive=st.floats(0.1, 100), j_load=st.floats(0.1, 1000), f_er=st.floats(1, 500),
    d=st.floats(10.5, 25)
)
def test_metric_and_inch_inputs_give_the_same_answer(m_a, j_drive, j_load, f_er, d):
    lbf_in, lb_in2 = 0.1129848290276167, 0.45359237 * 2.54**2  # N·m per lbf·in, kg·cm² per lb·in²
    bellows = of_type("bellows")
    metric = select_coupling(
        bellows, Q_(m_a, "N*m"), Q_(j_drive, "kg*cm**2"), Q_(j_load, "kg*cm**2"), Q_(f_er, "Hz"), f"{d!r} mm k6",
        f"{d!r} mm h7"
    )
    inch = select_coupling(
        bellows, Q_(m_a / lbf_in, "lbf*in"), Q_(j_drive / lb_in2, "lb*in**2"), Q_(j_load / lb_in2, "lb*in**2"),
        Q_(f_er * 60, "1/min"), f'{d / 25.4!r}" k6', f"{d / 25.4!r} in h7",
    )
    assert inch.M_N.m_as("N*m") == pytest.approx(metric.M_N.m_as("N*m"), rel=1e-9)
    # DKN-45-L41: no J, no f_e
    assert inch.f_e.m_as("Hz") == pytest.approx(metric.f_e.m_as("Hz"), rel=1e-9, nan_ok=True)
    assert inch.order.tolist() == metric.order.tolist() and inch.passes.tolist() == metric.passes.tolist()


# --- Line shafts (R+W ZA catalog, catalog-data.md) -------------------------------------------


def test_line_shaft_twist_of_the_published_example():
    # R+W ZA, size 150: bellows 87 500 N·m/rad, tube 20 230 N·m²/rad, hub H = 78 mm.
    # A = 1.5 m: Z = 1.5 - 2 · 0.078 = 1.344 m; C_T = 1 / (1/87 500 + 1.344/20 230) = 12 842 N·m/rad;
    # φ = 150 N·m / 12 842 N·m/rad = 0.01168 rad = 0.669° (the catalog's worked example).
    za = CATALOG.rows([CATALOG.index("ZA-150", "part")])
    z = Z(A=Q_(1.5, "m"), H=za["H"][0])
    c = C_T_line(C_B=za["C_T"][0], Z=z, C_tube=za["C_tube"][0])
    assert z.m_as("m") == pytest.approx(1.344)
    assert c.m_as("N*m/rad") == pytest.approx(12842, abs=1)
    assert phi(T=Q_(150, "N*m"), C_T=c).m_as("deg") == pytest.approx(0.669, abs=5e-4)


@given(a1=st.floats(0.2, 6), more=st.floats(0.01, 3))
def test_a_longer_line_shaft_is_softer_and_below_its_bellows(a1, more):
    za = CATALOG.rows([CATALOG.index("ZA-150", "part")])

    def c(a):
        return C_T_line(C_B=za["C_T"][0], Z=Z(A=Q_(a, "m"), H=za["H"][0]), C_tube=za["C_tube"][0]).m_as("N*m/rad")

    assert c(a1 + more) < c(a1) < 87_500


def test_line_shaft_selection_uses_the_stiffness_at_the_shaft_distance(tmp_path):
    # A complete (made-up) line-shaft row, so every check can be made.
    text = (resolve("couplings", None, "catalog").read_text().splitlines()[0] + "\n"
            "LS-150,LS,150,line-shaft,150,,87500,20230,20,3000,10,40,10,40,,,78,3000,,,,,,,,,,,,,yes,test row\n")
    (tmp_path / "ls.csv").write_text(text)
    cat = load_catalog(tmp_path / "ls.csv", SCHEMA)
    s = select_coupling(cat, shaft_distance=Q_(1.5, "m"), **EXAMPLE)
    assert s.C_T[0].m_as("N*m/rad") == pytest.approx(12842, abs=1)
    assert s.selected == "LS-150"
    too_long = select_coupling(cat, shaft_distance=Q_(3.5, "m"), **EXAMPLE)
    assert too_long.selected is None
    assert too_long.reasons(0) == ["A <= A_max: required 3500 mm > rated 3000 mm, 16.7 % over"]


def test_shaft_distance_shorter_than_the_hubs_is_an_error():
    with pytest.raises(CalcError,
                       match=r"shaft_distance: 100 mm is shorter than the two hubs of every line shaft \(2 H = 156 "
                             r"mm\)"):
        select_coupling(of_type("line-shaft"), shaft_distance=Q_(100, "mm"), **EXAMPLE)


# --- Safety couplings (E10) ------------------------------------------------------------------


def test_safety_coupling_of_the_source_example():
    # SKB-30 ordered with T_A = 25 N·m: inside the size's range 12 to 30 N·m (illustrative row),
    # above the peak torque of normal operation T_op = M_N / S_A = 23.7407 / 2.5 = 9.496 N·m.
    s = select_coupling(of_type("safety"), disengagement_torque=Q_(25, "N*m"), **EXAMPLE)
    assert s.selected == "SKB-30"
    assert s.T_op.m_as("N*m") == pytest.approx(9.4963, abs=1e-4)
    row = CATALOG.rows(CATALOG.text["type"] == "safety").index("SKB-15", "part")
    assert "T_A <= T_Amax: required 25 N·m > rated 15 N·m, 66.7 % over" in s.reasons(row)


def test_disengagement_torque_below_normal_operation_slips():
    # T_A = 8 N·m lies in SKB-15's range (6 to 15 N·m) but below T_op = 9.496 N·m: it would slip.
    safety = of_type("safety")
    s = select_coupling(safety, disengagement_torque=Q_(8, "N*m"), **{**EXAMPLE, "accel_torque": Q_(12, "N*m")})
    row = safety.index("SKB-15", "part")
    assert "T_op <= T_A: required 9.496 N·m > rated 8 N·m, 18.7 % over" in s.reasons(row)
    assert not s.passes[row]


def test_disengagement_torque_is_for_safety_couplings_only():
    with pytest.raises(CalcError,
                       match="disengagement_torque: a disengagement torque T_A .* is for safety couplings only"):
        select_coupling(of_type("bellows"), disengagement_torque=Q_(25, "N*m"), **EXAMPLE)
    with pytest.raises(CalcError, match="disengagement_torque: safety couplings need a disengagement torque"):
        select_coupling(of_type("safety"), **EXAMPLE)


# --- Selection ----------------------------------------------------------------------------------


def test_example_selects_the_smallest_adequate_bellows():
    s = select_coupling(of_type("bellows"), **EXAMPLE)
    parts = s.catalog.parts[s.order].tolist()
    # M_N = 23.74 N·m. Passing first by rated torque (RINGFEDER AKD and AKN, each row's source):
    # AKD-30 and AKN-30 36 N·m (tied on size and on the torque utilization 23.74/36 = 0.66: by name),
    # AKD-60 and AKN-60 75 (worst: the bore, d_2min / D_2 = 12/16 = 0.75), AKN-80 95 (14/16 = 0.875),
    # AKD-150 and AKN-150 180 (14/16 = 0.875); then failing, closest to passing first: AKD-18 and AKN-18
    # at 23.74/22 = 1.08 for torque, AKN-200 at 22/16 = 1.375 for the bore, AKD-300 and AKN-300 24/16 = 1.5.
    assert parts[:12] == [
        "AKD-30", "AKN-30", "AKD-60", "AKN-60", "AKN-80", "AKD-150", "AKN-150",
        "AKD-18", "AKN-18", "AKN-200", "AKD-300", "AKN-300",
    ]
    assert s.selected == "AKD-30"
    row = s.catalog.index("AKD-18", "part")
    assert s.reasons(row) == ["M_N · K_ϑ <= T_KN: required 23.74 N·m > rated 22 N·m, 7.91 % over"]


def test_an_empty_choice_of_couplings_is_an_error():
    # A type the catalog does not spell ("bellow") leaves no row to select from.
    with pytest.raises(CalcError) as err:
        select_coupling(of_type("bellow"), **EXAMPLE)
    assert str(err.value) == "coupling: no coupling to check, the catalog has no rows"


def test_a_bore_outside_every_hub_is_a_failing_check_not_an_error():
    s = select_coupling(of_type("bellows"), **{**EXAMPLE, "shaft_1": "80 mm k6"})
    assert s.selected is None
    row = s.catalog.index("AKD-30", "part")
    assert "D_1 <= d_1max: required 80 mm > rated 30 mm, 167 % over" in s.reasons(row)
    s = select_coupling(of_type("bellows"), **{**EXAMPLE, "shaft_2": "6 mm h7"})
    assert "d_2min <= D_2: 6 mm is below the least 8 mm, 25 % short" in s.reasons(s.catalog.index("AKD-18", "part"))


def test_resonance_fails_when_the_drive_excites_too_high():
    # 2 f_er = 1400 Hz: above AKD-30's 1316.35 Hz. AKN-30 (C_T 35 000 N·m/rad, J 1.1 kg·cm², RINGFEDER
    # AKN paper): J_A = 4.2 + 0.55 = 4.75, J_L = 15.93 + 0.55 = 16.48 kg·cm²; f_e = √(35 000 · (4.75 +
    # 16.48) / (4.75 · 16.48) · 10⁴) / 2π = √(9.4925·10⁷) / 2π = 1550.6 Hz >= 1400 Hz: it passes.
    s = select_coupling(of_type("bellows"), **{**EXAMPLE, "excitation_frequency": Q_(700, "Hz")})
    reasons = s.reasons(s.catalog.index("AKD-30", "part"))
    assert "2 f_er <= f_e: required 1400 Hz > rated 1316 Hz, 6.35 % over" in reasons
    assert s.f_e[s.catalog.index("AKN-30", "part")].m_as("Hz") == pytest.approx(1550.6, abs=0.1)
    assert s.selected == "AKN-30"


def test_missing_catalog_figures_fail_with_the_reason():
    s = select_coupling(of_type("elastomer"), temperature=Q_(20, "degC"), **{**EXAMPLE, "accel_torque": Q_(1, "N*m")})
    assert s.selected is None
    reasons = s.reasons(0)
    assert (
        "2 f_er <= f_e: not checked, f_e needs the coupling's torsional stiffness C_T, which the catalog leaves empty"
    ) in reasons
    assert "d_1min <= D_1: not checked, the catalog gives no bore range for hub 1" in reasons


def test_elastomer_couplings_need_the_temperature():
    with pytest.raises(CalcError, match="temperature: elastomer couplings need the operating temperature"):
        select_coupling(of_type("elastomer"), **EXAMPLE)


def test_selection_is_vectorized_over_the_catalog():
    s = select_coupling(
        CATALOG.rows(np.isin(CATALOG.text["type"], ["bellows", "elastomer", "safety"])),
        temperature=Q_(40, "degC"),
        **EXAMPLE,
    )
    n = len(s.catalog)
    assert s.f_e.shape == (n,) and all(c.utilization.shape == (n,) for c in s.checks)
    # Each f_e equals the scalar formula for its row.
    for row in range(n):
        if not np.isnan(s.f_e[row].magnitude):
            j = s.catalog["J"][row]
            scalar = f_e(C_T=s.catalog["C_T"][row], J_A=J_A(J_drive=EXAMPLE["drive_inertia"], J_K=j),
                         J_L_coupling=J_L(J_load=EXAMPLE["load_inertia"], J_K=j))
            assert s.f_e[row].m_as("Hz") == pytest.approx(scalar.m_as("Hz"))


@pytest.mark.parametrize(
    "change, fragment",
    [
        ({"drive_inertia": Q_(-1.5, "kg*cm**2")}, "coupling.drive_inertia: expected an inertia above zero"),
        ({"load_inertia": Q_(0, "kg*cm**2")}, "coupling.load_inertia: expected an inertia above zero"),
        ({"load_inertia": Q_(1.5, "kg")}, "coupling.load_inertia: expected an inertia"),
        ({"accel_torque": Q_(-3, "N*m")}, "coupling.accel_torque: expected a torque above zero"),
        ({"excitation_frequency": Q_(3000, "rpm")}, "coupling.excitation_frequency: expected a frequency"),
        ({"service_factor": 0.8}, "coupling.service_factor: expected a load factor S_A of 1 or more"),
        ({"shaft_1": "14 mm q99"}, "coupling.shaft_1 ('14 mm q99'): unknown ISO 286 tolerance class 'q99'"),
    ],
)
def test_bad_arguments_name_the_key(change, fragment):
    with pytest.raises(CalcError) as err:
        select_coupling(of_type("bellows"), **{**EXAMPLE, **change})
    assert fragment in str(err.value)


# --- Order line (source, Ordering Examples) ----------------------------------------------------


def test_order_lines_reproduce_the_sources_examples():
    assert order_lines("KM-20", "bellows", [parse_bore("14 mm k6"), parse_bore('1.00" +0/-.0005", x 1/8" keyway')]) == [
        "Standard coupling KM-20",
        "D1 = 14 mm k6",
        'D2 = 1.00" +0/-.0005", x 1/8" keyway',
    ]
    assert order_lines("SKB-30", "safety", [parse_bore("19 mm k6")], disengagement_torque=Q_(25, "N*m")) == [
        "Safety coupling SKB-30",
        "D1 = 19 mm k6",
        "T_A (disengagement torque) = 25 N·m",
    ]
    assert order_lines(
        "WDS-100", "line-shaft", [parse_bore('.500" +/- .0005"'), parse_bore("32 mm k6")], shaft_distance=Q_(915, "mm")
    ) == ["Drive shaft coupling WDS-100", 'D1 = .500" +/- .0005"', "D2 = 32 mm k6", "Distance between shafts = 915 mm"]


def test_order_lines_refuse_keys_of_another_type():
    with pytest.raises(CalcError, match="disengagement torque"):
        order_lines("AKD-30", "bellows", [parse_bore("19 mm k6")], disengagement_torque=Q_(25, "N*m"))
    with pytest.raises(CalcError, match="distance between shafts"):
        order_lines("ZA-150", "line-shaft", [parse_bore("19 mm k6")])
    with pytest.raises(CalcError, match="expected one of bellows, elastomer, safety, line-shaft"):
        order_lines("X", "rubber", [])


# --- Catalog -------------------------------------------------------------------------------------


def test_catalog_rows_say_their_source_and_safety_rows_are_illustrative():
    assert all(CATALOG.text["source"])
    # Only the SKB safety rows are illustrative (no public table when they were made); the Mayr
    # EAS-compact rows are published (B.4.14.1.EN, page 5).
    illustrative = CATALOG.text["illustrative"] == "yes"
    assert set(CATALOG.text["series"][illustrative]) == {"SKB"}
    # E14: inertia in kg·cm² in the file; AKD-30's 0.1e-3 kg·m² is 1 kg·cm².
    assert CATALOG["J"][CATALOG.index("AKD-30", "part")].m_as("kg*m**2") == pytest.approx(1e-4)


@pytest.mark.parametrize(
    "edit, fragment",
    [
        (lambda s: s.replace("AKD-18,AKD,18,bellows", "AKD-18,AKD,18,rubber"),
         "row 2 (AKD-18), column type: expected one of bellows"),
        (lambda s: s.replace("safety,22.5,,6000,,0.9,6000,8,22,8,22,6,15", "safety,22.5,,6000,,0.9,6000,8,22,8,22,,15"),
         "row 11 (SKB-15), column T_Amin: a safety coupling needs a value"),
        (lambda s: s.replace("8,22,8,22,6,15,", "8,22,8,22,16,15,"),
         "row 11 (SKB-15), column T_Amax: impossible value, expected T_Amax >= T_Amin"),
        (lambda s: s.replace("C_T [N*m/rad]", "C_T [N*m]"), "column C_T: expected a unit of stiffness"),
    ],
)
def test_bad_coupling_catalogs_name_row_and_column(tmp_path, edit, fragment):
    from calc.domain.coupling import check_types

    path = tmp_path / "c.csv"
    path.write_text(edit(resolve("couplings", None, "catalog").read_text()))
    with pytest.raises(CalcError) as err:
        check_types(load_catalog(path, SCHEMA))
    assert str(path) in str(err.value) and fragment in str(err.value)


def test_a_step_shows_its_own_numbers_after_sympy_forgets_a_symbol():
    # M_N with S_A = 2.5, then with S_A = 1 (the peak torque of normal operation, E10) after
    # enough other symbols to evict sympy's cached value symbol: the second step must print 1.
    import sympy as sp

    values = dict(M_a=Q_(12, "N*m"), J_load=Q_(15.93, "kg*cm**2"), J_drive=Q_(4.2, "kg*cm**2"))
    M_N.step(S_A=Q_(2.5, ""), **values).latex()
    for k in range(3000):
        sp.Symbol(f"churn_{k}")
    # M_N = 12 · 15.93 / (15.93 + 4.2) · 1 = 9.496 N·m, printed in the source's order (S_A last).
    assert r"4.2\,\mathrm{kg\,cm^{2}}} \cdot 1 = 9.496\,\mathrm{N\,m}" in M_N.step(S_A=Q_(1, ""), **values).latex()


def test_load_inertia_seen_through_the_gearbox():
    # E8, hand calculation for the example: 1500 kg·cm² / 10² + 0.93 kg·cm² = 15.93 kg·cm².
    from calc.domain.coupling import J_load_at_input

    assert J_load_at_input(J_L=Q_(1500, "kg*cm**2"), i=10,
                           J_1=Q_(0.93, "kg*cm**2")).m_as("kg*cm**2") == pytest.approx(15.93)


def test_candidates_frame_lists_the_ranked_candidates():
    from calc.domain.coupling import candidates_frame

    frame = candidates_frame(select_coupling(of_type("bellows"), **EXAMPLE))
    assert frame["part"].tolist()[:3] == ["AKD-30", "AKN-30", "AKD-60"]  # as ranked by hand above
    assert frame["verdict"].tolist().count("PASS") == 7
    assert frame.loc[0, "worst utilization"] == pytest.approx(23.7407 / 36, abs=1e-5)  # the torque check governs
    assert frame.loc[7, "reasons"].startswith("M_N · K_ϑ <= T_KN: required 23.74 N·m > rated 22 N·m")


def test_a_line_shaft_without_its_distance_is_not_checked_as_bellows_alone(tmp_path):
    # Without the shaft distance, the catalog's C_T (the two bellows) must not stand in for the
    # line shaft's stiffness: f_e cannot be computed and the check fails with its reason.
    text = (resolve("couplings", None, "catalog").read_text().splitlines()[0] + "\n"
            "LS-150,LS,150,line-shaft,150,,87500,20230,20,3000,10,40,10,40,,,78,3000,,,,,,,,,,,,,yes,test row\n"
            "AKD-30,AKD,30,bellows,36,,25000,,1,10200,10,30,10,30,,,,,,,,,,,,,,,,,no,test row\n")
    (tmp_path / "mixed.csv").write_text(text)
    s = select_coupling(load_catalog(tmp_path / "mixed.csv", SCHEMA), **EXAMPLE)
    assert np.isnan(s.f_e[0].magnitude) and not s.passes[0]
    assert "2 f_er <= f_e: not checked, a line shaft's stiffness needs coupling.shaft_distance" in s.reasons(0)
    assert s.selected == "AKD-30"


def test_a_published_coupling_ranks_before_an_illustrative_one():
    # The example selects AKD-30 (T_KN 36 N·m); with that row marked illustrative, the passing
    # published rows come first (AKN-30, then AKD-60 ... AKN-150 by size, as ranked by hand in
    # test_example_selects_the_smallest_adequate_bellows), then AKD-30, then the failing ones.
    bellows = of_type("bellows")
    assert select_coupling(bellows, **EXAMPLE).selected == "AKD-30"
    marked = bellows.rows(np.arange(len(bellows)))
    marked.illustrative = bellows.parts == "AKD-30"
    s = select_coupling(marked, **EXAMPLE)
    ranked = [str(marked.parts[k]) for k in s.order]
    assert s.selected == "AKN-30"
    assert ranked[:7] == ["AKN-30", "AKD-60", "AKN-60", "AKN-80", "AKD-150", "AKN-150", "AKD-30"]
