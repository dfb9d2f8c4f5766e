import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.weights.gross_weight import BREAKDOWN_LABELS, GrossWeightComp

# Public-code tally of docs theory/weights 'Gross mass' (kg): fuselage 411.8, booms 153.5,
# empennage 73.5, wing 375.7, battery 800, motors 330.1, payload 1340 (540 + 800),
# systems 244 -> "about 3729 kg".
TALLY = dict(
    wing_mass=375.7,
    fuselage_mass=411.8,
    empennage_mass=73.5,
    boom_mass=153.5,
    battery_mass=800.0,
    payload_mass=1340.0,
    systems_mass=244.0,
    power_electronics_mass=0.0,
    other_mass=0.0,
)


def run(num_motors=9, **values):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("gw", GrossWeightComp(num_motors=num_motors), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    for name, value in values.items():
        prob.set_val(name, value)
    prob.run_model()
    return prob


def test_public_code_tally():
    # Ref docs theory/weights 'Gross mass': the sum of the public-code masses is 3728.6 kg
    # (hand sum of the printed items, 1e-12); one motor entry of 330.1 kg stands for all motors.
    prob = run(num_motors=1, motor_mass=[330.1], **TALLY)
    assert_near_equal(prob.get_val("gross_mass"), 3728.6, 1e-12)
    assert_near_equal(prob.get_val("structures_mass"), 375.7 + 411.8 + 73.5 + 153.5, 1e-12)
    assert_near_equal(prob.get_val("powertrain_mass"), 330.1, 1e-12)


def test_paper_build_up():
    # Paper eqs. 31-33 by hand: structures 283.36 + 316.52 + 56.54 + 118.10 = 774.52;
    # powertrain 8 x 10.68 + 36.05 + 40.82 = 162.31; gross = 774.52 + 800 + 162.31 + 540 + 270
    # + 1177.15 = 3723.98 kg (exact sums of these inputs, 1e-12).
    values = dict(
        wing_mass=283.36,
        fuselage_mass=316.52,
        empennage_mass=56.54,
        boom_mass=118.10,
        battery_mass=800.0,
        motor_mass=[10.68] * 8 + [36.05],
        power_electronics_mass=40.82,
        payload_mass=540.0,
        systems_mass=270.0,
        other_mass=1177.15,
    )
    prob = run(**values)
    assert_near_equal(prob.get_val("structures_mass"), 774.52, 1e-12)
    assert_near_equal(prob.get_val("powertrain_mass"), 8 * 10.68 + 36.05 + 40.82, 1e-12)
    assert_near_equal(prob.get_val("gross_mass"), 3723.98, 1e-12)
    breakdown = dict(zip(BREAKDOWN_LABELS, prob.get_val("mass_breakdown"), strict=True))
    assert_near_equal(breakdown["motors"], 8 * 10.68 + 36.05, 1e-12)
    assert_near_equal(breakdown["other"], 1177.15, 1e-15)
    assert_near_equal(sum(breakdown.values()), 3723.98, 1e-12)


def test_partials():
    prob = run(motor_mass=np.arange(1.0, 10.0), **TALLY)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-12)


def test_bad_inputs():
    with pytest.raises(
        om.AnalysisError,
        match=r"'other_mass\[0\]' = -5.0 is out of range: "
        r"must be >= 0 \(kg\)",
    ):
        run(other_mass=-5.0)
    with pytest.raises(
        om.AnalysisError,
        match=r"'motor_mass\[0\]' = nan"
        r" is out of range: must be a finite",
    ):
        run(motor_mass=[np.nan] * 9)
