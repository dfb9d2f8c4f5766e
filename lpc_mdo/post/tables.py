"""Tables from recorder (SQLite case) files: constraints (paper Table 7), design variables and a
design comparison (paper Table 8), written as Markdown and CSV.

Everything here reads case files only, through ``om.CaseReader``; no live model is needed. The
functions work for any OpenMDAO problem whose driver (and, optionally, problem) was recorded:

* the driver cases give the design variables, objectives and constraints of every evaluation
  (``record_desvars``/``record_objectives``/``record_constraints``, on by default);
* ``prob.record('final')`` with ``includes=['*']`` gives every output of the final design;
* ``cr.problem_metadata['variables']`` gives the bounds, units and scaling the problem declared
  for each design variable, objective and constraint.

This module also holds the small case-access helpers the other ``lpc_mdo.post`` modules share
(:func:`open_reader`, :func:`final_case`, :func:`read_value`, :func:`constraint_metadata` ...).

Activity and feasibility tolerance
----------------------------------
An entry g_i of a constraint is compared with its limit(s) in the constraint's own units (the
units given to ``add_constraint``, else the output's units). With the reference magnitude

    r_i = max(|finite limits of entry i|, s)  for a constraint scaled by ref/ref0 or scaler,
          with s = |ref - ref0| (or 1/|scaler|), the magnitude its optimizer's tolerance
          is measured in (a small target, e.g. a prescribed acceleration of 0.017 m/s^2 on
          a row scaled by g, then does not make the band absurdly narrow),
    r_i = max |finite limits of entry i|     for an unscaled one, if that is > 0,
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
from collections.abc import Mapping
from dataclasses import dataclass, field
from os import PathLike
from pathlib import Path

import numpy as np
import openmdao.api as om

from lpc_mdo.checks import check_choice

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
    "final_case",
    "last_case",
    "limit_scale",
    "normalize_designs",
    "objective_metadata",
    "open_reader",
    "read_value",
    "recorded_units",
]

#: Default relative activity/feasibility tolerance (see the module docstring).
DEFAULT_TOL = 1e-4

# OpenMDAO stores an absent design-variable bound as -/+INF_BOUND = 1e30.
_INF_BOUND = 1e29


class MissingVariableError(KeyError):
    """A variable (or bound) that the case file does not hold."""

    def __str__(self):
        # KeyError quotes its message; print it plainly.
        return str(self.args[0]) if self.args else ""


# ------------------------------------------------------------------------------------------------
# Case access


def open_reader(source):
    """
    Return a case reader for a case file, or the reader itself.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Path of an SQLite case file, or an already open ``om.CaseReader``.

    Returns
    -------
    CaseReader
        The reader (opened once; pass it around to avoid re-opening the file).
    """
    if hasattr(source, "problem_metadata") and hasattr(source, "get_case"):
        return source
    path = Path(source)
    if not path.is_file():
        raise FileNotFoundError(f"Case file {str(path)!r} does not exist.")
    return om.CaseReader(str(path))


def _source_ids(cr, source):
    if source not in cr.list_sources(out_stream=None):
        return []
    return cr.list_cases(source, recurse=False, out_stream=None)


def driver_cases(source, include_failed=False):
    """
    Return the driver cases of a case file, in recording order.

    Reads the ``driver`` cases (one per model evaluation the driver recorded) and their
    ``success`` flag: lpc-mdo's drivers record an evaluation that raised ``om.AnalysisError``
    with success = 0, its outputs stale.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    include_failed : bool
        Also return the failed evaluations.

    Returns
    -------
    list of Case
        Empty when the driver was not recorded.
    """
    cr = open_reader(source)
    cases = [cr.get_case(i) for i in _source_ids(cr, "driver")]
    return cases if include_failed else [c for c in cases if c.success]


def last_case(source, kind="driver"):
    """
    Return the last successful case recorded by the driver or by the problem, or None.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    kind : str
        ``'driver'`` (last driver case) or ``'problem'`` (last ``prob.record(...)`` case,
        normally ``'final'``).

    Returns
    -------
    Case or None
        None when that source recorded no case.
    """
    check_choice("kind", kind, ("driver", "problem"))
    cr = open_reader(source)
    for case_id in reversed(_source_ids(cr, kind)):
        case = cr.get_case(case_id)
        if case.success:  # a driver case of a failed evaluation holds stale outputs
            return case
    return None


def final_case(source, case=None):
    """
    Return the case that represents the final design of a run.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    case : None, int, str or Case
        None: the last driver case (for ``IpoptDriver`` the optimum, which it re-evaluates last),
        or the last problem case when the driver recorded nothing; int: that driver case index
        (0 = initial design, -1 = last); str: a case id such as ``'final'``; a Case is
        returned as is.

    Returns
    -------
    Case
        The selected case.

    Raises
    ------
    ValueError
        When the file holds no driver or problem case.
    """
    if hasattr(case, "get_constraints"):
        return case
    cr = open_reader(source)
    if isinstance(case, str):
        return cr.get_case(case)
    if case is not None:
        ids = _source_ids(cr, "driver")
        if not ids:
            raise ValueError("The case file holds no driver cases.")
        return cr.get_case(ids[case])
    found = last_case(cr, "driver") or last_case(cr, "problem")
    if found is None:
        raise ValueError("The case file holds neither driver nor problem cases.")
    return found


def _metadata_vars(cr):
    return {k: v for k, v in cr.problem_metadata["variables"].items() if isinstance(v, dict)}


def design_var_metadata(source):
    """
    Return the recorded metadata of each design variable, by promoted name.

    Reads ``cr.problem_metadata['design_vars']`` (bounds in the design variable's declared
    units, ``units``, ``ref``/``ref0``/``scaler``/``adder``, ``size``, ``source``), or, in a
    file recorded with ``record_viewer_data=False``, the entries of
    ``problem_metadata['variables']`` that are not responses.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.

    Returns
    -------
    dict
        Name -> metadata dict, in declaration order.
    """
    cr = open_reader(source)
    if "design_vars" in cr.problem_metadata:
        return {meta["name"]: meta for meta in cr.problem_metadata["design_vars"].values()}
    return {name: meta for name, meta in _metadata_vars(cr).items() if "type" not in meta}


def _responses(source, kind):
    return {name: meta for name, meta in _metadata_vars(open_reader(source)).items()
            if meta.get("type") == kind}


def constraint_metadata(source):
    """
    Return the recorded metadata of each constraint, by name (alias where one was given).

    Reads ``cr.problem_metadata['variables']`` entries of type ``'con'``: ``lower``, ``upper``,
    ``equals`` (in the constraint's declared units), ``units``, ``ref``/``ref0``/``scaler``,
    ``size``, ``linear``, ``source``.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.

    Returns
    -------
    dict
        Name -> metadata dict, in declaration order.
    """
    return _responses(source, "con")


def objective_metadata(source):
    """
    Return the recorded metadata of each objective, by name.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.

    Returns
    -------
    dict
        Name -> metadata dict (entries of type ``'obj'`` of ``problem_metadata['variables']``).
    """
    return _responses(source, "obj")


def _bound(value, size):
    """Bound as a float array of ``size`` entries, or None when absent/infinite everywhere."""
    if value is None:
        return None
    arr = np.broadcast_to(np.asarray(value, dtype=float).ravel(), (size,)).copy()
    arr[np.abs(arr) >= _INF_BOUND] = np.nan
    return None if np.all(np.isnan(arr)) else arr


def read_value(source, name, units=None, case=None):
    """
    Read a recorded variable (or a declared bound) from a case file.

    Looks the name up in the last problem case (``prob.record('final')``, which holds every
    output when recorded with ``includes=['*']``) and then in the last driver case (design
    variables, objectives and constraints); with ``case`` given, only in that case. A name of
    the form ``'lower:NAME'``, ``'upper:NAME'`` or ``'equals:NAME'`` returns the bound declared
    for constraint or design variable NAME (from ``problem_metadata``, in its declared units),
    e.g. ``'lower:state_of_charge'`` for a sweep over the final-SoC requirement.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    name : str
        Promoted output name (or constraint alias), or a bound reference as above.
    units : str or None
        Units to convert to; None keeps the recorded units (ignored for bounds).
    case : None, int or str
        Restrict the look-up to this case (see :func:`final_case`).

    Returns
    -------
    numpy.ndarray
        The value (a copy), at least 1-D.

    Raises
    ------
    MissingVariableError
        When no searched case holds the name.
    ValueError
        When the variable cannot be expressed in ``units``.
    """
    cr = open_reader(source)
    kind, sep, target = name.partition(":")
    if sep and kind in ("lower", "upper", "equals"):
        meta = {**design_var_metadata(cr), **constraint_metadata(cr)}.get(target)
        value = None if meta is None else _bound(meta.get(kind), meta["size"])
        if value is None:
            raise MissingVariableError(f"No finite {kind} bound is declared for {target!r}.")
        return value
    cases = ([final_case(cr, case)] if case is not None
             else [c for c in (last_case(cr, "problem"), last_case(cr, "driver")) if c])
    for c in cases:
        try:
            val = c.get_val(name, units=units) if units else c.get_val(name)
        except KeyError:
            continue
        except TypeError as err:  # incompatible units
            raise ValueError(str(err)) from None
        return np.atleast_1d(np.array(val, dtype=float))
    raise MissingVariableError(f"Variable {name!r} is not in the recorded cases "
                               f"({', '.join(c.name for c in cases) or 'none'}).")


def recorded_units(source, name):
    """
    Units of a recorded output (those :func:`read_value` returns by default), or None.

    Reads ``problem_metadata['abs2prom']`` (promoted -> absolute name) and the units of that
    output in ``problem_metadata['tree']``; a name that is only a constraint or objective alias
    resolves to the units declared for it.

    Parameters
    ----------
    source : str, os.PathLike or CaseReader
        Case file or reader.
    name : str
        Promoted output name (or absolute name, or response alias).

    Returns
    -------
    str or None
        None for unitless variables, unknown names and files without a model tree.
    """
    md = open_reader(source).problem_metadata
    outputs = md["abs2prom"]["output"]
    abs_name = name if name in outputs else next(
        (a for a, prom in outputs.items() if prom == name), None)
    if abs_name is None:
        meta = md["variables"].get(name)
        return meta.get("units") if isinstance(meta, dict) else None
    node = md.get("tree")
    if not node:
        return None
    for part in abs_name.split("."):
        node = next((c for c in node.get("children") or [] if c.get("name") == part), None)
        if node is None:
            return None
    units = node.get("units")
    return None if units in (None, "None") else units


def normalize_designs(designs):
    """
    Return ``[(label, reader), ...]`` for one case file or several labelled ones.

    Parameters
    ----------
    designs : str, os.PathLike, CaseReader, Mapping or Sequence
        One case file or reader (labelled by its file name), a mapping label -> case file, or a
        sequence of ``(label, case file)`` pairs or of bare case files.

    Returns
    -------
    list of (str, CaseReader)
        Labels and open readers, in the given order.
    """
    if isinstance(designs, (str, PathLike)) or hasattr(designs, "problem_metadata"):
        designs = [designs]
    elif isinstance(designs, Mapping):
        designs = list(designs.items())
    out = []
    for item in designs:
        if isinstance(item, tuple) and len(item) == 2 and isinstance(item[0], str):
            label, src = item
        else:
            src = item
            label = _label_from_path(getattr(src, "_filename", src))
        out.append((label, open_reader(src)))
    return out


def _label_from_path(path):
    path = Path(path)
    label = path.stem
    if label in ("cases", "case", "driver", "recording") and path.parent.name:
        label = path.parent.name.removesuffix("_out")
    return label


@dataclass(frozen=True)
class Quantity:
    """
    A recorded quantity for a table column or a figure: variable name, label, units, index.

    Parameters
    ----------
    name : str
        Promoted name (anything :func:`read_value` accepts).
    label : str or None
        Column or axis label; None uses the name.
    units : str or None
        Units to convert to; None keeps the recorded units.
    index : int or None
        Entry of a vector variable (flat index); None takes the whole value.
    """

    name: str
    label: str | None = None
    units: str | None = None
    index: int | None = None

    @classmethod
    def coerce(cls, item):
        """Make a Quantity from a Quantity, a name or a ``(label, name[, units[, index]])``."""
        if isinstance(item, cls):
            return item
        if isinstance(item, str):
            return cls(item)
        label, name, *rest = item
        return cls(name, label, *rest)

    @property
    def title(self):
        """Label with units, e.g. ``'S_ref wing (m**2)'``."""
        text = self.label or self.name
        return f"{text} ({self.units})" if self.units else text

    def read(self, source, case=None):
        """Read the quantity from a case file (see :func:`read_value`); scalar when indexed."""
        val = read_value(source, self.name, self.units, case)
        return float(val.ravel()[self.index]) if self.index is not None else val


# ------------------------------------------------------------------------------------------------
# Tables


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
                writer.writerow(["" if v is None else (repr(float(v)) if isinstance(
                    v, (float, np.floating)) else v) for v in row])
        return md_path, csv_path


def _scalar_or_range(arr):
    """A bound array as one float when uniform, as 'a..b' text otherwise, or None."""
    if arr is None:
        return None
    finite = arr[~np.isnan(arr)]
    lo, hi = float(np.min(finite)), float(np.max(finite))
    return lo if lo == hi and finite.size == arr.size else f"{lo:.5g}..{hi:.5g}"


def limit_scale(meta, lower=None, upper=None, equals=None, ref=None):
    """
    Reference magnitude r_i of each constraint entry (see the module docstring).

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
        fallback = np.max(np.abs(np.asarray(meta["ref"], float)
                                 - np.asarray(meta.get("ref0") or 0.0, float)))
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
    eq = _bound(meta.get("equals"), size)
    if eq is not None:
        return None, None, eq
    return _bound(meta.get("lower"), size), _bound(meta.get("upper"), size), None


def constraint_rows(source, case=None, tol=DEFAULT_TOL, refs=None):
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

    Returns
    -------
    list of dict
        Per constraint: ``name, units, lower, upper, equals`` (arrays or None), ``values``,
        ``violation``, ``relative_violation``, ``active``, ``violated`` (arrays).
    """
    cr = open_reader(source)
    values = final_case(cr, case).get_constraints()
    refs = refs or {}
    rows = []
    for name, meta in constraint_metadata(cr).items():
        if name not in values:
            continue
        lower, upper, equals = constraint_limits(meta)
        g = np.asarray(values[name], float).ravel()
        scale = limit_scale(meta, lower, upper, equals, refs.get(name))
        violation, active, violated = entry_status(g, lower, upper, equals, scale, tol)
        rows.append(dict(name=name, units=meta.get("units"), lower=lower, upper=upper,
                         equals=equals, values=g, violation=violation,
                         relative_violation=violation / scale, active=active,
                         violated=violated))
    return rows


def _status(active, violated):
    n = active.size
    if violated.any():
        return "violated" if violated.all() else f"violated ({violated.sum()} of {n})"
    if active.all():
        return "active"
    return "inactive" if not active.any() else f"partially active ({active.sum()} of {n})"


def constraint_table(source, case=None, tol=DEFAULT_TOL, refs=None):
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

    Returns
    -------
    Table
        Columns ``constraint, units, lower, upper, equals, size, min, max, % viol., active,
        status``; ``active`` is ``'k/n'`` active entries, ``status`` one of ``active``,
        ``inactive``, ``partially active (k of n)``, ``violated [(k of n)]``.
    """
    rows = []
    for r in constraint_rows(source, case, tol, refs):
        rows.append([r["name"], r["units"] or "", _scalar_or_range(r["lower"]),
                     _scalar_or_range(r["upper"]), _scalar_or_range(r["equals"]),
                     int(r["values"].size), float(r["values"].min()), float(r["values"].max()),
                     100.0 * float(r["relative_violation"].max()),
                     f"{int(r['active'].sum())}/{r['active'].size}",
                     _status(r["active"], r["violated"])])
    notes = [f"Active: within tol*r of a limit; violated: beyond it by more than tol*r "
             f"(tol = {tol:g}; r = max(|limit|, |ref - ref0|) for a scaled constraint, "
             f"else |limit|, else 1"
             + (", or the given reference" if refs else "") + ").",
             "% viol. = 100 * max over entries of violation / r."]
    return Table(["constraint", "units", "lower", "upper", "equals", "size", "min", "max",
                  "% viol.", "active", "status"], rows, "Constraints", notes)


def design_variable_table(source, tol=DEFAULT_TOL, expand=True):
    """
    Design-variable table: initial (first driver case) and final (last driver case) values,
    bounds and an at-bound flag.

    Reads ``case.get_design_vars()`` (declared units) of the first and last driver cases and the
    bounds from ``problem_metadata['design_vars']``. An entry is at a bound when within
    ``tol * (upper - lower)`` of it (``tol * max(|bound|, 1)`` for a one-sided variable).

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
    cases = _source_ids(cr, "driver")
    first = cr.get_case(cases[0]).get_design_vars() if cases else {}
    last = final_case(cr).get_design_vars()
    rows = []
    for name, meta in design_var_metadata(cr).items():
        size = meta["size"]
        lo, up = _bound(meta.get("lower"), size), _bound(meta.get("upper"), size)
        lo_a = np.full(size, np.nan) if lo is None else lo
        up_a = np.full(size, np.nan) if up is None else up
        width = np.where(np.isnan(lo_a) | np.isnan(up_a),
                         np.maximum(np.nan_to_num(np.fmax(np.abs(lo_a), np.abs(up_a))), 1.0),
                         up_a - lo_a)
        x1 = np.asarray(last[name], float).ravel()
        x0 = np.asarray(first[name], float).ravel() if name in first else np.full(size, np.nan)
        at_lo = np.abs(x1 - lo_a) <= tol * width
        at_up = np.abs(x1 - up_a) <= tol * width
        flags = np.where(at_lo, "lower", np.where(at_up, "upper", ""))
        units = meta.get("units") or ""
        if expand:
            for i in range(size):
                label = name if size == 1 else f"{name}[{i}]"
                rows.append([label, units, _nan_none(lo_a[i]), _nan_none(up_a[i]),
                             _nan_none(x0[i]), float(x1[i]), str(flags[i])])
        else:
            flag = ", ".join(f"{n} {k}" for k, n in (("lower", at_lo.sum()),
                                                     ("upper", at_up.sum())) if n)
            rows.append([name, units, size, _scalar_or_range(lo), _scalar_or_range(up),
                         _nan_none(np.nanmin(x0) if name in first else np.nan),
                         _nan_none(np.nanmax(x0) if name in first else np.nan),
                         float(x1.min()), float(x1.max()), flag])
    columns = (["design variable", "units", "lower", "upper", "initial", "final", "at bound"]
               if expand else
               ["design variable", "units", "size", "lower", "upper", "initial min",
                "initial max", "final min", "final max", "at bound"])
    notes = [f"Initial: first driver case; final: last driver case. At bound: within "
             f"tol*(upper - lower) of it (tol = {tol:g})."]
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

