"""Time the rotor models: the 8 LPC lift rotors x 25 radial stations by BEM in hover.

    python run_scripts/benchmark_rotors.py [--repeats 30] [--num-nodes 1]
    openmdao n2 run_scripts/benchmark_rotors.py      # N2 diagram of the same model

BEM: BEMRotorGroup with the reference vehicle's 8 lift rotors (reference chord and twist
control points, R = 1.524 m, 2 blades), 25 radial stations, hover at 100 m and 1200 rpm with the
default polar. Prints the median wall time over the repeats of

- the BEM components alone: BEMInflowComp.solve_nonlinear (bracketing + Newton solve of all
  8 x 25 inflow angles) and the linearize of BEMInflowComp and BEMLoadsComp;
- the whole group: run_model (evaluate), run_linearize (all partials) and compute_totals (thrust,
  power and the body-frame force and moment wrt radius, chord and twist control points, rpm;
  adjoint);

and the rotor results; then the Pitt–Peters edgewise model (8 x 25 x 25 stations,
``benchmark_pitt_peters.py``).
"""

import argparse
import time

import numpy as np
import openmdao.api as om

from lpc_mdo.components.atmosphere import AtmosphereComp
from lpc_mdo.groups.bem_rotor import BEMRotorGroup
from lpc_mdo.vehicle import reference_vehicle


def median_ms(func, repeats):
    """Median wall time of ``func()`` over ``repeats`` calls, ms."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        func()
        times.append(time.perf_counter() - start)
    return 1e3 * float(np.median(times))


def build_bem_problem(num_nodes=1, num_radial=25):
    """Hover BEM of the 8 reference lift rotors, set up and run once."""
    rotors = reference_vehicle().lift_rotors
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "atmosphere", AtmosphereComp(num_nodes=num_nodes, constants="caddee"), promotes=["*"]
    )
    prob.model.add_subsystem(
        "rotors",
        BEMRotorGroup(rotors=rotors, num_nodes=num_nodes, num_radial=num_radial),
        promotes=["*"],
    )
    prob.setup(mode="rev")
    prob.set_val("altitude", np.full(num_nodes, 100.0))
    prob.set_val("rpm", np.full((len(rotors), num_nodes), 1200.0))
    prob.run_model()
    return prob


def benchmark_bem(repeats, num_nodes):
    """Time and print the BEM model; return the timings (ms) as a dict."""
    start = time.perf_counter()
    prob = build_bem_problem(num_nodes)
    setup_ms = 1e3 * (time.perf_counter() - start)
    group = prob.model.rotors
    inflow, loads = group.inflow, group.loads
    in_vals, out_vals = inflow._inputs, inflow._outputs
    times = {
        "setup + first run": setup_ms,
        "BEM inflow solve (solve_nonlinear)": median_ms(
            lambda: inflow.solve_nonlinear(in_vals, out_vals), repeats
        ),
        "BEM inflow + loads linearize": median_ms(
            lambda: (inflow.run_linearize(), loads.run_linearize()), repeats
        ),
        "run_model (whole group)": median_ms(prob.run_model, repeats),
        "run_linearize (whole group)": median_ms(prob.model.run_linearize, repeats),
        "compute_totals (adjoint)": median_ms(
            lambda: prob.compute_totals(
                of=["thrust", "power", "total_force", "total_moment"],
                wrt=["radius", "chord_cp", "twist_cp", "rpm"],
            ),
            repeats,
        ),
    }
    nr, nrad = len(reference_vehicle().lift_rotors), group.options["num_radial"]
    print(
        f"BEM benchmark: {nr} lift rotors x {nrad} radial stations, {num_nodes} node(s), "
        f"median of {repeats}"
    )
    for name, value in times.items():
        print(f"  {name:<36} {value:8.2f} ms")
    thrust, power = prob.get_val("thrust")[:, 0], prob.get_val("power", units="kW")[:, 0]
    print(
        f"  per rotor: T = {thrust[0]:.1f} N, P = {power[0]:.2f} kW, FoM = "
        f"{prob.get_val('figure_of_merit')[0, 0]:.4f}, tip Mach = "
        f"{prob.get_val('tip_mach')[0, 0]:.4f}; total force z = "
        f"{prob.get_val('total_force')[0, 2]:.1f} N"
    )
    return times


def main(argv=None):
    """Run the BEM benchmark, then the Pitt–Peters benchmark, with the same settings."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=30, help="timed repetitions (>= 1)")
    parser.add_argument("--num-nodes", type=int, default=1, help="operating points (>= 1)")
    args = parser.parse_args(argv)
    if args.repeats < 1 or args.num_nodes < 1:
        parser.error(
            f"--repeats = {args.repeats} and --num-nodes = {args.num_nodes}; both must be >= 1"
        )
    benchmark_bem(args.repeats, args.num_nodes)
    import benchmark_pitt_peters  # the sibling run script (this script's folder is on sys.path)

    benchmark_pitt_peters.main(["--repeats", str(args.repeats), "--nodes", str(args.num_nodes)])


if __name__ == "__main__":
    main()
