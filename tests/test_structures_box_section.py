"""Box cross-section (lpc_mdo.components.structures.box_section): closed forms and partials."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.structures.box_section import BoxSectionComp


def _run(width, height, top, bottom, front, rear, torsion_formula="polar"):
    width = np.atleast_1d(np.asarray(width, dtype=float))
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "box",
        BoxSectionComp(num_elements=width.size, torsion_formula=torsion_formula),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    for name, val in (
        ("box_width", width),
        ("box_height", height),
        ("top_skin_thickness", top),
        ("bottom_skin_thickness", bottom),
        ("front_spar_thickness", front),
        ("rear_spar_thickness", rear),
    ):
        prob.set_val(name, val)
    prob.run_model()
    return prob


def test_uniform_wall_box_is_exact_hollow_rectangle():
    # With equal walls t the neutral-axis shift vanishes and the section is a hollow rectangle:
    # A = w h - (w - 2t)(h - 2t), I_y = (w h³ - (w - 2t)(h - 2t)³)/12,
    # I_z = (h w³ - (h - 2t)(w - 2t)³)/12 (exact; 1e-12 relative).
    w, h, t = np.array([0.8, 0.5]), np.array([0.25, 0.12]), np.array([4e-3, 1e-3])
    prob = _run(w, h, t, t, t, t)
    assert_near_equal(prob.get_val("area"), w * h - (w - 2 * t) * (h - 2 * t), 1e-12)
    assert_near_equal(
        prob.get_val("bending_inertia_vertical"),
        (w * h**3 - (w - 2 * t) * (h - 2 * t) ** 3) / 12,
        1e-12,
    )
    assert_near_equal(
        prob.get_val("bending_inertia_inplane"),
        (h * w**3 - (h - 2 * t) * (w - 2 * t) ** 3) / 12,
        1e-12,
    )
    # Polar torsion constant (reference model): J = I_y + I_z.
    assert_near_equal(
        prob.get_val("torsion_constant"),
        prob.get_val("bending_inertia_vertical") + prob.get_val("bending_inertia_inplane"),
        1e-14,
    )
    assert_near_equal(prob.get_val("web_thickness"), t, 1e-15)


def test_bredt_torsion_constant_closed_forms():
    # Square thin-walled tube of uniform t: Bredt J = 4 A_m² t/perimeter = t b_m³, b_m = b - t.
    b, t = 0.3, 2e-3
    prob = _run(b, b, t, t, t, t, torsion_formula="bredt")
    assert_near_equal(prob.get_val("torsion_constant"), [t * (b - t) ** 3], 1e-12)
    # Rectangle with skins t_c and webs t_w: equals the Bredt form quoted in
    # docs theory/structures 'Box section',
    # J = 2 t_w t_c (w - t_w)² (h - t_c)²/(w t_w + h t_c - t_w² - t_c²).
    w, h, tc, tw = 0.8087064, 0.26502895, 6.5e-3, 0.3e-3
    prob = _run(w, h, tc, tc, tw, tw, torsion_formula="bredt")
    ref = 2 * tw * tc * (w - tw) ** 2 * (h - tc) ** 2 / (w * tw + h * tc - tw**2 - tc**2)
    assert_near_equal(prob.get_val("torsion_constant"), [ref], 1e-12)
    # ... and it is about 9x softer than the polar approximation for this root bay.
    polar = _run(w, h, tc, tc, tw, tw).get_val("torsion_constant")[0]
    assert 8.0 < polar / ref < 10.0


def test_neutral_axis_shift_as_coded():
    # Unequal skins: the reference's z_c = (t_top - t_bot)(w - 2 t_web)/w enters I_y
    # (docs theory/structures 'Box section');
    # hand computation for w = 0.5, h = 0.2, t_top = 4 mm, t_bot = 2 mm, t_web = 1 mm:
    # z_c = 0.002*0.498/0.5 = 1.992e-3; d_top = 0.1 - 0.002 - z_c = 0.096008,
    # d_bot = -0.1 + 0.001 - z_c = -0.100992, h_w = 0.194;
    # I_y = 0.5*0.004³/12 + 0.5*0.004*0.096008² + 0.5*0.002³/12 + 0.5*0.002*0.100992²
    #       + 2*(0.001*0.194³/12 + 0.001*0.194*z_c²) = 2.98559e-5 m⁴.
    z_c = 0.002 * 0.498 / 0.5
    d_top, d_bot, h_w = 0.1 - 0.002 - z_c, -0.1 + 0.001 - z_c, 0.194
    i_y = (
        0.5 * 0.004**3 / 12
        + 0.5 * 0.004 * d_top**2
        + 0.5 * 0.002**3 / 12
        + 0.5 * 0.002 * d_bot**2
        + 2 * (0.001 * h_w**3 / 12 + 0.001 * h_w * z_c**2)
    )
    prob = _run(0.5, 0.2, 4e-3, 2e-3, 1.5e-3, 0.5e-3)  # spars average to t_web = 1 mm
    assert_near_equal(prob.get_val("bending_inertia_vertical"), [i_y], 1e-12)
    assert_near_equal(prob.get_val("web_thickness"), [1e-3], 1e-15)


@pytest.mark.parametrize("torsion_formula", ["polar", "bredt"])
def test_partials(torsion_formula):
    rng = np.random.default_rng(0)
    prob = _run(
        rng.uniform(0.3, 1.0, 4),
        rng.uniform(0.08, 0.3, 4),
        rng.uniform(3e-4, 8e-3, 4),
        rng.uniform(3e-4, 8e-3, 4),
        rng.uniform(3e-4, 5e-3, 4),
        rng.uniform(3e-4, 5e-3, 4),
        torsion_formula,
    )
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-14, rtol=1e-9)


def test_walls_must_fit():
    with pytest.raises(om.AnalysisError, match="walls do not fit"):
        _run(0.5, 0.01, 6e-3, 6e-3, 1e-3, 1e-3)
    with pytest.raises(
        om.AnalysisError,
        match=r"'top_skin_thickness\[.*\]' = -0\.001"
        r" is out of range",
    ):
        _run(0.5, 0.2, -1e-3, 1e-3, 1e-3, 1e-3)
