"""The study's stage table: what each stage of the warm-start study solves, and how.

The warm start of paper Sec. II.E and Fig. 8 solves a sequence of stages (the subproblems of
paper Table 2, then the full problem of Table 6), each started from the previous stage's final
case. Every stage is declared here, once, as a :class:`Stage`: its problem (the condition kinds
it includes, its vehicle-level design variables, its constraint kinds, its objective, the trust
region of its bounds), its default optimizer with that optimizer's settings (tolerance,
iteration limit, acceptable-point stop), whether its conditions are trimmed before the
optimizer runs, and how it takes over the previous stage's result.
:func:`lpc_mdo.problems.build_problem`, :func:`lpc_mdo.warm_start.run_sequence`,
``lpc-mdo optimize`` and the theory manual (page "The optimization problem", which renders this
table and gives the reasons for its numbers) all read it from here.

Settings of a stage
-------------------
A stage has two sets of optimizer settings: ``options``, when it is solved as a problem of its
own (``build_problem(name)``, ``lpc-mdo optimize --problem name``), and ``sequence_options``,
when it is a step of the warm-start sequence before the full problem, where it only provides a
start and a scaling and therefore stops sooner (None: the same as ``options``). Both are given
per optimizer, since ``--optimizer`` may run any stage with any of them; settings a caller
passes (``driver_settings``) go over them.
"""

from dataclasses import dataclass, field, replace
from types import MappingProxyType

import numpy as np

from lpc_mdo import drivers

__all__ = [
    "HANDOVERS",
    "ITERATION_LIMIT",
    "LIFT_GROUPS",
    "OWN_OPTIONS",
    "PUSHER_GROUP",
    "SEQUENCE",
    "SEQUENCE_OPTIONS",
    "SQP",
    "STAGES",
    "STAGE_NAMES",
    "AcceptablePoint",
    "OptimizerOptions",
    "Stage",
    "default_optimizer",
    "rotor_group_indices",
    "run_rows",
    "settings_rows",
    "stage",
    "stage_rows",
]

#: Stand-in for an SQP method: SNOPT where pyoptsparse has it, else SciPy's SLSQP.
SQP = "SQP"
#: How a stage starts from the previous stage's final case: every design-variable array copied
#: by name; or copied and every design variable scaled by its magnitude there (paper Sec. II.E).
HANDOVERS = ("design", "design and scaling")

# make_driver keyword of each setting, per optimizer (IpoptDriver: tol and max_iter are options,
# the acceptable_* ones IPOPT options; SlsqpDriver: all options, max_iter as maxiter).
_SETTING_NAMES = {
    "IPOPT": {
        "tol": "tol",
        "max_iter": "max_iter",
        "iterations": "acceptable_iter",
        "constraint_violation": "acceptable_constr_viol_tol",
        "acceptable_tol": "acceptable_tol",
    },
    "SLSQP": {
        "tol": "tol",
        "max_iter": "max_iter",
        "iterations": "acceptable_iter",
        "constraint_violation": "acceptable_constr_viol",
        "objective_change": "acceptable_obj_change",
    },
    "SNOPT": {},
}


@dataclass(frozen=True)
class AcceptablePoint:
    """
    Stop at an acceptable point: an iterate that is feasible enough and no longer improving.

    IPOPT's ``acceptable_*`` options (Wachter and Biegler 2006, Sec. 3.9) and those of
    :class:`~lpc_mdo.drivers.SlsqpDriver`, all in the driver's scaled space.

    Attributes
    ----------
    iterations : int
        IPOPT: iterations an acceptable point has to persist (``acceptable_iter``); SLSQP: the
        window of the objective change (``acceptable_iter``).
    constraint_violation : float
        Largest constraint violation of an acceptable iterate (IPOPT
        ``acceptable_constr_viol_tol``, SLSQP ``acceptable_constr_viol``).
    tol : float or None
        IPOPT only: the scaled NLP error of an acceptable iterate (``acceptable_tol``).
    objective_change : float or None
        SLSQP only: relative objective change over the window below which the run has
        stalled (``acceptable_obj_change``).
    """

    iterations: int
    constraint_violation: float
    tol: float | None = None
    objective_change: float | None = None


@dataclass(frozen=True)
class OptimizerOptions:
    """
    The settings of one optimizer in one stage.

    Attributes
    ----------
    tol : float or None
        Convergence tolerance in the driver's scaled space (None: the driver's default, 1e-6
        for :class:`~lpc_mdo.drivers.IpoptDriver`).
    max_iter : int or None
        Iteration limit (IPOPT ``max_iter``, SLSQP ``maxiter``; None: the optimizer's own).
    acceptable : AcceptablePoint or None
        The acceptable-point stop (None: the driver's default).
    """

    tol: float | None = None
    max_iter: int | None = None
    acceptable: AcceptablePoint | None = None

    def driver_settings(self, optimizer):
        """
        Return the settings as :func:`lpc_mdo.drivers.make_driver` keywords.

        Parameters
        ----------
        optimizer : str
            ``'IPOPT'``, ``'SLSQP'`` or ``'SNOPT'`` (any case).

        Returns
        -------
        dict
            Keyword -> value for every setting that is not None.

        Raises
        ------
        ValueError
            For a setting the optimizer has no keyword for.
        """
        values = {"tol": self.tol, "max_iter": self.max_iter}
        if self.acceptable is not None:
            values.update(
                iterations=self.acceptable.iterations,
                constraint_violation=self.acceptable.constraint_violation,
                acceptable_tol=self.acceptable.tol,
                objective_change=self.acceptable.objective_change,
            )
        names = _SETTING_NAMES[optimizer.upper()]
        settings = {}
        for name, value in values.items():
            if value is None:
                continue
            if name not in names:
                raise ValueError(
                    f"study plan: {optimizer} has no setting for {name} = {value}; "
                    f"allowed: {list(names)}"
                )
            settings[names[name]] = value
        return settings

    def summary(self):
        """Return the settings in a few words (the docs' table)."""
        parts = ["driver's default tol" if self.tol is None else f"tol {_number(self.tol)}"]
        if self.max_iter is not None:
            parts.append(f"{self.max_iter} iterations")
        point = self.acceptable
        if point is not None:
            words = [
                f"{point.iterations} iterations",
                f"violation {_number(point.constraint_violation)}",
            ]
            if point.tol is not None:
                words.append(f"error {_number(point.tol)}")
            if point.objective_change is not None:
                words.append(f"objective change {_number(point.objective_change)}")
            parts.append(f"acceptable: {', '.join(words)}")
        return "; ".join(parts)


def _number(value):
    """Return a number as the docs write it: 3e-4, 0.2, 100, 5e5."""
    if value and not 1e-2 <= abs(value) < 1e4:
        mantissa, exponent = f"{value:e}".split("e")
        return f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"
    return f"{value:g}"


def _frozen(mapping):
    return MappingProxyType(dict(mapping))


@dataclass(frozen=True)
class Stage:
    """
    One stage of the study: a problem, its optimizer, and how it joins the sequence.

    Attributes
    ----------
    name : str
        The name of the problem (``build_problem(name)``, ``--problem name``).
    summary : str
        What the stage sizes, in which conditions (CLI help, docs).
    kinds : tuple of str or None
        Condition kinds it includes, selected by kind, never by name (None: every condition).
        The design variables of the included conditions (rotor speeds, pitch, elevator)
        always come with them.
    design_variables : tuple or None
        Vehicle-level design variables: names, or (name, flat indices) pairs (None: all).
    constraint_kinds : tuple of str or None
        Constraint kinds of :func:`lpc_mdo.problems.declare_problem` (None: every kind of
        paper Table 6, :data:`lpc_mdo.problems.CONSTRAINT_KINDS`).
    objective : tuple
        (output, ref): ``'gross_mass'`` (ref None: the vehicle's design gross mass),
        ``'baseline'`` (the penalised gross mass of paper eq. 8-9), or an output of the stage's
        first condition.
    trust_region : Mapping
        Design variable -> f: bounds within initial * (1 -+ f), inside the vehicle file's
        (:func:`lpc_mdo.problems.trust_region_bounds`).
    optimizer : str
        Default optimizer: ``'IPOPT'``, ``'SLSQP'`` or :data:`SQP` (:func:`default_optimizer`).
    options : Mapping
        Optimizer name -> :class:`OptimizerOptions` of the stage solved on its own.
    sequence_options : Mapping or None
        Optimizer name -> :class:`OptimizerOptions` of the stage as a step of the warm-start
        sequence (None: ``options``).
    trim_first : bool
        Trim the stage's conditions by their trim variables before its optimizer runs
        (:func:`lpc_mdo.trim.trim`).
    handover : str
        How the stage starts from the previous stage's final case, one of :data:`HANDOVERS`.
    in_sequence : bool
        A stage of the default warm-start sequence (:data:`SEQUENCE`).
    continuation : tuple of float
        Penalty weights alpha of paper eq. 8, solved in turn, each from the previous one
        (:func:`lpc_mdo.warm_start.solve_baseline`); empty for a single solve.
    """

    name: str
    summary: str
    optimizer: str
    options: MappingProxyType
    kinds: tuple | None = None
    design_variables: tuple | None = None
    constraint_kinds: tuple | None = None
    objective: tuple = ("gross_mass", None)
    trust_region: MappingProxyType = field(default_factory=lambda: _frozen({}))
    sequence_options: MappingProxyType | None = None
    trim_first: bool = True
    handover: str = "design"
    in_sequence: bool = True
    continuation: tuple = ()

    def __post_init__(self):
        where = f"study plan: stage '{self.name}'"
        if self.optimizer not in (*drivers.KNOWN_OPTIMIZERS, SQP):
            raise ValueError(
                f"{where}: optimizer = {self.optimizer!r}; allowed: "
                f"{[*drivers.KNOWN_OPTIMIZERS, SQP]}"
            )
        if self.handover not in HANDOVERS:
            raise ValueError(f"{where}: handover = {self.handover!r}; allowed: {HANDOVERS}")
        if self.kinds is None and self.objective[0] not in ("gross_mass", "baseline"):
            raise ValueError(
                f"{where}: objective {self.objective[0]!r} is an output of a condition, "
                "which needs the stage's condition kinds"
            )
        for label in ("options", "sequence_options"):
            mapping = getattr(self, label)
            if mapping is None:
                continue
            missing = sorted(set(drivers.KNOWN_OPTIMIZERS) - set(mapping))
            if missing:
                raise ValueError(f"{where}: {label} has no settings for {missing}")
            for optimizer, options in mapping.items():
                options.driver_settings(optimizer)  # a setting the optimizer lacks raises
            object.__setattr__(self, label, _frozen(mapping))
        object.__setattr__(self, "trust_region", _frozen(self.trust_region))

    @property
    def every_condition(self):
        """Whether the stage includes every condition (the full problem and the baseline)."""
        return self.kinds is None

    @property
    def rescales(self):
        """Whether the hand-over also scales each design variable by its magnitude."""
        return self.handover == "design and scaling"

    def optimizer_options(self, optimizer, in_sequence=False):
        """
        Return the :class:`OptimizerOptions` of an optimizer in this stage.

        Parameters
        ----------
        optimizer : str
            ``'IPOPT'``, ``'SLSQP'`` or ``'SNOPT'`` (any case).
        in_sequence : bool
            As a step of the warm-start sequence (``sequence_options``).

        Returns
        -------
        OptimizerOptions
            Empty for an optimizer name the table does not know (the driver factory then says
            which names it accepts).
        """
        table = self.sequence_options if in_sequence and self.sequence_options else self.options
        return table.get(optimizer.upper(), OptimizerOptions())

    def driver_settings(self, optimizer, in_sequence=False):
        """
        Return the stage's settings of an optimizer as :func:`lpc_mdo.drivers.make_driver` keywords.

        Parameters
        ----------
        optimizer : str
            ``'IPOPT'``, ``'SLSQP'`` or ``'SNOPT'`` (any case).
        in_sequence : bool
            As a step of the warm-start sequence (``sequence_options``).

        Returns
        -------
        dict
        """
        options = self.optimizer_options(optimizer, in_sequence)
        name = optimizer.upper()
        return options.driver_settings(name) if name in _SETTING_NAMES else {}


# --------------------------------------------------------------------------- the table

#: Iteration limit of every stage; also the default of IpoptDriver and SlsqpDriver.
ITERATION_LIMIT = 200

#: A stage solved as a problem of its own (and the full problem in the sequence).
OWN_OPTIONS = _frozen(
    {
        "IPOPT": OptimizerOptions(
            max_iter=ITERATION_LIMIT,
            acceptable=AcceptablePoint(iterations=10, constraint_violation=1e-4, tol=1e-4),
        ),
        "SLSQP": OptimizerOptions(
            tol=3e-4,
            max_iter=ITERATION_LIMIT,
            acceptable=AcceptablePoint(
                iterations=12, constraint_violation=3e-4, objective_change=5e-4
            ),
        ),
        "SNOPT": OptimizerOptions(),
    }
)

#: Row selections of the per-rotor-group design variables (rotor_radius, blade_chord_cp,
#: blade_twist_cp, motor_length, motor_rated_current), resolved against the vehicle's layout by
#: :func:`rotor_group_indices`: every lift-rotor pair's rows, or the pusher's row.
LIFT_GROUPS, PUSHER_GROUP = "lift groups", "pusher group"


def rotor_group_indices(selection, shape, num_pairs):
    """
    Return the flat indices of a rotor-group row selection in a design variable of ``shape``.

    ``shape[0]`` counts the rotor groups (the ``num_pairs`` lift pairs, then the pusher); each
    row holds ``prod(shape[1:])`` values (the 4 blade control points, or one).
    """
    per_row = int(np.prod(shape[1:], dtype=int))
    rows = range(num_pairs) if selection == LIFT_GROUPS else [num_pairs]
    return tuple(r * per_row + k for r in rows for k in range(per_row))


#: A stage before the full problem, as a step of the sequence: a start and a scaling.
SEQUENCE_OPTIONS = _frozen(
    {
        "IPOPT": OptimizerOptions(
            tol=1e-4,
            max_iter=ITERATION_LIMIT,
            acceptable=AcceptablePoint(iterations=5, constraint_violation=1e-3, tol=1e-3),
        ),
        "SLSQP": replace(OWN_OPTIONS["SLSQP"], tol=1e-3),
        "SNOPT": OptimizerOptions(),
    }
)

#: The stages, in the order of the sequence (the baseline last, outside it).
STAGES = (
    Stage(
        name="rotor_presizing",
        summary="lift rotors sized for the hover noise limit at minimum hover power "
        "(lpc-mdo's, before the paper's subproblems)",
        kinds=("hover",),
        design_variables=(
            ("rotor_radius", LIFT_GROUPS),
            ("blade_chord_cp", LIFT_GROUPS),
            ("blade_twist_cp", LIFT_GROUPS),
        ),
        constraint_kinds=("trim", "noise", "tip_mach", "clearance", "blade_stall"),
        objective=("electrical_power", 5.0e5),  # W, of the (first) hover condition
        optimizer="SLSQP",
        options={
            **OWN_OPTIONS,
            "IPOPT": OptimizerOptions(
                tol=1e-3,
                max_iter=ITERATION_LIMIT,
                acceptable=AcceptablePoint(iterations=10, constraint_violation=1e-3, tol=1e-3),
            ),
        },
        sequence_options=SEQUENCE_OPTIONS,
    ),
    Stage(
        name="subproblem_1",
        summary="rotors, battery and pusher motor in hover, transition, climb, cruise and "
        "descent (paper Table 2)",
        kinds=("hover", "transition", "steady"),
        design_variables=(
            "battery_mass",
            "design_gross_mass",
            ("motor_length", PUSHER_GROUP),
            ("motor_rated_current", PUSHER_GROUP),
            "rotor_radius",
            "blade_chord_cp",
            "blade_twist_cp",
        ),
        constraint_kinds=(
            "trim",
            "noise",
            "soc",
            "pusher_torque_margin",
            "rotor_speed",
            "advance_ratio",
            "tip_mach",
            "min_chord",
            "pusher_voltage_margin",
            "clearance",
            "wing_stall",
            "blade_stall",
        ),
        trust_region={"battery_mass": 0.2},  # the reference code's bounds
        optimizer="SLSQP",
        options=OWN_OPTIONS,
        sequence_options=SEQUENCE_OPTIONS,
    ),
    Stage(
        name="subproblem_2",
        summary="lift motors in the one-rotor-out cases (paper Table 2) and, for the control "
        "reserve, in hover",
        kinds=("hover", "oei"),
        design_variables=(("motor_length", LIFT_GROUPS), ("motor_rated_current", LIFT_GROUPS)),
        constraint_kinds=("trim", "lift_torque_margin", "lift_voltage_margin", "control_reserve"),
        optimizer="IPOPT",
        options=OWN_OPTIONS,
        sequence_options=SEQUENCE_OPTIONS,
    ),
    Stage(
        name="subproblem_3",
        summary="wing box at +3g and -1g (paper Table 2)",
        kinds=("structural",),
        design_variables=(
            "front_spar_thickness",
            "rear_spar_thickness",
            "top_skin_thickness",
            "bottom_skin_thickness",
        ),
        constraint_kinds=("trim", "buckling", "stress"),
        optimizer="SLSQP",
        options=OWN_OPTIONS,
        sequence_options=SEQUENCE_OPTIONS,
    ),
    Stage(
        name="subproblem_4",
        summary="planform in climb, cruise and descent (paper Table 2: cruise)",
        kinds=("steady",),
        design_variables=(
            "wing_area",
            "wing_aspect_ratio",
            "htail_area",
            "htail_aspect_ratio",
            "fuselage_length",
            "design_gross_mass",
        ),
        constraint_kinds=("trim", "static_margin", "clearance", "wing_stall"),
        optimizer="IPOPT",
        options=OWN_OPTIONS,
        sequence_options=SEQUENCE_OPTIONS,
        handover="design and scaling",
    ),
    Stage(
        name="full",
        summary="every design variable and constraint over every condition (paper Table 6)",
        optimizer=SQP,
        options=OWN_OPTIONS,
        handover="design and scaling",
    ),
    Stage(
        name="baseline",
        summary="the feasible design closest to the initial one (paper eq. 8-9), by "
        "continuation in the penalty weight",
        objective=("baseline", None),
        optimizer=SQP,
        options=OWN_OPTIONS,
        handover="design and scaling",
        in_sequence=False,
        continuation=(1.0, 10.0, 100.0),
    ),
)

#: Every stage's name: the problems ``build_problem`` and ``lpc-mdo optimize --problem`` know.
STAGE_NAMES = tuple(s.name for s in STAGES)
#: The default warm-start sequence (``lpc-mdo optimize`` without ``--problem``).
SEQUENCE = tuple(s.name for s in STAGES if s.in_sequence)
_BY_NAME = {s.name: s for s in STAGES}


def stage(name):
    """
    Return the :class:`Stage` of a name.

    Parameters
    ----------
    name : str
        One of :data:`STAGE_NAMES`.

    Returns
    -------
    Stage

    Raises
    ------
    ValueError
        For another name, listing the allowed ones.
    """
    try:
        return _BY_NAME[name]
    except (KeyError, TypeError):
        raise ValueError(f"problem name = {name!r}; allowed: {STAGE_NAMES}") from None


def default_optimizer(name):
    """
    Return the default optimizer of a stage: its table entry, with :data:`SQP` resolved.

    Parameters
    ----------
    name : str
        One of :data:`STAGE_NAMES`.

    Returns
    -------
    str
        ``'IPOPT'``, ``'SLSQP'``, or ``'SNOPT'`` for an SQP stage when pyoptsparse has SNOPT.
    """
    optimizer = stage(name).optimizer
    if optimizer != SQP:
        return optimizer
    return "SNOPT" if "SNOPT" in drivers.pyoptsparse_optimizers() else "SLSQP"


# --------------------------------------------------------------------------- text of the table


def _design_variables_text(entries):
    if entries is None:
        return "all"
    words = []
    for entry in entries:
        name, indices = (entry, None) if isinstance(entry, str) else entry
        words.append(name if indices is None else f"{name}{_indices_text(indices)}")
    return ", ".join(words)


def _indices_text(indices):
    if isinstance(indices, str):
        return f"[{indices}]"
    indices = list(indices)
    if len(indices) > 2 and indices == list(range(indices[0], indices[-1] + 1)):
        return f"[{indices[0]}..{indices[-1]}]"
    return "[" + ", ".join(str(i) for i in indices) + "]"


def _objective_text(objective):
    output, ref = objective
    if output == "gross_mass":
        return "gross mass"
    if output == "baseline":
        return "gross mass + alpha x deviation (eq. 8)"
    return f"{output.replace('_', ' ')} of the first condition" + (
        "" if ref is None else f" (ref {_number(ref)})"
    )


def stage_rows():
    """
    Return the problem of every stage as text: a header and one row per stage.

    Returns
    -------
    tuple of (list of str, list of list of str)
        Columns: stage, what it sizes, condition kinds, vehicle-level design variables,
        constraint kinds, objective, trust region.
    """
    header = [
        "stage",
        "sizes",
        "condition kinds",
        "vehicle-level design variables",
        "constraint kinds",
        "objective",
        "trust region",
    ]
    rows = [
        [
            s.name,
            s.summary,
            ", ".join(s.kinds) if s.kinds else "all",
            _design_variables_text(s.design_variables),
            ", ".join(s.constraint_kinds) if s.constraint_kinds else "all (Table 6)",
            _objective_text(s.objective),
            ", ".join(f"{n} ±{f:.0%}" for n, f in s.trust_region.items()) or "-",
        ]
        for s in STAGES
    ]
    return header, rows


def run_rows():
    """
    Return how every stage runs as text: a header and one row per stage.

    Returns
    -------
    tuple of (list of str, list of list of str)
        Columns: stage, default optimizer, trim first, hand-over, in the sequence.
    """
    header = ["stage", "default optimizer", "trim first", "hand-over", "in the sequence"]
    rows = []
    for s in STAGES:
        optimizer = "SQP: SNOPT, else SLSQP" if s.optimizer == SQP else s.optimizer
        if s.continuation:
            alphas = ", ".join(_number(a) for a in s.continuation)
            optimizer += f"; alpha = {alphas} in turn"
        rows.append(
            [
                s.name,
                optimizer,
                "yes" if s.trim_first else "no",
                s.handover,
                f"step {SEQUENCE.index(s.name) + 1}" if s.in_sequence else "no",
            ]
        )
    return header, rows


def settings_rows():
    """
    Return every stage's optimizer settings as text: a header and one row per stage and optimizer.

    Returns
    -------
    tuple of (list of str, list of list of str)
        Columns: stage, optimizer, the settings when the stage is solved on its own, and as a
        step of the sequence (SNOPT takes its own defaults everywhere).
    """
    header = ["stage", "optimizer", "on its own", "as a step of the sequence"]
    rows = []
    for s in STAGES:
        for optimizer in ("IPOPT", "SLSQP"):
            if not s.in_sequence:
                sequence = "-"
            elif s.sequence_options is None:
                sequence = "as on its own"
            else:
                sequence = s.optimizer_options(optimizer, in_sequence=True).summary()
            rows.append([s.name, optimizer, s.optimizer_options(optimizer).summary(), sequence])
    return header, rows
