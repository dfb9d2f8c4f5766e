"""The lpc_mdo.api wrappers return the same numbers as the models they wrap."""

import numpy as np
import openmdao.api as om
import pytest

import lpc_mdo.api as lpc
from lpc_mdo.vehicle import paper_calibrated_vehicle


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
    # the full model, which holds it) builds with, for the paper-calibrated vehicle; the
    # reference vehicle is itemised (W_other = 0 in the model).
    paper = paper_calibrated_vehicle()
    models_other = []
    for vehicle in (paper, lpc.reference_vehicle()):
        prob = om.Problem(reports=False)
        prob.model.add_subsystem("vehicle", lpc.VehicleGroup(vehicle=vehicle), promotes=["*"])
        prob.setup()
        prob.run_model()
        models_other.append(prob.get_val("other_mass", units="kg")[0])
    assert lpc.calibrate_other_mass(paper) == pytest.approx(models_other[0], rel=1e-9)
    assert models_other[1] == 0.0


_ROTOR = dict(radius=1.524, rpm=1200.0, thrust=4863.5, chord=0.2)


def test_rotor_noise_without_torque_gives_the_thickness_and_broadband_parts():
    # Thickness (Barry-Magliozzi) and broadband (Gill-Lee) noise do not read the torque: the
    # parts computed without it equal those of the full call (1e-12); the loading part and the
    # sums that include it (tonal, rotor, total) are not returned.
    full = lpc.rotor_noise(**_ROTOR, torque=803.4)
    part = lpc.rotor_noise(**_ROTOR, parts=("thickness", "broadband"))
    for key in ("thickness_spl_a", "thickness_spl", "broadband_spl_a", "broadband_oaspl_a"):
        np.testing.assert_allclose(part[key], full[key], rtol=1e-12)
    for key in ("loading_spl", "tonal_spl_a", "rotor_spl_a", "total_spl_a"):
        assert key not in part
    only = lpc.rotor_noise(**_ROTOR, parts="broadband")
    assert "thickness_spl" not in only
    np.testing.assert_allclose(only["broadband_oaspl_a"], full["broadband_oaspl_a"], rtol=1e-12)
    with pytest.raises(ValueError, match="torque is required .* parts=\\('thickness', 'broadb"):
        lpc.rotor_noise(**_ROTOR)
    with pytest.raises(ValueError, match="'parts' = 'tonal' is not allowed: must be one of"):
        lpc.rotor_noise(**_ROTOR, parts=("tonal",))


@pytest.mark.parametrize(
    "observers",
    [
        {"observer_distance": [60.0, 100.0, 250.0], "observer_elevation_deg": [45.0, 30.0, 80.0]},
        {"observer_distance": 150.0, "observer_azimuth_deg": [0.0, 90.0, 180.0]},
        {"observer_position": [[-70.0, 0.0, 70.0], [0.0, 50.0, 20.0], [30.0, -40.0, 200.0]]},
    ],
)
def test_rotor_noise_several_observers_equal_single_calls(observers):
    # Entry k of a several-observer call is the single-observer call at observer k (1e-12).
    kwargs = dict(
        radius=[1.5, 1.5],
        rpm=[1200.0, 1100.0],
        thrust=[4000.0, 3500.0],
        chord=0.2,
        torque=[800.0, 700.0],
        hub_position=[[0.0, -3.0, 0.0], [0.0, 3.0, 0.0]],
    )
    many = lpc.rotor_noise(**kwargs, **observers)
    assert many["total_spl_a"].shape == (3,) and many["loading_spl"].shape == (3, 2, 3)
    for k in range(3):
        single = {
            key: (np.asarray(v)[k] if np.ndim(v) and np.size(v) == 3 or np.ndim(v) == 2 else v)
            for key, v in observers.items()
        }
        one = lpc.rotor_noise(**kwargs, **single)
        for key, value in one.items():
            expected = value if key == "band_frequency" else many[key][k]
            np.testing.assert_allclose(expected, value, rtol=1e-12, atol=0, err_msg=key)


def test_rotor_noise_at_twice_the_distance():
    # Two observers on the paper's ray (45 deg below the rotor plane), at S and 2 S, hover:
    # - loading noise (Lowson, far field) falls as 1/S: -20 log10 2 = -6.0206 dB (plus
    #   absorption), 1e-9 dB;
    # - thickness noise (Barry-Magliozzi) falls by 6.02 dB within 0.2 dB (plus absorption);
    # - broadband (Gill-Lee) is an empirical spectrum in which S enters only through
    #   f8 = 4.97 C_T sin(theta) (1.5 (S/R) M_t - S/R + 15) (no spherical spreading): the band
    #   levels equal that formula (docs theory/acoustics 'Broadband noise', paper eq. 22)
    #   evaluated here independently at both distances (1e-10), in the public-code form
    #   (broadband_reference_distance=None; the default propagation is tested in
    #   tests/test_acoustics_propagation.py).
    out = lpc.rotor_noise(
        **_ROTOR,
        torque=803.4,
        observer_distance=[100.0, 200.0],
        broadband_reference_distance=None,
    )
    # Tonal levels also lose the ISO 9613-1 absorption of each harmonic over the extra 100 m
    # (default atmosphere 288.15 K, 101325 Pa, 70 % RH).
    from lpc_mdo.components.acoustics.absorption import iso9613_absorption

    extra = iso9613_absorption(out["harmonic_frequency"][0], 288.15, 101325.0, 70.0) * 100.0
    drop = out["loading_spl"][1] - out["loading_spl"][0]
    np.testing.assert_allclose(drop, -20.0 * np.log10(2.0) - extra, atol=1e-9)
    drop = out["thickness_spl"][1] - out["thickness_spl"][0]
    np.testing.assert_allclose(drop, -20.0 * np.log10(2.0) - extra, atol=0.2)

    radius, thrust, chord = _ROTOR["radius"], _ROTOR["thrust"], _ROTOR["chord"]
    omega = _ROTOR["rpm"] * np.pi / 30.0
    # V_tip = Omega R - norm(V): at rest the observer geometry's smooth in-plane speed is 1e-6 m/s
    vtip = omega * radius - 1e-6
    mt = vtip / 340.294
    ct = thrust / (1.225 * np.pi * radius**2 * (omega * radius) ** 2)
    csw = chord * 0.8  # chord x the blade length of the stations on [0.2 R, R]
    sigma = 2 * csw / (np.pi * radius)
    f = out["band_frequency"]
    x = f * csw / vtip - (sigma * np.log10(ct) + 0.9 * mt * sigma * (mt + 3.82) * np.log10(sigma))
    for k, distance in enumerate((100.0, 200.0)):
        s_r = distance / radius
        st = np.sqrt(0.5 + 1e-12 / distance**2)  # the model's smooth abs(z)/S
        f8 = 4.97 * ct * st * (1.5 * s_r * mt - s_r + 15.0)
        f6 = 1.0 - ct * mt * (ct - st + 2.06)
        spl = 78.4 * np.log10(vtip) * x**0.6 / ((x + 2.06 - 2 * mt**2) ** f6 + (ct * x) ** f8)
        np.testing.assert_allclose(out["broadband_spl"][k, 0], spl, rtol=1e-10)


def test_rotor_noise_observer_in_the_near_field_is_a_named_error():
    with pytest.raises(ValueError, match=r"'observer_distance\[1\]' = 1e-09 is out of range: "):
        lpc.rotor_noise(**_ROTOR, torque=800.0, observer_distance=[100.0, 1e-9])
    with pytest.raises(ValueError, match=r"'observer_distance' = 1.0 is out of range: must be >="):
        lpc.rotor_noise(**_ROTOR, torque=800.0, observer_distance=1.0)
    with pytest.raises(ValueError, match=r"'observer_position' must have shape \(n, 3\)"):
        lpc.rotor_noise(**_ROTOR, torque=800.0, observer_position=[[1.0, 2.0]])
    with pytest.raises(
        ValueError, match=r"'observer distance from hub\[0\]' = 0.5 is out of range"
    ):
        lpc.rotor_noise(**_ROTOR, torque=800.0, observer_position=[0.5, 0.0, 0.0])


def test_rotor_noise_mirrored_observers_hear_the_same():
    # A symmetric pair of hovering rotors (hubs at y = -/+3 m, equal speed and thrust) heard by
    # two observers mirrored about the x-z plane: the same levels (the far field of a hovering
    # rotor is axisymmetric about its axis, and the pair is its own mirror image), 1e-9 dB.
    pair = dict(
        radius=[1.5, 1.5],
        rpm=[1200.0, 1200.0],
        thrust=[4000.0, 4000.0],
        chord=0.2,
        torque=[800.0, 800.0],
        hub_position=[[0.0, -3.0, 0.0], [0.0, 3.0, 0.0]],
    )
    out = lpc.rotor_noise(**pair, observer_position=[[-40.0, 60.0, 70.0], [-40.0, -60.0, 70.0]])
    np.testing.assert_allclose(out["total_spl_a"][0], out["total_spl_a"][1], rtol=0, atol=1e-9)
    # Per rotor: observer 1 hears rotor 0 as observer 0 hears rotor 1 (the mirror swaps them).
    for key in ("tonal_spl_a", "broadband_oaspl_a"):
        assert np.shape(out[key]) == (2, 2)
        np.testing.assert_allclose(out[key][0], out[key][1][::-1], rtol=0, atol=1e-9, err_msg=key)
        assert abs(out[key][0][0] - out[key][0][1]) > 0.01  # the two rotors differ
    # ... and a different observer does not (the test can fail).
    other = lpc.rotor_noise(**pair, observer_position=[[-40.0, 30.0, 70.0]])
    assert abs(other["total_spl_a"][0] - out["total_spl_a"][0]) > 0.01
