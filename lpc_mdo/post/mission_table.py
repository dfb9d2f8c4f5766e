"""The mission table of ``lpc-mdo analyze``: what is flown, for how long, at what energy."""

import math

from lpc_mdo.vehicle.condition_contract import condition_kind
from lpc_mdo.vehicle.mission_profile import mission_profile
from lpc_mdo.vehicle.reserve_rules import RESERVE_PRESETS

_J_PER_KWH = 3.6e6


def _power(prob, vehicle, name):
    """Return the electrical power (W) of condition ``name`` in ``prob``; None if not there."""
    if prob is None or name not in prob.model.condition_names:
        return None
    output = condition_kind(vehicle.condition(name).kind).power_output
    return float(prob.get_val(f"{name}.{output}", units="W")[0])


def format_mission(vehicle, prob=None):
    """
    Return the mission as text: one row per segment (or condition), then the energy totals.

    A mission stated as ``[[mission.segments]]`` shows each segment's condition, altitudes,
    speeds, distance and time as the loader derived them; a mission carried by the conditions
    shows each condition's duration and energy weight. With ``prob`` (a run model) each row also
    gives its electrical power and energy, summed as the model's energy_used.
    """
    mission = vehicle.mission
    day = f"ISA{mission.isa_offset:+g} K" if mission.isa_offset else "ISA"
    lines = []
    header = (
        f"  {'segment':<14}{'condition':<14}{'altitude [m]':>17}{'V [m/s]':>9}{'Vz [m/s]':>10}"
        f"{'distance [km]':>15}{'time [s]':>10}{'x':>4}{'power [kW]':>12}{'energy [kWh]':>14}"
    )
    total = 0.0
    if mission.segments is None:
        lines.append(
            f"  mission ({day}): each condition's duration and energy weight, as the vehicle file "
            "gives them"
        )
        lines.append(header)
        for c in vehicle.mission_segments:
            power = _power(prob, vehicle, c.name)
            energy = None if power is None else power * c.duration * c.energy_weight
            total += energy or 0.0
            climb = c.speed * math.sin(c.flight_path_angle)
            distance = c.speed * math.cos(c.flight_path_angle) * c.duration
            lines.append(
                _row("-", c.name, c.altitude, c.altitude, c.speed, climb, distance, c.duration,
                     c.energy_weight, power, energy)
            )  # fmt: skip
    else:
        legs = mission.legs or 1
        reserve = ""
        if mission.reserve is not None:
            rule = mission.reserve.rule
            source = RESERVE_PRESETS[rule].source if rule in RESERVE_PRESETS else rule
            reserve = f", reserve: {mission.reserve_time / 60:.4g} min ({source})"
        lines.append(
            f"  mission ({day}) from the vehicle file's segments: {legs} leg(s) from "
            f"{mission.start_altitude:g} m{reserve}"
        )
        lines.append(header)
        rows, _, _ = mission_profile(mission, vehicle.conditions)
        for r in rows:
            power = _power(prob, vehicle, r.condition)
            energy = None if power is None else power * r.time * r.count
            total += energy or 0.0
            altitudes = (r.start_altitude, r.end_altitude)
            lines.append(
                _row(r.segment, r.condition, *altitudes, r.speed, r.vertical_speed, r.distance,
                     r.time, r.count, power, energy)
            )  # fmt: skip
    if prob is not None:
        used = float(prob.get_val("energy_used", units="J")[0])
        lines.append(
            f"  energy {total / _J_PER_KWH:.2f} kWh over these rows; the model's energy_used "
            f"{used / _J_PER_KWH:.2f} kWh (the conditions in the model)"
        )
    return "\n".join(lines)


def _row(segment, condition, start, end, speed, vz, distance, time, count, power, energy):
    altitude = f"{start:.0f}" if abs(end - start) < 0.5 else f"{start:.0f} -> {end:.0f}"
    power_text = "-" if power is None else f"{power / 1e3:.1f}"
    energy_text = "-" if energy is None else f"{energy / _J_PER_KWH:.2f}"
    return (
        f"  {segment:<14}{condition:<14}{altitude:>17}{speed:>9.2f}{vz:>10.2f}"
        f"{distance / 1e3:>15.2f}{time:>10.1f}{count:>4g}{power_text:>12}{energy_text:>14}"
    )
