"""
Warm starts of the inner solves of implicit components.

A driver's next point is close to its last one, so Newton starts from the previous solution
(BEM inflow angle, alpha*, the motor's em_torque and pointwise states) where it lies inside the
bracket. The bracket does not depend on the start, so the root is the cold start's to the
solver tolerance; these tests check that (independent number: the same component solved cold
in a fresh problem) and that the warm start needs fewer residual evaluations.
"""

import numpy as np
import openmdao.api as om
import pytest
from numpy.testing import assert_allclose
from rotor_cases import bem_problem

from lpc_mdo.components.aero.alpha_star import AlphaStarComp
from lpc_mdo.components.motor.efficiency import EMTorqueComp
from lpc_mdo.components.rotor.bem_inflow import BEMSections
from lpc_mdo.core.numerics import safeguarded_newton
from lpc_mdo.groups.motor import MotorGroup


def _counter(monkeypatch, owner, name):
    """Count the calls of ``owner.name`` (a class or an instance attribute)."""
    calls = [0]
    original = getattr(owner, name)

    def counted(*args, **kwargs):
        calls[0] += 1
        return original(*args, **kwargs)

    if isinstance(owner, type):

        def method(self, *args, **kwargs):
            calls[0] += 1
            return original(self, *args, **kwargs)

        monkeypatch.setattr(owner, name, method)
    else:
        monkeypatch.setattr(owner, name, counted)
    return calls


def test_start_inside_the_bracket_is_used_nan_and_outside_are_not():
    a = np.array([2.0, 3.0, 10.0, 0.5])
    evaluations = []

    def fun(x):
        evaluations.append(x.size)
        return x**3 - a, 3.0 * x**2

    lower, upper = np.zeros(4), np.full(4, 4.0)
    cold = safeguarded_newton(fun, lower, upper, xtol_abs=1e-15)
    cold_count = len(evaluations)
    evaluations.clear()
    # Entry 0 starts at its root, entry 1 at NaN (default start), entry 2 outside its bracket
    # (default start), entry 3 near its root.
    x0 = np.array([np.cbrt(2.0), np.nan, 7.0, np.cbrt(0.5) * (1.0 + 1e-6)])
    warm = safeguarded_newton(fun, lower, upper, x0=x0, xtol_abs=1e-15)
    assert_allclose(warm, np.cbrt(a), rtol=1e-14)
    assert_allclose(warm, cold, rtol=1e-14)
    assert len(evaluations) <= cold_count


def test_bem_inflow_warm_start_gives_the_cold_root_in_fewer_evaluations(monkeypatch):
    warm = bem_problem()
    rpm = warm.get_val("rpm") * 1.01
    speed = warm.get_val("axial_velocity") + 0.3
    evaluations = _counter(monkeypatch, BEMSections, "evaluate")
    warm.set_val("rpm", rpm)
    warm.set_val("axial_velocity", speed)
    warm.run_model()
    warm_count = evaluations[0]

    cold = bem_problem()
    cold.set_val("inflow_angle", np.nan)  # no usable previous solution: cold start
    cold.set_val("rpm", rpm)
    cold.set_val("axial_velocity", speed)
    evaluations[0] = 0
    cold.run_model()
    assert_allclose(warm.get_val("inflow_angle"), cold.get_val("inflow_angle"), atol=1e-12)
    assert_allclose(warm.get_val("thrust"), cold.get_val("thrust"), rtol=1e-11)
    assert warm_count < evaluations[0]


def _alpha_problem(cl):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "alpha", AlphaStarComp(num_sections=cl.size, airfoil="ls417"), promotes=["*"]
    )
    prob.setup()
    prob.set_val("lift_coefficient", cl)
    prob.set_val("reynolds", np.full(cl.size, 3.0e6))
    prob.set_val("mach", np.full(cl.size, 0.2))
    return prob


def test_alpha_star_warm_start_gives_the_cold_root_in_fewer_evaluations(monkeypatch):
    cl = np.linspace(-0.4, 1.3, 7)
    warm = _alpha_problem(cl)
    warm.run_model()
    comp = warm.model.alpha
    evaluations = _counter(monkeypatch, comp._polar, "evaluate")
    warm.set_val("lift_coefficient", cl + 0.002)
    warm.run_model()
    warm_count = evaluations[0]

    cold = _alpha_problem(cl + 0.002)
    evaluations_cold = _counter(monkeypatch, cold.model.alpha._polar, "evaluate")
    cold.run_model()
    assert_allclose(warm.get_val("alpha_star"), cold.get_val("alpha_star"), atol=1e-14)
    assert warm_count < evaluations_cold[0]


def _motor_problem(torque):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("motor", MotorGroup(num_motors=2, num_nodes=2), promotes=["*"])
    prob.setup()
    prob.set_val("length", [0.09, 0.13])
    prob.set_val("rotor_torque", torque)
    prob.set_val("rotor_rpm", [[2500.0, 1200.0], [1500.0, 900.0]])
    return prob


@pytest.mark.parametrize("scale", [1.0001, 0.9999, 1.0])
def test_motor_warm_starts_give_the_cold_solution_in_fewer_evaluations(monkeypatch, scale):
    # em_torque (own Newton started at the previous solution, above or below the new root) and
    # the pointwise states (torque limit): the same operating point as a cold solve. Measured
    # loss-model evaluations of em_torque, warm vs cold: 1 vs 4 at the same point, 3 vs 4 at
    # 1e-4 (a line-search step near an optimum), 4 vs 4 from 1 % on (Newton's quadratic rate
    # from the cold start's 5 % is as fast).
    torque = np.array([[300.0, 700.0], [200.0, 850.0]])
    warm = _motor_problem(torque)
    warm.run_model()
    evaluations = _counter(monkeypatch, EMTorqueComp, "_operating_point")
    warm.set_val("rotor_torque", scale * torque)
    warm.run_model()
    warm_count = evaluations[0]

    cold = _motor_problem(scale * torque)
    evaluations[0] = 0
    cold.run_model()
    for name in ("em_torque", "current_q", "input_power", "torque_limit", "torque_margin"):
        assert_allclose(warm.get_val(name), cold.get_val(name), rtol=1e-12, err_msg=name)
    assert warm_count < evaluations[0]


def test_em_torque_falls_back_to_the_cold_start_from_a_bad_previous_solution():
    # A previous em_torque far beyond the stall maximum (where the warm Newton would stop with
    # the stall error): the component starts again at T_L and finds the physical root.
    torque = np.array([[300.0, 700.0], [200.0, 850.0]])
    reference = _motor_problem(torque)
    reference.run_model()
    prob = _motor_problem(torque)
    prob.run_model()
    prob.set_val("em_torque", 1.0e5)
    prob.run_model()
    assert_allclose(prob.get_val("em_torque"), reference.get_val("em_torque"), rtol=1e-12)
