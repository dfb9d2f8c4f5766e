"""The base class of the design-condition groups.

A design condition of the vehicle file (``[[conditions]]``) is built by the group class registered
for its ``kind`` (:mod:`lpc_mdo.groups.condition_kinds`), one module per kind:
:mod:`~lpc_mdo.groups.hover_condition`, :mod:`~lpc_mdo.groups.transition_condition`,
:mod:`~lpc_mdo.groups.steady_flight_condition`, :mod:`~lpc_mdo.groups.structural_condition`. What a
condition of a kind reads, owns and constrains is the kind's declaration in the vehicle layer
(:mod:`lpc_mdo.vehicle.condition_contract`, :mod:`lpc_mdo.vehicle.condition_kinds`), known
before any model is set up; the group builds the subsystems that declaration promises.

Variable names inside a condition (promoted): ``lift_radius`` (num_lift,), the blade geometry
``lift_chord``, ``lift_twist``, ``lift_station_radius``, ``lift_station_width`` (num_lift,
num_radial) and ``lift_hub_radius`` (num_lift,) (rows of the vehicle group's ``blade_*``,
computed once per rotor group), ``lift_hub_position`` (num_lift, 3), ``lift_motor_length``
(num_lift,) and the ``pusher_`` equivalents. Each design variable a condition owns reaches it
as an input of its suffix's name, one name per quantity (``transition_lift_rpm`` row k ->
``transition_k.lift_rpm``): ``lift_rpm`` (1, num_speed_groups: per pair, or per working rotor
in OEI), in transition ``roll_yaw_rpm`` (1, 2), ``pusher_rpm`` (1, 1), ``pitch``, ``elevator``
(1,). Each lift rotor's own speed is ``lift_rotor_rpm`` (num_lift, 1). Outputs
``linear_acceleration``, ``angular_acceleration`` (1, 3), ``electrical_power`` (1,),
``lift_motor_em_torque``/``pusher_motor_em_torque``, and the discipline outputs. The trim rows
are the six accelerations of the equations of motion (paper eqs. 29, 34).
"""

import openmdao.api as om

from lpc_mdo.components.aero.polar import LinearQuadraticPolar, Polar
from lpc_mdo.vehicle.condition_contract import ConditionKind
from lpc_mdo.vehicle.parts import BROADBAND_MODELS


class ConditionGroup(om.Group):
    """
    Base class of the design-condition groups: the options every condition has.

    A subclass names the declaration of its kind (:attr:`declaration`, a
    :class:`~lpc_mdo.vehicle.condition_contract.ConditionKind`) and builds in ``setup`` what that
    declaration promises: the inputs it lists in ``vehicle_inputs``, the design variables of
    ``variables`` as inputs of their names, the outputs its trim rows, constraints, motor sets and
    ``power_output`` name. Options common to every condition: ``vehicle``
    (:class:`~lpc_mdo.vehicle.Vehicle`), ``condition`` (its name in the vehicle file),
    ``rotor_polar``/``pusher_polar`` (blade-section polars), ``num_radial``, ``broadband_model``
    (of the hover noise constraint) and ``footprint`` (the departure's noise at the
    noise-footprint observers, lpc_mdo.groups.footprint).
    """

    #: The declaration of the condition's kind (a ConditionKind subclass).
    declaration = ConditionKind

    def initialize(self):
        self.options.declare("vehicle", desc="lpc_mdo.vehicle.Vehicle")
        self.options.declare("condition", types=str, desc="condition name in the vehicle file")
        self.options.declare(
            "rotor_polar",
            default=LinearQuadraticPolar(),
            types=Polar,
            desc="blade-section polar of the lift rotors (and of the pusher "
            "when 'pusher_polar' is None)",
        )
        self.options.declare(
            "pusher_polar",
            default=None,
            types=Polar,
            allow_none=True,
            desc="blade-section polar of the pusher (None: 'rotor_polar')",
        )
        self.options.declare(
            "num_radial", default=25, types=int, lower=2, desc="radial stations of the rotor models"
        )
        self.options.declare(
            "broadband_model",
            default="gill_lee",
            values=BROADBAND_MODELS,
            desc="broadband noise model of the noise constraint: 'gill_lee' (paper eq. 22) or "
            "'bpm' (blade-section BPM self-noise, docs theory/acoustics 'BPM broadband model')",
        )
        self.options.declare(
            "footprint",
            default=False,
            types=bool,
            desc="add the noise of the condition's departure legs at the vehicle's noise-footprint "
            "observers (lpc_mdo.groups.footprint; a hover or transition point)",
        )
