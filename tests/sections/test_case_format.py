"""The case format is one document, docs/case-format.md, that cannot drift from the readers: its
key reference is what the sections' declarations give (calc.sections.reference), every declared key
has a kind the reader knows, and the results of every example and test case fit the JSON Schema
docs/results.schema.json (the tests' ``run`` checks each evaluation they make; here the files of
cases/ and tests/cases/ as the command line writes them)."""

import subprocess
import sys

import pytest

from calc.sections.case import OTHER_KINDS, Key, read_case
from calc.report import RENDERERS
from calc.sections import DECLARED, SECTIONS, TOP_KEYS, declared, places
from calc.sections.reference import BEGIN, END, reference
from calc.core.units import KINDS

from ..conftest import ROOT, check_results

DOC = ROOT / "docs" / "case-format.md"
CASES = sorted((ROOT / "cases").glob("*.toml")) + sorted((ROOT / "tests" / "cases").glob("*.toml"))


def all_keys(keys=None, path=""):
    """Every declared key with its path (``accuracy.component.stiffness_curve.K1``)."""
    for k in keys if keys is not None else ():
        yield f"{path}.{k.name}", k
        yield from all_keys(k.keys, f"{path}.{k.name}")


def every_key():
    for t in DECLARED:
        yield from all_keys(t.keys, t.name)


def test_the_document_holds_the_key_reference_the_declarations_give():
    text = DOC.read_text(encoding="utf-8")
    assert text.count(BEGIN) == 1 and text.count(END) == 1, "docs/case-format.md: the key reference's markers"
    written = text[text.index(BEGIN): text.index(END) + len(END)]
    assert written == reference(), (
        "docs/case-format.md: the key reference differs from the sections' declarations; paste the output of "
        'python -c "from calc.sections.reference import reference; print(reference())" between its markers'
    )


def test_every_declared_key_has_a_kind_the_reader_knows():
    unknown = [path for path, k in every_key() if k.kind not in KINDS and k.kind not in OTHER_KINDS]
    assert not unknown
    assert all(k.keys for _, k in every_key() if k.kind in ("table", "tables"))


@pytest.mark.parametrize("path,key", list(every_key()), ids=lambda x: x if isinstance(x, str) else "")
def test_a_declared_default_reads_as_its_kind(path, key):
    # A default is written as a case file would write it, so the reader parses it as it parses the file.
    from calc.core.units import parse_quantity

    if key.default is not None and key.kind in KINDS:
        assert parse_quantity(key.default, key.kind, path) is not None


def test_every_key_of_the_example_cases_is_declared():
    # Walk the files' tables by the declarations: a key the file gives is one a section declares.
    import tomllib

    for case in CASES:
        data = tomllib.loads(case.read_text(encoding="utf-8"))
        assert set(data) <= set(TOP_KEYS), case
        for name, table in data.items():
            if name == "title":
                continue
            rows = table if isinstance(table, list) else [table]
            for row in rows:
                for key, value in row.items():
                    k = declared(f"{name}.{key}")
                    assert isinstance(k, Key)
                    members = value if isinstance(value, list) else [value]
                    for member in members:
                        if isinstance(member, dict):
                            assert {x.name for x in k.keys} >= set(member), (case, name, key)


def in_order(names, known):
    """``names`` restricted to ``known``: a further section may come anywhere between them."""
    return [n for n in names if n in known]


def test_the_lists_of_sections_follow_from_the_modules():
    shared = ["motion", "profile", "gearbox", "coupling", "motor", "drive", "accuracy"]
    assert in_order([s.NAME for s in SECTIONS], shared) == shared
    # The sections that read a table of their own keep it typed once the case is read.
    example = read_case(ROOT / "cases" / "indexing-table.toml")
    assert list(example.inputs) == list(example.sections) == ["coupling", "drive", "accuracy"]
    assert all(example.inputs[name].table is example.sections[name] for name in example.inputs)
    assert TOP_KEYS == ("title", *(t.name for t in DECLARED))
    top = ["motor", "load", "mechanism", "move", "drive_record", "profile", "gearbox", "coupling", "drive", "accuracy"]
    assert in_order(TOP_KEYS, top) == top
    # The renderers are the sections' modules' namesakes', in their order.
    renderers = [type(r).__module__.rpartition(".")[2] for r in RENDERERS]
    assert renderers == [m.__name__.rpartition(".")[2] for m in places()]
    assert declared("accuracy.component[2].stiffness_curve.K1").kind == "stiffness"
    assert declared("profile").array


def test_the_document_names_every_top_level_table():
    text = DOC.read_text(encoding="utf-8").split(BEGIN)[0]
    missing = [t.name for t in DECLARED if f"[{t.name}]" not in text]
    assert not missing, f"docs/case-format.md describes no [{missing[0]}] before its key reference"


@pytest.mark.parametrize("case", CASES, ids=lambda p: p.name)
def test_the_results_of_every_case_fit_the_schema(case):
    read_case(case)  # readable: an error here names the key, not the schema
    proc = subprocess.run([sys.executable, "-m", "calc", "evaluate", str(case), "--json", "--all-candidates"],
                          capture_output=True, text=True, cwd=ROOT, check=False)
    assert proc.returncode == 0, proc.stderr
    check_results(proc.stdout)


def test_the_schema_refuses_what_the_contract_fixes():
    # A quantity is {value, unit} and nothing else; a verdict is true, false or null; a check's passes too.
    import copy
    import json

    import jsonschema

    from ..conftest import results_schema

    example = ROOT / "cases" / "indexing-table.toml"  # a case with a gearbox, whose candidates the schema fixes
    proc = subprocess.run([sys.executable, "-m", "calc", "evaluate", str(example), "--json"], capture_output=True,
                          text=True, cwd=ROOT, check=True)
    good = json.loads(proc.stdout)
    for change in (
        lambda r: r["duty"]["t_on"].update(value="0.5 s"),
        lambda r: r["duty"]["t_on"].update(magnitude=0.5),
        lambda r: r["verdict"].update(passes="yes"),
        lambda r: r.pop("cyclic"),
        lambda r: r["gearbox"]["candidates"][0]["checks"][0].update(passes="not made"),
        lambda r: r["duty"].update(mode="S3"),
    ):
        bad = copy.deepcopy(good)
        change(bad)
        with pytest.raises(jsonschema.ValidationError):
            results_schema().validate(bad)
    # Open where results may grow: a further key in a section, a check or a further section.
    grown = copy.deepcopy(good)
    grown["coupling"]["a_further_result"] = {"anything": 1}
    grown["gearbox"]["candidates"][0]["checks"][0]["reason"] = "not checked: the catalog gives no F_2R"
    grown["brake"] = {"selected": None}
    results_schema().validate(grown)
