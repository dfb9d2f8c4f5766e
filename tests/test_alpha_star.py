"""AlphaStarComp: alpha* from the sectional cl (paper eq. 16a)."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_check_totals

from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.components.aero.alpha_star import AlphaStarComp, stall_bracket
from lpc_mdo.components.aero.polar import LinearQuadraticPolar


def make_problem(airfoil, n, mode="auto", **options):
    prob = om.Problem()
    prob.model.add_subsystem(
        "alpha", AlphaStarComp(num_sections=n, airfoil=airfoil, **options), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True, mode=mode)
    return prob


@pytest.mark.parametrize("airfoil", ["ls413", "ls417", "naca0012"])
def test_inversion_recovers_alpha_in_attached_flow(airfoil):
    polar = get_polar(airfoil)
    rng = np.random.default_rng(7)
    n = 40
    re = 10 ** rng.uniform(5.5, 7.0, n)
    mach = rng.uniform(0.0, 0.5, n)
    lo, hi = stall_bracket(polar, re, mach)[:2]
    alpha = lo + (hi - lo) * rng.uniform(0.08, 0.92, n)  # attached, inside the bracket
    prob = make_problem(airfoil, n)
    prob.set_val("lift_coefficient", polar.evaluate(alpha, re, mach).cl)
    prob.set_val("reynolds", re)
    prob.set_val("mach", mach)
    prob.run_model()
    np.testing.assert_allclose(prob.get_val("alpha_star"), alpha, rtol=0.0, atol=1e-8)
    assert np.max(np.abs(prob.get_val("alpha_star") - alpha)) < 1e-12  # measured ~1e-15
    assert prob.model.alpha.num_beyond_stall == 0


def test_partials_inside_and_beyond_the_stall_bracket():
    n = 5
    prob = make_problem("ls413", n)
    # sections: attached (3), above cl_max, below cl_min (linear continuation)
    prob.set_val("lift_coefficient", [0.2, 0.9, 1.4, 2.6, -1.9])
    prob.set_val("reynolds", [1.1e6, 3.3e6, 7.7e6, 2.0e6, 4.0e6])
    prob.set_val("mach", [0.12, 0.21, 0.29, 0.18, 0.05])
    prob.run_model()
    assert prob.model.alpha.num_beyond_stall == 2
    residual = prob.model.alpha._residuals["alpha_star"]
    prob.model.run_apply_nonlinear()
    assert np.max(np.abs(residual)) < 1e-12
    data = prob.check_partials(method="cs", out_stream=None, compact_print=True)
    assert_check_partials(data, atol=1e-10, rtol=1e-8)


def test_beyond_stall_uses_the_linear_continuation():
    polar = get_polar("ls417")
    re, mach = 5e6, 0.2
    lo, hi = (float(x) for x in stall_bracket(polar, re, mach)[:2])
    cl_hi = float(polar.evaluate(hi, re, mach).cl)
    prob = make_problem("ls417", 1)
    prob.set_val("lift_coefficient", cl_hi + 0.2)
    prob.set_val("reynolds", re)
    prob.set_val("mach", mach)
    prob.run_model()
    assert prob.get_val("alpha_star")[0] == pytest.approx(hi + 0.2 / (2 * np.pi), abs=1e-12)


@pytest.mark.parametrize("mode", ["fwd", "rev"])
def test_totals_match_the_implicit_function_theorem(mode):
    """Check d alpha*/d cl_VLM = 1/cl_alpha(alpha*), through solve_linear (no linear solver)."""
    prob = make_problem("ls413", 3, mode=mode)
    prob.set_val("lift_coefficient", [0.3, 0.8, 1.2])
    prob.set_val("reynolds", [2e6, 5e6, 8e6])
    prob.set_val("mach", [0.1, 0.2, 0.3])
    prob.run_model()
    a = prob.get_val("alpha_star")
    slope = (
        get_polar("ls413").evaluate(a, prob.get_val("reynolds"), prob.get_val("mach")).dcl_dalpha
    )
    wrt = ["lift_coefficient", "reynolds", "mach"]
    totals = prob.compute_totals("alpha_star", wrt)
    np.testing.assert_allclose(
        np.diag(totals["alpha_star", "lift_coefficient"]), 1 / slope, rtol=1e-12
    )
    data = prob.check_totals("alpha_star", wrt, method="fd", step=1e-7, out_stream=None)
    assert_check_totals(data, atol=1e-6, rtol=2e-5)


@pytest.mark.filterwarnings("ignore::openmdao.utils.om_warnings.DerivativesWarning")
def test_user_table_and_analytic_polar_work_like_a_name():
    lq = LinearQuadraticPolar()
    a_deg = np.arange(-20.0, 25.0 + 1e-9, 0.5)
    v = lq.evaluate(np.radians(a_deg), 1e6, 0.0)
    table = np.column_stack([a_deg, v.cl, v.cd])
    target = np.array([-0.2, 0.5, 1.1])
    expected = (target - 0.5) / 5.1566  # attached: cl = 0.5 + 5.1566 a
    for airfoil in (table, lq):
        prob = make_problem(airfoil, 3)
        prob.set_val("lift_coefficient", target)
        prob.run_model()
        np.testing.assert_allclose(prob.get_val("alpha_star"), expected, atol=1e-10)
        data = prob.check_partials(method="cs", out_stream=None, compact_print=True)
        assert_check_partials(data, atol=1e-10, rtol=1e-8)


def test_non_finite_input_raises_analysis_error():
    prob = make_problem("ls413", 2)
    prob.set_val("lift_coefficient", [0.5, np.nan])
    with pytest.raises(om.AnalysisError, match=r"sections \[1\]"):
        prob.run_model()
