"""Mass and cg of the whole wing from the beam of one half wing."""

import numpy as np
import openmdao.api as om


class WingMirrorComp(om.ExplicitComponent):
    """
    Whole-wing mass and cg from the right half wing's beam (symmetric wing, paper eq. 32).

    - m_wing = 2 m_half
    - cg_wing = (x_half, 0, z_half): the mirror image cancels the lateral offset.

    Inputs
    ------
    half_wing_mass : scalar, kg
    half_wing_cg : (3,), m

    Outputs
    -------
    wing_mass : scalar, kg
    wing_cg : (3,), m
    """

    def setup(self):
        self.add_input("half_wing_mass", 100.0, units="kg", desc="mass of one half wing box")
        self.add_input("half_wing_cg", np.zeros(3), units="m", desc="cg of one half wing box")
        self.add_output("wing_mass", 200.0, units="kg", desc="mass of the whole wing box")
        self.add_output("wing_cg", np.zeros(3), units="m", desc="cg of the whole wing box")
        self.declare_partials("wing_mass", "half_wing_mass", val=2.0)
        self.declare_partials("wing_cg", "half_wing_cg", rows=[0, 2], cols=[0, 2], val=1.0)

    def compute(self, inputs, outputs):
        outputs["wing_mass"] = 2.0 * inputs["half_wing_mass"]
        cg = inputs["half_wing_cg"]
        outputs["wing_cg"] = np.array([cg[0], 0.0 * cg[1], cg[2]])
