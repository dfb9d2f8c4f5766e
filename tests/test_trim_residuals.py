"""lpc_mdo.post.trim_residuals: Table 6 trim rows as forces and moments, from a case file.

A synthetic recorded problem with LPC output names: m = 2000 kg, a diagonal-plus-xz inertia,
hover and one transition point with chosen accelerations; the residuals are checked against
the closed forms F = m (a - a_target) and M = I alpha computed here by hand, with the
transition point's prescribed acceleration a_target = (dV/dt, 0, 0) of the reference vehicle's
transition_1 (flight-path axes, the transition's linear rows).
"""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.post.tables import MissingVariableError
from lpc_mdo.post.trim_residuals import trim_residual_table, trim_residuals
from lpc_mdo.vehicle import reference_vehicle

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration

MASS = 2000.0
INERTIA = np.array([[5000.0, 0.0, -700.0], [0.0, 9000.0, 0.0], [-700.0, 0.0, 13000.0]])
HOVER_LINEAR = [0.0, 0.0, 2e-4]
HOVER_ANGULAR = [3e-3, -1e-5, 0.0]
_T1 = reference_vehicle().condition("transition_1")
T1_TARGET = (_T1.acceleration, 0.0)
T1_LINEAR = [T1_TARGET[0], 1e-6, T1_TARGET[1] + 2e-4]
T1_ANGULAR = [1e-6, 2e-6, -4e-6]


def _record(path, declare=True):
    prob = om.Problem(reports=False)
    ivc = prob.model.add_subsystem("ivc", om.IndepVarComp(), promotes=["*"])
    ivc.add_output("gross_mass", MASS, units="kg")
    ivc.add_output("inertia", INERTIA, units="kg*m**2")
    for name, lin, ang in (
        ("hover", HOVER_LINEAR, HOVER_ANGULAR),
        ("transition_1", T1_LINEAR, T1_ANGULAR),
    ):
        condition = prob.model.add_subsystem(name, om.IndepVarComp())
        condition.add_output("linear_acceleration", np.array([lin]), units="m/s**2")
        condition.add_output("angular_acceleration", np.array([ang]), units="rad/s**2")
    ivc.add_design_var("gross_mass")
    prob.model.add_objective("gross_mass")
    if declare:
        # As the optimizations declare them: hover w and q only; transition all six.
        prob.model.add_constraint(
            "hover.linear_acceleration", indices=[2], flat_indices=True, equals=0.0
        )
        prob.model.add_constraint(
            "hover.angular_acceleration", indices=[1], flat_indices=True, equals=0.0
        )
        prob.model.add_constraint(
            "transition_1.linear_acceleration",
            indices=[0, 1, 2],
            flat_indices=True,
            equals=np.array([T1_TARGET[0], 0.0, T1_TARGET[1]]),
        )
        prob.model.add_constraint("transition_1.angular_acceleration", equals=0.0)
    prob.add_recorder(om.SqliteRecorder(str(path)))
    prob.recording_options["includes"] = ["*"]
    prob.setup()
    prob.run_model()
    prob.record("final")
    prob.cleanup()
    return path


def test_residuals_are_forces_and_moments_of_every_table6_row(tmp_path):
    rows = trim_residuals(_record(tmp_path / "cases.sql"))
    by_key = {(r["condition"], r["component"]): r for r in rows}
    # Table 6 rows: hover (w, p, q), transition (u, v, w, p, q, r).
    assert list(by_key) == [("hover", c) for c in "wpq"] + [("transition_1", c) for c in "uvwpqr"]
    weight = MASS * 9.81
    # Closed forms, by hand.
    hover_moment = INERTIA @ np.array(HOVER_ANGULAR)
    assert_near_equal(by_key["hover", "w"]["residual"], MASS * 2e-4, 1e-12)
    assert_near_equal(by_key["hover", "p"]["residual"], hover_moment[0], 1e-12)
    assert_near_equal(by_key["hover", "p"]["residual"], 5000.0 * 3e-3, 1e-12)
    assert_near_equal(by_key["hover", "q"]["residual"], 9000.0 * -1e-5, 1e-12)
    assert by_key["hover", "p"]["declared"] is False and by_key["hover", "q"]["declared"]
    # Transition: residual against the prescribed acceleration.
    assert_near_equal(by_key["transition_1", "u"]["residual"], 0.0, 1e-12)
    assert_near_equal(by_key["transition_1", "w"]["residual"], MASS * 2e-4, 1e-9)
    assert_near_equal(by_key["transition_1", "w"]["target"], T1_TARGET[1], 1e-12)
    assert_near_equal(
        by_key["transition_1", "r"]["residual"], -700.0 * 1e-6 + 13000.0 * -4e-6, 1e-12
    )
    assert_near_equal(by_key["hover", "p"]["percent_of_weight"], 100 * 15.0 / weight, 1e-12)


def test_table_flags_rows_beyond_the_limit(tmp_path):
    table = trim_residual_table(_record(tmp_path / "cases.sql"), limit_percent=0.01)
    rows = {row[0]: row for row in table.rows}
    # hover p: 15 N m = 0.076 % of W0 = 19620 N > 0.01 %; transition: 0.4 N = 0.002 %.
    assert rows["hover"][-1] is False and rows["transition_1"][-1] is True
    assert rows["hover"][2] == "w q"
    assert_near_equal(rows["hover"][4], 15.0, 1e-12)
    assert "largest: hover p" in table.notes[1]


def test_undeclared_rows_are_evaluated_against_the_condition_targets(tmp_path):
    # The rows and targets come from the condition's contract, declared or not.
    rows = trim_residuals(_record(tmp_path / "cases.sql", declare=False))
    transition = {r["component"]: r for r in rows if r["condition"] == "transition_1"}
    assert list(transition) == list("uvwpqr")
    assert not any(r["declared"] for r in rows)
    assert_near_equal(transition["w"]["residual"], MASS * 2e-4, 1e-9)


def test_case_without_accelerations_is_a_clear_error(tmp_path):
    prob = om.Problem(reports=False)
    ivc = prob.model.add_subsystem("ivc", om.IndepVarComp(), promotes=["*"])
    ivc.add_output("gross_mass", MASS, units="kg")
    ivc.add_output("inertia", INERTIA, units="kg*m**2")
    prob.add_recorder(om.SqliteRecorder(str(tmp_path / "c.sql")))
    prob.setup()
    prob.run_model()
    prob.record("final")
    prob.cleanup()
    with pytest.raises(MissingVariableError, match="no condition's linear_acceleration"):
        trim_residuals(tmp_path / "c.sql")
