"""Beam and wing-box assemblies (frame FEM, box section, stress, buckling).

The plain-function wrappers ``beam`` and ``box_beam`` are in :mod:`lpc_mdo.api.structures`.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.ks import KSComp
from lpc_mdo.components.structures.beam import (
    BeamDisplacementComp,
    BeamForcesComp,
    BeamMassComp,
)
from lpc_mdo.components.structures.box_section import TORSION_FORMULAS, BoxSectionComp
from lpc_mdo.components.structures.buckling import PANEL_MODELS, PanelBucklingComp
from lpc_mdo.components.structures.load_transfer import LoadTransferComp
from lpc_mdo.components.structures.stress import BoxStressComp
from lpc_mdo.core.checks import check_integer


def _declare_frame_options(group):
    group.options.declare("num_nodes", types=int, lower=2, desc="Number of beam nodes (>= 2)")
    group.options.declare(
        "connectivity",
        default=None,
        allow_none=True,
        desc="Element node pairs (num_elements, 2); None: consecutive nodes",
    )
    group.options.declare(
        "fixed_nodes", default=(0,), types=(tuple, list), desc="Clamped nodes (all 6 DoF fixed)"
    )
    group.options.declare(
        "fixed_dofs",
        default=(),
        types=(tuple, list),
        desc="Further constrained (node, dof) pairs, dof 0..5",
    )


def _add_frame(group, with_mass=True):
    """Add mass, stiffness solve and load recovery, everything promoted."""
    opts = {"num_nodes": group.options["num_nodes"], "connectivity": group.options["connectivity"]}
    if with_mass:
        group.add_subsystem("mass", BeamMassComp(**opts), promotes=["*"])
    group.add_subsystem(
        "fem",
        BeamDisplacementComp(
            fixed_nodes=tuple(group.options["fixed_nodes"]),
            fixed_dofs=tuple(tuple(p) for p in group.options["fixed_dofs"]),
            **opts,
        ),
        promotes=["*"],
    )
    group.add_subsystem("internal_loads", BeamForcesComp(**opts), promotes=["*"])


class BeamGroup(om.Group):
    """
    Linear static Euler-Bernoulli space frame with given section properties (paper eq. 17).

    Subsystems, all promoted: ``mass`` (BeamMassComp: element masses, beam mass and cg),
    ``fem`` (BeamDisplacementComp: K u = f, sparse direct solve, implicit) and
    ``internal_loads`` (BeamForcesComp: element end forces, section resultants, reactions).
    The implicit ``fem`` solves itself and provides its own linear solve (LU of K), so the
    group runs once and needs no Newton or DirectSolver; totals (fwd or adjoint) cost one
    triangular solve pair per right-hand side.

    The inputs are promoted.

    Inputs
    ------
    nodes : (num_nodes, 3), m; area : (num_elements,), m**2;
    bending_inertia_vertical, bending_inertia_inplane, torsion_constant : (num_elements,), m**4;
    youngs_modulus, shear_modulus : scalar, Pa; density : scalar, kg/m**3;
    node_forces : (num_nodes, 3), N; node_moments : (num_nodes, 3), N*m (global frame).

    The outputs are promoted.

    Outputs
    -------
    displacements : (num_nodes, 3), m; rotations : (num_nodes, 3), rad;
    element_end_forces, element_end_moments : (num_elements, 2, 3), N and N*m (element frame);
    section_forces : (num_elements, 3), N; section_moments : (num_elements, 3), N*m;
    reaction_forces : (num_nodes, 3), N; reaction_moments : (num_nodes, 3), N*m;
    element_mass : (num_elements,), kg; beam_mass : scalar, kg; beam_cg : (3,), m.

    Options
    -------
    num_nodes : int
    connectivity : array (num_elements, 2) of int or None (consecutive nodes)
    fixed_nodes : tuple of int, default (0,) (clamped root)
    fixed_dofs : tuple of (node, dof) pairs, default ()
    """

    def initialize(self):
        _declare_frame_options(self)

    def setup(self):
        _add_frame(self)


class BoxBeamGroup(om.Group):
    """
    Wing-box beam: box section, frame FEM, stress recovery and skin-panel buckling.

    docs theory/structures and paper eqs. 17-18. Subsystems, all promoted, in execution order:

    - ``section`` (BoxSectionComp): A, I_y, I_z, J and the mean web thickness from the box
      width and height and the four wall thicknesses (per element = per bay);
    - ``mass`` (BeamMassComp): element masses, half-wing mass ``beam_mass`` and ``beam_cg``;
    - ``load_transfer`` (LoadTransferComp, only if ``num_aero_points`` > 0 or
      ``num_point_masses`` > 0): aerodynamic point forces, the beam's own weight and point
      masses at the load factor onto ``node_forces``/``node_moments``; otherwise those are
      inputs;
    - ``fem``, ``internal_loads``: as in BeamGroup;
    - ``stress`` (BoxStressComp): von Mises stress at 5 points per element, skin stresses;
    - ``buckling`` (PanelBucklingComp): critical stresses and buckling ratios of the top and
      bottom skin panels (curved panels, paper eq. 18, by default).

    - with ``ks_rho`` set: ``stress_ks`` (KSComp, paper eq. 7) aggregating every
      ``stress_ratio`` into ``stress_ratio_ks``, and ``top_buckling_ks``/``bottom_buckling_ks``
      aggregating the buckling ratios of the first ``num_buckling_bays`` bays into
      ``top_skin_buckling_ratio_ks``/``bottom_skin_buckling_ratio_ks``; with only
      ``stress_ks_rho`` set, the stress aggregate alone (its own KS parameter).

    The constraints of the paper's structural subproblem are ``top_skin_buckling_ratio`` and
    ``bottom_skin_buckling_ratio`` <= 1 without the tip bay, ``stress_ratio`` <= 1 and the
    vertical displacement (or their KS aggregates).

    The inputs are promoted.

    Inputs
    ------
    nodes : (num_nodes, 3), m; box_width, box_height : (num_elements,), m;
    top_skin_thickness, bottom_skin_thickness, front_spar_thickness, rear_spar_thickness :
    (num_elements,), m; top_skin_radius, bottom_skin_radius : (num_elements,), m (curved panels);
    youngs_modulus, shear_modulus : Pa; density : kg/m**3; poisson_ratio : -;
    node_forces, node_moments : (num_nodes, 3), N, N*m (without load transfer), or aero_points,
    aero_forces : (num_aero_points, 3), m, N; point_masses : (k,), kg;
    point_mass_locations : (k, 3), m; load_factor; pitch, roll : rad (with load transfer).

    The outputs are promoted.

    Outputs
    -------
    Those of BeamGroup, plus area, bending_inertia_vertical, bending_inertia_inplane,
    torsion_constant, web_thickness (num_elements,); von_mises_stress (num_elements, 5), Pa;
    top_skin_stress, bottom_skin_stress, top_skin_critical_stress,
    bottom_skin_critical_stress (num_elements,), Pa; top_skin_buckling_ratio,
    bottom_skin_buckling_ratio (num_elements,).

    Options
    -------
    num_nodes : int; fixed_nodes, fixed_dofs : as in BeamGroup (the chain of consecutive nodes
    is the only connectivity here);
    torsion_formula : 'polar' (default, reference model) or 'bredt';
    web_points : 'one' (default, five points) or 'both';
    panel : 'curved' (default) or 'flat'; flat_plate_coefficient : float (default 4);
    num_aero_points : int (default 0); num_point_masses : int (default 0);
    include_weight : bool (default True; with load transfer); span_axis : int (default 1);
    ks_rho : float or None (default None: no aggregation); stress_ks_rho : float or None
    (default None: ``ks_rho``); num_buckling_bays : int or None (bays from the root in the
    buckling aggregate; default None = all but the tip bay).
    """

    def initialize(self):
        _declare_frame_options(self)
        self.options.declare(
            "torsion_formula",
            default="polar",
            values=TORSION_FORMULAS,
            desc="Torsion constant and torsional shear: 'polar' or 'bredt'",
        )
        self.options.declare(
            "web_points",
            default="one",
            values=("one", "both"),
            desc="Stress points on the webs: 'one' (five points) or 'both'",
        )
        self.options.declare(
            "panel",
            default="curved",
            values=PANEL_MODELS,
            desc="Skin-panel buckling model: 'curved' (eq. 18) or 'flat'",
        )
        self.options.declare(
            "flat_plate_coefficient",
            default=4.0,
            types=(int, float),
            desc="Buckling coefficient k of flat panels",
        )
        self.options.declare(
            "num_aero_points",
            default=0,
            types=int,
            lower=0,
            desc="Aerodynamic force points for the load transfer (0: nodal loads are inputs)",
        )
        self.options.declare(
            "num_point_masses",
            default=0,
            types=int,
            lower=0,
            desc="Point masses carried by the wing box (load transfer)",
        )
        self.options.declare(
            "include_weight",
            default=True,
            types=bool,
            desc="With load transfer: add the box's own weight at the load factor",
        )
        self.options.declare(
            "span_axis", default=1, values=(0, 1, 2), desc="Span coordinate of the load transfer"
        )
        self.options.declare(
            "ks_rho",
            default=None,
            types=(int, float),
            allow_none=True,
            desc="KS parameter of the stress and buckling aggregates (None: no aggregation)",
        )
        self.options.declare(
            "stress_ks_rho",
            default=None,
            types=(int, float),
            allow_none=True,
            desc="KS parameter of the stress aggregate (None: ks_rho)",
        )
        self.options.declare(
            "num_buckling_bays",
            default=None,
            types=int,
            allow_none=True,
            desc="Bays from the root in the buckling aggregate (None: all but "
            "the tip bay, as the paper)",
        )

    def setup(self):
        if self.options["connectivity"] is not None:
            raise ValueError(
                f"{self.msginfo}: option 'connectivity' must be None; the box "
                "beam is a chain of consecutive nodes."
            )
        n = self.options["num_nodes"]
        ne = n - 1
        formula = self.options["torsion_formula"]
        self.add_subsystem(
            "section", BoxSectionComp(num_elements=ne, torsion_formula=formula), promotes=["*"]
        )
        self.add_subsystem("mass", BeamMassComp(num_nodes=n), promotes=["*"])
        if self.options["num_aero_points"] or self.options["num_point_masses"]:
            self.add_subsystem(
                "load_transfer",
                LoadTransferComp(
                    num_nodes=n,
                    num_points=self.options["num_aero_points"],
                    num_point_masses=self.options["num_point_masses"],
                    include_weight=self.options["include_weight"],
                    span_axis=self.options["span_axis"],
                ),
                promotes=["*"],
            )
        _add_frame(self, with_mass=False)
        self.add_subsystem(
            "stress",
            BoxStressComp(
                num_elements=ne, torsion_formula=formula, web_points=self.options["web_points"]
            ),
            promotes=["*"],
        )
        self.add_subsystem(
            "buckling",
            PanelBucklingComp(
                num_elements=ne,
                panel=self.options["panel"],
                flat_plate_coefficient=self.options["flat_plate_coefficient"],
            ),
            promotes=["*"],
        )
        stress_rho = self.options["stress_ks_rho"] or self.options["ks_rho"]
        if stress_rho is not None:
            npts = 5 if self.options["web_points"] == "one" else 6
            self.add_subsystem(
                "stress_ks",
                KSComp(width=ne * npts, rho=stress_rho),
                promotes_outputs=[("KS", "stress_ratio_ks")],
            )
            self.connect(
                "stress_ratio",
                "stress_ks.g",
                src_indices=np.arange(ne * npts),
                flat_src_indices=True,
            )
        if self.options["ks_rho"] is not None:
            self._add_buckling_aggregates(ne)

    def _add_buckling_aggregates(self, ne):
        rho = self.options["ks_rho"]
        nb = self.options["num_buckling_bays"]
        nb = max(ne - 1, 1) if nb is None else nb
        check_integer(
            "num_buckling_bays",
            nb,
            lower=1,
            upper=ne,
            allowed=f"in [1, {ne}] (num_nodes - 1)",
            where=self.msginfo,
        )
        for skin in ("top", "bottom"):
            self.add_subsystem(
                f"{skin}_buckling_ks",
                KSComp(width=nb, rho=rho),
                promotes_outputs=[("KS", f"{skin}_skin_buckling_ratio_ks")],
            )
            self.connect(
                f"{skin}_skin_buckling_ratio",
                f"{skin}_buckling_ks.g",
                src_indices=np.arange(nb),
                flat_src_indices=True,
            )


__all__ = ["BeamGroup", "BoxBeamGroup"]
