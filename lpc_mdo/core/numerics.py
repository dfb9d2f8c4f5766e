"""One safeguarded, vectorized Newton solver for many independent scalar residuals.

:func:`safeguarded_newton` finds a root of R_i(x_i) = 0 for every entry i of an array at once
(the BEM inflow angle of every blade station, alpha* of every wing section, the motor currents
and torques of every motor and node), without a Python loop over the entries. Every entry keeps a
sign-change bracket [lo, hi]; a Newton step x - R/R' is taken where it stays strictly inside the
bracket and shrinks at least half as fast as the step before (the safeguard of ``rtsafe``, Press
et al., *Numerical Recipes*, 3rd ed., §9.4), and a bisection step is taken otherwise. The
iteration thus converges wherever the bracket is valid, and quadratically near a simple root.
Without a derivative (``fun`` returning ``(R, None)``) it is plain bisection.

Failures raise ``om.AnalysisError`` (a bracket without a sign change, a non-finite residual, no
convergence within ``maxiter``), naming the variable, the entry and the values, so that an
optimizer can back off instead of receiving NaNs.

Complex step: the solve is real. A component under complex step solves with the real parts of
its inputs and then takes one Newton step in complex arithmetic from the real root
(:func:`newton_step`), which gives the implicit-function derivative exactly to first order in h.
"""

import numpy as np
import openmdao.api as om

__all__ = ["newton_step", "safeguarded_newton"]

_EPS = np.finfo(float).eps


def newton_step(fun, x):
    """
    One plain Newton step x - R(x)/R'(x) (complex-safe; used after a real solve).

    Parameters
    ----------
    fun : callable
        ``fun(x) -> (R, dR/dx)``.
    x : ndarray
        The point (the real root, possibly cast to complex).

    Returns
    -------
    ndarray
        The updated point.
    """
    f, dfdx = fun(x)
    return x - f / dfdx


def _index_text(shape, flat):
    if len(shape) > 1:
        return str([int(i) for i in np.unravel_index(int(flat), shape)])
    return f"[{int(flat)}]"


def safeguarded_newton(
    fun,
    lower,
    upper,
    *,
    f_lower=None,
    f_upper=None,
    x0=None,
    xtol_abs=0.0,
    xtol_rel=4.0 * _EPS,
    ftol=0.0,
    maxiter=100,
    indexed=False,
    variable="x",
    units="",
    where="",
    fail=None,
):
    """
    Roots of independent scalar residuals R_i(x_i) = 0 on brackets, all entries at once.

    Parameters
    ----------
    fun : callable
        ``fun(x) -> (R, dR/dx)`` with arrays of the shape of the bracket (real, pointwise), or
        with ``indexed=True`` ``fun(x, idx) -> (R, dR/dx)`` on the 1-D array ``x`` of the flat
        entries ``idx`` still iterating (so converged entries cost nothing). ``dR/dx`` may be
        ``None``: bisection only.
    lower, upper : array_like
        Bracket ends, broadcast (with ``x0``) to a common shape, the shape of the result; R must
        change sign on [lower, upper] (or vanish at an end). Either order is accepted.
    f_lower, f_upper : array_like or None
        R at the bracket ends, if already known (saves two evaluations).
    x0 : array_like or None
        Start, e.g. the previous solution (a warm start); entries that are NaN or not inside
        their bracket start at the default, the regula-falsi point of the bracket (its midpoint
        if that fails).
    xtol_abs, xtol_rel : float
        An entry has converged when its Newton step or its bracket width is at most
        ``xtol_abs + xtol_rel |x|``.
    ftol : float
        An entry has also converged when ``|R| <= ftol``.
    maxiter : int
        Iteration limit.
    indexed : bool
        Call ``fun(x, idx)`` on the active entries only (see ``fun``).
    variable, units : str
        Name and units of the unknown, for error messages.
    where : str
        Prefix of error messages (a component's ``msginfo``).
    fail : callable or None
        ``fail(idx, why)`` raises the error for the flat entries ``idx`` (to add the model's own
        context to the message); default raises ``om.AnalysisError``.

    Returns
    -------
    ndarray
        The roots, in the broadcast shape of the bracket.

    Raises
    ------
    om.AnalysisError
        If a bracket is not finite or has no sign change, the residual is not finite during the
        iteration, or an entry does not converge in ``maxiter`` iterations.
    """
    ends = [np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)]
    lo, hi = np.broadcast_arrays(*ends, *([np.asarray(x0, dtype=float)] if x0 is not None else []))[
        :2
    ]
    shape = lo.shape
    lo, hi = lo.ravel().copy(), hi.ravel().copy()
    n = lo.size
    prefix = f"{where}: " if where else ""

    def raise_fail(idx, why):
        if fail is not None:
            fail(idx, why)
        i = int(idx[0])
        raise om.AnalysisError(
            f"{prefix}the {variable} solve failed ({why}) at index "
            f"{_index_text(shape, i)}" + (f" and {idx.size - 1} more" if idx.size > 1 else "")
        )

    def evaluate(x, idx):
        if indexed:
            f, df = fun(x, idx)
        else:
            full = np.empty(n)
            full[:] = x_all
            full[idx] = x
            f, df = fun(full.reshape(shape))
            if np.size(f) != n:
                raise ValueError(
                    f"{prefix}the {variable} residual has shape {np.shape(f)}; "
                    f"must have the bracket's shape {shape}"
                )
            f = np.asarray(f).ravel()[idx]
            df = None if df is None else np.asarray(df).ravel()[idx]
        f = np.asarray(f, dtype=float).ravel()
        return f, (None if df is None else np.asarray(df, dtype=float).ravel())

    every = np.arange(n)
    x_all = 0.5 * (lo + hi)
    f_lo = (
        evaluate(lo, every)[0]
        if f_lower is None
        else np.broadcast_to(np.asarray(f_lower, dtype=float), shape).ravel().copy()
    )
    f_hi = (
        evaluate(hi, every)[0]
        if f_upper is None
        else np.broadcast_to(np.asarray(f_upper, dtype=float), shape).ravel().copy()
    )
    bad = (
        ~np.isfinite(lo)
        | ~np.isfinite(hi)
        | ~np.isfinite(f_lo)
        | ~np.isfinite(f_hi)
        | (np.sign(f_lo) * np.sign(f_hi) > 0)
    )
    if np.any(bad):
        idx = np.flatnonzero(bad)
        i = int(idx[0])
        if fail is not None:
            fail(idx, "no sign change of the residual on the bracket")
        raise om.AnalysisError(
            f"{prefix}the {variable} residual does not change sign on its bracket "
            f"[{lo[i]:.6g}, {hi[i]:.6g}] {units} at index {_index_text(shape, i)} (residual "
            f"{f_lo[i]:.6g} and {f_hi[i]:.6g}); the inputs are outside the range where the "
            f"{variable} solve has a solution."
        )
    # Geometric order lo < hi; f_lo keeps the residual sign of the lower end.
    swap = lo > hi
    lo, hi = np.where(swap, hi, lo), np.where(swap, lo, hi)
    f_lo, f_hi = np.where(swap, f_hi, f_lo), np.where(swap, f_lo, f_hi)

    x_all = np.empty(n)
    exact_lo = f_lo == 0.0
    exact_hi = (f_hi == 0.0) & ~exact_lo
    x_all[exact_lo], x_all[exact_hi] = lo[exact_lo], hi[exact_hi]
    act = np.flatnonzero(~(exact_lo | exact_hi))
    denom = f_hi[act] - f_lo[act]
    safe = np.where(denom != 0.0, denom, 1.0)
    x = np.where(
        denom != 0.0,
        lo[act] - f_lo[act] * (hi[act] - lo[act]) / safe,
        0.5 * (lo[act] + hi[act]),
    )
    lo, hi, f_lo = lo[act], hi[act], f_lo[act]
    x = np.where((x > lo) & (x < hi), x, 0.5 * (lo + hi))
    if x0 is not None:
        # A start inside the bracket replaces the regula-falsi point; NaN (or a start outside
        # the bracket) keeps it.
        start = np.broadcast_to(np.asarray(x0, dtype=float), shape).ravel()[act]
        x = np.where((start > lo) & (start < hi), start, x)
    x_all[act] = x
    step_old = hi - lo
    for _ in range(maxiter):
        if act.size == 0:
            return x_all.reshape(shape)
        f, df = evaluate(x, act)
        if not np.all(np.isfinite(f)):
            raise_fail(
                act[~np.isfinite(f)],
                f"residual not finite at {variable} = {x[~np.isfinite(f)][0]:.6g} {units}".rstrip(),
            )
        low_side = np.sign(f) == np.sign(f_lo)
        lo = np.where(low_side, x, lo)
        f_lo = np.where(low_side, f, f_lo)
        hi = np.where(low_side, hi, x)
        if df is None:
            step = np.full(x.shape, np.inf)
            x_newton = np.full(x.shape, np.nan)
        else:
            with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
                step = f / df
                x_newton = x - step
        tol = xtol_abs + xtol_rel * np.abs(x)
        small = np.abs(step) <= tol
        narrow = hi - lo <= tol
        done = (f == 0.0) | (np.abs(f) <= ftol) | small | narrow
        root = np.where(
            (f == 0.0) | (np.abs(f) <= ftol),
            x,
            np.where(small, np.clip(x_newton, lo, hi), 0.5 * (lo + hi)),
        )
        x_all[act[done]] = root[done]
        newton = (
            np.isfinite(x_newton)
            & (x_newton > lo)
            & (x_newton < hi)
            & (np.abs(step) < 0.5 * np.abs(step_old))
        )
        x_new = np.where(newton, x_newton, 0.5 * (lo + hi))
        step_old = np.where(newton, step, 0.5 * (hi - lo))
        keep = ~done
        act, x, lo, hi, f_lo, step_old = (v[keep] for v in (act, x_new, lo, hi, f_lo, step_old))
        x_all[act] = x
    if act.size:
        raise_fail(act, f"no convergence in {maxiter} iterations")
    return x_all.reshape(shape)
