"""Battery-side electrical power of a condition from its motors."""

import numpy as np
import openmdao.api as om


class TotalPowerComp(om.ExplicitComponent):
    """
    P_elec = sum over motors of the motor input power (paper Sec. III.G: the power of each
    mission segment; reference/models_structures_motor_vehicle.md §8.10 default).

    Inputs
    ------
    motor_input_power : (num_motors, num_nodes), W

    Outputs
    -------
    electrical_power : (num_nodes,), W

    Options
    -------
    num_motors, num_nodes : int
    """

    def initialize(self):
        self.options.declare("num_motors", types=int, lower=1, desc="number of motors")
        self.options.declare("num_nodes", default=1, types=int, lower=1,
                             desc="number of operating points")

    def setup(self):
        nm, nn = self.options["num_motors"], self.options["num_nodes"]
        self.add_input("motor_input_power", np.zeros((nm, nn)), units="W",
                       desc="electrical input power of each motor")
        self.add_output("electrical_power", np.zeros(nn), units="W", ref=1e5,
                        desc="total electrical power drawn from the battery")
        rows = np.tile(np.arange(nn), nm)
        self.declare_partials("electrical_power", "motor_input_power", rows=rows,
                              cols=np.arange(nm * nn), val=1.0)

    def compute(self, inputs, outputs):
        outputs["electrical_power"] = inputs["motor_input_power"].sum(axis=0)
