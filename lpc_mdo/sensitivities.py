"""Post-optimal sensitivities: d(W0*)/d(parameter) at an optimum, from multipliers and the adjoint.

At a local optimum x* of min f(x, p) s.t. g(x, p) = b (the active constraints, design-variable
bounds among them), the Karush-Kuhn-Tucker conditions give grad_x f = J^T nu with J the
Jacobian of the active constraints. Moving a parameter moves the optimum's objective by (first
order; Fiacco, *Introduction to Sensitivity and Stability Analysis in Nonlinear Programming*,
1983, Ch. 3; Martins & Ning, *Engineering Design Optimization*, 2021, Ch. 5):

    dW0*/db_i = nu_i                                     (a constraint's bound b_i)
    dW0*/dp   = df/dp - sum_i nu_i dg_i/dp               (a model input p, x held at x*)

without re-optimizing: the partial totals df/dp and dg/dp come from the adjoint pass that gives
grad_x f and J (one ``compute_totals`` over the objective and constraints with respect to the
design variables and the parameters), and nu from the KKT conditions at x*: a bounded linear
least-squares fit (free sign for equalities, nu >= 0 for an active lower bound, nu <= 0 for an
active upper bound) over the constraints and design-variable bounds within :data:`ACTIVE_TOL`
of their bounds, in the optimizer's scaled space. This does not depend on which optimizer ran
nor on the multipliers it reports; the relative KKT residual of the fit says how well x* is a
stationary point (a large residual means the sensitivities are not to be trusted).

The parameters (:data:`SENSITIVITY_PARAMETERS`) are those a designer asks about first: battery
energy density, the final-SoC limit, the hover noise limit, payload, the static-margin limit and
the cruise range. Where the problem closes the regressions' design gross mass (a design variable
with W0 - W_dg = 0, :data:`lpc_mdo.problems.CLOSED_MASS`), the sensitivities carry its response;
otherwise it is held at the vehicle file's value.
"""

import json
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
import openmdao.api as om
from scipy.optimize import lsq_linear

from lpc_mdo.drivers.scaling import driver_scaling
from lpc_mdo.post.tables import Table
from lpc_mdo.problems import build_problem, copy_design_variables
from lpc_mdo.sweep_parameters import SWEEP_PARAMETERS, reference_value
from lpc_mdo.vehicle import load_vehicle

SENSITIVITIES_FORMAT = "lpc_mdo.sensitivities/1"

#: A constraint or design variable is a candidate for the active set when its distance to a
#: bound is at most this, in the optimizer's scaled units (the sign bounds of the fit give a
#: candidate that is not active a multiplier of about zero). The full problem's SLSQP accepts
#: constraints within 3e-4 (its settings in lpc_mdo.study_plan); at an optimum stopped by its
#: iteration limit the final-SoC constraint was 2e-4 off its bound, and with 1e-4 the fit left it
#: out (KKT residual 0.48 against 0.020 with 1e-3, measured).
ACTIVE_TOL = 1e-3
#: Above this relative KKT residual the report shows no sensitivities, only how to polish first.
LOOSE_KKT_RESIDUAL = 0.025


@dataclass(frozen=True)
class SensitivityParameter:
    """
    One parameter whose post-optimal sensitivity is reported.

    Its description and units are those of the sweep parameter of the same name
    (:data:`lpc_mdo.sweep_parameters.SWEEP_PARAMETERS`), which re-optimizes to check it.

    Attributes
    ----------
    name : str
    kind : str
        ``"input"``: a model input (``variable``), ``"bound"``: the limit of the constraints
        whose names end with ``variable``.
    variable : str
    model_per_unit : float
        Model units of ``variable`` per reported unit (J/kg per Wh/kg: 3600).
    """

    name: str
    kind: str
    variable: str
    model_per_unit: float = 1.0

    @property
    def description(self):
        """Return the description of the sweep parameter of the same name."""
        return SWEEP_PARAMETERS[self.name][0]

    @property
    def units(self):
        """Return the units the sensitivity is reported in (kg per this unit)."""
        return SWEEP_PARAMETERS[self.name][1]


#: The distances the conditions with optimized speeds fly (lpc_mdo.groups.lpc.LPCGroup).
CRUISE_DISTANCE = "flight_time.distance"

SENSITIVITY_PARAMETERS = {
    p.name: p
    for p in (
        SensitivityParameter("energy_density", "input", "battery.specific_energy", 3600.0),
        SensitivityParameter("final_soc", "bound", "state_of_charge"),
        SensitivityParameter("max_noise", "bound", ".total_spl_a"),
        SensitivityParameter("payload", "input", "payload_mass"),
        SensitivityParameter("min_static_margin", "bound", ".static_margin"),
        # Range = cruise speed x cruise duration (the cruise condition's element of
        # mission.duration; :func:`_input_element`).
        SensitivityParameter("cruise_range", "input", "mission.duration"),
    )
}


@dataclass
class Sensitivity:
    """
    One row of the table: d(W0*)/d(parameter) in kg per unit and as an elasticity.

    Attributes
    ----------
    name, description, units : str
    value : float
        The parameter's value at the optimum, in ``units``.
    dw0_dp : float
        kg of optimum gross mass per unit of the parameter.
    elasticity : float
        % of gross mass per % of the parameter (dW0*/dp * p / W0*).
    active : bool or None
        For a bound: whether any of its constraints is active (None for inputs).
    """

    name: str
    description: str
    units: str
    value: float
    dw0_dp: float
    elasticity: float
    active: object = None


@dataclass
class SensitivityResult:
    """
    Sensitivities at one optimum, with what the fit of the multipliers says about it.

    Attributes
    ----------
    gross_mass : float
        W0* (kg).
    rows : list of Sensitivity
    kkt_residual : float
        ``norm(grad f - J^T nu) / norm(grad f)`` in the scaled space (0 at an exact KKT point).
    active : list of str
        Active constraints and design-variable bounds with their multipliers (kg per unit of
        the constraint's own units), largest first.
    """

    gross_mass: float
    rows: list
    kkt_residual: float
    active: list

    def row(self, name):
        """Return the row of parameter ``name``."""
        for r in self.rows:
            if r.name == name:
                return r
        raise KeyError(f"no sensitivity {name!r}; rows: {[r.name for r in self.rows]}")

    def to_json(self, path):
        """Write ``path`` (JSON, format :data:`SENSITIVITIES_FORMAT`); return its Path."""
        data = {"format": SENSITIVITIES_FORMAT, **asdict(self)}
        path = Path(path)
        path.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
        return path


def sensitivities_path(case_file):
    """Return the sensitivities sidecar of a case file: ``<stem>.sensitivities.json``."""
    return Path(case_file).with_suffix(".sensitivities.json")


def read_sensitivities(path):
    """
    Read a ``.sensitivities.json`` written by :meth:`SensitivityResult.to_json`.

    Returns
    -------
    SensitivityResult or None
        None when the file does not exist.

    Raises
    ------
    ValueError
        When the file is not in :data:`SENSITIVITIES_FORMAT`.
    """
    path = Path(path)
    if not path.is_file():
        return None
    data = json.loads(path.read_text(encoding="utf-8"))
    if data.pop("format", None) != SENSITIVITIES_FORMAT:
        raise ValueError(f"{str(path)!r} is not a {SENSITIVITIES_FORMAT} file.")
    data["rows"] = [Sensitivity(**r) for r in data["rows"]]
    return SensitivityResult(**data)


def _candidates(values, lower, upper, scaler, tol):
    """
    Active-set candidates of one array: (element, side) with side +1 (lower) or -1 (upper).

    ``values``, ``lower``, ``upper`` physical (None: no bound), ``scaler`` to the scaled units.
    """
    out = []
    scaler = np.broadcast_to(scaler, values.shape)
    lower = None if lower is None else np.broadcast_to(lower, values.shape)
    upper = None if upper is None else np.broadcast_to(upper, values.shape)
    for k, x in enumerate(values):
        if lower is not None and abs(lower[k]) < 1e29 and abs((x - lower[k]) * scaler[k]) <= tol:
            out.append((k, 1))
        elif upper is not None and abs(upper[k]) < 1e29 and abs((upper[k] - x) * scaler[k]) <= tol:
            out.append((k, -1))
    return out


@dataclass
class OptimumDerivatives:
    """
    What :func:`optimum_derivatives` returns.

    Attributes
    ----------
    objective : float
        f* (the objective's units).
    inputs : dict
        promoted input name -> array of df*/d(element), in the input's own units.
    bounds : dict
        constraint-name suffix -> df*/d(bound) (the sum over the constraints and elements whose
        name ends with it; 0 where none is active).
    active : dict
        constraint-name suffix -> whether any of those constraints is active.
    kkt_residual : float
        ``norm(grad f - J^T nu) / norm(grad f)`` in the scaled space (0 at an exact KKT point).
    multipliers : list of (str, int, float)
        (constraint or design variable, element, df*/d(its bound)) of the active set, largest
        first.
    residual_by_variable : dict
        design variable -> largest ``abs(grad f - J^T nu)`` of its elements over
        ``norm(grad f)`` (where the point is furthest from stationary).
    """

    objective: float
    inputs: dict
    bounds: dict
    active: dict
    kkt_residual: float
    multipliers: list
    residual_by_variable: dict


def optimum_derivatives(prob, inputs=(), bounds=(), active_tol=ACTIVE_TOL):
    """
    Return df*/d(input) and df*/d(bound) at the problem's current point, taken as its optimum.

    Works for any OpenMDAO problem with one objective and a driver (the model's design
    variables, constraints and driver scaling are used; which optimizer ran does not matter).

    Parameters
    ----------
    prob : om.Problem
        Set up, at a local optimum (after ``run_driver``, or ``run_model`` after loading an
        optimum's design variables).
    inputs : sequence of str
        Promoted names of model inputs (connected to the automatic IndepVarComp or an
        IndepVarComp output).
    bounds : sequence of str
        Constraint-name suffixes whose bound is the parameter (e.g. ``".static_margin"``).
    active_tol : float
        :data:`ACTIVE_TOL`.

    Returns
    -------
    OptimumDerivatives
    """
    model = prob.model
    ((obj_name, obj_meta),) = model.get_objectives().items()
    dvs = model.get_design_vars()
    cons = model.get_constraints()
    inputs = list(inputs)
    totals = prob.compute_totals(of=[obj_name, *cons], wrt=[*dvs, *inputs], driver_scaling=False)
    s_f, _ = driver_scaling(obj_meta)
    dv_values = prob.driver.get_design_var_values(driver_scaling=False)
    con_values = prob.driver.get_constraint_values(driver_scaling=False)

    # Scaled gradient of f, one entry per design-variable element.
    dv_scalers = {n: np.broadcast_to(driver_scaling(m)[0], (m["size"],)) for n, m in dvs.items()}
    grad = np.concatenate(
        [np.atleast_2d(totals[obj_name, n])[0] * s_f / dv_scalers[n] for n in dvs]
    )
    offsets = dict(zip(dvs, np.cumsum([0] + [m["size"] for m in dvs.values()])[:-1], strict=True))

    columns, lo, hi, labels = [], [], [], []  # candidate constraints, then bounds
    for cname, meta in cons.items():
        s_g = np.broadcast_to(driver_scaling(meta)[0], (meta["size"],))
        values = np.atleast_1d(con_values[cname])
        if meta.get("equals") is not None:
            cand = [(k, 0) for k in range(meta["size"])]
        else:
            cand = _candidates(values, meta.get("lower"), meta.get("upper"), s_g, active_tol)
        for k, side in cand:
            columns.append(
                np.concatenate(
                    [np.atleast_2d(totals[cname, n])[k] * s_g[k] / dv_scalers[n] for n in dvs]
                )
            )
            lo.append(0.0 if side > 0 else -np.inf)
            hi.append(0.0 if side < 0 else np.inf)
            labels.append((cname, k, s_g[k] / s_f, True))  # scaled nu -> physical: s_g / s_f
    for dname, meta in dvs.items():
        values = np.atleast_1d(dv_values[dname])
        scaler = dv_scalers[dname]
        for k, side in _candidates(
            values, meta.get("lower"), meta.get("upper"), scaler, active_tol
        ):
            col = np.zeros_like(grad)
            col[offsets[dname] + k] = 1.0
            columns.append(col)
            lo.append(0.0 if side > 0 else -np.inf)
            hi.append(0.0 if side < 0 else np.inf)
            labels.append((dname, k, dv_scalers[dname][k] / s_f, False))

    if columns:
        A = np.column_stack(columns)
        # Bounded-variable least squares (Stark & Parker): exact for this size; the default
        # trust-region method stopped at its iteration limit on a sweep point's 176 x 109 fit
        # and returned multipliers worse than none (residual 4.8, measured).
        nu_scaled = lsq_linear(A, grad, bounds=(np.array(lo), np.array(hi)), method="bvls").x
        stationarity = grad - A @ nu_scaled
    else:
        nu_scaled, stationarity = np.zeros(0), grad
    scale = max(np.linalg.norm(grad), 1e-300)
    residual = np.linalg.norm(stationarity) / scale
    by_variable = {
        n: float(np.max(np.abs(stationarity[offsets[n] : offsets[n] + m["size"]])) / scale)
        for n, m in dvs.items()
    }
    nu = np.array([v * lab[2] for v, lab in zip(nu_scaled, labels, strict=True)])

    d_inputs = {}
    for name in inputs:
        d = np.atleast_2d(totals[obj_name, name])[0].copy()
        for i, (cname, k, _, is_con) in enumerate(labels):
            if is_con:
                d -= nu[i] * np.atleast_2d(totals[cname, name])[k]
        d_inputs[name] = d
    d_bounds, active = {}, {}
    for suffix in bounds:
        sel = [i for i, lab in enumerate(labels) if lab[3] and lab[0].endswith(suffix)]
        d_bounds[suffix] = float(sum(nu[i] for i in sel))
        active[suffix] = any(abs(nu_scaled[i]) > 1e-8 for i in sel)
    order = np.argsort(-np.abs(nu_scaled))
    multipliers = [
        (labels[i][0], int(labels[i][1]), float(nu[i])) for i in order if abs(nu_scaled[i]) > 1e-8
    ]
    objective = float(np.atleast_1d(prob.get_val(obj_name))[0])
    return OptimumDerivatives(
        objective, d_inputs, d_bounds, active, float(residual), multipliers, by_variable
    )


def post_optimal_sensitivities(prob, vehicle, parameters=None, active_tol=ACTIVE_TOL):
    """
    Return d(W0*)/d(parameter) of the LPC problem at its current point, taken as its optimum.

    Parameters
    ----------
    prob : om.Problem
        A problem of :func:`lpc_mdo.problems.build_problem` with the gross mass as its
        objective (the full problem), at its optimum.
    vehicle : Vehicle
        The vehicle the problem was built with (the cruise speed and the limits).
    parameters : sequence of str or None
        Keys of :data:`SENSITIVITY_PARAMETERS` (None: all). A bound whose constraint the
        problem does not declare (the static margin of a run without it) has 0 kg per unit
        and ``active`` False: the optimum does not depend on it.
    active_tol : float
        :data:`ACTIVE_TOL`.

    Returns
    -------
    SensitivityResult

    Raises
    ------
    ValueError
        When the objective is not the gross mass, or a parameter name is unknown.
    """
    names = list(SENSITIVITY_PARAMETERS) if parameters is None else list(parameters)
    unknown = [n for n in names if n not in SENSITIVITY_PARAMETERS]
    if unknown:
        raise ValueError(
            f"sensitivities: parameters = {unknown}; allowed: {list(SENSITIVITY_PARAMETERS)}."
        )
    obj_name = next(iter(prob.model.get_objectives()))
    if obj_name.split(".")[-1] != "gross_mass":
        raise ValueError(
            f"sensitivities: the objective is {obj_name!r}; allowed: the gross mass "
            "(post-optimal sensitivities of W0* need W0 as the objective)."
        )
    params = [SENSITIVITY_PARAMETERS[n] for n in names]
    found = optimum_derivatives(
        prob,
        inputs=sorted({_input_variable(vehicle, p) for p in params if p.kind == "input"}),
        bounds=[p.variable for p in params if p.kind == "bound"],
        active_tol=active_tol,
    )
    w0 = float(prob.get_val(obj_name, units="kg")[0])
    cons = prob.model.get_constraints()
    rows = []
    for p in params:
        if p.kind == "bound":
            dw, active = found.bounds[p.variable], found.active[p.variable]
            value = _bound_value(cons, p, vehicle)
        else:
            index, per_model, value = _input_element(prob, vehicle, p)
            variable = _input_variable(vehicle, p)
            dw, active = float(found.inputs[variable][index] * per_model), None
        rows.append(Sensitivity(p.name, p.description, p.units, value, dw, dw * value / w0, active))
    active_list = [f"{name}[{k}]: {nu:.6g}" for name, k, nu in found.multipliers]
    return SensitivityResult(w0, rows, found.kkt_residual, active_list)


def _bound_value(cons, parameter, vehicle):
    """Return the limit a bound parameter sets: the declared constraint's, else the vehicle's."""
    for cname, meta in cons.items():
        if cname.endswith(parameter.variable):
            for key in ("lower", "upper", "equals"):
                bound = meta.get(key)
                if bound is not None and abs(np.atleast_1d(bound)[0]) < 1e29:
                    return float(np.atleast_1d(bound)[0])
    return reference_value(vehicle, parameter.name)


def _input_variable(vehicle, parameter):
    """Return the model input of an input parameter.

    At an optimized cruise speed the range is the distance it flies (:data:`CRUISE_DISTANCE`),
    not a duration.
    """
    cruise = vehicle.condition(vehicle.mission.cruise_condition)
    if parameter.name == "cruise_range" and cruise.optimizes_speed:
        return CRUISE_DISTANCE
    return parameter.variable


def _input_element(prob, vehicle, parameter):
    """(element index, model units per reported unit, value in reported units) of an input."""
    variable = _input_variable(vehicle, parameter)
    value = np.atleast_1d(prob.get_val(variable))
    if parameter.name == "cruise_range":
        # Range = cruise speed x cruise duration: d/d(range in km) = 1000 / V d/d(duration);
        # at an optimized speed the range is the distance itself: 1000 d/d(distance in m).
        powered = [c.name for c in prob.model._powered]
        index = powered.index(vehicle.mission.cruise_condition)
        if variable == CRUISE_DISTANCE:
            return index, 1000.0, float(value[index] / 1000.0)
        per_model = 1000.0 / vehicle.condition(vehicle.mission.cruise_condition).speed
        return index, per_model, float(value[index] / per_model)
    return 0, parameter.model_per_unit, float(value[0] / parameter.model_per_unit)


def polish_command(case_file):
    """Return the command that polishes the optimum recorded in ``case_file`` (a str)."""
    return f"lpc-mdo optimize --problem full --start-case {case_file} --tol 1e-6 --max-iter 150"


def sensitivity_table(result, case_file="<its case file>"):
    """
    Return the sensitivities as a :class:`lpc_mdo.post.tables.Table`.

    Columns: parameter, value, units, dW0*/dp (kg per unit), % W0* per % of the parameter.
    Above a relative KKT residual of :data:`LOOSE_KKT_RESIDUAL` the table has no rows: the
    numbers would not hold (docs theory/optimization 'Post-optimal sensitivities'), and its note
    gives the command that polishes the optimum of ``case_file`` first.
    """
    header = ["parameter", "value", "units", "dW0*/dp (kg per unit)", "% W0* per %"]
    if result.kkt_residual > LOOSE_KKT_RESIDUAL:
        return Table(
            header,
            [],
            title="Post-optimal sensitivities",
            notes=[
                f"Not shown: the optimum is loosely converged (relative KKT residual "
                f"{result.kkt_residual:.1e}, above {LOOSE_KKT_RESIDUAL}), where post-optimal "
                "sensitivities are unreliable (at 3.6e-02 they were 25 % off re-optimized "
                "neighbours, at 2.0e-02 within 5 %). Polish the optimum, then report its "
                f"case file: {polish_command(case_file)}"
            ],
        )
    rows = []
    for r in result.rows:
        note = "" if r.active is None else (" (active)" if r.active else " (inactive)")
        rows.append([f"{r.description}{note}", r.value, r.units, r.dw0_dp, r.elasticity])
    notes = [
        f"At W0* = {result.gross_mass:.2f} kg, from the KKT multipliers and the adjoint "
        f"(relative KKT residual {result.kkt_residual:.1e}); first order."
    ]
    return Table(header, rows, title="Post-optimal sensitivities", notes=notes)


def check_same_parameters(recorded, built, case_file):
    """
    Raise ValueError when a parameter the case was run with differs from the built problem's.

    ``recorded`` and ``built`` map names (model inputs, ``"<constraint> lower"`` etc.) to values
    (None or absent bounds compare equal to +-1e30). Sensitivities evaluated with another
    vehicle than the run's (a sweep point read with the reference vehicle) would be those of a
    point that is not the optimum of the problem built.
    """

    def plain(value):
        if value is None:
            return None
        value = np.atleast_1d(np.asarray(value, dtype=float))
        return None if np.all(np.abs(value) >= 1e29) else value

    for name, value in recorded.items():
        a, b = plain(value), plain(built.get(name))
        same = (a is None and b is None) or (
            a is not None and b is not None and a.shape == b.shape and np.allclose(a, b, rtol=1e-9)
        )
        if not same:
            raise ValueError(
                f"sensitivities: {str(case_file)!r} was run with {name} = {value}, the vehicle "
                f"gives {built.get(name)}; pass the vehicle file the run was made with "
                "(lpc-mdo report --vehicle)."
            )


def sensitivities_from_case(case_file, vehicle=None, parameters=None, active_tol=ACTIVE_TOL):
    """
    Return the sensitivities at a recorded full-problem optimum (its 'final' case).

    Builds the full problem for ``vehicle`` with the static-margin constraint when the case
    declared one, sets the recorded design variables, runs the model once and evaluates
    :func:`post_optimal_sensitivities` (about 10 s on 2 cores).

    Parameters
    ----------
    case_file : str or os.PathLike
        Case file of a full-problem run (``lpc-mdo optimize --problem full``, a sequence's
        ``full.sql``, a sweep point).
    vehicle : Vehicle, path or None
        The vehicle the run was made with (None: the reference vehicle).
    parameters : sequence of str or None
    active_tol : float

    Returns
    -------
    SensitivityResult

    Raises
    ------
    ValueError
        When the case's objective is not the gross mass, or it was run with other parameter
        values or limits than the vehicle's (:func:`check_same_parameters`).
    """
    if vehicle is None or isinstance(vehicle, (str, Path)):
        vehicle = load_vehicle(vehicle)
    reader = om.CaseReader(str(case_file))
    case = reader.get_case("final")
    objectives = list(case.get_objectives())
    if [n.split(".")[-1] for n in objectives] != ["gross_mass"]:
        raise ValueError(
            f"sensitivities: {str(case_file)!r} has objective(s) {objectives}; allowed: the "
            "gross mass (a full-problem run)."
        )
    static_margin = any(n.endswith(".static_margin") for n in case.get_constraints())
    prob = build_problem("full", vehicle=vehicle, static_margin=static_margin, optimizer="SLSQP")
    copy_design_variables(case, prob, vehicle)
    prob.final_setup()
    recorded, built = {}, {}
    for p in SENSITIVITY_PARAMETERS.values():
        if p.kind == "input":
            try:
                recorded[p.variable] = case.get_val(p.variable)
            except KeyError:
                continue
            built[p.variable] = prob.get_val(p.variable)
    bounds = reader.problem_metadata["variables"]
    for name, meta in prob.model.get_constraints().items():
        if name in bounds:
            for key in ("lower", "upper", "equals"):
                recorded[f"{name} {key}"] = bounds[name].get(key)
                built[f"{name} {key}"] = meta.get(key)
    check_same_parameters(recorded, built, case_file)
    prob.run_model()
    try:
        return post_optimal_sensitivities(prob, vehicle, parameters, active_tol)
    finally:
        prob.cleanup()
