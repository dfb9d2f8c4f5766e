"""A one-line-per-iteration progress display for long optimizations.

:class:`ProgressLine` is an OpenMDAO case recorder that records nothing: attached to a driver
(``prob.driver.add_recorder(ProgressLine('full'))`` before ``final_setup``), it prints the
driver's iteration, the objective, the largest constraint violation (in the driver's scaled
space, like IPOPT's ``inf_pr``) and the elapsed time each time the driver records an iteration,
whatever the optimizer.
"""

import sys
import time

import numpy as np
from openmdao.recorders.case_recorder import CaseRecorder

from lpc_mdo.checks import check_integer


class ProgressLine(CaseRecorder):
    """
    Print ``label  iter  objective  max violation  elapsed`` per driver iteration.

    Parameters
    ----------
    label : str
        Printed at the start of every line (the problem's name).
    stream : file-like
        Where to print (default: standard output).
    every : int
        Print every ``every``-th recorded iteration (>= 1).
    """

    def __init__(self, label, stream=None, every=1):
        super().__init__(record_viewer_data=False)
        check_integer("every", every, lower=1, where="ProgressLine")
        self.label = label
        self.stream = stream
        self.every = every
        self._start = None
        self._driver = None
        self._iterations = 0  # driver iterations recorded since startup

    def startup(self, recording_requester, comm=None):
        super().startup(recording_requester, comm)
        self._start = time.perf_counter()
        self._driver = recording_requester
        self._iterations = 0

    def record_iteration_driver(self, recording_requester, data, metadata):
        self._iterations += 1
        if (self._iterations - 1) % self.every:
            return
        driver = recording_requester
        if not metadata["success"]:  # an evaluation that raised AnalysisError
            print(
                f"{self.label:>16}  iter {self._iterations:5d}  evaluation failed: "
                f"{metadata['msg']}",
                file=self.stream or sys.stdout,
                flush=True,
            )
            return
        objective = driver.get_objective_values(driver_scaling=False)
        obj = float(np.ravel(next(iter(objective.values())))[0]) if objective else float("nan")
        elapsed = time.perf_counter() - self._start
        print(
            f"{self.label:>16}  iter {self._iterations:5d}  objective {obj:12.6g}  "
            f"max violation {max_violation(driver):9.3e}  {elapsed:8.1f} s",
            file=self.stream or sys.stdout,
            flush=True,
        )

    # A driver recorder receives only driver iterations; the other hooks have nothing to do.
    def record_iteration_system(self, recording_requester, data, metadata):
        pass

    def record_iteration_solver(self, recording_requester, data, metadata):
        pass

    def record_iteration_problem(self, recording_requester, data, metadata):
        pass

    def record_derivatives_driver(self, recording_requester, data, metadata):
        pass

    def record_metadata_system(self, system, run_number=None):
        pass

    def record_metadata_solver(self, solver, run_number=None):
        pass

    def record_viewer_data(self, model_viewer_data):
        pass


def max_violation(driver):
    """Largest constraint violation of a driver's current point, in its scaled space."""
    from lpc_mdo.drivers.openmdao_internals import owning_problem
    from lpc_mdo.trim import driver_scaling

    values = driver.get_constraint_values(driver_scaling=False)
    meta = owning_problem(driver).model.get_constraints()  # bounds as declared (unscaled)
    worst = 0.0
    for name, value in values.items():
        m = meta.get(name)
        if m is None:
            continue
        value = np.ravel(value)
        if m["equals"] is not None:
            viol = np.abs(value - np.ravel(m["equals"]))
        else:
            lower = -np.inf if m["lower"] is None else np.ravel(m["lower"])
            upper = np.inf if m["upper"] is None else np.ravel(m["upper"])
            viol = np.maximum(np.maximum(lower - value, value - upper), 0.0)
        if viol.size:
            worst = max(worst, float(np.max(np.abs(viol * driver_scaling(m)[0]))))
    return worst
