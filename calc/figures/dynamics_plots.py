"""Figures of the drive train's dynamics: the frequency response of the motor's speed to its torque
with the resonances, the anti-resonances and the speed loop's bandwidth marked.

Built without pyplot (no global figure state), matplotlib imported inside; drawn from the response
and the frequencies the dynamics computed, never computing them again.
"""

from __future__ import annotations

import numpy as np

from ..core.units import sig

RESONANCE_COLOR = "#b2222a"
ANTI_RESONANCE_COLOR = "#1f5fa8"
LOOP_COLOR = "#5a9e3a"


def frequency_response_figure(response, natural_frequencies, anti_resonances, f_er=None):
    """The magnitude of ``ω_motor / T_motor`` in dB over a logarithmic frequency axis, the
    resonances (red, solid), anti-resonances (blue, dashed), ``f_er`` and ``2 f_er`` (green) marked.

    Parameters
    ----------
    response : calc.domain.dynamics.FrequencyResponse
        The response as computed.
    natural_frequencies, anti_resonances : pint.Quantity [Hz]
        The chain's, lowest first.
    f_er : pint.Quantity [Hz], optional
        The speed loop's bandwidth; None where the case gives none.

    Returns
    -------
    matplotlib.figure.Figure
        One axes.

    Examples
    --------
    >>> from calc import Q_
    >>> from calc.domain.dynamics import frequency_response, modes
    >>> J, C = Q_([2, 8], "kg*cm**2"), Q_([1000], "N*m/rad")
    >>> m = modes(J, C)
    >>> fig = frequency_response_figure(frequency_response(J, C, Q_([10, 100, 1000], "Hz")),
    ...                                 m.natural_frequencies, m.anti_resonances, Q_(50, "Hz"))
    >>> len(fig.axes[0].lines)  # the response, one resonance, one anti-resonance, f_er and 2 f_er
    5
    """
    from matplotlib.figure import Figure

    f = response.frequency.m_as("Hz")
    db = 20 * np.log10(response.magnitude)
    fig = Figure(figsize=(8.0, 3.6), layout="constrained")
    ax = fig.add_subplot()
    ax.semilogx(f, db, color="black", lw=1.2, label="|ω_motor / T_motor|")
    for k, x in enumerate(natural_frequencies.m_as("Hz")):
        ax.axvline(x, color=RESONANCE_COLOR, lw=1, label="resonances" if k == 0 else None)
        ax.annotate(f"{sig(x, 4)} Hz", (x, 1.0), xycoords=("data", "axes fraction"), rotation=90, va="top",
                    ha="right", fontsize=7, color=RESONANCE_COLOR)
    for k, x in enumerate(anti_resonances.m_as("Hz")):
        ax.axvline(x, color=ANTI_RESONANCE_COLOR, lw=1, ls="--",
                   label="anti-resonances (motor held)" if k == 0 else None)
        ax.annotate(f"{sig(x, 4)} Hz", (x, 0.0), xycoords=("data", "axes fraction"), rotation=90, va="bottom",
                    ha="right", fontsize=7, color=ANTI_RESONANCE_COLOR)
    if f_er is not None:
        x = f_er.m_as("Hz")
        ax.axvline(x, color=LOOP_COLOR, lw=1.5, ls=":", label=f"f_er = {sig(x, 4)} Hz")
        ax.axvline(2 * x, color=LOOP_COLOR, lw=1, ls="-.", label=f"2 f_er = {sig(2 * x, 4)} Hz")
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("|ω / T| [dB re 1 rad/(s·N·m)]")
    ax.set_xlim(f.min(), f.max())
    ax.grid(True, which="both", lw=0.3, alpha=0.5)
    ax.legend(fontsize=7, loc="upper right")
    ax.set_title(f"Motor speed over motor torque (damping ratio {response.damping:g} at the first mode, for the "
                 "figure only)", fontsize=9)
    return fig
