"""Atmospheric absorption of sound by ISO 9613-1:1993 (pure-tone attenuation coefficient)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range

#: ISO 9613-1:1993 reference temperature T0 (K), triple-point temperature T01 (K) and reference
#: pressure p_r (Pa), clause 6.2 and Annex B.
ISO_REFERENCE_TEMPERATURE = 293.15
ISO_TRIPLE_POINT_TEMPERATURE = 273.16
ISO_REFERENCE_PRESSURE = 101325.0
#: Default relative humidity (%): the ICAO Annex 16 Vol. I / 14 CFR Part 36 noise-certification
#: reference atmosphere (70 %), also a row of ISO 9613-2:1996 Table 2.
DEFAULT_RELATIVE_HUMIDITY = 70.0


def molar_water_vapour(temperature, pressure, relative_humidity):
    """
    Molar concentration of water vapour h (%) from ISO 9613-1:1993 Annex B, eqs. (B.1)-(B.3).

    h = h_r (p_sat/p_r)/(p_a/p_r), p_sat/p_r = 10**C, C = -6.8346 (T01/T)**1.261 + 4.6151, with
    h_r the relative humidity (%), T the temperature (K) and p_a the pressure (Pa).
    Complex-step safe.
    """
    c = -6.8346 * (ISO_TRIPLE_POINT_TEMPERATURE / temperature) ** 1.261 + 4.6151
    return relative_humidity * 10.0**c / (pressure / ISO_REFERENCE_PRESSURE)


def iso9613_absorption(frequency, temperature, pressure, relative_humidity):
    """
    Pure-tone atmospheric attenuation coefficient alpha (dB/m) by ISO 9613-1:1993 eqs. (3)-(5).

    With p = p_a/p_r, t = T/T0 and h from :func:`molar_water_vapour`:

    - oxygen relaxation frequency f_rO = p (24 + 4.04e4 h (0.02 + h)/(0.391 + h))   (eq. 3);
    - nitrogen relaxation frequency
      f_rN = p t**-0.5 (9 + 280 h exp(-4.170 (t**(-1/3) - 1)))                        (eq. 4);
    - alpha = 8.686 f**2 [1.84e-11 t**0.5/p + t**-2.5 (0.01275 exp(-2239.1/T)/(f_rO + f**2/f_rO)
      + 0.1068 exp(-3352.0/T)/(f_rN + f**2/f_rN))]                                    (eq. 5).

    The standard states +-10 % accuracy for h in [0.05, 5] %, T in [253, 323] K and p below
    200 kPa (clause 7). Arguments broadcast against each other; complex-step safe.
    """
    f = np.asarray(frequency)
    T = np.asarray(temperature)
    p = np.asarray(pressure) / ISO_REFERENCE_PRESSURE
    t = T / ISO_REFERENCE_TEMPERATURE
    h = molar_water_vapour(T, np.asarray(pressure), np.asarray(relative_humidity))
    fro = p * (24.0 + 4.04e4 * h * (0.02 + h) / (0.391 + h))
    frn = p * t**-0.5 * (9.0 + 280.0 * h * np.exp(-4.170 * (t ** (-1.0 / 3.0) - 1.0)))
    f2 = f * f
    return (
        8.686
        * f2
        * (
            1.84e-11 * t**0.5 / p
            + t**-2.5
            * (
                0.01275 * np.exp(-2239.1 / T) / (fro + f2 / fro)
                + 0.1068 * np.exp(-3352.0 / T) / (frn + f2 / frn)
            )
        )
    )


#: Relative complex step of the absorption's partials (exact to round-off for any small step).
_COMPLEX_STEP = 1.0e-30


class AtmosphericAbsorptionComp(om.ExplicitComponent):
    """
    Atmospheric attenuation coefficient of each frequency by ISO 9613-1:1993.

    Implements :func:`iso9613_absorption` (ISO 9613-1:1993 eqs. (3)-(5) and Annex B; docs
    theory/acoustics 'Atmospheric absorption'). The absorption of a path of length d is
    alpha(f) d in dB. For one-third-octave bands the coefficient is taken at the exact band
    centre, which ISO 9613-1 clause 8.2.1 accepts for band attenuations of a few dB.

    Inputs
    ------
    temperature : float, (1,), K
        Air temperature (from the atmosphere).
    pressure : float, (1,), Pa
        Air pressure (from the atmosphere).
    relative_humidity : float, (1,), percent (units=None)
        Relative humidity h_r in (0, 100]. Default 70 (ICAO Annex 16 reference atmosphere).
    frequency : float, ``shape``, Hz
        Frequencies (only when option ``frequencies`` is None, e.g. rotor harmonics).

    Outputs
    -------
    absorption_coefficient : float, ``shape``, dB/m (units=None, dB per metre)
        Attenuation coefficient alpha at each frequency.

    Options
    -------
    shape : tuple of int
        Shape of the frequency array.
    frequencies : array or None
        Fixed frequencies (Hz) of ``shape`` (e.g. band centres); None: ``frequency`` is an input.

    Partials by complex step (the derivation through the relaxation frequencies is out of
    proportion to the cost of this small component), with a diagonal pattern in frequency:
    each coefficient depends on its own frequency only, so one complex step of every frequency
    at once gives the whole diagonal, and one step of each scalar its column (four evaluations
    in all, where OpenMDAO's column-by-column complex step took one per frequency).
    """

    def initialize(self):
        self.options.declare("shape", types=tuple, desc="Shape of the frequency array")
        self.options.declare(
            "frequencies",
            default=None,
            types=np.ndarray,
            allow_none=True,
            desc="Fixed frequencies (Hz) of shape; None: input",
        )

    def setup(self):
        shape = self.options["shape"]
        size = int(np.prod(shape))
        fixed = self.options["frequencies"]
        if fixed is not None:
            fixed = np.asarray(fixed, dtype=float)
            if fixed.shape != shape:
                raise ValueError(
                    f"{self.msginfo}: option 'frequencies' has shape {fixed.shape}, "
                    f"must be shape = {shape}."
                )
            check_range("frequencies", fixed, lower=0.0, lower_open=True, where=self.msginfo)
        self.add_input("temperature", val=288.15, units="K", desc="Air temperature")
        self.add_input("pressure", val=ISO_REFERENCE_PRESSURE, units="Pa", desc="Air pressure")
        self.add_input(
            "relative_humidity",
            val=DEFAULT_RELATIVE_HUMIDITY,
            units=None,
            desc="Relative humidity, percent",
        )
        if fixed is None:
            self.add_input("frequency", val=np.full(shape, 1000.0), units="Hz", desc="Frequencies")
        self.add_output(
            "absorption_coefficient",
            val=np.zeros(shape),
            units=None,
            desc="ISO 9613-1 attenuation coefficient, dB/m",
        )
        ar = np.arange(size)
        zeros = np.zeros(size, dtype=int)
        for name in ("temperature", "pressure", "relative_humidity"):
            self.declare_partials("absorption_coefficient", name, rows=ar, cols=zeros)
        if fixed is None:
            self.declare_partials("absorption_coefficient", "frequency", rows=ar, cols=ar)

    def compute(self, inputs, outputs):
        where = self.msginfo
        for name, lower in (("temperature", 0.0), ("pressure", 0.0), ("relative_humidity", 0.0)):
            check_range(
                name,
                inputs[name].real,
                lower=lower,
                lower_open=True,
                error=om.AnalysisError,
                where=where,
            )
        check_range(
            "relative_humidity",
            inputs["relative_humidity"].real,
            upper=100.0,
            error=om.AnalysisError,
            where=where,
        )
        if self.options["frequencies"] is None:
            freq = inputs["frequency"]
            check_range(
                "frequency",
                freq.real,
                lower=0.0,
                lower_open=True,
                error=om.AnalysisError,
                where=where,
            )
        else:
            freq = self.options["frequencies"]
        outputs["absorption_coefficient"] = iso9613_absorption(
            freq, inputs["temperature"][0], inputs["pressure"][0], inputs["relative_humidity"][0]
        )

    def compute_partials(self, inputs, partials):
        fixed = self.options["frequencies"]
        args = {
            "frequency": inputs["frequency"] if fixed is None else fixed,
            "temperature": inputs["temperature"][0],
            "pressure": inputs["pressure"][0],
            "relative_humidity": inputs["relative_humidity"][0],
        }
        names = ["temperature", "pressure", "relative_humidity"]
        if fixed is None:
            names.append("frequency")
        for name in names:
            step = max(float(np.max(np.abs(args[name]))), 1.0) * _COMPLEX_STEP
            stepped = {**args, name: args[name] + 1j * step}
            rate = np.imag(
                iso9613_absorption(
                    stepped["frequency"],
                    stepped["temperature"],
                    stepped["pressure"],
                    stepped["relative_humidity"],
                )
            )
            partials["absorption_coefficient", name] = (rate / step).ravel()
