"""
Section angle of attack alpha* from the VLM's sectional lift coefficient (paper eq. 16a).

R(alpha*) = cl_VLM - cl_airfoil(alpha*, Re, M) = 0, solved per spanwise section by a bracketed
safeguarded-Newton iteration between the stall angles of the airfoil at (Re, M)
(docs theory/aerodynamics 'Airfoil coupling' step 2: bracket [alpha_Clmin, alpha_Clmax]).
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.numerics import safeguarded_newton

from .airfoil import get_polar
from .polar import LinearQuadraticPolar

_EPS = np.finfo(float).eps

_SCAN = np.radians(np.arange(-40.0, 40.0 + 1e-9, 0.25))


def stall_bracket(polar, reynolds, mach):
    """
    Negative and positive stall angles of a polar at (Re, M), the bracket of the alpha* solve.

    - :class:`~lpc_mdo.components.aero.airfoil.TablePolar`: its stall angles (interpolated from
      each table slice's first dominant cl extremum), with their Re and M derivatives;
    - :class:`~lpc_mdo.components.aero.polar.LinearQuadraticPolar`: its constant stall angles;
    - any other Polar: the angles of min and max cl on -40..0 and 0..40 deg (0.25 deg scan),
      derivatives taken as zero.

    Returns
    -------
    tuple of ndarray
        (alpha_neg, alpha_pos, dneg_dre, dpos_dre, dneg_dm, dpos_dm), rad.
    """
    reynolds, mach = np.broadcast_arrays(np.asarray(reynolds), np.asarray(mach))
    if hasattr(polar, "stall_angles"):
        return polar.stall_angles(reynolds, mach)
    zero = np.zeros(reynolds.shape)
    if isinstance(polar, LinearQuadraticPolar):
        lo, hi = polar.alpha_stall
        return zero + lo, zero + hi, zero, zero, zero, zero
    cl = np.real(
        polar.evaluate(
            _SCAN[:, None], np.real(reynolds).ravel()[None], np.real(mach).ravel()[None]
        ).cl
    )
    neg = _SCAN <= 0.0
    lo = _SCAN[neg][np.argmin(cl[neg], axis=0)].reshape(reynolds.shape)
    hi = _SCAN[~neg][np.argmax(cl[~neg], axis=0)].reshape(reynolds.shape)
    return lo, hi, zero, zero, zero, zero


class AlphaStarComp(om.ImplicitComponent):
    """
    alpha* per spanwise section from the sectional lift coefficient (paper eq. 16a).

    Residual R = cl_VLM - g(alpha*, Re, M) with g the airfoil lift coefficient cl(alpha, Re, M)
    on the stall bracket [alpha_neg, alpha_pos] of :func:`stall_bracket`, continued linearly
    outside it: g = cl(alpha_pos) + s (alpha - alpha_pos) above and cl(alpha_neg) +
    s (alpha - alpha_neg) below, with s = ``extension_slope`` (default 2 pi per rad). A section
    whose cl_VLM lies beyond the airfoil's cl_max (the VLM has no stall) thus gets a finite alpha*
    just past the stall angle instead of a failed solve; the number of such sections of the last
    solve is in :attr:`num_beyond_stall`.

    ``solve_nonlinear`` solves each section by a bracketed Newton iteration (Newton steps kept
    inside the bracket, bisection otherwise) to abs(R) < ``tolerance``; ``linearize`` gives the
    exact diagonal Jacobian and ``solve_linear`` inverts it, so no linear solver is needed around
    the component (the implicit function theorem: d alpha*/d x = -(dR/d alpha*)^-1 dR/dx).

    Inputs
    ------
    lift_coefficient : float, (num_sections,)
        Sectional lift coefficient from the VLM, cl_VLM.
    reynolds : float, (num_sections,)
        Chord Reynolds number.
    mach : float, (num_sections,)
        Mach number.

    Outputs
    -------
    alpha_star : float, (num_sections,), rad
        Section angle of attack with cl_airfoil(alpha*) = cl_VLM.

    Options
    -------
    num_sections : int
        Number of spanwise sections (>= 1).
    airfoil : str, Polar, array_like or dict
        Anything :func:`~lpc_mdo.components.aero.airfoil.get_polar` takes; default 'ls413'.
    extension_slope : float
        Slope s of the linear continuation beyond the stall bracket, per rad (> 0).
    tolerance : float
        Residual tolerance of the inner solve (default 1e-13).
    max_iter : int
        Iteration limit of the inner solve; exceeding it raises om.AnalysisError.
    """

    def initialize(self):
        self.options.declare(
            "num_sections", default=1, types=int, lower=1, desc="Number of spanwise sections"
        )
        self.options.declare(
            "airfoil", default="ls413", desc="Airfoil name, table or Polar (see get_polar)"
        )
        self.options.declare(
            "extension_slope",
            default=2.0 * np.pi,
            types=float,
            lower=1e-3,
            desc="Lift slope beyond the stall bracket, per rad",
        )
        self.options.declare(
            "tolerance",
            default=1e-13,
            types=float,
            lower=0.0,
            desc="Residual tolerance of the inner solve",
        )
        self.options.declare(
            "max_iter", default=100, types=int, lower=1, desc="Iteration limit of the inner solve"
        )
        self.num_beyond_stall = 0

    def setup(self):
        n = self.options["num_sections"]
        self._polar = get_polar(self.options["airfoil"])
        self.add_input(
            "lift_coefficient", val=np.zeros(n), desc="Sectional lift coefficient from the VLM"
        )
        self.add_input("reynolds", val=1e6 * np.ones(n), desc="Chord Reynolds number")
        self.add_input("mach", val=np.zeros(n), desc="Mach number")
        self.add_output(
            "alpha_star",
            val=np.zeros(n),
            units="rad",
            desc="Section angle of attack with cl_airfoil = cl_VLM",
        )
        self.declare_partials("alpha_star", "lift_coefficient", diagonal=True, val=1.0)
        self.declare_partials("alpha_star", ["alpha_star", "reynolds", "mach"], diagonal=True)

    # ---------------------------------------------------------------------------- lift function

    def _lift(self, alpha, reynolds, mach, bracket=None):
        """g, dg/dalpha, dg/dRe, dg/dM (the bracketed, linearly continued lift curve)."""
        lo, hi, dlo_re, dhi_re, dlo_m, dhi_m = (
            bracket if bracket is not None else stall_bracket(self._polar, reynolds, mach)
        )
        s = self.options["extension_slope"]
        above, below = np.real(alpha) > np.real(hi), np.real(alpha) < np.real(lo)
        a_eval = np.where(above, hi, np.where(below, lo, alpha))
        v = self._polar.evaluate(a_eval, reynolds, mach)
        g = v.cl.copy()
        dg_da = v.dcl_dalpha.copy()
        dg_dre = v.dcl_dreynolds.copy()
        dg_dm = v.dcl_dmach.copy()
        for mask, edge, de_re, de_m in ((above, hi, dhi_re, dhi_m), (below, lo, dlo_re, dlo_m)):
            if np.any(mask):
                g[mask] += s * (alpha[mask] - edge[mask])
                dg_da[mask] = s
                dg_dre[mask] += (v.dcl_dalpha[mask] - s) * de_re[mask]
                dg_dm[mask] += (v.dcl_dalpha[mask] - s) * de_m[mask]
        return g, dg_da, dg_dre, dg_dm

    # ---------------------------------------------------------------------------- OpenMDAO API

    def apply_nonlinear(self, inputs, outputs, residuals):
        g = self._lift(outputs["alpha_star"], inputs["reynolds"], inputs["mach"])[0]
        residuals["alpha_star"] = inputs["lift_coefficient"] - g

    def solve_nonlinear(self, inputs, outputs):
        complex_step = any(
            np.iscomplexobj(inputs[n]) for n in ("lift_coefficient", "reynolds", "mach")
        )
        if complex_step:
            # Complex step: solve with the real parts, then one Newton step in complex
            # arithmetic carries the imaginary parts (the derivative) exactly, since the
            # Jacobian is exact at the converged real solution.
            self._solve(
                *(np.real(inputs[n]) for n in ("lift_coefficient", "reynolds", "mach")),
                guess=np.real(outputs["alpha_star"]),
            )
            alpha = self._solution.astype(complex)
            g, dg_da, _, _ = self._lift(alpha, inputs["reynolds"], inputs["mach"])
            outputs["alpha_star"] = alpha + (inputs["lift_coefficient"] - g) / dg_da
            return
        self._solve(
            inputs["lift_coefficient"],
            inputs["reynolds"],
            inputs["mach"],
            guess=outputs["alpha_star"],
        )
        outputs["alpha_star"] = self._solution

    def _solve(self, target, re, m, guess=None):
        """
        Solve for alpha* at every section.

        Newton starts from ``guess`` (the previous solution) where it lies inside a section's
        bracket; the bracket, and so the root, does not depend on it.
        """
        bad = ~(np.isfinite(target) & np.isfinite(re) & np.isfinite(m))
        if np.any(bad):
            raise om.AnalysisError(
                f"{self.msginfo}: non-finite lift_coefficient, reynolds or "
                f"mach at sections {np.flatnonzero(bad).tolist()}"
            )
        bracket = stall_bracket(self._polar, re, m)
        lo, hi = bracket[0].copy(), bracket[1].copy()
        s = self.options["extension_slope"]
        cl_lo = self._polar.evaluate(lo, re, m).cl
        cl_hi = self._polar.evaluate(hi, re, m).cl
        above, below = target >= cl_hi, target <= cl_lo
        self.num_beyond_stall = int(np.count_nonzero(above | below))
        alpha = np.where(
            above, hi + (target - cl_hi) / s, np.where(below, lo + (target - cl_lo) / s, 0.0)
        )
        inside = ~(above | below)
        if np.any(inside):
            alpha[inside] = self._bracketed_newton(
                target[inside],
                re[inside],
                m[inside],
                lo[inside],
                hi[inside],
                cl_lo[inside],
                cl_hi[inside],
                None if guess is None else np.array(guess, dtype=float)[inside],
            )
        self._solution = alpha

    def _bracketed_newton(self, target, re, m, a_lo, a_hi, f_lo, f_hi, guess=None):
        """Solve cl(alpha) = target on [a_lo, a_hi] with cl(a_lo) < target < cl(a_hi)."""

        def residual(alpha, idx):
            v = self._polar.evaluate(alpha, re[idx], m[idx])
            return v.cl - target[idx], v.dcl_dalpha

        return safeguarded_newton(
            residual,
            a_lo,
            a_hi,
            f_lower=f_lo - target,
            f_upper=f_hi - target,
            x0=guess,
            ftol=self.options["tolerance"],
            xtol_abs=4.0 * _EPS,
            xtol_rel=4.0 * _EPS,
            maxiter=self.options["max_iter"],
            indexed=True,
            variable="alpha*",
            units="rad",
            where=self.msginfo,
        )

    def linearize(self, inputs, outputs, partials):
        _, dg_da, dg_dre, dg_dm = self._lift(
            outputs["alpha_star"], inputs["reynolds"], inputs["mach"]
        )
        self._dr_da = -dg_da
        partials["alpha_star", "alpha_star"] = -dg_da
        partials["alpha_star", "reynolds"] = -dg_dre
        partials["alpha_star", "mach"] = -dg_dm

    def solve_linear(self, d_outputs, d_residuals, mode):
        if mode == "fwd":
            d_outputs["alpha_star"] = d_residuals["alpha_star"] / self._dr_da
        else:
            d_residuals["alpha_star"] = d_outputs["alpha_star"] / self._dr_da
