"""The case's motor catalog and the case's fields a row of it gives: read by the axis (a named
part), the motor section (every motor ranked) and the pair search (every motor with every
gearbox)."""

from __future__ import annotations

from .case import Case
from ..data.catalog import load_catalogs
from ..domain.motor_ratings import SCHEMA


def motor_ratings(cat, row: int) -> dict:
    """The case's fields a catalog motor gives.

    Parameters
    ----------
    cat : calc.data.catalog.Catalog
        A motor catalog, of :data:`calc.domain.motor_ratings.SCHEMA`.
    row : int
        The motor's row.

    Returns
    -------
    dict
        Field of :class:`calc.sections.case.Case` -> value: its maximum torque as T_1B, its rated
        torque, top speed and rotor inertia.
    """
    return {"motor_peak_torque": cat["M_max"][row], "motor_rated_torque": cat["M_N"][row],
            "motor_max_speed": cat["n_max"][row], "motor_inertia": cat["J"][row]}


def motor_catalog(case: Case):
    """The case's motor catalog.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.

    Returns
    -------
    calc.data.catalog.Catalog
        Of :data:`calc.domain.motor_ratings.SCHEMA` (read once per run,
        :func:`calc.data.catalog.load_catalog`).
    """
    return load_catalogs(case.motor_catalog, case.folder, f"{case.path}: motor.catalog", SCHEMA)
