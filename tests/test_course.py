"""The course's assessment: self-checks that a guess cannot pass, each student's own brief, the
checkpoint graded by the autograder, and what students receive kept apart from the lecturer's.

Where a value is expected, it comes from a hand calculation written out here."""

import contextlib
import csv
import json
import math
import re
import shutil
import zipfile
from pathlib import Path

import pytest

from calc.core.errors import CalcError
from calc.course import checkpoint, material, selfcheck, variants

from .conftest import ROOT

COURSE = sorted(p for p in (ROOT / "notebooks").glob("[0-9][0-9]-*.ipynb") if p.stem != "00-index")
CHECKS = {p.stem: selfcheck.items(selfcheck.self_check_of(json.loads(p.read_text()))) for p in COURSE}
SEED = 2026
STUDENTS = material.roster(ROOT / "course" / "roster.csv")


# -- self-checks --------------------------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(CHECKS))
def test_each_self_check_has_four_options_whose_distractors_name_misconceptions(name):
    found = CHECKS[name]
    choices = [i for i in found if i.tolerance is None]
    assert len(choices) >= 3 and any(i.tolerance for i in found), f"{name}: 3 choices and a numerical item"
    for item in choices:
        assert [o.letter for o in item.options] == list("abcd"), f"{name} item {item.number}"
        assert item.key, f"{name} item {item.number}: exactly one option is right"
        wrong = [o for o in item.options if not o.right]
        assert all(o.misconception for o in wrong), f"{name} item {item.number}: a distractor names no misconception"
    assert len({i.key for i in choices}) == len(choices), f"{name}: no letter is right twice (a guess scores once)"
    source = (ROOT / "notebooks" / f"{name}.ipynb").read_text()
    assert f'score(\\"{name}.ipynb\\"' in source, f"{name}: a cell scores the self-check"


def test_the_key_is_balanced_and_no_guessing_rule_scores_40_percent():
    every = [i for found in CHECKS.values() for i in found]
    choices = [i for i in every if i.tolerance is None]
    share = {letter: sum(i.key == letter for i in choices) / len(choices) for letter in "abcd"}
    assert all(0.2 <= s <= 0.3 for s in share.values()), share
    # A guess never scores a numerical item; the longest option's letter is the longest-answer rule.
    for letter in "abcd":
        assert sum(i.key == letter for i in choices) / len(every) < 0.4
        for found in CHECKS.values():
            assert sum(i.key == letter for i in found) / len(found) < 0.4
    longest = sum(max(i.options, key=lambda o: len(o.text)).right for i in choices)
    assert longest / len(every) < 0.4, f"the longest option is right {longest} times of {len(every)}"


def test_a_self_check_is_scored_on_letters_and_a_number_within_its_tolerance():
    path = ROOT / "notebooks" / "02-duty-cycle.ipynb"
    key = {i.number: i.key for i in CHECKS["02-duty-cycle"] if i.key}
    # Item 4, by hand: the dwell at 0.4 s; on-time 0.15 + 0.2 + 0.15 = 0.5 s, ED = 0.5 / 0.9 = 55.56 %.
    value = selfcheck.brief_value("duty.ED", move_2__dwell="0.4 s")
    assert value == pytest.approx(100 * 0.5 / 0.9)
    right = selfcheck.score(path, {**key, 4: 55.6}, numerical={4: value})
    assert right.startswith("Self-check of 02-duty-cycle: 4 of 4 right (100%)")
    guessed = selfcheck.score(path, {1: "b", 2: "b", 3: "b", 4: 50}, numerical={4: value})
    assert guessed.startswith("Self-check of 02-duty-cycle: 1 of 4 right (25%)")  # b is right once; 50 is 10 % off
    assert selfcheck.score(path, {}).startswith("Self-check of 02-duty-cycle: 0 of 4 right (0%), 0 answered")
    with pytest.raises(CalcError, match="numerical"):
        selfcheck.score(path, {4: 55.6})


# -- each student's brief ------------------------------------------------------------------------


def test_each_student_has_a_brief_of_their_own_drawn_again_the_same():
    drawn = variants.briefs(STUDENTS, SEED)
    assert drawn == [variants.variant(s, SEED) for s in STUDENTS]
    assert len({(v.table_inertia, v.stations, v.move_time, v.dwell) for v in drawn}) == len(drawn)
    assert drawn != [variants.variant(s, SEED + 1) for s in STUDENTS]
    for v in drawn:
        assert 1000 <= v.table_inertia <= 2000 and 0.4 <= v.move_time <= 0.8 and 0.3 <= v.dwell <= 2.0
        assert f"{v.table_inertia:g} kg·cm²" in variants.brief_markdown(v)
    with pytest.raises(CalcError, match="empty"):
        variants.variant(" ", SEED)
    with pytest.raises(CalcError, match="student-01 and student-01 draw the same brief"):
        variants.briefs(["student-01", "student-01"], SEED)


def _right(v):
    """A variant's items by hand, where a hand calculation reaches them: ED = t_move / (t_move +
    t_dwell); the S-curve's ramps are symmetric, so the index covers v_max · (t_move - t_ramp) and
    n_2max = (angle / 360°) / (t_move - t_ramp) in revolutions per second, · 60 in rpm."""
    return {"ED": 100 * v.move_time / (v.move_time + v.dwell),
            "n_2max": 60 * (v.index_angle / 360) / (v.move_time - v.ramp_time)}


def test_every_students_key_is_the_hand_calculation_where_one_reaches_it(lecturer):
    keys = {row[0]: row[1:] for row in csv.reader((lecturer / "grading" / "keys.csv").open(encoding="utf-8"))}
    assert keys.pop("student") == [i.name for i in checkpoint.ITEMS] and list(keys) == STUDENTS
    for student in STUDENTS:
        v = variants.variant(student, SEED)
        key = checkpoint.expected(v)
        assert keys[student] == [str(key[i.name]) for i in checkpoint.ITEMS], student  # the lecturer's keys.csv
        for name, value in _right(v).items():
            assert key[name] == pytest.approx(value), (student, name)
        assert key["mode"] == ("S5" if key["ED"] < 60 else "S1")
    marks = checkpoint.graded({**key, "T_2m": None, "ED": "a third"}, key)
    assert [(m.item.name, m.message) for m in marks if not m.passes] == [
        ("ED", "ED: expected a number (the duty cycle ED, in %), found 'a third'"),
        ("T_2m", "T_2m: not answered (the cubic mean output torque T_2m, in N·m)")]


# -- the autograder ------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def lecturer(tmp_path_factory):
    # Built into a folder named relative to the working folder, as `make lecturer` names it.
    with contextlib.chdir(tmp_path_factory.mktemp("work")):
        return material.build_lecturer(Path("lecturer"), STUDENTS, SEED, book=False).resolve()


def _submission(folder: Path, student: str, answers: dict, name: str) -> Path:
    import nbformat

    nb = material.checkpoint_notebook(student)
    nb.cells[-1].source = "\n".join(f"{k} = {v!r}" for k, v in answers.items())
    path = folder / f"{name}.ipynb"
    nbformat.write(nb, path)
    return path


def _off(key: dict, share: float, sign: int, others: dict) -> dict:
    """A submission whose every number is off the key by `share` of its item's tolerance (in the
    direction `sign`); with share < 1 its names are the key's as a student types them, else another
    part of the same kind that some student's brief gives and the other operating mode."""
    answers = {}
    for item in checkpoint.ITEMS:
        right = key[item.name]
        if item.tolerance:
            answers[item.name] = right * (1 + sign * share * item.tolerance)
        elif share < 1:
            answers[item.name] = f" {right.lower()} "
        else:
            answers[item.name] = {"S1": "S5", "S5": "S1"}.get(right) or sorted(others[item.name] - {right})[0]
    return answers


def _graded_by_otter(test_file: Path, submission: Path):
    """A submission graded as Otter's kernel grades it (otter.execute's export cell): its code cells
    run in fresh globals, then the autograder's test file checked against them by Otter's Checker."""
    import nbformat
    from otter.execute import Checker
    from otter.nbmeta_config import NBMetadataConfig
    from otter.test_files import GradingResults

    env = {}
    for cell in nbformat.read(submission, as_version=4).cells:
        if cell.cell_type == "code":
            exec(compile(cell.source, str(submission), "exec"), env)  # the test's own submission
    return GradingResults([Checker.check(str(test_file), NBMetadataConfig(), global_env=env)])


def _passed(graded) -> dict:
    """Item name -> whether it passed: Otter numbers a file's test cases in its order, which is ITEMS'."""
    results = [r for tf in graded.results.values() for r in tf.test_case_results]
    assert [r.test_case.name for r in results] == [f"checkpoint - {n}" for n in range(1, len(checkpoint.ITEMS) + 1)]
    return {item.name: r.passed for item, r in zip(checkpoint.ITEMS, results)}


def test_the_autograder_grades_a_right_and_a_wrong_submission_of_every_student(lecturer, tmp_path):
    """Every student of the roster: a right submission (each number within half its tolerance, the
    names as typed) scores 7 of 7, a wrong one (each number off by 1.5 times its tolerance, another
    part, the other mode) 0 of 7, graded by the test file of the lecturer's autograder.zip through
    Otter's Checker in this one process; one submission also goes through Otter's whole grading
    (grade_submission: the zip unpacked, the notebook executed in a kernel) with the same marks."""
    from otter.api import grade_submission

    with zipfile.ZipFile(lecturer / "grading" / "autograder.zip") as z:
        z.extract("tests/checkpoint.py", tmp_path)
    test_file = tmp_path / "tests" / "checkpoint.py"
    assert f"SEED = {SEED}" in test_file.read_text()
    assert re.findall(r"def (\w+)\(env\)", test_file.read_text()) == [i.name for i in checkpoint.ITEMS]
    keys = {s: checkpoint.expected(variants.variant(s, SEED)) for s in STUDENTS}
    others = {name: {k[name] for k in keys.values()} for name in ("motor", "gearbox")}
    assert all(len(found) > 1 for found in others.values()), others
    wrong_marks = set()
    for n, student in enumerate(STUDENTS):
        sign = 1 if n % 2 else -1
        for share, score in ((0.5, 7), (1.5, 0)):
            answers = _off(keys[student], share, sign, others)
            graded = _graded_by_otter(test_file, _submission(tmp_path, student, answers, "submission"))
            assert (graded.total, graded.possible) == (score, 7), (student, share, _passed(graded))
            wrong_marks |= {r.message for tf in graded.results.values() for r in tf.test_case_results
                            if not r.passed}
    # A failed item says which and why, never the key's value.
    assert wrong_marks and not [m for key in keys.values() for m in wrong_marks
                                for k in ("n_2max", "T_peak", "ED", "T_2m") if str(round(key[k], 2)) in m]
    right = _off(keys[STUDENTS[0]], 0.5, 1, others)
    mixed = {**right, **{k: v for k, v in _off(keys[STUDENTS[0]], 1.5, 1, others).items() if k in ("T_2m", "gearbox")}}
    path = _submission(tmp_path, STUDENTS[0], mixed, "mixed")
    whole = grade_submission(str(path), str(lecturer / "grading" / "autograder.zip"), quiet=True)
    assert _passed(whole) == _passed(_graded_by_otter(test_file, path))
    assert [name for name, ok in _passed(whole).items() if not ok] == ["T_2m", "gearbox"]


# -- what students receive -----------------------------------------------------------------------


NUMBER = re.compile(r"(?<![\w.])\d+\.\d+(?![\d])")


def _significant(number: str) -> int:
    return len(number.replace(".", "").lstrip("0"))


def _printed(notebook: dict) -> str:
    found = []
    for cell in notebook["cells"]:
        for out in cell.get("outputs", []):
            found.append("".join(out.get("text", "")))
            found += ["".join(v) for m, v in out.get("data", {}).items() if m.startswith("text/")]
    return "\n".join(found)


def test_the_students_material_holds_no_answer(tmp_path, students_book, monkeypatch):
    def book_built_already(into, lecturer, root=ROOT):
        # The students' book of this run (tests/conftest.py), as material.build_book leaves it: no pickled pages.
        assert not lecturer and root == ROOT
        shutil.copytree(students_book, into, symlinks=True, ignore=shutil.ignore_patterns(".doctrees"))

    monkeypatch.setattr(material, "build_book", book_built_already)
    out = material.build_student(tmp_path / "student", STUDENTS[:3], SEED, book=True)
    assert (out / "book" / "book" / "index.html").is_file()
    files = [p for p in out.rglob("*") if p.is_file()]
    names = {p.relative_to(out / "workbook").as_posix() for p in files if (out / "workbook") in p.parents}
    assert "notebooks/14-capstone.ipynb" in names and "calc/course/variants.py" in names
    assert not [n for n in names if not material.handed_out(n)]
    for student in STUDENTS[:3]:
        folder = out / "briefs" / student
        assert (folder / "brief.md").is_file() and (folder / "checkpoint.ipynb").is_file()
    text = {p: p.read_text(errors="ignore") for p in files if p.suffix in {".ipynb", ".md", ".html", ".toml", ".py",
                                                                           ".csv", ".txt", ".js", ".json"}}
    lecturers = [ROOT / p for p in material.repository_files() if not material.handed_out(p)
                 and p.startswith(("notebooks/instructor", "course/"))]
    assert not {(ROOT / p).read_bytes() for p in lecturers} & {p.read_bytes() for p in files}
    # The answers' values: what the lecturer's notebook prints, the checkpoint's keys and the
    # capstone's solution, at 4 significant digits or more; a value the students' notebooks print
    # themselves (the example's own numbers, from which an exercise starts) is not an answer.
    given = "\n".join(_printed(json.loads(p.read_text())) for p in (ROOT / "notebooks").glob("*.ipynb"))
    answers = set(NUMBER.findall(_printed(json.loads((ROOT / "notebooks/instructor/99-answers.ipynb").read_text()))))
    for student in STUDENTS[:3]:
        key = checkpoint.expected(variants.variant(student, SEED))
        answers |= {f"{key[i]:.4g}" for i in ("T_peak", "T_2m") if not math.isclose(key[i], round(key[i]))}
    from calc.sections import evaluate
    from calc.sections.case import read_case

    solved = evaluate(read_case(ROOT / "course" / "capstone-solution.toml")).to_json()
    answers |= {f"{solved['cyclic']['T2max']['value']:.4g}", f"{solved['continuous']['T2m']['value']:.4g}",
                f"{solved['motor']['rms_torque_required']['value']:.4g}"}
    answers = {a for a in answers if _significant(a) >= 4 and a not in set(NUMBER.findall(given))}
    assert len(answers) > 50
    any_answer = re.compile(rf"(?<![\w.])({'|'.join(map(re.escape, sorted(answers, key=len, reverse=True)))})(?!\d)")
    leaks = sorted({f"{p.relative_to(out)}: {a}" for p, t in text.items() for a in any_answer.findall(t)})
    assert leaks == []
    planted = sorted(answers)[0]  # the search finds an answer pasted into the students' material
    assert any_answer.findall(f"as the lecturer's notebook prints: {planted} N·m") == [planted]
    for p, t in text.items():
        if p.suffix in {".ipynb", ".html"} and "notebooks" in p.parts:
            assert "99-answers" not in t and "instructor/" not in t, p


# -- bad input ------------------------------------------------------------------------------------


def test_bad_input_gets_one_sentence_naming_it(tmp_path):
    bad = tmp_path / "roster.csv"
    with pytest.raises(CalcError, match="expected a roster file"):
        material.roster(tmp_path / "none.csv")
    bad.write_text("name\nAda\n")
    with pytest.raises(CalcError, match=r"expected a CSV with a column student, found columns \['name'\]"):
        material.roster(bad)
    bad.write_text("student\nAda\nAda\n")
    with pytest.raises(CalcError, match=r"expected each student once and none empty, found \['Ada'\]"):
        material.roster(bad)
    with pytest.raises(CalcError, match="expected a git checkout"):
        material.repository_files(tmp_path)
    with pytest.raises(CalcError, match="expected the book to build"):
        material.build_book(tmp_path / "book", lecturer=False, root=tmp_path)
    with pytest.raises(CalcError, match="expected otter to build the autograder"):
        material.autograder(tmp_path / "no-tests", tmp_path / "autograder.zip")
    with pytest.raises(CalcError, match="STUDENT: expected your name"):
        checkpoint.student_of({"STUDENT": " "})
    with pytest.raises(CalcError, match="expected a notebook with a self-check"):
        selfcheck.score(tmp_path / "none.ipynb", {})
