"""IPOPT driver that needs no pyoptsparse: :class:`IpoptDriver` on top of the ``cyipopt`` module.

pyoptsparse (the paper's route to IPOPT and SNOPT) is not on PyPI, so a plain ``pip install``
cannot reach it.  :class:`IpoptDriver` is a small OpenMDAO ``Driver`` on top of the ``cyipopt``
module (``pip install lpc-mdo[ipopt]`` brings the ``cyipopt-wheels`` build, conda users take
conda-forge ``cyipopt``).

The driver follows OpenMDAO's own ``ScipyOptimizeDriver`` (openmdao 3.45): design variables are
written in driver scaling, every model evaluation is recorded as a driver case, and total
derivatives come from the driver's total-derivative computation.  Every OpenMDAO internal it
needs for that is reached through :mod:`lpc_mdo.drivers.openmdao_internals`.
"""

import sys

import numpy as np
import openmdao.api as om

from lpc_mdo.drivers import openmdao_internals as omi

__all__ = ["DEFAULT_IPOPT_SETTINGS", "WARM_START_SETTINGS", "IpoptDriver", "IpoptMultipliers"]

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


class IpoptMultipliers(dict):
    """
    Final IPOPT multipliers of a run, keyed by OpenMDAO name, for a later warm start.

    Keys are ``'constraints'`` (constraint name -> multiplier array), ``'lower'`` and
    ``'upper'`` (design variable name -> bound multiplier array).  The values are in the
    driver-scaled space of the run that produced them: they help a warm start only when the
    next problem uses the same scaling (ref/ref0/scaler/adder) for the same names.
    """


class IpoptDriver(omi.DriverHooks):
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
        IPOPT console verbosity, 0 (silent, also without IPOPT's banner) to 12.
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

    driver_name = "IpoptDriver"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        omi.set_supports(
            self,
            optimization=True,
            inequality_constraints=True,
            equality_constraints=True,
            two_sided_constraints=True,
            linear_constraints=True,
            simultaneous_derivatives=True,
            total_jac_sparsity=True,
            gradients=True,
            multiple_objectives=False,
            active_set=False,
            integer_design_vars=False,
            distributed_design_vars=False,
        )

        self.opt_settings = {}
        self.analysis_errors = []
        self.multipliers = None
        self.ipopt_info = None
        self.fail = False
        self.iter_count = 0
        self._ipopt_iterations = 0
        self._status_msg = "NOT_RUN"
        self._user_stop = False
        self._callback_error = None  # sys.exc_info() of a Python error inside a callback
        self._reset_caches()

    def declare_options(self):
        """Declare the options listed in the class docstring."""
        self.options.declare(
            "max_iter", default=200, types=int, lower=0, desc="Maximum number of IPOPT iterations."
        )
        self.options.declare(
            "tol",
            default=1e-6,
            types=float,
            lower=0.0,
            desc="IPOPT convergence tolerance (driver-scaled space).",
        )
        self.options.declare(
            "print_level",
            default=5,
            types=int,
            lower=0,
            upper=12,
            desc="IPOPT console output level, 0 (silent) to 12.",
        )
        self.options.declare(
            "output_file",
            default=None,
            types=str,
            allow_none=True,
            desc="IPOPT log file; relative paths go into the outputs folder.",
        )
        self.options.declare(
            "warm_start",
            default=None,
            types=IpoptMultipliers,
            allow_none=True,
            desc="Multipliers of a previous run (driver.multipliers) to "
            "warm-start IPOPT from the current design point.",
        )

    def check_setup(self):
        """Reject a problem with more than one objective before any model run."""
        objectives = omi.objective_meta(self)
        if len(objectives) > 1:
            raise RuntimeError(
                f"{self.msginfo}: IPOPT takes one objective, "
                f"got {len(objectives)}: {list(objectives)}."
            )

    def _reset_caches(self):
        self._x_model = None  # x at which the model was last run successfully
        self._x_failed = None  # x at which the model last raised AnalysisError
        self._x_jac = None  # x at which the nonlinear Jacobian was last computed
        self._jac_cache = None
        self._funcs = None  # (objective, nonlinear constraint vector) at _x_model

    # ------------------------------------------------------------------ problem layout

    def _layout(self):
        """Size the design vector and constraint vector; gather scaled bounds."""
        dv_bounds = omi.scaled_bounds(self, "design_var")
        con_bounds = omi.scaled_bounds(self, "constraint")
        designvars, cons = omi.design_var_meta(self), omi.constraint_meta(self)

        self._dv_slices = {}
        lower, upper = [], []
        n = 0
        for name, meta in designvars.items():
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

        self._nl_cons = [c for c, m in cons.items() if not m["linear"]]
        self._lin_cons = [c for c, m in cons.items() if m["linear"]]
        self._con_slices = {}
        g_lower, g_upper = [], []
        m = 0
        for name in self._nl_cons + self._lin_cons:
            size = cons[name]["size"]
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
        self._m_nl = int(sum(cons[c]["size"] for c in self._nl_cons))
        g_lower = np.concatenate(g_lower).astype(float) if m else np.zeros(0)
        g_upper = np.concatenate(g_upper).astype(float) if m else np.zeros(0)
        self._g_lower, self._g_upper = np.minimum(g_lower, g_upper), np.maximum(g_lower, g_upper)

    def _jacobian_structure(self):
        """(rows, cols) of the nonlinear-constraint Jacobian entries IPOPT will be given."""
        cons = omi.constraint_meta(self)
        blocks = None
        coloring = omi.total_coloring(self)
        if coloring is not None:
            blocks = coloring.get_subjac_sparsity()
            if blocks is not None and not all(c in blocks for c in self._nl_cons):
                blocks = None  # coloring names do not match ours: fall back to relevance

        rows, cols = [], []
        for con in self._nl_cons:
            r0 = self._con_slices[con].start
            size = cons[con]["size"]
            if blocks is not None:
                for dv, (nzr, nzc, _shape) in blocks[con].items():
                    if dv in self._dv_slices:
                        rows.append(r0 + np.asarray(nzr))
                        cols.append(self._dv_slices[dv].start + np.asarray(nzc))
                continue
            for dv in omi.relevant_design_vars(self, con):
                sl = self._dv_slices[dv]
                rr, cc = np.meshgrid(np.arange(size), np.arange(sl.start, sl.stop), indexing="ij")
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
        try:  # optional dependency (lpc-mdo[ipopt]): imported when IPOPT runs
            import cyipopt
        except ImportError as err:
            raise ImportError(
                "IpoptDriver needs the 'cyipopt' module: pip install 'lpc-mdo[ipopt]' "
                "(cyipopt-wheels, CPython 3.11 on Linux x86-64) or conda install -c conda-forge "
                "cyipopt. Without IPOPT use make_driver('SLSQP')."
            ) from err

        self.result.reset()
        problem = omi.owning_problem(self)
        self.iter_count = 0
        self._ipopt_iterations = 0
        self._user_stop = False
        self._callback_error = None
        self.analysis_errors = []
        omi.reset_total_jacobians(self)
        self._reset_caches()

        omi.check_ready_to_run(self)

        # Initial run: the design point IPOPT starts from, recorded like every evaluation.
        with omi.record_evaluation(self):
            omi.run_model(self)
            self.iter_count += 1

        self._layout()
        dv_names = list(omi.design_var_meta(self))
        dv_vals = self.get_design_var_values()
        x0 = np.concatenate([np.atleast_1d(dv_vals[n]) for n in dv_names]).astype(float)
        self._x_model = x0.copy()
        self._store_funcs()

        omi.compute_total_coloring(self)

        # Linear constraints: Jacobian once, values from it for every x.
        self._lin_jac = np.zeros((0, self._n))
        self._lin_g0 = np.zeros(0)
        if self._lin_cons:
            self._lin_jac = np.atleast_2d(omi.compute_totals(self, self._lin_cons, dv_names))
            lin_vals = self.get_constraint_values(lintype="linear")
            self._lin_g0 = np.concatenate([np.atleast_1d(lin_vals[c]) for c in self._lin_cons])
        self._x0_lin = x0.copy()

        nl_rows, nl_cols = self._jacobian_structure()
        lin_r, lin_c = np.nonzero(self._lin_jac)
        self._nl_rows, self._nl_cols = nl_rows, nl_cols
        self._jac_rows = np.concatenate([nl_rows, lin_r + self._m_nl]).astype(int)
        self._jac_cols = np.concatenate([nl_cols, lin_c]).astype(int)
        self._lin_vals = self._lin_jac[lin_r, lin_c]

        nlp = cyipopt.Problem(
            n=self._n,
            m=self._m,
            problem_obj=_IpoptCallbacks(self, cyipopt),
            lb=self._x_lower,
            ub=self._x_upper,
            cl=self._g_lower,
            cu=self._g_upper,
        )
        settings = dict(DEFAULT_IPOPT_SETTINGS)
        settings["max_iter"] = self.options["max_iter"]
        settings["tol"] = self.options["tol"]
        settings["print_level"] = self.options["print_level"]
        if self.options["print_level"] == 0:
            settings["sb"] = "yes"  # no "This program contains Ipopt ..." banner either
        if self.options["output_file"]:
            settings["output_file"] = str(
                problem.get_outputs_dir(mkdir=True) / self.options["output_file"]
            )
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

        if self._callback_error is not None:
            error, self._callback_error = self._callback_error, None
            raise error[1].with_traceback(error[2])

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

    @property
    def user_stopped(self):
        """Whether the last run stopped on a Ctrl-C during a model evaluation."""
        return self._user_stop

    @property
    def optimizer_iterations(self):
        """IPOPT iterations completed so far (its intermediate callback's count)."""
        return self._ipopt_iterations

    def update_result(self, result):
        """
        Record IPOPT's iteration count and exit status in ``driver.result``.

        Parameters
        ----------
        result : DriverResult
            The result object of the driver.
        """
        result.iter_count = self._ipopt_iterations
        result.exit_status = self._status_msg

    # ------------------------------------------------------------------ evaluations

    def _set_x(self, x):
        omi.set_design_vector(self, x)

    def _store_funcs(self):
        obj = next(iter(self.get_objective_values().values()))
        cons = self.get_constraint_values(lintype="nonlinear")
        g = (
            np.concatenate([np.atleast_1d(cons[c]) for c in self._nl_cons])
            if self._nl_cons
            else np.zeros(0)
        )
        self._funcs = (float(np.asarray(obj).ravel()[0]), g)

    def _evaluate(self, x):
        """Run the model at x unless it was just run there; raise on AnalysisError."""
        if self._x_model is not None and np.array_equal(x, self._x_model):
            return True
        if self._x_failed is not None and np.array_equal(x, self._x_failed):
            return False
        self._set_x(x)
        ok = True
        with omi.record_evaluation(self):
            self.iter_count += 1
            try:
                omi.run_model(self)
            except om.AnalysisError as err:
                omi.clear_solver_print(self)
                self.analysis_errors.append(str(err))
                self._failure = err  # recorded as a failed case on leaving the block
                ok = False
            except KeyboardInterrupt:
                omi.clear_solver_print(self)
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
        of = list(omi.objective_meta(self)) + self._nl_cons
        jac = np.atleast_2d(omi.compute_totals(self, of, list(omi.design_var_meta(self))))
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
        for target, slices, key in (
            (lagrange, self._con_slices, "constraints"),
            (zl, self._dv_slices, "lower"),
            (zu, self._dv_slices, "upper"),
        ):
            for name, value in warm.get(key, {}).items():
                if name not in slices:
                    continue
                sl = slices[name]
                value = np.atleast_1d(value)
                if value.size != sl.stop - sl.start:
                    raise ValueError(
                        f"{self.msginfo}: warm_start multipliers for '{name}' have size "
                        f"{value.size}, but the problem has size {sl.stop - sl.start}."
                    )
                target[sl] = value
        return lagrange, zl, zu


class _IpoptCallbacks:
    """The callback object cyipopt calls; keeps the driver free of cyipopt's method names."""

    def __init__(self, driver, cyipopt):
        self._driver = driver
        self._error = cyipopt.CyIpoptEvaluationError

    def _guard(self, func, x):
        drv = self._driver
        if drv._callback_error is not None:
            raise self._error()
        try:
            out = func(x)
        except Exception:
            drv._callback_error = sys.exc_info()
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

    def intermediate(
        self,
        alg_mod,
        iter_count,
        obj_value,
        inf_pr,
        inf_du,
        mu,
        d_norm,
        regularization_size,
        alpha_du,
        alpha_pr,
        ls_trials,
    ):
        drv = self._driver
        drv._ipopt_iterations = int(iter_count)
        # Returning False stops IPOPT cleanly (user interrupt or a Python error in a callback).
        return not (drv._user_stop or drv._callback_error is not None)
