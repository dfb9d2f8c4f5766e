"""lpc_mdo.core.numerics.safeguarded_newton against closed-form roots."""

import numpy as np
import openmdao.api as om
import pytest
from numpy.testing import assert_allclose

from lpc_mdo.core.numerics import newton_step, safeguarded_newton


def test_cube_roots_vectorized():
    a = np.array([[0.001, 0.5, 1.0], [8.0, 27.0, 1.0e6]])
    root = safeguarded_newton(lambda x: (x**3 - a, 3.0 * x**2), 0.0, np.maximum(a, 1.0))
    assert root.shape == a.shape
    assert_allclose(root, np.cbrt(a), rtol=1e-14)


def test_bracket_keeps_newton_from_diverging():
    # Plain Newton on atan(x) - c diverges from |x0| > 1.39; the bracket keeps it convergent.
    c = np.array([-1.2, 0.0, 0.3, 1.5])
    fun = lambda x: (np.arctan(x) - c, 1.0 / (1.0 + x**2))  # noqa: E731
    x = np.full(c.shape, 50.0)
    with np.errstate(all="ignore"):
        for _ in range(5):
            x = newton_step(fun, x)
    assert not np.allclose(x, np.tan(c))
    root = safeguarded_newton(fun, np.full(c.shape, -100.0), 100.0, x0=50.0)
    assert_allclose(root, np.tan(c), rtol=1e-13, atol=1e-15)


def test_residual_shape_must_match_bracket():
    with pytest.raises(ValueError, match=r"residual has shape \(2,\); must have the bracket"):
        safeguarded_newton(lambda x: (x - np.ones(2), None), 0.0, 2.0)


def test_bisection_only_and_reversed_bracket():
    a = np.array([2.0, 3.0, 10.0])
    root = safeguarded_newton(
        lambda x: (x**2 - a, None), np.full(3, 10.0), 0.0, xtol_rel=1e-15, maxiter=200
    )
    assert_allclose(root, np.sqrt(a), rtol=1e-14)


def test_indexed_calls_only_active_entries():
    a = np.linspace(1.0, 100.0, 7)
    sizes = []

    def fun(x, idx):
        sizes.append(x.size)
        return x**3 - a[idx], 3.0 * x**2

    root = safeguarded_newton(fun, np.zeros(7), a, indexed=True)
    assert_allclose(root, np.cbrt(a), rtol=1e-14)
    assert sizes[0] == 7 and min(sizes) < 7


def test_root_at_bracket_end_and_residual_tolerance():
    root = safeguarded_newton(lambda x: (x - 1.0, np.ones_like(x)), [1.0, 0.0], [2.0, 3.0])
    assert_allclose(root, [1.0, 1.0])
    root = safeguarded_newton(lambda x: (x**3 - 2.0, 3 * x**2), 0.0, 2.0, ftol=1e-3)
    assert abs(root**3 - 2.0) <= 1e-3


def test_no_sign_change_raises_analysis_error():
    with pytest.raises(
        om.AnalysisError,
        match=r"Comp: the current residual does not change "
        r"sign on its bracket \[0, 1\] A at index \[1\]",
    ):
        safeguarded_newton(
            lambda x: (x**2 - np.array([0.5, 4.0]), 2 * x),
            np.zeros(2),
            1.0,
            variable="current",
            units="A",
            where="Comp",
        )


def test_non_finite_and_no_convergence_raise():
    def fun(x):
        return np.where(x > 0.75, np.nan, x - 0.8), np.ones_like(x)

    with pytest.raises(om.AnalysisError, match="residual not finite"):
        safeguarded_newton(fun, 0.0, 1.0, f_lower=-0.8, f_upper=0.2, x0=0.9)
    with pytest.raises(om.AnalysisError, match="no convergence in 3 iterations"):
        safeguarded_newton(lambda x: (x**3 - 2.0, None), 0.0, 2.0, maxiter=3)
    calls = []

    def fail(idx, why):
        calls.append((idx.tolist(), why))
        raise om.AnalysisError(f"custom: {why}")

    with pytest.raises(om.AnalysisError, match="custom: no convergence"):
        safeguarded_newton(lambda x: (x**3 - 2.0, None), [0.0], [2.0], maxiter=3, fail=fail)
    assert calls == [([0], "no convergence in 3 iterations")]


def test_complex_step_after_real_solve_gives_the_derivative():
    a = np.array([2.0, 5.0])
    root = safeguarded_newton(lambda x: (x**3 - a, 3 * x**2), np.zeros(2), 5.0)
    h = 1e-30
    a_c = a + 1j * h
    root_c = newton_step(lambda x: (x**3 - a_c, 3 * x**2), root.astype(complex))
    assert_allclose(root_c.imag / h, 1.0 / (3.0 * np.cbrt(a) ** 2), rtol=1e-12)
