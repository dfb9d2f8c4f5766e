"""Design constants and material fits of the PMSM motor model (lsdo_motor, Cheng et al.).

Everything here is data of docs theory/motor: the user-facing parameters of docs theory/motor
'Parameters' in the typed, validated :class:`MotorParameters`, and the fixed constants of the sizing
(docs theory/motor 'Sizing'), equivalent circuit (docs theory/motor 'Equivalent circuit', 'Magnet
circuit', 'Inductances') and loss model (docs theory/motor 'Losses and efficiency') as module
constants, named by their physical meaning with the reference symbol in the comment.
"""

from dataclasses import dataclass

import numpy as np

from lpc_mdo.core.checks import check_integer, check_number
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY

MU_0 = 4.0e-7 * np.pi  # vacuum permeability, H/m

#: The motor-design quantities that the operating-point models read, per motor design (outputs
#: of ``MotorDesignGroup`` that ``MotorOperationGroup`` reads; the stack length, a design
#: variable, besides).
DESIGN_OUTPUTS = (
    "peak_torque",
    "peak_current",
    "resistance",
    "inductance_d",
    "inductance_q",
    "flux_linkage",
    "air_gap_flux_density",
    "iron_volume",
    "magnet_volume",
    "rotor_diameter",
)

# --- Sizing (docs theory/motor 'Sizing')
STATOR_DIAMETER_RATIO = 1.25  # lambda_i = D / D_i
AIR_GAP_FLUX_DENSITY_MAX = 0.85  # B_delta,max, T (design value; independent of B_bar as coded)
DESIGN_EFFICIENCY = 0.96  # eta_0, assumed efficiency in the winding design
POWER_FACTOR = 1.0  # PF
PARALLEL_STRANDS = 2  # N_p
CURRENT_DENSITY = 5.0e6  # J, A/m**2 (5 A/mm**2)
LAMINATION_FACTOR = 0.95  # k_fe
TOOTH_FLUX_DENSITY = 1.7  # B_t, T
YOKE_FLUX_DENSITY = 1.35  # B_ys, T
AIR_GAP_FLUX_RATIO = 0.7  # alpha_B = B_avg/B_max in the air gap
SLOT_LIP_HEIGHT = 0.8e-3  # h_k, m
SLOT_OPENING_HEIGHT = 1.5 * SLOT_LIP_HEIGHT  # h_os, m
SLOT_BOTTOM_ANGLE_FRACTION = 0.5 * 0.3  # theta_ssi = 0.3 theta_sso = 0.15 theta_t

# --- Magnet and equivalent-circuit parameters (docs theory/motor 'Equivalent circuit')
# -------------------------------------
MAGNET_THICKNESS = 4.0e-3  # h_m, m
MAGNET_EMBED_DEPTH = 2.0e-3  # m, D_m = D_2 - 0.002
MAGNET_ARC_RATIO = 0.78  # theta_m / theta_p
REMANENCE_20C = 1.2  # B_r20, T
REMANENCE_TEMPERATURE_COEFFICIENT = -0.12  # alpha_Br, %/K (also applied to the coercivity)
COERCIVITY_20C = 907000.0  # H_c20, A/m
MAGNET_RECOIL_PERMEABILITY = 1.05  # mu_r
COPPER_RESISTIVITY = 0.0217e-6  # rho_cu, Ohm m
COIL_STRAIGHT_EXTENSION = 0.02  # l_B = l_ef + 0.02, m

# --- Magnet magnetic equivalent circuit (docs theory/motor 'Magnet circuit')
# ---------------------------------------------
AIR_GAP_FRINGE_LENGTH = 1.0e-4  # m, F_delta = 1.6 B_delta (1e-4 + K_theta delta)/mu_0
BRIDGE_LEAKAGE_PERMEANCE = 0.336e-6  # lambda_s, Wb/A: phi_s = F_tot * 0.336e-6
LEAKAGE_GAP = 5.0e-4  # m, lambda_leak = l_ef b_m mu_0 / 0.0005
AIR_GAP_FLUX_DENSITY_BRACKET = (1.0e-6, 1.2)  # T, bracket of the B_delta solve

# --- Inductances (docs theory/motor 'Inductances')
# ------------------------------------------------------------------
D_AXIS_CURRENT_ANGLE = 0.6283  # rad, I_d,r = I_w sin(0.6283)
Q_AXIS_REACTION_FACTOR = 0.36  # K_aq = 0.36/K_f
D_AXIS_REACTION_FACTOR = 0.35  # F_ad = 0.35 m K_ad K_dp1 W I_d,r / p
SLOT_LEAKAGE_LOWER = 0.45  # lambda_L1
DIFFERENTIAL_LEAKAGE = 0.1  # s_total in X_d1
END_WINDING_FACTOR = 0.47  # X_E1 = 0.47 C_x (l_B - 0.64 tau_y)/(l_ef K_dp1**2)
END_WINDING_PITCH_FACTOR = 0.64
Q_AXIS_FLUX_LOWER = 1.0e-5  # Wb, lower bracket of the phi_aq solve (upper: the pole flux)

# --- Losses (docs theory/motor 'Losses and efficiency')
# -----------------------------------------------------------------------
LAMINATION_THICKNESS = 0.55e-3  # a_l, m
IRON_CONDUCTIVITY = 2.0e6  # sigma_c, S/m
EDDY_COEFFICIENT = (LAMINATION_THICKNESS * np.pi) ** 2 * IRON_CONDUCTIVITY / 60.0  # K_e
HYSTERESIS_COEFFICIENT = 100.0  # K_h (n_h = 2)
STRAY_LOSS_FRACTION = 0.01  # P_stress = 0.01 P_0
ROTOR_ROUGHNESS = 4.0  # k_r
ROTOR_FRICTION = 3.0e-3  # f_r
WINDAGE_AIR_DENSITY = SEA_LEVEL_DENSITY  # rho_air, kg/m**3
MECHANICAL_LOSS = 100.0  # P_m, W


def field_strength_from_flux_density(b):
    """
    Evaluate the iron B-H fit H(B) = (a exp(b B + c) + 200) B**1.4.

    (a, b, c) = (1.12832651, 1, 1); see docs theory/motor 'Magnet circuit'.

    Complex-step safe. ``b`` in T, returns A/m.
    """
    return (1.12832651 * np.exp(b + 1.0) + 200.0) * b**1.4


def bridge_flux_density(h):
    """
    Evaluate the magnet-bridge fit B(H) = a_H tanh(H/300 - 0.25) + 0.4.

    a_H = 1.92052530e-3; see docs theory/motor 'Magnet circuit'.

    Complex-step safe. ``h`` in A/m, returns T.
    """
    return 1.92052530e-3 * np.tanh(h / 300.0 - 0.25) + 0.4


_WHERE = "MotorParameters"


@dataclass(frozen=True)
class MotorParameters:
    """
    Fixed parameters of the interior PMSM (docs theory/motor 'Parameters').

    Attributes
    ----------
    pole_pairs : int
        Pole pairs p (>= 1). Default 6.
    phases : int
        Phases m (>= 1). Default 3.
    num_slots : int
        Stator slots Z (>= 1). Default 36 (q = Z/(2 m p) = 1).
    rated_current : float
        Rated phase current I_w of the reference winding, A (> 0). Default 120 (lsdo_motor). The
        motor models take the winding's rated current as an input (one per motor, the winding
        chosen for the bus; docs theory/motor 'Winding for the bus') and use this value as its
        default and for the slot copper that the iron volume deducts.
    voltage_limit : float
        Terminal voltage limit V_lim, V (> 0). Default 400 (600 in the older m3l model).
    gear_ratio : float
        Motor speed / rotor speed (> 0). Default 4; the load torque is rotor_torque/gear_ratio.
    rated_speed : float
        Rated motor speed, rpm (> 0), used for the inductance frequency f_i = rated_speed p/60.
        Default 5000.
    torque_density : float
        Specific torque Q_sp, N*m/kg (> 0), in the mass eq. 23. Default 15.
    peak_torque_coefficients : tuple of float
        Polynomial T_pk(mass) coefficients, highest power first (docs theory/motor 'Sizing' order-2
        fit). Default (0.4840, 3.3169, 60.8142): T_pk = 0.4840 m**2 + 3.3169 m + 60.8142.
    magnet_temperature : float
        Magnet temperature, deg C, for the remanence and coercivity (docs theory/motor 'Equivalent
        circuit'). Default 75.
    """

    pole_pairs: int = 6
    phases: int = 3
    num_slots: int = 36
    rated_current: float = 120.0
    voltage_limit: float = 400.0
    gear_ratio: float = 4.0
    rated_speed: float = 5000.0
    torque_density: float = 15.0
    peak_torque_coefficients: tuple = (0.4840, 3.3169, 60.8142)
    magnet_temperature: float = 75.0

    @classmethod
    def of_motor_table(cls, motor):
        """
        Return the parameters of a vehicle file's ``[motor]`` table (``vehicle.motor``).

        Raises ValueError (naming the parameter) for a winding or a number the model cannot
        take; the vehicle loader calls it so that such a file is refused before any model.
        """
        return cls(
            pole_pairs=motor.pole_pairs,
            phases=motor.num_phases,
            num_slots=motor.num_slots,
            rated_current=motor.rated_current,
            voltage_limit=motor.voltage_limit,
            gear_ratio=motor.gear_ratio,
            torque_density=motor.torque_density,
        )

    def __post_init__(self):
        for name in ("pole_pairs", "phases", "num_slots"):
            value = getattr(self, name)
            if not isinstance(value, (int, np.integer)):
                raise ValueError(
                    f"{_WHERE}: '{name}' must be an integer, got {type(value).__name__} {value!r}"
                )
            check_integer(name, value, lower=1, where=_WHERE)
        for name in (
            "rated_current",
            "voltage_limit",
            "gear_ratio",
            "rated_speed",
            "torque_density",
        ):
            check_number(name, getattr(self, name), lower=0.0, lower_open=True, where=_WHERE)
        coeffs = self.peak_torque_coefficients
        if not isinstance(coeffs, (tuple, list)) or len(coeffs) < 1:
            raise ValueError(
                f"{_WHERE}: 'peak_torque_coefficients' = {coeffs!r} is not "
                "allowed: must be a non-empty tuple of finite floats (highest "
                "power first)"
            )
        for i, c in enumerate(coeffs):
            check_number(f"peak_torque_coefficients[{i}]", c, where=_WHERE)
        t = self.magnet_temperature
        check_number("magnet_temperature", t, lower=-50.0, upper=200.0, units="degC", where=_WHERE)
        q = self.num_slots / (2 * self.phases * self.pole_pairs)
        if not (q >= 1.0 and float(q).is_integer()):
            raise ValueError(
                f"{_WHERE}: 'num_slots' = {self.num_slots!r} is not allowed: must "
                f"be a multiple of 2*phases*pole_pairs = "
                f"{2 * self.phases * self.pole_pairs} (integral-slot winding, "
                "q = Z/(2 m p) integer)"
            )

    @property
    def slots_per_pole_per_phase(self):
        """Slots per pole per phase, q = Z/(2 m p)."""
        return self.num_slots / (2 * self.phases * self.pole_pairs)

    @property
    def winding_factor(self):
        """
        K_dp1 = K_d1 K_p1 with K_p1 = 1 (full pitch) and K_d1 = sin(q a/2)/(q sin(a/2)).

        a = 2 pi p/Z is the slot angle in electrical radians. lsdo_motor passes the angle in
        degrees to sin(), which is harmless only for q = 1 (K_d1 = 1); radians are used here.
        """
        q = self.slots_per_pole_per_phase
        alpha = 2.0 * np.pi * self.pole_pairs / self.num_slots
        return float(np.sin(q * alpha / 2.0) / (q * np.sin(alpha / 2.0)))

    @property
    def temperature_factor(self):
        """1 + (T - 20) alpha_Br/100: remanence and coercivity derating (0.934 at 75 deg C)."""
        return 1.0 + (self.magnet_temperature - 20.0) * REMANENCE_TEMPERATURE_COEFFICIENT / 100.0

    @property
    def remanence(self):
        """
        B_r = (1 + (T - 20) alpha_Br/100) B_r20, T (1.1208 at 75 deg C).

        The corrected form (docs theory/motor 'Public-code compatibility'); lsdo_motor's slip 1 +
        (T-20) alpha/100 B_r20 fed nothing, and this value is what it hard-codes as B_r' in the
        inductance model.
        """
        return self.temperature_factor * REMANENCE_20C

    @property
    def coercivity(self):
        """H_c = (1 + (T - 20) alpha_Br/100) H_c20, A/m (847138 at 75 deg C)."""
        return self.temperature_factor * COERCIVITY_20C

    @property
    def copper_area(self):
        """A_cu = I_w/(J N_p), m**2 (1.2e-5 for 120 A)."""
        return self.rated_current / (CURRENT_DENSITY * PARALLEL_STRANDS)

    @property
    def d_axis_rated_current(self):
        """I_d,r = I_w sin(0.6283), A."""
        return self.rated_current * np.sin(D_AXIS_CURRENT_ANGLE)

    @property
    def rated_frequency(self):
        """f_i = rated_speed p/60, Hz (500 Hz for 5000 rpm and p = 6)."""
        return self.rated_speed * self.pole_pairs / 60.0
