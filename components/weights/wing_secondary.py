"""Wing secondary structure: control surfaces and miscellaneous items (FLOPS wing weight, W2 + W3).

Wells, D. P., Horvath, B. L., and McCullers, L. A., "The Flight Optimization System Weights
Estimation Method", NASA/TM-2017-219627, Vol. I, Sec. "Wing", the general-aviation form of the
FLOPS wing equation (also OpenMDAO Aviary ``aviary/subsystems/mass/flops_based/wing_common.py``).
FLOPS splits the wing into bending material W1, shear material and control surfaces W2 and
miscellaneous items W3. The beam of lpc-mdo sizes the box (skins and spars, i.e. the bending and
the spar-web shear material); this component adds the part the box does not contain. In lb, ft^2
(composite fraction 0, no scaling):

- W2 = A3 S_flap^A4 W_dg^A5,  A3 = 0.25, A4 = 0.5, A5 = 0.5 (general aviation)
- W3 = A6 S_w^A7,             A6 = 0.16, A7 = 1.2  (general aviation)

with S_flap the control-surface (flap + aileron) area, S_flap = f_flap S_w (FLOPS input FLAPR,
default 0.333), S_w the wing reference area and W_dg the design gross weight.
docs theory/weights 'Wing secondary structure' gives the SI form and the overlap with the box.
"""

import openmdao.api as om

from lpc_mdo.core.checks import RangeCheck, check_range

_FT2 = 0.3048**2  # m^2 per ft^2
_LB = 0.45359237  # kg per lb

#: FLOPS general-aviation coefficients (NASA/TM-2017-219627, wing; Aviary GENERAL_AVIATION).
CONTROL_COEFFICIENT, CONTROL_AREA_EXPONENT, CONTROL_WEIGHT_EXPONENT = 0.25, 0.5, 0.5
MISC_COEFFICIENT, MISC_AREA_EXPONENT = 0.16, 1.2
#: FLOPS default flap ratio FLAPR (control-surface area / wing area).
DEFAULT_FLAP_RATIO = 0.333

_fraction = RangeCheck(lower=0.0, upper=1.0, lower_open=True)


class WingSecondaryMassComp(om.ExplicitComponent):
    """
    Mass of the wing's control surfaces and miscellaneous items (FLOPS W2 + W3, general aviation).

    In SI (S in m^2, W in kg, results in kg):

    - m_control = 0.45359 * 0.25 (f_flap S / 0.092903)^0.5 (W_dg / 0.45359)^0.5
    - m_misc    = 0.45359 * 0.16 (S / 0.092903)^1.2
    - wing_secondary_mass = m_control + m_misc

    Analytic partials (power laws).

    Inputs
    ------
    wing_area : float, (1,), m**2
        Wing reference area (> 0).
    design_gross_mass : float, (1,), kg
        Design gross mass W_dg (> 0).

    Outputs
    -------
    wing_control_surface_mass, wing_misc_mass, wing_secondary_mass : float, (1,), kg
        W2, W3 and their sum.

    Options
    -------
    flap_ratio : float
        Control-surface area over wing area, in (0, 1]; FLOPS default 0.333.
    """

    def initialize(self):
        self.options.declare(
            "flap_ratio",
            default=DEFAULT_FLAP_RATIO,
            types=(int, float),
            check_valid=_fraction,
            desc="control-surface area / wing area, (0, 1]",
        )

    def setup(self):
        self.add_input("wing_area", 19.6, units="m**2", desc="wing reference area")
        self.add_input("design_gross_mass", 3700.0, units="kg", desc="design gross mass")
        self.add_output("wing_control_surface_mass", 80.0, units="kg", desc="FLOPS W2")
        self.add_output("wing_misc_mass", 40.0, units="kg", desc="FLOPS W3")
        self.add_output("wing_secondary_mass", 120.0, units="kg", desc="W2 + W3")
        self.declare_partials("wing_control_surface_mass", ["wing_area", "design_gross_mass"])
        self.declare_partials("wing_misc_mass", "wing_area")
        self.declare_partials("wing_secondary_mass", ["wing_area", "design_gross_mass"])

    def _masses(self, inputs):
        for name, units in (("wing_area", "m**2"), ("design_gross_mass", "kg")):
            check_range(
                name,
                inputs[name],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        area = inputs["wing_area"] / _FT2
        weight = inputs["design_gross_mass"] / _LB
        control = (
            _LB
            * CONTROL_COEFFICIENT
            * (self.options["flap_ratio"] * area) ** CONTROL_AREA_EXPONENT
            * weight**CONTROL_WEIGHT_EXPONENT
        )
        misc = _LB * MISC_COEFFICIENT * area**MISC_AREA_EXPONENT
        return control, misc

    def compute(self, inputs, outputs):
        control, misc = self._masses(inputs)
        outputs["wing_control_surface_mass"] = control
        outputs["wing_misc_mass"] = misc
        outputs["wing_secondary_mass"] = control + misc

    def compute_partials(self, inputs, partials):
        control, misc = self._masses(inputs)
        area, weight = inputs["wing_area"], inputs["design_gross_mass"]
        dc_ds = CONTROL_AREA_EXPONENT * control / area
        dc_dw = CONTROL_WEIGHT_EXPONENT * control / weight
        dm_ds = MISC_AREA_EXPONENT * misc / area
        partials["wing_control_surface_mass", "wing_area"] = dc_ds
        partials["wing_control_surface_mass", "design_gross_mass"] = dc_dw
        partials["wing_misc_mass", "wing_area"] = dm_ds
        partials["wing_secondary_mass", "wing_area"] = dc_ds + dm_ds
        partials["wing_secondary_mass", "design_gross_mass"] = dc_dw


__all__ = ["WingSecondaryMassComp"]
