"""Serve the design-review panel alone as a web page, for reviewers who do not code (``make review``).

``python -m calc.review.serve [--cases DIR] [--case NAME] [--reports DIR] [--port N] [--ip ADDRESS] [--idle-minutes M]``
runs Voilà on ``design-review.ipynb`` beside this file: the panel and nothing else (no code, no
other notebook is served). The page opens the case ``NAME`` of the folder ``DIR`` (default
``cases/``, the example); the panel offers the folder's other case files, and no other path. A
kernel whose page was closed is shut down after ``M`` minutes (:data:`IDLE_MINUTES`). The address
is this machine's only (127.0.0.1) unless ``--ip`` says otherwise (README, "Design review":
sharing it on a network).

The calc reports built in ``--reports`` (default ``reports/``: ``python -m calc report
cases/*.toml --summary -o reports/``) are linked from the page. Voilà serves files only under the
folder it serves (its ``root_dir``, the page's folder), through its ``/voila/files/`` handler and
only those its ``VoilaConfiguration.file_allowlist`` names (by default images). So the server
serves a folder of its own (:func:`site`): a copy of the page, and the reports' folder linked in
as ``reports/``, of which only the PDFs are allowed (:data:`ALLOWED`); the page links
``voila/files/reports/NAME.pdf`` (:func:`report_address`).
"""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path
from urllib.parse import quote

PAGE = Path(__file__).with_name("design-review.ipynb")
#: The variables that tell the page's kernel which case to open and where the reports are.
CASE_VARIABLE = "CALC_REVIEW_CASE"
REPORTS_VARIABLE = "CALC_REVIEW_REPORTS"
IDLE_MINUTES = 10
#: The served folder's link to the reports' folder, and the files of it that are served (the PDFs
#: directly in it; Voilà's own deny list keeps refusing notebooks and Python files).
REPORTS_LINK = "reports"
ALLOWED = [rf"{REPORTS_LINK}/[^/]+\.pdf"]


def site(folder: Path, reports: Path) -> Path:
    """Lay out the served folder in ``folder``: a copy of the page and the link ``reports/`` to
    the reports' folder; returns the page's path in it."""
    page = folder / PAGE.name
    shutil.copyfile(PAGE, page)
    (folder / REPORTS_LINK).symlink_to(reports.resolve(), target_is_directory=True)
    return page


def report_address(pdf: Path) -> str:
    """The address of a report of the reports' folder, relative to the page."""
    return f"voila/files/{REPORTS_LINK}/{quote(pdf.name)}"


def command(port: int, ip: str = "127.0.0.1", idle_seconds: int = 60 * IDLE_MINUTES, page: Path = PAGE) -> list[str]:
    """The Voilà command line of the review ``page`` (in its served folder, :func:`site`); a
    kernel whose page was closed is shut down after ``idle_seconds``."""
    return [
        sys.executable, "-m", "voila", str(page), "--no-browser", f"--port={port}", f"--Voila.ip={ip}",
        f"--VoilaConfiguration.file_allowlist={ALLOWED!r}",
        "--strip_sources=True", "--show_tracebacks=False", "--theme=light",
        # One kernel waits with the panel already drawn, so a page is ready at once; its
        # successor starts when a page takes it.
        "--preheat_kernel=True", "--pool_size=1",
        # A kernel whose page was closed is culled; one with a page open stays, however idle.
        f"--MappingKernelManager.cull_idle_timeout={idle_seconds}", f"--MappingKernelManager.cull_interval={min(60, idle_seconds)}",
        "--MappingKernelManager.cull_connected=False",
    ]


def environment(case: Path, reports: Path | None = None) -> dict:
    """The environment of the server (and so of its kernels): the case to open, the reports' folder."""
    return {**os.environ, CASE_VARIABLE: str(case.resolve()), **({REPORTS_VARIABLE: str(reports.resolve())} if reports else {})}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m calc.review.serve", description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=Path, default=Path("cases"), help="the folder of case files offered (default: cases)")
    parser.add_argument("--case", default="indexing-table.toml", help="the case opened first (default: indexing-table.toml)")
    parser.add_argument("--reports", type=Path, default=Path("reports"),
                        help="the folder of the calc reports the page links (default: reports)")
    parser.add_argument("--port", type=int, default=8866)
    parser.add_argument("--ip", default="127.0.0.1", help="the address served (default: 127.0.0.1, this machine only)")
    parser.add_argument("--idle-minutes", type=float, default=IDLE_MINUTES,
                        help=f"shut a kernel down this long after its page was closed (default: {IDLE_MINUTES})")
    args = parser.parse_args(argv)
    case = args.cases / args.case
    if not case.is_file():
        print(f"{case}: the case file does not exist", file=sys.stderr)
        return 2
    print(f"Design review of {case} at http://{'localhost' if args.ip == '127.0.0.1' else args.ip}:{args.port}/ (Ctrl-C stops it)")
    # Voilà runs as a child, so that the served folder is removed when it stops (Ctrl-C, or a
    # SIGTERM, which ends this process as SystemExit).
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    with tempfile.TemporaryDirectory(prefix="calc-review-") as folder:
        argv = command(args.port, args.ip, round(60 * args.idle_minutes), site(Path(folder), args.reports))
        voila = subprocess.Popen(argv, env=environment(case, args.reports))
        try:
            return voila.wait()
        except (KeyboardInterrupt, SystemExit):
            voila.terminate()
            voila.wait()
            return 0


if __name__ == "__main__":
    sys.exit(main())
