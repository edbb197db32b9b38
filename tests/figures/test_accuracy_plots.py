"""Figures of accuracy: what each one marks, and that importing them stays light."""

import subprocess
import sys

import numpy as np
import pytest

from calc import Q_
from calc.domain.accuracy import analyze_positions
from calc.core.checks import BOUNDARY_RTOL
from calc.figures.accuracy_plots import (
    TARGETS,
    accuracy_targets_figure,
    hysteresis_figure,
    positioning_scatter_figure,
    stiffness_chain_figure,
    target_points,
    transmission_error_figure,
)
from calc.domain.hysteresis import analyze_loop, read_loop
from calc.domain.stiffness import Chain, Component
from calc.domain.transmission import analyze_trace, read_trace
from calc.sections.accuracy import chain_values

from ..conftest import ROOT


def texts(fig):
    return [t.get_text() for ax in fig.axes for t in ax.texts] + [ax.get_title() for ax in fig.axes]


def test_hysteresis_figure_marks_slopes_backlash_lost_motion_and_bands():
    loop = read_loop(ROOT / "data" / "hysteresis-NPT035-10-generated.csv")
    a = analyze_loop(loop, Q_(110, "N*m"))
    fig = hysteresis_figure(loop, a)
    whole, detail = fig.axes
    shown = texts(fig)
    assert any(t.startswith(r"$C_{\mathrm{t}}$ = 21.99 N·m/arcmin") for t in shown)
    assert any(t.startswith(r"$C_{\mathrm{t}}$ = 21.96 N·m/arcmin") for t in shown)
    assert "backlash $j_{\\mathrm{t}}$\n= 7.99 arcmin" in shown
    assert "lost motion\n(±3 % $T_{\\mathrm{N}}$)\n= 8.75 arcmin" in shown
    # Shaded: the ±3 % band on both axes, the two 50 % to 100 % bands on the whole loop.
    spans = [p.get_x() for p in whole.patches]
    assert sorted(np.round(spans, 2)) == [-110.0, -3.3, 55.0]
    assert detail.get_xlim() == (-8.25, 8.25)


def test_stiffness_chain_figure_shows_each_share():
    chain = Chain((
        Component("EKM-15", "input", Q_(0.24, "N*m/arcmin"), Q_(0, "arcmin")),
        Component("EPL-W-064 10:1", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin")),
    ), ratio=Q_(10, ""))
    fig = stiffness_chain_figure(chain_values(chain, Q_(20, "N*m")))
    # Shares 1/24 : 1/1.3 -> 5.14 % and 94.9 %; C_total 1.233 N·m/arcmin; twists 20 / 24 and 20 / 1.3 arcmin.
    assert [round(b.get_width(), 2) for b in fig.axes[0].patches] == [5.14, 94.86]
    assert "1.233 N·m/arcmin" in fig.axes[0].get_title()
    assert texts(fig)[:2] == ["5.14 %: 0.833 arcmin, C = 24 N·m/arcmin", "94.9 %: 15.4 arcmin, C = 1.3 N·m/arcmin"]


def test_stiffness_chain_figure_bounds_the_chain_of_an_unknown_member():
    # A member of unknown stiffness is reckoned rigid: no bar of its own, and C_total an upper bound.
    chain = Chain((
        Component("NPT035-10", "output", Q_(np.inf, "N*m/arcmin"), Q_(3, "arcmin")),
        Component("EPL-W-064 10:1", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin")),
    ))
    fig = stiffness_chain_figure(chain_values(chain, Q_(20, "N*m")))
    assert [b.get_width() for b in fig.axes[0].patches] == pytest.approx([0.0, 100.0])
    assert texts(fig)[0] == "C unknown: reckoned rigid, so the twist is more"
    assert "≤ 1.3 N·m/arcmin, twist 15.4 arcmin" in fig.axes[0].get_title()


def test_transmission_error_figure_marks_the_range():
    a = analyze_trace(read_trace(ROOT / "data" / "transmission-NPT035-10-generated.csv"), Q_(10, ""))
    fig = transmission_error_figure(a)
    assert "$\\varphi_{\\mathrm{TA}}$ = 62.9 arcsec" in texts(fig)
    assert len(fig.axes[0].lines) == 2 + 2  # both directions, and the two range lines


def test_target_pictures_are_seeded_and_say_what_they_show():
    a, b = accuracy_targets_figure(seed=3), accuracy_targets_figure(seed=3)
    pts = [ax.lines[1].get_xydata() for ax in a.axes]
    assert all(np.array_equal(p, ax.lines[1].get_xydata()) for p, ax in zip(pts, b.axes))
    # Spread and offset as the titles say: poor/poor wide and off, poor/good tight and off, good/good tight and on.
    spread = [np.std(p, axis=0).mean() for p in pts]
    offset = [np.hypot(*p.mean(axis=0)) for p in pts]
    assert spread[0] > 2 * max(spread[1:]) and offset[1] > 1 > offset[2]
    assert [t for t, _, _ in TARGETS] == [ax.get_title() for ax in a.axes]
    assert target_points((0, 0), 1.0, count=5, seed=1).shape == (5, 2)


def test_positioning_scatter_figure():
    target = Q_(np.repeat([0.0, 90.0], 3), "deg")
    s = analyze_positions(target, target + Q_([0.6, 1.2, 0.9, -0.3, 0.3, 1.5], "arcmin"))
    fig = positioning_scatter_figure(s)
    assert "repeatability 1.8 arcmin" in texts(fig)
    assert [t.get_text() for t in fig.axes[0].get_xticklabels()] == ["0°", "90°"]


def test_importing_the_accuracy_modules_stays_light():
    code = (
        "import sys, calc.domain.accuracy, calc.figures.accuracy_plots, calc.domain.hysteresis, "
        "calc.domain.transmission, calc.domain.stiffness; "
        "print(sorted(m for m in ('matplotlib', 'pandas', 'sympy') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_positioning_rule_figure_jumps_at_three_percent():
    from calc.figures.accuracy_plots import positioning_rule_figure

    chain = Chain((Component("gearbox", "output", Q_(22, "N*m/arcmin"), Q_(8, "arcmin"), Q_(60, "arcsec"),
                             Q_(110, "N*m")),))
    fig = positioning_rule_figure(chain, applied_torque=Q_(8, "N*m"))
    accuracy_line = fig.axes[0].lines[0]
    t, a = accuracy_line.get_xdata(), accuracy_line.get_ydata()
    # E13 by hand: up to 3.3 N·m (within BOUNDARY_RTOL above it counts as on it), 1 + 8 = 9 arcmin;
    # just above, 1 + 3.3 / 22 = 1.15 arcmin.
    on = t <= 3.3 * (1 + BOUNDARY_RTOL)
    assert a[on] == pytest.approx(9.0)
    assert a[~on][0] == pytest.approx(1.15, abs=1e-6)
    case_point = fig.axes[0].lines[2]
    assert case_point.get_ydata()[0] == pytest.approx(1 + 8 / 22)
