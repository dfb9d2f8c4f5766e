"""
Tables from recorder (SQLite case) files, written as Markdown and CSV.

:func:`format_constraint_status` prints the constraints of a case as text (``lpc-mdo
analyze``): each with its limit(s), value(s) and status *satisfied* (inactive: a margin beyond
the tolerance band), *active* or *violated* (the bands below).

The tables are the constraints (paper Table 7), the design variables and a design comparison
(paper Table 8).

The values come from case files only, read through :mod:`lpc_mdo.post.case_data`; the
case-access names (:func:`open_reader`, :func:`final_case`, :func:`read_value`,
:class:`Quantity` ...) are re-exported here for the callers that import them from this module.

Activity and feasibility tolerance
----------------------------------
An entry g_i of a constraint is compared with its limit(s) in the constraint's own units (the
units given to ``add_constraint``, else the output's units). With the reference magnitude::

    r_i = max(abs(finite limits of entry i), s)  for a constraint scaled by ref/ref0 or scaler,
          with s = abs(ref - ref0) (or 1/abs(scaler)), the magnitude its optimizer's tolerance
          is measured in (a small target, e.g. a prescribed acceleration of 0.017 m/s^2 on
          a row scaled by g, then does not make the band absurdly narrow),
    r_i = max abs(finite limits of entry i)     for an unscaled one, if that is > 0,
    r_i = 1                                  otherwise,

(or ``refs[name]`` when given), an entry is *violated* when it lies beyond a limit by more than
``tol * r_i``, *active* when it is not violated and lies within ``tol * r_i`` of a limit
(equality entries are active whenever they are not violated), and *inactive* otherwise. The
"% viol." column is ``100 * max_i(violation_i / r_i)``. The default ``tol = 1e-4`` (0.01 %)
is looser than the optimizers' own tolerances (IPOPT ``tol`` 1e-6, SLSQP 1e-6 in scaled space),
so a converged active constraint reads active, and tight enough that a constraint with a real
margin reads inactive. For trim-like equality constraints whose limit is 0, pass a physical
reference, e.g. ``refs={'trim_residual': 1e4}`` (the paper normalizes trim by W0 ~ 1e4 N).
"""

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from lpc_mdo.post.case_data import (
    MissingVariableError,
    Quantity,
    constraint_metadata,
    design_var_metadata,
    driver_cases,
    final_case,
    last_case,
    normalize_designs,
    objective_metadata,
    open_reader,
    read_value,
    recorded_bound,
    recorded_units,
    source_case_ids,
)

__all__ = [
    "DEFAULT_TOL",
    "MissingVariableError",
    "Quantity",
    "Table",
    "constraint_limits",
    "constraint_metadata",
    "constraint_rows",
    "constraint_table",
    "design_table",
    "design_var_metadata",
    "design_variable_table",
    "driver_cases",
    "entry_status",
    "format_constraint_status",
    "final_case",
    "last_case",
    "limit_scale",
    "normalize_designs",
    "objective_metadata",
    "open_reader",
    "read_value",
    "recorded_units",
    "status_word",
]

#: Default relative activity/feasibility tolerance (see the module docstring).
DEFAULT_TOL = 1e-4


@dataclass
class Table:
    """
    A small table with Markdown and CSV writers.

    Attributes
    ----------
    columns : list of str
        Column headers.
    rows : list of list
        Cells: str, int, float, bool or None (None prints empty).
    title : str
        Heading of the Markdown file.
    notes : list of str
        Lines printed under the Markdown table (tolerances, sources, skipped items).
    float_format : str
        Format of floats in Markdown; CSV keeps full precision.
    """

    columns: list
    rows: list = field(default_factory=list)
    title: str = ""
    notes: list = field(default_factory=list)
    float_format: str = "{:.5g}"

    def as_dicts(self):
        """Return the rows as dicts keyed by column."""
        return [dict(zip(self.columns, row, strict=True)) for row in self.rows]

    def _cell(self, value):
        if value is None:
            return ""
        if isinstance(value, (bool, np.bool_)):
            return "yes" if value else "no"
        if isinstance(value, (float, np.floating)):
            return "" if math.isnan(value) else self.float_format.format(value)
        return str(value).replace("|", "\\|")

    def to_markdown(self, heading=True):
        """Return the table as GitHub-flavoured Markdown (title, table, notes)."""
        lines = [f"# {self.title}", ""] if heading and self.title else []
        lines.append("| " + " | ".join(self._cell(c) for c in self.columns) + " |")
        lines.append("|" + "|".join("---" for _ in self.columns) + "|")
        lines += ["| " + " | ".join(self._cell(v) for v in row) + " |" for row in self.rows]
        if self.notes:
            lines += [""] + [f"- {note}" for note in self.notes]
        return "\n".join(lines) + "\n"

    def write(self, out_dir, stem):
        """
        Write ``{stem}.md`` and ``{stem}.csv`` into ``out_dir``.

        Returns
        -------
        tuple of Path
            The Markdown and CSV paths.
        """
        out_dir = Path(out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        md_path, csv_path = out_dir / f"{stem}.md", out_dir / f"{stem}.csv"
        md_path.write_text(self.to_markdown(), encoding="utf-8")
        with open(csv_path, "w", newline="", encoding="utf-8") as fh:
            writer = csv.writer(fh)
            writer.writerow(self.columns)
            for row in self.rows:
                writer.writerow(
                    [
                        ""
                        if v is None
                        else (repr(float(v)) if isinstance(v, (float, np.floating)) else v)
                        for v in row
                    ]
                )
        return md_path, csv_path


def _scalar_or_range(arr):
    """Return a bound array as one float when uniform, as 'a..b' text otherwise, or None."""
    if arr is None:
        return None
    finite = arr[~np.isnan(arr)]
    lo, hi = float(np.min(finite)), float(np.max(finite))
    return lo if lo == hi and finite.size == arr.size else f"{lo:.5g}..{hi:.5g}"


def limit_scale(meta, lower=None, upper=None, equals=None, ref=None):
    """
    Return the reference magnitude r_i of each constraint entry (see the module docstring).

    Parameters
    ----------
    meta : dict
        Recorded constraint metadata (``ref``, ``ref0``, ``scaler``, ``size``).
    lower, upper, equals : numpy.ndarray or None
        Limits per entry (NaN where absent).
    ref : float or None
        Explicit reference magnitude; overrides everything else.

    Returns
    -------
    numpy.ndarray
        r_i > 0 per entry.
    """
    size = meta["size"]
    if ref is not None:
        return np.full(size, abs(float(ref)))
    limits = [np.abs(b) for b in (lower, upper, equals) if b is not None]
    mag = np.nanmax(np.vstack(limits), axis=0) if limits else np.zeros(size)
    mag = np.nan_to_num(mag)
    if meta.get("ref") is not None:
        fallback = np.max(
            np.abs(np.asarray(meta["ref"], float) - np.asarray(meta.get("ref0") or 0.0, float))
        )
    elif meta.get("scaler") is not None:
        fallback = 1.0 / np.min(np.abs(np.asarray(meta["scaler"], float)))
    else:
        fallback = 1.0
    if not fallback > 0.0:
        fallback = 1.0
    if meta.get("ref") is not None or meta.get("scaler") is not None:
        return np.maximum(mag, fallback)
    return np.where(mag > 0.0, mag, fallback)


def entry_status(values, lower=None, upper=None, equals=None, scale=1.0, tol=DEFAULT_TOL):
    """
    Violation and activity of each constraint entry.

    Parameters
    ----------
    values : array_like
        Constraint entries g_i.
    lower, upper, equals : array_like or None
        Limits per entry (NaN or None where absent).
    scale : array_like or float
        Reference magnitude r_i per entry (:func:`limit_scale`).
    tol : float
        Relative tolerance.

    Returns
    -------
    violation : numpy.ndarray
        Amount beyond the limit(s), >= 0, in the constraint's units.
    active : numpy.ndarray of bool
        Entries within ``tol * r_i`` of a limit and not violated (all satisfied equalities).
    violated : numpy.ndarray of bool
        Entries beyond a limit by more than ``tol * r_i``.
    """
    g = np.asarray(values, dtype=float).ravel()
    band = tol * np.broadcast_to(np.asarray(scale, float), g.shape)
    violation = np.zeros_like(g)
    distance = np.full_like(g, np.inf)
    if equals is not None:
        eq = np.broadcast_to(np.asarray(equals, float), g.shape)
        violation = np.abs(g - eq)
        violated = violation > band
        return violation, ~violated, violated
    for bound, sign in ((lower, -1.0), (upper, 1.0)):
        if bound is None:
            continue
        b = np.broadcast_to(np.asarray(bound, float), g.shape)
        has = ~np.isnan(b)
        beyond = np.where(has, sign * (g - b), -np.inf)
        violation = np.maximum(violation, np.maximum(beyond, 0.0))
        distance = np.minimum(distance, np.where(has, np.abs(g - b), np.inf))
    violated = violation > band
    active = ~violated & (distance <= band)
    return violation, active, violated


def constraint_limits(meta):
    """
    Limits of a constraint per entry from its recorded metadata.

    Parameters
    ----------
    meta : dict
        Entry of :func:`constraint_metadata`.

    Returns
    -------
    lower, upper, equals : numpy.ndarray or None
        Arrays of ``meta['size']`` entries (NaN where a vector bound is infinite), None where
        absent; an equality constraint has only ``equals``.
    """
    size = meta["size"]
    eq = recorded_bound(meta.get("equals"), size)
    if eq is not None:
        return None, None, eq
    return recorded_bound(meta.get("lower"), size), recorded_bound(meta.get("upper"), size), None


def constraint_rows(source, case=None, tol=DEFAULT_TOL, refs=None, tols=None):
    """
    Evaluate every constraint of a case: values, limits, violation and activity.

    Reads the constraint values of the selected case (``case.get_constraints()``, in the
    constraint's declared units with its indices applied) and the limits from
    ``problem_metadata``.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    case : None, int, str or Case
        Which case (see :func:`final_case`); default the last driver case.
    tol : float
        Relative activity/feasibility tolerance (module docstring).
    refs : Mapping or None
        Constraint name -> reference magnitude for the violation (e.g. trim -> W0).
    tols : Mapping or None
        Constraint name -> its own relative tolerance instead of ``tol`` (e.g. the trim rows:
        :func:`lpc_mdo.analysis.status_tolerances`).

    Returns
    -------
    list of dict
        Per constraint: ``name, units, lower, upper, equals`` (arrays or None), ``values``,
        ``violation``, ``relative_violation``, ``active``, ``violated`` (arrays), ``tol``.
    """
    cr = open_reader(source)
    chosen = final_case(cr, case)
    values = chosen.get_constraints()
    own_units = {}  # each output's own units, by absolute and promoted name
    for path, meta in chosen.list_outputs(units=True, prom_name=True, out_stream=None):
        own_units[path] = own_units[meta["prom_name"]] = meta["units"]
    refs = refs or {}
    tols = tols or {}
    rows = []
    for name, meta in constraint_metadata(cr).items():
        if name not in values:
            continue
        lower, upper, equals = constraint_limits(meta)
        g = np.asarray(values[name], float).ravel()
        scale = limit_scale(meta, lower, upper, equals, refs.get(name))
        row_tol = tols.get(name, tol)
        violation, active, violated = entry_status(g, lower, upper, equals, scale, row_tol)
        rows.append(
            dict(
                name=name,
                units=meta.get("units")
                or own_units.get(meta.get("source", name))
                or own_units.get(name),
                lower=lower,
                upper=upper,
                equals=equals,
                values=g,
                violation=violation,
                relative_violation=violation / scale,
                active=active,
                violated=violated,
                tol=row_tol,
            )
        )
    return rows


#: What a dimensionless constraint counts in, by the end of its name (first match): the
#: A-weighted level and the footprint's exposure and maximum levels in decibels, Mach numbers,
#: the static margin in mean aerodynamic chords, the state of charge as a fraction of the
#: capacity, other margins and ratios as ratios.
DIMENSIONLESS_UNITS = (
    ("_spl_a", "dBA"),
    ("footprint_sel_max", "dBA"),
    ("footprint_lamax_max", "dBA"),
    ("tip_mach", "Mach"),
    ("static_margin", "MAC"),
    ("state_of_charge", "fraction"),
    ("", "ratio"),
)


def display_units(row):
    """Return the units a constraint row is shown in: its own, or what a ratio counts in."""
    if row["units"]:
        return row["units"]
    return next(label for end, label in DIMENSIONLESS_UNITS if row["name"].endswith(end))


def _limit_text(row):
    """Return the limit(s) of a constraint row as text: ``= a``, ``>= a``, ``a .. b``."""

    def text(arr):
        value = _scalar_or_range(arr)
        return f"{value:.4g}" if isinstance(value, float) else value

    if row["equals"] is not None:
        return f"= {text(row['equals'])}"
    lower = None if row["lower"] is None or np.isnan(row["lower"]).all() else text(row["lower"])
    upper = None if row["upper"] is None or np.isnan(row["upper"]).all() else text(row["upper"])
    if lower is not None and upper is not None:
        return f"{lower} .. {upper}"
    return f">= {lower}" if lower is not None else f"<= {upper}"


def status_word(active, violated):
    """
    Return the status of a constraint from its entries: satisfied, active or violated.

    ``violated`` when an entry is violated (``k of n`` when not all), else ``active`` when an
    entry is active (``k of n``), else ``satisfied`` (every entry with a margin beyond the
    tolerance band; :func:`entry_status`).
    """
    n = active.size
    if violated.any():
        return "violated" if violated.all() else f"violated ({violated.sum()} of {n})"
    if active.any():
        return "active" if active.all() else f"active ({active.sum()} of {n})"
    return "satisfied"


def format_constraint_status(rows):
    """
    Return a text table of :func:`constraint_rows`: constraint, limit(s), value(s), status.

    A vector constraint prints the range of its entries; the last line counts the statuses.
    """
    width = max([38] + [len(r["name"]) + 2 for r in rows])  # the longest name and 2 spaces
    lines = [
        f"  {'constraint':<{width}}{'units':<9}{'limit':>22}  {'value':>24}  status",
    ]
    counts = {"satisfied": 0, "active": 0, "violated": 0}
    for r in rows:
        g = r["values"]
        value = f"{g[0]:.5g}" if g.size == 1 else f"{g.min():.4g} .. {g.max():.4g}"
        status = status_word(r["active"], r["violated"])
        counts[status.split()[0]] += 1
        lines.append(
            f"  {r['name']:<{width}}{display_units(r):<9}{_limit_text(r):>22}  {value:>24}  "
            f"{status}"
        )
    entries = sum(r["values"].size for r in rows)
    lines.append(
        f"  {len(rows)} constraints ({entries} rows): {counts['satisfied']} satisfied, "
        f"{counts['active']} active, {counts['violated']} violated"
    )
    return "\n".join(lines)


def constraint_summary(rows):
    """
    Return the violated and the active constraints of :func:`constraint_rows`, one line each.

    Each constraint is named with how many of its rows are violated (or active) when not all.
    """
    groups = {"violated": [], "active": []}
    for r in rows:
        status = status_word(r["active"], r["violated"])
        word, _, detail = status.partition(" ")
        if word in groups:
            groups[word].append(f"{r['name']}{' ' + detail if detail else ''}")
    lines = []
    for word, names in groups.items():
        listed = ", ".join(names) if names else "none"
        lines.append(f"  {word} ({len(names)} of {len(rows)} constraints): {listed}")
    return "\n".join(lines)


def _status(active, violated):
    n = active.size
    if violated.any():
        return "violated" if violated.all() else f"violated ({violated.sum()} of {n})"
    if active.all():
        return "active"
    return "inactive" if not active.any() else f"partially active ({active.sum()} of {n})"


def constraint_table(source, case=None, tol=DEFAULT_TOL, refs=None, tols=None):
    """
    Constraint table like paper Table 7: limits, min/max over entries, % violation, activity.

    Reads the constraint values of the final driver case (or ``case``) and the declared limits,
    units and scaling from ``problem_metadata``; see the module docstring for the tolerance.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    case : None, int or str
        Which case (see :func:`final_case`); default the last driver case.
    tol : float
        Relative activity/feasibility tolerance.
    refs : Mapping or None
        Constraint name -> reference magnitude for % violation and the tolerance band.
    tols : Mapping or None
        Constraint name -> its own relative tolerance (see :func:`constraint_rows`).

    Returns
    -------
    Table
        Columns ``constraint, units, lower, upper, equals, size, min, max, % viol., active,
        status``; ``active`` is ``'k/n'`` active entries, ``status`` one of ``active``,
        ``inactive``, ``partially active (k of n)``, ``violated [(k of n)]``.
    """
    rows = []
    for r in constraint_rows(source, case, tol, refs, tols):
        rows.append(
            [
                r["name"],
                r["units"] or "",
                _scalar_or_range(r["lower"]),
                _scalar_or_range(r["upper"]),
                _scalar_or_range(r["equals"]),
                int(r["values"].size),
                float(r["values"].min()),
                float(r["values"].max()),
                100.0 * float(r["relative_violation"].max()),
                f"{int(r['active'].sum())}/{r['active'].size}",
                _status(r["active"], r["violated"]),
            ]
        )
    notes = [
        f"Active: within tol*r of a limit; violated: beyond it by more than tol*r "
        f"(tol = {tol:g}; r = max(|limit|, |ref - ref0|) for a scaled constraint, "
        f"else |limit|, else 1" + (", or the given reference" if refs else "") + ").",
        "% viol. = 100 * max over entries of violation / r.",
    ]
    if tols:
        own = sorted({float(t) for t in tols.values()})
        notes.append(
            f"{len(tols)} constraints use their own tol ({', '.join(f'{t:g}' for t in own)}; "
            "the trim rows: 0.1 % of the weight, lpc_mdo.analysis.TRIM_TOLERANCE)."
        )
    return Table(
        [
            "constraint",
            "units",
            "lower",
            "upper",
            "equals",
            "size",
            "min",
            "max",
            "% viol.",
            "active",
            "status",
        ],
        rows,
        "Constraints",
        notes,
    )


def design_variable_table(source, tol=DEFAULT_TOL, expand=True):
    """
    Design-variable table: initial and final values, bounds and an at-bound flag.

    The initial values are those of the first driver case, the final ones of the last.

    Reads ``case.get_design_vars()`` (declared units) of the first and last driver cases and the
    bounds from ``problem_metadata['design_vars']``. An entry is at a bound when within
    ``tol * (upper - lower)`` of it (``tol * max(abs(bound), 1)`` for a one-sided variable).

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    tol : float
        Relative at-bound tolerance.
    expand : bool
        True: one row per entry (``z[0]``, ``z[1]``, ...). False: one row per design variable,
        with the min and max of its entries and the count at each bound.

    Returns
    -------
    Table
        Columns ``design variable, units, lower, upper, initial, final, at bound`` (expanded),
        or ``design variable, units, size, lower, upper, initial min, initial max, final min,
        final max, at bound``.
    """
    cr = open_reader(source)
    cases = source_case_ids(cr, "driver")
    first = cr.get_case(cases[0]).get_design_vars() if cases else {}
    last = final_case(cr).get_design_vars()
    rows = []
    for name, meta in design_var_metadata(cr).items():
        size = meta["size"]
        lo, up = recorded_bound(meta.get("lower"), size), recorded_bound(meta.get("upper"), size)
        lo_a = np.full(size, np.nan) if lo is None else lo
        up_a = np.full(size, np.nan) if up is None else up
        width = np.where(
            np.isnan(lo_a) | np.isnan(up_a),
            np.maximum(np.nan_to_num(np.fmax(np.abs(lo_a), np.abs(up_a))), 1.0),
            up_a - lo_a,
        )
        x1 = np.asarray(last[name], float).ravel()
        x0 = np.asarray(first[name], float).ravel() if name in first else np.full(size, np.nan)
        at_lo = np.abs(x1 - lo_a) <= tol * width
        at_up = np.abs(x1 - up_a) <= tol * width
        flags = np.where(at_lo, "lower", np.where(at_up, "upper", ""))
        units = meta.get("units") or ""
        if expand:
            for i in range(size):
                label = name if size == 1 else f"{name}[{i}]"
                rows.append(
                    [
                        label,
                        units,
                        _nan_none(lo_a[i]),
                        _nan_none(up_a[i]),
                        _nan_none(x0[i]),
                        float(x1[i]),
                        str(flags[i]),
                    ]
                )
        else:
            flag = ", ".join(
                f"{n} {k}" for k, n in (("lower", at_lo.sum()), ("upper", at_up.sum())) if n
            )
            rows.append(
                [
                    name,
                    units,
                    size,
                    _scalar_or_range(lo),
                    _scalar_or_range(up),
                    _nan_none(np.nanmin(x0) if name in first else np.nan),
                    _nan_none(np.nanmax(x0) if name in first else np.nan),
                    float(x1.min()),
                    float(x1.max()),
                    flag,
                ]
            )
    columns = (
        ["design variable", "units", "lower", "upper", "initial", "final", "at bound"]
        if expand
        else [
            "design variable",
            "units",
            "size",
            "lower",
            "upper",
            "initial min",
            "initial max",
            "final min",
            "final max",
            "at bound",
        ]
    )
    notes = [
        f"Initial: first driver case; final: last driver case. At bound: within "
        f"tol*(upper - lower) of it (tol = {tol:g})."
    ]
    return Table(columns, rows, "Design variables", notes)


def _nan_none(v):
    v = float(v)
    return None if math.isnan(v) else v


def design_table(designs, quantities, case=None, title="Design comparison"):
    """
    Design comparison table like paper Table 8: one row per design, one column per quantity.

    Reads each quantity with :func:`read_value` (the final problem case, then the last driver
    case) from each design's case file.

    Parameters
    ----------
    designs : str, os.PathLike, Mapping or Sequence
        Designs as accepted by :func:`normalize_designs`, e.g. ``[('Initial', 'init.sql'),
        ('Optimized', 'opt.sql')]``.
    quantities : Sequence
        :class:`Quantity` objects, names, or ``(label, name[, units[, index]])`` tuples. An
        unindexed vector prints as ``a; b; c``.
    case : None, int or str
        Restrict every look-up to this case (see :func:`final_case`).
    title : str
        Table title.

    Returns
    -------
    Table
        Columns ``design`` and the quantity titles. Quantities absent from a design are empty
        cells (listed in the notes); quantities absent from every design are dropped.
    """
    designs = normalize_designs(designs)
    quantities = [Quantity.coerce(q) for q in quantities]
    cells = {}
    for q in quantities:
        for label, cr in designs:
            try:
                val = q.read(cr, case)
            except MissingVariableError:
                val = None
            if isinstance(val, np.ndarray):
                val = float(val[0]) if val.size == 1 else "; ".join(f"{v:.5g}" for v in val)
            cells[q, label] = val
    kept, notes = [], []
    for q in quantities:
        missing = [lb for lb, _ in designs if cells[q, lb] is None]
        if len(missing) == len(designs):
            notes.append(f"{q.name!r} dropped: recorded in no design.")
            continue
        kept.append(q)
        if missing:
            notes.append(f"{q.name!r} is not recorded in: {', '.join(missing)}.")
    rows = [[label] + [cells[q, label] for q in kept] for label, _ in designs]
    titles = []
    for q in kept:
        if q.units is None:
            cr = next(cr for lb, cr in designs if cells[q, lb] is not None)
            q = Quantity(q.name, q.label, recorded_units(cr, q.name), q.index)
        titles.append(q.title)
    return Table(["design"] + titles, rows, title, notes)
