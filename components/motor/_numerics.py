"""Vectorized numerics shared by the motor components (private).

- :func:`bisect`: bracketed scalar root finding over whole arrays at once (one bisection per
  entry, no Python loop over motors or nodes), raising ``om.AnalysisError`` on a bad bracket.
- :func:`declare_pointwise_partials` / :func:`complex_step_partials`: the motor models are
  pointwise, i.e. every output entry depends only on the inputs of the same motor (shape
  (num_motors,)) or the same motor and node (shape (num_motors, num_nodes)). Their Jacobians are
  therefore diagonal (or a per-motor column broadcast over the nodes), and one complex-step
  evaluation with *all* entries of one input perturbed at once yields every nonzero partial of
  that input exactly (to round-off): imag(f(x + i h))/h, h = 1e-40.
- :func:`polish_complex`: after a real bracketed solve under OpenMDAO's complex step, one Newton
  step in complex arithmetic restores the imaginary part of the state, which is the exact
  implicit-function derivative to first order in h.
"""

import numpy as np
import openmdao.api as om

CS_STEP = 1.0e-40
_EPS = np.finfo(float).eps


def pointwise_pattern(of_shape, wrt_shape):
    """
    Return (rows, cols) of d(of)/d(wrt) for a pointwise model.

    Parameters
    ----------
    of_shape : tuple
        Shape of the output (or residual): (num_motors,) or (num_motors, num_nodes).
    wrt_shape : tuple
        Shape of the input: the same shape, or (num_motors,) for a per-motor input of a
        per-node output.

    Returns
    -------
    rows, cols : ndarray of int
    """
    of_shape, wrt_shape = tuple(of_shape), tuple(wrt_shape)
    rows = np.arange(int(np.prod(of_shape)))
    if wrt_shape == of_shape:
        return rows, rows
    if len(of_shape) == 2 and wrt_shape == of_shape[:1]:
        return rows, np.repeat(np.arange(of_shape[0]), of_shape[1])
    raise ValueError(f'No pointwise pattern from shape {wrt_shape} to shape {of_shape}.')


def declare_pointwise_partials(comp, deps, shapes, val=None):
    """
    Declare sparse pointwise partials.

    Parameters
    ----------
    comp : Component
        The component (in setup).
    deps : dict
        Output (or residual) name -> iterable of the input (or state) names it depends on.
    shapes : dict
        Name -> shape of every variable named in deps.
    val : float or None
        Constant value of the partials, if any.
    """
    for of, wrts in deps.items():
        for wrt in wrts:
            rows, cols = pointwise_pattern(shapes[of], shapes[wrt])
            comp.declare_partials(of, wrt, rows=rows, cols=cols, val=val)


def complex_step_partials(func, values, deps, shapes, partials):
    """
    Fill pointwise partials by a vectorized complex step of ``func``.

    Parameters
    ----------
    func : callable
        func(values) -> dict name -> array; must be complex-step safe and pointwise.
    values : dict
        Name -> real array of every argument of func.
    deps : dict
        Output (or residual) name -> iterable of the argument names it depends on, as declared
        with :func:`declare_pointwise_partials`.
    shapes : dict
        Name -> shape of every output in deps.
    partials : Jacobian-like
        OpenMDAO partials (or jacobian) to fill.
    """
    by_wrt = {}
    for of, wrts in deps.items():
        for wrt in wrts:
            by_wrt.setdefault(wrt, []).append(of)
    base = {name: np.asarray(val).real.astype(complex) for name, val in values.items()}
    for wrt, ofs in by_wrt.items():
        perturbed = dict(base)
        perturbed[wrt] = base[wrt] + 1j * CS_STEP
        result = func(perturbed)
        for of in ofs:
            deriv = np.imag(np.asarray(result[of], dtype=complex)) / CS_STEP
            partials[of, wrt] = np.broadcast_to(deriv, shapes[of]).ravel()


def state_derivative(residual, state):
    """Return d(residual)/d(state) pointwise by complex step (residual(state) -> array)."""
    state = np.asarray(state).real
    return np.imag(residual(state + 1j * CS_STEP)) / CS_STEP


def polish_complex(residual, state, residual_derivative):
    """
    One Newton step x - R(x)/R'(x) in complex arithmetic after a real solve (complex step only).

    ``residual`` is evaluated with the complex inputs at the real root ``state``; the result has
    the imaginary part -h (dR/dp)/(dR/dx), the implicit-function derivative.
    """
    return state - residual(state) / residual_derivative


def bisect(fun, lower, upper, *, owner, variable, units='', xtol_abs=0.0,
           xtol_rel=4.0 * _EPS, maxiter=200):
    """
    Vectorized bisection: the root of fun(x) = 0 in [lower, upper] for every entry at once.

    Parameters
    ----------
    fun : callable
        fun(x) -> array of the shape of x (real, pointwise).
    lower, upper : array_like
        Bracket; broadcast to a common shape. fun must change sign on it (or vanish at an end).
    owner : str
        Prefix of error messages (the component's msginfo).
    variable : str
        Name of the unknown, for error messages.
    units : str
        Units of the unknown, for error messages.
    xtol_abs, xtol_rel : float
        Stop when every bracket is narrower than xtol_abs + xtol_rel |x|.
    maxiter : int
        Maximum number of halvings.

    Returns
    -------
    ndarray
        Midpoint of the final brackets (root to about machine precision).

    Raises
    ------
    om.AnalysisError
        If the residual is not finite at an end, has the same sign at both ends, or the
        bisection does not converge in maxiter halvings.
    """
    lo, hi = np.broadcast_arrays(np.asarray(lower, dtype=float), np.asarray(upper, dtype=float))
    lo, hi = lo.copy(), hi.copy()
    f_lo, f_hi = fun(lo), fun(hi)
    bad = (~np.isfinite(f_lo) | ~np.isfinite(f_hi) | ~np.isfinite(lo) | ~np.isfinite(hi)
           | (np.sign(f_lo) * np.sign(f_hi) > 0))
    if np.any(bad):
        idx = np.argwhere(bad)[0]
        i = tuple(idx)
        raise om.AnalysisError(
            f'{owner}: the {variable} residual does not change sign on its bracket '
            f'[{lo[i]:.6g}, {hi[i]:.6g}] {units} at index {idx.tolist()} (residual '
            f'{f_lo[i]:.6g} and {f_hi[i]:.6g}); the inputs are outside the range where the '
            f'{variable} solve has a solution.')
    # Orient every bracket so that fun(lo) <= 0 <= fun(hi).
    flip = f_lo > 0
    lo, hi = np.where(flip, hi, lo), np.where(flip, lo, hi)
    for _ in range(maxiter):
        mid = 0.5 * (lo + hi)
        if np.all(np.abs(hi - lo) <= xtol_abs + xtol_rel * np.abs(mid)):
            return mid
        f_mid = fun(mid)
        if not np.all(np.isfinite(f_mid)):
            idx = np.argwhere(~np.isfinite(f_mid))[0]
            raise om.AnalysisError(f'{owner}: the {variable} residual is not finite at '
                                   f'{mid[tuple(idx)]:.6g} {units} (index {idx.tolist()}).')
        below = f_mid <= 0
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    raise om.AnalysisError(f'{owner}: the {variable} bisection did not converge in {maxiter} '
                           'halvings.')


def newton_bracketed(fun, lower, upper, *, owner, variable, units='', xtol_abs=0.0,
                     xtol_rel=4.0 * _EPS, maxiter=100):
    """
    Vectorized safeguarded Newton method (Newton-bisection hybrid) on a sign-change bracket.

    Every entry keeps a bracket [lo, hi] with fun(lo) <= 0 <= fun(hi); a Newton step that leaves
    the bracket (or is not finite) is replaced by a bisection, so the iteration converges
    wherever the bracket is valid, quadratically near the root.

    Parameters
    ----------
    fun : callable
        fun(x) -> (f, dfdx), arrays of the shape of x (real, pointwise).
    lower, upper : array_like
        Bracket, broadcast to a common shape; fun must change sign on it.
    owner, variable, units : str
        For error messages (component msginfo, unknown's name and units).
    xtol_abs, xtol_rel : float
        Stop when every Newton/bisection step is below xtol_abs + xtol_rel |x|.
    maxiter : int
        Maximum number of iterations.

    Returns
    -------
    ndarray
        The roots.

    Raises
    ------
    om.AnalysisError
        If the residual is not finite or has the same sign at both ends of a bracket, or the
        iteration does not converge.
    """
    lo, hi = np.broadcast_arrays(np.asarray(lower, dtype=float), np.asarray(upper, dtype=float))
    lo, hi = lo.copy(), hi.copy()
    f_lo, _ = fun(lo)
    f_hi, _ = fun(hi)
    bad = (~np.isfinite(f_lo) | ~np.isfinite(f_hi) | ~np.isfinite(lo) | ~np.isfinite(hi)
           | (np.sign(f_lo) * np.sign(f_hi) > 0))
    if np.any(bad):
        i = tuple(int(k) for k in np.argwhere(bad)[0])
        raise om.AnalysisError(
            f'{owner}: the {variable} residual does not change sign on its bracket '
            f'[{lo[i]:.6g}, {hi[i]:.6g}] {units} at index {list(i)} (residual {f_lo[i]:.6g} and '
            f'{f_hi[i]:.6g}); the inputs are outside the range where the {variable} solve has '
            'a solution.')
    flip = f_lo > 0
    lo, hi = np.where(flip, hi, lo), np.where(flip, lo, hi)
    f_lo, f_hi = np.where(flip, f_hi, f_lo), np.where(flip, f_lo, f_hi)
    # Start from the end with the smaller residual.
    x = np.where(np.abs(f_lo) <= np.abs(f_hi), lo, hi)
    for _ in range(maxiter):
        f, dfdx = fun(x)
        if not np.all(np.isfinite(f)):
            i = tuple(int(k) for k in np.argwhere(~np.isfinite(f))[0])
            raise om.AnalysisError(f'{owner}: the {variable} residual is not finite at '
                                   f'{x[i]:.6g} {units} (index {list(i)}).')
        below = f <= 0
        lo = np.where(below, x, lo)
        hi = np.where(below, hi, x)
        with np.errstate(divide='ignore', invalid='ignore'):
            x_new = x - f / dfdx
        outside = ~np.isfinite(x_new) | (x_new < np.minimum(lo, hi)) | (x_new > np.maximum(lo,
                                                                                            hi))
        x_new = np.where(outside, 0.5 * (lo + hi), x_new)
        x_new = np.where(f == 0.0, x, x_new)
        tol = xtol_abs + xtol_rel * np.abs(x_new)
        done = (np.abs(x_new - x) <= tol) | (np.abs(hi - lo) <= tol)
        x = x_new
        if np.all(done):
            return x
    raise om.AnalysisError(f'{owner}: the {variable} Newton iteration did not converge in '
                           f'{maxiter} iterations.')


def check_saliency(owner, inductance_d, inductance_q, detail=''):
    """Raise AnalysisError naming the motors whose L_q - L_d is not > 0 (MTPA needs it).

    ``detail(idx)`` may add a sentence about those motors to the message.
    """
    saliency = (inductance_q - inductance_d).real
    if np.any(~(saliency > 0.0)):
        idx = np.flatnonzero(~(saliency > 0.0))
        extra = detail(idx) if callable(detail) else detail
        raise om.AnalysisError(
            f'{owner}: inductance_q - inductance_d = {saliency[idx].tolist()} H for '
            f'motor(s) {idx.tolist()}{extra}')
