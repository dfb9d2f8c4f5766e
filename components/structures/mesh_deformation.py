"""Deformed lifting-surface mesh from the displacements of its right half (two-way coupling)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_integer


class MeshDeformationComp(om.ExplicitComponent):
    """
    Mesh of a symmetric surface moved by the structure under a symmetric load.

    The beam models the right half (y >= 0); its displacements at the right-half mesh nodes
    (``DisplacementTransferComp``) move those nodes, and the left half moves as their mirror
    image, (dx, dy, dz) -> (dx, -dy, dz), so the deformed surface stays symmetric:

        X'[i, j] = X[i, j] + d[i, j]          for the right-half span nodes j >= ny // 2
        X'[i, j] = X[i, j] + M d[i, ny-1-j]   for the left-half nodes (M = diag(1, -1, 1))

    Inputs
    ------
    mesh : (nx, ny, 3), m
        Undeformed mesh (ny odd: a node on the symmetry plane).
    right_displacements : (nx * (ny // 2 + 1), 3), m
        Displacements of the right-half nodes, ordered chord-wise row by row (i, then j from
        the root node ny // 2 to the tip).

    Outputs
    -------
    deformed_mesh : (nx, ny, 3), m

    Options
    -------
    num_chord_nodes, num_span_nodes : int
    """

    def initialize(self):
        self.options.declare("num_chord_nodes", types=int, lower=2, desc="nx")
        self.options.declare("num_span_nodes", types=int, lower=3, desc="ny (odd)")

    def setup(self):
        nx, ny = self.options["num_chord_nodes"], self.options["num_span_nodes"]
        check_integer(
            "num_span_nodes",
            ny,
            upper=None if ny % 2 else ny - 1,
            allowed="odd (a node on the symmetry plane)",
            where=self.msginfo,
        )
        half = ny // 2
        nr = half + 1
        self.add_input("mesh", np.zeros((nx, ny, 3)), units="m", desc="undeformed mesh")
        self.add_input(
            "right_displacements",
            np.zeros((nx * nr, 3)),
            units="m",
            desc="displacements of the right-half mesh nodes",
        )
        self.add_output("deformed_mesh", np.zeros((nx, ny, 3)), units="m", desc="deformed mesh")
        n = nx * ny * 3
        self.declare_partials(
            "deformed_mesh", "mesh", rows=np.arange(n), cols=np.arange(n), val=1.0
        )
        rows, cols, vals = [], [], []
        out_index = np.arange(n).reshape(nx, ny, 3)
        in_index = np.arange(nx * nr * 3).reshape(nx, nr, 3)
        mirror = np.array([1.0, -1.0, 1.0])
        for j in range(ny):
            k = j - half if j >= half else (ny - 1 - j) - half
            sign = np.ones(3) if j >= half else mirror
            rows.append(out_index[:, j, :].ravel())
            cols.append(in_index[:, k, :].ravel())
            vals.append(np.tile(sign, nx))
        self._rows = np.concatenate(rows)
        self._cols = np.concatenate(cols)
        self._vals = np.concatenate(vals)
        self.declare_partials(
            "deformed_mesh", "right_displacements", rows=self._rows, cols=self._cols, val=self._vals
        )

    def compute(self, inputs, outputs):
        out = inputs["mesh"].reshape(-1).copy()
        disp = inputs["right_displacements"].reshape(-1)
        np.add.at(out, self._rows, self._vals * disp[self._cols])
        outputs["deformed_mesh"] = out.reshape(outputs["deformed_mesh"].shape)
