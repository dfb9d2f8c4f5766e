"""Size the wing box at +3g/-1g and store its thicknesses as the vehicle file's initial gauges.

    python run_scripts/size_wing_gauges.py [--vehicle FILE] [--write]

Runs the warm start's structural subproblem (``build_problem('subproblem_3')``, paper Table 2:
minimum gross mass over the 32 skin and spar thicknesses subject to skin buckling and trim at
+3g and -1g) on the vehicle's initial design, reports the von Mises stress ratio there, and
prints the sized thicknesses, root to tip. With ``--write`` it replaces the ``initial = ...``
line of the four ``[design_variables.*_thickness]`` tables of the vehicle file, so that the
initial design (and the W_other calibration of :func:`lpc_mdo.groups.vehicle.calibrated_other_mass`)
starts from a wing that is feasible at +3g/-1g (issue 17 item 2). Re-run it whenever the wing
planform, the wing-box model or the loads change (e.g. after merging the cranked wing).
"""

import argparse
import os
import re
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OPENMDAO_REPORTS", "0")

import numpy as np  # noqa: E402

from lpc_mdo.problems import build_problem  # noqa: E402
from lpc_mdo.vehicle import load_vehicle, reference_vehicle  # noqa: E402

THICKNESSES = (
    "front_spar_thickness",
    "rear_spar_thickness",
    "top_skin_thickness",
    "bottom_skin_thickness",
)
REFERENCE_FILE = os.path.join(
    os.path.dirname(__file__), os.pardir, "lpc_mdo", "data", "lpc_reference.toml"
)


def size_gauges(vehicle=None):
    """Return the sized thicknesses (m, dict of 8-vectors), the box mass (kg) and the result."""
    prob = build_problem("subproblem_3", vehicle=vehicle, optimizer="IPOPT")
    prob.driver.options["print_level"] = 0
    start = time.perf_counter()
    result = prob.run_driver()
    elapsed = time.perf_counter() - start
    gauges = {name: np.asarray(prob.get_val(name, units="m")).ravel() for name in THICKNESSES}
    box = float(prob.get_val("wing_mass", units="kg")[0])
    return gauges, box, result, elapsed


def write_gauges(path, gauges):
    """Replace the ``initial`` line of each thickness table of the TOML file at ``path``."""
    with open(path) as f:
        text = f.read()
    for name, values in gauges.items():
        listed = ", ".join(f"{v:.6g}" for v in values)
        pattern = rf"(\[design_variables\.{name}\]\nunits = \"m\"\n)initial = [^\n]*"
        line = f"initial = [{listed}]   # sized at +3g/-1g (run_scripts/size_wing_gauges.py)"
        text, count = re.subn(pattern, lambda m, line=line: m.group(1) + line, text)
        if count != 1:
            raise ValueError(f"{path}: no unique [design_variables.{name}] table with units first")
    with open(path, "w") as f:
        f.write(text)


def main():
    """Size the gauges, print them and optionally write them into the vehicle file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--vehicle", default=None, help="vehicle TOML (default: the reference)")
    parser.add_argument("--write", action="store_true", help="write the gauges into the file")
    args = parser.parse_args()
    vehicle = load_vehicle(args.vehicle) if args.vehicle else reference_vehicle()
    gauges, box, result, elapsed = size_gauges(vehicle)
    print(f"success {result.success}, {result.iter_count} iterations, {elapsed:.1f} s")
    print(f"wing-box mass (both halves): {box:.2f} kg")
    for name, values in gauges.items():
        print(f"{name:<24}" + " ".join(f"{1e3 * v:7.3f}" for v in values) + "  mm")
    if args.write:
        write_gauges(args.vehicle or REFERENCE_FILE, gauges)
        print(f"written to {args.vehicle or REFERENCE_FILE}")


if __name__ == "__main__":
    main()
