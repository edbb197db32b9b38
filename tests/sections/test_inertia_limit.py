"""The case's limit of the load to motor inertia ratio (``[motor] max_inertia_ratio``) holds in the
ratio search (``python -m calc ratios``) and the pair search (``python -m calc combinations``) as in
the motor section, not the default 10.

By hand, from the λ column of ``python -m calc ratios cases/indexing-table.toml`` (the motor
SGMUH-10DA, J_motor = 1.74 kg·cm², its catalog's choice at ratio 10, named here so that it stays
the motor whatever the limit): λ = 96.43, 54.63, 35.16, 18.20, 14.06, 9.44 at the ratios 3, 4, 5,
7, 8, 10 (J_1 with the motor-side coupling AKN-18's 0.5 kg·cm², as the motor's check counts
it: 0.5 / 1.74 = 0.287 above the gearbox's own); every ratio is feasible, and the motor's RMS
torque falls as the ratio rises (0.9546 N·m at 3 to 0.3199 N·m at 10).
"""

import json

import numpy as np
import pytest

from calc import Q_
from calc.domain.motor import MotorLoad
from calc.domain.ratios import pick_ratio
from calc.sections.case import read_case
from calc.sections.axis import motor_catalog
from calc.sections.pairs import search_pairs

from ..conftest import DERIVED_EXAMPLE, ROOT, results_schema

#: The ratio search's JSON as docs/results.schema.json describes it (``$defs/ratio_search``).
RESULTS_SCHEMA = results_schema()
RATIO_SEARCH_SCHEMA = type(RESULTS_SCHEMA)({"$defs": RESULTS_SCHEMA.schema["$defs"], "$ref": "#/$defs/ratio_search"})
LAMBDA = {3: 96.43, 4: 54.63, 5: 35.16, 7: 18.20, 8: 14.06, 10: 9.44}


def with_limit(tmp_path, limit, motor: str = ""):
    """The example copied into ``tmp_path/cases`` beside a link to the project's data (its
    measurement is ``../data/...``), with ``[motor] max_inertia_ratio = limit`` (and ``part``)."""
    (tmp_path / "cases").mkdir(exist_ok=True)
    if not (tmp_path / "data").exists():
        (tmp_path / "data").symlink_to(ROOT / "data")
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8")
    assert text.count('catalog = "motors"\n') == 1
    part = f'part = "{motor}"\n' if motor else ""
    path = tmp_path / "cases" / f"limit-{limit}{motor}.toml"
    motor = f'catalog = "motors"\n{part}max_inertia_ratio = {limit}\n'
    path.write_text(text.replace('catalog = "motors"\n', motor), encoding="utf-8")
    return path


def command(capsys, *args):
    from calc.__main__ import main

    code = main([*map(str, args)])
    out, err = capsys.readouterr()
    return code, out, err


LEAST_RMS = "of these it needs the lowest RMS motor torque, 0.3199 N·m"


@pytest.mark.parametrize("limit, within, reason", [
    # 18.20, 14.06 and 9.44 are at most 20: ratios 7, 8 and 10; of these 10 needs the least RMS torque.
    (20, [7, 8, 10], f"6 of 6 ratios are feasible, 3 of them with λ <= 20; {LEAST_RMS}"),
    # 34.87 is at most 40 as well: 5, 7, 8, 10.
    (40, [5, 7, 8, 10], f"6 of 6 ratios are feasible, 4 of them with λ <= 40; {LEAST_RMS}"),
    # The default: 9.44 alone.
    (10, [10], "6 of 6 ratios are feasible, and only this one keeps λ <= 10 (λ = 9.44)"),
    # None is at most 9: the feasible ratio of lowest λ, 10 (9.44).
    (9, [], "6 of 6 ratios are feasible, none with λ <= 9; it has the lowest, λ = 9.44"),
])
def test_the_ratio_search_keeps_to_the_cases_limit(tmp_path, capsys, limit, within, reason):
    code, out, err = command(capsys, "ratios", with_limit(tmp_path, limit, "SGMUH-10DA"), "--json")
    assert (code, err) == (0, "")
    j = json.loads(out)
    lam = {r["ratio"]: r["inertia_ratio"] for r in j["ratios"]}
    assert lam == pytest.approx(LAMBDA, abs=0.005)  # the motor named: the column of the shipped case
    assert [i for i, x in lam.items() if x <= limit] == within
    assert [r["ratio"] for r in j["ratios"] if r["inertia_ratio_within_limit"]] == within  # as the search records it
    assert not list(RATIO_SEARCH_SCHEMA.iter_errors(j))
    assert j["inertia_ratio_limit"] == limit
    rule = f"inertia ratio λ = (J_1 + J_L / i²) / J_motor (J_1 with a motor-side coupling's J) is at most {limit} (E6)"
    assert rule in j["rule"]
    assert j["pick"]["ratio"] == 10 and j["reason"] == f"Ratio 10 (NPT035-10): {reason}."
    code, out, err = command(capsys, "ratios", with_limit(tmp_path, limit, "SGMUH-10DA"))
    assert f"is at most {limit} (E6)" in out and f"Ratio 10 (NPT035-10): {reason}." in out


def test_the_ratio_search_and_the_motor_section_read_one_limit(tmp_path, capsys):
    # With the motor chosen from the catalog a limit of 3 chooses another motor (SGMUH-10DA's 9.44 is
    # too high): the ratio search keeps to the same 3 the motor section says it keeps to.
    path = with_limit(tmp_path, 3)
    code, out, _ = command(capsys, "evaluate", path)
    assert "λ <= 3 from motor.max_inertia_ratio" in out
    code, out, err = command(capsys, "ratios", path, "--json")
    j = json.loads(out)
    assert j["inertia_ratio_limit"] == 3 and "is at most 3 (E6)" in j["rule"]
    within = [r["ratio"] for r in j["ratios"] if r["inertia_ratio"] <= 3]
    lam = j["ratios"][-1]["inertia_ratio"]
    assert within == [10] and j["reason"].endswith(f"and only this one keeps λ <= 3 (λ = {lam:.3g}).")


def test_the_pick_moves_with_the_limit():
    # Two feasible ratios: 5 needs more RMS torque (2 N·m) than 10 (1 N·m) but has the lower λ (8
    # against 12). A limit of 10 keeps 5 alone (8 <= 10 < 12): 5 is picked; a limit of 20 keeps both,
    # and 10 needs less; a limit of 7 keeps neither: the lower λ, 5.
    ratios, parts, feasible, lam = np.array([5.0, 10.0]), np.array(["a", "b"]), np.ones(2, bool), np.array([8.0, 12.0])
    torques = MotorLoad(None, None, Q_([2.0, 1.0], "N*m"), True)
    alone = "Ratio 5 (a): 2 of 2 ratios are feasible, and only this one keeps λ <= 10 (λ = 8)."
    assert pick_ratio(ratios, parts, feasible, lam, torques, [], 10.0) == (0, alone)
    assert pick_ratio(ratios, parts, feasible, lam, torques, [], 20.0)[0] == 1
    k, why = pick_ratio(ratios, parts, feasible, lam, torques, [], 7.0)
    assert k == 0 and "none with λ <= 7; it has the lowest, λ = 8" in why


def test_the_pair_search_keeps_to_the_cases_limit(tmp_path):
    # By the default 10 the pick is SGMUH-10DA with NPT035-10: λ = (0.93 + 1500 / 10²) / 1.74 = 9.155.
    # A limit of 3 asks J_motor >= (0.93 + 15) / 3 = 5.31 kg·cm² even at ratio 10 (higher at lower
    # ratios, the load's 1500 kg·cm² divided by less): SGMUH-10DA fits with no gearbox, and the
    # pick's rotor keeps λ within 3.
    default = search_pairs(read_case(with_limit(tmp_path, 10)))
    assert (default.pick.motor, default.pick.gearbox) == ("SGMUH-10DA", "NPT035-10")
    found = search_pairs(read_case(with_limit(tmp_path, 3)))
    assert found.feasible_count < default.feasible_count
    sgmuh = int(np.flatnonzero(found.motor_parts == "SGMUH-10DA")[0])
    assert default.result.feasible[:, sgmuh].any() and not found.result.feasible[:, sgmuh].any()
    p = found.pick
    motors = motor_catalog(read_case(with_limit(tmp_path, 3)))
    J = motors["J"][motors.index(p.motor, "test")].m_as("kg*cm**2")
    assert p.gearbox == "NPT035-10" and (0.93 + 1500 / 10**2) / J <= 3
