"""The design review of a run's final design: each buildability limit at its worst point.

A designer checks an optimum item by item: every motor within its bus voltage and current,
every rotor's tip Mach inside its limit and inside the polar tables, every blade station within
its stall limit where blade-element momentum solves the rotor, chords and gauges a shop
can build, no powered lift rotor beyond the advance ratio its inflow model holds to, the lift
disks clear of each other, the fuselage, the tail and the pusher, no system or gear mass in the
cabin, every wing section within its stall limit, and the control reserve in hover and every
one-rotor-out case. :func:`design_review` evaluates each from the case file's final problem
case (``prob.record('final')``), whatever the run constrained, with the limits of the vehicle
file; :func:`design_review_table` formats it for the report. Values are the worst over the
conditions and rotors or motors, with where that worst point is.
"""

import dataclasses

import numpy as np

from lpc_mdo.api.weights import mass_properties
from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.post.tables import MissingVariableError, Table, last_case, open_reader, read_value
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.clearances import rotor_pairs
from lpc_mdo.vehicle.condition_kinds import blade_stall_limit, wing_stall_limit

__all__ = ["ReviewItem", "design_review", "design_review_table", "CABIN_EXCLUDED_ITEMS"]

#: Mass items that must sit outside the cabin (docs theory/weights 'Zones'): the landing gear,
#: the battery and the systems group.
CABIN_EXCLUDED_ITEMS = (
    "landing_gear",
    "battery",
    "flight_controls",
    "avionics",
    "electrical",
    "environmental_control",
)
#: Relative tolerance of the pass/fail status, as the optimizers' feasibility tolerance.
TOLERANCE = 1e-3


@dataclasses.dataclass(frozen=True)
class ReviewItem:
    """One line of the design review: the worst value of a quantity against its limit."""

    check: str
    value: float
    limit: float
    sense: str  # ">=" or "<="
    where: str
    units: str = "-"

    @property
    def margin(self):
        """Distance to the limit, positive when satisfied."""
        return self.value - self.limit if self.sense == ">=" else self.limit - self.value

    @property
    def ok(self):
        """Whether the value meets the limit within :data:`TOLERANCE` of its scale."""
        return self.margin >= -TOLERANCE * max(abs(self.limit), 1.0)


class _Final:
    """``get_val`` on the final problem case of a case file."""

    def __init__(self, cr, case):
        self.cr, self.case = cr, case

    def get_val(self, name, units=None):
        return read_value(self.cr, name, units, case=self.case)


def _worst(values, labels, sense):
    """Return (worst value, its label): the minimum for '>=', the maximum for '<='."""
    values = np.asarray(values, dtype=float)
    k = int(np.argmin(values) if sense == ">=" else np.argmax(values))
    return float(values[k]), labels[k]


def _per_condition(get, conditions, output, sense, entry="rotor"):
    """Worst of ``{condition}.{output}`` over the conditions and entries, and where."""
    values, labels = [], []
    for c in conditions:
        v = np.ravel(get(f"{c.name}.{output}"))
        values.extend(v)
        labels.extend(f"{c.name}, {entry} {i + 1}" if v.size > 1 else c.name for i in range(v.size))
    return _worst(values, labels, sense)


def design_review(source, vehicle=None, case=None):
    """
    Return the design review of a case file's final design as a list of :class:`ReviewItem`.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file of a run over the vehicle's conditions (the full problem's ``full.sql``).
    vehicle : Vehicle or None
        The vehicle the run sized (None: the reference vehicle): its limits and conditions.
    case : None, int or str
        The case to review (None: the last problem case, ``'final'``).

    Raises
    ------
    MissingVariableError
        When the case file lacks the outputs of a condition or of the vehicle.
    """
    vehicle = vehicle or reference_vehicle()
    cr = open_reader(source)
    found = last_case(cr, "problem") if case is None else case
    if found is None:
        raise MissingVariableError("the case file holds no problem case (prob.record('final')).")
    final = _Final(cr, found)
    get = final.get_val
    limits = vehicle.constraints
    conds = vehicle.conditions
    kinds = {c.name: c.kind for c in conds}
    hover = [c for c in conds if kinds[c.name] == "hover"]
    oei = [c for c in conds if kinds[c.name] == "oei"]
    transition = [c for c in conds if kinds[c.name] == "transition"]
    steady = [c for c in conds if kinds[c.name] == "steady"]
    lift_motor_conds = hover + oei + transition
    pusher_conds = transition + steady
    items = []

    def add(check, values_where, limit, sense, units="-"):
        value, where = values_where
        items.append(ReviewItem(check, value, float(limit), sense, where, units))

    # Motors: voltage, current and torque at every operating point.
    for prefix, group in (("lift", lift_motor_conds), ("pusher", pusher_conds)):
        entry = "motor"
        add(
            f"{prefix} motors: voltage margin 1 - |U|/V_lim",
            _per_condition(get, group, f"{prefix}_motor_voltage_margin", ">=", entry),
            limits.min_voltage_margin,
            ">=",
        )
        add(
            f"{prefix} motors: current margin 1 - |I|/I_peak",
            _per_condition(get, group, f"{prefix}_motor_current_margin", ">=", entry),
            0.0,
            ">=",
        )
        add(
            f"{prefix} motors: torque margin T_max/T - 1",
            _per_condition(get, group, f"{prefix}_motor_torque_margin", ">=", entry),
            limits.min_torque_margin,
            ">=",
        )

    # Rotors: tip Mach numbers, their tables, advance ratio, chords.
    add("hover tip Mach (per pair)", _per_condition(get, hover, "lift_tip_mach", "<="),
        limits.max_tip_mach, "<=")  # fmt: skip
    add(
        "lift rotors' helical tip Mach, OEI and transition",
        _per_condition(get, oei + transition, "lift_helical_tip_mach", "<="),
        limits.max_lift_rotor_tip_mach,
        "<=",
    )
    add(
        "pusher helical tip Mach",
        _per_condition(get, pusher_conds, "pusher_helical_tip_mach", "<="),
        limits.max_pusher_tip_mach,
        "<=",
    )
    for label, rotor, group, output in (
        ("lift", vehicle.lift_rotors[0], hover + oei + transition, "lift_helical_tip_mach"),
        ("pusher", vehicle.pusher, pusher_conds, "pusher_helical_tip_mach"),
    ):
        table_mach = np.atleast_1d(getattr(get_polar(rotor.airfoil), "table_mach", [0.0]))
        if table_mach.size > 1:
            add(
                f"{label} blade sections inside the polar table (tip Mach)",
                _per_condition(get, group, output, "<="),
                table_mach[-1],
                "<=",
            )
    add(
        "lift rotors' advance ratio in transition",
        _per_condition(get, transition, "lift_advance_ratio", "<="),
        limits.max_lift_rotor_advance_ratio,
        "<=",
    )
    for label, group, output in (
        ("lift rotors in hover and one-rotor-out hover", hover + oei, "lift_blade_stall_ratio_ks"),
        ("pusher", pusher_conds, "pusher_blade_stall_ratio_ks"),
    ):
        if group:
            add(
                f"blade alpha/alpha_stall (KS), {label}",
                _per_condition(get, group, output, "<="),
                blade_stall_limit(limits),
                "<=",
            )
    margin = np.asarray(get("blade_chord_margin"), dtype=float)
    rotor = int(np.unravel_index(np.argmin(margin), margin.shape)[0])
    add(
        f"blade chord / radius (min {limits.min_chord_radius_ratio})",
        (float(margin.min()) + limits.min_chord_radius_ratio, f"rotor group {rotor + 1}"),
        limits.min_chord_radius_ratio,
        ">=",
    )

    # Layout: clearances of the lift disks.
    for output, key, label in (
        ("lift_rotor_clearance", "min_lift_rotor_clearance", "lift disk to lift disk"),
        ("rotor_fuselage_clearance", "min_rotor_fuselage_clearance", "lift disk to fuselage"),
        ("rotor_tail_clearance", "min_rotor_tail_clearance", "lift disk to horizontal tail"),
        ("rotor_pusher_clearance", "min_rotor_pusher_clearance", "lift disk to pusher disk"),
    ):
        v = np.ravel(get(output, "m"))
        if output == "lift_rotor_clearance":
            where = [f"lift rotors {a + 1} and {b + 1}" for a, b in rotor_pairs(vehicle)]
        else:
            where = [f"lift rotor {i + 1}" for i in range(v.size)]
        add(f"clearance: {label}", _worst(v, where, ">="), getattr(limits, key), ">=", "m")

    # Fuselage: mass items outside the cabin.
    rows = mass_properties(final, vehicle)
    inside = [
        r["name"]
        for r in rows
        if r["name"] in CABIN_EXCLUDED_ITEMS
        and r["mass"] > 0.0
        and vehicle.fuselage.in_cabin(r["cg"])
    ]
    items.append(
        ReviewItem(
            "systems, battery and gear inside the cabin (count)",
            float(len(inside)),
            0.0,
            "<=",
            ", ".join(inside) or "none",
        )
    )

    # Wing: each section's lift within its stall limit (the KS the problem constrains).
    structural = [c for c in conds if kinds[c.name] == "structural"]
    for group, load_case, label in (
        (transition + steady, False, "1-g conditions"),
        (structural, True, "+3g/-1g"),
    ):
        if group:
            add(
                f"wing section c_l/c_l,max (KS), {label}",
                _per_condition(get, group, "wing_stall_ratio_ks", "<="),
                wing_stall_limit(limits, load_case),
                "<=",
            )

    # Wing box: gauges a shop builds.
    thickness = {
        name: np.ravel(get(name, "m"))
        for name in ("front_spar_thickness", "rear_spar_thickness", "top_skin_thickness",
                     "bottom_skin_thickness")
    }  # fmt: skip
    values = np.concatenate(list(thickness.values()))
    labels = [f"{name}, bay {i + 1}" for name, v in thickness.items() for i in range(v.size)]
    add("wing-box gauge", _worst(values, labels, ">="), vehicle.material.min_gauge, ">=", "m")

    # Control reserve in hover and every OEI case, relative to the required acceleration.
    required = np.asarray(limits.min_control_acceleration, dtype=float)
    axes = np.flatnonzero(required > 0.0)
    if axes.size:
        values, labels = [], []
        names = ("roll", "pitch", "yaw")
        for c in hover + oei:
            got = np.ravel(get(f"{c.name}.control_acceleration", "rad/s**2"))
            values.extend(got[axes] / required[axes])
            labels.extend(f"{c.name}, {names[a]}" for a in axes)
        add("control reserve / required acceleration", _worst(values, labels, ">="), 1.0, ">=")
    return items


def design_review_table(source, vehicle=None, case=None):
    """Return :func:`design_review` as a :class:`~lpc_mdo.post.tables.Table`."""
    items = design_review(source, vehicle, case)
    table = Table(
        columns=["check", "worst value", "limit", "units", "worst at", "status"],
        title="Design review",
        notes=[
            "Each limit at its worst point over the conditions, rotors and motors of the final "
            "case, whether or not the run constrained it; limits from the vehicle file.",
            f"ok: within {TOLERANCE:g} of the limit's scale (the optimizers' feasibility).",
        ],
    )
    for item in items:
        table.rows.append(
            [item.check, item.value, f"{item.sense} {item.limit:.4g}", item.units, item.where,
             "ok" if item.ok else "VIOLATED"]
        )  # fmt: skip
    return table
