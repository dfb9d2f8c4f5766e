"""Which plan-view rotor clearances a vehicle constrains, as data (docs theory/geometry).

The vehicle group computes the clearances of
:class:`~lpc_mdo.components.geometry.rotor_clearance.RotorClearanceComp`; the problem declares
the constraints :func:`clearance_constraints` lists (constraint kind ``clearance``). For a
mirror-symmetric layout (each lift-rotor pair the mirror image of itself about y = 0, as the
model moves them: same boom junction fraction, mirrored hubs) only the rotors on the left side
are constrained: the right side's clearances are equal, and equal constraints would be
linearly dependent rows. Of the rotor-rotor gaps only those of rotors on the same side are
needed then: a rotor on the other side is never nearer than the mirror image of it on this
side (reflecting it across y = 0 cannot increase its distance to a rotor with y < 0), and a
rotor and its own mirror image are 2 (abs(y) - R) apart, more than the fuselage clearance
allows. An asymmetric layout constrains every rotor and every pair.
"""

import dataclasses

import numpy as np

#: Vehicle-level clearance outputs (m) and the vehicle file's limit of each.
CLEARANCE_LIMITS = {
    "lift_rotor_clearance": "min_lift_rotor_clearance",
    "rotor_fuselage_clearance": "min_rotor_fuselage_clearance",
    "rotor_tail_clearance": "min_rotor_tail_clearance",
    "rotor_pusher_clearance": "min_rotor_pusher_clearance",
}
#: Scaling reference of the clearance constraints, m.
CLEARANCE_REF = 0.1
_MIRROR_TOLERANCE = 1e-9  # m


@dataclasses.dataclass(frozen=True)
class VehicleConstraint:
    """A vehicle-level constraint: constraint kind, output and ``add_constraint`` options."""

    kind: str
    output: str
    options: dict


def rotor_sides(vehicle):
    """Return +1 for each lift rotor on the right (y > 0) and -1 on the left."""
    return [1.0 if r.hub_position[1] > 0.0 else -1.0 for r in vehicle.lift_rotors]


def is_mirror_symmetric(vehicle):
    """Whether each lift-rotor pair is the mirror image of itself about y = 0 (hubs and booms)."""
    hubs = np.array([r.hub_position for r in vehicle.lift_rotors])
    attach = np.array(vehicle.booms.attach_points)
    mirror = np.array([1.0, -1.0, 1.0])
    for pair in vehicle.lift_rotor_pairs:
        if len(pair) != 2:
            return False
        i, j = pair
        for points in (hubs, attach):
            if np.any(np.abs(points[i] - mirror * points[j]) > _MIRROR_TOLERANCE):
                return False
        if vehicle.lift_rotors[i].hub_position[1] == 0.0:
            return False
    return True


def side_by_side_pairs(vehicle):
    """
    Return the neighbouring lift-rotor pairs of each row, (inner pair, outer pair), front first.

    The left rotors (y < 0) form rows: rotors whose hubs lie less than the smaller radius apart
    in x share a row (the reference: the front row x = -0.66 and -0.79 m, the rear -4.97 and
    -5.10 m). Within a row, sorted by abs(y), each rotor and the next one outboard are one entry:
    the pairs the radius intersection (paper Table 6) ties together. The reference gives
    ((2, 0), (3, 1)); a layout of one rotor per side in each row gives none.
    """
    left = [
        (r.hub_position[0], abs(r.hub_position[1]), r.radius, r.pair)
        for r in vehicle.lift_rotors
        if r.hub_position[1] < 0.0
    ]
    left.sort(key=lambda item: -item[0])  # front (largest x) first
    rows = []
    for item in left:
        row = rows[-1] if rows else None
        if row is not None and row[-1][0] - item[0] < min(row[-1][2], item[2]):
            row.append(item)
        else:
            rows.append([item])
    out = []
    for row in rows:
        row.sort(key=lambda item: item[1])
        out.extend((a[3], b[3]) for a, b in zip(row, row[1:], strict=False))
    return tuple(out)


def constrained_rotors(vehicle):
    """Return the indices into ``lift_rotors`` whose clearances are constrained."""
    n = len(vehicle.lift_rotors)
    if not is_mirror_symmetric(vehicle):
        return list(range(n))
    return [i for i, side in enumerate(rotor_sides(vehicle)) if side < 0.0]


def rotor_pairs(vehicle):
    """Return the lift-rotor index pairs of ``lift_rotor_clearance`` (module docstring)."""
    rotors = constrained_rotors(vehicle)
    return [(a, b) for k, a in enumerate(rotors) for b in rotors[k + 1 :]]


def clearance_constraints(vehicle):
    """
    Return the vehicle-level clearance constraints of a vehicle.

    Returns
    -------
    list of VehicleConstraint
        Kind ``clearance``: each clearance output of :data:`CLEARANCE_LIMITS` >= its limit of
        the vehicle file's ``[constraints]``, on the rotors of :func:`constrained_rotors` (all
        pairs of ``lift_rotor_clearance``).
    """
    limits = vehicle.constraints
    rotors = constrained_rotors(vehicle)
    out = []
    for output, key in CLEARANCE_LIMITS.items():
        options = {"lower": getattr(limits, key), "ref": CLEARANCE_REF, "units": "m"}
        if output != "lift_rotor_clearance":
            options.update(indices=rotors, flat_indices=True)
        out.append(VehicleConstraint("clearance", output, options))
    return out
