"""The departure's noise footprint: path geometry, observers, exposure, and the model's rows."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials

from lpc_mdo.components.acoustics.exposure import NoiseExposureComp
from lpc_mdo.components.acoustics.path_observer import PathObserverComp
from lpc_mdo.groups.acoustics import RotorNoiseGroup
from lpc_mdo.vehicle import VehicleSpecError, read_vehicle_file, vehicle_from_dict
from lpc_mdo.vehicle.footprint_path import (
    PathLeg,
    departure_legs,
    departure_points,
    footprint_geometry,
    footprint_observers,
    leg_geometry,
)

FOOTPRINT = {
    "track_positions": [-300.0, 0.0, 300.0, 1000.0, 2500.0],
    "hover_time": 30.0,
    "max_sel": 85.0,
    "leg_subdivisions": 1,
}


def footprint_vehicle(**changes):
    data = read_vehicle_file()
    table = {**FOOTPRINT, **changes}
    data["noise_footprint"] = {key: value for key, value in table.items() if value is not None}
    return vehicle_from_dict(data)


def test_quadrature_of_a_leg_integrates_the_spreading_exactly():
    # A leg of 600 m flown in 20 s at 80 m over the ground; observers under it, beside it and
    # beyond its end. A source of uniform directivity, L = L_1 - 20 log10(r / 1 m): the points'
    # sum_k 10^(L_k/10) tau_k is int dt / r(t)^2 (times 10^(L_1/10)) for any number of points,
    # against the midpoint rule on 200000 steps; the points lie on the leg.
    leg = PathLeg("t", (0.0, 0.0, -80.0), (600.0, 0.0, -80.0), 20.0)
    observers = np.array([[300.0, 0.0, 0.0], [100.0, 150.0, -1.2], [900.0, -50.0, 0.0]])
    t = (np.arange(200000) + 0.5) * 20.0 / 200000
    path = np.column_stack([30.0 * t, 0.0 * t, np.full(t.size, -80.0)])
    for nodes in (1, 3, 6):
        geometry = leg_geometry(leg, observers, nodes, angle=0.01)  # every observer: nodes
        np.testing.assert_array_equal(geometry.observer, np.repeat([0, 1, 2], nodes))
        points = observers[geometry.observer] - geometry.offset
        assert np.all((points[:, 0] >= 0.0) & (points[:, 0] <= 600.0))
        np.testing.assert_allclose(points[:, 1:], np.broadcast_to([0.0, -80.0], (3 * nodes, 2)))
        for i, obs in enumerate(observers):
            hand = np.sum(1.0 / np.sum((obs - path) ** 2, axis=1)) * (20.0 / 200000)
            mine = geometry.observer == i
            r2 = np.sum(geometry.offset[mine] ** 2, axis=1)
            assert np.sum(geometry.equivalent_time[mine] / r2) == pytest.approx(hand, rel=1e-7)
    # The default: one point per 30 deg the leg subtends, at most 6: the observer under the
    # middle sees it over 150 deg, the one beyond its end over 17 deg.
    geometry = leg_geometry(leg, observers, 6)
    np.testing.assert_array_equal(np.bincount(geometry.observer), [6, 4, 1])
    # A steady source (the hover: a leg of zero length) carries its time.
    hover = leg_geometry(PathLeg("h", (0.0, 0.0, -80.0), (0.0, 0.0, -80.0), 30.0), observers, 4)
    np.testing.assert_array_equal(hover.equivalent_time, 30.0)
    np.testing.assert_allclose(hover.offset, observers - [0.0, 0.0, -80.0])


def test_the_departure_is_the_hover_then_the_transition_legs_end_to_end():
    vehicle = footprint_vehicle(leg_subdivisions=2, lateral_offsets=[0.0, 200.0])
    legs = departure_legs(vehicle)
    transition = [c for c in vehicle.conditions if c.kind == "transition"]
    assert [leg.condition for leg in legs] == ["hover"] + [
        c.name for c in transition for _ in range(2)
    ]
    assert legs[0].time == 30.0 and legs[0].length == 0.0
    for a, b in zip(legs[1:-1], legs[2:], strict=True):
        np.testing.assert_allclose(a.end, b.start, atol=1e-9)
    total = sum(c.speed * c.duration for c in transition)
    assert legs[-1].end[0] == pytest.approx(total, rel=1e-12)
    observers = footprint_observers(vehicle.noise_footprint)
    assert observers.shape == (10, 3)
    np.testing.assert_allclose(observers[5], [-300.0, 200.0, -1.2])


@pytest.mark.parametrize(
    "changes, match",
    [
        ({"track_positions": [0.0], "observer_height": 30.0, "hover_time": 30.0}, None),
        ({"hover_time": 0.0}, "hover_time"),
        ({"max_sel": 500.0}, "max_sel"),
        ({"max_sel": None}, "no limit"),
    ],
)
def test_footprint_table_is_checked(changes, match):
    if match is None:
        assert footprint_vehicle(**changes).noise_footprint.height == 30.0
        return
    with pytest.raises(VehicleSpecError, match=match):
        footprint_vehicle(**changes)


@pytest.mark.parametrize("height", [1.2, 10.0])
def test_an_observer_in_the_near_field_is_a_named_error(height):
    # 10 m up: the departure flies at 10 m, through a 10 m mast's microphone (distance 0).
    data = read_vehicle_file()
    for c in data["conditions"]:
        if c["kind"] in ("hover", "transition"):
            c["altitude"] = 10.0
    data["noise_footprint"] = {**FOOTPRINT, "observer_height": height}
    with pytest.raises(VehicleSpecError, match="noise_footprint.*rotor radii"):
        vehicle_from_dict(data)


def test_path_observer_turns_with_the_pitch_and_partials_are_exact():
    offsets = np.array([[100.0, 20.0, 80.0], [-50.0, 0.0, 70.0]])
    hubs = np.array([[1.0, -2.0, -1.0], [3.0, 2.0, -1.0]])
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("obs", PathObserverComp(offsets=offsets, num_rotors=2))
    prob.setup(force_alloc_complex=True)
    prob.set_val("obs.hub_position", hubs)
    prob.set_val("obs.pitch", np.radians(10.0))
    prob.run_model()
    position = prob.get_val("obs.observer_position") - hubs.mean(axis=0)
    # Distances are kept; an observer ahead and below sits higher in the nose-up body frame.
    np.testing.assert_allclose(np.linalg.norm(position, axis=1), np.linalg.norm(offsets, axis=1))
    theta = np.radians(10.0)
    expected = offsets[:, 0] * np.sin(theta) + offsets[:, 2] * np.cos(theta)
    np.testing.assert_allclose(position[:, 2], expected)
    assert_check_partials(prob.check_partials(method="cs", out_stream=None), atol=1e-10, rtol=1e-10)


def test_exposure_of_ragged_sources_is_the_hand_sum():
    # Three observers hearing 2, 1 and 3 points of a source "a" and 1, 2, 1 of a source "b",
    # each point with its own time: SEL = 10 log10 sum 10^(L/10) tau over an observer's points.
    rng = np.random.default_rng(5)
    observers = {"a": [0, 0, 1, 2, 2, 2], "b": [0, 1, 1, 2]}
    levels = {name: 60.0 + 20.0 * rng.random(len(o)) for name, o in observers.items()}
    times = 0.5 + rng.random(10)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "e", NoiseExposureComp(num_observers=3, sources=list(observers.items()), rho=30.0)
    )
    prob.setup(force_alloc_complex=True)
    for name, level in levels.items():
        prob.set_val(f"e.{name}", level)
    prob.set_val("e.duration", times)
    prob.run_model()
    assert_check_partials(prob.check_partials(method="cs", out_stream=None), atol=1e-9)
    who = np.concatenate(list(observers.values()))
    level = np.concatenate(list(levels.values()))
    for i in range(3):
        mine = who == i
        hand = 10.0 * np.log10(np.sum(10.0 ** (level[mine] / 10.0) * times[mine]))
        assert prob.get_val("e.sel")[i] == pytest.approx(hand, abs=1e-12)
        top = level[mine].max()
        assert top <= prob.get_val("e.lmax")[i] <= top + np.log(mine.sum()) / 30.0


def test_an_observer_without_points_is_a_named_error():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("e", NoiseExposureComp(num_observers=3, sources=[("a", [0, 2])]))
    with pytest.raises(ValueError, match=r"observers \[1\] hear no point"):
        prob.setup()


def test_one_rotor_passing_overhead_against_a_time_integration():
    # One rotor (hover loads from thrust and torque) flies level at 40 m/s, 80 m up, past an
    # observer on the ground under the middle of its 800 m leg. Hand computation: the full noise
    # model at 801 points of the pass (directivity, Doppler, absorption of each), the energy
    # summed over time (trapezoids). The footprint's Gauss points in the line-of-sight angle
    # must agree within 0.5 dB with the default 6 points; the rotor is quietest on its axis,
    # straight below, so 1 point (the closest) is far off.
    speed, height, length = 40.0, 80.0, 800.0
    x = np.linspace(0.0, length, 801)
    observer = np.array([400.0, 0.0, -1.2])

    def levels(sources):
        offsets = observer - sources  # earth axes = body axes (level flight, no pitch)
        n = len(offsets)
        prob = om.Problem(reports=False)
        prob.model.add_subsystem(
            "noise",
            RotorNoiseGroup(
                num_rotors=1,
                num_observers=n,
                num_radial=9,
                num_bands=24,
                lowest_band_frequency=50.0,
                load_input="totals",
                observer_input="position",
            ),
            promotes=["*"],
        )
        prob.setup()
        prob.set_val("radius", [1.5])
        prob.set_val("rpm", [1100.0])
        prob.set_val("thrust", [4000.0])
        prob.set_val("torque", [700.0])
        prob.set_val("chord", np.full((1, 9), 0.15))
        prob.set_val("hub_position", np.zeros((1, 3)))
        prob.set_val("observer_position", offsets)
        prob.set_val("flight_velocity", [speed, 0.0, 0.0])
        prob.run_model()
        return prob.get_val("total_spl_a")

    path = np.column_stack([x, 0.0 * x, np.full(x.size, -height)])
    weights = np.full(x.size, 1.0)
    weights[[0, -1]] = 0.5
    hand = 10.0 * np.log10(np.sum(10.0 ** (levels(path) / 10.0) * weights) * (x[1] - x[0]) / speed)
    leg = PathLeg("t", (0.0, 0.0, -height), (length, 0.0, -height), length / speed)
    sel = {}
    for nodes in (1, 3, 6):  # 6: the default for this leg, seen over 157 deg
        geometry = leg_geometry(leg, observer[None, :], nodes)
        level = levels(observer - geometry.offset)
        sel[nodes] = 10.0 * np.log10(np.sum(10.0 ** (level / 10.0) * geometry.equivalent_time))
    assert sel[6] == pytest.approx(hand, abs=0.5)  # 57.11 against 57.09 dBA
    assert sel[3] == pytest.approx(hand, abs=0.5)  # 57.10
    assert abs(sel[1] - hand) > 3.0  # the closest point alone: 40.8 dBA


def test_reference_footprint_geometry_covers_the_departure():
    vehicle = footprint_vehicle()
    legs, geometry = footprint_geometry(vehicle)
    assert len(legs) == 6 and len(geometry) == 6
    # The observer under the vertiport hears the hover for its whole time, 76.2 - 1.2 m below.
    assert geometry[0].equivalent_time[1] == 30.0
    assert np.linalg.norm(geometry[0].offset[1]) == pytest.approx(75.0)


@pytest.fixture(scope="module")
def footprint_model():
    from lpc_mdo.groups.lpc import LPCGroup
    from lpc_mdo.problems import declare_problem

    vehicle = footprint_vehicle(max_lamax=95.0)
    prob = om.Problem(reports=False)
    prob.model = LPCGroup(vehicle=vehicle)
    declare_problem(prob.model)
    prob.driver = om.ScipyOptimizeDriver()
    prob.setup(mode="rev", force_alloc_complex=True)
    prob.run_model()
    return prob


@pytest.mark.integration
def test_footprint_rows_are_declared_and_sum_the_departure(footprint_model):
    prob = footprint_model
    constraints = prob.model.get_constraints()
    assert constraints["footprint_sel_max"]["upper"] == pytest.approx(85.0)
    assert constraints["footprint_lamax_max"]["upper"] == pytest.approx(95.0)
    # The exposure of each observer from the departure's levels and equivalent times by hand.
    vehicle = prob.model.options["vehicle"]
    legs, geometry = footprint_geometry(vehicle)
    energy = np.zeros(5)
    for name, points in departure_points(legs, geometry).items():
        level = prob.get_val(f"{name}.footprint_spl_a")
        np.add.at(energy, points.observer, 10.0 ** (level / 10.0) * points.equivalent_time)
    hand = 10.0 * np.log10(energy)
    np.testing.assert_allclose(prob.get_val("footprint_sel"), hand, rtol=1e-12)
    assert prob.get_val("footprint_sel_max")[0] >= hand.max()
    assert prob.get_val("footprint_sel_max")[0] <= hand.max() + np.log(5) / 10.0
    # The hover point heard straight below equals its own level there; a subproblem's model
    # (without every departure condition) has no footprint.
    from lpc_mdo.groups.lpc import footprint_conditions

    assert footprint_conditions(vehicle, vehicle.conditions[:3]) == {}


@pytest.mark.integration
def test_footprint_derivatives_match_complex_step(footprint_model):
    # The footprint rows' adjoint totals against complex step through the whole model, for the
    # design variables that reach them along both kinds of path: the lift rotors' hover speeds
    # (the hover's rotor state) and the transition pitch (the transition's rotor state and the
    # observers' directions); run_scripts/verify_derivatives.py --vehicle checks every column.
    prob = footprint_model
    wrt = ["hover_lift_rpm", "transition_pitch"]
    data = prob.check_totals(
        of=["footprint_sel_max", "footprint_lamax_max"],
        wrt=wrt,
        method="cs",
        out_stream=None,
        driver_scaling=True,
    )
    for key, entry in data.items():
        adjoint = np.asarray(entry["J_rev"] if "J_rev" in entry else entry["J_fwd"])
        reference = np.asarray(entry["J_fd"])
        scale = max(np.abs(reference).max(), 1e-8)
        assert np.abs(adjoint - reference).max() <= 1e-7 * scale, key


def test_footprint_figure_is_written_and_checks_its_values(tmp_path):
    from lpc_mdo.post.figures import plot_footprint

    vehicle = footprint_vehicle(
        lateral_offsets=[0.0, 150.0, 300.0], track_positions=[0.0, 1e3, 2e3]
    )
    sel = np.linspace(60.0, 80.0, 9)
    path = plot_footprint(vehicle, sel, sel - 10.0, tmp_path / "footprint.png")
    assert path.stat().st_size > 10000
    with pytest.raises(ValueError, match="9 observers"):
        plot_footprint(vehicle, sel[:5], sel[:5], tmp_path / "bad.png")


@pytest.mark.parametrize("name", ["footprint_sel_max", "footprint_lamax_max"])
def test_footprint_rows_are_shown_in_dba(name):
    from lpc_mdo.post.tables import display_units

    assert display_units({"units": None, "name": name}) == "dBA"


@pytest.mark.integration
def test_a_pusher_of_another_hub_ratio_is_heard_in_its_own_evaluation():
    # Lift rotors and pusher of different hub radius ratios cannot share the acoustic stations:
    # two noise evaluations per transition point, their levels added as energies.
    from lpc_mdo.groups.lpc import LPCGroup

    data = read_vehicle_file()
    data["pusher"]["hub_radius_ratio"] = 0.15
    data["noise_footprint"] = {**FOOTPRINT, "track_positions": [0.0, 1000.0]}
    vehicle = vehicle_from_dict(data)
    departure = [c.name for c in vehicle.conditions if c.kind in ("hover", "transition")]
    prob = om.Problem(reports=False)
    prob.model = LPCGroup(vehicle=vehicle, conditions=departure)
    prob.setup()
    prob.run_model()
    lift = prob.get_val("transition_2.footprint_noise_1.total_spl_a")
    pusher = prob.get_val("transition_2.footprint_noise_2.total_spl_a")
    both = prob.get_val("transition_2.footprint_spl_a")
    np.testing.assert_allclose(both, 10.0 * np.log10(10 ** (lift / 10) + 10 ** (pusher / 10)))
    assert np.all(np.isfinite(prob.get_val("footprint_sel")))


@pytest.mark.integration
def test_the_trim_keeps_the_departure_inside_the_footprint_levels_range():
    # A single condition's trim problem has no exposure (not the whole departure) but does
    # compute that condition's footprint levels, so that its solve backs off from a point
    # outside their range. Without them the reference's initial design trimmed transition_2
    # with a lift pair at 126 rpm, its tip slower than the flight (Gill-Lee: V_tip > 0), and
    # the whole model then failed on the trimmed design.
    from lpc_mdo.problems import build_analysis_problem
    from lpc_mdo.trim import single_condition_problem, trim

    prob = build_analysis_problem(footprint_vehicle(max_lamax=67.0), name="fp_trim")
    prob.final_setup()
    single = single_condition_problem(prob, "transition_2", name="fp_trim_single")
    assert single.model.heard_conditions == ["transition_2"]
    assert single.model.footprint_conditions == {}
    result = trim(prob, conditions=["transition_1", "transition_2", "transition_3"], workers=1)
    assert result.success, result.message
    prob.run_model()  # the whole model, with the exposure, runs at the trimmed design
    assert np.isfinite(prob.get_val("footprint_lamax_max")[0])
    plain = build_analysis_problem(vehicle_from_dict(read_vehicle_file()), name="plain_trim")
    plain.final_setup()
    assert (
        single_condition_problem(plain, "transition_2", "plain_single").model.heard_conditions == []
    )
