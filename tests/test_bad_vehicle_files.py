"""Bad vehicle files: each is one VehicleSpecError that names the key, never a traceback.

Issue 18 item 1: values that passed the type check and broke the model later (or ran on
nonsense), geometric inconsistencies, malformed polar files and files that are not UTF-8 TOML.
Each case mutates the reference vehicle (its dict or its file text) and asserts the exception
type, that the message names the key and a fragment that says what is wrong.
"""

import copy
import importlib.util
import math
import os
import zipfile
from importlib import resources
from pathlib import Path

import numpy as np
import pytest

from lpc_mdo.vehicle import (
    VehicleSpecError,
    load_vehicle,
    read_vehicle_file,
    reference_vehicle,
    vehicle_from_dict,
)

REFERENCE_TEXT = (
    resources.files("lpc_mdo").joinpath("data", "lpc_reference.toml").read_text("utf-8")
)
REFERENCE_DATA = read_vehicle_file()
CRUISE = 7  # index of the cruise condition in the reference file
H = math.sqrt(0.5)


def _set(*keys_and_value):
    """Return a mutator that sets data[k0][k1]... = value."""
    *keys, value = keys_and_value

    def mutate(d):
        for key in keys[:-1]:
            d = d[key]
        d[keys[-1]] = value

    return mutate


def _all_lift_rotors(key, value):
    def mutate(d):
        for rotor in d["lift_rotors"]:
            rotor[key] = copy.deepcopy(value)

    return mutate


def _mirror_pair(i, j, key, value):
    """Set rotor i's key to value and its mirror partner j's to the y-mirrored value."""

    def mutate(d):
        d["lift_rotors"][i][key] = list(value)
        d["lift_rotors"][j][key] = [value[0], -value[1], value[2]]

    return mutate


def _both(*mutators):
    def mutate(d):
        for m in mutators:
            m(d)

    return mutate


def _airframe_cases():
    """Families of parts off the airframe: each mass item, surface, rotor and boom moved out."""
    cases = []
    far = {"ahead of the nose": (0, 3.0), "behind the tail": (0, -15.0)}
    far_z = {"far above": (2, -8.0), "far below": (2, 8.0)}
    items = {
        "battery.cg": ("battery", "cg"),
        "masses.payload_cg": ("masses", "payload_cg"),
        "masses.systems_cg": ("masses", "systems_cg"),
        "masses.other_cg": ("masses", "other_cg"),
        "masses.power_electronics_cg": ("masses", "power_electronics_cg"),
    }
    for key, (table, field) in items.items():
        base = REFERENCE_DATA[table][field]
        for where, (axis, value) in {**far, **far_z, "beyond the wing tip": (1, 9.0)}.items():
            moved = list(base)
            moved[axis] = value
            fragment = {0: "nose to tail end", 1: "half span", 2: "must lie at z in"}[axis]
            if key == "masses.payload_cg" and axis == 1:  # in the cabin, not only the span
                fragment = "within half the fuselage width"
            cases.append((f"{key} {where}", _set(table, field, moved), key, fragment))
    for surface in ("wing", "horizontal_tail", "vertical_tail"):
        base = REFERENCE_DATA[surface]["root_leading_edge"]
        for where, (axis, value) in {**far, **far_z, "off the symmetry plane": (1, 0.5)}.items():
            moved = list(base)
            moved[axis] = value
            fragment = {0: "nose to tail end", 1: "symmetry plane", 2: "must lie at z in"}[axis]
            key = f"{surface}.root_leading_edge"
            cases.append(
                (f"{key} {where}", _set(surface, "root_leading_edge", moved), key, fragment)
            )
    for i, j in ((0, 6), (1, 7), (2, 4), (3, 5)):  # each lift-rotor pair, mirrored
        hub = REFERENCE_DATA["lift_rotors"][i]["hub_position"]
        for where, moved, fragment in (
            ("beyond the wing tip", [hub[0], -12.0, hub[2]], "half span"),
            ("ahead of the nose", [4.0, hub[1], hub[2]], "nose to tail end"),
            ("behind the tail", [-14.0, hub[1], hub[2]], "nose to tail end"),
        ):
            key = f"lift_rotors[{i}].hub_position"
            cases.append(
                (f"{key} {where}", _mirror_pair(i, j, "hub_position", moved), key, fragment)
            )
    for k in range(8):  # each boom attach point far from its rotor
        point = list(REFERENCE_DATA["booms"]["attach_points"][k])
        point[1] = -point[1] if abs(point[1]) > 1.0 else point[1] + 3.0
        key = f"booms.attach_points[{k}]"
        cases.append((f"{key} away from its rotor", _set("booms", "attach_points", k, point), key,
                      "within a rotor radius"))  # fmt: skip
    for i, c in enumerate(REFERENCE_DATA["conditions"]):  # each mission segment of 0 s
        if c["energy_weight"] > 0:
            key = f"conditions[{i}].duration"
            cases.append((f"{c['name']} of 0 s", _set("conditions", i, "duration", 0.0), key,
                          "must last > 0 s"))  # fmt: skip
    for i in range(8):  # each lift rotor's blades wider than half the radius
        rotors = REFERENCE_DATA["lift_rotors"]
        partner = next(j for j, r in enumerate(rotors) if r["pair"] == rotors[i]["pair"] and j != i)
        wide = [0.9, 0.8, 0.7, 0.6]
        first = min(i, partner)
        cases.append((
            f"lift_rotors[{i}] blades wider than half the radius",
            _both(_set("lift_rotors", i, "chord_cp", wide),
                  _set("lift_rotors", partner, "chord_cp", wide)),
            f"lift_rotors[{first}].chord_cp",
            "slender blade",
        ))  # fmt: skip
    return cases


def _hub(i):
    return REFERENCE_DATA["lift_rotors"][i]["hub_position"]


# (id, mutation, key the message names, fragment of what is wrong)
DICT_CASES = [
    # The values issue 18 lists (passed validation, failed or ran on nonsense later)
    (
        "max_height 1e30",
        _set("fuselage", "max_height", 1e30),
        "fuselage.max_height",
        "in [0.5, 10] (m)",
    ),
    (
        "max_height in mm",
        _set("fuselage", "max_height", 1688.0),
        "fuselage.max_height",
        "out of range",
    ),
    ("payload 1e30", _set("masses", "payload", 1e30), "masses.payload", "in [50, 10000] (kg)"),
    ("density 1e30", _set("material", "density", 1e30), "material.density", "in [500, 20000]"),
    (
        "target mass 100",
        _set("masses", "design_gross_mass", 100.0),
        "masses.design_gross_mass",
        "in [500, 20000] (kg)",
    ),
    (
        "num_blades 1e6",
        _set("lift_rotors", 0, "num_blades", 1000000),
        "lift_rotors[0].num_blades",
        "in [2, 8]",
    ),
    (
        "E 1e30",
        _set("material", "youngs_modulus", 1e30),
        "material.youngs_modulus",
        "in [1e+09, 1e+12] (Pa)",
    ),
    (
        "G 1 Pa",
        _set("material", "shear_modulus", 1.0),
        "material.shear_modulus",
        "in [1e+09, 5e+11] (Pa)",
    ),
    (
        "cruise duration 1e30",
        _set("conditions", CRUISE, "duration", 1e30),
        f"conditions[{CRUISE}].duration",
        "(s)",
    ),
    (
        "energy density 1e30",
        _set("battery", "energy_density_wh_per_kg", 1e30),
        "battery.energy_density_wh_per_kg",
        "in [50, 1000] (Wh/kg)",
    ),
    (
        "energy density in J/kg",
        _set("battery", "energy_density_wh_per_kg", 400.0 * 3600),
        "battery.energy_density_wh_per_kg",
        "in [50, 1000]",
    ),
    ("other mass 1e30", _set("masses", "other", 1e30), "masses.other", "in [0, 10000] (kg)"),
    (
        "observer 1e-9 m",
        _set("noise_observer", "distance", 1e-9),
        "noise_observer.distance",
        "must be >= 10 x the largest rotor radius",
    ),
    (
        "voltage 0.001 V",
        _set("motor", "voltage_limit", 0.001),
        "motor.voltage_limit",
        "in [24, 3000] (V)",
    ),
    (
        "pitch DV rad with degrees",
        _set("design_variables", "climb_pitch", "units", "rad"),
        "design_variables.climb_pitch.lower",
        "degree values need units = 'deg'",
    ),
    (
        "lift rotors thrust forward",
        _all_lift_rotors("thrust_axis", [1.0, 0.0, 0.0]),
        "lift_rotors[0].thrust_axis",
        "within 30 deg of body -z (up), got 90.0 deg",
    ),
    (
        "lift rotors thrust down",
        _all_lift_rotors("thrust_axis", [0.0, 0.0, 1.0]),
        "lift_rotors[0].thrust_axis",
        "got 180.0 deg",
    ),
    (
        "lift rotors tilted 45 deg",
        _all_lift_rotors("thrust_axis", [H, 0.0, -H]),
        "lift_rotors[0].thrust_axis",
        "got 45.0 deg",
    ),
    (
        "pusher thrusts backwards",
        _set("pusher", "thrust_axis", [-1.0, 0.0, 0.0]),
        "pusher.thrust_axis",
        "within 30 deg of body +x",
    ),
    (
        "pusher thrusts up",
        _set("pusher", "thrust_axis", [0.0, 0.0, -1.0]),
        "pusher.thrust_axis",
        "got 90.0 deg",
    ),
    (
        "two lift rotors at one position",
        _both(_mirror_pair(2, 4, "hub_position", _hub(0))),
        "lift_rotors[2].hub_position",
        "no two rotors share a position",
    ),
    (
        "lift disks overlap",
        _mirror_pair(2, 4, "hub_position", [-0.66020, -4.0, -0.77602]),
        "lift_rotors[2].hub_position",
        "overlaps that one's",
    ),
    (
        "front and rear disks overlap",
        _mirror_pair(1, 7, "hub_position", [-2.0, -5.715, -0.9]),
        "lift_rotors[1].hub_position",
        "R_i + R_j = 3.048 m",
    ),
    (
        "pusher at a lift hub",
        _set("pusher", "hub_position", list(_hub(0))),
        "pusher.hub_position",
        "share a position",
    ),
    (
        "min_final_soc above initial_soc",
        _both(_set("battery", "initial_soc", 0.5), _set("constraints", "min_final_soc", 0.6)),
        "constraints.min_final_soc",
        "must be <= 'battery.initial_soc' = 0.5 - 0.05",
    ),
    (
        "min_final_soc = initial_soc",
        _both(_set("battery", "initial_soc", 0.3), _set("constraints", "min_final_soc", 0.3)),
        "constraints.min_final_soc",
        "must be <",
    ),
    (
        "observer inside the rotors' near field",
        _set("noise_observer", "distance", 12.0),
        "noise_observer.distance",
        "10 x the largest rotor radius 1.524 = 15.24 (m)",
    ),
    # Further plausibility ranges (units mistaken, or absurd magnitudes)
    ("wing area 1e30", _set("wing", "area", 1e30), "wing.area", "in [0.1, 200] (m^2)"),
    ("wing area in ft^2", _set("wing", "area", 211.0), "wing.area", "out of range"),
    ("tail area 0", _set("horizontal_tail", "area", 0.0), "horizontal_tail.area", "in [0.1, 200]"),
    (
        "aspect ratio 1000",
        _set("wing", "aspect_ratio", 1000.0),
        "wing.aspect_ratio",
        "in [0.5, 30]",
    ),
    (
        "fin sweep 89 deg",
        _set("vertical_tail", "sweep_deg", 89.0),
        "vertical_tail.sweep_deg",
        "in [-70, 70] (deg)",
    ),
    (
        "dihedral 45 deg",
        _set("wing", "dihedral_deg", 45.0),
        "wing.dihedral_deg",
        "in [-30, 30] (deg)",
    ),
    (
        "wing LE in mm",
        _set("wing", "root_leading_edge", [-1959.25, 0.0, -1072.9]),
        "wing.root_leading_edge[0]",
        "in [-50, 50] (m)",
    ),
    (
        "fuselage length in mm",
        _set("fuselage", "length", 9144.0),
        "fuselage.length",
        "in [1, 30] (m)",
    ),
    (
        "fuselage width 1e-3",
        _set("fuselage", "max_width", 1e-3),
        "fuselage.max_width",
        "in [0.5, 10]",
    ),
    # The cabin (nose bay, seats) and the fuselage_length bounds that follow from it.
    (
        "nose length in mm",
        _set("fuselage", "nose_length", 1112.16),
        "fuselage.nose_length",
        "in [0.3, 10] (m)",
    ),
    ("no seats", _set("fuselage", "seats", 0), "fuselage.seats", "in [1, 100]"),
    ("2.5 seats", _set("fuselage", "seats", 2.5), "fuselage.seats", "integer"),
    (
        "20 seats abreast",
        _set("fuselage", "seats_abreast", 20),
        "fuselage.seats_abreast",
        "in [1, 10]",
    ),
    (
        "seat pitch in inches",
        _set("fuselage", "seat_pitch", 36.0),
        "fuselage.seat_pitch",
        "in [0.7, 1.5] (m)",
    ),
    (
        "cabin floor in mm",
        _set("fuselage", "cabin_floor_z", 531.88),
        "fuselage.cabin_floor_z",
        "in [-10, 10] (m)",
    ),
    (
        "18 seats in a 9 m fuselage",
        _set("fuselage", "seats", 18),
        "fuselage.length",
        "must be >= 11.6584 (m)",
    ),
    (
        "seats ahead of the cabin",
        _set("masses", "payload_cg", [-0.5, 0.0, 0.05844]),
        "masses.payload_cg",
        "the seats must be in the cabin",
    ),
    (
        "battery in the cabin",
        _set("battery", "cg", [-2.09897, 0.0, 0.0]),
        "battery.cg",
        "allowed: the nose bay, under the cabin floor",
    ),
    (
        "cabin over the systems bay",
        _set("fuselage", "seat_pitch", 1.1),
        "fuselage.seat_pitch",
        "covers NASA's station of the systems",
    ),
    (
        "fuselage shorter than its cabin",
        _set("design_variables", "fuselage_length", "lower", 6.0),
        "design_variables.fuselage_length.lower",
        "must be >= 6.4008 (m; the lower end of the M4 regressions' data range)",
    ),
    (
        # A fin of 5 m^2 has a 3.2504 m root chord: 3.85536 + 3.2504 = 7.1057 m.
        "fuselage bound cuts into the cabin",
        _set("fuselage", "seat_pitch", 1.0),
        "design_variables.fuselage_length.lower",
        "must be >= 6.42884 (m; fuselage.nose_length + cabin + shortest tail cone)",
    ),
    (
        "fuselage beyond the regression data",
        _set("design_variables", "fuselage_length", "upper", 13.0),
        "design_variables.fuselage_length.upper",
        "must be <= 11.8872 (m; the upper end of the M4 regressions' data range)",
    ),
    (
        "rotor radius in mm",
        _set("lift_rotors", 3, "radius", 1524.0),
        "lift_rotors[3].radius",
        "in [0.1, 10] (m)",
    ),
    (
        "rotor radius 1 mm",
        _set("lift_rotors", 3, "radius", 1e-3),
        "lift_rotors[3].radius",
        "in [0.1, 10]",
    ),
    ("pusher one blade", _set("pusher", "num_blades", 1), "pusher.num_blades", "in [2, 8]"),
    ("pusher 12 blades", _set("pusher", "num_blades", 12), "pusher.num_blades", "in [2, 8]"),
    (
        "chord in mm",
        _set("lift_rotors", 1, "chord_cp", [300.0, 233.0, 167.0, 100.0]),
        "lift_rotors[1].chord_cp[0]",
        "in (0, 2] (m)",
    ),
    (
        "hub ratio 0.9",
        _set("lift_rotors", 0, "hub_radius_ratio", 0.9),
        "lift_rotors[0].hub_radius_ratio",
        "in [0, 0.5]",
    ),
    (
        "hub position in mm",
        _set("lift_rotors", 0, "hub_position", [-794.31, -5715.0, -683.36]),
        "lift_rotors[0].hub_position[0]",
        "in [-50, 50] (m)",
    ),
    ("boom length in mm", _set("booms", "length", 2438.4), "booms.length", "in [0.1, 30] (m)"),
    ("boom form factor 0.5", _set("booms", "form_factor", 0.5), "booms.form_factor", "in [1, 3]"),
    (
        "attach point 1e30",
        _set("booms", "attach_points", 0, [1e30, 0.0, 0.0]),
        "booms.attach_points[0][0]",
        "in [-50, 50]",
    ),
    ("1000 bays", _set("wing_box", "num_bays", 1000), "wing_box.num_bays", "in [1, 50]"),
    ("systems 1e30", _set("masses", "systems", 1e30), "masses.systems", "in [0, 10000] (kg)"),
    (
        "inverter specific power in W/kg",
        _set("motor", "inverter_specific_power_kw_per_kg", 19000.0),
        "motor.inverter_specific_power_kw_per_kg",
        "in [1, 100]",
    ),
    (
        "cable mass in g/(A m)",
        _set("motor", "cable_mass_per_ampere_metre", 2.405),
        "motor.cable_mass_per_ampere_metre",
        "in [0.0001, 0.01]",
    ),
    (
        "voltage margin in percent",
        _set("constraints", "min_voltage_margin", 5.0),
        "constraints.min_voltage_margin",
        "in [0, 1]",
    ),
    (
        "payload cg 1e30",
        _set("masses", "payload_cg", [1e30, 0.0, 0.0]),
        "masses.payload_cg[0]",
        "in [-50, 50] (m)",
    ),
    (
        "target mass 1e9",
        _set("masses", "design_gross_mass", 1e9),
        "masses.design_gross_mass",
        "in [500, 20000]",
    ),
    (
        "density in g/cm^3",
        _set("material", "density", 2.7),
        "material.density",
        "in [500, 20000] (kg/m^3)",
    ),
    ("E in GPa", _set("material", "youngs_modulus", 69.0), "material.youngs_modulus", "(Pa)"),
    ("G in GPa", _set("material", "shear_modulus", 26.0), "material.shear_modulus", "(Pa)"),
    (
        "stress in MPa",
        _set("material", "allowable_stress", 350.0),
        "material.allowable_stress",
        "in [1e+06, 1e+10] (Pa)",
    ),
    (
        "min gauge in mm",
        _set("material", "min_gauge", 0.3),
        "material.min_gauge",
        "in [1e-05, 0.05] (m)",
    ),
    ("battery 1e30 kg", _set("battery", "mass", 1e30), "battery.mass", "in [1, 20000] (kg)"),
    (
        "energy density 10",
        _set("battery", "energy_density_wh_per_kg", 10.0),
        "battery.energy_density_wh_per_kg",
        "in [50, 1000]",
    ),
    (
        "battery cg in mm",
        _set("battery", "cg", [-2098.97, 0.0, 558.44]),
        "battery.cg[0]",
        "in [-50, 50]",
    ),
    ("gear ratio 1e6", _set("motor", "gear_ratio", 1e6), "motor.gear_ratio", "in [0.1, 50]"),
    (
        "rated current 1e9 A",
        _set("motor", "rated_current", 1e9),
        "motor.rated_current",
        "in [1, 5000] (A)",
    ),
    (
        "magnetic loading 85 T",
        _set("motor", "magnetic_loading", 85.0),
        "motor.magnetic_loading",
        "in [0.1, 2.5] (T)",
    ),
    (
        "electric loading in kA/m",
        _set("motor", "electric_loading", 30.0),
        "motor.electric_loading",
        "(A/m)",
    ),
    (
        "torque density 1e6",
        _set("motor", "torque_density", 1e6),
        "motor.torque_density",
        "in [1, 100] (N*m/kg)",
    ),
    ("1000 pole pairs", _set("motor", "pole_pairs", 1000), "motor.pole_pairs", "in [1, 50]"),
    (
        "L/D 100",
        _set("motor", "length_to_diameter", 100.0),
        "motor.length_to_diameter",
        "in [0.05, 5]",
    ),
    ("altitude 1e30", _set("conditions", 0, "altitude", 1e30), "conditions[0].altitude", "(m)"),
    (
        "speed in km/h",
        _set("conditions", CRUISE, "speed", 205.9),
        f"conditions[{CRUISE}].speed",
        "(m/s)",
    ),
    (
        "negative duration",
        _set("conditions", 0, "duration", -1.0),
        "conditions[0].duration",
        "out of range",
    ),
    (
        "noise limit 1e30",
        _set("constraints", "max_noise", 1e30),
        "constraints.max_noise",
        "in [20, 200] (dBA)",
    ),
    (
        "torque margin 10",
        _set("constraints", "min_torque_margin", 10.0),
        "constraints.min_torque_margin",
        "in [0, 1]",
    ),
    (
        "displacement in mm",
        _set("constraints", "max_displacement", 500.0),
        "constraints.max_displacement",
        "(m)",
    ),
    (
        "supersonic pusher tip",
        _set("constraints", "max_pusher_tip_mach", 1.2),
        "constraints.max_pusher_tip_mach",
        "in (0, 0.9]",
    ),
    (
        "lift-rotor tip Mach limit 0",
        _set("constraints", "max_lift_rotor_tip_mach", 0.0),
        "constraints.max_lift_rotor_tip_mach",
        "in (0, 0.9]",
    ),
    (
        "minimum chord in percent",
        _set("constraints", "min_chord_radius_ratio", 3.0),
        "constraints.min_chord_radius_ratio",
        "in [0, 0.5]",
    ),
    (
        "stall lift fraction in percent",
        _set("constraints", "wing_stall_lift_fraction", 90.0),
        "constraints.wing_stall_lift_fraction",
        "in (0, 1]",
    ),
    (
        "stall speed ratio below 1",
        _set("constraints", "min_stall_speed_ratio", 0.8),
        "constraints.min_stall_speed_ratio",
        "in [1, 2]",
    ),
    (
        "buckling ratio 1e30",
        _set("constraints", "max_buckling_ratio", 1e30),
        "constraints.max_buckling_ratio",
        "in (0, 10]",
    ),
    (
        "rotor clearance in mm",
        _set("constraints", "min_lift_rotor_clearance", 50.8),
        "constraints.min_lift_rotor_clearance",
        "in [0, 10] (m)",
    ),
    (
        "negative fuselage clearance",
        _set("constraints", "min_rotor_fuselage_clearance", -0.1),
        "constraints.min_rotor_fuselage_clearance",
        "in [0, 10] (m)",
    ),
    (
        "tail clearance missing",
        lambda d: d["constraints"].pop("min_rotor_tail_clearance"),
        "constraints.min_rotor_tail_clearance",
        "missing",
    ),
    (
        "pusher clearance as text",
        _set("constraints", "min_rotor_pusher_clearance", "2 in"),
        "constraints.min_rotor_pusher_clearance",
        "number",
    ),
    (
        "control acceleration in deg/s^2",
        _set("constraints", "min_control_acceleration", [8.0, 6.0, 25.0]),
        "constraints.min_control_acceleration[2]",
        "in [0, 20] (rad/s^2)",
    ),
    (
        "control acceleration of two axes",
        _set("constraints", "min_control_acceleration", [0.14, 0.1]),
        "constraints.min_control_acceleration",
        "3",
    ),
    ("observer 1e30 m", _set("noise_observer", "distance", 1e30), "noise_observer.distance", "(m)"),
    ("NaN wing area", _set("wing", "area", float("nan")), "wing.area", "nan"),
    (
        "inf energy density",
        _set("battery", "energy_density_wh_per_kg", float("inf")),
        "battery.energy_density_wh_per_kg",
        "inf",
    ),
    # Parts off the airframe and masses that do not add up (lpc_mdo.vehicle.airframe and the
    # limits of lpc_mdo.vehicle.consistency), as a new user's files had them.
    *[
        (
            f"horizontal tail at x = {x} m",
            _set("horizontal_tail", "root_leading_edge", [x, 0.0, -0.88]),
            "horizontal_tail.root_leading_edge",
            fragment,
        )
        for x, fragment in (
            (-1.0, "behind the wing's root trailing edge"),
            (3.0, "nose to tail end"),
            (-29.0, "nose to tail end"),
        )
    ],
    (
        "fin at the nose",
        _set("vertical_tail", "root_leading_edge", [-0.5, 0.0, -0.89]),
        "vertical_tail.root_leading_edge",
        "behind the wing's root trailing edge",
    ),
    (
        "wing off the symmetry plane",
        _set("wing", "root_leading_edge", [-1.96, 1.0, -1.07]),
        "wing.root_leading_edge",
        "symmetry plane",
    ),
    (
        "wing 5 m below the datum",
        _set("wing", "root_leading_edge", [-1.96, 0.0, 5.0]),
        "wing.root_leading_edge",
        "must lie at z in",
    ),
    (
        "lift rotors beyond the wing tips",
        _mirror_pair(0, 6, "hub_position", [-0.79431, -20.0, -0.68336]),
        "lift_rotors[0].hub_position",
        "half span",
    ),
    (
        "lift rotors ahead of the nose",
        _mirror_pair(0, 6, "hub_position", [2.0, -5.715, -0.68336]),
        "lift_rotors[0].hub_position",
        "nose to tail end",
    ),
    (
        "pusher ahead of the nose",
        _set("pusher", "hub_position", [2.0, 0.0, -0.816]),
        "pusher.hub_position",
        "the pusher must sit at the tail",
    ),
    (
        "pusher at the wing tip",
        _set("pusher", "hub_position", [-9.19, 7.0, -0.816]),
        "pusher.hub_position",
        "the pusher must sit at the tail",
    ),
    (
        "boom attach point 30 m outboard",
        _set("booms", "attach_points", 0, [-2.937, -30.0, -0.761]),
        "booms.attach_points[0]",
        "within a rotor radius",
    ),
    (
        "battery 16 m behind the tail",
        _set("battery", "cg", [-25.0, 0.0, 0.558]),
        "battery.cg",
        "nose to tail end",
    ),
    (
        "payload 40 m ahead",
        _set("masses", "payload_cg", [40.0, 0.0, 0.05]),
        "masses.payload_cg",
        "nose to tail end",
    ),
    (
        "power electronics 20 m down",
        _set("masses", "power_electronics_cg", [-0.25, 0.0, 20.0]),
        "masses.power_electronics_cg",
        "must lie at z in",
    ),
    (
        "systems 30 m to the side",
        _set("masses", "systems_cg", [-0.25, 30.0, 0.05]),
        "masses.systems_cg",
        "half span",
    ),
    (
        "wing sections as full span",
        lambda d: [sec.update(span=2 * sec["span"]) for sec in d["wing"]["sections"]],
        "wing.sections",
        "within a factor 1.4",
    ),
    (
        "blade chord longer than the radius",
        _all_lift_rotors("chord_cp", [1.9, 1.6, 1.2, 0.8]),
        "lift_rotors[0].chord_cp",
        "slender blade",
    ),
    (
        "blade twisted 89 deg",
        _all_lift_rotors("twist_cp_deg", [89.0, 60.0, 40.0, 10.0]),
        "lift_rotors[0].twist_cp_deg[0]",
        "[-80, 80]",
    ),
    (
        "payload above the design gross mass",
        _set("masses", "payload", 5000.0),
        "masses.payload",
        "must be < 'masses.design_gross_mass'",
    ),
    (
        "cruise of 0 s",
        _set("conditions", CRUISE, "duration", 0.0),
        f"conditions[{CRUISE}].duration",
        "must last > 0 s",
    ),
    (
        "transition of 0 s",
        _set("conditions", 1, "duration", 0.0),
        "conditions[1].duration",
        "must last > 0 s",
    ),
    *_airframe_cases(),
    *[
        (
            f"design-variable ref {ref:g}",
            _set("design_variables", "wing_area", "ref", ref),
            "design_variables.wing_area.ref",
            "must be within a factor 1000 of the bounds' magnitude",
        )
        for ref in (1e-300, 1e-3, 1e5, 1e300)
    ],
    (
        "climb sharing the cruise prefix, its own tables left",
        _set("conditions", 6, "design_variable_prefix", "cruise"),
        "design_variables.climb_pusher_rpm",
        "has design_variable_prefix = 'cruise', so its design variables are the 'cruise_*'",
    ),
    *[
        (f"a key with {what}", _set("wing", key, 19.6), shown, fragment)
        for what, key, shown, fragment in (
            ("a Cyrillic a", "\u0430rea", "wing.\u0430rea", "U+0430, which only looks like"),
            ("a zero-width space", "area\u200b", "wing.area\\u200b", "U+200B"),
            ("a terminal escape", "\x1b[31marea", "wing.\\x1b[31marea", "U+001B"),
            ("a million characters", "x" * 10**6, "wing." + "x" * 55, "(1000005 characters)"),
        )
    ],
    (
        "rear inner lift disks through the cabin",
        _mirror_pair(3, 5, "hub_position", [-3.6, -1.6, -0.9]),
        "lift_rotors[3].hub_position",
        "cuts through the fuselage",
    ),
    (
        "rear inner lift disks through the pusher disk",
        _mirror_pair(3, 5, "hub_position", [-8.5, -2.0, -1.38]),
        "lift_rotors[3].hub_position",
        "and the pusher disk",
    ),
    *[
        (
            f"pusher disk at x = {x} m, inside the body's length",
            _set("pusher", "hub_position", [x, 0.0, -0.816]),
            "pusher.hub_position",
            "cuts through the fuselage",
        )
        for x in (-4.5, -8.0)
    ],
    # Disks through a surface, a fin under the belly, booms that do not reach their rotors.
    (
        "outer lift rotors in the wing",
        _both(
            _mirror_pair(0, 6, "hub_position", [-2.9, -5.715, -0.85]),
            _mirror_pair(1, 7, "hub_position", [-6.0, -5.715, -1.37831]),
        ),
        "lift_rotors[0].hub_position",
        "cuts through the wing",
    ),
    (
        "rear inner lift rotors in the h-tail plane",
        _mirror_pair(3, 5, "hub_position", [-7.6, -2.6, -0.88]),
        "lift_rotors[3].hub_position",
        "cuts through the horizontal tail",
    ),
    (
        "fin reaching back through the pusher disk",
        _set("vertical_tail", "root_leading_edge", [-6.99774, 0.0, -0.89454]),
        "pusher.hub_position",
        "cuts through the fin",
    ),
    (
        "fin root under the belly",
        _set("vertical_tail", "root_leading_edge", [-6.36517, 0.0, 1.3]),
        "vertical_tail.root_leading_edge",
        "at or above the fuselage's bottom",
    ),
    (
        "booms in ft",
        _set("booms", "length", 8.0),
        "booms.length",
        "must be in [2.263, 3.787] (m)",
    ),
    (
        "1 micron wing root chord",
        _set("wing", "sections", 0, "root_chord", 1e-6),
        "wing.sections[0].root_chord",
        "0.05 x the largest section chord",
    ),
    (
        "blade roots that overlap at the hub",
        _both(_all_lift_rotors("num_blades", 8), _all_lift_rotors("chord_cp", [0.5] * 4)),
        "lift_rotors[0].chord_cp",
        "the blade roots overlap",
    ),
    (
        "fuselage height in ft",
        _set("fuselage", "max_height", 5.538),
        "fuselage.max_height",
        "must be in [0.5, 2]",
    ),
    (
        "radius intersection span fraction above 1/2",
        _set("constraints", "radius_intersection", 0.6),
        "constraints.radius_intersection",
        "must be <= 0.5",
    ),
    # Speeds no wing within the bounds can fly, a transition faster than the cruise.
    (
        "cruise at 0.5 m/s",
        _set("conditions", CRUISE, "speed", 0.5),
        f"conditions[{CRUISE}].speed",
        "must fly at >= 28.92 m/s",
    ),
    (
        "+3g pull-up at 5 m/s",
        _set("conditions", 10, "speed", 5.0),
        "conditions[10].speed",
        "must fly at >= 51.34 m/s",
    ),
    (
        "transition point in mph",
        _set("conditions", 5, "speed", 131.65),
        "conditions[5].speed",
        "no faster than the fastest 'steady' condition",
    ),
    # Design-variable tables in another unit: bounds outside what the quantity can be.
    (
        "hover rotor speeds in rad/s under units rpm",
        _both(
            _set("design_variables", "hover_lift_rpm", "lower", 52.36),
            _set("design_variables", "hover_lift_rpm", "upper", 188.5),
        ),
        "design_variables.hover_lift_rpm.upper[0]",
        "a tip speed of 50 m/s",
    ),
    (
        "climb pusher speeds in rev/s under units rpm",
        _set("design_variables", "climb_pusher_rpm", "upper", 41.67),
        "design_variables.climb_pusher_rpm.upper",
        "a table in rad/s or rev/s?",
    ),
    (
        "pusher speed bound with supersonic tips",
        _set("design_variables", "cruise_pusher_rpm", "lower", 6000.0),
        "design_variables.cruise_pusher_rpm.lower",
        "(Mach 1.2)",
    ),
    (
        "rated currents in mA",
        _both(
            _set("design_variables", "motor_rated_current", "upper", 1e6),
            _set("design_variables", "motor_rated_current", "ref", 1e5),
        ),
        "design_variables.motor_rated_current.upper[0]",
        "must be <= 5000 (A; the range of motor.rated_current)",
    ),
    (
        "motor lengths in mm",
        _both(
            _set("design_variables", "motor_length", "upper", 250.0),
            _set("design_variables", "motor_length", "ref", 100.0),
        ),
        "design_variables.motor_length.upper[0]",
        "must be <= 1 (m",
    ),
    (
        "motor length bound of 1 nm",
        _set("design_variables", "motor_length", "lower", 1e-9),
        "design_variables.motor_length.lower[0]",
        "must be >= 0.01 (m",
    ),
    (
        "spar thickness in mm",
        _both(
            _set("design_variables", "front_spar_thickness", "upper", 50.0),
            _set("design_variables", "front_spar_thickness", "ref", 1.0),
        ),
        "design_variables.front_spar_thickness.upper[0]",
        "must be <= 0.1 (m",
    ),
    (
        "rotor radius bound in ft",
        _set("design_variables", "rotor_radius", "upper", 20.0),
        "design_variables.rotor_radius.upper[0]",
        "must be <= 10 (m; the range of lift_rotors[i].radius",
    ),
    # Found by the second audit: typos and impossible placements that used to load.
    (
        "a transition sharing the climb's tables",
        _set("conditions", 3, "design_variable_prefix", "climb"),
        "conditions[6].design_variable_prefix",
        "must be of one kind",
    ),
    (
        "one-rotor-out name with a hyphen",
        _set("conditions", 9, "name", "oei-1"),
        "conditions[9].name",
        "the generated one-rotor-out conditions are named <name>_1",
    ),
    (
        "a quoted dotted key",
        lambda d: d.update({"wing.area": 20.0}),
        "wing.area",
        'one quoted key "wing.area" holding a dot',
    ),
    ("an empty key", lambda d: d["wing"].update({"": 1.0}), "wing.", "an empty key"),
    (
        "wing box through the seats",
        _set("wing", "root_leading_edge", [-1.95925, 0.0, -0.3]),
        "wing.root_leading_edge",
        "so its box would run through the seats",
    ),
    (
        "shear modulus 5x off E and nu",
        _set("material", "shear_modulus", 5e9),
        "material.shear_modulus",
        "an isotropic material has G = E/(2 (1 + nu))",
    ),
    (
        "whole-wing sweep against the sections",
        _set("wing", "sweep_deg", 35.0),
        "wing.sweep_deg",
        "the sections' leading edge from root to tip gives 7.821 deg",
    ),
    (
        "whole-wing dihedral against the sections",
        _set("wing", "dihedral_deg", 6.0),
        "wing.dihedral_deg",
        "gives -2 deg",
    ),
    ("wing incidence x10", _set("wing", "incidence_deg", 20.4), "wing.incidence_deg", "[-10, 10]"),
    (
        "h-tail floating above a short fin",
        _both(
            _set("vertical_tail", "area", 1.0),  # 1.08 m high: its tip at z = -1.98 m
            _set("horizontal_tail", "root_leading_edge", [-7.60903, 0.0, -2.4]),
        ),
        "horizontal_tail.root_leading_edge",
        "at most as high as the fin's tip",
    ),
    (
        "battery beside the fuselage, under the wing",
        _set("battery", "cg", [-2.09897, 3.0, 0.55844]),
        "battery.cg",
        "so it must lie inside the wing",
    ),
    ("payload 5.4 kg", _set("masses", "payload", 5.4), "masses.payload", "in [50, 10000] (kg)"),
    ("cabin at the nose tip", _set("fuselage", "nose_length", 0.0), "fuselage.nose_length", "0.3"),
    (
        "two rotors of one name",
        _set("lift_rotors", 1, "name", "front_left_outer"),
        "lift_rotors[1].name",
        "repeats 'lift_rotors[0].name'",
    ),
    ("a rotor without a name", _set("lift_rotors", 2, "name", " "), "lift_rotors[2].name", "empty"),
    (
        "no mission segment",
        lambda d: [c.update(energy_weight=0.0) for c in d["conditions"]],
        "conditions",
        "no mission segment",
    ),
    (
        "two seats abreast in 0.6 m",
        _set("fuselage", "max_width", 0.9),
        "fuselage.seats_abreast",
        "need a fuselage wider than 'fuselage.max_width' = 0.9",
    ),
    (
        "shear modulus above E/2",
        _set("material", "shear_modulus", 260e9),
        "material.shear_modulus",
        "G = E/(2 (1 + nu))",
    ),
    (
        "allowable stress of 3.5 GPa",
        _set("material", "allowable_stress", 3.5e9),
        "material.allowable_stress",
        "must be <= 1 % of 'material.youngs_modulus'",
    ),
    (
        "battery mass bounds swapped",
        lambda d: d["design_variables"]["battery_mass"].update(lower=1400.0, upper=400.0),
        "design_variables.battery_mass.lower",
        "the bounds are swapped?",
    ),
    *[
        (
            f"condition named {name!r}",
            _set("conditions", 6, "name", name),
            "conditions[6].name",
            "must be an ASCII identifier that does not start with '_'",
        )
        for name in ("mission", "_climb", "ho\u00f6ver", "lift_margin")
    ],
    (
        "motor slots that do not fit the poles",
        _set("motor", "num_slots", 35),
        "motor",
        "'num_slots' = 35 is not allowed",
    ),
    (
        "a wing box without packaged sections",
        _set("wing_box", "front_spar", 0.15),
        "wing_box.front_spar",
        "has no packaged section properties",
    ),
    (
        "a wing airfoil without a wing-box section",
        _set("wing", "airfoil", "naca0015"),
        "wing.airfoil",
        "has no packaged section properties",
    ),
    (
        "hover rotor speed lower bound -1800 rpm",
        lambda d: d["design_variables"]["hover_lift_rpm"].update(lower=-1800.0),
        "design_variables.hover_lift_rpm.lower[0]",
        "rotor speed is positive",
    ),
    (
        "rotor radius lower bound 0",
        lambda d: d["design_variables"]["rotor_radius"].update(lower=[0.0, 1.2, 1.2, 1.2, 0.959]),
        "design_variables.rotor_radius.lower[0]",
        "must be > 0",
    ),
    (
        "no state-of-charge window",
        _both(_set("battery", "initial_soc", 0.2000001), _set("constraints", "min_final_soc", 0.2)),
        "constraints.min_final_soc",
        "usable state-of-charge window",
    ),
]


@pytest.mark.parametrize(
    "mutate, key, fragment", [c[1:] for c in DICT_CASES], ids=[c[0] for c in DICT_CASES]
)
def test_bad_value_is_a_named_error(mutate, key, fragment):
    data = copy.deepcopy(REFERENCE_DATA)
    mutate(data)
    with pytest.raises(VehicleSpecError) as info:
        vehicle_from_dict(data)
    message = str(info.value)
    assert f"'{key}'" in message, message
    assert fragment in message, message


# ------------------------------------------------------------------------------------------------
# Polar files: rotor lift_rotors[3] names a malformed file (written into tmp_path)

ALPHA = np.arange(-10.0, 16.0, 1.0)  # covers the -5..+10 deg the model needs


def _rows(alpha=ALPHA, cl=None, cd=None):
    cl = 0.1 * alpha if cl is None else cl
    cd = 0.01 + 1e-4 * alpha**2 if cd is None else cd
    return "\n".join(f"{a:g} {c:g} {d:g}" for a, c, d in zip(alpha, cl, cd, strict=True)) + "\n"


def _with(index, value, array):
    array = np.array(array, dtype=float)
    array[index] = value
    return array


def _npz_bytes(tmp_path, **arrays):
    path = tmp_path / "scratch.npz"
    np.savez(path, **arrays)
    return path.read_bytes()


def _zip_bytes(tmp_path):
    path = tmp_path / "scratch.zip"
    with zipfile.ZipFile(path, "w") as z:
        z.writestr("readme.txt", "not an array")
    return path.read_bytes()


CD = 0.01 + 1e-4 * ALPHA**2
# (id, file name, content: str, bytes, or a function of tmp_path giving bytes, message fragment)
POLAR_CASES = [
    ("three rows", "blade.dat", _rows(ALPHA[:3]), "found 3 rows"),
    ("no numbers", "blade.dat", "alpha cl cd\nnone here\n", "found 0 rows"),
    ("empty file", "blade.txt", "", "found 0 rows"),
    ("duplicate alpha", "blade.dat", _rows(_with(5, ALPHA[4], ALPHA)), "not strictly increasing"),
    ("decreasing alpha", "blade.dat", _rows(ALPHA[::-1]), "not strictly increasing"),
    ("NaN cl", "blade.dat", _rows(cl=_with(3, np.nan, 0.1 * ALPHA)), "cl in row 3 is nan"),
    ("inf cd", "blade.csv", _rows(cd=_with(2, np.inf, CD)), "cd in row 2 is inf"),
    ("negative cd", "blade.dat", _rows(cd=_with(4, -0.01, CD)), "cd has the value -0.01"),
    ("zero cd", "blade.pol", _rows(cd=0.0 * ALPHA), "allowed: cd > 0"),
    ("span 0..5 deg", "blade.dat", _rows(np.linspace(0.0, 5.0, 11)), "covers at least -5..10 deg"),
    ("span -5..8 deg", "blade.dat", _rows(np.linspace(-5.0, 8.0, 14)), "alpha spans -5..8 deg"),
    ("text named .npz", "blade.npz", _rows(), "is not an .npz archive"),
    ("empty .npz", "blade.npz", b"", "is not an .npz archive"),
    ("zip without arrays", "blade.npz", _zip_bytes, "missing arrays"),
    (
        "npz negative cd",
        "blade.npz",
        lambda t: _npz_bytes(t, alpha_deg=ALPHA, cl=0.1 * ALPHA, cd=-CD),
        "allowed: cd > 0",
    ),
    (
        "npz duplicate alpha",
        "blade.npz",
        lambda t: _npz_bytes(t, alpha_deg=_with(1, ALPHA[0], ALPHA), cl=0.1 * ALPHA, cd=CD),
        "not strictly increasing",
    ),
    (
        "npz missing cd",
        "blade.npz",
        lambda t: _npz_bytes(t, alpha_deg=ALPHA, cl=0.1 * ALPHA),
        "missing arrays ['cd']",
    ),
    (
        "npz named .dat",
        "blade.dat",
        lambda t: _npz_bytes(t, alpha_deg=ALPHA, cl=0.1 * ALPHA, cd=CD),
        "is an .npz (zip) archive",
    ),
    ("cl in percent", "blade.dat", _rows(cl=10.0 * ALPHA + 10.0), "(coefficients, not percent)"),
    ("cd in percent", "blade.dat", _rows(cd=100.0 * CD + 4.0), "cd = 5.25 at alpha -5 deg"),
    (
        "2001 rows",
        "blade.dat",
        _rows(np.linspace(-10.0, 15.0, 2001)),
        "allowed: 5 to 2000 angles",
    ),
    (
        "npz with half a pressure table",
        "blade.npz",
        lambda t: _npz_bytes(t, alpha_deg=ALPHA, cl=0.1 * ALPHA, cd=CD, cp_upper=np.zeros(3)),
        "has cp_upper but misses the pressure arrays",
    ),
    ("binary .dat", "blade.dat", bytes(range(256)), "is binary"),
    (
        "latin-1 .dat",
        "blade.dat",
        "# d\xe9j\xe0 vu\n".encode("latin-1") + _rows().encode(),
        "not UTF-8",
    ),
]


def _write_polar(tmp_path, name, content):
    path = tmp_path / name
    if callable(content):
        content = content(tmp_path)
    if isinstance(content, str):
        path.write_text(content, encoding="utf-8")
    else:
        path.write_bytes(content)
    return path


@pytest.mark.parametrize(
    "name, content, fragment", [c[1:] for c in POLAR_CASES], ids=[c[0] for c in POLAR_CASES]
)
def test_bad_polar_file_is_a_named_error(tmp_path, name, content, fragment):
    path = _write_polar(tmp_path, name, content)
    data = copy.deepcopy(REFERENCE_DATA)
    data["lift_rotors"][3]["airfoil"] = str(path)
    with pytest.raises(VehicleSpecError) as info:
        vehicle_from_dict(data)
    message = str(info.value)
    assert "'lift_rotors[3].airfoil'" in message, message
    assert str(path) in message, message
    assert fragment in message, message


#: The reference with every rotor on the polar file polars/blade.dat, relative to the vehicle file.
RELATIVE_POLAR_TEXT = REFERENCE_TEXT.replace(
    'airfoil = "naca0012"', 'airfoil = "polars/blade.dat"\nthickness_to_chord = 0.12'
)


def test_missing_polar_file_says_where_it_looked(tmp_path, monkeypatch):
    vehicle_file = tmp_path / "vehicle" / "my_lpc.toml"
    vehicle_file.parent.mkdir()
    vehicle_file.write_text(
        RELATIVE_POLAR_TEXT,
        "utf-8",
    )
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    with pytest.raises(VehicleSpecError) as info:
        load_vehicle(vehicle_file)
    message = str(info.value)
    assert "'lift_rotors[0].airfoil' = 'polars/blade.dat': polar file not found" in message
    assert str(vehicle_file.parent / "polars" / "blade.dat") in message  # the file's folder
    assert str(work / "polars" / "blade.dat") in message  # then the working directory


def test_relative_polar_path_is_resolved_against_the_vehicle_file_folder(tmp_path, monkeypatch):
    folder = tmp_path / "vehicle"
    (folder / "polars").mkdir(parents=True)
    (folder / "polars" / "blade.dat").write_text("alpha cl cd\n" + _rows(), "utf-8")
    vehicle_file = folder / "my_lpc.toml"
    vehicle_file.write_text(
        RELATIVE_POLAR_TEXT,
        "utf-8",
    )
    monkeypatch.chdir(tmp_path)  # not the vehicle file's folder
    vehicle = load_vehicle(vehicle_file)
    expected = str((folder / "polars" / "blade.dat").resolve())
    assert {r.airfoil for r in (*vehicle.lift_rotors, vehicle.pusher)} == {expected}


# ------------------------------------------------------------------------------------------------
# File content: encodings, binary, truncated, not a file

TEXT_CASES = [
    ("binary", b"\x00\x01\x02\x03" * 100, "is binary (it holds NUL bytes)"),
    ("UTF-16", REFERENCE_TEXT[:2000].encode("utf-16"), "is binary"),
    (
        "latin-1",
        REFERENCE_TEXT.replace("NASA lift-plus-cruise", "NASA l\xe9ger").encode(
            "latin-1", "replace"
        ),
        "is not UTF-8 text (invalid byte 0xe9",
    ),
    ("png header", b"\x89PNG\r\n\x1a\n" + b"\xff" * 64, "is not UTF-8 text"),
    (
        "truncated before [motor]",
        REFERENCE_TEXT.split("[motor]")[0].encode(),
        "missing key 'motor'",
    ),
    (
        "truncated mid-line",
        (REFERENCE_TEXT.split("[fuselage]")[0] + "[fuselage]\nlength = ").encode(),
        "is not valid TOML",
    ),
    ("BOM then invalid TOML", b"\xef\xbb\xbf" + b"[wing\narea = 1\n", "is not valid TOML"),
    (
        "arrays nested 5000 deep",
        REFERENCE_TEXT.replace(
            "area = 19.6 ", "area = " + "[" * 5000 + "1" + "]" * 5000, 1
        ).encode(),
        "nests arrays or tables too deeply to read",
    ),
]


@pytest.mark.parametrize(
    "content, fragment", [c[1:] for c in TEXT_CASES], ids=[c[0] for c in TEXT_CASES]
)
def test_bad_file_content_is_a_named_error(tmp_path, content, fragment):
    path = tmp_path / "bad.toml"
    path.write_bytes(content)
    with pytest.raises(VehicleSpecError) as info:
        load_vehicle(path)
    message = str(info.value)
    assert fragment in message, message
    if "missing key" not in fragment:
        assert f"vehicle file '{path}'" in message, message


#: Values in a file's text that TOML reads but a vehicle cannot have: (id, text, fragment).
VALUE_TEXT_CASES = [
    (
        "an integer beyond 64 bits",
        REFERENCE_TEXT.replace("num_blades = 4", "num_blades = " + "9" * 30, 1).encode(),
        "'pusher.num_blades' = 1e+30 is out of range: must be in [2, 8]",
    ),
    (
        "an integer beyond the float range",
        REFERENCE_TEXT.replace("num_blades = 4", "num_blades = " + "9" * 400, 1).encode(),
        "'pusher.num_blades' = inf is out of range",
    ),
    (
        "a terminal escape in a name",
        REFERENCE_TEXT.replace('name = "pusher"', 'name = "pu\\u001b[31mRED"', 1).encode(),
        "'pusher.name' = 'pu\\x1b[31mRED' is not allowed: it holds the control character",
    ),
    (
        "a name of a million characters",
        REFERENCE_TEXT.replace('name = "pusher"', 'name = "' + "x" * 10**6 + '"', 1).encode(),
        "... (1000000 characters) is not allowed",
    ),
]


@pytest.mark.parametrize(
    "content, fragment", [c[1:] for c in VALUE_TEXT_CASES], ids=[c[0] for c in VALUE_TEXT_CASES]
)
def test_bad_value_in_the_file_text_is_a_named_error(tmp_path, content, fragment):
    path = tmp_path / "bad.toml"
    path.write_bytes(content)
    with pytest.raises(VehicleSpecError) as info:
        load_vehicle(path)
    assert fragment in str(info.value), str(info.value)
    assert len(str(info.value)) < 400  # a long or escaped name is cut, not printed


def test_polar_path_that_is_not_a_file_is_named(tmp_path):
    folder = tmp_path / "blade.dat"
    folder.mkdir()
    fifo = tmp_path / "pipe.dat"
    os.mkfifo(fifo)
    for path, kind in ((folder, "is a directory"), (fifo, "is not a regular file")):
        data = copy.deepcopy(REFERENCE_DATA)
        data["lift_rotors"][3]["airfoil"] = str(path)
        with pytest.raises(VehicleSpecError, match=f"'lift_rotors\\[3\\].airfoil' = .*{kind}"):
            vehicle_from_dict(data)


def test_missing_and_directory_paths_are_named_errors(tmp_path):
    with pytest.raises(VehicleSpecError, match=r"vehicle file '.*nowhere\.toml' not found"):
        load_vehicle(tmp_path / "nowhere.toml")
    with pytest.raises(VehicleSpecError, match=r"is a directory; allowed: a TOML file"):
        load_vehicle(tmp_path)


def test_utf8_bom_is_accepted(tmp_path):
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + REFERENCE_TEXT.encode("utf-8"))
    assert load_vehicle(path) == reference_vehicle()


# ------------------------------------------------------------------------------------------------
# Good files still load


def test_reference_vehicle_loads_unchanged():
    vehicle = load_vehicle()
    assert vehicle == reference_vehicle()
    assert vehicle.design_variable_count() == 182  # with W_dg


def test_loiter_vehicle_of_the_loiter_test_loads(tmp_path):
    spec = importlib.util.spec_from_file_location(
        "loiter_test", Path(__file__).with_name("test_loiter_condition.py")
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    path = tmp_path / "lpc_loiter.toml"
    path.write_text(REFERENCE_TEXT + module.LOITER, encoding="utf-8")
    vehicle = load_vehicle(path)
    assert [c.name for c in vehicle.conditions][-1] == "loiter"
    assert vehicle.design_variable_count() == 182 + 3


def test_a_good_polar_file_loads(tmp_path):
    path = _write_polar(tmp_path, "blade.dat", "# XFOIL-like header\nalpha CL CD\n" + _rows())
    data = copy.deepcopy(REFERENCE_DATA)
    for rotor in data["lift_rotors"]:
        rotor.update(airfoil=str(path), thickness_to_chord=0.11)
    vehicle = vehicle_from_dict(data)
    assert vehicle.lift_rotors[3].airfoil == str(path.resolve())
    assert vehicle.lift_rotors[3].thickness_to_chord == 0.11


def test_case_counts():
    # Issue 18 item 3: at least 60 parametrized bad-vehicle-file cases in this module.
    assert len(DICT_CASES) + len(POLAR_CASES) + len(TEXT_CASES) + len(VALUE_TEXT_CASES) >= 60
