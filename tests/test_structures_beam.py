"""Frame FEM (lpc_mdo.components.structures.beam): closed forms, statics, partials, errors."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_check_totals,
    assert_near_equal,
)

from lpc_mdo.components.structures.beam import (
    BeamDisplacementComp,
    BeamForcesComp,
    BeamMassComp,
    element_frames,
)

E, G, RHO = 70.0e9, 27.0e9, 2700.0
AREA, I_Y, I_Z, J = 2.0e-3, 3.0e-6, 5.0e-6, 4.0e-6


def _frame_problem(
    nodes, loads, fixed_nodes=(0,), fixed_dofs=(), props=None, connectivity=None, mode="auto"
):
    """Run mass, stiffness solve and load recovery on one frame (loads: (n, 6) global)."""
    n = len(nodes)
    ne = n - 1 if connectivity is None else len(connectivity)
    opts = {"num_nodes": n, "connectivity": connectivity}
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("mass", BeamMassComp(**opts), promotes=["*"])
    prob.model.add_subsystem(
        "fem",
        BeamDisplacementComp(fixed_nodes=fixed_nodes, fixed_dofs=fixed_dofs, **opts),
        promotes=["*"],
    )
    prob.model.add_subsystem("recovery", BeamForcesComp(**opts), promotes=["*"])
    prob.setup(force_alloc_complex=True, mode=mode)
    props = props or {}
    prob.set_val("nodes", nodes)
    prob.set_val("area", props.get("area", np.full(ne, AREA)))
    prob.set_val("bending_inertia_vertical", props.get("iy", np.full(ne, I_Y)))
    prob.set_val("bending_inertia_inplane", props.get("iz", np.full(ne, I_Z)))
    prob.set_val("torsion_constant", props.get("j", np.full(ne, J)))
    prob.set_val("youngs_modulus", E)
    prob.set_val("shear_modulus", G)
    prob.set_val("density", RHO)
    prob.set_val("node_forces", loads[:, :3])
    prob.set_val("node_moments", loads[:, 3:])
    prob.run_model()
    return prob


def _oblique_cantilever(num_elements=6, length=3.0):
    """Straight cantilever along an oblique axis and its local frame (rows x, y, z)."""
    axis = np.array([1.0, 2.0, 2.0]) / 3.0
    nodes = np.outer(np.linspace(0.0, length, num_elements + 1), axis) + [0.5, -1.0, 0.2]
    _, lam = element_frames(nodes[:1], nodes[1:2])
    return nodes, lam[0]


@pytest.mark.parametrize("direction, inertia", [("z", I_Y), ("y", I_Z)])
def test_cantilever_tip_force_closed_form(direction, inertia):
    # Euler-Bernoulli cantilever with tip force P (any textbook, e.g. Roark Table 8.1 case 1a):
    # w(x) = P x² (3L - x)/(6 E I), slope P x (2L - x)/(2 E I). Cubic elements are exact at the
    # nodes, so 1e-9 relative (round-off only) is well inside the 1e-6 of the acceptance.
    length, force = 3.0, 1200.0
    nodes, lam = _oblique_cantilever(length=length)
    local = {"y": 1, "z": 2}[direction]
    loads = np.zeros((len(nodes), 6))
    loads[-1, :3] = force * lam[local]
    prob = _frame_problem(nodes, loads)
    x = np.linspace(0.0, length, len(nodes))
    deflection = prob.get_val("displacements") @ lam[local]
    assert_near_equal(deflection, force * x**2 * (3 * length - x) / (6 * E * inertia), 1e-9)
    # Slope: rotation about local y is -dw/dx (z bending), about local z +dv/dx (y bending).
    slope = prob.get_val("rotations") @ lam[3 - local]
    sign = -1.0 if direction == "z" else 1.0
    assert_near_equal(sign * slope, force * x * (2 * length - x) / (2 * E * inertia), 1e-9)
    # The axial and other transverse displacements stay zero (round-off).
    assert np.max(np.abs(prob.get_val("displacements") @ lam[0])) < 1e-12


def test_cantilever_distributed_load_closed_form():
    # Uniform load q along local z with work-equivalent (consistent) nodal loads q L_e/2 and
    # ±q L_e²/12 per element; for cubic elements the nodal deflections are then exact:
    # w(x) = q x² (6L² - 4 L x + x²)/(24 E I_y), tip q L⁴/(8 E I_y) (Roark Table 8.1 case 2a).
    length, q = 3.0, 800.0
    nodes, lam = _oblique_cantilever(num_elements=8, length=length)
    le = length / 8
    loads = np.zeros((len(nodes), 6))
    f_node = np.full(len(nodes), q * le)
    f_node[[0, -1]] = q * le / 2
    loads[:, :3] = f_node[:, None] * lam[2]
    # End moments of each element's fixed-end actions: about local y, -q L²/12 at a, + at b
    # (for a load along +z, M_y = -q L²/12 at node a and +q L²/12 at node b).
    loads[-1, 3:] = q * le**2 / 12 * lam[1]
    prob = _frame_problem(nodes, loads)
    x = np.linspace(0.0, length, len(nodes))
    deflection = prob.get_val("displacements") @ lam[2]
    expected = q * x**2 * (6 * length**2 - 4 * length * x + x**2) / (24 * E * I_Y)
    assert_near_equal(deflection, expected, 1e-9)
    assert_near_equal(deflection[-1], q * length**4 / (8 * E * I_Y), 1e-9)


def test_cantilever_tip_torque_closed_form():
    # Uniform torsion: twist θ(x) = T x/(G J), exact.
    length, torque = 3.0, 250.0
    nodes, lam = _oblique_cantilever(length=length)
    loads = np.zeros((len(nodes), 6))
    loads[-1, 3:] = torque * lam[0]
    prob = _frame_problem(nodes, loads)
    x = np.linspace(0.0, length, len(nodes))
    assert_near_equal(prob.get_val("rotations") @ lam[0], torque * x / (G * J), 1e-9)
    # Section resultant: internal torque T in every element; reactions -T at the root.
    assert_near_equal(prob.get_val("section_moments")[:, 0], np.full(6, torque), 1e-9)
    assert_near_equal(prob.get_val("reaction_moments")[0], -torque * lam[0], 1e-9)


def test_right_angle_frame_bending_plus_torsion():
    # Two members at right angles in the x-y plane, clamped at the origin: member 1 along +x
    # (length a), member 2 along +y (length b), vertical tip force P (+z). Closed form (unit-load
    # method): w_tip = P a³/(3 E I_y) + P b³/(3 E I_y) + P b² a/(G J) -- bending of both
    # members plus the twist P b a/(G J) of member 1 times the lever b. Rotation of the corner
    # about x = P b a/(G J). Exact for cubic frame elements (1e-9 relative).
    a, b, force = 2.0, 1.5, 900.0
    nodes = np.vstack(
        [
            np.column_stack([np.linspace(0, a, 5), np.zeros(5), np.zeros(5)]),
            np.column_stack([np.full(3, a), np.linspace(0, b, 4)[1:], np.zeros(3)]),
        ]
    )
    loads = np.zeros((len(nodes), 6))
    loads[-1, 2] = force
    prob = _frame_problem(nodes, loads)
    w_tip = force * a**3 / (3 * E * I_Y) + force * b**3 / (3 * E * I_Y) + force * b**2 * a / (G * J)
    assert_near_equal(prob.get_val("displacements")[-1, 2], w_tip, 1e-9)
    assert_near_equal(prob.get_val("rotations")[4, 0], force * b * a / (G * J), 1e-9)
    # Reactions (statics): force -P, moment -(r_tip x F) about the clamped origin.
    assert_near_equal(prob.get_val("reaction_forces")[0], [0.0, 0.0, -force], 1e-9)
    assert_near_equal(
        prob.get_val("reaction_moments")[0], -np.cross(nodes[-1], [0, 0, force]), 1e-9
    )


def test_section_loads_match_statics_of_a_bent_wing_like_beam():
    # Independent statics check on a curved, swept, dihedralled beam with forces and moments at
    # every node: the internal force on the outboard face of element e, rotated to the global
    # frame, equals the sum of the loads outboard of it; the internal moment equals their moment
    # about the element mid-point (round-off, 1e-8 relative).
    rng = np.random.default_rng(3)
    t = np.linspace(0.0, 1.0, 7)
    nodes = np.column_stack([-0.4 * t**2, 6.0 * t, -0.3 * t])
    loads = rng.normal(size=(7, 6)) * [100, 100, 1000, 50, 50, 50]
    prob = _frame_problem(nodes, loads)
    _, lam = element_frames(nodes[:-1], nodes[1:])
    forces = np.einsum("epi,ep->ei", lam, prob.get_val("section_forces"))
    moments = np.einsum("epi,ep->ei", lam, prob.get_val("section_moments"))
    mid = 0.5 * (nodes[:-1] + nodes[1:])
    for e in range(6):
        out = slice(e + 1, None)
        assert_near_equal(forces[e], loads[out, :3].sum(axis=0), 1e-8)
        expected = np.cross(nodes[out] - mid[e], loads[out, :3]).sum(axis=0) + loads[out, 3:].sum(
            axis=0
        )
        assert_near_equal(moments[e], expected, 1e-8)


def test_mass_and_cg_closed_form():
    # m = ρ A L per element; cg at the mid-point of a uniform straight beam.
    nodes, _ = _oblique_cantilever(length=3.0)
    prob = _frame_problem(nodes, np.zeros((len(nodes), 6)))
    assert_near_equal(prob.get_val("beam_mass"), RHO * AREA * 3.0, 1e-12)
    assert_near_equal(prob.get_val("element_mass"), np.full(6, RHO * AREA * 0.5), 1e-12)
    assert_near_equal(prob.get_val("beam_cg"), nodes.mean(axis=0), 1e-12)


def test_symmetry_constraints_and_vertical_elements():
    # A portal with vertical legs (the D = 0 branch of the transformation) under a lateral load,
    # legs clamped at the ground: the sum of the reactions balances the load (statics).
    nodes = np.array([[0, 0, 0], [0, 0, -2.0], [3.0, 0, -2.0], [3.0, 0, 0]])
    loads = np.zeros((4, 6))
    loads[1, 0] = 1000.0
    prob = _frame_problem(nodes, loads, fixed_nodes=(0, 3))
    assert_near_equal(prob.get_val("reaction_forces")[[0, 3]].sum(axis=0), [-1000.0, 0, 0], 1e-9)
    # Symmetry-plane constraint (v, θx, θz at the root) plus a clamp elsewhere is accepted.
    prob = _frame_problem(nodes, loads, fixed_nodes=(3,), fixed_dofs=((0, 1), (0, 3), (0, 5)))
    assert np.all(np.isfinite(prob.get_val("displacements")))


def _random_frame():
    rng = np.random.default_rng(7)
    t = np.linspace(0.0, 1.0, 5)
    nodes = np.column_stack([-0.3 * t + 0.05 * rng.normal(size=5), 5.0 * t, -0.2 * t])
    nodes = np.vstack([nodes, nodes[-1] + [0.0, 0.0, -1.0]])  # a vertical tip element
    props = {
        k: v * rng.uniform(0.5, 1.5, 5)
        for k, v in (("area", AREA), ("iy", I_Y), ("iz", I_Z), ("j", J))
    }
    loads = rng.normal(size=(6, 6)) * [100, 100, 1000, 50, 50, 50]
    return nodes, loads, props


def test_partials():
    # Analytic partials (u, section properties, E, G, loads) and the internal complex step on
    # the node coordinates against OpenMDAO's complex step. Entries reach 1e10 (E u), so the
    # absolute tolerance of 1e-3 is 1e-13 relative.
    nodes, loads, props = _random_frame()
    prob = _frame_problem(nodes, loads, fixed_dofs=((5, 2),), props=props)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-3, rtol=1e-8)


@pytest.mark.parametrize("mode", ["fwd", "rev"])
def test_totals_through_the_component_linear_solve(mode):
    # The group has no DirectSolver: the totals use BeamDisplacementComp.solve_linear (LU of K,
    # transposed in rev mode); compared with complex step through the sparse direct solve.
    nodes, loads, props = _random_frame()
    prob = _frame_problem(nodes, loads, props=props, mode=mode)
    data = prob.check_totals(
        of=["displacements", "rotations", "section_moments", "beam_mass"],
        wrt=["area", "torsion_constant", "nodes", "node_forces"],
        method="cs",
        out_stream=None,
    )
    assert_check_totals(data, atol=1e-10, rtol=1e-8)


def test_errors():
    nodes, _ = _oblique_cantilever()
    with pytest.raises(ValueError, match="constrain no DoF"):
        _frame_problem(nodes, np.zeros((7, 6)), fixed_nodes=())
    with pytest.raises(ValueError, match=r"constrained node 9 .* allowed \[0, 6\]"):
        _frame_problem(nodes, np.zeros((7, 6)), fixed_nodes=(9,))
    with pytest.raises(ValueError, match=r"dof 7 at node 0; allowed 0\.\.5"):
        _frame_problem(nodes, np.zeros((7, 6)), fixed_nodes=(), fixed_dofs=((0, 7),))
    # A mechanism: only the root translations fixed, the beam spins about its axis.
    with pytest.raises(om.AnalysisError, match="singular"):
        _frame_problem(nodes, np.ones((7, 6)), fixed_nodes=(), fixed_dofs=((0, 0), (0, 1), (0, 2)))
    bad = nodes.copy()
    bad[3] = bad[2]
    with pytest.raises(
        om.AnalysisError,
        match=r"'element length \(from input 'nodes'\)\[2\]' "
        r"= 0\.0 is out of range: must be > 0 \(m\)",
    ):
        _frame_problem(bad, np.zeros((7, 6)))
    with pytest.raises(
        om.AnalysisError,
        match=r"'torsion_constant\[.*\]' = -1\.0 is out of "
        r"range: must be > 0 \(m\*\*4\)",
    ):
        _frame_problem(nodes, np.zeros((7, 6)), props={"j": np.r_[J, J, -1.0, J, J, J]})
