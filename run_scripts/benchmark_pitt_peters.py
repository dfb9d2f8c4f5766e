"""Benchmark: steady Pitt–Peters inflow and loads of the 8 LPC lift rotors (evaluate + linearize).

PittPetersInflowComp + PittPetersLoadsComp with 8 rotors x 25 radial x 25 azimuthal stations at
the reference vehicle's first transition point (22 m/s, pitch -2.85 deg), lift-rotor blades of the
vehicle file (R = 1.524 m, chord 0.3 -> 0.1 m, twist 30 -> 10 deg), 1100 rpm. Times, as the median
of ``--repeats`` runs after one warm-up run:

- evaluate from a cold start: the Newton solve of the 3 inflow states per rotor from the default
  initial states, plus the loads (``run_model``);
- evaluate warm: ``run_model`` again after a 1 rpm change (the optimizer's usual case);
- linearize: the exact partials of both components (``run_linearize``);
- the adjoint totals of the thrusts and hub moments with respect to rpm, chord, twist, radius
  and the velocities (``compute_totals``: linearize + block solve + transposed products).

Usage::

    python run_scripts/benchmark_pitt_peters.py [--repeats 15] [--nodes 1] [--no-swirl]

``--no-swirl`` runs the model without the tangential induction (docs theory/rotors 'Pitt-Peters
inflow'), to see what the per-station swirl solve costs.
"""

import argparse
import os
import time

import numpy as np
import openmdao.api as om

from lpc_mdo.components.rotor.pitt_peters_inflow import PittPetersInflowComp
from lpc_mdo.components.rotor.pitt_peters_loads import PittPetersLoadsComp
from lpc_mdo.groups.bem_rotor import rotor_options
from lpc_mdo.vehicle import reference_vehicle


def build_problem(num_radial=25, num_azimuth=25, num_nodes=1, tangential_induction=True):
    """Problem with the two Pitt–Peters components for the 8 lift rotors of the vehicle."""
    vehicle = reference_vehicle()
    opts = rotor_options(vehicle.lift_rotors)
    nr = opts["num_rotors"]
    condition = next(c for c in vehicle.conditions if c.name == "transition_1")
    kw = dict(
        num_rotors=nr,
        num_nodes=num_nodes,
        num_radial=num_radial,
        num_azimuth=num_azimuth,
        num_blades=opts["num_blades"],
        spin_direction=opts["spin_direction"],
        tangential_induction=tangential_induction,
    )
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("inflow", PittPetersInflowComp(**kw), promotes=["*"])
    prob.model.add_subsystem("loads", PittPetersLoadsComp(**kw), promotes=["*"])
    prob.setup(mode="rev")

    radius = np.array([r.radius for r in vehicle.lift_rotors])
    rh = radius * np.array(opts["hub_radius_ratio"])
    eta = (np.arange(num_radial) + 0.5) / num_radial
    prob.set_val("radius", radius)
    prob.set_val("hub_radius", rh)
    prob.set_val("station_radius", rh[:, None] + (radius - rh)[:, None] * eta)
    prob.set_val("station_width", ((radius - rh) / num_radial)[:, None] * np.ones(num_radial))
    prob.set_val("chord", np.tile(np.linspace(0.3, 0.1, num_radial), (nr, 1)))
    prob.set_val("twist", np.tile(np.radians(np.linspace(30.0, 10.0, num_radial)), (nr, 1)))
    prob.set_val("rpm", np.full((nr, num_nodes), 1100.0))
    # Body velocity (u, 0, w) of the condition; lift rotors: n = -z, e_x = +x.
    u = condition.speed * np.cos(condition.pitch)
    w = condition.speed * np.sin(condition.pitch)
    prob.set_val("axial_velocity", np.full((nr, num_nodes), -w))
    inplane = np.zeros((nr, num_nodes, 2))
    inplane[..., 0] = u
    prob.set_val("inplane_velocity", inplane)
    return prob


def _median_time(fn, repeats):
    fn()  # warm-up
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def main(argv=None):
    """Time the cold and warm evaluations, the linearization and the totals; return the times."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=15, help="timed runs per measurement")
    parser.add_argument("--nodes", type=int, default=1, help="operating points per rotor")
    parser.add_argument("--no-swirl", action="store_true", help="without tangential induction")
    args = parser.parse_args(argv)
    os.environ.setdefault("OPENMDAO_REPORTS", "0")

    prob = build_problem(num_nodes=args.nodes, tangential_induction=not args.no_swirl)
    comp = prob.model.inflow
    num_rotors = prob.get_val("inflow_states").shape[0]
    cold = np.tile([0.05, 0.0, 0.0], (num_rotors, args.nodes, 1))
    rpm = prob.get_val("rpm").copy()
    iterations = {}

    def evaluate_cold():
        prob.set_val("inflow_states", cold)
        prob.run_model()
        iterations["cold"] = comp.newton_iterations

    toggle = [0.0]

    def evaluate_warm():
        toggle[0] = 1.0 - toggle[0]
        prob.set_val("rpm", rpm + toggle[0])
        prob.run_model()
        iterations["warm"] = comp.newton_iterations

    def totals():
        prob.compute_totals(
            of=["thrust", "hub_moment"],
            wrt=["rpm", "chord", "twist", "radius", "axial_velocity", "inplane_velocity"],
        )

    t_cold = _median_time(evaluate_cold, args.repeats)
    t_warm = _median_time(evaluate_warm, args.repeats)
    t_lin = _median_time(prob.model.run_linearize, args.repeats)
    t_tot = _median_time(totals, args.repeats)

    shape = f"8 rotors x {args.nodes} node(s) x 25 radial x 25 azimuthal"
    print(f"Pitt–Peters benchmark: {shape}, median of {args.repeats} runs")
    print(
        f"  evaluate, cold start ({iterations['cold']} Newton iterations): {1e3 * t_cold:7.1f} ms"
    )
    print(
        f"  evaluate, warm start ({iterations['warm']} Newton iterations): {1e3 * t_warm:7.1f} ms"
    )
    print(f"  linearize (exact partials, both components):  {1e3 * t_lin:7.1f} ms")
    print(
        f"  compute_totals ({8 * args.nodes} thrusts + {16 * args.nodes} hub moments, adjoint): "
        f"{1e3 * t_tot:7.1f} ms"
    )
    print(f"  thrust per rotor: {np.round(prob.get_val('thrust')[:, 0], 1)} N")
    print(f"  inflow states rotor 0: {np.round(prob.get_val('inflow_states')[0, 0], 5)}")
    return {"evaluate_cold": t_cold, "evaluate_warm": t_warm, "linearize": t_lin, "totals": t_tot}


if __name__ == "__main__":
    main()
