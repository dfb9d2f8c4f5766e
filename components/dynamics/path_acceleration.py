"""Body-axis acceleration expressed in flight-path axes (the transition's trim rows)."""

import numpy as np
import openmdao.api as om


class PathAccelerationComp(om.ExplicitComponent):
    """
    Rotate the body-axis linear acceleration into flight-path axes.

    A quasi-steady transition point prescribes the acceleration along its flight path, dV/dt
    (docs theory/dynamics 'Design conditions'). In body axes that target is
    dV/dt (cos(theta - gamma), 0, sin(theta - gamma)) and depends on the pitch theta; in
    flight-path axes (x along the velocity, y right, z normal to the path, downward; the body
    axes turned by -(theta - gamma) about y, no roll) it is (dV/dt, 0, 0) for every pitch, so
    the pitch can be a trim variable. With d = theta - gamma (Etkin, *Dynamics of Atmospheric
    Flight*, the body-to-wind rotation at zero sideslip):

        a_path = (u_dot cos d + w_dot sin d,  v_dot,  -u_dot sin d + w_dot cos d)

    Inputs
    ------
    body_acceleration : (num_nodes, 3), m/s**2
        (u_dot, v_dot, w_dot) of the equations of motion.
    pitch : (num_nodes,), rad
        Pitch angle theta.
    flight_path_angle : (num_nodes,), rad
        Flight-path angle gamma (climb positive).

    Outputs
    -------
    path_acceleration : (num_nodes, 3), m/s**2
        Along-path, lateral and path-normal (downward) acceleration.

    Options
    -------
    num_nodes : int
        Number of flight conditions.
    """

    def initialize(self):
        self.options.declare("num_nodes", default=1, types=int, lower=1, desc="flight conditions")

    def setup(self):
        nn = self.options["num_nodes"]
        self.add_input(
            "body_acceleration", np.zeros((nn, 3)), units="m/s**2", desc="(u_dot, v_dot, w_dot)"
        )
        self.add_input("pitch", np.zeros(nn), units="rad", desc="pitch angle theta")
        self.add_input("flight_path_angle", np.zeros(nn), units="rad", desc="flight-path angle")
        self.add_output(
            "path_acceleration",
            np.zeros((nn, 3)),
            units="m/s**2",
            desc="along-path, lateral, path-normal (down) acceleration",
        )
        node = np.arange(nn)
        # Rows x and z of each node depend on u_dot and w_dot of that node; y is v_dot.
        rows = np.concatenate([3 * node, 3 * node, 3 * node + 2, 3 * node + 2])
        cols = np.concatenate([3 * node, 3 * node + 2, 3 * node, 3 * node + 2])
        self.declare_partials(
            "path_acceleration",
            "body_acceleration",
            rows=np.concatenate([rows, 3 * node + 1]),
            cols=np.concatenate([cols, 3 * node + 1]),
        )
        xz_rows = np.concatenate([3 * node, 3 * node + 2])
        xz_cols = np.concatenate([node, node])
        self.declare_partials("path_acceleration", "pitch", rows=xz_rows, cols=xz_cols)
        self.declare_partials("path_acceleration", "flight_path_angle", rows=xz_rows, cols=xz_cols)

    def compute(self, inputs, outputs):
        a = inputs["body_acceleration"]
        d = inputs["pitch"] - inputs["flight_path_angle"]
        c, s = np.cos(d), np.sin(d)
        outputs["path_acceleration"][:, 0] = a[:, 0] * c + a[:, 2] * s
        outputs["path_acceleration"][:, 1] = a[:, 1]
        outputs["path_acceleration"][:, 2] = -a[:, 0] * s + a[:, 2] * c

    def compute_partials(self, inputs, partials):
        a = inputs["body_acceleration"]
        d = inputs["pitch"] - inputs["flight_path_angle"]
        c, s = np.cos(d), np.sin(d)
        # Order of the body_acceleration pattern: (x,u), (x,w), (z,u), (z,w), then (y,v).
        partials["path_acceleration", "body_acceleration"] = np.concatenate(
            [c, s, -s, c, np.ones_like(c)]
        )
        d_x = -a[:, 0] * s + a[:, 2] * c
        d_z = -a[:, 0] * c - a[:, 2] * s
        partials["path_acceleration", "pitch"] = np.concatenate([d_x, d_z])
        partials["path_acceleration", "flight_path_angle"] = -np.concatenate([d_x, d_z])
