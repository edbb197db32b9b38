"""python -m calc combinations: every motor with every gearbox at every ratio of a case's
catalogs (calc.sections.pairs over the kernel of calc.domain.combinations)."""

import json

import numpy as np
import pytest

from calc import Q_
from calc.sections.case import read_case
from calc.domain.motor import motor_load
from calc.sections import evaluate
from calc.sections.pairs import search_pairs

from ..conftest import DERIVED_EXAMPLE, EXAMPLE


@pytest.fixture
def catalog_case(write_case):
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8")
    text = text.replace('peak_torque = "12 N*m"', 'catalog = "motors"').replace('inertia = "4.2 kg*cm**2"', "")
    return write_case(text.replace('"../data/', f'"{DERIVED_EXAMPLE.parent.parent / "data"}/'), "c.toml")


def test_the_pick_is_the_pair_the_evaluation_chooses_and_its_torques_are_exact(catalog_case):
    found = search_pairs(read_case(catalog_case))
    p = found.pick
    results = evaluate(read_case(catalog_case))
    # The evaluation ranks the motors through its gearbox with the motor's characteristic; the search
    # screens against M_max: on this cycle (far below every knee) both choose the same pair.
    assert (p.motor, p.gearbox) == (results["motor"].selection.selected, results["gearbox"].selection.selected)
    # The kernel's peak and RMS for the pair are the sampled motor torque's (calc.domain.motor.motor_load),
    # with the rotor and the gearbox's J_1 (the search leaves the motor-side coupling out, and says so).
    case = read_case(catalog_case)
    m = case.motion
    g = np.flatnonzero(found.gearbox_parts == p.gearbox)[0]
    cat = results["motor"].selection.catalog
    J = cat["J"][cat.index(p.motor, "test")]
    J_1 = results["gearbox"].selection.J_1[results["gearbox"].selection.order[0]]
    load = motor_load(Q_(m.cycle.dt, "s"), Q_(m.cycle.torque, "N*m"), Q_(m.cycle.speed, "rad/s"), Q_(p.ratio, ""),
                      Q_(0.97, ""), Q_(m.cycle.acceleration, "rad/s**2"), J, J_1)
    assert p.peak_torque == pytest.approx(load.peak.m_as("N*m"), rel=1e-9)
    assert p.rms_torque == pytest.approx(load.rms.m_as("N*m"), rel=1e-9)
    assert found.result.feasible[g].any()
    assert "the motor-side coupling's inertia is not counted here (evaluate counts it)" in found.notes


def test_the_command_prints_the_pick_and_draws_the_figure(catalog_case, tmp_path, capsys):
    from calc.__main__ import main

    figure = tmp_path / "pairs.png"
    assert main(["combinations", str(catalog_case), "--json", "--figure", str(figure)]) == 0
    r = json.loads(capsys.readouterr().out)
    assert r["pick"]["motor"] and r["feasible"] <= r["pairs"] == r["motors"] * r["gearboxes"]
    assert r["verdict"]["passes"] is True
    assert figure.stat().st_size > 10_000


def test_the_search_needs_a_motor_catalog(capsys):
    from calc.__main__ import main

    assert main(["combinations", str(EXAMPLE)]) == 2
    err = capsys.readouterr().err
    assert ("motor.catalog: the search of motors and gearboxes needs a motor catalog ([motor] catalog = \"motors\"), "
            "found none") in err


def test_the_search_needs_a_gearbox_catalog(write_case, capsys):
    from calc.__main__ import main

    from ..domain.test_motor_ratings import DIRECT_DRIVE

    assert main(["combinations", str(write_case(DIRECT_DRIVE.format(motor=""), "dd.toml"))]) == 2
    assert ("gearbox: the search of motors and gearboxes needs a [gearbox] table (its catalog gives the gearboxes), "
            "found none") in capsys.readouterr().err
