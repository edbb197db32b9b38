"""Servo drive-train sizing workbook: gearbox selection (S1, S5), couplings and accuracy.

The package's one unit registry is :data:`ureg` (``Q_`` builds quantities); every formula is a
:class:`calc.core.formula.Formula` defined once in the module of its topic.
"""

from .core.errors import CalcError

__version__ = "0.1.0"

__all__ = ["CalcError", "Q_", "ureg", "__version__"]


def __getattr__(name: str):
    # The registry (pint, some 0.13 s) is built when first asked for: a command that only starts another
    # program, such as the review's server (python -m calc.review.serve), does not wait for it.
    if name in ("Q_", "ureg"):
        from .core import units

        return getattr(units, name)
    raise AttributeError(f"module 'calc' has no attribute {name!r}")
