"""One-rotor-out hover cases generated from the lift-rotor layout.

A vehicle file asks for the one-engine-inoperative (OEI) hover cases once: a ``[[conditions]]``
table of kind ``oei`` with ``failed_rotor = "each"``. The loader replaces it by one OEI condition
per distinct single lift-rotor failure, named ``<name>_1`` .. ``<name>_k`` in pair order, each
failing the left rotor (y < 0) of its pair and sharing the table's other fields (its
``design_variable_prefix`` too, so their trim variables are the rows of one design variable).

Distinct failures: the rotors of a pair are mirror images about y = 0 (hub, thrust axis, blade,
radius, opposite spin: :func:`lpc_mdo.vehicle.consistency._check_lift_rotors` checks it), and the
vehicle is mirror-symmetric, so losing the right rotor of a pair is the mirror image of losing
its left one: the same case with roll and yaw reversed. Every pair gives one case: k = the number
of pairs (the reference's 8 rotors give 4, a 12-rotor layout 6).
"""

from __future__ import annotations

import copy
import re

from lpc_mdo.vehicle.parts import Rotor, Vehicle, _pairs
from lpc_mdo.vehicle.schema import VehicleSpecError, _convert, _hints, _spec

#: The ``failed_rotor`` value that asks for every distinct single failure.
EACH = "each"


def distinct_failures(lift_rotors: tuple[Rotor, ...]) -> tuple[int, ...]:
    """Return the rotor failed in each distinct one-rotor-out case: each pair's left rotor."""
    failures = []
    for members in _pairs(lift_rotors):
        left = [i for i in members if lift_rotors[i].hub_position[1] < 0.0]
        failures.append((left or members or (-1,))[0])
    return tuple(failures)


def expand_failures(data: dict) -> tuple[dict, list[str] | None]:
    """
    Return the vehicle data with each ``failed_rotor = "each"`` condition expanded (see above).

    Also returns, per condition of the expanded data, its key in the vehicle file
    (``conditions[9]`` or ``conditions[9] (generated oei_2)``), for messages; None when nothing
    was expanded. The data is left as it is when it asks for none, or when its lift rotors are
    missing (the reader then names what is wrong).
    """
    conditions = data.get("conditions") if isinstance(data, dict) else None
    if not isinstance(conditions, list) or not any(
        isinstance(c, dict) and c.get("failed_rotor") == EACH for c in conditions
    ):
        return data, None
    if "lift_rotors" not in data:
        return data, None
    field = Vehicle.__dataclass_fields__["lift_rotors"]
    rotors = _convert(
        _hints(Vehicle)["lift_rotors"], _spec(field), data["lift_rotors"], "lift_rotors"
    )
    failures = distinct_failures(rotors)
    expanded, keys = [], []
    for i, c in enumerate(conditions):
        if not (isinstance(c, dict) and c.get("failed_rotor") == EACH):
            expanded.append(c)
            keys.append(f"conditions[{i}]")
            continue
        if c.get("kind") != "oei":
            raise VehicleSpecError(
                f"'conditions[{i}].failed_rotor' = {EACH!r} is not allowed in a "
                f"{c.get('kind')!r} condition: only kind 'oei' generates one condition per "
                "distinct lift-rotor failure"
            )
        name = c.get("name")
        if not isinstance(name, str) or not name.isidentifier() or not name.isascii():
            raise VehicleSpecError(
                f"'conditions[{i}].name' = {name!r} is not allowed: must be an identifier "
                "(ASCII letters, digits and '_', not starting with a digit); the generated "
                "one-rotor-out conditions are named <name>_1, <name>_2, ..."
            )
        for k, rotor in enumerate(failures):
            case = copy.deepcopy(c)
            case["name"] = f"{name}_{k + 1}"
            case["failed_rotor"] = rotor
            expanded.append(case)
            keys.append(f"conditions[{i}] (generated {case['name']})")
    return {**data, "conditions": expanded}, keys


def file_keys(message: str, keys: list[str] | None) -> str:
    """Rewrite ``conditions[i]`` of the expanded conditions in a message as the file's keys."""
    if keys is None:
        return message
    return re.sub(
        r"conditions\[(\d+)\]",
        lambda m: keys[int(m.group(1))] if int(m.group(1)) < len(keys) else m.group(0),
        message,
    )
