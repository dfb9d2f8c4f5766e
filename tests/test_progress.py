"""Progress output: optimizer iterations, trim lines, Ctrl-C statistics, quiet IPOPT, no warning."""

import json
import re
import subprocess
import sys
import textwrap
import warnings

import numpy as np
import openmdao.api as om
import pytest
from openmdao.core.driver import Driver
from openmdao.utils.general_utils import determine_adder_scaler

import lpc_mdo.warm_start as warm_start
from lpc_mdo.drivers import SlsqpDriver, make_driver
from lpc_mdo.post.statistics import read_run_stats, run_stats_path
from lpc_mdo.problems import attach_recorder, build_analysis_problem
from lpc_mdo.progress import ProgressLine, interrupt_message, optimizer_iterations, trim_line
from lpc_mdo.trim import trim

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration

LINE = re.compile(r"iter +(\d+|-)  eval +(\d+)  ")


class Bowl(om.ExplicitComponent):
    """f = 4 (x - 2)^2 + (y + 1)^2, c = x + y; raises KeyboardInterrupt at call ``stop_at``."""

    def initialize(self):
        self.options.declare("stop_at", default=None, allow_none=True)

    def setup(self):
        self.add_input("x", 0.0)
        self.add_input("y", 0.0)
        self.add_output("f", 0.0)
        self.add_output("c", 0.0)
        self.declare_partials("f", ["x", "y"])
        self.declare_partials("c", ["x", "y"], val=1.0)
        self.calls = 0

    def compute(self, inputs, outputs):
        self.calls += 1
        if self.calls == self.options["stop_at"]:
            raise KeyboardInterrupt
        x, y = inputs["x"][0], inputs["y"][0]
        outputs["f"] = 4.0 * (x - 2.0) ** 2 + (y + 1.0) ** 2
        outputs["c"] = x + y

    def compute_partials(self, inputs, partials):
        partials["f", "x"] = 8.0 * (inputs["x"] - 2.0)
        partials["f", "y"] = 2.0 * (inputs["y"] + 1.0)


def bowl_problem(driver, stop_at=None, recorder_path=None):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("bowl", Bowl(stop_at=stop_at), promotes=["*"])
    prob.model.add_design_var("x", lower=-10.0, upper=10.0)
    prob.model.add_design_var("y", lower=-10.0, upper=10.0)
    prob.model.add_objective("f")
    prob.model.add_constraint("c", upper=5.0)
    prob.driver = driver
    if recorder_path is not None:
        attach_recorder(prob, recorder_path)
    prob.setup()
    prob.set_val("x", 8.0)
    prob.set_val("y", 6.0)
    return prob


def progress_counts(text):
    """Return (iterations, evaluations) of every progress line."""
    return [(None if i == "-" else int(i), int(e)) for i, e in LINE.findall(text)]


# ---------------------------------------------------------------------- iterations


def test_slsqp_progress_counts_iterations_and_evaluations_separately(capsys):
    prob = bowl_problem(SlsqpDriver(tol=1e-10, disp=False))
    prob.driver.add_recorder(ProgressLine("bowl"))
    prob.final_setup()
    result = prob.run_driver()
    counts = progress_counts(capsys.readouterr().out)
    nit = prob.driver._scipy_optimize_result.nit  # SciPy's own count of major iterations
    assert nit >= 2
    assert prob.driver.optimizer_iterations == nit == result.iter_count
    # One line per model evaluation, numbered 1..n (OpenMDAO's count), iterations beside them.
    assert [e for _, e in counts] == list(range(1, result.model_evals + 1))
    # 'iter': the iteration each evaluation belongs to, 0 (the start) to nit.
    iterations = [i for i, _ in counts]
    assert iterations[0] == 0 and iterations == sorted(iterations)
    assert set(iterations) == set(range(nit + 1))
    assert result.model_evals > nit  # the counters differ: line-search evaluations


def test_ipopt_progress_counts_ipopt_iterations(tmp_path, capsys):
    pytest.importorskip("cyipopt")
    driver = make_driver("IPOPT", print_level=0, output_file="ipopt.log")
    driver.opt_settings["file_print_level"] = 5
    prob = bowl_problem(driver)
    prob.driver.add_recorder(ProgressLine("bowl"))
    prob.final_setup()
    result = prob.run_driver()
    counts = progress_counts(capsys.readouterr().out)
    log = (prob.get_outputs_dir() / "ipopt.log").read_text()
    ipopt_iterations = int(re.search(r"Number of Iterations\.*: *(\d+)", log).group(1))
    assert optimizer_iterations(prob.driver) == ipopt_iterations == result.iter_count
    assert [e for _, e in counts] == list(range(1, result.model_evals + 1))
    # IPOPT's table numbers its rows 0..N, one accepted point each: so does 'iter'.
    iterations = [i for i, _ in counts]
    assert iterations == sorted(iterations)
    assert set(iterations) == set(range(ipopt_iterations + 1))


def test_unknown_iteration_count_is_a_dash():
    assert optimizer_iterations(om.ScipyOptimizeDriver()) is None
    out = trim_line("stage", "hover", 1.5, 2e-9, 4, 3.25)
    assert out == (
        "           stage  trim hover           max scaled residual 1.500e+00 -> 2.000e-09"
        "    4 iterations     3.2 s"
    )


# ---------------------------------------------------------------------- trim lines


def test_trim_reports_a_line_per_condition_with_residuals_before_and_after():
    prob = build_analysis_problem(
        None, conditions=["hover"], lateral_trim=False, constraint_kinds=["trim"]
    )
    prob.run_model()
    # Independent: the driver-scaled residual (value - target) * scaler of every trim row.
    before = 0.0
    for meta in prob.model.get_constraints().values():
        _, scaler = determine_adder_scaler(meta["ref0"], meta["ref"], meta["adder"], None)
        value = np.ravel(prob.get_val(meta["source"]))
        value = value if meta["indices"] is None else value[meta["indices"].as_array()]
        before = max(before, np.max(np.abs((value - meta["equals"]) * (scaler or 1.0))))
    lines = []
    result = trim(prob, separate=False, report=lines.append, label="test")
    assert len(lines) == 1
    match = re.fullmatch(
        r" +test  trim hover +max scaled residual (\S+) -> (\S+) +(\d+) iterations +(\S+) s",
        lines[0],
    )
    assert match, lines[0]
    assert float(match.group(1)) == pytest.approx(before, rel=1e-3)
    assert float(match.group(2)) == pytest.approx(result.max_residual, rel=1e-3, abs=1e-12)
    assert float(match.group(2)) < 1e-6 < before
    assert int(match.group(3)) >= 1


# ---------------------------------------------------------------------- Ctrl-C


@pytest.fixture
def tiny_stage(monkeypatch):
    """solve_stage on the bowl problem: build_problem and trim replaced (no LPC model)."""
    built = {}

    def fake_build_problem(name, recorder_path=None, optimizer=None, driver_settings=None, **_):
        driver = make_driver(optimizer, **(driver_settings or {}))
        prob = bowl_problem(driver, stop_at=built.get("stop_at"), recorder_path=recorder_path)
        built["prob"] = prob
        return prob

    monkeypatch.setattr(warm_start, "build_problem", fake_build_problem)
    return built


def test_ctrl_c_in_trim_writes_run_stats_and_the_message_says_no_cases(
    tmp_path, monkeypatch, tiny_stage
):
    def interrupted_trim(prob, **_):
        prob.run_model()
        raise KeyboardInterrupt

    monkeypatch.setattr(warm_start, "trim", interrupted_trim)
    case_file = tmp_path / "stage.sql"
    with pytest.raises(KeyboardInterrupt):
        warm_start.solve_stage("full", str(case_file), optimizer="SLSQP", log=lambda *_: None)
    stats = read_run_stats(run_stats_path(case_file))
    assert stats["success"] is False
    assert stats["exit_status"] == "interrupted (Ctrl-C) during the trim"
    assert interrupt_message(case_file) == (
        "interrupted; stage.sql holds 0 driver cases and no 'final' case"
    )
    assert interrupt_message([tmp_path / "next.sql"]) == "interrupted; next.sql was not written"


def test_ctrl_c_in_slsqp_writes_run_stats_and_a_final_case(tmp_path, tiny_stage):
    tiny_stage["stop_at"] = 4  # the 4th model run raises KeyboardInterrupt
    case_file = tmp_path / "stage.sql"
    with pytest.raises(KeyboardInterrupt):
        warm_start.solve_stage(
            "full",
            str(case_file),
            optimizer="SLSQP",
            driver_settings={"disp": False},
            trim_first=False,
            log=lambda *_: None,
        )
    stats = json.loads(run_stats_path(case_file).read_text())
    assert stats["success"] is False
    assert stats["exit_status"] == "interrupted (Ctrl-C) during the optimization"
    # The driver's 4 model runs are 4 driver cases (OpenMDAO records the interrupted one too,
    # on leaving its recording block); the statistics count the 3 completed evaluations.
    cases = om.CaseReader(str(case_file)).list_cases("driver", recurse=False, out_stream=None)
    assert len(cases) == tiny_stage["prob"].model.bowl.calls == 4
    assert stats["model_evals"] == 3
    assert interrupt_message(tmp_path) == (
        "interrupted; stage.sql holds 4 driver cases and a 'final' case"
    )


def test_ipopt_stopped_by_ctrl_c_ends_the_stage_with_an_interrupt(tmp_path, tiny_stage):
    pytest.importorskip("cyipopt")
    tiny_stage["stop_at"] = 4
    case_file = tmp_path / "stage.sql"
    with pytest.raises(KeyboardInterrupt):
        warm_start.solve_stage(
            "subproblem_1",
            str(case_file),
            optimizer="IPOPT",
            driver_settings={"print_level": 0},
            trim_first=False,
            log=lambda *_: None,
        )
    assert tiny_stage["prob"].driver.user_stopped
    stats = read_run_stats(run_stats_path(case_file))
    assert stats["success"] is False and stats["exit_status"].startswith("interrupted")
    assert "and a 'final' case" in interrupt_message(case_file)


# ---------------------------------------------------------------------- quiet


QUIET_SCRIPT = textwrap.dedent(
    """
    import openmdao.api as om
    from lpc_mdo.drivers import make_driver

    prob = om.Problem(reports=False)
    prob.model.add_subsystem("p", om.ExecComp("f = (x - 3.0) ** 2"), promotes=["*"])
    prob.model.add_design_var("x", lower=-10.0, upper=10.0)
    prob.model.add_objective("f")
    prob.driver = make_driver("IPOPT", print_level={level})
    prob.setup()
    prob.run_driver()
    print("x =", round(float(prob.get_val("x")[0]), 6))
    """
)


@pytest.mark.parametrize("level", [0, 5])
def test_print_level_0_silences_ipopt_and_its_banner(capfd, level, tmp_path):
    pytest.importorskip("cyipopt")
    # A fresh process: IPOPT prints its banner once per process.
    subprocess.run(
        [sys.executable, "-c", QUIET_SCRIPT.format(level=level)], check=True, cwd=tmp_path
    )
    out, err = capfd.readouterr()
    assert "x = 3.0" in out
    if level == 0:
        assert out.strip() == "x = 3.0", out
        assert "Ipopt" not in err
    else:  # the control: the banner this test removes
        assert "This program contains Ipopt" in out


def test_cli_quiet_turns_progress_off_and_ipopt_output_off(monkeypatch, tmp_path):
    from lpc_mdo import cli

    seen = {}

    def fake_solve_stage(name, case_file, **kwargs):
        seen.update(kwargs)
        return warm_start.StageResult(name, case_file, True, 1, 0.0, 1.0, "ok")

    monkeypatch.setattr(warm_start, "solve_stage", fake_solve_stage)
    argv = ["optimize", "--problem", "subproblem_1", "--output-dir", str(tmp_path)]
    assert cli.main([*argv, "--quiet"]) == 0
    assert seen["progress"] is False and seen["driver_settings"]["print_level"] == 0
    assert seen["log"] is print  # the one-line stage summaries stay
    assert cli.main(argv) == 0
    assert seen["progress"] is True and seen["log"] is print


# ---------------------------------------------------------------------- motor group warning


def test_motor_groups_raise_no_atomic_group_warning_and_totals_are_exact():
    from lpc_mdo.groups.motor import MotorGroup

    prob = om.Problem(reports=False)
    prob.model.add_subsystem("motors", MotorGroup(num_motors=2, num_nodes=2), promotes=["*"])
    prob.model.add_design_var("length", lower=0.05, upper=0.3)
    prob.model.add_design_var("rotor_torque", lower=10.0, upper=2000.0)
    prob.model.add_objective("mass", index=0)
    prob.model.add_constraint("torque_margin", lower=0.1)
    prob.model.add_constraint("input_power", upper=1e6)
    prob.driver = Driver()
    prob.setup(force_alloc_complex=True)
    prob.set_val("rotor_torque", np.array([[300.0, 500.0], [400.0, 600.0]]))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        prob.final_setup()
        prob.run_driver()
    assert not [w for w in caught if "treated as atomic" in str(w.message)]
    # Each implicit component's own linear solve against complex-step totals.
    data = prob.check_totals(method="cs", out_stream=None)
    for key, entry in data.items():
        exact, cs = entry["J_fwd"], entry["J_fd"]
        np.testing.assert_allclose(exact, cs, rtol=1e-8, atol=1e-10 * np.abs(cs).max(), err_msg=key)
