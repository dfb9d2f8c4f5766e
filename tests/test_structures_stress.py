"""Box stress recovery (lpc_mdo.components.structures.stress): closed forms and partials."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.structures.stress import BoxStressComp

W, H, T_TOP, T_BOT, T_WEB = 0.6, 0.18, 4e-3, 3e-3, 1e-3
AREA, I_Y, I_Z, J = 5e-3, 6e-5, 3e-4, 3.6e-4


def _run(forces, moments, torsion_formula="polar", web_points="one", allowable=350e6):
    forces = np.atleast_2d(forces).astype(float)
    ne = forces.shape[0]
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "stress",
        BoxStressComp(num_elements=ne, torsion_formula=torsion_formula, web_points=web_points),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("section_forces", forces)
    prob.set_val("section_moments", np.atleast_2d(moments))
    for name, val in (
        ("box_width", W),
        ("box_height", H),
        ("top_skin_thickness", T_TOP),
        ("bottom_skin_thickness", T_BOT),
        ("web_thickness", T_WEB),
        ("area", AREA),
        ("bending_inertia_vertical", I_Y),
        ("bending_inertia_inplane", I_Z),
    ):
        prob.set_val(name, np.full(ne, val))
    if torsion_formula == "polar":
        prob.set_val("torsion_constant", np.full(ne, J))
    prob.set_val("allowable_stress", allowable)
    prob.run_model()
    return prob


def test_axial_and_bending_closed_forms():
    # σ = N/A + M_y z/I_y - M_z y/I_z at (y, z) = corners (±W/2, ±H/2) and the web (W/2, 0);
    # no shear, so σ_vm = |σ| (up to the 1e-8 Pa² regularisation; 1e-12 relative).
    n, my, mz = 2.0e5, 3.0e4, -1.0e4
    prob = _run([n, 0.0, 0.0], [0.0, my, mz])
    y = np.array([-1, 1, 1, -1, 1]) * W / 2
    z = np.array([-1, -1, 1, 1, 0]) * H / 2
    sigma = n / AREA + my * z / I_Y - mz * y / I_Z
    assert_near_equal(prob.get_val("von_mises_stress")[0], np.abs(sigma), 1e-12)
    # Skin stresses: outer fibre, width average: N/A ∓ M_y (H/2)/I_y (top = -z side).
    assert_near_equal(prob.get_val("top_skin_stress"), [n / AREA - my * H / 2 / I_Y], 1e-12)
    assert_near_equal(prob.get_val("bottom_skin_stress"), [n / AREA + my * H / 2 / I_Y], 1e-12)
    assert_near_equal(prob.get_val("stress_ratio"), prob.get_val("von_mises_stress") / 350e6, 1e-14)


def test_torsion_polar_and_bredt():
    torque = 5.0e3
    # Polar (reference model): τ = M_x r/J, r = corner distance or W/2 at the web;
    # σ_vm = sqrt(3) τ.
    vm = _run([0, 0, 0], [torque, 0, 0]).get_val("von_mises_stress")[0]
    r = np.array([np.hypot(W, H) / 2] * 4 + [W / 2])
    assert_near_equal(vm, np.sqrt(3) * torque * r / J, 1e-12)
    # Bredt: τ = T/(2 A_m t), A_m = (W - t_web)(H - (t_top + t_bot)/2), t of the wall at the
    # point (top skin for 0, 1; bottom skin for 2, 3; web for 4).
    a_m = (W - T_WEB) * (H - 0.5 * (T_TOP + T_BOT))
    walls = np.array([T_TOP, T_TOP, T_BOT, T_BOT, T_WEB])
    vm = _run([0, 0, 0], [torque, 0, 0], "bredt").get_val("von_mises_stress")[0]
    assert_near_equal(vm, np.sqrt(3) * torque / (2 * a_m * walls), 1e-12)


def test_transverse_shear_and_both_webs():
    # Web shear τ_s = V_z Q/(2 t_web I_y), Q = W t_cap H/2 + t_web H²/4, t_cap = mean skin
    # (docs theory/structures 'Stress', main branch); corners carry no transverse shear.
    # With a torque the shear flows add on the web at +W/2 (point 4) and subtract at -W/2 (point 5).
    v, torque = 4.0e4, 2.0e3
    q = W * 0.5 * (T_TOP + T_BOT) * H / 2 + T_WEB * H**2 / 4
    tau_s = v * q / (2 * T_WEB * I_Y)
    tau_t = torque * (W / 2) / J
    vm = _run([0, 0, v], [torque, 0, 0], web_points="both").get_val("von_mises_stress")[0]
    assert_near_equal(vm[4:], np.sqrt(3) * np.abs([tau_s + tau_t, tau_s - tau_t]), 1e-12)
    assert_near_equal(vm[:4], np.sqrt(3) * torque * np.hypot(W, H) / 2 / J * np.ones(4), 1e-12)


@pytest.mark.parametrize("torsion_formula", ["polar", "bredt"])
@pytest.mark.parametrize("web_points", ["one", "both"])
def test_partials(torsion_formula, web_points):
    rng = np.random.default_rng(2)
    prob = _run(
        rng.normal(size=(3, 3)) * 1e4, rng.normal(size=(3, 3)) * 1e4, torsion_formula, web_points
    )
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    # Stresses are ~1e8 Pa and the partials up to ~1e12: 1e-3 absolute is round-off.
    assert_check_partials(data, atol=1e-3, rtol=1e-9)


def test_bad_input():
    with pytest.raises(
        om.AnalysisError,
        match=r"'allowable_stress' = 0.0"
        r" is out of range: must be > 0 \(Pa\)",
    ):
        _run([1, 0, 0], [0, 0, 0], allowable=0.0)
