"""The reference LPC half-wing box beam.

Reference: docs theory/structures 'Validation', aframe NASA_LPC_beam.py.
"""

import numpy as np
import pytest
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.api.structures import box_beam

# Inputs of docs theory/structures 'Validation' (FD frame: x forward, z down).
NODES = np.array(
    [
        (-3.53927, 2.96057e-5, -2.63734),
        (-3.55440, 0.924183, -2.60233),
        (-3.57151, 1.88572, -2.56586),
        (-3.58867, 2.84852, -2.52935),
        (-3.60592, 3.81277, -2.49278),
        (-3.62204, 4.77378, -2.45601),
        (-3.64281, 5.73453, -2.41846),
        (-3.67890, 6.69733, -2.38051),
        (-3.92518, 7.69578, -2.32876),
    ]
)
T_BOT = 1e-3 * np.array(
    [4.7226865, 4.3909194, 3.9121813, 3.3915973, 2.9390926, 2.0629110, 1.3926143, 0.3]
)
T_TOP = 1e-3 * np.array([8.298922, 7.689502, 6.751313, 5.704943, 4.375919, 2.971346, 1.925665, 0.3])
WIDTH = np.array(
    [0.8087064, 0.7670528, 0.7242612, 0.6813902, 0.6374276, 0.5865347, 0.5257780, 0.2467123]
)
HEIGHT = np.array(
    [0.26502895, 0.25133992, 0.23728960, 0.22321557, 0.20880246, 0.19208410, 0.17181877, 0.10655984]
)
FZ = np.array(
    [
        -4005.064,
        -6741.551,
        -6970.990,
        -6610.402,
        -6139.581,
        -5558.692,
        -4848.959,
        -3685.410,
        -1475.417,
    ]
)


def _solve(**kwargs):
    loads = np.zeros((9, 6))
    loads[:, 2] = FZ
    return box_beam(NODES, WIDTH, HEIGHT, T_TOP, T_BOT, 0.3e-3, 69e9, 26e9, 2700.0, loads, **kwargs)


@pytest.fixture(scope="module")
def result():
    return _solve()


def test_mass_and_tip_deflection(result):
    # Acceptance: within 1 % of the reference numbers (half-wing mass 113.836733 kg, tip
    # deflection -0.279624 m). The model is the reference model, so they agree to the digits
    # printed (1e-8 and 2e-6 relative).
    assert_near_equal(result["mass"], 113.836733, 1e-8)
    assert_near_equal(result["displacements"][-1, 2], -0.279624, 2e-6)
    assert_near_equal(result["cg"], [-3.583022, 2.453048, -2.544122], 1e-6)


def test_displacements(result):
    # docs theory/structures 'Validation' nodal displacements, 6 significant digits
    # (the root values are exactly 0).
    disp = result["displacements"]
    assert_near_equal(
        disp[1:, 2],
        [
            -4.96114e-3,
            -1.97650e-2,
            -4.35881e-2,
            -7.55631e-2,
            -0.114449,
            -0.159419,
            -0.209445,
            -0.279624,
        ],
        1e-5,
    )
    assert_near_equal(
        disp[1:, 1],
        [
            1.85892e-4,
            7.45222e-4,
            1.64640e-3,
            2.85685e-3,
            4.34246e-3,
            6.09752e-3,
            8.06612e-3,
            1.16325e-2,
        ],
        1e-5,
    )
    assert_near_equal(
        disp[1:, 0],
        [
            -3.2865e-6,
            -1.3461e-5,
            -3.0298e-5,
            -5.3442e-5,
            -8.2584e-5,
            -1.18918e-4,
            -1.64335e-4,
            -4.30141e-4,
        ],
        1e-4,
    )
    assert np.all(disp[0] == 0.0)


def test_section_properties(result):
    # docs theory/structures 'Validation' A, I_y, I_z, J (as printed: A to 5,
    # the inertias to 7 significant digits).
    assert_near_equal(
        result["area"],
        [0.010682, 0.009410, 0.007859, 0.006327, 0.004784, 0.003065, 0.001846, 0.000212],
        3e-4,
    )
    assert_near_equal(
        result["bending_inertia_vertical"],
        [
            1.736629e-4,
            1.377138e-4,
            1.028958e-4,
            7.365347e-5,
            4.915061e-5,
            2.674561e-5,
            1.283768e-5,
            4.773342e-7,
        ],
        1e-6,
    )
    assert_near_equal(
        result["bending_inertia_inplane"],
        [
            5.986300e-4,
            4.754349e-4,
            3.554181e-4,
            2.547174e-4,
            1.701482e-4,
            9.429416e-5,
            4.717107e-5,
            1.715899e-6,
        ],
        1e-6,
    )
    assert_near_equal(
        result["torsion_constant"],
        [
            7.722929e-4,
            6.131487e-4,
            4.583139e-4,
            3.283709e-4,
            2.192989e-4,
            1.210398e-4,
            6.000875e-5,
            2.193233e-6,
        ],
        1e-6,
    )
    lengths = np.linalg.norm(np.diff(NODES, axis=0), axis=1)
    assert_near_equal(
        lengths,
        [0.92494, 0.96238, 0.963645, 0.965097, 0.961848, 0.961708, 0.964223, 1.029677],
        1e-5,
    )


def test_corner_von_mises_stresses(result):
    # docs theory/structures 'Validation' table, points 0-3: the reference's points 0, 1, 2, 3
    # are our points 2, 3, 0, 1 (its section loads have the opposite sign, see BoxStressComp);
    # 6 digits printed -> 1e-5.
    ref = np.array(
        [
            [1.01017e8, 1.01049e8, 1.01315e8, 1.01347e8],
            [8.76384e7, 8.76664e7, 8.79226e7, 8.79507e7],
            [7.54932e7, 7.55285e7, 7.57662e7, 7.58015e7],
            [6.27398e7, 6.27858e7, 6.29998e7, 6.30458e7],
            [4.98825e7, 4.99524e7, 5.01312e7, 5.02011e7],
            [4.03043e7, 4.04038e7, 4.05591e7, 4.06586e7],
            [2.65161e7, 2.66506e7, 2.67352e7, 2.68698e7],
            [8.43289e7, 8.43289e7, 8.50298e7, 8.50298e7],
        ]
    )
    assert_near_equal(result["von_mises_stress"][:, [2, 3, 0, 1]], ref, 1e-5)


def test_web_point_follows_statics(result):
    # The docs theory/structures 'Validation' point-4 column cannot be reproduced from the
    # formula the reference page states (it implies e.g. a 43 N shear in the tip element,
    # which carries the 1475 N tip load).
    # Check instead against statics: the web shear uses V_z = the outboard load projected on the
    # element's local z axis, tau = V_z Q/(2 t_web I_y) + M_x (w/2)/J, σ = N/A - M_z (w/2)/I_z.
    sec = result["section_loads"]
    for e in range(8):
        d = NODES[e + 1] - NODES[e]
        ex = d / np.linalg.norm(d)
        ey = np.array([-ex[1], ex[0], 0.0]) / np.hypot(ex[0], ex[1])
        ez = np.cross(ex, ey)
        assert_near_equal(sec[e, 2], FZ[e + 1 :].sum() * ez[2], 1e-8)
    t_cap = 0.5 * (T_TOP + T_BOT)
    q = WIDTH * t_cap * HEIGHT / 2 + 0.3e-3 * HEIGHT**2 / 4
    tau = (
        sec[:, 2] * q / (2 * 0.3e-3 * result["bending_inertia_vertical"])
        + sec[:, 3] * WIDTH / 2 / result["torsion_constant"]
    )
    sigma = sec[:, 0] / result["area"] - sec[:, 5] * WIDTH / 2 / result["bending_inertia_inplane"]
    assert_near_equal(result["von_mises_stress"][:, 4], np.sqrt(sigma**2 + 3 * tau**2), 1e-10)
    # Root shear panel: 491 MPa here (reference table 448 MPa); above the 350 MPa allowable, as
    # in the paper, where stress is active only at the innermost shear panel.
    assert_near_equal(result["von_mises_stress"][0, 4], 4.91375e8, 1e-5)


def test_bredt_torsion_changes_the_tip_deflection_little():
    # The Bredt torsion constant is ~9x softer than the polar one; on this nearly straight wing
    # the tip deflection grows by only 0.19 % (the reference number is kept within 1 %).
    bredt = _solve(torsion_formula="bredt")
    assert_near_equal(bredt["displacements"][-1, 2], -0.279624, 1e-2)
    assert 0.0015 < bredt["displacements"][-1, 2] / -0.279624 - 1.0 < 0.0025
