"""Hover and one-engine-inoperative hover: BEM lift rotors, motors, trim and rotor noise."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.dynamics.control_reserve import ControlReserveComp
from lpc_mdo.groups.acoustics import RotorNoiseGroup
from lpc_mdo.groups.condition_base import ConditionGroup
from lpc_mdo.groups.condition_builders import (
    add_atmosphere,
    add_equations_of_motion,
    add_lift_rotors,
    add_power,
)
from lpc_mdo.groups.footprint import add_footprint_noise
from lpc_mdo.vehicle.condition_kinds import HoverKind, noise_group_name, num_lift_pairs

#: KS scale (rad/s**2) of a control axis without a required acceleration: the available
#: acceleration is reported to within ln(2 num_rotors)/rho times it (6e-4 rad/s**2 for 8 rotors).
UNREQUIRED_SCALE = 0.01


class HoverCondition(ConditionGroup):
    """
    Hover (and one-engine-inoperative hover): BEM lift rotors, their motors, trim and noise.

    The noise, in hover, is that at the paper's observer (paper Sec. IV; docs: theory/dynamics
    and theory/acoustics).

    Kinds ``hover`` and ``oei``. The failed rotor of an OEI case (``failed_rotor`` in the vehicle
    file) is left out; the working rotors have their own speeds (one speed group each), while in
    hover the mirror-symmetric pairs share theirs. Trim: all six accelerations are outputs; the
    Table 6 rows are w_dot, p_dot, q_dot in hover and v_dot, w_dot, p_dot, q_dot, r_dot in OEI
    (hover p_dot and OEI v_dot vanish for every design: degenerate rows). The body is level
    (``pitch`` = 0): the lift-rotor thrust axes are body-fixed and u_dot is not a hover trim row,
    so a pitched hover is a VehicleSpecError.

    The noise model (without a failed rotor) takes from the vehicle each observer
    (``noise_observer[k]`` distance, elevation and azimuth -> ``observer_distance``,
    ``observer_elevation``, ``observer_azimuth`` of the group ``noise``, then
    ``noise_2_observer_distance``, ... of ``noise_2``, ...; docs theory/acoustics 'Observer and
    constraint') and each lift rotor's section t/c (``lift_rotors[i].thickness_to_chord``, a
    named airfoil's own or the file's key -> ``lift_thickness_to_chord``, of the thickness
    noise).

    Outputs: ``linear_acceleration``, ``angular_acceleration`` (1, 3); ``electrical_power``
    (1,); ``lift_tip_mach``, ``lift_helical_tip_mach``, ``lift_figure_of_merit``,
    ``lift_motor_torque_margin``, ``lift_motor_em_torque`` (num_lift, 1); ``control_acceleration``
    (3,): the roll, pitch and yaw acceleration the running rotors can add within their motors'
    peak torque (:class:`~lpc_mdo.components.dynamics.control_reserve.ControlReserveComp`); with
    acoustics ``total_spl_a`` (dBA).
    """

    declaration = HoverKind

    def initialize(self):
        super().initialize()
        self.options.declare(
            "acoustics",
            default=None,
            types=bool,
            allow_none=True,
            desc="add the noise model (None: without a failed rotor)",
        )

    def setup(self):
        vehicle = self.options["vehicle"]
        condition = vehicle.condition(self.options["condition"])
        # A Vehicle built in code (dataclasses.replace) skips the file validation: check again.
        HoverKind.check(vehicle.conditions.index(condition), condition, vehicle)
        failed = condition.failed_rotor
        self.active_rotors = HoverKind.active_lift_rotors(vehicle, condition)
        rotors = [vehicle.lift_rotors[i] for i in self.active_rotors]
        if failed >= 0:
            groups, num_groups = list(range(len(rotors))), len(rotors)
        else:
            groups, num_groups = [r.pair for r in rotors], num_lift_pairs(rotors)
        self.speed_groups = num_groups

        add_atmosphere(self, condition, vehicle)
        add_lift_rotors(self, vehicle, rotors, groups, num_groups, edgewise=False)
        self.set_input_defaults("velocity", np.zeros((1, 3)), units="m/s")
        add_power(self, {"lift": len(rotors)})
        add_equations_of_motion(self, ["lift"])
        self.set_input_defaults("pitch", np.array([condition.pitch]), units="rad")  # 0, checked
        required = np.array(vehicle.constraints.min_control_acceleration)
        self.add_subsystem(
            "control_reserve",
            ControlReserveComp(
                spin_direction=[r.spin_direction for r in rotors],
                thrust_axis=[r.thrust_axis for r in rotors],
                # KS relative to the required accelerations; where none is required, to
                # UNREQUIRED_SCALE (the reported value then within ln(2 n)/rho of it)
                acceleration_scale=tuple(np.where(required > 0.0, required, UNREQUIRED_SCALE)),
            ),
            promotes_inputs=[
                ("thrust", "lift_thrust"),
                ("torque", "lift_torque"),
                ("torque_margin", "lift_motor_torque_margin"),
                ("hub_position", "lift_hub_position"),
                "cg",
                "inertia",
            ],
            promotes_outputs=["control_acceleration"],
        )

        acoustics = self.options["acoustics"]
        if acoustics is None:
            acoustics = failed < 0
        if acoustics:
            nrad = self.options["num_radial"]
            na = len(rotors)
            # (rotor, node = 0, station) of the BEM -> (rotor, station, azimuth = 0) of the
            # acoustics: a fancy index of the source shaped like the target.
            rotor, station = np.meshgrid(np.arange(na), np.arange(nrad), indexing="ij")
            reshape = om.slicer[rotor[..., None], 0 * rotor[..., None], station[..., None]]
            # One noise group per observer: 'noise' (its levels promoted: total_spl_a, ...)
            # and 'noise_2', 'noise_3', ... for further observers (levels under their paths,
            # e.g. noise_2.total_spl_a), each with its own observer inputs.
            for k, observer in enumerate(vehicle.noise_observer):
                name = noise_group_name(k)
                first = k == 0
                prefix = "" if first else f"{name}_"
                self.add_subsystem(
                    name,
                    RotorNoiseGroup(
                        num_rotors=na,
                        num_radial=nrad,
                        num_azimuth=1,
                        num_blades=[r.num_blades for r in rotors],
                        hub_radius_ratio=rotors[0].hub_radius_ratio,
                        load_input="sectional",
                        rotation_direction=tuple(float(r.spin_direction) for r in rotors),
                        broadband_model=self.options["broadband_model"],
                    ),
                    promotes_inputs=[
                        ("radius", "lift_radius"),
                        ("hub_position", "lift_hub_position"),
                        "density",
                        "speed_of_sound",
                        *(
                            (f"observer_{q}", f"{prefix}observer_{q}")
                            for q in ("distance", "elevation", "azimuth")
                        ),
                        ("thickness_to_chord", "lift_thickness_to_chord"),
                        ("chord", "lift_chord"),
                    ],
                    promotes_outputs=["total_spl_a", "total_spl", "rotor_spl_a"] if first else [],
                )
                for q, value, units in (
                    ("distance", observer.distance, "m"),
                    ("elevation", observer.elevation, "rad"),
                    ("azimuth", observer.azimuth_or_aft, "rad"),
                ):
                    self.set_input_defaults(f"{prefix}observer_{q}", np.array([value]), units=units)
                for load in ("thrust_per_span", "drag_per_span", "inflow_angle"):
                    self.connect(f"lift_rotors.{load}", f"{name}.{load}", src_indices=reshape)
                if self.options["broadband_model"] == "gill_lee":  # it takes the thrust
                    self.connect(
                        "lift_thrust",
                        f"{name}.thrust",
                        src_indices=np.arange(na),
                        flat_src_indices=True,
                    )
                self.connect(
                    "lift_rotor_rpm",
                    f"{name}.rpm",
                    src_indices=np.arange(na),
                    flat_src_indices=True,
                )
            # Each rotor's section t/c at every acoustic station (rotor, station).
            thickness = [vehicle.lift_rotors[i].thickness_to_chord for i in self.active_rotors]
            self.set_input_defaults(
                "lift_thickness_to_chord", np.repeat(np.array(thickness)[:, None], nrad, axis=1)
            )
        if self.options["footprint"]:  # the departure's noise at the footprint's observers
            add_footprint_noise(self, vehicle, condition.name, flying=False)
