"""Every formula's source is data: documents of one registry, the places cited, the readings taken
and the validity, rendered to the reference sentence the outputs print (calc.core.citation,
calc.domain.documents)."""

import re
import tomllib
from pathlib import Path
from urllib.parse import urlsplit

import numpy as np
import pytest

from calc import CalcError, Q_
from calc.core.citation import Band, Citation, Document, Source, Validity
from calc.core.formula import Formula
from calc.core.glossary import SYMBOLS, typeset
from calc.domain.accuracy import positioning_rule
from calc.domain.codegen import package_formulas
from calc.domain.coupling import f_e
from calc.domain.documents import CASE_FORMAT, DOCUMENTS, ERRATA, SOURCE
from calc.domain.gearbox import n_1
from calc.domain.stiffness import StiffnessCurve

ROOT = Path(__file__).resolve().parents[2]
FORMULAS = package_formulas()
BY_KEY = {f.key: f for f in FORMULAS}


def _validities():
    return [(f, f.source.validity) for f in FORMULAS if f.source.validity is not None]


def test_every_formula_cites_documents_of_the_registry():
    for f in FORMULAS:
        assert isinstance(f.source, Source), f.key
        strays = [c.document.name for c in f.source.all() if c.document not in DOCUMENTS]
        assert not strays, f"{f.key} cites documents outside calc.domain.documents: {strays}"


def test_every_document_of_the_registry_is_cited():
    cited = {d for f in FORMULAS for d in f.source.documents}
    assert [d.name for d in DOCUMENTS if d not in cited] == []
    assert len({d.name for d in DOCUMENTS}) == len(DOCUMENTS)  # a sentence's name picks one document


def test_addresses_are_https_and_well_formed():
    for d in DOCUMENTS:
        if d.url:
            parts = urlsplit(d.url)
            assert parts.scheme == "https" and "." in parts.netloc and " " not in d.url, d.name
    for bad in ("http://www.example.com/catalog.pdf", "https://no-dot/x", "https://www.example.com/a b", "www.x.com"):
        with pytest.raises(CalcError, match="expected an https address"):
            Document("a catalog", "A catalog", "A maker", url=bad)
    assert Document("a", "A", "B", url="https://doi.org/10.1007/978-3-662-54805-9").url


def test_a_document_names_its_title_and_publisher():
    with pytest.raises(CalcError, match="document 'a catalog': expected a publisher, found none"):
        Document("a catalog", "A catalog", " ")


def test_the_errata_cited_are_readings_the_project_lists():
    listed = tomllib.loads((ROOT / "calc" / "report" / "errata.toml").read_text(encoding="utf-8"))["errata"]
    cited = {p for f in FORMULAS for p in f.source.places(ERRATA)}
    assert cited and cited <= set(listed), sorted(cited - set(listed))


def test_the_case_format_places_cited_are_its_headings():
    headings = {line.lstrip("#").strip() for line in (ROOT / "docs" / "case-format.md").read_text().splitlines()
                if line.startswith("#")}
    cited = {p for f in FORMULAS for p in f.source.places(CASE_FORMAT)}
    assert cited and cited <= headings, sorted(cited - headings)


def test_a_validity_is_text_the_sentence_prints():
    assert len(_validities()) >= 10
    for f, v in _validities():
        assert v.text.strip() and v.text in f.reference, f.key
    with pytest.raises(CalcError, match="expected the condition in words, found an empty text"):
        Validity(" ")
    with pytest.raises(CalcError, match="expected stands to be one of heading, tail, aside, found 'before'"):
        Validity("elastomer couplings only", stands="before")


def test_a_band_states_its_numbers_in_its_words():
    # A share prints as a percentage ("3 %" of 0.03) or, a whole bound, as the symbol the source prints (T_L1 as T_1).
    banded = [(f, v) for f, v in _validities() if v.band is not None]
    assert len(banded) >= 7
    for f, v in banded:
        words = {typeset(w) for w in re.findall(r"[A-Za-z]+(?:_\w+)?", v.text)}
        for share, name in v.band.ends:
            assert f"{share * 100:g} %" in v.text or share == 1 and SYMBOLS[name].latex in words, (f.key, name)


def test_a_band_names_declared_symbols_of_one_kind():
    with pytest.raises(CalcError, match="band of T: the end n_N is a speed, expected torque"):
        Band("T", upto=(1, "n_N"))
    with pytest.raises(CalcError, match="band of T: no symbol 'T_nominal' is declared"):
        Band("T", upto=(0.03, "T_nominal"))
    with pytest.raises(CalcError, match="band of T: expected an end above or up to, found neither"):
        Band("T")


def _inside(band, value, ends):
    """Whether ``value`` lies in ``band``, its ends' symbols taking the values of ``ends``."""
    low = None if band.above is None else band.above[0] * ends[band.above[1]]
    high = None if band.upto is None else band.upto[0] * ends[band.upto[1]]
    return (low is None or abs(value) > low) and (high is None or abs(value) <= high)


def test_the_bands_of_the_stiffness_curve_are_the_curve_s_own():
    # Harmonic Drive's HFUC-32-100 (calc.domain.stiffness): T_1 = 29 N·m, T_2 = 108 N·m; a limit torque
    # belongs to the band below it.
    curve = StiffnessCurve(Q_(29, "N*m"), Q_(108, "N*m"), Q_(6.7e4, "N*m/rad"), Q_(1.1e5, "N*m/rad"),
                           Q_(1.2e5, "N*m/rad"))
    torques = np.array([0.0, 10.0, 29.0, 29.5, 60.0, 108.0, -108.5, 500.0])
    ends = {"T_L1": 29.0, "T_L2": 108.0}
    bands = [BY_KEY[f"calc.domain.stiffness.{name}"].source.validity.band for name in ("phi_c1", "phi_c2", "phi_c3")]
    chosen = curve.band(Q_(torques, "N*m"))
    for torque, k in zip(torques, chosen):
        assert [_inside(b, torque, ends) for b in bands] == [j == k for j in range(3)], torque
    for f in ("phi_c1", "phi_c2", "phi_c3"):
        assert "T" in {s.name for s in BY_KEY[f"calc.domain.stiffness.{f}"].inputs}


def test_the_bands_of_positioning_accuracy_are_the_3_percent_rule():
    # T_N = 110 N·m: the backlash form up to 3.3 N·m (errata E13), the twist form above.
    torques = np.array([0.0, 1.0, 3.3, -3.3, 3.5, -20.0, 110.0])
    low, high = (BY_KEY[f"calc.domain.accuracy.{name}"].source.validity.band
                 for name in ("Delta_phi_P_low", "Delta_phi_P_high"))
    rule = positioning_rule(Q_(torques, "N*m"), Q_(110, "N*m")).low_torque
    for torque, is_low in zip(torques, rule):
        assert (_inside(low, torque, {"T_N": 110.0}), _inside(high, torque, {"T_N": 110.0})) == (is_low, not is_low)


def test_three_sentences_as_written():
    assert f_e.reference == ("source, Couplings, Sizing 2 (garbled there); errata E7 (two-mass system, coupling as "
                             "the spring)")
    assert f_e.source.places(ERRATA) == ("E7",)
    assert f_e.source.validity.text == "two-mass system, coupling as the spring"
    assert n_1.reference == ("source, S1 criterion 1 (errata E1: n_2m · i <= n_1N) and S5 criterion 1 (errata E5: "
                             "n_2max · i <= n_1max)")
    assert n_1.source.places(SOURCE) == ("S1 criterion 1", "S5 criterion 1")
    assert n_1.source.places(ERRATA) == ("E1", "E5")
    high = BY_KEY["calc.domain.accuracy.Delta_phi_P_high"]
    assert high.reference == ("source, Positioning Accuracy, torque > 3 % of nominal torque: angular transmission "
                              "accuracy + applied torque / stiffness; errata E13")
    assert repr(high.source) == f"Source({high.reference!r})"


def test_a_formula_takes_its_source_as_data():
    with pytest.raises(CalcError, match="T_2max: expected the formula's source as a Source of citations, found str"):
        Formula("T_2max", ("T_1B",), lambda sp, T: T, "a note")
    with pytest.raises(CalcError, match="source: expected at least one citation, found none"):
        Source()
    twice = [ERRATA.at("E9", validity=Validity("elastomer couplings only")),
             SOURCE.at("Couplings", validity=Validity("a coupling between motor and gearbox"))]
    with pytest.raises(CalcError, match="expected one validity, found 2"):
        Source(*twice)
    with pytest.raises(CalcError, match="a note and a validity aside would share the parentheses"):
        Citation(ERRATA, "E9", note="a remark", validity=Validity("elastomer couplings only"))
