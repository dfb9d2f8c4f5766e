"""Kutta–Joukowski forces on the bound vortex segments (paper eq. 11)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_biot_savart import cross, skew
from lpc_mdo.components.aero.vlm_lattice import declare_lattice_options, lattice_of
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY


class VLMPanelForcesComp(om.ExplicitComponent):
    """
    Inviscid panel forces F = rho Gamma_net (v + w) x l (paper eq. 11), body axes.

    docs theory/aerodynamics 'Forces and induced drag': the bound segment of ring (i, j) carries the
    net circulation Gamma_net = Gamma[i, j] - Gamma[i-1, j] (Gamma[0, j] on the leading-edge row); v
    is the relative wind and w the induced velocity at its midpoint (the force point), l the
    bound vector. Lift and near-field induced drag both come out of F.

    Inputs
    ------
    circulation : float, (nn, np), m**2/s
    force_point_velocities : float, (nn, np, 3), m/s
        Relative wind at the force points.
    induced_velocities : float, (nn, np, 3), m/s
    bound_vectors : float, (np, 3), m
    density : float, (nn,), kg/m**3

    Outputs
    -------
    panel_forces : float, (nn, np, 3), N

    Options
    -------
    surfaces : tuple of VLMSurface
    num_nodes : int
    """

    def initialize(self):
        declare_lattice_options(self)

    def setup(self):
        nn = self.options["num_nodes"]
        lat = self._lattice = lattice_of(self.options["surfaces"])
        npn = lat.num_panels
        self.add_input("circulation", np.zeros((nn, npn)), units="m**2/s", desc="ring circulations")
        self.add_input(
            "force_point_velocities",
            np.zeros((nn, npn, 3)),
            units="m/s",
            desc="relative wind at the force points",
        )
        self.add_input(
            "induced_velocities",
            np.zeros((nn, npn, 3)),
            units="m/s",
            desc="induced velocity at the force points",
        )
        self.add_input("bound_vectors", np.zeros((npn, 3)), units="m", desc="bound segment vectors")
        self.add_input(
            "density", np.full(nn, SEA_LEVEL_DENSITY), units="kg/m**3", desc="air density"
        )
        self.add_output(
            "panel_forces",
            np.zeros((nn, npn, 3)),
            units="N",
            desc="Kutta-Joukowski force on each bound segment, body axes",
        )

        n_r, k_r, c_r = (
            a.ravel()
            for a in np.meshgrid(np.arange(nn), np.arange(npn), np.arange(3), indexing="ij")
        )
        row = (n_r * npn + k_r) * 3 + c_r
        # Gamma_net depends on Gamma[k] and Gamma[upstream(k)].
        up = lat.upstream_panel
        has_up = np.broadcast_to(up[None, :, None] >= 0, (nn, npn, 3)).ravel()
        self._has_up = has_up
        rows_g = np.concatenate([row, row[has_up]])
        cols_g = np.concatenate([n_r * npn + k_r, (n_r * npn + up[k_r])[has_up]])
        self.declare_partials("panel_forces", "circulation", rows=rows_g, cols=cols_g)
        blk_rows = np.repeat(row, 3)
        d = np.tile(np.arange(3), row.size)
        self.declare_partials(
            "panel_forces",
            ["force_point_velocities", "induced_velocities"],
            rows=blk_rows,
            cols=3 * np.repeat(n_r * npn + k_r, 3) + d,
        )
        self.declare_partials(
            "panel_forces", "bound_vectors", rows=blk_rows, cols=3 * np.repeat(k_r, 3) + d
        )
        self.declare_partials("panel_forces", "density", rows=row, cols=n_r)

    def _net_circulation(self, gamma):
        up = self._lattice.upstream_panel
        upstream = np.where(up[None, :] >= 0, gamma[:, np.maximum(up, 0)], 0.0)
        return gamma - upstream

    def compute(self, inputs, outputs):
        g_net = self._net_circulation(inputs["circulation"])
        vel = inputs["force_point_velocities"] + inputs["induced_velocities"]
        rho = inputs["density"]
        outputs["panel_forces"] = (rho[:, None] * g_net)[..., None] * cross(
            vel, inputs["bound_vectors"][None]
        )

    def compute_partials(self, inputs, partials):
        g_net = self._net_circulation(inputs["circulation"])
        vel = inputs["force_point_velocities"] + inputs["induced_velocities"]
        rho = inputs["density"]
        bound = inputs["bound_vectors"]
        vxl = cross(vel, bound[None])  # (nn, np, 3)
        d_g = (rho[:, None, None] * vxl).ravel()
        partials["panel_forces", "circulation"] = np.concatenate([d_g, -d_g[self._has_up]])
        scale = (rho[:, None] * g_net)[..., None, None]
        d_vel = -scale * skew(bound)[None]  # v x l = -l x v
        partials["panel_forces", "force_point_velocities"] = d_vel.ravel()
        partials["panel_forces", "induced_velocities"] = d_vel.ravel()
        partials["panel_forces", "bound_vectors"] = (scale * skew(vel)).ravel()
        partials["panel_forces", "density"] = (g_net[..., None] * vxl).ravel()
