"""Vortex-lattice geometry: rings, collocation and force points, bound vectors, panel areas."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.vlm_biot_savart import cross, dot, skew
from lpc_mdo.components.aero.vlm_lattice import (
    declare_lattice_options,
    lattice_of,
    sparse_pattern,
)


class VLMGeometryComp(om.ExplicitComponent):
    """
    Lattice geometry of all VLM surfaces from their meshes (mesh coordinates are inputs).

    Discretisation of docs theory/aerodynamics 'Lattice' (see
    :mod:`~lpc_mdo.components.aero.vlm_lattice`): vortex rings on the bound grid a quarter panel aft
    of the mesh, collocation points at the ring centres (3/4 chord), force points at the
    bound-segment midpoints (1/4 chord), bound vectors l = p2 - p1. Panel areas are those of the
    geometric mesh panels, norm((X[i+1,j+1] - X[i,j]) x (X[i,j+1] - X[i+1,j])) / 2; strip areas sum
    them chord-wise. Panels and strips of all surfaces are concatenated in ``surfaces`` order
    (np panels, nst strips in total).

    All outputs except the areas are linear in the mesh, with constant sparse partials declared
    in setup; the area partials are analytic and sparse.

    Inputs
    ------
    {name}_mesh : float, (nx, ny, 3), m
        Mesh of each surface: chord-wise nodes i (0 = leading edge), span-wise nodes j
        (0 = left tip), body frame (x forward, y right, z down).

    Outputs
    -------
    ring_vertices : float, (np, 4, 3), m
        Corners p1..p4 of every vortex ring.
    collocation_points : float, (np, 3), m
    force_points : float, (np, 3), m
    bound_vectors : float, (np, 3), m
    panel_areas : float, (np,), m**2
    strip_areas : float, (nst,), m**2

    Options
    -------
    surfaces : tuple of VLMSurface
        The lifting surfaces, in lattice order.
    """

    def initialize(self):
        declare_lattice_options(self, num_nodes=False)

    def setup(self):
        lat = self._lattice = lattice_of(self.options["surfaces"])
        npn, nst = lat.num_panels, lat.num_strips
        self.add_output(
            "ring_vertices",
            np.zeros((npn, 4, 3)),
            units="m",
            desc="corners p1..p4 of the vortex rings on the bound grid",
        )
        self.add_output(
            "collocation_points",
            np.zeros((npn, 3)),
            units="m",
            desc="ring centres (3/4 chord of each panel)",
        )
        self.add_output(
            "force_points",
            np.zeros((npn, 3)),
            units="m",
            desc="bound-segment midpoints (1/4 chord of each panel)",
        )
        self.add_output(
            "bound_vectors", np.zeros((npn, 3)), units="m", desc="bound segment vectors p2 - p1"
        )
        self.add_output(
            "panel_areas", np.zeros(npn), units="m**2", desc="areas of the geometric mesh panels"
        )
        self.add_output(
            "strip_areas", np.zeros(nst), units="m**2", desc="chord-wise sums of the panel areas"
        )

        self._area_index = []
        for isurf, s in enumerate(lat.surfaces):
            name = f"{s.name}_mesh"
            nx, ny, _ = s.mesh_shape
            self.add_input(
                name,
                np.zeros(s.mesh_shape),
                units="m",
                desc=f"mesh of surface '{s.name}' (chord-wise x span-wise nodes)",
            )
            for out, maps in (
                ("ring_vertices", lat.ring_map),
                ("collocation_points", lat.collocation_map),
                ("force_points", lat.force_point_map),
                ("bound_vectors", lat.bound_vector_map),
            ):
                rows, cols, vals = sparse_pattern(maps[isurf])
                self.declare_partials(out, name, rows=rows, cols=cols, val=vals)

            # Panel (i, j) corners in the order a0 = X[i,j], a1 = X[i,j+1], a2 = X[i+1,j+1],
            # a3 = X[i+1,j]; global panel and strip numbers.
            nc, ns = nx - 1, ny - 1
            node = np.arange(nx * ny).reshape(nx, ny)
            corner_nodes = np.stack(
                [node[:-1, :-1], node[:-1, 1:], node[1:, 1:], node[1:, :-1]], axis=-1
            )  # (nc, ns, 4)
            panels = lat.panel_offset[isurf] + np.arange(nc * ns)
            rows = np.repeat(panels, 12)
            cols = (3 * corner_nodes.reshape(-1, 4)[:, :, None] + np.arange(3)).ravel()
            self.declare_partials("panel_areas", name, rows=rows, cols=cols)
            # Strip j depends on all nodes of columns j and j+1.
            strip_nodes = np.stack([node[:, :-1], node[:, 1:]], axis=-1)  # (nx, ns, 2)
            strip_nodes = strip_nodes.transpose(1, 0, 2).reshape(ns, 2 * nx)
            srows = np.repeat(lat.strip_offset[isurf] + np.arange(ns), 6 * nx)
            scols = (3 * strip_nodes[:, :, None] + np.arange(3)).ravel()
            self.declare_partials("strip_areas", name, rows=srows, cols=scols)
            self._area_index.append((corner_nodes, strip_nodes))

    def _panel_diagonals(self, inputs, isurf):
        s = self._lattice.surfaces[isurf]
        x = inputs[f"{s.name}_mesh"]
        d1 = x[1:, 1:] - x[:-1, :-1]
        d2 = x[:-1, 1:] - x[1:, :-1]
        return d1, d2

    def compute(self, inputs, outputs):
        lat = self._lattice
        ring = collocation = force = bound = 0.0
        areas, strips = [], []
        for isurf, s in enumerate(lat.surfaces):
            x = inputs[f"{s.name}_mesh"].ravel()
            ring = ring + lat.ring_map[isurf] @ x
            collocation = collocation + lat.collocation_map[isurf] @ x
            force = force + lat.force_point_map[isurf] @ x
            bound = bound + lat.bound_vector_map[isurf] @ x
            d1, d2 = self._panel_diagonals(inputs, isurf)
            nrm = cross(d1, d2)
            area = 0.5 * np.sqrt(dot(nrm, nrm))  # (nc, ns)
            areas.append(area.ravel())
            strips.append(np.sum(area, axis=0))
        outputs["ring_vertices"] = ring.reshape(lat.num_panels, 4, 3)
        outputs["collocation_points"] = collocation.reshape(lat.num_panels, 3)
        outputs["force_points"] = force.reshape(lat.num_panels, 3)
        outputs["bound_vectors"] = bound.reshape(lat.num_panels, 3)
        outputs["panel_areas"] = np.concatenate(areas)
        outputs["strip_areas"] = np.concatenate(strips)

    def compute_partials(self, inputs, partials):
        lat = self._lattice
        for isurf, s in enumerate(lat.surfaces):
            name = f"{s.name}_mesh"
            d1, d2 = self._panel_diagonals(inputs, isurf)
            nrm = cross(d1, d2)
            area = 0.5 * np.sqrt(dot(nrm, nrm))
            # dA/dn = n/(4A); dn/dd1 = -skew(d2), dn/dd2 = skew(d1)
            g = nrm / (4.0 * area)[..., None]
            g1 = -np.einsum("...i,...ij->...j", g, skew(d2))  # dA/dd1
            g2 = np.einsum("...i,...ij->...j", g, skew(d1))  # dA/dd2
            # d1 = a2 - a0, d2 = a1 - a3
            dcorner = np.stack([-g1, g2, g1, -g2], axis=-2)  # (nc, ns, 4, 3)
            partials["panel_areas", name] = dcorner.ravel()
            nx = s.num_chord_panels + 1
            ns = s.num_span_panels
            # Scatter panel corner derivatives into (strip, chord node, side, xyz).
            dstrip = np.zeros((ns, nx, 2, 3), dtype=dcorner.dtype)
            dstrip[:, :-1, 0] += dcorner[:, :, 0].transpose(1, 0, 2)
            dstrip[:, :-1, 1] += dcorner[:, :, 1].transpose(1, 0, 2)
            dstrip[:, 1:, 1] += dcorner[:, :, 2].transpose(1, 0, 2)
            dstrip[:, 1:, 0] += dcorner[:, :, 3].transpose(1, 0, 2)
            partials["strip_areas", name] = dstrip.ravel()
