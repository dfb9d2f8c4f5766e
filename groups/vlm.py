"""Vortex-lattice aerodynamics of the wing and horizontal tail, solved together."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.aero.alpha_star import AlphaStarComp
from lpc_mdo.components.aero.lift_dependent_profile_drag import (
    LiftDependentProfileDragComp,
    StripFlowComp,
)
from lpc_mdo.components.aero.vlm_aic import VLMAICComp
from lpc_mdo.components.aero.vlm_circulation import VLMCirculationComp
from lpc_mdo.components.aero.vlm_forces import VLMPanelForcesComp
from lpc_mdo.components.aero.vlm_freestream import VLMFreestreamComp
from lpc_mdo.components.aero.vlm_geometry import VLMGeometryComp
from lpc_mdo.components.aero.vlm_induced_velocity import VLMInducedVelocityComp
from lpc_mdo.components.aero.vlm_lattice import VLMSurface, check_surfaces_option, lattice_of
from lpc_mdo.components.aero.vlm_loads import VLMLoadsComp
from lpc_mdo.components.aero.vlm_normals import VLMNormalsComp
from lpc_mdo.components.aero.vlm_profile_drag import VLMProfileDragComp
from lpc_mdo.components.aero.vlm_sectional import VLMSectionalLiftComp
from lpc_mdo.components.aero.vlm_trefftz import VLMTrefftzDragComp
from lpc_mdo.core.constants import SEA_LEVEL_DENSITY

__all__ = ["VLMGroup", "VLMSurface", "lpc_vlm_surfaces"]


def lpc_vlm_surfaces(wing_span_panels=26, tail_span_panels=8, chord_panels=1):
    """
    Return the LPC lattice of the public code: wing 26 x 1 and all-moving h-tail 8 x 1 panels.

    docs theory/aerodynamics 'Reference-vehicle defaults' (VLM meshes). Returns a tuple of
    :class:`VLMSurface` named ``wing`` and ``horizontal_tail`` (deflectable).
    """
    return (
        VLMSurface("wing", chord_panels, wing_span_panels),
        VLMSurface("horizontal_tail", chord_panels, tail_span_panels, deflectable=True),
    )


class VLMGroup(om.Group):
    """
    Steady vortex-lattice method for several lifting surfaces with mutual influence.

    Paper Sec. III.A, eqs. 10–11; docs theory/aerodynamics 'Vortex-lattice method'. One lattice
    holds all surfaces (wing and horizontal tail), so the tail sees the wing's wake and vice versa.
    Vortex rings on the quarter-panel-shifted bound grid, wake a semi-infinite vortex pair per
    strip along the relative wind, a dense AIC system solved by LU in an ImplicitComponent
    (:class:`VLMCirculationComp`, whose own ``solve_linear`` reuses the factors, so the group
    needs no linear solver: the default LinearRunOnce gives exact derivatives), Kutta–Joukowski
    forces at the bound segments, a Trefftz-plane drag check, strip-theory profile drag and
    sectional c_l. Airfoil camber enters through the sectional zero-lift angle, an all-moving
    control surface through its deflection (both tilt the boundary-condition normals, see
    :class:`VLMNormalsComp`). Mesh coordinates are inputs, so geometric design variables reach
    the aerodynamics through analytic partials.

    Subsystems (in order): geometry, freestream, normals, aic, circulation, induced_velocity,
    panel_forces, sectional, [per surface of ``lift_dependent_drag``: strip_flow, alpha_star,
    lift_dependent_drag], profile_drag, loads, trefftz. With ``lift_dependent_drag`` the
    surface's ``{name}_sectional_cd`` is computed (docs theory/aerodynamics 'Lift-dependent
    profile drag') and the group reads ``reynolds_per_length`` and ``mach``.

    Inputs (promoted; nn = num_nodes, ns = span-wise panels of a surface):

    Inputs
    ------
    {name}_mesh : (nx, ny, 3), m
        Mesh of each surface (e.g. from
        :class:`~lpc_mdo.components.geometry.planform.PlanformMeshComp`).
    speed : (nn,), m/s
    angle_of_attack : (nn,), rad
    sideslip_angle : (nn,), rad
    angular_velocity : (nn, 3), rad/s
        Body rates (p, q, r) about ``rotation_center`` (default 0).
    rotation_center : (3,), m
    density : (nn,), kg/m**3
    reference_point : (3,), m
        Moment reference point.
    reference_area : scalar, m**2
        Area of the coefficients (the wing area).
    {name}_zero_lift_angle : (nn, ns), rad
        Sectional zero-lift angle per strip (airfoil polar; 0 for a symmetric section).
    {name}_sectional_cd : (nn, ns)
        Sectional profile-drag coefficient per strip (airfoil polar; 0 = none).
    {name}_deflection : (nn,), rad
        Deflection of each deflectable (all-moving) surface, trailing edge down.

    The outputs are promoted.

    Outputs
    -------
    force : (nn, 3), N, body axes;  moment : (nn, 3), N*m about reference_point
    lift, drag, induced_drag, profile_drag, side_force, trefftz_induced_drag : (nn,), N
    CL, CDi, CD : (nn,)
    {name}_sectional_cl : (nn, ns)
    circulation : (nn, np), m**2/s;  panel_forces : (nn, np, 3), N
    and the lattice geometry (ring_vertices, collocation_points, force_points, bound_vectors,
    panel_areas, strip_areas).

    Options
    -------
    surfaces : tuple of VLMSurface
    num_nodes : int
    lift_dependent_drag : dict
        Surface name -> airfoil (anything ``get_polar`` takes) of the surfaces whose strips
        carry the lift-dependent profile drag of their polar; default none (c_d an input).
    """

    def initialize(self):
        self.options.declare(
            "surfaces",
            types=(tuple, list),
            check_valid=check_surfaces_option,
            desc="tuple of VLMSurface, in lattice order",
        )
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of flight conditions"
        )
        self.options.declare(
            "lift_dependent_drag",
            default={},
            types=dict,
            desc="surface name -> airfoil: strips whose profile drag grows with lift (polar)",
        )

    def setup(self):
        surfaces = tuple(self.options["surfaces"])
        unknown = set(self.options["lift_dependent_drag"]) - {s.name for s in surfaces}
        if unknown:
            raise ValueError(
                f"{self.msginfo}: lift_dependent_drag names {sorted(unknown)}, which are not "
                f"surfaces of the lattice ({[s.name for s in surfaces]})."
            )
        nn = self.options["num_nodes"]
        npn = lattice_of(surfaces).num_panels
        kw = {"surfaces": surfaces, "num_nodes": nn}

        self.add_subsystem("geometry", VLMGeometryComp(surfaces=surfaces), promotes=["*"])
        self.add_subsystem(
            "freestream", VLMFreestreamComp(num_nodes=nn, num_panels=npn), promotes=["*"]
        )
        self.add_subsystem("normals", VLMNormalsComp(**kw), promotes=["*"])
        self.add_subsystem("aic", VLMAICComp(**kw), promotes=["*"])
        self.add_subsystem(
            "circulation", VLMCirculationComp(num_nodes=nn, num_panels=npn), promotes=["*"]
        )
        self.add_subsystem("induced_velocity", VLMInducedVelocityComp(**kw), promotes=["*"])
        self.add_subsystem("panel_forces", VLMPanelForcesComp(**kw), promotes=["*"])
        self.add_subsystem("sectional", VLMSectionalLiftComp(**kw), promotes=["*"])
        for surface in surfaces:
            if surface.name in self.options["lift_dependent_drag"]:
                self._add_lift_dependent_drag(surface, nn)
        self.add_subsystem("profile_drag", VLMProfileDragComp(**kw), promotes=["*"])
        self.add_subsystem("loads", VLMLoadsComp(num_nodes=nn, num_panels=npn), promotes=["*"])
        self.add_subsystem("trefftz", VLMTrefftzDragComp(**kw), promotes=["*"])

        self.set_input_defaults("density", np.full(nn, SEA_LEVEL_DENSITY), units="kg/m**3")
        self.set_input_defaults("speed", np.zeros(nn), units="m/s")

    def _add_lift_dependent_drag(self, surface, nn):
        """
        Strip c_d of ``surface`` from its polar at the VLM's sectional c_l (module docstring).

        Strip Reynolds and Mach numbers (:class:`StripFlowComp`), the section angle alpha* of
        the sectional c_l (:class:`AlphaStarComp`, an implicit component that solves itself),
        then the lift-dependent c_d increment (:class:`LiftDependentProfileDragComp`) into
        ``{name}_sectional_cd``; the group then needs ``reynolds_per_length`` and ``mach``.
        """
        name, ns = surface.name, surface.num_span_panels
        airfoil = self.options["lift_dependent_drag"][name]
        self.add_subsystem(
            f"{name}_strip_flow",
            StripFlowComp(
                num_nodes=nn,
                num_chord_panels=surface.num_chord_panels,
                num_span_panels=ns,
            ),
            promotes_inputs=[("mesh", f"{name}_mesh"), "reynolds_per_length", "mach"],
        )
        self.add_subsystem(
            f"{name}_alpha_star",
            AlphaStarComp(num_sections=nn * ns, airfoil=airfoil),
        )
        self.add_subsystem(
            f"{name}_lift_dependent_drag",
            LiftDependentProfileDragComp(num_nodes=nn, num_span_panels=ns, airfoil=airfoil),
            promotes_outputs=[("sectional_cd", f"{name}_sectional_cd")],
        )
        self.connect(
            f"{name}_sectional_cl",
            f"{name}_alpha_star.lift_coefficient",
            src_indices=np.arange(nn * ns),
            flat_src_indices=True,
        )
        for source, target in (
            ("strip_reynolds", "reynolds"),
            ("strip_mach", "mach"),
        ):
            self.connect(f"{name}_strip_flow.{source}", f"{name}_alpha_star.{target}")
            self.connect(f"{name}_strip_flow.{source}", f"{name}_lift_dependent_drag.{target}")
        self.connect(f"{name}_alpha_star.alpha_star", f"{name}_lift_dependent_drag.alpha_star")
