"""Drive-train dynamics as a control engineer sees it: natural frequencies and mode shapes of the
chain, its anti-resonances with the motor held, the frequency response of the motor's speed to the
motor's torque, and the two-mass model that explains the inertia ratio.

The chain is the one :mod:`calc.domain.torsion` lumps (masses and springs, drive to load, referred
to one shaft). Seen from the motor, the transfer function from the motor's torque to its speed has
a pole pair at each natural frequency (a **resonance**: the speed loop sees a peak) and a zero
pair at each natural frequency of the chain with the motor held (an **anti-resonance**: the motor
barely moves while the load swings; a speed loop tuned up to it has nothing to act on). The
anti-resonances are the roots of the eigenproblem without the motor's row and column
(:func:`anti_resonances`); they interlace the resonances.

Two masses (the rotor, and everything the motor drives referred to its shaft, ``J_Lm``) on one
spring ``C_s`` give the closed forms :data:`two_mass_resonance` and :data:`two_mass_anti_resonance`,
whose ratio is ``f_r / f_ar = √(1 + J_Lm / J_motor) = √(1 + λ)`` (:data:`resonance_ratio`): the
inertia ratio λ says how far below the resonance the anti-resonance lies. ``λ <= 10`` keeps it
within a factor √11 = 3.3; at λ = 1 (inertia matched) the two lie a factor √2 apart.

The frequency response is that of the chain's state-space model (python-control's ``control.ss``
in :func:`state_space`) with a light damping proportional to the stiffness (:data:`DAMPING_RATIO`
at the first mode), for the figure only: every frequency the package states is the undamped one.
It is evaluated here in numpy, ``C (jω I - A)⁻¹ B`` for all frequencies in one stacked solve, the
computation ``control.frequency_response`` makes (without Slycot): importing python-control and
the SciPy it imports takes longer than the rest of a design review's first page. SI magnitudes
throughout (a stiffness in N·m/rad over an inertia gives 1/s² with the radian of E15).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.citation import Source, Validity
from ..core.errors import CalcError
from ..core.formula import Formula
from ..core.units import Q_, as_kind, from_si, to_si
from .documents import ERRATA, MECHANICS

#: The damping ratio of the first mode in the frequency response's figure (stiffness-proportional
#: damping, so a higher mode is damped more); a metal drive train lies between 0.01 and 0.05.
DAMPING_RATIO = 0.02

_TWO_MASS = Validity("two-mass model: the rotor against everything it drives, on the chain's springs in series")

two_mass_resonance = Formula(
    "f_r",
    ("C_s", "rad", "J_motor", "J_Lm"),
    lambda sp, C_s, rad, J_M, J_Lm: sp.sqrt(C_s * rad * (1 / J_M + 1 / J_Lm)) / (2 * sp.pi),
    Source(MECHANICS.at(label="torsional vibration", says="two masses on one spring swing against each other at "
                        "ω² = C (1/J_1 + 1/J_2)", validity=_TWO_MASS),
           ERRATA.at("E7", note="the source's two-mass formula with the rotor as one mass")),
)

two_mass_anti_resonance = Formula(
    "f_ar",
    ("C_s", "rad", "J_Lm"),
    lambda sp, C_s, rad, J_Lm: sp.sqrt(C_s * rad / J_Lm) / (2 * sp.pi),
    Source(MECHANICS.at(label="torsional vibration", says="with the motor held, the load swings alone on the spring: "
                        "ω² = C / J_2, the zero of the motor's speed over its torque", validity=_TWO_MASS)),
)

resonance_ratio = Formula(
    "q_r",
    ("lambda",),
    lambda sp, lam: sp.sqrt(1 + lam),
    Source(MECHANICS.at(label="torsional vibration",
                        says="f_r / f_ar = √((J_1 + J_2) / J_1) = √(1 + λ), λ = J_2 / J_1", validity=_TWO_MASS)),
)

two_mass_load = Formula(
    "J_Lm",
    ("J_K", "J_1", "J_L", "i"),
    lambda sp, J_K, J_1, J_L, i: J_K + J_1 + J_L / i**2,
    Source(ERRATA.at("E8", note="everything the motor drives, referred to its shaft: the coupling, the gearbox's "
                                "J_1, the load J_L / i²")),
)


def stiffness_matrix(stiffnesses: np.ndarray) -> np.ndarray:
    """The stiffness matrix of a free chain, ``K_kk = C_{k-1} + C_k``, ``K_k,k+1 = -C_k``.

    Parameters
    ----------
    stiffnesses : numpy.ndarray [N·m/rad]
        The springs, drive to load (SI magnitudes), shape ``(n - 1,)``.

    Returns
    -------
    numpy.ndarray [N·m/rad]
        Shape ``(n, n)``.
    """
    C = np.asarray(stiffnesses, float)
    n = len(C) + 1
    K = np.zeros((n, n))
    k = np.arange(n - 1)
    K[k, k] += C
    K[k + 1, k + 1] += C
    K[k, k + 1] -= C
    K[k + 1, k] -= C
    return K


def _si_chain(inertias, stiffnesses, where: str) -> tuple[np.ndarray, np.ndarray]:
    J = np.atleast_1d(np.asarray(to_si(as_kind(inertias, "inertia", f"{where}: inertias"), "inertia", where), float))
    C = np.atleast_1d(np.asarray(to_si(as_kind(stiffnesses, "stiffness", f"{where}: stiffnesses"), "stiffness",
                                       where), float))
    if J.ndim != 1 or C.shape != (len(J) - 1,) or len(J) < 2:
        raise CalcError(f"{where}: expected n >= 2 masses and n - 1 springs, found {J.size} masses and "
                        f"{C.size} springs")
    if not (np.all(J > 0) and np.all(C > 0)):
        raise CalcError(f"{where}: expected inertias and stiffnesses above zero, found {J.min():g} kg·m² and "
                        f"{C.min():g} N·m/rad at least")
    return J, C


def _symmetric_roots(J: np.ndarray, K: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The roots ω² and mass-normalized vectors of ``K φ = ω² J φ`` (``J`` diagonal)."""
    scale = 1 / np.sqrt(J)
    roots, vectors = np.linalg.eigh(K * scale[:, None] * scale[None, :])
    return np.clip(roots, 0.0, None), vectors * scale[:, None]


@dataclass(frozen=True)
class Modes:
    """A chain's modes: natural frequencies with their shapes, and its anti-resonances.

    Parameters
    ----------
    natural_frequencies : pint.Quantity [Hz]
        Lowest first, the rigid-body mode left out (``n - 1``).
    shapes : numpy.ndarray [1]
        The mode shape of each natural frequency (rows), the masses drive to load (columns), scaled
        so that the largest swing is 1 and the motor's is zero or more.
    anti_resonances : pint.Quantity [Hz]
        Lowest first: the natural frequencies of the chain with the motor held (``n - 1``).
    """

    natural_frequencies: object
    shapes: np.ndarray
    anti_resonances: object


def modes(inertias, stiffnesses, where: str = "drive train") -> Modes:
    r"""Natural frequencies, mode shapes and anti-resonances of a free chain.

    .. math:: (K - \omega^2 J)\,\varphi = 0, \qquad (K' - \omega^2 J')\,\varphi' = 0

    ``K'`` and ``J'`` are ``K`` and ``J`` without the motor's row and column (the motor held: its
    spring then joins the next mass to the ground).

    Parameters
    ----------
    inertias : pint.Quantity [kg·cm²], shape (n,)
        The masses, drive to load.
    stiffnesses : pint.Quantity [N·m/rad], shape (n - 1,)
        The springs between them.
    where : str
        The chain's name, for error messages; default ``"drive train"``.

    Returns
    -------
    Modes
        Natural frequencies [Hz] with their shapes, anti-resonances [Hz].

    Examples
    --------
    Two masses, 2 and 8 kg·cm² on 1000 N·m/rad: ω_r² = 1000 · (1/2e-4 + 1/8e-4) = 6.25e6 /s²,
    ω_ar² = 1000 / 8e-4 = 1.25e6 /s²; the ratio √5 = √(1 + 8/2):

    >>> m = modes(Q_([2, 8], "kg*cm**2"), Q_([1000], "N*m/rad"))
    >>> [round(float(f), 2) for f in m.natural_frequencies.m_as("Hz")], m.shapes.round(2).tolist()
    ([397.89], [[1.0, -0.25]])
    >>> [round(float(f), 2) for f in m.anti_resonances.m_as("Hz")]
    [177.94]
    """
    J, C = _si_chain(inertias, stiffnesses, where)
    K = stiffness_matrix(C)
    roots, vectors = _symmetric_roots(J, K)
    shapes = vectors[:, 1:].T  # the first root is the rigid-body mode, zero up to rounding
    shapes = shapes / np.abs(shapes).max(axis=1, keepdims=True)
    shapes = shapes * np.where(shapes[:, :1] < 0, -1.0, 1.0)
    held, _ = _symmetric_roots(J[1:], K[1:, 1:])
    return Modes(from_si(np.sqrt(roots[1:]) / (2 * np.pi), "frequency", "Hz"), shapes,
                 from_si(np.sqrt(held) / (2 * np.pi), "frequency", "Hz"))


def _state_matrices(inertias, stiffnesses, damping: float, where: str):
    """The matrices ``A``, ``B``, ``C`` of :func:`state_space` (SI; ``D`` is zero)."""
    J, C = _si_chain(inertias, stiffnesses, where)
    if not 0 <= damping < 1:
        raise CalcError(f"{where}: damping: expected a damping ratio from 0 to below 1, found {damping!r}")
    n = len(J)
    K = stiffness_matrix(C)
    omega_1 = np.sqrt(_symmetric_roots(J, K)[0][1])
    D = (2 * damping / omega_1) * K
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-K / J[:, None], -D / J[:, None]]])
    B = np.zeros((2 * n, 1))
    B[n, 0] = 1 / J[0]
    out = np.zeros((1, 2 * n))
    out[0, n] = 1.0
    return A, B, out


def state_space(inertias, stiffnesses, damping: float = DAMPING_RATIO, where: str = "drive train"):
    """The chain's state-space model, motor torque in, motor speed out (python-control).

    States: the angles of the masses, then their speeds. Damping ``D = β K`` with ``β = 2 ζ / ω_1``,
    so that the first mode has the damping ratio ``ζ``.

    Parameters
    ----------
    inertias : pint.Quantity [kg·cm²], shape (n,)
        The masses, drive to load.
    stiffnesses : pint.Quantity [N·m/rad], shape (n - 1,)
        The springs between them.
    damping : float
        ``ζ`` of the first mode [1]; default :data:`DAMPING_RATIO`.
    where : str
        The chain's name, for error messages.

    Returns
    -------
    control.StateSpace
        Input the motor's torque [N·m], output the motor's speed [rad/s].
    """
    import control  # the control systems library: imported where the model is asked for

    return control.ss(*_state_matrices(inertias, stiffnesses, damping, where), 0)


@dataclass(frozen=True)
class FrequencyResponse:
    """The motor's speed over the motor's torque, at each frequency.

    Parameters
    ----------
    frequency : pint.Quantity [Hz]
        The frequencies, ascending.
    magnitude : numpy.ndarray [rad/(s·N·m)]
        ``|ω_motor / T_motor|``.
    phase : numpy.ndarray [deg]
        Its phase.
    damping : float
        ``ζ`` of the first mode it was computed with [1].
    """

    frequency: object
    magnitude: np.ndarray
    phase: np.ndarray
    damping: float


def frequency_response(inertias, stiffnesses, frequencies, damping: float = DAMPING_RATIO,
                       where: str = "drive train") -> FrequencyResponse:
    """The frequency response of the motor's speed to its torque: :func:`state_space`'s model
    evaluated at ``s = j 2π f``, ``C (s I - A)⁻¹ B``, as ``control.frequency_response`` does.

    Parameters
    ----------
    inertias : pint.Quantity [kg·cm²], shape (n,)
        The masses, drive to load.
    stiffnesses : pint.Quantity [N·m/rad], shape (n - 1,)
        The springs between them.
    frequencies : pint.Quantity [Hz]
        Where to evaluate it, above zero.
    damping : float
        ``ζ`` of the first mode [1]; default :data:`DAMPING_RATIO`.
    where : str
        The chain's name, for error messages.

    Returns
    -------
    FrequencyResponse
        Magnitude [rad/(s·N·m)] and phase [deg].

    Examples
    --------
    Far below the first mode the chain turns as one body: |ω / T| = 1 / (2π f ΣJ); 10 kg·cm² at
    1 Hz gives 1 / (2π · 1e-3) = 159.2 rad/(s·N·m):

    >>> r = frequency_response(Q_([2, 8], "kg*cm**2"), Q_([1000], "N*m/rad"), Q_([1.0], "Hz"))
    >>> round(float(r.magnitude[0]), 1), round(float(r.phase[0]))
    (159.2, -90)
    """
    f = np.atleast_1d(as_kind(frequencies, "frequency", f"{where}: frequencies").m_as("Hz")).astype(float)
    if not np.all(f > 0):
        raise CalcError(f"{where}: frequencies: expected frequencies above zero, found {f.min():g} Hz")
    A, B, C = _state_matrices(inertias, stiffnesses, damping, where)
    h = _transfer(A, B, C, 2j * np.pi * f)
    return FrequencyResponse(Q_(f, "Hz"), np.abs(h), np.degrees(np.angle(h)), damping)


def _transfer(A: np.ndarray, B: np.ndarray, C: np.ndarray, s) -> np.ndarray:
    """``C (s I - A)⁻¹ B`` at each complex frequency ``s`` [1/s] (an array, or one); at a pole of an
    undamped chain, infinite."""
    s = np.asarray(s, complex)
    try:
        x = np.linalg.solve(s[..., None, None] * np.eye(len(A)) - A, np.broadcast_to(B, (*s.shape, *B.shape)))
    except np.linalg.LinAlgError:  # a frequency on a pole: each apart, the pole's own infinite
        if s.ndim:
            return np.array([_transfer(A, B, C, one) for one in s])
        return np.array(complex(np.inf, np.nan))
    return (C @ x)[..., 0, 0]


def band_slope(curve, torque):
    """The slope of a three-slope stiffness curve at a torque (the tangent: ``K_1``, ``K_2`` or
    ``K_3`` of the band ``|T|`` falls in), what a small oscillation about that torque sees.

    Parameters
    ----------
    curve : calc.domain.stiffness.StiffnessCurve
        The curve.
    torque : pint.Quantity [N·m]
        Scalar or array, either sign.

    Returns
    -------
    pint.Quantity [N·m/rad]
        The slope at each torque.

    Examples
    --------
    Harmonic Drive's HFUC-32-100 (K_1 = 6.7e4 up to 29 N·m, K_2 = 1.1e5 up to 108 N·m):

    >>> from calc.domain.stiffness import StiffnessCurve
    >>> hfuc = StiffnessCurve(Q_(29, "N*m"), Q_(108, "N*m"), Q_(6.7e4, "N*m/rad"), Q_(1.1e5, "N*m/rad"),
    ...                       Q_(1.2e5, "N*m/rad"))
    >>> band_slope(hfuc, Q_([10, 60], "N*m")).m_as("N*m/rad").tolist()
    [67000.0, 110000.0]
    """
    slopes = [curve.K_1.m_as("N*m/rad"), curve.K_2.m_as("N*m/rad"), curve.K_3.m_as("N*m/rad")]
    return Q_(np.choose(curve.band(torque), slopes)[()], "N*m/rad")


def loop_slope(model, torque):
    """The slope of a loop model's middle curve at a torque, ``1 / e'(T)``
    (:class:`calc.domain.hysteresis.LoopModel`): the soft zone below about 40 % of ``T_N`` makes it
    softer than ``C_t21`` there.

    Parameters
    ----------
    model : calc.domain.hysteresis.LoopModel
        The loop model.
    torque : pint.Quantity [N·m]
        Scalar or array, either sign, away from zero (the gap is crossed at zero).

    Returns
    -------
    pint.Quantity [N·m/rad]
        The slope at each torque.

    Examples
    --------
    >>> from calc.domain.hysteresis import LoopModel
    >>> m = LoopModel(Q_(22, "N*m/arcmin"), Q_(8, "arcmin"), Q_(110, "N*m"))
    >>> (loop_slope(m, Q_([55, 110], "N*m")) / m.stiffness).m_as("").round(3).tolist()
    [1.0, 1.0]
    """
    t = np.abs(np.asarray(as_kind(torque, "torque", "torque").m_as("N*m"), float))
    h = 1e-4 * model.nominal_torque.m_as("N*m")
    rise = (model.middle_curve(Q_(t + h, "N*m")) - model.middle_curve(Q_(t - h, "N*m"))).m_as("rad")
    return Q_((2 * h / rise)[()], "N*m/rad")


def torque_reversals(torques) -> int:
    """How often the torque changes sign over one cycle, the cycle repeated (zeros skipped: a
    torque that falls to zero and rises again with the same sign does not reverse).

    Parameters
    ----------
    torques : pint.Quantity [N·m]
        The torque of each segment or sample, in the cycle's order.

    Returns
    -------
    int
        Sign changes per cycle [1].

    Examples
    --------
    The example's table: accelerate, run against friction, brake, dwell:

    >>> torque_reversals(Q_([7.8, 3.0, -2.3, 0.0], "N*m"))
    2
    """
    t = np.asarray(as_kind(torques, "torque", "torques").m_as("N*m"), float).reshape(-1)
    signs = np.sign(t[t != 0])
    if len(signs) < 2:
        return 0
    return int(np.count_nonzero(signs != np.roll(signs, 1)))
