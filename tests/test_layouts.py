"""Lift-plus-cruise layouts of 4 to 12 lift rotors and the one-rotor-out cases they generate.

Independent numbers: the distinct single failures of a mirror-symmetric layout are one per
mirror pair (the right rotor's failure is the left one's mirror image), counted by hand from the
example files' layouts; the side-by-side neighbours by hand from their hub positions.
"""

import copy
from importlib import resources

import pytest

from lpc_mdo.vehicle import (
    VehicleSpecError,
    load_vehicle,
    read_vehicle_file,
    reference_vehicle,
    vehicle_from_dict,
)
from lpc_mdo.vehicle.clearances import side_by_side_pairs
from lpc_mdo.vehicle.one_rotor_out import distinct_failures

DATA = resources.files("lpc_mdo") / "data"


def _example(n):
    return load_vehicle(DATA / f"lpc_{n}_lift_rotors.toml")


def test_reference_generates_its_four_one_rotor_out_cases():
    vehicle = reference_vehicle()
    oei = [c for c in vehicle.conditions if c.kind == "oei"]
    # The four cases the file listed by hand before: the left rotor of pairs 0..3.
    assert [(c.name, c.failed_rotor) for c in oei] == [
        ("oei_1", 0),
        ("oei_2", 1),
        ("oei_3", 2),
        ("oei_4", 3),
    ]
    assert {c.design_variable_prefix for c in oei} == {"oei"}
    assert [c.name for c in vehicle.conditions].index("oei_1") == 9  # where the table is
    assert vehicle.design_variables["oei_lift_rpm"].shape == (4, 7)


@pytest.mark.parametrize(("n", "cases"), [(8, 4), (12, 6)])
def test_one_case_per_mirror_pair(n, cases):
    vehicle = reference_vehicle() if n == 8 else _example(n)
    failed = [c.failed_rotor for c in vehicle.conditions if c.kind == "oei"]
    assert len(failed) == cases == n // 2
    # Each case fails a different pair's left rotor; no two are mirror images of each other.
    pairs = [vehicle.lift_rotors[i].pair for i in failed]
    assert sorted(pairs) == list(range(n // 2))
    assert all(vehicle.lift_rotors[i].hub_position[1] < 0.0 for i in failed)
    assert distinct_failures(vehicle.lift_rotors) == tuple(failed)


def test_four_rotor_layout_has_no_one_rotor_out_case():
    vehicle = _example(4)
    assert len(vehicle.lift_rotors) == 4 and len(vehicle.lift_rotor_pairs) == 2
    assert not [c for c in vehicle.conditions if c.kind == "oei"]
    data = read_vehicle_file(DATA / "lpc_4_lift_rotors.toml")
    oei = copy.deepcopy(data["conditions"][0])
    oei.update(name="oei", kind="oei", failed_rotor="each", design_variable_prefix="oei")
    data["conditions"].append(oei)
    with pytest.raises(VehicleSpecError, match="3 working lift rotors cannot hover trimmed"):
        vehicle_from_dict(data)


def test_each_is_for_one_rotor_out_conditions_only():
    data = read_vehicle_file()
    data["conditions"][0]["failed_rotor"] = "each"
    with pytest.raises(VehicleSpecError, match=r"'conditions\[0\].failed_rotor' = 'each'"):
        vehicle_from_dict(data)


def test_a_message_names_the_file_table_of_a_generated_case():
    data = read_vehicle_file()
    data["conditions"][9]["altitude"] = -5.0
    with pytest.raises(VehicleSpecError) as info:
        vehicle_from_dict(data)
    assert "'conditions[9] (generated oei_1).altitude'" in str(info.value)
    data = read_vehicle_file()
    data["conditions"][10]["speed"] = 5.0  # plus_3g, after the generated cases
    with pytest.raises(VehicleSpecError, match=r"'conditions\[10\].speed' = 5.0"):
        vehicle_from_dict(data)


def test_side_by_side_neighbours():
    # Reference: front row inner pair 2, outer 0; rear row inner 3, outer 1.
    assert side_by_side_pairs(reference_vehicle()) == ((2, 0), (3, 1))
    assert side_by_side_pairs(_example(4)) == ()  # one rotor per side in each row
    # 12 rotors: per side and row three rotors at increasing |y| (pairs 0, 2, 4 front; 1, 3, 5
    # rear, in the order the example writes them).
    assert side_by_side_pairs(_example(12)) == ((0, 2), (2, 4), (1, 3), (3, 5))


@pytest.mark.parametrize("n", [4, 12])
def test_examples_have_one_rotor_group_per_pair(n):
    vehicle = _example(n)
    groups = n // 2 + 1  # the pairs, then the pusher
    assert vehicle.pusher.pair == n // 2
    assert vehicle.design_variables["rotor_radius"].shape == (groups,)
    assert vehicle.design_variables["blade_chord_cp"].shape == (groups, 4)
    # Equal total disk area to the reference's 8 rotors of 1.524 m.
    area = sum(r.radius**2 for r in vehicle.lift_rotors)
    assert area == pytest.approx(8 * 1.524**2, rel=1e-5)


def test_bad_layouts_are_named_errors():
    data = read_vehicle_file()
    del data["lift_rotors"][7]
    with pytest.raises(VehicleSpecError, match="must have 4 or 6 or 8 or 10 or 12 entries"):
        vehicle_from_dict(data)
    data = read_vehicle_file()
    data["lift_rotors"] += copy.deepcopy(data["lift_rotors"][:6])  # 14 rotors
    with pytest.raises(VehicleSpecError, match=r"'lift_rotors' must have 4 or 6 .* got 14"):
        vehicle_from_dict(data)
    data = read_vehicle_file()
    data["lift_rotors"][7]["pair"] = 0  # a rotor without its mirror partner
    with pytest.raises(VehicleSpecError, match="pair 0 has 3 rotors"):
        vehicle_from_dict(data)
    data = read_vehicle_file()
    data["booms"]["attach_points"].pop()
    with pytest.raises(VehicleSpecError, match="'booms.attach_points' has 7 entries"):
        vehicle_from_dict(data)


def test_bounds_follow_the_vehicle_when_left_out():
    # Without lower and upper, a design variable with an initial value in the vehicle's parts is
    # bounded by 0.7 and 1.3 times it (the paper's planform bounds), inside its limits.
    data = read_vehicle_file()
    names = ("wing_area", "rotor_radius", "battery_mass", "fuselage_length")
    for name in names:
        del data["design_variables"][name]["lower"], data["design_variables"][name]["upper"]
    dvs = vehicle_from_dict(data).design_variables
    assert dvs["wing_area"].lower == pytest.approx((0.7 * 19.6,))
    assert dvs["wing_area"].upper == pytest.approx((1.3 * 19.6,))
    assert dvs["rotor_radius"].upper == pytest.approx((1.3 * 1.524,) * 4 + (1.3 * 1.37,))
    assert dvs["battery_mass"].lower == pytest.approx((0.7 * 856.41,))  # battery.mass
    # 1.3 x 9.144 m = 11.887 m: the fuselage regressions' upper data limit holds it.
    assert dvs["fuselage_length"].upper == pytest.approx((11.8872,))
    # A variable without an initial value in the parts still needs its bounds.
    del data["design_variables"]["motor_length"]["lower"]
    with pytest.raises(VehicleSpecError, match="missing key 'design_variables.motor_length.lower'"):
        vehicle_from_dict(data)


def test_several_noise_observers_are_rows_of_the_noise_constraint():
    # Independent number: each observer's level in a three-observer model equals that of a
    # model with that observer alone (the groups share the rotors' loads, not the observer).
    from lpc_mdo.problems import build_analysis_problem
    from lpc_mdo.vehicle.condition_kinds import HoverKind

    data = read_vehicle_file()
    aft = data["noise_observer"]
    side, ahead = {**aft, "azimuth_deg": 90.0}, {**aft, "distance": 150.0, "azimuth_deg": 0.0}
    data["noise_observer"] = [aft, side, ahead]
    vehicle = vehicle_from_dict(data)
    hover = vehicle.condition("hover")
    outputs = [c.output for c in HoverKind.constraints(vehicle, hover, None) if c.kind == "noise"]
    assert outputs == ["total_spl_a", "noise_2.total_spl_a", "noise_3.total_spl_a"]
    prob = build_analysis_problem(vehicle, conditions=["hover"])
    prob.run_model()
    levels = [prob.get_val(f"hover.{name}")[0] for name in outputs]
    for observer, level in zip((aft, side, ahead), levels, strict=True):
        one = read_vehicle_file()
        one["noise_observer"] = observer
        alone = build_analysis_problem(vehicle_from_dict(one), conditions=["hover"])
        alone.run_model()
        assert level == pytest.approx(alone.get_val("hover.total_spl_a")[0], rel=1e-12)
    assert levels[2] < levels[0] - 3.0  # 150 m against 100 m: at least 20 log10(1.5) = 3.5 dB


def test_an_observer_list_names_its_entry():
    data = read_vehicle_file()
    data["noise_observer"] = [data["noise_observer"], {**data["noise_observer"], "distance": 5.0}]
    with pytest.raises(VehicleSpecError, match=r"'noise_observer\[1\]\.distance' = 5\.0"):
        vehicle_from_dict(data)
