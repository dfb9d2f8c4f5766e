import numpy as np
import openmdao.api as om
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.motor.shaft_torque import ShaftTorqueComp


def test_floor_and_passthrough():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("t", ShaftTorqueComp(num_motors=2, num_nodes=3), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("rotor_torque", [[-50.0, 0.0, 1.0], [100.0, 1000.0, 10.0]])
    prob.run_model()
    out = prob.get_val("motor_load_torque")
    # Closed form: f + ((tau - f) + sqrt((tau - f)^2 + w^2))/2 with f = 1, w = 2.
    tau = prob.get_val("rotor_torque")
    expected = 1.0 + 0.5 * ((tau - 1.0) + np.sqrt((tau - 1.0) ** 2 + 4.0))
    assert_near_equal(out, expected, 1e-14)
    assert 1.0 < out[0, 0] < 1.03  # windmilling: the motor idles
    assert_near_equal(out[1, 1], 1000.0, 2e-6)  # normal operation: unchanged
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)
