"""The design-condition groups of the lift-plus-cruise problem (paper Sec. IV, Fig. 11).

Each condition of the vehicle file is one OpenMDAO Group, built by the class of its ``kind``
(:mod:`lpc_mdo.groups.condition_kinds`), with its atmosphere, kinematics, the disciplines it needs
and the six-degree-of-freedom equations of motion, whose accelerations are the trim constraints
(paper eqs. 29, 34). Vehicle-level quantities (meshes, hub positions, radii, blade control points,
motor lengths, mass properties) are inputs, which each class declares
(:class:`~lpc_mdo.groups.condition_base.ConditionGroup`) and ``groups/lpc.py`` connects.

Kinds and their groups (the reference vehicle's conditions in parentheses):

- ``hover``, ``oei``: :class:`HoverCondition` (BEM lift rotors and motors, trim; without a failed
  rotor also the acoustics; hover, oei_1 .. oei_4);
- ``transition``: :class:`TransitionCondition` (VLM + drag, Pitt–Peters lift rotors, BEM pusher,
  all motors, prescribed speed, pitch and acceleration; transition_1 .. transition_5);
- ``steady``: :class:`SteadyFlightCondition` (VLM + drag, BEM pusher and its motor; the vehicle's
  ``mission.cruise_condition`` adds the static margin; climb, cruise, descent);
- ``structural``: :class:`StructuralCondition` (VLM at the load factor, wing-box beam, stress and
  buckling; plus_3g, minus_1g).

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
``lift_motor_em_torque``/``pusher_motor_em_torque``, and the discipline outputs.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.drag_buildup import (
    LPC_LEAKAGE_PROTUBERANCE,
    DragBuildupComp,
    lpc_drag_components,
)
from lpc_mdo.components.aero.tail_efficiency import TailEfficiencyComp
from lpc_mdo.components.aero.vlm_lattice import lattice_of
from lpc_mdo.components.aero.wing_zero_lift_moment import (
    WingZeroLiftMomentComp,
    wing_zero_lift_moment_options,
)
from lpc_mdo.components.atmosphere import AtmosphereComp
from lpc_mdo.components.dynamics.body_pitching_moment import BodyPitchingMomentComp
from lpc_mdo.components.dynamics.eom import EquationsOfMotionComp
from lpc_mdo.components.dynamics.force_sum import ForceSumComp, VectorSumComp
from lpc_mdo.components.dynamics.path_acceleration import PathAccelerationComp
from lpc_mdo.components.dynamics.stability_derivatives import (
    AnglePerturbationComp,
    StabilityDerivativeComp,
)
from lpc_mdo.components.dynamics.static_margin import NeutralPointComp, StaticMarginComp
from lpc_mdo.components.energy.power import TotalPowerComp
from lpc_mdo.components.geometry.blade import BLADE_OUTPUTS
from lpc_mdo.components.kinematics import KinematicsComp
from lpc_mdo.components.ks import KSComp
from lpc_mdo.components.motor.shaft_torque import ShaftTorqueComp
from lpc_mdo.components.rotor.rotor_speed import RotorSpeedComp
from lpc_mdo.components.structures.displacement import VerticalDisplacementComp
from lpc_mdo.components.structures.load_transfer import DisplacementTransferComp
from lpc_mdo.components.structures.mesh_deformation import MeshDeformationComp
from lpc_mdo.groups.acoustics import RotorNoiseGroup
from lpc_mdo.groups.beam import BoxBeamGroup
from lpc_mdo.groups.bem_rotor import BEMRotorGroup
from lpc_mdo.groups.condition_base import (
    ConditionConstraint,
    ConditionGroup,
    ConditionVariable,
    TrimRow,
    condition_layout,
    linear_trim_ref,
)
from lpc_mdo.groups.motor import DESIGN_OUTPUTS, MotorOperationGroup
from lpc_mdo.groups.pitt_peters_rotor import PittPetersRotorGroup
from lpc_mdo.groups.vehicle import motor_parameters
from lpc_mdo.groups.vlm import VLMGroup, lpc_vlm_surfaces
from lpc_mdo.vehicle import VehicleSpecError

#: Rotor section t/c of the thickness noise when a rotor's airfoil is a polar file (NACA 0012).
DEFAULT_ROTOR_THICKNESS_TO_CHORD = 0.12

_ZERO = (lambda x: x == 0, "0")
_ONE = (lambda x: x == 1, "1")
_POSITIVE = (lambda x: x > 0, "> 0")
_NO_FAILURE = (lambda x: x == -1, "-1")


def _declare_aero(group):
    group.options.declare(
        "wing_zero_lift_angle",
        default=0.0,
        types=float,
        desc="sectional zero-lift angle of the wing airfoil, rad",
    )
    group.options.declare("wing_panels", default=26, types=int, desc="wing VLM panels")
    group.options.declare("tail_panels", default=8, types=int, desc="tail VLM panels")


def num_lift_pairs(lift_rotors):
    """Count the mirror-symmetric lift-rotor pairs (rotor groups of the per-group variables)."""
    return len({r.pair for r in lift_rotors})


def _rotor_group_rows(vehicle, active):
    """Rows of the per-rotor-group design variables (pair index) of the lift rotors ``active``."""
    return np.array([vehicle.lift_rotors[i].pair for i in active])


def _lift_inputs(vehicle, active):
    """Vehicle-level inputs of the lift rotors ``active`` (indices into ``lift_rotors``)."""
    active = np.asarray(active)
    rows = _rotor_group_rows(vehicle, active)
    return (
        ("lift_rotor_radius", "lift_radius", active),
        *((f"blade_{name}", f"lift_{name}", _rows(name, rows)) for name in BLADE_OUTPUTS),
        ("lift_hub_position", "lift_hub_position", om.slicer[active, :]),
        ("motor_length", "lift_motor_length", rows),
        *_motor_design_inputs("lift", rows),
    )


def _pusher_inputs(vehicle):
    """Vehicle-level inputs of the pusher (its row follows the lift pairs)."""
    row = num_lift_pairs(vehicle.lift_rotors)
    return (
        ("rotor_radius", "pusher_radius", [row]),
        *((f"blade_{name}", f"pusher_{name}", _rows(name, [row])) for name in BLADE_OUTPUTS),
        ("pusher_hub_position", "pusher_hub_position", om.slicer[np.arange(3)[None, :],]),
        ("motor_length", "pusher_motor_length", [row]),
        *_motor_design_inputs("pusher", [row]),
    )


def _rows(name, rows):
    """Source indices of the ``rows`` (rotor groups) of a vehicle ``blade_*`` output."""
    return rows if name == "hub_radius" else om.slicer[rows, :]


def _motor_design_inputs(prefix, rows):
    """Vehicle-level motor designs (``motor_{name}``, one per rotor group): ``rows`` of them."""
    return tuple((f"motor_{name}", f"{prefix}_motor_{name}", rows) for name in DESIGN_OUTPUTS)


#: Vehicle-level inputs of the aerodynamics (VLM meshes, reference quantities, drag build-up).
_AERO_INPUTS = tuple(
    (name, name, None)
    for name in (
        "wing_mesh",
        "horizontal_tail_mesh",
        "wing_area",
        "wing_mac",
        "htail_area",
        "htail_mac",
        "fuselage_length",
        "body_moment_slope",
        "body_moment_zero_lift",
    )
)


#: Wing-box inputs of a structural condition (vehicle-level outputs of the same name).
_WING_BOX_INPUTS = (
    "wing_box_nodes",
    "box_width",
    "box_height",
    "top_skin_thickness",
    "bottom_skin_thickness",
    "front_spar_thickness",
    "rear_spar_thickness",
    "top_skin_radius",
    "bottom_skin_radius",
)


def _speed_variable(count, description):
    """Lift-rotor speeds per speed group as a (1, count) input ``lift_rpm`` of the condition."""
    return ConditionVariable("lift_rpm", (1, count), (count,), "rpm", description)


_PUSHER_RPM = ConditionVariable("pusher_rpm", (1, 1), (1,), "rpm", "pusher speed")
_ELEVATOR = ConditionVariable("elevator", (1,), (1,), "rad", "h-tail deflection")
_PITCH = ConditionVariable("pitch", (1,), (1,), "rad", "aircraft pitch", initial_from="pitch")

#: KS parameter of the structural conditions' stress aggregate ``stress_ratio_ks`` when no
#: structural ``ks_rho`` is given (the stress constraint of the problems). The KS value exceeds
#: the largest of the 40 ratios by at most ln(40)/rho = 3.7 % (paper eq. 7), less where the
#: other ratios are well below it.
STRESS_KS_RHO = 100.0


def _add_motors(group, vehicle, prefix, num_motors, rpm):
    """Motors of the ``prefix`` rotors (torque floored at idle), promoted as ``{prefix}_motor_*``.

    Inputs ``{prefix}_torque`` (rotor shaft torque), ``rpm`` (each rotor's speed),
    ``{prefix}_motor_length`` and the motor designs ``{prefix}_motor_{name}`` for ``name`` in
    :data:`~lpc_mdo.groups.motor.DESIGN_OUTPUTS` (peak torque, resistance, inductances, ...:
    the rows of the vehicle group's ``motor_design``, so each design is sized once, not once per
    condition); outputs ``{prefix}_motor_input_power``, ``_em_torque``,
    ``_torque_margin`` and ``_voltage_margin`` (1 - abs(U)/V_lim: below 0
    the MTPA operating point needs more than the voltage limit, i.e. flux weakening, which the
    motor model does not have; the problem kind ``voltage_margin`` constrains it).
    """
    group.add_subsystem(
        f"{prefix}_shaft",
        ShaftTorqueComp(num_motors=num_motors),
        promotes_inputs=[("rotor_torque", f"{prefix}_torque")],
    )
    group.add_subsystem(
        f"{prefix}_motors",
        MotorOperationGroup(
            num_motors=num_motors, num_nodes=1, parameters=motor_parameters(vehicle)
        ),
        promotes_inputs=[("length", f"{prefix}_motor_length"), ("rotor_rpm", rpm)]
        + [(name, f"{prefix}_motor_{name}") for name in DESIGN_OUTPUTS],
        promotes_outputs=[
            (name, f"{prefix}_motor_{name}")
            for name in ("input_power", "em_torque", "torque_margin", "voltage_margin")
        ],
    )
    group.connect(f"{prefix}_shaft.motor_load_torque", f"{prefix}_motors.rotor_torque")


def _add_atmosphere(group, condition):
    group.add_subsystem("atmosphere", AtmosphereComp(num_nodes=1), promotes=["*"])
    group.set_input_defaults("altitude", np.array([condition.altitude]), units="m")


def roll_yaw_mixing(rotors):
    """
    Mixing of the roll and yaw speed differentials onto the rotors, (num_rotors, 2).

    Roll: the left rotors (y < 0) turn half the roll differential faster, the right ones half
    of it slower; yaw: likewise the rotors that spin +1 against those that spin -1. Each
    differential is then the mean speed of one set minus that of the other, and every
    mirror-symmetric pair keeps its mean speed.
    """
    side = [1.0 if r.hub_position[1] < 0.0 else -1.0 for r in rotors]
    spin = [float(r.spin_direction) for r in rotors]
    return 0.5 * np.column_stack([side, spin])


def _add_lift_rotors(group, vehicle, rotors, speed_groups, num_groups, edgewise, roll_yaw=False):
    """Lift rotors (BEM or Pitt–Peters) with their speeds and motors, promoted as ``lift_*``.

    With ``roll_yaw`` the rotor speeds also take the roll and yaw differentials, input
    ``roll_yaw_rpm`` (1, 2) (:func:`roll_yaw_mixing`).
    """
    na = len(rotors)
    opts = group.options
    promoted = [("group_speed", "lift_rpm")]
    if roll_yaw:
        promoted.append(("mixer_speed", "roll_yaw_rpm"))
    group.add_subsystem(
        "lift_speed",
        RotorSpeedComp(
            group=speed_groups,
            num_groups=num_groups,
            mixing=roll_yaw_mixing(rotors) if roll_yaw else None,
        ),
        promotes_inputs=promoted,
        promotes_outputs=[("rpm", "lift_rotor_rpm")],
    )
    rotor_cls = PittPetersRotorGroup if edgewise else BEMRotorGroup
    kwargs = {"num_azimuth": opts["num_azimuth"]} if edgewise else {}
    group.add_subsystem(
        "lift_rotors",
        rotor_cls(
            rotors=list(rotors),
            num_nodes=1,
            num_radial=opts["num_radial"],
            polar=opts["rotor_polar"],
            blade_geometry="inputs",
            **kwargs,
        ),
        promotes_inputs=[
            ("radius", "lift_radius"),
            *((name, f"lift_{name}") for name in BLADE_OUTPUTS),
            ("rpm", "lift_rotor_rpm"),
            ("hub_position", "lift_hub_position"),
            "velocity",
            "density",
            "speed_of_sound",
            "dynamic_viscosity",
        ],
        promotes_outputs=[
            ("thrust", "lift_thrust"),
            ("torque", "lift_torque"),
            ("power", "lift_power"),
            ("tip_mach", "lift_tip_mach"),
            ("figure_of_merit", "lift_figure_of_merit"),
            ("total_force", "lift_force"),
            ("total_moment", "lift_moment"),
        ],
    )
    _add_motors(group, vehicle, "lift", na, "lift_rotor_rpm")
    group.set_input_defaults("lift_radius", np.array([r.radius for r in rotors]), units="m")
    group.set_input_defaults(
        "lift_hub_position", np.array([r.hub_position for r in rotors]), units="m"
    )


def _add_pusher(group, vehicle):
    """Add the pusher by BEM with its motor, promoted as ``pusher_*``."""
    opts = group.options
    pusher = vehicle.pusher
    polar = opts["rotor_polar"] if opts["pusher_polar"] is None else opts["pusher_polar"]
    group.add_subsystem(
        "pusher",
        BEMRotorGroup(
            rotors=[pusher],
            num_nodes=1,
            num_radial=opts["num_radial"],
            polar=polar,
            blade_geometry="inputs",
        ),
        promotes_inputs=[
            ("radius", "pusher_radius"),
            *((name, f"pusher_{name}") for name in BLADE_OUTPUTS),
            ("rpm", "pusher_rpm"),
            ("hub_position", "pusher_hub_position"),
            "velocity",
            "density",
            "speed_of_sound",
            "dynamic_viscosity",
        ],
        promotes_outputs=[
            ("thrust", "pusher_thrust"),
            ("torque", "pusher_torque"),
            ("power", "pusher_power"),
            ("efficiency", "pusher_efficiency"),
            ("total_force", "pusher_force"),
            ("total_moment", "pusher_moment"),
        ],
    )
    _add_motors(group, vehicle, "pusher", 1, "pusher_rpm")
    group.set_input_defaults("pusher_radius", np.array([pusher.radius]), units="m")
    group.set_input_defaults("pusher_hub_position", np.array([pusher.hub_position]), units="m")


def _add_aerodynamics(
    group, vehicle, condition, wing_zero_lift_angle, stability=False, wing_mesh="wing_mesh"
):
    """Kinematics, wing + tail VLM and the parasite-drag build-up.

    Outputs ``aero_force``/``aero_moment`` (about the body origin) and ``drag_force``; with
    ``stability`` a second VLM at alpha + delta gives the neutral point and static margin.
    """
    opts = group.options
    surfaces = lpc_vlm_surfaces(opts["wing_panels"], opts["tail_panels"])
    vlm_inputs = [
        ("wing_mesh", wing_mesh),
        "horizontal_tail_mesh",
        "speed",
        "density",
        ("reference_area", "wing_area"),
        ("horizontal_tail_deflection", "elevator"),
        "wing_zero_lift_angle",
        "reynolds_per_length",
        "mach",
    ]
    # The wing's profile drag grows with lift: its strips' c_d increment over the polar's
    # minimum (the minimum is the build-up's wing friction), docs theory/aerodynamics
    # 'Lift-dependent profile drag'.
    lift_dependent = {"wing": vehicle.wing.airfoil}
    group.add_subsystem("kinematics", KinematicsComp(num_nodes=1), promotes=["*"])
    group.add_subsystem(
        "vlm",
        VLMGroup(surfaces=surfaces, num_nodes=1, lift_dependent_drag=lift_dependent),
        promotes_inputs=vlm_inputs + ["angle_of_attack"],
        promotes_outputs=[
            ("force", "vlm_force"),
            ("moment", "vlm_moment"),
            "lift",
            "CL",
            "induced_drag",
            "wing_sectional_cl",
            "panel_forces",
            "force_points",
        ],
    )
    group.set_input_defaults(
        "wing_zero_lift_angle", np.full((1, opts["wing_panels"]), wing_zero_lift_angle), units="rad"
    )
    # alpha_0w of the body moment: the section zero-lift angle less the root incidence.
    body_options = {"wing_zero_lift_angle": float(wing_zero_lift_angle) - vehicle.wing.incidence}
    tail_options = _tail_efficiency_options(vehicle, surfaces)
    group.add_subsystem(
        "wing_camber_moment",
        WingZeroLiftMomentComp(
            num_nodes=1, **wing_zero_lift_moment_options(vehicle, wing_zero_lift_angle)
        ),
        promotes=["*"],
    )
    _add_body_moment(group, body_options, tail_options, "angle_of_attack", "vlm", "")
    group.set_input_defaults("elevator", np.zeros(1), units="rad")

    components, values = lpc_drag_components(vehicle)
    renames = {
        "wing_mean_aerodynamic_chord": "wing_mac",
        "horizontal_tail_area": "htail_area",
        "horizontal_tail_mean_aerodynamic_chord": "htail_mac",
        "reference_area": "wing_area",
    }
    group.add_subsystem(
        "drag",
        DragBuildupComp(
            components=components, num_nodes=1, allowance_fraction=LPC_LEAKAGE_PROTUBERANCE
        ),
        promotes_inputs=[
            (k, renames.get(k, f"drag_{k}"))
            for k in values
            if k not in ("wing_area", "fuselage_length")
        ]
        + [
            "wing_area",
            "fuselage_length",
            "speed",
            "density",
            "dynamic_viscosity",
            "speed_of_sound",
            "angle_of_attack",
        ],
        promotes_outputs=[
            ("parasite_drag_force", "drag_force"),
            "parasite_drag",
            "CD0",
            "drag_breakdown",
        ],
    )
    for name, value in values.items():
        if name not in renames and name not in ("wing_area", "fuselage_length"):
            group.set_input_defaults(f"drag_{name}", value)

    group.set_input_defaults("speed", np.array([condition.speed]), units="m/s")
    group.set_input_defaults("pitch", np.array([condition.pitch]), units="rad")
    group.set_input_defaults(
        "flight_path_angle", np.array([condition.flight_path_angle]), units="rad"
    )

    if stability:
        delta = 1e-3
        group.add_subsystem("perturbation", AnglePerturbationComp(delta=delta), promotes=["*"])
        group.add_subsystem(
            "vlm_perturbed",
            VLMGroup(surfaces=surfaces, num_nodes=1, lift_dependent_drag=lift_dependent),
            promotes_inputs=vlm_inputs + [("angle_of_attack", "perturbed_angle_of_attack")],
            promotes_outputs=[
                ("force", "perturbed_vlm_force"),
                ("moment", "perturbed_vlm_moment"),
            ],
        )
        _add_body_moment(
            group,
            body_options,
            tail_options,
            "perturbed_angle_of_attack",
            "vlm_perturbed",
            "perturbed_",
        )
        group.add_subsystem(
            "stability_derivatives",
            StabilityDerivativeComp(delta=delta),
            promotes_inputs=[
                ("force", "aero_force"),
                ("moment", "aero_moment"),
                ("perturbed_force", "perturbed_aero_force"),
                ("perturbed_moment", "perturbed_aero_moment"),
            ],
            promotes_outputs=["normal_force_slope", "pitching_moment_slope"],
        )
        nose_to_tail = (0.0, -1.5 * vehicle.fuselage.length)
        group.add_subsystem("neutral_point", NeutralPointComp(bracket=nose_to_tail), promotes=["*"])
        group.add_subsystem(
            "static_margin",
            StaticMarginComp(),
            promotes_inputs=["neutral_point", "cg_x", ("mean_aerodynamic_chord", "wing_mac")],
            promotes_outputs=["static_margin"],
        )


def _tail_efficiency_options(vehicle, surfaces):
    """TailEfficiencyComp options: the tail's panels in the lattice and the file's eta_t."""
    lattice = lattice_of(surfaces)
    start = surfaces[0].num_chord_panels * surfaces[0].num_span_panels  # wing first
    return {
        "num_panels": lattice.num_panels,
        "tail_panels": (start, lattice.num_panels),
        "dynamic_pressure_ratio": float(vehicle.stability.tail_dynamic_pressure_ratio),
    }


def _add_body_moment(group, body_options, tail_options, alpha, vlm, prefix):
    """Lattice loads plus the fuselage couple and the tail efficiency (issue 16 item 4).

    ``{prefix}aero_force`` = ``{prefix}vlm_force`` + tail correction and ``{prefix}aero_moment``
    = ``{prefix}vlm_moment`` + fuselage couple + tail correction + the wing's cm0 couple,
    about the body origin.
    """
    group.add_subsystem(
        f"{prefix}body_moment",
        BodyPitchingMomentComp(num_nodes=1, **body_options),
        promotes_inputs=[
            ("angle_of_attack", alpha),
            "density",
            "speed",
            "body_moment_slope",
            "body_moment_zero_lift",
        ],
        promotes_outputs=[("body_moment", f"{prefix}body_moment")],
    )
    group.add_subsystem(
        f"{prefix}tail_efficiency",
        TailEfficiencyComp(num_nodes=1, **tail_options),
        promotes_inputs=["force_points"],
        promotes_outputs=[
            ("tail_force_correction", f"{prefix}tail_force_correction"),
            ("tail_moment_correction", f"{prefix}tail_moment_correction"),
        ],
    )
    panel_forces = "panel_forces" if vlm == "vlm" else f"{vlm}.panel_forces"
    group.connect(panel_forces, f"{prefix}tail_efficiency.panel_forces")
    group.connect(f"{vlm}.viscous_panel_forces", f"{prefix}tail_efficiency.viscous_panel_forces")
    for name, units, parts in (
        ("force", "N", ("vlm_force", "tail_force_correction")),
        ("moment", "N*m", ("vlm_moment", "body_moment", "tail_moment_correction")),
    ):
        names = [f"{prefix}{p}" for p in parts]
        if name == "moment":  # the camber couple: independent of alpha, one for both solves
            names.append("wing_camber_moment")
        group.add_subsystem(
            f"{prefix}aero_{name}_sum",
            VectorSumComp(output_name=f"{prefix}aero_{name}", input_names=names, units=units),
            promotes=["*"],
        )


def _add_equations_of_motion(group, sources, forces_only=(), load_factor=1.0, path_axes=False):
    """Force sum and 6-DoF equations of motion; ``path_axes``: linear rows in flight-path axes.

    With ``path_axes`` the condition's ``linear_acceleration`` is the body-axis acceleration
    turned into flight-path axes (:class:`PathAccelerationComp`), so that a prescribed
    acceleration along the path is a constant target whatever the pitch.
    """
    group.add_subsystem(
        "loads", ForceSumComp(sources=sources, forces_only=forces_only), promotes=["*"]
    )
    group.add_subsystem(
        "eom",
        EquationsOfMotionComp(num_nodes=1),
        promotes_inputs=[
            ("mass", "gross_mass"),
            "cg",
            "inertia",
            "force",
            "moment",
            "pitch",
            "velocity",
            "load_factor",
        ],
        promotes_outputs=[
            ("linear_acceleration", "body_acceleration" if path_axes else "linear_acceleration"),
            "angular_acceleration",
        ],
    )
    group.set_input_defaults("load_factor", np.array([load_factor]))
    if path_axes:
        group.add_subsystem(
            "path_axes",
            PathAccelerationComp(num_nodes=1),
            promotes_inputs=["body_acceleration", "pitch", "flight_path_angle"],
            promotes_outputs=[("path_acceleration", "linear_acceleration")],
        )


def _add_power(group, motors):
    group.add_subsystem("power", TotalPowerComp(motors=motors), promotes=["*"])


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

    The noise model (without a failed rotor) takes from the vehicle the observer
    (``noise_observer.distance``, ``noise_observer.elevation`` -> ``observer_distance``,
    ``observer_elevation``; the azimuth stays aft, 180 deg) and each lift rotor's section t/c
    (``lift_rotors[i].airfoil`` -> ``lift_thickness_to_chord``, of the thickness noise).

    Outputs: ``linear_acceleration``, ``angular_acceleration`` (1, 3); ``electrical_power``
    (1,); ``lift_tip_mach``, ``lift_figure_of_merit``, ``lift_motor_torque_margin``,
    ``lift_motor_em_torque`` (num_lift, 1); with acoustics ``total_spl_a`` (dBA).
    """

    field_rules = {
        "hover": {
            "speed": _ZERO,
            "failed_rotor": _NO_FAILURE,
            "acceleration": _ZERO,
            "load_factor": _ONE,
        },
        "oei": {
            "speed": _ZERO,
            "failed_rotor": (lambda x: x >= 0, "a lift-rotor index (>= 0)"),
            "acceleration": _ZERO,
            "load_factor": _ONE,
        },
    }

    def initialize(self):
        super().initialize()
        self.options.declare(
            "acoustics",
            default=None,
            types=bool,
            allow_none=True,
            desc="add the noise model (None: without a failed rotor)",
        )

    @classmethod
    def check(cls, index, condition, vehicle):
        super().check(index, condition, vehicle)
        if condition.pitch != 0.0:
            raise VehicleSpecError(
                f"'conditions[{index}].pitch_deg' = {np.degrees(condition.pitch):.6g} deg is not "
                f"allowed: must be 0 in {condition.kind!r} conditions (the hover model holds the "
                f"body level; the lift-rotor thrust axes are body-fixed and u_dot is not a hover "
                f"trim constraint)"
            )
        failed = condition.failed_rotor
        if failed >= len(vehicle.lift_rotors):
            raise VehicleSpecError(
                f"'conditions[{index}].failed_rotor' = {failed} is out of range: must be -1 or a "
                f"lift-rotor index in [0, {len(vehicle.lift_rotors) - 1}]"
            )
        if failed >= 0:
            for j, other in enumerate(vehicle.conditions[:index]):
                if other.failed_rotor == failed:
                    raise VehicleSpecError(
                        f"'conditions[{index}].failed_rotor' = {failed} repeats "
                        f"'conditions[{j}].failed_rotor'; each OEI condition must fail a "
                        f"different lift rotor"
                    )

    @staticmethod
    def active_lift_rotors(vehicle, condition):
        """Return the indices into ``vehicle.lift_rotors`` of the rotors that run."""
        return [i for i in range(len(vehicle.lift_rotors)) if i != condition.failed_rotor]

    @classmethod
    def variables(cls, vehicle, condition):
        if condition.failed_rotor < 0:
            n = num_lift_pairs(vehicle.lift_rotors)
            return (_speed_variable(n, "lift-rotor speed per pair"),)
        n = len(vehicle.lift_rotors) - 1
        return (
            _speed_variable(
                n, "speed of the working lift rotors, in lift_rotors order (the failed one skipped)"
            ),
        )

    @classmethod
    def vehicle_inputs(cls, vehicle, condition):
        return super().vehicle_inputs(vehicle, condition) + _lift_inputs(
            vehicle, cls.active_lift_rotors(vehicle, condition)
        )

    @classmethod
    def trim_rows(cls, vehicle, condition):
        g = linear_trim_ref()
        if condition.failed_rotor < 0:
            # p_dot: the pairs share speeds and spin in opposite senses, so it vanishes.
            return (TrimRow("w", ref=g), TrimRow("p", degenerate=True), TrimRow("q"))
        # v_dot: no side force acts in hover (rotor thrust only, no edgewise flow).
        return (
            TrimRow("v", ref=g, degenerate=True),
            TrimRow("w", ref=g),
            TrimRow("p"),
            TrimRow("q"),
            TrimRow("r"),
        )

    @classmethod
    def constraints(cls, vehicle, condition, bounds):
        if condition.failed_rotor >= 0:
            return ()
        limits = vehicle.constraints
        active = cls.active_lift_rotors(vehicle, condition)
        pairs = [vehicle.lift_rotors[i].pair for i in active]
        one_per_pair = [pairs.index(p) for p in sorted(set(pairs))]
        return (
            ConditionConstraint("noise", "total_spl_a", {"upper": limits.max_noise, "ref": 10.0}),
            ConditionConstraint(
                "tip_mach",
                "lift_tip_mach",
                {"indices": one_per_pair, "flat_indices": True, "upper": limits.max_tip_mach},
            ),
        )

    @classmethod
    def motor_sets(cls, vehicle, condition):
        return {"lift": tuple(cls.active_lift_rotors(vehicle, condition))}

    def setup(self):
        vehicle = self.options["vehicle"]
        condition = vehicle.condition(self.options["condition"])
        # A Vehicle built in code (dataclasses.replace) skips the file validation: check again.
        self.check(vehicle.conditions.index(condition), condition, vehicle)
        failed = condition.failed_rotor
        self.active_rotors = self.active_lift_rotors(vehicle, condition)
        rotors = [vehicle.lift_rotors[i] for i in self.active_rotors]
        if failed >= 0:
            groups, num_groups = list(range(len(rotors))), len(rotors)
        else:
            groups, num_groups = [r.pair for r in rotors], num_lift_pairs(rotors)
        self.speed_groups = num_groups

        _add_atmosphere(self, condition)
        _add_lift_rotors(self, vehicle, rotors, groups, num_groups, edgewise=False)
        self.set_input_defaults("velocity", np.zeros((1, 3)), units="m/s")
        _add_power(self, {"lift": len(rotors)})
        _add_equations_of_motion(self, ["lift"])
        self.set_input_defaults("pitch", np.array([condition.pitch]), units="rad")  # 0, checked

        acoustics = self.options["acoustics"]
        if acoustics is None:
            acoustics = failed < 0
        if acoustics:
            nrad = self.options["num_radial"]
            na = len(rotors)
            self.add_subsystem(
                "noise",
                RotorNoiseGroup(
                    num_rotors=na,
                    num_radial=nrad,
                    num_azimuth=1,
                    num_blades=[r.num_blades for r in rotors],
                    hub_radius_ratio=rotors[0].hub_radius_ratio,
                    load_input="sectional",
                    rotation_direction=tuple(float(r.spin_direction) for r in rotors),
                ),
                promotes_inputs=[
                    ("radius", "lift_radius"),
                    ("hub_position", "lift_hub_position"),
                    "density",
                    "speed_of_sound",
                    "observer_distance",
                    "observer_elevation",
                    ("thickness_to_chord", "lift_thickness_to_chord"),
                    ("chord", "lift_chord"),
                ],
                promotes_outputs=["total_spl_a", "total_spl", "rotor_spl_a"],
            )
            observer = vehicle.noise_observer
            self.set_input_defaults("observer_distance", np.array([observer.distance]), units="m")
            self.set_input_defaults(
                "observer_elevation", np.array([observer.elevation]), units="rad"
            )
            # Each rotor's section t/c at every acoustic station (rotor, station).
            thickness = [_rotor_thickness_to_chord(vehicle, i) for i in self.active_rotors]
            self.set_input_defaults(
                "lift_thickness_to_chord", np.repeat(np.array(thickness)[:, None], nrad, axis=1)
            )
            # (rotor, node = 0, station) of the BEM -> (rotor, station, azimuth = 0) of the
            # acoustics: a fancy index of the source shaped like the target.
            rotor, station = np.meshgrid(np.arange(na), np.arange(nrad), indexing="ij")
            reshape = om.slicer[rotor[..., None], 0 * rotor[..., None], station[..., None]]
            for name in ("thrust_per_span", "drag_per_span", "inflow_angle"):
                self.connect(f"lift_rotors.{name}", f"noise.{name}", src_indices=reshape)
            self.connect(
                "lift_thrust", "noise.thrust", src_indices=np.arange(na), flat_src_indices=True
            )
            self.connect(
                "lift_rotor_rpm", "noise.rpm", src_indices=np.arange(na), flat_src_indices=True
            )


def _rotor_thickness_to_chord(vehicle, index):
    """Section t/c of ``vehicle.lift_rotors[index]`` for the thickness noise.

    A named airfoil gives its t/c (``lpc_mdo.vehicle.AIRFOILS``); a user polar file has none, so
    the noise model then uses that of NACA 0012 (the reference rotor section), with a warning
    naming the field.
    """
    rotor = vehicle.lift_rotors[index]
    if rotor.thickness_to_chord is not None:
        return rotor.thickness_to_chord
    om.issue_warning(
        f"'lift_rotors[{index}].airfoil' = {rotor.airfoil!r} is a polar file, "
        f"which gives no thickness: the thickness noise uses t/c = "
        f"{DEFAULT_ROTOR_THICKNESS_TO_CHORD} (NACA 0012)"
    )
    return DEFAULT_ROTOR_THICKNESS_TO_CHORD


class SteadyFlightCondition(ConditionGroup):
    """
    Climb, cruise or descent (kind ``steady``): VLM + parasite drag, the BEM pusher and trim.

    The pusher by BEM has its motor; trim is in F_x, F_z, M_y (paper Sec. IV; docs:
    theory/dynamics). Pitch, elevator and pusher speed are inputs (design variables). With
    ``stability`` (default: the condition named by the vehicle's ``mission.cruise_condition``)
    the neutral point and the static margin (paper eq. 30) are added.
    """

    field_rules = {
        "steady": {
            "speed": _POSITIVE,
            "failed_rotor": _NO_FAILURE,
            "acceleration": _ZERO,
            "load_factor": _ONE,
        }
    }

    def initialize(self):
        super().initialize()
        _declare_aero(self)
        self.options.declare(
            "stability",
            default=None,
            types=bool,
            allow_none=True,
            desc="add the neutral point and static margin (None: in the "
            "vehicle's cruise condition)",
        )

    @staticmethod
    def has_stability(vehicle, condition):
        """Whether the condition evaluates the static margin: the vehicle's cruise condition."""
        return vehicle.mission.cruise_condition == condition.name

    @classmethod
    def variables(cls, vehicle, condition):
        return (_PUSHER_RPM, _PITCH, _ELEVATOR)

    @classmethod
    def vehicle_inputs(cls, vehicle, condition):
        inputs = super().vehicle_inputs(vehicle, condition) + _pusher_inputs(vehicle) + _AERO_INPUTS
        if cls.has_stability(vehicle, condition):
            inputs += (("cg", "cg_x", [0]),)
        return inputs

    @classmethod
    def trim_rows(cls, vehicle, condition):
        g = linear_trim_ref()
        return (TrimRow("u", ref=g), TrimRow("w", ref=g), TrimRow("q"))

    @classmethod
    def constraints(cls, vehicle, condition, bounds):
        if not cls.has_stability(vehicle, condition):
            return ()
        return (
            ConditionConstraint(
                "static_margin",
                "static_margin",
                {"lower": vehicle.constraints.min_static_margin, "ref": 0.1},
            ),
        )

    @classmethod
    def motor_sets(cls, vehicle, condition):
        return {"pusher": (0,)}

    def setup(self):
        vehicle = self.options["vehicle"]
        condition = vehicle.condition(self.options["condition"])
        _add_atmosphere(self, condition)
        stability = self.options["stability"]
        if stability is None:
            stability = self.has_stability(vehicle, condition)
        _add_aerodynamics(
            self, vehicle, condition, self.options["wing_zero_lift_angle"], stability=stability
        )
        _add_pusher(self, vehicle)
        _add_power(self, {"pusher": 1})
        _add_equations_of_motion(self, ["aero", "drag", "pusher"], forces_only=["drag"])


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
    pitch, with the lift rotors at their lowest speed (measured 2026-12-04; docs
    theory/dynamics 'Design conditions').

    The rotors turn at their pair's ``lift_rpm`` (1, 4; the paper's per-pair speed)
    plus the roll and yaw differentials ``roll_yaw_rpm`` (1, 2; not in the paper; left
    minus right and spin +1 minus spin -1 rotor speed, :func:`roll_yaw_mixing`): the roll and
    yaw trim, since the pusher's torque reaction rolls the vehicle and the h-tail deflects
    symmetrically.
    """

    field_rules = {
        "transition": {"speed": _POSITIVE, "failed_rotor": _NO_FAILURE, "load_factor": _ONE}
    }

    def initialize(self):
        super().initialize()
        _declare_aero(self)
        self.options.declare(
            "num_azimuth",
            default=25,
            types=int,
            lower=3,
            desc="azimuthal stations of the Pitt-Peters rotors",
        )

    @classmethod
    def variables(cls, vehicle, condition):
        n = num_lift_pairs(vehicle.lift_rotors)
        return (
            _speed_variable(n, "lift-rotor speed, mean of the pair; columns: pairs"),
            ConditionVariable(
                "roll_yaw_rpm",
                (1, 2),
                (2,),
                "rpm",
                "lift-rotor speed differentials; columns: roll (left, y < 0, "
                "minus right rotors), yaw (spin +1 minus spin -1 rotors)",
            ),
            _PUSHER_RPM,
            _PITCH,
            _ELEVATOR,
        )

    @classmethod
    def vehicle_inputs(cls, vehicle, condition):
        return (
            super().vehicle_inputs(vehicle, condition)
            + _lift_inputs(vehicle, range(len(vehicle.lift_rotors)))
            + _pusher_inputs(vehicle)
            + _AERO_INPUTS
        )

    @classmethod
    def trim_rows(cls, vehicle, condition):
        g = linear_trim_ref()
        # Flight-path axes (the linear rows of a transition, PathAccelerationComp): the
        # prescribed acceleration is along the path whatever the pitch. v_dot: only the rotors'
        # net side force under the yaw differential moves it, with no trim variable of its own:
        # a degenerate row.
        return (
            TrimRow("u", condition.acceleration, ref=g),
            TrimRow("v", ref=g, degenerate=True),
            TrimRow("w", ref=g),
            TrimRow("p"),
            TrimRow("q"),
            TrimRow("r"),
        )

    @classmethod
    def constraints(cls, vehicle, condition, bounds):
        """
        Each lift rotor's own speed within the bounds of its pair's mean speed (linear).

        With the roll/yaw differentials a rotor turns at its pair's mean speed +- half of each
        differential, so the design-variable bounds alone let it reach 0 rpm (100 rpm mean -
        50 - 50), where the motor model stalls: an SLSQP line search of the baseline problem
        drove a rotor to 7 rpm and ended in an AnalysisError (measured 2026-12-01). The speeds
        are linear in the design variables, so these are linear constraints.
        """
        entry = condition_layout(vehicle).entry(condition.name, "lift_rpm")
        dv = vehicle.design_variables[entry.design_variable]
        lower, upper = (
            bounds(entry.design_variable)
            if bounds is not None
            else (dv.lower_array, dv.upper_array)
        )
        pairs = [r.pair for r in vehicle.lift_rotors]
        lower = np.ravel(lower)[entry.flat_indices][pairs]
        upper = np.ravel(upper)[entry.flat_indices][pairs]
        ref = dv.ref
        return (
            ConditionConstraint(
                "rotor_speed",
                "lift_rotor_rpm",
                {"lower": lower, "upper": upper, "ref": ref, "units": "rpm", "linear": True},
            ),
        )

    @classmethod
    def motor_sets(cls, vehicle, condition):
        return {"lift": tuple(range(len(vehicle.lift_rotors))), "pusher": (0,)}

    def setup(self):
        vehicle = self.options["vehicle"]
        condition = vehicle.condition(self.options["condition"])
        rotors = vehicle.lift_rotors
        self.active_rotors = list(range(len(rotors)))
        self.speed_groups = num_lift_pairs(rotors)
        _add_atmosphere(self, condition)
        _add_aerodynamics(self, vehicle, condition, self.options["wing_zero_lift_angle"])
        _add_lift_rotors(
            self,
            vehicle,
            rotors,
            [r.pair for r in rotors],
            self.speed_groups,
            edgewise=True,
            roll_yaw=True,
        )
        _add_pusher(self, vehicle)
        _add_power(self, {"lift": len(rotors), "pusher": 1})
        _add_equations_of_motion(
            self, ["aero", "drag", "lift", "pusher"], forces_only=["drag"], path_axes=True
        )


class StructuralCondition(ConditionGroup):
    """
    +3g or -1g pull-up/push-over: VLM at the load factor, trim in F_z only, and the wing-box beam.

    The beam is that of the right half wing, loaded by the VLM panel forces plus its own inertia at
    the load factor, with stress and curved-panel buckling (paper Sec. III.D, IV; docs
    theory/structures). Pitch is an input (design variable); the elevator is held at zero. With
    ``ks_rho`` the stress ratios, the buckling ratios (all bays but the tip bay) and the vertical
    tip-ward displacement in the direction of the load (-w at positive, +w at negative load factor)
    are also aggregated by KS (paper eq. 7): ``stress_ratio_ks``, ``top_skin_buckling_ratio_ks``,
    ``bottom_skin_buckling_ratio_ks``, ``displacement_ks`` (m). The beam's material is the vehicle's
    ``[material]``: inputs ``material_youngs_modulus``, ``material_shear_modulus``,
    ``material_density`` (the box's own weight), ``material_poisson_ratio`` and
    ``material_allowable_stress``.
    """

    power_output = None
    field_rules = {
        "structural": {
            "speed": _POSITIVE,
            "failed_rotor": _NO_FAILURE,
            "acceleration": _ZERO,
            "load_factor": (lambda x: x != 0, "non-zero"),
        }
    }

    def initialize(self):
        super().initialize()
        _declare_aero(self)
        self.options.declare(
            "ks_rho",
            default=None,
            types=(int, float),
            allow_none=True,
            desc="KS parameter of the structural aggregates (None: none)",
        )
        self.options.declare(
            "coupling",
            default="one_way",
            values=("one_way", "two_way"),
            desc="one-way (loads only) or two-way (the beam deforms the VLM "
            "wing mesh; block Gauss-Seidel)",
        )

    @staticmethod
    def compressed_skin(condition):
        """Return the skin in compression: ``top`` under a positive load factor, else ``bottom``."""
        return "top" if condition.load_factor > 0 else "bottom"

    @classmethod
    def variables(cls, vehicle, condition):
        return (_PITCH,)

    @classmethod
    def vehicle_inputs(cls, vehicle, condition):
        return (
            super().vehicle_inputs(vehicle, condition)
            + _AERO_INPUTS
            + tuple((name, name, None) for name in _WING_BOX_INPUTS)
        )

    @classmethod
    def trim_rows(cls, vehicle, condition):
        return (TrimRow("w", ref=linear_trim_ref(condition.load_factor)),)

    @classmethod
    def constraints(cls, vehicle, condition, bounds):
        bays = list(range(vehicle.wing_box.num_bays - 1))  # all bays but the tip bay
        skin = cls.compressed_skin(condition)
        return (
            ConditionConstraint(
                "buckling",
                f"{skin}_skin_buckling_ratio",
                {
                    "indices": bays,
                    "flat_indices": True,
                    "upper": vehicle.constraints.max_buckling_ratio,
                },
            ),
            # Not in the paper's full problem (its optimum is 16 % overstressed, Sec. V): the
            # KS aggregate of every von Mises stress ratio (sigma / material.allowable_stress,
            # the paper's 350 MPa) of the box, issue 20 item 1.
            ConditionConstraint("stress", "stress_ratio_ks", {"upper": 1.0}),
        )

    def setup(self):
        vehicle = self.options["vehicle"]
        condition = vehicle.condition(self.options["condition"])
        n_wing = self.options["wing_panels"]
        right = np.arange(n_wing // 2, n_wing)  # wing panels with y > 0 (one chord-wise row)
        nodes = vehicle.wing_box.num_bays + 1
        _add_atmosphere(self, condition)
        two_way = self.options["coupling"] == "two_way"
        if two_way:
            self._add_mesh_deformation(nodes, n_wing)
        _add_aerodynamics(
            self,
            vehicle,
            condition,
            self.options["wing_zero_lift_angle"],
            wing_mesh="deformed_wing_mesh" if two_way else "wing_mesh",
        )
        _add_equations_of_motion(
            self, ["aero", "drag"], forces_only=["drag"], load_factor=condition.load_factor
        )
        rho = self.options["ks_rho"]
        self.add_subsystem(
            "beam",
            BoxBeamGroup(
                num_nodes=nodes,
                num_aero_points=right.size,
                ks_rho=rho,
                stress_ks_rho=STRESS_KS_RHO if rho is None else None,
            ),
            promotes_inputs=[
                ("nodes", "wing_box_nodes"),
                "box_width",
                "box_height",
                "top_skin_thickness",
                "bottom_skin_thickness",
                "front_spar_thickness",
                "rear_spar_thickness",
                "top_skin_radius",
                "bottom_skin_radius",
                "load_factor",
                "pitch",
            ],
            promotes_outputs=[
                "von_mises_stress",
                "top_skin_buckling_ratio",
                "bottom_skin_buckling_ratio",
                "displacements",
                "rotations",
                "stress_ratio",
            ],
        )
        self.connect(
            "force_points", "beam.aero_points", src_indices=om.slicer[n_wing // 2 : n_wing, :]
        )
        self.connect(
            "panel_forces", "beam.aero_forces", src_indices=om.slicer[0, n_wing // 2 : n_wing, :]
        )
        material = vehicle.material
        for name, units in (
            ("youngs_modulus", "Pa"),
            ("shear_modulus", "Pa"),
            ("density", "kg/m**3"),
            ("poisson_ratio", None),
            ("allowable_stress", "Pa"),
        ):
            self.promotes("beam", inputs=[(name, f"material_{name}")])
            self.set_input_defaults(f"material_{name}", getattr(material, name), units=units)
        self.promotes("beam", outputs=["stress_ratio_ks"])
        if rho is not None:
            self.promotes(
                "beam",
                outputs=[
                    "top_skin_buckling_ratio_ks",
                    "bottom_skin_buckling_ratio_ks",
                ],
            )
            sign = -1.0 if condition.load_factor > 0 else 1.0
            self.add_subsystem(
                "displacement_sign", VerticalDisplacementComp(num_nodes=nodes, sign=sign)
            )
            self.add_subsystem(
                "displacement_ks",
                KSComp(width=nodes, rho=rho * 10.0, units="m"),
                promotes_outputs=[("KS", "displacement_ks")],
            )
            self.connect("displacements", "displacement_sign.displacements")
            self.connect("displacement_sign.vertical_displacement", "displacement_ks.g")
        if two_way:
            # The loop VLM -> beam -> mesh -> VLM: Newton on the coupled system (each implicit
            # component still solves itself first); a failure to converge is an AnalysisError
            # so an optimizer can back off.
            self.nonlinear_solver = om.NewtonSolver(
                solve_subsystems=True,
                maxiter=30,
                atol=1e-8,
                rtol=1e-8,
                iprint=-1,
                err_on_non_converge=True,
            )
            self.linear_solver = om.DirectSolver()

    def _add_mesh_deformation(self, nodes, n_wing):
        """Beam displacements -> right-half wing mesh nodes -> mirrored deformed mesh."""
        nx, ny = 2, n_wing + 1
        half = ny // 2
        chord, span = np.meshgrid(np.arange(nx), np.arange(half, ny), indexing="ij")
        points = chord.size
        self.add_subsystem(
            "displacement_transfer",
            DisplacementTransferComp(num_nodes=nodes, num_points=points),
            promotes_inputs=[("nodes", "wing_box_nodes"), "displacements", "rotations"],
        )
        xyz = np.arange(3)[np.newaxis, :]
        self.connect(
            "wing_mesh",
            "displacement_transfer.aero_points",
            src_indices=om.slicer[chord.reshape(-1, 1), span.reshape(-1, 1), xyz],
        )
        self.add_subsystem(
            "mesh_deformation",
            MeshDeformationComp(num_chord_nodes=nx, num_span_nodes=ny),
            promotes_inputs=[("mesh", "wing_mesh")],
            promotes_outputs=[("deformed_mesh", "deformed_wing_mesh")],
        )
        self.connect(
            "displacement_transfer.aero_displacements", "mesh_deformation.right_displacements"
        )
