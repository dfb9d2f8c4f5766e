import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.dynamics.force_sum import ForceSumComp
from lpc_mdo.components.energy.power import TotalPowerComp


def test_sums_and_partials():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "f",
        ForceSumComp(sources=["wing", "rotor", "drag"], forces_only=["drag"], num_nodes=2),
        promotes=["*"],
    )
    prob.model.add_subsystem(
        "p", TotalPowerComp(motors={"lift": 2, "pusher": 1}, num_nodes=2), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    rng = np.random.default_rng(1)
    values = {
        n: rng.normal(size=(2, 3))
        for n in ("wing_force", "rotor_force", "drag_force", "wing_moment", "rotor_moment")
    }
    for name, value in values.items():
        prob.set_val(name, value)
    prob.set_val("lift_motor_input_power", [[1.0, 2.0], [3.0, 4.0]])
    prob.set_val("pusher_motor_input_power", [[5.0, 6.0]])
    prob.run_model()
    # Closed forms: plain sums (drag has no moment).
    assert_near_equal(
        prob.get_val("force"),
        values["wing_force"] + values["rotor_force"] + values["drag_force"],
        1e-14,
    )
    assert_near_equal(prob.get_val("moment"), values["wing_moment"] + values["rotor_moment"], 1e-14)
    assert_near_equal(prob.get_val("electrical_power"), [9.0, 12.0], 1e-14)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-14, rtol=1e-14)


def test_bad_sources():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("f", ForceSumComp(sources=["wing"], forces_only=["drag"]))
    with pytest.raises(ValueError, match="forces_only must be a subset"):
        prob.setup()


def test_vector_sum_against_addsubtractcomp():
    """VectorSumComp gives OpenMDAO's AddSubtractComp's sum (the independent number), exactly."""
    from lpc_mdo.components.dynamics.force_sum import VectorSumComp

    names = ["vlm_moment", "body_moment", "tail_moment_correction"]
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "ours", VectorSumComp(output_name="total", input_names=names, units="N*m", num_nodes=2)
    )
    prob.model.add_subsystem(
        "stock",
        om.AddSubtractComp(
            output_name="total", input_names=names, vec_size=2, length=3, units="N*m"
        ),
    )
    prob.setup(force_alloc_complex=True)
    rng = np.random.default_rng(2)
    for name in names:
        value = rng.normal(size=(2, 3))
        prob.set_val(f"ours.{name}", value)
        prob.set_val(f"stock.{name}", value)
    prob.run_model()
    np.testing.assert_array_equal(prob.get_val("ours.total"), prob.get_val("stock.total"))
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-14, rtol=1e-14)
    with pytest.raises(ValueError, match="give distinct names"):
        bad = om.Problem(reports=False)
        bad.model.add_subsystem("s", VectorSumComp(output_name="a", input_names=["a", "b"]))
        bad.setup()
