"""Close the initial design: wing gauges at +3g/-1g, then battery, motors and W_dg on the mission.

    python run_scripts/close_initial_design.py [--vehicle FILE] [--gauges-only] [--write]

The initial design of a vehicle file is closed when (1) its wing box is sized for the loads of
its own gross mass, (2) the design gross mass W_dg of the regressions that scale with it
(landing gear, wing secondary structure, systems) is that gross mass, and (3) its battery and
motors are sized to its mission (``lpc-mdo size``: the mission and reserve end on the
state-of-charge floor, each motor at its torque and voltage margins). They depend on each other
(the loads scale with W0, W0 with the box, the battery and the motors), so this alternates:

- size the box: the warm start's structural subproblem (``build_problem('subproblem_3')``,
  paper Table 2: minimum gross mass over the 32 skin and spar thicknesses subject to skin
  buckling, von Mises stress and trim at +3g and -1g) on the vehicle's initial design, and
  close W_dg with :func:`lpc_mdo.groups.vehicle.closed_design_gross_mass`, until W_dg moves by
  less than 0.1 kg;
- size the battery, the motors and W_dg to the mission (:func:`lpc_mdo.sizing.size_vehicle`);

until the mission sizing moves W_dg by less than 0.5 kg from the W_dg the gauges were sized for.
``--gauges-only`` does the first step alone (battery and motors as the file gives them). It
prints the thicknesses (root to tip), the box mass and W_dg; with ``--write`` it replaces the
``initial = ...`` lines of the four ``[design_variables.*_thickness]`` tables, of
``motor_length`` and ``motor_rated_current``, and the ``design_gross_mass`` and battery ``mass``
lines of the vehicle file. Re-run it whenever the wing planform, the wing-box model, the
mission, the loads or a mass item change.
"""

import argparse
import os
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OPENMDAO_REPORTS", "0")

import numpy as np  # noqa: E402

from lpc_mdo.groups.vehicle import closed_design_gross_mass  # noqa: E402
from lpc_mdo.motor_sizing import CURRENT, LENGTH  # noqa: E402
from lpc_mdo.problems import build_problem  # noqa: E402
from lpc_mdo.sizing import size_vehicle, with_sized_values  # noqa: E402
from lpc_mdo.vehicle import read_vehicle_file, vehicle_from_dict  # noqa: E402
from lpc_mdo.vehicle.file_edit import replace_initial, replace_value, write_values  # noqa: E402

THICKNESSES = (
    "front_spar_thickness",
    "rear_spar_thickness",
    "top_skin_thickness",
    "bottom_skin_thickness",
)
REFERENCE_FILE = os.path.join(
    os.path.dirname(__file__), os.pardir, "lpc_mdo", "data", "lpc_reference.toml"
)


def size_gauges(vehicle=None):
    """Return the sized thicknesses (m, dict of 8-vectors), the box mass (kg) and the result."""
    # Sized tightly (SLSQP to 1e-8, no acceptable-point stop): the warm start's own tolerance
    # (relative to the gross mass) leaves the light outer bays a few percent under their limits.
    prob = build_problem(
        "subproblem_3",
        vehicle=vehicle,
        optimizer="SLSQP",
        driver_settings={"tol": 1e-8, "acceptable_iter": 0, "maxiter": 500},
    )
    start = time.perf_counter()
    result = prob.run_driver()
    elapsed = time.perf_counter() - start
    gauges = {name: np.asarray(prob.get_val(name, units="m")).ravel() for name in THICKNESSES}
    box = float(prob.get_val("wing_mass", units="kg")[0])
    return gauges, box, result, elapsed


def close(data, max_rounds=6, tolerance=0.1):
    """Alternate gauge sizing and the W_dg closure on a vehicle dict until W_dg settles.

    Returns the gauges (m), the box mass (kg) and W_dg (kg) of the last round; ``data`` is
    updated in place.
    """
    for round_ in range(1, max_rounds + 1):
        gauges, box, result, elapsed = size_gauges(vehicle_from_dict(data))
        print(
            f"round {round_}: gauges sized (success {result.success}, {result.iter_count} "
            f"iterations, {elapsed:.1f} s), box {box:.2f} kg"
        )
        for name, values in gauges.items():
            data["design_variables"][name]["initial"] = [float(v) for v in values]
        previous = data["masses"]["design_gross_mass"]
        w_dg = closed_design_gross_mass(vehicle_from_dict(data))
        data["masses"]["design_gross_mass"] = w_dg
        print(f"round {round_}: W_dg {previous:.2f} -> {w_dg:.2f} kg")
        if abs(w_dg - previous) < tolerance:
            return gauges, box, w_dg
    raise RuntimeError(f"W_dg did not settle within {max_rounds} rounds (last {w_dg:.2f} kg)")


def close_on_mission(data, processes=2, max_rounds=6, tolerance=0.5):
    """Alternate :func:`close` and the mission sizing until W_dg settles (module docstring).

    Returns the gauges (m), the box mass (kg) and the sizing result; ``data`` is updated.
    """
    for round_ in range(1, max_rounds + 1):
        gauges, box, w_dg = close(data)
        result = size_vehicle(vehicle_from_dict(data), processes=processes, log=print)
        data["battery"]["mass"] = result.battery_mass
        data["masses"]["design_gross_mass"] = result.design_gross_mass
        data["design_variables"][LENGTH]["initial"] = [float(v) for v in result.motors.length]
        data["design_variables"][CURRENT]["initial"] = [
            float(v) for v in result.motors.rated_current
        ]
        print(
            f"mission round {round_}: battery {result.battery_mass:.2f} kg, W_dg {w_dg:.2f} -> "
            f"{result.design_gross_mass:.2f} kg"
        )
        if abs(result.design_gross_mass - w_dg) < tolerance:
            return gauges, box, result
    raise RuntimeError(f"the mission sizing did not settle within {max_rounds} rounds")


def write_closure(path, gauges, design_gross_mass, sizing=None):
    """Replace the closed values of a TOML file: thicknesses, W_dg, and the sizing's if given."""
    note = "run_scripts/close_initial_design.py"

    def edit(text):
        for name, values in gauges.items():
            text = replace_initial(text, name, values, f"sized at +3g/-1g ({note})")
        if sizing is not None:  # its W_dg is the closure's
            return with_sized_values(text, sizing, f"sized to the mission ({note})")
        return replace_value(text, "design_gross_mass", f"{design_gross_mass:.2f}")

    write_values(path, edit)


def main():
    """Close the initial design, print it and optionally write it into the vehicle file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--vehicle", default=None, help="vehicle TOML (default: the reference)")
    parser.add_argument(
        "--gauges-only", action="store_true", help="size the gauges and W_dg only, not the mission"
    )
    parser.add_argument("--processes", type=int, default=2, help="processes of the trims")
    parser.add_argument("--write", action="store_true", help="write the result into the file")
    args = parser.parse_args()
    data = read_vehicle_file(args.vehicle)
    sizing = None
    if args.gauges_only:
        gauges, box, w_dg = close(data)
    else:
        gauges, box, sizing = close_on_mission(data, processes=args.processes)
        w_dg = sizing.design_gross_mass
        print(sizing.summary())
    print(f"wing-box mass (both halves): {box:.2f} kg; design gross mass {w_dg:.2f} kg")
    for name, values in gauges.items():
        print(f"{name:<24}" + " ".join(f"{1e3 * v:7.3f}" for v in values) + "  mm")
    if args.write:
        path = args.vehicle or REFERENCE_FILE
        write_closure(path, gauges, w_dg, sizing)
        print(f"written to {path}")


if __name__ == "__main__":
    main()
