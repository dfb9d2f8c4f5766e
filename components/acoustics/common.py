"""Shared constants, option checks and level arithmetic of the acoustics components.

Level arithmetic (docs theory/acoustics):

- SPL = 10 log10(p_ms/p_ref**2 + SPL_FLOOR), p_ref = 20 uPa. The tiny relative floor SPL_FLOOR =
  1e-12 (a -120 dB floor, i.e. a pressure floor of 2e-11 Pa rms) keeps the logarithm finite and
  smooth when a source is exactly silent (e.g. steady loading noise on the rotor axis, where
  J_mB(0) = 0). It changes no audible level: a source at 0 dB is altered by 4e-12 dB.
- Incoherent (energetic) sums: L = 10 log10(sum 10**(L_i/10)).
"""

import numpy as np
import openmdao.api as om
from scipy.special import jv, yv

from lpc_mdo.core.checks import check_integer, check_number, check_range, check_shape

#: Reference pressure, Pa (20 uPa).
P_REF = 2.0e-5
#: Relative mean-square floor added inside every log10 (a -120 dB floor), see module docstring.
SPL_FLOOR = 1.0e-12
#: 10/ln(10): d(10 log10 y)/dy = DB_PER_NEPER/y.
DB_PER_NEPER = 10.0 / np.log(10.0)

# Nominal (preferred) one-third-octave band centre mantissas, IEC 61260-1 / ANSI S1.11.
_NOMINAL_MANTISSAS = (10.0, 12.5, 16.0, 20.0, 25.0, 31.5, 40.0, 50.0, 63.0, 80.0)


def nominal_third_octave_bands(num_bands, lowest=12.5):
    """
    Nominal one-third-octave band centre frequencies (Hz), ``num_bands`` bands from ``lowest``.

    The default (38 bands from 12.5 Hz to 63 kHz) is the Gill-Lee band set of
    docs theory/acoustics 'Broadband noise'.
    """
    table = np.array([m * 10.0**k for k in range(0, 6) for m in _NOMINAL_MANTISSAS])
    matches = np.flatnonzero(np.isclose(table, lowest, rtol=1e-9))
    if matches.size != 1:
        raise ValueError(
            f"lowest_band_frequency must be a nominal one-third-octave centre "
            f"frequency between 10 Hz and 800 kHz (e.g. 12.5, 16, 20, 25, 31.5 ...), "
            f"got {lowest}."
        )
    start = matches[0]
    check_integer(
        "num_bands",
        num_bands,
        lower=1,
        upper=table.size - start,
        allowed=f"in [1, {table.size - start}] when starting at {lowest} Hz",
    )
    return table[start : start + num_bands].copy()


def radial_quadrature(num_radial, radial_stations=None, radial_weights=None, hub_radius_ratio=0.2):
    """
    Non-dimensional radial stations r/R and quadrature weights w (fractions of R).

    Integrals over the blade are R * sum_i w_i f(r_i). Defaults: stations at the centres of
    ``num_radial`` equal elements on [hub_radius_ratio, 1] (the BEM element centres of
    docs theory/rotors 'Stations and disk frame') and, for any stations, weights equal to the width
    of each station's cell, whose edges are the mid-points between stations and the hub and tip (the
    midpoint rule for element centres; sum w = 1 - hub_radius_ratio).

    Raises ValueError naming the option if stations are not strictly increasing inside
    (hub_radius_ratio, 1], or weights are not positive or of the wrong length.
    """
    check_number("hub_radius_ratio", hub_radius_ratio, lower=0.0, upper=1.0, upper_open=True)
    if radial_stations is None:
        stations = (
            hub_radius_ratio + (1.0 - hub_radius_ratio) * (np.arange(num_radial) + 0.5) / num_radial
        )
    else:
        stations = np.asarray(radial_stations, dtype=float).ravel()
        if stations.size != num_radial:
            raise ValueError(
                f"radial_stations must have num_radial = {num_radial} entries, got {stations.size}."
            )
        if (
            np.any(np.diff(stations) <= 0.0)
            or stations[0] <= hub_radius_ratio
            or stations[-1] > 1.0
        ):
            raise ValueError(
                f"radial_stations must be strictly increasing in "
                f"(hub_radius_ratio = {hub_radius_ratio}, 1], got "
                f"{stations.tolist()}."
            )
    if radial_weights is None:
        edges = np.concatenate(([hub_radius_ratio], 0.5 * (stations[1:] + stations[:-1]), [1.0]))
        weights = np.diff(edges)
    else:
        weights = np.asarray(radial_weights, dtype=float).ravel()
        check_shape("radial_weights", weights, (num_radial,))
        check_range("radial_weights", weights, lower=0.0, lower_open=True)
    return stations, weights


def declare_broadband_options(options):
    """
    Declare the options shared by the broadband spectrum components.

    num_rotors, num_blades, num_bands (38 from 12.5 Hz by default) and lowest_band_frequency.
    """
    options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
    options.declare(
        "num_blades",
        default=2,
        types=(int, tuple, list, np.ndarray),
        desc="Blades per rotor (int or one per rotor)",
    )
    options.declare(
        "num_bands", default=38, types=int, lower=1, desc="Number of one-third-octave bands"
    )
    options.declare(
        "lowest_band_frequency",
        default=12.5,
        types=(int, float),
        desc="Nominal centre frequency of the first band, Hz",
    )


def declare_radial_options(options):
    """Declare the radial-station options shared by the blade-integrating components."""
    options.declare("num_radial", default=25, types=int, lower=1, desc="Number of radial stations")
    options.declare(
        "radial_stations",
        default=None,
        types=(np.ndarray, list, tuple),
        allow_none=True,
        desc="Radial stations r/R (None: equal-element centres)",
    )
    options.declare(
        "radial_weights",
        default=None,
        types=(np.ndarray, list, tuple),
        allow_none=True,
        desc="Radial quadrature weights, fractions of R (None: cell widths)",
    )
    options.declare(
        "hub_radius_ratio",
        default=0.2,
        types=(int, float),
        desc="Hub radius / tip radius (inner edge of the first cell)",
    )


def blade_counts(num_blades, num_rotors):
    """Blade count per rotor as an int array; ``num_blades`` is an int or one int per rotor."""
    counts = np.atleast_1d(np.asarray(num_blades))
    if counts.size == 1:
        counts = np.full(num_rotors, counts[0])
    if counts.size != num_rotors or not np.issubdtype(counts.dtype, np.integer):
        raise ValueError(
            f"'num_blades' = {num_blades!r} is not allowed: must be an int >= 1 "
            f"or a sequence of num_rotors = {num_rotors} ints >= 1"
        )
    check_range("num_blades", counts, lower=1)
    return counts.astype(int)


def check_input_range(comp, name, value, lower=None, upper=None, lower_open=True, upper_open=True):
    """
    Raise om.AnalysisError if any entry of input ``name`` is not finite or lies outside the range.

    :func:`lpc_mdo.core.checks.check_range` with open bounds by default and the component's
    ``msginfo`` in front; only the real part is checked, so the check is complex-step safe.
    """
    check_range(
        name,
        value,
        lower=lower,
        upper=upper,
        lower_open=lower_open,
        upper_open=upper_open,
        error=om.AnalysisError,
        where=comp.msginfo,
    )


def spl_from_mean_square(mean_square):
    """SPL in dB re 20 uPa from the mean-square pressure (Pa**2), with the smooth floor."""
    return 10.0 * np.log10(mean_square / P_REF**2 + SPL_FLOOR)


def dspl_dmean_square(mean_square):
    """Return the derivative of :func:`spl_from_mean_square` with respect to the mean square."""
    return DB_PER_NEPER / (mean_square + SPL_FLOOR * P_REF**2)


def _complex_step_safe(func, order, x):
    """func(order, x) for real x; for complex x = x0 + i h, func(x0) + i h func'(x0).

    scipy's complex Bessel routines (AMOS) return imaginary parts of ~1e-17 for real arguments,
    which a complex step of 1e-40 would turn into huge derivatives; the first-order Taylor form is
    exact for complex step. func' = (func_{k-1} - func_{k+1})/2 for J and Y.
    """
    if np.iscomplexobj(x):
        xr = x.real
        deriv = 0.5 * (func(order - 1, xr) - func(order + 1, xr))
        return func(order, xr) + 1j * x.imag * deriv
    return func(order, x)


def bessel_j(order, x):
    """Bessel function of the first kind J_order(x), real x (complex-step safe)."""
    return _complex_step_safe(jv, order, x)


#: Arguments below which :func:`bessel_j_range` evaluates order by order (near the rotor axis,
#: where the downward recurrence would grow by 2n/x per step).
_MILLER_MIN_ARGUMENT = 1.0e-3
#: Rescaling threshold of the recurrence's running values (well inside the double range).
_MILLER_RESCALE = 1.0e250


def bessel_j_range(low, count, x):
    """
    Bessel functions J_n(x) of the consecutive integer orders n = low .. low + count - 1.

    Returns an array of shape broadcast(low, x) + (count,). Miller's algorithm (Press et al.,
    Numerical Recipes, 3rd ed., sec. 6.5; Abramowitz and Stegun 9.12): the recurrence
    J_{n-1} = (2n/x) J_n - J_{n+1} (A&S 9.1.27), run downward from an order N well above the
    orders needed and the argument (N = max(n, x) + 12 + 3 sqrt(max(n, x)), even) with
    J_{N+1} = 0 and an arbitrary J_N, is stable because J_n is its minimal solution as n grows;
    the sum rule J_0 + 2 (J_2 + J_4 + ...) = 1 (A&S 9.1.46) normalises it. Negative orders by
    J_{-n} = (-1)^n J_n (A&S 9.1.5). No library call, where one per order cost ten times as
    much; within 1e-10 of the library's values (tests: orders -12 to 62, arguments 1e-8 to 120).
    Complex-step safe: the recurrence and the normalisation are analytic in x. Arguments below
    1e-3 (near the rotor axis) take :func:`bessel_j` order by order.
    """
    low = np.asarray(low)
    x = np.asarray(x)
    shape = np.broadcast_shapes(low.shape, x.shape)
    low = np.broadcast_to(low, shape).astype(int)
    x = np.broadcast_to(x, shape)
    orders = low[..., None] + np.arange(count)  # (..., count)
    top = int(np.max(np.abs(orders)))
    small = np.abs(x.real) < _MILLER_MIN_ARGUMENT
    xs = np.where(small, 1.0, x)  # the small ones are replaced below
    reach = max(top, float(np.max(np.abs(xs.real))))
    start = int(np.ceil(reach + 12.0 + 3.0 * np.sqrt(reach)))
    start += start % 2
    dtype = np.result_type(x, float)
    positive = np.zeros(shape + (top + 1,), dtype=dtype)  # J_0 .. J_top, unnormalised
    after = np.zeros(shape, dtype=dtype)
    value = np.full(shape, 1.0e-30, dtype=dtype)
    norm = np.zeros(shape, dtype=dtype)
    for k in range(start, 0, -1):  # value = J_k, after = J_{k+1}
        if k <= top:
            positive[..., k] = value
        if k % 2 == 0:
            norm = norm + 2.0 * value
        value, after = 2.0 * k / xs * value - after, value
        if np.max(np.abs(value.real)) > _MILLER_RESCALE:
            scale = np.where(np.abs(value.real) > _MILLER_RESCALE, 1.0 / _MILLER_RESCALE, 1.0)
            value, after, norm = value * scale, after * scale, norm * scale
            positive *= scale[..., None]
    positive[..., 0] = value
    positive /= (norm + value)[..., None]
    table = np.take_along_axis(positive, np.abs(orders), axis=-1)
    table = np.where((orders < 0) & (orders % 2 == 1), -table, table)
    if np.any(small):
        table[small] = bessel_j(orders[small], x[small][..., None])
    return table


def bessel_y(order, x):
    """Bessel function of the second kind Y_order(x), real x > 0 (complex-step safe)."""
    return _complex_step_safe(yv, order, x)
