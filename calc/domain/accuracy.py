"""Lost motion, positioning accuracy and repeatability of a drive train, and the case's ``[accuracy]``.

Source: "Lost Motion" ("How can I use it?"), "Accuracy and Repeatability", read with errata E11
to E15. Everything is referred to the output shaft (E11, :mod:`calc.domain.stiffness`).

* Total lost motion at the applied torque is the backlash plus the twist under that torque,
  ``j_t + |T| / C`` (:data:`lost_motion`, the source's formula, E12). Summed over the components
  of a chain it is the chain's backlash plus ``|T| / C_total``.
* Positioning accuracy by the source's 3 % rule (E13): at a torque up to 3 % of the nominal
  torque the backlash is not taken up, ``φ_TA + j_t`` (:data:`positioning_accuracy_low`);
  above, the twist is what counts, ``φ_TA + |T| / C`` (:data:`positioning_accuracy_high`).
* Repeatability (E13): at ``T = 0`` it is the backlash; under torque it is bounded by the lost
  motion at that torque (:func:`repeatability`). The bound is loose: a repeated approach under
  the same torque ends within the backlash and the scatter of the drive, not the whole twist;
  what the 3 % rule decides is whether the torque changes sign between approaches (a torque
  that keeps its sign holds the flanks in contact, and the backlash does not enter).
* A measured positioning record (a target and the actual position, each target approached
  several times) gives the measured accuracy, the largest error, and repeatability, the largest
  spread at one target (:func:`analyze_positions`).
* The positioning accuracy is a **full width** (:data:`POSITIONING_CONVENTION`): the range of the
  position error, as E13 sums a range (``φ_TA``, E14) and a full play (``j_t``); positioned
  "within ±a" means a full width of 2a. Repeatability is a full width too (the spread at one
  target), so under torque it is bounded by the tighter of the lost motion and the positioning
  accuracy (:attr:`ChainAccuracy.repeatability_bound`).
* The error budget (:func:`error_budget`) splits the positioning accuracy into its contributions,
  each **systematic** (a load-independent transmission error, the same at every approach of an
  angle, which a controller can map out) or **random** (backlash, the twist under a process torque
  that scatters), with the worst case (every contribution added, the package's positioning
  accuracy) and the root-sum-square of the independent contributions.

The case's ``[accuracy]`` table (``docs/case-format.md``) is read by :func:`read_accuracy` and
evaluated by :func:`section_results` (the JSON contract) and :func:`summary_lines`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.checks import BOUNDARY_RTOL
from ..core.citation import Band, Source, Validity
from ..data.catalog import Column
from ..core.errors import CalcError
from ..core.formula import Formula, segment_sum
from ..data.measurement import check_pair, read_measurement
from .documents import ERRATA, MECHANICS, SOURCE
from .hysteresis import LOW_TORQUE_SHARE
from .stiffness import Chain, Component, angle_at_output, series_stiffness, stiffness_at_output  # noqa: F401 (Component: the doctests)
from ..core.units import Q_, as_kind, fmt  # noqa: F401 (fmt: the doctests print with it)

#: The one convention of the positioning accuracy, said once: package, notebooks and report follow it.
POSITIONING_CONVENTION = ("full width: the range of the position error, peak to peak (E13 sums the range φ_TA and "
                          "the full backlash); ± half of it about its middle")

#: The kinds of a contribution to the error budget, and what each means.
BUDGET_KINDS = {
    "systematic": "load-independent and the same at every approach of an angle: a controller can map it out",
    "random": "scatters from approach to approach (which flank carries, a process torque that varies)",
}

budget_worst_case = Formula(
    "Delta_phi_wc",
    ("phi_e_k",),
    lambda sp, phi: segment_sum(phi),
    Source(SOURCE.at("Positioning Accuracy", says="the terms added: transmission accuracy + backlash, or + applied "
                     "torque / stiffness"), ERRATA.at("E13")),
)

budget_rss = Formula(
    "Delta_phi_rss",
    ("phi_e_k",),
    lambda sp, phi: sp.sqrt(segment_sum(phi**2)),
    Source(MECHANICS.at(label="error budget", says="independent errors add in quadrature: the root-sum-square")),
)

lost_motion = Formula(
    "phi_LM",
    ("j_t", "T", "C"),
    lambda sp, j, T, C: j + sp.Abs(T) / C,
    Source(SOURCE.at("Lost Motion", says="Total Lost Motion at applied torque = Backlash + Applied Torque / Torsional "
                                         "Stiffness"),
           ERRATA.at("E12", note="the text's formula: the twist under T added to the backlash")),
)

positioning_accuracy_low = Formula(
    "Delta_phi_P_low",
    ("phi_TA", "j_t"),
    lambda sp, ta, j: ta + j,
    Source(SOURCE.at("Positioning Accuracy", says="angular transmission accuracy + backlash",
                     validity=Validity("torque <= 3 % of nominal torque", Band("T", upto=(LOW_TORQUE_SHARE, "T_N")),
                                       stands="heading")),
           ERRATA.at("E13")),
)

positioning_accuracy_high = Formula(
    "Delta_phi_P_high",
    ("phi_TA", "T", "C"),
    lambda sp, ta, T, C: ta + sp.Abs(T) / C,
    Source(SOURCE.at("Positioning Accuracy", says="angular transmission accuracy + applied torque / stiffness",
                     validity=Validity("torque > 3 % of nominal torque", Band("T", above=(LOW_TORQUE_SHARE, "T_N")),
                                       stands="heading")),
           ERRATA.at("E13")),
)

positioning_error = Formula(
    "Delta_phi",
    ("phi_actual", "phi_target"),
    lambda sp, actual, target: actual - target,
    Source(SOURCE.at("Positioning Accuracy",
                     says="the difference between the target position and the actual position")),
)


arc_length = Formula(
    "s",
    ("r", "phi", "rad"),
    lambda sp, r, phi, rad: r * phi / rad,
    Source(MECHANICS.at(label="geometry of the circle",
                        says="an angle φ at the output moves a point at radius r by the arc s = r · φ")),
)

angle_of_arc = Formula(
    "phi_s",
    ("s", "r", "rad"),
    lambda sp, s, r, rad: s / r * rad,
    Source(MECHANICS.at(label="geometry of the circle", says="an arc s at radius r is the angle φ = s / r")),
)


def low_torque_limit(nominal_torque):
    """The torque up to which the backlash form of positioning accuracy applies (E13): 3 % of
    ``T_N``.

    Parameters
    ----------
    nominal_torque : pint.Quantity [N·m]
        ``T_N``.

    Returns
    -------
    pint.Quantity [N·m]
        3 % of it.

    Examples
    --------
    >>> print(fmt(low_torque_limit(Q_(110, "N*m")), "N*m"))
    3.3 N·m
    """
    t_n = as_kind(nominal_torque, "torque", "nominal_torque")
    if np.any(np.asarray(t_n.m_as("N*m")) <= 0):
        raise CalcError(f"nominal_torque: expected a torque above zero, found {t_n:~P}")
    return LOW_TORQUE_SHARE * t_n


@dataclass(frozen=True)
class PositioningRule:
    """Which form of positioning accuracy applies at an applied torque (E13), and why.

    Parameters
    ----------
    applied_torque : pint.Quantity [N·m]
        The torque, scalar or array.
    limit : pint.Quantity [N·m] or None
        3 % of ``T_N`` (None at zero torque without a nominal torque).
    low_torque : bool or numpy.ndarray of bool
        ``|T| <= 3 %`` of the nominal torque: the backlash is not taken up, ``φ_TA + j_t``; else
        the twist counts, ``φ_TA + |T| / C``.
    """

    applied_torque: object
    limit: object
    low_torque: object

    @property
    def text(self) -> str:
        """The rule that applies, ``|T| <= 3 % of T_N: phi_TA + j_t`` (one torque)."""
        return "|T| <= 3 % of T_N: phi_TA + j_t" if self.low_torque else "|T| > 3 % of T_N: phi_TA + |T| / C"

    @property
    def why(self) -> str:
        """Why it applies, ``|T| = 8 N·m > 3 % of T_N = 3.3 N·m`` (one torque)."""
        t = fmt(abs(self.applied_torque), "N*m")
        if self.limit is None:
            return f"|T| = {t}: at rest the backlash counts, whatever T_N"
        return f"|T| = {t} {'<=' if self.low_torque else '>'} 3 % of T_N = {fmt(self.limit, 'N*m')}"

    def accuracy(self, transmission_accuracy, backlash, stiffness):
        """Positioning accuracy by this rule (over every torque of the rule).

        Parameters
        ----------
        transmission_accuracy : pint.Quantity [arcmin]
            ``φ_TA``.
        backlash : pint.Quantity [arcmin]
            ``j_t``.
        stiffness : pint.Quantity [N·m/arcmin]
            ``C``.

        Returns
        -------
        pint.Quantity [arcmin]
            The positioning accuracy at each torque.
        """
        low = positioning_accuracy_low(phi_TA=transmission_accuracy, j_t=backlash).m_as("arcmin")
        high = positioning_accuracy_high(phi_TA=transmission_accuracy, T=self.applied_torque,
                                         C=stiffness).m_as("arcmin")
        return Q_(np.where(self.low_torque, low, high)[()], "arcmin")

    def step(self, transmission_accuracy, backlash, stiffness):
        """The formula that applies, with the numbers (one torque).

        Parameters
        ----------
        transmission_accuracy : pint.Quantity [arcmin]
            ``φ_TA``.
        backlash : pint.Quantity [arcmin]
            ``j_t``.
        stiffness : pint.Quantity [N·m/arcmin]
            ``C``.

        Returns
        -------
        Step
            The evaluated formula.
        """
        if self.low_torque:
            return positioning_accuracy_low.step(phi_TA=transmission_accuracy, j_t=backlash)
        return positioning_accuracy_high.step(phi_TA=transmission_accuracy, T=self.applied_torque, C=stiffness)


def positioning_rule(applied_torque, nominal_torque=None) -> PositioningRule:
    """Which form of positioning accuracy applies (E13): ``|T| <= 3 %`` of ``T_N`` the backlash
    form, above it the twist form; scalar or array torques.

    A torque within :data:`calc.core.checks.BOUNDARY_RTOL` above 3 % counts as on it, as at the
    boundaries of E3 and E4. The nominal torque may be left out only at zero torque, where the
    backlash form holds whatever it is.

    Parameters
    ----------
    applied_torque : pint.Quantity [N·m]
        ``T``, scalar or array.
    nominal_torque : pint.Quantity [N·m], optional
        ``T_N``; may be left out only at zero torque.

    Returns
    -------
    PositioningRule
        The form that applies at each torque.

    Examples
    --------
    >>> r = positioning_rule(Q_(8, "N*m"), Q_(110, "N*m"))
    >>> r.text, r.why
    ('|T| > 3 % of T_N: phi_TA + |T| / C', '|T| = 8 N·m > 3 % of T_N = 3.3 N·m')
    >>> positioning_rule(Q_([3, -3.1], "N*m"), Q_(100, "N*m")).low_torque.tolist()
    [True, False]
    """
    t = as_kind(applied_torque, "torque", "applied_torque")
    if nominal_torque is None:
        if np.any(np.asarray(t.m_as("N*m")) != 0):
            raise CalcError("nominal_torque: the 3 % rule of positioning accuracy (E13) needs the nominal torque, "
                            "found none")
        return PositioningRule(t, None, np.full(np.shape(t.magnitude), True)[()])
    limit = low_torque_limit(nominal_torque)
    return PositioningRule(t, limit, (np.abs(t.m_as("N*m")) <= limit.m_as("N*m") * (1 + BOUNDARY_RTOL))[()])


def positioning_accuracy(applied_torque, nominal_torque, transmission_accuracy, backlash, stiffness):
    """Positioning accuracy by the source's 3 % rule (E13), scalars or arrays.

    .. math::
        \\Delta\\varphi_P = \\varphi_{TA} + j_t \\quad (|T| \\le 0.03\\,T_N), \\qquad
        \\Delta\\varphi_P = \\varphi_{TA} + |T| / C \\quad (|T| > 0.03\\,T_N)

    Parameters
    ----------
    applied_torque, nominal_torque : pint.Quantity [N·m]
    transmission_accuracy, backlash : pint.Quantity [arcmin]
    stiffness : pint.Quantity [N·m/arcmin]

    Returns
    -------
    pint.Quantity [arcmin]

    Notes
    -----
    Implemented as the text writes it (E13): the form jumps at 3 % of the nominal torque
    (:func:`positioning_rule`).

    Examples
    --------
    1 arcmin of transmission accuracy, 3 arcmin backlash, 23 N·m/arcmin, T_N = 81 N·m:

    >>> args = dict(nominal_torque=Q_(81, "N*m"), transmission_accuracy=Q_(1, "arcmin"),
    ...             backlash=Q_(3, "arcmin"), stiffness=Q_(23, "N*m/arcmin"))
    >>> print(fmt(positioning_accuracy(Q_(2, "N*m"), **args), "arcmin"))   # 2 <= 2.43 N·m: 1 + 3
    4 arcmin
    >>> print(fmt(positioning_accuracy(Q_(46, "N*m"), **args), "arcmin"))  # 1 + 46 / 23
    3 arcmin
    """
    return positioning_rule(applied_torque, nominal_torque).accuracy(transmission_accuracy, backlash, stiffness)


def repeatability(applied_torque, backlash, stiffness):
    """Positioning repeatability (E13): the backlash at ``T = 0``; under torque at most the lost
    motion at that torque, ``j_t + |T| / C`` (which is the backlash at ``T = 0``).

    The bound under torque is the source's, and loose: the twist ``|T| / C`` is the same on every
    approach under the same torque, so it shifts the position without spreading it. An axis
    positioned to within ±a cannot repeat worse than 2a, whatever this bound says.

    Parameters
    ----------
    applied_torque : pint.Quantity [N·m]
        ``T``, scalar or array.
    backlash : pint.Quantity [arcmin]
        ``j_t``.
    stiffness : pint.Quantity [N·m/arcmin]
        ``C``.

    Returns
    -------
    tuple of (pint.Quantity [arcmin], numpy.ndarray of bool)
        The value and whether it is an upper bound (``T ≠ 0``) rather than the value itself.

    Examples
    --------
    >>> value, bound = repeatability(Q_(0, "N*m"), Q_(3, "arcmin"), Q_(23, "N*m/arcmin"))
    >>> print(fmt(value, "arcmin"), bool(bound))
    3 arcmin False
    """
    value = lost_motion(j_t=backlash, T=applied_torque, C=stiffness)
    return value, np.asarray(as_kind(applied_torque, "torque", "applied_torque").magnitude) != 0


@dataclass(frozen=True)
class ChainAccuracy:
    """Lost motion, positioning accuracy and repeatability of a chain at an applied torque.

    Parameters
    ----------
    chain : Chain
        The members, as evaluated at the torque.
    applied_torque : pint.Quantity [N·m]
        ``T`` at the output.
    nominal_torque : pint.Quantity [N·m] or None
        ``T_N`` for the 3 % rule; None only at zero torque.
    rule : PositioningRule
        The form of positioning accuracy that applies.
    lost_motion : pint.Quantity [arcmin]
        The chain's lost motion at the torque.
    positioning_accuracy : pint.Quantity [arcmin]
        By the rule.
    repeatability : pint.Quantity [arcmin]
        The value, or its upper bound under torque.
    repeatability_is_bound : bool
        ``repeatability`` is an upper bound (``T ≠ 0``).
    """

    chain: Chain
    applied_torque: object
    nominal_torque: object  # for the 3 % rule; None only at zero torque
    rule: PositioningRule
    lost_motion: object
    positioning_accuracy: object
    repeatability: object
    repeatability_is_bound: bool

    @property
    def low_torque(self) -> bool:
        """Whether the backlash form of positioning accuracy applies (E13)."""
        return bool(self.rule.low_torque)

    @property
    def repeatability_bound(self):
        """Repeatability as the package states it: under torque the tighter of the source's bound,
        the lost motion (E13), and the positioning accuracy, both full widths
        (:data:`POSITIONING_CONVENTION`: positions within a band cannot spread wider than the band);
        at rest the backlash itself. Where no member gives its transmission accuracy, the lost motion.

        Returns
        -------
        pint.Quantity [arcmin]
        """
        if not self.repeatability_is_bound or not self.chain.transmission_accuracy_from:
            return self.repeatability  # no φ_TA given: the positioning accuracy is a lower bound, not a bound
        return Q_(float(np.fmin(self.repeatability.m_as("arcmin"), self.positioning_accuracy.m_as("arcmin"))),
                  "arcmin")

    def steps(self) -> list:
        """Each formula with the chain's numbers, in the order a reviewer reads them.

        Returns
        -------
        list of Step
            The evaluated formulas.
        """
        c = self.chain
        out = []
        # A member of unknown stiffness stands in rigid (its 1/C is zero): its steps are left out.
        known = np.isfinite(c.stiffness_at_output.magnitude)
        for comp, rigid in zip(c.components, ~known):
            if comp.stiffness_curve is not None:
                i = 1.0 if comp.side == "output" else c.ratio.m_as("")
                out += comp.stiffness_curve.steps(self.applied_torque / i)
            if comp.side == "input":
                out += [] if rigid else [stiffness_at_output.step(C_1=comp.stiffness, i=c.ratio)]
                out.append(angle_at_output.step(phi_1=comp.backlash, i=c.ratio))
        if known.any():
            out.append(series_stiffness.step(C_k=c.stiffness_at_output[known]))
        values = dict(j_t=c.backlash, T=self.applied_torque, C=c.stiffness)
        out.append(lost_motion.step(**values))
        out.append(self.rule.step(c.transmission_accuracy, c.backlash, c.stiffness))
        return out


def chain_accuracy(chain: Chain, applied_torque, nominal_torque=None) -> ChainAccuracy:
    """Evaluate a chain at an applied output torque (E11 to E13).

    ``nominal_torque`` sets the 3 % rule; by default the chain's (the lowest nominal torque of
    its components at the output). It may be left out only at zero torque. A member with a
    stiffness curve stands in with its secant stiffness at the torque it carries
    (:meth:`calc.domain.stiffness.Chain.at_torque`), so the chain's stiffness is its secant at
    ``applied_torque`` and the twist in the lost motion and positioning accuracy is the curve's.

    Parameters
    ----------
    chain : Chain
        The members of the chain.
    applied_torque : pint.Quantity [N·m]
        ``T`` at the output.
    nominal_torque : pint.Quantity [N·m], optional
        ``T_N`` for the 3 % rule.

    Returns
    -------
    ChainAccuracy
        Lost motion, positioning accuracy and repeatability.

    Examples
    --------
    >>> from calc.domain.stiffness import Component
    >>> gearbox = Component("EPL-W-064 10:1", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin"),
    ...                     Q_(60, "arcsec"), Q_(40, "N*m"))
    >>> coupling = Component("EKM-15", "output", Q_(0.24, "N*m/arcmin"), Q_(0, "arcmin"))
    >>> a = chain_accuracy(Chain((coupling, gearbox)), Q_(20, "N*m"))
    >>> print(fmt(a.lost_motion, "arcmin"), "|", fmt(a.positioning_accuracy, "arcmin"))
    101.7 arcmin | 99.72 arcmin
    """
    t = as_kind(applied_torque, "torque", "applied_torque")
    chain = chain.at_torque(t)
    t_n = chain.nominal_torque if nominal_torque is None else nominal_torque
    try:
        rule = positioning_rule(t, t_n)
    except CalcError as exc:
        if t_n is None:  # say where the nominal torque was looked for
            raise CalcError(f"{exc} for the chain or its components") from None
        raise
    c, j, ta = chain.stiffness, chain.backlash, chain.transmission_accuracy
    rep, bound = repeatability(t, j, c)
    return ChainAccuracy(
        chain=chain,
        applied_torque=t,
        nominal_torque=None if t_n is None else as_kind(t_n, "torque", "nominal_torque"),
        rule=rule,
        lost_motion=rep,  # repeatability() is the lost motion at t (bounded by it, E13)
        positioning_accuracy=rule.accuracy(ta, j, c),
        repeatability=rep,
        repeatability_is_bound=bool(bound),
    )


@dataclass(frozen=True)
class Contribution:
    """One contribution to the error budget of the positioning accuracy.

    Parameters
    ----------
    name : str
        What it is (``"transmission error"``).
    value : pint.Quantity [arcmin]
        Its full width.
    kind : str
        ``"systematic"`` or ``"random"`` (:data:`BUDGET_KINDS`).
    why : str
        Why it is of that kind, and where it comes from.
    """

    name: str
    value: object
    kind: str
    why: str


@dataclass(frozen=True)
class Budget:
    """The error budget of the positioning accuracy (:func:`error_budget`).

    Parameters
    ----------
    contributions : tuple of Contribution
        Each known contribution.
    worst_case : Step
        Every contribution added: the positioning accuracy.
    rss : Step
        The root-sum-square of the contributions (independent sources).
    rss_random : pint.Quantity [arcmin]
        The root-sum-square of the random ones alone: what is left once the systematic ones are mapped out.
    unknown : list of str
        The contributions not known (the budget is then a lower bound).
    """

    contributions: tuple
    worst_case: object
    rss: object
    rss_random: object
    unknown: list

    @property
    def shares(self) -> list[float]:
        """Each contribution's share of the worst case [1]."""
        total = self.worst_case.result.m_as("arcmin")
        return [float(c.value.m_as("arcmin") / total) if total > 0 else 0.0 for c in self.contributions]


def error_budget(a: ChainAccuracy) -> Budget:
    """The positioning accuracy of ``a`` as a budget: the transmission error (systematic), and
    either the backlash (random: at rest or under a torque up to 3 % of T_N, either flank may carry)
    or the twist under the applied torque (random: the process torque scatters), each a full width
    (:data:`POSITIONING_CONVENTION`). Its worst case is the positioning accuracy itself.

    Parameters
    ----------
    a : ChainAccuracy
        The chain at its applied torque.

    Returns
    -------
    Budget
        The contributions, worst case, root-sum-square, and that of the random ones alone.

    Examples
    --------
    The example's table at 8 N·m: NPT035-10's 62.95 arcsec of transmission error and the twist
    8 N·m / 20.1 N·m/arcmin; worst case 1.049 + 0.398 = 1.447 arcmin, RSS √(1.049² + 0.398²):

    >>> from calc.domain.stiffness import Component
    >>> g = Component("NPT035-10", "output", Q_(20.1, "N*m/arcmin"), Q_(8, "arcmin"), Q_(62.95, "arcsec"),
    ...               Q_(110, "N*m"))
    >>> b = error_budget(chain_accuracy(Chain((g,)), Q_(8, "N*m")))
    >>> [c.kind for c in b.contributions], fmt(b.worst_case.result, "arcmin"), fmt(b.rss.result, "arcmin")
    (['systematic', 'random'], '1.447 arcmin', '1.122 arcmin')
    """
    c = a.chain
    out, unknown = [], []
    ta = c.transmission_accuracy
    if not c.transmission_accuracy_from:
        unknown.append("the transmission error (no member gives its transmission accuracy)")
    else:
        out.append(Contribution("transmission error φ_TA", ta.to("arcmin"), "systematic",
                                "load-independent, repeats with the output angle (E14): a controller can map it out"))
    if a.low_torque:
        out.append(Contribution("backlash j_t", c.backlash.to("arcmin"), "random",
                                "at rest or within 3 % of T_N either flank may carry (E13)"))
    else:
        twist = (abs(a.applied_torque) / c.stiffness).to("arcmin")
        out.append(Contribution("twist |T| / C", twist, "random",
                                "the process torque scatters from part to part; one for the chain, its members "
                                "twist under the same torque (not independent)"))
    values = Q_([x.value.m_as("arcmin") for x in out], "arcmin")
    random = [x.value.m_as("arcmin") for x in out if x.kind == "random"]
    return Budget(tuple(out), budget_worst_case.step(phi_e_k=values), budget_rss.step(phi_e_k=values),
                  Q_(float(np.sqrt(np.sum(np.square(random)))), "arcmin"), unknown)


# --- measured positioning -------------------------------------------------------------------

POSITION_COLUMNS = (
    Column("target", "angle", "target position"),
    Column("actual", "angle", "actual position reached"),
)


@dataclass(frozen=True)
class PositioningScatter:
    """A measured positioning record: errors per approach, measured accuracy and repeatability.

    Parameters
    ----------
    target : pint.Quantity [deg]
        The target of each approach.
    error : pint.Quantity [arcmin]
        The error of each approach (actual minus target).
    accuracy : pint.Quantity [arcmin]
        The largest ``|error|``.
    repeatability : pint.Quantity [arcmin]
        The largest spread (max - min error) at one target.
    targets : int
        How many targets.
    source : str
        Where the record came from.
    """

    target: object  # quantity array [deg], per approach
    error: object  # quantity array [arcmin], per approach
    accuracy: object  # largest |error| [arcmin]
    repeatability: object  # largest spread (max - min error) at one target [arcmin]
    targets: int
    source: str


def analyze_positions(target, actual, source: str = "positions") -> PositioningScatter:
    """Measured positioning accuracy and repeatability from repeated approaches to targets.

    Accuracy is the largest difference between actual and target position (source, Positioning
    Accuracy); repeatability the largest spread of the actual position over the approaches to one
    target (source, Positioning Repeatability). Every target must be approached at least twice.

    Parameters
    ----------
    target : pint.Quantity [deg]
        The target of each approach.
    actual : pint.Quantity [deg]
        The position reached.
    source : str
        Where the record came from, for error messages; default ``"positions"``.

    Returns
    -------
    PositioningScatter
        The errors, accuracy and repeatability.

    Examples
    --------
    >>> r = analyze_positions(Q_([0, 0, 90, 90], "deg"), Q_([0.01, 0.02, 90.01, 90.03], "deg"))
    >>> print(fmt(r.accuracy, "arcmin"), fmt(r.repeatability, "arcmin"))
    1.8 arcmin 1.2 arcmin
    """
    # Checked before the formula, which would broadcast two lengths into a numpy error.
    check_pair(source, ("target", target, "angle"), ("actual", actual, "angle"))
    err = positioning_error(phi_actual=actual, phi_target=target).m_as("arcmin")
    tgt = target.m_as("deg")
    keys, g, count = np.unique(tgt, return_inverse=True, return_counts=True)
    if (count < 2).any():
        raise CalcError(f"{source}: expected each target approached at least twice, found target "
                        f"{keys[count < 2][0]:g}° once")
    spread = np.full(len(keys), -np.inf)
    low = np.full(len(keys), np.inf)
    np.maximum.at(spread, g, err)
    np.minimum.at(low, g, err)
    return PositioningScatter(
        target=Q_(tgt, "deg"),
        error=Q_(err, "arcmin"),
        accuracy=Q_(float(np.abs(err).max()), "arcmin"),
        repeatability=Q_(float((spread - low).max()), "arcmin"),
        targets=len(keys),
        source=source,
    )


def read_positions(path) -> PositioningScatter:
    """Read and analyse a positioning record: a CSV file with ``target [unit]`` and ``actual [unit]``.

    Parameters
    ----------
    path : pathlib.Path or str
        The file.

    Returns
    -------
    PositioningScatter
        Its analysis (:func:`analyze_positions`).
    """
    m = read_measurement(path, POSITION_COLUMNS)
    return analyze_positions(m["target"], m["actual"], source=str(path))
