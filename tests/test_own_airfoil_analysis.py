"""A vehicle whose wing section is the designer's own polar and coordinate files trims and sizes."""

import copy
import math
from pathlib import Path

import pytest

from lpc_mdo.analysis import analyze_vehicle
from lpc_mdo.components.aero.airfoil import get_polar, zero_lift_angle
from lpc_mdo.vehicle import read_vehicle_file, vehicle_from_dict

#: Builds or runs the full model: the integration tier (README, 'Run the tests').
pytestmark = pytest.mark.integration

DATA = Path(__file__).parent / "data" / "airfoils"
POLAR = DATA / "naca4412_re5e6.pol"


def _vehicle(**wing):
    data = copy.deepcopy(read_vehicle_file())
    data["wing"].update(wing)
    return vehicle_from_dict(data)


def test_polar_file_wing_trims_and_reaches_the_model():
    # The wing-borne conditions the section enters: its camber (cruise) and its box (-1 g).
    # (The whole vehicle trims all 15 conditions: docs user guide 'Your own airfoils'.)
    own = _vehicle(airfoil=str(POLAR), coordinates=str(DATA / "naca4412.dat"))
    analysis = analyze_vehicle(own, conditions=["cruise", "minus_1g"])
    assert analysis.failed == {}, analysis.failed
    prob = analysis.prob
    # the wing lattice's camber is the polar's zero-lift angle (NACA 4412: -4.3 deg at Re 5e6)
    alpha0 = prob.get_val("cruise.wing_zero_lift_angle")
    expected = zero_lift_angle(get_polar(POLAR), 5e6, 0.0)
    assert alpha0 == pytest.approx(expected, abs=1e-12)
    assert math.degrees(expected) == pytest.approx(-4.3, abs=0.1)
    # The wing box is the 4412's: its nearly flat lower surface gives the -1 g compression
    # skin little curvature, so at the reference's skins (sized to a buckling ratio of 1.0 on
    # the LS(1)-0413, docs theory/structures) the bottom skin buckles far beyond its limit.
    bottom = prob.get_val("minus_1g.bottom_skin_buckling_ratio")
    assert bottom.max() > 3.0
