"""PittPetersRotorGroup: the 8 LPC lift rotors at two transition points, totals and solvers."""

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_totals, assert_no_approx_partials
from openmdao.utils.logger_utils import TestLogger as RecordingLogger

from lpc_mdo.groups.pitt_peters_rotor import PittPetersRotorGroup
from lpc_mdo.vehicle import reference_vehicle

pytestmark = pytest.mark.filterwarnings("ignore::openmdao.utils.om_warnings.DerivativesWarning")


@pytest.fixture(scope="module")
def transition_problem():
    vehicle = reference_vehicle()
    conditions = [c for c in vehicle.conditions if c.name in ("transition_1", "transition_3")]
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "rotors",
        PittPetersRotorGroup(
            rotors=list(vehicle.lift_rotors), num_nodes=len(conditions), num_radial=6, num_azimuth=8
        ),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    prob.set_val(
        "velocity",
        [[c.speed * np.cos(c.pitch), 0.0, c.speed * np.sin(c.pitch)] for c in conditions],
    )
    prob.set_val("rpm", np.full((8, len(conditions)), 1100.0))
    prob.run_model()
    return prob


def test_symmetric_vehicle_loads(transition_problem):
    # The mirror-image rotor pairs (opposite spin) cancel side force, roll and yaw moments.
    prob = transition_problem
    force, moment = prob.get_val("total_force"), prob.get_val("total_moment")
    thrust = prob.get_val("thrust")
    assert np.all(thrust > 0.0)
    np.testing.assert_allclose(force[:, 1], 0.0, atol=1e-9 * np.abs(force).max())
    np.testing.assert_allclose(moment[:, [0, 2]], 0.0, atol=1e-9 * np.abs(moment).max())
    # lift rotors lift: total force up (-z), and the H-forces oppose the forward speed (-x)
    assert np.all(force[:, 2] < 0.0) and np.all(force[:, 0] < 0.0)


def test_group_totals(transition_problem):
    prob = transition_problem
    data = prob.check_totals(
        of=["thrust", "power", "total_force", "total_moment"],
        wrt=["rpm", "radius", "chord_cp", "twist_cp", "velocity", "density"],
        method="cs",
        compact_print=True,
        out_stream=None,
    )
    assert_check_totals(data, atol=1e-6, rtol=1e-6)
    assert_no_approx_partials(prob.model, method="any")


def test_group_solvers_clean(transition_problem):
    logger = RecordingLogger()
    transition_problem.check_config(checks=["solvers"], logger=logger)
    assert logger.get("warning") == [] and logger.get("error") == []


def test_group_without_body_frame():
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "rotors",
        PittPetersRotorGroup(
            num_rotors=2, spin_direction=[1, -1], num_radial=5, num_azimuth=6, body_frame=False
        ),
        promotes=["*"],
    )
    prob.setup()
    prob.set_val("radius", [1.5, 1.5])
    prob.set_val("rpm", [[1100.0], [1100.0]])
    prob.set_val("inplane_velocity", [[[20.0, 0.0]], [[20.0, 0.0]]])
    prob.run_model()
    np.testing.assert_allclose(prob.get_val("thrust")[0], prob.get_val("thrust")[1])
    with pytest.raises(KeyError):
        prob.get_val("total_force")
