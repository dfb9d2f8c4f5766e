"""A +3g or -1g manoeuvre: VLM at the load factor, trim in F_z and the wing-box beam."""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.ks import KSComp
from lpc_mdo.components.structures.displacement import VerticalDisplacementComp
from lpc_mdo.components.structures.load_transfer import DisplacementTransferComp
from lpc_mdo.components.structures.mesh_deformation import MeshDeformationComp
from lpc_mdo.groups.beam import BoxBeamGroup
from lpc_mdo.groups.condition_base import ConditionGroup
from lpc_mdo.groups.condition_builders import (
    add_aerodynamics,
    add_atmosphere,
    add_equations_of_motion,
    declare_aero_options,
)
from lpc_mdo.vehicle.condition_kinds import StructuralKind

#: KS parameter of the structural conditions' stress aggregate ``stress_ratio_ks`` when no
#: structural ``ks_rho`` is given (the stress constraint of the problems). The KS value exceeds
#: the largest of the 40 ratios by at most ln(40)/rho = 3.7 % (paper eq. 7), less where the
#: other ratios are well below it.
STRESS_KS_RHO = 100.0


class StructuralCondition(ConditionGroup):
    """
    +3g or -1g pull-up/push-over: VLM at the load factor, trim in F_z only, and the wing-box beam.

    The beam is that of the right half wing, loaded by the VLM panel forces plus its own inertia at
    the load factor, with stress and curved-panel buckling (paper Sec. III.D, IV; docs
    theory/structures). Pitch is an input (design variable); the elevator is held at zero. With
    ``ks_rho`` the stress ratios, the buckling ratios (all bays but the tip bay) and the vertical
    tip-ward displacement in the direction of the load (-w at positive, +w at negative load factor)
    are also aggregated by KS (paper eq. 7): ``stress_ratio_ks``, ``top_skin_buckling_ratio_ks``,
    ``bottom_skin_buckling_ratio_ks``, ``displacement_ks`` (m). The beam's material is the vehicle's
    ``[material]``: inputs ``material_youngs_modulus``, ``material_shear_modulus``,
    ``material_density`` (the box's own weight), ``material_poisson_ratio`` and
    ``material_allowable_stress``.
    """

    declaration = StructuralKind

    def initialize(self):
        super().initialize()
        declare_aero_options(self)
        self.options.declare(
            "ks_rho",
            default=None,
            types=(int, float),
            allow_none=True,
            desc="KS parameter of the structural aggregates (None: none)",
        )
        self.options.declare(
            "coupling",
            default="one_way",
            values=("one_way", "two_way"),
            desc="one-way (loads only) or two-way (the beam deforms the VLM "
            "wing mesh; block Gauss-Seidel)",
        )

    def setup(self):
        vehicle = self.options["vehicle"]
        condition = vehicle.condition(self.options["condition"])
        n_wing = self.options["wing_panels"]
        right = np.arange(n_wing // 2, n_wing)  # wing panels with y > 0 (one chord-wise row)
        nodes = vehicle.wing_box.num_bays + 1
        add_atmosphere(self, condition, vehicle)
        two_way = self.options["coupling"] == "two_way"
        if two_way:
            self._add_mesh_deformation(nodes, n_wing)
        add_aerodynamics(
            self,
            vehicle,
            condition,
            self.options["wing_zero_lift_angle"],
            wing_mesh="deformed_wing_mesh" if two_way else "wing_mesh",
        )
        add_equations_of_motion(
            self, ["aero", "drag"], forces_only=["drag"], load_factor=condition.load_factor
        )
        rho = self.options["ks_rho"]
        self.add_subsystem(
            "beam",
            BoxBeamGroup(
                num_nodes=nodes,
                num_aero_points=right.size,
                ks_rho=rho,
                stress_ks_rho=STRESS_KS_RHO if rho is None else None,
            ),
            promotes_inputs=[
                ("nodes", "wing_box_nodes"),
                "box_width",
                "box_height",
                "top_skin_thickness",
                "bottom_skin_thickness",
                "front_spar_thickness",
                "rear_spar_thickness",
                "top_skin_radius",
                "bottom_skin_radius",
                "load_factor",
                "pitch",
            ],
            promotes_outputs=[
                "von_mises_stress",
                "top_skin_buckling_ratio",
                "bottom_skin_buckling_ratio",
                "displacements",
                "rotations",
                "stress_ratio",
            ],
        )
        self.connect(
            "force_points", "beam.aero_points", src_indices=om.slicer[n_wing // 2 : n_wing, :]
        )
        self.connect(
            "panel_forces", "beam.aero_forces", src_indices=om.slicer[0, n_wing // 2 : n_wing, :]
        )
        material = vehicle.material
        for name, units in (
            ("youngs_modulus", "Pa"),
            ("shear_modulus", "Pa"),
            ("density", "kg/m**3"),
            ("poisson_ratio", None),
            ("allowable_stress", "Pa"),
        ):
            self.promotes("beam", inputs=[(name, f"material_{name}")])
            self.set_input_defaults(f"material_{name}", getattr(material, name), units=units)
        self.promotes("beam", outputs=["stress_ratio_ks"])
        if rho is not None:
            self.promotes(
                "beam",
                outputs=[
                    "top_skin_buckling_ratio_ks",
                    "bottom_skin_buckling_ratio_ks",
                ],
            )
            sign = -1.0 if condition.load_factor > 0 else 1.0
            self.add_subsystem(
                "displacement_sign", VerticalDisplacementComp(num_nodes=nodes, sign=sign)
            )
            self.add_subsystem(
                "displacement_ks",
                KSComp(width=nodes, rho=rho * 10.0, units="m"),
                promotes_outputs=[("KS", "displacement_ks")],
            )
            self.connect("displacements", "displacement_sign.displacements")
            self.connect("displacement_sign.vertical_displacement", "displacement_ks.g")
        if two_way:
            # The loop VLM -> beam -> mesh -> VLM: Newton on the coupled system (each implicit
            # component still solves itself first); a failure to converge is an AnalysisError
            # so an optimizer can back off.
            self.nonlinear_solver = om.NewtonSolver(
                solve_subsystems=True,
                maxiter=30,
                atol=1e-8,
                rtol=1e-8,
                iprint=-1,
                err_on_non_converge=True,
            )
            self.linear_solver = om.DirectSolver()

    def _add_mesh_deformation(self, nodes, n_wing):
        """Beam displacements -> right-half wing mesh nodes -> mirrored deformed mesh."""
        nx, ny = 2, n_wing + 1
        half = ny // 2
        chord, span = np.meshgrid(np.arange(nx), np.arange(half, ny), indexing="ij")
        points = chord.size
        self.add_subsystem(
            "displacement_transfer",
            DisplacementTransferComp(num_nodes=nodes, num_points=points),
            promotes_inputs=[("nodes", "wing_box_nodes"), "displacements", "rotations"],
        )
        xyz = np.arange(3)[np.newaxis, :]
        self.connect(
            "wing_mesh",
            "displacement_transfer.aero_points",
            src_indices=om.slicer[chord.reshape(-1, 1), span.reshape(-1, 1), xyz],
        )
        self.add_subsystem(
            "mesh_deformation",
            MeshDeformationComp(num_chord_nodes=nx, num_span_nodes=ny),
            promotes_inputs=[("mesh", "wing_mesh")],
            promotes_outputs=[("deformed_mesh", "deformed_wing_mesh")],
        )
        self.connect(
            "displacement_transfer.aero_displacements", "mesh_deformation.right_displacements"
        )
