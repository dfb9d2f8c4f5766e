"""Rotor blade and hub mass: the NDARC AFDD00 rotor-group weight model.

Johnson, W., "NDARC - NASA Design and Analysis of Rotorcraft, Theory", NASA TP-2015-218751
(and later releases), chapter "Weights", section "Rotor Group", AFDD00 model (fit to 51
aircraft; average error 7.9 % for the blades and 12.2 % for the hubs). In NDARC's units (lb,
ft, ft/s, per rev), for one rotor (N_rotor = 1):

- w_blade = 0.0024419 f_tilt N_b^0.53479 R^1.74231 c^0.77291 V_tip^0.87562 nu_b^2.51048
- w_hub   = 0.0061182 N_b^0.20373 R^0.60406 V_tip^0.52803 nu_h^1.00218 w_blade^0.87127

with N_b blades, radius R, blade chord c, hover tip speed V_tip and flap natural frequency nu
(f_tilt = 1 for non-tilting rotors; the flap frequency of the blades is used for the hub).
docs theory/weights 'Rotor blades and hubs' gives the derivation of the SI form below.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import RangeCheck, check_range

_FT = 0.3048  # m per ft
_LB = 0.45359237  # kg per lb

#: AFDD00 coefficients (NDARC theory manual, Rotor Group, AFDD00 model).
BLADE_COEFFICIENT = 0.0024419
BLADE_EXPONENTS = {"blades": 0.53479, "radius": 1.74231, "chord": 0.77291, "tip_speed": 0.87562,
                   "flap_frequency": 2.51048}  # fmt: skip
HUB_COEFFICIENT = 0.0061182
HUB_EXPONENTS = {"blades": 0.20373, "radius": 0.60406, "tip_speed": 0.52803,
                 "flap_frequency": 1.00218, "blade_weight": 0.87127}  # fmt: skip

_positive = RangeCheck(lower=0.0, lower_open=True)


def _check_blades(name, value):
    values = np.atleast_1d(value)
    if values.size == 0 or not all(isinstance(v, (int, np.integer)) and v >= 1 for v in values):
        raise ValueError(f"Option '{name}' = {value!r}; must be a list of integers >= 1.")


class RotorMassComp(om.ExplicitComponent):
    """
    Blade, hub and total mass of one rotor of each rotor group (NDARC AFDD00 model).

    In SI with x_ft = x / 0.3048 and the result in kg (1 lb = 0.45359237 kg), for group i:

    - mean chord  c_i = mean_j chord_cp[i, j] (the mean of a Bezier curve's control points is
      its mean over the curve parameter, docs theory/rotors 'Blade parameterization')
    - tip speed   V_i = Omega_i R_i (design rotor speed times radius)
    - m_blade,i = 0.45359237 * 0.0024419 N_b^0.53479 R_ft^1.74231 c_ft^0.77291 V_fps^0.87562
      nu^2.51048 (all blades of the rotor)
    - m_hub,i   = 0.45359237 * 0.0061182 N_b^0.20373 R_ft^0.60406 V_fps^0.52803 nu^1.00218
      w_blade,lb^0.87127
    - rotor_group_mass = m_blade + m_hub

    All partials are analytic (power laws: d m / d x = e m / x).

    Inputs
    ------
    rotor_radius : float, (n,), m
        Radius of each group's rotors (> 0).
    blade_chord_cp : float, (n, num_cp), m
        Blade-chord control points (> 0).
    rotor_design_speed : float, (n,), rpm
        Design (hover) rotor speed of each group (> 0).

    Outputs
    -------
    blade_mass, hub_mass, rotor_group_mass : float, (n,), kg
        Mass of the blades, of the hub and hinge, and their sum, for ONE rotor of each group.

    Options
    -------
    num_blades : sequence of int
        Blades per rotor of each group (its length is n).
    num_cp : int
        Chord control points per blade (default 4).
    flap_frequency : float
        Blade flap natural frequency nu, per rev (> 0); 1.25 for hingeless rotors.

    Raises
    ------
    om.AnalysisError
        In compute, if an input is not finite or not > 0.
    """

    def initialize(self):
        self.options.declare(
            "num_blades", types=(list, tuple), check_valid=_check_blades, desc="blades per group"
        )
        self.options.declare("num_cp", default=4, types=int, lower=1, desc="chord control points")
        self.options.declare(
            "flap_frequency",
            default=1.25,
            types=(int, float),
            check_valid=_positive,
            desc="blade flap natural frequency, per rev (> 0)",
        )

    def setup(self):
        n = len(self.options["num_blades"])
        ncp = self.options["num_cp"]
        self.add_input("rotor_radius", np.full(n, 1.5), units="m", desc="rotor radius per group")
        self.add_input(
            "blade_chord_cp", np.full((n, ncp), 0.2), units="m", desc="blade chord control points"
        )
        self.add_input(
            "rotor_design_speed", np.full(n, 1200.0), units="rpm", desc="design rotor speed"
        )
        for name, what in (
            ("blade_mass", "blades"),
            ("hub_mass", "hub and hinge"),
            ("rotor_group_mass", "blades and hub"),
        ):
            self.add_output(name, np.full(n, 10.0), units="kg", desc=f"{what} of one rotor")

        diag = np.arange(n)
        cp_rows = np.repeat(diag, ncp)
        cp_cols = np.arange(n * ncp)
        for out in ("blade_mass", "hub_mass", "rotor_group_mass"):
            self.declare_partials(out, ["rotor_radius", "rotor_design_speed"], diagonal=True)
            self.declare_partials(out, "blade_chord_cp", rows=cp_rows, cols=cp_cols)

        blades = np.asarray(self.options["num_blades"], dtype=float)
        nu = float(self.options["flap_frequency"])
        b, h = BLADE_EXPONENTS, HUB_EXPONENTS
        self._kb = BLADE_COEFFICIENT * blades ** b["blades"] * nu ** b["flap_frequency"]
        self._kh = HUB_COEFFICIENT * blades ** h["blades"] * nu ** h["flap_frequency"]

    def _evaluate(self, inputs):
        for name, units in (
            ("rotor_radius", "m"),
            ("blade_chord_cp", "m"),
            ("rotor_design_speed", "rpm"),
        ):
            check_range(
                name,
                inputs[name],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        b, h = BLADE_EXPONENTS, HUB_EXPONENTS
        radius = inputs["rotor_radius"] / _FT
        chord = np.mean(inputs["blade_chord_cp"], axis=1) / _FT
        tip = inputs["rotor_design_speed"] * (2.0 * np.pi / 60.0) * radius  # ft/s
        w_blade = self._kb * radius ** b["radius"] * chord ** b["chord"] * tip ** b["tip_speed"]
        w_hub = (
            self._kh * radius ** h["radius"] * tip ** h["tip_speed"] * w_blade ** h["blade_weight"]
        )
        return w_blade, w_hub

    def compute(self, inputs, outputs):
        w_blade, w_hub = self._evaluate(inputs)
        outputs["blade_mass"] = _LB * w_blade
        outputs["hub_mass"] = _LB * w_hub
        outputs["rotor_group_mass"] = _LB * (w_blade + w_hub)

    def compute_partials(self, inputs, partials):
        w_blade, w_hub = self._evaluate(inputs)
        b, h = BLADE_EXPONENTS, HUB_EXPONENTS
        ncp = self.options["num_cp"]
        # Logarithmic sensitivities: V = Omega R, so d ln V / d ln R = 1.
        eb = {
            "rotor_radius": b["radius"] + b["tip_speed"],
            "rotor_design_speed": b["tip_speed"],
            "blade_chord_cp": b["chord"],
        }
        eh = {
            "rotor_radius": h["radius"] + h["tip_speed"],
            "rotor_design_speed": h["tip_speed"],
            "blade_chord_cp": 0.0,
        }
        for name in ("rotor_radius", "rotor_design_speed", "blade_chord_cp"):
            if name == "blade_chord_cp":
                scale = np.repeat(1.0 / (ncp * np.mean(inputs[name], axis=1)), ncp)
                rep = ncp
            else:
                scale = 1.0 / inputs[name]
                rep = 1
            d_blade = _LB * w_blade * eb[name]
            d_hub = _LB * w_hub * (eh[name] + h["blade_weight"] * eb[name])
            d_blade = np.repeat(d_blade, rep) * scale
            d_hub = np.repeat(d_hub, rep) * scale
            partials["blade_mass", name] = d_blade
            partials["hub_mass", name] = d_hub
            partials["rotor_group_mass", name] = d_blade + d_hub
