"""The wing-section polars: XFOIL where it converged, NeuralFoil elsewhere, a C1 blend between.

Reference: docs theory/aerodynamics 'Airfoil polars' (Sources of the wing-section polars) and
lpc_mdo/data/README.md; the merge is ``merge_polars`` in run_scripts/make_airfoil_tables.py.
"""

import numpy as np
import pytest

from lpc_mdo.components.aero.airfoil import airfoil_table_path, get_polar

WING = ("ls413", "ls417")
XFOIL_MACH_MAX = 0.5  # run_scripts/make_airfoil_tables.py
XFOIL_BLEND_DEG = 2.0

# Independent XFOIL 6.99 runs (Debian xfoil 6.99.dfsg+1-3), one interactive session per row
# outside the table script: LOAD the Selig file of shared/data/airfoils, PPAR N 240, OPER, VISC
# Re, MACH M, ITER 200, PACC, then ALFA 0 2 4, INIT, ALFA 0 -1 -2 -3 -3.5 -4.5 -5.5 -6.5 -7.5
# (n_crit 9, free transition), run 2026-12-03. Columns: airfoil, Re, M, alpha [deg], cl, cd, cm.
XFOIL_REFERENCE = [
    ("ls413", 1e6, 0.0, 0.0, 0.5168, 0.00606, -0.1157),
    ("ls413", 1e6, 0.0, 2.0, 0.7477, 0.00664, -0.1171),
    ("ls413", 1e6, 0.0, 4.0, 0.9418, 0.01074, -0.1130),
    ("ls413", 1e6, 0.0, -2.0, 0.2800, 0.00582, -0.1135),
    ("ls413", 1e6, 0.0, -3.5, 0.0873, 0.00761, -0.1062),
    ("ls413", 1e6, 0.0, -5.5, -0.1581, 0.00968, -0.0998),
    ("ls413", 1e6, 0.0, -7.5, -0.3924, 0.01239, -0.0953),
    ("ls417", 1e6, 0.0, 0.0, 0.5363, 0.00693, -0.1186),
    ("ls417", 1e6, 0.0, 4.0, 0.9728, 0.01060, -0.1182),
    ("ls417", 1e6, 0.0, -3.5, 0.1030, 0.00667, -0.1102),
    ("ls417", 1e6, 0.0, -7.5, -0.4071, 0.01228, -0.0896),
    ("ls413", 3e6, 0.2, 0.0, 0.5361, 0.00465, -0.1199),
    ("ls413", 3e6, 0.2, 2.0, 0.7597, 0.00731, -0.1197),
    ("ls413", 3e6, 0.2, -3.5, 0.0893, 0.00651, -0.1079),
    ("ls413", 3e6, 0.2, -7.5, -0.4109, 0.00897, -0.0983),
]


def _data(name):
    with np.load(airfoil_table_path(name)) as d:
        return {k: d[k] for k in d.files}


@pytest.mark.parametrize("row", XFOIL_REFERENCE, ids=lambda r: f"{r[0]}-{r[1]:g}-{r[2]:g}-{r[3]:g}")
def test_packaged_wing_polar_matches_independent_xfoil_runs(row):
    """At converged attached points the shipped polar is XFOIL's: cd within 3 %, cl 0.01, cm 0.005.

    The table comes from XFOIL sweeps in 0.5 deg steps with ITER 80 (the table script), the
    reference from separate single-point sessions with ITER 200, so the tolerance covers the
    sweep history of XFOIL's boundary-layer solution only. Before the merge the NeuralFoil table
    gave cd 0.00681 at ls413, Re 1e6, -3.5 deg (-10.5 %) and 0.01108 at -7.5 deg (-10.6 %).
    """
    name, re, mach, alpha_deg, cl, cd, cm = row
    polar = get_polar(name)
    a = np.radians(alpha_deg)
    v = polar.evaluate(np.array([a]), re, mach)
    assert v.cd[0] == pytest.approx(cd, rel=0.03)
    assert v.cl[0] == pytest.approx(cl, abs=0.01)
    assert polar.moment_coefficient(np.array([a]), re, mach)[0][0] == pytest.approx(cm, abs=0.005)


@pytest.mark.parametrize("name", WING)
def test_source_weight_is_consistent_with_the_stored_sources(name):
    """cl, cd, cm are exactly the weight's blend of the stored XFOIL and NeuralFoil polars."""
    d = _data(name)
    w = d["polar_xfoil_weight"].astype(float)
    assert w.shape == d["cd"].shape
    assert np.all((w >= 0.0) & (w <= 1.0))
    xf = {k: d[f"polar_xfoil_{k}"].astype(float) for k in ("cl", "cd", "cm")}
    nf = {k: d[f"polar_neuralfoil_{k}"] for k in ("cl", "cd", "cm")}
    # XFOIL is used only where it converged and at M <= 0.5.
    assert np.all(np.isfinite(xf["cd"][w > 0]))
    assert np.all(w[:, :, d["mach"] > XFOIL_MACH_MAX + 1e-9] == 0.0)
    # A substantial part of the table is XFOIL, in the attached range around 0 deg.
    assert (w == 1.0).sum() > 0.2 * w.size
    for key in ("cl", "cm"):
        merged = w * np.where(w > 0, xf[key], 0.0) + (1 - w) * nf[key]
        np.testing.assert_allclose(d[key], merged, rtol=1e-6, atol=1e-6)
    log_cd = w * np.log(np.where(w > 0, xf["cd"], 1.0)) + (1 - w) * np.log(nf["cd"])
    np.testing.assert_allclose(np.log(d["cd"]), log_cd, rtol=0, atol=1e-6)
    # The weight follows the stored trusted range: 1 inside it shrunk by the blend width, 0
    # outside, a smoothstep between.
    alpha = d["alpha_deg"]
    for j in range(d["reynolds"].size):
        for k in range(d["mach"].size):
            a_lo, a_hi = d["polar_xfoil_range_deg"][j, k]
            if np.isnan(a_lo):
                assert np.all(w[:, j, k] == 0.0)
                continue
            assert a_lo < 0.0 < a_hi
            inner = (alpha >= a_lo + XFOIL_BLEND_DEG) & (alpha <= a_hi - XFOIL_BLEND_DEG)
            outer = (alpha <= a_lo) | (alpha >= a_hi)
            assert np.all(w[inner, j, k] == 1.0)
            assert np.all(w[outer, j, k] == 0.0)
            ramp = ~inner & ~outer
            assert np.all((w[ramp, j, k] > 0.0) & (w[ramp, j, k] < 1.0))


@pytest.mark.parametrize("name", WING)
def test_polar_is_c1_across_the_blend_ends(name):
    """Values and alpha slopes of the run-time polar are continuous at both ends of every blend.

    At each slice's blend ends (a_lo, a_lo + 2 deg, a_hi - 2 deg, a_hi) the left and right
    limits (2e-9 rad apart) of cl, cd and their exact alpha derivatives agree (that the exact
    derivatives are those of the values is tests/test_airfoil.py's complex-step check).
    """
    d = _data(name)
    polar = get_polar(name)
    h = 1e-9
    for j, re in enumerate(d["reynolds"]):
        for k, mach in enumerate(d["mach"]):
            a_lo, a_hi = d["polar_xfoil_range_deg"][j, k]
            if np.isnan(a_lo):
                continue
            ends = np.radians([a_lo, a_lo + XFOIL_BLEND_DEG, a_hi - XFOIL_BLEND_DEG, a_hi])
            left = polar.evaluate(ends - h, re, mach)
            right = polar.evaluate(ends + h, re, mach)
            np.testing.assert_allclose(left.cd, right.cd, rtol=1e-5)
            np.testing.assert_allclose(left.cl, right.cl, rtol=0, atol=1e-5)
            np.testing.assert_allclose(left.dcd_dalpha, right.dcd_dalpha, rtol=0, atol=1e-5)
            np.testing.assert_allclose(left.dcl_dalpha, right.dcl_dalpha, rtol=0, atol=1e-5)


@pytest.mark.parametrize("name", WING)
def test_blend_adds_no_kink_beyond_the_sources(name):
    """In the blend zones the merged cd's discrete curvature stays within the sources' own.

    |second difference of merged cd| <= |that of NeuralFoil| + |that of XFOIL| + the jump term
    of the smoothstep (|cd_X - cd_N| * max|second difference of w|, plus the cross term), with
    50 % margin for the log-space blend: the blend adds no corner of its own.
    """
    d = _data(name)
    w = d["polar_xfoil_weight"].astype(float)
    xf = d["polar_xfoil_cd"].astype(float)
    nf = d["polar_neuralfoil_cd"]
    ratio_max = 0.0
    for j in range(w.shape[1]):
        for k in range(w.shape[2]):
            ramp = np.flatnonzero((w[:, j, k] > 0) & (w[:, j, k] < 1))
            if ramp.size == 0:
                continue
            i = ramp[(ramp > 0) & (ramp < w.shape[0] - 1)]
            m = d["cd"][:, j, k]
            d2 = np.abs(m[i + 1] - 2 * m[i] + m[i - 1])
            xfj = np.where(np.isfinite(xf[:, j, k]), xf[:, j, k], nf[:, j, k])
            d2n = np.abs(nf[i + 1, j, k] - 2 * nf[i, j, k] + nf[i - 1, j, k])
            d2x = np.abs(xfj[i + 1] - 2 * xfj[i] + xfj[i - 1])
            jump = np.abs(xfj[i] - nf[i, j, k])
            # smoothstep over 2 deg in 0.5 deg steps: |second difference of w| <= 6 (0.25)^2
            bound = (
                d2n
                + d2x
                + jump * 6 * 0.25**2
                + 2 * 0.375 * np.abs(np.diff(xfj - nf[:, j, k])[i - 1])
            )
            ratio_max = max(ratio_max, float(np.max(d2 / (bound + 1e-12))))
    assert ratio_max <= 1.5
