"""Airfoil coordinate files and the section numbers taken from them."""

import math
import re
from pathlib import Path

import numpy as np
import pytest

from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.components.aero.airfoil_coordinates import (
    airfoil_shape,
    naca_four_digit,
    read_coordinates,
)

DATA = Path(__file__).parent / "data" / "airfoils"


def test_naca_4412_thickness_position_and_zero_lift_angle():
    # Sources: Abbott & von Doenhoff, Theory of Wing Sections (1959), sec. 6.4 (NACA four-digit
    # sections: t/c = the last two digits, maximum thickness at 30 % chord, camber m = 4 % at
    # p = 40 %); Anderson, Fundamentals of Aerodynamics, 6th ed., Example 4.6: thin-airfoil
    # alpha_L0 of the NACA 4412 camber line -4.15 deg. Tolerance 0.1 deg: the camber line here
    # is the mean of the two surfaces at one x/c, which for a section whose surfaces are offset
    # normal to the camber line differs from it by O(t x slope^2) (measured: -4.23 deg).
    shape = airfoil_shape(naca_four_digit("4412", 121), "NACA 4412")
    assert shape.thickness_to_chord == pytest.approx(0.12, abs=5e-4)
    assert shape.max_thickness_location == pytest.approx(0.30, abs=0.01)
    assert shape.max_camber == pytest.approx(0.04, abs=5e-4)
    assert math.degrees(shape.zero_lift_angle) == pytest.approx(-4.15, abs=0.1)


def test_symmetric_section_has_no_camber_and_zero_lift_at_zero_angle():
    shape = airfoil_shape(naca_four_digit("0015"), "NACA 0015")
    assert shape.max_camber == 0.0 and shape.zero_lift_angle == 0.0
    assert shape.thickness_to_chord == pytest.approx(0.15, abs=5e-4)


def test_shipped_coordinate_file_reads_the_uiuc_table():
    # UIUC ls413.dat (tests/data/airfoils/README.md): its largest thickness, at a table point,
    # is 0.1293 (x/c 0.375); the packaged airfoil lists the nominal 0.13.
    shape = read_coordinates(DATA / "ls413_gaw2.dat")
    assert shape.name.startswith("coordinate file") and "LS(1)-0413" in shape.name
    assert shape.thickness_to_chord == pytest.approx(0.1293, abs=2e-4)
    assert 0.35 < shape.max_thickness_location < 0.40


def test_coordinates_agree_with_their_polar():
    # The shipped LS(1)-0413 table (XFOIL/NeuralFoil) against thin-airfoil theory on its
    # coordinates: viscous decambering makes |alpha_L0| smaller, here by 0.3 deg (the vehicle
    # check allows 1.5 deg, lpc_mdo.vehicle.sections).
    from lpc_mdo.components.aero.airfoil import zero_lift_angle

    thin = math.degrees(read_coordinates(DATA / "ls413_gaw2.dat").zero_lift_angle)
    table = math.degrees(zero_lift_angle(get_polar("ls413"), 5e6, 0.0))
    assert -4.6 < thin < table < -4.0


def _write(tmp_path, text, name="section.dat"):
    path = tmp_path / name
    path.write_text(text, "utf-8")
    return path


def _selig(coords, name="SECTION"):
    return name + "\n" + "\n".join(f"{x:.6f} {y:.6f}" for x, y in coords) + "\n"


@pytest.mark.parametrize(
    "text, message",
    [
        ("NACA 4412\n81 81\n" + "0.0 0.0\n" * 30, "point counts"),  # Lednicer
        ("X\n" + "0 0\n" * 5, "points of (x/c, y/c); allowed: 20 to 2000"),
        ("X\n1 0 0\n" * 1 + "0 0\n" * 30, "holds 3 numbers"),
        ("X\nfoo bar\n" + "0 0\n" * 30, "is not a pair of numbers"),
    ],
    ids=["lednicer", "few points", "three columns", "words"],
)
def test_bad_coordinate_files_name_the_file_and_the_problem(tmp_path, text, message):
    path = _write(tmp_path, text)
    with pytest.raises(ValueError, match=re.escape(message)) as info:
        read_coordinates(path)
    assert str(path) in str(info.value)


def test_coordinates_in_millimetres_or_upside_down_are_refused(tmp_path):
    coords = naca_four_digit("4412")
    with pytest.raises(ValueError, match="normalised to a unit chord"):
        read_coordinates(_write(tmp_path, _selig(coords * 1000.0)))
    flipped = coords * np.array([1.0, -1.0])  # lower surface first
    with pytest.raises(ValueError, match="upper surface lies below the lower one"):
        read_coordinates(_write(tmp_path, _selig(flipped)))
    folded = coords.copy()
    folded[[5, 6]] = folded[[6, 5]]
    with pytest.raises(ValueError, match="not monotonic"):
        read_coordinates(_write(tmp_path, _selig(folded)))
    with pytest.raises(ValueError, match="binary"):
        read_coordinates(_write(tmp_path, "X\n\0\0"))


XFOIL_HEADER = """ Calculated polar for: SECTION

 Mach =   0.000     Re =     5.000 e 6     Ncrit =   9.000

  alpha    CL        CD       CDp       CM     Top_Xtr  Bot_Xtr
 ------ -------- --------- --------- -------- -------- --------
"""


def _xfoil_rows(alpha, cm=lambda a: -0.1 + 0.001 * a):
    return "".join(
        f"{a:7.3f} {0.4 + 0.1 * a:8.4f} {0.006 + 1e-4 * a**2:9.5f} 0.00300 {cm(a):8.4f} 0.5 0.5\n"
        for a in alpha
    )


def test_xfoil_polar_file_gives_its_moment_column(tmp_path):
    # XFOIL's polar file: the header line names the columns; CM is the fifth.
    alpha = np.arange(-8.0, 16.5, 0.5)
    polar = get_polar(_write(tmp_path, XFOIL_HEADER + _xfoil_rows(alpha), "s.pol"))
    cm = polar.moment_coefficient(np.radians([0.0, 4.0]), np.array([5e6, 5e6]), np.zeros(2))[0]
    np.testing.assert_allclose(cm, [-0.1, -0.096], atol=1e-12)
    # the shipped example (run_scripts/make_own_airfoil_example.py) carries its CM column
    assert get_polar(DATA / "naca4412_re5e6.pol").table_cm is not None
    # without a header naming CM, a text polar has no moment table
    plain = get_polar(_write(tmp_path, "alpha cl cd\n" + _xfoil_rows(alpha), "plain.dat"))
    assert plain.table_cm is None


def test_xfoil_polar_file_with_a_short_row_or_a_wild_moment_is_refused(tmp_path):
    alpha = np.arange(-8.0, 16.5, 0.5)
    short = XFOIL_HEADER + _xfoil_rows(alpha) + "  16.500   2.0000   0.03000\n"
    with pytest.raises(ValueError, match="no number in the CM column"):
        get_polar(_write(tmp_path, short, "short.pol"))
    wild = XFOIL_HEADER + _xfoil_rows(alpha, cm=lambda a: 5.0)
    with pytest.raises(ValueError, match="CM column holds 5.0"):
        get_polar(_write(tmp_path, wild, "wild.pol"))
