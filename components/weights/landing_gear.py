"""Landing-gear mass: NDARC's fixed fraction of the design gross mass, with NASA's LPC fraction.

Johnson, W., "NDARC - NASA Design and Analysis of Rotorcraft, Theory", NASA TP-2015-218751,
chapter "Weights", section "Landing Gear Group": the basic landing-gear weight is a fixed
fraction of the maximum takeoff weight, w_LG = f_LG W_MTO. The fraction of the NASA
lift-plus-cruise concept is its own NDARC weight statement (NASA SACD UAM reference
configurations, https://sacd.larc.nasa.gov/uam-refs/, as transcribed in NASA's GUAM,
github.com/nasa/Generic-Urban-Air-Mobility-GUAM,
vehicles/Lift+Cruise/AeroProp/SFunction/build_Lift_plus_Cruise.m): landing gear 8.48397 slug
= 123.81 kg of 181.789 slug = 2653.02 kg, f_LG = 0.04667.
"""

import openmdao.api as om

from lpc_mdo.core.checks import RangeCheck, check_range

_SLUG = 14.593903  # kg per slug
#: Landing-gear mass and total mass of the NASA LPC NDARC weight statement (GUAM), kg.
NASA_LANDING_GEAR_MASS = 8.48397 * _SLUG
NASA_TOTAL_MASS = 181.789249 * _SLUG  # sum of the GUAM items, 181.789 slug
#: f_LG of the NASA LPC.
NASA_LANDING_GEAR_FRACTION = NASA_LANDING_GEAR_MASS / NASA_TOTAL_MASS

_fraction = RangeCheck(lower=0.0, upper=1.0, lower_open=True)


class LandingGearMassComp(om.ExplicitComponent):
    """
    Landing-gear mass m_LG = f_LG W_dg (NDARC, Landing Gear Group).

    Inputs
    ------
    design_gross_mass : float, (1,), kg
        W_dg (>= 0).

    Outputs
    -------
    landing_gear_mass : float, (1,), kg

    Options
    -------
    fraction : float
        f_LG in (0, 1]; default the NASA LPC's 0.04667.
    """

    def initialize(self):
        self.options.declare("fraction", default=NASA_LANDING_GEAR_FRACTION, types=(int, float),
                             check_valid=_fraction, desc="f_LG, (0, 1]")  # fmt: skip

    def setup(self):
        self.add_input("design_gross_mass", 3700.0, units="kg", desc="design gross mass")
        self.add_output("landing_gear_mass", 170.0, units="kg", desc="landing-gear mass")
        self.declare_partials(
            "landing_gear_mass", "design_gross_mass", val=self.options["fraction"]
        )

    def compute(self, inputs, outputs):
        check_range("design_gross_mass", inputs["design_gross_mass"], lower=0.0, units="kg",
                    error=om.AnalysisError, where=self.msginfo)  # fmt: skip
        outputs["landing_gear_mass"] = self.options["fraction"] * inputs["design_gross_mass"]
