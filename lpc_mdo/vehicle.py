"""The vehicle definition: typed, documented, validated data of the NASA lift-plus-cruise eVTOL.

A vehicle is described by a TOML file; the packaged reference, ``lpc_mdo/data/lpc_reference.toml``,
is the initial design of the paper study, with every value's source in a comment. A user may pass
their own file with the same keys.

Conventions
-----------
- SI units (m, m^2, kg, s, m/s, Pa, N*m, J). Angles are radians in the dataclasses. In the file,
  angle keys end in ``_deg`` and hold degrees (``sweep_deg``, ``twist_cp_deg``, ``pitch_deg``, ...);
  ``battery.energy_density_wh_per_kg`` holds Wh/kg and is stored in J/kg.
- Body frame: x forward, y right, z down, origin at the fuselage nose. Vectors are tuples of floats
  (use ``np.asarray``).
- Conditions are data: each ``[[conditions]]`` entry has a ``name`` (any identifier), a ``kind``
  (a key of :data:`lpc_mdo.groups.condition_kinds.CONDITION_KINDS`: ``hover``, ``oei``,
  ``transition``, ``steady``, ``structural``), its flight state, its ``energy_weight`` in the
  mission energy and the ``design_variable_prefix`` of the design variables it owns. The
  reference vehicle has 15.
- Rotor groups: the 8 lift rotors form 4 mirror-symmetric pairs (``Rotor.pair`` 0..3) that share
  radius, blades, chord, twist and rpm; the pusher is group 4. Per-rotor design variables
  (``rotor_radius``, ``blade_chord_cp``, ``blade_twist_cp``, ``motor_length``) have one row per
  group in that order.

Validation
----------
Every key is required. An unknown key, a missing key, a value of the wrong type (a bool is not a
number; an integer field rejects 2.5 but accepts 2.0) or a non-physical value raises one
:class:`VehicleSpecError` that names the dotted key (``wing.area``, ``lift_rotors[3].radius``), the
value and what is allowed, before anything is built. The checks come from a small schema in the
dataclass field metadata (units, range, file-key suffix, array shape); checks that involve several
fields (symmetric pairs, unique condition names, each kind's own rules, design-variable bounds)
follow.

Design variables
----------------
``Vehicle.design_variables`` maps the design-variable names to :class:`DesignVariable`, in the
order of the vehicle file's ``[design_variables]`` tables. The vehicle-level ones are fixed by the
vehicle; each condition adds those its kind declares (rotor speeds, pitch, elevator), named
``{design_variable_prefix}_{variable}`` and stacked as rows where conditions share a prefix
(:class:`lpc_mdo.groups.condition_base.ConditionLayout`). The reference vehicle has the 31 below:
the paper's 161
(Table 6) and the 10 roll and yaw speed differentials of the transition lift rotors, which the
paper does not have. Without them no trim variable acts on roll in transition, where the pusher's
torque reaction rolls the vehicle (1.1-1.4e3 N m at our optimum, 3-4 % of the weight as a
moment in N m; the paper's trim residuals of at most 25 N m, Table 7, imply that its model
leaves that torque out). Rows of the per-group DVs: lift pairs 0..3, then the
pusher.

======================  =======  ================================================================
name                    shape    meaning
======================  =======  ================================================================
wing_aspect_ratio       1        wing aspect ratio (initial: ``wing.aspect_ratio``)
wing_area               1        wing reference area, m^2 (initial: ``wing.area``)
htail_aspect_ratio      1        h-tail aspect ratio (initial: ``horizontal_tail.aspect_ratio``)
htail_area              1        h-tail reference area, m^2 (initial: ``horizontal_tail.area``)
fuselage_length         1        fuselage length, m (initial: ``fuselage.length``)
rotor_radius            5        rotor radius per group, m (initial: the rotors)
blade_chord_cp          5 x 4    blade chord control points, m (initial: the rotors)
blade_twist_cp          5 x 4    blade twist control points, rad (initial: the rotors)
battery_mass            1        battery mass, kg (initial: ``battery.mass``)
motor_length            5        motor stack length per group, m
hover_lift_rpm          4        lift-rotor speed per pair in hover, rpm
transition_lift_rpm     5 x 4    lift-rotor speed per transition point and pair, rpm (the mean
                                 of the pair's two rotors)
transition_roll_yaw_rpm 5 x 2    lift-rotor speed differentials per transition point, rpm: left
                                 minus right rotors, spin +1 minus spin -1 rotors (not in the
                                 paper: the roll and yaw trim of transition)
oei_lift_rpm            4 x 7    speed of the 7 working lift rotors per OEI case, rpm
transition_pusher_rpm   5        pusher speed per transition point, rpm
climb_pusher_rpm        1        pusher speed in climb, rpm (likewise cruise_, descent_)
climb_pitch             1        pitch in climb, rad (likewise cruise_, descent_, plus_3g_,
                                 minus_1g_; initial: the condition's pitch)
transition_elevator     5        h-tail deflection per transition point, rad
climb_elevator          1        h-tail deflection in climb, rad (likewise cruise_, descent_)
front_spar_thickness    8        per wing-box bay, root to tip, m (likewise rear_spar_,
                                 top_skin_, bottom_skin_; 8 = ``wing_box.num_bays``)
======================  =======  ================================================================

API
---
:func:`load_vehicle` (a path, or ``None`` for the reference), :func:`reference_vehicle` (cached),
:func:`read_vehicle_file` (the raw dict), :func:`vehicle_from_dict` (validate and build from a dict)
and :func:`design_variable_count` (also the method ``Vehicle.design_variable_count()``). The
dataclasses are frozen: change a vehicle by editing the dict from :func:`read_vehicle_file` and
calling :func:`vehicle_from_dict`. ``dataclasses.replace`` also works for quick experiments, but
it skips validation and does not update the design-variable initial values that mirror vehicle
data.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import os
import tomllib
import typing
from collections.abc import Mapping
from dataclasses import dataclass, field
from importlib import resources

import numpy as np

__all__ = [
    "AIRFOILS",
    "Airfoil",
    "Battery",
    "Booms",
    "ConstraintLimits",
    "DesignCondition",
    "DesignVariable",
    "FixedMasses",
    "Fuselage",
    "LiftingSurface",
    "Material",
    "Mission",
    "Motor",
    "NoiseObserver",
    "Rotor",
    "Vehicle",
    "VehicleSpecError",
    "WingBox",
    "design_variable_count",
    "load_vehicle",
    "read_vehicle_file",
    "reference_vehicle",
    "vehicle_from_dict",
]


class VehicleSpecError(ValueError):
    """An invalid vehicle file or dict; the message names the key, the value and what is allowed."""


# ------------------------------------------------------------------------------------------------
# Schema: each dataclass field carries a _Spec in its metadata.


@dataclass(frozen=True)
class _Spec:
    """How a field is read from a vehicle file and checked.

    Ranges (``gt``, ``ge``, ``lt``, ``le``) apply to the file value, before ``scale``.
    """

    units: str = ""  # units of the file value, for messages
    gt: float | None = None
    ge: float | None = None
    lt: float | None = None
    le: float | None = None
    choices: tuple = ()
    suffix: str = ""  # file key = field name + suffix
    scale: float = 1.0  # stored value = file value * scale
    shape: tuple[int, ...] = ()  # arrays of numbers
    unit_vector: bool = False
    count: int | None = None  # lists of tables
    count_note: str = ""
    derived: bool = False  # set by the loader, not read from the file
    polar_file: bool = False  # a string may also name an existing airfoil polar file


_POLAR_SUFFIXES = (".npz", ".txt", ".dat", ".csv", ".pol")


def _param(units: str = "", **kw) -> typing.Any:
    return field(metadata={"spec": _Spec(units=units, **kw)})


def _angle(**kw) -> typing.Any:
    return _param("deg", suffix="_deg", scale=math.pi / 180.0, **kw)


def _spec(f: dataclasses.Field) -> _Spec:
    return f.metadata.get("spec", _Spec())


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


#: Airfoils a vehicle file may name (aero §2, §5, §6.1).
AIRFOILS: dict[str, Airfoil] = {
    a.name: a
    for a in (
        Airfoil("ls413", 0.13, 0.4, "NASA LS(1)-0413 = GA(W)-2, paper wing (ls413_gaw2.dat)"),
        Airfoil("ls417", 0.17, 0.4, "NASA LS(1)-0417 = GA(W)-1, public-code wing (ls417_gaw1.dat)"),
        Airfoil("naca0012", 0.12, 0.3, "NACA 0012, rotor blades (naca0012.dat)"),
        Airfoil("naca0015", 0.15, 0.3, "NACA 0015, tails (no coordinate table)"),
    )
}

_NUM_LIFT_ROTORS = 8
_NUM_PAIRS = 4
_PUSHER_GROUP = 4
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
        Section name, a key of :data:`AIRFOILS`.
    laminar_fraction : float
        Laminar part of the skin-friction build-up (-).
    """

    area: float = _param("m^2", gt=0)
    aspect_ratio: float = _param(gt=0)
    taper_ratio: float = _param(gt=0, le=1)
    sweep: float = _angle(gt=-90, lt=90)
    dihedral: float = _angle(gt=-90, lt=90)
    incidence: float = _angle(ge=-30, le=30)
    root_leading_edge: tuple[float, ...] = _param("m", shape=(3,))
    airfoil: str = _param(choices=_AIRFOIL_NAMES)
    laminar_fraction: float = _param(ge=0, le=1)

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
        """Section t/c of :attr:`airfoil` (-)."""
        return AIRFOILS[self.airfoil].thickness_to_chord

    @property
    def max_thickness_location(self) -> float:
        """Section (x/c)_m of :attr:`airfoil` (-)."""
        return AIRFOILS[self.airfoil].max_thickness_location


@dataclass(frozen=True)
class Fuselage:
    """Fuselage dimensions; the nose is the origin of the body frame.

    Attributes
    ----------
    length : float
        Length (m).
    max_height : float
        Maximum height (m).
    max_width : float
        Maximum width (m).
    """

    length: float = _param("m", gt=0)
    max_height: float = _param("m", gt=0)
    max_width: float = _param("m", gt=0)

    @property
    def fineness_ratio(self) -> float:
        """Length over the larger of height and width (-)."""
        return self.length / max(self.max_height, self.max_width)


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
        Group: 0..3 for the lift-rotor pairs, 4 for the pusher.
    airfoil : str
        Blade section, a key of :data:`AIRFOILS`, or a polar file (alpha [deg], cl, cd rows;
        ``.npz`` in the shipped table format) that ``components.aero.airfoil.get_polar`` reads.
    """

    name: str = _param()
    hub_position: tuple[float, ...] = _param("m", shape=(3,))
    radius: float = _param("m", gt=0)
    num_blades: int = _param(ge=1)
    hub_radius_ratio: float = _param(ge=0, lt=1)
    chord_cp: tuple[float, ...] = _param("m", gt=0, shape=(4,))
    twist_cp: tuple[float, ...] = _angle(gt=-90, lt=90, shape=(4,))
    spin_direction: int = _param(choices=(-1, 1))
    thrust_axis: tuple[float, ...] = _param(shape=(3,), unit_vector=True)
    pair: int = _param(ge=0, le=_PUSHER_GROUP)
    airfoil: str = _param(choices=_AIRFOIL_NAMES, polar_file=True)

    @property
    def hub_radius(self) -> float:
        """Hub radius (m)."""
        return self.hub_radius_ratio * self.radius

    @property
    def thickness_to_chord(self) -> float | None:
        """Section t/c of :attr:`airfoil` (-); None for a polar file, which gives no thickness."""
        airfoil = AIRFOILS.get(self.airfoil)
        return None if airfoil is None else airfoil.thickness_to_chord


@dataclass(frozen=True)
class Booms:
    """The 8 lift-rotor booms ("Rotor_i_Support"), one per lift rotor.

    Attributes
    ----------
    length : float
        Characteristic length of each boom for the drag build-up (m).
    form_factor : float
        Drag form factor of each boom (-).
    attach_points : tuple of 8 tuples of 3 float
        Boom-wing junction of the boom of ``lift_rotors[i]``, body frame (m).
    """

    length: float = _param("m", gt=0)
    form_factor: float = _param(gt=0)
    attach_points: tuple[tuple[float, ...], ...] = _param("m", shape=(_NUM_LIFT_ROTORS, 3))


@dataclass(frozen=True)
class WingBox:
    """Wing-box layout of the beam model (ref §6.7).

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
    num_bays: int = _param(ge=1)


@dataclass(frozen=True)
class FixedMasses:
    """Masses that are not sized by a model (paper eqs. 31 and 33) and their cg positions.

    Attributes
    ----------
    payload, systems, other, power_electronics : float
        Masses (kg). ``other`` is an initial guess, calibrated so that the initial gross mass
        equals ``target_gross_mass``.
    payload_cg, systems_cg, other_cg, power_electronics_cg : tuple of 3 float
        Centres of gravity, body frame (m).
    target_gross_mass : float
        Gross mass of the initial design that ``other`` is calibrated to (kg).
    other_cg_rule : str
        'fixed': ``other_cg`` as given. 'hover_balance': the x of ``other_cg`` is an initial
        guess, calibrated (like ``other``) so that the initial design's cg lies above the mean
        lift-hub x, i.e. the lift rotors trim hover with equal thrust.
    """

    payload: float = _param("kg", ge=0)
    payload_cg: tuple[float, ...] = _param("m", shape=(3,))
    systems: float = _param("kg", ge=0)
    systems_cg: tuple[float, ...] = _param("m", shape=(3,))
    other: float = _param("kg", ge=0)
    other_cg: tuple[float, ...] = _param("m", shape=(3,))
    power_electronics: float = _param("kg", ge=0)
    power_electronics_cg: tuple[float, ...] = _param("m", shape=(3,))
    target_gross_mass: float = _param("kg", gt=0)
    other_cg_rule: str = _param(choices=("fixed", "hover_balance"))


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
    youngs_modulus: float = _param("Pa", gt=0)
    shear_modulus: float = _param("Pa", gt=0)
    density: float = _param("kg/m^3", gt=0)
    poisson_ratio: float = _param(gt=-1, lt=0.5)
    allowable_stress: float = _param("Pa", gt=0)
    min_gauge: float = _param("m", gt=0)


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

    mass: float = _param("kg", gt=0)
    energy_density: float = _param("Wh/kg", gt=0, suffix="_wh_per_kg", scale=3600.0)
    initial_soc: float = _param(gt=0, le=1)
    cg: tuple[float, ...] = _param("m", shape=(3,))

    @property
    def energy(self) -> float:
        """Stored energy at full charge, mass x energy density (J)."""
        return self.mass * self.energy_density


@dataclass(frozen=True)
class Motor:
    """Design constants shared by the 9 PMSM motors (ref §7.1-7.2).

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
    """

    length_to_diameter: float = _param(gt=0)
    gear_ratio: float = _param(gt=0)
    pole_pairs: int = _param(ge=1)
    num_phases: int = _param(ge=1)
    num_slots: int = _param(ge=1)
    rated_current: float = _param("A", gt=0)
    voltage_limit: float = _param("V", gt=0)
    electric_loading: float = _param("A/m", gt=0)
    magnetic_loading: float = _param("T", gt=0)
    torque_density: float = _param("N*m/kg", gt=0)


@dataclass(frozen=True)
class Mission:
    """The mission-level choices of the sizing mission (paper Sec. IV).

    The mission segments are the design conditions with a positive ``energy_weight`` (see
    :attr:`Vehicle.mission_segments`); their durations and weights are in the conditions.

    Attributes
    ----------
    cruise_condition : str
        Name of the design cruise condition (a ``steady`` condition): the static margin is
        evaluated and constrained there, the M4 weight regressions take its speed, and the
        wing's sectional zero-lift angle is taken at its Reynolds and Mach numbers.
    """

    cruise_condition: str = _param()


@dataclass(frozen=True)
class DesignCondition:
    """One design condition of the vehicle file.

    Attributes
    ----------
    name : str
        Condition name, an identifier unique in the vehicle; the subsystem's name in the model.
    kind : str
        Which group class builds it and declares its design variables, trim rows, constraints
        and motors: a key of :data:`lpc_mdo.groups.condition_kinds.CONDITION_KINDS`
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
    """

    name: str = _param()
    kind: str = _param()
    altitude: float = _param("m", ge=0, le=11000)
    speed: float = _param("m/s", ge=0, le=150)
    pitch: float = _angle(gt=-90, lt=90)
    flight_path_angle: float = _angle(gt=-90, lt=90)
    duration: float = _param("s", ge=0, le=86400)
    energy_weight: float = _param(ge=0, le=100)
    load_factor: float = _param(ge=-5, le=5)
    failed_rotor: int = _param(ge=-1, le=_NUM_LIFT_ROTORS - 1)
    acceleration: float = _param("m/s^2", ge=-20, le=20)
    design_variable_prefix: str = _param()


@dataclass(frozen=True)
class ConstraintLimits:
    """Limits and targets of the paper's constraints (Tables 6-7).

    The stress limit is ``Material.allowable_stress``; the minimum gauge is ``Material.min_gauge``.

    Attributes
    ----------
    max_noise : float
        Hover A-weighted sound pressure level limit (dBA).
    min_static_margin : float
        Static margin in cruise, fraction of the MAC (-).
    min_torque_margin : float
        Motor torque safety margin (-).
    max_tip_mach : float
        Hover lift-rotor tip Mach number (-).
    radius_intersection : float
        Target of the 2 radius-intersection equalities: a span fraction (-) or a clearance (m).
    radius_intersection_definition : str
        ``"span_fraction"``: (R_inner + R_outer)/b = target (default);
        ``"clearance"``: |y_outer - y_inner| - (R_inner + R_outer) = target (ref §3.3).
    max_buckling_ratio : float
        Skin stress over critical buckling stress (-).
    min_final_soc : float
        State of charge at the end of the mission (-).
    max_displacement : float
        Wing-tip displacement in the structural subproblem (m).
    """

    max_noise: float = _param("dBA", gt=0, le=200)
    min_static_margin: float = _param(gt=-1, lt=1)
    min_torque_margin: float = _param(ge=0)
    max_tip_mach: float = _param(gt=0, le=1)
    radius_intersection: float = _param(ge=0)
    radius_intersection_definition: str = _param(choices=("span_fraction", "clearance"))
    max_buckling_ratio: float = _param(gt=0)
    min_final_soc: float = _param(ge=0, lt=1)
    max_displacement: float = _param("m", gt=0)


@dataclass(frozen=True)
class NoiseObserver:
    """Observer of the hover noise constraint (aero §10.1).

    Attributes
    ----------
    distance : float
        Slant distance from the vehicle reference point (m).
    elevation : float
        Angle below the rotor plane (rad); file key ``elevation_deg``.
    """

    distance: float = _param("m", gt=0)
    elevation: float = _angle(ge=-90, le=90)


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
    wing, horizontal_tail, vertical_tail : LiftingSurface
        Lifting surfaces.
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
    noise_observer : NoiseObserver
        Hover noise observer.
    design_variables : Mapping of str to DesignVariable
        The 161 paper design variables and the 10 transition roll/yaw speed differentials by
        name (read-only); see the module docstring.
    """

    name: str = _param()
    wing: LiftingSurface = _param()
    horizontal_tail: LiftingSurface = _param()
    vertical_tail: LiftingSurface = _param()
    fuselage: Fuselage = _param()
    lift_rotors: tuple[Rotor, ...] = _param(
        count=_NUM_LIFT_ROTORS,
        count_note="the lift-plus-cruise layout: 4 mirror-symmetric pairs, [[lift_rotors]] tables",
    )
    pusher: Rotor = _param()
    booms: Booms = _param()
    wing_box: WingBox = _param()
    masses: FixedMasses = _param()
    material: Material = _param()
    battery: Battery = _param()
    motor: Motor = _param()
    mission: Mission = _param()
    conditions: tuple[DesignCondition, ...] = _param(count_note="at least one [[conditions]] table")
    constraints: ConstraintLimits = _param()
    noise_observer: NoiseObserver = _param()
    design_variables: Mapping[str, DesignVariable] = _param()

    @property
    def lift_rotor_pairs(self) -> tuple[tuple[int, int], ...]:
        """Indices into :attr:`lift_rotors` of the rotors of pairs 0..3."""
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


# ------------------------------------------------------------------------------------------------
# Public API


def read_vehicle_file(path: str | os.PathLike | None = None) -> dict:
    """Parse a vehicle TOML file into a plain dict, without validation.

    Parameters
    ----------
    path : str or os.PathLike or None
        The file; ``None`` reads the packaged reference ``lpc_mdo/data/lpc_reference.toml``.

    Returns
    -------
    dict
        A fresh dict on every call, safe to modify and pass to :func:`vehicle_from_dict`.
    """
    if path is None:
        resource = resources.files("lpc_mdo").joinpath("data", "lpc_reference.toml")
        text, label = resource.read_text(encoding="utf-8"), "lpc_reference.toml"
    else:
        with open(path, encoding="utf-8") as fh:
            text, label = fh.read(), os.fspath(path)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise VehicleSpecError(f"vehicle file '{label}' is not valid TOML: {exc}") from exc


def load_vehicle(path: str | os.PathLike | None = None) -> Vehicle:
    """Read, validate and build a vehicle from a TOML file.

    Parameters
    ----------
    path : str or os.PathLike or None
        The file; ``None`` loads the packaged reference vehicle.

    Raises
    ------
    VehicleSpecError
        If the file is not valid TOML or any value is missing, unknown, mistyped or out of range.
    """
    return vehicle_from_dict(read_vehicle_file(path))


@functools.cache
def reference_vehicle() -> Vehicle:
    """The packaged reference vehicle, loaded once (it is immutable)."""
    return load_vehicle()


def vehicle_from_dict(data: Mapping) -> Vehicle:
    """Validate a vehicle description (the parsed TOML) and build the :class:`Vehicle`.

    Raises
    ------
    VehicleSpecError
        At the first problem, naming the dotted key, the value and what is allowed.
    """
    values = _read_fields(Vehicle, data, "", skip="design_variables")
    _check_lift_rotors(values["lift_rotors"])
    _check_pusher(values["pusher"])
    _check_conditions(values)
    wing_box = values["wing_box"]
    if wing_box.rear_spar <= wing_box.front_spar:
        raise VehicleSpecError(
            f"'wing_box.rear_spar' = {wing_box.rear_spar!r} is out of range: must be > "
            f"'wing_box.front_spar' = {wing_box.front_spar!r}"
        )
    _check_mission(values["mission"], values["conditions"])
    values["design_variables"] = _read_design_variables(data["design_variables"], values)
    return Vehicle(**values)


def design_variable_count(vehicle: Vehicle | None = None) -> int:
    """Total number of scalar design variables (171: the paper's 161 + 10 differentials).

    Parameters
    ----------
    vehicle : Vehicle or None
        The vehicle; ``None`` uses :func:`reference_vehicle`.
    """
    return (reference_vehicle() if vehicle is None else vehicle).design_variable_count()


# ------------------------------------------------------------------------------------------------
# Generic reading and checking


def _join(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key


def _show(value) -> str:
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return f"{type(value).__name__} {text}"


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _range_text(spec: _Spec) -> str:
    """``"> 0"``, ``"in [0, 1)"``, ... for the range of a spec; ``""`` if unbounded."""
    low = ("[", spec.ge) if spec.ge is not None else ("(", spec.gt) if spec.gt is not None else ()
    high = ("]", spec.le) if spec.le is not None else (")", spec.lt) if spec.lt is not None else ()
    if low and high:
        return f"in {low[0]}{_fmt(low[1])}, {_fmt(high[1])}{high[0]}"
    if low:
        return f"{'>=' if low[0] == '[' else '>'} {_fmt(low[1])}"
    if high:
        return f"{'<=' if high[0] == ']' else '<'} {_fmt(high[1])}"
    return ""


def _units_suffix(spec: _Spec) -> str:
    return f" ({spec.units})" if spec.units else ""


def _describe(tp, spec: _Spec) -> str:
    """Short description of what a key must hold, for 'missing key' messages."""
    if dataclasses.is_dataclass(tp):
        return "table"
    if typing.get_origin(tp) is tuple and dataclasses.is_dataclass(typing.get_args(tp)[0]):
        return f"list of {spec.count} tables"
    if typing.get_origin(tp) is Mapping:
        return "table of design-variable tables"
    if spec.choices:
        return "one of " + ", ".join(repr(c) for c in spec.choices)
    parts = [spec.units] if spec.units else []
    if spec.shape:
        kind = " x ".join(str(n) for n in spec.shape) + " numbers"
        parts.insert(0, kind)
    elif tp is int:
        parts.insert(0, "integer")
    elif tp is str:
        parts.insert(0, "string")
    if spec.unit_vector:
        parts.append("unit vector")
    if _range_text(spec):
        parts.append(_range_text(spec))
    return ", ".join(parts) if parts else "number"


@functools.cache
def _hints(cls) -> dict:
    return typing.get_type_hints(cls)


def _check_keys(data, allowed: Mapping[str, str], path: str) -> None:
    """Reject a non-table, unknown keys and missing keys; ``allowed`` maps key -> description."""
    if not isinstance(data, Mapping):
        what = f"'{path}'" if path else "a vehicle description"
        raise VehicleSpecError(f"{what} must be a table, got {_show(data)}")
    for key in data:
        if key not in allowed:
            names = ", ".join(repr(k) for k in sorted(allowed))
            raise VehicleSpecError(f"unknown key '{_join(path, key)}'; allowed keys: {names}")
    for key, description in allowed.items():
        if key not in data:
            raise VehicleSpecError(f"missing key '{_join(path, key)}' ({description})")


def _read_fields(cls, data, path: str, skip: str = "") -> dict:
    """Check the keys of a table and convert every file-backed field of ``cls`` except ``skip``."""
    hints = _hints(cls)
    fields = {f.name + _spec(f).suffix: f for f in dataclasses.fields(cls) if not _spec(f).derived}
    _check_keys(data, {k: _describe(hints[f.name], _spec(f)) for k, f in fields.items()}, path)
    return {
        f.name: _convert(hints[f.name], _spec(f), data[key], _join(path, key))
        for key, f in fields.items()
        if f.name != skip
    }


def _convert(tp, spec: _Spec, value, path: str):
    if dataclasses.is_dataclass(tp):
        return tp(**_read_fields(tp, value, path))
    if typing.get_origin(tp) is tuple:
        item = typing.get_args(tp)[0]
        if dataclasses.is_dataclass(item):
            return _table_list(item, spec, value, path)
        array = _array(value, spec.shape, spec, path)
        if spec.unit_vector and not math.isclose(math.hypot(*array), 1.0, rel_tol=1e-6):
            raise VehicleSpecError(
                f"'{path}' = {value!r} is out of range: must be a unit vector "
                f"(norm 1), got norm {_fmt(math.hypot(*array))}"
            )
        return array
    if tp is float:
        return _number(value, spec, path)
    if tp is int:
        return _integer(value, spec, path)
    return _string(value, spec, path)


def _out_of_range(path: str, value, spec: _Spec) -> VehicleSpecError:
    return VehicleSpecError(
        f"'{path}' = {value!r} is out of range: must be {_range_text(spec)}{_units_suffix(spec)}"
    )


def _in_range(x: float, spec: _Spec) -> bool:
    return not (
        (spec.gt is not None and x <= spec.gt)
        or (spec.ge is not None and x < spec.ge)
        or (spec.lt is not None and x >= spec.lt)
        or (spec.le is not None and x > spec.le)
    )


def _number(value, spec: _Spec, path: str) -> float:
    if not _is_number(value):
        raise VehicleSpecError(f"'{path}' must be a number, got {_show(value)}")
    x = float(value)
    if not math.isfinite(x):
        raise VehicleSpecError(f"'{path}' = {value!r} is out of range: must be a finite number")
    if not _in_range(x, spec):
        raise _out_of_range(path, value, spec)
    return x * spec.scale


def _integer(value, spec: _Spec, path: str) -> int:
    if not (_is_number(value) and float(value).is_integer()):
        raise VehicleSpecError(f"'{path}' must be an integer, got {_show(value)}")
    n = int(value)
    if spec.choices and n not in spec.choices:
        allowed = ", ".join(str(c) for c in spec.choices)
        raise VehicleSpecError(f"'{path}' = {value!r} is not allowed: must be one of {allowed}")
    if not _in_range(n, spec):
        raise _out_of_range(path, value, spec)
    return n


def _string(value, spec: _Spec, path: str) -> str:
    if not isinstance(value, str):
        raise VehicleSpecError(f"'{path}' must be a string, got {_show(value)}")
    if spec.choices and value not in spec.choices:
        if spec.polar_file and value.lower().endswith(_POLAR_SUFFIXES):
            if not os.path.isfile(value):
                raise VehicleSpecError(f"'{path}' = {value!r}: polar file not found")
            return os.path.abspath(value)
        allowed = ", ".join(repr(c) for c in spec.choices)
        extra = (f", or a polar file ({', '.join(_POLAR_SUFFIXES)}: alpha [deg], cl, cd)"
                 if spec.polar_file else "")
        raise VehicleSpecError(f"'{path}' = {value!r} is not allowed: must be one of "
                               f"{allowed}{extra}")
    return value


def _array(value, shape: tuple[int, ...], spec: _Spec, path: str) -> tuple:
    """A nested list of numbers with ``shape`` -> nested tuples of converted floats."""
    if not shape:
        return _number(value, spec, path)
    n = shape[0]
    what = f"a list of {n} " + ("numbers" if len(shape) == 1 else "lists")
    if not isinstance(value, list):
        raise VehicleSpecError(f"'{path}' must be {what}, got {_show(value)}")
    if len(value) != n:
        raise VehicleSpecError(f"'{path}' must have {n} elements, got {len(value)}")
    return tuple(_array(v, shape[1:], spec, f"{path}[{i}]") for i, v in enumerate(value))


def _table_list(cls, spec: _Spec, value, path: str) -> tuple:
    if not isinstance(value, list):
        raise VehicleSpecError(
            f"'{path}' must be a list of tables ([[{path}]]), got {_show(value)}"
        )
    if spec.count is not None and len(value) != spec.count:
        raise VehicleSpecError(
            f"'{path}' must have exactly {spec.count} entries ({spec.count_note}), got {len(value)}"
        )
    if not value:
        raise VehicleSpecError(f"'{path}' must have at least one entry ({spec.count_note})")
    return tuple(cls(**_read_fields(cls, v, f"{path}[{i}]")) for i, v in enumerate(value))


# ------------------------------------------------------------------------------------------------
# Checks across fields


def _pairs(rotors: tuple[Rotor, ...]) -> tuple[tuple[int, int], ...]:
    return tuple(tuple(i for i, r in enumerate(rotors) if r.pair == p) for p in range(_NUM_PAIRS))


def _close(a, b) -> bool:
    return bool(np.allclose(a, b, rtol=1e-9, atol=1e-6))


def _check_lift_rotors(rotors: tuple[Rotor, ...]) -> None:
    for i, r in enumerate(rotors):
        if r.pair >= _NUM_PAIRS:
            raise VehicleSpecError(
                f"'lift_rotors[{i}].pair' = {r.pair} is out of range: must be in [0, "
                f"{_NUM_PAIRS - 1}] (group {_PUSHER_GROUP} is the pusher)"
            )
    shared = ("radius", "num_blades", "hub_radius_ratio", "chord_cp", "twist_cp", "airfoil")
    for p, members in enumerate(_pairs(rotors)):
        if len(members) != 2:
            listed = ", ".join(f"lift_rotors[{i}]" for i in members) or "none"
            raise VehicleSpecError(
                f"'lift_rotors' pair {p} has {len(members)} rotors ({listed}); each pair "
                f"0..{_NUM_PAIRS - 1} must have exactly 2 mirror-image rotors"
            )
        i, j = members
        a, b = rotors[i], rotors[j]
        for name in shared:
            if not _close_or_equal(getattr(a, name), getattr(b, name)):
                raise VehicleSpecError(
                    f"'lift_rotors[{j}].{name}' = {getattr(b, name)!r} differs from its pair "
                    f"partner 'lift_rotors[{i}].{name}' = {getattr(a, name)!r}; the rotors of a "
                    f"pair share {', '.join(shared)}"
                )
        for name in ("hub_position", "thrust_axis"):
            va, vb = getattr(a, name), getattr(b, name)
            if not _close(vb, (va[0], -va[1], va[2])):
                raise VehicleSpecError(
                    f"'lift_rotors[{j}].{name}' = {vb!r} is not the mirror image (y -> -y) of "
                    f"its pair partner 'lift_rotors[{i}].{name}' = {va!r}"
                )
        if a.spin_direction == b.spin_direction:
            raise VehicleSpecError(
                f"'lift_rotors[{j}].spin_direction' = {b.spin_direction} must be opposite to its "
                f"pair partner 'lift_rotors[{i}].spin_direction' = {a.spin_direction}, so that "
                f"each pair balances its yaw torque"
            )


def _close_or_equal(a, b) -> bool:
    return a == b if isinstance(a, str) else _close(a, b)


def _check_pusher(pusher: Rotor) -> None:
    if pusher.pair != _PUSHER_GROUP:
        raise VehicleSpecError(
            f"'pusher.pair' = {pusher.pair} is not allowed: must be {_PUSHER_GROUP} "
            f"(the pusher is its own group; 0..3 are the lift-rotor pairs)"
        )


def _check_conditions(parts: dict) -> None:
    """Names unique identifiers, kinds registered, each kind's own rules (its class's check)."""
    from lpc_mdo.groups.condition_kinds import CONDITION_KINDS

    vehicle = _PartialVehicle(parts)
    seen: dict[str, int] = {}
    for i, c in enumerate(parts["conditions"]):
        path = f"conditions[{i}]"
        for key in ("name", "design_variable_prefix"):
            value = getattr(c, key)
            if not value.isidentifier():
                raise VehicleSpecError(f"'{path}.{key}' = {value!r} is not allowed: must be "
                                       f"{_IDENTIFIER}")
        if c.name in seen:
            raise VehicleSpecError(f"'{path}.name' = {c.name!r} repeats "
                                   f"'conditions[{seen[c.name]}].name'; names must be unique")
        seen[c.name] = i
        if c.kind not in CONDITION_KINDS:
            allowed = ", ".join(repr(k) for k in CONDITION_KINDS)
            raise VehicleSpecError(f"'{path}.kind' = {c.kind!r} is not allowed: must be one of "
                                   f"{allowed} (register a new kind with "
                                   f"lpc_mdo.groups.condition_kinds.register_condition_kind)")
        CONDITION_KINDS[c.kind].check(i, c, vehicle)


def _check_mission(mission: Mission, conditions: tuple[DesignCondition, ...]) -> None:
    steady = [c.name for c in conditions if c.kind == "steady"]
    if mission.cruise_condition not in steady:
        raise VehicleSpecError(
            f"'mission.cruise_condition' = {mission.cruise_condition!r} is not allowed: must be "
            f"the name of a 'steady' condition, one of {steady}"
        )


class _PartialVehicle:
    """The parts of a vehicle read so far, as attributes (for checks before it is built)."""

    def __init__(self, parts: dict):
        self.__dict__.update(parts)


# ------------------------------------------------------------------------------------------------
# Design variables


@dataclass(frozen=True)
class _DVSpec:
    """What the vehicle fixes about a design variable: units, shape and any linked initial value."""

    description: str
    units: str
    shape: tuple[int, ...]
    initial_from: str = ""
    initial: tuple[float, ...] | None = None
    lower_min: tuple[float, str] | None = None  # (value, key) the lower bound may not go below


def _design_variable_specs(parts: dict) -> dict[str, _DVSpec]:
    """The design variables (paper Table 6), sized from the built vehicle parts.

    The vehicle-level ones (planform, rotors, battery, motors, wing box), then those the
    conditions own (:class:`lpc_mdo.groups.condition_base.ConditionLayout`).
    """
    from lpc_mdo.groups.condition_base import ConditionLayout
    wing, htail = parts["wing"], parts["horizontal_tail"]
    groups = [parts["lift_rotors"][i] for i, _ in _pairs(parts["lift_rotors"])]
    groups.append(parts["pusher"])
    ng = len(groups)
    n_bays = parts["wing_box"].num_bays
    rotor_rows = "rows: lift pairs 0-3, pusher"
    rotor_from = "lift_rotors[i].{0} (one rotor per pair) and pusher.{0}"
    gauge = (parts["material"].min_gauge, "material.min_gauge")

    def scalar(description, units, key, value):
        return _DVSpec(description, units, (1,), key, (value,))

    def thickness(what):
        return _DVSpec(
            f"{what} thickness per wing-box bay, root to tip", "m", (n_bays,), lower_min=gauge
        )

    specs = {
        "wing_aspect_ratio": scalar(
            "wing aspect ratio", "unitless", "wing.aspect_ratio", wing.aspect_ratio
        ),
        "wing_area": scalar("wing reference area", "m**2", "wing.area", wing.area),
        "htail_aspect_ratio": scalar(
            "h-tail aspect ratio", "unitless", "horizontal_tail.aspect_ratio", htail.aspect_ratio
        ),
        "htail_area": scalar("h-tail reference area", "m**2", "horizontal_tail.area", htail.area),
        "fuselage_length": scalar(
            "fuselage length", "m", "fuselage.length", parts["fuselage"].length
        ),
        "rotor_radius": _DVSpec(
            f"rotor radius; {rotor_rows}",
            "m",
            (ng,),
            rotor_from.format("radius"),
            tuple(r.radius for r in groups),
        ),
        "blade_chord_cp": _DVSpec(
            f"blade chord control points, root to tip; {rotor_rows}",
            "m",
            (ng, 4),
            rotor_from.format("chord_cp"),
            tuple(x for r in groups for x in r.chord_cp),
        ),
        "blade_twist_cp": _DVSpec(
            f"blade twist control points, root to tip; {rotor_rows}",
            "rad",
            (ng, 4),
            rotor_from.format("twist_cp_deg"),
            tuple(x for r in groups for x in r.twist_cp),
        ),
        "battery_mass": scalar("battery mass", "kg", "battery.mass", parts["battery"].mass),
        "motor_length": _DVSpec(f"motor stack length; {rotor_rows}", "m", (ng,)),
        "front_spar_thickness": thickness("front-spar"),
        "rear_spar_thickness": thickness("rear-spar"),
        "top_skin_thickness": thickness("top-skin"),
        "bottom_skin_thickness": thickness("bottom-skin"),
    }
    conditions = parts["conditions"]
    index = {c.name: i for i, c in enumerate(conditions)}
    suffix = {f.name: _spec(f).suffix for f in dataclasses.fields(DesignCondition)}
    for name, dv in ConditionLayout(_PartialVehicle(parts)).design_variables.items():
        if name in specs:
            raise VehicleSpecError(
                f"the design variable {name!r} of condition {dv.conditions[0]!r} (its "
                f"design_variable_prefix + a variable of its kind) has the name of a "
                f"vehicle-level design variable; choose another design_variable_prefix"
            )
        initial_from = ""
        if dv.initial_from:
            initial_from = ", ".join(f"conditions[{index[c]}].{dv.initial_from}"
                                     f"{suffix[dv.initial_from]}" for c in dv.conditions)
        specs[name] = _DVSpec(dv.description, dv.units, dv.shape, initial_from, dv.initial)
    return specs


def _dv_values(value, shape: tuple[int, ...], path: str) -> tuple[float, ...]:
    """A number (the same for every entry) or a nested list of ``shape`` -> flat floats."""
    if _is_number(value):
        return (_number(value, _Spec(), path),) * math.prod(shape)
    if isinstance(value, list):
        return tuple(np.ravel(_array(value, shape, _Spec(), path)).tolist())
    what = "a number" if shape == (1,) else f"a number or a nested list of shape {shape}"
    raise VehicleSpecError(f"'{path}' must be {what}, got {_show(value)}")


def _read_design_variables(data, parts: dict) -> dict[str, DesignVariable]:
    specs = _design_variable_specs(parts)
    _check_keys(data, dict.fromkeys(specs, "design-variable table"), "design_variables")
    # In the file's order (the order of the model's design-variable outputs).
    return _ReadOnlyDict(
        (name, _read_design_variable(data[name], specs[name], f"design_variables.{name}"))
        for name in data
    )


def _read_design_variable(data, spec: _DVSpec, path: str) -> DesignVariable:
    if isinstance(data, Mapping) and "initial" in data and spec.initial is not None:
        raise VehicleSpecError(
            f"'{path}.initial' must not be given: the initial value is taken from "
            f"'{spec.initial_from}'"
        )
    unit_choices = ("rad", "deg") if spec.units == "rad" else (spec.units,)
    shape_text = "number" if spec.shape == (1,) else f"number or nested list of shape {spec.shape}"
    allowed = {"units": "one of " + ", ".join(repr(u) for u in unit_choices)}
    if spec.initial is None:
        allowed["initial"] = shape_text
    allowed |= {"lower": shape_text, "upper": shape_text, "ref": "number, > 0"}
    _check_keys(data, allowed, path)

    units = _string(data["units"], _Spec(choices=unit_choices), f"{path}.units")
    scale = math.pi / 180.0 if units == "deg" else 1.0
    values = {
        key: tuple(x * scale for x in _dv_values(data[key], spec.shape, f"{path}.{key}"))
        for key in ("initial", "lower", "upper")
        if key in data
    }
    initial = values.get("initial", spec.initial)
    lower, upper = values["lower"], values["upper"]
    ref = _number(data["ref"], _Spec(units=units, gt=0), f"{path}.ref") * scale

    def entry(key, k):
        if len(initial) == 1:
            return f"'{path}.{key}'"
        return f"'{path}.{key}" + "".join(f"[{i}]" for i in np.unravel_index(k, spec.shape)) + "'"

    source = f"; the initial value is taken from '{spec.initial_from}'" if spec.initial_from else ""
    for k, (x0, lo, up) in enumerate(zip(initial, lower, upper, strict=True)):
        if not lo <= x0 <= up:
            raise VehicleSpecError(
                f"{entry('initial', k)} = {_fmt(x0 / scale)} is out of range: must be in [lower, "
                f"upper] = [{_fmt(lo / scale)}, {_fmt(up / scale)}] ({units}){source}"
            )
        if spec.lower_min is not None and lo < spec.lower_min[0]:
            raise VehicleSpecError(
                f"{entry('lower', k)} = {_fmt(lo)} is out of range: must be >= "
                f"{spec.lower_min[1]} = {_fmt(spec.lower_min[0])} ({units})"
            )
    return DesignVariable(
        initial=initial,
        lower=lower,
        upper=upper,
        units="rad" if units == "deg" else units,
        ref=ref,
        shape=spec.shape,
        description=spec.description,
        initial_from=spec.initial_from,
    )
