"""Calc reports as PDF: ``python -m calc report CASE.toml [CASE2.toml ...] [-o reports/NAME.pdf] [--summary]``.

For each case the report notebook (``reports/calc-report.ipynb``) is executed by papermill with the
case as its parameter, then exported by nbconvert through xelatex with the code hidden, using our
LaTeX template (``reports/template/calc-report``). A progress bar runs over the cases; at the end
one line per case gives its verdict and its PDF. A case that fails its checks, or cannot be
evaluated, still gets its PDF (saying FAIL and why); only a PDF that cannot be built is an error.
With ``--summary`` the output folder also gets ``summary.pdf`` and ``summary.csv``: one row per
case (:mod:`calc.report.summary`), the rows :func:`summary_rows` gives the design review.
"""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

from .catalog import display_path, package_folder
from .errors import CalcError

#: The report notebook and template: package data ``calc.reports`` (the project's ``reports/``).
REPORTS_DIR = package_folder("reports")
NOTEBOOK = REPORTS_DIR / "calc-report.ipynb"
TEMPLATE_DIRS = [str(REPORTS_DIR / "template")]
TEMPLATE = "calc-report"
#: The programs the PDF needs and where they come from (Debian package names).
TOOLS = {"xelatex": "texlive-xetex", "pandoc": "pandoc"}
#: The summary's files in the output folder (``--summary``).
SUMMARY = "summary"


def check_tools() -> None:
    """Raise :class:`CalcError` naming each missing program and what to install."""
    missing = [f"{tool} ({package})" for tool, package in TOOLS.items() if shutil.which(tool) is None]
    if missing:
        raise CalcError(
            f"the PDF report needs {', '.join(missing)}, not found on this machine; on Debian run `make report` as root "
            "(it installs them), elsewhere install a TeX distribution with XeLaTeX, pandoc and the DejaVu fonts"
        )


def output_paths(cases: list[Path], output: str | None) -> list[Path]:
    """Where each case's PDF goes: ``reports/<case name>.pdf``, or ``output`` (a file for one case,
    a folder for several)."""
    if output is None:
        paths = [Path("reports") / f"{c.stem}.pdf" for c in cases]
    elif len(cases) == 1 and output.endswith(".pdf"):
        paths = [Path(output)]
    elif output.endswith(".pdf"):
        raise CalcError(f"-o {output}: with {len(cases)} cases, expected a folder for their PDFs, found a file name")
    else:
        paths = [Path(output) / f"{c.stem}.pdf" for c in cases]
    seen = {}
    for case, pdf in zip(cases, paths):
        if pdf in seen:
            raise CalcError(f"{case}: its report {pdf} would overwrite the report of {seen[pdf]}; give the case files distinct names")
        seen[pdf] = case
    return paths


def summary_folder(cases: list[Path], output: str | None) -> Path:
    """The folder of the reports and the summary (``--summary``): ``output``, default ``reports/``;
    no case's report may take the summary's name."""
    if output is not None and output.endswith(".pdf"):
        raise CalcError(f"-o {output}: with --summary, expected a folder for the reports and {SUMMARY}.pdf, found a file name")
    folder = Path("reports" if output is None else output)
    for case in cases:
        if case.stem == SUMMARY:
            raise CalcError(f"{case}: its report {folder / (SUMMARY + '.pdf')} would be overwritten by the summary; "
                            "rename the case file")
    return folder


def summary_rows(cases, output: str | None = None) -> list[dict]:
    """The summary's rows of ``cases`` (paths of case files), plain data (:func:`calc.report.summary.summary_row`),
    each with the path its report has (or would have) in ``output`` (a folder, default ``reports/``);
    no PDF is built. A case that cannot be read gets a row saying why."""
    from .report import build_report
    from .report.summary import summary_row

    paths = [Path(c) for c in cases]
    return [summary_row(build_report(c), pdf) for c, pdf in zip(paths, output_paths(paths, str(summary_folder(paths, output))))]


def exporter():
    """nbconvert's PDF exporter with our template, code and prompts hidden."""
    from nbconvert import PDFExporter
    from traitlets.config import Config

    c = Config()
    c.PDFExporter.extra_template_basedirs = TEMPLATE_DIRS
    c.PDFExporter.template_name = TEMPLATE
    c.PDFExporter.exclude_input = True
    c.PDFExporter.exclude_input_prompt = True
    c.PDFExporter.exclude_output_prompt = True
    c.TagRemovePreprocessor.enabled = True
    c.TagRemovePreprocessor.remove_cell_tags = {"remove"}
    return PDFExporter(config=c)


def render_pdf(case: Path, pdf: Path, workdir: Path) -> None:
    """Execute the report notebook for ``case`` and write its PDF to ``pdf``.

    The kernel talks over local sockets in ``workdir`` (IPC), not over TCP.
    """
    import papermill
    from jupyter_client.manager import KernelManager
    from nbconvert.exporters.pdf import LatexFailed

    executed = workdir / f"{pdf.stem}.ipynb"
    km = KernelManager(kernel_name="python3", transport="ipc", ip=str(workdir / "kernel"))
    try:
        nb = papermill.execute_notebook(
            str(NOTEBOOK), str(executed), parameters={"case": str(case.resolve())},
            cwd=str(NOTEBOOK.parent), progress_bar=False, log_output=False, kernel_name="python3", km=km,
        )
    except papermill.PapermillExecutionError as exc:
        raise CalcError(f"{case}: the report notebook stopped: {exc.ename}: {exc.evalue}") from None
    finally:
        if km.has_kernel:  # a kernel manager handed to papermill is ours to shut down
            km.shutdown_kernel()
    try:
        body, _ = exporter().from_notebook_node(nb, resources={"metadata": {"name": pdf.stem}})
    except LatexFailed as exc:
        tail = "\n".join(exc.output.splitlines()[-15:])
        raise CalcError(f"{case}: xelatex could not typeset the report:\n{tail}") from None
    pdf.parent.mkdir(parents=True, exist_ok=True)
    pdf.write_bytes(body)


def render_summary(rows: list[dict], reports: list, folder: Path) -> tuple[Path, Path]:
    """Write ``summary.pdf`` and ``summary.csv`` of ``rows`` into ``folder``; the PDF goes through
    the reports' own template (a notebook of one output, nothing executed)."""
    import nbformat
    from nbconvert.exporters.pdf import LatexFailed

    from .report.provenance import build_date, git_commit
    from .report.summary import summary_latex, write_csv

    pdf, table = folder / f"{SUMMARY}.pdf", folder / f"{SUMMARY}.csv"
    write_csv(rows, table)
    latex = summary_latex(rows, reports, build_date(), git_commit())
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(outputs=[
        nbformat.v4.new_output("display_data", data={"text/latex": str(latex)})])])
    try:
        body, _ = exporter().from_notebook_node(nb, resources={"metadata": {"name": SUMMARY}})
    except LatexFailed as exc:
        tail = "\n".join(exc.output.splitlines()[-15:])
        raise CalcError(f"{pdf}: xelatex could not typeset the summary:\n{tail}") from None
    pdf.write_bytes(body)
    return pdf, table


def main(cases: list[str], output: str | None = None, strict: bool = False, summary: bool = False) -> int:
    """Build one PDF per case with a progress bar; print one line per case; with ``summary``, also
    the summary's PDF and CSV in the output folder.

    Exit status (``docs/case-format.md``): 2 when a case could not be read or a PDF could not be
    built (a report of an unreadable case is still written, saying why), else 1 with ``strict``
    when a verdict is not PASS, else 0."""
    from tqdm import tqdm

    from .report import build_report
    from .report.summary import counts_text, summary_row

    paths = [Path(c) for c in cases]
    try:
        for p in paths:
            if not p.is_file():
                raise CalcError(f"{p}: the case file does not exist")
        if summary:
            output = str(summary_folder(paths, output))
        pdfs = output_paths(paths, output)
        check_tools()
    except CalcError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    lines, input_errors, not_passing, reports, rows = [], 0, 0, [], []
    with tempfile.TemporaryDirectory(prefix="calc-report-") as tmp:
        for case, pdf in zip(tqdm(paths, desc="calc reports", unit="case", file=sys.stderr), pdfs):
            report = build_report(case)
            try:
                render_pdf(case, pdf, Path(tmp))
            except CalcError as exc:
                input_errors += 1
                lines.append(f"ERROR {display_path(case)}: no PDF: {exc}")
                pdf = None
            else:
                input_errors += report.error is not None
                not_passing += report.verdict.passes is not True
                lines.append(f"{report.summary_line()}  ->  {pdf}")
            reports.append(report)
            rows.append(summary_row(report, pdf))
    if summary:
        try:
            written = render_summary(rows, reports, Path(output))
        except CalcError as exc:
            input_errors += 1
            lines.append(f"ERROR no summary: {exc}")
        else:
            lines.append(f"{counts_text(rows)}  ->  {'  '.join(map(str, written))}")
    print("\n".join(lines))
    if input_errors:
        return 2
    return 1 if strict and not_passing else 0
