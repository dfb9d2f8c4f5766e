"""Tests for lpc_mdo.components.geometry.blade (stations, chord and twist B-splines)."""

from math import comb

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_check_totals

from lpc_mdo.components.geometry.blade import (
    BladeGeometryGroup,
    BladeStationsComp,
    azimuth_angles,
    per_rotor,
    station_fractions,
)

RADII = np.array([1.524, 1.37])
HUB = [0.2, 0.15]
CHORD_CP = np.array([[0.3, 0.25, 0.18, 0.1], [0.25, 0.3, 0.2, 0.08]])
TWIST_CP = np.radians([[30.0, 22.0, 15.0, 10.0], [60.0, 45.0, 35.0, 25.0]])


def _geometry(num_radial=7, **options):
    prob = om.Problem()
    prob.model.add_subsystem(
        "blade",
        BladeGeometryGroup(num_rotors=2, num_radial=num_radial, hub_radius_ratio=HUB, **options),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("radius", RADII)
    prob.set_val("chord_cp", CHORD_CP)
    prob.set_val("twist_cp", TWIST_CP)
    prob.run_model()
    return prob


def _bernstein(cp, t):
    """
    Cubic Bezier in closed Bernstein form (docs theory/rotors 'Blade parameterization').

    One row per curve.
    """
    basis = np.stack([comb(3, i) * t**i * (1.0 - t) ** (3 - i) for i in range(4)], axis=-1)
    return cp @ basis.T


@pytest.mark.parametrize("quadrature", ["midpoint", "bladead"])
def test_stations_partials_and_values(quadrature):
    prob = om.Problem()
    prob.model.add_subsystem(
        "stations",
        BladeStationsComp(
            num_rotors=2, num_radial=5, num_azimuth=4, hub_radius_ratio=HUB, quadrature=quadrature
        ),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("radius", RADII)
    prob.run_model()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)

    # Independent numbers (docs theory/rotors 'Stations and disk frame'):
    # element centres r_i = r_h + (R - r_h)(i + 1/2)/N and the widths of both quadratures sum to the
    # blade length R - r_h; 1e-12 absolute.
    rh = np.array(HUB) * RADII
    centres = rh[:, None] + (RADII - rh)[:, None] * (np.arange(5) + 0.5) / 5
    np.testing.assert_allclose(prob.get_val("hub_radius"), rh, atol=1e-12)
    np.testing.assert_allclose(prob.get_val("station_radius"), centres, atol=1e-12)
    np.testing.assert_allclose(prob.get_val("station_width").sum(axis=1), RADII - rh, atol=1e-12)
    width = prob.get_val("station_width")
    if quadrature == "midpoint":
        np.testing.assert_allclose(width, np.repeat(((RADII - rh) / 5)[:, None], 5, 1), atol=1e-12)
    else:
        # public code (docs theory/rotors 'Public-code compatibility'): dr = (R - r_h)/(N - 1),
        # end elements halved
        np.testing.assert_allclose(
            width[:, 1:-1], np.repeat(((RADII - rh) / 4)[:, None], 3, 1), atol=1e-12
        )
        np.testing.assert_allclose(width[:, 0], 0.5 * (RADII - rh) / 4, atol=1e-12)
    # Azimuth psi_k = 2 pi k / N_psi (docs theory/rotors 'Stations and disk frame'): 0, 90, 180,
    # 270 deg.
    np.testing.assert_allclose(
        prob.get_val("azimuth", units="deg"), [0.0, 90.0, 180.0, 270.0], atol=1e-12
    )


def test_geometry_as_coded_mapping():
    # Reference docs theory/rotors 'Blade parameterization': value i of the spline,
    # evaluated at t = i/(N - 1), goes to station i; the closed Bernstein form is the independent
    # reference (1e-12 absolute).
    prob = _geometry()
    t = np.linspace(0.0, 1.0, 7)
    np.testing.assert_allclose(prob.get_val("chord"), _bernstein(CHORD_CP, t), atol=1e-12)
    np.testing.assert_allclose(prob.get_val("twist"), _bernstein(TWIST_CP, t), atol=1e-12)
    # Linearly spaced control points give an exactly linear profile from cp_0 to cp_3.
    prob.set_val("chord_cp", np.tile(np.linspace(0.3, 0.1, 4), (2, 1)))
    prob.run_model()
    np.testing.assert_allclose(
        prob.get_val("chord"), np.tile(np.linspace(0.3, 0.1, 7), (2, 1)), atol=1e-12
    )


def test_geometry_element_centre_mapping():
    prob = _geometry(spline_stations="element_centres")
    t = (np.arange(7) + 0.5) / 7  # normalized element centres (r_i - r_h)/(R - r_h)
    np.testing.assert_allclose(prob.get_val("chord"), _bernstein(CHORD_CP, t), atol=1e-12)


def test_geometry_partials_and_totals():
    prob = _geometry()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)
    totals = prob.check_totals(
        of=["chord", "twist", "station_radius", "station_width"],
        wrt=["radius", "chord_cp", "twist_cp"],
        method="cs",
        compact_print=True,
        out_stream=None,
    )
    assert_check_totals(totals, atol=1e-12, rtol=1e-12)


def test_helpers():
    eta, q = station_fractions(4)
    np.testing.assert_allclose(eta, [0.125, 0.375, 0.625, 0.875])
    np.testing.assert_allclose(q, 0.25)
    np.testing.assert_allclose(azimuth_angles(3), [0.0, 2 * np.pi / 3, 4 * np.pi / 3])
    np.testing.assert_array_equal(per_rotor(2, 3, "num_blades", kind=int, lower=1), [2, 2, 2])


def test_bad_options_and_inputs():
    with pytest.raises(
        ValueError,
        match=r"'hub_radius_ratio\[1\]' = 1.0 is out of range: "
        r"must be in \[0, 1\)",
    ):
        prob = om.Problem()
        prob.model.add_subsystem("s", BladeStationsComp(num_rotors=2, hub_radius_ratio=[0.2, 1.0]))
        prob.setup()
    with pytest.raises(ValueError, match="num_blades' = .* must be a scalar or have"):
        per_rotor([2, 3], 3, "num_blades", kind=int)
    with pytest.raises(ValueError, match=r"'num_blades\[0\]' must be an integer, got float 2.5"):
        per_rotor(2.5, 1, "num_blades", kind=int)
    with pytest.raises(
        ValueError,
        match=r"'num_radial' = 1"
        r" is out of range: must be >= 2 \(quadrature",
    ):
        station_fractions(1, "bladead")
    prob = om.Problem()
    prob.model.add_subsystem("s", BladeStationsComp(num_rotors=2), promotes=["*"])
    prob.setup()
    prob.set_val("radius", [1.0, -1.0])
    with pytest.raises(om.AnalysisError, match=r"radius = \[1.0, -1.0\] m; allowed range"):
        prob.run_model()
