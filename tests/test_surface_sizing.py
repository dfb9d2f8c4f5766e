import openmdao.api as om
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.geometry.surface_sizing import SurfaceSizingComp


def test_reference_wing_and_partials():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("wing", SurfaceSizingComp(taper_ratio=0.2), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("area", 19.6)
    prob.set_val("aspect_ratio", 12.12)
    prob.run_model()
    # Reference docs theory/geometry 'Reference vehicle': b = 15.41 m, c_root = 2.119 m,
    # c_tip = 0.424 m, MAC = 1.460 m.
    assert_near_equal(prob.get_val("span"), 15.41, 5e-4)
    assert_near_equal(prob.get_val("root_chord"), 2.119, 5e-4)
    assert_near_equal(prob.get_val("tip_chord"), 0.424, 5e-4)
    assert_near_equal(prob.get_val("mean_aerodynamic_chord"), 1.460, 5e-4)
    # Area closes: S = b (c_root + c_tip)/2.
    area = prob.get_val("span") * (prob.get_val("root_chord") + prob.get_val("tip_chord")) / 2
    assert_near_equal(area, 19.6, 1e-12)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)
