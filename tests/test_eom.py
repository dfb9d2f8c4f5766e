"""EquationsOfMotionComp (paper eq. 34; docs theory/dynamics 'Gravity', 'Equations of motion')."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.dynamics.eom import EquationsOfMotionComp
from lpc_mdo.core.constants import GRAVITY

# Reference docs theory/dynamics 'Equations of motion' check case (CADDEE code form,
# reference point = origin, inertia as given about the reference point, no gravity):
# m, cg, I, F = (100, 100, 100) N, M = (20, 20, 20) N m.
MASS = 7126.1992
CG = np.array([12.57675332, 0.0, 7.084392152])
I_REF = np.array(
    [[4376.344208, 0.0, 213.8989507], [0.0, 2174.842852, 0.0], [213.8989507, 0.0, 6157.83761]]
)
EXPECTED = np.array([1.67526e-2, -2.34018e-5, 9.20416e-3, 4.13169e-3, -3.83928e-4, 3.44498e-3])


def problem(nn=1):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("eom", EquationsOfMotionComp(num_nodes=nn), promotes=["*"])
    prob.setup(force_alloc_complex=True)
    return prob


def test_reference_check_case():
    """The code form's reference-point accelerations follow from ours about the cg.

    Its inertia is about the reference point (the origin), so ours takes
    I_cg = I_ref - m (|R|^2 E - R R^T) with R = cg, and the reference point accelerates with
    a_ref = a_cg + omega_dot x (0 - cg) at zero rates. Gravity is excluded (load factor 0).
    """
    prob = problem()
    prob.set_val("mass", MASS)
    prob.set_val("cg", CG)
    prob.set_val("inertia", I_REF - MASS * (CG @ CG * np.eye(3) - np.outer(CG, CG)))
    prob.set_val("force", [[100.0, 100.0, 100.0]])
    prob.set_val("moment", [[20.0, 20.0, 20.0]])
    prob.set_val("load_factor", [0.0])
    prob.run_model()
    a_cg = prob.get_val("linear_acceleration")[0]
    omega_dot = prob.get_val("angular_acceleration")[0]
    a_ref = a_cg + np.cross(omega_dot, -CG)
    # Reference numbers are printed to 6 significant digits.
    assert_near_equal(np.concatenate([a_ref, omega_dot]), EXPECTED, 2e-5)


def test_gravity_and_trim_closed_forms():
    prob = problem(nn=3)
    prob.set_val("mass", 3000.0)
    prob.set_val("inertia", np.diag([5e3, 8e3, 1.2e4]))
    prob.set_val("pitch", np.radians([0.0, 10.0, 0.0]))
    prob.set_val("load_factor", [1.0, 1.0, 3.0])
    # Node 0: hover with thrust exactly balancing weight -> zero acceleration (trim).
    # Node 1: no force at 10 deg pitch -> free fall resolved in the body axes.
    # Node 2: lift of 3 g at n = 3 -> trimmed.
    prob.set_val(
        "force",
        [[0.0, 0.0, -3000.0 * GRAVITY], [0.0, 0.0, 0.0], [0.0, 0.0, -3.0 * 3000.0 * GRAVITY]],
    )
    prob.run_model()
    acc = prob.get_val("linear_acceleration")
    assert_near_equal(acc[0], np.zeros(3), 1e-12)
    th = np.radians(10.0)
    assert_near_equal(acc[1], GRAVITY * np.array([-np.sin(th), 0.0, np.cos(th)]), 1e-12)
    assert_near_equal(acc[2], np.zeros(3), 1e-12)


def test_torque_free_gyroscopic_closed_form():
    # Euler's equations, zero moment: p_dot = (Iy - Iz) q r / Ix, etc.
    prob = problem()
    ix, iy, iz = 5e3, 8e3, 1.2e4
    p, q, r = 0.1, -0.2, 0.3
    prob.set_val("inertia", np.diag([ix, iy, iz]))
    prob.set_val("angular_rate", [[p, q, r]])
    prob.set_val("load_factor", [0.0])
    prob.run_model()
    expected = [(iy - iz) * q * r / ix, (iz - ix) * r * p / iy, (ix - iy) * p * q / iz]
    assert_near_equal(prob.get_val("angular_acceleration")[0], expected, 1e-12)


def test_partials():
    prob = problem(nn=2)
    rng = np.random.default_rng(0)
    prob.set_val("mass", 3700.0)
    prob.set_val("cg", [-3.1, 0.05, 0.4])
    inertia = np.array([[6e3, 50.0, -300.0], [50.0, 9e3, 20.0], [-300.0, 20.0, 1.4e4]])
    prob.set_val("inertia", inertia)
    for name in ("force", "moment", "velocity", "angular_rate"):
        prob.set_val(name, rng.normal(size=(2, 3)) * (1e3 if name in ("force", "moment") else 1))
    prob.set_val("roll", [0.1, -0.2])
    prob.set_val("pitch", [0.05, 0.3])
    prob.set_val("load_factor", [1.0, 3.0])
    prob.run_model()
    data = prob.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-9)


def test_bad_inputs():
    prob = problem()
    prob.set_val("mass", 0.0)
    with pytest.raises(om.AnalysisError, match=r"'mass' = 0.0 is out of range: must be > 0 \(kg\)"):
        prob.run_model()
    prob = problem()
    prob.set_val("inertia", np.zeros((3, 3)))
    with pytest.raises(om.AnalysisError, match="is singular"):
        prob.run_model()
