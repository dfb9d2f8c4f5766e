"""SLSQP driver: ``ScipyOptimizeDriver`` that backs off from failures and stops when stalled."""

import numpy as np
import openmdao.api as om
from openmdao.utils.om_warnings import DriverWarning, issue_warning

from lpc_mdo.drivers import openmdao_internals as omi
from lpc_mdo.drivers.scaling import max_violation

__all__ = ["SlsqpDriver"]


class SlsqpDriver(omi.ScipyHooks):
    """
    OpenMDAO's ``ScipyOptimizeDriver`` with SLSQP that backs off from points where the model fails.

    SciPy's SLSQP has no notion of a failed evaluation, and ``ScipyOptimizeDriver`` re-raises
    the first exception of the model, ending the run: an ``om.AnalysisError`` at one line-search
    point (a trial step that stalls a motor or leaves a rotor without through-flow) would end a
    full-problem optimization that a shorter step keeps feasible. Here an ``om.AnalysisError``
    at a trial point returns the last successful point's objective plus ``failure_penalty``
    (in the driver-scaled space) and that point's constraint values, so the merit function
    rises and SLSQP's line search cuts the step (by at least 10x each time); an error at the
    first evaluation, or any other exception, is re-raised as before. The messages are kept in
    ``analysis_errors``, as :class:`lpc_mdo.drivers.IpoptDriver` does.

    SciPy's SLSQP stops when an iteration changes the scaled objective by less than ``tol`` and
    the *sum* of the scaled constraint violations is below ``tol`` (Kraft 1988, the ``acc``
    test of ``slsqp``). In a problem with a hundred constraint rows that are each met to a
    fraction of ``tol``, the sum can stay above it for hundreds of iterations while the
    objective creeps. With ``acceptable_iter`` > 0 the driver also stops, as a success, at an
    *acceptable* point, in the spirit of IPOPT's ``acceptable_iter`` (Wachter and Biegler 2006,
    Sec. 3.9): the current iterate's largest scaled violation
    (:func:`lpc_mdo.drivers.scaling.max_violation`, as the progress line prints it) is at most
    ``acceptable_constr_viol`` and the best objective among the iterates of the last
    ``acceptable_iter`` iterations that met that violation differs from the current objective by
    at most ``acceptable_obj_change`` times its size. ``acceptable_stop`` then says why it
    stopped (None otherwise).

    Options
    -------
    failure_penalty : float
        Added to the last successful objective at a failed point (driver-scaled; >= 0).
    acceptable_iter : int
        Window of the acceptable-point stop in major iterations (0: off, SciPy's test only).
    acceptable_obj_change : float
        Relative objective change over the window below which the run has stalled.
    acceptable_constr_viol : float
        Largest scaled constraint violation of an acceptable iterate.
    """

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.options["optimizer"] = "SLSQP"
        self.analysis_errors = []
        self._last_good = None  # (scaled objective, constraint values) of the last good point
        self._last_failed = False  # whether the model holds a failed trial point
        self._iterations = 0  # SLSQP major iterations of the current run
        self._best_feasible = []  # per iteration: best objective among acceptable iterates
        self.acceptable_stop = None  # why the run stopped at an acceptable point, or None

    def declare_options(self):
        """Declare ``failure_penalty`` on top of ``ScipyOptimizeDriver``'s options."""
        self.options.declare(
            "failure_penalty",
            default=1.0e6,
            lower=0.0,
            desc="added to the last successful scaled objective at a point "
            "where the model raised om.AnalysisError",
        )
        self.options.declare(
            "acceptable_iter",
            default=0,
            types=int,
            lower=0,
            desc="window (major iterations) of the acceptable-point stop; 0 turns it off",
        )
        self.options.declare(
            "acceptable_obj_change",
            default=5.0e-4,
            lower=0.0,
            desc="relative objective change over acceptable_iter iterations below which "
            "the run has stalled",
        )
        self.options.declare(
            "acceptable_constr_viol",
            default=3.0e-4,
            lower=0.0,
            desc="largest scaled constraint violation of an acceptable iterate",
        )

    def run(self):
        """
        Optimize the problem with SLSQP.

        Returns
        -------
        bool
            Failure flag: True if SLSQP did not report success.
        """
        self.analysis_errors = []
        self._last_good = None
        self._last_failed = False
        self._iterations = 0
        self._best_feasible = []
        self.acceptable_stop = None
        with omi.scipy_iteration_callback(self._iteration_done, self._finish):
            fail = super().run()
        if self._last_failed:  # the model holds a failed trial point: evaluate the result
            omi.scipy_objective(self, omi.scipy_result_x(self))
            omi.raise_pending_error(self)
        return fail

    @property
    def optimizer_iterations(self):
        """SLSQP major iterations completed so far (SciPy's callback count; at the end ``nit``)."""
        return self._iterations

    def _iteration_done(self, intermediate_result):
        """Count the iteration; raise ``StopIteration`` at an acceptable point (see class)."""
        self._iterations += 1
        window = self.options["acceptable_iter"]
        if window == 0:
            return
        f = float(intermediate_result.fun)
        viol = max_violation(self)
        best = self._best_feasible[-1] if self._best_feasible else np.inf
        if viol <= self.options["acceptable_constr_viol"]:
            best = min(best, f)
        self._best_feasible.append(best)
        if len(self._best_feasible) <= window or viol > self.options["acceptable_constr_viol"]:
            return
        before = self._best_feasible[-1 - window]
        change = abs(before - f) / max(abs(f), 1e-30)
        if np.isfinite(before) and change <= self.options["acceptable_obj_change"]:
            self.acceptable_stop = (
                f"acceptable point: the objective changed by {change:.2e} (relative) over "
                f"the last {window} iterations, the largest scaled constraint violation is "
                f"{viol:.2e}"
            )
            raise StopIteration

    def _finish(self, result):
        """Report a run stopped at an acceptable point as a success (SciPy says status 99)."""
        if self.acceptable_stop is not None:
            result.success, result.status, result.message = True, 0, self.acceptable_stop

    def update_result(self, result):
        """
        Record SLSQP's major iterations as ``iter_count`` (OpenMDAO's: model evaluations).

        ``model_evals`` keeps the model evaluations. A stop at an acceptable point says so in
        ``exit_status``.

        Parameters
        ----------
        result : DriverResult
            The result object of the driver.
        """
        result.iter_count = self.optimizer_iterations
        if self.acceptable_stop is not None:
            result.exit_status = f"SUCCESS ({self.acceptable_stop})"

    def objective_callback(self, x_new):
        """
        Objective at ``x_new``; at a failed trial point, the last good one plus the penalty.

        Parameters
        ----------
        x_new : ndarray
            Design vector (driver-scaled).

        Returns
        -------
        float
            Objective value (driver-scaled).
        """
        value = omi.scipy_objective(self, x_new)
        self._last_failed = False
        error = omi.pending_error(self)
        if error is None:
            self._last_good = (value, omi.scipy_constraint_cache(self))
            return value
        if not isinstance(error, om.AnalysisError) or self._last_good is None:
            return value  # re-raised by the constraint callback, as in ScipyOptimizeDriver
        omi.clear_pending_error(self)
        self._last_failed = True
        self.analysis_errors.append(str(error))
        issue_warning(
            f"model evaluation {self.iter_count} failed ({error}); SLSQP's line "
            "search is given the last good point's values plus failure_penalty",
            prefix=self.msginfo,
            category=DriverWarning,
        )
        value, cache = self._last_good
        omi.set_scipy_constraint_cache(self, cache)
        return value + self.options["failure_penalty"]
