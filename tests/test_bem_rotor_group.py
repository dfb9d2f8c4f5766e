"""Tests for lpc_mdo.groups.bem_rotor.BEMRotorGroup (assembly, totals, vectorization)."""

import logging

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_totals, assert_no_approx_partials

from lpc_mdo.groups.bem_rotor import BEMRotorGroup, rotor_options
from lpc_mdo.vehicle import reference_vehicle

VEHICLE = reference_vehicle()
# A lift rotor and the pusher (different radius, blades, twist, thrust axis and spin).
ROTORS = (VEHICLE.lift_rotors[0], VEHICLE.pusher)


def _group_problem(rotors=ROTORS, num_nodes=2, num_radial=8, mode="auto", **options):
    prob = om.Problem()
    prob.model.add_subsystem(
        "rotor",
        BEMRotorGroup(rotors=rotors, num_nodes=num_nodes, num_radial=num_radial, **options),
        promotes=["*"],
    )
    prob.setup(mode=mode, force_alloc_complex=True)
    return prob


@pytest.mark.parametrize("mode", ["fwd", "rev"])
def test_check_totals(mode):
    prob = _group_problem(mode=mode)
    prob.set_val("rpm", [[1200.0, 1100.0], [900.0, 1300.0]])
    prob.set_val("velocity", [[0.0, 0.0, 0.0], [30.0, 0.0, -3.0]])  # hover; climbing flight
    prob.set_val("density", [1.2, 1.1])
    prob.set_val("reference_point", [-4.0, 0.0, -0.5])
    prob.run_model()
    data = prob.check_totals(
        of=[
            "thrust",
            "power",
            "figure_of_merit",
            "efficiency",
            "tip_mach",
            "thrust_per_span",
            "total_force",
            "total_moment",
        ],
        wrt=[
            "radius",
            "chord_cp",
            "twist_cp",
            "rpm",
            "velocity",
            "hub_position",
            "reference_point",
            "density",
        ],
        method="cs",
        compact_print=True,
        out_stream=None,
    )
    assert_check_totals(data, atol=1e-6, rtol=1e-6)


def test_assembly_checks():
    prob = _group_problem()
    prob.final_setup()
    assert_no_approx_partials(prob.model, method="any")
    records = []

    class _Collect(logging.Handler):
        def emit(self, record):
            records.append(record)

    logger = logging.getLogger("bem_rotor_group_check")
    logger.addHandler(_Collect())
    logger.setLevel(logging.INFO)
    prob.check_config(logger=logger, checks=["solvers"], out_file=None)
    assert not [r for r in records if r.levelno >= logging.WARNING]


def test_vectorized_rotors_match_single_rotor_runs():
    # 8 lift rotors at 8 different speeds in one call equal 8 separate single-rotor calls
    # (no coupling between rotors; 1e-12 relative), and mirror pairs at equal rpm give equal
    # thrust with opposite yaw moments.
    rpm = np.linspace(900.0, 1400.0, 8)[:, None]
    prob = _group_problem(rotors=VEHICLE.lift_rotors, num_nodes=1, num_radial=10)
    prob.set_val("rpm", rpm)
    prob.run_model()
    thrust, torque = prob.get_val("thrust"), prob.get_val("torque")
    for i, rotor in enumerate(VEHICLE.lift_rotors):
        single = _group_problem(rotors=(rotor,), num_nodes=1, num_radial=10)
        single.set_val("rpm", rpm[i])
        single.run_model()
        np.testing.assert_allclose(single.get_val("thrust")[0], thrust[i], rtol=1e-12)
        np.testing.assert_allclose(single.get_val("torque")[0], torque[i], rtol=1e-12)
    prob.set_val("rpm", np.full((8, 1), 1200.0))
    prob.run_model()
    moment = prob.get_val("moment")
    np.testing.assert_allclose(moment[0, 0, 2], -moment[6, 0, 2], rtol=1e-12)  # pair 0
    np.testing.assert_allclose(prob.get_val("total_moment")[0, [0, 2]], 0.0, atol=1e-8)


def test_axial_velocity_input_without_body_frame():
    prob = om.Problem()
    prob.model.add_subsystem(
        "rotor",
        BEMRotorGroup(num_rotors=2, num_blades=[2, 3], num_radial=6, body_frame=False),
        promotes=["*"],
    )
    prob.setup()
    prob.set_val("axial_velocity", [[0.0], [10.0]])
    prob.set_val("rpm", [[1500.0], [1500.0]])
    prob.run_model()
    assert prob.get_val("thrust").shape == (2, 1)
    assert prob.get_val("efficiency")[1, 0] > 0.0 == prob.get_val("efficiency")[0, 0]


def test_options():
    opts = rotor_options(VEHICLE.lift_rotors)
    assert opts["num_rotors"] == 8 and opts["spin_direction"][:2] == [1, -1]
    prob = om.Problem()
    prob.model.add_subsystem("rotor", BEMRotorGroup(rotors=ROTORS, num_blades=2))
    with pytest.raises(ValueError, match=r"options \['num_blades'\] must be left at None"):
        prob.setup()


def test_loads_partials_reuse_the_inflow_linearization_and_equal_their_own():
    # BEMInflowComp's linearization leaves the sections' local partials (with the loads) in a
    # cache that BEMLoadsComp, at the same inputs and inflow angle, reads; the partials are
    # those it computes on its own.
    from lpc_mdo.components.rotor import bem_inflow

    prob = _group_problem()
    prob.run_model()
    group = prob.model.rotor
    bem_inflow._SHARED_LINEARIZATIONS.clear()
    group.inflow.run_linearize()
    (entry,) = bem_inflow._SHARED_LINEARIZATIONS.values()
    group.loads.run_linearize()
    (after,) = bem_inflow._SHARED_LINEARIZATIONS.values()  # a hit: no new entry
    assert after is entry
    shared = {k: np.array(v["val"]) for k, v in group.loads._subjacs_info.items()}
    bem_inflow._SHARED_LINEARIZATIONS.clear()
    group.loads.run_linearize()  # on its own
    for key, meta in group.loads._subjacs_info.items():
        np.testing.assert_array_equal(shared[key], meta["val"], err_msg=str(key))
