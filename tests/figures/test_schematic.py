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


def test_the_planetary_gearbox_drawn_can_be_built():
    # Ring fixed, sun driving, carrier driven: i = 1 + z_ring / z_sun = 1 + 90 / 18 = 6. It can be
    # built: 18 + 2 · 36 = 90 (the planets fill the gap); (18 + 90) / 3 = 36, whole, so three planets
    # sit 120° apart; centre distance (18 + 36) / 2 = 27 modules, planets 27 · sqrt(3) = 46.77 apart,
    # their tips 36 + 2 = 38 modules across: they clear. Pitch radii at a ring of 0.9: sun 0.18,
    # planet 0.36, so the pins sit at 0.54.
    from matplotlib.patches import Circle

    from calc.figures.schematic import PLANETARY_TEETH, planetary_gearbox_figure, planetary_stage_ratio

    z = PLANETARY_TEETH
    assert planetary_stage_ratio() == 6
    assert z["sun"] + 2 * z["planet"] == z["ring"] and (z["sun"] + z["ring"]) % 3 == 0
    assert z["planet"] + 2 < (z["sun"] + z["planet"]) / 2 * np.sqrt(3) and z["sun"] >= 17
    (ax,) = planetary_gearbox_figure().axes
    texts = [t.get_text() for t in ax.texts]
    assert any(t.startswith("sun: on the input shaft (index 1") and "18 teeth" in t for t in texts)
    assert any(t.startswith("carrier (dashed): holds the planets, turns the output") and "index 2" in t for t in texts)
    pins = [p.center for p in ax.patches if isinstance(p, Circle) and p.radius == 0.035]
    assert len(pins) == 3 and all(abs(np.hypot(*c) - 0.54) < 1e-12 for c in pins)
    assert "$i$ = 1 + 90 / 18 = 6 times" in texts[-1]


def test_the_bellows_coupling_joins_the_two_shafts():
    from calc.figures.schematic import bellows_coupling_figure

    (ax,) = bellows_coupling_figure().axes
    texts = [t.get_text() for t in ax.texts]
    assert "hub 1: clamps the motor shaft $D_1$" in texts and "hub 2: clamps the gearbox shaft $D_2$" in texts
    assert any(t.startswith(r"metal bellows: stiff in torsion ($C_{\mathrm{T}}$)") for t in texts)
    assert len(ax.lines) == 2  # the bellows' two walls in the section
