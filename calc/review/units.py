"""The unit system a design review's fields show (:class:`ShownUnits`): each input in the system the results are
shown in, SI or inch-pound, whatever the case file writes, while the case keeps its own units: a value typed is
read in the unit its field shows and kept in the file's, and the page's address and a saved file carry the file's.
"""

from __future__ import annotations

from ..core.units import Q_
from .inputs import InputSpec, unit_factor, unit_shown


class ShownUnits:
    """What :class:`calc.review.state.ReviewState` shows of its inputs in a unit system: it holds ``specs``,
    ``values`` and ``texts`` by key path (values in the file's units, texts as the fields show them), ``refused``,
    ``file_units``, :meth:`spec` and :meth:`changes`."""

    _units = "SI"

    @property
    def units(self) -> str:
        """The unit system of the results and of the fields shown (``"SI"``, ``"inch-pound"``)."""
        return self._units

    @units.setter
    def units(self, system: str) -> None:
        self._units = system
        for key, v in self.values.items():  # each field in that system; a refused text stays as typed
            if key not in self.refused:
                self.texts[key] = self.field_text(key, v)

    def shown_spec(self, key: str) -> InputSpec:
        """An input as its field shows it: in the unit system shown (:func:`calc.review.inputs.unit_shown`).

        Parameters
        ----------
        key : str
            Its key path.

        Returns
        -------
        calc.review.inputs.InputSpec
            The input in the unit shown (itself where that is the file's).
        """
        spec = self.spec(key)
        return spec.in_unit(unit_shown(spec.unit, self.units))

    def field_text(self, key: str, value) -> str:
        """An input's value as its field shows it, in the unit system shown.

        Parameters
        ----------
        key : str
            Its key path.
        value : float or str
            Its value [the file's unit], or a choice.

        Returns
        -------
        str
            The field's text: the file's own where the unit is the file's, else six digits of the value converted.
        """
        spec, shown = self.spec(key), self.shown_spec(key)
        return spec.shown_text(value) if shown is spec else f"{Q_(value, spec.unit).m_as(shown.unit):.6g}"

    def file_texts(self) -> dict:
        """The changed inputs' values as texts in the file's units (the page's address and the variants carry
        them, whatever the unit system shown).

        Returns
        -------
        dict
            Key path -> text.
        """
        out = {}
        for key in self.changes():
            converted = key not in self.refused and self.shown_spec(key) is not self.spec(key)
            out[key] = f"{self.values[key]:.12g}" if converted else self.texts[key]
        return out

    def unit_factors(self) -> dict:
        """Each input shown in a unit other than the file's, and what a value in the file's unit is multiplied by
        to show it (the page's script keeps a value typed while the kernel is lost in the file's unit with it).

        Returns
        -------
        dict
            Key path -> factor [shown unit / file unit].
        """
        out = {}
        for spec in self.specs:
            shown = self.shown_spec(spec.key)
            if shown is not spec:
                out[spec.key] = unit_factor(spec.unit, shown.unit)
        return out
