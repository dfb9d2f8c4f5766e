"""The condition kinds of the lift-plus-cruise vehicle file and their registry.

Each kind is one :class:`~lpc_mdo.vehicle.condition_contract.ConditionKind` subclass: the data of
its contract (field rules, design variables, vehicle inputs, trim rows, constraints, motors; paper
Table 6), registered under its kind names in
:data:`~lpc_mdo.vehicle.condition_contract.CONDITION_KINDS` when this module is imported (the
package ``lpc_mdo.vehicle`` imports it). The groups that build conditions of these kinds are in
``lpc_mdo.groups`` (one module per kind); a new kind is a declaration here (or in user code)
plus its group, registered together with
:func:`lpc_mdo.groups.condition_kinds.register_condition_kind`.

Kinds (the reference vehicle's conditions in parentheses): ``hover`` and ``oei``
(:class:`HoverKind`; hover, oei_1 .. oei_4), ``transition`` (:class:`TransitionKind`;
transition_1 .. transition_5), ``steady`` (:class:`SteadyFlightKind`; climb, cruise, descent),
``structural`` (:class:`StructuralKind`; plus_3g, minus_1g).
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.geometry.blade import BLADE_OUTPUTS
from lpc_mdo.components.motor.parameters import DESIGN_OUTPUTS
from lpc_mdo.vehicle.condition_contract import (
    ConditionConstraint,
    ConditionKind,
    ConditionVariable,
    TrimRow,
    linear_trim_ref,
    register_kind,
)
from lpc_mdo.vehicle.condition_layout import condition_layout
from lpc_mdo.vehicle.schema import VehicleSpecError

__all__ = [
    "MIN_HOVER_ROTORS",
    "HoverKind",
    "SteadyFlightKind",
    "StructuralKind",
    "TransitionKind",
    "is_wing_load_case",
    "noise_group_name",
    "num_lift_pairs",
    "blade_stall_limit",
    "wing_stall_limit",
    "wing_stall_speed_fraction",
]

_ZERO = (lambda x: x == 0, "0")
_ONE = (lambda x: x == 1, "1")
_POSITIVE = (lambda x: x > 0, "> 0")
_NO_FAILURE = (lambda x: x == -1, "-1")


#: Fewest working lift rotors that hover trimmed: vertical force, roll, pitch and yaw are four
#: independent demands on the rotor speeds (three thrusts leave one unbalanced).
MIN_HOVER_ROTORS = 4


def noise_group_name(k):
    """Return the name of the hover noise group of observer ``k``: noise, noise_2, ..."""
    return "noise" if k == 0 else f"noise_{k + 1}"


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


def _lift_tip_mach(limits):
    """Declare each running lift rotor's helical tip Mach <= ``max_lift_rotor_tip_mach``."""
    return ConditionConstraint(
        "tip_mach", "lift_helical_tip_mach", {"upper": limits.max_lift_rotor_tip_mach}
    )


def _pusher_tip_mach(limits):
    """Declare the pusher's helical tip Mach number <= ``max_pusher_tip_mach``."""
    return ConditionConstraint(
        "tip_mach", "pusher_helical_tip_mach", {"upper": limits.max_pusher_tip_mach}
    )


def blade_stall_limit(limits):
    """
    Return the upper limit of a rotor's ``blade_stall_ratio_ks``: ``blade_stall_angle_fraction``.

    Every blade station's angle of attack within that fraction of its section's stall angles
    (docs theory/rotors 'Blade stall limit'); a vehicle file without the key keeps the stations
    within the stall angles themselves (1), the range of the blade-element model.
    """
    fraction = limits.blade_stall_angle_fraction
    return 1.0 if fraction is None else fraction


def _blade_stall(limits, prefix):
    """Declare the KS of the ``prefix`` rotors' stations' alpha / alpha_stall <= its limit."""
    return ConditionConstraint(
        "blade_stall", f"{prefix}_blade_stall_ratio_ks", {"upper": blade_stall_limit(limits)}
    )


def wing_stall_limit(limits, load_case=False):
    """
    Return the upper limit of a wing-borne condition's section lift ratio ``wing_stall_ratio_ks``.

    The wing stalls when its most loaded section reaches ``wing_stall_lift_fraction`` (kappa)
    of the section's maximum lift coefficient: a structural load case (``load_case``) may reach
    that line, a 1-g condition flies at least ``min_stall_speed_ratio`` (k) times the stall
    speed, so its sections stay within kappa / k^2 (docs theory/aerodynamics 'Section lift
    limit').
    """
    kappa = limits.wing_stall_lift_fraction
    return kappa if load_case else kappa / limits.min_stall_speed_ratio**2


def wing_stall_speed_fraction(limits, load_case=False):
    """
    Return the speed, as a fraction of a condition's, at which its section maxima are taken.

    A 1-g condition's limit kappa / k^2 says that at V / k (its stall speed when V = k V_S) the
    critical section reaches kappa c_l,max: taken there, c_l,max has the Reynolds and Mach
    numbers of that speed (1 / k); a load case's at its own speed (1).
    """
    return 1.0 if load_case else 1.0 / limits.min_stall_speed_ratio


def is_wing_load_case(condition):
    """Whether a wing-borne condition is a structural load case (kind ``structural``)."""
    return condition.kind == "structural"


def _wing_stall(limits, load_case=False):
    """Declare the KS of the wing sections' c_l / c_l,max (both stalls) <= its limit."""
    return ConditionConstraint(
        "wing_stall", "wing_stall_ratio_ks", {"upper": wing_stall_limit(limits, load_case)}
    )


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
        # the landing-gear tyres of the drag build-up, sized from W_dg (groups/vehicle_drag.py)
        "drag_main_wheels_frontal_area",
        "drag_nose_wheel_frontal_area",
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
#: A steady condition's speed where its ``speed_rule`` is "optimized": the optimizer's, not a
#: trim variable (lpc_mdo.components.energy.flight_time turns its distances into times).
_SPEED = ConditionVariable(
    "speed", (1,), (1,), "m/s", "flight speed", initial_from="speed", trim=False
)

#: KS parameter of the structural conditions' stress aggregate ``stress_ratio_ks`` when no
#: structural ``ks_rho`` is given (the stress constraint of the problems). The KS value exceeds
#: the largest of the 40 ratios by at most ln(40)/rho = 3.7 % (paper eq. 7), less where the


class HoverKind(ConditionKind):
    """
    Hover and one-engine-inoperative hover (kinds ``hover`` and ``oei``).

    The failed rotor of an OEI case (``failed_rotor``) is left out; the working rotors have their
    own speeds (one speed group each), while in hover the mirror-symmetric pairs share theirs.
    Trim rows of Table 6: w_dot, p_dot, q_dot in hover and v_dot, w_dot, p_dot, q_dot, r_dot in
    OEI (hover p_dot and OEI v_dot vanish for every design: degenerate rows). The body is level
    (``pitch`` = 0): the lift-rotor thrust axes are body-fixed and u_dot is not a hover trim row,
    so a pitched hover is a VehicleSpecError. Hover without a failed rotor declares the noise and
    tip-Mach constraints (tip Mach <= ``max_tip_mach`` per pair, the paper's); an OEI case the tip
    Mach number of each working rotor <= ``max_lift_rotor_tip_mach``; hover and OEI declare the
    control reserve (:meth:`control_reserve`) and the lift rotors' blade stations within their
    stall limit (:func:`blade_stall_limit`).
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
        working = len(vehicle.lift_rotors) - (failed >= 0)
        if working < MIN_HOVER_ROTORS:
            raise VehicleSpecError(
                f"'conditions[{index}].failed_rotor' = {failed} is not allowed: "
                f"{working} working lift rotors cannot hover trimmed; allowed: at least "
                f"{MIN_HOVER_ROTORS} (their thrusts must balance the weight and the roll, pitch "
                "and yaw moments independently, docs theory/dynamics 'Hover control reserve'); "
                "a layout of 4 lift rotors has no one-rotor-out hover case"
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
    def control_reserve(cls, vehicle):
        """
        Return the control-reserve constraint of a hover or OEI condition, or None.

        The axes (roll, pitch, yaw) with a required acceleration > 0 in the vehicle file's
        ``constraints.min_control_acceleration``: ``control_acceleration`` >= it (docs
        theory/dynamics 'Hover control reserve').
        """
        required = np.array(vehicle.constraints.min_control_acceleration)
        axes = [int(a) for a in np.flatnonzero(required > 0.0)]
        if not axes:
            return None
        return ConditionConstraint(
            "control_reserve",
            "control_acceleration",
            {
                "indices": axes,
                "flat_indices": True,
                "lower": required[axes],
                "ref": 0.1,
                "units": "rad/s**2",
            },
        )

    @classmethod
    def constraints(cls, vehicle, condition, bounds):
        reserve = cls.control_reserve(vehicle)
        reserve = () if reserve is None else (reserve,)
        limits = vehicle.constraints
        if condition.failed_rotor >= 0:
            # Every working rotor turns at its own speed: each one's tip Mach number (in hover
            # the helical and the rotational one are equal).
            return reserve + (_lift_tip_mach(limits), _blade_stall(limits, "lift"))
        active = cls.active_lift_rotors(vehicle, condition)
        pairs = [vehicle.lift_rotors[i].pair for i in active]
        one_per_pair = [pairs.index(p) for p in sorted(set(pairs))]
        noise = tuple(
            ConditionConstraint(
                "noise",
                "total_spl_a" if k == 0 else f"{noise_group_name(k)}.total_spl_a",
                {"upper": limits.max_noise, "ref": 10.0},
            )
            for k in range(len(vehicle.noise_observer))
        )
        return (
            reserve
            + noise
            + (
                ConditionConstraint(
                    "tip_mach",
                    "lift_tip_mach",
                    {"indices": one_per_pair, "flat_indices": True, "upper": limits.max_tip_mach},
                ),
                _blade_stall(limits, "lift"),
            )
        )

    @classmethod
    def motor_sets(cls, vehicle, condition):
        return {"lift": tuple(cls.active_lift_rotors(vehicle, condition))}


class SteadyFlightKind(ConditionKind):
    """
    Climb, cruise or descent (kind ``steady``): trim in F_x, F_z, M_y.

    The trim variables are pusher speed, pitch and elevator. Every steady condition declares the
    pusher's helical tip Mach number <= ``max_pusher_tip_mach``, its blade stations within
    their stall limit (:func:`blade_stall_limit`) and its wing sections' lift within the 1-g
    limit (:func:`wing_stall_limit`); the condition named by the
    vehicle's ``mission.cruise_condition`` also declares the static-margin constraint (paper
    eq. 30).
    """

    field_rules = {
        "steady": {
            "speed": _POSITIVE,
            "failed_rotor": _NO_FAILURE,
            "acceleration": _ZERO,
            "load_factor": _ONE,
        }
    }

    @staticmethod
    def has_stability(vehicle, condition):
        """Whether the condition evaluates the static margin: the vehicle's cruise condition."""
        return vehicle.mission.cruise_condition == condition.name

    @classmethod
    def variables(cls, vehicle, condition):
        if condition.optimizes_speed:
            return (_PUSHER_RPM, _PITCH, _ELEVATOR, _SPEED)
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
        pusher = (
            _pusher_tip_mach(vehicle.constraints),
            _blade_stall(vehicle.constraints, "pusher"),
            _wing_stall(vehicle.constraints),
        )
        if not cls.has_stability(vehicle, condition):
            return pusher
        return pusher + (
            ConditionConstraint(
                "static_margin",
                "static_margin",
                {"lower": vehicle.constraints.min_static_margin, "ref": 0.1},
            ),
        )

    @classmethod
    def motor_sets(cls, vehicle, condition):
        return {"pusher": (0,)}


class TransitionKind(ConditionKind):
    """
    A quasi-steady transition point (kind ``transition``): prescribed speed and acceleration.

    Trim variables: the lift pairs' mean speeds ``lift_rpm``, the roll and yaw speed
    differentials ``roll_yaw_rpm`` (not in the paper: the pusher's torque reaction rolls the
    vehicle and the h-tail deflects symmetrically), the pusher speed, pitch (prescribed in the
    paper; here the vehicle file's ``pitch_deg`` is its initial value) and elevator. The linear
    trim rows are in flight-path axes: the acceleration along the path equals the prescribed one.
    """

    field_rules = {
        "transition": {"speed": _POSITIVE, "failed_rotor": _NO_FAILURE, "load_factor": _ONE}
    }

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
        Each lift rotor's speed within its pair's bounds (linear), advance ratio and tip Mach.

        The advance ratio mu = V_inplane / (Omega R) of every lift rotor stays within
        ``constraints.max_lift_rotor_advance_ratio``, the range of the inflow model: no rotor
        outside it trims the vehicle (docs theory/rotors 'Advance-ratio limit'). The helical tip
        Mach number of each lift rotor (at its advancing blade) <= ``max_lift_rotor_tip_mach``
        and the pusher's <= ``max_pusher_tip_mach``; the pusher's blade stations within their
        stall limit (:func:`blade_stall_limit`); the wing sections' lift within the 1-g limit
        (:func:`wing_stall_limit`).

        With the roll/yaw differentials a rotor turns at its pair's mean speed +- half of each
        differential, so the design-variable bounds alone let it reach 0 rpm (100 rpm mean -
        50 - 50), where the motor model stalls: an SLSQP line search of the baseline problem
        drove a rotor to 7 rpm and ended in an AnalysisError. The speeds
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
            ConditionConstraint(
                "advance_ratio",
                "lift_advance_ratio",
                {"upper": vehicle.constraints.max_lift_rotor_advance_ratio, "ref": 0.1},
            ),
            _lift_tip_mach(vehicle.constraints),
            _pusher_tip_mach(vehicle.constraints),
            _blade_stall(vehicle.constraints, "pusher"),
            _wing_stall(vehicle.constraints),
        )

    @classmethod
    def motor_sets(cls, vehicle, condition):
        return {"lift": tuple(range(len(vehicle.lift_rotors))), "pusher": (0,)}


class StructuralKind(ConditionKind):
    """
    A +3g or -1g pull-up or push-over (kind ``structural``): trim in F_z by pitch.

    Declares the buckling constraint of the compressed skin (every bay but the tip bay), the
    KS-aggregated von Mises stress constraint and the wing sections' lift within the load-case
    limit (:func:`wing_stall_limit`); draws no power (``energy_weight`` 0).
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
            # the paper's 350 MPa) of the box.
            ConditionConstraint("stress", "stress_ratio_ks", {"upper": 1.0}),
            # The load case lies inside the manoeuvring envelope: on or below its stall line.
            _wing_stall(vehicle.constraints, load_case=True),
        )


for _kind, _declaration in (
    ("hover", HoverKind),
    ("oei", HoverKind),
    ("transition", TransitionKind),
    ("steady", SteadyFlightKind),
    ("structural", StructuralKind),
):
    register_kind(_kind, _declaration)
