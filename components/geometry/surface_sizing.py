"""Planform dimensions of a trapezoidal lifting surface from its area and aspect ratio."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


class SurfaceSizingComp(om.ExplicitComponent):
    """
    Span, root and tip chord and mean aerodynamic chord from area, aspect ratio and taper.

    Trapezoidal planform (docs theory/geometry 'Reference vehicle', CADDEE wing formulas):

    - b = sqrt(AR S)
    - c_root = 2 S / ((1 + lambda) b),  c_tip = lambda c_root
    - MAC = (2/3) c_root (1 + lambda + lambda**2) / (1 + lambda)

    Inputs
    ------
    area : scalar, m**2
        Reference (planform) area S.
    aspect_ratio : scalar
        AR = b**2 / S.

    Outputs
    -------
    span, root_chord, tip_chord, mean_aerodynamic_chord : scalar, m

    Options
    -------
    taper_ratio : float
        lambda = c_tip / c_root, in (0, 1].
    """

    def initialize(self):
        self.options.declare(
            "taper_ratio", types=float, lower=0.0, upper=1.0, desc="tip chord / root chord"
        )

    def setup(self):
        taper = self.options["taper_ratio"]
        check_range("taper_ratio", taper, lower=0.0, upper=1.0, lower_open=True, where=self.msginfo)
        self.add_input("area", 1.0, units="m**2", desc="planform reference area")
        self.add_input("aspect_ratio", 1.0, units=None, desc="aspect ratio b^2/S")
        self.add_output("span", 1.0, units="m", desc="span")
        self.add_output("root_chord", 1.0, units="m", desc="root chord")
        self.add_output("tip_chord", 1.0, units="m", desc="tip chord")
        self.add_output("mean_aerodynamic_chord", 1.0, units="m", desc="mean aerodynamic chord")
        self.declare_partials("*", ["area", "aspect_ratio"])

    def compute(self, inputs, outputs):
        area, ar = inputs["area"], inputs["aspect_ratio"]
        for name, value, units in (("area", area, "m**2"), ("aspect_ratio", ar, None)):
            check_range(
                name,
                value[0],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        lam = self.options["taper_ratio"]
        # c_root = 2 S/((1+lam) b) = 2 sqrt(S/AR)/(1+lam)
        root = 2.0 * np.sqrt(area / ar) / (1.0 + lam)
        outputs["span"] = np.sqrt(ar * area)
        outputs["root_chord"] = root
        outputs["tip_chord"] = lam * root
        outputs["mean_aerodynamic_chord"] = 2.0 / 3.0 * root * (1 + lam + lam**2) / (1 + lam)

    def compute_partials(self, inputs, partials):
        area, ar = inputs["area"], inputs["aspect_ratio"]
        lam = self.options["taper_ratio"]
        span = np.sqrt(ar * area)
        partials["span", "area"] = 0.5 * span / area
        partials["span", "aspect_ratio"] = 0.5 * span / ar
        root = 2.0 * np.sqrt(area / ar) / (1.0 + lam)
        d_area, d_ar = 0.5 * root / area, -0.5 * root / ar
        mac_factor = 2.0 / 3.0 * (1 + lam + lam**2) / (1 + lam)
        for name, factor in (
            ("root_chord", 1.0),
            ("tip_chord", lam),
            ("mean_aerodynamic_chord", mac_factor),
        ):
            partials[name, "area"] = factor * d_area
            partials[name, "aspect_ratio"] = factor * d_ar
