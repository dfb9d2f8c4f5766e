import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.kinematics import KinematicsComp


def make_problem():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("kin", KinematicsComp(num_nodes=3), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    # Hover, paper climb (V sin(gamma) = 4.572 m/s at 6 deg) and paper cruise (M 0.17 at
    # 999.74 m: V = 57.190 m/s, docs theory/rotors 'BEM inflow residual'); ICAO densities and speeds
    # of sound.
    prob.set_val("speed", [0.0, 4.572 / np.sin(np.radians(6.0)), 57.19])
    prob.set_val("pitch", np.radians([0.0, 8.0, 2.0]))
    prob.set_val("flight_path_angle", np.radians([0.0, 6.0, 0.0]))
    prob.set_val("density", [1.225, 1.16727, 1.11164])
    prob.set_val("speed_of_sound", [340.294, 338.370, 336.434])
    prob.set_val("dynamic_viscosity", [1.7894e-5, 1.7737e-5, 1.7579e-5])
    prob.run_model()
    return prob


def test_values_against_closed_form():
    prob = make_problem()
    speed = prob.get_val("speed")
    # Closed forms (docs theory/rotors 'BEM inflow residual'): alpha = theta - gamma;
    # cruise M 0.17 at 1000 m.
    assert_near_equal(prob.get_val("angle_of_attack"), np.radians([0.0, 2.0, 2.0]), 1e-12)
    assert_near_equal(prob.get_val("mach")[2], 0.17, 1e-4)
    assert_near_equal(
        prob.get_val("dynamic_pressure"), 0.5 * prob.get_val("density") * speed**2, 1e-12
    )
    assert_near_equal(np.hypot(prob.get_val("u"), prob.get_val("w")), speed, 1e-12)
    assert prob.get_val("u")[0] == 0.0 and prob.get_val("reynolds_per_length")[0] == 0.0
    # Cruise Reynolds number on the 1.460 m wing MAC (docs theory/geometry 'Reference vehicle'):
    # about 4e6.
    assert_near_equal(
        prob.get_val("reynolds_per_length")[2] * 1.460, 1.11164 * 57.19 * 1.46 / 1.7579e-5, 1e-12
    )


def test_partials():
    prob = make_problem()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_negative_speed_is_an_analysis_error():
    prob = make_problem()
    prob.set_val("speed", [-1.0, 10.0, 20.0])
    with pytest.raises(
        om.AnalysisError,
        match=r"'speed\[0\]' = -1.0"
        r" is out of range: must be >= 0 \(m/s\)",
    ):
        prob.run_model()
