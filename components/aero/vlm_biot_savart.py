"""Biot–Savart kernels of the vortex lattice and their exact derivatives (no OpenMDAO here).

Reference: docs theory/aerodynamics 'Biot-Savart kernels'. Both kernels are written in the form used
by AVL and OpenAeroStruct, which is singular only on the vortex line itself (not on its extension),
so that bound segments collinear with a force point stay regular:

- straight segment A->B of unit strength at P, r1 = P - A, r2 = P - B, r0 = r1 - r2:
  v = (norm(r1) + norm(r2)) (r1 x r2) / (4 pi [norm(r1) norm(r2) (norm(r1) norm(r2) + r1.r2) + (eps
  norm(r0)^2)^2])
  (equal to the Katz–Plotkin form (r1 x r2)/norm(r1 x r2)^2 r0.(r1/norm(r1) - r2/norm(r2)) / (4
  pi));
- semi-infinite line from A along the unit vector u (vorticity along +u), r = P - A:
  v = (u x r) / (4 pi [norm(r) (norm(r) - u.r) + eps^2 norm(r)^2]).

The eps terms (eps = 1e-6, relative to the segment length or the distance) only keep the kernels
finite on the vortex lines; elsewhere their effect is below 1e-12 relative. All operations are
complex-step safe (norms via sqrt of dot products; no abs, maximum or real).
"""

import numpy as np

INV_4PI = 0.25 / np.pi
#: Relative vortex-core size of both kernels (see module docstring).
CORE = 1.0e-6


def dot(a, b):
    """Row-wise dot product over the last axis of length 3 (complex-safe, no conjugation)."""
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1] + a[..., 2] * b[..., 2]


def cross(a, b):
    """Cross product over the last axis (complex-safe)."""
    a, b = np.broadcast_arrays(a, b)
    out = np.empty(a.shape, dtype=np.result_type(a, b))
    out[..., 0] = a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1]
    out[..., 1] = a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2]
    out[..., 2] = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    return out


def skew(a):
    """Matrices S(a), shape (..., 3, 3), with S(a) b = a x b."""
    out = np.zeros(a.shape + (3,), dtype=a.dtype)
    _add_skew(out, a, 1.0)
    return out


def _add_skew(out, a, scale):
    """Add scale S(a) to ``out`` in place (``scale`` broadcasts against a[..., 0])."""
    x, y, z = (scale * a[..., k] for k in range(3))
    out[..., 0, 1] -= z
    out[..., 0, 2] += y
    out[..., 1, 0] += z
    out[..., 1, 2] -= x
    out[..., 2, 0] -= y
    out[..., 2, 1] += x


def outer(a, b):
    """Outer products a b^T over the last axis."""
    return a[..., :, None] * b[..., None, :]


def segment_velocity(r1, r2, derivatives=False):
    """Velocity of a unit-strength straight vortex segment A->B (AVL/OAS form).

    Parameters
    ----------
    r1, r2 : array (..., 3)
        P - A and P - B.
    derivatives : bool
        Also return dv/dr1 and dv/dr2.

    Returns
    -------
    v : array (..., 3)
    dv_dr1, dv_dr2 : array (..., 3, 3), only with ``derivatives``
        dv/dP = dv_dr1 + dv_dr2, dv/dA = -dv_dr1, dv/dB = -dv_dr2.
    """
    n1 = np.sqrt(dot(r1, r1))
    n2 = np.sqrt(dot(r2, r2))
    c = cross(r1, r2)
    d = dot(r1, r2)
    r0 = r1 - r2
    r0s = dot(r0, r0)
    m = n1 * n2
    den = m * (m + d) + CORE**2 * r0s**2
    s = n1 + n2
    inv = INV_4PI / den
    v = (inv * s)[..., None] * c
    if not derivatives:
        return v
    # dv/dr = k (c (x) (dn/dr - q dden/dr)) -/+ k s S(r_other), k = 1/(4 pi den), q = s/den:
    # the two outer products of c share c, so they are one.
    q = (s / den)[..., None]
    a = (2.0 * m + d)[..., None]
    core_term = (4.0 * CORE**2 * r0s)[..., None] * r0
    kc = inv[..., None] * c
    g1 = r1 / n1[..., None] - q * (a * (n2 / n1)[..., None] * r1 + m[..., None] * r2 + core_term)
    g2 = r2 / n2[..., None] - q * (a * (n1 / n2)[..., None] * r2 + m[..., None] * r1 - core_term)
    ks = inv * s
    dv_dr1 = outer(kc, g1)
    _add_skew(dv_dr1, r2, -ks)
    dv_dr2 = outer(kc, g2)
    _add_skew(dv_dr2, r1, ks)
    return v, dv_dr1, dv_dr2


def semi_infinite_velocity(r, u, derivatives=False):
    """Velocity of a unit-strength semi-infinite vortex from A along the unit vector u.

    Parameters
    ----------
    r : array (..., 3)
        P - A.
    u : array (..., 3), broadcastable with r
        Direction of the vortex line (and of its vorticity).
    derivatives : bool
        Also return dv/dr and dv/du.

    Returns
    -------
    v : array (..., 3)
    dv_dr, dv_du : array (..., 3, 3), only with ``derivatives`` (dv/dA = -dv_dr).
    """
    r, u = np.broadcast_arrays(r, u)
    n = np.sqrt(dot(r, r))
    t = dot(u, r)
    w = cross(u, r)
    den = (1.0 + CORE**2) * n**2 - n * t
    inv = INV_4PI / den
    v = inv[..., None] * w
    if not derivatives:
        return v
    # dv/dr = k (S(u) - wq (x) dden/dr), dv/du = k (-S(r) - wq (x) dden/du), wq = w/den.
    kwq = (inv / den)[..., None] * w
    dden_dr = 2.0 * (1.0 + CORE**2) * r - (t / n)[..., None] * r - n[..., None] * u
    dv_dr = outer(kwq, -dden_dr)
    _add_skew(dv_dr, u, inv)
    dv_du = outer(kwq, n[..., None] * r)
    _add_skew(dv_du, r, -inv)
    return v, dv_dr, dv_du


def lattice_velocities(
    points, ring_vertices, te_panels, wake_direction, segment_weights, derivatives=False
):
    """Velocities induced at ``points`` by unit-strength vortex rings and their wakes.

    Every ring contributes its four straight segments (each scaled by ``segment_weights``);
    the trailing-edge ring of each strip also sheds a semi-infinite pair along the wake
    direction: +u from its corner p3 and -u from p4 (the wake ring of the same strength,
    docs theory/aerodynamics 'Wake', whose leading segment cancels the ring's p3->p4 segment).

    Parameters
    ----------
    points : array (npt, 3)
    ring_vertices : array (np, 4, 3)
    te_panels : int array (nte,)
    wake_direction : array (nn, 3), unit vectors
    segment_weights : array (np, 4) or (npt, np, 4)
    derivatives : bool

    Returns
    -------
    dict with
        ``ring`` (npt, np, 3): finite-segment velocities (node-independent);
        ``wake`` (nn, npt, nte, 3): wake velocities of the trailing-edge rings;
    and with ``derivatives``
        ``ring_d_point`` (npt, np, 3, 3), ``ring_d_vertices`` (npt, np, 3, 4, 3),
        ``wake_d_point`` (nn, npt, nte, 3, 3), ``wake_d_p3`` and ``wake_d_p4``
        (nn, npt, nte, 3, 3), ``wake_d_u`` (nn, npt, nte, 3, 3).
    """
    a = ring_vertices[None, :, :, :]
    b = np.roll(ring_vertices, -1, axis=1)[None, :, :, :]
    p = points[:, None, None, :]
    r1, r2 = p - a, p - b
    w = np.broadcast_to(segment_weights, (points.shape[0],) + ring_vertices.shape[:2])
    out = {}
    res = segment_velocity(r1, r2, derivatives)
    v = res[0] if derivatives else res
    out["ring"] = np.einsum("ijs,ijsc->ijc", w, v)

    u = wake_direction[:, None, None, :]
    rp3 = (points[:, None, :] - ring_vertices[te_panels, 2][None, :, :])[None]
    rp4 = (points[:, None, :] - ring_vertices[te_panels, 3][None, :, :])[None]
    res3 = semi_infinite_velocity(rp3, u, derivatives)
    res4 = semi_infinite_velocity(rp4, u, derivatives)
    if not derivatives:
        out["wake"] = res3 - res4
        return out
    out["wake"] = res3[0] - res4[0]

    _, dv1, dv2 = res
    dv1 *= w[..., None, None]
    dv2 *= w[..., None, None]
    # Segment s runs from vertex s to vertex s + 1: vertex k gets -dv_dr1 of segment k and
    # -dv_dr2 of segment k - 1; (npt, np, vertex, c, d) -> (npt, np, c, vertex, d).
    d_vert = dv1 + np.roll(dv2, 1, axis=2)
    out["ring_d_point"] = np.sum(d_vert, axis=2)
    np.negative(d_vert, out=d_vert)
    out["ring_d_vertices"] = d_vert.transpose(0, 1, 3, 2, 4)
    out["wake_d_point"] = res3[1] - res4[1]
    out["wake_d_p3"] = -res3[1]
    out["wake_d_p4"] = res4[1]
    out["wake_d_u"] = res3[2] - res4[2]
    return out
