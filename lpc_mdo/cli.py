"""Command-line interface: ``lpc-mdo analyze``."""

import argparse
import sys
from pathlib import Path

import numpy as np


def _analyze(args):
    import openmdao.api as om

    from lpc_mdo.problems import build_analysis_problem

    out = Path(args.output_dir)
    out.mkdir(parents=True, exist_ok=True)
    prob = build_analysis_problem(args.vehicle, recorder_path=out / "cases.sql")
    prob.run_model()
    prob.record("final")
    vehicle = prob.vehicle

    print(f"lpc-mdo analysis of '{vehicle.name}'")
    wing, tail = vehicle.wing, vehicle.horizontal_tail
    print(f"  wing: S = {wing.area:.2f} m^2, AR = {wing.aspect_ratio:.2f}, "
          f"span = {wing.span:.2f} m; h-tail: S = {tail.area:.2f} m^2, "
          f"AR = {tail.aspect_ratio:.2f}")
    print(f"  fuselage length = {vehicle.fuselage.length:.3f} m; "
          f"{len(vehicle.lift_rotors)} lift rotors R = "
          f"{', '.join(f'{r.radius:.3f}' for r in vehicle.lift_rotors)} m; "
          f"pusher R = {vehicle.pusher.radius:.3f} m")
    print(f"  design variables: {vehicle.design_variable_count()} "
          f"in {len(vehicle.design_variables)} groups")
    print()
    names = [c.name for c in vehicle.conditions]
    cols = {
        "altitude [m]": prob.get_val("conditions.altitude", units="m"),
        "speed [m/s]": prob.get_val("conditions.speed", units="m/s"),
        "Mach": prob.get_val("conditions.mach"),
        "alpha [deg]": prob.get_val("conditions.angle_of_attack", units="deg"),
        "rho [kg/m^3]": prob.get_val("conditions.density", units="kg/m**3"),
        "q [Pa]": prob.get_val("conditions.dynamic_pressure", units="Pa"),
        "Re/m [1e6/m]": prob.get_val("conditions.reynolds_per_length", units="1/m") / 1e6,
    }
    header = f"  {'condition':<14}" + "".join(f"{k:>14}" for k in cols)
    print(header)
    for i, name in enumerate(names):
        print(f"  {name:<14}" + "".join(f"{np.asarray(v)[i]:>14.4g}" for v in cols.values()))
    print(f"\ncase file: {out / 'cases.sql'}")

    if args.n2:
        om.n2(prob, outfile=str(args.n2), show_browser=False)
        print(f"N2 diagram: {args.n2}")
    return 0


def main(argv=None):
    """Entry point of the ``lpc-mdo`` command."""
    parser = argparse.ArgumentParser(prog="lpc-mdo", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    analyze = sub.add_parser("analyze", help="analyze a vehicle's design conditions")
    analyze.add_argument("--vehicle", default=None,
                         help="vehicle TOML file (default: the reference vehicle)")
    analyze.add_argument("--output-dir", default="analysis_out",
                         help="folder for the case file (default: analysis_out)")
    analyze.add_argument("--n2", default=None, metavar="HTML",
                         help="also write the N2 diagram to this file")
    analyze.set_defaults(func=_analyze)

    args = parser.parse_args(argv)
    from lpc_mdo.vehicle import VehicleSpecError

    try:
        return args.func(args)
    except VehicleSpecError as err:
        print(f"lpc-mdo: error in vehicle file: {err}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
