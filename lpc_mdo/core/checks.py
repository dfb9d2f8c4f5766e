"""One argument checker for every option, input and run-script argument, with one message form.

Every check names the argument, its value and what is allowed, in the form of the vehicle-file
errors of :mod:`lpc_mdo.vehicle`::

    'num_radial' = 1 is out of range: must be >= 2
    'wing.area' = -3.0 is out of range: must be > 0 (m**2)
    'chord[0, 2]' = nan is out of range: must be a finite number
    'quadrature' = 'simpson' is not allowed: must be one of 'gauss', 'midpoint'
    'num_blades' must be an integer, got float 2.5
    'thrust_axis' must have shape (8, 3), got shape (3,)

An array is checked entry by entry and the message names the first offending entry and its
index. NaN and inf never pass a range check. ``where`` (e.g. a component's ``msginfo``) is put in
front of the message as ``"<where>: "``; ``error`` selects the exception class (``ValueError``
for options and arguments, ``om.AnalysisError`` for inputs checked during a run, so that an
optimizer can back off). Under complex step only the real part of a value is checked.

:class:`RangeCheck` wraps :func:`check_range` as an OpenMDAO ``check_valid`` callback (a class
instance, so that recorders can pickle the options that use it).
"""

import math
import numbers

import numpy as np

__all__ = [
    "RangeCheck",
    "check_choice",
    "check_finite",
    "check_integer",
    "check_number",
    "check_range",
    "check_shape",
    "cut_text",
    "range_text",
    "units_suffix",
]


def _fmt(x) -> str:
    """Format a bound as the messages show it (6 significant digits)."""
    return f"{x:.6g}"


def _show(value) -> str:
    """Type and (shortened) repr of a value of the wrong kind."""
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


def cut_text(text, limit=60) -> str:
    """
    Return the ``repr`` of a text for a message, cut to ``limit`` characters if longer.

    A cut text ends with the length of the whole, e.g. ``'/tmp/xxxx'... (5000 characters)``;
    control characters are escaped (``repr``), so a message stays one line.
    """
    text = str(text)
    shown = repr(text[:limit])
    return shown if len(text) <= limit else f"{shown}... ({len(text)} characters)"


def _plain(value):
    """Return a numpy scalar as the Python number it holds (so the message shows ``-3.0``)."""
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, complex):
        value = value.real
    return value


def _prefix(where) -> str:
    return f"{where}: " if where else ""


def range_text(lower=None, upper=None, *, lower_open=False, upper_open=False) -> str:
    """
    Return the allowed range as the messages word it.

    For example ``"> 0"``, ``"in [0, 1)"``, or ``""`` if unbounded.

    Parameters
    ----------
    lower, upper : float or None
        Bounds; ``None`` leaves that side unbounded.
    lower_open, upper_open : bool
        Whether the bound itself is excluded.

    Returns
    -------
    str
        The range text.
    """
    if lower is not None and upper is not None:
        return (
            f"in {'(' if lower_open else '['}{_fmt(lower)}, {_fmt(upper)}"
            f"{')' if upper_open else ']'}"
        )
    if lower is not None:
        return f"{'>' if lower_open else '>='} {_fmt(lower)}"
    if upper is not None:
        return f"{'<' if upper_open else '<='} {_fmt(upper)}"
    return ""


def units_suffix(units) -> str:
    """``" (m**2)"`` for units ``"m**2"``; ``""`` for none."""
    return f" ({units})" if units else ""


def _entry_name(name, index) -> str:
    return f"{name}[{', '.join(str(int(i)) for i in index)}]" if index else name


def _first_bad(bad):
    """Index tuple of the first True entry of ``bad`` (an empty tuple for a 0-d array)."""
    return tuple(int(i) for i in np.argwhere(bad)[0]) if bad.ndim else ()


def _as_real_array(name, value, error, where):
    if isinstance(value, (bool, np.bool_)):
        raise error(f"{_prefix(where)}'{name}' must be a number, got {_show(value)}")
    try:
        arr = np.asarray(value)
    except Exception:  # noqa: BLE001 - any failure to form an array is the same user error
        arr = np.asarray(None, dtype=object)
    if arr.dtype.kind == "O":
        # Integers beyond 64 bits form an object array: they are numbers, compared as floats
        # (beyond 1.8e308 as infinite) so that the range check names the value and the range.
        try:
            arr = np.vectorize(_big_integer_as_float, otypes=[float])(arr)
        except (TypeError, ValueError):
            pass
    if arr.dtype.kind not in "iufc":
        raise error(
            f"{_prefix(where)}'{name}' must be a number or an array of numbers, got {_show(value)}"
        )
    return np.real(arr) if arr.dtype.kind == "c" else arr


def _big_integer_as_float(x):
    """Return a Python int as a float (+-inf beyond the float range); else raise TypeError."""
    if isinstance(x, bool) or not isinstance(x, int):
        raise TypeError(x)
    try:
        return float(x)
    except OverflowError:
        return math.inf if x > 0 else -math.inf


def check_range(
    name,
    value,
    *,
    lower=None,
    upper=None,
    lower_open=False,
    upper_open=False,
    units=None,
    allowed=None,
    error=ValueError,
    where=None,
):
    """
    Check that a number, or every entry of an array, is finite and in a range.

    Parameters
    ----------
    name : str
        Name of the argument, option, field or input, as the user wrote it.
    value : float or array_like
        The value; a complex value (complex step) is checked by its real part.
    lower, upper : float, array_like or None
        Bounds; ``None`` leaves that side unbounded (finite is still required). An array bound
        broadcasts against ``value`` (e.g. a hub radius below each rotor's radius); the message
        shows the bound of the offending entry.
    lower_open, upper_open : bool
        Whether the bound itself is excluded (``> lower`` instead of ``>= lower``).
    units : str or None
        Units of the value and the bounds, for the message.
    allowed : str or None
        Text that replaces the range text in the message (for a range the bounds cannot say,
        e.g. ``"even"``); the bounds are still what is checked.
    error : type
        Exception class raised; ``ValueError`` by default.
    where : str or None
        Prefix of the message (e.g. a component's ``msginfo``).

    Returns
    -------
    float or int or ndarray
        ``value`` unchanged (a Python number) or as an ndarray, for chaining.

    Raises
    ------
    error
        If the value is not a number, is NaN or infinite, or is outside the range; the message
        names the first offending entry, its index, its value and the allowed range.
    """
    arr = _as_real_array(name, value, error, where)
    # The check runs in every component evaluation, so the passing case is kept to a few
    # vectorized comparisons (a comparison with NaN is False without a warning).
    bad = ~np.isfinite(arr)
    if lower is not None:
        bad |= (arr <= np.real(lower)) if lower_open else (arr < np.real(lower))
    if upper is not None:
        bad |= (arr >= np.real(upper)) if upper_open else (arr > np.real(upper))
    if bad.any():
        index = _first_bad(bad)
        entry = _plain(arr[index])
        label = _entry_name(name, index)
        if not np.isfinite(arr[index]):
            need = "a finite number"
        else:
            bounds = [
                None if b is None else np.real(np.broadcast_to(b, arr.shape))
                for b in (lower, upper)
            ]
            low, high = (None if b is None else _plain(b[index]) for b in bounds)
            text = allowed or range_text(low, high, lower_open=lower_open, upper_open=upper_open)
            need = f"{text}{units_suffix(units)}"
        raise error(f"{_prefix(where)}'{label}' = {entry!r} is out of range: must be {need}")
    if isinstance(value, numbers.Number) and not isinstance(value, np.generic):
        return value
    return arr


def check_finite(name, value, *, error=ValueError, where=None):
    """
    Check that a number, or every entry of an array, is finite (not NaN, not inf).

    Parameters
    ----------
    name : str
        Name of the argument.
    value : float or array_like
        The value.
    error : type
        Exception class raised.
    where : str or None
        Prefix of the message.

    Returns
    -------
    float or ndarray
        ``value`` (see :func:`check_range`).
    """
    return check_range(name, value, error=error, where=where)


def check_number(
    name,
    value,
    *,
    lower=None,
    upper=None,
    lower_open=False,
    upper_open=False,
    units=None,
    allowed=None,
    error=ValueError,
    where=None,
) -> float:
    """
    Check that a value is one real number (not a bool, not an array) in a range.

    Parameters
    ----------
    name, lower, upper, lower_open, upper_open, units, allowed, error, where
        As for :func:`check_range`.
    value : object
        The value.

    Returns
    -------
    float
        The value as a float.
    """
    plain = _plain(value)
    if isinstance(plain, bool) or not isinstance(plain, (int, float)):
        raise error(f"{_prefix(where)}'{name}' must be a number, got {_show(value)}")
    check_range(
        name,
        plain,
        lower=lower,
        upper=upper,
        lower_open=lower_open,
        upper_open=upper_open,
        units=units,
        allowed=allowed,
        error=error,
        where=where,
    )
    return float(plain)


def check_integer(
    name, value, *, lower=None, upper=None, allowed=None, error=ValueError, where=None
) -> int:
    """
    Check that a value is an integer (an ``int`` or an integral float, not a bool) in a range.

    Parameters
    ----------
    name : str
        Name of the argument.
    value : object
        The value.
    lower, upper : int or None
        Inclusive bounds.
    allowed : str or None
        Text that replaces the range text in the message.
    error : type
        Exception class raised.
    where : str or None
        Prefix of the message.

    Returns
    -------
    int
        The value as an int.
    """
    plain = _plain(value)
    # An int of any size is an integer (check_range compares those beyond int64 as floats); a
    # float must be finite and integral.
    integral_float = isinstance(plain, float) and math.isfinite(plain) and plain.is_integer()
    if isinstance(plain, bool) or not (isinstance(plain, int) or integral_float):
        raise error(f"{_prefix(where)}'{name}' must be an integer, got {_show(value)}")
    check_range(name, plain, lower=lower, upper=upper, allowed=allowed, error=error, where=where)
    return int(plain)


def check_choice(name, value, allowed, *, error=ValueError, where=None):
    """
    Check that a value is one of a set of allowed values.

    Parameters
    ----------
    name : str
        Name of the argument.
    value : object
        The value.
    allowed : iterable
        The allowed values, in the order the message lists them.
    error : type
        Exception class raised.
    where : str or None
        Prefix of the message.

    Returns
    -------
    object
        ``value``.
    """
    allowed = tuple(allowed)
    try:
        ok = value in allowed
    except Exception:  # noqa: BLE001 - e.g. an array compared with strings
        ok = False
    if not ok:
        listed = ", ".join(repr(c) for c in allowed)
        shown = cut_text(value) if isinstance(value, str) else repr(value)
        raise error(f"{_prefix(where)}'{name}' = {shown} is not allowed: must be one of {listed}")
    return value


def check_shape(name, value, shape, *, error=ValueError, where=None) -> np.ndarray:
    """
    Check the shape of an array; ``None`` in ``shape`` accepts any length on that axis.

    Parameters
    ----------
    name : str
        Name of the argument.
    value : array_like
        The value.
    shape : tuple of int or None
        Required shape.
    error : type
        Exception class raised.
    where : str or None
        Prefix of the message.

    Returns
    -------
    ndarray
        ``np.asarray(value)``.
    """
    arr = np.asarray(value)
    shape = tuple(shape)
    ok = arr.ndim == len(shape) and all(
        n is None or n == m for n, m in zip(shape, arr.shape, strict=True)
    )
    if not ok:
        text = "(" + ", ".join("n" if n is None else str(n) for n in shape)
        text += ",)" if len(shape) == 1 else ")"
        raise error(f"{_prefix(where)}'{name}' must have shape {text}, got shape {arr.shape}")
    return arr


class RangeCheck:
    """
    An OpenMDAO ``check_valid`` callback that runs :func:`check_range` on an option.

    ``options.declare('rho', default=50.0, check_valid=RangeCheck(lower=0, lower_open=True))``
    rejects ``rho = -1`` with ``'rho' = -1 is out of range: must be > 0``. ``None`` passes when
    the option allows it (``allow_none=True``).

    Parameters
    ----------
    lower, upper, lower_open, upper_open, units, allowed
        As for :func:`check_range`.
    integer : bool
        Also require an integer (:func:`check_integer`).
    where : str or None
        Prefix of the message (e.g. the component class name).
    """

    def __init__(
        self,
        lower=None,
        upper=None,
        *,
        lower_open=False,
        upper_open=False,
        units=None,
        allowed=None,
        integer=False,
        where=None,
    ):
        self.kwargs = dict(
            lower=lower,
            upper=upper,
            lower_open=lower_open,
            upper_open=upper_open,
            units=units,
            allowed=allowed,
            where=where,
        )
        self.integer = integer

    def __call__(self, name, value):
        """Check option ``name`` = ``value``; raise ValueError if it is out of range."""
        if value is None:
            return
        if self.integer:
            kw = {
                k: v for k, v in self.kwargs.items() if k in ("lower", "upper", "allowed", "where")
            }
            check_integer(name, value, **kw)
        check_range(name, value, **self.kwargs)
