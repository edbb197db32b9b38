"""Where a formula comes from, as data: the document, the place in it, the reading taken, the validity.

A formula's :class:`Source` is one or more :class:`Citation` s, each of one :class:`Document` of a
registry (the package's is :mod:`calc.domain.documents`): the place cited in it (a section, a page, a
table, an errata entry), what it says there, a remark or a nested citation (the errata entry that
reads the place), and, where the document states one, the :class:`Validity` of the formula: a
condition in words and, where it is a band of a quantity, the :class:`Band`.

The sentence the outputs print (:attr:`Source.text`, a formula's ``reference``) is rendered from
those parts: ``name, place: says (note)``, the citations joined by ``; ``. A citation whose
sentence names the document and place otherwise (``a reading (spec, Motion and mechanism)``, a
textbook result stated without naming the book) gives those words as its ``label``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterator

from .errors import CalcError, listing, as_found
from .glossary import SYMBOLS

#: Where a validity stands in its citation's sentence: after the place, as the condition that selects
#: the form (``Positioning Accuracy, torque <= 3 % of nominal torque: ...``); after what the document
#: says, as its last words (``... at 0 Nm of torque``); or aside, in parentheses (``errata E9 (elastomer
#: couplings only)``).
STANDS = ("heading", "tail", "aside")

#: An https address: a host with a dot, then an optional path, no spaces.
_URL = re.compile(r"https://[A-Za-z0-9-]+(\.[A-Za-z0-9-]+)+(:[0-9]+)?(/\S*)?")


@dataclass(frozen=True)
class Document:
    """One document the formulas cite, as the registry holds it.

    Parameters
    ----------
    name : str
        What a reference sentence calls it (``"source"``, ``"errata"``, ``"R+W ZA line shaft catalog"``).
    title : str
        Its title (a document without one: what it is and its sections).
    publisher : str
        Its publisher or author.
    edition : str
        Its edition, date or document number; empty where none is known.
    url : str
        Its https address (a DOI as ``https://doi.org/...``); empty where there is none.
    held : str
        Where the project keeps it, or the readings and figures taken from it; empty where it does not.
    joiner : str
        What joins the name and a place in a sentence: ``", "`` (``source, Lost Motion``) or ``" "``
        (``errata E7``).

    Raises
    ------
    CalcError
        On an empty name, title or publisher, or an address that is not a well-formed https URL.
    """

    name: str
    title: str
    publisher: str
    edition: str = ""
    url: str = ""
    held: str = ""
    joiner: str = ", "

    def __post_init__(self):
        for key in ("name", "title", "publisher"):
            if not getattr(self, key).strip():
                raise CalcError(f"document {as_found(self.name or self.title)}: expected a {key}, found none")
        if self.url and not _URL.fullmatch(self.url):
            raise CalcError(f"document {as_found(self.name)}: expected an https address, found {as_found(self.url)}")

    def at(self, place: str | tuple[str, ...] = "", **parts) -> Citation:
        """A citation of this document.

        Parameters
        ----------
        place : str or tuple of str
            The section, page, table or entry cited; several are joined by "and".
        **parts
            The other fields of :class:`Citation` (``says``, ``note``, ``validity``, ``label``).

        Returns
        -------
        Citation
            The citation.
        """
        return Citation(self, place, **parts)

    def cited(self, places: tuple[str, ...]) -> str:
        """The words that name this document and places in a sentence.

        Parameters
        ----------
        places : tuple of str
            The places cited (none: the document alone).

        Returns
        -------
        str
            ``name``, or ``name`` joined to the places (``errata E8 and E11``).
        """
        return self.joiner.join((self.name, " and ".join(places))) if places else self.name


@dataclass(frozen=True)
class Band:
    """A band of a quantity's magnitude where a formula holds: above ``above`` and up to ``upto``,
    each a share of a quantity (``(0.03, "T_2N")``: 3 % of the nominal torque); an end left out is open.

    Parameters
    ----------
    quantity : str
        The symbol bounded, by its name in :mod:`calc.core.glossary`.
    above : tuple of (float, str), optional
        The lower end, not included: a share and a symbol's name.
    upto : tuple of (float, str), optional
        The upper end, included.

    Raises
    ------
    CalcError
        On a symbol not declared, an end of another kind than the quantity, or no end at all.
    """

    quantity: str
    above: tuple[float, str] | None = None
    upto: tuple[float, str] | None = None

    def __post_init__(self):
        if self.above is None and self.upto is None:
            raise CalcError(f"band of {self.quantity}: expected an end above or up to, found neither")
        names = [self.quantity] + [end[1] for end in self.ends]
        for name in names:
            if name not in SYMBOLS:
                raise CalcError(f"band of {self.quantity}: no symbol {as_found(name)} is declared")
        kind = SYMBOLS[self.quantity].kind
        for name in names[1:]:
            if SYMBOLS[name].kind != kind:
                raise CalcError(f"band of {self.quantity}: the end {name} is a {SYMBOLS[name].kind}, expected {kind}")

    @property
    def ends(self) -> tuple[tuple[float, str], ...]:
        """The ends given, lower first."""
        return tuple(end for end in (self.above, self.upto) if end is not None)


@dataclass(frozen=True)
class Validity:
    """Where a formula holds, as its document states it.

    Parameters
    ----------
    text : str
        The condition in the document's words (``"elastomer couplings only"``).
    band : Band, optional
        The condition as a band of a quantity, where it is one.
    stands : str
        Where the text stands in its citation's sentence, one of :data:`STANDS`; default ``"aside"``.

    Raises
    ------
    CalcError
        On an empty text or an unknown place in the sentence.
    """

    text: str
    band: Band | None = None
    stands: str = "aside"

    def __post_init__(self):
        if not self.text.strip():
            raise CalcError("validity: expected the condition in words, found an empty text")
        if self.stands not in STANDS:
            raise CalcError(f"validity {as_found(self.text)}: expected stands to be one of {listing(STANDS)}, "
                            f"found {as_found(self.stands)}")


@dataclass(frozen=True)
class Citation:
    """One place of one document, as a formula cites it.

    Parameters
    ----------
    document : Document
        The document, from the registry.
    place : str or tuple of str
        The section, page, table or errata entry; several are joined by "and"; empty for the whole.
    says : str
        What the document says there, or the formula in its words (after a colon).
    note : str or Citation
        A remark in parentheses, or the citation (an errata entry) that reads the place.
    validity : Validity, optional
        Where the formula holds, as this document states it.
    label : str, optional
        The words that name document and place in the sentence, where they are not ``name, place``
        (``"a reading (spec, Motion and mechanism)"``; empty: the sentence names neither).

    Raises
    ------
    CalcError
        On a note beside a validity that stands aside (both would print in the parentheses).
    """

    document: Document
    place: str | tuple[str, ...] = ""
    says: str = ""
    note: str | Citation = ""
    validity: Validity | None = None
    label: str | None = None

    def __post_init__(self):
        if self.note and self.validity is not None and self.validity.stands == "aside":
            raise CalcError(f"citation of {as_found(self.document.name)}: a note and a validity aside would share "
                            "the parentheses; give one")

    @property
    def places(self) -> tuple[str, ...]:
        """The places cited, each on its own."""
        places = (self.place,) if isinstance(self.place, str) else self.place
        return tuple(p for p in places if p)

    @property
    def text(self) -> str:
        """The citation as the sentence prints it: ``name, place: says (note)``."""
        head = self.document.cited(self.places) if self.label is None else self.label
        says = self.says
        aside = self.note.text if isinstance(self.note, Citation) else self.note
        v = self.validity
        if v is not None:
            if v.stands == "heading":
                head = f"{head}, {v.text}"
            elif v.stands == "tail":
                says = f"{says} {v.text}"
            else:
                aside = v.text
        out = f"{head}: {says}" if head and says else head or says
        return f"{out} ({aside})" if aside else out

    def citations(self) -> Iterator[Citation]:
        """This citation and the one its note holds, if any.

        Yields
        ------
        Citation
            Each, outermost first.
        """
        yield self
        if isinstance(self.note, Citation):
            yield from self.note.citations()


class Source:
    """Where a formula comes from: its citations, and the sentence they print.

    Parameters
    ----------
    *citations : Citation
        The citations, in the order the sentence gives them.
    joined : str
        What joins them in the sentence; default ``"; "``.

    Raises
    ------
    CalcError
        On no citation, or a validity stated twice.
    """

    def __init__(self, *citations: Citation, joined: str = "; "):
        if not citations:
            raise CalcError("source: expected at least one citation, found none")
        self.citations = citations
        self.joined = joined
        stated = [c.validity for c in self.all() if c.validity is not None]
        if len(stated) > 1:
            raise CalcError(f"source {as_found(self.text)}: expected one validity, found {len(stated)}")
        self.validity: Validity | None = stated[0] if stated else None

    def __repr__(self):
        return f"Source({self.text!r})"

    @property
    def text(self) -> str:
        """The sentence a formula's reference prints."""
        return self.joined.join(c.text for c in self.citations)

    def all(self) -> Iterator[Citation]:
        """Every citation, the nested ones (a note's) included.

        Yields
        ------
        Citation
            Each, in the order of the sentence.
        """
        for c in self.citations:
            yield from c.citations()

    @property
    def documents(self) -> tuple[Document, ...]:
        """The documents cited, each once, in the order of the sentence."""
        return tuple(dict.fromkeys(c.document for c in self.all()))

    def places(self, document: Document) -> tuple[str, ...]:
        """The places of one document cited (the errata: the entries whose readings are taken).

        Parameters
        ----------
        document : Document
            The document.

        Returns
        -------
        tuple of str
            Its places, each once, in the order of the sentence.
        """
        return tuple(dict.fromkeys(p for c in self.all() if c.document is document for p in c.places))
