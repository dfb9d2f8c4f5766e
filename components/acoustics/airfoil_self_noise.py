"""
Airfoil self-noise of one blade section by the Brooks-Pope-Marcolini method (NASA RP-1218).

Brooks, T. F., Pope, D. S. and Marcolini, M. A., "Airfoil Self-Noise and Prediction", NASA
Reference Publication 1218, 1989 (equation numbers below are the report's). docs
theory/acoustics 'BPM broadband model'. Every function is numpy-vectorized over broadcast
arrays and complex-step safe (branches are chosen on real parts).

Two mechanisms are modelled, the ones that dominate a rotor's broadband noise:

- turbulent-boundary-layer trailing-edge noise, pressure side, suction side and the
  angle-of-attack (separation) part, with the report's stall branch (eqs. 24-30 and 47-50);
- tip-vortex formation noise of a flat (square) tip (eqs. 61-67).

Laminar vortex shedding (untripped boundary layers at low Reynolds number) and trailing-edge
bluntness need the trailing-edge thickness and the transition state, which a sizing model does
not carry; they are left out (the boundary layers are taken as tripped, the report's
full-scale case). Thickness correlations are the report's NACA 0012 fits (eqs. 2-3, 8-12).

Where it holds: the report's data are NACA 0012 sections of 2.5-30.5 cm chord at free-stream
speeds up to 71.3 m/s (Mach 0.21, chord Reynolds number 4e4 to 1.5e6) and angles of attack
0 to 25.2 deg; Brooks & Burley (AIAA 2001-2210) applied it blade section by blade section to the
HART BO-105 model rotor, at a tip Mach number of 0.64. The angle of attack alpha* is measured
from zero lift (the report's symmetric section).
"""

import numpy as np

#: Largest abs(alpha*) of the report's measurements, deg.
MAX_ANGLE_OF_ATTACK_DEG = 25.0
#: Angle of attack (deg) above which the report switches to its stall (deep separation) form.
STALL_ANGLE_DEG = 12.5


def _re(x):
    return np.real(x)


def _abs(x):
    """|x| that keeps the complex-step perturbation."""
    return np.where(_re(x) < 0.0, -x, x)


def _sqrt(x):
    """Square root where its branch is taken; entries where x <= 0 (another branch) give 0."""
    return np.sqrt(np.where(_re(x) > 0.0, x, 0.0))


def _pick(conditions, choices):
    """np.select on real conditions, complex-safe."""
    out = choices[-1]
    for cond, choice in zip(conditions[::-1][1:], choices[::-1][1:], strict=True):
        out = np.where(cond, choice, out)
    return out


# ------------------------------------------------------------------ boundary layer (tripped)
def displacement_thickness(chord, reynolds, alpha_deg):
    """
    Pressure- and suction-side displacement thicknesses (m) of a tripped NACA 0012 at alpha*.

    Zero angle: delta*_0/c = 0.0601 Re**-0.114 (Re <= 3e5), else
    10**(3.411 - 1.5397 log Re + 0.1059 (log Re)**2) (eq. 3); pressure side
    delta*_p = delta*_0 10**(-0.0432 a + 0.00113 a**2) (eq. 9); suction side
    delta*_s = delta*_0 10**(0.0679 a) (a <= 5), 0.381 10**(0.1516 a) (a <= 12.5),
    14.296 10**(0.0258 a) (eq. 12).
    """
    lre = np.log10(reynolds)
    d0 = np.where(
        _re(reynolds) <= 3.0e5,
        0.0601 * reynolds**-0.114,
        10.0 ** (3.411 - 1.5397 * lre + 0.1059 * lre * lre),
    )
    a = alpha_deg
    dp = d0 * 10.0 ** (-0.0432 * a + 0.00113 * a * a)
    ds = d0 * _pick(
        [_re(a) <= 5.0, _re(a) <= 12.5, True],
        [10.0 ** (0.0679 * a), 0.381 * 10.0 ** (0.1516 * a), 14.296 * 10.0 ** (0.0258 * a)],
    )
    return chord * dp, chord * ds


# ------------------------------------------------------------------ spectral shapes
def _a_min(a):
    # eq. 35
    return _pick(
        [_re(a) < 0.204, _re(a) <= 0.244, True],
        [
            _sqrt(67.552 - 886.788 * a * a) - 8.219,
            -32.665 * a + 3.981,
            -142.795 * a**3 + 103.656 * a * a - 57.757 * a + 6.006,
        ],
    )


def _a_max(a):
    # eq. 36
    return _pick(
        [_re(a) < 0.13, _re(a) <= 0.321, True],
        [
            _sqrt(67.552 - 886.788 * a * a) - 8.219,
            -15.901 * a + 1.098,
            -4.669 * a**3 + 3.491 * a * a - 16.699 * a + 1.149,
        ],
    )


def _b_min(b):
    # eq. 41
    return _pick(
        [_re(b) < 0.13, _re(b) <= 0.145, True],
        [
            _sqrt(16.888 - 886.788 * b * b) - 4.109,
            -83.607 * b + 8.138,
            -817.810 * b**3 + 355.210 * b * b - 135.024 * b + 10.619,
        ],
    )


def _b_max(b):
    # eq. 42
    return _pick(
        [_re(b) < 0.10, _re(b) <= 0.187, True],
        [
            _sqrt(16.888 - 886.788 * b * b) - 4.109,
            -31.330 * b + 1.854,
            -80.541 * b**3 + 44.174 * b * b - 39.381 * b + 2.344,
        ],
    )


def spectrum_a(strouhal_ratio, reynolds):
    """Spectral shape A (dB) at St/St_peak for chord Reynolds number Re_c (eqs. 35-40)."""
    a = _abs(np.log10(strouhal_ratio))
    a0 = _pick(
        [_re(reynolds) < 9.52e4, _re(reynolds) <= 8.57e5, True],
        [0.57 + 0.0 * reynolds, -9.57e-13 * (reynolds - 8.57e5) ** 2 + 1.13, 1.13 + 0.0 * reynolds],
    )
    amin0, amax0 = _a_min(a0), _a_max(a0)
    ratio = (-20.0 - amin0) / (amax0 - amin0)
    amin = _a_min(a)
    return amin + ratio * (_a_max(a) - amin)


def spectrum_b(strouhal_ratio, reynolds):
    """Spectral shape B (dB) of the separation part at St_s/St_2 (eqs. 41-46)."""
    b = _abs(np.log10(strouhal_ratio))
    b0 = _pick(
        [_re(reynolds) < 9.52e4, _re(reynolds) <= 8.57e5, True],
        [0.30 + 0.0 * reynolds, -4.48e-13 * (reynolds - 8.57e5) ** 2 + 0.56, 0.56 + 0.0 * reynolds],
    )
    bmin0, bmax0 = _b_min(b0), _b_max(b0)
    ratio = (-20.0 - bmin0) / (bmax0 - bmin0)
    bmin = _b_min(b)
    return bmin + ratio * (_b_max(b) - bmin)


# ------------------------------------------------------------------ amplitude functions
def k1(reynolds):
    """K1 (dB), eq. 47."""
    lre = np.log10(reynolds)
    return _pick(
        [_re(reynolds) < 2.47e5, _re(reynolds) <= 8.0e5, True],
        [-4.31 * lre + 156.3, -9.0 * lre + 181.6, 128.5 + 0.0 * lre],
    )


def k2(reynolds, mach, alpha_deg):
    """
    K2 (dB), eqs. 49-50: K1 + a level that rises with alpha* towards stall.

    Below gamma_0 - gamma the separation part is absent (the report's -1000 dB); above the
    ellipse's -12 dB point it stays at K1 - 12.
    """
    gamma = 27.094 * mach + 3.31
    gamma0 = 23.43 * mach + 4.651
    beta = 72.65 * mach + 10.74
    beta0 = -34.19 * mach - 13.82
    upper = gamma0 + _sqrt(gamma**2 - (gamma / beta) ** 2 * (-12.0 - beta0) ** 2)
    ell = _sqrt(beta**2 - (beta / gamma) ** 2 * (alpha_deg - gamma0) ** 2)
    a = _re(alpha_deg)
    out = k1(reynolds) + _pick(
        [a < _re(gamma0 - gamma), a <= _re(upper), True],
        [-1000.0 + 0.0 * ell, ell + beta0, -12.0 + 0.0 * ell],
    )
    return out


def directivity_high(cos_theta, sin2_phi, mach, convective_mach):
    """High-frequency directivity D_h (eq. B1) from cos(Theta_e) and sin**2(Phi_e)."""
    return ((1.0 - cos_theta) * sin2_phi) / (
        (1.0 + mach * cos_theta) * (1.0 + (mach - convective_mach) * cos_theta) ** 2
    )


def directivity_low(cos_theta, sin2_phi, mach):
    """Low-frequency directivity D_l (eq. B2)."""
    return ((1.0 - cos_theta**2) * sin2_phi) / (1.0 + mach * cos_theta) ** 4


# ------------------------------------------------------------------ sources
def trailing_edge_noise(
    frequency, chord, speed, mach, alpha_deg, span, distance, d_high, d_low, nu
):
    """
    Mean-square pressure over p_ref**2 of turbulent-boundary-layer trailing-edge noise (eqs. 24-30).

    All arguments broadcast; ``alpha_deg`` is alpha* >= 0 in degrees, ``d_high`` and ``d_low``
    the directivities D_h and D_l, ``nu`` the kinematic viscosity (m**2/s), lengths in m,
    ``frequency`` the one-third-octave band centre (Hz). Returns the band's
    10**(SPL/10): pressure side + suction side + separation part (attached flow,
    alpha* <= min(12.5 deg, gamma_0)), or the separation part alone in the stall form
    (eq. 30: D_l, A evaluated at 3 Re_c). It is
    L/r_e**2 (D_h h + D_l l) with h, l of :func:`trailing_edge_parts`.
    """
    high, low = trailing_edge_parts(frequency, chord, speed, mach, alpha_deg, nu)
    return span / distance**2 * (d_high * high + d_low * low)


def trailing_edge_parts(frequency, chord, speed, mach, alpha_deg, nu):
    """
    Return the trailing-edge noise per unit L/r_e**2 and unit directivity: (h, l).

    h multiplies D_h (the attached-flow sum of eqs. 25-27), l multiplies D_l (the stall form of
    eq. 30); one of the two is zero.
    """
    reynolds = speed * chord / nu
    dp, ds = displacement_thickness(chord, reynolds, alpha_deg)
    st1 = 0.02 * mach**-0.6  # eq. 31
    a = alpha_deg
    st2 = st1 * _pick(  # eq. 34
        [_re(a) < 1.333, _re(a) <= 12.5, True],
        [1.0 + 0.0 * a, 10.0 ** (0.0054 * (a - 1.333) ** 2), 4.72 + 0.0 * a],
    )
    st1_bar = 0.5 * (st1 + st2)
    st_p = frequency * dp / speed
    st_s = frequency * ds / speed
    m5 = mach**5
    kk1 = k1(reynolds)
    re_dp = speed * dp / nu
    dk1 = np.where(_re(re_dp) < 5000.0, a * (1.43 * np.log10(re_dp) - 5.29), 0.0 * a)  # eq. 48
    kk2 = k2(reynolds, mach, a)
    gamma0 = 23.43 * mach + 4.651
    stalled = (_re(a) > STALL_ANGLE_DEG) | (_re(a) > _re(gamma0))
    pressure = dp * _energy(spectrum_a(st_p / st1, reynolds) + kk1 - 3.0 + dk1)
    suction = ds * _energy(spectrum_a(st_s / st1_bar, reynolds) + kk1 - 3.0)
    separation = ds * _energy(spectrum_b(st_s / st2, reynolds) + kk2)
    attached = m5 * (pressure + suction + separation)
    zero = 0.0 * attached
    if not np.any(stalled):  # (the stall form's spectrum only where a section has stalled)
        return attached, zero
    stall = m5 * ds * _energy(spectrum_a(st_s / st2, 3.0 * reynolds) + kk2)
    return np.where(stalled, zero, attached), np.where(stalled, stall, zero)


def _energy(level):
    """10**(level/10), the mean square of a level in dB."""
    return np.exp(level * (0.1 * np.log(10.0)))


def tip_vortex_noise(frequency, chord, mach, alpha_tip_deg, distance, d_high, speed_of_sound):
    """
    Mean-square pressure over p_ref**2 of tip-vortex formation noise, flat tip (eqs. 61-67).

    Vortex size l/c = 0.0230 + 0.0169 a (a < 2 deg), 0.0378 + 0.0095 a (eq. 67); maximum
    Mach number in the vortex M_max = (1 + 0.036 a) M (eq. 64); St'' = f l/U_max (eq. 62);
    SPL = 10 log10(M**2 M_max**3 l**2 D_h/r_e**2) - 30.5 (log10 St'' + 0.3)**2 + 126 (eq. 61).
    """
    a = alpha_tip_deg
    size = chord * np.where(_re(a) < 2.0, 0.0230 + 0.0169 * a, 0.0378 + 0.0095 * a)
    m_max = (1.0 + 0.036 * a) * mach
    st = frequency * size / (m_max * speed_of_sound)
    level = -30.5 * (np.log10(st) + 0.3) ** 2 + 126.0
    return mach**2 * m_max**3 * size**2 * d_high / distance**2 * _energy(level)
