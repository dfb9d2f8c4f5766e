"""The case recorder of lpc-mdo's problems: OpenMDAO's SQLite recorder, model metadata once."""

import openmdao.api as om

__all__ = ["CaseRecorder"]


class CaseRecorder(om.SqliteRecorder):
    """
    OpenMDAO's ``SqliteRecorder`` that records the systems' and solvers' metadata only once.

    OpenMDAO records the options and scaling vectors of every system and solver again at each
    ``run_model`` and ``run_driver`` of a problem with a recorder. A stage of the warm-start
    sequence runs the model three or four times (the trim's runs, the driver, the final case),
    and for the full LPC model (712 systems, whose options hold the vehicle) each recording
    took 1.9 s and added 712 rows to the case file (measured: 2442 rows in a
    full-problem case file). Here only the first run's metadata is recorded (OpenMDAO's run
    number None); the cases themselves are recorded as before, and ``CaseReader`` reads the
    system options of that first run. Nothing in lpc-mdo reads metadata per run.

    Parameters
    ----------
    filepath : str or os.PathLike
        The case file.
    **kwargs
        As ``om.SqliteRecorder``.
    """

    def __init__(self, filepath, **kwargs):
        super().__init__(str(filepath), **kwargs)

    def record_metadata_system(self, system, run_number=None):
        """Record a system's metadata at the first run only (see the class docstring)."""
        if run_number is None:
            super().record_metadata_system(system, run_number)

    def record_metadata_solver(self, solver, run_number=None):
        """Record a solver's metadata at the first run only (see the class docstring)."""
        if run_number is None:
            super().record_metadata_solver(solver, run_number)
