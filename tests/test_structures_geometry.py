"""Wing-box geometry (lpc_mdo.components.structures.wing_box_geometry)."""

import dataclasses
import pathlib

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.structures.wing_box_geometry import (
    WING_BOX_SECTIONS,
    WingBoxGeometryComp,
    WingBoxSection,
    wing_box_section,
)
from lpc_mdo.vehicle import reference_vehicle

# Selig coordinate files shipped with the tests (UIUC database; see data/airfoils/README.md).
AIRFOILS = pathlib.Path(__file__).parent / "data" / "airfoils"
# The trapezoidal planform this component builds: the reference wing's area, aspect ratio,
# angles and root leading edge with the CADDEE taper ratio 0.2 (docs theory/geometry 'Reference
# vehicle'; the reference vehicle itself now has the cranked NASA wing, planform = "sections").
TRAPEZOID_WING = dataclasses.replace(
    reference_vehicle().wing, planform="trapezoid", sections=None, taper_ratio=0.2
)


def _run(section=WING_BOX_SECTIONS["ls413"], num_nodes=9, **values):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "geometry",
        WingBoxGeometryComp(num_nodes=num_nodes, section=section, wing=TRAPEZOID_WING),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    for name, val in values.items():
        prob.set_val(name, val)
    prob.run_model()
    return prob


def test_reference_planform():
    # Reference docs theory/geometry 'Reference vehicle': b = sqrt(12.12 * 19.6) = 15.41 m,
    # c_root = 2.119 m, c_tip = 0.424 m.
    # Default inputs are the reference vehicle's wing; 9 nodes = 8 equal bays
    # (docs theory/structures 'Material, mesh and load transfer').
    prob = _run()
    nodes, chord = prob.get_val("nodes"), prob.get_val("chord")
    assert_near_equal(nodes[-1, 1] - nodes[0, 1], 15.4127220 / 2, 1e-7)
    assert_near_equal(np.diff(nodes[:, 1]), np.full(8, 15.4127220 / 16), 1e-7)
    assert_near_equal(chord[[0, -1]], [2.1194612, 0.4238922], 1e-7)
    # Node at 50 % chord and mid-height of the LS(1)-0413 section (camber line 0.02075 c at
    # x/c = 0.5 from the UIUC table: upper 0.0829, lower -0.0414), pitched by the incidence
    # 2.04 deg: x = x_LE - c (0.5 cos i + 0.02075 sin i), z = z_LE + c (0.5 sin i - 0.02075 cos i)
    inc = np.radians(2.04)
    c0 = 2.1194612
    assert_near_equal(
        nodes[0],
        [
            -1.95925 - c0 * (0.5 * np.cos(inc) + 0.02075 * np.sin(inc)),
            0.0,
            -1.0729 + c0 * (0.5 * np.sin(inc) - 0.02075 * np.cos(inc)),
        ],
        1e-7,
    )
    # Leading-edge sweep 7.81 deg and dihedral -2 deg move the tip aft and down.
    tip_le_x = -1.95925 - 15.412722 / 2 * np.tan(np.radians(7.81))
    tip = 0.4238922
    assert_near_equal(
        nodes[-1, 0], tip_le_x - tip * (0.5 * np.cos(inc) + 0.02075 * np.sin(inc)), 1e-7
    )
    assert nodes[-1, 2] > nodes[0, 2]
    # Box per bay from the mean chord: width 0.5 c̄ (spars 25 %/75 %), height 0.1243 c̄
    # (LS(1)-0413 thickness at 50 % chord, 0.124 c in the airfoil README).
    mean = 0.5 * (chord[:-1] + chord[1:])
    assert_near_equal(prob.get_val("box_width"), 0.5 * mean, 1e-14)
    assert_near_equal(prob.get_val("box_height"), 0.1243 * mean, 1e-14)
    assert_near_equal(prob.get_val("top_skin_radius"), 1.9089296 * mean, 1e-7)


def test_arc_radius_of_a_circle():
    # Skin points on a circle of radius R = 2 (centre below the chord): the three-point arc
    # radius is exactly R; a straight skin gives an infinite radius.
    x = np.linspace(0.0, 1.0, 41)
    upper = 0.1 + np.sqrt(4.0 - (x - 0.5) ** 2) - np.sqrt(4.0 - 0.25)
    lower = -0.05 * np.ones_like(x)
    coords = np.vstack([np.column_stack([x, upper])[::-1], np.column_stack([x, lower])[1:]])
    sec = WingBoxSection.from_coordinates(coords)
    assert_near_equal(sec.top_radius, 2.0, 1e-12)
    assert sec.bottom_radius == np.inf
    assert_near_equal(sec.thickness, upper[20] + 0.05, 1e-12)


@pytest.mark.parametrize("name, file", [("ls413", "ls413_gaw2.dat"), ("ls417", "ls417_gaw1.dat")])
def test_packaged_sections_match_the_coordinate_files(name, file):
    # The packaged numbers were produced with WingBoxSection.from_file (exact to print).
    sec = WingBoxSection.from_file(AIRFOILS / file)
    ref = WING_BOX_SECTIONS[name]
    for field in ("thickness", "camber", "top_radius", "bottom_radius"):
        assert_near_equal(getattr(sec, field), getattr(ref, field), 1e-12)


def test_section_from_vehicle():
    vehicle = reference_vehicle()
    assert wing_box_section(vehicle) is WING_BOX_SECTIONS[vehicle.wing.airfoil]
    moved = dataclasses.replace(
        vehicle, wing_box=dataclasses.replace(vehicle.wing_box, front_spar=0.2)
    )
    with pytest.raises(ValueError, match="front_spar=0.2"):
        wing_box_section(moved)
    coords = np.loadtxt(AIRFOILS / "ls413_gaw2.dat", skiprows=1)
    assert wing_box_section(moved, coords).front_spar == 0.2


def test_partials():
    prob = _run(
        num_nodes=5, wing_sweep=0.2, wing_dihedral=0.05, wing_incidence=0.04, wing_taper_ratio=0.35
    )
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-10)


def test_bad_inputs():
    with pytest.raises(
        om.AnalysisError,
        match=r"'wing_area\[0\]' = -1.0 is out of range: "
        r"must be > 0 \(m\*\*2\)",
    ):
        _run(wing_area=-1.0)
    with pytest.raises(
        ValueError,
        match=r"'front_spar' = 0.6"
        r" is out of range: must be in \(0, beam_axis",
    ):
        WingBoxSection.from_coordinates(np.zeros((10, 2)), front_spar=0.6)
