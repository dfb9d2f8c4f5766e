"""Rotor speeds per rotor from the speed design variables of rotor groups."""

import numpy as np
import openmdao.api as om


class RotorSpeedComp(om.ExplicitComponent):
    """
    rpm of each rotor from the speed of its group (e.g. the mirror-symmetric lift-rotor pairs
    of the LPC share one speed design variable, paper Table 6), and optionally from a speed
    differential between the two sides of each group:

        rpm[i, k] = group_speed[k, group[i]] + side[i] / 2 * group_differential[k, group[i]]

    With ``side`` = +1 for the left (y < 0) and -1 for the right rotor of each pair,
    ``group_differential`` is the left minus the right rotor's speed and ``group_speed`` their
    mean: the roll (and yaw) control of the transition points, where the pusher's torque
    reaction rolls the vehicle.

    Inputs
    ------
    group_speed : (num_nodes, num_groups), rpm
    group_differential : (num_nodes, num_groups), rpm
        Only with ``side``.

    Outputs
    -------
    rpm : (num_rotors, num_nodes), rpm

    Options
    -------
    group : sequence of int
        Group index of each rotor; its length is num_rotors.
    num_groups : int
    num_nodes : int
    side : sequence of float or None
        +1, -1 (or 0) per rotor: the share (side / 2) of its group's differential it takes.
        None: no differential input.
    """

    def initialize(self):
        self.options.declare("group", types=(list, tuple, np.ndarray),
                             desc="speed-group index of each rotor")
        self.options.declare("num_groups", types=int, lower=1, desc="number of speed groups")
        self.options.declare("num_nodes", default=1, types=int, lower=1,
                             desc="number of operating points")
        self.options.declare("side", default=None, types=(list, tuple, np.ndarray),
                             allow_none=True,
                             desc="+1 / -1 / 0 per rotor: its share (side/2) of the group's "
                                  "speed differential (None: no differential)")

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
        rows = (rotor * nn + node).ravel()
        cols = (node * ng + group[rotor]).ravel()
        self.declare_partials("rpm", "group_speed", rows=rows, cols=cols, val=1.0)

        side = self.options["side"]
        self._half_side = None
        if side is not None:
            side = np.asarray(side, dtype=float)
            if side.shape != (nr,) or not np.all(np.isin(side, (-1.0, 0.0, 1.0))):
                raise ValueError(f"{self.msginfo}: side = {side.tolist()}; allowed: one of "
                                 f"+1, -1, 0 per rotor ({nr} rotors).")
            self._half_side = 0.5 * side
            self.add_input("group_differential", np.zeros((nn, ng)), units="rpm",
                           desc="speed of the +1 side minus the -1 side of each group")
            self.declare_partials("rpm", "group_differential", rows=rows, cols=cols,
                                  val=self._half_side[rotor].ravel())

    def compute(self, inputs, outputs):
        rpm = inputs["group_speed"][:, self._group].T
        if self._half_side is not None:
            rpm = rpm + self._half_side[:, None] * inputs["group_differential"][:, self._group].T
        outputs["rpm"] = rpm
