"""Observer position and rotor-observer geometry.

Reference: docs theory/acoustics 'Observer and constraint', 'Observer geometry'.
"""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_near_equal

from lpc_mdo.components.acoustics.observer import ObserverGeometryComp, ObserverPositionComp


def _geometry(hub, direction, observer, velocity=(0.0, 0.0, 0.0), a=340.0, rotation=None):
    hub = np.atleast_2d(hub)
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "g",
        ObserverGeometryComp(num_rotors=hub.shape[0], rotation_direction=rotation),
        promotes=["*"],
    )
    prob.setup()
    prob.set_val("hub_position", hub)
    prob.set_val("thrust_direction", np.broadcast_to(direction, hub.shape))
    prob.set_val("observer_position", observer)
    prob.set_val("flight_velocity", velocity)
    prob.set_val("speed_of_sound", a)
    prob.run_model()
    return prob


def test_default_observer_is_paper_hover_observer():
    # docs theory/acoustics 'Observer and constraint': 100 m from the rotors,
    # 45 deg below the rotor plane; seen from the observer the vehicle is at (70.71, 0, -70.71) m,
    # i.e. the observer is at centroid + (-70.71, 0, 70.71).
    hubs = np.array([[1.0, -5.0, -1.0], [6.0, -5.0, -1.5], [1.0, 5.0, -1.0], [6.0, 5.0, -1.5]])
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("p", ObserverPositionComp(num_rotors=4), promotes=["*"])
    prob.setup()
    prob.set_val("hub_position", hubs)
    prob.run_model()
    expected = hubs.mean(axis=0) + 100.0 * np.array([-np.sqrt(0.5), 0.0, np.sqrt(0.5)])
    assert_near_equal(prob.get_val("observer_position"), expected, tolerance=1e-12)


def test_hover_geometry_and_azimuth_convention():
    # Thrust up (0, 0, -1), observer 100 m away, 45 deg below and aft of the hub: S = 100,
    # z = P.n = -70.71 (wake side), Y = 70.71; the observer lies at blade azimuth psi = 0 (aft)
    # of the BladeAD rotor frame, so cos(phi_o) = 1 (exact geometry, 1e-10).
    c = 100.0 * np.sqrt(0.5)
    prob = _geometry([0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [-c, 0.0, c])
    assert_near_equal(prob.get_val("distance"), [100.0], tolerance=1e-12)
    assert_near_equal(prob.get_val("axial_distance"), [-c], tolerance=1e-12)
    assert_near_equal(prob.get_val("inplane_distance"), [c], tolerance=1e-10)
    assert_near_equal(prob.get_val("convected_distance"), [100.0], tolerance=1e-12)
    assert_near_equal(prob.get_val("observer_azimuth_cos"), [1.0], tolerance=1e-10)
    assert abs(prob.get_val("observer_azimuth_sin")[0]) < 1e-12
    # Observer on the right (+y): psi = 90 deg for a rotor turning counter-clockwise seen from
    # above (rotation_direction +1, advancing side on the right), -90 deg for -1.
    for rotation, sign in ((1, 1.0), (-1, -1.0)):
        prob = _geometry([0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, c, c], rotation=(rotation,))
        assert_near_equal(prob.get_val("observer_azimuth_sin"), [sign], tolerance=1e-10)


def test_doppler_distance():
    # docs theory/acoustics 'Tonal loading noise': r1 = S (1 - V.P/(S a)).
    # Hub moving at 50 m/s straight towards an observer 100 m ahead: r1 = 100 (1 - 50/340);
    # moving away: 100 (1 + 50/340). Exact, 1e-12.
    for sign in (1.0, -1.0):
        prob = _geometry(
            [0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [100.0, 0.0, 0.0], velocity=(sign * 50.0, 0.0, 0.0)
        )
        assert_near_equal(
            prob.get_val("convected_distance"), [100.0 * (1 - sign * 50 / 340)], tolerance=1e-12
        )
        assert_near_equal(prob.get_val("inplane_speed"), [50.0], tolerance=1e-12)
        assert abs(prob.get_val("axial_speed")[0]) < 1e-12


def test_bad_inputs_raise_clear_errors():
    with pytest.raises(om.AnalysisError, match="'distance"):
        _geometry([1.0, 2.0, 3.0], [0.0, 0.0, -1.0], [1.0, 2.0, 3.0])
    with pytest.raises(om.AnalysisError, match="'thrust_direction"):
        _geometry([0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [10.0, 0.0, 0.0])
    with pytest.raises(om.AnalysisError, match="speed of sound"):
        _geometry([0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [100.0, 0.0, 0.0], velocity=(400.0, 0.0, 0.0))
    with pytest.raises(ValueError, match="rotation_direction"):
        _geometry([0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [100.0, 0.0, 0.0], rotation=(2,))


def test_several_observer_positions_and_per_rotor_observers():
    # Three observers about the hub centroid (closed form of ObserverPositionComp per observer),
    # and a geometry whose rotors each have their own observer equals the shared-observer
    # geometry rotor by rotor (1e-14); partials of both against complex step.
    from openmdao.utils.assert_utils import assert_check_partials

    hubs = np.array([[1.0, -5.0, -1.0], [6.0, -5.0, -1.5]])
    dist, elev, azim = (
        np.array([100.0, 30.0, 500.0]),
        np.array([0.7, -0.2, 1.2]),
        np.array([3.0, 0.4, -2.0]),
    )
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("p", ObserverPositionComp(num_rotors=2, num_observers=3))
    prob.model.add_subsystem(
        "g", ObserverGeometryComp(num_rotors=2, rotation_direction=(1, -1), observer_per_rotor=True)
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val("p.hub_position", hubs)
    prob.set_val("p.observer_distance", dist)
    prob.set_val("p.observer_elevation", elev)
    prob.set_val("p.observer_azimuth", azim)
    prob.set_val("g.hub_position", hubs)
    prob.set_val("g.thrust_direction", [[0.1, 0.0, -1.0], [0.0, 0.2, -1.0]])
    prob.set_val("g.observer_position", [[-60.0, 10.0, 70.0], [200.0, -50.0, 30.0]])
    prob.set_val("g.flight_velocity", [20.0, 1.0, -2.0])
    prob.run_model()
    direction = np.stack(
        [np.cos(elev) * np.cos(azim), np.cos(elev) * np.sin(azim), np.sin(elev)], 1
    )
    assert_near_equal(
        prob.get_val("p.observer_position"), hubs.mean(axis=0) + dist[:, None] * direction, 1e-12
    )
    for k, observer in enumerate(prob.get_val("g.observer_position")):
        one = _geometry(hubs[k], prob.get_val("g.thrust_direction")[k], observer,
                        velocity=[20.0, 1.0, -2.0], rotation=((1, -1)[k],))  # fmt: skip
        for name in ("distance", "inplane_distance", "observer_azimuth_cos", "inplane_speed"):
            assert_near_equal(prob.get_val(f"g.{name}")[k], one.get_val(name)[0], 1e-14)
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-9, rtol=1e-9)
