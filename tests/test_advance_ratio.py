import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.rotor.advance_ratio import EdgewiseAdvanceRatioComp


def _problem(velocity, rpm, radius):
    nr, nn = np.shape(rpm)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "mu", EdgewiseAdvanceRatioComp(num_rotors=nr, num_nodes=nn), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("inplane_velocity", velocity, units="m/s")
    prob.set_val("rpm", rpm, units="rpm")
    prob.set_val("radius", radius, units="m")
    prob.run_model()
    return prob


def test_hand_computed_advance_ratio():
    # 30-40-50 triangle: 50 m/s in plane; 600 rpm x 1.2 m = 20 pi x 1.2 = 75.398 m/s tip speed.
    prob = _problem([[[30.0, 40.0]], [[0.0, 0.0]]], [[600.0], [900.0]], [1.2, 1.5])
    mu = prob.get_val("edgewise_advance_ratio")
    assert_near_equal(mu[0, 0], 50.0 / (600.0 * 2.0 * np.pi / 60.0 * 1.2), 1e-14)
    assert mu[1, 0] == 0.0  # hover: no in-plane flow


def test_partials():
    rng = np.random.default_rng(3)
    prob = _problem(rng.normal(0.0, 30.0, (3, 2, 2)), rng.uniform(200, 2000, (3, 2)), [1.0, 1.4, 2])
    data = prob.check_partials(method="cs", out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_non_positive_speed_is_an_analysis_error():
    with pytest.raises(om.AnalysisError, match="rpm"):
        _problem([[[10.0, 0.0]]], [[0.0]], [1.0])
