"""Wind each motor design of a vehicle's initial design for its bus (initial motor_rated_current).

    python run_scripts/wind_motors_for_bus.py [--vehicle FILE] [--write]

A motor's winding (its rated current I_w, which sets the turns per phase W = pi D_i A_bar/(2 m
I_w)) scales its voltage by 1/I_w and its current by I_w and leaves its torque and losses
unchanged (docs theory/motor 'Winding for the bus'). For the initial design this finds, per motor
design (lift-rotor pair or pusher), the smallest I_w, rounded up to a whole ampere, at which in
every condition of the trimmed initial design

- the KS voltage margin of each of its motors (the constraint ``voltage_margin``) is at least
  ``constraints.min_voltage_margin``, and
- each operating point's voltage-limited torque exceeds the electromagnetic torque by
  ``constraints.min_torque_margin`` (the voltage part of the torque margin),

by bisection on the design variable's bounds (all designs at once: each design's margins depend
on its own winding only; the winding changes no force, so the trim stays). With ``--write`` it
replaces the ``initial = ...`` line of ``[design_variables.motor_rated_current]``. The winding
changes the inverter and cable masses, so close the initial design afterwards
(``run_scripts/close_initial_design.py --write``) and run this again until it is unchanged.
"""

import argparse
import math
import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OPENMDAO_REPORTS", "0")

import numpy as np  # noqa: E402

from lpc_mdo.analysis import analyze_vehicle  # noqa: E402
from lpc_mdo.motor_sizing import motor_margins  # noqa: E402
from lpc_mdo.vehicle import load_vehicle  # noqa: E402
from lpc_mdo.vehicle.file_edit import replace_initial, write_values  # noqa: E402

REFERENCE_FILE = os.path.join(
    os.path.dirname(__file__), os.pardir, "lpc_mdo", "data", "lpc_reference.toml"
)
NAME = "motor_rated_current"


def group_margins(prob, vehicle):
    """Per motor design: the least KS voltage margin and the least voltage-torque margin."""
    _, voltage, torque = motor_margins(prob, vehicle)
    return voltage, torque


def wind(vehicle, iterations=40):
    """Return the initial windings (A, one per motor design) and the analysis problem."""
    analysis = analyze_vehicle(vehicle, trim=True)
    prob = analysis.prob
    if analysis.failed:
        raise RuntimeError(f"the initial design does not trim: {analysis.failed}")
    dv = vehicle.design_variables[NAME]
    limits = vehicle.constraints
    lower = np.array(dv.lower_array, dtype=float)
    upper = np.array(dv.upper_array, dtype=float)

    def feasible(current):
        prob.set_val(NAME, current, units="A")
        prob.run_model()
        voltage, torque = group_margins(prob, vehicle)
        return (voltage >= limits.min_voltage_margin) & (torque >= limits.min_torque_margin)

    if not np.all(feasible(upper)):
        raise RuntimeError(f"no winding within the bounds of {NAME} fits the bus")
    for _ in range(iterations):  # bisection in log I_w, all designs at once
        middle = np.sqrt(lower * upper)
        ok = feasible(middle)
        upper = np.where(ok, middle, upper)
        lower = np.where(ok, lower, middle)
    current = np.array([math.ceil(x) for x in upper], dtype=float)
    assert np.all(feasible(current))
    return current, prob


def write_winding(path, current):
    """Replace the ``initial`` line of the winding's design-variable table of a TOML file."""
    write_values(
        path,
        lambda text: replace_initial(
            text, NAME, current, "run_scripts/wind_motors_for_bus.py", fmt="{:.1f}"
        ),
    )


def main():
    """Wind the motors, print the windings and optionally write them into the vehicle file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--vehicle", default=None, help="vehicle TOML (default: the reference)")
    parser.add_argument("--write", action="store_true", help="write the result into the file")
    args = parser.parse_args()
    vehicle = load_vehicle(args.vehicle)
    current, prob = wind(vehicle)
    voltage, torque = group_margins(prob, vehicle)
    print("motor design   rated current [A]   KS voltage margin   voltage-torque margin")
    for g, (i, v, t) in enumerate(zip(current, voltage, torque, strict=True)):
        print(f"{g:>12d}   {i:>17.1f}   {v:>17.3f}   {t:>21.3f}")
    if args.write:
        path = args.vehicle or REFERENCE_FILE
        write_winding(path, current)
        print(f"written to {path}")


if __name__ == "__main__":
    main()
