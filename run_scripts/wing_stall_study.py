"""What stops a shrinking wing: the section-lift limit against a lowered wing-area bound.

    python run_scripts/wing_stall_study.py [--lower 8.0] [--problem subproblem_4]
                                           [--optimizer IPOPT] [--out wing_stall_study]

A new user's first change: lower the wing-area bound (here to 8 m^2, the vehicle file's is
0.7 x 19.6 = 13.72 m^2) and minimise the gross mass. Runs the stage twice from the reference
vehicle's initial design, with its constraint kinds as the stage table gives them and again
without the kind ``wing_stall`` (the model before the section-lift limit), and prints for each:
the wing it ends with, whether the area sits on its bound, the cruise C_L, the largest section
c_l / c_l,max of every wing-borne condition against its limit, the active constraints and the
stall-speed check (docs theory/aerodynamics 'Section lift limit'). Each run records to
``<out>/<label>.sql``. A slow study (minutes), not a test.
"""

import argparse
import os
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OPENMDAO_REPORTS", "0")

import numpy as np  # noqa: E402
import openmdao.api as om  # noqa: E402

from lpc_mdo.drivers import make_driver  # noqa: E402
from lpc_mdo.groups.lpc import LPCGroup  # noqa: E402
from lpc_mdo.post.stall import WING_BORNE_KINDS, format_stall_speed_check  # noqa: E402
from lpc_mdo.problems import (  # noqa: E402
    CONSTRAINT_KINDS,
    attach_recorder,
    conditions_of_kinds,
    declare_problem,
)
from lpc_mdo.study_plan import stage  # noqa: E402
from lpc_mdo.vehicle import reference_vehicle  # noqa: E402
from lpc_mdo.vehicle.condition_kinds import is_wing_load_case, wing_stall_limit  # noqa: E402


def run(problem, lower, optimizer, out, with_stall):
    """Optimize ``problem`` with the wing-area lower bound ``lower``; return a summary dict."""
    vehicle = reference_vehicle()
    dv = vehicle.design_variables["wing_area"]
    kinds = stage(problem).constraint_kinds or CONSTRAINT_KINDS
    if not with_stall:
        kinds = tuple(k for k in kinds if k != "wing_stall")
    label = f"{problem}_area_{lower:g}_{'with' if with_stall else 'without'}_wing_stall"
    # The stage's problem as build_problem declares it, with the bound and the kinds changed.
    spec = stage(problem)
    conditions = None if spec.every_condition else conditions_of_kinds(vehicle, spec.kinds)
    model = LPCGroup(vehicle=vehicle, conditions=conditions)
    declare_problem(
        model,
        vehicle,
        design_variables=spec.design_variables,
        constraint_kinds=kinds,
        design_variable_bounds={"wing_area": (lower, dv.upper_array)},
        lateral_trim=False,
    )
    prob = om.Problem(model=model, name=label, reports=False)
    settings = spec.driver_settings(optimizer, False)
    if optimizer == "IPOPT":
        settings["print_level"] = 0
    prob.driver = make_driver(optimizer, **settings)
    attach_recorder(prob, os.path.join(out, f"{label}.sql"))
    prob.setup(mode="rev")
    start = time.perf_counter()
    result = prob.run_driver()
    elapsed = time.perf_counter() - start
    prob.record("final")
    area = float(prob.get_val("wing_area", units="m**2")[0])
    values = prob.driver.get_constraint_values(driver_scaling=False)
    cons = prob.model.get_constraints()
    active = []
    for name, meta in cons.items():
        for bound in ("lower", "upper"):
            limit = meta.get(bound)
            if limit is None or np.all(np.abs(np.asarray(limit)) >= 1e29) or meta["equals"]:
                continue
            gap = np.abs(np.asarray(values[name]) - limit)
            if np.any(gap <= 1e-3 * np.maximum(1.0, np.abs(limit))):
                active.append(name)
    # Design variables on a bound (the vehicle file's bounds, the lowered wing-area one).
    at_bounds = []
    for name, value in prob.driver.get_design_var_values(driver_scaling=False).items():
        spec_dv = vehicle.design_variables[name]
        lows = np.full(spec_dv.size, lower) if name == "wing_area" else spec_dv.lower_array
        for bound, limit in (("lower", lows), ("upper", spec_dv.upper_array)):
            gap = np.abs(np.ravel(value) - np.ravel(limit))
            hit = np.flatnonzero(gap <= 1e-6 * np.maximum(1.0, np.abs(np.ravel(limit))))
            if hit.size:
                where = f"{hit.tolist()}" if np.size(value) > 1 else ""
                at_bounds.append(f"{name}{where} ({bound})")
    # Every wing-borne condition's largest section lift ratio (KS), declared or not.
    limits = vehicle.constraints
    ratios = {
        c.name: (
            float(prob.get_val(f"{c.name}.wing_stall_ratio_ks")[0]),
            wing_stall_limit(limits, is_wing_load_case(c)),
        )
        for c in vehicle.conditions
        if c.name in prob.model.condition_names and c.kind in WING_BORNE_KINDS
    }
    summary = {
        "label": label,
        "success": result.success,
        "time": elapsed,
        "gross_mass": float(prob.get_val("gross_mass", units="kg")[0]),
        "wing_area": area,
        "area_on_bound": abs(area - lower) <= 1e-4 * lower,
        "aspect_ratio": float(prob.get_val("wing_aspect_ratio")[0]),
        "cruise_CL": float(prob.get_val("cruise.CL")[0]),
        "ratios": ratios,
        "active": sorted(set(active)),
        "at_bounds": at_bounds,
        "stall": format_stall_speed_check(prob, vehicle),
    }
    prob.cleanup()
    return summary


def main(argv=None):
    """Run the study and print its table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lower", type=float, default=8.0, help="wing-area lower bound, m^2")
    parser.add_argument("--problem", default="subproblem_4", help="stage to run")
    parser.add_argument("--optimizer", default="IPOPT")
    parser.add_argument("--out", default="wing_stall_study")
    args = parser.parse_args(argv)
    if args.lower <= 0.0:
        parser.error(f"--lower = {args.lower}; allowed: a wing area > 0 m^2")
    os.makedirs(args.out, exist_ok=True)
    for with_stall in (True, False):
        s = run(args.problem, args.lower, args.optimizer, args.out, with_stall)
        print(
            f"\n== {s['label']} ({'converged' if s['success'] else 'NOT converged'}, "
            f"{s['time']:.0f} s)"
        )
        print(
            f"  gross mass {s['gross_mass']:.2f} kg; wing S = {s['wing_area']:.3f} m^2"
            f"{' (ON ITS LOWER BOUND)' if s['area_on_bound'] else ''}, AR = "
            f"{s['aspect_ratio']:.2f}; cruise C_L = {s['cruise_CL']:.3f}"
        )
        for name, (value, limit) in s["ratios"].items():
            print(f"  {name:<14} c_l/c_l,max (KS) {value:.3f} <= {limit:.3f}")
        print(f"  active inequality constraints: {', '.join(s['active']) or 'none'}")
        print(f"  design variables on a bound: {', '.join(s['at_bounds']) or 'none'}")
        print(s["stall"])


if __name__ == "__main__":
    main()
