"""Landing-gear tyre frontal areas from the design gross mass, for the drag build-up."""

__all__ = ["TyreFrontalAreaComp", "tyre_frontal_areas"]

import openmdao.api as om

from lpc_mdo.components.aero.drag_buildup import LPC_MAIN_GEAR_FRACTION, raymer_ga_tyre
from lpc_mdo.core.checks import check_range

#: Exponents of Raymer's general-aviation tyre sizes in the wheel load (Aircraft Design, 6th ed.,
#: Table 11.1: diameter 1.51 W^0.349 in, width 0.7150 W^0.312 in): the frontal area D x width
#: grows as W^0.661.
_AREA_EXPONENT = 0.349 + 0.312


def tyre_frontal_areas(design_gross_mass):
    """Frontal areas D x width (m^2) of one main and the nose tyre at a design gross mass (kg).

    Two main wheels carry ``LPC_MAIN_GEAR_FRACTION`` of the weight, the nose wheel the rest
    (docs theory/aerodynamics 'Drag build-up').
    """
    main = raymer_ga_tyre(LPC_MAIN_GEAR_FRACTION * design_gross_mass / 2.0)
    nose = raymer_ga_tyre((1.0 - LPC_MAIN_GEAR_FRACTION) * design_gross_mass)
    return main[0] * main[1], nose[0] * nose[1]


class TyreFrontalAreaComp(om.ExplicitComponent):
    """
    Tyre frontal areas that follow the design gross mass W_dg (the gear's sizing weight).

    Inputs
    ------
    design_gross_mass : scalar, kg

    Outputs
    -------
    drag_main_wheels_frontal_area, drag_nose_wheel_frontal_area : scalar, m**2
        One main tyre's and the nose tyre's D x width (:func:`tyre_frontal_areas`); dA/dW_dg =
        0.661 A / W_dg.
    """

    def setup(self):
        self.add_input("design_gross_mass", 3000.0, units="kg", desc="design gross mass")
        for name in ("main_wheels", "nose_wheel"):
            self.add_output(f"drag_{name}_frontal_area", 0.1, units="m**2", desc="one tyre's D x w")
            self.declare_partials(f"drag_{name}_frontal_area", "design_gross_mass")

    def compute(self, inputs, outputs):
        w = inputs["design_gross_mass"]
        check_range("design_gross_mass", w, lower=0.0, lower_open=True, units="kg",
                    error=om.AnalysisError, where=self.msginfo)  # fmt: skip
        main, nose = tyre_frontal_areas(w)
        outputs["drag_main_wheels_frontal_area"] = main
        outputs["drag_nose_wheel_frontal_area"] = nose

    def compute_partials(self, inputs, partials):
        w = inputs["design_gross_mass"]
        main, nose = tyre_frontal_areas(w)
        partials["drag_main_wheels_frontal_area", "design_gross_mass"] = _AREA_EXPONENT * main / w
        partials["drag_nose_wheel_frontal_area", "design_gross_mass"] = _AREA_EXPONENT * nose / w
