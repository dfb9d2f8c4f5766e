"""Parameter sweeps of the full problem (paper Sec. V.C, Figs. 17-18).

Each point is the full problem for a vehicle with one parameter changed (battery energy density
or the final state-of-charge limit), with or without the static-margin constraint. Points run in
chains: a chain starts from a given case (the warm-start sequence's full-problem result) and
every further point of the chain starts from its neighbour's result. Chains run in parallel:
local processes (``processes``), or MPI ranks (``mpirun -n N lpc-mdo sweep --mpi``; mpi4py).
A point that fails is retried once from the chain's start case with twice the iterations; a
point that still fails is reported as failed in the summary (and the exit status), never
dropped.
"""

import csv
import dataclasses
import os
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass

from lpc_mdo.post.figures import plot_sweep
from lpc_mdo.sweep_parameters import PAPER_SWEEPS, SWEEP_PARAMETERS, reference_value, sweep_vehicle
from lpc_mdo.vehicle import load_vehicle
from lpc_mdo.warm_start import solve_stage


@dataclass
class SweepPoint:
    """One optimization of a sweep."""

    parameter: str
    value: float
    static_margin: bool
    success: bool
    retried: bool
    gross_mass: float
    iterations: int
    seconds: float
    case_file: str
    start_case: str
    exit_status: str


def sweep_chains(values, reference, workers):
    """
    Return ordered chains of sweep values, from the reference outwards.

    Each point is next to the one before it; the chains are split further until there are
    ``workers`` chains or single points.
    """
    values = sorted(set(float(v) for v in values))
    lower = [v for v in values if v <= reference][::-1]
    upper = [v for v in values if v > reference]
    chains = [c for c in (lower, upper) if c]
    while len(chains) < workers and max(len(c) for c in chains) > 1:
        longest = max(chains, key=len)
        chains.remove(longest)
        half = (len(longest) + 1) // 2
        chains += [longest[:half], longest[half:]]
    return chains


def point_case_file(out_dir, parameter, value, static_margin):
    """Return the case file of one sweep point (in ``out_dir``)."""
    tag = "sm" if static_margin else "nosm"
    return os.path.join(out_dir, f"{parameter}_{value:g}_{tag}.sql")


def run_chain(task):
    """Run one chain of sweep points (a picklable task for a worker process or rank)."""
    (
        vehicle_file,
        parameter,
        chain,
        static_margin,
        out_dir,
        start_case,
        driver_settings,
        optimizer,
        problem,
        use_mpi,
    ) = task
    comm = None
    if use_mpi:  # one problem per rank, not one problem spread over the ranks
        from mpi4py import MPI  # optional dependency (lpc-mdo[mpi]), needed only here

        comm = MPI.COMM_SELF
    base = load_vehicle(vehicle_file)
    results, previous = [], start_case
    for value in chain:
        vehicle = sweep_vehicle(base, parameter, value)
        case_file = point_case_file(out_dir, parameter, value, static_margin)
        label = f"{parameter}={value:g} ({'with' if static_margin else 'without'} SM)"
        retry = {**driver_settings, "max_iter": 2 * int(driver_settings.get("max_iter", 200))}
        attempts = [(previous, driver_settings), (start_case, retry)]
        stage, used, retried = None, previous, False
        for k, (start, settings) in enumerate(attempts):
            try:
                stage = solve_stage(
                    problem,
                    case_file,
                    vehicle=vehicle,
                    start_case=start,
                    static_margin=static_margin,
                    optimizer=optimizer,
                    driver_settings=settings,
                    rescale=True,
                    comm=comm,
                    log=lambda msg, label=label: print(f"{label}: {msg}", flush=True),
                )
            except Exception as err:  # a failed point is reported, never dropped
                print(f"{label}: attempt {k + 1} failed: {err}", flush=True)
                stage = None
            used, retried = start, k > 0
            if stage is not None and stage.success:
                break
        results.append(
            SweepPoint(
                parameter=parameter,
                value=value,
                static_margin=static_margin,
                success=bool(stage and stage.success),
                retried=retried,
                gross_mass=stage.gross_mass if stage else float("nan"),
                iterations=stage.iterations if stage else 0,
                seconds=stage.seconds if stage else 0.0,
                case_file=case_file,
                start_case=str(used),
                exit_status=stage.exit_status if stage else "exception",
            )
        )
        if stage is not None and stage.success:
            previous = case_file
    return results


def run_sweep(
    out_dir,
    start_case,
    parameters=PAPER_SWEEPS,
    values=None,
    static_margins=(True, False),
    vehicle=None,
    processes=1,
    mpi=False,
    driver_settings=None,
    optimizer=None,
    problem="full",
):
    """
    Run sweeps of the full problem (module docstring) and write ``sweep_summary.csv``.

    Parameters
    ----------
    out_dir : str
        Folder for one case file per point and the summary.
    start_case : str
        Case file whose final case starts every chain (e.g. the sequence's ``full.sql``).
    parameters : sequence of str
        Keys of :data:`lpc_mdo.sweep_parameters.SWEEP_PARAMETERS`.
    values : dict or None
        parameter -> values; a parameter without values takes the paper's five (an error for
        a parameter the paper did not sweep).
    static_margins : sequence of bool
        With and/or without the static-margin constraint.
    vehicle : str or None
        Vehicle file (None: the reference vehicle); each point changes one parameter of it.
    processes : int
        Local worker processes (ignored with ``mpi``).
    mpi : bool
        Distribute the chains over the ranks of MPI.COMM_WORLD (mpi4py); rank 0 writes the
        summary and returns the points, the other ranks return None.
    driver_settings : dict or None
        make_driver settings (default: 200 iterations).
    optimizer : str or None
        None: :func:`lpc_mdo.study_plan.default_optimizer` of the problem (as ``lpc-mdo
        optimize``: SNOPT if pyoptsparse has it, else SLSQP, for the full problem).
    problem : str
        The problem each point solves (default: the full problem, as in the paper).

    Returns
    -------
    list of SweepPoint or None
        Every point, in chain order (None on MPI ranks other than 0).
    """
    if vehicle is not None and not isinstance(vehicle, (str, os.PathLike)):
        raise TypeError("sweep: vehicle must be a vehicle file path or None (workers reload it)")
    if not os.path.exists(start_case):
        raise FileNotFoundError(f"sweep: start case file {start_case!r} does not exist.")
    base = load_vehicle(vehicle)
    values = values or {}
    settings = {"max_iter": 200, **(driver_settings or {})}
    os.makedirs(out_dir, exist_ok=True)

    comm = None
    if mpi:
        from mpi4py import MPI  # optional dependency (lpc-mdo[mpi]), needed only here

        comm = MPI.COMM_WORLD
    workers = comm.size if comm is not None else max(1, int(processes))
    tasks = []
    for parameter in parameters:
        chosen = values.get(parameter) or SWEEP_PARAMETERS[parameter][2]
        if not chosen:
            raise ValueError(
                f"sweep: parameter {parameter!r} has no default values (the paper did not "
                "sweep it); give its values."
            )
        for value in chosen:
            sweep_vehicle(base, parameter, value)  # validate before any work
        for sm in static_margins:
            for chain in sweep_chains(chosen, reference_value(base, parameter), workers):
                tasks.append(
                    (
                        vehicle,
                        parameter,
                        chain,
                        bool(sm),
                        out_dir,
                        start_case,
                        settings,
                        optimizer,
                        problem,
                        comm is not None,
                    )
                )

    if comm is not None:
        mine = [run_chain(t) for i, t in enumerate(tasks) if i % comm.size == comm.rank]
        gathered = comm.gather(mine, root=0)
        if comm.rank != 0:
            return None
        chunks = [chunk for rank_chunks in gathered for chunk in rank_chunks]
    elif workers == 1:
        chunks = [run_chain(t) for t in tasks]
    else:
        # One BLAS thread per worker: the workers are the parallelism.
        for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
            os.environ.setdefault(var, "1")
        with ProcessPoolExecutor(max_workers=workers) as pool:
            chunks = list(pool.map(run_chain, tasks))
    points = [p for chunk in chunks for p in chunk]
    write_summary(points, os.path.join(out_dir, "sweep_summary.csv"))
    plot_sweeps(points, out_dir)
    return points


def plot_sweeps(points, out_dir):
    """Gross mass against each swept parameter (paper Figs. 17-18), converged points only."""
    paths = []
    for parameter, (description, units, _) in SWEEP_PARAMETERS.items():
        runs = [
            (
                p.case_file,
                p.value,
                "with static margin" if p.static_margin else "without static margin",
            )
            for p in points
            if p.parameter == parameter and p.success
        ]
        if runs:
            unit = "" if units == "-" else f" ({units})"
            paths.append(
                plot_sweep(
                    runs,
                    os.path.join(out_dir, f"sweep_{parameter}.png"),
                    y="gross_mass",
                    y_units="kg",
                    xlabel=f"{description}{unit}",
                    ylabel="gross mass (kg)",
                )
            )
    return paths


def write_summary(points, path):
    """Write the sweep points as CSV (one row per optimization)."""
    fields = [f.name for f in dataclasses.fields(SweepPoint)]
    with open(path, "w", newline="", encoding="utf-8") as fh:
        writer = csv.DictWriter(fh, fieldnames=fields)
        writer.writeheader()
        for p in sorted(points, key=lambda p: (p.parameter, not p.static_margin, p.value)):
            writer.writerow(dataclasses.asdict(p))
    return path
