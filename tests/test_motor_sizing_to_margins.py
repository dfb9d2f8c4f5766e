"""Sizing motor designs to their margins: lpc_mdo.motor_sizing."""

import copy

import numpy as np
import openmdao.api as om
import pytest

from lpc_mdo.motor_sizing import STALLED, MotorSizingError, _smallest, design_labels, size_motors
from lpc_mdo.problems import build_analysis_problem
from lpc_mdo.sizing import MOTOR_KINDS
from lpc_mdo.vehicle import load_vehicle, read_vehicle_file, vehicle_from_dict


def motor_problem(vehicle, name):
    """Return the analysis problem of the conditions whose motors turn, at the file's loads."""
    names = [c.name for c in vehicle.conditions if c.kind in MOTOR_KINDS]
    prob = build_analysis_problem(vehicle, name=name, conditions=names, static_margin=False)
    prob.final_setup()
    return prob


def test_the_search_finds_each_entrys_root_from_a_guess_or_the_bounds():
    # slack x^3 - c, increasing: the smallest feasible x is c^(1/3), to the tolerance on slack.
    c = np.array([0.5, 2.0, 5.0, 9.0])
    lower, upper = np.full(4, 0.1), np.full(4, 3.0)
    for guess in (None, np.array([0.7, 1.3, 1.7, 2.0]), np.full(4, 0.2)):
        x, slack = _smallest(lambda x: x**3 - c, lower, upper, 1e-6, guess)
        np.testing.assert_allclose(x, np.cbrt(c), rtol=1e-5)
        # stopped on the slack's tolerance or a bracket of 1e-5 in log x (slack 3e-5 c)
        assert np.all(slack >= 0.0) and np.all(slack <= 1e-6 + 3e-5 * c)
    # feasible at the lower bound: the lower bound; not even at the upper: negative slack
    x, slack = _smallest(lambda x: x**3 - np.array([1e-4, 50.0]), lower[:2], upper[:2], 1e-6)
    assert x[0] == pytest.approx(0.1) and slack[1] == pytest.approx(27.0 - 50.0)


def test_a_failing_model_run_is_repeated_entry_by_entry():
    # Entry 0's model fails below x = 0.8 (a stalled motor); entry 1 must still be found.
    calls = []

    def slack(x):
        calls.append(x.copy())
        if x[0] < 0.8:
            raise om.AnalysisError("stall")
        return x - np.array([1.0, 0.5])

    x, _ = _smallest(slack, np.full(2, 0.1), np.full(2, 2.0), 1e-8)
    np.testing.assert_allclose(x, [1.0, 0.5], rtol=1e-5)
    assert STALLED < 0.0 and any(c[0] < 0.8 for c in calls)


def test_each_motor_design_is_labelled_by_the_rotors_it_drives():
    labels = design_labels(load_vehicle())
    assert labels[-1] == "pusher" and len(labels) == 5
    assert labels[0] == "lift front_left_outer + front_right_outer"


@pytest.mark.integration
def test_a_motor_its_length_bound_cannot_size_is_named():
    data = copy.deepcopy(read_vehicle_file())
    # TC2's 0.10 m lift motors (the paper's), which a rotor out needs 0.119 m of
    data["design_variables"]["motor_length"].update(
        initial=[0.10, 0.10, 0.10, 0.10, 0.15], upper=[0.1, 0.25, 0.25, 0.25, 0.3]
    )
    vehicle = vehicle_from_dict(data)
    prob = motor_problem(vehicle, "short_motor")
    with pytest.raises(
        MotorSizingError,
        match=r"motor design 'lift front_left_outer \+ front_right_outer': torque margin -?\d\.\d+ "
        r"at its largest motor_length \(0.1 m\)",
    ):
        size_motors(prob, vehicle)


@pytest.mark.integration
def test_the_lift_motors_grow_together_for_a_larger_control_reserve():
    # Three times MIL-F-83300's Level 1 roll and pitch acceleration: the torque margins alone
    # (twice the Level 1 reserve at the reference) no longer give it, so the lift motors are
    # lengthened together until the least ratio over hover and the one-rotor-out cases is 1
    # (the file's own loads, not trimmed: the motor sizing alone).
    data = copy.deepcopy(read_vehicle_file())
    data["constraints"]["min_control_acceleration"] = [3 * 0.1396, 3 * 0.1047, 0.0]
    vehicle = vehicle_from_dict(data)
    prob = motor_problem(vehicle, "big_reserve")
    sized = size_motors(prob, vehicle)
    assert sized.sets_length == ["control reserve"] * 4 + ["torque margin"]
    # on the reserve at the loosest winding; the winding for the bus then moves it (1.15 here)
    assert sized.control_ratio >= 1.0
    assert np.all(sized.torque_margin[:4] > 0.1)  # longer than the torque margin needs
