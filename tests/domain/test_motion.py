"""Motion laws (calc.domain.motion) and mechanisms (calc.domain.mechanism): each formula against a hand
calculation written out here, and the laws as hypothesis properties."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc.sections.case import read_case
from calc.domain.mechanism import J_L_linear, Mechanism, T_2_linear, T_2_rotary, phi_2, r_diameter, r_lead
from calc.domain.cycle import ACCEL, CONST, DECEL, PAUSE
from calc.domain.motion import Move, alpha_2max, omega_2max, record_samples, sample
from calc.domain.profile import segments
from calc.domain.profile import T_2m, n_2m
from calc.sections import evaluate
from calc.core.units import Q_


def test_peak_speed_and_acceleration_of_a_trapezoid_by_hand():
    # 90° = π/2 rad in 0.5 s with 0.1 s ramps: ω = (π/2) / (0.5 − 0.1) = 3.926991 rad/s = 37.5 rpm.
    w = omega_2max(phi_2=Q_(90, "deg"), t_m=Q_(0.5, "s"), t_a=Q_(0.1, "s"), t_d=Q_(0.1, "s"))
    assert w.m_as("rpm") == pytest.approx(37.5, rel=1e-12)
    # With a jerk time of 0.02 s: α = 3.926991 / (0.1 − 0.02) = 49.087385 rad/s².
    a = alpha_2max(omega_2max=w, t_r=Q_(0.1, "s"), t_j=Q_(0.02, "s"))
    assert a.m_as("rad/s**2") == pytest.approx(49.087385, rel=1e-7)


def test_an_s_curve_reaches_its_speed_and_distance_by_hand():
    # 1 rad in 1 s, ramps 0.4 s with 0.1 s of jerk: ω = 1 / (1 − 0.4) = 5/3 rad/s, α = (5/3) / 0.3 = 50/9 rad/s²,
    # jerk = α / 0.1 = 500/9 rad/s³. The speed after the ramp: two jerk ramps of α·0.1/2 and α·0.2 between = α·0.3 =
    # 5/3.
    move = Move(1.0, 1.0, 0.4, 0.4, 0.1)
    s = sample([move])
    assert s.acceleration.max() == pytest.approx(50 / 9, rel=1e-12)
    assert s.jerk.max() == pytest.approx(500 / 9, rel=1e-12)
    assert s.speed.max() == pytest.approx(5 / 3, rel=1e-12)  # the constant run
    assert (s.speed * s.dt).sum() == pytest.approx(1.0, rel=1e-9)  # the distance
    assert s.position[-1] == pytest.approx(1.0, rel=1e-6)
    assert s.dt.sum() == pytest.approx(1.0, rel=1e-12)


def test_a_triangle_has_no_constant_run():
    s = sample([Move(2.0, 1.0, 0.5, 0.5)])
    # ω = 2 / (1 − 0.5) = 4 rad/s, reached at the middle only.
    assert [int(p) for p in s.segment_phases] == [ACCEL, DECEL]
    assert s.speed.max() == pytest.approx(4.0, rel=1e-3)


def test_transmission_radius_and_reflected_inertia_by_hand():
    # r = 20 mm / 2π = 3.183099 mm; J_L = 50 kg · (3.183099e-3 m)² + 1 kg·cm² = 5.066059 + 1 = 6.066059 kg·cm².
    r = r_lead(p=Q_(20, "mm"))
    assert r.m_as("mm") == pytest.approx(3.183099, rel=1e-6)
    assert J_L_linear(m=Q_(50, "kg"), m_c=Q_(0, "kg"), r=r,
                      J_M=Q_(1, "kg*cm**2")).m_as("kg*cm**2") == pytest.approx(6.066059, rel=1e-6)
    # A 30 kg counterweight travels as far: J_L = 80 kg · r² + 1 kg·cm² = 8.105695 + 1 = 9.105695 kg·cm².
    assert J_L_linear(m=Q_(50, "kg"), m_c=Q_(30, "kg"), r=r,
                      J_M=Q_(1, "kg*cm**2")).m_as("kg*cm**2") == pytest.approx(9.105695, rel=1e-6)
    assert r_diameter(d=Q_(50, "mm")).m_as("mm") == 25.0
    # 100 mm of travel is 100 / 3.183099 = 31.4159 rad = 1800° of the screw.
    assert phi_2(s=Q_(100, "mm"), r=r).m_as("deg") == pytest.approx(1800.0, rel=1e-12)


def test_the_torque_formulas_by_hand():
    # Table: 0.15 kg·m² · 40 rad/s² − (2 + 3) N·m moving back = 6 − 5 = 1 N·m.
    t = T_2_rotary(J_L=Q_(1500, "kg*cm**2"), alpha_2=Q_(40, "rad/s**2"), s_v=-1, T_f=Q_(2, "N*m"), T_p=Q_(3, "N*m"))
    assert t.m_as("N*m") == pytest.approx(1.0, rel=1e-12)
    # Screw (η 0.8, η' 0.75): 100 N · 5 mm / 0.8 = 0.625 N·m driving, 100 N · 5 mm · 0.75 = 0.375 N·m driven back;
    # + 1e-4 kg·m² · 1000 rad/s² = 0.1.
    common = dict(F=Q_(100, "N"), r=Q_(5, "mm"), eta=0.8, eta_reverse=0.75, J_M=Q_(1, "kg*cm**2"),
                  alpha_2=Q_(1000, "rad/s**2"), s_v=1, T_d=Q_(0, "N*m"))
    assert T_2_linear(d_P=1, **common).m_as("N*m") == pytest.approx(0.725, rel=1e-12)
    assert T_2_linear(d_P=-1, **common).m_as("N*m") == pytest.approx(0.475, rel=1e-12)
    # A rack or a belt (η' = η = 0.8): 100 N · 5 mm · 0.8 = 0.4 N·m driven back, + 0.1.
    assert T_2_linear(d_P=-1, **{**common, "eta_reverse": 0.8}).m_as("N*m") == pytest.approx(0.5, rel=1e-12)
    # A drag torque of 0.2 N·m against the motion, outside the efficiency: + 0.2 moving forwards, − 0.2 back.
    assert T_2_linear(d_P=1, **{**common, "T_d": Q_(0.2, "N*m")}).m_as("N*m") == pytest.approx(0.925, rel=1e-12)
    assert T_2_linear(d_P=-1,
                      **{**common, "s_v": -1, "T_d": Q_(0.2, "N*m")}).m_as("N*m") == pytest.approx(0.275, rel=1e-12)


def test_a_drag_torque_and_a_counterweight_on_a_vertical_screw_by_hand():
    # A 20 kg load on a vertical screw (lead 10 mm: r = 1.591549 mm, η 0.9, no friction), 15 kg
    # counterweight, 0.3 N·m drag. Lifting at constant speed: F = (20 − 15) kg · 9.80665 = 49.033 N;
    # T_2 = 49.033 · 1.591549e-3 / 0.9 + 0.3 = 0.086710 + 0.3 = 0.386710 N·m. Held at rest: the load
    # pulls back through the screw, with η' = 2 − 1/0.9 = 0.888889: 49.033 · 1.591549e-3 · 0.888889 = 0.069368 N·m,
    # and no drag.
    # Accelerating up at 100 rad/s² of the screw (a = 0.159155 m/s²): F = 35 kg · 0.159155 + 49.033
    # = 54.603 N; T_2 = 54.603 · 1.591549e-3 / 0.9 + 2e-4 · 100 + 0.3 = 0.096560 + 0.02 + 0.3 = 0.416560 N·m.
    screw = Mechanism("ball-screw", mass=Q_(20, "kg"), friction_coefficient=Q_(0, ""), incline=Q_(90, "deg"),
                      force=Q_(0, "N"),
                      eta=Q_(0.9, ""), lead=Q_(10, "mm"), own_inertia=Q_(2, "kg*cm**2"), counterweight=Q_(15, "kg"),
                      drag_torque=Q_(0.3, "N*m"))
    T = screw.torque(np.array([10.0, 0.0, 10.0]), np.array([0.0, 0.0, 100.0]))
    assert T == pytest.approx([0.386709, 0.069368, 0.416561], rel=1e-5)
    # J_L = 35 kg · r² + 2 kg·cm² = 35 · 2.533030e-6 m² = 0.886560 + 2 = 2.886560 kg·cm².
    assert screw.load_inertia.m_as("kg*cm**2") == pytest.approx(2.886560, rel=1e-6)


VERTICAL_SCREW = Mechanism(
    "ball-screw", mass=Q_(20, "kg"), friction_coefficient=Q_(0.05, ""), incline=Q_(90, "deg"), force=Q_(0, "N"),
    eta=Q_(0.9, ""), lead=Q_(10, "mm"), own_inertia=Q_(2, "kg*cm**2"),
)


def test_a_vertical_ball_screw_up_down_and_held_by_hand():
    m = VERTICAL_SCREW
    r = 0.01 / (2 * np.pi)  # 1.591549 mm
    up = Move(m.to_output(Q_(100, "mm")).m_as("rad"), 0.5, 0.1, 0.1)
    down = Move(-up.distance, 0.5, 0.1, 0.1)
    s = sample([up, down, Move(0.0, 0.5)])
    g = segments(s, m.torque(s.speed, s.acceleration))
    # v = 0.1 m / (0.5 − 0.1) s = 0.25 m/s, a = 2.5 m/s², α_2 = 2.5 / r = 1570.796 rad/s²; J_M·α_2 = 2e-4 · 1570.796 =
    # 0.314159 N·m.
    # Gravity 20 · 9.80665 = 196.133 N (cos 90° = 0: no guide friction on a vertical axis).
    Ja = 2e-4 * 2.5 / r
    eta_r = 2 - 1 / 0.9                                   # η' = 0.888889: driven back, the screw's reverse efficiency
    # driving: 246.133 N · r / 0.9 + 0.314159 = 0.435259 + 0.314159 = 0.749418 N·m
    up_accel = (20 * 2.5 + 196.133) * r / 0.9 + Ja
    up_const = 196.133 * r / 0.9                          # 0.346839 N·m
    # still driving (F = 146.133 N up): 0.258420 − 0.314159 = −0.055739 N·m
    up_decel = (196.133 - 50) * r / 0.9 - Ja
    down_accel = (196.133 - 50) * r * eta_r - Ja         # the load drives back: 0.206736 − 0.314159 = −0.107423 N·m
    down_const = 196.133 * r * eta_r                      # 0.277471 N·m
    # braking a falling load, still driven back: 0.348207 + 0.314159 = 0.662366
    down_decel = (196.133 + 50) * r * eta_r + Ja
    held = 196.133 * r * eta_r                            # at rest the load pulls back through the screw: 0.277471 N·m
    assert g.torque.tolist() == pytest.approx([up_accel, up_const, up_decel, down_accel, down_const, down_decel, held],
                                              rel=1e-5)
    assert up_accel == pytest.approx(0.749418, rel=1e-6) and down_decel == pytest.approx(0.662366, rel=1e-6)
    braked = Mechanism(**{**VERTICAL_SCREW.__dict__, "holding_brake": True})
    assert segments(s, braked.torque(s.speed, s.acceleration)).torque[-1] == 0.0


def test_a_belt_axis_with_friction_and_process_force_by_hand():
    belt = Mechanism("belt", mass=Q_(10, "kg"), friction_coefficient=Q_(0.1, ""), incline=Q_(0, "deg"),
                     force=Q_(20, "N"),
                     eta=Q_(0.95, ""), diameter=Q_(50, "mm"), own_inertia=Q_(5, "kg*cm**2"))
    s = sample([Move(belt.to_output(Q_(500, "mm")).m_as("rad"), 1.0, 0.25, 0.25)])
    g = segments(s, belt.torque(s.speed, s.acceleration))
    # v = 0.5 / 0.75 = 0.666667 m/s, a = 2.666667 m/s², r = 25 mm, α_2 = 106.6667 rad/s².
    # Accel: F = 10 · 2.666667 + 0.1 · 10 · 9.80665 + 20 = 56.473317 N; T = 56.473317 · 0.025 / 0.95 + 5e-4 · 106.6667 =
    # 1.539474 N·m.
    # Const: F = 29.80665 N, T = 0.784386 N·m. Decel: F = 3.139983 N (still driving), T = 0.082631 − 0.053333 = 0.029297
    # N·m.
    assert g.torque.tolist() == pytest.approx([1.539474, 0.784386, 0.029297], abs=2e-6)
    assert belt.load_inertia.m_as("kg*cm**2") == pytest.approx(10 * 2.5**2 + 5)  # 62.5 + 5 = 67.5 kg·cm²


def test_s_curve_integrals_at_the_default_samples_are_accurate():
    # The docstring's claim: the relative error of an S-curve's segment means is below 1e-6 at the default.
    table = Mechanism("rotary", inertia=Q_(1500, "kg*cm**2"), friction_torque=Q_(2, "N*m"), process_torque=Q_(0, "N*m"))
    moves = [Move(np.pi / 2, 0.5, 0.15, 0.1, 0.05), Move(0.0, 0.3)]
    fine, default = sample(moves, samples=2_000_000), sample(moves)
    a, b = (segments(s, table.torque(s.speed, s.acceleration)) for s in (fine, default))
    assert b.torque == pytest.approx(a.torque, rel=1e-6)
    assert b.speed == pytest.approx(a.speed, rel=1e-9)


# --- properties ------------------------------------------------------------------------------

times = st.floats(0.05, 5.0)
shares = st.floats(0.05, 0.5)


def _table_torques(moves, friction=2.0):
    table = Mechanism("rotary", inertia=Q_(1500, "kg*cm**2"), friction_torque=Q_(friction, "N*m"),
                      process_torque=Q_(0, "N*m"))
    s = sample(moves, samples=2000)
    return s, table.torque(s.speed, s.acceleration)


@settings(max_examples=60, deadline=None)
@given(distance=st.floats(0.1, 50.0), time=times, accel=shares, decel=shares, dwell=times)
def test_a_trapezoids_sampled_and_segment_forms_agree(distance, time, accel, decel, dwell):
    s, T = _table_torques([Move(distance, time, accel * time, decel * time), Move(0.0, dwell)])
    g = segments(s, T)
    moving = g.phase != PAUSE
    by_segments = T_2m(n_2k=Q_(g.speed[moving], "rad/s"), t_k=Q_(g.duration[moving], "s"),
                       T_2k=Q_(g.torque[moving], "N*m")).m_as("N*m")
    on = s.phase != PAUSE
    w = np.abs(s.speed[on]) * s.dt[on]
    integral = np.cbrt(np.sum(w * np.abs(T[on]) ** 3) / np.sum(w))
    assert by_segments == pytest.approx(integral, rel=1e-9)
    mean = n_2m(n_2k=Q_(g.speed[moving], "rad/s"), t_k=Q_(g.duration[moving], "s")).m_as("rad/s")
    assert mean == pytest.approx(np.sum(w) / np.sum(s.dt[on]), rel=1e-9)
    # A trapezoid's torque is constant in each phase: the segment holds exactly that value.
    for k, phase in enumerate(g.phase):
        assert T[s.segment == k] == pytest.approx(g.torque[k], rel=1e-9, abs=1e-12)


@settings(max_examples=60, deadline=None)
@given(distance=st.floats(0.1, 50.0), time=times, accel=shares, jerk=st.one_of(st.just(0.0), st.floats(0.01, 0.5)))
def test_doubling_every_time_quarters_the_acceleration_torque(distance, time, accel, jerk):
    one = Move(distance, time, accel * time, accel * time, jerk * accel * time)
    two = Move(distance, 2 * time, 2 * accel * time, 2 * accel * time, 2 * jerk * accel * time)
    (s1, T1), (s2, T2) = _table_torques([one]), _table_torques([two])
    friction = 2.0
    peak = lambda s, T: np.max(T[s.phase == ACCEL]) - friction  # noqa: E731 (J·α only)
    assert peak(s2, T2) == pytest.approx(peak(s1, T1) / 4, rel=1e-9)


@settings(max_examples=60, deadline=None)
@given(distance=st.floats(0.1, 50.0), time=times, accel=shares, dwell=times)
def test_a_dwell_adds_no_rms_torque_but_lowers_the_rms(distance, time, accel, dwell):
    s1, T1 = _table_torques([Move(distance, time, accel * time, accel * time)])
    s2, T2 = _table_torques([Move(distance, time, accel * time, accel * time), Move(0.0, dwell)])
    square = lambda s, T: np.sum(T**2 * s.dt)  # noqa: E731
    assert square(s2, T2) == pytest.approx(square(s1, T1), rel=1e-9)  # nothing added while the table rests
    rms1, rms2 = (np.sqrt(square(s, T) / s.dt.sum()) for s, T in ((s1, T1), (s2, T2)))
    assert rms2 < rms1
    assert rms2 == pytest.approx(rms1 * np.sqrt(time / (time + dwell)), rel=1e-9)


AXIS = """
title = "linear axis"
[mechanism]
type = "ball-screw"
mass = "{mass}"
lead = "{lead}"
screw_inertia = "{screw_inertia}"
eta = {eta}
friction_coefficient = {mu}
incline = "{incline} deg"
force = "{force}"
[[move]]
distance = "{distance}"
time = "{time} s"
accel_time = "{accel} s"
[[move]]
distance = "-{distance}"
time = "{time} s"
accel_time = "{accel} s"
[[move]]
dwell = "0.3 s"
"""

LB, INCH, LBF = 0.45359237, 0.0254, 4.4482216152605


@settings(max_examples=25, deadline=None)
@given(mass=st.floats(1, 500), lead=st.floats(2, 50), eta=st.floats(0.5, 1.0),
       mu=st.one_of(st.just(0.0), st.floats(0.01, 0.3)),
       incline=st.integers(-90, 90), force=st.one_of(st.just(0.0), st.floats(1, 2000)), distance=st.floats(5, 1000),
       time=st.floats(0.2, 3), accel=shares)
def test_the_same_axis_in_si_and_inch_pound_units_gives_the_same_torques(tmp_path_factory, mass, lead, eta, mu, incline,
                                                                         force, distance, time, accel):
    folder = tmp_path_factory.mktemp("axis")
    common = dict(eta=repr(eta), mu=repr(mu), incline=repr(incline), time=repr(time), accel=repr(accel * time))
    si = AXIS.format(mass=f"{mass!r} kg", lead=f"{lead!r} mm", screw_inertia="1.5 kg*cm**2", force=f"{force!r} N",
                     distance=f"{distance!r} mm", **common)
    inch = AXIS.format(mass=f"{mass / LB!r} lb", lead=f"{lead / 25.4!r} in",
                       screw_inertia=f"{1.5e-4 / (LB * INCH**2)!r} lb*in**2",
                       force=f"{force / LBF!r} lbf", distance=f"{distance / 25.4!r} in", **common)
    out = []
    for name, text in (("si.toml", si), ("inch.toml", inch)):
        (folder / name).write_text(text)
        out.append(evaluate(read_case(folder / name)).to_json()["motion"])
    torques = [[s["torque"]["value"] for s in m["segments"]] for m in out]
    scale = max(abs(t) for t in torques[0])
    assert torques[1] == pytest.approx(torques[0], rel=1e-9, abs=1e-9 * scale)
    assert out[1]["J_L"]["value"] == pytest.approx(out[0]["J_L"]["value"], rel=1e-9)


def test_a_noisy_record_of_an_s_curve_keeps_its_four_phases():
    # A record every 10 ms of a quarter-turn S-curve (0.5 s, ramps 0.15 s, jerk 0.03 s) and a 1.0 s dwell, with
    # seeded noise of 0.2 rpm: the noise must not cut the constant run; the phases come out within a sample or two.
    s = sample([Move(np.pi / 2, 0.5, 0.15, 0.15, 0.03), Move(0.0, 1.0)])
    times = np.arange(0, 1.5 + 1e-9, 0.01)
    speed = np.interp(times, s.t, s.speed) + np.random.default_rng(7).normal(0, 0.2 * np.pi / 30, times.size)
    speed[times > 0.5] = 0.0
    record = record_samples(times, speed)
    assert [int(p) for p in record.segment_phases] == [ACCEL, CONST, DECEL, PAUSE]
    assert record.durations == pytest.approx([0.15, 0.2, 0.15, 1.0], abs=0.021)


def test_the_steps_of_a_move_decelerating_slower_than_it_accelerates(tmp_path):
    # A quarter turn in 1 s, accelerating in 0.1 s and decelerating in 0.2 s, no jerk, a table of
    # 1 kg·m² without friction. By hand: ω_2max = (π/2) / (1 − 0.1/2 − 0.2/2) = 1.84800 rad/s,
    # α = 1.84800 / 0.1 = 18.4800 rad/s², decelerating 1.84800 / 0.2 = 9.24000 rad/s²; the torques
    # J_L·α: 18.48 N·m while accelerating, −9.24 N·m while decelerating.
    case = tmp_path / "table.toml"
    case.write_text('title = "table"\n[mechanism]\ntype = "rotary"\ninertia = "1 kg*m**2"\n'
                    '[[move]]\ndistance = "90 deg"\ntime = "1 s"\naccel_time = "0.1 s"\ndecel_time = "0.2 '
                    's"\n[[move]]\ndwell = "1 s"\n')
    steps = dict(evaluate(read_case(case)).sections["motion"].steps)
    omega = (np.pi / 2) / 0.85
    assert steps["Move 1: peak output speed"].result.m_as("rad/s") == pytest.approx(omega, rel=1e-12)
    assert steps["Move 1: peak output deceleration"].result.m_as("rad/s**2") == pytest.approx(omega / 0.2, rel=1e-12)
    torque = {phase: step.result.m_as("N*m") for title, step in steps.items()
              for phase in ("acceleration", "deceleration")
              if title.startswith(f"Move 1, {phase}: output torque")}
    assert torque == pytest.approx({"acceleration": omega / 0.1, "deceleration": -omega / 0.2}, rel=1e-12)
