"""A notebook's self-check, read from its Markdown and scored.

The self-check is the notebook's cell headed ``## Self-check``: numbered items in bold
(``**1. ...**``), each with its options as ``<details>`` whose summary starts with the option's
letter (``a) ...``) and whose feedback starts with ``**Right.**`` or ``**Misconception: ...**``
(the wrong idea the option stands for). A numerical item says ``(numerical, within 2 %)`` and has
no options: its value comes from the package, in the cell that scores the self-check. The key is
read from the Markdown itself, so the options a student reads and the key cannot drift apart.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from pathlib import Path

from ..core.errors import CalcError

ITEM = re.compile(r"^\*\*(\d+)\.\s+(.*?)\*\*\s*$", re.MULTILINE)
OPTION = re.compile(r"<details><summary>([a-z])\)\s*(.*?)</summary>\s*(.*?)</details>", re.DOTALL)
NUMERICAL = re.compile(r"\(numerical, within (\d+(?:\.\d+)?)\s*%\)")
RIGHT = "**Right.**"
MISCONCEPTION = re.compile(r"^\*\*Misconception: ([^*]+?)\.\*\*")
#: The brief the numerical items change (notebook 00).
BRIEF = Path(__file__).resolve().parents[2] / "cases" / "indexing-table.toml"


@dataclass(frozen=True)
class Option:
    """One option of an item.

    Parameters
    ----------
    letter : str
        Its letter, ``a`` to ``d``.
    text : str
        What it says.
    feedback : str
        What opening it shows: why it is right, or the misconception it stands for.
    """

    letter: str
    text: str
    feedback: str

    @property
    def right(self) -> bool:
        """Whether it is the item's answer."""
        return self.feedback.startswith(RIGHT)

    @property
    def misconception(self) -> str | None:
        """The misconception a wrong option stands for, as its feedback names it."""
        found = MISCONCEPTION.match(self.feedback)
        return found.group(1) if found else None


@dataclass(frozen=True)
class Item:
    """One item of a self-check.

    Parameters
    ----------
    number : int
        Its number in the self-check.
    question : str
        What it asks.
    options : tuple of Option
        Its options (none for a numerical item).
    tolerance : float or None
        A numerical item's relative tolerance [1]; None for a choice.
    """

    number: int
    question: str
    options: tuple
    tolerance: float | None

    @property
    def key(self) -> str | None:
        """The right option's letter (None for a numerical item)."""
        right = [o.letter for o in self.options if o.right]
        return right[0] if len(right) == 1 else None


def self_check_of(notebook: dict) -> str:
    """The Markdown of a notebook's self-check cell.

    Parameters
    ----------
    notebook : dict
        The notebook as read from its JSON.

    Returns
    -------
    str
        The cell's text ('' where the notebook has none).
    """
    for cell in notebook["cells"]:
        text = "".join(cell["source"]) if isinstance(cell["source"], list) else cell["source"]
        if cell["cell_type"] == "markdown" and text.startswith("## Self-check"):
            return text
    return ""


def items(markdown: str) -> list[Item]:
    """The items of a self-check.

    Parameters
    ----------
    markdown : str
        The self-check cell's text.

    Returns
    -------
    list of Item
        In their order.
    """
    heads = list(ITEM.finditer(markdown))
    found = []
    for k, head in enumerate(heads):
        body = markdown[head.end(): heads[k + 1].start() if k + 1 < len(heads) else len(markdown)]
        options = tuple(Option(m.group(1), m.group(2).strip(), m.group(3).strip()) for m in OPTION.finditer(body))
        numerical = NUMERICAL.search(head.group(2))
        found.append(Item(int(head.group(1)), head.group(2), options,
                          float(numerical.group(1)) / 100 if numerical else None))
    return found


def score(notebook: str, answers: dict, numerical: dict | None = None) -> str:
    """A student's score on a notebook's self-check, item by item (the key is never shown).

    Parameters
    ----------
    notebook : str or pathlib.Path
        The notebook's file (beside the running notebook: its name).
    answers : dict
        Item number -> the student's letter, or their number for a numerical item; an empty
        answer ('' or None) is not yet answered.
    numerical : dict, optional
        Item number -> the package's value of a numerical item, in the unit the item asks.

    Returns
    -------
    str
        The score and a line per item.
    """
    path = Path(notebook)
    try:
        checked = items(self_check_of(json.loads(path.read_text(encoding="utf-8"))))
    except (OSError, ValueError) as exc:
        raise CalcError(f"score: expected a notebook with a self-check at {path}, found none ({exc})")
    numerical = numerical or {}
    lines, right, answered = [], 0, 0
    for item in checked:
        given = answers.get(item.number)
        if given in (None, "", ...):
            lines.append(f"  {item.number}: not answered yet")
            continue
        answered += 1
        if item.tolerance is None:
            ok = str(given).strip().lower().rstrip(")") == item.key
        else:
            try:
                ok = math.isclose(float(given), float(numerical[item.number]), rel_tol=item.tolerance)
            except (TypeError, ValueError):
                ok = False
            except KeyError:
                raise CalcError(f"score: item {item.number} of {path.name} is numerical; expected its value in "
                                f"numerical, found none")
        right += ok
        lines.append(f"  {item.number}: {'right' if ok else 'not right: open the options again'}")
    share = right / len(checked) if checked else 0.0
    text = "\n".join([f"Self-check of {path.stem}: {right} of {len(checked)} right ({share:.0%}),"
                      f" {answered} answered", *lines])
    return text


def brief_value(key: str, **edits) -> float:
    """A value of the brief's evaluation with some of its inputs edited, for a numerical item.

    Parameters
    ----------
    key : str
        The value's place in the results' JSON, its keys joined by dots (``"duty.ED"``); a name
        applied to a list takes it from each entry, ``max_abs`` is the largest magnitude of a list.
    **edits
        The case file's keys edited, as key paths with ``__`` for the dots and the entry of a list
        of tables as ``move_2`` (``move_2__dwell="0.4 s"``, ``gearbox__ratio=8``), each value as the
        file writes it (:mod:`calc.review.edit`).

    Returns
    -------
    float
        The value, in the unit the results give it (``"value"`` of a quantity).
    """
    from ..review.edit import Edit, edited_case
    from ..sections import evaluate

    changes = [Edit(".".join(re.sub(r"^(\w+?)_(\d+)$", r"\1[\2]", part) for part in name.split("__")), value)
               for name, value in edits.items()]
    value = evaluate(edited_case(BRIEF, BRIEF.read_text(encoding="utf-8"), changes)).to_json()
    for part in key.split("."):
        if part == "max_abs":
            value = max(abs(v["value"] if isinstance(v, dict) else v) for v in value)
        elif isinstance(value, list):
            value = [v[part] for v in value]
        else:
            value = value[part]
    return float(value["value"] if isinstance(value, dict) else value)
