"""Each student's own brief: the indexing table's axis (``cases/indexing-table.toml``) with the
table's inertia, its index, the move's time and the dwell drawn from ranges in which the design
stays interesting (the inertia ratio near its limit, the mode S5 or S1 by the dwell), seeded by
the course's seed and the student's name, so the lecturer draws the same brief again to grade it.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass

import numpy as np

from ..core.errors import CalcError

#: The ranges the variants are drawn from, each as (lowest, highest, step).
TABLE_INERTIA = (1000, 2000, 10)   # kg·cm², at the gearbox output: lambda from about 6 to 12 at i = 10
MOVE_TIME = (0.40, 0.80, 0.01)     # s, one index
DWELL = (0.30, 2.00, 0.05)         # s: ED from about 17 % to 73 %, S5 or S1 (E3)
STATIONS = (3, 4, 5, 6)            # an index is a whole turn over the stations
RAMP_SHARE = 0.3                   # of the move's time, each speed ramp (as the example's 0.15 s of 0.5 s)
JERK_SHARE = 0.2                   # of a ramp, its jerk time (as the example's 0.03 s of 0.15 s)


@dataclass(frozen=True)
class Variant:
    """One student's brief.

    Parameters
    ----------
    student : str
        The student's name or id, as in the roster.
    table_inertia : float
        J_L at the gearbox output [kg·cm²].
    stations : int
        The table's stations; an index turns 360° / stations [1].
    move_time : float
        The time of one index [s].
    dwell : float
        The time the station works while the table stands [s].
    """

    student: str
    table_inertia: float
    stations: int
    move_time: float
    dwell: float

    @property
    def index_angle(self) -> float:
        """The angle of one index [deg]."""
        return 360.0 / self.stations

    @property
    def ramp_time(self) -> float:
        """Each speed ramp's time [s], rounded to 0.01 s."""
        return round(RAMP_SHARE * self.move_time, 2)

    @property
    def jerk_time(self) -> float:
        """Each ramp's jerk time [s], rounded to 0.01 s."""
        return max(0.01, round(JERK_SHARE * self.ramp_time, 2))


def _drawn(rng: np.random.Generator, lowest: float, highest: float, step: float) -> float:
    count = int(round((highest - lowest) / step)) + 1
    return round(lowest + step * int(rng.integers(count)), 6)


def variant(student: str, seed: int) -> Variant:
    """The brief of one student, drawn from the ranges above with the course's seed.

    Parameters
    ----------
    student : str
        The student's name or id (not empty).
    seed : int
        The course's seed: a new one gives every student a new brief.

    Returns
    -------
    Variant
        The same brief for the same student and seed, on any machine.

    Examples
    --------
    >>> variant("student-01", 2026) == variant("student-01", 2026)
    True
    """
    if not str(student).strip():
        raise CalcError(f"course roster: expected a student's name or id, found an empty one (seed {seed})")
    digest = hashlib.sha256(f"{seed}:{student}".encode()).digest()
    rng = np.random.default_rng(int.from_bytes(digest[:8], "big"))
    return Variant(
        student=str(student),
        table_inertia=_drawn(rng, *TABLE_INERTIA),
        stations=int(rng.choice(STATIONS)),
        move_time=_drawn(rng, *MOVE_TIME),
        dwell=_drawn(rng, *DWELL),
    )


def briefs(students: list[str], seed: int) -> list[Variant]:
    """The briefs of a roster, each student's own.

    Parameters
    ----------
    students : list of str
        The roster.
    seed : int
        The course's seed.

    Returns
    -------
    list of Variant
        One per student, in the roster's order; two students never share a brief.
    """
    drawn = [variant(s, seed) for s in students]
    seen = {}
    for v in drawn:
        brief = (v.table_inertia, v.stations, v.move_time, v.dwell)
        if brief in seen:
            raise CalcError(f"course roster: {seen[brief]} and {v.student} draw the same brief with seed {seed}; "
                            f"expected each student's own: choose another seed")
        seen[brief] = v.student
    return drawn


def case_text(v: Variant) -> str:
    """The case file of a variant: the example's axis with the student's table, index and times
    (the motor chosen from the catalog, an NPT gearbox of ratio 10, no coupling or accuracy chain).

    Parameters
    ----------
    v : Variant
        The student's brief.

    Returns
    -------
    str
        The TOML text, read by :func:`calc.sections.case.read_case` with a path in ``cases/``.
    """
    return f"""# The checkpoint's brief of {v.student}: the indexing table of cases/indexing-table.toml with the
# student's own table, index, move and dwell (calc.course.variants). The lecturer's grading file.
title = "Indexing table of {v.student}"

[motor]
catalog = "motors"
shaft = "19 mm k6"

[load]
axial_force = "150 N"
axial_force_radius = "0 mm"
radial_force = "300 N"
lever_arm = "60 mm"

[gearbox]
ratio = 10
catalog = "gearboxes"
family = "NPT"

[mechanism]
type = "rotary"
inertia = "{v.table_inertia:g} kg*cm**2"
friction_torque = "3 N*m"

[[move]]
distance = "{v.index_angle:g} deg"
time = "{v.move_time:g} s"
accel_time = "{v.ramp_time:g} s"
jerk_time = "{v.jerk_time:g} s"
[[move]]
dwell = "{v.dwell:g} s"
"""


def brief_markdown(v: Variant) -> str:
    """A student's one-page brief, as Markdown: the machine and the motion, no result.

    Parameters
    ----------
    v : Variant
        The student's brief.

    Returns
    -------
    str
        The brief's Markdown.
    """
    return f"""# Your brief: the indexing table of {v.student}

Your axis is the course's indexing table (notebook 00) with a table, an index and a cycle of its own.
Write its case file from this page (notebook 01 shows how; `cases/indexing-table.toml` is the
format), evaluate it, and enter the checkpoint's numbers in `checkpoint.ipynb`.

| | |
|---|---|
| the table | {v.table_inertia:g} kg·cm² at the gearbox output, friction torque 3 N·m while it turns |
| the index | {v.stations} stations: {v.index_angle:g}° in {v.move_time:g} s, S-curve ramps of \
{v.ramp_time:g} s with {v.jerk_time:g} s of jerk |
| the dwell | {v.dwell:g} s while the station works |
| the loads on the output | axial 150 N on the axis, radial 300 N at 60 mm from the flange |
| the drive | a motor of the workbook's catalog (`catalog = "motors"`, shaft 19 mm k6), a gearbox of family NPT, \
ratio 10 |
"""
