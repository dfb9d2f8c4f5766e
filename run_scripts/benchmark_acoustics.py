"""Benchmark: hover noise of the 8 LPC lift rotors (evaluate + linearize).

RotorNoiseGroup with 8 rotors, 25 radial stations, 1 azimuthal station (hover BEM), tonal noise
with 3 blade-passing harmonics (Lowson-Ollerhead + Sears gusts with 10 load harmonics, and
Barry-Magliozzi thickness) and the 38-band Gill-Lee broadband spectrum, A-weighted and summed to
the total A-weighted level at the paper's observer (100 m, 45 deg below the rotor plane).

Times ``run_model`` (evaluate) and ``compute_totals`` of the total level with respect to the rotor
design inputs (linearize + adjoint solve); reports the median of ``--repeats`` runs after one
warm-up run. Usage:

    python run_scripts/benchmark_acoustics.py [--repeats 20]
"""

import argparse
import os
import time

import numpy as np
import openmdao.api as om

from lpc_mdo.groups.acoustics import HOVER_NOISE_LIMIT_DBA, RotorNoiseGroup

FT = 0.3048
# Approximate LPC lift-rotor hubs (docs theory/geometry 'Reference vehicle', CADDEE geometry in ft,
# x aft and z up) converted to the body frame (x forward, z down, origin at the nose), in the rotor
# order [front_outer, rear_outer, front_inner, rear_inner, front_inner,
# rear_inner, front_outer, rear_outer].
_HUBS_FT = np.array(
    [
        [5.070, -18.750, 7.355],
        [19.200, -18.750, 9.635],
        [4.630, -8.217, 7.659],
        [18.760, -8.537, 9.919],
        [4.630, 8.217, 7.659],
        [18.760, 8.537, 9.919],
        [5.070, 18.750, 7.355],
        [19.200, 18.750, 9.635],
    ]
)
NOSE_FT = np.array([2.464, 0.0, 5.113])


def hub_positions():
    """Hub positions in the lpc_mdo body frame, m."""
    rel = (_HUBS_FT - NOSE_FT) * FT
    return np.column_stack([-rel[:, 0], rel[:, 1], -rel[:, 2]])


def build_problem(num_rotors=None, num_radial=25):
    """Problem with the LPC-like hover case (R = 1.524 m, 1200 rpm, chord 0.3 -> 0.1 m).

    ``num_rotors`` defaults to the number of hubs of the layout table (the 8 lift rotors).
    """
    num_rotors = len(_HUBS_FT) if num_rotors is None else num_rotors
    prob = om.Problem(
        RotorNoiseGroup(
            num_rotors=num_rotors,
            num_radial=num_radial,
            num_azimuth=1,
            num_harmonics=3,
            num_bands=38,
        ),
        reports=False,
    )
    prob.setup(mode="rev")
    nr, nrad = num_rotors, num_radial
    rbar = 0.2 + 0.8 * (np.arange(nrad) + 0.5) / nrad
    radius, rpm, thrust, torque = 1.524, 1200.0, 4863.5, 803.4
    # Sectional loads of one blade (N/m) with the totals of the reference BEM case (docs
    # theory/dynamics 'Gravity'):
    # thrust per span ~ r, drag per span ~ r, integrated with the element-midpoint rule.
    w = np.full(nrad, 0.8 / nrad)
    t_span = thrust * rbar / (2 * radius * np.sum(w * rbar))
    d_span = torque * rbar / (2 * radius**2 * np.sum(w * rbar**2))
    prob.set_val("radius", np.full(nr, radius))
    prob.set_val("rpm", np.full(nr, rpm))
    prob.set_val("thrust", np.full(nr, thrust))
    prob.set_val("chord", np.tile(np.linspace(0.3, 0.1, nrad), (nr, 1)))
    prob.set_val("thrust_per_span", np.tile(t_span[None, :, None], (nr, 1, 1)))
    prob.set_val("drag_per_span", np.tile(d_span[None, :, None], (nr, 1, 1)))
    prob.set_val("inflow_angle", np.tile(np.arctan(0.0865 / rbar)[None, :, None], (nr, 1, 1)))
    prob.set_val("hub_position", hub_positions()[:nr])
    prob.set_val("density", 1.213457)
    prob.set_val("speed_of_sound", 339.885)
    return prob


WRT = [
    "radius",
    "rpm",
    "thrust",
    "chord",
    "thrust_per_span",
    "drag_per_span",
    "inflow_angle",
    "hub_position",
]


def main(repeats=20):
    """Time ``repeats`` evaluations and linearizations, print the medians and return them (s)."""
    prob = build_problem()
    prob.run_model()
    prob.compute_totals(of=["total_spl_a"], wrt=WRT)  # warm-up
    t_eval, t_lin = [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        prob.run_model()
        t1 = time.perf_counter()
        prob.compute_totals(of=["total_spl_a"], wrt=WRT)
        t2 = time.perf_counter()
        t_eval.append(t1 - t0)
        t_lin.append(t2 - t1)
    t_eval, t_lin = np.array(t_eval), np.array(t_lin)
    total = prob.get_val("total_spl_a")[0]
    print(
        f"{len(_HUBS_FT)} lift rotors in hover, 25 radial stations, 3 harmonics, 38 bands "
        f"(median of {repeats} runs, {os.cpu_count()} CPUs):"
    )
    print(f"  evaluate  (run_model)      {1e3 * np.median(t_eval):7.2f} ms")
    print(f"  linearize (compute_totals) {1e3 * np.median(t_lin):7.2f} ms")
    print(f"  evaluate + linearize       {1e3 * np.median(t_eval + t_lin):7.2f} ms")
    print(
        f"  total A-weighted SPL {total:.2f} dBA (hover limit {HOVER_NOISE_LIMIT_DBA:.0f} dBA); "
        f"per rotor {np.round(prob.get_val('rotor_spl_a'), 2)}"
    )
    return np.median(t_eval), np.median(t_lin)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=20, help="timed runs (median reported)")
    main(parser.parse_args().repeats)
