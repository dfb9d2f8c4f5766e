"""Tests for lpc_mdo.components.bspline.BsplineComp."""

from math import comb

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_near_equal,
)
from sparsity import assert_sparsity_matches

from lpc_mdo.components.bspline import BsplineComp, clamped_knots


def _run(cp, in_name="control_points", out_name="curve", **options):
    cp = np.atleast_2d(np.asarray(cp, dtype=float))
    prob = om.Problem()
    prob.model.add_subsystem(
        "spline",
        BsplineComp(
            num_cp=cp.shape[1], vec_size=cp.shape[0], in_name=in_name, out_name=out_name, **options
        ),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val(in_name, cp)
    prob.run_model()
    return prob


def _bezier(cp, x):
    """Bernstein form of a Bezier curve: sum_i C(n,i) x^i (1-x)^(n-i) cp_i (closed form)."""
    n = cp.shape[-1] - 1
    bern = np.stack([comb(n, i) * x**i * (1.0 - x) ** (n - i) for i in range(n + 1)], axis=-1)
    return cp @ bern.T


# Example chord control points (m) for 5 rotors; values only need to be generic.
CP5 = np.random.default_rng(1).uniform(0.05, 0.3, size=(5, 4))


@pytest.mark.parametrize(
    "num_cp, order, vec_size", [(4, 4, 1), (4, 4, 5), (7, 4, 3), (6, 3, 2), (5, 2, 2)]
)
def test_partials(num_cp, order, vec_size):
    cp = np.random.default_rng(2).normal(size=(vec_size, num_cp))
    prob = _run(cp, order=order, num_points=11)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)
    assert_sparsity_matches(prob, "spline")


def test_cubic_four_cp_is_bezier():
    # 4 control points, order 4, knots [0,0,0,0,1,1,1,1]: single cubic Bezier segment
    # (docs theory/rotors 'Blade parameterization'). Closed-form Bernstein comparison,
    # 1e-12 absolute.
    x = np.array([0.0, 0.1, 0.25, 1.0 / 3.0, 0.5, 0.77, 0.9, 1.0])
    prob = _run(CP5, num_points=x.size, x_interp=x, units="m")
    np.testing.assert_allclose(prob.get_val("curve"), _bezier(CP5, x), rtol=0.0, atol=1e-12)


def test_default_stations_uniform():
    # Default stations: linspace(0, 1, num_points) (docs theory/rotors 'Blade parameterization').
    # Bernstein closed form, 1e-12 absolute.
    prob = _run(CP5, num_points=25)
    x = np.linspace(0.0, 1.0, 25)
    np.testing.assert_allclose(prob.model.spline.x_interp, x, rtol=0.0, atol=0.0)
    np.testing.assert_allclose(prob.get_val("curve"), _bezier(CP5, x), rtol=0.0, atol=1e-12)


@pytest.mark.parametrize("num_cp, order", [(4, 4), (8, 4), (5, 3), (6, 2)])
def test_endpoint_interpolation(num_cp, order):
    # Clamped knots interpolate the end control points exactly (to round-off, 1e-14).
    cp = np.random.default_rng(4).normal(size=(3, num_cp))
    curve = _run(cp, order=order, num_points=9).get_val("curve")
    np.testing.assert_allclose(curve[:, 0], cp[:, 0], rtol=0.0, atol=1e-14)
    np.testing.assert_allclose(curve[:, -1], cp[:, -1], rtol=0.0, atol=1e-14)


def test_linear_control_points_give_linear_curve():
    # num_cp = order = 4: equally spaced control points give an exactly linear curve
    # (linear precision of B-splines; docs theory/rotors 'Blade parameterization'). y = 0.3 - 0.2 x,
    # 1e-14 absolute.
    cp = np.linspace(0.3, 0.1, 4)
    x = np.linspace(0.0, 1.0, 13)
    curve = _run(cp, num_points=x.size).get_val("curve")[0]
    np.testing.assert_allclose(curve, 0.3 - 0.2 * x, rtol=0.0, atol=1e-14)


def test_linear_precision_greville():
    # General clamped spline: cp_j = a + b * Greville abscissa_j reproduces a + b x exactly
    # (de Boor, A Practical Guide to Splines, linear precision), 1e-14 absolute.
    num_cp, order = 9, 4
    t = clamped_knots(num_cp, order)
    greville = np.array([t[j + 1 : j + order].mean() for j in range(num_cp)])
    x = np.random.default_rng(5).uniform(0.0, 1.0, 17)
    curve = _run(2.0 - 3.0 * greville, order=order, num_points=x.size, x_interp=x).get_val("curve")[
        0
    ]
    np.testing.assert_allclose(curve, 2.0 - 3.0 * x, rtol=0.0, atol=1e-14)


def test_partition_of_unity():
    # Constant control points give a constant curve (basis sums to one), 1e-14 absolute.
    curve = _run(np.full((2, 6), 0.7), order=4, num_points=15).get_val("curve")
    np.testing.assert_allclose(curve, 0.7, rtol=0.0, atol=1e-14)


def test_custom_names_and_units():
    # Twist control points in degrees, read back in radians: exact linear unit conversion.
    cp = np.array([[20.0, 15.0, 8.0, 2.0]])
    prob = _run(cp, in_name="twist_cp", out_name="twist", units="deg", num_points=5)
    assert_near_equal(
        prob.get_val("twist", units="rad"), np.deg2rad(prob.get_val("twist")), tolerance=1e-14
    )
    assert_near_equal(prob.get_val("twist")[0, [0, -1]], [20.0, 2.0], tolerance=1e-14)


def test_num_cp_less_than_order_raises():
    prob = om.Problem()
    prob.model.add_subsystem("spline", BsplineComp(num_cp=3, order=4))
    with pytest.raises(
        ValueError,
        match=r"'num_cp' = 3"
        r" is out of range: must be >= option 'order' = 4",
    ):
        prob.setup()


def test_x_interp_wrong_length_raises():
    prob = om.Problem()
    prob.model.add_subsystem("spline", BsplineComp(num_points=5, x_interp=[0.0, 0.5, 1.0]))
    with pytest.raises(ValueError, match=r"'num_points' = 5\): 'x_interp' must have shape \(5,\)"):
        prob.setup()


def test_x_interp_out_of_range_raises():
    prob = om.Problem()
    prob.model.add_subsystem("spline", BsplineComp(num_points=3, x_interp=[0.0, 0.5, 1.2]))
    with pytest.raises(
        ValueError,
        match=r"'x_interp\[.*\]' = 1.2"
        r" is out of range: must be in \[0, 1\]",
    ):
        prob.setup()


@pytest.mark.parametrize("name", ["num_cp", "num_points", "order", "vec_size"])
def test_bad_size_option_raises(name):
    with pytest.raises(ValueError, match=rf"\(0\) of option '{name}'"):
        BsplineComp(**{name: 0})
