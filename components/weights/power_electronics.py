"""Inverter and motor-cable masses from each motor's current rating and cable run."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range

#: Copper density, kg/m**3 (annealed copper, IACS).
COPPER_DENSITY = 8890.0
#: AWG 0000 of FAA AC 43.13-1B CHG 1, Table 11-9 (current-carrying capacity and resistance of
#: copper wire): nominal conductor area 210,900 circular mils (106.87 mm**2) and continuous duty
#: current 395 A for 200 deg C conductor rating (wires in bundles, 70 deg C ambient).
AWG_0000_AREA = 210900.0 * 5.067075e-10  # circular mils to m**2
AWG_0000_CURRENT = 395.0
#: Conductor mass per ampere of continuous current and metre of run, kg/(A m): the AWG 0000
#: wire above, the largest gauge of the table (heavier currents run as parallel 0000 wires, so
#: the mass per ampere-metre stays that of 0000). Copper only (insulation not counted).
CABLE_MASS_PER_AMPERE_METRE = COPPER_DENSITY * AWG_0000_AREA / AWG_0000_CURRENT


def smooth_abs(x, width):
    """sqrt(x**2 + w**2): abs(x) to within w (smooth at 0), and its derivative."""
    value = np.sqrt(x * x + width * width)
    return value, x / value


class PowerElectronicsMassComp(om.ExplicitComponent):
    """
    Masses of the motor drives: one inverter per motor and its three-phase cable run.

    See docs theory/weights 'Power electronics and cables'. Each motor j has its inverter at the
    power-electronics station x_s (the vehicle file's ``masses.power_electronics_cg``) and a
    cable of ``phases`` conductors from there to the motor:

    - inverter rating S_j = (m/2) V_lim I_pk,j, the apparent power of m phases at the phase
      voltage amplitude limit V_lim and the phase-current amplitude I_pk,j the motor draws at
      its peak torque (the motor's current limit, ``motor_peak_current``); inverter mass
      S_j/p_inv with the specific power p_inv (option ``inverter_specific_power``);
    - cable run length l_j = sum over x, y, z of sqrt((x_j - x_s)**2 + w**2): a rectilinear route
      (along the fuselage, then spanwise, then vertically), each leg abs(.) smoothed with w
      (option ``routing_width``, 0.01 m: at most w longer per leg);
    - cable mass m l_j mu I_pk,j/sqrt(2): each phase conductor sized for the rms of the peak
      current as a continuous rating, with mu the conductor mass per ampere-metre (option
      ``cable_mass_per_ampere_metre``, default :data:`CABLE_MASS_PER_AMPERE_METRE` from FAA AC
      43.13-1B Table 11-9);
    - cable cg: the length-weighted centroid of the three legs.

    Partials: analytic (masses linear in the current; the cg a ratio of smooth sums).

    Inputs
    ------
    peak_current : float, (num_motors,), A
        Phase-current amplitude at each motor's peak torque (> 0).
    motor_cg : float, (num_motors, 3), m
        Motor positions (the cable ends), body frame.
    inverter_station : float, (3,), m
        Power-electronics station (the inverters and the cable starts), body frame.

    Outputs
    -------
    inverter_mass : float, (num_motors,), kg
        Mass of each motor's inverter.
    power_electronics_mass : float, (1,), kg
        Sum of the inverter masses (at the station).
    power_cable_length : float, (num_motors,), m
        Length of each cable run.
    power_cable_mass : float, (num_motors,), kg
        Mass of each motor's cable (its ``phases`` conductors).
    power_cable_cg : float, (num_motors, 3), m
        Centroid of each cable run.

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 9.
    phases : int
        Motor phases m, the conductors per cable (>= 1). Default 3.
    voltage_limit : float
        Phase-voltage amplitude limit V_lim of the motors, V (> 0). Default 400.
    inverter_specific_power : float
        Inverter rating per mass p_inv, W/kg (> 0). Default 19e3.
    cable_mass_per_ampere_metre : float
        Conductor mass mu, kg/(A m) (> 0). Default :data:`CABLE_MASS_PER_AMPERE_METRE`.
    routing_width : float
        w of the smoothed leg lengths, m (> 0). Default 0.01.

    Raises
    ------
    om.AnalysisError
        If a peak current is not > 0.
    """

    def initialize(self):
        self.options.declare("num_motors", default=9, types=int, lower=1, desc="number of motors")
        self.options.declare("phases", default=3, types=int, lower=1, desc="motor phases")
        self.options.declare(
            "voltage_limit",
            default=400.0,
            types=(int, float),
            lower=1e-9,
            desc="phase-voltage amplitude limit, V",
        )
        self.options.declare(
            "inverter_specific_power",
            default=19.0e3,
            types=(int, float),
            lower=1e-9,
            desc="inverter rating per mass, W/kg",
        )
        self.options.declare(
            "cable_mass_per_ampere_metre",
            default=CABLE_MASS_PER_AMPERE_METRE,
            types=(int, float),
            lower=1e-12,
            desc="conductor mass per ampere and metre, kg/(A m)",
        )
        self.options.declare(
            "routing_width",
            default=0.01,
            types=(int, float),
            lower=1e-9,
            desc="smoothing width of the leg lengths, m",
        )

    def setup(self):
        n = self.options["num_motors"]
        self.add_input("peak_current", 300.0 * np.ones(n), units="A", desc="current rating")
        self.add_input("motor_cg", np.zeros((n, 3)), units="m", desc="motor positions")
        self.add_input("inverter_station", np.zeros(3), units="m", desc="inverter station")
        self.add_output("inverter_mass", np.ones(n), units="kg", desc="inverter of each motor")
        self.add_output("power_electronics_mass", 1.0, units="kg", desc="all inverters")
        self.add_output("power_cable_length", np.ones(n), units="m", desc="cable run lengths")
        self.add_output("power_cable_mass", np.ones(n), units="kg", desc="cable of each motor")
        self.add_output("power_cable_cg", np.zeros((n, 3)), units="m", desc="cable centroids")

        rows = np.arange(n)
        self.declare_partials("inverter_mass", "peak_current", rows=rows, cols=rows)
        self.declare_partials("power_electronics_mass", "peak_current")
        self.declare_partials("power_cable_mass", "peak_current", rows=rows, cols=rows)
        rows3 = np.repeat(rows, 3)
        cols3 = np.arange(3 * n)
        for of in ("power_cable_length", "power_cable_mass"):
            self.declare_partials(of, "motor_cg", rows=rows3, cols=cols3)
            self.declare_partials(of, "inverter_station", rows=rows3, cols=np.tile(np.arange(3), n))
        # cg (n, 3) depends on the motor's own three coordinates and on the station.
        rows9 = np.repeat(np.arange(3 * n), 3)
        cols9 = (3 * np.repeat(rows, 9) + np.tile(np.arange(3), 3 * n)).astype(int)
        self.declare_partials("power_cable_cg", "motor_cg", rows=rows9, cols=cols9)
        self.declare_partials(
            "power_cable_cg", "inverter_station", rows=rows9, cols=np.tile(np.arange(3), 3 * n)
        )

    def _inverter_per_ampere(self):
        opt = self.options
        return 0.5 * opt["phases"] * opt["voltage_limit"] / opt["inverter_specific_power"]

    def _cable_per_ampere_metre(self):
        opt = self.options
        return opt["phases"] * opt["cable_mass_per_ampere_metre"] / np.sqrt(2.0)

    def _legs(self, inputs):
        """Leg lengths (n, 3), their slopes, and the leg centroids (n, 3 legs, 3 coords)."""
        motor, station = inputs["motor_cg"], inputs["inverter_station"]
        delta = motor - station
        legs, slopes = smooth_abs(delta, self.options["routing_width"])
        # Leg k runs along axis k: coordinates before it are the motor's, after it the station's.
        n = motor.shape[0]
        centroids = np.empty((n, 3, 3), dtype=motor.dtype)
        for k in range(3):  # three legs: a fixed loop over the axes, not over motors
            centroids[:, k, :k] = motor[:, :k]
            centroids[:, k, k] = 0.5 * (motor[:, k] + station[k])
            centroids[:, k, k + 1 :] = station[k + 1 :]
        return legs, slopes, centroids

    def compute(self, inputs, outputs):
        current = inputs["peak_current"]
        check_range(
            "peak_current",
            current,
            lower=0.0,
            lower_open=True,
            units="A",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        legs, _, centroids = self._legs(inputs)
        length = legs.sum(axis=1)
        outputs["inverter_mass"] = self._inverter_per_ampere() * current
        outputs["power_electronics_mass"] = np.sum(outputs["inverter_mass"])
        outputs["power_cable_length"] = length
        outputs["power_cable_mass"] = self._cable_per_ampere_metre() * length * current
        outputs["power_cable_cg"] = np.einsum("nk,nkc->nc", legs, centroids) / length[:, None]

    def compute_partials(self, inputs, partials):
        current = inputs["peak_current"]
        n = current.size
        legs, slopes, centroids = self._legs(inputs)
        length = legs.sum(axis=1)
        k_inv, k_cable = self._inverter_per_ampere(), self._cable_per_ampere_metre()
        partials["inverter_mass", "peak_current"] = np.full(n, k_inv)
        partials["power_electronics_mass", "peak_current"] = np.full((1, n), k_inv)
        partials["power_cable_mass", "peak_current"] = k_cable * length
        # d(length)/d(motor_cg) = slopes; d/d(station) = -slopes.
        partials["power_cable_length", "motor_cg"] = slopes.ravel()
        partials["power_cable_length", "inverter_station"] = -slopes.ravel()
        partials["power_cable_mass", "motor_cg"] = (k_cable * current[:, None] * slopes).ravel()
        partials["power_cable_mass", "inverter_station"] = (
            -k_cable * current[:, None] * slopes
        ).ravel()

        # cg_c = sum_k legs_k centroid_kc / length. Partials by motor coordinate j and station
        # coordinate j: legs_j moves with it (slope), and the centroids move: centroid_kc by
        # motor_j is 1 for c = j < k, 1/2 for c = j = k; by station_j 1 for c = j > k, 1/2 for
        # c = j = k.
        cg = np.einsum("nk,nkc->nc", legs, centroids) / length[:, None]
        d_motor = np.zeros((n, 3, 3))  # [n, c, j]
        d_station = np.zeros((n, 3, 3))
        for j in range(3):  # fixed loop over the three coordinates
            # Through leg j's length.
            d_len = slopes[:, j]
            d_motor[:, :, j] += d_len[:, None] * (centroids[:, j, :] - cg) / length[:, None]
            d_station[:, :, j] -= d_len[:, None] * (centroids[:, j, :] - cg) / length[:, None]
            # Through the centroids (coordinate c = j of the legs).
            for k in range(3):
                if j < k:
                    d_motor[:, j, j] += legs[:, k] / length
                elif j == k:
                    d_motor[:, j, j] += 0.5 * legs[:, k] / length
                    d_station[:, j, j] += 0.5 * legs[:, k] / length
                else:
                    d_station[:, j, j] += legs[:, k] / length
        partials["power_cable_cg", "motor_cg"] = d_motor.ravel()
        partials["power_cable_cg", "inverter_station"] = d_station.ravel()
