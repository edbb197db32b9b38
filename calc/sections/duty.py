"""The load cycle of a case (``[[profile]]``, or derived from its motion): its duty (E3), its S1
means (E1, E2) and its S5 values (E4, E5, with the T_2max of the best-ranked gearbox), which
every other section builds on."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

from ..data.bands import BandTable
from .case import Case, Declared, Key, Table
from ..domain.cycle import SampledCycle
from ..core.errors import CalcError
from ..domain.gearbox import SHOCK_FACTORS, shock_factor
from ..domain.profile import ED, Duty, Profile, T_2m, Z_h, duty, n_2m
from ..core.units import Value
from .common import Verdict
from .protocol import Result, Section

NAME = "profile"
ORDER = 30
TABLES = (Declared(NAME, (
    Key("phase", "choice", "accel | const | decel | pause"),
    Key("duration", "time", "duration of the segment", "t_k", unit="s"),
    Key("speed", "speed", "mean output speed during the segment (a pause needs none)", "n_2k", unit="rpm"),
    Key("torque", "torque", "output torque during the segment; the sign may be negative (a pause needs none)", "T_2k",
        unit="N*m"),
), "the load cycle at the gearbox output, one table per segment in time order (or [[move]] or [drive_record] instead)",
    array=True),)


def read(top: Table) -> Profile:
    """The ``[[profile]]`` segments of a case, checked.

    Parameters
    ----------
    top : calc.sections.case.Table
        The case file's top-level table.

    Returns
    -------
    calc.domain.profile.Profile
        The load cycle at the gearbox output.

    Raises
    ------
    CalcError
        Where there is no segment or one is wrong, naming the segment and key.
    """
    if not top.has("profile"):
        raise CalcError(f"{top.path}: profile: expected one [[profile]] table per segment, found none")
    segments = [
        (
            seg.text("phase", required=True),
            seg.quantity("duration", required=True),
            seg.quantity("speed"),
            seg.quantity("torque"),
        )
        for seg in top.tables(NAME, TABLES[0].keys)
    ]
    return Profile.from_segments(segments, where=f"{top.path}: profile")


@dataclass(frozen=True)
class DutyValues:
    """The load cycle's values as the outputs print them (:attr:`DutyResult.shown`).

    Parameters
    ----------
    t_on : calc.core.units.Value
        The time in motion [s].
    t_cycle : calc.core.units.Value
        The cycle time [s].
    ED : calc.core.units.Value
        The duty (E3) [percent].
    mode : str
        The operating mode the duty gives, ``S1`` or ``S5``.
    n_2m : calc.core.units.Value
        The mean output speed (E1) [rpm].
    T_2m : calc.core.units.Value
        The cubic mean output torque (E2) [N*m].
    Z_h : calc.core.units.Value
        The cycles per hour [1/hour].
    f_s : float
        The shock factor [1].
    f_s_table : str
        Where the table of f_s comes from.
    n_2max : calc.core.units.Value
        The highest output speed [rpm].
    T_2max : calc.core.units.Value or None
        T_2max of the best-ranked gearbox [N*m], where the case has one.
    T_2max_part : str or None
        That gearbox.
    T_2max_eta : float or None
        That gearbox's efficiency η [1], which T_2max = T_1B · i · f_s · η credits; None where not known.
    """

    t_on: Value
    t_cycle: Value
    ED: Value
    mode: str
    n_2m: Value
    T_2m: Value
    Z_h: Value
    f_s: float
    f_s_table: str
    n_2max: Value
    T_2max: Value | None
    T_2max_part: str | None
    T_2max_eta: float | None = None


@dataclass
class DutyResult(Result):
    """The duty, the S1 means and the S5 values of the load cycle.

    Parameters
    ----------
    profile : calc.domain.profile.Profile
        The load cycle.
    duty : calc.domain.profile.Duty
        Its duty (E3).
    n2m : pint.Quantity [rpm]
        The mean output speed (E1).
    T2m : pint.Quantity [N*m]
        The cubic mean output torque (E2).
    Zh : pint.Quantity [1/hour]
        The cycles per hour.
    fs : float
        The shock factor f_s [1].
    T2max : pint.Quantity [N*m], optional
        T_2max of the best-ranked gearbox, when the case has one and the motor's peak torque.
    T2max_part : str, optional
        That gearbox.
    T2max_eta : float, optional
        Its efficiency η [1], as T_2max took it.
    cycle : calc.domain.cycle.SampledCycle, optional
        The sampled cycle where the motion form derived it.
    shock_factors : calc.data.bands.BandTable, optional
        The table f_s is read from (``[gearbox] shock_factors``).
    steps : list, optional
        (title, :class:`calc.core.formula.Step`) of ED, n_2m, T_2m and Z_h, as computed here.
    """

    #: The JSON contract writes its objects (duty, continuous, cyclic) at the top level.
    AT_TOP = True

    profile: Profile
    duty: Duty
    n2m: object
    T2m: object
    Zh: object
    fs: float
    T2max: object = None
    T2max_part: str | None = None
    T2max_eta: float | None = None
    cycle: SampledCycle | None = None
    shock_factors: BandTable = SHOCK_FACTORS
    steps: list = field(default_factory=list)

    @property
    def fs_table(self) -> str:
        """Where the table of f_s comes from."""
        return self.shock_factors.source

    @cached_property
    def shown(self) -> "DutyValues":
        """The values every output prints, in the units they are shown in."""
        d = self.duty
        return DutyValues(
            t_on=Value.of(d.t_on, "s", "duty.t_on"), t_cycle=Value.of(d.t_cycle, "s", "duty.t_cycle"),
            ED=Value.of(d.ED, "percent", "duty.ED"), mode=d.mode,
            n_2m=Value.of(self.n2m, "rpm", "continuous.n2m"), T_2m=Value.of(self.T2m, "N*m", "continuous.T2m"),
            Z_h=Value.of(self.Zh, "1/hour", "cyclic.Zh"), f_s=self.fs, f_s_table=self.fs_table,
            n_2max=Value.of(self.profile.n_2max, "rpm", "cyclic.n2max"),
            T_2max=None if self.T2max is None else Value.of(self.T2max, "N*m", "cyclic.T2max"),
            T_2max_part=self.T2max_part, T_2max_eta=self.T2max_eta,
        )

    def to_json(self, candidates: int | None = None) -> dict:
        v = self.shown
        out = {
            "duty": {"t_on": v.t_on.to_json(), "t_cycle": v.t_cycle.to_json(), "ED": v.ED.to_json(), "mode": v.mode},
            "continuous": {"n2m": v.n_2m.to_json(), "T2m": v.T_2m.to_json(), "governs": v.mode == "S1"},
            "cyclic": {"Zh": v.Z_h.to_json(), "fs": v.f_s, "fs_table": v.f_s_table, "n2max": v.n_2max.to_json(),
                       "governs": v.mode == "S5"},
        }
        if v.T_2max is not None:
            out["cyclic"]["T2max"] = v.T_2max.to_json()
            out["cyclic"]["T2max_part"] = v.T_2max_part
        return out

    def summary_lines(self, candidates: int | None = None) -> list[str]:
        v = self.shown
        return [
            f"Duty cycle: t_on = {v.t_on}, t_cycle = {v.t_cycle}, ED = {v.ED} -> mode {v.mode} (E3)",
            f"S1{' (governs)' if v.mode == 'S1' else ''}: n_2m = {v.n_2m}, T_2m = {v.T_2m}",
            f"S5{' (governs)' if v.mode == 'S5' else ''}: Z_h = {v.Z_h}, f_s = {v.f_s:g}, n_2max = {v.n_2max}"
            + (f", T_2max = {v.T_2max} ({v.T_2max_part})" if v.T_2max is not None else ""),
        ]

    def verdict(self) -> Verdict | None:
        """The load cycle has no checks of its own.

        Returns
        -------
        None
        """
        return None


class DutySection(Section):
    """The load cycle's duty, S1 means and S5 values; the T_2max of the best-ranked gearbox where
    the case has a gearbox."""

    NAME = NAME
    TABLES = TABLES
    REQUIRES = ("gearbox",)

    def read(self, top: Table, case: Case) -> None:
        """The typed segments, where the motion does not derive the load cycle.

        Parameters
        ----------
        top : calc.sections.case.Table
            The case file's top-level table.
        case : calc.sections.case.Case
            The case being read; its profile is written.

        Returns
        -------
        None
        """
        if case.motion is None:
            case.profile = read(top)

    def applies(self, case: Case) -> bool:
        return True

    def evaluate(self, case: Case, earlier) -> DutyResult:
        return duty_result(case, earlier.get("gearbox"))


SECTION = DutySection()


def duty_result(case: Case, gearbox) -> DutyResult:
    """The duty of the case's load cycle, with the sampled cycle where the motion form gives it
    and the T_2max of the gearbox's best-ranked row.

    Parameters
    ----------
    case : calc.sections.case.Case
        The case as read.
    gearbox : calc.sections.gearbox.GearboxResult or None
        The gearbox section's result; None where the case has no gearbox.

    Returns
    -------
    DutyResult
        Its duty, S1 means and S5 values, with the steps that compute them.
    """
    p = case.profile
    seg = p.moving_values()
    steps = [("Duty cycle", ED.step(t_on=p.t_on, t_cycle=p.t_cycle)),
             ("Mean output speed", n_2m.step(n_2k=seg["n_2k"], t_k=seg["t_k"])),
             ("Cubic mean output torque", T_2m.step(**seg)),
             ("Load cycles per hour", Z_h.step(**p.cycles_per_hour_inputs()))]
    _, n2m, t2m, zh = (step.result for _, step in steps)
    table = SHOCK_FACTORS if case.shock_factors is None else case.shock_factors
    out = DutyResult(p, duty(p), n2m, t2m, zh, float(shock_factor(zh, table)),
                     cycle=None if case.motion is None else case.motion.cycle, shock_factors=table, steps=steps)
    if gearbox is not None:
        selection = gearbox.selection
        if selection.T_2max is not None:
            row = selection.order[0]
            out.T2max, out.T2max_part = selection.T_2max[row], str(selection.catalog.parts[row])
            eta = float(selection.catalog["eta"][row].m_as(""))
            out.T2max_eta = None if math.isnan(eta) else eta  # NaN: the catalog gives none
    return out
