"""The catalog loader: every problem named by file, row and column."""

import pytest

from calc import CalcError
from calc.catalog import load_catalog
from calc.gearbox import SCHEMA

from .conftest import GEARBOXES

HEADER = "part,series,ratio [1],T_2N [N*m],T_2B [N*m],T_2Not [N*m],n_1N [rpm],n_1max [rpm],eta [percent],backlash [arcmin],C_t21 [N*m/arcmin],J_1 [kg*cm**2],illustrative,source"
ROW = "G-10,G,10,81,126,250,3100,7500,97,3,23,0.57,no,test"


def write(tmp_path, text):
    path = tmp_path / "gb.csv"
    path.write_text(text)
    return path


def test_shipped_catalog_loads_with_published_figures():
    cat = load_catalog(GEARBOXES, SCHEMA)
    k = cat.index("TP010-10", "part")
    # Beckhoff AG2400/AG3400 data (catalog-data.md): TP010 i=10: T2N 81, T2B 126, n1N 3100, Ct21 23, J1 0.57.
    assert cat["T_2N"][k].m_as("N*m") == 81
    assert cat["T_2B"][k].m_as("N*m") == 126
    assert cat["n_1N"][k].m_as("rpm") == 3100
    assert cat["C_t21"][k].m_as("N*m/arcmin") == pytest.approx(23)
    assert cat["J_1"][k].m_as("kg*cm**2") == pytest.approx(0.57)
    assert cat["eta"][k].m_as("") == pytest.approx(0.97)
    assert len(cat.sha256) == 64
    assert set(cat.text["illustrative"]) == {"yes", "no"}


def test_a_catalog_in_other_units_loads_the_same(tmp_path):
    inch = HEADER.replace("T_2N [N*m]", "T_2N [lbf*in]").replace("J_1 [kg*cm**2]", "J_1 [lb*in**2]")
    # 81 N·m = 716.9 lbf·in; 0.57 kg·cm² = 0.19478 lb·in².
    row = ROW.replace(",81,", f",{81 / 0.1129848290276167!r},").replace(",0.57,", f",{0.57 / (0.45359237 * 2.54**2)!r},")
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
