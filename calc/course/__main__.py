"""``python -m calc.course student|lecturer``: build what students receive or what the lecturer
keeps (:mod:`calc.course.material`), for a roster and the course's seed."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..core.errors import CalcError
from .material import ROOT, build_lecturer, build_student, roster


def main(argv=None) -> int:
    """Build the students' or the lecturer's material.

    Parameters
    ----------
    argv : list of str, optional
        The command line (``sys.argv[1:]`` when not given).

    Returns
    -------
    int
        0 when built, 2 on bad input (the message on standard error).
    """
    parser = argparse.ArgumentParser(prog="python -m calc.course", description=__doc__.split("\n\n")[0])
    parser.add_argument("who", choices=("student", "lecturer"), help="whose material to build")
    parser.add_argument("--roster", type=Path, default=ROOT / "course" / "roster.csv",
                        help="CSV with a column student (default: course/roster.csv)")
    parser.add_argument("--seed", type=int, default=2026, help="the course's seed: a new one, new briefs")
    parser.add_argument("-o", "--output", type=Path, help="folder to write (default: build/<who>)")
    parser.add_argument("--no-book", action="store_true", help="leave the book out")
    args = parser.parse_args(argv)
    into = args.output or ROOT / "build" / args.who
    build = build_student if args.who == "student" else build_lecturer
    try:
        build(into, roster(args.roster), args.seed, book=not args.no_book)
    except CalcError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(f"the {args.who}s' material: {into}" if args.who == "student" else f"the lecturer's material: {into}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
