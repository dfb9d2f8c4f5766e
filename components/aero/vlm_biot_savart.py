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

Internally the kernels work on component-first arrays (vectors of shape (3, ...)), so that every
elementwise operation runs over the long point and panel axes rather than over a trailing axis of
3; the public kernels take and return the usual trailing-axis layout. Each derivative is a rank-one
matrix plus a skew one (dv/dr = a b^T + S(q)); the cores return these factors, and
:func:`lattice_velocities` writes the 3 x 3 blocks straight into the Jacobian layout of its callers.
"""

import numpy as np

INV_4PI = 0.25 / np.pi
#: Relative vortex-core size of both kernels (see module docstring).
CORE = 1.0e-6
# Segment s of a ring runs from vertex s to vertex _NEXT[s]; vertex v ends segment _PREV[v].
_NEXT = [1, 2, 3, 0]
_PREV = [3, 0, 1, 2]


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


def _dot0(a, b):
    """Dot product of component-first arrays (3, ...)."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross0(a, b):
    """Cross product of component-first arrays (3, ...), broadcasting."""
    return np.stack(
        (
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        )
    )


# -sum over k of x[..., k, :] for k < n, as x.reshape(-1, 3 n) @ _NEG_SUM[n] (one matrix product;
# numpy reductions over short axes are slow).
_NEG_SUM = {n: -np.tile(np.eye(3), (n, 1)) for n in (2, 4)}


def _neg_sum(x):
    """-sum_k x[..., k, :] over the short second-last axis of a C-contiguous x (..., n, 3)."""
    n = x.shape[-2]
    return (x.reshape(-1, 3 * n) @ _NEG_SUM[n]).reshape(x.shape[:-2] + (3,))


def _fill_rank_one_plus_skew(out, pairs, q):
    """Write out[c, d] = sum over (a, b) in ``pairs`` of a[c] b[d], plus S(q)[c, d].

    ``out`` is a (3, 3, ...) view of a Jacobian (velocity component c, coordinate d), and ``a``,
    ``b``, ``q`` are component-first arrays that broadcast against out[c, d]; S(q)[c, d] is
    -q[e] or +q[e] off the diagonal (e the third index) and 0 on it. Each block is formed
    contiguous and copied once into the (strided) view.
    """
    for c in range(3):
        for d in range(3):
            (a, b), *rest = pairs
            block = a[c] * b[d]
            for a, b in rest:
                block += a[c] * b[d]
            if c != d:
                e = 3 - c - d
                if (c - d) % 3 == 1:
                    block += q[e]
                else:
                    block -= q[e]
            out[c, d] = block


def _segment(r1, r2, derivatives):
    """Component-first core of :func:`segment_velocity`: r1, r2 (3, ...).

    Returns v and, with ``derivatives``, (v, kc, g1, g2, ks) with
    dv/dr1 = kc g1^T - ks S(r2) and dv/dr2 = kc g2^T + ks S(r1).
    """
    n1 = np.sqrt(_dot0(r1, r1))
    n2 = np.sqrt(_dot0(r2, r2))
    c = _cross0(r1, r2)
    d = _dot0(r1, r2)
    r0 = r1 - r2
    r0s = _dot0(r0, r0)
    m = n1 * n2
    den = m * (m + d) + CORE**2 * r0s**2
    s = n1 + n2
    inv = INV_4PI / den
    ks = inv * s
    v = ks * c
    if not derivatives:
        return v
    # dv/dr = k (c (x) (dn/dr - q dden/dr)) -/+ k s S(r_other), k = 1/(4 pi den), q = s/den:
    # the two outer products of c share c, so they are one. With dden/dr1 = a (n2/n1) r1 + m r2
    # + kappa r0 (a = 2 m + r1.r2, kappa = 4 eps^2 r0s) and r0 = r1 - r2, the vectors
    # g = dn/dr - q dden/dr are combinations of r1 and r2 alone.
    q = s / den
    a = 2.0 * m + d
    kappa = 4.0 * CORE**2 * r0s
    kc = inv * c
    both = q * (kappa - m)
    g1 = (1.0 / n1 - q * (a * (n2 / n1) + kappa)) * r1 + both * r2
    g2 = (1.0 / n2 - q * (a * (n1 / n2) + kappa)) * r2 + both * r1
    return v, kc, g1, g2, ks


def _semi_infinite(r, u, derivatives):
    """Component-first core of :func:`semi_infinite_velocity`: r, u (3, ...), broadcasting.

    Returns v and, with ``derivatives``, (v, kwq, dden_dr, nr, inv) with
    dv/dr = -kwq dden_dr^T + inv S(u) and dv/du = kwq nr^T - inv S(r).
    """
    n = np.sqrt(_dot0(r, r))
    t = _dot0(u, r)
    w = _cross0(u, r)
    den = (1.0 + CORE**2) * n**2 - n * t
    inv = INV_4PI / den
    v = inv * w
    if not derivatives:
        return v
    # dv/dr = k (S(u) - wq (x) dden/dr), dv/du = k (-S(r) - wq (x) dden/du), wq = w/den.
    kwq = (inv / den) * w
    dden_dr = 2.0 * (1.0 + CORE**2) * r - (t / n) * r - n * u
    return v, kwq, dden_dr, n * r, inv


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
    r1, r2 = np.broadcast_arrays(r1, r2)
    res = _segment(np.moveaxis(r1, -1, 0), np.moveaxis(r2, -1, 0), derivatives)
    if not derivatives:
        return np.moveaxis(res, 0, -1)
    v, kc, g1, g2, ks = (np.moveaxis(x, 0, -1) if x.ndim == r1.ndim else x for x in res)
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
    res = _semi_infinite(np.moveaxis(r, -1, 0), np.moveaxis(u, -1, 0), derivatives)
    if not derivatives:
        return np.moveaxis(res, 0, -1)
    v, kwq, dden_dr, nr, inv = (np.moveaxis(x, 0, -1) if x.ndim == r.ndim else x for x in res)
    dv_dr = outer(kwq, -dden_dr)
    _add_skew(dv_dr, u, inv)
    dv_du = outer(kwq, nr)
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
    and with ``derivatives``, as Jacobians whose velocity component c follows the point axis
    (c, then the ring, then the coordinate d differentiated by):
        ``ring_d_point`` (npt, c, np, d), ``ring_d_vertices`` (npt, c, np, 4, d),
        ``wake_d_point`` (nn, npt, c, nte, d), ``wake_d_corners`` (nn, npt, c, nte, 2, d)
        (by the corners p3 and p4 of the trailing-edge rings) and ``wake_d_u``
        (nn, npt, c, nte, d).
    """
    npt, npn = points.shape[0], ring_vertices.shape[0]
    # Component-first (3, npt, np, segment s): r1 = P - vertex s, r2 = P - vertex s + 1.
    # (C-ordered copies first: numpy would otherwise give r1 the memory layout of the inputs.)
    pts = np.ascontiguousarray(points.T)
    verts = np.ascontiguousarray(ring_vertices.transpose(2, 0, 1))
    r1 = pts[:, :, None, None] - verts[:, None]
    r2 = r1.take(_NEXT, axis=-1)
    w = np.broadcast_to(segment_weights, (npt, npn, 4))
    seg = _segment(r1, r2, derivatives)
    v = seg[0] if derivatives else seg
    wv = w * v
    out = {"ring": np.moveaxis(wv[..., 0] + wv[..., 1] + wv[..., 2] + wv[..., 3], 0, -1)}

    # Wake legs on a last axis of 2: from p3 along +u and from p4 along -u (sign -1).
    corners = np.ascontiguousarray(verts[:, te_panels, 2:4])  # (3, nte, 2)
    rw = pts[:, None, :, None, None] - corners[:, None, None]  # (3, 1, npt, nte, 2)
    u = np.ascontiguousarray(wake_direction.T)[:, :, None, None, None]  # (3, nn, 1, 1, 1)
    wake = _semi_infinite(rw, u, derivatives)
    vw = wake[0] if derivatives else wake
    out["wake"] = np.moveaxis(vw[..., 0] - vw[..., 1], 0, -1)
    if not derivatives:
        return out

    # Vertex v ends segment v (dv/dA = -dv_dr1) and segment v - 1 (dv/dB = -dv_dr2):
    # d/dvertex_v = -(w kc)_v g1_v^T - (w kc)_(v-1) g2_(v-1)^T + S((w ks r2)_v - (w ks r1)_(v-1)).
    _, kc, g1, g2, ks = seg
    a = -w * kc
    wks = w * ks
    d_vert = np.empty((npt, 3, npn, 4, 3), dtype=a.dtype)
    _fill_rank_one_plus_skew(
        np.moveaxis(d_vert, (1, 4), (0, 1)),
        [(a, g1), (a.take(_PREV, axis=-1), g2.take(_PREV, axis=-1))],
        wks * r2 - (wks * r1).take(_PREV, axis=-1),
    )
    out["ring_d_vertices"] = d_vert
    out["ring_d_point"] = _neg_sum(d_vert)

    # Leg l (sign s_l) from corner p: d/dp = -s_l dv/dr = s_l (kwq dden_dr^T - inv S(u)) and
    # d/du = sum_l s_l (kwq nr^T - inv S(r)); kwq and inv take the signs in place.
    _, kwq, dden_dr, nr, inv = wake
    kwq[..., 1] *= -1.0
    inv[..., 1] *= -1.0
    nn, nte = wake_direction.shape[0], te_panels.size
    d_corners = np.empty((nn, npt, 3, nte, 2, 3), dtype=kwq.dtype)
    _fill_rank_one_plus_skew(np.moveaxis(d_corners, (2, 5), (0, 1)), [(kwq, dden_dr)], -inv * u)
    out["wake_d_corners"] = d_corners
    out["wake_d_point"] = _neg_sum(d_corners)
    d_u = np.empty((nn, npt, 3, nte, 3), dtype=kwq.dtype)
    inv_r = inv * rw
    _fill_rank_one_plus_skew(
        np.moveaxis(d_u, (2, 4), (0, 1)),
        [(kwq[..., 0], nr[..., 0]), (kwq[..., 1], nr[..., 1])],
        -inv_r[..., 0] - inv_r[..., 1],
    )
    out["wake_d_u"] = d_u
    return out
