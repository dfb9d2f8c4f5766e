"""Tests for lpc_mdo.components.rotor.hub_loads (disk frames, rotor velocity, hub loads)."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.rotor.hub_loads import HubLoadsComp, RotorVelocityComp, rotor_frames
from lpc_mdo.vehicle import reference_vehicle

TILTED = np.array([[0.0, 0.0, -1.0], [1.0, 0.0, 0.0], [0.3, -0.2, -0.9]])


def _problem(comp, **values):
    prob = om.Problem()
    prob.model.add_subsystem("comp", comp, promotes=["*"])
    prob.setup(force_alloc_complex=True)
    for name, value in values.items():
        prob.set_val(name, value)
    prob.run_model()
    return prob


def test_frames():
    frames = rotor_frames(TILTED)
    # Reference docs theory/rotors 'Stations and disk frame': lift rotor n = (0, 0, -1) -> e_x
    # forward, e_y right; pusher n = (1, 0, 0) -> e_x = n x e_y = down (hand-derived, exact).
    np.testing.assert_allclose(frames[0], [[1, 0, 0], [0, 1, 0], [0, 0, -1]], atol=1e-15)
    np.testing.assert_allclose(frames[1], [[0, 0, 1], [0, 1, 0], [1, 0, 0]], atol=1e-15)
    for f in frames:  # orthonormal; (e_x, e_y, -n) right-handed
        np.testing.assert_allclose(f @ f.T, np.eye(3), atol=1e-14)
        np.testing.assert_allclose(np.cross(f[0], f[1]), -f[2], atol=1e-14)
    with pytest.raises(ValueError, match=r"rows \[0\] = \[\[0.0, 2.0, 0.0\]\] lie along the body"):
        rotor_frames([[0.0, 2.0, 0.0]])
    with pytest.raises(ValueError, match="finite, non-zero"):
        rotor_frames([[0.0, 0.0, 0.0]])


def test_rotor_velocity():
    velocity = np.array([[60.0, 1.0, -3.0], [0.0, 0.0, 2.0]])
    prob = _problem(
        RotorVelocityComp(num_rotors=3, num_nodes=2, thrust_axis=TILTED), velocity=velocity
    )
    ax, ip = prob.get_val("axial_velocity"), prob.get_val("inplane_velocity")
    # Hand-derived: lift rotor V_x = -w (climb positive), in-plane (u, v); pusher V_x = u,
    # in-plane (w, v).
    np.testing.assert_allclose(ax[0], [3.0, -2.0], atol=1e-13)
    np.testing.assert_allclose(ip[0], [[60.0, 1.0], [0.0, 0.0]], atol=1e-13)
    np.testing.assert_allclose(ax[1], [60.0, 0.0], atol=1e-13)
    np.testing.assert_allclose(ip[1], [[-3.0, 1.0], [2.0, 0.0]], atol=1e-13)
    # The tilted rotor keeps the speed: |V|^2 = V_x^2 + |V_ip|^2.
    np.testing.assert_allclose(
        ax[2] ** 2 + np.sum(ip[2] ** 2, axis=-1), np.sum(velocity**2, axis=-1), rtol=1e-13
    )
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)


@pytest.mark.parametrize("inplane", [False, True])
def test_hub_loads_partials(inplane):
    rng = np.random.default_rng(3)
    values = dict(
        thrust=rng.uniform(500, 5000, (3, 2)),
        torque=rng.uniform(50, 800, (3, 2)),
        hub_position=rng.normal(size=(3, 3)),
        reference_point=[-3.0, 0.1, 0.2],
    )
    if inplane:
        values.update(
            inplane_force=rng.normal(size=(3, 2, 2)) * 100,
            hub_moment=rng.normal(size=(3, 2, 2)) * 100,
        )
    prob = _problem(
        HubLoadsComp(
            num_rotors=3,
            num_nodes=2,
            thrust_axis=TILTED,
            spin_direction=[1, -1, 1],
            inplane_loads=inplane,
        ),
        **values,
    )
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_hub_loads_single_rotor():
    # Lift rotor at p = (x, y, z), spin +1 (counter-clockwise from above): F = (0, 0, -T) and,
    # about the origin, M = p x F + Q (0, 0, 1) = (-y T, x T, Q); hand-derived, exact.
    x, y, z, t, q = -0.8, -5.7, -0.7, 4000.0, 700.0
    prob = _problem(HubLoadsComp(), thrust=t, torque=q, hub_position=[[x, y, z]])
    np.testing.assert_allclose(prob.get_val("force")[0, 0], [0.0, 0.0, -t], atol=1e-12)
    np.testing.assert_allclose(prob.get_val("moment")[0, 0], [-y * t, x * t, q], rtol=1e-14)
    # Edgewise in-plane loads along e_x = forward, e_y = right of a lift rotor.
    prob = _problem(
        HubLoadsComp(inplane_loads=True),
        thrust=t,
        torque=q,
        hub_position=[[0.0, 0.0, 0.0]],
        inplane_force=[[[-50.0, 20.0]]],
        hub_moment=[[[30.0, -40.0]]],
        reference_point=[0.0, 0.0, 1.0],
    )
    np.testing.assert_allclose(prob.get_val("force")[0, 0], [-50.0, 20.0, -t], atol=1e-12)
    arm = np.array([0.0, 0.0, -1.0])
    expected = np.cross(arm, [-50.0, 20.0, -t]) + [30.0, -40.0, q]
    np.testing.assert_allclose(prob.get_val("moment")[0, 0], expected, rtol=1e-14)


def test_reference_vehicle_hover_balance():
    # Eight lift rotors of the reference vehicle at equal thrust and torque (hover): the pairs
    # spin opposite and are mirror images, so yaw and roll cancel; force -8T along z and pitching
    # moment T sum(x_i) about the nose (hand-derived, 1e-9 relative).
    rotors = reference_vehicle().lift_rotors
    hubs = np.array([r.hub_position for r in rotors])
    t, q = 4400.0, 730.0
    prob = _problem(
        HubLoadsComp(
            num_rotors=8,
            thrust_axis=[r.thrust_axis for r in rotors],
            spin_direction=[r.spin_direction for r in rotors],
        ),
        thrust=np.full((8, 1), t),
        torque=np.full((8, 1), q),
        hub_position=hubs,
    )
    np.testing.assert_allclose(prob.get_val("total_force")[0], [0.0, 0.0, -8 * t], atol=1e-9)
    np.testing.assert_allclose(
        prob.get_val("total_moment")[0], [0.0, t * hubs[:, 0].sum(), 0.0], atol=1e-8
    )


def test_bad_options():
    for options, message in (
        ({"spin_direction": 0}, "'spin_direction\\[0\\]' = 0 is not allowed: must be one of 1, -1"),
        (
            {"spin_direction": 2},
            "'spin_direction\\[0\\]' = 2 is out of range: must be in \\[-1, 1\\]",
        ),
        ({"thrust_axis": [[0.0, 0.0]]}, "thrust_axis' has shape"),
    ):
        prob = om.Problem()
        prob.model.add_subsystem("h", HubLoadsComp(**options))
        with pytest.raises(ValueError, match=message):
            prob.setup()
