"""lpc_mdo.api.bem and lpc_mdo.api.pitt_peters: plain-function rotor analyses."""

import numpy as np
import pytest
from rotor_cases import APC_GEOMETRY, APC_PERFORMANCE, APC_POLAR

import lpc_mdo.api as lpc

# LPC lift-rotor blade (vehicle file: chord 0.3 -> 0.1 m, twist 30 -> 10 deg, R = 1.524 m).
LPC = dict(
    radius=1.524,
    hub_radius=0.3048,
    num_blades=2,
    radial_stations=25,
    chord=np.linspace(0.3, 0.1, 25),
    twist_deg=np.linspace(30.0, 10.0, 25),
)


def test_bem_apc_sport_14x13_with_a_user_polar():
    # Issue acceptance through the function: the APC Sport 14x13 (UIUC wind-tunnel data,
    # shared/data/validation) with the thin-airfoil-like polar given as a user table
    # {alpha_deg, cl, cd} sampled from APC_POLAR every 0.5 deg from -20 to 25 deg: C_T and C_P
    # within 15 % over J = 0.2 .. 0.9, peak efficiency within 0.05 (the component test measures
    # 5.5 %, 10.7 % and +0.044 with the analytic polar).
    radius, hub, n, rpm = 0.1778, 0.15, 30, 4000.0
    x = hub + (1 - hub) * (np.arange(n) + 0.5) / n
    alpha = np.arange(-20.0, 25.01, 0.5)  # an XFOIL-like range; Viterna covers the rest
    pv = APC_POLAR.evaluate(np.radians(alpha), 1e5, 0.1)
    polar = {"alpha_deg": alpha, "cl": pv.cl, "cd": pv.cd}
    j_data, ct_data, cp_data, eta_data = APC_PERFORMANCE.T
    out = lpc.bem(
        radius,
        hub * radius,
        2,
        n,
        np.interp(x, APC_GEOMETRY[:, 0], APC_GEOMETRY[:, 1]) * radius,
        np.interp(x, APC_GEOMETRY[:, 0], APC_GEOMETRY[:, 2]),
        rpm,
        j_data * rpm / 60.0 * 2 * radius,
        polar,
    )
    np.testing.assert_allclose(out["station_radius"], x * radius, rtol=1e-12)
    band = (j_data >= 0.2) & (j_data <= 0.9)
    assert np.max(np.abs(out["thrust_coefficient"][band] / ct_data[band] - 1)) < 0.15
    assert np.max(np.abs(out["power_coefficient"][band] / cp_data[band] - 1)) < 0.15
    assert abs(out["efficiency"].max() - eta_data.max()) < 0.05
    assert out["normal_load"].shape == (j_data.size, n)


def test_bem_hover_outputs_are_consistent():
    # Scalar operating point -> floats and (num_radial,) arrays; the integral of the sectional
    # loads is the thrust and torque (midpoint rule over the returned widths); P = Omega Q;
    # FM = T^1.5/(sqrt(2 rho A) P) (closed forms, to round-off).
    out = lpc.bem(**LPC, rpm=1200.0, axial_velocity=0.0, airfoil="naca0012")
    assert np.ndim(out["thrust"]) == 0 and out["normal_load"].shape == (25,)
    w, r = out["station_width"], out["station_radius"]
    assert np.sum(w) == pytest.approx(1.524 - 0.3048, rel=1e-12)
    assert 2 * np.sum(out["normal_load"] * w) == pytest.approx(out["thrust"], rel=1e-10)
    assert 2 * np.sum(out["tangential_load"] * w * r) == pytest.approx(out["torque"], rel=1e-10)
    assert out["power"] == pytest.approx(out["torque"] * 1200 * np.pi / 30, rel=1e-12)
    area = np.pi * 1.524**2
    fm = out["thrust"] ** 1.5 / np.sqrt(2 * 1.225 * area) / out["power"]
    assert out["figure_of_merit"] == pytest.approx(fm, rel=1e-10)
    assert 0.5 < out["figure_of_merit"] < 0.9


def test_station_radii_equal_to_midpoints_give_the_same_answer():
    # Station radii given explicitly at the midpoints of n equal elements reproduce the int form.
    base = lpc.bem(**LPC, rpm=1100.0, axial_velocity=2.0, airfoil="naca0012")
    given = lpc.bem(
        **dict(LPC, radial_stations=base["station_radius"]),
        rpm=1100.0,
        axial_velocity=2.0,
        airfoil="naca0012",
    )
    np.testing.assert_allclose(given["station_width"], base["station_width"], rtol=1e-12)
    assert given["thrust"] == pytest.approx(base["thrust"], rel=1e-12)


def test_pitt_peters_at_zero_edgewise_speed_matches_bem_hover():
    # Issue acceptance (Pitt–Peters reproduces the BEM hover thrust within 2 % on the same
    # blade), here with a packaged airfoil table (Reynolds and Mach dependent NACA 0012) and
    # through the plain functions. Measured (2026-11-22): -0.2 % thrust, -0.4 % power.
    bem = lpc.bem(**LPC, rpm=1200.0, axial_velocity=0.0, airfoil="naca0012")
    pp = lpc.pitt_peters(
        **LPC,
        rpm=1200.0,
        edgewise_velocity=0.0,
        disk_angle_deg=0.0,
        airfoil="naca0012",
        num_azimuth=8,
    )
    assert pp["thrust"] == pytest.approx(bem["thrust"], rel=0.02)
    assert pp["power"] == pytest.approx(bem["power"], rel=0.03)
    lam0, lam_c, lam_s = pp["inflow_states"]
    assert abs(lam_c) < 1e-10 and abs(lam_s) < 1e-10
    np.testing.assert_allclose(
        pp["normal_load"], pp["normal_load"][:, :1] * np.ones((1, 8)), rtol=1e-10
    )


def test_pitt_peters_edgewise_trends_and_shapes():
    # Several operating points broadcast; tilting the disk back (alpha_d > 0: upflow) raises
    # the thrust at fixed rpm, forward tilt lowers it; forward flight gives lambda_c > 0 (more
    # inflow at the rear, Glauert) and an H-force against the motion (negative along e_x).
    # A blade in attached flow (twist 20 -> 6 deg): the vehicle file's initial blade (30 -> 10
    # deg) is stalled at its outer stations here (advancing tip M 0.64, where the NACA 0012
    # stalls at 6 deg), and tilting it back lowers its thrust.
    out = lpc.pitt_peters(
        **dict(LPC, twist_deg=np.linspace(20.0, 6.0, 25)),
        rpm=1200.0,
        edgewise_velocity=30.0,
        disk_angle_deg=[-5.0, 0.0, 5.0],
        airfoil="naca0012",
        num_azimuth=12,
    )
    assert out["thrust"].shape == (3,) and out["normal_load"].shape == (3, 25, 12)
    assert out["inflow_states"].shape == (3, 3) and out["azimuth"].shape == (12,)
    assert out["thrust"][0] < out["thrust"][1] < out["thrust"][2]
    assert np.all(out["inflow_states"][:, 1] > 0.0)
    assert np.all(out["inplane_force"][:, 0] < 0.0)


@pytest.mark.parametrize(
    "changes, field",
    [
        ({"radial_stations": [0.2, 0.5, 1.0]}, "radial_stations"),
        ({"radial_stations": 0}, "radial_stations"),
        ({"hub_radius": 2.0}, "hub_radius"),
        ({"chord": np.ones(7)}, "chord"),
        ({"chord": -0.1}, "chord"),
        ({"rpm": 0.0}, "rpm"),
        ({"airfoil": "naca9999"}, "airfoil"),
    ],
)
def test_bad_input_names_the_field(changes, field):
    kw = dict(LPC, rpm=1200.0, axial_velocity=0.0, airfoil="naca0012")
    kw.update(changes)
    with pytest.raises(ValueError, match=field):
        lpc.bem(**kw)


def test_pitt_peters_rejects_negative_speed():
    with pytest.raises(ValueError, match="edgewise_velocity"):
        lpc.pitt_peters(
            **LPC, rpm=1200.0, edgewise_velocity=-1.0, disk_angle_deg=0.0, airfoil="naca0012"
        )
