"""Vertical beam displacement in the direction of the load, for displacement constraints."""

import numpy as np
import openmdao.api as om


class VerticalDisplacementComp(om.ExplicitComponent):
    """
    Vertical displacement s w_i of every beam node, positive in the direction of the load.

    w_i is the body-z displacement (z down), signed with s so that the deflection
    under the load is positive (s = -1 at positive load factors, where the wing bends up).
    A KS of it gives the aggregated displacement constraint of the structural subproblem
    (paper Table 4; limit 0.5 m).

    Inputs
    ------
    displacements : (num_nodes, 3), m

    Outputs
    -------
    vertical_displacement : (1, num_nodes), m

    Options
    -------
    num_nodes : int
    sign : float
        +1 or -1.
    """

    def initialize(self):
        self.options.declare("num_nodes", types=int, lower=1, desc="beam nodes")
        self.options.declare("sign", default=1.0, values=(1.0, -1.0), desc="+1 or -1")

    def setup(self):
        n = self.options["num_nodes"]
        self.add_input(
            "displacements", np.zeros((n, 3)), units="m", desc="node displacements, body frame"
        )
        self.add_output(
            "vertical_displacement",
            np.zeros((1, n)),
            units="m",
            desc="signed vertical displacement of each node",
        )
        self.declare_partials(
            "vertical_displacement",
            "displacements",
            rows=np.arange(n),
            cols=3 * np.arange(n) + 2,
            val=self.options["sign"],
        )

    def compute(self, inputs, outputs):
        outputs["vertical_displacement"][0] = self.options["sign"] * inputs["displacements"][:, 2]
