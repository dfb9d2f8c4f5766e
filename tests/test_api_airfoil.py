"""lpc_mdo.api.airfoil_polar against the shipped tables and thin-airfoil theory."""

import math
from importlib import resources

import numpy as np
import pytest

import lpc_mdo.api as lpc


@pytest.mark.parametrize("name", ["naca0012", "ls413"])
def test_table_grid_points_are_returned(name):
    # At a node of the shipped table (alpha on its 0.5 deg grid, Re and Mach on their nodes,
    # inside the attached range) the interpolant returns the table itself.
    path = resources.files("lpc_mdo") / "data" / f"airfoil_{name}.npz"
    with np.load(str(path)) as table:
        ia = [44, 50, 58, 66]  # -3, 0, 4, 8 deg
        ir, im = 4, 2
        alpha = table["alpha_deg"][ia]
        out = lpc.airfoil_polar(name, alpha, table["reynolds"][ir], table["mach"][im])
        for key in ("cl", "cd", "cm"):
            np.testing.assert_allclose(out[key], table[key][ia, ir, im], rtol=1e-9, atol=1e-12)
        assert out["cm_alpha_range_deg"] == (-25.0, 25.0)


def test_naca0012_thin_airfoil_lift_slope():
    # Thin-airfoil theory: dcl/dalpha = 2 pi per rad, cl(0) = 0 for a symmetric section.
    # Acceptance 10 %. Measured at Re 3e6: 6.45 /rad (+2.7 %).
    out = lpc.airfoil_polar("naca0012", [-1.0, 0.0, 1.0], reynolds=3e6)
    slope = (out["cl"][2] - out["cl"][0]) / math.radians(2.0)
    assert slope == pytest.approx(2.0 * math.pi, rel=0.10)
    assert out["dcl_dalpha"][1] == pytest.approx(2.0 * math.pi, rel=0.10)
    assert abs(out["cl"][1]) < 1e-12
    assert out["cd"][1] > 0.0


def test_degrees_in_and_shapes():
    # alpha in degrees: the value at 4 deg is the polar's value at 4 pi/180 rad.
    from lpc_mdo.components.aero.airfoil import get_polar

    ref = get_polar("ls413").evaluate(np.radians(4.0), 2e6, 0.1)
    out = lpc.airfoil_polar("ls413", 4.0, 2e6, 0.1)
    assert isinstance(out["cl"], float) and isinstance(out["cm"], float)
    assert out["cl"] == pytest.approx(float(ref.cl), rel=1e-14)
    assert out["cd"] == pytest.approx(float(ref.cd), rel=1e-14)
    grid = lpc.airfoil_polar("ls413", np.zeros((2, 3)), 2e6)
    assert grid["cl"].shape == grid["cm"].shape == (2, 3)


def test_cm_outside_its_table_and_without_a_table():
    # Post stall there is no moment model: cm is NaN outside the table's angles; a user table
    # of alpha, cl, cd has no cm at all (None).
    out = lpc.airfoil_polar("naca0012", [10.0, 40.0], 1e6)
    assert np.isfinite(out["cm"][0]) and np.isnan(out["cm"][1])
    assert np.isfinite(out["cl"][1])  # Viterna
    alpha = np.arange(-20.0, 20.5, 1.0)
    cl = 0.1 * np.clip(alpha, -12.0, 12.0) - 0.002 * np.clip(alpha, -12, 12) ** 3 / 12.0
    cl = np.where(np.abs(alpha) > 12.0, np.sign(alpha) * 0.9, cl)
    table = np.column_stack([alpha, cl, 0.01 + 0.0005 * alpha**2])
    user = lpc.airfoil_polar(table, [0.0, 5.0], 1e6)
    assert user["cm"] is None and user["cm_alpha_range_deg"] is None
    assert user["cl"][1] == pytest.approx(np.interp(5.0, alpha, cl), rel=1e-3)


@pytest.mark.parametrize(
    "args, match",
    [
        (("naca0012", 200.0, 1e6), r"'alpha_deg' = 200.0 is out of range: must be in \[-180, 1"),
        (("naca0012", [0.0, np.nan], 1e6), r"'alpha_deg\[1\]' = nan is out of range"),
        (("naca0012", 0.0, -5.0), r"'reynolds' = -5.0 is out of range: must be in \[1e3, 1e9\]"),
        (("naca0012", 0.0, 1e6, 1.2), r"'mach' = 1.2 is out of range: must be in \[0, 1\)"),
        (("naca9999", 0.0, 1e6), r"airfoil_polar: 'airfoil': airfoil = 'naca9999'; allowed"),
    ],
)
def test_bad_arguments_are_named_errors(args, match):
    with pytest.raises(ValueError, match=match):
        lpc.airfoil_polar(*args)
