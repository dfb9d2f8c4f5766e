"""Compressibility stall of the rotor section and the blade-station stall limit."""

import numpy as np
import openmdao.api as om
import pytest

from lpc_mdo.components.aero.airfoil import TablePolar, airfoil_table_path, get_polar
from lpc_mdo.components.aero.compressible_stall import NACA0012_STALL_ONSET, naca0012_max_lift
from lpc_mdo.components.rotor.blade_stall import BladeStallRatioComp

# Leishman & Beddoes (J. AHS 34(3), 1989, Table 1), NACA 0012: C_N1 and alpha_1 (deg) at M.
_MEASURED = {0.4: (1.20, 12.5), 0.5: (1.05, 10.5), 0.6: (0.92, 8.5), 0.7: (0.68, 5.6)}


def test_rotor_section_maximum_lift_is_the_measured_one_above_mach_0_3():
    # Independent numbers: the measured stall-onset normal force C_N1 at alpha_1, as lift
    # C_N1 / cos(alpha_1), at every Reynolds number of the table (to the bisection's 1e-12).
    polar = get_polar("naca0012")
    for mach, (cn1, alpha1) in _MEASURED.items():
        expected = cn1 / np.cos(np.radians(alpha1))
        for reynolds in (5e5, 1e6, 3e6, 1e7):
            cl_min, cl_max, *_ = polar.max_lift_coefficients(np.array([reynolds]), np.array([mach]))
            assert cl_max[0] == pytest.approx(expected, abs=1e-9)
            assert cl_min[0] == pytest.approx(-expected, abs=1e-9)
        # The composite polar's peak: the stall blend (+-1.5 deg) rounds it, 6 % below the
        # measured maximum at M 0.5 and 13 % at M 0.7 (conservative).
        alpha = np.radians(np.linspace(0.0, 20.0, 4001))
        cl = polar.evaluate(alpha, np.full(alpha.shape, 1e6), np.full(alpha.shape, mach)).cl
        assert 0.85 * expected <= cl.max() <= expected + 1e-9


def test_prandtl_glauert_table_without_the_data_keeps_its_low_speed_stall():
    # Below M 0.3 the data give no ceiling: the stall points are the table's own; above it the
    # uncapped table's maximum grows with M (the error the data correct).
    capped = get_polar("naca0012")
    plain = TablePolar.from_npz(airfoil_table_path("naca0012"))
    low = plain.table_mach < 0.3
    assert np.array_equal(capped.alpha_stall[:, :, low], plain.alpha_stall[:, :, low])
    reynolds = np.array([1e6, 1e6])
    mach = np.array([0.5, 0.7])
    assert np.all(plain.max_lift_coefficients(reynolds, mach)[1] > 1.5)
    assert np.all(capped.max_lift_coefficients(reynolds, mach)[1] < 1.1)


def test_ceiling_rule_outside_the_data():
    assert np.isinf(naca0012_max_lift(0.2))
    last = NACA0012_STALL_ONSET[-1]
    assert naca0012_max_lift(0.9) == pytest.approx(last[1] / np.cos(np.radians(last[2])))


def _problem(nr=2, nrad=5):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "stall",
        BladeStallRatioComp(num_rotors=nr, num_radial=nrad, polar=get_polar("naca0012")),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    rng = np.random.default_rng(3)
    prob.set_val("angle_of_attack", rng.uniform(-0.1, 0.25, (nr, 1, nrad)))
    prob.set_val("rpm", [[1500.0], [1700.0]])
    prob.set_val("axial_velocity", [[3.0], [10.0]])
    prob.set_val("station_radius", np.linspace(0.3, 1.4, nrad)[None] * np.array([[1.0], [1.1]]))
    prob.set_val("chord", rng.uniform(0.1, 0.3, (nr, nrad)))
    return prob


def test_blade_stall_ratio_partials():
    prob = _problem()
    prob.run_model()
    data = prob.check_partials(method="cs", out_stream=None)
    for key, entry in data["stall"].items():
        reference = np.abs(entry["J_fd"]).max()
        assert np.abs(entry["J_fwd"] - entry["J_fd"]).max() <= 1e-9 * max(reference, 1.0), key


def test_station_where_the_table_reaches_the_measured_maximum_has_ratio_one():
    # A hover station at a tabulated Reynolds and Mach number (1e6, 0.5): the angle where that
    # table slice's cl, interpolated linearly here (independently of the polar's Hermite),
    # reaches the measured maximum (L&B) is its stall angle: r+ = 1 within the two
    # interpolations' difference (0.5 % here), r- = -r+.
    polar = get_polar("naca0012")
    a, mu, rho = 340.294, 1.7894e-5, 1.225
    mach, reynolds, radius = 0.5, 1e6, 1.0
    omega = mach * a / radius
    chord = reynolds * mu / (rho * omega * radius)
    r = int(np.flatnonzero(np.isclose(polar.table_reynolds, reynolds))[0])
    m = int(np.flatnonzero(np.isclose(polar.table_mach, mach))[0])
    attached = polar.table_alpha > 0.0
    alpha = np.interp(
        1.05 / np.cos(np.radians(10.5)),
        polar.table_cl[attached, r, m],
        polar.table_alpha[attached],
    )
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "stall", BladeStallRatioComp(num_radial=1, polar=polar), promotes=["*"]
    )
    prob.setup()
    prob.set_val("angle_of_attack", alpha)
    prob.set_val("rpm", omega * 30.0 / np.pi)
    prob.set_val("station_radius", radius)
    prob.set_val("chord", chord)
    prob.run_model()
    ratio = prob.get_val("blade_stall_ratio")[0]
    assert ratio[0] == pytest.approx(1.0, abs=5e-3)
    assert ratio[1] == pytest.approx(-ratio[0])


def test_no_relative_flow_is_an_analysis_error():
    prob = _problem()
    prob.set_val("rpm", 0.0)
    prob.set_val("axial_velocity", 0.0)
    with pytest.raises(om.AnalysisError, match="no relative flow"):
        prob.run_model()


def _vehicle(**constraints):
    from lpc_mdo.vehicle import read_vehicle_file, vehicle_from_dict

    data = read_vehicle_file()
    data["constraints"] = {**data["constraints"], **constraints}
    for key, value in constraints.items():
        if value is None:
            del data["constraints"][key]
    return vehicle_from_dict(data)


def test_vehicle_key_and_the_declared_constraints():
    from lpc_mdo.vehicle import VehicleSpecError
    from lpc_mdo.vehicle.condition_contract import condition_kind
    from lpc_mdo.vehicle.condition_kinds import blade_stall_limit

    vehicle = _vehicle()
    assert blade_stall_limit(vehicle.constraints) == 0.9
    assert blade_stall_limit(_vehicle(blade_stall_angle_fraction=None).constraints) == 1.0
    with pytest.raises(VehicleSpecError, match="blade_stall_angle_fraction"):
        _vehicle(blade_stall_angle_fraction=1.2)
    declared = {}
    for condition in vehicle.conditions:
        for c in condition_kind(condition.kind).constraints(vehicle, condition, None):
            if c.kind == "blade_stall":
                declared[condition.name] = (c.output, c.options["upper"])
    kinds = {c.name: c.kind for c in vehicle.conditions}
    for name, kind in kinds.items():
        if kind in ("hover", "oei"):
            assert declared[name] == ("lift_blade_stall_ratio_ks", 0.9)
        elif kind in ("transition", "steady"):
            assert declared[name] == ("pusher_blade_stall_ratio_ks", 0.9)
        else:
            assert name not in declared
