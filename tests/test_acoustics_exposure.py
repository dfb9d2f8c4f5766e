"""Noise exposure over a path: lpc_mdo.components.acoustics.exposure."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.acoustics.exposure import NoiseExposureComp


def exposure(level, duration, **options):
    level = np.atleast_2d(level)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "exposure",
        NoiseExposureComp(num_observers=level.shape[0], num_points=level.shape[1], **options),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("level", level)
    prob.set_val("duration", duration)
    prob.run_model()
    return prob


def test_a_steady_level_over_a_window_is_the_closed_form():
    # sel = L + 10 log10(T / 1 s): 70 dBA for 10 s (any split of the window) is 80 dBA.
    prob = exposure([[70.0] * 4], [1.0, 2.0, 3.0, 4.0])
    assert prob.get_val("sel")[0] == pytest.approx(80.0, abs=1e-12)
    assert prob.get_val("lmax")[0] == pytest.approx(70.0 + np.log(4.0) / 20.0, abs=1e-12)


def test_a_straight_pass_with_spherical_spreading_is_the_closed_form():
    # One source passing at V = 30 m/s, closest distance d = 100 m, L(t) = L0 - 10 log10(1 +
    # (V t/d)^2) (spherical spreading, no absorption): over an infinite window the exposure is
    # the integral of 1/(1 + (V t/d)^2), pi d/V, so sel = L0 + 10 log10(pi d/V) = 90 + 10.21 dB;
    # over the window +-T it is (2 d/V) arctan(V T/d). Sampled every 0.05 s (midpoints) over
    # +-2000 s: the window's closed form to 1e-4 dB, the infinite one's to its 0.1 % of energy
    # in the tails (0.005 dB).
    speed, distance, top = 30.0, 100.0, 90.0
    t = np.arange(-2000.0, 2000.0, 0.05) + 0.025
    level = top - 10.0 * np.log10(1.0 + (speed * t / distance) ** 2)
    prob = exposure(level[None, :], np.full(t.size, 0.05), rho=50.0)
    window = top + 10.0 * np.log10(2.0 * distance / speed * np.arctan(speed * 2000.0 / distance))
    assert prob.get_val("sel")[0] == pytest.approx(window, abs=1e-4)
    hand = top + 10.0 * np.log10(np.pi * distance / speed)
    assert prob.get_val("sel")[0] == pytest.approx(hand, abs=6e-3)
    assert prob.get_val("lmax")[0] == pytest.approx(top, abs=np.log(t.size) / 50.0)
    assert prob.get_val("lmax")[0] >= level.max()


def test_observers_are_independent_and_partials_are_exact():
    rng = np.random.default_rng(3)
    level = 60.0 + 20.0 * rng.random((3, 5))
    prob = exposure(level, 0.5 + rng.random(5))
    for i in range(3):
        alone = exposure(level[i], prob.get_val("duration"))
        assert alone.get_val("sel")[0] == pytest.approx(prob.get_val("sel")[i], abs=1e-12)
    data = prob.check_partials(method="cs", out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


@pytest.mark.parametrize("name, value", [("duration", 0.0), ("level", np.nan)])
def test_bad_input_is_a_named_analysis_error(name, value):
    prob = exposure([[60.0, 70.0]], [1.0, 1.0])
    bad = np.array(prob.get_val(name))
    bad.flat[0] = value
    prob.set_val(name, bad)
    with pytest.raises(om.AnalysisError, match=name):
        prob.run_model()
