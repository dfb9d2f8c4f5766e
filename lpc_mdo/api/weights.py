"""Gross-mass breakdown of a problem or a recorded case: read it and print it.

Plain post-processing of the outputs of :class:`lpc_mdo.groups.weights.WeightsGroup` (paper
eqs. 31-33); works on a live problem or on a recorded case alike.
"""

import numpy as np

from lpc_mdo.components.weights.gross_weight import BREAKDOWN_LABELS
from lpc_mdo.components.weights.mass_properties import ITEM_COLUMNS
from lpc_mdo.groups.weights import vehicle_mass_items

__all__ = ["format_mass_breakdown", "format_mass_properties", "mass_breakdown", "mass_properties"]


def mass_breakdown(source, prefix=""):
    """
    Return the gross-mass breakdown (kg) of a problem or a recorded case as an ordered dict.

    Reads the outputs ``{prefix}mass_breakdown``, ``{prefix}structures_mass``,
    ``{prefix}powertrain_mass`` and ``{prefix}gross_mass`` of a :class:`WeightsGroup` (outputs
    only, so a driver case needs them in the recorder's ``includes``).

    Parameters
    ----------
    source : om.Problem or Case
        Anything with ``get_val(name, units=...)``.
    prefix : str
        Path of the WeightsGroup with a trailing dot, e.g. ``'weights.'``; '' when promoted.

    Returns
    -------
    dict
        wing, fuselage, empennage, booms, battery, motors, power_electronics, payload, systems,
        other, then the totals structures (eq. 32), powertrain (eq. 33) and gross (eq. 31).
    """
    values = np.asarray(source.get_val(f"{prefix}mass_breakdown", units="kg"), float).ravel()
    out = {label: float(v) for label, v in zip(BREAKDOWN_LABELS, values, strict=True)}
    for key in ("structures", "powertrain", "gross"):
        out[key] = float(np.asarray(source.get_val(f"{prefix}{key}_mass", units="kg")).ravel()[0])
    return out


def format_mass_breakdown(breakdown):
    """Return a text table of a :func:`mass_breakdown` dict: item, kg and % of the gross mass."""
    gross = breakdown["gross"]
    lines = [f"{'item':<20}{'mass (kg)':>12}{'share':>9}"]
    for label, value in breakdown.items():
        if label == "structures":
            lines.append("-" * 41)
        lines.append(f"{label.replace('_', ' '):<20}{value:>12.2f}{100.0 * value / gross:>8.1f}%")
    return "\n".join(lines)


def mass_properties(source, vehicle=None, prefix=""):
    """
    Return the mass, cg and inertia of every mass item of a problem or a recorded case.

    Reads the outputs ``{prefix}item_mass_properties`` (one row per kind of body of
    :func:`lpc_mdo.groups.weights.vehicle_mass_items`, in that order; bodies of one kind, e.g. 9
    motors, summed), ``{prefix}total_mass``, ``{prefix}cg`` and ``{prefix}inertia`` of the
    :class:`~lpc_mdo.groups.weights.WeightsGroup`. Each row's inertia is its contribution to the
    vehicle's inertia about the vehicle cg: its own inertia (items with one) plus
    m ((r.r) 1 - r r^T), r = p - cg (parallel-axis theorem, docs theory/weights 'Mass
    properties'); the rows add up to the vehicle's tensor. Outputs only, so a final case
    recorded with ``includes=['*']`` (as :func:`lpc_mdo.problems` records it) works as well as
    a live problem.

    Parameters
    ----------
    source : om.Problem or Case
        Anything with ``get_val(name, units=...)``.
    vehicle : Vehicle or None
        The vehicle whose item names label the rows; None = the reference vehicle.
    prefix : str
        Path of the WeightsGroup with a trailing dot; '' when promoted.

    Returns
    -------
    list of dict
        One per kind of body: ``name``, ``mass`` (kg), ``cg`` (3, m; mass-weighted),
        ``inertia`` (3x3, kg m^2 about the vehicle cg); the last row is ``name='vehicle'``.
    """
    table = np.asarray(source.get_val(f"{prefix}item_mass_properties"), float)
    items = vehicle_mass_items(vehicle)
    if table.shape != (len(items), len(ITEM_COLUMNS)):
        raise ValueError(
            f"'{prefix}item_mass_properties' has shape {table.shape}; the vehicle has "
            f"{len(items)} mass items, so ({len(items)}, {len(ITEM_COLUMNS)}) is expected: "
            "pass the vehicle of the problem."
        )
    rows = []
    for item, row in zip(items, table, strict=True):
        ixx, iyy, izz, ixy, ixz, iyz = row[4:]
        inertia = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        rows.append({"name": item.name, "mass": row[0], "cg": row[1:4], "inertia": inertia})
    rows.append(
        {
            "name": "vehicle",
            "mass": float(np.asarray(source.get_val(f"{prefix}total_mass", units="kg")).ravel()[0]),
            "cg": np.asarray(source.get_val(f"{prefix}cg", units="m"), float).ravel(),
            "inertia": np.asarray(source.get_val(f"{prefix}inertia", units="kg*m**2"), float),
        }
    )
    return rows


def format_mass_properties(rows):
    """Return a text table of :func:`mass_properties` rows: mass, cg and inertia per item."""
    head = (
        f"{'item':<22}{'mass kg':>9}{'x m':>8}{'y m':>7}{'z m':>7}"
        f"{'Ixx':>9}{'Iyy':>9}{'Izz':>9}{'Ixz':>8}  (kg m^2, about the vehicle cg)"
    )
    lines = [head]
    for row in rows:
        if row["name"] == "vehicle":
            lines.append("-" * 88)
        x, y, z = row["cg"]
        i = row["inertia"]
        lines.append(
            f"{row['name'].replace('_', ' '):<22}{row['mass']:>9.2f}{x:>8.3f}{y:>7.3f}{z:>7.3f}"
            f"{i[0, 0]:>9.0f}{i[1, 1]:>9.0f}{i[2, 2]:>9.0f}{i[0, 2]:>8.0f}"
        )
    return "\n".join(lines)
