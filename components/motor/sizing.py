"""PMSM sizing: main dimensions, internal geometry, mass and peak torque (paper eq. 23)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.motor import parameters as mp
from lpc_mdo.components.motor.parameters import MotorParameters
from lpc_mdo.core.checks import RangeCheck, check_range

# (name, units, description) of the geometry outputs, in output order.
GEOMETRY_OUTPUTS = (
    ("stator_inner_diameter", "m", "Stator inner (bore) diameter D_i = D/lambda_i"),
    ("pole_pitch", "m", "Pole pitch tau_p = pi D_i/(2p)"),
    ("tooth_pitch", "m", "Stator tooth (slot) pitch t_1 = pi D_i/Z"),
    ("air_gap", "m", "Air-gap length delta = 0.4 A_bar tau_p/(0.9e6 B_delta,max)"),
    ("rotor_diameter", "m", "Rotor outer diameter D_2 = D_i - 2 delta"),
    ("shaft_diameter", "m", "Shaft diameter D_sh = 0.3 D_2"),
    (
        "turns_per_phase",
        None,
        "Series turns per phase W = pi D_i A_bar/(2 m I_w PF) (continuous, not rounded)",
    ),
    ("tooth_width", "m", "Stator tooth width b_t = t_1 B_delta,max/(k_fe B_t)"),
    (
        "stator_yoke_height",
        "m",
        "Stator yoke height h_ys = tau_p alpha_B B_delta,max/(2 k_fe B_ys)",
    ),
    ("slot_bottom_width", "m", "Slot width at the bore b_sb = theta_ssi pi D_i/360"),
    ("slot_height", "m", "Slot height h_slot = (D - D_i)/2 - h_ys"),
    ("slot_inner_width", "m", "Radially inner slot width b_s1 = pi (D_i + 2(h_os + h_k))/Z - b_t"),
)


class MotorSizingComp(om.ExplicitComponent):
    """
    Interior PMSM sizing from stack length, diameter and electric/magnetic loading.

    Implements docs theory/motor 'Sizing' (lsdo_motor ``motor_sizing_model``, torque mode) and paper
    eq. 23 (paper Sec. III.F):

    - D = L/(L/D) when the option ``length_to_diameter`` is set (the paper ties D to the length
      design variable), otherwise D is an input;
    - mass m = (pi/2) A_bar B_bar D**2 L/Q_sp  (eq. 23);
    - peak (current-limited) torque T_pk = polynomial fit of the mass (docs theory/motor 'Sizing',
      order 2 by default);
    - internal geometry, see the outputs. B_delta,max = 0.85 T is a fixed design value of the
      internal geometry, as coded: the magnetic loading enters the mass only. The slot count Z
      replaces the hard-coded 36 of lsdo_motor in b_s1 (identical for the default Z = 36).

    The winding: turns per phase W = N_c/2 with N_c = pi D_i A_bar/(m I_w PF), the conductors
    per phase that carry the electric loading A_bar at the rated current I_w (docs theory/motor
    'Winding for the bus'). I_w is an input, one per motor: the winding is chosen for the
    supply voltage (design variable ``motor_rated_current`` of the vehicle), not fixed.

    Every geometry output is linear in D, or bilinear in D and A_bar (delta, D_2, D_sh), W is
    A_bar D/I_w times a constant, so the partials are analytic and diagonal over the motors.

    Inputs
    ------
    length : float, (num_motors,), m
        Stack length L (design variable); must be > 0.
    diameter : float, (num_motors,), m
        Outer stator diameter D; an input only when ``length_to_diameter`` is None; must be > 0.
    electric_loading : float, (num_motors,), A/m
        Electric loading A_bar (line current density); > 0. Default 30e3.
    magnetic_loading : float, (num_motors,), T
        Magnetic loading B_bar; > 0. Default 0.85.
    rated_current : float, (num_motors,), A
        Rated phase current I_w of the winding; > 0. Default ``parameters.rated_current``.

    Outputs
    -------
    diameter : float, (num_motors,), m
        Outer stator diameter D = L/(L/D); an output only when ``length_to_diameter`` is set.
    mass : float, (num_motors,), kg
        Motor mass, eq. 23.
    peak_torque : float, (num_motors,), N*m
        Peak (current-limited) motor torque from the mass fit.
    stator_inner_diameter, pole_pitch, tooth_pitch, air_gap, rotor_diameter, shaft_diameter,
    tooth_width, stator_yoke_height, slot_bottom_width, slot_height, slot_inner_width :
    float, (num_motors,), m
        Internal geometry (docs theory/motor 'Sizing'), formulas in each output's desc.
    turns_per_phase : float, (num_motors,), dimensionless
        Series turns per phase W.

    Options
    -------
    num_motors : int
        Number of motors sized at once (>= 1). Default 1.
    length_to_diameter : float or None
        L/D ratio (> 0) tying D to L. Default 0.5 (paper; lsdo_motor's example uses 1/3). None
        makes ``diameter`` an input.
    parameters : MotorParameters
        Pole pairs, phases, slots, rated current, torque density, peak-torque fit.

    Raises
    ------
    om.AnalysisError
        In compute, if length, diameter or a loading is not finite and > 0.
    """

    def initialize(self):
        self.options.declare(
            "num_motors", default=1, types=int, lower=1, desc="Number of motors sized at once"
        )
        self.options.declare(
            "length_to_diameter",
            default=0.5,
            types=(int, float),
            allow_none=True,
            check_valid=_check_ratio,
            desc="L/D ratio tying D to L (> 0); None makes diameter an input",
        )
        self.options.declare(
            "parameters",
            default=MotorParameters(),
            types=MotorParameters,
            desc="Fixed motor parameters",
        )

    def setup(self):
        nm = self.options["num_motors"]
        ratio = self.options["length_to_diameter"]
        self.add_input("length", val=0.1 * np.ones(nm), units="m", desc="Stack length L")
        if ratio is None:
            self.add_input(
                "diameter", val=0.2 * np.ones(nm), units="m", desc="Outer stator diameter D"
            )
        self.add_input(
            "electric_loading",
            val=30.0e3 * np.ones(nm),
            units="A/m",
            desc="Electric loading A_bar (line current density)",
        )
        self.add_input(
            "magnetic_loading", val=0.85 * np.ones(nm), units="T", desc="Magnetic loading B_bar"
        )
        self.add_input(
            "rated_current",
            val=self.options["parameters"].rated_current * np.ones(nm),
            units="A",
            desc="Rated phase current I_w of the winding",
        )

        if ratio is not None:
            self.add_output(
                "diameter",
                val=0.2 * np.ones(nm),
                units="m",
                desc="Outer stator diameter D = L/(L/D)",
            )
        self.add_output(
            "mass",
            val=np.ones(nm),
            units="kg",
            desc="Motor mass (pi/2) A_bar B_bar D**2 L/Q_sp (paper eq. 23)",
        )
        self.add_output(
            "peak_torque",
            val=np.ones(nm),
            units="N*m",
            desc="Peak (current-limited) motor torque from the mass fit",
        )
        for name, units, desc in GEOMETRY_OUTPUTS:
            self.add_output(name, val=0.01 * np.ones(nm), units=units, desc=desc)

        dep = "length" if ratio is not None else "diameter"
        if ratio is not None:
            self.declare_partials("diameter", "length", diagonal=True, val=np.full(nm, 1.0 / ratio))
        for name in ("mass", "peak_torque"):
            for wrt in {"length", dep, "electric_loading", "magnetic_loading"}:
                self.declare_partials(name, wrt, diagonal=True)
        for name, _, _ in GEOMETRY_OUTPUTS:
            self.declare_partials(name, dep, diagonal=True)
            if name in ("air_gap", "rotor_diameter", "shaft_diameter", "turns_per_phase"):
                self.declare_partials(name, "electric_loading", diagonal=True)
        self.declare_partials("turns_per_phase", "rated_current", diagonal=True)

    def _diameter(self, inputs):
        ratio = self.options["length_to_diameter"]
        if ratio is None:
            return inputs["diameter"]
        return inputs["length"] / ratio

    def _check_inputs(self, inputs):
        check_range(
            "length",
            inputs["length"],
            lower=0.0,
            lower_open=True,
            units="m",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        if self.options["length_to_diameter"] is None:
            check_range(
                "diameter",
                inputs["diameter"],
                lower=0.0,
                lower_open=True,
                units="m",
                error=om.AnalysisError,
                where=self.msginfo,
            )
        check_range(
            "electric_loading",
            inputs["electric_loading"],
            lower=0.0,
            lower_open=True,
            units="A/m",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        check_range(
            "magnetic_loading",
            inputs["magnetic_loading"],
            lower=0.0,
            lower_open=True,
            units="T",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        check_range(
            "rated_current",
            inputs["rated_current"],
            lower=0.0,
            lower_open=True,
            units="A",
            error=om.AnalysisError,
            where=self.msginfo,
        )

    def _geometry(self, diameter, electric_loading, rated_current):
        """Return {name: (value, d/dD, d/dA_bar)} of the geometry outputs."""
        par = self.options["parameters"]
        p, z, m = par.pole_pairs, par.num_slots, par.phases
        d, a = diameter, electric_loading
        one = np.ones_like(d)
        k_di = 1.0 / mp.STATOR_DIAMETER_RATIO
        k_tau = np.pi * k_di / (2 * p)
        k_t1 = np.pi * k_di / z
        k_gap = 0.4 * k_tau / (0.9e6 * mp.AIR_GAP_FLUX_DENSITY_MAX)  # delta = k_gap A D
        k_turns = np.pi * k_di / (2.0 * m * rated_current * mp.POWER_FACTOR)  # W = k A D
        k_tooth = (
            k_t1 * mp.AIR_GAP_FLUX_DENSITY_MAX / (mp.LAMINATION_FACTOR * mp.TOOTH_FLUX_DENSITY)
        )
        k_yoke = (
            k_tau
            * mp.AIR_GAP_FLUX_RATIO
            * mp.AIR_GAP_FLUX_DENSITY_MAX
            / (2.0 * mp.LAMINATION_FACTOR * mp.YOKE_FLUX_DENSITY)
        )
        k_sb = mp.SLOT_BOTTOM_ANGLE_FRACTION * np.pi * k_di / z
        k_slot = 0.5 * (1.0 - k_di) - k_yoke
        k_rotor = k_di - 2.0 * k_gap * a
        lip = 2.0 * (mp.SLOT_OPENING_HEIGHT + mp.SLOT_LIP_HEIGHT)
        zero = 0.0 * d
        return {
            "stator_inner_diameter": (k_di * d, k_di * one, zero),
            "pole_pitch": (k_tau * d, k_tau * one, zero),
            "tooth_pitch": (k_t1 * d, k_t1 * one, zero),
            "air_gap": (k_gap * a * d, k_gap * a, k_gap * d),
            "rotor_diameter": (k_rotor * d, k_rotor, -2.0 * k_gap * d),
            "shaft_diameter": (0.3 * k_rotor * d, 0.3 * k_rotor, -0.6 * k_gap * d),
            "turns_per_phase": (k_turns * a * d, k_turns * a, k_turns * d),
            "tooth_width": (k_tooth * d, k_tooth * one, zero),
            "stator_yoke_height": (k_yoke * d, k_yoke * one, zero),
            "slot_bottom_width": (k_sb * d, k_sb * one, zero),
            "slot_height": (k_slot * d, k_slot * one, zero),
            "slot_inner_width": (
                np.pi * (k_di * d + lip) / z - k_tooth * d,
                (np.pi * k_di / z - k_tooth) * one,
                zero,
            ),
        }

    def _mass(self, length, diameter, a_bar, b_bar):
        q_sp = self.options["parameters"].torque_density
        return 0.5 * np.pi * a_bar * b_bar * diameter**2 * length / q_sp

    def compute(self, inputs, outputs):
        self._check_inputs(inputs)
        d = self._diameter(inputs)
        if self.options["length_to_diameter"] is not None:
            outputs["diameter"] = d
        mass = self._mass(
            inputs["length"], d, inputs["electric_loading"], inputs["magnetic_loading"]
        )
        outputs["mass"] = mass
        outputs["peak_torque"] = np.polyval(
            self.options["parameters"].peak_torque_coefficients, mass
        )
        geometry = self._geometry(d, inputs["electric_loading"], inputs["rated_current"])
        for name, (value, _, _) in geometry.items():
            outputs[name] = value

    def compute_partials(self, inputs, partials):
        ratio = self.options["length_to_diameter"]
        length, a_bar, b_bar = (
            inputs["length"],
            inputs["electric_loading"],
            inputs["magnetic_loading"],
        )
        d = self._diameter(inputs)
        dd_dep = 1.0 / ratio if ratio is not None else 1.0
        dep = "length" if ratio is not None else "diameter"

        mass = self._mass(length, d, a_bar, b_bar)
        dpeak_dmass = np.polyval(
            np.polyder(self.options["parameters"].peak_torque_coefficients), mass
        )
        # mass ~ A B D**2 L: logarithmic derivatives.
        dmass = {"electric_loading": mass / a_bar, "magnetic_loading": mass / b_bar}
        if ratio is not None:
            dmass["length"] = 3.0 * mass / length  # D = L/ratio: mass ~ L**3
        else:
            dmass["length"] = mass / length
            dmass["diameter"] = 2.0 * mass / d
        for wrt, value in dmass.items():
            partials["mass", wrt] = value
            partials["peak_torque", wrt] = dpeak_dmass * value

        geometry = self._geometry(d, a_bar, inputs["rated_current"])
        for name, (_, d_dd, d_da) in geometry.items():
            partials[name, dep] = d_dd * dd_dep
            if name in ("air_gap", "rotor_diameter", "shaft_diameter", "turns_per_phase"):
                partials[name, "electric_loading"] = d_da
        # W = k A_bar D/I_w: dW/dI_w = -W/I_w.
        partials["turns_per_phase", "rated_current"] = (
            -geometry["turns_per_phase"][0] / inputs["rated_current"]
        )


_check_ratio = RangeCheck(lower=0.0, lower_open=True, where="MotorSizingComp")
