"""BPM airfoil self-noise and the blade-section rotor broadband model built on it."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.acoustics.airfoil_self_noise import (
    directivity_high,
    directivity_low,
    displacement_thickness,
    spectrum_a,
    tip_vortex_noise,
    trailing_edge_noise,
)
from lpc_mdo.components.acoustics.bpm_broadband import BPMBroadbandComp

# Measured one-third-octave spectra of tripped NACA 0012 sections (Brooks, Pope & Marcolini,
# NASA RP-1218, 1989), as distributed in the UCI "Airfoil Self-Noise" data set
# (doi:10.24432/C5VW2C): (chord m, alpha deg, speed m/s) -> (band centre Hz, scaled SPL dB),
# scaled SPL = SPL - 10 log10(delta*_s M**5 L/r_e**2), span L = 45.72 cm, r_e = 1.22 m, the
# observer at 90 deg; kinematic viscosity 1.4529e-5 m**2/s, speed of sound 340.46 m/s.
MEASURED = {
    (0.3048, 0.0, 71.3): (
        (800, 126.201), (1000, 125.201), (1250, 125.951), (1600, 127.591), (2000, 127.461),
        (2500, 125.571), (3150, 125.201), (4000, 123.061), (5000, 121.301), (6300, 119.541),
        (8000, 117.151), (10000, 115.391), (12500, 112.241), (16000, 108.721),
    ),
    (0.1016, 0.0, 71.3): (
        (630, 124.155), (800, 126.805), (1000, 128.825), (1250, 130.335), (1600, 131.725),
        (2000, 132.095), (2500, 132.595), (3150, 131.955), (4000, 130.935), (5000, 130.795),
        (6300, 129.395), (8000, 125.465), (10000, 123.305), (12500, 119.375),
    ),
    (0.2286, 4.0, 39.6): (
        (315, 122.229), (400, 123.879), (500, 127.039), (630, 129.579), (800, 130.469),
        (1000, 129.969), (1250, 128.339), (1600, 125.319), (2000, 121.659), (2500, 119.649),
        (3150, 120.419), (4000, 119.159), (5000, 117.649), (6300, 114.249), (8000, 113.129),
    ),
    (0.1524, 9.9, 39.6): (
        (200, 127.315), (250, 128.335), (315, 128.595), (400, 128.345), (500, 126.835),
        (630, 126.465), (800, 126.345), (1000, 123.835), (1250, 120.555), (1600, 118.545),
        (2000, 117.925), (2500, 116.295), (3150, 113.525), (4000, 112.265), (5000, 111.135),
        (6300, 109.885),
    ),
}  # fmt: skip
NU, C0, SPAN, R_E = 1.4529e-5, 340.46, 0.4572, 1.22


@pytest.mark.parametrize("case", sorted(MEASURED))
def test_section_model_against_nasa_measured_spectra(case):
    # Four spectra across chord, speed and angle (measured here: band RMS 1.2-3.5 dB, overall
    # level -3.0 to +1.5 dB). Over the whole data set's chords of 10 cm and more at alpha* <=
    # 12.5 deg (926 bands, 64 spectra) run_scripts/broadband_validation.py measures band mean
    # -0.8 dB, RMS 2.5 dB, overall-level RMS 2.0 dB.
    chord, alpha, speed = case
    f, measured = np.array(MEASURED[case]).T
    mach = speed / C0
    _, ds = displacement_thickness(chord, speed * chord / NU, alpha)
    level = 10.0 * np.log10(
        trailing_edge_noise(f, chord, speed, mach, alpha, SPAN, R_E, 1.0, 1.0, NU)
    )
    model = level - 10.0 * np.log10(ds * mach**5 * SPAN / R_E**2)
    error = model - measured
    assert np.sqrt(np.mean(error**2)) < 4.0
    overall = 10 * np.log10(np.sum(10 ** (model / 10))) - 10 * np.log10(
        np.sum(10 ** (measured / 10))
    )
    assert abs(overall) < 3.5


def test_boundary_layer_and_shape_functions_against_the_report():
    # Tripped displacement thickness at zero angle, eq. 3: 30.48 cm at 71.3 m/s (Re 1.5e6) is
    # 2.663 mm (the data set's column); the spectral shape A peaks at 0 dB where St = St_peak
    # and is -20 dB at a = a0 (its definition, eqs. 37-40).
    _, ds = displacement_thickness(0.3048, 71.3 * 0.3048 / NU, 0.0)
    assert ds == pytest.approx(0.00266337, rel=1e-4)
    assert spectrum_a(1.0, 1.0e6) == pytest.approx(0.0, abs=1e-5)
    assert spectrum_a(10**1.13, 1.0e6) == pytest.approx(-20.0, abs=1e-9)
    # Directivity: 1 broadside at M = 0 (eq. B1), and D_l vanishes along the chord.
    assert directivity_high(0.0, 1.0, 0.0, 0.0) == pytest.approx(1.0)
    assert directivity_low(1.0, 1.0, 0.2) == pytest.approx(0.0)


def test_complex_step_through_the_section_functions():
    # Every branch choice is on real parts: the complex step gives the central difference.
    x = dict(chord=0.2, speed=150.0, alpha=6.0, f=2000.0)
    h = 1e-30

    def level(chord, speed, alpha, f):
        return 10 * np.log10(
            trailing_edge_noise(f, chord, speed, speed / C0, alpha, 0.1, 50.0, 0.8, 0.7, NU)
            + tip_vortex_noise(f, chord, speed / C0, alpha, 50.0, 0.8, C0)
        )

    for name in x:
        cs = np.imag(level(**{**x, name: x[name] + 1j * h})) / h
        step = 1e-6 * x[name]
        fd = (level(**{**x, name: x[name] + step}) - level(**{**x, name: x[name] - step})) / (
            2 * step
        )
        assert cs == pytest.approx(fd, rel=1e-5, abs=1e-9)


def _rotor(num_blades=2, nrad=10, **options):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "b",
        BPMBroadbandComp(num_rotors=2, num_blades=num_blades, num_radial=nrad, **options),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    rbar = 0.2 + 0.8 * (np.arange(nrad) + 0.5) / nrad
    prob.set_val("radius", [1.5, 1.2])
    prob.set_val("rpm", [1100.0, 1300.0])
    prob.set_val("chord", np.tile(0.2 - 0.08 * rbar, (2, 1)))
    prob.set_val("thrust_per_span", np.tile((900.0 * rbar**2)[None, :, None], (2, 1, 1)))
    prob.set_val("inflow_angle", np.tile(np.arctan(0.07 / rbar)[None, :, None], (2, 1, 1)))
    prob.set_val("distance", [100.0, 80.0])
    prob.set_val("axial_distance", [-70.0, -30.0])
    prob.set_val("observer_azimuth_cos", [np.cos(0.4), -1.0])
    prob.set_val("observer_azimuth_sin", [np.sin(0.4), 0.0])
    prob.set_val("inplane_speed", [0.0, 15.0])
    prob.set_val("axial_speed", [0.0, 2.0])
    return prob


def test_rotor_partials():
    prob = _rotor(num_blades=[2, 3])
    prob.run_model()
    data = prob.check_partials(method="cs", out_stream=None)
    assert_check_partials(data, atol=1e-8, rtol=1e-8)


def test_rotor_on_its_axis_is_the_sum_of_its_sections():
    # An observer on the axis sees every blade azimuth alike and no blade moves towards it:
    # the rotor is B times the sum of its sections' self-noise, each seen from the axis.
    nrad = 6
    prob = _rotor(nrad=nrad)
    prob.set_val("axial_distance", [-100.0, -80.0])
    prob.run_model()
    k = 0
    R, omega, z = 1.5, 1100.0 * np.pi / 30, -100.0
    rbar = 0.2 + 0.8 * (np.arange(nrad) + 0.5) / nrad
    r, span = rbar * R, np.full(nrad, 0.8 * R / nrad)
    chord = 0.2 - 0.08 * rbar
    phi = np.arctan(0.07 / rbar)
    u0 = omega * r / np.cos(phi)
    alpha = 900.0 * rbar**2 / (np.cos(phi) * 0.5 * 1.225 * u0**2 * chord) / (2 * np.pi)
    pitch = phi + alpha
    r_e = np.sqrt(r * r + z * z)
    cos_theta = -np.sin(pitch) * z / r_e
    z_e = np.cos(pitch) * z
    sin2_phi = z_e**2 / (r * r + z_e**2)
    mach = u0 / 340.294
    f = prob.model.b.band_frequencies[:, None]
    args = (mach, np.degrees(alpha), span, r_e)
    d_h = directivity_high(cos_theta, sin2_phi, mach, 0.8 * mach)
    d_l = directivity_low(cos_theta, sin2_phi, mach)
    sections = trailing_edge_noise(
        f, chord, u0, args[0], args[1], span, r_e, d_h, d_l, 1.7894e-5 / 1.225
    )
    tip = tip_vortex_noise(f[:, 0], chord[-1], mach[-1], args[1][-1], r_e[-1], d_h[-1], 340.294)
    expected = 10 * np.log10(2 * (sections.sum(axis=1) + tip))
    np.testing.assert_allclose(prob.get_val("broadband_spl")[k], expected, atol=1e-9)


def test_blade_count_at_fixed_blade_loads_adds_sources():
    # Same chord, same load per blade: three blades are three halves of two, +1.76 dB.
    two, three = _rotor(num_blades=2), _rotor(num_blades=3)
    two.run_model()
    three.run_model()
    diff = three.get_val("broadband_spl") - two.get_val("broadband_spl")
    np.testing.assert_allclose(diff, 10 * np.log10(1.5), atol=1e-9)


def test_revolution_average_converges():
    coarse, fine = _rotor(num_source_azimuths=12), _rotor(num_source_azimuths=72)
    coarse.run_model()
    fine.run_model()
    energy = [10 * np.log10(np.sum(10 ** (p.get_val("broadband_spl") / 10), axis=1))
              for p in (coarse, fine)]  # fmt: skip
    np.testing.assert_allclose(energy[0], energy[1], atol=0.05)


def test_angle_of_attack_beyond_the_data_is_an_analysis_error():
    prob = _rotor()
    prob.set_val("thrust_per_span", 8.0 * prob.get_val("thrust_per_span"))
    with pytest.raises(om.AnalysisError, match="angle of attack"):
        prob.run_model()


def _bpm_vehicle(**constraints):
    from lpc_mdo.vehicle import read_vehicle_file, vehicle_from_dict

    data = read_vehicle_file()
    data["constraints"] = {**data["constraints"], **constraints}
    return vehicle_from_dict(data)


def test_vehicle_file_names_the_broadband_model():
    from lpc_mdo.vehicle import VehicleSpecError

    assert _bpm_vehicle().constraints.noise_broadband_model is None  # the paper's Gill-Lee
    assert _bpm_vehicle(noise_broadband_model="bpm").constraints.noise_broadband_model == "bpm"
    with pytest.raises(VehicleSpecError, match="noise_broadband_model"):
        _bpm_vehicle(noise_broadband_model="schlegel")


@pytest.mark.integration
def test_hover_noise_with_the_bpm_model_and_its_derivatives():
    # The hover condition's noise constraint through the BPM model: the blade-element loads
    # reach it, the level differs from Gill-Lee's, and the constraint's total derivatives
    # (rotor speed, chord, radius) match complex step through the whole hover condition.
    from lpc_mdo.groups.lpc import LPCGroup

    levels = {}
    for model in ("gill_lee", "bpm"):
        prob = om.Problem(reports=False)
        prob.model = LPCGroup(
            vehicle=_bpm_vehicle(noise_broadband_model=model), conditions=["hover"]
        )
        prob.setup(mode="rev", force_alloc_complex=True)
        prob.run_model()
        levels[model] = prob.get_val("hover.total_spl_a")[0]
    assert prob.model.hover.noise.broadband.__class__ is BPMBroadbandComp
    assert abs(levels["bpm"] - levels["gill_lee"]) > 0.1
    data = prob.check_totals(
        of=["hover.total_spl_a"],
        wrt=["hover_lift_rpm", "blade_chord_cp", "rotor_radius"],
        method="cs",
        out_stream=None,
    )
    for key, entry in data.items():
        adjoint = np.asarray(entry["J_rev"] if "J_rev" in entry else entry["J_fwd"])
        reference = np.asarray(entry["J_fd"])
        scale = max(np.abs(reference).max(), 1e-8)
        assert np.abs(adjoint - reference).max() <= 1e-8 * scale, key


def test_validation_script_loads_and_answers_bad_input(tmp_path, capsys):
    from run_script_loader import load_run_script

    script = load_run_script("broadband_validation")
    # The helicopters' uniform-lift loads carry the rotor's thrust.
    t, inflow = script.uniform_lift_loads(5, 9.45, 203.0, np.full(25, 0.46), 80000.0, 1.2)
    assert 5 * 9.45 * np.sum(np.full(25, 0.8 / 25) * t) == pytest.approx(80000.0)
    assert np.all(np.diff(inflow) < 0.0)
    # Bad input is one line and exit status 2, no traceback.
    (tmp_path / "bad.dat").write_text("1 2 3\n4 5 6\n")
    assert script.main(["airfoil", str(tmp_path / "bad.dat")]) == 2
    assert script.main(["blades", str(tmp_path / "none.sql")]) == 2
    assert script.main(["hover", str(tmp_path / "none.sql")]) == 2
    assert script.main(["nothing"]) == 2
    assert "usage" in capsys.readouterr().err


def test_helicopter_loading_fit_recovers_a_known_law():
    """The local-loading fit returns the slopes of levels built from a known law, exactly."""
    from run_script_loader import load_run_script

    script = load_run_script("broadband_validation")
    # Levels from SPL = a_rotor + 60 log10 V + 20 x + 5 x**2 about C_T/sigma = 0.04, seen from
    # C_T/sigma = 0.08: s = 20 + 10 log10 2, q = 5, k = 60, with zero residual.
    base = script.loading_fit(np.zeros(len(script.HELICOPTER_DATA)), 0.04)
    assert np.allclose(base[0], 0.0)
    levels = []
    for name, rpm, thrust_lbf, _ in script.HELICOPTER_DATA:
        diameter, _, sigma = script.HELICOPTERS[name]
        radius = diameter * script.FT / 2.0
        tip = rpm * np.pi / 30.0 * radius
        ct = thrust_lbf * script.LBF / (script.HELICOPTER_DENSITY * np.pi * radius**2 * tip**2)
        x = np.log10(ct / sigma / 0.04)
        levels.append((3.0 if name == "CH-3C" else 7.0) + 60 * np.log10(tip) + 20 * x + 5 * x * x)
    coef, error, span = script.loading_fit(levels, 0.08)
    assert coef[2:] == pytest.approx([60.0, 20.0 + 10.0 * np.log10(2.0), 5.0], abs=1e-8)
    assert np.all(error < 1e-6)
    # The measured data: loading 0.033-0.106, and a rise with loading that steepens with it.
    measured = [row[3] for row in script.HELICOPTER_DATA]
    (_, _, _, s05, q05), _, span = script.loading_fit(measured, 0.05)
    (_, _, _, s11, _), _, _ = script.loading_fit(measured, 0.11)
    assert span == pytest.approx((0.0331, 0.1060), abs=5e-4)
    assert q05 > 0.0 and s11 > s05
