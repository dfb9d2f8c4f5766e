import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.bspline import BsplineComp
from lpc_mdo.components.geometry.minimum_chord import BladeChordMarginComp


def test_chord_margin_values_and_constant_partials():
    # By hand: f = 0.03, R = (1.5, 1.781) m: minimum chords 0.045 and 0.05343 m.
    prob = om.Problem(reports=False)
    comp = BladeChordMarginComp(num_rotors=2, num_cp=4, min_chord_radius_ratio=0.03)
    prob.model.add_subsystem("c", comp, promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("blade_chord_cp", [[0.3, 0.2, 0.1, 0.045], [0.0274, 0.0564, 0.02, 0.02]])
    prob.set_val("rotor_radius", [1.5, 1.781])
    prob.run_model()
    expected = [[0.255, 0.155, 0.055, 0.0], [-0.02603, 0.00297, -0.03343, -0.03343]]
    np.testing.assert_allclose(prob.get_val("blade_chord_margin"), expected, atol=1e-12)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)


def test_margin_on_the_control_points_bounds_the_whole_chord_distribution():
    # Convex hull of the B-spline: control points at or above f R give a chord at or above f R
    # at every station (here 200 stations, control points on the bound or just above it).
    radius, ratio = 1.6, 0.03
    cps = np.array([[ratio * radius, 0.2, ratio * radius, ratio * radius + 1e-3]])
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "spline", BsplineComp(num_cp=4, num_points=200, in_name="cp", out_name="y", vec_size=1)
    )
    prob.setup()
    prob.set_val("spline.cp", cps)
    prob.run_model()
    assert np.min(prob.get_val("spline.y")) >= ratio * radius - 1e-14


def test_bad_ratio_is_refused():
    with pytest.raises(ValueError, match="min_chord_radius_ratio"):
        BladeChordMarginComp(num_rotors=1, min_chord_radius_ratio=0.8)
