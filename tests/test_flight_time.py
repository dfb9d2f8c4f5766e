"""Times of the conditions whose optimized speeds fly stated distances."""

import copy
from importlib import resources

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.energy.flight_time import FlightTimeComp
from lpc_mdo.vehicle import VehicleSpecError, read_vehicle_file, vehicle_from_dict

MISSION_EXAMPLE = resources.files("lpc_mdo") / "data" / "lpc_mission_example.toml"


def _run(speeds, **options):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("t", FlightTimeComp(**options), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    for name, value in speeds.items():
        prob.set_val(f"{name}_speed", value)
    prob.run_model()
    return prob


OPTIONS = dict(
    fixed_time=[60.0, 100.0, 50.0, 30.0],
    distance=[0.0, 40e3, 30e3, 0.0],
    speed_conditions={"cruise": 1, "cruise_fast": 2},
    reserve_time=1800.0,
    reserve_distance=100e3,
    reserve_condition="cruise",
)


def test_times_are_distance_over_speed_and_partials_exact():
    # By hand: 100 + 40 km / 50 m/s = 900 s; 50 + 30 km / 60 m/s = 550 s; the reserve's
    # 100 km at the cruise speed 2000 s (its 1800 s time is not used where it has a distance).
    prob = _run({"cruise": 50.0, "cruise_fast": 60.0}, **OPTIONS)
    assert_near_equal(prob.get_val("duration"), [60.0, 900.0, 550.0, 30.0], 1e-15)
    assert_near_equal(prob.get_val("reserve_duration"), [2000.0], 1e-15)
    data = prob.check_partials(method="cs", out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)


def test_a_reserve_flown_for_a_time_keeps_it():
    options = dict(OPTIONS, reserve_distance=0.0)
    prob = _run({"cruise": 50.0, "cruise_fast": 60.0}, **options)
    assert_near_equal(prob.get_val("reserve_duration"), [1800.0], 1e-15)


def test_a_speed_at_or_below_zero_is_an_analysis_error():
    with pytest.raises(om.AnalysisError, match=r"cruise_speed.*m/s"):
        _run({"cruise": 0.0, "cruise_fast": 60.0}, **OPTIONS)


def _mission_example(**cruise):
    data = copy.deepcopy(read_vehicle_file(str(MISSION_EXAMPLE)))
    names = [c["name"] for c in data["conditions"]]
    data["conditions"][names.index("cruise")].update(cruise)
    return data


def test_an_optimized_speed_is_a_design_variable_of_its_condition():
    data = _mission_example(speed_rule="optimized")
    data["design_variables"]["cruise_speed"] = {
        "units": "m/s",
        "lower": 45.0,
        "upper": 75.0,
        "ref": 50.0,
    }
    vehicle = vehicle_from_dict(data)
    cruise = vehicle.condition("cruise")
    assert cruise.optimizes_speed and cruise.level_distance == 40e3
    speed = vehicle.design_variables["cruise_speed"]
    assert speed.initial == (cruise.speed,) and (speed.lower, speed.upper) == ((45.0,), (75.0,))
    # the fixed speed of every other condition stays
    assert not vehicle.condition("cruise_fast").optimizes_speed


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"speed_rule": "optimized"}, r"missing key 'design_variables.cruise_speed'"),
        ({"speed_rule": "fastest"}, r"speed_rule.*'fixed', 'optimized'"),
    ],
)
def test_bad_speed_rules_are_named(change, message):
    with pytest.raises(VehicleSpecError, match=message):
        vehicle_from_dict(_mission_example(**change))


def test_an_optimized_speed_in_a_climb_is_refused():
    data = copy.deepcopy(read_vehicle_file(str(MISSION_EXAMPLE)))
    names = [c["name"] for c in data["conditions"]]
    data["conditions"][names.index("climb")]["speed_rule"] = "optimized"
    with pytest.raises(VehicleSpecError, match=r"speed_rule' = 'optimized' is not allowed.*climb"):
        vehicle_from_dict(data)


def test_the_mission_energy_follows_the_speed():
    # The model's energy of the 40 km cruise at V is P(V) x 40 km / V: run at two speeds (the
    # power at each from the model itself), by hand.
    from lpc_mdo.problems import build_analysis_problem

    data = _mission_example(speed_rule="optimized")
    data["design_variables"]["cruise_speed"] = {"units": "m/s", "lower": 45, "upper": 75, "ref": 50}
    prob = build_analysis_problem(vehicle_from_dict(data))
    for speed in (55.0, 62.0):
        prob.set_val("cruise_speed", speed, units="m/s")
        prob.run_model()
        power = prob.get_val("cruise.electrical_power", units="W")[0]
        names = [c.name for c in prob.model._powered]
        segment = prob.get_val("segment_energy", units="J")[names.index("cruise")]
        cruise = prob.vehicle.condition("cruise")
        fixed = cruise.duration - 40e3 / cruise.speed
        assert_near_equal(segment, power * (fixed + 40e3 / speed), 1e-12)
    np.testing.assert_allclose(fixed, 0.0, atol=1e-9)  # the cruise is one 40 km segment


def test_a_range_sweep_moves_the_distance_an_optimized_speed_flies():
    from lpc_mdo.sweep_parameters import reference_value, sweep_vehicle

    data = _mission_example(speed_rule="optimized")
    data["design_variables"]["cruise_speed"] = {"units": "m/s", "lower": 45, "upper": 75, "ref": 50}
    vehicle = vehicle_from_dict(data)
    assert reference_value(vehicle, "cruise_range") == pytest.approx(40.0)
    swept = sweep_vehicle(vehicle, "cruise_range", 55.0).condition("cruise")
    before = vehicle.condition("cruise")
    assert swept.level_distance == pytest.approx(55e3)
    # the time at the initial speed follows: 15 km more at 57.19 m/s
    assert swept.duration - before.duration == pytest.approx(15e3 / before.speed)


def test_the_best_range_study_writes_optimized_cruise_speeds(tmp_path):
    from run_script_loader import load_run_script

    from lpc_mdo.vehicle import load_vehicle

    script = load_run_script("best_range_study")
    target = tmp_path / "best_range.toml"
    assert script.main(["write", str(MISSION_EXAMPLE), str(target)]) == 0
    vehicle = load_vehicle(target)
    for name in ("cruise", "cruise_fast"):
        assert vehicle.condition(name).optimizes_speed
        assert vehicle.design_variables[f"{name}_speed"].lower == (40.0,)
    assert script.main(["write", str(MISSION_EXAMPLE), str(target)]) == 1  # not over a file


def test_an_optimized_speed_needs_the_mission_as_segments():
    data = copy.deepcopy(read_vehicle_file())  # the reference: durations, no segments
    names = [c["name"] for c in data["conditions"]]
    data["conditions"][names.index("cruise")]["speed_rule"] = "optimized"
    with pytest.raises(VehicleSpecError, match=r"speed_rule' = 'optimized' goes with the mission"):
        vehicle_from_dict(data)
