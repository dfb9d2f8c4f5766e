"""make_driver chooses pyoptsparse when it has the optimizer, else IpoptDriver or SLSQP.

pyoptsparse is not installable from PyPI, so its presence and absence are both simulated.
"""

import sys
import types

import openmdao.api as om
import pytest
from openmdao.core.driver import Driver

from lpc_mdo.drivers import IpoptDriver, factory, make_driver


def test_make_driver_without_pyoptsparse(monkeypatch):
    monkeypatch.setattr(factory, "pyoptsparse_optimizers", lambda: set())
    ipopt = make_driver("ipopt", max_iter=50, tol=1e-8, mu_strategy="adaptive")
    assert isinstance(ipopt, IpoptDriver)
    assert ipopt.options["max_iter"] == 50
    assert ipopt.opt_settings == {"mu_strategy": "adaptive"}

    slsqp = make_driver("SLSQP", max_iter=77)
    assert isinstance(slsqp, om.ScipyOptimizeDriver)
    assert slsqp.options["optimizer"] == "SLSQP"
    assert slsqp.options["maxiter"] == 77
    # `lpc-mdo optimize --tol` turns the acceptable-point stop off: an option of our SLSQP
    # driver, IPOPT's native option for IPOPT.
    assert make_driver("SLSQP", acceptable_iter=0).options["acceptable_iter"] == 0
    assert make_driver("IPOPT", acceptable_iter=0).opt_settings == {"acceptable_iter": 0}

    with pytest.raises(RuntimeError, match="SNOPT is reached only through pyoptsparse"):
        make_driver("SNOPT")
    with pytest.raises(ValueError, match="'optimizer' = 'BFGS' is not allowed: must be one of"):
        make_driver("BFGS")


def test_make_driver_with_pyoptsparse(monkeypatch):
    created = []

    class FakePyOptSparseDriver(Driver):
        def __init__(self, optimizer):
            super().__init__()
            self.optimizer = optimizer
            self.opt_settings = {}
            created.append(optimizer)

    monkeypatch.setattr(factory, "pyoptsparse_optimizers", lambda: {"IPOPT", "SNOPT"})
    monkeypatch.setattr(factory.om, "pyOptSparseDriver", FakePyOptSparseDriver)
    snopt = make_driver("SNOPT", **{"Major iterations limit": 150}, acceptable_iter=0)
    assert isinstance(snopt, FakePyOptSparseDriver)
    # SNOPT has no acceptable-point stop: turning it off passes nothing SNOPT would reject.
    assert snopt.opt_settings == {"Major iterations limit": 150}
    assert isinstance(make_driver("IPOPT"), FakePyOptSparseDriver)
    assert created == ["SNOPT", "IPOPT"]
    # SLSQP is not in that pyoptsparse build: SciPy's.
    assert isinstance(make_driver("SLSQP"), om.ScipyOptimizeDriver)


def test_pyoptsparse_detection(monkeypatch):
    monkeypatch.setitem(sys.modules, "pyoptsparse", None)
    assert factory.pyoptsparse_optimizers() == set()

    fake = types.ModuleType("pyoptsparse")

    class IPOPT:
        pass

    class SNOPT:
        def __init__(self):
            raise RuntimeError("There was an error importing the compiled snopt module")

    fake.IPOPT, fake.SNOPT = IPOPT, SNOPT
    monkeypatch.setitem(sys.modules, "pyoptsparse", fake)
    assert factory.pyoptsparse_optimizers() == {"IPOPT"}
