"""Velocity induced by the solved vortex lattice at the force points (bound-segment midpoints)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_biot_savart import lattice_velocities
from lpc_mdo.components.aero.vlm_lattice import declare_lattice_options, lattice_of


class VLMInducedVelocityComp(om.ExplicitComponent):
    """
    Induced velocity w at every force point from all rings and wakes (paper eq. 11's v_ind).

        w[n, i] = sum_j Gamma[n, j] (v_ring_j(x_f,i) + [j trailing edge] v_wake_j(x_f,i; u_n))

    docs theory/aerodynamics 'Forces and induced drag'. The two segments that pass through force
    point i (its own bound segment and the coincident p3->p4 segment of the ring upstream) are left
    out: they induce nothing there, and the kernel would be singular on them. Bound segments
    of neighbouring strips that are collinear with the force point are regular in the AVL/OAS
    kernel. Analytic partials (dense in the circulation and the ring corners, sparse in the
    force points).

    Inputs
    ------
    ring_vertices : float, (np, 4, 3), m
    force_points : float, (np, 3), m
    freestream_direction : float, (nn, 3)
        Wake direction.
    circulation : float, (nn, np), m**2/s

    Outputs
    -------
    induced_velocities : float, (nn, np, 3), m/s

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
        self._weights = lat.force_point_segment_weights()
        self.add_input(
            "ring_vertices",
            np.zeros((npn, 4, 3)),
            units="m",
            desc="corners p1..p4 of the vortex rings",
        )
        self.add_input("force_points", np.zeros((npn, 3)), units="m", desc="force points")
        self.add_input(
            "freestream_direction",
            np.zeros((nn, 3)),
            units=None,
            desc="unit vector along the relative wind (wake direction)",
        )
        self.add_input("circulation", np.zeros((nn, npn)), units="m**2/s", desc="ring circulations")
        self.add_output(
            "induced_velocities",
            np.zeros((nn, npn, 3)),
            units="m/s",
            desc="velocity induced by the lattice at the force points",
        )

        n_r, i_r, c_r = (
            a.ravel()
            for a in np.meshgrid(np.arange(nn), np.arange(npn), np.arange(3), indexing="ij")
        )
        row = (n_r * npn + i_r) * 3 + c_r
        self.declare_partials(
            "induced_velocities",
            "circulation",
            rows=np.repeat(row, npn),
            cols=(npn * np.repeat(n_r, npn) + np.tile(np.arange(npn), row.size)),
        )
        self.declare_partials("induced_velocities", "ring_vertices")  # dense
        self.declare_partials(
            "induced_velocities",
            "force_points",
            rows=np.repeat(row, 3),
            cols=3 * np.repeat(i_r, 3) + np.tile(np.arange(3), row.size),
        )
        self.declare_partials(
            "induced_velocities",
            "freestream_direction",
            rows=np.repeat(row, 3),
            cols=3 * np.repeat(n_r, 3) + np.tile(np.arange(3), row.size),
        )

    def _velocities(self, inputs, derivatives):
        return lattice_velocities(
            inputs["force_points"],
            inputs["ring_vertices"],
            self._lattice.te_panels,
            inputs["freestream_direction"],
            self._weights,
            derivatives,
        )

    def compute(self, inputs, outputs):
        te = self._lattice.te_panels
        gamma = inputs["circulation"]
        vel = self._velocities(inputs, False)
        outputs["induced_velocities"] = np.einsum("ijc,nj->nic", vel["ring"], gamma) + np.einsum(
            "nitc,nt->nic", vel["wake"], gamma[:, te]
        )

    def compute_partials(self, inputs, partials):
        nn = self.options["num_nodes"]
        te = self._lattice.te_panels
        npn = self._lattice.num_panels
        gamma = inputs["circulation"]
        g_te = gamma[:, te]
        vel = self._velocities(inputs, True)

        total = np.broadcast_to(vel["ring"][None], (nn,) + vel["ring"].shape).copy()
        total[:, :, te] += vel["wake"]
        partials["induced_velocities", "circulation"] = total.transpose(0, 1, 3, 2).ravel()

        # Jacobians of lattice_velocities: (.., npt, c, ...), ring ones without the node axis.
        d_vert = vel["ring_d_vertices"][None] * gamma[:, None, None, :, None, None]
        d_vert[:, :, :, te, 2:4] += vel["wake_d_corners"] * g_te[:, None, None, :, None, None]
        partials["induced_velocities", "ring_vertices"] = d_vert.reshape(nn * npn * 3, npn * 12)

        partials["induced_velocities", "force_points"] = (
            np.einsum("icjd,nj->nicd", vel["ring_d_point"], gamma)
            + np.einsum("nictd,nt->nicd", vel["wake_d_point"], g_te)
        ).ravel()
        partials["induced_velocities", "freestream_direction"] = np.einsum(
            "nictd,nt->nicd", vel["wake_d_u"], g_te
        ).ravel()
