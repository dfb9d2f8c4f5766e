"""The registry of design-condition groups: a kind name of the vehicle file -> its group class.

A vehicle file's ``[[conditions]]`` entry names its ``kind``; the kind's declaration
(:data:`lpc_mdo.vehicle.condition_contract.CONDITION_KINDS`) states its contract, and the group
class registered here for the same name builds it. A condition of an existing kind is a
vehicle-file edit only; a new kind is a declaration (a subclass of
:class:`~lpc_mdo.vehicle.condition_contract.ConditionKind`) and a group class that names it,
registered together with :func:`register_condition_kind` (e.g. from a user's run script).
"""

from lpc_mdo.groups.condition_base import ConditionGroup
from lpc_mdo.groups.hover_condition import HoverCondition
from lpc_mdo.groups.steady_flight_condition import SteadyFlightCondition
from lpc_mdo.groups.structural_condition import StructuralCondition
from lpc_mdo.groups.transition_condition import TransitionCondition
from lpc_mdo.vehicle.condition_contract import register_kind

__all__ = ["CONDITION_GROUPS", "condition_group", "register_condition_kind"]

#: Kind name -> condition group class. Hover and one-engine-inoperative hover share a class.
CONDITION_GROUPS = {
    "hover": HoverCondition,
    "oei": HoverCondition,
    "transition": TransitionCondition,
    "steady": SteadyFlightCondition,
    "structural": StructuralCondition,
}


def register_condition_kind(kind, group_class):
    """
    Register a condition kind: its declaration (the group's) and the group class that builds it.

    Parameters
    ----------
    kind : str
        The name a vehicle file's ``conditions[i].kind`` uses.
    group_class : type
        A subclass of :class:`~lpc_mdo.groups.condition_base.ConditionGroup` whose
        ``declaration`` is the kind's :class:`~lpc_mdo.vehicle.condition_contract.ConditionKind`.
    """
    if not (isinstance(group_class, type) and issubclass(group_class, ConditionGroup)):
        raise ValueError(
            f"'group_class' = {group_class!r} is not allowed: must be a subclass of "
            f"lpc_mdo.groups.condition_base.ConditionGroup"
        )
    register_kind(kind, group_class.declaration)
    CONDITION_GROUPS[kind] = group_class


def condition_group(kind):
    """Return the group class registered for condition kind ``kind`` (KeyError naming the kinds)."""
    try:
        return CONDITION_GROUPS[kind]
    except KeyError:
        raise KeyError(
            f"condition kind {kind!r} has no registered group; registered kinds: "
            f"{sorted(CONDITION_GROUPS)}"
        ) from None
