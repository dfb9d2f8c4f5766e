"""Broadband propagation: spherical spreading + ISO 9613-1 absorption (issue 16 item 5)."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.acoustics.absorption import iso9613_absorption
from lpc_mdo.components.acoustics.common import nominal_third_octave_bands
from lpc_mdo.components.acoustics.propagation import SphericalPropagationComp
from lpc_mdo.groups.acoustics import RotorNoiseGroup


def _broadband_bands(distance):
    p = om.Problem()
    p.model.add_subsystem(
        "n", RotorNoiseGroup(num_rotors=1, observer_input="relative"), promotes=["*"]
    )
    p.setup()
    p.set_val("observer_distance", distance)
    p.run_model()
    return p.get_val("broadband_spl")[0]


def _oaspl(bands):
    return 10.0 * np.log10(np.sum(10.0 ** (bands / 10.0)))


@pytest.mark.parametrize("distance", [10.0, 200.0, 1000.0, 2000.0])
def test_broadband_follows_spreading_and_absorption(distance):
    # Expected by hand: band levels at 100 m minus 20 log10(r/100) minus alpha(f)(r - 100), with
    # alpha from ISO 9613-1 at 288.15 K, 101325 Pa, 70 % RH (group defaults); OASPL within 1 dB.
    ref = _broadband_bands(100.0)
    f = nominal_third_octave_bands(38, 12.5)
    alpha = iso9613_absorption(f, 288.15, 101325.0, 70.0)
    expected = ref - 20.0 * np.log10(distance / 100.0) - alpha * (distance - 100.0)
    got = _broadband_bands(distance)
    assert _oaspl(got) == pytest.approx(_oaspl(expected), abs=1.0)


def test_propagation_partials_and_value():
    p = om.Problem()
    p.model.add_subsystem(
        "c", SphericalPropagationComp(num_rotors=2, num_bands=3, reference_distance=50.0)
    )
    p.setup(force_alloc_complex=True)
    p.set_val("c.source_spl", np.array([[60.0, 70.0, 80.0], [50.0, 55.0, 65.0]]))
    p.set_val("c.distance", [100.0, 500.0])
    p.set_val("c.absorption_coefficient", [1e-3, 5e-3, 2e-2])
    p.run_model()
    # Closed form: 60 - 20 log10(2) - 0.1 = 53.879 dB.
    assert p.get_val("c.spl")[0, 0] == pytest.approx(60.0 - 20.0 * np.log10(2.0) - 0.1, abs=1e-9)
    assert_check_partials(p.check_partials(method="cs", compact_print=True, out_stream=None))
