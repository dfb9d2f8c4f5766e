"""``make_driver``: the OpenMDAO driver for an optimizer name, preferring pyoptsparse."""

import importlib

import openmdao.api as om

from lpc_mdo.core.checks import check_choice
from lpc_mdo.drivers.ipopt import IpoptDriver
from lpc_mdo.drivers.slsqp import SlsqpDriver

__all__ = ["KNOWN_OPTIMIZERS", "make_driver", "pyoptsparse_optimizers"]

# Optimizer names make_driver accepts (case-insensitive).
KNOWN_OPTIMIZERS = ("IPOPT", "SNOPT", "SLSQP")


def pyoptsparse_optimizers():
    """
    Optimizers that the importable pyoptsparse provides, or an empty set without pyoptsparse.

    Returns
    -------
    set of str
        Optimizer names such as ``'IPOPT'`` or ``'SNOPT'`` that import successfully.
    """
    try:
        pyoptsparse = importlib.import_module("pyoptsparse")
    except ImportError:
        return set()
    found = set()
    for name in ("IPOPT", "SNOPT", "SLSQP", "ParOpt", "CONMIN", "PSQP", "NLPQLP"):
        try:
            getattr(pyoptsparse, name)()
        except Exception:  # pyoptsparse raises its own Error when a library is missing
            continue
        found.add(name)
    return found


def make_driver(optimizer="IPOPT", **settings):
    """
    Return an OpenMDAO driver for ``optimizer``, preferring pyoptsparse when it has it.

    Parameters
    ----------
    optimizer : str
        ``'IPOPT'``, ``'SNOPT'`` or ``'SLSQP'`` (case-insensitive).
    **settings
        Driver options (e.g. ``max_iter``/``maxiter``, ``tol``, ``print_level``) are set as
        options where the chosen driver has an option of that name; everything else goes into
        ``driver.opt_settings`` (IPOPT/SNOPT native options).

    Returns
    -------
    Driver
        ``om.pyOptSparseDriver`` when pyoptsparse is importable and provides the optimizer;
        otherwise :class:`IpoptDriver` for IPOPT and :class:`SlsqpDriver` (SciPy's SLSQP) for
        SLSQP.

    Raises
    ------
    ValueError
        For an unknown optimizer name.
    RuntimeError
        For SNOPT without a pyoptsparse that has it, saying what to install.
    """
    if not isinstance(optimizer, str) or optimizer.upper() not in KNOWN_OPTIMIZERS:
        check_choice("optimizer", optimizer, KNOWN_OPTIMIZERS)  # raises, naming the names
    name = optimizer.upper()
    available = pyoptsparse_optimizers()

    if name in available:
        driver = om.pyOptSparseDriver(optimizer=name)
    elif name == "IPOPT":
        driver = IpoptDriver()
    elif name == "SLSQP":
        driver = SlsqpDriver()
    else:
        raise RuntimeError(
            "SNOPT is reached only through pyoptsparse, which is not importable here"
            + (" (it is, but was built without SNOPT)" if available else "")
            + ". SNOPT is licensed software: build pyoptsparse with your SNOPT source "
            "(OpenMDAO's build_pyoptsparse, or conda-forge pyoptsparse plus SNOPT), or use "
            "make_driver('IPOPT'), which needs only pip install 'lpc-mdo[ipopt]'."
        )

    aliases = {"max_iter": "maxiter", "maxiter": "max_iter", "print_level": "disp"}
    for key, value in settings.items():
        if name == "SNOPT" and key.startswith("acceptable_") and not value:
            continue  # SNOPT has no acceptable-point stop to turn off
        if key in driver.options:
            driver.options[key] = value
        elif isinstance(driver, om.ScipyOptimizeDriver) and aliases.get(key) in driver.options:
            target = aliases[key]
            driver.options[target] = bool(value) if target == "disp" else value
        elif isinstance(driver, IpoptDriver) and aliases.get(key) in driver.options:
            driver.options[aliases[key]] = value
        else:
            driver.opt_settings[key] = value
    return driver


def tolerance_settings(tol):
    """
    Return the settings of a run that must meet ``tol``: the tolerance, and no earlier stop.

    Without ``acceptable_iter = 0`` IPOPT (and lpc-mdo's SLSQP) may stop at an acceptable
    point before the tolerance asked for: a polish from a sequence's ``full.sql`` stopped after
    16 iterations there.
    """
    return {"tol": tol, "acceptable_iter": 0}
