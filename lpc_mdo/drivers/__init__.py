"""Optimizer layer: ``make_driver`` and lpc-mdo's own IPOPT and SLSQP drivers.

pyoptsparse (the paper's route to IPOPT and SNOPT) is not on PyPI, so a plain ``pip install``
cannot reach it.  :func:`make_driver` picks pyoptsparse when it is importable and has the
requested optimizer, and falls back to :class:`IpoptDriver` (IPOPT through ``cyipopt``) or
:class:`SlsqpDriver` (OpenMDAO's ``ScipyOptimizeDriver`` with SLSQP, backing off from failed
model evaluations).

Modules
-------
ipopt
    :class:`IpoptDriver`, :class:`IpoptMultipliers` and the IPOPT default settings.
slsqp
    :class:`SlsqpDriver`.
factory
    :func:`make_driver`, :func:`pyoptsparse_optimizers`, :func:`tolerance_settings`.
scaling
    :func:`driver_scaling`, :func:`max_violation`: values in the driver's scaled space.
openmdao_internals
    Every use of OpenMDAO private or semi-private driver API, with the version it was checked
    against and why each is touched.
"""

from lpc_mdo.drivers.factory import (
    KNOWN_OPTIMIZERS,
    make_driver,
    pyoptsparse_optimizers,
    tolerance_settings,
)
from lpc_mdo.drivers.ipopt import (
    DEFAULT_IPOPT_SETTINGS,
    WARM_START_SETTINGS,
    IpoptDriver,
    IpoptMultipliers,
)
from lpc_mdo.drivers.scaling import driver_scaling, max_violation
from lpc_mdo.drivers.slsqp import SlsqpDriver

__all__ = [
    "DEFAULT_IPOPT_SETTINGS",
    "KNOWN_OPTIMIZERS",
    "WARM_START_SETTINGS",
    "IpoptDriver",
    "IpoptMultipliers",
    "SlsqpDriver",
    "driver_scaling",
    "make_driver",
    "max_violation",
    "pyoptsparse_optimizers",
    "tolerance_settings",
]
