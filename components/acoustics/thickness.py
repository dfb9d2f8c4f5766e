"""Tonal thickness noise of rotors by Barry & Magliozzi."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.common import (
    bessel_j_range,
    blade_counts,
    check_input_range,
    declare_radial_options,
    dspl_dmean_square,
    radial_quadrature,
    spl_from_mean_square,
)
from lpc_mdo.core.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND

#: Airfoil cross-section area / (chord * thickness) (lsdo_acoustics; NACA 00xx: 0.685).
SECTION_AREA_FACTOR = 0.6853

_BASE = (
    "rpm",
    "radius",
    "speed_of_sound",
    "axial_distance",
    "inplane_distance",
    "axial_speed",
    "density",
)


class BarryMagliozziThicknessComp(om.ExplicitComponent):
    """
    Thickness noise of each blade-passing harmonic by Barry & Magliozzi (hover and axial flight).

    docs theory/acoustics 'Thickness noise' (Gill, Lee, Ruh & Hwang form), for the harmonic n = m B
    (m = 1..num_harmonics), with X = z the observer distance along the thrust axis, Y the in-plane
    distance, M = V.n/a the axial flight Mach number and r = rbar R:

    - S0 = sqrt(X**2 + (1 - M**2) Y**2); section area A_x = 0.6853 c h, h = (t/c) c;
    - x = n Omega Y r/(a S0) (one common Bessel argument; docs theory/acoustics 'Public-code
      compatibility' not reproduced);
    - I_m = sum_i w_i R A_x,i [J_n(x_i) + ((1 - M**2) Y r_i/(2 S0**2))
      (J_{n-1}(x_i) - J_{n+1}(x_i))];
    - P_m = rho (m Omega)**2 B**3 (S0 + M X)**2/(2 pi sqrt(2) (1 - M**2)**2 S0**3) I_m (rms, Pa);
    - SPL_m = 10 log10(P_m**2/p_ref**2) (with the smooth floor of ``common``).

    Inputs
    ------
    radius, rpm : float, (num_rotors,), m and rpm
        Rotor radius and speed.
    chord : float, (num_rotors, num_radial), m
        Blade chord at the stations (> 0).
    thickness_to_chord : float, (num_rotors, num_radial), unitless
        Section thickness ratio t/c (>= 0). Default 0.12 (NACA 0012, the paper's rotor airfoil).
    density : float, (1,), kg/m**3
        Air density.
    speed_of_sound : float, (1,), m/s
        Speed of sound.
    axial_distance, inplane_distance : float, (num_rotors,), m
        X and Y from ObserverGeometryComp.
    axial_speed : float, (num_rotors,), m/s
        Flight speed along the thrust axis (abs(V.n) < a); zero in hover.

    Outputs
    -------
    thickness_spl : float, (num_rotors, num_harmonics), dB (units=None)
        Thickness-noise SPL per blade-passing harmonic, dB re 20 uPa.

    Options
    -------
    num_rotors : int
        Number of rotors.
    num_blades : int or sequence of int
        Blades per rotor.
    num_harmonics : int
        Number of blade-passing harmonics. Default 3.
    num_radial, radial_stations, radial_weights, hub_radius_ratio :
        Acoustic radial stations and quadrature (``common.radial_quadrature``).
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "num_blades",
            default=2,
            types=(int, tuple, list, np.ndarray),
            desc="Blades per rotor (int or one per rotor)",
        )
        self.options.declare(
            "num_harmonics", default=3, types=int, lower=1, desc="Number of blade-passing harmonics"
        )
        declare_radial_options(self.options)

    def setup(self):
        nr, nrad, nm = (self.options[k] for k in ("num_rotors", "num_radial", "num_harmonics"))
        B = blade_counts(self.options["num_blades"], nr)
        self._rbar, self._w = radial_quadrature(
            nrad,
            self.options["radial_stations"],
            self.options["radial_weights"],
            self.options["hub_radius_ratio"],
        )
        self._m = np.arange(1, nm + 1, dtype=float)
        self._n = (self._m[None, :] * B[:, None]).astype(int)
        self._b3 = B.astype(float) ** 3
        self._orders = self._n[:, :, None] + np.arange(-2, 3)[None, None, :]  # n-2 .. n+2

        self.add_input("radius", val=np.ones(nr), units="m", desc="Rotor radius")
        self.add_input("rpm", val=np.full(nr, 1000.0), units="rpm", desc="Rotor speed")
        self.add_input("chord", val=np.full((nr, nrad), 0.1), units="m", desc="Blade chord")
        self.add_input(
            "thickness_to_chord",
            val=np.full((nr, nrad), 0.12),
            units=None,
            desc="Section thickness-to-chord ratio t/c",
        )
        self.add_input("density", val=SEA_LEVEL_DENSITY, units="kg/m**3", desc="Air density")
        self.add_input(
            "speed_of_sound", val=SEA_LEVEL_SPEED_OF_SOUND, units="m/s", desc="Speed of sound"
        )
        self.add_input(
            "axial_distance",
            val=np.full(nr, -70.0),
            units="m",
            desc="Observer distance along the thrust axis X",
        )
        self.add_input(
            "inplane_distance",
            val=np.full(nr, 70.0),
            units="m",
            desc="Observer distance from the thrust axis Y",
        )
        self.add_input(
            "axial_speed", val=np.zeros(nr), units="m/s", desc="Flight speed along the thrust axis"
        )
        self.add_output(
            "thickness_spl",
            val=np.zeros((nr, nm)),
            units=None,
            desc="Thickness-noise SPL per blade-passing harmonic, dB re 20 uPa",
        )

        rows = np.arange(nr * nm)
        rotor = rows // nm
        for name in _BASE:
            if name in ("speed_of_sound", "density"):
                self.declare_partials(
                    "thickness_spl", name, rows=rows, cols=np.zeros(nr * nm, dtype=int)
                )
            else:
                self.declare_partials("thickness_spl", name, rows=rows, cols=rotor)
        r_i, m_i, i_i = np.meshgrid(np.arange(nr), np.arange(nm), np.arange(nrad), indexing="ij")
        for name in ("chord", "thickness_to_chord"):
            self.declare_partials(
                "thickness_spl",
                name,
                rows=(r_i * nm + m_i).ravel(),
                cols=(r_i * nrad + i_i).ravel(),
            )

    def _evaluate(self, inputs, grad):
        rbar, w = self._rbar, self._w
        R = inputs["radius"]
        omega = inputs["rpm"] * RPM_TO_RAD_S
        a = inputs["speed_of_sound"][0]
        rho = inputs["density"][0]
        X, Y = inputs["axial_distance"], inputs["inplane_distance"]
        M = inputs["axial_speed"] / a
        beta2 = 1.0 - M * M
        S0 = np.sqrt(X * X + beta2 * Y * Y)
        eta = omega * R * Y / (a * S0)
        zeta = beta2 * Y * R / (2.0 * S0 * S0)
        amp = (
            rho
            * omega**2
            * self._b3
            * (S0 + M * X) ** 2
            / (2.0 * np.pi * np.sqrt(2.0) * beta2**2 * S0**3)
        )
        chord, tc = inputs["chord"], inputs["thickness_to_chord"]
        area = SECTION_AREA_FACTOR * chord * chord * tc  # (nr, nrad)

        x = self._n[:, :, None] * eta[:, None, None] * rbar[None, None, :]  # (nr, nm, nrad)
        jt = bessel_j_range(self._orders[:, :, :1], 5, x)  # (.., 5): orders n-2 .. n+2
        j0 = jt[..., 2]
        j1 = 0.5 * (jt[..., 1] - jt[..., 3])  # J'_n
        g = j0 + 2.0 * zeta[:, None, None] * rbar * j1
        wa = w * area  # (nr, nrad)
        scale = self._m**2 * (amp * R)[:, None]  # (nr, nm)
        pressure = scale * np.einsum("rmi,ri->rm", g, wa)
        spl = spl_from_mean_square(pressure * pressure)
        if not grad:
            return spl, None

        j2 = 0.25 * (jt[..., 0] - 2.0 * j0 + jt[..., 4])  # J''_n
        n = self._n[:, :, None]
        dg_deta = n * rbar * j1 + 2.0 * zeta[:, None, None] * n * rbar**2 * j2
        dg_dzeta = 2.0 * rbar * j1
        dspl_dp = dspl_dmean_square(pressure * pressure) * 2.0 * pressure  # (nr, nm)
        d = {}
        d["area"] = (dspl_dp * scale)[:, :, None] * g * w  # (nr, nm, nrad)
        dspl_deta = dspl_dp * scale * np.einsum("rmi,ri->rm", dg_deta, wa)
        dspl_dzeta = dspl_dp * scale * np.einsum("rmi,ri->rm", dg_dzeta, wa)
        dspl_dlnamp = dspl_dp * pressure  # d/d ln(amp R)

        # Chain of the per-rotor scalars to the base inputs (dicts of (nr,) arrays).
        one = np.ones_like(R)
        dM = {"axial_speed": one / a, "speed_of_sound": -M / a}
        dbeta2 = {k: -2.0 * M * v for k, v in dM.items()}
        dS0 = {"axial_distance": X / S0, "inplane_distance": beta2 * Y / S0}
        for k, v in dbeta2.items():
            dS0[k] = dS0.get(k, 0.0) + Y * Y / (2.0 * S0) * v
        deta = {
            "rpm": eta / inputs["rpm"],
            "radius": eta / R,
            "inplane_distance": omega * R / (a * S0),
            "speed_of_sound": -eta / a,
        }
        dzeta = {"radius": zeta / R, "inplane_distance": beta2 * R / (2.0 * S0 * S0)}
        for k, v in dbeta2.items():
            dzeta[k] = dzeta.get(k, 0.0) + Y * R / (2.0 * S0 * S0) * v
        q = S0 + M * X
        dlnamp = {
            "density": one / rho,
            "rpm": 2.0 / inputs["rpm"],
            "radius": one / R,
            "axial_distance": 2.0 * M / q,
        }
        for k, v in dM.items():
            dlnamp[k] = dlnamp.get(k, 0.0) + 2.0 * X / q * v
        for k, v in dbeta2.items():
            dlnamp[k] = dlnamp.get(k, 0.0) - 2.0 / beta2 * v
        for k, v in dS0.items():
            deta[k] = deta.get(k, 0.0) - eta / S0 * v
            dzeta[k] = dzeta.get(k, 0.0) - 2.0 * zeta / S0 * v
            dlnamp[k] = dlnamp.get(k, 0.0) + (2.0 / q - 3.0 / S0) * v
        for k in _BASE:
            total = np.zeros_like(pressure)
            for dspl, dvar in ((dspl_deta, deta), (dspl_dzeta, dzeta), (dspl_dlnamp, dlnamp)):
                if k in dvar:
                    total = total + dspl * np.broadcast_to(dvar[k], R.shape)[:, None]
            d[k] = total
        return spl, d

    def compute(self, inputs, outputs):
        for name in ("radius", "rpm", "chord", "density", "speed_of_sound"):
            check_input_range(self, name, inputs[name], lower=0.0)
        check_input_range(
            self, "thickness_to_chord", inputs["thickness_to_chord"], lower=0.0, lower_open=False
        )
        check_input_range(
            self,
            "axial_speed / speed_of_sound (axial Mach number)",
            inputs["axial_speed"] / inputs["speed_of_sound"][0],
            lower=-1.0,
            upper=1.0,
        )
        outputs["thickness_spl"], _ = self._evaluate(inputs, grad=False)

    def compute_partials(self, inputs, partials):
        _, d = self._evaluate(inputs, grad=True)
        chord, tc = inputs["chord"], inputs["thickness_to_chord"]
        darea_dc = 2.0 * SECTION_AREA_FACTOR * chord * tc
        darea_dtc = SECTION_AREA_FACTOR * chord * chord
        partials["thickness_spl", "chord"] = (d["area"] * darea_dc[:, None, :]).ravel()
        partials["thickness_spl", "thickness_to_chord"] = (
            d["area"] * darea_dtc[:, None, :]
        ).ravel()
        for name in _BASE:
            partials["thickness_spl", name] = d[name].ravel()
