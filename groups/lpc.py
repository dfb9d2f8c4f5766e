"""The full lift-plus-cruise model: vehicle, 15 design conditions, mission energy, constraints."""

import numpy as np
import openmdao.api as om
from scipy.optimize import brentq

from lpc_mdo.components.atmosphere import standard_atmosphere
from lpc_mdo.components.design_deviation import DesignDeviationComp
from lpc_mdo.components.energy.battery import BatteryComp
from lpc_mdo.components.energy.mission_energy import MissionEnergyComp
from lpc_mdo.components.gather_across_conditions import GatherComp
from lpc_mdo.components.ks import KSComp
from lpc_mdo.groups.conditions import (
    HoverCondition,
    SteadyFlightCondition,
    StructuralCondition,
    TransitionCondition,
)
from lpc_mdo.groups.vehicle import VehicleGroup
from lpc_mdo.vehicle import VehicleSpecError, reference_vehicle

PUSHER = 4  # row of the pusher in the per-rotor-group design variables
CONSTRAINT_KINDS = ("trim", "noise", "tip_mach", "static_margin", "buckling", "soc",
                    "radius_intersection", "torque_margin", "rotor_speed")
# Paper eq. 8-9: the set S of design variables the initial specification gives (beta = 1) -
# every sizing variable; the operating variables (rotor speeds, pitch, elevator) are free - and
# the penalty weight alpha.
BASELINE_SET = ("wing_area", "wing_aspect_ratio", "htail_area", "htail_aspect_ratio",
                "fuselage_length", "rotor_radius", "blade_chord_cp", "blade_twist_cp",
                "battery_mass", "motor_length", "front_spar_thickness", "rear_spar_thickness",
                "top_skin_thickness", "bottom_skin_thickness")
BASELINE_ALPHA = 100.0
# Finer kinds a subproblem may name instead of 'torque_margin' (which means both).
TORQUE_MARGIN_KINDS = ("lift_torque_margin", "pusher_torque_margin")
# Torque margin reported for a lift motor that no included condition loads (a model built with
# a single OEI case); large, so it never binds.
UNUSED_MOTOR_MARGIN = 10.0

_CONDITION_CLASSES = {
    "hover": HoverCondition,
    "oei": HoverCondition,
    "transition": TransitionCondition,
    "steady": SteadyFlightCondition,
    "structural": StructuralCondition,
}


def _units(units):
    """OpenMDAO units of a vehicle-file design variable ('unitless' is None)."""
    return None if units == "unitless" else units


def _row(index):
    """src_indices that take row ``index`` of a 2-D source as a (1, n) target."""
    return om.slicer[[index], :]


def _as_row(size, start=0):
    """src_indices that take ``size`` entries of a 1-D source as a (1, size) target."""
    return om.slicer[np.arange(start, start + size)[np.newaxis, :],]


class LPCGroup(om.Group):
    """
    System-level model of the lift-plus-cruise vehicle (paper Fig. 11, Table 6).

    ``design_variables`` (an IndepVarComp) holds the 31 design-variable arrays of the vehicle
    file (171 values: the paper's 161 and the 10 roll/yaw lift-rotor speed differentials of the
    transition points);
    ``vehicle`` (VehicleGroup) turns them into geometry and mass properties; each design
    condition is a subsystem named as in the vehicle file (``hover``,
    ``transition_1`` .. ``transition_5``, ``climb``, ``cruise``, ``descent``, ``oei_1`` ..
    ``oei_4``, ``plus_3g``, ``minus_1g``); ``mission`` and ``battery`` give the final state of
    charge; ``lift_margin``/``pusher_margin`` aggregate the motor torque margins over the
    conditions by KS (paper eq. 7). With ``design_problem`` the design variables, the paper's
    96 constraints and the gross-mass objective are declared (see :meth:`add_design_problem`).

    Options
    -------
    vehicle : Vehicle or None
    static_margin : bool
        Constrain the cruise static margin (paper Sec. V.B, with and without).
    design_problem : bool
        Declare design variables, constraints and objective.
    rotor_polar : Polar or None
        Blade-section polar of all rotors (None: the lift rotors use the table of their
        ``lift_rotors[i].airfoil``, which must be the same for all eight, and the pusher that of
        ``pusher.airfoil``).
    wing_zero_lift_angle : float or None
        Sectional zero-lift angle of the wing airfoil, rad (None: from its table).
    ks_rho : float
        KS aggregation parameter of the torque margins.
    lateral_trim : bool
        Declare every trim row of paper Table 6 (96 constraints). False leaves out ten: the
        five that vanish for every design, with zero gradients (hover p_dot by symmetry, the
        OEI v_dot: no side force in hover), and the transition v_dot, which no trim variable
        controls on its own (the rotors' net side force under the yaw differential; at most
        0.06 % of the weight as a force at the optimum): 86 constraints.
    conditions : list of str or None
        The design conditions to include, by name (None: all of the vehicle's). Subproblems
        and single-condition studies use a subset; the mission energy then counts only those.
    """

    def initialize(self):
        self.options.declare(
            "vehicle",
            default=None,
            allow_none=True,
            desc="lpc_mdo.vehicle.Vehicle; None = reference vehicle",
        )
        self.options.declare(
            "static_margin", default=True, types=bool, desc="constrain the cruise static margin"
        )
        self.options.declare(
            "design_problem",
            default=True,
            types=bool,
            desc="declare design variables, constraints and objective",
        )
        self.options.declare(
            "rotor_polar",
            default=None,
            allow_none=True,
            desc="blade-section polar (None: from the rotor airfoil)",
        )
        self.options.declare(
            "wing_zero_lift_angle",
            default=None,
            allow_none=True,
            types=float,
            desc="wing sectional zero-lift angle, rad",
        )
        self.options.declare(
            "ks_rho", default=50.0, types=float, desc="KS parameter of the torque-margin aggregates"
        )
        self.options.declare("lateral_trim", default=True, types=bool,
                             desc="also constrain hover p_dot, OEI v_dot (zero for every "
                                  "design) and transition v_dot (no trim variable of its own) "
                                  "as paper Table 6 counts them (96): False gives 86")
        self.options.declare("objective", default=("gross_mass", None), types=tuple,
                             desc="(output, ref) of the objective; ref None = the vehicle's "
                                  "target gross mass (paper: gross mass); ('baseline', None) = "
                                  "the baseline design's penalised gross mass (eq. 8-9)")
        self.options.declare("baseline_alpha", default=BASELINE_ALPHA, types=(int, float),
                             lower=0.0,
                             desc="penalty weight alpha of the baseline objective (eq. 8; paper: "
                                  "100, chosen from a study over 1e-2 .. 1e4)")
        self.options.declare("conditions", default=None, types=(list, tuple), allow_none=True,
                             desc="names of the design conditions to include (None: all)")
        self.options.declare("design_variables", default=None, types=(list, tuple, dict),
                             allow_none=True,
                             desc="design variables to declare: names, or (name, flat indices) "
                                  "pairs (None: every one that acts on the conditions)")
        self.options.declare("design_variable_refs", default=None, types=dict, allow_none=True,
                             desc="name -> ref overriding the vehicle file's scaling")
        self.options.declare("design_variable_bounds", default=None, types=dict,
                             allow_none=True,
                             desc="name -> (lower, upper) overriding the vehicle file's bounds "
                                  "(vehicle-file units, scalars or the variable's shape)")
        self.options.declare("constraint_kinds", default=CONSTRAINT_KINDS, types=(list, tuple),
                             desc=f"constraint kinds to declare, from {CONSTRAINT_KINDS} "
                                  f"(or {TORQUE_MARGIN_KINDS} for one motor kind)")
        self.options.declare("structural_coupling", default="one_way",
                             values=("one_way", "two_way"),
                             desc="aerostructural coupling of the +3g/-1g cases")
        self.options.declare("structural_ks_rho", default=None, types=(int, float),
                             allow_none=True,
                             desc="KS parameter of the +3g/-1g structural aggregates (None: "
                                  "no aggregates)")

    def setup(self):
        vehicle = self.options["vehicle"] or reference_vehicle()
        self.vehicle_spec = vehicle
        names = [c.name for c in vehicle.conditions]
        chosen = self.options["conditions"]
        if chosen is not None:
            unknown = [c for c in chosen if c not in names]
            if unknown or not chosen:
                raise ValueError(f"{self.msginfo}: conditions = {list(chosen)}; each must be one "
                                 f"of the vehicle's conditions {names} (at least one).")
        # In the vehicle file's order, so the mission bookkeeping is stable.
        self.conditions = [c for c in vehicle.conditions
                           if chosen is None or c.name in chosen]
        polar, pusher_polar, alpha0 = _airfoil_models(
            vehicle, self.options["rotor_polar"], self.options["wing_zero_lift_angle"]
        )

        dvs = self.add_subsystem("design_variables", om.IndepVarComp(), promotes=["*"])
        for name, dv in vehicle.design_variables.items():
            dvs.add_output(
                name,
                np.asarray(dv.initial_array).reshape(dv.shape),
                units=_units(dv.units),
                desc=dv.description,
            )
        self.add_subsystem("vehicle", VehicleGroup(vehicle=vehicle), promotes=["*"])

        self.condition_names = []
        for condition in self.conditions:
            kind = condition.kind
            kwargs = {"vehicle": vehicle, "condition": condition.name, "rotor_polar": polar,
                      "pusher_polar": pusher_polar}
            if kind in ("transition", "steady", "structural"):
                kwargs["wing_zero_lift_angle"] = alpha0
            if kind == "structural":
                kwargs["ks_rho"] = self.options["structural_ks_rho"]
                kwargs["coupling"] = self.options["structural_coupling"]
            if condition.name == "cruise":
                kwargs["stability"] = True
            self.add_subsystem(condition.name, _CONDITION_CLASSES[kind](**kwargs))
            self.condition_names.append(condition.name)

        self._add_mission(vehicle)
        if self.options["design_problem"]:
            self.add_design_problem()

    # ------------------------------------------------------------------ connections

    def configure(self):
        vehicle = self.vehicle_spec
        pair = np.array([r.pair for r in vehicle.lift_rotors])
        for condition in self.conditions:
            name, kind = condition.name, condition.kind
            sub = getattr(self, name)
            self.connect("gross_mass", f"{name}.gross_mass")
            self.connect("cg", f"{name}.cg")
            self.connect("inertia", f"{name}.inertia")
            if kind in ("hover", "oei", "transition"):
                active = np.array(sub.active_rotors)
                self.connect("lift_rotor_radius", f"{name}.lift_radius", src_indices=active)
                self.connect(
                    "blade_chord_cp",
                    f"{name}.lift_chord_cp",
                    src_indices=om.slicer[pair[active], :],
                )
                self.connect(
                    "blade_twist_cp",
                    f"{name}.lift_twist_cp",
                    src_indices=om.slicer[pair[active], :],
                )
                self.connect(
                    "lift_hub_position",
                    f"{name}.lift_hub_position",
                    src_indices=om.slicer[active, :],
                )
                self.connect("motor_length", f"{name}.lift_motor_length", src_indices=pair[active])
            if kind in ("transition", "steady"):
                self.connect("rotor_radius", f"{name}.pusher_radius", src_indices=[PUSHER])
                self.connect("blade_chord_cp", f"{name}.pusher_chord_cp", src_indices=_row(PUSHER))
                self.connect("blade_twist_cp", f"{name}.pusher_twist_cp", src_indices=_row(PUSHER))
                self.connect(
                    "pusher_hub_position", f"{name}.pusher_hub_position", src_indices=_as_row(3)
                )
                self.connect("motor_length", f"{name}.pusher_motor_length", src_indices=[PUSHER])
            if kind in ("transition", "steady", "structural"):
                for src, tgt in (
                    ("wing_mesh", "wing_mesh"),
                    ("horizontal_tail_mesh", "horizontal_tail_mesh"),
                    ("wing_area", "wing_area"),
                    ("wing_mac", "wing_mac"),
                    ("htail_area", "htail_area"),
                    ("htail_mac", "htail_mac"),
                    ("fuselage_length", "fuselage_length"),
                ):
                    self.connect(src, f"{name}.{tgt}")
            if kind == "hover":
                self.connect("hover_lift_rpm", f"{name}.lift_rotor_speed", src_indices=_as_row(4))
            elif kind == "oei":
                k = int(name.split("_")[1]) - 1
                self.connect("oei_lift_rpm", f"{name}.lift_rotor_speed", src_indices=_row(k))
            elif kind == "transition":
                k = int(name.split("_")[1]) - 1
                self.connect("transition_lift_rpm", f"{name}.lift_rotor_speed", src_indices=_row(k))
                self.connect("transition_roll_yaw_rpm", f"{name}.lift_roll_yaw_rpm",
                             src_indices=_row(k))
                self.connect(
                    "transition_pusher_rpm", f"{name}.pusher_rpm", src_indices=_as_row(1, start=k)
                )
                self.connect("transition_elevator", f"{name}.elevator", src_indices=[k])
            elif kind == "steady":
                self.connect(f"{name}_pusher_rpm", f"{name}.pusher_rpm", src_indices=_as_row(1))
                self.connect(f"{name}_pitch", f"{name}.pitch")
                self.connect(f"{name}_elevator", f"{name}.elevator")
                if name == "cruise":
                    self.connect("cg", "cruise.cg_x", src_indices=[0])
            elif kind == "structural":
                self.connect(f"{name}_pitch", f"{name}.pitch")
                for var in (
                    "wing_box_nodes",
                    "box_width",
                    "box_height",
                    "top_skin_thickness",
                    "bottom_skin_thickness",
                    "front_spar_thickness",
                    "rear_spar_thickness",
                    "top_skin_radius",
                    "bottom_skin_radius",
                ):
                    self.connect(var, f"{name}.{var}")

        for i, condition in enumerate(self.conditions):
            if condition.kind != "structural":
                self.connect(
                    f"{condition.name}.electrical_power", f"power_mux.electrical_power_{i}"
                )
        lift = [c.name for c in self.conditions if c.kind in ("hover", "oei", "transition")]
        for name in lift:
            self.connect(f"{name}.lift_motor_torque_margin", f"lift_margin_gather.{name}")
        push = [c.name for c in self.conditions if c.kind in ("transition", "steady")]
        for name in push:
            self.connect(f"{name}.pusher_motor_torque_margin", f"pusher_margin_gather.{name}")
        super().configure()

    # ------------------------------------------------------------------ the design problem

    def add_design_problem(self):
        """
        Declare the design variables (the paper's 161 and our 10 transition roll/yaw speed
        differentials), the constraints (96) and the objective (Table 6).

        Constraints, with their count:

        - hover: total noise <= limit (1); w_dot, p_dot, q_dot = 0 (3); tip Mach <= limit, one
          rotor per pair (4);
        - climb, cruise, descent: u_dot, w_dot, q_dot = 0 (3 x 3);
        - transition points: u_dot = a cos(theta), w_dot = a sin(theta) (2 x 5); v_dot, p_dot,
          q_dot, r_dot = 0 (4 x 5);
        - OEI: v_dot, w_dot, p_dot, q_dot, r_dot = 0 (5 x 4);
        - +3g, -1g: w_dot = 0 (2);
        - cruise static margin >= limit (1, if ``static_margin``);
        - buckling ratio <= 1 of the top skin at +3g and the bottom skin at -1g, all bays but the
          tip bay (2 x 7);
        - final state of charge >= limit (1); radius intersection = target (2);
        - motor torque margin >= limit, KS over the conditions (8 lift + 1 pusher).

        Without ``lateral_trim`` the hover p_dot and the OEI v_dot rows, which vanish for every
        design, and the transition v_dot rows, which no trim variable controls on its own, are
        left out (86 constraints).

        Ours, beyond Table 6 (kind ``rotor_speed``, with ``transition_roll_yaw_rpm``): each
        lift rotor's own speed in transition within its pair's ``transition_lift_rpm`` bounds
        (8 x 5 linear two-sided constraints), which the differentials could otherwise drive to
        0 rpm.
        """
        vehicle = self.vehicle_spec
        limits = vehicle.constraints
        present = {c.name for c in self.conditions}
        kinds = {c.kind for c in self.conditions}
        chosen = self.options["design_variables"]
        if chosen is None:
            selection = {name: None for name in vehicle.design_variables}
        else:
            selection = {}
            for entry in chosen:
                name, indices = (entry, None) if isinstance(entry, str) else entry
                if name not in vehicle.design_variables:
                    raise ValueError(f"{self.msginfo}: design variable {name!r} is not in the "
                                     f"vehicle file; allowed: {list(vehicle.design_variables)}")
                selection[name] = None if indices is None else list(indices)
        refs = self.options["design_variable_refs"] or {}
        bounds = self.options["design_variable_bounds"] or {}
        for name in bounds:
            if name not in vehicle.design_variables:
                raise ValueError(f"{self.msginfo}: option 'design_variable_bounds' names "
                                 f"{name!r}; allowed: {list(vehicle.design_variables)}")
        for name, indices in selection.items():
            dv = vehicle.design_variables[name]
            if not _design_variable_used(name, present, kinds):
                continue
            lower, upper = _bounds(name, dv, bounds)
            ref = refs.get(name, dv.ref)
            if indices is not None:
                lower, upper = lower.ravel()[indices], upper.ravel()[indices]
                ref = ref if np.ndim(ref) == 0 else np.asarray(ref).ravel()[indices]
            self.add_design_var(name, lower=lower, upper=upper, ref=ref, units=_units(dv.units),
                                indices=indices, flat_indices=indices is not None)
        objective, objective_ref = self.options["objective"]
        if objective == "baseline":
            self._add_baseline_objective(vehicle)
            self.add_objective("baseline_objective", ref=1.0)
        else:
            self.add_objective(objective, ref=(vehicle.masses.target_gross_mass
                                               if objective_ref is None else objective_ref))
        wanted = set(self.options["constraint_kinds"])
        unknown = sorted(wanted - set(CONSTRAINT_KINDS) - set(TORQUE_MARGIN_KINDS))
        if unknown:
            raise ValueError(f"{self.msginfo}: option 'constraint_kinds' has unknown kinds "
                             f"{unknown}; allowed: {CONSTRAINT_KINDS + TORQUE_MARGIN_KINDS}")
        # Without lateral_trim, leave out the rows that vanish for every design (zero value,
        # zero gradient; they violate the constraint qualification): hover p_dot (the pairs
        # share speeds and spin in opposite senses) and the OEI v_dot (no side force in
        # hover); and the transition v_dot: only the rotors' net side force under the yaw
        # differential moves it, with no variable of its own (as an equality it would need
        # large rotor-speed excursions; with a differential per pair, which can null it, the
        # full problem took twice the SLSQP iterations); left free it stays within 0.06 % of
        # the weight at the optimum (measured; lpc_mdo.post.trim_residuals reports it).
        skip_lateral = not self.options["lateral_trim"]

        g = 9.81
        if "hover" in present and "noise" in wanted:
            self.add_constraint("hover.total_spl_a", upper=limits.max_noise, ref=10.0)
        if "hover" in present and "trim" in wanted:
            self._trim("hover", [2], [1] if skip_lateral else [0, 1], 0.0, g)
        if "hover" in present and "tip_mach" in wanted:
            pairs = np.array([r.pair for r in vehicle.lift_rotors])
            tip = [int(np.flatnonzero(pairs == p)[0]) for p in range(4)]
            self.add_constraint("hover.lift_tip_mach", indices=tip, flat_indices=True,
                                upper=limits.max_tip_mach)
        for c in self.conditions if "trim" in wanted else ():
            if c.kind == "steady":
                self._trim(c.name, [0, 2], [1], 0.0, g)
            elif c.kind == "transition":
                accel = c.acceleration * np.array([np.cos(c.pitch), 0.0, np.sin(c.pitch)])
                self._trim(c.name, [0, 2] if skip_lateral else [0, 1, 2], [0, 1, 2], accel, g)
            elif c.kind == "oei":
                # v_dot: no side force acts in hover (rotor thrust only, no edgewise flow).
                self._trim(c.name, [2] if skip_lateral else [1, 2], [0, 1, 2], 0.0, g)
            elif c.kind == "structural":
                self._trim(c.name, [2], [], 0.0, g * abs(c.load_factor))
        if self.options["static_margin"] and "cruise" in present and "static_margin" in wanted:
            self.add_constraint("cruise.static_margin", lower=limits.min_static_margin, ref=0.1)
        bays = list(range(vehicle.wing_box.num_bays - 1))
        for name, skin in (("plus_3g", "top"), ("minus_1g", "bottom")):
            if name in present and "buckling" in wanted:
                self.add_constraint(f"{name}.{skin}_skin_buckling_ratio", indices=bays,
                                    flat_indices=True, upper=limits.max_buckling_ratio)
        if "soc" in wanted:
            self.add_constraint("state_of_charge", lower=limits.min_final_soc, ref=0.1)
        if "radius_intersection" in wanted:
            self.add_constraint("radius_intersection", equals=limits.radius_intersection,
                                ref=0.1)
        if "rotor_speed" in wanted and "transition_roll_yaw_rpm" in selection:
            self._add_transition_speed_bounds(vehicle, bounds)
        both = "torque_margin" in wanted
        if kinds & {"hover", "oei", "transition"} and (both or "lift_torque_margin" in wanted):
            self.add_constraint("lift_motor_torque_margin", lower=limits.min_torque_margin,
                                ref=0.1)
        if kinds & {"transition", "steady"} and (both or "pusher_torque_margin" in wanted):
            self.add_constraint("pusher_motor_torque_margin", lower=limits.min_torque_margin,
                                ref=0.1)

    def _add_baseline_objective(self, vehicle):
        """Paper eq. 8-9: gross mass plus 100 x the squared relative deviation over the set S."""
        references = {name: (np.asarray(vehicle.design_variables[name].initial_array).reshape(
            vehicle.design_variables[name].shape), _units(vehicle.design_variables[name].units))
            for name in BASELINE_SET}
        self.add_subsystem("baseline", DesignDeviationComp(
            references=references, alpha=self.options["baseline_alpha"],
            objective_ref=vehicle.masses.target_gross_mass),
            promotes_inputs=[*BASELINE_SET, ("objective", "gross_mass")],
            promotes_outputs=["baseline_objective", ("deviation", "baseline_deviation")])

    def _add_transition_speed_bounds(self, vehicle, bounds):
        """
        Each lift rotor's own speed in transition within the bounds of its pair's mean speed.

        With the roll/yaw differentials a rotor turns at its pair's ``transition_lift_rpm``
        +- half of each differential, so the design-variable bounds alone let it reach 0 rpm
        (100 rpm mean - 50 - 50), where the motor model stalls: an SLSQP line search of the
        baseline problem drove a transition_2 rotor to 7 rpm and ended in an AnalysisError
        (measured 2026-12-01). The speeds are linear in the design variables, so these are
        linear constraints (Jacobian computed once; SLSQP's steps keep them).
        """
        dv = vehicle.design_variables["transition_lift_rpm"]
        lower, upper = _bounds("transition_lift_rpm", dv, bounds)
        pairs = np.array([r.pair for r in vehicle.lift_rotors])
        for c in self.conditions:
            if c.kind == "transition":
                k = int(c.name.split("_")[1]) - 1
                self.add_constraint(f"{c.name}.lift_rpm", lower=lower[k, pairs],
                                    upper=upper[k, pairs], ref=dv.ref, units=_units(dv.units),
                                    linear=True)

    def _trim(self, name, linear, angular, linear_target, ref):
        """Trim constraints: chosen body-axis accelerations of a condition equal targets."""
        target = np.broadcast_to(linear_target, 3)[linear] if np.ndim(linear_target) else 0.0
        self.add_constraint(f"{name}.linear_acceleration", indices=linear, flat_indices=True,
                            equals=target, ref=ref)
        if angular:
            self.add_constraint(f"{name}.angular_acceleration", indices=angular,
                                flat_indices=True, equals=0.0)

    # ------------------------------------------------------------------ mission and margins

    def _add_mission(self, vehicle):
        conditions = self.conditions
        n = len(conditions)
        mux = self.add_subsystem("power_mux", om.MuxComp(vec_size=n))
        mux.add_var("electrical_power", shape=(1,), axis=0, units="W")
        self.add_subsystem(
            "mission",
            MissionEnergyComp(energy_multipliers=[c.energy_multiplier for c in conditions]),
            promotes_outputs=["energy_used", "segment_energy"],
        )
        self.connect("power_mux.electrical_power", "mission.electrical_power")
        self.set_input_defaults(
            "mission.duration", np.array([c.duration for c in conditions]), units="s"
        )
        self.add_subsystem(
            "battery",
            BatteryComp(),
            promotes_inputs=["battery_mass", "energy_used"],
            promotes_outputs=["state_of_charge", "energy_capacity"],
        )
        self.set_input_defaults("battery.specific_energy", vehicle.battery.energy_density,
                                units="J/kg")
        self.set_input_defaults("battery.initial_soc", vehicle.battery.initial_soc)

        lift = [c for c in conditions if c.kind in ("hover", "oei", "transition")]
        push = [c for c in conditions if c.kind in ("transition", "steady")]
        if lift:
            self._add_margin_aggregate(vehicle, lift)
        if push:
            self._add_pusher_margin_aggregate(push)

    def _add_margin_aggregate(self, vehicle, lift):
        items = []
        for c in lift:
            failed = c.failed_rotor
            items.append([i for i in range(len(vehicle.lift_rotors)) if i != failed])
        self.add_subsystem(
            "lift_margin_gather",
            GatherComp(
                name="torque_margin",
                sources=[c.name for c in lift],
                items=items,
                num_items=len(vehicle.lift_rotors),
                absent_value=UNUSED_MOTOR_MARGIN,
            ),
        )
        self.add_subsystem(
            "lift_margin",
            KSComp(
                vec_size=len(vehicle.lift_rotors),
                width=len(lift),
                rho=self.options["ks_rho"],
                lower_flag=True,
            ),
            promotes_outputs=[("KS", "lift_motor_torque_margin")],
        )
        self.connect("lift_margin_gather.torque_margin", "lift_margin.g")

    def _add_pusher_margin_aggregate(self, push):
        self.add_subsystem(
            "pusher_margin_gather",
            GatherComp(
                name="torque_margin",
                sources=[c.name for c in push],
                items=[[0]] * len(push),
                num_items=1,
            ),
        )
        self.add_subsystem(
            "pusher_margin",
            KSComp(vec_size=1, width=len(push), rho=self.options["ks_rho"], lower_flag=True),
            promotes_outputs=[("KS", "pusher_motor_torque_margin")],
        )
        self.connect("pusher_margin_gather.torque_margin", "pusher_margin.g")


def condition_trim_variables(vehicle, name):
    """
    The design-variable entries that trim condition ``name`` (paper Table 6): list of
    (design-variable name, flat indices). Hover: the 4 lift-pair speeds; OEI: the 7 working lift
    rotor speeds; transition: 4 lift-pair speeds, the roll and yaw differentials (ours), pusher
    speed, elevator; climb, cruise,
    descent: pusher speed, pitch, elevator; +3g/-1g: pitch.
    """
    kind = vehicle.condition(name).kind
    if kind == "hover":
        return [("hover_lift_rpm", np.arange(4))]
    if kind == "oei":
        k = int(name.split("_")[1]) - 1
        n = vehicle.design_variables["oei_lift_rpm"].shape[1]
        return [("oei_lift_rpm", k * n + np.arange(n))]
    if kind == "transition":
        k = int(name.split("_")[1]) - 1
        return [("transition_lift_rpm", 4 * k + np.arange(4)),
                ("transition_roll_yaw_rpm", 2 * k + np.arange(2)),
                ("transition_pusher_rpm", np.array([k])),
                ("transition_elevator", np.array([k]))]
    if kind == "steady":
        return [(f"{name}_{v}", np.array([0])) for v in ("pusher_rpm", "pitch", "elevator")]
    return [(f"{name}_pitch", np.array([0]))]


def _bounds(name, dv, overrides):
    """(lower, upper) of a design variable in its shape: the override, else the vehicle file's."""
    lower, upper = overrides.get(name, (dv.lower_array, dv.upper_array))
    return (np.broadcast_to(np.asarray(lower, dtype=float), dv.shape),
            np.broadcast_to(np.asarray(upper, dtype=float), dv.shape))


def _design_variable_used(name, present, kinds):
    """Whether a design variable acts on the model with these conditions."""
    if name.startswith("hover_"):
        return "hover" in present
    if name.startswith("transition_"):
        return "transition" in kinds
    if name.startswith("oei_"):
        return "oei" in kinds
    for suffix in ("_pusher_rpm", "_pitch", "_elevator"):
        if name.endswith(suffix):
            return name[: -len(suffix)] in present
    return True


def zero_lift_angle(polar, reynolds, mach):
    """Angle of attack (rad) where a polar's cl vanishes, bracketed in [-20, +10] deg."""
    def cl(alpha):
        return float(polar.evaluate(np.array(alpha), reynolds, mach).cl)

    return float(brentq(cl, np.radians(-20.0), np.radians(10.0), xtol=1e-12))


def _airfoil_models(vehicle, rotor_polar, wing_zero_lift_angle):
    """
    The lift-rotor polar, the pusher polar and the wing's sectional zero-lift angle.

    A given ``rotor_polar`` serves every rotor; otherwise the lift rotors take the table of their
    airfoil and the pusher that of its own. One lift-rotor polar serves all eight lift rotors
    (one BEM/Pitt-Peters call per condition), so lift rotors with different airfoils are a
    VehicleSpecError naming the first that differs from ``lift_rotors[0]``.
    """
    if rotor_polar is not None and wing_zero_lift_angle is not None:
        return rotor_polar, rotor_polar, wing_zero_lift_angle
    from lpc_mdo.components.aero.airfoil import get_polar

    if rotor_polar is None:
        first = vehicle.lift_rotors[0].airfoil
        for i, rotor in enumerate(vehicle.lift_rotors):
            if rotor.airfoil != first:
                raise VehicleSpecError(
                    f"'lift_rotors[{i}].airfoil' = {rotor.airfoil!r} differs from "
                    f"'lift_rotors[0].airfoil' = {first!r}; allowed: one airfoil for all lift "
                    f"rotors (the model evaluates them with one polar), or pass LPCGroup option "
                    f"'rotor_polar'"
                )
        rotor_polar = get_polar(first)
        pusher_polar = get_polar(vehicle.pusher.airfoil)
    else:
        pusher_polar = rotor_polar
    if wing_zero_lift_angle is None:
        # At the cruise condition's Reynolds and Mach numbers on the wing MAC.
        cruise = vehicle.condition("cruise")
        _, _, rho, a, mu = standard_atmosphere(cruise.altitude)
        reynolds = rho * cruise.speed * vehicle.wing.mean_aerodynamic_chord / mu
        wing_zero_lift_angle = zero_lift_angle(get_polar(vehicle.wing.airfoil), reynolds,
                                               cruise.speed / a)
    return rotor_polar, pusher_polar, wing_zero_lift_angle
