"""Battery energy capacity and end-of-mission state of charge (paper eqs. 27-28)."""

import openmdao.api as om

from lpc_mdo.core.checks import check_range


class BatteryComp(om.ExplicitComponent):
    """
    Pack energy capacity from mass and specific energy, and the final state of charge.

    Equations (paper eq. 27-28; docs theory/energy; eq. 28 as corrected there):

    - E_total = e_bat m_bat                        (e_bat in J/kg; 400 Wh/kg = 1.44e6 J/kg)
    - SoC_final = SoC_0 - E_used / E_total         (SoC_0 = 1: (E_total - E_used) / E_total)

    SoC_0 is the state of charge at the start of the mission (the vehicle file's
    ``battery.initial_soc``); E_total is the full-charge capacity, so a pack that starts at
    SoC_0 < 1 holds SoC_0 E_total.

    Inputs
    ------
    battery_mass : float, scalar, kg
        Battery pack mass (a design variable).
    specific_energy : float, scalar, J/kg
        Pack-level specific energy (default 400 Wh/kg = 1.44e6 J/kg; the paper sweeps 250-450
        Wh/kg).
    energy_used : float, scalar, J
        Energy drawn from the pack over the sizing mission (MissionEnergyComp).
    initial_soc : float, scalar, unitless
        State of charge at the start of the mission, in (0, 1] (default 1: fully charged).

    Outputs
    -------
    energy_capacity : float, scalar, J
        Usable pack energy E_total.
    state_of_charge : float, scalar
        End-of-mission state of charge (constrained >= 0.20 in the full problem).
    """

    def setup(self):
        self.add_input("battery_mass", 800.0, units="kg", desc="battery pack mass")
        # Declared in J/kg so that E = e m is in J; set it in any unit, e.g.
        # prob.set_val('specific_energy', 400.0, units='W*h/kg').
        self.add_input(
            "specific_energy",
            400.0 * 3600.0,
            units="J/kg",
            desc="pack-level specific energy (default 400 Wh/kg)",
        )
        self.add_input("energy_used", 0.0, units="J", desc="mission energy drawn from the pack")
        self.add_input(
            "initial_soc",
            1.0,
            units=None,
            desc="state of charge at the start of the mission, in (0, 1]",
        )
        self.add_output("energy_capacity", 1.152e9, units="J", desc="usable pack energy")
        self.add_output("state_of_charge", 1.0, units=None, desc="end-of-mission state of charge")
        self.declare_partials("energy_capacity", ["battery_mass", "specific_energy"])
        self.declare_partials("state_of_charge", ["battery_mass", "specific_energy", "energy_used"])
        self.declare_partials("state_of_charge", "initial_soc", val=1.0)

    def compute(self, inputs, outputs):
        mass = inputs["battery_mass"]
        density = inputs["specific_energy"]
        for name, value, units in (
            ("battery_mass", mass, "kg"),
            ("specific_energy", density, "J/kg"),
        ):
            check_range(
                name,
                value[0],
                lower=0.0,
                lower_open=True,
                units=units,
                error=om.AnalysisError,
                where=self.msginfo,
            )
        soc0 = inputs["initial_soc"]
        check_range(
            "initial_soc",
            soc0[0],
            lower=0.0,
            upper=1.0,
            lower_open=True,
            error=om.AnalysisError,
            where=self.msginfo,
        )
        capacity = mass * density
        outputs["energy_capacity"] = capacity
        outputs["state_of_charge"] = soc0 - inputs["energy_used"] / capacity

    def compute_partials(self, inputs, partials):
        mass = inputs["battery_mass"]
        density = inputs["specific_energy"]
        used = inputs["energy_used"]
        capacity = mass * density
        partials["energy_capacity", "battery_mass"] = density
        partials["energy_capacity", "specific_energy"] = mass
        dsoc_dcap = used / capacity**2
        partials["state_of_charge", "battery_mass"] = dsoc_dcap * density
        partials["state_of_charge", "specific_energy"] = dsoc_dcap * mass
        partials["state_of_charge", "energy_used"] = -1.0 / capacity
