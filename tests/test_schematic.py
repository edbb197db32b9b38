"""The drive-train schematic each notebook opens with: the members in order, the ones a notebook
treats in colour, and an unknown member named in one sentence."""

import pytest
from matplotlib.colors import to_rgba

from calc import CalcError
from calc.schematic import FOCUS_COLOR, OTHER_COLOR, drive_train_figure


def test_the_members_in_order_with_the_focus_in_colour():
    fig = drive_train_figure(("coupling", "gearbox"))
    (ax,) = fig.axes
    names = [t.get_text() for t in ax.texts if t.get_fontweight() == "bold"]
    assert names == ["servo motor", "coupling", "gearbox", "load"]
    assert [p.get_facecolor() for p in ax.patches] == [to_rgba(c) for c in (OTHER_COLOR, FOCUS_COLOR, FOCUS_COLOR, OTHER_COLOR)]
    sides = [t.get_text() for t in ax.texts if t.get_text().startswith(("input side", "output side"))]
    assert sides == ["input side: index 1 ($n_1$, $T_1$)", "output side: index 2 ($n_2$, $T_2$)"]


def test_an_unknown_member_is_named():
    with pytest.raises(CalcError, match=r"^focus: expected members among motor, coupling, gearbox, load; found 'brake', 'belt'$"):
        drive_train_figure(("gearbox", "brake", "belt"))
