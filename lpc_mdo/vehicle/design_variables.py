"""The design-variable tables of a vehicle file (paper Table 6): shapes, units, bounds, refs.

The vehicle-level design variables are fixed by the vehicle's parts; the conditions' come from
their kinds' contracts (:class:`~lpc_mdo.vehicle.condition_layout.ConditionLayout`). Each table of
``[design_variables]`` is checked against its spec: units, shape, bounds around the initial
value, the minimum gauge. A design variable whose initial value the vehicle's parts give (and is
not zero) may leave out ``lower`` and ``upper``: they then follow the vehicle, 0.7 and 1.3 times
the initial value (:data:`RELATIVE_BOUNDS`), inside the variable's limits.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from lpc_mdo.components.weights.regressions import m4_coefficients
from lpc_mdo.vehicle.condition_layout import ConditionLayout
from lpc_mdo.vehicle.consistency import _PartialVehicle, min_fuselage_length
from lpc_mdo.vehicle.design_variable_registry import VEHICLE_DESIGN_VARIABLES
from lpc_mdo.vehicle.parts import (
    DesignCondition,
    DesignVariable,
    Rotor,
    _pairs,
    _ReadOnlyDict,
)
from lpc_mdo.vehicle.schema import (
    VehicleSpecError,
    _array,
    _check_keys,
    _fmt,
    _is_number,
    _number,
    _show,
    _Spec,
    _spec,
    _string,
)

# ------------------------------------------------------------------------------------------------
# Design variables


#: Largest factor between a design variable's ref and the magnitude of its bounds.
REF_RANGE = 1000.0
#: Units of design variables that are positive by nature (lengths, areas, masses, currents;
#: rotor speeds too, all but the transition roll/yaw differentials).
POSITIVE_UNITS = ("m", "m**2", "kg", "A")


@dataclass(frozen=True)
class _DVSpec:
    """What the vehicle fixes about a design variable: units, shape and any linked initial value."""

    description: str
    units: str
    shape: tuple[int, ...]
    initial_from: str = ""
    initial: tuple[float, ...] | None = None
    lower_min: tuple[float, str] | None = None  # (value, key) the lower bound may not go below
    upper_max: tuple[float, str] | None = None  # (value, key) the upper bound may not exceed
    tip_radius: float | None = None  # rotor speeds: the radius their tip speeds are checked at


def _design_variable_specs(parts: dict) -> dict[str, _DVSpec]:
    """
    Return the design variables (paper Table 6), sized from the built vehicle parts.

    The vehicle-level ones (the registry,
    :data:`~lpc_mdo.vehicle.design_variable_registry.VEHICLE_DESIGN_VARIABLES`), then those the
    conditions own (:class:`~lpc_mdo.vehicle.condition_layout.ConditionLayout`).
    """
    rotor_groups = [parts["lift_rotors"][i] for i, _ in _pairs(parts["lift_rotors"])]
    rotor_groups.append(parts["pusher"])
    gauge = (parts["material"].min_gauge, "material.min_gauge")
    specs = {}
    for dv in VEHICLE_DESIGN_VARIABLES:
        lower_min, upper_max = _physical_limits(dv, parts)
        specs[dv.name] = _DVSpec(
            dv.description,
            dv.units,
            dv.shape_of(len(rotor_groups), parts["wing_box"].num_bays),
            dv.initial_key,
            dv.initial_of(parts, rotor_groups),
            lower_min=gauge if dv.min_gauge else lower_min,
            upper_max=upper_max,
        )
    specs["fuselage_length"] = dataclasses.replace(
        specs["fuselage_length"], **_fuselage_length_limits(parts)
    )
    conditions = parts["conditions"]
    index = {c.name: i for i, c in enumerate(conditions)}
    suffix = {f.name: _spec(f).suffix for f in dataclasses.fields(DesignCondition)}
    for name, dv in ConditionLayout(_PartialVehicle(parts)).design_variables.items():
        if name in specs:
            raise VehicleSpecError(
                f"the design variable {name!r} of condition {dv.conditions[0]!r} (its "
                f"design_variable_prefix + a variable of its kind) has the name of a "
                f"vehicle-level design variable; choose another design_variable_prefix"
            )
        initial_from = ""
        if dv.initial_from:
            initial_from = ", ".join(
                f"conditions[{index[c]}].{dv.initial_from}{suffix[dv.initial_from]}"
                for c in dv.conditions
            )
        specs[name] = _DVSpec(
            dv.description,
            dv.units,
            dv.shape,
            initial_from,
            dv.initial,
            tip_radius=_tip_radius(name, parts),
        )
    return specs


def _physical_limits(dv, parts: dict) -> tuple:
    """
    Return the range a vehicle-level design variable's bounds lie in: (lower_min, upper_max).

    Its ``limits`` if it has them, else the range of the field that gives its initial value (a
    rotor radius of 0.1-10 m, a wing area of 0.1-200 m^2, ...): the bounds are values the design
    may take, so they obey what the vehicle file allows for that value. Each is None or
    (value, reason).
    """
    if dv.limits is not None:
        low, high, why = dv.limits
        return (
            None if low is None else (low, why),
            None if high is None else (high, why),
        )
    if not dv.initial_from or dv.units == "rad":  # angles: the degree check covers them
        return None, None
    table, _, name = dv.initial_from.partition(".")
    owner = Rotor if table == "rotors" else type(parts[table])
    spec = _spec(owner.__dataclass_fields__[name])
    key = f"the range of {dv.initial_key}"
    return (
        None if spec.ge is None else (spec.ge, key),
        None if spec.le is None else (spec.le, key),
    )


#: Highest tip speed a rotor-speed bound may give (m/s): Mach 1.2 at sea level, beyond the
#: transonic tips no rotor or propeller of the class runs (the tip-Mach constraints stop at
#: 0.9); a table of rad/s written as rpm stays below it, one in rev/s far below the lowest.
MAX_BOUND_TIP_SPEED = 408.0
#: Lowest tip speed the upper rotor-speed bound must allow (m/s): a rotor or propeller of the
#: class hovers or cruises at 120-290 m/s; below 50 m/s it lifts or pushes nothing useful.
MIN_UPPER_TIP_SPEED = 50.0


def _tip_radius(name: str, parts: dict) -> float | None:
    """Return the largest radius (m) of the rotors a rotor-speed design variable turns, or None."""
    if name.endswith("_pusher_rpm"):
        return parts["pusher"].radius
    if name.endswith("_lift_rpm"):
        return max(r.radius for r in parts["lift_rotors"])
    return None  # a speed differential (roll_yaw_rpm): its bounds may be small or negative


def _fuselage_length_limits(parts: dict) -> dict:
    """
    Limits of the fuselage_length bounds: the cabin and the M4 regressions' data range.

    The lower bound may not cut into the cabin (nose bay + cabin + the shortest tail cone,
    :func:`~lpc_mdo.vehicle.consistency.min_fuselage_length`) nor leave the fuselage, wing and
    boom regressions' data range; the upper bound may not leave that range either (docs
    theory/weights 'M4 regressions', theory/geometry 'Fuselage zones').
    """
    lower, upper = m4_coefficients()["data_range"]["fuselage_length"]
    data = "the M4 regressions' data range"
    cabin = min_fuselage_length(parts)
    if cabin > lower:
        lower_min = (cabin, "fuselage.nose_length + cabin + shortest tail cone")
    else:
        lower_min = (lower, f"the lower end of {data}")
    return {"lower_min": lower_min, "upper_max": (upper, f"the upper end of {data}")}


def _dv_values(value, shape: tuple[int, ...], path: str) -> tuple[float, ...]:
    """Convert a number (the same for every entry) or a nested list of ``shape`` to flat floats."""
    if _is_number(value):
        return (_number(value, _Spec(), path),) * math.prod(shape)
    if isinstance(value, list):
        return tuple(np.ravel(_array(value, shape, _Spec(), path)).tolist())
    what = "a number" if shape == (1,) else f"a number or a nested list of shape {shape}"
    raise VehicleSpecError(f"'{path}' must be {what}, got {_show(value)}")


#: Tables a vehicle file may leave out, read as given here: the design gross mass (its initial
#: value ``masses.design_gross_mass``, its bounds 0.7-1.3 times it), which files written before
#: the optimizer closed it do not carry.
DEFAULT_TABLES = {"design_gross_mass": {"units": "kg", "ref": 1000.0}}


def _read_design_variables(data, parts: dict) -> dict[str, DesignVariable]:
    specs = _design_variable_specs(parts)
    if isinstance(data, Mapping):
        _check_shared_prefixes(data, specs, parts["conditions"])
    optional = frozenset(name for name in DEFAULT_TABLES if name in specs)
    _check_keys(data, dict.fromkeys(specs, "design-variable table"), "design_variables", optional)
    data = {**data, **{name: DEFAULT_TABLES[name] for name in optional if name not in data}}
    # In the file's order (the order of the model's design-variable outputs).
    return _ReadOnlyDict(
        (name, _read_design_variable(data[name], specs[name], f"design_variables.{name}"))
        for name in data
    )


def _check_shared_prefixes(data, specs, conditions) -> None:
    """Name a table left over by a condition that shares another's ``design_variable_prefix``.

    Conditions with one prefix share one set of design variables (``{prefix}_*``, e.g. the five
    transition points); a table under the condition's own name is then not read.
    """
    for i, c in enumerate(conditions):
        if c.design_variable_prefix == c.name:
            continue
        for key in data:
            if key not in specs and key.startswith(f"{c.name}_"):
                raise VehicleSpecError(
                    f"unknown key 'design_variables.{key}': 'conditions[{i}]' ({c.name!r}) has "
                    f"design_variable_prefix = {c.design_variable_prefix!r}, so its design "
                    f"variables are the '{c.design_variable_prefix}_*' tables (shared with the "
                    "conditions of that prefix); allowed: remove the "
                    f"'{c.name}_*' tables, or give {c.name!r} its own prefix"
                )


def _check_tip_speeds(lower, upper, radius: float, entry) -> None:
    """Rotor-speed bounds (rpm) whose tip speeds at ``radius`` a rotor can run (see the limits)."""
    to_tip = 2.0 * math.pi / 60.0 * radius
    for k, (lo, up) in enumerate(zip(lower, upper, strict=True)):
        if up * to_tip < MIN_UPPER_TIP_SPEED:
            raise VehicleSpecError(
                f"{entry('upper', k)} = {_fmt(up)} is out of range: must be >= "
                f"{_fmt(MIN_UPPER_TIP_SPEED / to_tip)} (rpm), a tip speed of "
                f"{MIN_UPPER_TIP_SPEED:g} m/s at the radius {radius:g} m, got "
                f"{up * to_tip:.3g} m/s (a table in rad/s or rev/s? units = 'rpm')"
            )
        if lo * to_tip > MAX_BOUND_TIP_SPEED:
            raise VehicleSpecError(
                f"{entry('lower', k)} = {_fmt(lo)} is out of range: must be <= "
                f"{_fmt(MAX_BOUND_TIP_SPEED / to_tip)} (rpm), a tip speed of "
                f"{MAX_BOUND_TIP_SPEED:g} m/s (Mach 1.2) at the radius {radius:g} m, got "
                f"{lo * to_tip:.3g} m/s"
            )


#: Default bounds of a design variable whose initial value the vehicle gives (a wing area, a
#: rotor radius, a battery mass), as factors of that value: the paper's planform bounds, 0.7 and
#: 1.3 times the initial design (inferred from paper Table 8, where several optimized values sit
#: exactly at +-30 %); a table's own lower and upper replace them.
RELATIVE_BOUNDS = (0.7, 1.3)


def _relative_bound(initial, pick, spec: _DVSpec) -> tuple[float, ...]:
    """
    Return the lower (``pick`` = min) or upper (max) default bound of each initial value.

    Of the two factors of :data:`RELATIVE_BOUNDS` times the value (a negative value swaps them),
    kept inside the design variable's limits (``lower_min``, ``upper_max``).
    """
    low = -math.inf if spec.lower_min is None else spec.lower_min[0]
    high = math.inf if spec.upper_max is None else spec.upper_max[0]
    return tuple(min(max(pick(f * x for f in RELATIVE_BOUNDS), low), high) for x in initial)


def _read_design_variable(data, spec: _DVSpec, path: str) -> DesignVariable:
    if isinstance(data, Mapping) and "initial" in data and spec.initial is not None:
        raise VehicleSpecError(
            f"'{path}.initial' must not be given: the initial value is taken from "
            f"'{spec.initial_from}'"
        )
    unit_choices = ("rad", "deg") if spec.units == "rad" else (spec.units,)
    shape_text = "number" if spec.shape == (1,) else f"number or nested list of shape {spec.shape}"
    allowed = {"units": "one of " + ", ".join(repr(u) for u in unit_choices)}
    if spec.initial is None:
        allowed["initial"] = shape_text
    allowed |= {"lower": shape_text, "upper": shape_text, "ref": "number, > 0"}
    relative = spec.initial is not None and all(x != 0.0 for x in spec.initial)
    _check_keys(data, allowed, path, frozenset({"lower", "upper"}) if relative else frozenset())

    units = _string(data["units"], _Spec(choices=unit_choices), f"{path}.units")
    scale = math.pi / 180.0 if units == "deg" else 1.0
    values = {
        key: tuple(x * scale for x in _dv_values(data[key], spec.shape, f"{path}.{key}"))
        for key in ("initial", "lower", "upper")
        if key in data
    }
    initial = values.get("initial", spec.initial)
    if relative:  # bounds that follow the vehicle's own initial values (module docstring)
        values.setdefault("lower", _relative_bound(initial, min, spec))
        values.setdefault("upper", _relative_bound(initial, max, spec))
    lower, upper = values["lower"], values["upper"]
    if spec.units == "rad":
        # Pitch, twist and elevator angles lie within +-90 deg; larger values in rad are
        # degrees written with units = "rad".
        for key in ("initial", "lower", "upper"):
            for x in values.get(key, ()):
                if not -math.pi / 2 <= x <= math.pi / 2:
                    raise VehicleSpecError(
                        f"'{path}.{key}' = {_fmt(x / scale)} is out of range: must be in "
                        f"[-90, 90] deg = [-1.5708, 1.5708] rad (units = {units!r}; degree "
                        f"values need units = 'deg')"
                    )
    ref = _number(data["ref"], _Spec(units=units, gt=0), f"{path}.ref") * scale
    magnitude = max(abs(x) for x in (*lower, *upper))
    if magnitude > 0 and not magnitude / REF_RANGE <= ref <= magnitude * REF_RANGE:
        raise VehicleSpecError(
            f"'{path}.ref' = {_fmt(ref / scale)} is out of range: must be within a factor "
            f"{REF_RANGE:g} of the bounds' magnitude {_fmt(magnitude / scale)} ({units}), i.e. in "
            f"[{_fmt(magnitude / scale / REF_RANGE)}, {_fmt(magnitude / scale * REF_RANGE)}] "
            "(the optimizer sees value/ref, which should be of order one)"
        )

    def entry(key, k):
        if len(initial) == 1:
            return f"'{path}.{key}'"
        return f"'{path}.{key}" + "".join(f"[{i}]" for i in np.unravel_index(k, spec.shape)) + "'"

    speed = spec.units == "rpm" and "roll_yaw" not in path  # a differential may be negative
    if spec.units in POSITIVE_UNITS or speed:
        for k, lo in enumerate(lower):
            if lo <= 0.0:
                raise VehicleSpecError(
                    f"{entry('lower', k)} = {_fmt(lo)} is out of range: must be > 0 ({units}; "
                    "a length, area, mass, current or rotor speed is positive)"
                )
    if spec.tip_radius is not None:
        _check_tip_speeds(lower, upper, spec.tip_radius, entry)
    source = f"; the initial value is taken from '{spec.initial_from}'" if spec.initial_from else ""
    for k, (lo, up) in enumerate(zip(lower, upper, strict=True)):
        if lo > up:
            raise VehicleSpecError(
                f"{entry('lower', k)} = {_fmt(lo / scale)} is out of range: must be <= "
                f"{entry('upper', k)} = {_fmt(up / scale)} ({units}; the bounds are swapped?)"
            )
    for k, (x0, lo, up) in enumerate(zip(initial, lower, upper, strict=True)):
        if not lo <= x0 <= up:
            raise VehicleSpecError(
                f"{entry('initial', k)} = {_fmt(x0 / scale)} is out of range: must be in [lower, "
                f"upper] = [{_fmt(lo / scale)}, {_fmt(up / scale)}] ({units}){source}"
            )
        if spec.lower_min is not None and lo < spec.lower_min[0]:
            raise VehicleSpecError(
                f"{entry('lower', k)} = {_fmt(lo)} is out of range: must be >= "
                f"{_fmt(spec.lower_min[0])} ({units}; {spec.lower_min[1]})"
            )
        if spec.upper_max is not None and up > spec.upper_max[0]:
            raise VehicleSpecError(
                f"{entry('upper', k)} = {_fmt(up)} is out of range: must be <= "
                f"{_fmt(spec.upper_max[0])} ({units}; {spec.upper_max[1]})"
            )
    return DesignVariable(
        initial=initial,
        lower=lower,
        upper=upper,
        units="rad" if units == "deg" else units,
        ref=ref,
        shape=spec.shape,
        description=spec.description,
        initial_from=spec.initial_from,
    )
