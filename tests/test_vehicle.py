"""Tests of the vehicle definition: the reference file, user files and every kind of bad input."""

import dataclasses
import math
import pickle
import re
from importlib import resources

import numpy as np
import pytest

from lpc_mdo.vehicle import (
    Vehicle,
    VehicleSpecError,
    design_variable_count,
    load_vehicle,
    read_vehicle_file,
    reference_vehicle,
    vehicle_from_dict,
)


@pytest.fixture
def data():
    """Return a fresh dict of the reference file, free to modify."""
    return read_vehicle_file()


# ------------------------------------------------------------------------------------------------
# The reference vehicle


def test_reference_file_loads():
    vehicle = load_vehicle()
    assert isinstance(vehicle, Vehicle)
    assert vehicle == reference_vehicle()
    assert reference_vehicle() is reference_vehicle()


def test_counts_and_condition_order():
    vehicle = reference_vehicle()
    assert len(vehicle.lift_rotors) == 8
    assert [c.name for c in vehicle.conditions] == [
        "hover",
        "transition_1",
        "transition_2",
        "transition_3",
        "transition_4",
        "transition_5",
        "climb",
        "cruise",
        "descent",
        "oei_1",
        "oei_2",
        "oei_3",
        "oei_4",
        "plus_3g",
        "minus_1g",
    ]
    assert [c.kind for c in vehicle.conditions] == (
        ["hover"] + ["transition"] * 5 + ["steady"] * 3 + ["oei"] * 4 + ["structural"] * 2
    )
    assert design_variable_count() == 161 + 21
    assert vehicle.design_variable_count() == 161 + 21
    assert design_variable_count(vehicle) == sum(
        dv.size for dv in vehicle.design_variables.values()
    )
    assert len(vehicle.design_variables) == 34


def test_reference_values():
    vehicle = reference_vehicle()
    wing = vehicle.wing
    assert wing.area == 19.6
    assert wing.aspect_ratio == 12.12
    assert wing.span == pytest.approx(15.41, rel=1e-3)
    # The cranked NASA wing: MAC 1.33328 m by a trapezoid-rule integration of the file's
    # sections (tests/test_cranked_wing_vehicle.py::_hand_planform); 1e-4 m.
    assert wing.planform == "sections" and len(wing.sections) == 4
    assert wing.mean_aerodynamic_chord == pytest.approx(1.33328, abs=1e-4)
    assert wing.root_chord == pytest.approx(1.66237, abs=1e-4)
    assert wing.airfoil == "ls413" and wing.thickness_to_chord == 0.13
    assert vehicle.horizontal_tail.root_chord == pytest.approx(1.1595, abs=1e-4)
    assert vehicle.vertical_tail.span == pytest.approx(1.7239, abs=1e-4)
    assert all(r.radius == 1.524 and r.num_blades == 2 for r in vehicle.lift_rotors)
    assert vehicle.pusher.radius == 1.37 and vehicle.pusher.num_blades == 4
    assert vehicle.pusher.hub_radius == pytest.approx(0.274)
    assert vehicle.masses.other == 0.0
    assert vehicle.material.allowable_stress == 350e6
    assert vehicle.battery.energy == pytest.approx(856.41 * 400 * 3600)  # sized to the mission
    assert vehicle.constraints.min_final_soc == 0.2
    assert vehicle.constraints.radius_intersection_definition == "span_fraction"
    (observer,) = vehicle.noise_observer  # one [noise_observer] table: one observer
    assert observer.elevation == pytest.approx(math.pi / 4)
    assert observer.azimuth is None and observer.azimuth_or_aft == pytest.approx(math.pi)


def test_rotor_pairs_are_mirror_images_with_balanced_spin():
    vehicle = reference_vehicle()
    assert vehicle.lift_rotor_pairs == ((0, 6), (1, 7), (2, 4), (3, 5))
    for i, j in vehicle.lift_rotor_pairs:
        a, b = vehicle.lift_rotors[i], vehicle.lift_rotors[j]
        assert b.hub_position == (a.hub_position[0], -a.hub_position[1], a.hub_position[2])
        assert a.hub_position[1] < 0 < b.hub_position[1]
        assert a.spin_direction == -b.spin_direction
    assert sum(r.spin_direction for r in vehicle.lift_rotors) == 0
    # front rotors below the wing, rear rotors above it (z down)
    wing_z = vehicle.wing.root_leading_edge[2]
    assert all(vehicle.lift_rotors[i].hub_position[2] > wing_z for i in (0, 2, 4, 6))
    assert all(vehicle.lift_rotors[i].hub_position[2] < wing_z for i in (1, 3, 5, 7))


def test_angles_are_radians_and_energy_weights_follow_the_paper_rule():
    # The reference file's energy weights are the paper's rule (Sec. IV):
    # E_req = 2 (E_hover + 2 E_transition + E_climb + E_cruise + E_descent) + E_cruise.
    vehicle = reference_vehicle()
    assert vehicle.pusher.twist_cp[0] == pytest.approx(math.radians(60))
    assert vehicle.wing.dihedral == pytest.approx(math.radians(-2))
    multipliers = {c.name: c.energy_weight for c in vehicle.conditions}
    assert multipliers["hover"] == 2 and vehicle.condition("hover").duration == 60
    assert [multipliers[f"transition_{i}"] for i in range(1, 6)] == [4] * 5
    assert (multipliers["climb"], multipliers["cruise"], multipliers["descent"]) == (2, 3, 2)
    assert all(multipliers[n] == 0 for n in ("oei_1", "oei_4", "plus_3g", "minus_1g"))
    assert [c.name for c in vehicle.mission_segments] == [c.name for c in vehicle.conditions[:9]]
    assert vehicle.mission.cruise_condition == "cruise"
    accelerations = [c.acceleration for c in vehicle.conditions if c.kind == "transition"]
    assert min(accelerations) == pytest.approx(0.17, abs=0.01)  # paper Table 7 minimum
    assert [c.failed_rotor for c in vehicle.conditions if c.kind == "oei"] == [0, 1, 2, 3]
    assert vehicle.condition("plus_3g").load_factor == 3
    assert vehicle.condition("cruise").speed == pytest.approx(
        57.19, abs=0.01
    )  # docs theory/dynamics 'Condition kinematics'


def test_design_variables():
    vehicle = reference_vehicle()
    dvs = vehicle.design_variables
    assert dvs["wing_area"].initial == (19.6,)
    assert dvs["wing_area"].lower == pytest.approx((0.7 * 19.6,))
    assert dvs["wing_area"].initial_from == "wing.area"
    assert dvs["rotor_radius"].initial == (1.524, 1.524, 1.524, 1.524, 1.37)
    assert dvs["rotor_radius"].upper[4] == pytest.approx(1.3 * 1.37, abs=1e-3)
    assert dvs["blade_twist_cp"].units == "rad"
    assert dvs["blade_twist_cp"].initial_array.shape == (5, 4)
    assert dvs["blade_twist_cp"].initial_array[4, 0] == pytest.approx(math.radians(60))
    assert dvs["blade_twist_cp"].lower_array[0, 0] == pytest.approx(math.radians(3))
    assert dvs["oei_lift_rpm"].shape == (4, 7)
    assert dvs["cruise_pitch"].initial == (vehicle.condition("cruise").pitch,)
    assert dvs["top_skin_thickness"].size == vehicle.wing_box.num_bays == 8
    for dv in dvs.values():
        assert np.all(dv.lower_array <= dv.initial_array)
        assert np.all(dv.initial_array <= dv.upper_array)
    with pytest.raises(TypeError, match="read-only"):
        dvs["wing_area"] = dvs["cruise_pitch"]


def test_vehicle_is_immutable_and_picklable():
    vehicle = reference_vehicle()
    with pytest.raises(dataclasses.FrozenInstanceError):
        vehicle.wing.area = 20.0
    assert pickle.loads(pickle.dumps(vehicle)) == vehicle


def test_user_file_loads(tmp_path):
    reference = resources.files("lpc_mdo").joinpath("data", "lpc_reference.toml")
    text = reference.read_text(encoding="utf-8")
    path = tmp_path / "my_lpc.toml"
    path.write_text(
        text.replace('airfoil = "ls413"', 'airfoil = "ls417"').replace(
            "area = 19.6 ", "area = 21.0 "
        ),
        encoding="utf-8",
    )
    vehicle = load_vehicle(path)
    assert vehicle.wing.airfoil == "ls417" and vehicle.wing.thickness_to_chord == 0.17
    assert vehicle.wing.area == 21.0
    assert vehicle.design_variables["wing_area"].initial == (21.0,)
    assert load_vehicle(str(path)) == vehicle


def test_integral_float_is_accepted_for_an_integer(data):
    for rotor in data["lift_rotors"]:
        rotor["num_blades"] = 3.0
    assert all(r.num_blades == 3 for r in vehicle_from_dict(data).lift_rotors)


def test_number_of_bays_sizes_the_thickness_design_variables(data):
    data["wing_box"]["num_bays"] = 10
    for name in ("front_spar", "rear_spar", "top_skin", "bottom_skin"):
        # The reference file stores 8 sized gauges; a scalar initial fits any bay count.
        data["design_variables"][f"{name}_thickness"]["initial"] = 0.0015
    vehicle = vehicle_from_dict(data)
    assert vehicle.design_variables["bottom_skin_thickness"].shape == (10,)
    assert design_variable_count(vehicle) == 161 + 21 + 4 * 2


def test_invalid_toml_is_reported(tmp_path):
    path = tmp_path / "broken.toml"
    path.write_text("[wing\narea = 1\n", encoding="utf-8")
    with pytest.raises(VehicleSpecError, match=r"vehicle file '.*broken\.toml' is not valid TOML"):
        load_vehicle(path)


# ------------------------------------------------------------------------------------------------
# Bad input: one clear error per kind, naming the key, the value and what is allowed


def _explicit_oei(then):
    """Write the OEI cases out as four tables (failed_rotor 0..3), then apply ``then``."""

    def mutate(d):
        each = d["conditions"][9]
        assert each["failed_rotor"] == "each"
        cases = [{**each, "name": f"oei_{k + 1}", "failed_rotor": k} for k in range(4)]
        d["conditions"][9:10] = cases
        then(d)

    return mutate


def _set(*keys_and_value):
    """Return a mutator that sets data[k0][k1]... = value."""
    *keys, value = keys_and_value

    def mutate(d):
        for key in keys[:-1]:
            d = d[key]
        d[keys[-1]] = value

    return mutate


def _delete(*keys):
    def mutate(d):
        for key in keys[:-1]:
            d = d[key]
        del d[keys[-1]]

    return mutate


def _repeat_condition_name(d):
    d["conditions"][6]["name"] = "hover"


BAD_INPUTS = {
    "unknown key": (
        _set("wing", "spam", 1.0),
        "unknown key 'wing.spam'; allowed keys: 'airfoil', 'area', 'aspect_ratio', "
        "'coordinates', 'dihedral_deg'",
    ),
    "unknown top-level key": (_set("wings", {}), "unknown key 'wings'; allowed keys: "),
    "unknown design variable": (
        _set("design_variables", "wing_span", {}),
        "unknown key 'design_variables.wing_span'",
    ),
    "missing key": (_delete("wing", "area"), "missing key 'wing.area' (m^2, in [0.1, 200])"),
    "missing angle key": (
        _delete("lift_rotors", 3, "twist_cp_deg"),
        "missing key 'lift_rotors[3].twist_cp_deg' (4 numbers, deg, in [-80, 80])",
    ),
    "missing table": (_delete("battery"), "missing key 'battery' (table)"),
    "missing design variable": (
        _delete("design_variables", "hover_lift_rpm"),
        "missing key 'design_variables.hover_lift_rpm' (design-variable table)",
    ),
    "string for a number": (
        _set("wing", "area", "big"),
        "'wing.area' must be a number, got str 'big'",
    ),
    "bool for a number": (
        _set("fuselage", "length", True),
        "'fuselage.length' must be a number, got bool True",
    ),
    "fraction for an integer": (
        _set("pusher", "num_blades", 2.5),
        "'pusher.num_blades' must be an integer, got float 2.5",
    ),
    "number for a string": (_set("wing", "airfoil", 413), "'wing.airfoil' must be a string"),
    "number for a table": (_set("wing", 3), "'wing' must be a table, got int 3"),
    "table for a list of tables": (
        _set("conditions", {}),
        "'conditions' must be a list of tables ([[conditions]]), got dict {}",
    ),
    "number for a vector": (
        _set("pusher", "hub_position", 1.0),
        "'pusher.hub_position' must be a list of 3 numbers, got float 1.0",
    ),
    "string in a vector": (
        _set("pusher", "chord_cp", [0.3, "wide", 0.2, 0.1]),
        "'pusher.chord_cp[1]' must be a number, got str 'wide'",
    ),
    "negative area": (
        _set("wing", "area", -3.0),
        "'wing.area' = -3.0 is out of range: must be in [0.1, 200] (m^2)",
    ),
    "negative length": (
        _set("fuselage", "length", -9.144),
        "'fuselage.length' = -9.144 is out of range: must be in [1, 30] (m)",
    ),
    "not finite": (
        _set("fuselage", "max_width", float("nan")),
        "'fuselage.max_width' = nan is out of range: must be a finite number",
    ),
    "initial SoC above 1": (
        _set("battery", "initial_soc", 1.5),
        "'battery.initial_soc' = 1.5 is out of range: must be in (0, 1]",
    ),
    "final SoC below 0": (
        _set("constraints", "min_final_soc", -0.1),
        "'constraints.min_final_soc' = -0.1 is out of range: must be in [0, 1)",
    ),
    "negative rotor radius": (
        _set("lift_rotors", 3, "radius", -1.0),
        "'lift_rotors[3].radius' = -1.0 is out of range: must be in [0.1, 10] (m)",
    ),
    "negative chord": (
        _set("lift_rotors", 2, "chord_cp", [0.3, 0.2, -0.1, 0.1]),
        "'lift_rotors[2].chord_cp[2]' = -0.1 is out of range: must be in (0, 2] (m)",
    ),
    "angle out of range": (
        _set("wing", "sweep_deg", 95.0),
        "'wing.sweep_deg' = 95.0 is out of range: must be in [-70, 70] (deg)",
    ),
    "altitude above the troposphere": (
        _set("conditions", 7, "altitude", 20000.0),
        "'conditions[7].altitude' = 20000.0 is out of range: must be in [0, 11000] (m)",
    ),
    "short vector": (
        _set("lift_rotors", 3, "chord_cp", [0.3, 0.2, 0.1]),
        "'lift_rotors[3].chord_cp' must have 4 elements, got 3",
    ),
    "thrust axis not a unit vector": (
        _set("pusher", "thrust_axis", [1.0, 0.0, 1.0]),
        "'pusher.thrust_axis' = [1.0, 0.0, 1.0] is out of range: must be a unit vector",
    ),
    "unknown airfoil": (
        _set("wing", "airfoil", "naca2412"),
        "'wing.airfoil' = 'naca2412' is not allowed: must be one of 'ls413', 'ls417', 'naca0012'",
    ),
    "spin direction": (
        _set("pusher", "spin_direction", 0),
        "'pusher.spin_direction' = 0 is not allowed: must be one of -1, 1",
    ),
    "unknown radius-intersection definition": (
        _set("constraints", "radius_intersection_definition", "gap"),
        "'constraints.radius_intersection_definition' = 'gap' is not allowed: must be one of "
        "'span_fraction', 'clearance'",
    ),
    "seven lift rotors": (
        lambda d: d["lift_rotors"].__delitem__(7),
        "'lift_rotors' must have 4 or 6 or 8 or 10 or 12 entries (the lift-plus-cruise layout: "
        "2 to 6 mirror-symmetric pairs, [[lift_rotors]] tables), got 7",
    ),
    "fourteen lift rotors": (
        lambda d: d["lift_rotors"].extend(d["lift_rotors"][:6]),
        "'lift_rotors' must have 4 or 6 or 8 or 10 or 12 entries",
    ),
    "six lift rotors with the pairs of eight": (
        lambda d: d["lift_rotors"].__delitem__(slice(6, 8)),
        "'lift_rotors[3].pair' = 3 is out of range: must be in [0, 2] (6 lift rotors make 3 "
        "pairs; group 3 is the pusher)",
    ),
    "three rotors in a pair": (
        _set("lift_rotors", 7, "pair", 0),
        "'lift_rotors' pair 0 has 3 rotors (lift_rotors[0], lift_rotors[6], lift_rotors[7])",
    ),
    "lift rotor in the pusher group": (
        _set("lift_rotors", 7, "pair", 4),
        "'lift_rotors[7].pair' = 4 is out of range: must be in [0, 3]",
    ),
    "pusher in a lift pair": (
        _set("pusher", "pair", 1),
        "'pusher.pair' = 1 is not allowed: must be 4",
    ),
    "pair radii differ": (
        _set("lift_rotors", 6, "radius", 1.6),
        "'lift_rotors[6].radius' = 1.6 differs from its pair partner 'lift_rotors[0].radius' "
        "= 1.524",
    ),
    "pair not mirrored": (
        _set("lift_rotors", 5, "hub_position", [-4.9, 2.60208, -1.46487]),
        "'lift_rotors[5].hub_position' = (-4.9, 2.60208, -1.46487) is not the mirror image "
        "(y -> -y) of its pair partner 'lift_rotors[3].hub_position'",
    ),
    "pair spins the same way": (
        _set("lift_rotors", 7, "spin_direction", -1),
        "'lift_rotors[7].spin_direction' = -1 must be opposite to its pair partner",
    ),
    "condition name repeated": (
        _repeat_condition_name,
        "'conditions[6].name' = 'hover' repeats 'conditions[0].name'; names must be unique",
    ),
    "condition name not an identifier": (
        _set("conditions", 11, "name", "minus 1g"),
        "'conditions[11].name' = 'minus 1g' is not allowed: must be an identifier",
    ),
    "unknown condition kind": (
        _set("conditions", 11, "kind", "pull_up"),
        "'conditions[11].kind' = 'pull_up' is not allowed: must be one of 'hover', 'oei', "
        "'transition', 'steady', 'structural'",
    ),
    "missing energy weight": (
        _delete("conditions", 3, "energy_weight"),
        "missing key 'conditions[3].energy_weight'",
    ),
    "energy weight of a condition without power": (
        _set("conditions", 10, "energy_weight", 1.0),
        "'conditions[10].energy_weight' = 1.0 is not allowed: must be 0 in 'structural' "
        "conditions (they draw no power)",
    ),
    "cruise condition not steady": (
        _set("mission", "cruise_condition", "hover"),
        "'mission.cruise_condition' = 'hover' is not allowed: must be the name of a 'steady' "
        "condition, one of ['climb', 'cruise', 'descent']",
    ),
    "structural condition at zero load factor": (
        _set("conditions", 11, "load_factor", 0.0),
        "'conditions[11].load_factor' = 0.0 is not allowed: must be non-zero in 'structural'",
    ),
    "hover with speed": (
        _set("conditions", 0, "speed", 5.0),
        "'conditions[0].speed' = 5.0 is not allowed: must be 0 in 'hover' conditions",
    ),
    "cruise with a failed rotor": (
        _set("conditions", 7, "failed_rotor", 2),
        "'conditions[7].failed_rotor' = 2 is not allowed: must be -1 in 'steady' conditions",
    ),
    "OEI without a failed rotor": (
        _explicit_oei(_set("conditions", 9, "failed_rotor", -1)),
        "'conditions[9].failed_rotor' = -1 is not allowed: must be a lift-rotor index (>= 0) "
        "in 'oei' conditions",
    ),
    "OEI repeats a failed rotor": (
        _explicit_oei(_set("conditions", 10, "failed_rotor", 0)),
        "'conditions[10].failed_rotor' = 0 repeats 'conditions[9].failed_rotor'",
    ),
    "failed rotor index too large": (
        _explicit_oei(_set("conditions", 9, "failed_rotor", 8)),
        "'conditions[9].failed_rotor' = 8 is out of range: must be -1 or a lift-rotor index",
    ),
    "spars crossed": (
        _set("wing_box", "rear_spar", 0.2),
        "'wing_box.rear_spar' = 0.2 is out of range: must be > 'wing_box.front_spar' = 0.25",
    ),
    "initial below the lower bound": (
        _set("design_variables", "hover_lift_rpm", "lower", 1300.0),
        "'design_variables.hover_lift_rpm.initial[0]' = 1200 is out of range: must be in "
        "[lower, upper] = [1300, 1800] (rpm)",
    ),
    "linked initial above the upper bound": (
        _set("wing", "area", 30.0),
        "'design_variables.wing_area.initial' = 30 is out of range: must be in [lower, upper] "
        "= [13.72, 25.48] (m**2); the initial value is taken from 'wing.area'",
    ),
    "linked initial in degrees": (
        _set("conditions", 7, "pitch_deg", 12.0),
        "'design_variables.cruise_pitch.initial' = 12 is out of range: must be in [lower, "
        "upper] = [-10, 10] (deg); the initial value is taken from 'conditions[7].pitch_deg'",
    ),
    "linked initial repeated": (
        _set("design_variables", "wing_area", "initial", 19.6),
        "'design_variables.wing_area.initial' must not be given: the initial value is taken "
        "from 'wing.area'",
    ),
    "design variable of the wrong shape": (
        _set("design_variables", "rotor_radius", "lower", [1.2, 1.2, 1.2, 1.2]),
        "'design_variables.rotor_radius.lower' must have 5 elements, got 4",
    ),
    "design variable nested wrongly": (
        _set("design_variables", "blade_chord_cp", "upper", [0.5] * 5),
        "'design_variables.blade_chord_cp.upper[0]' must be a list of 4 numbers, got float 0.5",
    ),
    "design variable units": (
        _set("design_variables", "wing_area", "units", "ft**2"),
        "'design_variables.wing_area.units' = 'ft**2' is not allowed: must be one of 'm**2'",
    ),
    "design variable ref not positive": (
        _set("design_variables", "wing_area", "ref", 0.0),
        "'design_variables.wing_area.ref' = 0.0 is out of range: must be > 0 (m**2)",
    ),
    "thickness below the minimum gauge": (
        _set("design_variables", "top_skin_thickness", "lower", 1e-4),
        "'design_variables.top_skin_thickness.lower[0]' = 0.0001 is out of range: must be >= "
        "0.000508 (m; material.min_gauge)",
    ),
    "thickness of the wrong size": (
        _set("design_variables", "front_spar_thickness", "initial", [0.0015] * 7),
        "'design_variables.front_spar_thickness.initial' must have 8 elements, got 7",
    ),
}


@pytest.mark.parametrize("mutate, message", BAD_INPUTS.values(), ids=BAD_INPUTS.keys())
def test_bad_input_raises_one_clear_error(data, mutate, message):
    mutate(data)
    with pytest.raises(VehicleSpecError, match=re.escape(message)):
        vehicle_from_dict(data)


def test_error_is_a_value_error():
    with pytest.raises(ValueError, match="a vehicle description must be a table, got list"):
        vehicle_from_dict([])


def test_rotor_airfoil_may_be_a_user_polar_file(tmp_path):
    # A user polar (alpha [deg], cl, cd rows) works wherever an airfoil name does.
    alpha = np.linspace(-10.0, 12.0, 23)
    table = np.column_stack([alpha, 0.1 * alpha, 0.01 + 1e-4 * alpha**2])
    polar_path = tmp_path / "my_blade.dat"
    np.savetxt(polar_path, table)
    data = read_vehicle_file()
    for rotor in data["lift_rotors"]:
        rotor["airfoil"] = str(polar_path)
    with pytest.raises(
        VehicleSpecError, match=r"missing key 'lift_rotors\[0\]\.thickness_to_chord'"
    ):
        vehicle_from_dict(data)  # the thickness noise needs the blade's t/c
    for rotor in data["lift_rotors"]:
        rotor["thickness_to_chord"] = 0.1
    vehicle = vehicle_from_dict(data)
    assert vehicle.lift_rotors[0].airfoil == str(polar_path.resolve())
    assert vehicle.lift_rotors[0].thickness_to_chord == 0.1

    from lpc_mdo.components.aero.airfoil import get_polar

    polar = get_polar(vehicle.lift_rotors[0].airfoil)
    values = polar.evaluate(np.radians(4.0), 1e6, 0.1)
    assert abs(float(values.cl) - 0.4) < 1e-6  # the table's own value at 4 deg

    data["lift_rotors"][0]["airfoil"] = str(tmp_path / "missing.dat")
    with pytest.raises(VehicleSpecError, match="polar file not found"):
        vehicle_from_dict(data)
