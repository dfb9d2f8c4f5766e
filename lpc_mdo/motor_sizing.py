"""
Size each motor design to its margins at the loads of a trimmed problem.

A motor design (one per lift-rotor pair, one for the pusher; the rows of the ``motor_length`` and
``motor_rated_current`` design variables) is sized as a designer sizes it for its worst
operating point, with the limits of the vehicle file's ``[constraints]``:

1. its stack length L, the smallest at which its torque margin T_max/T_em - 1 (the KS over its
   motors and conditions that the problem constrains) reaches ``min_torque_margin`` plus
   :data:`TRIM_ALLOWANCE` (another trim of the one-rotor-out cases may read less). The peak
   torque grows with the motor's size (docs theory/motor 'Sizing'); the winding is held at its
   largest current meanwhile, so that T_max is the peak torque T_pk, and T_pk is sized
   (1 - ln(2)/k)^-1 above its share, the largest amount by which the smooth minimum T_max of
   T_pk and the voltage-limited torque T_lim falls below T_pk (k its sharpness,
   :data:`~lpc_mdo.components.motor.efficiency.SMOOTH_MIN_SHARPNESS`): so that step 3 can wind
   the motor with T_lim near T_pk;
2. the lift designs' lengths then scaled together (the smallest scale, :func:`_smallest_scale`)
   until the hover and one-rotor-out control reserve (the roll and pitch acceleration the lift
   rotors can add within their motors' torque, ``min_control_acceleration``) is met, where the
   torque margins alone leave it short;
3. its winding, the rated current I_w that sets its turns per phase: the smallest at which its
   voltage margin (KS) reaches ``min_voltage_margin`` and its voltage-limited torque T_lim stays
   ``min_torque_margin`` above every operating point's torque (docs
   theory/motor 'Winding for the bus'), rounded up to a whole ampere. The smallest, because the
   inverters and cables are rated for the current (docs theory/weights 'Power electronics and
   cables'); the lift windings are raised together if the control reserve needs it;
4. its length again, to the torque margin at that winding (shorter where the voltage margin
   set the winding and left T_lim well above T_pk), where the winding's margins and the control
   reserve still hold at the new length (not where the control reserve set the length).

Each step is a root-bracketing search (regula falsi, :func:`_smallest`) within the design
variables' bounds on model runs
at the problem's trimmed state: the motors change no rotor load, so the trim's forces stay and
only the masses move (the caller re-trims: :func:`lpc_mdo.sizing.size_vehicle`). A design whose
margin its upper bound cannot reach is a :class:`MotorSizingError` naming it.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import openmdao.api as om

from lpc_mdo.components.motor.efficiency import SMOOTH_MIN_SHARPNESS
from lpc_mdo.groups.weights import motor_group_indices
from lpc_mdo.vehicle.condition_contract import condition_kind

__all__ = [
    "MotorSizing",
    "MotorSizingError",
    "control_ratio",
    "design_labels",
    "motor_margins",
    "size_motors",
]

#: How far above its limit a sized length leaves the torque margin (0.0005: 0.05 % of the peak
#: torque, 0.02 % of the length) and the control reserve its ratio to the required acceleration.
TORQUE_MARGIN_TOLERANCE = 5e-4
CONTROL_TOLERANCE = 1e-3
#: How far above ``min_torque_margin`` the motors are sized. The one-rotor-out trims are not
#: unique (seven rotor speeds for five rows), so another trim of the same design splits the
#: torques a little differently: ``lpc-mdo analyze`` of the reference, re-trimmed from the file's
#: speeds, read 0.0999 where the sizing had left 0.1000-0.1005 (2026-12-07). Sized 1e-3 above
#: the limit (about 0.1 mm of stack), a design holds its margin under those trims.
TRIM_ALLOWANCE = 1e-3
#: The slack of a search point where the model fails (a stalled motor: no torque to spare).
STALLED = -1.0
LENGTH = "motor_length"
CURRENT = "motor_rated_current"


class MotorSizingError(om.AnalysisError):
    """A motor design cannot meet its margins within its design variable's bounds."""


@dataclasses.dataclass
class MotorSizing:
    """Sized motor designs, one entry per design (lift pairs, then the pusher)."""

    labels: list
    length: np.ndarray
    rated_current: np.ndarray
    torque_margin: np.ndarray
    voltage_margin: np.ndarray
    control_ratio: float
    sets_length: list


def design_labels(vehicle):
    """Return one label per motor design: the lift rotors it drives, or 'pusher'."""
    groups = motor_group_indices(vehicle)
    labels = []
    for g in range(max(groups) + 1):
        if g == vehicle.pusher.pair:
            labels.append("pusher")
        else:
            names = [r.name for r in vehicle.lift_rotors if r.pair == g]
            labels.append("lift " + " + ".join(names))
    return labels


def motor_margins(prob, vehicle):
    """
    Return per motor design the least torque, voltage and voltage-torque margins.

    The torque and voltage margins are the KS aggregates over each motor's conditions that the
    problem constrains (``lift_motor_torque_margin``, ...); the voltage-torque margin
    T_lim/T_em - 1 is the least over the operating points of the problem's conditions.
    """
    groups = np.asarray(motor_group_indices(vehicle))
    num_lift = len(vehicle.lift_rotors)
    rows = {"lift": groups[:num_lift], "pusher": groups[num_lift:]}
    size = groups.max() + 1
    torque, voltage, limit = (np.full(size, np.inf) for _ in range(3))
    for prefix, where in rows.items():
        np.minimum.at(torque, where, np.ravel(prob.get_val(f"{prefix}_motor_torque_margin")))
        np.minimum.at(voltage, where, np.ravel(prob.get_val(f"{prefix}_motor_voltage_margin")))
    for condition in prob.model.conditions:
        for prefix, motors in condition_kind(condition.kind).motor_sets(vehicle, condition).items():
            path = f"{condition.name}.{prefix}_motors.voltage_torque_margin"
            where = rows[prefix][list(motors)] if prefix == "lift" else rows[prefix]
            np.minimum.at(limit, where, np.ravel(prob.get_val(path)))
    return torque, voltage, limit


def control_ratio(prob, vehicle):
    """Return the least control acceleration over the required one (hover, OEI; inf: none)."""
    required = np.asarray(vehicle.constraints.min_control_acceleration, dtype=float)
    axes = np.flatnonzero(required > 0.0)
    ratio = np.inf
    for condition in prob.model.conditions:
        if condition.kind in ("hover", "oei") and axes.size:
            got = np.ravel(prob.get_val(f"{condition.name}.control_acceleration", "rad/s**2"))
            ratio = min(ratio, float(np.min(got[axes] / required[axes])))
    return ratio


def _smallest(slack, lower, upper, tolerance, guess=None):
    """
    Per entry, the smallest x in [lower, upper] with slack(x) >= 0 (slack increasing in x).

    Regula falsi with the Illinois modification in log x (Dahlquist and Bjorck, Numerical
    Methods, 1974, sec. 6.2), all entries at once: each run of ``slack`` evaluates every entry
    (entries are independent). Stops where 0 <= slack <= ``tolerance`` or the bracket is within
    1e-5 in log x; returns the feasible end and its slack (negative where even the upper bound is
    not feasible). A ``guess`` brackets within 1 % of it first, and widens by factors 1.02,
    1.02^2, 1.02^4, ... towards the bounds where that does not bracket.

    A model run that fails (``om.AnalysisError``: a motor too small to balance its load stalls,
    docs theory/motor 'Operating point') is repeated entry by entry, the others at the feasible
    end; an entry that fails alone takes the slack :data:`STALLED`.
    """

    def evaluate(x, safe):
        try:
            return slack(x)
        except om.AnalysisError:
            f = np.empty_like(x)
            for i in range(x.size):
                y = safe.copy()
                y[i] = x[i]
                try:
                    f[i] = slack(y)[i]
                except om.AnalysisError:
                    f[i] = STALLED
            return f

    if guess is None:
        x_lo, x_hi = lower.copy(), upper.copy()
    else:
        x_lo, x_hi = np.maximum(lower, guess / 1.01), np.minimum(upper, guess * 1.01)
    f_hi = evaluate(x_hi, upper)
    f_lo = evaluate(x_lo, np.where(f_hi >= 0.0, x_hi, upper))
    factor = 1.02
    for _ in range(20):  # widen by growing factors towards the bounds until bracketed
        widen_up = (f_hi < 0.0) & (x_hi < upper)
        widen_down = (f_lo >= 0.0) & (x_lo > lower)
        if not np.any(widen_up | widen_down):
            break
        x_w = np.where(
            widen_up,
            np.minimum(upper, factor * x_hi),
            np.where(widen_down, np.maximum(lower, x_lo / factor), x_hi),
        )
        factor *= factor
        f_w = evaluate(x_w, np.where(widen_up, upper, x_hi))
        x_lo, f_lo = np.where(widen_up, x_hi, x_lo), np.where(widen_up, f_hi, f_lo)
        x_hi, f_hi = np.where(widen_up, x_w, x_hi), np.where(widen_up, f_w, f_hi)
        x_hi, f_hi = np.where(widen_down, x_lo, x_hi), np.where(widen_down, f_lo, f_hi)
        x_lo, f_lo = np.where(widen_down, x_w, x_lo), np.where(widen_down, f_w, f_lo)
    lo, hi = np.log(x_lo), np.log(x_hi)
    side = np.zeros(lo.shape)
    g_hi = f_hi.copy()  # the slack at the feasible end (f_hi: the one Illinois may halve)
    for _ in range(40):
        done = (f_lo >= 0.0) | (g_hi <= tolerance) | (hi - lo < 1e-5)
        if np.all(done):
            break
        x = np.where(done, hi, hi - f_hi * (hi - lo) / np.where(done, 1.0, f_hi - f_lo))
        x = np.clip(x, lo + 1e-3 * (hi - lo), hi - 1e-3 * (hi - lo))
        f = np.where(done, f_hi, evaluate(np.exp(x), np.exp(hi)))
        up = ~done & (f >= 0.0)
        down = ~done & (f < 0.0)
        # Illinois: halve the value kept at the end that stays a second time running.
        f_lo = np.where(up & (side > 0), 0.5 * f_lo, f_lo)
        f_hi = np.where(down & (side < 0), 0.5 * f_hi, f_hi)
        hi, f_hi, g_hi = np.where(up, x, hi), np.where(up, f, f_hi), np.where(up, f, g_hi)
        lo, f_lo = np.where(down, x, lo), np.where(down, f, f_lo)
        side = np.where(up, 1.0, np.where(down, -1.0, side))
    return np.where(f_lo >= 0.0, np.exp(lo), np.exp(hi)), np.where(f_lo >= 0.0, f_lo, g_hi)


def size_motors(prob, vehicle, guess=None):
    """
    Size the motor designs of a trimmed problem to their margins (module docstring).

    The problem must hold the conditions that load the motors (hover, one rotor out,
    transition, climb, cruise, descent), trimmed. Leaves the sized motors set in the problem
    (after a final model run) and returns them. ``guess``: {"motor_length": ...,
    "motor_rated_current": ...} near the answer (a previous sizing), which saves model runs.

    Raises
    ------
    MotorSizingError
        When a design's margin is not reached at its design variable's upper bound.
    """
    limits = vehicle.constraints
    labels = design_labels(vehicle)
    dvs = vehicle.design_variables
    lower, upper = (
        {name: np.array(getattr(dvs[name], f"{end}_array"), float) for name in (LENGTH, CURRENT)}
        for end in ("lower", "upper")
    )
    lift = np.array([label != "pusher" for label in labels])
    guess = guess or {}

    last = {}

    def run(length, current):
        """Return the margins at these motors (the last run's if the motors are the same)."""
        key = (np.asarray(length).tobytes(), np.asarray(current).tobytes())
        if last.get("key") != key:
            prob.set_val(LENGTH, length, units="m")
            prob.set_val(CURRENT, current, units="A")
            prob.run_model()
            last.update(key=key, margins=motor_margins(prob, vehicle))
            last["control"] = control_ratio(prob, vehicle)
        return last["margins"]

    def control_slack(length, current):
        run(length, current)
        return np.array([last["control"] - 1.0])

    # 1. Lengths to the torque margin, wound for the largest current (T_lim not binding).
    loose = upper[CURRENT]
    floor = limits.min_torque_margin + TRIM_ALLOWANCE
    target = (1.0 + floor) / (1.0 - math.log(2.0) / SMOOTH_MIN_SHARPNESS) - 1.0
    length, slack = _smallest(
        lambda x: run(x, loose)[0] - target,
        lower[LENGTH],
        upper[LENGTH],
        TORQUE_MARGIN_TOLERANCE,
        guess.get(LENGTH),
    )
    if np.any(slack < 0.0):
        g = int(np.argmin(slack))
        raise MotorSizingError(
            f"motor design '{labels[g]}': torque margin {slack[g] + target:.3f} at its largest "
            f"{LENGTH} ({upper[LENGTH][g]:g} m) against constraints.min_torque_margin "
            f"{limits.min_torque_margin:g}; allowed: a larger upper bound of "
            f"[design_variables.{LENGTH}], or rotors that need less torque"
        )
    sets_length = ["torque margin"] * len(labels)

    # 2. Lift lengths scaled together for the control reserve, where it is short.
    if control_slack(length, loose)[0] < 0.0:
        largest = float(np.min(upper[LENGTH][lift] / length[lift]))
        scale, slack = _smallest_scale(
            lambda k: control_slack(_scaled(length, lift, k), loose)[0], largest
        )
        if slack < 0.0:
            raise MotorSizingError(
                "the lift motors cannot give the control reserve "
                f"(constraints.min_control_acceleration {list(limits.min_control_acceleration)} "
                f"rad/s^2) within the upper bounds of [design_variables.{LENGTH}]; allowed: "
                "larger bounds, or a smaller required acceleration"
            )
        length = _scaled(length, lift, scale)
        sets_length = [
            "control reserve" if f else s for f, s in zip(lift, sets_length, strict=True)
        ]

    # 3. Windings: the least current that keeps the voltage and torque margins.
    def winding_slack(length, current):
        _, voltage, limit = run(length, current)
        return np.minimum(voltage - limits.min_voltage_margin, limit - floor)

    current, slack = _smallest(
        lambda x: winding_slack(length, x),
        lower[CURRENT],
        upper[CURRENT],
        1e-3,
        guess.get(CURRENT),
    )
    if np.any(slack < 0.0):
        g = int(np.argmin(slack))
        raise MotorSizingError(
            f"motor design '{labels[g]}': no winding up to the {CURRENT} upper bound "
            f"{upper[CURRENT][g]:g} A keeps it within the voltage limit "
            f"({vehicle.motor.voltage_limit:g} V) with its torque margin; allowed: a larger "
            f"upper bound of [design_variables.{CURRENT}], or a higher motor.voltage_limit"
        )
    current = np.ceil(current)
    if control_slack(length, current)[0] < 0.0:
        scale, _ = _smallest_scale(
            lambda k: control_slack(length, _scaled(current, lift, k))[0],
            float(np.min(upper[CURRENT][lift] / current[lift])),
        )
        current = np.ceil(_scaled(current, lift, scale))
    # 4. The length to the torque margin at that winding, where the winding still holds there.
    shorter, _ = _smallest(
        lambda x: run(x, current)[0] - floor,
        lower[LENGTH],
        upper[LENGTH],
        TORQUE_MARGIN_TOLERANCE,
        length,
    )
    fits = (winding_slack(shorter, current) >= 0.0) & (run(shorter, current)[0] >= floor)
    # ... and not where the control reserve set the length, nor if it leaves the reserve short
    fits &= np.array([reason != "control reserve" for reason in sets_length])
    if control_slack(np.where(fits, shorter, length), current)[0] >= 0.0:
        length = np.where(fits, shorter, length)
    torque, voltage, _ = run(length, current)
    return MotorSizing(
        labels=labels,
        length=length,
        rated_current=current,
        torque_margin=torque,
        voltage_margin=voltage,
        control_ratio=last["control"],
        sets_length=sets_length,
    )


def _smallest_scale(slack, largest, step=1.05):
    """
    Return the smallest scale k in [1, largest] with slack(k) >= 0 and its slack (< 0: none).

    The control reserve is not monotonic in the lift motors' size: a longer motor gives more
    torque but adds mass and roll inertia at the booms, and past some length the reserve falls.
    So the scales are scanned up from 1 by ``step`` to the first feasible one (or ``largest``),
    and the root is found between it and the last infeasible one (:func:`_smallest`).
    """
    low, k = 1.0, 1.0
    while True:
        k = min(k * step, largest)
        found = slack(k)
        if found >= 0.0 or k >= largest:
            break
        low = k
    if found < 0.0:
        return k, found
    scale, value = _smallest(
        lambda x: np.array([slack(x[0])]), np.array([low]), np.array([k]), CONTROL_TOLERANCE
    )
    return float(scale[0]), float(value[0])


def _scaled(values, rows, factor):
    return np.where(rows, values * factor, values)
