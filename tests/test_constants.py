"""Every constant of engineering meaning has one owner: a numeric literal written in two modules of
the domain or the case layer is a rule typed twice (the load-to-motor inertia limit 10 stood in
five places, the ratio tolerance 1e-6 in three, the low-torque share 0.03 in two). Its owner
names it, the others import it.

Read from the source (``ast``) of ``calc/domain/*.py`` and ``calc/sections/*.py``: every int and
float literal, with the module it stands in. Left out: literals in the text of an f-string (a
column width, the digits shown), a section's ``ORDER`` (its place in the report) and the entries
of a standard's table (data read as printed). A value may stand in several modules only where
:data:`OBVIOUS` or :data:`APART` says why.
"""

import ast
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MODULES = sorted([*(ROOT / "calc" / "domain").glob("*.py"), *(ROOT / "calc" / "sections").glob("*.py")])

#: Values that are no one's constant: the numbers of arithmetic, of units and of formulas.
OBVIOUS = {
    0: "zero: an empty sum, a sign, an index",
    1: "one: a unit factor, a ratio of 1, the next index",
    2: "two: a half, a square, a pair",
    3: "three: a cube (the cubic mean), √3 of a three-phase voltage, three of a kind, three significant figures",
    4: "four: a quarter (π·D²/4), the four phases of a cycle, four rounds, four significant figures",
    6: "six: 1/6 of a cubic term (jerk), √6 of a space-vector voltage, 6π of a model's ripple",
    0.5: "a half",
}

#: Values that stand in two modules as different quantities that happen to agree: each module owns
#: its own, and another module writing the value must say which it means.
APART = {
    0.02: ({"domain/dynamics", "domain/hysteresis", "domain/motion"},
           "the damping ratio of a drive train's first mode in its frequency response; a model loop's friction, "
           "2 % of T_N; the shortest run of a motion, 2 % of its samples"),
    0.1: ({"domain/motion", "domain/motor_ratings", "sections/dynamics"},
          "a speed ramp's share of a move; the share of the thermal time constant a cycle may take; where the "
          "frequency response's figure starts, as a share of the lowest anti-resonance"),
    0.25: ({"domain/hysteresis", "domain/transmission"},
           "the largest shape factor of a model loop; a harmonic of a generated trace"),
    10: ({"domain/gearbox", "domain/hysteresis", "domain/transmission"},
         "the load-to-motor inertia limit (E6); a tenth of a loop's samples; ten digits of a written trace"),
    20: ({"domain/hysteresis", "domain/profile", "domain/transmission", "sections/common"},
         "the fewest samples of a loop and of a trace; S5's on-time of 20 min (E3); the candidates an output lists"),
}

#: Module-level names holding a standard's table as printed (ISO 286-1 in calc/domain/fits.py; the AC
#: supply classes of drives in calc/domain/drive.py):
#: their entries are data, not the constants of a rule.
TABLES = {"VOLTAGE_CLASSES", "SIZE_BANDS_MM", "STANDARD_TOLERANCES_UM", "SHAFT_DEVIATIONS_UM", "GRADES", "_K_GRADES",
          "EXCEPTIONS_UM"}


def literals(source: str) -> list[tuple[float, int]]:
    """Each numeric literal of a module's source, with its line, but those left out."""
    tree = ast.parse(source)
    skipped = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.JoinedStr):
            skipped |= {id(n) for n in ast.walk(node)}
    for node in tree.body:
        targets = node.targets if isinstance(node, ast.Assign) else [getattr(node, "target", None)]
        if {t.id for t in targets if isinstance(t, ast.Name)} & ({"ORDER"} | TABLES):
            skipped |= {id(n) for n in ast.walk(node)}
    return [(node.value, node.lineno) for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and type(node.value) in (int, float) and id(node) not in skipped]


def repeated(sources: dict) -> list[str]:
    """The values written in more than one module (``sources``: module name -> source) that
    :data:`OBVIOUS` and :data:`APART` do not allow there, each with where it stands."""
    where = defaultdict(set)
    for module, source in sources.items():
        for value, line in literals(source):
            where[value].add((module, line))
    out = []
    for value, places in sorted(where.items(), key=lambda item: abs(item[0])):
        modules = {m for m, _ in places}
        if len(modules) > 1 and value not in OBVIOUS and not modules <= APART.get(value, (set(), ""))[0]:
            out.append(f"{value!r} in " + ", ".join(f"{m}:{line}" for m, line in sorted(places)))
    return out


def test_no_numeric_literal_stands_in_two_modules():
    found = repeated({f"{path.parent.name}/{path.stem}": path.read_text(encoding="utf-8") for path in MODULES})
    assert not found, "a constant written in more than one module; give it one owner, import it: " + "; ".join(found)


def test_a_limit_written_twice_is_found():
    # The inertia limit as it stood: 10.0 in calc/domain/ratios.py and in calc/domain/motor_ratings.py
    # (and 10 as a case key's default); a value APART allows in some modules is found in another.
    sources = {"ratios": "INERTIA_RATIO_LIMIT = 10.0\n", "motor_ratings": "INERTIA_RATIO_LIMIT = 10.0\n",
               "drive": "ORDER = 10\nDEFAULT = 10\nTEXT = f'{x:10}'\n"}
    assert repeated(sources) == ["10.0 in drive:2, motor_ratings:1, ratios:1"]
    assert repeated({"a": "SHARE = 0.03\n", "b": "LIMIT = 0.03 * t\n"}) == ["0.03 in a:1, b:1"]
    assert repeated({"a": "x = 2 * y\n", "b": "z = y / 2\n"}) == []
