"""The formula machinery: one sympy definition gives LaTeX, evaluation, dimension check, display."""

import importlib
import pkgutil

import numpy as np
import pytest

import calc
from calc import CalcError, Q_
from calc.core.citation import Document, Source
from calc.core.formula import REGISTRY, Formula, global_names
from calc.core.glossary import Symbol
from calc.domain.gearbox import T_2max
from calc.domain.profile import T_2m

#: The source of the formulas the tests make up.
TESTS = Source(Document("tests", "the package's tests", "drivetrain-calc").at())


def _import_all_modules():
    for info in pkgutil.iter_modules(calc.__path__):
        if info.name != "__main__":
            importlib.import_module(f"calc.{info.name}")


def test_every_formula_of_the_package_is_dimensionally_consistent():
    _import_all_modules()
    assert len(REGISTRY) >= 7
    for formula in REGISTRY:
        formula.check_dimensions()


def test_dimension_check_catches_a_lost_angle():
    # A "stiffness" that forgot the angle: torque over time is neither dimension nor angle right.
    wrong = Formula(
        Symbol("C", "C", "stiffness", "N*m/arcmin", "stiffness"),
        (Symbol("T", "T", "torque", "N*m", "torque"),),
        lambda sp, T: T,  # a torque, not a torque per angle (the trap of E15)
        TESTS,
    )
    try:
        with pytest.raises(CalcError, match="expected stiffness"):
            wrong.check_dimensions()
    finally:
        REGISTRY.remove(wrong)


def test_latex_comes_from_the_expression():
    # ISO 80000-2: the subscripts that name (2max, 1B, s) upright.
    assert T_2max.latex() == r"T_{\mathrm{2max}} = T_{\mathrm{1B}} \cdot i \cdot f_{\mathrm{s}} \cdot \eta"
    assert r"\sqrt[3]" in T_2m.latex() and r"\sum_{k}" in T_2m.latex()


def test_step_shows_symbol_expression_numbers_result():
    step = T_2max.step(T_1B=Q_(12, "N*m"), i=Q_(10, ""), f_s=Q_(1.3, ""), eta=Q_(0.97, ""))
    # Hand calculation: 12 N·m × 10 × 1.3 × 0.97 = 151.32 N·m.
    assert step.result.m_as("N*m") == pytest.approx(151.32)
    assert step.latex() == (
        r"T_{\mathrm{2max}} = T_{\mathrm{1B}} \cdot i \cdot f_{\mathrm{s}} \cdot \eta = "
        r"12\,\mathrm{N\,m} \cdot 10 \cdot 1.3 \cdot 0.97 = 151.3\,\mathrm{N\,m}"
    )
    assert str(step) == "T_2max = 151.3 N·m"


def test_step_expands_segment_sums_with_every_segment():
    values = {"n_2k": Q_(np.array([100.0, 200.0]), "rpm"), "t_k": Q_(np.array([1.0, 2.0]), "s"),
              "T_2k": Q_(np.array([10.0, -5.0]), "N*m")}
    tex = T_2m.step(**values).latex()
    for number in ("100", "200", r"\left(-5\,\mathrm{N\,m}\right)", "10"):
        assert number in tex


def test_evaluation_is_vectorized_and_matches_scalars():
    i = Q_(np.array([3.0, 5.0, 10.0]), "")
    eta = Q_(np.array([0.97, 0.95, 0.9]), "")
    vector = T_2max(T_1B=Q_(2, "N*m"), i=i, f_s=Q_(1.1, ""), eta=eta)
    for k in range(3):
        scalar = T_2max(T_1B=Q_(2, "N*m"), i=i[k], f_s=Q_(1.1, ""), eta=eta[k])
        assert vector[k].m_as("N*m") == pytest.approx(scalar.m_as("N*m"))


def test_arguments_are_checked_by_name():
    with pytest.raises(CalcError, match=r"T_2max: argument 'T_1B': expected a torque"):
        T_2max(T_1B=12.0, i=Q_(10, ""), f_s=Q_(1.3, ""), eta=Q_(0.97, ""))
    with pytest.raises(CalcError, match=r"missing argument 'eta'"):
        T_2max(T_1B=Q_(12, "N*m"), i=Q_(10, ""), f_s=Q_(1.3, ""))
    with pytest.raises(CalcError, match=r"unknown argument 'x'"):
        T_2max(T_1B=Q_(12, "N*m"), i=Q_(10, ""), f_s=Q_(1.3, ""), eta=Q_(0.97, ""), x=1)
    # Bare numbers are fine where the symbol is dimensionless.
    assert T_2max(T_1B=Q_(1, "N*m"), i=2, f_s=1, eta=1).m_as("N*m") == pytest.approx(2)


def test_import_calc_does_not_load_sympy_pandas_or_matplotlib():
    import subprocess
    import sys

    code = (
        "import sys, calc.sections, calc.sections.case, calc.domain.codegen, calc.core.formula_numeric; "
        "print(sorted(m for m in ('sympy', 'pandas', 'matplotlib') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_evaluating_the_example_does_not_load_sympy_pandas_or_matplotlib():
    # The formulas run their stored numeric form (calc/core/formula_numeric.py): no sympy; the example's
    # short measured trace is read by numpy (calc.data.measurement): no pandas.
    import subprocess
    import sys

    from tests.conftest import EXAMPLE

    code = (
        "import sys, calc.sections, calc.sections.case; "
        "calc.sections.evaluate(calc.sections.case.read_case(sys.argv[1])).to_json(); "
        "print(sorted(m for m in ('sympy', 'pandas', 'matplotlib') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code, str(EXAMPLE)], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_stored_numeric_forms_are_what_sympy_generates():
    """calc/core/formula_numeric.py holds lambdify's source of every formula of the package, and each
    formula evaluates through it: the fast path and the checked path are one code."""
    import builtins
    from pathlib import Path

    from calc.domain import codegen
    from calc.core import formula_numeric

    assert Path(formula_numeric.__file__).read_text() == codegen.module_text(), (
        "calc/core/formula_numeric.py is out of date with the formulas: run .venv/bin/python -m calc.domain.codegen"
    )
    for f in codegen.package_formulas():
        stored = formula_numeric.FUNCTIONS[f.key][1]
        assert f.numeric is stored, f.key
        generated = f.lambdified()
        for name in global_names(stored.__code__):
            here = stored.__globals__.get(name, getattr(builtins, name, None))
            there = generated.__globals__.get(name, getattr(builtins, name, None))
            assert here is there, f"{f.key}: {name} is {here!r} in the stored code, {there!r} in lambdify's"


def test_a_changed_formula_is_not_evaluated_by_stale_stored_code(monkeypatch):
    from calc.core import formula_numeric

    f = Formula(
        Symbol("y", "y", "torque", "N*m", "result"),
        (Symbol("x", "x", "torque", "N*m", "argument"),),
        lambda sp, x: 2 * x,
        TESTS,
    )
    try:
        # An entry under this formula's key, stored from another builder (x + x + x).
        monkeypatch.setitem(formula_numeric.FUNCTIONS, f.key, ("0" * 16, lambda x: 3 * x))
        assert f(x=Q_(1.5, "N*m")).m_as("N*m") == pytest.approx(3.0)
    finally:
        REGISTRY.remove(f)


def test_fingerprint_follows_the_builder_and_the_constants_it_reads():
    def formula(build):
        f = Formula(Symbol("y", "y", "torque", "N*m", "r"), (Symbol("x", "x", "torque", "N*m", "a"),), build, TESTS)
        REGISTRY.remove(f)
        return f

    assert formula(lambda sp, x: 2 * x).fingerprint == formula(lambda sp, x: 2 * x).fingerprint
    assert formula(lambda sp, x: 2 * x).fingerprint != formula(lambda sp, x: 3 * x).fingerprint
    assert formula(lambda sp, x: 2 * x).fingerprint != formula(lambda sp, x: x / 2).fingerprint
    # Only the body counts, not its layout on the line or the names around it.
    f = formula(lambda sp, x: 2 * x)
    g = formula(
        lambda sp, x: 2 * x
    )
    assert f.fingerprint == g.fingerprint


def test_documentation_comes_from_the_formula_object():
    import inspect

    doc = inspect.getdoc(T_2max)
    assert doc.startswith("T_2max: maximum output torque [N·m]")
    assert T_2max.latex() in doc
    assert "T_1B : torque [N·m]" in doc and "source, S5 calculation 2" in doc
    assert inspect.getdoc(Formula).startswith("One formula of the source document, defined once.")


def test_segment_values_of_different_lengths_are_named():
    # Two speeds, three durations, two torques: no segment sum can pair them up.
    values = {
        "n_2k": Q_(np.array([100.0, 200.0]), "rpm"),
        "t_k": Q_(np.array([1.0, 2.0, 3.0]), "s"),
        "T_2k": Q_(np.array([10.0, -5.0]), "N*m"),
    }
    with pytest.raises(CalcError) as err:
        T_2m.substituted_latex(values)
    assert str(err.value) == "T_2m: the per-segment arguments differ in length"


def test_codegen_refuses_two_formulas_of_one_name_in_one_module():
    # A second T_2max in calc.domain.gearbox would be stored under the first one's key calc.domain.gearbox.T_2max.
    from calc.domain import codegen

    def build(sp, T_1B):
        return 2 * T_1B

    build.__module__ = "calc.domain.gearbox"
    twin = Formula(T_2max.result, (T_2max.inputs[0],), build, TESTS)
    try:
        with pytest.raises(CalcError) as err:
            codegen.package_formulas()
        assert str(err.value) == (
            "calc.domain.gearbox.T_2max: two formulas of one module have this name; give each its own result symbol"
        )
    finally:
        REGISTRY.remove(twin)


def test_codegen_refuses_a_function_it_cannot_import():
    # sympy's lambdify takes erf from the math module (numpy has none): the stored module could not import it.
    from calc.domain import codegen

    f = Formula(Symbol("y", "y", "dimensionless", "", "result"), (Symbol("x", "x", "dimensionless", "", "argument"),),
                lambda sp, x: sp.erf(x), TESTS)
    REGISTRY.remove(f)
    with pytest.raises(CalcError) as err:
        codegen.module_text([f])
    assert str(err.value) == (
        "the generated numeric form uses 'erf' = <built-in function erf>, which calc.domain.codegen cannot import"
    )
