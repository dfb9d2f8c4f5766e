"""The paper's warm-start sequence (Fig. 8): subproblems 1 to 4, then the full problem.

Each problem records its iterations and a final case (every variable) to its own case file; the
next one starts from the previous final case: every design-variable array of the vehicle file
is set from it by name (``load_case`` itself also sets inputs, whose shapes differ between
subproblems with different conditions), so the design variables a subproblem did not have keep
the values the earlier ones found. The
full problem then rescales every design variable by its optimized magnitude (the paper's remedy
for the conditioning of rotor speeds ~1e3 against thicknesses ~1e-3).
"""

import os
import time
from dataclasses import dataclass, field

import numpy as np
import openmdao.api as om

from lpc_mdo import study_plan
from lpc_mdo.groups.lpc import openmdao_units
from lpc_mdo.post.statistics import process_peak_memory_mb, run_stats_path, write_run_stats
from lpc_mdo.problems import build_analysis_problem, build_problem, copy_design_variables
from lpc_mdo.progress import ProgressLine, optimizer_iterations
from lpc_mdo.sensitivities import post_optimal_sensitivities, sensitivities_path
from lpc_mdo.trim import trim
from lpc_mdo.vehicle import load_vehicle


@dataclass
class StageResult:
    """Outcome of one stage of the sequence."""

    name: str
    case_file: str
    success: bool
    iterations: int
    seconds: float
    gross_mass: float
    exit_status: str
    analysis_errors: int = 0
    trim_seconds: float = 0.0
    trim_message: str = ""
    extra: dict = field(default_factory=dict)


def magnitude_refs(case, vehicle, floor=1e-6):
    """
    Design-variable refs from optimized magnitudes: abs(x) per entry (floored), paper Sec. II.F.

    Parameters
    ----------
    case : openmdao Case
        A recorded case holding the design variables (a final problem case).
    vehicle : Vehicle
    floor : float
        Smallest ref, relative to the vehicle file's ref of that variable.

    Returns
    -------
    dict
        name -> ref array in the design variable's shape.
    """
    refs = {}
    for name, dv in vehicle.design_variables.items():
        try:
            value = np.asarray(case.get_val(name))
        except KeyError:
            continue
        refs[name] = np.maximum(np.abs(value), floor * dv.ref).reshape(dv.shape)
    return refs


def start_point(path, vehicle):
    """
    Return the case a run starts from and how it was chosen.

    The problem case ``'final'`` (what every run records when it ends), or, in a case file
    without one (a run killed or stopped by two Ctrl-C), its last recorded driver iteration
    that evaluated without error, if it holds every design-variable array of ``vehicle`` (the
    driver records them all at each iteration, :func:`lpc_mdo.problems.attach_recorder`).

    Returns
    -------
    case : openmdao Case
    label : str
        ``"final"`` or, e.g., ``"driver iteration 52 of 53 (no 'final' case: an interrupted
        run)"``.

    Raises
    ------
    ValueError
        When the file holds neither, saying what it holds.
    """
    reader = om.CaseReader(os.fspath(path))
    if "final" in reader.list_cases("problem", recurse=False, out_stream=None):
        return reader.get_case("final"), "final"
    names = reader.list_cases("driver", recurse=False, out_stream=None)
    for k in range(len(names) - 1, -1, -1):
        case = reader.get_case(names[k])
        if not case.success:
            continue
        missing = [n for n in vehicle.design_variables if n not in case.outputs]
        if missing:
            raise ValueError(
                f"{os.fspath(path)!r} holds no 'final' case, and its last driver case lacks "
                f"design variables {missing[:3]}{' ...' if len(missing) > 3 else ''} (a run "
                "recorded before lpc-mdo kept every design variable at each iteration)"
            )
        return case, (
            f"driver iteration {k + 1} of {len(names)} (no 'final' case: an interrupted run)"
        )
    raise ValueError(
        f"{os.fspath(path)!r} holds no 'final' case and no driver iteration that evaluated "
        f"without error ({len(names)} driver case(s))"
    )


def load_design_variables(prob, case, vehicle):
    """Set every design-variable array of the vehicle file from a recorded case."""
    copy_design_variables(case, prob, vehicle)


def run_sequence(
    out_dir,
    names=study_plan.SEQUENCE,
    vehicle=None,
    static_margin=True,
    optimizer=None,
    full_optimizer=None,
    driver_settings=None,
    start_case=None,
    rescale_full=True,
    trim_first=True,
    log=print,
    progress=False,
    trim_processes=1,
    keep_going=False,
):
    """
    Solve the stages in order, each warm-started from the previous stage's final case.

    A stage that does not converge stops the sequence (its successor would start from a point
    that is not that stage's optimum) unless ``keep_going``.

    Parameters
    ----------
    out_dir : str
        Folder for one case file per stage (``{name}.sql``).
    names : sequence of str
        Stages, from :data:`lpc_mdo.study_plan.STAGE_NAMES` (default: the warm-start sequence,
        :data:`lpc_mdo.study_plan.SEQUENCE`).
    vehicle : Vehicle, path or None
    static_margin : bool
    optimizer : str or None
        Optimizer of the stages before the full problem (None: each stage's,
        :func:`lpc_mdo.study_plan.default_optimizer`).
    full_optimizer : str or None
        Optimizer of the stages over every condition, the full problem (None: the stage's, an
        SQP method).
    driver_settings : dict or None
        make_driver settings for every stage, over the stage's settings as a step of the
        sequence (:meth:`lpc_mdo.study_plan.Stage.driver_settings` with ``in_sequence``).
    start_case : str or None
        Case file whose final case initializes the first stage.
    rescale_full : bool
        Rescale the design variables by their optimized magnitudes in the stages whose
        hand-over says so (the full problem; :attr:`lpc_mdo.study_plan.Stage.handover`).
    trim_first : bool
        Before each stage's optimizer, trim the stage's conditions by their trim variables
        where the stage table says so (:func:`lpc_mdo.trim.trim`; recorded as the problem case
        ``'trimmed'``). The previous stage changed the vehicle under them (the initial design
        is far from trim), and IPOPT with a quasi-Newton Hessian started far from trim stalls
        at locally infeasible points.
    log : callable
        Progress messages.
    progress : bool
        Progress lines of the trim and the optimizer (see :func:`solve_stage`).
    trim_processes : int
        Processes of each stage's trim (see :func:`solve_stage`).
    keep_going : bool
        Run the later stages after a stage that did not converge.

    Returns
    -------
    list of StageResult
        One per stage run: the last is the failed stage when the sequence stopped.
    """
    os.makedirs(out_dir, exist_ok=True)
    if vehicle is None or isinstance(vehicle, (str, os.PathLike)):
        vehicle = load_vehicle(vehicle)
    previous = start_case
    results = []
    for name in names:
        spec = study_plan.stage(name)
        chosen = full_optimizer if spec.every_condition else optimizer
        result = solve_stage(
            name,
            os.path.join(out_dir, f"{name}.sql"),
            vehicle=vehicle,
            start_case=previous,
            static_margin=static_margin,
            optimizer=chosen or study_plan.default_optimizer(name),
            driver_settings=driver_settings,
            in_sequence=True,
            rescale=rescale_full and spec.rescales,
            trim_first=trim_first,
            log=log,
            progress=progress,
            trim_processes=trim_processes,
        )
        results.append(result)
        previous = result.case_file
        if not result.success and not keep_going and name != names[-1]:
            log(f"{name} did not converge: the sequence stops here")
            break
    return results


def _write_interrupted_stats(prob, case_file, start, when):
    """Write the run statistics known at a Ctrl-C: the driver's counts so far, success False."""
    driver = prob.driver
    known = {
        key: getattr(driver.result, key, None)
        for key in ("model_evals", "model_time", "deriv_evals", "deriv_time")
    }
    iterations = optimizer_iterations(driver)
    known.update(
        runtime=time.perf_counter() - start,
        iter_count=driver.iter_count if iterations is None else iterations,
        success=False,
        exit_status=f"interrupted (Ctrl-C) {when}",
    )
    write_run_stats(known, run_stats_path(case_file), peak_memory_mb=process_peak_memory_mb())


def _write_sensitivities(prob, vehicle, case_file, log):
    """Write the post-optimal sensitivities of a gross-mass optimum beside its case file."""
    path = sensitivities_path(case_file)
    try:
        post_optimal_sensitivities(prob, vehicle).to_json(path)
    except om.AnalysisError as err:  # the optimum is recorded all the same
        log(f"post-optimal sensitivities not written: the model failed at the optimum: {err}")
        return
    log(f"post-optimal sensitivities: {path}")


def perturbed_start_case(path, fraction, seed, vehicle=None):
    """
    Write a start case with every design variable of the initial design perturbed at random.

    Each scalar x of the vehicle's initial design becomes x (1 + u), u uniform in
    [-fraction, fraction] (seeded), clipped to its bounds; the case is the problem case
    ``'final'`` of ``path``, which :func:`run_sequence` and :func:`solve_stage` take as
    ``start_case`` (``run_scripts/benchmark_sequence.py --perturb 0.02`` runs the sequence from
    such a start).

    Parameters
    ----------
    path : str
        The case file to write.
    fraction : float
        Largest relative perturbation (0.02 for +-2 %).
    seed : int
        Seed of the random numbers (the same seed, the same start).
    vehicle : Vehicle, path or None

    Returns
    -------
    str
        ``path``.
    """
    if not 0.0 <= fraction < 1.0:
        raise ValueError(f"'fraction' = {fraction!r} is out of range: must be in [0, 1)")
    if vehicle is None or isinstance(vehicle, (str, os.PathLike)):
        vehicle = load_vehicle(vehicle)
    prob = build_analysis_problem(vehicle, recorder_path=path, name="perturbed_start")
    rng = np.random.default_rng(seed)
    for name, dv in vehicle.design_variables.items():
        units = openmdao_units(dv.units)
        value = np.asarray(prob.get_val(name, units=units), dtype=float)
        value = value * (1.0 + rng.uniform(-fraction, fraction, value.shape))
        lower = np.reshape(dv.lower_array, value.shape)
        upper = np.reshape(dv.upper_array, value.shape)
        prob.set_val(name, np.clip(value, lower, upper), units=units)
    prob.run_model()
    prob.record("final")
    prob.cleanup()
    return path


def solve_baseline(
    case_file,
    vehicle=None,
    start_case=None,
    static_margin=True,
    alphas=None,
    optimizer=None,
    driver_settings=None,
    trim_first=True,
    log=print,
    progress=False,
    comm=None,
    trim_processes=1,
):
    """
    Solve the baseline design by continuation in the penalty weight alpha.

    The baseline design is that of paper Sec. II.F, eq. 8-9. Each alpha is one :func:`solve_stage`
    of problem 'baseline', started (and rescaled) from the previous one's final case; the first from
    ``start_case``, best the full problem's optimum (the baseline for alpha -> 0). The intermediate
    case files are ``<stem>_alpha<a>.sql`` beside ``case_file``, which holds the last alpha's run.

    Parameters
    ----------
    case_file : str
        Case file of the final (largest alpha) run.
    vehicle : Vehicle, path or None
    start_case : str or None
        Case file whose final case starts the first alpha (None: the vehicle's initial design).
    static_margin : bool
    alphas : sequence of float or None
        Increasing penalty weights; the last is the baseline's (paper: 100). None: the
        baseline stage's ``continuation`` (:mod:`lpc_mdo.study_plan`).
    optimizer, driver_settings, trim_first, log, progress, comm, trim_processes
        As :func:`solve_stage`.

    Returns
    -------
    StageResult
        Of the last alpha; ``extra['continuation']`` lists every alpha's StageResult, and
        ``success`` requires all of them to succeed.
    """
    spec = study_plan.stage("baseline")
    alphas = [float(a) for a in (spec.continuation if alphas is None else alphas)]
    if not alphas or any(a < 0.0 for a in alphas) or any(np.diff(alphas) <= 0.0):
        raise ValueError(f"alphas = {alphas}; allowed: increasing values >= 0")
    stem, ext = os.path.splitext(os.path.abspath(case_file))
    previous, stages = start_case, []
    for k, alpha in enumerate(alphas):
        path = case_file if k == len(alphas) - 1 else f"{stem}_alpha{alpha:g}{ext}"
        log(f"baseline: alpha = {alpha:g}")
        stage = solve_stage(
            "baseline",
            path,
            vehicle=vehicle,
            start_case=previous,
            static_margin=static_margin,
            optimizer=optimizer,
            driver_settings=driver_settings,
            rescale=spec.rescales and previous is not None,
            trim_first=trim_first,
            log=log,
            progress=progress,
            comm=comm,
            trim_processes=trim_processes,
            baseline_alpha=alpha,
        )
        stage.extra["alpha"] = alpha
        stages.append(stage)
        previous = stage.case_file
    last = stages[-1]
    last.success = all(s.success for s in stages)
    last.extra["continuation"] = stages
    return last


def solve_stage(
    name,
    case_file,
    vehicle=None,
    start_case=None,
    static_margin=True,
    optimizer=None,
    driver_settings=None,
    rescale=False,
    trim_first=True,
    log=print,
    progress=False,
    comm=None,
    trim_processes=1,
    in_sequence=False,
    **model_options,
):
    """
    One optimization: build problem ``name``, start it from a recorded case, trim, optimize.

    Parameters
    ----------
    name : str
        A stage of :data:`lpc_mdo.study_plan.STAGE_NAMES`.
    case_file : str
        Its case file (driver iterations, the problem cases 'trimmed' and 'final').
    vehicle : Vehicle, path or None
    start_case : str or None
        Case file whose final case gives the starting design (None: the vehicle's initial one).
    static_margin : bool
    optimizer : str or None
        None: the stage's, :func:`lpc_mdo.study_plan.default_optimizer`.
    driver_settings : dict or None
        make_driver settings, over the stage's (:func:`lpc_mdo.problems.build_problem`).
    rescale : bool
        Scale the design variables by their magnitudes in the start case (paper Sec. II.E).
    trim_first : bool
        Trim the problem's conditions before optimizing where the stage table says so (see
        :func:`run_sequence`).
    log : callable
    progress : bool
        Print a progress line per model evaluation (:class:`lpc_mdo.progress.ProgressLine`)
        and, through ``log``, one per trimmed condition (:func:`lpc_mdo.progress.trim_line`).
    comm : MPI communicator or None
        The problem's communicator (MPI.COMM_SELF for one problem per rank).
    trim_processes : int
        Processes that trim the conditions at the same time (``workers`` of
        :func:`lpc_mdo.trim.trim`; the trim does not depend on it).
    in_sequence : bool
        Run the stage with its settings as a step of the warm-start sequence (see
        :func:`lpc_mdo.problems.build_problem`).
    **model_options
        Further LPCGroup options (e.g. ``baseline_alpha``).

    Returns
    -------
    StageResult
        Also written: ``<case file stem>.run_stats.json`` (driver statistics and the process's
        peak memory so far, for the report's Table 9) and, for the full problem,
        ``<case file stem>.sensitivities.json`` (d(W0*)/d(parameter) at the optimum,
        :func:`lpc_mdo.sensitivities.post_optimal_sensitivities`; one adjoint pass).

    Raises
    ------
    KeyboardInterrupt
        On Ctrl-C (also when IPOPT stopped on it), after writing the run statistics known so
        far (``success`` false, ``exit_status`` says when) and, during the optimization, a
        'final' case of the current point; :func:`lpc_mdo.progress.interrupt_message` says
        what the case file holds.
    """
    if vehicle is None or isinstance(vehicle, (str, os.PathLike)):
        vehicle = load_vehicle(vehicle)
    spec = study_plan.stage(name)
    optimizer = optimizer or study_plan.default_optimizer(name)
    # Absolute: OpenMDAO puts a bare file name under the problem's {name}_out folder.
    case_file = os.path.abspath(case_file)
    case = None
    if start_case is not None:
        case, label = start_point(start_case, vehicle)
        if label != "final":
            log(f"{name}: starts from {start_case}, {label}")
    refs = magnitude_refs(case, vehicle) if (rescale and case is not None) else None
    prob = build_problem(
        name,
        vehicle=vehicle,
        static_margin=static_margin,
        optimizer=optimizer,
        recorder_path=case_file,
        design_variable_refs=refs,
        driver_settings=driver_settings,
        comm=comm,
        in_sequence=in_sequence,
        **model_options,
    )
    if progress:
        prob.driver.add_recorder(ProgressLine(name))  # recorders start at final_setup
    if case is not None:
        load_design_variables(prob, case, vehicle)
    trim_seconds, trim_message = 0.0, ""
    start = time.perf_counter()
    if trim_first and spec.trim_first:
        try:
            trimmed = trim(
                prob,
                report=log if progress else None,
                label=name,
                workers=trim_processes,
                least_power=True,
            )
        except KeyboardInterrupt:  # nothing recorded yet: no 'final' case of an untrimmed point
            _write_interrupted_stats(prob, case_file, start, "during the trim")
            prob.cleanup()
            raise
        trim_seconds = time.perf_counter() - start
        trim_message = trimmed.message
        prob.record("trimmed")
        log(f"{name}: trim {trim_seconds:.1f} s: {trimmed.message}")
    start = time.perf_counter()
    try:
        result = prob.run_driver()
        if getattr(prob.driver, "user_stopped", False):  # IPOPT stopped cleanly on Ctrl-C
            raise KeyboardInterrupt
    except KeyboardInterrupt:
        prob.record("final")
        _write_interrupted_stats(prob, case_file, start, "during the optimization")
        prob.cleanup()
        raise
    seconds = time.perf_counter() - start
    prob.record("final")
    write_run_stats(result, run_stats_path(case_file), peak_memory_mb=process_peak_memory_mb())
    if name == "full":
        _write_sensitivities(prob, vehicle, case_file, log)
    stage = StageResult(
        name=name,
        case_file=case_file,
        success=bool(result.success),
        iterations=int(result.iter_count),
        seconds=seconds,
        gross_mass=float(prob.get_val("gross_mass", units="kg")[0]),
        exit_status=str(result.exit_status),
        analysis_errors=len(getattr(prob.driver, "analysis_errors", [])),
        trim_seconds=trim_seconds,
        trim_message=trim_message,
    )
    prob.cleanup()
    log(
        f"{name}: success={stage.success} iterations={stage.iterations} "
        f"{stage.seconds:.1f} s gross mass {stage.gross_mass:.2f} kg"
        + ("" if stage.exit_status == "SUCCESS" else f" ({stage.exit_status})")
    )
    return stage
