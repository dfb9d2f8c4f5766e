"""Checks of a vehicle file across fields: symmetric lift-rotor pairs, the pusher, conditions.

Each condition kind's own rules are its class's :meth:`~lpc_mdo.groups.condition_base.
ConditionGroup.check`; this module checks what spans fields (names unique, kinds registered,
the cruise condition a steady one).
"""

from __future__ import annotations

import numpy as np

from lpc_mdo.vehicle.parts import (
    _IDENTIFIER,
    _NUM_PAIRS,
    _PUSHER_GROUP,
    DesignCondition,
    Mission,
    Rotor,
    _pairs,
)
from lpc_mdo.vehicle.schema import VehicleSpecError

# ------------------------------------------------------------------------------------------------
# Checks across fields


def _close(a, b) -> bool:
    return bool(np.allclose(a, b, rtol=1e-9, atol=1e-6))


def _check_lift_rotors(rotors: tuple[Rotor, ...]) -> None:
    for i, r in enumerate(rotors):
        if r.pair >= _NUM_PAIRS:
            raise VehicleSpecError(
                f"'lift_rotors[{i}].pair' = {r.pair} is out of range: must be in [0, "
                f"{_NUM_PAIRS - 1}] (group {_PUSHER_GROUP} is the pusher)"
            )
    shared = ("radius", "num_blades", "hub_radius_ratio", "chord_cp", "twist_cp", "airfoil")
    for p, members in enumerate(_pairs(rotors)):
        if len(members) != 2:
            listed = ", ".join(f"lift_rotors[{i}]" for i in members) or "none"
            raise VehicleSpecError(
                f"'lift_rotors' pair {p} has {len(members)} rotors ({listed}); each pair "
                f"0..{_NUM_PAIRS - 1} must have exactly 2 mirror-image rotors"
            )
        i, j = members
        a, b = rotors[i], rotors[j]
        for name in shared:
            if not _close_or_equal(getattr(a, name), getattr(b, name)):
                raise VehicleSpecError(
                    f"'lift_rotors[{j}].{name}' = {getattr(b, name)!r} differs from its pair "
                    f"partner 'lift_rotors[{i}].{name}' = {getattr(a, name)!r}; the rotors of a "
                    f"pair share {', '.join(shared)}"
                )
        for name in ("hub_position", "thrust_axis"):
            va, vb = getattr(a, name), getattr(b, name)
            if not _close(vb, (va[0], -va[1], va[2])):
                raise VehicleSpecError(
                    f"'lift_rotors[{j}].{name}' = {vb!r} is not the mirror image (y -> -y) of "
                    f"its pair partner 'lift_rotors[{i}].{name}' = {va!r}"
                )
        if a.spin_direction == b.spin_direction:
            raise VehicleSpecError(
                f"'lift_rotors[{j}].spin_direction' = {b.spin_direction} must be opposite to its "
                f"pair partner 'lift_rotors[{i}].spin_direction' = {a.spin_direction}, so that "
                f"each pair balances its yaw torque"
            )


def _close_or_equal(a, b) -> bool:
    return a == b if isinstance(a, str) else _close(a, b)


def _check_pusher(pusher: Rotor) -> None:
    if pusher.pair != _PUSHER_GROUP:
        raise VehicleSpecError(
            f"'pusher.pair' = {pusher.pair} is not allowed: must be {_PUSHER_GROUP} "
            f"(the pusher is its own group; 0..3 are the lift-rotor pairs)"
        )


def _check_conditions(parts: dict) -> None:
    """Names unique identifiers, kinds registered, each kind's own rules (its class's check)."""
    from lpc_mdo.groups.condition_kinds import CONDITION_KINDS

    vehicle = _PartialVehicle(parts)
    seen: dict[str, int] = {}
    for i, c in enumerate(parts["conditions"]):
        path = f"conditions[{i}]"
        for key in ("name", "design_variable_prefix"):
            value = getattr(c, key)
            if not value.isidentifier():
                raise VehicleSpecError(
                    f"'{path}.{key}' = {value!r} is not allowed: must be {_IDENTIFIER}"
                )
        if c.name in seen:
            raise VehicleSpecError(
                f"'{path}.name' = {c.name!r} repeats "
                f"'conditions[{seen[c.name]}].name'; names must be unique"
            )
        seen[c.name] = i
        if c.kind not in CONDITION_KINDS:
            allowed = ", ".join(repr(k) for k in CONDITION_KINDS)
            raise VehicleSpecError(
                f"'{path}.kind' = {c.kind!r} is not allowed: must be one of "
                f"{allowed} (register a new kind with "
                f"lpc_mdo.groups.condition_kinds.register_condition_kind)"
            )
        CONDITION_KINDS[c.kind].check(i, c, vehicle)


def _check_mission(mission: Mission, conditions: tuple[DesignCondition, ...]) -> None:
    steady = [c.name for c in conditions if c.kind == "steady"]
    if mission.cruise_condition not in steady:
        raise VehicleSpecError(
            f"'mission.cruise_condition' = {mission.cruise_condition!r} is not allowed: must be "
            f"the name of a 'steady' condition, one of {steady}"
        )


class _PartialVehicle:
    """The parts of a vehicle read so far, as attributes (for checks before it is built)."""

    def __init__(self, parts: dict):
        self.__dict__.update(parts)
