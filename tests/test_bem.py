"""Tests for the BEM components: BEMInflowComp, BEMLoadsComp and RotorPerformanceComp."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_check_totals
from rotor_cases import BLADES, HUB, NRAD, RADIUS, bem_problem, stations
from scipy.optimize import brentq

from lpc_mdo.components.aero.polar import LinearQuadraticPolar, Polar, PolarValues
from lpc_mdo.components.rotor.bem_inflow import BEMInflowComp
from lpc_mdo.components.rotor.bem_loads import BEMLoadsComp, RotorPerformanceComp


class ReMachPolar(Polar):
    """Test polar with Reynolds and Mach dependence (exercises those partial paths).

    cl = cl_ref / sqrt(1 - M^2) (Prandtl-Glauert), cd = cd_ref (Re/1e6)^-0.2,
    with docs theory/aerodynamics 'Linear-quadratic polar' polar as cl_ref, cd_ref.
    """

    def __init__(self):
        self.base = LinearQuadraticPolar()

    def evaluate(self, alpha, reynolds, mach):
        alpha, reynolds, mach = np.broadcast_arrays(alpha, reynolds, mach)
        b = self.base.evaluate(alpha, reynolds, mach)
        pg = 1.0 / np.sqrt(1.0 - mach**2)
        re_factor = (reynolds / 1e6) ** -0.2
        cd = b.cd * re_factor
        zeros = np.zeros(alpha.shape)
        return PolarValues(
            cl=b.cl * pg,
            cd=cd,
            dcl_dalpha=b.dcl_dalpha * pg,
            dcd_dalpha=b.dcd_dalpha * re_factor,
            dcl_dreynolds=zeros,
            dcd_dreynolds=-0.2 * cd / reynolds,
            dcl_dmach=b.cl * mach * pg**3,
            dcd_dmach=zeros,
        )


class NaNPolar(LinearQuadraticPolar):
    """A broken polar that returns NaN lift (the solve must raise, not return NaN)."""

    def evaluate(self, alpha, reynolds, mach):
        v = super().evaluate(alpha, reynolds, mach)
        return PolarValues(np.full(np.shape(v.cl), np.nan), *list(v.__dict__.values())[1:])


@pytest.mark.parametrize(
    "options",
    [
        {},
        {"tip_loss_form": "bladead", "hub_loss": False},
        {"tip_loss": False},
    ],
)
def test_partials(options):
    prob = bem_problem(polar=ReMachPolar(), **options)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-8, rtol=1e-8)


def test_totals_through_solve_linear():
    # The inflow angle is inverted by BEMInflowComp.solve_linear (no DirectSolver).
    for mode in ("fwd", "rev"):
        prob = bem_problem(performance=False, mode=mode)
        data = prob.check_totals(
            of=["thrust", "torque", "thrust_per_span"],
            wrt=["rpm", "axial_velocity", "chord", "twist", "radius", "station_radius"],
            method="cs",
            compact_print=True,
            out_stream=None,
        )
        assert_check_totals(data, atol=1e-7, rtol=1e-7)


def _prandtl(b, r, big_r, rh, phi):
    s = np.abs(np.sin(phi))
    f_tip = 2 / np.pi * np.arccos(np.exp(-b / 2 * (big_r - r) / (r * s)))
    f_hub = 2 / np.pi * np.arccos(np.exp(-b / 2 * (r - rh) / (rh * s)))
    return f_tip * f_hub


def test_against_independent_ning_solution():
    # Independent check: Ning's original residual R_N = sin(phi)(1 - k) - (V_x/V_t) cos(phi)
    # (1 + k') (propeller form, k = sigma C_x/(4 F sin^2), k' = sigma C_theta/(4 F sin cos)),
    # solved station by station with scipy's brentq from the first sign change above phi = 0;
    # then the momentum-form loads of docs theory/rotors 'Loads and coefficients'
    # (dT = 4 pi r rho u_x (u_x - V_x) F, dQ = 2 pi r^2 rho u_x u_theta F). Tolerances:
    # 1e-10 rad on phi, 1e-9 relative on loads.
    prob = bem_problem()
    polar = LinearQuadraticPolar()
    r, _ = stations()
    chord, twist = prob.get_val("chord"), prob.get_val("twist")
    rpm, vx = prob.get_val("rpm"), prob.get_val("axial_velocity")
    rho = prob.get_val("density")
    phi_bem = prob.get_val("inflow_angle")
    thrust_ps, drag_ps = prob.get_val("thrust_per_span"), prob.get_val("drag_per_span")
    for i in range(2):
        b = BLADES[i]
        for j in range(2):
            for k in range(NRAD):
                vt = rpm[i, j] * np.pi / 30 * r[i, k]
                sigma = b * chord[i, k] / (2 * np.pi * r[i, k])

                def coefficients(phi, i=i, k=k):
                    p = polar.evaluate(twist[i, k] - phi, 1e6, 0.1)
                    cx = p.cl * np.cos(phi) - p.cd * np.sin(phi)
                    cth = p.cl * np.sin(phi) + p.cd * np.cos(phi)
                    return cx, cth

                def ning(phi, i=i, j=j, k=k, b=b, vt=vt, sigma=sigma):
                    f = _prandtl(b, r[i, k], RADIUS[i], HUB[i] * RADIUS[i], phi)
                    cx, cth = coefficients(phi)
                    kk = sigma * cx / (4 * f * np.sin(phi) ** 2)
                    kp = sigma * cth / (4 * f * np.sin(phi) * np.cos(phi))
                    return np.sin(phi) * (1 - kk) - vx[i, j] / vt * np.cos(phi) * (1 + kp)

                grid = np.linspace(1e-6, np.pi / 2 - 1e-6, 2001)
                values = ning(grid)
                first = np.flatnonzero(values[:-1] * values[1:] <= 0)[0]
                phi = brentq(ning, grid[first], grid[first + 1], xtol=1e-15, rtol=1e-15)
                assert abs(phi - phi_bem[i, j, k]) < 1e-10

                f = _prandtl(b, r[i, k], RADIUS[i], HUB[i] * RADIUS[i], phi)
                cx, cth = coefficients(phi)
                denominator = 4 * f * np.sin(phi) * np.cos(phi) + sigma * cth
                u_x = 4 * f * vt * np.sin(phi) ** 2 / denominator
                u_theta = 2 * vt * sigma * cth / denominator
                d_thrust = 4 * np.pi * r[i, k] * rho[j] * u_x * (u_x - vx[i, j]) * f
                d_torque = 2 * np.pi * r[i, k] ** 2 * rho[j] * u_x * u_theta * f
                np.testing.assert_allclose(b * thrust_ps[i, j, k], d_thrust, rtol=1e-9)
                np.testing.assert_allclose(b * r[i, k] * drag_ps[i, j, k], d_torque, rtol=1e-9)


def test_performance_values_and_partials():
    prob = om.Problem()
    prob.model.add_subsystem("p", RotorPerformanceComp(num_rotors=2, num_nodes=2), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("thrust", [[4000.0, 3000.0], [-200.0, 6000.0]])
    prob.set_val("torque", [[700.0, 650.0], [300.0, 2000.0]])
    prob.set_val("rpm", [[1200.0, 1100.0], [1500.0, 1800.0]])
    prob.set_val("axial_velocity", [[0.0, 5.0], [40.0, 60.0]])
    prob.set_val("radius", [1.5, 1.3])
    prob.set_val("density", [1.2, 1.0])
    prob.set_val("speed_of_sound", [340.0, 330.0])
    prob.run_model()
    # Hand-computed from docs theory/rotors 'Loads and coefficients' definitions for rotor 0,
    # node 0 (exact formulas):
    n, d, omega = 20.0, 3.0, 1200.0 * np.pi / 30.0
    p = omega * 700.0
    ct_h, cq_h = (
        4000.0 / (1.2 * np.pi * 1.5**2 * (omega * 1.5) ** 2),
        700.0 / (1.2 * np.pi * 1.5**3 * (omega * 1.5) ** 2),
    )
    expected = {
        "power": p,
        "thrust_coefficient": 4000.0 / (1.2 * n**2 * d**4),
        "power_coefficient": p / (1.2 * n**3 * d**5),
        "advance_ratio": 0.0,
        "efficiency": 0.0,
        "figure_of_merit": ct_h**1.5 / (np.sqrt(2) * cq_h),
        "tip_mach": omega * 1.5 / 340.0,
    }
    for name, value in expected.items():
        np.testing.assert_allclose(prob.get_val(name)[0, 0], value, rtol=1e-12, atol=1e-15)
    # Climb node of rotor 1: eta = J C_T / C_P (docs theory/rotors 'Loads and coefficients'),
    # 1e-12 relative.
    j_ct_cp = (
        prob.get_val("advance_ratio")
        * prob.get_val("thrust_coefficient")
        / prob.get_val("power_coefficient")
    )
    np.testing.assert_allclose(prob.get_val("efficiency")[1, 1], j_ct_cp[1, 1], rtol=1e-12)
    assert prob.get_val("figure_of_merit")[1, 0] < 0.0  # negative thrust: negative, not NaN
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


@pytest.mark.parametrize("edgewise", [False, True])
def test_helical_tip_mach_values_and_partials(edgewise):
    # Independent numbers by hand: a pusher of R 1.781 m at 1600 rpm in climb at V_x 60 m/s,
    # a = 340 m/s: Omega R = 298.40 m/s, helical sqrt(298.40^2 + 60^2)/340 = 0.89524 (Raymer's
    # helical tip speed, sec. 10.4); with an in-plane velocity of (3, 4) m/s at its advancing
    # blade sqrt((298.40 + 5)^2 + 60^2)/340 = 0.90966. A lift rotor of R 1.5 m at 900 rpm in
    # edgewise flight with V_ip = (30, 40) m/s and V_x 5 m/s: advancing tip
    # sqrt(5^2 + (141.37 + 50)^2)/340 = 0.56305 (Johnson, Rotorcraft Aeromechanics: M_at =
    # M_tip (1 + mu)), 0.41606 without V_ip (the axial model leaves it out).
    prob = om.Problem(reports=False)
    perf = RotorPerformanceComp(num_rotors=2, num_nodes=2, edgewise=edgewise)
    prob.model.add_subsystem("p", perf, promotes=["*"])
    prob.setup(force_alloc_complex=True)
    prob.set_val("thrust", [[4000.0, 3000.0], [2000.0, 1500.0]])
    prob.set_val("torque", [[700.0, 650.0], [300.0, 200.0]])
    prob.set_val("rpm", [[1600.0, 1100.0], [900.0, 800.0]])
    prob.set_val("axial_velocity", [[60.0, 5.0], [5.0, -3.0]])
    prob.set_val("radius", [1.781, 1.5])
    prob.set_val("speed_of_sound", [340.0, 330.0])
    if edgewise:
        prob.set_val("inplane_velocity", [[[3.0, 4.0], [10.0, -2.0]], [[30.0, 40.0], [-1.0, 2.0]]])
    prob.run_model()
    mach = prob.get_val("helical_tip_mach")
    assert mach[0, 0] == pytest.approx(0.90966 if edgewise else 0.89524, abs=5e-5)
    assert mach[1, 0] == pytest.approx(0.56305 if edgewise else 0.41606, abs=5e-5)
    if not edgewise:  # a rotor without axial velocity: the rotational tip Mach number
        ratio = np.hypot(1.0, 3.0 / (800.0 * np.pi / 30.0 * 1.5))
        np.testing.assert_allclose(mach[1, 1], prob.get_val("tip_mach")[1, 1] * ratio, rtol=1e-12)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_helical_tip_mach_in_hover_has_the_zero_subgradient():
    # |V_ip| is not differentiable at V_ip = 0 (hover); the component gives the subgradient 0
    # there, and the value is the rotational tip Mach number.
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("p", RotorPerformanceComp(edgewise=True), promotes=["*"])
    prob.setup()
    prob.set_val("torque", 500.0)
    prob.run_model()
    assert prob.get_val("helical_tip_mach") == pytest.approx(prob.get_val("tip_mach"), rel=1e-14)
    jac = prob.compute_totals("helical_tip_mach", "inplane_velocity")
    np.testing.assert_array_equal(jac["helical_tip_mach", "inplane_velocity"], 0.0)


def test_reverse_and_windmilling_stations_converge():
    # Descent, hover, climb and windmilling (V_x up to 2.5 Omega R, negative thrust and torque)
    # on one rotor; a second rotor pitched to -20 deg (no root on [0, pi/2]: found at phi < 0).
    prob = om.Problem()
    opts = dict(num_rotors=2, num_nodes=6, num_radial=12)
    prob.model.add_subsystem("inflow", BEMInflowComp(**opts), promotes=["*"])
    prob.model.add_subsystem("loads", BEMLoadsComp(**opts), promotes=["*"])
    prob.setup()
    eta = (np.arange(12) + 0.5) / 12
    prob.set_val("radius", [1.0, 1.0])
    prob.set_val("hub_radius", [0.2, 0.2])
    prob.set_val("station_radius", np.tile(0.2 + 0.8 * eta, (2, 1)))
    prob.set_val("station_width", np.full((2, 12), 0.8 / 12))
    prob.set_val("chord", np.full((2, 12), 0.1))
    prob.set_val("twist", np.stack([np.radians(40.0 - 30.0 * eta), np.full(12, np.radians(-20))]))
    tip_speed = 1000 * np.pi / 30
    prob.set_val("rpm", np.full((2, 6), 1000.0))
    prob.set_val(
        "axial_velocity",
        np.tile([-3.0, 0.0, 10.0, 0.8 * tip_speed, 1.5 * tip_speed, 2.5 * tip_speed], (2, 1)),
    )
    prob.run_model()
    prob.model.run_apply_nonlinear()
    residual = prob.model.inflow._residuals["inflow_angle"]
    assert np.max(np.abs(residual)) < 1e-9
    phi = prob.get_val("inflow_angle")
    assert np.all(np.isfinite(prob.get_val("thrust"))) and np.all(np.isfinite(phi))
    thrust, torque = prob.get_val("thrust"), prob.get_val("torque")
    assert np.all(thrust[0, :3] > 0) and thrust[0, -1] < 0 and torque[0, -1] < 0  # windmill
    assert np.all(phi[1, 1] < 0) and thrust[1, 1] < 0  # pitched below zero lift: push air up


def test_bad_inputs_raise():
    prob = bem_problem(performance=False)
    prob.set_val("rpm", [[0.0, 1300.0], [1500.0, 1800.0]])
    with pytest.raises(
        om.AnalysisError,
        match=r"'rpm\[0, 0\]' = 0.0 is out of range: "
        r"must be > 0 \(rpm\)",
    ):
        prob.run_model()
    prob = bem_problem(performance=False)
    r, _ = stations()
    r[1, -1] = 1.3
    prob.set_val("station_radius", r)
    with pytest.raises(
        om.AnalysisError,
        match=r"'station_radius\[1, \d+\]' = 1.3 is out "
        r"of range: must be in \(0.18, 1.2\) \(m\)",
    ):
        prob.run_model()
    with pytest.raises(om.AnalysisError, match="BEM inflow-angle solve failed .*no sign change"):
        bem_problem(polar=NaNPolar(), performance=False)
    prob = om.Problem()
    prob.model.add_subsystem("i", BEMInflowComp(num_rotors=2, num_blades=[2, 0]))
    with pytest.raises(ValueError, match=r"'num_blades\[1\]' = 0 is out of range: must be >= 1"):
        prob.setup()
