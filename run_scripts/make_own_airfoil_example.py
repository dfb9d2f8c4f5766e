#!/usr/bin/env python3
"""
Write the own-airfoil example: NACA 4412 coordinates and polar, as a designer brings them.

Writes two files, the kind a designer has for a section the package does not ship:

- ``naca4412.dat``: Selig-format coordinates from the NACA four-digit equations (Abbott & von
  Doenhoff, Theory of Wing Sections, 1959, sec. 6.4; 81 cosine-spaced points per surface,
  closed trailing edge; :func:`lpc_mdo.components.aero.airfoil_coordinates.naca_four_digit`);
- ``naca4412_re5e6.pol``: the polar in XFOIL's polar-file layout (header lines, then the
  columns ``alpha CL CD CDp CM Top_Xtr Bot_Xtr``) at Re = 5e6 (the reference wing's cruise
  Reynolds number on its mean chord: 5.2e6), M = 0, -10..20 deg every 0.5 deg, from NeuralFoil
  0.3.3 (``xxxlarge``, N_crit = 9, the settings of the shipped wing tables). NeuralFoil gives
  no split of the drag into pressure and friction, so the CDp column holds zeros; the package
  reads alpha, CL, CD and CM by the header's names and not CDp.

Usage (NeuralFoil and AeroSandbox are generation-time tools, not dependencies)::

    python3 -m venv /tmp/nfenv && /tmp/nfenv/bin/pip install neuralfoil==0.3.3 aerosandbox
    /tmp/nfenv/bin/python run_scripts/make_own_airfoil_example.py --output-dir tests/data/airfoils

Refuses to write over a file it did not create (a file without this script's header line).
"""

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from components.aero.airfoil_coordinates import naca_four_digit  # noqa: E402

MARK = "written by run_scripts/make_own_airfoil_example.py"
REYNOLDS = 5e6
ALPHA_DEG = np.arange(-10.0, 20.0 + 1e-9, 0.5)


def _writable(path):
    if path.exists() and MARK not in path.read_text(errors="replace")[:400]:
        raise SystemExit(f"{path} exists and was not written by this script; not overwritten")


def main(argv=None):
    """Write the two files into --output-dir."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument("--output-dir", type=Path, default=ROOT / "tests" / "data" / "airfoils")
    args = parser.parse_args(argv)
    import aerosandbox as asb
    import neuralfoil as nf

    coords = naca_four_digit("4412", 81)
    dat, pol = args.output_dir / "naca4412.dat", args.output_dir / "naca4412_re5e6.pol"
    for path in (dat, pol):
        _writable(path)
    lines = [f"NACA 4412 ({MARK})"] + [f"{x:10.6f} {y:10.6f}" for x, y in coords]
    dat.write_text("\n".join(lines) + "\n")

    out = nf.get_aero_from_airfoil(
        asb.Airfoil(name="naca4412", coordinates=coords),
        alpha=ALPHA_DEG,
        Re=np.full_like(ALPHA_DEG, REYNOLDS),
        n_crit=9.0,
        model_size="xxxlarge",
    )
    cl, cd, cm = (np.asarray(out[k], dtype=float) for k in ("CL", "CD", "CM"))
    top, bot = (np.asarray(out[k], dtype=float) for k in ("Top_Xtr", "Bot_Xtr"))
    head = [
        f"  NACA 4412 polar ({MARK}; NeuralFoil {nf.__version__}, xxxlarge)",
        "",
        " Calculated polar for: NACA 4412",
        "",
        " 1 1 Reynolds number fixed          Mach number fixed",
        "",
        " xtrf =   1.000 (top)        1.000 (bottom)",
        f" Mach =   0.000     Re =     {REYNOLDS / 1e6:.3f} e 6     Ncrit =   9.000",
        "",
        "  alpha    CL        CD       CDp       CM     Top_Xtr  Bot_Xtr",
        " ------ -------- --------- --------- -------- -------- --------",
    ]
    rows = [
        f"{a:7.3f} {c:8.4f} {d:9.5f} {0.0:9.5f} {m:8.4f} {t:8.4f} {b:8.4f}"
        for a, c, d, m, t, b in zip(ALPHA_DEG, cl, cd, cm, top, bot, strict=True)
    ]
    pol.write_text("\n".join(head + rows) + "\n")
    print(f"wrote {dat} and {pol}")


if __name__ == "__main__":
    main()
