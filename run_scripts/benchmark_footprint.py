"""Benchmark: the full model with and without a departure noise footprint, side by side.

    python run_scripts/benchmark_footprint.py VEHICLE.toml [--repeats 15]

Builds the full problem of the reference vehicle and of ``VEHICLE.toml`` (the reference with a
``[noise_footprint]`` table, e.g. from ``run_scripts/footprint_study.py write``), then times
``run_model`` and ``compute_totals`` (every objective and constraint row, adjoint, driver
scaling) of the two in turn, ``--repeats`` times, so that both see the same machine load.
Prints the medians and their ratios.
"""

import argparse
import os
import statistics
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENMDAO_REPORTS", "0")

from benchmark_lpc import build  # noqa: E402

from lpc_mdo.vehicle import load_vehicle  # noqa: E402


def main(argv=None):
    """Time both models in turn and print the medians and ratios."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("vehicle", help="vehicle file with a [noise_footprint] table")
    parser.add_argument("--repeats", type=int, default=15, help="timed rounds (median)")
    args = parser.parse_args(argv)
    problems = {"reference": build(), "with footprint": build(load_vehicle(args.vehicle))}
    times = {name: {"run_model": [], "totals": []} for name in problems}
    for prob in problems.values():  # warm-up: the first linearization allocates the Jacobians
        prob.run_model()
        prob.compute_totals()
    for _ in range(args.repeats):
        for name, prob in problems.items():
            t0 = time.perf_counter()
            prob.run_model()
            t1 = time.perf_counter()
            prob.compute_totals()
            t2 = time.perf_counter()
            times[name]["run_model"].append(t1 - t0)
            times[name]["totals"].append(t2 - t1)
    medians = {
        name: {step: statistics.median(values) for step, values in steps.items()}
        for name, steps in times.items()
    }
    print(f"median of {args.repeats} alternating rounds, OPENBLAS_NUM_THREADS=1")
    print(f"  {'step':<28}{'reference [s]':>15}{'with footprint [s]':>20}{'ratio':>8}")
    for step, label in (("run_model", "model evaluation"), ("totals", "total derivatives")):
        a, b = medians["reference"][step], medians["with footprint"][step]
        print(f"  {label:<28}{a:>15.3f}{b:>20.3f}{b / a:>7.2f}x")
    return medians


if __name__ == "__main__":
    main()
