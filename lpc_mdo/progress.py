"""A one-line-per-iteration progress display for long optimizations.

:class:`ProgressLine` is an OpenMDAO case recorder that records nothing: attached to a driver
(``prob.driver.add_recorder(ProgressLine('full'))`` before ``final_setup``), it prints the
optimizer's iteration count (:func:`optimizer_iterations`: IPOPT's from its intermediate
callback, SLSQP's from its gradient evaluations), the number of model evaluations (the driver
cases recorded), the objective, the largest constraint violation
(:func:`lpc_mdo.drivers.scaling.max_violation`: in the driver's scaled space, like IPOPT's
``inf_pr``) and the elapsed time each time the driver records a model evaluation,
whatever the optimizer.

:func:`trim_line` is the line of one trimmed condition and :func:`interrupt_message` the
message after Ctrl-C that says what the case files hold.
"""

import os
import sys
import time
from pathlib import Path

import numpy as np
import openmdao.api as om
from openmdao.recorders.case_recorder import CaseRecorder

from lpc_mdo.core.checks import check_integer
from lpc_mdo.drivers.scaling import max_violation


class ProgressLine(CaseRecorder):
    """
    Print ``label  iter  eval  objective  max violation  elapsed`` per model evaluation.

    ``iter`` is the optimizer iteration the evaluation belongs to: 0 for the start point, then
    the iterations completed (:func:`optimizer_iterations`) plus one, the numbering of IPOPT's
    own table (``-`` for a driver whose count is not known); ``eval`` counts the model
    evaluations (driver cases), several per iteration when a line search cuts a step.

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
        self._iterations = 0  # driver cases (model evaluations) recorded since startup

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
        counters = f"{self.label:>16}  iter {_format_count(self._iteration(driver))}  " + (
            f"eval {self._iterations:5d}"
        )
        if not metadata["success"]:  # an evaluation that raised AnalysisError
            print(
                f"{counters}  evaluation failed: {metadata['msg']}",
                file=self.stream or sys.stdout,
                flush=True,
            )
            return
        objective = driver.get_objective_values(driver_scaling=False)
        obj = float(np.ravel(next(iter(objective.values())))[0]) if objective else float("nan")
        elapsed = time.perf_counter() - self._start
        print(
            f"{counters}  objective {obj:12.6g}  "
            f"max violation {max_violation(driver):9.3e}  {elapsed:8.1f} s",
            file=self.stream or sys.stdout,
            flush=True,
        )

    def _iteration(self, driver):
        """Optimizer iteration of the evaluation just recorded: 0 the start, then done + 1."""
        done = optimizer_iterations(driver)
        if done is None:
            return None
        return 0 if self._iterations == 1 else done + 1

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


def _format_count(count):
    return "    -" if count is None else f"{count:5d}"


def optimizer_iterations(driver):
    """
    Return the optimizer iterations a driver has completed so far, or None if not known.

    :class:`~lpc_mdo.drivers.IpoptDriver`: IPOPT's iteration number from its intermediate
    callback; :class:`~lpc_mdo.drivers.SlsqpDriver` (and any driver with an
    ``optimizer_iterations`` attribute): SLSQP's major iterations. Other drivers
    (pyOptSparseDriver) do not expose theirs: None.

    Parameters
    ----------
    driver : Driver

    Returns
    -------
    int or None
    """
    count = getattr(driver, "optimizer_iterations", None)
    return None if count is None else int(count)


def trim_line(label, condition, before, after, iterations, seconds, power=None):
    """
    Return the progress line of one trimmed condition.

    Parameters
    ----------
    label : str
        The stage's name.
    condition : str
        The condition trimmed.
    before, after : float
        Largest driver-scaled trim residual before and after the trim.
    iterations : int
        Jacobian evaluations of the trim solve (its Gauss-Newton iterations).
    seconds : float
        Time of the condition's trim, including building its problem.
    power : tuple or None
        A least-power trim's (power at the trim reached, power kept in W, outcome):
        :attr:`lpc_mdo.trim.ConditionTrim.power`; None: not a least-power trim.

    Returns
    -------
    str
    """
    line = (
        f"{label:>16}  trim {condition:<14}  max scaled residual {before:9.3e} -> {after:9.3e}"
        f"  {iterations:3d} iterations  {seconds:6.1f} s"
    )
    if power is not None:
        line += f"  power {power[0] / 1e3:.1f} -> {power[1] / 1e3:.1f} kW ({power[2]})"
    return line


def interrupt_message(case_files):
    """
    Say what the case files of an interrupted run hold (for the message after Ctrl-C).

    Parameters
    ----------
    case_files : str, os.PathLike or sequence of them
        Case files of the run (those not written are said to be missing); a folder stands for
        every ``*.sql`` file in it.

    Returns
    -------
    str
        One line: ``interrupted; <file>: <n> driver cases, a 'final' case ...`` for each file.
    """
    if isinstance(case_files, (str, os.PathLike)):
        case_files = [case_files]
    paths = []
    for item in case_files:
        item = Path(item)
        paths.extend(sorted(item.glob("*.sql")) if item.is_dir() else [item])
    parts = [_case_file_summary(path) for path in paths] or ["no case file was written"]
    return "interrupted; " + "; ".join(parts)


def _case_file_summary(path):
    if not path.is_file():
        return f"{path.name} was not written"
    try:
        reader = om.CaseReader(str(path))
        driver_cases = len(reader.list_cases("driver", recurse=False, out_stream=None))
        problem_cases = reader.list_cases("problem", recurse=False, out_stream=None)
    except Exception as err:  # a file cut off by the interrupt
        return f"{path.name} cannot be read ({type(err).__name__}: {err})"
    names = {str(c).rsplit("|", 1)[-1] for c in problem_cases}
    final = "a 'final' case" if "final" in names else "no 'final' case"
    plural = "" if driver_cases == 1 else "s"
    return f"{path.name} holds {driver_cases} driver case{plural} and {final}"
