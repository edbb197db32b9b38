"""Calc reports as PDF: ``python -m calc report CASE.toml [CASE2.toml ...] [-o reports/NAME.pdf]
[--summary]``.

For each case the report's blocks (:meth:`calc.report.Report.blocks`, what the report notebook
``reports/calc-report.ipynb`` shows when run) become a notebook in this process, with no kernel,
which nbconvert exports through xelatex with our LaTeX template (``reports/template/calc-report``).
Several cases are built at a time (``-j``, default the number of cores). A progress bar runs over
the cases; at the end one line per case gives its verdict and its PDF. A case that fails its checks, or cannot be
evaluated, still gets its PDF (saying FAIL and why); only a PDF that cannot be built is an error.
With ``--summary`` the output folder also gets ``summary.pdf`` and ``summary.csv``: one row per
case (:mod:`calc.report.summary`), the rows :func:`summary_rows` gives the design review.
"""

from __future__ import annotations

import contextlib
import shutil
import sys
from pathlib import Path

from ..data.catalog import display_path, package_folder
from ..core.errors import CalcError, listing

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
    """Check that the programs the PDF needs (:data:`TOOLS`) are installed.

    Returns
    -------
    None

    Raises
    ------
    CalcError
        Naming each missing program and what to install.
    """
    missing = [f"{tool} ({package})" for tool, package in TOOLS.items() if shutil.which(tool) is None]
    if missing:
        raise CalcError(
            f"the PDF report needs {listing(missing)}, not found on this machine; on Debian run `make report` "
            "as root (it installs them), elsewhere install a TeX distribution with XeLaTeX, pandoc and the DejaVu "
            "fonts"
        )


def output_paths(cases: list[Path], output: str | None) -> list[Path]:
    """Where each case's PDF goes.

    Parameters
    ----------
    cases : list of pathlib.Path
        The case files.
    output : str or None
        The ``-o`` argument: a file for one case, a folder for several; None for ``reports/``.

    Returns
    -------
    list of pathlib.Path
        One PDF per case, ``reports/<case name>.pdf`` by default.

    Raises
    ------
    CalcError
        For a file name with several cases, or two cases whose reports would take the same name.
    """
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
            raise CalcError(f"{case}: its report {pdf} would overwrite the report of {seen[pdf]}; "
                            "give the case files distinct names")
        seen[pdf] = case
    return paths


def summary_folder(cases: list[Path], output: str | None) -> Path:
    """The folder of the reports and the summary (``--summary``).

    Parameters
    ----------
    cases : list of pathlib.Path
        The case files.
    output : str or None
        The ``-o`` argument, a folder; None for ``reports/``.

    Returns
    -------
    pathlib.Path
        The folder.

    Raises
    ------
    CalcError
        For a file name, or a case whose report would take the summary's name.
    """
    if output is not None and output.endswith(".pdf"):
        raise CalcError(f"-o {output}: with --summary, expected a folder for the reports and {SUMMARY}.pdf, "
                        "found a file name")
    folder = Path("reports" if output is None else output)
    for case in cases:
        if case.stem == SUMMARY:
            raise CalcError(f"{case}: its report {folder / (SUMMARY + '.pdf')} would be overwritten by the summary; "
                            "rename the case file")
    return folder


def summary_rows(cases, output: str | None = None) -> list[dict]:
    """The summary's rows of several cases, plain data (:func:`calc.report.summary.summary_row`); no
    PDF is built.

    Parameters
    ----------
    cases : iterable of str or pathlib.Path
        The case files.
    output : str, optional
        The folder of the reports (default ``reports/``).

    Returns
    -------
    list of dict
        One row per case, each with the path its report has (or would have) in ``output``; a case
        that cannot be read gets a row saying why.
    """
    from . import build_report
    from .summary import summary_row

    paths = [Path(c) for c in cases]
    pdfs = output_paths(paths, str(summary_folder(paths, output)))
    return [summary_row(build_report(c), pdf) for c, pdf in zip(paths, pdfs)]


def _without_iri_grammars() -> None:
    """Keep jsonschema (imported by nbformat, which nbconvert imports) from compiling the IRI
    grammars of rfc3987_syntax, when that is installed: some 40 of them, 2 s of CPU at every
    import, for a format check that no notebook's schema uses. Done once, as this module is
    imported, before any import of nbconvert; a process that imported jsonschema already keeps
    what it has.
    """
    if "jsonschema" not in sys.modules:
        sys.modules.setdefault("rfc3987_syntax", None)


_without_iri_grammars()


#: What xelatex writes to its log when a second pass would set the document differently (page
#: references, longtable's column widths).
RERUN = ("Rerun to get", "Rerun LaTeX", "Label(s) may have changed", "There were undefined references")


#: Where the report template's preamble ends: what comes before is the same for every report and
#: compiled once into a format (mylatexformat); what comes after (the fonts, which XeTeX cannot
#: keep in a format) is read on every pass.
END_OF_DUMP = r"\csname endofdump\endcsname"


def compiled_preamble(tex: Path) -> Path | None:
    """The xelatex format of a file's preamble (before :data:`END_OF_DUMP`), compiled on first use
    into the Python environment (beside pint's cache), one per preamble and TeX installation; it
    saves loading every package on every pass (about a third of each).

    Parameters
    ----------
    tex : pathlib.Path
        The LaTeX file nbconvert writes.

    Returns
    -------
    pathlib.Path or None
        The format, without its suffix (as ``-fmt`` takes it). None (xelatex reads the preamble
        itself) where the file has no such mark, the folder is not writable or the format cannot be
        made (then a marker beside it says so, and no later report tries again with this preamble
        and TeX).
    """
    import hashlib
    import os
    import subprocess
    import tempfile

    text = tex.read_text(encoding="utf-8")
    if END_OF_DUMP not in text or shutil.which("xelatex") is None:
        return None
    base = subprocess.run(["kpsewhich", "xelatex.fmt"], capture_output=True, text=True).stdout.strip()
    installed = f"{base} {os.stat(base).st_mtime_ns}" if base else ""  # a TeX update remakes xelatex.fmt
    key = hashlib.sha256((text[:text.index(END_OF_DUMP)] + installed).encode()).hexdigest()[:16]
    folder = Path(sys.prefix) / "latex-formats"
    fmt = folder / f"report-{key}.fmt"
    if fmt.is_file():
        return fmt.with_suffix("")
    failed = fmt.with_suffix(".failed")
    if failed.is_file():
        return None
    if not os.access(folder if folder.exists() else sys.prefix, os.W_OK):
        return None
    folder.mkdir(exist_ok=True)
    with tempfile.TemporaryDirectory(dir=folder) as work:
        subprocess.run(["xelatex", "-ini", "-interaction=batchmode", f"-jobname={fmt.stem}", "&xelatex",
                        "mylatexformat.ltx", str(tex.resolve())], cwd=work, capture_output=True)
        made, log = Path(work) / fmt.name, (Path(work) / fmt.stem).with_suffix(".log")
        errors = ([line for line in log.read_text(errors="replace").splitlines() if line.startswith("! ")]
                  if log.is_file() else ["no log"])
        # The only errors allowed: the kernel's own Latin Modern fonts, which a format cannot keep
        # (XeTeX loads fonts natively); the report sets its fonts after the format, so never uses them.
        fonts = r"! Can't \dump a format with native fonts or font-mappings."
        if not made.is_file() or any(e != fonts for e in errors):
            failed.write_text("\n".join(errors[:20]) + "\n", encoding="utf-8")  # what xelatex said, for whoever looks
            return None
        made.replace(fmt)  # atomic: reports built side by side may make it at once
    return fmt.with_suffix("")


#: The files of a pass that the next pass reads (labels, the last page, longtable's widths; the
#: outline), kept from a report's last build (:func:`kept_passes`).
PASS_FILES = (".aux", ".out")


def kept_passes(pdf: Path) -> Path | None:
    """Where the files of the last pass of the report ``pdf`` are kept (:data:`PASS_FILES`, beside
    the compiled preambles), so that a report built again starts from them: where its labels and
    widths have not moved, one xelatex pass sets it (xelatex says when they have, and passes again).

    Parameters
    ----------
    pdf : pathlib.Path
        The report's PDF file.

    Returns
    -------
    pathlib.Path or None
        The files' common stem (``<folder>/pass-<hash of the PDF's path>``); None where the folder
        is not writable.
    """
    import hashlib
    import os

    folder = Path(sys.prefix) / "latex-formats"
    if not os.access(folder if folder.exists() else sys.prefix, os.W_OK):
        return None
    return folder / f"pass-{hashlib.sha256(str(pdf.resolve()).encode()).hexdigest()[:16]}"


#: Kept pass files unused this long are removed as others are kept [s] (a report of a folder since deleted).
PASS_FILES_KEPT = 30 * 86400


def _forget_old_passes(folder: Path) -> None:
    """Remove the kept pass files of ``folder`` not written for :data:`PASS_FILES_KEPT`."""
    import time

    for path in folder.glob("pass-*"):
        try:
            if time.time() - path.stat().st_mtime > PASS_FILES_KEPT:
                path.unlink()
        except OSError:  # removed meanwhile by a build beside this one
            continue


def _pass_files(source: Path, target: Path) -> None:
    """Copy the :data:`PASS_FILES` of stem ``source`` that exist to stem ``target``, each replaced at once."""
    import os

    for suffix in PASS_FILES:
        made = source.with_name(source.name + suffix)
        if made.is_file():
            written = target.with_name(f"{target.name}{suffix}.{os.getpid()}")
            shutil.copyfile(made, written)
            written.replace(target.with_name(target.name + suffix))  # atomic: builds side by side


def exporter(kept: Path | None = None):
    """nbconvert's PDF exporter with our template, code and prompts hidden; xelatex runs until its
    log asks for no further pass (two for most reports, where nbconvert always runs three; one where
    the files of the last build's pass are ``kept`` and still hold), and no bibtex (a report cites
    no bibliography).

    Parameters
    ----------
    kept : pathlib.Path, optional
        The stem of the files of the last pass of the report's previous build (:func:`kept_passes`):
        read before the first pass, written after the last.

    Returns
    -------
    nbconvert.PDFExporter
        The exporter, configured.
    """
    from nbconvert import PDFExporter
    from nbconvert.exporters.pdf import LatexFailed
    from traitlets.config import Config

    class ReportPDF(PDFExporter):
        def run_latex(self, filename, raise_on_failure=LatexFailed):
            def log_error(command, out):
                self.log.critical("%s failed: %s\n%s", command[0], command, out)

            fmt = compiled_preamble(Path(filename))
            command = (self.latex_command if fmt is None
                       else [self.latex_command[0], f"-fmt={fmt}", *self.latex_command[1:]])
            log, stem = Path(filename).with_suffix(".log"), Path(filename).with_suffix("")
            if kept is not None:
                _pass_files(kept, stem)
            # Without the labels of an earlier pass the first only writes them: no PDF made (xdvipdfmx's 0.1 s).
            first = [] if stem.with_suffix(".aux").is_file() else ["-no-pdf"]
            for k in range(self.latex_count):
                self.run_command([command[0], *(first if k == 0 else []), *command[1:]], filename, 1, log_error,
                                 raise_on_failure)
                # The last pass's log: the tests read its overfull boxes.
                self.latex_log = log.read_text(encoding="utf-8", errors="replace")
                if not any(line in self.latex_log for line in RERUN) and (k or not first):
                    break
            if kept is not None:
                kept.parent.mkdir(exist_ok=True)
                _pass_files(stem, kept)
                _forget_old_passes(kept.parent)
            return True

        def run_bib(self, filename, raise_on_failure=False):
            return False

    c = Config()
    c.PDFExporter.extra_template_basedirs = TEMPLATE_DIRS
    c.PDFExporter.template_name = TEMPLATE
    c.PDFExporter.exclude_input = True
    c.PDFExporter.exclude_input_prompt = True
    c.PDFExporter.exclude_output_prompt = True
    c.TagRemovePreprocessor.enabled = True
    c.TagRemovePreprocessor.remove_cell_tags = {"remove"}
    return ReportPDF(config=c)


def figure_pdf(figure) -> str:
    """A matplotlib figure as vector PDF (the figures lay themselves out, so no tight bounding box:
    that would draw each one twice).

    Parameters
    ----------
    figure : matplotlib.figure.Figure
        The figure.

    Returns
    -------
    str
        The PDF, base64 as a notebook output holds it.
    """
    import base64
    import io

    buffer = io.BytesIO()
    figure.savefig(buffer, format="pdf")
    return base64.b64encode(buffer.getvalue()).decode("ascii")


#: The report whose figures forked workers make (:func:`figures_made`).
_MAKING = None


def _block_figures(k: int) -> list[tuple[str, str]]:
    """The figures of the ``k``-th renderer (:data:`calc.report.RENDERERS`) of :data:`_MAKING`, as
    (PDF, caption).
    """
    from . import RENDERERS

    return [(figure_pdf(figure), caption) for figure, caption in RENDERERS[k].figures(_MAKING)]


@contextlib.contextmanager
def figures_made(report, jobs: int = 1):
    """The report's figures, made while the rest of the report is set.

    Parameters
    ----------
    report : calc.report.Report
        The report.
    jobs : int, optional
        With more than 1, the figures are made from the moment the context opens, ``jobs``
        renderers at a time in processes forked from this one, while this one goes on (making and
        writing the figures is most of a report's time).

    Yields
    ------
    callable
        A function giving the report's figures (:meth:`calc.report.Report.figures`) as (vector PDF,
        caption), in their order.
    """
    if jobs <= 1 or report.case is None:
        yield lambda: [(figure_pdf(figure), caption) for figure, caption in report.figures()]
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    import matplotlib.figure  # noqa: F401 (imported once here, not in every worker)

    from . import RENDERERS

    global _MAKING
    _MAKING = report
    try:
        with ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("fork")) as pool:
            # The last renderers (the accuracy's loops and traces) have the most figures: they start first.
            futures = {k: pool.submit(_block_figures, k) for k in reversed(range(len(RENDERERS)))}
            yield lambda: [x for k in range(len(RENDERERS)) for x in futures[k].result()]
    finally:
        _MAKING = None


def report_notebook(report, figures=None):
    """The report's blocks (:meth:`calc.report.Report.blocks`) as the outputs of a notebook, the
    notebook ``reports/calc-report.ipynb`` gives when run, built here without a kernel.

    Parameters
    ----------
    report : calc.report.Report
        The report.
    figures : callable, optional
        A function giving the figures as (vector PDF, caption), as :func:`figures_made` does
        (default: made here, one after the other).

    Returns
    -------
    nbformat.NotebookNode
        A notebook of one code cell with the blocks as its outputs.
    """
    import nbformat

    from . import Latex

    with contextlib.ExitStack() as stack:
        figures = figures or stack.enter_context(figures_made(report))
        blocks = report.blocks(figures)
    outputs = []
    for shown, metadata in blocks:
        if isinstance(shown, Latex):
            if shown:
                outputs.append(nbformat.v4.new_output("display_data", data={"text/latex": str(shown)}))
        else:
            outputs.append(nbformat.v4.new_output("display_data",
                                                  data={"application/pdf": shown, "text/plain": "figure"},
                                                  metadata=metadata))
    return nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(outputs=outputs)])


def render_pdf(report, pdf: Path, jobs: int = 1) -> None:
    """Write the PDF of a report.

    Parameters
    ----------
    report : calc.report.Report
        The report.
    pdf : pathlib.Path
        The PDF file to write (its folder is made).
    jobs : int, optional
        The figures made this many at a time.

    Returns
    -------
    None

    Raises
    ------
    CalcError
        Where xelatex cannot typeset the report, with the end of its output.
    """
    with figures_made(report, jobs) as figures:
        export = exporter(kept_passes(pdf))  # importing nbconvert goes on beside the figures
        notebook = report_notebook(report, figures)
    from nbconvert.exporters.pdf import LatexFailed

    try:
        body, _ = export.from_notebook_node(notebook, resources={"metadata": {"name": pdf.stem}})
    except LatexFailed as exc:
        tail = "\n".join(exc.output.splitlines()[-15:])
        raise CalcError(f"{display_path(report.path)}: xelatex could not typeset the report:\n{tail}") from None
    pdf.parent.mkdir(parents=True, exist_ok=True)
    pdf.write_bytes(body)


def render_summary(rows: list[dict], files: list, folder: Path) -> tuple[Path, Path]:
    """Write ``summary.pdf`` and ``summary.csv`` of the rows; the PDF goes through the reports' own
    template (a notebook of one output, nothing executed).

    Parameters
    ----------
    rows : list of dict
        The summary's rows (:func:`calc.report.summary.summary_row`).
    files : list
        The files each row's report rests on, for the title block.
    folder : pathlib.Path
        The output folder.

    Returns
    -------
    tuple of pathlib.Path
        The PDF and the CSV written.

    Raises
    ------
    CalcError
        Where xelatex cannot typeset the summary, with the end of its output.
    """
    import nbformat
    from nbconvert.exporters.pdf import LatexFailed

    from .provenance import build_date, git_commit
    from .summary import summary_latex, write_csv

    pdf, table = folder / f"{SUMMARY}.pdf", folder / f"{SUMMARY}.csv"
    write_csv(rows, table)
    latex = summary_latex(rows, files, build_date(), git_commit(), folder)
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(outputs=[
        nbformat.v4.new_output("display_data", data={"text/latex": str(latex)})])])
    try:
        body, _ = exporter().from_notebook_node(nb, resources={"metadata": {"name": SUMMARY}})
    except LatexFailed as exc:
        tail = "\n".join(exc.output.splitlines()[-15:])
        raise CalcError(f"{pdf}: xelatex could not typeset the summary:\n{tail}") from None
    pdf.write_bytes(body)
    return pdf, table


def build_one(case: Path, pdf: Path, jobs: int = 1) -> dict:
    """Read, evaluate and typeset one case.

    Parameters
    ----------
    case : pathlib.Path
        The case file.
    pdf : pathlib.Path
        Its PDF.
    jobs : int, optional
        Its figures made this many at a time.

    Returns
    -------
    dict
        Its line for the terminal, its summary row, the files its results rest on, and whether it is
        an input error or does not pass (plain data, so that a worker process can hand it back).
    """
    from . import build_report
    from .summary import summary_row

    report = build_report(case)
    try:
        render_pdf(report, pdf, jobs)
    except CalcError as exc:
        return {"line": f"ERROR {display_path(case)}: no PDF: {exc}", "row": summary_row(report, None),
                "files": report.files, "input_error": True, "not_passing": False}
    return {"line": f"{report.summary_line()}  ->  {pdf}", "row": summary_row(report, pdf), "files": report.files,
            "input_error": report.error is not None, "not_passing": report.verdict.passes is not True}


def built(paths: list[Path], pdfs: list[Path], jobs: int):
    """Build the cases, ``jobs`` at a time (worker processes forked from this one, which has the
    package imported already); one case makes its figures ``jobs`` at a time instead.

    Parameters
    ----------
    paths : list of pathlib.Path
        The case files.
    pdfs : list of pathlib.Path
        Their PDFs.
    jobs : int
        The builds at a time.

    Yields
    ------
    dict
        :func:`build_one` of each case, in the order of the cases.
    """
    if jobs <= 1 or len(paths) <= 1:
        yield from (build_one(path, pdf, jobs) for path, pdf in zip(paths, pdfs))
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(min(jobs, len(paths)), mp_context=multiprocessing.get_context("fork")) as pool:
        yield from pool.map(build_one, paths, pdfs)


def main(cases: list[str], output: str | None = None, strict: bool = False, summary: bool = False,
         jobs: int | None = None) -> int:
    """Build one PDF per case, with a progress bar; print one line per case.

    Parameters
    ----------
    cases : list of str
        The case files.
    output : str, optional
        The PDF file (one case) or the folder (several); default ``reports/<case name>.pdf``.
    strict : bool, optional
        Exit 1 when a verdict is not PASS.
    summary : bool, optional
        Also write the summary's PDF and CSV in the output folder.
    jobs : int, optional
        The reports built at a time (default: the number of cores).

    Returns
    -------
    int
        The exit status (``docs/case-format.md``): 2 when a case could not be read or a PDF could
        not be built (a report of an unreadable case is still written, saying why), else 1 with
        ``strict`` when a verdict is not PASS, else 0.
    """
    import os

    from tqdm import tqdm

    from .summary import counts_text

    paths = [Path(c) for c in cases]
    try:
        for p in paths:
            if not p.is_file():
                raise CalcError(f"{p}: the case file does not exist")
        if jobs is not None and jobs < 1:
            raise CalcError(f"-j {jobs}: expected a number of parallel builds of 1 or more")
        if summary:
            output = str(summary_folder(paths, output))
        pdfs = output_paths(paths, output)
        check_tools()
    except CalcError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    done = list(tqdm(built(paths, pdfs, jobs or os.cpu_count() or 1), total=len(paths), desc="calc reports",
                     unit="case", file=sys.stderr))
    lines = [d["line"] for d in done]
    rows = [d["row"] for d in done]
    input_errors = sum(d["input_error"] for d in done)
    not_passing = sum(d["not_passing"] for d in done)
    if summary:
        try:
            written = render_summary(rows, [d["files"] for d in done], Path(output))
        except CalcError as exc:
            input_errors += 1
            lines.append(f"ERROR no summary: {exc}")
        else:
            lines.append(f"{counts_text(rows)}  ->  {'  '.join(map(str, written))}")
    print("\n".join(lines))
    if input_errors:
        return 2
    return 1 if strict and not_passing else 0
