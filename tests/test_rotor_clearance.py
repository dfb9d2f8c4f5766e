"""Plan-view rotor clearances (docs theory/geometry 'Rotor clearances')."""

import dataclasses

import numpy as np
import openmdao.api as om
import pytest
from openmdao.utils.assert_utils import assert_check_partials, assert_near_equal

from lpc_mdo.components.geometry.rotor_clearance import RotorClearanceComp
from lpc_mdo.groups.vehicle import VehicleGroup
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.clearances import (
    clearance_constraints,
    constrained_rotors,
    is_mirror_symmetric,
    rotor_pairs,
)

VEHICLE = reference_vehicle()


def _problem(side, **options):
    prob = om.Problem(reports=False)
    prob.model.add_subsystem(
        "clearance",
        RotorClearanceComp(side=side, num_groups=2, pusher_row=1, **options),
        promotes=["*"],
    )
    prob.setup(force_alloc_complex=True)
    return prob


@pytest.fixture
def sketch():
    """
    Two left rotors, a rectangular tail and a pusher, laid out for hand calculation.

    Rotor 0 at (-3.5, -3), R = 1; rotor 1 at (-3.5, -6), R = 1.2. Fuselage 1 m wide. Tail: a
    rectangle (no sweep, taper 1) from x = -5 to -6 over abs(y) <= 2. Pusher at (-8, 0),
    R_p = 1.5, thrust along x: the segment x = -8, abs(y) <= 1.5 in plan view.
    """
    prob = _problem([-1.0, -1.0], fuselage_max_width=1.0)
    prob.set_val("lift_hub_position", [[-3.5, -3.0, -1.0], [-3.5, -6.0, -0.5]])
    prob.set_val("lift_rotor_radius", [1.0, 1.2])
    prob.set_val("rotor_radius", [1.0, 1.5])
    prob.set_val("pusher_hub_position", [-8.0, 0.0, -0.8])
    prob.set_val("htail_root_leading_edge", [-5.0, 0.0, -0.9])
    prob.set_val("htail_span", 4.0)
    prob.set_val("htail_root_chord", 1.0)
    prob.set_val("htail_tip_chord", 1.0)
    prob.set_val("htail_sweep", 0.0)
    return prob


def test_circles_and_rectangle_by_hand(sketch):
    sketch.run_model()
    # Disks 3 m apart centre to centre, radii 1 + 1.2.
    assert_near_equal(sketch.get_val("lift_rotor_clearance"), [3.0 - 2.2], 1e-14)
    # abs(y) - R - w/2.
    assert_near_equal(sketch.get_val("rotor_fuselage_clearance"), [3 - 1 - 0.5, 6 - 1.2 - 0.5])
    # Nearest tail point: the leading-edge tip corner (-5, -2), 1.5 m aft and 1 m inboard
    # (rotor 0); 1.5 m and 4 m (rotor 1).
    assert_near_equal(
        sketch.get_val("rotor_tail_clearance"),
        [np.hypot(1.5, 1.0) - 1.0, np.hypot(1.5, 4.0) - 1.2],
        1e-14,
    )
    # Nearest pusher point: the disk's left tip (-8, -1.5).
    assert_near_equal(
        sketch.get_val("rotor_pusher_clearance"),
        [np.hypot(4.5, 1.5) - 1.0, np.hypot(4.5, 4.5) - 1.2],
        1e-14,
    )


def test_overlaps_are_negative(sketch):
    # Rotor 0 over the tail's side edge (y = -2, hub 0.5 m outboard of it); rotor 1's hub inside
    # the tail, 0.4 m from its nearest edge (the trailing edge x = -6).
    sketch.set_val("lift_hub_position", [[-5.5, -2.5, -1.0], [-5.6, -1.0, -0.5]])
    sketch.run_model()
    assert_near_equal(sketch.get_val("rotor_tail_clearance"), [0.5 - 1.0, -0.4 - 1.2], 1e-14)
    # Rotor 1 against the pusher segment: 2.4 m ahead of it, within its span.
    assert_near_equal(sketch.get_val("rotor_pusher_clearance")[1], 2.4 - 1.2, 1e-14)
    data = sketch.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_partials_of_a_swept_tapered_tail(sketch):
    sketch.set_val("htail_sweep", np.radians(12.0))
    sketch.set_val("htail_tip_chord", 0.6)
    sketch.set_val("lift_hub_position", [[-4.2, -1.9, -1.0], [-4.0, -3.5, -0.5]])
    sketch.run_model()
    assert np.all(np.isfinite(sketch.get_val("rotor_tail_clearance")))
    data = sketch.check_partials(method="cs", compact_print=True, out_stream=None)
    assert_check_partials(data, atol=1e-10, rtol=1e-10)


def test_hub_on_the_pusher_disk_is_an_analysis_error(sketch):
    sketch.set_val("lift_hub_position", [[-8.0, -1.0, -1.0], [-3.5, -6.0, -0.5]])
    with pytest.raises(om.AnalysisError, match="lies on the pusher disk"):
        sketch.run_model()


def test_bad_options():
    with pytest.raises(ValueError, match="option 'side'"):
        _problem([0.0, 1.0], fuselage_max_width=1.0)
    with pytest.raises(ValueError, match="option 'rotor_pairs'"):
        _problem([1.0, -1.0], fuselage_max_width=1.0, rotor_pairs=[(0, 0)])


def test_reference_vehicle_as_drawn():
    """
    Check the NASA LPC CAD layout (lpc_reference.toml) as the vehicle group sees it.

    Hand numbers from the file's CAD points: rear inner/outer hubs (-4.96702, -2.60208) and
    (-5.10113, -5.715), R 1.524 each; front (-0.66020, -2.50454) and (-0.79431, -5.715); the
    fuselage 1.557 m wide; the h-tail leading-edge tip corner at x = -7.60903 - 1.99436
    tan(3.33 deg), y = 1.99436 (span sqrt(4.3 x 3.7)); the pusher (-9.19307, 0), R 1.37.
    """
    prob = om.Problem(reports=False)
    prob.model.add_subsystem("vehicle", VehicleGroup(), promotes=["*"])
    prob.setup()
    prob.run_model()
    r = 1.524
    left = constrained_rotors(VEHICLE)
    assert left == [0, 1, 2, 3]
    pairs = rotor_pairs(VEHICLE)
    clearance = dict(zip(pairs, prob.get_val("lift_rotor_clearance", units="m"), strict=True))
    rear = np.hypot(5.10113 - 4.96702, 5.715 - 2.60208) - 2 * r
    front = np.hypot(0.79431 - 0.66020, 5.715 - 2.50454) - 2 * r
    assert_near_equal(clearance[(1, 3)], rear, 1e-6)  # 0.0678 m
    assert_near_equal(clearance[(0, 2)], front, 1e-6)  # 0.1653 m
    fuselage = prob.get_val("rotor_fuselage_clearance", units="m")
    assert_near_equal(fuselage[2], 2.50454 - r - 1.557 / 2, 1e-6)  # 0.202 m
    half = 0.5 * np.sqrt(4.3 * 3.7)
    tip = np.array([-7.60903 - half * np.tan(np.radians(3.33)), half])
    tail = prob.get_val("rotor_tail_clearance", units="m")
    assert_near_equal(tail[3], np.hypot(*(tip - [-4.96702, 2.60208])) - r, 1e-5)  # 1.300 m
    pusher = prob.get_val("rotor_pusher_clearance", units="m")
    assert_near_equal(pusher[3], np.hypot(9.19307 - 4.96702, 2.60208 - 1.37) - r, 1e-6)
    # The right side mirrors the left.
    for name in ("rotor_fuselage_clearance", "rotor_tail_clearance", "rotor_pusher_clearance"):
        values = prob.get_val(name)
        assert_near_equal(values[[6, 7, 4, 5]], values[[0, 1, 2, 3]], 1e-12)


def test_constraints_of_a_symmetric_and_an_asymmetric_layout():
    cons = {c.output: c.options for c in clearance_constraints(VEHICLE)}
    assert cons["rotor_tail_clearance"]["indices"] == [0, 1, 2, 3]
    assert cons["rotor_tail_clearance"]["lower"] == VEHICLE.constraints.min_rotor_tail_clearance
    assert "indices" not in cons["lift_rotor_clearance"]
    assert len(rotor_pairs(VEHICLE)) == 6
    # Move one right rotor: the layout is no longer mirror-symmetric, every rotor and pair counts.
    rotors = list(VEHICLE.lift_rotors)
    hub = list(rotors[7].hub_position)
    rotors[7] = dataclasses.replace(rotors[7], hub_position=(hub[0] - 0.1, hub[1], hub[2]))
    skewed = dataclasses.replace(VEHICLE, lift_rotors=tuple(rotors))
    assert is_mirror_symmetric(VEHICLE) and not is_mirror_symmetric(skewed)
    assert constrained_rotors(skewed) == list(range(8))
    assert len(rotor_pairs(skewed)) == 28
