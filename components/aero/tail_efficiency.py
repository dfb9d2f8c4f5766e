"""Tail efficiency: the horizontal tail's loads at its own dynamic pressure q_t = eta_t q."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


class TailEfficiencyComp(om.ExplicitComponent):
    """
    Correction of the lattice force and moment for the tail's dynamic-pressure ratio.

    The lattice sees the free-stream q at the tail; the wing's wake and the fuselage slow the
    flow there, q_t = eta_t q (Raymer, *Aircraft Design*, 6th ed., sec. 16.3 and eq. 16.12;
    eta_t about 0.9 for a conventional tail). The tail's panel loads F_k (inviscid plus
    profile drag) are scaled by eta_t, i.e. corrected by

        dF = -(1 - eta_t) sum_tail F_k,   dM = -(1 - eta_t) sum_tail r_k x F_k

    (about the body origin, the lattice's moment reference). The downwash stays the
    lattice's own (the tail's circulation is solved with the wing's wake).

    Inputs
    ------
    panel_forces, viscous_panel_forces : (nn, np, 3), N
    force_points : (np, 3), m

    Outputs
    -------
    tail_force_correction : (nn, 3), N
    tail_moment_correction : (nn, 3), N*m

    Options
    -------
    num_nodes, num_panels : int
    tail_panels : tuple (start, stop)
        Lattice panel indices of the horizontal tail.
    dynamic_pressure_ratio : float
        eta_t.
    """

    def initialize(self):
        self.options.declare("num_nodes", default=1, types=int, lower=1)
        self.options.declare("num_panels", types=int, lower=1)
        self.options.declare("tail_panels", types=tuple, desc="(start, stop) panel indices")
        self.options.declare("dynamic_pressure_ratio", types=float, desc="eta_t = q_t/q")

    def setup(self):
        nn, npn = self.options["num_nodes"], self.options["num_panels"]
        check_range(
            "tail_dynamic_pressure_ratio",
            self.options["dynamic_pressure_ratio"],
            lower=0.5,
            upper=1.2,
            where=self.msginfo,
        )
        for name in ("panel_forces", "viscous_panel_forces"):
            self.add_input(name, np.zeros((nn, npn, 3)), units="N", desc=name.replace("_", " "))
        self.add_input("force_points", np.zeros((npn, 3)), units="m", desc="force points")
        self.add_output(
            "tail_force_correction", np.zeros((nn, 3)), units="N", desc="tail-efficiency force"
        )
        self.add_output(
            "tail_moment_correction",
            np.zeros((nn, 3)),
            units="N*m",
            desc="tail-efficiency moment about the body origin",
        )
        start, stop = self.options["tail_panels"]
        k = 1.0 - self.options["dynamic_pressure_ratio"]
        # Force: constant sparse partials -k on the tail panels.
        n, t, d = np.meshgrid(np.arange(nn), np.arange(start, stop), np.arange(3), indexing="ij")
        rows = (3 * n + d).ravel()
        cols = ((n * npn + t) * 3 + d).ravel()
        for name in ("panel_forces", "viscous_panel_forces"):
            self.declare_partials("tail_force_correction", name, rows=rows, cols=cols, val=-k)
            self.declare_partials("tail_moment_correction", name)
        self.declare_partials("tail_moment_correction", "force_points")

    def _tail(self, inputs):
        start, stop = self.options["tail_panels"]
        f = inputs["panel_forces"][:, start:stop] + inputs["viscous_panel_forces"][:, start:stop]
        return f, inputs["force_points"][start:stop]

    def compute(self, inputs, outputs):
        k = 1.0 - self.options["dynamic_pressure_ratio"]
        f, r = self._tail(inputs)
        outputs["tail_force_correction"] = -k * f.sum(axis=1)
        outputs["tail_moment_correction"] = -k * np.cross(r[None], f).sum(axis=1)

    def compute_partials(self, inputs, partials):
        nn, npn = self.options["num_nodes"], self.options["num_panels"]
        start, stop = self.options["tail_panels"]
        k = 1.0 - self.options["dynamic_pressure_ratio"]
        f, r = self._tail(inputs)
        # d(r x F)/dF = skew(r); d(r x F)/dr = -skew(F).
        d_f = np.zeros((nn, 3, nn, npn, 3))
        d_r = np.zeros((nn, 3, npn, 3))
        for node in range(nn):
            d_f[node, :, node, start:stop, :] = -k * _skew(r).transpose(1, 0, 2)
            d_r[node, :, start:stop, :] = k * _skew(f[node]).transpose(1, 0, 2)
        for name in ("panel_forces", "viscous_panel_forces"):
            partials["tail_moment_correction", name] = d_f.reshape(nn * 3, nn * npn * 3)
        partials["tail_moment_correction", "force_points"] = d_r.reshape(nn * 3, npn * 3)


def _skew(v):
    """Cross-product matrices of the rows of v (m, 3): skew(v)[i] @ u = v[i] x u."""
    s = np.zeros(v.shape[:-1] + (3, 3), dtype=v.dtype)
    s[..., 0, 1], s[..., 0, 2] = -v[..., 2], v[..., 1]
    s[..., 1, 0], s[..., 1, 2] = v[..., 2], -v[..., 0]
    s[..., 2, 0], s[..., 2, 1] = -v[..., 1], v[..., 0]
    return s
