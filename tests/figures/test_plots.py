"""Figures (load cycle, shock factor, utilization) and the candidate tables of a selection."""

import numpy as np
import pytest
from matplotlib.colors import to_rgb
from matplotlib.patches import StepPatch

from calc import CalcError, Q_
from calc.data.bands import load_factor_table
from calc.data.catalog import load_catalog
from calc.domain.gearbox import (SCHEMA, SHOCK_FACTORS, candidates_summary, candidates_table, rows_at_ratio,
                                 select_gearbox)
from calc.figures.plots import FAIL_COLOR, PASS_COLOR, load_cycle_figure, shock_factor_figure, utilization_figure
from calc.domain.profile import Profile, Z_h, duty

from ..conftest import GEARBOXES
from ..domain.test_profile import example_profile


@pytest.fixture(scope="module")
def selection():
    """The example case at ratio 10 (S5): twelve complete rows, ranked by hand in
    tests/domain/test_gearbox.py::test_example_s5_selection_by_hand; NPT035-10 is selected."""
    rows = rows_at_ratio(load_catalog(GEARBOXES, SCHEMA), Q_(10, ""))
    return select_gearbox(example_profile(), rows, Q_(12, "N*m"), Q_(4.2, "kg*cm**2"), Q_(1500, "kg*cm**2"))


def _texts(fig):
    out = [fig.get_suptitle()]
    for ax in fig.axes:
        out += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel(), *(t.get_text() for t in ax.texts)]
    for legend in fig.legends + [ax.get_legend() for ax in fig.axes if ax.get_legend()]:
        out += [t.get_text() for t in legend.get_texts()]
    return "\n".join(out)


def test_load_cycle_figure_draws_the_profile_as_given():
    p = example_profile()
    fig = load_cycle_figure(p)
    ax_n, ax_T = fig.axes
    steps = [[a for a in ax.patches if isinstance(a, StepPatch)] for ax in (ax_n, ax_T)]
    assert [len(s) for s in steps] == [1, 1]
    # Each segment at its value: mean speeds 150, 300, 150, 0 rpm; torques 60, 20, -45, 0 N·m;
    # segment edges at 0, 0.2, 0.8, 1.0 and 2.0 s.
    speed, torque = steps[0][0].get_data(), steps[1][0].get_data()
    np.testing.assert_allclose(speed.values, [150, 300, 150, 0])
    np.testing.assert_allclose(torque.values, [60, 20, -45, 0])
    np.testing.assert_allclose(speed.edges, [0, 0.2, 0.8, 1.0, 2.0])
    assert ax_n.get_shared_x_axes().joined(ax_n, ax_T)
    assert ax_n.get_ylabel() == "mean output speed $n_2$ [rpm]"
    assert ax_T.get_ylabel() == "output torque $T_2$ [N·m]"
    assert ax_T.get_xlabel() == "time $t$ [s]"
    text = _texts(fig)
    # ED = (0.2 + 0.6 + 0.2) / 2.0 = 50 % → S5 (E3); the legend names on-time and pause.
    assert "ED = 50 %" in text and "mode S5" in text
    assert "on-time (moving), 1 s" in text and "pause, 1 s" in text
    assert "mean" in ax_n.get_title()
    for name in ("accel", "const", "decel", "pause"):
        assert name in text


def test_load_cycle_figure_shades_on_time_and_pause():
    p = example_profile()
    fig = load_cycle_figure(p)
    for ax in fig.axes:
        spans = [a for a in ax.patches if not isinstance(a, StepPatch)]
        assert len(spans) == 4  # one span per segment: three moving, one pause
        colors = [a.get_facecolor() for a in spans]
        assert colors[0] == colors[1] == colors[2] != colors[3]


def test_load_cycle_figure_takes_a_given_duty_and_s1():
    # An S1 variant: pause 0.5 s → ED = 1 / 1.5 = 66.7 % ≥ 60 % → S1 (E3).
    p = Profile.from_segments(
        [
            ("const", Q_(1, "s"), Q_(-100, "rpm"), Q_(10, "N*m")),
            ("pause", Q_(0.5, "s"), None, None),
        ]
    )
    fig = load_cycle_figure(p, duty(p))
    assert "ED = 66.7 %" in fig.get_suptitle() and "mode S1" in fig.get_suptitle()
    low, high = fig.axes[0].get_ylim()
    assert low < -100 and high > 0  # a negative speed stays negative and zero stays in view


def test_shock_factor_figure_draws_the_table_with_e4_boundaries():
    fig = shock_factor_figure()
    (ax,) = fig.axes
    lines = {line.get_gid(): line for line in ax.lines}
    assert "case" not in lines
    bounds, factors = SHOCK_FACTORS.bounds, SHOCK_FACTORS.factors
    # E4: each boundary is included (filled) in the band it starts and excluded (open) from the one it ends.
    np.testing.assert_array_equal(lines["included"].get_xdata(), bounds)
    np.testing.assert_array_equal(lines["included"].get_ydata(), factors)
    np.testing.assert_array_equal(lines["excluded"].get_xdata(), bounds[1:])
    np.testing.assert_array_equal(lines["excluded"].get_ydata(), factors[:-1])
    assert lines["excluded"].get_markerfacecolor() == "white"
    assert r"$Z_{\mathrm{h}}$" in ax.get_xlabel() and "[1/h]" in ax.get_xlabel()
    assert r"$f_{\mathrm{s}}$" in ax.get_ylabel()
    assert "E4" in ax.get_title()


def test_shock_factor_figure_follows_a_table_that_takes_the_lower_factor(tmp_path):
    # A table whose boundaries take the lower factor (at_boundary = lower): each boundary is filled on
    # the band it ends and open on the one it starts; 1000 /h reads 1.0 there, not E4's 1.1.
    (tmp_path / "shock-lower.csv").write_text(
        "from [1/h],to [1/h],factor [1],at_boundary,source\n"
        "0,1000,1.0,lower,hand-written\n1000,2000,1.1,lower,hand-written\n2000,3000,1.6,lower,hand-written\n")
    table = load_factor_table(tmp_path / "shock-lower.csv", "Z_h", "per_hour")
    fig = shock_factor_figure(Q_(1000, "1/hour"), table)
    lines = {line.get_gid(): line for line in fig.axes[0].lines}
    np.testing.assert_array_equal(lines["included"].get_xdata(), [0, 1000, 2000])
    np.testing.assert_array_equal(lines["included"].get_ydata(), [1.0, 1.0, 1.1])
    np.testing.assert_array_equal(lines["excluded"].get_xdata(), [1000, 2000])
    np.testing.assert_array_equal(lines["excluded"].get_ydata(), [1.1, 1.6])
    assert lines["case"].get_ydata()[0] == 1.0
    texts = _texts(fig)
    assert "boundary excluded (the lower factor applies, as the table reads)" in texts and "E4)" not in texts


@pytest.mark.parametrize("t_cycle, z, fs", [(2.0, 1800, 1.3), (2.4, 1500, 1.3), (7.2, 500, 1.0), (0.5, 7200, 2.0)])
def test_shock_factor_figure_marks_the_case(t_cycle, z, fs):
    # Z_h = 3600 s / t_cycle for one load cycle (E16); a point on a boundary (1500) takes the higher factor (E4).
    fig = shock_factor_figure(Z_h(z_c=Q_(1, ""), t_cycle=Q_(t_cycle, "s")))
    (ax,) = fig.axes
    (case,) = [line for line in ax.lines if line.get_gid() == "case"]
    assert case.get_xdata()[0] == pytest.approx(z)
    assert case.get_ydata()[0] == fs
    assert ax.get_xlim()[1] > z  # the point is inside the plot, also far to the right
    assert rf"this case: $Z_{{\mathrm{{h}}}}$ = {z} 1/h, $f_{{\mathrm{{s}}}}$ = {fs:g}" in _texts(fig)


def test_shock_factor_figure_marks_the_recorded_factor():
    # The caller's f_s (the duty result's) is the one marked; the table is not read again for it.
    fig = shock_factor_figure(Q_(1800, "1/hour"), f_s=1.45)
    (case,) = [line for line in fig.axes[0].lines if line.get_gid() == "case"]
    assert (case.get_xdata()[0], case.get_ydata()[0]) == (1800.0, 1.45)


def test_shock_factor_figure_takes_one_point():
    with pytest.raises(CalcError, match="cycles_per_hour: expected one number"):
        shock_factor_figure(Q_(np.array([1000.0, 2000.0]), "1/hour"))
    with pytest.raises(CalcError, match="cycles_per_hour"):
        shock_factor_figure(Q_(2, "s"))


def test_utilization_figure_bars_the_governing_checks(selection):
    fig = utilization_figure(selection)
    (ax,) = fig.axes
    bars = ax.patches
    # Best first (T_2B and n_1max of each row in catalogs/gearboxes.csv): T_2max = 151.32 N·m (η 0.97),
    # 148.2 N·m for TP300 and TP500 (η 0.95); n_2max · i = 3000 rpm. Each bar is the highest governing
    # utilization, cut at the axis end 2.
    t2b = np.array([220, 400, 400, 648, 2280, 4000, 126, 90, 42, 35, 35, 13])
    t2max = np.array([151.32] * 4 + [148.2] * 2 + [151.32] * 6)
    n1max = np.array([6000, 4000, 4000, 5000, 3000, 3000, 7500, 7000, 7500, 8000, 8000, 10000])
    t2not = np.array([480, 1000, 1000, 1250, 8750, 15000, 251, 190, 100, 80, 75, 26])  # T_2stop = 12 N·m · 10 = 120 N·m
    worst = np.maximum.reduce([t2max / t2b, 3000 / n1max, 120 / t2not])
    # the hub check governs too: its utilization (d_motor / d_hub,max) is below the others here but for NPT005-10
    heights = np.array([b.get_width() for b in bars])
    np.testing.assert_allclose(heights[:11], np.minimum(worst, 2.0)[:11])
    assert heights[11] == 2.0
    # The colour is the verdict: TP300-10 and TP500-10 sit at utilization 1.00 on the speed check, and pass.
    colours = [b.get_facecolor()[:3] for b in bars]
    assert colours == [to_rgb(PASS_COLOR)] * 6 + [to_rgb(FAIL_COLOR)] * 6
    texts = [t.get_text() for t in ax.texts]
    assert texts[0].startswith("0.69  T_2max <= T_2B") and texts[4].startswith("1.00  n_2max · i <= n_1max")
    assert texts[11].startswith("11.64  T_2max <= T_2B")
    labels = [t.get_text() for t in ax.get_yticklabels()]
    assert labels[:2] == ["NPT035-10  PASS (selected)", "NPS045-10  PASS"] and labels[6] == "TP010-10  FAIL"
    assert ax.get_ylim()[0] > ax.get_ylim()[1]  # the best at the top
    limit = [line for line in ax.lines if line.get_linestyle() == "--"]
    assert limit and limit[0].get_xdata()[0] == 1.0
    assert "S5" in ax.get_title() and "[–]" in ax.get_xlabel()


def test_utilization_figure_limits_the_candidates(selection):
    fig = utilization_figure(selection, limit=2)
    (ax,) = fig.axes
    assert len(ax.get_yticks()) == 2
    assert "best 2 of 12" in ax.get_title()


def test_utilization_figure_marks_a_missing_rating():
    # A catalog row without n_1N: the S1 speed check has no rated value → no bar, "no rating".
    from calc.data.catalog import Catalog

    rows = rows_at_ratio(load_catalog(GEARBOXES, SCHEMA), Q_(10, ""))
    values = dict(rows.values)
    n_1N = rows["n_1N"].m_as("rpm").copy()
    n_1N[rows.parts == "NPT035-10"] = np.nan
    values["n_1N"] = Q_(n_1N, "rpm")
    rows = Catalog(rows.name, rows.path, rows.sha256, rows.schema, rows.parts, values, rows.text, rows.lines)
    p = Profile.from_segments([("const", Q_(1, "s"), Q_(100, "rpm"), Q_(10, "N*m"))])  # ED 100 % → S1
    sel = select_gearbox(p, rows)
    fig = utilization_figure(sel)
    texts = [t.get_text() for t in fig.axes[0].texts]
    assert any("no rating: n_2m · i <= n_1N" in t for t in texts)
    table = candidates_table(sel)
    missing = table[(table.part == "NPT035-10") & (table.check == "n_2m · i <= n_1N")]
    assert np.isnan(missing.utilization.iloc[0]) and missing.verdict.iloc[0] == "FAIL"


def test_candidates_table_rows_and_values(selection):
    t = candidates_table(selection)
    assert list(t.columns) == ["rank", "part", "check", "governs", "required", "rated", "unit", "utilization",
                               "verdict"]
    assert len(t) == 12 * 5  # twelve complete rows at ratio 10, five checks each (the emergency stop the fifth)
    assert t.part.tolist()[::5][:3] == ["NPT035-10", "NPS045-10", "NPT045-10"]
    assert t["rank"].tolist()[::5] == list(range(1, 13))
    row = t[(t.part == "TP010-10") & (t.check == "T_2max <= T_2B")].iloc[0]
    # Hand calculation: T_2max = 12 · 10 · 1.3 · 0.97 = 151.32 N·m against T_2B = 126 N·m → 1.201, FAIL.
    assert row.required == pytest.approx(151.32)
    assert row.rated == 126
    assert row.unit == "N·m"
    assert row.utilization == pytest.approx(151.32 / 126)
    assert row.verdict == "FAIL" and bool(row.governs)
    row = t[(t.part == "NPT045-10") & (t.check == "n_2m · i <= n_1N")].iloc[0]
    # E1, for information in S5: n_2m · i = 240 · 10 = 2400 rpm against n_1N = 2300 rpm (NPT045 MF page).
    assert (row.required, row.rated, row.unit, row.verdict, bool(row.governs)) == (2400, 2300, "rpm", "FAIL", False)


def test_candidates_summary_gives_verdict_and_reasons(selection):
    s = candidates_summary(selection)
    assert s.part.tolist()[:3] == ["NPT035-10", "NPS045-10", "NPT045-10"] and s.part.iloc[6] == "TP010-10"
    assert s.verdict.tolist() == ["PASS"] * 6 + ["FAIL"] * 6
    # The worst governing utilization is T_2B's but for NPS045/NPT045 (3000 / 4000 rpm > 151.32 / 400).
    np.testing.assert_allclose(s["worst utilization"][:3], [151.32 / 220, 0.75, 0.75])
    np.testing.assert_allclose(s["T_2max [N·m]"][:4], 151.32)
    # E6: λ = (J_1 + J_L / i²) / J_motor = (0.93 + 1500 / 100) / 4.2 = 3.793, J_1 of the 19 mm hub.
    assert s["inertia ratio"].iloc[0] == pytest.approx(15.93 / 4.2)
    assert s["J_1 [kg·cm²]"].iloc[0] == 0.93 and s["hub [mm]"].iloc[0] == 19
    assert not s.illustrative.any()
    assert s.reasons.iloc[0] == ""
    assert s.reasons.iloc[6] == "T_2max <= T_2B: required 151.3 N·m > rated 126 N·m, 20.1 % over"
    assert s.family.tolist()[:4] == ["NPT", "NPS", "NPT",
                                     "TP+"] and s["best of family"].tolist()[:4] == [True, True, False, True]
    assert s.doubtful.iloc[2].startswith("n_1max/eta") and s.catalog.iloc[0] == "catalogs/gearboxes.csv"
