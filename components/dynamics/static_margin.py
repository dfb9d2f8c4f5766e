"""Neutral point (paper eq. 30) and static margin."""

import numpy as np
import openmdao.api as om
from scipy.optimize import brentq

from lpc_mdo.core.checks import check_range


class NeutralPointComp(om.ImplicitComponent):
    """
    Neutral point, solved from the pitching-moment slope.

    The neutral point is the body-x station about which the pitching moment does not change with
    angle of attack (paper eq. 30; docs theory/dynamics 'Neutral point and static margin').

    The pitching moment about P = (x, 0, 0) is M_P = M_O + x F_z (body frame, z down), so the
    residual

        R(x) = dM_O/dalpha + x dF_z/dalpha = 0

    is solved for x by a bracketed (Brent) search between the nose and the tail, as the paper
    bisects; it is affine in x, so the bracket converges at once, and the exact linearization
    makes the neutral point's derivatives one linear solve.

    Inputs
    ------
    pitching_moment_slope : scalar, N*m/rad
        dM_y/dalpha about the body origin.
    normal_force_slope : scalar, N/rad
        dF_z/dalpha (negative: lift grows upwards with alpha).

    Outputs
    -------
    neutral_point : scalar, m
        Body-x station of the neutral point (negative aft of the nose).

    Options
    -------
    bracket : (float, float)
        Search interval in body x, m (nose and tail); default (0, -12).
    """

    def initialize(self):
        self.options.declare(
            "bracket",
            default=(0.0, -12.0),
            types=tuple,
            desc="body-x search interval (nose, tail), m",
        )

    def setup(self):
        self.add_input(
            "pitching_moment_slope", 0.0, units="N*m/rad", desc="dM_y/dalpha about the body origin"
        )
        self.add_input("normal_force_slope", -1.0, units="N/rad", desc="dF_z/dalpha")
        self.add_output(
            "neutral_point",
            -4.0,
            units="m",
            desc="body-x station of the neutral point",
        )
        self.declare_partials(
            "neutral_point", ["pitching_moment_slope", "normal_force_slope", "neutral_point"]
        )

    def apply_nonlinear(self, inputs, outputs, residuals):
        residuals["neutral_point"] = (
            inputs["pitching_moment_slope"]
            + outputs["neutral_point"] * inputs["normal_force_slope"]
        )

    def solve_nonlinear(self, inputs, outputs):
        dm = float(inputs["pitching_moment_slope"][0].real)
        dfz = float(inputs["normal_force_slope"][0].real)
        lo, hi = self.options["bracket"]
        r_lo, r_hi = dm + lo * dfz, dm + hi * dfz
        if not np.isfinite(r_lo * r_hi) or r_lo * r_hi > 0.0:
            x = -dm / dfz if dfz != 0.0 else np.nan
            raise om.AnalysisError(
                f"{self.msginfo}: no neutral point in the bracket {self.options['bracket']} m "
                f"(dM/dalpha = {dm:.4g} N*m/rad, dFz/dalpha = {dfz:.4g} N/rad give x = {x:.4g} m)"
            )
        root = brentq(lambda x: dm + x * dfz, min(lo, hi), max(lo, hi), xtol=1e-12, rtol=1e-14)
        # One Newton step on the (possibly complex) inputs: exact for this affine residual, and
        # it carries the complex-step perturbation that the real bracketed solve drops.
        slope = inputs["normal_force_slope"]
        outputs["neutral_point"] = root - (inputs["pitching_moment_slope"] + root * slope) / slope

    def linearize(self, inputs, outputs, partials):
        partials["neutral_point", "pitching_moment_slope"] = 1.0
        partials["neutral_point", "normal_force_slope"] = outputs["neutral_point"]
        partials["neutral_point", "neutral_point"] = inputs["normal_force_slope"]
        self._dfz = inputs["normal_force_slope"][0]

    def solve_linear(self, d_outputs, d_residuals, mode):
        # The Jacobian dR/dx = dFz/dalpha is a scalar: divide.
        slope = self._dfz
        if mode == "fwd":
            d_outputs["neutral_point"] = d_residuals["neutral_point"] / slope
        else:
            d_residuals["neutral_point"] = d_outputs["neutral_point"] / slope


class StaticMarginComp(om.ExplicitComponent):
    """
    Static margin of the vehicle from its neutral point and cg.

    SM = (x_cg - x_np) / MAC in the body frame (x forward), i.e. the paper's
    (x_np - x_cg)/MAC with x aft (docs theory/dynamics 'Neutral point and static margin'); the
    constraint is SM >= 0.08.

    Inputs
    ------
    neutral_point : scalar, m
    cg_x : scalar, m
        Body-x station of the centre of gravity.
    mean_aerodynamic_chord : scalar, m

    Outputs
    -------
    static_margin : scalar
    """

    def setup(self):
        self.add_input("neutral_point", -4.0, units="m", desc="body-x of the neutral point")
        self.add_input("cg_x", -3.5, units="m", desc="body-x of the centre of gravity")
        self.add_input("mean_aerodynamic_chord", 1.46, units="m", desc="wing MAC")
        self.add_output("static_margin", 0.0, units=None, desc="static margin in MACs")
        self.declare_partials("static_margin", "*")

    def compute(self, inputs, outputs):
        mac = inputs["mean_aerodynamic_chord"]
        check_range(
            "mean_aerodynamic_chord",
            mac[0],
            lower=0.0,
            lower_open=True,
            units="m",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        outputs["static_margin"] = (inputs["cg_x"] - inputs["neutral_point"]) / mac

    def compute_partials(self, inputs, partials):
        mac = inputs["mean_aerodynamic_chord"]
        partials["static_margin", "cg_x"] = 1.0 / mac
        partials["static_margin", "neutral_point"] = -1.0 / mac
        partials["static_margin", "mean_aerodynamic_chord"] = (
            -(inputs["cg_x"] - inputs["neutral_point"]) / mac**2
        )
