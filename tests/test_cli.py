"""The lpc-mdo command line (the README's main job)."""

import re
from importlib import resources

import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.cli import main


def test_analyze_reference_vehicle(tmp_path, capsys):
    assert (
        main(
            [
                "analyze",
                "--output-dir",
                str(tmp_path / "out"),
                "--n2",
                str(tmp_path / "figures" / "n2.html"),  # a folder the command creates
            ]
        )
        == 0
    )
    text = capsys.readouterr().out
    assert (
        "15 design conditions, 171 design variables, 96 constraints, 40 linear rotor-speed bounds"
    ) in text
    assert "gross" in text and "minus_1g" in text
    assert (tmp_path / "figures" / "n2.html").stat().st_size > 0
    assert (tmp_path / "out" / "constraints.md").exists()
    case = om.CaseReader(str(tmp_path / "out" / "cases.sql")).get_case("final")
    # The calibration target (true by construction: W_other is calibrated so that the initial
    # design weighs the paper's 3723.99 kg, Table 8); what the analysis itself computes: the
    # untrimmed hover's thrust is below the weight (85 %).
    assert_near_equal(case.get_val("gross_mass", units="kg"), 3723.99, 1e-8)
    thrust = case.get_val("hover.lift_thrust", units="N").sum()
    assert 0.5 < thrust / (3723.99 * 9.81) < 1.0


def test_analyze_reports_a_bad_vehicle_file(tmp_path, capsys):
    path = tmp_path / "bad.toml"
    text = (resources.files("lpc_mdo") / "data" / "lpc_reference.toml").read_text()
    assert "[wing]\n" in text
    path.write_text(text.replace("[wing]\n", "[wing]\nspam = 1\n", 1))
    assert main(["analyze", "--vehicle", str(path), "--output-dir", str(tmp_path)]) == 2
    assert "unknown key 'wing.spam'" in capsys.readouterr().err


def test_missing_start_case_is_a_clear_error(tmp_path, capsys):
    missing = str(tmp_path / "nope.sql")
    for argv in (
        ["optimize", "--problem", "full", "--start-case", missing],
        ["sweep", "--start-case", missing],
    ):
        assert main(argv) == 2
        assert f"'--start-case' = '{missing}' does not exist" in capsys.readouterr().err


def test_unknown_command_is_a_one_line_error(capsys):
    assert main(["fly"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("lpc-mdo: error: argument command: invalid choice: 'fly'")
    assert err.count("\n") == 1


def test_help_exits_with_zero(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["analyze", "--help"])
    assert exc.value.code == 0
    assert "--n2" in capsys.readouterr().out


def test_optimize_subproblem_4_and_report(tmp_path, capsys):
    pytest.importorskip("cyipopt")
    out = tmp_path / "opt"
    assert (
        main(
            ["optimize", "--problem", "subproblem_4", "--max-iter", "100", "--output-dir", str(out)]
        )
        == 0
    )
    text = capsys.readouterr().out
    assert "subproblem_4: trim" in text and "subproblem_4: success=True" in text
    # The progress line of every iteration: label, iteration, objective, violation, time.
    assert re.search(r"subproblem_4  iter +\d+  eval +1  objective .* max violation .* s", text)
    assert (out / "subproblem_4.run_stats.json").exists()
    case = om.CaseReader(str(out / "subproblem_4.sql")).get_case("final")
    assert case.get_val("cruise.static_margin")[0] >= 0.08 - 1e-6
    assert main(["report", str(out), "--output-dir", str(tmp_path / "report")]) == 0
    assert (tmp_path / "report" / "index.md").exists()


def test_analyze_reports_voltage_margins_and_says_what_it_replaces(tmp_path, capsys):
    # The motor voltage limit is visible: a column of the lowest voltage margin per condition;
    # a second analysis into the same folder says which files it replaces.
    out = tmp_path / "out"
    assert main(["analyze", "--output-dir", str(out)]) == 0
    first = capsys.readouterr().out
    assert "V margin" in first and "replacing" not in first
    assert main(["analyze", "--output-dir", str(out)]) == 0
    second = capsys.readouterr().out
    assert f"lpc-mdo: replacing {out / 'cases.sql'}" in second
