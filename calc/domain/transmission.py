"""Angular transmission accuracy: the transmission error over one output revolution, and its range.

Source: "Angular Transmission Accuracy". The gearbox turns without load; input and output
positions are recorded, several times in each direction. The transmission error is the actual
output position minus the theoretical one, ``φ_1 / i`` (:data:`transmission_error`); the
angular transmission accuracy is its range, maximum minus minimum, over a full revolution of the
output (:data:`transmission_accuracy`). A record is a CSV file with columns ``input [unit]`` and
``output [unit]`` (angles, errata E15); each direction of travel is judged on its own (reversing
takes up the backlash, which is not a transmission error) and the larger range is the accuracy.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..data.catalog import Column
from ..core.citation import Source, Validity
from ..core.errors import CalcError, listing
from ..core.formula import Formula
from ..core.glossary import symbol
from ..data.measurement import check_pair, read_measurement, travel_direction, write_measurement
from .stiffness import angle_at_output
from ..core.units import Q_, as_kind, fmt  # noqa: F401 (fmt: the doctests print with it)
from .documents import SOURCE

COLUMNS = (
    Column("input", "angle", "position of the input shaft"),
    Column("output", "angle", "position of the output shaft"),
)

#: The fewest samples a record needs in a direction of travel.
MIN_SAMPLES = 20
#: The share of an output revolution a direction must cover: the samples at a reversal may fall
#: to either direction.
FULL_TURN = 0.99

transmission_error = Formula(
    "Delta_phi_2",
    ("phi_2", symbol("phi_1").shown_in("deg"), "i"),
    lambda sp, phi_2, phi_1, i: phi_2 - phi_1 / i,
    Source(SOURCE.at("Angular Transmission Accuracy",
                     says="actual output position relative to the theoretical output position according to the ratio")),
)

transmission_accuracy = Formula(
    symbol("phi_TA").shown_in("arcsec"),
    ("Delta_phi_max", "Delta_phi_min"),
    lambda sp, hi, lo: hi - lo,
    Source(SOURCE.at("Angular Transmission Accuracy", says="maximum position variation - minimum position variation",
                     validity=Validity("over a full output revolution", stands="tail"))),
)


@dataclass(frozen=True)
class Trace:
    """Input and output positions in the order recorded (quantity arrays), and their source.

    Parameters
    ----------
    input : pint.Quantity [deg]
        Input positions.
    output : pint.Quantity [deg]
        Output positions.
    source : str
        Where it came from; default ``"trace"``.
    comments : tuple of str
        The file's comment lines.
    """

    input: object
    output: object
    source: str = "trace"
    comments: tuple = ()

    def __post_init__(self):
        check_pair(self.source, ("input", self.input, "angle"), ("output", self.output, "angle"))


def read_trace(path) -> Trace:
    """Read a recorded trace: a CSV file with columns ``input [unit]`` and ``output [unit]``.

    Parameters
    ----------
    path : pathlib.Path or str
        The file.

    Returns
    -------
    Trace
        Its positions in the order recorded.
    """
    m = read_measurement(path, COLUMNS)
    return Trace(m["input"], m["output"], source=str(path), comments=m.comments)


def write_trace(path, trace: Trace, comments: tuple[str, ...]) -> None:
    """Write a trace as a measurement file (positions in degrees, to 10 significant figures).

    Parameters
    ----------
    path : pathlib.Path or str
        The file to write.
    trace : Trace
        The trace.
    comments : tuple of str
        The file's comment lines.

    Returns
    -------
    None
    """
    write_measurement(path, {"input": trace.input, "output": trace.output}, {"input": "deg", "output": "deg"}, comments,
                      digits=10)


def generate_trace(ratio, amplitude, samples: int = 1000, noise=None, seed: int = 0, teeth: int = 31) -> Trace:
    """A trace over one output revolution forward and one back, with a typical error pattern.

    The error is a once-per-revolution term (eccentricity of the output), a twice-per-revolution
    term (out-of-roundness) and a tooth-mesh ripple ``teeth · i`` times per revolution, with
    random phases; its peak amplitudes are 1/2, 1/4 and 1/8 of ``amplitude``.

    Returns
    -------
    Trace
        The input and output positions.

    Parameters
    ----------
    ratio : pint.Quantity [1]
        ``i``, input turns per output turn.
    amplitude : pint.Quantity [arcmin]
        Scale of the error (the range comes out somewhat below ``2 × amplitude``).
    samples : int
        Samples per direction.
    noise : pint.Quantity [arcmin], optional
        Standard deviation of normal noise on the output position.
    seed : int
        Seed of the random phases and noise.
    teeth : int
        Teeth of the mesh whose ripple the error carries (per input turn).
    """
    i = as_kind(ratio, "dimensionless", "ratio").m_as("")
    a = as_kind(amplitude, "angle", "amplitude").m_as("rad")
    rng = np.random.default_rng(seed)
    phases = rng.uniform(0, 2 * np.pi, 3)
    theta = np.linspace(0.0, 2 * np.pi, samples)
    theta = np.concatenate((theta, theta[::-1]))
    error = a * (
        0.5 * np.sin(theta + phases[0]) + 0.25 * np.sin(2 * theta + phases[1])
        + 0.125 * np.sin(teeth * i * theta + phases[2])
    )
    if noise is not None:
        error = error + rng.normal(0.0, as_kind(noise, "angle", "noise").m_as("rad"), len(theta))
    return Trace(Q_(theta * i, "rad").to("deg"), Q_(theta + error, "rad").to("deg"), source="generated trace")


@dataclass(frozen=True)
class TransmissionAnalysis:
    """The transmission error of a trace and its range per direction of travel.

    Parameters
    ----------
    output : pint.Quantity [deg]
        Output position per sample.
    error : pint.Quantity [arcsec]
        Transmission error per sample, its mean over the record taken out.
    direction : numpy.ndarray of int
        +1 forward, -1 backward, per sample.
    ranges : dict
        Direction name to ``(min, max)`` quantity array [arcsec].
    accuracy : pint.Quantity [arcsec]
        The larger range.
    governing : str
        The direction of the larger range.
    source : str
        Where the trace came from.
    """

    output: object  # quantity array, output position [deg]
    error: object  # quantity array, transmission error [arcsec], its mean over the record taken out
    direction: np.ndarray  # +1 forward, -1 backward, per sample
    ranges: dict  # direction name -> (min, max) quantity array [arcsec]
    accuracy: object  # the larger range [arcsec]
    governing: str  # the direction of the larger range
    source: str

    def step(self):
        """The accuracy formula with this trace's numbers.

        Returns
        -------
        Step
            The evaluated formula.
        """
        lo, hi = self.ranges[self.governing]
        return transmission_accuracy.step(Delta_phi_max=hi, Delta_phi_min=lo)


def analyze_trace(trace: Trace, ratio) -> TransmissionAnalysis:
    """Transmission error and angular transmission accuracy of a recorded trace.

    Parameters
    ----------
    trace : Trace
        Input and output positions, one or more output revolutions in one or both directions.
    ratio : pint.Quantity [1]
        ``i`` of the gearbox.

    Returns
    -------
    TransmissionAnalysis
        ``accuracy`` [arcsec]: the largest range of the error over the directions that cover a
        full output revolution.

    Notes
    -----
    The error's constant part (where the encoders were zeroed) is taken out; it does not change a
    range. The range is the literal maximum minus minimum, as the source defines it, so noise of
    the position encoders counts into it. A direction counts when its theoretical output
    position ``φ_1 / i`` spans at least 99 % of a revolution (the samples at a reversal may fall
    to either direction). Raises :class:`CalcError` for too few samples or for a record in which
    no direction covers a full output revolution.

    Examples
    --------
    >>> t = generate_trace(Q_(10, ""), Q_(40, "arcsec"), seed=3)
    >>> print(fmt(analyze_trace(t, Q_(10, "")).accuracy, "arcsec", 3))
    61.4 arcsec
    """
    where = trace.source
    i = as_kind(ratio, "dimensionless", f"{where}: ratio")
    if not i.m_as("") > 0:
        raise CalcError(f"{where}: ratio: expected a ratio above zero, found {i.m_as(''):g}")
    n = len(trace.input.magnitude)
    if n < MIN_SAMPLES:
        raise CalcError(f"{where}: expected a trace of at least {MIN_SAMPLES} samples, found {n}")
    error = transmission_error(phi_2=trace.output, phi_1=trace.input, i=i).m_as("arcsec")
    error = error - error.mean()
    output = trace.output.m_as("deg")
    theoretical = angle_at_output(phi_1=trace.input, i=i).m_as("deg")
    direction = travel_direction(theoretical)
    ranges, covered = {}, {}
    for sign, name in ((1, "forward"), (-1, "backward")):
        mask = direction == sign
        if mask.sum() < MIN_SAMPLES:
            continue
        covered[name] = float(np.ptp(theoretical[mask]))
        if covered[name] >= 360.0 * FULL_TURN:
            ranges[name] = Q_(np.array([error[mask].min(), error[mask].max()]), "arcsec")
    if not ranges:
        found = listing(f"{k} {v:.4g}°" for k, v in covered.items()) or "no direction with enough samples"
        raise CalcError(f"{where}: expected a full revolution of the output (360°) in at least one direction, found "
                        f"{found}")
    spans = {k: transmission_accuracy(Delta_phi_max=v[1], Delta_phi_min=v[0]) for k, v in ranges.items()}
    governing = max(spans, key=lambda k: spans[k].m_as("arcsec"))
    return TransmissionAnalysis(
        output=Q_(output, "deg"),
        error=Q_(error, "arcsec"),
        direction=direction,
        ranges=ranges,
        accuracy=spans[governing],
        governing=governing,
        source=where,
    )
