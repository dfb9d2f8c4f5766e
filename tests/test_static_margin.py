"""Neutral point (paper eq. 30) and static margin.

Reference: docs theory/dynamics 'Neutral point and static margin'.
"""

import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_check_totals,
    assert_near_equal,
)

from lpc_mdo.components.dynamics.static_margin import NeutralPointComp, StaticMarginComp


def problem():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("np", NeutralPointComp(), promotes=["*"])
    prob.model.add_subsystem("sm", StaticMarginComp(), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    return prob


def test_closed_form_neutral_point_and_margin():
    # Lift increments dF_z/dalpha = -1.2e5 N/rad acting at x_ac = -3.2 m give, about the
    # origin, dM_O/dalpha = -x_ac dF_z/dalpha; M_P = M_O + x F_z then puts the neutral point at
    # the aerodynamic centre, x = -3.2 m (closed form).
    prob = problem()
    dfz = -1.2e5
    prob.set_val("normal_force_slope", dfz)
    prob.set_val("pitching_moment_slope", 3.2 * dfz)  # = -x_ac * dfz
    prob.set_val("cg_x", -3.0)
    prob.set_val("mean_aerodynamic_chord", 1.46)
    prob.run_model()
    assert_near_equal(prob.get_val("neutral_point"), -3.2, 1e-12)
    # SM = (x_cg - x_np)/MAC = 0.2/1.46, positive: neutral point aft of the cg (stable).
    assert_near_equal(prob.get_val("static_margin"), 0.2 / 1.46, 1e-12)


def test_partials_and_totals():
    prob = problem()
    prob.set_val("normal_force_slope", -9.0e4)
    prob.set_val("pitching_moment_slope", 3.5 * -9.0e4)
    prob.run_model()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)
    for mode in ("fwd", "rev"):
        prob.setup(force_alloc_complex=True, mode=mode)
        prob.set_val("normal_force_slope", -9.0e4)
        prob.set_val("pitching_moment_slope", 3.5 * -9.0e4)
        prob.run_model()
        totals = prob.check_totals(
            of=["static_margin"],
            wrt=["normal_force_slope", "pitching_moment_slope", "cg_x"],
            method="cs",
            out_stream=None,
        )
        assert_check_totals(totals, atol=1e-12, rtol=1e-9)


def test_complex_step_through_the_solve():
    # Totals by complex step go through solve_nonlinear; they must match the analytic ones.
    prob = problem()
    prob.set_val("normal_force_slope", -9.0e4)
    prob.set_val("pitching_moment_slope", 3.5 * -9.0e4)
    prob.run_model()
    data = prob.check_totals(
        of=["neutral_point"], wrt=["normal_force_slope"], method="cs", out_stream=None
    )
    assert_check_totals(data, atol=1e-12, rtol=1e-10)


def test_no_neutral_point_in_bracket_is_an_analysis_error():
    prob = problem()
    prob.set_val("normal_force_slope", -1e5)
    prob.set_val("pitching_moment_slope", -20.0 * -1e5)  # would put it 20 m ahead of the nose
    with pytest.raises(om.AnalysisError, match="no neutral point in the bracket"):
        prob.run_model()
