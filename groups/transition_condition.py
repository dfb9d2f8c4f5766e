"""A quasi-steady transition point: VLM and drag, Pitt-Peters lift rotors, BEM pusher, trim."""

from lpc_mdo.groups.condition_base import ConditionGroup
from lpc_mdo.groups.condition_builders import (
    add_aerodynamics,
    add_atmosphere,
    add_equations_of_motion,
    add_lift_rotors,
    add_power,
    add_pusher,
    declare_aero_options,
)
from lpc_mdo.groups.footprint import add_footprint_noise
from lpc_mdo.vehicle.condition_kinds import TransitionKind, num_lift_pairs


class TransitionCondition(ConditionGroup):
    """
    A quasi-steady transition point: prescribed speed and acceleration, VLM + drag and rotors.

    The rotors are the Pitt–Peters lift rotors and the BEM pusher, with all nine motors (paper
    Sec. IV; docs theory/dynamics 'Design conditions'). The full problem constrains the
    acceleration along the flight path to the prescribed dV/dt and the path-normal, lateral and
    angular accelerations to zero; ``linear_acceleration`` is in flight-path axes
    (:class:`~lpc_mdo.components.dynamics.path_acceleration.PathAccelerationComp`).

    The pitch is a trim variable (``pitch``; the vehicle file's ``pitch_deg`` is its initial
    value). The paper prescribes it from a transition trajectory flown by its 3724 kg vehicle;
    a vehicle of another weight cannot fly that attitude schedule: the itemised reference
    (3067 kg) lifts more than its weight on the wing alone at points 2-5 at the prescribed
    pitch, with the lift rotors at their lowest speed (measured; docs
    theory/dynamics 'Design conditions').

    The rotors turn at their pair's ``lift_rpm`` (1, 4; the paper's per-pair speed)
    plus the roll and yaw differentials ``roll_yaw_rpm`` (1, 2; not in the paper; left
    minus right and spin +1 minus spin -1 rotor speed, :func:`roll_yaw_mixing`): the roll and
    yaw trim, since the pusher's torque reaction rolls the vehicle and the h-tail deflects
    symmetrically.
    """

    declaration = TransitionKind

    def initialize(self):
        super().initialize()
        declare_aero_options(self)
        self.options.declare(
            "num_azimuth",
            default=25,
            types=int,
            lower=3,
            desc="azimuthal stations of the Pitt-Peters rotors",
        )

    def setup(self):
        vehicle = self.options["vehicle"]
        condition = vehicle.condition(self.options["condition"])
        rotors = vehicle.lift_rotors
        self.active_rotors = list(range(len(rotors)))
        self.speed_groups = num_lift_pairs(rotors)
        add_atmosphere(self, condition, vehicle)
        add_aerodynamics(self, vehicle, condition, self.options["wing_zero_lift_angle"])
        add_lift_rotors(
            self,
            vehicle,
            rotors,
            [r.pair for r in rotors],
            self.speed_groups,
            edgewise=True,
            roll_yaw=True,
        )
        add_pusher(self, vehicle)
        add_power(self, {"lift": len(rotors), "pusher": 1})
        add_equations_of_motion(
            self, ["aero", "drag", "lift", "pusher"], forces_only=["drag"], path_axes=True
        )
        if self.options["footprint"]:
            add_footprint_noise(self, vehicle, condition.name, flying=True)
