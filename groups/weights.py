"""Vehicle weights: M4 regressions, gross-mass build-up, mass properties and W_other calibration.

- :class:`WeightsGroup` assembles the fuselage, boom and empennage regressions, the gross-mass
  build-up (paper eqs. 31-33) and the mass properties of the whole vehicle (total mass, cg,
  inertia tensor about the cg with the parallel-axis theorem) from a vehicle definition. The
  wing mass (wing-box beam) and the motor masses (paper eq. 23) are inputs, connected by the
  assembly.
- :func:`~lpc_mdo.groups.vehicle.calibrate_other_mass` returns the W_other of the paper's
  calibration: the one that makes the initial design's gross mass the vehicle's
  ``masses.design_gross_mass`` (the paper: 3723.99 kg, Table 8). The model uses it for a vehicle
  with ``masses.other_rule = "calibrated"``; the reference vehicle is itemised (W_other = 0).
- ``mass_breakdown`` and ``format_mass_breakdown`` (reading and printing the breakdown of a
  problem or a recorded case) are plain post-processing, in :mod:`lpc_mdo.api.weights`.
"""

import math

import numpy as np
import openmdao.api as om

from lpc_mdo.components.weights.drive_system import DriveSystemMassComp
from lpc_mdo.components.weights.gross_weight import GrossWeightComp
from lpc_mdo.components.weights.item_placement import (
    NASA_LANDING_GEAR_STATION,
    NASA_SYSTEMS_STATION,
    TailConeShiftComp,
)
from lpc_mdo.components.weights.landing_gear import LandingGearMassComp
from lpc_mdo.components.weights.mass_properties import MassItem, MassPropertiesComp
from lpc_mdo.components.weights.power_electronics import PowerElectronicsMassComp
from lpc_mdo.components.weights.regressions import (
    BoomRegressionComp,
    EmpennageRegressionComp,
    FuselageRegressionComp,
    WingRegressionComp,
    m4_coefficients,
)
from lpc_mdo.components.weights.rotor_mass import RotorMassComp
from lpc_mdo.components.weights.systems import SYSTEM_ITEMS, SystemsMassComp
from lpc_mdo.components.weights.wing_secondary import WingSecondaryMassComp
from lpc_mdo.core.checks import RangeCheck, check_choice
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.condition_layout import condition_layout

#: Raymer system items (:data:`SYSTEM_ITEMS` without the furnishings, which sit with the seats)
#: placed at NASA's systems station, in the equipment bay behind the cabin (docs theory/weights
#: 'Positions').
SYSTEMS_AT_NASA_STATION = ("flight_controls", "avionics", "electrical", "environmental_control")
SYSTEM_CG_INPUTS = tuple(f"{name}_cg" for name in SYSTEMS_AT_NASA_STATION)


def num_motors(vehicle=None):
    """Return the number of motors of a vehicle: one per lift rotor and one for the pusher."""
    return len(_vehicle(vehicle).lift_rotors) + 1


def num_motor_groups(vehicle=None):
    """
    Return the number of motor designs (rotor groups) of a vehicle.

    One per lift pair and the pusher.
    """
    return len(_vehicle(vehicle).lift_rotor_pairs) + 1


def vehicle_mass_items(vehicle=None):
    """
    Return the kinds of bodies of a vehicle's mass properties, as :class:`MassItem`.

    Their inputs are ``{name}_mass``, ``{name}_cg`` and, for parts with an own inertia,
    ``{name}_inertia``. ``motor`` has one row per motor (:func:`num_motors`).
    """
    return (
        MassItem("wing", own_inertia=True),
        MassItem("wing_secondary"),
        MassItem("fuselage", own_inertia=True),
        MassItem("empennage", own_inertia=True),
        MassItem("boom", own_inertia=True),
        MassItem("landing_gear"),
        MassItem("battery"),
        MassItem("motor", count=num_motors(vehicle)),
        MassItem("rotor", count=num_motors(vehicle)),
        MassItem("drive_system", count=num_motors(vehicle)),
        MassItem("power_electronics"),
        MassItem("power_cable", count=num_motors(vehicle)),
        MassItem("payload"),
        *(MassItem(name) for name in SYSTEM_ITEMS),
        MassItem("systems"),
        MassItem("other"),
    )


def max_load_factor(vehicle=None):
    """Return the largest load factor of the vehicle's conditions (the +3g limit: 3.0)."""
    return max(c.load_factor for c in _vehicle(vehicle).conditions)


def speed_of_sound(altitude):
    """Speed of sound (m/s), standard troposphere T = 288.16 - 6.5 h/1000 K (theory/atmosphere)."""
    return math.sqrt(1.4 * 287.0 * (288.16 - 6.5e-3 * altitude))


def rotor_group_blades(vehicle=None):
    """Return the blade count of each rotor group (lift pairs in pair order, then the pusher)."""
    vehicle = _vehicle(vehicle)
    blades = {r.pair: r.num_blades for r in vehicle.lift_rotors}
    return [blades[p] for p in sorted(blades)] + [vehicle.pusher.num_blades]


def rotor_design_speeds(vehicle=None):
    """
    Return the design rotor speed (rpm) of each rotor group for the rotor weight model.

    NDARC's AFDD00 blade and hub weights take the design hover tip speed: the lift pairs use
    the initial lift-rotor speeds of the (first) hover condition and the pusher the initial
    pusher speed of the mission's cruise condition, from their design variables in the vehicle
    file (fixed design values, not the conditions' trim variables; the reference's
    ``hover_lift_rpm`` and ``cruise_pusher_rpm``).
    """
    vehicle = _vehicle(vehicle)
    layout = condition_layout(vehicle)
    hover = next(c.name for c in vehicle.conditions if c.kind == "hover")
    speeds = []
    for condition, variable in (
        (hover, "lift_rpm"),
        (vehicle.mission.cruise_condition, "pusher_rpm"),
    ):
        entry = layout.entries[condition][variable]
        initial = np.asarray(vehicle.design_variables[entry.design_variable].initial_array)
        speeds.append(initial.ravel()[entry.flat_indices])
    return np.concatenate([speeds[0], speeds[1][:1]])


def _vehicle(vehicle):
    return reference_vehicle() if vehicle is None else vehicle


def motor_group_indices(vehicle=None):
    """
    Return, per motor, the rotor group whose motor design it shares.

    Motors are ordered as ``vehicle.lift_rotors`` (8) then the pusher; groups are the rows of
    the per-group design variables (lift pairs 0..3, pusher 4). For the reference vehicle:
    [0, 1, 2, 3, 2, 3, 0, 1, 4]. Use it as ``src_indices`` when a motor model sizes one motor per
    group: ``model.connect('motors.mass', 'weights.motor_mass', src_indices=...)``.
    """
    vehicle = _vehicle(vehicle)
    return [rotor.pair for rotor in vehicle.lift_rotors] + [vehicle.pusher.pair]


def wing_cg_estimate(vehicle=None):
    """
    Return a body-frame wing cg estimate (m): the planform centroid on the wing-box beam axis.

    Trapezoidal half wing: spanwise centroid y_c = (b/6)(1 + 2 lambda)/(1 + lambda), chord there =
    the mean aerodynamic chord; x = x_LE,root - y_c tan(sweep_LE) - beam_axis * MAC,
    z = z_LE,root - y_c tan(dihedral), y = 0. Sections (``planform = "sections"``): the leading
    edge of the MAC of the section planform minus beam_axis * MAC. Used only as the default of the
    ``wing_cg`` input
    until the beam model provides its mass centre.
    """
    vehicle = _vehicle(vehicle)
    wing = vehicle.wing
    if getattr(wing, "planform", "trapezoid") == "sections":
        # The same point of the section planform: the MAC's leading edge (its chord-weighted
        # mean, docs theory/geometry 'Cranked wing planform') minus beam_axis * MAC, y = 0.
        from lpc_mdo.components.geometry.cranked_planform import SectionLayout

        geometry = SectionLayout.from_wing(wing).geometry(
            wing.area, wing.aspect_ratio, np.array(wing.root_leading_edge)
        )
        x_le, _, z_le = geometry["mac_leading_edge"]
        x_beam = vehicle.wing_box.beam_axis * geometry["mean_aerodynamic_chord"]
        return np.array([x_le - x_beam, 0.0, z_le])
    lam = wing.taper_ratio
    y_c = wing.span / 6.0 * (1.0 + 2.0 * lam) / (1.0 + lam)
    x_le, _, z_le = wing.root_leading_edge
    x_beam = vehicle.wing_box.beam_axis * wing.mean_aerodynamic_chord
    return np.array(
        [x_le - y_c * math.tan(wing.sweep) - x_beam, 0.0, z_le - y_c * math.tan(wing.dihedral)]
    )


def placeholder_calibration_inputs(vehicle=None):
    """
    Return the default wing and motor masses of a stand-alone :class:`WeightsGroup`.

    The vehicle model connects the wing-box beam and the motor sizing instead; W_other is
    calibrated with those (:func:`~lpc_mdo.groups.vehicle.calibrate_other_mass`), not with these
    defaults.

    - ``wing_mass`` (kg): the M4 wing regression (docs theory/weights 'M4 regressions', public-code
      alternative to the beam) at the vehicle's initial planform, battery mass and cruise speed;
      283.3605 kg for the
      reference vehicle.
    - ``motor_mass`` (kg, 9 values in :func:`motor_group_indices` order): paper eq. 23,
      m = (pi/2) A_bar B_bar D**2 L/Q_sp with D = L/(L/D), at the initial ``motor_length`` design
      variables and the vehicle's motor constants; 10.681 kg per lift motor (L = 0.10 m) and
      36.050 kg for the pusher motor (L = 0.15 m) for the reference vehicle.
    - ``motor_peak_torque`` (N m, one per rotor group): the peak torque of those motors (the
      motor model's polynomial in the mass, docs theory/motor 'Sizing').
    - ``motor_current_rating`` (A, 9 values): :data:`PLACEHOLDER_CURRENT_RATING` for every motor
      (the vehicle model connects each motor design's MTPA current at its peak torque).

    """
    vehicle = _vehicle(vehicle)
    coeffs = m4_coefficients()["wing"]["mass"]
    regressors = [
        vehicle.wing.area,
        vehicle.wing.aspect_ratio,
        vehicle.fuselage.length,
        vehicle.battery.mass,
        vehicle.condition(vehicle.mission.cruise_condition).speed,
        1.0,
    ]
    wing_mass = float(np.dot(coeffs, regressors))
    motor = vehicle.motor
    length = np.asarray(vehicle.design_variables["motor_length"].initial, dtype=float)
    diameter = length / motor.length_to_diameter
    group_mass = (
        0.5
        * math.pi
        * motor.electric_loading
        * motor.magnetic_loading
        * diameter**2
        * length
        / motor.torque_density
    )
    from lpc_mdo.components.motor.parameters import MotorParameters

    peak = np.polyval(MotorParameters().peak_torque_coefficients, group_mass)
    return {
        "wing_mass": wing_mass,
        "motor_mass": group_mass[motor_group_indices(vehicle)],
        "motor_peak_torque": peak,
        "motor_current_rating": np.full(num_motors(vehicle), PLACEHOLDER_CURRENT_RATING),
    }


#: Current rating of a stand-alone WeightsGroup's motors, A: a round value of the order of the
#: reference motors' peak currents; the vehicle model connects the motor designs' own.
PLACEHOLDER_CURRENT_RATING = 300.0


def _check_wing_model(name, value):
    # 'input': wing mass, cg and inertia from the beam model; 'regression': M4 wing regression.
    check_choice(name, value, ("input", "regression"))


_check_nonnegative = RangeCheck(lower=0.0)
_check_positive = RangeCheck(lower=0.0, lower_open=True)


class WeightsGroup(om.Group):
    """
    Component masses, gross mass (paper eqs. 31-33) and mass properties of the whole vehicle.

    Subsystems (all variables promoted): ``fuselage``, ``booms``, ``empennage``
    (M4 regressions, docs theory/weights 'M4 regressions'), ``tail_cone_items``
    (:class:`~lpc_mdo.components.weights.item_placement.TailConeShiftComp`: the empennage and
    the pusher's rotor, motor and gearbox ride on the tail end, docs theory/geometry 'Fuselage
    zones'), ``wing`` (only with ``wing_model='regression'``), ``power_electronics``
    (:class:`PowerElectronicsMassComp`: inverters and motor cables from the motors' current
    ratings, docs theory/weights 'Power electronics and cables'), ``gross_weight``
    (:class:`GrossWeightComp`) and
    ``mass_properties`` (:class:`MassPropertiesComp`, docs theory/weights 'Mass properties') over
    the bodies of :func:`vehicle_mass_items`. Input defaults come from the vehicle.

    The inputs are promoted.

    Inputs
    ------
    wing_area, wing_aspect_ratio, fuselage_length : float, (1,), m**2 / - / m
        Planform design variables (regressors).
    htail_area, vtail_area : float, (1,), m**2
        Tail areas (regressors of the empennage).
    battery_mass : float, (1,), kg
        Battery mass (design variable).
    cruise_speed : float, (1,), m/s
        Cruise speed, a regressor (default: the vehicle's cruise condition, 57.19 m/s).
    wing_mass : float, (1,), kg
        Wing mass of both halves, from the beam (only with ``wing_model='input'``; default: the
        placeholder of :func:`placeholder_calibration_inputs`).
    wing_cg : float, (3,), m
        Wing cg, body frame (``'input'`` only; default :func:`wing_cg_estimate`).
    wing_inertia : float, (3, 3), kg*m**2
        Wing inertia about ``wing_cg`` (``'input'`` only; default 0, i.e. a point mass, until the
        beam provides it, e.g. a MassPropertiesComp over its element masses).
    motor_mass : float, (9,), kg
        Mass of each motor (paper eq. 23), lift rotors in ``vehicle.lift_rotors`` order, then
        the pusher (see :func:`motor_group_indices`; default: the eq. 23 placeholder).
    motor_reference_cg, rotor_reference_cg : float, (9, 3), m
        Motor and rotor cg at the vehicle's fuselage length; default the rotor hubs (assumption:
        the motor and its gearbox sit at the rotor's hub). The pusher's row moves with the tail
        end (``tail_cone_items``, below); the outputs ``motor_cg`` and ``rotor_cg`` are what
        the mass properties take.
    battery_cg : float, (3,), m
        Default ``vehicle.battery.cg`` (under the cabin floor in the reference vehicle).
    landing_gear_cg : float, (3,), m
        Default NASA's gear station, under the cabin floor
        (:data:`~lpc_mdo.components.weights.item_placement.NASA_LANDING_GEAR_STATION`).
    flight_controls_cg, avionics_cg, electrical_cg, environmental_control_cg : float, (3,), m
        Default NASA's systems station, behind the cabin
        (:data:`~lpc_mdo.components.weights.item_placement.NASA_SYSTEMS_STATION`).
    motor_current_rating : float, (9,), A
        Phase-current amplitude each motor draws at its peak torque (``motor_peak_current`` of
        its design), which rates its inverter and cable (default: the placeholder).
    payload_mass, systems_mass, other_mass : float, (1,), kg
        Fixed masses, default ``vehicle.masses`` (``other_mass``: the option if given).
    power_electronics_cg, payload_cg, systems_cg, other_cg : float, (3,), m
        Their cg (``power_electronics_cg``: the inverters' station, where the motor cables
        start), default ``vehicle.masses``.

    The outputs are promoted.

    Outputs
    -------
    fuselage_mass, boom_mass, empennage_mass : float, (1,), kg
        Regression masses (and ``wing_mass`` with ``wing_model='regression'``).
    fuselage_cg, boom_cg, empennage_cg : float, (3,), m
        Their cg, body frame: the fuselage's from its regression, the booms' at the vehicle's
        fuselage length (they hang on the wing, which keeps its station), the empennage's
        regression cg moved with the tail end (:class:`TailConeShiftComp`).
    motor_cg, rotor_cg : float, (9, 3), m
        Motor and rotor positions; the pusher's moves with the tail end.
    fuselage_inertia, boom_inertia, empennage_inertia : float, (3, 3), kg*m**2
        Their inertia about their own cg.
    power_electronics_mass : float, (1,), kg
        The inverters (PowerElectronicsMassComp; with ``inverter_mass``, ``power_cable_mass``,
        ``power_cable_length`` and ``power_cable_cg`` per motor).
    structures_mass, powertrain_mass : float, (1,), kg
        Eqs. 32 and 33.
    gross_mass : float, (1,), kg
        W0, eq. 31 (the objective).
    mass_breakdown : float, (10,), kg
        Items of eq. 31 in :data:`BREAKDOWN_LABELS` order (see :func:`mass_breakdown`).
    total_mass : float, (1,), kg
        Sum of the body masses (equals ``gross_mass``).
    cg : float, (3,), m
        Vehicle cg, body frame.
    inertia : float, (3, 3), kg*m**2
        Vehicle inertia tensor about ``cg``, body axes (off-diagonals are tensor entries,
        I_xz = -integral(x z dm)).

    Options
    -------
    vehicle : lpc_mdo.vehicle.Vehicle or None
        Vehicle definition; None = the reference vehicle.
    wing_model : str
        ``'input'`` (default; wing mass, cg and inertia are inputs from the beam) or
        ``'regression'`` (the M4 wing regression, public-code alternative).
    regression_mass_factor : float
        Factor (> 0) on the fuselage, boom and empennage regressions. Default 1.0 (paper);
        the public run scripts use 1.3.
    fuselage_cg_x_factor : float
        k_x (> 0) of the fuselage cg (:class:`FuselageRegressionComp`). Default 0.88, as coded.
    other_mass : float or None
        Default of the ``other_mass`` input (>= 0), e.g. from
        :func:`~lpc_mdo.groups.vehicle.calibrate_other_mass`; None = ``vehicle.masses.other`` (the
        uncalibrated initial guess).
    other_cg : sequence of 3 float or None
        Default of the ``other_cg`` input (m); None = ``vehicle.masses.other_cg``.
    """

    def initialize(self):
        self.options.declare(
            "vehicle",
            default=None,
            allow_none=True,
            desc="lpc_mdo.vehicle.Vehicle; None = reference vehicle",
        )
        self.options.declare(
            "wing_model",
            default="input",
            types=str,
            check_valid=_check_wing_model,
            desc="'input' (beam mass as input) or 'regression' (M4 wing)",
        )
        self.options.declare(
            "regression_mass_factor",
            default=1.0,
            types=(int, float),
            check_valid=_check_positive,
            desc="factor on the fuselage, boom and empennage regressions (> 0)",
        )
        self.options.declare(
            "fuselage_cg_x_factor",
            default=m4_coefficients()["fuselage"]["cg_x_factor"],
            types=(int, float),
            check_valid=_check_positive,
            desc="k_x of the fuselage cg (> 0); 0.88 as coded",
        )
        self.options.declare(
            "other_mass",
            default=None,
            types=(int, float),
            allow_none=True,
            check_valid=_check_nonnegative,
            desc="default of the other_mass input, kg (>= 0); None = vehicle",
        )
        self.options.declare(
            "other_cg",
            default=None,
            types=(tuple, list, np.ndarray),
            allow_none=True,
            desc="default of the other_cg input, m; None = vehicle",
        )

    def setup(self):
        vehicle = _vehicle(self.options["vehicle"])
        factor = self.options["regression_mass_factor"]
        wing_model = self.options["wing_model"]

        self.add_subsystem(
            "fuselage",
            FuselageRegressionComp(
                mass_factor=factor, cg_x_factor=self.options["fuselage_cg_x_factor"]
            ),
            promotes=["*"],
        )
        # The wing keeps its station when the fuselage is stretched, so do the booms it carries.
        self.add_subsystem(
            "booms",
            BoomRegressionComp(mass_factor=factor, cg_fuselage_length=vehicle.fuselage.length),
            promotes=["*"],
        )
        self.add_subsystem(
            "empennage",
            EmpennageRegressionComp(mass_factor=factor),
            promotes_inputs=["*"],
            promotes_outputs=[
                "empennage_mass",
                "empennage_inertia",
                ("empennage_cg", "empennage_reference_cg"),
            ],
        )
        if wing_model == "regression":
            self.add_subsystem("wing", WingRegressionComp(), promotes=["*"])
        # Named items (docs theory/weights 'Mass items'): wing secondary structure (FLOPS),
        # landing gear (NDARC fraction), systems (Raymer 15.3.3), rotor blades and hubs (NDARC
        # AFDD00), placed from the geometry.
        self.add_subsystem("wing_secondary", WingSecondaryMassComp(), promotes=["*"])
        self.add_subsystem("landing_gear", LandingGearMassComp(), promotes=["*"])
        cruise = vehicle.condition(vehicle.mission.cruise_condition)
        self.add_subsystem(
            "systems",
            SystemsMassComp(
                ultimate_load_factor=1.5 * max_load_factor(vehicle),
                cruise_mach=cruise.speed / speed_of_sound(cruise.altitude),
            ),
            promotes=["*"],
        )
        # A fuselage stretch is a tail-cone plug (docs theory/geometry 'Fuselage zones'): what
        # the tail end carries moves with it (the empennage; the pusher's rotor, motor and
        # gearbox, the last row of the motors), everything ahead of the plug keeps its station.
        pusher_row = [0] * len(vehicle.lift_rotors) + [1]
        self.add_subsystem(
            "tail_cone_items",
            TailConeShiftComp(
                items={"empennage": 1, "motor": pusher_row, "rotor": pusher_row},
                reference_length=vehicle.fuselage.length,
            ),
            promotes=["*"],
        )
        self.add_subsystem(
            "rotor_mass_model",
            RotorMassComp(num_blades=rotor_group_blades(vehicle)),
            promotes_inputs=["rotor_radius", "blade_chord_cp", "rotor_design_speed"],
            promotes_outputs=[
                ("blade_mass", "rotor_blade_mass"),
                ("hub_mass", "rotor_hub_mass"),
                "rotor_group_mass",
            ],
        )
        self.add_subsystem(
            "drive_system_model",
            DriveSystemMassComp(
                num_groups=len(rotor_group_blades(vehicle)), gear_ratio=vehicle.motor.gear_ratio
            ),
            promotes=["*"],
        )
        motor = vehicle.motor
        self.add_subsystem(
            "power_electronics",
            PowerElectronicsMassComp(
                num_motors=num_motors(vehicle),
                phases=motor.num_phases,
                voltage_limit=motor.voltage_limit,
                inverter_specific_power=motor.inverter_specific_power,
                cable_mass_per_ampere_metre=motor.cable_mass_per_ampere_metre,
            ),
            promotes_inputs=[
                ("peak_current", "motor_current_rating"),
                "motor_cg",
                ("inverter_station", "power_electronics_cg"),
            ],
            promotes_outputs=["*"],
        )
        self.add_subsystem(
            "gross_weight", GrossWeightComp(num_motors=num_motors(vehicle)), promotes=["*"]
        )
        self.add_subsystem(
            "mass_properties",
            MassPropertiesComp(items=list(vehicle_mass_items(vehicle)), item_table=True),
            promotes_inputs=[
                ("wing_secondary_cg", "wing_cg"),
                ("furnishings_cg", "payload_cg"),
                ("drive_system_cg", "motor_cg"),
                "*",
            ],
            promotes_outputs=["*"],
        )
        self.connect("rotor_group_mass", "rotor_mass", src_indices=motor_group_indices(vehicle))
        self.connect(
            "drive_system_group_mass", "drive_system_mass", src_indices=motor_group_indices(vehicle)
        )

        masses = vehicle.masses
        placeholder = placeholder_calibration_inputs(vehicle)
        other = self.options["other_mass"]
        defaults = {
            "wing_area": (vehicle.wing.area, "m**2"),
            "wing_aspect_ratio": (vehicle.wing.aspect_ratio, None),
            "fuselage_length": (vehicle.fuselage.length, "m"),
            "htail_area": (vehicle.horizontal_tail.area, "m**2"),
            "vtail_area": (vehicle.vertical_tail.area, "m**2"),
            "battery_mass": (vehicle.battery.mass, "kg"),
            "cruise_speed": (vehicle.condition(vehicle.mission.cruise_condition).speed, "m/s"),
            "battery_cg": (vehicle.battery.cg, "m"),
            "motor_mass": (placeholder["motor_mass"], "kg"),
            "motor_peak_torque": (placeholder["motor_peak_torque"], "N*m"),
            "motor_reference_cg": (
                [r.hub_position for r in vehicle.lift_rotors] + [vehicle.pusher.hub_position],
                "m",
            ),
            "rotor_reference_cg": (
                [r.hub_position for r in vehicle.lift_rotors] + [vehicle.pusher.hub_position],
                "m",
            ),
            "landing_gear_cg": (NASA_LANDING_GEAR_STATION, "m"),
            **{name: (NASA_SYSTEMS_STATION, "m") for name in SYSTEM_CG_INPUTS},
            "design_gross_mass": (masses.design_gross_mass, "kg"),
            "wing_span": (vehicle.wing.span, "m"),
            "rotor_radius": (vehicle.design_variables["rotor_radius"].initial_array, "m"),
            "blade_chord_cp": (
                np.asarray(vehicle.design_variables["blade_chord_cp"].initial_array).reshape(
                    vehicle.design_variables["blade_chord_cp"].shape
                ),
                "m",
            ),
            "rotor_design_speed": (rotor_design_speeds(vehicle), "rpm"),
            "motor_current_rating": (placeholder["motor_current_rating"], "A"),
            "power_electronics_cg": (masses.power_electronics_cg, "m"),
            "payload_mass": (masses.payload, "kg"),
            "payload_cg": (masses.payload_cg, "m"),
            "systems_mass": (masses.systems, "kg"),
            "systems_cg": (masses.systems_cg, "m"),
            "other_mass": (masses.other if other is None else other, "kg"),
            "other_cg": (
                masses.other_cg if self.options["other_cg"] is None else self.options["other_cg"],
                "m",
            ),
        }
        if wing_model == "input":
            defaults["wing_mass"] = (placeholder["wing_mass"], "kg")
            defaults["wing_cg"] = (wing_cg_estimate(vehicle), "m")
            defaults["wing_inertia"] = (np.zeros((3, 3)), "kg*m**2")
        for name, (value, units) in defaults.items():
            self.set_input_defaults(
                name, np.atleast_1d(np.asarray(value, dtype=float)), units=units
            )


# ------------------------------------------------------------------------------------------------
# Calibration of W_other and the mass breakdown
