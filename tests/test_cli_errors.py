"""Bad command-line uses of ``lpc-mdo``: each is one line ``lpc-mdo: error: ...``, exit code 2.

Every misuse is caught before any model is built: the commands
themselves (``_analyze``, ``_optimize``, ``_sweep``, ``_report``) are replaced by stubs that fail
the test if they are reached, so a misuse that only fails later is a failure here, and no test
builds the model. The start-case files are small OpenMDAO case files written here: one holds the
reference vehicle's design variables in a problem case 'final' (what a start loads,
:func:`lpc_mdo.warm_start.solve_stage`), the others are broken in one way each.
"""

import os
import shutil
import sqlite3
import subprocess
import sys
import tempfile
from importlib import resources
from pathlib import Path

import numpy as np
import openmdao.api as om
import pytest

from lpc_mdo import cli
from lpc_mdo.cli import main
from lpc_mdo.core.checks import check_range
from lpc_mdo.vehicle import load_vehicle

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration

REFERENCE_TOML = resources.files("lpc_mdo") / "data" / "lpc_reference.toml"


def _design_variable_problem(path, sizes, driver_cases=True, final=True, nan=(), values=None):
    """Record a case file whose outputs are design variables named as the reference vehicle's.

    The design variables named in ``nan`` hold NaN (a run that failed), those in ``values`` the
    values given there; the others the reference's initial design.
    """
    prob = om.Problem(reports=False)
    ivc = prob.model.add_subsystem("design", om.IndepVarComp(), promotes=["*"])
    dvs = load_vehicle(None).design_variables
    for name, size in sizes.items():
        dv = dvs.get(name)
        if dv is not None and dv.size == size:  # the reference's initial design, in its units
            units = None if dv.units == "unitless" else dv.units
            value = np.ravel(dv.initial_array)
        else:
            units, value = None, np.ones(size)
        value = (values or {}).get(name, value)
        ivc.add_output(name, np.full(size, np.nan) if name in nan else value, units=units)
    prob.model.add_subsystem(
        "objective", om.ExecComp("y = 2.0 * x", x=np.ones(1)), promotes_outputs=["y"]
    )
    first = next(iter(sizes))
    prob.model.connect(first, "objective.x", src_indices=[0])
    first_dv = dvs.get(first)
    if first_dv is not None and first_dv.size == sizes[first]:  # stays within its own bounds
        prob.model.add_design_var(
            first, lower=first_dv.lower_array.ravel(), upper=first_dv.upper_array.ravel()
        )
    else:
        prob.model.add_design_var(first, lower=-10.0, upper=10.0)
    prob.model.add_objective("y")
    recorder = om.SqliteRecorder(str(path))
    if driver_cases:
        prob.driver = om.ScipyOptimizeDriver(optimizer="SLSQP", disp=False, maxiter=3)
        prob.driver.add_recorder(recorder)
    if final or not driver_cases:  # a problem recorder writes the file even with no case
        prob.add_recorder(recorder)
    prob.setup()
    prob.run_driver() if driver_cases else prob.final_setup()
    if final:
        prob.record("final")
    prob.cleanup()


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    """Case files, good and broken, and other inputs; name -> path (str)."""
    root = tmp_path_factory.mktemp("inputs")
    vehicle = load_vehicle(None)
    sizes = {name: dv.size for name, dv in vehicle.design_variables.items()}
    paths = {}

    def path(name):
        paths[name] = str(root / name)
        return root / name

    _design_variable_problem(path("good.sql"), sizes)
    _design_variable_problem(path("driver_only.sql"), sizes, final=False)
    _design_variable_problem(path("zero_cases.sql"), sizes, driver_cases=False, final=False)
    _design_variable_problem(path("foreign.sql"), {"x": 1, "z": 2})
    _design_variable_problem(path("wrong_shape.sql"), {**sizes, "rotor_radius": 3})
    _design_variable_problem(path("nan_start.sql"), sizes, driver_cases=False, nan=("wing_area",))
    _design_variable_problem(
        path("outside_bounds.sql"), sizes, driver_cases=False, values={"wing_area": 100.0}
    )
    good = (root / "good.sql").read_bytes()
    page = int.from_bytes(good[16:18], "big")
    assert len(good) % page == 0 and len(good) // page > 4
    path("truncated.sql").write_bytes(good[: len(good) // 2 + 100])
    path("truncated_at_page.sql").write_bytes(good[: 2 * page])
    damaged = bytearray(good)
    for i in range(200, len(damaged), 50):
        damaged[i] ^= 0xFF
    path("corrupted.sql").write_bytes(bytes(damaged))
    path("random_bytes.sql").write_bytes(np.random.default_rng(18).bytes(5000))
    path("empty.sql").write_bytes(b"")
    with sqlite3.connect(path("not_a_recorder.sqlite")) as con:
        con.execute("CREATE TABLE measurements (x REAL)")
    con.close()
    path("vehicle.toml").write_text(REFERENCE_TOML.read_text(encoding="utf-8"), encoding="utf-8")
    text = REFERENCE_TOML.read_text(encoding="utf-8")
    path("unknown_key.toml").write_text(text.replace("[wing]\n", "[wing]\nspam = 1\n", 1))
    path("not_toml.toml").write_text("[wing\narea = \n")
    path("binary.toml").write_bytes(b"\xff\xfe\x00\x81" + os.urandom(64))
    path("a_file.txt").write_text("a regular file\n")
    os.mkfifo(path("pipe.toml"))  # reading it would block: refused as not a regular file
    path("empty_folder").mkdir()
    path("folder_with_empty_run").mkdir()
    shutil.copy(paths["zero_cases.sql"], root / "folder_with_empty_run" / "cases.sql")
    path("good_folder").mkdir()
    shutil.copy(paths["good.sql"], root / "good_folder" / "cases.sql")
    (root / "run").mkdir()  # a finished run: its full.sql is a start case for the next
    shutil.copy(paths["good.sql"], root / "run" / "full.sql")
    paths["run"], paths["run_full.sql"] = str(root / "run"), str(root / "run" / "full.sql")
    # Earlier runs' folders with a folder (or a pipe) where the command writes a file.
    for folder, name in [
        ("leftover_case_file", "cases.sql"),
        ("leftover_table", "constraints.md"),
        ("leftover_stage", "full.sql"),
        ("leftover_run_stats", "full.run_stats.json"),
        ("leftover_summary", "sweep_summary.csv"),
        ("leftover_index", "index.md"),
    ]:
        path(folder).mkdir()
        (root / folder / name).mkdir()
    path("leftover_pipe").mkdir()
    os.mkfifo(root / "leftover_pipe" / "full.sql")
    paths["missing"] = str(root / "missing" / "nothing.sql")
    paths["root"] = str(root)
    return paths


def _unwritable_folder(tmp_path):
    """Return a folder no file can be created in: mode 0o555, or for root a system folder."""
    folder = tmp_path / "read_only"
    folder.mkdir()
    folder.chmod(0o555)
    for candidate in (folder, Path("/sys"), Path("/proc/self")):
        try:
            with tempfile.TemporaryFile(dir=candidate):
                pass
        except OSError:
            return str(candidate)
    return None  # root on a system without a read-only folder


@pytest.fixture
def paths(files, tmp_path):
    """``files`` plus per-test paths: an unwritable folder and a fresh output folder."""
    out = dict(files)
    out["unwritable"] = _unwritable_folder(tmp_path)
    out["out"] = str(tmp_path / "out")
    yield out
    (tmp_path / "read_only").chmod(0o755)


@pytest.fixture(autouse=True)
def commands_must_not_start(monkeypatch):
    """Replace the commands: a misuse must be caught before any long work starts."""
    reached = []

    def stub(args):
        reached.append(args)
        return 0

    for name in ("_analyze", "_optimize", "_sweep", "_report"):
        monkeypatch.setattr(cli, name, stub)
    return reached


@pytest.fixture
def no_pyoptsparse(monkeypatch):
    """Behave as if pyoptsparse were not installed (whether it is or not)."""
    import lpc_mdo.drivers

    monkeypatch.setattr(lpc_mdo.drivers, "pyoptsparse_optimizers", lambda: ())


# (id, argv with {placeholders} of the ``paths`` fixture, the argument the message names)
FULL = ["optimize", "--problem", "full", "--output-dir", "{out}"]
SWEEP = ["sweep", "--output-dir", "{out}"]
MISUSES = [
    # Outputs over inputs, paths that are no files, numbers beyond any sensible run
    (
        "n2_over_the_vehicle_file",
        [
            "analyze",
            "--vehicle",
            "{vehicle.toml}",
            "--n2",
            "{vehicle.toml}",
            "--output-dir",
            "{out}",
        ],
        "--n2",
    ),
    (
        "output_over_the_start_case",
        [
            "optimize",
            "--problem",
            "full",
            "--start-case",
            "{run_full.sql}",
            "--output-dir",
            "{run}",
        ],
        "--output-dir",
    ),
    ("n2_empty", ["analyze", "--output-dir", "{out}", "--n2", ""], "--n2"),
    # A file named with a trailing '/', an empty path: one line, not a traceback or "a folder".
    ("vehicle_trailing_slash", ["analyze", "--vehicle", "{vehicle.toml}/"], "ends with '/'"),
    ("report_trailing_slash", ["report", "{good.sql}/", "--output-dir", "{out}"], "ends with '/'"),
    ("vehicle_empty", ["analyze", "--vehicle", ""], "is empty"),
    (
        "start_case_of_nan",
        [
            "optimize",
            "--problem",
            "full",
            "--start-case",
            "{nan_start.sql}",
            "--output-dir",
            "{out}",
        ],
        "not numbers",
    ),
    (
        "start_case_outside_the_bounds",
        [
            "optimize",
            "--problem",
            "full",
            "--start-case",
            "{outside_bounds.sql}",
            "--output-dir",
            "{out}",
        ],
        "outside the vehicle file's bounds",
    ),
    (
        "report_of_another_vehicle",
        ["report", "{wrong_shape.sql}", "--output-dir", "{out}"],
        "is a run of another vehicle",
    ),
    (
        "n2_is_the_lock_file",
        ["analyze", "--output-dir", "{out}", "--n2", "{out}/.lpc-mdo.lock"],
        "--n2",
    ),
    ("abbreviated_option", ["analyze", "--out", "{out}", "--output-dir", "{out}"], "--out"),
    ("report_empty", ["report", "", "--output-dir", "{out}"], "is empty"),
    ("n2_a_folder_name", ["analyze", "--output-dir", "{out}", "--n2", "{out}/n2dir/"], "--n2"),
    (
        "n2_over_the_case_file",
        ["analyze", "--output-dir", "{out}", "--n2", "{out}/cases.sql"],
        "--n2",
    ),
    (
        "n2_over_the_constraint_table",
        ["analyze", "--output-dir", "{out}", "--n2", "{out}/constraints.md"],
        "--n2",
    ),
    ("n2_is_the_output_dir", ["analyze", "--output-dir", "{out}", "--n2", "{root}"], "--n2"),
    # the output folder does not exist yet: the command creates it where the diagram would go
    ("n2_is_the_new_output_dir", ["analyze", "--output-dir", "{out}", "--n2", "{out}"], "--n2"),
    (
        "n2_is_the_new_output_dir_spelled_otherwise",
        ["analyze", "--output-dir", "{out}", "--n2", "{out}/../out"],
        "--n2",
    ),
    (
        "n2_is_a_folder_of_the_new_output_dir",
        ["analyze", "--output-dir", "{out}/a/b", "--n2", "{out}/a"],
        "--n2",
    ),
    (
        "n2_under_the_case_file",
        ["analyze", "--output-dir", "{out}", "--n2", "{out}/cases.sql/n2.html"],
        "--n2",
    ),
    ("n2_a_device", ["analyze", "--output-dir", "{out}", "--n2", "/dev/null"], "--n2"),
    ("n2_a_pipe", ["analyze", "--output-dir", "{out}", "--n2", "{pipe.toml}"], "--n2"),
    (
        "output_dir_twice",
        ["analyze", "--output-dir", "{out}", "--output-dir", "{out}/b"],
        "--output-dir",
    ),
    ("max_iter_twice", [*FULL, "--max-iter", "5", "--max-iter=7"], "--max-iter"),
    ("tol_1e300", [*FULL, "--tol", "1e300"], "--tol"),
    ("tol_1e-300", [*FULL, "--tol", "1e-300"], "--tol"),
    (
        "values_alike_to_6_digits",
        [
            *SWEEP,
            "--start-case",
            "{good.sql}",
            "--parameter",
            "final_soc",
            "--values",
            "0.2",
            "0.2000001",
        ],
        "--values",
    ),
    ("output_dir_empty", ["analyze", "--output-dir", ""], "--output-dir"),
    ("output_dir_blank", ["analyze", "--output-dir", "  "], "--output-dir"),
    ("max_iter_1e15", [*FULL, "--max-iter", "1000000000000000"], "--max-iter"),
    ("processes_1e6", [*FULL, "--processes", "1000000"], "--processes"),
    (
        "values_energy_density_1e9",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "energy_density", "--values", "1e9"],
        "--values",
    ),
    (
        "values_payload_above_the_gross_mass",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "payload", "--values", "5000"],
        "--values",
    ),
    ("vehicle_pipe", ["analyze", "--vehicle", "{pipe.toml}", "--output-dir", "{out}"], "--vehicle"),
    ("mpi_on_one_rank", [*SWEEP, "--start-case", "{good.sql}", "--mpi"], "--mpi"),
    # --start-case files
    ("start_case_corrupted", [*FULL, "--start-case", "{corrupted.sql}"], "--start-case"),
    ("start_case_truncated", [*FULL, "--start-case", "{truncated.sql}"], "--start-case"),
    (
        "start_case_truncated_page",
        [*FULL, "--start-case", "{truncated_at_page.sql}"],
        "--start-case",
    ),
    ("start_case_not_recorder", [*FULL, "--start-case", "{not_a_recorder.sqlite}"], "--start-case"),
    ("start_case_zero_cases", [*FULL, "--start-case", "{zero_cases.sql}"], "--start-case"),
    ("start_case_no_final", [*FULL, "--start-case", "{driver_only.sql}"], "--start-case"),
    ("start_case_toml", [*FULL, "--start-case", "{vehicle.toml}"], "--start-case"),
    ("start_case_empty_file", [*FULL, "--start-case", "{empty.sql}"], "--start-case"),
    ("start_case_random_bytes", [*FULL, "--start-case", "{random_bytes.sql}"], "--start-case"),
    ("start_case_other_model", [*FULL, "--start-case", "{foreign.sql}"], "--start-case"),
    ("start_case_wrong_shape", [*FULL, "--start-case", "{wrong_shape.sql}"], "--start-case"),
    ("start_case_missing", [*FULL, "--start-case", "{missing}"], "--start-case"),
    ("start_case_folder", [*FULL, "--start-case", "{empty_folder}"], "--start-case"),
    (
        "sequence_start_case_zero",
        ["optimize", "--optimizer", "SLSQP", "--start-case", "{zero_cases.sql}"],
        "--start-case",
    ),
    ("sweep_start_case_zero", [*SWEEP, "--start-case", "{zero_cases.sql}"], "--start-case"),
    ("sweep_start_case_toml", [*SWEEP, "--start-case", "{vehicle.toml}"], "--start-case"),
    ("sweep_without_start_case", SWEEP, "--start-case"),
    # output folders and files
    ("analyze_unwritable_output", ["analyze", "--output-dir", "{unwritable}/out"], "--output-dir"),
    ("analyze_output_under_file", ["analyze", "--output-dir", "{a_file.txt}/out"], "--output-dir"),
    ("optimize_output_is_file", ["optimize", "--output-dir", "{a_file.txt}"], "--output-dir"),
    (
        "sweep_output_under_file",
        ["sweep", "--start-case", "{good.sql}", "--output-dir", "{a_file.txt}/sweep"],
        "--output-dir",
    ),
    (
        "report_unwritable_output",
        ["report", "{good.sql}", "--output-dir", "{unwritable}"],
        "--output-dir",
    ),
    ("n2_under_file", ["analyze", "--output-dir", "{out}", "--n2", "{a_file.txt}/n2.html"], "--n2"),
    ("folder_named_cases_sql", ["analyze", "--output-dir", "{leftover_case_file}"], "--output-dir"),
    (
        "folder_named_constraints_md",
        ["analyze", "--output-dir", "{leftover_table}"],
        "--output-dir",
    ),
    (
        "folder_named_full_sql",
        ["optimize", "--optimizer", "SLSQP", "--output-dir", "{leftover_stage}"],
        "--output-dir",
    ),
    (
        "folder_named_run_stats",
        ["optimize", "--problem", "full", "--output-dir", "{leftover_run_stats}"],
        "--output-dir",
    ),
    (
        "pipe_named_full_sql",
        ["optimize", "--problem", "full", "--output-dir", "{leftover_pipe}"],
        "--output-dir",
    ),
    (
        "folder_named_sweep_summary",
        ["sweep", "--start-case", "{good.sql}", "--output-dir", "{leftover_summary}"],
        "--output-dir",
    ),
    (
        "folder_named_report_index",
        ["report", "{good.sql}", "--output-dir", "{leftover_index}"],
        "--output-dir",
    ),
    ("n2_is_folder", ["analyze", "--output-dir", "{out}", "--n2", "{empty_folder}"], "--n2"),
    ("n2_unwritable", ["analyze", "--output-dir", "{out}", "--n2", "{unwritable}/n2.html"], "--n2"),
    # integers
    ("max_iter_negative", [*FULL, "--max-iter", "-1"], "--max-iter"),
    ("max_iter_zero", [*FULL, "--max-iter", "0"], "--max-iter"),
    ("max_iter_not_integer", [*FULL, "--max-iter", "2.5"], "--max-iter"),
    ("max_iter_text", [*FULL, "--max-iter", "many"], "--max-iter"),
    (
        "sweep_processes_zero",
        [*SWEEP, "--start-case", "{good.sql}", "--processes", "0"],
        "--processes",
    ),
    (
        "sweep_max_iter_negative",
        [*SWEEP, "--start-case", "{good.sql}", "--max-iter", "-5"],
        "--max-iter",
    ),
    # vehicle files
    ("vehicle_missing", ["analyze", "--vehicle", "{missing}"], "--vehicle"),
    ("vehicle_folder", ["analyze", "--vehicle", "{empty_folder}"], "--vehicle"),
    ("vehicle_is_case_file", [*FULL, "--vehicle", "{good.sql}"], "--vehicle"),
    ("vehicle_binary", ["analyze", "--vehicle", "{binary.toml}"], "--vehicle"),
    ("vehicle_unknown_key", ["analyze", "--vehicle", "{unknown_key.toml}"], "--vehicle"),
    ("vehicle_not_toml", ["report", "{good.sql}", "--vehicle", "{not_toml.toml}"], "--vehicle"),
    # report inputs
    ("report_missing_folder", ["report", "{missing}", "--output-dir", "{out}"], "'cases'"),
    ("report_empty_folder", ["report", "{empty_folder}", "--output-dir", "{out}"], "'cases'"),
    (
        "report_zero_case_run",
        ["report", "{folder_with_empty_run}", "--output-dir", "{out}"],
        "'cases'",
    ),
    ("report_toml", ["report", "{vehicle.toml}", "--output-dir", "{out}"], "'cases'"),
    ("report_corrupted", ["report", "{corrupted.sql}", "--output-dir", "{out}"], "'cases'"),
    # optimizers
    ("optimizer_snopt_missing", [*FULL, "--optimizer", "SNOPT"], "--optimizer"),
    (
        "sweep_optimizer_snopt",
        [*SWEEP, "--start-case", "{good.sql}", "--optimizer", "snopt"],
        "--optimizer",
    ),
    ("optimizer_unknown", [*FULL, "--optimizer", "NLOPT"], "--optimizer"),
    ("tol_negative", [*FULL, "--tol", "-1e-6"], "--tol"),
    ("tol_text", [*FULL, "--tol", "tight"], "--tol"),
    # sweep values
    (
        "values_without_parameter",
        [*SWEEP, "--start-case", "{good.sql}", "--values", "300"],
        "--values",
    ),
    (
        "values_negative_energy_density",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "energy_density", "--values", "-300"],
        "--values",
    ),
    (
        "values_final_soc_above_one",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "final_soc", "--values", "1.5"],
        "--values",
    ),
    (
        "values_nan",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "final_soc", "--values", "nan"],
        "--values",
    ),
    ("values_text", [*SWEEP, "--start-case", "{good.sql}", "--values", "high"], "--values"),
    (
        "payload_without_values",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "payload"],
        "--parameter",
    ),
    (
        "values_negative_payload",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "payload", "--values", "-5"],
        "--values",
    ),
    # a swept limit whose constraint the points' problem leaves out: every point the same
    (
        "static_margin_limit_without_static_margin",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "min_static_margin"]
        + ["--values", "0.05", "0.1", "--static-margin", "off"],
        "--static-margin",
    ),
    (
        "static_margin_limit_in_a_problem_without_it",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "min_static_margin"]
        + ["--values", "0.05", "0.1", "--problem", "subproblem_1"],
        "--problem",
    ),
    (
        "noise_limit_in_a_problem_without_noise",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "max_noise"]
        + ["--values", "70", "75", "--problem", "subproblem_4"],
        "--problem",
    ),
    (
        "paper_sweeps_in_a_problem_without_soc",
        [*SWEEP, "--start-case", "{good.sql}", "--problem", "subproblem_3"],
        "--problem",
    ),
    # the command line itself
    ("unknown_command", ["fly"], "command"),
    ("unknown_problem", ["optimize", "--problem", "subproblem_9"], "--problem"),
    ("unknown_option", ["analyze", "--bogus"], "--bogus"),
    # an option of a command given before the command
    ("vehicle_before_the_command", ["--vehicle", "{vehicle.toml}", "analyze"], "--vehicle"),
    ("vehicle_equals_before_the_command", ["--vehicle={vehicle.toml}", "analyze"], "--vehicle"),
    ("flag_before_the_command", ["--no-trim", "analyze", "--output-dir", "{out}"], "--no-trim"),
    ("option_before_no_command", ["--output-dir", "{out}"], "--output-dir"),
    ("prefix_before_the_command", ["--start", "{good.sql}", "sweep"], "--start"),
    (
        "unknown_parameter",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "wing_area"],
        "--parameter",
    ),
]


def _assert_one_line_error(rc, captured, argument):
    """Assert exit code 2, no traceback, one stderr line naming ``argument`` (capsys or run)."""
    out = captured.out if hasattr(captured, "out") else captured.stdout
    err = captured.err if hasattr(captured, "err") else captured.stderr
    assert rc == 2, err
    assert "Traceback" not in err and "Traceback" not in out
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("lpc-mdo: error: ")
    assert argument in lines[0], lines[0]


def _format(template, paths):
    return [_fill(arg, paths) for arg in template]


def _fill(arg, paths):
    for key, value in paths.items():
        if value is not None:
            arg = arg.replace("{" + key + "}", value)
    assert "{" not in arg, f"unknown placeholder in {arg!r}"
    return arg


@pytest.mark.parametrize(
    ("argv", "argument"), [m[1:] for m in MISUSES], ids=[m[0] for m in MISUSES]
)
def test_misuse_is_one_line_error(
    argv, argument, paths, capsys, commands_must_not_start, no_pyoptsparse
):
    if any("{unwritable}" in arg for arg in argv) and paths["unwritable"] is None:
        pytest.skip("no folder is unwritable for this user")
    rc = main(_format(argv, paths))
    _assert_one_line_error(rc, capsys.readouterr(), argument)
    assert not commands_must_not_start, "the command started: the error was not caught early"


def test_enough_misuses():
    # The 27 misuses the command line was reviewed against, and more kinds.
    assert len(MISUSES) >= 30
    assert len({m[0] for m in MISUSES}) == len(MISUSES)


# --- The checks let good input through (else the misuses above would prove nothing) ---------


@pytest.mark.parametrize(
    "argv",
    [
        [*FULL, "--start-case", "{good.sql}", "--max-iter", "1"],
        [
            "optimize",
            "--problem",
            "full",
            "--output-dir",
            "{out}/new/deeper",
            "--optimizer",
            "slsqp",
        ],
        [
            *SWEEP,
            "--start-case",
            "{good.sql}",
            "--parameter",
            "final_soc",
            "--values",
            "0.2",
            "0.3",
        ],
        [
            *SWEEP,
            "--start-case",
            "{good.sql}",
            "--parameter",
            "min_static_margin",
            "--values",
            "0.05",
            "0.1",
            "--static-margin",
            "on",
        ],
        ["analyze", "--output-dir", "{out}", "--n2", "{out}/missing_folder/n2.html"],
        ["analyze", "--vehicle", "{vehicle.toml}", "--output-dir", "{out}"],
        ["report", "{good_folder}", "--output-dir", "{out}"],
        ["report", "{good.sql}", "--output-dir", "{out}"],
    ],
    ids=[
        "start_case",
        "new_output_dir",
        "sweep_values",
        "static_margin_limit_sweep",
        "n2_new_folder",
        "vehicle",
        "report_folder",
        "report_file",
    ],
)
def test_good_input_reaches_the_command(argv, paths, capsys, commands_must_not_start):
    assert main(_format(argv, paths)) == 0, capsys.readouterr().err
    assert len(commands_must_not_start) == 1
    assert capsys.readouterr().err == ""


def test_the_checks_create_nothing(paths, capsys):
    # The output folder is created by the command, not by the checks of a failing command line.
    assert main(["optimize", "--output-dir", paths["out"], "--max-iter", "-1"]) == 2
    assert not Path(paths["out"]).exists()


def test_optimizer_name_is_case_insensitive(paths, commands_must_not_start):
    assert main([*_format(FULL, paths), "--optimizer", "slsqp"]) == 0
    assert commands_must_not_start[0].optimizer == "SLSQP"


def test_default_ipopt_without_cyipopt(paths, capsys, monkeypatch, no_pyoptsparse):
    monkeypatch.setitem(sys.modules, "cyipopt", None)  # import cyipopt raises ImportError
    # Subproblem 2's default optimizer is IPOPT (lpc_mdo.study_plan.default_optimizer).
    rc = main(["optimize", "--problem", "subproblem_2", "--output-dir", paths["out"]])
    _assert_one_line_error(rc, capsys.readouterr(), "--optimizer")
    # An explicit SLSQP needs nothing beyond SciPy.
    argv = ["optimize", "--problem", "subproblem_1", "--optimizer", "SLSQP"]
    assert main([*argv, "--output-dir", paths["out"]]) == 0


def test_mpi_without_mpi4py(paths, capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "mpi4py", None)  # import mpi4py raises ImportError
    rc = main(["sweep", "--start-case", paths["good.sql"], "--mpi", "--output-dir", paths["out"]])
    _assert_one_line_error(rc, capsys.readouterr(), "--mpi")


def test_messages_say_what_is_allowed(paths, capsys, no_pyoptsparse):
    cases = {
        (*FULL, "--max-iter", "-1"): "'--max-iter' = -1 is out of range: must be in [1, 1e+06]",
        (
            "analyze",
            "--vehicle",
            "{vehicle.toml}",
            "--n2",
            "{vehicle.toml}",
        ): "is the file of --vehicle, which the command reads",
        ("analyze", "--vehicle", "{pipe.toml}"): "is not a regular file (a pipe or device)",
        ("analyze", "--output-dir", ""): "'--output-dir' = '' is empty",
        (*FULL, "--start-case", "{zero_cases.sql}"): "holds no cases",
        (*FULL, "--start-case", "{driver_only.sql}"): "not the problem case 'final'",
        (*FULL, "--start-case", "{vehicle.toml}"): "is a TOML file",
        (*FULL, "--start-case", "{truncated_at_page.sql}"): "is truncated",
        (*FULL, "--start-case", "{not_a_recorder.sqlite}"): "not an OpenMDAO case file",
        (*FULL, "--optimizer", "SNOPT"): "pyoptsparse",
        ("report", "{empty_folder}"): "without case files",
        ("analyze", "--output-dir", "{a_file.txt}/out"): "is a regular file, not a folder",
        ("analyze", "--n2", "/dev/null"): "'--n2' = '/dev/null' is not a regular file",
        ("analyze", "--output-dir", "{leftover_case_file}"): "cases.sql' where the command writes",
        ("analyze", "--output-dir", "{leftover_table}"): "holds a folder",
        ("optimize", "--output-dir", "{leftover_stage}"): "writes the file full.sql",
        ("optimize", "--output-dir", "{leftover_run_stats}"): "writes the file full.run_stats.json",
        ("optimize", "--output-dir", "{leftover_pipe}"): "holds a device, pipe or socket",
        ("sweep", "--start-case", "{good.sql}", "--output-dir", "{leftover_summary}"): (
            "writes the file sweep_summary.csv"
        ),
        ("report", "{good.sql}", "--output-dir", "{leftover_index}"): "writes the file index.md",
        (
            *SWEEP,
            "--start-case",
            "{good.sql}",
            "--parameter",
            "min_static_margin",
            "--values",
            "0.1",
            "--static-margin",
            "off",
        ): "every point would be the same problem: must be on",
        (*SWEEP, "--start-case", "{good.sql}", "--parameter", "max_noise", "--values", "70")
        + ("--problem", "subproblem_4"): "has no noise constraint",
        ("--vehicle", "{vehicle.toml}", "analyze"): (
            "'--vehicle' must come after the command: lpc-mdo analyze --vehicle ... "
            "(commands: analyze, size, optimize, sweep, report)"
        ),
        ("--max-iter", "5", "sweep", "--start-case", "{good.sql}"): "lpc-mdo sweep --max-iter",
        ("--n2", "n2.html", "optimize"): "lpc-mdo analyze --n2 ... (commands: analyze, "
        "size, optimize, sweep, report); optimize has no --n2",
        ("--start", "{good.sql}", "sweep"): "lpc-mdo sweep --start-case ...",
        ("analyze", "--output-dir", "{out}", "--n2", "{out}/../out"): "is the folder --output-dir",
        ("analyze", "--output-dir", "{out}/a/b", "--n2", "{out}/a"): "is a folder of --output-dir",
        ("analyze", "--output-dir", "{out}", "--n2", "{out}/cases.sql/x"): "lies under cases.sql",
        ("analyze", "--output-dir", "{out}", "--n2", "{out}"): "is the folder --output-dir",
    }
    for argv, text in cases.items():
        assert main(_format(argv, paths)) == 2
        assert text in capsys.readouterr().err, argv


# --- Long values are cut in the message -------------------------------------------------------

LONG = "x" * 5000
#: (id, argv, the argument the message names, the length the message gives)
LONG_VALUES = [
    ("vehicle", ["analyze", "--vehicle", "{root}/" + LONG], "--vehicle", "characters)"),
    ("output_dir", ["analyze", "--output-dir", "{root}/" + LONG], "--output-dir", "characters)"),
    (
        "output_dir_under_a_file",
        ["analyze", "--output-dir", "{a_file.txt}/" + LONG],
        "--output-dir",
        "characters)",
    ),
    ("n2", ["analyze", "--output-dir", "{out}", "--n2", "{root}/" + LONG], "--n2", "characters)"),
    ("start_case", [*FULL, "--start-case", "{root}/" + LONG], "--start-case", "characters)"),
    ("report_cases", ["report", "{root}/" + LONG], "'cases'", "characters)"),
    ("optimizer", [*FULL, "--optimizer", LONG], "--optimizer", "(5000 characters)"),
    ("problem", ["optimize", "--problem", LONG], "--problem", "(5000 characters)"),
    (
        "parameter_a_million",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "p" * 10**6],
        "--parameter",
        "(1000000 characters)",
    ),
    ("command", [LONG], "command", "(5000 characters)"),
    ("unrecognized", ["analyze", LONG], "unrecognized", "(5000 characters)"),
    ("unrecognized_many", ["analyze", *["x"] * 10**5], "unrecognized", "and 99997 more"),
    (
        "values_without_parameter",
        [*SWEEP, "--start-case", "{good.sql}", "--values", *[str(v) for v in range(500)]],
        "--values",
        "(500 values)",
    ),
    (
        "values_too_many",
        [*SWEEP, "--start-case", "{good.sql}", "--parameter", "final_soc", "--values"]
        + [str(0.1 + 1e-6 * i) for i in range(10**5)],
        "--values",
        "(100000 values)",
    ),
]


@pytest.mark.parametrize(
    ("argv", "argument", "length"), [m[1:] for m in LONG_VALUES], ids=[m[0] for m in LONG_VALUES]
)
def test_a_long_value_is_cut(argv, argument, length, paths, capsys, commands_must_not_start):
    rc = main(_format(argv, paths))
    captured = capsys.readouterr()
    _assert_one_line_error(rc, captured, argument)
    assert length in captured.err
    assert len(captured.err) < 700, captured.err
    assert not commands_must_not_start


def test_too_many_sweep_values_are_refused_first(paths, capsys, monkeypatch):
    # The count is checked before anything that takes time per value (a vehicle per value).
    def no_vehicle(*args):
        raise AssertionError("a vehicle was made for a value")

    monkeypatch.setattr(cli, "sweep_vehicle", no_vehicle)
    values = [str(0.1 + 1e-6 * i) for i in range(cli.MAX_SWEEP_VALUES + 1)]
    argv = [*_format(SWEEP, paths), "--start-case", paths["good.sql"], "--parameter", "final_soc"]
    rc = main([*argv, "--values", *values])
    captured = capsys.readouterr()
    _assert_one_line_error(rc, captured, "--values")
    assert f"must be at most {cli.MAX_SWEEP_VALUES} values" in captured.err


# --- --debug and bugs ----------------------------------------------------------------------


@pytest.mark.parametrize("where", ["before", "after"])
def test_debug_shows_the_traceback(where, paths, capsys):
    argv = [*_format(FULL, paths), "--max-iter", "-1"]
    argv = ["--debug", *argv] if where == "before" else [*argv, "--debug"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert "Traceback" in err
    assert err.splitlines()[-1] == (
        "lpc-mdo: error: '--max-iter' = -1 is out of range: must be in [1, 1e+06]"
    )


def test_a_bug_keeps_its_traceback(paths, capsys, monkeypatch):
    def broken(args):
        raise RuntimeError("boom")

    monkeypatch.setattr(cli, "_analyze", broken)
    assert main(["analyze", "--output-dir", paths["out"]]) == 1
    err = capsys.readouterr().err
    assert "Traceback" in err and "RuntimeError: boom" in err
    last = err.splitlines()[-1]
    assert last.startswith("lpc-mdo: internal error: RuntimeError: boom") and "bug" in last


def test_value_error_of_a_library_is_a_bug(paths, capsys, monkeypatch):
    def broken(args):
        np.zeros(2).reshape(3)  # a ValueError raised by numpy, not by lpc_mdo's checks

    monkeypatch.setattr(cli, "_analyze", broken)
    assert main(["analyze", "--output-dir", paths["out"]]) == 1
    assert "Traceback" in capsys.readouterr().err


def test_value_error_of_lpc_mdo_is_a_user_error(paths, capsys, monkeypatch):
    def checked(args):
        check_range("num_radial", 1, lower=2)

    monkeypatch.setattr(cli, "_analyze", checked)
    rc = main(["analyze", "--output-dir", paths["out"]])
    _assert_one_line_error(rc, capsys.readouterr(), "'num_radial' = 1")


# --- Through a real process: nothing but the one line reaches the terminal -----------------

SUBPROCESS_MISUSES = [
    (["optimize", "--problem", "full", "--start-case", "{corrupted.sql}"], "--start-case"),
    (["optimize", "--max-iter", "-1"], "--max-iter"),
    (["report", "{empty_folder}"], "'cases'"),
    (["analyze", "--vehicle", "{binary.toml}"], "--vehicle"),
]


@pytest.mark.parametrize(
    ("argv", "argument"),
    SUBPROCESS_MISUSES,
    ids=["corrupted_start_case", "max_iter", "report_empty", "binary_vehicle"],
)
def test_misuse_in_a_process(argv, argument, paths):
    run = subprocess.run(
        [sys.executable, "-m", "lpc_mdo.cli", *_format(argv, paths)],
        capture_output=True,
        text=True,
        cwd=paths["root"],
        timeout=120,
    )
    _assert_one_line_error(run.returncode, run, argument)


def test_entry_point_in_a_process(paths):
    script = shutil.which("lpc-mdo") or shutil.which(
        "lpc-mdo", path=str(Path(sys.executable).parent)
    )
    if script is None:
        pytest.skip("the lpc-mdo entry point is not installed")
    run = subprocess.run(
        [script, "sweep", "--start-case", paths["good.sql"], "--processes", "0"],
        capture_output=True,
        text=True,
        cwd=paths["root"],
        timeout=120,
    )
    _assert_one_line_error(run.returncode, run, "--processes")


# --- one run per output folder ----------------------------------------------------------------


def test_a_folder_in_use_is_refused_and_a_stale_lock_taken_over(paths, capsys, tmp_path):
    from lpc_mdo.run_lock import LOCK_NAME, _start_time

    out = Path(paths["out"])
    out.mkdir()
    # A running process holds the folder: its id and start time are in the lock (whatever its
    # command line: lpc-mdo run from a Python script holds it too).
    running = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    try:
        (out / LOCK_NAME).write_text(f"{running.pid} {_start_time(running.pid)}\n")
        rc = main(["analyze", "--output-dir", str(out)])
        _assert_one_line_error(rc, capsys.readouterr(), "--output-dir")
    finally:
        running.kill()
        running.wait()
    # The same lock once its process has ended: stale, taken over and removed at the end.
    assert main(["analyze", "--output-dir", str(out)]) == 0
    assert not (out / LOCK_NAME).exists()


@pytest.mark.parametrize(
    "error",
    [
        sqlite3.OperationalError("database or disk is full"),
        OSError(28, "No space left on device"),
    ],
    ids=["sqlite_disk_full", "no_space_left"],
)
def test_a_failed_write_is_one_line_and_keeps_the_case_files(paths, capsys, monkeypatch, error):
    out = Path(paths["out"])

    def fill_the_disk(args):
        out.mkdir(exist_ok=True)
        (out / "subproblem_1.sql").write_bytes(b"an earlier stage")
        raise error

    monkeypatch.setattr(cli, "_optimize", fill_the_disk)
    assert main([*_format(FULL, paths)]) == 1
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1, err
    assert f"writing into '--output-dir' = '{out}' failed" in err
    assert "kept as they were last written (subproblem_1.sql)" in err
    assert (out / "subproblem_1.sql").read_bytes() == b"an earlier stage"


def test_a_lock_of_another_program_or_in_the_way(paths, capsys, tmp_path):
    from lpc_mdo.run_lock import LOCK_NAME, _start_time

    out = Path(paths["out"])
    out.mkdir()
    # Process 1 runs, but it started at another time than the lock's writer: the id was reused
    # (after a reboot), a stale lock.
    (out / LOCK_NAME).write_text(f"1 {int(_start_time(1) or 0) + 12345}\n")
    assert main(["analyze", "--output-dir", str(out)]) == 0
    (out / LOCK_NAME).mkdir()  # a folder of the lock file's name
    rc = main(["analyze", "--output-dir", str(out)])
    _assert_one_line_error(rc, capsys.readouterr(), "--output-dir")
    dangling = tmp_path / "link"
    dangling.symlink_to(tmp_path / "nowhere")
    rc = main(["analyze", "--output-dir", str(dangling)])
    _assert_one_line_error(rc, capsys.readouterr(), "--output-dir")


def test_a_long_message_stays_one_short_line(paths, capsys, monkeypatch):
    # A message whose value no check cut (the net of main): its start and its end are kept.
    def long_message(args):
        raise cli.CLIError(f"'--vehicle' = {'y' * 10**5}: must be a vehicle TOML file")

    monkeypatch.setattr(cli, "_analyze", long_message)
    rc = main(["analyze", "--output-dir", paths["out"]])
    captured = capsys.readouterr()
    _assert_one_line_error(rc, captured, "--vehicle")
    assert "characters) ... " in captured.err and captured.err.rstrip().endswith("TOML file")
    assert len(captured.err) < 1200


def test_a_symbolic_link_loop_is_named(paths, tmp_path, capsys):
    (tmp_path / "a.toml").symlink_to(tmp_path / "b.toml")
    (tmp_path / "b.toml").symlink_to(tmp_path / "a.toml")
    rc = main(["analyze", "--vehicle", str(tmp_path / "a.toml"), "--output-dir", paths["out"]])
    _assert_one_line_error(rc, capsys.readouterr(), "symbolic link that leads nowhere")


def test_a_removed_working_folder_is_named(tmp_path, capsys, monkeypatch):
    gone = tmp_path / "gone"
    gone.mkdir()
    monkeypatch.chdir(gone)
    gone.rmdir()
    rc = main(["analyze", "--output-dir", "out"])
    _assert_one_line_error(rc, capsys.readouterr(), "the working folder no longer exists")


def test_a_closed_output_pipe_ends_quietly(paths, capsys, monkeypatch):
    # lpc-mdo analyze | head: the reader goes away; no traceback, no "internal error".
    def closed(args):
        raise BrokenPipeError(32, "Broken pipe")

    monkeypatch.setattr(cli, "_analyze", closed)
    assert main(["analyze", "--output-dir", paths["out"]]) == cli.EXIT_WRITE_ERROR
    assert capsys.readouterr().err == ""


def test_a_model_out_of_its_range_is_one_line(paths, capsys, monkeypatch):
    # om.AnalysisError outside an optimization (analyze): the model's own message, no traceback.
    def out_of_range(args):
        raise om.AnalysisError("'hover.motor' <class X>: stack length 0.01 m below 0.056 m")

    monkeypatch.setattr(cli, "_analyze", out_of_range)
    rc = main(["analyze", "--output-dir", paths["out"]])
    out = capsys.readouterr()
    assert rc == cli.EXIT_ANALYSIS_ERROR == 1
    assert out.err.strip().splitlines() == [
        "lpc-mdo: error: the analysis left a model's range: 'hover.motor' <class X>: stack "
        "length 0.01 m below 0.056 m"
    ]


def test_a_case_file_locked_by_a_writer_says_so(paths, tmp_path, capsys):
    busy = tmp_path / "busy.sql"
    shutil.copy(paths["good.sql"], busy)
    writer = sqlite3.connect(busy)
    try:
        writer.execute("BEGIN EXCLUSIVE")  # a run still writing it
        rc = main([*_format(FULL, paths), "--start-case", str(busy)])
        _assert_one_line_error(rc, capsys.readouterr(), "is locked by another process")
    finally:
        writer.rollback()
        writer.close()
