"""Load and displacement transfer (lpc_mdo.components.structures.load_transfer)."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.structures.load_transfer import (
    DisplacementTransferComp,
    LoadTransferComp,
    span_weights,
)

G = 9.81


def _setup(num_points=7, num_point_masses=2, seed=1, include_weight=True):
    rng = np.random.default_rng(seed)
    n = 5
    nodes = np.column_stack(
        [
            -0.1 * np.arange(n),
            np.linspace(0.0, 4.0, n) + 0.05 * rng.normal(size=n),
            0.02 * np.arange(n),
        ]
    )
    # Points inside the beam, one inboard of the root and one outboard of the tip.
    span = np.r_[-0.2, rng.uniform(0.0, 4.0, num_points - 2), 4.3]
    points = np.column_stack(
        [rng.uniform(-1, 0.5, num_points), span, 0.1 * rng.normal(size=num_points)]
    )
    forces = rng.normal(size=(num_points, 3)) * 100.0
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "loads",
        LoadTransferComp(
            num_nodes=n,
            num_points=num_points,
            num_point_masses=num_point_masses,
            include_weight=include_weight,
        ),
        promotes=["*"],
    )
    prob.model.add_subsystem(
        "motion", DisplacementTransferComp(num_nodes=n, num_points=num_points), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("nodes", nodes)
    prob.set_val("aero_points", points)
    prob.set_val("aero_forces", forces)
    if include_weight:
        prob.set_val("element_mass", [3.0, 2.0, 1.0, 0.5])
    if num_point_masses:
        prob.set_val("point_masses", [10.0, 20.0])
        prob.set_val("point_mass_locations", [[0.2, 1.1, 0.3], [-0.3, 2.9, -0.1]])
    if include_weight or num_point_masses:
        prob.set_val("load_factor", 3.0)
        prob.set_val("pitch", 0.1)
        prob.set_val("roll", 0.05)
    prob.set_val("displacements", rng.normal(size=(n, 3)) * 0.01)
    prob.set_val("rotations", rng.normal(size=(n, 3)) * 0.01)
    prob.run_model()
    return prob


def test_total_force_and_moment_are_conserved():
    # Statics: the nodal loads have the resultant force and moment (about the origin) of the
    # aerodynamic forces, the point masses and the lumped element masses (element mass at its
    # mid-point = half at each node), all at n g along the body gravity direction
    # (-sin θ, sin φ cos θ, cos φ cos θ) (docs theory/dynamics 'Gravity').
    # Round-off only: 1e-12 relative.
    prob = _setup()
    nodes, points = prob.get_val("nodes"), prob.get_val("aero_points")
    forces = prob.get_val("aero_forces")
    acc = 3.0 * G * np.array([-np.sin(0.1), np.sin(0.05) * np.cos(0.1), np.cos(0.05) * np.cos(0.1)])
    m_e = np.array([3.0, 2.0, 1.0, 0.5])
    pm_loc = np.array([[0.2, 1.1, 0.3], [-0.3, 2.9, -0.1]])
    pm_force = np.outer([10.0, 20.0], acc)
    mid = 0.5 * (nodes[:-1] + nodes[1:])
    total_force = forces.sum(0) + pm_force.sum(0) + m_e.sum() * acc
    total_moment = (
        np.cross(points, forces).sum(0)
        + np.cross(pm_loc, pm_force).sum(0)
        + np.cross(mid, np.outer(m_e, acc)).sum(0)
    )
    node_forces, node_moments = prob.get_val("node_forces"), prob.get_val("node_moments")
    assert_near_equal(node_forces.sum(0), total_force, 1e-12)
    assert_near_equal(
        np.cross(nodes, node_forces).sum(0) + node_moments.sum(0), total_moment, 1e-12
    )


def test_virtual_work_is_conserved():
    # The displacement transfer is the adjoint of the load transfer (aerodynamic forces only):
    # Σ F_q·d_q = Σ (F_j·u_j + M_j·θ_j) for any displacements and rotations (1e-12 relative).
    prob = _setup(num_point_masses=0, include_weight=False)
    work_aero = np.sum(prob.get_val("aero_forces") * prob.get_val("aero_displacements"))
    work_beam = np.sum(prob.get_val("node_forces") * prob.get_val("displacements")) + np.sum(
        prob.get_val("node_moments") * prob.get_val("rotations")
    )
    assert_near_equal(work_aero, work_beam, 1e-12)


def test_weights_closed_form():
    # Hat functions: a point 30 % of the way from node 1 to node 2 gets (0.7, 0.3); points
    # beyond the ends go to the end node; every column sums to 1.
    w, _, _ = span_weights(np.array([1.3, -0.5, 3.5, 2.0]), np.array([0.0, 1.0, 2.0, 3.0]))
    assert_near_equal(w[:, 0], [0.0, 0.7, 0.3, 0.0], 1e-15)
    assert_near_equal(w[:, 1], [1.0, 0.0, 0.0, 0.0], 1e-15)
    assert_near_equal(w[:, 2], [0.0, 0.0, 0.0, 1.0], 1e-15)
    assert_near_equal(w.sum(axis=0), np.ones(4), 1e-15)


def test_rigid_rotation_moves_points_rigidly():
    # Equal nodal rotation θ and translation u: every point moves by u + θ x (x_q - X_j),
    # which for a rigid motion is u_ref + θ x (x_q - X_ref) independent of the weights.
    prob = _setup(num_point_masses=0)
    nodes, points = prob.get_val("nodes"), prob.get_val("aero_points")
    theta, u0 = np.array([0.01, -0.02, 0.005]), np.array([0.1, 0.0, -0.2])
    prob.set_val("rotations", np.tile(theta, (5, 1)))
    prob.set_val("displacements", u0 + np.cross(theta, nodes - nodes[0]))
    prob.run_model()
    assert_near_equal(
        prob.get_val("aero_displacements"), u0 + np.cross(theta, points - nodes[0]), 1e-12
    )


@pytest.mark.parametrize("num_point_masses, include_weight", [(2, True), (0, False), (0, True)])
def test_partials(num_point_masses, include_weight):
    prob = _setup(num_point_masses=num_point_masses, include_weight=include_weight)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-9, rtol=1e-9)


def test_nodes_must_increase_along_the_span():
    prob = _setup()
    nodes = prob.get_val("nodes")
    prob.set_val("nodes", nodes[::-1])
    with pytest.raises(om.AnalysisError, match="strictly increasing along the span axis y"):
        prob.run_model()
