"""The wing planform as span-wise sections, scaled by wing area and aspect ratio.

One planform definition for the whole model: the VLM mesh
(:class:`~lpc_mdo.components.geometry.section_mesh.SectionMeshComp`), the wing box
(:class:`~lpc_mdo.components.structures.wing_box_geometry.WingBoxGeometryComp`), the drag
build-up (``wing_area``, ``wing_mac``) and the vehicle's ``Wing`` properties all read it.
"""

import dataclasses

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range


@dataclasses.dataclass(frozen=True, eq=False)
class SectionLayout:
    """
    Proportions of a wing of ``n`` span-wise sections, independent of its size.

    The scaling rule (docs theory/geometry 'Cranked wing planform'): the projected span
    fractions of the sections, the chord ratios c_k/c_root, the sweeps, sweep locations,
    dihedrals and twists are fixed; the wing area S and aspect ratio AR (design variables) set
    the projected half span h = sqrt(AR S)/2 and the root chord. This is the rule of MCEVS
    ``NASA_LPC_Wing`` (github.com/alfiyandyhr/MCEVS,
    ``MCEVS/Applications/OpenVSP/Components/Wing.py``: section spans scaled by b/2, section
    areas by S, section taper ratios kept).

    Attributes
    ----------
    span_fraction : ndarray, (n,)
        Projected span of each section over the half span, sum 1.
    chord_ratio : ndarray, (n + 1,)
        Chord at the section ends (root, kinks, tip) over the root chord; [0] = 1.
    sweep : ndarray, (n,)
        Sweep of each section's line at ``sweep_location`` (rad, positive aft).
    sweep_location : ndarray, (n,)
        Chord fraction of that line.
    dihedral : ndarray, (n,)
        Dihedral (rad, positive tip up).
    twist : ndarray, (n + 1,)
        Twist at the section ends relative to the root chord (rad, positive nose up); [0] = 0.
    """

    span_fraction: np.ndarray
    chord_ratio: np.ndarray
    sweep: np.ndarray
    sweep_location: np.ndarray
    dihedral: np.ndarray
    twist: np.ndarray

    def __post_init__(self):
        n = len(self.span_fraction)
        for name, size in (
            ("span_fraction", n),
            ("chord_ratio", n + 1),
            ("sweep", n),
            ("sweep_location", n),
            ("dihedral", n),
            ("twist", n + 1),
        ):
            value = np.asarray(getattr(self, name), dtype=float)
            if value.shape != (size,):
                raise ValueError(
                    f"SectionLayout.{name} has shape {value.shape}; allowed: ({size},) for "
                    f"{n} sections"
                )
            object.__setattr__(self, name, value)
        if n < 1 or np.any(self.span_fraction <= 0.0) or abs(self.span_fraction.sum() - 1) > 1e-12:
            raise ValueError(
                f"SectionLayout.span_fraction = {self.span_fraction.tolist()}; allowed: at "
                "least one positive fraction, sum 1"
            )
        if self.chord_ratio[0] != 1.0 or np.any(self.chord_ratio < 0.0):
            raise ValueError(
                f"SectionLayout.chord_ratio = {self.chord_ratio.tolist()}; allowed: [0] = 1, "
                "all >= 0"
            )

    @classmethod
    def from_wing(cls, wing):
        """
        Return the layout of a ``lpc_mdo.vehicle.Wing`` (or a trapezoidal ``LiftingSurface``).

        Sections: span fractions s_k cos(dihedral_k)/sum(s_j cos(dihedral_j)) of the section
        spans s_k (measured in the section plane, OpenVSP ``Span``), chord ratios over the first
        root chord, the sections' angles. Trapezoid: one section with chord ratios (1, taper),
        the leading-edge sweep (location 0), the dihedral and no twist.
        """
        sections = getattr(wing, "sections", None)
        if getattr(wing, "planform", "trapezoid") == "trapezoid" or sections is None:
            return cls(
                span_fraction=[1.0],
                chord_ratio=[1.0, wing.taper_ratio],
                sweep=[wing.sweep],
                sweep_location=[0.0],
                dihedral=[wing.dihedral],
                twist=[0.0, 0.0],
            )
        projected = np.array([s.span * np.cos(s.dihedral) for s in sections])
        chords = np.array([sections[0].root_chord] + [s.tip_chord for s in sections])
        return cls(
            span_fraction=projected / projected.sum(),
            chord_ratio=chords / chords[0],
            sweep=[s.sweep for s in sections],
            sweep_location=[s.sweep_location for s in sections],
            dihedral=[s.dihedral for s in sections],
            twist=[0.0] + [s.twist for s in sections],
        )

    @property
    def num_sections(self):
        """Number of sections n."""
        return self.span_fraction.size

    @property
    def stations(self):
        """Projected span stations eta_k = y_k/h of the section ends, (n + 1,), 0 to 1."""
        return np.concatenate([[0.0], np.cumsum(self.span_fraction)])

    @property
    def _true_fraction(self):
        # p_k / cos(dihedral_k): section span in its plane over h
        return self.span_fraction / np.cos(self.dihedral)

    @property
    def area_factor(self):
        """K = sum_k p_k/cos(G_k) (r_(k-1) + r_k): S = h c_root K."""
        r = self.chord_ratio
        return float(np.sum(self._true_fraction * (r[:-1] + r[1:])))

    @property
    def mac_factor(self):
        """MAC/c_root = (2/K) sum_k p_k/cos(G_k) (r_(k-1)^2 + r_(k-1) r_k + r_k^2)/3."""
        r = self.chord_ratio
        q = np.sum(self._true_fraction * (r[:-1] ** 2 + r[:-1] * r[1:] + r[1:] ** 2) / 3.0)
        return float(2.0 * q / self.area_factor)

    def section_offsets(self):
        """
        Section leading edges relative to the root's: (per unit h, per unit c_root), (n + 1, 3).

        Body frame (x forward, y right, z down). Section k moves its swept line aft by
        s_k tan(sweep_k) (s_k = h p_k/cos(G_k) in the section plane), out by h p_k and up by
        h p_k tan(G_k); its leading edge sits x_k (c_(k-1) - c_k) further aft than the swept
        line's change of chord implies.
        """
        n = self.num_sections
        per_h, per_c = np.zeros((n + 1, 3)), np.zeros((n + 1, 3))
        r = self.chord_ratio
        per_h[1:, 0] = -np.cumsum(self._true_fraction * np.tan(self.sweep))
        per_h[1:, 1] = np.cumsum(self.span_fraction)
        per_h[1:, 2] = -np.cumsum(self.span_fraction * np.tan(self.dihedral))
        per_c[1:, 0] = -np.cumsum(self.sweep_location * (r[:-1] - r[1:]))
        return per_h, per_c

    def mac_offsets(self):
        """
        Leading edge of the mean aerodynamic chord relative to the root's: (per h, per c_root).

        The chord-weighted mean (2/S) integral of c(s) X_LE(s) ds over the right half wing, exact
        for chord and leading edge linear in each section: per section
        s_k (2 c_0 X_0 + c_0 X_1 + c_1 X_0 + 2 c_1 X_1)/6.
        """
        r, w = self.chord_ratio, self._true_fraction
        out = []
        for offsets in self.section_offsets():
            a0, a1 = offsets[:-1], offsets[1:]
            moment = 2 * r[:-1, None] * a0 + r[:-1, None] * a1 + r[1:, None] * a0
            moment = moment + 2 * r[1:, None] * a1
            out.append(2.0 / self.area_factor * np.sum(w[:, None] * moment / 6.0, axis=0))
        return tuple(out)

    def interpolation(self, eta):
        """Matrix (len(eta), n + 1) that interpolates section-end values linearly to eta."""
        eta = np.asarray(eta, dtype=float)
        return np.column_stack(
            [np.interp(eta, self.stations, col) for col in np.eye(self.num_sections + 1)]
        )

    def geometry(self, area, aspect_ratio, root_leading_edge):
        """
        Planform at wing area S and aspect ratio AR, root leading edge X_0 (see the class).

        h = sqrt(AR S)/2, c_root = S/(h K) = 2 sqrt(S/AR)/K; returns a dict with ``span``,
        ``root_chord``, ``tip_chord``, ``mean_aerodynamic_chord``, ``mac_leading_edge`` (3,),
        ``section_leading_edges`` (n + 1, 3) and ``section_chords`` (n + 1,). Complex-safe.
        """
        half = 0.5 * np.sqrt(aspect_ratio * area)
        root = 2.0 * np.sqrt(area / aspect_ratio) / self.area_factor
        x0 = np.asarray(root_leading_edge)
        per_h, per_c = self.section_offsets()
        mac_h, mac_c = self.mac_offsets()
        return {
            "span": 2.0 * half,
            "root_chord": root,
            "tip_chord": root * self.chord_ratio[-1],
            "mean_aerodynamic_chord": root * self.mac_factor,
            "mac_leading_edge": x0 + half * mac_h + root * mac_c,
            "section_leading_edges": x0[None, :] + half * per_h + root * per_c,
            "section_chords": root * self.chord_ratio,
        }


class CrankedPlanformComp(om.ExplicitComponent):
    """
    Wing planform of span-wise sections from wing area and aspect ratio.

    With the layout's fixed proportions (:class:`SectionLayout`; docs theory/geometry 'Cranked
    wing planform'): projected span b = sqrt(AR S), root chord c_root = 2 sqrt(S/AR)/K with
    K = sum_k p_k/cos(G_k) (r_(k-1) + r_k), so that S is the sum of the section areas measured
    in their planes (OpenVSP's reference area; for one trapezoidal section without dihedral
    c_root = 2 S/((1 + taper) b)); chords c_k = r_k c_root; MAC = (2/S) integral of c^2 ds,
    closed form per linear section; its leading edge is the chord-weighted mean leading edge of
    the right half wing. All outputs are affine in h = b/2 and c_root, so the partials are
    analytic.

    Inputs
    ------
    area : float, scalar, m**2
        Wing reference area S.
    aspect_ratio : float, scalar
        b**2/S.
    root_leading_edge : float, (3,), m
        Leading edge of the root chord, body frame.

    Outputs
    -------
    span, root_chord, tip_chord, mean_aerodynamic_chord : float, scalar, m
    mac_leading_edge : float, (3,), m
        Leading edge of the right half wing's mean aerodynamic chord, body frame.
    section_leading_edges : float, (n + 1, 3), m
        Leading edges at the section ends of the right half wing, root to tip.
    section_chords : float, (n + 1,), m

    Options
    -------
    layout : SectionLayout
        The wing's proportions (``SectionLayout.from_wing(vehicle.wing)``).
    """

    def initialize(self):
        self.options.declare("layout", types=SectionLayout, desc="wing section proportions")

    def setup(self):
        layout = self.options["layout"]
        n1 = layout.num_sections + 1
        self.add_input("area", 1.0, units="m**2", desc="wing reference area")
        self.add_input("aspect_ratio", 1.0, units=None, desc="aspect ratio b^2/S")
        self.add_input(
            "root_leading_edge", np.zeros(3), units="m", desc="root-chord leading edge, body frame"
        )
        for name, desc in (
            ("span", "projected span"),
            ("root_chord", "root chord"),
            ("tip_chord", "tip chord"),
            ("mean_aerodynamic_chord", "mean aerodynamic chord"),
        ):
            self.add_output(name, 1.0, units="m", desc=desc)
        self.add_output(
            "mac_leading_edge", np.zeros(3), units="m", desc="leading edge of the MAC, body frame"
        )
        self.add_output(
            "section_leading_edges",
            np.zeros((n1, 3)),
            units="m",
            desc="leading edges at the section ends, right half wing, root to tip",
        )
        self.add_output("section_chords", np.ones(n1), units="m", desc="chords at section ends")
        self.declare_partials("*", ["area", "aspect_ratio"])
        self.declare_partials(
            "mac_leading_edge", "root_leading_edge", rows=[0, 1, 2], cols=[0, 1, 2]
        )
        self.declare_partials(
            "section_leading_edges",
            "root_leading_edge",
            rows=np.arange(3 * n1),
            cols=np.tile(np.arange(3), n1),
            val=1.0,
        )
        self.set_check_partial_options(wrt="*", method="cs")

    def compute(self, inputs, outputs):
        area, ar = inputs["area"][0], inputs["aspect_ratio"][0]
        for name, value in (("area", area), ("aspect_ratio", ar)):
            check_range(
                name,
                value,
                lower=0.0,
                lower_open=True,
                units="m**2" if name == "area" else None,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        geometry = self.options["layout"].geometry(area, ar, inputs["root_leading_edge"])
        for name, value in geometry.items():
            outputs[name] = value

    def compute_partials(self, inputs, partials):
        layout = self.options["layout"]
        area, ar = inputs["area"][0], inputs["aspect_ratio"][0]
        half = 0.5 * np.sqrt(ar * area)
        root = 2.0 * np.sqrt(area / ar) / layout.area_factor
        # d h/d S = h/(2 S), d h/d AR = h/(2 AR); d c/d S = c/(2 S), d c/d AR = -c/(2 AR)
        d_half = {"area": half / (2 * area), "aspect_ratio": half / (2 * ar)}
        d_root = {"area": root / (2 * area), "aspect_ratio": -root / (2 * ar)}
        per_h, per_c = layout.section_offsets()
        mac_h, mac_c = layout.mac_offsets()
        for wrt in ("area", "aspect_ratio"):
            dh, dc = d_half[wrt], d_root[wrt]
            partials["span", wrt] = 2.0 * dh
            partials["root_chord", wrt] = dc
            partials["tip_chord", wrt] = dc * layout.chord_ratio[-1]
            partials["mean_aerodynamic_chord", wrt] = dc * layout.mac_factor
            partials["mac_leading_edge", wrt] = (dh * mac_h + dc * mac_c)[:, None]
            partials["section_leading_edges", wrt] = (dh * per_h + dc * per_c).reshape(-1, 1)
            partials["section_chords", wrt] = (dc * layout.chord_ratio)[:, None]
        partials["mac_leading_edge", "root_leading_edge"] = np.ones(3)
