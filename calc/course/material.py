"""What students receive and what the lecturer keeps, built from the repository.

``make student`` (:func:`build_student`): the workbook without the lecturer's files (the worked
answers, the grading files, the capstone's solution), the students' book, and for each student of
the roster a folder with their own brief and their checkpoint notebook. ``make lecturer``
(:func:`build_lecturer`): the lecturer's book (the answers included), the autograder (an Otter
zip of the checkpoint's test file, seeded as the students' briefs were), each student's key and
case file, and the capstone's solution.
"""

from __future__ import annotations

import contextlib
import csv
import fnmatch
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat

from ..core.errors import CalcError
from .checkpoint import ITEMS, expected
from .variants import brief_markdown, briefs, case_text

ROOT = Path(__file__).resolve().parents[2]
#: The lecturer's files: never in what students receive.
LECTURER_ONLY = (
    "notebooks/instructor/*",    # the worked answers of every exercise
    "course/grading/*",          # the autograder's test file
    "course/capstone-solution*",  # the capstone's case file, solved
    "book/lecturer*",            # the lecturer's book's front page
)
#: The repository's development files, which a student does not need to run the course.
NOT_FOR_COURSE = ("tests/*", "bench/*", ".ci/*", ".git*")


def roster(path: Path) -> list[str]:
    """The students of a roster file: a CSV with a column ``student``.

    Parameters
    ----------
    path : pathlib.Path
        The roster file.

    Returns
    -------
    list of str
        The students' names or ids, in the file's order.
    """
    try:
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
    except OSError as exc:
        raise CalcError(f"{path}: expected a roster file (CSV with a column student), found none ({exc.strerror})")
    if not rows or "student" not in rows[0]:
        raise CalcError(f"{path}: expected a CSV with a column student, found columns {list(rows[0]) if rows else []}")
    names = [r["student"].strip() for r in rows]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice or "" in names:
        raise CalcError(f"{path}: expected each student once and none empty, found {twice or 'an empty name'}")
    return names


def handed_out(path: str) -> bool:
    """Whether a repository file goes to the students.

    Parameters
    ----------
    path : str
        The file's path in the repository, with ``/``.

    Returns
    -------
    bool
        False for the lecturer's files and the development files.

    Examples
    --------
    >>> handed_out("notebooks/02-duty-cycle.ipynb"), handed_out("notebooks/instructor/99-answers.ipynb")
    (True, False)
    """
    return not any(fnmatch.fnmatch(path, p) for p in LECTURER_ONLY + NOT_FOR_COURSE)


def repository_files(root: Path = ROOT) -> list[str]:
    """The repository's files as a clean clone has them (``git ls-files``).

    Parameters
    ----------
    root : pathlib.Path
        The repository.

    Returns
    -------
    list of str
        Their paths, with ``/``.
    """
    run = subprocess.run(["git", "ls-files", "-z"], cwd=root, capture_output=True)
    if run.returncode:
        raise CalcError(f"{root}: expected a git checkout of the workbook, found none ({run.stderr.decode().strip()})")
    return [p for p in run.stdout.decode().split("\0") if p and (root / p).is_file()]


def checkpoint_notebook(student: str) -> nbformat.NotebookNode:
    """A student's checkpoint notebook: their name set, one cell of answers to fill in.

    Parameters
    ----------
    student : str
        The student's name or id.

    Returns
    -------
    nbformat.NotebookNode
        The notebook (not executed).
    """
    items = "\n".join(f"* `{i.name}`: {i.question} (notebook {i.notebook})" for i in ITEMS)
    answers = "\n".join(f"{i.name} = ...  # {i.question}" for i in ITEMS)
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nb.cells = [
        nbformat.v4.new_markdown_cell(
            f"# Checkpoint: your own indexing table\n\nWork the brief beside this notebook (`brief.md`): write its "
            f"case file, evaluate it, and set each value below, a number in the unit asked or a part's name. "
            f"Run every cell, save, and hand in this notebook. The autograder compares each number with the "
            f"package's for your brief, within 1 % or 2 %.\n\n{items}"
        ),
        nbformat.v4.new_code_cell(f'STUDENT = "{student}"  # as on your brief: do not change it'),
        nbformat.v4.new_code_cell(answers),
    ]
    return nb


def _copy(root: Path, files, into: Path) -> None:
    for name in files:
        target = into / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(root / name, target)


def build_book(into: Path, lecturer: bool, root: Path = ROOT) -> None:
    """The course as a static website (Sphinx, warnings as errors), the lecturer's or the students'.

    Parameters
    ----------
    into : pathlib.Path
        The folder the website is written to.
    lecturer : bool
        Whether it is the lecturer's book (the worked answers and the grading notes included).
    root : pathlib.Path
        The repository.

    Returns
    -------
    None
    """
    tags = ["-t", "lecturer"] if lecturer else []
    run = subprocess.run([sys.executable, "-m", "sphinx", "-q", "-W", "--keep-going", *tags, "-c", "book", ".",
                          str(into)], cwd=root, capture_output=True, text=True)
    if run.returncode:
        raise CalcError(f"book/conf.py: expected the book to build, found errors: {run.stderr.strip()[:200]}")
    # MyST-NB's copies of the notebooks beside the book and Sphinx's pickled pages in it: not for reading.
    shutil.rmtree(into.parent / "jupyter_execute", ignore_errors=True)
    shutil.rmtree(into / ".doctrees", ignore_errors=True)


def build_student(into: Path, students: list[str], seed: int, book: bool = True, root: Path = ROOT) -> Path:
    """What students receive: the workbook without the lecturer's files, the students' book, and
    each student's brief and checkpoint notebook (``briefs/<student>/``).

    Parameters
    ----------
    into : pathlib.Path
        The folder to write (emptied first).
    students : list of str
        The roster.
    seed : int
        The course's seed (:func:`calc.course.variants.variant`).
    book : bool
        Whether to build the book too.
    root : pathlib.Path
        The repository.

    Returns
    -------
    pathlib.Path
        ``into``.
    """
    shutil.rmtree(into, ignore_errors=True)
    _copy(root, [f for f in repository_files(root) if handed_out(f)], into / "workbook")
    for v in briefs(students, seed):
        folder = into / "briefs" / v.student
        folder.mkdir(parents=True)
        (folder / "brief.md").write_text(brief_markdown(v), encoding="utf-8")
        nbformat.write(checkpoint_notebook(v.student), folder / "checkpoint.ipynb")
    if book:
        build_book(into / "book", lecturer=False, root=root)
    return into


def grading_test_file(seed: int, root: Path = ROOT) -> str:
    """The autograder's test file (Otter's exception-based format) with the course's seed.

    Parameters
    ----------
    seed : int
        The course's seed the students' briefs were drawn with.
    root : pathlib.Path
        The repository.

    Returns
    -------
    str
        The Python text of ``checkpoint.py``.
    """
    template = (root / "course" / "grading" / "checkpoint.py").read_text(encoding="utf-8")
    return template.replace("SEED = 0  # set by the lecturer's build", f"SEED = {int(seed)}")


def autograder(tests: Path, zipped: Path) -> Path:
    """The autograder Otter-Grader builds from a folder of test files (``otter generate``).

    Parameters
    ----------
    tests : pathlib.Path
        The folder of the test files.
    zipped : pathlib.Path
        The zip file to write.

    Returns
    -------
    pathlib.Path
        ``zipped``.
    """
    from otter.generate import main as generate

    # Absolute paths: otter is run in the zip's folder, where a path relative to ours would not resolve.
    tests, zipped = tests.resolve(), zipped.resolve()
    problem = "" if tests.is_dir() and any(tests.glob("*.py")) else "no test file (*.py) there"
    if not problem:
        # In this process (a second interpreter's imports cost seconds), with no otter_config.json,
        # requirements.txt or environment.yml taken from the working folder: the zip holds the test files.
        try:
            with contextlib.chdir(zipped.parent):
                generate(tests_dir=str(tests), output_path=str(zipped), no_config=True, no_requirements=True,
                         no_environment=True)
        except (OSError, ValueError) as exc:
            problem = str(exc)
    if problem or not zipped.is_file():
        raise CalcError(f"{tests}: expected otter to build the autograder from its test files, found: "
                        f"{(problem or 'no zip written')[-160:]}")
    return zipped


def build_lecturer(into: Path, students: list[str], seed: int, book: bool = True, root: Path = ROOT) -> Path:
    """What the lecturer keeps: the autograder, each student's key and case file, the capstone's
    solution and the lecturer's book.

    Parameters
    ----------
    into : pathlib.Path
        The folder to write (emptied first).
    students : list of str
        The roster.
    seed : int
        The course's seed.
    book : bool
        Whether to build the book too.
    root : pathlib.Path
        The repository.

    Returns
    -------
    pathlib.Path
        ``into``.
    """
    shutil.rmtree(into, ignore_errors=True)
    tests = into / "grading" / "tests"
    tests.mkdir(parents=True)
    (tests / "checkpoint.py").write_text(grading_test_file(seed, root), encoding="utf-8")
    autograder(tests, into / "grading" / "autograder.zip")
    (into / "cases").mkdir()
    with open(into / "grading" / "keys.csv", "w", newline="", encoding="utf-8") as f:
        out = csv.writer(f)
        out.writerow(["student", *(i.name for i in ITEMS)])
        for v in briefs(students, seed):
            key = expected(v)
            out.writerow([v.student, *(key[i.name] for i in ITEMS)])
            (into / "cases" / f"{v.student}.toml").write_text(case_text(v), encoding="utf-8")
    _copy(root, [f for f in repository_files(root) if fnmatch.fnmatch(f, "course/capstone-solution*")], into)
    if book:
        build_book(into / "book", lecturer=True, root=root)
    return into
