"""Baseline-design objective: the objective plus a penalty on relative deviation (paper eq. 8-9).

    J = f / f_ref + alpha * sum_k beta_k ((x_k - x0_k) / x0_k)^2

The paper defines the baseline design as the feasible design closest to the initial design in
the variables the initial specification gives (the set S; beta_k = 1 there, 0 elsewhere), with
alpha = 100. Here the variables of S are the component's inputs (the others simply are not
connected), each with its initial value x0.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


class DesignDeviationComp(om.ExplicitComponent):
    """
    Objective plus alpha times the squared relative deviation from reference values (eq. 8).

    Inputs
    ------
    objective : float, (1,), units of option ``objective_units``
        The design objective f (gross mass in the paper).
    <name> : float, shape of its reference value, units of the reference
        One input per entry of option ``references``.

    Outputs
    -------
    baseline_objective : float, (1,), -
        f / objective_ref + alpha * sum ((x - x0) / x0)^2.
    deviation : float, (1,), -
        The penalty sum without alpha, sum ((x - x0) / x0)^2 (to report how far the design moved).

    Options
    -------
    references : dict
        name -> (x0 array, units): the variables of the set S and their initial values; every
        x0 entry must be nonzero (the deviation is relative).
    alpha : float
        Penalty weight (> 0). Default 100 (paper Sec. II.F).
    objective_ref : float
        Scale of the objective (> 0), e.g. the initial gross mass.
    objective_units : str or None
        Units of the objective input. Default 'kg'.
    """

    def initialize(self):
        self.options.declare(
            "references", types=dict, desc="name -> (x0 array, units) of the variables of the set S"
        )
        self.options.declare(
            "alpha",
            default=100.0,
            types=(int, float),
            lower=0.0,
            desc="penalty weight (paper: 100)",
        )
        self.options.declare(
            "objective_ref", types=(int, float), lower=0.0, desc="scale of the objective (> 0)"
        )
        self.options.declare(
            "objective_units",
            default="kg",
            types=str,
            allow_none=True,
            desc="units of the objective input",
        )

    def setup(self):
        opts = self.options
        check_range(
            "objective_ref", opts["objective_ref"], lower=0.0, lower_open=True, where=self.msginfo
        )
        self._x0 = {}
        for name, (x0, units) in opts["references"].items():
            x0 = np.atleast_1d(np.asarray(x0, dtype=float))
            if np.any(x0 == 0.0) or not np.all(np.isfinite(x0)):
                raise ValueError(
                    f"{self.msginfo}: reference value of '{name}' = {x0.tolist()}; "
                    "the deviation is relative, so every entry must be finite and "
                    "nonzero."
                )
            self._x0[name] = x0
            self.add_input(name, val=x0, units=units, desc=f"Design variable '{name}' (set S)")
            self.declare_partials("baseline_objective", name)
            self.declare_partials("deviation", name)
        self.add_input(
            "objective",
            val=opts["objective_ref"],
            units=opts["objective_units"],
            desc="Design objective f",
        )
        self.add_output("baseline_objective", val=1.0, desc="f/f_ref + alpha * deviation")
        self.add_output("deviation", val=0.0, desc="sum of squared relative deviations")
        self.declare_partials("baseline_objective", "objective", val=1.0 / opts["objective_ref"])

    def compute(self, inputs, outputs):
        deviation = sum(np.sum(((inputs[n] - x0) / x0) ** 2) for n, x0 in self._x0.items())
        outputs["deviation"] = deviation
        outputs["baseline_objective"] = (
            inputs["objective"] / self.options["objective_ref"] + self.options["alpha"] * deviation
        )

    def compute_partials(self, inputs, partials):
        alpha = self.options["alpha"]
        for name, x0 in self._x0.items():
            d = 2.0 * (inputs[name] - x0) / x0**2
            partials["deviation", name] = d.reshape(1, -1)
            partials["baseline_objective", name] = alpha * d.reshape(1, -1)
