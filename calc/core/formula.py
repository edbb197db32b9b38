"""One definition per formula: a sympy expression, and everything derived from it.

A :class:`Formula` holds the right-hand side of one formula of the source document as a sympy
expression over symbols declared by name in :mod:`calc.core.glossary`. From that one object come

* its LaTeX (:meth:`Formula.latex`), for docstrings, notebooks and reports;
* its numeric evaluation (:meth:`Formula.__call__`): quantities in, each checked for its kind
  (dimension and angle, errata E15), converted to coherent SI magnitudes, evaluated by a
  ``lambdify``-generated numpy function over scalars or whole arrays, and the unit reattached;
  the generated function of each formula of the package is stored in :mod:`calc.core.formula_numeric`
  (written by ``python -m calc.domain.codegen``, checked by the tests), so evaluating needs no sympy;
* its dimensional check (:meth:`Formula.check_dimensions`), run over every formula by the tests;
* its display with substituted values (:meth:`Formula.step`), ``symbol = expression = numbers =
  result``, printed from the expression tree, never from source text.
* its source (:attr:`Formula.source`, :mod:`calc.core.citation`): the documents cited, the places in
  them, the readings taken and the validity, from which its reference sentence is rendered
  (:attr:`Formula.reference`, what the docstring and the calc report print).

Sums over the segments of a load profile are written with :func:`segment_sum` (Σ over k); the
numeric form sums over the last axis, so a batch of profiles evaluates at once.

sympy is imported on first use of a formula's expression, not when ``calc`` is imported, nor to
evaluate a formula whose stored numeric form is current.
"""

from __future__ import annotations

import functools
import hashlib
import inspect
import linecache
from dataclasses import dataclass
from types import CodeType, SimpleNamespace
from typing import Callable

import numpy as np

from .citation import Source
from .errors import CalcError, listing, as_found
from .glossary import Symbol, symbol
from .segment_sum import sum_last_axis
from .units import Q_, as_kind, fmt, from_si, kind, latex_unit, pretty_unit, sig, to_si, unit

REGISTRY: list["Formula"] = []


@functools.cache
def _sympy() -> SimpleNamespace:
    """sympy, and the Σ-over-segments function, built on first use."""
    import sympy as sp
    from sympy.printing.precedence import PRECEDENCE

    class SegmentSum(sp.Function):
        """Σ_k of its argument over the segments k of a load profile."""

        nargs = 1

        def _latex(self, printer, exp=None):
            body = printer.parenthesize(self.args[0], PRECEDENCE["Mul"])
            out = r"\sum_{k} " + body
            return rf"\left({out}\right)^{{{exp}}}" if exp else out

    class Value(sp.Symbol):
        """A number with its unit, standing in for a symbol in the substituted display."""

        def __new__(cls, key, tex, has_unit):
            # The text is part of the name: sympy caches symbols and products by name, and a
            # product cached with an earlier value of the same key would print that value.
            obj = super().__new__(cls, f"{key}={tex}")
            obj._tex = tex
            obj.precedence = PRECEDENCE["Mul"] if has_unit else PRECEDENCE["Atom"]
            return obj

        def _latex(self, printer):
            return self._tex

    return SimpleNamespace(sp=sp, SegmentSum=SegmentSum, Value=Value)


def segment_sum(x):
    """Σ over the profile's segments k (for use inside a formula's builder).

    Parameters
    ----------
    x : sympy.Expr
        The term of segment k.

    Returns
    -------
    sympy.Expr
        The sum, kept unevaluated so it prints as Σ and evaluates over the last axis.
    """
    return _sympy().SegmentSum(x)


class Formula:
    """One formula of the source document, defined once.

    Parameters
    ----------
    result : str or Symbol
        The left-hand side: a symbol's name in :mod:`calc.core.glossary`.
    inputs : tuple of str or Symbol
        The symbols of the right-hand side by name (or a declared symbol shown in another unit,
        :meth:`calc.core.glossary.Symbol.shown_in`), in the order of ``build``'s parameters.
    build : callable
        ``build(sp, *symbols)`` returns the right-hand side as a sympy expression; ``sp`` is the
        sympy module.
    source : Source
        Where the formula comes from: the documents cited, the places, the readings taken and the
        validity (:mod:`calc.core.citation`).

    Raises
    ------
    CalcError
        When ``source`` is not a :class:`calc.core.citation.Source`.
    """

    def __init__(self, result: str | Symbol, inputs: tuple[str | Symbol, ...], build: Callable, source: Source):
        self.result = _declared(result)
        if not isinstance(source, Source):
            raise CalcError(f"{self.result.name}: expected the formula's source as a Source of citations, found "
                            f"{type(source).__name__} {as_found(source)}")
        self.inputs = tuple(_declared(s) for s in inputs)
        self._build = build
        self.source = source
        REGISTRY.append(self)

    def __repr__(self):
        return f"Formula({self.result.name} = …, {self.reference})"

    @property
    def name(self) -> str:
        return self.result.name

    @property
    def reference(self) -> str:
        """Where the formula comes from, as one sentence (its source's text): what the outputs print."""
        return self.source.text

    @functools.cached_property
    def _symbols(self):
        sp = _sympy().sp
        return tuple(sp.Symbol(s.name) for s in self.inputs)

    @functools.cached_property
    def expr(self):
        """The right-hand side as a sympy expression."""
        return self._build(_sympy().sp, *self._symbols)

    @functools.cached_property
    def _symbol_names(self):
        return {sym: s.latex for sym, s in zip(self._symbols, self.inputs)}

    def latex(self) -> str:
        """``lhs = rhs`` in LaTeX.

        Returns
        -------
        str
            The formula as LaTeX math.
        """
        return f"{self.result.latex} = {self._latex(self.expr)}"

    def _latex(self, expr) -> str:
        return _sympy().sp.latex(expr, symbol_names=self._symbol_names, mul_symbol="dot", order="none")

    def _repr_latex_(self):
        return f"$${self.latex()}$$"

    @property
    def key(self) -> str:
        """The module that defines the formula and its name (``calc.domain.gearbox.T_2max``)."""
        return f"{self._build.__module__}.{self.name}"

    @functools.cached_property
    def fingerprint(self) -> str:
        """A digest of what the expression is built from (the builder's source text and the
        constants it reads, the symbols' names), computed without sympy. Source text, not bytecode,
        so the stored forms hold on every Python version."""
        parts = [self.result.name, [s.name for s in self.inputs], _builder_parts(self._build)]
        parts += [repr(c.cell_contents) for c in self._build.__closure__ or ()]
        return hashlib.sha256(repr(parts).encode()).hexdigest()[:16]

    @functools.cached_property
    def numeric(self) -> Callable:
        """The right-hand side as a numpy function of SI magnitudes, in the order of ``inputs``.

        It is what :meth:`lambdified` generates from the expression. For the package's formulas
        it is read from :mod:`calc.core.formula_numeric`, where it was stored from that same
        generator, as long as the builder is the one it was stored from (:attr:`fingerprint`).
        """
        from .formula_numeric import FUNCTIONS

        fingerprint, function = FUNCTIONS.get(self.key, (None, None))
        return function if fingerprint == self.fingerprint else self.lambdified()

    def lambdified(self) -> Callable:
        """The right-hand side turned into a numpy function by sympy's ``lambdify``.

        Returns
        -------
        callable
            A function of the inputs' SI magnitudes, in the order of :attr:`inputs`.
        """
        s = _sympy()
        return s.sp.lambdify(self._symbols, self.expr, modules=[{"SegmentSum": sum_last_axis}, "numpy"], cse=True)

    def numeric_source(self, name: str) -> str:
        """The source of :meth:`lambdified` as a function called ``name``.

        Parameters
        ----------
        name : str
            The function's name.

        Returns
        -------
        str
            Python source text.
        """
        source = inspect.getsource(self.lambdified())
        return source.replace("def _lambdifygenerated(", f"def {name}(", 1)

    @functools.cached_property
    def _arguments(self) -> tuple:
        """Per input: the symbol and, for a constant, its SI magnitude."""
        return tuple((s, None if s.value is None else Q_(s.value).m_as(unit(kind(s.kind).si_unit)))
                     for s in self.inputs)

    @functools.cached_property
    def _takes(self) -> tuple:
        return tuple(s.name for s in self.inputs if s.value is None)

    def _si_args(self, values: dict) -> list:
        if not values.keys() <= set(self._takes):
            unknown = sorted(set(values) - set(self._takes))
            raise CalcError(f"{self.name}: unknown argument {as_found(unknown[0])}; the formula takes "
                            f"{listing(self._takes)}")
        args = []
        for s, constant in self._arguments:
            if constant is not None:
                args.append(constant)
                continue
            if s.name not in values:
                raise CalcError(f"{self.name}: missing argument {as_found(s.name)} ({s.description}, "
                                f"{kind(s.kind).name})")
            args.append(to_si(values[s.name], s.kind, f"{self.name}: argument {s.name!r}"))
        if self._per_segment:
            lengths = {self.inputs[k].name: np.shape(args[k])[-1] for k in self._per_segment if np.ndim(args[k])}
            if len(set(lengths.values())) > 1:
                found = listing(f"{name} {n}" for name, n in lengths.items())
                raise CalcError(f"{self.name}: expected one value per segment in each per-segment argument, found "
                                f"lengths {found}")
        return args

    @functools.cached_property
    def _per_segment(self) -> tuple:
        """The positions of the inputs given one value per segment (summed over by the formula)."""
        return tuple(k for k, s in enumerate(self.inputs) if s.per_segment and s.value is None)

    def __call__(self, **values):
        """Evaluate with quantities (scalars or arrays); returns a quantity in the result's unit."""
        return from_si(self.numeric(*self._si_args(values)), self.result.kind, self.result.unit)

    def si(self, **magnitudes):
        """Evaluate on SI magnitudes (floats or arrays) without unit checks, constants supplied:
        for sampled cycles inside the package, whose inputs were checked once as quantities.

        Parameters
        ----------
        **magnitudes : float or numpy.ndarray [SI]
            Each input by its symbol's name, in its kind's SI unit.

        Returns
        -------
        float or numpy.ndarray [SI]
            The result in its kind's SI unit.
        """
        return self.numeric(*[magnitudes[s.name] if c is None else c for s, c in self._arguments])

    def check_dimensions(self) -> None:
        """Evaluate the expression on quantities of the declared units and check the result's kind.

        The check is on dimension and on the power of angle (errata E15), so a formula that
        loses or gains an angle fails.

        Returns
        -------
        None

        Raises
        ------
        CalcError
            On a mismatch, naming the formula, the unit found and the kind expected.
        """
        args = []
        for k, s in enumerate(self.inputs):
            unit = kind(s.kind).si_unit
            # A distinct value per input, so a difference of two inputs is never zero.
            args.append(Q_(np.array([1.0, 2.0]) if s.per_segment else 1.5 + 0.1 * k, unit))
        # only the unit counts: a root of a negative test value is NaN of the right unit
        with np.errstate(invalid="ignore"):
            out = self.numeric(*args)
        if not hasattr(out, "units"):
            out = Q_(out, "")
        if not kind(self.result.kind).accepts(out.units):
            raise CalcError(
                f"{self.name}: the expression gives {out.units:~P}, expected {kind(self.result.kind).name} "
                f"({self.result.unit})"
            )

    def documentation(self) -> str:
        """A numpydoc text of the formula: what it gives, its equation, its symbols, its source.

        Returns
        -------
        str
            Summary, ``.. math::``, Parameters and References.
        """
        r = self.result
        lines = [f"{r.name}: {r.description} [{pretty_unit(r.unit) or '-'}]", "", f".. math:: {self.latex()}", "",
                 "Parameters", "----------"]
        for s in self.inputs:
            lines += [f"{s.name} : {s.kind} [{pretty_unit(s.unit) or '-'}]{', per segment' if s.per_segment else ''}",
                      f"    {s.description}"]
        lines += ["", "References", "----------", self.reference]
        return "\n".join(lines)

    def step(self, result=None, **values) -> "Step":
        """Evaluate (unless ``result`` is given) and return the displayable step.

        Parameters
        ----------
        result : pint.Quantity [the result's unit], optional
            The result when already computed.
        **values : pint.Quantity [each symbol's unit]
            Each input by its symbol's name.

        Returns
        -------
        Step
            The formula with its values and result.
        """
        if result is None:
            result = self(**values)
        return Step(self, values, result)

    def substituted_latex(self, values: dict) -> str:
        """The right-hand side with each symbol replaced by its value and unit.

        Parameters
        ----------
        values : dict
            Each input by its symbol's name, a quantity (an array for a per-segment input).

        Returns
        -------
        str
            The expression as LaTeX with the numbers in it.

        Raises
        ------
        CalcError
            When the per-segment arguments differ in length.
        """
        s = _sympy()
        expr = self.expr
        values = {**{c.name: Q_(c.value) for c in self.inputs if c.value is not None}, **values}
        segment_syms = {sym: spec for sym, spec in zip(self._symbols, self.inputs) if spec.per_segment}
        if segment_syms:
            n_seg = {len(np.atleast_1d(values[spec.name].magnitude)) for spec in segment_syms.values()}
            if len(n_seg) != 1:
                raise CalcError(f"{self.name}: the per-segment arguments differ in length")
            count = n_seg.pop()

            def expand(node):
                terms = []
                for k in range(count):
                    repl = {sym: _value(s, values[spec.name][k], spec, f"{spec.name}_{k}")
                            for sym, spec in segment_syms.items()}
                    terms.append(node.args[0].xreplace(repl))
                return s.sp.Add(*terms, evaluate=False)

            with s.sp.evaluate(False):  # keep the formula's order and shape with numbers in it
                expr = expr.replace(lambda e: isinstance(e, s.SegmentSum), expand)
        repl = {
            sym: _value(s, values[spec.name], spec, spec.name)
            for sym, spec in zip(self._symbols, self.inputs)
            if not spec.per_segment
        }
        with s.sp.evaluate(False):
            expr = expr.xreplace(repl)
        return self._latex(expr)


def _declared(s: str | Symbol) -> Symbol:
    """A symbol by its name in the glossary (a symbol given as such is taken as it is: a declared one
    shown in another unit, or one of a formula made outside the package)."""
    return symbol(s) if isinstance(s, str) else s


class _Doc:
    """``help(formula)`` and ``formula?`` show the formula's own documentation."""

    def __get__(self, obj, cls):
        return cls._class_doc if obj is None else obj.documentation()


Formula._class_doc = Formula.__doc__
Formula.__doc__ = _Doc()


def _builder_parts(build: Callable) -> list:
    """The parts of a builder that decide its expression: the source text of its body and the
    values of the plain constants it reads from its module."""
    names = sorted(global_names(build.__code__))
    namespace = build.__globals__
    return [_body_text(build),
            [repr(namespace[n]) for n in names if isinstance(namespace.get(n), (bool, int, float, str, tuple, dict))]]


def _body_text(build: Callable) -> str:
    """The source text of a builder's body, cut out by the code's own source positions (so two
    lambdas on one line differ); the whole source where positions are missing; the bytecode where
    there is no source file (such a fingerprint never matches a stored one)."""
    code = build.__code__
    spans = [p for p in code.co_positions() if None not in p and (p[0], p[2]) != (p[1], p[3])]
    lines = linecache.getlines(code.co_filename)
    if not lines:
        return repr(code.co_code)
    if not spans:
        return inspect.getsource(build).strip()
    first, last = min(p[0] for p in spans), max(p[1] for p in spans)
    start = min(p[2] for p in spans if p[0] == first)
    end = max(p[3] for p in spans if p[1] == last)
    text = lines[first - 1 : last]
    text[-1] = text[-1][:end]
    text[0] = text[0][start:]
    return "".join(text)


def global_names(code: CodeType) -> set[str]:
    """The global names a function's code reads, nested code included.

    Parameters
    ----------
    code : types.CodeType
        A function's code object.

    Returns
    -------
    set of str
        The names.
    """
    names = set(code.co_names)
    for const in code.co_consts:
        if isinstance(const, CodeType):
            names |= global_names(const)
    return names


def _value(s, q, spec: Symbol, key: str):
    q = as_kind(q, spec.kind, spec.name)
    magnitude = q.m_as(spec.unit) if spec.unit else q.m_as("")
    number = sig(magnitude)
    tex = number if not spec.unit else rf"{number}\,{latex_unit(spec.unit)}"
    if magnitude < 0:
        tex = rf"\left({tex}\right)"
    return s.Value(f"v_{key}", tex, bool(spec.unit))


@dataclass(repr=False)
class Step:
    """One evaluated formula: what a notebook or report shows as a line of the calculation.

    Parameters
    ----------
    formula : Formula
        The formula.
    values : dict
        Its inputs by symbol name, as quantities.
    result : pint.Quantity [the result's unit]
        Its result.
    """

    formula: Formula
    values: dict
    result: object

    @property
    def result_text(self) -> str:
        return fmt(self.result, self.formula.result.unit)

    def parts(self) -> tuple[str, str, str, str]:
        """The step's four sides in LaTeX: symbol, expression, substituted values, result.

        Returns
        -------
        tuple of str
            ``(symbol, expression, substituted, result)``.
        """
        f = self.formula
        number = sig(self.result.m_as(f.result.unit))
        unit = latex_unit(f.result.unit)
        result = number + (rf"\,{unit}" if unit else "")
        return f.result.latex, f._latex(f.expr), f.substituted_latex(self.values), result

    def latex(self) -> str:
        """The step as one LaTeX equation, its four sides joined by ``=``.

        Returns
        -------
        str
            ``symbol = expression = substituted = result``.
        """
        return " = ".join(self.parts())

    def _repr_latex_(self):
        return f"$${self.latex()}$$"

    def __repr__(self):
        return f"<Step {self}>"

    def __str__(self):
        return f"{self.formula.result.name} = {self.result_text}"
