"""Optimization and model statistics (paper Table 9) from case files and ``run_stats.json``.

Two sources feed the table:

* the case file: driver case count and timestamps, recorded derivative evaluations, the problem
  size (design variables, objectives, constraints from ``problem_metadata``) and the model size
  from the recorded model tree (``problem_metadata['tree']``, written when the recorder's
  ``record_viewer_data`` option is on, the default);
* an optional ``run_stats.json`` sidecar next to the case file with what only the running
  driver knows (wall time, optimizer iterations, model and derivative evaluation times, memory).

``run_stats.json`` format (version 1)
-------------------------------------
A JSON object, written by :func:`write_run_stats` from the ``DriverResult`` that
``prob.run_driver()`` returns::

    {
      "format": "lpc_mdo.run_stats/1",
      "runtime": 3792.09,        # s, wall time of run_driver (DriverResult.runtime)
      "iter_count": 49,          # optimizer iterations (DriverResult.iter_count; IpoptDriver:
                                 #   IPOPT iterations, ScipyOptimizeDriver: scipy's count)
      "model_evals": 120,        # model (forward) evaluations
      "model_time": 847.2,       # s, total time in those evaluations
      "deriv_evals": 50,         # total-derivative evaluations
      "deriv_time": 1242.0,      # s, total time in those evaluations
      "peak_memory_mb": 23142.4, # MB, peak resident memory, or null when not measured
      "success": true,           # optimizer reported success
      "exit_status": "..."       # optimizer's exit message (DriverResult.exit_status)
    }

Any key may be null. Readers ignore unknown keys, so later versions may add some. The file is
found as ``run_stats.json`` in the case file's folder (one run per folder).
"""

import ast
import json
import math
import sys
from collections import Counter
from pathlib import Path

import numpy as np

from lpc_mdo.post.case_data import (
    constraint_metadata,
    design_var_metadata,
    normalize_designs,
    objective_metadata,
    open_reader,
)
from lpc_mdo.post.tables import Table

__all__ = [
    "RUN_STATS_FILENAME",
    "RUN_STATS_FORMAT",
    "RUN_STATS_KEYS",
    "STATISTICS_ROWS",
    "find_run_stats",
    "model_size",
    "process_peak_memory_mb",
    "read_run_stats",
    "run_statistics",
    "statistics_table",
    "write_run_stats",
]

RUN_STATS_FILENAME = "run_stats.json"
RUN_STATS_FORMAT = "lpc_mdo.run_stats/1"
#: Keys of ``run_stats.json`` besides ``format``, with their types.
RUN_STATS_KEYS = {
    "runtime": float,
    "iter_count": int,
    "model_evals": int,
    "model_time": float,
    "deriv_evals": int,
    "deriv_time": float,
    "peak_memory_mb": float,
    "success": bool,
    "exit_status": str,
}

# The automatic IndepVarComp OpenMDAO adds for unconnected inputs is not part of the user's model.
_AUTO_IVC = "_auto_ivc"


# ------------------------------------------------------------------------------------------------
# run_stats.json


def process_peak_memory_mb():
    """
    Peak resident memory of this process so far, in MB (``resource.getrusage``), or None.

    Returns
    -------
    float or None
        None where the ``resource`` module is unavailable (Windows).
    """
    try:  # Unix only
        import resource
    except ImportError:
        return None
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    # Linux reports kilobytes, macOS bytes.
    return peak / (1024.0**2 if sys.platform == "darwin" else 1024.0)


def _coerce(value, kind):
    if value is None:
        return None
    if kind is str:
        return value.decode() if isinstance(value, bytes) else str(value)
    if kind is float:
        value = float(value)
        return value if math.isfinite(value) else None
    return kind(value)


def write_run_stats(driver_result, path, peak_memory_mb=None):
    """
    Write ``run_stats.json`` from an OpenMDAO ``DriverResult``.

    Parameters
    ----------
    driver_result : DriverResult or Mapping
        What ``prob.run_driver()`` returns (attributes ``runtime``, ``iter_count``,
        ``model_evals``, ``model_time``, ``deriv_evals``, ``deriv_time``, ``success``,
        ``exit_status``), or a mapping with those keys; missing ones are written as null.
    path : str or os.PathLike
        Target file, or an existing folder (usually the case file's) to write
        ``run_stats.json`` into.
    peak_memory_mb : float or None
        Peak memory of the run in MB, e.g. :func:`process_peak_memory_mb` right after
        ``run_driver`` in a process that ran only this problem; None writes null.

    Returns
    -------
    Path
        The file written.
    """
    path = Path(path)
    if path.is_dir():
        path = path / RUN_STATS_FILENAME
    get = (
        driver_result.get
        if hasattr(driver_result, "get")
        else lambda key: getattr(driver_result, key, None)
    )
    data = {"format": RUN_STATS_FORMAT}
    for key, kind in RUN_STATS_KEYS.items():
        data[key] = _coerce(peak_memory_mb if key == "peak_memory_mb" else get(key), kind)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    return path


def find_run_stats(case_file):
    """
    Return the path of a case file's run statistics, or None.

    The statistics are ``<stem>.run_stats.json`` beside the case file (one per stage of a
    sequence), else a ``run_stats.json`` in its folder; None when neither exists.

    Parameters
    ----------
    case_file : str, os.PathLike or CaseReader
        The case file (a reader's own file name is used).

    Returns
    -------
    Path or None
        The sidecar path when it exists.
    """
    case_file = Path(getattr(case_file, "_filename", case_file))
    for path in (run_stats_path(case_file), case_file.parent / RUN_STATS_FILENAME):
        if path.is_file():
            return path
    return None


def run_stats_path(case_file):
    """Return the run-statistics sidecar of a case file: ``<stem>.run_stats.json``."""
    return Path(case_file).with_suffix(".run_stats.json")


def read_run_stats(path):
    """
    Read a ``run_stats.json`` (or the one next to a case file).

    Parameters
    ----------
    path : str or os.PathLike or CaseReader
        The JSON file, or a case file / reader whose folder holds it.

    Returns
    -------
    dict or None
        Every key of :data:`RUN_STATS_KEYS` (None where absent); None when no file exists.
    """
    path = Path(getattr(path, "_filename", path))
    if path.suffix != ".json":
        path = find_run_stats(path)
        if path is None:
            return None
    data = json.loads(Path(path).read_text(encoding="utf-8"))
    return {key: _coerce(data.get(key), kind) for key, kind in RUN_STATS_KEYS.items()}


# ------------------------------------------------------------------------------------------------
# Model size


def _shape_size(shape):
    try:
        return int(np.prod(ast.literal_eval(shape))) if shape not in (None, "None") else 1
    except (ValueError, SyntaxError):
        return 1


def model_size(source):
    """
    Count the model's systems and variables from the recorded model tree.

    Reads ``problem_metadata['tree']`` (the N2 viewer data). Without it (recorder option
    ``record_viewer_data=False``) the counts come from ``problem_metadata['abs2prom']`` and the
    component types are unknown (None). OpenMDAO's automatic ``_auto_ivc`` component and its
    outputs are not counted, so the counts match ``model.list_outputs()``/``list_inputs()``.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.

    Returns
    -------
    dict
        ``components``, ``groups`` (below the root), ``implicit_components``,
        ``explicit_components`` (explicit, ExecComp, IndepVarComp and meta-model components),
        ``inputs``, ``outputs``, ``output_size`` (scalar entries of all outputs),
        ``implicit_outputs`` and ``implicit_output_size`` (state variables),
        ``component_classes`` (Counter of component class paths).
    """
    md = open_reader(source).problem_metadata
    tree = md.get("tree")
    if not tree:
        abs2prom = md["abs2prom"]
        outputs = [n for n in abs2prom["output"] if not n.startswith(_AUTO_IVC + ".")]
        comps = {n.rpartition(".")[0] for n in outputs + list(abs2prom["input"])}
        groups = {p for c in comps for p in _parents(c)}
        return dict(
            components=len(comps),
            groups=len(groups),
            implicit_components=None,
            explicit_components=None,
            inputs=len(abs2prom["input"]),
            outputs=len(outputs),
            output_size=None,
            implicit_outputs=None,
            implicit_output_size=None,
            component_classes=Counter(),
        )

    counts = Counter()
    classes = Counter()

    def walk(node, path):
        for child in node.get("children") or []:
            name = f"{path}.{child['name']}" if path else child["name"]
            kind = child.get("subsystem_type")
            if kind == "group":
                counts["groups"] += 1
                walk(child, name)
            elif kind == "component" and name != _AUTO_IVC:
                counts["components"] += 1
                ctype = child.get("component_type")
                counts["implicit_components" if ctype == "implicit" else "explicit_components"] += 1
                classes[child.get("class")] += 1
                for var in child.get("children") or []:
                    size = _shape_size(var.get("shape"))
                    if var.get("type") == "input":
                        counts["inputs"] += 1
                    elif var.get("type") == "output":
                        counts["outputs"] += 1
                        counts["output_size"] += size
                        if var.get("implicit"):
                            counts["implicit_outputs"] += 1
                            counts["implicit_output_size"] += size

    walk(tree, "")
    keys = (
        "components",
        "groups",
        "implicit_components",
        "explicit_components",
        "inputs",
        "outputs",
        "output_size",
        "implicit_outputs",
        "implicit_output_size",
    )
    return {**{k: counts[k] for k in keys}, "component_classes": classes}


def _parents(path):
    parts = path.split(".")[:-1]
    return [".".join(parts[:i]) for i in range(1, len(parts) + 1)]


# ------------------------------------------------------------------------------------------------
# Run statistics


def run_statistics(source, run_stats="auto"):
    """
    Collect the statistics of one optimization run.

    Reads the driver cases (count, timestamps, which carry derivatives), the problem metadata
    (design variables, objectives, constraints, model tree) and the run's ``run_stats.json``.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    run_stats : 'auto', dict, str, os.PathLike or None
        ``'auto'`` reads ``run_stats.json`` next to the case file when present; a dict is used
        as is (keys of :data:`RUN_STATS_KEYS`); a path is read; None ignores run statistics.

    Returns
    -------
    dict
        Keys: ``wall_time`` (s; ``run_stats`` runtime, else the span of the driver-case
        timestamps), ``wall_time_source`` (``'run_stats.json'``, ``'case timestamps'`` or
        None), ``driver_cases``, ``derivative_cases`` (driver cases with recorded derivatives),
        ``iter_count``, ``model_evals``, ``deriv_evals``, ``mean_model_time``,
        ``mean_deriv_time`` (s per evaluation), ``peak_memory_mb``, ``success``,
        ``exit_status``, ``design_vars``/``design_var_size``, ``objectives``,
        ``constraints``/``constraint_size``, and every key of :func:`model_size`.
    """
    cr = open_reader(source)
    if isinstance(run_stats, str) and run_stats == "auto":
        stats = read_run_stats(cr)
    elif run_stats is None or isinstance(run_stats, dict):
        stats = run_stats
    else:
        stats = read_run_stats(run_stats)
    stats = stats or {}

    ids = (
        cr.list_cases("driver", recurse=False, out_stream=None)
        if "driver" in cr.list_sources(out_stream=None)
        else []
    )
    cases = [cr.get_case(i) for i in ids]
    deriv_cases = sum(1 for c in cases if c.derivatives is not None)

    wall, wall_source = stats.get("runtime"), "run_stats.json"
    if wall is None and len(cases) > 1:
        wall, wall_source = cases[-1].timestamp - cases[0].timestamp, "case timestamps"
    elif wall is None:
        wall_source = None

    def mean(total, count):
        t, n = stats.get(total), stats.get(count)
        return t / n if t is not None and n else None

    dvs, cons = design_var_metadata(cr), constraint_metadata(cr)
    out = dict(
        wall_time=wall,
        wall_time_source=wall_source,
        driver_cases=len(cases),
        derivative_cases=deriv_cases,
        iter_count=stats.get("iter_count"),
        model_evals=stats.get("model_evals"),
        deriv_evals=stats.get("deriv_evals"),
        mean_model_time=mean("model_time", "model_evals"),
        mean_deriv_time=mean("deriv_time", "deriv_evals"),
        peak_memory_mb=stats.get("peak_memory_mb"),
        success=stats.get("success"),
        exit_status=stats.get("exit_status"),
        design_vars=len(dvs),
        design_var_size=sum(m["size"] for m in dvs.values()),
        objectives=len(objective_metadata(cr)),
        constraints=len(cons),
        constraint_size=sum(m["size"] for m in cons.values()),
    )
    out.update(model_size(cr))
    return out


#: Rows of the statistics table: (key of run_statistics, label).
STATISTICS_ROWS = (
    ("wall_time", "Optimization wall time (s)"),
    ("wall_time_source", "Wall time source"),
    ("iter_count", "Optimizer iterations"),
    ("driver_cases", "Driver cases recorded (model evaluations)"),
    ("derivative_cases", "Driver cases with recorded derivatives"),
    ("model_evals", "Model evaluations"),
    ("deriv_evals", "Derivative evaluations"),
    ("mean_model_time", "Mean forward run time (s)"),
    ("mean_deriv_time", "Mean derivative time (s)"),
    ("peak_memory_mb", "Peak memory (MB)"),
    ("success", "Optimizer success"),
    ("exit_status", "Exit status"),
    ("design_var_size", "Design variables (scalars)"),
    ("design_vars", "Design variables (named)"),
    ("constraint_size", "Constraints (scalars)"),
    ("constraints", "Constraints (named)"),
    ("components", "Components"),
    ("implicit_components", "Implicit components"),
    ("explicit_components", "Explicit components"),
    ("groups", "Groups"),
    ("inputs", "Input variables"),
    ("outputs", "Output variables"),
    ("output_size", "Output scalars"),
    ("implicit_outputs", "Implicit outputs (states)"),
    ("implicit_output_size", "Implicit output scalars"),
)


def statistics_table(runs, run_stats="auto"):
    """
    Statistics table like paper Table 9: one row per metric, one column per run.

    Reads what :func:`run_statistics` reads for each run.

    Parameters
    ----------
    runs : str, os.PathLike, CaseReader, Mapping or Sequence
        One case file, or labelled case files as accepted by
        :func:`~lpc_mdo.post.case_data.normalize_designs`.
    run_stats : 'auto' or None
        ``'auto'`` uses each run's ``run_stats.json`` when present; None ignores them.

    Returns
    -------
    Table
        Columns ``metric`` and the run labels; metrics no run knows are left out.
    """
    runs = normalize_designs(runs)
    stats = [run_statistics(cr, run_stats) for _, cr in runs]
    rows = [
        [label] + [s[key] for s in stats]
        for key, label in STATISTICS_ROWS
        if any(s[key] is not None for s in stats)
    ]
    notes = [
        "Model counts exclude OpenMDAO's automatic _auto_ivc component.",
        "Iterations, evaluation counts and times come from run_stats.json when present.",
    ]
    return Table(["metric"] + [label for label, _ in runs], rows, "Optimization statistics", notes)
