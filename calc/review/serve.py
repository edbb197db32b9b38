"""Serve the design-review panel alone as a web page, for reviewers who do not code (``make review``).

``python -m calc.review.serve [--cases DIR] [--case NAME] [--reports DIR] [--port N] [--ip ADDRESS] [--idle-minutes M]``
runs Voilà on ``design-review.ipynb`` beside this file: the panel and nothing else (no code, no
other notebook is served). The page opens the case ``NAME`` of the folder ``DIR`` (default
``cases/``, the example); the panel offers the folder's other case files, and no other path. A
kernel whose page was closed is shut down within ``M`` minutes and 15 s (:data:`IDLE_MINUTES`, 45 s: within
a minute; the kernel waiting for the next page is culled and started again as often while no page is
open). The address
is this machine's only (127.0.0.1) unless ``--ip`` says otherwise (docs/user-guide.md, "Design review":
sharing it on a network).

The calc reports built in ``--reports`` (default ``reports/``: ``python -m calc report
cases/*.toml --summary -o reports/``) are linked from the page. Voilà serves files only under the
folder it serves (``Voila.root_dir``, by default the page's folder), through its ``/voila/files/``
handler, and only those its ``VoilaConfiguration.file_allowlist`` names (by default images); its
file handler (tornado's) refuses a link that leads out of that folder. So the served folder is
the one that holds both the page and the reports' folder (:func:`served_root`: the project, as
``make review`` runs it), and only the PDFs directly in the reports' folder are allowed
(:func:`allowed`); the page links them by their path under that folder (:func:`report_address`).
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from pathlib import Path
from urllib.parse import quote

PAGE = Path(__file__).with_name("design-review.ipynb")
#: The variables that tell the page's kernel which case to open and where the reports are.
CASE_VARIABLE = "CALC_REVIEW_CASE"
REPORTS_VARIABLE = "CALC_REVIEW_REPORTS"
IDLE_MINUTES = 0.75
#: Seconds from a page taking the waiting kernel to its successor's start (Voilà's default: 1 s). The
#: successor's start (its imports and the panel drawn, some 0.6 s of CPU) then no longer competes with
#: the browser drawing the page on a 2-core machine; a second page asked for within these seconds waits
#: for it.
FILL_DELAY = 3


def served_root(reports: Path) -> Path:
    """The folder Voilà serves: the nearest one that holds the page and the reports' folder.

    Parameters
    ----------
    reports : pathlib.Path
        The reports' folder.

    Returns
    -------
    pathlib.Path
        The folder, resolved.
    """
    return Path(os.path.commonpath([PAGE.parent.resolve(), reports.resolve()]))


def _under_root(path: Path, reports: Path) -> str:
    return path.resolve().relative_to(served_root(reports)).as_posix()


def allowed(reports: Path) -> list[str]:
    """The files Voilà may serve: the PDFs directly in ``reports`` (its own deny list keeps
    refusing notebooks and Python files).

    Parameters
    ----------
    reports : pathlib.Path
        The reports' folder.

    Returns
    -------
    list of str
        Voilà's ``file_allowlist``: one regular expression of paths under :func:`served_root`.
    """
    folder = _under_root(reports, reports)
    return [("" if folder == "." else re.escape(folder) + "/") + r"[^/]+\.pdf"]


def report_address(pdf: Path, reports: Path) -> str:
    """The address of the report ``pdf`` (in ``reports``), relative to the page.

    Parameters
    ----------
    pdf : pathlib.Path
        The report.
    reports : pathlib.Path
        The reports' folder.

    Returns
    -------
    str
        ``voila/files/<its path under the served folder>``, quoted.
    """
    return "voila/files/" + quote(_under_root(pdf, reports))


#: zlib's level of the server's compression: its quickest.
GZIP_LEVEL = 1

#: Voilà started as ``python -m voila`` does, with one import kept out of the server: jsonschema's
#: check of the IRI format (``rfc3987_syntax``, installed with the server's event-logging schemas)
#: builds its grammar when imported, 0.75 s of the server's 1.3 s of imports; jsonschema takes the
#: format as unchecked without it (none of the server's event schemas is checked against a link).
#: And every response compressed (tornado's ``compress_response``, which Voilà's ``tornado_settings`` set too late
#: to take): the page's scripts and styles are text, 5.2 MB sent as they are, 1.65 MB compressed. At zlib's
#: quickest level (:data:`GZIP_LEVEL`): the server compresses each response as it sends it, one at a time, so a
#: page's first load waits for it; tornado's level 6 sends 1.4 MB and made the page ready some 0.2 s later.
LAUNCH = ("import sys; sys.modules['rfc3987_syntax'] = None\n"
          "import tornado.web\n"
          "_init = tornado.web.Application.__init__\n"
          "def _compressed(self, *args, **settings):\n"
          "    _init(self, *args, **{**settings, 'compress_response': True})\n"
          "tornado.web.Application.__init__ = _compressed\n"
          f"tornado.web.GZipContentEncoding.GZIP_LEVEL = {GZIP_LEVEL}\n"
          "from voila.app import main; main()")


#: The JupyterLab extensions the page loads: the widgets' manager (Voilà's own for ipywidgets 8).
PAGE_EXTENSIONS = ("@jupyter-widgets/jupyterlab-manager", "@voila-dashboards/widgets-manager8")


def command(port: int, ip: str = "127.0.0.1", idle_seconds: int = round(60 * IDLE_MINUTES),
            reports: Path = Path("reports")) -> list[str]:
    """The Voilà command line of the review page.

    Parameters
    ----------
    port : int
        The port served.
    ip : str
        The address served (by default this machine's only).
    idle_seconds : int
        A kernel whose page was closed is shut down after this long [s].
    reports : pathlib.Path
        The folder of the reports the page links.

    Returns
    -------
    list of str
        The command's arguments, this Python first.
    """
    return [
        sys.executable, "-c", LAUNCH, str(PAGE), "--no-browser", f"--port={port}", f"--Voila.ip={ip}",
        f"--Voila.root_dir={served_root(reports)}", f"--VoilaConfiguration.file_allowlist={allowed(reports)!r}",
        "--strip_sources=True", "--show_tracebacks=False", "--theme=light",
        # The page's scripts: the widgets' and nothing else of the environment's JupyterLab extensions
        # (jupytext's, ipylab's, pygments' styles: some 250 kB the browser would load and run first).
        f"--VoilaConfiguration.extension_allowlist={list(PAGE_EXTENSIONS)!r}",
        # One kernel waits with the panel already drawn, so a page is ready at once; its
        # successor starts FILL_DELAY after a page takes it, once that page is drawn.
        "--preheat_kernel=True", "--pool_size=1", f"--VoilaKernelManager.fill_delay={FILL_DELAY}",
        # A kernel whose page was closed is culled; one with a page open stays, however idle.
        f"--MappingKernelManager.cull_idle_timeout={idle_seconds}",
        f"--MappingKernelManager.cull_interval={min(15, idle_seconds)}",
        "--MappingKernelManager.cull_connected=False",
    ]


def environment(case: Path, reports: Path | None = None) -> dict:
    """The environment of the server (and so of its kernels): the case to open, the reports' folder.

    Parameters
    ----------
    case : pathlib.Path
        The case file the page opens (:data:`CASE_VARIABLE`).
    reports : pathlib.Path, optional
        The reports' folder (:data:`REPORTS_VARIABLE`).

    Returns
    -------
    dict
        This process's environment with the two variables, their paths resolved.
    """
    reports_variable = {REPORTS_VARIABLE: str(reports.resolve())} if reports else {}
    return {**os.environ, CASE_VARIABLE: str(case.resolve()), **reports_variable}


def main(argv=None) -> int:
    """Serve the page (the command line of the module's docstring): Voilà takes this process's place.

    Parameters
    ----------
    argv : list of str, optional
        The arguments; by default the command line's.

    Returns
    -------
    int
        2 where the case file does not exist (said on stderr); else it does not return.
    """
    parser = argparse.ArgumentParser(prog="python -m calc.review.serve", description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=Path, default=Path("cases"),
                        help="the folder of case files offered (default: cases)")
    parser.add_argument("--case", default="indexing-table.toml",
                        help="the case opened first (default: indexing-table.toml)")
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
    host = "localhost" if args.ip == "127.0.0.1" else args.ip
    print(f"Design review of {case} at http://{host}:{args.port}/ (Ctrl-C stops it)")
    argv = command(args.port, args.ip, round(60 * args.idle_minutes), args.reports)
    os.execve(argv[0], argv, environment(case, args.reports))


if __name__ == "__main__":
    sys.exit(main())
