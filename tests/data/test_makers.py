"""Published makers' catalogs: partial rows, doubtful cells, clamping hubs, several catalogs ranked
together, and the output bearing's checks (axial force, radial force, tilting moment).

Every expected figure comes from the catalog row's own source (its ``source`` column: the Beckhoff
infosys page of the WITTENSTEIN alpha unit, as the published data's SOURCES.md lists them) or from a hand calculation
written beside it. The example's load cycle (tests/conftest.py): S5, n_2max = 300 rpm, Z_h = 1800 /h
so f_s = 1.3; T_2max = 12 · 10 · 1.3 · 0.97 = 151.32 N·m at ratio 10.
"""

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.data.catalog import combine, load_catalog, load_catalogs, resolve
from calc.domain.gearbox import HUB_SCHEMA, SCHEMA, M_2k, OutputForces, clamping_hubs, rows_at_ratio, select_gearbox

from ..conftest import GEARBOXES, HEAD_TOML, PROFILE_TOML, ROOT, run
from ..domain.test_profile import example_profile


def results(capsys, path, *options):
    code, out, err = run(capsys, path, "--json", *options)
    assert code == 0, err
    return json.loads(out)


def error(capsys, path):
    code, out, err = run(capsys, path)
    assert code == 2 and out == "" and err.count("\n") == 1
    return err


@pytest.fixture(scope="module")
def catalog():
    return load_catalog(GEARBOXES, SCHEMA)


# --- Partial rows --------------------------------------------------------------------------------


def test_partial_rows_load_but_are_never_ranked(catalog):
    # SP075 (Beckhoff page 'SP075 MF'): T_2B, n_1N, T_2Not, T_2N and J_1 not assignable to a ratio;
    # the row keeps what is (n_1max 7500 rpm, F_2A 3350 N, F_2R 4200 N, M_2K 236 N·m, as catalog-data.md).
    k = catalog.index("SP075-10", "part")
    assert catalog.partial[k] and np.isnan(catalog["T_2B"][k].magnitude)
    assert (catalog["F_2A"][k].m_as("N"), catalog["F_2R"][k].m_as("N"),
            catalog["M_2K"][k].m_as("N*m")) == (3350, 4200, 236)
    rows = rows_at_ratio(catalog, Q_(10, ""))
    assert not rows.partial.any() and "SP075-10" not in rows.parts


def test_a_ratio_with_only_partial_rows_says_so(catalog):
    sp = catalog.rows(np.char.startswith(catalog.parts.astype(str), "SP"))
    with pytest.raises(CalcError, match=r"has ratio 10 \(only partial rows, never checked: SP060-10, SP075-10"):
        rows_at_ratio(sp, Q_(10, ""))


def test_naming_a_partial_row_is_an_input_error(capsys, write_case):
    err = error(capsys, write_case(HEAD_TOML.replace("ratio = 10", 'ratio = 10\npart = "SP075-10"') + PROFILE_TOML))
    assert "gearbox.part: SP075-10 is a partial row of catalogs/gearboxes.csv (row " in err
    assert "never checked: T_2B, n_1N, T_2Not, T_2N, J_1: per-ratio split not readable" in err
    accuracy = '[accuracy]\napplied_torque = "1 N*m"\n[[accuracy.component]]\npart = "NPS035-10"\n'
    err = error(capsys, write_case(HEAD_TOML + PROFILE_TOML + accuracy))
    assert "accuracy.component[1].part: NPS035-10 is a partial row" in err and "T_2N not published on this page" in err


def test_a_required_cell_stays_required_on_a_complete_row(tmp_path):
    text = GEARBOXES.read_text().replace("TP010-10,TP010,10,81,", "TP010-10,TP010,10,,")
    (tmp_path / "g.csv").write_text(text)
    with pytest.raises(CalcError, match=r"row 11 \(TP010-10\), column T_2N: expected a number, found an empty cell"):
        load_catalog(tmp_path / "g.csv", SCHEMA)


@pytest.mark.parametrize(
    "old, new, fragment",
    [
        (",2795,,270,", ",2795x,,270,", "row 11 (TP010-10), column F_2A: expected a number, found '2795x'"),
        (",2795,,270,", ",2795,,-270,", "row 11 (TP010-10), column M_2K: expected a value above zero, found -270"),
        ("F_2A [N]", "F_2A [N*m]", "column F_2A: expected a unit of force"),
        ("J_1_hub [mm]", "J_1_hub [kg]", "column J_1_hub: expected a unit of length"),
    ],
)
def test_new_columns_are_checked_like_the_others(tmp_path, old, new, fragment):
    text = GEARBOXES.read_text()
    if old.startswith(","):  # the TP010-10 row only
        line = next(x for x in text.splitlines() if x.startswith("TP010-10,"))
        text = text.replace(line, line.replace(old, new, 1))
    else:
        text = text.replace(old, new, 1)
    (tmp_path / "g.csv").write_text(text)
    with pytest.raises(CalcError) as err:
        load_catalog(tmp_path / "g.csv", SCHEMA)
    assert fragment in str(err.value)


def test_a_maker_table_without_the_new_columns_loads(tmp_path):
    # The optional columns (F_2A, z_2, J_1_hub, ...) may be absent from a file: every cell empty.
    header = GEARBOXES.read_text().splitlines()[0].split(",")
    keep = [k for k, name in enumerate(header) if name.split(" [")[0] in
            ("part", "series", "ratio", "T_2N", "T_2B", "T_2Not", "n_1N", "n_1max", "eta", "backlash", "C_t21", "J_1",
             "source")]
    import csv
    import io

    rows = list(csv.reader(io.StringIO(GEARBOXES.read_text())))[:59]
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerows([[r[k] for k in keep] for r in rows])
    path = tmp_path / "maker.csv"
    path.write_text(out.getvalue())
    cat = load_catalog(path, SCHEMA)
    assert np.isnan(cat["F_2A"].magnitude).all() and np.isnan(cat["J_1_hub"].magnitude).all()
    assert (cat.family == cat.text["series"]).all()  # no family column: the series stands in


# --- Clamping hubs ---------------------------------------------------------------------------------


def test_the_motor_shaft_picks_the_smallest_hub_that_takes_it(catalog):
    hubs = load_catalog(resolve("gearbox-hubs", None, "hubs"), HUB_SCHEMA)
    rows = rows_at_ratio(catalog, Q_(10, ""))
    k = rows.index("TP010-10", "part")
    # Beckhoff page 'TP010 MF', i = 10: J_1 0.40 / 0.57 / 1.94 kg·cm² for the 14 / 19 / 24 mm hubs.
    J_1, d, d_max = clamping_hubs(rows, hubs)
    assert (J_1[k], d[k]) == (0.4, 14)  # no shaft given: the catalog's J_1, for its 14 mm hub
    J_1, d, d_max = clamping_hubs(rows, hubs, Q_(14, "mm"))
    assert (J_1[k], d[k], d_max[k]) == (0.4, 14, 24)  # a 14 mm shaft fits the 14 mm hub
    J_1, d, _ = clamping_hubs(rows, hubs, Q_(0.75, "in"))  # 19.05 mm: the 24 mm hub
    assert (J_1[k], d[k]) == (1.94, 24)
    J_1, d, _ = clamping_hubs(rows, hubs, Q_(30, "mm"))
    assert np.isnan(J_1[k]) and np.isnan(d[k])  # no hub of TP010-10 takes 30 mm


def test_motor_shaft_in_a_case_sets_j1_and_the_hub_check(capsys, write_case):
    head = HEAD_TOML.replace('inertia = "4.2 kg*cm**2"', 'inertia = "4.2 kg*cm**2"\nshaft = "16 mm k6"')
    r = results(capsys, write_case(head.replace("ratio = 10", 'ratio = 10\npart = "TP010-10"') + PROFILE_TOML))
    (c,) = r["gearbox"]["candidates"]
    # 16 mm: the 19 mm hub, J_1 = 0.57 kg·cm²; λ = (0.57 + 1500 / 10²) / 4.2 = 3.7071.
    assert c["J_1"] == {"value": 0.57, "unit": "kg*cm**2"} and c["J_1_hub"] == {"value": 19.0, "unit": "mm"}
    assert c["inertia_ratio"] == pytest.approx(15.57 / 4.2)
    hub = next(k for k in c["checks"] if k["name"] == "d_hub")
    assert hub["utilization"] == pytest.approx(16 / 24) and hub["passes"] is True and hub["governs"] is True
    wide = head.replace("16 mm k6", "30 mm").replace("ratio = 10", 'ratio = 10\npart = "TP010-10"')
    r = results(capsys, write_case(wide + PROFILE_TOML))
    (c,) = r["gearbox"]["candidates"]
    assert "d_motor <= d_hub,max: required 30 mm > rated 24 mm, 25 % over" in c["reasons"]


# --- Several catalogs ranked together ---------------------------------------------------------------


MAKER_CSV = (
    "part,series,ratio [1],T_2N [lbf*in],T_2B [lbf*in],T_2Not [lbf*in],n_1N [rpm],n_1max [rpm],eta [1],"
    "backlash [arcmin],C_t21 [N*m/arcmin],J_1 [kg*cm**2],family,size,source\n"
    "MK160-10,MK160,10,1000,1600,3000,3000,6000,0.96,6,20,1.0,MK,160,made-up maker row for a test\n"
)


def test_two_catalogs_rank_together_each_candidate_naming_its_own(capsys, write_case, tmp_path):
    (tmp_path / "my-maker.csv").write_text(MAKER_CSV)
    case = write_case(HEAD_TOML.replace("ratio = 10",
                                        'ratio = 10\ncatalog = ["gearboxes", "my-maker.csv"]') + PROFILE_TOML)
    g = results(capsys, case)["gearbox"]
    # MK160-10: T_2B = 1600 lbf·in = 180.78 N·m; T_2max = 12 · 10 · 1.3 · 0.96 = 149.76 N·m → 0.828;
    # n_1max 6000 → 0.5. Its T_2B is below NPT035-10's 220 N·m: the smallest adequate, first.
    assert [c["part"] for c in g["candidates"]][:3] == ["MK160-10", "NPT035-10", "NPS045-10"]
    first = g["candidates"][0]
    assert first["catalog"] == str(tmp_path / "my-maker.csv") and first["family"] == "MK"
    t2b = next(k for k in first["checks"] if k["name"] == "T_2B")
    assert t2b["rated"]["value"] == pytest.approx(1600 * 0.1129848290276167)
    assert t2b["utilization"] == pytest.approx(149.76 / 180.7757, rel=1e-5)
    assert g["candidates"][1]["catalog"] == "catalogs/gearboxes.csv"
    assert g["catalog"] == f"catalogs/gearboxes.csv + {tmp_path / 'my-maker.csv'}"
    assert [m["catalog"] for m in g["catalogs"]] == ["catalogs/gearboxes.csv", str(tmp_path / "my-maker.csv")]
    assert g["best_of_family"]["MK"] == "MK160-10" and g["selected"] == "MK160-10"
    code, out, _ = run(capsys, case)
    assert f"PASS  MK160-10 [{tmp_path / 'my-maker.csv'}], smallest adequate MK" in out
    # The ratio search names its rows' files as the gearbox section does (one provenance block).
    from calc.__main__ import main

    assert main(["ratios", str(case), "--json"]) == 0
    r = json.loads(capsys.readouterr().out)
    keys = ("catalog", "catalog_sha256", "catalogs")
    assert {k: r[k] for k in keys} == {k: g[k] for k in keys}


def test_a_list_with_a_missing_catalog_names_it(capsys, write_case):
    case = write_case(HEAD_TOML.replace("ratio = 10", 'ratio = 10\ncatalog = ["gearboxes", "nope.csv"]') + PROFILE_TOML)
    assert "gearbox.catalog[2]: the catalog 'nope.csv' does not exist" in error(capsys, case)


def test_the_same_part_in_two_catalogs_is_an_error(capsys, write_case, tmp_path):
    (tmp_path / "copy.csv").write_text(MAKER_CSV.replace("MK160-10,", "TP010-10,"))
    case = write_case(HEAD_TOML.replace("ratio = 10", 'ratio = 10\ncatalog = ["gearboxes", "copy.csv"]') + PROFILE_TOML)
    err = error(capsys, case)
    assert "gearbox.catalog: the part 'TP010-10' stands in catalogs/gearboxes.csv (row 11) and in" in err
    assert "(row 2)" in err


@pytest.mark.parametrize("value", ["[]", "[1, 2]", "3"])
def test_a_catalog_key_must_be_names(capsys, write_case, value):
    case = write_case(HEAD_TOML.replace("ratio = 10", f"ratio = 10\ncatalog = {value}") + PROFILE_TOML)
    assert "gearbox.catalog: expected a catalog name or path in quotes, or a list of them" in error(capsys, case)


def test_load_catalogs_refuses_an_empty_list():
    with pytest.raises(CalcError, match="expected a catalog name, a path to a CSV file or a list of them, found"):
        load_catalogs([], None, "catalog", SCHEMA)


def test_coupling_catalogs_rank_together(capsys, write_case, tmp_path):
    header = (ROOT / "catalogs" / "couplings.csv").read_text().splitlines()[0]
    pad = "," * 12
    row = f"XB-30,XB,30,bellows,30,,40000,,1.0,10000,10,30,10,30,,,,,{pad}no,made-up row"
    (tmp_path / "bellows.csv").write_text(f"{header}\n{row}\n")
    coupling = ('[coupling]\ncatalog = ["couplings", "bellows.csv"]\ntype = "bellows"\naccel_torque = "12 N*m"\n'
                'drive_inertia = "4.2 kg*cm**2"\nload_inertia = "15.93 kg*cm**2"\nexcitation_frequency = "150 Hz"\n'
                'shaft_1 = "19 mm k6"\nshaft_2 = "16 mm h7"\n')
    c = results(capsys, write_case(HEAD_TOML + PROFILE_TOML + coupling))["coupling"]
    # M_N = 12 · 15.93 / 20.13 · 2.5 = 23.74 N·m: XB-30's 30 N·m is the smallest adequate rated torque.
    assert c["selected"] == "XB-30" and c["candidates"][0]["catalog"] == str(tmp_path / "bellows.csv")
    assert c["candidates"][1]["part"] == "AKD-30" and "RINGFEDER" in c["candidates"][1]["source"]
    assert len(c["catalogs"]) == 2


# --- Output bearing -----------------------------------------------------------------------------------


def test_tilting_moment_by_hand():
    # M_2k = F_2a · y_2 + F_2r · (x_2 + z_2) = 1000 N · 0.02 m + 500 N · (0.05 + 0.03) m = 20 + 40 = 60 N·m.
    m = M_2k(F_2a=Q_(1000, "N"), y_2=Q_(20, "mm"), F_2r=Q_(500, "N"), x_2=Q_(50, "mm"), z_2=Q_(30, "mm"))
    assert m.m_as("N*m") == pytest.approx(60)
    # The same in inch units: 224.809 lbf, 0.787 in ... gives the same moment.
    m_in = M_2k(F_2a=Q_(1000 / 4.4482216152605, "lbf"), y_2=Q_(20 / 25.4, "in"), F_2r=Q_(500 / 4.4482216152605, "lbf"),
                x_2=Q_(50 / 25.4, "in"), z_2=Q_(30 / 25.4, "in"))
    assert m_in.m_as("N*m") == pytest.approx(60)


def test_bearing_checks_in_the_ranking(catalog):
    rows = rows_at_ratio(catalog, Q_(10, ""))
    # NPT035-10 (Beckhoff page 'NPT035 MF'): F_2A 3500 N, M_2K 134 N·m, no F_2R published.
    # F_2a = 1000 N on the axis at 20 mm, F_2r = 500 N at 50 mm from the flange, z_2 not given (0):
    # M_2k = 1000 · 0.02 + 500 · 0.05 = 45 N·m → 45 / 134 = 0.336; F_2a: 1000 / 3500 = 0.286.
    load = OutputForces(Q_(1000, "N"), Q_(500, "N"), Q_(50, "mm"), Q_(20, "mm"))
    sel = select_gearbox(example_profile(), rows, Q_(12, "N*m"), output_load=load)
    c = {k.name: k for k in next(x for x in sel.candidates() if x.part == "NPT035-10").checks}
    assert c["M_2K"].required.m_as("N*m") == pytest.approx(45) and c["M_2K"].utilization == pytest.approx(45 / 134)
    assert c["F_2A"].utilization == pytest.approx(1000 / 3500) and c["F_2A"].governs and c["F_2A"].passes
    assert c["F_2R"].passes is None and c["F_2R"].reason() == "F_2r <= F_2R: not checked, the catalog gives no F_2R"
    assert sel.selected == "NPT035-10" and any("z_2" in n for n in sel.notes)
    # F_2r = 3000 N at 50 mm: M_2k = 150 N·m > 134 N·m of NPT035-10, 11.9 % over; NPS045-10 gives no
    # M_2K (cut off in its source): not checked there, so it is the smallest adequate gearbox.
    forces = OutputForces(radial_force=Q_(3000, "N"), lever_arm=Q_(50, "mm"))
    sel = select_gearbox(example_profile(), rows, Q_(12, "N*m"), output_load=forces)
    npt = next(x for x in sel.candidates() if x.part == "NPT035-10")
    assert npt.reasons == ["M_2k <= M_2K: required 150 N·m > rated 134 N·m, 11.9 % over"]
    assert sel.selected == "NPS045-10"


def test_bearing_checks_from_the_case(capsys, write_case):
    head = HEAD_TOML.replace('inertia = "1500 kg*cm**2"', 'inertia = "1500 kg*cm**2"\naxial_force = "1 kN"\n'
                             'radial_force = "500 N"\nlever_arm = "50 mm"\naxial_force_radius = "20 mm"')
    g = results(capsys, write_case(head + PROFILE_TOML))["gearbox"]
    first = g["candidates"][0]
    names = [k["name"] for k in first["checks"]]
    assert names[-3:] == ["F_2A", "F_2R", "M_2K"] and "mode" not in first["checks"][-1]
    m = first["checks"][-1]
    assert m["required"] == {"value": pytest.approx(45), "unit": "N*m"} and m["rated"]["value"] == 134
    assert first["checks"][-2]["not_made"] == "the catalog gives no F_2R"
    assert any("z_2" in note for note in g["notes"])


@pytest.mark.parametrize(
    "keys, fragment",
    [
        ('lever_arm = "50 mm"',
         "load.lever_arm: a lever arm is the distance of load.radial_force from the output flange, but no radial_force "
         "is given"),
        ('radial_force = "500 N"',
         "load.radial_force: the tilting moment needs the force's lever arm from the output flange, load.lever_arm, "
         "found none"),
        ('axial_force_radius = "5 mm"',
         "load.axial_force_radius: the distance of load.axial_force from the axis, but no axial_force is given"),
        ('radial_force = "500 N"\nlever_arm = "-5 mm"',
         "load.lever_arm: expected a distance of zero or more, found '-5 mm'"),
        ('axial_force = "0 N"', "load.axial_force: expected an axial force above zero, found '0 N'"),
        ('radial_force = "5 N*m"\nlever_arm = "5 mm"', "load.radial_force: expected a force"),
    ],
)
def test_bad_output_load_names_its_key(capsys, write_case, keys, fragment):
    head = HEAD_TOML.replace('inertia = "1500 kg*cm**2"', f'inertia = "1500 kg*cm**2"\n{keys}')
    assert fragment in error(capsys, write_case(head + PROFILE_TOML))


def test_bad_motor_shaft_names_its_key(capsys, write_case):
    head = HEAD_TOML.replace('inertia = "4.2 kg*cm**2"', 'inertia = "4.2 kg*cm**2"\nshaft = "thick"')
    assert "motor.shaft" in error(capsys, write_case(head + PROFILE_TOML))


def test_combine_of_one_catalog_is_that_catalog(catalog):
    assert combine([catalog], "catalog") is catalog


def test_comparison_figure_colours_by_family(catalog):
    from calc.figures.plots import comparison_figure

    sel = select_gearbox(example_profile(), rows_at_ratio(catalog, Q_(10, "")), Q_(12, "N*m"))
    fig = comparison_figure(sel)
    ax = fig.axes[0]
    bars = ax.containers[0]
    # Heights: each candidate's worst governing utilization, best first (NPT035-10 151.32 / 220 = 0.688;
    # NPS045-10 and NPT045-10 3000 / 4000 rpm = 0.75).
    np.testing.assert_allclose([b.get_height() for b in bars][:3], [151.32 / 220, 0.75, 0.75])
    colours = [b.get_facecolor() for b in bars]
    assert colours[0] == colours[2] != colours[1]  # NPT, NPS, NPT
    labels = [t.get_text() for t in ax.texts]
    assert labels[0] == "0.69 ★" and labels[2] == "0.75"  # NPT035-10 is the smallest adequate NPT, NPT045-10 is not
    assert [t.get_text() for t in fig.legends[0].get_texts()] == ["NPT", "NPS", "TP+"]


def test_comparison_figure_hatches_the_failing_candidates(catalog):
    from calc.figures.plots import comparison_figure

    sel = select_gearbox(example_profile(), rows_at_ratio(catalog, Q_(10, "")), Q_(12, "N*m"))
    bars = comparison_figure(sel).axes[0].containers[0]
    # TP300-10 and TP500-10 sit exactly on n_1max (3000 rpm against 3000 rpm): on the limit, passing.
    assert [b.get_hatch() for b in bars] == [None] * 6 + ["///"] * 6


def test_an_accuracy_part_from_a_list_of_catalogs_names_its_file_and_doubt(capsys, write_case, tmp_path):
    (tmp_path / "my-maker.csv").write_text(MAKER_CSV)
    head = HEAD_TOML.replace("ratio = 10", 'ratio = 10\ncatalog = ["gearboxes", "my-maker.csv"]')
    accuracy = ('[accuracy]\napplied_torque = "1 N*m"\n[[accuracy.component]]\npart = "MK160-10"\n'
                '[[accuracy.component]]\npart = "NPS045-10"\n')
    a = results(capsys, write_case(head + PROFILE_TOML + accuracy))["accuracy"]
    first, second = a["components"]
    assert first["source"] == f"{tmp_path / 'my-maker.csv'} row 2"
    # NPS045-10's eta, L_PA and backlash are read per stage group (SOURCES.md): the doubt goes with the row.
    assert second["source"].startswith("catalogs/gearboxes.csv row ")
    assert "doubtful figures: eta/L_PA/backlash" in second["source"]

_force = st.floats(0, 1e5, allow_subnormal=False)
_arm = st.floats(0, 1e3, allow_subnormal=False)


@settings(max_examples=60, deadline=None)
@given(_force, _arm, _force, _arm, _arm, st.floats(0.1, 10))
def test_tilting_moment_laws(F_a, y, F_r, x, z, k):
    def moment(F_a, y, F_r, x, z):
        return M_2k(F_2a=Q_(F_a, "N"), y_2=Q_(y, "mm"), F_2r=Q_(F_r, "N"), x_2=Q_(x, "mm"), z_2=Q_(z, "mm")).m_as("N*m")

    m = moment(F_a, y, F_r, x, z)
    assert m >= 0
    assert moment(k * F_a, y, k * F_r, x, z) == pytest.approx(k * m, rel=1e-9, abs=1e-9)  # linear in the forces
    assert moment(F_a, y, F_r, x + z, 0.0) == pytest.approx(m, rel=1e-9, abs=1e-9)  # z_2 lengthens the lever arm
    assert moment(F_a, y, F_r, x, z + 1.0) >= m  # the bearing further in: never less moment
