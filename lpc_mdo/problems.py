"""Problem builders: the OpenMDAO problems that run scripts and the CLI share."""

import os

import openmdao.api as om

from lpc_mdo.groups.lpc import LPCGroup
from lpc_mdo.vehicle import load_vehicle


def build_analysis_problem(vehicle=None, recorder_path=None, name="analysis", **options):
    """
    The full lift-plus-cruise model of a vehicle at its initial design, ready to run.

    Parameters
    ----------
    vehicle : Vehicle, str, os.PathLike or None
        A vehicle, a vehicle file, or None for the reference vehicle.
    recorder_path : str or os.PathLike or None
        SQLite case file for a problem recorder (record with ``prob.record('final')``); it
        records every variable, so post-processing needs nothing else.
    name : str
        Problem name; OpenMDAO writes reports and outputs under ``{name}_out``.
    **options
        Further :class:`~lpc_mdo.groups.lpc.LPCGroup` options (``static_margin``,
        ``conditions``, ``rotor_polar``, ...).

    Returns
    -------
    om.Problem
        A problem that has been set up; ``prob.vehicle`` is the vehicle.
    """
    if vehicle is None or isinstance(vehicle, (str, os.PathLike)):
        vehicle = load_vehicle(vehicle)
    prob = om.Problem(model=LPCGroup(vehicle=vehicle, **options), name=name)
    if recorder_path is not None:
        prob.add_recorder(om.SqliteRecorder(str(recorder_path)))
        prob.recording_options["includes"] = ["*"]
    prob.setup(mode="rev")
    prob.vehicle = vehicle
    return prob
