"""
Tabulated airfoil polars with smooth interpolation, Viterna and reverse-flow extrapolation.

Smooth (C1) interpolation over alpha, Reynolds and Mach, Viterna to +-90 deg and reverse flow to
+-180 deg (docs theory/aerodynamics 'Airfoil polars', 'Viterna extrapolation', 'Linear-quadratic
polar').

:func:`get_polar` turns an airfoil name ('naca0012', 'naca0015', 'ls413', 'ls417'), a user table
of (alpha [deg], cl, cd) at one Reynolds and Mach number (array, dict or file) or a ready
:class:`~lpc_mdo.components.aero.polar.Polar` into a Polar, so a user table works wherever an
airfoil name does.

How a :class:`TablePolar` is built from a table cl, cd(alpha, Re, M):

1. **Stall points of each (Re, M) slice** from the table: the positive stall angle is the first
   table angle at or above the angle nearest 0 deg whose cl is not exceeded within the next
   ``stall_window`` (3 deg), i.e. the first local maximum of cl that dominates the next 3 deg;
   the negative stall angle is the mirror image (first local minimum going down). If there is
   none, the end of the table is the stall point. (The first dominant extremum, not the global
   one: NeuralFoil's low-confidence post-stall values can climb again beyond 20 deg.) With a
   measured maximum lift against Mach number (``max_lift``; the shipped NACA 0012 has one,
   :mod:`~lpc_mdo.components.aero.compressible_stall`), a slice whose stall lift exceeds it
   has its stall points moved in to where the table's cl reaches +-that maximum.
2. **Composite polar of each slice** on -180..180 deg, exactly as
   :class:`~lpc_mdo.components.aero.polar.LinearQuadraticPolar` does it, with the table in place
   of the linear/quadratic law: the table (cubic Hermite in alpha with 3-point slopes) between
   the stall blends; cubic Hermite blends on [alpha_s - eps, alpha_s + eps] (eps = 1.5 deg)
   matching value and slope of the table at the inner end and of Viterna at the outer end;
   Viterna–Corrigan (AR = 10, CD_max = 1.29) from the stall point (alpha_s, cl_s, cd_s) to
   +-90 deg; the reverse-flow continuation to +-180 deg (with cd(180 deg) >= the slice's
   minimum table cd, see ``_find_stall``). Values and exact alpha slopes are
   sampled on a fixed alpha grid (0.25 deg where the tables and blends are, 2 deg elsewhere).
3. **Run time**: tensor-product interpolation of those samples: cubic Hermite in alpha with the
   stored exact slopes, and cubic Hermite with 3-point (parabola) slopes in ln Re and in M.
   Each factor is C1, so cl and cd are C1 in (alpha, Re, M) jointly, periodic and C1 across
   +-180 deg, and the analytic derivatives are those of the interpolant (complex-step safe:
   intervals are chosen from real parts).
4. **Stated range**: the table holds for Mach numbers up to its highest tabulated one and for
   Reynolds numbers up to its highest; a query above either (or a negative or non-finite one)
   raises ``om.AnalysisError`` naming the polar, the value and the range, so that a rotor or
   wing model never runs on values held at those edges. Below the lowest tabulated Reynolds
   number (2e4 for the rotor section) the lowest slice is used, a stated rule, not a range
   error: such sections are those at almost no relative velocity (an edgewise rotor's
   reverse-flow boundary, where U -> 0 at every speed; a blade root at low rotor speed), whose
   dynamic pressure is below 0.05 % of a tip's (U < 3 m/s on a 0.1 m chord), so their loads do
   not depend on the polar; raising there would stop every transition trim (measured: Re down
   to 2e3 at Pitt-Peters stations during the trim of the reference vehicle). An axis with a
   single value (a user table at one Reynolds and Mach number) holds for every value.

Tables shipped in ``lpc_mdo/data/airfoil_<name>.npz`` were made by
``run_scripts/make_airfoil_tables.py`` (NeuralFoil 0.3.3, an XFOIL-trained model, with
Prandtl–Glauert for Mach, and for the rotor section the Korn–Lock transonic drag rise up to
M = 0.9); ``lpc_mdo/data/README.md`` says how. Ranges: NACA 0012 (rotor blades) Re 2e4..1e7,
M 0..0.9; the wing and tail sections Re 1e5..1e7, M 0..0.6 (docs theory/aerodynamics 'Airfoil
polars').
"""

import collections
import functools
import os
import zipfile
from importlib import resources
from pathlib import Path

import numpy as np
import openmdao.api as om
from scipy.optimize import brentq

from .compressible_stall import naca0012_max_lift
from .hermite import HermiteAxis, tensor_eval
from .polar import (
    Polar,
    PolarValues,
    _hermite,
    reverse_flow,
    viterna,
    viterna_cd_max,
    viterna_coefficients,
    wrap_angle,
)
from .pressure_table import PressureTable

#: Airfoil names with a shipped table, and the aliases that map to them.
AIRFOIL_NAMES = ("naca0012", "naca0015", "ls413", "ls417")
_ALIASES = {
    "naca0012": "naca0012",
    "naca 0012": "naca0012",
    "n0012": "naca0012",
    "naca0015": "naca0015",
    "naca 0015": "naca0015",
    "n0015": "naca0015",
    "ls413": "ls413",
    "ls(1)-0413": "ls413",
    "gaw2": "ls413",
    "ga(w)-2": "ls413",
    "ls417": "ls417",
    "ls(1)-0417": "ls417",
    "gaw1": "ls417",
    "ga(w)-1": "ls417",
}

_DEG = np.pi / 180.0


def _alpha_hermite_weights(grid, a):
    """Window [2k .. 2k+3] and weights on a (value, slope)-interleaved alpha table."""
    k = np.clip(np.searchsorted(grid, np.real(a), side="right") - 1, 0, grid.size - 2)
    h = grid[k + 1] - grid[k]
    t = (a - grid[k]) / h
    t2, t3 = t * t, t * t * t
    w = np.stack(
        [2 * t3 - 3 * t2 + 1, (t3 - 2 * t2 + t) * h, -2 * t3 + 3 * t2, (t3 - t2) * h], axis=-1
    )
    dw = np.stack(
        [(6 * t2 - 6 * t) / h, 3 * t2 - 4 * t + 1, (-6 * t2 + 6 * t) / h, 3 * t2 - 2 * t], axis=-1
    )
    return 2 * k[:, None] + np.arange(4), w, dw


class _FixedConditions:
    """
    A TablePolar's (Re, M) interpolation at fixed query conditions, cached.

    The blade-element solvers evaluate the polar many times at the same Reynolds and Mach
    numbers (taken from the undisturbed velocity) while only the angle of attack changes: the
    BEM bracket, the Pitt–Peters inflow Newton and its per-station swirl Newton. For each query
    this keeps the (Re, M) weights and the table contracted over Re and M on the query's current
    alpha window (value, d/dRe, d/dM at the window's 4 Hermite nodes), so a repeated evaluation
    only contracts over alpha; queries whose window moved are recontracted. The sums are the
    same as :func:`tensor_eval`'s, in another order (equal to round-off).
    """

    def __init__(self, polar, reynolds, mach):
        (self.ir, wr, dwr), (self.im, wm, dwm) = polar._conditions(reynolds, mach)
        n, nb, nc = reynolds.size, wr.shape[1], wm.shape[1]
        # The three (Re, M) weightings of each query, (n, 1, b c, 3): value, d/dRe, d/dM.
        self.weights = np.stack(
            [
                wr[:, :, None] * wm[:, None, :],
                dwr[:, :, None] * wm[:, None, :],
                wr[:, :, None] * dwm[:, None, :],
            ],
            axis=-1,
        ).reshape(n, 1, nb * nc, 3)
        self.window = np.full(n, -1)
        self.contracted = np.zeros((n, 4, polar._composite_table.shape[-1], 3))

    def contract(self, table, ia):
        """(N, 4, n_values, 3): value, d/dRe, d/dM on each query's alpha window ``ia``."""
        stale = np.flatnonzero(ia[:, 0] != self.window)
        if stale.size:
            # Basic slicing when every query is stale (a new set of conditions): no copies.
            rows = slice(None) if stale.size == self.window.size else stale
            n_re, n_mach, nv = table.shape[1:]
            ir, im = self.ir[rows], self.im[rows]
            # The (alpha, Re, M) window of each query by its flat index into the table's rows
            # of n_values: one np.take, several times faster than fancy indexing on 3 axes.
            flat = ((ia[rows] * n_re)[:, :, None, None] + ir[:, None, :, None]) * n_mach + im[
                :, None, None, :
            ]
            g = np.take(table.reshape(-1, nv), flat, axis=0)
            n, _, nb, nc, _ = g.shape
            # The three (Re, M) weightings as one batched product: (n, 4, values, b c) @
            # (n, 1, b c, 3) -> (n, 4, values, 3).
            self.contracted[rows] = (
                g.reshape(n, 4, nb * nc, nv).transpose(0, 1, 3, 2) @ self.weights[rows]
            )
            self.window[rows] = ia[rows, 0]
        return self.contracted


#: Fixed-condition caches kept per TablePolar (the most recently used ones). One pass over the
#: full LPC model queries each of the two rotor/wing polars at about 40 sets of (Re, M) (one per
#: rotor and VLM component and condition); with 16 the pass evicted every set before its reuse
#: (the linearization after a run, a Newton iteration's next residual) and recontracted it.
#: 128 keeps about three passes: benchmark run_model 0.25-0.31 -> 0.17-0.19 s, totals
#: 0.80-0.94 -> 0.69-0.76 s (benchmark_lpc.py, two runs each), 10 MB.
_CONDITION_CACHE_SIZE = 128


# ------------------------------------------------------------------------------------------------


class TablePolar(Polar):
    """
    Airfoil polar from tables over (alpha, Re, M) with Viterna and reverse flow, C1 everywhere.

    See the module docstring for the construction. Implements
    :meth:`~lpc_mdo.components.aero.polar.Polar.evaluate`; also gives the stall angles
    (:meth:`stall_angles`, the alpha* bracket), the tabulated moment coefficient
    (:meth:`moment_coefficient`) and, for the wing airfoils, the pressure table
    (:attr:`pressure`, see :mod:`lpc_mdo.components.aero.pressure_table`).

    Parameters
    ----------
    alpha : array_like, (n_a,)
        Table angles of attack, rad, strictly increasing, inside (-90, 90) deg. At least 5.
    reynolds : array_like, (n_r,)
        Table Reynolds numbers (> 0, increasing); one value for a single-Re table.
    mach : array_like, (n_m,)
        Table Mach numbers (>= 0, increasing); one value for a single-Mach table.
    cl, cd : array_like, (n_a, n_r, n_m) (or (n_a,) for a single slice)
        Lift and drag coefficients; cd > 0.
    cm : array_like, optional
        Moment coefficient about the quarter chord, same shape (stored, used by
        :meth:`moment_coefficient`).
    name : str
        Label.
    blend : float
        Half width eps of the stall blends, rad (default 1.5 deg, as the reference).
    aspect_ratio : float
        Viterna aspect ratio (CD_max = 1.11 + 0.018 AR); default 10.
    stall_window : float
        Look-ahead of the stall search, rad (default 3 deg).
    pressure : object, optional
        A pressure table (see :mod:`lpc_mdo.components.aero.pressure_table`) attached as
        :attr:`pressure`.
    max_lift : callable, optional
        Measured maximum lift coefficient as a function of Mach number (array in, array out;
        ``inf`` where there is none): the stall points of the slices whose table exceeds it move
        in to it (:meth:`_cap_stall`).
    """

    def __init__(
        self,
        alpha,
        reynolds,
        mach,
        cl,
        cd,
        cm=None,
        *,
        name="table",
        blend=1.5 * _DEG,
        aspect_ratio=10.0,
        stall_window=3.0 * _DEG,
        pressure=None,
        max_lift=None,
    ):
        self.name = str(name)
        alpha = np.asarray(alpha, dtype=float)
        reynolds = np.atleast_1d(np.asarray(reynolds, dtype=float))
        mach = np.atleast_1d(np.asarray(mach, dtype=float))
        shape = (alpha.size, reynolds.size, mach.size)
        cl, cd = np.asarray(cl, dtype=float), np.asarray(cd, dtype=float)
        if cl.size == cd.size == np.prod(shape):  # e.g. (n_a,) for a single slice
            cl, cd = cl.reshape(shape), cd.reshape(shape)
        self._check(alpha, reynolds, mach, cl, cd, shape, blend)
        self.blend = float(blend)
        self.cd_max = viterna_cd_max(aspect_ratio)
        self.pressure = pressure
        self.table_alpha, self.table_reynolds, self.table_mach = alpha, reynolds, mach
        self.table_cl, self.table_cd = cl, cd
        self.table_cm = None if cm is None else np.asarray(cm, dtype=float).reshape(shape)

        self._alpha_axis = HermiteAxis(alpha)
        self._re_axis = HermiteAxis(reynolds, log=True)
        self._mach_axis = HermiteAxis(mach)
        self.max_lift = max_lift
        self._find_stall(stall_window)
        if max_lift is not None:
            self._cap_stall(max_lift)
        self._check_stall()
        self._extrapolation_coefficients()
        self._build_composite()

    # ------------------------------------------------------------------------------ construction

    def _check(self, alpha, reynolds, mach, cl, cd, shape, blend):
        def fail(field, value, allowed):
            raise ValueError(f"TablePolar '{self.name}': {field} = {value}; allowed: {allowed}.")

        if alpha.ndim != 1 or alpha.size < 5:
            fail("alpha", alpha, "a 1-D array of at least 5 angles")
        if not np.all(np.isfinite(alpha)) or np.any(np.diff(alpha) <= 0.0):
            fail("alpha", alpha, "finite and strictly increasing (duplicate angles?)")
        if alpha[0] <= -np.pi / 2 + blend or alpha[-1] >= np.pi / 2 - blend:
            fail(
                "alpha range (deg)",
                np.degrees([alpha[0], alpha[-1]]),
                "inside (-90 + blend, 90 - blend) deg; Viterna covers the rest",
            )
        if np.any(reynolds <= 0.0) or np.any(np.diff(reynolds) <= 0.0):
            fail("reynolds", reynolds, "> 0 and strictly increasing")
        if np.any(mach < 0.0) or np.any(mach >= 1.0) or np.any(np.diff(mach) <= 0.0):
            fail("mach", mach, "in [0, 1) and strictly increasing")
        for field, value in (("cl", cl), ("cd", cd)):
            value = np.asarray(value)
            if value.shape != shape:
                fail(f"{field} shape", value.shape, f"{shape} (alpha, reynolds, mach)")
            if not np.all(np.isfinite(value)):
                fail(field, "non-finite values", "finite numbers")
        if np.any(np.asarray(cd) <= 0.0):
            fail("cd", f"min {np.min(cd)}", "> 0")

    def _find_stall(self, window):
        """First dominant local max (min) of cl going up (down) from the angle nearest 0."""
        a, cl, cd = self.table_alpha, self.table_cl, self.table_cd
        i0 = int(np.argmin(np.abs(a)))
        n_r, n_m = cl.shape[1:]
        idx = np.zeros((2, n_r, n_m), dtype=int)
        for r in range(n_r):
            for m in range(n_m):
                c = cl[:, r, m]
                hi = a.size - 1
                for i in range(i0, a.size):
                    ahead = c[(a > a[i]) & (a <= a[i] + window + 1e-12)]
                    if ahead.size == 0 or c[i] >= ahead.max():
                        hi = i
                        break
                lo = 0
                for i in range(i0, -1, -1):
                    ahead = c[(a < a[i]) & (a >= a[i] - window - 1e-12)]
                    if ahead.size == 0 or c[i] <= ahead.min():
                        lo = i
                        break
                idx[:, r, m] = (lo, hi)
        self.alpha_stall = a[idx]  # (2, n_r, n_m), rad
        grid = np.indices(idx.shape[1:])
        self.cl_stall = cl[idx, grid[0][None], grid[1][None]]
        self.cd_stall = cd[idx, grid[0][None], grid[1][None]]
        # Half width of each slice's stall blends: ``blend``, or less where a compressibility
        # stall (_cap_stall) comes within 2 blend of 0 deg.
        self.slice_blend = np.full(n_r * n_m, self.blend).reshape(n_r, n_m)

    def _cap_stall(self, max_lift):
        """
        Move the stall points down to the measured maximum lift ``max_lift(M)``.

        Module docstring step 1; :mod:`~lpc_mdo.components.aero.compressible_stall`. In a slice
        whose table cl at its stall point exceeds c = max_lift(M), the positive stall point
        becomes the angle where the table's cl (the run-time cubic Hermite in alpha) reaches c,
        found by bisection to 1e-12 rad, and the negative one where it reaches -c; cl there is
        c (-c) and cd the table's. The slice's blend half width becomes at most 0.45 of the
        smaller stall angle, so the blends stay on their side of 0 deg.
        """
        ceiling = np.asarray(max_lift(self.table_mach), dtype=float)[None, :]  # (1, n_m)
        a0 = self.table_alpha[int(np.argmin(np.abs(self.table_alpha)))]
        for side, sign in ((1, 1.0), (0, -1.0)):
            target = np.broadcast_to(sign * ceiling, self.cl_stall[side].shape)
            capped = sign * self.cl_stall[side] > sign * target
            if not capped.any():
                continue
            lo = np.full(target.shape, a0)
            hi = self.alpha_stall[side].copy()
            for _ in range(60):
                mid = 0.5 * (lo + hi)
                below = sign * self._table_at(mid)[0] < sign * target
                lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
            alpha = np.where(capped, 0.5 * (lo + hi), self.alpha_stall[side])
            cd = self._table_at(alpha)[1]
            self.alpha_stall[side] = alpha
            self.cl_stall[side] = np.where(capped, target, self.cl_stall[side])
            self.cd_stall[side] = np.where(capped, cd, self.cd_stall[side])
        smallest = np.minimum(-self.alpha_stall[0], self.alpha_stall[1])
        self.slice_blend = np.minimum(self.blend, 0.45 * smallest)

    def _check_stall(self):
        eps = self.slice_blend
        if np.any(self.alpha_stall[0] > -2 * eps) or np.any(self.alpha_stall[1] < 2 * eps):
            raise ValueError(
                f"TablePolar '{self.name}': stall angles (deg) "
                f"{np.degrees(self.alpha_stall.min()):.2f}..{np.degrees(self.alpha_stall.max()):.2f}"
                f" found from the table; allowed: negative stall < -2 blend and positive stall > "
                f"2 blend (the table must cover the attached range on both sides of 0 deg)."
            )
        if np.any(self.cl_stall[0] >= self.cl_stall[1]):
            raise ValueError(
                f"TablePolar '{self.name}': cl at negative stall >= cl at positive "
                f"stall; allowed: cl increasing through the attached range."
            )

    def _extrapolation_coefficients(self):
        cd = self.table_cd
        # Viterna's drag rises to CD_max at 90 deg; a stall drag above it (the rotor table's
        # Korn-Lock wave drag at the Prandtl-Glauert stall lift beyond M 0.8, where the section
        # is far past drag divergence) would make the post-stall and reverse-flow drag fall
        # below zero, so the extrapolation starts from at most CD_max (the table up to the stall
        # point is unchanged; the stall blend joins the two).
        self._a2, self._b2 = viterna_coefficients(
            self.alpha_stall, self.cl_stall, np.minimum(self.cd_stall, self.cd_max), self.cd_max
        )
        # Reverse flow (polar.reverse_flow) has cd(+-180 deg) = -B_m; B_m is the mean of the two
        # sides' B2 as in LinearQuadraticPolar, capped at -(the slice's minimum table cd) so the
        # drag at 180 deg is never below the forward minimum drag (low-Re slices with early
        # stall have B2 > 0 and would otherwise give cd < 0 near 180 deg).
        self._b_mean = np.minimum(0.5 * (self._b2[0] + self._b2[1]), -cd.min(axis=0))

    def _table_slices(self, a):
        """Table cl, cd and alpha slopes at angles a (n,), every slice: arrays (n, n_r, n_m)."""
        a_clip = np.clip(a, self.table_alpha[0], self.table_alpha[-1])
        index, w, dw = self._alpha_axis.weights(a_clip)
        out = []
        for table in (self.table_cl, self.table_cd):
            g = table[index]  # (n, width, n_r, n_m)
            out.append((np.einsum("nj,njrm->nrm", w, g), np.einsum("nj,njrm->nrm", dw, g)))
        return out[0][0], out[1][0], out[0][1], out[1][1]

    def _composite_grid(self):
        eps = self.blend
        lo = min(np.min(self.alpha_stall[0]) - eps, self.table_alpha[0], -30 * _DEG)
        hi = max(np.max(self.alpha_stall[1]) + eps, self.table_alpha[-1], 30 * _DEG)
        fine = np.arange(np.floor(lo / _DEG / 2) * 2, np.ceil(hi / _DEG / 2) * 2 + 1e-9, 0.25)
        left = np.arange(-180.0, fine[0] - 1e-9, 2.0)
        right = np.arange(180.0, fine[-1] + 1e-9, -2.0)[::-1]
        return np.concatenate([left, fine, right]) * _DEG

    def _composite(self, a):
        """Composite cl, cd and slopes at grid angles a (n,) for every slice: (n, n_r, n_m)."""
        eps = self.slice_blend
        n = a.size
        shape = (n,) + self.alpha_stall.shape[1:]
        aa = np.broadcast_to(a[:, None, None], shape)
        a_neg, a_pos = (np.broadcast_to(s, shape) for s in self.alpha_stall)
        half_pi = 0.5 * np.pi
        out = [np.zeros(shape) for _ in range(4)]

        tab = self._table_slices(a)
        attached = (aa >= a_neg + eps) & (aa <= a_pos - eps)
        for o, v in zip(out, tab, strict=True):
            o[attached] = v[attached]

        def stall_params(side, mask):
            sel = np.nonzero(mask)[1:]
            return self._a2[side][sel], self._b2[side][sel]

        for side, mask in (
            (0, (aa >= -half_pi) & (aa < a_neg - eps)),
            (1, (aa > a_pos + eps) & (aa <= half_pi)),
        ):
            a2, b2 = stall_params(side, mask)
            for o, v in zip(out, viterna(aa[mask], self.cd_max, a2, b2), strict=True):
                o[mask] = v
        for side, mask in ((0, aa < -half_pi), (1, aa > half_pi)):
            sel = np.nonzero(mask)[1:]
            values = reverse_flow(aa[mask], self.cd_max, self._b2[side][sel], self._b_mean[sel])
            for o, v in zip(out, values, strict=True):
                o[mask] = v
        # Stall blends: Hermite between the table at the inner end and Viterna at the outer end.
        for side in (0, 1):
            a_s = self.alpha_stall[side]
            x0, x1 = a_s - eps, a_s + eps
            inner = x1 if side == 0 else x0
            outer = x0 if side == 0 else x1
            t_cl, t_cd, t_dcl, t_dcd = self._table_at(inner)
            v_cl, v_cd, v_dcl, v_dcd = viterna(outer, self.cd_max, self._a2[side], self._b2[side])
            if side == 0:
                ends = ((v_cl, v_dcl, t_cl, t_dcl), (v_cd, v_dcd, t_cd, t_dcd))
            else:
                ends = ((t_cl, t_dcl, v_cl, v_dcl), (t_cd, t_dcd, v_cd, v_dcd))
            mask = (aa >= x0[None]) & (aa <= x1[None])
            if side == 0:
                mask &= aa < a_neg + eps
            else:
                mask &= aa > a_pos - eps
            sel = np.nonzero(mask)[1:]
            for (f0, d0, f1, d1), (o_f, o_d) in zip(
                ends, ((out[0], out[2]), (out[1], out[3])), strict=True
            ):
                f, df = _hermite(aa[mask], x0[sel], x1[sel], f0[sel], d0[sel], f1[sel], d1[sel])
                o_f[mask], o_d[mask] = f, df
        return out

    def _table_at(self, a_slice):
        """Table cl, cd and slopes at one angle per slice a_slice (n_r, n_m)."""
        n_r, n_m = a_slice.shape
        index, w, dw = self._alpha_axis.weights(
            np.clip(a_slice.ravel(), self.table_alpha[0], self.table_alpha[-1])
        )
        r, m = np.meshgrid(np.arange(n_r), np.arange(n_m), indexing="ij")
        r, m = r.ravel()[:, None], m.ravel()[:, None]
        out = []
        for table in (self.table_cl, self.table_cd):
            g = table[index, r, m]
            out.append(
                (np.sum(w * g, axis=1).reshape(n_r, n_m), np.sum(dw * g, axis=1).reshape(n_r, n_m))
            )
        return out[0][0], out[1][0], out[0][1], out[1][1]

    def _build_composite(self):
        grid = self._composite_grid()
        cl, cd, dcl, dcd = self._composite(grid)
        n_g = grid.size
        table = np.empty((2 * n_g,) + cl.shape[1:] + (2,))
        table[0::2, ..., 0], table[1::2, ..., 0] = cl, dcl
        table[0::2, ..., 1], table[1::2, ..., 1] = cd, dcd
        self.alpha_grid = grid
        self._composite_table = table
        stall = np.moveaxis(self.alpha_stall, 0, -1)  # (n_r, n_m, 2)
        self._stall_table = stall[None]  # (1, n_r, n_m, 2)
        self._max_lift_table = np.moveaxis(self.cl_stall, 0, -1)[None]  # (1, n_r, n_m, 2)

    # ------------------------------------------------------------------------------ evaluation

    def _fixed_conditions(self, reynolds, mach):
        """Return the cached :class:`_FixedConditions` of these query conditions (made if new)."""
        caches = self.__dict__.setdefault("_condition_caches", collections.OrderedDict())
        key = (reynolds.shape, reynolds.tobytes(), mach.tobytes())
        cache = caches.get(key)
        if cache is not None:
            caches.move_to_end(key)  # most recently used last
            return cache
        cache = caches[key] = _FixedConditions(self, reynolds, mach)
        while len(caches) > _CONDITION_CACHE_SIZE:
            caches.popitem(last=False)
        return cache

    def __getstate__(self):
        state = dict(self.__dict__)
        state.pop("_condition_caches", None)  # a cache, not part of the polar
        return state

    def check_conditions(self, reynolds, mach):
        """
        Raise ``om.AnalysisError`` if a query lies outside the table's Reynolds or Mach range.

        The table's stated range (module docstring, 'Stated range'): Mach numbers in
        [0, highest tabulated], Reynolds numbers in [0, highest tabulated] (below the lowest
        tabulated one the lowest slice is used); an axis with a single value holds for every
        value. The message names the polar, the extreme value queried and the range.
        """
        for label, values, grid in (
            ("Reynolds number", reynolds, self.table_reynolds),
            ("Mach number", mach, self.table_mach),
        ):
            if grid.size < 2:
                continue
            real = np.real(np.asarray(values))
            if real.size == 0:
                continue
            low, high = float(np.min(real)), float(np.max(real))
            floor = 0.0 if label == "Reynolds number" else grid[0]
            if low < floor or high > grid[-1] or not (np.isfinite(low) and np.isfinite(high)):
                raise om.AnalysisError(
                    f"airfoil polar '{self.name}': {label} {low:.4g}..{high:.4g} queried; the "
                    f"table holds for {floor:.4g}..{grid[-1]:.4g} (docs theory/aerodynamics "
                    f"'Airfoil polars'). A section outside it is outside the model's stated "
                    f"range: keep the design inside (tip-Mach and chord constraints) or supply "
                    f"a table that covers it."
                )

    def _conditions(self, reynolds, mach):
        self.check_conditions(reynolds, mach)
        ir, wr, dwr = self._re_axis.weights(reynolds)
        im, wm, dwm = self._mach_axis.weights(mach)
        return (ir, wr, dwr), (im, wm, dwm)

    def evaluate(self, alpha, reynolds, mach):
        alpha, reynolds, mach = np.broadcast_arrays(
            np.asarray(alpha), np.asarray(reynolds), np.asarray(mach)
        )
        shape = alpha.shape
        a = wrap_angle(alpha).ravel()
        ia, wa, dwa = _alpha_hermite_weights(self.alpha_grid, a)
        re, m = reynolds.ravel(), mach.ravel()
        if np.iscomplexobj(re) or np.iscomplexobj(m):
            (ir, wr, dwr), (im, wm, dwm) = self._conditions(re, m)
            values = tensor_eval(self._composite_table, (ia, ir, im), (wa, wr, wm), (dwa, dwr, dwm))
        else:
            c = self._fixed_conditions(re, m).contract(self._composite_table, ia)
            value = np.einsum("nasj,na->nsj", c, wa)
            values = (
                value[..., 0],
                np.einsum("nas,na->ns", c[..., 0], dwa),
                value[..., 1],
                value[..., 2],
            )
        out = [v[:, f].reshape(shape) for f in (0, 1) for v in values]
        return PolarValues(
            cl=out[0],
            dcl_dalpha=out[1],
            dcl_dreynolds=out[2],
            dcl_dmach=out[3],
            cd=out[4],
            dcd_dalpha=out[5],
            dcd_dreynolds=out[6],
            dcd_dmach=out[7],
        )

    def stall_angles(self, reynolds, mach):
        """
        Negative and positive stall angles at (Re, M), interpolated like the polar.

        Returns
        -------
        tuple of ndarray
            (alpha_neg, alpha_pos, dneg_dre, dpos_dre, dneg_dm, dpos_dm), each of the broadcast
            shape of the inputs; angles in rad.
        """
        return self._pair_at_conditions(self._stall_table, reynolds, mach)

    def max_lift_coefficients(self, reynolds, mach):
        """
        Section maximum and minimum lift coefficients at (Re, M), interpolated like the polar.

        The table's cl at each slice's positive and negative stall points (step 1 of the module
        docstring: the first dominant extremum of cl going up and down from the angle nearest
        0 deg), interpolated over (ln Re, M) with the same C1 cubic Hermite axes as
        :meth:`stall_angles`, so at a tabulated (Re, M) it is the table's own cl there. These
        are the section's cl_max and cl_min as the table gives them; the composite polar's
        stall blend (eps = ``blend``) rounds the peak, so :meth:`evaluate` at the stall angle
        gives up to 3 % less (the wing tables, measured). Queries outside the stated Reynolds
        and Mach range raise ``om.AnalysisError`` (:meth:`check_conditions`).

        Returns
        -------
        tuple of ndarray
            (cl_min, cl_max, dmin_dre, dmax_dre, dmin_dm, dmax_dm), each of the broadcast shape
            of the inputs (cl_min < 0 < cl_max for a section with a negative stall).
        """
        return self._pair_at_conditions(self._max_lift_table, reynolds, mach)

    def _pair_at_conditions(self, table, reynolds, mach):
        """
        Interpolate a (negative, positive) pair table over (ln Re, M) at each query point.

        Returns (neg, pos, dneg_dre, dpos_dre, dneg_dm, dpos_dm), each of the broadcast shape
        of ``reynolds`` and ``mach``.
        """
        reynolds, mach = np.broadcast_arrays(np.asarray(reynolds), np.asarray(mach))
        shape = reynolds.shape
        (ir, wr, dwr), (im, wm, dwm) = self._conditions(reynolds.ravel(), mach.ravel())
        zero_idx = np.zeros((ir.shape[0], 1), dtype=int)
        one = np.ones((ir.shape[0], 1))
        v, _, d_r, d_m = tensor_eval(
            table, (zero_idx, ir, im), (one, wr, wm), (0.0 * one, dwr, dwm)
        )
        return tuple(x[:, s].reshape(shape) for x in (v, d_r, d_m) for s in (0, 1))

    def moment_coefficient(self, alpha, reynolds, mach):
        """
        Tabulated quarter-chord moment coefficient and its derivatives (alpha, Re, M).

        Pre-stall table only: alpha is clamped to the table range (no post-stall model).

        Returns
        -------
        tuple of ndarray
            (cm, dcm_dalpha, dcm_dreynolds, dcm_dmach).
        """
        if self.table_cm is None:
            raise ValueError(f"TablePolar '{self.name}' has no cm table")
        alpha, reynolds, mach = np.broadcast_arrays(
            np.asarray(alpha), np.asarray(reynolds), np.asarray(mach)
        )
        shape = alpha.shape
        ia, wa, dwa = self._alpha_axis.weights(wrap_angle(alpha).ravel())
        (ir, wr, dwr), (im, wm, dwm) = self._conditions(reynolds.ravel(), mach.ravel())
        values = tensor_eval(self.table_cm, (ia, ir, im), (wa, wr, wm), (dwa, dwr, dwm))
        return tuple(v.reshape(shape) for v in values)

    # ------------------------------------------------------------------------------ constructors

    @classmethod
    def from_npz(cls, path, **kwargs):
        """Load a table in the ``lpc_mdo/data/airfoil_<name>.npz`` format (alpha in degrees).

        The content must be a zip archive of arrays (a text file named ``.npz`` is an error that
        names the path); the arrays pass :func:`check_polar_file_arrays`.
        """
        with open(path, "rb") as fh:
            head = fh.read(4)
        if head not in (b"PK\x03\x04", b"PK\x05\x06"):
            raise ValueError(
                f"polar file '{path}' is not an .npz archive (it starts with {head!r}); allowed: "
                f"an .npz written by numpy.savez, or a text table (alpha [deg], cl, cd) named "
                f"{', '.join(_TEXT_SUFFIXES)}"
            )
        try:
            data = np.load(path, allow_pickle=False)
        except (OSError, ValueError, EOFError, zipfile.BadZipFile) as exc:
            raise ValueError(f"polar file '{path}' is not a readable .npz archive: {exc}") from exc
        with data:
            keys = set(data.files)
            missing = {"alpha_deg", "cl", "cd"} - keys
            if missing:
                raise ValueError(
                    f"{path}: missing arrays {sorted(missing)}; an airfoil table "
                    f"needs alpha_deg, cl, cd (and optionally reynolds, mach, cm)"
                )
            try:
                alpha_deg, cl, cd = (
                    np.asarray(data[k], dtype=float) for k in ("alpha_deg", "cl", "cd")
                )
            except (ValueError, TypeError) as exc:
                raise ValueError(f"polar file '{path}': arrays are not numbers: {exc}") from exc
            check_polar_file_arrays(path, alpha_deg, cl, cd)
            alpha = np.radians(alpha_deg)
            reynolds = data["reynolds"] if "reynolds" in keys else np.array([1e6])
            mach = data["mach"] if "mach" in keys else np.array([0.0])
            cm = data["cm"] if "cm" in keys else None
            name = str(data["name"]) if "name" in keys else Path(path).stem
            pressure = None
            if "cp_upper" in keys:
                missing = sorted(set(_PRESSURE_ARRAYS) - keys)
                if missing:
                    raise ValueError(
                        f"{path}: has cp_upper but misses the pressure arrays {missing}; a "
                        f"pressure table needs {', '.join(_PRESSURE_ARRAYS)} (or none of them)"
                    )
                pressure = PressureTable.from_npz_data(data)
            try:
                return cls(
                    alpha, reynolds, mach, cl, cd, cm, name=name, pressure=pressure, **kwargs
                )
            except ValueError as exc:  # shapes of cm, reynolds, mach against cl
                raise ValueError(f"polar file '{path}': {exc}") from exc

    @classmethod
    def from_alpha_cl_cd(
        cls, alpha_deg, cl, cd, reynolds=1e6, mach=0.0, name="user table", **kwargs
    ):
        """
        Build a single-(Re, M) polar from a table of alpha [deg], cl, cd (any order; sorted here).

        Reynolds and Mach derivatives are zero (the table holds for every Re and M).
        """
        alpha_deg, cl, cd = (np.asarray(v, dtype=float).ravel() for v in (alpha_deg, cl, cd))
        if not alpha_deg.size == cl.size == cd.size:
            raise ValueError(
                f"{name}: alpha, cl and cd have lengths {alpha_deg.size}, {cl.size},"
                f" {cd.size}; allowed: equal lengths"
            )
        if alpha_deg.size and np.ptp(alpha_deg) < 2.0:
            raise ValueError(
                f"{name}: alpha spans {np.ptp(alpha_deg):.3g} deg; tables give alpha "
                f"in degrees over the attached range and past both stall points"
            )
        order = np.argsort(alpha_deg, kind="stable")
        return cls(
            np.radians(alpha_deg[order]),
            [reynolds],
            [mach],
            cl[order],
            cd[order],
            name=name,
            **kwargs,
        )

    @classmethod
    def from_text(cls, path, **kwargs):
        """
        Read a polar text file of alpha [deg], cl, cd rows (and cm where the header names it).

        Every line with at least three numbers gives alpha [deg], cl, cd (its first three
        columns); other lines (headers, comments) are skipped, so XFOIL polar files (alpha CL CD
        CDp CM ...) load as they are. A header line whose words start with ``alpha`` and hold
        ``CM`` (XFOIL's column line) makes that column the quarter-chord moment coefficient:
        every row must then have it. The file must be UTF-8 text (a UTF-8 BOM is accepted) and
        its rows must pass :func:`check_polar_file_arrays`.
        """
        with open(path, "rb") as fh:
            raw = fh.read()
        if raw[:4] == b"PK\x03\x04":
            raise ValueError(
                f"polar file '{path}' is an .npz (zip) archive; allowed: name it .npz, or give a "
                f"text table of alpha [deg], cl, cd rows"
            )
        if b"\0" in raw:
            raise ValueError(
                f"polar file '{path}' is binary (it holds NUL bytes); allowed: a text table of "
                f"alpha [deg], cl, cd rows, or an .npz archive named .npz"
            )
        try:
            text = raw.decode("utf-8-sig")
        except UnicodeDecodeError as exc:
            raise ValueError(
                f"polar file '{path}' is not UTF-8 text (byte {exc.start}); allowed: a UTF-8 "
                f"text table of alpha [deg], cl, cd rows"
            ) from exc
        rows, cm_column, cm = [], None, []
        for number, line in enumerate(text.splitlines(), start=1):
            parts = line.replace(",", " ").split()
            words = [p.lower() for p in parts]
            if cm_column is None and words[:1] == ["alpha"] and "cm" in words:
                cm_column = words.index("cm")
                continue
            try:
                values = [float(p) for p in parts[:3]]
            except ValueError:
                continue
            if len(values) < 3:
                continue
            rows.append(values)
            if cm_column is not None:
                try:
                    cm.append(float(parts[cm_column]))
                except (IndexError, ValueError):
                    raise ValueError(
                        f"polar file '{path}': line {number} has no number in the CM column "
                        f"({cm_column + 1}) its header names; allowed: every row with all the "
                        "header's columns"
                    ) from None
        if len(rows) < _MIN_POLAR_ROWS:
            raise ValueError(
                f"{path}: found {len(rows)} rows of (alpha [deg], cl, cd); allowed:"
                f" a text table with at least {_MIN_POLAR_ROWS} such rows"
            )
        rows = np.array(rows)
        check_polar_file_arrays(path, rows[:, 0], rows[:, 1], rows[:, 2])
        kwargs.setdefault("name", Path(path).stem)
        if cm_column is not None and len(cm) == len(rows):
            if not np.all(np.isfinite(cm)) or np.max(np.abs(cm)) > POLAR_MAX_ABS_CM:
                raise ValueError(
                    f"polar file '{path}': the CM column holds {max(cm, key=abs)!r}; allowed: "
                    f"finite moment coefficients within +-{POLAR_MAX_ABS_CM:g}"
                )
            kwargs.setdefault("cm", np.asarray(cm))  # rows are in increasing alpha (checked)
        return cls.from_alpha_cl_cd(rows[:, 0], rows[:, 1], rows[:, 2], **kwargs)


#: Fewest and most alpha rows of a polar file (the interpolation builds an n x n matrix: 2000
#: rows are 32 MB; tables resolve a polar with 100-200).
_MIN_POLAR_ROWS = 5
_MAX_POLAR_ROWS = 2000
#: The arrays of a pressure table in an .npz polar (:class:`PressureTable`).
_PRESSURE_ARRAYS = (
    "cp_alpha_deg", "cp_reynolds", "cp_mach", "x", "y_upper", "y_lower", "cp_upper", "cp_lower"
)  # fmt: skip
#: Angles (deg) a polar file must cover: the attached range of a blade section in hover,
#: transition and cruise. The stall detection needs a stall point beyond +-2 blends (3 deg) on
#: each side, and past the table's ends the Viterna extrapolation from its stall points takes
#: over, so a table that stops short of +10 deg would put stall where the section is attached.
POLAR_FILE_ALPHA_SPAN_DEG = (-5.0, 10.0)
_TEXT_SUFFIXES = (".txt", ".dat", ".csv", ".pol")
#: Physical ranges of a section's coefficients in the attached range
#: (:data:`POLAR_FILE_ALPHA_SPAN_DEG`): the largest lift coefficient of a single-element airfoil
#: is about 2 (Abbott & von Doenhoff, Theory of Wing Sections, 1959, appendix IV; the shipped
#: NACA 0012 table reaches 2.57 at M 0.9 by Prandtl-Glauert), and no drag exceeds that of a
#: flat plate normal to the flow, 1.98 in 2-D (Hoerner, Fluid-Dynamic Drag, 1965, ch. 3);
#: beyond 3 and 2 a table is in percent or in another unit.
POLAR_MAX_ABS_CL = 3.0
POLAR_MAX_CD = 2.0
#: Largest magnitude of cm about the quarter chord a polar file may hold: a flat plate normal to
#: the flow has its centre of pressure at mid-chord, a quarter-chord moment of magnitude
#: 0.25 x 1.98 = 0.5 (Hoerner, ch. 3); highly cambered sections stay within 0.3 in the attached
#: range (Abbott & von Doenhoff, appendix IV); 1 catches a column of other numbers.
POLAR_MAX_ABS_CM = 1.0
#: Lift-curve slope of a polar file between -2 and +6 deg, per rad, as fractions of thin-airfoil
#: theory's 2 pi: measured sections lie near 0.9 x 2 pi (Abbott & von Doenhoff, appendix IV:
#: 0.098-0.11 per deg), low-Reynolds rotor sections down to about 0.7 x 2 pi. Checked at the
#: table's lowest Mach number (compressibility raises it by 1/sqrt(1 - M^2)). Outside: no lift,
#: a table of other columns (cd for cl) or a slope per degree read as per radian.
POLAR_LIFT_SLOPE_RANGE = (0.4, 1.3)
#: Least minimum drag coefficient in the attached range: two sides of a flat plate in laminar
#: flow at Re 1e7, 2 x 1.328/sqrt(Re) = 0.00084 (Blasius; Hoerner, Fluid-Dynamic Drag, ch. 2);
#: no section has less. Most (the smallest cd of the table) at most 0.1, a bluff section.
POLAR_CD_MIN_RANGE = (0.0008, 0.1)


def check_polar_file_arrays(path, alpha_deg, cl, cd):
    """Check the arrays of a polar file; raise a ValueError naming the path and the problem.

    ``alpha_deg`` is 1-D, at least 5 finite angles, strictly increasing (a repeated angle is an
    error) and covering :data:`POLAR_FILE_ALPHA_SPAN_DEG`; ``cl`` and ``cd`` are finite with
    ``cd > 0`` and have as many rows as ``alpha_deg`` (further axes are Reynolds and Mach).
    """
    alpha_deg, cl, cd = (np.asarray(v, dtype=float) for v in (alpha_deg, cl, cd))

    def fail(what):
        raise ValueError(f"polar file '{path}': {what}")

    if alpha_deg.ndim != 1 or not _MIN_POLAR_ROWS <= alpha_deg.size <= _MAX_POLAR_ROWS:
        fail(
            f"alpha has shape {alpha_deg.shape}; allowed: {_MIN_POLAR_ROWS} to "
            f"{_MAX_POLAR_ROWS} angles"
        )
    for label, values in (("alpha", alpha_deg), ("cl", cl), ("cd", cd)):
        bad = ~np.isfinite(values)
        if np.any(bad):
            row = int(np.argwhere(bad)[0][0])
            fail(
                f"{label} in row {row} is {float(values.reshape(values.shape[0], -1)[row][0])!r}; "
                f"allowed: finite numbers"
            )
        if values.shape[:1] != alpha_deg.shape:
            fail(
                f"{label} has {values.shape[0] if values.ndim else 0} rows and alpha "
                f"{alpha_deg.size}; allowed: one row per angle"
            )
    step = np.diff(alpha_deg)
    if np.any(step <= 0.0):
        i = int(np.argmax(step <= 0.0))
        fail(
            f"alpha is not strictly increasing: row {i + 1} = {alpha_deg[i + 1]:g} deg after "
            f"{alpha_deg[i]:g} deg; allowed: increasing angles without repeats"
        )
    if np.any(cd <= 0.0):
        fail(f"cd has the value {float(np.min(cd)):g}; allowed: cd > 0")
    lo, hi = POLAR_FILE_ALPHA_SPAN_DEG
    attached = (alpha_deg >= lo) & (alpha_deg <= hi)
    for label, values, limit in (("cl", cl, POLAR_MAX_ABS_CL), ("cd", cd, POLAR_MAX_CD)):
        beyond = np.abs(values) > limit
        beyond &= attached.reshape((-1,) + (1,) * (values.ndim - 1))
        if np.any(beyond):
            index = tuple(int(i) for i in np.argwhere(beyond)[0])
            fail(
                f"{label} = {float(values[index]):g} at alpha {alpha_deg[index[0]]:g} deg (row "
                f"{index[0]}); allowed in the attached range {lo:g}..{hi:g} deg: |cl| <= "
                f"{POLAR_MAX_ABS_CL:g}, cd <= {POLAR_MAX_CD:g} (coefficients, not percent)"
            )
    if alpha_deg[0] > lo or alpha_deg[-1] < hi:
        fail(
            f"alpha spans {alpha_deg[0]:g}..{alpha_deg[-1]:g} deg; allowed: a table that "
            f"covers at least {lo:g}..{hi:g} deg (the attached range the rotor model needs)"
        )
    # The lift slope between -2 and 6 deg and the least drag at every Reynolds number of the
    # lowest Mach number (tables run alpha, Reynolds, Mach: the Mach axis, if any, is the third;
    # at transonic Mach numbers drag rise and compressibility leave these ranges).
    columns = (cl[:, :, 0] if cl.ndim == 3 else cl).reshape(alpha_deg.size, -1)
    slope = (
        np.array([np.interp(6.0, alpha_deg, c) - np.interp(-2.0, alpha_deg, c) for c in columns.T])
        / np.radians(8.0)
        / (2.0 * np.pi)
    )
    low, high = POLAR_LIFT_SLOPE_RANGE
    if np.any((slope < low) | (slope > high)):
        worst = float(slope[np.argmax(np.abs(slope - 0.9))])
        fail(
            f"the lift-curve slope between -2 and 6 deg is {worst:.3g} x 2 pi per rad; allowed: "
            f"{low:g} to {high:g} x 2 pi (a lifting section; columns alpha [deg], cl, cd in "
            "this order, cl per radian of alpha)"
        )
    drag = (cd[:, :, 0] if cd.ndim == 3 else cd).reshape(alpha_deg.size, -1)
    least = np.min(np.where(attached[:, None], drag, np.inf), axis=0)
    low, high = POLAR_CD_MIN_RANGE
    if np.any((least < low) | (least > high)):
        worst = float(least[np.argmax(np.abs(np.log(least / 0.01)))])
        fail(
            f"the least drag coefficient in {lo:g}..{hi:g} deg is {worst:g}; allowed: {low:g} "
            f"to {high:g} (below: less than laminar skin friction; above: not a lifting "
            "section, or drag in percent)"
        )


# ------------------------------------------------------------------------------------------------


def zero_lift_angle(polar, reynolds, mach):
    """Angle of attack (rad) where a polar's cl vanishes, bracketed in [-20, +10] deg."""

    def cl(alpha):
        return float(polar.evaluate(np.array(alpha), reynolds, mach).cl)

    return float(brentq(cl, np.radians(-20.0), np.radians(10.0), xtol=1e-12))


def airfoil_table_path(name):
    """Path of the shipped table of an airfoil name (see :data:`AIRFOIL_NAMES`)."""
    key = _ALIASES.get(str(name).strip().lower())
    if key is None:
        raise ValueError(
            f"airfoil = {name!r}; allowed: {', '.join(AIRFOIL_NAMES)}, a file "
            f"(.npz or text with alpha [deg], cl, cd columns), an (n, 3) table or a "
            f"Polar"
        )
    return Path(str(resources.files("lpc_mdo") / "data" / f"airfoil_{key}.npz"))


#: Measured maximum lift against Mach number of the shipped sections that have it: the tables'
#: stall points move down to it (:mod:`~lpc_mdo.components.aero.compressible_stall`).
_MEASURED_MAX_LIFT = {"naca0012": naca0012_max_lift}


@functools.lru_cache(maxsize=None)
def _named_polar(key):
    return TablePolar.from_npz(airfoil_table_path(key), max_lift=_MEASURED_MAX_LIFT.get(key))


def get_polar(airfoil):
    """
    Get a :class:`~lpc_mdo.components.aero.polar.Polar` from an airfoil name, a table or a Polar.

    Parameters
    ----------
    airfoil : str, os.PathLike, Polar, array_like or dict
        - a name: 'naca0012', 'naca0015', 'ls413' (= GA(W)-2, LS(1)-0413), 'ls417' (= GA(W)-1,
          LS(1)-0417); the shipped table (one cached instance per name);
        - a file: ``.npz`` in the shipped format (``alpha_deg``, ``cl``, ``cd`` and optional
          ``reynolds``, ``mach``, ``cm``), or a text file whose rows are alpha [deg], cl, cd
          (e.g. an XFOIL polar file);
        - an (n, 3) array of rows alpha [deg], cl, cd at one Reynolds and Mach number;
        - a dict with ``cl``, ``cd`` and ``alpha_deg`` or ``alpha_rad`` (optional ``reynolds``,
          ``mach`` for a 3-D table, ``name``);
        - a Polar, returned unchanged.

    Returns
    -------
    Polar
    """
    if isinstance(airfoil, Polar):
        return airfoil
    if isinstance(airfoil, (str, os.PathLike)):
        text = str(airfoil)
        key = _ALIASES.get(text.strip().lower())
        if key is not None:
            return _named_polar(key)
        path = Path(text).expanduser()
        if path.is_file():
            if path.suffix.lower() == ".npz":
                return TablePolar.from_npz(path)
            return TablePolar.from_text(path)
        airfoil_table_path(text)  # raises the error listing the allowed names
    if isinstance(airfoil, dict):
        d = dict(airfoil)
        if "alpha_deg" in d:
            alpha = np.radians(np.asarray(d.pop("alpha_deg"), dtype=float))
        elif "alpha_rad" in d:
            alpha = np.asarray(d.pop("alpha_rad"), dtype=float)
        else:
            raise ValueError("airfoil table dict: needs 'alpha_deg' or 'alpha_rad', 'cl', 'cd'")
        name = d.pop("name", "user table")
        re = d.pop("reynolds", [1e6])
        m = d.pop("mach", [0.0])
        cl, cd, cm = d.pop("cl"), d.pop("cd"), d.pop("cm", None)
        if d:
            raise ValueError(f"airfoil table dict: unknown keys {sorted(d)}")
        if np.size(re) == 1 and np.size(m) == 1:
            return TablePolar.from_alpha_cl_cd(
                np.degrees(alpha), cl, cd, np.ravel(re)[0], np.ravel(m)[0], name=name
            )
        return TablePolar(alpha, re, m, cl, cd, cm, name=name)
    table = np.asarray(airfoil, dtype=float)
    if table.ndim == 2 and table.shape[1] != 3 and table.shape[0] == 3:
        table = table.T
    if table.ndim != 2 or table.shape[1] != 3:
        raise ValueError(
            f"airfoil table shape {table.shape}; allowed: (n, 3) rows of alpha [deg], cl, cd"
        )
    return TablePolar.from_alpha_cl_cd(table[:, 0], table[:, 1], table[:, 2])
