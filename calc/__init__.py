"""Servo drive-train sizing workbook: gearbox selection (S1, S5), couplings and accuracy.

The package's one unit registry is :data:`ureg` (``Q_`` builds quantities); every formula is a
:class:`calc.core.formula.Formula` defined once in the module of its topic.
"""

from .core.errors import CalcError
from .core.units import Q_, ureg

__version__ = "0.1.0"

__all__ = ["CalcError", "Q_", "ureg", "__version__"]
