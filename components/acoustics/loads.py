"""Blade loads for the tonal noise models: azimuthal Fourier coefficients and a hover load shape."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.common import (
    blade_counts,
    check_input_range,
    declare_radial_options,
    radial_quadrature,
)
from lpc_mdo.core.checks import check_integer
from lpc_mdo.core.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY


def max_load_harmonics(num_azimuth):
    """Largest load harmonic resolvable from ``num_azimuth`` equally spaced azimuths."""
    return (num_azimuth - 1) // 2


def default_load_harmonics(num_azimuth):
    """Default number of load harmonics: all resolvable ones, at most 10 (lsdo_acoustics)."""
    return min(10, max_load_harmonics(num_azimuth))


class LoadFourierComp(om.ExplicitComponent):
    """
    Fourier coefficients of the azimuthally varying blade loads (paper eqs. 19-20).

    Paper eq. 19 writes the load at each radial station as
    f(psi) = a_0 + sum_{lambda=1..L} a_lambda cos(lambda psi) + b_lambda sin(lambda psi), and eq. 20
    finds the coefficients a_f from the linear system H a_f = f_aero, H holding the cosines and
    sines at the azimuths psi_k = 2 pi k/N_psi (k = 0..N_psi-1; docs theory/acoustics 'Unsteady
    path', without the endpoint quirk Q12). H is constant, so the system is factorised once in
    setup: a_f = H^+ f_aero, the exact solution when 2L + 1 = N_psi and the
    least-squares solution otherwise (which for equally spaced azimuths equals the trapezoidal
    Fourier quadrature of docs theory/acoustics 'Unsteady path'). The Jacobian is this constant,
    sparse matrix. With N_psi = 1 (hover BEM) a_0 is the load itself.

    Inputs
    ------
    thrust_per_span : float, (num_rotors, num_radial, num_azimuth), N/m
        Sectional thrust per unit span of one blade at each station and azimuth.
    drag_per_span : float, (num_rotors, num_radial, num_azimuth), N/m
        Sectional in-plane drag per unit span of one blade (opposing rotation; dQ/dr / r).

    Outputs
    -------
    thrust_cos_coeff, thrust_sin_coeff : float, (num_rotors, num_radial, L + 1), N/m
        a_lambda and b_lambda of the thrust, lambda = 0..L (b_0 = 0).
    drag_cos_coeff, drag_sin_coeff : float, (num_rotors, num_radial, L + 1), N/m
        a_lambda and b_lambda of the drag.

    Options
    -------
    num_rotors, num_radial, num_azimuth : int
        Array sizes (>= 1).
    num_load_harmonics : int or None
        L, the highest load harmonic, 0 <= L <= (num_azimuth - 1)//2. None (default):
        min(10, (num_azimuth - 1)//2).
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "num_radial", default=1, types=int, lower=1, desc="Number of radial stations"
        )
        self.options.declare(
            "num_azimuth",
            default=1,
            types=int,
            lower=1,
            desc="Number of equally spaced azimuthal stations",
        )
        self.options.declare(
            "num_load_harmonics",
            default=None,
            types=int,
            allow_none=True,
            desc="Highest load harmonic L (None: min(10, (num_azimuth-1)//2))",
        )

    def setup(self):
        nr, nrad, naz = (self.options[k] for k in ("num_rotors", "num_radial", "num_azimuth"))
        L = self.options["num_load_harmonics"]
        if L is None:
            L = default_load_harmonics(naz)
        check_integer(
            "num_load_harmonics",
            L,
            lower=0,
            upper=max_load_harmonics(naz),
            allowed=f"in [0, (num_azimuth - 1)//2 = {max_load_harmonics(naz)}]",
            where=self.msginfo,
        )
        nl = L + 1
        psi = 2.0 * np.pi * np.arange(naz) / naz
        lam = np.arange(nl)
        H = np.hstack([np.cos(np.outer(psi, lam)), np.sin(np.outer(psi, lam[1:]))])
        pinv = np.linalg.pinv(H)  # (2L+1, naz)
        cos_map = pinv[:nl]
        sin_map = np.vstack([np.zeros((1, naz)), pinv[nl:]])
        self._maps = {"cos": cos_map, "sin": sin_map}

        shape_in = (nr, nrad, naz)
        shape_out = (nr, nrad, nl)
        for load in ("thrust", "drag"):
            self.add_input(
                f"{load}_per_span",
                val=np.zeros(shape_in),
                units="N/m",
                desc=f"Sectional {load} per unit span of one blade over azimuth",
            )
        # Row (station s, harmonic l) depends on columns (station s, azimuth k); b_0 = 0 has no
        # partials (and none of the sine coefficients exist when L = 0).
        stations = np.arange(nr * nrad)
        for load in ("thrust", "drag"):
            for kind in ("cos", "sin"):
                name = f"{load}_{kind}_coeff"
                self.add_output(
                    name,
                    val=np.zeros(shape_out),
                    units="N/m",
                    desc=f"{'a' if kind == 'cos' else 'b'}_lambda Fourier "
                    f"coefficients of the {load} per span, lambda = 0..{L}",
                )
                harmonics = lam if kind == "cos" else lam[1:]
                if harmonics.size == 0:
                    continue
                rows = (
                    stations[:, None, None] * nl
                    + harmonics[None, :, None]
                    + np.zeros((1, 1, naz), dtype=int)
                ).ravel()
                cols = (
                    stations[:, None, None] * naz
                    + np.zeros((1, harmonics.size, 1), dtype=int)
                    + np.arange(naz)[None, None, :]
                ).ravel()
                val = np.tile(self._maps[kind][harmonics][None], (nr * nrad, 1, 1)).ravel()
                self.declare_partials(name, f"{load}_per_span", rows=rows, cols=cols, val=val)

    def compute(self, inputs, outputs):
        for load in ("thrust", "drag"):
            f = inputs[f"{load}_per_span"]
            for kind in ("cos", "sin"):
                outputs[f"{load}_{kind}_coeff"] = f @ self._maps[kind].T


class HoverLoadDistributionComp(om.ExplicitComponent):
    """
    Sectional hover loads and inflow angle from rotor thrust and torque (assumed load shape).

    For use when a rotor model provides only totals (e.g. the ``rotor_noise`` wrapper). Uniform
    induced inflow (momentum theory, ideal twist) gives a thrust per span proportional to r and,
    taking dQ/dr proportional to r**2, a drag per span proportional to r; both are scaled so that
    the quadrature of the acoustic stations returns the totals:

    - thrust per span (one blade) t_i = T r_i/(B R**2 sum_j w_j rbar_j),
      B R sum_i w_i t_i = T;
    - drag per span (one blade) d_i = Q rbar_i/(B R**2 sum_j w_j rbar_j**2),
      B R**2 sum_i w_i rbar_i d_i = Q;
    - inflow angle phi_i = arctan(lambda_h/rbar_i), lambda_h = sqrt(C_T/2),
      C_T = T/(rho pi R**2 (Omega R)**2) (hover momentum theory, docs theory/rotors 'Loads and
      coefficients' coefficient definition).

    Inputs
    ------
    thrust : float, (num_rotors,), N
        Rotor thrust (> 0).
    torque : float, (num_rotors,), N*m
        Rotor shaft torque.
    radius : float, (num_rotors,), m
        Rotor radius.
    rpm : float, (num_rotors,), rpm
        Rotor speed.
    density : float, (1,), kg/m**3
        Air density.

    Outputs
    -------
    thrust_per_span, drag_per_span : float, (num_rotors, num_radial, 1), N/m
        Sectional loads of one blade (one azimuthal station).
    inflow_angle : float, (num_rotors, num_radial, 1), rad
        Inflow angle at each station.

    Options
    -------
    num_rotors, num_radial : int
        Array sizes (>= 1).
    num_blades : int or sequence of int
        Blades per rotor (one value for all rotors or one per rotor).
    radial_stations, radial_weights, hub_radius_ratio :
        Acoustic radial stations r/R and quadrature weights (see ``common.radial_quadrature``).
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "num_blades",
            default=2,
            types=(int, tuple, list, np.ndarray),
            desc="Blades per rotor (int or one per rotor)",
        )
        declare_radial_options(self.options)

    def setup(self):
        nr, nrad = self.options["num_rotors"], self.options["num_radial"]
        self._blades = blade_counts(self.options["num_blades"], nr).astype(float)
        self._rbar, self._w = radial_quadrature(
            nrad,
            self.options["radial_stations"],
            self.options["radial_weights"],
            self.options["hub_radius_ratio"],
        )
        for name, units, desc in (
            ("thrust", "N", "Rotor thrust"),
            ("torque", "N*m", "Rotor shaft torque"),
            ("radius", "m", "Rotor radius"),
            ("rpm", "rpm", "Rotor speed"),
        ):
            self.add_input(name, val=np.ones(nr), units=units, desc=desc)
        self.add_input("density", val=SEA_LEVEL_DENSITY, units="kg/m**3", desc="Air density")
        shape = (nr, nrad, 1)
        self.add_output(
            "thrust_per_span",
            val=np.zeros(shape),
            units="N/m",
            desc="Sectional thrust per unit span of one blade (assumed shape)",
        )
        self.add_output(
            "drag_per_span",
            val=np.zeros(shape),
            units="N/m",
            desc="Sectional drag per unit span of one blade (assumed shape)",
        )
        self.add_output(
            "inflow_angle",
            val=np.zeros(shape),
            units="rad",
            desc="Inflow angle from uniform hover momentum inflow",
        )

        rows = np.arange(nr * nrad)
        cols = np.repeat(np.arange(nr), nrad)
        for name in ("thrust", "radius"):
            self.declare_partials("thrust_per_span", name, rows=rows, cols=cols)
        for name in ("torque", "radius"):
            self.declare_partials("drag_per_span", name, rows=rows, cols=cols)
        for name in ("thrust", "radius", "rpm"):
            self.declare_partials("inflow_angle", name, rows=rows, cols=cols)
        self.declare_partials(
            "inflow_angle", "density", rows=rows, cols=np.zeros(nr * nrad, dtype=int)
        )

    def _parts(self, inputs):
        rbar, w, B = self._rbar, self._w, self._blades
        R = inputs["radius"]
        omega = inputs["rpm"] * RPM_TO_RAD_S
        ct = inputs["thrust"] / (inputs["density"][0] * np.pi * R**2 * (omega * R) ** 2)
        lam_h = np.sqrt(0.5 * ct)
        ratio = lam_h[:, None] / rbar[None, :]
        t_shape = rbar / (B[:, None] * np.sum(w * rbar))  # times T/R
        d_shape = rbar / (B[:, None] * np.sum(w * rbar**2))  # times Q/R**2
        return R, lam_h, ratio, t_shape, d_shape

    def compute(self, inputs, outputs):
        check_input_range(self, "thrust", inputs["thrust"], lower=0.0)
        check_input_range(self, "radius", inputs["radius"], lower=0.0)
        check_input_range(self, "rpm", inputs["rpm"], lower=0.0)
        check_input_range(self, "density", inputs["density"], lower=0.0)
        R, lam_h, ratio, t_shape, d_shape = self._parts(inputs)
        outputs["thrust_per_span"] = (inputs["thrust"][:, None] / R[:, None] * t_shape)[..., None]
        outputs["drag_per_span"] = (inputs["torque"][:, None] / R[:, None] ** 2 * d_shape)[
            ..., None
        ]
        outputs["inflow_angle"] = np.arctan(ratio)[..., None]

    def compute_partials(self, inputs, partials):
        R, lam_h, ratio, t_shape, d_shape = self._parts(inputs)
        T, Q = inputs["thrust"][:, None], inputs["torque"][:, None]
        Rc = R[:, None]
        partials["thrust_per_span", "thrust"] = (t_shape / Rc).ravel()
        partials["thrust_per_span", "radius"] = (-T / Rc**2 * t_shape).ravel()
        partials["drag_per_span", "torque"] = (d_shape / Rc**2).ravel()
        partials["drag_per_span", "radius"] = (-2.0 * Q / Rc**3 * d_shape).ravel()
        # phi = arctan(lam_h/rbar), lam_h ~ sqrt(T/(rho rpm**2 R**4)): dln(lam_h) =
        # 0.5 dT/T - 0.5 drho/rho - d(rpm)/rpm - 2 dR/R.
        dphi_dlnlam = ratio / (1.0 + ratio**2)
        partials["inflow_angle", "thrust"] = (0.5 * dphi_dlnlam / T).ravel()
        partials["inflow_angle", "radius"] = (-2.0 * dphi_dlnlam / Rc).ravel()
        partials["inflow_angle", "rpm"] = (-dphi_dlnlam / inputs["rpm"][:, None]).ravel()
        partials["inflow_angle", "density"] = (-0.5 * dphi_dlnlam / inputs["density"][0]).ravel()
