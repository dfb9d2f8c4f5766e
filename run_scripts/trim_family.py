"""
How much a vehicle's trimmed numbers depend on where the trim starts.

Usage::

    python run_scripts/trim_family.py [--vehicle FILE] [--seeds 5] [--fraction 0.1]
                                      [--processes 2] [--start-member]

Hover, transition and one-rotor-out conditions have more trim variables than trim rows, so a
family of trims holds each. The script trims the vehicle's initial design as ``lpc-mdo
analyze`` does, once from the file's trim values and once from each of ``--seeds`` starts
whose trim variables are perturbed uniformly within +-``--fraction`` of them, and prints the
spread of the mission energy, the final state of charge and each condition's electrical power.
By default each trim is the least-power one within the condition's limits (what ``analyze`` and
``size`` use); ``--start-member`` instead keeps the member the solve reaches from its start.

docs theory/optimization 'Trim before each stage' shows the numbers.
"""

import argparse
import sys
import tempfile

import numpy as np

from lpc_mdo.groups.lpc import openmdao_units
from lpc_mdo.problems import build_analysis_problem
from lpc_mdo.trim import free_trim_variables, problem_vehicle, trim
from lpc_mdo.vehicle import load_vehicle
from lpc_mdo.vehicle.condition_layout import condition_layout


def perturb_trim_variables(prob, fraction, seed):
    """Scale every condition's trim-variable entries by 1 + U(-fraction, fraction)."""
    vehicle = problem_vehicle(prob)
    rng = np.random.default_rng(seed)
    layout = condition_layout(vehicle)
    for cond in prob.model.condition_names:
        for name, flat in layout.trim_variables(cond):
            units = openmdao_units(vehicle.design_variables[name].units)
            value = np.asarray(prob.get_val(name, units=units), dtype=float).copy()
            flat = np.atleast_1d(flat)
            value.reshape(-1)[flat] *= 1.0 + rng.uniform(-fraction, fraction, flat.size)
            prob.set_val(name, value, units=units)


def trimmed_numbers(vehicle, seed, fraction, least_power, processes, work_dir):
    """Trim the initial design from a start (seed None: the file's); return its numbers."""
    prob = build_analysis_problem(vehicle, work_dir=work_dir, name="trim_family")
    if seed is not None:
        perturb_trim_variables(prob, fraction, seed)
    result = trim(prob, workers=processes, least_power=least_power)
    powers = {
        cond: float(prob.get_val(f"{cond}.electrical_power", units="kW")[0])
        for cond in prob.model.condition_names
        if free_trim_variables(vehicle, cond) > 0
    }
    notes = {c: r.power[2] for c, r in result.conditions.items() if r.power is not None}
    return {
        "trimmed": result.success,
        "energy": float(prob.get_val("energy_used", units="kW*h")[0]),
        "soc": float(prob.get_val("state_of_charge")[0]),
        "powers": powers,
        "notes": notes,
    }


def main(argv=None):
    """Run the measurement of ``argv`` (default: the command line); return the exit status."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--vehicle", default=None, help="vehicle file (default: the reference)")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--fraction", type=float, default=0.1)
    parser.add_argument("--processes", type=int, default=1)
    parser.add_argument("--start-member", action="store_true")
    args = parser.parse_args(argv)
    if args.seeds < 1 or not 0.0 < args.fraction < 1.0 or args.processes < 1:
        parser.error(
            f"--seeds {args.seeds}, --fraction {args.fraction}, --processes {args.processes}: "
            "need seeds >= 1, 0 < fraction < 1 and processes >= 1"
        )
    try:
        vehicle = load_vehicle(args.vehicle)
    except (OSError, ValueError) as err:
        print(f"trim_family: {err}", file=sys.stderr)
        return 2
    least_power = not args.start_member
    with tempfile.TemporaryDirectory() as work_dir:
        runs = [
            trimmed_numbers(vehicle, seed, args.fraction, least_power, args.processes, work_dir)
            for seed in [None, *range(args.seeds)]
        ]
    what = "least power within the limits" if least_power else "the member the solve reaches"
    print(f"{vehicle.name}: trims from the file's values and from {args.seeds} starts within "
          f"+-{100 * args.fraction:g} % of them ({what})")  # fmt: skip
    base, others = runs[0], runs[1:]
    print(f"  all trimmed: {all(r['trimmed'] for r in runs)}")
    for key, unit in (("energy", "kWh"), ("soc", "")):
        values = [r[key] for r in others]
        print(f"  {key:8s} {base[key]:10.4f} {unit:4s} perturbed {min(values):.4f} to "
              f"{max(values):.4f} ({100 * (min(values) / base[key] - 1):+.2f} to "
              f"{100 * (max(values) / base[key] - 1):+.2f} %)")  # fmt: skip
    for cond, power in base["powers"].items():
        values = [r["powers"][cond] for r in others]
        note = base["notes"].get(cond, "")
        print(f"  {cond:14s} {power:8.1f} kW  perturbed {min(values):8.1f} to {max(values):8.1f} "
              f"({100 * (min(values) / power - 1):+.2f} to {100 * (max(values) / power - 1):+.2f} "
              f"%)  {note}")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
