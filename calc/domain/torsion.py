"""Torsional modes of a drive train: a chain of masses and springs, its natural frequencies.

The source's resonance check (errata E7) takes the coupling as the only spring of a two-mass
system. A drive train through a gearbox has a second spring, the gearbox's own torsional
stiffness ``C_t21``, and seen from the motor it is ``i²`` times softer than the catalog prints it
(E11 turned round: an output-side stiffness appears at the input as ``C / i²``). Behind a ratio
of 10 a gearbox of 22 N·m/arcmin (75 600 N·m/rad) is about 756 N·m/rad at the input, far softer
than a bellows coupling; the first mode of the train is then set by the gearbox and the load, not
by the coupling.

The train is lumped as a chain, drive to load, every member referred to one shaft (the gearbox
input for a coupling between motor and gearbox):

* the motor's rotor with half the coupling;
* the other half of the coupling with the gearbox's ``J_1``;
* the load reflected to the input, ``J_L / i²``;

joined by the springs ``C_T`` (the coupling) and ``C_t21 / i²`` (the gearbox). A member not in the
case is left out (a direct drive has no gearbox spring). The natural frequencies are the roots of
the eigenproblem ``K·φ = ω²·J·φ`` (``K`` the chain's stiffness matrix, ``J`` the diagonal of its
inertias), solved by numpy for every candidate at once; the chain is free at both ends, so its
lowest root is the rigid-body mode (ω = 0), which is left out. Two masses give the source's
two-mass formula (:data:`calc.domain.coupling.f_e`) exactly.

A spring rate in N·m/rad over an inertia gives 1/s² only with the radian of ``J·α = T·rad``
(E15); on SI magnitudes the factor is 1.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.citation import Source
from ..core.errors import CalcError
from ..core.formula import Formula
from ..core.units import as_kind, fmt, from_si, to_si  # noqa: F401 (fmt: the doctests print with it)
from .documents import ERRATA, MECHANICS

load_at_input = Formula(
    "J_L1",
    ("J_L", "i"),
    lambda sp, J_L, i: J_L / i**2,
    Source(ERRATA.at("E8", note="the load reflected to the input, J_L / i²")),
)

gearbox_at_input = Formula(
    "C_t1",
    ("C_t21", "i"),
    lambda sp, C_t21, i: C_t21 / i**2,
    Source(ERRATA.at("E11", label="errata E11 turned round",
                     says="an output-side stiffness appears at the input as C / i²")),
)

inertia_at_output = Formula(
    "J_out",
    ("J_in", "i"),
    lambda sp, J_in, i: J_in * i**2,
    Source(ERRATA.at(("E8", "E11"), says="an input-side inertia appears at the output as J · i²")),
)


@dataclass(frozen=True)
class TrainMember:
    """One member of a drive train, drive to load, referred to the chain's shaft.

    Each value is a quantity, scalar or an array over candidates.

    Parameters
    ----------
    name : str
        What it is (``"gearbox"``).
    inertia : pint.Quantity [kg·cm²]
        The inertia on the member's drive end.
    stiffness : pint.Quantity [N·m/rad], optional
        The spring joining it to ``load_inertia``; None for a rigid mass.
    load_inertia : pint.Quantity [kg·cm²], optional
        The inertia on its load end (half a coupling).
    """

    name: str
    inertia: object
    stiffness: object = None
    load_inertia: object = None


@dataclass(frozen=True)
class MassSpringChain:
    """Masses and springs in series, drive to load, as lumped from :class:`TrainMember` s.

    Parameters
    ----------
    masses : tuple of str
        What each mass holds (``"motor + coupling"``).
    springs : tuple of str
        What each spring is.
    inertias : pint.Quantity [kg·cm²]
        The masses on the last axis; leading axes run over candidates.
    stiffnesses : pint.Quantity [N·m/rad]
        The springs between them (one fewer) on the last axis.
    """

    masses: tuple
    springs: tuple
    inertias: object
    stiffnesses: object

    def natural_frequencies(self):
        """The chain's natural frequencies, lowest first, the rigid-body mode left out
        (:func:`natural_frequencies`).

        Returns
        -------
        pint.Quantity [Hz]
            Shape ``(..., n - 1)``.
        """
        return natural_frequencies(self.inertias, self.stiffnesses)


def lumped(members, where: str = "drive train") -> MassSpringChain:
    """The chain of masses and springs of ``members`` (drive to load): inertias with no spring
    between them add into one mass.

    Parameters
    ----------
    members : sequence of TrainMember
        The drive train, drive to load.
    where : str
        The train's name, for error messages; default ``"drive train"``.

    Returns
    -------
    MassSpringChain
        Its masses and springs.

    Examples
    --------
    The example axis seen from the gearbox input: a 4.2 kg·cm² motor, AKD-30 (1 kg·cm²,
    25 000 N·m/rad), NPT035-10's J_1 = 0.93 kg·cm² and C_t21 / i² = 756.3 N·m/rad, the table's
    1500 kg·cm² / 10² = 15 kg·cm²:

    >>> from calc.core.units import Q_
    >>> chain = lumped([
    ...     TrainMember("motor", Q_(4.2, "kg*cm**2")),
    ...     TrainMember("coupling", Q_(0.5, "kg*cm**2"), Q_(25_000, "N*m/rad"), Q_(0.5, "kg*cm**2")),
    ...     TrainMember("gearbox", Q_(0.93, "kg*cm**2"), Q_(756.3, "N*m/rad")),
    ...     TrainMember("load", Q_(15, "kg*cm**2")),
    ... ])
    >>> chain.masses, chain.springs
    (('motor + coupling', 'coupling + gearbox', 'load'), ('coupling', 'gearbox'))
    >>> [fmt(f, "Hz") for f in chain.natural_frequencies()]
    ['208 Hz', '2425 Hz']
    """
    names, masses, springs, spring_names = [], [], [], []
    parts, mass = [], []
    for m in members:
        parts.append(m.name)
        mass.append(to_si(m.inertia, "inertia", f"{where}: {m.name}, inertia"))
        if m.stiffness is None:
            continue
        names.append(" + ".join(dict.fromkeys(parts)))
        masses.append(sum(mass))
        springs.append(to_si(m.stiffness, "stiffness", f"{where}: {m.name}, stiffness"))
        spring_names.append(m.name)
        parts, mass = ([m.name],
                       [to_si(m.load_inertia, "inertia",
                              f"{where}: {m.name}, load-end inertia")]) if m.load_inertia is not None else ([], [])
    if not mass:
        raise CalcError(f"{where}: the chain ends in a spring ({spring_names[-1]}); expected a mass after it")
    names.append(" + ".join(dict.fromkeys(parts)))
    masses.append(sum(mass))
    inertias = np.stack(np.broadcast_arrays(*masses), axis=-1)
    stiffnesses = np.stack(np.broadcast_arrays(*springs), axis=-1) if springs else np.zeros(inertias.shape[:-1] + (0,))
    return MassSpringChain(tuple(names), tuple(spring_names), from_si(inertias, "inertia", "kg*cm**2"),
                           from_si(stiffnesses, "stiffness", "N*m/rad"))


def natural_frequencies(inertias, stiffnesses, where: str = "drive train"):
    r"""Natural frequencies of a free chain of masses and springs, lowest first, without the
    rigid-body mode.

    .. math:: \left(K - \omega^2 J\right) \varphi = 0, \qquad f = \frac{\omega}{2\pi}

    with ``J = diag(J_1 … J_n)`` and ``K`` tridiagonal: ``K_kk = C_{k-1} + C_k``,
    ``K_k,k+1 = -C_k``. Solved as the symmetric problem ``J^-1/2 K J^-1/2`` (numpy's ``eigvalsh``).

    Parameters
    ----------
    inertias : pint.Quantity [kg·cm²], shape (..., n)
        The masses, drive to load; leading axes run over candidates.
    stiffnesses : pint.Quantity [N·m/rad], shape (..., n - 1)
        The springs between neighbouring masses (with their angle unit, E15).
    where : str
        The train's name, for error messages; default ``"drive train"``.

    Returns
    -------
    pint.Quantity [Hz], shape (..., n - 1)
        NaN in a candidate whose inertias or stiffnesses hold a NaN (a value the catalog leaves
        empty).

    Examples
    --------
    Two masses give the source's two-mass formula (E7), AKD-30 between the example's motor and
    load: ``f_e = √(25 000 · (4.7 + 16.43) / (4.7 · 16.43) / 1e-4) / 2π = 1316.35 Hz``:

    >>> from calc.core.units import Q_
    >>> natural_frequencies(Q_([4.7, 16.43], "kg*cm**2"), Q_([25_000], "N*m/rad")).m_as("Hz").round(2).tolist()
    [1316.35]
    """
    J = np.asarray(to_si(as_kind(inertias, "inertia", f"{where}: inertias"), "inertia", where), dtype=float)
    C = np.asarray(to_si(as_kind(stiffnesses, "stiffness", f"{where}: stiffnesses"), "stiffness", where), dtype=float)
    if J.ndim == 0 or C.shape[:-1] != J.shape[:-1] or C.shape[-1] != J.shape[-1] - 1:
        raise CalcError(f"{where}: expected one spring fewer than masses, found inertias of shape {np.shape(J)} and "
                        f"stiffnesses of shape {np.shape(C)}")
    n = J.shape[-1]
    if n < 2:
        raise CalcError(f"{where}: a chain needs two masses and a spring to have a mode, found {n} mass")
    valid = ~(np.isnan(J).any(axis=-1) | np.isnan(C).any(axis=-1))
    if np.any(J[valid] <= 0) or np.any(C[valid] <= 0):
        raise CalcError(f"{where}: expected inertias and stiffnesses above zero, found {J[valid].min():g} kg·m² and "
                        f"{C[valid].min():g} N·m/rad at least")
    J_ok, C_ok = J[valid], C[valid]
    K = np.zeros(J_ok.shape + (n,))
    k = np.arange(n - 1)
    K[..., k, k] += C_ok
    K[..., k + 1, k + 1] += C_ok
    K[..., k, k + 1] -= C_ok
    K[..., k + 1, k] -= C_ok
    scale = 1 / np.sqrt(J_ok)
    roots = np.linalg.eigvalsh(K * scale[..., :, None] * scale[..., None, :])
    # The first root is the rigid-body mode, zero up to rounding.
    omega = np.sqrt(np.clip(roots[..., 1:], 0.0, None))
    out = np.full(J.shape[:-1] + (n - 1,), np.nan)
    out[valid] = omega / (2 * np.pi)
    return from_si(out, "frequency", "Hz")


@dataclass(frozen=True)
class CouplingSpan:
    """The couplings a case may fit between motor and gearbox, and what the drive train around
    them holds fixed: enough to bound, for any gearbox, the first mode its train can reach.

    Parameters
    ----------
    drive_inertia : pint.Quantity [kg·cm²]
        The motor's rotor.
    load_inertia : pint.Quantity [kg·cm²]
        The load at the gearbox output.
    stiffness : pint.Quantity [N·m/rad]
        Each coupling's ``C_T``, an array over the couplings.
    inertia : pint.Quantity [kg·cm²]
        Each coupling's whole ``J`` (half on each end of its spring), an array over the couplings.
    f_min : pint.Quantity [Hz]
        The lowest first mode allowed (``2 f_er``, E7).
    couplings : str
        Which couplings they are.
    """

    drive_inertia: object
    load_inertia: object
    stiffness: object
    inertia: object
    f_min: object
    couplings: str


def _first_mode_of_three(sp, J_a, J_b, J_c, C_ab, C_bc, rad):
    # det(K - ω² J) = ω² (ω⁴ - p ω² + q) for three masses free at both ends; the lower root of the
    # quadratic, written 2q / (p + √(p² - 4q)) so that it keeps its digits where p² ≫ 4q.
    p = C_ab * rad * (1 / J_a + 1 / J_b) + C_bc * rad * (1 / J_b + 1 / J_c)
    q = C_ab * rad * C_bc * rad * (J_a + J_b + J_c) / (J_a * J_b * J_c)
    return sp.sqrt(2 * q / (p + sp.sqrt(p**2 - 4 * q))) / (2 * sp.pi)


first_mode_of_three = Formula(
    "f_1",
    ("J_a", "J_b", "J_c", "C_ab", "C_bc", "rad"),  # masses a, b, c drive to load (J_1 is the gearbox's inertia)
    _first_mode_of_three,
    Source(MECHANICS.at(label="", says="the eigenproblem of three masses and two springs, free at both ends, solved in "
                                       "closed form", note="calc.domain.torsion")),
)


def highest_first_mode(span: CouplingSpan, J_1, C_t21, i):
    """For each gearbox, the highest first natural frequency of the train motor, coupling, gearbox,
    load that any coupling of ``span`` gives it: the train lumped as :func:`lumped` does, seen from
    the gearbox input (the load as ``J_L / i²``, the gearbox's spring as ``C_t21 / i²``).

    A gearbox is the train's soft spring: where even the best coupling leaves the first mode below
    ``2 f_er``, no coupling can rescue it.

    Parameters
    ----------
    span : CouplingSpan
        The couplings and the fixed members.
    J_1 : pint.Quantity [kg·cm²]
        Each gearbox's input inertia, an array over gearboxes.
    C_t21 : pint.Quantity [N·m/arcmin]
        Each gearbox's torsional stiffness at its output.
    i : pint.Quantity [1]
        Each gearbox's ratio.

    Returns
    -------
    pint.Quantity [Hz]
        Over gearboxes; NaN for a gearbox whose ``J_1`` or ``C_t21`` is unknown.

    Examples
    --------
    >>> from calc.core.units import Q_
    >>> span = CouplingSpan(Q_(4.2, "kg*cm**2"), Q_(1500, "kg*cm**2"), Q_([25_000, 6_000], "N*m/rad"),
    ...                     Q_([1.0, 0.6], "kg*cm**2"), Q_(200, "Hz"), "two bellows")
    >>> f_1 = highest_first_mode(span, Q_([0.93], "kg*cm**2"), Q_([22], "N*m/arcmin"), Q_([10], ""))
    >>> f_1.m_as("Hz").round(1).tolist()
    [208.0]
    """
    C, J = span.stiffness.m_as("N*m/rad"), span.inertia.m_as("kg*m**2")
    # A stiffer spring raises every mode and more inertia lowers every one: a coupling that another
    # beats on both (stiffer, no heavier; or lighter, no softer) cannot give the highest.
    beaten = ((C[None, :] >= C[:, None]) & (J[None, :] <= J[:, None])
              & ((C[None, :] > C[:, None]) | (J[None, :] < J[:, None]))).any(axis=1)
    C, J = C[~beaten], J[~beaten]
    # Gearboxes down, couplings across: SI magnitudes, checked as quantities by the formulas above.
    half = J[None, :] / 2
    with np.errstate(invalid="ignore"):
        first = first_mode_of_three.si(
            J_a=span.drive_inertia.m_as("kg*m**2") + half,
            J_b=half + J_1.m_as("kg*m**2")[:, None],
            J_c=load_at_input(J_L=span.load_inertia, i=i).m_as("kg*m**2")[:, None],
            C_ab=C[None, :],
            C_bc=gearbox_at_input(C_t21=C_t21, i=i).m_as("N*m/rad")[:, None],
        )
    best = np.full(first.shape[0], np.nan)
    known = ~np.isnan(first).all(axis=1)
    best[known] = np.nanmax(first[known], axis=1)
    return from_si(best, "frequency", "Hz")
