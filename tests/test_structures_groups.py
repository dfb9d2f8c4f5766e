"""Beam assemblies (lpc_mdo.groups.beam): totals, solver configuration and the wrappers."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_totals, assert_near_equal

from lpc_mdo.api.structures import beam, box_beam
from lpc_mdo.components.structures.beam import BeamDisplacementComp
from lpc_mdo.components.structures.wing_box_geometry import WingBoxGeometryComp
from lpc_mdo.groups.beam import BeamGroup, BoxBeamGroup
from lpc_mdo.vehicle import reference_vehicle

THICKNESSES = (
    "top_skin_thickness",
    "bottom_skin_thickness",
    "front_spar_thickness",
    "rear_spar_thickness",
)


def _wing_problem(mode="auto"):
    """
    Return the run reference half wing: geometry, load transfer and box beam with KS aggregates.

    The loads are lift strips, 2 booms and the wing's own weight at +3 g.
    """
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "geometry", WingBoxGeometryComp(wing=reference_vehicle().wing), promotes=["*"]
    )
    prob.model.add_subsystem(
        "wing_box",
        BoxBeamGroup(num_nodes=9, num_aero_points=12, num_point_masses=2, ks_rho=50.0),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True, mode=mode)
    span = np.linspace(0.3, 7.5, 12)
    prob.set_val("aero_points", np.column_stack([-2.5 - 0.05 * span, span, -1.0 + 0.03 * span]))
    prob.set_val(
        "aero_forces",
        np.column_stack(
            [np.full(12, 20.0), np.zeros(12), -3000.0 * np.sqrt(1 - (span / 7.8) ** 2)]
        ),
    )
    prob.set_val("point_masses", [40.0, 40.0])
    prob.set_val("point_mass_locations", [[-2.8, 2.5, -0.8], [-2.9, 5.7, -0.76]])
    prob.set_val("load_factor", 3.0)
    prob.set_val("pitch", 0.14)
    rng = np.random.default_rng(0)
    for name in THICKNESSES:
        prob.set_val(name, rng.uniform(1e-3, 4e-3, 8))
    prob.run_model()
    return prob


@pytest.mark.parametrize("mode", ["fwd", "rev"])
def test_box_beam_group_totals(mode):
    # Totals through geometry, load transfer, the implicit stiffness solve (its own LU solve,
    # transposed in rev mode), stress, buckling and KS, against complex step.
    prob = _wing_problem(mode)
    data = prob.check_totals(
        of=[
            "displacements",
            "von_mises_stress",
            "top_skin_buckling_ratio",
            "bottom_skin_buckling_ratio",
            "stress_ratio_ks",
            "top_skin_buckling_ratio_ks",
            "beam_mass",
        ],
        wrt=[
            *THICKNESSES,
            "wing_area",
            "wing_aspect_ratio",
            "aero_forces",
            "pitch",
            "point_masses",
        ],
        method="cs",
        out_stream=None,
    )
    assert_check_totals(data, atol=1e-8, rtol=1e-7)


def test_beam_group_totals():
    nodes = np.column_stack([-0.1 * np.linspace(0, 1, 6) ** 2, np.linspace(0, 5, 6), np.zeros(6)])
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("beam", BeamGroup(num_nodes=6), promotes=["*"])
    prob.setup(force_alloc_complex=True, mode="rev")
    prob.set_val("nodes", nodes)
    prob.set_val("area", np.linspace(3e-3, 1e-3, 5))
    prob.set_val("bending_inertia_vertical", np.linspace(4e-6, 1e-6, 5))
    prob.set_val("bending_inertia_inplane", np.linspace(9e-6, 3e-6, 5))
    prob.set_val("torsion_constant", np.linspace(6e-6, 2e-6, 5))
    forces = np.zeros((6, 3))
    forces[1:, 2] = -500.0
    prob.set_val("node_forces", forces)
    prob.run_model()
    data = prob.check_totals(
        of=["displacements", "section_moments", "reaction_forces", "beam_mass"],
        wrt=["area", "bending_inertia_vertical", "nodes", "node_forces"],
        method="cs",
        out_stream=None,
    )
    assert_check_totals(data, atol=1e-8, rtol=1e-8)


@pytest.mark.parametrize("mode", ["fwd", "rev"])
def test_solver_configuration_and_cost(tmp_path, mode, monkeypatch):
    # The implicit stiffness solve needs no Newton/DirectSolver (check_config is clean), and its
    # cost is counted, not timed: each run_model solves K u = f once (one sparse LU), each
    # compute_totals factorizes K once more in linearize and then takes exactly one triangular
    # solve pair per right-hand side that reaches the displacements (fwd: every thickness
    # entry; rev: every output entry but beam_mass, which does not depend on them), so no
    # iterative solver repeats work.
    prob = _wing_problem(mode)
    report = tmp_path / "config.txt"
    prob.check_config(checks=["solvers"], out_file=str(report))
    assert "WARNING" not in report.read_text()
    fem = prob.model._get_subsystem("wing_box.fem")
    assert isinstance(fem, BeamDisplacementComp)
    calls = {"solve_nonlinear": 0, "_factorize": 0, "solve_linear": 0}

    def counted(name):
        method = getattr(fem, name)

        def wrapper(*args, **kwargs):
            calls[name] += 1
            return method(*args, **kwargs)

        return wrapper

    for name in calls:
        monkeypatch.setattr(fem, name, counted(name))
    of = [
        "displacements",
        "von_mises_stress",
        "top_skin_buckling_ratio",
        "bottom_skin_buckling_ratio",
        "beam_mass",
    ]
    repeats = 3
    for _ in range(repeats):
        prob.run_model()
        prob.compute_totals(of=of, wrt=list(THICKNESSES))
    assert calls["solve_nonlinear"] == repeats
    assert calls["_factorize"] == 2 * repeats
    seeds = THICKNESSES if mode == "fwd" else [n for n in of if n != "beam_mass"]
    rhs = sum(prob.get_val(name).size for name in seeds)
    assert calls["solve_linear"] == repeats * rhs


def test_beam_wrapper_cantilever():
    # Cantilever along x, tip force F_z and tip torque: w_tip = P L³/(3 E I_y),
    # twist T L/(G J) (Euler-Bernoulli closed forms); reactions balance the loads.
    nodes = np.column_stack([np.linspace(0, 2.0, 5), np.zeros(5), np.zeros(5)])
    loads = np.zeros((5, 6))
    loads[-1, 2], loads[-1, 3] = 100.0, 30.0
    out = beam(nodes, 1e-3, 2e-6, 3e-6, 4e-6, 70e9, 27e9, 2700.0, loads)
    assert out["displacements"].shape == (5, 6) and out["element_forces"].shape == (4, 12)
    assert_near_equal(out["displacements"][-1, 2], 100.0 * 2.0**3 / (3 * 70e9 * 2e-6), 1e-10)
    assert_near_equal(out["displacements"][-1, 3], 30.0 * 2.0 / (27e9 * 4e-6), 1e-10)
    assert_near_equal(out["reactions"][0], [0, 0, -100.0, -30.0, 200.0, 0.0], 1e-10)
    assert_near_equal(out["mass"], 2700.0 * 1e-3 * 2.0, 1e-12)
    # Element end forces (element frame): node a carries -P along local z (z here).
    assert_near_equal(out["element_forces"][0, 2], -100.0, 1e-10)


def test_box_beam_wrapper_options():
    nodes = np.column_stack([np.zeros(4), np.linspace(0, 3, 4), np.zeros(4)])
    loads = np.zeros((4, 6))
    loads[1:, 2] = -1000.0
    args = (nodes, 0.5, 0.15, 2e-3, 1.5e-3)
    flat = box_beam(*args, 1e-3, 69e9, 26e9, 2700.0, loads)
    spars = box_beam(
        *args,
        None,
        69e9,
        26e9,
        2700.0,
        loads,
        front_spar_thickness=1.5e-3,
        rear_spar_thickness=0.5e-3,
    )
    # Same mean web thickness -> the same beam (reference: the beam uses the mean of the spars).
    assert_near_equal(spars["displacements"], flat["displacements"], 1e-12)
    curved = box_beam(
        *args, 1e-3, 69e9, 26e9, 2700.0, loads, top_skin_radius=2.0, bottom_skin_radius=3.0
    )
    # Upward load: top skin in compression (positive ratio), curvature raises σ'.
    assert np.all(flat["top_skin_buckling_ratio"] > 0)
    assert np.all(flat["bottom_skin_buckling_ratio"] < 0)
    assert np.all(curved["top_skin_critical_stress"] > flat["top_skin_critical_stress"])
    assert flat["von_mises_stress"].shape == (3, 5)


def test_wrapper_errors_name_the_field():
    nodes = np.column_stack([np.zeros(3), np.arange(3.0), np.zeros(3)])
    loads = np.zeros((3, 6))
    with pytest.raises(ValueError, match=r"'area' = -1.0 is out of range: must be > 0 \(m\*\*2\)"):
        beam(nodes, -1.0, 1e-6, 1e-6, 1e-6, 70e9, 27e9, 2700.0, loads)
    with pytest.raises(ValueError, match=r"'loads' must have shape \(3, 6\)"):
        beam(nodes, 1e-3, 1e-6, 1e-6, 1e-6, 70e9, 27e9, 2700.0, np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"'torsion_constant' must be a scalar or have shape"):
        beam(nodes, 1e-3, 1e-6, 1e-6, [1e-6] * 3, 70e9, 27e9, 2700.0, loads)
    with pytest.raises(ValueError, match=r"'fixed_nodes' = \(5,\)"):
        beam(nodes, 1e-3, 1e-6, 1e-6, 1e-6, 70e9, 27e9, 2700.0, loads, fixed_nodes=(5,))
    with pytest.raises(ValueError, match="'poisson_ratio' = 0.7"):
        box_beam(nodes, 0.5, 0.1, 1e-3, 1e-3, 1e-3, 69e9, 26e9, 2700.0, loads, poisson_ratio=0.7)
    with pytest.raises(ValueError, match="give both 'top_skin_radius' and 'bottom_skin_radius'"):
        box_beam(nodes, 0.5, 0.1, 1e-3, 1e-3, 1e-3, 69e9, 26e9, 2700.0, loads, top_skin_radius=2.0)
