"""The lpc-mdo command line (the README's main job)."""

import re
from importlib import resources

import numpy as np
import openmdao.api as om
import pytest
from test_design_review import check_trimmed_initial_design

from lpc_mdo.cli import main
from lpc_mdo.post.stall import stall_speed_rows
from lpc_mdo.vehicle import reference_vehicle

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration


def test_analyze_reference_vehicle_is_trimmed(tmp_path, capsys):
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
    assert "(initial design, trimmed: each condition by its rotor speeds" in text
    assert (
        "15 design conditions, 182 design variables, 101 constraints of 333 rows "
        "(273 nonlinear, 60 linear bounds)"
    ) in text
    assert "gross" in text and "minus_1g" in text
    assert "trim: all 15 conditions trimmed" in text
    # Structural conditions show their load factor, not a power.
    assert re.search(r"plus_3g +n = \+3 ", text) and re.search(r"minus_1g +n = -1 ", text)
    assert "(none)" not in text
    # Every declared constraint with its limit and status; the paper's initial design violates
    # the hover noise limit (70 dBA) and satisfies the final state of charge (>= 0.2).
    # Every row has its units: its own, or what a ratio counts in (dBA, Mach, fraction).
    assert re.search(r"hover\.total_spl_a +dBA +<= 70 +\d+\.\d+ +violated", text)
    assert re.search(r"state_of_charge +fraction +>= 0\.2 +0\.\d+ +(satisfied|violated)", text)
    assert re.search(r"cruise\.linear_acceleration +m/s\*\*2 +\= 0 .* active", text)
    assert re.search(r"hover\.lift_tip_mach +Mach +<= ", text)
    assert re.search(r"101 constraints \(333 rows\): \d+ satisfied, \d+ active, \d+ violated", text)
    # At the end: the violated and the active constraints by name.
    assert re.search(r"violated \(\d+ of 101 constraints\): hover\.total_spl_a, ", text)
    active = r"active \(\d+ of 101 constraints\): "
    assert re.search(active + r"design_gross_mass_closure, hover\.linear_acceleration, ", text)
    # The trimmed variables per condition.
    assert re.search(r"cruise +pusher_rpm [\d.]+ rpm; pitch [\d.]+ deg; elevator", text)
    # The airframe L/D of trimmed cruise and its maximum (about 15, docs theory/aerodynamics).
    found = re.search(r"trimmed (\d+\.\d+) at C_L [\d.]+, C_D [\d.]+; maximum (\d+\.\d+)", text)
    assert found and 10.0 < float(found[1]) <= float(found[2]) < 20.0
    # The static-margin budget names the fuselage and the booms.
    assert re.search(r"fuselage +-0\.\d+", text) and re.search(r"booms +-0\.\d+", text)
    assert (tmp_path / "figures" / "n2.html").stat().st_size > 0
    assert (tmp_path / "out" / "constraints.md").exists()
    case = om.CaseReader(str(tmp_path / "out" / "cases.sql")).get_case("final")
    # The closed itemised initial design: W0 = the design gross mass of the vehicle file, to the
    # 0.01 kg the file keeps (run_scripts/close_initial_design.py).
    w0 = reference_vehicle().masses.design_gross_mass
    assert abs(case.get_val("gross_mass", units="kg")[0] - w0) < 0.01
    # Closed form of the trimmed hover (zero pitch, no forward speed): the lift rotors carry
    # the weight, sum T = m g, to the trim tolerance 1e-3 of the weight (0.1 %; the solver
    # reaches ~1e-10).
    thrust = case.get_val("hover.lift_thrust", units="N").sum()
    assert thrust == pytest.approx(w0 * 9.81, rel=1e-3)
    # The stall-speed check, printed and from the case file alone: every wing-borne condition
    # within its section-lift limit, cruise above 1.2 V_S with V/V_S = sqrt(kappa / r) to within
    # the Reynolds-number effect on c_l,max (a few %; docs theory/aerodynamics 'Section lift
    # limit').
    assert re.search(r"stall-speed check: 1-g stall speed \d+\.\d m/s EAS", text)
    assert "ABOVE LIMIT" not in text
    vehicle = reference_vehicle()
    design, rows = stall_speed_rows(case, vehicle)
    assert [r["condition"] for r in rows] == [
        c.name for c in vehicle.conditions if c.kind in ("transition", "steady", "structural")
    ]
    for row in rows:
        assert row["ratio"] <= row["ratio_ks"] <= row["limit"]
    cruise = next(r for r in rows if r["condition"] == "cruise")
    kappa = vehicle.constraints.wing_stall_lift_fraction
    assert cruise["speed_ratio"] >= vehicle.constraints.min_stall_speed_ratio
    assert cruise["speed_ratio"] == pytest.approx(np.sqrt(kappa / cruise["ratio"]), rel=0.03)
    # The design review of the same case (tests/test_design_review.py).
    check_trimmed_initial_design(tmp_path / "out" / "cases.sql")
    assert 30.0 < design < 50.0


def test_analyze_names_a_condition_that_cannot_trim(tmp_path, capsys):
    # Cruise trims at a pusher speed of 976 rpm (the reference vehicle's initial design);
    # with the pusher's cruise upper bound at 750 rpm its thrust cannot balance the drag.
    text = (resources.files("lpc_mdo") / "data" / "lpc_reference.toml").read_text()
    block = '[design_variables.cruise_pusher_rpm]\nunits = "rpm"\ninitial = 1200.0\n'
    assert block + "lower = 700.0\nupper = 2500.0\n" in text
    path = tmp_path / "slow_pusher.toml"
    path.write_text(
        text.replace(
            block + "lower = 700.0\nupper = 2500.0\n",
            block.replace("1200.0", "740.0") + "lower = 700.0\nupper = 750.0\n",
        )
    )
    assert main(["analyze", "--vehicle", str(path), "--output-dir", str(tmp_path / "out")]) == 1
    captured = capsys.readouterr()
    # The slower pusher also changes the pusher motor's size and so the vehicle's mass: other
    # conditions may then need more than the trim's evaluation budget (transition_2 did, residual
    # 1.9e-3, measured 2026-12-04); each failed condition is named, cruise among them.
    assert re.search(
        r"trim FAILED for (\w+ \(residual [\d.e-]+\), )*cruise \(residual [\d.e-]+\)",
        captured.out,
    )
    assert re.search(r"cruise .*NOT TRIMMED", captured.out)
    assert "climb" not in captured.out.split("trim FAILED for")[1].split("\n")[0]
    assert re.search(r"lpc-mdo: trim failed for ([\w, ]+, )?cruise \(exit status 1\)", captured.err)
    assert (tmp_path / "out" / "constraints.md").exists()  # written all the same


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
            ["optimize", "--problem", "subproblem_4", "--max-iter", "200", "--output-dir", str(out)]
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


def test_analyze_no_trim_says_so_and_reports_voltage_margins(tmp_path, capsys):
    # --no-trim shows the raw initial design and says so; the motor voltage limit is visible
    # (a column of the lowest voltage margin per condition); a second analysis into the same
    # folder says which files it replaces.
    out = tmp_path / "out"
    assert main(["analyze", "--no-trim", "--output-dir", str(out)]) == 0
    first = capsys.readouterr().out
    assert "(initial design, NOT trimmed (--no-trim)" in first
    assert "trim: not trimmed (--no-trim)" in first
    assert "trim variables (initial values, not trimmed)" in first
    assert "V margin" in first and "replacing" not in first
    # Each condition's lowest voltage margin with its status, as any constraint has.
    assert re.search(r"hover +[\d.]+ .* -?\d\.\d{3} +(satisfied|active|violated)", first)
    case = om.CaseReader(str(out / "cases.sql")).get_case("final")
    thrust = case.get_val("hover.lift_thrust", units="N").sum()
    # Untrimmed: the initial rotor speeds lift 103.5 % of the weight (measured 2026-12-04).
    assert abs(thrust / (reference_vehicle().masses.design_gross_mass * 9.81) - 1.0) > 0.02
    assert main(["analyze", "--no-trim", "--output-dir", str(out)]) == 0
    second = capsys.readouterr().out
    assert f"lpc-mdo: replacing {out / 'cases.sql'}" in second
