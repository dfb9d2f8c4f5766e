"""Aerodynamic influence coefficient (AIC) matrix of the vortex lattice."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_biot_savart import lattice_velocities
from lpc_mdo.components.aero.vlm_lattice import declare_lattice_options, lattice_of


class VLMAICComp(om.ExplicitComponent):
    """
    AIC matrix A of paper eq. 10, the wake included.

    A[n, i, j] is the normal velocity at collocation point i per unit circulation of ring j.

    docs theory/aerodynamics 'Biot-Savart kernels', 'Circulation system':

        A[n, i, j] = (sum over the segments of ring j of v_seg(x_i)
                      + [j trailing edge] (v_inf(x_i; p3, u_n) - v_inf(x_i; p4, u_n))) . n'_i

    with the AVL/OAS form of the Biot–Savart kernels
    (:mod:`~lpc_mdo.components.aero.vlm_biot_savart`). The wake of each strip is a
    semi-infinite vortex pair from the bound-grid trailing-edge nodes along the relative wind
    u = e_D (docs theory/aerodynamics 'Wake'), so A depends on the flight condition n. All VLM
    surfaces are in one lattice, so wing–tail interference is included.

    Partials are analytic and sparse in the structure of the problem: A[n, i, j] depends on the
    12 corner coordinates of ring j, the collocation point and normal of panel i and (trailing-
    edge rings) the wake direction of node n.

    Inputs
    ------
    ring_vertices : float, (np, 4, 3), m
    collocation_points : float, (np, 3), m
    boundary_normals : float, (nn, np, 3)
    freestream_direction : float, (nn, 3)
        Unit vector along the relative wind; the wake direction.

    Outputs
    -------
    aic : float, (nn, np, np), 1/m

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
        npn, nte = lat.num_panels, lat.te_panels.size
        self._weights = lat.collocation_segment_weights()
        self.add_input(
            "ring_vertices",
            np.zeros((npn, 4, 3)),
            units="m",
            desc="corners p1..p4 of the vortex rings",
        )
        self.add_input(
            "collocation_points", np.zeros((npn, 3)), units="m", desc="collocation points"
        )
        self.add_input(
            "boundary_normals",
            np.zeros((nn, npn, 3)),
            units=None,
            desc="boundary-condition unit normals",
        )
        self.add_input(
            "freestream_direction",
            np.zeros((nn, 3)),
            units=None,
            desc="unit vector along the relative wind (wake direction)",
        )
        self.add_output(
            "aic",
            np.zeros((nn, npn, npn)),
            units="1/m",
            desc="normal velocity at collocation point i per unit circulation of ring j",
        )

        n_i, i_i, j_i = (
            a.ravel()
            for a in np.meshgrid(np.arange(nn), np.arange(npn), np.arange(npn), indexing="ij")
        )
        row = (n_i * npn + i_i) * npn + j_i  # flat index of A[n, i, j]
        three = np.arange(3)
        self.declare_partials(
            "aic",
            "boundary_normals",
            rows=np.repeat(row, 3),
            cols=(3 * np.repeat(n_i * npn + i_i, 3) + np.tile(three, row.size)),
        )
        self.declare_partials(
            "aic",
            "collocation_points",
            rows=np.repeat(row, 3),
            cols=(3 * np.repeat(i_i, 3) + np.tile(three, row.size)),
        )
        self.declare_partials(
            "aic",
            "ring_vertices",
            rows=np.repeat(row, 12),
            cols=(12 * np.repeat(j_i, 12) + np.tile(np.arange(12), row.size)),
        )
        n_t, i_t, t_t = (
            a.ravel()
            for a in np.meshgrid(np.arange(nn), np.arange(npn), np.arange(nte), indexing="ij")
        )
        row_t = (n_t * npn + i_t) * npn + lat.te_panels[t_t]
        self.declare_partials(
            "aic",
            "freestream_direction",
            rows=np.repeat(row_t, 3),
            cols=3 * np.repeat(n_t, 3) + np.tile(three, row_t.size),
        )

    def _velocities(self, inputs, derivatives):
        lat = self._lattice
        return lattice_velocities(
            inputs["collocation_points"],
            inputs["ring_vertices"],
            lat.te_panels,
            inputs["freestream_direction"],
            self._weights,
            derivatives,
        )

    def compute(self, inputs, outputs):
        te = self._lattice.te_panels
        vel = self._velocities(inputs, False)
        normals = inputs["boundary_normals"]
        aic = np.einsum("ijc,nic->nij", vel["ring"], normals)
        aic[:, :, te] += np.einsum("nitc,nic->nit", vel["wake"], normals)
        outputs["aic"] = aic

    def compute_partials(self, inputs, partials):
        nn = self.options["num_nodes"]
        te = self._lattice.te_panels
        vel = self._velocities(inputs, True)
        normals = inputs["boundary_normals"]

        total = np.broadcast_to(vel["ring"][None], (nn,) + vel["ring"].shape).copy()
        total[:, :, te] += vel["wake"]
        partials["aic", "boundary_normals"] = total.ravel()

        # Jacobians of lattice_velocities: (.., npt, c, ...), ring ones without the node axis.
        d_point = _normal_part(normals, vel["ring_d_point"][None])
        d_point[:, :, te] += _normal_part(normals, vel["wake_d_point"])
        partials["aic", "collocation_points"] = d_point.ravel()

        d_vert = _normal_part(normals, vel["ring_d_vertices"][None])
        d_vert[:, :, te, 2:4] += _normal_part(normals, vel["wake_d_corners"])
        partials["aic", "ring_vertices"] = d_vert.ravel()

        partials["aic", "freestream_direction"] = _normal_part(normals, vel["wake_d_u"]).ravel()


def _normal_part(normals, d):
    """sum_c normals[n, i, c] d[n, i, c, ...]: the normal's row of velocity derivatives.

    Explicit over the three components (faster than einsum on these small axes); ``d`` has the
    velocity component on axis 2 and may have a node axis of 1.
    """
    extra = (None,) * (d.ndim - 3)
    return sum(normals[(slice(None), slice(None), c) + extra] * d[:, :, c] for c in range(3))
