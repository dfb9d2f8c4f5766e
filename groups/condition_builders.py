"""Subsystems that several design-condition groups share: atmosphere, rotors, motors, aerodynamics.

The condition groups (``hover_condition``, ``transition_condition``, ``steady_flight_condition``,
``structural_condition``) build themselves from these functions; each adds its subsystems to a
group and promotes the names the conditions share (see :mod:`lpc_mdo.groups.condition_base`).
"""

import warnings

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.drag_buildup import (
    LPC_LEAKAGE_PROTUBERANCE,
    DragBuildupComp,
)
from lpc_mdo.components.aero.section_stall import SectionStallRatioComp
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
from lpc_mdo.components.motor.parameters import DESIGN_OUTPUTS
from lpc_mdo.components.motor.shaft_torque import ShaftTorqueComp
from lpc_mdo.components.rotor.rotor_speed import RotorSpeedComp
from lpc_mdo.groups.bem_rotor import BEMRotorGroup
from lpc_mdo.groups.motor import MotorOperationGroup
from lpc_mdo.groups.pitt_peters_rotor import PittPetersRotorGroup
from lpc_mdo.groups.vehicle import motor_parameters
from lpc_mdo.groups.vehicle_drag import SIZED_DRAG_INPUTS, lpc_drag_components
from lpc_mdo.groups.vlm import VLMGroup, lpc_vlm_surfaces
from lpc_mdo.vehicle.condition_kinds import is_wing_load_case, wing_stall_speed_fraction

#: KS parameter of ``wing_stall_ratio_ks``, the smooth maximum of the 2 x 26 section lift ratios
#: of a wing-borne condition (paper eq. 7): it exceeds the largest ratio by at most
#: ln(52)/rho = 0.020; at the reference vehicle's wing-borne conditions by 0.003-0.011
#: (measured: the strips next to the most loaded one are within a few percent of it; rho = 100
#: gave up to 0.025), i.e. 1.5 % of the 0.625 limit, on the safe side (docs
#: theory/aerodynamics 'Section lift limit').
WING_STALL_KS_RHO = 200.0


def declare_aero_options(group):
    """Declare the aerodynamics options of a wing-borne condition: zero-lift angle, panel counts."""
    group.options.declare(
        "wing_zero_lift_angle",
        default=0.0,
        types=float,
        desc="sectional zero-lift angle of the wing airfoil, rad",
    )
    group.options.declare("wing_panels", default=26, types=int, desc="wing VLM panels")
    group.options.declare("tail_panels", default=8, types=int, desc="tail VLM panels")


def add_motors(group, vehicle, prefix, num_motors, rpm):
    """Motors of the ``prefix`` rotors (torque floored at idle), promoted as ``{prefix}_motor_*``.

    Inputs ``{prefix}_torque`` (rotor shaft torque), ``rpm`` (each rotor's speed),
    ``{prefix}_motor_length`` and the motor designs ``{prefix}_motor_{name}`` for ``name`` in
    :data:`~lpc_mdo.groups.motor.DESIGN_OUTPUTS` (peak torque, resistance, inductances, ...:
    the rows of the vehicle group's ``motor_design``, so each design is sized once, not once per
    condition); outputs ``{prefix}_motor_input_power``, ``_em_torque``,
    ``_torque_margin`` (against the smooth minimum of the peak and the voltage-limited torque),
    ``_current_margin`` (1 - abs(I)/I_pk) and ``_voltage_margin`` (1 - abs(U)/V_lim: below 0
    the MTPA operating point needs more than the voltage limit, i.e. flux weakening, which the
    motor model does not have; the constraint kind ``voltage_margin`` keeps it >= 0).
    """
    group.add_subsystem(
        f"{prefix}_shaft",
        ShaftTorqueComp(num_motors=num_motors),
        promotes_inputs=[("rotor_torque", f"{prefix}_torque")],
    )
    motors = group.add_subsystem(
        f"{prefix}_motors",
        MotorOperationGroup(
            num_motors=num_motors, num_nodes=1, parameters=motor_parameters(vehicle)
        ),
        promotes_inputs=[("length", f"{prefix}_motor_length"), ("rotor_rpm", rpm)]
        + [(name, f"{prefix}_motor_{name}") for name in DESIGN_OUTPUTS],
        promotes_outputs=[
            (name, f"{prefix}_motor_{name}")
            for name in (
                "input_power",
                "em_torque",
                "torque_margin",
                "voltage_margin",
                "current_margin",
            )
        ],
    )
    group.connect(f"{prefix}_shaft.motor_load_torque", f"{prefix}_motors.rotor_torque")
    one_factorization(motors)


# OpenMDAO lists every group with a DirectSolver as "treated as atomic" when it sorts the
# model into pre-, in- and post-optimization systems; the rotor and motor groups lie on the
# optimization's paths anyway, so the list (one line per group and problem) says nothing a
# user can act on. Only that message is silenced.
warnings.filterwarnings(
    "ignore",
    message="The following groups have a nonlinear solver that computes gradients",
    module="openmdao.utils.relevance",
)


def one_factorization(rotors_or_motors):
    """
    Give a condition's rotor or motor group one sparse LU of its assembled Jacobian.

    Nearly every adjoint right-hand side of the optimization (the trim rows, the motor margins,
    the state of charge, the tip Mach numbers) passes back through a condition's rotors and
    motors; a ``DirectSolver`` turns each such pass into one back-substitution instead of a
    visit to each of the group's components, 20 % of the total derivative time of the full
    model (docs theory/optimization 'Speed of an evaluation and of the derivatives'). The
    groups are small and feed-forward, so the factors have little fill; exact, like the
    block passes they replace.
    """
    rotors_or_motors.linear_solver = om.DirectSolver(assemble_jac=True)


def add_atmosphere(group, condition, vehicle):
    """Add the atmosphere at the condition's altitude on the mission's day (ISA + dT), promoted."""
    offset = vehicle.mission.isa_offset
    group.add_subsystem(
        "atmosphere", AtmosphereComp(num_nodes=1, temperature_offset=offset), promotes=["*"]
    )
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


def add_lift_rotors(group, vehicle, rotors, speed_groups, num_groups, edgewise, roll_yaw=False):
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
    # Nothing in a condition reads the edgewise rotors' sectional loads (the noise is the hover
    # condition's, by BEM); left out, they do not lengthen every adjoint transfer.
    kwargs = {"num_azimuth": opts["num_azimuth"], "sectional_loads": False} if edgewise else {}
    lift_rotors = group.add_subsystem(
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
            ("helical_tip_mach", "lift_helical_tip_mach"),
            ("figure_of_merit", "lift_figure_of_merit"),
            ("total_force", "lift_force"),
            ("total_moment", "lift_moment"),
            *([("edgewise_advance_ratio", "lift_advance_ratio")] if edgewise else []),
            *([] if edgewise else [("blade_stall_ratio_ks", "lift_blade_stall_ratio_ks")]),
        ],
    )
    one_factorization(lift_rotors)
    add_motors(group, vehicle, "lift", na, "lift_rotor_rpm")
    group.set_input_defaults("lift_radius", np.array([r.radius for r in rotors]), units="m")
    group.set_input_defaults(
        "lift_hub_position", np.array([r.hub_position for r in rotors]), units="m"
    )


def add_pusher(group, vehicle):
    """Add the pusher by BEM with its motor, promoted as ``pusher_*``."""
    opts = group.options
    pusher = vehicle.pusher
    polar = opts["rotor_polar"] if opts["pusher_polar"] is None else opts["pusher_polar"]
    pusher_rotor = group.add_subsystem(
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
            ("helical_tip_mach", "pusher_helical_tip_mach"),
            ("total_force", "pusher_force"),
            ("total_moment", "pusher_moment"),
            ("blade_stall_ratio_ks", "pusher_blade_stall_ratio_ks"),
        ],
    )
    one_factorization(pusher_rotor)
    add_motors(group, vehicle, "pusher", 1, "pusher_rpm")
    group.set_input_defaults("pusher_radius", np.array([pusher.radius]), units="m")
    group.set_input_defaults("pusher_hub_position", np.array([pusher.hub_position]), units="m")


def add_aerodynamics(
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
    load_case = is_wing_load_case(condition)
    _add_wing_stall(
        group,
        vehicle.wing.airfoil,
        opts["wing_panels"],
        wing_stall_speed_fraction(vehicle.constraints, load_case),
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
        connected = name in ("wing_area", "fuselage_length") or name in SIZED_DRAG_INPUTS
        if name not in renames and not connected:
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


def _add_wing_stall(group, airfoil, num_strips, speed_fraction):
    """Each wing strip's c_l over its section's c_l,max and c_l,min, and their KS maximum.

    The section maxima are taken at ``speed_fraction`` times the condition's Re and M
    (:func:`~lpc_mdo.vehicle.condition_kinds.wing_stall_speed_fraction`).

    Outputs ``wing_stall_ratio`` (1, 2 ns) and ``wing_stall_ratio_ks`` (1,), the constraint of
    kind ``wing_stall`` (docs theory/aerodynamics 'Section lift limit'). The strips' Reynolds
    and Mach numbers are those the VLM's lift-dependent drag already computes.
    """
    group.add_subsystem(
        "wing_stall",
        SectionStallRatioComp(
            num_nodes=1,
            num_span_panels=num_strips,
            airfoil=airfoil,
            speed_fraction=float(speed_fraction),
        ),
        promotes_inputs=[("sectional_cl", "wing_sectional_cl")],
        promotes_outputs=[("stall_ratio", "wing_stall_ratio")],
    )
    for name in ("reynolds", "mach"):
        group.connect(f"vlm.wing_strip_flow.strip_{name}", f"wing_stall.{name}")
    group.add_subsystem(
        "wing_stall_ks",
        KSComp(width=2 * num_strips, rho=WING_STALL_KS_RHO),
        promotes_inputs=[("g", "wing_stall_ratio")],
        promotes_outputs=[("KS", "wing_stall_ratio_ks")],
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
    """Lattice loads plus the fuselage couple and the tail efficiency (docs theory/dynamics).

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


def add_equations_of_motion(group, sources, forces_only=(), load_factor=1.0, path_axes=False):
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


def add_power(group, motors):
    """Add the electrical power of the motor sets ``motors`` (prefix -> number of motors)."""
    group.add_subsystem("power", TotalPowerComp(motors=motors), promotes=["*"])
