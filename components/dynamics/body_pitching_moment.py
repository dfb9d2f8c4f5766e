"""Destabilizing pitching moment of the fuselage and the booms by Multhopp's strip method."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.drag_buildup import LPC_BOOM_DIAMETER
from lpc_mdo.core.checks import check_range


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
    f = fineness_ratio  # complex-safe (BodyMomentSlopeComp differentiates by complex step)
    check_range(
        "fineness_ratio",
        float(np.real(f)),
        lower=1.0,
        lower_open=True,
        where="munk_apparent_mass_factor",
    )
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
    # Gamma_k/V = (2 S C_L/(pi b)) gk, so w/V per radian of alpha:
    prefactor = lift_slope * 2.0 * wing_area / (np.pi * span)
    return prefactor * elliptic_wake_kernel(np.asarray(x) - x_bound, y, span, num_vortices)


def elliptic_wake_kernel(xi, y, span, num_vortices=400):
    """
    Geometric part of :func:`lifting_line_upwash_gradient`: sum_k g_k w_k at (xi, y).

    w_k is the upwash of horseshoe k of unit strength (positive up), g_k its share of the
    elliptic circulation, xi the distance ahead of the bound vortex; the upwash gradient is
    C_La 2 S/(pi b) times this. Pointwise in the field points (complex-safe in ``xi`` and
    ``span``), so one complex step of all ``xi`` gives every point's derivative.
    """
    xi = np.asarray(xi)
    y = np.asarray(y)
    b = span
    # Horseshoe edges at cosine-spaced stations; strength = jump of Gamma/V per unit C_L.
    theta = np.linspace(0.0, np.pi, num_vortices + 1)
    edges = -0.5 * b * np.cos(theta)
    g_edge = np.sin(theta)  # sqrt(1 - (2 y/b)^2) at y = -(b/2) cos(theta)
    # Horseshoe k spans [edges[k], edges[k+1]] with strength = mean of its edge values.
    gk = 0.5 * (g_edge[:-1] + g_edge[1:])
    # Core radius of each leg: the local vortex spacing (fine near the tips, cosine spacing).
    spacing = np.gradient(edges)
    delta_a, delta_b = spacing[:-1], spacing[1:]
    xi = xi[..., None]  # distance ahead of the bound vortex
    ya = edges[:-1] - y[..., None]  # lateral offsets of the legs (left, right)
    yb = edges[1:] - y[..., None]
    with np.errstate(divide="ignore", invalid="ignore"):
        # Bound segment from ya to yb at xi: upwash ahead (xi > 0).
        # sqrt(a^2 + b^2) rather than hypot: complex-safe for the complex-step derivatives.
        ra, rb = np.sqrt(xi**2 + ya**2), np.sqrt(xi**2 + yb**2)
        bound = (yb / rb - ya / ra) / xi
        # Semi-infinite legs aft: downwash between them (ya < 0 < yb), upwash outside.
        # A core of radius delta (the local vortex spacing) regularizes a leg passing close
        # to the field point: 1/h -> h/(h^2 + delta^2) (Scully/Kaufmann-type smoothing).
        left = (1.0 - xi / ra) * ya / (ya**2 + delta_a**2)
        right = -(1.0 - xi / rb) * yb / (yb**2 + delta_b**2)
    w_per_gamma = (bound + left + right) / (4.0 * np.pi)
    return np.sum(gk * w_per_gamma, axis=-1)


def multhopp_flow_gradient(x_stations, y, span, wing_area, lift_slope, x_leading_edge, root_chord):
    """
    Local flow-angle gradient d(beta)/d(alpha) at body strips (Multhopp, NACA TM 1036).

    1 + d(epsilon_up)/dalpha ahead of the wing and 1 - d(epsilon)/dalpha behind it, from
    :func:`lifting_line_upwash_gradient` with the bound vortex at the root quarter chord;
    zero under the root chord (DATCOM 4.2.2.1: the wing carries that part's load).
    """
    x = np.asarray(x_stations)
    grad = 1.0 + lifting_line_upwash_gradient(
        x,
        np.full(x.shape, y),
        span,
        wing_area,
        lift_slope,
        x_leading_edge - 0.25 * root_chord,
    )
    xr, le, c = np.real(x), np.real(x_leading_edge), np.real(root_chord)
    under = (xr <= le) & (xr >= le - c)
    return np.where(under, 0.0, grad)


class BodyPitchingMomentComp(om.ExplicitComponent):
    """
    Pitching moment of the slender bodies (fuselage, booms) in the wing's flow field.

    Multhopp's strip method (NACA TM 1036, 1942), as in Perkins & Hage (1949) eq. 5-23,
    DATCOM 4.2.2.1 and Raymer (*Aircraft Design*, 6th ed.) sec. 16.3: a body of strip widths
    w_i and lengths dx_i, at local flow angle beta_i, carries

        M_y = q (pi/2) (k2 - k1) sum_i w_i^2 beta_i dx_i,

    (nose up positive, body y to the right) with Munk's apparent-mass factor k2 - k1
    (:func:`munk_apparent_mass_factor`). The local angle follows the wing's up- and
    downwash: beta_i = alpha + (g_i - 1)(alpha - alpha_0w), g_i = d(beta)/d(alpha) of
    :func:`multhopp_flow_gradient` and alpha_0w the wing's zero-lift angle of attack. With the
    design-dependent sums of :class:`BodyMomentSlopeComp`, S_b = (pi/2)(k2 - k1) sum w^2 g dx
    and Z_b = (pi/2)(k2 - k1) sum w^2 (g - 1) dx per body b,

        M_y = q sum_b (S_b alpha - Z_b alpha_0w).

    The bodies' own lift is zero in this potential-flow model (Munk), so only the moment is
    returned.

    Inputs
    ------
    angle_of_attack : (nn,), rad
    density : (nn,), kg/m**3
    speed : (nn,), m/s
    body_moment_slope : (nb,), m**3
        S_b, one per body.
    body_moment_zero_lift : (nb,), m**3
        Z_b, one per body.

    Outputs
    -------
    body_moment : (nn, 3), N*m, about any point (a pure couple)

    Options
    -------
    num_nodes : int
    num_bodies : int
    wing_zero_lift_angle : float
        alpha_0w, rad.
    """

    def initialize(self):
        self.options.declare("num_nodes", default=1, types=int, lower=1)
        self.options.declare("num_bodies", default=2, types=int, lower=1)
        self.options.declare("wing_zero_lift_angle", default=0.0, types=float, desc="rad")

    def setup(self):
        nn, nb = self.options["num_nodes"], self.options["num_bodies"]
        self.add_input("angle_of_attack", np.zeros(nn), units="rad", desc="angle of attack")
        self.add_input("density", np.full(nn, 1.225), units="kg/m**3", desc="air density")
        self.add_input("speed", np.zeros(nn), units="m/s", desc="airspeed")
        self.add_input(
            "body_moment_slope", np.zeros(nb), units="m**3", desc="dM/(q dalpha) per body"
        )
        self.add_input(
            "body_moment_zero_lift",
            np.zeros(nb),
            units="m**3",
            desc="(pi/2)(k2-k1) sum w^2 (g-1) dx per body",
        )
        self.add_output("body_moment", np.zeros((nn, 3)), units="N*m", desc="body couple")
        ar = np.arange(nn)
        for name in ("angle_of_attack", "density", "speed"):
            self.declare_partials("body_moment", name, rows=3 * ar + 1, cols=ar)
        rows = np.repeat(3 * ar + 1, nb)
        cols = np.tile(np.arange(nb), nn)
        for name in ("body_moment_slope", "body_moment_zero_lift"):
            self.declare_partials("body_moment", name, rows=rows, cols=cols)

    def _per_q(self, inputs):
        slope = np.sum(inputs["body_moment_slope"])
        offset = -np.sum(inputs["body_moment_zero_lift"]) * self.options["wing_zero_lift_angle"]
        return slope, slope * inputs["angle_of_attack"] + offset

    def compute(self, inputs, outputs):
        q = 0.5 * inputs["density"] * inputs["speed"] ** 2
        outputs["body_moment"] = 0.0 * q[:, None]
        outputs["body_moment"][:, 1] = q * self._per_q(inputs)[1]

    def compute_partials(self, inputs, partials):
        rho, v, a = inputs["density"], inputs["speed"], inputs["angle_of_attack"]
        nb = self.options["num_bodies"]
        q = 0.5 * rho * v**2
        slope, m_per_q = self._per_q(inputs)
        partials["body_moment", "angle_of_attack"] = q * slope
        partials["body_moment", "density"] = 0.5 * v**2 * m_per_q
        partials["body_moment", "speed"] = rho * v * m_per_q
        partials["body_moment", "body_moment_slope"] = np.repeat(q * a, nb)
        partials["body_moment", "body_moment_zero_lift"] = np.repeat(
            -q * self.options["wing_zero_lift_angle"], nb
        )


class BodyMomentSlopeComp(om.ExplicitComponent):
    """
    Multhopp sums of the fuselage and the booms for the current wing and fuselage design.

    For each body b (0 the fuselage, 1 the booms together):
    S_b = (pi/2)(k2 - k1)_b sum_i w_i^2 g_i dx_i and Z_b = (pi/2)(k2 - k1)_b sum_i w_i^2
    (g_i - 1) dx_i, the inputs of :class:`BodyPitchingMomentComp`.

    - Fuselage: the ellipse strips of :func:`fuselage_strips` over the current
      ``fuselage_length`` (stations and strip lengths scale with it; the widths follow
      ``fuselage_max_width``), k2 - k1 of the spheroid of fineness L/w_max.
    - Booms: each boom line a cylinder of diameter d from the front to the rear lift-rotor hub
      at its span station (:func:`boom_strips`), k2 - k1 of the spheroid of its fineness (a
      cylinder's is not tabulated: assumption). The boom strips, their stations and the strips
      under the wing are fixed from the vehicle file (booms move little with the design).
    - Flow gradient g_i: :func:`multhopp_flow_gradient` of the current wing (``wing_area``,
      ``wing_span``, ``wing_root_chord``; lift slope of :func:`wing_lift_slope` at the current
      aspect ratio b^2/S and the file's sweep), zero under the wing.

    Partials: the chain rule through the lifting line's geometric kernel
    (:func:`elliptic_wake_kernel`), whose derivatives with respect to the points' distance from
    the bound vortex and the span come from two vectorized complex steps (exact to round-off).

    Inputs
    ------
    fuselage_length : scalar, m
    wing_area : scalar, m**2
    wing_span : scalar, m
    wing_root_chord : scalar, m

    Outputs
    -------
    body_moment_slope : (2,), m**3
    body_moment_zero_lift : (2,), m**3

    Options
    -------
    fuselage_max_width : float, m
    wing_sweep : float, rad (leading edge, whole wing)
    wing_root_leading_edge_x : float, m
    boom_x, boom_y, boom_strip_factor, boom_flow_mask : arrays (see :func:`boom_strips`)
    boom_apparent_mass_factor : float
    num_strips : int (fuselage strips)
    """

    _INPUTS = ("fuselage_length", "wing_area", "wing_span", "wing_root_chord")

    def initialize(self):
        self.options.declare("fuselage_max_width", types=float, desc="m")
        self.options.declare("wing_sweep", types=float, desc="LE sweep, rad")
        self.options.declare("wing_root_leading_edge_x", types=float, desc="m")
        self.options.declare("boom_x", types=np.ndarray, desc="strip stations, m")
        self.options.declare("boom_y", types=np.ndarray, desc="strip span stations, m")
        self.options.declare("boom_strip_factor", types=np.ndarray, desc="w^2 dx, m**3")
        self.options.declare("boom_flow_mask", types=np.ndarray, desc="0 under the wing, else 1")
        self.options.declare("boom_apparent_mass_factor", types=float, desc="k2 - k1")
        self.options.declare("num_strips", default=40, types=int, lower=4)

    def setup(self):
        for name, units, value in zip(
            self._INPUTS, ("m", "m**2", "m", "m"), (9.144, 19.6, 15.41, 1.66), strict=True
        ):
            self.add_input(name, value, units=units)
        self.add_output("body_moment_slope", np.zeros(2), units="m**3")
        self.add_output("body_moment_zero_lift", np.zeros(2), units="m**3")
        for out in ("body_moment_slope", "body_moment_zero_lift"):
            self.declare_partials(out, self._INPUTS)

    def _points(self, length, root_chord):
        """Fuselage parts outside the root chord (:func:`fuselage_wing_split`), then the booms."""
        o = self.options
        le = o["wing_root_leading_edge_x"]
        split = fuselage_wing_split(
            length, o["fuselage_max_width"], le, root_chord, o["num_strips"]
        )
        x = np.concatenate([split["front_x"], split["rear_x"], o["boom_x"]])
        y = np.concatenate([np.zeros(2 * o["num_strips"]), o["boom_y"]])
        return split, x - (le - 0.25 * root_chord), y

    def _prefactor(self, area, span):
        """C_La 2 S/(pi b): the lifting line's upwash per unit kernel value."""
        cla = wing_lift_slope(span**2 / area, self.options["wing_sweep"])
        return cla * 2.0 * area / (np.pi * span)

    def _munk(self, length):
        return 0.5 * np.pi * munk_apparent_mass_factor(length / self.options["fuselage_max_width"])

    def compute(self, inputs, outputs):
        length, area, span, root_chord = (inputs[n][0] for n in self._INPUTS)
        o = self.options
        n = o["num_strips"]
        split, xi, y = self._points(length, root_chord)
        g = 1.0 + self._prefactor(area, span) * elliptic_wake_kernel(xi, y, span)
        # Fuselage: the parts outside the root chord at g of their centroids; the part under
        # it has g = 0 (no slope; beta = alpha_0w there, so -1 in the zero-lift sum).
        w2 = split["width_squared"]
        slope_f = np.sum(w2 * (split["front_length"] * g[:n] + split["rear_length"] * g[n : 2 * n]))
        k_f = self._munk(length)
        # Booms: strip centres, the file's mask (see boom_strips).
        k_b = 0.5 * np.pi * o["boom_apparent_mass_factor"]
        sb = o["boom_strip_factor"]
        g_b = g[2 * n :] * o["boom_flow_mask"]
        outputs["body_moment_slope"] = [k_f * slope_f, k_b * np.sum(sb * g_b)]
        outputs["body_moment_zero_lift"] = [
            k_f * (slope_f - np.sum(w2) * length / n),
            k_b * np.sum(sb * (g_b - 1.0)),
        ]

    def compute_partials(self, inputs, partials):
        # Fuselage: A = sum_i w_i^2 (l_f g(x_f) + l_r g(x_r)) over the parts outside the root
        # chord (lengths l, centroids x), S_f = k_f(L) A and Z_f = k_f (A - sum w^2 L/n)
        # (the parts' own lengths cancel against the part under the chord); g = 1 + P(S, b)
        # W(xi, y, b) with P = C_La(b^2/S) 2 S/(pi b) and W the lifting line's geometric kernel
        # at xi = x - (x_le - c/4). W is pointwise in the points, so two complex evaluations (all
        # xi at once, then b) give every derivative; P and k_f by their own complex steps.
        o = self.options
        length, area, span, root_chord = (inputs[n][0] for n in self._INPUTS)
        h = 1e-30
        n = o["num_strips"]
        split, xi, y = self._points(length, root_chord)
        w_xi = elliptic_wake_kernel(xi + 1j * h, y, span)
        w = w_xi.real
        dw_dxi = w_xi.imag / h
        dw_db = elliptic_wake_kernel(xi, y, span + 1j * h).imag / h
        p = self._prefactor(area, span)
        dp_ds = self._prefactor(area + 1j * h, span).imag / h
        dp_db = self._prefactor(area, span + 1j * h).imag / h
        k_f, dk_dl = self._munk(length), self._munk(length + 1j * h).imag / h
        g = 1.0 + p * w
        fus = slice(0, 2 * n)
        w2 = np.tile(split["width_squared"], 2)
        lengths = np.concatenate([split["front_length"], split["rear_length"]])
        nb = xi.size - 2 * n
        # d(xi)/d(L) and d(xi)/d(c) of every point; d(part length)/d(L), d(c).
        dxi_dl = np.concatenate([split["front_dx_dlength"], split["rear_dx_dlength"], np.zeros(nb)])
        dxi_dc = 0.25 + np.concatenate([np.zeros(n), split["rear_dx_dchord"], np.zeros(nb)])
        dlen = {
            "fuselage_length": np.concatenate(
                [split["front_dlength_dlength"], split["rear_dlength_dlength"]]
            ),
            "wing_root_chord": np.concatenate([np.zeros(n), split["rear_dlength_dchord"]]),
        }
        dg = {
            "wing_area": dp_ds * w,
            "wing_span": dp_db * w + p * dw_db,
            "wing_root_chord": p * dw_dxi * dxi_dc,
            "fuselage_length": p * dw_dxi * dxi_dl,
        }
        k_b = 0.5 * np.pi * o["boom_apparent_mass_factor"]
        boom_weight = k_b * o["boom_strip_factor"] * o["boom_flow_mask"]
        slope_f = np.sum(w2 * lengths * g[fus])
        for name, d in dg.items():
            d_fus = np.sum(w2 * (lengths * d[fus] + dlen.get(name, 0.0) * g[fus]))
            d_boom = np.sum(boom_weight * d[2 * n :])
            d_slope = np.array([k_f * d_fus, d_boom])
            d_zero = d_slope.copy()
            if name == "fuselage_length":
                # k_f(L), and the whole strips' sum w^2 L/n of the zero-lift part.
                d_slope[0] += dk_dl * slope_f
                total = np.sum(split["width_squared"]) / n
                d_zero[0] += dk_dl * (slope_f - total * length) - k_f * total
            partials["body_moment_slope", name] = d_slope
            partials["body_moment_zero_lift", name] = d_zero


def fuselage_wing_split(length, max_width, wing_leading_edge_x, root_chord, num_strips=40):
    """
    Split the strips of :func:`fuselage_strips` where the wing's root chord covers them.

    Strip i spans x in [-(i+1) L/n, -i L/n]; the root chord covers [x_le - c, x_le], where the
    wing carries the load (DATCOM 4.2.2.1). Each strip's part ahead of the chord ("front") and
    behind it ("rear") enters the strip sums with its exact length at its own centroid (the
    midpoint rule on the part), so the sums are continuous in L and c where a chord edge
    crosses a strip; an empty part has length 0 and its centroid on the chord's edge.

    Returns
    -------
    dict
        ``width_squared`` (n,), m**2; for ``front`` and ``rear``: ``_length`` and ``_x``
        (centroid) in m, their derivatives ``_dlength_dlength``, ``_dx_dlength`` (d/dL) and, for
        the rear part, ``_dlength_dchord`` and ``_dx_dchord`` (d/dc; the front part does not
        depend on c).
    """
    n = num_strips
    i = np.arange(n)
    _, width, _ = fuselage_strips(length, max_width, n)
    top, bottom = -length * i / n, -length * (i + 1) / n
    dtop, dbottom = -i / n, -(i + 1) / n
    le, lo = wing_leading_edge_x, wing_leading_edge_x - root_chord
    # Ahead of the chord: [max(bottom, le), top].
    start = np.maximum(bottom, le)
    dstart = np.where(bottom > le, dbottom, 0.0)
    front = top > start
    front_len = np.where(front, top - start, 0.0)
    front_x = np.where(front, 0.5 * (start + top), le)
    # Behind it: [bottom, min(top, le - c)].
    end = np.minimum(top, lo)
    end_dl, end_dc = np.where(top < lo, dtop, 0.0), np.where(top < lo, 0.0, -1.0)
    rear = end > bottom
    rear_len = np.where(rear, end - bottom, 0.0)
    rear_x = np.where(rear, 0.5 * (bottom + end), lo)
    return {
        "width_squared": width**2,
        "front_length": front_len,
        "front_x": front_x,
        "front_dlength_dlength": np.where(front, dtop - dstart, 0.0),
        "front_dx_dlength": np.where(front, 0.5 * (dstart + dtop), 0.0),
        "rear_length": rear_len,
        "rear_x": rear_x,
        "rear_dlength_dlength": np.where(rear, end_dl - dbottom, 0.0),
        "rear_dx_dlength": np.where(rear, 0.5 * (dbottom + end_dl), 0.0),
        "rear_dlength_dchord": np.where(rear, end_dc, 0.0),
        "rear_dx_dchord": np.where(rear, 0.5 * end_dc, -1.0),
    }


def fuselage_strips(length, max_width, num_strips=40):
    """
    Strip stations (body x, nose at 0, aft negative), widths and w^2 dx of the fuselage.

    The vehicle file gives only length and maximum width, so the planform is taken as the
    ellipse w(x) = w_max sqrt(1 - (1 + 2x/L)^2) (assumption: the spheroid of the same length
    and width, the body for which k2 - k1 is exact; it has pi/4 of a box's w^2 integral).
    Equal strips: the widths do not depend on L, the stations and w^2 dx scale with it
    (complex-safe in ``length``).
    """
    fraction = (np.arange(num_strips) + 0.5) / num_strips  # strip centres, x = -fraction L
    xc = -length * fraction
    w = max_width * np.sqrt(np.clip(1.0 - (1.0 - 2.0 * fraction) ** 2, 0.0, None))
    return xc, w, w**2 * (length / num_strips)


def wing_lift_slope(aspect_ratio, sweep, eta=0.95):
    """
    Subsonic wing lift-curve slope, 1/rad (DATCOM 4.1.3.2 / Raymer eq. 12.6, M = 0, F = 1).

    C_La = 2 pi A / (2 + sqrt(4 + A^2/eta^2 (1 + tan^2 Lambda))), eta = 0.95 the section's
    lift slope over 2 pi (Raymer sec. 12.4).
    """
    a = aspect_ratio  # complex-safe
    return 2.0 * np.pi * a / (2.0 + np.sqrt(4.0 + a**2 / eta**2 * (1.0 + np.tan(sweep) ** 2)))


def boom_strips(vehicle, num_strips=20, diameter=None):
    """
    Return the strips of a vehicle's booms, one boom line per distinct span station.

    Each boom line is a cylinder of diameter ``diameter`` (default the drag build-up's
    ``LPC_BOOM_DIAMETER``, 1 ft) from the most forward to the most aft lift-rotor hub at the
    span station of its attach point (``[booms] attach_points``), in ``num_strips`` equal
    strips. Strips under the wing's local chord (the file's planform at that span station)
    carry no moment (DATCOM 4.2.2.1: the wing carries that part's load).

    Returns
    -------
    dict
        ``boom_x``, ``boom_y`` (strip stations, m), ``boom_strip_factor`` (w^2 dx, m**3),
        ``boom_flow_mask`` (0 under the wing, else 1) and ``boom_apparent_mass_factor``.
    """
    d = LPC_BOOM_DIAMETER if diameter is None else float(diameter)
    wing = vehicle.wing
    attach = np.array(vehicle.booms.attach_points, dtype=float)
    hubs = np.array([r.hub_position for r in vehicle.lift_rotors], dtype=float)
    if wing.planform == "sections":
        geometry = wing._geometry()
        sec_y = np.asarray(geometry["section_leading_edges"])[:, 1]
        sec_x = np.asarray(geometry["section_leading_edges"])[:, 0] + wing.root_leading_edge[0]
        sec_c = np.asarray(geometry["section_chords"])
    else:
        sec_y = np.array([0.0, 0.5 * wing.span])
        sec_x = wing.root_leading_edge[0] - sec_y * np.tan(wing.sweep)
        sec_c = np.array([wing.root_chord, wing.tip_chord])
    xs, ys, factors, masks, lengths = [], [], [], [], []
    for y in np.unique(np.round(attach[:, 1], 6)):
        on_line = np.isclose(attach[:, 1], y, atol=1e-6)
        front, rear = hubs[on_line, 0].max(), hubs[on_line, 0].min()
        edges = np.linspace(front, rear, num_strips + 1)
        xc = 0.5 * (edges[:-1] + edges[1:])
        le = np.interp(abs(y), sec_y, sec_x)
        chord = np.interp(abs(y), sec_y, sec_c)
        xs.append(xc)
        ys.append(np.full(num_strips, y))
        factors.append(np.full(num_strips, d**2 * (front - rear) / num_strips))
        masks.append(np.where((xc <= le) & (xc >= le - chord), 0.0, 1.0))
        lengths.append(front - rear)
    return {
        "boom_x": np.concatenate(xs),
        "boom_y": np.concatenate(ys),
        "boom_strip_factor": np.concatenate(factors),
        "boom_flow_mask": np.concatenate(masks),
        "boom_apparent_mass_factor": float(munk_apparent_mass_factor(np.mean(lengths) / d)),
    }


def body_moment_slope_options(vehicle):
    """Options of :class:`BodyMomentSlopeComp` for a vehicle (fuselage width, wing, booms)."""
    wing = vehicle.wing
    return {
        "fuselage_max_width": float(vehicle.fuselage.max_width),
        "wing_sweep": float(wing.sweep),
        "wing_root_leading_edge_x": float(wing.root_leading_edge[0]),
        **boom_strips(vehicle),
    }
