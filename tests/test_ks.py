"""Tests for lpc_mdo.components.ks.KSComp."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_near_equal,
)
from sparsity import assert_sparsity_matches

from lpc_mdo.components.ks import KSComp


def _run(g, **options):
    g = np.atleast_2d(np.asarray(g, dtype=float))
    prob = om.Problem()
    prob.model.add_subsystem(
        "ks", KSComp(vec_size=g.shape[0], width=g.shape[1], **options), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("g", g)
    prob.run_model()
    return prob


def _random_g(vec_size=4, width=7, scale=1.0, seed=0):
    return scale * np.random.default_rng(seed).uniform(-1.0, 1.0, size=(vec_size, width))


@pytest.mark.parametrize("lower_flag", [False, True])
@pytest.mark.parametrize("rho", [1.0, 50.0])
def test_partials(lower_flag, rho):
    prob = _run(_random_g(), rho=rho, lower_flag=lower_flag)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


@pytest.mark.parametrize("rho", [1.0, 10.0, 50.0, 300.0])
def test_bounds_max(rho):
    # Closed-form bounds: max(g) <= KS <= max(g) + ln(width)/rho (round-off slack 1e-12).
    g = _random_g(width=9)
    ks = _run(g, rho=rho).get_val("KS")
    g_max = g.max(axis=1)
    assert np.all(ks >= g_max - 1e-12)
    assert np.all(ks - g_max <= np.log(g.shape[1]) / rho + 1e-12)


@pytest.mark.parametrize("rho", [1.0, 50.0])
def test_bounds_min(rho):
    # Closed-form bounds with lower_flag: min(g) - ln(width)/rho <= KS <= min(g).
    g = _random_g(width=9)
    ks = _run(g, rho=rho, lower_flag=True).get_val("KS")
    g_min = g.min(axis=1)
    assert np.all(ks <= g_min + 1e-12)
    assert np.all(g_min - ks <= np.log(g.shape[1]) / rho + 1e-12)


def test_equal_entries_closed_form():
    # All entries equal to c: KS = c + ln(width)/rho exactly (max) and c - ln(width)/rho (min);
    # only round-off of ln/exp differs, 1e-14 relative.
    width, rho = 6, 50.0
    c = np.array([[-2.0], [0.0], [0.3], [1.5e3]])
    g = np.repeat(c, width, axis=1)
    assert_near_equal(
        _run(g, rho=rho).get_val("KS"), c[:, 0] + np.log(width) / rho, tolerance=1e-14
    )
    assert_near_equal(
        _run(g, rho=rho, lower_flag=True).get_val("KS"),
        c[:, 0] - np.log(width) / rho,
        tolerance=1e-14,
    )


def test_two_values_closed_form():
    # Two values a > b: KS = a + ln(1 + exp(-rho (a - b)))/rho (algebra of eq. 7), 1e-14 relative.
    rho = 5.0
    g = np.array([[1.0, 0.8], [0.2, -0.4]])
    a, b = g[:, 0], g[:, 1]
    expected = a + np.log1p(np.exp(-rho * (a - b))) / rho
    assert_near_equal(_run(g, rho=rho).get_val("KS"), expected, tolerance=1e-14)


@pytest.mark.parametrize("lower_flag", [False, True])
def test_matches_openmdao_kscomp(lower_flag):
    # Independent implementation: OpenMDAO's om.KSComp (same eq. with alpha = 1), 1e-12 relative.
    # Our lower_flag (smooth minimum) is om.KSComp's `minimum` option; om.KSComp's own lower_flag
    # only flips the sign of g and returns KS_max(-g) = -min.
    g = _random_g(vec_size=3, width=5, seed=3)
    ours = _run(g, rho=20.0, lower_flag=lower_flag).get_val("KS")

    prob = om.Problem()
    prob.model.add_subsystem(
        "ks", om.KSComp(width=5, vec_size=3, rho=20.0, minimum=lower_flag), promotes=["*"]
    )
    prob.setup()
    prob.set_val("g", g)
    prob.run_model()
    assert_near_equal(ours, prob.get_val("KS")[:, 0], tolerance=1e-12)


def test_large_values_no_overflow():
    # Stresses in Pa with rho = 50/Pa would overflow exp() without the shift; the result must be
    # finite and equal the hard max to within ln(width)/rho (closed-form bound).
    g = np.array([[3.0e8, 2.0e8, 2.9e8]])
    ks = _run(g, rho=50.0, units="Pa").get_val("KS", units="Pa")
    assert np.all(np.isfinite(ks))
    assert 3.0e8 <= ks[0] <= 3.0e8 + np.log(3) / 50.0


def test_units_conversion():
    # KS carries the units of g: KS in MPa equals KS in Pa / 1e6 (exact conversion).
    g = np.array([[1.0, 2.0, 1.5]])
    prob = _run(g, rho=5.0, units="MPa")
    assert_near_equal(prob.get_val("KS", units="Pa"), prob.get_val("KS") * 1e6, tolerance=1e-15)


def test_declared_sparsity_matches_the_sensitivities():
    # Output i depends on row i of g only; the declared rows/cols must match the sensitivities.
    prob = _run(_random_g(vec_size=3, width=4))
    assert_sparsity_matches(prob, "ks")


@pytest.mark.parametrize("rho", [0.0, -1.0])
def test_bad_rho_raises(rho):
    with pytest.raises(ValueError, match=rf"KSComp: 'rho' = {rho} is out of range: must be > 0$"):
        KSComp(rho=rho)


@pytest.mark.parametrize("name", ["vec_size", "width"])
def test_bad_shape_option_raises(name):
    with pytest.raises(ValueError, match=rf"\(0\) of option '{name}'"):
        KSComp(**{name: 0})
