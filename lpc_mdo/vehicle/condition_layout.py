"""The design variables of a vehicle's conditions: named by the kinds' declarations, stacked.

Each condition kind declares the variables a condition of it owns
(:meth:`~lpc_mdo.vehicle.condition_contract.ConditionKind.variables`); the layout names them
``{design_variable_prefix}_{variable}`` and stacks the conditions that share a prefix into one
table of the vehicle file's design variables.
"""

import dataclasses
import functools

import numpy as np

from lpc_mdo.vehicle.condition_contract import ConditionVariable, condition_kind
from lpc_mdo.vehicle.schema import VehicleSpecError


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
            for v in condition_kind(c.kind).variables(vehicle, c):
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
