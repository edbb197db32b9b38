"""Every motor with every gearbox: the moments of a cycle give the same motor torque as a pass over
its samples per pair (calc.domain.motor.motor_load, which evaluates T_1_drive, T_1_back and T_1rms)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import Q_
from calc.domain import combinations
from calc.domain.combinations import CycleMoments, Envelope, motor_torques, search
from calc.domain.gearbox import INERTIA_RATIO_LIMIT
from calc.domain.motor import motor_load

finite = st.floats(-500, 500, allow_nan=False)


def brute_envelope(T, alpha, x):
    return np.max(np.abs(np.asarray(T)[None, :] + np.outer(x, alpha)), axis=1, initial=0.0)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(finite, st.floats(-50, 50, allow_nan=False)), min_size=0, max_size=40),
       st.lists(st.floats(0, 1e4, allow_nan=False), min_size=1, max_size=20))
def test_the_envelope_is_the_largest_magnitude_of_every_line(lines, xs):
    # E(x) = max_k |T_k + x α_k| for x >= 0, against the maximum over every sample.
    T = np.array([t for t, _ in lines], float)
    alpha = np.array([a for _, a in lines], float)
    x = np.array(xs)
    assert Envelope.of(T, alpha)(x) == pytest.approx(brute_envelope(T, alpha, x), rel=1e-9, abs=1e-9)


def test_the_envelope_by_hand():
    # Lines ±(10 - 2x) and ±(4 + x): at x = 0 the largest is 10; 10 - 2x and 4 + x cross at x = 2
    # (value 6), 4 + x leads to x = 14 (18 against |10 - 28| = 18), and 2x - 10 beyond.
    e = Envelope.of(np.array([10.0, 4.0]), np.array([-2.0, 1.0]))
    assert e(np.array([0.0, 2.0, 7.0, 14.0, 20.0])).tolist() == pytest.approx([10.0, 6.0, 11.0, 18.0, 30.0])


@given(st.lists(finite, min_size=0, max_size=20), st.floats(-50, 50, allow_nan=False))
def test_an_envelope_of_one_acceleration_is_one_line_read_without_a_search(torques, accel):
    # Every sample of one acceleration (a typed cycle: none): the lines ±(T_k + x α) of one slope keep
    # the highest each, and the zero line; one of them holds for every x >= 0, read as it is.
    T, alpha = np.array(torques, float), np.full(len(torques), accel)
    e = Envelope.of(T, alpha)
    x = np.array([[0.0], [0.5], [3.0], [1e3]])  # a column, as the screen reads it for each gearbox row
    got = e(x)
    assert got.shape == x.shape
    assert got.ravel() == pytest.approx(brute_envelope(T, alpha, x.ravel()), rel=1e-9, abs=1e-9)
    if accel == 0:
        assert len(e.breaks) == 0 and (got == np.max(np.abs(T), initial=0.0)).all()


cycles = st.integers(1, 60).flatmap(lambda n: st.tuples(
    st.lists(st.floats(1e-3, 1.0), min_size=n, max_size=n),
    st.lists(finite, min_size=n, max_size=n),
    st.lists(st.floats(-300, 300, allow_nan=False), min_size=n, max_size=n),
    st.lists(st.floats(-5e3, 5e3, allow_nan=False), min_size=n, max_size=n),
))


@settings(max_examples=150, deadline=None)
@given(cycles, st.floats(1.0, 100.0), st.floats(0.5, 1.0), st.floats(0.0, 1e-2))
def test_moments_give_the_peak_and_rms_of_a_pass_over_the_samples(cycle, i, eta, J):
    dt, T, w, a = (np.array(x, float) for x in cycle)
    reference = motor_load(Q_(dt, "s"), Q_(T, "N*m"), Q_(w, "rad/s"), Q_(i, ""), Q_(eta, ""), Q_(a, "rad/s**2"),
                           Q_(J, "kg*m**2"), Q_(0.0, "kg*m**2"))
    peak, rms = motor_torques(CycleMoments.of(dt, T, w, a), i, eta, J)
    scale = max(1.0, float(reference.peak.m_as("N*m")))
    assert float(peak) == pytest.approx(float(reference.peak.m_as("N*m")), rel=1e-9, abs=1e-9 * scale)
    assert float(rms) == pytest.approx(float(reference.rms.m_as("N*m")), rel=1e-7, abs=1e-7 * scale)


def test_a_hand_cycle_through_two_gearboxes_and_two_motors():
    # One acceleration, one braking, one hold: dt = 0.1, 0.1, 0.3 s; T_2 = 50, -30, 10 N·m;
    # ω_2 = 10, 10, 0 rad/s; α_2 = 100, -100, 0 rad/s². Through i = 10, η = 0.9 with J = 1e-4 kg·m²:
    # driving sample: 1e-4 · 10 · 100 + 50 / 9 = 0.1 + 5.5556 = 5.6556 N·m; driven back: -0.1 - 30 · 0.09
    # = -2.8 N·m; hold (T_2 ω_2 = 0 drives): 10 / 9 = 1.1111 N·m. Peak 5.6556 N·m;
    # RMS = √((5.6556² · 0.1 + 2.8² · 0.1 + 1.1111² · 0.3) / 0.5) = √((3.1985 + 0.784 + 0.3704) / 0.5) = 2.9505 N·m.
    m = CycleMoments.of([0.1, 0.1, 0.3], [50.0, -30.0, 10.0], [10.0, 10.0, 0.0], [100.0, -100.0, 0.0])
    peak, rms = motor_torques(m, np.array([[10.0], [5.0]]), np.array([[0.9], [0.9]]), np.array([[1e-4, 0.0]]))
    assert peak[0, 0] == pytest.approx(5.6556, abs=1e-4) and rms[0, 0] == pytest.approx(2.9505, abs=1e-4)
    # Without the rotor (J = 0) the peak is 50 / 9 = 5.5556 N·m; through i = 5, 50 / 4.5 = 11.111 N·m.
    assert peak[0, 1] == pytest.approx(5.5556, abs=1e-4) and peak[1, 1] == pytest.approx(11.1111, abs=1e-4)


#: The hand cycle above; its top speed 10 rad/s, its mean speed (10 · 0.1 + 10 · 0.1) / 0.5 = 4 rad/s.
SPEEDS = (10.0, 4.0)


def hand_pairs():
    """Gearbox rows: i = 10 (ranked second, size 100 N·m), i = 5 (ranked first, size 60), i = 10 failing
    its own checks. Motors, J = 1e-4 kg·m² each: A 3 N·m rated / 12 N·m peak, B 6 N·m / 20 N·m."""
    m = CycleMoments.of([0.1, 0.1, 0.3], [50.0, -30.0, 10.0], [10.0, 10.0, 0.0], [100.0, -100.0, 0.0])
    gearboxes = {"i": [10.0, 5.0, 10.0], "eta": [0.9, 0.9, 0.9], "J_1": [0.0, 0.0, 0.0], "passes": [True, True, False],
                 "peak_limit": [np.inf, np.inf, np.inf], "rank": [1.0, 0.0, 2.0], "J_L": 1e-3}
    motors = {"J": [1e-4, 1e-4], "rated_torque": [3.0, 6.0], "peak_torque": [12.0, 20.0], "max_speed": [300.0, 300.0]}
    return m, gearboxes, motors


def test_the_pick_is_the_smallest_adequate_motor_then_the_first_ranked_gearbox():
    m, gearboxes, motors = hand_pairs()
    found = search(m, SPEEDS, gearboxes, motors, INERTIA_RATIO_LIMIT)
    # At i = 5: driving 1e-4 · 5 · 100 + 50 / 4.5 = 11.161 N·m, driven back -0.05 - 30 · 0.9 / 5 = -5.45,
    # hold 10 / 4.5 = 2.222; RMS = √((11.161² · 0.1 + 5.45² · 0.1 + 2.222² · 0.3) / 0.5) = 5.815 N·m:
    # over A's 3 N·m, within B's 6. At i = 10 both pass (peak 5.66, RMS 2.95 N·m).
    assert found.rms[1, 0] == pytest.approx(5.815, abs=1e-3)
    assert found.feasible.tolist() == [[True, True], [False, True], [False, False]]
    assert found.pick == (0, 0) and found.closest is None  # the smaller motor A, through the only gearbox it can use
    # Without A: B through the gearbox the gearbox ranking puts first (i = 5, size 60 N·m).
    only_b = {k: v[1:] for k, v in motors.items()}
    assert search(m, SPEEDS, gearboxes, only_b, INERTIA_RATIO_LIMIT).pick == (1, 0)
    # λ = (J_1 + J_L / i²) / J_motor = (0 + 1e-3 / 100) / 1e-4 = 0.1 at i = 10 (0.4 at i = 5): a limit
    # of 0.05 refuses every pair.
    assert search(m, SPEEDS, gearboxes, motors, inertia_limit=0.05).pick is None
    # A gearbox whose T_2B takes a motor peak of at most 15 N·m (T_2B / (i · f_s · η)) refuses B there.
    limited = {**gearboxes, "peak_limit": [15.0, np.inf, np.inf]}
    assert search(m, SPEEDS, limited, motors, INERTIA_RATIO_LIMIT).feasible[0].tolist() == [True, False]


def test_where_no_pair_passes_the_closest_is_named():
    # A limit of 0.05 refuses every pair (λ above): the lowest highest utilization is B through
    # i = 10: λ 0.1 / 0.05 = 2 against A's and B's at i = 5 (0.4 / 0.05 = 8); A and B at i = 10 both
    # give λ / limit = 2, A's RMS 2.95 / 3 and B's 2.95 / 6 are under it: the first of the tie, A.
    m, gearboxes, motors = hand_pairs()
    found = search(m, SPEEDS, gearboxes, motors, inertia_limit=0.05)
    assert found.pick is None and found.closest == (0, 0)
    assert found.utilization[0, 0] == pytest.approx(2.0)


def test_the_characteristic_refuses_a_motor_and_the_next_one_is_picked():
    # A's peak torque falls off with speed: say it gives only 5 N·m at the cycle's speeds through any
    # gearbox. Its peak through i = 10 is 5.6556 N·m: 5.6556 / 5 = 1.131 fails; B is taken, through
    # the first-ranked gearbox it passes with (i = 5). Only A's pairs are examined: the motor after
    # the one that passes is left as screened.
    m, gearboxes, motors = hand_pairs()
    asked = []

    def examine(motor, rows):
        asked.append((motor, rows.tolist()))
        return peak[rows, motor] / (5.0 if motor == 0 else 20.0), np.ones(len(rows), bool), None

    peak = search(m, SPEEDS, gearboxes, motors, INERTIA_RATIO_LIMIT).peak
    found = search(m, SPEEDS, gearboxes, motors, INERTIA_RATIO_LIMIT, examine=examine)
    assert asked == [(0, [0]), (1, [0, 1])]
    assert found.pick == (1, 1) and not found.feasible[0, 0]
    assert found.utilization[0, 0] == pytest.approx(5.6556 / 5.0, abs=1e-4)


@pytest.mark.parametrize("first", [False, True])
def test_a_pair_the_full_evaluation_refuses_gives_way_to_the_next_in_the_rule_order(first):
    # The hand pairs: A passes through i = 10 only; B through i = 5 (ranked first) and i = 10. The
    # rule's order is (i=10, A), then B's (i=5, B), (i=10, B). Refusing (i=10, A) takes (i=5, B);
    # refusing that too takes (i=10, B); refusing all picks none, and the closest pair is named.
    m, gearboxes, motors = hand_pairs()
    for refused, pick in (({(0, 0)}, (1, 1)), ({(0, 0), (1, 1)}, (0, 1)), ({(0, 0), (1, 1), (0, 1)}, None)):
        asked = []

        def confirm(row, motor):
            asked.append((row, motor))
            return (row, motor) not in refused

        found = search(m, SPEEDS, gearboxes, motors, INERTIA_RATIO_LIMIT, first=first, confirm=confirm)
        # a finite walk down one ordered list: each pair asked once, in the rule's order, up to the pick
        assert asked == [(0, 0), (1, 1), (0, 1)][:len(refused) + (pick is not None)]
        columns = list(range(2)) if found.motors is None else found.motors.tolist()  # first: the motors screened
        got = None if found.pick is None else (found.pick[0], columns[found.pick[1]])
        assert got == pick
        assert (found.closest is None) == (pick is not None)


def test_the_gearbox_ranking_with_the_motor_decides_among_its_gearboxes():
    # B passes through i = 10 and i = 5; the ranking with B puts i = 10 first (say a coupling lifts
    # only its drive train above 2 f_er): the pick follows it. A gearbox that fails with the motor
    # is not taken: with i = 10 failing, i = 5.
    m, gearboxes, motors = hand_pairs()
    only_b = {k: v[1:] for k, v in motors.items()}
    ranked = search(m, SPEEDS, gearboxes, only_b, INERTIA_RATIO_LIMIT,
                    examine=lambda motor, rows: (np.zeros(len(rows)), np.ones(len(rows), bool), [0.0, 1.0]))
    assert ranked.pick == (0, 0)
    failing = search(m, SPEEDS, gearboxes, only_b, INERTIA_RATIO_LIMIT,
                     examine=lambda motor, rows: (np.zeros(len(rows)), rows != 0, [0.0, 1.0]))
    assert failing.pick == (1, 0) and not failing.feasible[0, 0]


def test_the_rated_speed_is_checked_against_the_mean_speed_where_given():
    # A's n_N of 35 rad/s against the mean speed 4 · 10 = 40 rad/s through i = 10: fails (1.14);
    # through i = 5, 20 rad/s passes it, but A's RMS there fails: B through i = 5 is taken.
    m, gearboxes, motors = hand_pairs()
    found = search(m, SPEEDS, gearboxes, {**motors, "rated_speed": [35.0, 300.0]}, INERTIA_RATIO_LIMIT)
    assert found.feasible[:, 0].tolist() == [False, False, False] and found.pick == (1, 1)


def test_the_figure_shows_the_lowest_working_utilization_of_each_motor_and_ratio():
    # Rows: two gearboxes at i = 5 and one at i = 10; motors A, B. At i = 5 motor A works through
    # the first (0.7) and second (0.4): the cell shows 0.4; B works through none there: grey (no
    # value). At i = 10 A fails (1.3), B works (0.9).
    from calc.figures.combination_plots import combinations_figure

    u = np.array([[0.7, 1.1], [0.4, 1.5], [1.3, 0.9]])
    fig = combinations_figure(u, u <= 1, [5.0, 10.0], ["A", "B"], pick=(1, 0), ratio_of_rows=np.array([5.0, 5.0, 10.0]))
    shown = np.ma.filled(fig.axes[0].images[0].get_array().astype(float), np.nan)
    assert np.allclose(shown, [[0.4, np.nan], [np.nan, 0.9]], equal_nan=True)  # rows: motors; columns: ratios


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(1, 12), st.integers(1, 9), st.booleans())
def test_the_first_motor_screened_is_the_pick_of_the_whole_table(seed, rows, motors, examined):
    # One rule, two ways to reach it: screening every pair at once, or the motors one at a time in
    # the rule's order until one has a passing pair (a case's evaluation). Both pick the same pair,
    # with or without an examination that refuses some pairs; where none passes, the first way names
    # the pair closest to passing and the second, having screened every motor, the same.
    rng = np.random.default_rng(seed)
    m = CycleMoments.of([0.1, 0.1, 0.3], [50.0, -30.0, 10.0], [10.0, 10.0, 0.0], [100.0, -100.0, 0.0])
    gearboxes = {"i": rng.choice([3.0, 5.0, 10.0], rows), "eta": rng.uniform(0.9, 0.98, rows),
                 "J_1": rng.uniform(0, 2e-5, rows), "passes": rng.random(rows) > 0.2,
                 "peak_limit": rng.uniform(5, 40, rows), "rank": rng.permutation(rows).astype(float), "J_L": 1e-3}
    motors = {"J": rng.uniform(2e-5, 4e-4, motors), "rated_torque": rng.choice([1.0, 2.0, 4.0, 8.0], motors),
              "peak_torque": rng.uniform(4, 30, motors), "max_speed": rng.uniform(50, 300, motors)}
    refused = rng.random((rows, len(motors["J"]))) < 0.3

    def examine(motor, at):
        return np.where(refused[at, motor], 1.5, 0.5), np.ones(len(at), bool), None

    kw = {"examine": examine} if examined else {}
    whole = search(m, (10.0, 4.0), gearboxes, motors, INERTIA_RATIO_LIMIT, **kw)
    first = search(m, (10.0, 4.0), gearboxes, motors, INERTIA_RATIO_LIMIT, first=True, **kw)
    as_whole = None if first.pick is None else (first.pick[0], int(first.motors[first.pick[1]]))
    assert as_whole == whole.pick
    # the motors screened together give each pair's torques as the whole table does, to the last bit
    screened = first.motors
    assert np.array_equal(first.peak, whole.peak[:, screened]) and np.array_equal(first.rms, whole.rms[:, screened])
    # and so do the motors screened a few at a time (a large catalog's rows): the same pick and arrays
    kept, combinations.SCREEN_PAIRS = combinations.SCREEN_PAIRS, rows + 1
    try:
        few = search(m, (10.0, 4.0), gearboxes, motors, INERTIA_RATIO_LIMIT, first=True, **kw)
    finally:
        combinations.SCREEN_PAIRS = kept
    assert few.pick == first.pick and few.closest == first.closest and np.array_equal(few.motors, first.motors)
    assert all(np.array_equal(getattr(few, k), getattr(first, k)) for k in ("peak", "rms", "utilization", "feasible"))
    if whole.pick is None:
        _, k = first.closest
        assert whole.utilization[first.closest[0], first.motors[k]] == pytest.approx(whole.utilization[whole.closest])


def test_rows_an_examination_leaves_out_stay_as_screened():
    # B's examination stops at the first row of its ranking that passes (i = 5, ranked first): the
    # other row (i = 10) is not examined (NaN), keeps its screened utilization and stays feasible.
    m, gearboxes, motors = hand_pairs()
    only_b = {k: v[1:] for k, v in motors.items()}
    screened = search(m, SPEEDS, gearboxes, only_b, INERTIA_RATIO_LIMIT)
    found = search(m, SPEEDS, gearboxes, only_b, INERTIA_RATIO_LIMIT,
                   examine=lambda motor, rows: (np.where(rows == 1, 0.5, np.nan), np.ones(len(rows), bool), None))
    assert found.pick == (1, 0) and found.feasible[0, 0]
    assert found.utilization[0, 0] == screened.utilization[0, 0]
