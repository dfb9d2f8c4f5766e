"""Benchmark of the full lift-plus-cruise model: one evaluation and one total derivative.

    python run_scripts/benchmark_lpc.py [--repeats 5] [--profile]

Builds the 15-condition model with its 176 design variables (the paper's 161, 10 transition
roll/yaw speed differentials and 5 transition pitch angles) and its constraints (paper Table 6,
ours and the 40 linear transition rotor-speed bounds), then times ``run_model`` and
``compute_totals`` (the objective and all constraints x 176, adjoint) at one point, and
``run_model`` at points moved by 0.1 % (an optimizer's next point: the inner solves iterate
from the last solution). It prints the medians, the ratios to the paper's CSDL figures (7.06 s
forward, 24.84 s derivatives after 3.7 h of compilation; paper Table 9), the component count,
the ratios to a recorded reference run and, with --profile, where the time goes by module (the
OpenMDAO framework's share).
"""

import argparse
import cProfile
import os
import pstats
import statistics
import time

# Dense VLM mat-vecs on a loaded 2-core machine are much faster single-threaded (measured 40x
# on this machine); set before numpy is imported.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENMDAO_REPORTS", "0")

import numpy as np  # noqa: E402
import openmdao.api as om  # noqa: E402

from lpc_mdo.groups.lpc import LPCGroup  # noqa: E402
from lpc_mdo.problems import declare_problem  # noqa: E402
from lpc_mdo.vehicle import load_vehicle  # noqa: E402

PAPER_FORWARD_S = 7.06
PAPER_DERIVATIVE_S = 24.84
#: Reference times, s (2-core machine, idle, median of 5; 2026-12-05, the model before the
#: constraints that keep the optimum buildable): a change of the model is judged by its ratio.
REFERENCE_TIMES = {"setup": 2.96, "run_model": 0.121, "totals": 0.366}
#: Relative move of every design variable for the evaluation at a new point (an optimizer step).
MOVED_BY = 1.0e-3


def build(vehicle=None):
    """Return the set-up full LPC model with a driver, so that totals use the driver scaling."""
    prob = om.Problem(reports=False)
    prob.model = LPCGroup(vehicle=vehicle)
    declare_problem(prob.model)  # paper Table 6 + ours: 176 design variables, every constraint
    prob.driver = om.ScipyOptimizeDriver()  # only so compute_totals uses the driver's scaling
    prob.setup(mode="rev")
    prob.final_setup()
    return prob


def main(argv=None):
    """Time the set-up, evaluation and total derivatives of the full model; print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="timed repetitions (median)")
    parser.add_argument("--profile", action="store_true", help="profile one run + totals")
    parser.add_argument("--vehicle", default=None, help="vehicle file (default: the reference)")
    args = parser.parse_args(argv)

    start = time.perf_counter()
    prob = build(None if args.vehicle is None else load_vehicle(args.vehicle))
    setup = time.perf_counter() - start
    prob.run_model()
    prob.compute_totals()  # warm-up: first linearization allocates the Jacobians

    forward, totals = [], []
    for _ in range(args.repeats):
        t0 = time.perf_counter()
        prob.run_model()
        t1 = time.perf_counter()
        prob.compute_totals()
        t2 = time.perf_counter()
        forward.append(t1 - t0)
        totals.append(t2 - t1)
    # An optimizer's evaluations are at a new point, where the inner solves (rotor inflow,
    # alpha*, motor states) iterate from the last point's solution and the airfoil polars meet
    # new (Re, M): time those too, each design variable moved by up to MOVED_BY.
    rng = np.random.default_rng(0)
    sources = [meta.get("source", name) for name, meta in prob.model.get_design_vars().items()]
    start = {name: prob.get_val(name).copy() for name in sources}
    moved = []
    for _ in range(args.repeats):
        for name, value in start.items():
            prob.set_val(name, value * (1.0 + MOVED_BY * rng.uniform(-1.0, 1.0, value.shape)))
        t0 = time.perf_counter()
        prob.run_model()
        moved.append(time.perf_counter() - t0)
    for name, value in start.items():
        prob.set_val(name, value)
    dvs = sum(m["size"] for m in prob.model.get_design_vars().values())
    cons = sum(m["size"] for m in prob.model.get_constraints().values())
    f_med, t_med = statistics.median(forward), statistics.median(totals)
    print(
        f"full LPC model: {dvs} design variables, {cons} constraints, "
        f"median of {args.repeats} (OPENBLAS_NUM_THREADS={os.environ['OPENBLAS_NUM_THREADS']})"
    )
    print(f"  {'step':<36}{'time [s]':>10}{'paper [s]':>11}{'ratio':>9}")
    print(f"  {'setup + final_setup':<36}{setup:>10.3f}{'13320':>11}{13320.0 / setup:>8.0f}x")
    print(
        f"  {'model evaluation (run_model)':<36}{f_med:>10.3f}{PAPER_FORWARD_S:>11.2f}"
        f"{PAPER_FORWARD_S / f_med:>8.1f}x"
    )
    m_med = statistics.median(moved)
    label = f"  at a point moved by {100 * MOVED_BY:g} %"
    print(f"{label:<38}{m_med:>10.3f}{PAPER_FORWARD_S:>11.2f}{PAPER_FORWARD_S / m_med:>8.1f}x")
    label = f"total derivatives ({1 + cons} x {dvs}, rev)"
    print(
        f"  {label:<36}{t_med:>10.3f}{PAPER_DERIVATIVE_S:>11.2f}{PAPER_DERIVATIVE_S / t_med:>8.1f}x"
    )

    explicit = sum(1 for _ in prob.model.system_iter(recurse=True, typ=om.ExplicitComponent))
    implicit = sum(1 for _ in prob.model.system_iter(recurse=True, typ=om.ImplicitComponent))
    groups = sum(1 for _ in prob.model.system_iter(recurse=True, typ=om.Group))
    print(
        f"\n  {explicit + implicit} components ({explicit} explicit, {implicit} implicit) "
        f"in {groups} groups"
    )
    print(f"\n  {'against the reference run':<36}{'reference':>10}{'ratio':>10}")
    for key, value in (("setup", setup), ("run_model", f_med), ("totals", t_med)):
        base = REFERENCE_TIMES[key]
        print(f"  {key:<36}{base:>10.3f}{value / base:>9.2f}x")

    if args.profile:
        profiler = cProfile.Profile()
        profiler.enable()
        prob.run_model()
        prob.compute_totals()
        profiler.disable()
        stats = pstats.Stats(profiler)
        by_file = {}
        for (filename, _, _func), (_, _, tottime, _, _) in stats.stats.items():
            if "lpc_mdo" in filename or "/components/" in filename or "/groups/" in filename:
                key = os.path.basename(filename)
            elif "openmdao" in filename:
                key = "openmdao (framework)"
            elif "numpy" in filename or "scipy" in filename or filename.startswith("~"):
                key = "numpy/scipy/builtins"
            else:
                key = "other"
            by_file[key] = by_file.get(key, 0.0) + tottime
        total = sum(by_file.values())
        print("\nwhere the time goes (one evaluation + totals, own time by module):")
        for key, value in sorted(by_file.items(), key=lambda kv: -kv[1])[:15]:
            print(f"  {key:<40}{value:>8.3f} s {100 * value / total:>6.1f} %")


if __name__ == "__main__":
    main()
