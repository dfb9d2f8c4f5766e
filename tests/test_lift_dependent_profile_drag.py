"""Lift-dependent profile drag of the VLM strips: strip flow, c_d increment, VLM wiring."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_check_totals,
    assert_near_equal,
)

from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.components.aero.lift_dependent_profile_drag import (
    LiftDependentProfileDragComp,
    StripFlowComp,
)
from lpc_mdo.components.geometry.planform import PlanformMeshComp
from lpc_mdo.groups.vlm import VLMGroup, VLMSurface


def _mesh(num_span_panels, **values):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "p", PlanformMeshComp(num_span_panels=num_span_panels, num_chord_panels=1), promotes=["*"]
    )
    prob.setup()
    for name, value in values.items():
        prob.set_val(name, value)
    prob.run_model()
    return prob.get_val("mesh")


def test_strip_flow_of_a_trapezoid():
    # Closed form: the strip chord of a trapezoid is linear in |y|, c(y) = c_r + (c_t - c_r)
    # 2|y|/b, and the strip's chord is the mean of its two stations' (the mesh's incidence
    # does not change a chord length); Re = (rho V/mu) c, M per condition. 1e-12.
    mesh = _mesh(6, span=8.0, root_chord=1.2, tip_chord=0.6, sweep=0.1, incidence=0.05)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "flow",
        StripFlowComp(num_nodes=2, num_chord_panels=1, num_span_panels=6),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("mesh", mesh)
    prob.set_val("reynolds_per_length", [3.0e6, 1.0e6])
    prob.set_val("mach", [0.17, 0.05])
    prob.run_model()
    y = mesh[0, :, 1]
    c = 1.2 + (0.6 - 1.2) * np.abs(y) / 4.0
    strip = 0.5 * (c[:-1] + c[1:])
    assert_near_equal(
        prob.get_val("strip_reynolds"), np.concatenate([3e6 * strip, 1e6 * strip]), 1e-12
    )
    assert_near_equal(prob.get_val("strip_mach"), np.repeat([0.17, 0.05], 6), 1e-15)
    data = prob.check_partials(method="cs", out_stream=None, compact_print=True)
    assert_check_partials(data, atol=1e-6, rtol=1e-10)


def _increment_problem(alpha, reynolds, mach, airfoil="ls413"):
    n = len(alpha)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "cd",
        LiftDependentProfileDragComp(num_nodes=1, num_span_panels=n, airfoil=airfoil),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("alpha_star", alpha)
    prob.set_val("reynolds", reynolds)
    prob.set_val("mach", mach)
    prob.run_model()
    return prob


@pytest.mark.parametrize("airfoil", ["ls413", "naca0012"])
def test_increment_against_the_polar(airfoil):
    # Independent numbers: the polar's c_d at alpha* less its minimum found by a 0.005 deg scan
    # of -10..15 deg (one level, 4x finer than the component's refinement and wider); tolerance
    # 5e-7 in c_d (the scans' error is second order in their steps).
    polar = get_polar(airfoil)
    alpha = np.radians([-2.0, 0.0, 3.0, 6.0, 9.0])
    re = np.array([1.0e6, 2.0e6, 3.0e6, 4.0e6, 5.0e6])
    mach = np.full(5, 0.17)
    prob = _increment_problem(alpha, re, mach, airfoil)
    fine = np.radians(np.arange(-10.0, 15.0, 0.005))
    expected = []
    for a, r, m in zip(alpha, re, mach, strict=True):
        low = polar.evaluate(fine, r, m).cd.min()
        expected.append(polar.evaluate(a, r, m).cd - low)
    increment = prob.get_val("sectional_cd")[0]
    assert np.all(np.abs(increment - np.array(expected)) < 5e-7)
    assert np.all(increment >= 0.0)
    # At high lift the increment is the rise out of the drag bucket: positive and growing.
    assert increment[4] > increment[3] > 0.0
    data = prob.check_partials(method="cs", out_stream=None, compact_print=True)
    assert_check_partials(data, atol=1e-9, rtol=1e-6)


def _vlm_problem(lift_dependent):
    surfaces = (VLMSurface("wing", 1, 6), VLMSurface("tail", 1, 2, deflectable=True))
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "vlm",
        VLMGroup(surfaces=surfaces, num_nodes=2, lift_dependent_drag=lift_dependent),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("wing_mesh", _mesh(6, span=8.0, root_chord=1.2, tip_chord=0.6, sweep=0.1))
    prob.set_val(
        "tail_mesh",
        _mesh(2, span=3.0, root_chord=0.6, tip_chord=0.3, root_leading_edge=[-4.0, 0.0, -0.5]),
    )
    prob.set_val("speed", [50.0, 30.0])
    prob.set_val("density", [1.1, 1.2])
    prob.set_val("angle_of_attack", [0.08, 0.12])
    prob.set_val("reference_area", 8.0)
    prob.set_val("wing_zero_lift_angle", -0.04)
    if lift_dependent:
        prob.set_val("reynolds_per_length", [3.2e6, 2.0e6])
        prob.set_val("mach", [0.15, 0.09])
    prob.run_model()
    return prob


def test_vlm_books_the_increment_at_the_sectional_lift():
    prob = _vlm_problem({"wing": "ls413"})
    plain = _vlm_problem({})
    # The increment does not feed back on the lattice: same circulation and sectional cl.
    assert_near_equal(prob.get_val("circulation"), plain.get_val("circulation"), 1e-14)
    cl = prob.get_val("wing_sectional_cl")
    # Independent chain: alpha* from the polar's cl by bisection, c_d less its minimum (fine
    # scan), each strip q c_d A_strip (strip theory), summed: the lattice's profile drag. 1e-5.
    polar = get_polar("ls413")
    re = prob.get_val("vlm.wing_strip_flow.strip_reynolds").reshape(2, 6)
    areas = prob.get_val("strip_areas")[:6]
    fine = np.radians(np.arange(-10.0, 15.0, 0.005))
    for i, (v, rho, mach) in enumerate(((50.0, 1.1, 0.15), (30.0, 1.2, 0.09))):
        drag = 0.0
        for j in range(6):
            lo, hi = np.radians(-8.0), np.radians(14.0)
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                if polar.evaluate(mid, re[i, j], mach).cl < cl[i, j]:
                    lo = mid
                else:
                    hi = mid
            cd = polar.evaluate(lo, re[i, j], mach).cd
            cd -= polar.evaluate(fine, re[i, j], mach).cd.min()
            drag += 0.5 * rho * v**2 * cd * areas[j]
        assert_near_equal(prob.get_val("profile_drag")[i], drag, 1e-5)
    assert np.all(prob.get_val("profile_drag") > 0.0)
    assert np.all(plain.get_val("profile_drag") == 0.0)


def test_vlm_totals_with_the_increment():
    prob = _vlm_problem({"wing": "ls413"})
    data = prob.check_totals(
        of=["profile_drag", "force"],
        wrt=["wing_mesh", "angle_of_attack", "speed", "reynolds_per_length", "mach"],
        method="cs",
        out_stream=None,
    )
    assert_check_totals(data, atol=1e-6, rtol=1e-6)


def test_unknown_surface_is_an_error():
    with pytest.raises(ValueError, match=r"lift_dependent_drag names \['fin'\]"):
        _vlm_problem({"fin": "ls413"})
