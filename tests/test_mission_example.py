"""The shipped mission example: ISA+20, two cruise segments, a reserve rule; it trims."""

from importlib import resources

import pytest
from run_script_loader import load_run_script

from lpc_mdo.analysis import analyze_vehicle
from lpc_mdo.vehicle import load_vehicle

EXAMPLE = resources.files("lpc_mdo") / "data" / "lpc_mission_example.toml"


def test_the_shipped_file_is_what_its_script_writes(tmp_path):
    module = load_run_script("make_mission_example")
    assert module.main(["--output-dir", str(tmp_path)]) == 0
    assert (tmp_path / module.NAME).read_text() == EXAMPLE.read_text()


def test_the_example_derives_its_conditions():
    vehicle = load_vehicle(EXAMPLE)
    assert vehicle.mission.isa_offset == 20.0 and vehicle.mission.reserve_time == 1800.0
    fast = vehicle.condition("cruise_fast")
    assert fast.duration == pytest.approx(30e3 / 65.0) and fast.altitude == 457.2
    assert vehicle.condition("hover").altitude == pytest.approx(7.62)  # mean of 0 and 15.24 m


@pytest.mark.integration
def test_the_example_trims_its_mission():
    vehicle = load_vehicle(EXAMPLE)
    mission = [c.name for c in vehicle.mission_segments]  # the energy's conditions
    analysis = analyze_vehicle(vehicle, conditions=mission, processes=2)
    assert analysis.failed == {}, analysis.failed
    prob = analysis.prob
    # the hot day: cruise at 457.2 m and ISA+20 (ICAO Doc 7488/3 convention)
    assert prob.get_val("cruise.temperature")[0] == pytest.approx(288.15 - 6.5e-3 * 457.2 + 20.0)
    # the energy: the one leg's segments once each plus 30 min of cruise
    segments = prob.get_val("segment_energy")
    cruise_power = prob.get_val("cruise.electrical_power")[0]
    assert prob.get_val("energy_used")[0] == pytest.approx(segments.sum() + cruise_power * 1800.0)
