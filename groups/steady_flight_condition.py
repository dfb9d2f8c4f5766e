"""Climb, cruise and descent: VLM and parasite drag, the BEM pusher and its motor, trim."""

from lpc_mdo.groups.condition_base import ConditionGroup
from lpc_mdo.groups.condition_builders import (
    add_aerodynamics,
    add_atmosphere,
    add_equations_of_motion,
    add_power,
    add_pusher,
    declare_aero_options,
)
from lpc_mdo.vehicle.condition_kinds import SteadyFlightKind


class SteadyFlightCondition(ConditionGroup):
    """
    Climb, cruise or descent (kind ``steady``): VLM + parasite drag, the BEM pusher and trim.

    The pusher by BEM has its motor; trim is in F_x, F_z, M_y (paper Sec. IV; docs:
    theory/dynamics). Pitch, elevator and pusher speed are inputs (design variables). With
    ``stability`` (default: the condition named by the vehicle's ``mission.cruise_condition``)
    the neutral point and the static margin (paper eq. 30) are added.
    """

    declaration = SteadyFlightKind

    def initialize(self):
        super().initialize()
        declare_aero_options(self)
        self.options.declare(
            "stability",
            default=None,
            types=bool,
            allow_none=True,
            desc="add the neutral point and static margin (None: in the "
            "vehicle's cruise condition)",
        )

    def setup(self):
        vehicle = self.options["vehicle"]
        condition = vehicle.condition(self.options["condition"])
        add_atmosphere(self, condition, vehicle)
        stability = self.options["stability"]
        if stability is None:
            stability = SteadyFlightKind.has_stability(vehicle, condition)
        add_aerodynamics(
            self, vehicle, condition, self.options["wing_zero_lift_angle"], stability=stability
        )
        add_pusher(self, vehicle)
        add_power(self, {"pusher": 1})
        add_equations_of_motion(self, ["aero", "drag", "pusher"], forces_only=["drag"])
