"""The lpc_mdo.api wrappers return the same numbers as the models they wrap."""

import pytest

import lpc_mdo.api as lpc


def test_motor_wrapper_reference_point():
    # Reference page §7.11, case A: 1200 N m rotor torque at 1193.7 rpm, L = 0.131 m, with
    # that case's L/D = 1/3 (the vehicle default is 0.5).
    out = lpc.motor(0.131, 1200.0, 1193.7, length_to_diameter=1.0 / 3.0)
    assert out["mass"] == pytest.approx(54.03, rel=1e-3)
    assert out["peak_torque"] == pytest.approx(1652.9, rel=1e-3)
    assert out["efficiency"] == pytest.approx(0.98155, rel=1e-4)
    for key in ("input_power", "flux_linkage", "inductance_d", "inductance_q"):
        assert key in out


def test_public_names_import():
    for name in lpc.__all__:
        assert getattr(lpc, name) is not None
