"""The inertia of a load from its geometry (calc.domain.inertia, [[mechanism.body]]): hand calculations,
the laws between the shapes, and bad input."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import Q_
from calc.domain.inertia import J_cylinder, J_hollow, J_steiner, Body

from ..conftest import DERIVED_EXAMPLE

BODIES = """
[[mechanism.body]]
shape = "cylinder"
diameter = "400 mm"
length = "15 mm"
density = "2700 kg/m**3"

[[mechanism.body]]
shape = "plate"
width = "100 mm"
depth = "60 mm"
length = "40 mm"
mass = "2.5 kg"
offset = "150 mm"
"""


def test_a_table_of_a_disc_and_a_fixture_by_hand():
    # An aluminium disc of 400 mm by 15 mm: m = 2700 · π · 0.4² · 0.015 / 4 = 5.0894 kg,
    # J = m · D² / 8 = 5.0894 · 0.16 / 8 = 0.101788 kg·m² = 1017.88 kg·cm².
    disc = Body("cylinder", {"D": Q_(400, "mm"), "L": Q_(15, "mm")}, density=Q_(2700, "kg/m**3"))
    assert disc.steps()[0].result.m_as("kg") == pytest.approx(2700 * math.pi * 0.4**2 * 0.015 / 4, rel=1e-12)
    assert disc.inertia.m_as("kg*cm**2") == pytest.approx(1017.876, rel=1e-6)
    # A 2.5 kg fixture of 100 × 60 mm at 150 mm: 2.5 · (0.1² + 0.06²) / 12 + 2.5 · 0.15² = 0.0028333 + 0.05625
    # = 0.0590833 kg·m² = 590.833 kg·cm².
    fixture = Body("plate", {"a": Q_(100, "mm"), "b": Q_(60, "mm"), "L": Q_(40, "mm")}, mass=Q_(2.5, "kg"),
                   offset=Q_(150, "mm"))
    assert fixture.inertia.m_as("kg*cm**2") == pytest.approx(590.8333, rel=1e-6)


def test_the_bodies_give_the_tables_inertia(write_case, tmp_path):
    import re

    from calc.sections.case import read_case

    text = DERIVED_EXAMPLE.read_text(encoding="utf-8")
    start = re.search(r"^\[mechanism\]", text, re.M).start()
    end = re.search(r"^\[\[move\]\]", text, re.M).start()
    mechanism = '[mechanism]\ntype = "rotary"\ninertia = "100 kg*cm**2"\nfriction_torque = "3 N*m"\n' + BODIES
    text = text[:start] + mechanism + "\n" + text[end:]
    case = read_case(write_case(text.replace('"../data/', f'"{DERIVED_EXAMPLE.parent.parent / "data"}/'), "b.toml"))
    # 100 kg·cm² given besides the bodies: 100 + 1017.876 + 590.833 = 1708.709 kg·cm².
    assert case.motion.mechanism.inertia.m_as("kg*cm**2") == pytest.approx(1708.709, rel=1e-6)
    assert case.load_inertia.m_as("kg*cm**2") == pytest.approx(1708.709, rel=1e-6)


@settings(max_examples=50, deadline=None)
@given(st.floats(0.1, 10), st.floats(10, 1000), st.floats(0.0, 0.999), st.floats(0, 500))
def test_the_shapes_laws(m, D, ratio, e):
    mass, outer = Q_(m, "kg"), Q_(D, "mm")
    # A hollow cylinder of the same mass lies between the solid one and a thin ring (m·D²/4).
    hollow = J_hollow(m=mass, D=outer, d_i=outer * ratio).m_as("kg*m**2")
    solid = J_cylinder(m=mass, D=outer).m_as("kg*m**2")
    assert solid * (1 - 1e-12) <= hollow <= m * (D / 1000) ** 2 / 4 * (1 + 1e-12)
    # Off the axis, a body turns with more inertia, never less.
    assert J_steiner(J_own=Q_(solid, "kg*m**2"), m=mass, e=Q_(e, "mm")).m_as("kg*m**2") >= solid


@pytest.mark.parametrize("body, message", [
    ('shape = "sphere"\ndiameter = "10 mm"\nmass = "1 kg"',
     "mechanism.body[1].shape: expected one of cylinder, hollow-cylinder, plate, found 'sphere'"),
    ('shape = "cylinder"\ndiameter = "100 mm"\nlength = "10 mm"',
     "mechanism.body[1].mass: give the body's mass or its material's density, one of them, found neither"),
    ('shape = "cylinder"\ndiameter = "100 mm"\nlength = "10 mm"\nmass = "1 kg"\ndensity = "7850 kg/m**3"',
     "mechanism.body[1].mass: give the body's mass or its material's density, one of them, found both"),
    ('shape = "cylinder"\ndiameter = "100 mm"\nlength = "10 mm"\nwidth = "5 mm"\nmass = "1 kg"',
     "mechanism.body[1].width: a cylinder takes diameter, length, not width"),
    ('shape = "hollow-cylinder"\ndiameter = "100 mm"\ninner_diameter = "120 mm"\nlength = "10 mm"\nmass = "1 kg"',
     "mechanism.body[1].inner_diameter: expected an inner diameter below the outer '100 mm', found '120 mm'"),
    ('shape = "plate"\nwidth = "100 mm"\ndepth = "50 mm"\nlength = "10 mm"\ndensity = "7850 kg"',
     "mechanism.body[1].density: expected a density"),
])
def test_bad_bodies_get_one_sentence(write_case, capsys, body, message):
    from calc.__main__ import main

    text = ('title = "t"\n[motor]\npeak_torque = "12 N*m"\n[mechanism]\ntype = "rotary"\n[[mechanism.body]]\n' + body
            + '\n[[move]]\ndistance = "90 deg"\ntime = "0.5 s"\naccel_time = "0.15 s"\n[[move]]\ndwell = "1 s"\n')
    assert main(["evaluate", str(write_case(text, "bad.toml"))]) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1
