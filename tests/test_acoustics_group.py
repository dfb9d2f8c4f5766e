"""RotorNoiseGroup: energetic totals, rotor-order invariance, totals derivatives, wrappers."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import (
    assert_check_partials,
    assert_check_totals,
    assert_near_equal,
    assert_no_approx_partials,
)

from lpc_mdo.api.acoustics import rotor_noise
from lpc_mdo.components.acoustics.a_weighting import a_weighting
from lpc_mdo.components.acoustics.total import TotalNoiseComp, energetic_sum
from lpc_mdo.groups.acoustics import HOVER_NOISE_LIMIT_DBA, RotorNoiseGroup

NRAD = 8
RBAR = 0.2 + 0.8 * (np.arange(NRAD) + 0.5) / NRAD


def _rotor_data(nr, seed=0):
    """Hover rotors of different size, speed and loading (per-rotor arrays)."""
    rng = np.random.default_rng(seed)
    radius = rng.uniform(1.3, 1.6, nr)
    rpm = rng.uniform(1000.0, 1300.0, nr)
    thrust = rng.uniform(3500.0, 5000.0, nr)
    t_span = thrust[:, None] * RBAR[None, :] / (2 * radius[:, None] * 0.8 * RBAR.mean())
    return {
        "radius": radius,
        "rpm": rpm,
        "thrust": thrust,
        "chord": rng.uniform(0.1, 0.3, (nr, NRAD)),
        "thrust_per_span": t_span[..., None],
        "drag_per_span": 0.12 * t_span[..., None],
        "inflow_angle": np.tile(np.arctan(0.08 / RBAR)[None, :, None], (nr, 1, 1)),
        "hub_position": rng.uniform(-6.0, 6.0, (nr, 3)),
    }


def _problem(nr, data, **options):
    prob = om.Problem(RotorNoiseGroup(num_rotors=nr, num_radial=NRAD, **options), reports=False)
    prob.setup(force_alloc_complex=True)
    for name, val in data.items():
        prob.set_val(name, val)
    prob.run_model()
    return prob


def test_total_comp_closed_form():
    # docs theory/acoustics 'Total noise': incoherent sums of 10**(L/10) (numpy re-computation;
    # 1e-12 relative).
    rng = np.random.default_rng(1)
    lo, th, bb = (rng.uniform(20.0, 80.0, s) for s in ((3, 2), (3, 2), (3, 5)))
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "t",
        TotalNoiseComp(num_rotors=3, num_harmonics=2, num_bands=5, weighting="none"),
        promotes=["*"],
    )
    prob.setup()
    prob.set_val("loading_spl", lo)
    prob.set_val("thickness_spl", th)
    prob.set_val("broadband_spl", bb)
    prob.run_model()
    tonal = energetic_sum(np.hstack([lo, th]), axis=1)
    broad = energetic_sum(bb, axis=1)
    assert_near_equal(prob.get_val("tonal_spl"), tonal, tolerance=1e-12)
    assert_near_equal(prob.get_val("broadband_oaspl"), broad, tolerance=1e-12)
    assert_near_equal(
        prob.get_val("rotor_spl"),
        energetic_sum(np.column_stack([tonal, broad]), axis=1),
        tolerance=1e-12,
    )
    assert_near_equal(
        prob.get_val("total_spl"), [energetic_sum(np.hstack([lo, th, bb]))], tolerance=1e-12
    )


def test_total_invariant_to_rotor_order():
    # Permuting the rotors permutes the per-rotor levels and leaves the total unchanged
    # (1e-12 relative; summation order only).
    nr = 4
    data = _rotor_data(nr)
    base = _problem(nr, data)
    perm = np.array([2, 0, 3, 1])
    permuted = _problem(nr, {k: v[perm] for k, v in data.items()})
    for name in ("total_spl_a", "total_spl"):
        assert_near_equal(permuted.get_val(name), base.get_val(name), tolerance=1e-12)
    assert_near_equal(
        permuted.get_val("rotor_spl_a"), base.get_val("rotor_spl_a")[perm], tolerance=1e-12
    )


@pytest.mark.parametrize("copies", [2, 8])
def test_identical_sources_add_energetically(copies):
    # Co-located identical rotors: total = single + 10 log10(N), i.e. +3.0103 dB for two and
    # +9.0309 dB for eight (exact; the -120 dB floor is 1e-19 dB here). Tolerance 1e-9 dB.
    one = _rotor_data(1, seed=5)
    single = _problem(1, one)
    many = _problem(copies, {k: np.repeat(v, copies, axis=0) for k, v in one.items()})
    for name in ("total_spl_a", "total_spl"):
        gain = many.get_val(name)[0] - single.get_val(name)[0]
        assert abs(gain - 10.0 * np.log10(copies)) < 1e-9
    assert abs(10 * np.log10(2.0) - 3.0103) < 1e-4


@pytest.mark.parametrize(
    "options",
    [
        {},  # paper hover case
        {"num_azimuth": 5, "num_harmonics": 2, "num_bands": 12, "load_input": "sectional"},
        {"load_input": "totals", "observer_input": "position", "num_bands": 12},
    ],
)
def test_group_totals(options):
    # check_totals against complex step for the constraint and per-rotor levels, and no
    # approximated partials anywhere (analytic everywhere). Tolerance 1e-7 relative.
    nr = 3
    data = _rotor_data(nr, seed=2)
    naz = options.get("num_azimuth", 1)
    wrt = [
        "radius",
        "rpm",
        "thrust",
        "chord",
        "hub_position",
        "thrust_direction",
        "density",
        "speed_of_sound",
        "thickness_to_chord",
        "flight_velocity",
    ]
    if options.get("load_input") == "totals":
        for name in ("thrust_per_span", "drag_per_span", "inflow_angle"):
            data.pop(name)
        data["torque"] = np.array([700.0, 650.0, 600.0])
        data["observer_position"] = np.array([-50.0, 30.0, 80.0])
        wrt += ["torque", "observer_position"]
    else:
        for name in ("thrust_per_span", "drag_per_span", "inflow_angle"):
            data[name] = data[name] * (1.0 + 0.1 * np.cos(2 * np.pi * np.arange(naz) / naz))
        wrt += [
            "thrust_per_span",
            "drag_per_span",
            "inflow_angle",
            "observer_distance",
            "observer_elevation",
            "observer_azimuth",
        ]
        if naz > 1:
            data["flight_velocity"] = np.array([0.09, 0.02, -1.0])  # inside the path switch
    prob = _problem(nr, data, **options)
    totals = prob.check_totals(
        of=["total_spl_a", "rotor_spl_a", "total_spl"], wrt=wrt, method="cs", out_stream=None
    )
    assert_check_totals(totals, atol=1e-8, rtol=1e-7)
    assert_no_approx_partials(prob.model, method="fd")
    # ISO 9613-1 absorption uses complex step by design (components/acoustics/absorption.py).
    assert_no_approx_partials(
        prob.model, method="cs", excludes=["band_absorption", "tonal_absorption"]
    )


def test_rotor_noise_wrapper_matches_group_and_limit():
    # The wrapper builds the same group: identical numbers to 1e-12, and the paper's limit.
    data = _rotor_data(2, seed=3)
    group = _problem(2, data)
    res = rotor_noise(
        data["radius"],
        data["rpm"],
        data["thrust"],
        data["chord"],
        thrust_per_span=data["thrust_per_span"],
        drag_per_span=data["drag_per_span"],
        inflow_angle=data["inflow_angle"],
        hub_position=data["hub_position"],
    )
    assert_near_equal(res["total_spl_a"], group.get_val("total_spl_a")[0], tolerance=1e-12)
    assert_near_equal(res["tonal_spl"], group.get_val("tonal_spl"), tolerance=1e-12)
    assert res["broadband_spl_a"].shape == (2, 38) and res["loading_spl"].shape == (2, 3)
    assert_near_equal(res["band_frequency"][[0, -1]], [12.5, 63000.0], tolerance=1e-15)
    assert HOVER_NOISE_LIMIT_DBA == 70.0
    assert a_weighting(1000.0) == pytest.approx(0.0, abs=1e-12)


def test_rotor_noise_from_totals():
    # With thrust and torque only (assumed hover load shape): one LPC-like rotor at the paper's
    # observer (100 m, 45 deg below) sits at elevation -45 deg; broadband dominates the A-weighted
    # level there (paper Sec. V). Doubling the rotors adds 3.0103 dB (1e-9 dB).
    chord = np.linspace(0.3, 0.1, 25)
    one = rotor_noise(1.524, 1200.0, 4863.5, chord, torque=803.4)
    assert_near_equal(one["elevation_deg"], [-45.0], tolerance=1e-12)
    assert_near_equal(one["distance"], [100.0], tolerance=1e-12)
    assert one["broadband_oaspl_a"][0] > one["tonal_spl_a"][0] + 10.0
    two = rotor_noise([1.524] * 2, [1200.0] * 2, [4863.5] * 2, chord, torque=803.4)
    assert abs(two["total_spl_a"] - one["total_spl_a"] - 10 * np.log10(2.0)) < 1e-9


def test_bad_inputs_raise_clear_errors():
    with pytest.raises(ValueError, match="torque is required"):
        rotor_noise(1.5, 1200.0, 4000.0, 0.2)
    with pytest.raises(ValueError, match="give all of thrust_per_span"):
        rotor_noise(1.5, 1200.0, 4000.0, 0.2, thrust_per_span=np.ones(25))
    with pytest.raises(om.AnalysisError, match=r"'thrust\[0\]' = -10.0 is out of range"):
        rotor_noise(1.5, 1200.0, -10.0, 0.2, torque=100.0)
    with pytest.raises(om.AnalysisError, match=r"'chord\[.*\]' = 0.0 is out of range: must be > 0"):
        rotor_noise(1.5, 1200.0, 4000.0, np.r_[0.2 * np.ones(24), 0.0], torque=500.0)
    with pytest.raises(ValueError, match="radial_stations must be strictly increasing"):
        rotor_noise(
            1.5, 1200.0, 4000.0, 0.2, torque=500.0, radial_stations=np.linspace(0.1, 1.0, 25)
        )
    with pytest.raises(ValueError, match="num_load_harmonics"):
        om.Problem(RotorNoiseGroup(num_azimuth=4, num_load_harmonics=2), reports=False).setup()
    with pytest.raises(ValueError, match="num_blades"):
        om.Problem(RotorNoiseGroup(num_rotors=2, num_blades=(2, 3, 4)), reports=False).setup()


@pytest.mark.parametrize("observer_input", ["relative", "position"])
def test_several_observers_in_one_pass(observer_input):
    # num_observers = 3: one evaluation over the rotor-observer pairs gives, for every
    # observer, the levels of a one-observer group there (1e-12), in forward flight with
    # azimuthal loads (both loading paths), and its totals check against complex step.
    nr, naz = 2, 5
    data = _rotor_data(nr, seed=4)
    for name in ("thrust_per_span", "drag_per_span", "inflow_angle"):
        data[name] = data[name] * (1.0 + 0.1 * np.cos(2 * np.pi * np.arange(naz) / naz))
    data["flight_velocity"] = np.array([20.0, 1.0, -2.0])
    options = {"num_azimuth": naz, "num_harmonics": 2, "num_bands": 12,
               "observer_input": observer_input, "rotation_direction": (1, -1)}  # fmt: skip
    if observer_input == "relative":
        observers = {
            "observer_distance": np.array([100.0, 400.0, 40.0]),
            "observer_elevation": np.array([0.7, 0.2, -0.3]),
            "observer_azimuth": np.array([3.0, 0.5, -1.5]),
        }
    else:
        observers = {"observer_position": np.array([[-60.0, 10.0, 70.0], [200.0, -50.0, 30.0],
                                                    [0.0, 80.0, -20.0]])}  # fmt: skip
    many = _problem(nr, {**data, **observers}, num_observers=3, **options)
    for j in range(3):
        one = _problem(nr, {**data, **{k: v[j] for k, v in observers.items()}}, **options)
        assert_near_equal(many.get_val("total_spl_a")[j], one.get_val("total_spl_a")[0], 1e-12)
        for name in ("rotor_spl_a", "tonal_spl", "broadband_oaspl", "distance"):
            assert_near_equal(many.get_val(name)[j * nr : (j + 1) * nr], one.get_val(name), 1e-12)
    wrt = ["radius", "rpm", "thrust", "chord", "hub_position", "thrust_per_span",
           "drag_per_span", "inflow_angle", "flight_velocity", *observers]  # fmt: skip
    totals = many.check_totals(
        of=["total_spl_a", "rotor_spl"], wrt=wrt, method="cs", out_stream=None
    )
    assert_check_totals(totals, atol=1e-8, rtol=1e-7)


def test_total_comp_per_observer():
    # Rows are rotor-observer pairs, observer-major: each observer's total is the energetic sum
    # of its own rows (closed form), with partials.
    levels = np.array([[60.0, 50.0], [55.0, 40.0], [70.0, 30.0], [45.0, 65.0]])
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "t",
        TotalNoiseComp(num_rotors=4, num_harmonics=2, num_bands=2, num_observers=2),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("loading_spl_a", levels)
    prob.set_val("thickness_spl_a", levels - 10.0)
    prob.set_val("broadband_spl_a", levels - 5.0)
    prob.run_model()
    rows = [energetic_sum(np.concatenate([v, v - 10.0, v - 5.0])) for v in levels]
    expected = [energetic_sum(rows[:2]), energetic_sum(rows[2:])]
    assert_near_equal(prob.get_val("total_spl_a"), expected, 1e-12)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)
