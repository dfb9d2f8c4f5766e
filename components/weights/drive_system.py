"""Reduction gearbox and rotor shaft mass: the NDARC AFDD00 drive-system weight model.

Johnson, W., "NDARC - NASA Design and Analysis of Rotorcraft, Theory", NASA TP-2015-218751
(and later releases), chapter "Weights", section "Drive System", AFDD00 model for the gear boxes
and rotor shafts. In NDARC's units (lb, hp, rpm):

    w_gbrs = 95.7634 N_rotor^0.38553 P_DSlimit^0.78137 Omega_eng^0.09899 / Omega_rotor^0.80686

with N_rotor the rotors the drive system turns, P_DSlimit the drive system's rated power (its
torque limit times the reference rotor speed), Omega_eng the input (engine, here motor) speed and
Omega_rotor the rotor speed.

Each rotor of the lift-plus-cruise vehicle is turned by its own motor through its own reduction
gear (motor speed / rotor speed = the motor model's gear ratio G, docs theory/motor), so every
rotor has a one-rotor drive system, N_rotor = 1. Its rating follows the motor: the rotor-side
torque limit is G T_pk (T_pk the motor's peak torque, paper eq. 23 sizing), so at the design
rotor speed Omega_r

    P_DSlimit = G T_pk Omega_r,   Omega_eng = G Omega_r,

and a bigger motor needs a bigger gearbox. NASA's NDARC weight statement of the LPC carries
10.25 kg of drive system per lift rotor and 33.4 kg for the pusher (GUAM
``build_Lift_plus_Cruise.m``, from the SACD Lift+Cruise NDARC files); the paper's model has
the gear ratio but no gearbox mass. docs theory/weights 'Drive system'.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import RangeCheck, check_range

_LB = 0.45359237  # kg per lb
_HP = 745.69987158227022  # W per mechanical horsepower
_RPM = 2.0 * np.pi / 60.0  # rad/s per rpm

#: AFDD00 gear box and rotor shaft coefficients (NDARC theory manual, Drive System).
COEFFICIENT = 95.7634
EXPONENTS = {"rotors": 0.38553, "power": 0.78137, "engine_speed": 0.09899,
             "rotor_speed": -0.80686}  # fmt: skip

_positive = RangeCheck(lower=0.0, lower_open=True)


class DriveSystemMassComp(om.ExplicitComponent):
    """
    Gearbox and rotor-shaft mass of one rotor of each rotor group (NDARC AFDD00 model).

    For group i with motor peak torque T_i (N m, motor side), design rotor speed n_i (rpm) and
    gear ratio G, in NDARC's units (P in hp, speeds in rpm, mass in lb, then kg):

    - P_i = G T_i n_i (2 pi / 60) / 745.70         (rated drive power, hp)
    - w_i = 95.7634 P_i^0.78137 (G n_i)^0.09899 n_i^-0.80686   (N_rotor = 1)
    - drive_system_group_mass_i = 0.45359237 w_i

    Partials are analytic (a power law: d m / d T = 0.78137 m / T,
    d m / d n = (0.78137 + 0.09899 - 0.80686) m / n).

    Inputs
    ------
    motor_peak_torque : float, (n,), N*m
        Peak (current-limited) torque of each group's motor, motor side (> 0).
    rotor_design_speed : float, (n,), rpm
        Design rotor speed of each group (> 0), the speed of the rotor weight model.

    Outputs
    -------
    drive_system_group_mass : float, (n,), kg
        Gearbox and rotor-shaft mass of ONE rotor of each group.

    Options
    -------
    num_groups : int
        Rotor groups n (>= 1).
    gear_ratio : float
        Motor speed / rotor speed G (> 0), the motor model's.

    Raises
    ------
    om.AnalysisError
        In compute, if an input is not finite or not > 0.
    """

    def initialize(self):
        self.options.declare("num_groups", types=int, lower=1, desc="rotor groups")
        self.options.declare(
            "gear_ratio",
            default=4.0,
            types=(int, float),
            check_valid=_positive,
            desc="motor speed / rotor speed (> 0)",
        )

    def setup(self):
        n = self.options["num_groups"]
        self.add_input(
            "motor_peak_torque", np.full(n, 150.0), units="N*m", desc="motor peak torque"
        )
        self.add_input(
            "rotor_design_speed", np.full(n, 1200.0), units="rpm", desc="design rotor speed"
        )
        self.add_output(
            "drive_system_group_mass",
            np.full(n, 10.0),
            units="kg",
            desc="gearbox and rotor shaft of one rotor",
        )
        diag = np.arange(n)
        self.declare_partials(
            "drive_system_group_mass",
            ["motor_peak_torque", "rotor_design_speed"],
            rows=diag,
            cols=diag,
        )

    def _mass(self, inputs):
        for name, units in (("motor_peak_torque", "N*m"), ("rotor_design_speed", "rpm")):
            check_range(
                name,
                inputs[name],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        gear = float(self.options["gear_ratio"])
        speed = inputs["rotor_design_speed"]
        power = gear * inputs["motor_peak_torque"] * speed * _RPM / _HP
        e = EXPONENTS
        return (
            _LB
            * COEFFICIENT
            * power ** e["power"]
            * (gear * speed) ** e["engine_speed"]
            * speed ** e["rotor_speed"]
        )

    def compute(self, inputs, outputs):
        outputs["drive_system_group_mass"] = self._mass(inputs)

    def compute_partials(self, inputs, partials):
        mass = self._mass(inputs)
        e = EXPONENTS
        partials["drive_system_group_mass", "motor_peak_torque"] = (
            e["power"] * mass / inputs["motor_peak_torque"]
        )
        partials["drive_system_group_mass", "rotor_design_speed"] = (
            (e["power"] + e["engine_speed"] + e["rotor_speed"])
            * mass
            / inputs["rotor_design_speed"]
        )
