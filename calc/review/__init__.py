"""The live design review: a case re-evaluated whole as its inputs change.

* :mod:`.edit`: every edit of a case as a key path and the value as the file writes it, applied
  to the parsed TOML and read again by the case reader;
* :mod:`.inputs`: the inputs a reviewer changes, as a declarative list of specs (key path in the
  case file, label with unit, range, step), and :func:`with_inputs` / :func:`with_changes`, a copy
  of a case with inputs replaced (through :mod:`.edit`);
* :mod:`.state`: :class:`ReviewState`, the review without its widgets (the case, the changes,
  undo and redo, the moves' edits, the results); :mod:`.keep` the case files offered and saved,
  :mod:`.variants` the variants kept and compared;
* :mod:`.view`: what a reviewer reads of an evaluated case, as one HTML text (verdict, chosen
  parts, governing checks, candidate tables, accuracy); :mod:`.page` the panel's other texts;
* :mod:`.panel`: :class:`DesignReview`, the ipywidgets panel of notebook 12 and of the served
  page (``make review``, :mod:`.serve`), which draws the state.

ipywidgets and matplotlib are imported inside, so ``import calc`` stays light.
"""

from .inputs import InputSpec, input_specs, with_changes, with_inputs
from .panel import DesignReview
from .state import ReviewState
from .view import evaluated, results_html

__all__ = ["DesignReview", "InputSpec", "ReviewState", "evaluated", "input_specs", "results_html", "with_changes",
           "with_inputs"]
