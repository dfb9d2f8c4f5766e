"""BEM against independent numbers: public reference code, momentum theory, wind-tunnel data."""

import dataclasses

import numpy as np
import openmdao.api as om
import pytest
from rotor_cases import APC_GEOMETRY, APC_PERFORMANCE, APC_POLAR

from lpc_mdo.components.aero.polar import LinearQuadraticPolar
from lpc_mdo.components.atmosphere import AtmosphereComp
from lpc_mdo.components.geometry.blade import station_fractions
from lpc_mdo.components.rotor.bem_inflow import BEMInflowComp
from lpc_mdo.components.rotor.bem_loads import BEMLoadsComp, RotorPerformanceComp
from lpc_mdo.groups.bem_rotor import BEMRotorGroup
from lpc_mdo.vehicle import reference_vehicle

#: NACA 4412-like polar: a LinearQuadraticPolar fitted to the BladeAD NACA 4412 network's
#: spot values at Re = 1e6, M = 0.1 (docs theory/aerodynamics 'Airfoil polars'): cl0 = 0.472,
#: slope (0.895 - 0.038)/8 deg = 6.138 /rad, cd0 = 0.0066 and k = 0.0086 from cd(8 deg) = 0.0129;
#: stall 14 deg, cl_max 1.6.
NACA4412_LIKE = LinearQuadraticPolar(
    alpha_stall=(np.radians(-10.0), np.radians(14.0)),
    cl_stall=(-0.55, 1.6),
    cd_stall=(0.0156, 0.0175),
    cl0=0.472,
    cd0=0.0066,
    cl_alpha=6.138,
)


def _bem(
    r,
    width,
    chord,
    twist,
    radius,
    hub_radius,
    rpm,
    axial_velocity,
    density=1.225,
    speed_of_sound=343.0,
    viscosity=1.735e-5,
    **options,
):
    """One rotor, one node per axial velocity, stations given directly."""
    nn, nrad = len(axial_velocity), len(r)
    opts = dict(num_nodes=nn, num_radial=nrad, **options)
    prob = om.Problem()
    prob.model.add_subsystem("inflow", BEMInflowComp(**opts), promotes=["*"])
    prob.model.add_subsystem("loads", BEMLoadsComp(**opts), promotes=["*"])
    prob.model.add_subsystem("performance", RotorPerformanceComp(num_nodes=nn), promotes=["*"])
    prob.setup()
    for name, value in (
        ("station_radius", r),
        ("station_width", width),
        ("chord", chord),
        ("twist", twist),
    ):
        prob.set_val(name, np.asarray(value)[None])
    prob.set_val("radius", radius)
    prob.set_val("hub_radius", hub_radius)
    prob.set_val("rpm", np.full((1, nn), rpm))
    prob.set_val("axial_velocity", np.asarray(axial_velocity, dtype=float)[None])
    prob.set_val("density", np.full(nn, density))
    prob.set_val("speed_of_sound", np.full(nn, speed_of_sound))
    prob.set_val("dynamic_viscosity", np.full(nn, viscosity))
    prob.run_model()
    return prob


def test_bladead_example_reproduced():
    """BladeAD examples/ex_run_bem.py, docs theory/rotors 'Validation' table (public code run).

    R = 1.2 m, B = 2, 35 stations, chord 0.25 -> 0.05 m and twist 50 -> 20 deg
    (linear, the as-coded B-spline mapping of linear control points), 2000 rpm,
    rho = 1.22518316, the docs theory/aerodynamics 'Linear-quadratic polar' polar,
    with the public code's tip-loss form (docs theory/rotors 'Public-code compatibility')
    and quadrature (docs theory/rotors 'Public-code compatibility') switched on.
    Tolerance: the printed digits (relative 2e-6, 0.002 deg on phi).
    """
    n, radius = 35, 1.2
    eta, q = station_fractions(n, "bladead")
    prob = _bem(
        (0.2 + 0.8 * eta) * radius,
        0.8 * q * radius,
        np.linspace(0.25, 0.05, n),
        np.radians(np.linspace(50.0, 20.0, n)),
        radius,
        0.2 * radius,
        2000.0,
        [50.0, 0.0],
        density=1.22518316,
        tip_loss_form="bladead",
    )
    omega = 2000.0 * np.pi / 30.0
    ct_rotorcraft = prob.get_val("thrust")[0] / (
        1.22518316 * np.pi * radius**2 * (omega * radius) ** 2
    )
    phi = prob.get_val("inflow_angle", units="deg")[0][:, [0, n // 2, n - 1]]
    expected = {  # V_x = 50 m/s, V_x = 0
        "thrust": ([4684.063, 3621.662], 2e-6),
        "torque": ([1528.762, 831.885], 2e-6),
        "power": ([320183.2, 174229.7], 2e-6),
        "figure_of_merit": ([0.30072, 0.37572], 2e-5),
        "power_coefficient": ([0.088615, None], 2e-5),
        "efficiency": ([0.73147, 0.0], 2e-5),
    }
    for name, (values, rtol) in expected.items():
        for j, value in enumerate(values):
            if value is not None:
                np.testing.assert_allclose(prob.get_val(name)[0, j], value, rtol=rtol, atol=1e-12)
    np.testing.assert_allclose(ct_rotorcraft, [0.013379, 0.010345], rtol=5e-5)
    np.testing.assert_allclose(phi, [[52.300, 23.250, 15.085], [39.307, 7.689, 8.241]], atol=2e-3)


def test_hover_matches_momentum_theory():
    """Uniform-inflow rotor in hover, tip and hub loss off: induced power = momentum theory.

    Constant chord (sigma = 0.127), twist theta = phi + alpha with phi = atan(lambda R/r) and
    cl = 8 pi lambda^2 R/(B c r/R) (blade-element thrust = momentum thrust for uniform
    lambda = 0.05), a loss-free polar (cd = 1e-6, cl = 2 pi alpha). Ideal induced power
    P_i = T^1.5/sqrt(2 rho A) on the annulus A = pi (R^2 - r_h^2) (momentum theory, e.g.
    Leishman, Principles of Helicopter Aerodynamics, eq. 2.23). The BEM shaft power may only
    exceed it by the swirl loss and the small non-uniformity: within 2 %.
    """
    n, radius, hub, blades, chord, lam = 25, 1.0, 0.2, 4, 0.1, 0.05
    x = hub + (1 - hub) * (np.arange(n) + 0.5) / n
    cl = 8 * np.pi * lam**2 / (blades * chord * x)
    twist = np.arctan(lam / x) + cl / (2 * np.pi)
    polar = LinearQuadraticPolar(
        cl0=0.0, cd0=1e-6, cl_alpha=2 * np.pi, cd_stall=(1e-6, 1e-6), cl_stall=(-1.2, 1.2)
    )
    prob = _bem(
        x * radius,
        np.full(n, (1 - hub) / n),
        np.full(n, chord),
        twist,
        radius,
        hub * radius,
        1000.0,
        [0.0],
        num_blades=blades,
        polar=polar,
        tip_loss=False,
        hub_loss=False,
    )
    thrust, power = prob.get_val("thrust")[0, 0], prob.get_val("power")[0, 0]
    area = np.pi * (radius**2 - (hub * radius) ** 2)
    ideal = thrust**1.5 / np.sqrt(2 * 1.225 * area)
    assert 1.0 <= power / ideal < 1.02
    # The inflow is uniform: u_x = Omega r tan(phi) (V_x = 0, small swirl) within 2 % of the
    # momentum value lambda Omega R.
    omega = 1000.0 * np.pi / 30.0
    phi = prob.get_val("inflow_angle")[0, 0]
    u_x = omega * x * radius * np.tan(phi)
    np.testing.assert_allclose(u_x, np.sqrt(thrust / (2 * 1.225 * area)), rtol=0.02)


@pytest.mark.parametrize(
    "polar, thrust_tol, power_tol",
    [(NACA4412_LIKE, 0.05, 0.05), (LinearQuadraticPolar(), 0.10, 0.10)],
)
def test_lpc_lift_rotor_hover(polar, thrust_tol, power_tol):
    """
    Reference LPC lift rotor in hover at 100 m and 1200 rpm versus docs theory/rotors 'Validation'.

    docs theory/rotors 'Validation' gives T = 4863.5 N, P = 100.96 kW (FoM 0.798) from
    the public code with the BladeAD NACA 4412 neural network, the as-coded tip loss and
    quadrature (docs theory/rotors 'Public-code compatibility', Q9) and the 100 m atmosphere
    (CADDEE constants). That network is not available here, so the comparison is run
    with the public code's switches and

    - a NACA 4412-like LinearQuadraticPolar fitted to the network's spot values
      (docs theory/aerodynamics 'Airfoil polars'): T -1.9 %, P -4.0 %, within 5 %. The rest is
      the network's Reynolds and Mach dependence (tip Mach 0.56) and its non-quadratic drag,
      which the fit at M = 0.1 leaves out;
    - the project's default docs theory/aerodynamics 'Linear-quadratic polar' polar
      (cl0 = 0.5, slope 5.16 /rad vs 0.472 and 6.14 /rad of NACA 4412): T -8.3 %, P -7.5 %,
      within 10 %; the difference is the airfoil.
    """
    # The paper's initial blade (chord 0.3 -> 0.1 m, twist 30 -> 10 deg), which the public
    # code's numbers are for; the reference file's initial blade is wider (lpc_reference.toml).
    paper_blade = dataclasses.replace(
        reference_vehicle().lift_rotors[0],
        chord_cp=tuple(np.linspace(0.3, 0.1, 4)),
        twist_cp=tuple(np.radians(np.linspace(30.0, 10.0, 4))),
    )
    prob = om.Problem()
    prob.model.add_subsystem("atmosphere", AtmosphereComp(constants="caddee"), promotes=["*"])
    prob.model.add_subsystem(
        "rotor",
        BEMRotorGroup(
            rotors=[paper_blade],
            polar=polar,
            tip_loss_form="bladead",
            quadrature="bladead",
        ),
        promotes=["*"],
    )
    prob.setup()
    prob.set_val("altitude", 100.0)
    prob.set_val("rpm", 1200.0)
    prob.run_model()
    np.testing.assert_allclose(
        prob.get_val("density"), 1.213457, rtol=1e-6
    )  # docs theory/atmosphere table
    np.testing.assert_allclose(prob.get_val("thrust")[0, 0], 4863.5, rtol=thrust_tol)
    np.testing.assert_allclose(prob.get_val("power", units="kW")[0, 0], 100.96, rtol=power_tol)


def test_apc_sport_14x13():
    """APC Sport 14x13 (2 blades, R = 0.1778 m) against the UIUC wind-tunnel C_T, C_P, eta.

    BEM with the project defaults (classical tip and hub loss, hub 0.15 R as in lsdo_rotor's
    script, midpoint rule, 30 stations, geometry interpolated linearly at the stations) and the
    thin-airfoil-like APC_POLAR. Acceptance (issue): C_T and C_P within 15 % over
    J = 0.2 .. 0.9 and peak efficiency within 0.05. Achieved: C_T within 5.5 %, C_P within
    10.7 %, peak eta 0.780 vs 0.736 measured. (The polar matters: with the
    docs theory/aerodynamics 'Linear-quadratic polar' polar C_T is off by up to 48 %.) Reynolds
    effects are not modelled (the polar has none), so the rpm is immaterial.
    """
    radius, hub, n, rpm = 0.1778, 0.15, 30, 4000.0
    x = hub + (1 - hub) * (np.arange(n) + 0.5) / n
    chord = np.interp(x, APC_GEOMETRY[:, 0], APC_GEOMETRY[:, 1]) * radius
    twist = np.radians(np.interp(x, APC_GEOMETRY[:, 0], APC_GEOMETRY[:, 2]))
    j_data, ct_data, cp_data, eta_data = APC_PERFORMANCE.T
    prob = _bem(
        x * radius,
        np.full(n, (1 - hub) * radius / n),
        chord,
        twist,
        radius,
        hub * radius,
        rpm,
        j_data * rpm / 60.0 * 2 * radius,
        polar=APC_POLAR,
    )
    ct = prob.get_val("thrust_coefficient")[0]
    cp = prob.get_val("power_coefficient")[0]
    eta = prob.get_val("efficiency")[0]
    np.testing.assert_allclose(prob.get_val("advance_ratio")[0], j_data, rtol=1e-12)
    band = (j_data >= 0.2) & (j_data <= 0.9)
    assert np.max(np.abs(ct[band] / ct_data[band] - 1)) < 0.15
    assert np.max(np.abs(cp[band] / cp_data[band] - 1)) < 0.15
    assert abs(eta.max() - eta_data.max()) < 0.05
