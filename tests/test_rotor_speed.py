import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.rotor.rotor_speed import RotorSpeedComp


def test_pairs_share_speed():
    prob = om.Problem(reports=False)
    # LPC pairing (vehicle file): rotors 0..7 belong to pairs [0, 1, 2, 3, 2, 3, 0, 1].
    prob.model.add_subsystem("s", RotorSpeedComp(group=[0, 1, 2, 3, 2, 3, 0, 1], num_groups=4,
                                                 num_nodes=2), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("group_speed", [[1000.0, 1100.0, 1200.0, 1300.0],
                                 [900.0, 950.0, 980.0, 990.0]])
    prob.run_model()
    rpm = prob.get_val("rpm")
    assert_near_equal(rpm[:, 0], [1000, 1100, 1200, 1300, 1200, 1300, 1000, 1100], 1e-15)
    assert_near_equal(rpm[6, 1], 900.0, 1e-15)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-14, rtol=1e-14)


def test_bad_group():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("s", RotorSpeedComp(group=[0, 4], num_groups=4))
    with pytest.raises(ValueError, match=r"group = \[0, 4\]; each entry must be in 0..3"):
        prob.setup()
