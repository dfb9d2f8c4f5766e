"""Trim of the design conditions by their own trim variables, at a fixed vehicle design.

Each condition has its trim constraints (paper Table 6: force and moment balance, the
prescribed transition acceleration) and its trim variables (rotor speeds, pitch, elevator;
:meth:`lpc_mdo.vehicle.condition_layout.ConditionLayout.trim_variables`, from each kind's
contract). With everything else fixed these form a small nonlinear system per condition,
square or under-determined, with bounds. :func:`trim` solves them one condition at a time (a
shared trust region would let the hardest condition throttle the others) by bounded
Gauss-Newton least squares on the exact total derivatives, in the optimizer's scaled space:
first scipy's dogbox trust-region method for :data:`DOGBOX_EVALUATIONS` evaluations; where that
does not reach the tolerance, trust-region reflective again from the same start (``max_iter``
evaluations), keeping the better of the two; where that still does not, dogbox once more from
the better end point, with a fresh trust region.

Where a condition has more trim variables than rows (hover, transition, one rotor out), a
family of trims holds it and the least-squares solve returns the member its path reaches. With
``least_power`` (what ``lpc-mdo analyze``, ``lpc-mdo size`` and the sequence's stages use) the
trim then moves to the member of least electrical power within the condition's
:data:`LEAST_POWER_LIMITS` (:func:`_least_power`), so the trimmed numbers depend on the design,
not on the start.

The stages of the warm-start sequence trim their conditions before their optimizer runs
(:attr:`lpc_mdo.study_plan.Stage.trim_first`): an optimizer with a quasi-Newton Hessian started
far from trim stalls at a locally infeasible point. The measurements behind these choices are
in the theory manual (page "The optimization problem", section "Trim before each stage").
"""

import atexit
import functools
import multiprocessing
import shutil
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field

import numpy as np
import openmdao.api as om
from scipy.optimize import least_squares, minimize

from lpc_mdo.drivers.scaling import driver_scaling
from lpc_mdo.groups.lpc import openmdao_units
from lpc_mdo.problems import build_analysis_problem, copy_design_variables, trim_constraints
from lpc_mdo.progress import trim_line
from lpc_mdo.vehicle.condition_layout import condition_layout


@dataclass
class ConditionTrim:
    """
    Outcome of the trim of one condition.

    Attributes
    ----------
    initial_residual, max_residual : float
        Largest driver-scaled trim residual before and after (force rows scaled by g abs(n),
        moment rows by 1 rad/s**2: 1e-3 is 0.1 % of the weight).
    iterations : int
        Jacobian evaluations.
    seconds : float
        Wall time, including the single-condition problem's setup.
    method : str
        The scipy method whose result was kept (``dogbox`` or ``trf``).
    message : str
        The solver's message.
    power : tuple or None
        With ``least_power`` where the condition has more trim variables than rows: its
        electrical power (W) at the trim the solve reached and at the one kept, and the
        least-power solver's message; None otherwise.
    """

    initial_residual: float
    max_residual: float
    iterations: int
    seconds: float
    method: str
    message: str
    power: tuple | None = None


@dataclass
class TrimResult:
    """Outcome of :func:`trim` (``iterations``: Jacobian evaluations over all conditions).

    ``conditions`` maps each trimmed condition to its :class:`ConditionTrim`.
    """

    success: bool
    iterations: int
    max_residual: float
    residuals: dict
    message: str
    conditions: dict = field(default_factory=dict)


def _trim_constraints(prob, conditions):
    """Trim constraints of the given conditions: name -> metadata (bounds as declared)."""
    cons = prob.model.get_constraints()
    found = {}
    for name, meta in cons.items():
        head, _, tail = name.partition(".")
        if head in conditions and tail in ("linear_acceleration", "angular_acceleration"):
            found[name] = meta
    return found


def _trim_variables(prob, vehicle, conditions):
    """(DV name, positions in the driver's DV vector) of every condition's trim variables."""
    dvs = prob.model.get_design_vars()
    entries = []
    for cond in conditions:
        for dv_name, flat in condition_layout(vehicle).trim_variables(cond):
            if dv_name not in dvs:
                raise ValueError(
                    f"trim: condition '{cond}' needs design variable '{dv_name}', "
                    "which the problem does not declare."
                )
            indices = dvs[dv_name]["indices"]
            declared = np.arange(dvs[dv_name]["size"]) if indices is None else indices.as_array()
            pos = np.searchsorted(declared, flat)
            if np.any(pos >= declared.size) or np.any(
                declared[np.minimum(pos, declared.size - 1)] != flat
            ):
                raise ValueError(
                    f"trim: design variable '{dv_name}' of condition '{cond}' is "
                    f"declared without entries {flat.tolist()}."
                )
            entries.append((dv_name, pos))
    merged = {}
    for dv_name, pos in entries:
        merged[dv_name] = np.union1d(merged.get(dv_name, np.array([], int)), pos).astype(int)
    return merged


#: Residual evaluations of the first (dogbox) attempt per condition (docs/theory/optimization.rst,
#: "Trim before each stage": every condition dogbox trims takes 4-7 Jacobians).
DOGBOX_EVALUATIONS = 20


@functools.lru_cache(maxsize=1)
def _scratch_dir():
    """
    Return a per-process folder for the trim problems' OpenMDAO output folders (removed at exit).

    Trimming thus does not leave 15 ``trim_<condition>_out`` folders in the user's.
    """
    path = tempfile.mkdtemp(prefix="lpc_mdo_trim_")
    atexit.register(shutil.rmtree, path, ignore_errors=True)
    return path


#: Constraint kinds of its condition within which a least-power trim keeps it: the rotor models'
#: ranges (tip Mach number, advance ratio, blade stall, the transition rotor-speed range).
LEAST_POWER_LIMITS = ("tip_mach", "advance_ratio", "blade_stall", "rotor_speed")
#: Reference of a condition's electrical power as a single-condition problem's objective, W.
POWER_REF = 1.0e5
#: Largest scaled limit violation a least-power trim accepts (the trim rows' 1e-6 otherwise).
LIMIT_TOLERANCE = 1.0e-6

# LPCGroup options a single-condition trim problem inherits from the problem it trims.
_INHERITED_OPTIONS = ("rotor_polar", "wing_zero_lift_angle", "ks_rho", "structural_coupling")


def problem_vehicle(prob):
    """Return the Vehicle of a set-up LPC problem (``prob.vehicle``, else the model's)."""
    return prob.vehicle if hasattr(prob, "vehicle") else prob.model.vehicle_spec


#: Vehicle-level inputs that are not design variables but a caller may set on the problem, copied
#: into each single-condition problem with the design: the design gross mass of the weight
#: regressions and the tyres (:mod:`lpc_mdo.sizing` closes it).
COPIED_PARAMETERS = (("design_gross_mass", "kg"),)


def free_trim_variables(vehicle, condition):
    """Trim variables of a condition beyond its trim rows (without the degenerate rows)."""
    variables = sum(
        np.size(flat) for _, flat in condition_layout(vehicle).trim_variables(condition)
    )
    rows = sum(
        len(indices)
        for _, indices, _, _ in trim_constraints(
            vehicle, vehicle.condition(condition), lateral_trim=False
        )
    )
    return variables - rows


def single_condition_problem(prob, condition, name, least_power=False):
    """
    Return a set-up problem of one condition of ``prob``'s model with ``prob``'s design.

    The same vehicle and model options (:data:`_INHERITED_OPTIONS`), the condition's trim
    constraints only, no static margin; every design variable and the
    :data:`COPIED_PARAMETERS` copied from ``prob`` (not run). Where ``prob``'s model computes
    the condition's footprint levels, this one does too: a trim point outside their range
    (a lift rotor turning slower than the flight speed) then fails in the solve, which backs
    off from it, and not afterwards in ``prob``. With ``least_power``, the problem also declares
    the condition's :data:`LEAST_POWER_LIMITS` and its electrical power as the objective.
    Its OpenMDAO output folder is in the per-process scratch folder.
    """
    vehicle = problem_vehicle(prob)
    declared = {}
    if least_power and free_trim_variables(vehicle, condition) > 0:
        declared = {
            "constraint_kinds": ["trim", *LEAST_POWER_LIMITS],
            "objective": (f"{condition}.electrical_power", POWER_REF),
        }
    single = build_analysis_problem(
        vehicle,
        name=name,
        conditions=[condition],
        lateral_trim=False,
        static_margin=False,
        comm=prob.comm,
        work_dir=_scratch_dir(),
        footprint_levels=condition in getattr(prob.model, "heard_conditions", ()),
        **({"constraint_kinds": ["trim"]} | declared),
        **{k: prob.model.options[k] for k in _INHERITED_OPTIONS},
    )
    copy_design_variables(prob, single, vehicle)
    for name, units in COPIED_PARAMETERS:
        single.set_val(name, prob.get_val(name, units=units), units=units)
    return single


def trim(
    prob,
    conditions=None,
    tol=1e-10,
    max_iter=100,
    separate=True,
    report=None,
    label="trim",
    workers=1,
    least_power=False,
):
    """
    Trim conditions of a set-up LPC problem by their trim variables (module docstring).

    Parameters
    ----------
    prob : om.Problem
        A problem whose model is an :class:`~lpc_mdo.groups.lpc.LPCGroup` that declares the trim
        design variables of the conditions (and, with ``separate=False``, their trim
        constraints: build it with ``lateral_trim=False``, since some lateral rows have no
        trim variable: hover p_dot and the OEI and transition v_dot).
    conditions : sequence of str or None
        Conditions to trim; None = every condition of the model.
    tol : float
        Tolerance on the scaled residual, step and gradient (scipy ``ftol``/``xtol``/``gtol``).
    max_iter : int
        Limit on residual evaluations per condition of trust-region reflective, which runs
        from the same start where dogbox (at most :data:`DOGBOX_EVALUATIONS` of them) does
        not reach 1e-6.
    separate : bool
        Solve each condition in its own single-condition problem (the same vehicle design,
        copied over), whose model runs cost a fraction of the whole model's; the trim
        variables found are copied back. False: solve in ``prob`` itself.
    report : callable or None
        Called with one line per condition when it is trimmed (:func:`lpc_mdo.progress.trim_line`:
        the largest driver-scaled residual before and after, iterations, seconds); None: quiet.
    label : str
        Start of each reported line (the stage's name).
    workers : int
        Processes that trim conditions at the same time (``separate`` only, not under MPI;
        forked, so each inherits ``prob``). The conditions are independent at a fixed design,
        so the result does not depend on it; 1 (default) trims in this process. The lines of
        ``report`` then come when all conditions are done, in order.
    least_power : bool
        Where a condition has more trim variables than rows (hover, transition, one rotor
        out), a family of trims holds it; move each such trim to the member of least
        electrical power within the condition's :data:`LEAST_POWER_LIMITS` (module
        docstring). ``separate`` only. False: the member the solve reaches from the start.

    Returns
    -------
    TrimResult
        ``residuals`` maps each trim constraint to its unscaled residual (value - target);
        ``success`` means the largest driver-scaled residual is below 1e-6 (for the force rows,
        scaled by g, that is 1e-6 of the weight). ``prob`` is left at the solution, run.

    Raises
    ------
    ValueError
        When a problem lacks a trim constraint or variable of a condition.
    om.AnalysisError
        When the model fails during the solve.
    """
    vehicle = problem_vehicle(prob)
    conditions = list(prob.model.condition_names if conditions is None else conditions)
    if least_power and not separate:
        raise ValueError("trim: least_power needs separate=True (single-condition problems)")
    prob.run_model()
    workers = min(int(workers), len(conditions))
    if separate and workers > 1 and prob.comm.size == 1:
        outcomes = _trim_in_processes(
            prob, vehicle, conditions, tol, max_iter, workers, least_power
        )
    else:
        outcomes = (
            _trim_condition(prob, vehicle, cond, tol, max_iter, separate, least_power)
            for cond in conditions
        )
    residuals, iterations, messages, worst, per_condition = {}, 0, [], 0.0, {}
    for cond, outcome in zip(conditions, outcomes, strict=True):
        for name, (flat, entries) in outcome.values.items():
            units = openmdao_units(vehicle.design_variables[name].units)
            full = np.asarray(prob.get_val(name, units=units)).copy()
            full.reshape(-1)[flat] = entries
            prob.set_val(name, full, units=units)
        result = outcome.result
        residuals.update(outcome.residuals)
        iterations += result.iterations
        worst = max(worst, result.max_residual)
        if result.max_residual >= 1e-6:
            messages.append(f"{cond}: max scaled residual {result.max_residual:.3g} "
                            f"({result.message})")  # fmt: skip
        per_condition[cond] = result
        if report is not None:
            report(
                trim_line(
                    label,
                    cond,
                    result.initial_residual,
                    result.max_residual,
                    result.iterations,
                    result.seconds,
                    result.power,
                )
            )
    if separate:
        prob.run_model()
    return TrimResult(
        success=worst < 1e-6,
        iterations=iterations,
        max_residual=worst,
        residuals=residuals,
        message="; ".join(messages) or "all conditions trimmed",
        conditions=per_condition,
    )


def _least_power(prob, cond, cons, variables, max_iter):
    """
    Move a trimmed condition to its least electrical power within its trim rows and limits.

    ``prob`` is a single-condition problem built with ``least_power`` (its objective the
    condition's electrical power, its constraints the trim rows and the condition's
    :data:`LEAST_POWER_LIMITS`), set at a trimmed point. In the optimizer's scaled space, with
    the variables' bounds: where the trim breaks a limit, first SLSQP finds the trim of least
    total excess over the limits (an elastic phase one: the sum of slacks s >= 0 with
    margin + s >= 0, the trim rows as equalities); then SLSQP minimizes the power with the
    trim rows as equalities and the limits as inequalities. A trial point where the model
    fails is answered with large values, so that SLSQP's line search backs off.

    Where no trim within the limits is found, each limit is relaxed to its margin at the trim of
    least excess, and the least power sought within that.

    Returns (power at the start, power kept, message, scaled trim residuals at the point kept,
    as :func:`_solve_block` gives them); the problem is left at the point kept:
    the least-power point where its trim rows are within 1e-6 and its (relaxed) limits within
    :data:`LIMIT_TOLERANCE`, else the first such trim found; else the start.
    """
    dv_meta = prob.model.get_design_vars()
    limits = {
        name: meta
        for name, meta in prob.model.get_constraints().items()
        if name.partition(".")[0] == cond and name not in cons
    }
    objective = prob.model.get_objectives()
    block = _ScaledBlock(prob, dv_meta, variables)
    targets = block.scaled_bounds(cons, "equals")
    lower, upper = block.scaled_bounds(limits, "lower"), block.scaled_bounds(limits, "upper")
    has_lower, has_upper = ~np.isnan(lower), ~np.isnan(upper)
    count = int(has_lower.sum() + has_upper.sum())  # bounded limit entries
    bounds = (block.lower, block.upper)

    def evaluates(x):
        try:
            block.set_x(x)
        except om.AnalysisError:
            return False
        return True

    # A trial point where the model fails gets large finite values (SLSQP's line search then
    # backs off, where infinities would stop it); SLSQP differentiates at accepted points only.
    failed = 1.0e3

    def margins(x):
        """Scaled limit margins (>= 0 where a limit holds), one per bounded entry."""
        if not evaluates(x):
            return np.full(count, -failed)
        value = block.values(limits)
        return np.concatenate([(value - lower)[has_lower], (upper - value)[has_upper]])

    last = {}

    def derivative(key, responses, x):
        """d(responses)/dx at x; at a point where the model fails, the last one computed."""
        if evaluates(x) or key not in last:
            block.set_x(x)
            last[key] = block.jacobian(responses)
        return last[key]

    def margins_jacobian(x):
        jac = derivative("limits", limits, x)
        return np.vstack([jac[has_lower], -jac[has_upper]])

    def rows(x):
        return block.values(cons) - targets if evaluates(x) else np.full(targets.size, failed)

    def rows_jacobian(x):
        return derivative("rows", cons, x)

    def power(x):
        return float(block.values(objective)[0]) if evaluates(x) else failed

    def power_gradient(x):
        return derivative("power", objective, x)[0]

    # The least margin each limit may have: 0, or where no trim meets the limits, the margin
    # of the trim of least excess over them.
    floor = np.zeros(count)

    def trimmed(x, tol=1e-6):
        return np.max(np.abs(rows(x)), initial=0.0) < tol

    def feasible(x):
        return (
            evaluates(x)
            and trimmed(x)
            and np.min(margins(x) - floor, initial=0.0) >= -LIMIT_TOLERANCE
        )

    def above_floor(x):
        return margins(x) - floor

    start = block.x0.copy()
    before = power(start)
    kept, note, within_limits = start, "the trim kept: no trim within the limits found", True
    start_feasible = feasible(start)
    try:
        if not start_feasible:
            # The trim of least total excess over the limits: SLSQP on (x, s), minimizing the sum
            # of the slacks s >= 0 with margins(x) + s >= 0 and the trim rows as equalities
            # (an elastic phase one: linear in s, so each step is a well-posed QP).
            n, m = start.size, count
            slack0 = np.maximum(-margins(start), 0.0)

            def excess(z):
                return float(np.sum(z[n:]))

            def excess_gradient(z):
                return np.concatenate([np.zeros(n), np.ones(m)])

            def elastic(z):
                return margins(z[:n]) + z[n:]

            def elastic_jacobian(z):
                return np.hstack([margins_jacobian(z[:n]), np.eye(m)])

            def trim_rows(z):
                return rows(z[:n])

            def trim_rows_jacobian(z):
                return np.hstack([rows_jacobian(z[:n]), np.zeros((targets.size, m))])

            within = minimize(
                excess, np.concatenate([start, slack0]), jac=excess_gradient,
                bounds=list(zip(*bounds, strict=True)) + [(0.0, None)] * m,
                constraints=[
                    {"type": "eq", "fun": trim_rows, "jac": trim_rows_jacobian},
                    {"type": "ineq", "fun": elastic, "jac": elastic_jacobian},
                ],
                method="SLSQP", options={"maxiter": max_iter, "ftol": 1e-10},
            )  # fmt: skip
            within.x = within.x[:n]

            def excess_at(x):
                return float(np.sum(np.maximum(-margins(x), 0.0)))

            x = np.clip(within.x, *bounds)
            note += f" ({within.message})"
            if not excess_at(x) <= excess_at(start):  # the start itself, where it ended worse
                x = start
            if feasible(x):
                kept = x
            elif trimmed(x, tol=1e-3):
                # No trim within the limits from here: the least power within the least excess
                # (the least-power solve from there makes the trim rows exact).
                floor = np.minimum(margins(x), 0.0) - LIMIT_TOLERANCE
                kept, within_limits = x, False
        if kept is not start or start_feasible:
            note = (
                "the first trim within the limits kept: least power not reached"
                if within_limits
                else "no trim within the limits: the trim of least excess kept"
            )
            constraints = [{"type": "eq", "fun": rows, "jac": rows_jacobian}]
            if limits:
                constraints.append({"type": "ineq", "fun": above_floor, "jac": margins_jacobian})
            sol = minimize(
                power, kept, jac=power_gradient, bounds=list(zip(*bounds, strict=True)),
                constraints=constraints, method="SLSQP",
                options={"maxiter": max_iter, "ftol": 1e-9},
            )  # fmt: skip
            x = np.clip(sol.x, *bounds)
            if sol.success and feasible(x) and power(x) <= power(kept):
                kept = x
                note = (
                    "least power"
                    if within_limits
                    else "no trim within the limits: least power at the least excess over them"
                )
            else:
                note += f" ({sol.message})"
    except (ValueError, om.AnalysisError) as err:  # a model failure SLSQP did not back off from
        note = f"{'the trim' if kept is start else 'the first trim found'} kept ({err})"
    if kept is not start and not trimmed(kept):
        kept, note = start, f"the trim kept: {note}"
    block.set_x(kept)
    return before, power(kept), note, rows(kept)


@dataclass
class _Outcome:
    """One condition's trim: its trim-variable entries (separate mode), residuals and record."""

    values: dict
    residuals: dict
    result: ConditionTrim


def _trim_condition(prob, vehicle, cond, tol, max_iter, separate, least_power=False):
    """Trim one condition of ``prob`` (in its own single-condition problem if ``separate``)."""
    started = time.perf_counter()
    target = prob
    if separate:
        target = single_condition_problem(prob, cond, name=f"trim_{cond}", least_power=least_power)
        target.run_model()
    cons = _trim_constraints(target, [cond])
    if not cons:
        raise ValueError(f"trim: no trim constraints declared for conditions ['{cond}'].")
    variables = _trim_variables(target, vehicle, [cond])
    sol, scaled, initial, method = _solve_block(
        target, target.model.get_design_vars(), cons, variables, tol, max_iter
    )
    powers = None
    trimmed = np.max(np.abs(scaled), initial=0.0) < 1e-6
    if least_power and separate and trimmed and free_trim_variables(vehicle, cond) > 0:
        before, after, note, scaled = _least_power(target, cond, cons, variables, max_iter)
        powers = (before * POWER_REF, after * POWER_REF, note)
    values = {}  # name -> (flat entries of this condition, their values): other conditions
    if separate:  # may share the array (e.g. one row per transition point)
        for name, flat in condition_layout(vehicle).trim_variables(cond):
            units = openmdao_units(vehicle.design_variables[name].units)
            entries = np.asarray(target.get_val(name, units=units)).ravel()[flat]
            values[name] = (np.asarray(flat), entries.copy())
    residuals, start = {}, 0
    for name, meta in cons.items():  # scaled residual = (value - target) * scaler
        part = scaled[start : start + meta["size"]]
        start += meta["size"]
        residuals[name] = part / driver_scaling(meta)[0]
    block_max = float(np.max(np.abs(scaled)))
    before = float(np.max(np.abs(initial))) if initial.size else 0.0
    result = ConditionTrim(
        before,
        block_max,
        int(sol.njev or 0),
        time.perf_counter() - started,
        method,
        str(sol.message),
        powers,
    )
    return _Outcome(values, residuals, result)


# The problem a trim worker process trims in: set by the pool initializer (fork start method,
# so the problem is inherited, not pickled).
_WORKER_PROBLEM = {}


def _worker_trim(cond, tol, max_iter, least_power):
    prob = _WORKER_PROBLEM["prob"]
    return _trim_condition(prob, problem_vehicle(prob), cond, tol, max_iter, True, least_power)


def _trim_in_processes(prob, vehicle, conditions, tol, max_iter, workers, least_power):
    """
    Trim the conditions in ``workers`` forked processes, each in its own single-condition problem.

    The conditions are independent at a fixed design, so the result is the serial one; the
    outcomes come back in the order of ``conditions``. Uses the fork start method (the workers
    inherit ``prob``); where fork is unavailable, trims serially.
    """
    if "fork" not in multiprocessing.get_all_start_methods():
        return [
            _trim_condition(prob, vehicle, c, tol, max_iter, True, least_power) for c in conditions
        ]
    _WORKER_PROBLEM["prob"] = prob
    try:
        with ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("fork")) as pool:
            futures = [
                pool.submit(_worker_trim, cond, tol, max_iter, least_power) for cond in conditions
            ]
            return [future.result() for future in futures]
    finally:
        _WORKER_PROBLEM.clear()


class _ScaledBlock:
    """
    One condition's trim variables in the optimizer's scaled space, and responses of its model.

    ``x`` holds the variables' entries scaled as the driver scales them, with their scaled
    bounds; responses (constraints, by name) are read and differentiated with the driver's
    scaling of responses and design variables.
    """

    def __init__(self, prob, dv_meta, variables):
        self.prob, self.dv_meta, self.variables = prob, dv_meta, variables
        x0 = []
        for name, pos in variables.items():
            scaler, adder, units = self._scaling(name)
            value = np.asarray(prob.get_val(name, units=units), dtype=float).ravel()
            x0.append((value[self._entries(name, pos)] + adder) * scaler)
        # get_design_vars keeps the bounds as declared (unscaled): scale them like the values.
        self.lower, self.upper = (
            np.concatenate(
                [
                    (
                        np.broadcast_to(dv_meta[n][side], (dv_meta[n]["size"],))[p]
                        + self._scaling(n)[1]
                    )
                    * self._scaling(n)[0]
                    for n, p in variables.items()
                ]
            )  # fmt: skip
            for side in ("lower", "upper")
        )
        self.x0 = np.clip(np.concatenate(x0), self.lower, self.upper)
        self._x = None

    def _scaling(self, name):
        return (*driver_scaling(self.dv_meta[name]), self.dv_meta[name]["units"])

    def _entries(self, name, pos):
        indices = self.dv_meta[name]["indices"]
        return pos if indices is None else indices.as_array()[pos]

    def set_x(self, x):
        """Set the variables to ``x`` (scaled) and run the model, unless already there."""
        if self._x is not None and np.array_equal(x, self._x):
            return
        self._x = None
        start = 0
        for name, pos in self.variables.items():
            scaler, adder, units = self._scaling(name)
            full = np.asarray(self.prob.get_val(name, units=units), dtype=float).copy()
            full.reshape(-1)[self._entries(name, pos)] = (
                x[start : start + pos.size] / scaler - adder
            )
            start += pos.size
            self.prob.set_val(name, full, units=units)
        self.prob.run_model()
        self._x = np.array(x)

    @staticmethod
    def _index(meta):
        return None if meta["indices"] is None else meta["indices"].as_array()

    def values(self, responses):
        """Return the scaled values (value + adder) * scaler of ``responses`` (name -> meta)."""
        parts = []
        for meta in responses.values():
            value = np.asarray(self.prob.get_val(meta["source"]), dtype=float).ravel()
            index = self._index(meta)
            value = value if index is None else value[index]
            scaler, adder = driver_scaling(meta)
            parts.append((value + adder) * scaler)
        return np.concatenate(parts) if parts else np.zeros(0)

    def jacobian(self, responses):
        """d(scaled responses)/d(scaled x) at the current point, one row per response entry."""
        # By response name (not source), so that OpenMDAO applies the declared scaling and
        # units of responses and design variables: the space of x and of values().
        totals = self.prob.compute_totals(
            of=list(responses),
            wrt=list(self.variables),
            driver_scaling=True,
            return_format="dict",
        )
        rows = []
        for name, meta in responses.items():
            index = self._index(meta)
            blocks = []
            for dv_name, pos in self.variables.items():
                block = np.atleast_2d(totals[name][dv_name])
                if block.shape[0] != meta["size"] and index is not None:
                    block = block[index]
                blocks.append(block[:, pos])
            rows.append(np.hstack(blocks))
        return np.vstack(rows)

    @staticmethod
    def scaled_bounds(responses, side):
        """Scaled ``side`` ('lower', 'upper' or 'equals') of each response entry (nan: none)."""
        parts = []
        for meta in responses.values():
            bound = meta[side]
            if bound is None or np.all(np.abs(np.asarray(bound, dtype=float)) >= 1e29):
                parts.append(np.full(meta["size"], np.nan))
                continue
            scaler, adder = driver_scaling(meta)
            parts.append((np.broadcast_to(bound, (meta["size"],)) + adder) * scaler)
        return np.concatenate(parts) if parts else np.zeros(0)


def _solve_block(prob, dv_meta, cons, variables, tol, max_iter):
    """
    Bounded least squares of one condition's trim residuals in its trim variables.

    Returns the scipy result, the scaled residuals at the solution and at the start, and the
    method kept (dogbox, else trust-region reflective from the start: module docstring).
    """
    block = _ScaledBlock(prob, dv_meta, variables)
    x0, lower, upper = block.x0, block.lower, block.upper
    targets = block.scaled_bounds(cons, "equals")

    def residual(x, strict=False):
        # A trial point at which the model fails (e.g. a motor stalls at a rotor speed near
        # zero) is answered with infinite residuals: scipy's dogbox and trust-region-reflective
        # methods then reject the step and shrink the trust region, as the optimizers back off
        # from a failed evaluation. The start and the returned solution must evaluate (strict).
        try:
            block.set_x(x)
        except om.AnalysisError:
            if strict:
                raise
            return np.full(targets.size, np.inf)
        return block.values(cons) - targets

    def jacobian(x):
        block.set_x(x)
        return block.jacobian(cons)

    def solve(method, budget, start=x0):
        return least_squares(
            residual,
            start,
            jac=jacobian,
            bounds=(lower, upper),
            method=method,
            ftol=tol,
            xtol=tol,
            gtol=tol,
            max_nfev=budget,
        )

    try:
        initial = residual(x0, strict=True)  # least_squares starts here: the run is reused
        sol, method = solve("dogbox", min(max_iter, DOGBOX_EVALUATIONS)), "dogbox"
        if x0.size and np.max(np.abs(sol.fun)) >= 1e-6:
            try:
                second = solve("trf", max_iter)
            except ValueError:  # scipy refuses the fallback (e.g. a non-finite residual)
                second = None  # keep dogbox's result, which the caller reports as not trimmed
            if second is not None:
                spent = (sol.njev or 0) + (second.njev or 0)
                if np.max(np.abs(second.fun)) < np.max(np.abs(sol.fun)):
                    sol, method = second, "trf"
                sol.njev = spent
        if x0.size and np.max(np.abs(sol.fun)) >= 1e-6:
            # Restarted from the better end point with a fresh trust region: a solve that ran
            # out of evaluations next to the solution (2.2e-6 measured, a transition point of
            # the mission example during its sizing) has shrunk its own.
            try:
                third = solve("dogbox", DOGBOX_EVALUATIONS, start=sol.x)
            except ValueError:
                third = None
            if third is not None and np.max(np.abs(third.fun)) < np.max(np.abs(sol.fun)):
                third.njev = (sol.njev or 0) + (third.njev or 0)
                sol, method = third, "dogbox"
        final = residual(sol.x, strict=True)
    except om.AnalysisError as err:
        raise om.AnalysisError(f"trim: the model failed during the trim solve: {err}") from err
    return sol, final, initial, method
