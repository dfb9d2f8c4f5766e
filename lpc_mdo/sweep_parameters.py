"""The parameters a sweep moves: which field of the vehicle each one sets, and its value.

A sweep parameter is vehicle knowledge: battery energy density, the final state-of-charge limit,
the hover noise limit, payload, the static-margin limit and the cruise range each map to one
field of the :class:`~lpc_mdo.vehicle.Vehicle`. :func:`sweep_vehicle` returns a vehicle with
one of them changed and :func:`reference_value` reads the vehicle's own value. The sweeps
(:mod:`lpc_mdo.sweeps`) re-optimize over them and the post-optimal sensitivities
(:mod:`lpc_mdo.sensitivities`) differentiate with respect to them.
"""

import dataclasses

from lpc_mdo.vehicle.consistency import check_across_parts
from lpc_mdo.vehicle.parts import Battery, ConstraintLimits, DesignCondition, FixedMasses
from lpc_mdo.vehicle.schema import VehicleSpecError, check_field

#: name -> (description, units, the paper's values or None). The paper swept the first two
#: (``--parameter all``); the others are the parameters of the post-optimal sensitivities
#: (:mod:`lpc_mdo.sensitivities`), swept to check them by re-optimizing (values required).
SWEEP_PARAMETERS = {
    "energy_density": ("battery energy density", "Wh/kg", (250.0, 300.0, 350.0, 400.0, 450.0)),
    "final_soc": ("final state-of-charge limit", "-", (0.1, 0.15, 0.2, 0.25, 0.3)),
    "max_noise": ("hover noise limit", "dBA", None),
    "payload": ("payload", "kg", None),
    "min_static_margin": ("static-margin limit", "-", None),
    "cruise_range": ("cruise range", "km", None),
}
#: The constraint limits among them: name -> the kind of the constraint each one bounds
#: (:data:`lpc_mdo.problems.CONSTRAINT_KINDS`). Swept in a problem without that constraint (or
#: with the static-margin constraint left out), every point is the same problem.
LIMIT_CONSTRAINT_KINDS = {
    "final_soc": "soc",
    "max_noise": "noise",
    "min_static_margin": "static_margin",
}
#: The sweeps of the paper (Sec. V.C): ``lpc-mdo sweep --parameter all``.
PAPER_SWEEPS = tuple(k for k, (_, _, values) in SWEEP_PARAMETERS.items() if values)


def _cruise(vehicle):
    return vehicle.condition(vehicle.mission.cruise_condition)


def sweep_vehicle(vehicle, parameter, value):
    """
    Return the vehicle with one sweep parameter set.

    Units: energy density Wh/kg, SoC and static-margin limits -, noise limit dBA, payload kg,
    cruise range km (the cruise condition's duration at its speed; at an optimized speed, the
    distance its segments state).
    """
    if parameter not in SWEEP_PARAMETERS:
        raise ValueError(f"sweep: parameter = {parameter!r}; allowed: {list(SWEEP_PARAMETERS)}.")
    try:
        changed = _with_value(vehicle, parameter, value)
        check_across_parts(changed)  # the rules a vehicle file meets, on the swept vehicle
    except VehicleSpecError as err:
        raise ValueError(f"sweep: {parameter} = {value:g}: {err}") from err
    return changed


def _with_value(vehicle, parameter, value):
    """Return the vehicle with one sweep parameter set, within its vehicle-file range."""
    replace = dataclasses.replace
    if parameter == "energy_density":
        stored = check_field(Battery, "energy_density", value, "battery.energy_density_wh_per_kg")
        return replace(vehicle, battery=replace(vehicle.battery, energy_density=stored))
    limits = {
        "final_soc": "min_final_soc",
        "max_noise": "max_noise",
        "min_static_margin": "min_static_margin",
    }
    if parameter in limits:
        name = limits[parameter]
        stored = check_field(ConstraintLimits, name, value, f"constraints.{name}")
        return replace(vehicle, constraints=replace(vehicle.constraints, **{name: stored}))
    if parameter == "payload":
        stored = check_field(FixedMasses, "payload", value, "masses.payload")
        return replace(vehicle, masses=replace(vehicle.masses, payload=stored))
    cruise = _cruise(vehicle)  # cruise_range, km
    if not cruise.speed > 0.0:
        raise VehicleSpecError(
            f"'conditions.{cruise.name}.speed' = {cruise.speed!r}: a cruise range needs a "
            "cruise speed > 0"
        )
    key = f"{cruise.name}.duration (cruise range {value:g} km at {cruise.speed:g} m/s)"
    if cruise.optimizes_speed:  # the range is the distance its segments state (at its speed)
        fixed = cruise.duration - cruise.level_distance / cruise.speed
        time = check_field(DesignCondition, "duration", fixed + value * 1000.0 / cruise.speed, key)
        changed = replace(cruise, duration=time, level_distance=value * 1000.0)
    else:
        duration = check_field(DesignCondition, "duration", value * 1000.0 / cruise.speed, key)
        changed = replace(cruise, duration=duration)
    conditions = tuple(changed if c is cruise else c for c in vehicle.conditions)
    return replace(vehicle, conditions=conditions)


def _cruise_range(cruise):
    """Cruise range (km): its stated distance at an optimized speed, else speed x duration."""
    if cruise.optimizes_speed:
        return cruise.level_distance / 1000.0
    return cruise.speed * cruise.duration / 1000.0


def reference_value(vehicle, parameter):
    """Return the vehicle's own value of a sweep parameter (units of :func:`sweep_vehicle`)."""
    values = {
        "energy_density": lambda: vehicle.battery.energy_density / 3600.0,
        "final_soc": lambda: vehicle.constraints.min_final_soc,
        "max_noise": lambda: vehicle.constraints.max_noise,
        "min_static_margin": lambda: vehicle.constraints.min_static_margin,
        "payload": lambda: vehicle.masses.payload,
        "cruise_range": lambda: _cruise_range(_cruise(vehicle)),
    }
    if parameter not in values:
        raise ValueError(f"sweep: parameter = {parameter!r}; allowed: {list(SWEEP_PARAMETERS)}.")
    return values[parameter]()
