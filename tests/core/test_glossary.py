"""The glossary (calc.core.glossary): each symbol declared once, the formulas of the package taking
theirs from it by name, and the one typesetter of ISO 80000-2."""

import ast
import importlib
import pkgutil
from pathlib import Path

import pytest

import calc.domain
from calc import Q_
from calc.core.formula import REGISTRY
from calc.core.glossary import SYMBOLS, Symbol, latex, symbol, typeset
from calc.core.units import KINDS, as_kind, declared_once

CALC = Path(calc.domain.__file__).resolve().parent.parent

for _module in pkgutil.iter_modules(calc.domain.__path__):  # every formula of the package defined
    importlib.import_module(f"calc.domain.{_module.name}")


def package_formulas():
    return [f for f in REGISTRY if f.key.startswith("calc.")]


def test_every_formula_takes_its_symbols_from_the_glossary():
    # By name, or a declared symbol shown in another unit (the transmission error in arcsec).
    for f in package_formulas():
        for s in (f.result, *f.inputs):
            assert s == SYMBOLS[s.name].shown_in(s.unit), (f.key, s.name)


def test_no_module_but_the_glossary_declares_a_symbol():
    # A Symbol(...) anywhere else would be a second declaration a name could drift in.
    found = []
    for path in sorted(CALC.rglob("*.py")):
        if path.name == "glossary.py" and path.parent.name == "core":
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "Symbol":
                found.append(f"{path.relative_to(CALC)}:{node.lineno}")
    assert not found, found


def test_a_name_is_declared_once():
    twice = (Symbol("i", "i", "dimensionless", "", "ratio"), Symbol("i", "i", "dimensionless", "", "another ratio"))
    with pytest.raises(ValueError, match="the symbol 'i' is declared twice"):
        declared_once(twice, "symbol")
    with pytest.raises(ValueError, match="no symbol 'T_9' is declared"):
        symbol("T_9")


@pytest.mark.parametrize("name", sorted(SYMBOLS))
def test_every_symbol_is_shown_in_a_unit_of_its_kind(name):
    s = SYMBOLS[name]
    assert s.kind in KINDS
    as_kind(Q_(1.0, s.unit), s.kind, name)


def test_every_declared_symbol_is_used():
    # By a formula of the package, by the band of a formula's validity (the nominal torque T_N), or by the
    # report (the positioning accuracy of either form).
    used = {s.name for f in package_formulas() for s in (f.result, *f.inputs)}
    bands = [f.source.validity.band for f in package_formulas() if f.source.validity is not None]
    used |= {name for band in bands if band is not None for name in (band.quantity, *(end[1] for end in band.ends))}
    assert set(SYMBOLS) - used == {"Delta_phi_P"}


@pytest.mark.parametrize("written, expected", [
    ("T_1B", r"T_{\mathrm{1B}}"),  # ISO 80000-2: a subscript that names is upright, digits and letters alike
    ("T_2max", r"T_{\mathrm{2max}}"),
    ("M_N", r"M_{\mathrm{N}}"),
    ("n_1", "n_{1}"),
    ("t_k", "t_{k}"),  # a running index is italic
    ("T_1,k", "T_{1,k}"),
    ("P_back_k", r"P_{\mathrm{back},k}"),
    ("d_hub,max", r"d_{\mathrm{hub,max}}"),
    ("phi_TA", r"\varphi_{\mathrm{TA}}"),
    ("K_ϑ", r"K_{\vartheta}"),
    ("M_Nϑ", r"M_{\mathrm{N}\vartheta}"),
    ("ΔT", r"\Delta T"),
    ("Δφ_2", r"\Delta\varphi_{2}"),
    ("lambda", r"\lambda"),
    ("ED", r"\mathrm{ED}"),  # an abbreviation is upright
])
def test_the_one_typesetter(written, expected):
    assert typeset(written) == expected


def test_a_declared_symbol_prints_as_the_source_prints_it():
    # Two quantities the source prints alike keep their own names: the coupling's load side with
    # half the coupling, the limit torques of a stiffness curve.
    assert latex("J_L_coupling") == latex("J_L") == r"J_{\mathrm{L}}"
    assert latex("T_L1") == "T_{1}" and SYMBOLS["T_L1"].description != SYMBOLS["T_1"].description
    assert latex("T_2N") == r"T_{\mathrm{2N}}"  # not declared: typeset by the rule
