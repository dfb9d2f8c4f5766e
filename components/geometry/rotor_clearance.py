"""Plan-view clearances of the lift-rotor disks to each other, fuselage, h-tail and pusher."""

import numpy as np
import openmdao.api as om

#: Names of the clearance outputs of :class:`RotorClearanceComp`, in m.
CLEARANCE_OUTPUTS = (
    "lift_rotor_clearance",
    "rotor_fuselage_clearance",
    "rotor_tail_clearance",
    "rotor_pusher_clearance",
)


def point_segment_distance(point, start, end):
    """
    Return the distance from points to segments in a plane, with the nearest-point parameter.

    Vectorized over any leading shape (broadcast): ``point``, ``start`` and ``end`` are
    (..., 2). The nearest point of the segment is Q = start + t (end - start) with t the
    projection clipped to [0, 1]; the distance is abs(point - Q). Its gradient is, with
    u = (point - Q)/d: u for the point, -(1 - t) u for ``start`` and -t u for ``end`` (the
    same formula whether t is clipped or not, as the distance is the minimum over t).

    Parameters
    ----------
    point, start, end : ndarray, (..., 2)

    Returns
    -------
    distance : ndarray, (...)
    t : ndarray, (...)
        Parameter of the nearest point, in [0, 1].
    unit : ndarray, (..., 2)
        (point - Q)/distance; NaN where the distance is 0.
    """
    edge = end - start
    length2 = np.sum(edge * edge, axis=-1)
    t = np.sum((point - start) * edge, axis=-1) / length2
    t = np.minimum(1.0, np.maximum(0.0, t))  # the nearest point of a segment, not a clip of data
    offset = point - (start + t[..., None] * edge)
    distance = np.sqrt(np.sum(offset * offset, axis=-1))
    with np.errstate(invalid="ignore", divide="ignore"):
        unit = offset / distance[..., None]
    return distance, t, unit


def trapezoid_half_planform(root_le_x, span, root_chord, tip_chord, sweep):
    """
    Return the plan-view corners of the right half of a mirrored trapezoidal surface.

    Corners (x, y) in order root leading edge, tip leading edge, tip trailing edge, root trailing
    edge (body frame x forward, y right: counter-clockwise in the x-y plane), with the leading
    edge at x = x0 - y tan(sweep) and the chords along -x, as
    :class:`~lpc_mdo.components.geometry.planform.PlanformMeshComp` builds the surface (``span``
    is the projected span; the section incidence is left out, so the chords are their full
    length in plan view, which is conservative for a clearance).

    Returns
    -------
    corners : ndarray, (4, 2)
    derivative : ndarray, (4, 2, 5)
        d corners / d (root_le_x, span, root_chord, tip_chord, sweep).
    """
    h = 0.5 * span
    tan = np.tan(sweep)
    tip_x = root_le_x - h * tan
    corners = np.array(
        [[root_le_x, 0.0], [tip_x, h], [tip_x - tip_chord, h], [root_le_x - root_chord, 0.0]]
    )
    d = np.zeros((4, 2, 5), dtype=np.result_type(root_le_x, span, root_chord, tip_chord, sweep))
    d[:, 0, 0] = 1.0  # every x moves with the root leading edge
    d[1:3, 0, 1] = -0.5 * tan
    d[1:3, 1, 1] = 0.5
    d[3, 0, 2] = -1.0
    d[2, 0, 3] = -1.0
    d[1:3, 0, 4] = -h / np.cos(sweep) ** 2
    return corners, d


class RotorClearanceComp(om.ExplicitComponent):
    """
    Plan-view clearances of the lift-rotor disks, for the clearance constraints.

    See docs theory/geometry 'Rotor clearances'. In plan view (the body x-y plane) a lift rotor
    is the disk of its radius about its hub; the clearance of two parts is the gap between them
    in that view, negative where they overlap. The plan view is conservative: the gap in space is
    never smaller than the gap of the projections.

    - ``lift_rotor_clearance`` (one per rotor pair of ``rotor_pairs``):
      abs(c_i - c_j) - R_i - R_j, edge to edge (c the hub in plan view);
    - ``rotor_fuselage_clearance``: s_i y_i - R_i - w/2, disk edge to the fuselage side, with the
      fuselage taken as a strip of its maximum width w along its whole length (the disks lie
      alongside the cabin, where the width is the largest) and s_i = +-1 the side of rotor i;
    - ``rotor_tail_clearance``: the signed distance from the hub to the horizontal tail's
      planform (a mirrored trapezoid; negative inside) minus R_i; >= 0 means that no part of
      the disk lies over the tail;
    - ``rotor_pusher_clearance``: distance from the hub to the pusher disk minus R_i; the
      pusher disk, normal to its thrust axis, is seen from above as the segment of length
      2 R_p through its hub perpendicular to the axis.

    Partials: analytic (the distance to a segment or to a convex polygon is continuously
    differentiable away from it, :func:`point_segment_distance`).

    Inputs
    ------
    lift_hub_position : (num_rotors, 3), m
    lift_rotor_radius : (num_rotors,), m
    pusher_hub_position : (3,), m
    rotor_radius : (num_groups,), m
        Radius per rotor group; row ``pusher_row`` is the pusher's.
    htail_root_leading_edge : (3,), m
        Root leading edge of the horizontal tail (only x enters; the tail is mirrored about y = 0).
    htail_span, htail_root_chord, htail_tip_chord : scalar, m
    htail_sweep : scalar, rad
        Leading-edge sweep of the horizontal tail.

    Outputs
    -------
    lift_rotor_clearance : (num_pairs,), m
    rotor_fuselage_clearance, rotor_tail_clearance, rotor_pusher_clearance : (num_rotors,), m

    Options
    -------
    side : sequence of float
        +1 for a rotor on the right (y > 0), -1 on the left, per lift rotor.
    rotor_pairs : sequence of (int, int) or None
        Lift-rotor index pairs of ``lift_rotor_clearance``; None: every pair i < j.
    fuselage_max_width : float
        Fuselage maximum width, m.
    num_groups : int
        Rows of ``rotor_radius``.
    pusher_row : int
        Row of the pusher in ``rotor_radius``.
    pusher_axis : sequence of 3 float
        Pusher thrust axis, body frame (its plan-view part must not vanish).

    Raises
    ------
    om.AnalysisError
        When a lift-rotor hub lies on the pusher disk or the tail's outline in plan view (the
        clearance has no direction there) or a radius is not > 0.
    """

    def initialize(self):
        self.options.declare("side", desc="+1 right, -1 left, per lift rotor")
        self.options.declare(
            "rotor_pairs", default=None, allow_none=True, desc="lift-rotor index pairs"
        )
        self.options.declare("fuselage_max_width", types=float, lower=0.0, desc="m")
        self.options.declare("num_groups", types=int, lower=1, desc="rows of rotor_radius")
        self.options.declare("pusher_row", types=int, lower=0, desc="pusher row of rotor_radius")
        self.options.declare(
            "pusher_axis", default=(1.0, 0.0, 0.0), desc="pusher thrust axis, body frame"
        )

    def setup(self):
        side = np.asarray(self.options["side"], dtype=float)
        if side.ndim != 1 or not np.all(np.abs(side) == 1.0):
            raise ValueError(f"{self.msginfo}: option 'side' = {side.tolist()}; allowed: +-1 each")
        n = side.size
        self._side = side
        pairs = self.options["rotor_pairs"]
        if pairs is None:
            pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
        pairs = np.array(pairs, dtype=int).reshape(-1, 2)
        if pairs.size and (
            pairs.min() < 0 or pairs.max() >= n or np.any(pairs[:, 0] == pairs[:, 1])
        ):
            raise ValueError(
                f"{self.msginfo}: option 'rotor_pairs' = {pairs.tolist()}; allowed: pairs of two "
                f"different lift-rotor indices in [0, {n - 1}]"
            )
        self._pairs = pairs
        axis = np.asarray(self.options["pusher_axis"], dtype=float)
        plan = np.array([-axis[1], axis[0]])  # plan-view direction of the pusher disk
        if np.linalg.norm(plan) < 1e-9:
            raise ValueError(
                f"{self.msginfo}: option 'pusher_axis' = {axis.tolist()} has no plan-view part"
            )
        self._pusher_dir = plan / np.linalg.norm(plan)
        groups, row = self.options["num_groups"], self.options["pusher_row"]
        if row >= groups:
            raise ValueError(
                f"{self.msginfo}: option 'pusher_row' = {row}; allowed: [0, {groups - 1}]"
            )

        self.add_input("lift_hub_position", np.zeros((n, 3)), units="m", desc="lift-rotor hubs")
        self.add_input("lift_rotor_radius", np.ones(n), units="m", desc="lift-rotor radii")
        self.add_input("pusher_hub_position", np.zeros(3), units="m", desc="pusher hub")
        self.add_input("rotor_radius", np.ones(groups), units="m", desc="radius per rotor group")
        self.add_input("htail_root_leading_edge", np.zeros(3), units="m", desc="h-tail root LE")
        self.add_input("htail_span", 1.0, units="m", desc="h-tail projected span")
        self.add_input("htail_root_chord", 1.0, units="m", desc="h-tail root chord")
        self.add_input("htail_tip_chord", 1.0, units="m", desc="h-tail tip chord")
        self.add_input("htail_sweep", 0.0, units="rad", desc="h-tail leading-edge sweep")
        npairs = len(pairs)
        self.add_output(
            "lift_rotor_clearance", np.zeros(npairs), units="m", desc="disk edge to disk edge"
        )
        for name, desc in (
            ("rotor_fuselage_clearance", "disk edge to fuselage side"),
            ("rotor_tail_clearance", "disk edge to h-tail planform"),
            ("rotor_pusher_clearance", "disk edge to pusher disk"),
        ):
            self.add_output(name, np.zeros(n), units="m", desc=f"{desc}, plan view")

        rows = np.arange(n)
        hub_x, hub_y = 3 * rows, 3 * rows + 1
        prow = np.repeat(np.arange(npairs), 2)
        self.declare_partials(
            "lift_rotor_clearance",
            "lift_hub_position",
            rows=np.repeat(prow, 2),
            cols=(3 * np.repeat(pairs.ravel(), 2) + np.tile([0, 1], 2 * npairs)),
        )
        self.declare_partials(
            "lift_rotor_clearance", "lift_rotor_radius", rows=prow, cols=pairs.ravel(), val=-1.0
        )
        self.declare_partials(
            "rotor_fuselage_clearance", "lift_hub_position", rows=rows, cols=hub_y, val=side
        )
        for name in ("rotor_fuselage_clearance", "rotor_tail_clearance", "rotor_pusher_clearance"):
            self.declare_partials(name, "lift_rotor_radius", rows=rows, cols=rows, val=-1.0)
        for name in ("rotor_tail_clearance", "rotor_pusher_clearance"):
            self.declare_partials(
                name,
                "lift_hub_position",
                rows=np.repeat(rows, 2),
                cols=np.column_stack([hub_x, hub_y]).ravel(),
            )
        self.declare_partials(
            "rotor_tail_clearance", "htail_root_leading_edge", rows=rows, cols=np.zeros(n, int)
        )
        self.declare_partials(
            "rotor_tail_clearance",
            ["htail_span", "htail_root_chord", "htail_tip_chord", "htail_sweep"],
        )
        self.declare_partials(
            "rotor_pusher_clearance",
            "pusher_hub_position",
            rows=np.repeat(rows, 2),
            cols=np.tile([0, 1], n),
        )
        self.declare_partials(
            "rotor_pusher_clearance", "rotor_radius", rows=rows, cols=np.full(n, row)
        )

    # -------------------------------------------------------------------- geometry

    def _rotor_pairs(self, inputs):
        hub = inputs["lift_hub_position"][:, :2]
        i, j = self._pairs[:, 0], self._pairs[:, 1]
        delta = hub[i] - hub[j]
        distance = np.sqrt(np.sum(delta * delta, axis=-1))
        return delta, distance

    def _tail(self, inputs):
        """Signed distance of each (mirrored) hub to the tail half-planform and its gradients."""
        corners, dcorners = trapezoid_half_planform(
            inputs["htail_root_leading_edge"][0],
            inputs["htail_span"][0],
            inputs["htail_root_chord"][0],
            inputs["htail_tip_chord"][0],
            inputs["htail_sweep"][0],
        )
        hub = inputs["lift_hub_position"][:, :2] * np.column_stack(
            [np.ones_like(self._side), self._side]
        )
        start = corners[None, :, :]
        end = np.roll(corners, -1, axis=0)[None, :, :]
        distance, t, unit = point_segment_distance(hub[:, None, :], start, end)
        edge = end - start
        rel = hub[:, None, :] - start
        # Inside the counter-clockwise polygon: left of every edge.
        inside = np.all(edge[..., 0] * rel[..., 1] - edge[..., 1] * rel[..., 0] > 0.0, axis=1)
        nearest = np.argmin(distance, axis=1)
        rows = np.arange(hub.shape[0])
        d = distance[rows, nearest]
        sign = np.where(inside, -1.0, 1.0)
        return corners, dcorners, sign * d, sign, t[rows, nearest], unit[rows, nearest], nearest

    def _pusher(self, inputs):
        hub = inputs["lift_hub_position"][:, :2]
        centre = inputs["pusher_hub_position"][:2]
        radius = inputs["rotor_radius"][self.options["pusher_row"]]
        half = radius * self._pusher_dir
        distance, t, unit = point_segment_distance(hub, centre + half, centre - half)
        return distance, t, unit

    def _check(self, inputs, tail_distance, pusher_distance):
        for name in ("lift_rotor_radius", "rotor_radius"):
            if np.any(inputs[name] <= 0.0):
                raise om.AnalysisError(
                    f"{self.msginfo}: {name} = {inputs[name].tolist()} m; allowed: > 0"
                )
        for what, distance in (("pusher disk", pusher_distance), ("h-tail outline", tail_distance)):
            if np.any(np.abs(distance) <= 1e-12):
                bad = int(np.argmin(np.abs(distance)))
                raise om.AnalysisError(
                    f"{self.msginfo}: lift-rotor hub {bad} lies on the {what} in plan view; "
                    f"allowed: a hub off it (the clearance has no direction there)"
                )

    def compute(self, inputs, outputs):
        radius = inputs["lift_rotor_radius"]
        _, pair_distance = self._rotor_pairs(inputs)
        i, j = self._pairs[:, 0], self._pairs[:, 1]
        outputs["lift_rotor_clearance"] = pair_distance - radius[i] - radius[j]
        half_width = 0.5 * self.options["fuselage_max_width"]
        outputs["rotor_fuselage_clearance"] = (
            self._side * inputs["lift_hub_position"][:, 1] - radius - half_width
        )
        tail = self._tail(inputs)[2]
        pusher = self._pusher(inputs)[0]
        self._check(inputs, tail, pusher)
        outputs["rotor_tail_clearance"] = tail - radius
        outputs["rotor_pusher_clearance"] = pusher - radius

    def compute_partials(self, inputs, partials):
        delta, pair_distance = self._rotor_pairs(inputs)
        unit = delta / pair_distance[:, None]
        # rows (pair, i/j, x/y): +unit for rotor i, -unit for rotor j.
        partials["lift_rotor_clearance", "lift_hub_position"] = np.stack(
            [unit, -unit], axis=1
        ).ravel()

        _, dcorners, _, sign, t, u, nearest = self._tail(inputs)
        n = self._side.size
        # Gradient of the signed distance: +-u for the (mirrored) hub, -(1 - t) u and -t u for
        # the nearest edge's start and end corners.
        du = sign[:, None] * u
        partials["rotor_tail_clearance", "lift_hub_position"] = (
            du * np.column_stack([np.ones(n), self._side])
        ).ravel()
        start = dcorners[nearest]  # (n, 2, 5)
        end = dcorners[(nearest + 1) % 4]
        dparam = -np.einsum("nc,ncp->np", du, (1.0 - t)[:, None, None] * start) - np.einsum(
            "nc,ncp->np", du, t[:, None, None] * end
        )
        for k, name in enumerate(
            ("htail_root_leading_edge", "htail_span", "htail_root_chord", "htail_tip_chord")
        ):
            partials["rotor_tail_clearance", name] = dparam[:, k]
        partials["rotor_tail_clearance", "htail_sweep"] = dparam[:, 4]

        _, t, u = self._pusher(inputs)
        partials["rotor_pusher_clearance", "lift_hub_position"] = u.ravel()
        partials["rotor_pusher_clearance", "pusher_hub_position"] = -u.ravel()
        # Segment ends centre +- R_p e: d/dR_p = -(1 - t) u.e + t u.e.
        partials["rotor_pusher_clearance", "rotor_radius"] = (2.0 * t - 1.0) * (
            u @ self._pusher_dir
        )
