"""Pitt–Peters components: partial derivatives against complex step (and FD for the CS part)."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_no_approx_partials

from lpc_mdo.components.aero.polar import Polar, PolarValues
from lpc_mdo.components.rotor.pitt_peters_inflow import PittPetersInflowComp
from lpc_mdo.components.rotor.pitt_peters_loads import PittPetersLoadsComp

# The analytic default polar does not depend on Reynolds or Mach number: OpenMDAO warns that
# those declared partials are zero. They are exercised with ReMachPolar below.
pytestmark = pytest.mark.filterwarnings("ignore::openmdao.utils.om_warnings.DerivativesWarning")


class ReMachPolar(Polar):
    """Smooth test polar with Reynolds and Mach dependence (exercises those partial paths)."""

    name = "test_re_mach"

    def evaluate(self, alpha, reynolds, mach):
        alpha, reynolds, mach = np.broadcast_arrays(
            np.asarray(alpha), np.asarray(reynolds), np.asarray(mach)
        )
        s, c = np.sin(alpha), np.cos(alpha)
        beta = 1.0 / np.sqrt(1.0 - mach**2)  # Prandtl–Glauert
        f_re = 1.0 + 0.05 * np.log(reynolds / 1e6)
        a = 5.5 * beta * f_re
        cl = a * s * c + 0.4 * c**2 * s + 0.3 * c
        dcl = a * (c * c - s * s) + 0.4 * (c**3 - 2 * c * s * s) - 0.3 * s
        cd0 = 0.01 * (reynolds / 1e6) ** -0.2
        cd = cd0 + 1.2 * s * s
        return PolarValues(
            cl=cl,
            cd=cd,
            dcl_dalpha=dcl,
            dcd_dalpha=2.4 * s * c,
            dcl_dreynolds=5.5 * beta * 0.05 / reynolds * s * c,
            dcd_dreynolds=-0.2 * cd0 / reynolds,
            dcl_dmach=5.5 * f_re * mach * beta**3 * s * c,
            dcd_dmach=np.zeros(alpha.shape),
        )


def build(nr=2, nn=3, nrad=6, naz=7, loads_options=None, **options):
    """
    Return a problem of two rotors (opposite spin) at three nodes.

    ``loads_options``: further options of the loads component only.

    The nodes are hover-climb, edgewise with sideslip, and high advance ratio with reverse flow
    on the retreating side.
    """
    kw = dict(
        num_rotors=nr,
        num_nodes=nn,
        num_radial=nrad,
        num_azimuth=naz,
        num_blades=[2, 3],
        spin_direction=[1, -1],
        **options,
    )
    prob = om.Problem()
    prob.model.add_subsystem("inflow", PittPetersInflowComp(**kw), promotes=["*"])
    prob.model.add_subsystem(
        "loads", PittPetersLoadsComp(**kw, **(loads_options or {})), promotes=["*"]
    )
    prob.setup(force_alloc_complex=True)
    radius = np.array([1.2, 1.5])
    rh = np.array([0.24, 0.33])
    eta = (np.arange(nrad) + 0.5) / nrad
    prob.set_val("radius", radius)
    prob.set_val("hub_radius", rh)
    prob.set_val("station_radius", rh[:, None] + (radius - rh)[:, None] * eta)
    prob.set_val("station_width", ((radius - rh) / nrad)[:, None] * np.ones(nrad))
    prob.set_val("chord", np.array([np.linspace(0.25, 0.08, nrad), np.linspace(0.3, 0.1, nrad)]))
    prob.set_val(
        "twist", np.radians([np.linspace(40.0, 15.0, nrad), np.linspace(30.0, 10.0, nrad)])
    )
    prob.set_val("rpm", np.array([[2000.0, 1800.0, 1000.0], [1500.0, 1300.0, 900.0]])[:, :nn])
    prob.set_val("axial_velocity", np.array([[1.5, -2.0, 3.0], [0.0, 2.0, -4.0]])[:, :nn])
    prob.set_val(
        "inplane_velocity",
        np.array([[[0.0, 0.0], [30.0, 6.0], [60.0, 0.0]], [[0.0, 0.0], [25.0, -8.0], [55.0, 5.0]]])[
            :, :nn
        ],
    )
    prob.set_val("density", np.array([1.2, 1.1, 1.0])[:nn])
    prob.set_val("speed_of_sound", np.array([340.0, 338.0, 336.0])[:nn])
    prob.set_val("dynamic_viscosity", np.array([1.79e-5, 1.78e-5, 1.77e-5])[:nn])
    prob.run_model()
    return prob


CASES = {
    "default": {},  # F on the momentum side, with the tangential induction (swirl)
    "blade_element_placement": {"loss_placement": "blade_element"},
    "no_swirl": {"tangential_induction": False},
    "blade_element_no_swirl": {"loss_placement": "blade_element", "tangential_induction": False},
    "tip_loss_only": {"hub_loss": False},
    "re_mach_polar": {"polar": ReMachPolar()},
}


@pytest.mark.parametrize("case", CASES, ids=list(CASES))
def test_partials_complex_step(case):
    prob = build(**CASES[case])
    inflow = prob.get_val("inflow_states")
    # the high-advance-ratio node has reverse flow at inboard retreating stations
    assert np.any(prob.get_val("inflow_angle")[0, 2] > np.pi / 2)
    assert np.all(np.isfinite(inflow))
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-6, rtol=1e-8)
    assert_no_approx_partials(prob.model, method="any")


def test_without_sectional_loads_the_rotor_loads_are_the_same():
    # A condition that reads only the rotor loads leaves the sectional loads out; the thrust,
    # torque, in-plane force and hub moment and their partials must not change.
    full = build()
    lean = build(loads_options={"sectional_loads": False})
    outputs = lean.model.loads.list_outputs(out_stream=None)
    assert {name for name, _ in outputs} == {"thrust", "torque", "inplane_force", "hub_moment"}
    for name, _ in outputs:
        np.testing.assert_array_equal(lean.get_val(name), full.get_val(name))
    data = lean.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-6, rtol=1e-8)


def test_partials_no_losses_finite_difference():
    # Independent check method (FD) of the complex-stepped 3x3 algebra, without Prandtl losses.
    prob = build(nr=2, nn=2, nrad=5, naz=6, tip_loss=False, hub_loss=False)
    data = prob.check_partials(
        method="fd", form="central", step=1e-6, compact_print=True, out_stream=None
    )
    assert_check_partials(data, atol=1e-3, rtol=2e-5)


def test_solve_linear_matches_jacobian_blocks():
    # solve_linear inverts the 3x3 blocks of d R/d lambda: fwd and rev against numpy.
    prob = build(nr=2, nn=2, nrad=5, naz=6)
    comp = prob.model.inflow
    prob.model.run_linearize()
    jac = comp._inverse
    rng = np.random.default_rng(0)
    rhs = rng.normal(size=(2, 2, 3))
    d_out = {"inflow_states": np.zeros((2, 2, 3))}
    d_res = {"inflow_states": rhs}
    comp.solve_linear(d_out, d_res, "fwd")
    direct = np.linalg.inv(jac)
    np.testing.assert_allclose(
        np.einsum("...ab,...b->...a", direct, d_out["inflow_states"]), rhs, rtol=1e-12, atol=1e-14
    )
    d_out = {"inflow_states": rhs}
    d_res = {"inflow_states": np.zeros((2, 2, 3))}
    comp.solve_linear(d_out, d_res, "rev")
    np.testing.assert_allclose(
        np.einsum("...ba,...b->...a", direct, d_res["inflow_states"]), rhs, rtol=1e-12, atol=1e-14
    )
