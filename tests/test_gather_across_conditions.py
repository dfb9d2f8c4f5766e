import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.gather_across_conditions import GatherComp


def test_gather_with_gap_filled():
    prob = om.Problem(reports=False)
    # Three motors: hover has all, an OEI case lacks motor 1.
    prob.model.add_subsystem(
        "g",
        GatherComp(name="margin", sources=["hover", "oei"], items=[[0, 1, 2], [0, 2]], num_items=3),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("hover", [[0.3], [0.4], [0.5]])
    prob.set_val("oei", [[0.1], [0.2]])
    prob.run_model()
    # Closed form: columns are the sources; the gap (motor 1 in OEI) repeats hover's value.
    assert_near_equal(prob.get_val("margin"), np.array([[0.3, 0.1], [0.4, 0.4], [0.5, 0.2]]), 1e-15)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-14, rtol=1e-14)


def test_item_in_no_source_takes_the_absent_value():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "g",
        GatherComp(name="m", sources=["oei"], items=[[0, 2]], num_items=3, absent_value=10.0),
        promotes=["*"],
    )
    prob.setup()
    prob.set_val("oei", [[0.1], [0.2]])
    prob.run_model()
    assert_near_equal(prob.get_val("m"), [[0.1], [10.0], [0.2]], 1e-15)
    bad = om.Problem(reports=False)
    bad.model.add_subsystem("g", GatherComp(name="m", sources=["oei"], items=[[0, 2]], num_items=3))
    with pytest.raises(ValueError, match=r"items \[1\] are in no source"):
        bad.setup()


def test_bad_items():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("g", GatherComp(name="m", sources=["a"], items=[[0, 3]], num_items=3))
    with pytest.raises(ValueError, match="values in 0..2"):
        prob.setup()
