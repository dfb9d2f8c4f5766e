"""The schema engine of vehicle files: typed fields with units, ranges and file-key suffixes.

Each dataclass field of a vehicle part carries a :class:`_Spec` in its metadata (units, range,
file-key suffix, array shape, allowed strings); :func:`_read_fields` checks a table's keys and
converts every field, raising one :class:`VehicleSpecError` that names the dotted key, the value
and what is allowed. The vehicle parts (:mod:`lpc_mdo.vehicle.parts`) and the design-variable
tables (:mod:`lpc_mdo.vehicle.design_variables`) are read with it.
"""

from __future__ import annotations

import contextvars
import dataclasses
import functools
import math
import os
import typing
import unicodedata
from collections.abc import Mapping
from dataclasses import dataclass, field

from lpc_mdo.core.checks import (
    _fmt,
    _show,
    check_integer,
    check_number,
    check_range,
    cut_text,
    range_text,
)


class VehicleSpecError(ValueError):
    """An invalid vehicle file or dict; the message names the key, the value and what is allowed."""


# ------------------------------------------------------------------------------------------------
# Schema: each dataclass field carries a _Spec in its metadata.


@dataclass(frozen=True)
class _Spec:
    """How a field is read from a vehicle file and checked.

    Ranges (``gt``, ``ge``, ``lt``, ``le``) apply to the file value, before ``scale``.
    """

    units: str = ""  # units of the file value, for messages
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None
    choices: tuple = ()
    suffix: str = ""  # file key = field name + suffix
    scale: float = 1.0  # stored value = file value * scale
    shape: tuple[int, ...] = ()  # arrays of numbers
    unit_vector: bool = False
    count: int | tuple[int, ...] | None = None  # lists of tables: the allowed lengths
    count_note: str = ""
    derived: bool = False  # set by the loader, not read from the file
    polar_file: bool = False  # a string may also name an existing airfoil polar file
    coordinate_file: bool = False  # the string names an airfoil coordinate file (Selig format)
    optional: bool = False  # the key may be absent (the field is then None); see _read_fields


_POLAR_SUFFIXES = (".npz", ".txt", ".dat", ".csv", ".pol")


def _param(units: str = "", **kw) -> typing.Any:
    return field(metadata={"spec": _Spec(units=units, **kw)})


def _angle(**kw) -> typing.Any:
    return _param("deg", suffix="_deg", scale=math.pi / 180.0, **kw)


def _spec(f: dataclasses.Field) -> _Spec:
    return f.metadata.get("spec", _Spec())


# ------------------------------------------------------------------------------------------------
# Generic reading and checking


def _join(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _bounds(spec: _Spec) -> dict:
    """Return the range of a spec as :func:`lpc_mdo.core.checks.check_range` keywords."""
    return dict(
        lower=spec.gt if spec.gt is not None else spec.ge,
        lower_open=spec.gt is not None,
        upper=spec.lt if spec.lt is not None else spec.le,
        upper_open=spec.lt is not None,
    )


def _range_text(spec: _Spec) -> str:
    """``"> 0"``, ``"in [0, 1)"``, ... for the range of a spec; ``""`` if unbounded."""
    return range_text(**_bounds(spec))


def _describe(tp, spec: _Spec) -> str:
    """Short description of what a key must hold, for 'missing key' messages."""
    if dataclasses.is_dataclass(tp):
        return "table"
    if typing.get_origin(tp) is tuple and dataclasses.is_dataclass(typing.get_args(tp)[0]):
        counts = (spec.count,) if isinstance(spec.count, int) else spec.count
        return "list of " + (" or ".join(str(n) for n in counts) + " " if counts else "") + "tables"
    if typing.get_origin(tp) is Mapping:
        return "table of design-variable tables"
    if spec.choices:
        return "one of " + ", ".join(repr(c) for c in spec.choices)
    parts = [spec.units] if spec.units else []
    if spec.shape:
        kind = " x ".join("N" if n is None else str(n) for n in spec.shape) + " numbers"
        parts.insert(0, kind)
    elif tp is int:
        parts.insert(0, "integer")
    elif tp is str:
        parts.insert(0, "string")
    if spec.unit_vector:
        parts.append("unit vector")
    if _range_text(spec):
        parts.append(_range_text(spec))
    return ", ".join(parts) if parts else "number"


@functools.cache
def _hints(cls) -> dict:
    return typing.get_type_hints(cls)


def _check_keys(
    data, allowed: Mapping[str, str], path: str, optional: frozenset = frozenset()
) -> None:
    """Reject a non-table, unknown keys and missing keys; ``allowed`` maps key -> description.

    Keys in ``optional`` may be missing (the cross-field checks say when they are required).
    """
    if not isinstance(data, Mapping):
        what = f"'{path}'" if path else "a vehicle description"
        raise VehicleSpecError(f"{what} must be a table, got {_show(data)}")
    for key in data:
        if key not in allowed:
            names = ", ".join(repr(k) for k in sorted(allowed))
            odd = next((c for c in str(key) if not (c.isascii() and c.isprintable())), None)
            note = (
                f" (it holds the character {odd!r}, U+{ord(odd):04X}, which only looks like "
                "plain text)"
                if odd is not None
                else ""
            )
            if not str(key):
                note = ' (an empty key, "" = ...)'
            elif "." in str(key):  # a quoted key "wing.area" is one key, not a table's key
                note = (
                    f' (one quoted key "{key}" holding a dot; a key of a table is written '
                    "under the table's [header], or unquoted as table.key)"
                )
            shown = cut_text(_join(path, str(key)))
            raise VehicleSpecError(f"unknown key {shown}{note}; allowed keys: {names}")
    for key, description in allowed.items():
        if key not in data and key not in optional:
            raise VehicleSpecError(f"missing key '{_join(path, key)}' ({description})")


def _read_fields(cls, data, path: str, skip: str = "") -> dict:
    """Check the keys of a table and convert every file-backed field of ``cls`` except ``skip``."""
    hints = _hints(cls)
    fields = {f.name + _spec(f).suffix: f for f in dataclasses.fields(cls) if not _spec(f).derived}
    optional = frozenset(k for k, f in fields.items() if _spec(f).optional)
    _check_keys(
        data, {k: _describe(hints[f.name], _spec(f)) for k, f in fields.items()}, path, optional
    )
    return {
        f.name: (
            _convert(hints[f.name], _spec(f), data[key], _join(path, key)) if key in data else None
        )
        for key, f in fields.items()
        if f.name != skip
    }


def _convert(tp, spec: _Spec, value, path: str):
    if dataclasses.is_dataclass(tp):
        return tp(**_read_fields(tp, value, path))
    if typing.get_origin(tp) is tuple:
        item = typing.get_args(tp)[0]
        if dataclasses.is_dataclass(item):
            return _table_list(item, spec, value, path)
        array = _array(value, spec.shape, spec, path)
        if spec.unit_vector and not math.isclose(math.hypot(*array), 1.0, rel_tol=1e-6):
            raise VehicleSpecError(
                f"'{path}' = {value!r} is out of range: must be a unit vector "
                f"(norm 1), got norm {_fmt(math.hypot(*array))}"
            )
        return array
    if tp is float:
        return _number(value, spec, path)
    if tp is int:
        return _integer(value, spec, path)
    return _string(value, spec, path)


def _number(value, spec: _Spec, path: str) -> float:
    bounds = _bounds(spec)
    x = check_number(path, value, units=spec.units or None, error=VehicleSpecError, **bounds)
    return x * spec.scale


def _integer(value, spec: _Spec, path: str) -> int:
    n = check_integer(path, value, error=VehicleSpecError)
    if spec.choices and n not in spec.choices:
        allowed = ", ".join(str(c) for c in spec.choices)
        raise VehicleSpecError(f"'{path}' = {value!r} is not allowed: must be one of {allowed}")
    check_range(path, n, units=spec.units or None, error=VehicleSpecError, **_bounds(spec))
    return n


#: Folder of the vehicle file being read (None for a dict): relative polar paths are looked up
#: there first, then in the working directory.
BASE_DIR: contextvars.ContextVar[str | None] = contextvars.ContextVar("BASE_DIR", default=None)


def _input_file(value: str, path: str, what: str) -> str:
    """Resolve a file named in a vehicle file (a polar or coordinate file); its absolute path.

    A relative path is looked up in the vehicle file's folder, then in the working directory.
    """
    candidate = os.path.expanduser(value)
    if os.path.isabs(candidate):
        places = [candidate]
    else:
        base = BASE_DIR.get()
        places = [os.path.join(base, candidate)] if base is not None else []
        places.append(os.path.join(os.getcwd(), candidate))
    found = next((p for p in places if os.path.isfile(p)), None)
    other = next((p for p in places if os.path.exists(p) and not os.path.isfile(p)), None)
    if found is None and other is not None:
        kind = "a directory" if os.path.isdir(other) else "not a regular file (a pipe or device)"
        raise VehicleSpecError(
            f"'{path}' = {value!r}: '{os.path.abspath(other)}' is {kind}; allowed: a {what}"
        )
    broken = next((p for p in places if not os.path.exists(p) and os.path.islink(p)), None)
    if found is None and broken is not None:
        raise VehicleSpecError(
            f"'{path}' = {value!r}: '{os.path.abspath(broken)}' is a symbolic link that leads "
            f"nowhere (a broken link or a loop); allowed: a {what}"
        )
    if found is None:
        looked = ", ".join(repr(os.path.abspath(p)) for p in places)
        raise VehicleSpecError(f"'{path}' = {value!r}: {what} not found (looked at {looked})")
    return os.path.abspath(found)


def _polar_file(value: str, path: str) -> str:
    """Resolve and load a polar file named in a vehicle file; return its absolute path."""
    from lpc_mdo.components.aero.airfoil import get_polar

    return _read_file(value, path, "polar file", "polar file", get_polar)


def _coordinate_file(value: str, path: str) -> str:
    """Resolve and read an airfoil coordinate file named in a vehicle file; its absolute path."""
    from lpc_mdo.components.aero.airfoil_coordinates import read_coordinates

    what = "coordinate file (Selig format)"
    return _read_file(value, path, what, "coordinate file", read_coordinates)


def _read_file(value: str, path: str, what: str, kind: str, read) -> str:
    """Resolve a file (``what`` it must be) and read it with ``read``; its absolute path.

    Reading at load time makes a malformed file a :class:`VehicleSpecError` naming the key, not
    an error during the run.
    """
    found = _input_file(value, path, what)
    try:
        read(found)
    except (ValueError, OSError) as exc:
        raise VehicleSpecError(f"'{path}' = {value!r}: invalid {kind}: {exc}") from exc
    return found


#: Longest name or keyword (characters) and longest polar-file path in a vehicle file.
_MAX_NAME = 200
_MAX_PATH = 4096


def check_field(cls, name: str, value, key: str) -> float:
    """
    Check a number against the range of field ``name`` of vehicle part ``cls`` (file units).

    The range a vehicle file's ``key`` has (e.g. ``battery.energy_density_wh_per_kg`` in
    Wh/kg), for values that reach a vehicle another way (a sweep); returns the stored value.

    Raises
    ------
    VehicleSpecError
        Naming ``key``, the value and the range.
    """
    spec = _spec(next(f for f in dataclasses.fields(cls) if f.name == name))
    return _number(value, spec, key)


def _string(value, spec: _Spec, path: str) -> str:
    if not isinstance(value, str):
        raise VehicleSpecError(f"'{path}' must be a string, got {_show(value)}")
    control = next((c for c in value if unicodedata.category(c) in ("Cc", "Cf")), None)
    longest = _MAX_PATH if spec.polar_file or spec.coordinate_file else _MAX_NAME
    if control is not None or len(value) > longest:
        why = (
            f"it holds the control character {control!r}"
            if control is not None
            else f"it has {len(value)} characters"
        )
        raise VehicleSpecError(
            f"'{path}' = {cut_text(value)} is not allowed: {why}; allowed: printable text of at "
            f"most {longest} characters"
        )
    if spec.coordinate_file:
        return _coordinate_file(value, path)
    if spec.choices and value not in spec.choices:
        if spec.polar_file and value.lower().endswith(_POLAR_SUFFIXES):
            return _polar_file(value, path)
        allowed = ", ".join(repr(c) for c in spec.choices)
        extra = (
            f", or a polar file ({', '.join(_POLAR_SUFFIXES)}: alpha [deg], cl, cd)"
            if spec.polar_file
            else ""
        )
        raise VehicleSpecError(
            f"'{path}' = {value!r} is not allowed: must be one of {allowed}{extra}"
        )
    return value


def _array(value, shape: tuple[int, ...], spec: _Spec, path: str) -> tuple:
    """Convert a nested list of numbers with ``shape`` to nested tuples of converted floats."""
    if not shape:
        return _number(value, spec, path)
    n = shape[0]  # None: any length of at least one (checked against other keys elsewhere)
    what = f"a list of {n or ''} ".replace("  ", " ") + ("numbers" if len(shape) == 1 else "lists")
    if not isinstance(value, list):
        raise VehicleSpecError(f"'{path}' must be {what}, got {_show(value)}")
    if n is None and not value:
        raise VehicleSpecError(f"'{path}' must have at least one element, got 0")
    if n is not None and len(value) != n:
        raise VehicleSpecError(f"'{path}' must have {n} elements, got {len(value)}")
    return tuple(_array(v, shape[1:], spec, f"{path}[{i}]") for i, v in enumerate(value))


def _table_list(cls, spec: _Spec, value, path: str) -> tuple:
    if not isinstance(value, list):
        raise VehicleSpecError(
            f"'{path}' must be a list of tables ([[{path}]]), got {_show(value)}"
        )
    counts = (spec.count,) if isinstance(spec.count, int) else spec.count
    if counts is not None and len(value) not in counts:
        allowed = " or ".join(str(n) for n in counts)
        raise VehicleSpecError(
            f"'{path}' must have {'exactly ' if len(counts) == 1 else ''}{allowed} entries "
            f"({spec.count_note}), got {len(value)}"
        )
    if not value:
        raise VehicleSpecError(f"'{path}' must have at least one entry ({spec.count_note})")
    return tuple(cls(**_read_fields(cls, v, f"{path}[{i}]")) for i, v in enumerate(value))
