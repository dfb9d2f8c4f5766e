"""Lift-rotor hubs on booms that follow the wing, the pusher at the tail, rotor clearance."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


class RotorLayoutComp(om.ExplicitComponent):
    """
    Rotor hub positions and radii, and the radius intersection constraint.

    Hub positions and radii follow the planform design variables, as does the radius
    intersection constraint (docs theory/geometry 'Rotor layout and radius intersection').

    Each boom is attached to the wing at a fixed fraction of the semispan, eta_i = abs(y_i) / (b/2)
    of the reference vehicle. When the span changes, the junction slides along the wing's
    leading-edge direction (LE sweep Lambda, dihedral Gamma, z down):

        attach_i(b) = attach_i,ref + (eta_i b/2 - abs(y_i,ref)) (tan Lambda, sign y_i, -tan Gamma)

    and the hub keeps its offset from the junction (front rotors ahead of and below the wing,
    rear rotors behind and above it). The pusher hub keeps its offset from the fuselage tail:
    x = -l_fus + (x_ref + l_fus,ref).

    Radius intersection of each row's side-by-side neighbours (option ``side_by_side``, from
    :func:`lpc_mdo.vehicle.clearances.side_by_side_pairs`; the reference: front and rear, paper
    Table 6, 2 equality constraints, target 0.20; none for one rotor per side in each row):

    - ``span_fraction`` (default, the public code's form, which the paper's Table 8 satisfies):
      (R_inner + R_outer) / b
    - ``clearance`` (literal reading, m): abs(y_outer - y_inner) - (R_inner + R_outer)

    Inputs
    ------
    wing_span : scalar, m
    fuselage_length : scalar, m
    rotor_radius : (num_pairs + 1,), m
        Radius per rotor group: the lift pairs of ``vehicle.lift_rotor_pairs`` (reference
        vehicle: 0..3 = front outer, rear outer, front inner, rear inner), then the pusher.

    Outputs
    -------
    lift_hub_position : (num_lift, 3), m
        Hub positions of the lift rotors, body frame.
    pusher_hub_position : (3,), m
    lift_rotor_radius : (num_lift,), m
        Radius of each lift rotor (its pair's).
    radius_intersection : (num_neighbours,), - or m
        Each row's neighbours' value of the chosen definition, front row first (absent when
        there are none).

    Options
    -------
    vehicle : lpc_mdo.vehicle.Vehicle
        Reference layout (hub positions, boom junctions, wing sweep and dihedral, pairs).
    definition : str
        'span_fraction' or 'clearance'; default: the vehicle's constraint definition.
    side_by_side : sequence of (int, int)
        (inner pair, outer pair) of each row's neighbouring lift rotors, front row first.
    """

    def initialize(self):
        self.options.declare("vehicle", desc="lpc_mdo.vehicle.Vehicle with the reference layout")
        self.options.declare(
            "definition",
            default=None,
            allow_none=True,
            values=("span_fraction", "clearance", None),
            desc="radius-intersection definition; None: the vehicle's",
        )
        self.options.declare(
            "side_by_side",
            default=((2, 0), (3, 1)),
            desc="(inner pair, outer pair) of each row's neighbours, front row first",
        )

    def setup(self):
        vehicle = self.options["vehicle"]
        rotors = vehicle.lift_rotors
        wing = vehicle.wing
        definition = (
            self.options["definition"] or vehicle.constraints.radius_intersection_definition
        )
        self._definition = definition

        hubs = np.array([r.hub_position for r in rotors])
        attach = np.array(vehicle.booms.attach_points)
        self._sign = np.sign(attach[:, 1])
        half_span_ref = 0.5 * wing.span
        self._eta = np.abs(attach[:, 1]) / half_span_ref
        num_lift = len(rotors)
        num_pairs = len(vehicle.lift_rotor_pairs)
        self._direction = np.stack(
            [
                np.full(num_lift, np.tan(wing.sweep)),
                self._sign,
                np.full(num_lift, -np.tan(wing.dihedral)),
            ],
            axis=1,
        )
        # Position at span b: hub_ref + (eta b/2 - |y_ref|) * direction = base + b * slope.
        self._base = hubs - (np.abs(attach[:, 1]))[:, None] * self._direction
        self._slope = 0.5 * self._eta[:, None] * self._direction
        self._pusher_offset = np.array(vehicle.pusher.hub_position) + np.array(
            [vehicle.fuselage.length, 0.0, 0.0]
        )
        self._pair = np.array([r.pair for r in rotors])
        # Side-by-side neighbours of each row (reference: front (2 inner, 0 outer), rear (3, 1)).
        neighbours = np.array(self.options["side_by_side"], dtype=int).reshape(-1, 2)
        self._inner, self._outer = neighbours[:, 0], neighbours[:, 1]
        num_intersections = len(neighbours)
        left = self._sign < 0
        self._rotor_of_pair = np.array(
            [np.flatnonzero(left & (self._pair == p))[0] for p in range(num_pairs)]
        )

        self.add_input("wing_span", wing.span, units="m", desc="wing span")
        self.add_input(
            "fuselage_length", vehicle.fuselage.length, units="m", desc="fuselage length"
        )
        radius = [rotors[i].radius for i in self._rotor_of_pair] + [vehicle.pusher.radius]
        self.add_input(
            "rotor_radius",
            np.array(radius),
            units="m",
            desc="radius per rotor group (the lift pairs, then the pusher)",
        )
        # Lateral gap between the inner and outer left rotors, front and rear: on the left side
        # y_inner > y_outer, so |y_outer - y_inner| = gap_base + b * gap_slope.
        inner = self._rotor_of_pair[self._inner]
        outer = self._rotor_of_pair[self._outer]
        self._gap_base = self._base[inner, 1] - self._base[outer, 1]
        self._gap_slope = self._slope[inner, 1] - self._slope[outer, 1]

        self.add_output("lift_hub_position", hubs, units="m", desc="lift-rotor hubs, body frame")
        self.add_output(
            "pusher_hub_position",
            np.array(vehicle.pusher.hub_position),
            units="m",
            desc="pusher hub, body frame",
        )
        self.add_output(
            "lift_rotor_radius", np.full(num_lift, 1.0), units="m", desc="radius of each lift rotor"
        )
        if num_intersections:  # none when no two rotors of a row stand side by side
            self.add_output(
                "radius_intersection",
                np.zeros(num_intersections),
                units="m" if definition == "clearance" else None,
                desc=f"radius intersection of each row's neighbours, front first ({definition})",
            )

        self.declare_partials("lift_hub_position", "wing_span", val=self._slope.ravel())
        self.declare_partials(
            "pusher_hub_position", "fuselage_length", rows=[0], cols=[0], val=-1.0
        )
        self.declare_partials(
            "lift_rotor_radius", "rotor_radius", rows=np.arange(num_lift), cols=self._pair, val=1.0
        )
        rows = np.repeat(np.arange(num_intersections), 2)
        cols = np.column_stack([self._inner, self._outer]).ravel()
        if not num_intersections:
            pass
        elif definition == "span_fraction":
            self.declare_partials("radius_intersection", "rotor_radius", rows=rows, cols=cols)
            self.declare_partials("radius_intersection", "wing_span")
        else:
            self.declare_partials(
                "radius_intersection", "rotor_radius", rows=rows, cols=cols, val=-1.0
            )
            self.declare_partials("radius_intersection", "wing_span", val=self._gap_slope)

    def compute(self, inputs, outputs):
        span = inputs["wing_span"][0]
        check_range(
            "wing_span",
            span,
            lower=0.0,
            lower_open=True,
            units="m",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        radius = inputs["rotor_radius"]
        outputs["lift_hub_position"] = self._base + span * self._slope
        outputs["pusher_hub_position"] = self._pusher_offset - np.array(
            [inputs["fuselage_length"][0], 0.0, 0.0]
        )
        outputs["lift_rotor_radius"] = radius[self._pair]
        if not self._inner.size:
            return
        pair_sum = radius[self._inner] + radius[self._outer]
        if self._definition == "span_fraction":
            outputs["radius_intersection"] = pair_sum / span
        else:
            outputs["radius_intersection"] = self._gap_base + self._gap_slope * span - pair_sum

    def compute_partials(self, inputs, partials):
        span = inputs["wing_span"][0]
        radius = inputs["rotor_radius"]
        if not self._inner.size:
            return
        if self._definition == "span_fraction":
            partials["radius_intersection", "rotor_radius"] = np.full(
                self._inner.size + self._outer.size, 1.0 / span
            )
            pair_sum = radius[self._inner] + radius[self._outer]
            partials["radius_intersection", "wing_span"] = -pair_sum / span**2
