"""A 16th design condition of an existing kind is a vehicle-file edit only.

A steady loiter (given speed, altitude, duration and energy weight) appended to the reference
vehicle file: it builds, trims by its own design variables, counts in the mission energy as
power x duration x weight (checked by hand against the model's own condition powers), and
appears in ``lpc-mdo analyze`` and the report tables. Nothing in the package names it.
"""

from importlib import resources

import numpy as np
import pytest

from lpc_mdo.cli import main
from lpc_mdo.post.report import ReportSpec, write_report
from lpc_mdo.problems import build_analysis_problem, build_problem
from lpc_mdo.trim import trim
from lpc_mdo.vehicle import load_vehicle, reference_vehicle
from lpc_mdo.vehicle.condition_contract import condition_kind

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration

LOITER_DURATION = 600.0  # s
LOITER_WEIGHT = 1.5  # the loiter counts 1.5 times in the mission energy
LOITER = f"""
[[conditions]]
name = "loiter"
kind = "steady"
altitude = 600.0
speed = 50.0                # CL ~1.3; at 45 m/s (CL ~1.6) trim stops at 1 % of W (measured)
pitch_deg = 4.0
flight_path_angle_deg = 0.0
duration = {LOITER_DURATION}
energy_weight = {LOITER_WEIGHT}
load_factor = 1.0
failed_rotor = -1
acceleration = 0.0
design_variable_prefix = "loiter"

[design_variables.loiter_pusher_rpm]
units = "rpm"
initial = 1100.0
lower = 500.0
upper = 2500.0
ref = 1000.0

[design_variables.loiter_pitch]
units = "deg"
lower = -10.0
upper = 12.0
ref = 5.729577951308232

[design_variables.loiter_elevator]
units = "deg"
initial = 0.0
lower = -15.0
upper = 15.0
ref = 5.729577951308232
"""


@pytest.fixture(scope="module")
def loiter_file(tmp_path_factory):
    reference = resources.files("lpc_mdo").joinpath("data", "lpc_reference.toml")
    path = tmp_path_factory.mktemp("loiter") / "lpc_loiter.toml"
    path.write_text(reference.read_text(encoding="utf-8") + LOITER, encoding="utf-8")
    return path


def test_loiter_is_a_sixteenth_condition_with_its_own_design_variables(loiter_file):
    vehicle = load_vehicle(loiter_file)
    assert len(vehicle.conditions) == 16 and vehicle.conditions[-1].name == "loiter"
    assert vehicle.design_variable_count() == 182 + 3
    assert vehicle.design_variables["loiter_pitch"].initial == pytest.approx((np.radians(4.0),))
    # The file's 13th table (the one 'oei' table generates four conditions).
    assert vehicle.design_variables["loiter_pitch"].initial_from == "conditions[12].pitch_deg"
    assert "loiter" in [c.name for c in vehicle.mission_segments]


def test_full_problem_declares_the_loiter_trim_and_variables(loiter_file):
    prob = build_problem("full", vehicle=loiter_file, optimizer="SLSQP")
    prob.final_setup()
    dvs = prob.model.get_design_vars()
    cons = prob.model.get_constraints()
    assert {"loiter_pusher_rpm", "loiter_pitch", "loiter_elevator"} <= set(dvs)
    # Steady flight: u_dot, w_dot, q_dot, as climb, cruise and descent (Table 6).
    assert cons["loiter.linear_acceleration"]["size"] == 2
    assert cons["loiter.angular_acceleration"]["size"] == 1
    assert sum(m["size"] for m in dvs.values()) == 182 + 3
    # ... and the advance ratios (40), the tip Mach numbers (OEI 28, transition 45,
    # climb/cruise/descent and the loiter's pusher 4), the 20 linear minimum chords, the 9
    # voltage margins and the wing section lift of the 11 wing-borne conditions; the 18
    # clearances and 10 control reserves in place of the 2 radius intersections; the blade
    # stall limits of the 14 BEM rotor groups (hover, 4 OEI, the pusher at 5 transition points,
    # climb, cruise, descent and the loiter).
    count = sum(m["size"] for m in cons.values())
    assert count == 86 + 2 + 40 + 3 + 40 + 28 + 45 + 4 + 20 + 9 + 11 + 18 + 10 - 2 + 1 + 14
    # Subproblems select by kind: the loiter is a steady condition of subproblem 4.
    sub4 = build_problem("subproblem_4", vehicle=loiter_file, optimizer="SLSQP")
    assert "loiter" in sub4.model.condition_names


def test_loiter_trims_and_counts_power_times_duration_times_weight(loiter_file):
    prob = build_analysis_problem(loiter_file, lateral_trim=False, constraint_kinds=["trim"])
    result = trim(prob, conditions=["loiter"])
    assert result.success, result.message
    assert np.abs(prob.get_val("loiter.linear_acceleration")[0, [0, 2]]).max() < 1e-5
    prob.run_model()
    # By hand: E = sum over the conditions of P x t x weight, with the loiter's 600 s x 1.5.
    vehicle = prob.vehicle
    by_hand = 0.0
    for c in vehicle.conditions:
        output = condition_kind(c.kind).power_output
        if output is not None:
            power = prob.get_val(f"{c.name}.{output}", units="W")[0]
            by_hand += power * c.duration * c.energy_weight
    loiter_power = prob.get_val("loiter.electrical_power", units="W")[0]
    assert loiter_power > 1e4
    assert prob.get_val("energy_used", units="J")[0] == pytest.approx(by_hand, rel=1e-12)
    # The loiter's share, and the same model without it.
    reference = build_analysis_problem(reference_vehicle(), design_problem=False)
    reference.run_model()
    delta = prob.get_val("energy_used")[0] - reference.get_val("energy_used")[0]
    assert delta == pytest.approx(loiter_power * LOITER_DURATION * LOITER_WEIGHT, rel=1e-9)


def test_loiter_appears_in_analyze_and_the_report(loiter_file, tmp_path, capsys):
    out = tmp_path / "analysis"
    assert main(["analyze", "--vehicle", str(loiter_file), "--output-dir", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "16 design conditions" in printed
    assert any(line.strip().startswith("loiter") for line in printed.splitlines())
    assert "loiter.linear_acceleration" in (out / "constraints.md").read_text()
    index = write_report(out, tmp_path / "report", ReportSpec(vehicle=load_vehicle(loiter_file)))
    trim_tables = list(index.parent.rglob("trim_residuals_*.md"))
    assert trim_tables and "loiter" in trim_tables[0].read_text()
