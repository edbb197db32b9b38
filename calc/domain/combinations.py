"""Every motor with every gearbox at once: the motor torque's peak and RMS through each pair from a
few moments of the cycle, exactly, without a pass over the samples per pair.

Through a gearbox of ratio ``i`` and efficiency ``η``, with ``J = J_motor + J_1`` on the motor
shaft, the motor torque of sample ``k`` is (:data:`calc.domain.motor.T_1_drive`, :data:`calc.domain.motor.T_1_back`)

* driving (``T_2 · ω_2 >= 0``): ``T_1k = J · i · α_2k + T_2k / (i · η) = (T_2k + x_D · α_2k) / (i · η)``,
  ``x_D = J · i² · η``;
* driven back: ``T_1k = J · i · α_2k + T_2k · η / i = (T_2k + x_B · α_2k) · η / i``, ``x_B = J · i² / η``.

Which samples drive depends on the load alone, not on the pair. So

* the RMS (:data:`calc.domain.motor.T_1rms`) is a quadratic form in the pair's figures,
  ``T_1rms² · Σ t_k = (J · i)² · A + 2 · J · (S_D / η + S_B · η) + Q_D / (i · η)² + Q_B · (η / i)²``,
  with five sums over the samples taken once: ``A = Σ t_k α_2k²``, ``S = Σ t_k α_2k T_2k`` and
  ``Q = Σ t_k T_2k²`` over the driving (D) and driven-back (B) samples;
* the peak ``max_k |T_1k|`` is ``max(E_D(x_D) / (i · η), E_B(x_B) · η / i)`` where
  ``E(x) = max_k |T_2k + x · α_2k|`` over a set of samples: the upper envelope of the lines
  ``±(T_2k + x · α_2k)``, a convex function of ``x`` taken once per set (:class:`Envelope`) and
  read at each pair's ``x`` by a binary search.

So a cycle of N samples costs O(N log N) once, and each pair O(log N) (:func:`motor_torques`), the
same numbers as :func:`calc.domain.motor.motor_load` per pair (the tests hold them equal).

:func:`search` checks every (gearbox row, motor) pair of a cycle and picks one by :data:`RULE`.
Values are plain floats in SI units (N·m, rad/s², kg·m², s, rad/s), as the catalogs hold them.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ..core.checks import within_rating
from .gearbox import inertia_ratio

#: How :func:`search` picks a pair: the one rule by which a case's evaluation takes its motor and gearbox.
RULE = ("passing pairs first: the smallest adequate motor (lowest rated torque, a tie to the lower rotor inertia), "
        "for it the adequate gearbox the gearbox ranking puts first (published rows, then the smallest governing "
        "rating, then margin), then the lower RMS utilization of the motor and the lower ratio; where no pair "
        "passes, the pair closest to passing")


@dataclass(frozen=True)
class Envelope:
    """``E(x) = max_k |T_k + x · α_k|`` for ``x >= 0`` over a set of samples: the lines of the
    upper envelope, by increasing slope, and the ``x`` where each next one takes over.

    Parameters
    ----------
    intercepts : numpy.ndarray [N·m]
        ``T_k`` of each line of the envelope.
    slopes : numpy.ndarray [rad/s²]
        ``α_k`` of each line, increasing.
    breaks : numpy.ndarray
        The ``x`` where each next line takes over (one fewer than the lines), increasing.
    """

    intercepts: np.ndarray
    slopes: np.ndarray
    breaks: np.ndarray  # len(lines) - 1, increasing

    @classmethod
    def of(cls, T, alpha) -> "Envelope":
        """The envelope of the lines ``±(T_k + x · α_k)`` (an empty set gives E = 0).

        Parameters
        ----------
        T : numpy.ndarray [N·m]
            The samples' output torques.
        alpha : numpy.ndarray [rad/s²]
            The samples' output accelerations.

        Returns
        -------
        Envelope
            Its lines and breaks.
        """
        b = np.concatenate((T, -T, [0.0]))  # the zero line: no sample, no torque
        a = np.concatenate((alpha, -alpha, [0.0]))
        # Of lines of one slope only the highest counts; a trapezoidal cycle has few slopes.
        order = np.lexsort((-b, a))
        a, b = a[order], b[order]
        first = np.concatenate(([True], a[1:] != a[:-1]))
        a, b = a[first], b[first]
        # Upper envelope on x >= 0 (the convex hull trick): lines by increasing slope, each kept
        # while it is highest somewhere to the right of where the previous one is overtaken.
        keep_a, keep_b, starts = [], [], []
        for slope, intercept in zip(a.tolist(), b.tolist()):
            while keep_a:
                # where this line overtakes the last kept one
                x = (keep_b[-1] - intercept) / (slope - keep_a[-1])
                if x <= starts[-1]:
                    keep_a.pop(), keep_b.pop(), starts.pop()
                    continue
                break
            if keep_a:
                starts.append(max(x, 0.0))
            else:
                starts.append(0.0)
            keep_a.append(slope)
            keep_b.append(intercept)
        # a line that only takes over before x = 0 is dropped: the first kept line holds at 0
        starts_arr = np.asarray(starts)
        last_at_zero = np.flatnonzero(starts_arr <= 0.0)[-1]
        return cls(np.asarray(keep_b[last_at_zero:]), np.asarray(keep_a[last_at_zero:]), starts_arr[last_at_zero + 1:])

    def __call__(self, x):
        """``E`` at ``x`` (an array, each >= 0)."""
        if not len(self.breaks):  # one line (every sample of one acceleration): nothing to search
            return self.intercepts[0] + x * self.slopes[0]
        k = np.searchsorted(self.breaks, x, side="right")
        return self.intercepts[k] + x * self.slopes[k]


@dataclass(frozen=True)
class CycleMoments:
    """What the motor torque through any gearbox with any motor needs of a sampled cycle at the
    gearbox output: its duration, the five sums and the two envelopes of the module's docstring.

    Parameters
    ----------
    duration : float [s]
        ``Σ t_k``.
    A : float [rad²/s³]
        ``Σ t_k α_2k²``.
    S_D, S_B : float [N·m·rad/s]
        ``Σ t_k α_2k T_2k`` over the driving and the driven-back samples.
    Q_D, Q_B : float [N²·m²·s]
        ``Σ t_k T_2k²`` over the driving and the driven-back samples.
    drive, back : Envelope
        The envelopes of the driving and the driven-back samples.
    """

    duration: float
    A: float
    S_D: float
    S_B: float
    Q_D: float
    Q_B: float
    drive: Envelope
    back: Envelope

    @classmethod
    def of(cls, dt, torque, speed, alpha) -> "CycleMoments":
        """The moments of a sampled cycle (floats, samples on the one axis).

        Parameters
        ----------
        dt : numpy.ndarray [s]
            Each sample's duration.
        torque : numpy.ndarray [N·m]
            Its output torque.
        speed : numpy.ndarray [rad/s]
            Its output speed.
        alpha : numpy.ndarray [rad/s²]
            Its output acceleration.

        Returns
        -------
        CycleMoments
            The sums and envelopes.
        """
        dt, T, w, a = (np.asarray(x, float) for x in (dt, torque, speed, alpha))
        back = T * w < 0  # calc.domain.motor.driven_back: a hold at rest drives
        d = ~back
        return cls(
            float(dt.sum()), float(np.dot(dt, a * a)),
            float(np.dot(dt[d], a[d] * T[d])), float(np.dot(dt[back], a[back] * T[back])),
            float(np.dot(dt[d], T[d] * T[d])), float(np.dot(dt[back], T[back] * T[back])),
            Envelope.of(T[d], a[d]), Envelope.of(T[back], a[back]),
        )


def motor_torques(m: CycleMoments, i, eta, J) -> tuple[np.ndarray, np.ndarray]:
    """The peak ``max |T_1|`` and the RMS of the motor torque through gearboxes of ratio ``i`` and
    efficiency ``eta`` with ``J = J_motor + J_1`` on the motor shaft [kg·m²]; the arguments
    broadcast (a column of gearboxes against a row of motors gives their table).

    The example's cycle without the rotor term (i = 10, η = 0.97; :func:`calc.domain.motor.motor_load`):
    peak 60 / 9.7 = 6.186 N·m, RMS 2.647 N·m.

    Parameters
    ----------
    m : CycleMoments
        The cycle's moments.
    i : numpy.ndarray [1]
        The gearboxes' ratios.
    eta : numpy.ndarray [1]
        Their efficiencies.
    J : numpy.ndarray [kg·m²]
        ``J_motor + J_1``.

    Returns
    -------
    tuple of numpy.ndarray
        The peak and the RMS motor torque [N·m], broadcast.

    Examples
    --------
    >>> m = CycleMoments.of([0.2, 0.6, 0.2, 1.0], [60.0, 20.0, -45.0, 0.0], [15.7, 31.4, 15.7, 0.0],
    ...                     [0.0, 0.0, 0.0, 0.0])
    >>> [round(float(x), 4) for x in motor_torques(m, 10.0, 0.97, 0.0)]
    [6.1856, 2.647]
    """
    i, eta, J = np.broadcast_arrays(*(np.asarray(x, float) for x in (i, eta, J)))
    return _torques(m, _through(m, i, eta), J)


def _through(m: CycleMoments, i, eta) -> dict:
    """The terms of :func:`motor_torques` of the gearboxes alone: taken once, then for every motor."""
    return {"i": i, "eta": eta, "i_eta": i * eta, "S": m.S_D / eta + m.S_B * eta, "Q_D": m.Q_D / (i * eta) ** 2,
            "Q_B": m.Q_B * (eta / i) ** 2}


def _torques(m: CycleMoments, g: dict, J) -> tuple[np.ndarray, np.ndarray]:
    """:func:`motor_torques` from the gearboxes' terms ``g`` (:func:`_through`) and ``J`` [kg·m²]."""
    i, eta, Ji = g["i"], g["eta"], J * g["i"]
    square = (Ji ** 2 * m.A + 2 * J * g["S"] + g["Q_D"] + g["Q_B"]) / m.duration
    rms = np.sqrt(np.maximum(square, 0.0))  # rounding may leave a zero RMS a hair below zero
    x = Ji * i
    peak = np.maximum(m.drive(x * eta) / g["i_eta"], m.back(x / eta) * eta / i)
    return peak, rms


@dataclass
class Combinations:
    """Every (gearbox row, motor) pair of :func:`search`: arrays of shape (gearbox rows, motors).

    Parameters
    ----------
    peak : numpy.ndarray [N·m]
        ``max |T_1|``.
    rms : numpy.ndarray [N·m]
        ``T_1rms``.
    utilization : numpy.ndarray [1]
        The highest of the pair's utilizations (gearbox and motor).
    feasible : numpy.ndarray of bool
        The pair passes.
    pick : tuple of int or None
        ``(gearbox row, motor)`` by :data:`RULE`; None where no pair is feasible.
    closest : tuple of int or None
        The pair closest to passing (lowest highest utilization) where none passes; else None.
    motors : numpy.ndarray of int or None
        The motor of each column, where the search screened some only (``first``); None: every motor,
        in their order.
    """

    peak: np.ndarray
    rms: np.ndarray
    utilization: np.ndarray
    feasible: np.ndarray
    pick: tuple[int, int] | None
    closest: tuple[int, int] | None = None
    motors: np.ndarray | None = None


def search(moments: CycleMoments, speeds: tuple, gearboxes: dict, motors: dict, inertia_limit: float,
           examine=None, first: bool = False, confirm=None) -> Combinations:
    """Check every pair of a gearbox row and a motor against the cycle, and pick one (:data:`RULE`).

    A pair is feasible where the gearbox passes, its ratings take the motor's peak torque, the motor's
    peak and RMS torque and its top speed ``n_2max · i`` (and, where ``motors`` gives ``rated_speed``, its
    mean speed ``n_2m · i``) are within the motor's ratings, and ``λ = (J_1 + J_L / i²) / J_motor``
    (:data:`calc.domain.gearbox.inertia_ratio`) is at most ``inertia_limit`` (E6). The peak is screened
    against the motor's ``M_max``; with ``examine``, the pairs of the motors in the rule's order are then
    examined in full (the peak torque the motor gives at each sample's speed, the gearbox's checks with
    that motor and its ranking), until a motor has a pair that passes (the pairs found failing are
    marked so, the motors after it are left screened). With ``confirm``, each pair that passes is then
    confirmed in the rule's order, and the first confirmed is the pick: a finite walk down one ordered
    list (a pair refused is marked failing; where none is confirmed, none is picked).

    Parameters
    ----------
    moments : CycleMoments
        The sampled cycle at the gearbox output.
    speeds : tuple of float [rad/s]
        The highest output speed ``n_2max`` and the mean output speed ``n_2m``.
    gearboxes : dict
        Arrays over the gearbox rows (each at its own ratio): ``i`` [1], ``eta`` [1], ``J_1`` [kg·m²] (with
        what else turns with the motor), ``passes`` (its governing checks that do not depend on the motor),
        ``peak_limit`` (the highest motor peak torque its ratings take, ``T_2B / (i · f_s · η)`` (E2) or
        ``T_2Not / i``, inf where no such check governs) [N·m], ``rank`` (its place in the gearbox ranking,
        lower first); and ``J_L``, the load's inertia at the output [kg·m²], a scalar.
    motors : dict
        Arrays over the motors: ``J`` [kg·m²], ``rated_torque`` [N·m], ``peak_torque`` [N·m],
        ``max_speed`` [rad/s], optionally ``rated_speed`` [rad/s].
    inertia_limit : float [1]
        The highest ``λ`` a pair may have: the case's ``[motor] max_inertia_ratio``.
    examine : callable, optional
        ``examine(motor, rows)`` -> ``(utilization, passes, rank)`` over those gearbox rows: the motor's
        peak utilization against its speed-torque characteristic [1] (NaN where not examined: it may
        stop at the first row of its ranking that passes), whether the gearbox passes its checks with
        that motor, and its place in the gearbox ranking with it (None: ``rank`` holds).
    first : bool
        Examine the motors one at a time in the rule's order and stop at the first that has a pair
        that passes, the arrays holding the motors up to it (the pick alone is wanted: a case's
        evaluation; screened :data:`SCREEN_PAIRS` pairs at a time); default False, every pair.
    confirm : callable, optional
        ``confirm(gearbox row, motor)`` -> bool: whether the pair, evaluated in full, passes (a case's
        evaluation: the coupling chosen with that motor counted); None: every pair that passes is taken.

    Returns
    -------
    Combinations
        Every pair's motor torques, utilization and feasibility, and the pick.
    """
    g = {k: np.asarray(v, float)[:, None] for k, v in gearboxes.items() if k != "J_L"}
    g["J_L"] = float(gearboxes["J_L"])
    mo = {k: np.asarray(v, float)[None, :] for k, v in motors.items()}
    terms = _row_terms(moments, speeds, g)
    if first:
        return _first(moments, terms, g, mo, inertia_limit, examine, confirm)
    columns = _screen(moments, terms, mo, inertia_limit)
    pick = _pick(columns.feasible, columns.utilization, columns.rms / mo["rated_torque"], g, mo, examine, confirm)
    columns.pick, columns.closest = pick, None if pick is not None else _closest(columns.utilization)
    return columns


def _row_terms(moments: CycleMoments, speeds: tuple, g: dict) -> dict:
    """What :func:`_screen` needs of the gearbox rows ``g`` alone, taken once for every motor."""
    top, mean = speeds
    # λ is the rows' (J_1 + J_L / i²) over each motor's J_motor: the rows' part once (J_motor = 1)
    return {**_through(moments, g["i"], g["eta"]), "J_1": g["J_1"], "peak_limit": g["peak_limit"],
            "passes": g["passes"] > 0, "top": top * g["i"], "mean": mean * g["i"],
            "lam": inertia_ratio.si(J_1=g["J_1"], J_L=g["J_L"], i=g["i"], J_motor=1.0)}


def _screen(moments: CycleMoments, terms: dict, mo: dict, inertia_limit: float) -> Combinations:
    """Every pair of the gearbox rows (a column each; their ``terms``, :func:`_row_terms`) and the motors ``mo``
    (a row each) screened, nothing picked."""
    peak, rms = _torques(moments, terms, terms["J_1"] + mo["J"])
    utilizations = [peak / mo["peak_torque"], rms / mo["rated_torque"], terms["top"] / mo["max_speed"],
                    mo["peak_torque"] / terms["peak_limit"], terms["lam"] / mo["J"] / inertia_limit]
    if "rated_speed" in mo:
        utilizations.append(terms["mean"] / mo["rated_speed"])
    utilization = functools.reduce(np.maximum, utilizations)  # NaN where any is: within no rating
    # every utilization within its rating is the highest within it (one comparison, not one per check)
    feasible = terms["passes"] & within_rating(utilization)
    return Combinations(peak, rms, utilization, feasible, None)


#: The most pairs the evaluation's search screens in one numpy pass: every motor at once against the few
#: rows a catalog has at a ratio, a few motors at a time against a large catalog's, so that its memory
#: and time stay those of the rows (100,000 rows x 184 motors at once took 1.2 GB).
SCREEN_PAIRS = 100_000


def _first(moments: CycleMoments, terms: dict, g: dict, mo: dict, inertia_limit: float, examine,
           confirm) -> Combinations:
    """:func:`search` with ``first``: the motors screened in the rule's order, as many at once as
    :data:`SCREEN_PAIRS` allows (one pass of numpy over their pairs), each examined in turn until one has
    a pair that passes; the arrays hold the motors up to it (:attr:`Combinations.motors`)."""
    order = np.lexsort((mo["J"][0], mo["rated_torque"][0]))
    ordered = {k: v[:, order] for k, v in mo.items()}
    step = max(1, SCREEN_PAIRS // max(len(g["i"]), 1))
    done, found, count = [], None, len(order)
    for start in range(0, len(order), step):
        part = {k: v[:, start:start + step] for k, v in ordered.items()}
        screened = _screen(moments, terms, part, inertia_limit)
        done.append(screened)
        share = screened.rms / part["rated_torque"]
        for j in range(screened.feasible.shape[1]):
            if not screened.feasible[:, j].any():
                continue  # no pair of it passes the screen: nothing to examine
            one, m = slice(j, j + 1), int(order[start + j])  # views: what examining it finds is marked in the arrays
            found = _pick(screened.feasible[:, one], screened.utilization[:, one], share[:, one], g,
                          {k: v[:, one] for k, v in part.items()},
                          None if examine is None else lambda _, rows, m=m: examine(m, rows),
                          None if confirm is None else lambda row, _, m=m: confirm(row, m))
            if found is not None:
                count = start + j + 1
                break
        if found is not None:
            break
    # joined motor by motor: a pass's columns of a large catalog's rows, transposed, are whole blocks of memory
    out = Combinations(*(np.concatenate([getattr(c, k).T for c in done])[:count].T
                         for k in ("peak", "rms", "utilization", "feasible")), None, motors=order[:count])
    if found is not None:
        out.pick = (found[0], count - 1)
    else:
        out.closest = _closest(out.utilization)
    return out


def _closest(utilization) -> tuple[int, int] | None:
    """The pair of the lowest highest utilization; None where there is no pair."""
    if not utilization.size:
        return None
    return tuple(int(k) for k in np.unravel_index(np.argmin(np.nan_to_num(utilization, nan=np.inf)),
                                                  utilization.shape))


def _pick(feasible, utilization, rms_share, g, mo, examine, confirm=None) -> tuple[int, int] | None:
    """The pair :data:`RULE` picks among the feasible ones, ``examine`` asked motor by motor and
    ``confirm`` pair by pair in the rule's order (``feasible`` and ``utilization`` updated where they are)."""
    motors = np.flatnonzero(feasible.any(axis=0))
    for m in motors[np.lexsort((mo["J"][0, motors], mo["rated_torque"][0, motors]))]:
        rows = np.flatnonzero(feasible[:, m])
        rank = g["rank"][rows, 0]
        if examine is not None:
            u, passes, found = examine(int(m), rows)
            u = np.asarray(u, float)
            utilization[rows, m] = np.fmax(utilization[rows, m], u)
            examined = ~np.isnan(u)
            fails = ~np.asarray(passes, bool) | (examined & ~within_rating(u))
            feasible[rows[fails], m] = False
            ok = examined & ~fails
            rows, rank = rows[ok], (rank if found is None else np.asarray(found, float))[ok]
        for k in np.lexsort((g["i"][rows, 0], rms_share[rows, m], rank)):
            if confirm is None or confirm(int(rows[k]), int(m)):
                return int(rows[k]), int(m)
            feasible[rows[k], m] = False
    return None
