"""SlsqpDriver: SciPy's SLSQP that backs off from model failures instead of ending the run.

Reference optimum: f = 4 (x - 2)^2 + (y + 1)^2 has its minimum 0 at (2, -1) (closed form).
"""

import io

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_near_equal
from openmdao.utils.om_warnings import DriverWarning

from lpc_mdo.drivers import SlsqpDriver, make_driver, max_violation
from lpc_mdo.post.case_data import driver_cases, last_case
from lpc_mdo.progress import ProgressLine


class Bowl(om.ExplicitComponent):
    """f = 4 (x - 2)^2 + (y + 1)^2, failing (AnalysisError, or ``error``) where x > x_fail."""

    def initialize(self):
        self.options.declare("x_fail", default=np.inf)
        self.options.declare("error", default=om.AnalysisError)

    def setup(self):
        self.add_input("x", 0.0)
        self.add_input("y", 0.0)
        self.add_output("f", 0.0)
        self.add_output("c", 0.0)
        self.declare_partials("f", ["x", "y"])
        self.declare_partials("c", ["x", "y"], val=1.0)
        self.failures = 0

    def compute(self, inputs, outputs):
        x, y = inputs["x"][0], inputs["y"][0]
        if x > self.options["x_fail"]:
            self.failures += 1
            raise self.options["error"](f"no solution at x = {x:.4g}")
        outputs["f"] = 4.0 * (x - 2.0) ** 2 + (y + 1.0) ** 2
        outputs["c"] = x + y

    def compute_partials(self, inputs, partials):
        partials["f", "x"] = 8.0 * (inputs["x"] - 2.0)
        partials["f", "y"] = 2.0 * (inputs["y"] + 1.0)


def bowl_problem(driver, **options):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("bowl", Bowl(**options), promotes=["*"])
    prob.model.add_design_var("x", lower=-10.0, upper=10.0)
    prob.model.add_design_var("y", lower=-10.0, upper=10.0)
    prob.model.add_objective("f")
    prob.model.add_constraint("c", upper=5.0)  # inactive at the optimum (c = 1)
    prob.driver = driver
    prob.setup()
    return prob


def test_failed_trial_point_is_backed_off_and_optimum_reached():
    # From x = 0 the first SLSQP step (unit initial Hessian, gradient -16) lands at x = 16,
    # clipped to the bound 10, where the model fails (x_fail = 3): the line search must cut it.
    prob = bowl_problem(SlsqpDriver(tol=1e-10, disp=False), x_fail=3.0)
    prob.set_val("x", 0.0)
    prob.set_val("y", 0.0)
    with pytest.warns(DriverWarning, match="model evaluation 3 failed .*no solution at x = 10"):
        prob.run_driver()
    assert prob.model.bowl.failures >= 1
    assert len(prob.driver.analysis_errors) == prob.model.bowl.failures
    assert prob.driver.analysis_errors[0].endswith("no solution at x = 10")
    assert prob.driver.result.success
    assert_near_equal(prob.get_val("x"), 2.0, 1e-6)
    assert_near_equal(prob.get_val("y"), -1.0, 1e-6)
    # The model holds the optimum, not a failed trial point.
    assert_near_equal(prob.get_val("f"), 0.0, 1e-10)


def test_failed_evaluation_is_recorded_as_failed_case(tmp_path):
    path = str(tmp_path / "bowl.sql")
    prob = bowl_problem(SlsqpDriver(tol=1e-10, disp=False), x_fail=3.0)
    prob.driver.add_recorder(om.SqliteRecorder(path))
    out = io.StringIO()
    prob.driver.add_recorder(ProgressLine("bowl", stream=out))
    prob.final_setup()
    with pytest.warns(DriverWarning):
        prob.run_driver()
    prob.cleanup()
    cases = driver_cases(path, include_failed=True)
    failed = [c for c in cases if not c.success]
    assert len(failed) == prob.model.bowl.failures == 1
    assert failed[0].msg.endswith("no solution at x = 10")
    assert len(driver_cases(path)) == len(cases) - 1
    assert last_case(path).success
    assert "eval     3  evaluation failed: 'bowl' <class Bowl>" in out.getvalue()


def test_scipy_driver_without_back_off_ends_the_run():
    # The same problem with OpenMDAO's driver: the first failed trial point ends the run.
    prob = bowl_problem(
        om.ScipyOptimizeDriver(optimizer="SLSQP", tol=1e-10, disp=False), x_fail=3.0
    )
    with pytest.raises(om.AnalysisError, match="no solution at x"):
        prob.run_driver()


def test_other_errors_and_a_failed_start_are_reraised():
    prob = bowl_problem(SlsqpDriver(disp=False), x_fail=3.0, error=KeyError)
    with pytest.raises(KeyError, match="no solution at x"):
        prob.run_driver()
    prob = bowl_problem(SlsqpDriver(disp=False), x_fail=-1.0)  # fails at the start, x = 0
    with pytest.raises(om.AnalysisError, match="no solution at x = 0"):
        prob.run_driver()


def test_make_driver_gives_slsqp_driver_and_penalty_option():
    driver = make_driver("SLSQP", failure_penalty=10.0)
    assert isinstance(driver, SlsqpDriver) and driver.options["optimizer"] == "SLSQP"
    assert driver.options["failure_penalty"] == 10.0
    with pytest.raises(ValueError, match="failure_penalty"):
        driver.options["failure_penalty"] = -1.0


class Banana(Bowl):
    """f = 1 + 100 (y - x^2)^2 + (1 - x)^2 (Rosenbrock plus 1: minimum 1 at (1, 1)); c = x + y."""

    def compute(self, inputs, outputs):
        x, y = inputs["x"][0], inputs["y"][0]
        outputs["f"] = 1.0 + 100.0 * (y - x * x) ** 2 + (1.0 - x) ** 2
        outputs["c"] = x + y

    def compute_partials(self, inputs, partials):
        x, y = inputs["x"][0], inputs["y"][0]
        partials["f", "x"] = -400.0 * x * (y - x * x) - 2.0 * (1.0 - x)
        partials["f", "y"] = 200.0 * (y - x * x)


def banana_run(**options):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("banana", Banana(), promotes=["*"])
    prob.model.add_design_var("x", lower=-5.0, upper=5.0)
    prob.model.add_design_var("y", lower=-5.0, upper=5.0)
    prob.model.add_objective("f")
    prob.model.add_constraint("c", upper=5.0)  # inactive along the path
    prob.driver = SlsqpDriver(tol=1e-12, disp=False, **options)
    prob.setup()
    prob.set_val("x", -1.2)
    prob.set_val("y", 1.0)
    iterates = []
    original = prob.driver._iteration_done

    def spy(intermediate_result):
        iterates.append(float(intermediate_result.fun))
        original(intermediate_result)

    prob.driver._iteration_done = spy
    prob.run_driver()
    return prob, iterates


def test_acceptable_point_stop_ends_a_stalled_run_as_success():
    # Reference: the same run without the stop converges to the closed-form minimum f = 1 at
    # (1, 1); with it, the run ends at the first iterate whose objective is within 2 % of the
    # best of the 3 iterations before (every iterate is feasible: c = x + y stays below 5).
    full, full_iterates = banana_run()
    assert full.driver.result.success and full.driver.acceptable_stop is None
    assert_near_equal(full.get_val("f"), 1.0, 1e-9)

    prob, iterates = banana_run(acceptable_iter=3, acceptable_obj_change=0.02)
    stop = len(iterates)
    assert 3 < stop < len(full_iterates)
    assert prob.driver.result.success
    assert prob.driver.result.iter_count == stop
    assert prob.driver.result.exit_status.startswith("SUCCESS (acceptable point")
    best = np.minimum.accumulate(iterates)
    assert abs(best[-4] - iterates[-1]) <= 0.02 * iterates[-1]
    # No earlier iterate met the test.
    for k in range(3, stop - 1):
        assert abs(best[k - 3] - iterates[k]) > 0.02 * iterates[k]
    # The model holds the last iterate.
    assert_near_equal(prob.get_val("f")[0], iterates[-1], 1e-12)


def test_acceptable_point_needs_a_feasible_iterate():
    # The same run with a constraint that every point violates (c >= 10 where x, y <= 4 keep
    # c <= 8): no iterate is acceptable, so the stop never fires.
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("banana", Banana(), promotes=["*"])
    prob.model.add_design_var("x", lower=-5.0, upper=4.0)
    prob.model.add_design_var("y", lower=-5.0, upper=4.0)
    prob.model.add_objective("f")
    prob.model.add_constraint("c", lower=10.0)
    prob.driver = SlsqpDriver(
        tol=1e-12, disp=False, maxiter=20, acceptable_iter=1, acceptable_obj_change=1.0
    )
    prob.setup()
    prob.run_driver()
    assert prob.driver.acceptable_stop is None
    assert not prob.driver.result.success
    assert max_violation(prob.driver) >= 2.0 - 1e-9  # c <= 8 at the corner


def test_violation_of_the_stop_is_in_the_driver_scaled_space():
    # Hand computation: x = 3, y = 1 -> c = 4, f = 1 + 100 * 64 + 4 = 6405.
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("banana", Banana(), promotes=["*"])
    prob.model.add_subsystem("copy", om.ExecComp("g = f"), promotes=["*"])
    prob.model.add_design_var("x")
    prob.model.add_objective("f")
    prob.model.add_constraint("c", equals=1.0, ref=2.0)  # |4 - 1| / 2 = 1.5
    prob.model.add_constraint("g", upper=6000.0, ref=100.0)  # (6405 - 6000) / 100 = 4.05
    prob.driver = SlsqpDriver(disp=False)
    prob.setup()
    prob.set_val("x", 3.0)
    prob.set_val("y", 1.0)
    prob.run_model()
    assert_near_equal(max_violation(prob.driver), 4.05, 1e-12)
    prob.model.set_val("y", 9.0 + 1e-3)  # f = 1 + 1e-4 + 4 (within), c = 12.001: 5.5005
    prob.run_model()
    assert_near_equal(max_violation(prob.driver), 5.5005, 1e-12)
