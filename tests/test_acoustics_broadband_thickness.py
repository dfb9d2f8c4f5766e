"""Gill-Lee broadband and Barry-Magliozzi thickness noise against the reference page cases.

Case (docs theory/acoustics, "LPC hover, single lift rotor", a transcription of the public code):
R = 1.524 m, B = 2, 1200 rpm, rho = 1.213457 kg/m**3, a = 339.885 m/s,
C_T = T/(rho pi R**2 (Omega R)**2) = 0.014977; chord linear 0.3 -> 0.1 m at 25 stations
rbar = linspace(0.2 R + 0.01, R - 0.01, 25)/R (docs theory/acoustics 'Tonal loading noise',
docs theory/rotors 'Validation'); observer 80 m away, 15 deg below the rotor plane (ex_lpc);
modes m = 1..3. The public code integrates with dr = 0.8 R/(N_r - 1) at every station,
which the radial_weights option reproduces.
"""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.api.acoustics import rotor_noise
from lpc_mdo.components.acoustics.a_weighting import a_weighting
from lpc_mdo.components.acoustics.broadband import GillLeeBroadbandComp
from lpc_mdo.components.acoustics.thickness import BarryMagliozziThicknessComp
from lpc_mdo.components.acoustics.total import energetic_sum

RADIUS, RPM, RHO, SOUND = 1.524, 1200.0, 1.213457, 339.885
NRAD = 25
STATIONS = np.linspace(0.2 * RADIUS + 0.01, RADIUS - 0.01, NRAD) / RADIUS
CODE_WEIGHTS = np.full(NRAD, 0.8 / (NRAD - 1))
CHORD = np.linspace(0.3, 0.1, NRAD)
OMEGA = RPM * np.pi / 30.0
THRUST = 0.014977 * RHO * np.pi * RADIUS**2 * (OMEGA * RADIUS) ** 2
DIST, ELEV = 80.0, np.radians(15.0)


def _run(comp, values):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("comp", comp, promotes=["*"])
    prob.setup()
    for name, val in values.items():
        prob.set_val(name, val)
    prob.run_model()
    return prob


def _gill_lee(weights):
    comp = GillLeeBroadbandComp(num_radial=NRAD, radial_stations=STATIONS, radial_weights=weights)
    prob = _run(
        comp,
        {
            "radius": RADIUS,
            "rpm": RPM,
            "thrust": THRUST,
            "chord": CHORD,
            "density": RHO,
            "speed_of_sound": SOUND,
            "distance": DIST,
            "axial_distance": -DIST * np.sin(ELEV),
        },
    )
    spl = prob.get_val("broadband_spl")[0]
    return energetic_sum(spl), energetic_sum(spl + a_weighting(comp.band_frequencies))


@pytest.mark.parametrize("weights, tol", [(CODE_WEIGHTS, 0.01), (None, 1.0)])
def test_gill_lee_reference_case(weights, tol):
    # Reference: Gill-Lee OASPL 77.76 dB unweighted and 78.33 dBA A-weighted per band
    # (docs theory/acoustics ). With the code's radial weights the spectrum must match to 0.01 dB
    # (the page's rounding); with the default element-cell weights (blade area 4 % smaller)
    # within 1 dB (acceptance).
    oaspl, oaspl_a = _gill_lee(weights)
    assert abs(oaspl - 77.76) < tol
    assert abs(oaspl_a - 78.33) < tol


def _thickness(tc, weights=CODE_WEIGHTS):
    prob = _run(
        BarryMagliozziThicknessComp(
            num_radial=NRAD, radial_stations=STATIONS, radial_weights=weights
        ),
        {
            "radius": RADIUS,
            "rpm": RPM,
            "chord": CHORD,
            "thickness_to_chord": tc,
            "density": RHO,
            "speed_of_sound": SOUND,
            "axial_distance": -DIST * np.sin(ELEV),
            "inplane_distance": DIST * np.cos(ELEV),
        },
    )
    return prob.get_val("thickness_spl")[0]


@pytest.mark.parametrize("tc, reference", [(0.12 * CHORD, 52.36), (np.full(NRAD, 0.12), 67.28)])
def test_barry_magliozzi_reference_cases(tc, reference):
    # Reference: BM thickness noise of modes 1..3 summed, 52.36 dB with ex_lpc's
    # thickness_to_chord = 0.12 * chord (quirk Q16, passed here as input data)
    # and 67.28 dB with t/c = 0.12 (docs theory/acoustics ). Tolerance 1 dB (acceptance).
    # Observed +0.15 dB: the page's numbers were produced with the J_{n+-1} argument scaled
    # by (n +- 1) (docs theory/acoustics 'Public-code compatibility', not reproduced);
    # with that quirk a transcription gives 52.36 and 67.28 exactly.
    total = energetic_sum(_thickness(tc))
    assert abs(total - reference) < 1.0
    assert 0.1 < total - reference < 0.2  # the known Q15 offset, documented


def test_barry_magliozzi_scales_with_thickness_and_distance():
    # P_m is linear in the section area 0.6853 c**2 t/c: doubling t/c adds 20 log10 2 = 6.0206 dB
    # to every mode (exact algebra, 1e-9 dB).
    base = _thickness(np.full(NRAD, 0.06))
    assert_near_equal(
        _thickness(np.full(NRAD, 0.12)) - base, np.full(3, 20 * np.log10(2.0)), tolerance=1e-9
    )


@pytest.mark.parametrize("num_rotors, reference", [(1, 78.34), (8, 87.37)])
def test_total_reference_case(num_rotors, reference):
    # docs theory/acoustics totals: one rotor 78.34 dBA, 8 identical co-located rotors 87.37 dBA.
    # The page's tonal part carries code quirks (Q13, Q17, Q18) and BEM loads we do not have; here
    # the loads come from thrust 4863.5 N and torque 803.4 N*m (docs theory/rotors 'Validation')
    # with the assumed hover shape. The broadband part dominates by more than 20 dB,
    # so the total must agree to 0.1 dB.
    res = rotor_noise(
        [RADIUS] * num_rotors,
        [RPM] * num_rotors,
        [4863.5] * num_rotors,
        CHORD,
        torque=803.4,
        radial_stations=STATIONS,
        radial_weights=CODE_WEIGHTS,
        density=RHO,
        speed_of_sound=SOUND,
        observer_distance=DIST,
        observer_elevation_deg=15.0,
        # The page's numbers come from the public code, where S enters the Gill-Lee f8 term and
        # neither spreading nor absorption is applied: compare with that form.
        broadband_reference_distance=None,
    )
    assert res["broadband_oaspl_a"][0] > res["tonal_spl_a"][0] + 20.0
    assert abs(res["total_spl_a"] - reference) < 0.1
