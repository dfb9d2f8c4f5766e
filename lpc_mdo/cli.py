"""Command-line interface: ``lpc-mdo analyze | optimize | sweep | report``."""

import argparse
import os
import sys
from pathlib import Path

import numpy as np


def _analyze(args):
    import openmdao.api as om

    from lpc_mdo.api.weights import format_mass_breakdown, mass_breakdown
    from lpc_mdo.post.tables import constraint_table
    from lpc_mdo.problems import build_analysis_problem

    out = Path(args.output_dir)
    out.mkdir(parents=True, exist_ok=True)
    case_file = out / "cases.sql"
    prob = build_analysis_problem(
        args.vehicle, recorder_path=case_file, static_margin=not args.no_static_margin
    )
    prob.run_model()
    prob.record("final")
    vehicle = prob.vehicle

    dvs = prob.model.get_design_vars()
    cons = prob.model.get_constraints()
    print(f"lpc-mdo analysis of '{vehicle.name}' (initial design)")
    print(
        f"  {len(prob.model.condition_names)} design conditions, "
        f"{sum(m['size'] for m in dvs.values())} design variables, "
        f"{sum(m['size'] for m in cons.values() if not m['linear'])} constraints, "
        f"{sum(m['size'] for m in cons.values() if m['linear'])} linear rotor-speed bounds"
    )
    print(
        f"  wing: S = {prob.get_val('wing_area')[0]:.2f} m^2, "
        f"AR = {prob.get_val('wing_aspect_ratio')[0]:.2f}, "
        f"span = {prob.get_val('wing_span')[0]:.2f} m; fuselage "
        f"{prob.get_val('fuselage_length')[0]:.3f} m; rotor radii "
        f"{np.array2string(prob.get_val('rotor_radius'), precision=3)} m"
    )
    print()
    print(format_mass_breakdown(mass_breakdown(prob)))
    print()
    print(
        f"  {'condition':<14}{'power [kW]':>12}{'u_dot':>9}{'w_dot':>9}{'q_dot':>9}"
        "   (accelerations in m/s^2, rad/s^2; trim drives them to the targets)"
    )
    from lpc_mdo.groups.condition_kinds import condition_class

    for condition in prob.model.conditions:
        name = condition.name
        lin = prob.get_val(f"{name}.linear_acceleration")[0]
        ang = prob.get_val(f"{name}.angular_acceleration")[0]
        output = condition_class(condition.kind).power_output
        power = (
            f"{prob.get_val(f'{name}.{output}', units='kW')[0]:>12.1f}"
            if output
            else f"{'(none)':>12}"
        )
        print(f"  {name:<14}{power}{lin[0]:>9.3f}{lin[2]:>9.3f}{ang[1]:>9.3f}")
    summary = [f"final state of charge {prob.get_val('state_of_charge')[0]:.3f}"]
    for condition in prob.model.conditions:
        for con in condition_class(condition.kind).constraints(vehicle, condition, None):
            if con.kind == "noise":
                value = prob.get_val(f"{condition.name}.{con.output}")[0]
                summary.append(f"{condition.name} noise {value:.1f} dBA")
    cruise = vehicle.mission.cruise_condition
    if cruise in prob.model.condition_names:
        summary.append(f"{cruise} static margin {prob.get_val(f'{cruise}.static_margin')[0]:.3f}")
    print("\n  " + ", ".join(summary))
    prob.cleanup()

    table = constraint_table(str(case_file), case="final")
    table.write(str(out), "constraints")
    print(f"\nconstraint table (paper Table 7 layout): {out / 'constraints.md'}")
    print(f"case file: {case_file}")
    if args.n2:
        om.n2(str(case_file), outfile=str(args.n2), show_browser=False)
        print(f"N2 diagram: {args.n2}")
    return 0


def _optimize(args):
    from lpc_mdo.warm_start import FULL_PROBLEMS, run_sequence, solve_baseline, solve_stage

    out = Path(args.output_dir)
    out.mkdir(parents=True, exist_ok=True)
    settings = {"max_iter": args.max_iter}
    if args.quiet:
        settings["print_level"] = 0
    common = dict(
        vehicle=args.vehicle,
        static_margin=not args.no_static_margin,
        driver_settings=settings,
        trim_first=not args.no_trim,
        progress=not args.quiet,
    )
    # Each stage prints a progress line per iteration (and IPOPT its own table unless
    # --quiet); Ctrl-C stops cleanly: the case file keeps every recorded iteration and a
    # 'final' case of the interrupted point.
    try:
        if args.problem == "sequence":
            results = run_sequence(
                str(out),
                optimizer=args.optimizer or "IPOPT",
                full_optimizer=args.optimizer,
                start_case=args.start_case,
                **common,
            )
            return 0 if all(r.success for r in results) else 1
        case_file = out / f"{args.problem}.sql"
        if args.problem == "baseline":  # continuation in alpha (paper eq. 8)
            stage = solve_baseline(
                str(case_file), start_case=args.start_case, optimizer=args.optimizer, **common
            )
        else:
            stage = solve_stage(
                args.problem,
                str(case_file),
                start_case=args.start_case,
                optimizer=args.optimizer,
                rescale=(args.problem in FULL_PROBLEMS and args.start_case is not None),
                **common,
            )
    except KeyboardInterrupt:
        print("lpc-mdo: interrupted; the case files hold the iterations so far", file=sys.stderr)
        return 130
    print(f"case file: {case_file}")
    return 0 if stage.success else 1


def _sweep(args):
    from lpc_mdo.sweeps import SWEEP_PARAMETERS, run_sweep

    parameters = list(SWEEP_PARAMETERS) if args.parameter == "all" else [args.parameter]
    values = {parameters[0]: args.values} if args.values else None
    if args.values and len(parameters) > 1:
        print("lpc-mdo: --values needs a single --parameter", file=sys.stderr)
        return 2
    margins = {"on": (True,), "off": (False,), "both": (True, False)}[args.static_margin]
    points = run_sweep(
        args.output_dir,
        args.start_case,
        parameters=parameters,
        values=values,
        static_margins=margins,
        vehicle=args.vehicle,
        processes=args.processes,
        mpi=args.mpi,
        driver_settings={"max_iter": args.max_iter, "print_level": 0},
        optimizer=args.optimizer,
        problem=args.problem,
    )
    if points is None:  # an MPI rank other than 0
        return 0
    for p in points:
        print(
            f"{p.parameter}={p.value:g} static margin {'on' if p.static_margin else 'off'}: "
            f"{'converged' if p.success else 'FAILED'}{' (retried)' if p.retried else ''}, "
            f"gross mass {p.gross_mass:.2f} kg, {p.iterations} iterations, {p.seconds:.1f} s"
        )
    print(f"summary: {Path(args.output_dir) / 'sweep_summary.csv'}")
    return 0 if all(p.success for p in points) else 1


def _report(args):
    from lpc_mdo.post.report import ReportSpec, write_report
    from lpc_mdo.vehicle import load_vehicle

    spec = ReportSpec(vehicle=load_vehicle(args.vehicle))
    index = write_report(args.cases, args.output_dir, spec)
    print(f"report: {index}")
    return 0


def main(argv=None):
    """Entry point of the ``lpc-mdo`` command."""
    os.environ.setdefault("OPENMDAO_REPORTS", "0")
    parser = argparse.ArgumentParser(prog="lpc-mdo", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    analyze = sub.add_parser("analyze", help="analyze a vehicle's design conditions")
    analyze.add_argument(
        "--vehicle", default=None, help="vehicle TOML file (default: the reference vehicle)"
    )
    analyze.add_argument(
        "--output-dir",
        default="analysis_out",
        help="folder for the case file and tables (default: analysis_out)",
    )
    analyze.add_argument(
        "--n2", default=None, metavar="HTML", help="also write the N2 diagram to this file"
    )
    analyze.add_argument(
        "--no-static-margin", action="store_true", help="leave the static-margin constraint out"
    )
    analyze.set_defaults(func=_analyze)

    from lpc_mdo.problems import PROBLEM_NAMES

    optimize = sub.add_parser(
        "optimize", help="solve a subproblem, the full problem, or the warm-start sequence"
    )
    optimize.add_argument(
        "--problem",
        default="sequence",
        choices=(*PROBLEM_NAMES, "sequence"),
        help="which problem (default: the whole warm-start sequence)",
    )
    optimize.add_argument(
        "--optimizer",
        default=None,
        choices=("IPOPT", "SNOPT", "SLSQP"),
        help="default: IPOPT for the presizing and subproblems, SQP (SNOPT "
        "if pyoptsparse has it, else SLSQP) for full and baseline",
    )
    optimize.add_argument("--max-iter", type=int, default=200, help="iteration limit")
    optimize.add_argument("--vehicle", default=None, help="vehicle TOML file")
    optimize.add_argument(
        "--no-static-margin", action="store_true", help="leave the static-margin constraint out"
    )
    optimize.add_argument(
        "--start-case", default=None, help="case file whose final case gives the starting design"
    )
    optimize.add_argument(
        "--output-dir", default="optimize_out", help="folder for case files and run statistics"
    )
    optimize.add_argument(
        "--no-trim", action="store_true", help="do not trim the conditions before optimizing"
    )
    optimize.add_argument(
        "--quiet", action="store_true", help="only the progress lines, not IPOPT's iteration table"
    )
    optimize.set_defaults(func=_optimize)

    sweep = sub.add_parser("sweep", help="parameter sweeps of the full problem (paper Sec. V.C)")
    sweep.add_argument(
        "--start-case",
        required=True,
        help="case file whose final case starts every chain, e.g. the sequence's full.sql",
    )
    sweep.add_argument("--parameter", default="all", choices=("energy_density", "final_soc", "all"))
    sweep.add_argument(
        "--values",
        type=float,
        nargs="+",
        default=None,
        help="values of the one --parameter (default: the paper's five)",
    )
    sweep.add_argument("--static-margin", default="both", choices=("on", "off", "both"))
    sweep.add_argument("--processes", type=int, default=2, help="local worker processes")
    sweep.add_argument(
        "--mpi",
        action="store_true",
        help="distribute over MPI ranks (run under mpirun; needs mpi4py)",
    )
    sweep.add_argument(
        "--problem",
        default="full",
        choices=PROBLEM_NAMES,
        help="problem each point solves (default: full)",
    )
    sweep.add_argument("--max-iter", type=int, default=200, help="iteration limit per point")
    sweep.add_argument(
        "--optimizer",
        default=None,
        choices=("IPOPT", "SNOPT", "SLSQP"),
        help="default: as optimize (SNOPT if pyoptsparse has it, else SLSQP)",
    )
    sweep.add_argument("--vehicle", default=None, help="vehicle TOML file")
    sweep.add_argument("--output-dir", default="sweep_out", help="folder for case files")
    sweep.set_defaults(func=_sweep)

    report = sub.add_parser("report", help="tables and figures from case files")
    report.add_argument("cases", help="a case file or a folder of case files")
    report.add_argument("--output-dir", default="report", help="report folder")
    report.add_argument(
        "--vehicle",
        default=None,
        help="vehicle file the runs were made with (its conditions and trim "
        "rows; default: the reference vehicle)",
    )
    report.set_defaults(func=_report)

    args = parser.parse_args(argv)
    from lpc_mdo.vehicle import VehicleSpecError

    start_case = getattr(args, "start_case", None)
    if start_case is not None and not os.path.isfile(start_case):
        print(
            f"lpc-mdo: --start-case {start_case!r} is not a file (a case file written by "
            "lpc-mdo optimize, e.g. optimize_out/full.sql)",
            file=sys.stderr,
        )
        return 2
    try:
        return args.func(args)
    except VehicleSpecError as err:
        print(f"lpc-mdo: error in vehicle file: {err}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
