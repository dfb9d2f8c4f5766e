import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.acoustics.absorption import (
    AtmosphericAbsorptionComp,
    iso9613_absorption,
)

# ISO 9613-2:1996 Table 2: attenuation coefficient (dB/km) at 101.325 kPa, octave bands with
# exact mid-band frequencies 1000 * 10**(0.3 k), k = -4..3 (63 Hz .. 8 kHz), computed there from
# ISO 9613-1:1993 and rounded to 0.1 dB/km (three significant figures above 100 dB/km).
_TABLE_2 = {
    (10.0, 70.0): [0.1, 0.4, 1.0, 1.9, 3.7, 9.7, 32.8, 117.0],
    (20.0, 70.0): [0.1, 0.3, 1.1, 2.8, 5.0, 9.0, 22.9, 76.6],
    (30.0, 70.0): [0.1, 0.3, 1.0, 3.1, 7.4, 12.7, 23.1, 59.3],
    (15.0, 20.0): [0.3, 0.6, 1.2, 2.7, 8.2, 28.2, 88.8, 202.0],
    (15.0, 50.0): [0.1, 0.5, 1.2, 2.2, 4.2, 10.8, 36.2, 129.0],
    (15.0, 80.0): [0.1, 0.3, 1.1, 2.4, 4.1, 8.3, 23.7, 82.8],
}
_OCTAVES = 1000.0 * 10.0 ** (0.3 * np.arange(-4, 4))


@pytest.mark.parametrize(("celsius", "humidity"), list(_TABLE_2))
def test_absorption_matches_iso_9613_2_table_2(celsius, humidity):
    # Tolerance: the table's rounding (0.05 dB/km, plus 0.01 for a value at the rounding edge;
    # 0.5 dB/km above 100) or 1 %, well inside the
    # +-10 % accuracy ISO 9613-1 clause 7 states for the formulae.
    table = np.array(_TABLE_2[(celsius, humidity)])
    alpha = 1000.0 * iso9613_absorption(_OCTAVES, 273.15 + celsius, 101325.0, humidity)
    tol = np.maximum(np.where(table >= 100.0, 0.5, 0.06), 0.01 * table) + 1e-9
    assert np.all(np.abs(alpha - table) <= tol), (alpha, table)


def test_absorption_rises_with_frequency_and_scales_with_path():
    f = np.array([50.0, 500.0, 5000.0, 50000.0])
    alpha = iso9613_absorption(f, 288.15, 101325.0, 70.0)
    assert np.all(np.diff(alpha) > 0.0)
    # Classical limit at high frequency: alpha -> 8.686 * 1.84e-11 f**2 t**0.5 / p + relaxation
    # tails ~ const, so alpha/f**2 tends to a positive constant from above.
    ratio = alpha / f**2
    assert ratio[-1] > 8.686 * 1.84e-11 * (288.15 / 293.15) ** 0.5


def _problem(**options):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("abs", AtmosphericAbsorptionComp(**options), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    return prob


def test_component_equals_function_and_partials():
    bands = np.array([100.0, 1000.0, 8000.0])
    fixed = _problem(shape=(3,), frequencies=bands)
    fixed.set_val("temperature", 281.65, units="K")
    fixed.set_val("pressure", 95000.0, units="Pa")
    fixed.set_val("relative_humidity", 55.0)
    fixed.run_model()
    assert_near_equal(
        fixed.get_val("absorption_coefficient"),
        iso9613_absorption(bands, 281.65, 95000.0, 55.0),
        1e-14,
    )
    assert_check_partials(fixed.check_partials(method="fd", out_stream=None), atol=1e-9, rtol=1e-4)

    free = _problem(shape=(2, 3))
    free.set_val("frequency", np.array([[40.0, 80.0, 120.0], [400.0, 4000.0, 16000.0]]))
    free.run_model()
    assert_check_partials(free.check_partials(method="fd", out_stream=None), atol=1e-9, rtol=1e-4)


def test_bad_humidity_is_an_analysis_error():
    prob = _problem(shape=(1,), frequencies=np.array([1000.0]))
    prob.set_val("relative_humidity", 120.0)
    with pytest.raises(om.AnalysisError, match="relative_humidity"):
        prob.run_model()
