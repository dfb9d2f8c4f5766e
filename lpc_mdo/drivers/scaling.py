"""The driver's scaled space: scaling of a design variable or response, constraint violation.

An optimizer sees every design variable and response as ``(x + adder) * scaler``.
:func:`driver_scaling` gives scaler and adder from the metadata OpenMDAO keeps (the trim and the
post-optimal sensitivities work in that space too); :func:`max_violation` is the largest scaled
constraint violation of a driver's current point, the feasibility measure of the SLSQP driver's
acceptable-point stop and of the progress line.
"""

import numpy as np
from openmdao.utils.general_utils import determine_adder_scaler

from lpc_mdo.drivers.openmdao_internals import owning_problem

__all__ = ["driver_scaling", "max_violation"]


def driver_scaling(meta):
    """
    Return (scaler, adder) of a design variable or response from its metadata.

    Scaled = (x + adder) * scaler. The metadata of ``get_design_vars``/``get_constraints`` keep
    ref/ref0 as declared and leave scaler/adder None when they were declared through refs.

    Parameters
    ----------
    meta : dict
        Metadata of one design variable or response (``ref``, ``ref0``, ``scaler``,
        ``adder``).

    Returns
    -------
    tuple of (float or ndarray, float or ndarray)
        The scaler and the adder.
    """
    adder, scaler = determine_adder_scaler(
        meta.get("ref0"), meta.get("ref"), meta.get("adder"), meta.get("scaler")
    )
    return (1.0 if scaler is None else scaler), (0.0 if adder is None else adder)


def max_violation(driver):
    """
    Return the largest constraint violation of a driver's current point, in its scaled space.

    Parameters
    ----------
    driver : Driver
        A driver that has been set up and evaluated.

    Returns
    -------
    float
        The largest scaled distance of a constraint value outside its bounds (0 when feasible).
    """
    values = driver.get_constraint_values(driver_scaling=False)
    meta = owning_problem(driver).model.get_constraints()  # bounds as declared (unscaled)
    worst = 0.0
    for name, value in values.items():
        m = meta.get(name)
        if m is None:
            continue
        value = np.ravel(value)
        if m["equals"] is not None:
            viol = np.abs(value - np.ravel(m["equals"]))
        else:
            lower = -np.inf if m["lower"] is None else np.ravel(m["lower"])
            upper = np.inf if m["upper"] is None else np.ravel(m["upper"])
            viol = np.maximum(np.maximum(lower - value, value - upper), 0.0)
        if viol.size:
            worst = max(worst, float(np.max(np.abs(viol * driver_scaling(m)[0]))))
    return worst
