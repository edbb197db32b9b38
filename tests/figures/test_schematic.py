"""The drive-train schematic each notebook opens with: the members in order, the ones a notebook
treats in colour, and an unknown member named in one sentence."""

import numpy as np
import pytest
from matplotlib.colors import to_rgba

from calc import CalcError
from calc.figures.schematic import FOCUS_COLOR, OTHER_COLOR, drive_train_figure


def test_the_members_in_order_with_the_focus_in_colour():
    fig = drive_train_figure(("coupling", "gearbox"))
    (ax,) = fig.axes
    names = [t.get_text() for t in ax.texts if t.get_fontweight() == "bold"]
    assert names == ["servo motor", "coupling", "gearbox", "load"]
    assert [p.get_facecolor() for p in ax.patches] == [to_rgba(c)
                                                       for c in (OTHER_COLOR, FOCUS_COLOR, FOCUS_COLOR, OTHER_COLOR)]
    sides = [t.get_text() for t in ax.texts if t.get_text().startswith(("input side", "output side"))]
    assert sides == ["input side: index 1 ($n_1$, $T_1$)", "output side: index 2 ($n_2$, $T_2$)"]


def test_an_unknown_member_is_named():
    with pytest.raises(CalcError,
                       match=r"^focus: expected members among motor, coupling, gearbox, load; found 'brake', 'belt'$"):
        drive_train_figure(("gearbox", "brake", "belt"))


def test_the_planetary_gearbox_is_drawn_to_a_ratio_of_ten():
    # Ring fixed, sun driving, carrier driven: i = 1 + r_ring / r_sun. The picture's pitch circles,
    # sun 0.1, planets 0.4, ring 0.1 + 2 · 0.4 = 0.9, give i = 1 + 9 = 10, the example's ratio.
    from matplotlib.patches import Circle

    from calc.figures.schematic import planetary_gearbox_figure

    (ax,) = planetary_gearbox_figure().axes
    texts = [t.get_text() for t in ax.texts]
    assert any(t.startswith("sun: on the input shaft (index 1") for t in texts)
    assert any(t.startswith("carrier (dashed): holds the planets, turns the output") and "index 2" in t for t in texts)
    pins = [p.center for p in ax.patches if isinstance(p, Circle) and p.radius == 0.035]
    assert len(pins) == 3 and all(abs(np.hypot(*c) - 0.5) < 1e-12 for c in pins)  # sun + planet = 0.1 + 0.4
    assert "here $i$ = 10" in texts[-1]


def test_the_bellows_coupling_joins_the_two_shafts():
    from calc.figures.schematic import bellows_coupling_figure

    (ax,) = bellows_coupling_figure().axes
    texts = [t.get_text() for t in ax.texts]
    assert "hub 1: clamps the motor shaft $D_1$" in texts and "hub 2: clamps the gearbox shaft $D_2$" in texts
    assert any(t.startswith(r"metal bellows: stiff in torsion ($C_{\mathrm{T}}$)") for t in texts)
    assert len(ax.lines) == 2  # the bellows' two walls in the section
