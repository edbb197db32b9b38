"""python -m calc combinations: every motor with every gearbox at every ratio of a case's
catalogs (calc.sections.pairs over the kernel of calc.domain.combinations)."""

import importlib.util
import json
import sys

import numpy as np
import pytest

from calc import Q_
from calc.sections.case import read_case
from calc.domain.motor import motor_load
from calc.sections import evaluate
from calc.sections.pairs import case_pairs, search_pairs

from ..conftest import DERIVED_EXAMPLE, EXAMPLE, ROOT


@pytest.fixture
def catalog_case(write_case):
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8")
    text = text.replace('peak_torque = "12 N*m"', 'catalog = "motors"').replace('inertia = "4.2 kg*cm**2"', "")
    return write_case(text.replace('"../data/', f'"{DERIVED_EXAMPLE.parent.parent / "data"}/'), "c.toml")


def test_the_pick_is_the_pair_the_evaluation_chooses_and_its_torques_are_exact(catalog_case):
    found = search_pairs(read_case(catalog_case))
    p = found.pick
    results = evaluate(read_case(catalog_case))
    # The evaluation takes its pair from the search of the rows at the case's ratio by the same rule; the
    # search over every ratio picks the same pair where the case's ratio is the one it picks.
    assert (p.motor, p.gearbox) == (results["motor"].selection.selected, results["gearbox"].selection.selected)
    # The kernel's peak and RMS for the pair are the sampled motor torque's (calc.domain.motor.motor_load),
    # with the rotor, the gearbox's J_1 and the lightest motor-side coupling's whole inertia.
    case = read_case(catalog_case)
    m = case.motion
    g = np.flatnonzero(found.gearbox_parts == p.gearbox)[0]
    cat = results["motor"].selection.catalog
    J = cat["J"][cat.index(p.motor, "test")]
    couplings = results["coupling"].inputs.catalog
    J_c = np.nanmin(couplings["J"].m_as("kg*m**2")[~couplings.partial])
    J_1 = results["gearbox"].selection.J_1[results["gearbox"].selection.order[0]] + Q_(J_c, "kg*m**2")
    load = motor_load(Q_(m.cycle.dt, "s"), Q_(m.cycle.torque, "N*m"), Q_(m.cycle.speed, "rad/s"), Q_(p.ratio, ""),
                      Q_(0.97, ""), Q_(m.cycle.acceleration, "rad/s**2"), J, J_1)
    assert p.peak_torque == pytest.approx(load.peak.m_as("N*m"), rel=1e-9)
    assert p.rms_torque == pytest.approx(load.rms.m_as("N*m"), rel=1e-9)
    assert found.result.feasible[g].any()
    assert any(n.startswith("the motor-side coupling turns with the motor: the lightest candidate's inertia")
               for n in found.notes)


def test_the_evaluation_takes_the_pair_of_the_rows_at_the_case_ratio(catalog_case):
    case = read_case(catalog_case)
    found = case_pairs(case)
    results = evaluate(case)
    axis = results.every["axis"]
    # One search, one rule: the motor and the gearbox the outputs name are the pair's.
    assert (axis.chosen, axis.gearbox) == (found.pick.motor, found.pick.gearbox)
    assert set(found.ratios.tolist()) == {case.ratio.m_as("")}
    assert results["gearbox"].selection.selected == found.pick.gearbox
    assert results["motor"].selection.selected == found.pick.motor


def test_where_no_pair_passes_the_evaluation_checks_the_closest_and_fails(catalog_case, write_case):
    # A limit of λ <= 0.01 no motor meets with any gearbox: the pair closest to passing is checked and
    # its inertia ratio fails; the case gets an answer, not an error.
    text = catalog_case.read_text(encoding="utf-8").replace('catalog = "motors"', 'catalog = "motors"\n'
                                                             'max_inertia_ratio = 0.01')
    case = read_case(write_case(text, "tight.toml"))
    found = case_pairs(case)
    assert found.pick is None and found.chosen is not None
    g, m = found.chosen
    results = evaluate(case)
    assert results.every["axis"].chosen == found.motor_parts[m] and results.verdict.passes is False


@pytest.fixture(scope="module")
def large_case(tmp_path_factory):
    """The shipped example with a generated 100,000-row gearbox catalog at its ratio (the benchmark's)."""
    spec = importlib.util.spec_from_file_location("bench_catalogs", ROOT / "bench" / "bench.py")
    sys.path.insert(0, str(ROOT / "bench"))
    try:
        bench = sys.modules[spec.name] = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(bench)
    finally:
        sys.path.remove(str(ROOT / "bench"))
    return bench.write_large_case(tmp_path_factory.mktemp("large"), 100_000, "filled")


def test_a_100k_gearbox_catalog_evaluates_and_picks_a_pair(large_case):
    case = read_case(large_case)
    results = evaluate(case)
    axis = results.every["axis"]
    found = case_pairs(case)
    assert found.pick is not None and len(found.gearbox_parts) >= 100_000 - 100
    assert (axis.chosen, axis.gearbox) == (found.pick.motor, found.pick.gearbox)
    assert results["gearbox"].selection.selected == found.pick.gearbox
    assert results["motor"].selection.selected == found.pick.motor


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
