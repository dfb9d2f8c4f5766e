"""The run scripts that build the full problem themselves still declare paper Table 6.

They are run by hand (benchmarks, derivative verification), not by the test suite, so a change
of the model's or the problem's API would otherwise go unnoticed until someone runs them.
"""

import pytest
from run_script_loader import load_run_script

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration


def test_benchmark_lpc_builds_the_table6_problem():
    prob = load_run_script("benchmark_lpc").build()
    dvs = prob.model.get_design_vars()
    cons = prob.model.get_constraints()
    assert sum(m["size"] for m in dvs.values()) == 161 + 21
    # Paper Table 6, the 2 stress rows, the 40 advance ratios, the 76 tip-Mach rows, the 9
    # voltage margins, the 10 wing section-lift rows, the 13 blade-stall rows and the design
    # gross mass closure.
    count = sum(m["size"] for m in cons.values() if not m["linear"])
    # clearances, reserve, no radius intersection
    assert count == 96 + 2 + 40 + 76 + 9 + 10 + 13 + 18 + 10 - 2 + 1
    assert sum(m["size"] for m in cons.values() if m["linear"]) == 40 + 20  # speeds, chords


def test_close_initial_design_writes_gauges_and_design_gross_mass(tmp_path):
    # The closure's file edit: the four thickness tables' initial values and design_gross_mass
    # are replaced, everything else is kept, and the file still loads.
    import shutil

    from lpc_mdo.vehicle import load_vehicle, reference_vehicle

    script = load_run_script("close_initial_design")
    path = tmp_path / "lpc.toml"
    shutil.copy(script.REFERENCE_FILE, path)
    gauges = {name: [1e-3 * (k + 1)] * 8 for k, name in enumerate(script.THICKNESSES)}
    script.write_closure(path, gauges, 3111.234)
    vehicle = load_vehicle(path)
    assert vehicle.masses.design_gross_mass == 3111.23
    for name, values in gauges.items():
        assert list(vehicle.design_variables[name].initial_array) == values
    reference = reference_vehicle()
    assert vehicle.wing == reference.wing and vehicle.conditions == reference.conditions


def test_trim_family_perturbs_the_trim_variables_only_and_refuses_bad_input(capsys):
    import numpy as np

    from lpc_mdo.problems import build_analysis_problem

    script = load_run_script("trim_family")
    with pytest.raises(SystemExit) as stop:
        script.main(["--seeds", "0"])
    assert stop.value.code == 2 and "need seeds >= 1" in capsys.readouterr().err
    assert script.main(["--vehicle", "no_such_file.toml"]) == 2
    prob = build_analysis_problem(None, conditions=["hover", "cruise"])
    rpm = prob.get_val("hover_lift_rpm", units="rpm").copy()
    span = prob.get_val("wing_span", units="m").copy()
    script.perturb_trim_variables(prob, 0.1, seed=1)
    moved = prob.get_val("hover_lift_rpm", units="rpm")
    assert np.all(np.abs(moved / rpm - 1.0) <= 0.1) and np.any(moved != rpm)
    assert np.array_equal(prob.get_val("wing_span", units="m"), span)  # not a trim variable
