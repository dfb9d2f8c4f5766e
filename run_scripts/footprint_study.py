"""The reference vehicle with a departure noise footprint: write it, check it, compare optima.

Usage::

    python run_scripts/footprint_study.py write OUT.toml
    python run_scripts/footprint_study.py check OUT.toml CASE.sql
    lpc-mdo optimize --vehicle OUT.toml --output-dir footprint
    python run_scripts/footprint_study.py compare OUT.toml REFERENCE.sql footprint/full.sql

``write`` adds a ``[noise_footprint]`` table to the reference vehicle file: observers on the
ground under the departure track (-300 m behind the vertiport to 3 km ahead, where the
transition ends) and 150 m beside it, a maximum A-weighted level of 67 dBA (Uber Elevate's
goal for an eVTOL air taxi at 250 ft, the reference's hover and transition altitude: "67 dB(A)
at ground level from eVTOL PAV at 250 ft altitude", Holden and Goel, Fast-Forwarding to a
Future of On-Demand Urban Air Transportation, Uber Elevate, 2016, sec. 5). It writes only the
file it is given, and not over an existing one.

``check`` evaluates the footprint at a recorded design (e.g. the reference sequence's optimum)
and measures the footprint's settings: its hover levels against the hover condition's own
noise model (BEM sectional loads, 25 stations, 38 bands, 10 gust harmonics) at the same
observers, and every level against the footprint model with those full settings.

``compare`` tabulates the two optima: gross mass, the footprint's levels, the hover
constraint's level, rotor speeds and radii.
"""

import argparse
import math
import sys
from pathlib import Path

import numpy as np

FOOTPRINT_TABLE = """
# ---------------------------------------------------------------------------------------------
# Departure noise footprint (docs theory/acoustics 'Noise footprint'): ground observers under
# the track from 300 m behind the vertiport to the end of the transition, and 150 m beside it.
# Limit: 67 dBA, Uber Elevate's goal for an eVTOL at 250 ft (Holden and Goel 2016, sec. 5).
[noise_footprint]
track_positions = [-300.0, 0.0, 300.0, 1000.0, 2000.0, 3000.0]
lateral_offsets = [0.0, 150.0]
hover_time = 30.0
max_lamax = 67.0
"""


def write(target):
    """Write ``target``: the reference vehicle file with the footprint table."""
    from importlib import resources

    target = Path(target)
    if target.exists():
        print(f"footprint_study: {target} exists; give a new file name", file=sys.stderr)
        return 1
    reference = resources.files("lpc_mdo").joinpath("data", "lpc_reference.toml")
    text = reference.read_text(encoding="utf-8")
    target.write_text(text.rstrip("\n") + "\n" + FOOTPRINT_TABLE, encoding="utf-8")
    print(f"wrote {target}")
    return 0


def _evaluate(vehicle, case_file, work_dir):
    """Return the analysis problem of ``vehicle`` at the design of ``case_file``, evaluated."""
    from lpc_mdo.problems import build_analysis_problem
    from lpc_mdo.warm_start import load_design_variables, start_point

    prob = build_analysis_problem(vehicle, work_dir=work_dir)
    case, _ = start_point(case_file, vehicle)
    load_design_variables(prob, case, vehicle)
    prob.run_model()
    return prob


def _hover_observers(vehicle):
    """Return the footprint's observers seen from the hover as [[noise_observer]] tables."""
    from lpc_mdo.vehicle.footprint_path import footprint_geometry

    _, geometry = footprint_geometry(vehicle)
    tables = []
    for dx, dy, dz in geometry[0].offset:  # the hover: one point per observer
        distance = math.sqrt(dx * dx + dy * dy + dz * dz)
        elevation = math.degrees(math.asin(dz / distance))
        azimuth = math.degrees(math.atan2(dy, dx)) if abs(dx) + abs(dy) > 0 else 0.0
        tables.append({"distance": distance, "elevation_deg": elevation, "azimuth_deg": azimuth})
    return tables


def check(vehicle_file, case_file, work_dir="."):
    """Print the footprint at a design and the measured effect of its settings."""
    import lpc_mdo.groups.footprint as footprint
    from lpc_mdo.vehicle import read_vehicle_file, vehicle_from_dict

    data = read_vehicle_file(vehicle_file)
    vehicle = vehicle_from_dict(data)
    prob = _evaluate(vehicle, case_file, work_dir)
    no = len(prob.get_val("footprint_sel"))
    print(f"gross mass {prob.get_val('gross_mass')[0]:.2f} kg")
    print("observer (x, y) m:      " + "  ".join(f"{o}" for o in _observer_labels(vehicle)))
    print("SEL   dBA: " + " ".join(f"{v:7.2f}" for v in prob.get_val("footprint_sel")))
    print("LAmax dBA: " + " ".join(f"{v:7.2f}" for v in prob.get_val("footprint_lamax")))

    # The hover's footprint levels against the hover condition's own noise model there.
    hover = dict(data)
    hover["noise_observer"] = (
        [data["noise_observer"]]
        if isinstance(data["noise_observer"], dict)
        else list(data["noise_observer"])
    )
    first = len(hover["noise_observer"])
    hover["noise_observer"] += _hover_observers(vehicle)
    full = _evaluate(vehicle_from_dict(hover), case_file, work_dir)
    own = np.array([full.get_val(f"hover.noise_{first + 1 + i}.total_spl_a")[0] for i in range(no)])
    ours = prob.get_val("hover.footprint_spl_a")  # one point per observer, in order
    print("hover, footprint model:          " + " ".join(f"{v:7.2f}" for v in ours))
    print("hover, the hover constraint's:   " + " ".join(f"{v:7.2f}" for v in own))
    print(f"  largest difference {np.max(np.abs(ours - own)):.2f} dB")

    # Every level against the footprint model with the hover constraint's settings.
    saved = (footprint.FOOTPRINT_BANDS, footprint.FOOTPRINT_GUST_HARMONICS)
    saved_step = footprint.FOOTPRINT_STATION_STEP
    footprint.FOOTPRINT_BANDS, footprint.FOOTPRINT_GUST_HARMONICS = (38, 12.5), 10
    footprint.FOOTPRINT_STATION_STEP = 1
    try:
        fine = _evaluate(vehicle, case_file, work_dir)
    finally:
        footprint.FOOTPRINT_BANDS, footprint.FOOTPRINT_GUST_HARMONICS = saved
        footprint.FOOTPRINT_STATION_STEP = saved_step
    for name in ("footprint_sel", "footprint_lamax"):
        diff = prob.get_val(name) - fine.get_val(name)
        print(f"{name} with the full settings: largest difference {np.max(np.abs(diff)):.3f} dB")
    levels = list(prob.model.footprint_conditions)
    worst = 0.0
    for name in levels:
        a = prob.get_val(f"{name}.footprint_spl_a")
        b = fine.get_val(f"{name}.footprint_spl_a")
        loud = a > prob.get_val("footprint_lamax").max() - 20.0  # the levels that count
        if np.any(loud):
            worst = max(worst, float(np.max(np.abs(a - b)[loud])))
    print(f"point levels within 20 dB of the loudest: largest difference {worst:.3f} dB")

    # The quadrature: one Gauss point per 45 deg of a leg (at most 4) against one per 10 deg
    # (at most 16).
    import lpc_mdo.vehicle.footprint_path as footprint_path

    saved_angle = footprint_path.QUADRATURE_ANGLE
    footprint_path.QUADRATURE_ANGLE = math.radians(10.0)
    dense = dict(data, noise_footprint={**data["noise_footprint"], "quadrature_points": 16})
    try:
        fine = _evaluate(vehicle_from_dict(dense), case_file, work_dir)
    finally:
        footprint_path.QUADRATURE_ANGLE = saved_angle
    for name in ("footprint_sel", "footprint_lamax"):
        diff = prob.get_val(name) - fine.get_val(name)
        print(f"{name}, a Gauss point per 10 deg: largest difference {np.max(np.abs(diff)):.3f} dB")
    points = sum(prob.get_val(f"{n}.footprint_spl_a").size for n in levels if n != "hover")
    print(
        f"transition points heard: {points} (with a point per 10 deg: "
        f"{sum(fine.get_val(f'{n}.footprint_spl_a').size for n in levels if n != 'hover')})"
    )
    return 0


def _observer_labels(vehicle):
    from lpc_mdo.vehicle.footprint_path import footprint_observers

    return [f"({x:.0f},{y:.0f})" for x, y, _ in footprint_observers(vehicle.noise_footprint)]


def compare(vehicle_file, reference_case, footprint_case, work_dir="."):
    """Print the two optima side by side, both evaluated with the footprint."""
    from lpc_mdo.vehicle import load_vehicle

    vehicle = load_vehicle(vehicle_file)
    rows = []
    for label, case in (
        ("hover constraint only", reference_case),
        ("with footprint", footprint_case),
    ):
        prob = _evaluate(vehicle, case, work_dir)
        rows.append(
            (
                label,
                prob.get_val("gross_mass")[0],
                prob.get_val("battery_mass")[0],
                prob.get_val("hover.total_spl_a")[0],
                prob.get_val("footprint_lamax"),
                prob.get_val("footprint_sel"),
                prob.get_val("rotor_radius"),
                prob.get_val("hover_lift_rpm").ravel(),
                prob.get_val("transition_pusher_rpm").ravel(),
                prob.get_val("transition_lift_rpm").reshape(
                    -1, prob.get_val("hover_lift_rpm").size
                ),
            )
        )
    print("observers (x, y) m: " + " ".join(_observer_labels(vehicle)))
    for row in rows:
        label, w0, battery, hover, lamax, sel, radius, hover_rpm, pusher_rpm, transition = row
        print(f"\n{label}:")
        print(f"  gross mass {w0:.2f} kg, battery {battery:.2f} kg")
        print(f"  hover noise at the paper's observer {hover:.2f} dBA")
        print("  LAmax dBA " + " ".join(f"{v:.1f}" for v in lamax))
        print("  SEL dBA   " + " ".join(f"{v:.1f}" for v in sel))
        print("  rotor radii m (lift pairs, pusher) " + " ".join(f"{v:.3f}" for v in radius))
        print("  hover lift rpm " + " ".join(f"{v:.0f}" for v in hover_rpm))
        print("  transition pusher rpm " + " ".join(f"{v:.0f}" for v in pusher_rpm))
        print("  transition lift rpm (points x pairs)")
        for line in transition:
            print("    " + " ".join(f"{v:.0f}" for v in line))
    return 0


def main(argv=None):
    """Run one of the study's commands; return the exit status."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("write", help="write the reference with the footprint table")
    p.add_argument("target")
    p = sub.add_parser("check", help="the footprint at a design and its settings' effect")
    p.add_argument("vehicle")
    p.add_argument("case")
    p = sub.add_parser("compare", help="two optima evaluated with the footprint")
    p.add_argument("vehicle")
    p.add_argument("reference_case")
    p.add_argument("footprint_case")
    args = parser.parse_args(argv)
    if args.command == "write":
        return write(args.target)
    if args.command == "check":
        return check(args.vehicle, args.case)
    return compare(args.vehicle, args.reference_case, args.footprint_case)


if __name__ == "__main__":
    sys.exit(main())
