"""Hover control reserve (docs theory/dynamics 'Hover control reserve')."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.dynamics.control_reserve import ControlReserveComp
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.condition_kinds import HoverKind

# A symmetric quad: arms a along x and y, diagonal rotors spin alike (every pair of rotors on
# one side holds one rotor of each sense), so thrust, roll, pitch and yaw are independent.
ARM, THRUST, TORQUE = 2.0, 4000.0, 500.0
HUBS = np.array([[ARM, ARM, -1.0], [-ARM, -ARM, -1.0], [ARM, -ARM, -1.0], [-ARM, ARM, -1.0]])
SPIN = [1, 1, -1, -1]
INERTIA = np.diag([8000.0, 9000.0, 15000.0])


def _quad(margin, rho=50.0, scale=(1.0, 1.0, 1.0)):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "reserve",
        ControlReserveComp(spin_direction=SPIN, ks_rho=rho, acceleration_scale=scale),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("thrust", np.full((4, 1), THRUST))
    prob.set_val("torque", np.full((4, 1), TORQUE))
    prob.set_val("torque_margin", np.full((4, 1), margin))
    prob.set_val("hub_position", HUBS)
    prob.set_val("inertia", INERTIA)
    prob.run_model()
    return prob


def _closed_form(margin):
    """
    Return the quad's available accelerations by hand.

    Roll: the moment L = Ixx p_dot is shared equally, dT = L/(4 a) on each rotor (up on one
    side, down on the other); the thrust can rise by m T (the motor's torque margin, constant
    T/Q along the speed line) and fall by T, so p_dot = 4 a T min(m, 1)/Ixx; pitch likewise
    with Iyy. Yaw: N = Izz r_dot from torque changes dQ = N/4 on each rotor, dT = (T/Q) dQ,
    so r_dot = 4 Q min(m, 1)/Izz.
    """
    use = min(margin, 1.0)
    return np.array(
        [
            4 * ARM * THRUST * use / INERTIA[0, 0],
            4 * ARM * THRUST * use / INERTIA[1, 1],
            4 * TORQUE * use / INERTIA[2, 2],
        ]
    )


@pytest.mark.parametrize("margin", [0.3, 1.4])
def test_symmetric_quad_closed_form(margin):
    # Tight KS (rho 1e5): within 4 rotors x ln(4)/rho of the exact minimum.
    exact = _closed_form(margin)
    assert_near_equal(_quad(margin, rho=1e5).get_val("control_acceleration"), exact, 1e-4)


def test_ks_bound_of_the_quad():
    # With rho = 50 on ratios scaled by s, every axis has the 4 rotors tied at the minimum and
    # the other headroom far above: KS = min - ln(4)/rho times s (tolerance: round-off).
    scale = np.array([0.5, 0.5, 0.05])
    exact = _closed_form(0.3)
    value = _quad(0.3, rho=50.0, scale=tuple(scale)).get_val("control_acceleration")
    assert_near_equal(value, exact - np.log(4.0) / 50.0 * scale, 1e-9)


def test_partials_of_an_asymmetric_layout():
    # Seven rotors, an offset cg and a product of inertia (an OEI-like case).
    rng = np.random.default_rng(3)
    n = 7
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "reserve",
        ControlReserveComp(
            spin_direction=[1, -1, 1, -1, 1, -1, 1], acceleration_scale=(0.14, 0.1, 0.05)
        ),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("thrust", 3000.0 + 1500.0 * rng.random((n, 1)))
    prob.set_val("torque", 400.0 + 200.0 * rng.random((n, 1)))
    prob.set_val("torque_margin", 0.05 + 0.4 * rng.random((n, 1)))
    prob.set_val("hub_position", 3.0 * rng.normal(size=(n, 3)))
    prob.set_val("cg", [-2.9, 0.05, -0.1])
    prob.set_val("inertia", [[9700.0, 0.0, -1230.0], [0.0, 10950.0, 0.0], [-1230.0, 0.0, 17760.0]])
    prob.run_model()
    assert np.all(prob.get_val("control_acceleration") > 0.0)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-9, rtol=1e-8)


def test_no_thrust_is_an_analysis_error():
    prob = _quad(0.3)
    prob.set_val("thrust", [[THRUST], [THRUST], [0.0], [THRUST]])
    with pytest.raises(om.AnalysisError, match="thrust"):
        prob.run_model()


def test_hover_and_oei_declare_the_reserve():
    vehicle = reference_vehicle()
    required = vehicle.constraints.min_control_acceleration
    for name in ("hover", "oei_1"):
        cons = {c.kind: c for c in HoverKind.constraints(vehicle, vehicle.condition(name), None)}
        reserve = cons["control_reserve"]
        assert reserve.output == "control_acceleration"
        # Roll and pitch required (MIL-F-83300 Level 1), yaw not (the reference's 0).
        assert reserve.options["indices"] == [0, 1]
        assert_near_equal(reserve.options["lower"], required[:2], 1e-15)
