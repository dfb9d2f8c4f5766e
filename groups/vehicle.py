"""The vehicle: geometry, wing-box mass, motor masses and mass properties from design variables."""

import functools
import warnings

import numpy as np
import openmdao.api as om
from openmdao.utils.om_warnings import OpenMDAOWarning

from lpc_mdo.components.aero.tyre_size import TyreFrontalAreaComp
from lpc_mdo.components.dynamics.body_pitching_moment import (
    BodyMomentSlopeComp,
    body_moment_slope_options,
)
from lpc_mdo.components.geometry.blade import BLADE_OUTPUTS, BladeGeometryGroup
from lpc_mdo.components.geometry.cranked_planform import CrankedPlanformComp, SectionLayout
from lpc_mdo.components.geometry.minimum_chord import BladeChordMarginComp
from lpc_mdo.components.geometry.planform import PlanformMeshComp
from lpc_mdo.components.geometry.rotor_clearance import RotorClearanceComp
from lpc_mdo.components.geometry.rotor_layout import RotorLayoutComp
from lpc_mdo.components.geometry.section_mesh import SectionMeshComp
from lpc_mdo.components.geometry.surface_sizing import SurfaceSizingComp
from lpc_mdo.components.geometry.tail_position import TailPositionComp
from lpc_mdo.components.motor.parameters import DESIGN_OUTPUTS, MotorParameters
from lpc_mdo.components.structures.beam import BeamMassComp
from lpc_mdo.components.structures.box_section import BoxSectionComp
from lpc_mdo.components.structures.section_wing_box_geometry import SectionWingBoxGeometryComp
from lpc_mdo.components.structures.wing_box_geometry import (
    WingBoxGeometryComp,
    wing_box_section,
)
from lpc_mdo.components.weights.wing_mass import WingMirrorComp
from lpc_mdo.core.mpi import serial_comm
from lpc_mdo.groups.motor import MotorDesignGroup
from lpc_mdo.groups.weights import WeightsGroup, motor_group_indices
from lpc_mdo.vehicle import reference_vehicle
from lpc_mdo.vehicle.clearances import rotor_pairs, rotor_sides, side_by_side_pairs
from lpc_mdo.vehicle.design_variable_registry import VEHICLE_DESIGN_VARIABLES

# OpenMDAO notes, when a driver splits the model into systems before, in and after the
# optimization iteration, that a group with a DirectSolver is "treated as atomic" there. Every
# system of the vehicle group depends on the design variables and feeds the objective, so the
# split is the same either way: VehicleGroup.setup hides the notice when it lists the vehicle
# group alone. A user's own groups with such solvers are still reported.
_ATOMIC_VEHICLE_NOTICE = (
    r"The following groups have a nonlinear solver that computes gradients .*: "
    r"\n([\w.]+\.)?vehicle\n\Z"
)


def motor_parameters(vehicle):
    """Return the PMSM's fixed parameters from the vehicle file's [motor] table."""
    return MotorParameters.of_motor_table(vehicle.motor)


def motor_loadings(vehicle):
    """
    Return the electric and magnetic loadings (A/m, T) of the vehicle file's [motor] table.

    They are keyword arguments of :class:`~lpc_mdo.groups.motor.MotorGroup`.
    """
    m = vehicle.motor
    return {"electric_loading": m.electric_loading, "magnetic_loading": m.magnetic_loading}


class VehicleGroup(om.Group):
    """
    Everything about the vehicle that does not depend on a flight condition.

    From the planform, rotor, motor, battery and wing-box design variables to the planform
    dimensions, rotor layout, wing-box geometry and mass, motor masses and the mass properties
    and gross mass of the whole vehicle (paper Sec. II.D, eqs. 23, 31-33).

    Subsystems (promoted):

    - ``wing_sizing``, ``htail_sizing`` (SurfaceSizingComp): span, root/tip chord, MAC
      (outputs ``wing_span``, ``wing_root_chord``, ``wing_tip_chord``, ``wing_mac`` and the
      ``htail_`` equivalents);
    - ``tail_position`` (TailPositionComp): tail root leading edges follow the fuselage length;
    - ``wing_mesh``, ``htail_mesh`` (PlanformMeshComp): VLM meshes ``wing_mesh`` and
      ``horizontal_tail_mesh`` (cosine span-wise spacing, one chord-wise panel);
    - ``rotor_layout`` (RotorLayoutComp): hub positions, radii, radius intersection;
    - ``rotor_clearance`` (RotorClearanceComp): plan-view clearances of the lift disks to each
      other, the fuselage, the h-tail and the pusher (the rotors and pairs of
      :mod:`lpc_mdo.vehicle.clearances`);
    - ``blades`` (BladeGeometryGroup, one row per rotor group): blade stations, chord and twist
      (``blade_chord``, ``blade_twist``, ``blade_station_radius``, ...) that every condition's
      rotor models read;
    - ``wing_box`` (WingBoxGeometryComp), ``box_section`` (BoxSectionComp), ``box_mass``
      (BeamMassComp), ``wing_mirror`` (WingMirrorComp): the beam of one half wing (the
      vehicle's taper, sweep, dihedral, incidence and root leading edge), its mass and the whole
      wing's mass and cg;
    - ``motor_design`` (MotorDesignGroup, one motor design per rotor group): motor masses
      (eq. 23) with the vehicle's electric and magnetic loadings, and the equivalent circuit
      (``motor_resistance``, ``motor_inductance_d``, ...: ``motor_{name}`` for the names in
      :data:`~lpc_mdo.components.motor.parameters.DESIGN_OUTPUTS`) that every condition's motors
      read;
    - ``weights`` (WeightsGroup): regressions, gross mass (objective), cg, inertia.

    Inputs (promoted): the vehicle-level design variables
    (:data:`~lpc_mdo.vehicle.design_variable_registry.VEHICLE_DESIGN_VARIABLES`) (the wing-box
    thicknesses per bay, root to tip).

    Options
    -------
    vehicle : Vehicle or None
        None = the reference vehicle.
    other_mass : float or None
        W_other in kg; None = the vehicle's rule (``masses.other_rule``): ``masses.other``
        ("fixed"; the reference vehicle: 0), or calibrated so that the initial design's gross
        mass equals ``masses.design_gross_mass`` ("calibrated", the paper's procedure).
    other_cg : sequence of 3 float or None
        cg of W_other in m; None = the vehicle's ``masses.other_cg``.
    """

    def initialize(self):
        self.options.declare(
            "vehicle",
            default=None,
            allow_none=True,
            desc="lpc_mdo.vehicle.Vehicle; None = reference vehicle",
        )
        self.options.declare(
            "other_mass",
            default=None,
            types=(int, float),
            allow_none=True,
            desc="W_other (kg); None = the vehicle's masses.other_rule",
        )
        self.options.declare(
            "other_cg",
            default=None,
            types=(tuple, list, np.ndarray),
            allow_none=True,
            desc="cg of W_other (m); None = the vehicle's masses.other_cg",
        )
        self.options.declare(
            "wing_panels",
            default=26,
            types=int,
            desc="span-wise VLM panels of the wing (even; paper code 26)",
        )
        self.options.declare(
            "tail_panels",
            default=8,
            types=int,
            desc="span-wise VLM panels of the horizontal tail (even; code 8)",
        )
        self.options.declare(
            "num_radial",
            default=25,
            types=int,
            lower=2,
            desc="radial stations of the blade geometry (the conditions' num_radial)",
        )

    def _add_blades(self, vehicle):
        """
        Blade stations, chord and twist of each rotor group: ``blade_*`` (:data:`BLADE_OUTPUTS`).

        One row per row of the per-group design variables (``rotor_radius``, ``blade_chord_cp``,
        ``blade_twist_cp``: the lift pairs, then the pusher). They depend on the design alone,
        so they are computed once here and every condition's rotor models read the rows of their
        rotors (the rotor groups' ``blade_geometry="inputs"``), with the rotor groups' default
        quadrature and spline stations (docs theory/rotors 'Blade parameterization').
        """
        rotors = {r.pair: r for r in (*vehicle.lift_rotors, vehicle.pusher)}
        hub_ratio = [rotors[row].hub_radius_ratio for row in range(len(rotors))]
        self.add_subsystem(
            "blades",
            BladeGeometryGroup(
                num_rotors=len(rotors),
                num_radial=self.options["num_radial"],
                num_azimuth=1,
                hub_radius_ratio=hub_ratio,
            ),
            promotes_inputs=[
                ("radius", "rotor_radius"),
                ("chord_cp", "blade_chord_cp"),
                ("twist_cp", "blade_twist_cp"),
            ],
            promotes_outputs=[(name, f"blade_{name}") for name in BLADE_OUTPUTS],
        )
        # The minimum-chord constraint's output (docs theory/rotors 'Minimum chord').
        self.add_subsystem(
            "blade_chord_margin",
            BladeChordMarginComp(
                num_rotors=len(rotors),
                num_cp=len(vehicle.pusher.chord_cp),
                min_chord_radius_ratio=vehicle.constraints.min_chord_radius_ratio,
            ),
            promotes=["*"],
        )

    def _add_section_wing(self, vehicle):
        """
        Add the planform and VLM mesh of a wing of span-wise sections (``planform = "sections"``).

        One planform (:class:`CrankedPlanformComp`, docs theory/geometry 'Cranked wing
        planform') gives span, root and tip chord, the MAC (drag build-up, static margin) and
        its leading edge (``wing_mac_leading_edge``), and the section leading edges and chords
        that the VLM mesh (:class:`SectionMeshComp`) and the wing box
        (:class:`SectionWingBoxGeometryComp`) read.
        """
        wing = vehicle.wing
        self._layout = SectionLayout.from_wing(wing)
        self.add_subsystem(
            "wing_planform",
            CrankedPlanformComp(layout=self._layout),
            promotes_inputs=[
                ("area", "wing_area"),
                ("aspect_ratio", "wing_aspect_ratio"),
                ("root_leading_edge", "wing_root_leading_edge"),
            ],
            promotes_outputs=[
                ("span", "wing_span"),
                ("root_chord", "wing_root_chord"),
                ("tip_chord", "wing_tip_chord"),
                ("mean_aerodynamic_chord", "wing_mac"),
                ("mac_leading_edge", "wing_mac_leading_edge"),
                ("section_leading_edges", "wing_section_leading_edges"),
                ("section_chords", "wing_section_chords"),
            ],
        )
        self.add_subsystem(
            "wing_mesh",
            SectionMeshComp(
                layout=self._layout,
                num_chord_panels=1,
                num_span_panels=self.options["wing_panels"],
                spacing="cosine",
            ),
            promotes_inputs=[
                ("section_leading_edges", "wing_section_leading_edges"),
                ("section_chords", "wing_section_chords"),
                ("incidence", "wing_incidence"),
            ],
            promotes_outputs=[("mesh", "wing_mesh")],
        )
        self.set_input_defaults("wing_incidence", wing.incidence, units="rad")

    def setup(self):
        vehicle = self.options["vehicle"] or reference_vehicle()
        other, other_cg = self.options["other_mass"], self.options["other_cg"]
        if other is None:
            if vehicle.masses.other_rule == "calibrated":
                other = calibrated_other_mass(vehicle)[0]
            else:
                other = vehicle.masses.other
        wing, tail = vehicle.wing, vehicle.horizontal_tail

        sections = wing.planform == "sections"
        if sections:
            self._add_section_wing(vehicle)
        else:
            self.add_subsystem(
                "wing_sizing",
                SurfaceSizingComp(taper_ratio=wing.taper_ratio),
                promotes_inputs=[("area", "wing_area"), ("aspect_ratio", "wing_aspect_ratio")],
                promotes_outputs=[
                    ("span", "wing_span"),
                    ("root_chord", "wing_root_chord"),
                    ("tip_chord", "wing_tip_chord"),
                    ("mean_aerodynamic_chord", "wing_mac"),
                ],
            )
        self.add_subsystem(
            "htail_sizing",
            SurfaceSizingComp(taper_ratio=tail.taper_ratio),
            promotes_inputs=[("area", "htail_area"), ("aspect_ratio", "htail_aspect_ratio")],
            promotes_outputs=[
                ("span", "htail_span"),
                ("root_chord", "htail_root_chord"),
                ("tip_chord", "htail_tip_chord"),
                ("mean_aerodynamic_chord", "htail_mac"),
            ],
        )
        self.add_subsystem("tail_position", TailPositionComp(vehicle=vehicle), promotes=["*"])
        meshes = [("horizontal_tail", "htail", tail, self.options["tail_panels"])]
        if not sections:  # the section wing has its own mesh (_add_section_wing)
            meshes.insert(0, ("wing", "wing", wing, self.options["wing_panels"]))
        for name, prefix, surface, panels in meshes:
            self.add_subsystem(
                f"{prefix}_mesh",
                PlanformMeshComp(num_chord_panels=1, num_span_panels=panels, spacing="cosine"),
                promotes_inputs=[
                    (p, f"{prefix}_{p}")
                    for p in (
                        "span",
                        "root_chord",
                        "tip_chord",
                        "sweep",
                        "dihedral",
                        "incidence",
                        "root_leading_edge",
                    )
                ],
                promotes_outputs=[("mesh", f"{name}_mesh")],
            )
            for p in ("sweep", "dihedral", "incidence"):
                self.set_input_defaults(f"{prefix}_{p}", getattr(surface, p), units="rad")
        self.set_input_defaults(
            "wing_root_leading_edge", np.array(wing.root_leading_edge), units="m"
        )
        self.add_subsystem(
            "rotor_layout",
            RotorLayoutComp(vehicle=vehicle, side_by_side=side_by_side_pairs(vehicle)),
            promotes=["*"],
        )
        self.add_subsystem(
            "rotor_clearance",
            RotorClearanceComp(
                side=rotor_sides(vehicle),
                rotor_pairs=rotor_pairs(vehicle),
                fuselage_max_width=float(vehicle.fuselage.max_width),
                num_groups=len(vehicle.lift_rotor_pairs) + 1,
                pusher_row=len(vehicle.lift_rotor_pairs),
                pusher_axis=tuple(vehicle.pusher.thrust_axis),
            ),
            promotes=["*"],
        )
        self._add_blades(vehicle)
        # Multhopp sums of the fuselage and booms for the aerodynamic conditions' body moment
        # (docs theory/dynamics 'Fuselage, booms, camber and tail efficiency').
        self.add_subsystem(
            "body_moment_slope",
            BodyMomentSlopeComp(**body_moment_slope_options(vehicle)),
            promotes=["*"],
        )

        nodes = vehicle.wing_box.num_bays + 1
        if sections:
            self.add_subsystem(
                "wing_box",
                SectionWingBoxGeometryComp(
                    layout=self._layout, num_nodes=nodes, section=wing_box_section(vehicle)
                ),
                promotes_inputs=[
                    ("section_leading_edges", "wing_section_leading_edges"),
                    ("section_chords", "wing_section_chords"),
                    "wing_incidence",
                ],
                promotes_outputs=[
                    ("nodes", "wing_box_nodes"),
                    "box_width",
                    "box_height",
                    "top_skin_radius",
                    "bottom_skin_radius",
                ],
            )
        else:
            # The wing box shares the VLM mesh's sweep, dihedral, incidence and root leading
            # edge (promoted inputs, defaults set above); the taper ratio is an option of the
            # planform sizing, so the box's own input keeps the vehicle's value (its default
            # from ``wing``).
            self.add_subsystem(
                "wing_box",
                WingBoxGeometryComp(num_nodes=nodes, section=wing_box_section(vehicle), wing=wing),
                promotes_inputs=[
                    "wing_area",
                    "wing_aspect_ratio",
                    "wing_sweep",
                    "wing_dihedral",
                    "wing_incidence",
                    "wing_root_leading_edge",
                ],
                promotes_outputs=[
                    ("nodes", "wing_box_nodes"),
                    "box_width",
                    "box_height",
                    "top_skin_radius",
                    "bottom_skin_radius",
                ],
            )
        self.add_subsystem("box_section", BoxSectionComp(num_elements=nodes - 1), promotes=["*"])
        self.add_subsystem(
            "box_mass",
            BeamMassComp(num_nodes=nodes),
            promotes_inputs=[("nodes", "wing_box_nodes"), "area", ("density", "material_density")],
            promotes_outputs=[
                "element_mass",
                ("beam_mass", "half_wing_mass"),
                ("beam_cg", "half_wing_cg"),
            ],
        )
        self.add_subsystem("wing_mirror", WingMirrorComp(), promotes=["*"])

        groups = motor_group_indices(vehicle)
        num_groups = len(vehicle.lift_rotor_pairs) + 1  # motor designs: one per lift pair, pusher
        self.add_subsystem(
            "motor_design",
            MotorDesignGroup(
                num_motors=num_groups,
                length_to_diameter=vehicle.motor.length_to_diameter,
                parameters=motor_parameters(vehicle),
                **motor_loadings(vehicle),
            ),
            promotes_inputs=[("length", "motor_length"), ("rated_current", "motor_rated_current")],
            promotes_outputs=[("mass", "motor_group_mass")]
            + [(name, f"motor_{name}") for name in DESIGN_OUTPUTS],
        )
        self.add_subsystem(
            "weights",
            WeightsGroup(vehicle=vehicle, other_mass=float(other), other_cg=other_cg),
            promotes=["*"],
        )
        self.connect("motor_group_mass", "motor_mass", src_indices=groups)
        self.connect("motor_peak_current", "motor_current_rating", src_indices=groups)
        # The landing-gear tyres of the drag build-up, sized from W_dg (groups/vehicle_drag.py).
        self.add_subsystem("tyres", TyreFrontalAreaComp(), promotes=["*"])

        self.set_input_defaults("material_density", vehicle.material.density, units="kg/m**3")
        dvs = vehicle.design_variables
        # W_dg from the vehicle's masses, not its design-variable table: a caller may replace
        # the masses without reloading the file (lpc_mdo.sizing does).
        self.set_input_defaults("design_gross_mass", vehicle.masses.design_gross_mass, units="kg")
        for dv in VEHICLE_DESIGN_VARIABLES:
            if dv.name == "design_gross_mass":
                continue
            self.set_input_defaults(
                dv.name,
                np.asarray(dvs[dv.name].initial_array).reshape(dvs[dv.name].shape),
                units=None if dv.units == "unitless" else dv.units,
            )

        # Total derivatives: nearly every right-hand side of the adjoint (each trim row, margin
        # and the state of charge) passes back through the vehicle's geometry, motor-design and
        # mass chain (about 30 components). One sparse LU of the group's assembled Jacobian per
        # linearization turns those visits into one back-substitution per right-hand side
        # (compute_totals of the full model -9 to -13 %, measured A/B in one process). The group
        # is feed-forward, so the LU has little fill; the nonlinear solver stays RunOnce.
        self.linear_solver = om.DirectSolver(assemble_jac=True)
        warnings.filterwarnings("ignore", message=_ATOMIC_VEHICLE_NOTICE, category=OpenMDAOWarning)


@functools.lru_cache(maxsize=8)
def calibrated_other_mass(vehicle):
    """
    Return W_other and its cg such that the vehicle's initial design has its design gross mass.

    This is lpc-mdo's one W_other calibration: :class:`VehicleGroup` (so the full model) uses
    it when the vehicle's ``masses.other_rule`` is ``"calibrated"``, and
    :func:`calibrate_other_mass` (``lpc_mdo.api``) returns its mass. The
    target is ``masses.design_gross_mass``. W_other is the named unitemised item at
    ``masses.other_cg`` (a stated position; no rule moves it to balance hover).

    The paper calibrates W_other at the initial design because the NASA reference does not itemise
    every weight (docs theory/weights 'Gross mass'). Gross mass and cg are affine in W_other and its
    position, so one run of the vehicle group with W_other = 0 gives both exactly. Every other item
    is held at its initial-design value as the model computes it: the wing mass from the wing-box
    beam at the initial thicknesses (the vehicle file's gauges, sized at +3g/-1g by
    ``run_scripts/close_initial_design.py``) plus its secondary structure, the rotor, landing-gear
    and system items, the motor masses from the motor sizing (paper eq. 23), the
    fuselage, boom and empennage masses from the M4 regressions, and the fixed masses of the vehicle
    file.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle definition (hashable; results are cached per vehicle).

    Returns
    -------
    tuple of (float, tuple of 3 float)
        W_other in kg and its cg in m (body frame).

    Raises
    ------
    ValueError
        When the other items already weigh the target or more (W_other would be <= 0).
    """
    masses = vehicle.masses
    bare_mass = _gross_mass(_initial_design(vehicle, other=0.0))
    other = masses.design_gross_mass - bare_mass
    if other <= 0.0:
        raise ValueError(
            f"masses.design_gross_mass = {masses.design_gross_mass} kg; the other "
            f"items of the initial design weigh {bare_mass:.2f} kg, so W_other "
            f"would be {other:.2f} kg; allowed: a target above {bare_mass:.2f} kg."
        )
    return other, tuple(float(v) for v in masses.other_cg)


def calibrate_other_mass(vehicle=None):
    """
    Return W_other (kg) such that the vehicle's initial design has its target gross mass.

    This is the W_other the model uses: :class:`VehicleGroup` (and so
    the full model) calibrates with the same function,
    :func:`calibrated_other_mass`, which evaluates the vehicle at its
    initial design with the wing mass from the wing-box beam and the motor masses from the motor
    sizing (paper eq. 23). The paper chose W_other "so that the initial gross weight computed by
    our computational model matches closely with the NASA reference" (Sec. IV).

    Parameters
    ----------
    vehicle : lpc_mdo.vehicle.Vehicle or None
        None = the reference vehicle. The target is its ``masses.design_gross_mass``
        (3723.99 kg for the reference vehicle, paper Table 8).

    Returns
    -------
    float
        Calibrated W_other, kg.

    Raises
    ------
    ValueError
        When the vehicle's other items already weigh more than the target (W_other <= 0).
    """
    return calibrated_other_mass(reference_vehicle() if vehicle is None else vehicle)[0]


def _initial_design(vehicle, other):
    """Return a set-up problem of the vehicle group at its initial design, W_other = other kg."""
    prob = om.Problem(reports=False, comm=serial_comm())
    prob.model.add_subsystem(
        "vehicle",
        VehicleGroup(vehicle=vehicle, other_mass=float(other), other_cg=(0.0, 0.0, 0.0)),
        promotes=["*"],
    )
    prob.setup()
    return prob


def _gross_mass(prob):
    prob.run_model()
    return float(prob.get_val("gross_mass", units="kg")[0])


def closed_design_gross_mass(vehicle, tolerance=1e-3, max_iterations=50):
    """
    Return the design gross mass W_dg at which the vehicle's initial design weighs W_dg (kg).

    The landing-gear, wing-secondary and systems regressions scale with the design gross mass
    (docs theory/weights 'Mass items'), which NDARC and FLOPS take as an input and a sizing
    code closes on the gross mass it computes. This is that closure for the initial design
    (:func:`close_design_gross_mass`), with the vehicle's fixed W_other. A
    calibrated vehicle (``masses.other_rule = "calibrated"``) is closed by construction (its
    W_other makes W0 = W_dg), so its W_dg is returned unchanged.
    ``run_scripts/close_initial_design.py`` writes the result into a vehicle file.

    Parameters
    ----------
    vehicle : Vehicle
        The vehicle definition; its ``masses.design_gross_mass`` is the first W_dg.
    tolerance : float
        Absolute tolerance on W0 - W_dg, kg.
    max_iterations : int
        Iterations before giving up.

    Returns
    -------
    float
        The closed design gross mass, kg.

    Raises
    ------
    om.AnalysisError
        When the iteration does not converge within ``max_iterations``.
    """
    masses = vehicle.masses
    if masses.other_rule == "calibrated":
        return masses.design_gross_mass
    prob = _initial_design(vehicle, masses.other)
    return close_design_gross_mass(prob, masses.design_gross_mass, tolerance, max_iterations)


def close_design_gross_mass(prob, design_gross_mass, tolerance=1e-3, max_runs=50):
    """
    Return W_dg = W0(W_dg) of a set-up problem, by secant steps on h = W0(W_dg) - W_dg (kg).

    W0 is nearly linear in W_dg (the regressions' exponents), so the secant settles in about
    three model runs where substitution W_dg <- W0, converging by dW0/dW_dg ~ 0.14 a run, takes
    six. The first step is that substitution. The problem is left at the last W_dg tried,
    within ``tolerance`` of the returned W0.

    Parameters
    ----------
    prob : om.Problem
        A set-up problem with the input ``design_gross_mass`` and the output ``gross_mass``.
    design_gross_mass : float
        The first W_dg, kg.
    tolerance : float
        Absolute tolerance on W0 - W_dg, kg.
    max_runs : int
        Model runs before giving up.

    Raises
    ------
    om.AnalysisError
        When W_dg does not settle within ``max_runs``.
    """
    previous = None
    for _ in range(max_runs):
        prob.set_val("design_gross_mass", design_gross_mass, units="kg")
        gross = _gross_mass(prob)
        miss = gross - design_gross_mass
        if abs(miss) <= tolerance:
            return gross
        if previous is None or miss == previous[1]:
            step_to = gross
        else:
            step_to = design_gross_mass - miss * (design_gross_mass - previous[0]) / (
                miss - previous[1]
            )
        previous = (design_gross_mass, miss)
        design_gross_mass = step_to
    raise om.AnalysisError(
        f"the design gross mass did not settle in {max_runs} model runs: W0 {gross:.3f} kg, "
        f"W_dg {design_gross_mass:.3f} kg"
    )
