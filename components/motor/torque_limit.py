"""Voltage-limited torque of the PMSM at each operating speed (quartic, zero discriminant)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.motor._pointwise import PointwiseImplicitComp
from lpc_mdo.core.checks import check_range

_MAX_DOUBLINGS = 200


def _quartic(v, par):
    """
    Return the monic voltage-limit torque quartic in x = T/T_s, T_s = 1.5 p Psi_F I_w.

    See docs theory/motor 'Voltage-limited torque'.

    Returns (torque_scale, b, c, d, e) with P(x) = x**4 + b x**3 + c x**2 + d x + e, i.e. the
    reference quartic A T**4 + B T**3 + C T**2 + D T + E divided by A T_s**4 (A > 0 always).
    Complex-safe.
    """
    p = par.pole_pairs
    r, l_d, l_q, psi = v["resistance"], v["inductance_d"], v["inductance_q"], v["flux_linkage"]
    r, l_d, l_q, psi = (x[:, np.newaxis] for x in (r, l_d, l_q, psi))
    omega = v["rotor_rpm"] * par.gear_ratio * 2.0 * np.pi / 60.0 * p  # electrical, rad/s
    v_lim = par.voltage_limit

    den = 3.0 * p * (l_d - l_q)
    a = den**2 * ((omega * l_q) ** 2 + r**2)
    c_1 = 12.0 * p * omega * r * (l_d - l_q) ** 2
    c_2 = (3.0 * p * psi) ** 2 * (r**2 + (omega * l_q) ** 2) - (v_lim * den) ** 2
    d = -12.0 * p * psi * (omega**2 * l_d * l_q + r**2)
    e = 4.0 * ((omega * l_d) ** 2 + r**2)

    coef_a = 256 * a**2 * e**3 - 128 * a * e**2 * c_1**2 + 16 * e * c_1**4
    coef_b = (
        -256 * a * e**2 * c_1 * c_2
        + 144 * a * d**2 * e * c_1
        + 64 * e * c_1**3 * c_2
        - 4 * d**2 * c_1**3
    )
    coef_c = (
        -128 * a * e**2 * c_2**2
        + 144 * a * d**2 * e * c_2
        - 27 * a * d**4
        + 96 * c_1**2 * c_2**2 * e
        - 12 * d**2 * c_1**2 * c_2
    )
    coef_d = 64 * e * c_1 * c_2**3 - 12 * d**2 * c_1 * c_2**2
    coef_e = 16 * e * c_2**4 - 4 * d**2 * c_2**3

    scale = 1.5 * p * psi * par.rated_current + 0.0 * omega
    return (
        scale,
        coef_b / (coef_a * scale),
        coef_c / (coef_a * scale**2),
        coef_d / (coef_a * scale**3),
        coef_e / (coef_a * scale**4),
    )


class TorqueLimitComp(PointwiseImplicitComp):
    """
    Voltage-limited EM torque T_lim at each operating speed (implicit).

    See docs theory/motor 'Voltage-limited torque'.

    The largest torque reachable on the voltage ellipse abs(U) = V_lim (no current limit) is where
    the quartic in I_q of the voltage constraint has a double root; its discriminant (divided by
    a T**2) is the quartic in T of docs theory/motor 'Voltage-limited torque' with the coefficients
    A...E of lsdo_motor ``torque_limit_model`` (omega the electrical speed, D = 3p(L_d - L_q)). The
    residual is that
    quartic divided by A T_s**4, in x = T/T_s with T_s = 1.5 p Psi_F I_w (same root, well
    scaled; the reference divides by E and 1e3, which is singular where E = 0):

        R = x**4 + (B/(A T_s)) x**3 + (C/(A T_s**2)) x**2 + (D/(A T_s**3)) x + E/(A T_s**4),

    solve_nonlinear follows the reference bracketing, vectorized: lower bracket = the largest
    real root of the derivative cubic (companion-matrix eigenvalues over all points at once),
    upper bracket = the lower one plus a step doubled until the sign changes, then bisection.
    T_lim is thus the largest real root. linearize: exact complex-step Jacobian (pointwise).

    Inputs
    ------
    resistance : float, (num_motors,), ohm
        Phase resistance R.
    inductance_d, inductance_q : float, (num_motors,), H
        L_d, L_q.
    flux_linkage : float, (num_motors,), Wb
        Psi_F.
    rotor_rpm : float, (num_motors, num_nodes), rpm
        Rotor speed; motor electrical speed omega = rpm gear_ratio 2 pi/60 p. Must be > 0.

    Outputs
    -------
    torque_limit : float, (num_motors, num_nodes), N*m
        Voltage-limited EM torque T_lim (state).

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    num_nodes : int
        Operating points per motor (>= 1). Default 1.
    parameters : MotorParameters
        Pole pairs, gear ratio, voltage limit, rated current.

    Raises
    ------
    om.AnalysisError
        If rotor_rpm is not > 0, or the quartic has no real root above its largest critical
        point (no voltage-limited torque).
    """

    _input_vars = (
        ("resistance", "ohm", "Phase resistance R", 0.02, False),
        ("inductance_d", "H", "D-axis inductance L_d", 7.5e-4, False),
        ("inductance_q", "H", "Q-axis inductance L_q", 1.0e-3, False),
        ("flux_linkage", "Wb", "Permanent-magnet flux linkage Psi_F", 0.3, False),
        ("rotor_rpm", "rpm", "Rotor speed", 1000.0, True),
    )
    _state_var = (
        "torque_limit",
        "N*m",
        "Voltage-limited EM torque T_lim (no flux weakening, no current limit)",
        400.0,
        True,
    )
    _deps = ("resistance", "inductance_d", "inductance_q", "flux_linkage", "rotor_rpm")
    _per_node = True

    def _check_values(self, values):
        check_range(
            "rotor_rpm",
            values["rotor_rpm"],
            lower=0.0,
            lower_open=True,
            units="rpm",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        for name, units in (
            ("resistance", "ohm"),
            ("inductance_d", "H"),
            ("inductance_q", "H"),
            ("flux_linkage", "Wb"),
        ):
            check_range(
                name,
                values[name],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )

    def _residual(self, v, torque):
        scale, b, c, d, e = _quartic(v, self.options["parameters"])
        x = torque / scale
        return (((x + b) * x + c) * x + d) * x + e

    def _solve(self, v):
        """
        Return the largest real root of the quartic on its bracket (safeguarded Newton).

        The coefficients are formed once per solve (the residual would form them at every
        iteration) and the slope is the polynomial's derivative.
        """
        scale, b, c, d, e = _quartic(v, self.options["parameters"])
        lower, upper = self._bracket(v, (scale, b, c, d, e))

        def residual_and_slope(torque):
            x = torque / scale
            value = (((x + b) * x + c) * x + d) * x + e
            slope = ((4.0 * x + 3.0 * b) * x + 2.0 * c) * x + d
            return value, slope / scale

        return self._newton(residual_and_slope, lower, upper)

    def _bracket(self, v, quartic=None):
        scale, b, c, d, e = _quartic(v, self.options["parameters"]) if quartic is None else quartic
        # Largest real root of P'(x)/4 = x**3 + (3b/4) x**2 + (c/2) x + d/4 (companion matrix).
        n = b.size
        companion = np.zeros((n, 3, 3))
        companion[:, 0, :] = -np.stack(
            [0.75 * b.ravel(), 0.5 * c.ravel(), 0.25 * d.ravel()], axis=1
        )
        companion[:, 1, 0] = 1.0
        companion[:, 2, 1] = 1.0
        roots = np.linalg.eigvals(companion)
        real = np.abs(roots.imag) <= 1e-9 * np.maximum(1.0, np.abs(roots.real))
        lower = np.max(np.where(real, roots.real, -np.inf), axis=1).reshape(b.shape)

        def poly(x):
            return (((x + b) * x + c) * x + d) * x + e

        if np.any(poly(lower) > 0.0):
            idx = np.argwhere(poly(lower) > 0.0)[0].tolist()
            raise om.AnalysisError(
                f"{self.msginfo}: the voltage-limit torque quartic has no real root above its "
                f"largest critical point at index {idx} (rotor_rpm "
                f"{v['rotor_rpm'][tuple(idx)]:.6g} rpm); no voltage-limited torque exists."
            )
        step = np.maximum(1.0, np.abs(lower))
        upper = lower + step
        for _ in range(_MAX_DOUBLINGS):
            open_ = poly(upper) <= 0.0
            if not np.any(open_):
                break
            step = np.where(open_, 2.0 * step, step)
            upper = np.where(open_, lower + step, upper)
        else:
            raise om.AnalysisError(f"{self.msginfo}: no upper bracket found for torque_limit.")
        return lower * scale, upper * scale
