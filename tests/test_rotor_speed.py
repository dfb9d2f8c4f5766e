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


def test_side_differential_splits_each_pair_about_its_mean():
    """Closed form: left = mean + d/2, right = mean - d/2, so left - right = d and the pair's
    mean stays the group speed."""
    prob = om.Problem(reports=False)
    # LPC: rotors 0-3 on the left (side +1), 4-7 on the right (-1).
    side = [1, 1, 1, 1, -1, -1, -1, -1]
    prob.model.add_subsystem("s", RotorSpeedComp(group=[0, 1, 2, 3, 2, 3, 0, 1], num_groups=4,
                                                 num_nodes=2, side=side), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("group_speed", [[1000.0, 1100.0, 1200.0, 1300.0],
                                 [900.0, 950.0, 980.0, 990.0]])
    prob.set_val("group_differential", [[10.0, -20.0, 30.0, -40.0], [1.0, 2.0, 3.0, 4.0]])
    prob.run_model()
    rpm = prob.get_val("rpm")
    assert_near_equal(rpm[:, 0], [1005, 1090, 1215, 1280, 1185, 1320, 995, 1110], 1e-15)
    assert_near_equal(rpm[0, 1] - rpm[6, 1], 1.0, 1e-12)
    assert_near_equal(0.5 * (rpm[3, 1] + rpm[5, 1]), 990.0, 1e-15)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-14, rtol=1e-14)


def test_bad_side():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("s", RotorSpeedComp(group=[0, 0], num_groups=1, side=[1, 2]))
    with pytest.raises(ValueError, match=r"side = \[1.0, 2.0\]; allowed: one of \+1, -1, 0"):
        prob.setup()
