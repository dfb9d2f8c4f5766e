"""Tests for lpc_mdo.components.atmosphere.AtmosphereComp."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.atmosphere import AtmosphereComp


def _run(altitude, **options):
    altitude = np.atleast_1d(np.asarray(altitude, dtype=float))
    prob = om.Problem()
    prob.model.add_subsystem(
        "atmos", AtmosphereComp(num_nodes=altitude.size, **options), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("altitude", altitude, units="m")
    prob.run_model()
    return prob


# ICAO standard atmosphere 1976/1993 tables (ICAO Doc 7488/3; identical to U.S. Standard
# Atmosphere 1976 below 11 km), rows h = 0 m and h = 1000 m. Issue acceptance: 1e-4 relative.
ICAO_TABLE = {
    0.0: {
        "temperature": 288.15,
        "pressure": 101325.0,
        "density": 1.225,
        "speed_of_sound": 340.294,
        "dynamic_viscosity": 1.7894e-5,
        "kinematic_viscosity": 1.4607e-5,
    },
    1000.0: {
        "temperature": 281.65,
        "pressure": 89874.6,
        "density": 1.11164,
        "speed_of_sound": 336.434,
        "dynamic_viscosity": 1.7579e-5,
        "kinematic_viscosity": 1.5813e-5,
    },
}


@pytest.mark.parametrize("altitude", sorted(ICAO_TABLE))
def test_icao_table_values(altitude):
    prob = _run(altitude)
    for name, expected in ICAO_TABLE[altitude].items():
        # ICAO tables, 1e-4 relative (acceptance criterion of the issue).
        assert_near_equal(prob.get_val(name)[0], expected, tolerance=1e-4)


def test_vectorized_nodes_match_scalar_runs():
    altitudes = np.array([0.0, 76.2, 1000.0, 5000.0, 11000.0])
    prob = _run(altitudes)
    for i, h in enumerate(altitudes):
        single = _run(h)
        for name in (
            "temperature",
            "pressure",
            "density",
            "speed_of_sound",
            "dynamic_viscosity",
            "kinematic_viscosity",
        ):
            # Same equations node by node: agreement to round-off.
            assert_near_equal(prob.get_val(name)[i], single.get_val(name)[0], tolerance=1e-14)


def test_tropopause_values():
    # U.S. Standard Atmosphere 1976, 11 km: T = 216.65 K, p = 22632.1 Pa, rho = 0.363918 kg/m^3,
    # a = 295.070 m/s (geopotential 11 km; the model uses h directly, as CADDEE does).
    # Table precision 6 significant digits -> 1e-5 relative.
    prob = _run(11000.0)
    assert_near_equal(prob.get_val("temperature")[0], 216.65, tolerance=1e-5)
    assert_near_equal(prob.get_val("pressure")[0], 22632.1, tolerance=1e-5)
    assert_near_equal(prob.get_val("density")[0], 0.363918, tolerance=1e-5)
    assert_near_equal(prob.get_val("speed_of_sound")[0], 295.070, tolerance=1e-5)


def test_caddee_constants_reproduce_reference_numbers():
    # docs theory/atmosphere table (public CADDEE code, 100 m and 1000 m rows)
    # and docs theory/atmosphere; the tables round to 6 significant digits
    # (half a unit in the last digit is up to 5e-6 relative), so 5e-6 relative.
    prob = _run([100.0, 1000.0], constants="caddee")
    assert_near_equal(prob.get_val("temperature"), [287.51, 281.66], tolerance=5e-6)
    assert_near_equal(prob.get_val("pressure"), [100128.85, 89869.3], tolerance=5e-6)
    assert_near_equal(prob.get_val("density"), [1.213457, 1.11174], tolerance=5e-6)
    assert_near_equal(prob.get_val("speed_of_sound"), [339.885, 336.409], tolerance=5e-6)
    assert_near_equal(prob.get_val("dynamic_viscosity"), [1.731957e-5, 1.70442e-5], tolerance=5e-6)


def test_ideal_gas_and_consistency():
    # Closed-form identities: p = rho R T, a^2 = gamma p / rho, nu = mu / rho (round-off).
    prob = _run(np.linspace(0.0, 11000.0, 7))
    T = prob.get_val("temperature")
    p = prob.get_val("pressure")
    rho = prob.get_val("density")
    R = 8.31432 / 0.0289644
    assert_near_equal(p, rho * R * T, tolerance=1e-13)
    assert_near_equal(prob.get_val("speed_of_sound") ** 2, 1.4 * p / rho, tolerance=1e-13)
    assert_near_equal(
        prob.get_val("kinematic_viscosity"),
        prob.get_val("dynamic_viscosity") / rho,
        tolerance=1e-13,
    )


def test_unit_conversion_of_altitude():
    # 3280.84 ft = 1000 m; density from the ICAO table at 1000 m, 1e-4 relative.
    prob = _run([0.0])
    prob.set_val("altitude", 1000.0 / 0.3048, units="ft")
    prob.run_model()
    assert_near_equal(prob.get_val("density")[0], 1.11164, tolerance=1e-4)


@pytest.mark.parametrize("constants", ["icao", "caddee"])
def test_partials(constants):
    prob = _run([0.0, 76.2, 1000.0, 4000.0, 11000.0], constants=constants)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


@pytest.mark.parametrize("altitude", [11000.1, 20000.0, -1.0, np.nan])
def test_altitude_outside_troposphere_raises(altitude):
    prob = om.Problem()
    prob.model.add_subsystem("atmos", AtmosphereComp(num_nodes=2), promotes=["*"])
    prob.setup()
    prob.set_val("altitude", [1000.0, altitude])
    with pytest.raises(
        om.AnalysisError,
        match=r"'altitude\[1\]' = .* is out of range: "
        r"must be (in \[0, 11000\] \(m\)|a finite number)",
    ):
        prob.run_model()


@pytest.mark.parametrize("num_nodes", [0, -3])
def test_bad_num_nodes_raises(num_nodes):
    with pytest.raises(ValueError, match=rf"\({num_nodes}\) of option 'num_nodes'"):
        AtmosphereComp(num_nodes=num_nodes)


def test_bad_constants_raises():
    with pytest.raises(ValueError, match="constants"):
        AtmosphereComp(constants="isa1962")
