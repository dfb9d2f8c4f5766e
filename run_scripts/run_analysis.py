"""Analyze the reference vehicle at its initial design: a run script to copy and edit.

    python run_scripts/run_analysis.py            # run, record and print
    openmdao n2 --problem run_analysis -o run_analysis_n2.html run_scripts/run_analysis.py
                                                  # N2 diagram of the same model

``--problem run_analysis`` is needed: building the vehicle runs a small calibration problem
first (the 'other' mass, groups/vehicle.py), and without it ``openmdao n2`` draws that
problem (the vehicle group alone) instead of the analysis. ``-o`` gives the diagram its own
name so it does not replace the ``n2.html`` of another step (OpenMDAO's default name).

The full model: the vehicle group and the 15 design conditions with their 171 design variables
(the paper's 161 and 10 transition roll/yaw speed differentials) and 96 constraints (paper Table 6).
Every variable of the final case is recorded to ``run_analysis_out/cases.sql``; read it back
with ``om.CaseReader``.
"""

import openmdao.api as om

from lpc_mdo.problems import build_analysis_problem
from lpc_mdo.vehicle import reference_vehicle

vehicle = reference_vehicle()  # or lpc_mdo.vehicle.load_vehicle("my_lpc.toml")
prob = build_analysis_problem(vehicle, name="run_analysis")
case_file = prob.get_outputs_dir(mkdir=True) / "cases.sql"
if case_file.exists():  # the recorder starts the file afresh: say so
    print(f"replacing {case_file} (the case file of an earlier run)")
prob.add_recorder(om.SqliteRecorder(case_file))
prob.recording_options["includes"] = ["*"]
prob.final_setup()
prob.run_model()
prob.record("final")

print(f"gross mass {prob.get_val('gross_mass', units='kg')[0]:.2f} kg")
for name in prob.model.condition_names:
    print(f"{name:<14} accelerations {prob.get_val(f'{name}.linear_acceleration')[0]} m/s^2")
prob.cleanup()
