"""
Chordwise pressure table of an airfoil section: Cp on both surfaces over (alpha, Re, M).

:class:`PressureTable` interpolates the Cp tables shipped with the wing airfoils' polar files
(``lpc_mdo/data/airfoil_ls413.npz``, ``airfoil_ls417.npz``) and integrates them into the section
force and moment coefficients; the integration rule is written out in
:mod:`lpc_mdo.components.aero.pressure`, which evaluates it in an OpenMDAO component. A
:class:`~lpc_mdo.components.aero.airfoil.TablePolar` loaded from such a file carries its table
as ``polar.pressure``.
"""

import numpy as np

from .hermite import HermiteAxis, tensor_eval

__all__ = ["PressureTable"]


class PressureTable:
    """
    Cp on the upper and lower surface over (alpha, Re, M), C1 interpolation, and its integrals.

    Interpolation: cubic Hermite with 3-point slopes in alpha, ln Re and M (tensor product; held
    at the table edges outside the ranges, with zero derivative there).

    Parameters
    ----------
    alpha : array_like, (p_a,)
        Angles of attack, rad.
    reynolds, mach : array_like, (p_r,), (p_m,)
        Reynolds and Mach numbers of the table.
    x : array_like, (n_x,)
        Chordwise stations x/c, increasing from 0 (leading edge) to 1 (trailing edge).
    y_upper, y_lower : array_like, (n_x,)
        Surface heights y/c at the stations.
    cp_upper, cp_lower : array_like, (p_a, p_r, p_m, n_x)
        Pressure coefficients.
    name : str
        Label.
    """

    def __init__(
        self, alpha, reynolds, mach, x, y_upper, y_lower, cp_upper, cp_lower, name="pressure table"
    ):
        self.name = name
        self.x = np.asarray(x, dtype=float)
        self.y_upper = np.asarray(y_upper, dtype=float)
        self.y_lower = np.asarray(y_lower, dtype=float)
        n_x = self.x.size
        shape = (np.size(alpha), np.size(reynolds), np.size(mach), n_x)
        cp_upper = np.asarray(cp_upper, dtype=float)
        cp_lower = np.asarray(cp_lower, dtype=float)
        for field, value in (("cp_upper", cp_upper), ("cp_lower", cp_lower)):
            if value.shape != shape:
                raise ValueError(
                    f"PressureTable '{name}': {field} shape {value.shape}; allowed: "
                    f"{shape} (alpha, reynolds, mach, x)"
                )
            if not np.all(np.isfinite(value)):
                raise ValueError(f"PressureTable '{name}': {field} has non-finite values")
        if self.y_upper.shape != (n_x,) or self.y_lower.shape != (n_x,):
            raise ValueError(f"PressureTable '{name}': y_upper, y_lower need shape ({n_x},)")
        self.alpha = np.asarray(alpha, dtype=float)
        self.axes = (HermiteAxis(self.alpha), HermiteAxis(reynolds, log=True), HermiteAxis(mach))
        self.table = np.stack([cp_upper, cp_lower], axis=3)  # (p_a, p_r, p_m, 2, n_x)

        # Quadrature vectors of the trapezoid rule (exactly the rule in the module docstring).
        x = self.x
        tw = np.zeros(n_x)
        dx = np.diff(x)
        tw[:-1] += 0.5 * dx
        tw[1:] += 0.5 * dx

        def dy_weights(y):
            w = np.zeros(n_x)
            dy = np.diff(y)
            w[:-1] += 0.5 * dy
            w[1:] += 0.5 * dy
            return w

        wy_u, wy_l = dy_weights(self.y_upper), dy_weights(self.y_lower)
        # rows: cn, ca, cm_0; columns: (surface, station)
        self.quadrature = np.stack(
            [
                np.stack([-tw, tw]),
                np.stack([wy_u, -wy_l]),
                np.stack([tw * x + wy_u * self.y_upper, -(tw * x + wy_l * self.y_lower)]),
            ]
        )  # (3, 2, n_x)
        self._mid = HermiteAxis(x)
        self._mid_height = 0.5 * (self.y_upper + self.y_lower)

    @classmethod
    def from_npz_data(cls, data):
        """Build from the arrays of an ``airfoil_<name>.npz`` file (angles in degrees)."""
        return cls(
            np.radians(data["cp_alpha_deg"]),
            data["cp_reynolds"],
            data["cp_mach"],
            data["x"],
            data["y_upper"],
            data["y_lower"],
            data["cp_upper"],
            data["cp_lower"],
            name=str(data["name"]) if "name" in data.files else "",
        )

    def cp(self, alpha, reynolds, mach):
        """
        Cp and its derivatives at N conditions.

        Returns
        -------
        tuple of ndarray, each (N, 2, n_x)
            (cp, dcp_dalpha, dcp_dreynolds, dcp_dmach); index 0 of axis 1 is the upper surface.
        """
        (ia, wa, dwa), (ir, wr, dwr), (im, wm, dwm) = (
            ax.weights(np.atleast_1d(q))
            for ax, q in zip(self.axes, (alpha, reynolds, mach), strict=True)
        )
        return tensor_eval(self.table, (ia, ir, im), (wa, wr, wm), (dwa, dwr, dwm))

    def integrate(self, cp):
        """(cn, ca, cm_0) from Cp arrays (..., 2, n_x) (linear; also for derivatives)."""
        return np.einsum("kij,...ij->k...", self.quadrature, cp)

    def mid_height(self, x_a):
        """Section mid-height y_a/c at chordwise stations x_a/c and d(y_a)/d(x_a)."""
        index, w, dw = self._mid.weights(np.atleast_1d(x_a))
        g = self._mid_height[index]
        return np.sum(w * g, axis=1), np.sum(dw * g, axis=1)
