"""The mission as a designer states it: segments, legs, reserve rules, a hot day."""

import copy
import math
import re

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.atmosphere import AtmosphereComp, standard_atmosphere
from lpc_mdo.components.energy.mission_energy import MissionEnergyComp
from lpc_mdo.vehicle import VehicleSpecError, read_vehicle_file, vehicle_from_dict
from lpc_mdo.vehicle.mission_profile import mission_profile
from lpc_mdo.vehicle.reserve_rules import RESERVE_PRESETS

REFERENCE = read_vehicle_file()
CLIMB_RATE = 60.8756 * math.sin(math.radians(4.3072))  # the reference climb, m/s
DESCENT_RATE = -60.8756 * math.sin(math.radians(3.0))


def segment_data(segments=None, reserve=None, **mission):
    """Return the reference data with its mission stated as segments (the paper's mission)."""
    data = copy.deepcopy(REFERENCE)
    if segments is None:  # the paper's mission: two legs, the outbound transition flown twice
        transition = 14.41482 * 5  # the reference's five points, s
        segments = [
            {"condition": "hover", "duration": 60.0},
            {"condition": "transition", "duration": transition},
            {"condition": "climb", "to_altitude": 999.74, "vertical_speed": CLIMB_RATE},
            {"condition": "cruise", "duration": 1210.04},
            {"condition": "descent", "to_altitude": 76.2, "vertical_speed": DESCENT_RATE},
            {"condition": "transition", "duration": transition},
        ]
        reserve = {"rule": "time", "duration_min": 1210.04 / 60.0} if reserve is None else reserve
    named = {s["condition"] for s in segments}
    for c in data["conditions"]:
        if c["name"] in named or c["design_variable_prefix"] in named and c["kind"] == "transition":
            c.pop("altitude")
            c.pop("flight_path_angle_deg")
        c.pop("duration")
        c.pop("energy_weight")
    data["mission"].update(start_altitude=76.2, legs=2, segments=segments, **mission)
    if reserve is not None:
        data["mission"]["reserve"] = reserve
    return data


def test_the_papers_mission_as_segments_gives_the_reference_energy_sum():
    # The reference file states the paper's rule per condition (hover 60 s x 2, each transition
    # point x 4, climb x 2, cruise x 3, descent x 2); as segments: two legs plus a reserve of
    # one cruise pass. Each condition's energy time k t must agree (the file rounds durations to
    # 0.01 s; the transition points: the file's 14.40-14.43 s against their mean, 0.2 %).
    ours = vehicle_from_dict(segment_data())
    reference = vehicle_from_dict(copy.deepcopy(REFERENCE))
    for a, b in zip(ours.conditions, reference.conditions, strict=True):
        assert a.altitude == pytest.approx(b.altitude, abs=0.01), a.name
        assert a.flight_path_angle == pytest.approx(b.flight_path_angle, abs=1e-6), a.name
        reserve = ours.mission.reserve_time if a.name == ours.mission.reserve_condition else 0.0
        tolerance = 2e-3 if a.kind == "transition" else 5e-5
        assert a.energy_weight * a.duration + reserve == pytest.approx(
            b.energy_weight * b.duration, rel=tolerance
        ), a.name
    assert ours.mission.reserve_condition == "cruise"
    assert ours.mission.reserve_time == pytest.approx(1210.04)


def test_a_mission_by_hand():
    # Start at 100 m; hover 30 s; climb in 'climb' (60.8756 m/s) to 400 m at 5 m/s: 60 s,
    # gamma = asin(5/60.8756) = 4.711 deg, at the mean 250 m; cruise 50 km at 57.1897 m/s:
    # 874.29 s at 400 m; descent at -2 m/s to 100 m: 150 s; a 2-leg mission; the NASA reserve:
    # 20 min at the cruise condition.
    segments = [
        {"condition": "hover", "duration": 30.0},
        {"condition": "climb", "to_altitude": 400.0, "vertical_speed": 5.0},
        {"condition": "cruise", "distance_km": 50.0},
        {"condition": "descent", "to_altitude": 100.0, "vertical_speed": -2.0},
    ]
    data = segment_data(segments, reserve={"rule": "nasa_uam"})
    data["mission"]["start_altitude"] = 100.0
    vehicle = vehicle_from_dict(data)
    climb, cruise, descent = (vehicle.condition(n) for n in ("climb", "cruise", "descent"))
    assert climb.duration == pytest.approx(60.0)
    assert math.degrees(climb.flight_path_angle) == pytest.approx(4.7112, abs=1e-4)
    assert climb.altitude == pytest.approx(250.0)
    assert cruise.duration == pytest.approx(50e3 / 57.1897) and cruise.altitude == 400.0
    assert descent.duration == pytest.approx(150.0) and descent.energy_weight == 2.0
    assert math.degrees(descent.flight_path_angle) == pytest.approx(
        math.degrees(math.asin(-2.0 / 60.8756))
    )
    assert vehicle.mission.reserve_time == 1200.0
    # the transition points are not flown: no energy weight
    assert vehicle.condition("transition_1").energy_weight == 0.0
    rows, _, _ = mission_profile(vehicle.mission, vehicle.conditions)
    assert [r.segment for r in rows][-1] == "reserve" and rows[-1].distance == pytest.approx(
        57.1897 * 1200.0
    )


@pytest.mark.parametrize(
    "rule, minutes",
    [
        ("faa_vfr_day", 30.0),
        ("faa_vfr_night", 45.0),
        ("faa_vfr_rotorcraft", 20.0),
        ("nasa_uam", 20.0),
    ],
)
def test_reserve_presets_against_the_rule(rule, minutes):
    # Each preset is a time at the reserve condition (its source: RESERVE_PRESETS[rule].source);
    # the reserve energy is that time times the condition's power (MissionEnergyComp below).
    vehicle = vehicle_from_dict(segment_data(reserve={"rule": rule}))
    assert vehicle.mission.reserve_time == minutes * 60.0
    assert re.search(r"14 CFR|NASA", RESERVE_PRESETS[rule].source)


def test_a_climb_by_its_flight_path_angle():
    # gamma = 4.3072 deg at 60.8756 m/s: V_z = 4.5720 m/s (the reference's 900 ft/min).
    data = segment_data()
    data["mission"]["segments"][2] = {
        "condition": "climb", "to_altitude": 999.74, "flight_path_angle_deg": 4.3072
    }  # fmt: skip
    climb = vehicle_from_dict(data).condition("climb")
    assert climb.duration == pytest.approx((999.74 - 76.2) / CLIMB_RATE, rel=1e-12)
    data["mission"]["segments"][2]["vertical_speed"] = CLIMB_RATE
    _fails(data, "'mission.segments[2].flight_path_angle_deg' goes with 'to_altitude' in a")


def test_reserve_by_distance_and_at_another_condition():
    vehicle = vehicle_from_dict(
        segment_data(reserve={"rule": "distance", "distance_km": 30.0, "condition": "climb"})
    )
    assert vehicle.mission.reserve_condition == "climb"
    assert vehicle.mission.reserve_time == pytest.approx(30e3 / 60.8756)


def test_mission_energy_with_a_reserve_by_hand_and_its_partials():
    # E = k . (P t) + P_r t_res: two conditions of 100 kW (x2, 60 s) and 50 kW (x2, 600 s),
    # reserve 1200 s at the second: 2 (6 + 30) MJ + 60 MJ = 132 MJ.
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "m", MissionEnergyComp(energy_multipliers=[2.0, 2.0], reserve_index=1), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("electrical_power", [1e5, 5e4])
    prob.set_val("duration", [60.0, 600.0])
    prob.set_val("reserve_duration", 1200.0)
    prob.run_model()
    assert prob.get_val("energy_used")[0] == pytest.approx(132e6)
    assert_check_partials(prob.check_partials(method="cs", out_stream=None), atol=1e-6, rtol=1e-9)


def test_hot_day_atmosphere_keeps_the_pressure_and_its_partials():
    # ISA+20 K at 1000 m: the ISA pressure (89875 Pa), T = 281.65 + 20 K, rho = p/(R T)
    # (ICAO Doc 7488/3 convention), a = sqrt(gamma R T).
    t0, p0, rho0, a0, _ = standard_atmosphere(1000.0)
    t, p, rho, a, _ = standard_atmosphere(1000.0, temperature_offset=20.0)
    assert p == pytest.approx(p0, rel=1e-14) and p0 == pytest.approx(89874.6, rel=1e-5)
    assert t == pytest.approx(t0 + 20.0)
    assert rho == pytest.approx(rho0 * t0 / (t0 + 20.0), rel=1e-12)
    assert a == pytest.approx(a0 * math.sqrt((t0 + 20.0) / t0), rel=1e-12)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("atm", AtmosphereComp(num_nodes=3, temperature_offset=20.0))
    prob.setup(force_alloc_complex=True)
    prob.set_val("atm.altitude", np.array([0.0, 1000.0, 3048.0]))
    prob.run_model()
    assert_check_partials(prob.check_partials(method="cs", out_stream=None), atol=1e-12, rtol=1e-9)


@pytest.mark.integration
def test_a_hot_day_reaches_every_condition():
    from lpc_mdo.components.aero.polar import LinearQuadraticPolar
    from lpc_mdo.groups.lpc import LPCGroup

    vehicle = vehicle_from_dict(segment_data(temperature_offset=20.0))
    assert vehicle.mission.isa_offset == 20.0
    prob = om.Problem(
        LPCGroup(
            vehicle=vehicle,
            conditions=["hover", "cruise"],
            rotor_polar=LinearQuadraticPolar(),
            wing_zero_lift_angle=-0.07,
        ),
        reports=False,
    )
    prob.setup()
    for name in ("hover", "cruise"):  # the component's physics: the test above
        atmosphere = prob.model._get_subsystem(f"{name}.atmosphere")
        assert atmosphere.options["temperature_offset"] == 20.0


def _fails(data, message):
    with pytest.raises(VehicleSpecError, match=re.escape(message)):
        vehicle_from_dict(data)


def test_bad_missions_get_one_named_error():
    def segment(index, **values):
        data = segment_data()
        condition = data["mission"]["segments"][index]["condition"]
        data["mission"]["segments"][index] = {"condition": condition, **values}
        return data

    _fails(segment(3, distance_km=-5.0), "'mission.segments[3].distance_km' = -5.0 is out of range")
    _fails(
        segment(2, to_altitude=50.0, vertical_speed=CLIMB_RATE),
        "'mission.segments[2].to_altitude' = 50 m with 'vertical_speed' = 4.572 m/s: a climb "
        "from 76.2 m (where the segment starts) must end above it",
    )
    _fails(
        segment(3, duration=10.0, distance_km=5.0), "give exactly one of 'duration', 'distance_km'"
    )
    _fails(
        segment(3, to_altitude=2000.0),
        "'mission.segments[3].vertical_speed' (or 'flight_path_angle_deg') goes with",
    )
    _fails(segment(0, distance_km=1.0), "a distance is flown in a 'steady' condition")
    _fails(segment(1, distance_km=1.0), "a transition segment is flown for a 'duration'")
    data = segment_data()
    data["mission"]["segments"][0]["condition"] = "oei_1"
    _fails(data, "'mission.segments[0].condition' = 'oei_1' is of kind 'oei'")
    data["mission"]["segments"][0]["condition"] = "taxi"
    _fails(data, "'mission.segments[0].condition' = 'taxi' is not a condition of the vehicle")
    data = segment_data()
    data["conditions"][7]["duration"] = 1210.04  # cruise: the mission sets it
    _fails(data, "'conditions[7].duration': condition 'cruise' is flown by the mission's segments")
    data = segment_data()
    data["conditions"][9]["energy_weight"] = 1.0  # oei_1 is not flown
    _fails(data, "a condition they do not fly has no energy weight")
    data = segment_data(reserve={"rule": "nasa_uam", "duration_min": 30.0})
    _fails(data, "rule 'nasa_uam' sets the reserve (20 min)")
    data = segment_data(reserve={"rule": "time"})
    _fails(data, "rule 'time' takes 'duration_min'")
    data = segment_data(reserve={"rule": "time", "duration_min": 20.0, "condition": "plus_3g"})
    _fails(data, "'mission.reserve.condition' = 'plus_3g': allowed: a 'steady' or 'hover'")
    data = segment_data()
    data["mission"].pop("start_altitude")
    _fails(data, "missing key 'mission.start_altitude'")
    data = copy.deepcopy(REFERENCE)
    data["mission"]["legs"] = 2
    _fails(data, "'mission.legs' goes with the mission's segments")
    data = copy.deepcopy(REFERENCE)
    data["conditions"][0].pop("duration")
    _fails(data, "missing key 'conditions[0].duration' (without [[mission.segments]]")
    data = segment_data(temperature_offset=80.0)
    _fails(data, "'mission.temperature_offset' = 80.0 is out of range")


def test_one_condition_flown_at_two_altitudes_is_refused():
    data = segment_data()
    data["mission"]["segments"].append({"condition": "hover", "duration": 30.0})
    data["mission"]["segments"].insert(
        4, {"condition": "cruise", "to_altitude": 1200.0, "vertical_speed": 0.0}
    )
    with pytest.raises(VehicleSpecError):
        vehicle_from_dict(data)
    data = segment_data()
    data["mission"]["segments"][4]["to_altitude"] = 300.0  # descent ends at 300 m, hover at 76 m
    data["mission"]["segments"].append({"condition": "hover", "duration": 30.0})
    _fails(data, "at 300 m and 0 deg, 'mission.segments[1]' at 76.2 m")
