"""Battery-side electrical power of a condition from its motors."""

import numpy as np
import openmdao.api as om


class TotalPowerComp(om.ExplicitComponent):
    """
    Electrical power of the vehicle: the sum of the motor input powers.

    P_elec = sum over all motors of the motor input power (paper Sec. III.G: the power of each
    mission segment; docs theory/energy default).

    Inputs
    ------
    {name}_motor_input_power : (num_motors of that set, num_nodes), W
        One input per motor set (e.g. ``lift`` and ``pusher``).

    Outputs
    -------
    electrical_power : (num_nodes,), W

    Options
    -------
    motors : dict
        Motor-set name -> number of motors.
    num_nodes : int
    """

    def initialize(self):
        self.options.declare("motors", types=dict, desc="motor-set name -> number of motors")
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of operating points"
        )

    def setup(self):
        nn = self.options["num_nodes"]
        motors = self.options["motors"]
        if not motors or any(not isinstance(n, int) or n < 1 for n in motors.values()):
            raise ValueError(
                f"{self.msginfo}: motors = {motors}; must map names to motor counts >= 1."
            )
        self.add_output(
            "electrical_power",
            np.zeros(nn),
            units="W",
            desc="total electrical power drawn from the battery",
        )
        for name, nm in motors.items():
            self.add_input(
                f"{name}_motor_input_power",
                np.zeros((nm, nn)),
                units="W",
                desc=f"electrical input power of each {name} motor",
            )
            self.declare_partials(
                "electrical_power",
                f"{name}_motor_input_power",
                rows=np.tile(np.arange(nn), nm),
                cols=np.arange(nm * nn),
                val=1.0,
            )

    def compute(self, inputs, outputs):
        outputs["electrical_power"] = sum(
            inputs[f"{name}_motor_input_power"].sum(axis=0) for name in self.options["motors"]
        )
