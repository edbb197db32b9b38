"""The load cycle of a case (``[[profile]]``, or derived from its motion): its duty (E3), its S1
means (E1, E2) and its S5 values (E4, E5, with the T_2max of the best-ranked gearbox), which
every other section builds on."""

from __future__ import annotations

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
    Key("torque", "torque", "output torque during the segment; the sign may be negative (a pause needs none)", "T_2k", unit="N*m"),
), "the load cycle at the gearbox output, one table per segment in time order (or [[move]] or [drive_record] instead)", array=True),)


def read(top: Table) -> Profile:
    """The ``[[profile]]`` segments of a case, checked; errors name the segment and key."""
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
    """The load cycle's values as the outputs print them (:attr:`DutyResult.shown`)."""

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
    T_2max: Value | None  # of the best-ranked gearbox, where the case has one
    T_2max_part: str | None


@dataclass
class DutyResult(Result):
    """The duty, the S1 means and the S5 values of the load cycle."""

    #: The JSON contract writes its objects (duty, continuous, cyclic) at the top level.
    AT_TOP = True

    profile: Profile
    duty: Duty
    n2m: object
    T2m: object
    Zh: object
    fs: float
    T2max: object = None  # of the best-ranked gearbox, when the case has one and the motor's peak torque
    T2max_part: str | None = None
    cycle: SampledCycle | None = None  # the sampled cycle where the motion form derived it
    shock_factors: BandTable = SHOCK_FACTORS  # the table f_s is read from ([gearbox] shock_factors)
    #: (title, calc.core.formula.Step) of ED, n_2m, T_2m and Z_h, as computed here
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
            T_2max=None if self.T2max is None else Value.of(self.T2max, "N*m", "cyclic.T2max"), T_2max_part=self.T2max_part,
        )

    def to_json(self, candidates: int | None = None) -> dict:
        v = self.shown
        out = {
            "duty": {"t_on": v.t_on.to_json(), "t_cycle": v.t_cycle.to_json(), "ED": v.ED.to_json(), "mode": v.mode},
            "continuous": {"n2m": v.n_2m.to_json(), "T2m": v.T_2m.to_json(), "governs": v.mode == "S1"},
            "cyclic": {"Zh": v.Z_h.to_json(), "fs": v.f_s, "fs_table": v.f_s_table, "n2max": v.n_2max.to_json(), "governs": v.mode == "S5"},
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
        """The load cycle has no checks of its own."""
        return None


class DutySection(Section):
    """The load cycle's duty, S1 means and S5 values; the T_2max of the best-ranked gearbox where
    the case has a gearbox."""

    NAME = NAME
    TABLES = TABLES
    REQUIRES = ("gearbox",)

    def read(self, top: Table, case: Case) -> None:
        """The typed segments, where the motion does not derive the load cycle."""
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
    """
    p = case.profile
    seg = p.moving_values()
    steps = [("Duty cycle", ED.step(t_on=p.t_on, t_cycle=p.t_cycle)), ("Mean output speed", n_2m.step(n_2k=seg["n_2k"], t_k=seg["t_k"])),
             ("Cubic mean output torque", T_2m.step(**seg)), ("Cycles per hour", Z_h.step(t_cycle=p.t_cycle))]
    _, n2m, t2m, zh = (step.result for _, step in steps)
    table = SHOCK_FACTORS if case.shock_factors is None else case.shock_factors
    out = DutyResult(p, duty(p), n2m, t2m, zh, float(shock_factor(zh, table)),
                     cycle=None if case.motion is None else case.motion.cycle, shock_factors=table, steps=steps)
    if gearbox is not None:
        selection = gearbox.selection
        if selection.T_2max is not None:
            row = selection.order[0]
            out.T2max, out.T2max_part = selection.T_2max[row], str(selection.catalog.parts[row])
    return out
