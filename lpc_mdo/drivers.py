"""Optimizer layer: ``make_driver`` and an IPOPT driver that needs no pyoptsparse.

pyoptsparse (the paper's route to IPOPT and SNOPT) is not on PyPI, so a plain ``pip install``
cannot reach it.  :class:`IpoptDriver` is a small OpenMDAO ``Driver`` on top of the ``cyipopt``
module (``pip install lpc-mdo[ipopt]`` brings the ``cyipopt-wheels`` build, conda users take
conda-forge ``cyipopt``).  :func:`make_driver` picks pyoptsparse when it is importable and has the
requested optimizer, and falls back to :class:`IpoptDriver` or :class:`SlsqpDriver` (OpenMDAO's
``ScipyOptimizeDriver`` with SLSQP, backing off from failed model evaluations).

The driver follows OpenMDAO's own ``ScipyOptimizeDriver`` (openmdao 3.45): design variables are
written through ``self._vectors['design_var']`` in driver scaling, every model evaluation is
recorded through ``RecordingDebugging``, and total derivatives come from ``_compute_totals``.
"""

import importlib
import sys

import numpy as np
import openmdao.api as om
from openmdao.core.driver import Driver, RecordingDebugging
from openmdao.utils.om_warnings import DriverWarning, issue_warning

from lpc_mdo.checks import check_choice

__all__ = ["IpoptDriver", "IpoptMultipliers", "SlsqpDriver", "make_driver",
           "pyoptsparse_optimizers"]

# IPOPT return codes 0 (Solve_Succeeded) and 1 (Solved_To_Acceptable_Level) count as success,
# as in pyOptSparseDriver.
_IPOPT_SUCCESS = (0, 1)

# Settings OpenMDAO's pyOptSparseDriver uses for IPOPT; the model supplies exact first
# derivatives only, so the Hessian is approximated by L-BFGS.
DEFAULT_IPOPT_SETTINGS = {
    "hessian_approximation": "limited-memory",
    "linear_solver": "mumps",
}

# Settings that make IPOPT start from a previous primal-dual point instead of pushing the
# iterate into the interior (measured on Sellar: 21 -> 11 model evaluations).
WARM_START_SETTINGS = {
    "warm_start_init_point": "yes",
    "mu_init": 1e-6,
    "warm_start_bound_push": 1e-9,
    "warm_start_bound_frac": 1e-9,
    "warm_start_slack_bound_push": 1e-9,
    "warm_start_slack_bound_frac": 1e-9,
    "warm_start_mult_bound_push": 1e-9,
}


class _FlagsFailedCases:
    """
    Driver mixin: a model evaluation that raised ``om.AnalysisError`` is recorded as a driver
    case with ``success = 0`` and the error as ``msg`` (OpenMDAO records every evaluation with
    success = 1), so post-processing can leave its stale outputs out (``case.success``).
    """

    _failure = None  # the AnalysisError of the evaluation being recorded, when caught

    def _get_recorder_metadata(self, case_name):
        meta = super()._get_recorder_metadata(case_name)
        error = self._failure if self._failure is not None else sys.exc_info()[1]
        if isinstance(error, om.AnalysisError):
            meta["success"], meta["msg"] = 0, str(error)
        return meta


class IpoptMultipliers(dict):
    """
    Final IPOPT multipliers of a run, keyed by OpenMDAO name, for a later warm start.

    Keys are ``'constraints'`` (constraint name -> multiplier array), ``'lower'`` and
    ``'upper'`` (design variable name -> bound multiplier array).  The values are in the
    driver-scaled space of the run that produced them: they help a warm start only when the
    next problem uses the same scaling (ref/ref0/scaler/adder) for the same names.
    """


class IpoptDriver(_FlagsFailedCases, Driver):
    """
    OpenMDAO driver for IPOPT through the ``cyipopt`` module.

    Supports design-variable bounds and scaling, equality, inequality and two-sided
    constraints, linear constraints (Jacobian computed once, values evaluated from it without
    running the model), a sparse constraint Jacobian (from the total coloring when
    ``declare_coloring`` was called, otherwise from the relevance of each constraint to each
    design variable), ``om.AnalysisError`` handled by IPOPT's step back-off, recording of every
    model evaluation, and warm starts from the multipliers of a previous run.

    Options
    -------
    max_iter : int
        Maximum number of IPOPT iterations (IPOPT option ``max_iter``).
    tol : float
        IPOPT convergence tolerance (IPOPT option ``tol``), in the driver-scaled space.
    print_level : int
        IPOPT console verbosity, 0 (silent) to 12.
    output_file : str or None
        IPOPT log file; a relative path is placed in the problem's outputs folder.
    warm_start : IpoptMultipliers or None
        Multipliers of a previous run (``driver.multipliers``); when given, IPOPT starts from
        the current design point with these multipliers and the warm-start settings.

    Attributes
    ----------
    opt_settings : dict
        IPOPT options passed through verbatim; they override the defaults and the options above.
    multipliers : IpoptMultipliers or None
        Multipliers of the last run, to pass to another driver's ``warm_start`` option.
    ipopt_info : dict or None
        The raw ``info`` dict cyipopt returned for the last run.
    analysis_errors : list of str
        Messages of the ``om.AnalysisError`` raised during the last run (each made IPOPT cut
        its step back); the first place to look when IPOPT reports evaluation errors.
    """

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.supports._read_only = False
        self.supports["optimization"] = True
        self.supports["inequality_constraints"] = True
        self.supports["equality_constraints"] = True
        self.supports["two_sided_constraints"] = True
        self.supports["linear_constraints"] = True
        self.supports["simultaneous_derivatives"] = True
        self.supports["total_jac_sparsity"] = True
        self.supports["gradients"] = True
        self.supports["multiple_objectives"] = False
        self.supports["active_set"] = False
        self.supports["integer_design_vars"] = False
        self.supports["distributed_design_vars"] = False
        self.supports._read_only = True

        self.opt_settings = {}
        self.analysis_errors = []
        self.multipliers = None
        self.ipopt_info = None
        self.fail = False
        self.iter_count = 0
        self._ipopt_iterations = 0
        self._status_msg = "NOT_RUN"
        self._user_stop = False
        self._reset_caches()

    def _declare_options(self):
        self.options.declare("max_iter", default=200, types=int, lower=0,
                             desc="Maximum number of IPOPT iterations.")
        self.options.declare("tol", default=1e-6, types=float, lower=0.0,
                             desc="IPOPT convergence tolerance (driver-scaled space).")
        self.options.declare("print_level", default=5, types=int, lower=0, upper=12,
                             desc="IPOPT console output level, 0 (silent) to 12.")
        self.options.declare("output_file", default=None, types=str, allow_none=True,
                             desc="IPOPT log file; relative paths go into the outputs folder.")
        self.options.declare("warm_start", default=None, types=IpoptMultipliers,
                             allow_none=True,
                             desc="Multipliers of a previous run (driver.multipliers) to "
                                  "warm-start IPOPT from the current design point.")

    def _get_name(self):
        return "IpoptDriver"

    def _setup_driver(self, problem):
        super()._setup_driver(problem)
        if len(self._objs) > 1:
            raise RuntimeError(f"{self.msginfo}: IPOPT takes one objective, "
                               f"got {len(self._objs)}: {list(self._objs)}.")

    def _reset_caches(self):
        self._x_model = None       # x at which the model was last run successfully
        self._x_failed = None      # x at which the model last raised AnalysisError
        self._x_jac = None         # x at which the nonlinear Jacobian was last computed
        self._jac_cache = None
        self._funcs = None         # (objective, nonlinear constraint vector) at _x_model

    # ------------------------------------------------------------------ problem layout

    def _layout(self):
        """Size the design vector and constraint vector; gather scaled bounds."""
        dv_bounds = self._autoscaler.get_bounds_scaling("design_var")
        con_bounds = self._autoscaler.get_bounds_scaling("constraint")

        self._dv_slices = {}
        lower, upper = [], []
        n = 0
        for name, meta in self._designvars.items():
            size = meta["size"]
            self._dv_slices[name] = slice(n, n + size)
            n += size
            lo, up = dv_bounds[name].lower, dv_bounds[name].upper
            lower.append(np.full(size, -np.inf) if lo is None else np.broadcast_to(lo, size))
            upper.append(np.full(size, np.inf) if up is None else np.broadcast_to(up, size))
        if n == 0:
            raise RuntimeError(f"{self.msginfo}: the problem has no design variables.")
        self._n = int(n)
        # A negative scaler (ref < ref0) flips the scaled bounds; IPOPT needs lower <= upper.
        lower, upper = np.concatenate(lower).astype(float), np.concatenate(upper).astype(float)
        self._x_lower, self._x_upper = np.minimum(lower, upper), np.maximum(lower, upper)

        self._nl_cons = [c for c, m in self._cons.items() if not m["linear"]]
        self._lin_cons = [c for c, m in self._cons.items() if m["linear"]]
        self._con_slices = {}
        g_lower, g_upper = [], []
        m = 0
        for name in self._nl_cons + self._lin_cons:
            meta = self._cons[name]
            size = meta["size"]
            self._con_slices[name] = slice(m, m + size)
            m += size
            b = con_bounds[name]
            if b.equals is not None:
                lo = up = np.broadcast_to(b.equals, size)
            else:
                lo = np.full(size, -np.inf) if b.lower is None else np.broadcast_to(b.lower, size)
                up = np.full(size, np.inf) if b.upper is None else np.broadcast_to(b.upper, size)
            g_lower.append(lo)
            g_upper.append(up)
        self._m = int(m)
        self._m_nl = int(sum(self._cons[c]["size"] for c in self._nl_cons))
        g_lower = np.concatenate(g_lower).astype(float) if m else np.zeros(0)
        g_upper = np.concatenate(g_upper).astype(float) if m else np.zeros(0)
        self._g_lower, self._g_upper = np.minimum(g_lower, g_upper), np.maximum(g_lower, g_upper)

    def _jacobian_structure(self):
        """(rows, cols) of the nonlinear-constraint Jacobian entries IPOPT will be given."""
        dv_names = list(self._designvars)
        blocks = None
        coloring = self._coloring_info.coloring
        if coloring is not None:
            blocks = coloring.get_subjac_sparsity()
            if blocks is not None and not all(c in blocks for c in self._nl_cons):
                blocks = None  # coloring names do not match ours: fall back to relevance

        rows, cols = [], []
        relevance = self._problem().model._relevance
        for con in self._nl_cons:
            r0 = self._con_slices[con].start
            meta = self._cons[con]
            if blocks is not None:
                for dv, (nzr, nzc, _shape) in blocks[con].items():
                    if dv in self._dv_slices:
                        rows.append(r0 + np.asarray(nzr))
                        cols.append(self._dv_slices[dv].start + np.asarray(nzc))
                continue
            with relevance.seeds_active(rev_seeds=(meta["source"],)):
                for dv in dv_names:
                    if relevance.is_relevant(self._designvars[dv]["source"]):
                        sl = self._dv_slices[dv]
                        rr, cc = np.meshgrid(np.arange(meta["size"]),
                                             np.arange(sl.start, sl.stop), indexing="ij")
                        rows.append(r0 + rr.ravel())
                        cols.append(cc.ravel())
        if not rows:
            return np.zeros(0, dtype=int), np.zeros(0, dtype=int)
        return np.concatenate(rows).astype(int), np.concatenate(cols).astype(int)

    # ------------------------------------------------------------------ run

    def run(self):
        """
        Optimize the problem with IPOPT.

        Returns
        -------
        bool
            Failure flag: True if IPOPT did not report success.
        """
        try:
            import cyipopt
        except ImportError as err:
            raise ImportError(
                "IpoptDriver needs the 'cyipopt' module: pip install 'lpc-mdo[ipopt]' "
                "(cyipopt-wheels, CPython 3.11 on Linux x86-64) or conda install -c conda-forge "
                "cyipopt. Without IPOPT use make_driver('SLSQP')."
            ) from err

        self.result.reset()
        problem = self._problem()
        model = problem.model
        self.iter_count = 0
        self._ipopt_iterations = 0
        self._user_stop = False
        self._exc_info = None
        self.analysis_errors = []
        self._total_jac = None
        self._total_jac_linear = None
        self._reset_caches()

        self._check_for_missing_objective()
        self._check_for_invalid_desvar_values()

        # Initial run: the design point IPOPT starts from, recorded like every evaluation.
        with RecordingDebugging(self._get_name(), self.iter_count, self):
            with model._relevance.nonlinear_active("iter"):
                self._run_solve_nonlinear()
            self.iter_count += 1

        self._layout()
        dv_vals = self.get_design_var_values()
        x0 = np.concatenate([np.atleast_1d(dv_vals[n]) for n in self._designvars]).astype(float)
        self._x_model = x0.copy()
        self._store_funcs()

        problem.get_total_coloring(self._coloring_info, run_model=False)

        # Linear constraints: Jacobian once, values from it for every x.
        self._lin_jac = np.zeros((0, self._n))
        self._lin_g0 = np.zeros(0)
        if self._lin_cons:
            self._lin_jac = np.atleast_2d(self._compute_totals(
                of=self._lin_cons, wrt=list(self._designvars), return_format="array"))
            lin_vals = self.get_constraint_values(lintype="linear")
            self._lin_g0 = np.concatenate([np.atleast_1d(lin_vals[c]) for c in self._lin_cons])
        self._x0_lin = x0.copy()

        nl_rows, nl_cols = self._jacobian_structure()
        lin_r, lin_c = np.nonzero(self._lin_jac)
        self._nl_rows, self._nl_cols = nl_rows, nl_cols
        self._jac_rows = np.concatenate([nl_rows, lin_r + self._m_nl]).astype(int)
        self._jac_cols = np.concatenate([nl_cols, lin_c]).astype(int)
        self._lin_vals = self._lin_jac[lin_r, lin_c]

        nlp = cyipopt.Problem(n=self._n, m=self._m, problem_obj=_IpoptCallbacks(self, cyipopt),
                              lb=self._x_lower, ub=self._x_upper,
                              cl=self._g_lower, cu=self._g_upper)
        settings = dict(DEFAULT_IPOPT_SETTINGS)
        settings["max_iter"] = self.options["max_iter"]
        settings["tol"] = self.options["tol"]
        settings["print_level"] = self.options["print_level"]
        if self.options["output_file"]:
            settings["output_file"] = str(problem.get_outputs_dir(mkdir=True)
                                          / self.options["output_file"])
        warm = self.options["warm_start"]
        if warm is not None:
            settings.update(WARM_START_SETTINGS)
        settings.update(self.opt_settings)
        for key, value in settings.items():
            nlp.add_option(key, value)

        kwargs = {}
        if warm is not None:
            lagrange, zl, zu = self._unpack_multipliers(warm)
            kwargs = {"lagrange": lagrange, "zl": zl, "zu": zu}

        x_opt, info = nlp.solve(x0, **kwargs)

        if self._exc_info is not None:
            self._reraise()

        # IPOPT relaxes bounds by ~1e-8; leave the model exactly inside them, at the optimum
        # IPOPT returned (the last evaluation may have been elsewhere).
        x_opt = np.clip(x_opt, self._x_lower, self._x_upper)
        if self._x_model is None or not np.array_equal(x_opt, self._x_model):
            self._evaluate(x_opt)

        self.ipopt_info = info
        self.multipliers = self._pack_multipliers(info)
        status = info["status"]
        self._status_msg = info["status_msg"]
        if isinstance(self._status_msg, bytes):
            self._status_msg = self._status_msg.decode()
        self.fail = status not in _IPOPT_SUCCESS
        return self.fail

    def _update_result(self, result):
        result.iter_count = self._ipopt_iterations
        result.exit_status = self._status_msg

    # ------------------------------------------------------------------ evaluations

    def _set_x(self, x):
        self._vectors["design_var"].set_data(x, driver_scaling=True)
        self._set_design_vars(driver_scaling=True)

    def _store_funcs(self):
        obj = next(iter(self.get_objective_values().values()))
        cons = self.get_constraint_values(lintype="nonlinear")
        g = (np.concatenate([np.atleast_1d(cons[c]) for c in self._nl_cons])
             if self._nl_cons else np.zeros(0))
        self._funcs = (float(np.asarray(obj).ravel()[0]), g)

    def _evaluate(self, x):
        """Run the model at x unless it was just run there; raise on AnalysisError."""
        if self._x_model is not None and np.array_equal(x, self._x_model):
            return True
        if self._x_failed is not None and np.array_equal(x, self._x_failed):
            return False
        model = self._problem().model
        self._set_x(x)
        ok = True
        with RecordingDebugging(self._get_name(), self.iter_count, self):
            self.iter_count += 1
            try:
                with model._relevance.nonlinear_active("iter"):
                    self._run_solve_nonlinear()
            except om.AnalysisError as err:
                model._clear_iprint()
                self.analysis_errors.append(str(err))
                self._failure = err  # recorded as a failed case on leaving the block
                ok = False
            except KeyboardInterrupt:
                model._clear_iprint()
                self._user_stop = True
                ok = False
        self._failure = None
        if ok:
            self._x_model = np.array(x, copy=True)
            self._x_failed = None
            self._store_funcs()
        else:
            self._x_model = None
            self._x_failed = np.array(x, copy=True)
        return ok

    def _objective(self, x):
        """Objective at x, or None when the model failed there."""
        return self._funcs[0] if self._evaluate(x) else None

    def _constraints(self, x):
        """Constraint vector at x (linear ones from their Jacobian), or None on failure."""
        if not self._evaluate(x):
            return None
        g_lin = self._lin_g0 + self._lin_jac @ (x - self._x0_lin)
        return np.concatenate([self._funcs[1], g_lin])

    def _gradients(self, x):
        """Objective gradient and nonlinear constraint Jacobian (dense), cached per x."""
        if self._x_jac is not None and np.array_equal(x, self._x_jac):
            return self._jac_cache
        if not self._evaluate(x):
            return None
        of = list(self._objs) + self._nl_cons
        jac = np.atleast_2d(self._compute_totals(of=of, wrt=list(self._designvars),
                                                 return_format="array"))
        self._x_jac = np.array(x, copy=True)
        self._jac_cache = jac
        return jac

    # ------------------------------------------------------------------ multipliers

    def _pack_multipliers(self, info):
        mult_g = np.asarray(info["mult_g"])
        zl = np.asarray(info["mult_x_L"])
        zu = np.asarray(info["mult_x_U"])
        return IpoptMultipliers(
            constraints={c: mult_g[s].copy() for c, s in self._con_slices.items()},
            lower={d: zl[s].copy() for d, s in self._dv_slices.items()},
            upper={d: zu[s].copy() for d, s in self._dv_slices.items()},
        )

    def _unpack_multipliers(self, warm):
        """Place named multipliers into IPOPT's ordering; names not in this problem are zero."""
        lagrange = np.zeros(self._m)
        zl = np.zeros(self._n)
        zu = np.zeros(self._n)
        for target, slices, key in ((lagrange, self._con_slices, "constraints"),
                                    (zl, self._dv_slices, "lower"),
                                    (zu, self._dv_slices, "upper")):
            for name, value in warm.get(key, {}).items():
                if name not in slices:
                    continue
                sl = slices[name]
                value = np.atleast_1d(value)
                if value.size != sl.stop - sl.start:
                    raise ValueError(
                        f"{self.msginfo}: warm_start multipliers for '{name}' have size "
                        f"{value.size}, but the problem has size {sl.stop - sl.start}.")
                target[sl] = value
        return lagrange, zl, zu


class _IpoptCallbacks:
    """The callback object cyipopt calls; keeps the driver free of cyipopt's method names."""

    def __init__(self, driver, cyipopt):
        self._driver = driver
        self._error = cyipopt.CyIpoptEvaluationError

    def _guard(self, func, x):
        drv = self._driver
        if drv._exc_info is not None:
            raise self._error()
        try:
            out = func(x)
        except Exception:
            drv._exc_info = sys.exc_info()
            raise self._error() from None
        if out is None:  # AnalysisError or Ctrl-C at x: let IPOPT cut its step
            raise self._error()
        return out

    def objective(self, x):
        return self._guard(self._driver._objective, x)

    def constraints(self, x):
        return self._guard(self._driver._constraints, x)

    def gradient(self, x):
        drv = self._driver

        def grad(x):
            jac = drv._gradients(x)
            return None if jac is None else jac[0].copy()
        return self._guard(grad, x)

    def jacobianstructure(self):
        drv = self._driver
        return drv._jac_rows, drv._jac_cols

    def jacobian(self, x):
        drv = self._driver

        def jacobian(x):
            jac = drv._gradients(x)
            if jac is None:
                return None
            nl = jac[1:][drv._nl_rows, drv._nl_cols]
            return np.concatenate([nl, drv._lin_vals])
        return self._guard(jacobian, x)

    def intermediate(self, alg_mod, iter_count, obj_value, inf_pr, inf_du, mu, d_norm,
                     regularization_size, alpha_du, alpha_pr, ls_trials):
        drv = self._driver
        drv._ipopt_iterations = int(iter_count)
        # Returning False stops IPOPT cleanly (user interrupt or a Python error in a callback).
        return not (drv._user_stop or drv._exc_info is not None)


# ---------------------------------------------------------------------- driver factory

def pyoptsparse_optimizers():
    """
    Optimizers that the importable pyoptsparse provides, or an empty set without pyoptsparse.

    Returns
    -------
    set of str
        Optimizer names such as ``'IPOPT'`` or ``'SNOPT'`` that import successfully.
    """
    try:
        pyoptsparse = importlib.import_module("pyoptsparse")
    except ImportError:
        return set()
    found = set()
    for name in ("IPOPT", "SNOPT", "SLSQP", "ParOpt", "CONMIN", "PSQP", "NLPQLP"):
        try:
            getattr(pyoptsparse, name)()
        except Exception:  # pyoptsparse raises its own Error when a library is missing
            continue
        found.add(name)
    return found


class SlsqpDriver(_FlagsFailedCases, om.ScipyOptimizeDriver):
    """
    OpenMDAO's ``ScipyOptimizeDriver`` with SLSQP that backs off from points where the model
    fails.

    SciPy's SLSQP has no notion of a failed evaluation, and ``ScipyOptimizeDriver`` re-raises
    the first exception of the model, ending the run: an ``om.AnalysisError`` at one line-search
    point (a trial step that stalls a motor or leaves a rotor without through-flow) would end a
    full-problem optimization that a shorter step keeps feasible. Here an ``om.AnalysisError``
    at a trial point returns the last successful point's objective plus ``failure_penalty``
    (in the driver-scaled space) and that point's constraint values, so the merit function
    rises and SLSQP's line search cuts the step (by at least 10x each time); an error at the
    first evaluation, or any other exception, is re-raised as before. The messages are kept in
    ``analysis_errors``, as :class:`IpoptDriver` does.

    Options
    -------
    failure_penalty : float
        Added to the last successful objective at a failed point (driver-scaled; >= 0).
    """

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.options["optimizer"] = "SLSQP"
        self.analysis_errors = []
        self._last_good = None     # (scaled objective, constraint values) of the last good point
        self._last_failed = False  # whether the model holds a failed trial point

    def _declare_options(self):
        super()._declare_options()
        self.options.declare("failure_penalty", default=1.0e6, lower=0.0,
                             desc="added to the last successful scaled objective at a point "
                                  "where the model raised om.AnalysisError")

    def run(self):
        self.analysis_errors = []
        self._last_good = None
        self._last_failed = False
        fail = super().run()
        if self._last_failed:  # the model holds a failed trial point: evaluate the result
            super()._objfunc(self._scipy_optimize_result.x)
            if self._exc_info is not None:
                self._reraise()
        return fail

    def _objfunc(self, x_new):
        value = super()._objfunc(x_new)
        self._last_failed = False
        if self._exc_info is None:
            self._last_good = (value, self._con_cache)
            return value
        error = self._exc_info[1]
        if not isinstance(error, om.AnalysisError) or self._last_good is None:
            return value  # re-raised by the constraint callback, as in ScipyOptimizeDriver
        self._exc_info = None
        self._last_failed = True
        self.analysis_errors.append(str(error))
        issue_warning(f"model evaluation {self.iter_count} failed ({error}); SLSQP's line "
                      "search is given the last good point's values plus failure_penalty",
                      prefix=self.msginfo, category=DriverWarning)
        value, self._con_cache = self._last_good
        return value + self.options["failure_penalty"]


_KNOWN = ("IPOPT", "SNOPT", "SLSQP")


def make_driver(optimizer="IPOPT", **settings):
    """
    Return an OpenMDAO driver for ``optimizer``, preferring pyoptsparse when it has it.

    Parameters
    ----------
    optimizer : str
        ``'IPOPT'``, ``'SNOPT'`` or ``'SLSQP'`` (case-insensitive).
    **settings
        Driver options (e.g. ``max_iter``/``maxiter``, ``tol``, ``print_level``) are set as
        options where the chosen driver has an option of that name; everything else goes into
        ``driver.opt_settings`` (IPOPT/SNOPT native options).

    Returns
    -------
    Driver
        ``om.pyOptSparseDriver`` when pyoptsparse is importable and provides the optimizer;
        otherwise :class:`IpoptDriver` for IPOPT and :class:`SlsqpDriver` (SciPy's SLSQP) for
        SLSQP.

    Raises
    ------
    ValueError
        For an unknown optimizer name.
    RuntimeError
        For SNOPT without a pyoptsparse that has it, saying what to install.
    """
    if not isinstance(optimizer, str) or optimizer.upper() not in _KNOWN:
        check_choice("optimizer", optimizer, _KNOWN)  # raises, naming the allowed names
    name = optimizer.upper()
    available = pyoptsparse_optimizers()

    if name in available:
        driver = om.pyOptSparseDriver(optimizer=name)
    elif name == "IPOPT":
        driver = IpoptDriver()
    elif name == "SLSQP":
        driver = SlsqpDriver()
    else:
        raise RuntimeError(
            "SNOPT is reached only through pyoptsparse, which is not importable here"
            + (" (it is, but was built without SNOPT)" if available else "")
            + ". SNOPT is licensed software: build pyoptsparse with your SNOPT source "
            "(OpenMDAO's build_pyoptsparse, or conda-forge pyoptsparse plus SNOPT), or use "
            "make_driver('IPOPT'), which needs only pip install 'lpc-mdo[ipopt]'.")

    aliases = {"max_iter": "maxiter", "maxiter": "max_iter", "print_level": "disp"}
    for key, value in settings.items():
        if key in driver.options:
            driver.options[key] = value
        elif isinstance(driver, om.ScipyOptimizeDriver) and aliases.get(key) in driver.options:
            target = aliases[key]
            driver.options[target] = bool(value) if target == "disp" else value
        elif isinstance(driver, IpoptDriver) and aliases.get(key) in driver.options:
            driver.options[aliases[key]] = value
        else:
            driver.opt_settings[key] = value
    return driver
