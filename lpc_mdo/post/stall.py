"""Stall-speed check: the design's 1-g stall speed from its wing sections, next to its speeds.

Reads recorded values only (a case with ``get_val``, e.g. a case file's final case; a run
problem answers the same calls). For each wing-borne condition (kinds ``transition``,
``steady``, ``structural``) the model records the ratio of every wing strip's lift coefficient
to its section's maximum, ``wing_stall_ratio`` (docs theory/aerodynamics 'Section lift limit').

The stall speed from one condition
----------------------------------
The critical-section criterion: the wing stalls when its most loaded section reaches
kappa c_l,max (``constraints.wing_stall_lift_fraction``). In the linear range the sections'
c_l grow in proportion to the lattice's C_L (the additional loading; the basic loading of the
-0.5 deg twist is left out), so from a condition with lift coefficient C_L and largest ratio
r = max_j c_l,j / c_l,max,j:

    C_L,max = kappa C_L / r,        V_S = sqrt(2 W / (rho S C_L,max)),

with W the gross weight (1 g) and rho the condition's density. The section maximum depends on
the strip's Reynolds and Mach numbers, which at V_S are those of the condition times V_S / V:
r is re-evaluated there and V_S iterated to 1e-6 (a few steps: c_l,max varies slowly with Re).
The design's stall speed is that of the vehicle's cruise condition (clean wing, 1 g), given as
an equivalent airspeed V_S,EAS = V_S sqrt(rho / rho_0); each condition's equivalent airspeed
over it is its margin (the 1-g conditions' limit kappa / k^2 on r is V >= k V_S).
"""

import numpy as np

from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.core.constants import GRAVITY, SEA_LEVEL_DENSITY
from lpc_mdo.vehicle.condition_kinds import is_wing_load_case, wing_stall_limit

__all__ = ["WING_BORNE_KINDS", "format_stall_speed_check", "stall_speed", "stall_speed_rows"]

#: Condition kinds with a wing: the kinds that record ``wing_stall_ratio``.
WING_BORNE_KINDS = ("transition", "steady", "structural")
_TOLERANCE = 1e-6
_MAX_ITER = 50


def _value(source, name, units=None):
    value = source.get_val(name, units=units) if units else source.get_val(name)
    return np.asarray(value, dtype=float)


def stall_speed(source, vehicle, condition):
    """
    Return the 1-g stall speed of the design as seen from one wing-borne condition.

    Parameters
    ----------
    source : Case or om.Problem
        Anything with ``get_val`` that holds the condition's recorded outputs.
    vehicle : Vehicle
        The vehicle of the run (its wing airfoil and ``constraints.wing_stall_lift_fraction``).
    condition : str
        A condition of kind ``transition``, ``steady`` or ``structural``.

    Returns
    -------
    dict
        ``CL`` (the condition's lattice C_L), ``ratio`` (the largest section lift ratio at
        the condition, c_l / c_l,max or, in a push-over, c_l / c_l,min), ``CL_max``,
        ``stall_speed`` (m/s, true airspeed at the condition's density) and
        ``stall_speed_eas`` (m/s, equivalent airspeed); the speeds are NaN when the
        condition's wing carries no positive lift.
    """
    kappa = vehicle.constraints.wing_stall_lift_fraction
    ratio = _value(source, f"{condition}.wing_stall_ratio").ravel()
    positive = ratio[: ratio.size // 2]  # c_l / c_l,max; the second half is c_l / c_l,min
    cl = _value(source, f"{condition}.wing_sectional_cl").ravel()
    reynolds = _value(source, f"{condition}.vlm.wing_strip_flow.strip_reynolds").ravel()
    mach = _value(source, f"{condition}.vlm.wing_strip_flow.strip_mach").ravel()
    lift_coefficient = float(_value(source, f"{condition}.CL")[0])
    density = float(_value(source, f"{condition}.density", "kg/m**3")[0])
    speed = float(_value(source, f"{condition}.speed", "m/s")[0])
    area = float(_value(source, "wing_area", "m**2")[0])
    weight = float(_value(source, "gross_mass", "kg")[0]) * GRAVITY
    result = {"CL": lift_coefficient, "ratio": float(ratio.max())}
    nan = {"CL_max": np.nan, "stall_speed": np.nan, "stall_speed_eas": np.nan}
    if lift_coefficient <= 0.0 or positive.max() <= 0.0:
        return result | nan
    polar = get_polar(vehicle.wing.airfoil)
    v_stall = speed
    for _ in range(_MAX_ITER):
        scale = v_stall / speed
        _, cl_max, *_ = polar.max_lift_coefficients(reynolds * scale, mach * scale)
        r = float(np.max(cl / cl_max))
        cl_wing_max = kappa * lift_coefficient / r
        new = float(np.sqrt(2.0 * weight / (density * area * cl_wing_max)))
        converged = abs(new - v_stall) <= _TOLERANCE * new
        v_stall = new
        if converged:
            break
    return result | {
        "CL_max": cl_wing_max,
        "stall_speed": v_stall,
        "stall_speed_eas": v_stall * np.sqrt(density / SEA_LEVEL_DENSITY),
    }


def stall_speed_rows(source, vehicle):
    """
    Return the stall-speed check of every wing-borne condition of the vehicle that is recorded.

    Returns
    -------
    tuple of (float, list of dict)
        The design's 1-g stall speed (equivalent airspeed, m/s: that of the cruise condition,
        NaN without it) and one dict per condition: ``condition``, ``kind``, ``load_factor``,
        ``speed`` and ``speed_eas`` (m/s), ``CL``, ``ratio`` (largest c_l / c_l,max),
        ``ratio_ks`` (the constrained KS of both stalls), ``limit``, ``stall_speed_eas`` (from
        this condition) and ``speed_ratio`` (its equivalent airspeed over the design's stall
        speed).
    """
    rows = []
    for c in vehicle.conditions:
        if c.kind not in WING_BORNE_KINDS:
            continue
        try:
            found = stall_speed(source, vehicle, c.name)
        except KeyError:
            continue  # not in this model or not recorded
        density = float(_value(source, f"{c.name}.density", "kg/m**3")[0])
        speed = float(_value(source, f"{c.name}.speed", "m/s")[0])
        rows.append(
            {
                "condition": c.name,
                "kind": c.kind,
                "load_factor": c.load_factor,
                "speed": speed,
                "speed_eas": speed * np.sqrt(density / SEA_LEVEL_DENSITY),
                "ratio_ks": float(_value(source, f"{c.name}.wing_stall_ratio_ks")[0]),
                "limit": wing_stall_limit(vehicle.constraints, is_wing_load_case(c)),
                **found,
            }
        )
    cruise = [r for r in rows if r["condition"] == vehicle.mission.cruise_condition]
    design = cruise[0]["stall_speed_eas"] if cruise else np.nan
    for row in rows:
        row["speed_ratio"] = row["speed_eas"] / design
    return design, rows


def _speed(value):
    return f"{'-':>10}" if np.isnan(value) else f"{value:>10.1f}"


def format_stall_speed_check(source, vehicle):
    """Return the stall-speed check as text (:func:`stall_speed_rows`)."""
    design, rows = stall_speed_rows(source, vehicle)
    if not rows:
        return "  stall-speed check: no wing-borne condition recorded"
    limits = vehicle.constraints
    lines = [
        f"  stall-speed check: 1-g stall speed {design:.1f} m/s EAS (from the "
        f"{vehicle.mission.cruise_condition} condition's wing sections: the wing stalls when a "
        f"section reaches {limits.wing_stall_lift_fraction:g} c_l,max; 1-g conditions keep "
        f">= {limits.min_stall_speed_ratio:g} V_S, i.e. c_l/c_l,max <= "
        f"{wing_stall_limit(limits):.3f})",
        f"  {'condition':<14}{'n':>5}{'V [m/s]':>9}{'EAS':>7}{'V/V_S':>7}{'C_L':>7}"
        f"{'cl/clmax':>10}{'KS':>7}{'limit':>7}{'V_S here':>10}",
    ]
    for r in rows:
        status = "" if r["ratio_ks"] <= r["limit"] else "  ABOVE LIMIT"
        lines.append(
            f"  {r['condition']:<14}{r['load_factor']:>+5g}{r['speed']:>9.1f}"
            f"{r['speed_eas']:>7.1f}{r['speed_ratio']:>7.2f}{r['CL']:>7.3f}{r['ratio']:>10.3f}"
            f"{r['ratio_ks']:>7.3f}{r['limit']:>7.3f}{_speed(r['stall_speed_eas'])}{status}"
        )
    lines.append(
        "  (EAS: equivalent airspeed; V/V_S: EAS over the design's 1-g stall speed, below 1 the "
        "wing alone cannot carry the weight there; cl/clmax: the most loaded wing section, KS: "
        "its constrained smooth maximum over both stalls; V_S here: the stall speed as seen from "
        "that condition's lift distribution, EAS; - in a push-over)"
    )
    return "\n".join(lines)
