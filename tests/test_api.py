"""The lpc_mdo.api wrappers return the same numbers as the models they wrap."""

import numpy as np
import openmdao.api as om
import pytest

import lpc_mdo.api as lpc


def test_motor_wrapper_reference_point():
    # Reference docs theory/motor 'Validation', case A: 1200 N m rotor torque at 1193.7 rpm,
    # L = 0.131 m, with that case's L/D = 1/3 (the vehicle default is 0.5).
    out = lpc.motor(0.131, 1200.0, 1193.7, length_to_diameter=1.0 / 3.0)
    assert out["mass"] == pytest.approx(54.03, rel=1e-3)
    assert out["peak_torque"] == pytest.approx(1652.9, rel=1e-3)
    assert out["efficiency"] == pytest.approx(0.98155, rel=1e-4)
    for key in ("input_power", "flux_linkage", "inductance_d", "inductance_q"):
        assert key in out


def test_public_names_import():
    for name in lpc.__all__:
        assert getattr(lpc, name) is not None


def test_a_weighting_wrapper():
    # IEC 61672-1: A(1 kHz) = 0.0 dB, A(100 Hz) = -19.1 dB at the exact base-10 frequency.
    assert lpc.a_weighting(1000.0) == pytest.approx(0.0, abs=0.05)
    assert lpc.a_weighting(10**2.0) == pytest.approx(-19.1, abs=0.1)


def test_rotor_noise_wrapper_doubles_with_two_identical_rotors():
    kwargs = dict(radius=1.524, rpm=1200.0, thrust=4000.0, chord=0.2, torque=900.0)
    one = lpc.rotor_noise(**kwargs)
    two = lpc.rotor_noise(
        radius=[1.524, 1.524],
        rpm=[1200.0, 1200.0],
        thrust=[4000.0, 4000.0],
        chord=0.2,
        torque=[900.0, 900.0],
        hub_position=[[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]],
        rotation_direction=[1.0, 1.0],
    )
    for key in ("total_spl_a",):
        assert np.asarray(two[key]).item() == pytest.approx(
            np.asarray(one[key]).item() + 10 * np.log10(2), abs=1e-6
        )


def test_calibrate_other_mass_is_the_models():
    # One calibration path: the W_other the api returns is the one the vehicle model (and so
    # the full model, which holds it) builds with, for the reference vehicle.
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vehicle", lpc.VehicleGroup(), promotes=["*"])
    prob.setup()
    prob.run_model()
    model_other = prob.get_val("other_mass", units="kg")[0]
    assert lpc.calibrate_other_mass() == pytest.approx(model_other, rel=1e-9)
    assert lpc.calibrate_other_mass(lpc.reference_vehicle()) == pytest.approx(model_other, rel=1e-9)
