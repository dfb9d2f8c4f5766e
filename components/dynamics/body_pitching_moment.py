"""Destabilizing pitching moment of the fuselage by Multhopp's strip method."""

import numpy as np
import openmdao.api as om

from lpc_mdo.checks import check_range


def munk_apparent_mass_factor(fineness_ratio):
    """
    Munk's apparent-mass factor k2 - k1 of a prolate spheroid of the given fineness ratio.

    Lamb, *Hydrodynamics* (6th ed., 1932) sec. 373, and Munk, NACA TR 184 (1924): with
    e = sqrt(1 - 1/f^2) and L = ln((1 + e)/(1 - e)),

        alpha0 = 2 (1 - e^2)/e^3 (L/2 - e),   beta0 = 1/e^2 - (1 - e^2)/(2 e^3) L,
        k1 = alpha0/(2 - alpha0),             k2 = beta0/(2 - beta0).

    k2 - k1 is 0 for a sphere and tends to 1 for an infinitely slender body (Raymer,
    *Aircraft Design* 6th ed., Fig. 16.13 plots the same curve).
    """
    f = float(fineness_ratio)
    check_range("fineness_ratio", f, lower=1.0, lower_open=True, where="munk_apparent_mass_factor")
    e = np.sqrt(1.0 - 1.0 / f**2)
    log = np.log((1.0 + e) / (1.0 - e))
    alpha0 = 2.0 * (1.0 - e**2) / e**3 * (0.5 * log - e)
    beta0 = 1.0 / e**2 - (1.0 - e**2) / (2.0 * e**3) * log
    return beta0 / (2.0 - beta0) - alpha0 / (2.0 - alpha0)


def lifting_line_upwash_gradient(x, y, span, wing_area, lift_slope, x_bound, num_vortices=400):
    """
    d(epsilon_up)/dalpha in the wing plane of an elliptically loaded lifting line.

    The lifting line of Prandtl (the model behind Multhopp's upwash chart, NACA TM 1036,
    1942, reproduced in Perkins & Hage, *Airplane Performance, Stability and Control*, 1949,
    Fig. 5-19) is a bound vortex at body x = ``x_bound`` (the wing quarter chord) with the
    elliptic circulation Gamma(y) = Gamma0 sqrt(1 - (2y/b)^2), Gamma0 = 2 V S C_L/(pi b).
    It is discretized in ``num_vortices`` horseshoes
    (Biot-Savart, Katz & Plotkin, *Low-Speed Aerodynamics*, eq. 10.115), whose trailing legs run
    aft (-x). Returns the upwash angle per radian of wing angle of attack, positive up
    (ahead of the wing) and negative (downwash) behind it; far behind on the centre line it
    tends to -2 C_La/(pi A), the classic elliptic far-wake value.

    Parameters
    ----------
    x, y : arrays of the same shape, m (body frame, x forward)
    span : float, m
    wing_area : float, m**2
    lift_slope : float, 1/rad, the wing's C_La referred to the wing area
    x_bound : float, m
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    b = float(span)
    # Horseshoe edges at cosine-spaced stations; strength = jump of Gamma/V per unit C_L.
    theta = np.linspace(0.0, np.pi, num_vortices + 1)
    edges = -0.5 * b * np.cos(theta)
    g_edge = np.sqrt(np.clip(1.0 - (2.0 * edges / b) ** 2, 0.0, None))
    # Horseshoe k spans [edges[k], edges[k+1]] with strength = mean of its edge values.
    gk = 0.5 * (g_edge[:-1] + g_edge[1:])
    # Core radius of each leg: the local vortex spacing (fine near the tips, cosine spacing).
    spacing = np.gradient(edges)
    delta_a, delta_b = spacing[:-1], spacing[1:]
    xi = (x - x_bound)[..., None]  # distance ahead of the bound vortex
    ya = edges[:-1] - y[..., None]  # lateral offsets of the legs (left, right)
    yb = edges[1:] - y[..., None]
    with np.errstate(divide="ignore", invalid="ignore"):
        # Bound segment from ya to yb at xi: upwash ahead (xi > 0).
        bound = (yb / np.hypot(xi, yb) - ya / np.hypot(xi, ya)) / xi
        # Semi-infinite legs aft: downwash between them (ya < 0 < yb), upwash outside.
        # A core of radius delta (the local vortex spacing) regularizes a leg passing close
        # to the field point: 1/h -> h/(h^2 + delta^2) (Scully/Kaufmann-type smoothing).
        left = (1.0 - xi / np.hypot(xi, ya)) * ya / (ya**2 + delta_a**2)
        right = -(1.0 - xi / np.hypot(xi, yb)) * yb / (yb**2 + delta_b**2)
    w_per_gamma = (bound + left + right) / (4.0 * np.pi)
    # Gamma_k/V = (2 S C_L/(pi b)) gk, so w/V per radian of alpha:
    return lift_slope * 2.0 * wing_area / (np.pi * b) * np.sum(gk * w_per_gamma, axis=-1)


def multhopp_flow_gradient(x_stations, y, span, wing_area, lift_slope, x_leading_edge, root_chord):
    """
    Local flow-angle gradient d(beta)/d(alpha) at body strips (Multhopp, NACA TM 1036).

    1 + d(epsilon_up)/dalpha ahead of the wing and 1 - d(epsilon)/dalpha behind it, from
    :func:`lifting_line_upwash_gradient` with the bound vortex at the root quarter chord;
    zero under the root chord (DATCOM 4.2.2.1: the wing carries that part's load).
    """
    x = np.asarray(x_stations, dtype=float)
    grad = 1.0 + lifting_line_upwash_gradient(
        x,
        np.full_like(x, float(y)),
        span,
        wing_area,
        lift_slope,
        x_leading_edge - 0.25 * root_chord,
    )
    under = (x <= x_leading_edge) & (x >= x_leading_edge - root_chord)
    return np.where(under, 0.0, grad)


class FuselagePitchingMomentComp(om.ExplicitComponent):
    """
    Pitching moment of a slender body in the wing's flow field (Munk-Multhopp strip method).

    Multhopp (NACA TM 1036, 1942), as in Perkins & Hage (1949) eq. 5-23, DATCOM 4.2.2.1 and
    Raymer (*Aircraft Design*, 6th ed.) sec. 16.3: the body of strip widths w_i and lengths
    dx_i, at local flow angle beta_i, carries

        M_y = q (pi/2) (k2 - k1) sum_i w_i^2 beta_i dx_i,

    (nose up positive, body y to the right) with Munk's apparent-mass factor k2 - k1
    (:func:`munk_apparent_mass_factor`). The local angle follows the wing's up- and
    downwash: beta_i = alpha + (g_i - 1)(alpha - alpha_0w), g_i = d(beta)/d(alpha) of
    :func:`multhopp_flow_gradient` and alpha_0w the wing's zero-lift angle of attack, so the
    slope is dM/dalpha = q (pi/2)(k2 - k1) sum w_i^2 g_i dx_i. The body's own lift is zero
    in this potential-flow model (Munk), so only the moment is returned.

    Inputs
    ------
    angle_of_attack : (nn,), rad
    density : (nn,), kg/m**3
    speed : (nn,), m/s

    Outputs
    -------
    body_moment : (nn, 3), N*m, about any point (a pure couple)

    Options
    -------
    num_nodes : int
    strip_factor : array
        w_i^2 dx_i per strip, m**3.
    flow_gradient : array
        g_i per strip.
    apparent_mass_factor : float
        k2 - k1.
    wing_zero_lift_angle : float
        alpha_0w, rad.
    """

    def initialize(self):
        self.options.declare("num_nodes", default=1, types=int, lower=1)
        self.options.declare("strip_factor", types=np.ndarray, desc="w^2 dx per strip, m**3")
        self.options.declare("flow_gradient", types=np.ndarray, desc="dbeta/dalpha per strip")
        self.options.declare("apparent_mass_factor", types=float, desc="k2 - k1")
        self.options.declare("wing_zero_lift_angle", default=0.0, types=float, desc="rad")

    def setup(self):
        nn = self.options["num_nodes"]
        check_range(
            "apparent_mass_factor",
            self.options["apparent_mass_factor"],
            lower=0.0,
            upper=1.0,
            where=self.msginfo,
        )
        self.add_input("angle_of_attack", np.zeros(nn), units="rad", desc="angle of attack")
        self.add_input("density", np.full(nn, 1.225), units="kg/m**3", desc="air density")
        self.add_input("speed", np.zeros(nn), units="m/s", desc="airspeed")
        self.add_output("body_moment", np.zeros((nn, 3)), units="N*m", desc="body couple")
        ar = np.arange(nn)
        for name in ("angle_of_attack", "density", "speed"):
            self.declare_partials("body_moment", name, rows=3 * ar + 1, cols=ar)
        k = self.options["apparent_mass_factor"]
        sw = self.options["strip_factor"]
        g = self.options["flow_gradient"]
        self._slope = 0.5 * np.pi * k * np.sum(sw * g)  # dM/(q dalpha), m**3
        self._offset = (
            -0.5 * np.pi * k * np.sum(sw * (g - 1.0)) * self.options["wing_zero_lift_angle"]
        )

    def compute(self, inputs, outputs):
        q = 0.5 * inputs["density"] * inputs["speed"] ** 2
        outputs["body_moment"] = 0.0 * q[:, None]
        outputs["body_moment"][:, 1] = q * (self._slope * inputs["angle_of_attack"] + self._offset)

    def compute_partials(self, inputs, partials):
        rho, v, a = inputs["density"], inputs["speed"], inputs["angle_of_attack"]
        m_per_q = self._slope * a + self._offset
        partials["body_moment", "angle_of_attack"] = 0.5 * rho * v**2 * self._slope
        partials["body_moment", "density"] = 0.5 * v**2 * m_per_q
        partials["body_moment", "speed"] = rho * v * m_per_q


def fuselage_strips(length, max_width, num_strips=40):
    """
    Strip stations (body x, nose at 0, aft negative), widths and w^2 dx of the fuselage.

    The vehicle file gives only length and maximum width, so the planform is taken as the
    ellipse w(x) = w_max sqrt(1 - (1 + 2x/L)^2) (assumption: the spheroid of the same length
    and width, the body for which k2 - k1 is exact; it has pi/4 of a box's w^2 integral).
    """
    edges = np.linspace(0.0, -float(length), num_strips + 1)
    xc = 0.5 * (edges[:-1] + edges[1:])
    dx = -np.diff(edges)
    w = max_width * np.sqrt(np.clip(1.0 - (1.0 + 2.0 * xc / length) ** 2, 0.0, None))
    return xc, w, w**2 * dx


def wing_lift_slope(aspect_ratio, sweep, eta=0.95):
    """
    Subsonic wing lift-curve slope, 1/rad (DATCOM 4.1.3.2 / Raymer eq. 12.6, M = 0, F = 1).

    C_La = 2 pi A / (2 + sqrt(4 + A^2/eta^2 (1 + tan^2 Lambda))), eta = 0.95 the section's
    lift slope over 2 pi (Raymer sec. 12.4).
    """
    a = float(aspect_ratio)
    return 2.0 * np.pi * a / (2.0 + np.sqrt(4.0 + a**2 / eta**2 * (1.0 + np.tan(sweep) ** 2)))


def fuselage_pitching_moment_options(vehicle, wing_zero_lift_angle, num_strips=40):
    """
    Options of :class:`FuselagePitchingMomentComp` for a vehicle (fixed at setup).

    Fuselage strips from :func:`fuselage_strips`; the wing's flow field from its file
    planform (area, aspect ratio, LE sweep, root leading edge and the trapezoid root chord)
    and :func:`wing_lift_slope`; alpha_0w = (sectional zero-lift angle) - (root incidence).
    The options do not follow wing or fuselage design variables (they are set from the file).
    """
    wing, fus = vehicle.wing, vehicle.fuselage
    xc, _, strip = fuselage_strips(fus.length, fus.max_width, num_strips)
    grad = multhopp_flow_gradient(
        xc,
        0.0,
        wing.span,
        wing.area,
        wing_lift_slope(wing.aspect_ratio, wing.sweep),
        wing.root_leading_edge[0],
        wing.root_chord,
    )
    return {
        "strip_factor": strip,
        "flow_gradient": grad,
        "apparent_mass_factor": float(munk_apparent_mass_factor(fus.length / fus.max_width)),
        "wing_zero_lift_angle": float(wing_zero_lift_angle) - float(wing.incidence),
    }
