"""Stacking the per-rotor quantities of rotor sets: lpc_mdo.components.rotor_stack."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.rotor_stack import RotorStackComp


def test_sets_follow_each_other_and_partials_are_exact():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "s",
        RotorStackComp(
            sets=[("lift", 3), ("pusher", 1)],
            quantities=[("rpm", (), "rpm"), ("hub_position", (3,), "m")],
        ),
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("s.lift_rpm", [1.0, 2.0, 3.0])
    prob.set_val("s.pusher_rpm", [4.0])
    hubs = np.arange(9.0).reshape(3, 3)
    prob.set_val("s.lift_hub_position", hubs)
    prob.set_val("s.pusher_hub_position", [[9.0, 10.0, 11.0]])
    prob.run_model()
    np.testing.assert_array_equal(prob.get_val("s.rpm"), [1.0, 2.0, 3.0, 4.0])
    np.testing.assert_array_equal(prob.get_val("s.hub_position"), np.arange(12.0).reshape(4, 3))
    assert_check_partials(prob.check_partials(method="cs", out_stream=None), atol=1e-12)


def test_an_empty_set_is_a_named_error():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "s", RotorStackComp(sets=[("lift", 0)], quantities=[("rpm", (), "rpm")])
    )
    with pytest.raises(ValueError, match="'lift' must have >= 1 rotor"):
        prob.setup()
