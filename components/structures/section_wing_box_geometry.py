"""Wing-box beam geometry of a wing of span-wise sections (the cranked NASA LPC wing)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.geometry.cranked_planform import SectionLayout
from lpc_mdo.components.structures.wing_box_geometry import WING_BOX_SECTIONS, WingBoxSection


class SectionWingBoxGeometryComp(om.ExplicitComponent):
    """
    Box-beam geometry of the right half wing from the section planform.

    The same planform as the VLM mesh: the leading edges X_k and chords c_k at the section ends
    come from :class:`~lpc_mdo.components.geometry.cranked_planform.CrankedPlanformComp`, and
    between section ends both are linear in the projected span station eta = y/h (docs
    theory/geometry 'Cranked wing planform'). The ``num_nodes`` ribs sit at evenly spaced eta
    from root to tip, as in
    :class:`~lpc_mdo.components.structures.wing_box_geometry.WingBoxGeometryComp`; with W the
    linear interpolation matrix of the layout at those stations:

    - chord c_j = (W c)_j, leading edge X_j = (W X)_j (so each bay follows the sweep and
      dihedral of the section it lies in; a bay across a kink takes the chord of both ribs);
    - node j = X_j + c_j (-k_x, 0, k_z), k_x = xi_b cos i + z_c sin i, k_z = xi_b sin i - z_c cos i
      with the beam-axis chord fraction xi_b, the mid-height z_c/c of the outer mould line and
      the incidence i (the section pitched about its leading edge, as the VLM mesh);
    - per bay, with the mean chord c_bar of its two ribs: width (xi_r - xi_f) c_bar, height
      (t/c)(xi_b) c_bar, skin radii (r/c) c_bar (docs theory/structures 'Material, mesh and load
      transfer'; the section numbers of :class:`WingBoxSection`).

    The outputs are linear in X and c, so the partials are exact constants except those with
    respect to the incidence. The layout's twist does not pitch the box (the box is a beam along
    the nodes; the twist of the reference wing is 0.5 deg).

    Inputs
    ------
    section_leading_edges : float, (n + 1, 3), m
        Leading edges at the section ends of the right half wing, root to tip.
    section_chords : float, (n + 1,), m
    wing_incidence : float, scalar, rad
        Section incidence i, positive nose up.

    Outputs
    -------
    nodes : float, (num_nodes, 3), m
    chord : float, (num_nodes,), m
    box_width, box_height, top_skin_radius, bottom_skin_radius : float, (num_nodes - 1,), m

    Options
    -------
    layout : SectionLayout
    num_nodes : int
        Beam nodes per half wing (>= 2).
    section : WingBoxSection
    """

    def initialize(self):
        self.options.declare("layout", types=SectionLayout, desc="wing section proportions")
        self.options.declare("num_nodes", default=9, types=int, lower=2, desc="num_bays + 1")
        self.options.declare(
            "section",
            default=WING_BOX_SECTIONS["ls413"],
            types=WingBoxSection,
            desc="Airfoil thickness/camber/skin radii and spar fractions",
        )

    def setup(self):
        layout, n = self.options["layout"], self.options["num_nodes"]
        n1 = layout.num_sections + 1
        self._w = layout.interpolation(np.linspace(0.0, 1.0, n))  # (n, n1)
        self._w_bay = 0.5 * (self._w[:-1] + self._w[1:])  # (n - 1, n1)
        self.add_input(
            "section_leading_edges",
            np.zeros((n1, 3)),
            units="m",
            desc="leading edges at the section ends, right half, root to tip",
        )
        self.add_input("section_chords", np.ones(n1), units="m", desc="chords at section ends")
        self.add_input("wing_incidence", 0.0, units="rad", desc="incidence, positive nose up")
        self.add_output("nodes", np.zeros((n, 3)), units="m", desc="beam nodes, root to tip")
        self.add_output("chord", np.ones(n), units="m", desc="local chord at the nodes")
        for name, desc in (
            ("box_width", "spar-to-spar box width"),
            ("box_height", "box height"),
            ("top_skin_radius", "radius of curvature of the top skin panel"),
            ("bottom_skin_radius", "radius of curvature of the bottom skin panel"),
        ):
            self.add_output(name, np.ones(n - 1), units="m", desc=desc)

        # nodes[j, d] = sum_k W[j, k] X[k, d] (+ chord terms in x and z)
        j, k = np.nonzero(self._w)
        rows = (3 * j[:, None] + np.arange(3)[None, :]).ravel()
        cols = (3 * k[:, None] + np.arange(3)[None, :]).ravel()
        self.declare_partials(
            "nodes",
            "section_leading_edges",
            rows=rows,
            cols=cols,
            val=np.repeat(self._w[j, k], 3),
        )
        self._wj, self._wk = j, k
        self.declare_partials(
            "nodes",
            "section_chords",
            rows=np.concatenate([3 * j, 3 * j + 2]),
            cols=np.concatenate([k, k]),
        )
        xz = np.concatenate([3 * np.arange(n), 3 * np.arange(n) + 2])
        self.declare_partials("nodes", "wing_incidence", rows=xz, cols=np.zeros(2 * n, int))
        self.declare_partials("chord", "section_chords", rows=j, cols=k, val=self._w[j, k])
        jb, kb = np.nonzero(self._w_bay)
        sec = self.options["section"]
        for name, factor in self._factors(sec).items():
            self.declare_partials(
                name, "section_chords", rows=jb, cols=kb, val=factor * self._w_bay[jb, kb]
            )

    @staticmethod
    def _factors(sec):
        return {
            "box_width": sec.rear_spar - sec.front_spar,
            "box_height": sec.thickness,
            "top_skin_radius": sec.top_radius,
            "bottom_skin_radius": sec.bottom_radius,
        }

    def _k(self, incidence):
        sec = self.options["section"]
        kx = sec.beam_axis * np.cos(incidence) + sec.camber * np.sin(incidence)
        kz = sec.beam_axis * np.sin(incidence) - sec.camber * np.cos(incidence)
        return kx, kz

    def compute(self, inputs, outputs):
        chords = inputs["section_chords"]
        if np.any(chords.real <= 0.0):
            raise om.AnalysisError(
                f"{self.msginfo}: 'section_chords' = {chords.real.tolist()} m; allowed: > 0 m"
            )
        kx, kz = self._k(inputs["wing_incidence"][0])
        c = self._w @ chords
        nodes = self._w @ inputs["section_leading_edges"]
        nodes[:, 0] -= c * kx
        nodes[:, 2] += c * kz
        outputs["nodes"] = nodes
        outputs["chord"] = c
        mean = self._w_bay @ chords
        for name, factor in self._factors(self.options["section"]).items():
            outputs[name] = factor * mean

    def compute_partials(self, inputs, partials):
        kx, kz = self._k(inputs["wing_incidence"][0])
        w = self._w[self._wj, self._wk]
        partials["nodes", "section_chords"] = np.concatenate([-kx * w, kz * w])
        c = self._w @ inputs["section_chords"]
        # d kx/di = -kz, d kz/di = kx
        partials["nodes", "wing_incidence"] = np.concatenate([c * kz, c * kx])
