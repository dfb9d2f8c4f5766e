"""Problem builders: the OpenMDAO problems that run scripts and the CLI share."""

import os

import openmdao.api as om

from lpc_mdo.groups.flight_conditions import FlightConditionsGroup
from lpc_mdo.vehicle import load_vehicle


def build_analysis_problem(vehicle=None, recorder_path=None, name="analysis"):
    """
    Problem that analyzes a vehicle's design conditions with every discipline that exists.

    Parameters
    ----------
    vehicle : Vehicle, str, os.PathLike or None
        A vehicle, a vehicle file, or None for the reference vehicle.
    recorder_path : str or os.PathLike or None
        SQLite case file for a problem recorder (record with ``prob.record('final')``).
    name : str
        Problem name; OpenMDAO writes reports and outputs under ``{name}_out``.

    Returns
    -------
    om.Problem
        A problem that has been set up.
    """
    if vehicle is None or isinstance(vehicle, (str, os.PathLike)):
        vehicle = load_vehicle(vehicle)
    prob = om.Problem(name=name)
    prob.model.add_subsystem("conditions", FlightConditionsGroup(vehicle=vehicle))
    if recorder_path is not None:
        prob.add_recorder(om.SqliteRecorder(str(recorder_path)))
        prob.recording_options["includes"] = ["*"]
    prob.setup()
    prob.vehicle = vehicle
    return prob
