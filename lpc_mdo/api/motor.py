"""Plain-function PMSM motor analysis: size a motor from its length and run it at given points.

:func:`motor_analysis` builds a small Problem around :class:`lpc_mdo.groups.motor.MotorGroup`
(the assembly the vehicle model uses), runs it and returns plain numbers.
"""

import dataclasses

import numpy as np
import openmdao.api as om

from lpc_mdo.components.motor.parameters import MotorParameters
from lpc_mdo.core.checks import check_range
from lpc_mdo.core.mpi import serial_comm
from lpc_mdo.groups.motor import MotorGroup

__all__ = ["motor_analysis"]


_RESULT_NAMES = (
    "mass",
    "peak_torque",
    "diameter",
    "resistance",
    "inductance_d",
    "inductance_q",
    "flux_linkage",
    "air_gap_flux_density",
    "em_torque",
    "efficiency",
    "input_power",
    "output_power",
    "power_loss",
    "copper_loss",
    "iron_loss",
    "windage_loss",
    "current_q",
    "current_d",
    "current",
    "voltage",
    "voltage_margin",
    "torque_limit",
    "torque_margin",
    "voltage_torque_margin",
    "peak_current",
    "available_torque",
    "current_margin",
)


def _positive_array(name, value, units):
    return np.asarray(
        check_range(name, value, lower=0.0, lower_open=True, units=units, where="motor"),
        dtype=float,
    )


def motor_analysis(
    length,
    rotor_torque,
    rotor_rpm,
    length_to_diameter=0.5,
    gear_ratio=4.0,
    parameters=None,
    rated_current=None,
):
    """
    Size a PMSM from its length and analyse it at given rotor torques and speeds.

    Builds a small Problem around :class:`MotorGroup`, runs it and returns plain numbers
    (docs theory/motor; paper eqs. 23-26).

    Parameters
    ----------
    length : float or array_like (num_motors,)
        Stack length, m (> 0).
    rotor_torque : float or array_like (num_nodes,) or (num_motors, num_nodes)
        Required rotor torque, N*m (> 0), before the gearbox.
    rotor_rpm : float or array_like, same shape rules as rotor_torque
        Rotor speed, rpm (> 0).
    length_to_diameter : float
        L/D ratio (> 0). Default 0.5 (paper); lsdo_motor's reference case A uses 1/3.
    gear_ratio : float
        Motor speed / rotor speed (> 0). Default 4.
    parameters : MotorParameters or None
        Other fixed parameters; its gear_ratio is replaced by ``gear_ratio``.
    rated_current : float or array_like (num_motors,) or None
        Rated phase current of the winding, A (> 0): the turns per phase follow from it
        (docs theory/motor 'Winding for the bus'). None: ``parameters.rated_current``.

    Returns
    -------
    dict
        'mass', 'peak_torque', 'diameter', 'resistance', 'inductance_d', 'inductance_q',
        'flux_linkage', 'air_gap_flux_density' (per motor) and 'em_torque', 'efficiency',
        'input_power', 'output_power', 'power_loss', 'copper_loss', 'iron_loss',
        'windage_loss', 'current_q', 'current_d', 'current', 'voltage', 'voltage_margin',
        'torque_limit', 'torque_margin', 'voltage_torque_margin', 'available_torque',
        'current_margin' (per operating point) and 'peak_current' (per motor) in SI units,
        plus 'beyond_voltage_limit' (bool). Floats when every argument is a scalar,
        otherwise arrays of shape (num_motors,) and (num_motors, num_nodes).

    Raises
    ------
    ValueError
        If an argument is not finite and > 0 or the shapes do not fit.
    om.AnalysisError
        If an inner solve fails.
    """
    length_arr = _positive_array("length", length, "m")
    torque_arr = _positive_array("rotor_torque", rotor_torque, "N*m")
    rpm_arr = _positive_array("rotor_rpm", rotor_rpm, "rpm")
    ratio = _positive_array("length_to_diameter", length_to_diameter, None)
    gear = _positive_array("gear_ratio", gear_ratio, None)
    if ratio.ndim or gear.ndim:
        raise ValueError("motor: 'length_to_diameter' and 'gear_ratio' must be scalars.")
    if parameters is None:
        parameters = MotorParameters()
    if not isinstance(parameters, MotorParameters):
        raise ValueError(
            f"motor: 'parameters' = {parameters!r} must be a MotorParameters instance or None."
        )
    parameters = dataclasses.replace(parameters, gear_ratio=float(gear))
    scalar = length_arr.ndim == 0 and torque_arr.ndim == 0 and rpm_arr.ndim == 0

    if length_arr.ndim > 1:
        raise ValueError(
            f"motor: 'length' must be a scalar or 1-D (num_motors,), got shape {length_arr.shape}."
        )
    length_arr = np.atleast_1d(length_arr)
    nm = length_arr.size
    try:
        point_shape = np.broadcast_shapes(np.shape(torque_arr), np.shape(rpm_arr))
        if len(point_shape) <= 1:
            point_shape = (nm,) + (point_shape or (1,))
        torque_arr = np.broadcast_to(torque_arr, point_shape)
        rpm_arr = np.broadcast_to(rpm_arr, point_shape)
        if len(point_shape) != 2 or point_shape[0] != nm:
            raise ValueError
    except ValueError:
        raise ValueError(
            f"motor: 'rotor_torque' {np.shape(rotor_torque)} and 'rotor_rpm' "
            f"{np.shape(rotor_rpm)} must be scalars, (num_nodes,) or "
            f"(num_motors, num_nodes) with num_motors = {nm} (length)."
        ) from None
    nn = point_shape[1]

    prob = om.Problem(reports=False, comm=serial_comm())
    prob.model.add_subsystem(
        "motor",
        MotorGroup(
            num_motors=nm, num_nodes=nn, length_to_diameter=float(ratio), parameters=parameters
        ),
        promotes=["*"],
    )
    prob.setup()
    prob.set_val("length", length_arr, units="m")
    if rated_current is not None:
        current = _positive_array("rated_current", rated_current, "A")
        prob.set_val("rated_current", np.broadcast_to(current, (nm,)), units="A")
    prob.set_val("rotor_torque", torque_arr, units="N*m")
    prob.set_val("rotor_rpm", rpm_arr, units="rpm")
    prob.run_model()

    result = {}
    for name in _RESULT_NAMES:
        value = np.array(prob.get_val(name))
        if not np.all(np.isfinite(value)):
            raise om.AnalysisError(
                f"motor: the analysis returned non-finite '{name}' = {value.tolist()}."
            )
        result[name] = float(value.ravel()[0]) if scalar else value
    flag = np.array(prob.get_val("beyond_voltage_limit")) > 0.5
    result["beyond_voltage_limit"] = bool(flag.ravel()[0]) if scalar else flag
    return result
