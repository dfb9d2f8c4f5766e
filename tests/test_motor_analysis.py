"""
Tests for the motor analysis (lpc_mdo.groups.motor, lpc_mdo.api.motor).

EM torque (eq. 24), losses, torque limit, margins, MotorGroup and the motor_analysis wrapper.
"""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_check_totals,
    assert_near_equal,
    assert_no_approx_partials,
)

from lpc_mdo.api.motor import motor_analysis
from lpc_mdo.components.motor.efficiency import (
    EMTorqueComp,
    MotorLossComp,
    MotorMarginComp,
    smooth_min_ratio,
)
from lpc_mdo.components.motor.torque_limit import TorqueLimitComp
from lpc_mdo.groups.motor import MotorGroup

pytestmark = pytest.mark.filterwarnings("ignore:.*nonlinear solver that computes gradients")


def printed_tolerance(value):
    """Relative tolerance of a reference number: half a unit in its last printed digit."""
    mantissa, _, exponent = repr(float(value)).lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals) / abs(value) * 1.01


# docs theory/motor 'Validation': lsdo_motor (dev_csdl_alpha) run unchanged.
# (length m, L/D, rotor torque N*m, rotor rpm) and the printed results.
REFERENCE_CASES = {
    "A": (
        (0.131, 1.0 / 3.0, 1200.0, 1193.7),
        {
            "mass": 54.0287842,
            "peak_torque": 1652.87128,
            "inductance_d": 7.4966e-4,
            "inductance_q": 1.04832e-3,
            "flux_linkage": 0.29958174,
            "torque_limit": 471.691,
            "em_torque": 305.63923318,
            "efficiency": 0.98154938,
            "output_power": 150004.766,
            "input_power": 152824.472,
        },
    ),
    "B": (
        (0.131, 1.0 / 3.0, 172.317, 3375.10),
        {
            "em_torque": 45.09625639,
            "efficiency": 0.95527331,
            "output_power": 60903.659,
            "input_power": 63755.219,
        },
    ),
    "C": (
        (0.08, 0.5, 300.0, 1500.0),
        {
            "diameter": 0.16,
            "mass": 5.46888449,
            "peak_torque": 93.4297526,
            "resistance": 0.00506054,
            "em_torque": 77.42764173,
            "efficiency": 0.96864632,
            "output_power": 47123.890,
            "input_power": 48649.222,
        },
    ),
}


@pytest.mark.parametrize("case", sorted(REFERENCE_CASES))
def test_reference_operating_points(case):
    """
    The three operating points of docs theory/motor 'Validation' through motor_analysis.

    The reference is lsdo_motor, run unchanged.

    Tolerance: the printed precision of each reference number (half a unit in its last digit),
    with a floor of 1e-9 relative. Every value agrees; no difference needs explaining. The floor
    covers the reference's own inner solves, csdl bracketed searches that stop about 1e-8 from
    the root (case C: B_delta 0.78545407 printed vs 0.785454083 here, which moves T_em in the
    10th digit); the solves here run to machine precision. The issue's acceptance is 1 %.
    """
    (length, ratio, torque, rpm), expected = REFERENCE_CASES[case]
    result = motor_analysis(length, torque, rpm, length_to_diameter=ratio)
    for name, value in expected.items():
        assert_near_equal(result[name], value, tolerance=max(printed_tolerance(value), 1e-9))


def test_efficiency_residual_and_power_balance():
    # Paper eq. 24 at the solution: eta T_em = Q_r/G (1e-12 relative, solved to machine
    # precision), and P_in = P_out + losses, P_out = Q_r omega_rotor (identities, 1e-14).
    result = motor_analysis(
        np.array([0.1, 0.131]),
        [[600.0, 300.0], [1200.0, 800.0]],
        [[1300.0, 2500.0], [1193.7, 1500.0]],
    )
    torque = np.array([[600.0, 300.0], [1200.0, 800.0]])
    rpm = np.array([[1300.0, 2500.0], [1193.7, 1500.0]])
    assert_near_equal(result["efficiency"] * result["em_torque"], torque / 4.0, tolerance=1e-12)
    assert_near_equal(result["output_power"], torque * rpm * np.pi / 30.0, tolerance=1e-14)
    assert_near_equal(
        result["input_power"], result["output_power"] + result["power_loss"], tolerance=1e-14
    )


def test_voltage_limit_report():
    # Case A (L/D = 1/3, 1193.7 rpm): the back-EMF omega Psi_F = 3000.095 rad/s * 0.29958 Wb
    # = 898.8 V alone exceeds V_lim = 400 V, so the MTPA point is beyond the voltage limit.
    # Hand check from the printed case A values (R 0.02348894 ohm, L_d 7.4966e-4 H, L_q
    # 1.04832e-3 H, I_q 111.979 A, I_d -12.349 A): U_d = -352.47 V, U_q = 873.63 V,
    # |U| = 942.05 V (5 digits: 1e-5). T_em < T_lim nonetheless: T_lim assumes flux weakening.
    # Case C is within the limit.
    case_a = motor_analysis(0.131, 1200.0, 1193.7, length_to_diameter=1.0 / 3.0)
    case_c = motor_analysis(0.08, 300.0, 1500.0)
    assert case_a["beyond_voltage_limit"] and not case_c["beyond_voltage_limit"]
    assert_near_equal(case_a["voltage"], 942.05, tolerance=1e-5)
    assert_near_equal(case_a["voltage_margin"], 1.0 - case_a["voltage"] / 400.0, tolerance=1e-14)
    assert case_c["voltage"] < 400.0 and case_c["voltage_margin"] > 0.0
    assert case_a["voltage_torque_margin"] > 0.0


def test_torque_margin_definition():
    # Torque margin = T_pk/T_em - 1 (paper Sec. V, docs theory/motor 'Torque margin'): case C,
    # T_pk 93.4297526 and T_em 77.42764173 from docs theory/motor 'Validation' -> 0.2066719,
    # to the printed precision (1e-8).
    result = motor_analysis(0.08, 300.0, 1500.0)
    assert_near_equal(result["torque_margin"], 93.4297526 / 77.42764173 - 1.0, tolerance=1e-8)


def _group(nm=2, nn=3, **options):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "motor", MotorGroup(num_motors=nm, num_nodes=nn, **options), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("length", np.linspace(0.08, 0.15, nm))
    prob.set_val("rotor_torque", np.linspace(150.0, 900.0, nm * nn).reshape(nm, nn))
    prob.set_val("rotor_rpm", np.linspace(3000.0, 1100.0, nm * nn).reshape(nm, nn))
    prob.run_model()
    return prob


def test_vectorized_group_matches_single_runs():
    # Five motors (as in the LPC problem) at three operating points each, one call, against one
    # wrapper call per (motor, point): same arithmetic, agreement to 1e-10 relative.
    prob = _group(nm=5, nn=3)
    lengths = prob.get_val("length")
    torque, rpm = prob.get_val("rotor_torque"), prob.get_val("rotor_rpm")
    for i in (0, 4):
        for j in range(3):
            single = motor_analysis(lengths[i], torque[i, j], rpm[i, j])
            for name in ("em_torque", "efficiency", "input_power", "torque_limit", "current"):
                assert_near_equal(prob.get_val(name)[i, j], single[name], tolerance=1e-10)
            for name in ("mass", "inductance_d", "inductance_q", "flux_linkage"):
                assert_near_equal(prob.get_val(name)[i], single[name], tolerance=1e-12)


def test_group_totals():
    # Totals by the DirectSolver (adjoint) against complex step through every inner solve
    # (exact: 1e-9) and against central finite differences (1e-5, FD truncation).
    prob = _group()
    of = [
        "mass",
        "peak_torque",
        "efficiency",
        "input_power",
        "em_torque",
        "torque_margin",
        "voltage_margin",
        "voltage_torque_margin",
        "inductance_d",
        "flux_linkage",
    ]
    wrt = ["length", "rotor_torque", "rotor_rpm"]
    data = prob.check_totals(of=of, wrt=wrt, method="cs", out_stream=None)
    assert_check_totals(data, atol=1e-9, rtol=1e-9)
    data = prob.check_totals(
        of=of, wrt=wrt, method="fd", form="central", step=1e-7, step_calc="rel_avg", out_stream=None
    )
    assert_check_totals(data, atol=1e-5, rtol=1e-5)


def test_group_totals_diameter_input():
    # With length_to_diameter None the diameter is a second design input; cs totals, 1e-9.
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "motor", MotorGroup(num_nodes=2, length_to_diameter=None), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("length", 0.1)
    prob.set_val("diameter", 0.25)
    prob.set_val("rotor_torque", [[500.0, 300.0]])
    prob.set_val("rotor_rpm", [[1200.0, 2000.0]])
    prob.run_model()
    data = prob.check_totals(
        of=["mass", "efficiency", "torque_margin"],
        wrt=["length", "diameter"],
        method="cs",
        out_stream=None,
    )
    assert_check_totals(data, atol=1e-9, rtol=1e-9)


def test_solver_configuration(tmp_path):
    # check_config(checks=['solvers']) is clean, and no partial is approximated by OpenMDAO.
    prob = _group()
    report = tmp_path / "solvers.txt"
    prob.check_config(checks=["solvers"], out_file=str(report))
    assert "WARNING" not in report.read_text()
    assert_no_approx_partials(prob.model, method="any")


def _isolated(comp, source):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("comp", comp, promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.final_setup()
    for io in (prob.model.list_inputs, prob.model.list_outputs):
        for _, meta in io(out_stream=None, prom_name=True):
            prob.set_val(meta["prom_name"], source.get_val(meta["prom_name"]))
    prob.run_model()
    return prob


@pytest.mark.parametrize(
    "comp_class, method",
    [
        (MotorLossComp, "cs"),  # analytic partials
        (MotorMarginComp, "cs"),  # analytic partials
        (EMTorqueComp, "fd"),  # partials by vectorized complex step: check with FD
        (TorqueLimitComp, "fd"),  # partials by vectorized complex step: check with FD
    ],
)
def test_component_partials(comp_class, method):
    # Analytic partials against complex step: 1e-10. Complex-step partials against central FD
    # (relative step 1e-6): 1e-5 relative, FD truncation and round-off.
    source = _group()
    prob = _isolated(comp_class(num_motors=2, num_nodes=3), source)
    if method == "cs":
        data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
        assert_check_partials(data, atol=1e-10, rtol=1e-10)
    else:
        data = prob.check_partials(
            method="fd",
            form="central",
            step=1e-6,
            step_calc="rel_avg",
            compact_print=True,
            out_stream=None,
        )
        assert_check_partials(data, atol=1e-6, rtol=1e-5)


def test_torque_limit_is_largest_quartic_root():
    # T_lim (bracketed solve) equals the largest real root of the
    # docs theory/motor 'Voltage-limited torque' quartic found by numpy.roots on the raw reference
    # coefficients A..E: 1e-9 relative (root conditioning).
    from lpc_mdo.components.motor.parameters import MotorParameters
    from lpc_mdo.components.motor.torque_limit import _quartic

    prob = _group()
    values = {
        name: prob.get_val(name)
        for name in ("resistance", "inductance_d", "inductance_q", "flux_linkage", "rotor_rpm")
    }
    scale, b, c, d, e = _quartic(values, MotorParameters())
    torque_limit = prob.get_val("torque_limit")
    for idx in np.ndindex(torque_limit.shape):
        roots = np.roots([1.0, b[idx], c[idx], d[idx], e[idx]]) * scale[idx]
        largest = np.max(roots[np.abs(roots.imag) < 1e-9 * np.abs(roots)].real)
        assert_near_equal(torque_limit[idx], largest, tolerance=1e-9)


@pytest.mark.parametrize(
    "kwargs, pattern",
    [
        ({"length": -0.1}, r"motor: 'length' = -0.1 is out of range: must be > 0 \(m\)"),
        ({"rotor_rpm": 0.0}, r"motor: 'rotor_rpm' = 0.0 is out of range: must be > 0 \(rpm\)"),
        ({"rotor_torque": -50.0}, r"'rotor_torque' = -50.0 is out of range: must be > 0 \(N\*m\)"),
        ({"length_to_diameter": 0.0}, r"'length_to_diameter' = 0.0 is out of range: must be > 0$"),
        ({"gear_ratio": np.nan}, r"'gear_ratio' = nan is out of range: must be a finite number"),
        ({"rotor_torque": [1.0, 2.0], "rotor_rpm": [1.0, 2.0, 3.0]}, r"must be scalars"),
    ],
)
def test_wrapper_bad_inputs_raise(kwargs, pattern):
    args = {"length": 0.1, "rotor_torque": 500.0, "rotor_rpm": 1200.0}
    args.update(kwargs)
    with pytest.raises(ValueError, match=pattern):
        motor_analysis(**args)


def test_group_zero_rpm_raises():
    prob = _group(nm=1, nn=2)
    prob.set_val("rotor_rpm", [[1200.0, 0.0]])
    with pytest.raises(
        om.AnalysisError,
        match=r"'rotor_rpm\[0, 1\]' = 0.0 is out of range: "
        r"must be > 0 \(rpm\)",
    ):
        prob.run_model()


def test_stall_raises():
    # 1500 N*m at 1200 rpm on a 6 cm motor: the copper loss grows faster than the torque, no
    # T_em satisfies eq. 24. A clear AnalysisError, not NaN.
    with pytest.raises(
        om.AnalysisError,
        match=r"no electromagnetic torque balances "
        r"rotor_torque = 1500 N\*m",
    ):
        motor_analysis(0.06, 1500.0, 1200.0)


def test_too_short_motor_raises():
    # Below about 0.056 m (L/D = 0.5) the equivalent circuit gives L_q < L_d, where the MTPA
    # quartic (and reluctance torque) does not exist: a clear AnalysisError.
    with pytest.raises(
        om.AnalysisError,
        match=r"inductance_q - inductance_d = .* is outside the allowed range .* minimum stack "
        r"length",
    ):
        motor_analysis(0.05, 100.0, 1500.0)


def test_wrapper_returns_floats_for_scalars():
    result = motor_analysis(0.1, 500.0, 1200.0)
    for name in (
        "mass",
        "peak_torque",
        "efficiency",
        "input_power",
        "flux_linkage",
        "inductance_d",
        "inductance_q",
    ):
        assert isinstance(result[name], float) and np.isfinite(result[name])
    assert isinstance(result["beyond_voltage_limit"], bool)


def test_winding_for_the_bus_scales_voltage_and_current_only():
    # Rewinding a motor for its bus (docs theory/motor 'Winding for the bus'): W = pi D_i A_bar/
    # (2 m I_w), so at 2.5 times the rated current the motor has 1/2.5 of the turns. An ideal
    # rewinding with the same slot fill (Hendershot & Miller, ch. 5: the turns scale the EMF
    # constant and the phase current inversely, the ampere-turns and copper loss stay) leaves
    # torque, losses and efficiency unchanged and scales the voltage by 1/2.5 and the current by
    # 2.5; R, L_d, L_q by 1/2.5**2 and Psi_F by 1/2.5. Case A, hand-computed turns: 41.1549 at
    # 120 A (the reference's W) and 16.4619 at 300 A. Tolerance 1e-9 (the inner solves).
    (length, ratio, torque, rpm), _ = REFERENCE_CASES["A"]
    base = motor_analysis(length, torque, rpm, length_to_diameter=ratio)
    rewound = motor_analysis(length, torque, rpm, length_to_diameter=ratio, rated_current=300.0)
    k = 120.0 / 300.0
    d_i = base["diameter"] / 1.25
    turns = np.pi * d_i * 30.0e3 / (2 * 3 * np.array([120.0, 300.0]))
    assert_near_equal(turns, [41.15486376, 16.46194550], 1e-8)
    for name in ("em_torque", "efficiency", "power_loss", "copper_loss", "mass", "peak_torque"):
        assert_near_equal(rewound[name], base[name], 1e-9)
    for name, power in (
        ("voltage", 1),
        ("flux_linkage", 1),
        ("current", -1),
        ("resistance", 2),
        ("inductance_d", 2),
        ("inductance_q", 2),
    ):
        assert_near_equal(rewound[name], base[name] * k**power, 1e-9)
    # The back-EMF amplitude omega_e Psi_F with the hand-computed winding: Psi_F = W phi.
    omega_e = rpm * 4.0 * 2.0 * np.pi / 60.0 * 6
    assert_near_equal(
        omega_e * rewound["flux_linkage"], omega_e * turns[1] * 0.29958174 / turns[0], 1e-7
    )


def test_smooth_min_of_peak_and_voltage_limited_torque():
    # s(x) = -ln(exp(-k) + exp(-k x))/k against the exact minimum: at x = 1 the gap is ln(2)/k
    # (k = 100: 0.00693), 7/k away it is below 1e-4 (1e-3 relative to ln 2/k: exp(-7)), and s
    # never exceeds min(1, x). Complex step of s equals its stated slope (1e-12).
    k = 100.0
    x = np.array([0.5, 0.93, 0.999, 1.0, 1.001, 1.07, 2.0])
    value, slope = smooth_min_ratio(x, k)
    exact = -np.log(np.exp(-k) + np.exp(-k * x)) / k
    assert_near_equal(value, exact, tolerance=1e-13)
    assert_near_equal(value[3], 1.0 - np.log(2.0) / k, tolerance=1e-14)
    gap = np.minimum(1.0, x) - value
    assert np.all(gap >= 0.0) and np.all(gap <= np.log(2.0) / k + 1e-15)
    assert np.all(gap[[0, 1, 5, 6]] < 1e-4)
    cs, _ = smooth_min_ratio(x + 1e-30j, k)
    assert_near_equal(cs.imag / 1e-30, slope, tolerance=1e-12)


def test_torque_margin_takes_the_voltage_limited_torque():
    # At a point where T_lim < T_pk the available torque is the voltage-limited one: margin
    # T_lim/T_em - 1 to the smooth-min error (T_lim/T_pk far from 1: below 1e-6 absolute);
    # where T_lim >> T_pk it is the paper's T_pk/T_em - 1. Partials near T_lim = T_pk, where the
    # smooth minimum bends, against complex step: 1e-10.
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("margins", MotorMarginComp(num_motors=1, num_nodes=4), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("em_torque", [[100.0, 100.0, 100.0, 100.0]])
    prob.set_val("peak_torque", [200.0])
    prob.set_val("torque_limit", [[150.0, 199.0, 201.5, 900.0]])
    prob.set_val("peak_current", [400.0])
    prob.set_val("current", [[150.0, 150.0, 150.0, 150.0]])
    prob.run_model()
    margin = prob.get_val("torque_margin")[0]
    assert_near_equal(margin[[0, 3]], [0.5, 1.0], tolerance=1e-6)
    assert margin[1] < 0.99 and margin[2] < 1.0
    assert_near_equal(prob.get_val("current_margin")[0], np.full(4, 1.0 - 150.0 / 400.0), 1e-14)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)
