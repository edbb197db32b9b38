"""ISO 286 limit deviations and bore specifications as the source's ordering examples write them."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from calc import CalcError, Q_
from calc.domain.fits import GRADES, SIZE_BANDS_MM, STANDARD_TOLERANCES_UM, limit_deviations, parse_bore

# Published limit deviations [µm]: (class, nominal size in mm, lower, upper).
# k6 rows: ../shared/reference/catalog-data.md ("ISO 286 k6 limits, for example"). The others:
# ISO 286-2 tables of limit deviations for shafts and holes, at the size band named.
PUBLISHED = [
    ("k6", 14, 1, 12),  # over 10 up to 18 mm (catalog-data.md)
    ("k6", 19, 2, 15),  # over 18 up to 30 mm (catalog-data.md)
    ("k6", 32, 2, 18),  # over 30 up to 50 mm (catalog-data.md)
    ("k6", 2, 0, 6),  # up to 3 mm
    ("k6", 5, 1, 9),  # over 3 up to 6 mm
    ("k5", 20, 2, 11),
    ("k8", 20, 0, 33),  # k beyond IT7: ei = 0
    ("h6", 19, -13, 0),
    ("h7", 16, -18, 0),
    ("h7", 40, -25, 0),
    ("g6", 25, -20, -7),
    ("f7", 12, -34, -16),
    ("e8", 40, -89, -50),
    ("d9", 25, -117, -65),
    ("m6", 25, 8, 21),
    ("n6", 25, 15, 28),
    ("p6", 25, 22, 35),
    ("js6", 12, -5.5, 5.5),
    ("js7", 25, -10, 10),  # IT7 = 21 µm, rounded down to even: ±10
    ("js7", 40, -12, 12),  # IT7 = 25 µm: ±12
    ("H7", 8, 0, 15),
    ("H7", 25, 0, 21),
    ("H8", 40, 0, 39),
    ("F7", 25, 20, 41),
    ("G7", 25, 7, 28),
    ("E8", 25, 40, 73),
    ("D9", 25, 65, 117),
    ("JS7", 25, -10, 10),
    ("K6", 25, -11, 2),
    ("K7", 25, -15, 6),
    ("K7", 12, -12, 6),
    ("K8", 25, -23, 10),
    ("M7", 25, -21, 0),
    ("M7", 12, -18, 0),
    ("M8", 12, -25, 2),
    ("N6", 12, -20, -9),
    ("N7", 25, -28, -7),
    ("N8", 12, -30, -3),
    ("P7", 25, -35, -14),
    ("P7", 12, -29, -11),
    ("M6", 300, -41, -9),  # the standard's exception: ES = -9 µm, not -11
    ("M7", 2, -12, -2),  # up to 3 mm: no Δ
    ("N7", 2, -14, -4),
]


@pytest.mark.parametrize("cls, size, lower, upper", PUBLISHED)
def test_published_limit_deviations(cls, size, lower, upper):
    lo, up = limit_deviations(Q_(size, "mm"), cls)
    assert (lo.m_as("um"), up.m_as("um")) == (pytest.approx(lower), pytest.approx(upper))


def test_a_size_on_a_band_edge_belongs_to_the_band_below():
    # ISO 286 bands run "over 10 up to and including 18": 18 mm takes the 10-18 mm limits.
    assert [q.m_as("um") for q in limit_deviations(Q_(18, "mm"), "k6")] == [1, 12]
    assert [q.m_as("um") for q in limit_deviations(Q_(18.001, "mm"), "k6")] == [2, 15]


def test_limits_are_vectorized_over_sizes():
    lo, up = limit_deviations(Q_(np.array([14.0, 19.0, 32.0]), "mm"), "k6")
    assert lo.m_as("um").tolist() == [1, 2, 2] and up.m_as("um").tolist() == [12, 15, 18]


def test_inch_sizes_take_the_limits_of_their_millimetres():
    # 1 in = 25.4 mm, in the 18-30 mm band.
    assert [q.m_as("um") for q in limit_deviations(Q_(1, "in"), "k6")] == [2, 15]


CLASSES = sorted(f"{letter}{grade}" for letter, grades in GRADES.items() for grade in grades)
SIZES = st.floats(min_value=0.01, max_value=500.0, allow_nan=False)


@given(size=SIZES, cls=st.sampled_from(CLASSES))
def test_the_zone_is_one_standard_tolerance_wide(size, cls):
    grade = int(cls.lstrip("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"))
    band = int(np.searchsorted(SIZE_BANDS_MM, size, side="left"))
    lo, up = limit_deviations(Q_(size, "mm"), cls)
    width = up.m_as("um") - lo.m_as("um")
    it = STANDARD_TOLERANCES_UM[grade][band]
    if cls.lower().startswith("js") and grade >= 7:
        assert width == it - it % 2  # odd IT rounded down to even (ISO 286-1, js)
    else:
        assert width == pytest.approx(it)


@given(size=SIZES, letter=st.sampled_from("defgh"), grade=st.integers(4, 11))
def test_holes_a_to_h_mirror_their_shafts(size, letter, grade):
    s_lo, s_up = limit_deviations(Q_(size, "mm"), f"{letter}{grade}")
    h_lo, h_up = limit_deviations(Q_(size, "mm"), f"{letter.upper()}{grade}")
    assert h_lo.m_as("um") == -s_up.m_as("um") and h_up.m_as("um") == -s_lo.m_as("um")


@given(size=SIZES, grade=st.integers(4, 11))
def test_basic_shaft_and_hole_touch_the_nominal_size(size, grade):
    assert limit_deviations(Q_(size, "mm"), f"h{grade}")[1].m_as("um") == 0
    assert limit_deviations(Q_(size, "mm"), f"H{grade}")[0].m_as("um") == 0


@pytest.mark.parametrize(
    "text, limits, keyway_mm",
    [
        # The source's ordering examples (KM-20, SKB-30, WDS-100).
        ("14 mm k6", "14.001 / 14.012 mm", None),
        ('1.00" +0/-.0005", x 1/8" keyway', "0.9995 / 1.0000 in", 3.175),
        ("19 mm k6", "19.002 / 19.015 mm", None),
        ('.500" +/- .0005"', "0.4995 / 0.5005 in", None),
        ("32 mm k6", "32.002 / 32.018 mm", None),
        # Variants a user writes.
        ("32 mm h7", "31.975 / 32.000 mm", None),
        ("16 mm H7", "16.000 / 16.018 mm", None),
        ("1.000 in", "no tolerance given", None),
        ("20 mm +0.021/0", "20.000 / 20.021 mm", None),
        ('1.00" -.0005/+0 x 1/4" keyway', "0.9995 / 1.0000 in", 6.35),
        ("19mm k6, x 6 mm keyway", "19.002 / 19.015 mm", 6.0),
        (".500 in ± 0.0127 mm", "0.4995 / 0.5005 in", None),
    ],
)
def test_bores_as_the_source_writes_them(text, limits, keyway_mm):
    bore = parse_bore(text)
    assert bore.limits_text() == limits
    assert (None if bore.keyway is None else bore.keyway.m_as("mm")) == (None if keyway_mm is None
                                                                         else pytest.approx(keyway_mm))


def test_order_text_keeps_the_sources_notation():
    assert parse_bore('1.00"  +0/-.0005" ,x  1/8"   keyway').text == '1.00" +0/-.0005", x 1/8" keyway'
    assert parse_bore(".500\" +/- .0005\"").text == '.500" +/- .0005"'
    assert parse_bore("14 mm k6").text == "14 mm k6"
    assert parse_bore("14 mm k6").member == "shaft" and parse_bore("14 mm H7").member == "hole"


@given(size=st.floats(min_value=0.1, max_value=19.0, allow_nan=False))
def test_metric_and_inch_bores_are_the_same_size(size):
    inch = parse_bore(f'{size!r}" k6')
    metric = parse_bore(f"{size * 25.4!r} mm k6")
    assert inch.nominal.m_as("mm") == pytest.approx(metric.nominal.m_as("mm"), rel=1e-12)
    assert inch.upper.m_as("mm") == pytest.approx(metric.upper.m_as("mm"), rel=1e-12)


@pytest.mark.parametrize(
    "text, fragment",
    [
        ("14 mm q99", "unknown ISO 286 tolerance class 'q99'"),
        ("14 mm k", "expected a shaft size with its tolerance such as"),
        ("14 mm k6 keyway", "expected a shaft size with its tolerance such as"),
        ("k6", "expected a shaft size with its tolerance such as"),
        ("14 N k6", "expected a length unit such as mm or in, found 'N'"),
        ("14 furlongz k6", "the unit 'furlongz'"),
        ("600 mm k6", "expected a nominal size over 0 up to 500 mm"),
        ("0 mm k6", "expected a shaft size above zero"),
        ("14 mm k12", "for k the tables here cover IT4 to IT11"),
        ("14 mm K4", "for K the tables here cover IT5 to IT8"),
        ('1.00" +.001/+.001"', "leave no tolerance"),
        ("__import__('os')", "expected a shaft size with its tolerance such as"),
        (14, "expected a shaft size with its tolerance as text"),
        ('1.00" +0/-.0005", x 0" keyway',
         "expected a keyway width above zero, found '1.00\" +0/-.0005\", x 0\" keyway'"),
    ],
)
def test_bad_bores_name_the_key(text, fragment):
    with pytest.raises(CalcError) as err:
        parse_bore(text, "coupling.shaft_1")
    assert str(err.value).startswith("coupling.shaft_1") and fragment in str(err.value)


@pytest.mark.parametrize("cls", ["6k", "k", "", 6])
def test_a_malformed_tolerance_class_is_named(cls):
    # A class is a letter or two and a grade (k6, H7, js9); the grade first is no class.
    with pytest.raises(CalcError) as err:
        limit_deviations(Q_(14, "mm"), cls, "coupling.shaft_1")
    assert str(err.value) == (
        f"coupling.shaft_1: expected an ISO 286 tolerance class such as 'k6' or 'H7', found {cls!r}"
    )


def test_a_fraction_over_zero_is_an_input_error():
    # An inch keyway of 1/0" was a ZeroDivisionError; it is a one-line error naming the key.
    with pytest.raises(CalcError) as err:
        parse_bore('1.000" +0/-.0005", x 1/0" keyway', "coupling.shaft_1")
    assert str(err.value) == (
        "coupling.shaft_1: expected a fraction with a denominator above zero, found '1/0' in '1.000\" +0/-.0005\", x "
        "1/0\" keyway'"
    )
