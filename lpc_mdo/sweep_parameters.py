"""The parameters a sweep moves: which field of the vehicle each one sets, and its value.

A sweep parameter is vehicle knowledge: battery energy density, the final state-of-charge limit,
the hover noise limit, payload, the static-margin limit and the cruise range each map to one
field of the :class:`~lpc_mdo.vehicle.Vehicle`. :func:`sweep_vehicle` returns a vehicle with
one of them changed and :func:`reference_value` reads the vehicle's own value. The sweeps
(:mod:`lpc_mdo.sweeps`) re-optimize over them and the post-optimal sensitivities
(:mod:`lpc_mdo.sensitivities`) differentiate with respect to them.
"""

import dataclasses

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
#: The sweeps of the paper (Sec. V.C): ``lpc-mdo sweep --parameter all``.
PAPER_SWEEPS = tuple(k for k, (_, _, values) in SWEEP_PARAMETERS.items() if values)


def _cruise(vehicle):
    return vehicle.condition(vehicle.mission.cruise_condition)


def sweep_vehicle(vehicle, parameter, value):
    """
    Return the vehicle with one sweep parameter set.

    Units: energy density Wh/kg, SoC and static-margin limits -, noise limit dBA, payload kg,
    cruise range km (the cruise condition's duration at its speed).
    """
    replace = dataclasses.replace
    if parameter == "energy_density":
        if not value > 0.0:
            raise ValueError(f"sweep: energy_density = {value}; allowed: > 0 Wh/kg.")
        return replace(vehicle, battery=replace(vehicle.battery, energy_density=value * 3600.0))
    limits = {
        "final_soc": ("min_final_soc", 0.0 <= value < 1.0, "[0, 1)"),
        "max_noise": ("max_noise", 20.0 <= value <= 200.0, "[20, 200] dBA"),
        "min_static_margin": ("min_static_margin", -1.0 < value < 1.0, "(-1, 1)"),
    }
    if parameter in limits:
        field_name, ok, allowed = limits[parameter]
        if not ok:
            raise ValueError(f"sweep: {parameter} = {value}; allowed: {allowed}.")
        return replace(vehicle, constraints=replace(vehicle.constraints, **{field_name: value}))
    if parameter == "payload":
        if not value >= 0.0:
            raise ValueError(f"sweep: payload = {value}; allowed: >= 0 kg.")
        return replace(vehicle, masses=replace(vehicle.masses, payload=value))
    if parameter == "cruise_range":
        cruise = _cruise(vehicle)
        if not (value > 0.0 and cruise.speed > 0.0):
            raise ValueError(
                f"sweep: cruise_range = {value}; allowed: > 0 km (with a cruise speed > 0)."
            )
        changed = replace(cruise, duration=value * 1000.0 / cruise.speed)
        conditions = tuple(changed if c is cruise else c for c in vehicle.conditions)
        return replace(vehicle, conditions=conditions)
    raise ValueError(f"sweep: parameter = {parameter!r}; allowed: {list(SWEEP_PARAMETERS)}.")


def reference_value(vehicle, parameter):
    """Return the vehicle's own value of a sweep parameter (units of :func:`sweep_vehicle`)."""
    values = {
        "energy_density": lambda: vehicle.battery.energy_density / 3600.0,
        "final_soc": lambda: vehicle.constraints.min_final_soc,
        "max_noise": lambda: vehicle.constraints.max_noise,
        "min_static_margin": lambda: vehicle.constraints.min_static_margin,
        "payload": lambda: vehicle.masses.payload,
        "cruise_range": lambda: _cruise(vehicle).speed * _cruise(vehicle).duration / 1000.0,
    }
    if parameter not in values:
        raise ValueError(f"sweep: parameter = {parameter!r}; allowed: {list(SWEEP_PARAMETERS)}.")
    return values[parameter]()
