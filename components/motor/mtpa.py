"""Maximum-torque-per-ampere (MTPA) q-axis current of the PMSM (paper eq. 26)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.motor._numerics import check_saliency
from lpc_mdo.components.motor._pointwise import PointwiseExplicitComp, _declare_common_options
from lpc_mdo.core.checks import check_range
from lpc_mdo.core.numerics import safeguarded_newton


def mtpa_base(flux_linkage, inductance_d, inductance_q, pole_pairs):
    """
    Return the base current and torque of the per-unit MTPA quartic (complex-safe).

    See docs theory/motor 'MTPA'.

    I_base = -Psi_F/(L_d - L_q), T_base = 1.5 p Psi_F I_base.
    """
    current_base = flux_linkage / (inductance_q - inductance_d)
    return current_base, 1.5 * pole_pairs * flux_linkage * current_base


def mtpa_residual(current_pu, torque_pu):
    """Per-unit MTPA residual I_q*^4 + T* I_q* - T*^2 (paper eq. 26)."""
    return current_pu**4 + torque_pu * current_pu - torque_pu**2


#: The last real roots of :func:`mtpa_current_pu` by torque array. A complex-step Jacobian
#: evaluates the motor residuals once per input with the same real parts, so the real root is
#: the same each time; solving it once per linearize instead of once per input saved the
#: safeguarded Newton iterations of the MTPA quartic (measured with run_scripts/benchmark_lpc.py).
_REAL_ROOTS = {}
_REAL_ROOTS_KEPT = 64


def _real_root(t_real, owner):
    """Return the real root of eq. 26 for the real per-unit torques (cached by value)."""
    key = (t_real.shape, t_real.tobytes())
    root = _REAL_ROOTS.get(key)
    if root is None:
        root = safeguarded_newton(
            lambda x: (mtpa_residual(x, t_real), 4.0 * x**3 + t_real),
            np.zeros_like(t_real),
            np.minimum(t_real, np.sqrt(t_real)),
            where=owner,
            variable="current_q (per unit)",
        )
        if len(_REAL_ROOTS) >= _REAL_ROOTS_KEPT:
            _REAL_ROOTS.clear()
        _REAL_ROOTS[key] = root
    return root.copy()


def mtpa_current_pu(torque_pu, owner="MTPA"):
    """
    Per-unit MTPA q-axis current I_q*(T*): the root of eq. 26 for T* > 0 (vectorized).

    For T* > 0 the residual is increasing and convex in I_q* >= 0 with R(0) = -T*^2 < 0 and
    R(min(T*, sqrt(T*))) > 0, so the root is unique in that bracket; a safeguarded Newton
    iteration on it converges to machine precision in a few steps. For a complex ``torque_pu``
    (complex step) the real root is followed by one complex Newton step, which gives the exact
    derivative dI_q*/dT* = -(I_q* - 2T*)/(4 I_q*^3 + T*).
    """
    torque_pu = np.asarray(torque_pu)
    t_real = torque_pu.real
    current_pu = _real_root(t_real, owner)
    if np.iscomplexobj(torque_pu):
        current_pu = current_pu - (
            mtpa_residual(current_pu, torque_pu) / (4.0 * current_pu**3 + t_real)
        )
    return current_pu


class MTPAComp(om.ImplicitComponent):
    """
    Q-axis current of maximum-torque-per-ampere control (implicit).

    See paper eq. 26 and docs theory/motor 'MTPA'.

    With I_base = -Psi_F/(L_d - L_q) and T_base = 1.5 p Psi_F I_base, the per-unit q-axis current
    I_q* = I_q/I_base at the per-unit EM torque T* = T_em/T_base solves

        R = I_q*^4 + T* I_q* - T*^2 = 0.

    For T* > 0, R is increasing in I_q* >= 0 (dR/dI_q* = 4 I_q*^3 + T* > 0) with R(0) < 0 and
    R(min(T*, sqrt(T*))) > 0, so the root is unique; solve_nonlinear solves on that bracket
    (the reference bisects on [0, 50 I_base], same root) with a safeguarded Newton iteration
    (:func:`mtpa_current_pu`), vectorized over all motors and nodes, to machine precision.
    linearize: analytic partials of R (pointwise, sparse). The d-axis current follows as
    I_d = (T_em/(1.5 p I_q) - Psi_F)/(L_d - L_q) (MotorLossComp).

    Inputs
    ------
    em_torque : float, (num_motors, num_nodes), N*m
        Electromagnetic torque T_em; must be > 0.
    flux_linkage : float, (num_motors,), Wb
        Psi_F; must be > 0.
    inductance_d, inductance_q : float, (num_motors,), H
        L_d, L_q; MTPA of this form needs saliency L_q > L_d > 0.

    Outputs
    -------
    current_q : float, (num_motors, num_nodes), A
        MTPA q-axis current I_q = I_q* I_base (state).

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    num_nodes : int
        Operating points per motor (>= 1). Default 1.
    parameters : MotorParameters
        Pole pairs.

    Raises
    ------
    om.AnalysisError
        If em_torque or flux_linkage is not > 0, or L_q <= L_d (no reluctance torque, the
        per-unit quartic is undefined).
    """

    def initialize(self):
        _declare_common_options(self, per_node=True)

    def setup(self):
        nm, nn = self.options["num_motors"], self.options["num_nodes"]
        self.add_input(
            "em_torque",
            val=100.0 * np.ones((nm, nn)),
            units="N*m",
            desc="Electromagnetic torque T_em",
        )
        self.add_input(
            "flux_linkage",
            val=0.3 * np.ones(nm),
            units="Wb",
            desc="Permanent-magnet flux linkage Psi_F",
        )
        self.add_input(
            "inductance_d", val=7.5e-4 * np.ones(nm), units="H", desc="D-axis inductance L_d"
        )
        self.add_input(
            "inductance_q", val=1.0e-3 * np.ones(nm), units="H", desc="Q-axis inductance L_q"
        )
        self.add_output(
            "current_q",
            val=50.0 * np.ones((nm, nn)),
            units="A",
            desc="MTPA q-axis current I_q",
        )

        rows = np.arange(nm * nn)
        per_motor = np.repeat(np.arange(nm), nn)
        self.declare_partials("current_q", ["current_q", "em_torque"], rows=rows, cols=rows)
        self.declare_partials(
            "current_q", ["flux_linkage", "inductance_d", "inductance_q"], rows=rows, cols=per_motor
        )

    def _per_unit(self, inputs, current_q):
        p = self.options["parameters"].pole_pairs
        psi, l_d, l_q = (
            inputs[name][:, np.newaxis] for name in ("flux_linkage", "inductance_d", "inductance_q")
        )
        i_base, t_base = mtpa_base(psi, l_d, l_q, p)
        return current_q / i_base, inputs["em_torque"] / t_base, i_base, t_base

    def _check_values(self, inputs):
        check_range(
            "em_torque",
            inputs["em_torque"],
            lower=0.0,
            lower_open=True,
            units="N*m",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        check_range(
            "flux_linkage",
            inputs["flux_linkage"],
            lower=0.0,
            lower_open=True,
            units="Wb",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        check_range(
            "inductance_d",
            inputs["inductance_d"],
            lower=0.0,
            lower_open=True,
            units="H",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        check_saliency(
            self.msginfo,
            inputs["inductance_d"],
            inputs["inductance_q"],
            " is outside the allowed range (0, inf): the MTPA quartic needs L_q > L_d.",
        )

    def apply_nonlinear(self, inputs, outputs, residuals):
        current_pu, torque_pu, _, _ = self._per_unit(inputs, outputs["current_q"])
        residuals["current_q"] = mtpa_residual(current_pu, torque_pu)

    def solve_nonlinear(self, inputs, outputs):
        self._check_values(inputs)
        _, torque_pu, i_base, _ = self._per_unit(inputs, outputs["current_q"])
        outputs["current_q"] = mtpa_current_pu(torque_pu, owner=self.msginfo) * i_base

    def guess_nonlinear(self, inputs, outputs, residuals):
        # Only used by a Newton solver above; keep the state positive.
        current = outputs["current_q"]
        if np.any(current.real <= 0.0):
            outputs["current_q"] = np.where(current.real > 0.0, current, 1.0)

    def solve_linear(self, d_outputs, d_residuals, mode):
        """
        Solve the linear system of I_q: dR/dI_q is diagonal, so divide by it (no DirectSolver).

        Parameters
        ----------
        d_outputs : Vector
            Unscaled output derivatives (solution in fwd, right-hand side in rev).
        d_residuals : Vector
            Unscaled residual derivatives (right-hand side in fwd, solution in rev).
        mode : str
            'fwd' or 'rev'.
        """
        if mode == "fwd":
            d_outputs["current_q"] = d_residuals["current_q"] / self._state_jac_diag
        else:
            d_residuals["current_q"] = d_outputs["current_q"] / self._state_jac_diag

    def linearize(self, inputs, outputs, partials):
        p = self.options["parameters"].pole_pairs
        psi, l_d, l_q = (
            inputs[name][:, np.newaxis] for name in ("flux_linkage", "inductance_d", "inductance_q")
        )
        current_q, torque = outputs["current_q"], inputs["em_torque"]
        current_pu, torque_pu, i_base, t_base = self._per_unit(inputs, current_q)
        dr_dx = 4.0 * current_pu**3 + torque_pu  # dR/dI_q*
        dr_dt = current_pu - 2.0 * torque_pu  # dR/dT*
        # d(per-unit)/d(base): x = I_q/I_base, t = T/T_base.
        dx_dib = -current_q / i_base**2
        dt_dtb = -torque / t_base**2
        saliency = l_q - l_d
        dib = {
            "flux_linkage": 1.0 / saliency,
            "inductance_q": -psi / saliency**2,
            "inductance_d": psi / saliency**2,
        }
        dtb = {
            "flux_linkage": 3.0 * p * psi / saliency,
            "inductance_q": -1.5 * p * psi**2 / saliency**2,
            "inductance_d": 1.5 * p * psi**2 / saliency**2,
        }
        self._state_jac_diag = dr_dx / i_base  # dR/dI_q: diagonal (pointwise)
        partials["current_q", "current_q"] = self._state_jac_diag.ravel()
        partials["current_q", "em_torque"] = (dr_dt / t_base).ravel()
        for name in ("flux_linkage", "inductance_d", "inductance_q"):
            partials["current_q", name] = (
                dr_dx * dx_dib * dib[name] + dr_dt * dt_dtb * dtb[name]
            ).ravel()


class PeakCurrentComp(PointwiseExplicitComp):
    """
    Phase-current amplitude of the MTPA point at the peak torque: the motor's current limit.

    See docs theory/motor 'Winding for the bus' and 'Torque margin'. With the MTPA base values
    of :func:`mtpa_base` and the per-unit root of paper eq. 26 at T* = T_pk/T_base:

        I_q = I_q*(T*) I_base,  I_d = (T_pk/(1.5 p I_q) - Psi_F)/(L_d - L_q),
        I_pk = sqrt(I_q**2 + I_d**2).

    The motor delivers its peak (current-limited) torque T_pk at this current, so its inverter
    and cables are rated for it. Under MTPA the current grows with the torque, so an operating
    point within the torque margin (T_em <= T_pk/1.1) draws less than I_pk. Partials: exact
    vectorized complex step (the MTPA root is complex-step safe), diagonal over the motors.

    Inputs
    ------
    peak_torque : float, (num_motors,), N*m
        Peak (current-limited) torque T_pk; must be > 0.
    flux_linkage : float, (num_motors,), Wb
        Psi_F; must be > 0.
    inductance_d, inductance_q : float, (num_motors,), H
        L_d, L_q (L_q > L_d).

    Outputs
    -------
    peak_current : float, (num_motors,), A
        Phase-current amplitude I_pk at the peak torque.

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 1.
    parameters : MotorParameters
        Pole pairs.

    Raises
    ------
    om.AnalysisError
        If peak_torque or flux_linkage is not > 0 or L_q <= L_d.
    """

    _input_vars = (
        ("peak_torque", "N*m", "Peak (current-limited) torque T_pk", 200.0, False),
        ("flux_linkage", "Wb", "Permanent-magnet flux linkage Psi_F", 0.3, False),
        ("inductance_d", "H", "D-axis inductance L_d", 7.5e-4, False),
        ("inductance_q", "H", "Q-axis inductance L_q", 1.0e-3, False),
    )
    _output_vars = (
        (
            "peak_current",
            "A",
            "Phase-current amplitude of the MTPA point at the peak torque",
            300.0,
            False,
        ),
    )
    _deps = {"peak_current": ("peak_torque", "flux_linkage", "inductance_d", "inductance_q")}

    def _check_values(self, values):
        for name, units in (("peak_torque", "N*m"), ("flux_linkage", "Wb")):
            check_range(
                name,
                values[name],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        check_saliency(
            self.msginfo,
            values["inductance_d"],
            values["inductance_q"],
            " is outside the allowed range (0, inf): the MTPA current needs L_q > L_d, which the "
            "equivalent circuit gives only above a minimum stack length (about 0.056 m at L/D = "
            "0.5 with the default parameters).",
        )

    def _evaluate(self, v):
        p = self.options["parameters"].pole_pairs
        psi, l_d, l_q, torque = (
            v["flux_linkage"],
            v["inductance_d"],
            v["inductance_q"],
            v["peak_torque"],
        )
        i_base, t_base = mtpa_base(psi, l_d, l_q, p)
        current_q = mtpa_current_pu(torque / t_base, owner=self.msginfo) * i_base
        current_d = (torque / (1.5 * p * current_q) - psi) / (l_d - l_q)
        return {"peak_current": np.sqrt(current_q**2 + current_d**2)}
