"""Rotor speeds per rotor from the speed design variables of rotor groups."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


class RotorSpeedComp(om.ExplicitComponent):
    """
    Speed (rpm) of each rotor from the speed of its group and optional mixer inputs.

    Rotors of a group share one speed (e.g. the mirror-symmetric lift-rotor pairs
    of the LPC share one speed design variable, paper Table 6); mixer inputs
    speed some rotors up and others down, as a multicopter's flight control does:

        rpm[i, k] = group_speed[k, group[i]] + sum_j mixing[i, j] * mixer_speed[k, j]

    The LPC transition points use two mixers: roll (mixing = +1/2 for the left rotors, y < 0,
    -1/2 for the right ones) and yaw (+1/2 for the rotors that spin +1, -1/2 for the others),
    so each mixer speed is the difference of the two sets' speeds and ``group_speed`` stays the
    pair's mean: the roll and yaw trim, since the pusher's torque reaction rolls the vehicle.

    Inputs
    ------
    group_speed : (num_nodes, num_groups), rpm
    mixer_speed : (num_nodes, num_mixers), rpm
        Only with ``mixing``.

    Outputs
    -------
    rpm : (num_rotors, num_nodes), rpm

    Options
    -------
    group : sequence of int
        Group index of each rotor; its length is num_rotors.
    num_groups : int
    num_nodes : int
    mixing : array (num_rotors, num_mixers) or None
        Share of each mixer speed each rotor takes; None: no mixer input.
    """

    def initialize(self):
        self.options.declare(
            "group", types=(list, tuple, np.ndarray), desc="speed-group index of each rotor"
        )
        self.options.declare("num_groups", types=int, lower=1, desc="number of speed groups")
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of operating points"
        )
        self.options.declare(
            "mixing",
            default=None,
            types=(list, tuple, np.ndarray),
            allow_none=True,
            desc="(num_rotors, num_mixers) share of each mixer speed per "
            "rotor (None: no mixer input)",
        )

    def setup(self):
        group = np.asarray(self.options["group"], dtype=int)
        ng, nn = self.options["num_groups"], self.options["num_nodes"]
        if group.ndim != 1 or group.size == 0:
            raise ValueError(
                f"{self.msginfo}: 'group' = {group.tolist()} is not allowed: must "
                "be a non-empty 1-D sequence of rotor-group indices"
            )
        check_range("group", group, lower=0, upper=ng - 1, where=self.msginfo)
        nr = group.size
        self._group = group
        self.add_input(
            "group_speed", np.full((nn, ng), 1000.0), units="rpm", desc="rotor speed of each group"
        )
        self.add_output(
            "rpm", np.full((nr, nn), 1000.0), units="rpm", desc="rotor speed of each rotor"
        )
        rotor, node = np.meshgrid(np.arange(nr), np.arange(nn), indexing="ij")
        self.declare_partials(
            "rpm",
            "group_speed",
            rows=(rotor * nn + node).ravel(),
            cols=(node * ng + group[rotor]).ravel(),
            val=1.0,
        )

        mixing = self.options["mixing"]
        self._mixing = None
        if mixing is not None:
            mixing = np.asarray(mixing, dtype=float)
            if mixing.ndim != 2 or mixing.shape[0] != nr or not np.all(np.isfinite(mixing)):
                raise ValueError(
                    f"{self.msginfo}: mixing has shape {mixing.shape}; allowed: "
                    f"finite values of shape ({nr}, num_mixers), one row per "
                    f"rotor."
                )
            self._mixing = mixing
            nm = mixing.shape[1]
            self.add_input(
                "mixer_speed", np.zeros((nn, nm)), units="rpm", desc="speed of each mixer input"
            )
            # d rpm[i, k] / d mixer_speed[k, j] = mixing[i, j]
            r, k, j = np.meshgrid(np.arange(nr), np.arange(nn), np.arange(nm), indexing="ij")
            self.declare_partials(
                "rpm",
                "mixer_speed",
                rows=(r * nn + k).ravel(),
                cols=(k * nm + j).ravel(),
                val=mixing[r, j].ravel(),
            )

    def compute(self, inputs, outputs):
        rpm = inputs["group_speed"][:, self._group].T
        if self._mixing is not None:
            rpm = rpm + self._mixing @ inputs["mixer_speed"].T
        outputs["rpm"] = rpm
