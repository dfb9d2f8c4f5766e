"""Measured compressibility stall of the NACA 0012: the section's maximum lift against Mach number.

A table built from an incompressible section model scaled by Prandtl–Glauert (the shipped polars,
``lpc_mdo/data/README.md``) keeps the low-speed stall angle at every Mach number, so its maximum
lift coefficient grows as 1/sqrt(1 - M^2): 1.47 at M 0.3 to 1.96 at M 0.7 for the NACA 0012 at
Re 1e6. Measured maxima fall instead above M of about 0.3: the leading-edge suction peak turns
supersonic and a shock separates the boundary layer (McCroskey, "A critical assessment of wind
tunnel results for the NACA 0012 airfoil", NASA TM-100019, 1987).

The data used here are Leishman and Beddoes' static stall-onset parameters of the NACA 0012
(Leishman, J. G. and Beddoes, T. S., "A semi-empirical model for dynamic stall", J. American
Helicopter Society 34(3), 1989, Table 1; read from a public transcription of that table): the
critical normal-force coefficient C_N1 at which the leading edge separates and the angle alpha_1
of the static stall break, at M = 0.3 to 0.8. Before separation the resultant force is normal
to the stream up to the section drag, so c_l = C_N cos(alpha) + C_C sin(alpha) with the
leading-edge suction C_C = C_N tan(alpha) - c_d / cos(alpha); together
c_l = C_N / cos(alpha) - c_d tan(alpha), and without the last term (below 0.006 before stall,
under 0.5 % of c_l) c_l,max = C_N1 / cos(alpha_1).

:func:`max_lift_ceiling` gives that c_l,max at a Mach number; :class:`TablePolar` with
``max_lift=`` moves each (Re, M) slice's stall point down to where the table's c_l reaches it
(docs theory/aerodynamics 'Compressibility stall'). Below M 0.3 the data give no ceiling (the
low-speed stall depends on the Reynolds number, which the table carries); above M 0.8 the
section is beyond drag divergence and the M 0.8 value is used, a stated rule for table slices no
feasible design reaches (the rotor tip-Mach limits, ``[constraints]``, stop below it).
"""

import numpy as np

__all__ = ["NACA0012_STALL_ONSET", "max_lift_ceiling", "naca0012_max_lift"]

#: Mach number, C_N1 and alpha_1 (deg) of the NACA 0012 (Leishman and Beddoes 1989, Table 1).
NACA0012_STALL_ONSET = np.array(
    [
        [0.30, 1.45, 15.25],
        [0.40, 1.20, 12.50],
        [0.50, 1.05, 10.50],
        [0.60, 0.92, 8.50],
        [0.70, 0.68, 5.60],
        [0.75, 0.50, 3.50],
        [0.80, 0.18, 0.70],
    ]
)


def max_lift_ceiling(mach, onset=NACA0012_STALL_ONSET):
    """
    Measured maximum lift coefficient C_N1 / cos(alpha_1) at Mach numbers ``mach``.

    Linear in M between the data points; ``inf`` (no ceiling) below the first, the last point's
    value above the last (module docstring).

    Parameters
    ----------
    mach : array_like
        Mach numbers (>= 0).
    onset : ndarray, (n, 3)
        Rows of Mach number, C_N1, alpha_1 (deg), increasing in Mach number.

    Returns
    -------
    ndarray
        c_l,max, the shape of ``mach``.
    """
    mach = np.asarray(mach, dtype=float)
    onset = np.asarray(onset, dtype=float)
    cl_max = onset[:, 1] / np.cos(np.radians(onset[:, 2]))
    return np.where(mach < onset[0, 0], np.inf, np.interp(mach, onset[:, 0], cl_max))


def naca0012_max_lift(mach):
    """Return the NACA 0012's measured c_l,max at ``mach`` (:func:`max_lift_ceiling`)."""
    return max_lift_ceiling(mach, NACA0012_STALL_ONSET)
