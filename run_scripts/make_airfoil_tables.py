#!/usr/bin/env python3
"""
Regenerate the airfoil tables ``lpc_mdo/data/airfoil_<name>.npz``.

What each file holds (all angles in degrees in the files; the runtime converts to radians):

- ``alpha_deg`` (n_a), ``reynolds`` (n_r), ``mach`` (n_m) and ``cl``, ``cd``, ``cm``
  (n_a, n_r, n_m): the polar from NeuralFoil 0.3.3 (an XFOIL-trained network; incompressible)
  with the Prandtl-Glauert rule for Mach (cl and cm divided by sqrt(1 - M^2)); cd unchanged,
  except for the rotor-blade section (``naca0012``: Re 2e4..1e7, M 0..0.9), whose cd adds the
  Korn-Lock transonic wave drag (:func:`wave_drag`); ``confidence`` is NeuralFoil's analysis
  confidence (0..1).
- wing airfoils only (``ls413``, ``ls417``), when XFOIL runs: ``cl``, ``cd``, ``cm`` are the
  XFOIL/NeuralFoil merge (:func:`merge_polars`): XFOIL 6.99 in each (Re, M) slice's converged
  attached range at M <= XFOIL_MACH_MAX, NeuralFoil elsewhere, a C1 smoothstep blend over
  XFOIL_BLEND_DEG at the ends of the range; ``polar_xfoil_weight`` (n_a, n_r, n_m) is the weight
  of XFOIL at every point (1 XFOIL, 0 NeuralFoil), ``polar_xfoil_range_deg`` (n_r, n_m, 2) the
  trusted range (NaN where none), ``polar_xfoil_cl``/``_cd``/``_cm`` the XFOIL polar (NaN
  where not converged; short gaps filled, marked in ``polar_xfoil_filled``) and
  ``polar_neuralfoil_cl``/``_cd``/``_cm`` the NeuralFoil one.
- wing airfoils only (``ls413``, ``ls417``): the chordwise pressure coefficient from XFOIL 6.99
  (Debian package ``xfoil``), ``cp_alpha_deg`` (p_a), ``cp_reynolds`` (p_r), ``cp_mach`` (p_m),
  ``x`` (n_x stations, x/c from the leading edge, cosine spaced), ``y_upper``, ``y_lower`` (n_x,
  surface heights y/c at the stations), ``cp_upper``, ``cp_lower`` (p_a, p_r, p_m, n_x),
  ``cp_converged`` (p_a, p_r, p_m) and XFOIL's own ``xfoil_cl``, ``xfoil_cd``, ``xfoil_cm``
  (NaN where XFOIL did not converge).

Usage (a few seconds for the polars; the XFOIL pressure tables take about 5 minutes of CPU,
about 5 minutes wall time with ``--jobs 2``; a rerun reproduces the shipped arrays bit for bit)::

    python3 -m venv /tmp/genvenv && /tmp/genvenv/bin/pip install neuralfoil==0.3.3
    apt-get install xfoil xvfb   # pressure tables only (XFOIL 6.99 needs an X display)
    /tmp/genvenv/bin/python run_scripts/make_airfoil_tables.py [--airfoils ls413 ...]
        [--coordinates ../shared/data/airfoils] [--out lpc_mdo/data] [--jobs 2] [--no-pressure]

NeuralFoil and XFOIL are generation-time tools only; the lpc_mdo runtime reads the ``.npz`` files
with numpy. ``lpc_mdo/data/README.md`` records the settings used for the shipped files.
"""

import argparse
import concurrent.futures
import datetime
import os
import pickle
import queue
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from importlib import metadata
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
DEFAULT_COORDINATES = REPO.parent / "shared" / "data" / "airfoils"
DEFAULT_OUT = REPO / "lpc_mdo" / "data"

# Transonic drag rise of the rotor-blade section (the only table the rotors read; the wing and
# tail fly at M < 0.3). Korn's equation (Mason, "Configuration Aerodynamics", Virginia Tech
# class notes, ch. 7 'Transonic Aerodynamics of Airfoils and Wings'; Gur, Mason and Schetz,
# "Full-Configuration Drag Estimation", J. Aircraft 47(4), 2010) for an unswept section,
# M_dd = kappa_A - t/c - |c_l|/10, with the airfoil technology factor kappa_A = 0.87 of
# conventional (not supercritical: 0.95) sections; the critical Mach number from Lock's
# fourth-power law, M_crit = M_dd - (0.1/80)^(1/3) (the Mach number where the drag-rise
# slope dc_d/dM reaches 0.1), and the wave drag c_d,w = 20 (M - M_crit)^4 above it.
KORN_KAPPA_CONVENTIONAL = 0.87
LOCK_COEFFICIENT = 20.0
LOCK_OFFSET = (0.1 / 80.0) ** (1.0 / 3.0)

# Rotor-section grids: the wing grids below plus Re 2e4 and 5e4 (blade roots of small chords in
# transition) and Mach every 0.05 up to 0.9 (a pusher's helical tip is limited to 0.85 and the
# lift rotors' to 0.7; beyond 0.9 the model raises an AnalysisError instead of extrapolating).
ROTOR_REYNOLDS = np.array([2e4, 5e4, 1e5, 2e5, 3e5, 5e5, 1e6, 2e6, 3e6, 5e6, 1e7])
ROTOR_MACH = np.array([0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9])

# name: coordinate file (None = generated NACA 4-digit symmetric section with thickness t),
# description, symmetric flag, whether to make XFOIL pressure tables; optional ``reynolds`` and
# ``mach`` grids (default REYNOLDS, MACH) and ``kappa`` (Korn's technology factor: add the
# transonic wave drag, with thickness t).
AIRFOILS = {
    "naca0012": dict(
        file="naca0012.dat",
        t=0.12,
        symmetric=True,
        pressure=False,
        reynolds=ROTOR_REYNOLDS,
        mach=ROTOR_MACH,
        kappa=KORN_KAPPA_CONVENTIONAL,
        description="NACA 0012 (rotor and propeller blades)",
    ),
    "naca0015": dict(
        file=None,
        t=0.15,
        symmetric=True,
        pressure=False,
        description="NACA 0015 (tails), coordinates generated from the four-digit "
        "equation with the naca0012.dat rule (open trailing edge)",
    ),
    "ls413": dict(
        file="ls413_gaw2.dat",
        symmetric=False,
        pressure=True,
        description="NASA LS(1)-0413 = GA(W)-2 (wing, project default)",
    ),
    "ls417": dict(
        file="ls417_gaw1.dat",
        symmetric=False,
        pressure=True,
        description="NASA LS(1)-0417 = GA(W)-1 (wing, public-code alternative)",
    ),
}

# Polar grid (NeuralFoil): alpha every 0.5 deg on +-25 deg (NeuralFoil's confident range; the
# runtime replaces everything beyond each slice's stall point by Viterna), Reynolds numbers
# roughly log-uniform on 1e5..1e7 (covers the paper's 1e5..8e6), Mach 0..0.6 (the wing and tail
# fly below 0.3; the rotor section has its own grids, ROTOR_REYNOLDS and ROTOR_MACH).
ALPHA_DEG = np.arange(-25.0, 25.0 + 1e-9, 0.5)
REYNOLDS = np.array([1e5, 2e5, 3e5, 5e5, 1e6, 2e6, 3e6, 5e6, 1e7])
MACH = np.array([0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6])
N_CRIT = 9.0
MODEL_SIZE = "xxxlarge"

# Pressure grid (XFOIL): every 1 deg on -16..22 deg (run in 0.5 deg steps from 0 deg up and down
# for convergence), 5 Reynolds numbers, Mach 0..0.5, 240 panel nodes resampled to N_X cosine
# spaced stations per surface.
CP_ALPHA_DEG = np.arange(-16.0, 22.0 + 1e-9, 1.0)
CP_REYNOLDS = np.array([1e5, 3e5, 1e6, 3e6, 1e7])
CP_MACH = np.array([0.0, 0.1, 0.2, 0.3, 0.4, 0.5])
XFOIL_PANELS = 240
XFOIL_ITER = 80
XFOIL_SUBSTEP = 0.5
N_X = 61


def naca4_symmetric(t, n=81):
    """NACA 00tt coordinates, Selig order, cosine spacing, open trailing edge (as naca0012.dat)."""
    beta = np.linspace(0.0, np.pi, n)
    x = 0.5 * (1.0 - np.cos(beta))
    y = 5 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1015 * x**4)
    upper = np.column_stack([x[::-1], y[::-1]])
    lower = np.column_stack([x[1:], -y[1:]])
    return np.vstack([upper, lower])


def load_coordinates(name, coordinates_dir):
    """Return the Selig-order coordinates of airfoil ``name`` (read from a file or generated)."""
    spec = AIRFOILS[name]
    if spec["file"] is None:
        return naca4_symmetric(spec["t"])
    path = Path(coordinates_dir) / spec["file"]
    if not path.is_file():
        raise SystemExit(f"coordinate file {path} not found; pass --coordinates DIR")
    return np.loadtxt(path, skiprows=1)


# ------------------------------------------------------------------------------ polars (NeuralFoil)


def wave_drag(cl, mach, thickness, kappa):
    """
    Korn-Lock wave drag of an unswept section at lift coefficient ``cl`` and Mach ``mach``.

    M_dd = kappa - t/c - |cl|/10, M_crit = M_dd - (0.1/80)^(1/3) and
    c_d,w = 20 (M - M_crit)^4 for M > M_crit, else 0 (see KORN_KAPPA_CONVENTIONAL). Returns
    (c_d,w, M_dd); broadcasts.
    """
    m_dd = kappa - thickness - np.abs(cl) / 10.0
    excess = np.maximum(mach - (m_dd - LOCK_OFFSET), 0.0)
    return LOCK_COEFFICIENT * excess**4, m_dd


def polar_tables(coords, symmetric, reynolds=REYNOLDS, mach=MACH, thickness=None, kappa=None):
    """
    cl, cd, cm, confidence on ALPHA_DEG x reynolds x mach.

    NeuralFoil is incompressible; Mach enters by Prandtl-Glauert, cl = cl_0/beta and
    cm = cm_0/beta with beta = sqrt(1 - M^2). Without ``kappa`` cd is unchanged (subcritical
    flow, no wave drag); with it cd = cd_0 + the Korn-Lock wave drag (:func:`wave_drag`) at the
    Prandtl-Glauert cl and the section's ``thickness`` ratio.
    """
    import aerosandbox as asb
    import neuralfoil as nf

    airfoil = asb.Airfoil(name="airfoil", coordinates=coords)
    a, r = np.meshgrid(ALPHA_DEG, reynolds, indexing="ij")
    out = nf.get_aero_from_airfoil(
        airfoil, alpha=a.ravel(), Re=r.ravel(), n_crit=N_CRIT, model_size=MODEL_SIZE
    )
    cl, cd, cm, conf = (
        np.reshape(np.asarray(out[k], dtype=float), a.shape)
        for k in ("CL", "CD", "CM", "analysis_confidence")
    )
    if symmetric:  # remove the Kulfan-fit asymmetry: cl, cm odd and cd even in alpha
        cl = 0.5 * (cl - cl[::-1])
        cm = 0.5 * (cm - cm[::-1])
        cd = 0.5 * (cd + cd[::-1])
        conf = 0.5 * (conf + conf[::-1])
    inv_beta = 1.0 / np.sqrt(1.0 - mach**2)
    cl_m = cl[..., None] * inv_beta
    cd_m = cd[..., None] * np.ones_like(mach)
    if kappa is not None:
        cd_m = cd_m + wave_drag(cl_m, mach, thickness, kappa)[0]
    return (
        cl_m,
        cd_m,
        cm[..., None] * inv_beta,
        conf[..., None] * np.ones_like(mach),
    )


# ------------------------------------------------------------------------------ pressure (XFOIL)


def _xfoil_alphas():
    """Return the two sweeps (0 deg up, -0.5 deg down) over the polar's angles, 0.5 deg steps."""
    up = np.arange(0.0, ALPHA_DEG.max() + 1e-9, XFOIL_SUBSTEP)
    down = np.arange(-XFOIL_SUBSTEP, ALPHA_DEG.min() - 1e-9, -XFOIL_SUBSTEP)
    return up, down


class Xfoil:
    """
    An interactive XFOIL process, driven one point at a time.

    Each call sends commands plus an unknown marker command and reads the output up to XFOIL's
    "not recognized" reply, so the script can react to each point (re-initialise the boundary
    layer after a failure, stop a sweep after repeated failures).
    """

    MARK = "ZZMARK"
    REPLY = "ZZMA command not recognized"

    def __init__(self, workdir, display):
        env = dict(os.environ, DISPLAY=display, GFORTRAN_UNBUFFERED_ALL="y")
        self.proc = subprocess.Popen(
            ["xfoil"],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            cwd=workdir,
            env=env,
        )
        self.lines = queue.Queue()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.proc.stdout:
            self.lines.put(line)
        self.lines.put(None)

    def run(self, *commands, timeout=30.0):
        try:
            self.proc.stdin.write("\n".join((*commands, self.MARK)) + "\n")
            self.proc.stdin.flush()
        except OSError:  # XFOIL died (e.g. a floating-point exception at high Mach)
            raise TimeoutError("xfoil exited") from None
        out = []
        deadline = time.monotonic() + timeout
        while True:
            try:
                line = self.lines.get(timeout=max(deadline - time.monotonic(), 1e-3))
            except queue.Empty:
                raise TimeoutError from None
            if line is None:
                raise TimeoutError("xfoil exited")
            if self.REPLY in line:
                return "".join(out)
            out.append(line)

    def close(self):
        try:
            self.proc.stdin.write("\n\n\nQUIT\n")
            self.proc.stdin.flush()
            self.proc.wait(timeout=5)
        except (OSError, subprocess.TimeoutExpired):
            self.proc.kill()
            self.proc.wait()


_RE_CL = re.compile(r"a =\s*(\S+)\s+CL =\s*(\S+)")
_RE_CD = re.compile(r"Cm =\s*(\S+)\s+CD =\s*(\S+)")


def _start(workdir, display, reynolds):
    (workdir / "nodes.txt").unlink(missing_ok=True)  # PSAV would ask before overwriting
    xf = Xfoil(workdir, display)
    xf.run("LOAD airfoil.dat")
    xf.run("PPAR", f"N {XFOIL_PANELS}", "", "")
    xf.run("PSAV nodes.txt")
    xf.run("OPER", f"VISC {reynolds:.6g}", f"ITER {XFOIL_ITER}")
    return xf


def xfoil_session(args):
    """
    XFOIL for one airfoil and Reynolds number over all MACH; return the converged points.

    For each Mach number two sweeps from a fresh boundary layer (0 deg up to the polar's
    largest angle, -0.5 deg down to its smallest) in XFOIL_SUBSTEP steps; a sweep goes on from
    the unconverged state after a failure (as XFOIL's ASEQ does) and stops after 4 failures in
    a row, or when XFOIL dies (then XFOIL is restarted for the next sweep). Every converged
    step keeps (cl, cd, cm); at the whole degrees of CP_ALPHA_DEG and where ``want_cp[k]`` the
    pressure distribution (CPWR) too.
    """
    coords, reynolds, want_cp, workdir, display = args
    workdir = Path(workdir)
    workdir.mkdir(parents=True, exist_ok=True)
    np.savetxt(workdir / "airfoil.dat", coords, header="airfoil", comments="", fmt="%.7f")
    cp_angles = {round(float(a), 2) for a in CP_ALPHA_DEG}
    result = {"mach": {}}
    xf = _start(workdir, display, reynolds)
    result["nodes"] = np.loadtxt(workdir / "nodes.txt")
    for k, mach in enumerate(MACH):
        converged = {}
        for sweep in _xfoil_alphas():
            try:
                xf.run(f"MACH {mach:g}")
                bl_ready = xf.run("INIT")  # INIT toggles XFOIL's flag; make it "initialise"
                if "will be initialized" not in bl_ready:
                    xf.run("INIT")
                failures = 0
                for a in sweep:
                    out = xf.run(f"ALFA {a:.2f}")
                    m_cl, m_cd = _RE_CL.findall(out), _RE_CD.findall(out)
                    ok = (
                        "VISCAL:  Convergence failed" not in out
                        and m_cl
                        and m_cd
                        and np.isfinite(float(m_cd[-1][1]))
                    )
                    if not ok:  # go on from the unconverged state (as XFOIL's ASEQ does)
                        failures += 1
                        if failures >= 4:
                            break
                        continue
                    failures = 0
                    key = round(float(a), 2)
                    cp = None
                    if want_cp[k] and key in cp_angles:
                        name = f"cp_{k}_{key:+06.2f}.txt"
                        xf.run(f"CPWR {name}")
                        cp = np.loadtxt(workdir / name, skiprows=1)[:, -1]
                    converged[key] = (
                        float(m_cl[-1][1]),
                        float(m_cd[-1][1]),
                        float(m_cd[-1][0]),
                        cp,
                    )
            except TimeoutError:
                xf.close()
                xf = _start(workdir, display, reynolds)
        result["mach"][k] = converged
    xf.close()
    return reynolds, result


def run_xfoil(coords, jobs, name, display, cache_dir=None):
    """
    Run the XFOIL sessions of one airfoil (one per REYNOLDS value, ``jobs`` in parallel).

    With ``cache_dir`` the raw results are kept in ``cache_dir/xfoil_<name>.pkl`` and read
    back on a rerun with the same grids and settings (to re-merge without rerunning XFOIL).
    """
    settings = (
        ALPHA_DEG.tolist(),
        REYNOLDS.tolist(),
        MACH.tolist(),
        CP_ALPHA_DEG.tolist(),
        CP_REYNOLDS.tolist(),
        CP_MACH.tolist(),
        XFOIL_PANELS,
        XFOIL_ITER,
        XFOIL_SUBSTEP,
        np.asarray(coords).tolist(),
    )
    cache = None if cache_dir is None else Path(cache_dir) / f"xfoil_{name}.pkl"
    if cache is not None and cache.is_file():
        with open(cache, "rb") as fh:
            stored = pickle.load(fh)
        if stored["settings"] == settings:
            print(f"  {name}: XFOIL results read from {cache}")
            return stored["results"]
    want_cp = np.isin(MACH, CP_MACH)
    with tempfile.TemporaryDirectory(prefix=f"xfoil_{name}_") as tmp:
        tasks = [
            (coords, rey, want_cp & np.isin(rey, CP_REYNOLDS), Path(tmp) / f"re{j}", display)
            for j, rey in enumerate(REYNOLDS)
        ]
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            results = [res for _, res in pool.map(xfoil_session, tasks)]
    if cache is not None:
        cache.parent.mkdir(parents=True, exist_ok=True)
        with open(cache, "wb") as fh:
            pickle.dump({"settings": settings, "results": results}, fh)
    return results


def xfoil_polar_arrays(results):
    """XFOIL cl, cd, cm on ALPHA_DEG x REYNOLDS x MACH (NaN where XFOIL did not converge)."""
    shape = (len(ALPHA_DEG), len(REYNOLDS), len(MACH))
    out = {k: np.full(shape, np.nan) for k in ("cl", "cd", "cm")}
    for j, res in enumerate(results):
        for k, converged in res["mach"].items():
            for i, a in enumerate(ALPHA_DEG):
                point = converged.get(round(float(a), 2))
                if point is not None:
                    out["cl"][i, j, k], out["cd"][i, j, k], out["cm"][i, j, k] = point[:3]
    return out


# ------------------------------------------------------------------------------ polar merge

# XFOIL/NeuralFoil merge of the wing polars: XFOIL is used where it converged, in the attached
# range of each (Re, M) slice and at M <= XFOIL_MACH_MAX, NeuralFoil elsewhere; the weight of
# XFOIL falls from 1 to 0 over XFOIL_BLEND_DEG at each end of the trusted alpha range with the
# C1 smoothstep 3t^2 - 2t^3, so the merged samples carry no jump.
XFOIL_MACH_MAX = 0.5
XFOIL_BLEND_DEG = 2.0
# Isolated XFOIL failures inside a converged sweep (up to this many angles in a row, bounded by
# converged angles on both sides) are filled by PCHIP in alpha through the slice's converged
# points (marked in polar_xfoil_filled); a longer gap ends the trusted range.
XFOIL_MAX_GAP = 2
XFOIL_STALL_WINDOW_DEG = 3.0
XFOIL_SLOPE_FRACTION = 0.5


def fill_xfoil_gaps(xf):
    """
    Fill short non-converged gaps of the XFOIL polar (:data:`XFOIL_MAX_GAP`).

    Returns the filled copy of ``xf`` and the boolean mask of the filled points.
    """
    from scipy.interpolate import PchipInterpolator

    out = {k: v.copy() for k, v in xf.items()}
    filled = np.zeros(xf["cd"].shape, dtype=bool)
    for j in range(xf["cd"].shape[1]):
        for k in range(xf["cd"].shape[2]):
            ok = np.isfinite(xf["cd"][:, j, k]) & np.isfinite(xf["cl"][:, j, k])
            good = np.flatnonzero(ok)
            if good.size < 4:
                continue
            gap = np.zeros(ok.size, dtype=bool)
            for i0, i1 in zip(good[:-1], good[1:], strict=True):
                if 1 < i1 - i0 <= XFOIL_MAX_GAP + 1:
                    gap[i0 + 1 : i1] = True
            if not gap.any():
                continue
            for key in ("cl", "cd", "cm"):
                f = PchipInterpolator(ALPHA_DEG[good], xf[key][good, j, k])
                out[key][gap, j, k] = f(ALPHA_DEG[gap])
            filled[:, j, k] = gap
    return out, filled


def _smoothstep(t):
    t = np.clip(t, 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def xfoil_trusted_range(alpha, cl, ok):
    """
    Return the attached-flow range [a_lo, a_hi] in which one slice's XFOIL polar is trusted.

    The run of consecutive converged (or gap-filled, :func:`fill_xfoil_gaps`) angles that
    contains 0 deg, cut at XFOIL's own stall
    points so that no post-stall XFOIL value (a separated boundary layer, XFOIL's weak spot)
    enters the table: the first angle above 0 deg whose cl is not exceeded within the next
    XFOIL_STALL_WINDOW_DEG, and its mirror image below 0 deg (the rule the run time uses for
    the table's stall points, components/aero/airfoil.py), or earlier where the lift slope
    first falls below XFOIL_SLOPE_FRACTION of its value at 0 deg. None if XFOIL did
    not converge at 0 deg.
    """
    i0 = int(np.argmin(np.abs(alpha)))
    if not ok[i0]:
        return None
    hi = i0
    while hi + 1 < alpha.size and ok[hi + 1]:
        hi += 1
    lo = i0
    while lo - 1 >= 0 and ok[lo - 1]:
        lo -= 1
    step = alpha[1] - alpha[0]
    look = max(int(round(XFOIL_STALL_WINDOW_DEG / step)), 1)
    up = next((i for i in range(i0, hi + 1) if cl[i] >= np.max(cl[i : min(i + look, hi) + 1])), hi)
    down = next(
        (i for i in range(i0, lo - 1, -1) if cl[i] <= np.min(cl[max(i - look, lo) : i + 1])), lo
    )
    # ... and where the lift curve first flattens to XFOIL_SLOPE_FRACTION of its slope at 0 deg
    # (the onset of separation; XFOIL's lift curve can wiggle there, and the runtime stall search
    # and the alpha* inversion need a monotonic cl between the stall points).
    slope = np.diff(cl) / step
    limit = XFOIL_SLOPE_FRACTION * slope[i0 if i0 < slope.size else i0 - 1]
    up = next((i for i in range(i0, up) if slope[i] < limit), up)
    down = next((i for i in range(i0, down, -1) if slope[i - 1] < limit), down)
    return float(alpha[down]), float(alpha[up])


def xfoil_weight(xf):
    """
    Weight of XFOIL (0..1) on ALPHA_DEG x REYNOLDS x MACH, and each slice's trusted range.

    1 inside the trusted range (:func:`xfoil_trusted_range`) shrunk by XFOIL_BLEND_DEG at each
    end, a smoothstep to 0 at the ends of that range, 0 outside it, at M > XFOIL_MACH_MAX and
    where the slice did not converge at 0 deg.
    """
    shape = xf["cd"].shape
    weight = np.zeros(shape)
    ranges = np.full(shape[1:] + (2,), np.nan)
    for j in range(shape[1]):
        for k in range(shape[2]):
            if MACH[k] > XFOIL_MACH_MAX + 1e-9:
                continue
            ok = np.isfinite(xf["cd"][:, j, k])
            band = xfoil_trusted_range(ALPHA_DEG, xf["cl"][:, j, k], ok)
            if band is None:
                continue
            a_lo, a_hi = band
            ranges[j, k] = band
            w = _smoothstep((ALPHA_DEG - a_lo) / XFOIL_BLEND_DEG) * _smoothstep(
                (a_hi - ALPHA_DEG) / XFOIL_BLEND_DEG
            )
            weight[:, j, k] = np.where((ALPHA_DEG >= a_lo) & (ALPHA_DEG <= a_hi), w, 0.0)
    return weight, ranges


def merge_polars(nf, xf, name):
    """
    Merge cl, cd, cm: weight * XFOIL + (1 - weight) * NeuralFoil (see :func:`xfoil_weight`).

    ``nf`` and ``xf`` are dicts of (n_a, n_r, n_m) arrays; returns the merged dict, the weight,
    the trusted ranges, the mask of gap-filled XFOIL points and the gap-filled XFOIL polar.
    cd is blended in log space (positive, and the relative difference
    of the two sources is what varies smoothly).
    """
    xf, filled = fill_xfoil_gaps(xf)
    weight, ranges = xfoil_weight(xf)
    filled &= weight > 0.0
    out = {}
    for key in ("cl", "cd", "cm"):
        x = np.where(weight > 0.0, xf[key], 0.0)
        if key == "cd":
            lx = np.log(np.where(weight > 0.0, xf[key], 1.0))
            out[key] = np.exp(weight * lx + (1.0 - weight) * np.log(nf[key]))
        else:
            out[key] = weight * x + (1.0 - weight) * nf[key]
    full = weight == 1.0
    ratio = xf["cd"][full] / nf["cd"][full]
    print(
        f"  {name}: XFOIL weight 1 at {full.sum()} of {weight.size} polar points, blend at "
        f"{((weight > 0) & ~full).sum()}; cd XFOIL/NeuralFoil there: median "
        f"{np.median(ratio):.3f}, range {ratio.min():.3f}..{ratio.max():.3f}; "
        f"{filled.sum()} XFOIL points gap-filled"
    )
    return out, weight, ranges, filled, xf


def stations(n):
    """Return ``n`` cosine-spaced chordwise stations x/c from 0 to 1."""
    beta = np.linspace(0.0, np.pi, n)
    return 0.5 * (1.0 - np.cos(beta))


def split_surfaces(nodes, values, x_st):
    """Resample node values (XFOIL order: TE, upper, LE, lower, TE) to x stations per surface."""
    from scipy.interpolate import PchipInterpolator

    x, y = nodes[:, 0], nodes[:, 1]
    i_le = int(np.argmin(x))
    x_le, y_le = x[i_le], y[i_le]
    chord = 0.5 * (x[0] + x[-1]) - x_le
    xn, yn = (x - x_le) / chord, (y - y_le) / chord
    out = []
    for idx in (np.arange(i_le, -1, -1), np.arange(i_le, len(x))):
        xs = xn[idx]
        keep = np.concatenate([[True], np.diff(xs) > 1e-9])  # x strictly increasing from the LE
        xs = xs[keep]
        cols = [yn[idx][keep]] + [v[idx][keep] for v in values]
        out.append([PchipInterpolator(xs, c)(np.clip(x_st, xs[0], xs[-1])) for c in cols])
    return out  # [[y_u, v1_u, ...], [y_l, v1_l, ...]]


def integrate_cl(x, y_u, y_l, cp_u, cp_l, alpha_deg):
    """Pressure lift coefficient (trapezoid on the stations; see components/aero/pressure.py)."""
    cn = np.trapezoid(cp_l - cp_u, x, axis=-1)
    ca = np.sum(0.5 * (cp_u[..., 1:] + cp_u[..., :-1]) * np.diff(y_u), axis=-1) - np.sum(
        0.5 * (cp_l[..., 1:] + cp_l[..., :-1]) * np.diff(y_l), axis=-1
    )
    a = np.radians(alpha_deg)
    return cn * np.cos(a) - ca * np.sin(a)


def fill_alpha_gaps(values, ok):
    """Fill non-converged angles along axis 0: linear between neighbours, nearest at the ends."""
    n = values.shape[0]
    idx = np.arange(n)
    good = np.flatnonzero(ok)
    if good.size == 0:
        return None
    flat = values.reshape(n, -1)
    filled = np.empty_like(flat)
    for j in range(flat.shape[1]):
        filled[:, j] = np.interp(idx, good, flat[good, j])
    return filled.reshape(values.shape)


def start_display():
    """Start a private Xvfb server (XFOIL 6.99 needs an X display); return (process, ':N')."""
    proc = subprocess.Popen(
        ["Xvfb", "-displayfd", "1", "-nolisten", "tcp"],
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
    )
    number = proc.stdout.readline().strip()
    if not number:
        proc.kill()
        raise SystemExit("could not start Xvfb")
    return proc, f":{number}"


def pressure_tables(results, name):
    """Pressure tables on the Cp grid from the XFOIL sessions of :func:`run_xfoil`."""
    shape = (len(CP_ALPHA_DEG), len(CP_REYNOLDS), len(CP_MACH))
    x_st = stations(N_X)
    cp_u = np.full(shape + (N_X,), np.nan)
    cp_l = np.full(shape + (N_X,), np.nan)
    conv = np.zeros(shape, dtype=bool)
    xf = {k: np.full(shape, np.nan) for k in ("cl", "cd", "cm")}
    y_u = y_l = None
    for j, rey in enumerate(CP_REYNOLDS):
        res = results[int(np.flatnonzero(np.isclose(REYNOLDS, rey))[0])]
        nodes = res["nodes"]
        for k, mach in enumerate(CP_MACH):
            converged = res["mach"][int(np.flatnonzero(np.isclose(MACH, mach))[0])]
            for i, a in enumerate(CP_ALPHA_DEG):
                key = round(float(a), 2)
                if key not in converged:
                    continue
                cl, cd, cm, cp = converged[key]
                (yu, cpu), (yl, cpl) = split_surfaces(nodes, [cp], x_st)
                y_u, y_l = yu, yl
                cp_u[i, j, k], cp_l[i, j, k] = cpu, cpl
                xf["cl"][i, j, k], xf["cd"][i, j, k], xf["cm"][i, j, k] = cl, cd, cm
                conv[i, j, k] = True
    # Consistency of the resampled Cp with XFOIL's own cl (converged points only).
    cl_int = integrate_cl(x_st, y_u, y_l, cp_u, cp_l, CP_ALPHA_DEG[:, None, None])
    err = np.abs(cl_int - xf["cl"])[conv]
    print(
        f"  {name}: XFOIL converged {conv.sum()}/{conv.size}; |cl(Cp) - cl_xfoil| max "
        f"{err.max():.4f}, mean {err.mean():.5f}"
    )
    for j in range(shape[1]):
        for k in range(shape[2]):
            ok = conv[:, j, k]
            fu, fl = fill_alpha_gaps(cp_u[:, j, k], ok), fill_alpha_gaps(cp_l[:, j, k], ok)
            if fu is None:
                raise SystemExit(
                    f"XFOIL converged nowhere for {name} Re={CP_REYNOLDS[j]:g} M={CP_MACH[k]:g}"
                )
            cp_u[:, j, k], cp_l[:, j, k] = fu, fl
    return dict(
        cp_alpha_deg=CP_ALPHA_DEG,
        cp_reynolds=CP_REYNOLDS,
        cp_mach=CP_MACH,
        x=x_st,
        y_upper=y_u,
        y_lower=y_l,
        cp_upper=cp_u.astype(np.float32),
        cp_lower=cp_l.astype(np.float32),
        cp_converged=conv,
        xfoil_cl=xf["cl"].astype(np.float32),
        xfoil_cd=xf["cd"].astype(np.float32),
        xfoil_cm=xf["cm"].astype(np.float32),
    )


def xfoil_version():
    """Return the XFOIL version text recorded in the files (with the Debian package version)."""
    try:
        out = subprocess.run(
            ["dpkg-query", "-W", "-f=${Version}", "xfoil"],
            capture_output=True,
            text=True,
            check=False,
        ).stdout.strip()
    except OSError:
        out = ""
    return f"XFOIL 6.99 (Debian xfoil {out})" if out else "XFOIL 6.99"


def main(argv=None):
    """Write ``airfoil_<name>.npz`` for the chosen airfoils (polars, then the Cp tables)."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--airfoils", nargs="+", default=list(AIRFOILS), choices=list(AIRFOILS))
    parser.add_argument(
        "--coordinates",
        default=str(DEFAULT_COORDINATES),
        help="folder with the Selig .dat files (default ../shared/data/airfoils)",
    )
    parser.add_argument("--out", default=str(DEFAULT_OUT), help="output folder")
    parser.add_argument("--jobs", type=int, default=2, help="parallel XFOIL processes")
    parser.add_argument(
        "--no-pressure",
        action="store_true",
        help="skip the XFOIL Cp tables (wing files are then written without them)",
    )
    parser.add_argument(
        "--xfoil-cache",
        default=None,
        help="folder for the raw XFOIL results (reused on a rerun with the same settings)",
    )
    args = parser.parse_args(argv)

    try:
        nf_version = metadata.version("neuralfoil")
        asb_version = metadata.version("aerosandbox")
    except metadata.PackageNotFoundError:
        raise SystemExit(
            "neuralfoil is not installed: pip install neuralfoil==0.3.3 (into a "
            "separate venv; lpc_mdo itself does not need it)"
        ) from None
    need_pressure = not args.no_pressure and any(AIRFOILS[n]["pressure"] for n in args.airfoils)
    if need_pressure and not (shutil.which("xfoil") and shutil.which("Xvfb")):
        raise SystemExit(
            "the pressure tables need XFOIL and Xvfb: apt-get install xfoil xvfb "
            "(or pass --no-pressure)"
        )
    out_dir = Path(args.out)
    out_dir.mkdir(parents=True, exist_ok=True)
    stamp = datetime.date.today().isoformat()
    xvfb, display = start_display() if need_pressure else (None, None)
    try:
        for name in args.airfoils:
            make_one(name, args, nf_version, asb_version, stamp, display, out_dir)
    finally:
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()
    return 0


def make_one(name, args, nf_version, asb_version, stamp, display, out_dir):
    """Write airfoil_<name>.npz."""
    spec = AIRFOILS[name]
    t0 = time.process_time()
    w0 = time.time()
    coords = load_coordinates(name, args.coordinates)
    reynolds, mach = spec.get("reynolds", REYNOLDS), spec.get("mach", MACH)
    kappa = spec.get("kappa")
    if spec["pressure"] and (reynolds is not REYNOLDS or mach is not MACH):
        raise SystemExit(f"{name}: the XFOIL merge of a wing table needs the grids REYNOLDS, MACH")
    cl, cd, cm, conf = polar_tables(
        coords, spec["symmetric"], reynolds, mach, thickness=spec.get("t"), kappa=kappa
    )
    compressibility = "Prandtl-Glauert cl/beta and cm/beta, cd unchanged"
    if kappa is not None:
        compressibility = (
            f"Prandtl-Glauert cl/beta and cm/beta, cd plus the Korn-Lock wave drag "
            f"{LOCK_COEFFICIENT:g} (M - M_crit)^4, M_crit = kappa_A - t/c - |cl|/10 - "
            f"(0.1/80)^(1/3), kappa_A = {kappa:g}, t/c = {spec['t']:g}"
        )
    data = dict(
        name=name,
        description=spec["description"],
        alpha_deg=ALPHA_DEG,
        reynolds=reynolds,
        mach=mach,
        cl=cl,
        cd=cd,
        cm=cm,
        confidence=conf.astype(np.float32),
        coordinates=coords,
        source=f"NeuralFoil {nf_version} get_aero_from_airfoil ({MODEL_SIZE}, "
        f"n_crit={N_CRIT:g}, free transition; AeroSandbox {asb_version} Kulfan "
        f"fit), incompressible, {compressibility}; made {stamp} by "
        f"run_scripts/make_airfoil_tables.py",
    )
    msg = f"{name}: polar {time.process_time() - t0:.1f} s CPU"
    if spec["pressure"] and display is not None:
        results = run_xfoil(coords, args.jobs, name, display, args.xfoil_cache)
        data.update(pressure_tables(results, name))
        xf = xfoil_polar_arrays(results)
        merged, weight, ranges, filled, xf = merge_polars(dict(cl=cl, cd=cd, cm=cm), xf, name)
        data.update(merged)
        data.update(
            polar_xfoil_weight=weight.astype(np.float32),
            polar_xfoil_filled=filled,
            polar_xfoil_range_deg=ranges,
            polar_xfoil_cl=xf["cl"].astype(np.float32),
            polar_xfoil_cd=xf["cd"].astype(np.float32),
            polar_xfoil_cm=xf["cm"].astype(np.float32),
            polar_neuralfoil_cl=cl,
            polar_neuralfoil_cd=cd,
            polar_neuralfoil_cm=cm,
        )
        data["source"] = (
            f"{xfoil_version()} (PANE {XFOIL_PANELS} nodes, viscous, n_crit={N_CRIT:g}, "
            f"ITER {XFOIL_ITER}, Karman-Tsien, sweeps from 0 deg in {XFOIL_SUBSTEP} deg steps) "
            f"in each slice's converged attached range at M <= {XFOIL_MACH_MAX:g} "
            f"(polar_xfoil_weight = 1), smoothstep blend over {XFOIL_BLEND_DEG:g} deg at its "
            f"ends (cd in log space); elsewhere (weight 0) " + data["source"]
        )
        data["cp_source"] = (
            f"{xfoil_version()}, PANE {XFOIL_PANELS} nodes, viscous, "
            f"n_crit={N_CRIT:g}, ITER {XFOIL_ITER}, sweeps from 0 deg in "
            f"{XFOIL_SUBSTEP} deg steps; CPWR resampled (PCHIP) to {N_X} "
            f"cosine-spaced stations per surface; made {stamp}"
        )
    path = out_dir / f"airfoil_{name}.npz"
    np.savez_compressed(path, **data)
    print(
        f"{msg}; total {time.time() - w0:.1f} s wall, {time.process_time() - t0:.1f} s "
        f"CPU in this process -> {path} ({path.stat().st_size / 1024:.0f} KiB)"
    )


if __name__ == "__main__":
    sys.exit(main())
