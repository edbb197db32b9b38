"""The graded checkpoint: the numbers a student finds for their own brief
(:mod:`calc.course.variants`), the package's values for the same brief, and a submission graded
item by item within each item's tolerance. The autograder's test files (``course/grading/``) call
:func:`graded`; the lecturer's key is :func:`expected`.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from pathlib import Path

from ..core.errors import CalcError
from .variants import Variant, case_text

#: Where a variant's case is read as if it lay: its catalogs are found by name from there.
CASES = Path(__file__).resolve().parents[2] / "cases"


@dataclass(frozen=True)
class Item:
    """One item of the checkpoint.

    Parameters
    ----------
    name : str
        The variable the student's notebook sets.
    question : str
        What the item asks, with its unit.
    tolerance : float
        The relative tolerance of a number [1]; 0 for a name, compared exactly (case ignored).
    notebook : str
        The notebook that teaches it.
    """

    name: str
    question: str
    tolerance: float
    notebook: str


ITEMS = (
    Item("n_2max", "the peak output speed of the index, in rpm", 0.01, "01"),
    Item("T_peak", "the largest output torque of the cycle's segments (inertia and friction), in N·m", 0.02, "01"),
    Item("ED", "the duty cycle ED, in %", 0.01, "02"),
    Item("mode", 'the operating mode, "S1" or "S5"', 0.0, "02"),
    Item("T_2m", "the cubic mean output torque T_2m, in N·m", 0.02, "06"),
    Item("motor", "the motor the catalog gives (its part name)", 0.0, "04"),
    Item("gearbox", "the gearbox the catalog gives (its part name)", 0.0, "07"),
)


def expected(v: Variant) -> dict:
    """The package's value of every item for a student's brief.

    Parameters
    ----------
    v : Variant
        The student's brief.

    Returns
    -------
    dict
        Item name -> value: a float in the item's unit (rpm, N·m, %) or a str.
    """
    return dict(_key(v))


# The autograder's seven test cases of one submission, and the lecturer's keys and a batch of submissions
# graded in one process, ask for the same student's key: the brief is evaluated once.
@functools.lru_cache(maxsize=1024)
def _key(v: Variant) -> tuple:
    from ..sections import evaluate
    from ..sections.case import read_case

    results = evaluate(read_case(CASES / f"checkpoint-{v.student}.toml", case_text(v))).to_json()
    motion, duty = results["motion"], results["duty"]
    return tuple({
        "n_2max": motion["peak_speed"]["value"],
        "T_peak": max(abs(s["torque"]["value"]) for s in motion["segments"]),
        "ED": duty["ED"]["value"],
        "mode": duty["mode"],
        "T_2m": results["continuous"]["T2m"]["value"],
        "motor": results["motor"].get("selected") or "none",
        "gearbox": results["gearbox"].get("selected") or "none",
    }.items())


@dataclass(frozen=True)
class Mark:
    """The grade of one item.

    Parameters
    ----------
    item : Item
        The item graded.
    passes : bool
        Whether the submitted value is the package's within the tolerance.
    message : str
        What the student reads: the item and why it failed (never the package's value).
    """

    item: Item
    passes: bool
    message: str


def graded(submitted: dict, key: dict) -> list[Mark]:
    """Each item of a submission against the package's values.

    Parameters
    ----------
    submitted : dict
        Item name -> the student's value (a number in the item's unit, or a name); a missing or
        empty item fails.
    key : dict
        Item name -> the package's value (:func:`expected`).

    Returns
    -------
    list of Mark
        One mark per item, in the order of :data:`ITEMS`.
    """
    marks = []
    for item in ITEMS:
        value, right = submitted.get(item.name), key[item.name]
        if value is None or value == "" or value is ...:
            marks.append(Mark(item, False, f"{item.name}: not answered ({item.question})"))
        elif item.tolerance == 0:
            ok = str(value).strip().casefold() == str(right).casefold()
            marks.append(Mark(item, ok, f"{item.name}: {'right' if ok else 'not the one the brief gives'}"))
        else:
            try:
                number = float(value)
            except (TypeError, ValueError):
                marks.append(Mark(item, False, f"{item.name}: expected a number ({item.question}), found {value!r}"))
                continue
            ok = math.isclose(number, right, rel_tol=item.tolerance)
            marks.append(Mark(item, ok, f"{item.name}: {'right' if ok else f'not within {item.tolerance:.0%}'}"))
    return marks


def submitted_from(env: dict) -> dict:
    """The items a student's notebook set, from its global variables.

    Parameters
    ----------
    env : dict
        The notebook's globals after it ran.

    Returns
    -------
    dict
        Item name -> value, for the items it set.
    """
    return {item.name: env[item.name] for item in ITEMS if item.name in env}


def student_of(env: dict) -> str:
    """The student a notebook was submitted by (its ``STUDENT`` variable).

    Parameters
    ----------
    env : dict
        The notebook's globals after it ran.

    Returns
    -------
    str
        The student's name or id as in the roster.
    """
    student = env.get("STUDENT")
    if not isinstance(student, str) or not student.strip():
        raise CalcError("checkpoint.ipynb, STUDENT: expected your name or id as in the roster, found none")
    return student.strip()
