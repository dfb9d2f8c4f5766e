"""Check the post-optimal sensitivities against finite differences of re-optimized neighbours.

    python run_scripts/check_sensitivities.py --start-case full.sql [--output-dir sens_out]
        [--parameters energy_density,final_soc,...] [--steps payload=40,...]
        [--max-iter 100] [--tol 1e-6] [--processes 2] [--vehicle file.toml]

At the optimum recorded in ``--start-case`` (a full-problem run) it evaluates
d(W0*)/d(parameter) from the KKT multipliers and the adjoint
(:func:`lpc_mdo.sensitivities.sensitivities_from_case`), then re-optimizes the full problem
with each parameter moved by -step and +step (the vehicle changed as ``lpc-mdo sweep`` changes
it; trimmed, then the optimizer from the start case's design), and compares the central
difference (W0*(p + h) - W0*(p - h)) / 2h with the sensitivity. Prints and writes
``sensitivity_check.md``; exits 1 when a relative difference exceeds 10 % or a
neighbour fails to run.

Every neighbour gets the same optimizer settings (``--max-iter`` iterations at ``--tol``), so
that how far the last iterations creep along a flat valley is common to both and cancels in the
central difference. Start from an optimum converged as tightly (its KKT residual, printed, is
what limits the sensitivities; with SLSQP at the full problem's tol 3e-4 it was 6 % and the
sensitivities 22 % off, measured 2026-12-04). A bound that is not active (the static-margin
limit when the margin is above it) has sensitivity 0 and no neighbour is run: moving an
inactive limit within its slack leaves the optimum where it is.
"""

import argparse
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # see benchmark_lpc.py
os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENMDAO_REPORTS", "0")

from lpc_mdo.drivers import tolerance_settings  # noqa: E402
from lpc_mdo.sensitivities import SENSITIVITY_PARAMETERS, sensitivities_from_case  # noqa: E402
from lpc_mdo.sweep_parameters import reference_value, sweep_vehicle  # noqa: E402
from lpc_mdo.vehicle import load_vehicle  # noqa: E402

#: Default steps h (units of the parameter): large enough that W0* moves by tens of kg, so the
#: optimizer's stopping tolerance (about 1 kg) is small against 2h dW0*/dp.
DEFAULT_STEPS = {
    "energy_density": 20.0,
    "final_soc": 0.03,
    "max_noise": 2.0,
    "payload": 40.0,
    "min_static_margin": 0.02,
    "cruise_range": 8.0,
}
#: A sensitivity must lie within 10 % of the re-optimized difference.
TOLERANCE = 0.10


def _neighbour(task):
    """Re-optimize the full problem for one changed parameter value; return W0* or None."""
    from lpc_mdo.warm_start import solve_stage

    vehicle_file, parameter, value, start_case, static_margin, out_dir, settings = task
    vehicle = sweep_vehicle(load_vehicle(vehicle_file), parameter, value)
    case_file = Path(out_dir) / f"{parameter}_{value:g}.sql"
    try:
        stage = solve_stage(
            "full",
            str(case_file),
            vehicle=vehicle,
            start_case=start_case,
            static_margin=static_margin,
            optimizer="SLSQP",
            driver_settings=settings,
            rescale=True,
            log=lambda msg: print(f"{parameter}={value:g}: {msg}", flush=True),
        )
    except Exception as err:  # reported in the table, never dropped
        print(f"{parameter}={value:g}: failed: {err}", flush=True)
        return parameter, value, None, 0, 0.0
    return parameter, value, stage.gross_mass, stage.iterations, stage.seconds


def main(argv=None):
    """Evaluate, re-optimize, compare; return the exit status."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--start-case", required=True, help="full-problem case file (optimum)")
    parser.add_argument("--output-dir", default="sensitivity_check", help="folder for the runs")
    parser.add_argument(
        "--parameters",
        default=",".join(SENSITIVITY_PARAMETERS),
        help=f"comma-separated subset of {','.join(SENSITIVITY_PARAMETERS)}",
    )
    parser.add_argument("--steps", default="", help="name=h,... overriding DEFAULT_STEPS")
    parser.add_argument("--max-iter", type=int, default=100, help="SLSQP iterations per run")
    parser.add_argument("--tol", type=float, default=1e-6, help="SLSQP tolerance per run")
    parser.add_argument("--processes", type=int, default=2, help="neighbours run at once")
    parser.add_argument("--vehicle", default=None, help="vehicle file of the start case's run")
    args = parser.parse_args(argv)

    names = [n for n in args.parameters.split(",") if n]
    unknown = [n for n in names if n not in SENSITIVITY_PARAMETERS]
    if unknown:
        parser.error(f"--parameters: {unknown}; allowed: {list(SENSITIVITY_PARAMETERS)}")
    steps = dict(DEFAULT_STEPS)
    for item in filter(None, args.steps.split(",")):
        key, _, value = item.partition("=")
        if key not in steps:
            parser.error(f"--steps: {key!r}; allowed: {list(steps)}")
        steps[key] = float(value)
    if not os.path.isfile(args.start_case):
        parser.error(f"--start-case: {args.start_case!r} does not exist")
    out_dir = Path(args.output_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    vehicle = load_vehicle(args.vehicle)

    start = time.perf_counter()
    found = sensitivities_from_case(args.start_case, vehicle, names)
    print(
        f"sensitivities at W0* = {found.gross_mass:.2f} kg (KKT residual "
        f"{found.kkt_residual:.1e}), {time.perf_counter() - start:.1f} s",
        flush=True,
    )
    import openmdao.api as om

    declared = om.CaseReader(args.start_case).get_case("final").get_constraints()
    static_margin = any(n.endswith(".static_margin") for n in declared)

    settings = {"maxiter": args.max_iter, **tolerance_settings(args.tol)}
    tasks = []
    for row in found.rows:
        if row.active is False:
            continue
        ref, h = reference_value(vehicle, row.name), steps[row.name]
        for value in (ref - h, ref + h):
            tasks.append(
                (args.vehicle, row.name, value, args.start_case, static_margin, out_dir, settings)
            )
    with ProcessPoolExecutor(max_workers=max(1, args.processes)) as pool:
        results = list(pool.map(_neighbour, tasks))

    lines = [
        f"Post-optimal sensitivities at `{args.start_case}` (W0* = {found.gross_mass:.2f} kg, "
        f"relative KKT residual {found.kkt_residual:.1e}) against central differences of "
        f"re-optimized neighbours (SLSQP, {args.max_iter} iterations at tol {args.tol:g}).",
        "",
        "| parameter | value | h | W0*(p-h) (kg) | W0*(p+h) (kg) | iterations | "
        "central difference (kg/unit) | sensitivity (kg/unit) | difference |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    status = 0
    for row in found.rows:
        if row.active is False:
            lines.append(
                f"| {row.description} ({row.units}) | {row.value:g} | - | - | - | - | 0 (inactive) "
                f"| {row.dw0_dp:.4g} | - |"
            )
            continue
        got = {value: (w0, it) for p, value, w0, it, _ in results if p == row.name}
        (lo, (w_lo, it_lo)), (hi, (w_hi, it_hi)) = sorted(got.items())
        if w_lo is None or w_hi is None:
            status = 1
            lines.append(f"| {row.description} | {row.value:g} | failed neighbour |")
            continue
        fd = (w_hi - w_lo) / (hi - lo)
        diff = abs(row.dw0_dp - fd) / max(abs(fd), 1e-12)
        status |= int(diff > TOLERANCE)
        lines.append(
            f"| {row.description} ({row.units}) | {row.value:g} | {(hi - lo) / 2:g} | "
            f"{w_lo:.2f} | {w_hi:.2f} | {it_lo}, {it_hi} | {fd:.4g} | {row.dw0_dp:.4g} | "
            f"{100 * diff:.1f} % |"
        )
    lines += ["", f"Total {time.perf_counter() - start:.0f} s."]
    text = "\n".join(lines) + "\n"
    (out_dir / "sensitivity_check.md").write_text(text, encoding="utf-8")
    print(text)
    return status


if __name__ == "__main__":
    sys.exit(main())
