import sqlite3

import openmdao.api as om
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.recorder import CaseRecorder


def _problem(path):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("a", om.ExecComp("y = 2.0*x"), promotes=["*"])
    prob.model.add_subsystem("b", om.ExecComp("z = y + 1.0"), promotes=["*"])
    prob.model.nonlinear_solver = om.NonlinearRunOnce()
    prob.model.add_design_var("x", lower=-10.0, upper=10.0)
    prob.model.add_objective("z")
    prob.driver = om.ScipyOptimizeDriver(optimizer="SLSQP", maxiter=5, disp=False)
    recorder = path if isinstance(path, om.SqliteRecorder) else CaseRecorder(path)
    prob.driver.add_recorder(recorder)
    prob.add_recorder(recorder)
    prob.setup()
    return prob


def _rows(path, table):
    with sqlite3.connect(path) as db:
        return db.execute(f"SELECT COUNT(*) FROM {table}").fetchone()[0]


def test_metadata_recorded_once_cases_as_before(tmp_path):
    # Three model runs and a driver run: OpenMDAO's recorder writes the metadata of the four
    # systems (root, _auto_ivc, a, b) at each of the four runs, ours once; the cases are the
    # same.
    ours, theirs = tmp_path / "ours.sql", tmp_path / "theirs.sql"
    for recorder in (CaseRecorder(ours), om.SqliteRecorder(str(theirs))):
        prob = _problem(recorder)
        prob.set_val("x", 3.0)
        prob.run_model()
        prob.run_model()
        prob.run_driver()
        prob.run_model()
        prob.record("final")
        prob.cleanup()
    systems = len(list(prob.model.system_iter(include_self=True, recurse=True)))
    assert systems == 4
    assert _rows(ours, "system_metadata") == systems
    assert _rows(theirs, "system_metadata") == 4 * systems
    assert _rows(ours, "driver_iterations") == _rows(theirs, "driver_iterations")
    a, b = om.CaseReader(str(ours)), om.CaseReader(str(theirs))
    assert_near_equal(a.get_case("final").get_val("z"), b.get_case("final").get_val("z"), 1e-15)
    assert a.problem_metadata["design_vars"].keys() == b.problem_metadata["design_vars"].keys()
    assert a.list_sources(out_stream=None) == b.list_sources(out_stream=None)
