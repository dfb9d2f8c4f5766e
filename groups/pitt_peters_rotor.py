"""Pitt–Peters rotor assembly: blade geometry, inflow states, loads, performance and hub loads."""

from lpc_mdo.components.rotor.advance_ratio import EdgewiseAdvanceRatioComp
from lpc_mdo.components.rotor.pitt_peters_inflow import PittPetersInflowComp
from lpc_mdo.components.rotor.pitt_peters_loads import LOSS_PLACEMENTS, PittPetersLoadsComp
from lpc_mdo.groups.bem_rotor import RotorGroupBase


class PittPetersRotorGroup(RotorGroupBase):
    """
    Several rotors at several operating points by steady Pitt–Peters inflow (edgewise flight).

    Paper eq. 14-15, docs theory/rotors 'Pitt-Peters inflow'. The same interface as
    :class:`~lpc_mdo.groups.bem_rotor.BEMRotorGroup`, so a condition group can use either.
    Subsystems (all variables promoted):

    - ``blade``: BladeGeometryGroup (stations, chord and twist B-splines; docs theory/rotors 'Blade
      parameterization', 'Stations and disk frame');
    - ``velocity``: RotorVelocityComp (body velocity to each disk's axial and in-plane
      velocity), if ``body_frame``;
    - ``inflow``: PittPetersInflowComp (the three inflow states per rotor and operating point,
      L^-1 lambda - c = 0 by Newton);
    - ``loads``: PittPetersLoadsComp (sectional loads over (r, psi), thrust, torque, in-plane hub
      force, hub moments);
    - ``performance``: RotorPerformanceComp (power, C_T, C_P, J, eta, FoM, tip Mach; docs
      theory/rotors 'Loads and coefficients', 'Pitt-Peters inflow');
    - ``hub_loads``: HubLoadsComp with the in-plane loads (body-frame forces and moments), if
      ``body_frame``.

    Solvers: the group is feed-forward (NonlinearRunOnce, LinearRunOnce). PittPetersInflowComp
    solves itself in ``solve_nonlinear`` (Newton on 3x3 blocks) and inverts those blocks in
    ``solve_linear``, so no DirectSolver is needed and a total derivative costs one pass.

    The inputs are promoted.

    Inputs
    ------
    radius : (num_rotors,), m
        Tip radius (design variable).
    chord_cp, twist_cp : (num_rotors, num_cp), m and rad
        Chord and twist control points, root to tip (design variables).
    rpm : (num_rotors, num_nodes), rpm
        Rotor speed.
    velocity : (num_nodes, 3), m/s
        Body-axis velocity of the vehicle relative to the air (u, v, w), if ``body_frame``;
        otherwise the inputs are axial_velocity (num_rotors, num_nodes) and inplane_velocity
        (num_rotors, num_nodes, 2), m/s.
    density, speed_of_sound, dynamic_viscosity : (num_nodes,), kg/m**3, m/s, Pa*s
        Atmosphere.
    hub_position : (num_rotors, 3), m;  reference_point : (3,), m
        If ``body_frame``.

    The outputs are promoted.

    Outputs
    -------
    hub_radius, station_radius, station_width, chord, twist, azimuth
        Blade geometry (BladeGeometryGroup).
    axial_velocity, inplane_velocity
        If ``body_frame`` (RotorVelocityComp).
    inflow_states : (num_rotors, num_nodes, 3), -
        (lambda_0, lambda_c, lambda_s).
    thrust_per_span, drag_per_span, inflow_angle : (num_rotors, num_nodes, num_radial,
    num_azimuth), N/m, N/m, rad
        Sectional loads of one blade over (r, psi) (for the tonal acoustics), if
        ``sectional_loads``.
    thrust, torque : (num_rotors, num_nodes), N, N*m
    inplane_force, hub_moment : (num_rotors, num_nodes, 2), N, N*m
        In-plane hub force and hub moment along / about the disk e_x and e_y.
    power, thrust_coefficient, power_coefficient, advance_ratio, efficiency, figure_of_merit,
    tip_mach, helical_tip_mach : (num_rotors, num_nodes)
        RotorPerformanceComp (helical_tip_mach at the advancing blade).
    edgewise_advance_ratio : (num_rotors, num_nodes)
        mu = abs(inplane_velocity) / (Omega R) (EdgewiseAdvanceRatioComp).
    force, moment : (num_rotors, num_nodes, 3); total_force, total_moment : (num_nodes, 3)
        If ``body_frame`` (HubLoadsComp).

    Options
    -------
    rotors : sequence of lpc_mdo.vehicle.Rotor or None
        Supplies num_rotors, num_blades, hub_radius_ratio, thrust_axis and spin_direction
        (leave those options at None) and the defaults of radius, chord_cp, twist_cp and
        hub_position.
    num_rotors, num_blades, hub_radius_ratio, thrust_axis, spin_direction
        None: from ``rotors``, else 1, 2, 0.2, (0, 0, -1), +1.
    num_nodes, num_radial, num_azimuth, num_cp : int
        Operating points (1), radial stations (25), azimuthal stations (25), control points (4).
    polar : Polar
        Sectional polar. Default LinearQuadraticPolar() (docs theory/aerodynamics 'Linear-quadratic
        polar').
    tip_loss, hub_loss : bool
        Prandtl losses (default True).
    loss_placement : str
        'momentum' (default, as the BEM) or 'blade_element' (docs theory/rotors 'Pitt-Peters
        inflow'); see PittPetersInflowComp.
    tangential_induction : bool
        Wake swirl per station (default True; see PittPetersLoadsComp).
    sectional_loads : bool
        Output the sectional loads (default True; a condition that does not read them leaves
        them out, see PittPetersLoadsComp).
    quadrature, spline_stations : str
        'midpoint', 'as_coded' (defaults; see BladeGeometryGroup).
    body_frame : bool
        Include RotorVelocityComp and HubLoadsComp (default True).
    """

    num_azimuth_option = True

    def declare_model_options(self):
        self.options.declare(
            "num_azimuth",
            default=25,
            types=int,
            lower=3,
            desc="Number of azimuthal stations (>= 3)",
        )
        self.options.declare(
            "loss_placement",
            default="momentum",
            values=LOSS_PLACEMENTS,
            desc="Prandtl factor on the momentum side or on the blade loads",
        )
        self.options.declare(
            "tangential_induction",
            default=True,
            types=bool,
            desc="Wake swirl per station (as the BEM)",
        )
        self.options.declare(
            "sectional_loads",
            default=True,
            types=bool,
            desc="Output the sectional loads over (r, psi)",
        )

    def add_rotor_model(self, geo):
        opts = self.options
        pp = {
            "num_rotors": geo["num_rotors"],
            "num_nodes": opts["num_nodes"],
            "num_radial": opts["num_radial"],
            "num_azimuth": opts["num_azimuth"],
            "num_blades": geo["num_blades"],
            "spin_direction": geo["spin_direction"],
            "polar": opts["polar"],
            "tip_loss": opts["tip_loss"],
            "hub_loss": opts["hub_loss"],
            "loss_placement": opts["loss_placement"],
            "tangential_induction": opts["tangential_induction"],
        }
        self.add_subsystem("inflow", PittPetersInflowComp(**pp), promotes=["*"])
        self.add_subsystem(
            "loads",
            PittPetersLoadsComp(**pp, sectional_loads=opts["sectional_loads"]),
            promotes=["*"],
        )
        self.add_subsystem(
            "advance_ratio",
            EdgewiseAdvanceRatioComp(num_rotors=geo["num_rotors"], num_nodes=opts["num_nodes"]),
            promotes=["*"],
        )
        return True  # edgewise model: in-plane forces and hub moments
