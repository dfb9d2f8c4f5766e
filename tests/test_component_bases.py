"""The shared component bases, through minimal subclasses with closed-form answers.

PointwiseExplicitComp and PointwiseImplicitComp (components/motor/_pointwise.py) and
_M4RegressionComp (components/weights/regressions.py) are otherwise exercised only through the
motor and weight models; here each gets a toy model whose values follow from a closed form, and
its partials are checked against finite differences.
"""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.motor._pointwise import PointwiseExplicitComp, PointwiseImplicitComp
from lpc_mdo.components.weights.regressions import _M4RegressionComp


class SquareComp(PointwiseExplicitComp):
    """y = a x^2 + sin(x): x per node, a per motor."""

    _input_vars = (("x", None, "x", 1.0, True), ("a", None, "a", 1.0, False))
    _output_vars = (("y", None, "y", 0.0, True),)
    _deps = {"y": ("x", "a")}
    _per_node = True

    def _evaluate(self, values):
        return {"y": values["a"][:, None] * values["x"] ** 2 + np.sin(values["x"])}


class CubicRootComp(PointwiseImplicitComp):
    """The real root s of s^3 + s - c = 0 (one per motor and node), by bisection."""

    _state_var = ("s", None, "s", 0.0, True)
    _input_vars = (("c", None, "c", 1.0, True),)
    _deps = ("c",)
    _per_node = True

    def _residual(self, values, state):
        return state**3 + state - values["c"]

    def _bracket(self, values):
        bound = np.abs(values["c"]) + 1.0
        return -bound, bound


def _run(comp, **values):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("comp", comp, promotes=["*"])
    prob.model.linear_solver = om.DirectSolver()
    prob.setup(force_alloc_complex=True)
    for name, value in values.items():
        prob.set_val(name, value)
    prob.run_model()
    return prob


def test_pointwise_explicit_base_values_and_partials():
    x = np.array([[0.3, -1.2, 2.0], [1.5, 0.0, -0.7]])
    a = np.array([2.0, -0.5])
    prob = _run(SquareComp(num_motors=2, num_nodes=3), x=x, a=a)
    np.testing.assert_allclose(prob.get_val("y"), a[:, None] * x**2 + np.sin(x), rtol=1e-14)
    assert_check_partials(prob.check_partials(out_stream=None, method="fd"), atol=1e-5, rtol=1e-5)


def test_pointwise_implicit_base_root_partials_and_total_derivative():
    # No c = 0: a root at exactly 0 never meets bisect's purely relative default tolerance.
    c = np.array([[-3.0, 0.5, 10.0], [2.0, 0.1, -0.25]])
    prob = _run(CubicRootComp(num_motors=2, num_nodes=3), c=c)
    s = prob.get_val("s")
    # Independent: the real root of each cubic by numpy.roots.
    for k, ck in np.ndenumerate(c):
        roots = np.roots([1.0, 0.0, 1.0, -ck])
        assert s[k] == pytest.approx(roots[np.abs(roots.imag) < 1e-9].real[0], abs=1e-10)
    assert_check_partials(prob.check_partials(out_stream=None, method="fd"), atol=1e-5, rtol=1e-5)
    # Implicit-function theorem: ds/dc = 1/(3 s^2 + 1), diagonal over the points.
    totals = prob.compute_totals("s", "c")[("s", "c")]
    np.testing.assert_allclose(
        totals, np.diag(1.0 / (3.0 * s.ravel() ** 2 + 1.0)), rtol=1e-8, atol=1e-12
    )


class TwoPointMassComp(_M4RegressionComp):
    """Two sub-parts, no own inertia: mass = 10 x + 5 split 1:3 between two points."""

    _regressors = (("x", "m", "regressor", 2.0, 0.0, True),)
    _prefix = "toy"
    _what = "toy part"

    def _sub_parts(self):
        # (fraction, {cg coefficients on [x, 1]}, k_x): the base maps cg_x with -k_x, cg_z with
        # -1 (M4 frame -> body frame) and adds the nose.
        return [
            (0.25, {"cg_x": [1.0, 0.0], "cg_y": [0.0, 1.0], "cg_z": [0.0, 0.5]}, 1.0),
            (0.75, {"cg_x": [2.0, 0.0], "cg_y": [0.0, -1.0 / 3.0], "cg_z": [0.0, 0.0]}, 1.0),
        ]

    def _mass_coefficients(self):
        return [10.0, 5.0]


def test_m4_regression_base_is_two_point_masses():
    x = 1.7
    prob = _run(TwoPointMassComp(nose=(0.0, 0.0, 0.0)), x=x)
    mass = 10.0 * x + 5.0
    masses = mass * np.array([0.25, 0.75])
    points = np.array([[-x, 1.0, -0.5], [-2.0 * x, -1.0 / 3.0, 0.0]])
    cg = masses @ points / mass
    assert prob.get_val("toy_mass")[0] == pytest.approx(mass, rel=1e-14)
    np.testing.assert_allclose(prob.get_val("toy_cg"), cg, rtol=1e-14, atol=1e-15)
    # Independent: the inertia of two point masses about their common cg.
    inertia = sum(
        m * (r @ r * np.eye(3) - np.outer(r, r)) for m, r in zip(masses, points - cg, strict=True)
    )
    np.testing.assert_allclose(prob.get_val("toy_inertia"), inertia, rtol=1e-12, atol=1e-12)
    assert_check_partials(prob.check_partials(out_stream=None, method="cs"), atol=1e-10, rtol=1e-10)
