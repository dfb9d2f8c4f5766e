"""Atmosphere and kinematics of every design condition of a vehicle, vectorized."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.atmosphere import AtmosphereComp
from lpc_mdo.components.kinematics import KinematicsComp


class FlightConditionsGroup(om.Group):
    """
    Atmosphere and body-frame kinematics of all design conditions in one vectorized pass.

    The conditions (hover, transition_1..5, climb, cruise, descent, oei_1..4, plus_3g,
    minus_1g for the reference vehicle) are the nodes; their altitude, speed, pitch and
    flight-path angle default to the vehicle file's values and are inputs, so a run script or
    an optimizer can change them.

    Inputs (promoted)
    -----------------
    altitude : (num_conditions,), m
    speed : (num_conditions,), m/s
    pitch : (num_conditions,), rad
    flight_path_angle : (num_conditions,), rad

    Outputs (promoted)
    ------------------
    temperature, pressure, density, speed_of_sound, dynamic_viscosity, kinematic_viscosity
        from :class:`~lpc_mdo.components.atmosphere.AtmosphereComp`;
    angle_of_attack, u, w, mach, dynamic_pressure, reynolds_per_length
        from :class:`~lpc_mdo.components.kinematics.KinematicsComp`.

    Options
    -------
    vehicle : lpc_mdo.vehicle.Vehicle or None
        The vehicle whose conditions are evaluated; None takes the reference vehicle.
    """

    def initialize(self):
        self.options.declare("vehicle", default=None, allow_none=True,
                             desc="lpc_mdo.vehicle.Vehicle; None = reference vehicle")

    def setup(self):
        from lpc_mdo.vehicle import reference_vehicle

        vehicle = self.options["vehicle"] or reference_vehicle()
        conditions = vehicle.conditions
        nn = len(conditions)
        self.condition_names = [c.name for c in conditions]

        self.add_subsystem("atmosphere", AtmosphereComp(num_nodes=nn), promotes=["*"])
        self.add_subsystem("kinematics", KinematicsComp(num_nodes=nn), promotes=["*"])

        self.set_input_defaults("altitude", np.array([c.altitude for c in conditions]),
                                units="m")
        self.set_input_defaults("speed", np.array([c.speed for c in conditions]), units="m/s")
        self.set_input_defaults("pitch", np.array([c.pitch for c in conditions]), units="rad")
        self.set_input_defaults("flight_path_angle",
                                np.array([c.flight_path_angle for c in conditions]),
                                units="rad")
