"""
Broadband noise models against measurements, and the blade-count trade on the reference rotor.

Usage::

    python run_scripts/broadband_validation.py airfoil airfoil_self_noise.dat
    python run_scripts/broadband_validation.py helicopters
    python run_scripts/broadband_validation.py blades CASE.sql
    python run_scripts/broadband_validation.py hover CASE.sql [CASE.sql ...]

``airfoil``: the BPM section model (components/acoustics/airfoil_self_noise.py) against NASA's
measured one-third-octave spectra of NACA 0012 sections (Brooks, Pope & Marcolini, NASA RP-1218,
1989), as distributed in the UCI Machine Learning Repository "Airfoil Self-Noise" data set
(doi:10.24432/C5VW2C; 1503 rows: frequency, angle of attack, chord, speed, suction-side
displacement thickness, scaled SPL = SPL - 10 log10(delta*_s M**5 L/r_e**2), L = 45.72 cm span,
r_e = 1.22 m, observer at 90 deg).

``helicopters``: the measured broadband (vortex) noise of two helicopter rotors in hover at
300 ft (CH-3C: 5 blades, solidity 0.078; CH-53A: 6 blades, solidity 0.115), against the
Gill-Lee and BPM rotor models; and the data's local rise with blade loading, with the 2 -> 3
blade change it implies.

``blades``: 2 -> 3 blades at equal thrust and tip speed on the reference optimum's hover
rotors (CASE.sql, e.g. the sequence's full.sql), at the paper's hover observer, with both
models, unweighted (as the helicopter data) and A-weighted.

``hover``: each design's hover noise at the paper's observer by both models, and its lift
rotors' tip speed, blade loading, angle of attack and lift coefficient in hover.

docs results/broadband shows the numbers.
"""

import math
import os
import sqlite3
import sys
import tempfile

import numpy as np

from lpc_mdo.components.acoustics.common import radial_quadrature

FT = 0.3048
LBF = 4.4482216152605

#: Measured vortex (broadband) noise in hover at 300 ft, dB: (rotor, rpm, thrust lbf, SPL).
#: Schlegel, King & Mull, "Helicopter Rotor Noise Generation and Propagation", USAAVLABS
#: TR 66-4 (1966), as reproduced in Leishman, "Principles of Helicopter Aerodynamics" (2nd ed.,
#: 2006) and transcribed in the public convexengineering/eVTOL noise validation script.
HELICOPTER_DATA = (
    ("CH-3C", 183, 13400, 76), ("CH-3C", 183, 16200, 79), ("CH-3C", 183, 18700, 81),
    ("CH-3C", 183, 20500, 82), ("CH-3C", 203, 16300, 81), ("CH-3C", 203, 18100, 81),
    ("CH-3C", 203, 19900, 82), ("CH-3C", 203, 21400, 83), ("CH-3C", 213, 14500, 81),
    ("CH-3C", 213, 18200, 83), ("CH-3C", 213, 20000, 83),
    ("CH-53A", 166, 24000, 80), ("CH-53A", 166, 28400, 81), ("CH-53A", 166, 32000, 83),
    ("CH-53A", 166, 36200, 83), ("CH-53A", 166, 39000, 85), ("CH-53A", 185.5, 25000, 83),
    ("CH-53A", 185.5, 30100, 83), ("CH-53A", 185.5, 36200, 85), ("CH-53A", 185.5, 41600, 87),
    ("CH-53A", 215, 23700, 85), ("CH-53A", 215, 29600, 86), ("CH-53A", 215, 37900, 89),
    ("CH-53A", 215, 43520, 90),
)  # fmt: skip
#: Rotor diameter (ft), blade count and solidity of the two helicopters (same sources).
HELICOPTERS = {"CH-3C": (62.0, 5, 0.078), "CH-53A": (72.0, 6, 0.115)}
#: Air density of the comparison, kg/m**3 (the transcription's value).
HELICOPTER_DENSITY = 1.19956
HELICOPTER_DISTANCE = 300.0 * FT


def rotor_broadband(model, blades, radius, rpm, chord, thrust_per_span, inflow, observer,
                    density=1.225, hub_radius_ratio=0.2):  # fmt: skip
    """
    Broadband level (dB, dBA) of one hovering rotor at an observer, by ``model``.

    ``chord``, ``thrust_per_span`` (one blade) and ``inflow`` at the acoustic stations (equal
    elements on [hub_radius_ratio, 1]); ``observer`` = (distance m, elevation deg below the
    rotor plane). Runs the package's RotorNoiseGroup (propagation, absorption, A-weighting).
    """
    import openmdao.api as om

    from lpc_mdo.groups.acoustics import RotorNoiseGroup

    nrad = len(chord)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "noise",
        RotorNoiseGroup(
            num_rotors=1,
            num_radial=nrad,
            num_blades=int(blades),
            hub_radius_ratio=hub_radius_ratio,
            broadband_model=model,
        ),
        promotes=["*"],
    )
    prob.setup()
    _, w = radial_quadrature(nrad, hub_radius_ratio=hub_radius_ratio)
    prob.set_val("radius", radius, units="m")
    prob.set_val("rpm", rpm, units="rpm")
    prob.set_val("chord", np.reshape(chord, (1, nrad)), units="m")
    t = np.reshape(thrust_per_span, (1, nrad, 1))
    prob.set_val("thrust_per_span", t, units="N/m")
    prob.set_val("drag_per_span", 0.05 * t, units="N/m")
    prob.set_val("inflow_angle", np.reshape(inflow, (1, nrad, 1)), units="rad")
    if model == "gill_lee":  # the Gill-Lee model takes the rotor's thrust
        thrust = blades * radius * np.sum(w * np.ravel(thrust_per_span))
        prob.set_val("thrust", thrust, units="N")
    prob.set_val("density", density, units="kg/m**3")
    prob.set_val("observer_distance", observer[0], units="m")
    prob.set_val("observer_elevation", -abs(observer[1]), units="deg")
    prob.run_model()
    return float(prob.get_val("broadband_oaspl")[0]), float(prob.get_val("broadband_oaspl_a")[0])


def uniform_lift_loads(
    blades, radius, rpm, chord, thrust, density, hub_radius_ratio=0.2, exponent=2.0
):
    """
    Sectional thrust per span and inflow angle of a hovering blade of uniform lift coefficient.

    C_l the same at every station (Leishman's blade-element mean C_l = 6 C_T/sigma for a
    rectangular blade), scaled so that B R sum_i w_i t_i = T; inflow angle from hover momentum
    theory, phi_i = arctan(lambda/rbar_i), lambda = sqrt(C_T/2). ``exponent`` n other than 2
    gives t proportional to c rbar**n instead (C_l proportional to rbar**(n - 2): n < 2 loads
    the root more), the check of how much the comparison depends on the load shape.
    """
    chord = np.asarray(chord, dtype=float)
    rbar, w = radial_quadrature(chord.size, hub_radius_ratio=hub_radius_ratio)
    omega = rpm * math.pi / 30.0
    shape = chord * rbar**exponent
    t = thrust / (blades * radius * np.sum(w * shape)) * shape
    ct = thrust / (density * math.pi * radius**2 * (omega * radius) ** 2)
    return t, np.arctan(math.sqrt(ct / 2.0) / rbar)


def airfoil(data):
    """Print the BPM section model against the measured NACA 0012 spectra (rows of ``data``)."""
    from lpc_mdo.components.acoustics.airfoil_self_noise import (
        displacement_thickness,
        trailing_edge_noise,
    )

    f, alpha, chord, speed, ds_file, scaled = data.T
    nu = 1.4529e-5  # the data set's kinematic viscosity (its delta*_s column reproduces with it)
    mach = speed / 340.46
    span, r_e = 0.4572, 1.22
    _, ds = displacement_thickness(chord, speed * chord / nu, alpha)
    print(f"suction-side displacement thickness, model/data: {np.min(ds / ds_file):.5f} to "
          f"{np.max(ds / ds_file):.5f}")  # fmt: skip
    level = 10.0 * np.log10(
        trailing_edge_noise(f, chord, speed, mach, alpha, span, r_e, 1.0, 1.0, nu)
    )
    model = level - 10.0 * np.log10(ds_file * mach**5 * span / r_e**2)
    err = model - scaled
    print("band levels, model - measured (dB):")
    print(f"{'cases':32s} {'bands':>5s} {'mean':>6s} {'rms':>6s}")
    for label, mask in (
        ("all", np.ones_like(f, dtype=bool)),
        ("chord >= 10 cm, alpha* <= 12.5 deg", (chord >= 0.1) & (alpha <= 12.5)),
        ("chord >= 10 cm, alpha* > 12.5 deg", (chord >= 0.1) & (alpha > 12.5)),
        ("chord < 10 cm", chord < 0.1),
    ):
        e = err[mask]
        print(f"{label:32s} {e.size:5d} {e.mean():6.2f} {np.sqrt(np.mean(e * e)):6.2f}")
    print("overall level of each measured spectrum, model - measured (dB):")
    keys = sorted(set(zip(chord, alpha, speed, strict=True)))
    rows = []
    for key in keys:
        m = (chord == key[0]) & (alpha == key[1]) & (speed == key[2])
        rows.append((*key, _sum_db(scaled[m]), _sum_db(model[m])))
    rows = np.array(rows)
    for label, mask in (
        ("chord >= 10 cm, alpha* <= 12.5 deg", (rows[:, 0] >= 0.1) & (rows[:, 1] <= 12.5)),
        ("all", rows[:, 0] > 0.0),
    ):
        e = rows[mask, 4] - rows[mask, 3]
        print(f"{label:32s} {e.size:5d} {e.mean():6.2f} {np.sqrt(np.mean(e * e)):6.2f}")
    print("by chord (alpha* <= 12.5 deg): chord m, spectra, mean, rms")
    for c in np.unique(rows[:, 0]):
        m = (rows[:, 0] == c) & (rows[:, 1] <= 12.5)
        e = rows[m, 4] - rows[m, 3]
        print(f"  {c:.4f} {e.size:3d} {e.mean():6.2f} {np.sqrt(np.mean(e * e)):6.2f}")


def _header_rows(path):
    with open(path) as handle:
        first = handle.readline().split()
    try:
        [float(x) for x in first]
    except ValueError:
        return 1
    return 0


def _sum_db(levels):
    return 10.0 * np.log10(np.sum(10.0 ** (np.asarray(levels) / 10.0)))


def _helicopter_levels(model, elevation, exponent=2.0, nrad=25):
    """Return (rotor, measured, model level) of each helicopter point (nan: out of range)."""
    import openmdao.api as om

    rows = []
    for name, rpm, thrust_lbf, measured in HELICOPTER_DATA:
        diameter, blades, sigma = HELICOPTERS[name]
        radius = diameter * FT / 2.0
        chord = np.full(nrad, sigma * math.pi * radius / blades)
        t, inflow = uniform_lift_loads(
            blades, radius, rpm, chord, thrust_lbf * LBF, HELICOPTER_DENSITY, exponent=exponent
        )
        try:
            level, _ = rotor_broadband(
                model, blades, radius, rpm, chord, t, inflow,
                (HELICOPTER_DISTANCE, elevation), density=HELICOPTER_DENSITY,
            )  # fmt: skip
        except om.AnalysisError:  # outside the model's range
            level = math.nan
        rows.append((name, measured, level))
    return rows


def _fit_slopes(levels, rows):
    """k_T, k_V of SPL = a_rotor + k_T log10 T + k_V log10 V_tip over HELICOPTER_DATA[rows]."""
    design = np.array([
        [HELICOPTER_DATA[k][0] == "CH-3C", HELICOPTER_DATA[k][0] == "CH-53A",
         math.log10(HELICOPTER_DATA[k][2]), math.log10(HELICOPTER_DATA[k][1])]
        for k in rows
    ], dtype=float)  # fmt: skip
    coef, *_ = np.linalg.lstsq(design, np.asarray(levels, dtype=float), rcond=None)
    return coef[2], coef[3]


def helicopters(elevations=(10.0, 45.0, 90.0)):
    """Print the two helicopters' measured broadband levels against both models."""
    results = {
        (model, elevation): _helicopter_levels(model, elevation)
        for elevation in elevations
        for model in ("gill_lee", "bpm")
    }
    print("measured vortex noise of two helicopter rotors at 300 ft (dB) and the models:")
    for elevation in elevations:
        print(f"observer {elevation:.0f} deg below the rotor plane")
        print(f"  {'model':9s} {'CH-3C mean':>10s} {'CH-53A mean':>11s} {'53A - 3C':>9s} "
              f"{'rms after offset':>16s}")  # fmt: skip
        # The points both models hold (the BPM's section Mach limit leaves out the CH-53A's
        # fastest points).
        keep = [
            not any(math.isnan(results[m, elevation][k][2]) for m in ("gill_lee", "bpm"))
            for k in range(len(HELICOPTER_DATA))
        ]
        for model in ("gill_lee", "bpm"):
            rows = results[model, elevation]
            ok = [row for row, kept in zip(rows, keep, strict=True) if kept]
            err = np.array([lev - meas for _, meas, lev in ok])
            kind = np.array([name for name, _, _ in ok])
            off3 = err[kind == "CH-3C"].mean()
            off53 = err[kind == "CH-53A"].mean()
            rms = np.sqrt(np.mean((err - err.mean()) ** 2))
            print(f"  {model:9s} {off3:10.2f} {off53:11.2f} {off53 - off3:9.2f} {rms:16.2f}"
                  f"  ({len(rows) - len(ok)} points left out)")  # fmt: skip
    print("level against thrust at fixed rotor and speed, dB per decade of thrust (45 deg):")
    elevation = 45.0 if 45.0 in elevations else elevations[-1]
    groups = sorted({(name, rpm) for name, rpm, _, _ in HELICOPTER_DATA})
    slopes = {"measured": [], "gill_lee": [], "bpm": []}
    for name, rpm in groups:
        idx = [k for k, row in enumerate(HELICOPTER_DATA) if row[:2] == (name, rpm)]
        logt = np.log10([HELICOPTER_DATA[k][2] for k in idx])
        line = [f"  {name:6s} {rpm:6.1f}"]
        for key in slopes:
            if key == "measured":
                level = [HELICOPTER_DATA[k][3] for k in idx]
            else:
                level = [results[key, elevation][k][2] for k in idx]
            slope = np.polyfit(logt, level, 1)[0] if not np.any(np.isnan(level)) else math.nan
            slopes[key].append(slope)
            line.append(f"{key} {slope:5.1f}")
        print("  ".join(line))
    print("  mean over the groups both models hold: " + "  ".join(
        f"{key} {np.nanmean(np.where(np.isnan(slopes['bpm']), np.nan, v)):5.1f}"
        for key, v in slopes.items()))  # fmt: skip
    # Least squares over the points both models hold: SPL = a_rotor + k_T log10 T + k_V log10 V_T
    # (one offset per helicopter): the level's dependence on thrust and tip speed.
    rows = [k for k in range(len(HELICOPTER_DATA)) if keep[k]]
    print("fit SPL = a_rotor + k_T log10 T + k_V log10 V_tip over the points both models hold:")
    for key in ("measured", "gill_lee", "bpm"):
        if key == "measured":
            level = [HELICOPTER_DATA[k][3] for k in rows]
        else:
            level = [results[key, elevation][k][2] for k in rows]
        k_t, k_v = _fit_slopes(level, rows)
        # C_T/sigma is proportional to T/V_tip**2 on each rotor: at fixed blade loading the
        # level rises k_V + 2 k_T per decade of tip speed.
        print(f"  {key:9s} k_T {k_t:5.1f}  k_V {k_v:5.1f}  (at fixed C_T/sigma "
              f"{k_v + 2.0 * k_t:5.1f})")  # fmt: skip
    # The same fit with a root-heavier load shape (thrust per span ~ c r**1.5).
    line = []
    for key in ("gill_lee", "bpm"):
        other = _helicopter_levels(key, elevation, exponent=1.5)
        k_t, k_v = _fit_slopes([other[k][2] for k in rows], rows)
        line.append(f"{key} k_T {k_t:5.1f}  k_V {k_v:5.1f}")
    print("  with thrust per span ~ c r**1.5 instead of c r**2: " + ";  ".join(line))
    every = np.array([
        [row[0] == "CH-3C", row[0] == "CH-53A", math.log10(row[2]), math.log10(row[1])]
        for row in HELICOPTER_DATA
    ], dtype=float)  # fmt: skip
    levels = np.array([row[3] for row in HELICOPTER_DATA], dtype=float)
    coef, *_ = np.linalg.lstsq(every, levels, rcond=None)
    resid = levels - every @ coef
    variance = (resid @ resid) / (len(levels) - every.shape[1])
    error = np.sqrt(np.diag(np.linalg.inv(every.T @ every)) * variance)
    print(f"  measured, all {len(levels)} points: k_T {coef[2]:.1f} +- {error[2]:.1f}  "
          f"k_V {coef[3]:.1f} +- {error[3]:.1f} (one standard error)")  # fmt: skip
    print_loading_fit()
    print("per point (45 deg): rotor, rpm, thrust lbf, measured, Gill-Lee, BPM")
    for k, (name, rpm, thrust_lbf, measured) in enumerate(HELICOPTER_DATA):
        gl = results["gill_lee", elevation][k][2]
        bpm = results["bpm", elevation][k][2]
        print(f"  {name:6s} {rpm:6.1f} {thrust_lbf:6d} {measured:4d} {gl:7.1f} {bpm:7.1f}")


def loading_fit(levels, reference):
    """
    Fit the helicopter levels' local rise with blade loading; return (coefficients, errors).

    Least squares over HELICOPTER_DATA: SPL = a_3C + a_53A + k log10 V_tip + s x + q x**2,
    x = log10((C_T/sigma)/reference), C_T = T/(rho pi R**2 V_tip**2); coefficients and their
    standard errors in that order. s is the rise per decade of thrust at fixed rotor and tip
    speed at C_T/sigma = reference, k the rise per decade of tip speed at fixed blade loading.
    Also returns the loading range of the data as a third item.
    """
    design = []
    for name, rpm, thrust_lbf, _ in HELICOPTER_DATA:
        diameter, _, sigma = HELICOPTERS[name]
        radius = diameter * FT / 2.0
        tip = rpm * math.pi / 30.0 * radius
        ct = thrust_lbf * LBF / (HELICOPTER_DENSITY * math.pi * radius**2 * tip**2)
        x = math.log10(ct / sigma / reference)
        design.append([name == "CH-3C", name == "CH-53A", math.log10(tip), x, x * x])
    design, levels = np.array(design, dtype=float), np.asarray(levels, dtype=float)
    coef, *_ = np.linalg.lstsq(design, levels, rcond=None)
    resid = levels - design @ coef
    variance = (resid @ resid) / (len(levels) - design.shape[1])
    error = np.sqrt(np.diag(np.linalg.inv(design.T @ design)) * variance)
    loading = reference * 10.0 ** design[:, 3]
    return coef, error, (loading.min(), loading.max())


def print_loading_fit(references=(0.05, 0.08, 0.11, 0.16, 0.22)):
    """
    Print the measured level's local rise with blade loading and the 2 -> 3 blade change.

    A third blade of the same chord at equal thrust and tip speed has 1.5 times the blade area
    and 2/3 of the loading per blade area: (10 - s) log10 1.5 dB, s of :func:`loading_fit`.
    """
    measured = [row[3] for row in HELICOPTER_DATA]
    print("measured level against blade loading: SPL = a_rotor + k log10 V_tip + s x + q x**2, "
          "x = log10((C_T/sigma)/ref)")  # fmt: skip
    for ref in references:
        (_, _, k, s, q), (_, _, dk, ds, dq), span = loading_fit(measured, ref)
        change = (10.0 - s) * math.log10(1.5)
        print(f"  ref {ref:.3f} (data {span[0]:.3f}-{span[1]:.3f}): s {s:5.1f} +- {ds:.1f} "
              f"dB/decade, q {q:5.1f} +- {dq:.1f}, k {k:5.1f} +- {dk:.1f}; 3 blades of the "
              f"same chord: {change:+.2f} +- {ds * math.log10(1.5):.2f} dB"
              + ("  (beyond the data)" if ref > span[1] else ""))  # fmt: skip


def _evaluated(case_file, work_dir, broadband_model):
    """Return the reference model at the design of ``case_file``, run with ``broadband_model``."""
    from lpc_mdo.problems import build_analysis_problem
    from lpc_mdo.vehicle import load_vehicle
    from lpc_mdo.warm_start import load_design_variables, start_point

    vehicle = load_vehicle(None)
    prob = build_analysis_problem(
        vehicle, work_dir=work_dir, design_problem=False, broadband_model=broadband_model
    )
    case, _ = start_point(case_file, vehicle)
    load_design_variables(prob, case, vehicle)
    prob.run_model()
    return prob


def _hover_rotors(prob):
    """
    One lift rotor of each pair in the evaluated model's hover: its state and blade loading.

    Radius, rpm, chord, thrust per span of one blade and inflow angle at the acoustic stations
    (rbar), the thrust B R sum_i w_i t_i, tip speed and C_T/sigma, sigma = B R sum_i w_i c_i/(pi
    R**2); blade count and hub from the vehicle.
    """
    pairs = len(prob.get_val("hover_lift_rpm"))
    rotor = prob.vehicle.lift_rotors[0]
    get = prob.get_val
    r = {
        "radius": get("hover.noise.radius", units="m")[:pairs],
        "rpm": get("hover.noise.rpm", units="rpm")[:pairs],
        "chord": get("hover.noise.chord", units="m")[:pairs],
        "load": get("hover.noise.thrust_per_span", units="N/m")[:pairs, :, 0],
        "inflow": get("hover.noise.inflow_angle", units="rad")[:pairs, :, 0],
        "density": float(get("hover.noise.density", units="kg/m**3")[0]),
        "blades": rotor.num_blades,
    }
    r["rbar"], w = radial_quadrature(r["chord"].shape[1], hub_radius_ratio=rotor.hub_radius_ratio)
    r["thrust"] = r["blades"] * r["radius"] * (r["load"] @ w)
    r["tip"] = r["rpm"] * math.pi / 30.0 * r["radius"]
    ct = r["thrust"] / (r["density"] * math.pi * r["radius"] ** 2 * r["tip"] ** 2)
    r["ct_sigma"] = ct / (r["blades"] * (r["chord"] @ w) / (math.pi * r["radius"]))
    return r


def hover(case_files, work_dir):
    """Print each design's hover noise by both models and its lift rotors' loading."""
    for case_file in case_files:
        levels = {}
        for model in ("gill_lee", "bpm"):
            prob = _evaluated(case_file, work_dir, model)
            levels[model] = prob.get_val("hover.total_spl_a")[0]
        print(f"{case_file}: W0 {prob.get_val('gross_mass', units='kg')[0]:.2f} kg, battery "
              f"{prob.get_val('battery_mass', units='kg')[0]:.1f} kg; hover noise at the "
              f"paper's observer: Gill-Lee {levels['gill_lee']:.2f} dBA, BPM "
              f"{levels['bpm']:.2f} dBA")  # fmt: skip
        r = _hover_rotors(prob)
        a0 = prob.get_val("hover.noise.speed_of_sound", units="m/s")[0]
        aoa = np.degrees(prob.get_val("hover.lift_rotors.angle_of_attack", units="rad"))
        phi = r["inflow"]
        speed = r["tip"][:, None] * r["rbar"] / np.cos(phi)
        cl = r["load"] / np.cos(phi) / (0.5 * r["density"] * speed**2 * r["chord"])
        k = int(np.argmin(np.abs(r["rbar"] - 0.75)))
        print("  pair  R m     tip m/s  C_T/sigma  mean alpha deg  c_l at 0.75 R (Mach)")
        for i in range(len(r["tip"])):
            print(f"  {i + 1:4d}  {r['radius'][i]:.3f}  {r['tip'][i]:7.1f}  "
                  f"{r['ct_sigma'][i]:9.3f}  {aoa[i, 0].mean():14.1f}  "
                  f"{cl[i, k]:.2f} ({speed[i, k] / a0:.2f})")  # fmt: skip


def blades(case_file, work_dir):
    """Print 2 -> 3 blades at equal thrust and tip speed on the reference optimum's rotors."""
    prob = _evaluated(case_file, work_dir, "gill_lee")
    r = _hover_rotors(prob)
    print(f"reference optimum: gross mass {prob.get_val('gross_mass')[0]:.2f} kg; paper's hover "
          "observer (100 m, 45 deg below the rotor plane)")  # fmt: skip
    print("levels unweighted (dB, as the helicopter data) and A-weighted (dBA)")
    print(
        "columns: 2 blades; the change with 3 blades of the same chord, 3 of the same "
        "solidity, 2 blades 1.5 times as wide (all at equal thrust and tip speed)"
    )
    print(f"{'rotor':>5s} {'R m':>6s} {'rpm':>7s} {'T N':>7s} {'CT/s':>6s} {'loading':10s} "
          f"{'model':9s} {'B=2 dB':>7s} {'3, same c':>10s} {'3, same sigma':>14s} "
          f"{'2, c x1.5':>10s} {'B=2 dBA':>8s} {'3, same c':>10s} {'3, same sigma':>14s} "
          f"{'2, c x1.5':>10s}")  # fmt: skip
    for k in range(len(r["tip"])):  # one rotor of each pair
        args = (r["radius"][k], r["rpm"][k])
        chord, ct_sigma = r["chord"][k], r["ct_sigma"][k]
        # The same rotor at the optimum's loading, and unloaded to C_T/sigma = 0.05, 0.08 and
        # 0.11, across the helicopter data's 0.03-0.11 (thrust scaled, inflow by momentum theory).
        loadings = [("optimum", 1.0)] + [
            (f"C_T/s {target:.2f}", target / ct_sigma) for target in (0.05, 0.08, 0.11)
        ]
        for label, scale in loadings:
            load = r["load"][k] * scale
            phi = np.arctan(np.tan(r["inflow"][k]) * math.sqrt(scale))
            for model in ("gill_lee", "bpm"):
                observer = (100.0, 45.0)
                base = np.array(rotor_broadband(model, 2, *args, chord, load, phi, observer))
                same_c = rotor_broadband(model, 3, *args, chord, load * 2 / 3, phi, observer)
                same_s = rotor_broadband(model, 3, *args, chord * 2 / 3, load * 2 / 3, phi,
                                         observer)  # fmt: skip
                wide = rotor_broadband(model, 2, *args, chord * 1.5, load, phi, observer)
                same_c, same_s = np.array(same_c) - base, np.array(same_s) - base
                wide = np.array(wide) - base
                print(f"{k:5d} {args[0]:6.3f} {args[1]:7.1f} {r['thrust'][k] * scale:7.0f} "
                      f"{ct_sigma * scale:6.3f} {label:10s} {model:9s} "
                      f"{base[0]:7.2f} {same_c[0]:+10.2f} {same_s[0]:+14.2f} {wide[0]:+10.2f} "
                      f"{base[1]:8.2f} {same_c[1]:+10.2f} {same_s[1]:+14.2f} "
                      f"{wide[1]:+10.2f}")  # fmt: skip


def main(argv=None):
    """Run the command of ``argv`` (default: the command line); return the exit status."""
    argv = sys.argv[1:] if argv is None else argv
    usage = __doc__.split("Usage::")[1].split("``airfoil``")[0]
    if not argv or argv[0] not in ("airfoil", "helicopters", "blades", "hover"):
        print("usage:" + usage, file=sys.stderr)
        return 2
    if argv[0] == "airfoil" and len(argv) == 2:
        try:
            data = np.loadtxt(argv[1], skiprows=_header_rows(argv[1]), ndmin=2)
        except (OSError, ValueError) as err:
            print(f"broadband_validation: cannot read {argv[1]!r}: {err}", file=sys.stderr)
            return 2
        if data.shape[1] != 6:
            print(
                f"broadband_validation: {argv[1]!r} has {data.shape[1]} columns; the airfoil "
                "self-noise data set has 6 (frequency, angle, chord, speed, displacement "
                "thickness, scaled SPL)",
                file=sys.stderr,
            )
            return 2
        airfoil(data)
    elif argv[0] == "helicopters" and len(argv) == 1:
        helicopters()
    elif argv[0] in ("blades", "hover") and len(argv) >= 2:
        if argv[0] == "blades" and len(argv) != 2:
            print("usage:" + usage, file=sys.stderr)
            return 2
        for path in argv[1:]:
            if not os.path.isfile(path):
                print(f"broadband_validation: no case file {path!r}", file=sys.stderr)
                return 2
        with tempfile.TemporaryDirectory() as work_dir:  # OpenMDAO's output folder
            try:
                if argv[0] == "blades":
                    blades(argv[1], work_dir)
                else:
                    hover(argv[1:], work_dir)
            except (ValueError, OSError, sqlite3.DatabaseError) as err:
                print(f"broadband_validation: {err}", file=sys.stderr)
                return 2
    else:
        print("usage:" + usage, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
