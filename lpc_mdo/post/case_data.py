"""Reading recorder (SQLite case) files: cases, recorded values, bounds, units and metadata.

Everything here reads case files only, through ``om.CaseReader``; no live model is needed. The
functions work for any OpenMDAO problem whose driver (and, optionally, problem) was recorded:

* the driver cases give the design variables, objectives and constraints of every evaluation
  (``record_desvars``/``record_objectives``/``record_constraints``, on by default);
* ``prob.record('final')`` with ``includes=['*']`` gives every output of the final design;
* ``cr.problem_metadata['variables']`` gives the bounds, units and scaling the problem declared
  for each design variable, objective and constraint.

These are the case-access helpers every ``lpc_mdo.post`` module shares (:func:`open_reader`,
:func:`final_case`, :func:`read_value`, :func:`constraint_metadata` ...); the tables built from
them are in :mod:`lpc_mdo.post.tables`.
"""

from collections.abc import Mapping
from dataclasses import dataclass
from os import PathLike
from pathlib import Path

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_choice

__all__ = [
    "MissingVariableError",
    "Quantity",
    "constraint_metadata",
    "design_var_metadata",
    "driver_cases",
    "final_case",
    "last_case",
    "normalize_designs",
    "objective_metadata",
    "open_reader",
    "read_value",
    "recorded_bound",
    "recorded_units",
    "source_case_ids",
]

# Recorded bounds at or beyond this magnitude mean "no bound" (OpenMDAO stores +-1e30).
_INF_BOUND = 1e29


class MissingVariableError(KeyError):
    """A variable (or bound) that the case file does not hold."""

    def __str__(self):
        # KeyError quotes its message; print it plainly.
        return str(self.args[0]) if self.args else ""


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


def source_case_ids(cr, source):
    """
    Return the ids of the cases one recording source holds, in recording order.

    Parameters
    ----------
    cr : CaseReader
        Open case reader.
    source : str
        ``'driver'``, ``'problem'`` or a system/solver source name.

    Returns
    -------
    list of str
        Case ids; empty when that source recorded nothing.
    """
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
    cases = [cr.get_case(i) for i in source_case_ids(cr, "driver")]
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
    for case_id in reversed(source_case_ids(cr, kind)):
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
        ids = source_case_ids(cr, "driver")
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
    return {
        name: meta
        for name, meta in _metadata_vars(open_reader(source)).items()
        if meta.get("type") == kind
    }


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


def recorded_bound(value, size):
    """
    Return a recorded bound as a float array of ``size`` entries, NaN where it is infinite.

    Parameters
    ----------
    value : float, array_like or None
        Bound as recorded in ``problem_metadata`` (scalar or per entry).
    size : int
        Number of entries of the variable.

    Returns
    -------
    numpy.ndarray or None
        None when the bound is absent or infinite everywhere.
    """
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
        value = None if meta is None else recorded_bound(meta.get(kind), meta["size"])
        if value is None:
            raise MissingVariableError(f"No finite {kind} bound is declared for {target!r}.")
        return value
    cases = (
        [final_case(cr, case)]
        if case is not None
        else [c for c in (last_case(cr, "problem"), last_case(cr, "driver")) if c]
    )
    for c in cases:
        try:
            val = c.get_val(name, units=units) if units else c.get_val(name)
        except KeyError:
            continue
        except TypeError as err:  # incompatible units
            raise ValueError(str(err)) from None
        return np.atleast_1d(np.array(val, dtype=float))
    raise MissingVariableError(
        f"Variable {name!r} is not in the recorded cases "
        f"({', '.join(c.name for c in cases) or 'none'})."
    )


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
    abs_name = (
        name if name in outputs else next((a for a, prom in outputs.items() if prom == name), None)
    )
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
