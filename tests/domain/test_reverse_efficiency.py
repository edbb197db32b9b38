"""A screw driven back by its load (calc.domain.mechanism.eta_reverse): the reverse efficiency η'
against hand calculations and the textbook relation of lead and friction angles, its laws as
hypothesis properties, the case key and the self-locking screw."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from calc.core.errors import CalcError
from calc.core.units import Q_
from calc.domain.mechanism import Mechanism, converted, eta_reverse
from calc.domain.motor import motor_torque
from calc.sections import evaluate
from calc.sections.case import read_case


def test_the_reverse_efficiency_by_hand():
    # η = 0.9: η' = 2 − 1/0.9 = 2 − 1.111111 = 0.888889; η = 0.5: 2 − 2 = 0 (the limit of self-locking).
    assert eta_reverse(eta=0.9).m_as("") == pytest.approx(0.888889, rel=1e-6)
    assert eta_reverse(eta=0.5).m_as("") == pytest.approx(0.0, abs=1e-15)


def test_the_approximation_against_the_lead_and_friction_angles():
    # A ball screw of 10 mm lead on 16 mm: tan β = 10 / (π · 16) = 0.198944, β = 11.2517°; a rolling friction
    # angle ρ = 0.6°: η = tan β / tan(β + ρ) = 0.198944 / tan 11.8517° = 0.198944 / 0.209853 = 0.948013,
    # η' = tan(β − ρ) / tan β = tan 10.6517° / 0.198944 = 0.188079 / 0.198944 = 0.945391; 2 − 1/η = 2 − 1.054838
    # = 0.945163: 0.024 % below the exact one.
    beta, rho = math.atan(10 / (math.pi * 16)), math.radians(0.6)
    eta = math.tan(beta) / math.tan(beta + rho)
    exact = math.tan(beta - rho) / math.tan(beta)
    assert eta == pytest.approx(0.948013, rel=1e-6) and exact == pytest.approx(0.945391, rel=1e-6)
    assert eta_reverse(eta=eta).m_as("") == pytest.approx(0.945163, rel=1e-6)
    assert eta_reverse(eta=eta).m_as("") == pytest.approx(exact, rel=3e-4)


@given(eta=st.floats(0.05, 0.999))
def test_the_reverse_efficiency_is_below_the_efficiency(eta):
    # η − η' = η + 1/η − 2 = (1 − η)² / η > 0 below η = 1.
    eta_r = eta_reverse(eta=eta).m_as("")
    assert eta_r < eta
    assert eta - eta_r == pytest.approx((1 - eta) ** 2 / eta, rel=1e-9)


def test_a_loss_free_screw_is_as_efficient_both_ways():
    assert eta_reverse(eta=1.0).m_as("") == 1.0


@given(beta=st.floats(1.0, 8.0), rho=st.floats(0.1, 1.0))
def test_the_approximation_holds_for_small_angles(beta, rho):
    # Degrees: the first order error is of the angles' product, well under 2 % up to β 8°, ρ 1°.
    b, r = math.radians(beta), math.radians(rho)
    eta = math.tan(b) / math.tan(b + r)
    assert eta_reverse(eta=eta).m_as("") == pytest.approx(math.tan(b - r) / math.tan(b), abs=0.02)


def test_a_braking_phase_through_the_reverse_efficiency_by_hand():
    # A 40 kg slide on a 10 mm lead screw (r = 1.591549 mm), η 0.9, no friction, no own inertia; it brakes
    # from moving forwards at 3000 rad/s² of the screw: a = 3000 · 1.591549e-3 = 4.774648 m/s²,
    # F = −40 · 4.774648 = −190.986 N, F · v < 0: the load drives the screw back, through η' = 0.888889:
    # T_2 = −190.986 · 1.591549e-3 · 0.888889 = −0.270190 N·m (η would give −0.273563).
    screw = Mechanism("ball-screw", mass=Q_(40, "kg"), friction_coefficient=Q_(0, ""), incline=Q_(0, "deg"),
                      force=Q_(0, "N"), eta=Q_(0.9, ""), lead=Q_(10, "mm"), own_inertia=Q_(0, "kg*cm**2"))
    T_2 = screw.torque(np.array([100.0]), np.array([-3000.0]))
    assert T_2[0] == pytest.approx(-0.270190, rel=1e-5)
    # Through a gearbox i = 5, η_g 0.95, a 0.5 kg·cm² motor: α_1 = 15000 rad/s², T_1 = 5e-5 · (−15000) +
    # (−0.270190) · 0.95 / 5 = −0.75 − 0.051336 = −0.801336 N·m.
    T_1 = motor_torque(Q_(T_2, "N*m"), Q_([100.0], "rad/s"), Q_(5, ""), Q_(0.95, ""), alpha_2=Q_([-3000.0], "rad/s**2"),
                       J_motor=Q_(0.5, "kg*cm**2"), J_1=Q_(0, "kg*cm**2"))
    assert T_1.m_as("N*m")[0] == pytest.approx(-0.801336, rel=1e-5)


def test_a_given_reverse_efficiency_is_used():
    # η' = 0.7 given: held at rest, a 20 kg vertical load pulls back 196.133 N · 1.591549e-3 m · 0.7 = 0.218510 N·m.
    screw = Mechanism("ball-screw", mass=Q_(20, "kg"), friction_coefficient=Q_(0, ""), incline=Q_(90, "deg"),
                      force=Q_(0, "N"), eta=Q_(0.9, ""), reverse_efficiency=Q_(0.7, ""), lead=Q_(10, "mm"),
                      own_inertia=Q_(0, "kg*cm**2"))
    assert screw.reverse_step() is None
    assert screw.torque(np.array([0.0]), np.array([0.0]))[0] == pytest.approx(0.218510, rel=1e-5)


def test_a_rack_is_driven_back_through_its_efficiency():
    rack = Mechanism("rack-pinion", mass=Q_(20, "kg"), friction_coefficient=Q_(0, ""), incline=Q_(90, "deg"),
                     force=Q_(0, "N"), eta=Q_(0.9, ""), diameter=Q_(20, "mm"), own_inertia=Q_(0, "kg*cm**2"))
    # 196.133 N · 10 mm · 0.9 = 1.765197 N·m held; no reverse step of its own.
    assert rack.reverse_step() is None and not rack.self_locking
    assert rack.torque(np.array([0.0]), np.array([0.0]))[0] == pytest.approx(1.765197, rel=1e-6)


LOCKING = """title = "Lifting table on a lead screw"
[mechanism]
type = "ball-screw"
mass = "20 kg"
lead = "10 mm"
eta = 0.4
incline = "90 deg"
[[move]]
distance = "50 mm"
time = "1 s"
accel_time = "0.2 s"
[[move]]
dwell = "1 s"
[[move]]
distance = "-50 mm"
time = "1 s"
accel_time = "0.2 s"
[[move]]
dwell = "1 s"
"""


def test_a_self_locking_screw_is_driven_down_and_holds_its_load(write_case):
    # η 0.4: η' = 2 − 2.5 = −0.5. Lowering at constant speed, the load cannot drive the screw back: the motor
    # drives it down with 196.133 N · 1.591549e-3 m · (−0.5) = −0.156078 N·m, with the motion (power into the
    # screw). At rest it holds the load itself: no torque.
    result = evaluate(read_case(write_case(LOCKING)))["motion"]
    screw = result.motion.mechanism
    assert screw.self_locking and screw.reverse.m_as("") == pytest.approx(-0.5, rel=1e-12)
    const = [g for g in result.segments if g.phase == "const"]
    pauses = [g for g in result.segments if g.phase == "pause"]
    assert const[1].speed.value < 0
    assert const[1].torque.value == pytest.approx(-0.156078, rel=1e-5)
    assert [g.torque.value for g in pauses] == [0.0, 0.0]
    assert any("self-locking" in line and "η' = -0.5" in line for line in result.summary_lines())
    assert any(title == "Reverse efficiency of the screw" for title, _ in result.steps)


@pytest.mark.parametrize("value, found", [("1.2", "1.2"), ("0", "0")])
def test_a_reverse_efficiency_outside_its_range_is_refused(write_case, value, found):
    text = LOCKING.replace("eta = 0.4", f"eta = 0.9\nreverse_efficiency = {value}")
    with pytest.raises(CalcError, match=r"mechanism\.reverse_efficiency.*expected an efficiency.*found " + found):
        read_case(write_case(text))


def test_a_reverse_efficiency_is_a_key_of_screws_only(write_case):
    text = LOCKING.replace('type = "ball-screw"', 'type = "belt"')
    text = text.replace('lead = "10 mm"', 'pulley_diameter = "40 mm"')
    with pytest.raises(CalcError, match="reverse_efficiency"):
        read_case(write_case(text.replace("eta = 0.4", "eta = 0.9\nreverse_efficiency = 0.8")))


def test_a_given_reverse_efficiency_stays_with_a_screw_and_is_named_when_left():
    screw = Mechanism("ball-screw", mass=Q_(20, "kg"), friction_coefficient=Q_(0, ""), incline=Q_(90, "deg"),
                      force=Q_(0, "N"), eta=Q_(0.9, ""), reverse_efficiency=Q_(0.7, ""), lead=Q_(10, "mm"),
                      own_inertia=Q_(0, "kg*cm**2"))
    other, left = converted(screw, "ball-screw", Q_(20, "mm"))
    assert other.reverse.m_as("") == 0.7 and left == []
    belt, left = converted(screw, "belt", Q_(40, "mm"))
    assert belt.reverse.m_as("") == 0.9 and left == ["the screw's reverse efficiency 0.7: a belt is driven back "
                                                     "through eta"]
