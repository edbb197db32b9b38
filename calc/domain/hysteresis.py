"""Torque/twist hysteresis loops of a gearbox: a model that draws one, and the analysis of a measured one.

Source: "Torsional Stiffness", "Backlash" and "Lost Motion" ("How is it determined?"), read with
errata E12. The input shaft is locked, the output is loaded with a rising torque up to the
nominal torque ``T_N``, unloaded, loaded the other way to ``-T_N`` and unloaded, and torque and
twist at the output are recorded: a loop. From the loop,

* torsional stiffness is the slope between 50 % and 100 % of ``T_N``, for each loading direction
  (:data:`stiffness_from_slope`, least squares over the loading samples in the band);
* backlash is the width of the loop at 0 N·m, maximum minus minimum twist
  (:data:`backlash_from_loop`);
* lost motion is the width over the part of the loop between -3 % and +3 % of ``T_N``
  (:data:`lost_motion_from_loop`): the backlash plus the small elastic twist of that band.

The analysis is vectorized (a million samples in well under a second) and made robust to noise
and uneven sampling: the loading direction of each sample is the sign of the torque's change
between the means of a few samples either side; the loop's twist at a torque level is read, for each pass through a
narrow window around that level, from a straight line fitted to that pass's samples, so noise
neither widens max - min nor shifts it.

The model (:class:`LoopModel`) draws a loop with the features of a real one: backlash (a gap
crossed at small torque), a soft zone near zero (stiffness rising to its full value within a few
per cent of ``T_N``), linear stiffness above, and a little friction (the branches of the loop part
by a constant friction torque; at each reversal the output sticks until the torque has changed by
twice that). Its parameters are those a catalog gives (``C_t21``, backlash, ``T_2N``), so a loop
drawn for a catalog part analyses back to that part's figures.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

from ..data.catalog import Column, load_catalog, resolve
from ..core.citation import Band, Source, Validity
from ..core.errors import CalcError, as_found
from ..core.formula import Formula
from ..data.measurement import check_pair, read_measurement, travel_direction, write_measurement
from ..core.units import Q_, as_kind, fmt  # noqa: F401 (fmt: the doctests print with it)
from .documents import ERRATA, SOURCE

#: Stiffness band, as shares of the nominal torque (source; E12).
STIFFNESS_BAND = (0.5, 1.0)
#: The low-torque share of the nominal torque (source; E12, E13): lost motion is the loop's width
#: over ± this share of T_N, and up to it the positioning rule counts the backlash
#: (calc.domain.accuracy).
LOW_TORQUE_SHARE = 0.03
#: The fewest samples a loop may have, and the fewest loading samples in a stiffness band.
MIN_SAMPLES = 20
MIN_BAND_SAMPLES = 3

COLUMNS = (
    Column("torque", "torque", "torque applied at the output"),
    Column("twist", "angle", "twist of the output against the locked input"),
)

stiffness_from_slope = Formula(
    "C_t",
    ("Delta_T", "Delta_phi_twist"),
    lambda sp, dT, dphi: dT / dphi,
    Source(SOURCE.at("Torsional Stiffness", says="applied torque / deflection",
                     validity=Validity("at 50 % to 100 % of nominal torque", stands="tail",
                                       band=Band("T", above=(STIFFNESS_BAND[0], "T_N"),
                                                 upto=(STIFFNESS_BAND[1], "T_N")))),
           ERRATA.at("E12")),
)

backlash_from_loop = Formula(
    "j_t",
    ("phi_max_0", "phi_min_0"),
    lambda sp, hi, lo: hi - lo,
    Source(SOURCE.at("Backlash", says="maximum deflection - minimum deflection",
                     validity=Validity("at 0 Nm of torque", stands="tail")),
           ERRATA.at("E12")),
)

lost_motion_from_loop = Formula(
    "phi_LM3",
    ("phi_max_3", "phi_min_3"),
    lambda sp, hi, lo: hi - lo,
    Source(SOURCE.at("Lost Motion", says="maximum deflection - minimum deflection",
                     validity=Validity("at ±3 % of nominal torque", stands="tail",
                                       band=Band("T", upto=(LOW_TORQUE_SHARE, "T_N")))),
           ERRATA.at("E12")),
)


@dataclass(frozen=True)
class Loop:
    """A torque/twist loop: two quantity arrays in the order recorded, and where it came from.

    Parameters
    ----------
    torque : pint.Quantity [N·m]
        Torque at the output, per sample.
    twist : pint.Quantity [arcmin]
        Twist at the output, per sample.
    source : str
        Where it came from (a file), for error messages; default ``"loop"``.
    comments : tuple of str
        The file's comment lines.
    """

    torque: object
    twist: object
    source: str = "loop"
    comments: tuple = ()

    def __post_init__(self):
        check_pair(self.source, ("torque", self.torque, "torque"), ("twist", self.twist, "angle"))


def read_loop(path) -> Loop:
    """Read a measured loop: a CSV file with columns ``torque [unit]`` and ``twist [unit]``.

    Parameters
    ----------
    path : pathlib.Path or str
        The file.

    Returns
    -------
    Loop
        Its samples in the order recorded.
    """
    m = read_measurement(path, COLUMNS)
    return Loop(m["torque"], m["twist"], source=str(path), comments=m.comments)


def write_loop(path, loop: Loop, comments: tuple[str, ...]) -> None:
    """Write a loop as a measurement file (torque in N·m, twist in arcmin).

    Parameters
    ----------
    path : pathlib.Path or str
        The file to write.
    loop : Loop
        The loop.
    comments : tuple of str
        The file's comment lines.

    Returns
    -------
    None
    """
    write_measurement(path, {"torque": loop.torque, "twist": loop.twist}, {"torque": "N*m", "twist": "arcmin"},
                      comments)


@dataclass(frozen=True)
class LoopModel:
    r"""A gearbox's hysteresis loop, from its catalog figures and four shape factors.

    The twist through the middle of the loop is the odd curve

    .. math:: e(T) = \frac{T}{C} + \varphi_s \tanh\frac{T}{T_s} + \frac{g}{2}\tanh\frac{T}{T_g}

    (linear stiffness, a soft zone of extra twist ``φ_s`` that saturates over ``T_s``, and a gap
    ``g`` crossed over ``T_g``). Friction ``T_f`` makes the twist follow ``e(T - T_f)`` while the
    torque rises and ``e(T + T_f)`` while it falls, sticking at each reversal. The gap ``g`` is
    chosen so that the loop's width at 0 N·m, ``2 e(T_f)``, is the given backlash.

    Parameters
    ----------
    stiffness : pint.Quantity [N·m/arcmin]
        ``C``, the slope of the loop between 50 % and 100 % of the nominal torque (``C_t21``).
    backlash : pint.Quantity [arcmin]
        Width of the loop at 0 N·m.
    nominal_torque : pint.Quantity [N·m]
        ``T_N`` (``T_2N``), the torque the loop is drawn to.
    soft_share : float
        The soft zone's extra twist ``φ_s`` as a share of the elastic twist at ``T_N`` (0.15).
    soft_width : float
        ``T_s`` as a share of ``T_N`` (0.08): the stiffness is within 0.1 % of ``C`` above 40 %.
    friction : float
        ``T_f`` as a share of ``T_N`` (0.02).
    gap_width : float
        ``T_g`` as a share of ``T_N`` (0.004).

    Examples
    --------
    >>> m = LoopModel(Q_(23, "N*m/arcmin"), Q_(3, "arcmin"), Q_(81, "N*m"))
    >>> print(fmt(m.lost_motion, "arcmin"))  # 2 e(0.03 T_N + T_f), T_f = 0.02 T_N
    3.539 arcmin
    """

    stiffness: object
    backlash: object
    nominal_torque: object
    soft_share: float = 0.15
    soft_width: float = 0.08
    friction: float = 0.02
    gap_width: float = 0.004
    _gap: float = field(init=False, repr=False, default=0.0)

    def __post_init__(self):
        c = as_kind(self.stiffness, "stiffness", "loop model: stiffness").m_as("N*m/rad")
        j = as_kind(self.backlash, "angle", "loop model: backlash").m_as("rad")
        t_n = as_kind(self.nominal_torque, "torque", "loop model: nominal_torque").m_as("N*m")
        if not c > 0:
            raise CalcError(f"loop model: stiffness: expected a stiffness above zero, found {self.stiffness:~P}")
        if not j >= 0:
            raise CalcError(f"loop model: backlash: expected an angle of zero or more, found {self.backlash:~P}")
        if not t_n > 0:
            raise CalcError(f"loop model: nominal_torque: expected a torque above zero, found {self.nominal_torque:~P}")
        for name in ("soft_share", "friction"):
            if not 0 <= getattr(self, name) < 1:
                raise CalcError(f"loop model: {name}: expected a share from 0 to below 1, found "
                                f"{as_found(getattr(self, name))}")
        for name in ("soft_width", "gap_width"):
            if not 0 < getattr(self, name) < 0.25:
                raise CalcError(f"loop model: {name}: expected a share above 0 and below 0.25, found "
                                f"{as_found(getattr(self, name))}")
        t_f = self.friction * t_n
        if t_f == 0:
            if j > 0:
                raise CalcError("loop model: friction: a loop with backlash needs friction above zero to hold the "
                                "output at one side of the gap at 0 N·m")
            return
        # Width at 0 N·m is 2 e(T_f); the gap makes up what stiffness and soft zone do not.
        without_gap = 2 * self._e(t_f, gap=0.0)
        if without_gap > j:
            raise CalcError(
                f"loop model: friction {self.friction:g} × T_N alone opens the loop by "
                f"{Q_(without_gap, 'rad').m_as('arcmin'):.3g} arcmin at 0 N·m, "
                f"more than the backlash {self.backlash:~P}; give less friction"
            )
        object.__setattr__(self, "_gap", (j - without_gap) / np.tanh(self.friction / self.gap_width))

    @functools.cached_property
    def _si(self):
        c = self.stiffness.m_as("N*m/rad")
        t_n = self.nominal_torque.m_as("N*m")
        return c, t_n, self.soft_share * t_n / c, self.soft_width * t_n, self.gap_width * t_n, self.friction * t_n

    def _e(self, torque, gap=None):
        """The middle curve e(T) in radians, for torques in N·m (floats or arrays)."""
        c, _, phi_s, t_s, t_g, _ = self._si
        g = self._gap if gap is None else gap
        return torque / c + phi_s * np.tanh(torque / t_s) + 0.5 * g * np.tanh(torque / t_g)

    def middle_curve(self, torque):
        """``e(T)``, the twist through the middle of the loop.

        Parameters
        ----------
        torque : pint.Quantity [N·m]
            Scalar or array.

        Returns
        -------
        pint.Quantity [arcmin]
            The twist at each torque.
        """
        t = as_kind(torque, "torque", "torque").m_as("N*m")
        return Q_(self._e(t), "rad").to("arcmin")

    @property
    def lost_motion(self):
        """Width of the model's loop over ±3 % of ``T_N``: ``2 e(0.03 T_N + T_f)`` (E12)."""
        _, t_n, *_, t_f = self._si
        return Q_(2 * self._e(LOW_TORQUE_SHARE * t_n + t_f), "rad").to("arcmin")

    def twist(self, torque):
        """Twist along a torque path, in the order given: the path starts unloaded at 0 N·m.

        The path is cut into monotone ramps at its turning points; on a rising ramp the
        internal torque is ``max(T - T_f, state)``, on a falling one ``min(T + T_f, state)``,
        ``state`` being where the previous ramp left it (a play operator, one step per ramp).

        Parameters
        ----------
        torque : pint.Quantity [N·m]
            The torque path, an array.

        Returns
        -------
        pint.Quantity [arcmin]
            The twist at each point of the path.
        """
        t = as_kind(torque, "torque", "torque").m_as("N*m")
        t_f = self._si[5]
        internal = np.zeros(len(t))
        if len(t) > 1:
            rising = np.diff(t) >= 0  # per step, sample j to j + 1
            bounds = np.concatenate(([0], np.flatnonzero(rising[1:] != rising[:-1]) + 1, [len(rising)]))
            state = 0.0
            for a, b in zip(bounds[:-1], bounds[1:]):
                ramp = slice(a + 1, b + 1)
                if rising[a]:
                    internal[ramp] = np.maximum(t[ramp] - t_f, state)
                else:
                    internal[ramp] = np.minimum(t[ramp] + t_f, state)
                state = internal[b]
        return Q_(self._e(internal), "rad").to("arcmin")

    def loop(self, samples: int = 2000, noise_torque=None, noise_twist=None, seed: int = 0,
             uneven: bool = True) -> Loop:
        """A loop as a rig records it: from unloaded, 0 → +T_N → -T_N → +T_N.

        The source's procedure loads to ``+T_N`` and then the other way to ``-T_N``; the last
        ramp back to ``+T_N`` closes the loop, so each branch passes 0 N·m and ±3 % whole.

        Returns
        -------
        Loop
            The sampled loop.

        Parameters
        ----------
        samples : int
            Number of samples over the whole path.
        noise_torque, noise_twist : pint.Quantity [N·m], [arcmin], optional
            Standard deviation of normal noise added to each torque and twist sample.
        seed : int
            Seed of the random generator (sampling positions and noise).
        uneven : bool
            Sample unevenly: the rate along the path swings by ±30 % and each sample jitters by
            up to ±45 % of a step (a rig sampling in time while the torque rate varies).
        """
        if not isinstance(samples, (int, np.integer)) or samples < 2:
            raise CalcError(f"loop model: samples: expected a whole number of 2 or more, found {as_found(samples)}")
        rng = np.random.default_rng(seed)
        t_n = self._si[1]
        corners = np.array([0.0, t_n, -t_n, t_n])
        lengths = np.abs(np.diff(corners))
        u = np.linspace(0.0, 1.0, samples)
        if uneven:
            # The rate along the path swings ±30 % three times, and each sample jitters ±45 % of a step.
            u = u + 0.3 * np.sin(6 * np.pi * u) / (6 * np.pi)
            u = np.sort(np.clip(u + rng.uniform(-0.45, 0.45, samples) / (samples - 1), 0.0, 1.0))
        s = u * lengths.sum()
        # Torque along the path: piecewise linear through the corners.
        torque = np.interp(s, np.concatenate(([0.0], np.cumsum(lengths))), corners)
        twist = self.twist(Q_(torque, "N*m")).m_as("arcmin")
        if noise_torque is not None:
            torque = torque + rng.normal(0.0, as_kind(noise_torque, "torque", "noise_torque").m_as("N*m"), samples)
        if noise_twist is not None:
            twist = twist + rng.normal(0.0, as_kind(noise_twist, "angle", "noise_twist").m_as("arcmin"), samples)
        return Loop(Q_(torque, "N*m"), Q_(twist, "arcmin"), source="generated loop")


def model_for_part(part: str, catalog: str = "gearboxes", **shape) -> LoopModel:
    """The loop model of a catalog gearbox: ``C_t21``, backlash and ``T_2N`` from its row.

    Parameters
    ----------
    part : str
        The gearbox's part.
    catalog : str
        The catalog's name or path; default ``"gearboxes"``.
    **shape : float
        The shape factors of :class:`LoopModel` (``soft_share``, ...), by name.

    Returns
    -------
    LoopModel
        The gearbox's loop.

    Examples
    --------
    >>> m = model_for_part("TP010-10")
    >>> print(fmt(m.stiffness, "N*m/arcmin"), fmt(m.backlash, "arcmin"), fmt(m.nominal_torque, "N*m"))
    23 N·m/arcmin 3 arcmin 81 N·m
    """
    from .gearbox import SCHEMA

    rows = load_catalog(resolve(catalog, None, "catalog"), SCHEMA)
    row = rows.index(part, "part")
    for column in ("C_t21", "backlash"):
        if np.isnan(rows[column][row].magnitude):
            raise CalcError(f"{rows.path}, row {rows.lines[row]} ({part}), column {column}: expected a value for the "
                            "loop model, found an empty cell")
    return model_for_row(rows, row, **shape)


def model_for_row(rows, row: int, **shape) -> LoopModel:
    """The loop model of a gearbox catalog row: its ``C_t21``, backlash and ``T_2N``.

    Parameters
    ----------
    rows : calc.data.catalog.Catalog
        A gearbox catalog (:data:`calc.domain.gearbox.SCHEMA`).
    row : int
        The row, whose ``C_t21`` and backlash are given.
    **shape
        The shape factors of :class:`LoopModel` (its defaults where left out).

    Returns
    -------
    LoopModel
        The model of that gearbox's loop.
    """
    return LoopModel(rows["C_t21"][row], rows["backlash"][row], rows["T_2N"][row], **shape)


@dataclass(frozen=True)
class LineFit:
    """A fitted straight line of the loop, from torque ``T_a`` to ``T_b`` (for plots and steps).

    Parameters
    ----------
    torque : pint.Quantity [N·m]
        ``[T_a, T_b]``.
    twist : pint.Quantity [arcmin]
        The fitted twist at ``T_a`` and ``T_b``.
    samples : int
        The samples the line is fitted through.
    """

    torque: object  # quantity array [T_a, T_b]
    twist: object  # quantity array, the fitted twist at T_a and T_b
    samples: int


@dataclass(frozen=True)
class LoopAnalysis:
    """Stiffness, backlash and lost motion of a loop (E12), with what a plot or report shows.

    Parameters
    ----------
    nominal_torque : pint.Quantity [N·m]
        ``T_N``.
    stiffness_positive, stiffness_negative : pint.Quantity [N·m/arcmin]
        The stiffness loading each way.
    fit_positive, fit_negative : LineFit
        The lines they come from.
    backlash : pint.Quantity [arcmin]
        The loop's width at 0 N·m.
    backlash_range : pint.Quantity [arcmin]
        ``[min, max]`` of the twist at 0 N·m.
    lost_motion : pint.Quantity [arcmin]
        The loop's width over ±3 % of ``T_N``.
    lost_motion_range : pint.Quantity [arcmin]
        ``[min, max]`` of the twist over ±3 % of ``T_N``.
    source : str
        Where the loop came from.
    """

    nominal_torque: object
    stiffness_positive: object
    stiffness_negative: object
    fit_positive: LineFit
    fit_negative: LineFit
    backlash: object
    backlash_range: object  # quantity array [min, max] of the twist at 0 N·m
    lost_motion: object
    lost_motion_range: object  # quantity array [min, max] of the twist over ±3 % of T_N
    source: str

    @property
    def stiffness(self):
        """The lower of the two directions' stiffness (the one that twists more)."""
        return min(self.stiffness_positive, self.stiffness_negative)

    def steps(self) -> list:
        """The formulas with this loop's numbers, for a notebook or report.

        Returns
        -------
        list of Step
            The stiffness each way, the backlash and the lost motion.
        """
        out = []
        for fit in (self.fit_positive, self.fit_negative):
            d_t, d_phi = fit.torque[1] - fit.torque[0], fit.twist[1] - fit.twist[0]
            out.append(stiffness_from_slope.step(Delta_T=d_t, Delta_phi_twist=d_phi))
        out.append(backlash_from_loop.step(phi_max_0=self.backlash_range[1], phi_min_0=self.backlash_range[0]))
        out.append(lost_motion_from_loop.step(phi_max_3=self.lost_motion_range[1], phi_min_3=self.lost_motion_range[0]))
        return out


def analyze_loop(loop: Loop, nominal_torque) -> LoopAnalysis:
    """Stiffness per direction, backlash and lost motion of a measured loop (E12).

    Parameters
    ----------
    loop : Loop
        Torque and twist at the output, in the order recorded, loaded both ways.
    nominal_torque : pint.Quantity [N·m]
        ``T_N``, which sets the 50 % to 100 % band and the ±3 % band.

    Returns
    -------
    LoopAnalysis
        ``stiffness_positive`` and ``stiffness_negative`` [N·m/arcmin], ``backlash`` and
        ``lost_motion`` [arcmin].

    Notes
    -----
    Stiffness: least-squares slope of twist on torque over the *loading* samples (``|T|``
    rising) between 50 % and 100 % of ``T_N``; ``C = ΔT / Δφ`` of the fitted line. Backlash and lost
    motion: max - min over the passes of the loop's twist at 0 N·m, and at -3 %, 0 and +3 % of
    ``T_N`` (each branch rises with torque, so the extremes over the band lie at its edges),
    leaving out the unloaded start of a record until the torque first leaves the ±3 % band; a
    pass's twist at a level is read from a least-squares line through the samples around its
    crossing (about ±0.5 % of ``T_N`` of path).

    Raises :class:`CalcError` for too few samples, a loop loaded one way only, fewer than three
    loading samples in a band, or a loop that does not pass 0 N·m both ways.

    Examples
    --------
    >>> loop = LoopModel(Q_(23, "N*m/arcmin"), Q_(3, "arcmin"), Q_(81, "N*m")).loop(4000, seed=1)
    >>> a = analyze_loop(loop, Q_(81, "N*m"))
    >>> print(fmt(a.stiffness, "N*m/arcmin", 3), fmt(a.backlash, "arcmin", 3), fmt(a.lost_motion, "arcmin", 3))
    23 N·m/arcmin 3 arcmin 3.54 arcmin
    """
    where = loop.source
    t_n = as_kind(nominal_torque, "torque", f"{where}: nominal torque").m_as("N*m")
    if not t_n > 0:
        raise CalcError(f"{where}: nominal torque: expected a torque above zero, found {nominal_torque:~P}")
    torque, twist = _checked_samples(loop, t_n)
    direction = travel_direction(torque)
    fits = {name: _loading_fit(torque, twist, direction, sign, name, t_n, where)
            for sign, name in ((1, "positive"), (-1, "negative"))}
    zero_range, band_range = _level_ranges(torque, twist, direction, t_n, where)

    def stiffness(fit):
        return stiffness_from_slope(Delta_T=fit.torque[1] - fit.torque[0],
                                    Delta_phi_twist=fit.twist[1] - fit.twist[0])

    return LoopAnalysis(
        nominal_torque=Q_(t_n, "N*m"),
        stiffness_positive=stiffness(fits["positive"]),
        stiffness_negative=stiffness(fits["negative"]),
        fit_positive=fits["positive"],
        fit_negative=fits["negative"],
        backlash=backlash_from_loop(phi_max_0=zero_range[1], phi_min_0=zero_range[0]),
        backlash_range=zero_range,
        lost_motion=lost_motion_from_loop(phi_max_3=band_range[1], phi_min_3=band_range[0]),
        lost_motion_range=band_range,
        source=where,
    )


def _checked_samples(loop: Loop, t_n: float):
    """The loop's torque [N·m] and twist [rad] as SI floats, once they are enough, finite and loaded
    both ways beyond the ±3 % band of ``t_n`` [N·m]."""
    where = loop.source
    torque = loop.torque.m_as("N*m")
    twist = loop.twist.m_as("rad")
    n = len(torque)
    if n < MIN_SAMPLES:
        raise CalcError(f"{where}: expected a loop of at least {MIN_SAMPLES} samples, found {n}")
    if not (np.isfinite(torque).all() and np.isfinite(twist).all()):
        raise CalcError(f"{where}: expected finite torque and twist samples, found NaN or infinity")
    edge = LOW_TORQUE_SHARE * t_n
    if torque.max() < edge or torque.min() > -edge:
        raise CalcError(
            f"{where}: the loop is loaded in one direction only (torque from {torque.min():.4g} to "
            f"{torque.max():.4g} N·m); expected torque beyond both -3 % and +3 % of the nominal torque (±{edge:.4g} "
            "N·m)"
        )
    return torque, twist


def _loading_fit(torque, twist, direction, sign: int, name: str, t_n: float, where: str) -> LineFit:
    """The line through the samples loading in one direction (``sign``, called ``name``) between 50 %
    and 100 % of ``t_n`` [N·m]; SI floats in."""
    lo, hi = (x * t_n for x in STIFFNESS_BAND)
    band = (sign * torque >= lo) & (sign * torque <= hi) & (direction == sign)
    count = int(band.sum())
    if count < MIN_BAND_SAMPLES:
        raise CalcError(
            f"{where}: expected at least {MIN_BAND_SAMPLES} samples loading in the {name} direction between 50 % "
            f"and 100 % of the nominal torque ({sign * lo:.4g} to {sign * hi:.4g} N·m), found {count}"
        )
    slope, t_mean, phi_mean = _line(torque[band], twist[band])
    if not slope > 0:
        raise CalcError(
            f"{where}: the twist does not rise with the torque between 50 % and 100 % of the nominal torque "
            f"in the {name} direction"
        )
    ends = np.array([lo, hi]) if sign > 0 else np.array([-hi, -lo])
    return LineFit(Q_(ends, "N*m"), Q_(phi_mean + slope * (ends - t_mean), "rad").to("arcmin"), count)


def _level_ranges(torque, twist, direction, t_n: float, where: str):
    """The least and greatest twist [arcmin] over the loop's passes at 0 N·m, and at -3 %, 0 and
    +3 % of ``t_n`` [N·m]; SI floats in."""
    n = len(torque)
    edge = LOW_TORQUE_SHARE * t_n
    passes = np.concatenate(([0], np.cumsum(direction[1:] != direction[:-1])))
    # Level readings use about ±0.5 % of T_N of path either side of a crossing (a record that
    # mostly dwells has no typical step; then the two samples either side of it).
    step = _torque_step(torque)
    half_window = min(int(round(0.005 * t_n / step)), n // 10) if step > 0 else 0
    # A record that starts unloaded is not on the loop until the torque first leaves the ±3 % band.
    on_loop = np.ones(n, bool)
    on_loop[: int(np.argmax(np.abs(torque) > edge))] = False
    passes = np.where(on_loop, passes, -1)
    at_zero = _level_twists(torque, twist, passes, 0.0, half_window)
    if len(at_zero) < 2:
        raise CalcError(
            f"{where}: expected the loop to pass 0 N·m in both directions, "
            f"found {len(at_zero)} pass{'' if len(at_zero) == 1 else 'es'}"
        )
    band_twists = np.concatenate([at_zero, _level_twists(torque, twist, passes, -edge, half_window),
                                  _level_twists(torque, twist, passes, edge, half_window)])
    zero_range = Q_(np.array([at_zero.min(), at_zero.max()]), "rad").to("arcmin")
    band_range = Q_(np.array([band_twists.min(), band_twists.max()]), "rad").to("arcmin")
    return zero_range, band_range


def _torque_step(torque: np.ndarray) -> float:
    """The typical torque change from one sample to the next along the path, noise left out:
    the median change over ``k = max(1, n // 500)`` samples, divided by ``k``."""
    k = max(1, len(torque) // 500)
    return float(np.median(np.abs(torque[k:] - torque[:-k]))) / k


def _line(x: np.ndarray, y: np.ndarray):
    """Least-squares slope of y on x, and the means the line passes through."""
    x_mean, y_mean = float(x.mean()), float(y.mean())
    dx = x - x_mean
    sxx = float(dx @ dx)
    return (float(dx @ (y - y_mean)) / sxx if sxx > 0 else np.nan), x_mean, y_mean


def _level_twists(torque, twist, passes, level: float, half_window: int) -> np.ndarray:
    """The loop's twist at a torque level, one value per pass that crosses it.

    At each crossing (two samples of one pass either side of ``level``) a least-squares line
    through ``2 × half_window + 2`` samples around it is read at ``level``; noise that makes a
    pass cross several times gives several readings, of which the pass keeps the median. Windows
    count samples, not torque, so uneven sampling leaves no crossing without a reading.
    """
    n = len(torque)
    s = torque - level
    j = np.flatnonzero((s[:-1] * s[1:] <= 0) & (s[:-1] != s[1:]) & (passes[:-1] == passes[1:]) & (passes[:-1] >= 0))
    if not len(j):
        return np.empty(0)
    idx = np.clip(j[:, None] + np.arange(-half_window, half_window + 2), 0, n - 1)
    x, y = s[idx], twist[idx]
    x_mean, y_mean = x.mean(axis=1), y.mean(axis=1)
    dx = x - x_mean[:, None]
    sxx, sxy = (dx * dx).sum(axis=1), (dx * (y - y_mean[:, None])).sum(axis=1)
    slope = np.divide(sxy, sxx, out=np.zeros_like(sxx), where=sxx > 0)
    readings = y_mean - slope * x_mean
    g, v = passes[j], readings
    order = np.lexsort((v, g))
    g, v = g[order], v[order]
    _, start, count = np.unique(g, return_index=True, return_counts=True)
    return 0.5 * (v[start + (count - 1) // 2] + v[start + count // 2])
