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

import textwrap
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Circle, Patch, Polygon
from matplotlib.ticker import MaxNLocator

from lpc_mdo.core.checks import check_choice
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
    "LABELS",
    "axis_label",
    "convergence_history",
    "describe",
    "objective_value",
    "plot_bars",
    "plot_convergence",
    "plot_distribution",
    "plot_per_condition",
    "fin_outline",
    "fuselage_outline",
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


def _title(ax, text):
    """Set the title, wrapped to the width of the figure so that none of it is cut off."""
    width = ax.figure.get_figwidth()
    ax.set_title(textwrap.fill(text, width=max(30, int(8.5 * width))))


def _save(fig, path):
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120)
    return path


#: The one label table of the figures: variable name (the last part of a promoted name, so
#: ``hover.electrical_power`` is ``electrical_power``; or a bound reference such as
#: ``lower:state_of_charge``) -> (words, units to plot in; None keeps the recorded units, ``'-'``
#: marks a dimensionless quantity). A name not listed is shown with its underscores as spaces.
LABELS = {
    "mass_breakdown": ("Mass", "kg"),
    "gross_mass": ("Gross mass", "kg"),
    "battery_mass": ("Battery mass", "kg"),
    "electrical_power": ("Electrical power", "kW"),
    "shaft_power": ("Shaft power", "kW"),
    "lift_figure_of_merit": ("Lift-rotor figure of merit", "-"),
    "figure_of_merit": ("Figure of merit", "-"),
    "top_skin_thickness": ("Top skin thickness", "mm"),
    "bottom_skin_thickness": ("Bottom skin thickness", "mm"),
    "front_spar_thickness": ("Front spar thickness", "mm"),
    "rear_spar_thickness": ("Rear spar thickness", "mm"),
    "von_mises_stress": ("Von Mises stress", "MPa"),
    "state_of_charge": ("Final state of charge", "-"),
    "lower:state_of_charge": ("Required final state of charge", "-"),
    "specific_energy": ("Battery energy density", "W*h/kg"),
    "fuselage_length": ("Fuselage length", "m"),
    "wing_area": ("Wing area", "m**2"),
    "wing_aspect_ratio": ("Wing aspect ratio", "-"),
    "wing_span": ("Wing span", "m"),
    "htail_area": ("Horizontal-tail area", "m**2"),
    "rotor_radius": ("Rotor radius", "m"),
    "static_margin": ("Static margin", "-"),
    "noise": ("A-weighted sound pressure level", "dBA"),
}

# How units are written on an axis.
_UNIT_TEXT = {"W*h/kg": "Wh/kg", "m**2": "m²", "m**3": "m³", "deg": "°"}


def describe(name):
    """
    Return the words and the plotting units of a variable, from :data:`LABELS`.

    Parameters
    ----------
    name : str
        Promoted name, e.g. ``'hover.electrical_power'``, ``'{condition}.electrical_power'`` or
        ``'lower:state_of_charge'``.

    Returns
    -------
    (str, str or None)
        Words (capitalised; the name with spaces for underscores when it is not in the table)
        and the units to plot in (None: the recorded units; ``'-'``: dimensionless).
    """
    name = name.replace("{condition}.", "").replace("{condition}", "")
    for key in (name, name.rsplit(".", 1)[-1]):
        if key in LABELS:
            return LABELS[key]
    words = name.rsplit(".", 1)[-1].replace("lower:", "").replace("upper:", "")
    words = words.replace("_", " ").strip() or name
    return words[0].upper() + words[1:], None


def _plot_units(name, units):
    """Units to read ``name`` in: the caller's, else the label table's (None for '-')."""
    if units is not None:
        return units
    table_units = describe(name)[1]
    return None if table_units == "-" else table_units


def axis_label(name, units=None, cr=None, words=None):
    """
    Return the axis label ``'Words (units)'`` of a variable.

    Parameters
    ----------
    name : str
        Variable name, looked up with :func:`describe`.
    units : str or None
        Units the values are plotted in; None: the label table's, else those recorded for
        ``name`` in ``cr``, else ``'-'``.
    cr : CaseReader or None
        Where the recorded units are looked up.
    words : str or None
        Words to use instead of the table's.

    Returns
    -------
    str
        The label, e.g. ``'Electrical power (kW)'``.
    """
    table_words, table_units = describe(name)
    units = units or table_units
    if units is None and cr is not None:
        units = recorded_units(cr, name.replace("{condition}", ""))
    units = _UNIT_TEXT.get(units, units) if units else "-"
    return f"{words or table_words} ({units})"


def _read(cr, name, units, case=None):
    """Read ``name`` in ``units`` or the table's units; the units used (None: recorded)."""
    plot_units = _plot_units(name, units)
    try:
        return read_value(cr, name, plot_units, case), plot_units
    except ValueError:
        if units is not None:
            raise
        # The table's units do not fit this model's variable: keep the recorded ones.
        return read_value(cr, name, None, case), None


def _label_of(cr, name, units):
    """Axis label with the units actually used to read ``name`` (recorded when None)."""
    if units is None:
        return f"{describe(name)[0]} ({_unit_text(recorded_units(cr, name))})"
    return axis_label(name, units)


def _unit_text(units):
    return _UNIT_TEXT.get(units, units) if units else "-"


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
        Figure title; None: ``'Convergence history'``.

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
            it[d],
            hist["objective"][d],
            "o",
            ms=3,
            color="C0",
            label="Case with derivatives (an optimizer iteration)",
        )
        ax_obj.legend(loc="best", fontsize="small")
    name = hist["objective_name"] or "objective"
    cr = open_reader(source)
    units = objective_metadata(cr).get(name, {}).get("units") or recorded_units(cr, name)
    ax_obj.set_ylabel(f"Objective: {describe(name)[0].lower()} ({_unit_text(units)})")
    ax_con.semilogy(it, np.maximum(hist["max_violation"], _VIOLATION_FLOOR), "-", color="C3")
    ax_con.set_ylabel("Largest constraint\nviolation (relative, -)")
    ax_con.set_xlabel("Driver case (one per model evaluation, -)")
    ax_con.xaxis.set_major_locator(MaxNLocator(integer=True))
    for ax in (ax_obj, ax_con):
        ax.grid(True, alpha=0.3)
    _title(ax_obj, title or "Convergence history")
    return _save(fig, path)


# ------------------------------------------------------------------------------------------------
# Bars


def _grouped_bars(ax, categories, series, ylabel, xlabel=None):
    """series: list of (label, values aligned with categories)."""
    n = max(len(series), 1)
    width = 0.8 / n
    x = np.arange(len(categories))
    missing = False
    for k, (label, values) in enumerate(series):
        pos = x + (k - (n - 1) / 2) * width
        ax.bar(pos, values, width, label=label, color=f"C{k}")
        absent = np.isnan(np.asarray(values, dtype=float))
        if absent.any():  # an empty slot would read as zero: mark it
            ax.plot(pos[absent], np.zeros(absent.sum()), "x", color=f"C{k}", ms=7, mew=1.5)
            missing = True
    if missing:
        ax.plot([], [], "x", color="0.35", ms=7, mew=1.5, label="not computed in that run")
    names = [str(c) for c in categories]
    # Rotate the names when they would not fit side by side (about 7 characters per inch).
    crowded = sum(len(s) + 2 for s in names) > 7 * ax.figure.get_figwidth()
    ax.set_xticks(
        x,
        names,
        rotation=45 if crowded else 0,
        ha="right" if crowded else "center",
        rotation_mode="anchor" if crowded else "default",
    )
    ax.set_ylabel(ylabel)
    if xlabel:
        ax.set_xlabel(xlabel)
    ax.grid(True, axis="y", alpha=0.3)
    if len(series) > 1 or missing:
        ax.legend(fontsize="small")


def plot_bars(
    designs,
    name,
    path,
    labels=None,
    units=None,
    ylabel=None,
    title=None,
    case=None,
    xlabel="Item",
):
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
        Units to plot in; None: those of :data:`LABELS`, else the recorded units.
    ylabel, title : str or None
        Axis label (default: :func:`axis_label`) and figure title (default: the words of
        ``name``).
    case : None, int or str
        Restrict the look-up to this case (see :func:`~lpc_mdo.post.case_data.final_case`).
    xlabel : str or None
        Label of the category axis.

    Returns
    -------
    Path
        The PNG written.
    """
    designs = normalize_designs(designs)
    series, used = [], units
    for label, cr in designs:
        value, used = _read(cr, name, units, case)
        series.append((label, value.ravel()))
    size = series[0][1].size
    if any(v.size != size for _, v in series):
        raise ValueError(f"{name!r} has different sizes in the designs.")
    labels = list(labels) if labels is not None else [str(i) for i in range(size)]
    if len(labels) != size:
        raise ValueError(f"{len(labels)} labels for {size} entries of {name!r}.")
    fig, (ax,) = _figure(figsize=(max(6.4, 0.5 * size * len(series) + 2), 4.0))
    _grouped_bars(ax, labels, series, ylabel or _label_of(designs[0][1], name, used), xlabel=xlabel)
    _title(ax, title or describe(name)[0])
    return _save(fig, path)


def _condition_value(cr, name, units, reduce):
    val = read_value(cr, name, _plot_units(name, units)).ravel()
    if reduce is None:
        if val.size != 1:
            raise ValueError(f"{name!r} has {val.size} entries; give reduce= to combine them.")
        return float(val[0])
    return float(_REDUCE[reduce](val))


def plot_per_condition(
    designs,
    variable,
    conditions,
    path,
    units=None,
    reduce="sum",
    ylabel=None,
    title=None,
    xlabel="Design condition",
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
        Units to plot in; None: those of :data:`LABELS`, else the recorded units.
    reduce : {'sum', 'mean', 'max', 'min'} or None
        How a vector value of one condition becomes one bar (e.g. 'sum' of rotor powers, 'mean'
        figure of merit of the lift rotors); None requires scalars.
    ylabel, title : str or None
        Axis label (default: :func:`axis_label`) and figure title (default: the words of the
        variable, "per design condition").
    xlabel : str or None
        Label of the condition axis.

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
        table = np.array(
            [read_value(cr, variable, _plot_units(variable, units)).ravel() for _, cr in designs]
        )
        if table.shape[1] != len(conditions):
            raise ValueError(
                f"{variable!r} has {table.shape[1]} entries for {len(conditions)} conditions."
            )
        categories = conditions
    series = [(label, table[i]) for i, (label, _) in enumerate(designs)]
    width = min(max(6.4, 0.45 * len(categories) * len(series) + 2), 12.0)
    fig, (ax,) = _figure(figsize=(width, 4.0))
    first = variable.format(condition=categories[0]) if "{condition}" in variable else variable
    _grouped_bars(
        ax,
        categories,
        series,
        ylabel or _label_of(designs[0][1], first, _plot_units(variable, units)),
        xlabel=xlabel,
    )
    _title(ax, title or f"{describe(variable)[0]} per design condition")
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
    limit_label="Limit",
    column_label="column {}",
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
        Units of the arrays and of the abscissa; None: those of :data:`LABELS`, else the
        recorded units.
    limit : float or None
        Draws a horizontal dashed line there (e.g. the allowable stress), in ``units``.
    ylabel, xlabel, title : str or None
        Axis labels (default: :func:`axis_label` of the first array, and of ``x`` or "Index")
        and figure title (default: the words of the first array).
    limit_label : str
        Legend words of the limit line (its value and units are appended).
    column_label : str
        Legend words of column j of a 2-D array, formatted with j + 1.

    Returns
    -------
    Path
        The PNG written.
    """
    designs = normalize_designs(designs)
    names = [names] if isinstance(names, str) else list(names)
    fig, (ax,) = _figure()
    styles = ["-", "--", "-.", ":"]
    markers = [".", "o", "s", "^", "v", "x"]
    used = units
    for k, (label, cr) in enumerate(designs):
        for m, name in enumerate(names):
            y, used = _read(cr, name, units)
            y = y.reshape(y.shape[0], -1)
            if x is None:
                xs = np.arange(y.shape[0])
            else:
                xs = read_value(cr, x, _plot_units(x, x_units)).ravel()
                if xs.size == y.shape[0] + 1:
                    xs = 0.5 * (xs[1:] + xs[:-1])
                elif xs.size != y.shape[0]:
                    raise ValueError(f"{x!r} has {xs.size} entries, {name!r} {y.shape[0]}.")
            for j in range(y.shape[1]):
                parts = [label] if len(designs) > 1 else []
                if len(names) > 1:
                    parts.append(describe(name)[0] if not parts else describe(name)[0].lower())
                if y.shape[1] > 1:
                    words = column_label.format(j + 1)
                    parts.append(words[0].upper() + words[1:] if not parts else words)
                parts = parts or [describe(name)[0]]
                # One design: every line its own colour, style and marker (so that equal
                # lines stay visible); several: the design's colour, the array's line style
                # and the column's marker.
                single = len(designs) == 1
                ax.plot(
                    xs,
                    y[:, j],
                    styles[(m * y.shape[1] + j) % len(styles)] if single else styles[m % 4],
                    color=f"C{m * y.shape[1] + j}" if single else f"C{k}",
                    marker=markers[(m * y.shape[1] + j) % len(markers)]
                    if single
                    else markers[j % 6],
                    ms=4,
                    label=", ".join(parts) if j == 0 or y.shape[1] <= 6 else None,
                )
    cr0 = designs[0][1]
    if limit is not None:
        limit_units = _unit_text(used or recorded_units(cr0, names[0]))
        ax.axhline(limit, color="k", ls="--", lw=1, label=f"{limit_label} {limit:g} {limit_units}")
    ax.set_xlabel(xlabel or (_label_of(cr0, x, _plot_units(x, x_units)) if x else "Index (-)"))
    ax.set_ylabel(ylabel or _label_of(cr0, names[0], used))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    _title(ax, title or describe(names[0])[0])
    return _save(fig, path)


def fuselage_outline(length, max_width, num=41):
    """
    Return the top-view outline of a fuselage of a given length and maximum width.

    The shape is schematic, the dimensions are true: a nose that is an ellipse quadrant over the
    first 20 % of the length, a constant-width cabin to 50 %, and a tail cone that narrows to
    15 % of the width at the tail, so the outline spans x = 0 (nose) to -``length`` (body x
    forward) and y = +-``max_width`` / 2 exactly.

    Parameters
    ----------
    length, max_width : float
        Fuselage length and maximum width (same units).
    num : int
        Points per side.

    Returns
    -------
    numpy.ndarray
        (2 num, 2) closed polygon of (x, y) points, right side nose to tail then left side back.
    """
    s = np.linspace(0.0, 1.0, num)
    nose, cabin, tail = 0.2, 0.5, 0.15
    half = np.where(
        s < nose,
        np.sqrt(np.clip(1.0 - (1.0 - s / nose) ** 2, 0.0, 1.0)),
        np.where(
            s <= cabin, 1.0, 1.0 - (1.0 - tail) * np.sin(0.5 * np.pi * (s - cabin) / (1 - cabin))
        ),
    )
    half = 0.5 * max_width * half
    x = -length * s
    return np.vstack([np.column_stack([x, half]), np.column_stack([x[::-1], -half[::-1]])])


def fin_outline(root_le, surface):
    """
    Return the top-view outline of a vertical tail (a fin in the x-z plane).

    Seen from above the fin is its root section: a thin symmetric section of the surface's
    thickness-to-chord ratio, from the root leading edge to the aftmost trailing edge (root or
    tip; the tip leading edge sits ``height tan(sweep)`` behind the root's).

    Parameters
    ----------
    root_le : array_like
        (x, y, z) of the root leading edge, body frame.
    surface : object
        With ``root_chord``, ``tip_chord``, ``span`` (the fin height), ``sweep`` (leading
        edge, rad) and ``thickness_to_chord``, e.g. :class:`lpc_mdo.vehicle.LiftingSurface`.

    Returns
    -------
    numpy.ndarray
        (4, 2) polygon of (x, y) points.
    """
    x0, y0 = float(root_le[0]), float(root_le[1])
    tip_te = x0 - surface.span * np.tan(surface.sweep) - surface.tip_chord
    x_aft = min(x0 - surface.root_chord, tip_te)
    half = 0.5 * surface.thickness_to_chord * surface.root_chord
    x_max = x0 - 0.3 * surface.root_chord
    return np.array([[x0, y0], [x_max, y0 + half], [x_aft, y0], [x_max, y0 - half]])


def _radius(cr, name, index, units):
    value = read_value(cr, name, units).ravel()
    if index is None:
        return value
    if not -value.size <= index < value.size:
        raise ValueError(f"{name!r} has {value.size} entries; index {index} is out of range.")
    return value[index : index + 1] if index != -1 else value[-1:]


def _legend_handle(artist, color=None):
    """
    Return a legend entry that looks like the part: a patch for filled parts, else a line.

    With ``color`` the entry is drawn in that colour (grey when designs have the colours).
    """
    if isinstance(artist, Line2D):
        return Line2D(
            [],
            [],
            color=color or artist.get_color(),
            lw=artist.get_linewidth(),
            alpha=artist.get_alpha(),
        )
    face, edge = artist.get_facecolor(), artist.get_edgecolor()
    if color is not None:
        face, edge = to_rgba(color, face[3]), to_rgba(color)
    return Patch(fc=face, ec=edge, ls=artist.get_linestyle(), lw=1.0)


def plot_planform(
    designs,
    meshes,
    path,
    rotors=(),
    units="m",
    mirror=False,
    title=None,
    fuselage=None,
    pushers=(),
    vertical_tail=None,
    booms=None,
):
    """
    Plot the top view of several designs to scale (paper Fig. 15).

    Body x (forward) points up the page and body y (right) to the right; both axes have the
    same scale. Each design has its colour; each part its line style (see the legend).

    Reads, from each design:

    - each mesh of ``meshes``, an array (nx, ny, 3) of chordwise x spanwise nodes with the
      leading edge at ``[0, :, :]``, and draws its outline (leading edge, tip, trailing edge,
      root);
    - for each ``rotors`` entry, hub positions (..., 3) and radii (one per hub or one for all):
      rotor disks (thrust axis up) drawn as circles;
    - for each ``pushers`` entry, a hub position (3,) and a radius: a disk whose thrust axis is
      body x, which seen from above is a line across y = hub y +- radius;
    - ``fuselage``: the length (the nose is the origin), drawn with :func:`fuselage_outline`;
    - ``vertical_tail``: the root leading edge, drawn with :func:`fin_outline`;
    - ``booms``: the lift-rotor hub positions; each boom is drawn from its hub to its wing
      junction, junction = hub - offset.

    Parameters
    ----------
    designs : str, os.PathLike, CaseReader, Mapping or Sequence
        One or several labelled case files.
    meshes : Sequence of str
        Promoted names of the surface meshes, e.g. ``('wing_mesh', 'horizontal_tail_mesh')``.
    path : str or os.PathLike
        PNG file to write.
    rotors : Sequence of (str, str)
        ``(hub positions name, radii name)`` pairs of rotors with a vertical thrust axis.
    units : str
        Length units of the plot.
    mirror : bool
        Also draw each outline mirrored about y = 0 (for half-span meshes).
    title : str or None
        Figure title; None: ``'Planform, top view to scale'``.
    fuselage : (str, float) or None
        ``(length name, maximum width in units)``, e.g. ``('fuselage_length', 1.557)``.
    pushers : Sequence of (str, str, int or None)
        ``(hub position name, radii name, index of the radius or None)``, e.g.
        ``('pusher_hub_position', 'rotor_radius', 4)``.
    vertical_tail : (str, object) or None
        ``(root leading edge name, surface)``, the surface as in :func:`fin_outline` (lengths
        in ``units``).
    booms : (str, array_like) or None
        ``(hub positions name, offsets (n, 3) in units)``; offset i is hub i minus its boom's
        wing junction (constant in RotorLayoutComp, so the junction follows the hub).

    Returns
    -------
    Path
        The PNG written.
    """
    designs = normalize_designs(designs)
    fig, (ax,) = _figure(figsize=(7.2, 7.6))
    parts = {}

    def draw(gid, artist, label):
        artist.set_gid(gid)
        parts.setdefault(label, artist)
        return artist

    for k, (_, cr) in enumerate(designs):
        color = f"C{k}"
        if fuselage is not None:
            length_name, max_width = fuselage
            length = float(read_value(cr, length_name, units).ravel()[0])
            outline = fuselage_outline(length, max_width)
            body = Polygon(outline[:, ::-1], closed=True, fc=to_rgba(color, 0.15), ec=color, lw=1.2)
            draw("fuselage", ax.add_patch(body), "Fuselage (length, maximum width)")
        for name in meshes:
            mesh = read_value(cr, name, units)
            if mesh.ndim != 3 or mesh.shape[2] != 3:
                raise ValueError(f"{name!r} has shape {mesh.shape}; a mesh is (nx, ny, 3).")
            outline = np.vstack([mesh[0, :, :2], mesh[-1, ::-1, :2], mesh[:1, 0, :2]])
            for sign in (1.0, -1.0) if mirror else (1.0,):
                (line,) = ax.plot(sign * outline[:, 1], outline[:, 0], "-", color=color, lw=1.6)
                draw("surface", line, "Wing and horizontal tail (VLM meshes)")
        if vertical_tail is not None:
            le_name, surface = vertical_tail
            fin = fin_outline(read_value(cr, le_name, units).ravel(), surface)
            patch = Polygon(fin[:, ::-1], closed=True, fc=color, ec=color, lw=1.2)
            draw("vertical_tail", ax.add_patch(patch), "Vertical tail (root section)")
        if booms is not None:
            hub_name, offsets = booms
            hubs = read_value(cr, hub_name, units).reshape(-1, 3)
            offsets = np.asarray(offsets, dtype=float).reshape(-1, 3)
            if offsets.shape != hubs.shape:
                raise ValueError(
                    f"{hub_name!r} has {len(hubs)} hubs; {len(offsets)} boom offsets given."
                )
            junctions = hubs - offsets
            for hub, junction in zip(hubs, junctions, strict=True):
                (line,) = ax.plot(
                    [hub[1], junction[1]],
                    [hub[0], junction[0]],
                    "-",
                    color=color,
                    lw=3.0,
                    alpha=0.6,
                    solid_capstyle="butt",
                )
                draw("boom", line, "Boom (hub to wing junction)")
        for hub_name, radius_name in rotors:
            hubs = read_value(cr, hub_name, units).reshape(-1, 3)
            radii = np.broadcast_to(read_value(cr, radius_name, units).ravel(), (len(hubs),))
            for (hx, hy, _), r in zip(hubs, radii, strict=True):
                disk = Circle((hy, hx), r, fc=to_rgba(color, 0.12), ec=color, ls="--", lw=1.0)
                draw("lift_rotor_disk", ax.add_patch(disk), "Lift-rotor disk (radius)")
                (hub,) = ax.plot([hy], [hx], "+", color=color, ms=5)
                hub.set_gid("hub")
        for hub_name, radius_name, index in pushers:
            hubs = read_value(cr, hub_name, units).reshape(-1, 3)
            radii = np.broadcast_to(_radius(cr, radius_name, index, units), (len(hubs),))
            for (hx, hy, _), r in zip(hubs, radii, strict=True):
                (line,) = ax.plot(
                    [hy - r, hy + r], [hx, hx], "-", color=color, lw=3.0, solid_capstyle="butt"
                )
                draw("pusher_disk", line, "Pusher disk, edge-on (diameter)")
    grey = "0.35" if len(designs) > 1 else None
    handles = [_legend_handle(artist, grey) for label, artist in parts.items() if label]
    labels = [label for label in parts if label]
    if len(designs) > 1:
        handles += [Line2D([], [], color=f"C{k}", lw=4) for k in range(len(designs))]
        labels += [label for label, _ in designs]
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    ax.set_xlabel(f"Body y, to the right ({units})")
    ax.set_ylabel(f"Body x, forward ({units})")
    ax.grid(True, alpha=0.3)
    if handles:
        ax.legend(handles, labels, fontsize="small", loc="lower right", framealpha=0.9)
    _title(ax, title or "Planform, top view to scale")
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
    xlabel="Parameter (-)",
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
        return y, float(read_value(src, y, _plot_units(y, y_units)).ravel()[0])

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
    yname = yname or "objective"
    if y is None and first is not None:
        y_used = objective_metadata(first).get(yname, {}).get("units")
    else:
        y_used = _plot_units(yname, y_units)
    ax.set_ylabel(ylabel or _label_of(first, yname, y_used))
    ax.grid(True, alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize="small")
    _title(ax, title or f"{describe(yname)[0]} against {xlabel.split(' (')[0].lower()}")
    return _save(fig, path)


def plot_footprint(vehicle, sel, lamax, path, title=None):
    """
    Plot the departure's noise footprint on the ground (docs theory/acoustics 'Noise footprint').

    The ground seen from above, the flight direction to the right of the page (so the right
    side of the track is down): the departure's legs (the hover point and each transition
    leg, named by its condition), each observer coloured by its sound exposure level with its
    SEL and L_Amax written beside it, and, when the observers form a grid of at least three by
    three, filled SEL contours between them.

    Parameters
    ----------
    vehicle : Vehicle
        A vehicle with a ``noise_footprint``: the observers and the path.
    sel, lamax : array, (num_observers,)
        Sound exposure level and maximum level of each observer, dBA.
    path : str or Path
        Image file to write.
    title : str or None
        Figure title.
    """
    from lpc_mdo.vehicle.footprint_path import departure_legs, footprint_observers

    footprint = vehicle.noise_footprint
    observers = footprint_observers(footprint)
    sel, lamax = np.ravel(sel), np.ravel(lamax)
    if sel.size != len(observers) or lamax.size != len(observers):
        raise ValueError(
            f"plot_footprint: {len(observers)} observers in the vehicle's noise_footprint, "
            f"got {sel.size} SEL and {lamax.size} L_Amax values"
        )
    fig, (ax,) = _figure(figsize=(8.0, 4.2))
    x, y = observers[:, 0], observers[:, 1]
    levels = np.linspace(np.floor(sel.min()), np.ceil(sel.max()), 11)
    if len(footprint.track_positions) >= 3 and len(footprint.offsets) >= 3:
        filled = ax.tricontourf(x, y, sel, levels=levels, cmap="viridis", alpha=0.5)
        fig.colorbar(filled, ax=ax, label="sound exposure level SEL [dBA]")
    dots = ax.scatter(x, y, c=sel, cmap="viridis", vmin=levels[0], vmax=levels[-1], s=40,
                      edgecolors="k", zorder=3)  # fmt: skip
    if len(footprint.track_positions) < 3 or len(footprint.offsets) < 3:
        fig.colorbar(dots, ax=ax, label="sound exposure level SEL [dBA]")
    for xi, yi, s, m in zip(x, y, sel, lamax, strict=True):
        ax.annotate(f"{s:.1f}\n{m:.1f}", (xi, yi), textcoords="offset points", xytext=(4, -22),
                    fontsize=7)  # fmt: skip
    names = []
    for leg in departure_legs(vehicle):
        (x0, y0, _), (x1, y1, _) = leg.start, leg.end
        if leg.length == 0.0:
            ax.plot([x0], [y0], marker="*", ms=12, color="C3", zorder=4)
        else:
            ax.plot([x0, x1], [y0, y1], "-", color="C3", lw=2, zorder=2)
            ax.plot([x0], [y0], "|", color="C3", ms=10, zorder=2)
        if leg.condition not in names and leg.length > 0.0:
            names.append(leg.condition)
            ax.annotate(leg.condition.replace("_", " "), (x0, y0), textcoords="offset points",
                        xytext=(3, 6), fontsize=7, color="C3")  # fmt: skip
    ax.set_xlabel("distance along the track from the vertiport [m]")
    ax.set_ylabel("distance to the right of the track [m]")
    ax.margins(0.12)
    ax.invert_yaxis()
    ax.legend(
        handles=[
            Line2D([], [], marker="*", ms=10, color="C3", ls="", label="hover over the vertiport"),
            Line2D([], [], color="C3", lw=2, label="transition legs"),
            Line2D(
                [],
                [],
                marker="o",
                color="k",
                mfc="w",
                ls="",
                label="observer: SEL over L_Amax [dBA]",
            ),  # fmt: skip
        ],
        loc="upper center",
        bbox_to_anchor=(0.5, -0.16),
        ncol=3,
        fontsize=7,
    )
    _title(ax, title or "Departure noise footprint: sound exposure level on the ground")
    return _save(fig, path)
