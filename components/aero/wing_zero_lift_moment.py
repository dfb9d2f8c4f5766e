"""Zero-lift pitching moment of the wing from its airfoil's cm0 (a couple)."""

import numpy as np
import openmdao.api as om


def wing_zero_lift_moment_coefficient(airfoil_cm0, aspect_ratio, quarter_chord_sweep):
    """
    Wing Cm0 from the section's zero-lift moment, untwisted wing.

    DATCOM 4.1.4.1 / Raymer (*Aircraft Design*, 6th ed.) eq. 16.13 without its twist term:
    Cm0,w = cm0,airfoil A cos^2(Lambda) / (A + 2 cos(Lambda)). The twist of the reference
    wing is zero (trapezoid file planform), so the twist term vanishes.
    """
    c = np.cos(quarter_chord_sweep)
    return float(airfoil_cm0) * aspect_ratio * c**2 / (aspect_ratio + 2.0 * c)


def airfoil_zero_lift_moment(polar, zero_lift_angle, reynolds, mach):
    """Tabulated quarter-chord cm of ``polar`` at its zero-lift angle (one Re, M)."""
    cm = polar.moment_coefficient(
        np.array([zero_lift_angle]), np.array([reynolds]), np.array([mach])
    )[0]
    return float(cm[0])


class WingZeroLiftMomentComp(om.ExplicitComponent):
    """
    Pitching couple of the wing's camber, M_y = q S c_bar Cm0,w (nose up positive).

    The single-chordwise-panel lattice carries the camber only as a zero-lift angle, whose
    load acts at the quarter chord: the section's moment about it, cm0 (negative for a
    cambered section), is missing. It is a couple (no force), independent of alpha, so it moves
    the trim and not the neutral point. Cm0,w from
    :func:`wing_zero_lift_moment_coefficient`.

    Inputs
    ------
    density, speed : (nn,)
    wing_area : scalar, m**2
    wing_mac : scalar, m

    Outputs
    -------
    wing_camber_moment : (nn, 3), N*m

    Options
    -------
    num_nodes : int
    moment_coefficient : float
        Cm0,w.
    """

    def initialize(self):
        self.options.declare("num_nodes", default=1, types=int, lower=1)
        self.options.declare("moment_coefficient", types=float, desc="wing Cm0")

    def setup(self):
        nn = self.options["num_nodes"]
        self.add_input("density", np.full(nn, 1.225), units="kg/m**3", desc="air density")
        self.add_input("speed", np.zeros(nn), units="m/s", desc="airspeed")
        self.add_input("wing_area", 19.6, units="m**2", desc="wing area")
        self.add_input("wing_mac", 1.46, units="m", desc="wing mean aerodynamic chord")
        self.add_output(
            "wing_camber_moment", np.zeros((nn, 3)), units="N*m", desc="wing cm0 couple"
        )
        ar = np.arange(nn)
        self.declare_partials("wing_camber_moment", ["density", "speed"], rows=3 * ar + 1, cols=ar)
        self.declare_partials(
            "wing_camber_moment", ["wing_area", "wing_mac"], rows=3 * ar + 1, cols=0 * ar
        )

    def compute(self, inputs, outputs):
        q = 0.5 * inputs["density"] * inputs["speed"] ** 2
        cm = self.options["moment_coefficient"]
        outputs["wing_camber_moment"] = 0.0 * q[:, None]
        outputs["wing_camber_moment"][:, 1] = q * inputs["wing_area"] * inputs["wing_mac"] * cm

    def compute_partials(self, inputs, partials):
        rho, v = inputs["density"], inputs["speed"]
        s, c = inputs["wing_area"], inputs["wing_mac"]
        cm = self.options["moment_coefficient"]
        partials["wing_camber_moment", "density"] = 0.5 * v**2 * s * c * cm
        partials["wing_camber_moment", "speed"] = rho * v * s * c * cm
        partials["wing_camber_moment", "wing_area"] = 0.5 * rho * v**2 * c * cm
        partials["wing_camber_moment", "wing_mac"] = 0.5 * rho * v**2 * s * cm


def wing_zero_lift_moment_options(vehicle, wing_zero_lift_angle):
    """
    Cm0,w of the vehicle's wing: its airfoil's cm at the sectional zero-lift angle.

    At the design cruise condition's Reynolds and Mach numbers on the wing MAC (as the
    zero-lift angle itself, groups/lpc.py), with the quarter-chord sweep of the trapezoid
    tan(L_c/4) = tan(L_LE) - (1 - taper)/(A (1 + taper)) (Raymer eq. 7.4, x/c = 0.25).
    """
    from lpc_mdo.components.aero.airfoil import get_polar
    from lpc_mdo.components.atmosphere import standard_atmosphere

    wing = vehicle.wing
    cruise = vehicle.condition(vehicle.mission.cruise_condition)
    _, _, rho, a, mu = standard_atmosphere(
        cruise.altitude, temperature_offset=vehicle.mission.isa_offset
    )
    reynolds = rho * cruise.speed * wing.mean_aerodynamic_chord / mu
    cm0 = airfoil_zero_lift_moment(
        get_polar(wing.airfoil), wing_zero_lift_angle, reynolds, cruise.speed / a
    )
    taper = wing.taper_ratio if wing.taper_ratio is not None else 1.0
    sweep = np.arctan(np.tan(wing.sweep) - (1.0 - taper) / (wing.aspect_ratio * (1.0 + taper)))
    return {"moment_coefficient": wing_zero_lift_moment_coefficient(cm0, wing.aspect_ratio, sweep)}
