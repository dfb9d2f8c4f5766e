"""Airfoil polar interface and the analytic "linear lift, quadratic drag" polar with Viterna.

Every sectional model (VLM strips, BEM and Pitt–Peters blade elements) asks a :class:`Polar` for
lift and drag coefficients and their derivatives, so any polar (this analytic one, the tabulated
XFOIL-trained ones, a user's table) works wherever an airfoil is expected.
"""

import abc
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PolarValues:
    """Lift and drag coefficients and their partial derivatives, all of one broadcast shape.

    Angles in rad; derivatives per rad, per unit Reynolds number and per unit Mach number.
    """

    cl: np.ndarray
    cd: np.ndarray
    dcl_dalpha: np.ndarray
    dcd_dalpha: np.ndarray
    dcl_dreynolds: np.ndarray
    dcd_dreynolds: np.ndarray
    dcl_dmach: np.ndarray
    dcd_dmach: np.ndarray


class Polar(abc.ABC):
    """
    A sectional airfoil model: cl(alpha, Re, M) and cd(alpha, Re, M) on -pi..pi.

    Subclasses implement :meth:`evaluate`, vectorized over arrays of any common broadcast shape,
    C1 in alpha everywhere (the Newton and bracketed solves of the rotor and alpha* models rely
    on it) and complex-step safe: complex inputs give complex outputs whose imaginary parts are
    the complex-step derivatives.
    """

    name = "polar"

    @abc.abstractmethod
    def evaluate(self, alpha, reynolds, mach):
        """
        Evaluate the polar.

        Parameters
        ----------
        alpha : array_like
            Angle of attack, rad (any real value; wrapped to -pi..pi).
        reynolds : array_like
            Chord Reynolds number.
        mach : array_like
            Mach number.

        Returns
        -------
        PolarValues
        """


def wrap_angle(alpha):
    """Wrap angles to (-pi, pi]; complex-safe (the shift is chosen from the real part)."""
    alpha = np.asarray(alpha)
    turns = np.round(np.real(alpha) / (2.0 * np.pi))
    return alpha - 2.0 * np.pi * turns


def _hermite(x, x0, x1, f0, d0, f1, d1):
    """Cubic Hermite interpolant on [x0, x1] and its derivative."""
    h = x1 - x0
    t = (x - x0) / h
    t2, t3 = t * t, t * t * t
    f = (
        (2 * t3 - 3 * t2 + 1) * f0
        + (t3 - 2 * t2 + t) * h * d0
        + (-2 * t3 + 3 * t2) * f1
        + (t3 - t2) * h * d1
    )
    df = (
        (6 * t2 - 6 * t) * f0
        + (3 * t2 - 4 * t + 1) * h * d0
        + (-6 * t2 + 6 * t) * f1
        + (3 * t2 - 2 * t) * h * d1
    ) / h
    return f, df


def viterna_cd_max(aspect_ratio=10.0):
    """
    Return Viterna's maximum drag coefficient CD_max = 1.11 + 0.018 AR (1.29 for AR = 10).

    See docs theory/aerodynamics 'Viterna extrapolation'.
    """
    return 1.11 + 0.018 * aspect_ratio


def viterna_coefficients(alpha_stall, cl_stall, cd_stall, cd_max):
    """
    Return the Viterna–Corrigan coefficients A2, B2 of one stall point.

    See docs theory/aerodynamics 'Viterna extrapolation'.

    A2 = (cl_s - CD_max sin a_s cos a_s) sin a_s/cos^2 a_s,  B2 = (cd_s - CD_max sin^2 a_s)/cos a_s;
    works elementwise on arrays of stall points.
    """
    s, c = np.sin(alpha_stall), np.cos(alpha_stall)
    a2 = (cl_stall - cd_max * s * c) * s / c**2
    b2 = (cd_stall - cd_max * s**2) / c
    return a2, b2


def viterna(a, cd_max, a2, b2):
    """
    Evaluate the Viterna–Corrigan post-stall law and its alpha slopes, to +-90 deg.

    See docs theory/aerodynamics 'Viterna extrapolation'.

    cl = A1 sin 2a + A2 cos^2 a/sin a,  cd = B1 sin^2 a + B2 cos a,  A1 = CD_max/2, B1 = CD_max.
    Returns (cl, cd, dcl/da, dcd/da).
    """
    a1, b1 = 0.5 * cd_max, cd_max
    s, c = np.sin(a), np.cos(a)
    cl = a1 * np.sin(2 * a) + a2 * c**2 / s
    cd = b1 * s**2 + b2 * c
    dcl = 2 * a1 * np.cos(2 * a) + a2 * (-2 * c - c**3 / s**2)
    dcd = 2 * b1 * s * c - b2 * s
    return cl, cd, dcl, dcd


def reverse_flow(a, cd_max, b2, b_mean):
    """
    Reverse-flow continuation beyond +-90 deg (see :class:`LinearQuadraticPolar`).

    cl = (CD_max/2) sin 2a,  cd = CD_max sin^2 a + cos a [B_m + (B2 - B_m) sin^2 a], with B2 of the
    side (negative stall for a < -90 deg, positive for a > 90 deg) and B_m the mean of both sides'
    B2: C1 at +-90 deg with :func:`viterna` and periodic and C1 across +-180 deg.
    Returns (cl, cd, dcl/da, dcd/da).
    """
    a1 = 0.5 * cd_max
    s, c = np.sin(a), np.cos(a)
    g = b_mean + (b2 - b_mean) * s**2
    dg = 2.0 * (b2 - b_mean) * s * c
    cl = a1 * np.sin(2 * a)
    cd = cd_max * s**2 + c * g
    dcl = 2 * a1 * np.cos(2 * a)
    dcd = 2 * cd_max * s * c - s * g + c * dg
    return cl, cd, dcl, dcd


_DEFAULT_STALL = (np.radians(-10.0), np.radians(15.0))
_DEFAULT_BLEND = np.radians(1.5)


class LinearQuadraticPolar(Polar):
    """
    Analytic polar: linear lift and quadratic drag before stall, Viterna–Corrigan after it.

    docs theory/aerodynamics 'Viterna extrapolation', 'Linear-quadratic polar' (BladeAD 0-D
    airfoil):

    - pre-stall: cl = cl0 + cl_alpha alpha,  cd = cd0 + k (cl_alpha alpha)**2 with
      k = [(cd_s+ - cd0)/(cl0 - cl_s+)**2 + (cd_s- - cd0)/(cl0 - cl_s-)**2] / 2;
    - post-stall to +-90 deg (Viterna, AR = 10, CD_max = 1.11 + 0.018 AR):
      cl = A1 sin 2a + A2 cos^2 a / sin a,  cd = B1 sin^2 a + B2 cos a,
      A1 = CD_max/2, B1 = CD_max, A2 and B2 from the stall point of each side;
    - cubic Hermite blends on [alpha_s - eps, alpha_s + eps] (eps = 1.5 deg) matching value and
      slope of the neighbouring laws.

    Beyond +-90 deg (reverse flow on rotor blades) the polar continues as a flat plate,
    cl = A1 sin 2a, and cd = CD_max sin^2 a + cos a [B_m + (B2 - B_m) sin^2 a] with B_m the mean
    of the two sides' B2. Both are C1 at +-90 deg and periodic and C1 across +-180 deg, so no
    station in reverse flow breaks a Newton or bracketed solve. (This continuation is our
    choice; the reference covers +-90 deg only.)

    The model depends on alpha only: its Reynolds and Mach derivatives are zero.

    Parameters
    ----------
    alpha_stall : (float, float)
        Negative and positive stall angles, rad. Default (-10, 15) deg.
    cl_stall, cd_stall : (float, float)
        Lift and drag coefficients at the negative and positive stall points.
    cl0, cd0 : float
        Lift coefficient at zero angle and minimum drag coefficient.
    cl_alpha : float
        Pre-stall lift-curve slope, per rad.
    blend : float
        Half width eps of the stall blends, rad (default 1.5 deg).
    aspect_ratio : float
        Viterna aspect ratio (sets CD_max); default 10.

    The defaults are the example polar of the public BladeAD examples (docs theory/aerodynamics
    'Linear-quadratic polar'), used there for the BEM and Pitt–Peters reference numbers.
    """

    name = "linear_quadratic"

    def __init__(
        self,
        alpha_stall=_DEFAULT_STALL,
        cl_stall=(-1.0, 1.5),
        cd_stall=(0.02, 0.06),
        cl0=0.5,
        cd0=0.008,
        cl_alpha=5.1566,
        blend=_DEFAULT_BLEND,
        aspect_ratio=10.0,
    ):
        a_neg, a_pos = (float(a) for a in alpha_stall)
        checks = (
            (
                "alpha_stall",
                (a_neg, a_pos),
                -np.pi / 2 + blend < a_neg < 0.0 < a_pos < np.pi / 2 - blend,
                "negative < 0 < positive, within +-(90 deg - blend)",
            ),
            ("blend", blend, 0.0 < blend < min(-a_neg, a_pos) / 2, "0 < blend < stall angle/2"),
            ("cd0", cd0, cd0 > 0.0, "> 0"),
            ("cl_alpha", cl_alpha, cl_alpha > 0.0, "> 0 per rad"),
            ("aspect_ratio", aspect_ratio, aspect_ratio > 0.0, "> 0"),
            ("cd_stall", cd_stall, min(cd_stall) > 0.0, "> 0"),
            (
                "cl_stall",
                cl_stall,
                cl_stall[0] < cl0 < cl_stall[1],
                "cl_stall[0] < cl0 < cl_stall[1]",
            ),
        )
        for field, value, ok, allowed in checks:
            if not ok:
                raise ValueError(f"LinearQuadraticPolar: {field} = {value}; allowed: {allowed}.")

        self.alpha_stall = (a_neg, a_pos)
        self.cl_stall = tuple(float(c) for c in cl_stall)
        self.cd_stall = tuple(float(c) for c in cd_stall)
        self.cl0, self.cd0, self.cl_alpha = float(cl0), float(cd0), float(cl_alpha)
        self.blend = float(blend)
        self.cd_max = viterna_cd_max(aspect_ratio)
        self.k = 0.5 * (
            (self.cd_stall[1] - cd0) / (cl0 - self.cl_stall[1]) ** 2
            + (self.cd_stall[0] - cd0) / (cl0 - self.cl_stall[0]) ** 2
        )
        self._a2 = []
        self._b2 = []
        for a_s, cl_s, cd_s in zip(self.alpha_stall, self.cl_stall, self.cd_stall, strict=True):
            a2, b2 = viterna_coefficients(a_s, cl_s, cd_s, self.cd_max)
            self._a2.append(a2)
            self._b2.append(b2)
        self._b_mean = 0.5 * (self._b2[0] + self._b2[1])

    def stall_angles(self, reynolds, mach):
        """
        Negative and positive stall angles (rad), the same at every Reynolds and Mach number.

        Returns (alpha_neg, alpha_pos, dneg_dre, dpos_dre, dneg_dm, dpos_dm) of the broadcast
        shape of the inputs, as :meth:`~lpc_mdo.components.aero.airfoil.TablePolar.stall_angles`.
        """
        zero = np.zeros(np.broadcast(np.asarray(reynolds), np.asarray(mach)).shape)
        return (zero + self.alpha_stall[0], zero + self.alpha_stall[1], zero, zero, zero, zero)

    # ---------------------------------------------------------------- the laws and their slopes

    def _attached(self, a):
        cl = self.cl0 + self.cl_alpha * a
        cd = self.cd0 + self.k * (self.cl_alpha * a) ** 2
        return cl, cd, self.cl_alpha + 0.0 * a, 2.0 * self.k * self.cl_alpha**2 * a

    def _viterna(self, a, side):
        return viterna(a, self.cd_max, self._a2[side], self._b2[side])

    def _reverse(self, a, side):
        return reverse_flow(a, self.cd_max, self._b2[side], self._b_mean)

    def _blend(self, a, side):
        eps = self.blend
        a_s = self.alpha_stall[side]
        if side == 1:
            x0, x1 = a_s - eps, a_s + eps
            left, right = self._attached(x0), self._viterna(x1, 1)
        else:
            x0, x1 = a_s - eps, a_s + eps
            left, right = self._viterna(x0, 0), self._attached(x1)
        cl, dcl = _hermite(a, x0, x1, left[0], left[2], right[0], right[2])
        cd, dcd = _hermite(a, x0, x1, left[1], left[3], right[1], right[3])
        return cl, cd, dcl, dcd

    def evaluate(self, alpha, reynolds, mach):
        alpha, reynolds, mach = np.broadcast_arrays(
            np.asarray(alpha), np.asarray(reynolds), np.asarray(mach)
        )
        a = wrap_angle(alpha)
        ar = np.real(a)
        eps = self.blend
        a_neg, a_pos = self.alpha_stall
        half_pi = 0.5 * np.pi
        regions = [
            (ar < -half_pi, lambda x: self._reverse(x, 0)),
            ((ar >= -half_pi) & (ar < a_neg - eps), lambda x: self._viterna(x, 0)),
            ((ar >= a_neg - eps) & (ar < a_neg + eps), lambda x: self._blend(x, 0)),
            ((ar >= a_neg + eps) & (ar <= a_pos - eps), self._attached),
            ((ar > a_pos - eps) & (ar <= a_pos + eps), lambda x: self._blend(x, 1)),
            ((ar > a_pos + eps) & (ar <= half_pi), lambda x: self._viterna(x, 1)),
            (ar > half_pi, lambda x: self._reverse(x, 1)),
        ]
        dtype = np.result_type(a, float)
        out = [np.zeros(a.shape, dtype=dtype) for _ in range(4)]
        for mask, law in regions:
            if np.any(mask):
                values = law(a[mask])
                for target, value in zip(out, values, strict=True):
                    target[mask] = value
        zeros = np.zeros(a.shape)
        return PolarValues(
            cl=out[0],
            cd=out[1],
            dcl_dalpha=out[2],
            dcd_dalpha=out[3],
            dcl_dreynolds=zeros,
            dcd_dreynolds=zeros,
            dcl_dmach=zeros,
            dcd_dmach=zeros,
        )
