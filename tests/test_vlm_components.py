"""Partials and building blocks of the VLM components (components/aero/vlm_*.py)."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_near_equal,
    assert_no_approx_partials,
)

from lpc_mdo.components.aero.vlm_aic import VLMAICComp
from lpc_mdo.components.aero.vlm_biot_savart import (
    INV_4PI,
    segment_velocity,
    semi_infinite_velocity,
)
from lpc_mdo.components.aero.vlm_circulation import VLMCirculationComp
from lpc_mdo.components.aero.vlm_forces import VLMPanelForcesComp
from lpc_mdo.components.aero.vlm_freestream import VLMFreestreamComp
from lpc_mdo.components.aero.vlm_geometry import VLMGeometryComp
from lpc_mdo.components.aero.vlm_induced_velocity import VLMInducedVelocityComp
from lpc_mdo.components.aero.vlm_lattice import Lattice, VLMSurface
from lpc_mdo.components.aero.vlm_loads import VLMLoadsComp
from lpc_mdo.components.aero.vlm_normals import VLMNormalsComp
from lpc_mdo.components.aero.vlm_profile_drag import VLMProfileDragComp
from lpc_mdo.components.aero.vlm_sectional import VLMSectionalLiftComp
from lpc_mdo.components.aero.vlm_trefftz import VLMTrefftzDragComp
from lpc_mdo.components.geometry.planform import PlanformMeshComp
from lpc_mdo.groups.vlm import VLMGroup

SURFACES = (VLMSurface("wing", 2, 4), VLMSurface("tail", 1, 2, deflectable=True))


def _meshes():
    """Swept, tapered, dihedral, twisted wing (2 x 4) and an offset tail (1 x 2)."""
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("wing", PlanformMeshComp(num_span_panels=4, num_chord_panels=2))
    prob.model.add_subsystem("tail", PlanformMeshComp(num_span_panels=2, num_chord_panels=1))
    prob.setup()
    for name, b, c, x0, sweep, dihedral in (
        ("wing", 8.0, 1.2, [0.0, 0.0, 0.0], 0.2, 0.1),
        ("tail", 3.0, 0.6, [-4.0, 0.1, -0.5], 0.1, -0.05),
    ):
        prob.set_val(f"{name}.span", b)
        prob.set_val(f"{name}.root_chord", c)
        prob.set_val(f"{name}.tip_chord", 0.6 * c)
        prob.set_val(f"{name}.sweep", sweep)
        prob.set_val(f"{name}.dihedral", dihedral)
        prob.set_val(f"{name}.incidence", 0.03)
        prob.set_val(f"{name}.root_leading_edge", x0)
    prob.set_val("wing.twist", [0.0, -0.02, -0.05])
    prob.run_model()
    return prob.get_val("wing.mesh"), prob.get_val("tail.mesh")


def make_problem():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vlm", VLMGroup(surfaces=SURFACES, num_nodes=2), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    wing, tail = _meshes()
    prob.set_val("wing_mesh", wing)
    prob.set_val("tail_mesh", tail)
    prob.set_val("speed", [50.0, 30.0])
    prob.set_val("angle_of_attack", [0.05, 0.1])
    prob.set_val("sideslip_angle", [0.02, -0.05])
    prob.set_val("angular_velocity", [[0.1, -0.2, 0.05], [0.0, 0.1, -0.1]])
    prob.set_val("rotation_center", [-1.0, 0.1, 0.2])
    prob.set_val("reference_point", [-0.5, 0.05, 0.1])
    prob.set_val("reference_area", 8.0)
    prob.set_val("density", [1.2, 1.1])
    prob.set_val(
        "wing_zero_lift_angle", [[-0.03, -0.04, -0.05, -0.04], [-0.02, -0.03, -0.035, -0.025]]
    )
    prob.set_val("wing_sectional_cd", 0.01 + 0.001 * np.arange(8).reshape(2, 4))
    prob.set_val("tail_zero_lift_angle", [[0.01, 0.0], [0.0, -0.01]])
    prob.set_val("tail_sectional_cd", [[0.009, 0.008], [0.01, 0.011]])
    prob.set_val("tail_deflection", [0.05, -0.1])
    prob.run_model()
    return prob


def test_partials_of_every_vlm_component():
    prob = make_problem()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    expected = {
        "geometry": VLMGeometryComp,
        "freestream": VLMFreestreamComp,
        "normals": VLMNormalsComp,
        "aic": VLMAICComp,
        "circulation": VLMCirculationComp,
        "induced_velocity": VLMInducedVelocityComp,
        "panel_forces": VLMPanelForcesComp,
        "profile_drag": VLMProfileDragComp,
        "loads": VLMLoadsComp,
        "sectional": VLMSectionalLiftComp,
        "trefftz": VLMTrefftzDragComp,
    }
    # Every VLM component is checked, each in its subsystem of the group.
    assert {name.split(".")[-1] for name in data} == set(expected)
    for name, cls in expected.items():
        assert isinstance(getattr(prob.model.vlm, name), cls)
    # Mesh-coordinate partials included (ring vertices, collocation and force points, areas).
    assert ("aic", "ring_vertices") in data["vlm.aic"]
    assert_check_partials(data, atol=1e-8, rtol=1e-8)
    assert_no_approx_partials(prob.model, method="any")


def test_biot_savart_kernels_against_katz_plotkin():
    # Katz & Plotkin (2001) eq. 10.115: v = (r1 x r2)/|r1 x r2|^2 r0.(r1/|r1| - r2/|r2|)/(4 pi).
    rng = np.random.default_rng(1)
    r1, r2 = rng.normal(size=(6, 3)), rng.normal(size=(6, 3))
    cr = np.cross(r1, r2)
    ref = (
        INV_4PI
        * cr
        / np.sum(cr * cr, axis=1)[:, None]
        * np.sum(
            (r1 - r2)
            * (r1 / np.linalg.norm(r1, axis=1)[:, None] - r2 / np.linalg.norm(r2, axis=1)[:, None]),
            axis=1,
        )[:, None]
    )
    assert_near_equal(segment_velocity(r1, r2), ref, 1e-9)
    # Semi-infinite line = limit of a long segment (1e5 lengths; truncation ~1e-5 relative).
    u = rng.normal(size=(6, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    far = r1 - 1e5 * u
    cr = np.cross(r1, far)
    ref = (
        INV_4PI
        * cr
        / np.sum(cr * cr, axis=1)[:, None]
        * np.sum(
            (r1 - far)
            * (
                r1 / np.linalg.norm(r1, axis=1)[:, None]
                - far / np.linalg.norm(far, axis=1)[:, None]
            ),
            axis=1,
        )[:, None]
    )
    assert_near_equal(semi_infinite_velocity(r1, u), ref, 1e-4)
    # Biot-Savart for an infinite line at distance h: 1/(2 pi h); a semi-infinite one from the
    # foot point gives half of it.
    v = semi_infinite_velocity(np.array([0.0, 2.0, 0.0]), np.array([1.0, 0.0, 0.0]))
    assert_near_equal(v, [0.0, 0.0, 0.5 / (2.0 * np.pi * 2.0)], 1e-10)


def test_biot_savart_kernel_derivatives_against_complex_step():
    rng = np.random.default_rng(2)
    r1, r2 = rng.normal(size=(5, 3)), rng.normal(size=(5, 3))
    u = rng.normal(size=(5, 3))
    u /= np.linalg.norm(u, axis=1)[:, None]
    h = 1e-30
    for kernel, args in ((segment_velocity, (r1, r2)), (semi_infinite_velocity, (r1, u))):
        _, *jacs = kernel(*args, derivatives=True)
        for k, jac in enumerate(jacs):
            for d in range(3):
                step = [np.asarray(x, dtype=complex) for x in args]
                step[k][:, d] += 1j * h
                assert_near_equal(jac[:, :, d], kernel(*step).imag / h, 1e-12)


def test_lattice_bookkeeping():
    lat = Lattice(SURFACES)
    assert lat.num_panels == 2 * 4 + 2 and lat.num_strips == 6
    assert list(lat.te_panels) == [4, 5, 6, 7, 8, 9]
    assert list(lat.upstream_panel) == [-1, -1, -1, -1, 0, 1, 2, 3, -1, -1]
    w = lat.force_point_segment_weights()
    assert w[5, 5, 0] == 0.0 and w[5, 1, 2] == 0.0  # own bound segment; upstream ring's p3->p4
    assert w[5, 4, 0] == 1.0 and np.all(w[:, lat.te_panels, 2] == 0.0)
    with pytest.raises(ValueError, match="'num_span_panels' = 0 is out of range: must be >= 1"):
        VLMSurface("wing", 1, 0)
    with pytest.raises(ValueError, match="names .* must be unique"):
        Lattice((VLMSurface("a", 1, 2), VLMSurface("a", 1, 2)))


def test_singular_system_is_an_analysis_error():
    # Two coincident surfaces: identical collocation points, so the AIC has equal rows.
    surfaces = (VLMSurface("a", 1, 2), VLMSurface("b", 1, 2))
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vlm", VLMGroup(surfaces=surfaces), promotes=["*"])
    prob.setup()
    wing, _ = _meshes()
    mesh = wing[::2, ::2]  # 2 x 3 nodes
    prob.set_val("a_mesh", mesh)
    prob.set_val("b_mesh", mesh)
    prob.set_val("speed", 30.0)
    prob.set_val("angle_of_attack", 0.05)
    with pytest.raises(om.AnalysisError, match="AIC matrix .* (singular|non-finite)"):
        prob.run_model()


def test_bad_flight_inputs_are_analysis_errors():
    prob = make_problem()
    prob.set_val("speed", [-1.0, 30.0])
    with pytest.raises(
        om.AnalysisError,
        match=r"'speed\[0\]' = -1.0"
        r" is out of range: must be >= 0 \(m/s\)",
    ):
        prob.run_model()
    prob.set_val("speed", [0.0, 30.0])  # hover node: no circulation, finite coefficients
    prob.set_val("reference_area", 0.0)
    with pytest.raises(
        om.AnalysisError,
        match=r"'reference_area' = 0.0"
        r" is out of range: must be > 0 \(m\*\*2\)",
    ):
        prob.run_model()
    prob.set_val("reference_area", 8.0)
    prob.set_val("angular_velocity", [[0.0, 0.0, 0.0], [0.0, 0.1, -0.1]])
    prob.run_model()
    assert np.all(prob.get_val("circulation")[0] == 0.0)
    assert prob.get_val("CL")[0] == 0.0 and np.isfinite(prob.get_val("CL")[1])
