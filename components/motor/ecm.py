"""PMSM equivalent-circuit parameters: magnet circuit, magnet MEC and d/q inductances.

docs theory/motor 'Equivalent circuit', 'Magnet circuit', 'Inductances' (lsdo_motor
``motor_ecm_parameters_model``, ``magnet_mec_model``, ``inductance_model``). All quantities are per
motor, shape (num_motors,).
The two implicit solves (air-gap flux density of the magnet MEC, q-axis flux of the inductance
iteration) are vectorized bisections on the reference brackets; the partials of every component
are an exact vectorized complex step (see :mod:`._numerics`).

Reproduced as coded, because the docs theory/motor 'Validation' reference numbers depend on it:
lsdo_motor overwrites its air-gap flux ``phi_air = alpha_i tau_p l B_delta`` with the magnet
operating flux
``phi_r - F_m lambda_m`` (equal to phi_air + phi_f + phi_s at the MEC solution) before the
post-processing, so the "air-gap flux" that feeds K_sigma, lambda_theta, the back-EMF E_0, the
q-axis bracket and Psi_F = W phi is the flux leaving the magnet, called ``pole_flux`` here
(0.0072794 Wb for case A, against alpha_i tau_p l B_delta = 0.0065758 Wb). With the geometric
air-gap flux instead, Psi_F would be 9.7 % lower (0.2706 Wb) than the reference 0.2996 Wb.
"""

import numpy as np
from openmdao.api import AnalysisError

from lpc_mdo.components.motor import parameters as mp
from lpc_mdo.components.motor._pointwise import PointwiseExplicitComp, PointwiseImplicitComp
from lpc_mdo.core.checks import check_range


def _complex_safe_abs(x):
    """abs(x) with the derivative sign(Re x) under complex step."""
    return x * np.sign(np.asarray(x).real)


# --------------------------------------------------------------------------------------------
# Magnet circuit and equivalent-circuit parameters (explicit, docs theory/motor 'Equivalent
# circuit')
# --------------------------------------------------------------------------------------------


class MotorECMParametersComp(PointwiseExplicitComp):
    """
    Geometry-derived equivalent-circuit parameters of the PMSM, per motor.

    See docs theory/motor 'Equivalent circuit'.

    - yoke pitch tau_y = pi (D_i + h_slot)/(2p); yoke path L_j1 = pi (D - h_ys)/(4p);
    - magnet: b_m = (D_2 - 0.002) pi theta_m/360 with theta_m = 0.78 * 360/(2p); A_m = b_m l;
      phi_r = 1.2 A_m (B_r20, as coded); lambda_m = phi_r/(2 H_c h_m), H_c at the magnet
      temperature (847138 A/m at 75 deg C);
    - alpha_p1 = b_m/tau_p; alpha_i = alpha_p1 + 4/(tau_p/delta + 6/(1 - alpha_p1));
      K_f = 4 sin(alpha_i pi/2)/pi; K_phi = 8.5 sin(alpha_i pi/2)/(pi**2 alpha_i);
    - Carter factor K_theta = t_1 (4.4 delta + 0.75 b_sb)/(t_1 (4.4 delta + 0.75 b_sb) - b_sb**2);
    - bridge area A_f2 = h_m l;
    - R_dc = 2 rho_cu W (l + 0.02 + 2 tau_p)/(A_cu N_p), with the strand area of the winding
      A_cu = I_w/(J N_p) at its rated current I_w (an input: the winding chosen for the bus);
    - loss volumes (docs theory/motor 'Losses and efficiency'): iron V_s + V_s1 = pi l (D -
      D_i)**2/4 - Z l A_cu,0 + pi l (D_2 - D_sh)**2/4, magnet V_t = 2 p l b_m h_m. The slot
      copper deducted, Z l A_cu,0 as coded, is that of the parameters' reference winding
      (``parameters.rated_current``): a rewinding for another bus keeps the slot fill (W A_cu
      is independent of I_w), so it does not change the iron.

    The effective length is l_ef = L (lsdo_motor dev_csdl_alpha). Partials: exact vectorized
    complex step, diagonal over the motors.

    Inputs
    ------
    length, diameter, stator_inner_diameter, pole_pitch, tooth_pitch, air_gap, rotor_diameter,
    shaft_diameter, slot_bottom_width, slot_height, stator_yoke_height : float, (num_motors,), m
        Sizing geometry (MotorSizingComp).
    turns_per_phase : float, (num_motors,), dimensionless
        Series turns per phase W.
    rated_current : float, (num_motors,), A
        Rated phase current I_w of the winding (sets the strand area A_cu).

    Outputs
    -------
    yoke_pitch, yoke_path_length, magnet_width : float, (num_motors,), m
        tau_y, L_j1, b_m.
    magnet_area, bridge_area : float, (num_motors,), m**2
        A_m = b_m l, A_f2 = h_m l.
    remanent_flux : float, (num_motors,), Wb
        phi_r = 1.2 A_m.
    magnet_permeance : float, (num_motors,), H
        lambda_m = phi_r/F_c.
    pole_arc_coefficient, air_gap_field_coefficient, air_gap_flux_coefficient,
    carter_coefficient : float, (num_motors,), dimensionless
        alpha_i, K_f, K_phi, K_theta.
    resistance : float, (num_motors,), ohm
        Phase resistance R_dc.
    iron_volume, magnet_volume : float, (num_motors,), m**3
        Iron (stator + rotor) and magnet volumes of the loss model.

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    parameters : MotorParameters
        Fixed motor parameters (pole pairs, slots, rated current, magnet temperature).

    Raises
    ------
    om.AnalysisError
        If the rotor is too small to hold the embedded magnets (D_2 <= 0.002 m).
    """

    _input_vars = (
        ("length", "m", "Stack (effective) length l_ef = L", 0.1, False),
        ("diameter", "m", "Outer stator diameter D", 0.2, False),
        ("stator_inner_diameter", "m", "Stator inner diameter D_i", 0.16, False),
        ("pole_pitch", "m", "Pole pitch tau_p", 0.04, False),
        ("tooth_pitch", "m", "Tooth pitch t_1", 0.014, False),
        ("air_gap", "m", "Air-gap length delta", 6.0e-4, False),
        ("rotor_diameter", "m", "Rotor diameter D_2", 0.16, False),
        ("shaft_diameter", "m", "Shaft diameter D_sh", 0.05, False),
        ("turns_per_phase", None, "Series turns per phase W", 20.0, False),
        ("slot_bottom_width", "m", "Slot width at the bore b_sb", 2.0e-3, False),
        ("slot_height", "m", "Slot height h_slot", 0.01, False),
        ("stator_yoke_height", "m", "Stator yoke height h_ys", 0.01, False),
        ("rated_current", "A", "Rated phase current I_w of the winding", 120.0, False),
    )
    _output_vars = (
        ("yoke_pitch", "m", "Yoke pitch tau_y = pi (D_i + h_slot)/(2p)", 0.04, False),
        ("yoke_path_length", "m", "Stator yoke MEC path L_j1 = pi (D - h_ys)/(4p)", 0.025, False),
        ("magnet_width", "m", "Magnet arc width b_m", 0.03, False),
        ("magnet_area", "m**2", "Magnet pole-face area A_m = b_m l_ef", 3.0e-3, False),
        ("remanent_flux", "Wb", "Remanent magnet flux phi_r = 1.2 A_m", 3.6e-3, False),
        (
            "magnet_permeance",
            "H",
            "Internal magnet permeance lambda_m = phi_r/(2 H_c h_m)",
            5.0e-7,
            False,
        ),
        ("pole_arc_coefficient", None, "Calculated pole-arc coefficient alpha_i", 0.8, False),
        (
            "air_gap_field_coefficient",
            None,
            "Air-gap flux-density waveform coefficient K_f",
            1.2,
            False,
        ),
        ("air_gap_flux_coefficient", None, "Air-gap flux waveform coefficient K_phi", 1.0, False),
        ("carter_coefficient", None, "Carter coefficient K_theta", 1.07, False),
        ("bridge_area", "m**2", "Magnet bridge cross-section A_f2 = h_m l_ef", 4.0e-4, False),
        ("resistance", "ohm", "Phase DC resistance R_dc", 0.01, False),
        ("iron_volume", "m**3", "Iron volume of the core losses V_s + V_s1", 1.0e-3, False),
        (
            "magnet_volume",
            "m**3",
            "Magnet volume of the magnet eddy loss V_t = 2p l b_m h_m",
            1.0e-4,
            False,
        ),
    )
    _deps = {
        "yoke_pitch": ("stator_inner_diameter", "slot_height"),
        "yoke_path_length": ("diameter", "stator_yoke_height"),
        "magnet_width": ("rotor_diameter",),
        "magnet_area": ("rotor_diameter", "length"),
        "remanent_flux": ("rotor_diameter", "length"),
        "magnet_permeance": ("rotor_diameter", "length"),
        "pole_arc_coefficient": ("rotor_diameter", "pole_pitch", "air_gap"),
        "air_gap_field_coefficient": ("rotor_diameter", "pole_pitch", "air_gap"),
        "air_gap_flux_coefficient": ("rotor_diameter", "pole_pitch", "air_gap"),
        "carter_coefficient": ("tooth_pitch", "air_gap", "slot_bottom_width"),
        "bridge_area": ("length",),
        "resistance": ("turns_per_phase", "length", "pole_pitch", "rated_current"),
        "iron_volume": (
            "length",
            "diameter",
            "stator_inner_diameter",
            "rotor_diameter",
            "shaft_diameter",
        ),
        "magnet_volume": ("length", "rotor_diameter"),
    }

    def _check_values(self, values):
        check_range(
            "rated_current",
            values["rated_current"],
            lower=0.0,
            lower_open=True,
            units="A",
            error=AnalysisError,
            where=self.msginfo,
        )
        check_range(
            "rotor_diameter",
            values["rotor_diameter"],
            lower=mp.MAGNET_EMBED_DEPTH,
            lower_open=True,
            units="m",
            error=AnalysisError,
            where=self.msginfo,
        )

    def _evaluate(self, v):
        par = self.options["parameters"]
        p, z = par.pole_pairs, par.num_slots
        length, diameter, d_i = v["length"], v["diameter"], v["stator_inner_diameter"]
        tau, delta, d_2 = v["pole_pitch"], v["air_gap"], v["rotor_diameter"]
        b_sb, t_1 = v["slot_bottom_width"], v["tooth_pitch"]

        theta_m = mp.MAGNET_ARC_RATIO * 360.0 / (2 * p)
        b_m = (d_2 - mp.MAGNET_EMBED_DEPTH) * np.pi * theta_m / 360.0
        a_m = b_m * length
        phi_r = mp.REMANENCE_20C * a_m
        alpha_p1 = b_m / tau
        alpha_i = alpha_p1 + 4.0 / (tau / delta + 6.0 / (1.0 - alpha_p1))
        carter = t_1 * (4.4 * delta + 0.75 * b_sb)
        a_cu = v["rated_current"] / (mp.CURRENT_DENSITY * mp.PARALLEL_STRANDS)
        coil = length + mp.COIL_STRAIGHT_EXTENSION + 2.0 * tau
        return {
            "yoke_pitch": np.pi * (d_i + v["slot_height"]) / (2 * p),
            "yoke_path_length": np.pi * (diameter - v["stator_yoke_height"]) / (4 * p),
            "magnet_width": b_m,
            "magnet_area": a_m,
            "remanent_flux": phi_r,
            "magnet_permeance": phi_r / (2.0 * par.coercivity * mp.MAGNET_THICKNESS),
            "pole_arc_coefficient": alpha_i,
            "air_gap_field_coefficient": 4.0 * np.sin(alpha_i * np.pi / 2.0) / np.pi,
            "air_gap_flux_coefficient": 8.5 * np.sin(alpha_i * np.pi / 2.0) / (np.pi**2 * alpha_i),
            "carter_coefficient": carter / (carter - b_sb**2),
            "bridge_area": mp.MAGNET_THICKNESS * length,
            "resistance": (
                2.0
                * mp.COPPER_RESISTIVITY
                * v["turns_per_phase"]
                * coil
                / (a_cu * mp.PARALLEL_STRANDS)
            ),
            "iron_volume": (
                np.pi * length * (diameter - d_i) ** 2 / 4.0
                - z * length * par.copper_area
                + np.pi * length * (d_2 - v["shaft_diameter"]) ** 2 / 4.0
            ),
            "magnet_volume": 2 * p * length * b_m * mp.MAGNET_THICKNESS,
        }


# --------------------------------------------------------------------------------------------
# Magnet magnetic equivalent circuit (docs theory/motor 'Magnet circuit')
# --------------------------------------------------------------------------------------------

_MEC_INPUTS = (
    ("tooth_pitch", "m", "Tooth pitch t_1", 0.014, False),
    ("tooth_width", "m", "Stator tooth width b_t", 7.0e-3, False),
    ("slot_height", "m", "Slot height h_slot (tooth MEC path)", 0.01, False),
    ("pole_arc_coefficient", None, "Calculated pole-arc coefficient alpha_i", 0.8, False),
    ("pole_pitch", "m", "Pole pitch tau_p", 0.04, False),
    ("length", "m", "Stack (effective) length l_ef", 0.1, False),
    ("stator_yoke_height", "m", "Stator yoke height h_ys", 0.01, False),
    ("yoke_path_length", "m", "Stator yoke MEC path L_j1", 0.025, False),
    ("air_gap", "m", "Air-gap length delta", 6.0e-4, False),
    ("carter_coefficient", None, "Carter coefficient K_theta", 1.07, False),
    ("bridge_area", "m**2", "Magnet bridge cross-section A_f2", 4.0e-4, False),
)
_MAGNET_INPUTS = (
    ("magnet_width", "m", "Magnet arc width b_m", 0.03, False),
    ("remanent_flux", "Wb", "Remanent magnet flux phi_r", 3.6e-3, False),
    ("magnet_permeance", "H", "Internal magnet permeance lambda_m", 5.0e-7, False),
)
_MEC_NAMES = tuple(name for name, *_ in _MEC_INPUTS)
_MAGNET_NAMES = tuple(name for name, *_ in _MAGNET_INPUTS)


def magnet_circuit(b_delta, v):
    """
    Evaluate the magnet MEC at the air-gap flux density ``b_delta`` (complex-safe).

    The MEC is that of docs theory/motor 'Magnet circuit'.

    Returns a dict with the air-gap flux phi_air = alpha_i tau_p l B_delta, the air-gap and
    total MMFs, the bridge flux phi_f, the bridge leakage phi_s and the magnet flux
    phi_mag = phi_air + phi_f + phi_s.
    """
    length = v["length"]
    b_tooth = b_delta * v["tooth_pitch"] / v["tooth_width"] / mp.LAMINATION_FACTOR
    mmf_tooth = 2.0 * mp.field_strength_from_flux_density(b_tooth) * v["slot_height"]
    flux_air = v["pole_arc_coefficient"] * v["pole_pitch"] * length * b_delta
    # B_y = phi_air/(2 h_ys l_ef), with l_ef cancelled exactly.
    b_yoke = v["pole_arc_coefficient"] * v["pole_pitch"] * b_delta / (2.0 * v["stator_yoke_height"])
    mmf_yoke = 2.0 * v["yoke_path_length"] * mp.field_strength_from_flux_density(b_yoke)
    mmf_gap = (
        1.6
        * b_delta
        * (mp.AIR_GAP_FRINGE_LENGTH + v["carter_coefficient"] * v["air_gap"])
        / mp.MU_0
    )
    mmf_total = mmf_tooth + mmf_yoke + mmf_gap
    flux_bridge = mp.bridge_flux_density(mmf_total / mp.MAGNET_THICKNESS) * v["bridge_area"]
    flux_leak = mmf_total * mp.BRIDGE_LEAKAGE_PERMEANCE
    return {
        "flux_air": flux_air,
        "mmf_total": mmf_total,
        "mmf_air_gap": mmf_gap,
        "flux_bridge": flux_bridge,
        "flux_leak": flux_leak,
        "flux_magnet": flux_air + flux_bridge + flux_leak,
    }


def magnet_operating_flux(circuit, v):
    """
    Return the magnet operating flux phi_r - F_m lambda_m for a :func:`magnet_circuit` circuit.

    See docs theory/motor 'Magnet circuit'.

    F_m = F_tot + phi_mag/lambda_leak with the leakage permeance lambda_leak = l b_m mu_0/0.0005.
    """
    permeance_leak = v["length"] * v["magnet_width"] * mp.MU_0 / mp.LEAKAGE_GAP
    mmf_magnet = circuit["mmf_total"] + circuit["flux_magnet"] / permeance_leak
    return v["remanent_flux"] - mmf_magnet * v["magnet_permeance"]


class MagnetCircuitComp(PointwiseImplicitComp):
    """
    Magnet magnetic equivalent circuit: air-gap flux density B_delta (implicit).

    See docs theory/motor 'Magnet circuit'.

    For a trial B_delta the circuit gives the tooth, yoke and air-gap MMFs (iron B-H fit
    H(B) = (1.12832651 e^(B+1) + 200) B**1.4), the bridge flux (B(H) = 1.92e-3 tanh(H/300 -
    0.25) + 0.4), the bridge leakage and the magnet MMF F_m = F_tot + phi_mag/lambda_leak. The
    residual is the reference one divided by phi_r (same root, dimensionless):

        R = ((phi_r - F_m lambda_m) - phi_mag)/phi_r = 0.

    solve_nonlinear: vectorized bisection on the reference bracket B_delta in [1e-6, 1.2] T.
    linearize: exact complex-step Jacobian of R (diagonal over the motors).

    Inputs
    ------
    tooth_pitch, tooth_width, slot_height, pole_pitch, length, stator_yoke_height,
    yoke_path_length, air_gap, magnet_width : float, (num_motors,), m
        Geometry.
    pole_arc_coefficient, carter_coefficient : float, (num_motors,), dimensionless
        alpha_i, K_theta.
    bridge_area : float, (num_motors,), m**2
        A_f2.
    remanent_flux : float, (num_motors,), Wb
        phi_r.
    magnet_permeance : float, (num_motors,), H
        lambda_m.

    Outputs
    -------
    air_gap_flux_density : float, (num_motors,), T
        No-load air-gap flux density B_delta (state).

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    parameters : MotorParameters
        Fixed motor parameters.

    Raises
    ------
    om.AnalysisError
        If the residual does not change sign on [1e-6, 1.2] T.
    """

    _input_vars = _MEC_INPUTS + _MAGNET_INPUTS
    _state_var = ("air_gap_flux_density", "T", "No-load air-gap flux density B_delta", 0.75, False)
    _deps = _MEC_NAMES + _MAGNET_NAMES

    def _residual(self, v, b_delta):
        circuit = magnet_circuit(b_delta, v)
        return (magnet_operating_flux(circuit, v) - circuit["flux_magnet"]) / v["remanent_flux"]

    def _bracket(self, v):
        lower, upper = mp.AIR_GAP_FLUX_DENSITY_BRACKET
        shape = v["length"].shape
        return np.full(shape, lower), np.full(shape, upper)


class MagnetFluxComp(PointwiseExplicitComp):
    """
    Magnet MEC post-processing: pole flux, MMFs and per-unit permeances.

    See docs theory/motor 'Magnet circuit'.

    With phi the flux per pole (as coded, the magnet operating flux phi_r - F_m lambda_m = phi_mag
    at the MEC solution; see the module docstring):

    - K_sigma = (phi + phi_f + phi_s)/phi  (as coded: 1.09666 for case A);
    - lambda_theta = phi/F_tot; lambda_theta,std = 2 lambda_theta h_m/(mu_r mu_0 A_m), mu_r = 1.05;
    - lambda_n = K_sigma lambda_theta,std; lambda_leak,std = (K_sigma - 1) lambda_theta,std.

    Partials: exact vectorized complex step, diagonal over the motors.

    Inputs
    ------
    air_gap_flux_density : float, (num_motors,), T
        B_delta (MagnetCircuitComp).
    magnet_area : float, (num_motors,), m**2
        A_m.
    tooth_pitch, tooth_width, slot_height, pole_pitch, length, stator_yoke_height,
    yoke_path_length, air_gap : float, (num_motors,), m
        Geometry, as in MagnetCircuitComp.
    pole_arc_coefficient, carter_coefficient : float, (num_motors,), dimensionless
        alpha_i, K_theta.
    bridge_area : float, (num_motors,), m**2
        A_f2.

    Outputs
    -------
    pole_flux : float, (num_motors,), Wb
        Flux per pole linking the winding, phi (as coded).
    mmf_total, mmf_air_gap : float, (num_motors,), A
        Total no-load MMF F_tot and its air-gap part F_delta.
    leakage_coefficient, magnet_permeance_pu, leakage_permeance_pu :
    float, (num_motors,), dimensionless
        K_sigma, lambda_n, lambda_leak,std.

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    parameters : MotorParameters
        Fixed motor parameters.
    """

    _input_vars = _MEC_INPUTS + (
        ("air_gap_flux_density", "T", "No-load air-gap flux density B_delta", 0.75, False),
        ("magnet_area", "m**2", "Magnet pole-face area A_m", 3.0e-3, False),
    )
    _output_vars = (
        (
            "pole_flux",
            "Wb",
            "Flux per pole linking the winding (as coded: the magnet "
            "operating flux phi_r - F_m lambda_m)",
            5.0e-3,
            False,
        ),
        ("mmf_total", "A", "Total no-load MMF F_tot", 1000.0, False),
        ("mmf_air_gap", "A", "Air-gap MMF F_delta", 1000.0, False),
        ("leakage_coefficient", None, "Magnet leakage coefficient K_sigma", 1.1, False),
        ("magnet_permeance_pu", None, "Per-unit magnet load permeance lambda_n", 4.0, False),
        ("leakage_permeance_pu", None, "Per-unit leakage permeance lambda_leak,std", 0.35, False),
    )
    _mmf_names = (
        "tooth_pitch",
        "tooth_width",
        "slot_height",
        "pole_arc_coefficient",
        "pole_pitch",
        "length",
        "stator_yoke_height",
        "yoke_path_length",
        "air_gap",
        "carter_coefficient",
        "air_gap_flux_density",
    )
    _deps = {
        "pole_flux": _mmf_names + ("bridge_area",),
        "mmf_total": tuple(n for n in _mmf_names if n != "length"),
        "mmf_air_gap": ("air_gap_flux_density", "carter_coefficient", "air_gap"),
        "leakage_coefficient": _mmf_names + ("bridge_area",),
        "magnet_permeance_pu": _mmf_names + ("bridge_area", "magnet_area"),
        # (K_sigma - 1) lambda_theta,std = 2 (phi_f + phi_s)/F_tot h_m/(mu_r mu_0 A_m): the
        # stack length cancels with the pole flux it scales.
        "leakage_permeance_pu": tuple(n for n in _mmf_names if n != "length")
        + ("bridge_area", "magnet_area"),
    }

    def _evaluate(self, v):
        circuit = magnet_circuit(v["air_gap_flux_density"], v)
        flux = circuit["flux_magnet"]
        leakage = (flux + circuit["flux_bridge"] + circuit["flux_leak"]) / flux
        permeance_std = (
            2.0
            * flux
            / circuit["mmf_total"]
            * mp.MAGNET_THICKNESS
            / (mp.MAGNET_RECOIL_PERMEABILITY * mp.MU_0 * v["magnet_area"])
        )
        return {
            "pole_flux": flux,
            "mmf_total": circuit["mmf_total"],
            "mmf_air_gap": circuit["mmf_air_gap"],
            "leakage_coefficient": leakage,
            "magnet_permeance_pu": leakage * permeance_std,
            "leakage_permeance_pu": (leakage - 1.0) * permeance_std,
        }


# --------------------------------------------------------------------------------------------
# Inductances (docs theory/motor 'Inductances')
# --------------------------------------------------------------------------------------------

_Q_AXIS_INPUTS = (
    ("pole_arc_coefficient", None, "Calculated pole-arc coefficient alpha_i", 0.8, False),
    ("pole_pitch", "m", "Pole pitch tau_p", 0.04, False),
    ("length", "m", "Stack (effective) length l_ef", 0.1, False),
    ("carter_coefficient", None, "Carter coefficient K_theta", 1.07, False),
    ("air_gap", "m", "Air-gap length delta", 6.0e-4, False),
    ("tooth_pitch", "m", "Tooth pitch t_1", 0.014, False),
    ("tooth_width", "m", "Stator tooth width b_t", 7.0e-3, False),
    ("slot_height", "m", "Slot height h_slot", 0.01, False),
    ("stator_yoke_height", "m", "Stator yoke height h_ys", 0.01, False),
    ("yoke_path_length", "m", "Stator yoke MEC path L_j1", 0.025, False),
    ("turns_per_phase", None, "Series turns per phase W", 20.0, False),
    (
        "air_gap_field_coefficient",
        None,
        "Air-gap flux-density waveform coefficient K_f",
        1.2,
        False,
    ),
    ("rated_current", "A", "Rated phase current I_w of the winding", 120.0, False),
)
_Q_AXIS_NAMES = tuple(name for name, *_ in _Q_AXIS_INPUTS)


def q_axis_current(flux_q, v, par):
    """
    Return the q-axis current I_q,tmp that drives the q-axis flux ``flux_q`` (complex-safe).

    See docs theory/motor 'Inductances'.

    I_q,tmp = p (F_sigma,q + F_t1,q + F_j1,q)/(0.9 m K_aq K_dp1 W), K_aq = 0.36/K_f.
    """
    length = v["length"]
    b_q = flux_q / (v["pole_arc_coefficient"] * v["pole_pitch"] * length)
    mmf_gap = 1.6 * b_q * v["carter_coefficient"] * v["air_gap"] / mp.MU_0
    b_tooth = b_q * v["tooth_pitch"] / v["tooth_width"] / mp.LAMINATION_FACTOR
    mmf_tooth = 2.0 * mp.field_strength_from_flux_density(b_tooth) * v["slot_height"]
    b_yoke = flux_q / (2.0 * length * v["stator_yoke_height"])
    mmf_yoke = 2.0 * mp.field_strength_from_flux_density(b_yoke) * v["yoke_path_length"]
    k_aq = mp.Q_AXIS_REACTION_FACTOR / v["air_gap_field_coefficient"]
    return (
        par.pole_pairs
        * (mmf_gap + mmf_tooth + mmf_yoke)
        / (0.9 * par.phases * k_aq * par.winding_factor * v["turns_per_phase"])
    )


class QAxisFluxComp(PointwiseImplicitComp):
    """
    Q-axis flux of the inductance iteration (implicit, docs theory/motor 'Inductances').

    With the rated d-axis current I_d,r = I_w sin(0.6283) and the q-axis current I_q,tmp(phi_aq)
    of :func:`q_axis_current`, the rated current circle closes:

        R = (I_d,r**2 + I_q,tmp**2)/I_w**2 - 1 = sin(0.6283)**2 + (I_q,tmp/I_w)**2 - 1 = 0

    (the reference residual I_d,r**2 + I_q,tmp**2 - I_w**2 divided by I_w**2). I_w is the
    winding's rated current, an input; I_q,tmp is proportional to 1/W, i.e. to I_w, so
    phi_aq does not depend on the winding.
    solve_nonlinear: vectorized bisection on the reference bracket phi_aq in [1e-5, phi] Wb, phi
    the pole flux. linearize: exact complex-step Jacobian (diagonal over the motors); the pole
    flux sets the bracket only and is not a residual input.

    Inputs
    ------
    pole_arc_coefficient, carter_coefficient, air_gap_field_coefficient, turns_per_phase :
    float, (num_motors,), dimensionless
        alpha_i, K_theta, K_f, W.
    pole_pitch, length, air_gap, tooth_pitch, tooth_width, slot_height, stator_yoke_height,
    yoke_path_length : float, (num_motors,), m
        Geometry.
    rated_current : float, (num_motors,), A
        Rated phase current I_w of the winding.
    pole_flux : float, (num_motors,), Wb
        Upper end of the bracket.

    Outputs
    -------
    q_axis_flux : float, (num_motors,), Wb
        Q-axis flux phi_aq at rated current (state).

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    parameters : MotorParameters
        Fixed motor parameters (rated current, pole pairs, phases, winding factor).

    Raises
    ------
    om.AnalysisError
        If the residual does not change sign on [1e-5 Wb, pole_flux].
    """

    _input_vars = _Q_AXIS_INPUTS + (
        ("pole_flux", "Wb", "Flux per pole (upper end of the phi_aq bracket)", 5.0e-3, False),
    )
    _state_var = ("q_axis_flux", "Wb", "Q-axis flux phi_aq at rated current", 2.0e-3, False)
    _deps = _Q_AXIS_NAMES

    def _residual(self, v, flux_q):
        par = self.options["parameters"]
        current = q_axis_current(flux_q, v, par)
        rated = v["rated_current"]
        return np.sin(mp.D_AXIS_CURRENT_ANGLE) ** 2 + (current / rated) ** 2 - 1.0

    def _bracket(self, v):
        return np.full(v["pole_flux"].shape, mp.Q_AXIS_FLUX_LOWER), v["pole_flux"]


class InductanceComp(PointwiseExplicitComp):
    """
    D/q-axis inductances and flux linkage (docs theory/motor 'Inductances'), per motor.

    With f_i = rated_speed p/60 and C_x = 4 pi f_i mu_0 l (K_dp1 W)**2/p:

    - leakage reactance X_1 = X_s1 + X_d1 + X_E1 (slot, differential, end winding), with
      lambda_S1 = h_k/b_sb + 2 h_os/(b_sb + b_s1) + 0.45 and K_st = F_tot/F_delta;
    - d axis: F_ad = 0.35 m K_dp1 W I_d,r/(K_f p); f_a = F_ad/(K_sigma h_m H_c);
      b_mN = lambda_n (1 - f_a)/(lambda_n + 1); phi_N = (b_mN - (1 - b_mN) lambda_leak,std) A_m B_r;
      E_0 = 4.44 f_i K_dp1 W phi K_phi, E_d likewise with phi_N;
      X_ad = abs(E_0 - E_d)/(sqrt(2) I_d,r); L_d = (X_ad + X_1)/(2 pi f_i);
    - q axis: X_aq = (phi_aq E_0/phi)/I_q,tmp(phi_aq); L_q = (X_aq + X_1)/(2 pi f_i);
    - flux linkage Psi_F = W phi.

    B_r and H_c are the magnet values at the magnet temperature (1.1208 T and 847138 A/m at
    75 deg C, the constants lsdo_motor hard-codes here; quirk S3 corrected). I_d,r = I_w
    sin(0.6283) with the winding's rated current I_w (an input, in the inputs of
    QAxisFluxComp): with W proportional to 1/I_w, L_d and L_q scale as W**2 and Psi_F as W.
    Partials: exact vectorized complex step, diagonal over the motors.

    Inputs
    ------
    q_axis_flux, pole_flux : float, (num_motors,), Wb
        phi_aq (QAxisFluxComp) and phi (MagnetFluxComp).
    mmf_total, mmf_air_gap : float, (num_motors,), A
        F_tot, F_delta.
    leakage_coefficient, magnet_permeance_pu, leakage_permeance_pu, air_gap_flux_coefficient,
    (and the dimensionless inputs of QAxisFluxComp) : float, (num_motors,), dimensionless
        K_sigma, lambda_n, lambda_leak,std, K_phi.
    magnet_area : float, (num_motors,), m**2
        A_m.
    slot_bottom_width, slot_inner_width, yoke_pitch, (and the length inputs of QAxisFluxComp) :
    float, (num_motors,), m
        b_sb, b_s1, tau_y.

    Outputs
    -------
    inductance_d, inductance_q : float, (num_motors,), H
        L_d, L_q.
    flux_linkage : float, (num_motors,), Wb
        Permanent-magnet flux linkage Psi_F.

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    parameters : MotorParameters
        Fixed motor parameters.
    """

    _input_vars = _Q_AXIS_INPUTS + (
        ("q_axis_flux", "Wb", "Q-axis flux phi_aq at rated current", 2.0e-3, False),
        ("pole_flux", "Wb", "Flux per pole linking the winding phi", 5.0e-3, False),
        ("mmf_total", "A", "Total no-load MMF F_tot", 1000.0, False),
        ("mmf_air_gap", "A", "Air-gap MMF F_delta", 1000.0, False),
        ("leakage_coefficient", None, "Magnet leakage coefficient K_sigma", 1.1, False),
        ("magnet_permeance_pu", None, "Per-unit magnet load permeance lambda_n", 4.0, False),
        ("leakage_permeance_pu", None, "Per-unit leakage permeance lambda_leak,std", 0.35, False),
        ("magnet_area", "m**2", "Magnet pole-face area A_m", 3.0e-3, False),
        ("air_gap_flux_coefficient", None, "Air-gap flux waveform coefficient K_phi", 1.0, False),
        ("slot_bottom_width", "m", "Slot width at the bore b_sb", 2.0e-3, False),
        ("slot_inner_width", "m", "Radially inner slot width b_s1", 5.0e-3, False),
        ("yoke_pitch", "m", "Yoke pitch tau_y", 0.04, False),
    )
    _output_vars = (
        ("inductance_d", "H", "D-axis inductance L_d", 5.0e-4, False),
        ("inductance_q", "H", "Q-axis inductance L_q", 7.0e-4, False),
        ("flux_linkage", "Wb", "Permanent-magnet flux linkage Psi_F = W phi", 0.1, False),
    )

    _leakage_inputs = (
        "length",
        "turns_per_phase",
        "pole_pitch",
        "air_gap",
        "carter_coefficient",
        "mmf_total",
        "mmf_air_gap",
        "slot_bottom_width",
        "slot_inner_width",
        "yoke_pitch",
    )
    _d_inputs = (
        "rated_current",
        "pole_flux",
        "leakage_coefficient",
        "magnet_permeance_pu",
        "leakage_permeance_pu",
        "magnet_area",
        "air_gap_flux_coefficient",
        "air_gap_field_coefficient",
    )
    _deps = {
        "inductance_d": _leakage_inputs + _d_inputs,
        # I_q,tmp and hence L_q do not depend on I_w (only the q-axis flux solve does).
        "inductance_q": tuple(
            name
            for name in dict.fromkeys(
                _leakage_inputs + _Q_AXIS_NAMES + ("q_axis_flux", "air_gap_flux_coefficient")
            )
            if name != "rated_current"
        ),
        "flux_linkage": ("turns_per_phase", "pole_flux"),
    }

    def _evaluate(self, v):
        par = self.options["parameters"]
        p, m, z, k_w = par.pole_pairs, par.phases, par.num_slots, par.winding_factor
        f_i = par.rated_frequency
        i_dr = v["rated_current"] * np.sin(mp.D_AXIS_CURRENT_ANGLE)
        length, turns, flux = v["length"], v["turns_per_phase"], v["pole_flux"]

        # Leakage reactance X_1.
        c_x = 4.0 * np.pi * f_i * mp.MU_0 * length * (k_w * turns) ** 2 / p
        b_sb = v["slot_bottom_width"]
        slot_permeance = (
            mp.SLOT_LIP_HEIGHT / b_sb
            + 2.0 * mp.SLOT_OPENING_HEIGHT / (b_sb + v["slot_inner_width"])
            + mp.SLOT_LEAKAGE_LOWER
        )
        x_slot = 2.0 * p * m * slot_permeance * c_x / (z * k_w**2)
        saturation = v["mmf_total"] / v["mmf_air_gap"]
        x_diff = (
            m
            * v["pole_pitch"]
            * mp.DIFFERENTIAL_LEAKAGE
            * c_x
            / (v["air_gap"] * v["carter_coefficient"] * saturation * (np.pi * k_w) ** 2)
        )
        x_end = (
            mp.END_WINDING_FACTOR
            * c_x
            * (length + mp.COIL_STRAIGHT_EXTENSION - mp.END_WINDING_PITCH_FACTOR * v["yoke_pitch"])
            / (length * k_w**2)
        )
        x_leak = x_slot + x_diff + x_end

        # D axis: demagnetized operating point of the magnet under the rated d-axis current.
        emf_factor = 4.44 * f_i * k_w * turns * v["air_gap_flux_coefficient"]
        mmf_ad = (
            mp.D_AXIS_REACTION_FACTOR
            * m
            * k_w
            * turns
            * i_dr
            / (v["air_gap_field_coefficient"] * p)
        )
        demag = mmf_ad / (v["leakage_coefficient"] * mp.MAGNET_THICKNESS * par.coercivity)
        lam_n = v["magnet_permeance_pu"]
        b_mn = lam_n * (1.0 - demag) / (lam_n + 1.0)
        flux_n = (
            (b_mn - (1.0 - b_mn) * v["leakage_permeance_pu"]) * v["magnet_area"] * (par.remanence)
        )
        emf_0 = emf_factor * flux
        emf_d = emf_factor * flux_n
        x_ad = _complex_safe_abs(emf_0 - emf_d) / (i_dr * np.sqrt(2.0))

        # Q axis: X_aq = (phi_aq E_0/phi)/I_q,tmp, with E_0/phi = emf_factor cancelled exactly.
        x_aq = v["q_axis_flux"] * emf_factor / q_axis_current(v["q_axis_flux"], v, par)

        omega_i = 2.0 * np.pi * f_i
        return {
            "inductance_d": (x_ad + x_leak) / omega_i,
            "inductance_q": (x_aq + x_leak) / omega_i,
            "flux_linkage": turns * flux,
        }
