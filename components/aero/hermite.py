"""
C1 interpolation of tabulated data: one cubic Hermite axis and the tensor product over three.

:class:`HermiteAxis` is one grid with cubic Hermite interpolation whose node slopes are 3-point
(parabola) finite differences, evaluated as weights on a 4-point window so that a tensor product
is a gather plus an einsum; :func:`tensor_eval` is that tensor product over the three leading
axes of a table, with the three partial derivatives. The airfoil polars
(:mod:`lpc_mdo.components.aero.airfoil`) and the section pressure tables
(:mod:`lpc_mdo.components.aero.pressure_table`) both interpolate their (alpha, Re, M) tables with
them (cubic Hermite interpolation: de Boor, *A Practical Guide to Splines*, 2001, ch. IV).
"""

import numpy as np

__all__ = ["HermiteAxis", "tensor_eval"]


class HermiteAxis:
    """
    A 1-D grid with C1 cubic Hermite interpolation and 3-point finite-difference node slopes.

    The node slopes are the slopes of the parabola through each node and its neighbours
    (one-sided parabolas at the ends), so the interpolant is linear in the node values.

    The interpolant on interval k is sum_j W_kj(t) f_(s_k + j), j < width, with W_kj cubic in the
    local coordinate t; :meth:`weights` returns the window start s_k and the weights and their
    derivatives. Queries outside the grid are clamped to its ends (zero derivative weights beyond
    them).

    Parameters
    ----------
    nodes : array_like
        Strictly increasing grid values (any count >= 1; one node means a constant).
    log : bool
        Interpolate in ln(x) (for Reynolds numbers); nodes must be > 0.
    """

    _H = np.array(
        [
            [1.0, 0.0, -3.0, 2.0],  # h00
            [0.0, 1.0, -2.0, 1.0],  # h10 (times h)
            [0.0, 0.0, 3.0, -2.0],  # h01
            [0.0, 0.0, -1.0, 1.0],
        ]
    )  # h11 (times h)

    def __init__(self, nodes, log=False):
        nodes = np.asarray(nodes, dtype=float)
        if nodes.ndim != 1 or nodes.size < 1 or not np.all(np.isfinite(nodes)):
            raise ValueError(f"HermiteAxis: nodes must be a finite 1-D array, got {nodes!r}")
        if np.any(np.diff(nodes) <= 0.0):
            raise ValueError(f"HermiteAxis: nodes must be strictly increasing, got {nodes}")
        if log and nodes[0] <= 0.0:
            raise ValueError(f"HermiteAxis: log axis needs positive nodes, got {nodes}")
        self.nodes = nodes
        self.log = log
        self.x = np.log(nodes) if log else nodes
        n = nodes.size
        self.n = n
        self.width = min(n, 4)
        if n == 1:
            return
        x = self.x
        self.h = np.diff(x)
        d = self.slope_matrix(x)
        self.starts = np.clip(np.arange(n - 1) - 1, 0, n - self.width)
        coef = np.zeros((n - 1, 4, self.width))
        for k in range(n - 1):
            full = np.zeros((4, n))
            full[:, k] += self._H[0]
            full[:, k + 1] += self._H[2]
            full += self.h[k] * (np.outer(self._H[1], d[k]) + np.outer(self._H[3], d[k + 1]))
            s = self.starts[k]
            coef[k] = full[:, s : s + self.width]
        self.coef = coef

    @staticmethod
    def slope_matrix(x):
        """Matrix D with node slopes d = D f (3-point parabola slopes; secant if 2 nodes)."""
        n = x.size
        d = np.zeros((n, n))
        if n == 2:
            d[:, 0], d[:, 1] = -1.0 / (x[1] - x[0]), 1.0 / (x[1] - x[0])
            return d
        h = np.diff(x)
        for i in range(1, n - 1):
            h0, h1 = h[i - 1], h[i]
            d[i, i - 1 : i + 2] = (
                -h1 / (h0 * (h0 + h1)),
                (h1 - h0) / (h0 * h1),
                h0 / (h1 * (h0 + h1)),
            )
        h0, h1 = h[0], h[1]
        d[0, :3] = (
            -(2 * h0 + h1) / (h0 * (h0 + h1)),
            (h0 + h1) / (h0 * h1),
            -h0 / (h1 * (h0 + h1)),
        )
        h0, h1 = h[-2], h[-1]
        d[-1, -3:] = (
            h1 / (h0 * (h0 + h1)),
            -(h0 + h1) / (h0 * h1),
            (2 * h1 + h0) / (h1 * (h0 + h1)),
        )
        return d

    def weights(self, q, second=False):
        """
        Interpolation weights at the query points.

        Parameters
        ----------
        q : ndarray, (N,)
            Query values (real or complex; the interval comes from the real part).
        second : bool
            Also return second-derivative weights.

        Returns
        -------
        index : ndarray of int, (N, width)
            Node indices of each window.
        w, dw[, d2w] : ndarray, (N, width)
            Weights of the value and of d/dq (and d2/dq2) in the units of q (not ln q).
        """
        q = np.asarray(q)
        num = q.shape[0]
        dtype = np.result_type(q, float)
        if self.n == 1:
            ones = np.ones((num, 1), dtype=dtype)
            out = [np.zeros((num, 1), dtype=int), ones, np.zeros_like(ones)]
            return tuple(out + [np.zeros_like(ones)]) if second else tuple(out)
        qr = np.real(q)
        # Strictly outside: at an end node itself the derivative is the end interval's slope
        # (a query at a table's edge, e.g. a polar at its highest Mach number, keeps it).
        lo, hi = qr < self.nodes[0], qr > self.nodes[-1]
        clamped = lo | hi
        q_in = np.where(clamped, self.nodes[0], q)
        u = np.log(q_in) if self.log else q_in
        u = np.where(lo, self.x[0], np.where(hi, self.x[-1], u))
        k = np.clip(np.searchsorted(self.x, np.real(u), side="right") - 1, 0, self.n - 2)
        h = self.h[k]
        t = (u - self.x[k]) / h
        one, zero = np.ones_like(t), np.zeros_like(t)
        powers = np.stack([one, t, t * t, t * t * t], axis=-1)
        dpowers = np.stack([zero, one, 2 * t, 3 * t * t], axis=-1) / h[:, None]
        coef = self.coef[k]
        w = np.einsum("np,npj->nj", powers, coef)
        du_dq = np.where(clamped, 0.0, 1.0 / q_in if self.log else 1.0)
        dw = np.einsum("np,npj->nj", dpowers, coef) * du_dq[:, None]
        index = self.starts[k][:, None] + np.arange(self.width)
        if not second:
            return index, w, dw
        d2powers = np.stack([zero, zero, 2 * one, 6 * t], axis=-1) / (h * h)[:, None]
        d2w = np.einsum("np,npj->nj", d2powers, coef) * (du_dq**2)[:, None]
        if self.log:
            d2w = d2w - np.einsum("np,npj->nj", dpowers, coef) * (du_dq**2)[:, None]
        return index, w, dw, d2w


def tensor_eval(table, index, weights, dweights):
    """
    Tensor-product interpolation over the 3 leading table axes, with the 3 partial derivatives.

    value = sum_abc T[i_a, j_b, k_c, ...] u_a v_b w_c for each query; the derivative along an
    axis replaces that axis' weights by its derivative weights.

    Parameters
    ----------
    table : ndarray, (n1, n2, n3, ...)
    index : sequence of three (N, width) int arrays
        Node indices of each query's window on each axis.
    weights, dweights : sequences of three (N, width) arrays
        Value weights and derivative weights on each axis.

    Returns
    -------
    tuple of ndarray, each (N, *value_shape)
        (value, d/dq1, d/dq2, d/dq3).
    """
    i1, i2, i3 = index
    g = table[i1[:, :, None, None], i2[:, None, :, None], i3[:, None, None, :]]
    (u, v, w), (du, dv, dw) = weights, dweights
    g3 = np.einsum("nabc...,nc->nab...", g, w)
    g3d = np.einsum("nabc...,nc->nab...", g, dw)
    g23 = np.einsum("nab...,nb->na...", g3, v)
    g2d3 = np.einsum("nab...,nb->na...", g3, dv)
    g23d = np.einsum("nab...,nb->na...", g3d, v)
    return (
        np.einsum("na...,na->n...", g23, u),
        np.einsum("na...,na->n...", g23, du),
        np.einsum("na...,na->n...", g2d3, u),
        np.einsum("na...,na->n...", g23d, u),
    )
