import numpy as np
import openmdao.api as om
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.structures.mesh_deformation import MeshDeformationComp


def test_mirror_symmetric_deformation():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "d", MeshDeformationComp(num_chord_nodes=2, num_span_nodes=5), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    y = np.array([-2.0, -1.0, 0.0, 1.0, 2.0])
    mesh = np.zeros((2, 5, 3))
    mesh[:, :, 1] = y
    mesh[1, :, 0] = -1.0
    disp = np.zeros((2 * 3, 3))
    # Right-half nodes (root, mid, tip) of each chord row bend up (z down: negative) and out.
    disp.reshape(2, 3, 3)[:, :, 2] = [0.0, -0.1, -0.3]
    disp.reshape(2, 3, 3)[:, :, 1] = [0.0, 0.01, 0.02]
    prob.set_val("mesh", mesh)
    prob.set_val("right_displacements", disp)
    prob.run_model()
    out = prob.get_val("deformed_mesh")
    # Closed form: symmetric bending, the tips rise 0.3 m and move 0.02 m outwards.
    assert_near_equal(out[:, :, 2], np.tile([-0.3, -0.1, 0.0, -0.1, -0.3], (2, 1)), 1e-15)
    assert_near_equal(out[0, :, 1], y + np.array([-0.02, -0.01, 0.0, 0.01, 0.02]), 1e-15)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-14, rtol=1e-14)
