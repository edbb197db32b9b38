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


#: The most files the page writes into one folder (case files, calc reports, variants PDFs), and the
#: largest case file it writes [bytes]: anyone who reaches the port can save, and a report costs some 7 s.
MAX_WRITTEN = 40
MAX_CASE_BYTES = 256_000
#: The list of the files the page wrote into a folder: only these are counted, listed and removable.
WRITTEN_LIST = ".design-review-written.json"


class Written:
    """The files the design review wrote into ``folder`` (listed in :data:`WRITTEN_LIST` there):
    at most :data:`MAX_WRITTEN`, each removable from the page; no other file is ever removed.

    Parameters
    ----------
    folder : str or pathlib.Path
        The folder written into.
    """

    def __init__(self, folder):
        self.folder = Path(folder)

    def names(self) -> list[str]:
        """The files written here that still exist, oldest first.

        Returns
        -------
        list of str
            Their names (no folder).
        """
        import json

        try:
            listed = json.loads((self.folder / WRITTEN_LIST).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return []
        return [n for n in listed if isinstance(n, str) and _plain_name(n) and (self.folder / n).is_file()]

    def check_room(self, what: str) -> None:
        """Refuse a further file where the page has written :data:`MAX_WRITTEN` here.

        Parameters
        ----------
        what : str
            The file about to be written, in words (``"the case file x.toml"``).

        Returns
        -------
        None
        """
        if len(self.names()) >= MAX_WRITTEN:
            raise CalcError(f"{what}: the design review has written {MAX_WRITTEN} files into "
                            f"{self.folder.name}/, its most; remove old ones from the page first")

    def add(self, name: str) -> None:
        """List a file just written.

        Parameters
        ----------
        name : str
            Its name (no folder).

        Returns
        -------
        None
        """
        import json

        names = [n for n in self.names() if n != name] + [name]
        (self.folder / WRITTEN_LIST).write_text(json.dumps(names), encoding="utf-8")

    def remove(self, name: str) -> None:
        """Remove a file the page wrote (never another).

        Parameters
        ----------
        name : str
            Its name, as :meth:`names` gives it.

        Returns
        -------
        None
        """
        import json

        names = self.names()
        if name not in names:
            raise CalcError(f"remove {name!r}: not a file the design review wrote into {self.folder.name}/")
        (self.folder / name).unlink(missing_ok=True)
        (self.folder / WRITTEN_LIST).write_text(json.dumps([n for n in names if n != name]), encoding="utf-8")


def write_case(path: Path, text: str, original: str | None) -> None:
    """Write a new case file and read it back: at most :data:`MAX_CASE_BYTES`, only where the page
    has room left in its folder (:class:`Written`), never over a file; then its text must be the one
    written, the case reader must read it, and it may hold no table the original has not but the
    mechanism's, the moves', the typed cycle's and its load's. Otherwise the file is removed and nothing saved.

    Parameters
    ----------
    path : pathlib.Path
        The new file (:func:`save_path`).
    text : str
        Its text (:func:`calc.review.edit.changed_text`).
    original : str or None
        The text of the case file it was changed from.

    Returns
    -------
    None
        A file not written, or not reading back as written, raises :class:`calc.core.errors.CalcError`
        saying why.
    """
    import tomllib

    from ..sections.case import read_case

    size = len(text.encode("utf-8"))
    if size > MAX_CASE_BYTES:
        raise CalcError(f"save as {path.name}: the case file would be {size} bytes, above the {MAX_CASE_BYTES} "
                        "the design review writes")
    written = Written(path.parent)
    written.check_room(f"save as {path.name}")
    try:
        with path.open("x", encoding="utf-8") as f:  # never over a file made meanwhile
            f.write(text)
    except OSError as exc:
        raise CalcError(f"save as {path.name}: {exc.strerror or exc}") from None
    written.add(path.name)
    try:
        back = path.read_text(encoding="utf-8")
        read_case(path, back)
        tables = set(tomllib.loads(back)) - set(tomllib.loads(original or ""))
    except (OSError, ValueError, CalcError) as exc:
        written.remove(path.name)
        raise CalcError(f"not saved: {path.name} read back does not read as a case ({str(exc)[:150]}); "
                        "it was removed") from None
    if back != text or tables - {"mechanism", "move", "profile", "load"}:
        written.remove(path.name)
        why = "differs from what was written" if back != text else f"has tables the file has not: {sorted(tables)}"
        raise CalcError(f"not saved: {path.name} read back {why}; it was removed")


def _plain_name(name: str) -> bool:
    """Whether ``name`` is a plain file name (no folder, not hidden)."""
    return bool(re.match(r"^[\w][\w.-]*$", name))


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
        self.cases = Path(folder or path.parent)
        self.choices = sorted({*self.cases.glob("*.toml"), path})
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

    def look_again(self, shown: Path) -> bool:
        """The folder's case files as they are now: one saved since (from another page) offered,
        one removed no longer offered (the case shown stays).

        Parameters
        ----------
        shown : pathlib.Path
            The case shown.

        Returns
        -------
        bool
            Whether the files offered changed.
        """
        now = {*self.cases.glob("*.toml"), shown}
        new, gone = now - set(self.labels), set(self.labels) - now
        for p in new:
            self.labels[p] = p.name
        for p in gone:
            del self.labels[p]
        return bool(new or gone)

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
