"""Trim residuals of the paper's Table 6 rows as forces and moments, in % of the weight.

The optimizations constrain body-axis accelerations (m/s^2, rad/s^2); the paper's Table 7 reports
the trim residuals as forces and moments (N, N m) relative to the weight W0 = m g (about 3.6e4 N
here). This module reads a case file's final case and evaluates every trim row of Table 6 for
the conditions the case holds, whether or not the run declared it as a constraint (the
optimizations leave out hover p_dot and the OEI v_dot, which vanish for every design, and the
transition v_dot, which no trim variable controls on its own):

    force residual  F_i = m (a_i - a_target,i)          i in (u, v, w)
    moment residual M   = I . alpha                      (quasi-steady: zero body rates)

with m = ``gross_mass``, I = ``inertia`` (3 x 3, about the cg) and the accelerations
``{condition}.linear_acceleration``, ``{condition}.angular_acceleration``. The rows and their
targets (zero except the prescribed transition accelerations) are those the optimization
problems declare: each condition kind's :meth:`~lpc_mdo.vehicle.condition_contract.ConditionKind.
trim_rows`. The reference vehicle: hover (w, p, q), steady (u, w, q), transition (u, v, w, p, q,
r), OEI (v, w, p, q, r), structural (w): 64 of the 96 constraints for its 15 conditions.
"""

import numpy as np

from lpc_mdo.core.constants import GRAVITY
from lpc_mdo.post.tables import (
    MissingVariableError,
    Table,
    constraint_metadata,
    final_case,
    last_case,
    open_reader,
    read_value,
)
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.condition_contract import ANGULAR_COMPONENTS, LINEAR_COMPONENTS, condition_kind

__all__ = ["trim_residuals", "trim_residual_table"]


def _declared_indices(metadata, name):
    """Flat component indices of the declared constraint ``name`` (empty if undeclared)."""
    meta = metadata.get(name)
    if meta is None:
        return set()
    indices = meta.get("indices")
    return set(range(meta["size"])) if indices is None else {int(i) for i in np.ravel(indices)}


def _problem_case(source, case):
    """Return the given case, else the last problem case (``'final'``), which holds every output."""
    found = final_case(source, case) if case is not None else last_case(source, "problem")
    if found is None:
        raise MissingVariableError(
            "the case file holds no problem case (prob.record('final')), "
            "which the trim residuals need (every output)."
        )
    return found


def trim_residuals(source, case=None, vehicle=None):
    """
    Force and moment residuals of every Table 6 trim row of the conditions a case holds.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    case : None, int, str or Case
        Which case (see :func:`lpc_mdo.post.tables.final_case`); None: the last problem case
        (``'final'``), which holds every output.
    vehicle : Vehicle or None
        The vehicle the run was made with (None: the reference vehicle): its conditions and
        their trim rows.

    Returns
    -------
    list of dict
        Per row: ``condition``, ``component`` (u, v, w, p, q, r), ``declared`` (whether the run
        constrained it), ``acceleration`` and ``target`` (m/s^2 or rad/s^2), ``residual`` (N or
        N m), ``percent_of_weight``.

    Raises
    ------
    MissingVariableError
        When the case holds no condition's accelerations, or not ``gross_mass``/``inertia``.
    """
    vehicle = vehicle or reference_vehicle()
    source = open_reader(source)  # once: every read_value below would reopen a path
    case = _problem_case(source, case)
    mass = float(read_value(source, "gross_mass", "kg", case)[0])
    inertia = read_value(source, "inertia", "kg*m**2", case).reshape(3, 3)
    weight = mass * GRAVITY
    metadata = constraint_metadata(source)
    rows = []
    for condition in vehicle.conditions:
        name = condition.name
        try:
            values = {
                "linear_acceleration": read_value(
                    source, f"{name}.linear_acceleration", "m/s**2", case
                ).ravel(),
                "angular_acceleration": read_value(
                    source, f"{name}.angular_acceleration", "rad/s**2", case
                ).ravel(),
            }
        except MissingVariableError:
            continue
        moment = inertia @ values["angular_acceleration"]
        for row in condition_kind(condition.kind).trim_rows(vehicle, condition):
            value = values[row.output][row.index]
            declared = row.index in _declared_indices(metadata, f"{name}.{row.output}")
            if row.output == "linear_acceleration":
                residual = mass * (value - row.target)
            else:
                residual = moment[row.index]
            rows.append(
                dict(
                    condition=name,
                    component=row.component,
                    declared=declared,
                    acceleration=float(value),
                    target=float(row.target),
                    residual=float(residual),
                    percent_of_weight=100.0 * abs(float(residual)) / weight,
                )
            )
    if not rows:
        raise MissingVariableError(
            "no condition's linear_acceleration/angular_acceleration is recorded in the case."
        )
    return rows


def trim_residual_table(source, case=None, limit_percent=0.1, vehicle=None):
    """
    Table of the Table 6 trim rows per condition: largest force and moment residuals.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
    case : None, int, str or Case
        As :func:`trim_residuals`.
    limit_percent : float
        The residual, in % of the weight, above which a row counts as not trimmed (the
        optimization issue's criterion: 0.1 %).
    vehicle : Vehicle or None
        As :func:`trim_residuals`.

    Returns
    -------
    Table
        Columns ``condition, rows, declared, max |force| (N), max |moment| (N m), max % of
        W0, trimmed``; a note gives the weight and the overall largest residual.
    """
    source = open_reader(source)
    case = _problem_case(source, case)
    rows = trim_residuals(source, case, vehicle)
    weight = float(read_value(source, "gross_mass", "kg", case)[0]) * GRAVITY
    out, worst = [], max(rows, key=lambda r: r["percent_of_weight"])
    for name in dict.fromkeys(r["condition"] for r in rows):
        mine = [r for r in rows if r["condition"] == name]
        forces = [abs(r["residual"]) for r in mine if r["component"] in LINEAR_COMPONENTS]
        moments = [abs(r["residual"]) for r in mine if r["component"] in ANGULAR_COMPONENTS]
        percent = max(r["percent_of_weight"] for r in mine)
        out.append(
            [
                name,
                " ".join(r["component"] for r in mine),
                " ".join(r["component"] for r in mine if r["declared"]) or "none",
                max(forces) if forces else None,
                max(moments) if moments else None,
                percent,
                percent <= limit_percent,
            ]
        )
    n_ok = sum(1 for r in rows if r["percent_of_weight"] <= limit_percent)
    notes = [
        f"W0 = m g = {weight:.6g} N; residual = m (a - a_target) for u, v, w and I alpha "
        f"for p, q, r (paper Table 7 reports trim this way).",
        f"{n_ok} of {len(rows)} Table 6 trim rows within {limit_percent:g} % of W0; the "
        f"largest: {worst['condition']} {worst['component']}, "
        f"{worst['residual']:.4g} ({worst['percent_of_weight']:.3g} %).",
        "'declared': the rows the run constrained; the others are evaluated all the same.",
    ]
    return Table(
        [
            "condition",
            "rows",
            "declared",
            "max |force| (N)",
            "max |moment| (N m)",
            "max % of W0",
            "trimmed",
        ],
        out,
        "Trim residuals (Table 6 rows)",
        notes,
    )
