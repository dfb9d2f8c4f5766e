"""Skin-panel buckling (lpc_mdo.components.structures.buckling): paper eq. 18 and partials."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.structures.buckling import PanelBucklingComp

E, NU = 69.0e9, 0.33


def _run(t, b, r=None, stress=None, panel="curved", k=4.0, nu=NU):
    t = np.atleast_1d(np.asarray(t, dtype=float))
    ne = t.size
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "buckling",
        PanelBucklingComp(num_elements=ne, panel=panel, flat_plate_coefficient=k),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("top_skin_thickness", t)
    prob.set_val("bottom_skin_thickness", 0.5 * t)
    prob.set_val("box_width", b)
    if panel == "curved":
        prob.set_val("top_skin_radius", r)
        prob.set_val("bottom_skin_radius", 2.0 * np.asarray(r))
    if stress is not None:
        prob.set_val("top_skin_stress", stress)
        prob.set_val("bottom_skin_stress", -np.asarray(stress))
    prob.set_val("youngs_modulus", E)
    prob.set_val("poisson_ratio", nu)
    prob.run_model()
    return prob


def test_hand_computed_points():
    # Paper eq. 18 by hand, E = 69 GPa, ν = 0.33: 1 - ν² = 0.8911, E/(6 (1 - ν²)) = 1.29054e10.
    # (t, b, r) = (2 mm, 0.5 m, 2 m): 12(1-ν²)(t/r)² = 1.06932e-5, (πt/b)² = 1.57914e-4,
    #   (πt/b)⁴ = 2.49367e-8, sqrt(...) = 3.27386e-3, σ' = 1.29054e10 (3.27386e-3 + 1.57914e-4)
    #   = 4.42884e7 Pa;
    # (1 mm, 1 m, 4 m): 6.68325e-7, 9.86960e-6, 9.74091e-11, 8.17571e-4 -> σ' = 1.06785e7 Pa;
    # (3 mm, 0.3 m, 1 m): 9.62388e-5, 9.86960e-4, 9.74091e-7, 9.85966e-3 -> σ' = 1.39980e8 Pa.
    # 6 significant digits: 1e-5 relative.
    prob = _run([2e-3, 1e-3, 3e-3], [0.5, 1.0, 0.3], [2.0, 4.0, 1.0])
    assert_near_equal(
        prob.get_val("top_skin_critical_stress"), [4.42884e7, 1.06785e7, 1.39980e8], 1e-5
    )


def test_flat_plate_limit():
    # r -> infinity: eq. 18 -> (π²/3) E/(1 - ν²) (t/b)², the simply supported long plate with
    # k = 4 in σ = k π² E/(12 (1 - ν²)) (t/b)² (Timoshenko & Gere; Roark Table 15.1 case 1a).
    # r = 1e9 m leaves 12(1-ν²)(t/r)² ~ 1e-23 against (πt/b)⁴ ~ 1e-8: 1e-12 relative.
    t, b = np.array([1e-3, 4e-3]), np.array([0.4, 0.9])
    flat = np.pi**2 / 3 * E / (1 - NU**2) * (t / b) ** 2
    assert_near_equal(_run(t, b, [1e9, 1e9]).get_val("top_skin_critical_stress"), flat, 1e-12)
    assert_near_equal(_run(t, b, panel="flat").get_val("top_skin_critical_stress"), flat, 1e-14)
    # aframe's flat panel, σ = 6.3 E (t/b)²/(1 - ν²), is k = 6.3*12/π² here.
    aframe = _run(t, b, panel="flat", k=6.3 * 12 / np.pi**2).get_val("top_skin_critical_stress")
    assert_near_equal(aframe, 6.3 * E * (t / b) ** 2 / (1 - NU**2), 1e-14)


def test_thin_cylinder_limit():
    # (πt/b)² << t/r: σ' -> E t/(r sqrt(3 (1 - ν²))), the classical axially compressed cylinder.
    # t = 1 mm, r = 1 m, b = 10 m: the neglected terms are ~3e-5 of the result.
    sigma = _run(1e-3, 10.0, 1.0).get_val("top_skin_critical_stress")
    assert_near_equal(sigma, [E * 1e-3 / np.sqrt(3 * (1 - NU**2))], 5e-5)


def test_ratio_sign_and_partials():
    # Ratio = -σ/σ': compression (negative stress) gives a positive ratio.
    stress = np.array([-3e7, 1e7, -5e6])
    prob = _run([2e-3, 1e-3, 3e-3], [0.5, 1.0, 0.3], [2.0, 4.0, 1.0], stress=stress)
    crit = prob.get_val("top_skin_critical_stress")
    assert_near_equal(prob.get_val("top_skin_buckling_ratio"), -stress / crit, 1e-14)
    assert prob.get_val("top_skin_buckling_ratio")[0] > 0.0
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-6, rtol=1e-9)


def test_flat_partials():
    prob = _run([2e-3, 1e-3], [0.5, 1.0], stress=[-3e7, 2e7], panel="flat")
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-6, rtol=1e-9)


def test_bad_values():
    with pytest.raises(
        ValueError, match="'flat_plate_coefficient' = -1.0 is out of range: must be > 0"
    ):
        _run(1e-3, 0.5, panel="flat", k=-1.0)
    with pytest.raises(
        om.AnalysisError,
        match=r"'poisson_ratio' = 0.6"
        r" is out of range: must be in \(-1, 0.5\)",
    ):
        _run(1e-3, 0.5, 2.0, nu=0.6)
    with pytest.raises(
        om.AnalysisError,
        match=r"'top_skin_radius\[0\]' = 0.0"
        r" is out of range: must be > 0 \(m\)",
    ):
        _run(1e-3, 0.5, 0.0)
