"""TablePolar, get_polar and the shipped airfoil tables.

Reference: docs theory/aerodynamics 'Airfoil polars'.
"""

import numpy as np
import openmdao.api as om
import pytest

from lpc_mdo.components.aero.airfoil import (
    AIRFOIL_NAMES,
    TablePolar,
    airfoil_table_path,
    get_polar,
)
from lpc_mdo.components.aero.hermite import HermiteAxis
from lpc_mdo.components.aero.polar import LinearQuadraticPolar, viterna, viterna_coefficients

DEG = np.pi / 180.0


def zero_lift_angle(polar, re, mach):
    lo, hi = np.radians(-10.0), np.radians(10.0)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if polar.evaluate(mid, re, mach).cl > 0.0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


# ----------------------------------------------------------------------------- acceptance numbers


def test_naca0012_at_re_1e6_lift_slope_zero_lift_angle_and_minimum_drag():
    polar = get_polar("naca0012")
    a = np.radians(np.linspace(-2.0, 2.0, 9))
    v = polar.evaluate(a, 1e6, 0.0)
    cl_alpha = np.polyfit(a, v.cl, 1)[0]
    assert cl_alpha == pytest.approx(2 * np.pi, rel=0.10)  # measured 6.15 /rad (-2 %)
    assert abs(zero_lift_angle(polar, 1e6, 0.0)) < 1e-12  # symmetric section: exactly 0
    cd_min = polar.evaluate(np.radians(np.linspace(-5, 5, 1001)), 1e6, 0.0).cd.min()
    assert cd_min == pytest.approx(0.0055, rel=0.20)  # measured 0.00540 (-1.8 %)


@pytest.mark.parametrize("name", ["ls413", "ls417"])
def test_cambered_wing_airfoils_have_negative_zero_lift_angle(name):
    polar = get_polar(name)
    for re in (1e6, 5e6):
        a0 = np.degrees(zero_lift_angle(polar, re, 0.2))
        assert -6.0 < a0 < -2.5  # about -4.3 deg


def test_mach_dependence_is_prandtl_glauert_in_attached_flow():
    # NeuralFoil tables (NACA sections): Prandtl-Glauert by construction.
    polar = get_polar("naca0012")
    a = np.radians([2.0, 4.0])
    cl0 = polar.evaluate(a, 3e6, 0.0).cl
    cl5 = polar.evaluate(a, 3e6, 0.5).cl
    np.testing.assert_allclose(cl5, cl0 / np.sqrt(1 - 0.25), rtol=1e-3)
    # Wing sections: XFOIL's Karman-Tsien rule in attached flow (lpc_mdo/data/README.md), within
    # 3 % of Prandtl-Glauert at M 0.5 (measured +2.0 % at 0 deg, +0.4 % at 4 deg).
    polar = get_polar("ls413")
    a = np.radians([0.0, 4.0])
    cl0 = polar.evaluate(a, 3e6, 0.0).cl
    cl5 = polar.evaluate(a, 3e6, 0.5).cl
    np.testing.assert_allclose(cl5, cl0 / np.sqrt(1 - 0.25), rtol=0.03)


# ----------------------------------------------------------------------------- smoothness


@pytest.mark.parametrize("name", AIRFOIL_NAMES)
@pytest.mark.parametrize("re, mach", [(1e6, 0.0), (3e5, 0.2), (7.3e6, 0.37), (1.4e5, 0.55)])
def test_continuity_of_values_and_slopes_at_the_stall_blend_points(name, re, mach):
    """Values and slopes agree on both sides of alpha_s +- eps on both stall sides."""
    polar = get_polar(name)
    lo, hi = (float(x) for x in polar.stall_angles(re, mach)[:2])
    eps, h = polar.blend, 1e-7
    for a in (lo - eps, lo + eps, hi - eps, hi + eps, lo, hi, np.pi / 2, -np.pi / 2, np.pi):
        left = polar.evaluate(np.array([a - h]), re, mach)
        right = polar.evaluate(np.array([a + h]), re, mach)
        for f in ("cl", "cd"):
            assert getattr(left, f)[0] == pytest.approx(getattr(right, f)[0], abs=1e-5)
        for f in ("dcl_dalpha", "dcd_dalpha"):
            assert getattr(left, f)[0] == pytest.approx(getattr(right, f)[0], abs=5e-3)


def test_slopes_are_continuous_everywhere_on_a_fine_sweep():
    """C1 in alpha: the slope never jumps between neighbouring points 1e-4 rad apart."""
    polar = get_polar("ls413")
    a = np.linspace(-np.pi, np.pi, 62832)
    for re, m in ((1e6, 0.1), (2.2e6, 0.33)):
        v = polar.evaluate(a, re, m)
        for f, df in (("cl", "dcl_dalpha"), ("cd", "dcd_dalpha")):
            slope = getattr(v, df)
            # the slope changes by at most curvature * step (curvature < 600 /rad^2 here)
            assert np.max(np.abs(np.diff(slope))) < 0.1
            # and is the derivative of the value (centred difference)
            fd = np.gradient(getattr(v, f), a)
            assert np.max(np.abs(fd - slope)[1:-1]) < 2e-2


@pytest.mark.parametrize("name", ["naca0012", "ls417"])
def test_derivatives_match_complex_step_everywhere(name):
    polar = get_polar(name)
    rng = np.random.default_rng(1)
    n = 4000
    a = rng.uniform(-2 * np.pi, 2 * np.pi, n)
    polar_re, polar_m = polar.table_reynolds, polar.table_mach
    re = 10 ** rng.uniform(np.log10(polar_re[0]), np.log10(polar_re[-1]), n)
    m = rng.uniform(0.0, polar_m[-1], n)  # the whole stated range (to M 0.9 for naca0012)
    v = polar.evaluate(a, re, m)
    h = 1e-30
    for arg, field in ((0, "alpha"), (1, "reynolds"), (2, "mach")):
        args = [a.astype(complex), re.astype(complex), m.astype(complex)]
        step = h * (re if arg == 1 else 1.0)
        args[arg] = args[arg] + 1j * step
        cs = polar.evaluate(*args)
        for f in ("cl", "cd"):
            np.testing.assert_allclose(
                getattr(cs, f).imag / step, getattr(v, f"d{f}_d{field}"), rtol=1e-9, atol=1e-12
            )
    assert np.all(v.cd > 0.0)


def test_table_slice_is_reproduced_at_grid_conditions():
    polar = get_polar("naca0012")
    data = np.load(airfoil_table_path("naca0012"))
    j, k = 4, 2  # Re 1e6, M 0.2
    a = np.radians(data["alpha_deg"])
    lo, hi = polar.alpha_stall[:, j, k]
    inside = (a > lo + polar.blend) & (a < hi - polar.blend)
    v = polar.evaluate(a[inside], data["reynolds"][j], data["mach"][k])
    np.testing.assert_allclose(v.cl, data["cl"][inside, j, k], atol=1e-12)
    np.testing.assert_allclose(v.cd, data["cd"][inside, j, k], atol=1e-12)


def test_post_stall_is_viterna_from_the_table_stall_point_and_reverse_flow_is_periodic():
    polar = get_polar("ls417")
    j, k = 5, 1
    re, m = polar.table_reynolds[j], polar.table_mach[k]
    a_s, cl_s, cd_s = (x[1, j, k] for x in (polar.alpha_stall, polar.cl_stall, polar.cd_stall))
    a2, b2 = viterna_coefficients(a_s, cl_s, cd_s, 1.29)
    a = np.radians(np.array([30.0, 45.0, 60.0, 75.0]))
    ref = viterna(a, 1.29, a2, b2)
    v = polar.evaluate(a, re, m)
    np.testing.assert_allclose(v.cl, ref[0], atol=1e-6)
    np.testing.assert_allclose(v.cd, ref[1], atol=1e-6)
    v90 = polar.evaluate(np.array([np.pi / 2, -np.pi / 2]), re, m)
    np.testing.assert_allclose(v90.cd, 1.29, atol=1e-6)
    wrap = polar.evaluate(np.array([np.pi - 1e-9, -np.pi + 1e-9, 3 * np.pi]), re, m)
    assert wrap.cl[0] == pytest.approx(wrap.cl[1], abs=1e-7)
    assert wrap.cd[0] == pytest.approx(wrap.cd[1], abs=1e-7)
    assert wrap.cd[2] == pytest.approx(wrap.cd[0], abs=1e-7)


def test_stall_points_are_the_first_dominant_extrema_of_each_slice():
    polar = get_polar("naca0012")
    data = np.load(airfoil_table_path("naca0012"))
    a = data["alpha_deg"]
    for j in range(len(data["reynolds"])):
        cl = data["cl"][:, j, 0]
        hi = np.degrees(polar.alpha_stall[1, j, 0])
        i = int(np.flatnonzero(np.isclose(a, hi))[0])
        ahead = (a > hi) & (a <= hi + 3.0)
        assert cl[i] >= cl[ahead].max()
        if data["reynolds"][j] >= 1e5:  # rising up to it (below Re 1e5 the laminar separation
            # of the NACA 0012 gives NeuralFoil's nonlinear lift near 0 deg: cl slightly
            # negative at 0.5-1 deg at Re 5e4, nearly flat to 3 deg at Re 2e4)
            assert np.all(np.diff(cl[(a >= 0) & (a <= hi)]) > 0.0)
    # symmetric section: symmetric stall angles; stall angle grows with Re
    np.testing.assert_allclose(polar.alpha_stall[0], -polar.alpha_stall[1])
    assert np.all(np.diff(polar.alpha_stall[1, :, 0]) >= 0.0)


@pytest.mark.parametrize(
    ("name", "re", "mach", "what"),
    [
        ("naca0012", 1e6, 0.91, "Mach number"),  # beyond the rotor table's M 0.9
        ("naca0012", 2e7, 0.3, "Reynolds number"),  # above its Re 1e7
        ("naca0012", -1.0, 0.3, "Reynolds number"),
        ("naca0012", 1e6, -0.1, "Mach number"),
        ("ls413", 1e6, 0.65, "Mach number"),  # the wing table stops at M 0.6
        ("ls413", 1.2e7, 0.2, "Reynolds number"),
    ],
)
def test_queries_outside_the_stated_range_raise_an_analysis_error(name, re, mach, what):
    # No value is held at a table edge: outside its grid the polar names itself, the value
    # and the range (TablePolar 'Stated range'); every entry point checks (evaluate, the
    # complex-step path, stall angles, the moment table).
    polar = get_polar(name)
    a = np.radians([3.0, 4.0])
    with pytest.raises(om.AnalysisError, match=rf"'{name}': {what}.*table holds for"):
        polar.evaluate(a, re, mach)
    with pytest.raises(om.AnalysisError, match=what):
        polar.evaluate(a.astype(complex), complex(re), complex(mach))
    with pytest.raises(om.AnalysisError, match=what):
        polar.stall_angles(re, mach)
    with pytest.raises(om.AnalysisError, match=what):
        polar.moment_coefficient(a, re, mach)
    # The edges themselves are inside.
    edge_re = np.clip(re, polar.table_reynolds[0], polar.table_reynolds[-1])
    edge_m = np.clip(mach, polar.table_mach[0], polar.table_mach[-1])
    assert np.all(np.isfinite(polar.evaluate(a, edge_re, edge_m).cl))


def test_below_the_lowest_reynolds_number_the_lowest_slice_is_used():
    # The stated low-Re rule (TablePolar 'Stated range'): sections at almost no relative
    # velocity (reverse-flow boundary of an edgewise rotor) take the lowest slice, with zero
    # Reynolds derivative; no error, down to Re 0.
    polar = get_polar("naca0012")
    a = np.radians([2.0, 6.0])
    low = polar.evaluate(a, polar.table_reynolds[0], 0.3)
    for re in (1e4, 10.0, 0.0):
        v = polar.evaluate(a, re, 0.3)
        np.testing.assert_allclose(v.cl, low.cl, rtol=1e-14)
        np.testing.assert_array_equal(v.dcl_dreynolds, 0.0)


def test_single_slice_user_table_holds_for_every_condition():
    a_deg, cl, cd = _lq_table()
    polar = TablePolar.from_alpha_cl_cd(a_deg, cl, cd)
    v = polar.evaluate(np.radians(3.0), 1e3, 0.95)
    assert np.isfinite(v.cl) and v.dcl_dmach == 0.0 and v.dcl_dreynolds == 0.0


# ------------------------------------------------------------------ compressibility (rotor table)


def test_rotor_table_lift_follows_prandtl_glauert_to_mach_0_9():
    # Independent number: the Prandtl-Glauert factor 1/sqrt(1 - M^2) (Anderson, Fundamentals of
    # Aerodynamics, sec. 11.4), 2.294 at M 0.9, on the stored incompressible (M = 0) slice, at
    # every tabulated Mach number and Reynolds number; exact to round-off by construction of the
    # table (docs theory/aerodynamics 'Airfoil polars').
    data = np.load(airfoil_table_path("naca0012"))
    mach = data["mach"]
    assert mach[-1] == pytest.approx(0.9) and data["reynolds"][0] == pytest.approx(2e4)
    factor = 1.0 / np.sqrt(1.0 - mach**2)
    assert factor[-1] == pytest.approx(2.2942, abs=1e-4)
    np.testing.assert_allclose(data["cl"], data["cl"][..., :1] * factor, rtol=1e-12, atol=1e-14)


def test_rotor_table_drag_rise_is_korn_and_lock():
    # Independent numbers, by hand: NACA 0012 (t/c 0.12), conventional section kappa_A = 0.87
    # (Mason, Configuration Aerodynamics ch. 7): at c_l = 0 Korn gives M_dd = 0.75 and Lock
    # M_crit = 0.75 - (0.1/80)^(1/3) = 0.64228; at M 0.8 the wave drag is
    # 20 (0.8 - 0.64228)^4 = 0.012376, at M 0.85 0.037236, at M 0.9 0.088234. The table's cd at
    # 0 deg (c_l = 0 on the symmetric section) minus its incompressible value must be these
    # (1e-6), and zero below M_crit (M <= 0.6).
    data = np.load(airfoil_table_path("naca0012"))
    i0 = int(np.argmin(np.abs(data["alpha_deg"])))
    mach = data["mach"]
    increment = data["cd"][i0] - data["cd"][i0, :, :1]  # (n_re, n_m)
    hand = {0.8: 0.012376, 0.85: 0.037236, 0.9: 0.088234}
    for m, value in hand.items():
        k = int(np.flatnonzero(np.isclose(mach, m))[0])
        np.testing.assert_allclose(increment[:, k], value, atol=2e-6)
    np.testing.assert_array_equal(increment[:, mach <= 0.6], 0.0)
    # With lift the divergence comes earlier: at c_l 0.5 M_dd = 0.70 and the drag-rise slope
    # dc_d,w/dM = 80 (M - M_crit)^3 is 0.1 exactly there (the definition Lock's law encodes).
    m_crit = 0.87 - 0.12 - 0.05 - (0.1 / 80.0) ** (1.0 / 3.0)
    assert 80.0 * (0.70 - m_crit) ** 3 == pytest.approx(0.1, rel=1e-12)


def test_rotor_polar_charges_the_drag_rise_between_table_nodes():
    # The run-time polar interpolates the table in M: at 0 deg, Re 1e6 the drag at M 0.825
    # lies between its neighbours' and within 10 % of the law (cd_0 + 20 (M - M_crit)^4), and
    # the drag-rise slope dcd/dM is positive from M_crit on.
    polar = get_polar("naca0012")
    m = np.array([0.7, 0.75, 0.8, 0.825, 0.85, 0.9])
    v = polar.evaluate(np.zeros_like(m), 1e6, m)
    cd0 = polar.evaluate(0.0, 1e6, 0.0).cd
    law = cd0 + 20.0 * np.maximum(m - 0.64228, 0.0) ** 4
    np.testing.assert_allclose(v.cd, law, rtol=0.10)
    assert np.all(np.diff(v.cd) > 0.0) and np.all(v.dcd_dmach > 0.0)


# ----------------------------------------------------------------------------- user tables


def _lq_table(step=1.0):
    lq = LinearQuadraticPolar()
    a_deg = np.arange(-20.0, 25.0 + 1e-9, step)
    v = lq.evaluate(np.radians(a_deg), 1e6, 0.0)
    return a_deg, v.cl, v.cd


def test_user_table_as_array_dict_and_text_file(tmp_path):
    a_deg, cl, cd = _lq_table()
    from_array = get_polar(np.column_stack([a_deg, cl, cd]))
    from_dict = get_polar({"alpha_deg": a_deg, "cl": cl, "cd": cd, "name": "lq"})
    path = tmp_path / "polar.txt"
    lines = [
        "  XFOIL-like header",
        "   alpha    CL        CD       CDp       CM",
        "  ------ -------- --------- --------- --------",
    ]
    lines += [
        f"{x:8.3f} {y:9.5f} {z:9.6f} 0.0 -0.05" for x, y, z in zip(a_deg, cl, cd, strict=True)
    ]
    path.write_text("\n".join(lines) + "\n")
    from_file = get_polar(path)
    a = np.radians(np.array([-7.0, 0.0, 3.3, 9.0]))
    ref = from_array.evaluate(a, 3e6, 0.3)
    for p in (from_dict, from_file):
        v = p.evaluate(a, 3e6, 0.3)
        np.testing.assert_allclose(v.cl, ref.cl, atol=2e-5)
        np.testing.assert_allclose(v.cd, ref.cd, atol=2e-6)
    # the table reproduces its source in attached flow; Re and Mach derivatives are zero
    np.testing.assert_allclose(ref.cl, 0.5 + 5.1566 * a, atol=1e-9)
    assert np.all(ref.dcl_dreynolds == 0.0) and np.all(ref.dcd_dmach == 0.0)
    # stall points from the table: the source's cl extrema lie inside its +-1.5 deg stall blends
    # around -10 and 15 deg (its negative blend overshoots to -12 deg)
    lo, hi = (float(x) for x in from_array.stall_angles(1e6, 0.0)[:2])
    assert -13.0 <= np.degrees(lo) <= -9.0 and 14.0 <= np.degrees(hi) <= 17.0


def test_npz_user_table_with_reynolds_axis(tmp_path):
    shipped = np.load(airfoil_table_path("ls417"))
    path = tmp_path / "my_airfoil.npz"
    np.savez(
        path,
        alpha_deg=shipped["alpha_deg"],
        reynolds=shipped["reynolds"],
        mach=shipped["mach"],
        cl=shipped["cl"],
        cd=shipped["cd"],
    )
    mine, ref = get_polar(str(path)), get_polar("ls417")
    a = np.radians([-3.0, 5.0, 40.0])
    np.testing.assert_allclose(mine.evaluate(a, 2.5e6, 0.15).cl, ref.evaluate(a, 2.5e6, 0.15).cl)
    assert mine.pressure is None


def test_names_aliases_and_passthrough():
    assert get_polar("GA(W)-2") is get_polar("ls413")
    assert get_polar("LS(1)-0417") is get_polar("ls417")
    lq = LinearQuadraticPolar()
    assert get_polar(lq) is lq
    assert get_polar("ls413").pressure is not None
    assert get_polar("naca0012").pressure is None


def test_bad_tables_are_named():
    with pytest.raises(ValueError, match=r"airfoil = 'naca4412'; allowed: naca0012"):
        get_polar("naca4412")
    a_deg, cl, cd = _lq_table()
    with pytest.raises(ValueError, match=r"cd = min .*; allowed: > 0"):
        get_polar(np.column_stack([a_deg, cl, -cd]))
    with pytest.raises(ValueError, match="degrees"):
        get_polar(np.column_stack([np.radians(a_deg[:3]), cl[:3], cd[:3]]))
    with pytest.raises(ValueError, match="negative stall"):
        get_polar(np.column_stack([a_deg[a_deg >= 0], cl[a_deg >= 0], cd[a_deg >= 0]]))
    with pytest.raises(ValueError, match=r"shape \(4, 2\)"):
        get_polar(np.ones((4, 2)))


# ----------------------------------------------------------------------------- interpolation core


def test_hermite_axis_reproduces_quadratics_and_their_derivatives():
    x = np.array([0.0, 0.3, 0.5, 1.2, 2.0, 2.1])
    axis = HermiteAxis(x)
    f = 1.0 - 2.0 * x + 0.7 * x**2
    q = np.linspace(-0.5, 2.6, 301)
    index, w, dw, d2w = axis.weights(q, second=True)
    value = np.sum(w * f[index], axis=1)
    inside = (q > 0) & (q < 2.1)
    qc = np.clip(q, 0.0, 2.1)
    np.testing.assert_allclose(value, 1.0 - 2.0 * qc + 0.7 * qc**2, atol=1e-12)
    np.testing.assert_allclose(
        np.sum(dw * f[index], axis=1)[inside], (-2.0 + 1.4 * q)[inside], atol=1e-12
    )
    np.testing.assert_allclose(np.sum(d2w * f[index], axis=1)[inside], 1.4, atol=1e-9)
    assert np.all(np.sum(dw * f[index], axis=1)[~inside] == 0.0)


def test_hermite_axis_small_grids():
    one = HermiteAxis([5.0])
    index, w, dw = one.weights(np.array([1.0, 7.0]))
    assert np.all(index == 0) and np.all(w == 1.0) and np.all(dw == 0.0)
    two = HermiteAxis([1.0, 3.0], log=True)
    index, w, dw = two.weights(np.array([2.0]))
    f = np.log(np.array([1.0, 3.0]))  # linear in ln x is reproduced exactly
    assert np.sum(w * f[index]) == pytest.approx(np.log(2.0))
    assert np.sum(dw * f[index]) == pytest.approx(0.5)


def test_table_polar_validates_its_input():
    a = np.radians(np.arange(-10.0, 11.0))
    with pytest.raises(ValueError, match="strictly increasing"):
        TablePolar(a[::-1], [1e6], [0.0], 0.1 * a, 0.01 + 0 * a)
    with pytest.raises(ValueError, match=r"cl shape"):
        TablePolar(a, [1e6, 2e6], [0.0], 0.1 * a, 0.01 + 0 * a)


def test_repeated_conditions_reuse_the_cached_re_mach_contraction():
    # The fixed-condition cache (blade-element solvers evaluate the polar many times at the same
    # Reynolds and Mach numbers) gives the uncached tensor-product sums to round-off: a first
    # call, a call whose angles moved within their alpha windows and one whose angles moved to
    # other windows; the complex (complex-step) path never uses the cache. Pickling drops it.
    import pickle

    from lpc_mdo.components.aero.airfoil import _alpha_hermite_weights, wrap_angle
    from lpc_mdo.components.aero.hermite import tensor_eval

    polar = TablePolar.from_npz(airfoil_table_path("ls417"))
    rng = np.random.default_rng(3)
    n = 400
    re, mach = rng.uniform(2e5, 8e6, n), rng.uniform(0.0, 0.6, n)
    alpha0 = rng.uniform(-0.4, 0.5, n)
    for alpha in (alpha0, alpha0 + 1e-6, alpha0 + 0.3, alpha0 - 3.0):
        got = polar.evaluate(alpha, re, mach)
        (ir, wr, dwr), (im, wm, dwm) = polar._conditions(re, mach)
        ia, wa, dwa = _alpha_hermite_weights(polar.alpha_grid, wrap_angle(alpha))
        v, d_a, d_r, d_m = tensor_eval(
            polar._composite_table, (ia, ir, im), (wa, wr, wm), (dwa, dwr, dwm)
        )
        for f, name in enumerate(("cl", "cd")):  # d/dRe as d/dln(Re): all of order 1
            for value, ref in (
                (getattr(got, name), v[:, f]),
                (getattr(got, f"d{name}_dalpha"), d_a[:, f]),
                (getattr(got, f"d{name}_dreynolds") * re, d_r[:, f] * re),
                (getattr(got, f"d{name}_dmach"), d_m[:, f]),
            ):
                # round-off of two summation orders (1.1e-13 measured on a d/dalpha of 7)
                np.testing.assert_allclose(value, ref, rtol=1e-12, atol=1e-12)
    assert len(polar._condition_caches) == 1
    complex_values = polar.evaluate(alpha0 + 0j, re + 0j, mach)
    np.testing.assert_allclose(
        np.real(complex_values.cl), polar.evaluate(alpha0, re, mach).cl, rtol=1e-12
    )
    assert "_condition_caches" not in pickle.loads(pickle.dumps(polar)).__dict__


def test_condition_caches_outlast_a_model_pass(monkeypatch):
    # One pass over the LPC model queries a polar at about 40 sets of (Re, M); a second pass
    # (the linearization after a run) must find every set still contracted. 60 sets evaluated
    # twice: 60 contractions, none in the second pass; beyond the bound the oldest set goes.
    import lpc_mdo.components.aero.airfoil as airfoil

    polar = TablePolar.from_npz(airfoil_table_path("ls417"))
    made = [0]
    original = airfoil._FixedConditions.__init__

    def counted(self, *args):
        made[0] += 1
        original(self, *args)

    monkeypatch.setattr(airfoil._FixedConditions, "__init__", counted)
    alpha = np.linspace(-0.2, 0.3, 25)
    sets = [(np.full(25, 1e5 * (1 + k)), np.full(25, 0.01 * k)) for k in range(60)]
    first = [polar.evaluate(alpha, re, mach).cl for re, mach in sets]
    second = [polar.evaluate(alpha, re, mach).cl for re, mach in sets]
    assert made[0] == 60
    for a, b in zip(first, second, strict=True):
        np.testing.assert_array_equal(a, b)
    monkeypatch.setattr(airfoil, "_CONDITION_CACHE_SIZE", 50)
    polar.evaluate(alpha, np.full(25, 8e6), np.zeros(25))  # a new set: 11 oldest evicted
    assert len(polar._condition_caches) == 50
    polar.evaluate(alpha, *sets[0])
    assert made[0] == 62
