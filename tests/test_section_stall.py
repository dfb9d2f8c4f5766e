"""Section lift limit: the polar's c_l,max(Re, M), the strip ratios and their KS aggregate."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.components.aero.polar import LinearQuadraticPolar
from lpc_mdo.components.aero.section_stall import SectionStallRatioComp
from lpc_mdo.components.ks import KSComp
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.condition_kinds import wing_stall_limit


def _first_dominant_extremum(alpha_deg, cl, window=3.0, sign=1.0):
    """Hand rule of the stall point: from 0 deg, the first cl not exceeded in the next 3 deg."""
    i = int(np.argmin(np.abs(alpha_deg)))
    step = 1 if sign > 0 else -1
    while 0 <= i + step < alpha_deg.size:
        ahead = (sign * (alpha_deg - alpha_deg[i]) > 0) & (
            sign * (alpha_deg - alpha_deg[i]) <= window + 1e-12
        )
        if sign * cl[i] >= np.max(sign * cl[ahead]):
            return cl[i]
        i += step
    return cl[i]


@pytest.mark.parametrize(("i_re", "i_mach"), [(0, 0), (5, 1), (6, 2), (8, 3)])
def test_max_lift_at_table_nodes_from_the_table_arrays(i_re, i_mach):
    # Independent number: the stall point read off the table arrays by hand (first local maximum
    # of cl going up from 0 deg that the next 3 deg do not exceed; mirrored for the minimum). At
    # a tabulated (Re, M) the C1 interpolant passes through its node: equal to 1e-12.
    polar = get_polar("ls413")
    alpha_deg = np.degrees(polar.table_alpha)
    cl = polar.table_cl[:, i_re, i_mach]
    re, mach = polar.table_reynolds[i_re], polar.table_mach[i_mach]
    low, high, *_ = polar.max_lift_coefficients(np.array([re]), np.array([mach]))
    assert_near_equal(high[0], _first_dominant_extremum(alpha_deg, cl, sign=1.0), 1e-12)
    assert_near_equal(low[0], _first_dominant_extremum(alpha_deg, cl, sign=-1.0), 1e-12)


def test_max_lift_of_the_ls417_table_against_the_wind_tunnel():
    # Published data: GA(W)-1 = LS(1)-0417 in the Langley low-turbulence tunnel, Re 2e6-2e7,
    # M 0.10-0.28: "maximum section lift coefficients greater than 2.0" (McGhee and Beasley,
    # NASA TN D-7428, 1973, summary), rising with Reynolds number. The table (NeuralFoil, a
    # model of the section) within 5 % below that over Re 2e6-1e7 at M 0.15, and rising.
    polar = get_polar("ls417")
    re = np.array([2e6, 3e6, 5e6, 1e7])
    _, high, *_ = polar.max_lift_coefficients(re, np.full(4, 0.15))
    assert np.all(high >= 0.95 * 2.0)
    assert np.all(np.diff(high) > 0.0)


def test_max_lift_between_nodes_is_smooth_and_derivatives_match():
    # The Re and M derivatives against central differences of the interpolant (1e-6).
    polar = get_polar("ls413")
    re = np.array([1.5e6, 4.0e6, 7.7e6])
    mach = np.array([0.05, 0.17, 0.28])
    low, high, dlow_re, dhigh_re, dlow_m, dhigh_m = polar.max_lift_coefficients(re, mach)
    h_re, h_m = 1e-6 * re, 1e-6
    up = polar.max_lift_coefficients(re + h_re, mach)
    down = polar.max_lift_coefficients(re - h_re, mach)
    assert_near_equal(dhigh_re, (up[1] - down[1]) / (2 * h_re), 1e-6)
    assert_near_equal(dlow_re, (up[0] - down[0]) / (2 * h_re), 1e-6)
    up = polar.max_lift_coefficients(re, mach + h_m)
    down = polar.max_lift_coefficients(re, mach - h_m)
    assert_near_equal(dhigh_m, (up[1] - down[1]) / (2 * h_m), 1e-6)
    assert_near_equal(dlow_m, (up[0] - down[0]) / (2 * h_m), 1e-6)
    # Between the nodes it lies within the stall cl of the 4 surrounding table slices (the data
    # are monotone in Re and M there, so the C1 Hermite interpolant does not overshoot).
    for k in range(re.size):
        i = np.searchsorted(polar.table_reynolds, re[k]) - 1
        j = np.searchsorted(polar.table_mach, mach[k]) - 1
        for value, corners in ((low[k], polar.cl_stall[0]), (high[k], polar.cl_stall[1])):
            box = corners[i : i + 2, j : j + 2]
            assert box.min() <= value <= box.max()


def test_max_lift_outside_the_table_raises():
    # The wing table's stated range: Re <= 1e7, M <= 0.6; beyond it an AnalysisError names the
    # polar and the value, no clip.
    polar = get_polar("ls413")
    with pytest.raises(om.AnalysisError, match="Reynolds number"):
        polar.max_lift_coefficients(np.array([1.2e7]), np.array([0.2]))
    with pytest.raises(om.AnalysisError, match="Mach number"):
        polar.max_lift_coefficients(np.array([3e6]), np.array([0.65]))


def _ratio_problem(cl, reynolds, mach, rho=200.0, speed_fraction=1.0):
    nn, ns = cl.shape
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "stall",
        SectionStallRatioComp(num_nodes=nn, num_span_panels=ns, speed_fraction=speed_fraction),
        promotes_inputs=["*"],
    )
    prob.model.add_subsystem("ks", KSComp(vec_size=nn, width=2 * ns, rho=rho))
    prob.model.connect("stall.stall_ratio", "ks.g")
    prob.setup(force_alloc_complex=True)
    prob.set_val("sectional_cl", cl)
    prob.set_val("reynolds", reynolds)
    prob.set_val("mach", mach)
    prob.run_model()
    return prob


def _strips(nn=2, ns=6, seed=3):
    rng = np.random.default_rng(seed)
    return (
        rng.uniform(-0.9, 1.6, (nn, ns)),
        rng.uniform(2e5, 9.5e6, nn * ns),
        rng.uniform(0.0, 0.3, nn * ns),
    )


@pytest.mark.parametrize("speed_fraction", [1.0, 1.0 / 1.2])
def test_partials(speed_fraction):
    prob = _ratio_problem(*_strips(), speed_fraction=speed_fraction)
    data = prob.check_partials(method="cs", out_stream=None, compact_print=True)
    assert_check_partials(data, atol=1e-9, rtol=1e-9)


def test_section_maximum_at_the_stall_speed():
    # With speed_fraction f the maxima are the polar's at f Re and f M (1e-12): a 1-g condition
    # at 1.2 V_S takes them at its stall speed's flow, where c_l,max is lower (Re 4e6 -> 3.3e6).
    cl, re, mach = _strips()
    f = 1.0 / 1.2
    prob = _ratio_problem(cl, re, mach, speed_fraction=f)
    low, high, *_ = get_polar("ls413").max_lift_coefficients(f * re, f * mach)
    nn, ns = cl.shape
    expected = np.concatenate([cl / high.reshape(nn, ns), cl / low.reshape(nn, ns)], axis=1)
    assert_near_equal(prob.get_val("stall.stall_ratio"), expected, 1e-12)
    unscaled = _ratio_problem(cl, re, mach).get_val("stall.stall_ratio")
    positive = cl > 0.0
    assert np.all(prob.get_val("stall.stall_ratio")[:, :ns][positive] > unscaled[:, :ns][positive])


def test_ratios_and_ks_against_hand_computation():
    # Independent numbers: r+ = c_l / c_l,max and r- = c_l / c_l,min per strip from the polar's
    # table values, and the KS by its definition ln(sum exp(rho g))/rho in long double,
    # without the component's shift (1e-12); the KS is within [max, max + ln(2 ns)/rho].
    cl, re, mach = _strips()
    prob = _ratio_problem(cl, re, mach)
    low, high, *_ = get_polar("ls413").max_lift_coefficients(re, mach)
    nn, ns = cl.shape
    expected = np.concatenate([cl / high.reshape(nn, ns), cl / low.reshape(nn, ns)], axis=1)
    ratio = prob.get_val("stall.stall_ratio")
    assert_near_equal(ratio, expected, 1e-12)
    rho = 200.0
    hand = np.log(np.sum(np.exp(rho * expected.astype(np.longdouble)), axis=1)) / rho
    ks = prob.get_val("ks.KS")
    assert_near_equal(ks, hand.astype(float), 1e-12)
    assert np.all(ks >= expected.max(axis=1))
    assert np.all(ks <= expected.max(axis=1) + np.log(2 * ns) / rho)


def test_negative_stall_counts_in_the_same_row():
    # A push-over: every strip at c_l = 0.9 c_l,min gives r- = 0.9 and r+ < 0, so the row's KS
    # is 0.9 + ln(ns)/rho exactly (ns equal largest entries).
    re = np.full(5, 3.0e6)
    mach = np.full(5, 0.2)
    low, *_ = get_polar("ls413").max_lift_coefficients(re, mach)
    prob = _ratio_problem((0.9 * low)[None], re, mach)
    assert_near_equal(prob.get_val("ks.KS")[0], 0.9 + np.log(5) / 200.0, 1e-8)


def test_a_polar_without_a_table_is_refused():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "stall", SectionStallRatioComp(num_span_panels=2, airfoil=LinearQuadraticPolar())
    )
    with pytest.raises(ValueError, match="option 'airfoil'"):
        prob.setup()


def test_limits_of_the_reference_vehicle():
    # lpc_reference.toml: kappa = 0.9 (Raymer), 1.2 V_S in the 1-g conditions (14 CFR
    # 23.65(a)(4)): 0.9 / 1.2^2 = 0.625; the load cases 0.9.
    limits = reference_vehicle().constraints
    assert_near_equal(wing_stall_limit(limits), 0.625, 1e-12)
    assert_near_equal(wing_stall_limit(limits, load_case=True), 0.9, 1e-12)
