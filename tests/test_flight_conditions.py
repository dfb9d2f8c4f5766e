from importlib import resources

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_totals, assert_near_equal

from lpc_mdo.cli import main
from lpc_mdo.groups.flight_conditions import FlightConditionsGroup
from lpc_mdo.vehicle import CONDITION_NAMES, reference_vehicle


def make_problem():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("conditions", FlightConditionsGroup(), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.run_model()
    return prob


def test_reference_conditions():
    prob = make_problem()
    assert prob.model.conditions.condition_names == list(CONDITION_NAMES)
    cruise = CONDITION_NAMES.index("cruise")
    # Paper cruise: M 0.17 at 3280 ft = 999.74 m, V = 57.190 m/s (reference page §8.2; our ICAO
    # speed of sound differs from the reference model's by 7e-5).
    assert_near_equal(prob.get_val("mach")[cruise], 0.17, 1e-4)
    assert_near_equal(prob.get_val("speed")[cruise], 57.19, 1e-4)
    hover = CONDITION_NAMES.index("hover")
    assert prob.get_val("dynamic_pressure")[hover] == 0.0
    # Climb rate of the paper: 900 ft/min = 4.572 m/s (V sin(gamma)).
    climb = CONDITION_NAMES.index("climb")
    rate = prob.get_val("speed")[climb] * np.sin(prob.get_val("flight_path_angle")[climb])
    assert_near_equal(rate, 4.572, 1e-3)


def test_totals():
    prob = make_problem()
    data = prob.check_totals(of=["mach", "dynamic_pressure", "u", "w", "reynolds_per_length"],
                             wrt=["altitude", "speed", "pitch"], method="cs", out_stream=None)
    assert_check_totals(data, atol=1e-8, rtol=1e-8)


def test_cli_analyze(tmp_path, capsys):
    assert main(["analyze", "--output-dir", str(tmp_path / "out"),
                 "--n2", str(tmp_path / "n2.html")]) == 0
    text = capsys.readouterr().out
    assert "design variables: 161" in text
    assert "cruise" in text and "minus_1g" in text
    assert (tmp_path / "n2.html").stat().st_size > 0
    case = om.CaseReader(str(tmp_path / "out" / "cases.sql")).get_case("final")
    assert_near_equal(case.get_val("conditions.mach")[CONDITION_NAMES.index("cruise")], 0.17,
                      1e-4)


def test_cli_reports_a_bad_vehicle_file(tmp_path, capsys):
    path = tmp_path / "bad.toml"
    text = (resources.files("lpc_mdo") / "data" / "lpc_reference.toml").read_text()
    assert "[wing]\n" in text
    path.write_text(text.replace("[wing]\n", "[wing]\nspam = 1\n", 1))
    assert main(["analyze", "--vehicle", str(path), "--output-dir", str(tmp_path)]) == 2
    assert "unknown key 'wing.spam'" in capsys.readouterr().err


def test_group_takes_a_user_vehicle():
    vehicle = reference_vehicle()
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("c", FlightConditionsGroup(vehicle=vehicle))
    prob.setup()
    prob.set_val("c.altitude", np.full(len(CONDITION_NAMES), 12000.0))
    with pytest.raises(om.AnalysisError, match="outside the troposphere"):
        prob.run_model()
