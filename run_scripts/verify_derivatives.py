"""Verify the full model's total derivatives against finite differences (paper Fig. 12 idea).

    python run_scripts/verify_derivatives.py [--steps 1e-2 1e-3 1e-4 1e-5 1e-6 1e-7] [--out fig]
        [--vehicle FILE] [--complex-step-only]

Computes all totals of the objective and the 98 constraints with respect to the 176 design
variables (the paper's 161, 10 transition roll/yaw speed differentials, 5 transition pitches) by
the adjoint method, then by forward finite differences in the driver-scaled space for each step
size, and plots the relative error ||J_fd - J_adj|| / ||J_adj|| against the step: it falls
with the step (truncation) until round-off takes over, as in the paper's Fig. 12.
Also prints the complex-step comparison, which has no step-size trade-off.
"""

import argparse
import os
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OPENMDAO_REPORTS", "0")

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import openmdao.api as om  # noqa: E402

from lpc_mdo.groups.lpc import LPCGroup  # noqa: E402
from lpc_mdo.problems import declare_problem  # noqa: E402
from lpc_mdo.vehicle import load_vehicle  # noqa: E402


def jacobian(prob, method=None, step=None):
    """Dense driver-scaled total Jacobian (rows: objective then constraints)."""
    of = list(prob.model.get_objectives()) + list(prob.model.get_constraints())
    wrt = list(prob.model.get_design_vars())
    if method is None:  # every row, the linear constraints' too, as check_totals gives them
        totals = prob.compute_totals(of=of, wrt=wrt, driver_scaling=True, return_format="array")
        return np.asarray(totals)
    kwargs = {"form": "forward"} if method == "fd" else {}
    data = prob.check_totals(
        method=method, step=step, out_stream=None, driver_scaling=True, **kwargs
    )
    rows = []
    for o in of:
        rows.append(np.hstack([np.atleast_2d(data[o, w]["J_fd"]) for w in wrt]))
    return np.vstack(rows)


def main(argv=None):
    """Compare the adjoint totals with finite differences of each step and complex step."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--steps", type=float, nargs="+", default=[1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7]
    )
    parser.add_argument(
        "--out", default="derivative_verification", help="output folder for the PNG and the numbers"
    )
    parser.add_argument("--vehicle", help="vehicle file (default: the reference vehicle)")
    parser.add_argument(
        "--complex-step-only", action="store_true", help="skip the finite-difference steps"
    )
    args = parser.parse_args(argv)
    if args.complex_step_only:
        args.steps = []

    prob = om.Problem(reports=False)
    prob.model = LPCGroup(vehicle=load_vehicle(args.vehicle))
    declare_problem(prob.model)  # paper Table 6 + ours: 176 design variables, 98 + 40 constraints
    prob.setup(mode="rev", force_alloc_complex=True)
    prob.run_model()
    adjoint = jacobian(prob)
    norm = np.linalg.norm(adjoint)

    os.makedirs(args.out, exist_ok=True)
    errors = []
    for step in args.steps:
        t0 = time.perf_counter()
        fd = jacobian(prob, "fd", step)
        errors.append(np.linalg.norm(fd - adjoint) / norm)
        print(
            f"step {step:8.1e}: relative error {errors[-1]:.3e} ({time.perf_counter() - t0:.1f} s)"
        )
    cs = jacobian(prob, "cs")
    cs_error = np.linalg.norm(cs - adjoint) / norm
    significant = np.abs(adjoint) > 1e-6 * np.abs(adjoint).max()
    entrywise = np.max(np.abs(cs - adjoint)[significant] / np.abs(adjoint)[significant])
    print(
        f"complex step: relative error {cs_error:.3e}; largest entry-wise relative error "
        f"{entrywise:.3e} over {significant.sum()} entries above 1e-6 of the largest"
    )

    if not errors:
        return
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.loglog(args.steps, errors, "o-", label="forward FD vs adjoint")
    ax.axhline(cs_error, color="k", ls="--", label="complex step vs adjoint")
    ax.set_xlabel("finite-difference step (driver-scaled)")
    ax.set_ylabel(r"$\|J_{FD} - J_{adj}\| / \|J_{adj}\|$")
    ax.set_title(f"Full LPC model, {adjoint.shape[0]} x {adjoint.shape[1]} totals")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    path = os.path.join(args.out, "derivative_verification.png")
    fig.savefig(path, dpi=150)
    np.savetxt(
        os.path.join(args.out, "derivative_verification.csv"),
        np.column_stack([args.steps, errors]),
        delimiter=",",
        header="step,relative_error",
        comments="",
    )
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
