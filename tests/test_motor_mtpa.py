"""Tests for lpc_mdo.components.motor.mtpa (MTPA q-axis current, paper eq. 26)."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal
from scipy.optimize import brentq, minimize_scalar

from lpc_mdo.components.motor.mtpa import (
    MTPAComp,
    PeakCurrentComp,
    mtpa_base,
    mtpa_current_pu,
    mtpa_residual,
)

# Case A motor of docs theory/motor 'Validation' (L = 0.131 m, L/D = 1/3),
# equivalent-circuit values as computed by MotorGroup (they match the reference to its printed
# digits, see test_motor_ecm.py).
FLUX_LINKAGE = 0.2995817371190801
INDUCTANCE_D = 7.496609361335175e-4
INDUCTANCE_Q = 1.0483249288405264e-3
POLE_PAIRS = 6


def _run(torque, flux=FLUX_LINKAGE, l_d=INDUCTANCE_D, l_q=INDUCTANCE_Q):
    torque = np.atleast_2d(np.asarray(torque, dtype=float))
    nm, nn = torque.shape
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("mtpa", MTPAComp(num_motors=nm, num_nodes=nn), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("em_torque", torque)
    prob.set_val("flux_linkage", flux * np.ones(nm))
    prob.set_val("inductance_d", l_d * np.ones(nm))
    prob.set_val("inductance_q", l_q * np.ones(nm))
    prob.run_model()
    return prob


def test_base_values_case_a():
    # docs theory/motor 'Validation' case A: I_base 1003.07 A and T_base 2704.52 N*m
    # (printed to 6 digits: 1e-5 relative).
    i_base, t_base = mtpa_base(FLUX_LINKAGE, INDUCTANCE_D, INDUCTANCE_Q, POLE_PAIRS)
    assert_near_equal(i_base, 1003.07, tolerance=1e-5)
    assert_near_equal(t_base, 2704.52, tolerance=1e-5)


@pytest.mark.parametrize("torque", [1.0, 45.09625639, 77.4, 305.63923318, 1000.0, 3000.0, 30000.0])
def test_quartic_root_is_max_torque_per_ampere(torque):
    # Independent check of eq. 26: the MTPA current minimizes |I| for the torque T, i.e.
    # maximizes torque per ampere T/|I| along the torque curve I_d(I_q) = (T/(1.5 p I_q) -
    # Psi)/(L_d - L_q). scipy's Brent maximization (tol 1e-12) against the quartic root:
    # 1e-8 relative (issue acceptance).
    i_q = _run(torque).get_val("current_q")[0, 0]
    k_t, saliency = 1.5 * POLE_PAIRS, INDUCTANCE_D - INDUCTANCE_Q

    def negative_torque_per_ampere(current_q):
        current_d = (torque / (k_t * current_q) - FLUX_LINKAGE) / saliency
        return -torque / np.sqrt(current_q**2 + current_d**2)

    no_reluctance = torque / (k_t * FLUX_LINKAGE)  # I_q with I_d = 0: above the MTPA I_q
    best = minimize_scalar(
        negative_torque_per_ampere,
        bracket=(no_reluctance, 0.9 * no_reluctance),
        method="brent",
        tol=1e-12,
    )
    assert best.success
    assert_near_equal(i_q, best.x, tolerance=1e-8)


def test_closed_form_limits():
    # Small T*: I_q* -> T* (no reluctance torque, I_q = T/(1.5 p Psi)); large T*: I_q*^4 ~ T*^2,
    # I_q* -> sqrt(T*). Relative errors O(T*^2) and O(T*^-1/2) -> 1e-5 at T* = 1e-6 and 1e-2
    # at T* = 1e4 (asymptotics of eq. 26).
    small, large = np.array([1e-6]), np.array([1e4])
    assert_near_equal(mtpa_current_pu(small), small, tolerance=1e-5)
    assert_near_equal(mtpa_current_pu(large), np.sqrt(large), tolerance=1e-2)


def test_vectorized_root_to_machine_precision():
    # Many motors and nodes at once: residual of eq. 26 at round-off, 1e-14 relative to T*^2.
    torque_pu = np.geomspace(1e-4, 1e3, 40).reshape(5, 8)
    current_pu = mtpa_current_pu(torque_pu)
    assert np.all(
        np.abs(mtpa_residual(current_pu, torque_pu)) <= 1e-14 * torque_pu**2 + 1e-14 * current_pu**4
    )


def test_partials():
    # Analytic partials against complex step (exact): 1e-11.
    torque = np.array([[20.0, 305.0, 1500.0], [40.0, 90.0, 700.0]])
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("mtpa", MTPAComp(num_motors=2, num_nodes=3), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("em_torque", torque)
    prob.set_val("flux_linkage", [FLUX_LINKAGE, 0.0345])
    prob.set_val("inductance_d", [INDUCTANCE_D, 9.3863e-5])
    prob.set_val("inductance_q", [INDUCTANCE_Q, 1.1168e-4])
    prob.run_model()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-11, rtol=1e-11)


def test_complex_step_through_solve():
    # d I_q/d T_em through the solve (complex step: real solve + one complex Newton step)
    # equals the implicit-function derivative from the analytic partials, -R_T/R_Iq: 1e-10.
    prob = _run([[305.63923318]])
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)["mtpa"]
    slope = -(
        data["current_q", "em_torque"]["J_fwd"][0, 0]
        / data["current_q", "current_q"]["J_fwd"][0, 0]
    )
    totals = prob.check_totals(of=["current_q"], wrt=["em_torque"], method="cs", out_stream=None)
    assert_near_equal(totals["current_q", "em_torque"]["J_fd"][0, 0], slope, tolerance=1e-10)


@pytest.mark.parametrize(
    "name, value, pattern",
    [
        ("em_torque", 0.0, r"'em_torque\[0, 0\]' = 0.0 is out of range: must be > 0 \(N\*m\)"),
        ("flux_linkage", -0.3, r"'flux_linkage\[0.*\]' = -0.3 is out of range: must be > 0 \(Wb\)"),
        ("inductance_q", 5.0e-4, r"inductance_q - inductance_d = .* allowed range \(0, inf\)"),
    ],
)
def test_bad_inputs_raise(name, value, pattern):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("mtpa", MTPAComp(), promotes=["*"])
    prob.setup()
    prob.set_val("em_torque", 100.0)
    prob.set_val("flux_linkage", FLUX_LINKAGE)
    prob.set_val("inductance_d", INDUCTANCE_D)
    prob.set_val("inductance_q", INDUCTANCE_Q)
    prob.set_val(name, value)
    with pytest.raises(om.AnalysisError, match=pattern):
        prob.run_model()


def test_cached_real_roots_are_the_roots_of_their_own_torques():
    # The real roots are cached by torque array (a complex-step Jacobian evaluates the same real
    # parts once per input); a changed torque must get its own root, and a caller that edits the
    # returned array must not edit the cache.
    first, second = np.array([0.2, 1.5, 3.0]), np.array([0.25, 1.5, 2.0])
    a = mtpa_current_pu(first)
    b = mtpa_current_pu(second)
    a[:] = -1.0
    again = mtpa_current_pu(first)
    for torque, root in ((first, again), (second, b)):
        np.testing.assert_allclose(mtpa_residual(root, torque), 0.0, atol=1e-12)
    derivative = mtpa_current_pu(first + 1e-30j).imag / 1e-30  # the complex step still works
    np.testing.assert_allclose(
        derivative, -(again - 2 * first) / (4 * again**3 + first), rtol=1e-12
    )


def _peak_current(peak_torque, flux, l_d, l_q):
    prob = om.Problem(reports=False)
    n = len(peak_torque)
    prob.model.add_subsystem("peak", PeakCurrentComp(num_motors=n), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("peak_torque", peak_torque)
    prob.set_val("flux_linkage", flux)
    prob.set_val("inductance_d", l_d)
    prob.set_val("inductance_q", l_q)
    prob.run_model()
    return prob


def test_peak_current_is_the_least_current_for_the_peak_torque():
    # Independent of eq. 26: the smallest current amplitude I at which some current angle beta
    # (I_d = -I sin(beta), I_q = I cos(beta)) gives the peak torque, T(I, beta) = 1.5 p (Psi_F
    # I_q + (L_d - L_q) I_d I_q), found by brentq on I of max_beta T(I, beta) - T_pk with the
    # inner maximum by scipy's bounded Brent. Case A motor at T_pk = 1652.87128 N*m (its fit)
    # and a second, smaller motor: 1e-7 relative (the inner maximisation's tolerance).
    peak = np.array([1652.87128, 120.0])
    flux = np.array([FLUX_LINKAGE, 0.0345])
    l_d = np.array([INDUCTANCE_D, 9.3863e-5])
    l_q = np.array([INDUCTANCE_Q, 1.1168e-4])
    result = _peak_current(peak, flux, l_d, l_q).get_val("peak_current")

    def best_torque(current, k):
        def negative(beta):
            i_d, i_q = -current * np.sin(beta), current * np.cos(beta)
            return -1.5 * POLE_PAIRS * (flux[k] * i_q + (l_d[k] - l_q[k]) * i_d * i_q)

        res = minimize_scalar(
            negative, bounds=(0.0, 0.5 * np.pi), method="bounded", options={"xatol": 1e-12}
        )
        return -res.fun

    for k in range(2):
        expected = brentq(lambda i, k=k: best_torque(i, k) - peak[k], 1.0, 1.0e5, xtol=1e-10)
        assert_near_equal(result[k], expected, tolerance=1e-7)


def test_peak_current_partials():
    # Complex-step partials (exact to round-off) against central FD: 1e-6 relative.
    prob = _peak_current(
        np.array([1652.87128, 120.0]),
        np.array([FLUX_LINKAGE, 0.0345]),
        np.array([INDUCTANCE_D, 9.3863e-5]),
        np.array([INDUCTANCE_Q, 1.1168e-4]),
    )
    data = prob.check_partials(
        method="fd",
        form="central",
        step=1e-7,
        step_calc="rel_avg",
        compact_print=True,
        out_stream=None,
    )
    assert_check_partials(data, atol=1e-6, rtol=1e-6)
