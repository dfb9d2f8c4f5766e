"""Baseline-design objective (paper eq. 8-9)."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.design_deviation import DesignDeviationComp


def make(alpha=100.0):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "dev",
        DesignDeviationComp(
            references={"area": (19.6, "m**2"), "chord": (np.array([0.3, 0.2, 0.1]), "m")},
            alpha=alpha,
            objective_ref=3723.99,
        ),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    return prob


def test_value_is_objective_plus_weighted_relative_deviation():
    prob = make()
    prob.set_val("objective", 3500.0)
    prob.set_val("area", 21.56)  # +10 %
    prob.set_val("chord", [0.3, 0.1, 0.1])  # -50 % on one entry
    prob.run_model()
    # Closed form: 3500/3723.99 + 100 (0.1^2 + 0.5^2) = 0.939851 + 26.
    assert_near_equal(prob.get_val("deviation"), 0.26, 1e-12)
    assert_near_equal(prob.get_val("baseline_objective"), 3500.0 / 3723.99 + 26.0, 1e-12)


def test_partials():
    prob = make(alpha=7.0)
    prob.set_val("area", 18.0)
    prob.set_val("chord", [0.25, 0.3, 0.05])
    prob.run_model()
    assert_check_partials(prob.check_partials(method="cs", out_stream=None), atol=1e-12, rtol=1e-10)


def test_zero_reference_is_an_error():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "dev",
        DesignDeviationComp(references={"twist": (np.array([0.1, 0.0]), "rad")}, objective_ref=1.0),
    )
    with pytest.raises(ValueError, match=r"reference value of 'twist' = \[0.1, 0.0\]"):
        prob.setup()
