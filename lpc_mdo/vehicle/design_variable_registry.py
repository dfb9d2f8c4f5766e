"""The registry of the vehicle-level design variables: one entry per variable, with its metadata.

Every place that needs the list of vehicle-level design variables derives it from
:data:`VEHICLE_DESIGN_VARIABLES`: the vehicle file's ``[design_variables]`` tables are checked
against it (:mod:`lpc_mdo.vehicle.design_variables`), the vehicle group declares its inputs from it
(:class:`~lpc_mdo.groups.vehicle.VehicleGroup`), and the baseline problem's set S (paper eqs.
8-9) is its ``baseline`` entries (:data:`BASELINE_SET`). The design variables that conditions own
(rotor speeds, pitch, elevator) are declared by their kinds
(:meth:`~lpc_mdo.vehicle.condition_contract.ConditionKind.variables`) and named by the condition
layout (:mod:`lpc_mdo.vehicle.condition_layout`). The pattern follows Aviary's variable metadata
registry: one declaration, read everywhere.
"""

import dataclasses

import numpy as np

__all__ = ["BASELINE_SET", "VEHICLE_DESIGN_VARIABLES", "VehicleDesignVariable"]

#: Shape rules: what each dimension of a design variable counts.
SHAPES = ("scalar", "rotor_groups", "rotor_groups_by_control_points", "bays")


@dataclasses.dataclass(frozen=True)
class VehicleDesignVariable:
    """
    Metadata of one vehicle-level design variable.

    Attributes
    ----------
    name : str
        Name in the vehicle file's ``[design_variables]``, the model's input and output.
    units : str
        SI units of its values (``"unitless"`` for none); angles in rad (a vehicle file may give
        ``"deg"``).
    shape : str
        Shape rule, one of :data:`SHAPES`: ``scalar`` (1,); ``rotor_groups`` one row per rotor
        group (the lift-rotor pairs, then the pusher); ``rotor_groups_by_control_points`` (rotor
        groups, 4): the blade's cubic Bezier control points, root to tip; ``bays`` one entry per
        wing-box bay, root to tip.
    description : str
        What it is.
    initial_from : str
        The vehicle field whose value is the initial design (``wing.area``); ``rotors.X`` takes
        field ``X`` of one lift rotor per pair and of the pusher. Empty: the vehicle file's table
        gives the initial value.
    min_gauge : bool
        Whether the lower bound may not go below the material's minimum gauge
        (``material.min_gauge``).
    limits : tuple of (float or None, float or None, str) or None
        The range its bounds must lie in, with the reason, for a design variable without an
        ``initial_from`` field (whose bounds lie in that field's range): what can be built,
        wide enough for any vehicle of the class and narrow enough to catch a table written in
        another unit (mm for m, mA for A).
    baseline : bool
        Whether it is in the set S of the baseline problem (paper eqs. 8-9): the sizing variables
        the initial specification gives.
    """

    name: str
    units: str
    shape: str
    description: str
    initial_from: str = ""
    min_gauge: bool = False
    baseline: bool = True
    limits: tuple | None = None

    def __post_init__(self):
        if self.shape not in SHAPES:
            raise ValueError(f"'shape' = {self.shape!r} is not allowed: must be one of {SHAPES}")

    def shape_of(self, num_rotor_groups, num_bays):
        """Return the array shape for a vehicle of ``num_rotor_groups`` groups and ``num_bays``."""
        return {
            "scalar": (1,),
            "rotor_groups": (num_rotor_groups,),
            "rotor_groups_by_control_points": (num_rotor_groups, 4),
            "bays": (num_bays,),
        }[self.shape]

    def initial_of(self, parts, rotor_groups):
        """
        Return the initial values (flat tuple) from the vehicle's parts, or None.

        Parameters
        ----------
        parts : dict
            The built parts of the vehicle file (table name -> part).
        rotor_groups : sequence
            One rotor per rotor group (a lift rotor per pair, then the pusher).
        """
        if not self.initial_from:
            return None
        table, _, field = self.initial_from.partition(".")
        if table == "rotors":
            values = [getattr(r, field) for r in rotor_groups]
        else:
            values = [getattr(parts[table], field)]
        return tuple(float(x) for x in np.ravel(values))

    @property
    def initial_key(self):
        """The vehicle-file key the initial value comes from, for messages ("" for none)."""
        if self.initial_from.startswith("rotors."):
            field = self.initial_from.partition(".")[2]
            key = f"{field}_deg" if self.units == "rad" else field
            return f"lift_rotors[i].{key} (one rotor per pair) and pusher.{key}"
        return self.initial_from


_ROTOR_ROWS = "rows: lift pairs, then the pusher"

#: The vehicle-level design variables (paper Table 6), in the reference vehicle file's order.
VEHICLE_DESIGN_VARIABLES = (
    VehicleDesignVariable(
        "wing_aspect_ratio", "unitless", "scalar", "wing aspect ratio", "wing.aspect_ratio"
    ),
    VehicleDesignVariable("wing_area", "m**2", "scalar", "wing reference area", "wing.area"),
    VehicleDesignVariable(
        "htail_aspect_ratio",
        "unitless",
        "scalar",
        "h-tail aspect ratio",
        "horizontal_tail.aspect_ratio",
    ),
    VehicleDesignVariable(
        "htail_area", "m**2", "scalar", "h-tail reference area", "horizontal_tail.area"
    ),
    VehicleDesignVariable("fuselage_length", "m", "scalar", "fuselage length", "fuselage.length"),
    VehicleDesignVariable(
        "rotor_radius", "m", "rotor_groups", f"rotor radius; {_ROTOR_ROWS}", "rotors.radius"
    ),
    VehicleDesignVariable(
        "blade_chord_cp",
        "m",
        "rotor_groups_by_control_points",
        f"blade chord control points, root to tip; {_ROTOR_ROWS}",
        "rotors.chord_cp",
    ),
    VehicleDesignVariable(
        "blade_twist_cp",
        "rad",
        "rotor_groups_by_control_points",
        f"blade twist control points, root to tip; {_ROTOR_ROWS}",
        "rotors.twist_cp",
    ),
    VehicleDesignVariable("battery_mass", "kg", "scalar", "battery mass", "battery.mass"),
    # Not in the paper: the W_dg of the regressions that scale with the gross mass (landing
    # gear, wing secondary structure, systems), closed on the gross mass by an equality
    # constraint wherever it is a design variable (docs theory/weights 'Gross mass'); not a
    # sizing variable of the baseline set S.
    VehicleDesignVariable(
        "design_gross_mass",
        "kg",
        "scalar",
        "design gross mass W_dg of the weight regressions",
        "masses.design_gross_mass",
        baseline=False,
    ),
    # 0.01-1 m: a stack of 1 cm to 1 m, beyond the aircraft PMSMs of the class either way
    # (the reference's 0.06-0.3 m); the motor model itself raises an AnalysisError below its
    # smallest stack (about 0.056 m, docs theory/motor 'Sizing').
    VehicleDesignVariable(
        "motor_length",
        "m",
        "rotor_groups",
        f"motor stack length; {_ROTOR_ROWS}",
        limits=(0.01, 1.0, "a motor stack of 1 cm to 1 m"),
    ),
    # Not in the paper (it fixes the winding at 120 A); a sizing variable with an initial value
    # of the vehicle file, so in the baseline set S like the others.
    VehicleDesignVariable(
        "motor_rated_current",
        "A",
        "rotor_groups",
        f"rated phase current of the motor winding, which sets its turns per phase; {_ROTOR_ROWS}",
        limits=(1.0, 5000.0, "the range of motor.rated_current"),
    ),
    *(
        VehicleDesignVariable(
            f"{part}_thickness",
            "m",
            "bays",
            f"{part.replace('_', '-')} thickness per wing-box bay, root to tip",
            min_gauge=True,
            # At most 0.1 m: twice the reference's upper bound, thicker than a light
            # aircraft's wing-box wall; catches a table in mm.
            limits=(None, 0.1, "a wing-box wall of at most 0.1 m"),
        )
        for part in ("front_spar", "rear_spar", "top_skin", "bottom_skin")
    ),
)

#: The set S of the baseline problem (paper eqs. 8-9): the sizing variables the initial
#: specification gives (beta = 1); the operating variables (rotor speeds, pitch, elevator) are free.
BASELINE_SET = tuple(dv.name for dv in VEHICLE_DESIGN_VARIABLES if dv.baseline)
