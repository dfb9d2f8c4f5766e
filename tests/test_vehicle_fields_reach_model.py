"""Vehicle-file fields that must reach the OpenMDAO model, not stay at component defaults.

The audited fields' component defaults equal the reference vehicle's values, so a run of the
reference vehicle cannot show whether they are wired; these tests change them
(dataclasses.replace on the reference vehicle) and check the model's inputs and the outputs
that depend on them. The wing fields audited here (taper, sweep, dihedral, incidence, root
leading edge) are those of the "trapezoid" planform, so the wing tests start from the reference
vehicle with its taper-0.2 trapezoid; the cranked planform's sections are audited in
tests/test_cranked_wing_vehicle.py (a section chord reaches the wing box and its mass).
"""

import dataclasses

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.components.motor.sizing import MotorSizingComp
from lpc_mdo.components.structures.wing_box_geometry import wing_box_section
from lpc_mdo.groups.motor import MotorGroup
from lpc_mdo.groups.vehicle import VehicleGroup, motor_loadings, motor_parameters
from lpc_mdo.groups.weights import placeholder_calibration_inputs
from lpc_mdo.vehicle import reference_vehicle

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration

REFERENCE = reference_vehicle()
REFERENCE = dataclasses.replace(
    REFERENCE,
    wing=dataclasses.replace(REFERENCE.wing, planform="trapezoid", sections=None, taper_ratio=0.2),
)


def _wing(**fields):
    return dataclasses.replace(REFERENCE, wing=dataclasses.replace(REFERENCE.wing, **fields))


def _motor(**fields):
    return dataclasses.replace(REFERENCE, motor=dataclasses.replace(REFERENCE.motor, **fields))


# [wing]: taper 0.2 -> 0.3, sweep 7.81 -> 12 deg, dihedral -2 -> 1 deg, incidence 2.04 -> 3 deg,
# root leading edge moved 0.15 m aft and 0.07 m up.
WING = _wing(
    taper_ratio=0.3,
    sweep=np.radians(12.0),
    dihedral=np.radians(1.0),
    incidence=np.radians(3.0),
    root_leading_edge=(-2.1, 0.0, -1.0),
)
# [motor]: electric loading 30e3 -> 40e3 A/m, magnetic loading 0.85 -> 0.95 T.
MOTOR = _motor(electric_loading=40.0e3, magnetic_loading=0.95)


def _vehicle_problem(vehicle):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vehicle", VehicleGroup(vehicle=vehicle), promotes=["*"])
    prob.setup()
    prob.run_model()
    return prob


@pytest.fixture(scope="module")
def reference():
    return _vehicle_problem(REFERENCE)


def test_wing_planform_reaches_the_wing_box(reference):
    prob = _vehicle_problem(WING)
    wing = WING.wing
    # The wing box's inputs are the vehicle's [wing] values (they once stayed at the reference
    # vehicle's, the component's defaults).
    for name, value in (
        ("taper_ratio", wing.taper_ratio),
        ("sweep", wing.sweep),
        ("dihedral", wing.dihedral),
        ("incidence", wing.incidence),
        ("root_leading_edge", wing.root_leading_edge),
    ):
        assert_near_equal(prob.get_val(f"vehicle.wing_box.wing_{name}"), value, 1e-15)

    # Beam nodes by the planform of WingBoxGeometryComp's docstring
    # (docs theory/geometry 'Reference vehicle',
    # docs theory/structures 'Material, mesh and load transfer') evaluated with the vehicle's own
    # LiftingSurface properties: chord c(eta) linear from c_root to c_tip, leading edge
    # x0 - y tan(sweep), z0 - y tan(dihedral), node at the beam axis and the camber line of the
    # section, pitched by the incidence.
    sec = wing_box_section(WING)
    eta = np.linspace(0.0, 1.0, WING.wing_box.num_bays + 1)
    chord = wing.root_chord + (wing.tip_chord - wing.root_chord) * eta
    y = 0.5 * wing.span * eta
    i = wing.incidence
    x0, y0, z0 = wing.root_leading_edge
    expected = np.column_stack(
        [
            x0
            - y * np.tan(wing.sweep)
            - chord * (sec.beam_axis * np.cos(i) + sec.camber * np.sin(i)),
            y0 + y,
            z0
            - y * np.tan(wing.dihedral)
            + chord * (sec.beam_axis * np.sin(i) - sec.camber * np.cos(i)),
        ]
    )
    assert_near_equal(prob.get_val("wing_box_nodes", units="m"), expected, 1e-12)

    # The wing box and the VLM wing mesh describe the same wing: at the tip the box node is the
    # mesh's chord point at the beam-axis fraction plus the camber offset along the section's
    # "up" (-sin i, 0, -cos i) (both components' docstrings; the mesh has no twist here).
    mesh = prob.get_val("wing_mesh", units="m")
    tip = int(np.argmax(mesh[0, :, 1]))
    le, te = mesh[0, tip], mesh[-1, tip]
    offset = sec.camber * wing.tip_chord * np.array([-np.sin(i), 0.0, -np.cos(i)])
    assert_near_equal(
        prob.get_val("wing_box_nodes", units="m")[-1],
        le + sec.beam_axis * (te - le) + offset,
        1e-12,
    )

    # Direction: a larger taper ratio at the same area moves chord outboard, so the root bay's
    # box is narrower and the tip bay's wider (box width = (xi_r - xi_f) x mean bay chord); more
    # sweep moves the tip node further aft of the root node (x forward).
    width, ref_width = prob.get_val("box_width"), reference.get_val("box_width")
    assert width[0] < ref_width[0] and width[-1] > ref_width[-1]
    nodes, ref_nodes = prob.get_val("wing_box_nodes"), reference.get_val("wing_box_nodes")
    assert nodes[-1, 0] - nodes[0, 0] < ref_nodes[-1, 0] - ref_nodes[0, 0]
    assert prob.get_val("half_wing_mass")[0] != pytest.approx(
        reference.get_val("half_wing_mass")[0], rel=1e-6
    )


def test_wing_sweep_alone_lengthens_the_beam(reference):
    # Sweep only (everything else as the reference): the section areas are unchanged and every
    # beam element is longer (the nodes also move aft), so the box mass (density x area x
    # element length, BeamMassComp) grows and its cg moves aft.
    prob = _vehicle_problem(_wing(sweep=np.radians(12.0)))
    assert_near_equal(prob.get_val("area"), reference.get_val("area"), 1e-14)
    assert prob.get_val("half_wing_mass")[0] > reference.get_val("half_wing_mass")[0]
    assert prob.get_val("half_wing_cg")[0] < reference.get_val("half_wing_cg")[0]


def test_motor_loadings_reach_the_vehicle_motor_sizing(reference):
    prob = _vehicle_problem(MOTOR)
    motor = MOTOR.motor
    assert_near_equal(
        prob.get_val("vehicle.motor_design.electric_loading", units="A/m"),
        np.full(5, motor.electric_loading),
        1e-15,
    )
    assert_near_equal(
        prob.get_val("vehicle.motor_design.magnetic_loading", units="T"),
        np.full(5, motor.magnetic_loading),
        1e-15,
    )
    # Paper eq. 23: m = (pi/2) A B D^2 L/Q_sp, so at the same lengths the masses scale with
    # A B: (40e3 x 0.95)/(30e3 x 0.85) = 1.4902.
    ratio = (40.0e3 * 0.95) / (30.0e3 * 0.85)
    assert_near_equal(
        prob.get_val("motor_group_mass", units="kg"),
        ratio * reference.get_val("motor_group_mass", units="kg"),
        1e-12,
    )
    # Same closed form evaluated independently from the vehicle's [motor] table
    # (groups/weights.py, placeholder_calibration_inputs), per motor.
    assert_near_equal(
        prob.get_val("motor_mass", units="kg"),
        placeholder_calibration_inputs(MOTOR)["motor_mass"],
        1e-12,
    )


def test_motor_group_loading_options():
    def run(**options):
        prob = om.Problem(reports=False)
        prob.model.add_subsystem("motor", MotorGroup(num_motors=2, **options), promotes=["*"])
        prob.setup()
        prob.set_val("length", [0.1, 0.15], units="m")
        prob.run_model()
        return prob

    default, loaded = run(), run(electric_loading=40.0e3, magnetic_loading=0.95)
    # Defaults unchanged (MotorSizingComp's 30e3 A/m and 0.85 T, the reference [motor] values).
    assert_near_equal(default.get_val("electric_loading"), [30.0e3, 30.0e3], 1e-15)
    assert_near_equal(default.get_val("magnetic_loading"), [0.85, 0.85], 1e-15)
    assert_near_equal(loaded.get_val("electric_loading", units="A/m"), [40.0e3, 40.0e3], 1e-15)
    assert_near_equal(loaded.get_val("magnetic_loading", units="T"), [0.95, 0.95], 1e-15)
    # Eq. 23: mass proportional to A B.
    assert_near_equal(
        loaded.get_val("mass"), (40.0e3 * 0.95) / (30.0e3 * 0.85) * default.get_val("mass"), 1e-12
    )

    with pytest.raises(
        ValueError,
        match=r"MotorGroup: 'electric_loading' = -1.0 is out of range: "
        r"must be > 0",
    ):
        MotorGroup(electric_loading=-1.0)
    with pytest.raises(ValueError, match=r"'magnetic_loading' = 0.0 is out of range: must be > 0"):
        MotorGroup(magnetic_loading=0.0)


def test_motor_designs_are_sized_once_and_read_by_every_condition():
    from lpc_mdo.components.motor.parameters import DESIGN_OUTPUTS
    from lpc_mdo.groups.lpc import LPCGroup

    # The vehicle group sizes one motor per rotor group with the vehicle's loadings; the
    # conditions (hover: lift motors, cruise: pusher) only run operating points and read the
    # rows of their rotor groups.
    prob = om.Problem(LPCGroup(vehicle=MOTOR, conditions=["hover", "cruise"]), reports=False)
    prob.setup()
    prob.run_model()
    sizing = list(prob.model.system_iter(recurse=True, typ=MotorSizingComp))
    assert [s.pathname for s in sizing] == ["vehicle.motor_design.sizing"]
    for name, value in (("electric_loading", 40.0e3), ("magnetic_loading", 0.95)):
        assert_near_equal(prob.get_val(f"vehicle.motor_design.{name}"), np.full(5, value), 1e-15)
    lift_rows = [r.pair for r in MOTOR.lift_rotors]
    for name in DESIGN_OUTPUTS:
        design = prob.get_val(f"motor_{name}")
        assert_near_equal(prob.get_val(f"hover.lift_motor_{name}"), design[lift_rows], 1e-15)
        assert_near_equal(
            prob.get_val(f"cruise.pusher_motor_{name}"), design[[MOTOR.pusher.pair]], 1e-15
        )
    # The same numbers as a stand-alone MotorGroup (design and operation in one group) of the
    # lift motors at hover's operating points.
    alone = om.Problem(reports=False)
    alone.model.add_subsystem(
        "motor",
        MotorGroup(
            num_motors=len(lift_rows),
            length_to_diameter=MOTOR.motor.length_to_diameter,
            parameters=motor_parameters(MOTOR),
            **motor_loadings(MOTOR),
        ),
        promotes=["*"],
    )
    alone.setup()
    alone.set_val("length", prob.get_val("hover.lift_motor_length", units="m"), units="m")
    alone.set_val(
        "rated_current", prob.get_val("motor_rated_current", units="A")[lift_rows], units="A"
    )
    alone.set_val("rotor_torque", prob.get_val("hover.lift_motors.rotor_torque", units="N*m"))
    alone.set_val("rotor_rpm", prob.get_val("hover.lift_motors.rotor_rpm", units="rpm"))
    alone.run_model()
    for name in ("input_power", "torque_margin", "voltage_margin", "current_margin"):
        assert_near_equal(prob.get_val(f"hover.lift_motor_{name}"), alone.get_val(name), 1e-12)
