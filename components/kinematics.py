"""Flight-condition kinematics: body-axis velocity, Mach number, dynamic pressure, Reynolds."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND


class KinematicsComp(om.ExplicitComponent):
    """
    Body-frame kinematics of a quasi-steady flight condition, vectorized over conditions.

    Equations (docs theory/dynamics 'Condition kinematics', CADDEE condition kinematics; body frame
    x forward, z down):

    - angle of attack alpha = theta - gamma
    - u = V cos(alpha), w = V sin(alpha)        (body-axis velocity components)
    - M = V / a,  q = rho V**2 / 2,  Re' = rho V / mu   (Reynolds number per metre)

    Inputs
    ------
    speed : float, (num_nodes,), m/s
        Airspeed V (0 in hover).
    pitch : float, (num_nodes,), rad
        Pitch angle theta.
    flight_path_angle : float, (num_nodes,), rad
        Flight-path angle gamma (positive climbing).
    density : float, (num_nodes,), kg/m**3
        Air density.
    speed_of_sound : float, (num_nodes,), m/s
        Speed of sound.
    dynamic_viscosity : float, (num_nodes,), Pa*s
        Dynamic viscosity of air.

    Outputs
    -------
    angle_of_attack : float, (num_nodes,), rad
    u : float, (num_nodes,), m/s
        Body-axis x velocity.
    w : float, (num_nodes,), m/s
        Body-axis z velocity (positive down).
    velocity : float, (num_nodes, 3), m/s
        Body-axis velocity vector (u, 0, w).
    mach : float, (num_nodes,)
    dynamic_pressure : float, (num_nodes,), Pa
    reynolds_per_length : float, (num_nodes,), 1/m

    Options
    -------
    num_nodes : int
        Number of flight conditions (>= 1).
    """

    def initialize(self):
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="Number of flight conditions."
        )

    def setup(self):
        nn = self.options["num_nodes"]
        self.add_input("speed", np.zeros(nn), units="m/s", desc="airspeed")
        self.add_input("pitch", np.zeros(nn), units="rad", desc="pitch angle")
        self.add_input(
            "flight_path_angle",
            np.zeros(nn),
            units="rad",
            desc="flight-path angle, positive climbing",
        )
        self.add_input(
            "density", np.full(nn, SEA_LEVEL_DENSITY), units="kg/m**3", desc="air density"
        )
        self.add_input(
            "speed_of_sound",
            np.full(nn, SEA_LEVEL_SPEED_OF_SOUND),
            units="m/s",
            desc="speed of sound",
        )
        self.add_input(
            "dynamic_viscosity",
            np.full(nn, 1.7894e-5),
            units="Pa*s",
            desc="dynamic viscosity of air",
        )

        self.add_output(
            "angle_of_attack",
            np.zeros(nn),
            units="rad",
            desc="angle of attack, pitch minus flight-path angle",
        )
        self.add_output("u", np.zeros(nn), units="m/s", desc="body-axis x velocity")
        self.add_output("w", np.zeros(nn), units="m/s", desc="body-axis z velocity (down)")
        self.add_output(
            "velocity", np.zeros((nn, 3)), units="m/s", desc="body-axis velocity vector (u, 0, w)"
        )
        self.add_output("mach", np.zeros(nn), units=None, desc="Mach number")
        self.add_output("dynamic_pressure", np.zeros(nn), units="Pa", desc="dynamic pressure")
        self.add_output(
            "reynolds_per_length",
            np.zeros(nn),
            units="1/m",
            desc="Reynolds number per metre of reference length",
        )

        self.declare_partials("angle_of_attack", "pitch", diagonal=True, val=1.0)
        self.declare_partials("angle_of_attack", "flight_path_angle", diagonal=True, val=-1.0)
        self.declare_partials(["u", "w"], ["speed", "pitch", "flight_path_angle"], diagonal=True)
        rows = np.concatenate([3 * np.arange(nn), 3 * np.arange(nn) + 2])
        cols = np.concatenate([np.arange(nn), np.arange(nn)])
        self.declare_partials(
            "velocity", ["speed", "pitch", "flight_path_angle"], rows=rows, cols=cols
        )
        self.declare_partials("mach", ["speed", "speed_of_sound"], diagonal=True)
        self.declare_partials("dynamic_pressure", ["speed", "density"], diagonal=True)
        self.declare_partials(
            "reynolds_per_length", ["speed", "density", "dynamic_viscosity"], diagonal=True
        )

    def compute(self, inputs, outputs):
        speed = inputs["speed"]
        check_range(
            "speed", speed, lower=0.0, units="m/s", error=om.AnalysisError, where=self.msginfo
        )
        alpha = inputs["pitch"] - inputs["flight_path_angle"]
        rho = inputs["density"]
        outputs["angle_of_attack"] = alpha
        outputs["u"] = speed * np.cos(alpha)
        outputs["w"] = speed * np.sin(alpha)
        outputs["velocity"][:, 0] = outputs["u"]
        outputs["velocity"][:, 1] = 0.0
        outputs["velocity"][:, 2] = outputs["w"]
        outputs["mach"] = speed / inputs["speed_of_sound"]
        outputs["dynamic_pressure"] = 0.5 * rho * speed**2
        outputs["reynolds_per_length"] = rho * speed / inputs["dynamic_viscosity"]

    def compute_partials(self, inputs, partials):
        speed = inputs["speed"]
        alpha = inputs["pitch"] - inputs["flight_path_angle"]
        rho = inputs["density"]
        a = inputs["speed_of_sound"]
        mu = inputs["dynamic_viscosity"]
        cos, sin = np.cos(alpha), np.sin(alpha)

        partials["u", "speed"] = cos
        partials["u", "pitch"] = -speed * sin
        partials["u", "flight_path_angle"] = speed * sin
        partials["w", "speed"] = sin
        partials["w", "pitch"] = speed * cos
        partials["w", "flight_path_angle"] = -speed * cos
        for wrt in ("speed", "pitch", "flight_path_angle"):
            partials["velocity", wrt] = np.concatenate([partials["u", wrt], partials["w", wrt]])
        partials["mach", "speed"] = 1.0 / a
        partials["mach", "speed_of_sound"] = -speed / a**2
        partials["dynamic_pressure", "speed"] = rho * speed
        partials["dynamic_pressure", "density"] = 0.5 * speed**2
        partials["reynolds_per_length", "speed"] = rho / mu
        partials["reynolds_per_length", "density"] = speed / mu
        partials["reynolds_per_length", "dynamic_viscosity"] = -rho * speed / mu**2
