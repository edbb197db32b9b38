"""Lost motion, positioning accuracy and repeatability of a drive train, and the case's ``[accuracy]``.

Source: "Lost Motion" ("How can I use it?"), "Accuracy and Repeatability", read with errata E11
to E15. Everything is referred to the output shaft (E11, :mod:`calc.stiffness`).

* Total lost motion at the applied torque is the backlash plus the twist under that torque,
  ``j_t + |T| / C`` (:data:`lost_motion`, the source's formula, E12). Summed over the components
  of a chain it is the chain's backlash plus ``|T| / C_total``.
* Positioning accuracy by the source's 3 % rule (E13): at a torque up to 3 % of the nominal
  torque the backlash is not taken up, ``φ_TA + j_t`` (:data:`positioning_accuracy_low`);
  above, the twist is what counts, ``φ_TA + |T| / C`` (:data:`positioning_accuracy_high`).
* Repeatability (E13): at ``T = 0`` it is the backlash; under torque it is bounded by the lost
  motion at that torque (:func:`repeatability`).
* A measured positioning record (a target and the actual position, each target approached
  several times) gives the measured accuracy, the largest error, and repeatability, the largest
  spread at one target (:func:`analyze_positions`).

The case's ``[accuracy]`` table (``spec/case-format.md``) is read by :func:`read_accuracy` and
evaluated by :func:`section_results` (the JSON contract) and :func:`summary_lines`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .case import Case, Section, once
from .catalog import Column, display_path, load_catalog, resolve
from .errors import CalcError
from .formula import Formula, Symbol
from .measurement import check_pair, measurement_path, read_measurement
from .stiffness import SIDES, Chain, Component, angle_at_output, series_stiffness, stiffness_at_output
from .units import Q_, as_kind, fmt, sig  # noqa: F401 (fmt: the doctests print with it)

#: E13: "torque <= 3 % nominal torque" selects the backlash form of positioning accuracy.
LOW_TORQUE_SHARE = 0.03

_T = Symbol("T", "T", "torque", "N*m", "applied torque at the output")
_j = Symbol("j_t", "j_{t}", "angle", "arcmin", "torsional backlash at the output")
_C = Symbol("C", "C", "stiffness", "N*m/arcmin", "torsional stiffness at the output")
_TA = Symbol("phi_TA", r"\varphi_{\mathrm{TA}}", "angle", "arcmin", "angular transmission accuracy at the output")

lost_motion = Formula(
    Symbol("phi_LM", r"\varphi_{\mathrm{LM}}", "angle", "arcmin", "total lost motion at the applied torque"),
    (_j, _T, _C),
    lambda sp, j, T, C: j + sp.Abs(T) / C,
    "source, Lost Motion: Total Lost Motion at applied torque = Backlash + Applied Torque / Torsional Stiffness; "
    "errata E12 (the text's formula: the twist under T added to the backlash)",
)

positioning_accuracy_low = Formula(
    Symbol("Delta_phi_P_low", r"\Delta\varphi_{P}", "angle", "arcmin", "positioning accuracy, torque up to 3 % of nominal"),
    (_TA, _j),
    lambda sp, ta, j: ta + j,
    "source, Positioning Accuracy, torque <= 3 % of nominal torque: angular transmission accuracy + backlash; errata E13",
)

positioning_accuracy_high = Formula(
    Symbol("Delta_phi_P_high", r"\Delta\varphi_{P}", "angle", "arcmin", "positioning accuracy, torque above 3 % of nominal"),
    (_TA, _T, _C),
    lambda sp, ta, T, C: ta + sp.Abs(T) / C,
    "source, Positioning Accuracy, torque > 3 % of nominal torque: angular transmission accuracy + applied torque / stiffness; errata E13",
)

positioning_error = Formula(
    Symbol("Delta_phi", r"\Delta\varphi", "angle", "arcmin", "positioning error"),
    (
        Symbol("phi_actual", r"\varphi_{\mathrm{actual}}", "angle", "deg", "actual position"),
        Symbol("phi_target", r"\varphi_{\mathrm{target}}", "angle", "deg", "target position"),
    ),
    lambda sp, actual, target: actual - target,
    "source, Positioning Accuracy: the difference between the target position and the actual position",
)


def low_torque(applied_torque, nominal_torque) -> np.ndarray:
    """Whether ``|T| <= 3 %`` of the nominal torque (E13: the backlash form applies).

    >>> bool(low_torque(Q_(3, "N*m"), Q_(100, "N*m"))), bool(low_torque(Q_(-3.1, "N*m"), Q_(100, "N*m")))
    (True, False)
    """
    t = as_kind(applied_torque, "torque", "applied_torque").m_as("N*m")
    t_n = as_kind(nominal_torque, "torque", "nominal_torque").m_as("N*m")
    return np.abs(t) <= LOW_TORQUE_SHARE * t_n


def positioning_accuracy(applied_torque, nominal_torque, transmission_accuracy, backlash, stiffness):
    """Positioning accuracy by the source's 3 % rule (E13), scalars or arrays.

    .. math::
        \\Delta\\varphi_P = \\varphi_{TA} + j_t \\quad (|T| \\le 0.03\\,T_N), \\qquad
        \\Delta\\varphi_P = \\varphi_{TA} + |T| / C \\quad (|T| > 0.03\\,T_N)

    Parameters
    ----------
    applied_torque, nominal_torque : Quantity [torque]
    transmission_accuracy, backlash : Quantity [angle]
    stiffness : Quantity [torque / angle]

    Returns
    -------
    Quantity [arcmin]

    Notes
    -----
    Implemented as the text writes it (E13): the form jumps at 3 % of the nominal torque.

    Examples
    --------
    1 arcmin of transmission accuracy, 3 arcmin backlash, 23 N·m/arcmin, T_N = 81 N·m:

    >>> args = dict(nominal_torque=Q_(81, "N*m"), transmission_accuracy=Q_(1, "arcmin"),
    ...             backlash=Q_(3, "arcmin"), stiffness=Q_(23, "N*m/arcmin"))
    >>> print(fmt(positioning_accuracy(Q_(2, "N*m"), **args), "arcmin"))   # 2 <= 2.43 N·m: 1 + 3
    4 arcmin
    >>> print(fmt(positioning_accuracy(Q_(46, "N*m"), **args), "arcmin"))  # 1 + 46 / 23
    3 arcmin
    """
    low = low_torque(applied_torque, nominal_torque)
    a = positioning_accuracy_low(phi_TA=transmission_accuracy, j_t=backlash)
    b = positioning_accuracy_high(phi_TA=transmission_accuracy, T=applied_torque, C=stiffness)
    return Q_(np.where(low, a.m_as("arcmin"), b.m_as("arcmin")), "arcmin")


def repeatability(applied_torque, backlash, stiffness):
    """Positioning repeatability (E13): the backlash at ``T = 0``; under torque at most the lost
    motion at that torque, ``j_t + |T| / C`` (which is the backlash at ``T = 0``).

    Returns
    -------
    (Quantity [arcmin], bool array)
        The value and whether it is an upper bound (``T ≠ 0``) rather than the value itself.

    >>> value, bound = repeatability(Q_(0, "N*m"), Q_(3, "arcmin"), Q_(23, "N*m/arcmin"))
    >>> print(fmt(value, "arcmin"), bool(bound))
    3 arcmin False
    """
    value = lost_motion(j_t=backlash, T=applied_torque, C=stiffness)
    return value, np.asarray(as_kind(applied_torque, "torque", "applied_torque").magnitude) != 0


@dataclass(frozen=True)
class ChainAccuracy:
    """Lost motion, positioning accuracy and repeatability of a chain at an applied torque."""

    chain: Chain
    applied_torque: object
    nominal_torque: object  # for the 3 % rule; None only at zero torque
    low_torque: bool
    lost_motion: object
    positioning_accuracy: object
    repeatability: object
    repeatability_is_bound: bool

    def steps(self) -> list:
        """Each formula with the chain's numbers, in the order a reviewer reads them."""
        c = self.chain
        out = []
        for comp, c_out, j_out in zip(c.components, c.stiffness_at_output, c.backlash_at_output):
            if comp.side == "input":
                out.append(stiffness_at_output.step(C_1=comp.stiffness, i=c.ratio))
                out.append(angle_at_output.step(phi_1=comp.backlash, i=c.ratio))
        out.append(series_stiffness.step(C_k=c.stiffness_at_output))
        values = dict(j_t=c.backlash, T=self.applied_torque, C=c.stiffness)
        out.append(lost_motion.step(**values))
        ta = c.transmission_accuracy
        if self.low_torque:
            out.append(positioning_accuracy_low.step(phi_TA=ta, j_t=c.backlash))
        else:
            out.append(positioning_accuracy_high.step(phi_TA=ta, T=self.applied_torque, C=c.stiffness))
        return out


def chain_accuracy(chain: Chain, applied_torque, nominal_torque=None) -> ChainAccuracy:
    """Evaluate a chain at an applied output torque (E11 to E13).

    ``nominal_torque`` sets the 3 % rule; by default the chain's (the lowest nominal torque of
    its components at the output). It may be left out only at zero torque.

    >>> from calc.stiffness import Component
    >>> gearbox = Component("EPL-W-064 10:1", "output", Q_(1.3, "N*m/arcmin"), Q_(3, "arcmin"),
    ...                     Q_(60, "arcsec"), Q_(40, "N*m"))
    >>> coupling = Component("EKM-15", "output", Q_(0.24, "N*m/arcmin"), Q_(0, "arcmin"))
    >>> a = chain_accuracy(Chain((coupling, gearbox)), Q_(20, "N*m"))
    >>> print(fmt(a.lost_motion, "arcmin"), "|", fmt(a.positioning_accuracy, "arcmin"))
    101.7 arcmin | 99.72 arcmin
    """
    t = as_kind(applied_torque, "torque", "applied_torque")
    t_n = chain.nominal_torque if nominal_torque is None else as_kind(nominal_torque, "torque", "nominal_torque")
    if t_n is not None and not t_n.m_as("N*m") > 0:
        raise CalcError(f"nominal_torque: expected a torque above zero, found {t_n:~P}")
    if t_n is None and t.m_as("N*m") != 0:
        raise CalcError(
            "nominal_torque: the 3 % rule of positioning accuracy (E13) needs the nominal torque, found none for the chain or its components"
        )
    low = True if t_n is None else bool(low_torque(t, t_n))
    c, j, ta = chain.stiffness, chain.backlash, chain.transmission_accuracy
    if low:
        accuracy = positioning_accuracy_low(phi_TA=ta, j_t=j)
    else:
        accuracy = positioning_accuracy_high(phi_TA=ta, T=t, C=c)
    rep, bound = repeatability(t, j, c)
    return ChainAccuracy(
        chain=chain,
        applied_torque=t,
        nominal_torque=t_n,
        low_torque=low,
        lost_motion=rep,  # repeatability() is the lost motion at t (bounded by it, E13)
        positioning_accuracy=accuracy,
        repeatability=rep,
        repeatability_is_bound=bool(bound),
    )


# --- measured positioning -------------------------------------------------------------------

POSITION_COLUMNS = (
    Column("target", "angle", "target position"),
    Column("actual", "angle", "actual position reached"),
)


@dataclass(frozen=True)
class PositioningScatter:
    """A measured positioning record: errors per approach, measured accuracy and repeatability."""

    target: object  # quantity array [deg], per approach
    error: object  # quantity array [arcmin], per approach
    accuracy: object  # largest |error| [arcmin]
    repeatability: object  # largest spread (max - min error) at one target [arcmin]
    targets: int
    source: str


def analyze_positions(target, actual, source: str = "positions") -> PositioningScatter:
    """Measured positioning accuracy and repeatability from repeated approaches to targets.

    Accuracy is the largest difference between actual and target position (source, Positioning
    Accuracy); repeatability the largest spread of the actual position over the approaches to one
    target (source, Positioning Repeatability). Every target must be approached at least twice.

    >>> r = analyze_positions(Q_([0, 0, 90, 90], "deg"), Q_([0.01, 0.02, 90.01, 90.03], "deg"))
    >>> print(fmt(r.accuracy, "arcmin"), fmt(r.repeatability, "arcmin"))
    1.8 arcmin 1.2 arcmin
    """
    # Checked before the formula, which would broadcast two lengths into a numpy error.
    check_pair(source, ("target", target, "angle"), ("actual", actual, "angle"))
    err = positioning_error(phi_actual=actual, phi_target=target).m_as("arcmin")
    tgt = target.m_as("deg")
    keys, g, count = np.unique(tgt, return_inverse=True, return_counts=True)
    if (count < 2).any():
        raise CalcError(f"{source}: expected each target approached at least twice, found target {keys[count < 2][0]:g}° once")
    spread = np.full(len(keys), -np.inf)
    low = np.full(len(keys), np.inf)
    np.maximum.at(spread, g, err)
    np.minimum.at(low, g, err)
    return PositioningScatter(
        target=Q_(tgt, "deg"),
        error=Q_(err, "arcmin"),
        accuracy=Q_(float(np.abs(err).max()), "arcmin"),
        repeatability=Q_(float((spread - low).max()), "arcmin"),
        targets=len(keys),
        source=source,
    )


def read_positions(path) -> PositioningScatter:
    """Read and analyse a positioning record: a CSV file with ``target [unit]`` and ``actual [unit]``."""
    m = read_measurement(path, POSITION_COLUMNS)
    return analyze_positions(m["target"], m["actual"], source=str(path))


# --- the case's [accuracy] section ----------------------------------------------------------

SECTION_KEYS = (
    "applied_torque", "nominal_torque", "component", "positions",
    "required_positioning_accuracy", "required_repeatability",
)
COMPONENT_KEYS = (
    "name", "side", "stiffness", "backlash", "transmission_accuracy", "nominal_torque",
    "part", "catalog", "hysteresis", "transmission_trace",
)


@dataclass
class AccuracyCase:
    """The ``[accuracy]`` table of a case, read and checked, with what its measurements gave."""

    chain: Chain
    applied_torque: object
    nominal_torque: object = None  # given in the section; else the chain's
    loops: dict = field(default_factory=dict)  # component name -> (file, LoopAnalysis)
    traces: dict = field(default_factory=dict)  # component name -> (file, TransmissionAnalysis)
    positions: PositioningScatter | None = None
    required: dict = field(default_factory=dict)  # "positioning_accuracy" | "repeatability" -> Quantity

    def evaluate(self) -> ChainAccuracy:
        return chain_accuracy(self.chain, self.applied_torque, self.nominal_torque)


def read_accuracy(case: Case) -> AccuracyCase:
    """Read the case's ``[accuracy]`` table; every error names the file and the key."""
    sec = Section(case.path, "accuracy", case.sections["accuracy"], SECTION_KEYS)
    applied = sec.quantity("applied_torque", "torque", required=True)
    nominal = _positive(sec, "nominal_torque", "torque")
    tables = sec.tables("component", COMPONENT_KEYS)
    if not tables:
        raise CalcError(f"{sec.where('component')}: expected one [[accuracy.component]] table per member of the chain, drive to load, found none")
    ratio = _case_ratio(case)
    out = AccuracyCase(chain=None, applied_torque=applied, nominal_torque=nominal)
    components = [_component(case, t, ratio, out) for t in tables]
    names = [c.name for c in components]
    for k, name in enumerate(names):
        if name in names[:k]:
            raise CalcError(f"{tables[k].where('name')}: the name {name!r} is already used by {tables[names.index(name)].key('name')}")
    input_side = [t for t, c in zip(tables, components) if c.side == "input"]
    if input_side and ratio is None:
        raise CalcError(
            f"{input_side[0].where('side')}: an input-side component is referred to the output through the gearbox ratio (E11), "
            "but the case gives no gearbox.ratio"
        )
    out.chain = Chain(tuple(components), ratio)
    if sec.has("positions"):
        out.positions = read_positions(measurement_path(sec.data["positions"], case.folder, sec.where("positions")))
    for key, kind in (("required_positioning_accuracy", "angle"), ("required_repeatability", "angle")):
        q = _positive(sec, key, kind)
        if q is not None:
            out.required[key.removeprefix("required_")] = q
    return out


def _positive(sec: Section, key: str, kind: str):
    q = sec.quantity(key, kind)
    if q is not None and not q.magnitude > 0:
        raise CalcError(f"{sec.where(key)}: expected {'an' if kind == 'angle' else 'a'} {kind} above zero, found {sec.data[key]!r}")
    return q


def _case_ratio(case: Case):
    """The gearbox ratio the chain is referred through: ``gearbox.ratio``, else the named part's."""
    if case.ratio is not None:
        return case.ratio
    if case.gearbox_part is not None:
        rows, row = _catalog_row(case, case.gearbox_catalog or "gearboxes", case.gearbox_part, f"{case.path}: gearbox")
        return rows["ratio"][row]
    return None


def _catalog_row(case: Case, catalog: str, part: str, where: str):
    from .gearbox import SCHEMA

    rows = load_catalog(resolve(catalog, case.folder, f"{where}.catalog"), SCHEMA)
    return rows, rows.index(part, f"{where}.part")


def _component(case: Case, t: Section, ratio, out: AccuracyCase) -> Component:
    """One ``[[accuracy.component]]``: from its keys, a catalog part, or measurements."""
    part = t.text("part")
    name = t.text("name", required=part is None, default=part)
    side = t.text("side", required=part is None, default="output")
    if side not in SIDES:
        raise CalcError(f"{t.where('side')}: expected input or output, found {side!r}")
    stiffness = _positive(t, "stiffness", "stiffness")
    backlash = t.quantity("backlash", "angle")
    if backlash is not None and not backlash.magnitude >= 0:
        raise CalcError(f"{t.where('backlash')}: expected an angle of zero or more, found {t.data['backlash']!r}")
    accuracy = t.quantity("transmission_accuracy", "angle")
    if accuracy is not None and not accuracy.magnitude >= 0:
        raise CalcError(f"{t.where('transmission_accuracy')}: expected an angle of zero or more, found {t.data['transmission_accuracy']!r}")
    nominal = _positive(t, "nominal_torque", "torque")
    sources = []
    own_ratio = ratio
    if part is not None:
        for key in ("stiffness", "backlash", "nominal_torque"):
            if t.has(key):
                raise CalcError(f"{t.where(key)}: the part {part!r} gives its {key} from the catalog; give either part or {key}")
        if side != "output":
            raise CalcError(f"{t.where('side')}: a gearbox's catalog figures are referred to its output, so the part {part!r} sits on the output side, found {side!r}")
        rows, row = _catalog_row(case, t.text("catalog", default=case.gearbox_catalog or "gearboxes"), part, t.where("").rstrip("."))
        own_ratio = rows["ratio"][row]
        if ratio is not None and not np.isclose(own_ratio.m_as(""), ratio.m_as(""), rtol=1e-6):
            raise CalcError(f"{t.where('part')}: {part} has ratio {own_ratio.m_as(''):g}, but the case's gearbox ratio is {ratio.m_as(''):g}")
        stiffness, backlash, nominal = rows["C_t21"][row], rows["backlash"][row], rows["T_2N"][row]
        for column, q in (("C_t21", stiffness), ("backlash", backlash)):
            if np.isnan(q.magnitude):
                raise CalcError(f"{t.where('part')}: {rows.path}, row {rows.lines[row]} ({part}), column {column}: expected a value, found an empty cell")
        sources.append(f"{display_path(rows.path)} row {rows.lines[row]}")
    elif t.has("catalog"):
        raise CalcError(f"{t.where('catalog')}: a catalog is read only for a part; give part as well")
    if t.has("hysteresis"):
        from .hysteresis import analyze_loop, read_loop

        for key in ("stiffness", "backlash"):
            if t.has(key):
                raise CalcError(f"{t.where(key)}: the measured loop gives the {key}; give either hysteresis or {key}")
        if nominal is None:
            raise CalcError(f"{t.where('nominal_torque')}: a measured loop is analysed at 50 % to 100 % and ±3 % of the nominal torque (E12), found none")
        path = measurement_path(t.data["hysteresis"], case.folder, t.where("hysteresis"))
        analysis = analyze_loop(read_loop(path), nominal)
        stiffness, backlash = analysis.stiffness, analysis.backlash
        out.loops[name] = (display_path(path), analysis)
        sources.append(f"measured loop {display_path(path)}")
    if t.has("transmission_trace"):
        from .transmission import analyze_trace, read_trace

        if accuracy is not None:
            raise CalcError(f"{t.where('transmission_accuracy')}: the trace gives the transmission accuracy; give either transmission_trace or transmission_accuracy")
        if own_ratio is None:
            raise CalcError(f"{t.where('transmission_trace')}: the transmission error is reckoned through the gearbox ratio, but the case gives no gearbox.ratio")
        path = measurement_path(t.data["transmission_trace"], case.folder, t.where("transmission_trace"))
        analysis = analyze_trace(read_trace(path), own_ratio)
        accuracy = analysis.accuracy
        out.traces[name] = (display_path(path), analysis)
        sources.append(f"trace {display_path(path)}")
    if stiffness is None:
        raise CalcError(f"{t.where('stiffness')}: expected a stiffness such as \"1.3 N*m/arcmin\" (or a part, or a measured hysteresis loop), found none")
    if backlash is None:
        raise CalcError(f"{t.where('backlash')}: expected an angle such as \"3 arcmin\" (\"0 arcmin\" for none), found none")
    return Component(name, side, stiffness, backlash, accuracy, nominal, source="; ".join(sources) or "case")


def accuracy_of(case: Case) -> tuple:
    """The ``[accuracy]`` section as read and evaluated, ``(spec, ChainAccuracy)``; computed once per case."""

    def compute():
        spec = read_accuracy(case)
        try:
            return spec, spec.evaluate()
        except CalcError as exc:
            raise CalcError(f"{case.path}: accuracy.{exc}") from None

    return once(case, "accuracy", compute)


def section_results(case: Case) -> dict:
    """The ``accuracy`` section of the results (``spec/case-format.md``): ``C_total`` referred to
    the output, ``lost_motion``, ``positioning_accuracy``, ``repeatability`` and the
    ``components`` with their ``stiffness_at_output`` and ``backlash_at_output``, each quantity as
    ``{"value", "unit"}``; measured loops, traces and positioning records where the case names them.

    >>> from calc.case import read_case
    >>> from calc.catalog import CATALOG_DIR
    >>> r = section_results(read_case(CATALOG_DIR.parent / "cases" / "indexing-table.toml"))
    >>> round(r["C_total"]["value"], 2), r["C_total"]["unit"], [c["side"] for c in r["components"]]
    (21.35, 'N*m/arcmin', ['input', 'output'])
    """
    from .evaluate import number, quantity

    spec, a = accuracy_of(case)
    c = a.chain
    shares = c.compliance_shares
    twist = c.twist(a.applied_torque)
    components = []
    for k, comp in enumerate(c.components):
        ta = c.transmission_accuracy_at_output[k]
        item = {
            "name": comp.name,
            "side": comp.side,
            "source": comp.source,
            "stiffness_at_output": quantity(c.stiffness_at_output[k], "N*m/arcmin"),
            "backlash_at_output": quantity(c.backlash_at_output[k], "arcmin"),
            "transmission_accuracy_at_output": None if np.isnan(ta.magnitude) else quantity(ta, "arcsec"),
            "share_of_compliance": number(shares[k]),
            "twist_at_applied_torque": quantity(twist[k], "arcmin"),
        }
        if comp.name in spec.loops:
            path, loop = spec.loops[comp.name]
            item["measured_loop"] = {
                "file": path,
                "stiffness_positive": quantity(loop.stiffness_positive, "N*m/arcmin"),
                "stiffness_negative": quantity(loop.stiffness_negative, "N*m/arcmin"),
                "backlash": quantity(loop.backlash, "arcmin"),
                "lost_motion": quantity(loop.lost_motion, "arcmin"),
            }
        if comp.name in spec.traces:
            path, trace = spec.traces[comp.name]
            item["measured_trace"] = {"file": path, "transmission_accuracy": quantity(trace.accuracy, "arcsec"), "direction": trace.governing}
        components.append(item)
    out = {
        "applied_torque": quantity(a.applied_torque, "N*m"),
        "ratio": None if c.ratio is None else number(c.ratio.m_as("")),
        "nominal_torque": None if a.nominal_torque is None else quantity(a.nominal_torque, "N*m"),
        "nominal_torque_from": "accuracy.nominal_torque" if spec.nominal_torque is not None else c.nominal_torque_from,
        "C_total": quantity(c.stiffness, "N*m/arcmin"),
        "backlash": quantity(c.backlash, "arcmin"),
        "transmission_accuracy": quantity(c.transmission_accuracy, "arcsec"),
        "transmission_accuracy_from": c.transmission_accuracy_from,
        "lost_motion": quantity(a.lost_motion, "arcmin"),
        "positioning_rule": "|T| <= 3 % of T_N: phi_TA + j_t" if a.low_torque else "|T| > 3 % of T_N: phi_TA + |T| / C",
        "positioning_accuracy": quantity(a.positioning_accuracy, "arcmin"),
        "repeatability": quantity(a.repeatability, "arcmin"),
        "repeatability_is_bound": a.repeatability_is_bound,
        "components": components,
    }
    if spec.positions is not None:
        p = spec.positions
        out["measured_positioning"] = {
            "file": display_path(p.source),
            "targets": p.targets,
            "approaches": len(p.error.magnitude),
            "accuracy": quantity(p.accuracy, "arcmin"),
            "repeatability": quantity(p.repeatability, "arcmin"),
        }
    checks = []
    for name, limit in spec.required.items():
        value = a.positioning_accuracy if name == "positioning_accuracy" else a.repeatability
        utilization = float((value / limit).m_as(""))
        checks.append({
            "name": name,
            "criterion": f"{name} <= required",
            "value": quantity(value, "arcmin"),
            "required": quantity(limit, "arcmin"),
            "utilization": number(utilization),
            "passes": utilization <= 1.0,
        })
    if checks:
        out["checks"] = checks
        out["passes"] = all(k["passes"] for k in checks)
    return out



def summary_lines(section: dict) -> list[str]:
    """The accuracy results (:func:`section_results`) as lines of the terminal report: the chain
    table, then C_total, lost motion, positioning accuracy with the rule that applied, and
    repeatability, each with its errata entry; measurements and checks after."""
    from .evaluate import quantity_text

    s = section
    ratio = "" if s["ratio"] is None else f", ratio {s['ratio']:g}"
    lines = [f"Accuracy at the output (applied torque {quantity_text(s['applied_torque'])}{ratio}; E11 to E13):"]
    width = max(len(c["name"]) for c in s["components"])
    lines.append(f"  {'component':<{width}}  side    {'stiffness at output':>20}  {'share of twist':>14}  {'backlash at output':>18}  source")
    for c in s["components"]:
        lines.append(
            f"  {c['name']:<{width}}  {c['side']:<6}  {quantity_text(c['stiffness_at_output']):>20}  {100 * c['share_of_compliance']:>12.1f} %"
            f"  {quantity_text(c['backlash_at_output']):>18}  {c['source']}"
        )
    ta_from = ", ".join(s["transmission_accuracy_from"]) or "no component gives one"
    t_n = "" if s["nominal_torque"] is None else f", T_N = {quantity_text(s['nominal_torque'])} ({s['nominal_torque_from']})"
    lines += [
        f"  C_total = {quantity_text(s['C_total'])}; backlash = {quantity_text(s['backlash'])}; transmission accuracy = {quantity_text(s['transmission_accuracy'])} ({ta_from})",
        f"  Lost motion = j_t + |T| / C = {quantity_text(s['lost_motion'])} (E12)",
        f"  Positioning accuracy ({s['positioning_rule']}{t_n}) = {quantity_text(s['positioning_accuracy'])} (E13)",
        f"  Repeatability {'<=' if s['repeatability_is_bound'] else '='} {quantity_text(s['repeatability'])} "
        f"({'bounded by the lost motion under torque' if s['repeatability_is_bound'] else 'the backlash at T = 0'}, E13)",
    ]
    for c in s["components"]:
        if "measured_loop" in c:
            m = c["measured_loop"]
            lines.append(
                f"  Measured loop of {c['name']} ({m['file']}): C = {quantity_text(m['stiffness_positive'])} / {quantity_text(m['stiffness_negative'])} "
                f"(+ / -), backlash {quantity_text(m['backlash'])}, lost motion ±3 % {quantity_text(m['lost_motion'])}"
            )
        if "measured_trace" in c:
            m = c["measured_trace"]
            lines.append(f"  Measured trace of {c['name']} ({m['file']}): transmission accuracy {quantity_text(m['transmission_accuracy'])} ({m['direction']})")
    if "measured_positioning" in s:
        m = s["measured_positioning"]
        lines.append(
            f"  Measured positioning ({m['file']}, {m['approaches']} approaches to {m['targets']} targets): "
            f"accuracy {quantity_text(m['accuracy'])}, repeatability {quantity_text(m['repeatability'])}"
        )
    for k in s.get("checks", []):
        lines.append(
            f"  {k['name']:<22} {quantity_text(k['value']):>12} required <= {quantity_text(k['required']):>12}  utilization {k['utilization']:.2f}  {'ok' if k['passes'] else 'FAIL'}"
        )
    return lines
