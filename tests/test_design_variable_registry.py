"""The vehicle-level design variables come from one registry: schema, model and baseline.

Each place that lists them (the vehicle file's tables, the vehicle group's inputs, the baseline
problem's set S of paper eqs. 8-9) is checked against
``lpc_mdo.vehicle.design_variable_registry.VEHICLE_DESIGN_VARIABLES``.
"""

import dataclasses

import numpy as np
import openmdao.api as om
import pytest

from lpc_mdo.groups.vehicle import VehicleGroup
from lpc_mdo.problems import BaselineModel
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.condition_layout import condition_layout
from lpc_mdo.vehicle.design_variable_registry import (
    BASELINE_SET,
    VEHICLE_DESIGN_VARIABLES,
    VehicleDesignVariable,
)
from lpc_mdo.vehicle.design_variables import _design_variable_specs

VEHICLE = reference_vehicle()
NAMES = [dv.name for dv in VEHICLE_DESIGN_VARIABLES]


def test_vehicle_file_tables_follow_the_registry():
    dvs = VEHICLE.design_variables
    # Every design variable of the file is the registry's or a condition's (the layout's).
    conditions = condition_layout(VEHICLE).design_variables
    assert sorted(set(dvs) - set(conditions)) == sorted(NAMES)
    groups = len(VEHICLE.lift_rotor_pairs) + 1
    bays = VEHICLE.wing_box.num_bays
    for dv in VEHICLE_DESIGN_VARIABLES:
        entry = dvs[dv.name]
        assert entry.units == dv.units
        assert entry.shape == dv.shape_of(groups, bays)
        assert entry.description == dv.description
    # Initial values mirror the vehicle fields the registry names.
    assert dvs["wing_area"].initial == (VEHICLE.wing.area,)
    pairs = [VEHICLE.lift_rotors[i] for i, _ in VEHICLE.lift_rotor_pairs]
    twist = np.array([r.twist_cp for r in (*pairs, VEHICLE.pusher)])
    np.testing.assert_array_equal(dvs["blade_twist_cp"].initial_array.reshape(groups, 4), twist)
    assert dvs["blade_twist_cp"].initial_from == (
        "lift_rotors[i].twist_cp_deg (one rotor per pair) and pusher.twist_cp_deg"
    )


def test_the_registry_drives_the_schema():
    # A registry entry changed in code changes what the vehicle file is checked against.
    parts = {
        name: getattr(VEHICLE, name)
        for name in (
            "wing",
            "horizontal_tail",
            "vertical_tail",
            "fuselage",
            "battery",
            "masses",
            "material",
            "wing_box",
            "lift_rotors",
            "pusher",
            "conditions",
            "mission",
        )
    }
    specs = _design_variable_specs(parts)
    gauge = [dv.name for dv in VEHICLE_DESIGN_VARIABLES if dv.min_gauge]
    assert gauge == [
        f"{p}_thickness" for p in ("front_spar", "rear_spar", "top_skin", "bottom_skin")
    ]
    for name in gauge:
        assert specs[name].lower_min == (VEHICLE.material.min_gauge, "material.min_gauge")
        assert specs[name].upper_max[0] == 0.1, name  # a table in mm fails
    fuselage = specs["fuselage_length"]  # the cabin and the M4 data range (theory/geometry)
    assert fuselage.lower_min == (6.4008, "the lower end of the M4 regressions' data range")
    assert fuselage.upper_max == (11.8872, "the upper end of the M4 regressions' data range")
    # Bounds within the range of the field that gives the initial value (parts.Rotor.radius,
    # LiftingSurface.area), or the design variable's own limits.
    assert specs["rotor_radius"].lower_min[0] == 0.1
    assert specs["rotor_radius"].upper_max[0] == 10.0
    assert specs["wing_area"].upper_max[0] == 200.0
    assert specs["motor_length"].lower_min[0] == 0.01
    assert specs["motor_rated_current"].upper_max[0] == 5000.0
    assert specs["blade_twist_cp"].lower_min is None  # angles: the degree check
    # Rotor speeds are checked at the tip speed of the largest radius they turn.
    assert specs["hover_lift_rpm"].tip_radius == max(r.radius for r in VEHICLE.lift_rotors)
    assert specs["cruise_pusher_rpm"].tip_radius == VEHICLE.pusher.radius
    assert specs["transition_roll_yaw_rpm"].tip_radius is None


def test_vehicle_group_inputs_are_the_registry():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vehicle", VehicleGroup(vehicle=VEHICLE), promotes=["*"])
    prob.setup()
    prob.final_setup()
    inputs = prob.model.get_io_metadata(iotypes="input", metadata_keys=["units"], get_remote=True)
    promoted = {meta["prom_name"]: meta["units"] for meta in inputs.values()}
    for dv in VEHICLE_DESIGN_VARIABLES:
        assert dv.name in promoted, dv.name
        assert promoted[dv.name] == (None if dv.units == "unitless" else dv.units), dv.name
        np.testing.assert_allclose(
            prob.get_val(dv.name).ravel(), VEHICLE.design_variables[dv.name].initial_array.ravel()
        )


def test_baseline_set_is_the_registrys_sizing_variables():
    assert BASELINE_SET == tuple(dv.name for dv in VEHICLE_DESIGN_VARIABLES if dv.baseline)
    # every vehicle-level variable is a sizing variable but W_dg, closed on the gross mass
    assert set(BASELINE_SET) == set(NAMES) - {"design_gross_mass"}
    prob = om.Problem(BaselineModel(vehicle=VEHICLE), reports=False)
    prob.setup()
    assert list(prob.model.baseline.options["references"]) == list(BASELINE_SET)


def test_a_bad_shape_rule_is_refused():
    with pytest.raises(ValueError, match="'shape' = 'blades' is not allowed"):
        VehicleDesignVariable("x", "m", "blades", "x")
    assert dataclasses.is_dataclass(VEHICLE_DESIGN_VARIABLES[0])


def test_a_file_without_the_design_gross_mass_table_reads_its_default():
    # Files written before the optimizer closed W_dg have no such table: it is read as
    # DEFAULT_TABLES gives it (kg, ref 1000 kg, bounds 0.7-1.3 x masses.design_gross_mass),
    # which is what the reference file writes out.
    from lpc_mdo.vehicle import read_vehicle_file, vehicle_from_dict

    data = read_vehicle_file()
    del data["design_variables"]["design_gross_mass"]
    read = vehicle_from_dict(data).design_variables["design_gross_mass"]
    w_dg = reference_vehicle().masses.design_gross_mass
    assert read == reference_vehicle().design_variables["design_gross_mass"]
    assert read.initial == (w_dg,)
    assert read.lower == pytest.approx((0.7 * w_dg,)) and read.upper == pytest.approx((1.3 * w_dg,))
