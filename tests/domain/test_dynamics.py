"""Drive-train dynamics (calc.domain.dynamics): a two-mass chain's resonance and anti-resonance and
their ratio against √(1 + λ), a three-mass chain's anti-resonances written out, a strain-wave gear's
first mode at two working torques on its K1–K3 curve, the frequency response (against python-control's), and
the laws: anti-resonances interlace the resonances, the response falls as 1 / (ΣJ ω) far below them."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.domain.dynamics import (
    band_slope, frequency_response, loop_slope, modes, resonance_ratio, torque_reversals, two_mass_anti_resonance,
    two_mass_load, two_mass_resonance,
)
from calc.domain.hysteresis import LoopModel
from calc.domain.stiffness import StiffnessCurve
from calc.domain.torsion import natural_frequencies

KG_CM2 = "kg*cm**2"


def test_two_masses_by_hand():
    # J_motor = 2 kg·cm², J_Lm = 8 kg·cm², C_s = 1000 N·m/rad (SI: 2e-4 and 8e-4 kg·m²):
    #   ω_r²  = 1000 · (1 / 2e-4 + 1 / 8e-4) = 1000 · 6250 = 6.25e6 /s², ω_r = 2500 /s, f_r = 397.887 Hz
    #   ω_ar² = 1000 / 8e-4 = 1.25e6 /s², ω_ar = 1118.034 /s, f_ar = 177.941 Hz
    #   λ = 8 / 2 = 4, f_r / f_ar = 2500 / 1118.034 = 2.23607 = √5 = √(1 + λ)
    J_M, J_L, C = Q_(2, KG_CM2), Q_(8, KG_CM2), Q_(1000, "N*m/rad")
    f_r = two_mass_resonance(C_s=C, J_motor=J_M, J_Lm=J_L).m_as("Hz")
    f_ar = two_mass_anti_resonance(C_s=C, J_Lm=J_L).m_as("Hz")
    assert f_r == pytest.approx(2500 / (2 * math.pi), rel=1e-12) == pytest.approx(397.887, abs=1e-3)
    assert f_ar == pytest.approx(1118.034 / (2 * math.pi), rel=1e-6) == pytest.approx(177.941, abs=1e-3)
    assert f_r / f_ar == pytest.approx(resonance_ratio(**{"lambda": Q_(4, "")}).m_as(""), rel=1e-12)
    assert f_r / f_ar == pytest.approx(2.23607, abs=1e-5)
    # The eigenproblem gives the same two numbers.
    m = modes(Q_([2, 8], KG_CM2), Q_([1000], "N*m/rad"))
    assert m.natural_frequencies.m_as("Hz") == pytest.approx([f_r], rel=1e-12)
    assert m.anti_resonances.m_as("Hz") == pytest.approx([f_ar], rel=1e-12)
    # The rotor swings against the load four times as heavy: amplitudes 1 and -1/4.
    assert m.shapes.tolist() == [pytest.approx([1.0, -0.25])]


def test_three_masses_anti_resonances_by_hand():
    # Masses 1, 2, 4 kg·cm² (1e-4, 2e-4, 4e-4 kg·m²), springs C_1 = 2000 and C_2 = 1000 N·m/rad.
    # The motor held: the second mass hangs on C_1 to the ground and on C_2 to the third,
    #   K' = [[C_1 + C_2, -C_2], [-C_2, C_2]] = [[3000, -1000], [-1000, 1000]], J' = diag(2e-4, 4e-4)
    #   det(K' - x J') = (3000 - 2e-4 x)(1000 - 4e-4 x) - 1000² = 8e-8 x² - 1.4 x + 2e6 = 0
    #   x = (1.4 ∓ √(1.4² - 4 · 8e-8 · 2e6)) / (2 · 8e-8) = (1.4 ∓ √1.32) / 1.6e-7
    root = math.sqrt(1.4**2 - 4 * 8e-8 * 2e6)
    x = [(1.4 - root) / 1.6e-7, (1.4 + root) / 1.6e-7]  # 1.569294e6 and 1.593071e7 /s²
    expected = [math.sqrt(v) / (2 * math.pi) for v in x]  # 199.376 Hz and 635.240 Hz
    assert expected == pytest.approx([199.376, 635.240], abs=1e-3)
    m = modes(Q_([1, 2, 4], KG_CM2), Q_([2000, 1000], "N*m/rad"))
    assert m.anti_resonances.m_as("Hz") == pytest.approx(expected, rel=1e-10)
    # The natural frequencies are the torsion module's (coupling.torsion's) to the last digit.
    assert m.natural_frequencies.m_as("Hz") == pytest.approx(
        natural_frequencies(Q_([1, 2, 4], KG_CM2), Q_([2000, 1000], "N*m/rad")).m_as("Hz"), rel=1e-12)


def test_strain_wave_first_mode_at_two_working_torques():
    # Harmonic Drive HFUC-32-100: K_1 = 6.7e4 N·m/rad up to T_1 = 29 N·m, K_2 = 1.1e5 up to 108 N·m
    # (K_3 = 1.2e5 stands in above). Seen from the output: motor and wave generator 3 kg·cm² · 100² =
    # 3 kg·m², the load 1 kg·m². A small oscillation about a working torque sees the slope there:
    #   at 10 N·m (band 1): ω² = 6.7e4 · (1/3 + 1/1) = 8.9333e4 /s², f_1 = 298.887 / 2π = 47.569 Hz
    #   at 60 N·m (band 2): ω² = 1.1e5 · (4/3) = 1.46667e5 /s², f_1 = 382.971 / 2π = 60.952 Hz
    curve = StiffnessCurve(Q_(29, "N*m"), Q_(108, "N*m"), Q_(6.7e4, "N*m/rad"), Q_(1.1e5, "N*m/rad"),
                           Q_(1.2e5, "N*m/rad"))
    slopes = band_slope(curve, Q_([10, 60], "N*m"))
    first = [modes(Q_([3, 1], "kg*m**2"), Q_([c], "N*m/rad")).natural_frequencies.m_as("Hz")[0]
             for c in slopes.m_as("N*m/rad")]
    assert first == pytest.approx([47.569, 60.952], abs=1e-3)
    assert first[0] == pytest.approx(math.sqrt(6.7e4 * 4 / 3) / (2 * math.pi), rel=1e-12)
    # The lower working torque governs: its first mode is the lower.
    assert min(first) == first[0]


def test_loop_model_is_soft_at_low_torque():
    # NPT035-10 (C_t21 = 22 N·m/arcmin, 8 arcmin, T_2N = 110 N·m) with the loop model's defaults:
    # e'(T) = 1/C + (φ_s / T_s) sech²(T / T_s), φ_s / T_s = 0.15 T_N / (C · 0.08 T_N) = 1.875 / C.
    # At 3 N·m: sech²(3 / 8.8) = 1 / cosh²(0.34091) = 0.89207, so the slope is 1 / (1 + 1.875 · 0.89207)
    # = 0.3741 of C (the gap's tanh adds 5e-6 of it at 3 N·m, below the tolerance).
    m = LoopModel(Q_(22, "N*m/arcmin"), Q_(8, "arcmin"), Q_(110, "N*m"))
    share = (loop_slope(m, Q_(3, "N*m")) / m.stiffness).m_as("")
    assert share == pytest.approx(1 / (1 + 1.875 / math.cosh(3 / 8.8) ** 2), rel=1e-3)
    assert share == pytest.approx(0.3741, abs=1e-3)


def test_inertia_matching_load():
    # The example: the coupling 0.5, the gearbox's J_1 0.93, the table 1500 kg·cm² behind i = 10:
    # J_Lm = 0.5 + 0.93 + 15 = 16.43 kg·cm²; over the rotor's 1.74 kg·cm², λ = 9.443.
    J = two_mass_load(J_K=Q_(0.5, KG_CM2), J_1=Q_(0.93, KG_CM2), J_L=Q_(1500, KG_CM2), i=Q_(10, ""))
    assert J.m_as(KG_CM2) == pytest.approx(16.43, rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(0.1, 100), min_size=2, max_size=6), st.data())
def test_anti_resonances_interlace_the_resonances(inertias, data):
    springs = data.draw(st.lists(st.floats(100, 1e5), min_size=len(inertias) - 1, max_size=len(inertias) - 1))
    m = modes(Q_(inertias, KG_CM2), Q_(springs, "N*m/rad"))
    f, z = m.natural_frequencies.m_as("Hz"), m.anti_resonances.m_as("Hz")
    # Holding the motor adds a constraint: each anti-resonance lies between neighbouring resonances
    # (the rigid-body mode at 0 Hz first), Cauchy's interlacing theorem.
    below = np.concatenate(([0.0], f[:-1]))
    assert np.all(z >= below * (1 - 1e-9)) and np.all(z <= f * (1 + 1e-9))


@settings(max_examples=25, deadline=None)
@given(st.floats(0.5, 50), st.floats(0.5, 500), st.floats(1e2, 1e5))
def test_two_mass_ratio_is_root_of_one_plus_lambda(J_M, J_L, C):
    m = modes(Q_([J_M, J_L], KG_CM2), Q_([C], "N*m/rad"))
    ratio = m.natural_frequencies.m_as("Hz")[0] / m.anti_resonances.m_as("Hz")[0]
    assert ratio == pytest.approx(math.sqrt(1 + J_L / J_M), rel=1e-9)


def test_frequency_response_marks_resonance_and_anti_resonance():
    inertias, springs = Q_([2, 8], KG_CM2), Q_([1000], "N*m/rad")
    m = modes(inertias, springs)
    f_r, f_ar = m.natural_frequencies.m_as("Hz")[0], m.anti_resonances.m_as("Hz")[0]
    r = frequency_response(inertias, springs, Q_([1.0, f_ar, f_r, 5 * f_r], "Hz"))
    rigid = 1 / (2 * math.pi * np.array([1.0, f_ar, f_r, 5 * f_r]) * 10e-4)  # the chain as one body
    # Far below the mode the motor sees the one body (10 kg·cm²), far above its rotor alone (2 of them).
    assert r.magnitude[0] == pytest.approx(rigid[0], rel=1e-4)
    assert r.magnitude[3] == pytest.approx(rigid[3] * 10 / 2, rel=0.05)
    # A notch at the anti-resonance, a peak at the resonance.
    assert r.magnitude[1] < 0.1 * rigid[1] and r.magnitude[2] > 10 * rigid[2]
    assert r.phase[0] == pytest.approx(-90, abs=0.1)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.floats(0.5, 500), min_size=2, max_size=5), st.floats(1e2, 1e5), st.floats(0, 0.3))
def test_frequency_response_is_python_controls(inertias, spring, damping):
    # The reference: python-control's control.frequency_response of the same model (control.ss of
    # state_space), which the package evaluates itself in numpy to keep python-control out of a case.
    import control

    from calc.domain.dynamics import state_space

    J, C = Q_(inertias, KG_CM2), Q_([spring] * (len(inertias) - 1), "N*m/rad")
    f = np.geomspace(0.5, 5e3, 40)
    mine = frequency_response(J, C, Q_(f, "Hz"), damping=max(damping, 1e-3))
    theirs = control.frequency_response(state_space(J, C, max(damping, 1e-3)), 2 * np.pi * f)
    np.testing.assert_allclose(mine.magnitude, np.asarray(theirs.magnitude).reshape(-1), rtol=1e-9)
    np.testing.assert_allclose(mine.phase, np.degrees(np.asarray(theirs.phase).reshape(-1)), rtol=0, atol=1e-7)


def test_an_undamped_chain_at_its_resonance_is_infinite():
    # ζ = 0: the pole pair lies on the imaginary axis at f_r = 397.887 Hz (test_two_masses_by_hand).
    J, C = Q_([2, 8], KG_CM2), Q_([1000], "N*m/rad")
    f_r = modes(J, C).natural_frequencies.m_as("Hz")[0]
    r = frequency_response(J, C, Q_([1.0, f_r], "Hz"), damping=0)
    assert r.magnitude[0] == pytest.approx(1 / (2 * math.pi * 10e-4), rel=1e-4) and r.magnitude[1] > 1e12


def test_a_case_and_its_frequency_response_need_no_python_control():
    # python-control and the SciPy parts it imports (pint imports SciPy's top, 8 ms) take longer to
    # import than the design review's first page takes to compute; the response is evaluated without
    # them (a fresh interpreter: what a kernel imports).
    import subprocess
    import sys

    code = ("import sys; from calc.sections import evaluate; from calc.sections.case import read_case;"
            " r = evaluate(read_case('cases/indexing-table.toml'))['dynamics'].response;"
            " assert r.magnitude.size > 100, r;"
            " print(sorted(set(sys.modules) & {'control', 'scipy.signal', 'scipy.linalg'}))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"


def test_torque_reversals():
    assert torque_reversals(Q_([7.8, 3.0, -2.3, 0.0], "N*m")) == 2
    assert torque_reversals(Q_([5.0, 0.0, 3.0, 0.0], "N*m")) == 0  # the flanks stay in contact
    assert torque_reversals(Q_([1.0, -1.0, 1.0, -1.0], "N*m")) == 4
    assert torque_reversals(Q_([0.0, 0.0], "N*m")) == 0


def test_bad_chains_are_one_sentence():
    with pytest.raises(CalcError, match="expected n >= 2 masses and n - 1 springs"):
        modes(Q_([2], KG_CM2), Q_([], "N*m/rad"))
    with pytest.raises(CalcError, match="above zero"):
        modes(Q_([2, 0], KG_CM2), Q_([10], "N*m/rad"))
    with pytest.raises(CalcError, match="damping ratio"):
        frequency_response(Q_([2, 8], KG_CM2), Q_([1000], "N*m/rad"), Q_([1.0], "Hz"), damping=1.5)
    with pytest.raises(CalcError, match="frequencies above zero"):
        frequency_response(Q_([2, 8], KG_CM2), Q_([1000], "N*m/rad"), Q_([0.0], "Hz"))


def test_optimal_ratio_of_an_inertial_load():
    # The example's table, 1500 kg·cm², behind the rotor 1.74, the coupling 0.5 and NPT035-10's J_1 0.93:
    # J_in = 3.17 kg·cm², i_opt = √(1500 / 3.17) = √473.19 = 21.753.
    from calc.domain.ratios import optimal_ratio

    i = optimal_ratio(J_L=Q_(1500, KG_CM2), J_in=Q_(3.17, KG_CM2)).m_as("")
    assert i == pytest.approx(21.753, abs=1e-3)


@settings(max_examples=30, deadline=None)
@given(st.floats(1e-2, 1e4), st.floats(0.1, 100))
def test_optimal_ratio_needs_the_least_torque(J_L, J_in):
    # T = (J_in · i + J_L / i) · α_2 for an inertial load: least at i_opt, more on either side.
    from calc.domain.ratios import optimal_ratio

    i = optimal_ratio(J_L=Q_(J_L, KG_CM2), J_in=Q_(J_in, KG_CM2)).m_as("")

    def torque(x):
        return J_in * x + J_L / x

    assert torque(i) <= min(torque(0.9 * i), torque(1.1 * i))
    assert torque(i) == pytest.approx(2 * math.sqrt(J_L * J_in), rel=1e-9)
