"""PathAccelerationComp: body-axis acceleration in flight-path axes (transition trim rows)."""

import numpy as np
import openmdao.api as om
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.dynamics.path_acceleration import PathAccelerationComp
from lpc_mdo.core.constants import GRAVITY


def problem(nn):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("path", PathAccelerationComp(num_nodes=nn), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    return prob


def test_prescribed_transition_acceleration_is_along_the_path_for_every_pitch():
    # A horizontal acceleration a seen in body axes at pitch theta, z down: the earth x axis is
    # (cos theta, 0, sin theta) in the body (the transition's former body-axis targets), so in
    # path axes (gamma = 0) it is (a, 0, 0) whatever the pitch, to round-off.
    theta = np.radians([-8.0, -2.8, 0.0, 3.8, 6.2, 10.0])
    a = 1.8456
    prob = problem(theta.size)
    prob.set_val("pitch", theta)
    prob.set_val(
        "body_acceleration", np.column_stack([a * np.cos(theta), 0 * theta, a * np.sin(theta)])
    )
    prob.run_model()
    expected = np.column_stack([np.full(theta.size, a), 0 * theta, 0 * theta])
    assert_near_equal(prob.get_val("path_acceleration"), expected, 1e-12)


def test_gravity_in_path_axes():
    # Gravity alone, body axes g (-sin theta, 0, cos theta) (docs theory/dynamics 'Gravity'), in
    # the axes of a path climbing at gamma: (-g sin gamma, 0, g cos gamma), the along-path
    # deceleration of a climb (closed form), whatever the pitch; 1e-12.
    theta = np.radians([0.0, 5.0, 12.0])
    gamma = np.radians([0.0, 3.0, -4.0])
    prob = problem(3)
    prob.set_val("pitch", theta)
    prob.set_val("flight_path_angle", gamma)
    prob.set_val(
        "body_acceleration",
        GRAVITY * np.column_stack([-np.sin(theta), 0 * theta, np.cos(theta)]),
    )
    prob.run_model()
    expected = GRAVITY * np.column_stack([-np.sin(gamma), 0 * gamma, np.cos(gamma)])
    assert_near_equal(prob.get_val("path_acceleration"), expected, 1e-12)


def test_lateral_row_is_v_dot_and_partials():
    rng = np.random.default_rng(3)
    prob = problem(4)
    prob.set_val("body_acceleration", rng.normal(size=(4, 3)))
    prob.set_val("pitch", rng.uniform(-0.3, 0.3, 4))
    prob.set_val("flight_path_angle", rng.uniform(-0.1, 0.1, 4))
    prob.run_model()
    assert_near_equal(
        prob.get_val("path_acceleration")[:, 1], prob.get_val("body_acceleration")[:, 1], 1e-15
    )
    data = prob.check_partials(method="cs", out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)
