"""Gross-mass build-up of the lift-plus-cruise vehicle (paper eqs. 31-33)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_range

#: Order of the entries of the ``mass_breakdown`` output of :class:`GrossWeightComp`.
BREAKDOWN_LABELS = (
    "wing",
    "wing_secondary",
    "fuselage",
    "empennage",
    "booms",
    "landing_gear",
    "battery",
    "motors",
    "rotors",
    "drive_system",
    "power_electronics",
    "power_cables",
    "payload",
    "flight_controls",
    "avionics",
    "electrical",
    "environmental_control",
    "furnishings",
    "systems",
    "other",
)

# (input, breakdown label, description); motor_mass and rotor_mass are vectors (one per rotor).
_SCALAR_MASSES = (
    ("wing_mass", "wing", "wing-box mass (beam, both halves)"),
    ("wing_secondary_mass", "wing_secondary", "wing control surfaces and misc. items (FLOPS)"),
    ("fuselage_mass", "fuselage", "fuselage structural mass (M4 regression)"),
    ("empennage_mass", "empennage", "empennage structural mass (M4 regression)"),
    ("boom_mass", "booms", "total mass of the 8 booms (M4 regression)"),
    ("landing_gear_mass", "landing_gear", "landing-gear mass (NDARC fraction)"),
    ("battery_mass", "battery", "battery mass (design variable)"),
    ("power_electronics_mass", "power_electronics", "inverters of the motors (their ratings)"),
    ("payload_mass", "payload", "payload mass (fixed)"),
    ("flight_controls_mass", "flight_controls", "flight controls (Raymer 15.54)"),
    ("avionics_mass", "avionics", "avionics (Raymer 15.57)"),
    ("electrical_mass", "electrical", "electrical system (Raymer 15.56)"),
    ("environmental_control_mass", "environmental_control", "air conditioning (Raymer 15.58)"),
    ("furnishings_mass", "furnishings", "furnishings (Raymer 15.59)"),
    ("systems_mass", "systems", "further fixed systems of the vehicle file"),
    ("other_mass", "other", "unitemised remainder (calibrated to the initial gross mass)"),
)
_VECTOR_MASSES = (
    ("motor_mass", "motors", "mass of each motor (paper eq. 23)"),
    ("rotor_mass", "rotors", "blade and hub mass of each rotor (NDARC AFDD00)"),
    ("drive_system_mass", "drive_system", "gearbox and rotor shaft of each rotor (NDARC AFDD00)"),
    ("power_cable_mass", "power_cables", "phase cables from the inverters to each motor"),
)
_STRUCTURES = (
    "wing_mass",
    "wing_secondary_mass",
    "fuselage_mass",
    "empennage_mass",
    "boom_mass",
    "landing_gear_mass",
)
_POWERTRAIN = (
    "motor_mass",
    "rotor_mass",
    "drive_system_mass",
    "power_cable_mass",
    "power_electronics_mass",
)
_INDEX = {label: i for i, label in enumerate(BREAKDOWN_LABELS)}


class GrossWeightComp(om.ExplicitComponent):
    """
    Gross mass W0 and its build-up from the component masses.

    The build-up of paper eqs. 31-33 (reference/paper.md Sec. IV;
    docs theory/weights 'Gross mass').

    - W_structures = W_wing + W_wing,secondary + W_fuselage + W_empennage + W_booms
      + W_landing_gear                                                       (eq. 32, extended)
    - W_powertrain = sum_j (W_motor,j + W_rotor,j + W_drive,j + W_cable,j)
      + W_power_electronics                                                (eq. 33, extended)
    - W0 = W_structures + W_battery + W_powertrain + W_payload + W_systems + W_other  (eq. 31)

    with W_systems the sum of the named system items (flight controls, avionics, electrical,
    environmental control, furnishings, further fixed systems). Masses in kg (the paper writes
    "weight"). The model is linear, so every partial is a constant set once in setup.

    Inputs
    ------
    wing_mass, wing_secondary_mass, fuselage_mass, empennage_mass, boom_mass,
    landing_gear_mass : float, (1,), kg
        Structural masses.
    battery_mass : float, (1,), kg
        Battery mass (design variable).
    motor_mass, rotor_mass, drive_system_mass, power_cable_mass : float, (num_motors,), kg
        Mass of each motor (paper eq. 23), of each rotor's blades and hub, of its gearbox and
        rotor shaft and of its phase cable.
    power_electronics_mass, payload_mass, flight_controls_mass, avionics_mass, electrical_mass,
    environmental_control_mass, furnishings_mass, systems_mass, other_mass : float, (1,), kg
        The other items (``other``: the unitemised remainder).

    Outputs
    -------
    structures_mass : float, (1,), kg
        W_structures.
    powertrain_mass : float, (1,), kg
        W_powertrain.
    gross_mass : float, (1,), kg
        W0, the objective.
    mass_breakdown : float, (20,), kg
        The items in the order of :data:`BREAKDOWN_LABELS` (motors, rotors, drive systems and
        cables summed). An output
        so that a recorded case holds the whole breakdown.

    Options
    -------
    num_motors : int
        Number of motors (>= 1). Default 9 (8 lift + 1 pusher).

    Raises
    ------
    om.AnalysisError
        In compute, if a mass is not finite or negative.
    """

    def initialize(self):
        self.options.declare(
            "num_motors", default=9, types=int, lower=1, desc="number of motors (8 lift + 1 pusher)"
        )

    def setup(self):
        nm = self.options["num_motors"]
        nb = len(BREAKDOWN_LABELS)
        for name, _, desc in _SCALAR_MASSES:
            self.add_input(name, 0.0, units="kg", desc=desc)
        for name, _, desc in _VECTOR_MASSES:
            self.add_input(name, np.zeros(nm), units="kg", desc=desc)

        self.add_output("structures_mass", 500.0, units="kg", desc="W_structures (eq. 32)")
        self.add_output("powertrain_mass", 100.0, units="kg", desc="W_powertrain (eq. 33)")
        self.add_output("gross_mass", 3000.0, units="kg", desc="gross mass W0 (eq. 31)")
        self.add_output(
            "mass_breakdown",
            np.zeros(nb),
            units="kg",
            desc="items: " + ", ".join(BREAKDOWN_LABELS),
        )

        for name, label, _ in _SCALAR_MASSES:
            self.declare_partials("gross_mass", name, val=1.0)
            self.declare_partials("mass_breakdown", name, rows=[_INDEX[label]], cols=[0], val=1.0)
        for name, label, _ in _VECTOR_MASSES:
            self.declare_partials("gross_mass", name, val=np.ones((1, nm)))
            self.declare_partials(
                "mass_breakdown",
                name,
                rows=np.full(nm, _INDEX[label]),
                cols=np.arange(nm),
                val=1.0,
            )
        for name in _STRUCTURES:
            self.declare_partials("structures_mass", name, val=1.0)
        for name in _POWERTRAIN:
            size = nm if name != "power_electronics_mass" else 1
            self.declare_partials("powertrain_mass", name, val=np.ones((1, size)))

    def compute(self, inputs, outputs):
        dtype = inputs["motor_mass"].dtype
        breakdown = np.zeros(len(BREAKDOWN_LABELS), dtype=dtype)
        names = [n for n, _, _ in _SCALAR_MASSES + _VECTOR_MASSES]
        for name in names:
            check_range(
                name,
                inputs[name],
                lower=0.0,
                units="kg",
                error=om.AnalysisError,
                where=self.msginfo,
            )
        for name, label, _ in _SCALAR_MASSES + _VECTOR_MASSES:
            breakdown[_INDEX[label]] = np.sum(inputs[name])
        outputs["mass_breakdown"] = breakdown
        outputs["structures_mass"] = sum(np.sum(inputs[n]) for n in _STRUCTURES)
        outputs["powertrain_mass"] = sum(np.sum(inputs[n]) for n in _POWERTRAIN)
        outputs["gross_mass"] = np.sum(breakdown)
