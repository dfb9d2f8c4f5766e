"""Gross-mass breakdown of a problem or a recorded case: read it and print it.

Plain post-processing of the outputs of :class:`lpc_mdo.groups.weights.WeightsGroup` (paper
eqs. 31-33); works on a live problem or on a recorded case alike.
"""

import numpy as np

from lpc_mdo.components.weights.gross_weight import BREAKDOWN_LABELS

__all__ = ["format_mass_breakdown", "mass_breakdown"]


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
