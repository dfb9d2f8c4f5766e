"""Wing-box beam geometry from the wing planform: beam nodes, box dimensions, skin curvature."""

import dataclasses
import math

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.airfoil_coordinates import read_coordinates, split_surfaces
from lpc_mdo.core.checks import check_number, check_range


@dataclasses.dataclass(frozen=True)
class WingBoxSection:
    """
    Airfoil numbers the wing-box geometry needs, as fractions of the local chord c.

    Attributes
    ----------
    front_spar, rear_spar, beam_axis : float
        Chord fractions of the spars and of the beam nodes these numbers were computed for.
    thickness : float
        Outer-mould-line height (upper minus lower surface) at the beam axis, over c: the box
        height is thickness * c (docs theory/structures 'Material, mesh and load transfer': the
        height at the node).
    camber : float
        Mid-height ((upper + lower)/2) at the beam axis over c: the node's vertical offset from
        the chord line.
    top_radius, bottom_radius : float
        Radius of curvature of the upper and lower skin between the spars, over c: the radius
        of the circular arc through the surface points at the front spar, half-way between the
        spars and at the rear spar.
    source : str
        Where the numbers come from.
    """

    front_spar: float
    rear_spar: float
    beam_axis: float
    thickness: float
    camber: float
    top_radius: float
    bottom_radius: float
    source: str = ""

    @classmethod
    def from_coordinates(
        cls, coordinates, front_spar=0.25, rear_spar=0.75, beam_axis=0.5, source=""
    ):
        """
        Compute the section numbers from airfoil coordinates in Selig order.

        Parameters
        ----------
        coordinates : array_like, (n, 2)
            x/c, y/c from the trailing edge over the upper surface to the leading edge and back
            along the lower surface (Selig format), y up.
        front_spar, rear_spar, beam_axis : float
            Chord fractions, 0 < front_spar < beam_axis < rear_spar < 1.
        source : str
            Label stored with the numbers.
        """
        check_number(
            "front_spar",
            front_spar,
            lower=0.0,
            upper=beam_axis,
            lower_open=True,
            upper_open=True,
            allowed=f"in (0, beam_axis = {beam_axis:g})",
        )
        check_number(
            "rear_spar",
            rear_spar,
            lower=beam_axis,
            upper=1.0,
            lower_open=True,
            upper_open=True,
            allowed=f"in (beam_axis = {beam_axis:g}, 1)",
        )
        xy = np.asarray(coordinates, dtype=float)
        if xy.ndim != 2 or xy.shape[1] != 2 or xy.shape[0] < 5:
            raise ValueError(f"coordinates must have shape (n >= 5, 2), got {xy.shape}.")
        upper, lower = split_surfaces(xy)

        def y_of(surf, x):
            return np.interp(x, surf[:, 0], surf[:, 1])

        mid = 0.5 * (front_spar + rear_spar)
        stations = np.array([front_spar, mid, rear_spar])
        radii = [_arc_radius(stations, y_of(s, stations)) for s in (upper, lower)]
        y_up, y_lo = y_of(upper, beam_axis), y_of(lower, beam_axis)
        return cls(
            front_spar=front_spar,
            rear_spar=rear_spar,
            beam_axis=beam_axis,
            thickness=float(y_up - y_lo),
            camber=float(0.5 * (y_up + y_lo)),
            top_radius=radii[0],
            bottom_radius=radii[1],
            source=source,
        )

    @classmethod
    def from_file(cls, path, front_spar=0.25, rear_spar=0.75, beam_axis=0.5):
        """Read a Selig-format coordinate file (a name line, then x/c y/c pairs)."""
        shape = read_coordinates(path)
        return cls.from_coordinates(
            shape.coordinates, front_spar, rear_spar, beam_axis, source=str(path)
        )


def _arc_radius(x, y):
    """Radius of the circle through three points (x_i, y_i); inf if they are collinear."""
    p = np.column_stack([x, y])
    a, b, c = p
    ab, bc, ca = np.linalg.norm(a - b), np.linalg.norm(b - c), np.linalg.norm(c - a)
    cross = (b - a)[0] * (c - a)[1] - (b - a)[1] * (c - a)[0]
    return math.inf if cross == 0.0 else float(ab * bc * ca / (2.0 * abs(cross)))


#: Section numbers of the two wing airfoils for the reference layout (spars at 25 % and 75 %,
#: beam axis at 50 % chord), from the UIUC coordinate tables (ls413_gaw2.dat, ls417_gaw1.dat,
#: shipped in tests/data/airfoils) with ``WingBoxSection.from_file``; the tables hold points at
#: exactly x/c = 0.25, 0.5 and 0.75, so no interpolation enters. tests/test_structures_geometry.py
#: recomputes them from those files.
WING_BOX_SECTIONS = {
    "ls413": WingBoxSection(
        0.25,
        0.75,
        0.5,
        thickness=0.1243,
        camber=0.02075,
        top_radius=1.9089296147276130,
        bottom_radius=2.5495526693349944,
        source="LS(1)-0413 (GA(W)-2), UIUC ls413.dat",
    ),
    "ls417": WingBoxSection(
        0.25,
        0.75,
        0.5,
        thickness=0.1636,
        camber=0.02089,
        top_radius=1.4929635168850313,
        bottom_radius=1.8327388853441626,
        source="LS(1)-0417 (GA(W)-1), UIUC ls417.dat",
    ),
}


def wing_box_section(vehicle, coordinates=None):
    """
    Return the WingBoxSection of a vehicle's wing and wing-box layout.

    From ``coordinates`` if given, else from the wing's coordinate file
    (``vehicle.wing.coordinates``) if it has one, else the packaged numbers
    (:data:`WING_BOX_SECTIONS`), which hold for the reference layout (spars 0.25/0.75, beam
    axis 0.5) only.
    """
    box, wing = vehicle.wing_box, vehicle.wing
    spars = (box.front_spar, box.rear_spar, box.beam_axis)
    if coordinates is not None:
        return WingBoxSection.from_coordinates(coordinates, *spars, source=wing.airfoil)
    if wing.coordinates is not None:
        return WingBoxSection.from_file(wing.coordinates, *spars)
    sec = WING_BOX_SECTIONS.get(wing.airfoil)
    if sec is None or (sec.front_spar, sec.rear_spar, sec.beam_axis) != spars:
        raise ValueError(
            f"no packaged wing-box section for airfoil {wing.airfoil!r} with front_spar="
            f"{box.front_spar}, rear_spar={box.rear_spar}, beam_axis={box.beam_axis}; packaged: "
            f"{sorted(WING_BOX_SECTIONS)} with 0.25/0.75/0.5. Give the wing's coordinates."
        )
    return sec


class WingBoxGeometryComp(om.ExplicitComponent):
    """
    Box-beam geometry of one (the right) half wing from the trapezoidal planform.

    Planform (docs theory/geometry 'Reference vehicle'; docs theory/aerodynamics 'Drag build-up'):
    span b = sqrt(AR S), root chord c_r = 2 S/((1 + λ) b), chord c(η) = c_r (1 - (1 - λ) η) at η =
    y/(b/2). Leading edge at
    x_LE = x_0 - y tan Λ_LE, z_LE = z_0 - y tan Γ (body frame, z down; positive dihedral raises
    the tip). The section is pitched by the incidence i (nose up), so the chord runs along
    (-cos i, 0, sin i) and the section's "up" along (-sin i, 0, -cos i).

    Wing box (docs theory/structures 'Material, mesh and load transfer'): ``num_nodes`` nodes evenly
    spaced in span from root to tip (the ribs; 9 nodes = 8 bays), at the beam-axis chord fraction
    ξ_b and at mid-height of the
    outer mould line; spars at ξ_f and ξ_r. Per bay, with the mean chord c̄ of its two ribs:

    - box width w = (ξ_r - ξ_f) c̄ (chord-wise spar spacing, not projected normal to the beam);
    - box height h = (t/c)(ξ_b) c̄, the airfoil thickness at the beam axis;
    - skin radii r = (r/c) c̄, the radius of the circular arc through each skin at the front
      spar, mid-box and rear spar (see WingBoxSection).

    The textbook default for the radius is the point-wise radius (1 + y'²)^(3/2)/abs(y'')
    averaged over 6 points; this component uses the three-point arc instead, because y'' of a
    4-digit coordinate table depends strongly on how it is smoothed and the aft-loaded lower
    surface of both LS(1) sections has an inflection point inside the box (x/c ≈ 0.65), where
    the point-wise radius goes to infinity. The arc radius is the panel's mean curvature radius
    and uses surface heights only.

    All outputs are smooth closed forms of the inputs; partials are analytic. The inputs'
    defaults are the planform of the ``wing`` option.

    Inputs
    ------
    wing_area : float, scalar, m**2
        Reference area S of the whole wing.
    wing_aspect_ratio : float, scalar
    wing_taper_ratio : float, scalar
        Tip chord over root chord λ.
    wing_sweep : float, scalar, rad
        Leading-edge sweep Λ_LE.
    wing_dihedral : float, scalar, rad
        Dihedral Γ, positive tip up.
    wing_incidence : float, scalar, rad
        Section incidence i, positive nose up.
    wing_root_leading_edge : float, (3,), m
        Leading edge of the root chord, body frame.

    Outputs
    -------
    nodes : float, (num_nodes, 3), m
        Beam nodes, body frame, root to tip.
    chord : float, (num_nodes,), m
        Local chord at the nodes.
    box_width : float, (num_nodes - 1,), m
    box_height : float, (num_nodes - 1,), m
    top_skin_radius, bottom_skin_radius : float, (num_nodes - 1,), m

    Options
    -------
    num_nodes : int
        Beam nodes per half wing (>= 2); default 9 (8 bays).
    section : WingBoxSection
        Airfoil numbers and chord fractions; default ``WING_BOX_SECTIONS['ls413']``.
    wing : object
        The wing whose planform gives the input defaults: anything with ``area``,
        ``aspect_ratio``, ``taper_ratio``, ``sweep``, ``dihedral``, ``incidence`` and
        ``root_leading_edge`` (SI), such as a vehicle's ``wing``
        (:class:`lpc_mdo.vehicle.LiftingSurface`), which VehicleGroup passes.
    """

    def initialize(self):
        self.options.declare(
            "num_nodes",
            default=9,
            types=int,
            lower=2,
            desc="Beam nodes per half wing (num_bays + 1)",
        )
        self.options.declare(
            "section",
            default=WING_BOX_SECTIONS["ls413"],
            types=WingBoxSection,
            desc="Airfoil thickness/camber/skin radii and spar fractions",
        )
        self.options.declare(
            "wing",
            desc="the wing whose planform gives the input defaults (area, aspect_ratio, "
            "taper_ratio, sweep, dihedral, incidence, root_leading_edge; e.g. a vehicle's wing)",
        )

    def setup(self):
        n = self.options["num_nodes"]
        ne = n - 1
        wing = self.options["wing"]
        self.add_input("wing_area", val=wing.area, units="m**2", desc="wing reference area")
        self.add_input(
            "wing_aspect_ratio", val=wing.aspect_ratio, units=None, desc="wing aspect ratio"
        )
        self.add_input(
            "wing_taper_ratio", val=wing.taper_ratio, units=None, desc="tip chord over root chord"
        )
        self.add_input("wing_sweep", val=wing.sweep, units="rad", desc="leading-edge sweep")
        self.add_input(
            "wing_dihedral", val=wing.dihedral, units="rad", desc="dihedral, positive tip up"
        )
        self.add_input(
            "wing_incidence",
            val=wing.incidence,
            units="rad",
            desc="section incidence, positive nose up",
        )
        self.add_input(
            "wing_root_leading_edge",
            val=np.array(wing.root_leading_edge),
            units="m",
            desc="leading edge of the root chord, body frame",
        )

        self.add_output(
            "nodes",
            val=np.zeros((n, 3)),
            units="m",
            desc="wing-box beam nodes, body frame, root to tip",
        )
        self.add_output("chord", val=np.ones(n), units="m", desc="local chord at the nodes")
        self.add_output("box_width", val=np.ones(ne), units="m", desc="spar-to-spar box width")
        self.add_output("box_height", val=np.ones(ne), units="m", desc="box height")
        self.add_output(
            "top_skin_radius",
            val=np.ones(ne),
            units="m",
            desc="radius of curvature of the top skin panel",
        )
        self.add_output(
            "bottom_skin_radius",
            val=np.ones(ne),
            units="m",
            desc="radius of curvature of the bottom skin panel",
        )

        self._eta = np.linspace(0.0, 1.0, n)
        xrows, zrows = 3 * np.arange(n), 3 * np.arange(n) + 2
        xz = np.sort(np.concatenate([xrows, zrows]))
        self.declare_partials("nodes", ["wing_area", "wing_aspect_ratio"])
        self.declare_partials(
            "nodes", ["wing_taper_ratio", "wing_incidence"], rows=xz, cols=np.zeros_like(xz)
        )
        self.declare_partials("nodes", "wing_sweep", rows=xrows, cols=np.zeros(n))
        self.declare_partials("nodes", "wing_dihedral", rows=zrows, cols=np.zeros(n))
        self.declare_partials(
            "nodes",
            "wing_root_leading_edge",
            rows=np.arange(3 * n),
            cols=np.tile(np.arange(3), n),
            val=1.0,
        )
        self.declare_partials(
            ["chord", "box_width", "box_height", "top_skin_radius", "bottom_skin_radius"],
            ["wing_area", "wing_aspect_ratio", "wing_taper_ratio"],
        )

    def _planform(self, inputs):
        area, ar, taper = (
            inputs["wing_area"],
            inputs["wing_aspect_ratio"],
            inputs["wing_taper_ratio"],
        )
        for name, val, units in (
            ("wing_area", area, "m**2"),
            ("wing_aspect_ratio", ar, None),
            ("wing_taper_ratio", taper, None),
        ):
            check_range(
                name,
                val,
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        span = np.sqrt(ar * area)
        root_chord = 2.0 * area / ((1.0 + taper) * span)
        chord = root_chord * (1.0 - (1.0 - taper) * self._eta)
        y = 0.5 * span * self._eta
        return span, root_chord, chord, y

    def _section_factors(self, incidence):
        sec = self.options["section"]
        kx = sec.beam_axis * np.cos(incidence) + sec.camber * np.sin(incidence)
        kz = sec.beam_axis * np.sin(incidence) - sec.camber * np.cos(incidence)
        return kx, kz

    def compute(self, inputs, outputs):
        sec = self.options["section"]
        _, _, chord, y = self._planform(inputs)
        kx, kz = self._section_factors(inputs["wing_incidence"])
        le = inputs["wing_root_leading_edge"]
        nodes = np.zeros((chord.size, 3), dtype=chord.dtype)
        nodes[:, 0] = le[0] - y * np.tan(inputs["wing_sweep"]) - chord * kx
        nodes[:, 1] = le[1] + y
        nodes[:, 2] = le[2] - y * np.tan(inputs["wing_dihedral"]) + chord * kz
        outputs["nodes"] = nodes
        outputs["chord"] = chord
        mean = 0.5 * (chord[:-1] + chord[1:])
        outputs["box_width"] = (sec.rear_spar - sec.front_spar) * mean
        outputs["box_height"] = sec.thickness * mean
        outputs["top_skin_radius"] = sec.top_radius * mean
        outputs["bottom_skin_radius"] = sec.bottom_radius * mean

    def compute_partials(self, inputs, partials):
        sec = self.options["section"]
        area, ar, taper = (
            inputs["wing_area"],
            inputs["wing_aspect_ratio"],
            inputs["wing_taper_ratio"],
        )
        _, root_chord, chord, y = self._planform(inputs)
        incidence = inputs["wing_incidence"]
        kx, kz = self._section_factors(incidence)
        tan_sweep, tan_dih = np.tan(inputs["wing_sweep"]), np.tan(inputs["wing_dihedral"])

        # c_j = 2 sqrt(S)/((1 + λ) sqrt(AR)) (1 - (1 - λ) η_j); y_j = sqrt(AR S) η_j/2
        dc = {
            "wing_area": chord / (2.0 * area),
            "wing_aspect_ratio": -chord / (2.0 * ar),
            "wing_taper_ratio": -chord / (1.0 + taper) + root_chord * self._eta,
        }
        dy = {"wing_area": y / (2.0 * area), "wing_aspect_ratio": y / (2.0 * ar)}

        for wrt in ("wing_area", "wing_aspect_ratio"):
            d = np.column_stack(
                [-tan_sweep * dy[wrt] - kx * dc[wrt], dy[wrt], -tan_dih * dy[wrt] + kz * dc[wrt]]
            )
            partials["nodes", wrt] = d.reshape(-1, 1)
        partials["nodes", "wing_taper_ratio"] = np.column_stack(
            [-kx * dc["wing_taper_ratio"], kz * dc["wing_taper_ratio"]]
        ).ravel()
        # d kx/di = -kz, d kz/di = kx
        partials["nodes", "wing_incidence"] = np.column_stack([chord * kz, chord * kx]).ravel()
        partials["nodes", "wing_sweep"] = -y / np.cos(inputs["wing_sweep"]) ** 2
        partials["nodes", "wing_dihedral"] = -y / np.cos(inputs["wing_dihedral"]) ** 2

        factors = {
            "box_width": sec.rear_spar - sec.front_spar,
            "box_height": sec.thickness,
            "top_skin_radius": sec.top_radius,
            "bottom_skin_radius": sec.bottom_radius,
        }
        for wrt, d in dc.items():
            partials["chord", wrt] = d[:, np.newaxis]
            dmean = 0.5 * (d[:-1] + d[1:])
            for of, factor in factors.items():
                partials[of, wrt] = factor * dmean[:, np.newaxis]
