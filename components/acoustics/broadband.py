"""Broadband rotor noise spectrum by the Gill-Lee gene-expression-programming model."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.common import (
    blade_counts,
    check_input_range,
    declare_broadband_options,
    declare_radial_options,
    nominal_third_octave_bands,
    radial_quadrature,
)
from lpc_mdo.core.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND

# Squared-length floor under sqrt(z**2) for a smooth |sin(theta_0)| (m**2).
_EPS_Z2 = 1.0e-12
_LN10 = np.log(10.0)

# Per-rotor intermediate quantities of the Gill-Lee functions, in this order.
_INTER = ("vtip", "mt", "ct", "sigma", "csw", "sth", "sr")
# Per-rotor inputs (and the chord sum) they depend on.
_BASE = (
    "radius",
    "rpm",
    "thrust",
    "chord_sum",
    "density",
    "speed_of_sound",
    "distance",
    "axial_distance",
    "axial_speed",
    "inplane_speed",
)
# Spectrum parameters.
_PARAM = ("u", "xs", "f0", "f5", "f6", "f7", "f8")


class GillLeeBroadbandComp(om.ExplicitComponent):
    """
    One-third-octave broadband noise spectrum of each rotor by the Gill-Lee model (paper eq. 22).

    docs theory/acoustics 'Broadband noise' (default, public-code function set; paper eq. 22 has f3
    Delta**4 where f3 X**f4 with f4 = 1 is meant). Per rotor:

    - blade area A_b = R sum_i w_i c_i; solidity sigma = B A_b/(pi R**2); solidity-weighted chord
      c_sw = A_b/R; C_T = T/(rho pi R**2 (Omega R)**2);
    - V_tip = Omega R - norm(V) (retreating-blade correction), M_t = V_tip/a; Strouhal number
      St = f c_sw/V_tip at each band centre f;
    - f0 = 10 log10(V_tip**7.84), f1 = sigma, f2 = 0.9 M_t sigma (M_t + 3.82), f5 = 2.06 - 2 M_t**2,
      f6 = 1 - C_T M_t (C_T - sin|theta_0| + 2.06), f7 = C_T,
      f8 = 4.97 C_T sin|theta_0| (1.5 (S/R) M_t - S/R + 15);
    - X = St - (f1 log10 C_T + f2 log10 sigma);
      SPL_1/3(f) = f0 X**0.6/[(X + f5)**f6 + (f7 X)**f8] (f3 = f4 = 1).

    abs(sin theta_0) = sqrt(z**2 + 1e-12 m**2)/S (smooth). Optional edgewise adjustment (newest
    GL_model): Delta = g(mu_e) (0.5 tanh(1000 (mu_e - 0.05)) + 0.5) with the edgewise advance ratio
    mu_e = (in-plane speed)/(Omega R) and g = 14.8 mu_e - 0.74 (B = 2) or 10 mu_e - 0.5 (B != 2);
    it is added to every band, so it enters the A-weighted level too (the public code adds it to
    the unweighted OASPL only, which makes the weighted and unweighted levels inconsistent), and
    mu_e uses the in-plane speed norm(V - (V.n) n) (the code's norm(V (x) b) element-wise product
    equals
    it when V lies along a body axis). It vanishes in hover.

    Inputs
    ------
    radius, rpm, thrust : float, (num_rotors,), m, rpm, N
        Rotor radius, speed and thrust (> 0).
    chord : float, (num_rotors, num_radial), m
        Blade chord at the stations.
    density : float, (1,), kg/m**3
        Air density.
    speed_of_sound : float, (1,), m/s
        Speed of sound.
    distance, axial_distance : float, (num_rotors,), m
        Hub-observer distance S and the axial distance z (ObserverGeometryComp).
    axial_speed, inplane_speed : float, (num_rotors,), m/s
        Flight speed along and across the thrust axis (norm(V) = sqrt of their squares).

    Outputs
    -------
    broadband_spl : float, (num_rotors, num_bands), dB (units=None)
        One-third-octave band levels, dB re 20 uPa.

    Options
    -------
    reference_distance : float or None
        If set, the spectrum is the source spectrum at this distance S_ref along the observer's
        direction (S/R in f8 becomes S_ref/R; sin|theta_0| keeps the true direction) and the
        caller propagates it to S (SphericalPropagationComp). None: S enters f8 directly (the
        public-code form, whose level falls ~54 dB per decade in hover, not 20 dB).
    num_rotors : int
        Number of rotors.
    num_blades : int or sequence of int
        Blades per rotor.
    num_bands : int
        Number of one-third-octave bands. Default 38 (12.5 Hz to 63 kHz, docs theory/acoustics
        'Broadband noise').
    lowest_band_frequency : float
        Nominal centre of the first band, Hz. Default 12.5.
    edgewise_correction : bool
        Add the edgewise adjustment. Default True.
    num_radial, radial_stations, radial_weights, hub_radius_ratio :
        Acoustic radial stations and quadrature (``common.radial_quadrature``).

    Raises
    ------
    om.AnalysisError
        If thrust, radius, rpm, density or a chord is not positive, V_tip <= 0, the solidity is
        not below 1, or the spectrum variable X (or X + f5) is not positive.
    """

    def initialize(self):
        declare_broadband_options(self.options)
        self.options.declare(
            "edgewise_correction",
            default=True,
            types=bool,
            desc="Add the Gill-Lee edgewise adjustment",
        )
        self.options.declare(
            "reference_distance",
            default=None,
            types=(int, float),
            allow_none=True,
            desc="Source distance S_ref of the spectrum (S/R = S_ref/R in f8), m; None: S",
        )
        declare_radial_options(self.options)

    def setup(self):
        nr, nrad, nb = (self.options[k] for k in ("num_rotors", "num_radial", "num_bands"))
        r_ref = self.options["reference_distance"]
        self._r_ref = None if r_ref is None else float(r_ref)
        self._blades = blade_counts(self.options["num_blades"], nr).astype(float)
        _, self._w = radial_quadrature(
            nrad,
            self.options["radial_stations"],
            self.options["radial_weights"],
            self.options["hub_radius_ratio"],
        )
        self.band_frequencies = nominal_third_octave_bands(
            nb, float(self.options["lowest_band_frequency"])
        )
        self._edge_slope = np.where(self._blades == 2, 3.7 / 0.25, 2.5 / 0.25)
        self._edge_offset = np.where(self._blades == 2, -0.74, -0.5)

        for name, units, desc in (
            ("radius", "m", "Rotor radius"),
            ("rpm", "rpm", "Rotor speed"),
            ("thrust", "N", "Rotor thrust"),
        ):
            self.add_input(name, val=np.ones(nr), units=units, desc=desc)
        self.add_input("chord", val=np.full((nr, nrad), 0.1), units="m", desc="Blade chord")
        self.add_input("density", val=SEA_LEVEL_DENSITY, units="kg/m**3", desc="Air density")
        self.add_input(
            "speed_of_sound", val=SEA_LEVEL_SPEED_OF_SOUND, units="m/s", desc="Speed of sound"
        )
        self.add_input(
            "distance", val=np.full(nr, 100.0), units="m", desc="Hub-observer distance S"
        )
        self.add_input(
            "axial_distance",
            val=np.full(nr, -70.0),
            units="m",
            desc="Observer distance along the thrust axis z",
        )
        self.add_input(
            "axial_speed", val=np.zeros(nr), units="m/s", desc="Flight speed along the thrust axis"
        )
        self.add_input(
            "inplane_speed", val=np.zeros(nr), units="m/s", desc="Flight speed in the rotor plane"
        )
        self.add_output(
            "broadband_spl",
            val=np.zeros((nr, nb)),
            units=None,
            desc="One-third-octave broadband band levels, dB re 20 uPa",
        )

        rows = np.arange(nr * nb)
        rotor = rows // nb
        for name in _BASE:
            if name == "chord_sum":
                r_i, b_i, i_i = np.meshgrid(
                    np.arange(nr), np.arange(nb), np.arange(nrad), indexing="ij"
                )
                self.declare_partials(
                    "broadband_spl",
                    "chord",
                    rows=(r_i * nb + b_i).ravel(),
                    cols=(r_i * nrad + i_i).ravel(),
                )
            elif name in ("density", "speed_of_sound"):
                self.declare_partials(
                    "broadband_spl", name, rows=rows, cols=np.zeros(nr * nb, dtype=int)
                )
            else:
                self.declare_partials("broadband_spl", name, rows=rows, cols=rotor)

    # ------------------------------------------------------------------ model
    def _intermediates(self, inputs, grad):
        R = inputs["radius"]
        rpm = inputs["rpm"]
        omega = rpm * RPM_TO_RAD_S
        rho = inputs["density"][0]
        a = inputs["speed_of_sound"][0]
        S, z = inputs["distance"], inputs["axial_distance"]
        va, vp = inputs["axial_speed"], inputs["inplane_speed"]
        chord_sum = inputs["chord"] @ self._w  # sum_i w_i c_i = A_b/R = c_sw
        speed = np.sqrt(va * va + vp * vp)
        B = self._blades
        v = {
            "vtip": omega * R - speed,
            "ct": inputs["thrust"] / (rho * np.pi * R**2 * (omega * R) ** 2),
            "sigma": B * chord_sum / (np.pi * R),
            "csw": chord_sum,
            "sth": np.sqrt(z * z + _EPS_Z2) / S,
            "sr": (S if self._r_ref is None else self._r_ref) / R,
        }
        v["mt"] = v["vtip"] / a
        if not grad:
            return v, None
        one = np.ones_like(R)
        # d(intermediate)/d(base), each a dict base -> (nr,) array.
        d = {}
        d["vtip"] = {
            "radius": omega * one,
            "rpm": RPM_TO_RAD_S * R,
            "axial_speed": -va / speed,
            "inplane_speed": -vp / speed,
        }
        d["mt"] = {k: val / a for k, val in d["vtip"].items()}
        d["mt"]["speed_of_sound"] = -v["mt"] / a
        ct = v["ct"]
        d["ct"] = {
            "thrust": ct / inputs["thrust"],
            "density": -ct / rho,
            "rpm": -2.0 * ct / rpm,
            "radius": -4.0 * ct / R,
        }
        d["sigma"] = {"chord_sum": B / (np.pi * R), "radius": -v["sigma"] / R}
        d["csw"] = {"chord_sum": one}
        sz = np.sqrt(z * z + _EPS_Z2)
        d["sth"] = {"axial_distance": z / (sz * S), "distance": -v["sth"] / S}
        d["sr"] = {"distance": one / R, "radius": -v["sr"] / R}
        if self._r_ref is not None:
            d["sr"]["distance"] = 0.0 * one
        return v, d

    def _parameters(self, v, dv):
        """Spectrum parameters (u = c_sw/V_tip, xs, f0, f5..f8) and their derivatives."""
        vtip, mt, ct, sigma, csw, sth, sr = (v[k] for k in _INTER)
        lct, lsig = np.log10(ct), np.log10(sigma)
        f2 = 0.9 * mt * sigma * (mt + 3.82)
        h = 1.5 * sr * mt - sr + 15.0
        p = {
            "u": csw / vtip,
            "xs": sigma * lct + f2 * lsig,
            "f0": 78.4 * np.log10(vtip),
            "f5": 2.06 - 2.0 * mt * mt,
            "f6": 1.0 - ct * mt * (ct - sth + 2.06),
            "f7": ct,
            "f8": 4.97 * ct * sth * h,
        }
        if dv is None:
            return p, None
        # d(parameter)/d(intermediate).
        dp = {
            "u": {"csw": 1.0 / vtip, "vtip": -csw / vtip**2},
            "xs": {
                "sigma": lct + f2 / (sigma * _LN10) + 0.9 * mt * (mt + 3.82) * lsig,
                "ct": sigma / (ct * _LN10),
                "mt": 0.9 * sigma * (2.0 * mt + 3.82) * lsig,
            },
            "f0": {"vtip": 78.4 / (vtip * _LN10)},
            "f5": {"mt": -4.0 * mt},
            "f6": {
                "ct": -mt * (2.0 * ct - sth + 2.06),
                "mt": -ct * (ct - sth + 2.06),
                "sth": ct * mt,
            },
            "f7": {"ct": np.ones_like(ct)},
            "f8": {
                "ct": 4.97 * sth * h,
                "sth": 4.97 * ct * h,
                "mt": 4.97 * ct * sth * 1.5 * sr,
                "sr": 4.97 * ct * sth * (1.5 * mt - 1.0),
            },
        }
        # Chain to the base inputs.
        dpb = {}
        for name in _PARAM:
            dpb[name] = {}
            for inter, dval in dp[name].items():
                for base, dib in dv[inter].items():
                    dpb[name][base] = dpb[name].get(base, 0.0) + dval * dib
        return p, dpb

    def _edgewise(self, inputs):
        omega_r = inputs["rpm"] * RPM_TO_RAD_S * inputs["radius"]
        mu = inputs["inplane_speed"] / omega_r
        t = np.tanh(1000.0 * (mu - 0.05))
        g = self._edge_slope * mu + self._edge_offset
        delta = g * (0.5 * t + 0.5)
        ddelta_dmu = self._edge_slope * (0.5 * t + 0.5) + g * 500.0 * (1.0 - t * t)
        return delta, ddelta_dmu, mu

    def _spectrum(self, inputs, grad, checked=False):
        v, dv = self._intermediates(inputs, grad)
        if checked:  # the ranges the spectrum's logarithms and powers need, before them
            check_input_range(self, "tip speed minus flight speed (V_tip)", v["vtip"], lower=0.0)
            check_input_range(self, "solidity", v["sigma"], lower=0.0, upper=1.0)
        p, dpb = self._parameters(v, dv)
        f = self.band_frequencies[None, :]
        X = f * p["u"][:, None] - p["xs"][:, None]
        A = X + p["f5"][:, None]
        if checked:
            check_input_range(
                self,
                "Gill-Lee spectrum variable X (St - f1 log10 C_T - f2 log10 sigma)",
                X,
                lower=0.0,
            )
            check_input_range(self, "Gill-Lee X + f5", A, lower=0.0)
        Bq = p["f7"][:, None] * X
        f6, f8 = p["f6"][:, None], p["f8"][:, None]
        a_pow = A**f6
        b_pow = Bq**f8
        den = a_pow + b_pow
        num = p["f0"][:, None] * X**0.6
        spl = num / den
        return v, p, dpb, X, A, Bq, a_pow, b_pow, den, num, spl

    def compute(self, inputs, outputs):
        for name in ("radius", "rpm", "thrust", "chord", "density", "speed_of_sound", "distance"):
            check_input_range(self, name, inputs[name], lower=0.0)
        spl = self._spectrum(inputs, grad=False, checked=True)[-1]
        if self.options["edgewise_correction"]:
            spl = spl + self._edgewise(inputs)[0][:, None]
        outputs["broadband_spl"] = spl

    def compute_partials(self, inputs, partials):
        v, p, dpb, X, A, Bq, a_pow, b_pow, den, num, spl = self._spectrum(inputs, grad=True)
        f = self.band_frequencies[None, :]
        f6, f8 = p["f6"][:, None], p["f8"][:, None]
        q = num / den**2
        dspl = {
            "f0": X**0.6 / den,
            "f5": -q * f6 * a_pow / A,
            "f6": -q * a_pow * np.log(A),
            "f7": -q * f8 * b_pow / p["f7"][:, None],
            "f8": -q * b_pow * np.log(Bq),
        }
        dspl_dx = (0.6 * num / X) / den - q * (f6 * a_pow / A + f8 * b_pow / X)
        dspl["u"] = dspl_dx * f
        dspl["xs"] = -dspl_dx

        total = {base: 0.0 for base in _BASE}
        for name in _PARAM:
            for base, val in dpb[name].items():
                total[base] = total[base] + dspl[name] * np.asarray(val)[:, None]
        if self.options["edgewise_correction"]:
            _, ddelta, mu = self._edgewise(inputs)
            dd = ddelta[:, None]
            omega_r = inputs["rpm"] * RPM_TO_RAD_S * inputs["radius"]
            total["inplane_speed"] = total["inplane_speed"] + dd / omega_r[:, None]
            total["rpm"] = total["rpm"] - dd * (mu / inputs["rpm"])[:, None]
            total["radius"] = total["radius"] - dd * (mu / inputs["radius"])[:, None]

        for base in _BASE:
            val = np.broadcast_to(total[base], spl.shape)
            if base == "chord_sum":
                partials["broadband_spl", "chord"] = (
                    val[:, :, None] * self._w[None, None, :]
                ).ravel()
            else:
                partials["broadband_spl", base] = val.ravel()
