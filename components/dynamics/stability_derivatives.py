"""Angle-of-attack derivatives of the aerodynamic force and moment for the neutral point."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


class AnglePerturbationComp(om.ExplicitComponent):
    """
    Angle of attack alpha + delta of a second aerodynamic solve.

    Paper eq. 30 needs dM/dalpha, which an optimizer cannot take as a derivative of a
    derivative; a second VLM solve at alpha + delta gives it as a difference whose own
    derivatives are exact.

    Inputs
    ------
    angle_of_attack : (num_nodes,), rad

    Outputs
    -------
    perturbed_angle_of_attack : (num_nodes,), rad

    Options
    -------
    delta : float
        Perturbation, rad (default 1e-3; the VLM is linear in alpha to O(alpha^2), so the
        difference has a relative error of order delta).
    num_nodes : int
    """

    def initialize(self):
        self.options.declare("delta", default=1e-3, types=float, desc="perturbation, rad")
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of flight conditions"
        )

    def setup(self):
        nn = self.options["num_nodes"]
        check_range(
            "delta",
            self.options["delta"],
            lower=0.0,
            upper=0.1,
            lower_open=True,
            upper_open=True,
            units="rad",
            where=self.msginfo,
        )
        self.add_input("angle_of_attack", np.zeros(nn), units="rad", desc="angle of attack")
        self.add_output(
            "perturbed_angle_of_attack",
            np.zeros(nn),
            units="rad",
            desc="angle of attack plus the perturbation",
        )
        self.declare_partials(
            "perturbed_angle_of_attack", "angle_of_attack", diagonal=True, val=1.0
        )

    def compute(self, inputs, outputs):
        outputs["perturbed_angle_of_attack"] = inputs["angle_of_attack"] + self.options["delta"]


class StabilityDerivativeComp(om.ExplicitComponent):
    """
    dF_z/dalpha and dM_y/dalpha (about the body origin) from two solves delta apart.

    Inputs
    ------
    force, perturbed_force : (num_nodes, 3), N
    moment, perturbed_moment : (num_nodes, 3), N*m

    Outputs
    -------
    normal_force_slope : (num_nodes,), N/rad
    pitching_moment_slope : (num_nodes,), N*m/rad

    Options
    -------
    delta : float
        The perturbation of :class:`AnglePerturbationComp`, rad.
    num_nodes : int
    """

    def initialize(self):
        self.options.declare("delta", default=1e-3, types=float, desc="perturbation, rad")
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of flight conditions"
        )

    def setup(self):
        nn = self.options["num_nodes"]
        inv = 1.0 / self.options["delta"]
        for name, units in (("force", "N"), ("moment", "N*m")):
            self.add_input(name, np.zeros((nn, 3)), units=units, desc=f"aerodynamic {name}")
            self.add_input(
                f"perturbed_{name}",
                np.zeros((nn, 3)),
                units=units,
                desc=f"aerodynamic {name} at alpha + delta",
            )
        self.add_output("normal_force_slope", np.zeros(nn), units="N/rad", desc="dF_z/dalpha")
        self.add_output(
            "pitching_moment_slope",
            np.zeros(nn),
            units="N*m/rad",
            desc="dM_y/dalpha about the body origin",
        )
        ar = np.arange(nn)
        for out, name, col in (
            ("normal_force_slope", "force", 2),
            ("pitching_moment_slope", "moment", 1),
        ):
            self.declare_partials(out, f"perturbed_{name}", rows=ar, cols=3 * ar + col, val=inv)
            self.declare_partials(out, name, rows=ar, cols=3 * ar + col, val=-inv)

    def compute(self, inputs, outputs):
        inv = 1.0 / self.options["delta"]
        outputs["normal_force_slope"] = (
            inputs["perturbed_force"][:, 2] - inputs["force"][:, 2]
        ) * inv
        outputs["pitching_moment_slope"] = (
            inputs["perturbed_moment"][:, 1] - inputs["moment"][:, 1]
        ) * inv
