"""IpoptDriver and make_driver.

Reference optima: Sellar MDA, objective 3.18339 at z = (1.9776, 0), x = 0 (Sellar, Batill and
Renaud 1996; OpenMDAO's documentation); the paraboloid optima are derived in closed form below.
"""

import sys

import numpy as np
import openmdao.api as om
import pytest
from openmdao.test_suite.components.sellar import (
    SellarDis1withDerivatives,
    SellarDis2withDerivatives,
)
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.drivers import IpoptDriver, IpoptMultipliers


class Paraboloid(om.ExplicitComponent):
    """f = (x - 3)^2 + x y + (y + 4)^2 - 3; optionally raises AnalysisError on chosen calls."""

    def initialize(self):
        self.options.declare("fail_on_calls", default=(), types=tuple)

    def setup(self):
        self.add_input("x", 0.0)
        self.add_input("y", 0.0)
        self.add_output("f", 0.0)
        self.declare_partials("f", ["x", "y"])
        self.calls = 0
        self.failures = 0

    def compute(self, inputs, outputs):
        self.calls += 1
        if self.calls in self.options["fail_on_calls"]:
            self.failures += 1
            raise om.AnalysisError(f"simulated failure on call {self.calls}")
        x, y = inputs["x"], inputs["y"]
        outputs["f"] = (x - 3.0) ** 2 + x * y + (y + 4.0) ** 2 - 3.0

    def compute_partials(self, inputs, partials):
        x, y = inputs["x"], inputs["y"]
        partials["f", "x"] = 2.0 * (x - 3.0) + y
        partials["f", "y"] = x + 2.0 * (y + 4.0)


def paraboloid_problem(
    driver,
    *,
    x_upper=50.0,
    equality=False,
    linear=False,
    scaled=False,
    y_ref=20.0,
    fail_on_calls=(),
):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("parab", Paraboloid(fail_on_calls=fail_on_calls), promotes=["*"])
    prob.model.add_subsystem("con", om.ExecComp("c = x - y"), promotes=["*"])
    prob.model.set_input_defaults("x", 0.0)
    prob.model.set_input_defaults("y", 0.0)
    if scaled:
        prob.model.add_design_var("x", lower=-50.0, upper=x_upper, ref=10.0, ref0=-2.0)
        prob.model.add_design_var("y", lower=-50.0, upper=50.0, ref=y_ref, ref0=1.0)
        prob.model.add_objective("f", ref=30.0, ref0=-5.0)
    else:
        prob.model.add_design_var("x", lower=-50.0, upper=x_upper)
        prob.model.add_design_var("y", lower=-50.0, upper=50.0)
        prob.model.add_objective("f")
    if equality:
        prob.model.add_constraint("c", equals=15.0, linear=linear, ref=5.0 if scaled else None)
    else:
        prob.model.add_constraint("c", lower=15.0, linear=linear, ref=5.0 if scaled else None)
    prob.driver = driver
    prob.setup()
    prob.set_val("x", 0.0)
    prob.set_val("y", 0.0)
    return prob


def sellar_problem(driver, con2_upper=0.0):
    """Sellar MDA with a Newton-solved cycle and a direct linear solve (exact totals).

    OpenMDAO's feature SellarMDA keeps LinearRunOnce around its cycle, which gives wrong totals
    (reference page, section 8), so the model is assembled here.
    """
    prob = om.Problem(reports=False)
    model = prob.model
    cycle = model.add_subsystem("cycle", om.Group(), promotes=["*"])
    cycle.add_subsystem("d1", SellarDis1withDerivatives(), promotes=["*"])
    cycle.add_subsystem("d2", SellarDis2withDerivatives(), promotes=["*"])
    cycle.nonlinear_solver = om.NewtonSolver(
        solve_subsystems=False, atol=1e-14, rtol=1e-14, iprint=-1
    )
    cycle.linear_solver = om.DirectSolver()
    model.add_subsystem(
        "obj_cmp",
        om.ExecComp("obj = x**2 + z[1] + y1 + exp(-y2)", z=np.array([5.0, 2.0]), x=1.0),
        promotes=["*"],
    )
    model.add_subsystem("con_cmp1", om.ExecComp("con1 = 3.16 - y1"), promotes=["*"])
    model.add_subsystem("con_cmp2", om.ExecComp("con2 = y2 - 24.0"), promotes=["*"])
    model.set_input_defaults("x", 1.0)
    model.set_input_defaults("z", np.array([5.0, 2.0]))
    model.add_design_var("x", lower=0.0, upper=10.0)
    model.add_design_var("z", lower=np.array([-10.0, 0.0]), upper=np.array([10.0, 10.0]))
    model.add_objective("obj")
    model.add_constraint("con1", upper=0.0)
    model.add_constraint("con2", upper=con2_upper)
    prob.driver = driver
    prob.setup()
    return prob


@pytest.mark.requires_ipopt
def test_sellar_reaches_known_optimum():
    prob = sellar_problem(IpoptDriver(print_level=0, tol=1e-9))
    result = prob.run_driver()
    assert result.success, result.exit_status
    # Sellar MDA optimum, objective 3.18339 to 1e-5 (issue acceptance).
    assert_near_equal(prob.get_val("obj"), 3.18339, 1e-5)
    assert_near_equal(prob.get_val("z"), [1.97763888, 0.0], 1e-5)
    assert prob.get_val("x")[0] == pytest.approx(0.0, abs=1e-6)
    assert 0 < result.iter_count < 50


@pytest.mark.requires_ipopt
def test_bounded_constrained_paraboloid_matches_closed_form():
    # With x <= 5 and x - y >= 15 both active: x = 5, y = -10, f = -13.  KKT: grad f = (-6, -7)
    # balanced by multipliers 13 (bound) and 7 (constraint), both >= 0; f is convex (Hessian
    # [[2, 1], [1, 2]]), so this is the global optimum.
    prob = paraboloid_problem(IpoptDriver(print_level=0, tol=1e-10), x_upper=5.0)
    assert prob.run_driver().success
    assert_near_equal(prob.get_val("x"), 5.0, 1e-6)
    assert_near_equal(prob.get_val("y"), -10.0, 1e-6)
    assert_near_equal(prob.get_val("f"), -13.0, 1e-6)
    mult = prob.driver.multipliers
    assert isinstance(mult, IpoptMultipliers)
    assert mult["upper"]["x"][0] == pytest.approx(13.0, rel=1e-5)
    assert mult["constraints"]["c"][0] == pytest.approx(-7.0, rel=1e-5)


@pytest.mark.requires_ipopt
def test_inequality_paraboloid_closed_form():
    # Only x - y >= 15 active: y = x - 15, df/dx = 6 x - 43 = 0 -> x = 43/6, y = -47/6,
    # f = -867/36 - 3.
    prob = paraboloid_problem(IpoptDriver(print_level=0, tol=1e-10))
    assert prob.run_driver().success
    assert_near_equal(prob.get_val("x"), 43.0 / 6.0, 1e-7)
    assert_near_equal(prob.get_val("y"), -47.0 / 6.0, 1e-7)
    assert_near_equal(prob.get_val("f"), -867.0 / 36.0 - 3.0, 1e-7)


@pytest.mark.requires_ipopt
@pytest.mark.parametrize("equality", [False, True])
@pytest.mark.parametrize("linear", [False, True])
def test_scaled_problems_agree_with_slsqp(equality, linear):
    ipopt = paraboloid_problem(
        IpoptDriver(print_level=0, tol=1e-10), equality=equality, linear=linear, scaled=True
    )
    assert ipopt.run_driver().success
    slsqp = paraboloid_problem(
        om.ScipyOptimizeDriver(optimizer="SLSQP", tol=1e-12, disp=False),
        equality=equality,
        linear=linear,
        scaled=True,
    )
    assert slsqp.run_driver().success
    for name in ("x", "y", "f"):
        assert_near_equal(ipopt.get_val(name), slsqp.get_val(name), 1e-6)
    assert_near_equal(ipopt.get_val("c"), 15.0, 1e-7)


@pytest.mark.requires_ipopt
def test_negative_scaler_flips_bounds_correctly():
    # ref < ref0 gives a negative scaler, so scaled lower > scaled upper; SLSQP cannot take this,
    # IPOPT gets the bounds sorted and reaches the closed-form optimum of the inequality case.
    prob = paraboloid_problem(IpoptDriver(print_level=0, tol=1e-10), scaled=True, y_ref=-20.0)
    assert prob.run_driver().success
    assert_near_equal(prob.get_val("y"), -47.0 / 6.0, 1e-7)


@pytest.mark.requires_ipopt
def test_linear_constraint_is_not_evaluated_by_the_model():
    prob = paraboloid_problem(IpoptDriver(print_level=0), linear=True)
    assert prob.run_driver().success
    # The linear constraint Jacobian is computed once, and all its values come from it.
    assert prob.driver._lin_cons == ["c"]
    assert prob.driver._m_nl == 0


@pytest.mark.requires_ipopt
def test_recorder_records_every_evaluation_and_final_case_loads(tmp_path):
    prob = sellar_problem(IpoptDriver(print_level=0))
    path = str(tmp_path / "cases.sql")
    recorder = om.SqliteRecorder(path)
    prob.driver.add_recorder(recorder)
    prob.add_recorder(recorder)
    result = prob.run_driver()
    prob.record("final")
    prob.cleanup()

    reader = om.CaseReader(path)
    driver_cases = reader.list_cases("driver", recurse=False, out_stream=None)
    # One case per model evaluation, including the initial point.
    assert len(driver_cases) == prob.driver.iter_count == result.model_evals
    assert len(driver_cases) >= result.iter_count
    last = reader.get_case(driver_cases[-1])
    assert_near_equal(last.get_objectives()["obj"], 3.18339, 1e-5)

    fresh = sellar_problem(IpoptDriver(print_level=0))
    fresh.load_case(reader.get_case("final"))
    fresh.run_model()
    assert_near_equal(fresh.get_val("obj"), 3.18339, 1e-5)
    assert_near_equal(fresh.get_val("z"), prob.get_val("z"), 1e-12)


@pytest.mark.requires_ipopt
def test_analysis_error_is_cut_back_and_optimization_converges(tmp_path):
    # Fail the 3rd and 5th model evaluations; IPOPT must back off and still converge.
    prob = paraboloid_problem(IpoptDriver(print_level=0, tol=1e-10), fail_on_calls=(3, 5))
    path = str(tmp_path / "cases.sql")
    prob.driver.add_recorder(om.SqliteRecorder(path))
    prob.final_setup()
    result = prob.run_driver()
    prob.cleanup()
    # The failed evaluations are recorded as failed driver cases (success 0, the error as msg).
    reader = om.CaseReader(path)
    failed = [
        c
        for c in map(reader.get_case, reader.list_cases("driver", out_stream=None))
        if not c.success
    ]
    assert len(failed) == 2
    assert failed[0].msg.endswith("simulated failure on call 3")
    assert failed[1].msg.endswith("simulated failure on call 5")
    comp = prob.model.parab
    assert comp.failures == 2
    errors = prob.driver.analysis_errors
    assert len(errors) == 2 and errors[0].endswith("simulated failure on call 3")
    assert result.success, result.exit_status
    assert_near_equal(prob.get_val("x"), 43.0 / 6.0, 1e-6)
    assert_near_equal(prob.get_val("f"), -867.0 / 36.0 - 3.0, 1e-7)


@pytest.mark.requires_ipopt
def test_error_in_model_is_reraised_not_swallowed():
    class Broken(Paraboloid):
        def compute(self, inputs, outputs):
            super().compute(inputs, outputs)
            if self.calls == 3:
                raise KeyError("bug in a component")

    prob = om.Problem(reports=False)
    prob.model.add_subsystem("parab", Broken(), promotes=["*"])
    prob.model.add_design_var("x", lower=-50.0, upper=50.0)
    prob.model.add_design_var("y", lower=-50.0, upper=50.0)
    prob.model.add_objective("f")
    prob.driver = IpoptDriver(print_level=0)
    prob.setup()
    with pytest.raises(KeyError, match="bug in a component"):
        prob.run_driver()


@pytest.mark.requires_ipopt
def test_warm_start_takes_fewer_iterations_than_cold_start(tmp_path):
    path = str(tmp_path / "cold.sql")
    cold = sellar_problem(IpoptDriver(print_level=0))
    cold.add_recorder(om.SqliteRecorder(path))
    cold_result = cold.run_driver()
    cold.record("final")
    cold.cleanup()
    assert cold_result.success

    # A neighbouring problem (con2 limit moved by 0.05) started from the recorded optimum with
    # the previous multipliers, the paper's sweep situation.
    def neighbour(driver):
        return sellar_problem(driver, con2_upper=0.05)

    warm = neighbour(IpoptDriver(print_level=0, warm_start=cold.driver.multipliers))
    warm.load_case(om.CaseReader(path).get_case("final"))
    warm_result = warm.run_driver()

    reference = neighbour(IpoptDriver(print_level=0))
    reference_result = reference.run_driver()

    assert warm_result.success and reference_result.success
    assert_near_equal(warm.get_val("obj"), reference.get_val("obj"), 1e-6)
    assert warm_result.iter_count < reference_result.iter_count
    assert warm_result.iter_count <= cold_result.iter_count // 2


@pytest.mark.requires_ipopt
def test_warm_start_multipliers_of_wrong_size_are_rejected():
    prob = sellar_problem(IpoptDriver(print_level=0))
    prob.driver.options["warm_start"] = IpoptMultipliers(
        constraints={"con1": np.zeros(3)}, lower={}, upper={}
    )
    with pytest.raises(ValueError, match="'con1' have size 3, but the problem has size 1"):
        prob.run_driver()


@pytest.mark.requires_ipopt
def test_sparse_jacobian_from_coloring_and_relevance():
    n = 6

    def build(color):
        prob = om.Problem(reports=False)
        prob.model.add_subsystem(
            "f",
            om.ExecComp(
                "obj = sum((x - 2.0)**2) + sum((y + 1.0)**2)", x=np.zeros(n), y=np.zeros(n)
            ),
            promotes=["*"],
        )
        prob.model.add_subsystem(
            "cx",
            om.ExecComp("c = x**2", c=np.zeros(n), x=np.zeros(n), has_diag_partials=True),
            promotes=["*"],
        )
        prob.model.add_subsystem(
            "cy",
            om.ExecComp("d = 2.0 * y", d=np.zeros(n), y=np.zeros(n), has_diag_partials=True),
            promotes=["*"],
        )
        prob.model.add_design_var("x", lower=-10.0, upper=10.0)
        prob.model.add_design_var("y", lower=-10.0, upper=10.0)
        prob.model.add_objective("obj")
        prob.model.add_constraint("c", upper=1.0)
        prob.model.add_constraint("d", lower=-1.0)
        prob.driver = IpoptDriver(print_level=0)
        if color:
            prob.driver.declare_coloring()
        prob.setup()
        return prob

    relevance_only = build(color=False)
    assert relevance_only.run_driver().success
    # c depends on x only and d on y only: two dense n x n blocks of the 2n x 2n Jacobian.
    assert relevance_only.driver._jac_rows.size == 2 * n * n

    colored = build(color=True)
    assert colored.run_driver().success
    # Total coloring finds the diagonal pattern: 2n nonzeros.
    assert colored.driver._jac_rows.size == 2 * n
    assert_near_equal(colored.get_val("x"), np.ones(n), 1e-6)
    assert_near_equal(colored.get_val("y"), -0.5 * np.ones(n), 1e-6)


@pytest.mark.requires_ipopt
def test_opt_settings_pass_through_to_ipopt():
    prob = paraboloid_problem(IpoptDriver(print_level=0))
    prob.driver.opt_settings["max_iter"] = 2
    result = prob.run_driver()
    assert not result.success
    assert result.iter_count == 2
    assert "Maximum number of iterations" in result.exit_status


def test_missing_cyipopt_gives_install_hint(monkeypatch):
    monkeypatch.setitem(sys.modules, "cyipopt", None)
    prob = paraboloid_problem(IpoptDriver(print_level=0))
    with pytest.raises(ImportError, match=r"pip install 'lpc-mdo\[ipopt\]'"):
        prob.run_driver()
