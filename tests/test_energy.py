import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.energy.battery import BatteryComp
from lpc_mdo.components.energy.mission_energy import MissionEnergyComp

# Paper rule (docs theory/energy): hover 60 s x2, each transition point x4, climb x2,
# cruise x3, descent x2; OEI and structural cases are not flown.
PAPER_MULTIPLIERS = [2.0, 4.0, 4.0, 2.0, 3.0, 2.0, 0.0]


def mission_problem():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "mission", MissionEnergyComp(energy_multipliers=PAPER_MULTIPLIERS), promotes=["*"]
    )
    prob.model.add_subsystem("battery", BatteryComp(), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("electrical_power", [1.0, 0.8, 0.6, 0.5, 0.3, 0.2, 1.2], units="MW")
    prob.set_val("duration", [60.0, 1.82, 1.82, 218.7, 1210.0, 300.0, 30.0])
    prob.set_val("battery_mass", 800.0)
    prob.set_val("specific_energy", 400.0, units="W*h/kg")
    prob.run_model()
    return prob


def test_mission_energy_matches_hand_calculation():
    prob = mission_problem()
    # By hand (MJ): 2(1.0*60 + 2(0.8*1.82 + 0.6*1.82) + 0.5*218.7 + 0.3*1210 + 0.2*300)
    #               + 0.3*1210 = 2(60 + 5.096 + 109.35 + 363 + 60) + 363 = 1557.892 MJ.
    assert_near_equal(prob.get_val("energy_used", units="MJ"), 1557.892, 1e-12)
    # Capacity, paper eq. 27: 400 Wh/kg x 3600 J/Wh x 800 kg = 1152 MJ.
    assert_near_equal(prob.get_val("energy_capacity", units="MJ"), 1152.0, 1e-12)
    assert_near_equal(prob.get_val("state_of_charge"), 1.0 - 1557.892 / 1152.0, 1e-12)


def test_soc_is_one_without_power_and_linear_in_energy():
    prob = mission_problem()
    prob.set_val("electrical_power", np.zeros(7))
    prob.run_model()
    assert prob.get_val("state_of_charge")[0] == 1.0
    socs = []
    for scale in (1.0, 2.0, 3.0):
        prob.set_val("electrical_power", scale * np.full(7, 1e5))
        prob.run_model()
        socs.append(prob.get_val("state_of_charge")[0])
    # Equal steps in energy give equal steps in SoC (eq. 28 is affine in E_used).
    assert_near_equal(socs[1] - socs[0], socs[2] - socs[1], 1e-12)


def test_initial_soc_shifts_the_final_soc_by_itself():
    prob = mission_problem()
    full = prob.get_val("state_of_charge")[0]
    prob.set_val("initial_soc", 0.9)
    prob.run_model()
    # Closed form: SoC_final = SoC_0 - E_used / E_total = 0.9 - 1557.892 / 1152 (MJ).
    assert_near_equal(prob.get_val("state_of_charge"), 0.9 - 1557.892 / 1152.0, 1e-12)
    assert_near_equal(full - prob.get_val("state_of_charge")[0], 0.1, 1e-12)
    # The capacity is that of a full charge, whatever the start.
    assert_near_equal(prob.get_val("energy_capacity", units="MJ"), 1152.0, 1e-12)


def test_partials():
    prob = mission_problem()
    prob.set_val("initial_soc", 0.85)
    prob.run_model()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-8, rtol=1e-10)
    assert ("state_of_charge", "initial_soc") in data["battery"]


def test_bad_inputs():
    with pytest.raises(
        ValueError,
        match=r"'energy_multipliers\[1\]' = -2.0 is out of range: "
        r"must be >= 0",
    ):
        prob = om.Problem(reports=False)
        prob.model.add_subsystem("m", MissionEnergyComp(energy_multipliers=[1.0, -2.0]))
        prob.setup()
    prob = mission_problem()
    prob.set_val("battery_mass", -5.0)
    with pytest.raises(
        om.AnalysisError,
        match=r"'battery_mass' = -5.0"
        r" is out of range: must be > 0 \(kg\)",
    ):
        prob.run_model()
    for bad in (0.0, 1.2):
        prob = mission_problem()
        prob.set_val("initial_soc", bad)
        with pytest.raises(
            om.AnalysisError,
            match=rf"'initial_soc' = {bad} is out of range: "
            r"must be in \(0, 1\]",
        ):
            prob.run_model()
    prob = mission_problem()
    prob.set_val("duration", [-1.0, 0, 0, 0, 0, 0, 0])
    with pytest.raises(om.AnalysisError, match="duration = .* s; must be >= 0"):
        prob.run_model()
