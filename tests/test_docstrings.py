"""Every public function, method and class of the covered layers documents its arguments in numpydoc
form, read by ``numpydoc.docscrape`` as Sphinx would read it.

A public callable is a function, a method or a class defined in ``calc/`` whose name does not start
with ``_`` (properties are values, not callables; the generated :mod:`calc.core.formula_numeric` is
left out). Each argument other than ``self``/``cls`` must appear in its Parameters section, and every
entry there must name an argument; a class documents its constructor's arguments, a dataclass its
fields as Parameters or Attributes. A parameter given as a ``pint.Quantity`` names its unit in
brackets (``T_2max : pint.Quantity [N*m]``). Each covered layer has at least :data:`MIN_SHARE` of
its callables with a Parameters section (or no arguments) and of its functions and methods with a
Returns (or Yields) section; ``python -m tests.test_docstrings`` prints the shares of every layer.
A layer not yet held whole has its finished modules held one by one (:data:`COVERED_MODULES`),
each to the same rules, so that they do not fall back while the rest of it is written.
"""

import dataclasses
import importlib
import inspect
import warnings
from pathlib import Path

import pytest
from numpydoc.docscrape import NumpyDocString

CALC = Path(__file__).resolve().parent.parent / "calc"

#: The layers whose docstrings are held to the rule: every subpackage of calc, lowest first.
COVERED = ("core", "data", "domain", "figures", "sections", "report", "review")
#: The modules held to the rule outside the layers (dotted names): the package and its command line.
COVERED_MODULES = ("calc", "calc.__main__")
#: Generated code, not written by hand.
SKIPPED = {"calc.core.formula_numeric"}
#: The least share of a covered layer's (or module's) callables with Parameters (and of its functions with Returns).
MIN_SHARE = 0.8


@dataclasses.dataclass(frozen=True)
class Callable:
    """A public callable with the arguments its docstring must document.

    Parameters
    ----------
    name : str
        Its dotted name from the package, ``calc.domain.gearbox.select_gearbox``.
    arguments : tuple of str
        The arguments to document, ``*args``/``**kwargs`` with their stars.
    doc : str
        Its docstring, dedented (empty when it has none).
    is_class : bool
        A class (its constructor's arguments; it has no Returns).
    fields_as_attributes : bool
        A dataclass or named tuple, whose fields may be documented as Attributes.
    """

    name: str
    arguments: tuple
    doc: str
    is_class: bool = False
    fields_as_attributes: bool = False


def modules(layer: str) -> list:
    """The modules of one layer, imported.

    Parameters
    ----------
    layer : str
        A subpackage of calc (``"domain"``).

    Returns
    -------
    list of module
        Its modules in file order, the generated ones left out.
    """
    names = sorted(
        ".".join(("calc", *path.relative_to(CALC).with_suffix("").parts)).removesuffix(".__init__")
        for path in (CALC / layer).rglob("*.py")
    )
    return [importlib.import_module(name) for name in names if name not in SKIPPED]


def arguments(function, bound: bool) -> tuple:
    """The arguments of ``function`` its docstring names, ``self``/``cls`` left out.

    Parameters
    ----------
    function : callable
        A function, unwrapped from its decorators.
    bound : bool
        A method or constructor, whose first argument is ``self`` or ``cls``.

    Returns
    -------
    tuple of str
        The argument names, ``*args`` and ``**kwargs`` with their stars.
    """
    names = []
    for k, parameter in enumerate(inspect.signature(function).parameters.values()):
        if bound and k == 0:
            continue
        star = {parameter.VAR_POSITIONAL: "*", parameter.VAR_KEYWORD: "**"}.get(parameter.kind, "")
        names.append(star + parameter.name)
    return tuple(names)


def constructor_arguments(cls) -> tuple:
    """The arguments a class takes when built: a dataclass's fields (those it adds to a base
    dataclass's), a named tuple's fields, or its
    own ``__init__``'s (one written outside calc, as an exception's, takes none of its own).

    Parameters
    ----------
    cls : type
        A class defined in calc.

    Returns
    -------
    tuple of str
        The argument names.
    """
    if dataclasses.is_dataclass(cls):
        # A base dataclass documents the fields it declares.
        inherited = {f.name for base in cls.__mro__[1:] if dataclasses.is_dataclass(base)
                     for f in dataclasses.fields(base)}
        return tuple(f.name for f in dataclasses.fields(cls) if f.init and f.name not in inherited)
    if issubclass(cls, tuple) and hasattr(cls, "_fields"):
        return tuple(cls._fields)
    init = next(vars(c)["__init__"] for c in cls.__mro__ if "__init__" in vars(c))
    # Written in calc (tests/conftest.py wraps CalcError's to record the messages the tests raise).
    if not inspect.isfunction(init) or not Path(init.__code__.co_filename).is_relative_to(CALC):
        return ()
    return arguments(init, bound=True)


def function_entry(name: str, function, bound: bool) -> Callable:
    """One function or method as a :class:`Callable`.

    Parameters
    ----------
    name : str
        Its dotted name.
    function : callable
        The function as defined (decorated or not).
    bound : bool
        A method, whose first argument is ``self`` or ``cls`` (not for a static method).

    Returns
    -------
    Callable
        Its arguments and docstring.
    """
    return Callable(name, arguments(inspect.unwrap(function), bound), inspect.getdoc(function) or "")


def methods(cls, prefix: str):
    """The public methods a class defines itself (not those it inherits), properties left out.

    Parameters
    ----------
    cls : type
        A class defined in calc.
    prefix : str
        The class's dotted name.

    Yields
    ------
    Callable
        Each method.
    """
    for name, member in vars(cls).items():
        if name.startswith("_"):
            continue
        if isinstance(member, staticmethod):
            yield function_entry(f"{prefix}.{name}", member.__func__, bound=False)
        elif isinstance(member, classmethod):
            yield function_entry(f"{prefix}.{name}", member.__func__, bound=True)
        elif inspect.isfunction(member):
            yield function_entry(f"{prefix}.{name}", member, bound=True)


def public_callables(layer: str) -> list:
    """Every public function, class and method defined in a layer.

    Parameters
    ----------
    layer : str
        A subpackage of calc.

    Returns
    -------
    list of Callable
        In module order, then by definition.
    """
    return [item for module in modules(layer) for item in module_callables(module)]


def module_callables(module) -> list:
    """Every public function, class and method defined in one module.

    Parameters
    ----------
    module : module
        A module of calc, imported.

    Returns
    -------
    list of Callable
        By definition.
    """
    found = []
    for name, obj in vars(module).items():
        defined_here = getattr(obj, "__module__", None) == module.__name__
        if name.startswith("_") or not defined_here or getattr(obj, "__qualname__", None) != name:
            continue  # private, imported or an alias of a callable named otherwise
        dotted = f"{module.__name__}.{name}"
        if inspect.isclass(obj):
            fields = dataclasses.is_dataclass(obj) or issubclass(obj, tuple)
            found.append(Callable(dotted, constructor_arguments(obj), inspect.getdoc(obj) or "", True, fields))
            found.extend(methods(obj, dotted))
        elif callable(obj) and inspect.isfunction(inspect.unwrap(obj)):
            found.append(function_entry(dotted, obj, bound=False))
    return found


def parsed(item: Callable) -> NumpyDocString:
    """The docstring as numpydoc reads it.

    Parameters
    ----------
    item : Callable
        The callable.

    Returns
    -------
    NumpyDocString
        Its sections.

    Raises
    ------
    ValueError
        For a docstring numpydoc cannot read (an unknown section's heading, a section twice),
        naming the callable.
    """
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            return NumpyDocString(item.doc)
        except (ValueError, UserWarning) as error:
            raise ValueError(f"{item.name}: numpydoc cannot read its docstring: {error}") from None


def documented(doc: NumpyDocString, item: Callable) -> dict:
    """The arguments a docstring documents, each with its type text.

    Parameters
    ----------
    doc : NumpyDocString
        The parsed docstring.
    item : Callable
        Its callable (a dataclass's Attributes count as its fields).

    Returns
    -------
    dict
        Argument name to type text; ``a, b : float`` gives both names.
    """
    entries = list(doc["Parameters"]) + list(doc["Other Parameters"])
    if item.fields_as_attributes:
        entries += list(doc["Attributes"])
    return {name.strip(): entry.type for entry in entries for name in entry.name.split(",")}


def has_parameters(item: Callable) -> bool:
    """Whether a callable's Parameters share counts it: it has no arguments, or a section for them.

    Parameters
    ----------
    item : Callable
        The callable.

    Returns
    -------
    bool
        True for one with nothing to document or its arguments' section.
    """
    return not item.arguments or bool(documented(parsed(item), item))


def has_returns(item: Callable) -> bool:
    """Whether a function or method documents what it returns (or yields).

    Parameters
    ----------
    item : Callable
        A function or method.

    Returns
    -------
    bool
        True when its docstring has a Returns or Yields section.
    """
    doc = parsed(item)
    return bool(doc["Returns"] or doc["Yields"])


def shares(items: list) -> tuple:
    """The shares of documented callables among ``items`` (a layer's or a module's).

    Parameters
    ----------
    items : list of Callable
        The callables (:func:`public_callables`, :func:`module_callables`).

    Returns
    -------
    tuple
        (callables, share with Parameters or no arguments [1], functions and methods, share with
        Returns [1]); a share is 1 where there is nothing to count.
    """
    functions = [item for item in items if not item.is_class]
    with_parameters = sum(_counts(has_parameters, item) for item in items)
    with_returns = sum(_counts(has_returns, item) for item in functions)
    return (len(items), with_parameters / len(items) if items else 1.0,
            len(functions), with_returns / len(functions) if functions else 1.0)


def _counts(has, item: Callable) -> bool:
    # A docstring numpydoc cannot read counts as missing (the test per callable names it).
    try:
        return has(item)
    except ValueError:
        return False


def assert_shares(what: str, items: list) -> None:
    """Fail where fewer than :data:`MIN_SHARE` of ``items`` have Parameters, or of their functions Returns.

    Parameters
    ----------
    what : str
        The layer or module, for the message.
    items : list of Callable
        Its public callables.

    Returns
    -------
    None
    """
    count, parameters, functions, returns = shares(items)
    print(f"{what}: {count} public callables, {parameters:.0%} with Parameters; "
          f"{functions} functions and methods, {returns:.0%} with Returns")
    assert parameters >= MIN_SHARE, f"{what}: {parameters:.0%} of {count} callables have Parameters"
    assert returns >= MIN_SHARE, f"{what}: {returns:.0%} of {functions} functions and methods have Returns"


COVERED_CALLABLES = ([item for layer in COVERED for item in public_callables(layer)]
                     + [item for name in COVERED_MODULES for item in module_callables(importlib.import_module(name))])


@pytest.mark.parametrize("item", COVERED_CALLABLES, ids=lambda item: item.name.removeprefix("calc."))
def test_every_argument_is_documented(item):
    doc = parsed(item)
    named = documented(doc, item)
    missing = [name for name in item.arguments if name not in named and name.lstrip("*") not in named]
    assert not missing, f"{item.name}: argument(s) {', '.join(missing)} not documented in its Parameters section"
    known = set(item.arguments) | {name.lstrip("*") for name in item.arguments}
    stale = [name for name in named if name not in known]
    if not any(name.startswith("**") for name in item.arguments):
        assert not stale, f"{item.name}: Parameters names {', '.join(stale)}, which it does not take"
    unitless = [name for name, kind in named.items() if "Quantity" in kind and "[" not in kind]
    assert not unitless, f"{item.name}: the quantity parameter(s) {', '.join(unitless)} name no unit in brackets"


@pytest.mark.parametrize("layer", COVERED)
def test_most_callables_have_parameters_and_returns(layer):
    assert_shares(f"calc/{layer}", public_callables(layer))


@pytest.mark.parametrize("name", COVERED_MODULES)
def test_most_callables_of_a_covered_module_have_parameters_and_returns(name):
    assert_shares(name, module_callables(importlib.import_module(name)))


def test_the_rule_catches_an_undocumented_argument():
    def gear_torque(T_2max, i):
        """The input torque.

        Parameters
        ----------
        T_2max : pint.Quantity [N*m]
            The output torque.

        Returns
        -------
        pint.Quantity [N*m]
            The input torque.
        """

    item = function_entry("gear_torque", gear_torque, bound=False)
    assert item.arguments == ("T_2max", "i")
    assert set(documented(parsed(item), item)) == {"T_2max"}
    with pytest.raises(AssertionError, match=r"gear_torque: argument\(s\) i not documented"):
        test_every_argument_is_documented(item)


def test_a_dataclass_documents_its_fields():
    @dataclasses.dataclass
    class Stage:
        """A stage.

        Attributes
        ----------
        ratio : float
            Its ratio [1].
        """

        ratio: float
        name: str = ""

    item = Callable("Stage", constructor_arguments(Stage), inspect.getdoc(Stage), True, True)
    with pytest.raises(AssertionError, match=r"Stage: argument\(s\) name not documented"):
        test_every_argument_is_documented(item)


if __name__ == "__main__":
    rows = [(f"calc/{layer}", public_callables(layer)) for layer in COVERED]
    rows += [(name, module_callables(importlib.import_module(name))) for name in COVERED_MODULES]
    for what, items in rows:
        count, parameters, functions, returns = shares(items)
        print(f"{what}: {count} callables, {parameters:.0%} with Parameters; "
              f"{functions} functions and methods, {returns:.0%} with Returns")
