"""Mechanisms between the load and the gearbox output: a rotary table, a ball screw, a rack and
pinion, a belt drive.

A rotary table sits on the output: its angle is the output's. A linear mechanism turns the output
through a transmission radius ``r`` (the load's travel per radian): ``r = p / (2π)`` of a screw of
lead ``p``, ``r = d / 2`` of a pinion's pitch diameter or a pulley's diameter. Then

* a distance as the output's angle ``φ_2 = s·rad / r`` (the radian of errata E15: one radian of
  output moves the load by r), so the motion law runs at the output (:mod:`calc.domain.motion`), and
  the load's acceleration ``a = α_2·r / rad``;
* the force on the load: ``F = (m + m_c)·a + (m·sin θ − m_c)·g + s_v·(μ·m·g·cos θ + F_p)``, with
  ``s_v`` the direction of motion (+1 forwards, −1 back, 0 at rest): inertia and gravity (up is
  forwards) act always, friction and the process force oppose the motion while it moves; a
  counterweight ``m_c`` hangs on a rope over the same lead or radius and travels as far as the load,
  the other way and vertically (a reading): its mass accelerates with the load, its weight pulls
  against the load's (on a vertical axis ``(m − m_c)·g``);
* the output torque ``T_2 = F·r·((1 + d)/(2η) + (1 − d)·η'/2) + J_M·α_2 / rad + s_v·T_d``: the
  efficiency divides the force torque while the drive drives (``d = +1``, power into the load) and
  the reverse efficiency ``η'`` multiplies it while the load drives back (``d = −1``, at rest too:
  the load held against gravity pulls back through the mechanism). A rack or a belt has ``η' = η``;
  a screw has its own, given or ``η' = 2 − 1/η`` (:data:`eta_reverse`), below η. A screw with
  ``η' ≤ 0`` is self-locking: the load cannot drive it back, the motor drives it (``F·r·η'`` turns
  against the load's pull) and at rest it holds the load itself (``η'`` taken as 0 there);
  ``J_M`` is the screw's, pinion's or pulley's own inertia, outside the efficiency;
  ``T_d`` a drag torque at that shaft (a ball screw's preload, seals), against the motion while it
  moves and outside the efficiency, none at rest;
* the load's inertia at the output ``J_L = (m + m_c)·r² + J_M`` (no efficiency).

A rotary table: ``T_2 = J_L·α_2 / rad + s_v·(T_f + T_p)``, its friction and process torque
against the motion while it moves.

These are a reading (``docs/case-format.md``, "Motion and mechanism"): g = 9.80665 m/s²; forces
that oppose motion are positive while moving forwards.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.citation import Source, Validity
from ..core.formula import Formula
from ..core.units import Q_
from .documents import ERRATA, MECHANICS, motion_reading

#: The mechanism types a case may name.
TYPES = ("rotary", "ball-screw", "rack-pinion", "belt")

#: The reading with the angle convention of E15.
_ANGLES = Source(motion_reading(), ERRATA.at("E15", label="E15"))

r_lead = Formula("r_lead", ("p",), lambda sp, p: p / (2 * sp.pi),
                 Source(motion_reading("a lead p per revolution of 2π rad")))
r_diameter = Formula("r_diameter", ("d",), lambda sp, d: d / 2, Source(motion_reading("the pitch circle's radius")))

phi_2 = Formula(
    "phi_2", ("s", "rad", "r"),
    lambda sp, s, rad, r: s * rad / r, _ANGLES,
)
a_load = Formula(
    "a_load", ("alpha_2", "r", "rad"),
    lambda sp, alpha, r, rad: alpha * r / rad, _ANGLES,
)
F = Formula(
    "F", ("m", "m_c", "a_load", "g", "theta", "s_v", "mu", "F_p"),
    lambda sp, m, m_c, a, g, theta, s_v, mu, F_p: (
        (m + m_c) * a + (m * sp.sin(theta) - m_c) * g + s_v * (mu * m * g * sp.cos(theta) + F_p)
    ),
    Source(motion_reading("inertia, gravity on the incline, a counterweight, friction of the guide and the process "
                          "force")),
)
eta_reverse = Formula(
    "eta_reverse", ("eta",),
    lambda sp, eta: 2 - 1 / eta,
    Source(MECHANICS.at(label="", says="a screw's η = tan β / tan(β + ρ) and η' = tan(β − ρ) / tan β of its lead "
                        "angle β and friction angle ρ, to first order in the angles; the ball-screw makers' catalogs "
                        "quote this approximation",
                        validity=Validity("small lead and friction angles; η' ≤ 0 (η ≤ 0.5): self-locking"))),
)
T_2_linear = Formula(
    "T_2_linear",
    ("F", "r", "eta", "eta_reverse", "d_P", "J_M", "alpha_2", "rad", "s_v", "T_d"),
    lambda sp, F, r, eta, eta_r, d_P, J_M, alpha, rad, s_v, T_d: (
        F * r * ((1 + d_P) / (2 * eta) + (1 - d_P) * eta_r / 2) + J_M * alpha / rad + s_v * T_d
    ),
    Source(motion_reading("the efficiency divides while driving, the reverse efficiency multiplies while driven back; "
                          "the drag outside it"),
           ERRATA.at("E15", label="E15")),
)
J_L_linear = Formula(
    "J_L_linear",
    ("m", "m_c", "r", "J_M"), lambda sp, m, m_c, r, J_M: (m + m_c) * r**2 + J_M,
    Source(motion_reading("the moved masses (load and counterweight) reflected through r, no efficiency")),
)
T_2_rotary = Formula(
    "T_2_rotary",
    ("J_L", "alpha_2", "rad", "s_v", "T_f", "T_p"),
    lambda sp, J_L, alpha, rad, s_v, T_f, T_p: J_L * alpha / rad + s_v * (T_f + T_p),
    Source(motion_reading(), ERRATA.at("E15", label="E15", note="J·α = T·rad")),
)


@dataclass(frozen=True)
class Mechanism:
    """A mechanism as the case gives it, quantities (checked by the case layer).

    ``type`` is one of :data:`TYPES`. A rotary table has ``inertia``, ``friction_torque`` and
    ``process_torque``; a linear one ``mass``, ``friction_coefficient``, ``incline``, ``force``,
    ``eta``, its ``lead`` (ball screw) or ``diameter`` (pinion, pulley), the own inertia
    ``own_inertia``, a ``counterweight`` and a ``drag_torque`` (None: none).

    Parameters
    ----------
    type : str
        One of :data:`TYPES`.
    inertia : pint.Quantity [kg·cm²], optional
        A table's inertia at the output.
    friction_torque : pint.Quantity [N·m], optional
        A table's friction torque.
    process_torque : pint.Quantity [N·m], optional
        A table's process torque.
    mass : pint.Quantity [kg], optional
        The moved mass of a linear axis.
    friction_coefficient : pint.Quantity [1], optional
        ``μ`` of its guide.
    incline : pint.Quantity [deg], optional
        ``θ``, the axis's angle to the horizontal.
    force : pint.Quantity [N], optional
        ``F_p``, the process force.
    eta : pint.Quantity [1], optional
        The mechanism's efficiency.
    reverse_efficiency : pint.Quantity [1], optional
        ``η'``, a screw's efficiency driven back, as the case gives it (None: from η).
    lead : pint.Quantity [mm], optional
        ``p``, a ball screw's lead.
    diameter : pint.Quantity [mm], optional
        ``d``, a pinion's or pulley's diameter.
    own_inertia : pint.Quantity [kg·cm²], optional
        ``J_M``, the screw's, pinion's or pulleys' own inertia.
    counterweight : pint.Quantity [kg], optional
        ``m_c``.
    drag_torque : pint.Quantity [N·m], optional
        ``T_d``, a drag at the shaft.
    holding_brake : bool
        A brake holds the load in a dwell (no torque there); default False.
    bodies : tuple of Body
        A rotary table's bodies, whose inertias are in ``inertia``.
    given_inertia : pint.Quantity [kg·cm²], optional
        The inertia the case gives besides the bodies.
    """

    type: str
    inertia: object = None
    friction_torque: object = None
    process_torque: object = None
    mass: object = None
    friction_coefficient: object = None
    incline: object = None
    force: object = None
    eta: object = None
    reverse_efficiency: object = None
    lead: object = None
    diameter: object = None
    own_inertia: object = None
    counterweight: object = None
    drag_torque: object = None
    holding_brake: bool = False
    bodies: tuple = ()  # calc.domain.inertia.Body of a rotary table, whose inertias are in ``inertia``
    given_inertia: object = None  # the inertia the case gives besides the bodies

    @property
    def _counterweight(self):
        return Q_(0.0, "kg") if self.counterweight is None else self.counterweight

    @property
    def _drag(self):
        return Q_(0.0, "N*m") if self.drag_torque is None else self.drag_torque

    def reverse_step(self):
        """The step giving a screw's reverse efficiency from η, where the case gives none.

        Returns
        -------
        Step or None
            ``η' = 2 − 1/η`` (dimensionless); None for a rack, a belt or a given ``η'``.
        """
        if self.type != "ball-screw" or self.reverse_efficiency is not None:
            return None
        return eta_reverse.step(eta=self.eta)

    @property
    def reverse(self):
        """``η'`` [1]: a screw's given or derived one, η of a rack or a belt."""
        if self.type != "ball-screw":
            return Q_(self.eta).to("")
        if self.reverse_efficiency is not None:
            return Q_(self.reverse_efficiency).to("")
        return self.reverse_step().result.to("")

    @property
    def self_locking(self) -> bool:
        """A screw the load cannot drive back (``η' ≤ 0``)."""
        return self.linear and float(self.reverse.m_as("")) <= 0.0

    def _reverse_at(self, speed) -> np.ndarray:
        # A self-locking screw at rest holds the load itself: no torque from the load's pull there.
        eta_r = float(self.reverse.m_as(""))
        return np.where(np.asarray(speed) == 0, max(eta_r, 0.0), eta_r)

    @property
    def linear(self) -> bool:
        return self.type != "rotary"

    @property
    def distance_kind(self) -> str:
        """What a move's distance must be: an angle on a table, a length on a linear axis."""
        return "length" if self.linear else "angle"

    def radius_step(self):
        """The step giving r (linear types): ``p / (2π)`` of a screw, ``d / 2`` else.

        Returns
        -------
        Step
            Its result in mm.
        """
        if self.type == "ball-screw":
            return r_lead.step(p=self.lead)
        return r_diameter.step(d=self.diameter)

    @property
    def radius(self):
        return self.radius_step().result

    def load_inertia_step(self):
        """The step giving J_L, the load's inertia at the output (linear types).

        Returns
        -------
        Step
            Its result in kg·cm².
        """
        return J_L_linear.step(m=self.mass, m_c=self._counterweight, r=self.radius, J_M=self.own_inertia)

    @property
    def load_inertia(self):
        """J_L at the gearbox output [kg·cm²]."""
        return self.load_inertia_step().result if self.linear else self.inertia.to("kg*cm**2")

    def to_output(self, distance):
        """A move's distance as the output's angle.

        Parameters
        ----------
        distance : pint.Quantity [deg or mm]
            An angle (a table) or a length (a linear axis).

        Returns
        -------
        pint.Quantity [rad]
            The output's angle.
        """
        if not self.linear:
            return distance.to("deg")
        return phi_2(s=distance, r=self.radius)

    def to_load(self):
        """The factor from the output's angle to the load's travel (SI floats).

        Returns
        -------
        float [m/rad or 1]
            The load's travel per radian of the output: ``r`` of a linear axis, 1 for a table.
        """
        return float(self.radius.m_as("m")) if self.linear else 1.0

    def torque(self, speed: np.ndarray, acceleration: np.ndarray) -> np.ndarray:
        """``T_2`` at output speeds and accelerations: the formulas of this module with the direction of
        motion from the speed's sign (0 at rest) and, on a linear axis, the direction of power from the
        force's. Zero at rest where a holding brake holds the load.

        Parameters
        ----------
        speed : numpy.ndarray [rad/s]
            Output speeds (SI floats).
        acceleration : numpy.ndarray [rad/s²]
            Output accelerations (SI floats).

        Returns
        -------
        numpy.ndarray [N·m]
            ``T_2`` per sample.
        """
        s_v = np.sign(speed)
        if self.linear:
            r = self.to_load()
            force = F.si(m=self._si(self.mass, "kg"), m_c=self._si(self._counterweight, "kg"),
                         a_load=a_load.si(alpha_2=acceleration, r=r), theta=self._si(self.incline, "rad"), s_v=s_v,
                         mu=self._si(self.friction_coefficient, ""), F_p=self._si(self.force, "N"))
            d_power = np.where(force * speed > 0, 1.0, -1.0)
            out = T_2_linear.si(F=force, r=r, eta=self._si(self.eta, ""), eta_reverse=self._reverse_at(speed),
                                d_P=d_power,
                                J_M=self._si(self.own_inertia, "kg*m**2"), alpha_2=acceleration,
                                s_v=s_v, T_d=self._si(self._drag, "N*m"))
        else:
            out = T_2_rotary.si(J_L=self._si(self.inertia, "kg*m**2"), alpha_2=acceleration, s_v=s_v,
                                T_f=self._si(self.friction_torque, "N*m"), T_p=self._si(self.process_torque, "N*m"))
        out = np.broadcast_to(out, np.shape(speed)).astype(float)
        if self.holding_brake:
            out[speed == 0] = 0.0
        return out

    @staticmethod
    def _si(q, unit: str) -> float:
        return float(Q_(q).m_as(unit))

    def steps(self, speed, acceleration) -> list:
        """The steps of the output torque at one output speed and acceleration: the force and the torque
        of a linear axis, the torque of a table. For the report and the notebook; the direction of
        motion and of power as :meth:`torque` takes them.

        Parameters
        ----------
        speed : pint.Quantity [rpm]
            The output speed.
        acceleration : pint.Quantity [rad/s²]
            The output acceleration.

        Returns
        -------
        list of Step
            The evaluated formulas.
        """
        w = speed.m_as("rad/s")
        s_v = Q_(float(np.sign(w)), "")
        if not self.linear:
            return [T_2_rotary.step(J_L=self.inertia, alpha_2=acceleration, s_v=s_v, T_f=self.friction_torque,
                                    T_p=self.process_torque)]
        r_q = self.radius
        acc = a_load.step(alpha_2=acceleration, r=r_q)
        f = F.step(m=self.mass, m_c=self._counterweight, a_load=acc.result, theta=self.incline, s_v=s_v,
                   mu=self.friction_coefficient, F_p=self.force)
        d_power = Q_(1.0 if f.result.m_as("N") * w > 0 else -1.0, "")
        t = T_2_linear.step(F=f.result, r=r_q, eta=self.eta, eta_reverse=Q_(float(self._reverse_at(w)), ""),
                            d_P=d_power, J_M=self.own_inertia, alpha_2=acceleration, s_v=s_v, T_d=self._drag)
        return [acc, f, t]


# -- another type for the same drive: the starting values of a mechanism changed in a review ----------

m_equivalent = Formula(
    "m_equivalent", ("J_L", "r"),
    lambda sp, J_L, r: J_L / r**2,
    Source(MECHANICS.at(label="", says="the inverse of J_L = m·r²",
                        validity=Validity("no counterweight, no own inertia"))),
)
T_d_equivalent = Formula(
    "T_d_equivalent", ("T_f", "T_p"),
    lambda sp, T_f, T_p: T_f + T_p,
    Source(MECHANICS.at(label="", says="the table's torques against the motion, at the same shaft")),
)
J_L_equivalent = Formula(
    "J_L_equivalent", ("m", "m_c", "r", "eta", "J_M"),
    lambda sp, m, m_c, r, eta, J_M: (m + m_c) * r**2 / eta + J_M,
    Source(MECHANICS.at(label="", says="T_2 while the drive accelerates the load: (m + m_c)·a·r / η + J_M·α_2")),
)
T_f_equivalent = Formula(
    "T_f_equivalent", ("mu", "m", "g", "theta", "r", "eta", "T_d"),
    lambda sp, mu, m, g, theta, r, eta, T_d: mu * m * g * sp.cos(theta) * r / eta + T_d,
    Source(MECHANICS.at(label="", says="the guide's friction and the drag while the drive drives")),
)
T_p_equivalent = Formula(
    "T_p_equivalent", ("F_p", "r", "eta"),
    lambda sp, F_p, r, eta: F_p * r / eta,
    Source(MECHANICS.at(label="", says="the process force while the drive drives")),
)


def radius_of(type_: str, size):
    """The transmission radius of a linear type from its lead (a screw) or diameter.

    Parameters
    ----------
    type_ : str
        A linear type of :data:`TYPES`.
    size : pint.Quantity [mm]
        The lead or the diameter.

    Returns
    -------
    pint.Quantity [mm]
        ``r``.
    """
    return r_lead(p=size) if type_ == "ball-screw" else r_diameter(d=size)


def converted(mech: Mechanism, type_: str, size=None) -> tuple[Mechanism, list[str]]:
    """A mechanism of ``type_`` in place of ``mech`` (a linear one of lead or diameter ``size``),
    and what it leaves out, in words: the starting values of a design whose mechanism changes.

    * Table to linear axis: the same motion and torques at the gearbox output. The moved mass has
      the table's inertia at the output (``m = J_L / r²``, η = 1, no friction of the guide) and
      the table's friction and process torque are the drag at the shaft.
    * Linear axis to table: the torques the drive gives while it drives: ``J_L = (m + m_c)·r² / η
      + J_M``, friction ``μ·m·g·cos θ·r / η + T_d``, process ``F_p·r / η``. Gravity on an incline
      and the counterweight's weight pull one way only, which a table's torques cannot: left out.
    * Linear axis to another: the same carriage (mass, forces, efficiency, own inertia) on the
      new drive of radius ``size``.

    A move's distance follows :func:`converted_distance`.

    Parameters
    ----------
    mech : Mechanism
        The mechanism replaced.
    type_ : str
        The new type, one of :data:`TYPES`.
    size : pint.Quantity [mm], optional
        The new lead or diameter (a linear type).

    Returns
    -------
    tuple of (Mechanism, list of str)
        The new mechanism and what it leaves out.

    Examples
    --------
    >>> table = Mechanism("rotary", inertia=Q_(1500, "kg*cm**2"), friction_torque=Q_(3, "N*m"),
    ...                   process_torque=Q_(0, "N*m"))
    >>> screw, left = converted(table, "ball-screw", Q_(20, "mm"))
    >>> # the mass: 0.15 / (0.02 / 2π)²
    >>> round(screw.mass.m_as("kg"), 2), screw.drag_torque, float(screw.load_inertia.m_as("kg*cm**2")), left
    (14804.41, <Quantity(3, 'newton * meter')>, 1500.0, [])
    """
    zero = {"incline": Q_(0.0, "deg"), "force": Q_(0.0, "N"), "counterweight": Q_(0.0, "kg")}
    size_key = {"lead": size} if type_ == "ball-screw" else {"diameter": size}
    if not mech.linear and type_ == "rotary":
        return mech, []
    if not mech.linear:
        r_new = radius_of(type_, size)
        return Mechanism(type_, holding_brake=mech.holding_brake,
                         mass=m_equivalent(J_L=mech.load_inertia, r=r_new).to("kg"),
                         friction_coefficient=Q_(0.0, ""), eta=Q_(1.0, ""), own_inertia=Q_(0.0, "kg*cm**2"),
                         drag_torque=T_d_equivalent(T_f=mech.friction_torque, T_p=mech.process_torque), **zero,
                         **size_key), []
    r_old, eta_old, incline = mech.radius, mech.eta, Q_(0.0, "deg") if mech.incline is None else mech.incline
    if type_ != "rotary":
        carriage = ("mass", "friction_coefficient", "incline", "force", "eta", "own_inertia", "counterweight",
                    "drag_torque", "holding_brake")
        # a screw's given reverse efficiency stays with a screw; a rack or a belt is driven back through η
        reverse = mech.reverse_efficiency if type_ == "ball-screw" else None
        left = [] if reverse is not None or mech.reverse_efficiency is None else [
            f"the screw's reverse efficiency {float(mech.reverse_efficiency.m_as('')):.4g}: a {type_} is driven back "
            "through eta"]
        return Mechanism(type_, **{k: getattr(mech, k) for k in carriage}, reverse_efficiency=reverse,
                         **size_key), left
    mu_ = Q_(0.0, "") if mech.friction_coefficient is None else mech.friction_coefficient
    own = Q_(0.0, "kg*cm**2") if mech.own_inertia is None else mech.own_inertia
    table = Mechanism("rotary", holding_brake=mech.holding_brake,
                      inertia=J_L_equivalent(m=mech.mass, m_c=mech._counterweight, r=r_old, eta=eta_old,
                                             J_M=own).to("kg*cm**2"),
                      friction_torque=T_f_equivalent(mu=mu_, m=mech.mass, theta=incline, r=r_old, eta=eta_old,
                                                     T_d=mech._drag).to("N*m"),
                      process_torque=T_p_equivalent(F_p=Q_(0.0, "N") if mech.force is None else mech.force, r=r_old,
                                                    eta=eta_old).to("N*m"))
    pulling = (mech.mass * np.sin(incline.m_as("rad")) - mech._counterweight).m_as("kg")
    left = [] if pulling == 0 else [f"gravity pulling one way ((m·sin θ − m_c)·g = {pulling * 9.80665:.4g} N on the "
                                    "load): a table's torques oppose the motion"]
    if mech.force is not None and mech.force.m_as("N") < 0:
        left.append("a process force that drives the load (negative) is taken as one against it")
    return table, left


def converted_distance(old: Mechanism, new: Mechanism, distance):
    """A move's distance for the mechanism ``new`` that replaced ``old`` (:func:`converted`): the
    same travel of the carriage from one linear axis to another, else the same angle of the
    gearbox output.

    Parameters
    ----------
    old : Mechanism
        The mechanism replaced.
    new : Mechanism
        Its replacement.
    distance : pint.Quantity [deg or mm]
        The move's distance on ``old``.

    Returns
    -------
    pint.Quantity [deg or mm]
        The distance on ``new``.
    """
    if old.linear and new.linear:
        return distance
    angle = old.to_output(distance)
    return angle.to("deg") if not new.linear else (angle.to("rad").magnitude * new.radius).to("mm")
