"""The condition contract: what every design-condition kind declares about itself.

A design condition of the vehicle file (``[[conditions]]``) has a ``kind``; the kind's
declaration (a subclass of :class:`ConditionKind`, registered in
:mod:`lpc_mdo.vehicle.condition_kinds`) states, in one place and as data, everything the
assembly (:class:`~lpc_mdo.groups.lpc.LPCGroup`), the problem specification
(:mod:`lpc_mdo.problems`) and the post-processing need to know about a condition of that kind:

- :meth:`ConditionKind.check`: the kind's rules on the vehicle-file fields;
- :meth:`ConditionKind.variables`: the design variables it owns (trim variables such as rotor
  speeds, pitch, elevator), with their shape per condition;
  :func:`~lpc_mdo.vehicle.condition_layout.condition_layout` names them and stacks the conditions
  that share a ``design_variable_prefix`` into one table;
- :meth:`ConditionKind.vehicle_inputs`: the vehicle-level outputs it reads (connections);
- :meth:`ConditionKind.trim_rows`: its rows of the paper's Table 6 trim constraints;
- :meth:`ConditionKind.constraints`: its other constraints (noise, tip Mach, buckling, ...);
- :meth:`ConditionKind.motor_sets`: the motors it runs, whose torque margins the assembly
  aggregates over the conditions (paper eq. 7);
- :attr:`ConditionKind.power_output`: its electrical power, which the mission energy weighs by
  the condition's ``energy_weight`` (vehicle file).

Every declaration is a class method of (vehicle, condition) and imports no OpenMDAO group, so it
is known before any model is set up: the vehicle file is validated and the problem declared from
the same declarations that wire the model. The group that builds a condition of the kind
(:class:`~lpc_mdo.groups.condition_base.ConditionGroup`) names its declaration. The pattern
follows pyCycle's elements, which declare their own default connections, and Aviary's subsystem
builders, which declare their own design variables and constraints.
"""

import dataclasses
import math

from lpc_mdo.core.constants import GRAVITY
from lpc_mdo.vehicle.schema import VehicleSpecError

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
        ``buckling``, ``rotor_speed``, ``control_reserve``, ``wing_stall``, ...).
    output : str
        Output of the condition group (promoted, relative to it).
    options : dict
        Keyword arguments of ``add_constraint`` (``lower``, ``upper``, ``equals``, ``ref``,
        ``indices``, ``flat_indices``, ``units``, ``linear``).
    """

    kind: str
    output: str
    options: dict


class ConditionKind:
    """
    Base class of the condition-kind declarations: the contract's defaults.

    A subclass overrides the class methods that apply to its kind (see the module docstring).
    It is never instantiated.
    """

    #: Output of the condition's electrical power (W), None for a condition without motors.
    power_output = "electrical_power"

    #: Rules of the vehicle-file fields for this kind: kind -> field -> (test, requirement text).
    field_rules = {}

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
        if condition.optimizes_speed and (
            condition.kind != "steady" or (condition.flight_path_angle or 0.0) != 0.0
        ):
            raise VehicleSpecError(
                f"'conditions[{index}].speed_rule' = 'optimized' is not allowed in condition "
                f"{condition.name!r} (kind {condition.kind!r}): an optimized speed is flown in "
                "level flight in a 'steady' condition (a climb or descent fixes its speed with its "
                "vertical speed); allowed: 'fixed'"
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


#: Kind name -> declaration (a :class:`ConditionKind` subclass): the kinds a vehicle file may
#: name. :mod:`lpc_mdo.vehicle.condition_kinds` registers the package's kinds.
CONDITION_KINDS = {}


def register_kind(kind, declaration):
    """
    Register the declaration of a condition kind.

    Parameters
    ----------
    kind : str
        The name a vehicle file's ``conditions[i].kind`` uses (a Python identifier).
    declaration : type
        A subclass of :class:`ConditionKind`.
    """
    if not (isinstance(kind, str) and kind.isidentifier()):
        raise ValueError(f"'kind' = {kind!r} is not allowed: must be a Python identifier")
    if not (isinstance(declaration, type) and issubclass(declaration, ConditionKind)):
        raise ValueError(
            f"'declaration' = {declaration!r} is not allowed: must be a subclass of "
            f"lpc_mdo.vehicle.condition_contract.ConditionKind"
        )
    CONDITION_KINDS[kind] = declaration


def condition_kind(kind):
    """Return the declaration registered for condition kind ``kind`` (KeyError naming the kinds)."""
    try:
        return CONDITION_KINDS[kind]
    except KeyError:
        raise KeyError(
            f"condition kind {kind!r} is not registered; registered kinds: "
            f"{sorted(CONDITION_KINDS)}"
        ) from None


def linear_trim_ref(load_factor=1.0):
    """Scaling reference of a linear trim row: g abs(n) (m/s**2; paper eq. 29)."""
    return GRAVITY * abs(load_factor)
