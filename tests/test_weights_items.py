"""Named mass items: wing secondary structure, landing gear, systems, stations, rotors, cg."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.api.weights import format_mass_properties, mass_breakdown, mass_properties
from lpc_mdo.components.weights.item_placement import FuselageStationComp
from lpc_mdo.components.weights.landing_gear import (
    NASA_LANDING_GEAR_FRACTION,
    LandingGearMassComp,
)
from lpc_mdo.components.weights.systems import SystemsMassComp
from lpc_mdo.components.weights.wing_secondary import WingSecondaryMassComp
from lpc_mdo.groups.vehicle import VehicleGroup, calibrated_other_mass
from lpc_mdo.groups.weights import NASA_FUSELAGE_LENGTH, WeightsGroup, motor_group_indices
from lpc_mdo.vehicle import paper_calibrated_vehicle, reference_vehicle

LB, FT = 0.45359237, 0.3048


def run(comp, **values):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("comp", comp, promotes=["*"])
    prob.setup(force_alloc_complex=True)
    for name, value in values.items():
        prob.set_val(name, value)
    prob.run_model()
    return prob


def test_wing_secondary_flops_general_aviation():
    # FLOPS GA wing terms (NASA/TM-2017-219627) by hand in lb and ft^2 at S_w = 200 ft^2,
    # W_dg = 5000 lb, FLAPR 0.333: W2 = 0.25 sqrt(66.6) sqrt(5000) = 144.2654 lb,
    # W3 = 0.16 * 200^1.2 = 92.3328 lb; 1e-6.
    prob = run(WingSecondaryMassComp(), wing_area=200.0 * FT**2, design_gross_mass=5000.0 * LB)
    assert_near_equal(prob.get_val("wing_control_surface_mass", units="lbm"), 144.26538, 1e-6)
    assert_near_equal(prob.get_val("wing_misc_mass", units="lbm"), 92.332794, 1e-6)
    assert_near_equal(prob.get_val("wing_secondary_mass", units="lbm"), 236.59817, 1e-6)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_raymer_general_aviation_systems():
    # Raymer Sec. 15.3.3 (eqs. 15.54-15.59) by hand in lb/ft: L 25 ft, b 36 ft, N_z 5.7,
    # W_dg 2500 lb, W_uav 30 lb, N_p 4, M 0.2 -> flight controls 37.3209, avionics 50.5679,
    # electrical 92.9633, air conditioning 68.1266, furnishings 80.5 lb; 1e-6.
    comp = SystemsMassComp(
        ultimate_load_factor=5.7, num_persons=4, uninstalled_avionics_mass=30.0 * LB,
        cruise_mach=0.2,
    )  # fmt: skip
    prob = run(comp, fuselage_length=25.0 * FT, wing_span=36.0 * FT, design_gross_mass=2500.0 * LB)
    expected = {
        "flight_controls": 37.320877,
        "avionics": 50.567908,
        "electrical": 92.963298,
        "environmental_control": 68.126585,
        "furnishings": 80.5,
    }
    for name, value in expected.items():
        assert_near_equal(prob.get_val(f"{name}_mass", units="lbm"), value, 1e-6)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_landing_gear_nasa_weight_statement():
    # NASA LPC NDARC weight statement (GUAM build_Lift_plus_Cruise.m): landing gear
    # 8.48397 slug = 123.814 kg of 181.789 slug = 2653.016 kg; the fraction reproduces it, 1e-5.
    assert_near_equal(NASA_LANDING_GEAR_FRACTION, 0.0466692, 1e-5)
    prob = run(LandingGearMassComp(), design_gross_mass=2653.0159)
    assert_near_equal(prob.get_val("landing_gear_mass"), 123.81424, 1e-6)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)


def test_landing_gear_station_is_nasa_gear_position():
    # At NASA's fuselage length the gear sits where GUAM puts it: (-13.3246 ft + 2.464 ft)
    # * 0.3048 = -3.310324 m, z (-1.391179 + 5.113) * 0.3048 = 1.134411 m; 1e-6.
    from lpc_mdo.groups.weights import NASA_STATIONS

    comp = FuselageStationComp(stations={"landing_gear": NASA_STATIONS["landing_gear"]})
    prob = run(comp, fuselage_length=NASA_FUSELAGE_LENGTH)
    assert_near_equal(prob.get_val("landing_gear_cg"), [-3.310324, 0.0, 1.134411], 1e-6)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)
    with pytest.raises(ValueError, match="must be"):
        FuselageStationComp(stations={"gear": (2.0, 0.0, 0.0)})


def weights():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("weights", WeightsGroup(), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.run_model()
    return prob


def test_rotor_masses_are_wired_per_group_and_grow_with_radius():
    prob = weights()
    group = prob.get_val("rotor_group_mass").copy()
    assert_near_equal(prob.get_val("rotor_mass"), group[motor_group_indices()], 1e-15)
    before = prob.get_val("gross_mass").copy()
    radius = prob.get_val("rotor_radius").copy()
    prob.set_val("rotor_radius", radius * 1.1)
    prob.run_model()
    # AFDD00: blade mass ~ R^(1.742 + 0.876), so +10 % radius adds > 20 % rotor mass.
    assert np.all(prob.get_val("rotor_group_mass") > 1.2 * group)
    assert prob.get_val("gross_mass")[0] > before[0]


def test_cg_moves_with_fuselage_length_and_battery_position():
    prob = weights()
    cg0 = prob.get_val("cg").copy()
    mass = prob.get_val("total_mass")[0]
    battery = prob.get_val("battery_mass")[0]
    # Battery 1 m aft: the cg moves aft by m_battery / m exactly (first moment), 1e-10.
    prob.set_val("battery_cg", prob.get_val("battery_cg") + [-1.0, 0.0, 0.0])
    prob.run_model()
    assert_near_equal(cg0[0] - prob.get_val("cg")[0], battery / mass, 1e-10)
    # Fuselage 1 m longer: fuselage, empennage, gear and systems move aft, so does the cg.
    prob.set_val("battery_cg", prob.get_val("battery_cg") + [1.0, 0.0, 0.0])
    prob.set_val("fuselage_length", prob.get_val("fuselage_length") + 1.0)
    prob.run_model()
    assert prob.get_val("cg")[0] < cg0[0] - 0.05


def test_mass_properties_table_adds_up():
    prob = weights()
    rows = mass_properties(prob)
    vehicle = rows[-1]
    assert_near_equal(sum(r["mass"] for r in rows[:-1]), vehicle["mass"], 1e-12)
    assert_near_equal(sum(r["inertia"] for r in rows[:-1]), vehicle["inertia"], 1e-10)
    moment = sum(r["mass"] * r["cg"] for r in rows[:-1])
    assert_near_equal(moment / vehicle["mass"], vehicle["cg"], 1e-12)
    text = format_mass_properties(rows)
    assert "landing gear" in text and "drive system" in text and "vehicle" in text


def test_report_reads_the_mass_properties_of_a_recorded_case(tmp_path):
    # The report reads the item table from the final case (includes=['*'], as the problems
    # record it): the same rows as the live problem.
    from lpc_mdo.post.report import mass_properties_table

    prob = om.Problem(reports=False)
    prob.model.add_subsystem("weights", WeightsGroup(), promotes=["*"])
    path = tmp_path / "cases.sql"
    prob.add_recorder(om.SqliteRecorder(str(path)))
    prob.recording_options["includes"] = ["*"]
    prob.setup()
    prob.run_model()
    prob.record("final")
    prob.cleanup()
    live = mass_properties(prob)
    table = mass_properties_table(om.CaseReader(str(path)))
    assert [r[0] for r in table.rows] == [r["name"].replace("_", " ") for r in live]
    for row, ref in zip(table.rows, live, strict=True):
        assert_near_equal(row[1], ref["mass"], 1e-12)
        assert_near_equal(np.array(row[3:6]), ref["cg"], 1e-12)
        assert_near_equal(row[6], ref["inertia"][0, 0], 1e-12)
    assert_near_equal(table.rows[-1][2], 100.0, 1e-12)


def test_every_kilogram_of_the_reference_is_an_item():
    # At most 10 % of the gross mass may be unitemised (W_other). The reference vehicle itemises
    # everything: its rule keeps W_other at the file's 0 kg, and the breakdown's items add up to
    # the gross mass. The paper's calibration to 3723.99 kg (paper Sec. IV) would leave 15.1 %
    # unitemised (docs theory/weights 'Gross mass'), which is why the reference does not use it.
    vehicle = reference_vehicle()
    assert (vehicle.masses.other_rule, vehicle.masses.other) == ("fixed", 0.0)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vehicle", VehicleGroup(vehicle=vehicle), promotes=["*"])
    prob.setup()
    prob.run_model()
    breakdown = mass_breakdown(prob)
    assert breakdown["other"] == 0.0
    items = sum(v for k, v in breakdown.items() if k not in ("structures", "powertrain", "gross"))
    assert_near_equal(items, breakdown["gross"], 1e-12)
    paper = paper_calibrated_vehicle()
    other, _ = calibrated_other_mass(paper)
    assert_near_equal(other / paper.masses.design_gross_mass, 0.1510, 2e-3)
