"""The case layer: a design case's sections read, evaluated and written the same way.

Every section is a module of this package holding one :class:`calc.sections.protocol.Section`
(``SECTION``) and its result record (:class:`calc.sections.protocol.Result`), with its place in
the outputs (``ORDER``). The sections are found here (:mod:`calc.sections.evaluation`), so a new
section is its module alone: :data:`SECTIONS`, :data:`DECLARED`, :data:`TOP_KEYS` and
:data:`OWN_TABLES` follow from them. :func:`evaluate` evaluates what the case gives, each section
after those it requires, and :class:`Results` holds the one verdict of the case
(``docs/case-format.md``, "One verdict"), which the JSON, the text summary, the report and the
design review all print.
"""

from __future__ import annotations

from .case import Case, declared_tables, read_case, top_keys  # noqa: F401 (Case, read_case: the package's readers)
from .common import SHOWN_CANDIDATES, Verdict  # noqa: F401 (SHOWN_CANDIDATES: the command line)
from .evaluation import NOTHING_CHECKED, Results, evaluate, places, sections  # noqa: F401 (the package's evaluation)

#: Every section, in the order of the results.
SECTIONS = sections()
#: Every table a case file may have, as its section declares it.
DECLARED = declared_tables()
#: The keys a case file may have at its top level.
TOP_KEYS = top_keys()
#: The tables a case keeps as written (``case.sections``): those of the sections that read a
#: table of their own (:attr:`calc.sections.protocol.Section.keeps_table`).
OWN_TABLES = tuple(s.NAME for s in SECTIONS if s.keeps_table)


def declared(path: str):
    """The declaration of a key path of a case file.

    Parameters
    ----------
    path : str
        The key path (``motor.inertia``, ``profile[2].torque``,
        ``accuracy.component[1].stiffness_curve.K1``); an index in brackets is ignored.

    Returns
    -------
    calc.sections.case.Key or calc.sections.case.Declared
        The key's declaration; a table's own path gives its :class:`calc.sections.case.Declared`.
    """
    names = [part.split("[")[0] for part in path.split(".")]
    out = next(t for t in DECLARED if t.name == names[0])
    for name in names[1:]:
        out = next(k for k in out.keys if k.name == name)
    return out
