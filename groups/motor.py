"""PMSM motor model assembly (sizing, equivalent circuit, operating points) and a plain wrapper."""

import dataclasses

import numpy as np
import openmdao.api as om

from lpc_mdo.checks import RangeCheck, check_range
from lpc_mdo.components.motor.ecm import (
    InductanceComp,
    MagnetCircuitComp,
    MagnetFluxComp,
    MotorECMParametersComp,
    QAxisFluxComp,
)
from lpc_mdo.components.motor.efficiency import EMTorqueComp, MotorLossComp, MotorMarginComp
from lpc_mdo.components.motor.mtpa import MTPAComp
from lpc_mdo.components.motor.parameters import MotorParameters
from lpc_mdo.components.motor.sizing import MotorSizingComp
from lpc_mdo.components.motor.torque_limit import TorqueLimitComp
from lpc_mdo.mpi import serial_comm

_check_ratio = RangeCheck(lower=0.0, lower_open=True, where="MotorGroup")
_check_loading = RangeCheck(lower=0.0, lower_open=True, where="MotorGroup")


def _declare_options(group):
    group.options.declare('num_motors', default=1, types=int, lower=1,
                          desc='Number of motors (different designs) evaluated at once')
    group.options.declare('num_nodes', default=1, types=int, lower=1,
                          desc='Number of operating points (nodes) per motor')
    group.options.declare('parameters', default=MotorParameters(), types=MotorParameters,
                          desc='Fixed motor parameters')


class MotorGroup(om.Group):
    """
    Interior PMSM model of the lift-plus-cruise motors: sizing, equivalent circuit, operation.

    reference/models_structures_motor_vehicle.md §7 and paper Sec. III.F (eqs. 23-26):

    - ``sizing`` (MotorSizingComp): D, mass (eq. 23), peak torque, internal geometry;
    - ``ecm_parameters`` (MotorECMParametersComp): magnet and circuit parameters, R_dc;
    - ``magnet_circuit`` (MagnetCircuitComp, implicit, bracketed) and ``magnet_flux``
      (MagnetFluxComp): magnet MEC, B_delta and the pole flux;
    - ``q_axis_flux`` (QAxisFluxComp, implicit, bracketed) and ``inductance``
      (InductanceComp): L_d, L_q, Psi_F;
    - ``torque_limit`` (TorqueLimitComp, implicit, bracketed; optional): voltage-limited torque;
    - ``em_torque`` (EMTorqueComp, implicit, Newton with bracket safeguard): T_em from the
      efficiency residual eq. 24, with the loss model at the MTPA current inside;
    - ``mtpa`` (MTPAComp, implicit, bracketed): MTPA q-axis current, eq. 26;
    - ``losses`` (MotorLossComp): currents, voltage, losses, efficiency, input power;
    - ``margins`` (MotorMarginComp): torque margin (>= 0.10 in the paper), voltage margin and
      the beyond-voltage-limit flag (no flux weakening, as in the paper).

    Per-motor variables have shape (num_motors,), per-operating-point ones
    (num_motors, num_nodes). Everything is promoted. The model is feed-forward (each implicit
    component solves itself in solve_nonlinear), so the group runs once; the implicit components
    sit under a sparse DirectSolver, so the totals are one linear solve (adjoint or direct).

    Inputs
    ------
    length : float, (num_motors,), m
        Stack length (design variable).
    diameter : float, (num_motors,), m
        Outer stator diameter; an input only with ``length_to_diameter`` None.
    electric_loading : float, (num_motors,), A/m
        Electric loading A_bar. Default: the option ``electric_loading``.
    magnetic_loading : float, (num_motors,), T
        Magnetic loading B_bar. Default: the option ``magnetic_loading``.
    rotor_torque : float, (num_motors, num_nodes), N*m
        Required rotor torque at each operating point.
    rotor_rpm : float, (num_motors, num_nodes), rpm
        Rotor speed at each operating point.

    Outputs
    -------
    mass, peak_torque, diameter (with ``length_to_diameter``) : float, (num_motors,)
        kg, N*m, m.
    resistance, inductance_d, inductance_q, flux_linkage, air_gap_flux_density : float,
    (num_motors,)
        ohm, H, H, Wb, T (and every other geometry/circuit output of the components).
    em_torque, current_q, current_d, current, voltage, efficiency, input_power, output_power,
    power_loss (and its parts), torque_limit, torque_margin, voltage_margin,
    voltage_torque_margin, beyond_voltage_limit : float, (num_motors, num_nodes)
        See the components.

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    num_nodes : int
        Operating points per motor (>= 1). Default 1.
    length_to_diameter : float or None
        L/D ratio tying D to L (> 0). Default 0.5 (paper). None: diameter is an input.
    parameters : MotorParameters
        Fixed motor parameters (pole pairs, gear ratio, voltage limit, ...).
    electric_loading : float
        Default of the input ``electric_loading``, A/m (> 0). Default 30e3; a vehicle's value
        is ``vehicle.motor.electric_loading`` (``lpc_mdo.groups.vehicle.motor_loadings``).
    magnetic_loading : float
        Default of the input ``magnetic_loading``, T (> 0). Default 0.85; a vehicle's value is
        ``vehicle.motor.magnetic_loading``.
    include_torque_limit : bool
        Compute the voltage-limited torque and its margin. Default True.
    """

    def initialize(self):
        _declare_options(self)
        self.options.declare('length_to_diameter', default=0.5, types=(int, float),
                             allow_none=True, check_valid=_check_ratio,
                             desc='L/D ratio tying D to L (> 0); None makes diameter an input')
        self.options.declare('include_torque_limit', default=True, types=bool,
                             desc='Compute the voltage-limited torque and its margin')
        self.options.declare('electric_loading', default=30.0e3, types=(int, float),
                             check_valid=_check_loading,
                             desc='Default of the input electric_loading, A/m (> 0)')
        self.options.declare('magnetic_loading', default=0.85, types=(int, float),
                             check_valid=_check_loading,
                             desc='Default of the input magnetic_loading, T (> 0)')

    def setup(self):
        nm, nn = self.options['num_motors'], self.options['num_nodes']
        par = self.options['parameters']
        motors = {'num_motors': nm, 'parameters': par}
        points = {'num_motors': nm, 'num_nodes': nn, 'parameters': par}
        with_limit = self.options['include_torque_limit']

        self.add_subsystem('sizing', MotorSizingComp(
            length_to_diameter=self.options['length_to_diameter'], **motors), promotes=['*'])
        self.add_subsystem('ecm_parameters', MotorECMParametersComp(**motors), promotes=['*'])
        self.add_subsystem('magnet_circuit', MagnetCircuitComp(**motors), promotes=['*'])
        self.add_subsystem('magnet_flux', MagnetFluxComp(**motors), promotes=['*'])
        self.add_subsystem('q_axis_flux', QAxisFluxComp(**motors), promotes=['*'])
        self.add_subsystem('inductance', InductanceComp(**motors), promotes=['*'])
        if with_limit:
            self.add_subsystem('torque_limit', TorqueLimitComp(**points), promotes=['*'])
        self.add_subsystem('em_torque', EMTorqueComp(**points), promotes=['*'])
        self.add_subsystem('mtpa', MTPAComp(**points), promotes=['*'])
        self.add_subsystem('losses', MotorLossComp(**points), promotes=['*'])
        self.add_subsystem('margins', MotorMarginComp(include_torque_limit=with_limit,
                                                      **points), promotes=['*'])

        self.set_input_defaults('length', 0.1 * np.ones(nm), units='m')
        self.set_input_defaults('electric_loading',
                                np.full(nm, float(self.options['electric_loading'])), units='A/m')
        self.set_input_defaults('magnetic_loading',
                                np.full(nm, float(self.options['magnetic_loading'])), units='T')
        if self.options['length_to_diameter'] is None:
            self.set_input_defaults('diameter', 0.2 * np.ones(nm), units='m')
        self.set_input_defaults('rotor_torque', 500.0 * np.ones((nm, nn)), units='N*m')
        self.set_input_defaults('rotor_rpm', 1000.0 * np.ones((nm, nn)), units='rpm')

        self.linear_solver = om.DirectSolver(assemble_jac=True)


_RESULT_NAMES = (
    'mass', 'peak_torque', 'diameter', 'resistance', 'inductance_d', 'inductance_q',
    'flux_linkage', 'air_gap_flux_density', 'em_torque', 'efficiency', 'input_power',
    'output_power', 'power_loss', 'copper_loss', 'iron_loss', 'windage_loss', 'current_q',
    'current_d', 'current', 'voltage', 'voltage_margin', 'torque_limit', 'torque_margin',
    'voltage_torque_margin',
)


def _positive_array(name, value, units):
    return np.asarray(check_range(name, value, lower=0.0, lower_open=True, units=units,
                                  where="motor"), dtype=float)


def motor_analysis(length, rotor_torque, rotor_rpm, length_to_diameter=0.5, gear_ratio=4.0,
                   parameters=None):
    """
    Size a PMSM from its length and analyse it at given rotor torques and speeds.

    Builds a small Problem around :class:`MotorGroup`, runs it and returns plain numbers
    (reference/models_structures_motor_vehicle.md §7; paper eqs. 23-26).

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

    Returns
    -------
    dict
        'mass', 'peak_torque', 'diameter', 'resistance', 'inductance_d', 'inductance_q',
        'flux_linkage', 'air_gap_flux_density' (per motor) and 'em_torque', 'efficiency',
        'input_power', 'output_power', 'power_loss', 'copper_loss', 'iron_loss',
        'windage_loss', 'current_q', 'current_d', 'current', 'voltage', 'voltage_margin',
        'torque_limit', 'torque_margin', 'voltage_torque_margin' (per operating point) in SI
        units, plus 'beyond_voltage_limit' (bool). Floats when every argument is a scalar,
        otherwise arrays of shape (num_motors,) and (num_motors, num_nodes).

    Raises
    ------
    ValueError
        If an argument is not finite and > 0 or the shapes do not fit.
    om.AnalysisError
        If an inner solve fails.
    """
    length_arr = _positive_array('length', length, 'm')
    torque_arr = _positive_array('rotor_torque', rotor_torque, 'N*m')
    rpm_arr = _positive_array('rotor_rpm', rotor_rpm, 'rpm')
    ratio = _positive_array('length_to_diameter', length_to_diameter, None)
    gear = _positive_array('gear_ratio', gear_ratio, None)
    if ratio.ndim or gear.ndim:
        raise ValueError("motor: 'length_to_diameter' and 'gear_ratio' must be scalars.")
    if parameters is None:
        parameters = MotorParameters()
    if not isinstance(parameters, MotorParameters):
        raise ValueError(f"motor: 'parameters' = {parameters!r} must be a MotorParameters "
                         "instance or None.")
    parameters = dataclasses.replace(parameters, gear_ratio=float(gear))
    scalar = length_arr.ndim == 0 and torque_arr.ndim == 0 and rpm_arr.ndim == 0

    if length_arr.ndim > 1:
        raise ValueError(f"motor: 'length' must be a scalar or 1-D (num_motors,), got shape "
                         f"{length_arr.shape}.")
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
        raise ValueError(f"motor: 'rotor_torque' {np.shape(rotor_torque)} and 'rotor_rpm' "
                         f"{np.shape(rotor_rpm)} must be scalars, (num_nodes,) or "
                         f"(num_motors, num_nodes) with num_motors = {nm} (length).") from None
    nn = point_shape[1]

    prob = om.Problem(reports=False, comm=serial_comm())
    prob.model.add_subsystem('motor', MotorGroup(num_motors=nm, num_nodes=nn,
                                                 length_to_diameter=float(ratio),
                                                 parameters=parameters), promotes=['*'])
    prob.setup()
    prob.set_val('length', length_arr, units='m')
    prob.set_val('rotor_torque', torque_arr, units='N*m')
    prob.set_val('rotor_rpm', rpm_arr, units='rpm')
    prob.run_model()

    result = {}
    for name in _RESULT_NAMES:
        value = np.array(prob.get_val(name))
        if not np.all(np.isfinite(value)):
            raise om.AnalysisError(f"motor: the analysis returned non-finite '{name}' = "
                                   f"{value.tolist()}.")
        result[name] = float(value.ravel()[0]) if scalar else value
    flag = np.array(prob.get_val('beyond_voltage_limit')) > 0.5
    result['beyond_voltage_limit'] = bool(flag.ravel()[0]) if scalar else flag
    return result
