import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.rotor.rotor_speed import RotorSpeedComp
from lpc_mdo.groups.condition_builders import roll_yaw_mixing
from lpc_mdo.vehicle import reference_vehicle


def test_pairs_share_speed():
    prob = om.Problem(reports=False)
    # LPC pairing (vehicle file): rotors 0..7 belong to pairs [0, 1, 2, 3, 2, 3, 0, 1].
    prob.model.add_subsystem(
        "s",
        RotorSpeedComp(group=[0, 1, 2, 3, 2, 3, 0, 1], num_groups=4, num_nodes=2),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("group_speed", [[1000.0, 1100.0, 1200.0, 1300.0], [900.0, 950.0, 980.0, 990.0]])
    prob.run_model()
    rpm = prob.get_val("rpm")
    assert_near_equal(rpm[:, 0], [1000, 1100, 1200, 1300, 1200, 1300, 1000, 1100], 1e-15)
    assert_near_equal(rpm[6, 1], 900.0, 1e-15)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-14, rtol=1e-14)


def test_bad_group():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("s", RotorSpeedComp(group=[0, 4], num_groups=4))
    with pytest.raises(ValueError, match=r"'group\[1\]' = 4 is out of range: must be in \[0, 3\]"):
        prob.setup()


def test_roll_and_yaw_mixers_split_each_pair_about_its_mean():
    """
    Check the mixers against the closed form rpm = pair speed + (side * roll + spin * yaw) / 2.

    So roll = mean left minus mean right speed, yaw = mean spin(+1) minus mean spin(-1) speed,
    and each pair's mean stays its group speed.
    """
    prob = om.Problem(reports=False)
    # LPC: rotors 0-3 on the left, 4-7 on the right; spins of the vehicle file.
    side = np.array([1, 1, 1, 1, -1, -1, -1, -1], dtype=float)
    spin = np.array([1, -1, -1, 1, 1, -1, -1, 1], dtype=float)
    mixing = 0.5 * np.column_stack([side, spin])
    prob.model.add_subsystem(
        "s",
        RotorSpeedComp(group=[0, 1, 2, 3, 2, 3, 0, 1], num_groups=4, num_nodes=2, mixing=mixing),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    speeds = np.array([[1000.0, 1100.0, 1200.0, 1300.0], [900.0, 950.0, 980.0, 990.0]])
    prob.set_val("group_speed", speeds)
    prob.set_val("mixer_speed", [[20.0, -8.0], [2.0, 6.0]])
    prob.run_model()
    rpm = prob.get_val("rpm")
    # Node 0: rotor 0 (left, spin +1): 1000 + 10 - 4; rotor 1 (left, -1): 1100 + 10 + 4; ...
    assert_near_equal(rpm[:, 0], [1006, 1114, 1214, 1306, 1186, 1294, 994, 1086], 1e-15)
    assert_near_equal(rpm[:4, 1].mean() - rpm[4:, 1].mean(), 2.0, 1e-12)
    assert_near_equal(rpm[spin > 0, 1].mean() - rpm[spin < 0, 1].mean(), 6.0, 1e-12)
    pairs = np.array([0, 1, 2, 3, 2, 3, 0, 1])
    for p in range(4):
        assert_near_equal(rpm[pairs == p, 1].mean(), speeds[1, p], 1e-15)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-14, rtol=1e-14)
    # The transition condition's mixing, from the reference vehicle's rotors, is this one.
    np.testing.assert_array_equal(roll_yaw_mixing(reference_vehicle().lift_rotors), mixing)


def test_bad_mixing():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "s", RotorSpeedComp(group=[0, 0], num_groups=1, mixing=[[0.5], [0.5], [0.5]])
    )
    with pytest.raises(
        ValueError,
        match=r"mixing has shape \(3, 1\); allowed: finite values "
        r"of shape \(2, num_mixers\)",
    ):
        prob.setup()
