"""Gross-mass build-up of the lift-plus-cruise vehicle (paper eqs. 31-33)."""

import numpy as np
import openmdao.api as om

from lpc_mdo.checks import check_range

#: Order of the entries of the ``mass_breakdown`` output of :class:`GrossWeightComp`.
BREAKDOWN_LABELS = (
    "wing",
    "fuselage",
    "empennage",
    "booms",
    "battery",
    "motors",
    "power_electronics",
    "payload",
    "systems",
    "other",
)

# (input, breakdown index, description); motor_mass is added separately (vector).
_SCALAR_MASSES = (
    ("wing_mass", 0, "wing structural mass (wing-box beam, both halves)"),
    ("fuselage_mass", 1, "fuselage structural mass (M4 regression)"),
    ("empennage_mass", 2, "empennage structural mass (M4 regression)"),
    ("boom_mass", 3, "total mass of the 8 booms (M4 regression)"),
    ("battery_mass", 4, "battery mass (design variable)"),
    ("power_electronics_mass", 6, "power electronics mass (paper: about 90 lb)"),
    ("payload_mass", 7, "payload mass (fixed)"),
    ("systems_mass", 8, "systems mass (fixed)"),
    ("other_mass", 9, "other mass (fixed, calibrated to the initial gross mass)"),
)
_STRUCTURES = ("wing_mass", "fuselage_mass", "empennage_mass", "boom_mass")
_MOTORS = BREAKDOWN_LABELS.index("motors")


class GrossWeightComp(om.ExplicitComponent):
    """
    Gross mass W0 and its build-up from the component masses.

    The build-up of paper eqs. 31-33 (reference/paper.md Sec. IV;
    docs theory/weights 'Gross mass').

    - W_structures = W_wing + W_fuselage + W_empennage + W_booms             (eq. 32)
    - W_powertrain = sum_j W_motor,j + W_power_electronics                  (eq. 33)
    - W0 = W_structures + W_battery + W_powertrain + W_payload + W_systems + W_other  (eq. 31)

    Masses in kg (the paper writes "weight"). The model is linear, so every partial is a
    constant set once in setup.

    Inputs
    ------
    wing_mass, fuselage_mass, empennage_mass, boom_mass : float, (1,), kg
        Structural masses (wing from the beam; the others from the M4 regressions).
    battery_mass : float, (1,), kg
        Battery mass (design variable).
    motor_mass : float, (num_motors,), kg
        Mass of each motor (paper eq. 23).
    power_electronics_mass, payload_mass, systems_mass, other_mass : float, (1,), kg
        Fixed masses.

    Outputs
    -------
    structures_mass : float, (1,), kg
        W_structures.
    powertrain_mass : float, (1,), kg
        W_powertrain.
    gross_mass : float, (1,), kg
        W0, the objective.
    mass_breakdown : float, (10,), kg
        The items of eq. 31 in the order of :data:`BREAKDOWN_LABELS`: wing, fuselage, empennage,
        booms, battery, motors (sum), power electronics, payload, systems, other. An output so
        that a recorded case holds the whole breakdown.

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
        self.add_input("motor_mass", np.zeros(nm), units="kg", desc="mass of each motor")

        self.add_output("structures_mass", 500.0, units="kg", ref=1e2, desc="W_structures (eq. 32)")
        self.add_output("powertrain_mass", 100.0, units="kg", ref=1e2, desc="W_powertrain (eq. 33)")
        self.add_output("gross_mass", 3000.0, units="kg", ref=1e3, desc="gross mass W0 (eq. 31)")
        self.add_output(
            "mass_breakdown",
            np.zeros(nb),
            units="kg",
            ref=1e2,
            desc="items of eq. 31: " + ", ".join(BREAKDOWN_LABELS),
        )

        for name, index, _ in _SCALAR_MASSES:
            self.declare_partials("gross_mass", name, val=1.0)
            self.declare_partials("mass_breakdown", name, rows=[index], cols=[0], val=1.0)
        for name in _STRUCTURES:
            self.declare_partials("structures_mass", name, val=1.0)
        self.declare_partials("powertrain_mass", ["motor_mass", "power_electronics_mass"], val=1.0)
        self.declare_partials("gross_mass", "motor_mass", val=np.ones((1, nm)))
        self.declare_partials(
            "mass_breakdown", "motor_mass", rows=np.full(nm, _MOTORS), cols=np.arange(nm), val=1.0
        )

    def compute(self, inputs, outputs):
        breakdown = np.zeros(len(BREAKDOWN_LABELS), dtype=inputs["motor_mass"].dtype)
        for name, index, _ in _SCALAR_MASSES:
            breakdown[index] = inputs[name][0]
        breakdown[_MOTORS] = np.sum(inputs["motor_mass"])
        for name in [n for n, _, _ in _SCALAR_MASSES] + ["motor_mass"]:
            check_range(
                name,
                inputs[name],
                lower=0.0,
                units="kg",
                error=om.AnalysisError,
                where=self.msginfo,
            )
        outputs["mass_breakdown"] = breakdown
        outputs["structures_mass"] = np.sum(breakdown[:4])
        outputs["powertrain_mass"] = breakdown[_MOTORS] + inputs["power_electronics_mass"]
        outputs["gross_mass"] = np.sum(breakdown)
