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

ipywidgets and matplotlib are imported inside, so ``import calc`` stays light. The names below are
imported when first asked for, so the server (:mod:`.serve`, which starts Voilà) does not wait for them.
"""

import importlib

#: Each name the package offers, by the module that defines it.
_HOMES = {"InputSpec": "inputs", "input_specs": "inputs", "with_changes": "inputs", "with_inputs": "inputs",
          "DesignReview": "panel", "ReviewState": "state", "evaluated": "view", "results_html": "view"}

__all__ = ["DesignReview", "InputSpec", "ReviewState", "evaluated", "input_specs", "results_html", "with_changes",
           "with_inputs"]


def __getattr__(name: str):
    if name in _HOMES:
        return getattr(importlib.import_module(f".{_HOMES[name]}", __name__), name)
    raise AttributeError(f"module 'calc.review' has no attribute {name!r}")
