"""Vectorized numerics shared by the motor components (private).

- root finding: :func:`lpc_mdo.core.numerics.safeguarded_newton` (bisection when no derivative is
  given), shared with the rotor and aero solves.
- :func:`declare_pointwise_partials` / :func:`complex_step_partials`: the motor models are
  pointwise, i.e. every output entry depends only on the inputs of the same motor (shape
  (num_motors,)) or the same motor and node (shape (num_motors, num_nodes)). Their Jacobians are
  therefore diagonal (or a per-motor column broadcast over the nodes), and one complex-step
  evaluation with *all* entries of one input perturbed at once yields every nonzero partial of
  that input exactly (to round-off): imag(f(x + i h))/h, h = 1e-40; the perturbations of all
  inputs are stacked along the motor axis into a single evaluation.
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
    raise ValueError(f"No pointwise pattern from shape {wrt_shape} to shape {of_shape}.")


def pointwise_values(value, shape):
    """
    Flat partial values of ``shape`` from a value broadcastable to it (per-motor column, scalar).

    Same as ``np.broadcast_to(value, shape).ravel()``, at a third of its cost (the motor
    components set about 70 partials per linearization this way).
    """
    value = np.asarray(value)
    if value.shape == tuple(shape):
        return value.ravel()
    full = np.empty(shape, dtype=value.dtype)
    full[...] = value
    return full.ravel()


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
            if tuple(shapes[of]) == tuple(shapes[wrt]):
                # Declared diagonal: OpenMDAO's product for it is a plain multiply.
                comp.declare_partials(of, wrt, diagonal=True, val=val)
                continue
            rows, cols = pointwise_pattern(shapes[of], shapes[wrt])
            comp.declare_partials(of, wrt, rows=rows, cols=cols, val=val)


def complex_step_partials(func, values, deps, shapes, partials):
    """
    Fill pointwise partials by a vectorized complex step of ``func``.

    All inputs are perturbed in one evaluation: the arguments are stacked ``k`` times along the
    motor axis (axis 0), block ``j`` with input ``j`` perturbed by i h. The model is pointwise
    over the motors, so block ``j`` of each result is f(x + i h e_j), and its imaginary part
    over h is every nonzero partial of input ``j`` (one evaluation of k times the points
    instead of k evaluations: the models are small, so their cost is per call, not per point).

    Parameters
    ----------
    func : callable
        func(values) -> dict name -> array; must be complex-step safe and pointwise over the
        leading (motor) axis of every argument and result.
    values : dict
        Name -> real array of every argument of func, leading axis the motors.
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
    wrts = list(by_wrt)
    k = len(wrts)
    stacked = {}
    for name, val in values.items():
        val = np.asarray(val).real
        block = np.tile(val.astype(complex), (k,) + (1,) * (val.ndim - 1))
        if name in by_wrt:
            n = val.shape[0]
            j = wrts.index(name)
            block[j * n : (j + 1) * n] += 1j * CS_STEP
        stacked[name] = block
    result = func(stacked)
    for j, wrt in enumerate(wrts):
        for of in by_wrt[wrt]:
            res = np.asarray(result[of])
            n = res.shape[0] // k
            deriv = res[j * n : (j + 1) * n].imag / CS_STEP
            partials[of, wrt] = pointwise_values(deriv, shapes[of])


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


def check_saliency(owner, inductance_d, inductance_q, detail=""):
    """Raise AnalysisError naming the motors whose L_q - L_d is not > 0 (MTPA needs it).

    ``detail(idx)`` may add a sentence about those motors to the message.
    """
    saliency = (inductance_q - inductance_d).real
    if np.any(~(saliency > 0.0)):
        idx = np.flatnonzero(~(saliency > 0.0))
        extra = detail(idx) if callable(detail) else detail
        raise om.AnalysisError(
            f"{owner}: inductance_q - inductance_d = {saliency[idx].tolist()} H for "
            f"motor(s) {idx.tolist()}{extra}"
        )
