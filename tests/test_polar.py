"""LinearQuadraticPolar.

Reference: docs theory/aerodynamics 'Viterna extrapolation', 'Linear-quadratic polar'.
"""

import numpy as np
import pytest

from lpc_mdo.components.aero.polar import LinearQuadraticPolar, wrap_angle

POLAR = (
    LinearQuadraticPolar()
)  # the reference page's example polar (docs theory/aerodynamics 'Linear-quadratic polar' table)


def values(alpha):
    return POLAR.evaluate(np.asarray(alpha, dtype=float), 1e6, 0.1)


def test_attached_flow_closed_form():
    # docs theory/aerodynamics 'Linear-quadratic polar':
    # cl = cl0 + cl_alpha a, cd = cd0 + k (cl_alpha a)^2 with
    # k = [(0.06 - 0.008)/(0.5 - 1.5)^2 + (0.02 - 0.008)/(0.5 + 1)^2]/2 = 0.028667.
    a = np.radians([-5.0, 0.0, 5.0, 10.0])
    k = 0.5 * (0.052 / 1.0 + 0.012 / 2.25)
    v = values(a)
    np.testing.assert_allclose(v.cl, 0.5 + 5.1566 * a, rtol=1e-14)
    np.testing.assert_allclose(v.cd, 0.008 + k * (5.1566 * a) ** 2, rtol=1e-14)


def test_viterna_closed_form_at_30_and_90_degrees():
    # docs theory/aerodynamics 'Viterna extrapolation' with AR = 10: CD_max = 1.29, A1 = 0.645,
    # B1 = 1.29; positive stall at 15 deg, cl_s = 1.5, cd_s = 0.06.
    s, c = np.sin(np.radians(15.0)), np.cos(np.radians(15.0))
    a2 = (1.5 - 1.29 * s * c) * s / c**2
    b2 = (0.06 - 1.29 * s**2) / c
    a = np.radians(30.0)
    v = values([a, np.pi / 2])
    assert v.cl[0] == pytest.approx(
        0.645 * np.sin(2 * a) + a2 * np.cos(a) ** 2 / np.sin(a), rel=1e-13
    )
    assert v.cd[0] == pytest.approx(1.29 * np.sin(a) ** 2 + b2 * np.cos(a), rel=1e-13)
    assert v.cl[1] == pytest.approx(0.0, abs=1e-14)
    assert v.cd[1] == pytest.approx(1.29, rel=1e-14)


@pytest.mark.parametrize("deg", [-90.0, -11.5, -8.5, 13.5, 16.5, 90.0, 180.0, -180.0])
def test_c1_continuity_at_every_junction(deg):
    """Values and slopes agree on both sides of each law boundary (and across +-180 deg)."""
    h = 1e-9
    a = np.radians(deg)
    left, right = values([a - h]), values([a + h])
    for f in ("cl", "cd"):
        assert getattr(left, f)[0] == pytest.approx(getattr(right, f)[0], abs=1e-7)
    # Slopes 2e-9 rad apart differ by curvature x 2e-9; the negative-stall blend bridges
    # cl -1.0 -> -0.27 over 3 deg, a curvature of order 1e3/rad^2, hence 1e-5.
    for f in ("dcl_dalpha", "dcd_dalpha"):
        assert getattr(left, f)[0] == pytest.approx(getattr(right, f)[0], abs=1e-5)


def test_derivatives_match_complex_step_everywhere():
    a = np.linspace(-2 * np.pi, 2 * np.pi, 2001) + 1e-4  # crosses every region and the wrap
    h = 1e-30
    cs = POLAR.evaluate(a + 1j * h, 1e6, 0.1)
    v = values(a)
    np.testing.assert_allclose(v.dcl_dalpha, cs.cl.imag / h, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(v.dcd_dalpha, cs.cd.imag / h, rtol=1e-10, atol=1e-12)
    assert np.all(v.cd > 0.0)
    assert np.all(np.isfinite(v.cl))


def test_wrap_angle():
    np.testing.assert_allclose(
        wrap_angle(np.array([3 * np.pi / 2, -3 * np.pi / 2, 0.1])),
        [-np.pi / 2, np.pi / 2, 0.1],
        atol=1e-15,
    )


def test_bad_parameters_are_named():
    with pytest.raises(ValueError, match=r"cd0 = -0.1; allowed: > 0"):
        LinearQuadraticPolar(cd0=-0.1)
    with pytest.raises(ValueError, match="alpha_stall"):
        LinearQuadraticPolar(alpha_stall=(0.1, 0.2))
