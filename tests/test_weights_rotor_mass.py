import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.weights.rotor_mass import RotorMassComp

CHORD = [0.3, 0.23333333333333334, 0.16666666666666669, 0.1]


def run(radius, chord_cp, rpm, blades, nu=1.25):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "rotor", RotorMassComp(num_blades=blades, flap_frequency=nu), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("rotor_radius", radius, units="m")
    prob.set_val("blade_chord_cp", chord_cp, units="m")
    prob.set_val("rotor_design_speed", rpm, units="rpm")
    prob.run_model()
    return prob


def test_afdd00_in_ndarc_units_for_the_lpc_lift_rotor():
    # Independent evaluation of the NDARC AFDD00 equations in NDARC's own units (lb, ft, ft/s):
    # LPC lift rotor R = 5 ft, 2 blades, mean chord 0.2 m, 1200 rpm, hingeless nu = 1.25/rev.
    r_ft, c_ft = 5.0, 0.2 / 0.3048
    v_fps = 1200.0 * 2.0 * np.pi / 60.0 * r_ft
    w_blade = (
        0.0024419 * 2**0.53479 * r_ft**1.74231 * c_ft**0.77291 * v_fps**0.87562 * 1.25**2.51048
    )
    w_hub = (
        0.0061182 * 2**0.20373 * r_ft**0.60406 * v_fps**0.52803 * 1.25**1.00218
        * w_blade**0.87127
    )  # fmt: skip
    prob = run([1.524], [CHORD], [1200.0], [2])
    # Tolerance 1e-10: same equations, only the unit conversions differ.
    assert_near_equal(prob.get_val("blade_mass", units="lbm")[0], w_blade, 1e-10)
    assert_near_equal(prob.get_val("hub_mass", units="lbm")[0], w_hub, 1e-10)
    # 20.8 lb of blades and 9.85 lb of hub (hand evaluation, 3 digits).
    assert w_blade == pytest.approx(20.8, abs=0.05)
    assert w_hub == pytest.approx(9.85, abs=0.05)


def test_scaling_laws_of_the_blade_mass():
    base = run([1.5], [CHORD], [1200.0], [2]).get_val("blade_mass")[0]
    wide = run([1.5], [2.0 * np.array(CHORD)], [1200.0], [2]).get_val("blade_mass")[0]
    fast = run([1.5], [CHORD], [2400.0], [2]).get_val("blade_mass")[0]
    four = run([1.5], [CHORD], [1200.0], [4]).get_val("blade_mass")[0]
    # NDARC AFDD00 exponents: chord 0.77291, tip speed 0.87562, blade count 0.53479.
    assert_near_equal(wide / base, 2**0.77291, 1e-12)
    assert_near_equal(fast / base, 2**0.87562, 1e-12)
    assert_near_equal(four / base, 2**0.53479, 1e-12)


def test_partials():
    prob = run(
        [1.5, 1.6, 1.4, 1.7, 1.37],
        np.array([CHORD] * 5) * np.linspace(0.8, 1.2, 5)[:, None],
        [1100.0, 1200.0, 1300.0, 1250.0, 1500.0],
        [2, 2, 2, 2, 4],
    )
    data = prob.check_partials(method="cs", out_stream=None)
    assert_check_partials(data, atol=1e-8, rtol=1e-8)


def test_bad_input_raises_analysis_error():
    prob = run([1.5], [CHORD], [1200.0], [2])
    prob.set_val("rotor_radius", -1.0)
    with pytest.raises(om.AnalysisError, match="rotor_radius"):
        prob.run_model()


def test_bad_blade_count_option():
    with pytest.raises(ValueError, match="num_blades"):
        RotorMassComp(num_blades=[2, 0])
