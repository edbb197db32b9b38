"""The best ratio (calc.domain.ratios, calc.sections.ratios, ``python -m calc ratios``): one evaluation over
every row agrees with the case evaluated at each ratio; hand-calculated torques; the pick rule;
exit status and errors."""

import dataclasses
import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import Q_
from calc.sections.case import read_case
from calc.domain.gearbox import INERTIA_RATIO_LIMIT
from calc.domain.ratios import pick_ratio
from calc.sections import evaluate
from calc.sections.ratios import search

from ..conftest import EXAMPLE, PROFILE_TOML
from .test_motor import trapezoid, with_cycle


def ratios_cli(capsys, *args):
    from calc.__main__ import main

    code = main(["ratios", *map(str, args)])
    out, err = capsys.readouterr()
    return code, out, err


def test_each_ratio_gives_what_the_case_gives_at_that_ratio():
    # The search evaluates every row at once; at each ratio, its best gearbox and motor torques must
    # be those of the case evaluated at that ratio alone (gearbox section, motor section).
    case = read_case(EXAMPLE)
    s = search(case).search
    for k, ratio in enumerate(s.ratios):
        at = dataclasses.replace(case, ratio=Q_(ratio, ""), sections={})  # the gearbox and the motor only
        r = evaluate(at)
        assert str(s.parts[k]) == str(r["gearbox"].selection.catalog.parts[r["gearbox"].selection.order[0]])
        m = r.to_json()["motor"]
        assert s.load.peak[k].m_as("N*m") == pytest.approx(m["peak_torque_required"]["value"], rel=1e-12)
        assert s.load.rms[k].m_as("N*m") == pytest.approx(m["rms_torque_required"]["value"], rel=1e-12)


def test_example_by_hand():
    # The example's cycle (typed, rotor term left out): peak = 60 N·m / (i · 0.97), RMS = 26.4704 N·m / i
    # (2.64704 N·m at i = 10, calc.domain.motor.motor_load's docstring). Ratios 3, 4, 5, 7, 8, 10 (shipped
    # catalog); the motor's 12 N·m peak needs 60 / (i · 0.97) <= 12: i >= 5.15, so 7, 8 and 10 remain
    # (their gearboxes pass). λ = (J_1 + 1500 / i²) / 4.2 at i = 10 with NPT035-10 (J_1 = 0.93):
    # (0.93 + 15) / 4.2 = 3.793 <= 10. Lowest RMS among 7, 8, 10: 10 (2.647 N·m).
    j = search(read_case(EXAMPLE)).to_json()
    by = {r["ratio"]: r for r in j["ratios"]}
    assert sorted(by) == [3, 4, 5, 7, 8, 10]
    for i, r in by.items():
        assert r["peak_torque_required"]["value"] == pytest.approx(60 / (i * 0.97), rel=1e-9)
        assert r["rms_torque_required"]["value"] == pytest.approx(26.4704006 / i, rel=1e-8)
        assert r["max_speed_required"]["value"] == pytest.approx(300 * i)
    assert [i for i, r in by.items() if r["passes"]] == [7, 8, 10]
    assert by[10]["inertia_ratio"] == pytest.approx((0.93 + 15) / 4.2)
    assert j["pick"]["ratio"] == 10 and j["pick"]["part"] == "NPT035-10"
    assert "lowest RMS motor torque" in j["pick"]["reason"]
    assert j["rotor_term"] is False and any("left out" in n for n in j["notes"])


def test_the_rotor_term_favours_lower_ratios():
    # With the trapezoid (calc tests/domain/test_motor.py) the rotor term (J_motor + J_1) · i · α_2 grows with
    # i while the load term falls as 1/i: the torques are those of the hand-calculated formula.
    case = with_cycle(read_case(EXAMPLE), trapezoid())
    s = search(case).search
    assert s.load.rotor_term
    cat = s.selection.catalog
    J_c = s.selection.J_1[s.rows].m_as("kg*m**2")  # gearbox J_1 per ratio, for the 19 mm motor shaft's clamping hub
    coupling = search(case).to_json()["notes"]
    assert any("motor-side coupling" in n for n in coupling)
    for k, i in enumerate(s.ratios):
        if np.isnan(J_c[k]):
            continue
        eta = cat["eta"][s.rows[k]].m_as("")
        J = 4.2e-4 + J_c[k]  # J_motor + J_1, and the coupling below
        J_coupling = evaluate(case).to_json()["motor"]["J_coupling"]["value"] * 1e-4
        # accel phase: (J + J_coupling) · i · 100 rad/s² + 12 N·m / (i · η)
        expected = (J + J_coupling) * i * 100 + 12 / (i * eta)
        assert s.load.peak[k].m_as("N*m") == pytest.approx(expected, rel=1e-9)


def test_pick_rule_falls_back_to_lowest_inertia_ratio():
    ratios = np.array([3.0, 5.0, 10.0])
    parts = np.array(["a", "b", "c"])
    feasible = np.array([True, True, False])
    lam = np.array([40.0, 12.0, 3.0])  # the only ratio within the limit is not feasible
    k, why = pick_ratio(ratios, parts, feasible, lam, None, [], INERTIA_RATIO_LIMIT)
    assert k == 1 and f"none with λ <= {INERTIA_RATIO_LIMIT:g}" in why
    k, why = pick_ratio(ratios, parts, np.zeros(3, bool), lam, None, ["it needs motor.inertia"], INERTIA_RATIO_LIMIT)
    assert k is None and "motor.inertia" in why
    k, why = pick_ratio(ratios, parts, feasible, np.full(3, np.nan), None, [], INERTIA_RATIO_LIMIT)
    assert k == 0 and "not known" in why  # no inertias, no torques: the lower ratio


def test_cli_json_text_and_exit_status(capsys, write_case):
    code, out, err = ratios_cli(capsys, EXAMPLE, "--json")
    assert code == 0 and err == "" and json.loads(out)["pick"]["ratio"] == 10
    code, out, _ = ratios_cli(capsys, EXAMPLE)
    assert code == 0 and "<- pick" in out
    weak = EXAMPLE.read_text().replace('peak_torque = "12 N*m"', 'peak_torque = "1.2 N*m"')
    # The trace's path absolute: it is found as the case is read.
    path = write_case(weak.replace("../../data/", str(EXAMPLE.parents[2] / "data") + "/"))
    code, out, _ = ratios_cli(capsys, path, "--strict")
    assert code == 1 and "No ratio can be picked" in out
    code, out, _ = ratios_cli(capsys, path)
    assert code == 0


def test_a_case_without_a_gearbox_is_an_error(capsys, write_case):
    code, out, err = ratios_cli(capsys, write_case('title = "x"\n' + PROFILE_TOML))
    assert code == 2 and out == "" and "gearbox: the ratio search needs a [gearbox] table" in err
    assert err.count("\n") == 1


def test_a_sampled_cycle_without_the_motors_inertia_picks_nothing_and_says_why():
    case = with_cycle(dataclasses.replace(read_case(EXAMPLE), motor_inertia=None, sections={}), trapezoid())
    j = search(case).to_json()
    assert j["pick"] is None and "motor.inertia" in j["reason"]
    assert all(r["peak_torque_required"] is None for r in j["ratios"])


@settings(max_examples=25, deadline=None)
@given(peak=st.floats(2.0, 30.0), rated=st.floats(0.5, 1.0))
def test_the_pick_is_feasible_and_needs_the_least_rms_within_the_inertia_limit(peak, rated):
    # The rule of calc.domain.ratios: no feasible ratio with λ within the limit needs less RMS torque.
    case = dataclasses.replace(read_case(EXAMPLE), motor_peak_torque=Q_(peak, "N*m"),
                               motor_rated_torque=Q_(rated * peak, "N*m"))
    s = search(case).search
    if s.pick is None:
        assert not s.feasible.any()
        return
    assert s.feasible[s.pick]
    rms = s.load.rms.m_as("N*m")
    within = s.feasible & (s.inertia_ratio <= s.inertia_limit)
    if within.any():
        assert within[s.pick] and rms[s.pick] == rms[within].min()
    else:
        assert s.inertia_ratio[s.pick] == s.inertia_ratio[s.feasible].min()


def test_a_catalog_motor_is_chosen_once_and_kept_at_every_ratio():
    # The shipped example names a motor catalog: the search takes the motor the case chooses at its
    # ratio (SGMUH-10DA, 1.74 kg·cm²) and keeps it. By hand, λ = (J_1 + J_L / i²) / J_motor with J_1
    # counting the motor-side coupling AKN-18 (0.5 kg·cm²), as the motor's check does:
    #   i = 10 (NPT035-10, J_1 0.93): (0.93 + 0.5 + 1500 / 100) / 1.74 = 9.443 <= 10;
    #   i = 8 (NPT025-8, J_1 0.53): (0.53 + 0.5 + 1500 / 64) / 1.74 = 14.06 > 10;
    # every ratio is feasible, and 10 alone keeps λ within the limit: it is picked.
    from ..conftest import DERIVED_EXAMPLE

    r = search(read_case(DERIVED_EXAMPLE))
    s = r.search
    assert s.feasible.all() and s.ratios[s.pick] == 10 and str(s.parts[s.pick]) == "NPT035-10"
    lam = dict(zip(s.ratios.tolist(), s.inertia_ratio.tolist()))
    assert lam[10] == pytest.approx((0.93 + 0.5 + 15) / 1.74)
    assert lam[8] == pytest.approx((0.53 + 0.5 + 1500 / 64) / 1.74)
    assert any("the motor is SGMUH-10DA, the motor catalog's choice at the case's ratio 10" in n for n in r.notes)


def _derived(write_case, change=lambda text: text):
    """The example (its motor from the catalog, its coupling and accuracy chain) written elsewhere, changed."""
    from ..conftest import DERIVED_EXAMPLE, ROOT

    return read_case(write_case(change(DERIVED_EXAMPLE.read_text().replace('"../data/', f'"{ROOT}/data/'))))


def test_at_the_cases_ratio_the_search_shows_the_gearbox_the_case_is_checked_with(write_case):
    # A part the case names is kept at its ratio: NPT025-10 named, the catalog chooses the smallest motor that
    # pairs with it, SGM7G-03A (M_max 5.88 N·m), and the evaluation checks NPT025-10: T_2max = T_1B · i · f_s · η
    # = 5.88 · 10 · 1.6 · 0.97 = 91.26 N·m > T_2B 90 N·m, it fails. The search showed NPT035-10 at ratio 10, the
    # ranking's first, and picked it: two gearboxes at one ratio. It shows NPT025-10 failing there, and says that
    # it picks another ratio and why.
    case = _derived(write_case, lambda t: t.replace('family = "NPT"\n', 'family = "NPT"\npart = "NPT025-10"\n'))
    results = evaluate(case)
    gearbox = results["gearbox"].selection
    assert str(gearbox.catalog.parts[gearbox.order[0]]) == "NPT025-10" and results.every["axis"].case.motor_part is None
    assert results.every["axis"].chosen == "SGM7G-03A"
    r = search(results.case, results.every)
    s = r.search
    at = int(np.flatnonzero(s.ratios == 10)[0])
    assert str(s.parts[at]) == "NPT025-10" and not s.feasible[at]
    assert "91.26 N·m > rated 90 N·m" in " ".join(s.gearbox_reasons(at))
    assert s.ratios[s.pick] != 10
    j = r.to_json()["checked"]
    assert j["ratio"] == 10 and j["part"] == "NPT025-10" and j["same"] is False
    assert j["said"].startswith("The case is checked at its ratio 10 with NPT025-10 (gearbox.part); the search picks "
                                f"ratio {s.ratios[s.pick]:g} ({s.parts[s.pick]}), since at 10 NPT025-10 fails (T_2max")
    assert j["said"].endswith(f"set [gearbox] ratio = {s.ratios[s.pick]:g} to check that one in full.")
    assert any("gearbox.part = 'NPT025-10' is kept at its ratio" in n for n in r.notes)
    assert j["said"] in r.summary()


@pytest.mark.parametrize("inertia, family", [(300, True), (1500, True), (1600, True), (2500, False)])
def test_one_gearbox_at_the_cases_ratio_and_a_pick_that_differs_is_said(write_case, inertia, family):
    # Over load inertias where the catalog chooses another motor (300: MHD041A-144 with NPT025-10; 1600: none is
    # confirmed and the closest pair is checked) and over every family of the catalog (2500 kg·cm²: the case is
    # checked at its ratio 10, the rule's lowest RMS motor torque is at another ratio), the search's gearbox at the
    # case's ratio is the one the evaluation checks, and a pick elsewhere is said with the case's own.
    def change(text):
        text = text.replace('inertia = "1500 kg*cm**2"', f'inertia = "{inertia} kg*cm**2"')
        return text if family else text.replace('family = "NPT"\n', "")

    results = evaluate(_derived(write_case, change))
    gearbox = results["gearbox"].selection
    checked_with = str(gearbox.catalog.parts[gearbox.order[0]])
    r = search(results.case, results.every)
    s = r.search
    at = int(np.flatnonzero(s.ratios == 10)[0])
    assert str(s.parts[at]) == checked_with
    assert r.checked.part == checked_with and r.checked.same == (s.pick == at)
    if s.pick == at:
        assert r.checked.said.endswith("the search picks the same.")
    else:
        assert f"the search picks ratio {s.ratios[s.pick]:g} ({s.parts[s.pick]}), since " in r.checked.said


def test_a_pick_at_the_cases_ratio_that_the_evaluation_fails_is_said(write_case):
    # SGMUH-10DA named (1.74 kg·cm²) under a table of 2500 kg·cm²: at ratio 10 with NPT035-10 (J_1 0.93) and the
    # coupling AKN-18 (0.5), λ = (0.93 + 0.5 + 2500 / 10²) / 1.74 = 15.19 > 10, and lower ratios give more. No ratio
    # keeps λ within the limit, so the search picks the lowest λ, the case's own ratio, which the motor's check
    # fails: the sentence says so instead of a bare "the same".
    case = _derived(write_case, lambda t: t.replace('catalog = "motors"\n', 'catalog = "motors"\npart = "SGMUH-10DA"\n')
                    .replace('inertia = "1500 kg*cm**2"', 'inertia = "2500 kg*cm**2"'))
    r = search(case)
    assert r.checked.same and r.search.inertia_ratio[r.search.pick] == pytest.approx((0.93 + 0.5 + 25) / 1.74)
    assert r.checked.said.startswith("The case is checked at its ratio 10 with NPT035-10 (chosen at gearbox.ratio): "
                                     "the search picks the same, though the evaluation fails it there (")
    assert "SGMUH-10DA: λ <= λ_max: required 15.19 > rated 10" in r.checked.said
