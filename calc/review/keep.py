"""The case files a review offers and keeps: those of one folder, each with its verdict and calc
report where a reports' folder gives them (:class:`CaseFiles`), and a reviewer's changes saved
beside them under a new name (:func:`save_path`; the text is :func:`calc.review.edit.changed_text`'s);
an existing file is never overwritten.
"""

from __future__ import annotations

import re
from pathlib import Path

from ..core.errors import CalcError, as_found

#: A new case file's name: letters, digits, ``-``, ``_`` and ``.``, ending in ``.toml``.
_NAME = re.compile(r"^[\w][\w.-]*\.toml$")


def save_path(original: Path, name: str) -> Path:
    """The new case file ``name`` beside ``original``: a plain file name (no folder), ending in
    ``.toml``, of a file that does not exist yet.

    Parameters
    ----------
    original : pathlib.Path
        The case file reviewed (the new one goes into its folder).
    name : str
        The new file's name (``"indexing-table-variant.toml"``).

    Returns
    -------
    pathlib.Path
        The new file's path. A name that is not a plain ``.toml`` file name, or of a file that
        exists, raises :class:`calc.core.errors.CalcError` saying so.
    """
    if not _NAME.match(name) or name in (".", ".."):
        raise CalcError(f"save as {as_found(name)}: expected a file name such as {original.stem}-variant.toml "
                        "(letters, digits, - _ .), no folder")
    path = original.parent / name
    if path.exists():
        raise CalcError(f"save as {name}: the file exists in {original.parent.name}/; choose another name "
                        "(a case file is never overwritten here)")
    return path


def free_name(original: Path) -> str:
    """The first free name ``<stem>-variant-N.toml`` beside ``original``.

    Parameters
    ----------
    original : pathlib.Path
        The case file reviewed.

    Returns
    -------
    str
        The file name (no folder), N counted from 1.
    """
    n = 1
    while (original.parent / f"{original.stem}-variant-{n}.toml").exists():
        n += 1
    return f"{original.stem}-variant-{n}.toml"


class CaseFiles:
    """The case files offered beside ``path``: those of the folder ``folder`` (by default the one
    it is in), and ``path``.

    Parameters
    ----------
    path : str or pathlib.Path
        The case file reviewed.
    folder : str or pathlib.Path, optional
        The folder whose case files are offered; by default the one ``path`` is in.
    reports : str or pathlib.Path, optional
        The folder of the calc reports (``python -m calc report cases/*.toml --summary -o
        reports/``): each file is then labelled with its verdict as its file reads
        (:func:`calc.report.publish.summary_rows`), and its report linked only where it was built.
    report_link : callable, optional
        ``report_link(path)`` returns the address of a report (of the case file itself where no
        reports' folder is given).
    """

    def __init__(self, path, folder=None, reports=None, report_link=None):
        from ..report.publish import summary_rows

        path = Path(path)
        self.choices = sorted({*Path(folder or path.parent).glob("*.toml"), path})
        self.labels = {p: p.name for p in self.choices}
        self.reports: dict = {}  # case file -> the path of its report
        self.folder, self.report_link = reports, report_link
        self.note = ""  # why no verdicts or reports are shown
        if reports is None:
            return
        try:
            rows = summary_rows(self.choices, str(reports))
        except CalcError as exc:
            self.note, rows = str(exc), []
        for p, row in zip(self.choices, rows):
            self.labels[p] = f"{p.name} · {row['verdict']}"
            self.reports[p] = Path(row["report_path"])

    def named(self, name: str) -> Path | None:
        """The case file offered of the name ``name``.

        Parameters
        ----------
        name : str
            A file name, no folder.

        Returns
        -------
        pathlib.Path or None
            Its path, or None where no file offered is so named.
        """
        return next((p for p in self.labels if p.name == name), None)

    def add(self, path: Path) -> None:
        """A case file saved beside the others, offered too.

        Parameters
        ----------
        path : pathlib.Path
            The new case file.

        Returns
        -------
        None
        """
        self.labels[path] = path.name

    def options(self, shown: Path | None = None, label: str | None = None) -> list[tuple]:
        """The chooser's options: the case files with their labels.

        Parameters
        ----------
        shown : pathlib.Path, optional
            The case shown, whose label is ``label``.
        label : str, optional
            Its label in place of the file's.

        Returns
        -------
        list of tuple
            (label, path) of each case file, by path.
        """
        return [(label if p == shown and label else self.labels[p], p) for p in sorted(self.labels)]

    def label(self, path: Path, word: str, changed: bool) -> str:
        """The label of the case ``path`` shown with the verdict ``word``: the screen's, once
        changed; the file's where the reports give verdicts.

        Parameters
        ----------
        path : pathlib.Path
            The case file shown.
        word : str
            The verdict of the design on the screen.
        changed : bool
            Whether an input is changed from the file.

        Returns
        -------
        str
            ``"<name> · <word> (changed here)"`` once changed; else the file's label with ``word``
            where the reports give verdicts, or the file's name.
        """
        if changed:
            return f"{path.name} · {word} (changed here)"
        return f"{path.name} · {word}" if " · " in self.labels.get(path, "") else self.labels.get(path, path.name)

    def report_address(self, path: Path) -> str | None:
        """The address of the report of the case file ``path``: given the reports' folder, only
        where the report was built.

        Parameters
        ----------
        path : pathlib.Path
            A case file offered.

        Returns
        -------
        str or None
            The address (``report_link``'s), or None where there is no link or no report.
        """
        if self.report_link is None:
            return None
        if self.folder is None:
            return self.report_link(path)
        pdf = self.reports.get(path)
        return self.report_link(pdf) if pdf is not None and pdf.is_file() else None

    def pdf_folder(self, path: Path) -> Path:
        """Where a PDF of the case ``path`` goes: the reports' folder, else the case's.

        Parameters
        ----------
        path : pathlib.Path
            The case file.

        Returns
        -------
        pathlib.Path
            The folder.
        """
        return Path(self.folder) if self.folder else path.parent

    def link(self, pdf: Path) -> str | None:
        """The address of a PDF built here.

        Parameters
        ----------
        pdf : pathlib.Path
            The PDF.

        Returns
        -------
        str or None
            ``report_link``'s address of it, or None where no ``report_link`` was given.
        """
        return self.report_link(pdf) if self.report_link is not None else None
