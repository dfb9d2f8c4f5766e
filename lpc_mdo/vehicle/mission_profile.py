"""The mission as a designer states it: segments and a reserve, turned into the conditions' keys.

``[[mission.segments]]`` lists what the vehicle flies, in order, from ``mission.start_altitude``:
each segment in one design condition (its power), for a time it states directly, a distance at
the condition's speed, or a climb or descent at a vertical speed to an altitude. The legs
(``mission.legs``) repeat the segments without recharging; ``[mission.reserve]`` follows.

From them the loader derives, for every condition the segments fly:

- ``altitude``: the mean altitude of its segments, weighted by their times (the atmosphere of a
  climb is taken at its mean altitude, docs theory/dynamics 'Condition kinematics');
- ``flight_path_angle``: gamma = asin(vertical_speed / V) in a steady climb or descent, 0 in
  level flight;
- ``duration``: its time per leg (the sum over its segments), and ``energy_weight`` = legs;
- ``level_distance``: the distance its ``distance_km`` segments state, whose time follows the
  speed in the model where the condition's ``speed_rule`` is "optimized"
  (:class:`~lpc_mdo.components.energy.flight_time.FlightTimeComp`);

and the reserve's time at its condition (:attr:`~lpc_mdo.vehicle.parts.Mission.reserve_time`), a
term of its own in the mission energy, so that changing a leg's cruise range leaves the reserve
as it is. The energy is then E = legs x sum_i P_i t_i + P_reserve t_reserve, each condition's
power P_i evaluated once (quasi-steady segments; docs theory/energy 'Mission energy').

Rules (each broken rule is a VehicleSpecError naming the segment):

- a segment flies a condition of kind ``hover``, ``transition`` or ``steady``; a condition's
  segments all fly at one flight-path angle (within 0.01 deg) and at altitudes within
  :data:`ALTITUDE_SPREAD` of each other, the condition at their time-weighted mean;
- hover: ``duration``, or a vertical climb or descent (``to_altitude``, ``vertical_speed``) whose
  power is taken as that of hover at the mean altitude: at 0.5 m/s (100 ft/min) against a hover
  induced velocity of about 10 m/s momentum theory adds 2.5 % (Leishman, Principles of
  Helicopter Aerodynamics, 2nd ed., eq. 2.56), not modelled;
- transition: the points sharing a ``design_variable_prefix`` are one segment, ``duration`` split
  evenly among them (the quasi-steady points sample the manoeuvre at equal times);
- steady: ``duration`` or ``distance`` in level flight; ``to_altitude`` with ``vertical_speed``
  (or ``flight_path_angle_deg``, V_z = V sin gamma) in a climb (positive, to a higher
  ``to_altitude``) or a descent;
- the conditions the segments fly leave ``altitude``, ``flight_path_angle``, ``duration`` and
  ``energy_weight`` out (the mission sets them); the others keep them, with no energy weight.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass

from lpc_mdo.vehicle.parts import DesignCondition, Mission, MissionReserve, MissionSegment
from lpc_mdo.vehicle.reserve_rules import RESERVE_PRESETS
from lpc_mdo.vehicle.schema import VehicleSpecError

#: Condition kinds a segment may fly (the powered kinds of the mission).
SEGMENT_KINDS = ("hover", "transition", "steady")
#: The condition keys the mission derives.
DERIVED_KEYS = {
    "altitude": "altitude",
    "flight_path_angle": "flight_path_angle_deg",
    "duration": "duration",
    "energy_weight": "energy_weight",
}
#: Largest spread (m) of the altitudes at which one condition is flown: it is evaluated at their
#: time-weighted mean, and 150 m moves the density by 1.5 % (ISA near sea level); a vertiport's
#: hover at 50 ft and the take-off climb to it share the hover condition.
ALTITUDE_SPREAD = 150.0
_ANGLE_TOLERANCE = math.radians(0.01)


@dataclass(frozen=True)
class ProfileRow:
    """One segment (or transition point) of the derived mission, for the analysis table."""

    segment: str  # "segments[3]" or "reserve"
    condition: str
    start_altitude: float  # m
    end_altitude: float  # m
    speed: float  # m/s
    vertical_speed: float  # m/s
    distance: float  # m (horizontal)
    time: float  # s, one pass
    count: int  # passes (legs; 1 for the reserve)


def _condition_targets(segment: MissionSegment, conditions, where: str) -> list[int]:
    """Return the indices of the conditions a segment flies: a name, or a transition prefix."""
    named = [i for i, c in enumerate(conditions) if c.name == segment.condition]
    if named:
        return named
    group = [
        i
        for i, c in enumerate(conditions)
        if c.kind == "transition" and c.design_variable_prefix == segment.condition
    ]
    if group:
        return group
    names = ", ".join(repr(c.name) for c in conditions if c.kind in SEGMENT_KINDS)
    raise VehicleSpecError(
        f"'{where}.condition' = {segment.condition!r} is not a condition of the vehicle; allowed: "
        f"one of {names}, or the design_variable_prefix of transition points"
    )


def _segment_time(segment, condition, altitude, where, in_group):
    """Return (time s, end altitude m, flight-path angle rad, distance m) of one segment."""
    given = [k for k in ("duration", "distance", "to_altitude") if getattr(segment, k) is not None]
    keys = {"duration": "duration", "distance": "distance_km", "to_altitude": "to_altitude"}
    if len(given) != 1:
        shown = ", ".join(f"'{where}.{keys[k]}'" for k in given) or "none"
        raise VehicleSpecError(
            f"'{where}': give exactly one of 'duration', 'distance_km' or 'to_altitude' (with "
            f"'vertical_speed'); given: {shown}"
        )
    (key,) = given
    kind, speed = condition.kind, condition.speed
    rate = segment.vertical_speed
    if segment.flight_path_angle is not None:
        if rate is not None or kind != "steady":
            raise VehicleSpecError(
                f"'{where}.flight_path_angle_deg' goes with 'to_altitude' in a 'steady' "
                "condition, in place of 'vertical_speed' (not with it)"
            )
        rate = speed * math.sin(segment.flight_path_angle)
    if (key == "to_altitude") != (rate is not None):
        raise VehicleSpecError(
            f"'{where}.vertical_speed' (or 'flight_path_angle_deg') goes with 'to_altitude' (a "
            "climb or descent) and only with it"
        )
    if in_group and key != "duration":
        raise VehicleSpecError(
            f"'{where}': a transition segment is flown for a 'duration' (split among its "
            f"points), not by '{keys[key]}'"
        )
    if key == "duration":
        return segment.duration, altitude, 0.0, speed * segment.duration
    if key == "distance":
        if kind != "steady":
            raise VehicleSpecError(
                f"'{where}.distance_km': condition {condition.name!r} is of kind {kind!r}; a "
                "distance is flown in a 'steady' condition (a hover covers none)"
            )
        return segment.distance / speed, altitude, 0.0, segment.distance
    target = segment.to_altitude
    rise = target - altitude
    if rate == 0.0 or rise == 0.0 or (rate > 0.0) != (rise > 0.0):
        verb = "climb" if rate > 0.0 else "descent"
        raise VehicleSpecError(
            f"'{where}.to_altitude' = {target:g} m with 'vertical_speed' = {rate:g} m/s: a "
            f"{verb} from {altitude:g} m (where the segment starts) must end "
            f"{'above' if rate > 0.0 else 'below'} it; allowed: vertical_speed > 0 to a higher "
            "altitude, < 0 to a lower one"
        )
    time = rise / rate
    if kind == "hover":
        return time, target, 0.0, 0.0
    if kind != "steady" or abs(rate) >= speed:
        raise VehicleSpecError(
            f"'{where}.vertical_speed' = {rate:g} m/s in condition {condition.name!r} (kind "
            f"{kind!r}, {speed:g} m/s): a climb or descent is flown in a 'steady' condition "
            "faster than its vertical speed, or vertically in a 'hover' one"
        )
    gamma = math.asin(rate / speed)
    return time, target, gamma, speed * math.cos(gamma) * time


def _reserve_time(reserve: MissionReserve, condition) -> float:
    rule = reserve.rule
    if rule in RESERVE_PRESETS:
        if reserve.duration is not None or reserve.distance is not None:
            raise VehicleSpecError(
                f"'mission.reserve': rule {rule!r} sets the reserve "
                f"({RESERVE_PRESETS[rule].duration / 60:g} min); leave out 'duration_min' and "
                "'distance_km', or use rule 'time' or 'distance'"
            )
        return RESERVE_PRESETS[rule].duration
    key, other = ("duration", "distance") if rule == "time" else ("distance", "duration")
    if getattr(reserve, key) is None or getattr(reserve, other) is not None:
        file_key = {"duration": "duration_min", "distance": "distance_km"}
        raise VehicleSpecError(
            f"'mission.reserve': rule {rule!r} takes '{file_key[key]}' and not '{file_key[other]}'"
        )
    if rule == "time":
        return reserve.duration
    if condition.kind != "steady":
        raise VehicleSpecError(
            f"'mission.reserve.condition' = {condition.name!r} is of kind {condition.kind!r}; a "
            "reserve distance is flown in a 'steady' condition"
        )
    return reserve.distance / condition.speed


def mission_profile(mission: Mission, conditions: Sequence[DesignCondition]):
    """
    Return the derived mission: its rows and the per-condition keys it sets.

    Returns
    -------
    rows : list of ProfileRow
    derived : dict
        condition index -> {'altitude', 'flight_path_angle', 'duration', 'energy_weight'}.
    reserve : tuple of (int, float, float) or None
        (condition index, reserve time s, reserve distance m: 0 unless the rule is a distance).
    """
    altitude = mission.start_altitude
    legs = mission.legs or 1
    rows, per_condition = [], {}
    for k, segment in enumerate(mission.segments):
        where = f"mission.segments[{k}]"
        targets = _condition_targets(segment, conditions, where)
        group = len(targets) > 1 or conditions[targets[0]].name != segment.condition
        for i in targets:
            c = conditions[i]
            if c.kind not in SEGMENT_KINDS:
                raise VehicleSpecError(
                    f"'{where}.condition' = {segment.condition!r} is of kind {c.kind!r}; a "
                    f"segment flies a condition of kind {', '.join(map(repr, SEGMENT_KINDS))}"
                )
        if group:  # transition points: the duration split evenly
            time, end, gamma, _ = _segment_time(segment, conditions[targets[0]], altitude, where, 1)
            pieces = [(i, time / len(targets), end, gamma) for i in targets]
        else:
            time, end, gamma, _ = _segment_time(segment, conditions[targets[0]], altitude, where, 0)
            pieces = [(targets[0], time, end, gamma)]
        for i, piece_time, end_altitude, gamma in pieces:
            c = conditions[i]
            mean = 0.5 * (altitude + end_altitude)
            entry = per_condition.setdefault(
                i,
                {
                    "altitudes": [],
                    "flight_path_angle": gamma,
                    "duration": 0.0,
                    "level_distance": 0.0,
                    "first": k,
                },
            )
            if segment.distance is not None:
                entry["level_distance"] += segment.distance
            heights = [h for h, _ in entry["altitudes"]] + [mean]
            first = heights[0]
            if max(heights) - min(heights) > ALTITUDE_SPREAD or (
                abs(entry["flight_path_angle"] - gamma) > _ANGLE_TOLERANCE
            ):
                raise VehicleSpecError(
                    f"'{where}' flies condition {c.name!r} at {mean:g} m and "
                    f"{math.degrees(gamma):g} deg, 'mission.segments[{entry['first']}]' at "
                    f"{first:g} m and {math.degrees(entry['flight_path_angle']):g} deg; allowed: "
                    f"one flight-path angle and altitudes within {ALTITUDE_SPREAD:g} m per "
                    "condition (give the other segment a condition of its own)"
                )
            entry["altitudes"].append((mean, piece_time))
            entry["duration"] += piece_time
            vertical = 0.0 if piece_time == 0 else (end_altitude - altitude) / piece_time
            horizontal = c.speed * math.cos(gamma) * piece_time
            rows.append(
                ProfileRow(
                    f"segments[{k}]",
                    c.name,
                    altitude,
                    end_altitude,
                    c.speed,
                    vertical,
                    horizontal,
                    piece_time,
                    legs,
                )  # fmt: skip
            )
        altitude = pieces[-1][2]
    derived = {
        i: {
            "altitude": sum(h * t for h, t in e["altitudes"]) / e["duration"],
            "flight_path_angle": e["flight_path_angle"],
            "duration": e["duration"],
            "energy_weight": float(legs),
            "level_distance": e["level_distance"],
        }
        for i, e in per_condition.items()
    }
    reserve = None
    if mission.reserve is not None:
        name = mission.reserve.condition or mission.cruise_condition
        index = next((i for i, c in enumerate(conditions) if c.name == name), None)
        if index is None or conditions[index].kind not in ("hover", "steady"):
            raise VehicleSpecError(
                f"'mission.reserve.condition' = {name!r}: allowed: a 'steady' or 'hover' "
                "condition of the vehicle"
            )
        time = _reserve_time(mission.reserve, conditions[index])
        c = conditions[index]
        level = derived.get(index, {}).get("altitude", c.altitude)
        rows.append(
            ProfileRow("reserve", c.name, level, level, c.speed, 0.0, c.speed * time, time, 1)
        )
        distance = mission.reserve.distance if mission.reserve.rule == "distance" else 0.0
        reserve = (index, time, distance)
    return rows, derived, reserve


def apply_mission(mission: Mission, conditions: tuple[DesignCondition, ...]):
    """
    Return (mission, conditions) with the keys the segments derive; check the keys given.

    Without segments the conditions must carry every mission key themselves.
    """
    if mission.segments is None:
        for key in ("start_altitude", "legs", "reserve"):
            if getattr(mission, key) is not None:
                raise VehicleSpecError(
                    f"'mission.{key}' goes with the mission's segments ([[mission.segments]]); "
                    "without them the conditions' durations and energy weights are the mission"
                )
        for i, c in enumerate(conditions):
            if c.optimizes_speed:
                raise VehicleSpecError(
                    f"'conditions[{i}].speed_rule' = 'optimized' goes with the mission's segments "
                    "([[mission.segments]]): they say which distance the speed flies; without "
                    "them a condition's duration is fixed and the optimizer would fly it at its "
                    "best-endurance speed; allowed: 'fixed', or segments"
                )
            for field, key in DERIVED_KEYS.items():
                if getattr(c, field) is None:
                    raise VehicleSpecError(
                        f"missing key 'conditions[{i}].{key}' (without [[mission.segments]] each "
                        "condition states it)"
                    )
        return mission, conditions
    if mission.start_altitude is None:
        raise VehicleSpecError(
            "missing key 'mission.start_altitude' (m: where the first segment starts)"
        )
    rows, derived, reserve = mission_profile(mission, conditions)
    out = []
    for i, c in enumerate(conditions):
        keys = derived.get(i)
        if keys is not None:
            given = [DERIVED_KEYS[f] for f in DERIVED_KEYS if getattr(c, f) is not None]
            if given:
                raise VehicleSpecError(
                    f"'conditions[{i}].{given[0]}': condition {c.name!r} is flown by the "
                    "mission's segments, which set its altitude, flight_path_angle_deg, "
                    "duration and energy_weight; leave them out"
                )
            out.append(dataclasses.replace(c, **keys))
            continue
        if c.energy_weight:
            raise VehicleSpecError(
                f"'conditions[{i}].energy_weight' = {c.energy_weight!r}: with "
                "[[mission.segments]] the segments make the mission; a condition they do not "
                "fly has no energy weight (leave it out, or 0)"
            )
        missing = [k for f, k in DERIVED_KEYS.items() if f in ("altitude", "flight_path_angle")
                   and getattr(c, f) is None]  # fmt: skip
        if missing:
            raise VehicleSpecError(
                f"missing key 'conditions[{i}].{missing[0]}' (condition {c.name!r} is not flown "
                "by the mission's segments, so it states its own)"
            )
        out.append(dataclasses.replace(c, duration=c.duration or 0.0, energy_weight=0.0))
    reserve_index, reserve_time, reserve_distance = reserve or (None, 0.0, 0.0)
    mission = dataclasses.replace(
        mission,
        reserve_condition=None if reserve_index is None else conditions[reserve_index].name,
        reserve_time=reserve_time,
        reserve_distance=reserve_distance,
    )
    return mission, tuple(out)
