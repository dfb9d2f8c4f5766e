"""PMSM losses, efficiency, EM-torque residual (paper eq. 24) and torque/voltage margins."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.motor import parameters as mp
from lpc_mdo.components.motor._numerics import (
    CS_STEP,
    check_saliency,
    declare_pointwise_partials,
    pointwise_values,
)
from lpc_mdo.components.motor._pointwise import PointwiseImplicitComp, _declare_common_options
from lpc_mdo.components.motor.mtpa import mtpa_base, mtpa_current_pu
from lpc_mdo.core.checks import check_range
from lpc_mdo.core.constants import RPM_TO_RAD_S
from lpc_mdo.core.numerics import safeguarded_newton

_WINDAGE_COEFFICIENT = (
    mp.ROTOR_ROUGHNESS * np.pi * mp.ROTOR_FRICTION * mp.WINDAGE_AIR_DENSITY * (2.0 * np.pi) ** 2
)  # P_w = C f**2 l D_2**4
_RPM_TO_RAD_S = RPM_TO_RAD_S


def _combine(*terms):
    """Sum of coef * gradient dicts: terms are (coef, {name: array})."""
    total = {}
    for coef, grad in terms:
        for name, value in grad.items():
            total[name] = total.get(name, 0.0) + coef * value
    return total


# Per-motor inputs of the loss model: (name, units, desc, default).
#: Sharpness k of the smooth min(T_pk, T_lim) in MotorMarginComp (its largest gap ln(2)/k = 0.0069
#: of T_pk, at T_lim = T_pk).
SMOOTH_MIN_SHARPNESS = 100.0

MOTOR_INPUTS = (
    ("resistance", "ohm", "Phase resistance R", 0.02),
    ("inductance_d", "H", "D-axis inductance L_d", 7.5e-4),
    ("inductance_q", "H", "Q-axis inductance L_q", 1.0e-3),
    ("flux_linkage", "Wb", "Permanent-magnet flux linkage Psi_F", 0.3),
    ("air_gap_flux_density", "T", "No-load air-gap flux density B_delta", 0.75),
    ("iron_volume", "m**3", "Iron volume of the core losses V_s + V_s1", 1.0e-3),
    ("magnet_volume", "m**3", "Magnet volume of the magnet eddy loss V_t", 1.0e-4),
    ("length", "m", "Stack length l", 0.1),
    ("rotor_diameter", "m", "Rotor diameter D_2", 0.16),
)
MOTOR_NAMES = tuple(name for name, *_ in MOTOR_INPUTS)


def loss_model(v, par, with_partials=False):
    """
    Compute the currents, MTPA voltage, losses, powers and efficiency (complex-safe, pointwise).

    The model is that of docs theory/motor 'Losses and efficiency'.

    Parameters
    ----------
    v : dict
        'rotor_torque', 'rotor_rpm', 'em_torque', 'current_q' of shape (num_motors, num_nodes)
        and the MOTOR_NAMES of shape (num_motors,), SI units (rpm for the speed).
    par : MotorParameters
        Pole pairs, phases, gear ratio.
    with_partials : bool
        Also return the analytic gradients {output: {input: array}}.

    Returns
    -------
    dict or (dict, dict)
        Output name -> array (num_motors, num_nodes), and the gradients if requested.
    """
    p, m, gear = par.pole_pairs, par.phases, par.gear_ratio
    motor = {name: v[name][:, np.newaxis] for name in MOTOR_NAMES}
    r, l_d, l_q, psi = (
        motor["resistance"],
        motor["inductance_d"],
        motor["inductance_q"],
        motor["flux_linkage"],
    )
    b_gap, v_fe, v_mag = (
        motor["air_gap_flux_density"],
        motor["iron_volume"],
        motor["magnet_volume"],
    )
    length, d_2 = motor["length"], motor["rotor_diameter"]
    torque_r, rpm, torque, i_q = v["rotor_torque"], v["rotor_rpm"], v["em_torque"], v["current_q"]

    c_omega = gear * _RPM_TO_RAD_S * p  # omega = c_omega rpm (electrical, rad/s)
    c_freq = c_omega * p / 60.0  # f = c_freq rpm (as coded)
    omega, freq = c_omega * rpm, c_freq * rpm
    k_t = 1.5 * p
    saliency = l_d - l_q

    i_d = (torque / (k_t * i_q) - psi) / saliency
    current = np.sqrt(i_q**2 + i_d**2)
    u_d = r * i_d - omega * l_q * i_q
    u_q = omega * l_d * i_d + r * i_q + omega * psi
    voltage = np.sqrt(u_d**2 + u_q**2)

    p_out = _RPM_TO_RAD_S * torque_r * rpm
    p_cu = m * r * current**2
    k_e, k_h = mp.EDDY_COEFFICIENT, mp.HYSTERESIS_COEFFICIENT
    p_fe = k_e * (v_fe + v_mag) * (b_gap * freq) ** 2 + k_h * v_fe * freq * b_gap**2
    p_w = _WINDAGE_COEFFICIENT * freq**2 * length * d_2**4
    p_loss = p_cu + p_fe + p_w + mp.STRAY_LOSS_FRACTION * p_out + mp.MECHANICAL_LOSS
    p_in = p_out + p_loss
    values = {
        "current_d": i_d,
        "current": current,
        "voltage": voltage,
        "copper_loss": p_cu,
        "iron_loss": p_fe,
        "windage_loss": p_w,
        "power_loss": p_loss,
        "output_power": p_out,
        "input_power": p_in,
        "efficiency": p_out / p_in,
    }
    if not with_partials:
        return values

    eta = values["efficiency"]
    d_id = {
        "em_torque": 1.0 / (k_t * i_q * saliency),
        "current_q": -torque / (k_t * i_q**2 * saliency),
        "flux_linkage": -1.0 / saliency,
        "inductance_d": -i_d / saliency,
        "inductance_q": i_d / saliency,
    }
    d_current = _combine((i_d / current, d_id), (i_q / current, {"current_q": 1.0}))
    d_ud = _combine(
        (r, d_id),
        (
            1.0,
            {
                "resistance": i_d,
                "inductance_q": -omega * i_q,
                "current_q": -omega * l_q,
                "rotor_rpm": -c_omega * l_q * i_q,
            },
        ),
    )
    d_uq = _combine(
        (omega * l_d, d_id),
        (
            1.0,
            {
                "inductance_d": omega * i_d,
                "resistance": i_q,
                "current_q": r,
                "flux_linkage": omega,
                "rotor_rpm": c_omega * (l_d * i_d + psi),
            },
        ),
    )
    d_voltage = _combine((u_d / voltage, d_ud), (u_q / voltage, d_uq))
    d_cu = _combine((2.0 * m * r * current, d_current), (1.0, {"resistance": m * current**2}))
    d_fe = {
        "iron_volume": k_e * (b_gap * freq) ** 2 + k_h * freq * b_gap**2,
        "magnet_volume": k_e * (b_gap * freq) ** 2,
        "air_gap_flux_density": (
            2.0 * k_e * (v_fe + v_mag) * b_gap * freq**2 + 2.0 * k_h * v_fe * freq * b_gap
        ),
        "rotor_rpm": (2.0 * k_e * (v_fe + v_mag) * b_gap**2 * freq + k_h * v_fe * b_gap**2)
        * c_freq,
    }
    d_w = {
        "rotor_rpm": 2.0 * _WINDAGE_COEFFICIENT * freq * length * d_2**4 * c_freq,
        "length": _WINDAGE_COEFFICIENT * freq**2 * d_2**4,
        "rotor_diameter": 4.0 * _WINDAGE_COEFFICIENT * freq**2 * length * d_2**3,
    }
    d_out = {"rotor_torque": _RPM_TO_RAD_S * rpm, "rotor_rpm": _RPM_TO_RAD_S * torque_r}
    d_loss = _combine((1.0, d_cu), (1.0, d_fe), (1.0, d_w), (mp.STRAY_LOSS_FRACTION, d_out))
    d_in = _combine((1.0, d_out), (1.0, d_loss))
    d_eta = _combine((1.0 / p_in, d_out), (-eta / p_in, d_in))
    grads = {
        "current_d": d_id,
        "current": d_current,
        "voltage": d_voltage,
        "copper_loss": d_cu,
        "iron_loss": d_fe,
        "windage_loss": d_w,
        "power_loss": d_loss,
        "output_power": d_out,
        "input_power": d_in,
        "efficiency": d_eta,
    }
    return values, grads


class MotorLossComp(om.ExplicitComponent):
    """
    PMSM currents, terminal voltage, losses, input power and efficiency.

    See docs theory/motor 'Losses and efficiency' and paper eq. 24.

    With the MTPA q-axis current I_q (MTPAComp), the electrical speed omega = rpm G 2 pi/60 p,
    the load torque T_L = Q_r/G (G the gear ratio) and, as coded, f = omega p/60:

    - I_d = (T_em/(1.5 p I_q) - Psi_F)/(L_d - L_q); abs(I) = sqrt(I_q**2 + I_d**2);
    - U_d = R I_d - omega L_q I_q, U_q = omega L_d I_d + R I_q + omega Psi_F,
      abs(U) = sqrt(U_d**2 + U_q**2) (MTPA terminal voltage amplitude, no flux weakening);
    - P_0 = T_L omega/p = Q_r rpm 2 pi/60 (shaft output power);
    - copper P_cu = m R abs(I)**2;
    - iron: eddy K_e (V_s + V_s1)(B_delta f)**2 + magnet eddy K_e V_t (B_delta f)**2 +
      hysteresis K_h (V_s + V_s1) f B_delta**2, K_e = (a_l pi)**2 sigma_c/60;
    - windage P_w = k_r pi f_r rho_air (2 pi f)**2 l D_2**4; stray 0.01 P_0; mechanical 100 W;
    - P_in = P_0 + losses; efficiency eta = P_0/P_in.

    The as-coded omega and f are kept as the reference document requires (the numbers of docs
    theory/motor 'Validation' depend on them). Partials are analytic and pointwise: diagonal over
    (motor, node),
    per-motor inputs broadcast over the nodes.

    Inputs
    ------
    rotor_torque : float, (num_motors, num_nodes), N*m
        Required rotor (shaft after the gearbox) torque Q_r; must be > 0.
    rotor_rpm : float, (num_motors, num_nodes), rpm
        Rotor speed; must be > 0.
    em_torque : float, (num_motors, num_nodes), N*m
        Electromagnetic torque T_em (EMTorqueComp); must be > 0.
    current_q : float, (num_motors, num_nodes), A
        MTPA q-axis current (MTPAComp); must be > 0.
    resistance : float, (num_motors,), ohm
        Phase resistance R.
    inductance_d, inductance_q : float, (num_motors,), H
        L_d, L_q.
    flux_linkage : float, (num_motors,), Wb
        Psi_F.
    air_gap_flux_density : float, (num_motors,), T
        B_delta.
    iron_volume, magnet_volume : float, (num_motors,), m**3
        V_s + V_s1 and V_t.
    length, rotor_diameter : float, (num_motors,), m
        l and D_2 of the windage loss.

    Outputs
    -------
    current_d, current : float, (num_motors, num_nodes), A
        D-axis current and current amplitude abs(I).
    voltage : float, (num_motors, num_nodes), V
        MTPA terminal voltage amplitude abs(U).
    copper_loss, iron_loss, windage_loss, power_loss : float, (num_motors, num_nodes), W
        Copper, iron (eddy + magnet eddy + hysteresis), windage and total losses (the total
        also holds the stray and mechanical losses).
    output_power, input_power : float, (num_motors, num_nodes), W
        P_0 and P_in.
    efficiency : float, (num_motors, num_nodes), dimensionless
        eta = P_0/P_in.

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    num_nodes : int
        Operating points per motor (>= 1). Default 1.
    parameters : MotorParameters
        Pole pairs, phases, gear ratio.

    Raises
    ------
    om.AnalysisError
        If rotor_torque, rotor_rpm, em_torque or current_q is not > 0.
    """

    _node_inputs = (
        ("rotor_torque", "N*m", "Required rotor torque Q_r", 500.0),
        ("rotor_rpm", "rpm", "Rotor speed", 1000.0),
        ("em_torque", "N*m", "Electromagnetic torque T_em", 130.0),
        ("current_q", "A", "MTPA q-axis current I_q", 50.0),
    )
    _output_vars = (
        ("current_d", "A", "D-axis current I_d (MTPA)", -10.0),
        ("current", "A", "Current amplitude |I| = sqrt(I_d**2 + I_q**2)", 50.0),
        ("voltage", "V", "MTPA terminal voltage amplitude |U| (no flux weakening)", 300.0),
        ("copper_loss", "W", "Copper loss m R |I|**2", 100.0),
        ("iron_loss", "W", "Iron loss: stator/rotor eddy + magnet eddy + hysteresis", 100.0),
        ("windage_loss", "W", "Windage and friction loss", 10.0),
        ("power_loss", "W", "Total loss (copper, iron, windage, stray, mechanical)", 500.0),
        ("output_power", "W", "Shaft output power P_0 = Q_r omega_rotor", 5.0e4),
        ("input_power", "W", "Electrical input power P_in = P_0 + losses", 5.0e4),
        ("efficiency", None, "Motor efficiency P_0/P_in", 0.95),
    )
    _current = ("em_torque", "current_q", "flux_linkage", "inductance_d", "inductance_q")
    _iron = ("iron_volume", "magnet_volume", "air_gap_flux_density", "rotor_rpm")
    _windage = ("rotor_rpm", "length", "rotor_diameter")
    _loss = tuple(dict.fromkeys(_current + ("resistance",) + _iron + _windage + ("rotor_torque",)))
    _deps = {
        "current_d": _current,
        "current": _current,
        "voltage": _current + ("resistance", "rotor_rpm"),
        "copper_loss": _current + ("resistance",),
        "iron_loss": _iron,
        "windage_loss": _windage,
        "power_loss": _loss,
        "output_power": ("rotor_torque", "rotor_rpm"),
        "input_power": _loss,
        "efficiency": _loss,
    }

    def initialize(self):
        _declare_common_options(self, per_node=True)

    def setup(self):
        nm, nn = self.options["num_motors"], self.options["num_nodes"]
        self._shapes = {}
        for name, units, desc, default in self._node_inputs:
            self._shapes[name] = (nm, nn)
            self.add_input(name, val=default * np.ones((nm, nn)), units=units, desc=desc)
        for name, units, desc, default in MOTOR_INPUTS:
            self._shapes[name] = (nm,)
            self.add_input(name, val=default * np.ones(nm), units=units, desc=desc)
        for name, units, desc, default in self._output_vars:
            self._shapes[name] = (nm, nn)
            self.add_output(name, val=default * np.ones((nm, nn)), units=units, desc=desc)
        declare_pointwise_partials(self, self._deps, self._shapes)

    def _values(self, inputs):
        names = [name for name, *_ in self._node_inputs] + list(MOTOR_NAMES)
        return {name: inputs[name] for name in names}

    def compute(self, inputs, outputs):
        for name, units, _, _ in self._node_inputs:
            check_range(
                name,
                inputs[name],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        for name, value in loss_model(self._values(inputs), self.options["parameters"]).items():
            outputs[name] = value

    def compute_partials(self, inputs, partials):
        _, grads = loss_model(self._values(inputs), self.options["parameters"], with_partials=True)
        for of, wrts in self._deps.items():
            for wrt in wrts:
                partials[of, wrt] = pointwise_values(grads[of][wrt], self._shapes[of])


class EMTorqueComp(PointwiseImplicitComp):
    """
    Electromagnetic torque from the efficiency residual (implicit).

    See paper eq. 24 and docs theory/motor 'Losses and efficiency':

        R = eta(T_em) T_em - T_L = 0,  T_L = rotor_torque/gear_ratio,

    where eta(T_em) is the loss model of MotorLossComp evaluated at the MTPA current of T_em
    (paper eq. 26, :func:`mtpa_current_pu`), so the residual closes over the whole operating
    point and no solver loop is needed outside the component.

    solve_nonlinear (vectorized over all motors and nodes): the equivalent form
    h(T) = omega_m (T - T_L) - P_loss(T) = T_L-scaled R (same sign, omega_m the motor shaft
    speed) is solved by Newton's method (paper Table 1) started at T = T_L, where h < 0 (or at
    the previous solution when it is above T_L, falling back to T_L if that fails). For a
    loss convex in the torque, h is concave and the iterates increase monotonically to the
    smaller (physical) root; any step that overshoots creates a sign-change bracket and the
    iteration continues safeguarded (bisection fallback). h < 0 with dh/dT <= 0 means the torque
    exceeds the stall maximum of eta T_em: om.AnalysisError. dh/dT comes from a complex step.

    linearize: exact vectorized complex step of R (pointwise; the MTPA root is
    complex-step safe).

    Inputs
    ------
    rotor_torque : float, (num_motors, num_nodes), N*m
        Required rotor torque Q_r; must be > 0.
    rotor_rpm : float, (num_motors, num_nodes), rpm
        Rotor speed; must be > 0.
    resistance, inductance_d, inductance_q, flux_linkage, air_gap_flux_density, iron_volume,
    magnet_volume, length, rotor_diameter : float, (num_motors,)
        As in MotorLossComp (ohm, H, H, Wb, T, m**3, m**3, m, m).

    Outputs
    -------
    em_torque : float, (num_motors, num_nodes), N*m
        Electromagnetic torque T_em (state).

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    num_nodes : int
        Operating points per motor (>= 1). Default 1.
    parameters : MotorParameters
        Pole pairs, phases, gear ratio.

    Raises
    ------
    om.AnalysisError
        If rotor_torque or rotor_rpm is not > 0, L_q <= L_d, or no EM torque balances the load
        (the load exceeds the stall maximum of eta T_em).
    """

    _input_vars = (
        ("rotor_torque", "N*m", "Required rotor torque Q_r", 500.0, True),
        ("rotor_rpm", "rpm", "Rotor speed", 1000.0, True),
    ) + tuple((name, units, desc, default, False) for name, units, desc, default in MOTOR_INPUTS)
    _state_var = ("em_torque", "N*m", "Electromagnetic torque T_em", 130.0, True)
    _deps = ("rotor_torque", "rotor_rpm") + MOTOR_NAMES
    _per_node = True
    _maxiter = 100

    def _check_values(self, values):
        check_range(
            "rotor_torque",
            values["rotor_torque"],
            lower=0.0,
            lower_open=True,
            units="N*m",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        check_range(
            "rotor_rpm",
            values["rotor_rpm"],
            lower=0.0,
            lower_open=True,
            units="rpm",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        check_saliency(
            self.msginfo,
            values["inductance_d"],
            values["inductance_q"],
            lambda idx: (
                f" (length {values['length'].real[idx].tolist()} m) is outside the "
                "allowed range (0, inf): the MTPA current needs L_q > L_d, which the "
                "equivalent circuit gives only above a minimum length (about 0.056 m "
                "at L/D = 0.5 with the default parameters)."
            ),
        )

    def _operating_point(self, v, torque):
        """Loss-model outputs at EM torque ``torque`` with the MTPA q-axis current."""
        par = self.options["parameters"]
        i_base, t_base = mtpa_base(
            v["flux_linkage"][:, np.newaxis],
            v["inductance_d"][:, np.newaxis],
            v["inductance_q"][:, np.newaxis],
            par.pole_pairs,
        )
        current_q = mtpa_current_pu(torque / t_base, owner=self.msginfo) * i_base
        return loss_model(dict(v, em_torque=torque, current_q=current_q), par)

    def _residual(self, v, torque):
        load = v["rotor_torque"] / self.options["parameters"].gear_ratio
        return self._operating_point(v, torque)["efficiency"] * torque - load

    def _solve(self, v):
        guess = self._guess
        if guess is not None:
            # Warm start from the previous solution: on the rising side of the concave h, so
            # Newton reaches the same (smaller) root from either side; if it fails, start cold.
            try:
                return self._solve_from(v, guess)
            except om.AnalysisError:
                pass
        return self._solve_from(v, None)

    def _solve_from(self, v, guess):
        par = self.options["parameters"]
        load = v["rotor_torque"] / par.gear_ratio
        shaft_speed = v["rotor_rpm"] * par.gear_ratio * _RPM_TO_RAD_S  # motor omega_m, rad/s

        def balance(torque):
            """Return h = omega_m (T - T_L) - P_loss and dh/dT (complex step)."""
            loss = self._operating_point(v, torque + 1j * CS_STEP)["power_loss"]
            value = shaft_speed * (torque - load) - loss.real
            return value, shaft_speed - loss.imag / CS_STEP

        torque = load.copy() if guess is None else np.where(guess > load, guess, load)
        lower = load.copy()
        upper = np.full_like(load, np.inf)
        for _ in range(self._maxiter):
            value, slope = balance(torque)
            if not np.all(np.isfinite(value)):
                i = tuple(int(k) for k in np.argwhere(~np.isfinite(value))[0])
                raise om.AnalysisError(
                    f"{self.msginfo}: the em_torque residual is not finite at "
                    f"{torque[i]:.6g} N*m (index {list(i)})."
                )
            above = value > 0.0
            upper = np.where(above, np.minimum(upper, torque), upper)
            lower = np.where(above, lower, torque)
            stall = (value < 0.0) & ~(slope > 0.0) & ~np.isfinite(upper)
            if np.any(stall):
                i = tuple(int(k) for k in np.argwhere(stall)[0])
                raise om.AnalysisError(
                    f"{self.msginfo}: no electromagnetic torque balances rotor_torque = "
                    f"{v['rotor_torque'][i]:.6g} N*m at rotor_rpm = {v['rotor_rpm'][i]:.6g} rpm "
                    f"(index {list(i)}): the losses grow faster than the torque (stall). The "
                    "allowed range is below the maximum of efficiency * em_torque; use a longer "
                    "motor or a smaller load."
                )
            with np.errstate(divide="ignore", invalid="ignore"):
                step_to = torque - value / slope
            bracketed = np.isfinite(upper)
            outside = ~np.isfinite(step_to) | (step_to < lower) | (bracketed & (step_to > upper))
            new = np.where(
                outside, np.where(bracketed, 0.5 * (lower + upper), 2.0 * torque), step_to
            )
            new = np.where(value == 0.0, torque, new)
            done = np.abs(new - torque) <= 4.0 * np.finfo(float).eps * np.abs(new)
            torque = new
            if np.all(done):
                return torque
        if np.all(np.isfinite(upper)):
            # Slow convergence: finish on the brackets.
            return safeguarded_newton(
                balance, lower, upper, where=self.msginfo, variable="em_torque", units="N*m"
            )
        raise om.AnalysisError(
            f"{self.msginfo}: the em_torque Newton iteration did not "
            f"converge in {self._maxiter} iterations."
        )


def smooth_min_ratio(ratio, sharpness):
    """
    Return the smooth minimum s(x) of 1 and x and its derivative ds/dx (complex-safe).

    s(x) = -ln(exp(-k) + exp(-k x))/k, the log-sum-exp (KS) minimum of 1 and x with sharpness
    k: min(1, x) - ln(2)/k <= s(x) <= min(1, x), the gap ln(2)/k at x = 1 and vanishing away
    from it (below 1e-4 for abs(x - 1) > 7/k). Evaluated in the overflow-free form
    min(1, x) - ln(1 + exp(-k abs(x - 1)))/k, with abs taken on the real part (smooth: the two
    branches are one analytic function). ds/dx = 1/(1 + exp(k (x - 1))).
    """
    gap = ratio - 1.0
    sign = np.where(np.real(gap) >= 0.0, 1.0, -1.0)
    low = np.where(np.real(gap) >= 0.0, 1.0 + 0.0 * ratio, ratio)
    value = low - np.log1p(np.exp(-sharpness * sign * gap)) / sharpness
    slope = 0.5 * (1.0 - np.tanh(0.5 * sharpness * gap))
    return value, slope


class MotorMarginComp(om.ExplicitComponent):
    """
    Torque, current and voltage margins of each operating point.

    See docs theory/motor 'Torque margin' and 'Winding for the bus'.

    - available torque T_max = smooth min(T_pk, T_lim) = T_pk s(T_lim/T_pk) with s of
      :func:`smooth_min_ratio` (sharpness option ``smooth_min_sharpness`` k = 100: T_max is at
      most 0.7 % of T_pk below the exact minimum, never above it): the motor's torque is limited
      by its current (the peak torque T_pk of the sizing fit) and, at the operating speed, by
      the voltage (T_lim, docs theory/motor 'Voltage-limited torque'). Without
      ``include_torque_limit`` T_max = T_pk (the paper);
    - torque_margin = T_max/T_em - 1 (paper: available/required - 1, constrained >= 0.10; the
      full problem aggregates the margin over a motor's conditions with KS);
    - current_margin = 1 - abs(I)/I_pk: the phase current against the current at the peak
      torque, which the inverter and cables are rated for (a report: the torque margin keeps it
      positive, since the MTPA current grows with the torque);
    - voltage_margin = 1 - abs(U)/V_lim (>= 0 when the MTPA point respects the voltage limit:
      the range where the MTPA model without flux weakening holds);
    - voltage_torque_margin = T_lim/T_em - 1 (only with ``include_torque_limit``);
    - beyond_voltage_limit = 1.0 where abs(U) > V_lim, else 0.0: flux weakening (out of scope, as
      in the paper) would be needed there. A report, not differentiable (no partials); constrain
      voltage_margin instead.

    Partials: analytic, pointwise.

    Inputs
    ------
    em_torque : float, (num_motors, num_nodes), N*m
        T_em.
    voltage : float, (num_motors, num_nodes), V
        MTPA terminal voltage amplitude.
    current : float, (num_motors, num_nodes), A
        Phase-current amplitude abs(I).
    peak_torque : float, (num_motors,), N*m
        Peak (current-limited) motor torque T_pk.
    peak_current : float, (num_motors,), A
        Phase-current amplitude at the peak torque I_pk (PeakCurrentComp).
    torque_limit : float, (num_motors, num_nodes), N*m
        Voltage-limited torque T_lim (only with ``include_torque_limit``).

    Outputs
    -------
    available_torque : float, (num_motors, num_nodes), N*m
        T_max.
    torque_margin, current_margin, voltage_margin : float, (num_motors, num_nodes),
    dimensionless
        See above.
    voltage_torque_margin : float, (num_motors, num_nodes), dimensionless
        See above (only with ``include_torque_limit``).
    beyond_voltage_limit : float, (num_motors, num_nodes), dimensionless
        1.0 where the MTPA voltage exceeds V_lim, else 0.0.

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    num_nodes : int
        Operating points per motor (>= 1). Default 1.
    parameters : MotorParameters
        Voltage limit.
    include_torque_limit : bool
        Add the torque_limit input, the voltage-limited torque in T_max and the
        voltage_torque_margin output. Default True.
    smooth_min_sharpness : float
        k of the smooth minimum (> 0). Default 100.
    """

    def initialize(self):
        _declare_common_options(self, per_node=True)
        self.options.declare(
            "include_torque_limit",
            default=True,
            types=bool,
            desc="Add torque_limit, the voltage limit in T_max and voltage_torque_margin",
        )
        self.options.declare(
            "smooth_min_sharpness",
            default=SMOOTH_MIN_SHARPNESS,
            types=(int, float),
            lower=1e-9,
            desc="Sharpness k of the smooth min(T_pk, T_lim) (> 0)",
        )

    def setup(self):
        nm, nn = self.options["num_motors"], self.options["num_nodes"]
        with_limit = self.options["include_torque_limit"]
        self.add_input(
            "em_torque",
            val=130.0 * np.ones((nm, nn)),
            units="N*m",
            desc="Electromagnetic torque T_em",
        )
        self.add_input(
            "voltage",
            val=300.0 * np.ones((nm, nn)),
            units="V",
            desc="MTPA terminal voltage amplitude |U|",
        )
        self.add_input(
            "current", val=50.0 * np.ones((nm, nn)), units="A", desc="Phase-current amplitude |I|"
        )
        self.add_input(
            "peak_torque",
            val=200.0 * np.ones(nm),
            units="N*m",
            desc="Peak (current-limited) motor torque T_pk",
        )
        self.add_input(
            "peak_current",
            val=300.0 * np.ones(nm),
            units="A",
            desc="Phase-current amplitude at the peak torque I_pk",
        )
        if with_limit:
            self.add_input(
                "torque_limit",
                val=400.0 * np.ones((nm, nn)),
                units="N*m",
                desc="Voltage-limited EM torque T_lim",
            )
        self.add_output(
            "available_torque",
            val=np.ones((nm, nn)),
            units="N*m",
            desc="Available torque T_max = smooth min(T_pk, T_lim)",
        )
        self.add_output(
            "torque_margin",
            val=np.zeros((nm, nn)),
            units=None,
            desc="Torque margin T_max/T_em - 1 (constrained >= 0.10 in the paper)",
        )
        self.add_output(
            "current_margin",
            val=np.zeros((nm, nn)),
            units=None,
            desc="Current margin 1 - |I|/I_pk",
        )
        self.add_output(
            "voltage_margin",
            val=np.zeros((nm, nn)),
            units=None,
            desc="Voltage margin 1 - |U|/V_lim of the MTPA point",
        )
        if with_limit:
            self.add_output(
                "voltage_torque_margin",
                val=np.zeros((nm, nn)),
                units=None,
                desc="Margin to the voltage-limited torque T_lim/T_em - 1",
            )
        self.add_output(
            "beyond_voltage_limit",
            val=np.zeros((nm, nn)),
            units=None,
            desc="1.0 where the MTPA voltage exceeds V_lim (flux weakening would "
            "be needed), else 0.0; not differentiable",
        )

        rows = np.arange(nm * nn)
        per_motor = np.repeat(np.arange(nm), nn)
        v_lim = self.options["parameters"].voltage_limit
        self.declare_partials("available_torque", "peak_torque", rows=rows, cols=per_motor)
        self.declare_partials("torque_margin", "em_torque", rows=rows, cols=rows)
        self.declare_partials("torque_margin", "peak_torque", rows=rows, cols=per_motor)
        self.declare_partials("current_margin", "current", rows=rows, cols=rows)
        self.declare_partials("current_margin", "peak_current", rows=rows, cols=per_motor)
        self.declare_partials(
            "voltage_margin", "voltage", rows=rows, cols=rows, val=np.full(nm * nn, -1.0 / v_lim)
        )
        if with_limit:
            for of in ("available_torque", "torque_margin"):
                self.declare_partials(of, "torque_limit", rows=rows, cols=rows)
            self.declare_partials(
                "voltage_torque_margin", ["em_torque", "torque_limit"], rows=rows, cols=rows
            )

    def _available(self, inputs):
        """Return T_max and its derivatives by T_pk and T_lim (None without the limit)."""
        peak = inputs["peak_torque"][:, np.newaxis] + 0.0 * inputs["em_torque"]
        if not self.options["include_torque_limit"]:
            return peak, np.ones_like(peak), None
        ratio = inputs["torque_limit"] / peak
        value, slope = smooth_min_ratio(ratio, self.options["smooth_min_sharpness"])
        # T_max = T_pk s(T_lim/T_pk).
        return peak * value, value - ratio * slope, slope

    def compute(self, inputs, outputs):
        for name, units in (("em_torque", "N*m"), ("peak_current", "A"), ("peak_torque", "N*m")):
            check_range(
                name,
                inputs[name],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        v_lim = self.options["parameters"].voltage_limit
        torque = inputs["em_torque"]
        available, _, _ = self._available(inputs)
        outputs["available_torque"] = available
        outputs["torque_margin"] = available / torque - 1.0
        outputs["current_margin"] = 1.0 - inputs["current"] / inputs["peak_current"][:, np.newaxis]
        outputs["voltage_margin"] = 1.0 - inputs["voltage"] / v_lim
        if self.options["include_torque_limit"]:
            outputs["voltage_torque_margin"] = inputs["torque_limit"] / torque - 1.0
        outputs["beyond_voltage_limit"] = (inputs["voltage"].real > v_lim).astype(float)

    def compute_partials(self, inputs, partials):
        torque = inputs["em_torque"]
        available, d_peak, d_limit = self._available(inputs)
        partials["available_torque", "peak_torque"] = d_peak.ravel()
        partials["torque_margin", "em_torque"] = (-available / torque**2).ravel()
        partials["torque_margin", "peak_torque"] = (d_peak / torque).ravel()
        peak_current = inputs["peak_current"][:, np.newaxis]
        partials["current_margin", "current"] = np.broadcast_to(
            -1.0 / peak_current, torque.shape
        ).ravel()
        partials["current_margin", "peak_current"] = (inputs["current"] / peak_current**2).ravel()
        if self.options["include_torque_limit"]:
            partials["available_torque", "torque_limit"] = d_limit.ravel()
            partials["torque_margin", "torque_limit"] = (d_limit / torque).ravel()
            partials["voltage_torque_margin", "em_torque"] = (
                -inputs["torque_limit"] / torque**2
            ).ravel()
            partials["voltage_torque_margin", "torque_limit"] = (1.0 / torque).ravel()
