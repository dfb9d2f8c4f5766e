"""BEM versus the APC Sport 14x13 wind-tunnel data (UIUC): C_T, C_P and efficiency versus J.

    python run_scripts/validate_apc.py [--data-dir ../shared/data/validation] [--plot apc.png]

The 2-blade APC Sport 14x13 (R = 0.1778 m; geometry r/R, c/R, beta from
APC_sport_14_13_blade_geometry.txt, interpolated linearly at the stations) is run by
BEMInflowComp + BEMLoadsComp + RotorPerformanceComp at every measured advance ratio, with the
project's default BEM settings (classical Prandtl tip and hub loss, hub 0.15 R, midpoint rule,
30 stations) and a thin-airfoil-like polar: lift slope 2 pi, cl0 = 0.30 (alpha_L0 = -2.7 deg),
cd0 = 0.028 (low Reynolds number, QPROP's default), otherwise docs theory/aerodynamics
'Linear-quadratic polar' polar. Prints the table of computed and measured C_T, C_P, eta and, with
--plot, saves the three curves.
"""

import argparse
from pathlib import Path

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.polar import LinearQuadraticPolar
from lpc_mdo.components.rotor.bem_inflow import BEMInflowComp
from lpc_mdo.components.rotor.bem_loads import BEMLoadsComp, RotorPerformanceComp

DEFAULT_DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "validation"
RADIUS = 0.1778  # m, 14 in diameter
HUB_RATIO = 0.15  # first geometry station (lsdo_rotor's script)
RPM = 4000.0  # immaterial: the polar has no Reynolds or Mach dependence
POLAR = LinearQuadraticPolar(cl0=0.30, cl_alpha=2.0 * np.pi, cd0=0.028, cd_stall=(0.040, 0.080))


def run_bem(geometry, advance_ratio, polar=POLAR, num_radial=30):
    """C_T, C_P and eta of the APC propeller at the given advance ratios."""
    nn = len(advance_ratio)
    x = HUB_RATIO + (1 - HUB_RATIO) * (np.arange(num_radial) + 0.5) / num_radial
    opts = dict(num_nodes=nn, num_radial=num_radial, polar=polar)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("inflow", BEMInflowComp(**opts), promotes=["*"])
    prob.model.add_subsystem("loads", BEMLoadsComp(**opts), promotes=["*"])
    prob.model.add_subsystem("performance", RotorPerformanceComp(num_nodes=nn), promotes=["*"])
    prob.setup()
    prob.set_val("radius", RADIUS)
    prob.set_val("hub_radius", HUB_RATIO * RADIUS)
    prob.set_val("station_radius", x[None] * RADIUS)
    prob.set_val("station_width", np.full((1, num_radial), (1 - HUB_RATIO) * RADIUS / num_radial))
    prob.set_val("chord", np.interp(x, geometry[:, 0], geometry[:, 1])[None] * RADIUS)
    prob.set_val("twist", np.radians(np.interp(x, geometry[:, 0], geometry[:, 2]))[None])
    prob.set_val("rpm", np.full((1, nn), RPM))
    prob.set_val("axial_velocity", np.asarray(advance_ratio)[None] * RPM / 60.0 * 2.0 * RADIUS)
    prob.set_val("density", np.full(nn, 1.225))
    prob.run_model()
    return (
        prob.get_val("thrust_coefficient")[0],
        prob.get_val("power_coefficient")[0],
        prob.get_val("efficiency")[0],
    )


def main(argv=None):
    """Compare the BEM with the APC data over the advance ratios; print the errors, plot them."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--data-dir",
        type=Path,
        default=DEFAULT_DATA,
        help="folder with APC_sport_14_13_{blade_geometry,performance}.txt",
    )
    parser.add_argument("--plot", type=Path, default=None, help="save a PNG of the curves")
    args = parser.parse_args(argv)
    files = [args.data_dir / f"APC_sport_14_13_{k}.txt" for k in ("blade_geometry", "performance")]
    missing = [str(f) for f in files if not f.is_file()]
    if missing:
        parser.error(f"--data-dir = {args.data_dir}: missing {missing}")
    geometry, data = (np.loadtxt(f) for f in files)
    j, ct_data, cp_data, eta_data = data.T
    ct, cp, eta = run_bem(geometry, j)

    print(
        f"{'J':>6} {'CT bem':>8} {'CT data':>8} {'err':>7} {'CP bem':>8} {'CP data':>8} "
        f"{'err':>7} {'eta bem':>8} {'eta data':>8}"
    )
    for row in zip(j, ct, ct_data, cp, cp_data, eta, eta_data, strict=True):
        jj, c1, c2, p1, p2, e1, e2 = row
        print(
            f"{jj:6.3f} {c1:8.4f} {c2:8.4f} {100 * (c1 / c2 - 1):+6.1f}% {p1:8.4f} {p2:8.4f} "
            f"{100 * (p1 / p2 - 1):+6.1f}% {e1:8.3f} {e2:8.3f}"
        )
    band = (j >= 0.2) & (j <= 0.9)
    ct_err = 100 * np.max(np.abs(ct[band] / ct_data[band] - 1))
    cp_err = 100 * np.max(np.abs(cp[band] / cp_data[band] - 1))
    print(
        f"J in [0.2, 0.9]: max |C_T error| {ct_err:.1f} %, max |C_P error| {cp_err:.1f} %; "
        f"peak eta {eta.max():.3f} (data {eta_data.max():.3f})"
    )

    if args.plot is not None:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        order = np.argsort(j)
        fig, axes = plt.subplots(1, 3, figsize=(12, 3.6), constrained_layout=True)
        for ax, bem, meas, label in zip(
            axes,
            (ct, cp, eta),
            (ct_data, cp_data, eta_data),
            ("$C_T$", "$C_P$", r"$\eta$"),
            strict=True,
        ):
            ax.plot(j, meas, "ko", ms=4, mfc="none", label="UIUC wind tunnel")
            ax.plot(j[order], bem[order], "C0-", label="BEM (lpc_mdo)")
            ax.set_xlabel("advance ratio J")
            ax.set_ylabel(label)
            ax.grid(alpha=0.3)
        axes[0].legend()
        fig.suptitle("APC Sport 14x13: BEM vs. wind-tunnel data")
        fig.savefig(args.plot, dpi=120)
        print(f"saved {args.plot}")


if __name__ == "__main__":
    main()
