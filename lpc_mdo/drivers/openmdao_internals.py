"""Every use of OpenMDAO private or semi-private driver API in lpc-mdo, in one place.

Checked against OpenMDAO 3.45.1, the version pinned in ``pyproject.toml``
(``openmdao>=3.45.1,<3.46``).  OpenMDAO does not promise that names with a leading underscore
stay put: the driver autoscaler, for one, changed within 3.45.x.  When the pin moves, this
module is the only one to re-check; :mod:`lpc_mdo.drivers.ipopt`,
:mod:`lpc_mdo.drivers.slsqp` and :mod:`lpc_mdo.drivers.scaling` reach OpenMDAO's internals only
through the names below.

What is touched, and why
------------------------
Hooks a ``Driver`` subclass has to override (OpenMDAO's own drivers do the same):

* ``Driver._declare_options`` - called by ``Driver.__init__`` to declare options; routed to
  :meth:`DriverHooks.declare_options`.
* ``Driver._setup_driver`` - called by ``Problem.final_setup``; routed to
  :meth:`DriverHooks.check_setup` after OpenMDAO's own setup (the IPOPT driver rejects several
  objectives there, before any model run).
* ``Driver._get_name`` - the name OpenMDAO prints and records; returns ``driver_name``.
* ``Driver._update_result`` - fills ``driver.result`` (iteration count, exit status) after
  ``run``; routed to :meth:`DriverHooks.update_result`.
* ``Driver._get_recorder_metadata`` - the metadata of each recorded case; overridden by
  :class:`FailedCaseFlags` so that an evaluation that raised ``om.AnalysisError`` is recorded
  with ``success = 0`` (OpenMDAO records every evaluation as a success).
* ``ScipyOptimizeDriver._objfunc`` - SciPy's objective callback; routed to
  :meth:`ScipyHooks.objective_callback` so SLSQP can back off from a failed evaluation.
* ``openmdao.drivers.scipy_optimizer.minimize`` - the ``scipy.optimize.minimize`` that
  ``ScipyOptimizeDriver.run`` calls with ``callback=None``; :func:`scipy_iteration_callback`
  replaces it for the duration of a run by one that passes a callback (SciPy calls it after
  every major iteration: the driver's iteration count).
* ``ScipyOptimizeDriver._update_result`` - routed to :meth:`ScipyHooks.update_result` after
  OpenMDAO's own.

Driver state read or written from outside OpenMDAO's own methods:

* ``Driver.supports._read_only`` - the ``supports`` dictionary is locked after
  ``Driver.__init__``; a new driver has to unlock it once to declare what it supports.
* ``Driver._designvars``, ``Driver._cons``, ``Driver._objs`` - the driver-level metadata
  (size, source, linear flag) of design variables, constraints and objectives, in the order the
  driver vectors use; there is no public accessor at driver level.
* ``Driver._autoscaler.get_bounds_scaling`` (through the public ``autoscaler`` property) - the
  design-variable and constraint bounds in the driver-scaled space IPOPT works in.
* ``Driver._coloring_info`` - the total-derivative coloring declared with
  ``declare_coloring``, passed to ``Problem.get_total_coloring`` and read for the sparsity of the
  constraint Jacobian.
* ``Driver._problem`` - weak reference to the owning problem (the largest constraint violation,
  :func:`lpc_mdo.drivers.scaling.max_violation`, reads the declared constraint bounds from its
  model).
* ``System._relevance`` (``nonlinear_active``, ``seeds_active``, ``is_relevant``) - restricts a
  model run to the systems the optimization needs, as ``ScipyOptimizeDriver`` does, and tells
  which design variables a constraint depends on when there is no coloring.
* ``Driver._run_solve_nonlinear`` and ``Driver._compute_totals`` - one model evaluation and
  one total-derivative evaluation, counted and recorded as OpenMDAO's drivers count them.
* ``Driver._vectors['design_var']`` and ``Driver._set_design_vars`` - write a driver-scaled
  design vector into the model in one call.
* ``Driver._check_for_missing_objective``, ``Driver._check_for_invalid_desvar_values`` - the
  checks OpenMDAO's drivers run before optimizing.
* ``Driver._total_jac``, ``Driver._total_jac_linear`` - cached total-Jacobian objects, cleared
  at the start of a run as ``ScipyOptimizeDriver.run`` clears them.
* ``System._clear_iprint`` - resets solver print state after an evaluation that raised.
* ``Driver._exc_info`` and ``Driver._reraise`` - ``ScipyOptimizeDriver`` keeps the first
  exception of a SciPy callback here and re-raises it after SciPy returns; SLSQP's back-off
  reads and clears it.
* ``ScipyOptimizeDriver._con_cache`` - the constraint values of the point last evaluated, which
  SciPy's constraint callbacks read; SLSQP's back-off replaces them at a failed point.
* ``ScipyOptimizeDriver._scipy_optimize_result`` - SciPy's ``OptimizeResult`` of the last run.
* ``openmdao.core.driver.RecordingDebugging`` - records one evaluation as a driver case (not
  exported by ``openmdao.api``).
"""

import contextlib
import sys

import openmdao.api as om
from openmdao.core.driver import Driver, RecordingDebugging
from openmdao.drivers import scipy_optimizer

__all__ = [
    "DriverHooks",
    "FailedCaseFlags",
    "ScipyHooks",
    "check_ready_to_run",
    "clear_solver_print",
    "compute_total_coloring",
    "compute_totals",
    "constraint_meta",
    "design_var_meta",
    "clear_pending_error",
    "objective_meta",
    "owning_problem",
    "pending_error",
    "raise_pending_error",
    "record_evaluation",
    "relevant_design_vars",
    "reset_total_jacobians",
    "run_model",
    "scaled_bounds",
    "scipy_constraint_cache",
    "scipy_objective",
    "scipy_result_x",
    "set_design_vector",
    "set_scipy_constraint_cache",
    "set_supports",
    "total_coloring",
]


# ---------------------------------------------------------------------- hooks


class FailedCaseFlags:
    """
    Driver mixin that records a model evaluation that raised ``om.AnalysisError`` as failed.

    Such an evaluation is recorded as a driver case with ``success = 0`` and the error as
    ``msg`` (OpenMDAO records every evaluation with ``success = 1``), so post-processing can
    leave its stale outputs out (``case.success``).

    The error is the exception being handled when the case is recorded, or ``_failure`` when a
    driver caught it itself before leaving the recording block.
    """

    _failure = None  # the AnalysisError of the evaluation being recorded, when caught

    def _get_recorder_metadata(self, case_name):
        meta = super()._get_recorder_metadata(case_name)
        error = self._failure if self._failure is not None else sys.exc_info()[1]
        if isinstance(error, om.AnalysisError):
            meta["success"], meta["msg"] = 0, str(error)
        return meta


class DriverHooks(FailedCaseFlags, Driver):
    """
    ``Driver`` base whose underscore hooks call public methods a subclass may define.

    Attributes
    ----------
    driver_name : str
        The name OpenMDAO prints and records for the driver.
    """

    driver_name = "Driver"

    def _declare_options(self):
        self.declare_options()

    def _setup_driver(self, problem):
        super()._setup_driver(problem)
        self.check_setup()

    def _get_name(self):
        return self.driver_name

    def _update_result(self, result):
        self.update_result(result)

    def declare_options(self):
        """Declare the driver's options (called once by ``Driver.__init__``)."""

    def check_setup(self):
        """Check the problem the driver was set up on (called by ``Problem.final_setup``)."""

    def update_result(self, result):
        """
        Fill ``driver.result`` after a run.

        Parameters
        ----------
        result : DriverResult
            The result object of the driver.
        """


class ScipyHooks(FailedCaseFlags, om.ScipyOptimizeDriver):
    """``ScipyOptimizeDriver`` base whose option and objective hooks call public methods."""

    def _declare_options(self):
        super()._declare_options()
        self.declare_options()

    def _objfunc(self, x_new):
        return self.objective_callback(x_new)

    def _update_result(self, result):
        super()._update_result(result)
        self.update_result(result)

    def update_result(self, result):
        """
        Fill ``driver.result`` after a run (called after OpenMDAO's own).

        Parameters
        ----------
        result : DriverResult
            The result object of the driver.
        """

    def declare_options(self):
        """Declare options on top of ``ScipyOptimizeDriver``'s (called by ``__init__``)."""

    def objective_callback(self, x_new):
        """
        SciPy's objective callback; by default OpenMDAO's.

        Parameters
        ----------
        x_new : ndarray
            Design vector (driver-scaled).

        Returns
        -------
        float
            Objective value (driver-scaled).
        """
        return scipy_objective(self, x_new)


@contextlib.contextmanager
def scipy_iteration_callback(callback, finish=None):
    """
    Make ``ScipyOptimizeDriver.run`` pass ``callback`` to ``scipy.optimize.minimize``.

    SciPy calls it after every major iteration with the iterate (``intermediate_result``);
    OpenMDAO's driver passes no callback of its own. A callback that raises ``StopIteration``
    ends the run (SciPy then reports ``success = False``, status 99).

    Parameters
    ----------
    callback : callable
        ``callback(intermediate_result)``; returns nothing or raises ``StopIteration``.
    finish : callable or None
        ``finish(result)`` is applied to SciPy's ``OptimizeResult`` before
        ``ScipyOptimizeDriver.run`` reads its ``success`` and ``message``.
    """
    original = scipy_optimizer.minimize

    def minimize(*args, **kwargs):
        kwargs["callback"] = callback
        result = original(*args, **kwargs)
        if finish is not None:
            finish(result)
        return result

    scipy_optimizer.minimize = minimize
    try:
        yield
    finally:
        scipy_optimizer.minimize = original


# ---------------------------------------------------------------------- driver set-up


def set_supports(driver, **flags):
    """
    Declare what ``driver`` supports (``supports`` is read-only after ``Driver.__init__``).

    Parameters
    ----------
    driver : Driver
        The driver being built.
    **flags : bool
        ``supports`` entries such as ``optimization=True``.
    """
    driver.supports._read_only = False
    try:
        for key, value in flags.items():
            driver.supports[key] = value
    finally:
        driver.supports._read_only = True


def owning_problem(driver):
    """
    Return the problem ``driver`` belongs to.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.

    Returns
    -------
    Problem
        The owning problem.
    """
    return driver._problem()


def design_var_meta(driver):
    """
    Return the driver-level metadata of the design variables, in driver order.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.

    Returns
    -------
    dict
        Design variable name -> metadata (``size``, ``source``, ...).
    """
    return driver._designvars


def constraint_meta(driver):
    """
    Return the driver-level metadata of the constraints, in driver order.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.

    Returns
    -------
    dict
        Constraint name -> metadata (``size``, ``source``, ``linear``, ...).
    """
    return driver._cons


def objective_meta(driver):
    """
    Return the driver-level metadata of the objectives.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.

    Returns
    -------
    dict
        Objective name -> metadata.
    """
    return driver._objs


def scaled_bounds(driver, kind):
    """
    Return the bounds of design variables or constraints in the driver-scaled space.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.
    kind : str
        ``'design_var'`` or ``'constraint'``.

    Returns
    -------
    dict
        Name -> bounds object with ``lower``, ``upper`` (and ``equals`` for constraints).
    """
    if kind not in ("design_var", "constraint"):
        raise ValueError(f"kind = {kind!r} is not allowed; use 'design_var' or 'constraint'.")
    return driver.autoscaler.get_bounds_scaling(kind)


def total_coloring(driver):
    """
    Return the total-derivative coloring of ``driver``, or None when none was computed.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.

    Returns
    -------
    Coloring or None
        The coloring.
    """
    return driver._coloring_info.coloring


def compute_total_coloring(driver):
    """
    Compute the total coloring ``declare_coloring`` asked for, without running the model again.

    Parameters
    ----------
    driver : Driver
        A driver whose model has just been run.
    """
    owning_problem(driver).get_total_coloring(driver._coloring_info, run_model=False)


def relevant_design_vars(driver, constraint):
    """
    Return the design variables that constraint ``constraint`` depends on in the model.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.
    constraint : str
        Driver-level constraint name.

    Returns
    -------
    list of str
        Design variable names, in driver order.
    """
    relevance = owning_problem(driver).model._relevance
    designvars = design_var_meta(driver)
    with relevance.seeds_active(rev_seeds=(constraint_meta(driver)[constraint]["source"],)):
        return [dv for dv, meta in designvars.items() if relevance.is_relevant(meta["source"])]


def check_ready_to_run(driver):
    """
    Run OpenMDAO's pre-optimization checks (an objective exists; design values are valid).

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.
    """
    driver._check_for_missing_objective()
    driver._check_for_invalid_desvar_values()


def reset_total_jacobians(driver):
    """
    Drop the cached total Jacobians of a previous run.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.
    """
    driver._total_jac = None
    driver._total_jac_linear = None


# ---------------------------------------------------------------------- evaluations


@contextlib.contextmanager
def record_evaluation(driver):
    """
    Record the model evaluation made inside the block as one driver case.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.

    Yields
    ------
    None
    """
    with RecordingDebugging(driver._get_name(), driver.iter_count, driver):
        yield


def run_model(driver):
    """
    Run the model once for the driver (only the systems the optimization needs).

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.
    """
    with owning_problem(driver).model._relevance.nonlinear_active("iter"):
        driver._run_solve_nonlinear()


def clear_solver_print(driver):
    """
    Reset the solvers' print state after an evaluation that raised.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.
    """
    owning_problem(driver).model._clear_iprint()


def set_design_vector(driver, x):
    """
    Write the driver-scaled design vector ``x`` into the model.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.
    x : ndarray
        All design variables concatenated in driver order, driver-scaled.
    """
    driver._vectors["design_var"].set_data(x, driver_scaling=True)
    driver._set_design_vars(driver_scaling=True)


def compute_totals(driver, of, wrt):
    """
    Return the driver-scaled total derivatives of ``of`` with respect to ``wrt`` as an array.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up.
    of : list of str
        Objective and constraint names.
    wrt : list of str
        Design variable names.

    Returns
    -------
    ndarray
        Jacobian, rows in the order of ``of``, columns in the order of ``wrt``.
    """
    return driver._compute_totals(of=of, wrt=wrt, return_format="array")


# ---------------------------------------------------------------------- ScipyOptimizeDriver


def scipy_objective(driver, x_new):
    """
    Run ``ScipyOptimizeDriver``'s own objective callback at ``x_new``.

    Parameters
    ----------
    driver : ScipyOptimizeDriver
        The driver.
    x_new : ndarray
        Design vector (driver-scaled).

    Returns
    -------
    float
        Objective value (driver-scaled); on an exception, the exception is kept as pending.
    """
    return om.ScipyOptimizeDriver._objfunc(driver, x_new)


def pending_error(driver):
    """
    Return the exception a SciPy callback caught and has not re-raised yet, or None.

    Parameters
    ----------
    driver : ScipyOptimizeDriver
        The driver.

    Returns
    -------
    Exception or None
        The pending exception.
    """
    return None if driver._exc_info is None else driver._exc_info[1]


def clear_pending_error(driver):
    """
    Forget the pending exception of a SciPy callback (it has been handled).

    Parameters
    ----------
    driver : ScipyOptimizeDriver
        The driver.
    """
    driver._exc_info = None


def raise_pending_error(driver):
    """
    Re-raise the pending exception of a SciPy callback, if any, with its traceback.

    Parameters
    ----------
    driver : ScipyOptimizeDriver
        The driver.
    """
    if driver._exc_info is not None:
        driver._reraise()


def scipy_constraint_cache(driver):
    """
    Return the constraint values SciPy's constraint callbacks read for the last point.

    Parameters
    ----------
    driver : ScipyOptimizeDriver
        The driver.

    Returns
    -------
    object
        The cached constraint values.
    """
    return driver._con_cache


def set_scipy_constraint_cache(driver, cache):
    """
    Replace the constraint values SciPy's constraint callbacks read.

    Parameters
    ----------
    driver : ScipyOptimizeDriver
        The driver.
    cache : object
        Values returned earlier by :func:`scipy_constraint_cache`.
    """
    driver._con_cache = cache


def scipy_result_x(driver):
    """
    Return the design vector of SciPy's result of the last run (driver-scaled).

    Parameters
    ----------
    driver : ScipyOptimizeDriver
        The driver after ``run``.

    Returns
    -------
    ndarray
        The design vector.
    """
    return driver._scipy_optimize_result.x
