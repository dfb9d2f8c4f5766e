"""VLMGroup: total derivatives, solver configuration and the LPC wing + tail lattice."""

import math

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils import logger_utils
from openmdao.utils.assert_utils import assert_check_totals, assert_near_equal

from lpc_mdo.components.geometry.planform import PlanformMeshComp, planform_values
from lpc_mdo.groups.vlm import VLMGroup, VLMSurface, lpc_vlm_surfaces
from lpc_mdo.vehicle import reference_vehicle


def _mesh(num_span_panels, values, num_chord_panels=1):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "p",
        PlanformMeshComp(num_span_panels=num_span_panels, num_chord_panels=num_chord_panels),
        promotes=["*"],
    )
    prob.setup()
    for name, value in values.items():
        prob.set_val(name, value)
    prob.run_model()
    return prob.get_val("mesh")


def small_problem(mode):
    surfaces = (VLMSurface("wing", 1, 6), VLMSurface("tail", 1, 2, deflectable=True))
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vlm", VLMGroup(surfaces=surfaces, num_nodes=2), promotes=["*"])
    prob.setup(force_alloc_complex=True, mode=mode)
    prob.set_val(
        "wing_mesh",
        _mesh(
            6, {"span": 8.0, "root_chord": 1.2, "tip_chord": 0.6, "sweep": 0.1, "dihedral": 0.05}
        ),
    )
    prob.set_val(
        "tail_mesh",
        _mesh(
            2,
            {
                "span": 3.0,
                "root_chord": 0.6,
                "tip_chord": 0.3,
                "root_leading_edge": [-4.0, 0.0, -0.5],
            },
        ),
    )
    prob.set_val("speed", [50.0, 30.0])
    prob.set_val("angle_of_attack", [0.05, 0.1])
    prob.set_val("sideslip_angle", [0.02, 0.0])
    prob.set_val("angular_velocity", [[0.0, 0.05, 0.0], [0.02, 0.0, 0.0]])
    prob.set_val("reference_area", 8.0)
    prob.set_val("reference_point", [-0.5, 0.0, 0.0])
    prob.set_val("wing_zero_lift_angle", -0.04)
    prob.set_val("wing_sectional_cd", 0.01)
    prob.set_val("tail_deflection", [0.02, -0.05])
    prob.run_model()
    return prob


@pytest.mark.parametrize("mode", ["fwd", "rev"])
def test_totals_wrt_mesh_alpha_speed(mode):
    prob = small_problem(mode)
    of = [
        "CL",
        "CDi",
        "CD",
        "moment",
        "force",
        "side_force",
        "wing_sectional_cl",
        "trefftz_induced_drag",
    ]
    wrt = [
        "wing_mesh",
        "tail_mesh",
        "angle_of_attack",
        "sideslip_angle",
        "speed",
        "tail_deflection",
        "wing_zero_lift_angle",
        "angular_velocity",
    ]
    data = prob.check_totals(of=of, wrt=wrt, method="cs", out_stream=None)
    # The circulation component solves its own linear system (LU); CS agrees to round-off.
    assert_check_totals(data, atol=1e-8, rtol=1e-7)


def test_solver_configuration_is_clean():
    prob = small_problem("rev")
    logger = logger_utils.TestLogger()
    prob.check_config(logger=logger, checks=["solvers"])
    assert not logger.get("warning") and not logger.get("error")
    assert isinstance(prob.model.vlm.linear_solver, om.LinearRunOnce)


def lpc_problem():
    """Paper mesh (wing 26 x 1, h-tail 8 x 1) on the reference vehicle, cruise conditions."""
    vehicle = reference_vehicle()
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vlm", VLMGroup(surfaces=lpc_vlm_surfaces()), promotes=["*"])
    prob.setup()
    prob.set_val("wing_mesh", _mesh(26, planform_values(vehicle.wing)))
    prob.set_val("horizontal_tail_mesh", _mesh(8, planform_values(vehicle.horizontal_tail)))
    prob.set_val("speed", 57.19)
    prob.set_val("density", 1.11177)
    prob.set_val("reference_area", vehicle.wing.area)
    prob.set_val("reference_point", [-2.37, 0.0, 0.0])  # wing root quarter chord (x)
    prob.set_val("angle_of_attack", math.radians(2.0))
    prob.run_model()
    return prob


def test_lpc_wing_and_tail():
    prob = lpc_problem()
    cl = prob.get_val("CL")[0]
    # Wing at 2 deg + 2.04 deg incidence: CL ~ a (4.04 deg) with a ~ 5.3 /rad for AR 12.1.
    assert 0.3 < cl < 0.45
    tail_cl = prob.get_val("horizontal_tail_sectional_cl")[0].mean()
    # Elevator: a trailing-edge-down deflection adds tail lift and a nose-down moment.
    prob.set_val("horizontal_tail_deflection", math.radians(2.0))
    prob.run_model()
    assert prob.get_val("horizontal_tail_sectional_cl")[0].mean() > tail_cl
    assert prob.get_val("CL")[0] > cl
    deflected_moment = prob.get_val("moment")[0, 1]
    prob.set_val("horizontal_tail_deflection", 0.0)
    prob.run_model()
    assert deflected_moment < prob.get_val("moment")[0, 1]
    # Mutual influence: the wing's downwash lowers the tail's lift (tail alone at the same
    # angle of attack lifts more).
    alone = om.Problem(reports=False)
    alone.model.add_subsystem("vlm", VLMGroup(surfaces=(lpc_vlm_surfaces()[1],)), promotes=["*"])
    alone.setup()
    alone.set_val("horizontal_tail_mesh", prob.get_val("horizontal_tail_mesh"))
    alone.set_val("speed", 57.19)
    alone.set_val("angle_of_attack", math.radians(2.0))
    alone.run_model()
    assert alone.get_val("horizontal_tail_sectional_cl")[0].mean() > tail_cl + 0.05


def test_deflection_matches_tail_incidence():
    # The all-moving tail deflection tilts the boundary normals (AVL treatment); rotating the
    # tail mesh by the same angle gives the same tail lift (0.16% apart at 3 deg; test 0.5%).
    vehicle = reference_vehicle()
    surfaces = (VLMSurface("horizontal_tail", 1, 8, deflectable=True),)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vlm", VLMGroup(surfaces=surfaces), promotes=["*"])
    prob.setup()
    values = planform_values(vehicle.horizontal_tail)
    prob.set_val("horizontal_tail_mesh", _mesh(8, values))
    prob.set_val("speed", 50.0)
    prob.set_val("reference_area", vehicle.horizontal_tail.area)
    prob.set_val("horizontal_tail_deflection", math.radians(3.0))
    prob.run_model()
    deflected = prob.get_val("CL")[0]
    values["incidence"] = math.radians(3.0)
    prob.set_val("horizontal_tail_mesh", _mesh(8, values))
    prob.set_val("horizontal_tail_deflection", 0.0)
    prob.run_model()
    assert_near_equal(deflected, prob.get_val("CL")[0], 5e-3)
    assert np.all(np.isfinite(prob.get_val("circulation")))
