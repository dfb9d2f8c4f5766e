"""The condition contract: what every design-condition group declares about itself.

A design condition of the vehicle file (``[[conditions]]``) is built by the group class of its
``kind`` (:mod:`lpc_mdo.groups.condition_kinds`). Besides building its subsystems, that class
declares, in one place, everything the assembly (:class:`~lpc_mdo.groups.lpc.LPCGroup`), the
problem specification (:mod:`lpc_mdo.problems`) and the post-processing need to know about it:

- :meth:`ConditionGroup.check`: the kind's rules on the vehicle-file fields;
- :meth:`ConditionGroup.variables`: the design variables it owns (trim variables such as rotor
  speeds, pitch, elevator), with their shape per condition; :func:`condition_layout` names them
  and stacks the conditions that share a ``design_variable_prefix`` into one table;
- :meth:`ConditionGroup.vehicle_inputs`: the vehicle-level outputs it reads (connections);
- :meth:`ConditionGroup.trim_rows`: its rows of the paper's Table 6 trim constraints;
- :meth:`ConditionGroup.constraints`: its other constraints (noise, tip Mach, buckling, ...);
- :meth:`ConditionGroup.motor_sets`: the motors it runs, whose torque margins the assembly
  aggregates over the conditions (paper eq. 7);
- :attr:`ConditionGroup.power_output`: its electrical power, which the mission energy weighs by
  the condition's ``energy_weight`` (vehicle file).

Every declaration is a class method of (vehicle, condition), so it is known before any model is
set up: the vehicle file is validated and the problem declared from the same declarations that
wire the model. The pattern follows pyCycle's elements, which declare their own default
connections, and Aviary's subsystem builders, which declare their own design variables and
constraints.
"""

import dataclasses
import functools
import math

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.polar import LinearQuadraticPolar, Polar
from lpc_mdo.core.constants import GRAVITY
from lpc_mdo.vehicle import VehicleSpecError

#: Body-axis components of the trim rows: linear (u, v, w) and angular (p, q, r) accelerations.
LINEAR_COMPONENTS = ("u", "v", "w")
ANGULAR_COMPONENTS = ("p", "q", "r")


@dataclasses.dataclass(frozen=True)
class ConditionVariable:
    """
    A design variable that a condition owns.

    Attributes
    ----------
    name : str
        The condition group's promoted input it drives, and the suffix of the design variable:
        the vehicle file's design variable is ``{design_variable_prefix}_{name}`` (see
        :func:`condition_layout`), one name for the quantity through the model.
    target_shape : tuple of int
        Shape of that input; the condition's entries of the design variable are flattened into
        it.
    shape : tuple of int
        Shape of the condition's own entries (``(1,)`` for a scalar).
    units : str
        OpenMDAO units (``"unitless"`` for none).
    description : str
        What it is and how its entries are ordered.
    initial_from : str
        A field of the condition whose value is the initial value (e.g. ``"pitch"``), or ``""``
        when the design-variable table of the vehicle file gives it.
    trim : bool
        Whether it is a trim variable of the condition (paper Table 6), which
        :func:`lpc_mdo.trim.trim_vehicle` solves for.
    """

    name: str
    target_shape: tuple
    shape: tuple
    units: str
    description: str
    initial_from: str = ""
    trim: bool = True

    @property
    def size(self):
        """Number of entries per condition."""
        return math.prod(self.shape)


@dataclasses.dataclass(frozen=True)
class TrimRow:
    """
    One trim row of paper Table 6: a body-axis acceleration equals its target.

    Attributes
    ----------
    component : str
        ``u``, ``v``, ``w`` (linear, m/s**2) or ``p``, ``q``, ``r`` (angular, rad/s**2).
    target : float
        Required acceleration: 0, or the prescribed one of a transition point.
    ref : float
        Constraint scaling reference (g abs(n) for the linear rows, 1 rad/s**2 for the angular).
    degenerate : bool
        True for a row that vanishes for every design or that no trim variable controls on its
        own: declared only when a problem asks for every row (``lateral_trim``); the
        post-processing evaluates it anyway.
    """

    component: str
    target: float = 0.0
    ref: float = 1.0
    degenerate: bool = False

    @property
    def output(self):
        """The condition output that holds the acceleration."""
        linear = self.component in LINEAR_COMPONENTS
        return "linear_acceleration" if linear else "angular_acceleration"

    @property
    def index(self):
        """Index of the component in :attr:`output`."""
        if self.component in LINEAR_COMPONENTS:
            return LINEAR_COMPONENTS.index(self.component)
        return ANGULAR_COMPONENTS.index(self.component)

    @property
    def units(self):
        """Units of the acceleration."""
        return "m/s**2" if self.component in LINEAR_COMPONENTS else "rad/s**2"


@dataclasses.dataclass(frozen=True)
class ConditionConstraint:
    """
    A constraint a condition declares on one of its outputs (besides the trim rows).

    Attributes
    ----------
    kind : str
        Constraint kind a problem selects by (``noise``, ``tip_mach``, ``static_margin``,
        ``buckling``, ``rotor_speed``).
    output : str
        Output of the condition group (promoted, relative to it).
    options : dict
        Keyword arguments of ``add_constraint`` (``lower``, ``upper``, ``equals``, ``ref``,
        ``indices``, ``flat_indices``, ``units``, ``linear``).
    """

    kind: str
    output: str
    options: dict


@dataclasses.dataclass(frozen=True)
class LayoutEntry:
    """
    Where a condition's design variable lives in the vehicle file's design variables.

    Attributes
    ----------
    design_variable : str
        Name of the vehicle file's design variable.
    variable : ConditionVariable
        The condition's declaration.
    row : int or None
        Row of the condition in a table its prefix shares with other conditions (None: the
        design variable is the condition's alone).
    """

    design_variable: str
    variable: ConditionVariable
    row: int | None

    @property
    def flat_indices(self):
        """Flat indices of the condition's entries in the design variable."""
        size = self.variable.size
        start = 0 if self.row is None else self.row * size
        return np.arange(start, start + size)


@dataclasses.dataclass(frozen=True)
class DesignVariableShape:
    """A condition design variable of the vehicle file, as the layout derives it.

    Attributes
    ----------
    name : str
    shape : tuple of int
    units : str
    description : str
    initial : tuple of float or None
        Initial values taken from the conditions (``initial_from``), else None.
    initial_from : str
        The condition field the initial values come from (e.g. ``"pitch"``), or ``""``.
    conditions : tuple of str
        The conditions whose entries it holds, in row order.
    """

    name: str
    shape: tuple
    units: str
    description: str
    initial: tuple | None
    initial_from: str
    conditions: tuple


class ConditionLayout:
    """
    The design variables of a vehicle's conditions, named and stacked.

    A condition's variable ``v`` is the vehicle file's design variable ``{prefix}_{v}``, with
    ``prefix`` the condition's ``design_variable_prefix``. When the prefix is the condition's
    own name and no other condition uses it, the design variable has the variable's shape;
    otherwise the conditions that share the prefix are its rows, in vehicle-file order:
    shape ``(n,) + shape`` (``(n,)`` for scalars). The reference vehicle: ``hover_lift_rpm``
    (4,), ``transition_lift_rpm`` (5, 4), ``climb_pitch`` (1,), ``oei_lift_rpm`` (4, 7).

    Parameters
    ----------
    vehicle : Vehicle or namespace
        Needs ``conditions``, ``lift_rotors`` and ``pusher`` (a partly built vehicle works).
    """

    def __init__(self, vehicle):
        from lpc_mdo.groups.condition_kinds import condition_class

        self.entries = {}
        self.design_variables = {}
        rows = {}
        by_prefix = {}
        for c in vehicle.conditions:
            by_prefix.setdefault(c.design_variable_prefix, []).append(c)
        for c in vehicle.conditions:
            sharing = by_prefix[c.design_variable_prefix]
            stacked = not (len(sharing) == 1 and c.design_variable_prefix == c.name)
            entries = {}
            for v in condition_class(c.kind).variables(vehicle, c):
                name = f"{c.design_variable_prefix}_{v.name}"
                row = rows.setdefault(name, {}).setdefault(c.name, len(rows[name]))
                entries[v.name] = LayoutEntry(name, v, row if stacked else None)
            self.entries[c.name] = entries
        for name, members in rows.items():
            conds = [vehicle_condition(vehicle, n) for n in members]
            first = self.entries[conds[0].name]
            var = next(e.variable for e in first.values() if e.design_variable == name)
            for c in conds[1:]:
                other = next(
                    e.variable for e in self.entries[c.name].values() if e.design_variable == name
                )
                if (other.shape, other.units) != (var.shape, var.units):
                    raise VehicleSpecError(
                        f"conditions {conds[0].name!r} and {c.name!r} share the design variable "
                        f"{name!r} with different shapes or units ({var.shape} {var.units} vs "
                        f"{other.shape} {other.units}); allowed: one kind per "
                        f"design_variable_prefix"
                    )
            stacked = first[var.name].row is not None
            shape = (
                (len(conds),) + (() if var.shape == (1,) else var.shape) if stacked else var.shape
            )
            initial = None
            if var.initial_from:
                initial = tuple(
                    float(getattr(c, var.initial_from)) for c in conds for _ in range(var.size)
                )
            rows_text = f"; rows: {', '.join(members)}" if stacked else ""
            self.design_variables[name] = DesignVariableShape(
                name,
                shape,
                var.units,
                var.description + rows_text,
                initial,
                var.initial_from,
                tuple(members),
            )

    def entry(self, condition, variable):
        """Return the :class:`LayoutEntry` of ``variable`` of condition ``condition`` (names)."""
        return self.entries[condition][variable]

    def trim_variables(self, condition):
        """(design-variable name, flat indices) of the trim variables of ``condition``."""
        return [
            (e.design_variable, e.flat_indices)
            for e in self.entries[condition].values()
            if e.variable.trim
        ]


def vehicle_condition(vehicle, name):
    """Return the condition called ``name`` of a (possibly partly built) vehicle."""
    for c in vehicle.conditions:
        if c.name == name:
            return c
    raise KeyError(name)


@functools.lru_cache(maxsize=32)
def _cached_layout(vehicle):
    return ConditionLayout(vehicle)


def condition_layout(vehicle):
    """Return the :class:`ConditionLayout` of a vehicle (cached per vehicle)."""
    try:
        return _cached_layout(vehicle)
    except TypeError:  # an unhashable, partly built vehicle
        return ConditionLayout(vehicle)


class ConditionGroup(om.Group):
    """
    Base class of the design-condition groups: options and the contract's defaults.

    Subclasses build their subsystems in ``setup`` and override the class methods of the
    contract that apply to them (see the module docstring). Options common to every condition:
    ``vehicle`` (:class:`~lpc_mdo.vehicle.Vehicle`), ``condition`` (its name in the vehicle
    file), ``rotor_polar``/``pusher_polar`` (blade-section polars) and ``num_radial``.
    """

    #: Output of the condition's electrical power (W), None for a condition without motors.
    power_output = "electrical_power"

    #: Rules of the vehicle-file fields for this kind: field -> (test, requirement text).
    field_rules = {}

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

    # -------------------------------------------------------------- the contract (defaults)

    @classmethod
    def check(cls, index, condition, vehicle):
        """
        Raise VehicleSpecError unless ``condition`` obeys the kind's field rules.

        Parameters
        ----------
        index : int
            Position in the vehicle file's ``conditions`` (for the message).
        condition : DesignCondition
        vehicle : Vehicle or namespace
            The (partly built) vehicle: ``lift_rotors``, ``conditions``.
        """
        for name, (test, text) in cls.field_rules.get(condition.kind, {}).items():
            value = getattr(condition, name)
            if not test(value):
                raise VehicleSpecError(
                    f"'conditions[{index}].{name}' = {value!r} is not allowed: must be {text} "
                    f"in {condition.kind!r} conditions"
                )
        if cls.power_output is None and condition.energy_weight != 0.0:
            raise VehicleSpecError(
                f"'conditions[{index}].energy_weight' = {condition.energy_weight!r} is not "
                f"allowed: must be 0 in {condition.kind!r} conditions (they draw no power)"
            )

    @classmethod
    def variables(cls, vehicle, condition):
        """Return the design variables the condition owns: tuple of :class:`ConditionVariable`."""
        return ()

    @classmethod
    def vehicle_inputs(cls, vehicle, condition):
        """
        Return the connections from vehicle-level outputs: tuple of (source, target, src_indices).

        ``source`` is a promoted output of the assembly, ``target`` an input of the condition
        (relative to it), ``src_indices`` None or indices as ``connect`` takes them.
        """
        return (
            ("gross_mass", "gross_mass", None),
            ("cg", "cg", None),
            ("inertia", "inertia", None),
        )

    @classmethod
    def trim_rows(cls, vehicle, condition):
        """Return the condition's trim rows of paper Table 6: tuple of :class:`TrimRow`."""
        return ()

    @classmethod
    def constraints(cls, vehicle, condition, bounds):
        """
        Return the condition's constraints besides trim: tuple of :class:`ConditionConstraint`.

        ``bounds(name)`` returns the (lower, upper) arrays of a design variable, in its shape,
        with the problem's overrides (some constraints bound outputs by them); None: the
        vehicle file's bounds.
        """
        return ()

    @classmethod
    def motor_sets(cls, vehicle, condition):
        """
        Return the motors the condition runs, by set: dict prefix -> indices.

        ``lift``: indices into ``vehicle.lift_rotors`` of the running lift rotors (output
        ``lift_motor_torque_margin``, one entry per running rotor); ``pusher``: ``(0,)``
        (``pusher_motor_torque_margin``). These are also the condition's motor operating
        points, under the same names in every kind: shaft torque ``{prefix}_torque`` and rotor
        speed (``lift_rotor_rpm``, ``pusher_rpm``), one row per motor of the set, so that a
        discipline batched over all conditions (one motor model for every condition's motors)
        can gather them by these declarations and hand its results back.
        """
        return {}


def linear_trim_ref(load_factor=1.0):
    """Scaling reference of a linear trim row: g abs(n) (m/s**2; paper eq. 29)."""
    return GRAVITY * abs(load_factor)
