"""Time the wing + horizontal-tail VLM on the paper's mesh (wing 26 x 1, h-tail 8 x 1 panels).

    python run_scripts/benchmark_vlm.py [--repeats 30] [--num-nodes 1]
    openmdao n2 run_scripts/benchmark_vlm.py      # N2 diagram of the same model

Geometry: the reference vehicle's wing and h-tail meshed by PlanformMeshComp (cosine span-wise
spacing) feeding VLMGroup; cruise condition (M 0.17 at 999.74 m, 2 deg). Prints the median
wall time of run_model (evaluate), run_linearize (all partials) and compute_totals (linearize
plus one adjoint solve per output) over the repeats, and the aerodynamic results.

BLAS runs single-threaded here (set before numpy is imported): the matrices are small, and on a
shared machine multi-threaded BLAS made a 1530 x 408 mat-vec 40 times slower. Export
OPENBLAS_NUM_THREADS etc. yourself to override.
"""

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import math  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
import openmdao.api as om  # noqa: E402

from lpc_mdo.components.geometry.planform import PlanformMeshComp, planform_values  # noqa: E402
from lpc_mdo.groups.vlm import VLMGroup, lpc_vlm_surfaces  # noqa: E402
from lpc_mdo.vehicle import reference_vehicle  # noqa: E402


def build_problem(num_nodes=1):
    """Planform meshes of the reference vehicle + VLMGroup, set up and run once."""
    vehicle = reference_vehicle()
    surfaces = lpc_vlm_surfaces()
    prob = om.Problem(reports=False)
    for surface in surfaces:
        prob.model.add_subsystem(
            f"{surface.name}_planform",
            PlanformMeshComp(
                num_span_panels=surface.num_span_panels, num_chord_panels=surface.num_chord_panels
            ),
            promotes_outputs=[("mesh", f"{surface.name}_mesh")],
        )
    prob.model.add_subsystem(
        "vlm", VLMGroup(surfaces=surfaces, num_nodes=num_nodes), promotes=["*"]
    )
    prob.setup(mode="rev")
    for surface, data in zip(surfaces, (vehicle.wing, vehicle.horizontal_tail), strict=True):
        for name, value in planform_values(data).items():
            prob.set_val(f"{surface.name}_planform.{name}", value)
    prob.set_val("speed", np.full(num_nodes, 57.1897))
    prob.set_val("density", np.full(num_nodes, 1.11177))
    prob.set_val("angle_of_attack", np.full(num_nodes, math.radians(2.0)))
    prob.set_val("reference_area", vehicle.wing.area)
    prob.set_val("reference_point", [-2.37, 0.0, 0.0])
    prob.run_model()
    return prob


def median_ms(func, repeats):
    """Return the median wall time of ``repeats`` calls of ``func``, in milliseconds."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        func()
        times.append(time.perf_counter() - start)
    return 1e3 * float(np.median(times))


def main(argv=None):
    """Time the VLM set-up, evaluation, linearization and totals; print them, return the problem."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=30, help="timed repetitions (>= 1)")
    parser.add_argument("--num-nodes", type=int, default=1, help="flight conditions (>= 1)")
    args = parser.parse_args(argv)
    if args.repeats < 1 or args.num_nodes < 1:
        parser.error(
            f"--repeats = {args.repeats} and --num-nodes = {args.num_nodes}; both must be >= 1"
        )

    start = time.perf_counter()
    prob = build_problem(args.num_nodes)
    setup_s = time.perf_counter() - start
    of = ["CL", "CDi", "moment", "wing_sectional_cl"]
    wrt = [
        "wing_planform.span",
        "wing_planform.root_chord",
        "wing_planform.tip_chord",
        "horizontal_tail_planform.span",
        "angle_of_attack",
        "horizontal_tail_deflection",
    ]
    evaluate = median_ms(prob.run_model, args.repeats)
    linearize = median_ms(prob.model.run_linearize, args.repeats)
    totals_cl = median_ms(lambda: prob.compute_totals(of=["CL"], wrt=wrt), args.repeats)
    totals = median_ms(lambda: prob.compute_totals(of=of, wrt=wrt), args.repeats)

    npn = sum(s.num_panels for s in lpc_vlm_surfaces())
    print(
        f"VLM benchmark: wing 26 x 1 + h-tail 8 x 1 = {npn} panels, "
        f"{args.num_nodes} node(s), median of {args.repeats}"
    )
    print(f"  setup + first run     {1e3 * setup_s:8.1f} ms")
    print(f"  evaluate (run_model)  {evaluate:8.2f} ms")
    print(f"  linearize (partials)  {linearize:8.2f} ms")
    print(
        f"  compute_totals, CL    {totals_cl:8.2f} ms  (linearize + {args.num_nodes} adjoint "
        f"solve(s), {len(wrt)} inputs)"
    )
    print(
        f"  compute_totals        {totals:8.2f} ms  ({', '.join(of)} x {len(wrt)} inputs, "
        "one adjoint solve per output entry)"
    )
    print(
        f"  CL {prob.get_val('CL')[0]:.5f}  CDi {prob.get_val('CDi')[0]:.6f}  "
        f"Trefftz D_i {prob.get_val('trefftz_induced_drag')[0]:.2f} N  "
        f"near-field D_i {prob.get_val('induced_drag')[0]:.2f} N  "
        f"M_y {prob.get_val('moment')[0, 1]:.1f} N*m"
    )
    return prob


if __name__ == "__main__":
    main()
