"""Tests for lpc_mdo.components.motor.sizing (MotorSizingComp) and MotorParameters."""

import dataclasses

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_near_equal,
)
from sparsity import assert_sparsity_matches

from lpc_mdo.components.motor.parameters import MotorParameters
from lpc_mdo.components.motor.sizing import MotorSizingComp


def printed_tolerance(value):
    """Relative tolerance of a reference number: half a unit in its last printed digit."""
    mantissa, _, exponent = repr(float(value)).lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals) / abs(value) * 1.01


def _run(length, ratio=0.5, diameter=None, **inputs):
    length = np.atleast_1d(np.asarray(length, dtype=float))
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "sizing", MotorSizingComp(num_motors=length.size, length_to_diameter=ratio), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("length", length, units="m")
    if diameter is not None:
        prob.set_val("diameter", diameter, units="m")
    for name, value in inputs.items():
        prob.set_val(name, value)
    prob.run_model()
    return prob


# docs theory/motor 'Validation', case A (L = 0.131 m, L/D = 1/3): values
# from running lsdo_motor unchanged, printed to 4-9 significant digits. The model here is the
# same arithmetic, so the tolerance is the printed precision (half a unit in the last digit).
CASE_A_SIZING = {
    "diameter": 0.393,
    "mass": 54.0287842,
    "peak_torque": 1652.87128,
    "stator_inner_diameter": 0.3144,
    "shaft_diameter": 0.09354532,
    "pole_pitch": 0.08230973,
    "tooth_pitch": 0.02743658,
    "air_gap": 0.00129113,
    "rotor_diameter": 0.31181773,
    "turns_per_phase": 41.15486376,
    "tooth_width": 0.0144403,
    "stator_yoke_height": 0.01909329,
    "slot_bottom_width": 0.00411549,
    "slot_height": 0.02020671,
    "slot_inner_width": 0.01334534,
}


def test_case_a_reference_values():
    prob = _run(0.131, ratio=1.0 / 3.0)
    for name, expected in CASE_A_SIZING.items():
        # docs theory/motor 'Validation' case A, to the printed precision.
        assert_near_equal(prob.get_val(name)[0], expected, tolerance=printed_tolerance(expected))


def test_case_c_reference_values():
    # docs theory/motor 'Validation' case C (L = 0.08 m, L/D = 0.5): D 0.16, mass 5.46888449 kg,
    # T_pk 93.4297526 N*m, to the printed precision.
    prob = _run(0.08, ratio=0.5)
    for name, expected in (("diameter", 0.16), ("mass", 5.46888449), ("peak_torque", 93.4297526)):
        assert_near_equal(prob.get_val(name)[0], expected, tolerance=printed_tolerance(expected))


def test_mass_is_paper_eq_23():
    # Paper eq. 23 evaluated by hand, m = pi A B D**2 L/(2 Q_sp), with non-default loadings and an
    # explicit diameter; the same arithmetic -> 1e-14 relative.
    length, diameter, a_bar, b_bar = 0.12, 0.3, 25.0e3, 0.9
    prob = _run(
        length, ratio=None, diameter=diameter, electric_loading=a_bar, magnetic_loading=b_bar
    )
    expected = np.pi * a_bar * b_bar * diameter**2 * length / (2.0 * 15.0)
    assert_near_equal(prob.get_val("mass")[0], expected, tolerance=1e-14)
    # T_pk = 0.4840 m**2 + 3.3169 m + 60.8142 (docs theory/motor 'Sizing'), 1e-14 relative.
    assert_near_equal(
        prob.get_val("peak_torque")[0],
        0.4840 * expected**2 + 3.3169 * expected + 60.8142,
        tolerance=1e-14,
    )


def test_vectorized_motors_match_single_runs():
    lengths = np.array([0.08, 0.1, 0.131, 0.15, 0.2])
    prob = _run(lengths)
    for i, length in enumerate(lengths):
        single = _run(length)
        for name in CASE_A_SIZING:
            # Same arithmetic per motor: round-off only.
            assert_near_equal(prob.get_val(name)[i], single.get_val(name)[0], tolerance=1e-14)


@pytest.mark.parametrize("ratio", [0.5, 1.0 / 3.0, None])
def test_partials(ratio):
    # Analytic partials against complex step (exact): 1e-12.
    prob = _run(
        [0.08, 0.131, 0.2],
        ratio=ratio,
        diameter=None if ratio else [0.2, 0.3, 0.45],
        electric_loading=[25.0e3, 30.0e3, 35.0e3],
        magnetic_loading=[0.8, 0.85, 0.9],
    )
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-12, rtol=1e-12)


def test_declared_sparsity_matches_the_sensitivities():
    prob = _run([0.08, 0.131, 0.2], ratio=None, diameter=[0.2, 0.3, 0.45])
    assert_sparsity_matches(prob, "sizing")


@pytest.mark.parametrize(
    "name, value",
    [
        ("length", -0.1),
        ("length", 0.0),
        ("electric_loading", 0.0),
        ("magnetic_loading", -0.85),
        ("diameter", np.nan),
    ],
)
def test_bad_inputs_raise(name, value):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("sizing", MotorSizingComp(length_to_diameter=None), promotes=["*"])
    prob.setup()
    prob.set_val(name, value)
    with pytest.raises(om.AnalysisError, match=rf"'{name}\[0\]' = .* is out of range: must be "):
        prob.run_model()


@pytest.mark.parametrize("ratio", [0.0, -0.5, float("inf")])
def test_bad_ratio_option_raises(ratio):
    with pytest.raises(
        ValueError,
        match=r"MotorSizingComp: 'length_to_diameter' = .* "
        r"is out of range: must be ",
    ):
        MotorSizingComp(length_to_diameter=ratio)


@pytest.mark.parametrize(
    "field, value",
    [
        ("pole_pairs", 0),
        ("rated_current", -120.0),
        ("voltage_limit", 0.0),
        ("gear_ratio", float("nan")),
        ("num_slots", 35),
        ("magnet_temperature", 500.0),
    ],
)
def test_bad_parameters_raise(field, value):
    with pytest.raises(
        ValueError,
        match=rf"MotorParameters: '{field}' = .* is (out of "
        r"range|not allowed): must be",
    ):
        MotorParameters(**{field: value})


def test_parameters_derived_values():
    # docs theory/motor 'Equivalent circuit'/7.5 constants derived from the defaults:
    # K_dp1 = 1 (q = 1), B_r(75 C) = 1.1208 T and H_c(75 C) = 847138 A/m (the values lsdo_motor
    # hard-codes), A_cu = 1.2e-5 m**2, f_i = 500 Hz.
    par = MotorParameters()
    assert_near_equal(par.winding_factor, 1.0, tolerance=1e-15)
    assert_near_equal(par.remanence, 1.1208, tolerance=1e-14)
    assert_near_equal(par.coercivity, 847138.0, tolerance=1e-14)
    assert_near_equal(par.copper_area, 1.2e-5, tolerance=1e-14)
    assert_near_equal(par.rated_frequency, 500.0, tolerance=1e-15)
    # q = 2 (Z = 72): slot angle 2 pi p/Z = 30 deg electrical, K_d1 = sin(2 * 15 deg)/(2 sin(15
    # deg)) = 0.9659 (textbook distribution factor; radians inside), 1e-14.
    par2 = dataclasses.replace(par, num_slots=72)
    expected = np.sin(np.radians(30.0)) / (2.0 * np.sin(np.radians(15.0)))
    assert_near_equal(par2.winding_factor, expected, tolerance=1e-14)
