"""The inertia of a load from its geometry: a solid cylinder (a disc, a table top), a hollow
cylinder (a ring, a tube) and a rectangular plate, each turning about an axis parallel to its own
at a distance ``e`` (Steiner's parallel-axis theorem), with its mass given or from its density.

* solid cylinder of diameter ``D``, length ``L`` along its axis: ``m = ρ·π·D²·L / 4``,
  ``J = m·D² / 8``;
* hollow cylinder, outer ``D``, inner ``d``: ``m = ρ·π·(D² − d²)·L / 4``, ``J = m·(D² + d²) / 8``;
* rectangular plate of sides ``a`` and ``b`` across the axis, thickness ``L`` along it:
  ``m = ρ·a·b·L``, ``J = m·(a² + b²) / 12``;
* about an axis at ``e`` from the body's own: ``J + m·e²``.

(Standard results of rigid-body mechanics, e.g. Dubbel, Taschenbuch für den Maschinenbau,
"Massenträgheitsmomente".)
"""

from __future__ import annotations

from dataclasses import dataclass

from ..core.citation import Source
from ..core.formula import Formula
from .documents import DUBBEL

#: The shapes a body may have.
SHAPES = ("cylinder", "hollow-cylinder", "plate")



def _handbook(says: str = "") -> Source:
    """The standard results as Dubbel gives them, with what a formula takes from them."""
    return Source(DUBBEL.at("Massenträgheitsmomente", says=says,
                            label="rigid-body mechanics (Dubbel, Massenträgheitsmomente)"))


#: The source of the shapes' mass and inertia.
REFERENCE = _handbook()

m_cylinder = Formula("m_cylinder", ("rho", "D", "L"), lambda sp, rho, D, L: rho * sp.pi * D**2 * L / 4, REFERENCE)
m_hollow = Formula("m_hollow", ("rho", "D", "d_i", "L"),
                   lambda sp, rho, D, d_i, L: rho * sp.pi * (D**2 - d_i**2) * L / 4, REFERENCE)
m_plate = Formula("m_plate", ("rho", "a", "b", "L"), lambda sp, rho, a, b, L: rho * a * b * L, REFERENCE)
J_cylinder = Formula("J_cylinder", ("m", "D"), lambda sp, m, D: m * D**2 / 8, REFERENCE)
J_hollow = Formula("J_hollow", ("m", "D", "d_i"), lambda sp, m, D, d_i: m * (D**2 + d_i**2) / 8, REFERENCE)
J_plate = Formula("J_plate", ("m", "a", "b"), lambda sp, m, a, b: m * (a**2 + b**2) / 12, REFERENCE)
J_steiner = Formula("J_body", ("J_own", "m", "e"), lambda sp, J_own, m, e: J_own + m * e**2,
                    _handbook("the parallel-axis theorem"))

#: Per shape: its mass formula and its inertia formula, and the dimensions each takes.
FORMULAS = {
    "cylinder": (m_cylinder, J_cylinder, ("D", "L")),
    "hollow-cylinder": (m_hollow, J_hollow, ("D", "d_i", "L")),
    "plate": (m_plate, J_plate, ("a", "b", "L")),
}


@dataclass(frozen=True)
class Body:
    """A body of one of :data:`SHAPES` turning about an axis.

    Parameters
    ----------
    shape : str
        One of :data:`SHAPES`.
    dimensions : dict
        Its dimensions, quantities [mm] by the names of the formulas: ``D``, ``d_i``, ``L``, ``a``,
        ``b``.
    mass : pint.Quantity [kg], optional
        Its mass; give it or ``density``.
    density : pint.Quantity [kg/m³], optional
        Its density; give it or ``mass``.
    offset : pint.Quantity [mm], optional
        The distance ``e`` of its axis from the axis of rotation.
    """

    shape: str
    dimensions: dict
    mass: object = None
    density: object = None
    offset: object = None

    def steps(self) -> list:
        """The steps giving its inertia about the axis of rotation: its mass (from the density),
        its own inertia, and the parallel-axis term where it is off the axis.

        Returns
        -------
        list of Step
            The last one's result is the inertia.
        """
        m_formula, J_formula, names = FORMULAS[self.shape]
        out = []
        mass = self.mass
        if mass is None:
            out.append(m_formula.step(rho=self.density, **{n: self.dimensions[n] for n in names}))
            mass = out[-1].result
        own = J_formula.step(m=mass, **{n: self.dimensions[n] for n in names if n in ("D", "d_i", "a", "b")})
        out.append(own)
        if self.offset is not None and self.offset.magnitude != 0:
            out.append(J_steiner.step(J_own=own.result, m=mass, e=self.offset))
        return out

    @property
    def inertia(self):
        """Its inertia about the axis of rotation."""
        return self.steps()[-1].result.to("kg*cm**2")
