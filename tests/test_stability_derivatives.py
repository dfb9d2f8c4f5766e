import numpy as np
import openmdao.api as om
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.dynamics.stability_derivatives import (
    AnglePerturbationComp,
    StabilityDerivativeComp,
)


def test_difference_of_an_affine_model_is_exact():
    # For forces affine in alpha (the small-angle VLM), the difference is the slope exactly.
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("a", AnglePerturbationComp(delta=2e-3), promotes=["*"])
    prob.model.add_subsystem("s", StabilityDerivativeComp(delta=2e-3), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    alpha = 0.05
    slope_fz, slope_my = -1.1e5, 3.3e5
    prob.set_val("angle_of_attack", alpha)
    prob.run_model()
    alpha_p = prob.get_val("perturbed_angle_of_attack")[0]
    assert_near_equal(alpha_p, alpha + 2e-3, 1e-15)
    prob.set_val("force", [[0.0, 0.0, slope_fz * alpha]])
    prob.set_val("perturbed_force", [[0.0, 0.0, slope_fz * alpha_p]])
    prob.set_val("moment", [[0.0, slope_my * alpha, 0.0]])
    prob.set_val("perturbed_moment", [[0.0, slope_my * alpha_p, 0.0]])
    prob.run_model()
    assert_near_equal(prob.get_val("normal_force_slope"), slope_fz, 1e-10)
    assert_near_equal(prob.get_val("pitching_moment_slope"), slope_my, 1e-10)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-8, rtol=1e-10)
    assert np.isfinite(prob.get_val("normal_force_slope")).all()
