"""Pitt–Peters components: frames and signs, symmetry, solver robustness, input errors."""

import numpy as np
import openmdao.api as om
import pytest

from lpc_mdo.components.rotor.pitt_peters_inflow import PittPetersInflowComp
from lpc_mdo.components.rotor.pitt_peters_loads import PittPetersLoadsComp

RADIUS = 1.524
NRAD, NAZ = 12, 16


def build(nr=1, nn=1, spin=1, naz=NAZ, **options):
    kw = dict(
        num_rotors=nr,
        num_nodes=nn,
        num_radial=NRAD,
        num_azimuth=naz,
        spin_direction=spin,
        **options,
    )
    prob = om.Problem()
    prob.model.add_subsystem("inflow", PittPetersInflowComp(**kw), promotes=["*"])
    prob.model.add_subsystem("loads", PittPetersLoadsComp(**kw), promotes=["*"])
    prob.setup()
    rh = 0.2 * RADIUS
    eta = (np.arange(NRAD) + 0.5) / NRAD
    prob.set_val("radius", np.full(nr, RADIUS))
    prob.set_val("hub_radius", np.full(nr, rh))
    prob.set_val("station_radius", np.tile(rh + (RADIUS - rh) * eta, (nr, 1)))
    prob.set_val("station_width", np.full((nr, NRAD), (RADIUS - rh) / NRAD))
    prob.set_val("chord", np.tile(np.linspace(0.3, 0.1, NRAD), (nr, 1)))
    prob.set_val("twist", np.tile(np.radians(np.linspace(30.0, 10.0, NRAD)), (nr, 1)))
    prob.set_val("rpm", np.full((nr, nn), 1100.0))
    return prob


def test_hub_loads_equal_vector_sums_of_sectional_loads():
    # Independent check of the frame conventions: the blade of azimuth psi sits at
    # r (-cos psi e_x + s sin psi e_y) and moves along t = sin psi e_x + s cos psi e_y; summing
    # the body-frame vectors t n - d t and p x (t n - d t) over the disk must give thrust,
    # inplane_force, hub_moment and the torque reaction -s Q n (HubLoadsComp convention).
    prob = build(nr=2, spin=[1, -1])
    prob.set_val("inplane_velocity", [[[35.0, 4.0]], [[35.0, 4.0]]])
    prob.set_val("axial_velocity", [[-1.5], [-1.5]])
    prob.run_model()
    n, e_y = np.array([0.0, 0.0, -1.0]), np.array([0.0, 1.0, 0.0])
    e_x = np.cross(n, e_y)
    psi = 2 * np.pi * np.arange(NAZ) / NAZ
    r = prob.get_val("station_radius")
    w = prob.get_val("station_width")
    for j, s in enumerate((1.0, -1.0)):
        t = prob.get_val("thrust_per_span")[j, 0]
        d = prob.get_val("drag_per_span")[j, 0]
        pos = r[j][:, None, None] * (
            -np.cos(psi)[None, :, None] * e_x + s * np.sin(psi)[None, :, None] * e_y
        )
        tangent = np.sin(psi)[:, None] * e_x + s * np.cos(psi)[:, None] * e_y
        # the blade velocity s Omega n x p is along +tangent (direction of rotation)
        np.testing.assert_allclose(s * np.cross(n, pos[-1]), r[j, -1] * tangent, atol=1e-12)
        force = t[..., None] * n - d[..., None] * tangent[None]
        weight = 2 * w[j][:, None, None] / NAZ
        f_sum = np.sum(weight * force, axis=(0, 1))
        m_sum = np.sum(weight * np.cross(pos, force), axis=(0, 1))
        thrust = prob.get_val("thrust")[j, 0]
        h = prob.get_val("inplane_force")[j, 0]
        m = prob.get_val("hub_moment")[j, 0]
        q = prob.get_val("torque")[j, 0]
        np.testing.assert_allclose(
            f_sum, thrust * n + h[0] * e_x + h[1] * e_y, rtol=1e-12, atol=1e-9
        )
        np.testing.assert_allclose(
            m_sum, m[0] * e_x + m[1] * e_y - s * q * n, rtol=1e-12, atol=1e-9
        )


def test_forward_flight_signs_and_mirror_symmetry():
    # Lift rotors in forward flight (V along +e_x = +x): the H-force opposes the motion, the
    # advancing side (psi = 90 deg: +y for spin +1, -y for spin -1) lifts more, so the rolling
    # moment is toward the retreating side, and the mirror-image rotor (spin -1, mirrored
    # sideslip) has mirrored in-plane loads and the same thrust, torque and sectional fields.
    prob = build(nr=2, spin=[1, -1])
    prob.set_val("inplane_velocity", [[[30.0, 3.0]], [[30.0, -3.0]]])
    prob.run_model()
    thrust, torque = prob.get_val("thrust")[:, 0], prob.get_val("torque")[:, 0]
    h, m = prob.get_val("inplane_force")[:, 0], prob.get_val("hub_moment")[:, 0]
    assert thrust[0] == pytest.approx(thrust[1], rel=1e-12)
    assert torque[0] == pytest.approx(torque[1], rel=1e-12)
    np.testing.assert_allclose(h[1], h[0] * [1, -1], rtol=1e-12)
    np.testing.assert_allclose(m[1], m[0] * [-1, 1], rtol=1e-12)
    np.testing.assert_allclose(
        prob.get_val("thrust_per_span")[1], prob.get_val("thrust_per_span")[0], rtol=1e-12
    )
    assert h[0, 0] < 0.0  # H-force against the flight direction
    assert m[0, 0] < 0.0 < m[1, 0]  # roll toward the retreating side (right up for s=+1)
    states = prob.get_val("inflow_states")
    assert states[0, 0, 1] > 0.0 and states[0, 0, 2] > 0.0  # more inflow aft and advancing


def test_newton_converges_over_transition_envelope_from_cold_start():
    # Speeds 0..60 m/s and body pitch -10..10 deg (axial velocity -V sin(theta) for a lift
    # rotor) at 1100 rpm, all in one vectorized call from the cold start.
    speeds, pitches = np.meshgrid(np.linspace(0.0, 60.0, 7), np.radians([-10, -5, 0, 5, 10]))
    speeds, pitches = speeds.ravel(), pitches.ravel()
    nn = speeds.size
    prob = build(nn=nn)
    prob.set_val("inplane_velocity", np.stack([speeds * np.cos(pitches), 0 * speeds], -1)[None])
    prob.set_val("axial_velocity", (-speeds * np.sin(pitches))[None])
    prob.run_model()
    comp = prob.model.inflow
    assert comp.newton_iterations <= 12
    prob.model.run_apply_nonlinear()
    res = prob.model.inflow._residuals["inflow_states"]
    assert np.max(np.abs(res)) < 1e-12
    # warm start after a small change: few iterations
    prob.set_val("rpm", np.full((1, nn), 1120.0))
    prob.run_model()
    assert comp.newton_iterations <= 4


def test_states_outside_model_raise_instead_of_nan():
    # Axial descent with a total inflow lambda = mu_z + lambda_0 < 0 and no edgewise speed has
    # no mass flow parameter (V_T + lambda = 0): the residual raises, it never returns NaN.
    prob = build()
    prob.set_val("axial_velocity", [[-25.0]])
    prob.final_setup()
    prob.model.inflow._outputs["inflow_states"] = [[[0.01, 0.0, 0.0]]]
    with pytest.raises(om.AnalysisError, match="outside the Pitt"):
        prob.model.run_apply_nonlinear()


@pytest.mark.parametrize(
    "name, value, pattern",
    [
        (
            "hub_radius",
            [1.6],
            "'hub_radius\\[0\\]' = 1.6 is out of range: must be in \\(0, 1.524\\) \\(m\\)",
        ),
        (
            "chord",
            np.full((1, NRAD), -0.1),
            "'chord\\[0, 0\\]' = -0.1 is out of range: must be > 0 \\(m\\)",
        ),
        ("rpm", [[0.0]], "'rpm\\[0, 0\\]' = 0.0 is out of range: must be > 0 \\(rpm\\)"),
        (
            "axial_velocity",
            [[np.nan]],
            "'axial_velocity\\[0, 0\\]' = nan is out of range: must be a finite number",
        ),
    ],
)
def test_bad_inputs_raise_clear_errors(name, value, pattern):
    prob = build()
    prob.set_val(name, value)
    with pytest.raises(om.AnalysisError, match=pattern):
        prob.run_model()


@pytest.mark.parametrize(
    "option, value, pattern",
    [
        ("num_blades", 0, "'num_blades\\[0\\]' = 0 is out of range: must be >= 1"),
        ("spin_direction", 0, "'spin_direction\\[0\\]' = 0 is not allowed: must be one of 1, -1"),
        ("spin_direction", [1, 1], "option 'spin_direction'.*num_rotors = 1"),
    ],
)
def test_bad_options_raise_clear_errors(option, value, pattern):
    prob = om.Problem()
    prob.model.add_subsystem("inflow", PittPetersInflowComp(**{option: value}))
    with pytest.raises(ValueError, match=pattern):
        prob.setup()


def test_too_few_azimuth_stations_rejected():
    with pytest.raises(ValueError, match="num_azimuth"):
        PittPetersLoadsComp(num_azimuth=2)


def test_loads_partials_reuse_the_inflow_linearization_and_equal_their_own():
    # The inflow component's linearization leaves its station field (with partials) in a cache
    # that the loads component, at the same inputs and states, reads instead of recomputing;
    # the partials are those the loads component computes on its own.
    from lpc_mdo.components.aero.polar import LinearQuadraticPolar
    from lpc_mdo.components.rotor import pitt_peters_loads as ppl

    # One polar object for both, as in a rotor group (the cache knows polars by identity).
    prob = build(nr=2, spin=[1, -1], polar=LinearQuadraticPolar())
    prob.set_val("inplane_velocity", [[[30.0, 2.0]], [[30.0, 2.0]]])
    prob.set_val("axial_velocity", [[-1.0], [-1.0]])
    prob.run_model()
    inflow, loads = prob.model.inflow, prob.model.loads
    ppl._SHARED_FIELDS.clear()
    inflow.run_linearize()
    assert len(ppl._SHARED_FIELDS) == 1
    (entry,) = ppl._SHARED_FIELDS.values()
    loads.run_linearize()
    shared = {k: np.array(v["val"]) for k, v in loads._subjacs_info.items()}
    (after,) = ppl._SHARED_FIELDS.values()  # a hit: no new entry
    assert after is entry
    ppl._SHARED_FIELDS.clear()
    loads.run_linearize()  # on its own
    for key, meta in loads._subjacs_info.items():
        np.testing.assert_allclose(shared[key], meta["val"], rtol=1e-12, atol=1e-14, err_msg=key)
    # Other inputs, another entry.
    prob.set_val("rpm", np.full((2, 1), 1150.0))
    prob.run_model()
    inflow.run_linearize()
    assert len(ppl._SHARED_FIELDS) == 2


def test_linearization_reusing_the_solve_equals_a_fresh_one():
    # The nonlinear solve leaves its last swirl solution and its checked inputs (keyed by the
    # exact inputs and states) on the component; the linearization at the solved point reuses
    # them. Its partials are those of a fresh evaluation, and changed inputs are checked again.
    from lpc_mdo.components.rotor import pitt_peters_loads as ppl

    prob = build(nr=2, spin=[1, -1])
    prob.set_val("inplane_velocity", [[[25.0, -3.0]], [[25.0, -3.0]]])
    prob.run_model()
    comps = (prob.model.inflow, prob.model.loads)
    ppl._SHARED_FIELDS.clear()
    for comp in comps:
        comp.run_linearize()
    reused = [{k: np.array(v["val"]) for k, v in c._subjacs_info.items()} for c in comps]
    ppl._SHARED_FIELDS.clear()
    for comp, ref in zip(comps, reused, strict=True):
        comp._field._last_swirl = (None, None)
        comp._checked_inputs = None
        comp.run_linearize()
        for key, meta in comp._subjacs_info.items():
            np.testing.assert_allclose(meta["val"], ref[key], rtol=1e-12, atol=1e-14, err_msg=key)
    prob.set_val("chord", np.full((2, NRAD), -0.1))
    with pytest.raises(om.AnalysisError, match="chord"):
        prob.run_model()
