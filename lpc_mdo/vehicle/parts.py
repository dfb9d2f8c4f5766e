"""The vehicle's parts as frozen dataclasses: geometry, rotors, masses, conditions, limits.

Every field declares its file key, units and range for the schema engine
(:mod:`lpc_mdo.vehicle.schema`); the package docstring (:mod:`lpc_mdo.vehicle`) gives the
conventions.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from lpc_mdo.components.aero.airfoil_coordinates import read_coordinates
from lpc_mdo.vehicle.reserve_rules import RESERVE_RULES
from lpc_mdo.vehicle.schema import _angle, _param, _Spec

# ------------------------------------------------------------------------------------------------
# Airfoils and conditions


@dataclass(frozen=True)
class Airfoil:
    """Section data the vehicle needs from an airfoil name.

    Attributes
    ----------
    name : str
        Key used in vehicle files.
    thickness_to_chord : float
        Maximum thickness over chord, t/c (-).
    max_thickness_location : float
        Chord-wise position of the maximum thickness, (x/c)_m (-), as used by the drag build-up.
    description : str
        Full name and coordinate file in ``shared/data/airfoils`` (if any).
    """

    name: str
    thickness_to_chord: float
    max_thickness_location: float
    description: str


#: Airfoils a vehicle file may name (docs theory/aerodynamics 'Reference-vehicle defaults', docs
#: theory/weights 'M4 regressions', docs theory/structures 'Frame element').
AIRFOILS: dict[str, Airfoil] = {
    a.name: a
    for a in (
        Airfoil("ls413", 0.13, 0.4, "NASA LS(1)-0413 = GA(W)-2, paper wing (ls413_gaw2.dat)"),
        Airfoil("ls417", 0.17, 0.4, "NASA LS(1)-0417 = GA(W)-1, public-code wing (ls417_gaw1.dat)"),
        Airfoil("naca0012", 0.12, 0.3, "NACA 0012, rotor blades (naca0012.dat)"),
        Airfoil("naca0015", 0.15, 0.3, "NACA 0015, tails (no coordinate table)"),
    )
}

#: Lift-rotor counts of the lift-plus-cruise layouts the model holds: 2 to 6 mirror-symmetric
#: pairs (a 4-rotor to a 12-rotor vehicle), each pair a rotor group of the design variables;
#: the pusher is the group after the last pair.
LIFT_ROTOR_COUNTS = (4, 6, 8, 10, 12)
#: A condition's ``speed_rule``: its speed as given, or a design variable of the optimizer.
SPEED_RULES = ("fixed", "optimized")
#: Broadband noise models of the hover noise level (``constraints.noise_broadband_model``):
#: the paper's Gill-Lee fit (eq. 22, the default) or the blade-section BPM self-noise (docs
#: theory/acoustics 'BPM broadband model').
BROADBAND_MODELS = ("gill_lee", "bpm")
#: Microphone height of a noise footprint's ground observers when the file gives none (m): the
#: certification microphone 1.2 m (4 ft) above ground (14 CFR Part 36, Appendix H, H36.109;
#: ICAO Annex 16 Vol. I, Appendix 2).
DEFAULT_OBSERVER_HEIGHT = 1.2
#: Parts of each transition leg of a noise footprint, and the most Gauss points per part in the
#: angle of the line of sight, when the file gives none (lpc_mdo.vehicle.footprint_path; docs
#: theory/acoustics 'Noise footprint' measures the SEL's change with more).
DEFAULT_LEG_SUBDIVISIONS = 1
DEFAULT_QUADRATURE_POINTS = 6
_MAX_PAIRS = max(LIFT_ROTOR_COUNTS) // 2
#: Bound of every body-frame coordinate (m): a vehicle of this class is at most 30 m long and
#: wide; 50 m catches positions in mm or in ft x 1000.
_REACH = 50.0
_MAX_FIXED_MASS = 10000.0  # kg
# How W_other (masses.other) is set: as given, or calibrated to the design gross mass (paper IV).
OTHER_MASS_RULES = ("fixed", "calibrated")
#: Section t/c of a rotor blade or a lifting surface (-): propeller tips are 4-6 % thick, wing
#: roots of light aircraft up to 21 % (Raymer, Aircraft Design, 6th ed., sec. 4.3, Fig. 4.14;
#: the reference's sections are 12-17 %); beyond 25 % no lifting section is built.
SECTION_THICKNESS_RANGE = (0.04, 0.25)
_IDENTIFIER = "an identifier (letters, digits and '_', not starting with a digit)"
_AIRFOIL_NAMES = tuple(AIRFOILS)


# ------------------------------------------------------------------------------------------------
# Vehicle dataclasses


@dataclass(frozen=True)
class LiftingSurface:
    """A trapezoidal lifting surface (wing, horizontal or vertical tail).

    The wing and the horizontal tail are mirrored about y = 0; the vertical tail is one surface
    in the x-z plane whose span is its height, measured upwards from the root.

    Attributes
    ----------
    area : float
        Reference area S (m^2), both halves of a mirrored surface.
    aspect_ratio : float
        Aspect ratio b^2/S (-).
    taper_ratio : float
        Tip chord over root chord (-).
    sweep : float
        Leading-edge sweep (rad); file key ``sweep_deg``.
    dihedral : float
        Dihedral (rad), positive tip up; file key ``dihedral_deg``.
    incidence : float
        Root-chord incidence relative to the body x axis (rad), positive nose up; file key
        ``incidence_deg``.
    root_leading_edge : tuple of 3 float
        Leading edge of the root chord, body frame (m).
    airfoil : str
        Section: a key of :data:`AIRFOILS`, or a polar file (alpha [deg], cl, cd rows; the
        wing's needs a cm column, an XFOIL polar file has one) that
        ``components.aero.airfoil.get_polar`` reads.
    laminar_fraction : float
        Laminar part of the skin-friction build-up (-).
    coordinates : str or None
        The section's coordinate file (Selig format), absolute path: its thickness and its
        position feed the drag build-up and, for the wing, the wing box's depth and skins.
        Required with a polar-file airfoil; with a named one it replaces the packaged section
        numbers (then another spar layout is possible).
    """

    # 0.1-200 m^2: tails to wings of 500-20000 kg vehicles (the reference wing in ft^2 is 211).
    area: float = _param("m^2", ge=0.1, le=200)
    # 0.5-30: a low fin (reference vertical tail 1.17) to a sailplane wing.
    aspect_ratio: float = _param(ge=0.5, le=30)
    taper_ratio: float = _param(gt=0, le=1)
    # Leading-edge sweep up to 70 deg (reference fin 51 deg); dihedral up to 30 deg either way;
    # incidence within 10 deg either way (built wings and tails are set at -5..+5 deg; the
    # reference wing's is 2.04 deg; 20 deg is a factor-10 typo).
    sweep: float = _angle(ge=-70, le=70)
    dihedral: float = _angle(ge=-30, le=30)
    incidence: float = _angle(ge=-10, le=10)
    root_leading_edge: tuple[float, ...] = _param("m", ge=-_REACH, le=_REACH, shape=(3,))
    airfoil: str = _param(choices=_AIRFOIL_NAMES, polar_file=True)
    laminar_fraction: float = _param(ge=0, le=1)
    coordinates: str = _param(coordinate_file=True, optional=True)

    @property
    def span(self) -> float:
        """Span b = sqrt(AR S) (m); the height of the vertical tail."""
        return math.sqrt(self.aspect_ratio * self.area)

    @property
    def root_chord(self) -> float:
        """Root chord 2S/((1 + taper) b) (m)."""
        return 2.0 * self.area / ((1.0 + self.taper_ratio) * self.span)

    @property
    def tip_chord(self) -> float:
        """Tip chord (m)."""
        return self.taper_ratio * self.root_chord

    @property
    def mean_aerodynamic_chord(self) -> float:
        """Mean aerodynamic chord (2/3)(1 + λ + λ²)/(1 + λ) c_root (m)."""
        lam = self.taper_ratio
        return 2.0 / 3.0 * (1.0 + lam + lam**2) / (1.0 + lam) * self.root_chord

    @property
    def thickness_to_chord(self) -> float:
        """Section t/c (-): from :attr:`coordinates` if given, else of the named airfoil."""
        if self.coordinates is not None:
            return read_coordinates(self.coordinates).thickness_to_chord
        return AIRFOILS[self.airfoil].thickness_to_chord

    @property
    def max_thickness_location(self) -> float:
        """Section (x/c)_m (-): from :attr:`coordinates` if given, else of the named airfoil."""
        if self.coordinates is not None:
            return read_coordinates(self.coordinates).max_thickness_location
        return AIRFOILS[self.airfoil].max_thickness_location


#: Wing planform kinds of the vehicle file's ``wing.planform``.
WING_PLANFORMS = ("trapezoid", "sections")


@dataclass(frozen=True)
class WingSection:
    """One span-wise section of a cranked wing, as an OpenVSP wing section (``XSec``) defines it.

    The sections run from the root to the tip; a section's root chord is the previous section's
    tip chord. Only their proportions enter the model: the planform is scaled to the wing-area
    and aspect-ratio design variables with span fractions and chord ratios fixed (docs
    theory/geometry 'Cranked wing planform').

    Attributes
    ----------
    span : float
        Section span (m) measured in the section's plane (OpenVSP ``Span``; its projection on
        y is ``span cos(dihedral)``).
    root_chord, tip_chord : float
        Chords at the section's inboard and outboard ends (m).
    sweep : float
        Sweep of the line at ``sweep_location`` (rad), positive aft; file key ``sweep_deg``.
    sweep_location : float
        Chord fraction of the swept line (OpenVSP ``Sweep_Location``; 0 = leading edge).
    twist : float
        Twist of the section's tip chord relative to the wing root chord (rad), positive nose up
        (OpenVSP absolute ``Twist``); file key ``twist_deg``.
    dihedral : float
        Dihedral (rad), positive tip up; file key ``dihedral_deg``.
    """

    # 1 mm to 100 m (catches a span in mm); chords 1 mm to 30 m.
    span: float = _param("m", gt=0, le=100)
    root_chord: float = _param("m", gt=0, le=30)
    tip_chord: float = _param("m", ge=0, le=30)
    sweep: float = _angle(ge=-70, le=70)
    sweep_location: float = _param(ge=0, le=1)
    twist: float = _angle(ge=-30, le=30)
    dihedral: float = _angle(ge=-30, le=30)


@dataclass(frozen=True)
class Wing(LiftingSurface):
    """The wing: a :class:`LiftingSurface` whose planform is a trapezoid or a list of sections.

    ``planform = "trapezoid"`` uses ``taper_ratio``, ``sweep`` (leading edge) and ``dihedral``
    of the surface; ``planform = "sections"`` uses ``sections`` (the NASA LPC wing of OpenVSP in
    the reference vehicle) and sets ``taper_ratio`` to the sections' tip over root chord, and
    ``sweep`` and ``dihedral`` remain whole-wing (root-to-tip leading-edge) figures for the
    estimates that need one number. Either way the planform is scaled to ``area`` and
    ``aspect_ratio`` (:class:`lpc_mdo.components.geometry.cranked_planform.SectionLayout`).

    Attributes
    ----------
    planform : str
        ``"trapezoid"`` or ``"sections"``.
    sections : tuple of WingSection or None
        Root to tip; required with ``planform = "sections"``, not allowed otherwise.
    """

    taper_ratio: float = _param(gt=0, le=1, optional=True)
    planform: str = _param(choices=WING_PLANFORMS)
    sections: tuple[WingSection, ...] = _param(
        optional=True, count_note="the wing sections, [[wing.sections]] tables, root to tip"
    )

    def _geometry(self):
        """Return the sections' planform at ``area`` and ``aspect_ratio``."""
        from lpc_mdo.components.geometry.cranked_planform import SectionLayout

        layout = SectionLayout.from_wing(self)
        return layout.geometry(self.area, self.aspect_ratio, np.zeros(3))

    @property
    def root_chord(self) -> float:
        """Root chord (m) of the planform scaled to ``area`` and ``aspect_ratio``."""
        if self.planform == "trapezoid":
            return super().root_chord
        return float(self._geometry()["root_chord"])

    @property
    def tip_chord(self) -> float:
        """Tip chord (m)."""
        if self.planform == "trapezoid":
            return super().tip_chord
        return float(self._geometry()["tip_chord"])

    @property
    def mean_aerodynamic_chord(self) -> float:
        """Mean aerodynamic chord (2/S) integral of c^2 over the half span (m)."""
        if self.planform == "trapezoid":
            return super().mean_aerodynamic_chord
        return float(self._geometry()["mean_aerodynamic_chord"])


@dataclass(frozen=True)
class Fuselage:
    """Fuselage dimensions and cabin; the nose is the origin of the body frame.

    The fuselage is a nose bay, a cabin and a tail cone, in this order from the nose (docs
    theory/geometry 'Fuselage zones'). The cabin's length follows from its seats: rows of
    ``seats_abreast`` seats at ``seat_pitch``. The length is a design variable: a stretch or a
    shrink goes into the tail cone, so the nose bay and the cabin keep their stations.

    Attributes
    ----------
    length : float
        Length (m); the initial value of the ``fuselage_length`` design variable.
    max_height : float
        Maximum height (m).
    max_width : float
        Maximum width (m).
    nose_length : float
        Length of the nose bay (m): the cabin starts this far aft of the nose.
    seats : int
        Seats in the cabin, crew included.
    seats_abreast : int
        Seats side by side in a row.
    seat_pitch : float
        Length of one seat row (m).
    cabin_floor_z : float
        Body-frame z of the cabin floor (m, z down): an item whose cg is lower (larger z) is
        under the floor, not in the cabin.
    """

    # 1-30 m long, 0.5-10 m high and wide: a one-seat to an airliner-sized cabin (catches mm).
    length: float = _param("m", ge=1, le=30)
    max_height: float = _param("m", ge=0.5, le=10)
    max_width: float = _param("m", ge=0.5, le=10)
    # A nose bay of 0.3-10 m (the cabin cannot start at the nose's tip: the nose cone tapers
    # over at least a third of a metre; the reference's is 1.11 m); 1-100 seats, 1-10 abreast;
    # a seat row of 0.7-1.5 m (an airliner's tightest economy pitch is 0.71 m, 28 in; Kundu,
    # Aircraft Design, 2010, Table 4.5; catches inches and mm); the floor within 10 m of the
    # nose's height.
    nose_length: float = _param("m", ge=0.3, le=10)
    seats: int = _param(ge=1, le=100)
    seats_abreast: int = _param(ge=1, le=10)
    seat_pitch: float = _param("m", ge=0.7, le=1.5)
    cabin_floor_z: float = _param("m", ge=-10, le=10)

    @property
    def fineness_ratio(self) -> float:
        """Length over the larger of height and width (-)."""
        return self.length / max(self.max_height, self.max_width)

    @property
    def seat_rows(self) -> int:
        """Rows of seats: ceil(seats / seats_abreast)."""
        return -(-self.seats // self.seats_abreast)

    @property
    def cabin_length(self) -> float:
        """Cabin length (m): seat rows x seat pitch."""
        return self.seat_rows * self.seat_pitch

    @property
    def cabin_start(self) -> float:
        """Distance of the cabin's front from the nose (m): the nose bay's length."""
        return self.nose_length

    @property
    def cabin_end(self) -> float:
        """Distance of the cabin's aft bulkhead from the nose (m); the tail cone starts here."""
        return self.nose_length + self.cabin_length

    def in_cabin(self, position) -> bool:
        """Whether a body-frame point lies in the cabin: between its stations, above the floor."""
        x, _, z = position
        return bool(self.cabin_start < -x < self.cabin_end and z < self.cabin_floor_z)


@dataclass(frozen=True)
class Rotor:
    """A lift rotor or the pusher propeller.

    Attributes
    ----------
    name : str
        Label, e.g. ``"front_left_outer"``.
    hub_position : tuple of 3 float
        Hub centre, body frame (m).
    radius : float
        Tip radius R (m).
    num_blades : int
        Number of blades.
    hub_radius_ratio : float
        Hub radius over tip radius (-); see :attr:`hub_radius`.
    chord_cp : tuple of 4 float
        Blade chord B-spline control points, root to tip (m).
    twist_cp : tuple of 4 float
        Blade twist B-spline control points, root to tip (rad); file key ``twist_cp_deg``.
    spin_direction : int
        +1: rotation vector along :attr:`thrust_axis` (right-handed), -1: opposite.
    thrust_axis : tuple of 3 float
        Unit thrust direction, body frame: (0, 0, -1) for a lift rotor, (1, 0, 0) for the pusher.
    pair : int
        Group: one per mirror-symmetric lift-rotor pair (0, 1, ...), the next for the pusher.
    airfoil : str
        Blade section, a key of :data:`AIRFOILS`, or a polar file (alpha [deg], cl, cd rows;
        ``.npz`` in the shipped table format) that ``components.aero.airfoil.get_polar`` reads.
    thickness_to_chord : float
        Blade-section t/c (-), of the thickness noise: required with a polar-file airfoil; a
        named airfoil's own when the key is absent (the loader fills it in).
    """

    name: str = _param()
    hub_position: tuple[float, ...] = _param("m", ge=-_REACH, le=_REACH, shape=(3,))
    # 0.1-10 m: a small propeller to a helicopter rotor (the reference lift rotor is 1.524 m).
    radius: float = _param("m", ge=0.1, le=10)
    # 2-8 blades: the range of built rotors and propellers.
    num_blades: int = _param(ge=2, le=8)
    # Hub up to half the radius: beyond it the blade is a stub.
    hub_radius_ratio: float = _param(ge=0, le=0.5)
    # Chord up to 2 m (the reference root chord is 0.3 m; catches mm).
    chord_cp: tuple[float, ...] = _param("m", gt=0, le=2, shape=(4,))
    # Blade pitch within 80 deg of the disk plane either way: a section pitched further is
    # nearly edge-on to the rotation, so its lift acts in the disk plane (no thrust); the
    # reference pusher's root is at 60 deg, its lift rotors' at 30 deg.
    twist_cp: tuple[float, ...] = _angle(ge=-80, le=80, shape=(4,))
    spin_direction: int = _param(choices=(-1, 1))
    thrust_axis: tuple[float, ...] = _param(shape=(3,), unit_vector=True)
    pair: int = _param(ge=0, le=_MAX_PAIRS)
    airfoil: str = _param(choices=_AIRFOIL_NAMES, polar_file=True)
    thickness_to_chord: float = _param(
        ge=SECTION_THICKNESS_RANGE[0], le=SECTION_THICKNESS_RANGE[1], optional=True
    )

    @property
    def hub_radius(self) -> float:
        """Hub radius (m)."""
        return self.hub_radius_ratio * self.radius


@dataclass(frozen=True)
class Booms:
    """The 8 lift-rotor booms ("Rotor_i_Support"), one per lift rotor.

    Attributes
    ----------
    length : float
        Characteristic length of each boom for the drag build-up (m).
    form_factor : float
        Drag form factor of each boom (-).
    attach_points : tuple of tuples of 3 float
        Boom-wing junction of the boom of ``lift_rotors[i]``, body frame (m): one per lift rotor.
    """

    # A boom is 0.1-30 m long (at most a fuselage length); form factors of bodies are 1-3.
    length: float = _param("m", ge=0.1, le=30)
    form_factor: float = _param(ge=1, le=3)
    attach_points: tuple[tuple[float, ...], ...] = _param(
        "m", ge=-_REACH, le=_REACH, shape=(None, 3)
    )


@dataclass(frozen=True)
class Stability:
    """
    Longitudinal-stability allowances of the aerodynamics (docs theory/dynamics).

    Attributes
    ----------
    tail_dynamic_pressure_ratio : float
        Tail efficiency eta_t = q_t/q on the horizontal tail's forces (-); Raymer, *Aircraft
        Design* (6th ed.) sec. 16.3: about 0.9 for a conventional tail.
    """

    # 0.5-1.2: a tail deep in a wing wake to one in a propeller slipstream.
    tail_dynamic_pressure_ratio: float = _param(ge=0.5, le=1.2)


@dataclass(frozen=True)
class WingBox:
    """
    Wing-box layout of the beam model.

    See docs theory/structures 'Material, mesh and load transfer'.

    Attributes
    ----------
    front_spar : float
        Front-spar chord fraction (-).
    rear_spar : float
        Rear-spar chord fraction (-), greater than ``front_spar``.
    beam_axis : float
        Chord fraction of the beam nodes (-).
    num_bays : int
        Bays (rib spaces) per half wing; each thickness design variable has this size.
    """

    front_spar: float = _param(gt=0, lt=1)
    rear_spar: float = _param(gt=0, lt=1)
    beam_axis: float = _param(gt=0, lt=1)
    # 1-50 bays: each adds 4 thickness design variables (the reference has 8).
    num_bays: int = _param(ge=1, le=50)


@dataclass(frozen=True)
class FixedMasses:
    """Masses that are not sized by a model (paper eqs. 31 and 33) and their cg positions.

    Attributes
    ----------
    payload, systems, other : float
        Masses (kg). ``other`` is W_other, the unitemised mass; with ``other_rule = "fixed"``
        the vehicle model uses it as given (the reference vehicle: 0, every mass is an item).
    payload_cg, systems_cg, other_cg : tuple of 3 float
        Centres of gravity, body frame (m).
    power_electronics_cg : tuple of 3 float
        Station of the motors' inverters, body frame (m), where their cables start; the
        inverter and cable masses follow from the motors' current ratings (docs theory/weights
        'Power electronics and cables').
    other_rule : str
        ``"fixed"``: W_other is ``other``. ``"calibrated"``: the paper's procedure (Sec. IV):
        W_other is chosen so that the initial design's gross mass equals
        ``design_gross_mass`` (:func:`lpc_mdo.groups.vehicle.calibrated_other_mass`; ``other``
        is then not read by the vehicle model).
    design_gross_mass : float
        Design gross mass W_dg (kg): the input of the weight regressions that scale with the
        gross mass (landing gear, wing secondary structure, systems), as NDARC's and FLOPS'
        design gross weight is an input of their weight estimates; also the objective's
        reference and, with ``other_rule = "calibrated"``, the calibration target.
    """

    # Each fixed mass is 0-10 t, half the largest gross mass of the class (catches g and 1e30);
    # the payload at least 50 kg, one light occupant (a passenger vehicle carries at least one;
    # the FAA's standard adult is 77-88 kg, AC 120-27F), which catches 5.4 for 540.
    payload: float = _param("kg", ge=50, le=_MAX_FIXED_MASS)
    payload_cg: tuple[float, ...] = _param("m", ge=-_REACH, le=_REACH, shape=(3,))
    systems: float = _param("kg", ge=0, le=_MAX_FIXED_MASS)
    systems_cg: tuple[float, ...] = _param("m", ge=-_REACH, le=_REACH, shape=(3,))
    other: float = _param("kg", ge=0, le=_MAX_FIXED_MASS)
    other_cg: tuple[float, ...] = _param("m", ge=-_REACH, le=_REACH, shape=(3,))
    other_rule: str = _param(choices=OTHER_MASS_RULES)
    power_electronics_cg: tuple[float, ...] = _param("m", ge=-_REACH, le=_REACH, shape=(3,))
    # 500-20000 kg: a one-seat eVTOL to the heaviest of the class (the reference is 3089 kg).
    design_gross_mass: float = _param("kg", ge=500, le=20000)


@dataclass(frozen=True)
class Material:
    """Isotropic wing-box material.

    Attributes
    ----------
    name : str
        Label.
    youngs_modulus : float
        E (Pa).
    shear_modulus : float
        G (Pa).
    density : float
        Density (kg/m^3).
    poisson_ratio : float
        ν (-).
    allowable_stress : float
        Allowable von Mises stress (Pa), the stress limit of the structural subproblem.
    min_gauge : float
        Minimum skin and spar thickness (m); no thickness design variable may go below it.
    """

    name: str = _param()
    # Structural solids: E 1-1000 GPa (wood to diamond), G 1-500 GPa, density 500-20000 kg/m^3
    # (balsa-free wood to tungsten); GPa or g/cm^3 written by mistake fall outside.
    youngs_modulus: float = _param("Pa", ge=1e9, le=1e12)
    shear_modulus: float = _param("Pa", ge=1e9, le=5e11)
    density: float = _param("kg/m^3", ge=500, le=20000)
    poisson_ratio: float = _param(gt=-1, lt=0.5)
    # 1 MPa-10 GPa: above any engineering material's strength (aluminium 350 MPa).
    allowable_stress: float = _param("Pa", ge=1e6, le=1e10)
    # 0.01-50 mm: a foil to a thick plate (catches mm written as m).
    min_gauge: float = _param("m", ge=1e-5, le=0.05)


@dataclass(frozen=True)
class Battery:
    """Energy-based battery.

    Attributes
    ----------
    mass : float
        Initial battery mass, the initial value of the ``battery_mass`` design variable (kg).
    energy_density : float
        Pack-level specific energy (J/kg); file key ``energy_density_wh_per_kg`` in Wh/kg.
    initial_soc : float
        State of charge at the start of the mission (-).
    cg : tuple of 3 float
        Centre of gravity, body frame (m).
    """

    # 1-20000 kg: at most the heaviest gross mass of the class.
    mass: float = _param("kg", ge=1, le=20000)
    # 50-1000 Wh/kg at pack level: lead-acid to beyond lithium-sulphur; catches J/kg (x 3600).
    energy_density: float = _param("Wh/kg", ge=50, le=1000, suffix="_wh_per_kg", scale=3600.0)
    initial_soc: float = _param(gt=0, le=1)
    cg: tuple[float, ...] = _param("m", ge=-_REACH, le=_REACH, shape=(3,))

    @property
    def energy(self) -> float:
        """Stored energy at full charge, mass x energy density (J)."""
        return self.mass * self.energy_density


@dataclass(frozen=True)
class Motor:
    """Design constants shared by the 9 PMSM motors (docs theory/motor 'Parameters', 'Sizing').

    Attributes
    ----------
    length_to_diameter : float
        Stack length over outer stator diameter, L/D (-).
    gear_ratio : float
        Motor speed over rotor speed (-).
    pole_pairs, num_phases, num_slots : int
        Winding layout.
    rated_current : float
        Rated phase current (A).
    voltage_limit : float
        Supply voltage limit (V).
    electric_loading : float
        Specific electric loading Ā (A/m).
    magnetic_loading : float
        Specific magnetic loading B̄ (T).
    torque_density : float
        Torque per mass Q_sp used in the sizing mass (N*m/kg).
    inverter_specific_power : float
        Inverter rating per mass (W/kg); file key ``inverter_specific_power_kw_per_kg`` in
        kW/kg (docs theory/weights 'Power electronics and cables').
    cable_mass_per_ampere_metre : float
        Conductor mass of the motor cables per ampere of continuous current and metre of run
        (kg/(A*m)).
    """

    # Ranges of built radial-flux PMSMs: L/D 0.05-5, gears 0.1-50 (1 = direct drive), up to 50
    # pole pairs, 12 phases, 500 slots, 1-5000 A; supply 24-3000 V (traction packs are
    # 300-1000 V; the limit sets the torque margin, docs theory/motor 'Torque margin');
    # electric loading 1-300 kA/m, air-gap flux 0.1-2.5 T (iron saturates near 2 T),
    # 1-100 N*m/kg.
    length_to_diameter: float = _param(ge=0.05, le=5)
    gear_ratio: float = _param(ge=0.1, le=50)
    pole_pairs: int = _param(ge=1, le=50)
    num_phases: int = _param(ge=1, le=12)
    num_slots: int = _param(ge=1, le=500)
    rated_current: float = _param("A", ge=1, le=5000)
    voltage_limit: float = _param("V", ge=24, le=3000)
    electric_loading: float = _param("A/m", ge=1e3, le=3e5)
    magnetic_loading: float = _param("T", ge=0.1, le=2.5)
    torque_density: float = _param("N*m/kg", ge=1, le=100)
    # 1-100 kW/kg: from industrial drives to beyond the projected aircraft inverters; catches
    # W/kg (x 1000).
    inverter_specific_power: float = _param(
        "kW/kg", ge=1, le=100, suffix="_kw_per_kg", scale=1000.0
    )
    # 1e-4 to 1e-2 kg/(A m): a copper conductor at 0.0112-1.12 mm**2/A (current densities of
    # 0.9-90 A/mm**2); catches g/(A m).
    cable_mass_per_ampere_metre: float = _param("kg/(A*m)", ge=1e-4, le=1e-2)


@dataclass(frozen=True)
class MissionSegment:
    """One segment of the mission as a designer states it (``[[mission.segments]]``).

    A segment is flown in one design condition, whose power it draws; its time comes from one
    of: ``duration``; ``distance`` at the condition's speed; or a climb or descent to
    ``to_altitude`` at ``vertical_speed``. A segment naming the ``design_variable_prefix`` of
    several transition points flies them in turn, ``duration`` split evenly among them. The
    mission sets the conditions' altitudes, flight-path angles, durations and energy weights
    (:mod:`lpc_mdo.vehicle.mission_profile`).

    Attributes
    ----------
    condition : str
        A condition name, or the shared ``design_variable_prefix`` of transition points.
    duration : float or None
        Time (s).
    distance : float or None
        Ground distance (m); file key ``distance_km``.
    to_altitude : float or None
        Altitude at the segment's end (m); with ``vertical_speed``.
    vertical_speed : float or None
        Rate of climb (m/s), negative descending; with ``to_altitude``.
    flight_path_angle : float or None
        Or the climb's flight-path angle (rad), file key ``flight_path_angle_deg``: V_z = V sin
        gamma at the condition's speed (a steady condition only).
    """

    condition: str = _param()
    # Up to 24 h; up to 5000 km; the troposphere; 0.1-25 m/s of climb or descent (a helicopter
    # climbs at up to 15 m/s; 25 catches ft/min).
    duration: float = _param("s", gt=0, le=86400, optional=True)
    distance: float = _param("km", gt=0, le=5000, suffix="_km", scale=1000.0, optional=True)
    to_altitude: float = _param("m", ge=0, le=11000, optional=True)
    vertical_speed: float = _param("m/s", ge=-25, le=25, optional=True)
    # Within 30 deg either way: steeper is no longer a climb of a fixed-wing flight condition.
    flight_path_angle: float = _angle(gt=-30, lt=30, optional=True)


@dataclass(frozen=True)
class MissionReserve:
    """The energy reserve after the mission's legs (``[mission.reserve]``).

    Attributes
    ----------
    rule : str
        ``"time"`` (``duration``), ``"distance"`` (``distance``) or a preset of
        :data:`RESERVE_RULES` (its time or distance is the preset's; cited in
        :data:`lpc_mdo.vehicle.reserve_rules.RESERVE_PRESETS`).
    condition : str or None
        The condition flown in reserve; default the mission's cruise condition.
    duration : float or None
        Reserve time (s), file key ``duration_min`` (minutes); with ``rule = "time"``.
    distance : float or None
        Reserve distance (m), file key ``distance_km``; with ``rule = "distance"``.
    """

    rule: str = _param(choices=RESERVE_RULES)
    condition: str = _param(optional=True)
    duration: float = _param("min", gt=0, le=600, suffix="_min", scale=60.0, optional=True)
    distance: float = _param("km", gt=0, le=5000, suffix="_km", scale=1000.0, optional=True)


@dataclass(frozen=True)
class Mission:
    """The mission-level choices of the sizing mission (paper Sec. IV).

    Either the conditions carry the mission (each its ``duration`` and ``energy_weight``; the
    reference's form, the paper's energy rule) or ``segments`` state it as a designer does, and
    the loader derives those keys (:mod:`lpc_mdo.vehicle.mission_profile`).

    Attributes
    ----------
    cruise_condition : str
        Name of the design cruise condition (a ``steady`` condition): the static margin is
        evaluated and constrained there, the M4 weight regressions take its speed, and the
        wing's sectional zero-lift angle is taken at its Reynolds and Mach numbers.
    temperature_offset : float or None
        ISA temperature offset (K) of every condition: T = T_ISA(h) + dT at the ISA pressure of
        h (a hot or cold day); None: 0.
    start_altitude : float or None
        Altitude of the departure (m): where the first segment starts; required with segments.
    legs : int or None
        How often the segments are flown before the reserve (2: out and back without
        recharging); None: 1.
    segments : tuple of MissionSegment or None
        The mission, in flight order.
    reserve : MissionReserve or None
        The reserve flown after the legs; None: no reserve (the final state-of-charge floor,
        ``constraints.min_final_soc``, is then the only margin).
    reserve_condition, reserve_time : str or None, float
        Derived: the condition flown in reserve and for how long (s); None and 0 without one.
    reserve_distance : float
        Derived: the reserve's distance (m) where its rule is ``distance`` (its time then
        follows an optimized speed), else 0.
    """

    cruise_condition: str = _param()
    # -60..+60 K: ISA-60 is the coldest and ISA+40 the hottest day certification considers.
    temperature_offset: float = _param("K", ge=-60, le=60, optional=True)
    start_altitude: float = _param("m", ge=0, le=11000, optional=True)
    legs: int = _param(ge=1, le=20, optional=True)
    segments: tuple[MissionSegment, ...] = _param(
        optional=True, count_note="the mission's segments, [[mission.segments]] tables"
    )
    reserve: MissionReserve = _param(optional=True)
    # Set by the loader from the segments (lpc_mdo.vehicle.mission_profile.apply_mission).
    reserve_condition: str | None = field(default=None, metadata={"spec": _Spec(derived=True)})
    reserve_time: float = field(default=0.0, metadata={"spec": _Spec(derived=True)})
    reserve_distance: float = field(default=0.0, metadata={"spec": _Spec(derived=True)})

    @property
    def isa_offset(self) -> float:
        """ISA temperature offset (K), 0 when not given."""
        return 0.0 if self.temperature_offset is None else self.temperature_offset


@dataclass(frozen=True)
class DesignCondition:
    """One design condition of the vehicle file.

    Attributes
    ----------
    name : str
        Condition name, an identifier unique in the vehicle; the subsystem's name in the model.
    kind : str
        Which group class builds it and declares its design variables, trim rows, constraints
        and motors: a key of :data:`lpc_mdo.vehicle.condition_contract.CONDITION_KINDS`
        (``hover``, ``oei``, ``transition``, ``steady``, ``structural``).
    altitude : float
        Altitude for the atmosphere (m); the mean altitude in climb and descent.
    speed : float
        Flight speed (m/s); 0 in hover and OEI.
    pitch : float
        Pitch angle (rad): initial value where pitch is a design variable, prescribed in
        transition, 0 in hover and OEI; file key ``pitch_deg``.
    flight_path_angle : float
        Flight-path angle γ (rad), positive climbing; file key ``flight_path_angle_deg``.
    duration : float
        Time the condition represents in the energy sum (s).
    energy_weight : float
        How many times the condition's energy (power x duration) counts in the mission energy
        (-); 0 where it is not part of the mission. The paper's rule E_req = 2 (E_hover +
        2 E_transition + E_climb + E_cruise + E_descent) + E_cruise gives hover 2, each
        transition point 4, climb 2, cruise 3, descent 2, OEI and structural 0.
    load_factor : float
        Load factor n (-): 1 except in structural conditions.
    failed_rotor : int
        Index into ``Vehicle.lift_rotors`` of the failed rotor in an OEI case, else -1.
    acceleration : float
        Prescribed dV/dt (m/s^2) in transition (u̇ = a cos θ, ẇ = a sin θ), else 0.
    design_variable_prefix : str
        Prefix of the design variables the condition owns: its variable ``v`` is the vehicle
        file's ``design_variables.{prefix}_{v}``. Conditions that share a prefix share the
        tables, one row each in vehicle-file order (the reference's five transition points:
        ``transition``); a prefix equal to the condition's name gives it tables of its own.
    speed_rule : str or None
        ``"optimized"``: the speed is a design variable of the condition (``{prefix}_speed``,
        initial value ``speed``), so a level segment flown over a distance takes the time
        distance / V and the optimum flies it at its best-range speed (over a duration, at its
        best-endurance speed); a ``steady`` condition in level flight only. None (default, or
        ``"fixed"``): the speed is ``speed``.
    level_distance : float
        Derived from the mission's segments: the distance (m) per leg flown by the condition's
        ``distance_km`` segments; 0 without.
    """

    name: str = _param()
    kind: str = _param()
    # altitude, flight_path_angle, duration and energy_weight are derived from the mission's
    # segments for the conditions the segments fly (leave them out there), required otherwise.
    altitude: float = _param("m", ge=0, le=11000, optional=True)
    speed: float = _param("m/s", ge=0, le=150)
    pitch: float = _angle(gt=-90, lt=90)
    flight_path_angle: float = _angle(gt=-90, lt=90, optional=True)
    duration: float = _param("s", ge=0, le=86400, optional=True)
    energy_weight: float = _param(ge=0, le=100, optional=True)
    load_factor: float = _param(ge=-5, le=5)
    failed_rotor: int = _param(ge=-1, le=max(LIFT_ROTOR_COUNTS) - 1)
    acceleration: float = _param("m/s^2", ge=-20, le=20)
    design_variable_prefix: str = _param()
    speed_rule: str = _param(choices=SPEED_RULES, optional=True)
    level_distance: float = field(default=0.0, metadata={"spec": _Spec(derived=True)})

    @property
    def optimizes_speed(self) -> bool:
        """Whether the speed is a design variable (``speed_rule = "optimized"``)."""
        return self.speed_rule == "optimized"


@dataclass(frozen=True)
class ConstraintLimits:
    """Limits and targets of the paper's constraints (Tables 6-7).

    The stress limit is ``Material.allowable_stress``; the minimum gauge is ``Material.min_gauge``.

    Attributes
    ----------
    max_noise : float
        Hover A-weighted sound pressure level limit (dBA).
    noise_broadband_model : str or None
        Broadband model of the hover noise level: ``"gill_lee"`` (the paper's, the default when
        absent) or ``"bpm"`` (blade-section Brooks-Pope-Marcolini self-noise; not with a
        ``[noise_footprint]``, whose noise is Gill-Lee's). docs results/broadband compares them.
    min_static_margin : float
        Static margin in cruise, fraction of the MAC (-).
    min_torque_margin : float
        Motor torque safety margin (-).
    min_voltage_margin : float
        Lower limit of each motor's voltage margin 1 - abs(U)/V_lim of its MTPA point, KS over
        its conditions (-).
    max_tip_mach : float
        Hover lift-rotor tip Mach number (-).
    max_lift_rotor_advance_ratio : float
        Edgewise advance ratio mu = V_inplane / (Omega R) of every lift rotor in transition
        (-): the range of the inflow model (docs theory/rotors 'Advance-ratio limit').
    max_lift_rotor_tip_mach : float
        Helical tip Mach number of every working lift rotor in one-rotor-out hover and in
        transition (at the advancing blade) (-).
    max_pusher_tip_mach : float
        Helical tip Mach number of the pusher in every condition that runs it (-).
    min_chord_radius_ratio : float
        Smallest blade chord of every rotor, as a fraction of its radius (-): each chord control
        point >= this times the radius (the B-spline chord lies in their convex hull).
    radius_intersection : float
        Target of the 2 radius-intersection equalities: a span fraction (-) or a clearance (m).
    radius_intersection_definition : str
        ``"span_fraction"``: (R_inner + R_outer)/b = target (default);
        ``"clearance"``: abs(y_outer - y_inner) - (R_inner + R_outer) = target (docs
        theory/geometry 'Rotor layout and radius intersection').
    max_buckling_ratio : float
        Skin stress over critical buckling stress (-).
    min_final_soc : float
        State of charge at the end of the mission (-).
    max_displacement : float
        Wing-tip displacement in the structural subproblem (m).
    min_lift_rotor_clearance : float
        Plan-view gap between two lift-rotor disks (m), docs theory/geometry 'Rotor clearances'.
    min_rotor_fuselage_clearance : float
        Plan-view gap between a lift-rotor disk and the fuselage side (m).
    min_rotor_tail_clearance : float
        Plan-view gap between a lift-rotor disk and the horizontal-tail planform (m); 0 keeps
        every disk off the tail.
    min_rotor_pusher_clearance : float
        Plan-view gap between a lift-rotor disk and the pusher disk (m).
    min_control_acceleration : tuple of 3 float
        Roll, pitch and yaw acceleration (rad/s^2) the lift rotors must be able to add at the
        trimmed hover and one-engine-inoperative points, within their motors' peak torque
        (docs theory/dynamics 'Hover control reserve'); 0 for an axis that is not required.
    wing_stall_lift_fraction : float
        Fraction kappa of a section's maximum lift coefficient at which the wing stalls (-):
        the structural load cases keep every wing section's c_l within kappa c_l,max (and
        kappa c_l,min), docs theory/aerodynamics 'Section lift limit'.
    min_stall_speed_ratio : float
        Least speed over the 1-g stall speed, V/V_S, of every 1-g wing-borne condition
        (transition, steady) (-): their sections keep c_l within kappa c_l,max / ratio^2.
    blade_stall_angle_fraction : float or None
        Fraction of its section's stall angles within which every blade station of the rotors
        solved by blade-element momentum (lift rotors in hover and one-rotor-out hover, the
        pusher wherever it turns) keeps its angle of attack (-); absent: 1, the stall itself
        (docs theory/rotors 'Blade stall limit').
    """

    # 20-200 dBA: a quiet room to beyond the pain threshold.
    max_noise: float = _param("dBA", ge=20, le=200)
    noise_broadband_model: str = _param(choices=BROADBAND_MODELS, optional=True)
    min_static_margin: float = _param(gt=-1, lt=1)
    # A torque margin is a fraction of the rated torque: 0-1.
    min_torque_margin: float = _param(ge=0, le=1)
    # A voltage margin is a fraction of the voltage limit: 0-1.
    min_voltage_margin: float = _param(ge=0, le=1)
    max_tip_mach: float = _param(gt=0, le=1)
    # Edgewise rotor data and inflow models reach mu ~ 1 at most (slowed-rotor tests).
    max_lift_rotor_advance_ratio: float = _param(gt=0, le=1)
    # Subsonic tips only: the rotor polar's stated range ends at M 0.9.
    max_lift_rotor_tip_mach: float = _param(gt=0, le=0.9)
    max_pusher_tip_mach: float = _param(gt=0, le=0.9)
    # At most half the radius: a chord that size already exceeds every blade of the class.
    min_chord_radius_ratio: float = _param(ge=0, le=0.5)
    # A span fraction (<= 1) or a clearance in m (at most 10 m, a rotor radius of the class).
    radius_intersection: float = _param(ge=0, le=10)
    radius_intersection_definition: str = _param(choices=("span_fraction", "clearance"))
    # Stress over the critical buckling stress: 1 is the limit, 10 ignores buckling.
    max_buckling_ratio: float = _param(gt=0, le=10)
    min_final_soc: float = _param(ge=0, lt=1)
    # Wing-tip deflection up to 10 m, more than half the largest span of the class.
    max_displacement: float = _param("m", gt=0, le=10)
    # Clearances 0-10 m (at most a rotor diameter of the class; catches mm).
    min_lift_rotor_clearance: float = _param("m", ge=0, le=10)
    min_rotor_fuselage_clearance: float = _param("m", ge=0, le=10)
    min_rotor_tail_clearance: float = _param("m", ge=0, le=10)
    min_rotor_pusher_clearance: float = _param("m", ge=0, le=10)
    # Angular accelerations 0-20 rad/s^2: beyond what any piloted VTOL demands (catches deg).
    min_control_acceleration: tuple[float, ...] = _param("rad/s^2", ge=0, le=20, shape=(3,))
    # A fraction of the section maximum: above 0 and at most the section maximum itself.
    wing_stall_lift_fraction: float = _param(gt=0, le=1)
    # A fraction of the stall angle: above 0 and at most the stall itself.
    blade_stall_angle_fraction: float = _param(gt=0, le=1, optional=True)
    # 1 (flight at the stall speed) to 2 (far beyond any regulation's 1.1-1.3 V_S floors).
    min_stall_speed_ratio: float = _param(ge=1, le=2)


@dataclass(frozen=True)
class NoiseObserver:
    """An observer of the hover noise constraint (docs theory/acoustics 'Observer and constraint').

    A vehicle file gives one ``[noise_observer]`` table or several ``[[noise_observer]]`` tables;
    each observer is one row of the hover noise constraint.

    Attributes
    ----------
    distance : float
        Slant distance from the rotor-hub centroid (m).
    elevation : float
        Angle below the rotor plane (rad); file key ``elevation_deg``.
    azimuth : float or None
        Azimuth about the body z axis from +x (forward) towards +y (right) (rad); file key
        ``azimuth_deg``, optional: 180 deg (aft, the paper's observer) when absent.
    """

    # Up to 10 km, where a rotor is inaudible; at least 10 rotor radii (checked with the rotors).
    distance: float = _param("m", gt=0, le=10000)
    elevation: float = _angle(ge=-90, le=90)
    azimuth: float = _angle(ge=-360, le=360, optional=True)

    @property
    def azimuth_or_aft(self) -> float:
        """Azimuth (rad): the file's, or pi (aft)."""
        return math.pi if self.azimuth is None else self.azimuth


@dataclass(frozen=True)
class NoiseFootprint:
    """Ground observers of the departure's noise footprint (``[noise_footprint]``).

    The departure is the first hover without a failed rotor, held over the vertiport for
    ``hover_time``, then every transition point in file order, each flown along the track for
    its duration at its speed (:mod:`lpc_mdo.vehicle.footprint_path`; docs theory/acoustics
    'Noise footprint'). The observers stand on the ground at every combination of a track
    position (along the flight direction from the vertiport) and a lateral offset.

    Attributes
    ----------
    track_positions : tuple of float
        Observer positions along the track from the vertiport (m), flight direction positive.
    lateral_offsets : tuple of float or None
        Observer offsets to the right of the track (m); None: on the track only (0).
    observer_height : float or None
        Microphone height above the ground (m); None: 1.2 m (:data:`DEFAULT_OBSERVER_HEIGHT`).
    hover_time : float
        Time hovering over the vertiport on departure (s).
    max_sel : float or None
        Limit of every observer's sound exposure level (dBA); None: not constrained.
    max_lamax : float or None
        Limit of every observer's maximum A-weighted level (dBA); None: not constrained.
        At least one of the two limits is given.
    leg_subdivisions : int or None
        Parts each transition leg is split into (None: 1).
    quadrature_points : int or None
        Most Gauss points per part, in the angle of the line of sight (None: 6; one per 30 deg
        the part subtends at the observer, lpc_mdo.vehicle.footprint_path).
    """

    # Within 20 km of the vertiport: the departure's transition covers a few km.
    track_positions: tuple[float, ...] = _param("m", ge=-20000, le=20000, shape=(None,))
    lateral_offsets: tuple[float, ...] = _param(
        "m", ge=-20000, le=20000, shape=(None,), optional=True
    )
    # A microphone 0-30 m above ground (a roof top at most).
    observer_height: float = _param("m", ge=0, le=30, optional=True)
    hover_time: float = _param("s", gt=0, le=600)
    # 20-200 dBA: a quiet room to beyond the pain threshold.
    max_sel: float = _param("dBA", ge=20, le=200, optional=True)
    max_lamax: float = _param("dBA", ge=20, le=200, optional=True)
    leg_subdivisions: int = _param(ge=1, le=20, optional=True)
    quadrature_points: int = _param(ge=1, le=20, optional=True)

    @property
    def offsets(self) -> tuple[float, ...]:
        """Lateral offsets (m): the file's, or (0,)."""
        return (0.0,) if self.lateral_offsets is None else self.lateral_offsets

    @property
    def height(self) -> float:
        """Microphone height (m): the file's, or 1.2 m."""
        return DEFAULT_OBSERVER_HEIGHT if self.observer_height is None else self.observer_height

    @property
    def subdivisions(self) -> int:
        """Parts of each transition leg: the file's, or 1."""
        return DEFAULT_LEG_SUBDIVISIONS if self.leg_subdivisions is None else self.leg_subdivisions

    @property
    def nodes(self) -> int:
        """Most Gauss points per part of a transition leg: the file's, or 6."""
        return (
            DEFAULT_QUADRATURE_POINTS if self.quadrature_points is None else self.quadrature_points
        )


@dataclass(frozen=True)
class DesignVariable:
    """Bounds, initial value and scaling of one (vector) design variable.

    Values are flattened in row-major order; :attr:`shape` restores them (the ``*_array``
    properties do it).

    Attributes
    ----------
    initial, lower, upper : tuple of float
        Initial value and bounds, ``size`` entries each, in :attr:`units`.
    units : str
        OpenMDAO units (``"m"``, ``"m**2"``, ``"kg"``, ``"rad"``, ``"rpm"``, ``"unitless"``).
    ref : float
        OpenMDAO scaling reference (scaled value = value / ref).
    shape : tuple of int
        Shape, ``(1,)`` for a scalar.
    description : str
        What it is and how its rows and columns are ordered.
    initial_from : str
        The vehicle-file key the initial value is taken from (e.g. ``"wing.area"``), or ``""``
        if the design-variable table gives it.
    """

    initial: tuple[float, ...]
    lower: tuple[float, ...]
    upper: tuple[float, ...]
    units: str
    ref: float
    shape: tuple[int, ...]
    description: str
    initial_from: str

    @property
    def size(self) -> int:
        """Number of entries."""
        return math.prod(self.shape)

    @property
    def initial_array(self) -> np.ndarray:
        """Initial value with :attr:`shape`."""
        return np.reshape(self.initial, self.shape)

    @property
    def lower_array(self) -> np.ndarray:
        """Lower bound with :attr:`shape`."""
        return np.reshape(self.lower, self.shape)

    @property
    def upper_array(self) -> np.ndarray:
        """Upper bound with :attr:`shape`."""
        return np.reshape(self.upper, self.shape)


class _ReadOnlyDict(dict):
    """A dict that refuses changes, so that a cached vehicle cannot be modified by accident."""

    def _refuse(self, *args, **kwargs):
        raise TypeError("Vehicle.design_variables is read-only; build a new vehicle instead")

    __setitem__ = __delitem__ = clear = pop = popitem = setdefault = update = __ior__ = _refuse

    def __reduce__(self):
        return (type(self), (dict(self),))

    def __hash__(self):
        return hash(tuple(self.items()))


@dataclass(frozen=True)
class Vehicle:
    """The complete vehicle definition.

    Attributes
    ----------
    name : str
        Label.
    wing : Wing
        The wing (trapezoid or sections).
    horizontal_tail, vertical_tail : LiftingSurface
        Tail surfaces.
    fuselage : Fuselage
        Fuselage.
    lift_rotors : tuple of 8 Rotor
        Lift rotors, 0..3 on the left, 4..7 on the right; see :attr:`lift_rotor_pairs`.
    pusher : Rotor
        Pusher propeller (group 4).
    booms : Booms
        Lift-rotor booms.
    wing_box : WingBox
        Wing-box layout.
    stability : Stability
        Longitudinal-stability allowances (tail efficiency).
    masses : FixedMasses
        Fixed masses and their cg.
    material : Material
        Wing-box material.
    battery : Battery
        Battery.
    motor : Motor
        Motor design constants.
    mission : Mission
        Energy-accounting rule.
    conditions : tuple of DesignCondition
        Design conditions, in vehicle-file order (15 in the reference vehicle).
    constraints : ConstraintLimits
        Constraint limits.
    noise_observer : tuple of NoiseObserver
        Hover noise observers (one row of the noise constraint each).
    noise_footprint : NoiseFootprint or None
        Ground observers of the departure's noise footprint; None: no footprint.
    design_variables : Mapping of str to DesignVariable
        The 161 paper design variables and the 10 transition roll/yaw speed differentials by
        name (read-only); see the module docstring.
    """

    name: str = _param()
    wing: Wing = _param()
    horizontal_tail: LiftingSurface = _param()
    vertical_tail: LiftingSurface = _param()
    fuselage: Fuselage = _param()
    lift_rotors: tuple[Rotor, ...] = _param(
        count=LIFT_ROTOR_COUNTS,
        count_note="the lift-plus-cruise layout: 2 to 6 mirror-symmetric pairs, [[lift_rotors]] "
        "tables",
    )
    pusher: Rotor = _param()
    booms: Booms = _param()
    wing_box: WingBox = _param()
    stability: Stability = _param()
    masses: FixedMasses = _param()
    material: Material = _param()
    battery: Battery = _param()
    motor: Motor = _param()
    mission: Mission = _param()
    conditions: tuple[DesignCondition, ...] = _param(count_note="at least one [[conditions]] table")
    constraints: ConstraintLimits = _param()
    noise_observer: tuple[NoiseObserver, ...] = _param(
        count_note="one [noise_observer] table or [[noise_observer]] tables"
    )
    noise_footprint: NoiseFootprint = _param(optional=True)
    design_variables: Mapping[str, DesignVariable] = _param()

    @property
    def lift_rotor_pairs(self) -> tuple[tuple[int, int], ...]:
        """Indices into :attr:`lift_rotors` of the rotors of each pair, pair 0 first."""
        return _pairs(self.lift_rotors)

    @property
    def mission_segments(self) -> tuple[DesignCondition, ...]:
        """The conditions that make up the mission energy, in flight order."""
        return tuple(c for c in self.conditions if c.energy_weight > 0)

    def design_variable_count(self) -> int:
        """Total number of scalar design variables (171: the paper's 161 + 10 differentials)."""
        return sum(dv.size for dv in self.design_variables.values())

    def condition(self, name: str) -> DesignCondition:
        """Return the design condition called ``name``."""
        for c in self.conditions:
            if c.name == name:
                return c
        names = [c.name for c in self.conditions]
        raise KeyError(f"no design condition {name!r}; the vehicle's conditions are {names}")


def _pairs(rotors: tuple[Rotor, ...]) -> tuple[tuple[int, int], ...]:
    """Return the indices of the rotors of each pair 0 .. len(rotors)/2 - 1 (the rotor groups)."""
    num_pairs = len(rotors) // 2
    return tuple(tuple(i for i, r in enumerate(rotors) if r.pair == p) for p in range(num_pairs))
