"""Analyze the reference vehicle's 15 design conditions: a run script to copy and edit.

    python run_scripts/run_analysis.py            # run and print
    openmdao n2 run_scripts/run_analysis.py       # N2 diagram of the same model

The case file lands in ``run_analysis_out/cases.sql``; read it with ``om.CaseReader``.
"""

import openmdao.api as om

from lpc_mdo.problems import build_analysis_problem
from lpc_mdo.vehicle import reference_vehicle

vehicle = reference_vehicle()  # or lpc_mdo.vehicle.load_vehicle("my_lpc.toml")
prob = build_analysis_problem(vehicle, name="run_analysis")
prob.add_recorder(om.SqliteRecorder(prob.get_outputs_dir(mkdir=True) / "cases.sql"))
prob.final_setup()
prob.run_model()
prob.record("final")

for name, mach, q in zip([c.name for c in vehicle.conditions],
                         prob.get_val("conditions.mach"),
                         prob.get_val("conditions.dynamic_pressure", units="Pa"), strict=True):
    print(f"{name:<14} Mach {mach:6.4f}   q {q:8.1f} Pa")
prob.cleanup()
