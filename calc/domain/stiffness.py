"""Torsional stiffness of a drive train: springs in series, referred to the output shaft.

Source: "Torsional Stiffness" ("How can I use it?"), read with errata E11. The components of a
drive train (couplings, gearbox, shafts, line shafts) carry the same torque one after the other,
so their twists add and their compliances ``1/C`` add. That sum holds only when every ``C`` is
seen from the same shaft (E11): a component on the input side of a gearbox of ratio ``i`` turns
``i`` times as far under ``1/i`` of the torque, so seen from the output it is ``i²`` times as
stiff, and its backlash is ``1/i`` as large. Every figure here is referred to the output.

A :class:`Chain` holds the components from drive to load, each on the ``input`` or ``output``
side of the gearbox; its arrays run over the components (one formula call for all of them).

The source's example, ``1/C_total = 1/1.3 + 1/0.24`` (N·m/arcmin), with both parts on the output:

>>> print(series_stiffness.step(C_k=Q_([1.3, 0.24], "N*m/arcmin")))
C_total = 0.2026 N·m/arcmin

A motor-side coupling of 0.24 N·m/arcmin behind a 10:1 gearbox, seen from the output (E11):

>>> print(stiffness_at_output.step(C_1=Q_(0.24, "N*m/arcmin"), i=Q_(10, "")))
C_2 = 24 N·m/arcmin

A strain-wave gear's stiffness is not one slope: its makers publish three, ``K_1`` up to the limit
torque ``T_1``, ``K_2`` up to ``T_2`` and ``K_3`` above (:class:`StiffnessCurve`). A member with
such a curve twists by the curve, and the chain's twist at a torque is the sum of its members'
twists at that torque. Where one stiffness stands for the chain (``C_total``, the lost motion
``j_t + |T| / C``, the 3 % rule), it is the **secant** at the applied torque, ``|T| / φ(T)``
(:meth:`Chain.at_torque`): the one slope that gives the curve's own twist at that torque. At zero
torque the secant is the first slope ``K_1``.
"""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass

import numpy as np

from ..core.citation import Band, Source, Validity
from ..core.errors import CalcError, as_found
from ..core.formula import Formula, segment_sum
from ..core.glossary import symbol
from ..core.units import Q_, as_kind, fmt
from .documents import ERRATA, HARMONIC_DRIVE, MECHANICS, SOURCE

SIDES = ("input", "output")

series_stiffness = Formula(
    "C_total",
    ("C_k",),
    lambda sp, C: 1 / segment_sum(1 / C),
    Source(SOURCE.at("Torsional Stiffness", says="1/C_total = 1/C_1 + ... + 1/C_n"),
           ERRATA.at("E11", note="every C_k at the output")),
)

stiffness_at_output = Formula(
    "C_2",
    ("C_1", "i"),
    lambda sp, C_1, i: C_1 * i**2,
    Source(ERRATA.at("E11", says="an input-side component appears at the output with stiffness C · i²")),
)

angle_at_output = Formula(
    symbol("phi_2").shown_in("arcmin"),
    ("phi_1", "i"),
    lambda sp, phi_1, i: phi_1 / i,
    Source(ERRATA.at("E11", says="an input-side backlash appears at the output as backlash / i")),
)

torque_at_output = Formula(
    "T_2",
    ("T_1", "i"),
    lambda sp, T_1, i: T_1 * i,
    Source(MECHANICS.at(label="", says="torque through an ideal gearbox",
                        note="losses left out: a rating at the input limits the output to T_1 · i")),
)




def _curve(validity: str, band: Band) -> Source:
    """The makers' curve of three slopes, and the band of torque a slope holds over."""
    return Source(HARMONIC_DRIVE.at(
        says="torsional stiffness as three slopes K_1, K_2, K_3 with limit torques T_1, T_2",
        validity=Validity(validity, band)))


twist_low = Formula(
    "phi_c1",
    ("T", "K_1"),
    lambda sp, T, K_1: T / K_1,
    _curve("T <= T_1", Band("T", upto=(1, "T_L1"))),
)

twist_middle = Formula(
    "phi_c2",
    ("T", "T_L1", "K_1", "K_2"),
    lambda sp, T, T_L1, K_1, K_2: sp.Add(T_L1 / K_1, (T - T_L1) / K_2, evaluate=False),
    _curve("T_1 < T <= T_2", Band("T", above=(1, "T_L1"), upto=(1, "T_L2"))),
)

twist_high = Formula(
    "phi_c3",
    ("T", "T_L1", "T_L2", "K_1", "K_2", "K_3"),
    lambda sp, T, T_L1, T_L2, K_1, K_2, K_3: sp.Add(T_L1 / K_1, (T_L2 - T_L1) / K_2, (T - T_L2) / K_3,
                                                    evaluate=False),
    _curve("T > T_2", Band("T", above=(1, "T_L2"))),
)

secant_stiffness = Formula(
    "C_sec",
    ("T", "phi"),
    lambda sp, T, phi: T / phi,
    Source(MECHANICS.at(label="", says="the one slope that gives a curve's own twist at the torque: C = |T| / φ(T)")),
)


@dataclass(frozen=True)
class StiffnessCurve:
    """Torsional stiffness as three slopes, as strain-wave gear makers publish it: ``K_1`` from 0
    to the limit torque ``T_1``, ``K_2`` from ``T_1`` to ``T_2``, ``K_3`` above ``T_2``.

    The twist under a torque of either sign is the curve's at ``|T|`` (a gear's curve is
    published for one direction; the other is taken as its mirror).

    Parameters
    ----------
    T_1 : pint.Quantity [N·m]
        The first limit torque.
    T_2 : pint.Quantity [N·m]
        The second limit torque, above ``T_1``.
    K_1, K_2, K_3 : pint.Quantity [N·m/rad]
        The slopes below ``T_1``, from ``T_1`` to ``T_2``, above ``T_2``.
    where : str
        The key, for error messages; default ``"stiffness_curve"``.

    Examples
    --------
    Harmonic Drive's engineering data for HFUC-32-100: T_1 = 29 N·m, K_1 = 6.7·10⁴ N·m/rad,
    T_2 = 108 N·m, K_2 = 1.1·10⁵ N·m/rad; at 60 N·m, φ = 29/6.7e4 + 31/1.1e5 = 7.15·10⁻⁴ rad
    (``K_3`` does not enter below ``T_2``; 1.2·10⁵ N·m/rad here stands in for it):

    >>> hfuc = StiffnessCurve(Q_(29, "N*m"), Q_(108, "N*m"), Q_(6.7e4, "N*m/rad"), Q_(1.1e5, "N*m/rad"),
    ...                       Q_(1.2e5, "N*m/rad"))
    >>> print(f"{hfuc.twist(Q_(60, 'N*m')).m_as('rad'):.2e}")
    7.15e-04
    """

    T_1: object
    T_2: object
    K_1: object
    K_2: object
    K_3: object
    where: str = "stiffness_curve"

    def __post_init__(self):
        for key, k in (("T_1", "torque"), ("T_2", "torque"), ("K_1", "stiffness"), ("K_2", "stiffness"),
                       ("K_3", "stiffness")):
            name = key.replace("_", "")  # T_1 is T1 in a case file
            q = as_kind(getattr(self, key), k, f"{self.where}.{name}")
            if not np.all(q.magnitude > 0):
                raise CalcError(
                    f"{self.where}.{name}: expected {'a torque' if k == 'torque' else 'a slope'} above zero, found "
                    f"{fmt(q, 'N*m' if k == 'torque' else 'N*m/rad')}"
                )
        if not self.T_2.m_as("N*m") > self.T_1.m_as("N*m"):
            raise CalcError(f"{self.where}.T2: expected a limit torque above T1 = {fmt(self.T_1, 'N*m')}, found "
                            f"{fmt(self.T_2, 'N*m')}")

    def band(self, torque) -> np.ndarray:
        """The slope ``|T|`` falls on: 0 up to ``T_1``, 1 up to ``T_2``, 2 above (a limit torque
        belongs to the band below it).

        Parameters
        ----------
        torque : pint.Quantity [N·m]
            Scalar or array, either sign.

        Returns
        -------
        numpy.ndarray of int
            The band of each torque.
        """
        x = abs(as_kind(torque, "torque", "torque")).m_as("N*m")
        return np.searchsorted([self.T_1.m_as("N*m"), self.T_2.m_as("N*m")], x, side="left")

    def _band_formulas(self) -> tuple:
        """The twist formula of each band, with the curve's figures it takes."""
        low = dict(K_1=self.K_1)
        middle = dict(low, T_L1=self.T_1, K_2=self.K_2)
        return (twist_low, low), (twist_middle, middle), (twist_high, dict(middle, T_L2=self.T_2, K_3=self.K_3))

    def twist(self, torque):
        """The twist under ``torque``: by the slope of the band ``|T|`` falls in (the three formulas
        :data:`twist_low`, :data:`twist_middle`, :data:`twist_high`).

        Parameters
        ----------
        torque : pint.Quantity [N·m]
            Scalar or array, either sign.

        Returns
        -------
        pint.Quantity [arcmin]
            The twist at each torque.
        """
        t = abs(as_kind(torque, "torque", "torque"))
        by_band = [f(T=t, **figures).m_as("arcmin") for f, figures in self._band_formulas()]
        return Q_(np.choose(self.band(t), np.broadcast_arrays(*by_band))[()], "arcmin")

    def steps(self, torque) -> list:
        """The twist at ``torque`` by the formula of its band, and the secant stiffness from it.

        Parameters
        ----------
        torque : pint.Quantity [N·m]
            One torque.

        Returns
        -------
        list of Step
            The twist, and the secant stiffness where the torque is not zero.
        """
        t = abs(as_kind(torque, "torque", "torque"))
        formula, figures = self._band_formulas()[int(self.band(t))]
        twist = formula.step(T=t, **figures)
        return [twist] if t.m_as("N*m") == 0 else [twist, secant_stiffness.step(T=t, phi=twist.result)]

    def secant(self, torque):
        """The secant stiffness ``|T| / φ(T)``; up to ``T_1``, zero torque included, that is ``K_1``
        itself.

        Parameters
        ----------
        torque : pint.Quantity [N·m]
            Scalar or array, either sign.

        Returns
        -------
        pint.Quantity [N·m/arcmin]
            The secant stiffness at each torque.
        """
        t = abs(as_kind(torque, "torque", "torque"))
        first = t.m_as("N*m") <= self.T_1.m_as("N*m")
        with np.errstate(invalid="ignore", divide="ignore"):
            c = secant_stiffness(T=t, phi=self.twist(t)).m_as("N*m/arcmin")
        return Q_(np.where(first, self.K_1.m_as("N*m/arcmin"), c)[()], "N*m/arcmin")


@dataclass(frozen=True)
class Component:
    """One member of a drive train, with its figures as seen from its own shaft.

    Parameters
    ----------
    name : str
        What it is (``"EKM-15 coupling"``, a catalog part).
    side : {"input", "output"}
        Which side of the gearbox it sits on; the gearbox itself gives its figures at its output
        (``C_t21``), so it is an ``"output"`` component.
    stiffness : pint.Quantity [N·m/arcmin]
        Torsional stiffness, above zero.
    backlash : pint.Quantity [arcmin]
        Torsional backlash, zero or more.
    transmission_accuracy : pint.Quantity [arcmin], optional
        Angular transmission accuracy (range of the transmission error over one revolution).
    nominal_torque : pint.Quantity [N·m], optional
        Nominal torque (the 3 % rule of positioning accuracy, E13).
    source : str
        Where the figures come from (the case, a catalog row, a measured loop).
    stiffness_curve : StiffnessCurve, optional
        The member's stiffness as three slopes; its ``stiffness`` is then the first slope
        ``K_1`` until the chain is taken at a torque (:meth:`Chain.at_torque`).
    """

    name: str
    side: str
    stiffness: object
    backlash: object
    transmission_accuracy: object = None
    nominal_torque: object = None
    source: str = ""
    stiffness_curve: StiffnessCurve | None = None

    def __post_init__(self):
        where = f"component {self.name!r}"
        if self.side not in SIDES:
            raise CalcError(f"{where}: side: expected input or output, found {as_found(self.side)}")
        c = as_kind(self.stiffness, "stiffness", f"{where}: stiffness")
        if not np.all(c.magnitude > 0):
            raise CalcError(f"{where}: stiffness: expected a stiffness above zero, found {c:~P}")
        for key, kind in (("backlash", "angle"), ("transmission_accuracy", "angle"), ("nominal_torque", "torque")):
            q = getattr(self, key)
            if q is None:
                continue
            q = as_kind(q, kind, f"{where}: {key}")
            if key == "nominal_torque" and not q.magnitude > 0:
                raise CalcError(f"{where}: {key}: expected a torque above zero, found {q:~P}")
            if not q.magnitude >= 0:
                raise CalcError(f"{where}: {key}: expected an angle of zero or more, found {q:~P}")
        if self.backlash is None:
            raise CalcError(f"{where}: backlash: expected an angle such as \"3 arcmin\" (0 arcmin for none), found "
                            "none")


@dataclass(frozen=True)
class Chain:
    """Components from drive to load, every figure referred to the output shaft (E11).

    Parameters
    ----------
    components : tuple of Component
        The members, drive to load.
    ratio : pint.Quantity [1], optional
        The gearbox's ratio ``i``; needed as soon as one component sits on the input side.

    Examples
    --------
    >>> coupling = Component("EKM-15", "output", Q_(0.24, "N*m/arcmin"), Q_(0, "arcmin"))
    >>> gearbox = Component("EPL-W-064 10:1", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin"))
    >>> round(float(Chain((coupling, gearbox)).stiffness.m_as("N*m/arcmin")), 2)
    0.2
    >>> motor_side = Component("EKM-15", "input", Q_(0.24, "N*m/arcmin"), Q_(0, "arcmin"))
    >>> round(float(Chain((motor_side, gearbox), ratio=Q_(10, "")).stiffness.m_as("N*m/arcmin")), 2)
    1.23
    """

    components: tuple
    ratio: object = None

    def __post_init__(self):
        if not self.components:
            raise CalcError("chain: expected at least one component, found none")
        if self.ratio is not None:
            i = as_kind(self.ratio, "dimensionless", "chain: ratio").m_as("")
            if not i > 0:
                raise CalcError(f"chain: ratio: expected a ratio above zero, found {i:g}")
        elif any(c.side == "input" for c in self.components):
            first = next(c for c in self.components if c.side == "input")
            raise CalcError(
                f"component {as_found(first.name)}: sits on the input side, which is referred to the output "
                "through the "
                "gearbox ratio (E11), found no ratio"
            )

    def with_component(self, component: Component) -> "Chain":
        """The chain with one more component at its load end.

        Parameters
        ----------
        component : Component
            The member added.

        Returns
        -------
        Chain
            A new chain.
        """
        return Chain((*self.components, component), self.ratio)

    @property
    def has_curves(self) -> bool:
        """Whether a member gives a stiffness curve (:class:`StiffnessCurve`)."""
        return any(c.stiffness_curve is not None for c in self.components)

    def at_torque(self, torque) -> "Chain":
        """The chain at an output torque: each member with a stiffness curve stands in with its
        secant stiffness at the torque it carries (``|T| / i`` on the input side), so that
        ``|T| / C_k`` is the curve's own twist and ``C_total`` the chain's secant. A chain without
        curves is returned as it is.

        Parameters
        ----------
        torque : pint.Quantity [N·m]
            The torque at the output.

        Returns
        -------
        Chain
            The chain with secant stiffnesses.
        """
        if not self.has_curves:
            return self
        t = abs(as_kind(torque, "torque", "torque"))
        members = []
        for c, i in zip(self.components, self._i.magnitude):
            if c.stiffness_curve is not None:
                c = dataclasses.replace(c, stiffness=c.stiffness_curve.secant(t / i))
            members.append(c)
        return Chain(tuple(members), self.ratio)

    def stiffness_at(self, torque):
        """The chain's stiffness at the output at each torque (scalar or array): ``C_total`` for a
        chain without curves; with curves the secant ``|T| / Σ φ_k(T)`` (at zero torque, the
        series of the first slopes).

        Parameters
        ----------
        torque : pint.Quantity [N·m]
            The torque at the output, scalar or array.

        Returns
        -------
        pint.Quantity [N·m/arcmin]
            The chain's stiffness at each torque.
        """
        if not self.has_curves:
            return self.stiffness
        t = abs(as_kind(torque, "torque", "torque"))
        x = np.atleast_1d(t.m_as("N*m"))
        c = np.array([self.at_torque(Q_(v, "N*m")).stiffness.m_as("N*m/arcmin") for v in x])
        return Q_(c.reshape(np.shape(t.magnitude))[()], "N*m/arcmin")

    @functools.cached_property
    def _i(self):
        """Each component's ratio to the output: ``i`` on the input side, 1 on the output side."""
        i = 1.0 if self.ratio is None else self.ratio.m_as("")
        return Q_(np.array([i if c.side == "input" else 1.0 for c in self.components]), "")

    def _column(self, key: str, unit: str) -> object:
        return Q_(np.array([np.nan if getattr(c, key) is None else getattr(c, key).m_as(unit)
                            for c in self.components]), unit)

    @property
    def names(self) -> list[str]:
        return [c.name for c in self.components]

    @functools.cached_property
    def stiffness_at_output(self):
        """Each component's stiffness seen from the output, ``C · i²`` on the input side (E11)."""
        return stiffness_at_output(C_1=self._column("stiffness", "N*m/arcmin"), i=self._i)

    @functools.cached_property
    def backlash_at_output(self):
        """Each component's backlash seen from the output, ``backlash / i`` on the input side (E11)."""
        return angle_at_output(phi_1=self._column("backlash", "arcmin"), i=self._i)

    @functools.cached_property
    def transmission_accuracy_at_output(self):
        """Each component's angular transmission accuracy at the output (NaN where not given)."""
        return angle_at_output(phi_1=self._column("transmission_accuracy", "arcsec"), i=self._i).to("arcsec")

    @functools.cached_property
    def nominal_torque_at_output(self):
        """Each component's nominal torque at the output, ``T · i`` on the input side (NaN where not given)."""
        return torque_at_output(T_1=self._column("nominal_torque", "N*m"), i=self._i)

    @functools.cached_property
    def stiffness(self):
        """Total stiffness at the output, ``1 / Σ 1/C_k`` (E11)."""
        return series_stiffness(C_k=self.stiffness_at_output)

    @property
    def compliance_shares(self) -> np.ndarray:
        """Each component's share of the total compliance, ``(1/C_k) / Σ 1/C`` (sums to 1); it is
        also its share of the twist under any torque, since every component carries the same."""
        return (self.stiffness / self.stiffness_at_output).m_as("")  # (1/C_k) / (1/C_total)

    def twist(self, torque):
        """Each component's twist under ``torque`` at the output, ``|T| / C_k`` (the sum is
        ``|T| / C_total``); a member with a stiffness curve twists by its curve.

        Parameters
        ----------
        torque : pint.Quantity [N·m]
            The torque at the output.

        Returns
        -------
        pint.Quantity [arcmin]
            Each component's twist, drive to load (an array).
        """
        t = as_kind(torque, "torque", "torque")
        return (abs(t) / self.at_torque(t).stiffness_at_output).to("arcmin")

    @property
    def backlash(self):
        """Total backlash at the output: the sum of the components' (E11, E12)."""
        return self.backlash_at_output.sum()

    @property
    def transmission_accuracy(self):
        """Worst-case angular transmission accuracy at the output: the sum over the components
        that give one (a coupling transmits the angle one to one and gives none)."""
        return Q_(np.nansum(self.transmission_accuracy_at_output.m_as("arcsec")), "arcsec")

    @property
    def transmission_accuracy_from(self) -> list[str]:
        """Names of the components that give a transmission accuracy."""
        return [n for n, v in zip(self.names, self.transmission_accuracy_at_output.magnitude) if not np.isnan(v)]

    @property
    def nominal_torque(self):
        """The chain's nominal torque at the output: the lowest of those given (None if none is)."""
        t = self.nominal_torque_at_output.m_as("N*m")
        return None if np.isnan(t).all() else Q_(float(np.nanmin(t)), "N*m")

    @property
    def nominal_torque_from(self) -> str | None:
        """Name of the component whose nominal torque is the chain's."""
        t = self.nominal_torque_at_output.m_as("N*m")
        return None if np.isnan(t).all() else self.names[int(np.nanargmin(t))]
