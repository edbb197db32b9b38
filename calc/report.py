"""The calc report of a design case: what it holds, collected once and laid out in LaTeX.

:func:`build_report` reads and evaluates a case and collects what a reviewer reads, in the order
they read it (efficalc's order): the verdict and the chosen parts; the title block (the case file
and each catalog with its SHA-256, the build date, the package version, the commit); method and
assumptions (the source's sections and the errata readings that apply); the inputs; each
calculation as ``symbol = formula = substituted values = result`` from the
:class:`calc.formula.Formula` objects; the checks; the candidate tables; the figures; the order
lines. Each part is a :class:`Latex` block: the report notebook (``reports/calc-report.ipynb``)
displays it and nbconvert passes it unchanged into the PDF (:mod:`calc.publish`).

Text from a case file or a catalog goes through :func:`latex_escape`, so it prints as written. A
case that fails its checks, or cannot be evaluated at all, still gives a report: its verdict is
FAIL and it says why.
"""

from __future__ import annotations

import hashlib
import re
import subprocess
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path

import numpy as np

from . import __version__
from .case import Case, read_case
from .catalog import PROJECT_DIR, display_path
from .errors import CalcError
from .sections import FURTHER as SECTIONS
from .sections import Results, Verdict, evaluate
from .formula import REGISTRY, Step
from .gearbox import SHOCK_FACTORS, T_2max, inertia_ratio, n_1
from .profile import ED, T_2m, Z_h, n_2m
from .profile import t_k as t_k_symbol
from .units import NUMBER, Q_, pretty_unit, sig

#: The sections of the source document each part of a case is computed from.
SOURCE_SECTIONS = {
    "gearbox": (
        "Determination of the Duty Cycle (ED)",
        "Selection of Optimum Gearbox for a Continuous Operation (S1)",
        "Selection of Optimum Gearbox for a Cycle Operation (S5)",
    ),
    "coupling": ("Sizing and Selecting for Couplings and Safety Couplings",),
    "accuracy": ("Accuracy in Gearboxes and Couplings: Definitions (torsional stiffness, backlash, lost motion)",),
}

#: The errata readings (``errata.md``), one line each, and the part of a case each applies to.
ERRATA = {
    "E1": ("gearbox", "The S1 speed criterion is on the input side: n_2m · i ≤ n_1N."),
    "E2": ("gearbox", "T_2m is the speed-weighted cubic mean of torque magnitudes and n_2m averages over the "
           "moving time only (pauses drop out), for any number of segments."),
    "E3": ("gearbox", "S5 if and only if ED < 60 % and the on-time t_a + t_c + t_d < 20 min; every other case S1. "
           "The cycle time includes the pauses."),
    "E4": ("gearbox", "Shock factor f_s: at a band boundary of Z_h (1000, 1500, 2000, 3000 per hour) the higher factor applies."),
    "E5": ("gearbox", "The S5 speed check uses the highest output speed of the cycle: n_2max · i ≤ n_1max."),
    "E6": ("gearbox", "The inertia match is reported as the ratio λ = (J_1 + J_L / i²) / J_motor; 1 is the ideal match."),
    "E7": ("coupling", "Coupling resonance: the two-mass natural frequency f_e = 1/(2π) · √(C_T (J_A + J_L) / (J_A J_L)), "
           "checked as f_e ≥ 2 f_er."),
    "E8": ("coupling", "The factor 2.5 in M_N is the service factor S_A (default 2.5); between motor and gearbox "
           "the coupling sees the load reflected to the input, J_L / i² + J_1."),
    "E9": ("coupling", "The temperature factor applies to elastomer couplings only; at a band boundary the higher factor applies."),
    "E10": ("coupling", "A safety coupling's disengagement torque T_A lies inside the size's adjustable range and "
            "above the highest torque of normal operation."),
    "E11": ("accuracy", "Stiffness and backlash are referred to the output: an input-side component counts with C · i² "
            "and backlash / i."),
    "E12": ("accuracy", "Stiffness, backlash and lost motion from a hysteresis curve: slope between 50 % and 100 % of "
            "nominal torque, loop width at 0 N·m, deflection span within ±3 % of nominal torque."),
    "E13": ("accuracy", "Positioning accuracy by the source's rule: up to 3 % of nominal torque, transmission accuracy "
            "+ backlash; above, transmission accuracy + T / C."),
    "E14": (None, "Units: stiffness in N·m/arcmin, inertia in kg·cm², speed in rpm; every conversion goes through "
            "the one unit registry."),
    "E15": (None, "Every angle, speed and stiffness input is checked for the angle in its unit (the unit library "
            "treats angles as dimensionless); a shaft's frequency is n / 60 s per revolution."),
}


class Latex(str):
    """A block of LaTeX: Jupyter shows it, nbconvert's LaTeX export passes it into the PDF as is."""

    def _repr_latex_(self):
        return str(self)


_SPECIAL = {
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
    "^": r"\textasciicircum{}", "_": r"\_", "%": r"\%", "~": r"\textasciitilde{}",
}
_LIGATURE = re.compile(r"(?<=[-`',<>!?])(?=[-`',<>!?])")


def latex_escape(text) -> str:
    r"""Text as LaTeX that prints exactly as written.

    The ten special characters are escaped, line breaks become spaces, and ``{}`` is put between
    characters that TeX would join (``--`` into a dash, ``''`` into a quote).

    >>> print(latex_escape("Axis #3 — 50% load & T_2 {v2} \\ 100$"))
    Axis \#3 — 50\% load \& T\_2 \{v2\} \textbackslash{} 100\$
    >>> print(latex_escape("a--b"))
    a-{}-b
    """
    out = "".join(_SPECIAL.get(c, c) for c in " ".join(str(text).splitlines()))
    return _LIGATURE.sub("{}", out)


_SYMBOL = re.compile(r"\b(phi|eta|lambda|[A-Za-z])_([A-Za-z0-9]+)\b")
_GREEK = {"phi": r"\varphi", "eta": r"\eta", "lambda": r"\lambda"}


def prose(text: str) -> str:
    """Our own running text (readings, assumptions, reasons) as LaTeX: escaped, with each symbol
    written as in code (``n_2m``, ``J_motor``) set in math and ``<=``, ``>=`` as ≤, ≥.

    >>> print(prose("n_2m · i <= n_1N, 100%"))
    $n_{\\mathrm{2m}}$ · i ≤ $n_{\\mathrm{1N}}$, 100\\%
    """
    out, last = [], 0
    text = text.replace("<=", "≤").replace(">=", "≥")
    for m in _SYMBOL.finditer(text):
        out += [latex_escape(text[last:m.start()]), rf"${_GREEK.get(m.group(1), m.group(1))}_{{\mathrm{{{m.group(2)}}}}}$"]
        last = m.end()
    return "".join(out) + latex_escape(text[last:])


def _text_math(text: str) -> str:
    """A criterion written in plain text (``n_2m · i <= n_1N``) as LaTeX math."""
    out = re.sub(r"\b([A-Za-z])_([A-Za-z0-9]+)", r"\1_{\\mathrm{\2}}", text)
    return "$" + out.replace("<=", r"\le").replace(">=", r"\ge").replace("·", r"\cdot") + "$"


def _plain(d) -> str:
    """A result quantity ``{"value", "unit"}`` as plain text (``151.3 N·m``)."""
    if d is None or d.get("value") is None:
        return "n/a"
    return f"{_signed(sig(d['value']))} {pretty_unit(d['unit'])}".rstrip()


def _q(d) -> str:
    """A result quantity as LaTeX text."""
    return latex_escape(_plain(d))


def _signed(text: str) -> str:
    """A number's minus as a minus sign, not a hyphen."""
    return text.replace("-", "−", 1) if text.startswith("-") else text


def _num(q, unit: str) -> str:
    return _signed(sig(q.m_as(unit)))


def _util(u) -> str:
    if u is None or (isinstance(u, float) and np.isnan(u)):
        return "no rating"
    text = f"{u:.2f}"
    return rf"\textcolor{{failred}}{{\textbf{{{text}}}}}" if u > 1 else text


def _verdict(passes: bool) -> str:
    return r"\pass" if passes else r"\fail"


def sha256(path: Path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def git_commit(folder: Path | None = PROJECT_DIR) -> str:
    """The commit the package was built from, marked when calc/ or catalogs/ differ from it.

    An installed calc (``folder`` None) has no git tree; a checkout that is not the top of its own
    git tree (an unpacked source archive inside another repository) is not under version control:
    the enclosing repository's commit would name the wrong source.
    """
    if folder is None:
        return "none: an installed package, not a git checkout"
    try:
        head = subprocess.run(["git", "-C", str(folder), "rev-parse", "--show-toplevel", "HEAD"],
                              capture_output=True, text=True, check=True)
        dirty = subprocess.run(
            ["git", "-C", str(folder), "status", "--porcelain", "--untracked-files=no", "--", "calc", "catalogs"],
            capture_output=True, text=True, check=True,
        )
    except (OSError, subprocess.CalledProcessError):
        return "not under version control"
    top, commit = head.stdout.splitlines()
    if Path(top).resolve() != Path(folder).resolve():
        return "not under version control"
    return commit + (" (with uncommitted changes in calc/ or catalogs/)" if dirty.stdout.strip() else "")


def _listed(value) -> str:
    return ", ".join(map(str, value)) if isinstance(value, (list, tuple)) else str(value)


def table(columns: str, header: list[str], rows: list[list[str]], caption: str = "", note: str = "", small: bool = False) -> str:
    """A booktabs longtable: a long one breaks across pages with its header repeated, a short one
    (up to 15 rows) stays on one page. Cells are LaTeX already; the note goes below the table."""
    columns = re.sub(r"(?<!})p\{", r">{\\raggedright\\arraybackslash}p{", columns)  # no stretched words
    head = " & ".join(rf"\textbf{{{h}}}" for h in header) + r" \\"
    end = r" \\*" if len(rows) <= 15 else r" \\"
    body = "\n".join(" & ".join(r) + end for r in rows)
    cap = rf"\caption{{{caption}}}\\*" if caption else ""
    out = (
        rf"\begin{{longtable}}{{{columns}}}" "\n" rf"{cap}\toprule {head}* \midrule\endfirsthead" "\n"
        rf"\toprule {head} \midrule\endhead" "\n" r"\bottomrule\endlastfoot" "\n"
        f"{body}\n" r"\end{longtable}"
    )
    if small:
        out = r"{\small " + out + "}"
    if not caption:
        out += r"\addtocounter{table}{-1}"  # longtable counts every table; only captioned ones are numbered
    if note:
        out += "\n" rf"\vspace{{-4pt}}{{\par\noindent\footnotesize {note}\par}}\vspace{{6pt}}"
    return out


def step_block(title: str, step: Step, note: str = "") -> str:
    """One calculation: a heading, ``symbol = formula = values = result`` aligned on the equals
    signs (scaled down only if wider than the page), and its reference."""
    lhs, expr, values, result = step.parts()
    f = step.formula
    lines = rf"{lhs} &= {expr} \\ &= {values} \\ &= {result}"
    ref = prose(f.reference + (f"; {note}" if note else ""))
    return (
        rf"\calcstep{{{latex_escape(title)}}}{{${f.result.latex}$}}"
        "\n" r"\begin{adjustbox}{max width=\linewidth,center}$\displaystyle\begin{aligned}" f"{lines}"
        r"\end{aligned}$\end{adjustbox}" "\n" rf"\calcref{{{ref}}}"
    )


def _symbols() -> dict:
    """The symbols of the load cycle's and the gearbox's formulas, by their name in code (the
    case's [motor], [load], [gearbox] and [[profile]] inputs; the further sections have their own,
    see :func:`_section_symbols`: a coupling's J_L is another quantity than the gearbox's)."""
    own = ("calc.profile.", "calc.gearbox.")
    return {s.name: s for f in REGISTRY if f.key.startswith(own) for s in (f.result, *f.inputs)}


@dataclass
class Report:
    """Everything a calc report holds, collected from one case file."""

    path: Path
    title: str
    built: str
    commit: str
    case: Case | None = None
    evaluated: Results | None = None
    results: dict | None = None  # evaluated, as the JSON contract writes it (every candidate)
    selection: object = None  # GearboxSelection
    coupling: object = None  # (CouplingCase, CouplingSelection) when the case has [coupling]
    accuracy: object = None  # (AccuracyCase, ChainAccuracy) when the case has [accuracy]
    error: str | None = None  # why the case could not be evaluated
    files: list = field(default_factory=list)  # (label, path text, sha256)

    # -- the verdict -------------------------------------------------------------------------

    @property
    def chosen(self) -> list[tuple[str, str, str]]:
        """(what, part, detail) of each chosen part; part is None where none passes."""
        out = []
        if self.results is None:
            return out
        g = self.results.get("gearbox")
        if g:
            best = g["candidates"][0] if g["candidates"] else None
            detail = f"ratio {best['ratio']:g}, {self.selection.mode} checks, catalog {g['catalog']}" if best else ""
            out.append(("Gearbox", g["selected"], detail))
        for name in SECTIONS:
            s = self.results.get(name)
            if s and "selected" in s:
                out.append((name.capitalize(), s["selected"], f"catalog {s['catalog']}" if s.get("catalog") else ""))
        return out

    @property
    def verdict(self) -> Verdict:
        """The case's one verdict (:mod:`calc.sections`); FAIL with the reason for a case that
        cannot be evaluated."""
        if self.error is not None:
            return Verdict(False, [f"The case cannot be evaluated: {self.error}"])
        return self.evaluated.verdict

    @property
    def reasons(self) -> list[str]:
        """Why the case does not pass, one plain sentence each (empty when it passes)."""
        return self.verdict.reasons

    @property
    def passes(self) -> bool:
        return self.verdict.passes is True

    def summary_line(self) -> str:
        """One line for a terminal: verdict, case, chosen parts or the first reason."""
        if self.passes:
            what = ", ".join(f"{w.lower()} {p}" for w, p, _ in self.chosen)
        else:
            what = " ".join(self.reasons[:2])
        return f"{self.verdict.word}  {display_path(self.path)}: {what}"

    # -- the blocks, in the order of the report ------------------------------------------------

    def front_page(self) -> Latex:
        """Title, verdict with its reasons, chosen parts, title block and signature lines."""
        title = latex_escape(self.title)
        out = [
            rf"\renewcommand{{\reporttitle}}{{{title}}}",
            rf"\renewcommand{{\reportcase}}{{{latex_escape(display_path(self.path))}}}",
            rf"\hypersetup{{pdftitle={{{title}}}}}",
            rf"\reportheading{{{title}}}{{{latex_escape(display_path(self.path))}}}",
        ]
        if self.passes:
            body = "Every governing check passes." + self._governing_lines()
        else:
            render = latex_escape if self.error else prose  # an error message quotes the case file as written
            items = "\n".join(rf"\item {render(r)}" for r in self.reasons)
            body = r"The design does not pass. Why:" "\n" rf"\begin{{itemize}}{items}\end{{itemize}}"
        out.append(rf"\verdictbox{{{self.verdict.word}}}{{{'passgreen' if self.passes else 'failred'}}}{{{body}}}")
        if self.chosen:
            rows = [[w, latex_escape(p) if p else r"\textcolor{failred}{none passes}", latex_escape(d)] for w, p, d in self.chosen]
            out.append(r"\subsection*{Chosen parts}" + table(r"@{}l l p{0.55\linewidth}@{}", ["Part", "Chosen", "Basis"], rows))
        rows = [
            ["Case file", rf"\texttt{{{latex_escape(display_path(self.path))}}}"],
            ["SHA-256", rf"\texttt{{\footnotesize {self.files[0][2]}}}" if self.files else "unreadable"],
        ]
        for label, path, digest in self.files[1:]:
            rows += [[latex_escape(label), rf"\texttt{{{latex_escape(path)}}}"], ["SHA-256", rf"\texttt{{\footnotesize {digest}}}"]]
        rows += [
            ["Built", latex_escape(self.built)],
            ["Package", latex_escape(f"calc {__version__}")],
            ["Commit", rf"\texttt{{\footnotesize {latex_escape(self.commit)}}}"],
        ]
        out.append(r"\subsection*{Title block}" + table(r"@{}l p{0.78\linewidth}@{}", ["Item", "Value"], rows))
        out.append(r"\signatures")
        return Latex("\n".join(out))

    def _governing_lines(self) -> str:
        """The governing checks of each chosen part, one line each with its utilization."""
        lines = []
        for name in ("gearbox", *SECTIONS):
            s = (self.results or {}).get(name)
            if not s or not s.get("candidates") or not s.get("selected"):
                continue
            c = s["candidates"][0]
            for k in c.get("checks", []):
                if k.get("governs", True):
                    crit = prose(k["criterion"]) if k.get("criterion") else latex_escape(k["name"])
                    lines.append(rf"\item {latex_escape(name.capitalize())} {latex_escape(c['part'])}: {crit}: "
                                 rf"{_q(k['required'])} against {_q(k['rated'])}, utilization {_util(k['utilization'])}")
        return (r"\begin{itemize}" + "".join(lines) + r"\end{itemize}") if lines else ""

    def method(self) -> Latex:
        """The source's sections, the errata readings that apply, and the assumptions."""
        if self.case is None:
            return Latex("")
        parts = {"gearbox"} | {name for name in SECTIONS if self.case.sections.get(name) is not None}
        sections = [s for p in ("gearbox", *SECTIONS) if p in parts for s in SOURCE_SECTIONS[p]]
        out = [r"\section{Method and assumptions}", r"\paragraph{Source.} The project's source document, sections:"]
        out.append(r"\begin{itemize}" + "".join(rf"\item {latex_escape(s)}" for s in sections) + r"\end{itemize}")
        out.append(r"\paragraph{Readings of the source (errata) applied in this report.}")
        applied = [(k, text) for k, (part, text) in ERRATA.items() if part is None or part in parts]
        if self.selection is None or self.selection.inertia_ratio is None:
            applied = [(k, t) for k, t in applied if k != "E6"]
        out.append(
            r"\begin{description}[font=\normalfont\bfseries,leftmargin=3em,style=sameline]"
            + "".join(rf"\item[{k}] {prose(t)}" for k, t in applied)
            + r"\end{description}"
        )
        assumptions = [
            "The load cycle is given at the gearbox output: each segment's mean output speed and output torque, "
            "pauses by their duration.",
            "Ratings are the catalog's published figures (each row names its source); rows marked illustrative are not "
            "a maker's own figures and are never chosen without a look at the maker's data.",
            "The operating mode decides which checks govern the verdict; the checks of the other mode are reported "
            "for information only.",
        ]
        for name in ("gearbox", *SECTIONS):
            s = (self.results or {}).get(name)
            if s and s.get("ranking"):
                assumptions.append(f"Ranking of the {name} candidates: {s['ranking']}.")
        out.append(r"\paragraph{Assumptions.}" r"\begin{itemize}" + "".join(rf"\item {prose(a)}" for a in assumptions) + r"\end{itemize}")
        return Latex("\n".join(out))

    def inputs(self) -> Latex:
        """The inputs as tables: symbol, value, unit, description (and where in the case file)."""
        if self.case is None:
            return Latex("")
        c, sym = self.case, _symbols()
        rows = []

        def add(name, q, key):
            if q is None:
                return
            s = sym[name]
            unit = s.unit
            rows.append([f"${s.latex}$", sig(q.m_as(unit)), latex_escape(pretty_unit(unit)) or "–",
                         latex_escape(s.description), rf"\texttt{{\footnotesize {latex_escape(key)}}}"])

        add("T_1B", c.motor_peak_torque, "motor.peak_torque")
        add("J_motor", c.motor_inertia, "motor.inertia")
        add("J_L", c.load_inertia, "load.inertia")
        add("i", c.ratio, "gearbox.ratio")
        if c.gearbox_part:
            rows.append(["–", latex_escape(c.gearbox_part), "–", "gearbox part to check", r"\texttt{\footnotesize gearbox.part}"])
        if c.gearbox_catalog and (c.ratio is not None or c.gearbox_part):
            rows.append(["–", latex_escape(c.gearbox_catalog), "–", "gearbox catalog", r"\texttt{\footnotesize gearbox.catalog}"])
        out = [r"\section{Inputs}"]
        if rows:
            out.append(table(r"@{}l r l p{0.38\linewidth} l@{}", ["Symbol", "Value", "Unit", "Description", "Case key"], rows))
        p = c.profile
        prow = []
        for k, (phase, t, n, T) in enumerate(zip(p.phases, p.durations, p.speeds, p.torques), start=1):
            moving = phase != "pause"
            prow.append([str(k), phase, _num(t, "s"), _num(n, "rpm") if moving else "–", _num(T, "N*m") if moving else "–"])
        s = _symbols()
        out.append(table(
            r"@{}r l r r r@{}",
            ["k", "Phase", f"${t_k_symbol.latex}$ [s]", rf"${s['n_2k'].latex}$ [rpm]", rf"${s['T_2k'].latex}$ [N·m]"],
            prow,
            caption="Load cycle at the gearbox output (case key \\texttt{[[profile]]})",
            note="Speeds are the mean output speed of each segment; a negative torque brakes.",
        ))
        for name in SECTIONS:
            raw = c.sections.get(name)
            if raw is not None:
                out.append(_raw_section_tables(name, raw, self._derived_inputs(name, raw)))
        return Latex("\n".join(out))

    def calculations(self) -> Latex:
        """Every formula used, as ``symbol = formula = values = result`` with its reference."""
        if self.results is None:
            return Latex("")
        p = self.case.profile
        seg = p.moving_values()
        out = [r"\section{Calculations}", r"\subsection{Duty cycle and operating mode}"]
        d = self.results["duty"]
        out.append(step_block("Duty cycle", ED.step(t_on=p.t_on, t_cycle=p.t_cycle),
                              f"operating mode {d['mode']} (E3)"))
        out.append(r"\subsection{Continuous operation (S1)}")
        s_n2m = n_2m.step(n_2k=seg["n_2k"], t_k=seg["t_k"])
        out.append(step_block("Mean output speed", s_n2m))
        out.append(step_block("Cubic mean output torque", T_2m.step(**seg)))
        out.append(r"\subsection{Cycle operation (S5)}")
        s_zh = Z_h.step(t_cycle=p.t_cycle)
        out.append(step_block("Cycles per hour", s_zh))
        out.append(_shock_factor_block(s_zh.result))
        out += self._gearbox_check_steps() + self._coupling_steps() + self._accuracy_steps()
        return Latex("\n".join(out))

    def _gearbox_check_steps(self) -> list[str]:
        sel = self.selection
        if sel is None:
            return []
        p, fs = self.case.profile, self.results["cyclic"]["fs"]
        row = int(sel.order[0])
        cat = sel.catalog
        i = cat["ratio"][row]
        chosen = "the chosen gearbox" if sel.selected else "the closest candidate (none passes)"
        out = [rf"\subsection{{Checks of {chosen}, {latex_escape(str(cat.parts[row]))}}}"]
        n2m = n_2m(**{k: v for k, v in p.moving_values().items() if k != "T_2k"})
        out.append(step_block("Input speed at the mean output speed (S1)", n_1.step(n_2=n2m, i=i), "compared with n_1N"))
        out.append(step_block("Input speed at the highest output speed (S5)", n_1.step(n_2=p.n_2max, i=i), "compared with n_1max"))
        if self.case.motor_peak_torque is not None:
            out.append(step_block("Maximum output torque", T_2max.step(T_1B=self.case.motor_peak_torque, i=i, f_s=Q_(fs, ""),
                                                                      eta=cat["eta"][row]), "compared with T_2B"))
        if sel.inertia_ratio is not None and not np.isnan(cat["J_1"][row].magnitude):
            out.append(step_block("Load to motor inertia ratio", inertia_ratio.step(
                J_1=cat["J_1"][row], J_L=self.case.load_inertia, i=i, J_motor=self.case.motor_inertia), "errata E6"))
        return out

    def _derived_inputs(self, name: str, raw: dict) -> dict:
        """A section's inputs that the case left out and the package took from the rest of it
        (a motor-side coupling's M_a, J_drive, J_load, speed), as the case would write them."""
        if name != "coupling" or self.coupling is None:
            return {}
        units = {"accel_torque": "N*m", "drive_inertia": "kg*cm**2", "load_inertia": "kg*cm**2", "speed": "rpm"}
        x = self.coupling[0].inputs
        return {k: f"{sig(x[k].m_as(u))} {u}" for k, u in units.items() if k not in raw and x.get(k) is not None}

    def _coupling_steps(self) -> list[str]:
        if self.coupling is None:
            return []
        from . import coupling as cp

        cc, sel = self.coupling
        x, cat = cc.inputs, sel.catalog
        row = int(sel.order[0])
        part = latex_escape(str(cat.parts[row]))
        chosen = "the chosen coupling" if sel.selected else "the closest candidate (none passes)"
        out = [r"\subsection{Coupling: nominal torque and resonance}"]
        if "load_inertia" in self._derived_inputs("coupling", self.case.sections["coupling"]) and self.selection is not None:
            g = self.selection.catalog
            k = int(self.selection.order[0])
            out.append(step_block(
                f"Load inertia seen by the coupling, through {latex_escape(str(g.parts[k]))}",
                cp.J_load_at_input.step(J_L=self.case.load_inertia, i=g["ratio"][k], J_1=g["J_1"][k]),
            ))
        m_n = cp.M_N.step(M_a=x["accel_torque"], J_load=x["load_inertia"], J_drive=x["drive_inertia"], S_A=x["service_factor"])
        out.append(step_block("Nominal torque of the coupling", m_n, "compared with T_KN"))
        if sel.row_type(row) == "elastomer":
            bands = cp.TEMPERATURE_FACTORS
            band = bands.text(int(bands.band(x["temperature"], "coupling.temperature")))
            out.append(step_block(f"With the temperature factor ({part})",
                                  cp.M_Nt.step(M_N=m_n.result, K_T=Q_(float(sel.temperature_factor[row]), "")),
                                  f"K_T of the band {band} (E9)"))
        out.append(step_block("Lowest natural frequency allowed", cp.f_e_min.step(f_er=x["excitation_frequency"])))
        if np.isnan(sel.f_e[row].magnitude):
            return out
        out.append(rf"\subsection{{Natural frequency of {chosen}, {part}}}")
        J = cat["J"][row]
        out.append(step_block("Drive side with half the coupling", cp.J_A.step(J_drive=x["drive_inertia"], J_K=J)))
        out.append(step_block("Load side with half the coupling", cp.J_L.step(J_load=x["load_inertia"], J_K=J)))
        if sel.row_type(row) == "line-shaft" and x["shaft_distance"] is not None:
            z = cp.Z.step(A=x["shaft_distance"], H=cat["H"][row])
            out.append(step_block("Tube length", z))
            out.append(step_block("Stiffness of the line shaft", cp.C_T_line.step(C_B=cat["C_T"][row], Z=z.result, C_tube=cat["C_tube"][row])))
        out.append(step_block("Natural frequency", cp.f_e.step(C_T=sel.C_T[row], J_A=sel.J_A[row], J_L=sel.J_L[row]),
                              "compared with 2 f_er"))
        return out

    def _accuracy_steps(self) -> list[str]:
        if self.accuracy is None:
            return []
        spec, a = self.accuracy
        out = []
        for name, (path, analysis) in spec.loops.items():
            out.append(rf"\subsection{{Measured hysteresis loop of {latex_escape(name)}}}")
            out.append(rf"From \texttt{{{latex_escape(path)}}} (E12).")
            out += [step_block(s.formula.result.description.capitalize(), s) for s in analysis.steps()]
        for name, (path, analysis) in spec.traces.items():
            out.append(rf"\subsection{{Measured transmission error of {latex_escape(name)}}}")
            out.append(rf"From \texttt{{{latex_escape(path)}}}.")
            out.append(step_block(analysis.step().formula.result.description.capitalize(), analysis.step()))
        out.append(r"\subsection{Accuracy of the drive train at the output}")
        out.append(prose(f"Applied torque: {a.rule.why}, so the positioning rule of E13 for that range applies, {a.rule.text}."))
        out += [step_block(s.formula.result.description.capitalize(), s) for s in a.steps()]
        return out

    def checks(self) -> Latex:
        """The checks of each chosen part (or the closest candidate) with required, rated,
        utilization and verdict."""
        if not self.results or "gearbox" not in self.results:
            return Latex("")
        g = self.results["gearbox"]
        c = g["candidates"][0]
        out = [r"\section{Checks}"]
        out.append(_checks_table(c, f"Checks of gearbox {c['part']}" + (" (chosen)" if g["selected"] else " (the closest candidate; none passes)")))
        for name in SECTIONS:
            s = self.results.get(name)
            if s and s.get("candidates"):
                first = s["candidates"][0]
                if first.get("checks"):
                    out.append(_checks_table(first, f"Checks of {name} {first.get('part', '')}"))
            elif s and s.get("checks"):
                out.append(_requirement_table(s["checks"], f"{name.capitalize()} against the requirements of the case"))
        return Latex("\n".join(out))

    def candidates(self) -> Latex:
        """Every candidate at the ratio: its catalog ratings, and the utilization of each check."""
        if not self.results or "gearbox" not in self.results:
            return Latex("")
        g, sel = self.results["gearbox"], self.selection
        cat = sel.catalog
        out = [r"\section{Candidates}"]
        illustrative = False
        rows = []
        for r in sel.order:
            c = next(x for x in g["candidates"] if x["part"] == str(cat.parts[r]))
            illustrative |= c["illustrative"]
            j1 = cat["J_1"][r]
            rows.append([
                latex_escape(c["part"]) + (r"$^{*}$" if c["illustrative"] else ""),
                latex_escape(str(cat.text["series"][r])) if "series" in cat.text else "",
                _num(cat["T_2N"][r], "N*m"), _num(cat["T_2B"][r], "N*m"),
                _num(cat["n_1N"][r], "rpm"), _num(cat["n_1max"][r], "rpm"),
                _num(cat["eta"][r], "percent"), "–" if np.isnan(j1.magnitude) else _num(j1, "kg*cm**2"),
            ])
        sources = sorted({str(cat.text["source"][r]) for r in sel.order})
        note = "Sources: " + "; ".join(latex_escape(s) for s in sources)
        if illustrative:
            note = r"$^{*}$ illustrative row: not a maker's own figures. " + note
        out.append(table(
            r"@{}l l r r r r r r@{}",
            ["Part", "Series", "$T_{2N}$ [N·m]", "$T_{2B}$ [N·m]", "$n_{1N}$ [rpm]", "$n_{1\\mathrm{max}}$ [rpm]", r"$\eta$ [\%]", "$J_1$ [kg·cm²]"],
            rows, caption=latex_escape(f"Catalog ratings of the candidates ({g['catalog']}), best first"), note=note,
        ))
        out.append(_candidates_table(g, f"Utilization of each check (required / rated), {g['mode']} governs; "
                                        "checks in grey are for information", inertia=True))
        rejected = [c for c in g["candidates"] if c["reasons"]]
        if rejected:
            items = "".join(rf"\item \textbf{{{latex_escape(c['part'])}}}: {prose('; '.join(c['reasons']))}" for c in rejected)
            out.append(r"\paragraph{Why the others are rejected.}" r"\begin{itemize}" + items + r"\end{itemize}")
        for name in SECTIONS:
            s = self.results.get(name)
            if s and s.get("candidates"):
                out.append(rf"\subsection*{{{name.capitalize()}}}")
                out.append(_candidates_table(s, latex_escape(f"Utilization of each check of the {name} candidates, best first")))
                rejected = [c for c in s["candidates"] if c.get("reasons")]
                if rejected:
                    items = "".join(rf"\item \textbf{{{latex_escape(c['part'])}}}: {prose('; '.join(c['reasons']))}" for c in rejected)
                    out.append(r"\paragraph{Why the others are rejected.}" r"\begin{itemize}" + items + r"\end{itemize}")
        return Latex("\n".join(out))

    def section_results(self) -> Latex:
        """What the coupling and accuracy sections give besides their checks."""
        out = []
        c = (self.results or {}).get("coupling")
        if c:
            rows = [
                [r"$M_{N}$", _q(c["M_N"]), prose(f"nominal torque of the coupling, S_A = {c['service_factor']:g} included (E8)")],
                [r"$T_{\mathrm{op}}$", _q(c["T_op"]), prose("peak torque of normal operation (M_N with S_A = 1)")],
                [r"$K_{\vartheta}$", f"{c['temperature_factor']:g}",
                 prose("temperature factor (elastomer couplings, E9)" + (f" at {_plain(c['temperature'])}" if c.get("temperature") else ""))],
                [r"$f_{e,\mathrm{min}}$", _q(c["f_e_min"]), prose("lowest natural frequency allowed, 2 f_er (E7)")],
            ]
            out += [r"\subsection{Coupling: results}",
                    table(r"@{}l r p{0.6\linewidth}@{}", ["Symbol", "Value", "Description"], rows)]
            bores = [[rf"\texttt{{\footnotesize coupling.{latex_escape(b['key'])}}}", latex_escape(b["text"]),
                      latex_escape(b.get("limits") or "–")] for b in c.get("bores", [])]
            if bores:
                out.append(table(r"@{}l l l@{}", ["Case key", "Shaft as written", "Limits of the shaft (ISO 286)"], bores,
                                 caption="Shafts of the coupling"))
            if c.get("notes"):
                out.append(r"\paragraph{Notes.}\begin{itemize}" + "".join(rf"\item {prose(n)}" for n in c["notes"]) + r"\end{itemize}")
        a = (self.results or {}).get("accuracy")
        if a:
            rep = "repeatability, an upper bound under torque (E13)" if a["repeatability_is_bound"] else "repeatability (E13)"
            rows = [
                [r"$C_{\mathrm{total}}$", _q(a["C_total"]), prose("total torsional stiffness at the output (E11)")],
                [r"$j_{t}$", _q(a["backlash"]), prose("torsional backlash at the output")],
                [r"$\varphi_{\mathrm{TA}}$", _q(a["transmission_accuracy"]),
                 prose("angular transmission accuracy, from " + _listed(a["transmission_accuracy_from"]))],
                [r"$\varphi_{\mathrm{LM}}$", _q(a["lost_motion"]), prose("total lost motion at the applied torque (E12)")],
                [r"$\Delta\varphi_{P}$", _q(a["positioning_accuracy"]), prose(f"positioning accuracy, {a['positioning_rule']} (E13)")],
                ["–", _q(a["repeatability"]), prose(rep)],
            ]
            out += [r"\subsection{Accuracy: results}", table(r"@{}l r p{0.6\linewidth}@{}", ["Symbol", "Value", "Description"], rows)]
            comp = [[latex_escape(m["name"]), latex_escape(m["side"]), _q(m["stiffness_at_output"]), _q(m["backlash_at_output"]),
                     _q(m.get("transmission_accuracy_at_output")), f"{100 * m['share_of_compliance']:.1f}", _q(m["twist_at_applied_torque"])]
                    for m in a["components"]]
            out.append(table(r"@{}l l r r r r r@{}", ["Member", "Side", "$C$", "$j_t$", r"$\varphi_{\mathrm{TA}}$",
                                                      r"$1/C$ [\%]", r"Twist at $T$"], comp, small=True,
                             caption=prose(f"Members of the chain referred to the output, at T = {_plain(a['applied_torque'])}")))
        return Latex("\n".join([r"\section{Coupling and accuracy: results}"] + out) if out else "")

    def figures(self) -> list:
        """(figure, caption) pairs: the load cycle, the shock factor, the utilizations; the caption
        is LaTeX, for the output's ``caption`` metadata that our LaTeX template reads."""
        if self.case is None:
            return []
        from .plots import load_cycle_figure, shock_factor_figure, utilization_figure

        p = self.case.profile
        out = [
            (load_cycle_figure(p), "Load cycle at the gearbox output, with ED and the operating mode (E3)."),
            (shock_factor_figure(Z_h(t_cycle=p.t_cycle)), "Shock factor against cycles per hour; the case's point marked (E4)."),
        ]
        if self.selection is not None:
            out.append((utilization_figure(self.selection), "Utilization of the governing checks of each candidate, best first."))
        return out + self._coupling_figures() + self._accuracy_figures()

    def _coupling_figures(self) -> list:
        if self.coupling is None:
            return []
        from .coupling import f_e_min
        from .coupling_plots import natural_frequency_figure, temperature_factor_figure

        cc, sel = self.coupling
        out = [(natural_frequency_figure(sel, f_e_min(f_er=cc.inputs["excitation_frequency"])),
                prose("Natural frequency of each coupling candidate against the lowest allowed, 2 f_er (E7)."))]
        if (sel.catalog.text["type"] == "elastomer").any():
            out.append((temperature_factor_figure(cc.inputs["temperature"]), "Temperature factor of elastomer couplings (E9)."))
        return out

    def _accuracy_figures(self) -> list:
        if self.accuracy is None and self.selection is None:
            return []
        from .accuracy_plots import hysteresis_figure, positioning_scatter_figure, stiffness_chain_figure, transmission_error_figure
        from .hysteresis import analyze_loop, model_for_part, read_loop

        out = []
        spec = self.accuracy[0] if self.accuracy else None
        if spec is not None:
            out.append((stiffness_chain_figure(spec.chain, spec.applied_torque),
                        "Stiffness chain referred to the output (E11): each member's share of the twist."))
            for name, (path, analysis) in spec.loops.items():
                # a relative display path lies in the checkout (an installed calc shows measurements absolute)
                loop = read_loop(path if Path(path).is_absolute() else PROJECT_DIR / path)
                out.append((hysteresis_figure(loop, analysis), latex_escape(f"Measured hysteresis loop of {name} (E12).")))
        if (spec is None or not spec.loops) and self.selection is not None:
            sel, row = self.selection, int(self.selection.order[0])
            if not (np.isnan(sel.catalog["C_t21"][row].magnitude) or np.isnan(sel.catalog["backlash"][row].magnitude)):
                part = str(sel.catalog.parts[row])
                model = model_for_part(part, str(sel.catalog.path))
                loop = model.loop(800)
                out.append((hysteresis_figure(loop, analyze_loop(loop, model.nominal_torque)),
                            latex_escape(f"Hysteresis loop of {part} modelled from its catalog figures (C_t21, backlash, T_2N), "
                                         "not a measurement (E12).")))
        if spec is not None:
            for name, (path, analysis) in spec.traces.items():
                out.append((transmission_error_figure(analysis), latex_escape(f"Transmission error of {name}, from {path}.")))
            if spec.positions is not None:
                out.append((positioning_scatter_figure(spec.positions), "Measured positions: accuracy and repeatability."))
        return out

    def figures_heading(self) -> Latex:
        return Latex(r"\clearpage\section{Figures}") if self.case is not None else Latex("")  # figures start a page

    def order_lines(self) -> Latex:
        """What to order: one line per chosen part."""
        if not self.results:
            return Latex("")
        lines = []
        g = self.results.get("gearbox")
        if g and g["selected"]:
            sel = self.selection
            r = int(sel.order[0])
            lines.append(rf"Gearbox \textbf{{{latex_escape(g['selected'])}}}, ratio $i = {sig(sel.catalog['ratio'][r].m_as(''))}$"
                         rf" (series {latex_escape(str(sel.catalog.text['series'][r]))})")
        for name in SECTIONS:
            s = self.results.get(name)
            if s and s.get("order"):
                lines.append(latex_escape(s["order"]))
        out = [r"\section{Order}"]
        if lines:
            out.append(r"\begin{itemize}" + "".join(rf"\item {x}" for x in lines) + r"\end{itemize}")
        else:
            out.append(r"\textcolor{failred}{\textbf{Nothing to order: no part passes.}}")
        return Latex("\n".join(out))


def _shock_factor_block(zh) -> str:
    """The shock factor of ``Z_h`` (a quantity) with its band, the one calc.gearbox.shock_factor
    chooses (E4, with its boundary tolerance)."""
    k = int(SHOCK_FACTORS.band(zh, "Z_h"))
    return (
        r"\calcstep{Shock factor}{$f_{s}$, from the source's table}" "\n"
        rf"\[ f_{{s}} = {SHOCK_FACTORS.factors[k]:g} \quad\text{{for }} {SHOCK_FACTORS.text(k, latex=True)} "
        rf"\quad (Z_h = {sig(zh.m_as(SHOCK_FACTORS.unit))}) \]" "\n"
        r"\calcref{source, S5 calculation 1; errata E4 (the higher factor at a band boundary)}"
    )


def _checks_table(candidate: dict, caption: str) -> str:
    """Required, rated, utilization and verdict of each check of one candidate; checks of the
    other operating mode (gearboxes) in grey, for information."""
    modes = any(k.get("mode") for k in candidate["checks"])
    rows = []
    for k in candidate["checks"]:
        grey = "" if k.get("governs", True) else r"\color{infogrey}"
        name = _text_math(k["criterion"]) if k.get("criterion") else latex_escape(k["name"])
        cells = [grey + name] + ([grey + latex_escape(k.get("mode", ""))] if modes else [])
        cells += [grey + _q(k["required"]), grey + _q(k["rated"]), grey + _util(k["utilization"]),
                  grey + _verdict(k["passes"]) + ("" if k.get("governs", True) else r"{} \footnotesize(for information)")]
        rows.append(cells)
    header = ["Criterion"] + (["Mode"] if modes else []) + ["Required", "Rated", "Utilization", "Verdict"]
    return table("@{}l " + ("l " if modes else "") + "r r r l@{}", header, rows, caption=latex_escape(caption),
                 note="Utilization = required / rated; a check passes at 1.00 or below.")


def _requirement_table(checks: list, caption: str) -> str:
    """Checks of a value reached against a limit the case requires (``value <= required``)."""
    rows = [[prose(k["criterion"].replace("_", " ")), _q(k["value"]), _q(k["required"]), _util(k["utilization"]), _verdict(k["passes"])]
            for k in checks]
    return table(r"@{}l r r r l@{}", ["Criterion", "Value", "Required", "Utilization", "Verdict"], rows,
                 caption=latex_escape(caption), note="Utilization = value / required; a check passes at 1.00 or below.")


def _candidates_table(section: dict, caption: str, inertia: bool = False) -> str:
    checks = [k for c in section["candidates"] for k in c.get("checks", [])]
    names = list(dict.fromkeys(k["name"] for k in checks))  # every check any candidate has, in order
    governs = {k["name"]: k.get("governs", True) for k in checks}
    header = ["Part"] + [
        (r"\color{infogrey}" if not governs[n] else "") + _text_math(n) for n in names
    ] + ([r"$\lambda$"] if inertia else []) + ["Verdict"]
    rows = []
    for c in section["candidates"]:
        by = {k["name"]: k for k in c.get("checks", [])}
        cells = [latex_escape(c.get("part", ""))]
        cells += [(r"\color{infogrey}" if not governs[n] else "") + _util(by[n]["utilization"]) if n in by else "–" for n in names]
        if inertia:
            cells.append("–" if c.get("inertia_ratio") is None else f"{c['inertia_ratio']:.2f}")
        cells.append(_verdict(c.get("passes", False)) + (r"{} \footnotesize(chosen)" if c.get("part") == section.get("selected") else ""))
        rows.append(cells)
    cols = "@{}l " + "r " * (len(names) + (1 if inertia else 0)) + "l@{}"
    criteria = {k["name"]: k.get("criterion") for c in section["candidates"] for k in c.get("checks", [])}
    note = "Checks: " + "; ".join(_text_math(criteria[n]) if criteria.get(n) else latex_escape(n) for n in names) + "."
    if inertia:
        note += rf" ${inertia_ratio.latex()}$, load to motor inertia ratio (E6)."
    return table(cols, header, rows, caption=caption, note=note)


#: What each key of the further sections means, for the inputs table: (symbol name in the
#: section's formulas, or None; description when there is no symbol).
SECTION_KEYS = {
    "coupling": {
        "catalog": (None, "coupling catalog"), "type": (None, "coupling type"), "part": (None, "coupling part to check"),
        "side": (None, "where the coupling sits (input: between motor and gearbox)"),
        "accel_torque": ("M_a", ""), "drive_inertia": ("J_drive", ""), "load_inertia": ("J_load", ""),
        "service_factor": ("S_A", ""), "temperature": (None, "operating temperature (elastomer couplings, E9)"),
        "excitation_frequency": ("f_er", ""), "speed": (None, "speed of the coupling"),
        "shaft_1": (None, "shaft 1 with its fit"), "shaft_2": (None, "shaft 2 with its fit"),
        "disengagement_torque": (None, "disengagement torque T_A (safety couplings, E10)"),
        "shaft_distance": ("A", ""),
    },
    "accuracy": {
        "applied_torque": ("T", ""), "nominal_torque": (None, "nominal torque for the 3 % rule (E13)"),
        "positions": (None, "file of measured positions"),
        "required_positioning_accuracy": (None, "positioning accuracy required"),
        "required_repeatability": (None, "repeatability required"),
    },
}


def _section_symbols(name: str) -> dict:
    """The symbols of a further section's formulas, by name."""
    if name == "coupling":
        from . import coupling as m

        formulas = (m.M_N, m.f_e_min, m.Z)
    else:
        from . import accuracy as m

        formulas = (m.lost_motion,)
    return {s.name: s for f in formulas for s in (f.result, *f.inputs)}


def _value_unit(value) -> tuple[str, str]:
    """A value as written in the case, split into number and unit where it is a quantity."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return f"{value:g}", "–"
    m = NUMBER.match(value) if isinstance(value, str) else None
    if m and m.group(2) and re.fullmatch(r"[A-Za-z°][A-Za-z0-9*/()^.-]*", m.group(2)):  # "19 mm k6" stays whole
        return latex_escape(m.group(1)), latex_escape(pretty_unit(m.group(2)))
    return latex_escape(value), "–"


def _raw_section_tables(name: str, raw: dict, derived: dict | None = None) -> str:
    """A further section of the case as its inputs: symbol, value, unit, description, key; its
    arrays of tables (the members of an accuracy chain) as one row each, figures as written.
    ``derived`` holds inputs the case left out and the package took from the rest of the case."""
    symbols, known = _section_symbols(name), SECTION_KEYS.get(name, {})
    rows, members = [], []
    derived = derived or {}
    for key, v in {**raw, **derived}.items():
        if isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            members += [(key, k, x) for k, x in enumerate(v, start=1)]
            continue
        sym_name, desc = known.get(key, (None, ""))
        sym = symbols.get(sym_name)
        value, unit = _value_unit(v)
        where = rf"\texttt{{{latex_escape(f'{name}.{key}')}}}" + (r"\textsuperscript{\dag}" if key in derived else "")
        rows.append([f"${sym.latex}$" if sym else "–", value, unit, latex_escape(sym.description if sym else desc), where])
    out = [rf"\subsection*{{{latex_escape(name.capitalize())}}}"]
    if rows:
        note = (r"\textsuperscript{\dag} Not in the case file: taken from the rest of the case (a coupling between "
                r"motor and gearbox, E8); the calculations show how.") if derived else ""
        out.append(table(r"@{}l r l p{0.38\linewidth} l@{}", ["Symbol", "Value", "Unit", "Description", "Case key"], rows, note=note))
    if members:
        body = []
        for key, k, x in members:
            what = ", ".join(f"{f} = {x[f]}" for f in x if f not in ("name", "side", "part"))
            body.append([rf"\texttt{{\footnotesize {latex_escape(f'{name}.{key}[{k}]')}}}", latex_escape(x.get("name") or x.get("part", "")),
                         latex_escape(x.get("side", "output" if "part" in x else "")), latex_escape(what)])
        out.append(table(r"@{}l l l p{0.42\linewidth}@{}", ["Case key", "Member", "Side", "Figures as written"], body,
                         caption=latex_escape(f"Members of the {name} chain, drive to load")))
    return "\n".join(out)


def build_report(case_path) -> Report:
    """Read and evaluate a case and collect its report; a case that cannot be evaluated gives a
    report whose verdict is FAIL with the reason (never an exception for bad input)."""
    path = Path(case_path)
    report = Report(
        path=path,
        title=path.stem,
        built=datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        commit=git_commit(),
    )
    if path.is_file():
        report.files.append(("Case file", display_path(path), sha256(path)))
    try:
        case = read_case(path)
    except CalcError as exc:
        report.error = str(exc)
        return report
    return report_of(case, report)


def report_of(case: Case, report: Report | None = None) -> Report:
    """Evaluate a case already read (the design review passes changed copies) into ``report``
    (a new one, without build date and commit, when not given)."""
    if report is None:
        report = Report(path=case.path, title=case.title, built="", commit="")
    report.case, report.title = case, case.title
    try:
        evaluated = evaluate(case)
        results = evaluated.to_json(candidates=None)
    except CalcError as exc:
        report.error = str(exc)
        return report
    report.evaluated, report.results = evaluated, results
    if "gearbox" in evaluated.sections:
        report.selection = evaluated["gearbox"].selection
    if "coupling" in evaluated.sections:
        report.coupling = (evaluated["coupling"].inputs, evaluated["coupling"].selection)
    if "accuracy" in evaluated.sections:
        report.accuracy = (evaluated["accuracy"].inputs, evaluated["accuracy"].accuracy)
    for name in ("gearbox", *SECTIONS):
        s = results.get(name)
        if s and s.get("catalog") and s.get("catalog_sha256"):
            report.files.append((f"{name.capitalize()} catalog", s["catalog"], s["catalog_sha256"]))
    return report
