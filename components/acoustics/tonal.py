"""Tonal loading noise: Lowson-Ollerhead with Doppler correction, and Sears-function gust loads."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.acoustics.common import (
    bessel_j,
    bessel_j_range,
    bessel_y,
    blade_counts,
    check_input_range,
    declare_radial_options,
    dspl_dmean_square,
    radial_quadrature,
    spl_from_mean_square,
)
from lpc_mdo.core.constants import RPM_TO_RAD_S, SEA_LEVEL_DENSITY, SEA_LEVEL_SPEED_OF_SOUND

#: Smooth switch between the Sears (hover) and unsteady (edgewise) loading-noise paths
#: (docs theory/acoustics 'Tonal loading noise'): weight of the unsteady path 0.5 tanh(SHARPNESS (v
#: - THRESHOLD)) + 0.5, with v the in-plane flight speed in m/s.
PATH_SWITCH_THRESHOLD = 0.1
PATH_SWITCH_SHARPNESS = 100.0


def sears_function(k):
    """
    Sears function S(k) = [J0(k) - i J1(k)] C(k) + i J1(k) and its k-derivative, as real pairs.

    C(k) = F + iG is Theodorsen's function (docs theory/acoustics 'Sears path'): F = (J1 (J1 + Y0) +
    Y1 (Y1 - J0))/den, G = -(Y1 Y0 + J1 J0)/den, den = (J1 + Y0)**2 + (Y1 - J0)**2. Returns (Re S,
    Im S, dRe S/dk, dIm S/dk); k > 0.
    S -> 1 as k -> 0 (quasi-steady) and abs(S) decays like 1/sqrt(2 pi k).
    """
    j0, j1, y0, y1 = bessel_j(0, k), bessel_j(1, k), bessel_y(0, k), bessel_y(1, k)
    dj0, dy0 = -j1, -y1
    dj1, dy1 = j0 - j1 / k, y0 - y1 / k
    p, q = j1 + y0, y1 - j0
    den = p * p + q * q
    nf = j1 * p + y1 * q
    ng = -(y1 * y0 + j1 * j0)
    f, g = nf / den, ng / den
    dp, dq = dj1 + dy0, dy1 - dj0
    dden = 2.0 * (p * dp + q * dq)
    dnf = dj1 * p + j1 * dp + dy1 * q + y1 * dq
    dng = -(dy1 * y0 + y1 * dy0 + dj1 * j0 + j1 * dj0)
    df = (dnf - f * dden) / den
    dg = (dng - g * dden) / den
    s_re = f * j0 + g * j1
    s_im = g * j0 - f * j1 + j1
    ds_re = df * j0 + f * dj0 + dg * j1 + g * dj1
    ds_im = dg * j0 + g * dj0 - df * j1 - f * dj1 + dj1
    return s_re, s_im, ds_re, ds_im


class SearsGustLoadsComp(om.ExplicitComponent):
    """
    Gust (unsteady) blade-load harmonics in hover from the Sears function (Kvurt & Stalnov).

    docs theory/acoustics 'Sears path', load harmonics lambda = 1..L_g, per blade and unit span, at
    each radial station r = rbar R:

    - U_t = Omega r; reduced frequency k = lambda Omega c/(2 U_t) = lambda c/(2 r);
    - gust amplitude w = q lambda_i Omega R/lambda with lambda_i = phi rbar, i.e. q phi U_t/lambda;
    - unsteady lift amplitude L' = pi rho U_t c w;
    - a_T = Re S(k) L' cos phi, b_T = Im S(k) L' cos phi, a_D = Re S(k) L' sin phi,
      b_D = Im S(k) L' sin phi.

    phi is the azimuthal mean of the input inflow angle. The loads of docs theory/acoustics
    'Public-code compatibility' are per blade.

    Inputs
    ------
    inflow_angle : float, (num_rotors, num_radial, num_azimuth), rad
        Inflow angle phi at each station (e.g. from BEM).
    chord : float, (num_rotors, num_radial), m
        Blade chord at the stations (> 0).
    radius : float, (num_rotors,), m
        Rotor radius.
    rpm : float, (num_rotors,), rpm
        Rotor speed.
    density : float, (1,), kg/m**3
        Air density.

    Outputs
    -------
    thrust_gust_cos, thrust_gust_sin : float, (num_rotors, num_radial, num_gust_harmonics), N/m
        a_lambda and b_lambda of the gust thrust per span, lambda = 1..num_gust_harmonics.
    drag_gust_cos, drag_gust_sin : float, (num_rotors, num_radial, num_gust_harmonics), N/m
        a_lambda and b_lambda of the gust drag per span.

    Options
    -------
    num_rotors, num_radial, num_azimuth : int
        Array sizes.
    num_gust_harmonics : int
        Highest gust load harmonic L_g (>= 1). Default 10.
    gust_factor : float
        Gust amplification factor q (>= 0). Default 0.06 (csdl_alpha lsdo_acoustics).
    radial_stations, radial_weights, hub_radius_ratio :
        Acoustic radial stations (see ``common.radial_quadrature``).
    """

    def initialize(self):
        self.options.declare("num_rotors", default=1, types=int, lower=1, desc="Number of rotors")
        self.options.declare(
            "num_azimuth",
            default=1,
            types=int,
            lower=1,
            desc="Number of azimuthal stations of the inflow angle",
        )
        self.options.declare(
            "num_gust_harmonics", default=10, types=int, lower=1, desc="Highest gust load harmonic"
        )
        self.options.declare(
            "gust_factor",
            default=0.06,
            types=(int, float),
            lower=0.0,
            desc="Gust amplification factor q",
        )
        declare_radial_options(self.options)

    def setup(self):
        nr, nrad, naz = (self.options[k] for k in ("num_rotors", "num_radial", "num_azimuth"))
        ng = self.options["num_gust_harmonics"]
        self._rbar, _ = radial_quadrature(
            nrad,
            self.options["radial_stations"],
            self.options["radial_weights"],
            self.options["hub_radius_ratio"],
        )
        self._lam = np.arange(1, ng + 1, dtype=float)

        self.add_input(
            "inflow_angle",
            val=np.full((nr, nrad, naz), 0.1),
            units="rad",
            desc="Inflow angle at each station and azimuth",
        )
        self.add_input("chord", val=np.full((nr, nrad), 0.1), units="m", desc="Blade chord")
        self.add_input("radius", val=np.ones(nr), units="m", desc="Rotor radius")
        self.add_input("rpm", val=np.full(nr, 1000.0), units="rpm", desc="Rotor speed")
        self.add_input("density", val=SEA_LEVEL_DENSITY, units="kg/m**3", desc="Air density")

        shape = (nr, nrad, ng)
        size = nr * nrad * ng
        ar = np.arange(size)
        station = ar // ng  # flat (rotor, station) index of each output
        rotor = station // nrad
        rows_az = np.repeat(ar, naz)
        cols_az = (station[:, None] * naz + np.arange(naz)[None, :]).ravel()
        for load in ("thrust", "drag"):
            for kind in ("cos", "sin"):
                name = f"{load}_gust_{kind}"
                self.add_output(
                    name,
                    val=np.zeros(shape),
                    units="N/m",
                    desc=f"{'a' if kind == 'cos' else 'b'}_lambda of the Sears gust "
                    f"{load} per span of one blade, lambda = 1..{ng}",
                )
                self.declare_partials(name, "inflow_angle", rows=rows_az, cols=cols_az)
                self.declare_partials(name, "chord", rows=ar, cols=station)
                self.declare_partials(name, "radius", rows=ar, cols=rotor)
                self.declare_partials(name, "rpm", rows=ar, cols=rotor)
                self.declare_partials(name, "density", rows=ar, cols=np.zeros(size, dtype=int))

    def _parts(self, inputs):
        q = float(self.options["gust_factor"])
        rbar, lam = self._rbar, self._lam
        phi = np.mean(inputs["inflow_angle"], axis=2)[:, :, None]  # (nr, nrad, 1)
        chord = inputs["chord"][:, :, None]
        R = inputs["radius"][:, None, None]
        omega = inputs["rpm"][:, None, None] * RPM_TO_RAD_S
        rho = inputs["density"][0]
        k = lam * chord / (2.0 * rbar[None, :, None] * R)  # (nr, nrad, ng)
        # L' = phi * amp with amp = pi rho q U_t**2 c/lambda.
        amp = np.pi * rho * q * (omega * rbar[None, :, None] * R) ** 2 * chord / lam
        return phi, k, amp

    def compute(self, inputs, outputs):
        check_input_range(self, "chord", inputs["chord"], lower=0.0)
        check_input_range(self, "radius", inputs["radius"], lower=0.0)
        check_input_range(self, "rpm", inputs["rpm"], lower=0.0)
        check_input_range(self, "density", inputs["density"], lower=0.0)
        phi, k, amp = self._parts(inputs)
        s_re, s_im, _, _ = sears_function(k)
        lift = amp * phi
        outputs["thrust_gust_cos"] = s_re * lift * np.cos(phi)
        outputs["thrust_gust_sin"] = s_im * lift * np.cos(phi)
        outputs["drag_gust_cos"] = s_re * lift * np.sin(phi)
        outputs["drag_gust_sin"] = s_im * lift * np.sin(phi)

    def compute_partials(self, inputs, partials):
        naz = self.options["num_azimuth"]
        phi, k, amp = self._parts(inputs)
        s_re, s_im, ds_re, ds_im = sears_function(k)
        chord = inputs["chord"][:, :, None]
        R = inputs["radius"][:, None, None]
        rpm = inputs["rpm"][:, None, None]
        rho = inputs["density"][0]
        cos_phi, sin_phi = np.cos(phi), np.sin(phi)
        proj = {
            "thrust": (phi * cos_phi, cos_phi - phi * sin_phi),  # (phi cos, d/dphi)
            "drag": (phi * sin_phi, sin_phi + phi * cos_phi),
        }
        sears = {"cos": (s_re, ds_re), "sin": (s_im, ds_im)}
        for load, (g, dg) in proj.items():
            for kind, (s, ds) in sears.items():
                name = f"{load}_gust_{kind}"
                val = s * amp * g
                # k ~ c/R, amp ~ rho rpm**2 R**2 c.
                dval_dlnk = ds * k * amp * g
                partials[name, "inflow_angle"] = np.repeat((s * amp * dg / naz).ravel(), naz)
                partials[name, "chord"] = ((dval_dlnk + val) / chord).ravel()
                partials[name, "radius"] = ((-dval_dlnk + 2.0 * val) / R).ravel()
                partials[name, "rpm"] = (2.0 * val / rpm).ravel()
                partials[name, "density"] = (val / rho).ravel()


def _complex_powers(c, s, lam):
    """(c + i s)**lam for integer lam >= 0 as real pairs, and their derivatives (real algebra)."""
    nl = lam.size
    lmax = int(lam.max()) if nl else 0
    pr = [np.ones_like(c)]
    pi = [np.zeros_like(c)]
    for _ in range(lmax):
        re, im = pr[-1], pi[-1]
        pr.append(re * c - im * s)
        pi.append(im * c + re * s)
    pr, pi = np.stack(pr, axis=-1), np.stack(pi, axis=-1)  # (..., lmax+1)
    idx = lam.astype(int)
    prev = np.maximum(idx - 1, 0)
    C, S = pr[..., idx], pi[..., idx]
    dC_dc, dS_dc = lam * pr[..., prev], lam * pi[..., prev]
    dC_ds, dS_ds = -lam * pi[..., prev], lam * pr[..., prev]
    return C, S, (dC_dc, dS_dc), (dC_ds, dS_ds)


# (-i)**k for k mod 4 = 0, 1, 2, 3, as (real, imaginary).
_PHASE = np.array([[1.0, 0.0], [0.0, -1.0], [-1.0, 0.0], [0.0, 1.0]])
_SIGN = np.array([-1, 1])  # term s = 0: order n - lambda; s = 1: order n + lambda


class _LowsonSum:
    """
    Complex radial and harmonic sum of the Lowson-Ollerhead kernel for one group of load harmonics.

    For harmonic n = m B and load harmonics lambda in ``lam``, with complex load coefficients
    T_{+-lambda} = (a_lambda -+ i b_lambda)/2 (T_0 = a_0) rotated by exp(+-i lambda phi_o):

        Psi = sum_lambda sum_{s = -1, +1} sum_i w_i (-i)**k J_k(n mu rbar_i)
              [-n nu T_{s lambda}(r_i) + (k/rbar_i) D_{s lambda}(r_i)],   k = n + s lambda

    The amplitude of harmonic n of one blade is abs(Psi)/(2 pi r1) (times R, absorbed in mu and nu:
    mu = Omega R Y/(a r1), nu = Omega R z/(a r1)). All complex algebra is done on real pairs so
    the component is complex-step safe.
    """

    def __init__(self, n, lam, offset, rbar, weights):
        self.lam = np.asarray(lam, dtype=float)
        lam_i = np.asarray(lam, dtype=int)
        self.q_index = offset + _SIGN[None, :] * lam_i[:, None]  # (nl, 2)
        self.order = n[:, :, None, None] + _SIGN[None, None, None, :] * lam_i[None, None, :, None]
        phase = _PHASE[self.order % 4]  # (.., 2, 2)
        zero = lam_i[:, None] == 0
        alpha = np.where(zero, np.array([1.0, 0.0]), 0.5)  # (nl, 2)
        beta = np.where(zero, 0.0, np.array([0.5, -0.5]))  # beta = i*this
        self.ga = (phase[..., 0] * alpha, phase[..., 1] * alpha)
        self.gb = (-phase[..., 1] * beta, phase[..., 0] * beta)
        self.n = n[:, :, None, None].astype(float)
        self.w = weights
        self.w_r = weights / rbar
        self.rbar = rbar

    def evaluate(self, jtab, jdtab, coeffs, nu, rotation=None, grad=False):
        """Return abs(Psi)**2 (nr, nm) and, if ``grad``, its derivatives."""
        J = jtab[..., self.q_index]  # (nr, nm, nrad, nl, 2)
        n, k = self.n, self.order
        nu4 = nu[:, None, None, None]
        a_t, b_t, a_d, b_d = (coeffs[key] for key in ("a_t", "b_t", "a_d", "b_d"))
        ja_t = np.einsum("rmils,i,ril->rmls", J, self.w, a_t)
        jb_t = np.einsum("rmils,i,ril->rmls", J, self.w, b_t)
        ja_d = np.einsum("rmils,i,ril->rmls", J, self.w_r, a_d)
        jb_d = np.einsum("rmils,i,ril->rmls", J, self.w_r, b_d)
        ua = -n * nu4 * ja_t + k * ja_d
        ub = -n * nu4 * jb_t + k * jb_d
        zr = self.ga[0] * ua + self.gb[0] * ub
        zi = self.ga[1] * ua + self.gb[1] * ub
        if rotation is None:
            rr, ri = 1.0, 0.0
        else:
            C, S = rotation[0][:, None, :, None], rotation[1][:, None, :, None]
            rr, ri = C, _SIGN * S
        psi_r = np.sum(rr * zr - ri * zi, axis=(2, 3))
        psi_i = np.sum(rr * zi + ri * zr, axis=(2, 3))
        mag2 = psi_r**2 + psi_i**2
        if not grad:
            return mag2, None

        pr, pi = psi_r[:, :, None, None], psi_i[:, :, None, None]
        ur = pr * rr + pi * ri  # u = conj(Psi) * rho
        ui = pr * ri - pi * rr
        wa = 2.0 * (ur * self.ga[0] - ui * self.ga[1])
        wb = 2.0 * (ur * self.gb[0] - ui * self.gb[1])
        g = {}
        g["a_t"] = -n * nu4 * np.einsum("rmls,rmils->rmil", wa, J) * self.w[None, None, :, None]
        g["b_t"] = -n * nu4 * np.einsum("rmls,rmils->rmil", wb, J) * self.w[None, None, :, None]
        g["a_d"] = np.einsum("rmls,rmils->rmil", wa * k, J) * self.w_r[None, None, :, None]
        g["b_d"] = np.einsum("rmls,rmils->rmil", wb * k, J) * self.w_r[None, None, :, None]
        g["nu"] = np.sum(-n * (wa * ja_t + wb * jb_t), axis=(2, 3))
        # x_i = n mu rbar_i: dJ/dmu = J'(x) n rbar_i.
        Jd = jdtab[..., self.q_index]
        dja_t = np.einsum("rmils,i,ril->rmls", Jd, self.w * self.rbar, a_t)
        djb_t = np.einsum("rmils,i,ril->rmls", Jd, self.w * self.rbar, b_t)
        dja_d = np.einsum("rmils,i,ril->rmls", Jd, self.w, a_d)
        djb_d = np.einsum("rmils,i,ril->rmls", Jd, self.w, b_d)
        dua = n * (-n * nu4 * dja_t + k * dja_d)
        dub = n * (-n * nu4 * djb_t + k * djb_d)
        g["mu"] = np.sum(wa * dua + wb * dub, axis=(2, 3))
        if rotation is not None:
            for key, (dC, dS) in (("cos", rotation[2]), ("sin", rotation[3])):
                drr, dri = dC[:, None, :, None], _SIGN * dS[:, None, :, None]
                g[key] = 2.0 * np.sum(
                    pr * (drr * zr - dri * zi) + pi * (drr * zi + dri * zr), axis=(2, 3)
                )
        return mag2, g


class LowsonLoadingNoiseComp(om.ExplicitComponent):
    """
    Tonal loading noise of each rotor by Lowson & Ollerhead, with Sears-function gusts in hover.

    Frequency-domain far-field loading noise of rotating blade forces (Lowson & Ollerhead 1969;
    paper Sec. III.E, eq. 21; docs theory/acoustics 'Tonal loading noise'). For the harmonic n = m B
    (frequency m B rpm/60, m = 1..num_harmonics) and an observer at axial distance z and in-plane
    distance Y of the hub, the blade loads per unit span with azimuthal Fourier
    coefficients (a_lambda, b_lambda) (paper eq. 19) radiate the complex amplitude (one blade)

        p_n = 1/(2 pi r1) sum_lambda sum_i w_i R (-i)**k J_k(x_i) [-(n Omega z/(a r1)) T_lambda
              + (k/r_i) D_lambda],   k = n -+ lambda,  x_i = n Omega r_i Y/(a r1),

    with T_{-+lambda} = (a_lambda +- i b_lambda)/2, derived from the far-field compact dipole with
    the Jacobi-Anger expansion; r1 is the Doppler-corrected distance (docs theory/acoustics
    'Observer geometry'), thrust is positive along the thrust axis and drag opposes
    rotation. This is the docs theory/acoustics 'Tonal loading noise' kernel with the (-i)**k phase
    written out; it reduces to Gutin's formula for steady loading for every n (the public code's
    odd-(n - lambda) sign branch does not, see below). B equally spaced identical blades add
    coherently: abs(p) = B abs(p_n). SPL = 10 log10(abs(p)**2/(2 p_ref**2)) (paper eq. 21) with
    the smooth floor of ``common``.

    Two load models, selected smoothly by the in-plane flight speed v (docs theory/acoustics 'Tonal
    loading noise'): SPL = SPL_Sears (1 - h) + SPL_unsteady h,
    h = 0.5 tanh(100 (v - 0.1 m/s)) + 0.5.

    - Sears path (hover): steady loads (the lambda = 0 coefficients) plus the Sears-function gust
      loads lambda = 1..L_g (SearsGustLoadsComp), summed coherently over lambda within each part;
      the steady and gust parts add energetically (docs theory/acoustics 'Sears path').
    - Unsteady path (edgewise flight): all load harmonics lambda = 0..L of the azimuthal loads
      (LoadFourierComp, paper eq. 20) added coherently, with the coefficients rotated into the
      observer's azimuth: T_{+-lambda} exp(+-i lambda phi_o) (docs theory/acoustics 'Unsteady
      path').

    Deviations from the public code (lsdo_acoustics), on purpose:

    - Its odd-(n - lambda) sign branch (c1 = c2 = +1, docs theory/acoustics 'Tonal loading noise',
      flagged there as unchecked) makes the thrust and torque terms add on the thrust side for odd
      n, e.g. B = 3, m = 1, which
      contradicts Gutin's formula and mirrors the steady directivity through the disk plane.
      Here the phase (-i)**k is applied for every k, so steady loading reduces to Gutin's formula
      for all n (tests/test_acoustics_tonal.py), and the Kvurt-Stalnov hover case matches H. Gill's
      MATLAB directivity mirrored through the disk plane to 0.3 dB.
    - The unsteady path adds the B blades coherently (abs(p) = B abs(p_n), as the Sears path of docs
      theory/acoustics 'Sears path'
      does) rather than energetically (+10 log10 B, docs theory/acoustics 'Unsteady path' as coded):
      for identical, equally spaced blades the harmonics m B are in phase, so steady hover loading
      gives the same level
      on both paths.
    - Loads are per unit span and integrated with the acoustic quadrature weights in both paths.

    Inputs
    ------
    radius, rpm : float, (num_rotors,), m and rpm
        Rotor radius and speed.
    speed_of_sound : float, (1,), m/s
        Speed of sound.
    axial_distance, inplane_distance, convected_distance : float, (num_rotors,), m
        z, Y and r1 from ObserverGeometryComp.
    observer_azimuth_cos, observer_azimuth_sin : float, (num_rotors,), unitless
        Observer azimuth in the rotor frame (unsteady path).
    inplane_speed : float, (num_rotors,), m/s
        Edgewise flight speed (path switch).
    thrust_cos_coeff, thrust_sin_coeff, drag_cos_coeff, drag_sin_coeff :
        float, (num_rotors, num_radial, num_load_harmonics + 1), N/m
        Fourier coefficients of the loads per span of one blade (LoadFourierComp).
    thrust_gust_cos, thrust_gust_sin, drag_gust_cos, drag_gust_sin :
        float, (num_rotors, num_radial, num_gust_harmonics), N/m
        Sears gust coefficients (SearsGustLoadsComp); absent when loading_path = 'unsteady'.

    Outputs
    -------
    loading_spl : float, (num_rotors, num_harmonics), dB (units=None)
        Loading-noise SPL of each blade-passing harmonic, dB re 20 uPa.
    harmonic_frequency : float, (num_rotors, num_harmonics), Hz
        Frequency m B rpm/60 of each harmonic.

    Options
    -------
    num_rotors : int
        Number of rotors.
    num_blades : int or sequence of int
        Blades per rotor.
    num_harmonics : int
        Number of blade-passing harmonics m = 1..num_harmonics. Default 3.
    num_load_harmonics : int
        Highest azimuthal load harmonic L of the coefficient inputs. Default 0 (hover).
    num_gust_harmonics : int
        Highest Sears gust harmonic L_g. Default 10.
    loading_path : str
        'auto' (default, smooth switch), 'sears' or 'unsteady'.
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
        self.options.declare(
            "num_load_harmonics",
            default=0,
            types=int,
            lower=0,
            desc="Highest azimuthal load harmonic of the coefficient inputs",
        )
        self.options.declare(
            "num_gust_harmonics",
            default=10,
            types=int,
            lower=1,
            desc="Highest Sears gust load harmonic",
        )
        self.options.declare(
            "loading_path",
            default="auto",
            values=("auto", "sears", "unsteady"),
            desc="Load model: 'sears' (hover), 'unsteady' (azimuthal loads) or "
            "'auto' (smooth switch on the in-plane speed)",
        )
        declare_radial_options(self.options)

    def setup(self):
        nr, nrad, nm = (self.options[k] for k in ("num_rotors", "num_radial", "num_harmonics"))
        L = self.options["num_load_harmonics"]
        path = self.options["loading_path"]
        self._use_sears = path in ("auto", "sears")
        self._use_unsteady = path in ("auto", "unsteady")
        ng = self.options["num_gust_harmonics"] if self._use_sears else 0
        nl = L + 1
        self._blades = B = blade_counts(self.options["num_blades"], nr)
        self._rbar, self._w = radial_quadrature(
            nrad,
            self.options["radial_stations"],
            self.options["radial_weights"],
            self.options["hub_radius_ratio"],
        )
        m = np.arange(1, nm + 1)
        self._n = n = m[None, :] * B[:, None]  # (nr, nm)
        self._kappa = (B.astype(float) / (2.0 * np.pi)) ** 2 / 2.0  # ms = kappa |Psi/r1|^2
        lmax = max(L if self._use_unsteady else 0, ng)
        self._offset = off = lmax + 1
        self._orders = n[:, :, None] + np.arange(-off, off + 1)[None, None, :]
        self._steady = _LowsonSum(n, [0], off, self._rbar, self._w)
        self._gust = _LowsonSum(n, np.arange(1, ng + 1), off, self._rbar, self._w) if ng else None
        self._unsteady = _LowsonSum(n, np.arange(nl), off, self._rbar, self._w)

        self.add_input("radius", val=np.ones(nr), units="m", desc="Rotor radius")
        self.add_input("rpm", val=np.full(nr, 1000.0), units="rpm", desc="Rotor speed")
        self.add_input(
            "speed_of_sound", val=SEA_LEVEL_SPEED_OF_SOUND, units="m/s", desc="Speed of sound"
        )
        for name, desc in (
            ("axial_distance", "Observer distance along the thrust axis z"),
            ("inplane_distance", "Observer distance from the thrust axis Y"),
            ("convected_distance", "Doppler-corrected distance r1"),
        ):
            self.add_input(name, val=np.full(nr, 100.0), units="m", desc=desc)
        self.add_input(
            "observer_azimuth_cos",
            val=np.ones(nr),
            units=None,
            desc="cos of the observer azimuth in the rotor frame",
        )
        self.add_input(
            "observer_azimuth_sin",
            val=np.zeros(nr),
            units=None,
            desc="sin of the observer azimuth in the rotor frame",
        )
        self.add_input(
            "inplane_speed", val=np.zeros(nr), units="m/s", desc="In-plane (edgewise) flight speed"
        )
        self._coeff_inputs = {}
        for load, key in (("thrust", "t"), ("drag", "d")):
            for kind, ab in (("cos", "a"), ("sin", "b")):
                name = f"{load}_{kind}_coeff"
                self.add_input(
                    name,
                    val=np.zeros((nr, nrad, nl)),
                    units="N/m",
                    desc=f"{ab}_lambda of the {load} per span, lambda = 0..{L}",
                )
                self._coeff_inputs[name] = (f"{ab}_{key}", nl)
                if self._use_sears:
                    gname = f"{load}_gust_{kind}"
                    self.add_input(
                        gname,
                        val=np.zeros((nr, nrad, ng)),
                        units="N/m",
                        desc=f"{ab}_lambda of the Sears gust {load} per span, lambda = 1..{ng}",
                    )
                    self._coeff_inputs[gname] = (f"{ab}_{key}", ng)

        self.add_output(
            "loading_spl",
            val=np.zeros((nr, nm)),
            units=None,
            desc="Loading-noise SPL per blade-passing harmonic, dB re 20 uPa",
        )
        self.add_output(
            "harmonic_frequency",
            val=np.ones((nr, nm)),
            units="Hz",
            desc="Blade-passing harmonic frequencies m B rpm/60",
        )

        rows = np.arange(nr * nm)
        rotor = rows // nm
        self.declare_partials(
            "harmonic_frequency", "rpm", rows=rows, cols=rotor, val=(n / 60.0).ravel()
        )
        scalars = ["radius", "rpm", "axial_distance", "inplane_distance", "convected_distance"]
        if self._use_unsteady and L > 0:
            scalars += ["observer_azimuth_cos", "observer_azimuth_sin"]
        if path == "auto":
            scalars.append("inplane_speed")
        for name in scalars:
            self.declare_partials("loading_spl", name, rows=rows, cols=rotor)
        self.declare_partials(
            "loading_spl", "speed_of_sound", rows=rows, cols=np.zeros(nr * nm, dtype=int)
        )
        self._rotation_partials = self._use_unsteady and L > 0
        self._coeff_width = {}
        for name, (_, full) in self._coeff_inputs.items():
            # The Sears path alone uses only lambda = 0 of the azimuthal coefficients.
            width = 1 if (name.endswith("_coeff") and not self._use_unsteady) else full
            self._coeff_width[name] = width
            # b_0 (sin coefficient of lambda = 0) does not radiate: no partials for it.
            first = 1 if name.endswith("_sin_coeff") else 0
            if width <= first:
                continue
            r_i, m_i, i_i, l_i = np.meshgrid(
                np.arange(nr),
                np.arange(nm),
                np.arange(nrad),
                np.arange(first, width),
                indexing="ij",
            )
            self.declare_partials(
                "loading_spl",
                name,
                rows=(r_i * nm + m_i).ravel(),
                cols=((r_i * nrad + i_i) * full + l_i).ravel(),
            )

    # ------------------------------------------------------------------ evaluation helpers
    def _kinematics(self, inputs):
        R = inputs["radius"]
        omega = inputs["rpm"] * RPM_TO_RAD_S
        a = inputs["speed_of_sound"][0]
        r1 = inputs["convected_distance"]
        scale = omega * R / (a * r1)
        mu = scale * inputs["inplane_distance"]
        nu = scale * inputs["axial_distance"]
        return mu, nu, scale

    def _bessel(self, mu, grad):
        x = self._n[:, :, None] * mu[:, None, None] * self._rbar[None, None, :]
        low = self._orders[:, :, :1]  # (nr, nm, 1): the lowest order of each harmonic
        jtab = bessel_j_range(low, self._orders.shape[-1], x)  # (nr, nm, nrad, nq)
        if not grad:
            return jtab, None
        jdtab = np.zeros_like(jtab)
        jdtab[..., 1:-1] = 0.5 * (jtab[..., :-2] - jtab[..., 2:])
        return jtab, jdtab

    def _coeffs(self, inputs, kind):
        if kind == "gust":
            names = ("thrust_gust_cos", "thrust_gust_sin", "drag_gust_cos", "drag_gust_sin")
            sl = slice(None)
        else:
            names = ("thrust_cos_coeff", "thrust_sin_coeff", "drag_cos_coeff", "drag_sin_coeff")
            sl = slice(0, 1) if kind == "steady" else slice(None)
        keys = ("a_t", "b_t", "a_d", "b_d")
        return {key: inputs[name][:, :, sl] for key, name in zip(keys, names, strict=True)}

    def _rotation(self, inputs):
        lam = self._unsteady.lam
        return _complex_powers(inputs["observer_azimuth_cos"], inputs["observer_azimuth_sin"], lam)

    def _paths(self, inputs, grad):
        """Mean-square pressures of the Sears and unsteady paths and their abs(Psi)^2 gradients."""
        mu, nu, scale = self._kinematics(inputs)
        r1 = inputs["convected_distance"]
        jtab, jdtab = self._bessel(mu, grad)
        factor = self._kappa[:, None] / r1[:, None] ** 2  # ms = factor |Psi|^2
        res = {"mu": mu, "nu": nu, "scale": scale, "factor": factor}
        if self._use_sears:
            m_s, g_s = self._steady.evaluate(
                jtab, jdtab, self._coeffs(inputs, "steady"), nu, grad=grad
            )
            m_g, g_g = self._gust.evaluate(jtab, jdtab, self._coeffs(inputs, "gust"), nu, grad=grad)
            res["sears"] = (factor * (m_s + m_g), g_s, g_g)
        if self._use_unsteady:
            m_u, g_u = self._unsteady.evaluate(
                jtab,
                jdtab,
                self._coeffs(inputs, "unsteady"),
                nu,
                rotation=self._rotation(inputs),
                grad=grad,
            )
            res["unsteady"] = (factor * m_u, g_u)
        return res

    def _switch(self, inputs):
        path = self.options["loading_path"]
        if path == "sears":
            return 0.0, 0.0
        if path == "unsteady":
            return 1.0, 0.0
        t = np.tanh(PATH_SWITCH_SHARPNESS * (inputs["inplane_speed"] - PATH_SWITCH_THRESHOLD))
        return (0.5 * t + 0.5)[:, None], (0.5 * PATH_SWITCH_SHARPNESS * (1.0 - t * t))[:, None]

    def compute(self, inputs, outputs):
        check_input_range(self, "radius", inputs["radius"], lower=0.0)
        check_input_range(self, "rpm", inputs["rpm"], lower=0.0)
        check_input_range(self, "speed_of_sound", inputs["speed_of_sound"], lower=0.0)
        check_input_range(self, "convected_distance", inputs["convected_distance"], lower=0.0)
        res = self._paths(inputs, grad=False)
        h, _ = self._switch(inputs)
        spl = 0.0
        if self._use_sears:
            spl = spl + (1.0 - h) * spl_from_mean_square(res["sears"][0])
        if self._use_unsteady:
            spl = spl + h * spl_from_mean_square(res["unsteady"][0])
        outputs["loading_spl"] = spl
        outputs["harmonic_frequency"] = self._n * inputs["rpm"][:, None] / 60.0

    def compute_partials(self, inputs, partials):
        nr, nm = self.options["num_rotors"], self.options["num_harmonics"]
        nrad = self.options["num_radial"]
        res = self._paths(inputs, grad=True)
        h, dh = self._switch(inputs)
        factor = res["factor"]
        mu, nu, scale = res["mu"], res["nu"], res["scale"]
        r1 = inputs["convected_distance"][:, None]

        d_mu = np.zeros((nr, nm))
        d_nu = np.zeros((nr, nm))
        d_r1 = np.zeros((nr, nm))  # through the explicit 1/r1**2 of the mean square
        d_rot = {"cos": np.zeros((nr, nm)), "sin": np.zeros((nr, nm))}
        d_coeff = {
            name: np.zeros((nr, nm, nrad, width)) for name, width in self._coeff_width.items()
        }
        coeff_names = {
            "a_t": "thrust_cos_coeff",
            "b_t": "thrust_sin_coeff",
            "a_d": "drag_cos_coeff",
            "b_d": "drag_sin_coeff",
        }
        gust_names = {
            "a_t": "thrust_gust_cos",
            "b_t": "thrust_gust_sin",
            "a_d": "drag_gust_cos",
            "b_d": "drag_gust_sin",
        }

        spl_paths = {}
        groups = []
        if self._use_sears:
            ms, g_s, g_g = res["sears"]
            spl_paths["sears"] = spl_from_mean_square(ms)
            groups.append((1.0 - h, ms, ((g_s, coeff_names), (g_g, gust_names))))
        if self._use_unsteady:
            ms, g_u = res["unsteady"]
            spl_paths["unsteady"] = spl_from_mean_square(ms)
            groups.append((h, ms, ((g_u, coeff_names),)))

        for weight, ms, grads in groups:
            dspl_dms = weight * dspl_dmean_square(ms)
            dspl = dspl_dms * factor  # d SPL / d|Psi|^2
            d_r1 += dspl_dms * (-2.0 * ms / r1)
            for g, names in grads:
                d_mu += dspl * g["mu"]
                d_nu += dspl * g["nu"]
                for key, name in names.items():
                    width = g[key].shape[-1]
                    d_coeff[name][..., :width] += dspl[:, :, None, None] * g[key]
                for key in ("cos", "sin"):
                    if key in g:
                        d_rot[key] += dspl * g[key]

        # mu = s Y and nu = s z with s = Omega R/(a r1).
        R = inputs["radius"][:, None]
        rpm = inputs["rpm"][:, None]
        a = inputs["speed_of_sound"][0]
        s = scale[:, None]
        d_lns = d_mu * mu[:, None] + d_nu * nu[:, None]  # d SPL / d ln(s)
        partials["loading_spl", "radius"] = (d_lns / R).ravel()
        partials["loading_spl", "rpm"] = (d_lns / rpm).ravel()
        partials["loading_spl", "speed_of_sound"] = (-d_lns / a).ravel()
        partials["loading_spl", "inplane_distance"] = (d_mu * s).ravel()
        partials["loading_spl", "axial_distance"] = (d_nu * s).ravel()
        partials["loading_spl", "convected_distance"] = (d_r1 - d_lns / r1).ravel()
        if self._rotation_partials:
            partials["loading_spl", "observer_azimuth_cos"] = d_rot["cos"].ravel()
            partials["loading_spl", "observer_azimuth_sin"] = d_rot["sin"].ravel()
        if self.options["loading_path"] == "auto":
            partials["loading_spl", "inplane_speed"] = (
                dh * (spl_paths["unsteady"] - spl_paths["sears"])
            ).ravel()
        for name, val in d_coeff.items():
            first = 1 if name.endswith("_sin_coeff") else 0
            if val.shape[-1] > first:
                partials["loading_spl", name] = val[..., first:].ravel()
