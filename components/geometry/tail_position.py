"""Tail positions that follow the fuselage length."""

import numpy as np
import openmdao.api as om


class TailPositionComp(om.ExplicitComponent):
    """
    Root leading edges of the horizontal and vertical tail, carried by the tail cone.

    The tails sit at the end of the fuselage, so a change of fuselage length moves them aft by
    the same amount (body x forward): x_le = x_le,ref - (l_fus - l_fus,ref). The nose, the wing
    and the cabin stay where they are; this is how a longer fuselage adds tail arm (paper Sec.
    V.B: the static-margin constraint lengthens the fuselage).

    Inputs
    ------
    fuselage_length : scalar, m

    Outputs
    -------
    htail_root_leading_edge, vtail_root_leading_edge : (3,), m

    Options
    -------
    vehicle : lpc_mdo.vehicle.Vehicle
        Reference tail positions and fuselage length.
    """

    def initialize(self):
        self.options.declare("vehicle", desc="lpc_mdo.vehicle.Vehicle with the reference tails")

    def setup(self):
        vehicle = self.options["vehicle"]
        self._length_ref = vehicle.fuselage.length
        self._refs = {
            "htail": np.array(vehicle.horizontal_tail.root_leading_edge),
            "vtail": np.array(vehicle.vertical_tail.root_leading_edge),
        }
        self.add_input("fuselage_length", self._length_ref, units="m", desc="fuselage length")
        for name, ref in self._refs.items():
            self.add_output(
                f"{name}_root_leading_edge",
                ref,
                units="m",
                desc=f"{name} root leading edge, body frame",
            )
            self.declare_partials(
                f"{name}_root_leading_edge", "fuselage_length", rows=[0], cols=[0], val=-1.0
            )

    def compute(self, inputs, outputs):
        shift = inputs["fuselage_length"][0] - self._length_ref
        for name, ref in self._refs.items():
            outputs[f"{name}_root_leading_edge"] = ref - np.array([shift, 0.0, 0.0])
