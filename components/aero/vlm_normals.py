"""Boundary-condition normals of the flat vortex lattice, tilted for camber and deflection."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_biot_savart import cross, dot, outer, skew
from lpc_mdo.components.aero.vlm_lattice import declare_lattice_options, lattice_of


class VLMNormalsComp(om.ExplicitComponent):
    """
    Unit normals of the vortex rings, rotated about the span-wise axis by the section incidence.

    Geometric normal (docs theory/aerodynamics 'Lattice'): n = (p3 - p1) x (p2 - p4), normalised; it
    points up (-z) on a wing. Camber and control deflections enter the flat lattice as an incidence
    increment of the boundary condition (the AVL treatment):

        theta = -alpha_L0 (strip) + delta (deflectable surfaces),
        n' = n cos(theta) + (s x n) sin(theta) + s (s.n) (1 - cos(theta)),

    a Rodrigues rotation about the unit bound vector s = (p2 - p1)/norm(p2 - p1), positive nose up.
    A section with zero-lift angle alpha_L0 < 0 (positive camber) then carries lift at zero
    geometric incidence, as in docs theory/aerodynamics 'Airfoil coupling', and a trailing-edge-down
    deflection delta > 0 of an all-moving tail adds incidence. The mesh itself is not moved.

    Inputs
    ------
    ring_vertices : float, (np, 4, 3), m
    {name}_zero_lift_angle : float, (nn, ns), rad
        Sectional zero-lift angle of each strip of each surface (from the airfoil polar).
    {name}_deflection : float, (nn,), rad
        Only for surfaces with ``deflectable=True``; positive trailing edge down.

    Outputs
    -------
    boundary_normals : float, (nn, np, 3)
        Tilted unit normals used in the boundary condition (paper eq. 10).

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
        self.add_input(
            "ring_vertices",
            np.zeros((npn, 4, 3)),
            units="m",
            desc="corners p1..p4 of the vortex rings",
        )
        self.add_output(
            "boundary_normals",
            np.zeros((nn, npn, 3)),
            units=None,
            desc="unit normals tilted by -alpha_L0 + deflection",
        )
        rows = np.repeat(np.arange(nn * npn * 3), 12)
        k = np.tile(np.repeat(np.arange(npn), 3), nn)
        cols = 12 * np.repeat(k, 12) + np.tile(np.arange(12), nn * npn * 3)
        self.declare_partials("boundary_normals", "ring_vertices", rows=rows, cols=cols)

        for isurf, s in enumerate(lat.surfaces):
            ns = s.num_span_panels
            panels = np.arange(npn)[lat.surface_panels(isurf)]
            rows_s = (
                3 * (npn * np.arange(nn)[:, None, None] + panels[None, :, None]) + np.arange(3)
            ).ravel()
            strip_local = lat.panel_strip[panels] - lat.strip_offset[isurf]
            cols_s = np.broadcast_to(
                ns * np.arange(nn)[:, None, None] + strip_local[None, :, None], (nn, panels.size, 3)
            ).ravel()
            name = f"{s.name}_zero_lift_angle"
            self.add_input(
                name,
                np.zeros((nn, ns)),
                units="rad",
                desc=f"sectional zero-lift angle of the strips of '{s.name}'",
            )
            self.declare_partials("boundary_normals", name, rows=rows_s, cols=cols_s)
            if s.deflectable:
                name = f"{s.name}_deflection"
                self.add_input(
                    name,
                    np.zeros(nn),
                    units="rad",
                    desc=f"all-moving deflection of '{s.name}', trailing edge down",
                )
                self.declare_partials(
                    "boundary_normals",
                    name,
                    rows=rows_s,
                    cols=np.broadcast_to(
                        np.arange(nn)[:, None, None], (nn, panels.size, 3)
                    ).ravel(),
                )

    def _incidence(self, inputs):
        lat = self._lattice
        nn = self.options["num_nodes"]
        pieces = []
        for s in lat.surfaces:
            theta = -inputs[f"{s.name}_zero_lift_angle"]
            theta = np.tile(theta, (1, s.num_chord_panels))  # (nn, np_s) in row order
            if s.deflectable:
                theta = theta + inputs[f"{s.name}_deflection"][:, None]
            pieces.append(theta.reshape(nn, s.num_panels))
        return np.concatenate(pieces, axis=1)

    def _parts(self, inputs):
        v = inputs["ring_vertices"]
        a = v[:, 2] - v[:, 0]
        b = v[:, 1] - v[:, 3]
        n_raw = cross(a, b)
        n_len = np.sqrt(dot(n_raw, n_raw))
        n = n_raw / n_len[:, None]
        bound = v[:, 1] - v[:, 0]
        b_len = np.sqrt(dot(bound, bound))
        s = bound / b_len[:, None]
        return a, b, n_len, n, b_len, s

    def compute(self, inputs, outputs):
        _, _, _, n, _, s = self._parts(inputs)
        theta = self._incidence(inputs)
        c, si = np.cos(theta)[..., None], np.sin(theta)[..., None]
        sxn = cross(s, n)[None]
        sdn = dot(s, n)[None, :, None]
        outputs["boundary_normals"] = n[None] * c + sxn * si + s[None] * sdn * (1.0 - c)

    def compute_partials(self, inputs, partials):
        lat = self._lattice
        a, b, n_len, n, b_len, s = self._parts(inputs)
        theta = self._incidence(inputs)
        c, si = np.cos(theta)[..., None, None], np.sin(theta)[..., None, None]
        eye = np.eye(3)
        sdn = dot(s, n)[:, None, None]
        # n' as a function of n, s and theta
        d_n = c * eye + si * skew(s)[None] + (1.0 - c) * outer(s, s)[None]
        d_s = -si * skew(n)[None] + (1.0 - c) * (sdn * eye + outer(s, n))[None]
        d_theta = (
            -si[..., 0] * n[None]
            + c[..., 0] * cross(s, n)[None]
            + si[..., 0] * s[None] * sdn[None, :, :, 0]
        )  # (nn, np, 3)
        # n = n_raw/|n_raw|, n_raw = a x b with a = p3 - p1, b = p2 - p4
        dn_draw = (eye - outer(n, n)) / n_len[:, None, None]
        dn_da = dn_draw @ -skew(b)
        dn_db = dn_draw @ skew(a)
        ds_dl = (eye - outer(s, s)) / b_len[:, None, None]
        dn_dv = np.stack([-dn_da, dn_db, dn_da, -dn_db], axis=-2)  # (np, 3, 4, 3)
        ds_dv = np.stack([-ds_dl, ds_dl, np.zeros_like(ds_dl), np.zeros_like(ds_dl)], axis=-2)
        jac = np.einsum("nkij,kjvd->nkivd", d_n, dn_dv) + np.einsum("nkij,kjvd->nkivd", d_s, ds_dv)
        partials["boundary_normals", "ring_vertices"] = jac.ravel()
        for isurf, surf in enumerate(lat.surfaces):
            sl = lat.surface_panels(isurf)
            partials["boundary_normals", f"{surf.name}_zero_lift_angle"] = (-d_theta[:, sl]).ravel()
            if surf.deflectable:
                partials["boundary_normals", f"{surf.name}_deflection"] = d_theta[:, sl].ravel()
