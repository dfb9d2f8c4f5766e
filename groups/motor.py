"""PMSM motor model assembly (sizing, equivalent circuit, operating points).

The plain-function wrapper ``motor_analysis`` is in :mod:`lpc_mdo.api.motor`.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.motor.ecm import (
    InductanceComp,
    MagnetCircuitComp,
    MagnetFluxComp,
    MotorECMParametersComp,
    QAxisFluxComp,
)
from lpc_mdo.components.motor.efficiency import EMTorqueComp, MotorLossComp, MotorMarginComp
from lpc_mdo.components.motor.mtpa import MTPAComp, PeakCurrentComp
from lpc_mdo.components.motor.parameters import MotorParameters
from lpc_mdo.components.motor.sizing import MotorSizingComp
from lpc_mdo.components.motor.torque_limit import TorqueLimitComp
from lpc_mdo.core.checks import RangeCheck

_check_ratio = RangeCheck(lower=0.0, lower_open=True, where="MotorGroup")
_check_loading = RangeCheck(lower=0.0, lower_open=True, where="MotorGroup")


def _declare_options(group):
    group.options.declare(
        "num_motors",
        default=1,
        types=int,
        lower=1,
        desc="Number of motors (different designs) evaluated at once",
    )
    group.options.declare(
        "num_nodes",
        default=1,
        types=int,
        lower=1,
        desc="Number of operating points (nodes) per motor",
    )
    group.options.declare(
        "parameters",
        default=MotorParameters(),
        types=MotorParameters,
        desc="Fixed motor parameters",
    )


class MotorGroup(om.Group):
    """
    Interior PMSM model of the lift-plus-cruise motors: sizing, equivalent circuit, operation.

    docs theory/motor and paper Sec. III.F (eqs. 23-26):

    - ``sizing`` (MotorSizingComp): D, mass (eq. 23), peak torque, internal geometry;
    - ``ecm_parameters`` (MotorECMParametersComp): magnet and circuit parameters, R_dc;
    - ``magnet_circuit`` (MagnetCircuitComp, implicit, bracketed) and ``magnet_flux``
      (MagnetFluxComp): magnet MEC, B_delta and the pole flux;
    - ``q_axis_flux`` (QAxisFluxComp, implicit, bracketed) and ``inductance``
      (InductanceComp): L_d, L_q, Psi_F;
    - ``peak_current`` (PeakCurrentComp): the MTPA phase current at the peak torque, which the
      inverter and cables are rated for;
    - ``torque_limit`` (TorqueLimitComp, implicit, bracketed; optional): voltage-limited torque;
    - ``em_torque`` (EMTorqueComp, implicit, Newton with bracket safeguard): T_em from the
      efficiency residual eq. 24, with the loss model at the MTPA current inside;
    - ``mtpa`` (MTPAComp, implicit, bracketed): MTPA q-axis current, eq. 26;
    - ``losses`` (MotorLossComp): currents, voltage, losses, efficiency, input power;
    - ``margins`` (MotorMarginComp): torque margin against the smooth minimum of the peak and
      the voltage-limited torque (>= 0.10 in the paper), current margin, voltage margin and the
      beyond-voltage-limit flag (no flux weakening, as in the paper).

    The first seven components depend on the motor design alone: they are also
    :class:`MotorDesignGroup`, the rest :class:`MotorOperationGroup`. The LPC model splits them
    (one design group over the vehicle's motor designs, one operating group per condition);
    this group keeps both for a motor on its own (:func:`lpc_mdo.api.motor.motor_analysis`).

    Per-motor variables have shape (num_motors,), per-operating-point ones
    (num_motors, num_nodes). Everything is promoted. The model is feed-forward (each implicit
    component solves itself in solve_nonlinear), so the group runs once; each implicit
    component also solves its own linear system (its state Jacobian is diagonal), so one pass of
    the group's default LinearRunOnce gives the exact totals.

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
    rated_current : float, (num_motors,), A
        Rated phase current I_w of the winding (turns per phase W = pi D_i A_bar/(2 m I_w)):
        the winding chosen for the supply voltage. Default ``parameters.rated_current``.
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
        _declare_design_options(self)
        _declare_operation_options(self)

    def setup(self):
        add_design_components(self)
        add_operation_components(self)
        _design_input_defaults(self)
        _operating_point_defaults(self)

        # Feed-forward, and each implicit component solves its own (diagonal) linear system:
        # one LinearRunOnce pass gives exact totals. No DirectSolver here, since OpenMDAO treats
        # a group with one as atomic for relevance and warns about it on every driver run.


class MotorDesignGroup(om.Group):
    """
    The design half of :class:`MotorGroup`: what depends on the motor design alone.

    ``sizing``, ``ecm_parameters``, ``magnet_circuit``, ``magnet_flux``, ``q_axis_flux``,
    ``inductance`` and ``peak_current`` of :class:`MotorGroup` (same components, names and
    promotion), evaluated once per motor design. The vehicle group runs one over the vehicle's
    motor designs (one per lift-rotor pair and the pusher) and the conditions'
    :class:`MotorOperationGroup` read its outputs :data:`DESIGN_OUTPUTS`, instead of every
    condition sizing its own motors again (the reference vehicle's 18 condition motor groups
    had 126 design components; now 7).

    Inputs: ``length``, ``diameter`` (with ``length_to_diameter`` None), ``electric_loading``,
    ``magnetic_loading``, ``rated_current`` (num_motors,). Outputs: the design outputs of
    :class:`MotorGroup`.
    Options: ``num_motors``, ``parameters``, ``length_to_diameter``, ``electric_loading``,
    ``magnetic_loading`` as :class:`MotorGroup`.
    """

    def initialize(self):
        _declare_options(self)
        _declare_design_options(self)

    def setup(self):
        add_design_components(self)
        _design_input_defaults(self)


class MotorOperationGroup(om.Group):
    """
    The operating-point half of :class:`MotorGroup`, for motor designs computed elsewhere.

    ``torque_limit`` (optional), ``em_torque``, ``mtpa``, ``losses`` and ``margins`` of
    :class:`MotorGroup` (same components, names and promotion). The design quantities
    :data:`DESIGN_OUTPUTS` and ``length`` are inputs, shape (num_motors,), connected from a
    :class:`MotorDesignGroup` (a condition connects the rows of its motors from the vehicle
    group's).

    Options: ``num_motors``, ``num_nodes``, ``parameters``, ``include_torque_limit`` as
    :class:`MotorGroup`.
    """

    def initialize(self):
        _declare_options(self)
        _declare_operation_options(self)

    def setup(self):
        add_operation_components(self)
        self.set_input_defaults("length", 0.1 * np.ones(self.options["num_motors"]), units="m")
        _operating_point_defaults(self)


def _declare_design_options(group):
    group.options.declare(
        "length_to_diameter",
        default=0.5,
        types=(int, float),
        allow_none=True,
        check_valid=_check_ratio,
        desc="L/D ratio tying D to L (> 0); None makes diameter an input",
    )
    group.options.declare(
        "electric_loading",
        default=30.0e3,
        types=(int, float),
        check_valid=_check_loading,
        desc="Default of the input electric_loading, A/m (> 0)",
    )
    group.options.declare(
        "magnetic_loading",
        default=0.85,
        types=(int, float),
        check_valid=_check_loading,
        desc="Default of the input magnetic_loading, T (> 0)",
    )


def _declare_operation_options(group):
    group.options.declare(
        "include_torque_limit",
        default=True,
        types=bool,
        desc="Compute the voltage-limited torque and its margin",
    )


def add_design_components(group):
    """Add the seven design components of :class:`MotorGroup` to ``group``, promoted."""
    motors = {"num_motors": group.options["num_motors"], "parameters": group.options["parameters"]}
    group.add_subsystem(
        "sizing",
        MotorSizingComp(length_to_diameter=group.options["length_to_diameter"], **motors),
        promotes=["*"],
    )
    group.add_subsystem("ecm_parameters", MotorECMParametersComp(**motors), promotes=["*"])
    group.add_subsystem("magnet_circuit", MagnetCircuitComp(**motors), promotes=["*"])
    group.add_subsystem("magnet_flux", MagnetFluxComp(**motors), promotes=["*"])
    group.add_subsystem("q_axis_flux", QAxisFluxComp(**motors), promotes=["*"])
    group.add_subsystem("inductance", InductanceComp(**motors), promotes=["*"])
    group.add_subsystem("peak_current", PeakCurrentComp(**motors), promotes=["*"])


def add_operation_components(group):
    """Add the operating-point components of :class:`MotorGroup` to ``group``, promoted."""
    points = {
        "num_motors": group.options["num_motors"],
        "num_nodes": group.options["num_nodes"],
        "parameters": group.options["parameters"],
    }
    with_limit = group.options["include_torque_limit"]
    if with_limit:
        group.add_subsystem("torque_limit", TorqueLimitComp(**points), promotes=["*"])
    group.add_subsystem("em_torque", EMTorqueComp(**points), promotes=["*"])
    group.add_subsystem("mtpa", MTPAComp(**points), promotes=["*"])
    group.add_subsystem("losses", MotorLossComp(**points), promotes=["*"])
    group.add_subsystem(
        "margins", MotorMarginComp(include_torque_limit=with_limit, **points), promotes=["*"]
    )


def _operating_point_defaults(group):
    shape = (group.options["num_motors"], group.options["num_nodes"])
    group.set_input_defaults("rotor_torque", np.full(shape, 500.0), units="N*m")
    group.set_input_defaults("rotor_rpm", np.full(shape, 1000.0), units="rpm")


def _design_input_defaults(group):
    nm = group.options["num_motors"]
    group.set_input_defaults("length", 0.1 * np.ones(nm), units="m")
    group.set_input_defaults(
        "rated_current", np.full(nm, group.options["parameters"].rated_current), units="A"
    )
    for name, units in (("electric_loading", "A/m"), ("magnetic_loading", "T")):
        group.set_input_defaults(name, np.full(nm, float(group.options[name])), units=units)
    if group.options["length_to_diameter"] is None:
        group.set_input_defaults("diameter", 0.2 * np.ones(nm), units="m")
