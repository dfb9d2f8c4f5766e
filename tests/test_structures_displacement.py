import numpy as np
import openmdao.api as om
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.structures.displacement import VerticalDisplacementComp


def test_signed_vertical_displacement():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("d", VerticalDisplacementComp(num_nodes=3, sign=-1.0), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("displacements", np.array([[0.0, 0.0, 0.0], [0.1, 0.0, -0.2], [0.2, 0, -0.5]]))
    prob.run_model()
    # Upward bending (z down): -w is the deflection magnitude.
    assert_near_equal(prob.get_val("vertical_displacement"), [[0.0, 0.2, 0.5]], 1e-15)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-15, rtol=1e-15)
