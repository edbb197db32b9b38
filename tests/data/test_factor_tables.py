"""Factor tables as data (calc.data.bands.load_factor_table, factor_table): the makers' published
figures, the source's tables as they were, the case keys that choose a table, and one-line errors
naming the file, row and column."""

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.data.bands import FACTOR_DIR, BandTable, factor_table, load_factor_table, table_names
from calc.domain.coupling import TEMPERATURE_FACTORS, start_factor, temperature_factor
from calc.domain.gearbox import SHOCK_FACTORS, shock_factor

from ..conftest import HEAD_TOML, PROFILE_TOML, run

# The tables as the code held them before they became data (calc/domain/gearbox.py, calc/domain/coupling.py).
OLD_SHOCK = BandTable("Z_h", (0, 1000, 1500, 2000, 3000), (1.0, 1.1, 1.3, 1.6, 2.0), "1/h", "per_hour", "old")
OLD_TEMPERATURE = BandTable("T", (-math.inf, 50.0, 70.0, 90.0, 110.0), (1.0, 1.3, 1.6, 1.8, 2.0), "degC", "temperature",
                            "old", top=120.0)


# --- published figures -----------------------------------------------------------------------


@pytest.mark.parametrize("celsius, factor",
                         [(20, 1.0), (30, 1.0), (45, 1.5), (60, 1.5), (75, 2.0), (90, 2.0), (100, 2.5), (110, 2.5)])
def test_roba_es_temperature_factors(celsius, factor):
    # Mayr ROBA-ES, B.9.6.EN (11/03/2022) p. 26, safety factor for temperature S_δ: -30/+30 °C 1,
    # +60 °C 1.5, +90 °C 2, +110 °C 2.5; between two columns the higher one applies.
    table = factor_table("temperature", "roba-es")
    assert float(temperature_factor(Q_(celsius, "degC"), table)) == factor


@pytest.mark.parametrize("celsius, factor", [(60, 1.4), (80, 1.8), (70, 1.8), (40, 1.4)])
def test_comintec_temperature_factors(celsius, factor):
    # COMINTEC: 1.4 at 60 °C, 1.8 at 80 °C (the two figures quoted); below 60 °C the table holds 1.4.
    assert float(temperature_factor(Q_(celsius, "degC"), factor_table("temperature", "comintec"))) == factor


def test_comintec_table_ends_at_its_last_published_figure():
    with pytest.raises(CalcError, match=r"^temperature: expected T <= 80 °C \(COMINTEC"):
        temperature_factor(Q_(85, "degC"), factor_table("temperature", "comintec"))


@pytest.mark.parametrize("starts, factor",
                         [(0, 1.0), (100, 1.0), (101, 1.2), (200, 1.2), (201, 1.4), (400, 1.4), (800, 1.6), (801, 1.8),
                          (1000, 1.8)])
def test_roba_es_start_factors(starts, factor):
    # Mayr ROBA-ES, B.9.6.EN p. 26, start-up factor S_z: 0-100 starts/h 1, 101-200 1.2, 201-400 1.4,
    # 401-800 1.6, 801-1000 1.8.
    assert float(start_factor(Q_(starts, "1/hour"), factor_table("starts", "roba-es"))) == factor


def test_start_factors_end_at_1000_starts_per_hour():
    with pytest.raises(CalcError, match=r"^starts_per_hour: expected 0 <= Z_h <= 1000 1/h"):
        start_factor(Q_(1200, "1/hour"), factor_table("starts", "roba-es"))


def test_the_shipped_tables_by_role():
    assert table_names("temperature") == ["comintec", "roba-es", "source"]
    assert table_names("starts") == ["roba-es"]
    assert table_names("shock") == ["source"]
    assert factor_table("temperature", "roba-es").text(1) == "30 < T <= 60 °C"
    assert factor_table("temperature", "comintec").text(0) == "T <= 60 °C"


# --- the source's tables, now data, give today's results ---------------------------------------


@settings(max_examples=300, deadline=None)
@given(st.floats(0, 10_000))
def test_default_shock_table_is_the_old_one(zh):
    z = Q_(zh, "1/hour")
    assert shock_factor(z) == OLD_SHOCK.lookup(z) and SHOCK_FACTORS.band(z) == OLD_SHOCK.band(z)


@settings(max_examples=300, deadline=None)
@given(st.floats(-273.15, 120))
def test_default_temperature_table_is_the_old_one(celsius):
    t = Q_(celsius, "degC")
    assert temperature_factor(t) == OLD_TEMPERATURE.lookup(t)


def test_default_tables_keep_their_bounds_text_and_source():
    for new, old in ((SHOCK_FACTORS, OLD_SHOCK), (TEMPERATURE_FACTORS, OLD_TEMPERATURE)):
        assert new.lower == old.lower and new.values == old.values and new.top == old.top
        assert [new.text(k) for k in range(len(new))] == [old.text(k) for k in range(len(old))]
    assert SHOCK_FACTORS.source == "the source's shock-factor table, S5 calculation 1, read with errata E4"


@settings(max_examples=100, deadline=None)
@given(st.sampled_from(["roba-es", "comintec", "source"]), st.floats(-30, 80), st.floats(-30, 80))
def test_every_temperature_table_never_falls(name, a, b):
    table = factor_table("temperature", name)
    lo, hi = sorted((a, b))
    assert table.lookup(Q_(lo, "degC")) <= table.lookup(Q_(hi, "degC"))


# --- errors: file, row and column ----------------------------------------------------------------

HEADER = "from [degC],to [degC],factor [1],at_boundary,source\n"


def write(tmp_path, text, name="t.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


@pytest.mark.parametrize(
    "body, message",
    [
        (",50,1.0,higher,a\n50,70,0.9,higher,a\n",
         r"row 3, column factor: expected factors that never fall as T rises, found 0.9 after 1.0"),
        (",50,1.0,higher,a\n60,70,1.3,higher,a\n",
         r"row 3, column from: expected the band to start where the row before ends \(50\), found '60', a gap"),
        (",50,1.0,higher,a\n40,70,1.3,higher,a\n", r"row 3, column from: .* found '40', an overlap"),
        (",50,-1.0,higher,a\n", r"row 2, column factor: expected a factor above zero, found '-1.0'"),
        (",50,1.0,higher,a\n70,50,1.3,higher,a\n", r"row 3, column to: expected a band that rises"),
        (",50,x,higher,a\n", r"row 2, column factor: expected a number, found 'x'"),
        (",50,1.0,higher,a\n,70,1.3,higher,a\n", r"row 3, column from: expected a number, found an empty cell"),
        (",50,1.0,upward,a\n", r"row 2, column at_boundary: expected one of higher, lower, found 'upward'"),
        (",50,1.0,higher,a\n50,70,1.3,lower,a\n", r"row 3, column at_boundary: expected the same rule in every row"),
        (",50,1.0,higher,\n", r"row 2, column source: expected where the factors come from"),
        ("", r"expected one row per band, found none"),
    ],
)
def test_a_bad_table_is_named_by_row_and_column(tmp_path, body, message):
    path = write(tmp_path, HEADER + body)
    with pytest.raises(CalcError, match=rf"^{path}, |^{path}: "):
        load_factor_table(path, "T", "temperature")
    with pytest.raises(CalcError, match=message):
        load_factor_table(path, "T", "temperature")


@pytest.mark.parametrize(
    "text, message",
    [
        ("", r": expected a header row, found an empty file"),
        ("from [degC],to [degC],factor [1],source\n",
         r": expected the columns from, to, factor, at_boundary, source, found no column 'at_boundary'"),
        ("from [N*m],to [N*m],factor [1],at_boundary,source\n,1,1,higher,a\n",
         r"header, column from: expected a unit of temperature"),
        ("from [degC],to [K],factor [1],at_boundary,source\n,1,1,higher,a\n",
         r"header: expected the columns from and to in one unit"),
        ("from [degC],to (degC),factor,at_boundary,source\n", r"header column 2 'to \(degC\)' is not of the form"),
    ],
)
def test_a_bad_header_is_named(tmp_path, text, message):
    path = write(tmp_path, text)
    with pytest.raises(CalcError, match=message):
        load_factor_table(path, "T", "temperature")


def test_a_table_that_is_not_utf8(tmp_path):
    path = tmp_path / "t.csv"
    path.write_bytes(b"from [degC]\xff")
    with pytest.raises(CalcError, match="not UTF-8"):
        load_factor_table(path, "T", "temperature")


def test_an_unknown_name_or_missing_file(tmp_path):
    with pytest.raises(CalcError,
                       match=r"^coupling.start_factors: unknown starts-factor table 'ktr'; expected one of roba-es or "
                             r"a path"):
        factor_table("starts", "ktr", where="coupling.start_factors")
    with pytest.raises(CalcError, match=r"the factor table 'mine.csv' does not exist"):
        factor_table("starts", "mine.csv", tmp_path)
    with pytest.raises(CalcError, match=r"expected a table name \(roba-es\) or a path"):
        factor_table("starts", " ")


def test_the_at_boundary_rule_of_a_band_table():
    with pytest.raises(CalcError, match="expected at_boundary to be one of higher, lower"):
        BandTable("x", (0, 1), (1.0, 1.1), "1/h", "per_hour", "a table", at_boundary="middle")


# --- case keys -----------------------------------------------------------------------------------

ELASTOMER = """
[coupling]
type = "elastomer"
accel_torque = "2 N*m"
drive_inertia = "1.5 kg*cm**2"
load_inertia = "30 kg*cm**2"
temperature = "60 degC"
excitation_frequency = "40 Hz"
shaft_1 = "14 mm k6"
shaft_2 = "12 mm h7"
"""


def test_case_names_a_makers_temperature_table(capsys, write_case):
    path = write_case(HEAD_TOML + PROFILE_TOML + ELASTOMER + 'temperature_factors = "roba-es"\n')
    code, out, err = run(capsys, path, "--json")
    assert code == 0, err
    c = json.loads(out)["coupling"]
    assert c["temperature_factor"] == 1.5  # Mayr: 1.5 at +60 °C (the source's table: 1.3)
    assert c["temperature_factors"].startswith("Mayr")


def test_case_names_its_own_table_by_path(capsys, write_case, tmp_path):
    write(tmp_path, HEADER + ",65,1.25,higher,our own test bench\n65,120,1.7,higher,our own test bench\n", "ours.csv")
    code, out, err = run(capsys,
                         write_case(HEAD_TOML + PROFILE_TOML + ELASTOMER + 'temperature_factors = "ours.csv"\n'),
                         "--json")
    assert code == 0, err
    c = json.loads(out)["coupling"]
    assert c["temperature_factor"] == 1.25 and "ours.csv: our own test bench" in c["temperature_factors"]


def test_case_with_an_unknown_table_name(capsys, write_case):
    path = write_case(HEAD_TOML + PROFILE_TOML + ELASTOMER + 'temperature_factors = "ktr"\n')
    code, out, err = run(capsys, path)
    assert code == 2 and out == ""
    assert err.strip().endswith("coupling.temperature_factors: unknown temperature-factor table 'ktr'; expected one of "
                                "comintec, roba-es, source or a path to a CSV file")
    assert err.count("\n") == 1


def test_case_names_a_shock_table(capsys, write_case, tmp_path):
    # A shock table of 1.5 over every Z_h: T_2max = 12 N·m · 10 · 1.5 · eta; the example cycle has
    # Z_h = 3600 / 2 s = 1800 per hour, f_s 1.3 by the source's table.
    write(tmp_path, "from [1/h],to [1/h],factor [1],at_boundary,source\n0,,1.5,higher,a test table\n", "shock.csv")
    head = HEAD_TOML.replace('ratio = 10', 'ratio = 10\nshock_factors = "shock.csv"')
    assert 'shock_factors' in head
    code, out, err = run(capsys, write_case(head + PROFILE_TOML), "--json")
    assert code == 0, err
    r = json.loads(out)
    assert r["cyclic"]["fs"] == 1.5 and r["cyclic"]["fs_table"].endswith("shock.csv: a test table")
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML, "plain.toml"), "--json")
    assert json.loads(out)["cyclic"]["fs"] == 1.3
    named = HEAD_TOML.replace('ratio = 10', 'ratio = 10\nshock_factors = "source"')
    code, out2, err = run(capsys, write_case(named + PROFILE_TOML, "named.toml"), "--json")
    assert json.loads(out2) == {**json.loads(out), "case": json.loads(out2)["case"]}


def test_the_factor_folder_is_package_data():
    assert FACTOR_DIR.name == "factors" and FACTOR_DIR.parent.name == "catalogs"
    assert np.all([p.suffix == ".csv" for p in FACTOR_DIR.iterdir()])


# --- the peak-torque check of elastomer couplings ------------------------------------------------

JAWS = (
    "part,series,size,type,T_KN [N*m],T_Kmax [N*m],C_T [N*m/rad],C_tube [N*m**2/rad],J [kg*cm**2],n_max [rpm],"
    "d_1min [mm],d_1max [mm],d_2min [mm],d_2max [mm],T_Amin [N*m],T_Amax [N*m],H [mm],A_max [mm],source\n"
    "J-10,J,10,elastomer,10,15,3000,,0.2,,6,20,6,20,,,,,a test row\n"
    "J-11,J,11,elastomer,11,,3000,,0.2,,6,20,6,20,,,,,a test row without T_Kmax\n"
)


def jaw_selection(tmp_path, **kw):
    from calc.data.catalog import load_catalog
    from calc.domain.coupling import SCHEMA, select_coupling

    catalog = load_catalog(write(tmp_path, JAWS, "jaws.csv"), SCHEMA)
    args = dict(accel_torque=Q_(3.5, "N*m"), drive_inertia=Q_(1.5, "kg*cm**2"), load_inertia=Q_(30, "kg*cm**2"),
                excitation_frequency=Q_(10, "Hz"), shaft_1="14 mm k6", shaft_2="12 mm h7", temperature=Q_(20, "degC"))
    return select_coupling(catalog, **{**args, **kw})


def test_peak_torque_against_t_kmax(tmp_path):
    # Hand calculation: T_S = M_N = 3.5 · 30 / 31.5 · 2.5 = 8.3333 N·m; 20 °C: K_ϑ = 1.0; 900 starts
    # per hour, Mayr S_z = 1.8 (801-1000): T_S · S_z · K_ϑ = 15.0 N·m against T_Kmax = 15 N·m (passes, at 1.0);
    # 1000 starts: still 1.8. With Mayr's temperature factor at 45 °C (1.5): 22.5 N·m > 15 N·m, 50 % over.
    s = jaw_selection(tmp_path, start_factors=factor_table("starts", "roba-es"), starts_per_hour=Q_(900, "1/hour"))
    check = next(c for c in s.checks if c.name == "T_Kmax")
    assert s.start_factor == 1.8
    assert check.required[0].m_as("N*m") == pytest.approx(15.0) and check.passes[0]
    hot = jaw_selection(tmp_path, start_factors=factor_table("starts", "roba-es"), starts_per_hour=Q_(900, "1/hour"),
                        temperature=Q_(45, "degC"), temperature_factors=factor_table("temperature", "roba-es"))
    check = next(c for c in hot.checks if c.name == "T_Kmax")
    assert check.utilization[0] == pytest.approx(1.5) and not check.passes[0]
    assert "T_S · S_z · K_ϑ <= T_Kmax: required 22.5 N·m > rated 15 N·m, 50 % over" in hot.reasons(0)


def test_a_row_without_t_kmax_is_reported_not_checked(tmp_path):
    s = jaw_selection(tmp_path, start_factors=factor_table("starts", "roba-es"), starts_per_hour=Q_(50, "1/hour"))
    check = next(c for c in s.checks if c.name == "T_Kmax")
    one = check.at(1)
    assert one.passes is None and one.governs is False and one.not_made == "the catalog gives no maximum torque T_Kmax"
    assert check.passes[1] and not any("T_Kmax" in r for r in s.reasons(1))


def test_without_a_start_table_the_check_is_not_made(tmp_path):
    s = jaw_selection(tmp_path)
    assert s.start_factor is None and s.M_Smax is None and not any(c.name == "T_Kmax" for c in s.checks)
    assert any("start_factors not given" in n for n in s.notes)


def test_starts_and_start_table_go_together(tmp_path):
    with pytest.raises(CalcError,
                       match=r"^coupling.starts_per_hour: the start-factor table needs the number of starts per hour"):
        jaw_selection(tmp_path, start_factors=factor_table("starts", "roba-es"))
    with pytest.raises(CalcError,
                       match=r"^coupling.starts_per_hour: starts per hour are read against a start-factor table"):
        jaw_selection(tmp_path, starts_per_hour=Q_(10, "1/hour"))


def test_case_start_factors_default_to_one_start_per_cycle(capsys, write_case):
    # The load cycle of PROFILE_TOML lasts 2 s: Z_h = 1800 per hour, beyond Mayr's 1000: an input error.
    path = write_case(HEAD_TOML + PROFILE_TOML + ELASTOMER + 'start_factors = "roba-es"\n')
    code, out, err = run(capsys, path)
    assert code == 2 and "coupling.starts_per_hour: expected 0 <= Z_h <= 1000 1/h" in err
    path = write_case(HEAD_TOML + PROFILE_TOML + ELASTOMER + 'start_factors = "roba-es"\nstarts_per_hour = "150 '
                                                             '1/hour"\n', "b.toml")
    code, out, err = run(capsys, path, "--json")
    assert code == 0, err
    c = json.loads(out)["coupling"]
    # M_N = 2 · 30 / 31.5 · 2.5 = 4.7619 N·m; S_z = 1.2 (101-200); K_ϑ = 1.3 (60 °C, the source's).
    assert c["start_factor"] == 1.2 and c["starts_per_hour"] == {"value": pytest.approx(150), "unit": "1/hour"}
    first = c["candidates"][0]
    assert first["peak_torque_required"]["value"] == pytest.approx(4.7619 * 1.2 * 1.3, rel=1e-4)
    assert any(k["name"] == "T_Kmax" for k in first["checks"])


def test_temperature_figure_draws_a_makers_table():
    from calc.figures.coupling_plots import temperature_factor_figure

    fig = temperature_factor_figure(Q_(60, "degC"), factor_table("temperature", "roba-es"))
    case = next(line for line in fig.axes[0].lines if line.get_gid() == "case")
    assert float(case.get_ydata()[0]) == 1.5
    assert "holds up to it" in fig.axes[0].get_title()


def test_summary_names_a_makers_temperature_table(capsys, write_case):
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + ELASTOMER + 'temperature_factors = "roba-es"\n'))
    assert code == 0, err
    assert "temperature factor 1.5 (Mayr, Installation and Operational Instructions for ROBA-ES" in out
    code, out, err = run(capsys, write_case(HEAD_TOML + PROFILE_TOML + ELASTOMER, "plain.toml"))
    assert "temperature factor 1.3 (E9)" in out
