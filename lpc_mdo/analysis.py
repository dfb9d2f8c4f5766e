"""Analysis of a vehicle at its initial design, trimmed: the one code path of ``lpc-mdo analyze``.

:func:`analyze_vehicle` builds the full model of a vehicle (:func:`~lpc_mdo.problems.
build_analysis_problem`), trims every design condition by its own trim variables (rotor speeds,
pitch, elevator; :func:`lpc_mdo.trim.trim`) unless told not to, and records the problem case
``'final'``. ``lpc-mdo analyze`` and ``run_scripts/run_analysis.py`` both call it.

Trim tolerance
--------------
A condition counts as trimmed when its largest driver-scaled trim residual is below
:data:`TRIM_TOLERANCE` = 1e-3. The force rows are scaled by g abs(n) and the moment rows by
1 rad/s**2, so this is 0.1 % of the weight (times the load factor) as a force: the criterion the
project uses for the Table 6 trim rows ("trim rows < 0.1 % of W0") and the default limit
of :func:`lpc_mdo.post.trim_residuals.trim_residual_table`. The same tolerance is the status
band of the trim rows in the constraint status (:func:`status_tolerances`). The design gross
mass closure W0 - W_dg = 0 has the band :data:`CLOSURE_TOLERANCE`: the vehicle file keeps W_dg
to 0.01 kg. The other constraints use :data:`lpc_mdo.post.tables.DEFAULT_TOL`.
"""

from dataclasses import dataclass, field

import numpy as np

from lpc_mdo.api.weights import format_mass_properties, mass_properties
from lpc_mdo.groups.vehicle_drag import lpc_drag_components
from lpc_mdo.problems import MASS_CLOSURE, build_analysis_problem
from lpc_mdo.trim import problem_vehicle, single_condition_problem
from lpc_mdo.trim import trim as trim_conditions
from lpc_mdo.vehicle.condition_layout import condition_layout

__all__ = [
    "CLOSURE_TOLERANCE",
    "TRIM_TOLERANCE",
    "Analysis",
    "analyze_vehicle",
    "format_static_margin_budget",
    "format_drag_breakdown",
    "format_trim_variables",
    "static_margin_budget",
    "status_tolerances",
    "trim_variable_values",
]

#: Largest driver-scaled trim residual of a trimmed condition (module docstring).
TRIM_TOLERANCE = 1e-3
#: Outputs of the trim rows of a condition.
TRIM_OUTPUTS = ("linear_acceleration", "angular_acceleration")
#: Status band of W0 - W_dg = 0 (relative to its 10 kg ref): 0.01 kg, the precision to which the
#: vehicle file keeps W_dg (lpc_mdo.sizing rounds it to that).
CLOSURE_TOLERANCE = 1e-3


@dataclass
class Analysis:
    """
    Result of :func:`analyze_vehicle`.

    Attributes
    ----------
    prob : om.Problem
        The set-up, run problem (call ``prob.cleanup()`` when done).
    trimmed : bool
        Whether the conditions were trimmed (False: the raw initial design).
    trim : TrimResult or None
        The trim's outcome (:func:`lpc_mdo.trim.trim`), None when not trimmed.
    failed : dict
        Condition -> largest scaled trim residual, for every condition whose residual is not
        below :data:`TRIM_TOLERANCE` (empty when all trimmed or not trimmed).
    """

    prob: object
    trimmed: bool
    trim: object = None
    failed: dict = field(default_factory=dict)

    @property
    def vehicle(self):
        """The analyzed vehicle."""
        return self.prob.vehicle


def analyze_vehicle(
    vehicle=None,
    trim=True,
    recorder_path=None,
    static_margin=True,
    report=None,
    processes=1,
    **options,
):
    """
    Build, (trim,) run and record the full model of a vehicle at its initial design.

    Parameters
    ----------
    vehicle : Vehicle, str, os.PathLike or None
        A vehicle, a vehicle file, or None for the reference vehicle.
    trim : bool
        Trim every condition by its trim variables (:func:`lpc_mdo.trim.trim`), where more
        variables than rows leave a family of trims the one of least electrical power within
        the condition's limits (``least_power``); False: run the raw initial design (the vehicle
        file's initial rotor speeds, pitch and elevator).
    recorder_path : str, os.PathLike or None
        Case file; the problem case ``'final'`` (every variable) is recorded into it.
    static_margin : bool
        Declare the cruise static-margin constraint.
    report : callable or None
        Called with one line per trimmed condition (see :func:`lpc_mdo.trim.trim`).
    processes : int
        Processes that trim conditions at the same time (``workers`` of
        :func:`lpc_mdo.trim.trim`; the result does not depend on it).
    **options
        Further options of :func:`~lpc_mdo.problems.build_analysis_problem` (``name``,
        ``work_dir``, model options).

    Returns
    -------
    Analysis
        The problem, left at the (trimmed) design and run, and the trim's outcome.
    """
    prob = build_analysis_problem(
        vehicle, recorder_path=recorder_path, static_margin=static_margin, **options
    )
    result, failed = None, {}
    if trim:
        result = trim_conditions(
            prob, report=report, label="analyze", workers=processes, least_power=True
        )
        failed = {
            name: c.max_residual
            for name, c in result.conditions.items()
            if not c.max_residual < TRIM_TOLERANCE
        }
    else:
        prob.run_model()
    if recorder_path is not None:
        prob.record("final")
    return Analysis(prob, trim, result, failed)


def format_mass_table(analysis):
    """
    Return the mass, cg and inertia table per mass item of an analysis.

    See :func:`lpc_mdo.api.weights.mass_properties`; NASA's cg of the LPC for comparison is in
    docs theory/weights 'Mass items'.
    """
    return format_mass_properties(mass_properties(analysis.prob, analysis.vehicle))


def status_tolerances(prob, tol=TRIM_TOLERANCE):
    """
    Return constraint name -> status band for the constraints that do not use the default.

    Every declared trim-row constraint of ``prob`` gets ``tol``, the design gross mass closure
    :data:`CLOSURE_TOLERANCE`.
    """
    constraints = prob.model.get_constraints()
    tols = {
        name: tol
        for name in constraints
        if name.partition(".")[0] in prob.model.condition_names
        and name.partition(".")[2] in TRIM_OUTPUTS
    }
    if MASS_CLOSURE in constraints:
        tols[MASS_CLOSURE] = CLOSURE_TOLERANCE
    return tols


def trim_variable_values(prob, condition):
    """
    Return the trim variables of a condition and their values.

    Parameters
    ----------
    prob : om.Problem
        A set-up problem of the vehicle (``prob.vehicle``).
    condition : str
        The condition's name.

    Returns
    -------
    list of (str, numpy.ndarray, str)
        (variable of the condition, e.g. ``lift_rpm``; its values; units), elevator and pitch
        angles in degrees.
    """
    out = []
    for variable, entry in condition_layout(prob.vehicle).entries[condition].items():
        if not entry.variable.trim:
            continue
        units = entry.variable.units
        units = "deg" if units in ("rad", "deg") else (None if units == "unitless" else units)
        value = np.asarray(prob.get_val(entry.design_variable, units=units), float).ravel()
        out.append((variable, value[entry.flat_indices], units or "-"))
    return out


def format_trim_variables(prob, conditions=None):
    """Return a text table: one line per condition with its trim variables' values."""
    names = prob.model.condition_names if conditions is None else conditions
    lines = []
    for name in names:
        parts = []
        for variable, value, units in trim_variable_values(prob, name):
            text = (
                f"{value[0]:.4g}"
                if value.size == 1
                else "[" + ", ".join(f"{v:.4g}" for v in value) + "]"
            )
            parts.append(f"{variable} {text} {units}")
        lines.append(f"  {name:<14}{'; '.join(parts) or '(no trim variables)'}")
    return "\n".join(lines)


def static_margin_budget(prob, condition=None, wing_panels=None):
    """
    Contributions to the static margin of a condition solved with the stability option.

    SM = (x_cg - x_np)/MAC with x_np = -(dM/dalpha)/(dF_z/dalpha) (both about the body
    origin) is a sum over the parts i of the force and moment:

        dSM_i = (dM_i/dalpha + x_cg dF_z,i/dalpha) / (dF_z/dalpha MAC),

    each slope the difference of the nominal and the perturbed solve over their delta (the
    model's own :class:`~lpc_mdo.components.dynamics.stability_derivatives.
    StabilityDerivativeComp`). Parts: ``wing`` and ``horizontal_tail`` (the lattice's inviscid
    and profile-drag panel forces of each surface; the tail's at eta_t q), ``fuselage`` and
    ``booms`` (the Munk-Multhopp couples,
    :mod:`lpc_mdo.components.dynamics.body_pitching_moment`); the airfoils' cm0, a couple
    independent of alpha, moves the trim but not the neutral point.

    Parameters
    ----------
    prob : om.Problem
        A run LPC problem that holds the condition.
    condition : str or None
        The condition; None: the mission's design cruise condition
        (``mission.cruise_condition`` of the problem's vehicle).
    wing_panels : int or None
        Spanwise panels of the wing in the lattice (None: from ``wing_sectional_cl``).

    Returns
    -------
    dict
        Part -> dSM, and ``total`` (equal to the model's ``static_margin``).
    """
    c = condition or problem_vehicle(prob).mission.cruise_condition
    delta = prob.model._get_subsystem(f"{c}.stability_derivatives").options["delta"]
    x_cg = prob.get_val(f"{c}.static_margin.cg_x", units="m")[0]
    mac = prob.get_val(f"{c}.static_margin.mean_aerodynamic_chord", units="m")[0]
    dfz = prob.get_val(f"{c}.normal_force_slope", units="N/rad")[0]
    points = prob.get_val(f"{c}.vlm.force_points", units="m")
    if wing_panels is None:
        wing_panels = prob.get_val(f"{c}.wing_sectional_cl").shape[-1]

    def part_loads(prefix):
        f = prob.get_val(f"{c}.{prefix}.panel_forces", units="N")[0]
        f = f + prob.get_val(f"{c}.{prefix}.viscous_panel_forces", units="N")[0]
        m_y = points[:, 2] * f[:, 0] - points[:, 0] * f[:, 2]  # (r x F)_y about the origin
        return f[:, 2], m_y

    fz0, my0 = part_loads("vlm")
    fz1, my1 = part_loads("vlm_perturbed")
    dfz_p, dmy_p = (fz1 - fz0) / delta, (my1 - my0) / delta
    budget = {}
    parts = (("wing", slice(0, wing_panels)), ("horizontal_tail", slice(wing_panels, None)))
    for name, sl in parts:
        budget[name] = (dmy_p[sl].sum() + x_cg * dfz_p[sl].sum()) / (dfz * mac)
    # Tail efficiency (TailEfficiencyComp): its correction belongs to the tail.
    f0 = prob.get_val(f"{c}.tail_force_correction", units="N")[0, 2]
    f1 = prob.get_val(f"{c}.perturbed_tail_force_correction", units="N")[0, 2]
    t0 = prob.get_val(f"{c}.tail_moment_correction", units="N*m")[0, 1]
    t1 = prob.get_val(f"{c}.perturbed_tail_moment_correction", units="N*m")[0, 1]
    budget["horizontal_tail"] += ((t1 - t0) + x_cg * (f1 - f0)) / delta / (dfz * mac)
    # Bodies (BodyPitchingMomentComp): the couple is linear in alpha with the slope
    # q sum_b S_b, so each body's share of the difference is its S_b over the sum.
    m0 = prob.get_val(f"{c}.body_moment", units="N*m")[0, 1]
    m1 = prob.get_val(f"{c}.perturbed_body_moment", units="N*m")[0, 1]
    slopes = prob.get_val(f"{c}.body_moment.body_moment_slope", units="m**3")
    for name, share in zip(("fuselage", "booms"), slopes / slopes.sum(), strict=True):
        budget[name] = share * (m1 - m0) / delta / (dfz * mac)
    budget["total"] = sum(budget.values())
    return budget


def format_static_margin_budget(prob, condition=None):
    """
    Return one line per part of :func:`static_margin_budget`, for ``lpc-mdo analyze``.

    Parameters
    ----------
    prob : om.Problem
        A run LPC problem that holds the condition.
    condition : str or None
        The condition; None: the mission's design cruise condition.

    Returns
    -------
    str
    """
    condition = condition or problem_vehicle(prob).mission.cruise_condition
    budget = static_margin_budget(prob, condition)
    model = prob.get_val(f"{condition}.static_margin")[0]
    lines = [f"    {name:<16s} {value:+.4f}" for name, value in budget.items()]
    lines.append(f"    {'(model)':<16s} {model:+.4f}")
    return "\n".join(lines)


def format_drag_breakdown(prob, vehicle=None):
    """Return a text table: C_D0 and D/q of each drag part in every wing-borne condition.

    The parts are those of :func:`lpc_mdo.groups.vehicle_drag.lpc_drag_components`
    (then the lumped drag area and the leakage/protuberance allowance); conditions without a
    ``drag_breakdown`` output (hover) are skipped.
    """
    vehicle = vehicle or prob.vehicle
    comps, _ = lpc_drag_components(vehicle)
    names = [c.name for c in comps] + ["lumped", "allowance"]
    s_ref = float(prob.get_val("wing_area", units="m**2")[0])
    rows = []
    for name in prob.model.condition_names:
        try:
            breakdown = np.asarray(prob.get_val(f"{name}.drag_breakdown"))[0]
        except KeyError:
            continue
        rows.append((name, breakdown))
    if not rows:
        return "  drag breakdown: no wing-borne condition"
    header = f"  {'part':<20}" + "".join(f"{n[:12]:>13}" for n, _ in rows) + f"{'D/q [m^2]':>12}"
    lines = [
        f"  drag breakdown, C_D0 per part on S_ref = {s_ref:.2f} m^2 (D/q of the first column):",
        header,
    ]
    for i, part in enumerate(names):
        lines.append(
            f"  {part:<20}"
            + "".join(f"{b[i]:>13.5f}" for _, b in rows)
            + f"{rows[0][1][i] * s_ref:>12.4f}"
        )
    lines.append(
        f"  {'total C_D0':<20}"
        + "".join(f"{b.sum():>13.5f}" for _, b in rows)
        + f"{rows[0][1].sum() * s_ref:>12.4f}"
    )
    return "\n".join(lines)


def airframe_lift_drag(prob, condition):
    """
    Airframe (C_L, C_D) of a run wing-borne condition, on the wing area.

    The aerodynamic force of the lattice (with its profile drag and the tail-efficiency
    correction) plus the parasite-drag build-up, not the rotors, in wind axes: with
    e_V = (cos a, 0, sin a) and e_L = (-sin a, 0, cos a) in body axes (x forward, z down),
    D = -F . e_V and L = -F . e_L.
    """
    alpha = prob.get_val(f"{condition}.angle_of_attack", units="rad")[0]
    force = (
        prob.get_val(f"{condition}.aero_force", units="N")[0]
        + prob.get_val(f"{condition}.drag_force", units="N")[0]
    )
    q_s = (
        prob.get_val(f"{condition}.dynamic_pressure", units="Pa")[0]
        * prob.get_val("wing_area", units="m**2")[0]
    )
    drag = -(force[0] * np.cos(alpha) + force[2] * np.sin(alpha))
    lift = -(-force[0] * np.sin(alpha) + force[2] * np.cos(alpha))
    return lift / q_s, drag / q_s


def lift_to_drag(prob, condition=None, pitch_deg=None):
    """
    Airframe lift-to-drag ratio of a wing-borne condition over a sweep of pitch angles.

    The condition is evaluated alone (its own single-condition problem with ``prob``'s design
    variables: rotor speeds and elevator as they are) at each pitch angle; lift and drag are
    those of :func:`airframe_lift_drag`. Comparable with a glider polar of the airframe (NASA's
    CFD model of the LPC, docs theory/aerodynamics 'Drag build-up').

    Parameters
    ----------
    prob : om.Problem
        A run LPC problem that holds ``condition``.
    condition : str or None
        A condition with aerodynamics; None: the mission's design cruise condition.
    pitch_deg : array_like or None
        Pitch angles, deg; None: -2 to 14 deg in 1 deg steps (the parabola through the best
        point and its neighbours finds the maximum within 0.05 % of a 0.05 deg sweep).

    Returns
    -------
    dict
        ``pitch_deg``, ``CL``, ``CD``, ``L/D`` (arrays over the sweep), ``max_L/D`` and its
        ``CL_at_max`` (the sweep's largest ratio, refined by a parabola through its
        neighbours).
    """
    vehicle = problem_vehicle(prob)
    condition = condition or vehicle.mission.cruise_condition
    pitch_deg = np.arange(-2.0, 14.0 + 1e-9, 1.0) if pitch_deg is None else np.asarray(pitch_deg)
    variables = dict(condition_layout(vehicle).trim_variables(condition))
    pitch_names = [n for n in variables if n.endswith("_pitch")]
    if not pitch_names:
        raise ValueError(
            f"lift_to_drag: condition '{condition}' has no pitch design variable "
            f"(its trim variables are {list(variables)}); allowed: a steady wing-borne "
            "condition."
        )
    single = single_condition_problem(prob, condition, name=f"lift_to_drag_{condition}")
    pitch_name = pitch_names[0]
    base = np.asarray(single.get_val(pitch_name, units="deg"), dtype=float).copy()
    position = variables[pitch_name]
    cl, cd = [], []
    for pitch in pitch_deg:
        value = base.copy()
        value.reshape(-1)[position] = pitch
        single.set_val(pitch_name, value, units="deg")
        single.run_model()
        coefficients = airframe_lift_drag(single, condition)
        cl.append(coefficients[0])
        cd.append(coefficients[1])
    cl, cd = np.array(cl), np.array(cd)
    ratio = cl / cd
    k = int(np.argmax(ratio))
    best, cl_best = ratio[k], cl[k]
    if 0 < k < ratio.size - 1:  # vertex of the parabola through the three points
        y0, y1, y2 = ratio[k - 1 : k + 2]
        denom = y0 - 2.0 * y1 + y2
        if denom < 0.0:
            t = 0.5 * (y0 - y2) / denom
            best = y1 - 0.25 * (y0 - y2) * t
            cl_best = cl[k] + t * 0.5 * (cl[k + 1] - cl[k - 1])
    single.cleanup()
    return {
        "pitch_deg": pitch_deg,
        "CL": cl,
        "CD": cd,
        "L/D": ratio,
        "max_L/D": float(best),
        "CL_at_max": float(cl_best),
    }
