"""``python -m calc export`` and ``python -m calc import``: the files written only once everything
they hold was built and verified, so that a bad input leaves nothing behind."""

from __future__ import annotations

from pathlib import Path

from ..core.errors import CalcError
from ..sections import evaluate
from ..sections.case import read_case
from . import aasx_beside
from .build import export_environment
from .package import open_aas, write_aasx, write_json
from .reader import import_case


def export_beside(case: Path) -> Path:
    """The case's IDTA 02021 AASX written beside the case file (``case.aasx``), for the review page.

    Parameters
    ----------
    case : pathlib.Path
        The case file.

    Returns
    -------
    pathlib.Path
        The AASX written.

    Raises
    ------
    CalcError
        For a case that cannot be read or evaluated, or a file that cannot be written.
    """
    out = aasx_beside(case)
    exported = export_environment(evaluate(read_case(case)), in_package=True)
    try:
        return write_aasx(exported, out)
    except OSError as exc:
        raise CalcError(f"{out}: the AASX cannot be written ({exc.strerror})") from None


def run_exchange(args) -> str:
    """Run ``export`` or ``import`` with the parsed command line.

    Parameters
    ----------
    args : argparse.Namespace
        ``command`` and its options (``case``, ``aas``, ``aasx``, ``report``; or ``file``, ``output``).

    Returns
    -------
    str
        What was written, one file a line.

    Raises
    ------
    CalcError
        For bad input, naming the file and what is wrong.
    """
    if args.command == "export":
        if not (args.aas or args.aasx):
            raise CalcError("export: expected --aas OUT.json or --aasx OUT.aasx, found neither")
        results = evaluate(read_case(args.case))
        report = Path(args.report) if args.report else None
        if report is not None and not report.is_file():
            raise CalcError(f"export: --report {args.report}: expected a calc report PDF, found no file")
        written = []
        if args.aas:
            written += write_json(export_environment(results), Path(args.aas))
        if args.aasx:
            written.append(write_aasx(export_environment(results, report, in_package=True), Path(args.aasx)))
        return "\n".join(f"wrote {p}" for p in written)
    out = Path(args.output)
    record = out.with_name(f"{out.stem}.record.csv")
    imported = import_case(open_aas(Path(args.file)), record.name)
    out.write_text(imported.case, encoding="utf-8")
    record.write_text(imported.record, encoding="utf-8")
    return f"wrote {out}\nwrote {record}"
