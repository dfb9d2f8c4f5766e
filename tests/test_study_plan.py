"""The stage table (lpc_mdo.study_plan) is what the problems, the sequence and the CLI run."""

import pytest

from lpc_mdo import study_plan, warm_start
from lpc_mdo.cli import build_parser
from lpc_mdo.drivers import make_driver
from lpc_mdo.problems import build_problem
from lpc_mdo.study_plan import (
    SEQUENCE,
    STAGE_NAMES,
    STAGES,
    AcceptablePoint,
    OptimizerOptions,
    Stage,
    default_optimizer,
    stage,
)
from lpc_mdo.vehicle import reference_vehicle

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration


@pytest.fixture(scope="module")
def vehicle():
    return reference_vehicle()


def driver_state(driver):
    """Everything a driver runs with: its options and its native optimizer settings."""
    return dict(driver.options.items()), dict(driver.opt_settings)


def driver_value(driver, key):
    """Return what a make_driver keyword became (an option, its alias, or a native setting)."""
    if key in driver.options:
        return driver.options[key]
    if key == "max_iter" and "maxiter" in driver.options:
        return driver.options["maxiter"]
    return driver.opt_settings[key]


@pytest.mark.parametrize("in_sequence", [False, True], ids=["own", "in_sequence"])
@pytest.mark.parametrize("optimizer", ["IPOPT", "SLSQP"])
@pytest.mark.parametrize("name", STAGE_NAMES)
def test_build_problem_runs_the_stage_row(name, optimizer, in_sequence, vehicle):
    row = stage(name).optimizer_options(optimizer, in_sequence)
    settings = row.driver_settings(optimizer)
    prob = build_problem(name, vehicle=vehicle, optimizer=optimizer, in_sequence=in_sequence)
    assert driver_state(prob.driver) == driver_state(make_driver(optimizer, **settings))
    for key, value in settings.items():
        assert driver_value(prob.driver, key) == value, key
    # Settings a caller passes go over the row.
    prob = build_problem(
        name,
        vehicle=vehicle,
        optimizer=optimizer,
        in_sequence=in_sequence,
        driver_settings={"tol": 0.5},
    )
    assert prob.driver.options["tol"] == 0.5


def test_the_rows_hold_the_study_settings():
    # The full problem with SLSQP and the stages before it as steps of the sequence: the
    # numbers docs/theory/optimization.rst explains.
    full = stage("full").optimizer_options("SLSQP")
    assert (full.tol, full.max_iter) == (3e-4, 200)
    assert full.acceptable == AcceptablePoint(12, 3e-4, objective_change=5e-4)
    for name in SEQUENCE[:-1]:
        assert stage(name).optimizer_options("SLSQP", in_sequence=True).tol == 1e-3
        ipopt = stage(name).driver_settings("IPOPT", in_sequence=True)
        assert ipopt == {
            "tol": 1e-4,
            "max_iter": 200,
            "acceptable_iter": 5,
            "acceptable_constr_viol_tol": 1e-3,
            "acceptable_tol": 1e-3,
        }
    assert stage("full").driver_settings("SNOPT") == {}
    assert stage("baseline").continuation == (1.0, 10.0, 100.0)


def test_build_problem_declares_the_stage_problem(vehicle):
    presizing = build_problem("rotor_presizing", vehicle=vehicle)
    presizing.final_setup()
    assert type(presizing.driver).__name__ == "SlsqpDriver"  # the row's default optimizer
    ((objective, meta),) = presizing.model.get_objectives().items()
    assert objective == "hover.electrical_power" and meta["ref"] == 5.0e5
    assert presizing.model.condition_names == ["hover"]
    sub1 = build_problem("subproblem_1", vehicle=vehicle)
    sub1.final_setup()
    fraction = stage("subproblem_1").trust_region["battery_mass"]
    initial = vehicle.design_variables["battery_mass"].initial_array[0]
    dv = sub1.model.get_design_vars()["battery_mass"]
    assert (dv["lower"], dv["upper"]) == pytest.approx((initial * (1.0 - fraction), initial * 1.2))
    baseline = build_problem("baseline", vehicle=vehicle, optimizer="SLSQP")
    baseline.final_setup()
    assert list(baseline.model.get_objectives()) == ["baseline_objective"]


class _Built(Exception):
    """Raised by the replaced build_problem: the test needs its arguments, not a run."""


def test_solve_stage_hands_the_table_to_build_problem(monkeypatch, tmp_path):
    seen = {}

    def fake_build_problem(name, **kwargs):
        seen.update(kwargs, name=name)
        raise _Built

    monkeypatch.setattr(warm_start, "build_problem", fake_build_problem)
    for name in STAGE_NAMES:
        for in_sequence in (False, True):
            with pytest.raises(_Built):
                warm_start.solve_stage(name, str(tmp_path / "x.sql"), in_sequence=in_sequence)
            assert seen["name"] == name
            assert seen["optimizer"] == default_optimizer(name)
            assert seen["in_sequence"] is in_sequence


def test_run_sequence_runs_the_table_in_order(monkeypatch, tmp_path):
    calls = []

    def fake_solve_stage(name, case_file, **kwargs):
        calls.append((name, kwargs))
        return warm_start.StageResult(name, case_file, True, 1, 0.0, 1.0, "SUCCESS")

    monkeypatch.setattr(warm_start, "solve_stage", fake_solve_stage)
    warm_start.run_sequence(str(tmp_path), log=lambda *_: None)
    assert [name for name, _ in calls] == list(SEQUENCE)
    for name, kwargs in calls:
        spec = stage(name)
        assert kwargs["optimizer"] == default_optimizer(name)
        assert kwargs["in_sequence"] is True
        assert kwargs["rescale"] is spec.rescales
        assert kwargs["trim_first"] is True
    # Subproblem 4 and the full problem rescale; the stages before them hand over the design.
    rescaled = [name for name, kwargs in calls if kwargs["rescale"]]
    assert rescaled == ["subproblem_4", "full"]


def _subcommand(parser, name):
    (subparsers,) = [a for a in parser._actions if a.dest == "command"]
    return subparsers.choices[name]


def _action(command, flag):
    (action,) = [a for a in command._actions if flag in a.option_strings]
    return action


def test_cli_stage_names_and_help_come_from_the_table():
    parser = build_parser()
    optimize, sweep = _subcommand(parser, "optimize"), _subcommand(parser, "sweep")
    problem = _action(optimize, "--problem")
    assert tuple(problem.choices) == (*STAGE_NAMES, "sequence")
    assert tuple(_action(sweep, "--problem").choices) == STAGE_NAMES
    for s in STAGES:
        assert f"{s.name}: {s.summary}" in problem.help
        assert s.name in _action(optimize, "--optimizer").help
    assert ", ".join(SEQUENCE) in problem.help
    assert _action(optimize, "--max-iter").default is None  # the stage's limit
    assert "(default: the stage's, 200)" in _action(optimize, "--max-iter").help
    assert "SLSQP 3e-4 on the full problem" in _action(optimize, "--tol").help


def test_docs_rows_cover_every_stage():
    for rows_of in (study_plan.stage_rows, study_plan.run_rows):
        header, rows = rows_of()
        assert [row[0] for row in rows] == list(STAGE_NAMES)
        assert all(len(row) == len(header) for row in rows)
    header, rows = study_plan.settings_rows()
    assert [row[0] for row in rows] == [n for n in STAGE_NAMES for _ in ("IPOPT", "SLSQP")]
    assert rows[0][:3] == [
        "rotor_presizing",
        "IPOPT",
        "tol 1e-3; 200 iterations; acceptable: 10 iterations, violation 1e-3, error 1e-3",
    ]
    assert rows[-3][2:] == [
        "tol 3e-4; 200 iterations; acceptable: 12 iterations, violation 3e-4, objective "
        "change 5e-4",
        "as on its own",
    ]


def test_unknown_names_and_rows_are_refused():
    with pytest.raises(ValueError, match="problem name = 'subproblem_9'; allowed: "):
        stage("subproblem_9")
    own = study_plan.OWN_OPTIONS
    with pytest.raises(ValueError, match="handover = 'copy'"):
        Stage("x", "x", "SLSQP", own, kinds=("hover",), handover="copy")
    with pytest.raises(ValueError, match="optimizer = 'NLOPT'"):
        Stage("x", "x", "NLOPT", own, kinds=("hover",))
    with pytest.raises(ValueError, match=r"options has no settings for \['SNOPT'\]"):
        Stage("x", "x", "SLSQP", {"IPOPT": own["IPOPT"], "SLSQP": own["SLSQP"]})
    with pytest.raises(ValueError, match="SNOPT has no setting for tol"):
        Stage("x", "x", "SLSQP", {**own, "SNOPT": OptimizerOptions(tol=1e-6)})
    with pytest.raises(ValueError, match="needs the stage's condition kinds"):
        Stage("x", "x", "SLSQP", own, objective=("electrical_power", 1.0))
    with pytest.raises(TypeError):
        stage("full").options["SLSQP"] = OptimizerOptions()  # the table is read-only
