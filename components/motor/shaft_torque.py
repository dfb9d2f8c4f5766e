"""Torque a motor must deliver to its rotor, without regeneration."""

import numpy as np
import openmdao.api as om


class ShaftTorqueComp(om.ExplicitComponent):
    """
    Motor load torque from the rotor torque, floored smoothly at an idle torque.

    A rotor that windmills (negative shaft torque, e.g. the pusher in descent at low speed)
    would drive its motor as a generator, which the motor model (paper eqs. 24-26, motoring
    only) and the paper's energy accounting do not cover. The motor then idles instead:

        tau_m = f + ((tau - f) + sqrt((tau - f)**2 + w**2)) / 2

    which equals tau when tau >> f (error w**2 / (4 (tau - f)): 0.01 N*m at 100 N*m with the
    defaults) and tends to the idle torque f when tau << f, smoothly, so the optimizer is
    never handed a point where the motor model fails.

    Inputs
    ------
    rotor_torque : (num_motors, num_nodes), N*m

    Outputs
    -------
    motor_load_torque : (num_motors, num_nodes), N*m

    Options
    -------
    num_motors, num_nodes : int
    idle_torque : float
        f, N*m (> 0). Default 1.
    width : float
        w, N*m (> 0). Default 2.
    """

    def initialize(self):
        self.options.declare("num_motors", types=int, lower=1, desc="number of motors")
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of operating points"
        )
        self.options.declare(
            "idle_torque",
            default=1.0,
            types=float,
            lower=1e-9,
            desc="torque of an idling motor, N*m",
        )
        self.options.declare(
            "width", default=2.0, types=float, lower=1e-9, desc="width of the smooth floor, N*m"
        )

    def setup(self):
        shape = (self.options["num_motors"], self.options["num_nodes"])
        self.add_input(
            "rotor_torque", np.ones(shape), units="N*m", desc="shaft torque the rotor demands"
        )
        self.add_output(
            "motor_load_torque",
            np.ones(shape),
            units="N*m",
            desc="torque the motor delivers (idle when the rotor windmills)",
        )
        self.declare_partials("motor_load_torque", "rotor_torque", diagonal=True)

    def compute(self, inputs, outputs):
        f, w = self.options["idle_torque"], self.options["width"]
        d = inputs["rotor_torque"] - f
        outputs["motor_load_torque"] = f + 0.5 * (d + np.sqrt(d * d + w * w))

    def compute_partials(self, inputs, partials):
        f, w = self.options["idle_torque"], self.options["width"]
        d = inputs["rotor_torque"] - f
        partials["motor_load_torque", "rotor_torque"] = (
            0.5 * (1.0 + d / np.sqrt(d * d + w * w))
        ).ravel()
