"""The load cycle of a case (``[[profile]]``): its duty (E3), its S1 means (E1, E2) and its S5
values (E4, E5), which every other section builds on."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..bands import BandTable
from ..case import Case, Declared, Key, Table, once
from ..cycle import SampledCycle
from ..errors import CalcError
from ..gearbox import SHOCK_FACTORS, shock_factor
from ..profile import ED, Duty, Profile, T_2m, Z_h, duty, n_2m
from . import gearbox
from .common import Verdict, quantity, quantity_text

NAME = "profile"
ORDER = 30  # after the motion, which may derive the load cycle
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


@dataclass
class DutyResult:
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
    #: (title, calc.formula.Step) of ED, n_2m, T_2m and Z_h, as computed here
    steps: list = field(default_factory=list)

    @property
    def fs_table(self) -> str:
        """Where the table of f_s comes from."""
        return self.shock_factors.source

    def to_json(self, candidates: int | None = None) -> dict:
        d = self.duty
        out = {
            "duty": {
                "t_on": quantity(d.t_on, "s", "duty.t_on"),
                "t_cycle": quantity(d.t_cycle, "s", "duty.t_cycle"),
                "ED": quantity(d.ED, "percent", "duty.ED"),
                "mode": d.mode,
            },
            "continuous": {
                "n2m": quantity(self.n2m, "rpm", "continuous.n2m"),
                "T2m": quantity(self.T2m, "N*m", "continuous.T2m"),
                "governs": d.mode == "S1",
            },
            "cyclic": {
                "Zh": quantity(self.Zh, "1/hour", "cyclic.Zh"),
                "fs": self.fs,
                "fs_table": self.fs_table,
                "n2max": quantity(self.profile.n_2max, "rpm", "cyclic.n2max"),
                "governs": d.mode == "S5",
            },
        }
        if self.T2max is not None:
            out["cyclic"]["T2max"] = quantity(self.T2max, "N*m", "cyclic.T2max")
            out["cyclic"]["T2max_part"] = self.T2max_part
        return out

    def summary_lines(self, candidates: int | None = None) -> list[str]:
        j = self.to_json()
        d, s1, s5 = j["duty"], j["continuous"], j["cyclic"]
        return [
            f"Duty cycle: t_on = {quantity_text(d['t_on'])}, t_cycle = {quantity_text(d['t_cycle'])}, ED = {quantity_text(d['ED'])} -> mode {d['mode']} (E3)",
            f"S1{' (governs)' if s1['governs'] else ''}: n_2m = {quantity_text(s1['n2m'])}, T_2m = {quantity_text(s1['T2m'])}",
            f"S5{' (governs)' if s5['governs'] else ''}: Z_h = {quantity_text(s5['Zh'])}, f_s = {self.fs:g}, n_2max = {quantity_text(s5['n2max'])}"
            + (f", T_2max = {quantity_text(s5['T2max'])} ({s5['T2max_part']})" if "T2max" in s5 else ""),
        ]

    def verdict(self) -> Verdict | None:
        """The load cycle has no checks of its own."""
        return None


def applies(case: Case) -> bool:
    return True


def evaluate(case: Case) -> DutyResult:
    """The duty of the case's load cycle; computed once per case, so that a section after it (the
    motor's side) reads the same result, with the sampled cycle where the motion form gives it."""
    return once(case, NAME, lambda: _evaluate(case))


def _evaluate(case: Case) -> DutyResult:
    p = case.profile
    seg = p.moving_values()
    steps = [("Duty cycle", ED.step(t_on=p.t_on, t_cycle=p.t_cycle)), ("Mean output speed", n_2m.step(n_2k=seg["n_2k"], t_k=seg["t_k"])),
             ("Cubic mean output torque", T_2m.step(**seg)), ("Cycles per hour", Z_h.step(t_cycle=p.t_cycle))]
    _, n2m, t2m, zh = (step.result for _, step in steps)
    table = SHOCK_FACTORS if case.shock_factors is None else case.shock_factors
    out = DutyResult(p, duty(p), n2m, t2m, zh, float(shock_factor(zh, table)),
                     cycle=None if case.motion is None else case.motion.cycle, shock_factors=table, steps=steps)
    if gearbox.applies(case):
        selection = gearbox.gearbox_selection(case)
        if selection.T_2max is not None:
            row = selection.order[0]
            out.T2max, out.T2max_part = selection.T_2max[row], str(selection.catalog.parts[row])
    return out
