"""A stage that does not converge stops the warm-started sequence (exit status 1, named)."""

import pytest

from lpc_mdo import study_plan, warm_start
from lpc_mdo.cli import main
from lpc_mdo.vehicle import reference_vehicle


@pytest.fixture
def fake_stages(monkeypatch):
    """Replace the optimizations: every stage converges but subproblem_2 (no model is built)."""
    ran = []

    def solve_stage(name, case_file, **kwargs):
        ran.append(name)
        failed = name == "subproblem_2"
        return warm_start.StageResult(
            name=name,
            case_file=case_file,
            success=not failed,
            iterations=200 if failed else 10,
            seconds=1.0,
            gross_mass=3000.0,
            exit_status="Maximum number of iterations exceeded" if failed else "SUCCESS",
            analysis_errors=0,
            trim_seconds=0.0,
            trim_message="",
        )

    monkeypatch.setattr(warm_start, "solve_stage", solve_stage)
    return ran


def test_a_failed_stage_stops_the_sequence(tmp_path, fake_stages):
    lines = []
    results = warm_start.run_sequence(str(tmp_path), vehicle=reference_vehicle(), log=lines.append)
    stop = study_plan.SEQUENCE.index("subproblem_2") + 1
    assert fake_stages == list(study_plan.SEQUENCE[:stop])
    assert [r.name for r in results] == fake_stages and not results[-1].success
    assert lines == ["subproblem_2 did not converge: the sequence stops here"]


def test_keep_going_runs_the_rest(tmp_path, fake_stages):
    warm_start.run_sequence(
        str(tmp_path), vehicle=reference_vehicle(), log=lambda m: None, keep_going=True
    )
    assert fake_stages == list(study_plan.SEQUENCE)


def test_the_command_names_the_stage_and_exits_1(tmp_path, fake_stages, capsys):
    rc = main(["optimize", "--output-dir", str(tmp_path), "--optimizer", "SLSQP", "--quiet"])
    err = capsys.readouterr().err
    assert rc == 1
    assert err.startswith(
        "lpc-mdo: subproblem_2: Maximum number of iterations exceeded; the sequence stopped there"
    ), err
    assert "subproblem_4" not in fake_stages
