"""SLSQP driver: OpenMDAO's ``ScipyOptimizeDriver`` that backs off from failed evaluations."""

import openmdao.api as om
from openmdao.utils.om_warnings import DriverWarning, issue_warning

from lpc_mdo.drivers import openmdao_internals as omi

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

    Options
    -------
    failure_penalty : float
        Added to the last successful objective at a failed point (driver-scaled; >= 0).
    """

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.options["optimizer"] = "SLSQP"
        self.analysis_errors = []
        self._last_good = None  # (scaled objective, constraint values) of the last good point
        self._last_failed = False  # whether the model holds a failed trial point
        self._iterations = 0  # SLSQP major iterations of the current run

    def declare_options(self):
        """Declare ``failure_penalty`` on top of ``ScipyOptimizeDriver``'s options."""
        self.options.declare(
            "failure_penalty",
            default=1.0e6,
            lower=0.0,
            desc="added to the last successful scaled objective at a point "
            "where the model raised om.AnalysisError",
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
        with omi.scipy_iteration_callback(self._iteration_done):
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
        self._iterations += 1

    def update_result(self, result):
        """
        Record SLSQP's major iterations as ``iter_count`` (OpenMDAO's: model evaluations).

        ``model_evals`` keeps the model evaluations.

        Parameters
        ----------
        result : DriverResult
            The result object of the driver.
        """
        result.iter_count = self.optimizer_iterations

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
