"""Command line: ``python -m calc evaluate CASE.toml [--json] [--strict] [--all-candidates]``,
``python -m calc ratios CASE.toml [--json] [--strict]`` (the case at every ratio of its gearbox
catalog, and the ratio to pick) and
``python -m calc report CASE.toml [CASE2.toml ...] [-o reports/NAME.pdf] [--strict] [--summary]`` and
``python -m calc compare A.toml B.toml [...] [--json] [--pdf FILE]`` (the designs side by side).

Exit status (``docs/case-format.md``): 0 when results were produced, whatever the verdict; with
``--strict``, 1 when the verdict is not PASS (for ``ratios``: when no ratio can be picked); 2 on
input errors, always.
"""

from __future__ import annotations

import argparse
import json
import os
import sys

import numpy as np

from .core.errors import CalcError


def main(argv=None) -> int:
    """Run one command of the command line.

    Parameters
    ----------
    argv : list of str, optional
        The arguments after ``python -m calc`` (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit status: 0 when results were produced, 1 with ``--strict`` when a verdict is not PASS,
        2 on input errors.
    """
    parser = argparse.ArgumentParser(prog="python -m calc", description="Servo drive-train sizing workbook.")
    sub = parser.add_subparsers(dest="command", required=True)
    ev = sub.add_parser("evaluate", help="evaluate a design case and print its results")
    ev.add_argument("case", help="the design-case TOML file")
    ev.add_argument("--json", action="store_true",
                    help="print the results as JSON (the contract of docs/case-format.md)")
    ev.add_argument("--all-candidates", action="store_true",
                    help="list every candidate (default: the best 20 and the count)")
    ra = sub.add_parser("ratios", help="evaluate a design case at every ratio of its gearbox catalog and pick one")
    ra.add_argument("case", help="the design-case TOML file")
    ra.add_argument("--json", action="store_true", help="print the results as JSON")
    co = sub.add_parser("combinations", help="every motor of the case's motor catalog with every gearbox at every "
                                             "ratio: the feasible pairs and the pick")
    co.add_argument("case", help="the design-case TOML file (with [motor] catalog and [gearbox] catalog)")
    co.add_argument("--json", action="store_true", help="print the results as JSON")
    co.add_argument("--figure", metavar="FILE",
                    help="also draw the motors against the ratios (PDF, PNG or SVG, by the file's suffix)")
    rp = sub.add_parser("report", help="build the PDF calc report of one or more design cases")
    rp.add_argument("cases", nargs="+", metavar="case", help="design-case TOML files, one PDF each")
    rp.add_argument("-o", "--output",
                    help="the PDF file (one case) or the folder (several); default reports/<case name>.pdf")
    rp.add_argument("--summary", action="store_true",
                    help="also write summary.pdf and summary.csv in the output folder: one row per case")
    rp.add_argument("-j", "--jobs", type=int, metavar="N",
                    help="build N reports at a time (default: the number of cores)")
    cp = sub.add_parser("compare",
                        help="compare design cases side by side (verdict, chosen parts, utilizations, key results)")
    cp.add_argument("cases", nargs="+", metavar="case", help="design-case TOML files, one column each")
    cp.add_argument("--json", action="store_true", help="print the table as JSON")
    cp.add_argument("--pdf", help="also write the table and a comparison figure as a PDF file")
    ex = sub.add_parser("export", help="write a case and its results as an IDTA 02021 submodel (AAS JSON or AASX)")
    ex.add_argument("case", help="the design-case TOML file")
    ex.add_argument("--aas", metavar="OUT.json",
                    help="write AAS JSON (metamodel V3.0), the motion pattern's CSV beside it")
    ex.add_argument("--aasx", metavar="OUT.aasx", help="write an AASX package with the case file and the CSV inside")
    ex.add_argument("--report", metavar="PDF", help="a calc report built of the case, carried in the AASX")
    im = sub.add_parser("import", help="write a case file from an IDTA 02021 submodel (AAS JSON or AASX)")
    im.add_argument("file", help="the .json or .aasx file")
    im.add_argument("-o", "--output", required=True, metavar="CASE.toml",
                    help="the case file to write; its drive record is written beside it")
    for p in (ev, ra, co, rp):
        p.add_argument("--strict", action="store_true", help="exit 1 when a verdict is not PASS")
    args = parser.parse_args(argv)
    # Nothing but the results and the one-line error reach the terminal: numpy's floating-point
    # warnings are not printed (a non-finite result is an input error naming where it came from,
    # calc.sections.common.number; the loaders hold every value within calc.core.units.SI_SCALE).
    with np.errstate(all="ignore"):
        return _run(args)


def _run(args) -> int:
    if args.command == "report":
        from .report.publish import main as report

        return report(args.cases, args.output, strict=args.strict, summary=args.summary, jobs=args.jobs)

    from .sections.case import read_case
    from .sections import SHOWN_CANDIDATES, evaluate

    try:
        if args.command == "compare":
            from .review.view import compare_cases

            print(compare_cases(args.cases, args.json, args.pdf))
            return 0
        if args.command in ("export", "import"):
            from .exchange.command import run_exchange

            print(run_exchange(args))
            return 0
        if args.command == "combinations":
            from .sections.pairs import search_pairs

            results = search_pairs(read_case(args.case))
            text = _json(results.to_json()) if args.json else results.summary()
            passes = results.verdict().passes
            if args.figure:
                results.figure().savefig(args.figure)
        elif args.command == "ratios":
            from .sections.ratios import search

            results = search(read_case(args.case))
            text = _json(results.to_json()) if args.json else results.summary()
            passes = results.verdict().passes
        else:
            candidates = None if args.all_candidates else SHOWN_CANDIDATES
            results = evaluate(read_case(args.case))
            text = _json(results.to_json(candidates)) if args.json else results.summary(candidates)
            passes = results.verdict.passes
    except CalcError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(text)
    return 1 if args.strict and passes is not True else 0


def _json(results: dict) -> str:
    # NaN or infinity in the results is a defect, not valid JSON to print.
    return json.dumps(results, indent=2, ensure_ascii=False, allow_nan=False)


def run_quietly_into_a_closed_pipe(argv=None) -> int:
    """Run :func:`main`, ending quietly when the reader of standard output goes away
    (``python -m calc evaluate case.toml | head -1``).

    Parameters
    ----------
    argv : list of str, optional
        The arguments after ``python -m calc`` (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        :func:`main`'s exit status, or 1 when standard output was closed (as the Python docs use).

    Notes
    -----
    Python ignores SIGPIPE, so a write to a closed pipe raises BrokenPipeError, and again at exit
    when it flushes standard output; as the Python docs' note on SIGPIPE advises, standard output
    then points at devnull.
    """
    try:
        code = main(argv)
        sys.stdout.flush()  # inside the try: a closed pipe shows here, not at exit
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    return code


if __name__ == "__main__":
    sys.exit(run_quietly_into_a_closed_pipe())
