"""The evaluation of a case (calc.sections.evaluation): each section after those it requires, each
reading only the results it declares, a cycle of requirements named; and the typed inputs of a
section's own table, read with the case and again from a copy whose table was changed."""

import copy
import dataclasses

import pytest

from calc.core.errors import CalcError
from calc.sections import SECTIONS, evaluate, read_case
from calc.sections.evaluation import Earlier, evaluation_order, requirement_order, results_of, section

from ..conftest import DERIVED_EXAMPLE, EXAMPLE


@dataclasses.dataclass(frozen=True)
class Named:
    """A section as the order sees it: its name and what it requires."""

    NAME: str
    REQUIRES: tuple = ()


def test_each_section_comes_after_what_it_requires():
    order = [s.NAME for s in evaluation_order()]
    assert sorted(order) == sorted(s.NAME for s in SECTIONS)
    for s in SECTIONS:
        assert all(order.index(r) < order.index(s.NAME) for r in s.REQUIRES), s.NAME
    # The load cycle's T_2max is the best gearbox's: it is evaluated after the gearbox, though shown before it.
    assert order.index("gearbox") < order.index("profile")
    assert [s.NAME for s in SECTIONS].index("profile") < [s.NAME for s in SECTIONS].index("gearbox")


def test_sections_that_require_each_other_are_an_error_naming_the_cycle():
    found = (Named("a"), Named("b", ("d",)), Named("c", ("b",)), Named("d", ("c",)))
    with pytest.raises(CalcError, match=r"the sections require each other in a cycle: b -> d -> c -> b"):
        requirement_order(found)
    with pytest.raises(CalcError, match=r"section b requires 'x', which is no section; the sections are a, b"):
        requirement_order((Named("a"), Named("b", ("x",))))
    assert [s.NAME for s in requirement_order((Named("c", ("b",)), Named("a"), Named("b", ("a",))))] == ["a", "b", "c"]


def test_a_section_reads_only_the_results_it_requires():
    earlier = Earlier(section("coupling"), {"axis": "the axis", "accuracy": "the chain"})
    assert earlier["axis"] == "the axis" and earlier.get("gearbox") is None  # required; no gearbox in this case
    with pytest.raises(LookupError, match="section coupling reads the results of accuracy but does not require it"):
        earlier.get("accuracy")


def test_a_section_is_evaluated_with_what_it_requires_only():
    # The gearbox needs the motor the case is checked with (the axis) and nothing else.
    assert set(results_of(read_case(EXAMPLE), ("gearbox",))) == {"axis", "gearbox"}
    # A coupling needs the gearbox; the accuracy chain both; the motor's side the three.
    assert set(results_of(read_case(EXAMPLE), ("accuracy",))) == {"axis", "gearbox", "coupling", "accuracy"}
    assert list(evaluate(read_case(EXAMPLE), "motor").sections) == ["gearbox", "coupling", "motor"]


def test_the_motor_chosen_from_the_catalog_is_the_axis_result():
    # The example chooses its motor from catalogs/motors.csv: the case as checked has its ratings,
    # and every section that requires the axis sees them.
    case = read_case(DERIVED_EXAMPLE)
    assert case.motor_peak_torque is None
    results = evaluate(case)
    axis = results.every["axis"]
    assert axis.chosen == results["motor"].selection.selected and results.case is axis.case
    motors = results["motor"].selection
    assert results.case.motor_peak_torque == motors.catalog["M_max"][motors.order[0]]
    # The gearbox was chosen with it, from the same pair (calc.sections.pairs.case_pairs).
    assert axis.gearbox == results["gearbox"].selection.selected


def test_a_bad_key_of_a_sections_own_table_is_an_error_when_the_case_is_read(write_case):
    text = DERIVED_EXAMPLE.read_text(encoding="utf-8").replace("../data/", f"{DERIVED_EXAMPLE.parents[1] / 'data'}/")
    with pytest.raises(CalcError, match=r"coupling\.side: expected one of input, output, found 'inside'"):
        read_case(write_case(text.replace('side = "input"', 'side = "inside"')))
    with pytest.raises(CalcError, match=r"accuracy\.applied_torque: expected a value, found none"):
        read_case(write_case(text.replace('applied_torque = "8 N*m"', "")))


def test_a_changed_table_is_read_again_when_evaluated():
    case = read_case(EXAMPLE)
    tables = copy.deepcopy(case.sections)
    tables["coupling"]["service_factor"] = 3.0
    changed = dataclasses.replace(case, sections=tables)
    assert section("coupling").inputs(case) is case.inputs["coupling"]
    assert section("coupling").inputs(changed).given["service_factor"].m_as("") == 3.0
    assert evaluate(changed)["coupling"].service_factor == 3.0 and evaluate(case)["coupling"].service_factor == 2.5
    tables["coupling"]["side"] = "inside"
    with pytest.raises(CalcError, match=r"coupling\.side: expected one of input, output, found 'inside'"):
        evaluate(changed)
