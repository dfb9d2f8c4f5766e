"""
Figures (PNG) from recorder (SQLite case) files.

The figures are the convergence history, bar charts of recorded vectors, values per design
condition, distributions along an index, planform outlines and parameter sweeps (paper
Figs. 13-21).

The figures are drawn on ``matplotlib.figure.Figure`` objects with the Agg canvas, so they need
no display and never touch pyplot's global state or the user's chosen backend. Every function
reads case files only (see :func:`lpc_mdo.post.case_data.read_value` for where a variable is looked
up), writes one PNG and returns its path. Functions that compare designs take ``designs`` as
accepted by :func:`lpc_mdo.post.case_data.normalize_designs`: one case file, a mapping
label -> case file, or a sequence of ``(label, case file)`` pairs.

A variable absent from a case file raises
:class:`~lpc_mdo.post.case_data.MissingVariableError` naming it.
"""

from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Circle

from lpc_mdo.checks import check_choice
from lpc_mdo.post.case_data import (
    MissingVariableError,
    driver_cases,
    final_case,
    normalize_designs,
    objective_metadata,
    open_reader,
    read_value,
    recorded_units,
)
from lpc_mdo.post.tables import constraint_rows

__all__ = [
    "convergence_history",
    "objective_value",
    "plot_bars",
    "plot_convergence",
    "plot_distribution",
    "plot_per_condition",
    "plot_planform",
    "plot_sweep",
    "sweep_points",
]

# Floor of the log axis for zero constraint violation.
_VIOLATION_FLOOR = 1e-16

_REDUCE = {"sum": np.sum, "mean": np.mean, "max": np.max, "min": np.min}


def _figure(nrows=1, figsize=(6.4, 4.0), sharex=False):
    fig = Figure(figsize=figsize, layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(nrows, 1, sharex=sharex, squeeze=False)[:, 0]
    return fig, axes


def _save(fig, path):
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120)
    return path


def _axis_label(text, units, cr=None, name=None):
    """'text (units)'; without units, those recorded for ``name`` in ``cr`` when given."""
    if units is None and cr is not None:
        units = recorded_units(cr, name or text)
    return f"{text} ({units})" if units else text


# ------------------------------------------------------------------------------------------------
# Convergence


def convergence_history(source, refs=None):
    """
    Objective and maximum relative constraint violation of every driver case.

    Reads ``get_objectives()`` and ``get_constraints()`` of each driver case, the constraint
    limits from ``problem_metadata`` and whether the case carries recorded derivatives.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    refs : Mapping or None
        Constraint name -> reference magnitude (see :mod:`lpc_mdo.post.tables`).

    Returns
    -------
    dict
        ``objective_name``; arrays ``iteration`` (driver case index), ``objective`` (declared
        units), ``max_violation`` (max over all constraint entries of violation / r, 0 when
        feasible or without constraints) and ``derivatives`` (bool).
    """
    cr = open_reader(source)
    obj_name = next(iter(objective_metadata(cr)), None)
    objective, violation, derivs = [], [], []
    for case in driver_cases(cr):
        objs = case.get_objectives()
        objective.append(float(np.ravel(objs[obj_name])[0]) if obj_name in objs else np.nan)
        rows = constraint_rows(cr, case, refs=refs)
        violation.append(
            max(
                (float(r["relative_violation"].max()) for r in rows if r["values"].size),
                default=0.0,
            )
        )
        derivs.append(case.derivatives is not None)
    return dict(
        objective_name=obj_name,
        iteration=np.arange(len(objective)),
        objective=np.array(objective),
        max_violation=np.array(violation),
        derivatives=np.array(derivs, dtype=bool),
    )


def plot_convergence(source, path, refs=None, title=None):
    """
    Convergence history: objective and maximum relative constraint violation per driver case.

    Reads what :func:`convergence_history` reads. Cases that carry recorded derivatives
    (``record_derivatives=True``; roughly the major iterations) are marked.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    path : str or os.PathLike
        PNG file to write.
    refs : Mapping or None
        Constraint name -> reference magnitude for the relative violation.
    title : str or None
        Figure title.

    Returns
    -------
    Path
        The PNG written.

    Raises
    ------
    ValueError
        When the file holds no driver cases.
    """
    hist = convergence_history(source, refs)
    it = hist["iteration"]
    if it.size == 0:
        raise ValueError("The case file holds no driver cases to plot.")
    fig, (ax_obj, ax_con) = _figure(2, (6.4, 5.0), sharex=True)
    ax_obj.plot(it, hist["objective"], "-", color="C0")
    d = hist["derivatives"]
    if d.any():
        ax_obj.plot(
            it[d], hist["objective"][d], "o", ms=3, color="C0", label="derivatives evaluated"
        )
        ax_obj.legend(loc="best", fontsize="small")
    ax_obj.set_ylabel(f"objective: {hist['objective_name']}")
    ax_con.semilogy(it, np.maximum(hist["max_violation"], _VIOLATION_FLOOR), "-", color="C3")
    ax_con.set_ylabel("max. relative\nconstraint violation")
    ax_con.set_xlabel("driver case (model evaluation)")
    for ax in (ax_obj, ax_con):
        ax.grid(True, alpha=0.3)
    if title:
        fig.suptitle(title)
    return _save(fig, path)


# ------------------------------------------------------------------------------------------------
# Bars


def _grouped_bars(ax, categories, series, ylabel):
    """series: list of (label, values aligned with categories)."""
    n = max(len(series), 1)
    width = 0.8 / n
    x = np.arange(len(categories))
    for k, (label, values) in enumerate(series):
        ax.bar(x + (k - (n - 1) / 2) * width, values, width, label=label, color=f"C{k}")
    ax.set_xticks(
        x,
        [str(c) for c in categories],
        rotation=45 if len(categories) > 6 else 0,
        ha="right" if len(categories) > 6 else "center",
    )
    ax.set_ylabel(ylabel)
    ax.grid(True, axis="y", alpha=0.3)
    if len(series) > 1:
        ax.legend(fontsize="small")


def plot_bars(designs, name, path, labels=None, units=None, ylabel=None, title=None, case=None):
    """
    Bar chart of a recorded vector, grouped by design (e.g. a mass breakdown, paper Figs. 19-20).

    Reads variable ``name`` from each design (:func:`~lpc_mdo.post.case_data.read_value`).

    Parameters
    ----------
    designs : str, os.PathLike, CaseReader, Mapping or Sequence
        One or several labelled case files.
    name : str
        Promoted name of the vector (flattened).
    path : str or os.PathLike
        PNG file to write.
    labels : Sequence of str or None
        One label per entry; None numbers the entries.
    units : str or None
        Units to plot in; None keeps the recorded units.
    ylabel, title : str or None
        Axis label (default: name and units) and figure title.
    case : None, int or str
        Restrict the look-up to this case (see :func:`~lpc_mdo.post.case_data.final_case`).

    Returns
    -------
    Path
        The PNG written.
    """
    designs = normalize_designs(designs)
    series = [(label, read_value(cr, name, units, case).ravel()) for label, cr in designs]
    size = series[0][1].size
    if any(v.size != size for _, v in series):
        raise ValueError(f"{name!r} has different sizes in the designs.")
    labels = list(labels) if labels is not None else [str(i) for i in range(size)]
    if len(labels) != size:
        raise ValueError(f"{len(labels)} labels for {size} entries of {name!r}.")
    fig, (ax,) = _figure(figsize=(max(6.4, 0.5 * size * len(series) + 2), 4.0))
    _grouped_bars(ax, labels, series, ylabel or _axis_label(name, units, designs[0][1]))
    if title:
        ax.set_title(title)
    return _save(fig, path)


def _condition_value(cr, name, units, reduce):
    val = read_value(cr, name, units).ravel()
    if reduce is None:
        if val.size != 1:
            raise ValueError(f"{name!r} has {val.size} entries; give reduce= to combine them.")
        return float(val[0])
    return float(_REDUCE[reduce](val))


def plot_per_condition(
    designs, variable, conditions, path, units=None, reduce="sum", ylabel=None, title=None
):
    """
    Plot a value per design condition as bars grouped by design (paper Fig. 16).

    Typical values are the power and the figure of merit.

    Reads, for each design, either ``variable.format(condition=c)`` for each condition ``c``
    (a template such as ``'{condition}.electrical_power'``) or one vector ``variable`` with one
    entry per condition.

    Parameters
    ----------
    designs : str, os.PathLike, CaseReader, Mapping or Sequence
        One or several labelled case files.
    variable : str
        Template containing ``{condition}``, or the name of a per-condition vector.
    conditions : Sequence of str
        Condition names (template fill-ins, or the vector's entry labels).
    path : str or os.PathLike
        PNG file to write.
    units : str or None
        Units to plot in.
    reduce : {'sum', 'mean', 'max', 'min'} or None
        How a vector value of one condition becomes one bar (e.g. 'sum' of rotor powers, 'mean'
        figure of merit of the lift rotors); None requires scalars.
    ylabel, title : str or None
        Axis label and figure title.

    Returns
    -------
    Path
        The PNG written. With a template, conditions recorded in no design are left out.

    Raises
    ------
    MissingVariableError
        When no condition (or the vector) is recorded in any design.
    """
    check_choice("reduce", reduce, [*sorted(_REDUCE), None])
    designs = normalize_designs(designs)
    conditions = list(conditions)
    if "{condition}" in variable:
        table = np.full((len(designs), len(conditions)), np.nan)
        for i, (_, cr) in enumerate(designs):
            for j, cond in enumerate(conditions):
                try:
                    table[i, j] = _condition_value(
                        cr, variable.format(condition=cond), units, reduce
                    )
                except MissingVariableError:
                    pass
        keep = ~np.all(np.isnan(table), axis=0)
        if not keep.any():
            raise MissingVariableError(
                f"{variable!r} is recorded for none of the conditions {conditions}."
            )
        categories = [c for c, k in zip(conditions, keep, strict=True) if k]
        table = table[:, keep]
    else:
        table = np.array([read_value(cr, variable, units).ravel() for _, cr in designs])
        if table.shape[1] != len(conditions):
            raise ValueError(
                f"{variable!r} has {table.shape[1]} entries for {len(conditions)} conditions."
            )
        categories = conditions
    series = [(label, table[i]) for i, (label, _) in enumerate(designs)]
    fig, (ax,) = _figure(figsize=(max(6.4, 0.45 * len(categories) * len(series) + 2), 4.0))
    name = variable.replace("{condition}.", "").replace("{condition}", "")
    first = variable.format(condition=categories[0]) if "{condition}" in variable else variable
    _grouped_bars(ax, categories, series, ylabel or _axis_label(name, units, designs[0][1], first))
    if title:
        ax.set_title(title)
    return _save(fig, path)


# ------------------------------------------------------------------------------------------------
# Distributions and planform


def plot_distribution(
    designs,
    names,
    path,
    x=None,
    units=None,
    x_units=None,
    limit=None,
    ylabel=None,
    xlabel=None,
    title=None,
):
    """
    Plot recorded arrays along their index or along another recorded array.

    Typical arrays are skin thickness and stress distributions (paper Figs. 13, 14, 21).

    Reads each of ``names`` (and ``x``) from each design. A 2-D array gives one line per column
    (e.g. several stress recovery points per element).

    Parameters
    ----------
    designs : str, os.PathLike, CaseReader, Mapping or Sequence
        One or several labelled case files.
    names : str or Sequence of str
        Promoted names of the arrays to plot (first axis along the abscissa).
    path : str or os.PathLike
        PNG file to write.
    x : str or None
        Promoted name of the abscissa (e.g. spanwise node positions); None uses the index. With
        one entry more than the arrays (nodes vs elements), element midpoints are used.
    units, x_units : str or None
        Units of the arrays and of the abscissa.
    limit : float or None
        Draws a horizontal dashed line there (e.g. the allowable stress), in ``units``.
    ylabel, xlabel, title : str or None
        Axis labels and figure title.

    Returns
    -------
    Path
        The PNG written.
    """
    designs = normalize_designs(designs)
    names = [names] if isinstance(names, str) else list(names)
    fig, (ax,) = _figure()
    styles = ["-", "--", "-.", ":"]
    for k, (label, cr) in enumerate(designs):
        for m, name in enumerate(names):
            y = read_value(cr, name, units)
            y = y.reshape(y.shape[0], -1)
            if x is None:
                xs = np.arange(y.shape[0])
            else:
                xs = read_value(cr, x, x_units).ravel()
                if xs.size == y.shape[0] + 1:
                    xs = 0.5 * (xs[1:] + xs[:-1])
                elif xs.size != y.shape[0]:
                    raise ValueError(f"{x!r} has {xs.size} entries, {name!r} {y.shape[0]}.")
            for j in range(y.shape[1]):
                parts = [label] if len(designs) > 1 else []
                parts += [name] if len(names) > 1 or len(designs) == 1 else []
                parts += [f"[:, {j}]"] if y.shape[1] > 1 else []
                ax.plot(
                    xs,
                    y[:, j],
                    styles[m % len(styles)],
                    color=f"C{k}",
                    marker=".",
                    label=" ".join(parts) if j == 0 or y.shape[1] <= 5 else None,
                )
    if limit is not None:
        ax.axhline(limit, color="k", ls="--", lw=1, label=f"limit {limit:g}")
    cr0 = designs[0][1]
    ax.set_xlabel(xlabel or (_axis_label(x, x_units, cr0) if x else "index"))
    ax.set_ylabel(
        ylabel or _axis_label(names[0] if len(names) == 1 else "value", units, cr0, names[0])
    )
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    if title:
        ax.set_title(title)
    return _save(fig, path)


def plot_planform(designs, meshes, path, rotors=(), units="m", mirror=False, title=None):
    """
    Plot the top view of several designs' lifting surfaces and rotor disks (paper Fig. 15).

    Reads each mesh, an array (nx, ny, 3) of chordwise x spanwise nodes with coordinates
    (x, y, z) and the leading edge at ``[0, :, :]``, and draws its outline (leading edge, tip,
    trailing edge, root) in the x-y plane with y horizontal and x vertical. Each rotor entry
    reads hub positions (..., 3) and radii (one per hub or one for all) and draws circles.

    Parameters
    ----------
    designs : str, os.PathLike, CaseReader, Mapping or Sequence
        One or several labelled case files.
    meshes : Sequence of str
        Promoted names of the surface meshes, e.g. ``('wing_mesh', 'horizontal_tail_mesh')``.
    path : str or os.PathLike
        PNG file to write.
    rotors : Sequence of (str, str)
        ``(hub positions name, radii name)`` pairs.
    units : str
        Length units of the plot.
    mirror : bool
        Also draw each outline mirrored about y = 0 (for half-span meshes).
    title : str or None
        Figure title.

    Returns
    -------
    Path
        The PNG written.
    """
    designs = normalize_designs(designs)
    fig, (ax,) = _figure(figsize=(6.4, 6.4))
    styles = ["-", "--", "-.", ":"]
    for k, (label, cr) in enumerate(designs):
        style = dict(color=f"C{k}", ls=styles[k % len(styles)], lw=1.4)
        first = True
        for name in meshes:
            mesh = read_value(cr, name, units)
            if mesh.ndim != 3 or mesh.shape[2] != 3:
                raise ValueError(f"{name!r} has shape {mesh.shape}; a mesh is (nx, ny, 3).")
            outline = np.vstack([mesh[0, :, :2], mesh[-1, ::-1, :2], mesh[:1, 0, :2]])
            for sign in (1.0, -1.0) if mirror else (1.0,):
                ax.plot(
                    sign * outline[:, 1], outline[:, 0], label=label if first else None, **style
                )
                first = False
        for hub_name, radius_name in rotors:
            hubs = read_value(cr, hub_name, units).reshape(-1, 3)
            radii = np.broadcast_to(read_value(cr, radius_name, units).ravel(), (len(hubs),))
            for (hx, hy, _), r in zip(hubs, radii, strict=True):
                ax.add_patch(
                    Circle((hy, hx), r, fill=False, lw=0.8, color=style["color"], ls=style["ls"])
                )
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    ax.set_xlabel(f"y ({units})")
    ax.set_ylabel(f"x ({units})")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    if title:
        ax.set_title(title)
    return _save(fig, path)


# ------------------------------------------------------------------------------------------------
# Sweeps


def objective_value(source, case=None):
    """
    Return the (first) objective of a run's final case, in its declared units.

    Reads ``get_objectives()`` of :func:`~lpc_mdo.post.case_data.final_case`.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    case : None, int or str
        Which case (see :func:`~lpc_mdo.post.case_data.final_case`).

    Returns
    -------
    (str, float)
        Objective name and value.
    """
    cr = open_reader(source)
    name = next(iter(objective_metadata(cr)), None)
    if name is None:
        raise MissingVariableError("The problem has no objective.")
    return name, float(np.ravel(final_case(cr, case).get_objectives()[name])[0])


def sweep_points(sources, x, group=None, x_units=None, group_units=None):
    """
    Read sweep parameters from the runs themselves.

    Reads ``x`` (and ``group``) with :func:`~lpc_mdo.post.case_data.read_value` from each case
    file; names such as ``'lower:state_of_charge'`` read a declared bound instead. Runs that
    do not record ``x`` are left out.

    Parameters
    ----------
    sources : Sequence
        Case files or readers (or ``(label, case file)`` pairs).
    x, group : str, str or None
        Parameter names (first entry of each value is used).
    x_units, group_units : str or None
        Units to read them in.

    Returns
    -------
    list of tuple
        ``(reader, x value, group value or None)`` per run that records ``x``.
    """
    points = []
    for _, cr in normalize_designs(sources):
        try:
            xv = float(read_value(cr, x, x_units).ravel()[0])
            gv = None if group is None else float(read_value(cr, group, group_units).ravel()[0])
        except MissingVariableError:
            continue
        points.append((cr, xv, gv))
    return points


def plot_sweep(
    runs,
    path,
    y=None,
    y_units=None,
    xlabel="parameter",
    ylabel=None,
    group_label=None,
    highlight=(),
    title=None,
):
    """
    Plot the objective (or any recorded scalar) against a parameter (paper Figs. 17-18).

    One line per value of a second parameter.

    Reads, from each run's case file, the objective of the final case (or ``y``).

    Parameters
    ----------
    runs : Sequence of tuple
        ``(case file or reader, x)`` or ``(case file or reader, x, group)`` per converged run,
        e.g. from :func:`sweep_points`; a numeric group is labelled ``group_label = value``,
        a string group by itself.
    path : str or os.PathLike
        PNG file to write.
    y : str or None
        Recorded scalar to plot; None plots each run's objective.
    y_units : str or None
        Units of ``y``.
    xlabel, ylabel : str or None
        Axis labels (``ylabel`` defaults to the objective's name).
    group_label : str or None
        Legend prefix of the lines, e.g. ``'static margin'``.
    highlight : Sequence of (str, case file, float)
        Extra points drawn as stars, e.g. ``[('baseline', 'baseline.sql', 400.0)]``.
    title : str or None
        Figure title.

    Returns
    -------
    Path
        The PNG written.
    """

    def value(src):
        if y is None:
            return objective_value(src)
        return y, float(read_value(src, y, y_units).ravel()[0])

    groups, yname, first = {}, y, None
    for run in runs:
        src, xv, gv = (*run, None)[:3]
        src = open_reader(src)
        first = src if first is None else first
        yname, yv = value(src)
        groups.setdefault(gv, []).append((float(xv), yv))
    fig, (ax,) = _figure()

    def order(item):
        gv = item[0]
        return (
            gv is None,
            isinstance(gv, str),
            gv if isinstance(gv, (int, float)) else 0.0,
            str(gv),
        )

    for k, (gv, pts) in enumerate(sorted(groups.items(), key=order)):
        pts = np.array(sorted(pts))
        if gv is None or isinstance(gv, str):
            label = gv
        else:
            label = f"{group_label} = {gv:g}" if group_label else f"{gv:g}"
        ax.plot(pts[:, 0], pts[:, 1], "o-", color=f"C{k}", label=label)
    for k, (label, src, xv) in enumerate(highlight):
        ax.plot([xv], [value(src)[1]], "*", ms=14, color=f"C{len(groups) + k}", label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel or _axis_label(yname or "objective", y_units, first))
    ax.grid(True, alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize="small")
    if title:
        ax.set_title(title)
    return _save(fig, path)
