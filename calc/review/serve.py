"""Serve the design-review panel alone as a web page, for reviewers who do not code (``make review``).

``python -m calc.review.serve [--cases DIR] [--case NAME] [--port N] [--ip ADDRESS] [--idle-minutes M]``
runs Voilà on ``design-review.ipynb`` beside this file: the panel and nothing else (no code, no
other notebook is served). The page opens the case ``NAME`` of the folder ``DIR`` (default
``cases/``, the example); the panel offers the folder's other case files, and no other path. A
kernel whose page was closed is shut down after ``M`` minutes (:data:`IDLE_MINUTES`). The address
is this machine's only (127.0.0.1) unless ``--ip`` says otherwise (README, "Design review":
sharing it on a network).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

PAGE = Path(__file__).with_name("design-review.ipynb")
#: The variable that tells the page's kernel which case to open.
CASE_VARIABLE = "CALC_REVIEW_CASE"
IDLE_MINUTES = 10


def command(port: int, ip: str = "127.0.0.1", idle_seconds: int = 60 * IDLE_MINUTES) -> list[str]:
    """The Voilà command line of the review page; a kernel whose page was closed is shut down
    after ``idle_seconds``."""
    return [
        sys.executable, "-m", "voila", str(PAGE), "--no-browser", f"--port={port}", f"--Voila.ip={ip}",
        "--strip_sources=True", "--show_tracebacks=False", "--theme=light",
        # One kernel waits with the panel already drawn, so a page is ready at once; its
        # successor starts when a page takes it.
        "--preheat_kernel=True", "--pool_size=1",
        # A kernel whose page was closed is culled; one with a page open stays, however idle.
        f"--MappingKernelManager.cull_idle_timeout={idle_seconds}", f"--MappingKernelManager.cull_interval={min(60, idle_seconds)}",
        "--MappingKernelManager.cull_connected=False",
    ]


def environment(case: Path) -> dict:
    """The environment of the server (and so of its kernels): the case to open."""
    return {**os.environ, CASE_VARIABLE: str(case.resolve())}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m calc.review.serve", description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=Path, default=Path("cases"), help="the folder of case files offered (default: cases)")
    parser.add_argument("--case", default="indexing-table.toml", help="the case opened first (default: indexing-table.toml)")
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
    argv = command(args.port, args.ip, round(60 * args.idle_minutes))
    os.execve(argv[0], argv, environment(case))


if __name__ == "__main__":
    sys.exit(main())
