"""Each design-condition group alone (with the vehicle group), trimmed by its own variables."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.components.aero.polar import LinearQuadraticPolar
from lpc_mdo.components.dynamics.eom import GRAVITY
from lpc_mdo.drivers import IpoptDriver
from lpc_mdo.groups.lpc import LPCGroup

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration


def condition_problem(name, design_vars=(), constraints=(), objective=None):
    prob = om.Problem(reports=False)
    prob.model = LPCGroup(
        conditions=[name], rotor_polar=LinearQuadraticPolar(), wing_zero_lift_angle=-0.07
    )
    for dv, kw in design_vars:
        prob.model.add_design_var(dv, **kw)
    for con, kw in constraints:
        prob.model.add_constraint(con, **kw)
    if objective:
        prob.model.add_objective(objective[0], **objective[1])
    prob.driver = IpoptDriver(print_level=0, tol=1e-8)
    prob.setup()
    return prob


@pytest.mark.requires_ipopt
def test_hover_trim_is_reachable_by_rpm_alone():
    prob = condition_problem(
        "hover",
        design_vars=[("hover_lift_rpm", dict(lower=500.0, upper=2500.0, ref=1e3))],
        constraints=[
            ("hover.linear_acceleration", dict(indices=[2], flat_indices=True, equals=0.0)),
            ("hover.angular_acceleration", dict(indices=[0, 1], flat_indices=True, equals=0.0)),
        ],
        objective=("hover.electrical_power", dict(ref=1e5)),
    )
    result = prob.run_driver()
    assert result.success, result.exit_status
    weight = prob.get_val("gross_mass")[0] * GRAVITY
    # Closed form: thrust axes vertical, so the rotor thrusts carry the weight exactly and
    # the other accelerations vanish.
    assert_near_equal(prob.get_val("hover.lift_thrust").sum(), weight, 1e-6)
    np.testing.assert_allclose(prob.get_val("hover.linear_acceleration"), 0.0, atol=1e-6)
    np.testing.assert_allclose(prob.get_val("hover.angular_acceleration")[0, :2], 0.0, atol=1e-6)


@pytest.mark.requires_ipopt
def test_cruise_trim_by_pitch_elevator_and_pusher_speed():
    prob = condition_problem(
        "cruise",
        design_vars=[
            ("cruise_pitch", dict(lower=-0.2, upper=0.2, ref=0.1)),
            ("cruise_elevator", dict(lower=-0.3, upper=0.3, ref=0.1)),
            ("cruise_pusher_rpm", dict(lower=300.0, upper=3000.0, ref=1e3)),
        ],
        constraints=[
            ("cruise.linear_acceleration", dict(indices=[0, 2], flat_indices=True, equals=0.0)),
            ("cruise.angular_acceleration", dict(indices=[1], flat_indices=True, equals=0.0)),
        ],
        objective=("cruise.electrical_power", dict(ref=1e5)),
    )
    result = prob.run_driver()
    assert result.success, result.exit_status
    weight = prob.get_val("gross_mass")[0] * GRAVITY
    # Level flight: the wing and tail carry the weight, less the pusher's small vertical
    # component at the trim pitch (a few degrees), so lift = W within 2 %.
    assert_near_equal(prob.get_val("cruise.lift"), weight, 0.02)
    # ... and the pusher thrust balances the total drag (build-up, induced and the wing's
    # lift-dependent profile drag) within 5 %.
    drag = (
        prob.get_val("cruise.parasite_drag")
        + prob.get_val("cruise.induced_drag")
        + prob.get_val("cruise.vlm.profile_drag")
    )
    assert_near_equal(prob.get_val("cruise.pusher_thrust").ravel(), drag, 0.05)
    assert -0.1 < prob.get_val("cruise.static_margin")[0] < 1.5


@pytest.mark.requires_ipopt
def test_plus_3g_trim_by_pitch_alone():
    prob = condition_problem(
        "plus_3g",
        design_vars=[("plus_3g_pitch", dict(lower=-0.2, upper=0.4, ref=0.1))],
        constraints=[
            ("plus_3g.linear_acceleration", dict(indices=[2], flat_indices=True, equals=0.0))
        ],
        objective=("gross_mass", dict(ref=1e3)),
    )
    result = prob.run_driver()
    assert result.success, result.exit_status
    weight = prob.get_val("gross_mass")[0] * GRAVITY
    theta = prob.get_val("plus_3g_pitch")[0]
    # z-force balance at n = 3: aerodynamic z-force = -3 W cos(theta) (drag adds little).
    fz = prob.get_val("plus_3g.force")[0, 2]
    assert_near_equal(fz, -3.0 * weight * np.cos(theta), 1e-6)
    assert_near_equal(-prob.get_val("plus_3g.aero_force")[0, 2], 3.0 * weight * np.cos(theta), 0.02)
    ratios = prob.get_val("plus_3g.top_skin_buckling_ratio")
    # The vehicle file's gauges are sized at +3g (run_scripts/close_initial_design.py): every
    # constrained bay (all but the tip bay) is at one buckling ratio <= 1 (fully stressed; 0.969
    # measured with the sizing's own pitch), the unconstrained tip bay at minimum gauge is not.
    assert np.all(np.isfinite(ratios))
    assert np.all(ratios[:-1] <= 1.0) and np.ptp(ratios[:-1]) < 0.01


def test_transition_point_runs_alone_and_obeys_newton():
    prob = om.Problem(reports=False)
    prob.model = LPCGroup(
        conditions=["transition_2"], rotor_polar=LinearQuadraticPolar(), wing_zero_lift_angle=-0.07
    )
    prob.setup()
    prob.run_model()
    c = "transition_2"
    mass = prob.get_val("gross_mass")[0]
    theta = prob.get_val(f"{c}.pitch")[0]
    force = (
        prob.get_val(f"{c}.aero_force")
        + prob.get_val(f"{c}.drag_force")
        + prob.get_val(f"{c}.lift_force")
        + prob.get_val(f"{c}.pusher_force")
    )[0]
    gravity = GRAVITY * np.array([-np.sin(theta), 0.0, np.cos(theta)])
    velocity = prob.get_val(f"{c}.velocity")[0]
    # Closed form with zero body rates: a = F/m + g (resolved in body axes).
    assert_near_equal(prob.get_val(f"{c}.body_acceleration")[0], force / mass + gravity, 1e-10)
    assert velocity[0] > 40.0  # prescribed speed of the point (~46.6 m/s)
    assert prob.get_val(f"{c}.electrical_power")[0] > 0.0
    assert np.all(prob.get_val(f"{c}.lift_thrust") > 0.0)


def test_unknown_condition_is_named():
    prob = om.Problem(reports=False)
    prob.model = LPCGroup(
        conditions=["landing"], rotor_polar=LinearQuadraticPolar(), wing_zero_lift_angle=-0.07
    )
    with pytest.raises(ValueError, match=r"conditions = \['landing'\]; each must be one of"):
        prob.setup()


@pytest.mark.parametrize(
    "name",
    [
        "hover",
        "transition_1",
        "transition_5",
        "climb",
        "cruise",
        "descent",
        "oei_1",
        "oei_4",
        "plus_3g",
        "minus_1g",
    ],
)
def test_each_condition_runs_alone(name):
    prob = om.Problem(reports=False)
    prob.model = LPCGroup(
        conditions=[name], rotor_polar=LinearQuadraticPolar(), wing_zero_lift_angle=-0.07
    )
    prob.setup()
    prob.run_model()
    assert np.all(np.isfinite(prob.get_val(f"{name}.linear_acceleration")))
    assert np.all(np.isfinite(prob.get_val(f"{name}.angular_acceleration")))
    if name.startswith("oei"):
        # One lift rotor is out: seven thrusts, each positive.
        assert prob.get_val(f"{name}.lift_thrust").shape == (7, 1)
