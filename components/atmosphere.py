"""Standard atmosphere, troposphere layer (0 to 11 km), vectorized over flight-condition nodes."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range

# Constant sets. Each entry: sea-level temperature T0 (K), sea-level pressure p0 (Pa), lapse rate
# L (K/m), gravity g0 (m/s**2), specific gas constant R (J/(kg K)), ratio of specific heats gamma,
# and the Sutherland law mu = mu_ref (T/T_mu_ref)**1.5 (T_mu_ref + S)/(T + S).
ATMOSPHERE_CONSTANTS = {
    # ICAO standard atmosphere (ICAO Doc 7488/3, 1993) = U.S. Standard Atmosphere 1976 below 11 km:
    # R = R*/M0 = 8.31432/0.0289644, g0 = 9.80665, Sutherland beta_s = 1.458e-6 kg/(m s K**0.5),
    # S = 110.4 K, i.e. mu_ref = 1.458e-6 * 288.15**1.5/(288.15 + 110.4) = 1.7894e-5 Pa s.
    "icao": {
        "T0": 288.15,
        "p0": 101325.0,
        "L": 6.5e-3,
        "g0": 9.80665,
        "R": 8.31432 / 0.0289644,
        "gamma": 1.4,
        "mu_ref": 1.458e-6 * 288.15**1.5 / (288.15 + 110.4),
        "T_mu_ref": 288.15,
        "S": 110.4,
    },
    # CADDEE SimpleAtmosphereModel (docs theory/atmosphere): rounded constants; gives rho = 1.11174
    # kg/m**3 and a = 336.409 m/s at 1000 m (docs theory/atmosphere). Kept only to reproduce those
    # numbers.
    "caddee": {
        "T0": 288.16,
        "p0": 101325.0,
        "L": 6.5e-3,
        "g0": 9.81,
        "R": 287.0,
        "gamma": 1.4,
        "mu_ref": 1.735e-5,
        "T_mu_ref": 288.16,
        "S": 110.4,
    },
}


def standard_atmosphere(altitude, constants="icao", temperature_offset=0.0):
    """
    Return the troposphere states at ``altitude`` (m), on a day ``temperature_offset`` (K) off ISA.

    The states are temperature (K), pressure (Pa), density (kg/m**3), speed of sound (m/s) and
    dynamic viscosity (Pa s), with a constant set of :data:`ATMOSPHERE_CONSTANTS`. An offset
    dT keeps the standard pressure of the altitude and raises the temperature, T = T_ISA(h) +
    dT (the ISA-deviation convention of performance charts: ICAO Doc 7488/3, sec. 2; density
    then follows from the gas law). Complex-step safe; no range check (AtmosphereComp checks).
    """
    c = ATMOSPHERE_CONSTANTS[constants]
    standard = c["T0"] - c["L"] * altitude
    pressure = c["p0"] * (standard / c["T0"]) ** (c["g0"] / (c["R"] * c["L"]))
    temperature = standard + temperature_offset
    density = pressure / (c["R"] * temperature)
    speed_of_sound = np.sqrt(c["gamma"] * c["R"] * temperature)
    mu = (
        c["mu_ref"]
        * (temperature / c["T_mu_ref"]) ** 1.5
        * (c["T_mu_ref"] + c["S"])
        / (temperature + c["S"])
    )
    return temperature, pressure, density, speed_of_sound, mu


class AtmosphereComp(om.ExplicitComponent):
    """
    Standard atmosphere in the troposphere (constant lapse rate, 0 to 11 km).

    Equations (docs theory/atmosphere, with the constants of the option ``constants``; ICAO by
    default):

    - T_ISA = T0 - L h, T = T_ISA + dT (option ``temperature_offset``, a hot or cold day)
    - p = p0 (T_ISA/T0)**(g0/(R L))
    - rho = p/(R T)
    - a = sqrt(gamma R T)
    - mu = mu_ref (T/T_mu_ref)**1.5 (T_mu_ref + S)/(T + S)   (Sutherland)
    - nu = mu/rho

    Inputs
    ------
    altitude : float, (num_nodes,), m
        Geometric altitude above mean sea level; must lie in [0, 11000] m.

    Outputs
    -------
    temperature : float, (num_nodes,), K
        Static air temperature.
    pressure : float, (num_nodes,), Pa
        Static air pressure.
    density : float, (num_nodes,), kg/m**3
        Air density.
    speed_of_sound : float, (num_nodes,), m/s
        Speed of sound.
    dynamic_viscosity : float, (num_nodes,), Pa*s
        Dynamic viscosity (Sutherland's law).
    kinematic_viscosity : float, (num_nodes,), m**2/s
        Kinematic viscosity mu/rho.

    Options
    -------
    num_nodes : int
        Number of flight-condition nodes (>= 1). Default 1.
    temperature_offset : float
        ISA temperature offset dT (K); default 0 (the standard day).
    constants : str
        'icao' (default): ICAO / U.S. 1976 standard atmosphere constants, T0 = 288.15 K,
        g0 = 9.80665 m/s**2, R = 287.053 J/(kg K), mu(T0) = 1.7894e-5 Pa s.
        'caddee': the rounded constants of the CADDEE SimpleAtmosphereModel (T0 = 288.16 K,
        g0 = 9.81, R = 287, mu(T0) = 1.735e-5), which reproduce the public-code numbers of the
        reference documents (rho = 1.11174 kg/m**3 at 1000 m) but miss the ICAO density and
        viscosity by about 1.5e-4 and 3 % relative.

    Raises
    ------
    om.AnalysisError
        In compute, if any altitude lies outside [0, 11000] m or is not finite.
    """

    altitude_min = 0.0
    altitude_max = 11000.0

    def initialize(self):
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="Number of flight-condition nodes"
        )
        self.options.declare(
            "temperature_offset",
            default=0.0,
            types=float,
            lower=-100.0,
            upper=100.0,
            desc="ISA temperature offset, K",
        )
        self.options.declare(
            "constants",
            default="icao",
            values=tuple(ATMOSPHERE_CONSTANTS),
            desc="Constant set: 'icao' (standard atmosphere) or 'caddee' "
            "(rounded constants of the public reference code)",
        )

    def setup(self):
        nn = self.options["num_nodes"]
        c = ATMOSPHERE_CONSTANTS[self.options["constants"]]
        self._c = c
        self._exponent = c["g0"] / (c["R"] * c["L"])

        self.add_input(
            "altitude",
            val=np.zeros(nn),
            units="m",
            desc="Geometric altitude above mean sea level, valid in [0, 11000] m",
        )

        self.add_output(
            "temperature", val=c["T0"] * np.ones(nn), units="K", desc="Static air temperature"
        )
        self.add_output(
            "pressure", val=c["p0"] * np.ones(nn), units="Pa", desc="Static air pressure"
        )
        self.add_output("density", val=1.225 * np.ones(nn), units="kg/m**3", desc="Air density")
        self.add_output(
            "speed_of_sound", val=340.0 * np.ones(nn), units="m/s", desc="Speed of sound"
        )
        self.add_output(
            "dynamic_viscosity",
            val=1.8e-5 * np.ones(nn),
            units="Pa*s",
            desc="Dynamic viscosity of air (Sutherland's law)",
        )
        self.add_output(
            "kinematic_viscosity",
            val=1.5e-5 * np.ones(nn),
            units="m**2/s",
            desc="Kinematic viscosity of air (dynamic viscosity / density)",
        )

        # dT/dh = -L is constant: set once here.
        self.declare_partials("temperature", "altitude", diagonal=True, val=-c["L"] * np.ones(nn))
        for name in (
            "pressure",
            "density",
            "speed_of_sound",
            "dynamic_viscosity",
            "kinematic_viscosity",
        ):
            self.declare_partials(name, "altitude", diagonal=True)

    def _check_altitude(self, h):
        # Range check only (real part); the troposphere model's valid range.
        check_range(
            "altitude",
            h,
            lower=self.altitude_min,
            upper=self.altitude_max,
            units="m",
            error=om.AnalysisError,
            where=self.msginfo,
        )

    def _states(self, h):
        return standard_atmosphere(h, self.options["constants"], self.options["temperature_offset"])

    def compute(self, inputs, outputs):
        h = inputs["altitude"]
        self._check_altitude(h)
        temperature, pressure, density, speed_of_sound, mu = self._states(h)
        outputs["temperature"] = temperature
        outputs["pressure"] = pressure
        outputs["density"] = density
        outputs["speed_of_sound"] = speed_of_sound
        outputs["dynamic_viscosity"] = mu
        outputs["kinematic_viscosity"] = mu / density

    def compute_partials(self, inputs, partials):
        c = self._c
        n = self._exponent
        temperature, pressure, density, speed_of_sound, mu = self._states(inputs["altitude"])
        standard = temperature - self.options["temperature_offset"]
        dT_dh = -c["L"]

        # p ~ T_ISA**n, rho = p/(R T), a ~ T**0.5, mu ~ T**1.5/(T + S), T = T_ISA + dT:
        # logarithmic derivatives (dT/dh = dT_ISA/dh).
        dlnp_dT = n / standard
        dlnrho_dT = dlnp_dT - 1.0 / temperature
        dlnmu_dT = 1.5 / temperature - 1.0 / (temperature + c["S"])

        partials["pressure", "altitude"] = pressure * dlnp_dT * dT_dh
        partials["density", "altitude"] = density * dlnrho_dT * dT_dh
        partials["speed_of_sound", "altitude"] = 0.5 * speed_of_sound / temperature * dT_dh
        partials["dynamic_viscosity", "altitude"] = mu * dlnmu_dT * dT_dh
        partials["kinematic_viscosity", "altitude"] = mu / density * (dlnmu_dT - dlnrho_dT) * dT_dh
