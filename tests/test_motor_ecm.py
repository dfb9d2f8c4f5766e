"""Tests for lpc_mdo.components.motor.ecm: circuit parameters, magnet MEC, inductances."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_check_totals,
    assert_near_equal,
)
from sparsity import assert_sparsity_matches

from lpc_mdo.components.motor.ecm import (
    InductanceComp,
    MagnetCircuitComp,
    MagnetFluxComp,
    MotorECMParametersComp,
    QAxisFluxComp,
    magnet_circuit,
    magnet_operating_flux,
)
from lpc_mdo.components.motor.sizing import MotorSizingComp

LENGTHS = np.array([0.08, 0.131, 0.2])


pytestmark = pytest.mark.filterwarnings("ignore:.*nonlinear solver that computes gradients")


def printed_tolerance(value):
    """Relative tolerance of a reference number: half a unit in its last printed digit."""
    mantissa, _, exponent = repr(float(value)).lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals) / abs(value) * 1.01


def _chain(lengths, ratio=1.0 / 3.0, upto=None):
    """Sizing -> ECM chain of MotorGroup, run at the given lengths."""
    nm = lengths.size
    comps = [
        ("sizing", MotorSizingComp(num_motors=nm, length_to_diameter=ratio)),
        ("ecm_parameters", MotorECMParametersComp(num_motors=nm)),
        ("magnet_circuit", MagnetCircuitComp(num_motors=nm)),
        ("magnet_flux", MagnetFluxComp(num_motors=nm)),
        ("q_axis_flux", QAxisFluxComp(num_motors=nm)),
        ("inductance", InductanceComp(num_motors=nm)),
    ]
    prob = om.Problem(reports=False)
    for name, comp in comps:
        prob.model.add_subsystem(name, comp, promotes=["*"])
        if name == upto:
            break
    prob.model.linear_solver = om.DirectSolver()
    prob.setup(force_alloc_complex=True)
    prob.set_val("length", lengths, units="m")
    prob.run_model()
    return prob


def _isolated(comp, source):
    """Return the component alone, its inputs (and state guess) taken from a run of the chain."""
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("comp", comp, promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.final_setup()
    for io in (prob.model.list_inputs, prob.model.list_outputs):
        for _, meta in io(out_stream=None, prom_name=True):
            prob.set_val(meta["prom_name"], source.get_val(meta["prom_name"]))
    prob.run_model()
    return prob


# docs theory/motor 'Validation' case A (L = 0.131 m, L/D = 1/3): values from
# running lsdo_motor unchanged, printed to 4-9 significant digits; compared to the printed
# precision (half a unit in the last digit; the model is the same arithmetic).
CASE_A = {
    "magnet_width": 0.06326587,
    "magnet_area": 0.00828783,
    "remanent_flux": 0.0099454,
    "magnet_permeance": 1.46749927e-6,
    "pole_arc_coefficient": 0.81323348,
    "air_gap_field_coefficient": 1.2188393,
    "air_gap_flux_coefficient": 1.01377193,
    "carter_coefficient": 1.07574257,
    "bridge_area": 5.24e-4,
    "resistance": 0.02348894,
    "yoke_pitch": 0.08759983,
    "yoke_path_length": 0.04894427,
    "air_gap_flux_density": 0.74991057,
    "pole_flux": 0.00727938,
    "mmf_total": 1467.236,
    "mmf_air_gap": 1421.651,
    "leakage_coefficient": 1.09665631,
    "magnet_permeance_pu": 3.9802905,
    "leakage_permeance_pu": 0.350812,
    "inductance_d": 7.4966e-4,
    "inductance_q": 1.04832e-3,
    "flux_linkage": 0.29958174,
}


def test_case_a_reference_values():
    prob = _chain(np.array([0.131]))
    for name, expected in CASE_A.items():
        # docs theory/motor 'Validation' case A, to the printed precision.
        assert_near_equal(prob.get_val(name)[0], expected, tolerance=printed_tolerance(expected))


def test_case_c_reference_values():
    # docs theory/motor 'Validation' case C (L = 0.08 m, L/D = 0.5): R_dc 0.00506054 ohm to the
    # printed precision.
    prob = _chain(np.array([0.08]), ratio=0.5)
    assert_near_equal(
        prob.get_val("resistance")[0], 0.00506054, tolerance=printed_tolerance(0.00506054)
    )
    # B_delta 0.78545407 T: here 0.785454083 (1.7e-8 relative), solved to machine precision;
    # the reference's csdl BracketedSearch stops at its own tolerance, about 1e-8 from the root
    # (case A happens to agree to 9 digits). 5e-8 relative; case C's T_em and efficiency, which
    # depend on B_delta, agree to all printed digits (test_motor_analysis.py).
    assert_near_equal(prob.get_val("air_gap_flux_density")[0], 0.78545407, tolerance=5e-8)


def test_mec_solution_and_pole_flux_as_coded():
    # At B_delta the magnet operating flux phi_r - F_m lambda_m equals phi_air + phi_f + phi_s
    # (the MEC residual, solved by bisection to machine precision: 1e-12 relative), and the pole
    # flux is that magnet flux, not the geometric air-gap flux alpha_i tau l B_delta (case A:
    # 0.0072794 vs 0.0065758 Wb; module docstring of ecm.py).
    prob = _chain(LENGTHS)
    values = {
        meta["prom_name"]: prob.get_val(meta["prom_name"])
        for _, meta in prob.model.magnet_circuit.list_inputs(out_stream=None, prom_name=True)
    }
    circuit = magnet_circuit(prob.get_val("air_gap_flux_density"), values)
    assert_near_equal(
        magnet_operating_flux(circuit, values), circuit["flux_magnet"], tolerance=1e-12
    )
    assert_near_equal(prob.get_val("pole_flux"), circuit["flux_magnet"], tolerance=1e-14)
    assert np.all(circuit["flux_air"] < 0.95 * circuit["flux_magnet"])


@pytest.mark.parametrize(
    "name", ["ecm_parameters", "magnet_circuit", "magnet_flux", "q_axis_flux", "inductance"]
)
def test_partials(name):
    # The partials are an exact vectorized complex step, so they are checked against central
    # finite differences (relative step 1e-6): FD truncation and round-off allow ~1e-6.
    source = _chain(LENGTHS)
    comp = type(getattr(source.model, name))(num_motors=LENGTHS.size)
    prob = _isolated(comp, source)
    data = prob.check_partials(
        method="fd",
        form="central",
        step=1e-6,
        step_calc="rel_avg",
        compact_print=True,
        out_stream=None,
    )
    assert_check_partials(data, atol=1e-6, rtol=1e-5)


@pytest.mark.parametrize("name", ["ecm_parameters", "magnet_flux", "inductance"])
def test_declared_sparsity_matches_the_sensitivities(name):
    source = _chain(LENGTHS)
    comp = type(getattr(source.model, name))(num_motors=LENGTHS.size)
    prob = _isolated(comp, source)
    assert_sparsity_matches(prob, "comp")


def test_implicit_residuals_vanish():
    # The bracketed solves leave the residuals at round-off (both are O(1) dimensionless): 1e-12.
    prob = _chain(LENGTHS)
    prob.model.run_apply_nonlinear()
    for name in ("magnet_circuit", "q_axis_flux"):
        outputs = getattr(prob.model, name).list_outputs(residuals=True, out_stream=None)
        for _, meta in outputs:
            assert np.max(np.abs(meta["resids"])) < 1e-12


def test_totals_through_solves():
    # Totals of the chain (DirectSolver on the exact partials, implicit function theorem)
    # against complex step through the bracketed solves (real solve + one complex Newton step):
    # both exact, 1e-9.
    prob = _chain(LENGTHS)
    of = [
        "air_gap_flux_density",
        "pole_flux",
        "q_axis_flux",
        "inductance_d",
        "inductance_q",
        "flux_linkage",
        "resistance",
        "mass",
    ]
    data = prob.check_totals(of=of, wrt=["length"], method="cs", out_stream=None)
    assert_check_totals(data, atol=1e-9, rtol=1e-9)


def test_too_small_rotor_raises():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("ecm", MotorECMParametersComp(), promotes=["*"])
    prob.setup()
    prob.set_val("rotor_diameter", 0.0015)
    with pytest.raises(
        om.AnalysisError,
        match=r"'rotor_diameter\[0\]' = 0.0015 is out of range: "
        r"must be > 0.002 \(m\)",
    ):
        prob.run_model()


def test_q_axis_bracket_failure_raises():
    # A 1 cm motor has a pole flux below the reference bracket's lower end (1e-5 Wb): the q-axis
    # solve has no root there and must say so, not return NaN.
    with pytest.raises(om.AnalysisError, match=r"q_axis_flux residual does not change sign"):
        _chain(np.array([0.01]), ratio=0.5)
