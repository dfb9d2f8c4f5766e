"""The optimization problems, declared outside the physics model (paper Tables 2 and 6).

:func:`declare_problem` declares the objective, design variables and constraints of a problem on
an :class:`~lpc_mdo.groups.lpc.LPCGroup` from the condition contracts
(:mod:`lpc_mdo.vehicle.condition_contract`): each condition's design variables, its trim rows (paper
Table 6) and its other constraints come from the class of its kind, the vehicle-level ones
(state of charge, radius intersection, torque margins) from here. The stages of the warm
start (:mod:`lpc_mdo.study_plan`; the subproblems of Table 2) select conditions by kind, never
by name, so a vehicle file with other or more conditions gets the same problems.
:func:`build_problem` (a stage's problem and driver, as the stage table declares them) and
:func:`build_analysis_problem` put model, problem and driver together.
"""

import os

import numpy as np
import openmdao.api as om

from lpc_mdo.components.design_deviation import DesignDeviationComp
from lpc_mdo.drivers import make_driver
from lpc_mdo.groups.lpc import LPCGroup, footprint_conditions, included_conditions, openmdao_units
from lpc_mdo.recorder import CaseRecorder
from lpc_mdo.study_plan import default_optimizer, rotor_group_indices, stage
from lpc_mdo.vehicle import load_vehicle, reference_vehicle
from lpc_mdo.vehicle.clearances import clearance_constraints, side_by_side_pairs
from lpc_mdo.vehicle.condition_contract import condition_kind
from lpc_mdo.vehicle.condition_layout import condition_layout
from lpc_mdo.vehicle.design_variable_registry import BASELINE_SET

#: Constraint kinds a problem may declare (by default, all of them). Beyond paper Table 6:
#: ``clearance``, the plan-view clearances of the lift disks to each other, the fuselage, the
#: horizontal tail and the pusher disk (lpc_mdo.vehicle.clearances), each >= the vehicle file's
#: floor; ``control_reserve``, the roll and pitch acceleration the lift rotors can still add in
#: hover and every one-rotor-out case; the rotors' advance ratio, tip Mach and minimum chord,
#: the motors' voltage margin and the wing sections' lift (each condition kind's
#: ``constraints()`` says where they apply); ``noise_footprint``, where the vehicle file has a
#: ``[noise_footprint]`` and the model every condition of the departure: the smooth maximum
#: over its ground observers of the sound exposure level (and of the maximum level, if the
#: file limits it) within the file's limits (lpc_mdo.groups.footprint).
CONSTRAINT_KINDS = (
    "trim",
    "noise",
    "tip_mach",
    "static_margin",
    "buckling",
    "stress",
    "soc",
    "clearance",
    "control_reserve",
    "torque_margin",
    "rotor_speed",
    "advance_ratio",
    "min_chord",
    "voltage_margin",
    "wing_stall",
    "blade_stall",
    "noise_footprint",
)
#: Finer kinds a subproblem may name instead of 'torque_margin' or 'voltage_margin' (which mean
#: both motor kinds). ``voltage_margin`` (not in the paper): every motor's MTPA operating point
#: in every condition within the voltage limit (``motor.voltage_limit``), the KS over the
#: conditions of 1 - abs(U)/V_lim >= ``constraints.min_voltage_margin`` per motor; the motor
#: model has no flux weakening, so beyond it the torque would be computed at a voltage the drive
#: does not have. The windings (``motor_rated_current``) let the optimizer meet it.
TORQUE_MARGIN_KINDS = (
    "lift_torque_margin",
    "pusher_torque_margin",
    "lift_voltage_margin",
    "pusher_voltage_margin",
)
#: Kinds declared only when a problem names them: ``radius_intersection``, the paper's
#: equality (R_inner + R_outer)/b = 0.20 (Table 6). It fixes the rotor radii to the span rather
#: than keeping the disks apart, and with the clearance floors it over-constrains the layout
#: (the 2 in rotor-to-rotor floor and the equality together need a span >= 18.1 m), so the
#: clearances replace it; name it in ``constraint_kinds`` to pose the paper's problem.
OPTIONAL_CONSTRAINT_KINDS = ("radius_intersection",)
#: The design variable closed by an equality on the gross mass wherever it is declared (not for
#: a calibrated vehicle, whose W_dg is the target of its W_other): design_gross_mass_closure =
#: W0 - W_dg = 0 (kg, ref 10 kg).
CLOSED_MASS = "design_gross_mass"
#: Its closure, W0 - W_dg (an output of lpc_mdo.groups.lpc.LPCGroup).
MASS_CLOSURE = "design_gross_mass_closure"
# Paper eq. 8-9: the penalty weight alpha of the baseline problem (its set S is the registry's
# BASELINE_SET, every sizing variable; the operating variables are free).
BASELINE_ALPHA = 100.0
#: Keyword arguments of :func:`declare_problem` (the rest of a builder's options are the
#: model's).
PROBLEM_OPTIONS = (
    "static_margin",
    "lateral_trim",
    "constraint_kinds",
    "design_variables",
    "design_variable_refs",
    "design_variable_bounds",
    "objective",
)


class BaselineModel(LPCGroup):
    """
    The lift-plus-cruise model plus the baseline objective of paper eq. 8-9.

    ``baseline_objective`` = gross mass + alpha x the squared relative deviation of the design
    variables of the set S (:data:`BASELINE_SET`) from their initial values: minimised subject
    to every constraint, it gives the feasible design closest to the initial one. Option
    ``baseline_alpha`` (paper: 100, chosen from a study over 1e-2 .. 1e4).
    """

    def initialize(self):
        super().initialize()
        self.options.declare(
            "baseline_alpha",
            default=BASELINE_ALPHA,
            types=(int, float),
            lower=0.0,
            desc="penalty weight alpha of eq. 8",
        )

    def setup(self):
        super().setup()
        vehicle = self.vehicle_spec
        dvs = vehicle.design_variables
        references = {
            name: (
                np.asarray(dvs[name].initial_array).reshape(dvs[name].shape),
                openmdao_units(dvs[name].units),
            )
            for name in BASELINE_SET
        }
        self.add_subsystem(
            "baseline",
            DesignDeviationComp(
                references=references,
                alpha=self.options["baseline_alpha"],
                objective_ref=vehicle.masses.design_gross_mass,
            ),
            promotes_inputs=[*BASELINE_SET, ("objective", "gross_mass")],
            promotes_outputs=["baseline_objective", ("deviation", "baseline_deviation")],
        )


def _bounds(name, dv, overrides):
    """(lower, upper) of a design variable in its shape: the override, else the vehicle file's."""
    lower, upper = overrides.get(name, (dv.lower_array, dv.upper_array))
    return (
        np.broadcast_to(np.asarray(lower, dtype=float), dv.shape),
        np.broadcast_to(np.asarray(upper, dtype=float), dv.shape),
    )


def trim_constraints(vehicle, condition, lateral_trim=True):
    """
    Return the trim constraints of a condition (its Table 6 rows), grouped by output.

    Parameters
    ----------
    vehicle : Vehicle
    condition : DesignCondition
    lateral_trim : bool
        Also the degenerate rows (:class:`~lpc_mdo.vehicle.condition_contract.TrimRow`).

    Returns
    -------
    list of (output, indices, targets, ref)
        One entry per acceleration output of the condition that has declared rows.
    """
    rows = [
        r
        for r in condition_kind(condition.kind).trim_rows(vehicle, condition)
        if lateral_trim or not r.degenerate
    ]
    out = []
    for output in ("linear_acceleration", "angular_acceleration"):
        mine = sorted((r for r in rows if r.output == output), key=lambda r: r.index)
        if mine:
            out.append(
                (output, [r.index for r in mine], np.array([r.target for r in mine]), mine[0].ref)
            )
    return out


def declare_problem(
    model,
    vehicle=None,
    *,
    static_margin=True,
    lateral_trim=True,
    constraint_kinds=CONSTRAINT_KINDS,
    design_variables=None,
    design_variable_refs=None,
    design_variable_bounds=None,
    objective=("gross_mass", None),
):
    """
    Declare the objective, design variables and constraints of a problem on ``model``.

    Call it before ``prob.setup()``. With the defaults it declares paper Table 6: the 161 design
    variables, our 10 transition roll/yaw speed differentials and 5 transition pitches; the 96
    constraints, and the gross-mass objective. Per condition, from its kind's contract: its design
    variables, its trim rows and its constraints (hover: noise, tip Mach; the cruise condition:
    static margin; structural: skin buckling; transition: each lift rotor's own speed within its
    pair's bounds, linear, ours); vehicle-level: final state of charge, radius intersection, the KS
    torque margins of the lift motors and the pusher motor and (not in the paper) their KS
    voltage margins.

    Parameters
    ----------
    model : LPCGroup
        Not yet set up (its ``conditions`` option says which conditions it holds).
    vehicle : Vehicle or None
        The model's vehicle (None: the model's option, else the reference vehicle).
    static_margin : bool
        Constrain the cruise static margin (paper Sec. V.B, with and without).
    lateral_trim : bool
        Declare every trim row of Table 6 (96 constraints). False leaves out the degenerate
        rows, which vanish for every design with zero gradients (hover p_dot by symmetry, the
        OEI v_dot: no side force in hover) or which no trim variable controls on its own (the
        transition v_dot: the rotors' net side force under the yaw differential, at most
        0.06 % of the weight at the optimum): 86 constraints.
    constraint_kinds : sequence of str
        Constraint kinds to declare, from :data:`CONSTRAINT_KINDS` (or
        :data:`TORQUE_MARGIN_KINDS` for one motor kind), plus any of
        :data:`OPTIONAL_CONSTRAINT_KINDS`.
    design_variables : sequence or None
        Vehicle-level design variables to declare: names, or (name, flat indices) pairs (None:
        all of them). The design variables of the included conditions are always declared.
    design_variable_refs : dict or None
        name -> ref overriding the vehicle file's scaling.
    design_variable_bounds : dict or None
        name -> (lower, upper) overriding the vehicle file's bounds (vehicle-file units,
        scalars or the variable's shape).
    objective : tuple
        (output, ref): ref None = the vehicle's target gross mass; ``("baseline", None)`` =
        the baseline design's penalised gross mass (eq. 8-9; needs a :class:`BaselineModel`).
    """
    vehicle = vehicle or model.options["vehicle"] or reference_vehicle()
    where = type(model).__name__
    conditions = included_conditions(vehicle, model.options["conditions"], where=where)
    layout = condition_layout(vehicle)
    limits = vehicle.constraints
    dvs = vehicle.design_variables
    refs = dict(design_variable_refs or {})
    bounds = dict(design_variable_bounds or {})
    for label, names in (("design_variable_bounds", bounds), ("design_variable_refs", refs)):
        for name in names:
            if name not in dvs:
                raise ValueError(f"{where}: option '{label}' names {name!r}; allowed: {list(dvs)}")
    wanted = set(constraint_kinds)
    allowed_kinds = CONSTRAINT_KINDS + TORQUE_MARGIN_KINDS + OPTIONAL_CONSTRAINT_KINDS
    unknown = sorted(wanted - set(allowed_kinds))
    if unknown:
        raise ValueError(
            f"{where}: option 'constraint_kinds' has unknown kinds {unknown}; "
            f"allowed: {allowed_kinds}"
        )
    if "static_margin" in wanted and not static_margin:
        wanted.discard("static_margin")

    # Design variables: the chosen vehicle-level ones, then those of the included conditions.
    condition_dvs = {e.design_variable for c in conditions for e in layout.entries[c.name].values()}
    owned = set(layout.design_variables)
    if design_variables is None:
        selection = {name: None for name in dvs if name not in owned}
    else:
        selection = {}
        for entry in design_variables:
            name, indices = (entry, None) if isinstance(entry, str) else entry
            if name not in dvs or name in owned:
                raise ValueError(
                    f"{where}: design variable {name!r} is not a vehicle-level "
                    f"design variable of the vehicle file; allowed: "
                    f"{[n for n in dvs if n not in owned]} (a condition's own "
                    f"design variables come with the condition)"
                )
            if isinstance(indices, str):  # lift groups or the pusher group of this layout
                indices = rotor_group_indices(
                    indices, dvs[name].shape, len(vehicle.lift_rotor_pairs)
                )
            selection[name] = None if indices is None else list(indices)
    selection.update({name: None for name in dvs if name in condition_dvs})
    if vehicle.masses.other_rule == "calibrated":  # W_dg is the calibration's target, fixed
        selection.pop(CLOSED_MASS, None)
    for name in dvs:  # in the vehicle file's order
        if name not in selection:
            continue
        indices, dv = selection[name], dvs[name]
        lower, upper = _bounds(name, dv, bounds)
        ref = refs.get(name, dv.ref)
        if indices is not None:
            lower, upper = lower.ravel()[indices], upper.ravel()[indices]
            ref = ref if np.ndim(ref) == 0 else np.asarray(ref).ravel()[indices]
        model.add_design_var(
            name,
            lower=lower,
            upper=upper,
            ref=ref,
            units=openmdao_units(dv.units),
            indices=indices,
            flat_indices=indices is not None,
        )

    if CLOSED_MASS in selection:
        # W_dg closed on the gross mass it gives: every optimum sizes the items that scale with
        # it (landing gear, wing secondary structure, systems) for its own weight.
        model.add_constraint(MASS_CLOSURE, equals=0.0, ref=10.0)

    name, ref = objective
    if name == "baseline":
        if not isinstance(model, BaselineModel):
            raise ValueError(
                f"{where}: objective ('baseline', ...) needs the model to be a "
                f"lpc_mdo.problems.BaselineModel, got {where}"
            )
        model.add_objective("baseline_objective", ref=1.0)
    else:
        model.add_objective(name, ref=vehicle.masses.design_gross_mass if ref is None else ref)

    # Each condition's trim rows and constraints, from its kind's contract.
    def bounds_of(dv_name):
        return _bounds(dv_name, dvs[dv_name], bounds)

    for c in conditions:
        if "trim" in wanted:
            for output, indices, targets, scale in trim_constraints(vehicle, c, lateral_trim):
                model.add_constraint(
                    f"{c.name}.{output}",
                    indices=indices,
                    flat_indices=True,
                    equals=targets,
                    ref=scale,
                )
        for con in condition_kind(c.kind).constraints(vehicle, c, bounds_of):
            if con.kind in wanted:
                model.add_constraint(f"{c.name}.{con.output}", **con.options)

    # Vehicle-level constraints.
    if "noise_footprint" in wanted and footprint_conditions(vehicle, conditions):
        footprint = vehicle.noise_footprint
        if footprint.max_sel is not None:
            model.add_constraint("footprint_sel_max", upper=footprint.max_sel, ref=10.0)
        if footprint.max_lamax is not None:
            model.add_constraint("footprint_lamax_max", upper=footprint.max_lamax, ref=10.0)
    if "soc" in wanted:
        model.add_constraint("state_of_charge", lower=limits.min_final_soc, ref=0.1)
    if "radius_intersection" in wanted:
        if not side_by_side_pairs(vehicle):
            raise ValueError(
                "the radius-intersection constraint needs two lift rotors side by side in a row; "
                f"the vehicle {vehicle.name!r} has one rotor per side in each row: choose a "
                "problem without it (the clearance constraints space the disks)"
            )
        model.add_constraint("radius_intersection", equals=limits.radius_intersection, ref=0.1)
    for con in clearance_constraints(vehicle):  # lpc_mdo.vehicle.clearances
        if con.kind in wanted:
            model.add_constraint(con.output, **con.options)
    if "min_chord" in wanted:  # every chord control point >= f R (linear; docs theory/rotors)
        model.add_constraint("blade_chord_margin", lower=0.0, ref=0.01, linear=True)
    motor_sets = set()
    for c in conditions:
        motor_sets.update(condition_kind(c.kind).motor_sets(vehicle, c))
    for prefix in sorted(motor_sets):
        if "torque_margin" in wanted or f"{prefix}_torque_margin" in wanted:
            model.add_constraint(
                f"{prefix}_motor_torque_margin", lower=limits.min_torque_margin, ref=0.1
            )
        if "voltage_margin" in wanted or f"{prefix}_voltage_margin" in wanted:
            model.add_constraint(
                f"{prefix}_motor_voltage_margin", lower=limits.min_voltage_margin, ref=0.1
            )


def attach_recorder(prob, path, design_variables=()):
    """
    Attach one SQLite recorder to the driver and the problem.

    The driver records every iteration and the problem ``'final'`` with every variable, so a
    single case file holds the run and what post-processing needs. Each driver case also holds
    every array named in ``design_variables`` (the vehicle file's design variables, 181 values
    for the reference), also those the problem does not vary, so that the last iteration of an
    interrupted run is a whole design to start from (:func:`lpc_mdo.warm_start.start_point`).
    """
    recorder = CaseRecorder(path)
    prob.driver.recording_options["includes"] = list(design_variables)
    prob.driver.add_recorder(recorder)
    prob.add_recorder(recorder)
    prob.recording_options["includes"] = ["*"]
    prob.recording_options["record_inputs"] = True  # fixed parameters too (sweep plots)


def copy_design_variables(source, target, vehicle, names=None):
    """
    Set the vehicle file's design-variable arrays of ``target`` from ``source``.

    ``target`` is a set-up problem, ``source`` a set-up problem or a recorded case; arrays are
    copied by name, in the vehicle file's units; arrays that either side lacks are skipped.
    """
    declared = target.model.get_design_vars() if hasattr(target, "model") else {}
    for name in names or vehicle.design_variables:
        dv = vehicle.design_variables[name]
        units = openmdao_units(dv.units)
        try:
            value = np.asarray(source.get_val(name, units=units)).reshape(dv.shape)
        except KeyError:
            continue
        meta = declared.get(name)
        if meta is not None and meta.get("units") == units:
            value = _onto_bounds(value, meta.get("lower"), meta.get("upper"))
        try:
            target.set_val(name, value, units=units)
        except KeyError:
            continue


def _onto_bounds(value, lower, upper, rel=1e-9):
    """
    Return ``value`` with elements within round-off outside a bound put on it.

    A design variable recorded on its bound comes back a few ulps outside after a unit
    conversion (fuselage length 21 ft = 6.4008 m), and OpenMDAO then warns that the start is
    out of bounds; anything further out is left for that warning.
    """
    value = np.array(value, dtype=float)
    for bound, outside in ((lower, np.less), (upper, np.greater)):
        bound = None if bound is None else np.asarray(bound, dtype=float).reshape(-1)
        if bound is None or bound.size not in (1, value.size):
            continue  # no bound, or bounds on some indices only (left to OpenMDAO)
        bound = np.broadcast_to(bound, value.size).reshape(value.shape)
        slack = rel * np.maximum(1.0, np.abs(bound))
        near = outside(value, bound) & (np.abs(value - bound) <= slack)
        value[near] = bound[near]
    return value


def build_analysis_problem(
    vehicle=None,
    recorder_path=None,
    name="analysis",
    comm=None,
    work_dir=None,
    design_problem=True,
    **options,
):
    """
    Build the full lift-plus-cruise model of a vehicle at its initial design, ready to run.

    Parameters
    ----------
    vehicle : Vehicle, str, os.PathLike or None
        A vehicle, a vehicle file, or None for the reference vehicle.
    recorder_path : str or os.PathLike or None
        SQLite case file for a problem recorder (record with ``prob.record('final')``); it
        records every variable, so post-processing needs nothing else.
    name : str
        Problem name; OpenMDAO writes reports and outputs under ``{name}_out``.
    comm : MPI communicator or None
        The problem's communicator (MPI.COMM_SELF for one problem per rank).
    work_dir : str or None
        Where OpenMDAO puts ``{name}_out`` (None: the current directory).
    design_problem : bool
        Also declare the problem (:func:`declare_problem`; for constraint tables, totals and
        trim): design variables, constraints and objective.
    **options
        :data:`PROBLEM_OPTIONS` go to :func:`declare_problem`, the rest to
        :class:`~lpc_mdo.groups.lpc.LPCGroup` (``conditions``, ``rotor_polar``, ...).

    Returns
    -------
    om.Problem
        A problem that has been set up; ``prob.vehicle`` is the vehicle.
    """
    if vehicle is None or isinstance(vehicle, (str, os.PathLike)):
        vehicle = load_vehicle(vehicle)
    problem_options = {k: options.pop(k) for k in PROBLEM_OPTIONS if k in options}
    kwargs = {} if work_dir is None else {"work_dir": str(work_dir)}
    model = LPCGroup(vehicle=vehicle, **options)
    if design_problem:
        declare_problem(model, vehicle, **problem_options)
    prob = om.Problem(model=model, name=name, comm=comm, **kwargs)
    if recorder_path is not None:
        prob.add_recorder(CaseRecorder(recorder_path))
        prob.recording_options["includes"] = ["*"]
        prob.recording_options["record_inputs"] = True
    prob.setup(mode="rev")
    prob.vehicle = vehicle
    return prob


def conditions_of_kinds(vehicle, kinds):
    """Names of the vehicle's conditions of the given kinds, in vehicle-file order."""
    names = [c.name for c in vehicle.conditions if c.kind in kinds]
    if not names:
        raise ValueError(
            f"the vehicle has no condition of kind {list(kinds)}; its conditions: "
            f"{[(c.name, c.kind) for c in vehicle.conditions]}"
        )
    return names


def trust_region_bounds(vehicle, fractions):
    """
    Bounds within a fraction of each design variable's initial value, inside the file's bounds.

    Parameters
    ----------
    vehicle : Vehicle
    fractions : dict
        name -> f: bounds initial * (1 -+ f) (of abs(initial)), intersected with the vehicle file's.

    Returns
    -------
    dict
        name -> (lower, upper) arrays, for :func:`declare_problem`'s ``design_variable_bounds``.
    """
    bounds = {}
    for name, f in fractions.items():
        dv = vehicle.design_variables[name]
        x0 = np.asarray(dv.initial_array, dtype=float)
        lower = np.maximum(np.asarray(dv.lower_array, dtype=float), x0 - f * np.abs(x0))
        upper = np.minimum(np.asarray(dv.upper_array, dtype=float), x0 + f * np.abs(x0))
        bounds[name] = (lower.reshape(dv.shape), upper.reshape(dv.shape))
    return bounds


def build_problem(
    name,
    vehicle=None,
    static_margin=True,
    optimizer=None,
    recorder_path=None,
    design_variable_refs=None,
    driver_settings=None,
    lateral_trim=False,
    comm=None,
    in_sequence=False,
    **model_options,
):
    """
    Return the problem of a stage of the study (:mod:`lpc_mdo.study_plan`) with its driver.

    Parameters
    ----------
    name : str
        A stage of :data:`lpc_mdo.study_plan.STAGE_NAMES`: 'rotor_presizing', the paper's
        warm-start subproblems 'subproblem_1' .. 'subproblem_4' (Table 2), the full problem
        'full' (Table 6), or 'baseline' (the full problem with the objective of eq. 8: the
        feasible design closest to the initial one).
    vehicle : Vehicle, path or None
    static_margin : bool
        Include the cruise static-margin constraint (subproblem 4 and the full problem).
    optimizer : str or None
        For :func:`lpc_mdo.drivers.make_driver` (None: the stage's,
        :func:`lpc_mdo.study_plan.default_optimizer`).
    recorder_path : str or None
        One case file for the driver iterations and the final problem case (record it with
        ``prob.record('final')``).
    design_variable_refs : dict or None
        Design-variable scaling overrides (the warm start sets them from optimized magnitudes).
    driver_settings : dict or None
        Passed to make_driver, over the stage's settings of the optimizer
        (:meth:`lpc_mdo.study_plan.Stage.driver_settings`).
    lateral_trim : bool
        Also constrain hover p_dot, the OEI v_dot and the transition v_dot. Paper Table 6
        counts them (96 constraints), but the first two vanish for every design (symmetry; no
        side force in hover): zero gradients that violate the constraint qualification (SLSQP
        stops on a singular matrix, IPOPT's dual infeasibility explodes); and no trim variable
        acts on the transition v_dot on its own (the rotors' net side force under the yaw
        differential; at most 0.06 % of the weight at the optimum). Optimizations leave them out
        (86 constraints) and the report evaluates all 96 at the final design.
    comm : MPI communicator or None
        The problem's communicator (MPI.COMM_SELF for one problem per rank, as in sweeps).
    in_sequence : bool
        The stage's optimizer settings as a step of the warm-start sequence
        (``sequence_options`` of its :class:`~lpc_mdo.study_plan.Stage`) instead of those of
        the problem solved on its own.
    **model_options
        Further :func:`declare_problem` options (:data:`PROBLEM_OPTIONS`) and model options
        (:class:`~lpc_mdo.groups.lpc.LPCGroup`; ``baseline_alpha`` of :class:`BaselineModel`).

    Returns
    -------
    om.Problem
        Set up, not run.
    """
    spec = stage(name)
    optimizer = optimizer or default_optimizer(name)
    if vehicle is None or isinstance(vehicle, (str, os.PathLike)):
        vehicle = load_vehicle(vehicle)
    problem_options = {k: model_options.pop(k) for k in PROBLEM_OPTIONS if k in model_options}
    conditions = None if spec.every_condition else conditions_of_kinds(vehicle, spec.kinds)
    output, ref = spec.objective
    if output not in ("gross_mass", "baseline"):
        output = f"{conditions[0]}.{output}"
    problem_options.setdefault("objective", (output, ref))
    if spec.trust_region:
        problem_options.setdefault(
            "design_variable_bounds", trust_region_bounds(vehicle, spec.trust_region)
        )
    baseline = output == "baseline"
    if not baseline:
        model_options.pop("baseline_alpha", None)
    model_cls = BaselineModel if baseline else LPCGroup
    model = model_cls(vehicle=vehicle, conditions=conditions, **model_options)
    declare_problem(
        model,
        vehicle,
        static_margin=static_margin,
        design_variables=spec.design_variables,
        constraint_kinds=spec.constraint_kinds or CONSTRAINT_KINDS,
        design_variable_refs=design_variable_refs,
        lateral_trim=lateral_trim,
        **problem_options,
    )
    prob = om.Problem(model=model, name=name, reports=False, comm=comm)
    settings = {**spec.driver_settings(optimizer, in_sequence), **(driver_settings or {})}
    prob.driver = make_driver(optimizer, **settings)
    if recorder_path is not None:
        attach_recorder(prob, recorder_path, vehicle.design_variables)
    prob.setup(mode="rev")
    prob.vehicle = vehicle
    return prob
