"""Landing-gear tyres sized from the design gross mass, and their drag."""

import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.aero.drag_buildup import DragBuildupComp, SizedBluffDrag
from lpc_mdo.components.aero.tyre_size import TyreFrontalAreaComp, tyre_frontal_areas


def test_tyres_by_hand_and_the_partials():
    # Raymer, Aircraft Design, 6th ed., Table 11.1 (general aviation): D = 1.51 W^0.349 in,
    # width = 0.7150 W^0.312 in, W the load per wheel in lb. 3265.27 kg, 90 % on two mains:
    # 1469.4 kg = 3239.4 lb per main wheel.
    w_lb = 0.9 * 3265.27 / 2.0 / 0.45359237
    main = (1.51 * w_lb**0.349) * (0.7150 * w_lb**0.312) * 0.0254**2
    assert tyre_frontal_areas(3265.27)[0] == pytest.approx(main, rel=1e-12)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("t", TyreFrontalAreaComp(), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("design_gross_mass", 2900.0)
    prob.run_model()
    assert prob.get_val("drag_main_wheels_frontal_area")[0] == pytest.approx(
        tyre_frontal_areas(2900.0)[0]
    )
    assert_check_partials(prob.check_partials(method="cs", out_stream=None), atol=1e-12, rtol=1e-9)


def test_sized_bluff_part_in_the_build_up_and_its_partials():
    # D/q = count C_D A: two wheels of C_D 0.25 on 0.15 m^2 give 0.075 m^2.
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "d", DragBuildupComp(components=(SizedBluffDrag("wheels", 0.25, 2),)), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("wheels_frontal_area", 0.15)
    prob.set_val("speed", 50.0)
    prob.run_model()
    assert prob.get_val("drag_areas")[0, 0] == pytest.approx(0.075)
    data = prob.check_partials(method="cs", out_stream=None)
    assert_check_partials(data, atol=1e-9, rtol=1e-7)
    with pytest.raises(ValueError, match="drag_coefficient"):
        SizedBluffDrag("wheels", 3.0)
