"""The drive train's dynamics (results key ``dynamics``): the chain of masses and springs the case
gives (motor, coupling halves, gearbox input, load reflected), its natural frequencies and mode
shapes, its anti-resonances with the motor held, the two-mass model's resonance ratio beside
``√(1 + λ)``, the frequency response of the motor's speed to its torque, the stiffness each spring
stands on at the working point, and the torque reversals per cycle with the backlash crossed at each
(:mod:`calc.domain.dynamics`).

The chain is the coupling section's (``coupling.torsion``) where the case has one, so both give the
same frequencies; without a coupling it is the motor and the gearbox's ``J_1`` on the gearbox's
``C_t21 / i²`` against the load ``J_L / i²``. The gearbox's spring is taken at the torques the
gearbox carries over the cycle where the case gives its curve (an ``[accuracy]`` component's
``stiffness_curve``): the lowest first mode governs. Where only ``C_t21`` is known, the check stands
on it (the makers' convention) and says so, with the band where ``C_t21`` holds and the first mode
the workbook's loop model gives at the working torques, for information.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

from ..core.checks import Check, within_rating
from ..core.units import Q_, Value, fmt
from ..domain.coupling import f_e_min
from ..domain.dynamics import (
    band_slope, frequency_response, loop_slope, modes, resonance_ratio, torque_reversals,
    two_mass_anti_resonance, two_mass_load, two_mass_resonance,
)
from ..domain.hysteresis import STIFFNESS_BAND, model_for_row
from ..domain.stiffness import series_stiffness
from ..domain.torsion import TrainMember, gearbox_at_input, load_at_input, lumped
from .case import Case
from .common import SHOWN_CANDIDATES, Governing, Verdict, check_json, check_line, json_of
from .protocol import Result, Section

NAME = "dynamics"
ORDER = 55  # after the coupling, before the motor
#: Points of the frequency response (log-spaced); enough to resolve a peak of ζ = 0.02.
RESPONSE_POINTS = 600
#: The response's span: from this share of the lowest anti-resonance to this multiple of the highest mode.
RESPONSE_SPAN = (0.1, 3.0)
#: What λ's limit means, in one sentence (the two-mass model).
LAMBDA_MEANING = ("λ = J_Lm / J_motor, everything the motor drives over its rotor; in the two-mass model the "
                  "resonance lies a factor √(1 + λ) above the anti-resonance, so λ <= {limit:g} keeps the "
                  "anti-resonance, where the motor barely moves and the speed loop loses its grip on the load, "
                  "within a factor {factor:.3g} below the resonance")


@dataclass(frozen=True)
class Spring:
    """A spring of the chain as the dynamics take it.

    Parameters
    ----------
    name : str
        What it is (``"gearbox"``).
    part : str
        The part (``"NPT035-10"``).
    C : calc.core.units.Value
        Its stiffness at the chain's shaft, as the check takes it [N*m/rad].
    basis : str
        Which stiffness it is and where it comes from.
    band : tuple of calc.core.units.Value or None
        (from, to) [N*m] at the part's own shaft where that stiffness holds; None where unbounded.
    outside : bool
        The working torques lie outside ``band``.
    """

    name: str
    part: str
    C: Value
    basis: str
    band: tuple | None
    outside: bool = False

    def to_json(self) -> dict:
        """The spring as ``dynamics.springs`` writes it.

        Returns
        -------
        dict
            Name, part, C, basis, band and whether the working torques lie outside it.
        """
        band = None if self.band is None else {"from": self.band[0].to_json(), "to": self.band[1].to_json()}
        return {"name": self.name, "part": self.part, "C": self.C.to_json(), "basis": self.basis, "band": band,
                "outside_band": self.outside}


@dataclass
class Train:
    """The chain as evaluated: masses and springs at the chain's shaft, the factor that refers the
    motor's shaft to it, and what the case does not give.

    Parameters
    ----------
    masses : tuple of str
        What each mass holds, drive to load.
    inertias : pint.Quantity [kg*cm**2] or None
        The masses at the chain's shaft; None where a member's inertia is unknown.
    springs : list of Spring
        The springs between them.
    shaft : str
        The shaft they are referred to.
    to_shaft : float
        An inertia or stiffness at the motor's shaft times this is at the chain's shaft [1].
    gearbox_spring : int or None
        The index of the gearbox's spring; None without one.
    missing : list of str
        The members the case does not give.
    """

    masses: tuple
    inertias: object  # kg*cm**2, shape (n,)
    springs: list  # of Spring
    shaft: str
    to_shaft: float  # inertia and stiffness at the motor's shaft times this: at the chain's shaft
    gearbox_spring: int | None = None  # index of the gearbox's spring
    missing: list = field(default_factory=list)


def _gearbox_row(gearbox) -> tuple:
    """(selection, best-ranked row, its part) of the gearbox section."""
    sel = gearbox.selection
    row = int(sel.order[0])
    return sel, row, str(sel.catalog.parts[row])


def _chain(case: Case, gearbox, coupling) -> Train | None:
    """The chain of the case: the coupling section's where it has one, else the motor with the
    gearbox's ``J_1`` on ``C_t21 / i²`` against the load ``J_L / i²``; None without a spring."""
    sel_c = None if coupling is None else coupling.selection
    g_part = None if gearbox is None else _gearbox_row(gearbox)[2]
    if sel_c is not None and sel_c.chain is not None:
        row = int(sel_c.order[0])
        chain, train = sel_c.chain, sel_c.drive_train
        part = str(sel_c.catalog.parts[row])
        i = None if gearbox is None else float(gearbox.selection.catalog["ratio"][_gearbox_row(gearbox)[1]].m_as(""))
        to_shaft = i**2 if train.shaft == "the gearbox output" else 1.0
        springs = [Spring(name, part if name == "coupling" else g_part, Value.of(C, "N*m/rad"), "", None)
                   for name, C in zip(chain.springs, chain.stiffnesses[row])]
        g = chain.springs.index("gearbox") if "gearbox" in chain.springs else None
        return Train(chain.masses, chain.inertias[row], springs, train.shaft, to_shaft, g, list(train.missing))
    if gearbox is None or case.motor_inertia is None or case.load_inertia is None:
        return None
    sel, row, part = _gearbox_row(gearbox)
    i, C_t21, J_1 = sel.catalog["ratio"][row], sel.catalog["C_t21"][row], sel.J_1[row]
    missing = [f"the gearbox's {what} ({part}: the catalog gives none)"
               for what, q in (("C_t21", C_t21), ("J_1", J_1)) if np.isnan(q.magnitude)]
    if missing:
        return Train(("motor + gearbox", "load"), None, [], "the gearbox input", 1.0, None, missing)
    chain = lumped([TrainMember("motor", case.motor_inertia),
                    TrainMember("gearbox", J_1, gearbox_at_input(C_t21=C_t21, i=i)),
                    TrainMember("load", load_at_input(J_L=case.load_inertia, i=i))])
    springs = [Spring("gearbox", part, Value.of(chain.stiffnesses[0], "N*m/rad"), "", None)]
    return Train(chain.masses, chain.inertias, springs, "the gearbox input", 1.0, 0)


def _curve_of(accuracy, part: str):
    """The stiffness curve an ``[accuracy]`` component gives for the gearbox ``part``; None without."""
    if accuracy is None:
        return None
    for c in accuracy.inputs.chain.components:
        if c.stiffness_curve is not None and c.name == part:
            return c.stiffness_curve
    return None


def _working_torques(case: Case):
    """The distinct torques the gearbox carries over the cycle, their sizes, zero left out [N*m]."""
    t = np.abs(case.profile.torques.m_as("N*m"))
    return Q_(np.unique(t[t > 0]), "N*m")


@dataclass
class Basis:
    """The gearbox spring at the working point.

    Parameters
    ----------
    per_torque : pint.Quantity [N*m/rad]
        Its stiffness at each working torque, at the chain's shaft.
    spring : Spring
        The spring as shown.
    sentence : str
        What the check stands on.
    model_per_torque : pint.Quantity [N*m/rad] or None
        With C_t21 alone, the loop model's slope at each working torque (for information).
    """

    per_torque: object  # N*m/rad at the chain's shaft, one per working torque
    spring: Spring
    sentence: str
    model_per_torque: object = None


def _gearbox_basis(train: Train, gearbox, accuracy, torques) -> Basis:
    """How the gearbox's spring is taken at the working torques (module docstring)."""
    sel, row, part = _gearbox_row(gearbox)
    i = float(sel.catalog["ratio"][row].m_as(""))
    factor = train.to_shaft / i**2  # the output's N*m/rad at the chain's shaft
    spring = train.springs[train.gearbox_spring]
    span = f"{fmt(torques.min(), 'N*m')} to {fmt(torques.max(), 'N*m')}" if len(torques) else "no torque"
    curve = _curve_of(accuracy, part)
    if curve is not None and len(torques):
        slopes = band_slope(curve, torques).m_as("N*m/rad")
        low = int(np.argmin(slopes))
        band = curve.band(torques[low])
        edges = [Q_(0, "N*m"), curve.T_1, curve.T_2, Q_(np.inf, "N*m")]
        basis = (f"the K1–K3 curve of {part} ([accuracy] stiffness_curve): K{band + 1}, its slope at "
                 f"{fmt(torques[low], 'N*m')}, the softest of the working torques {span}")
        shown = Spring("gearbox", part, Value.of(Q_(slopes[low] * factor, "N*m/rad"), "N*m/rad"), basis,
                       (Value.of(edges[band], "N*m"), Value.of(edges[band + 1], "N*m")))
        return Basis(Q_(slopes * factor, "N*m/rad"), shown, f"stands on {basis}")
    t_n = sel.catalog["T_2N"][row]
    band = (Value.of(STIFFNESS_BAND[0] * t_n, "N*m"), Value.of(STIFFNESS_BAND[1] * t_n, "N*m"))
    outside = bool(len(torques)) and float(torques.max().m_as("N*m")) < band[0].value
    basis = (f"C_t21 of {part} from the catalog: the makers' slope between {band[0]} and {band[1]} "
             f"({STIFFNESS_BAND[0]:.0%} to {STIFFNESS_BAND[1]:.0%} of T_2N)")
    sentence = f"stands on {basis}"
    if outside:
        sentence += (f"; the gearbox carries {span} over the cycle, below that band: the stiffness is taken "
                     "outside its band, as the makers' convention takes it. Give the curve as an [accuracy] "
                     "component's stiffness_curve (T1, T2, K1, K2, K3) or a measured hysteresis loop to check "
                     "the mode where the gearbox works")
    shown = Spring("gearbox", part, spring.C, basis, band, outside)
    model = None
    if len(torques) and not np.isnan(sel.catalog["backlash"][row].magnitude):
        model = Q_(loop_slope(model_for_row(sel.catalog, row), torques).m_as("N*m/rad") * factor, "N*m/rad")
    per = Q_(np.full(len(torques) or 1, spring.C.value), "N*m/rad")
    return Basis(per, shown, sentence, model)


def _check(name: str, criterion: str, required, rated, unit: str, governs: bool, not_made: str | None = None) -> Check:
    """A check of the dynamics: required <= rated, or not made with its reason."""
    if not_made is not None or required is None or rated is None:
        return Check(name, criterion, None, Q_(np.nan, unit) if rated is None else rated, unit, None, None, governs,
                     not_made=not_made or "the chain has no mode to check")
    u = float(required.m_as(unit) / rated.m_as(unit))
    return Check(name, criterion, required, rated, unit, u, bool(within_rating(u)), governs)


@dataclass
class TwoMass:
    """The two-mass model: the rotor against everything it drives on the chain's springs in series,
    referred to the chain's shaft.

    Parameters
    ----------
    J_motor, J_Lm : calc.core.units.Value
        The rotor, and everything it drives [kg*cm**2].
    C_s : calc.core.units.Value
        The springs in series [N*m/rad].
    f_r, f_ar : calc.core.units.Value
        Resonance and anti-resonance [Hz].
    ratio : float
        ``f_r / f_ar`` [1].
    inertia_ratio : float
        ``λ = J_Lm / J_motor`` [1].
    steps : list
        (title, :class:`calc.core.formula.Step`) as computed.
    """

    J_motor: Value
    J_Lm: Value
    C_s: Value
    f_r: Value
    f_ar: Value
    ratio: float
    inertia_ratio: float
    steps: list

    def to_json(self) -> dict:
        """The two-mass model as ``dynamics.two_mass`` writes it.

        Returns
        -------
        dict
            J_motor, J_Lm, C_s, f_r, f_ar and the ratio.
        """
        return {"J_motor": self.J_motor.to_json(), "J_Lm": self.J_Lm.to_json(), "C_s": self.C_s.to_json(),
                "f_r": self.f_r.to_json(), "f_ar": self.f_ar.to_json(), "f_r_over_f_ar": self.ratio}


def _two_mass(case: Case, train: Train, stiffnesses, gearbox, coupling) -> TwoMass:
    """The two-mass model of the chain with the springs ``stiffnesses`` [N*m/rad]."""
    J_M = case.motor_inertia * train.to_shaft
    J_Lm = Q_(float(train.inertias.m_as("kg*cm**2").sum()), "kg*cm**2") - J_M
    steps = []
    if gearbox is not None and train.to_shaft == 1.0:
        sel, row, _ = _gearbox_row(gearbox)
        sel_c = None if coupling is None else coupling.selection
        J_K = Q_(0.0, "kg*cm**2") if sel_c is None else sel_c.catalog["J"][int(sel_c.order[0])]
        steps.append(("Everything the motor drives, at its shaft", two_mass_load.step(
            J_K=J_K, J_1=sel.J_1[row], J_L=case.load_inertia, i=sel.catalog["ratio"][row])))
    c_s = series_stiffness.step(C_k=stiffnesses)
    lam = float((J_Lm / J_M).m_as(""))
    f_r = two_mass_resonance.step(C_s=c_s.result, J_motor=J_M, J_Lm=J_Lm)
    f_ar = two_mass_anti_resonance.step(C_s=c_s.result, J_Lm=J_Lm)
    ratio = resonance_ratio.step(**{"lambda": Q_(lam, "")})
    steps += [("The chain's springs in series", c_s), ("Resonance of the two-mass model", f_r),
              ("Anti-resonance of the two-mass model (motor held)", f_ar), ("Their ratio from λ", ratio)]
    return TwoMass(Value.of(J_M, "kg*cm**2"), Value.of(J_Lm, "kg*cm**2"), Value.of(c_s.result, "N*m/rad"),
                   Value.of(f_r.result, "Hz"), Value.of(f_ar.result, "Hz"), float(ratio.result.m_as("")), lam, steps)


@dataclass
class DynamicsResult(Result):
    """The drive train's dynamics as evaluated (module docstring).

    Parameters
    ----------
    train : Train or None
        The chain; None where the case gives no spring.
    reason : str or None
        Why there is no chain, or what it lacks.
    springs : list of Spring
        Each spring with its basis and band.
    working_torques : pint.Quantity [N*m]
        The sizes of the torques the gearbox carries over the cycle.
    governing_torque : pint.Quantity [N*m] or None
        The working torque whose first mode is the lowest (a curve); None at one stiffness.
    modes : calc.domain.dynamics.Modes or None
        Of the chain as the check takes it.
    stiffnesses : pint.Quantity [N*m/rad] or None
        The springs as the check takes them, at the chain's shaft.
    two_mass : TwoMass or None
        The two-mass model.
    inertia_limit : tuple
        (λ_max, where it comes from).
    reversals : int
        Torque reversals per cycle at the gearbox.
    backlash : calc.core.units.Value or None
        The backlash crossed at each reversal, at the output [arcmin].
    checks : list of calc.core.checks.Check
        The resonance check, the loop model's (for information) and the anti-resonance's.
    bases : dict
        Check name -> the sentence saying what stiffness it stands on.
    notes : list of str
        What else the results say.
    """

    train: Train | None
    reason: str | None
    springs: list
    working_torques: object
    governing_torque: object
    modes: object
    stiffnesses: object
    two_mass: TwoMass | None
    inertia_limit: tuple
    reversals: int
    backlash: Value | None
    checks: list
    bases: dict
    notes: list

    @functools.cached_property
    def response(self):
        """The frequency response of the motor's speed to its torque over the chain's modes
        (:data:`RESPONSE_SPAN`); None without modes."""
        if self.modes is None:
            return None
        f = np.concatenate((self.modes.natural_frequencies.m_as("Hz"), self.modes.anti_resonances.m_as("Hz")))
        grid = np.geomspace(f.min() * RESPONSE_SPAN[0], f.max() * RESPONSE_SPAN[1], RESPONSE_POINTS)
        return frequency_response(self.train.inertias, self.stiffnesses, Q_(np.sort(np.concatenate((grid, f))), "Hz"))

    @property
    def lam_meaning(self) -> str:
        """What λ's limit means (:data:`LAMBDA_MEANING`)."""
        limit = self.inertia_limit[0]
        return LAMBDA_MEANING.format(limit=limit, factor=np.sqrt(1 + limit))

    def inertia_ratio_json(self) -> dict | None:
        """``dynamics.inertia_ratio``: λ as used, its terms, its limit and what the limit means."""
        tm = self.two_mass
        if tm is None:
            return None
        return {"value": tm.inertia_ratio, "J_Lm": tm.J_Lm.to_json(), "J_motor": tm.J_motor.to_json(),
                "definition": "λ = J_Lm / J_motor with J_Lm = J_K + J_1 + J_L / i² (the coupling counted: the motor "
                              "accelerates it, and its check counts it)",
                "limit": self.inertia_limit[0], "limit_from": self.inertia_limit[1],
                "sqrt_1_plus_lambda": float(np.sqrt(1 + tm.inertia_ratio)), "meaning": self.lam_meaning}

    def to_json(self, candidates: int | None = SHOWN_CANDIDATES) -> dict:
        """The ``dynamics`` results of the JSON contract (``docs/case-format.md``).

        Parameters
        ----------
        candidates : int or None
            Unused: the dynamics list no candidates.

        Returns
        -------
        dict
            masses, springs, natural_frequencies, mode_shapes, anti_resonances, two_mass,
            resonance_ratio, inertia_ratio, torque_reversals, checks and notes.
        """
        t, m = self.train, self.modes
        masses = [] if t is None or t.inertias is None else [
            {"members": name, "J": Value.of(J, "kg*cm**2").to_json()} for name, J in zip(t.masses, t.inertias)]
        return {
            "shaft": None if t is None else t.shaft,
            "complete": t is not None and not t.missing and m is not None,
            "missing": [] if self.reason is None else [self.reason],
            "masses": masses,
            "springs": [s.to_json() for s in self.springs],
            "working_torques": [Value.of(q, "N*m").to_json() for q in self.working_torques],
            "governing_torque": None if self.governing_torque is None else Value.of(self.governing_torque,
                                                                                    "N*m").to_json(),
            "natural_frequencies": [] if m is None else [Value.of(f, "Hz").to_json() for f in m.natural_frequencies],
            "mode_shapes": [] if m is None else [[round(float(x), 6) for x in row] for row in m.shapes],
            "anti_resonances": [] if m is None else [Value.of(f, "Hz").to_json() for f in m.anti_resonances],
            "two_mass": None if self.two_mass is None else self.two_mass.to_json(),
            "resonance_ratio": None if self.two_mass is None else self.two_mass.ratio,
            "resonance_ratio_of_chain": None if m is None else float(m.natural_frequencies[0] / m.anti_resonances[0]),
            "inertia_ratio": self.inertia_ratio_json(),
            "torque_reversals": {"per_cycle": self.reversals, "backlash_crossed": json_of(self.backlash)},
            "checks": [dict(check_json(k), basis=self.bases.get(k.name)) for k in self.checks],
            "notes": list(self.notes),
        }

    def summary_lines(self, candidates: int | None = SHOWN_CANDIDATES) -> list[str]:
        """The dynamics as lines of the text summary.

        Parameters
        ----------
        candidates : int or None
            Unused.

        Returns
        -------
        list of str
            The chain, its modes and anti-resonances, the two-mass model and λ, the springs' bases,
            the reversals, the checks and the notes.
        """
        t, m = self.train, self.modes
        lines = [f"Drive-train dynamics{'' if t is None else ', at ' + t.shaft}:"]
        if m is None:
            return lines + [f"  no modes: {self.reason}"] + [f"  {check_line(k, 20)}" for k in self.checks]
        hz = ", ".join(fmt(f, "Hz") for f in m.natural_frequencies)
        lines += [f"  natural frequencies {hz}; anti-resonances (motor held) "
                  f"{', '.join(fmt(f, 'Hz') for f in m.anti_resonances)}"]
        tm = self.two_mass
        lines.append(f"  two-mass model: f_r = {tm.f_r}, f_ar = {tm.f_ar}, f_r / f_ar = {tm.ratio:.4g} = √(1 + λ), "
                     f"λ = J_Lm / J_motor = {tm.J_Lm} / {tm.J_motor} = {tm.inertia_ratio:.4g}")
        lines.append(f"  λ <= {self.inertia_limit[0]:g} ({self.inertia_limit[1]}): {self.lam_meaning}")
        lines += [f"  spring {s.name} {s.part}: C = {s.C} ({s.basis})" for s in self.springs]
        lines.append(f"  torque reversals per cycle at the gearbox: {self.reversals}"
                     + ("" if self.backlash is None or not self.reversals
                        else f", each crossing the backlash {self.backlash} with no stiffness"))
        for k in self.checks:
            lines.append(f"  {check_line(k, 20)}")
            if k.name in self.bases:
                lines.append(f"      {self.bases[k.name]}")
        return lines + [f"  note: {n}" for n in self.notes]

    def governing(self) -> Governing:
        """The governing resonance check.

        Returns
        -------
        calc.sections.common.Governing
            The section's own governing checks.
        """
        return Governing(NAME, None, True, [k for k in self.checks if k.governs])

    def unchecked(self) -> list[str]:
        """The checks not made, with why.

        Returns
        -------
        list of str
            ``dynamics: f_1: why``.
        """
        return [f"{NAME}: {k.name}: {k.not_made}" for k in self.checks if k.passes is None]

    def verdict(self) -> Verdict | None:
        """Fails where the governing resonance check fails; None where no check governs.

        Returns
        -------
        calc.sections.common.Verdict or None
        """
        governing = [k for k in self.checks if k.governs]
        if not governing:
            return None
        failing = [k for k in governing if k.passes is False]
        if failing:
            return Verdict(False, [f"Drive-train dynamics: {k.reason()}" for k in failing])
        open_ = [k for k in governing if k.passes is None]
        return Verdict(None, [f"Drive-train dynamics: {k.reason()}" for k in open_]) if open_ else Verdict(True)


def _lowest_first_mode(train: Train, per_torque, g: int | None):
    """The modes at each working torque's gearbox stiffness, and the index of the lowest first mode."""
    base = np.array([s.C.value for s in train.springs], float)
    found = []
    for c in np.atleast_1d(per_torque.m_as("N*m/rad")):
        springs = base.copy()
        if g is not None:
            springs[g] = c
        found.append((modes(train.inertias, Q_(springs, "N*m/rad")), springs))
    low = int(np.argmin([m.natural_frequencies.m_as("Hz")[0] for m, _ in found]))
    return found, low


def evaluate_dynamics(case: Case, gearbox, coupling, accuracy) -> DynamicsResult:
    """The dynamics of the case's drive train (module docstring).

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as checked, with the motor it is checked with.
    gearbox, coupling, accuracy : Result or None
        The sections' results; None where the case has none.

    Returns
    -------
    DynamicsResult
        The chain, its modes and checks.
    """
    train = _chain(case, gearbox, coupling)
    torques = _working_torques(case)
    f_er = None if coupling is None else coupling.inputs.inputs["excitation_frequency"]
    limit = case.motor_max_inertia_ratio
    backlash = None
    if gearbox is not None:
        sel, row, _ = _gearbox_row(gearbox)
        j = sel.catalog["backlash"][row]
        backlash = None if np.isnan(j.magnitude) else Value.of(j, "arcmin")
    reversals = torque_reversals(case.profile.torques)
    common = dict(working_torques=torques, inertia_limit=limit, reversals=reversals, backlash=backlash)
    unknown = [s for s in (train.springs if train else []) if s.C.value is None]
    reason = None
    if train is None:
        reason = ("the case gives no spring: a coupling, or a gearbox with C_t21 and J_1, and the motor's and "
                  "the load's inertia")
    elif train.inertias is None or unknown or np.isnan(train.inertias.magnitude).any():
        no_j = [] if train.inertias is None else [f"the inertia of {name} (the catalog leaves a member's J empty)"
                                                  for name, J in zip(train.masses, train.inertias)
                                                  if np.isnan(J.magnitude)]
        reason = "; ".join(train.missing + [f"the {s.name}'s stiffness ({s.part}: the catalog gives none)"
                                            for s in unknown] + no_j)
    if reason is not None:
        not_made = f"the chain's first mode needs {reason}"
        checks = [_check("f_1", "2 f_er <= f_1", None, None, "Hz", False, not_made)]
        return DynamicsResult(train, reason, [] if train is None else train.springs, governing_torque=None,
                              modes=None, stiffnesses=None, two_mass=None, checks=checks, bases={}, notes=[], **common)
    springs, bases, notes = list(train.springs), {}, []
    springs = [s if s.name != "coupling" else Spring(s.name, s.part, s.C, f"C_T of {s.part} from the catalog", None)
               for s in springs]
    basis = None
    if train.gearbox_spring is not None:
        basis = _gearbox_basis(train, gearbox, accuracy, torques)
        springs[train.gearbox_spring] = basis.spring
        found, low = _lowest_first_mode(train, basis.per_torque, train.gearbox_spring)
    else:
        found, low = _lowest_first_mode(train, Q_([0.0], "N*m/rad"), None)
    m, stiff = found[low]
    curve = basis is not None and basis.model_per_torque is None and len(torques) > 1 and len(found) > 1
    two = _two_mass(case, train, Q_(stiff, "N*m/rad"), gearbox, coupling)
    required = None if f_er is None else f_e_min(f_er=f_er)
    why = None if f_er is not None else "the case gives no excitation frequency f_er (coupling.excitation_frequency)"
    governs = not train.missing and f_er is not None  # nothing to decide without f_er
    checks = [_check("f_1", "2 f_er <= f_1", required, m.natural_frequencies[0], "Hz", governs,
                     why)]
    bases["f_1"] = ("the chain as given" if basis is None else basis.sentence) + (
        f"; the lowest first mode of the working torques, at {fmt(torques[low], 'N*m')}" if curve else "")
    if basis is not None and basis.model_per_torque is not None:
        model, low_m = _lowest_first_mode(train, basis.model_per_torque, train.gearbox_spring)
        f_model = model[low_m][0].natural_frequencies[0]
        checks.append(_check("f_1,model", "2 f_er <= f_1,model", required, f_model, "Hz", False,
                             why))
        share = (basis.model_per_torque[low_m] / Q_(stiff[train.gearbox_spring], "N*m/rad")).m_as("")
        bases["f_1,model"] = (f"the workbook's loop model of {basis.spring.part} (calc.hysteresis defaults, not a "
                              f"measurement): its slope at {fmt(torques[low_m], 'N*m')} is {share:.0%} of C_t21")
    checks.append(_check("f_ar,1", "2 f_er <= f_ar,1", required, m.anti_resonances[0], "Hz", False,
                         why))
    bases["f_ar,1"] = ("the speed loop's bandwidth kept well below the lowest anti-resonance, where the motor barely "
                       "moves while the load swings (servo tuning guides), with E7's margin of 2; for information")
    if reversals and backlash is not None:
        notes.append(f"the gearbox torque changes sign {reversals} times per cycle; at each the chain crosses the "
                     f"backlash {backlash} with no stiffness at all: the load coasts free until the flanks meet")
    return DynamicsResult(train, None, springs, governing_torque=torques[low] if curve else None, modes=m,
                          stiffnesses=Q_(stiff, "N*m/rad"), two_mass=two, checks=checks, bases=bases, notes=notes,
                          **common)


class DynamicsSection(Section):
    """The drive train's dynamics: evaluated for every case with a drive train (a coupling, or a
    gearbox), from the chain the other sections chose."""

    NAME = NAME
    REQUIRES = ("axis", "gearbox", "coupling", "accuracy")

    def applies(self, case: Case) -> bool:
        """With a coupling or a gearbox, and the motor's and the load's inertia (or a catalog motor).

        Parameters
        ----------
        case : calc.sections.case.Case
            The case as read.

        Returns
        -------
        bool
        """
        train = "coupling" in case.sections or case.ratio is not None or case.gearbox_part is not None
        return train and case.load_inertia is not None

    def evaluate(self, case: Case, earlier) -> DynamicsResult:
        """The dynamics with the parts the other sections chose.

        Parameters
        ----------
        case : calc.sections.case.Case
            The case as read (the axis's case, with its motor, is the one checked).
        earlier : dict
            The results of ``axis``, and of ``gearbox``, ``coupling`` and ``accuracy`` where the
            case has them.

        Returns
        -------
        DynamicsResult
            The chain, its modes and checks.
        """
        return evaluate_dynamics(earlier["axis"].case, earlier.get("gearbox"), earlier.get("coupling"),
                                 earlier.get("accuracy"))


SECTION = DynamicsSection()
