"""BEM rotor assembly: blade geometry, inflow-angle solve, loads, performance and hub loads."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.polar import LinearQuadraticPolar, Polar
from lpc_mdo.components.geometry.blade import QUADRATURES, SPLINE_STATIONS, BladeGeometryGroup
from lpc_mdo.components.ks import KSComp
from lpc_mdo.components.rotor.bem_inflow import TIP_LOSS_FORMS, BEMInflowComp
from lpc_mdo.components.rotor.bem_loads import BEMLoadsComp, RotorPerformanceComp
from lpc_mdo.components.rotor.blade_stall import BladeStallRatioComp
from lpc_mdo.components.rotor.hub_loads import HubLoadsComp, RotorVelocityComp

#: KS parameter of ``blade_stall_ratio_ks``, the smooth maximum of the stations' alpha /
#: alpha_stall (both stalls): it exceeds the largest ratio by at most ln(2 nr nn nrad) / 200
#: (0.030 for 8 rotors of 25 stations), on the safe side (paper eq. 7).
BLADE_STALL_KS_RHO = 200.0

# Options that the `rotors` option can supply, with their values without it.
_ROTOR_DERIVED = {
    "num_rotors": 1,
    "num_blades": 2,
    "hub_radius_ratio": 0.2,
    "thrust_axis": None,
    "spin_direction": 1,
}


def rotor_options(rotors):
    """
    Options of :class:`BEMRotorGroup` (and its components) taken from vehicle rotors.

    Parameters
    ----------
    rotors : sequence of lpc_mdo.vehicle.Rotor
        E.g. ``vehicle.lift_rotors`` or ``(vehicle.pusher,)``.

    Returns
    -------
    dict
        num_rotors, num_blades, hub_radius_ratio, thrust_axis, spin_direction.
    """
    rotors = tuple(rotors)
    if not rotors:
        raise ValueError("option 'rotors' is empty; give at least one lpc_mdo.vehicle.Rotor.")
    return {
        "num_rotors": len(rotors),
        "num_blades": [r.num_blades for r in rotors],
        "hub_radius_ratio": [r.hub_radius_ratio for r in rotors],
        "thrust_axis": np.array([r.thrust_axis for r in rotors], dtype=float),
        "spin_direction": [r.spin_direction for r in rotors],
    }


class RotorGroupBase(om.Group):
    """
    Base of the rotor assemblies: the parts every rotor model shares.

    The shared parts are the rotor options (from vehicle rotors or given), blade geometry,
    body-frame velocity, performance, hub loads and the input defaults. Subclasses add their
    inflow and loads components in :meth:`add_rotor_model` and may declare more options in
    :meth:`declare_model_options`.
    """

    num_azimuth_option = False  # whether the subclass resolves azimuthal stations

    def initialize(self):
        self.options.declare(
            "rotors",
            default=None,
            types=(list, tuple),
            allow_none=True,
            desc="lpc_mdo.vehicle.Rotor objects supplying the rotor options",
        )
        self.options.declare(
            "num_rotors",
            default=None,
            types=int,
            lower=1,
            allow_none=True,
            desc="Number of rotors (None: from rotors, else 1)",
        )
        self.options.declare(
            "num_blades",
            default=None,
            allow_none=True,
            types=(int, list, tuple, np.ndarray),
            desc="Blades per rotor (None: from rotors, else 2)",
        )
        self.options.declare(
            "hub_radius_ratio",
            default=None,
            allow_none=True,
            types=(int, float, list, tuple, np.ndarray),
            desc="Hub radius over tip radius (None: from rotors, else 0.2)",
        )
        self.options.declare(
            "thrust_axis",
            default=None,
            allow_none=True,
            types=(list, tuple, np.ndarray),
            desc="Thrust axes (num_rotors, 3) (None: from rotors, else lift)",
        )
        self.options.declare(
            "spin_direction",
            default=None,
            allow_none=True,
            types=(int, list, tuple, np.ndarray),
            desc="+1 or -1 per rotor (None: from rotors, else +1)",
        )
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="Number of operating points per rotor"
        )
        self.options.declare(
            "num_radial", default=25, types=int, lower=1, desc="Number of radial stations"
        )
        self.options.declare(
            "num_cp", default=4, types=int, lower=4, desc="Chord and twist control points per rotor"
        )
        self.options.declare(
            "polar", default=LinearQuadraticPolar(), types=Polar, desc="Sectional airfoil polar"
        )
        self.options.declare("tip_loss", default=True, types=bool, desc="Prandtl tip loss")
        self.options.declare("hub_loss", default=True, types=bool, desc="Prandtl hub loss")
        self.options.declare(
            "quadrature",
            default="midpoint",
            values=QUADRATURES,
            desc="Radial quadrature ('bladead': as the public code, "
            "docs theory/rotors 'Public-code compatibility')",
        )
        self.options.declare(
            "spline_stations",
            default="as_coded",
            values=SPLINE_STATIONS,
            desc="Where the chord and twist spline values are placed "
            '(docs theory/rotors "Blade parameterization")',
        )
        self.options.declare(
            "body_frame", default=True, types=bool, desc="Include body-frame velocity and hub loads"
        )
        self.options.declare(
            "blade_geometry",
            default="internal",
            values=("internal", "inputs"),
            desc="'internal': the group computes its blade geometry from radius, chord_cp and "
            "twist_cp; 'inputs': the BLADE_OUTPUTS are inputs (computed once elsewhere, e.g. "
            "by the vehicle group's blades)",
        )
        self.declare_model_options()

    def declare_model_options(self):
        """Options of the inflow model (override)."""

    def add_rotor_model(self, geo):
        """Add the inflow and loads components (override)."""
        raise NotImplementedError

    def _resolved(self):
        opts = self.options
        values = {name: opts[name] for name in _ROTOR_DERIVED}
        rotors = opts["rotors"]
        if rotors is not None:
            derived = rotor_options(rotors)
            given = [name for name, value in values.items() if value is not None]
            if given:
                raise ValueError(
                    f"{self.msginfo}: options {given} must be left at None when "
                    "option 'rotors' is given (they are taken from the rotors)."
                )
            return derived
        return {
            name: (_ROTOR_DERIVED[name] if value is None else value)
            for name, value in values.items()
        }

    def setup(self):
        opts = self.options
        geo = self._resolved()
        nr, nn = geo["num_rotors"], opts["num_nodes"]
        frame = {"num_rotors": nr, "num_nodes": nn, "thrust_axis": geo["thrust_axis"]}

        naz = opts["num_azimuth"] if self.num_azimuth_option else 1
        internal = opts["blade_geometry"] == "internal"
        if internal:
            self.add_subsystem(
                "blade",
                BladeGeometryGroup(
                    num_rotors=nr,
                    num_radial=opts["num_radial"],
                    num_azimuth=naz,
                    num_cp=opts["num_cp"],
                    hub_radius_ratio=geo["hub_radius_ratio"],
                    quadrature=opts["quadrature"],
                    spline_stations=opts["spline_stations"],
                ),
                promotes=["*"],
            )
        if opts["body_frame"]:
            self.add_subsystem("velocity", RotorVelocityComp(**frame), promotes=["*"])
        inplane = self.add_rotor_model(geo)
        self.add_subsystem(
            "performance",
            RotorPerformanceComp(num_rotors=nr, num_nodes=nn, edgewise=inplane),
            promotes=["*"],
        )
        if opts["body_frame"]:
            self.add_subsystem(
                "hub_loads",
                HubLoadsComp(spin_direction=geo["spin_direction"], inplane_loads=inplane, **frame),
                promotes=["*"],
            )

        rotors = opts["rotors"]
        if rotors is not None:
            if internal:
                if opts["num_cp"] != 4:
                    raise ValueError(
                        f"{self.msginfo}: option 'num_cp' = {opts['num_cp']}; the "
                        "vehicle rotors have 4 chord and twist control points, so it "
                        "must be 4 when option 'rotors' is given."
                    )
                chord_cp = np.array([r.chord_cp for r in rotors])
                twist_cp = np.array([r.twist_cp for r in rotors])
                self.set_input_defaults("chord_cp", chord_cp, units="m")
                self.set_input_defaults("twist_cp", twist_cp, units="rad")
            self.set_input_defaults("radius", np.array([r.radius for r in rotors]), units="m")
            if opts["body_frame"]:
                self.set_input_defaults(
                    "hub_position", np.array([r.hub_position for r in rotors]), units="m"
                )
        else:
            self.set_input_defaults("radius", np.ones(nr), units="m")


class BEMRotorGroup(RotorGroupBase):
    """
    Several rotors at several operating points by BEM, from design variables to body loads.

    Subsystems (all variables promoted):

    - ``blade``: BladeGeometryGroup (stations, chord and twist B-splines; docs theory/rotors 'Blade
      parameterization', 'Stations and disk frame');
    - ``velocity``: RotorVelocityComp (body velocity to each disk's axial velocity), if
      ``body_frame``;
    - ``inflow``: BEMInflowComp (inflow angle of every station, paper eq. 13, docs theory/rotors
      'BEM inflow residual');
    - ``loads``: BEMLoadsComp (sectional loads, thrust, torque; eq. 12, docs theory/rotors 'Loads
      and coefficients');
    - ``performance``: RotorPerformanceComp (power, C_T, C_P, J, eta, FoM, tip Mach; docs
      theory/rotors 'Loads and coefficients');
    - ``hub_loads``: HubLoadsComp (forces and moments in the body frame), if ``body_frame``.

    Solvers: the group is feed-forward (NonlinearRunOnce, LinearRunOnce). BEMInflowComp solves
    itself in ``solve_nonlinear`` and inverts its diagonal Jacobian in ``solve_linear``, so no
    DirectSolver is needed and a total derivative costs one pass.

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
        Body-axis velocity of the vehicle (u, v, w), if ``body_frame``; otherwise the input is
        axial_velocity (num_rotors, num_nodes), m/s.
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
    inflow_angle : (num_rotors, num_nodes, num_radial), rad
    thrust_per_span, drag_per_span, angle_of_attack : (num_rotors, num_nodes, num_radial)
    thrust, torque : (num_rotors, num_nodes), N, N*m
    blade_stall_ratio : (1, 2 num_rotors num_nodes num_radial); blade_stall_ratio_ks : (1,)
        Every station's alpha over its section's stall angles (positive, then negative) and
        their KS maximum (BladeStallRatioComp; docs theory/rotors 'Blade stall limit').
    power, thrust_coefficient, power_coefficient, advance_ratio, efficiency, figure_of_merit,
    tip_mach, helical_tip_mach : (num_rotors, num_nodes)
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
    num_nodes, num_radial, num_cp : int
        Operating points (1), radial stations (25), control points (4).
    polar : Polar
        Sectional polar. Default LinearQuadraticPolar() (docs theory/aerodynamics 'Linear-quadratic
        polar').
    tip_loss, hub_loss : bool
        Prandtl losses (default True).
    tip_loss_form, quadrature, spline_stations : str
        'classical', 'midpoint', 'as_coded' (defaults; see the components for the public-code
        compatibility values 'bladead').
    body_frame : bool
        Include RotorVelocityComp and HubLoadsComp (default True).
    """

    def declare_model_options(self):
        self.options.declare(
            "tip_loss_form",
            default="classical",
            values=TIP_LOSS_FORMS,
            desc="Tip-loss form ('bladead': compatibility with the public code, "
            "docs theory/rotors 'Public-code compatibility')",
        )

    def add_rotor_model(self, geo):
        opts = self.options
        bem = {
            "num_rotors": geo["num_rotors"],
            "num_nodes": opts["num_nodes"],
            "num_radial": opts["num_radial"],
            "num_blades": geo["num_blades"],
            "polar": opts["polar"],
            "tip_loss": opts["tip_loss"],
            "hub_loss": opts["hub_loss"],
            "tip_loss_form": opts["tip_loss_form"],
        }
        self.add_subsystem("inflow", BEMInflowComp(**bem), promotes=["*"])
        self.add_subsystem("loads", BEMLoadsComp(**bem), promotes=["*"])
        nr, nn, nrad = geo["num_rotors"], opts["num_nodes"], opts["num_radial"]
        self.add_subsystem(
            "blade_stall",
            BladeStallRatioComp(num_rotors=nr, num_nodes=nn, num_radial=nrad, polar=opts["polar"]),
            promotes=["*"],
        )
        self.add_subsystem(
            "blade_stall_ks",
            KSComp(width=2 * nr * nn * nrad, rho=BLADE_STALL_KS_RHO),
            promotes_inputs=[("g", "blade_stall_ratio")],
            promotes_outputs=[("KS", "blade_stall_ratio_ks")],
        )
        return False  # axial model: no in-plane hub loads
