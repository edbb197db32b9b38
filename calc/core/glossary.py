"""The workbook's symbols, each declared once, and the one typesetter of a symbol.

Every quantity a formula takes or gives is declared here, once, by its name in code (the source
document's symbol: ``T_2B``, ``n_2m``, ``J_L``): its LaTeX, the kind :mod:`calc.core.units` checks it
for, the unit it is shown in and what it is. Formulas (:class:`calc.core.formula.Formula`) and the
outputs refer to a symbol by its name; a name means one quantity everywhere. A formula may show a
symbol in another unit (:meth:`Symbol.shown_in`): the transmission error in arcsec, the positioning
accuracy in arcmin.

One typesetter (:func:`typeset`) writes every symbol the package prints, ISO 80000-2: the letter
italic, a subscript that names (``1B``, ``2max``, ``motor``, ``N``) upright, a running index (``k``)
italic, a Greek name as its letter. The LaTeX of a declared symbol is its name's (or the name the
source prints it by, where two quantities print alike: ``J_L_linear`` as ``J_L``); the calc report's
prose sets the symbols it finds by :func:`latex`, so a criterion and a calculation print a symbol
alike.
"""

from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass

from .units import declared_once


@dataclass(frozen=True)
class Symbol:
    """A quantity in a formula: its name in code, its LaTeX, its kind and the unit it is shown in.

    A symbol with a ``value`` (such as ``"1 rad"``) is a constant of the formula: callers do not
    pass it, the formula supplies it. It makes a unit convention explicit where strict angle
    bookkeeping needs one (errata E15), and is shown in the expression and its substitution.

    Parameters
    ----------
    name : str
        Its name in code, as the source document writes it (``"T_2max"``).
    latex : str
        Its LaTeX (``"T_{\\mathrm{2max}}"``), set by :func:`typeset`.
    kind : str
        Its kind (:data:`calc.core.units.KINDS`: ``"torque"``).
    unit : str
        The unit it is shown in (``"N*m"``; empty for a bare number).
    description : str
        What it is, in words.
    per_segment : bool
        One value per segment of the profile (an array summed by
        :func:`calc.core.formula.segment_sum`); default False.
    value : str, optional
        The constant's value as text (``"1 rad"``); None for an input.
    """

    name: str
    latex: str
    kind: str
    unit: str
    description: str
    per_segment: bool = False
    value: str | None = None

    def shown_in(self, unit: str) -> "Symbol":
        """The same symbol shown in another unit of its kind.

        Parameters
        ----------
        unit : str
            A unit of the symbol's kind (``"arcsec"``).

        Returns
        -------
        Symbol
            The symbol with that unit; name, LaTeX, kind and description its own.
        """
        return dataclasses.replace(self, unit=unit)


#: Greek letters written out in code (and the difference sign), as LaTeX and as text.
GREEK = {
    "alpha": (r"\alpha", "α"), "eta": (r"\eta", "η"), "lambda": (r"\lambda", "λ"), "mu": (r"\mu", "μ"),
    "omega": (r"\omega", "ω"), "phi": (r"\varphi", "φ"), "rho": (r"\rho", "ρ"), "theta": (r"\theta", "θ"),
    "vartheta": (r"\vartheta", "ϑ"), "Delta": (r"\Delta", "Δ"),
}
_LETTERS = {text: tex for tex, text in GREEK.values()}
#: A subscript that counts (the segment or sample k of a sum) rather than names: italic.
INDEX = "k"


def typeset(name: str) -> str:
    r"""A symbol as written in code or prose as LaTeX math, by ISO 80000-2.

    The part before the first underscore is the letter (a Greek name or letter as the letter; an
    abbreviation of two letters or more upright); after it, the subscript: its parts (split at
    commas and further underscores) upright where they name, italic where they count (``k``),
    digits as they are, a Greek letter as the letter; a subscript that only names is one upright run.

    Parameters
    ----------
    name : str
        The symbol as code writes it (``T_1B``, ``phi_TA``, ``T_1,k``, ``K_ϑ``, ``Δφ_2,max``).

    Returns
    -------
    str
        LaTeX math, without the dollars.

    >>> print(typeset("T_1B"), typeset("T_1,k"), typeset("phi_TA"), typeset("K_ϑ"), typeset("ED"))
    T_{\mathrm{1B}} T_{1,k} \varphi_{\mathrm{TA}} K_{\vartheta} \mathrm{ED}
    >>> print(typeset("d_hub,max"), typeset("Δφ_2,max"), typeset("lambda"), typeset("P_back_k"), typeset("n_2"))
    d_{\mathrm{hub,max}} \Delta\varphi_{\mathrm{2,max}} \lambda P_{\mathrm{back},k} n_{2}
    """
    base, _, sub = name.partition("_")
    letter = _letter(base)
    if not sub:
        return letter
    parts = re.split("[,_]", sub)
    if sub.isdigit() or any(p == INDEX or p in GREEK or any(c in _LETTERS for c in p) for p in parts):
        return f"{letter}_{{{','.join(_subscript_part(part) for part in parts)}}}"
    return rf"{letter}_{{\mathrm{{{','.join(parts)}}}}}"  # names alone: one upright run, d_{\mathrm{hub,max}}


def _letter(text: str) -> str:
    """The letter of a symbol: a Greek name or letters (``Δφ``) as LaTeX, a Latin letter as is, an
    abbreviation (``ED``) upright."""
    if text in GREEK:
        return GREEK[text][0]
    if any(c in _LETTERS for c in text):
        tokens = [_LETTERS.get(c, c) for c in text]
        # a command before a Latin letter needs a space: \Delta T, not \DeltaT
        following = [*tokens[1:], ""]
        return "".join(t + (" " if t.startswith("\\") and n.isalpha() else "") for t, n in zip(tokens, following))
    return text if len(text) == 1 else rf"\mathrm{{{text}}}"


def _subscript_part(part: str) -> str:
    if part.isdigit() or part == INDEX:
        return part
    if part in GREEK:
        return GREEK[part][0]
    # Runs of Latin letters and digits upright, Greek letters as the letter: Nϑ -> \mathrm{N}\vartheta
    greek = "".join(_LETTERS)
    return "".join(_LETTERS.get(run, rf"\mathrm{{{run}}}") for run in re.findall(f"[{greek}]|[^{greek}]+", part))


def _symbol(name: str, kind: str, unit: str, description: str, written: str | None = None, latex: str | None = None,
            per_segment: bool = False, value: str | None = None) -> Symbol:
    """A declaration: its LaTeX is :func:`typeset` of ``written`` (default: the name), or ``latex``
    where the rule cannot write it (a ± 3 % in a subscript)."""
    return Symbol(name, latex or typeset(written or name), kind, unit, description, per_segment, value)


#: Every symbol of the formulas, by name.
SYMBOLS: dict[str, Symbol] = declared_once((
    # Constants of formulas (errata E15: angles as a dimension).
    _symbol("rad", "angle", "rad", "one radian (E15: J·α = T·rad, an arc is r · φ with φ in radians)", value="1 rad"),
    _symbol("g", "linear_acceleration", "m/s**2", "standard gravity", value="9.80665 m/s**2"),
    # The load cycle (source, Determination of the Duty Cycle; S1 and S5 calculations).
    _symbol("ED", "dimensionless", "percent", "duty cycle"),
    _symbol("t_on", "time", "s", "on-time, t_a + t_c + t_d (moving segments)"),
    _symbol("t_cycle", "time", "s", "cycle time, pauses included"),
    _symbol("t_k", "time", "s", "duration of segment or sample k", per_segment=True),
    _symbol("n_2k", "speed", "rpm", "mean output speed of moving segment k", "n_2,k", per_segment=True),
    _symbol("T_2k", "torque", "N*m", "output torque of moving segment k", "T_2,k", per_segment=True),
    _symbol("n_2m", "speed", "rpm", "mean output speed"),
    _symbol("T_2m", "torque", "N*m", "cubic mean output torque"),
    _symbol("z_c", "dimensionless", "", "load cycles (moves) in the cycle: acceleration, constant speed, deceleration, "
                                         "pause (E16)"),
    _symbol("Z_h", "per_hour", "1/hour", "number of load cycles (moves) per hour (E16)"),
    # The gearbox (source, S1 and S5; errata E1 to E6) and its output bearing.
    _symbol("i", "dimensionless", "", "ratio of the gearbox"),
    _symbol("eta", "dimensionless", "", "efficiency (of the gearbox; of a mechanism, its own)"),
    _symbol("n", "speed", "rpm", "motor speed"),
    _symbol("n_1", "speed", "rpm", "input speed"),
    _symbol("n_2", "speed", "rpm", "output speed"),
    _symbol("T_1", "torque", "N*m", "torque at the gearbox input: the motor torque"),
    _symbol("T_2", "torque", "N*m", "torque referred to the output"),
    _symbol("T_1B", "torque", "N*m", "maximum torque of the motor"),
    _symbol("T_2max", "torque", "N*m", "maximum output torque"),
    _symbol("T_2stop", "torque", "N*m", "output torque of an emergency stop"),
    _symbol("f_s", "dimensionless", "", "shock factor"),
    _symbol("lambda", "dimensionless", "", "load to motor inertia ratio"),
    _symbol("J_1", "inertia", "kg*cm**2",
            "gearbox inertia at the input (with a motor-side coupling's, where the motor turns it)"),
    _symbol("J_L", "inertia", "kg*cm**2", "load inertia at the gearbox output"),
    _symbol("J_motor", "inertia", "kg*cm**2", "motor inertia"),
    _symbol("M_2k", "torque", "N*m", "tilting moment on the output bearing"),
    _symbol("F_2a", "force", "N", "axial force on the output shaft"),
    _symbol("F_2r", "force", "N", "radial force on the output shaft"),
    _symbol("x_2", "length", "mm", "distance of the radial force from the output flange (lever arm)"),
    _symbol("y_2", "length", "mm", "distance of the axial force's line of action from the axis"),
    _symbol("z_2", "length", "mm",
            "distance from the output flange to the bearing's centre (catalog; 0 where not given)"),
    # The motor (case format, The motor's side; the motor chosen from a catalog).
    _symbol("alpha_1", "angular_acceleration", "rad/s**2", "angular acceleration of the motor"),
    _symbol("alpha_2", "angular_acceleration", "rad/s**2", "angular acceleration at the gearbox output"),
    _symbol("T_1_drive", "torque", "N*m", "motor torque, driving", "T_1"),
    _symbol("T_1_back", "torque", "N*m", "motor torque, driven back", "T_1"),
    _symbol("T_1rms", "torque", "N*m", "RMS motor torque over the whole cycle"),
    _symbol("T_1k", "torque", "N*m", "motor torque of sample k", "T_1,k", per_segment=True),
    _symbol("P_1", "power", "W",
            "mechanical power at the motor shaft (negative: the load drives back, the drive brakes)"),
    _symbol("omega_1", "speed", "rpm", "motor speed"),
    _symbol("W_regen", "energy", "J",
            "energy the load gives back to the drive per cycle (its braking resistor or DC link)"),
    _symbol("P_back_k", "power", "W", "braking power of sample k, |P_1| where P_1 < 0, else 0", per_segment=True),
    _symbol("T_peak_line", "torque", "N*m",
            "peak torque of the motor above its rated speed, from its ratings", "T_peak"),
    _symbol("M_max", "torque", "N*m", "maximum torque of the motor"),
    _symbol("M_N_motor", "torque", "N*m", "rated torque of the motor (its catalog's M_N)", "M_N"),
    _symbol("n_N", "speed", "rpm", "rated speed of the motor"),
    _symbol("n_max", "speed", "rpm", "maximum speed of the motor"),
    _symbol("T_V", "torque", "N*m", "torque the DC-link voltage allows at the speed (no field weakening)"),
    _symbol("U_DC", "voltage", "V", "DC-link voltage of the drive"),
    _symbol("k_E", "voltage_constant", "V/krpm", "voltage constant, line-to-line RMS"),
    _symbol("k_T", "torque_constant", "N*m/A", "torque constant, per A rms"),
    _symbol("R_ph", "resistance", "ohm", "phase resistance"),
    _symbol("L_ph", "inductance", "mH", "phase inductance"),
    # The servo drive, its braking energy and the winding's heat (case format, "The servo drive").
    _symbol("I_ph", "current", "A", "motor phase current, rms, from the torque (saturation not modelled)", "I"),
    _symbol("M_0", "torque", "N*m", "standstill torque of the motor"),
    _symbol("I_0", "current", "A", "standstill current of the motor, rms"),
    _symbol("k_T_derived", "torque_constant", "N*m/A", "torque constant derived as M_0 / I_0", "k_T"),
    _symbol("C_DC", "capacitance", "uF", "capacitance of the DC link"),
    _symbol("U_on", "voltage", "V", "switch-on voltage of the brake chopper"),
    _symbol("E_C", "energy", "J", "energy the DC link absorbs from U_DC up to U_on"),
    _symbol("R_br", "resistance", "ohm", "resistance of the brake resistor"),
    _symbol("P_R_peak", "power", "W", "power the brake resistor takes at the chopper voltage", "P_R,peak"),
    _symbol("E_R", "energy", "J", "energy the brake resistor takes per cycle"),
    _symbol("P_R_avg", "power", "W", "average power of the brake resistor over the cycle", "P_R,avg"),
    _symbol("T_th", "time", "min", "thermal time constant of the winding"),
    _symbol("u_th", "dimensionless", "", "thermal load of the winding, (T_1 / M_0)^2: 1 under M_0 held", "u"),
    _symbol("t_1", "time", "s", "time under load of a square cycle"),
    _symbol("theta_max", "dimensionless", "",
            "highest winding temperature rise over its rise under M_0 held continuously", "theta_max"),
    _symbol("poles", "dimensionless", "", "number of poles", "N_p"),
    # Couplings (source, Couplings; errata E7 to E10; makers' catalogs).
    _symbol("M_N", "torque", "N*m", "nominal torque of the coupling"),
    _symbol("M_a", "torque", "N*m", "acceleration torque of the motor"),
    _symbol("J_load", "inertia", "kg*cm**2", "load-side inertia as the coupling sees it"),
    _symbol("J_drive", "inertia", "kg*cm**2", "drive-side inertia"),
    _symbol("S_A", "dimensionless", "", "load (shock) factor"),
    _symbol("M_Nt", "torque", "N*m", "nominal torque with the temperature factor", "M_Nϑ"),
    _symbol("K_T", "dimensionless", "", "temperature factor (elastomer couplings)", "K_ϑ"),
    _symbol("M_Smax", "torque", "N*m", "peak torque with the start and temperature factors"),
    _symbol("T_S", "torque", "N*m", "peak torque at the coupling (the source's M_N: a drive-side shock with S_A)"),
    _symbol("S_z", "dimensionless", "", "start factor (starts per hour)"),
    _symbol("J_K", "inertia", "kg*cm**2", "inertia of the coupling"),
    _symbol("J_A", "inertia", "kg*cm**2", "drive side with half the coupling"),
    _symbol("J_L_coupling", "inertia", "kg*cm**2",
            "load side with half the coupling",
            "J_L"),
    _symbol("C_T", "stiffness", "N*m/rad", "torsional stiffness of the coupling"),
    _symbol("f_e", "frequency", "Hz", "natural frequency of the two-mass system"),
    _symbol("f_e_min", "frequency", "Hz", "lowest natural frequency allowed"),
    _symbol("f_er", "frequency", "Hz", "excitation frequency of the drive"),
    _symbol("A", "length", "mm", "distance between the shafts"),
    _symbol("H", "length", "mm", "hub length"),
    _symbol("Z", "length", "mm", "tube length"),
    _symbol("C_B", "stiffness", "N*m/rad", "stiffness of the two bellows together"),
    _symbol("C_tube", "stiffness_length", "N*m**2/rad", "tube stiffness per unit length"),
    # Stiffness, backlash and lost motion, accuracy (source; errata E11 to E15).
    _symbol("T", "torque", "N*m", "torque applied at the output, or through a member or coupling (its magnitude)"),
    _symbol("T_N", "torque", "N*m", "nominal torque of the gearbox, the measure of the loop's bands and the 3 % rule"),
    _symbol("C", "stiffness", "N*m/arcmin", "torsional stiffness at the output"),
    _symbol("C_t", "stiffness", "N*m/arcmin", "torsional stiffness, slope of the loop from 50 % to 100 % of T_N"),
    _symbol("C_k", "stiffness", "N*m/arcmin", "stiffness of component k, at the output", per_segment=True),
    _symbol("C_total", "stiffness", "N*m/arcmin", "total torsional stiffness, at the output"),
    _symbol("C_1", "stiffness", "N*m/arcmin", "stiffness of an input-side component"),
    _symbol("C_2", "stiffness", "N*m/arcmin", "stiffness referred to the output"),
    _symbol("C_t1", "stiffness", "N*m/rad", "torsional stiffness of the gearbox referred to its input"),
    _symbol("C_t21", "stiffness", "N*m/arcmin", "torsional stiffness of the gearbox at its output (catalog)"),
    _symbol("C_sec", "stiffness", "N*m/arcmin", "secant stiffness at a torque"),
    _symbol("T_L1", "torque", "N*m", "first limit torque of the stiffness curve", "T_1"),
    _symbol("T_L2", "torque", "N*m", "second limit torque of the stiffness curve", "T_2"),
    _symbol("K_1", "stiffness", "N*m/rad", "stiffness from 0 to T_1"),
    _symbol("K_2", "stiffness", "N*m/rad", "stiffness from T_1 to T_2"),
    _symbol("K_3", "stiffness", "N*m/rad", "stiffness above T_2"),
    _symbol("phi", "angle", "arcmin", "angle of twist"),
    _symbol("phi_c1", "angle", "arcmin",
            "twist by the stiffness curve, first slope (up to the first limit torque)", "phi"),
    _symbol("phi_c2", "angle", "arcmin",
            "twist by the stiffness curve, second slope (between the limit torques)", "phi"),
    _symbol("phi_c3", "angle", "arcmin",
            "twist by the stiffness curve, third slope (above the second limit torque)", "phi"),
    _symbol("phi_1", "angle", "arcmin", "angle at the gearbox input (a position, a backlash, an error)"),
    _symbol("phi_2", "angle", "deg", "angle referred to the output"),
    _symbol("j_t", "angle", "arcmin", "torsional backlash, width of the loop at 0 N·m"),
    _symbol("phi_LM", "angle", "arcmin", "total lost motion at the applied torque"),
    _symbol("phi_LM3", "angle", "arcmin",
            "lost motion, width of the loop over ±3 % of T_N", latex=r"\varphi_{\mathrm{LM},3\%}"),
    _symbol("phi_max_0", "angle", "arcmin", "largest twist at 0 N·m"),
    _symbol("phi_min_0", "angle", "arcmin", "smallest twist at 0 N·m"),
    _symbol("phi_max_3", "angle", "arcmin",
            "largest twist between -3 % and +3 % of T_N", latex=r"\varphi_{\mathrm{max},\pm 3\%}"),
    _symbol("phi_min_3", "angle", "arcmin",
            "smallest twist between -3 % and +3 % of T_N", latex=r"\varphi_{\mathrm{min},\pm 3\%}"),
    _symbol("Delta_T", "torque", "N*m", "torque from 50 % to 100 % of T_N", "ΔT"),
    _symbol("Delta_phi_twist", "angle", "arcmin", "twist over that torque, from the fitted line", "Δφ"),
    _symbol("phi_TA", "angle", "arcmin", "angular transmission accuracy"),
    _symbol("Delta_phi_P", "angle", "arcmin",
            "positioning accuracy at the applied torque (E13: the form its torque takes)", "Δφ_P"),
    _symbol("Delta_phi_P_low", "angle", "arcmin", "positioning accuracy, torque up to 3 % of nominal", "Δφ_P"),
    _symbol("Delta_phi_P_high", "angle", "arcmin", "positioning accuracy, torque above 3 % of nominal", "Δφ_P"),
    _symbol("Delta_phi", "angle", "arcmin", "positioning error", "Δφ"),
    _symbol("phi_e_k", "angle", "arcmin", "contribution k to the positioning accuracy's error budget (a full width)",
            "φ_e,k", per_segment=True),
    _symbol("Delta_phi_wc", "angle", "arcmin", "worst case of the error budget: every contribution added", "Δφ_wc"),
    _symbol("Delta_phi_rss", "angle", "arcmin", "root-sum-square of the error budget's independent contributions",
            "Δφ_RSS"),
    _symbol("phi_actual", "angle", "deg", "actual position"),
    _symbol("phi_target", "angle", "deg", "target position"),
    _symbol("Delta_phi_2", "angle", "arcsec", "transmission error at the output", "Δφ_2"),
    _symbol("Delta_phi_max", "angle", "arcsec", "largest transmission error over one output revolution", "Δφ_2,max"),
    _symbol("Delta_phi_min", "angle", "arcsec", "smallest transmission error over one output revolution", "Δφ_2,min"),
    _symbol("r", "length", "mm",
            "radius that turns an angle at the output into travel, s = r · φ (a pinion's pitch radius, a table's rim)"),
    _symbol("s", "length", "mm", "arc length at the radius"),
    _symbol("phi_s", "angle", "arcmin", "angle at the output that moves a point at the radius by s", "phi"),
    # The drive train's torsion (errata E7, E8, E11).
    _symbol("J_L1", "inertia", "kg*cm**2", "load inertia referred to the gearbox input"),
    _symbol("J_in", "inertia", "kg*cm**2", "inertia on the gearbox input (the motor's, the gearbox's J_1)"),
    _symbol("J_out", "inertia", "kg*cm**2", "inertia referred to the gearbox output"),
    _symbol("f_1", "frequency", "Hz", "first natural frequency of the drive train (of a chain of three masses)"),
    _symbol("J_a", "inertia", "kg*cm**2",
            "the first mass (the drive) of a chain of three masses, referred to one shaft"),
    _symbol("J_b", "inertia", "kg*cm**2", "the middle mass of a chain of three masses, referred to one shaft"),
    _symbol("J_c", "inertia", "kg*cm**2", "the last mass (the load) of a chain of three masses, referred to one shaft"),
    _symbol("C_ab", "stiffness", "N*m/rad",
            "the spring between the first and the middle mass of a chain of three masses, referred to the same shaft"),
    _symbol("C_bc", "stiffness", "N*m/rad",
            "the spring between the middle and the last mass of a chain of three masses, referred to the same shaft"),
    # The drive train's dynamics: the two-mass model, resonance and anti-resonance, the best ratio.
    _symbol("f_r", "frequency", "Hz", "resonance of the two-mass model: the rotor against everything it drives"),
    _symbol("f_ar", "frequency", "Hz", "anti-resonance of the two-mass model: the load swinging with the motor held"),
    _symbol("q_r", "dimensionless", "", "resonance ratio f_r / f_ar of the two-mass model"),
    _symbol("C_s", "stiffness", "N*m/rad", "the drive train's springs in series, referred to the motor shaft"),
    _symbol("J_Lm", "inertia", "kg*cm**2",
            "everything the motor drives (coupling, gearbox J_1, load), referred to the motor shaft"),
    _symbol("i_opt", "dimensionless", "", "inertia-matching ratio of an inertial load"),
    # The inertia of a body (rigid-body mechanics).
    _symbol("rho", "density", "kg/m**3", "density of the material"),
    _symbol("m", "mass", "kg", "mass (of a body, of the load a mechanism moves)"),
    _symbol("m_cylinder", "mass", "kg", "mass of a solid cylinder", "m"),
    _symbol("m_hollow", "mass", "kg", "mass of a hollow cylinder", "m"),
    _symbol("m_plate", "mass", "kg", "mass of a rectangular plate", "m"),
    _symbol("D", "length", "mm", "outer diameter"),
    _symbol("d_i", "length", "mm", "inner diameter (a hollow cylinder)", "d"),
    _symbol("L", "length", "mm", "length along the axis (a plate's thickness)"),
    _symbol("a", "length", "mm", "side of the plate across the axis"),
    _symbol("b", "length", "mm", "other side of the plate across the axis"),
    _symbol("e", "length", "mm", "distance of the body's own axis from the axis of rotation"),
    _symbol("J_own", "inertia", "kg*cm**2", "inertia of the body about its own axis"),
    _symbol("J_cylinder", "inertia", "kg*cm**2", "inertia of a solid cylinder about its axis", "J_own"),
    _symbol("J_hollow", "inertia", "kg*cm**2", "inertia of a hollow cylinder about its axis", "J_own"),
    _symbol("J_plate", "inertia", "kg*cm**2",
            "inertia of a plate about the axis through its centre, across it", "J_own"),
    _symbol("J_body", "inertia", "kg*cm**2", "inertia of the body about the axis of rotation", "J"),
    # The mechanism and the motion (a reading: spec, Motion and mechanism).
    _symbol("p", "length", "mm", "lead of the screw: travel per revolution"),
    _symbol("d", "length", "mm", "pitch diameter of the pinion or diameter of the pulley"),
    _symbol("r_lead", "length", "mm", "transmission radius: the load's travel per radian of the output", "r"),
    _symbol("r_diameter", "length", "mm", "transmission radius: the load's travel per radian of the output", "r"),
    _symbol("a_load", "linear_acceleration", "m/s**2", "acceleration of the load", "a"),
    _symbol("F", "force", "N", "force on the load along its travel"),
    _symbol("m_c", "mass", "kg", "counterweight, moving the other way"),
    _symbol("theta", "angle", "deg", "incline of the axis (90°: vertical, up is forwards)"),
    _symbol("s_v", "dimensionless", "", "direction of motion: +1 forwards, −1 back, 0 at rest"),
    _symbol("mu", "dimensionless", "", "friction coefficient of the guide"),
    _symbol("F_p", "force", "N", "process force, against the motion while it moves"),
    _symbol("d_P", "dimensionless", "",
            "direction of power: +1 while the drive drives, −1 while the load drives back or is held"),
    _symbol("eta_reverse", "dimensionless", "",
            "reverse efficiency of the mechanism, driven back by the load (a screw's below η; ≤ 0: self-locking)",
            latex=r"\eta'"),
    _symbol("J_M", "inertia", "kg*cm**2", "own inertia of the screw, pinion or pulley"),
    _symbol("T_d", "torque", "N*m",
            "drag torque at the screw, pinion or pulley shaft, against the motion while it moves"),
    _symbol("T_f", "torque", "N*m", "friction torque of the table, against the motion while it moves"),
    _symbol("T_p", "torque", "N*m", "process torque, against the motion while it moves"),
    _symbol("T_2_linear", "torque", "N*m", "output torque of a linear mechanism", "T_2"),
    _symbol("T_2_rotary", "torque", "N*m", "output torque of a rotary table", "T_2"),
    _symbol("J_L_linear", "inertia", "kg*cm**2", "inertia of the load at the gearbox output", "J_L"),
    _symbol("m_equivalent", "mass", "kg", "moved mass of a linear axis with the table's inertia at the output", "m"),
    _symbol("J_L_equivalent", "inertia", "kg*cm**2",
            "inertia of a table that needs the axis' torque to accelerate", "J_L"),
    _symbol("T_d_equivalent", "torque", "N*m",
            "drag torque at the screw, pinion or pulley shaft, against the motion while it moves", "T_d"),
    _symbol("T_f_equivalent", "torque", "N*m",
            "friction torque of the table, against the motion while it moves", "T_f"),
    _symbol("T_p_equivalent", "torque", "N*m", "process torque, against the motion while it moves", "T_p"),
    _symbol("omega_2max", "speed", "rpm", "peak output speed of the move"),
    _symbol("alpha_2max", "angular_acceleration", "rad/s**2", "peak output acceleration of a speed ramp"),
    _symbol("t_m", "time", "s", "time of the move"),
    _symbol("t_a", "time", "s", "acceleration time"),
    _symbol("t_d", "time", "s", "deceleration time"),
    _symbol("t_r", "time", "s", "time of a speed ramp (acceleration or deceleration time)"),
    _symbol("t_j", "time", "s", "jerk time: the ramp of constant jerk at each end of a speed ramp"),
), "symbol")


def symbol(name: str) -> Symbol:
    """The symbol declared by ``name``.

    Parameters
    ----------
    name : str
        A name of :data:`SYMBOLS`.

    Returns
    -------
    Symbol
        Its declaration.
    """
    try:
        return SYMBOLS[name]
    except KeyError:
        raise ValueError(f"calc.core.glossary: no symbol {name!r} is declared") from None


def math(name: str) -> str:
    r"""A symbol by its name as inline math, for a label or a table's cell: ``$T_{\mathrm{2N}}$``.

    Parameters
    ----------
    name : str
        A symbol as code or prose writes it.

    Returns
    -------
    str
        Its LaTeX (:func:`latex`) between dollars.
    """
    return f"${latex(name)}$"


def latex(name: str) -> str:
    r"""A symbol's LaTeX by its name: the declared symbol's, else its name typeset by :func:`typeset`.

    Parameters
    ----------
    name : str
        A symbol as code or prose writes it (``T_1B``, ``T_2N``, ``d_hub,max``).

    Returns
    -------
    str
        LaTeX math, without the dollars.

    >>> print(latex("T_2max"), latex("T_1rms"), latex("T_2N"), latex("J_L_linear"))
    T_{\mathrm{2max}} T_{\mathrm{1rms}} T_{\mathrm{2N}} J_{\mathrm{L}}
    """
    declared = SYMBOLS.get(name)
    return declared.latex if declared is not None else typeset(name)
