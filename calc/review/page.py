"""The HTML texts the design-review panel shows of its state (:mod:`calc.review.state`): each
input's label, the message under its row, and the results with the state they were computed for.

The results carry that state as attributes, which the page's script (:mod:`calc.review.client`)
compares with the fields and writes into the page's address: ``data-inputs`` (each field's text),
``data-changed`` (those of the changed inputs), ``data-edits`` (the moves' edits), ``data-case``,
``data-units`` and ``data-file-units`` (with ``data-factors``, what a value in the file's unit is multiplied by
for each field shown in another unit), ``data-variants`` and ``data-variants-asked``
(:func:`variants_attribute`), and ``data-generation`` (counting the results drawn).
"""

from __future__ import annotations

import functools

import json
import re
from html import escape

from ..core.units import pretty_unit
from ..report.page import FAIL_COLOR
from ..report.provenance import PACKAGE, build_date, git_commit, sha256
from ..report.symbols import html as typeset
from .inputs import InputSpec
from .state import ReviewState, Screen
from .variants import Variants
from .view import results_html

SHOWN_CANDIDATES = 6  # rows of each candidate table, best first, unless all are asked for


def label_html(spec: InputSpec, changed: bool, added: str | None = None, follows: str | None = None,
               shown: InputSpec | None = None) -> str:
    """An input's label with its unit (the whole of it, and what became of the file's value, as
    its tooltip; its key path as ``data-key``), marked where changed or made by an edit of the moves.

    Parameters
    ----------
    spec : InputSpec
        The input.
    changed : bool
        Whether its value differs from the file's.
    added : str, optional
        What an edit of the moves made of it, in words.
    follows : str, optional
        What its value follows where the file leaves it out, in words
        (:meth:`calc.review.state.ReviewState.following`): shown under the label.
    shown : InputSpec, optional
        The input in the unit its field shows (:meth:`calc.review.state.ReviewState.shown_spec`); by default
        ``spec``. The file's value is said in the file's unit.

    Returns
    -------
    str
        HTML.
    """
    shown = spec if shown is None else shown
    file_value = spec.shown_text(spec.value)
    file_value += f" {pretty_unit(spec.unit)}" if spec.unit else ""
    unit = pretty_unit(shown.unit) if shown.unit else ""
    was = f" ({added})" if added else f" (changed; the file: {file_value})" if changed else ""
    marked = " class=dr-changed" if changed or added else ""
    was += f" ({follows})" if follows and not was else ""
    note = f"<br><small class=dr-follows>{typeset(follows)}</small>" if follows else ""
    return (f'<span title="{escape(shown.text + was)}" data-key="{escape(spec.key)}"{marked}>'
            f"{typeset(spec.label)}{f' [{unit}]' if unit else ''}{note}</span>")


def message_html(refused: str | None, idle: str | None = None) -> str:
    """The message under an input's row: why its text was refused, else that it has no effect.

    Parameters
    ----------
    refused : str or None
        Why the text typed was refused.
    idle : str, optional
        Why the input has no effect on the design.

    Returns
    -------
    str
        HTML (empty where there is nothing to say).
    """
    if refused:
        return f'<div class="dr-message">{typeset(refused)}</div>'
    return f'<div class="dr-idle">{typeset(idle)}</div>' if idle else ""


def failed_html(word: str, why: str, whole: bool = False) -> str:
    """What could not be done and why, as the page says it: under the case and in the results the
    word stands out; under the buttons (``whole``) all of it.

    Parameters
    ----------
    word : str
        What was not done (``"not added"``, ``"input error"``, ``"not saved"``).
    why : str
        The sentence saying why.
    whole : bool
        Whether the whole of it is marked, not the word alone.

    Returns
    -------
    str
        HTML.
    """
    if whole:
        return f'<span style="color:{FAIL_COLOR}">{word}: {typeset(why)}</span>'
    return f'<b style="color:{FAIL_COLOR}">{word}</b>: {typeset(why)}'


def link_html(address: str | None, pdf) -> str:
    """A PDF built by the panel: linked at ``address``, else named by its path.

    Parameters
    ----------
    address : str or None
        Where the page serves it.
    pdf : pathlib.Path
        The PDF.

    Returns
    -------
    str
        HTML.
    """
    return f'<a href="{escape(address)}" target="_blank">{escape(pdf.name)}</a>' if address else escape(str(pdf))


def variants_attribute(variants: Variants) -> str:
    """The variants' states, and those a link asked for (which the page's script waits for).

    Parameters
    ----------
    variants : calc.review.variants.Variants
        The variants kept.

    Returns
    -------
    str
        The two attributes of the results (HTML).
    """
    return (f'data-variants="{escape(json.dumps(variants.states))}" '
            f'data-variants-asked="{escape(json.dumps(variants.asked))}"')


def with_variants(results: str, variants: Variants) -> str:
    """The results carrying the variants' states as they now are.

    Parameters
    ----------
    results : str
        The results' HTML (:func:`results_text`).
    variants : calc.review.variants.Variants
        The variants kept.

    Returns
    -------
    str
        The results' HTML, its ``data-variants`` and ``data-variants-asked`` written again.
    """
    return re.sub(r'data-variants="[^"]*" data-variants-asked="[^"]*"', variants_attribute(variants), results, count=1)


@functools.cache
def _commit() -> str:
    """The package's commit, looked up once (a git call costs some 10 ms, too much for every change)."""
    return git_commit()


def print_head(state: ReviewState) -> str:
    """The title block a printed page starts with (shown in print only): the case file and its
    SHA-256, whether the screen changed it, when the results were computed, the package's version
    and commit.

    Parameters
    ----------
    state : calc.review.state.ReviewState
        The state evaluated.

    Returns
    -------
    str
        HTML: one ``div`` of class ``dr-print-head``.
    """
    try:
        digest = f" (sha256 {sha256(state.path)[:16]})"
    except OSError:
        digest = ""
    changed = " with the changes marked on the page" if state.modified() else ""
    computed = build_date()
    running = css_string(f"Design review of {state.path.name}{' (changed)' if changed else ''} · computed {computed} "
                         f"· {PACKAGE}")
    head = f"@page {{ @top-left {{ content: {running}; font: 8pt sans-serif; color: #333; }} }}"  # on every page
    return (f"<style>@media print {{ {head} }}</style>"
            f'<div class="dr-print-head">Design review of {escape(state.path.name)}{digest}{changed} · '
            f"computed {computed} · {escape(PACKAGE)} · commit {escape(_commit())}</div>")


def css_string(text: str) -> str:
    """A text as a CSS string, in a style element of an HTML page: its quotes and backslashes escaped, a line
    break a space, and ``<`` escaped, so no text (a case file's name) can end the style element.

    Parameters
    ----------
    text : str
        The text.

    Returns
    -------
    str
        The CSS string, quoted.

    Examples
    --------
    >>> print(css_string('a "b" </style>'))
    "a \\"b\\" \\3c /style>"
    """
    quoted = text.replace("\\", "\\\\").replace('"', '\\"').replace("<", "\\3c ")
    return '"' + re.sub(r"[\x00-\x1f\x7f]", " ", quoted) + '"'


def results_text(state: ReviewState, screen: Screen, link: str | None, generation: int, variants: Variants) -> str:
    """The results of ``screen`` (:func:`calc.review.view.results_html`: verdict and chosen parts
    first, then the governing checks), or its input error, with the state they were computed for
    (see the module's docstring).

    Parameters
    ----------
    state : calc.review.state.ReviewState
        The state evaluated (its options, refusals and unit system).
    screen : calc.review.state.Screen
        Its results.
    link : str or None
        The address of the case's report, beside the verdict.
    generation : int
        The results drawn so far, these included.
    variants : calc.review.variants.Variants
        The variants kept (their states go with the results).

    Returns
    -------
    str
        HTML.
    """
    if screen.report is None:
        text = f'<div class="dr">{failed_html("input error", screen.error)}</div>'
    else:
        refused = [f"{state.spec(k).label}: {why}" for k, (_, why) in state.refused.items()]
        text = results_html(screen.report, screen.left_out, link, typed_by_hand=screen.typed_by_hand,
                            shown=None if state.all_candidates else SHOWN_CANDIDATES, refused=refused,
                            system=state.units, ratios=screen.ratios)
    text = text.replace('<div class="dr">', '<div class="dr">' + print_head(state), 1)
    attributes = (f'data-generation="{generation}" data-case="{escape(state.path.name)}" '
                  f'data-inputs="{escape(json.dumps(screen.texts))}" data-edits="{escape(json.dumps(screen.moves))}" '
                  f'data-units="{escape(state.units)}" data-file-units="{escape(state.file_units)}" '
                  f'data-factors="{escape(json.dumps(screen.factors))}" '
                  f'{variants_attribute(variants)} '
                  f'data-changed="{escape(json.dumps(screen.changed_texts))}"')
    return text.replace('<div class="dr">', f'<div class="dr" {attributes}>', 1)
