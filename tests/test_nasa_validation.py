"""NASA's own sizing of the lift-plus-cruise vehicle as a validation case."""

from importlib import resources

import pytest
from run_script_loader import load_run_script

from lpc_mdo.sizing import size_vehicle
from lpc_mdo.vehicle import load_vehicle

VEHICLE = resources.files("lpc_mdo") / "data" / "nasa_lpc_mission.toml"
LB, KW_PER_HP = 0.45359237, 0.7457

#: NASA's numbers (AIAA 2018-3847 Table 3, as transcribed; docs results 'Validation') and the
#: tolerances the docs justify, set before the comparison was run.
NASA = {
    "gross_mass": (8210 * LB, 0.10),
    "empty_mass": (7000 * LB, 0.10),
    "battery_mass": (2200 * LB, 0.15),
    "disk_loading": (13.1 * 47.880259, 0.10),
}
#: Our differences as the docs give them (relative), to 0.5 %, and whether each is within its
#: tolerance: with the trims at least power within the rotors' limits none is, for the reasons
#: the docs measure (drag area, hover efficiency, weights, battery rule).
DOCUMENTED = {
    "gross_mass": (-0.155, False),
    "empty_mass": (-0.181, False),
    "battery_mass": (-0.463, False),
    "disk_loading": (-0.157, False),
}


def test_the_shipped_file_is_what_its_script_writes(tmp_path):
    module = load_run_script("make_nasa_validation")
    assert module.main(["--output-dir", str(tmp_path)]) == 0
    assert (tmp_path / module.NAME).read_text() == VEHICLE.read_text()
    vehicle = load_vehicle(VEHICLE)
    assert vehicle.masses.payload == pytest.approx(1200 * LB, abs=0.01)
    assert vehicle.mission.legs == 2 and vehicle.mission.reserve_time == 1200.0
    assert vehicle.condition("cruise").altitude == pytest.approx(3048.0)


@pytest.mark.slow  # 90-105 s on the 2-core machine: the whole sizing, 5 steps of 15 trims
def test_sized_to_nasas_mission_against_nasas_numbers():
    result = size_vehicle(load_vehicle(VEHICLE), processes=2)
    assert abs(result.final_soc - 0.0) <= 1e-3  # closed: the whole capacity used
    assert abs(result.gross_mass - result.design_gross_mass) <= 0.1
    # every motor sized to its torque margin, within its voltage limit
    limits = load_vehicle(VEHICLE).constraints
    assert result.motors.torque_margin == pytest.approx(limits.min_torque_margin, abs=2e-3)
    assert min(result.motors.voltage_margin) >= limits.min_voltage_margin
    ours = {
        "gross_mass": result.gross_mass,
        "empty_mass": result.gross_mass - result.breakdown["payload"],
        "battery_mass": result.battery_mass,
        "disk_loading": result.disk_loading,
    }
    for name, (nasa, tolerance) in NASA.items():
        difference = ours[name] / nasa - 1.0
        documented, within = DOCUMENTED[name]
        assert difference == pytest.approx(documented, abs=5e-3), name
        assert (abs(difference) <= tolerance) == within, name  # the docs' account of each
