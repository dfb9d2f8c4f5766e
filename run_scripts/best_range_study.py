"""Cruise at the best-range speed: the mission example with its cruise speeds optimized.

Usage::

    python run_scripts/best_range_study.py write SIZED.toml OUT.toml
    lpc-mdo optimize --vehicle OUT.toml --output-dir opt
    python run_scripts/best_range_study.py check OUT.toml opt/full.sql

``write`` turns the mission example (or its sized file, ``lpc-mdo size``) into one whose two
cruise conditions have ``speed_rule = "optimized"``, with speed bounds 40-80 m/s. ``check``
re-trims each cruise condition of the optimum at speeds 10 % around the optimizer's and prints
the electrical power P, P/V and the wing sections' lift against its limit (1.2 stall speeds): the
optimizer's speed is the best-range speed where P/V is least among the speeds within the
limit. Writes only the file it is given, and not over an existing one.
"""

import sys
from pathlib import Path

import numpy as np
import openmdao.api as om

CRUISES = ("cruise", "cruise_fast")
SPEED_TABLE = """
[design_variables.{name}_speed]
units = "m/s"
lower = 40.0
upper = 80.0
ref = 50.0
"""


def write(source, target):
    """Write ``target``: ``source`` with its cruise conditions' speeds optimized."""
    target = Path(target)
    if target.exists():
        print(f"best_range_study: {target} exists; give a new file name", file=sys.stderr)
        return 1
    text = Path(source).read_text(encoding="utf-8")
    for name in CRUISES:
        line = f'name = "{name}"\nkind = "steady"\n'
        if line not in text:
            print(f"best_range_study: no steady condition {name!r} in {source}", file=sys.stderr)
            return 1
        text = text.replace(line, line + 'speed_rule = "optimized"\n', 1)
        text += SPEED_TABLE.format(name=name)
    target.write_text(text, encoding="utf-8")
    print(f"wrote {target}")
    return 0


def check(vehicle_file, case_file, factors=(0.9, 0.95, 0.98, 1.0, 1.02, 1.05, 1.1)):
    """Print P and P/V of each cruise condition around the optimizer's speed."""
    from lpc_mdo.problems import build_analysis_problem
    from lpc_mdo.trim import trim
    from lpc_mdo.vehicle.condition_kinds import wing_stall_limit

    reader = om.CaseReader(str(case_file))
    case = reader.get_case(reader.list_cases("driver", out_stream=None)[-1])
    prob = build_analysis_problem(vehicle_file)
    for name, value in case.get_design_vars(scaled=False).items():
        prob.set_val(name, value)
    prob.run_model()
    limit = wing_stall_limit(prob.vehicle.constraints)
    for cond in CRUISES:
        best = float(prob.get_val(f"{cond}_speed", units="m/s")[0])
        print(f"{cond}: the optimizer's speed {best:.2f} m/s")
        rows = []
        for factor in factors:
            prob.set_val(f"{cond}_speed", best * factor, units="m/s")
            result = trim(prob, conditions=[cond])
            power = float(prob.get_val(f"{cond}.electrical_power", units="kW")[0])
            stall = float(np.max(prob.get_val(f"{cond}.wing_stall_ratio_ks")))
            rows.append((best * factor, power / (best * factor), stall <= limit * (1 + 1e-3)))
            print(
                f"  V {best * factor:6.2f} m/s  P {power:7.2f} kW  P/V {rows[-1][1]:.4f} kJ/m  "
                f"wing c_l/c_l,max {stall:.3f} (limit {limit:.3f})  trimmed {result.success}"
            )
        prob.set_val(f"{cond}_speed", best, units="m/s")
        allowed = [row for row in rows if row[2]]
        least = min(allowed, key=lambda row: row[1])
        print(f"  least P/V within the wing-section lift limit at {least[0]:.2f} m/s")
    return 0


def main(argv=None):
    """Run ``write`` or ``check`` (module docstring)."""
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 3 or argv[0] not in ("write", "check"):
        print(__doc__, file=sys.stderr)
        return 2
    return (write if argv[0] == "write" else check)(argv[1], argv[2])


if __name__ == "__main__":
    sys.exit(main())
