"""VLM lattice of a mirrored wing of span-wise sections, with nodes on the section ends."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.geometry.cranked_planform import SectionLayout
from lpc_mdo.components.geometry.planform import SPACINGS, _check_even, span_stations


def kinked_stations(layout, num_span_panels, spacing="cosine"):
    """
    Half-span node stations eta_j = y_j/h in [0, 1], root to tip, with a node on every kink.

    The N/2 + 1 stations of :func:`~lpc_mdo.components.geometry.planform.span_stations`
    (cosine: clustered at the tip) with, for each interior section end eta_k of ``layout``,
    the nearest not yet moved interior station moved onto eta_k. Raises ValueError when the
    panels are too few for a node on every kink.
    """
    eta = np.abs(span_stations(num_span_panels, spacing)[num_span_panels // 2 :])
    free = list(range(1, eta.size - 1))
    for kink in layout.stations[1:-1]:
        if not free:
            raise ValueError(
                f"num_span_panels = {num_span_panels} leaves no node for the kink at eta = "
                f"{kink:.4f}; allowed: at least {2 * layout.num_sections} panels"
            )
        j = min(free, key=lambda i: abs(eta[i] - kink))
        eta[j] = kink
        free.remove(j)
    if np.any(np.diff(eta) <= 0.0):
        raise ValueError(
            f"num_span_panels = {num_span_panels} is too coarse to place nodes on the kinks at "
            f"eta = {layout.stations[1:-1].round(4).tolist()} in order; allowed: more panels"
        )
    return eta


class SectionMeshComp(om.ExplicitComponent):
    """
    Lattice nodes of a wing of span-wise sections mirrored about its root (y = y_root).

    The planform (:class:`~lpc_mdo.components.geometry.cranked_planform.CrankedPlanformComp`)
    gives the leading edge X_k and chord c_k at the section ends; between them both are linear
    in the projected span station (docs theory/geometry 'Cranked wing planform'). At the
    half-span stations eta_j of :func:`kinked_stations` (a node on every kink), with
    W the linear interpolation matrix and s_i = i/nc the chord fraction:

    - X_j = W X, c_j = W c, theta_j = incidence + W twist (twist from the layout, positive nose
      up);
    - node (i, j) = X_j + s_i c_j (-cos theta_j, 0, sin theta_j) (body frame, x forward, z
      down; each section pitched about its leading edge, as
      :class:`~lpc_mdo.components.geometry.planform.PlanformMeshComp`);
    - the left half is the mirror image y -> 2 y_root - y.

    Partials are analytic and sparse.

    Inputs
    ------
    section_leading_edges : float, (n + 1, 3), m
        Leading edges at the section ends of the right half, root to tip.
    section_chords : float, (n + 1,), m
    incidence : float, scalar, rad
        Root incidence relative to the body x axis, positive nose up.

    Outputs
    -------
    mesh : float, (num_chord_panels + 1, num_span_panels + 1, 3), m
        Nodes i chord-wise (0 = leading edge), j span-wise (0 = left tip).

    Options
    -------
    layout : SectionLayout
        Section proportions (stations and twist).
    num_chord_panels : int
        Chord-wise panels nc (>= 1), uniform.
    num_span_panels : int
        Span-wise panels N, both halves (even, >= 2 n).
    spacing : str
        'cosine' (default) or 'uniform', before the kink nodes are placed.
    """

    def initialize(self):
        self.options.declare("layout", types=SectionLayout, desc="wing section proportions")
        self.options.declare("num_chord_panels", default=1, types=int, lower=1)
        self.options.declare("num_span_panels", types=int, lower=2, check_valid=_check_even)
        self.options.declare("spacing", default="cosine", values=SPACINGS)

    def setup(self):
        layout = self.options["layout"]
        nc, nsp = self.options["num_chord_panels"], self.options["num_span_panels"]
        n1 = layout.num_sections + 1
        nx, ny = nc + 1, nsp + 1
        self._eta_half = kinked_stations(layout, nsp, self.options["spacing"])
        weights = layout.interpolation(self._eta_half)  # (nh, n1)
        half = np.abs(np.arange(ny) - nsp // 2)
        self._half = half
        self._side = np.where(np.arange(ny) < nsp // 2, -1.0, 1.0)
        self._w = weights[half]  # (ny, n1)
        self._s = np.arange(nx) / nc
        self._twist = weights @ layout.twist

        self.add_input(
            "section_leading_edges",
            np.zeros((n1, 3)),
            units="m",
            desc="leading edges at the section ends, right half, root to tip",
        )
        self.add_input("section_chords", np.ones(n1), units="m", desc="chords at section ends")
        self.add_input("incidence", 0.0, units="rad", desc="root incidence, positive nose up")
        self.add_output(
            "mesh", np.zeros((nx, ny, 3)), units="m", desc="lattice nodes, chord x span x xyz"
        )

        idx = np.arange(nx * ny * 3).reshape(nx, ny, 3)
        # mesh[i, j, d] depends on X[k, d] for every section end k (weights, mostly zero but
        # the pattern is small: (n + 1) per node and coordinate).
        rows = np.repeat(idx.ravel(), n1)
        cols = (np.arange(n1)[None, None, None, :] * 3 + np.arange(3)[None, None, :, None]) + (
            np.zeros((nx, ny, 1, 1), int)
        )
        vals = np.broadcast_to(self._w[None, :, None, :], (nx, ny, 3, n1)).copy()
        # left half: y = 2 y_root - W y
        left = self._side < 0
        vals[:, left, 1, :] *= -1.0
        vals[:, left, 1, 0] += 2.0
        keep = vals.ravel() != 0.0
        self.declare_partials(
            "mesh",
            "section_leading_edges",
            rows=rows[keep],
            cols=cols.ravel()[keep],
            val=vals.ravel()[keep],
        )
        rxz = np.concatenate([idx[..., 0].ravel(), idx[..., 2].ravel()])
        self._chord_rows = np.repeat(rxz, n1)
        self._chord_cols = np.tile(np.arange(n1), rxz.size)
        self.declare_partials(
            "mesh", "section_chords", rows=self._chord_rows, cols=self._chord_cols
        )
        self.declare_partials("mesh", "incidence", rows=rxz, cols=np.zeros(rxz.size, int))

    def compute(self, inputs, outputs):
        le_sections, chords = inputs["section_leading_edges"], inputs["section_chords"]
        le = self._w @ le_sections  # (ny, 3)
        le[:, 1] = np.where(self._side < 0, 2.0 * le_sections[0, 1] - le[:, 1], le[:, 1])
        c = self._w @ chords
        theta = inputs["incidence"][0] + self._twist[self._half]
        sc = self._s[:, None] * c[None, :]
        mesh = outputs["mesh"]
        mesh[..., 0] = le[None, :, 0] - sc * np.cos(theta)[None, :]
        mesh[..., 1] = le[None, :, 1]
        mesh[..., 2] = le[None, :, 2] + sc * np.sin(theta)[None, :]

    def compute_partials(self, inputs, partials):
        c = self._w @ inputs["section_chords"]
        theta = inputs["incidence"][0] + self._twist[self._half]
        s = self._s[:, None, None]
        w = self._w[None, :, :]
        dx = -s * np.cos(theta)[None, :, None] * w  # (nx, ny, n1)
        dz = s * np.sin(theta)[None, :, None] * w
        partials["mesh", "section_chords"] = np.concatenate([dx.ravel(), dz.ravel()])
        sc = self._s[:, None] * c[None, :]
        partials["mesh", "incidence"] = np.concatenate(
            [(sc * np.sin(theta)).ravel(), (sc * np.cos(theta)).ravel()]
        )
