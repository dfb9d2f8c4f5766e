"""The single import surface of lpc-mdo: ``import lpc_mdo.api as lpc``.

Plain functions that wrap the OpenMDAO models for quick studies, and the public classes.
"""

from lpc_mdo.drivers import IpoptDriver, IpoptMultipliers, SlsqpDriver, make_driver
from lpc_mdo.groups.acoustics import RotorNoiseGroup, a_weighting, rotor_noise
from lpc_mdo.groups.beam import beam, box_beam
from lpc_mdo.groups.lpc import LPCGroup
from lpc_mdo.groups.motor import MotorGroup
from lpc_mdo.groups.motor import motor_analysis as motor
from lpc_mdo.groups.rotor_analysis import bem, blade_stations, pitt_peters
from lpc_mdo.groups.vehicle import VehicleGroup
from lpc_mdo.groups.weights import WeightsGroup, calibrate_other_mass, mass_breakdown
from lpc_mdo.problems import build_analysis_problem
from lpc_mdo.vehicle import VehicleSpecError, load_vehicle, reference_vehicle

__all__ = [
    "LPCGroup",
    "VehicleGroup",
    "beam",
    "bem",
    "blade_stations",
    "box_beam",
    "IpoptDriver",
    "IpoptMultipliers",
    "MotorGroup",
    "SlsqpDriver",
    "VehicleSpecError",
    "WeightsGroup",
    "build_analysis_problem",
    "calibrate_other_mass",
    "load_vehicle",
    "make_driver",
    "mass_breakdown",
    "motor",
    "pitt_peters",
    "reference_vehicle",
    "RotorNoiseGroup",
    "a_weighting",
    "rotor_noise",
]
