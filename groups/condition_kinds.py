"""The registry of design-condition kinds: a kind name of the vehicle file -> its group class.

A vehicle file's ``[[conditions]]`` entry names its ``kind``; the class registered for it builds
the condition and declares its contract (:class:`~lpc_mdo.groups.condition_base.ConditionGroup`).
A condition of an existing kind is a vehicle-file edit only; a new kind is one subclass of
``ConditionGroup`` registered here, or from user code with :func:`register_condition_kind`.
"""

from lpc_mdo.groups.condition_base import ConditionGroup
from lpc_mdo.groups.conditions import (
    HoverCondition,
    SteadyFlightCondition,
    StructuralCondition,
    TransitionCondition,
)

__all__ = ["CONDITION_KINDS", "condition_class", "register_condition_kind"]

#: Kind name -> condition group class. Hover and one-engine-inoperative hover share a class.
CONDITION_KINDS = {
    "hover": HoverCondition,
    "oei": HoverCondition,
    "transition": TransitionCondition,
    "steady": SteadyFlightCondition,
    "structural": StructuralCondition,
}


def register_condition_kind(kind, cls):
    """
    Register the group class of a condition kind (e.g. from a user's run script).

    Parameters
    ----------
    kind : str
        The name a vehicle file's ``conditions[i].kind`` uses.
    cls : type
        A subclass of :class:`~lpc_mdo.groups.condition_base.ConditionGroup`.
    """
    if not (isinstance(kind, str) and kind.isidentifier()):
        raise ValueError(f"'kind' = {kind!r} is not allowed: must be a Python identifier")
    if not (isinstance(cls, type) and issubclass(cls, ConditionGroup)):
        raise ValueError(
            f"'cls' = {cls!r} is not allowed: must be a subclass of "
            f"lpc_mdo.groups.condition_base.ConditionGroup"
        )
    CONDITION_KINDS[kind] = cls


def condition_class(kind):
    """Return the group class registered for condition kind ``kind`` (KeyError naming the kinds)."""
    try:
        return CONDITION_KINDS[kind]
    except KeyError:
        raise KeyError(
            f"condition kind {kind!r} is not registered; registered kinds: "
            f"{sorted(CONDITION_KINDS)}"
        ) from None
