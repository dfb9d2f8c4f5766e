"""A-weighting against the IEC 61672-1 table."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.components.acoustics.a_weighting import (
    AWeightingComp,
    a_weighting,
    a_weighting_derivative,
)

# IEC 61672-1:2013, Table 3: A-weighting (dB) at the nominal one-third-octave frequencies
# 10 Hz .. 20 kHz. The standard computes the tabulated values at the exact base-10 frequencies
# f = 1000 * 10**(k/10) Hz (k = -20..13) and rounds them to 0.1 dB; the nominal labels
# (12.5, 16, 31.5 ...) differ from the exact frequencies by up to 2.6 %, i.e. up to 0.27 dB
# at 16 Hz where the curve is steep, so the check uses the exact frequencies.
IEC_61672_A = {
    10: -70.4,
    12.5: -63.4,
    16: -56.7,
    20: -50.5,
    25: -44.7,
    31.5: -39.4,
    40: -34.6,
    50: -30.2,
    63: -26.2,
    80: -22.5,
    100: -19.1,
    125: -16.1,
    160: -13.4,
    200: -10.9,
    250: -8.6,
    315: -6.6,
    400: -4.8,
    500: -3.2,
    630: -1.9,
    800: -0.8,
    1000: 0.0,
    1250: 0.6,
    1600: 1.0,
    2000: 1.2,
    2500: 1.3,
    3150: 1.2,
    4000: 1.0,
    5000: 0.5,
    6300: -0.1,
    8000: -1.1,
    10000: -2.5,
    12500: -4.3,
    16000: -6.6,
    20000: -9.3,
}


def test_iec_61672_table():
    # Tolerance 0.1 dB (acceptance); the table is rounded to 0.1 dB, observed max 0.05 dB.
    nominal = np.array(list(IEC_61672_A))
    exact = 1000.0 * 10.0 ** (np.arange(-20, 14) / 10.0)
    assert np.allclose(exact, nominal, rtol=0.03)  # same bands
    table = np.array(list(IEC_61672_A.values()))
    assert np.max(np.abs(a_weighting(exact) - table)) < 0.1


def test_reference_page_check_values():
    # docs theory/acoustics 'A-weighting' check values (2 decimals): 0.01 dB.
    freq = [40.0, 100.0, 500.0, 1000.0, 2000.0, 4000.0, 10000.0]
    ref = [-34.54, -19.14, -3.25, 0.00, 1.20, 0.96, -2.49]
    assert np.max(np.abs(a_weighting(freq) - ref)) < 0.01
    assert a_weighting(1000.0) == pytest.approx(0.0, abs=1e-12)


def test_derivative_matches_complex_step():
    f = np.array([12.5, 40.0, 315.0, 2500.0, 40000.0])
    h = 1e-30
    assert_near_equal(
        a_weighting_derivative(f), np.imag(a_weighting(f + 1j * h)) / h, tolerance=1e-12
    )


def test_bad_frequency():
    with pytest.raises(
        ValueError,
        match=r"'frequency\[.*\]' = .*"
        r" is out of range: must be > 0 \(Hz\)",
    ):
        a_weighting([100.0, 0.0])


def test_component_adds_weighting():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("w", AWeightingComp(shape=(2, 2), names=["spl"]), promotes=["*"])
    prob.setup()
    prob.set_val("frequency", [[100.0, 1000.0], [2000.0, 10000.0]])
    prob.set_val("spl", [[80.0, 70.0], [60.0, 50.0]])
    prob.run_model()
    assert_near_equal(
        prob.get_val("spl_a"), [[80.0 - 19.145, 70.0], [61.203, 47.512]], tolerance=1e-4
    )
