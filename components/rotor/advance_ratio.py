"""Edgewise advance ratio of a rotor: in-plane air speed over tip speed, V_inplane / (Omega R)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range
from lpc_mdo.core.constants import RPM_TO_RAD_S


class EdgewiseAdvanceRatioComp(om.ExplicitComponent):
    """
    Edgewise advance ratio mu = sqrt(v_x^2 + v_y^2) / (Omega R) of each rotor at each node.

    The in-plane velocity is that of the air relative to the disk (the rotor models' input
    ``inplane_velocity``). mu bounds where an inflow model holds: at mu above about 0.5 the
    reverse-flow region covers much of the retreating side and simple inflow models depart
    from test (docs theory/rotors 'Advance-ratio limit'; Harris, NASA CR-2008-215370).

    Inputs
    ------
    inplane_velocity : float, (num_rotors, num_nodes, 2), m/s
        Air velocity in the disk plane, along the disk axes e_x and e_y.
    rpm : float, (num_rotors, num_nodes), rpm
        Rotor speed (> 0).
    radius : float, (num_rotors,), m
        Tip radius (> 0).

    Outputs
    -------
    edgewise_advance_ratio : float, (num_rotors, num_nodes), -
        mu.

    Options
    -------
    num_rotors, num_nodes : int
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="rotors")
        self.options.declare("num_nodes", default=1, types=int, lower=1, desc="nodes")

    def setup(self):
        nr, nn = self.options["num_rotors"], self.options["num_nodes"]
        self.add_input("inplane_velocity", np.zeros((nr, nn, 2)), units="m/s")
        self.add_input("rpm", np.full((nr, nn), 1000.0), units="rpm")
        self.add_input("radius", np.ones(nr), units="m")
        self.add_output("edgewise_advance_ratio", np.zeros((nr, nn)), units=None)
        size = nr * nn
        point = np.arange(size)
        self.declare_partials(
            "edgewise_advance_ratio",
            "inplane_velocity",
            rows=np.repeat(point, 2),
            cols=np.arange(2 * size),
        )
        self.declare_partials("edgewise_advance_ratio", "rpm", rows=point, cols=point)
        self.declare_partials(
            "edgewise_advance_ratio", "radius", rows=point, cols=np.repeat(np.arange(nr), nn)
        )

    @staticmethod
    def _tip_speed(inputs):
        return inputs["rpm"] * RPM_TO_RAD_S * inputs["radius"][:, None]

    def compute(self, inputs, outputs):
        for name in ("rpm", "radius"):
            check_range(
                name,
                inputs[name],
                lower=0.0,
                lower_open=True,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        speed = np.sqrt(np.sum(inputs["inplane_velocity"] ** 2, axis=-1))
        outputs["edgewise_advance_ratio"] = speed / self._tip_speed(inputs)

    def compute_partials(self, inputs, partials):
        v = inputs["inplane_velocity"]
        tip = self._tip_speed(inputs)
        speed = np.sqrt(np.sum(v**2, axis=-1))
        mu = speed / tip
        # d|v|/dv = v/|v|; at |v| = 0 the subgradient 0 (hover: no in-plane flow).
        safe = np.where(speed > 0.0, speed, 1.0)
        unit = np.where((speed > 0.0)[..., None], v / safe[..., None], 0.0)
        partials["edgewise_advance_ratio", "inplane_velocity"] = (unit / tip[..., None]).ravel()
        partials["edgewise_advance_ratio", "rpm"] = (-mu / inputs["rpm"]).ravel()
        partials["edgewise_advance_ratio", "radius"] = (-mu / inputs["radius"][:, None]).ravel()
