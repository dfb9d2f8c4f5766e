"""Rotor speeds per rotor from the speed design variables of rotor groups."""

import numpy as np
import openmdao.api as om


class RotorSpeedComp(om.ExplicitComponent):
    """
    rpm of each rotor from the speed of its group (e.g. the mirror-symmetric lift-rotor pairs
    of the LPC share one speed design variable, paper Table 6).

        rpm[i, k] = group_speed[k, group[i]]

    Inputs
    ------
    group_speed : (num_nodes, num_groups), rpm

    Outputs
    -------
    rpm : (num_rotors, num_nodes), rpm

    Options
    -------
    group : sequence of int
        Group index of each rotor; its length is num_rotors.
    num_groups : int
    num_nodes : int
    """

    def initialize(self):
        self.options.declare("group", types=(list, tuple, np.ndarray),
                             desc="speed-group index of each rotor")
        self.options.declare("num_groups", types=int, lower=1, desc="number of speed groups")
        self.options.declare("num_nodes", default=1, types=int, lower=1,
                             desc="number of operating points")

    def setup(self):
        group = np.asarray(self.options["group"], dtype=int)
        ng, nn = self.options["num_groups"], self.options["num_nodes"]
        if group.ndim != 1 or group.size == 0 or group.min() < 0 or group.max() >= ng:
            raise ValueError(f"{self.msginfo}: group = {group.tolist()}; each entry must be in "
                             f"0..{ng - 1}.")
        nr = group.size
        self._group = group
        self.add_input("group_speed", np.full((nn, ng), 1000.0), units="rpm",
                       desc="rotor speed of each group")
        self.add_output("rpm", np.full((nr, nn), 1000.0), units="rpm",
                        desc="rotor speed of each rotor")
        rotor, node = np.meshgrid(np.arange(nr), np.arange(nn), indexing="ij")
        self.declare_partials("rpm", "group_speed", rows=(rotor * nn + node).ravel(),
                              cols=(node * ng + group[rotor]).ravel(), val=1.0)

    def compute(self, inputs, outputs):
        outputs["rpm"] = inputs["group_speed"][:, self._group].T
