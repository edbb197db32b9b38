"""The live design review: a case re-evaluated whole as its inputs change.

* :mod:`.inputs`: the inputs a reviewer changes, as a declarative list of specs (key path in the
  case file, label with unit, range, step), and :func:`with_inputs` / :func:`with_changes`, a copy
  of a case with inputs replaced;
* :mod:`.view`: what a reviewer reads of an evaluated case, as one HTML text (verdict, chosen
  parts, governing checks, candidate tables, accuracy);
* :mod:`.panel`: :class:`DesignReview`, the ipywidgets panel of notebook 07 and of the served
  page (``make review``, :mod:`.serve`).

ipywidgets and matplotlib are imported inside, so ``import calc`` stays light.
"""

from .inputs import InputSpec, input_specs, with_changes, with_inputs
from .panel import DesignReview
from .view import evaluated, results_html

__all__ = ["DesignReview", "InputSpec", "evaluated", "input_specs", "results_html", "with_changes", "with_inputs"]
