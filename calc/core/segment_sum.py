"""The numeric form of ``SegmentSum``, the sum over a load cycle's segments inside a formula
(:func:`calc.core.formula.segment_sum`): its own module, so that the formulas' stored numeric
forms (:mod:`calc.core.formula_numeric`) import it without importing :mod:`calc.core.formula`,
which imports them."""

from __future__ import annotations

import numpy as np


def sum_last_axis(x):
    """Σ over the last axis of ``x``, the segments of a load cycle.

    Parameters
    ----------
    x : numpy.ndarray
        Values per segment along the last axis [SI unit of the summed term].

    Returns
    -------
    numpy.ndarray or float
        Their sum over the segments [the same unit].

    >>> float(sum_last_axis(np.array([1.0, 2.0, 3.5])))
    6.5
    """
    return np.sum(x, axis=-1)
