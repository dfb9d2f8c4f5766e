"""Plain-function airfoil polar: cl, cd and cm over angles of attack given in degrees.

:func:`airfoil_polar` evaluates the polar the rotor and wing models use
(:func:`lpc_mdo.components.aero.airfoil.get_polar`: the shipped tables with Viterna and
reverse-flow extrapolation, or a user table) without the caller converting to radians.
"""

import numpy as np

from lpc_mdo.components.aero.airfoil import get_polar
from lpc_mdo.core.checks import check_number, check_range

__all__ = ["airfoil_polar"]


def airfoil_polar(airfoil, alpha_deg, reynolds, mach=0.0):
    """
    Sectional lift, drag and moment coefficients of an airfoil over angles of attack.

    docs theory/aerodynamics 'Airfoil polars' and 'Viterna extrapolation': the table is
    interpolated (C1) in alpha, Reynolds and Mach; beyond its stall points Viterna–Corrigan to
    +-90 deg and the reverse-flow continuation to +-180 deg. Outside the table's Reynolds and
    Mach ranges the values are held at the nearest edge.

    Parameters
    ----------
    airfoil : str, os.PathLike, Polar, array_like or dict
        What :func:`~lpc_mdo.components.aero.airfoil.get_polar` accepts: 'naca0012',
        'naca0015', 'ls413' (GA(W)-2), 'ls417' (GA(W)-1), a ``.npz`` or text polar file, an
        (n, 3) table of alpha [deg], cl, cd, a dict, or a Polar.
    alpha_deg : float or array_like
        Angles of attack, deg, in [-180, 180].
    reynolds : float
        Chord Reynolds number, in [1e3, 1e9].
    mach : float
        Mach number, in [0, 1).

    Returns
    -------
    dict
        'alpha_deg', 'cl', 'cd', 'dcl_dalpha' (per rad), each of the shape of ``alpha_deg``
        (floats for a scalar); 'cm': the quarter-chord moment coefficient where the polar has a
        cm table (the shipped tables do), inside the table's angles only (NaN outside them: no
        post-stall moment model), or None if the polar has no cm table (a user table of alpha,
        cl, cd); 'cm_alpha_range_deg': the (min, max) table angles of cm (None without cm);
        'name': the polar's label.
    """
    where = "airfoil_polar"
    alpha = check_range(
        "alpha_deg",
        np.asarray(alpha_deg, dtype=float),
        lower=-180.0,
        upper=180.0,
        units="deg",
        where=where,
    )
    reynolds = check_number(
        "reynolds", reynolds, lower=1e3, upper=1e9, allowed="in [1e3, 1e9]", where=where
    )
    mach = check_number("mach", mach, lower=0.0, upper=1.0, upper_open=True, where=where)
    try:
        polar = get_polar(airfoil)
    except ValueError as err:
        raise ValueError(f"{where}: 'airfoil': {err}") from None
    alpha_rad = np.radians(alpha)
    values = polar.evaluate(alpha_rad, reynolds, mach)
    result = {
        "alpha_deg": alpha.copy(),
        "cl": np.asarray(values.cl, dtype=float).copy(),
        "cd": np.asarray(values.cd, dtype=float).copy(),
        "dcl_dalpha": np.asarray(values.dcl_dalpha, dtype=float).copy(),
        "cm": None,
        "cm_alpha_range_deg": None,
        "name": getattr(polar, "name", "polar"),
    }
    if getattr(polar, "table_cm", None) is not None:
        low, high = np.degrees(polar.table_alpha[[0, -1]])
        cm = np.asarray(polar.moment_coefficient(alpha_rad, reynolds, mach)[0], dtype=float)
        result["cm"] = np.where((alpha >= low) & (alpha <= high), cm, np.nan)
        result["cm_alpha_range_deg"] = (float(low), float(high))
    if alpha.ndim == 0:
        for key in ("alpha_deg", "cl", "cd", "dcl_dalpha", "cm"):
            if result[key] is not None:
                result[key] = float(result[key])
    return result
