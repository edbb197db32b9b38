"""The catalog loader: every problem named by file, row and column."""

import csv
import dataclasses
import hashlib
import itertools
import math
import os
import re
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from calc import CalcError
from calc.data import catalog, parsed
from calc.sections.case import read_case
from calc.data.catalog import load_catalog
from calc.domain.coupling import SCHEMA as COUPLING_SCHEMA
from calc.sections import evaluate
from calc.domain.gearbox import SCHEMA
from calc.domain.hysteresis import model_for_part

from ..conftest import EXAMPLE, GEARBOXES, ROOT

HEADER = (
    "part,series,ratio [1],T_2N [N*m],T_2B [N*m],T_2Not [N*m],n_1N [rpm],n_1max [rpm],eta [percent],backlash "
    "[arcmin],C_t21 [N*m/arcmin],J_1 [kg*cm**2],illustrative,source"
)
ROW = "G-10,G,10,81,126,250,3100,7500,97,3,23,0.57,no,test"


def write(tmp_path, text):
    path = tmp_path / "gb.csv"
    path.write_text(text)
    return path


def test_shipped_catalog_loads_with_published_figures():
    cat = load_catalog(GEARBOXES, SCHEMA)
    k = cat.index("TP010-10", "part")
    # Beckhoff AG2400 page 'TP010 MF', table 'Mechanical data, 1-stage' (the row's source): i=10: T2N 81,
    # T2B 126, T2Not 251, n1N 3100, Ct21 23, J1 0.40 for the 14 mm clamping hub (the smallest listed),
    # F2A 2795 N, M2Max 270 N·m.
    assert cat["T_2N"][k].m_as("N*m") == 81
    assert cat["T_2B"][k].m_as("N*m") == 126
    assert cat["T_2Not"][k].m_as("N*m") == 251
    assert cat["n_1N"][k].m_as("rpm") == 3100
    assert cat["C_t21"][k].m_as("N*m/arcmin") == pytest.approx(23)
    assert cat["J_1"][k].m_as("kg*cm**2") == pytest.approx(0.40)
    assert cat["J_1_hub"][k].m_as("mm") == 14
    assert cat["F_2A"][k].m_as("N") == 2795 and np.isnan(cat["F_2R"][k].magnitude) and cat["M_2K"][k].m_as("N*m") == 270
    assert cat["eta"][k].m_as("") == pytest.approx(0.97)
    assert len(cat.sha256) == 64
    # All rows are published figures; 58 complete, 42 partial (SP+ and NPS035, SOURCES.md) with the reason.
    assert set(cat.text["illustrative"]) == {"no"}
    assert cat.partial.sum() == 42 and (cat.text["partial"][cat.partial] != "").all()
    assert cat.text["partial"][cat.index("SP075-10", "part")].startswith("T_2B, n_1N, T_2Not, T_2N, J_1")


def test_a_catalog_in_other_units_loads_the_same(tmp_path):
    inch = HEADER.replace("T_2N [N*m]", "T_2N [lbf*in]").replace("J_1 [kg*cm**2]", "J_1 [lb*in**2]")
    # 81 N·m = 716.9 lbf·in; 0.57 kg·cm² = 0.19478 lb·in².
    row = ROW.replace(",81,", f",{81 / 0.1129848290276167!r},").replace(",0.57,",
                                                                        f",{0.57 / (0.45359237 * 2.54**2)!r},")
    cat = load_catalog(write(tmp_path, f"{inch}\n{row}\n"), SCHEMA)
    assert cat["T_2N"][0].m_as("N*m") == pytest.approx(81)
    assert cat["J_1"][0].m_as("kg*cm**2") == pytest.approx(0.57)


@pytest.mark.parametrize(
    "header, row, fragment",
    [
        (HEADER.replace(",T_2B [N*m]", ""), ROW.replace(",126,", ","), "expected a column 'T_2B [unit]'"),
        (HEADER, ROW.replace(",81,", ",eighty,"), "row 2 (G-10), column T_2N: expected a number, found 'eighty'"),
        (HEADER, ROW.replace(",81,", ",,"), "row 2 (G-10), column T_2N: expected a number, found an empty cell"),
        (HEADER, ROW.replace(",81,", ",1e2*3,"), "expected a number, found '1e2*3'"),
        (HEADER, ROW.replace(",126,", ",60,"), "row 2 (G-10), column T_2B: impossible value, expected T_2B >= T_2N"),
        (HEADER, ROW.replace(",97,", ",104,"), "column eta: impossible value, expected efficiency eta in (0, 1]"),
        (HEADER, ROW.replace(",97,", ",0,"), "column eta: expected a value above zero, found 0"),
        (HEADER, ROW.replace(",81,", ",-81,"), "expected a value above zero"),
        (HEADER.replace("C_t21 [N*m/arcmin]", "C_t21 [N*m]"), ROW, "column C_t21: expected a unit of stiffness"),
        (HEADER.replace("n_1N [rpm]", "n_1N [Hz]"), ROW, "column n_1N: expected a unit of speed"),
        (HEADER.replace("T_2N [N*m]", "T_2N [N*mm*]"), ROW, "is not one the unit registry knows"),
        (HEADER.replace("T_2N [N*m]", "T_2N"), ROW, "expected a unit in brackets"),
        (HEADER, ROW + ",extra", "expected 14 cells as in the header, found 15"),
        # 1e999 is a number by its spelling, but overflows to infinity: an overloaded gearbox would pass.
        (HEADER, ROW.replace(",81,", ",1e999,"), "row 2 (G-10), column T_2N: expected a finite number, found '1e999'"),
        (HEADER, ROW.replace(",81,", ",-1e999,"), "column T_2N: expected a finite number, found '-1e999'"),
        (HEADER, ROW.replace(",0.57,", ",1E+400,"), "column J_1: expected a finite number, found '1E+400'"),
        # Spellings Python's float() takes that a catalog must not hold.
        (HEADER, ROW.replace(",81,", ",inf,"), "column T_2N: expected a number, found 'inf'"),
        (HEADER, ROW.replace(",81,", ",-Infinity,"), "column T_2N: expected a number, found '-Infinity'"),
        (HEADER, ROW.replace(",81,", ",nan,"), "column T_2N: expected a number, found 'nan'"),
        (HEADER, ROW.replace(",0.57,", ",NaN,"), "column J_1: expected a number, found 'NaN'"),
        (HEADER, ROW.replace(",3100,", ",3_100,"), "column n_1N: expected a number, found '3_100'"),
        (HEADER, ROW.replace(",81,", ",0x51,"), "column T_2N: expected a number, found '0x51'"),
        # Numbers a float holds but a calculation cannot: 1e-320 N·m/arcmin is a subnormal whose inverse
        # overflows (the series stiffness, the twist), and T_2N = T_2B = 1e-308 N·m makes every utilization
        # infinite. Held to calc.core.units.SI_SCALE as a case file's values are: 1e-320 N·m/arcmin is
        # 1e-320 / (π / 10800) = 3.44e-317 N·m/rad.
        (HEADER, ROW.replace(",23,", ",1e-320,"),
         "row 2 (G-10), column C_t21: expected a magnitude between 1e-12 and 1e+12 in SI units (kg·m²/s²/rad), found "
         "1e-320, which is 3.44e-317"),
        (HEADER, ROW.replace(",81,126,", ",1e-308,1e-308,"),
         "column T_2N: expected a magnitude between 1e-12 and 1e+12 in SI units (kg·m²/s²), found 1e-308"),
        (HEADER, ROW.replace(",3100,", ",2e13,"),
         "column n_1N: expected a magnitude between 1e-12 and 1e+12 in SI units (rad/s), found 2e13, which is "
         "2.09e+12"),
        # A header unit never carries a number (pint refuses a scaling factor), so none can be infinite.
        (HEADER.replace("T_2N [N*m]", "T_2N [1e999*N*m]"), ROW,
         "column T_2N: the unit '1e999*N*m' is not one the unit registry knows"),
    ],
)
def test_bad_catalogs_name_file_row_and_column(tmp_path, header, row, fragment):
    path = write(tmp_path, f"{header}\n{row}\n")
    with pytest.raises(CalcError) as err:
        load_catalog(path, SCHEMA)
    assert str(path) in str(err.value)
    assert fragment in str(err.value)


def test_duplicate_part(tmp_path):
    path = write(tmp_path, f"{HEADER}\n{ROW}\n{ROW}\n")
    with pytest.raises(CalcError, match=r"row 3, column part: the part 'G-10' already stands in row 2"):
        load_catalog(path, SCHEMA)


def test_the_first_repeated_part_is_named_with_its_first_row(tmp_path):
    # Rows 2..6 hold B, A, C, A, B: row 5 repeats A (first in row 3) before row 6 repeats B (row 2).
    rows = [ROW.replace("G-10", p) for p in ("B", "A", "C", "A", "B")]
    path = write(tmp_path, "\n".join([HEADER, *rows]) + "\n")
    with pytest.raises(CalcError, match=r"row 5, column part: the part 'A' already stands in row 3$"):
        load_catalog(path, SCHEMA)


@pytest.mark.parametrize(
    "rows, fragment",
    [
        # A bad cell in a late column of row 2 comes before a bad cell in an early column of row 3.
        ((ROW.replace(",0.57,", ",x,"), ROW.replace("G-10,G,10,81,", "G-11,G,10,y,")),
         "row 2 (G-10), column J_1: expected a number, found 'x'"),
        # In one row, the columns in the schema's order: T_2N before J_1.
        ((ROW.replace(",81,", ",1e999,").replace(",0.57,", ",x,"),),
         "row 2 (G-10), column T_2N: expected a finite number"),
        # The text columns of a row come before its numbers.
        ((ROW.replace("G-10,", ",").replace(",81,", ",x,"),),
         "row 2, column part: expected a value, found an empty cell"),
        # A row of the wrong length after a bad cell: the bad cell; before it: the row.
        ((ROW.replace(",81,", ",x,"), ROW + ",extra"), "row 2 (G-10), column T_2N: expected a number, found 'x'"),
        ((ROW + ",extra", ROW.replace(",81,", ",x,")), "row 2: expected 14 cells as in the header, found 15"),
        # A blank row is skipped, yet counted in the line numbers.
        (("", ",,,,,,,,,,,,,", ROW.replace(",81,", ",-81,")),
         "row 4 (G-10), column T_2N: expected a value above zero, found -81"),
    ],
)
def test_the_first_problem_in_reading_order_is_named(tmp_path, rows, fragment):
    path = write(tmp_path, "\n".join([HEADER, *rows]) + "\n")
    with pytest.raises(CalcError) as err:
        load_catalog(path, SCHEMA)
    assert fragment in str(err.value)


#: A plain decimal number, as the case-format spec writes a catalog number: sign, digits with at
#: most one point, an optional exponent; nothing else (no inf, nan, 1_000, hex).
NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")
BACKLASH_CELLS = st.one_of(
    st.text(alphabet="0123456789+-.eE_xXinfaINFA \t", max_size=7),
    st.sampled_from(["", " ", "3", " 3.5 ", "0", "-0", "1e999", "-1e999", "1e-999", "nan", "inf", "1_0", "0x1", "+.5",
                     "5.", ".5e-3", "١٢"]),
)
FILES = itertools.count()


ARCMIN = math.pi / 10800  # rad


@settings(max_examples=150, deadline=None)
@given(st.lists(BACKLASH_CELLS, min_size=1, max_size=5))
def test_a_cell_loads_exactly_when_it_is_a_finite_number_in_range(tmp_path_factory, cells):
    # backlash [arcmin] is optional and may be zero: each cell, stripped, is empty (NaN), or a plain
    # number that is finite and not below zero; the first that is not is named.
    rows = [ROW.replace("G-10", f"G-{k}").replace(",3,23,", f",{cell},23,") for k, cell in enumerate(cells)]
    path = tmp_path_factory.getbasetemp() / f"backlash-{next(FILES)}.csv"
    path.write_text("\n".join([HEADER, *rows]) + "\n", encoding="utf-8")
    expected = []
    for k, cell in enumerate(c.strip() for c in cells):
        where = f"row {k + 2} (G-{k}), column backlash: "
        if not cell:
            expected.append(math.nan)
        elif not NUMBER.fullmatch(cell):
            expected.append(where + f"expected a number, found {cell!r}")
        elif not math.isfinite(float(cell)):
            expected.append(where + f"expected a finite number, found {cell!r}")
        elif float(cell) < 0:
            expected.append(where + f"expected a value of zero or more, found {cell}")
        elif float(cell) != 0 and not 1e-12 <= float(cell) * ARCMIN <= 1e12:
            # Held to the SI scale of a case file's values (calc.core.units.SI_SCALE): 1 arcmin = π / 10800 rad.
            expected.append(where + f"expected a magnitude between 1e-12 and 1e+12 in SI units (rad), found {cell}, "
                                    f"which is {float(cell) * ARCMIN:.3g}")
        else:
            expected.append(float(cell))
    first_error = next((e for e in expected if isinstance(e, str)), None)
    if first_error:
        with pytest.raises(CalcError) as err:
            load_catalog(path, SCHEMA)
        assert str(err.value) == f"{path}, {first_error}"
    else:
        np.testing.assert_array_equal(load_catalog(path, SCHEMA)["backlash"].m_as("arcmin"), expected)


@pytest.mark.parametrize("name, schema", [("gearboxes", SCHEMA), ("couplings", COUPLING_SCHEMA)])
def test_shipped_catalogs_load_cell_for_cell_as_written(name, schema):
    # Reference: the file read row by row with the csv module, each numeric cell float() of its text
    # in the header's unit, NaN where empty, each row at its line in the file (as the row-by-row
    # loader that the column-wise one replaced gave them).
    path = ROOT / "catalogs" / f"{name}.csv"
    with open(path, encoding="utf-8-sig", newline="") as f:
        header, *rows = list(csv.reader(f))
    index = {cell.split(" [")[0]: k for k, cell in enumerate(header)}
    cat = load_catalog(path, schema)
    assert list(cat.parts) == [r[index["part"]] for r in rows]
    assert list(cat.lines) == list(range(2, len(rows) + 2))
    for c in schema.columns:
        if c.name not in index:  # an optional column the file does not have: every cell empty
            assert c.may_be_absent and np.isnan(cat[c.name].magnitude).all()
            continue
        expected = [float(r[index[c.name]]) if r[index[c.name]] else np.nan for r in rows]
        np.testing.assert_array_equal(cat[c.name].magnitude, expected)  # NaN where NaN, else equal
        assert cat.header_units[c.name] == header[index[c.name]].split("[")[1].rstrip("]")
    for column, cells in cat.text.items():
        assert list(cells) == [r[index[column]] for r in rows]


def test_each_catalog_is_read_once_per_run(monkeypatch):
    # The example's evaluation wants the gearbox catalog for its selection and for the accuracy
    # chain's part NPT035-10, the coupling catalog once; the loop model of NPT035-10 afterwards
    # wants the gearbox catalog again.
    reads = []
    read = catalog._read_catalog
    monkeypatch.setattr(catalog, "_LOADED", {})
    monkeypatch.setattr(catalog, "_read_catalog", lambda path, schema: reads.append(path.name) or read(path, schema))
    evaluate(read_case(EXAMPLE))
    model_for_part("NPT035-10")
    assert sorted(reads) == ["couplings.csv", "gearbox-hubs.csv", "gearboxes.csv"]


def test_a_catalog_changed_since_it_was_read_is_read_again(tmp_path):
    path = write(tmp_path, f"{HEADER}\n{ROW}\n")
    first = load_catalog(path, SCHEMA)
    assert load_catalog(path, SCHEMA) is first
    relative = load_catalog(Path(os.path.relpath(path)), SCHEMA)  # another spelling of the path: one read
    assert relative.parts is first.parts and relative.path == Path(os.path.relpath(path))
    # The same number of bytes, T_2N 81 -> 82: only the modification time tells; set it one second on.
    stat = path.stat()
    path.write_text(f"{HEADER}\n{ROW.replace(',81,', ',82,')}\n")
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))
    assert load_catalog(path, SCHEMA)["T_2N"][0].m_as("N*m") == 82
    # A longer file, even within the same tick of the clock.
    path.write_text(f"{HEADER}\n{ROW.replace(',81,', ',83.5,')}\n")
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))
    assert load_catalog(path, SCHEMA)["T_2N"][0].m_as("N*m") == 83.5


def test_a_loaded_catalog_cannot_be_changed_by_one_of_its_users():
    cat = load_catalog(GEARBOXES, SCHEMA)
    with pytest.raises(ValueError, match="read-only"):
        cat["T_2N"].magnitude[0] = 1e6
    with pytest.raises(ValueError, match="read-only"):
        cat.parts[0] = "X"


def test_empty_optional_cells_are_nan_not_zero(tmp_path):
    cat = load_catalog(write(tmp_path, f"{HEADER}\n{ROW.replace(',0.57,', ',,')}\n"), SCHEMA)
    assert str(cat["J_1"][0].magnitude) == "nan"


def test_unknown_part(tmp_path):
    cat = load_catalog(write(tmp_path, f"{HEADER}\n{ROW}\n"), SCHEMA)
    with pytest.raises(CalcError, match=r"gearbox.part: no part 'X' in catalog"):
        cat.index("X", "gearbox.part")


def test_to_frame_has_units_in_column_names():
    frame = load_catalog(GEARBOXES, SCHEMA).to_frame()
    assert {"T_2N [N·m]", "J_1 [kg·cm²]", "C_t21 [N·m/arcmin]", "eta [%]"} <= set(frame.columns)
    assert frame.loc[frame.part == "TP010-10", "T_2B [N·m]"].item() == 126


def large_catalog(tmp_path, rows: int = 12_000, bad: str | None = None) -> Path:
    """The shipped gearbox catalog's rows repeated under new part names to over a megabyte
    (calc.data.parsed.SMALLEST), optionally with the T_2N cell of file row 7001 replaced by ``bad``."""
    header, *shipped = GEARBOXES.read_text(encoding="utf-8").splitlines()
    lines = [header]
    for k in range(rows):
        row = shipped[k % len(shipped)]
        lines.append(f"X{k:06d}-{row.split(',', 1)[0]},{row.split(',', 1)[1]}")
    if bad is not None:
        cells = lines[7000].split(",", 4)
        cells[3] = bad
        lines[7000] = ",".join(cells)
    path = tmp_path / "large.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    assert path.stat().st_size >= parsed.SMALLEST
    return path


def test_a_large_catalog_is_kept_parsed_by_its_content(tmp_path, monkeypatch):
    monkeypatch.setenv("CALC_CACHE_DIR", str(tmp_path / "kept"))
    path = large_catalog(tmp_path)
    first = load_catalog(path, SCHEMA)
    kept = list((tmp_path / "kept").iterdir())
    assert len(kept) == 1 and kept[0].name == parsed.cache_key(hashlib.sha256(path.read_bytes()).hexdigest(), SCHEMA)
    # The next run (no catalog read in this process yet) loads the arrays kept: the same catalog.
    monkeypatch.setattr(catalog, "_LOADED", {})
    monkeypatch.setattr(catalog, "_rows", lambda *a: pytest.fail("the kept catalog was parsed again"))
    again = load_catalog(path, SCHEMA)
    assert again is not first and again.sha256 == first.sha256 and list(again.parts) == list(first.parts)
    for c in SCHEMA.columns:
        np.testing.assert_array_equal(again[c.name].magnitude, first[c.name].magnitude)
        assert again[c.name].units == first[c.name].units
    assert again.text.keys() == first.text.keys()
    assert all(list(again.text[k]) == list(first.text[k]) for k in first.text)
    assert list(again.lines) == list(first.lines) and again.header_units == first.header_units
    assert not again["T_2N"].magnitude.flags.writeable and type(again.parts[0]) is str


def test_a_bad_large_catalog_is_never_kept_and_its_error_is_the_same(tmp_path, monkeypatch):
    monkeypatch.setenv("CALC_CACHE_DIR", str(tmp_path / "kept"))
    path = large_catalog(tmp_path, bad="12x")
    messages = []
    for _ in range(2):
        monkeypatch.setattr(catalog, "_LOADED", {})
        with pytest.raises(CalcError) as raised:
            load_catalog(path, SCHEMA)
        messages.append(str(raised.value))
    assert messages[0] == messages[1] and "row 7001" in messages[0] and "T_2N" in messages[0] and "12x" in messages[0]
    assert not (tmp_path / "kept").exists() or not list((tmp_path / "kept").iterdir())


def test_the_kept_catalogs_can_be_turned_off_and_a_damaged_one_is_read_again(tmp_path, monkeypatch):
    path = large_catalog(tmp_path)
    monkeypatch.setenv("CALC_CACHE_DIR", "off")
    assert parsed.cache_folder() is None
    load_catalog(path, SCHEMA)
    monkeypatch.setenv("CALC_CACHE_DIR", str(tmp_path / "kept"))
    (tmp_path / "kept").mkdir()
    key = parsed.cache_key(hashlib.sha256(path.read_bytes()).hexdigest(), SCHEMA)
    (tmp_path / "kept" / key).mkdir()
    (tmp_path / "kept" / key / "meta.json").write_text("not json")
    assert parsed.load_parsed(key) is None
    monkeypatch.setattr(catalog, "_LOADED", {})
    assert len(load_catalog(path, SCHEMA)) == 12_000
    # Read again and kept afresh; then a cut-short array is damage too.
    assert parsed.load_parsed(key) is not None
    values = tmp_path / "kept" / key / "value-0.npy"
    values.write_bytes(values.read_bytes()[:1000])
    assert parsed.load_parsed(key) is None and not (tmp_path / "kept" / key).exists()


def test_the_kept_catalogs_are_the_last_few_and_nothing_else_in_the_folder_goes(tmp_path, monkeypatch):
    monkeypatch.setenv("CALC_CACHE_DIR", str(tmp_path))
    foreign, earlier = tmp_path / "notes.txt", tmp_path / f"{'e' * 64}.npz"  # a user's file; an earlier form's
    foreign.write_text("mine")
    earlier.write_bytes(b"an archive")
    os.utime(foreign, ns=(0, 0))
    os.utime(earlier, ns=(0, 0))
    keys = [f"{k:064x}" for k in range(parsed.KEPT + 2)]
    for k, key in enumerate(keys):
        parsed.keep_parsed(key, np.array(["P1"], dtype=object), np.array([2]), {"T_2N": (np.array([1.0]), "N*m")},
                           {"family": np.array(["TP"], dtype=object)}, {"T_2N": "Nm"})
        os.utime(tmp_path / key, ns=(10**9 * (k + 1),) * 2)
    kept = sorted(f.name for f in tmp_path.iterdir())
    assert kept == sorted(keys[2:] + ["notes.txt"])
    got = parsed.load_parsed(keys[-1])
    assert list(got["parts"]) == ["P1"] and list(got["text"]["family"]) == ["TP"]
    assert got["values"]["T_2N"][1] == "N*m" and not got["values"]["T_2N"][0].flags.writeable


def test_a_kept_cut_is_cut_once_shared_read_only_and_the_whole_catalog_is_not_copied():
    cat = dataclasses.replace(load_catalog(GEARBOXES, SCHEMA))  # a copy: none of the run's cuts, and none kept for it
    at_10 = np.isclose(cat["ratio"].m_as(""), 10.0)
    cut = cat.kept_rows(("ratio", 10.0), at_10)
    assert cat.kept_rows(("ratio", 10.0), at_10) is cut and list(cut.parts) == list(cat.parts[at_10])
    for a in (cut.parts, cut["T_2N"].magnitude, cut.family, cut.partial, cut.illustrative):
        with pytest.raises(ValueError, match="read-only"):
            a[0] = a[1]
    assert cat.kept_rows(("every row",), np.ones(len(cat), bool)) is cat
    mine = cut.rows([0])  # a cut of one's own is one's own to change
    mine["T_2N"].magnitude[0] = 0.0
    assert cut["T_2N"].magnitude[0] != 0.0
    # A copy of the catalog (another spelling of its path) keeps cuts of its own, named as it is.
    renamed = dataclasses.replace(cat, name="other")
    assert renamed.kept_rows(("ratio", 10.0), at_10).name == "other"
    # The oldest goes first beyond KEPT_CUTS.
    for k in range(catalog.KEPT_CUTS):
        cat.kept_rows(("rows", k), [k])
    assert cat.kept_rows(("ratio", 10.0), at_10) is not cut


def test_each_part_has_its_row_and_a_repeated_part_its_last():
    cat = load_catalog(GEARBOXES, SCHEMA)
    assert all(cat.row_of_part[part] == k for k, part in enumerate(cat.parts))
    repeated = cat.rows([0, 1, 0])
    assert repeated.row_of_part == {cat.parts[0]: 2, cat.parts[1]: 1}
