"""The full lift-plus-cruise model: vehicle, the vehicle file's design conditions, mission energy.

The physics only: the optimization problem (design variables, constraints, objective) is
declared outside, by :mod:`lpc_mdo.problems`, from the same condition contracts
(:mod:`lpc_mdo.vehicle.condition_contract`) that wire this model.
"""

import functools

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.airfoil import zero_lift_angle
from lpc_mdo.components.atmosphere import standard_atmosphere
from lpc_mdo.components.energy.battery import BatteryComp
from lpc_mdo.components.energy.flight_time import FlightTimeComp
from lpc_mdo.components.energy.mission_energy import MissionEnergyComp
from lpc_mdo.components.gather_across_conditions import GatherComp
from lpc_mdo.components.ks import KSComp
from lpc_mdo.groups.condition_kinds import condition_group
from lpc_mdo.groups.footprint import FootprintGroup, footprint_chord_inputs
from lpc_mdo.groups.vehicle import VehicleGroup
from lpc_mdo.vehicle import VehicleSpecError, reference_vehicle
from lpc_mdo.vehicle.condition_contract import condition_kind
from lpc_mdo.vehicle.condition_layout import condition_layout
from lpc_mdo.vehicle.footprint_path import (
    departure_conditions,
    departure_points,
    footprint_geometry,
)
from lpc_mdo.vehicle.parts import BROADBAND_MODELS

# Torque margin reported for a motor that no included condition loads (a model built with a
# single OEI case); large, so it never binds.
UNUSED_MOTOR_MARGIN = 10.0
#: The motor margins aggregated over the conditions by KS, one per motor (output
#: ``{prefix}_motor_{quantity}``), and the name of their aggregate (``{prefix}_{name}``): the
#: torque margin (paper Table 6) and the voltage margin of the MTPA point (docs theory/motor
#: 'Winding for the bus').
MOTOR_MARGIN_AGGREGATES = {"torque_margin": "margin", "voltage_margin": "voltage_margin"}


def openmdao_units(units):
    """OpenMDAO units of a vehicle-file design variable ('unitless' is None)."""
    return None if units == "unitless" else units


class LPCGroup(om.Group):
    """
    System-level model of the lift-plus-cruise vehicle (paper Fig. 11).

    ``design_variables`` (an IndepVarComp) holds the design-variable arrays of the vehicle file
    (the reference: 33 arrays, 181 values: the paper's 161, the 5 motor windings, the 10
    roll/yaw lift-rotor speed differentials and the 5 pitch angles of the transition points);
    ``vehicle`` (VehicleGroup) turns them into geometry and mass properties; each design
    condition of the vehicle file is a subsystem of its name, built by the class of its kind
    (:mod:`lpc_mdo.groups.condition_kinds`), which also declares what it reads from the vehicle,
    which design-variable entries drive it, its motors and its power; ``mission`` and
    ``battery`` give the final state of charge (each condition's energy weighted by its
    ``energy_weight``); ``lift_margin``/``pusher_margin`` aggregate the motor torque margins
    over the conditions by KS (paper eq. 7), ``lift_voltage_margin``/ ``pusher_voltage_margin``
    the motor voltage margins likewise.

    The optimization problem is not part of the model: :func:`lpc_mdo.problems.declare_problem`
    declares it (paper Table 6).

    Options
    -------
    vehicle : Vehicle or None
        None: the reference vehicle.
    conditions : list of str or None
        The design conditions to include, by name (None: all of the vehicle's). Subproblems
        and single-condition studies use a subset; the mission energy then counts only those.
    rotor_polar : Polar or None
        Blade-section polar of all rotors (None: the lift rotors use the table of their
        ``lift_rotors[i].airfoil``, which must be the same for all, and the pusher that of
        ``pusher.airfoil``).
    wing_zero_lift_angle : float or None
        Sectional zero-lift angle of the wing airfoil, rad (None: from its table).
    broadband_model : str or None
        Broadband noise model of the hover noise constraint: 'gill_lee' (the paper's eq. 22) or
        'bpm' (blade-section Brooks-Pope-Marcolini self-noise, docs theory/acoustics 'BPM
        broadband model'; not with a noise footprint). None (default): the vehicle's
        ``constraints.noise_broadband_model``, else 'gill_lee'.
    footprint_levels : bool
        Build each departure condition's footprint levels even where the model does not have
        the whole departure, and so no exposure (a single condition's trim problem, whose
        solve then meets the levels' range as the whole model's run will). Default False.
    ks_rho : float
        KS aggregation parameter of the torque and voltage margins.
    structural_coupling : str
        Aerostructural coupling of the structural conditions: 'one_way' or 'two_way'.
    structural_ks_rho : float or None
        KS parameter of the structural conditions' aggregates (None: no aggregates).
    """

    def initialize(self):
        self.options.declare(
            "vehicle",
            default=None,
            allow_none=True,
            desc="lpc_mdo.vehicle.Vehicle; None = reference vehicle",
        )
        self.options.declare(
            "conditions",
            default=None,
            types=(list, tuple),
            allow_none=True,
            desc="names of the design conditions to include (None: all)",
        )
        self.options.declare(
            "rotor_polar",
            default=None,
            allow_none=True,
            desc="blade-section polar (None: from the rotor airfoil)",
        )
        self.options.declare(
            "wing_zero_lift_angle",
            default=None,
            allow_none=True,
            types=float,
            desc="wing sectional zero-lift angle, rad",
        )
        self.options.declare(
            "broadband_model",
            default=None,
            values=(None, *BROADBAND_MODELS),
            allow_none=True,
            desc="broadband noise model of the hover noise constraint: 'gill_lee' (the paper's "
            "eq. 22), 'bpm' (blade-section BPM self-noise) or None (the vehicle's "
            "constraints.noise_broadband_model, default 'gill_lee')",
        )
        self.options.declare(
            "footprint_levels",
            default=False,
            types=bool,
            desc="each departure condition's footprint levels even where the model lacks the "
            "rest of the departure (no exposure then): a trim then meets the levels' range",
        )
        self.options.declare(
            "ks_rho",
            default=50.0,
            types=float,
            desc="KS parameter of the torque- and voltage-margin aggregates",
        )
        self.options.declare(
            "structural_coupling",
            default="one_way",
            values=("one_way", "two_way"),
            desc="aerostructural coupling of the structural conditions",
        )
        self.options.declare(
            "structural_ks_rho",
            default=None,
            types=(int, float),
            allow_none=True,
            desc="KS parameter of the structural aggregates (None: none)",
        )

    def setup(self):
        vehicle = self.options["vehicle"] or reference_vehicle()
        self.vehicle_spec = vehicle
        self.conditions = included_conditions(
            vehicle, self.options["conditions"], where=self.msginfo
        )
        polar, pusher_polar, alpha0 = _airfoil_models(
            vehicle, self.options["rotor_polar"], self.options["wing_zero_lift_angle"]
        )

        dvs = self.add_subsystem("design_variables", om.IndepVarComp(), promotes=["*"])
        for name, dv in vehicle.design_variables.items():
            dvs.add_output(
                name,
                np.asarray(dv.initial_array).reshape(dv.shape),
                units=openmdao_units(dv.units),
                desc=dv.description,
            )
        self.add_subsystem("vehicle", VehicleGroup(vehicle=vehicle), promotes=["*"])
        # W0 - W_dg: zero where the design gross mass is closed (lpc_mdo.problems constrains it
        # wherever design_gross_mass is a design variable).
        self.add_subsystem(
            "design_gross_mass_closure",
            om.ExecComp(
                "design_gross_mass_closure = gross_mass - design_gross_mass",
                design_gross_mass_closure={"units": "kg"},
                gross_mass={"units": "kg"},
                design_gross_mass={"units": "kg"},
                has_diag_partials=True,
            ),
            promotes=["*"],
        )

        self.footprint_conditions = footprint_conditions(vehicle, self.conditions)
        # The conditions whose footprint levels the model computes: those the exposure hears,
        # or with footprint_levels every departure condition it has.
        heard = set(self.footprint_conditions)
        if self.options["footprint_levels"] and vehicle.noise_footprint is not None:
            heard |= {c.name for c in departure_conditions(vehicle)}
        self.heard_conditions = [c.name for c in self.conditions if c.name in heard]
        broadband = self.options["broadband_model"] or (
            vehicle.constraints.noise_broadband_model or "gill_lee"
        )
        if broadband == "bpm" and self.footprint_conditions:
            raise ValueError(
                f"{self.msginfo}: broadband_model = 'bpm' does not serve the noise footprint "
                "(it hears the rotors through their thrust and torque alone): use 'gill_lee'"
            )
        for condition in self.conditions:
            cls = condition_group(condition.kind)
            kwargs = {
                "vehicle": vehicle,
                "condition": condition.name,
                "rotor_polar": polar,
                "pusher_polar": pusher_polar,
                "footprint": condition.name in self.heard_conditions,
                "broadband_model": broadband,
            }
            if _declares(cls, "wing_zero_lift_angle"):
                kwargs["wing_zero_lift_angle"] = alpha0
            if _declares(cls, "ks_rho"):
                kwargs["ks_rho"] = self.options["structural_ks_rho"]
            if _declares(cls, "coupling"):
                kwargs["coupling"] = self.options["structural_coupling"]
            self.add_subsystem(condition.name, cls(**kwargs))
        self.condition_names = [c.name for c in self.conditions]
        if self.footprint_conditions:
            self.add_subsystem("footprint", FootprintGroup(vehicle=vehicle), promotes_outputs=["*"])
        self._add_mission(vehicle)

    def configure(self):
        vehicle = self.vehicle_spec
        layout = condition_layout(vehicle)
        for condition in self.conditions:
            name = condition.name
            cls = condition_kind(condition.kind)
            for source, target, src_indices in cls.vehicle_inputs(vehicle, condition):
                self.connect(source, f"{name}.{target}", src_indices=src_indices)
            for entry in layout.entries[name].values():
                v = entry.variable
                # A tuple: one fancy index of the flattened source, shaped like the target.
                self.connect(
                    entry.design_variable,
                    f"{name}.{v.name}",
                    src_indices=(entry.flat_indices.reshape(v.target_shape),),
                    flat_src_indices=True,
                )
        for name in self.heard_conditions:
            nrad = self._get_subsystem(name).options["num_radial"]
            flying = vehicle.condition(name).kind == "transition"
            for source, target, src_indices in footprint_chord_inputs(vehicle, flying, nrad):
                self.connect(
                    source, f"{name}.{target}", src_indices=src_indices, flat_src_indices=True
                )
            if name in self.footprint_conditions:
                self.connect(f"{name}.footprint_spl_a", f"footprint.exposure.{name}")
        for i, condition in enumerate(self._powered):
            power = condition_kind(condition.kind).power_output
            self.connect(f"{condition.name}.{power}", f"power_mux.electrical_power_{i}")
        for prefix, members in self._motor_sets.items():
            for condition, _ in members:
                for quantity, gather in MOTOR_MARGIN_AGGREGATES.items():
                    self.connect(
                        f"{condition.name}.{prefix}_motor_{quantity}",
                        f"{prefix}_{gather}_gather.{condition.name}",
                    )
        super().configure()

    # ------------------------------------------------------------------ mission and margins

    def _add_flight_time(self, vehicle, powered, free, reserve):
        """Add the times of the conditions whose optimized speeds fly stated distances."""
        mission = vehicle.mission
        fixed = [
            c.duration - (c.level_distance / c.speed if c.optimizes_speed else 0.0) for c in powered
        ]
        self.add_subsystem(
            "flight_time",
            FlightTimeComp(
                fixed_time=fixed,
                distance=[c.level_distance if c.optimizes_speed else 0.0 for c in powered],
                speed_conditions=free,
                reserve_time=None if reserve is None else mission.reserve_time,
                reserve_distance=mission.reserve_distance,
                reserve_condition=mission.reserve_condition,
            ),
        )
        self.connect("flight_time.duration", "mission.duration")
        if reserve is not None:
            self.connect("flight_time.reserve_duration", "mission.reserve_duration")
        entries = condition_layout(vehicle).entries
        for name in free:
            entry = entries[name]["speed"]
            self.connect(
                entry.design_variable,
                f"flight_time.{name}_speed",
                src_indices=entry.flat_indices,
                flat_src_indices=True,
            )

    def _add_mission(self, vehicle):
        powered = [c for c in self.conditions if condition_kind(c.kind).power_output]
        self._powered = powered
        if powered:
            mux = self.add_subsystem("power_mux", om.MuxComp(vec_size=len(powered)))
            mux.add_var("electrical_power", shape=(1,), axis=0, units="W")
            names = [c.name for c in powered]
            mission = vehicle.mission
            reserve = (
                names.index(mission.reserve_condition)
                if mission.reserve_condition in names
                else None
            )
            free = {c.name: i for i, c in enumerate(powered) if c.optimizes_speed}
            if free:  # ahead of the mission energy, which takes its times
                self._add_flight_time(vehicle, powered, free, reserve)
            self.add_subsystem(
                "mission",
                MissionEnergyComp(
                    energy_multipliers=[c.energy_weight for c in powered], reserve_index=reserve
                ),
                promotes_outputs=["energy_used", "segment_energy"],
            )
            self.connect("power_mux.electrical_power", "mission.electrical_power")
            if not free:
                self.set_input_defaults(
                    "mission.duration", np.array([c.duration for c in powered]), units="s"
                )
                if reserve is not None:
                    self.set_input_defaults(
                        "mission.reserve_duration", mission.reserve_time, units="s"
                    )
        else:
            self.add_subsystem(
                "mission",
                om.IndepVarComp("energy_used", 0.0, units="J"),
                promotes_outputs=["energy_used"],
            )
        self.add_subsystem(
            "battery",
            BatteryComp(),
            promotes_inputs=["battery_mass", "energy_used"],
            promotes_outputs=["state_of_charge", "energy_capacity"],
        )
        self.set_input_defaults(
            "battery.specific_energy", vehicle.battery.energy_density, units="J/kg"
        )
        self.set_input_defaults("battery.initial_soc", vehicle.battery.initial_soc)

        # Motor sets: prefix -> [(condition, motor indices)], in condition order.
        self._motor_sets = {}
        for c in self.conditions:
            for prefix, motors in condition_kind(c.kind).motor_sets(vehicle, c).items():
                self._motor_sets.setdefault(prefix, []).append((c, list(motors)))
        sizes = {"lift": len(vehicle.lift_rotors), "pusher": 1}
        for prefix, members in self._motor_sets.items():
            for quantity, name in MOTOR_MARGIN_AGGREGATES.items():
                self._add_margin_aggregate(prefix, members, sizes[prefix], quantity, name)

    def _add_margin_aggregate(self, prefix, members, num_motors, quantity, name):
        """Add the KS over the conditions of each motor's ``quantity`` margin (paper eq. 7)."""
        self.add_subsystem(
            f"{prefix}_{name}_gather",
            GatherComp(
                name=quantity,
                sources=[c.name for c, _ in members],
                items=[motors for _, motors in members],
                num_items=num_motors,
                absent_value=UNUSED_MOTOR_MARGIN,
            ),
        )
        self.add_subsystem(
            f"{prefix}_{name}",
            KSComp(
                vec_size=num_motors, width=len(members), rho=self.options["ks_rho"], lower_flag=True
            ),
            promotes_outputs=[("KS", f"{prefix}_motor_{quantity}")],
        )
        self.connect(f"{prefix}_{name}_gather.{quantity}", f"{prefix}_{name}.g")


def footprint_conditions(vehicle, conditions):
    """
    Return the departure conditions the noise footprint hears, name -> their points.

    Empty unless the vehicle has a ``noise_footprint`` and ``conditions`` include every
    condition of its departure (lpc_mdo.vehicle.footprint_path): a model of a subset of the
    conditions (a subproblem) has no footprint.
    """
    if vehicle.noise_footprint is None:
        return {}
    names = {c.name for c in conditions}
    if not all(c.name in names for c in departure_conditions(vehicle)):
        return {}
    return departure_points(*footprint_geometry(vehicle))


@functools.cache
def _declared_options(cls):
    """Return the options condition class ``cls`` declares (from a throw-away instance)."""
    return frozenset(cls().options)


def _declares(cls, option):
    """Whether condition class ``cls`` declares option ``option``."""
    return option in _declared_options(cls)


def included_conditions(vehicle, names=None, where="LPCGroup"):
    """
    Return the vehicle's conditions to include, in vehicle-file order.

    Parameters
    ----------
    vehicle : Vehicle
    names : list of str or None
        Condition names (None: all).
    where : str
        Prefix of the error message.

    Raises
    ------
    ValueError
        When a name is not a condition of the vehicle, or the list is empty.
    """
    all_names = [c.name for c in vehicle.conditions]
    if names is None:
        return list(vehicle.conditions)
    unknown = [c for c in names if c not in all_names]
    if unknown or not names:
        raise ValueError(
            f"{where}: conditions = {list(names)}; each must be one of the "
            f"vehicle's conditions {all_names} (at least one)."
        )
    return [c for c in vehicle.conditions if c.name in names]


def _airfoil_models(vehicle, rotor_polar, wing_zero_lift_angle):
    """
    Return the lift-rotor polar, the pusher polar and the wing's sectional zero-lift angle.

    A given ``rotor_polar`` serves every rotor; otherwise the lift rotors take the table of their
    airfoil and the pusher that of its own. One lift-rotor polar serves all eight lift rotors
    (one BEM/Pitt-Peters call per condition), so lift rotors with different airfoils are a
    VehicleSpecError naming the first that differs from ``lift_rotors[0]``.
    """
    if rotor_polar is not None and wing_zero_lift_angle is not None:
        return rotor_polar, rotor_polar, wing_zero_lift_angle
    from lpc_mdo.components.aero.airfoil import get_polar

    if rotor_polar is None:
        first = vehicle.lift_rotors[0].airfoil
        for i, rotor in enumerate(vehicle.lift_rotors):
            if rotor.airfoil != first:
                raise VehicleSpecError(
                    f"'lift_rotors[{i}].airfoil' = {rotor.airfoil!r} differs from "
                    f"'lift_rotors[0].airfoil' = {first!r}; allowed: one airfoil for all lift "
                    f"rotors (the model evaluates them with one polar), or pass LPCGroup option "
                    f"'rotor_polar'"
                )
        rotor_polar = get_polar(first)
        pusher_polar = get_polar(vehicle.pusher.airfoil)
    else:
        pusher_polar = rotor_polar
    if wing_zero_lift_angle is None:
        # At the design cruise condition's Reynolds and Mach numbers on the wing MAC.
        cruise = vehicle.condition(vehicle.mission.cruise_condition)
        _, _, rho, a, mu = standard_atmosphere(
            cruise.altitude, temperature_offset=vehicle.mission.isa_offset
        )
        reynolds = rho * cruise.speed * vehicle.wing.mean_aerodynamic_chord / mu
        wing_zero_lift_angle = zero_lift_angle(
            get_polar(vehicle.wing.airfoil), reynolds, cruise.speed / a
        )
    return rotor_polar, pusher_polar, wing_zero_lift_angle
