"""The single import surface of lpc-mdo: ``import lpc_mdo.api as lpc``.

Plain functions that wrap the OpenMDAO models for quick studies, and the public classes. The
plain functions live in this package, one module per discipline:

acoustics
    :func:`~lpc_mdo.api.acoustics.rotor_noise`.
airfoil
    :func:`~lpc_mdo.api.airfoil.airfoil_polar`.
motor
    :func:`~lpc_mdo.api.motor.motor_analysis` (``lpc.motor``).
rotor
    :func:`~lpc_mdo.api.rotor.bem`, :func:`~lpc_mdo.api.rotor.pitt_peters`,
    :func:`~lpc_mdo.api.rotor.blade_stations`.
structures
    :func:`~lpc_mdo.api.structures.beam`, :func:`~lpc_mdo.api.structures.box_beam`.
vlm
    :func:`~lpc_mdo.api.vlm.vlm`.
weights
    :func:`~lpc_mdo.api.weights.mass_breakdown`,
    :func:`~lpc_mdo.api.weights.format_mass_breakdown`.

and :func:`~lpc_mdo.sizing.size_vehicle`, which closes a vehicle's battery, gross mass and motors
on its mission (``lpc-mdo size``).
"""

from lpc_mdo.api.acoustics import rotor_noise
from lpc_mdo.api.airfoil import airfoil_polar
from lpc_mdo.api.motor import motor_analysis as motor
from lpc_mdo.api.rotor import bem, blade_stations, pitt_peters
from lpc_mdo.api.structures import beam, box_beam
from lpc_mdo.api.vlm import vlm
from lpc_mdo.api.weights import format_mass_breakdown, mass_breakdown
from lpc_mdo.components.acoustics.a_weighting import a_weighting
from lpc_mdo.drivers import IpoptDriver, IpoptMultipliers, SlsqpDriver, make_driver
from lpc_mdo.groups.acoustics import RotorNoiseGroup
from lpc_mdo.groups.lpc import LPCGroup
from lpc_mdo.groups.motor import MotorGroup
from lpc_mdo.groups.vehicle import VehicleGroup, calibrate_other_mass
from lpc_mdo.groups.weights import WeightsGroup
from lpc_mdo.problems import build_analysis_problem
from lpc_mdo.sizing import SizingError, SizingResult, size_vehicle
from lpc_mdo.vehicle import (
    VehicleSpecError,
    load_vehicle,
    paper_calibrated_vehicle,
    paper_initial_vehicle,
    reference_vehicle,
)

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
    "format_mass_breakdown",
    "load_vehicle",
    "make_driver",
    "mass_breakdown",
    "motor",
    "paper_calibrated_vehicle",
    "paper_initial_vehicle",
    "pitt_peters",
    "reference_vehicle",
    "RotorNoiseGroup",
    "SizingError",
    "SizingResult",
    "size_vehicle",
    "a_weighting",
    "airfoil_polar",
    "rotor_noise",
    "vlm",
]
