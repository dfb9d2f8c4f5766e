"""Checks of a vehicle file across fields: symmetric lift-rotor pairs, the pusher, conditions.

Each condition kind's own rules are its declaration's
:meth:`~lpc_mdo.vehicle.condition_contract.ConditionKind.check`; this module checks what spans
fields (names unique, kinds registered, the cruise condition a steady one).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from lpc_mdo.components.atmosphere import standard_atmosphere
from lpc_mdo.components.motor.parameters import MotorParameters
from lpc_mdo.components.structures.wing_box_geometry import WING_BOX_SECTIONS, WingBoxSection
from lpc_mdo.components.weights.item_placement import (
    NASA_LANDING_GEAR_STATION,
    NASA_SYSTEMS_STATION,
)
from lpc_mdo.core.constants import GRAVITY
from lpc_mdo.vehicle.airframe import check_airframe
from lpc_mdo.vehicle.condition_contract import CONDITION_KINDS
from lpc_mdo.vehicle.parts import (
    _IDENTIFIER,
    DesignCondition,
    Mission,
    Rotor,
    Wing,
    _pairs,
)
from lpc_mdo.vehicle.schema import VehicleSpecError

# ------------------------------------------------------------------------------------------------
# Checks across fields


def _close(a, b) -> bool:
    return bool(np.allclose(a, b, rtol=1e-9, atol=1e-6))


def _first_use(seen: dict, table: str, i: int, name: str, note: str) -> None:
    """Record ``name`` as ``table[i].name``; refuse it if an earlier entry has it already."""
    if name in seen:
        raise VehicleSpecError(
            f"'{table}[{i}].name' = {name!r} repeats '{table}[{seen[name]}].name'; {note}"
        )
    seen[name] = i


def _check_lift_rotors(rotors: tuple[Rotor, ...]) -> None:
    seen = {}
    for i, r in enumerate(rotors):
        if not r.name.strip():
            raise VehicleSpecError(
                f"'lift_rotors[{i}].name' = {r.name!r} is empty: must name the rotor (reports "
                "and messages use it)"
            )
        _first_use(seen, "lift_rotors", i, r.name, "each rotor needs its own name")
    num_pairs = len(rotors) // 2  # the count is even (LIFT_ROTOR_COUNTS, the schema)
    for i, r in enumerate(rotors):
        if r.pair >= num_pairs:
            raise VehicleSpecError(
                f"'lift_rotors[{i}].pair' = {r.pair} is out of range: must be in [0, "
                f"{num_pairs - 1}] ({len(rotors)} lift rotors make {num_pairs} pairs; group "
                f"{num_pairs} is the pusher)"
            )
    shared = (
        "radius", "num_blades", "hub_radius_ratio", "chord_cp", "twist_cp", "airfoil",
        "thickness_to_chord",
    )  # fmt: skip
    for p, members in enumerate(_pairs(rotors)):
        if len(members) != 2:
            listed = ", ".join(f"lift_rotors[{i}]" for i in members) or "none"
            raise VehicleSpecError(
                f"'lift_rotors' pair {p} has {len(members)} rotors ({listed}); each pair "
                f"0..{num_pairs - 1} must have exactly 2 mirror-image rotors"
            )
        i, j = members
        a, b = rotors[i], rotors[j]
        for name in shared:
            if not _close_or_equal(getattr(a, name), getattr(b, name)):
                raise VehicleSpecError(
                    f"'lift_rotors[{j}].{name}' = {getattr(b, name)!r} differs from its pair "
                    f"partner 'lift_rotors[{i}].{name}' = {getattr(a, name)!r}; the rotors of a "
                    f"pair share {', '.join(shared)}"
                )
        for name in ("hub_position", "thrust_axis"):
            va, vb = getattr(a, name), getattr(b, name)
            if not _close(vb, (va[0], -va[1], va[2])):
                raise VehicleSpecError(
                    f"'lift_rotors[{j}].{name}' = {vb!r} is not the mirror image (y -> -y) of "
                    f"its pair partner 'lift_rotors[{i}].{name}' = {va!r}"
                )
        if a.spin_direction == b.spin_direction:
            raise VehicleSpecError(
                f"'lift_rotors[{j}].spin_direction' = {b.spin_direction} must be opposite to its "
                f"pair partner 'lift_rotors[{i}].spin_direction' = {a.spin_direction}, so that "
                f"each pair balances its yaw torque"
            )


def _close_or_equal(a, b) -> bool:
    return a == b if isinstance(a, str) else _close(a, b)


def _named_rotors(lift_rotors: tuple[Rotor, ...], pusher: Rotor) -> list[tuple[str, Rotor]]:
    """Every rotor with its key in the vehicle file: ``lift_rotors[i]``, then ``pusher``."""
    return [(f"lift_rotors[{i}]", r) for i, r in enumerate(lift_rotors)] + [("pusher", pusher)]


#: Largest blade chord over the rotor radius: the root chords of built lift rotors and
#: propellers are below 0.3 R (the reference's 0.2 R); beyond 0.5 R a blade is a paddle,
#: outside the slender-blade assumption of the BEM and Pitt-Peters models.
MAX_CHORD_OVER_RADIUS = 0.5


def _check_blades(lift_rotors: tuple[Rotor, ...], pusher: Rotor) -> None:
    """
    Every chord control point shorter than half its rotor's radius; blade roots that fit.

    At the hub radius r_h the blades' root chords c_0 (the first control point: the clamped
    B-spline starts there) take B c_0 of the circumference 2 pi r_h: the local solidity
    B c_0 / (2 pi r_h) must be <= 1, or the blade roots overlap.
    """
    rotors = _named_rotors(lift_rotors, pusher)
    for path, rotor in rotors:
        longest = max(rotor.chord_cp)
        if longest > MAX_CHORD_OVER_RADIUS * rotor.radius:
            raise VehicleSpecError(
                f"'{path}.chord_cp' = {list(rotor.chord_cp)!r} is out of range: every chord "
                f"must be <= {MAX_CHORD_OVER_RADIUS:g} x '{path}.radius' = "
                f"{MAX_CHORD_OVER_RADIUS * rotor.radius:.4g} (m; a slender blade)"
            )
        hub = rotor.hub_radius
        root = rotor.num_blades * rotor.chord_cp[0]
        if hub > 0.0 and root > 2.0 * math.pi * hub:
            raise VehicleSpecError(
                f"'{path}.chord_cp' = {list(rotor.chord_cp)!r} is out of range: "
                f"{rotor.num_blades} blades of root chord {rotor.chord_cp[0]:g} m take "
                f"{root:.4g} m of the {2.0 * math.pi * hub:.4g} m circumference at the hub "
                f"radius {hub:.4g} m ('{path}.hub_radius_ratio' x radius): the blade roots "
                "overlap; allowed: num_blades x chord_cp[0] <= 2 pi x hub radius"
            )


def _check_pusher(pusher: Rotor, lift_rotors: tuple[Rotor, ...]) -> None:
    group = len(lift_rotors) // 2
    if pusher.pair != group:
        raise VehicleSpecError(
            f"'pusher.pair' = {pusher.pair} is not allowed: must be {group} (the pusher is its "
            f"own group, after the lift-rotor pairs 0..{group - 1})"
        )


def _check_conditions(parts: dict) -> None:
    """Names unique identifiers, kinds registered, each kind's own rules (its declaration)."""
    vehicle = _PartialVehicle(parts)
    first_of_prefix = {}
    for i, c in enumerate(parts["conditions"]):
        j = first_of_prefix.setdefault(c.design_variable_prefix, i)
        other = parts["conditions"][j]
        if other.kind != c.kind:
            raise VehicleSpecError(
                f"'conditions[{i}].design_variable_prefix' = {c.design_variable_prefix!r} is "
                f"that of 'conditions[{j}]' ({other.name!r}, kind {other.kind!r}), but "
                f"{c.name!r} is of kind {c.kind!r}: conditions that share design-variable "
                "tables must be of one kind (their trim variables differ); give it a prefix of "
                "its own"
            )
    seen: dict[str, int] = {}
    for i, c in enumerate(parts["conditions"]):
        path = f"conditions[{i}]"
        for key in ("name", "design_variable_prefix"):
            value = getattr(c, key)
            if not value.isidentifier():
                raise VehicleSpecError(
                    f"'{path}.{key}' = {value!r} is not allowed: must be {_IDENTIFIER}"
                )
        _first_use(seen, "conditions", i, c.name, "names must be unique")
        if c.kind not in CONDITION_KINDS:  # lpc_mdo.vehicle imports condition_kinds
            allowed = ", ".join(repr(k) for k in CONDITION_KINDS)
            raise VehicleSpecError(
                f"'{path}.kind' = {c.kind!r} is not allowed: must be one of "
                f"{allowed} (register a new kind with "
                f"lpc_mdo.groups.condition_kinds.register_condition_kind)"
            )
        CONDITION_KINDS[c.kind].check(i, c, vehicle)


#: Names of the full model's own subsystems beside the conditions (groups/lpc.py), which a
#: condition name may not take.
RESERVED_NAMES = frozenset(
    ["design_variables", "vehicle", "power_mux", "mission", "battery"]
    + [
        f"{prefix}_{name}{suffix}"
        for prefix in ("lift", "pusher")
        for name in ("margin", "voltage_margin")
        for suffix in ("", "_gather")
    ]
)


def _check_condition_names(conditions: tuple[DesignCondition, ...]) -> None:
    """Condition names that can name a subsystem of the model: ASCII, no leading '_', free."""
    for i, c in enumerate(conditions):
        if not c.name.isascii() or c.name.startswith("_") or c.name in RESERVED_NAMES:
            raise VehicleSpecError(
                f"'conditions[{i}].name' = {c.name!r} is not allowed: must be an ASCII "
                "identifier that does not start with '_' and is none of the model's own "
                f"subsystems ({', '.join(sorted(RESERVED_NAMES))})"
            )


#: Largest relative difference between a material's shear modulus and E/(2 (1 + nu)): the
#: handbook values of one alloy agree to a few per cent (aluminium 7075-T6: E 71.7, G 26.9 GPa,
#: nu 0.33 give 26.95; MMPDS); the reference's 26.0 GPa is 0.2 % from 25.94.
MATERIAL_G_TOLERANCE = 0.1


def _check_material(material) -> None:
    """Check G = E/(2 (1 + nu)) <= E/2 (isotropic) and an allowable below 1 % strain."""
    e, g = material.youngs_modulus, material.shear_modulus
    if g > e / 2.0:
        raise VehicleSpecError(
            f"'material.shear_modulus' = {g:g} is out of range: must be <= "
            f"'material.youngs_modulus' / 2 = {e / 2.0:g} (Pa; G = E/(2 (1 + nu)) of an "
            "isotropic material)"
        )
    isotropic = e / (2.0 * (1.0 + material.poisson_ratio))
    if abs(g / isotropic - 1.0) > MATERIAL_G_TOLERANCE:
        raise VehicleSpecError(
            f"'material.shear_modulus' = {g:g} is out of range with 'material.youngs_modulus' = "
            f"{e:g} and 'material.poisson_ratio' = {material.poisson_ratio:g}: an isotropic "
            f"material has G = E/(2 (1 + nu)) = {isotropic:.4g} (Pa); allowed: within "
            f"{MATERIAL_G_TOLERANCE:.0%} of it (the wing box takes the material as isotropic)"
        )
    if material.allowable_stress > 0.01 * e:
        raise VehicleSpecError(
            f"'material.allowable_stress' = {material.allowable_stress:g} is out of range: "
            f"must be <= 1 % of 'material.youngs_modulus' = {0.01 * e:g} (Pa; airframe materials "
            "yield or reach their design allowables below 1 % strain: aluminium alloys about "
            "0.7 %)"
        )


def _check_buildable(parts: dict) -> None:
    """Check the fixed models the vehicle needs: its motor winding and its wing-box section."""
    _check_material(parts["material"])
    try:
        MotorParameters.of_motor_table(parts["motor"])
    except ValueError as err:
        raise VehicleSpecError(f"'motor' (num_slots, pole_pairs, num_phases): {err}") from err
    airfoil, box = parts["wing"].airfoil, parts["wing_box"]
    if box.rear_spar <= box.front_spar:
        raise VehicleSpecError(
            f"'wing_box.rear_spar' = {box.rear_spar!r} is out of range: must be > "
            f"'wing_box.front_spar' = {box.front_spar!r}"
        )
    layout = (box.front_spar, box.rear_spar, box.beam_axis)
    coordinates = parts["wing"].coordinates
    if coordinates is not None:  # any spar layout inside the chord
        try:
            WingBoxSection.from_file(coordinates, *layout)
        except ValueError as err:
            raise VehicleSpecError(f"'wing_box' with 'wing.coordinates': {err}") from None
        return
    section = WING_BOX_SECTIONS.get(airfoil)
    if section is None or (section.front_spar, section.rear_spar, section.beam_axis) != layout:
        packaged = ", ".join(
            f"{name!r} with front_spar {s.front_spar:g}, rear_spar {s.rear_spar:g}, beam_axis "
            f"{s.beam_axis:g}"
            for name, s in sorted(WING_BOX_SECTIONS.items())
        )
        key = "wing.airfoil" if section is None else "wing_box.front_spar"
        raise VehicleSpecError(
            f"'{key}': the wing box of airfoil {airfoil!r} with front_spar {box.front_spar:g}, "
            f"rear_spar {box.rear_spar:g}, beam_axis {box.beam_axis:g} has no packaged section "
            f"properties; allowed: {packaged}, or any layout with the section's coordinate "
            "file as 'wing.coordinates' (docs theory/structures)"
        )


def _check_mission(mission: Mission, conditions: tuple[DesignCondition, ...]) -> None:
    if not any(c.energy_weight > 0 for c in conditions):
        raise VehicleSpecError(
            "'conditions' has no mission segment: at least one condition needs energy_weight > "
            "0 (the mission's energy and the final state of charge are their sum)"
        )
    for i, c in enumerate(conditions):
        if c.energy_weight > 0 and c.duration <= 0:
            raise VehicleSpecError(
                f"'conditions[{i}].duration' = {c.duration!r} is out of range: a mission "
                f"segment (energy_weight = {c.energy_weight!r} > 0) must last > 0 s; set "
                f"energy_weight = 0 to keep '{c.name}' as a design condition outside the mission"
            )
    if not any(c.kind == "hover" for c in conditions):
        raise VehicleSpecError(
            "'conditions' has no condition of kind 'hover': a lift-plus-cruise vehicle needs "
            "one (its lift rotors are designed for it: their weight, noise and speeds)"
        )
    steady = [c.name for c in conditions if c.kind == "steady"]
    fastest = max((c.speed for c in conditions if c.kind == "steady"), default=None)
    for i, c in enumerate(conditions):
        if c.kind == "transition" and fastest is not None and c.speed > fastest:
            raise VehicleSpecError(
                f"'conditions[{i}].speed' = {c.speed!r} is out of range: a transition point "
                f"must fly no faster than the fastest 'steady' condition, {fastest:g} m/s (the "
                "transition ends where wing-borne flight begins)"
            )
    if mission.cruise_condition not in steady:
        raise VehicleSpecError(
            f"'mission.cruise_condition' = {mission.cruise_condition!r} is not allowed: must be "
            f"the name of a 'steady' condition, one of {steady}"
        )


#: Highest lift coefficient a wing-borne condition may need at the largest wing area the
#: design variables allow: beyond any wing without high-lift devices (section c_l,max of the
#: packaged airfoils 1.4-1.8) and most with them (Raymer, Aircraft Design, Table 12.5: about 3
#: for a wing with double-slotted flaps and slats).
MAX_LIFT_COEFFICIENT = 3.0


def check_flight_speeds(vehicle) -> None:
    """
    Check that every wing-borne condition is fast enough for some wing the design may have.

    A steady (1 g) or structural (load factor n) condition needs lift abs(n) m g from the wing
    alone: 1/2 rho V^2 S_max C_L,max >= abs(n) m g, with m the design gross mass, rho at the
    condition's altitude (ISA), S_max the wing-area design variable's upper bound and C_L,max
    :data:`MAX_LIFT_COEFFICIENT`. Slower, no design within the bounds can fly it (the
    optimizer's stall constraints, docs theory/aerodynamics 'Section lift limit', then hold the
    design's own wing within its polar).
    """
    area = vehicle.design_variables.get("wing_area")
    s_max = max(area.upper) if area is not None else vehicle.wing.area
    weight = vehicle.masses.design_gross_mass * GRAVITY
    for i, c in enumerate(vehicle.conditions):
        if c.kind not in ("steady", "structural"):
            continue
        density = standard_atmosphere(c.altitude, temperature_offset=vehicle.mission.isa_offset)[2]
        least = math.sqrt(
            2.0 * abs(c.load_factor) * weight / (density * s_max * MAX_LIFT_COEFFICIENT)
        )
        if c.speed < least:
            raise VehicleSpecError(
                f"'conditions[{i}].speed' = {c.speed!r} is out of range: the wing-borne "
                f"condition {c.name!r} (load factor {c.load_factor:g}) must fly at >= "
                f"{least:.4g} m/s, where the largest wing the design variables allow "
                f"({s_max:g} m^2) at C_L = {MAX_LIFT_COEFFICIENT:g} carries "
                f"{abs(c.load_factor):g} x the design gross mass "
                f"{vehicle.masses.design_gross_mass:g} kg at {c.altitude:g} m"
            )


class _PartialVehicle:
    """The parts of a vehicle read so far, as attributes (for checks before it is built)."""

    def __init__(self, parts: dict):
        self.__dict__.update(parts)


# ------------------------------------------------------------------------------------------------
# Geometric and energy consistency

#: Largest angle (deg) between a lift rotor's thrust axis and body -z, and between the pusher's
#: thrust axis and body +x (the flight direction). 30 deg admits canted rotors and a tilted
#: pusher; beyond it a lift rotor would not mainly lift nor the pusher mainly push.
MAX_THRUST_AXIS_ANGLE_DEG = 30.0
#: Hubs closer than this (m) share a position.
_SAME_POSITION = 1e-3


def _angle_deg(a, b) -> float:
    cos = float(np.dot(a, b) / (np.linalg.norm(a) * np.linalg.norm(b)))
    return float(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))


def _check_thrust_axes(lift_rotors: tuple[Rotor, ...], pusher: Rotor) -> None:
    """Lift-rotor thrust axes within 30 deg of -z (up), the pusher's within 30 deg of +x."""
    wanted = [
        (f"lift_rotors[{i}]", r, (0.0, 0.0, -1.0), "-z (up)") for i, r in enumerate(lift_rotors)
    ]
    wanted.append(("pusher", pusher, (1.0, 0.0, 0.0), "+x (the flight direction)"))
    for path, rotor, direction, label in wanted:
        angle = _angle_deg(rotor.thrust_axis, direction)
        if angle > MAX_THRUST_AXIS_ANGLE_DEG:
            raise VehicleSpecError(
                f"'{path}.thrust_axis' = {list(rotor.thrust_axis)!r} is out of range: must be "
                f"within {MAX_THRUST_AXIS_ANGLE_DEG:g} deg of body {label}, got {angle:.1f} deg"
            )


def _check_rotor_positions(lift_rotors: tuple[Rotor, ...], pusher: Rotor) -> None:
    """No two hubs at one position; lift-rotor disks at similar height do not overlap.

    Two lift-rotor disks are at similar height when their hubs are closer along the first
    rotor's thrust axis than the smaller radius; their hub distance in that disk plane must then
    be at least R_i + R_j (no clearance is required: the reference's inner and outer rotors are
    0.16 m apart, 5 % of a diameter).
    """
    rotors = _named_rotors(lift_rotors, pusher)
    for k, (path_i, a) in enumerate(rotors):
        for path_j, b in rotors[k + 1 :]:
            d = np.subtract(b.hub_position, a.hub_position)
            if np.linalg.norm(d) < _SAME_POSITION:
                raise VehicleSpecError(
                    f"'{path_j}.hub_position' = {list(b.hub_position)!r} is not allowed: it is "
                    f"the position of '{path_i}.hub_position'; no two rotors share a position"
                )
            if path_j == "pusher":
                continue
            n = np.asarray(a.thrust_axis, dtype=float)
            axial = abs(float(np.dot(d, n)))
            in_plane = float(np.linalg.norm(d - np.dot(d, n) * n))
            if axial < min(a.radius, b.radius) and in_plane < a.radius + b.radius:
                raise VehicleSpecError(
                    f"'{path_j}.hub_position' = {list(b.hub_position)!r} is not allowed: seen "
                    f"along the thrust axis of '{path_i}', its disk (radius {b.radius:g} m) "
                    f"overlaps that one's (radius {a.radius:g} m): hub distance across the axis "
                    f"{in_plane:.3f} m < R_i + R_j = {a.radius + b.radius:.3f} m, with the disks "
                    f"only {axial:.3f} m apart along it (less than the smaller radius), so one "
                    "rotor would run in the other's inflow, which the rotor models do not "
                    "include; allowed: disks side by side or at least a radius apart along the "
                    "axis"
                )


#: Least noise-observer distance in rotor radii: the far-field forms of the noise model drop
#: terms of order R/r against 1; at 10 radii (5 diameters) they are near 10 % (docs
#: theory/acoustics 'Observer geometry'). The reference observer is at 100 m, 66 radii.
FAR_FIELD_RADII = 10.0
#: Largest radius-intersection span fraction (R_inner + R_outer)/b: the two rotors of a side
#: lie side by side within its half span b/2.
MAX_RADIUS_SPAN_FRACTION = 0.5
#: Smallest usable state-of-charge window, initial less final: a narrower window flies the
#: reference mission's hover alone (about 2 % of its energy) and little more.
MIN_SOC_WINDOW = 0.05


def _check_limits(parts: dict) -> None:
    """
    Check the state-of-charge window, the fixed masses and the noise observer.

    The window must be usable, the fixed masses and the battery lighter than the design gross
    mass, the noise observer at least a rotor radius away.
    """
    limits, battery = parts["constraints"], parts["battery"]
    if limits.min_final_soc > battery.initial_soc - MIN_SOC_WINDOW:
        raise VehicleSpecError(
            f"'constraints.min_final_soc' = {limits.min_final_soc!r} is out of range: must be "
            f"<= 'battery.initial_soc' = {battery.initial_soc!r} - {MIN_SOC_WINDOW:g} (the "
            "mission needs a usable state-of-charge window)"
        )
    masses = parts["masses"]
    other = masses.other if masses.other_rule == "fixed" else 0.0  # calibrated: not read
    fixed = masses.payload + masses.systems + other + battery.mass
    if fixed >= masses.design_gross_mass:
        raise VehicleSpecError(
            f"the fixed masses are out of range: 'masses.payload' {masses.payload:g} + "
            f"'masses.systems' {masses.systems:g} + 'masses.other' {other:g} + 'battery.mass' "
            f"{battery.mass:g} = {fixed:g} kg must be < 'masses.design_gross_mass' = "
            f"{masses.design_gross_mass!r} (the airframe, rotors and motors weigh the rest)"
        )
    radius = max(r.radius for r in (*parts["lift_rotors"], parts["pusher"]))
    for k, observer in enumerate(parts["noise_observer"]):
        if observer.distance < FAR_FIELD_RADII * radius:
            raise VehicleSpecError(
                f"'noise_observer[{k}].distance' = {observer.distance!r} is out of range: must "
                f"be >= {FAR_FIELD_RADII:g} x the largest rotor radius {radius:g} = "
                f"{FAR_FIELD_RADII * radius:g} (m); the noise model is a far-field one"
            )
    if limits.noise_broadband_model == "bpm" and parts.get("noise_footprint") is not None:
        raise VehicleSpecError(
            "'constraints.noise_broadband_model' = 'bpm' is not allowed with a "
            "[noise_footprint] table: the footprint hears the rotors through their thrust and "
            "torque alone, which the BPM model (blade-section angles of attack) cannot use; "
            "remove the key (the Gill-Lee model) or the footprint"
        )
    if (
        limits.radius_intersection_definition == "span_fraction"
        and limits.radius_intersection > MAX_RADIUS_SPAN_FRACTION
    ):
        raise VehicleSpecError(
            f"'constraints.radius_intersection' = {limits.radius_intersection!r} is out of "
            f"range: as a span fraction, (R_inner + R_outer)/b, it must be <= "
            f"{MAX_RADIUS_SPAN_FRACTION:g} (two rotors side by side on a half wing span at most "
            "b/2 together); a clearance in m needs radius_intersection_definition = 'clearance'"
        )


def min_tail_cone_length(parts) -> float:
    """
    Shortest tail cone (m): the root chord of the vertical tail, which the tail cone carries.

    The fin of the NASA LPC sits on the tail cone (NASA's OpenVSP model as MCEVS rebuilds it
    attaches it at 0.77 of the fuselage length, its 2.32 m root chord reaching past the tail
    end), and so does the horizontal tail on it; a tail cone shorter than the fin's root chord
    would put the fin's root structure into the cabin.
    """
    return parts["vertical_tail"].root_chord


def min_fuselage_length(parts) -> float:
    """Shortest fuselage that keeps its cabin (m): nose bay + cabin + the shortest tail cone."""
    return parts["fuselage"].cabin_end + min_tail_cone_length(parts)


#: Narrowest seat with its share of the side clearance (m): 0.46 m, the economy seat width of
#: Kundu, Aircraft Design, 2010, Table 4.5 (the reference's two seats abreast in 1.557 m).
MIN_SEAT_WIDTH = 0.46


#: Largest ratio of the fuselage's height to its width or width to height: the drag build-up
#: takes a body of revolution of the mean diameter (form factor of Raymer, Aircraft Design, eq.
#: 12.31) and the M4 weight regression a fuselage of its wetted area; the reference's is 1.08,
#: built cabins 0.8-1.3.
MAX_SECTION_ASPECT = 2.0


def _check_fuselage_section(fuselage) -> None:
    """Check a near-round cross-section (:data:`MAX_SECTION_ASPECT`)."""
    ratio = fuselage.max_height / fuselage.max_width
    if not 1.0 / MAX_SECTION_ASPECT <= ratio <= MAX_SECTION_ASPECT:
        raise VehicleSpecError(
            f"'fuselage.max_height' = {fuselage.max_height!r} is out of range with "
            f"'fuselage.max_width' = {fuselage.max_width!r}: the height over the width, "
            f"{ratio:.3g}, must be in [{1.0 / MAX_SECTION_ASPECT:g}, {MAX_SECTION_ASPECT:g}] "
            "(a near-round body, as the fuselage drag and weight models take it)"
        )


def _check_cabin(parts: dict) -> None:
    """Check that the fuselage holds nose bay, cabin and tail cone, and the cabin its seats."""
    fuselage = parts["fuselage"]
    if fuselage.seats_abreast * MIN_SEAT_WIDTH > fuselage.max_width:
        raise VehicleSpecError(
            f"'fuselage.seats_abreast' = {fuselage.seats_abreast} is out of range: "
            f"{fuselage.seats_abreast} seats of at least {MIN_SEAT_WIDTH:g} m (Kundu, Aircraft "
            f"Design, Table 4.5) need a fuselage wider than 'fuselage.max_width' = "
            f"{fuselage.max_width:g} (m)"
        )
    shortest = min_fuselage_length(parts)
    if fuselage.length < shortest:
        raise VehicleSpecError(
            f"'fuselage.length' = {fuselage.length!r} is out of range: must be >= "
            f"{shortest:.4f} (m) = fuselage.nose_length {fuselage.nose_length:g} + cabin "
            f"{fuselage.cabin_length:.4f} ({fuselage.seat_rows} rows of fuselage.seat_pitch "
            f"{fuselage.seat_pitch:g}) + the shortest tail cone "
            f"{min_tail_cone_length(parts):.4f} (the vertical tail's root chord)"
        )
    # Equipment stays out of the cabin: the battery (file), NASA's gear and systems stations.
    cabin = (
        f"the cabin, x in [-{fuselage.cabin_end:.4f}, -{fuselage.cabin_start:.4f}] (m) and z < "
        f"fuselage.cabin_floor_z = {fuselage.cabin_floor_z:g}"
    )
    battery = parts["battery"].cg
    if fuselage.in_cabin(battery):
        raise VehicleSpecError(
            f"'battery.cg' = {battery!r} is out of range: it lies in {cabin}; allowed: the nose "
            "bay, under the cabin floor (larger z) or the tail cone"
        )
    stations = (
        ("the landing gear", NASA_LANDING_GEAR_STATION),
        ("the systems", NASA_SYSTEMS_STATION),
    )
    for what, position in stations:
        if fuselage.in_cabin(position):
            raise VehicleSpecError(
                f"'fuselage.seat_pitch' = {fuselage.seat_pitch!r} with 'fuselage.nose_length' = "
                f"{fuselage.nose_length!r} is out of range: {cabin} then covers NASA's station "
                f"of {what} at {tuple(round(float(v), 4) for v in position)} (m); allowed: a "
                "cabin that leaves the equipment in the nose bay, under the floor or in the "
                "tail cone"
            )
    payload = parts["masses"].payload_cg
    if not fuselage.in_cabin(payload):
        raise VehicleSpecError(
            f"'masses.payload_cg' = {payload!r} is out of range: the seats must be in the "
            f"cabin, x in [-{fuselage.cabin_end:.4f}, -{fuselage.cabin_start:.4f}] (m) and z < "
            f"fuselage.cabin_floor_z = {fuselage.cabin_floor_z:g}"
        )


def _check_geometry(parts: dict) -> None:
    """
    Check the geometry across parts.

    Thrust axes, rotor positions, the fuselage's section (first: the other parts are placed
    against it), the parts on the airframe (:mod:`lpc_mdo.vehicle.airframe`), blade chords, the
    cabin and the energy and noise limits (see above).
    """
    _check_thrust_axes(parts["lift_rotors"], parts["pusher"])
    _check_rotor_positions(parts["lift_rotors"], parts["pusher"])
    _check_fuselage_section(parts["fuselage"])
    check_airframe(parts)
    _check_blades(parts["lift_rotors"], parts["pusher"])
    _check_cabin(parts)
    _check_limits(parts)
    _check_buildable(parts)
    _check_condition_names(parts["conditions"])


def _check_wing(wing: Wing) -> Wing:
    """Check the wing's planform keys; return the wing with the sections' taper ratio set.

    ``planform = "trapezoid"`` needs ``taper_ratio`` and no ``sections``; ``planform =
    "sections"`` needs ``sections`` (each starting with the previous one's tip chord) and no
    ``taper_ratio`` (it is the sections' tip over root chord).
    """
    if wing.planform == "trapezoid":
        if wing.taper_ratio is None:
            raise VehicleSpecError(
                "missing key 'wing.taper_ratio' (number, in (0, 1]; required with "
                "wing.planform = 'trapezoid')"
            )
        if wing.sections is not None:
            raise VehicleSpecError(
                "'wing.sections' is given with wing.planform = 'trapezoid'; allowed: "
                "[[wing.sections]] only with planform = 'sections' (or remove them)"
            )
        return wing
    if wing.sections is None:
        raise VehicleSpecError(
            "missing key 'wing.sections' (list of [[wing.sections]] tables, root to tip; "
            "required with wing.planform = 'sections')"
        )
    if wing.taper_ratio is not None:
        raise VehicleSpecError(
            f"'wing.taper_ratio' = {wing.taper_ratio!r} is given with wing.planform = "
            "'sections'; allowed: no taper_ratio (the sections' chords set the taper), or "
            "planform = 'trapezoid'"
        )
    for k in range(1, len(wing.sections)):
        root, tip = wing.sections[k].root_chord, wing.sections[k - 1].tip_chord
        if not np.isclose(root, tip, rtol=1e-6, atol=0.0):
            raise VehicleSpecError(
                f"'wing.sections[{k}].root_chord' = {root!r} differs from "
                f"'wing.sections[{k - 1}].tip_chord' = {tip!r}; allowed: equal (within 1e-6), "
                "a section starts where the previous one ends"
            )
    taper = wing.sections[-1].tip_chord / wing.sections[0].root_chord
    return dataclasses.replace(wing, taper_ratio=taper)


def check_across_parts(vehicle) -> None:
    """
    Re-check a vehicle built another way than from a file (a sweep's) across its parts.

    The geometry, mass and energy rules and the mission rules of a vehicle file
    (:func:`_check_geometry`, :func:`_check_mission`).

    Raises
    ------
    VehicleSpecError
        At the first rule broken, naming the key.
    """
    parts = {f.name: getattr(vehicle, f.name) for f in dataclasses.fields(vehicle)}
    _check_geometry(parts)
    _check_mission(parts["mission"], parts["conditions"])
    check_flight_speeds(vehicle)
