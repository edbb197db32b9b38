"""The case layer: a design case's sections read, evaluated and written the same way.

Every section is a module with the same shape (:mod:`calc.sections.common`): ``NAME``,
``applies(case)``, ``evaluate(case)`` returning a result with ``to_json``, ``summary_lines`` and
``verdict``. :data:`SECTIONS` lists them in the order the results show them; :func:`evaluate`
evaluates what the case gives, and :class:`Results` holds the one verdict of the case
(``spec/case-format.md``, "One verdict"), which the JSON, the text summary, the report and the
design review all print.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..case import Case
from ..catalog import display_path
from . import accuracy, coupling, drive, duty, gearbox, motion, motor
from .common import SHOWN_CANDIDATES, Verdict  # noqa: F401 (SHOWN_CANDIDATES: the command line)

#: The evaluated sections, in the order of the results.
SECTIONS = (duty, motion, gearbox, coupling, motor, accuracy)
#: Sections that read their own table when evaluated (the case keeps it raw until then).
FURTHER = (coupling.NAME, accuracy.NAME)
#: The keys a case file may have at its top level.
TOP_KEYS = ("title", "motor", "load", gearbox.NAME, duty.NAME, *motion.TABLES, *FURTHER)

NOTHING_CHECKED = "Nothing is checked: the case names no gearbox ratio or part, no coupling and no accuracy requirement."


@dataclass
class Results:
    """Every result the case's inputs allow, by section, and the verdict of the case."""

    case: Case
    sections: dict  # section name -> its result

    @property
    def verdict(self) -> Verdict:
        return Verdict.combine([r.verdict() for r in self.sections.values()], NOTHING_CHECKED)

    def __getitem__(self, name: str):
        return self.sections[name]

    def to_json(self, candidates: int | None = SHOWN_CANDIDATES) -> dict:
        """The results as the JSON contract writes them; ``candidates`` bounds each candidate list
        (all for None)."""
        out = {"title": self.case.title, "case": display_path(self.case.path), "verdict": self.verdict.to_json()}
        for name, result in self.sections.items():
            written = result.to_json(candidates)
            out.update(written if name == duty.NAME else {name: written})
        return out

    def summary(self, candidates: int | None = SHOWN_CANDIDATES) -> str:
        """The results as a short report for a terminal: the verdict first, then each section."""
        title = self.case.title
        v = self.verdict
        lines = [title, "=" * len(title), f"Verdict: {v.word}", *[f"  {r}" for r in v.reasons]]
        for result in self.sections.values():
            lines += ["", *result.summary_lines(candidates)]
        return "\n".join(lines)


def evaluate(case: Case) -> Results:
    """Evaluate every section the case gives; numpy's floating-point warnings are not printed
    (what overflows gives inf or NaN, which the results report: :func:`calc.sections.common.number`)."""
    with np.errstate(all="ignore"):
        return Results(case, {m.NAME: m.evaluate(case) for m in SECTIONS if m.applies(case)})

