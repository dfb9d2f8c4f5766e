"""Analyze the reference vehicle at its initial design, trimmed: a run script to copy and edit.

    python run_scripts/run_analysis.py            # trim, run, record and print
    openmdao n2 --problem run_analysis -o run_analysis_n2.html run_scripts/run_analysis.py
                                                  # N2 diagram of the same model

``--problem run_analysis`` is needed: the trim builds one small problem per condition (and a
vehicle with the paper's calibrated 'other' mass, groups/vehicle.py, one more); without it
``openmdao n2`` may draw one of those instead of the analysis. ``-o``
gives the diagram its own name so it does not replace the ``n2.html`` of another step.

The full model: the vehicle group and the 15 design conditions with their 176 design variables
(the paper's 161, 10 transition roll/yaw speed differentials and 5 transition pitch angles) and
98 constraints (paper Table 6 and the 2 wing-box stress constraints).
Every condition is trimmed by its trim variables (rotor speeds, pitch, elevator) through
:func:`lpc_mdo.analysis.analyze_vehicle`, the code path of ``lpc-mdo analyze``; pass
``trim=False`` for the raw initial design. Every variable of the final case is recorded to
``run_analysis_out/cases.sql``; read it back with ``om.CaseReader``.
"""

from pathlib import Path

from lpc_mdo.analysis import analyze_vehicle, format_trim_variables
from lpc_mdo.vehicle import reference_vehicle

vehicle = reference_vehicle()  # or lpc_mdo.vehicle.load_vehicle("my_lpc.toml")
case_file = Path("run_analysis_out") / "cases.sql"
case_file.parent.mkdir(exist_ok=True)
if case_file.exists():  # the recorder starts the file afresh: say so
    print(f"replacing {case_file} (the case file of an earlier run)")
analysis = analyze_vehicle(vehicle, trim=True, recorder_path=case_file, name="run_analysis")
prob = analysis.prob

print(f"gross mass {prob.get_val('gross_mass', units='kg')[0]:.2f} kg")
for name in prob.model.condition_names:
    print(f"{name:<14} accelerations {prob.get_val(f'{name}.linear_acceleration')[0]} m/s^2")
print(format_trim_variables(prob))
for name, residual in analysis.failed.items():
    print(f"{name} did not trim: largest scaled trim residual {residual:.3g}")
prob.cleanup()
