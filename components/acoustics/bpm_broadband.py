"""Broadband rotor noise summed blade section by blade section from the BPM airfoil self-noise."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.airfoil_self_noise import (
    MAX_ANGLE_OF_ATTACK_DEG,
    directivity_high,
    directivity_low,
    tip_vortex_noise,
    trailing_edge_parts,
)
from lpc_mdo.components.acoustics.common import (
    DB_PER_NEPER,
    SPL_FLOOR,
    blade_counts,
    check_input_range,
    declare_broadband_options,
    declare_radial_options,
    nominal_third_octave_bands,
    radial_quadrature,
)
from lpc_mdo.core.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND

#: Dynamic viscosity of air at 15 deg C, Pa s (ISO 2533:1975 standard atmosphere, sea level).
SEA_LEVEL_DYNAMIC_VISCOSITY = 1.7894e-5
#: Largest section Mach number: the HART BO-105 model rotor's hover tip Mach number (0.64) at
#: which Brooks & Burley (AIAA 2001-2210) compared the section-by-section BPM with measured
#: broadband noise, rounded up to 0.7.
MAX_SECTION_MACH = 0.7
#: Smallest chord Reynolds number: the report's smallest (2.54 cm chord at 31.7 m/s is 5.5e4),
#: rounded down to 4e4.
MIN_CHORD_REYNOLDS = 4.0e4

# Squared-length floor under the in-plane distance, m**2.
_EPS2 = 1.0e-12
# Per-row inputs (one value per rotor, or shared) whose derivatives are taken row-parallel.
_ROW_INPUTS = (
    "radius",
    "rpm",
    "distance",
    "axial_distance",
    "observer_azimuth_cos",
    "observer_azimuth_sin",
    "axial_speed",
    "inplane_speed",
)
_SHARED_INPUTS = ("density", "speed_of_sound", "dynamic_viscosity")
# Station inputs: each station's energy depends on its own values only.
_STATION_INPUTS = ("chord", "thrust_per_span", "inflow_angle")


class BPMBroadbandComp(om.ExplicitComponent):
    """
    One-third-octave broadband noise of each rotor from BPM self-noise of its blade sections.

    docs theory/acoustics 'BPM broadband model'. Brooks & Burley (AIAA 2001-2210) method: each
    blade section is a compact source with the airfoil self-noise of
    ``airfoil_self_noise`` (Brooks, Pope & Marcolini, NASA RP-1218: turbulent-boundary-layer
    trailing-edge noise with its separation part, and flat-tip vortex noise at the tip), seen
    from the observer at ``num_source_azimuths`` equally spaced blade azimuths; the observer
    hears the time average over a revolution, times the blade count.

    Per station i (r_i = rbar_i R, span L_i = w_i R), with the azimuth means of the sectional
    loads t_i (thrust per span of one blade) and inflow angles phi_i:

    - section speed U_0 = Omega r_i/cos(phi_i); lift coefficient C_l = t_i/(cos(phi_i) q c_i),
      q = rho U_0**2/2; angle of attack from zero lift alpha* = C_l/(2 pi) (thin-airfoil slope,
      Abbott & von Doenhoff Sec. 4.3); the chord is pitched theta = phi + alpha* to the disk;
    - at blade azimuth psi (0 aft, growing with rotation; ObserverGeometryComp's frame) the
      flow speed normal to the span is U = sqrt((Omega r + V_e sin psi)**2 + (Omega r tan
      phi)**2), V_e the in-plane flight speed (taken along the frame's e_x, forward for a lift
      rotor), M = U/a;
    - the observer relative to the section, in chord (to the trailing edge), span and normal
      axes, gives r_e, cos(Theta_e) and sin(Phi_e)**2, and D_h, D_l (RP-1218 eqs. B1-B2,
      convective Mach 0.8 M);
    - the section's Mach number towards the observer M_r (rotation and flight velocity) shifts
      the frequency, f_source = f (1 - M_r), and weights the azimuth by the observer time it
      fills, (1 - M_r)/N;
    - p**2/p_ref**2 = B sum_psi (1 - M_r)/N [sum_i TBL-TE_i + tip vortex at the outermost
      station].

    A negative alpha* (a section pushing down) is the report's symmetric section turned over:
    abs(alpha*) is used. With ``reference_distance`` set the spectrum is computed for the observer
    moved along its direction to that distance from the hub, and the caller propagates it.

    Inputs
    ------
    radius, rpm : float, (num_rotors,), m, rpm
        Rotor radius and speed.
    chord : float, (num_rotors, num_radial), m
        Blade chord at the stations.
    thrust_per_span : float, (num_rotors, num_radial, num_azimuth), N/m
        Thrust per span of one blade at the stations (azimuth mean is used).
    inflow_angle : float, (num_rotors, num_radial, num_azimuth), rad
        Inflow angle at the stations (azimuth mean is used).
    density, speed_of_sound, dynamic_viscosity : float, (1,), kg/m**3, m/s, Pa*s
        Atmosphere (viscosity default: ISO 2533 sea level).
    distance, axial_distance : float, (num_rotors,), m
        Hub-observer distance S and the axial distance z (ObserverGeometryComp).
    observer_azimuth_cos, observer_azimuth_sin : float, (num_rotors,), unitless
        Observer azimuth in the rotor's azimuth frame.
    axial_speed, inplane_speed : float, (num_rotors,), m/s
        Flight speed along and across the thrust axis.

    Outputs
    -------
    broadband_spl : float, (num_rotors, num_bands), dB (units=None)
        One-third-octave band levels, dB re 20 uPa.

    Options
    -------
    num_rotors, num_blades, num_bands, lowest_band_frequency, reference_distance :
        As GillLeeBroadbandComp.
    num_azimuth : int
        Azimuthal stations of the sectional loads.
    num_source_azimuths : int
        Blade positions of the revolution average (default 12).
    num_radial, radial_stations, radial_weights, hub_radius_ratio :
        Acoustic radial stations and quadrature (``common.radial_quadrature``).

    Raises
    ------
    om.AnalysisError
        If radius, rpm, a chord, density, viscosity or distance is not positive, or a section
        leaves the model's range: abs(alpha*) above 25 deg (the report's largest), section Mach
        number above 0.7, chord Reynolds number below 4e4, or reverse flow (Omega r + V_e sin
        psi <= 0).
    """

    def initialize(self):
        declare_broadband_options(self.options)
        self.options.declare(
            "num_azimuth", default=1, types=int, lower=1, desc="Azimuthal load stations"
        )
        self.options.declare(
            "num_source_azimuths",
            default=12,
            types=int,
            lower=4,
            desc="Blade positions of the revolution average",
        )
        self.options.declare(
            "reference_distance",
            default=None,
            types=(int, float),
            allow_none=True,
            desc="Distance of the computed spectrum from the hub along the observer direction, "
            "m; None: the observer itself",
        )
        declare_radial_options(self.options)

    def setup(self):
        opt = self.options
        nr, nrad, naz, nb = (
            opt["num_rotors"],
            opt["num_radial"],
            opt["num_azimuth"],
            opt["num_bands"],
        )
        self._blades = blade_counts(opt["num_blades"], nr).astype(float)
        self._rbar, self._w = radial_quadrature(
            nrad, opt["radial_stations"], opt["radial_weights"], opt["hub_radius_ratio"]
        )
        self.band_frequencies = nominal_third_octave_bands(nb, float(opt["lowest_band_frequency"]))
        npsi = opt["num_source_azimuths"]
        psi = 2.0 * np.pi * np.arange(npsi) / npsi
        self._cos_psi, self._sin_psi = np.cos(psi), np.sin(psi)
        ref = opt["reference_distance"]
        self._r_ref = None if ref is None else float(ref)

        for name, value, units, desc in (
            ("radius", 1.0, "m", "Rotor radius"),
            ("rpm", 1000.0, "rpm", "Rotor speed"),
            ("distance", 100.0, "m", "Hub-observer distance S"),
            ("axial_distance", -70.0, "m", "Observer distance along the thrust axis z"),
            ("observer_azimuth_cos", 1.0, None, "cos of the observer azimuth"),
            ("observer_azimuth_sin", 0.0, None, "sin of the observer azimuth"),
            ("axial_speed", 0.0, "m/s", "Flight speed along the thrust axis"),
            ("inplane_speed", 0.0, "m/s", "Flight speed in the rotor plane"),
        ):
            self.add_input(name, val=np.full(nr, value), units=units, desc=desc)
        self.add_input("chord", val=np.full((nr, nrad), 0.1), units="m", desc="Blade chord")
        for name, value, units, desc in (
            ("thrust_per_span", 100.0, "N/m", "Thrust per span of one blade"),
            ("inflow_angle", 0.1, "rad", "Inflow angle"),
        ):
            self.add_input(name, val=np.full((nr, nrad, naz), value), units=units, desc=desc)
        for name, value, units, desc in (
            ("density", SEA_LEVEL_DENSITY, "kg/m**3", "Air density"),
            ("speed_of_sound", SEA_LEVEL_SPEED_OF_SOUND, "m/s", "Speed of sound"),
            ("dynamic_viscosity", SEA_LEVEL_DYNAMIC_VISCOSITY, "Pa*s", "Dynamic viscosity of air"),
        ):
            self.add_input(name, val=value, units=units, desc=desc)
        self.add_output(
            "broadband_spl",
            val=np.zeros((nr, nb)),
            units=None,
            desc="One-third-octave broadband band levels, dB re 20 uPa",
        )

        rows = np.arange(nr * nb)
        rotor = rows // nb
        for name in _ROW_INPUTS:
            self.declare_partials("broadband_spl", name, rows=rows, cols=rotor)
        for name in _SHARED_INPUTS:
            self.declare_partials("broadband_spl", name, rows=rows, cols=np.zeros_like(rows))
        for name in _STATION_INPUTS:
            width = nrad if name == "chord" else nrad * naz
            r_i, b_i, j_i = np.meshgrid(
                np.arange(nr), np.arange(nb), np.arange(width), indexing="ij"
            )
            self.declare_partials(
                "broadband_spl",
                name,
                rows=(r_i * nb + b_i).ravel(),
                cols=(r_i * width + j_i).ravel(),
            )

    # ------------------------------------------------------------------ model
    def _elements(self, inputs, check=False):
        """
        Return the blade elements seen from the observer: arrays (nr, nrad, npsi), (nr, nrad, 1).

        shift = 1 - M_r (frequency shift and observer-time weight), chord, speed U, mach,
        alpha (abs(alpha*), deg), span, r_e, d_h, d_l; and the scalars nu, a0.
        """
        R = inputs["radius"][:, None, None]
        omega = inputs["rpm"][:, None, None] * RPM_TO_RAD_S
        rho = inputs["density"][0]
        a0 = inputs["speed_of_sound"][0]
        nu = inputs["dynamic_viscosity"][0] / rho
        S = inputs["distance"][:, None, None]
        z = inputs["axial_distance"][:, None, None]
        cphi = inputs["observer_azimuth_cos"][:, None, None]
        sphi = inputs["observer_azimuth_sin"][:, None, None]
        v_ax = inputs["axial_speed"][:, None, None]
        v_e = inputs["inplane_speed"][:, None, None]
        if self._r_ref is not None:
            z = z * (self._r_ref / S)
            S = self._r_ref + 0.0 * S
        Y = np.sqrt(S * S - z * z + _EPS2)

        # Station quantities, shape (nr, nrad, 1).
        r = self._rbar[None, :, None] * R
        chord = inputs["chord"][:, :, None]
        load = inputs["thrust_per_span"].mean(axis=2)[:, :, None]
        inflow = inputs["inflow_angle"].mean(axis=2)[:, :, None]
        cos_in = np.cos(inflow)
        u0 = omega * r / cos_in
        alpha = load / (cos_in * 0.5 * rho * u0 * u0 * chord) / (2.0 * np.pi)  # rad
        alpha_deg = alpha * (180.0 / np.pi)
        pitch = inflow + alpha
        cth, sth = np.cos(pitch), np.sin(pitch)

        # Blade azimuths, shape (1, 1, npsi).
        cpsi, spsi = self._cos_psi[None, None, :], self._sin_psi[None, None, :]
        ut = omega * r + v_e * spsi
        up = omega * r * np.tan(inflow)
        speed = np.sqrt(ut * ut + up * up)
        mach = speed / a0
        if check:
            check_input_range(self, "section tangential speed (reverse flow)", ut, lower=0.0)
            check_input_range(
                self,
                "BPM angle of attack from zero lift alpha* (deg)",
                np.abs(np.real(alpha_deg)),
                upper=MAX_ANGLE_OF_ATTACK_DEG,
                upper_open=False,
            )
            check_input_range(self, "section Mach number", mach, upper=MAX_SECTION_MACH)
            check_input_range(
                self, "chord Reynolds number", speed * chord / nu, lower=MIN_CHORD_REYNOLDS
            )
        # Observer relative to the section: along the blade motion, along the span, axial.
        cd = cphi * cpsi + sphi * spsi  # cos(phi_o - psi)
        sd = sphi * cpsi - cphi * spsi  # sin(phi_o - psi)
        along = Y * sd
        radial = Y * cd - r
        x_e = -cth * along - sth * z
        z_e = -sth * along + cth * z
        r_e = np.sqrt(along * along + radial * radial + z * z)
        cos_theta = x_e / r_e
        sin2_phi = z_e * z_e / (radial * radial + z_e * z_e + _EPS2)
        # Mach number of the section towards the observer (blade motion and flight).
        d_x = -Y * cphi + r * cpsi  # observer minus section along e_x
        m_r = (omega * r * along + v_e * d_x + v_ax * z) / (a0 * r_e)
        return {
            "shift": 1.0 - m_r,
            "chord": chord,
            "speed": speed,
            "mach": mach,
            "alpha": np.where(np.real(alpha_deg) < 0.0, -alpha_deg, alpha_deg),
            "span": self._w[None, :, None] * R,
            "r_e": r_e,
            "d_h": directivity_high(cos_theta, sin2_phi, mach, 0.8 * mach),
            "d_l": directivity_low(cos_theta, sin2_phi, mach),
            "nu": nu,
            "a0": a0,
        }

    def _parts(self, el, **changed):
        """Return trailing_edge_parts of every element and band, with ``changed`` arguments."""
        args = {k: el[k][..., None] for k in ("shift", "chord", "speed", "mach", "alpha")}
        args["nu"] = el["nu"]
        args.update(changed)
        f = self.band_frequencies * args.pop("shift")
        return trailing_edge_parts(f, alpha_deg=args.pop("alpha"), **args)

    def _tip(self, el):
        """Tip-vortex energy of the outermost station, (nr, nb), summed over the revolution."""
        tip = {k: el[k][:, -1, :, None] for k in ("shift", "chord", "mach", "alpha", "r_e", "d_h")}
        energy = tip_vortex_noise(
            self.band_frequencies * tip["shift"],
            tip["chord"],
            tip["mach"],
            tip["alpha"],
            tip["r_e"],
            tip["d_h"],
            el["a0"],
        )
        return (energy * tip["shift"]).sum(axis=1) / self._cos_psi.size

    def _weight(self, el):
        """Return L/r_e**2 times the observer-time weight (1 - M_r)/N of each element."""
        return el["span"] / el["r_e"] ** 2 * el["shift"] / self._cos_psi.size

    @staticmethod
    def _directed(el, high, low):
        """Return D_h h + D_l l of every element and band."""
        return el["d_h"][..., None] * high + el["d_l"][..., None] * low

    def _station_energy(self, el, high, low):
        """Mean-square pressure over p_ref**2 per rotor, station and band, (nr, nrad, nb)."""
        te = (self._weight(el)[..., None] * self._directed(el, high, low)).sum(axis=2)
        te[:, -1, :] = te[:, -1, :] + self._tip(el)
        return te * self._blades[:, None, None]

    def compute(self, inputs, outputs):
        for name in ("radius", "rpm", "chord", "density", "dynamic_viscosity", "distance"):
            check_input_range(self, name, inputs[name], lower=0.0)
        el = self._elements(inputs, check=True)
        energy = self._station_energy(el, *self._parts(el)).sum(axis=1)
        outputs["broadband_spl"] = 10.0 * np.log10(energy + SPL_FLOOR)

    def compute_partials(self, inputs, partials):
        """
        Exact partials by complex steps in two stages.

        The elements' quantities are cheap: one complex step per input, for every rotor (and
        every station) at once. The band spectra h, l of trailing_edge_parts depend on an input
        only through six of them (shift, chord, speed, Mach number, alpha*, nu): one complex
        step per quantity, chained. The rest (span, r_e, directivities, the observer-time
        weight) multiply the spectra, and the tip vortex (one station) is stepped whole.
        """
        nr, nrad, naz = (self.options[k] for k in ("num_rotors", "num_radial", "num_azimuth"))
        h = 1.0e-30
        el = self._elements(inputs)
        high, low = self._parts(el)
        total = self._station_energy(el, high, low).sum(axis=1)
        scale = DB_PER_NEPER / (total + SPL_FLOOR)  # d SPL / d energy, (nr, nb)

        # d(h, l)/d(quantity) for the six quantities the spectra depend on.
        spectra = {}
        for key in ("shift", "chord", "speed", "mach", "alpha"):
            value = el[key][..., None] + 1j * h
            if key == "shift":
                value = value + 0.0 * high
            hi, lo = self._parts(el, **{key: value})
            spectra[key] = (np.imag(hi) / h, np.imag(lo) / h)
        hi, lo = self._parts(el, nu=el["nu"] + 1j * h)
        spectra["nu"] = (np.imag(hi) / h, np.imag(lo) / h)

        weight = self._weight(el)
        directed = self._directed(el, high, low)
        blades = self._blades[:, None, None]
        work = {k: np.asarray(v, dtype=complex) for k, v in inputs.items()}
        for name in _ROW_INPUTS + _SHARED_INPUTS + _STATION_INPUTS:
            saved = work[name].copy()
            work[name] = saved + 1j * h
            step = self._elements(work)
            work[name] = saved
            d = {k: np.imag(v) / h for k, v in step.items()}
            d_high = sum(spectra[k][0] * d[k][..., None] for k in spectra if np.any(d[k]))
            d_low = sum(spectra[k][1] * d[k][..., None] for k in spectra if np.any(d[k]))
            d_weight = weight * (
                d["span"] / el["span"] - 2.0 * d["r_e"] / el["r_e"] + d["shift"] / el["shift"]
            )
            dte = d_weight[..., None] * directed + weight[..., None] * (
                self._directed(d, high, low) + self._directed(el, d_high, d_low)
            )
            d_station = dte.sum(axis=2)
            d_station[:, -1, :] = d_station[:, -1, :] + np.imag(self._tip(step)) / h
            d_station = d_station * blades * scale[:, None, :]  # (nr, nrad, nb)
            if name == "chord":
                partials["broadband_spl", name] = d_station.transpose(0, 2, 1).ravel()
            elif name in _STATION_INPUTS:
                # The station's azimuth mean: each load station carries 1/num_azimuth.
                per = np.repeat(d_station.transpose(0, 2, 1)[..., None], naz, axis=3) / naz
                partials["broadband_spl", name] = per.reshape(nr, -1, nrad * naz).ravel()
            else:
                partials["broadband_spl", name] = d_station.sum(axis=1).ravel()
